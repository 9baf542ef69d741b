//! What the directive reader hands the grammar: a *unit* of directive-free text (a statement,
//! a declared value, a macro's arguments, a directive's condition …) and where each part of
//! it came from.
//!
//! The reader (`eval::lang::reader`) carries out `#if`, `#while`, macros and includes as POV-Ray's
//! token reader does, so a unit's text is spliced from pieces of several places: a file's
//! text between two directives, a macro's body, a loop's body read again. Each [`Piece`] maps
//! a stretch of the unit's text back to its file, so that spans and messages point at the
//! text as written. Every word of the unit has a *slot* ([`Slot`]): the reader binds the
//! identifiers among them to their values when it reads them (as POV-Ray's reader does, so a
//! macro's parameters and a loop's counter have the values they had there), and evaluation
//! finds those values by slot.

use crate::diag::{FileId, Span};

/// Where a stretch of a unit's text comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Piece {
    /// Where the stretch starts in the unit's text.
    pub at: u32,
    /// Its length in the unit's text.
    pub len: u32,
    /// The file it was read from.
    pub file: FileId,
    /// Where it starts in that file.
    pub start: u32,
    /// Its length in the file: `len` for text copied as written; another length for a
    /// stand-in (one marker byte for a mesh2 list read by the fast lane).
    pub src_len: u32,
}

/// The binding of a word of a unit: an index into the unit's words.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Slot(pub u32);

impl Slot {
    /// No binding: a word read without the reader (or one the grammar made up).
    pub const NONE: Slot = Slot(u32::MAX);
}

impl std::fmt::Debug for Slot {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if *self == Slot::NONE {
            f.write_str("-")
        } else {
            write!(f, "#{}", self.0)
        }
    }
}

/// A unit of directive-free text.
#[derive(Clone, Debug, Default)]
pub struct Unit {
    /// The text the grammar reads.
    pub text: String,
    /// Where each stretch of `text` comes from, in order, covering it but for the single
    /// blanks that separate pieces.
    pub pieces: Vec<Piece>,
    /// Where each word of `text` starts, in order: a word's slot is its index here.
    pub words: Vec<u32>,
    /// mesh2 lists read by the fast lane, by where their marker byte stands in `text`.
    pub lists: Vec<(u32, super::bulk::BulkList)>,
}

impl Unit {
    /// A unit that is the text of one file from byte `start` on, as written (the grammar's
    /// tests read such units).
    #[cfg(test)]
    pub fn from_file_text(text: &str, file: FileId, start: usize) -> Unit {
        Unit {
            text: text.to_string(),
            pieces: vec![Piece {
                at: 0,
                len: text.len() as u32,
                file,
                start: start as u32,
                src_len: text.len() as u32,
            }],
            words: Vec::new(),
            lists: Vec::new(),
        }
    }

    /// The slot of the word starting at byte `at` of the text.
    pub fn slot(&self, at: usize) -> Slot {
        self.words
            .binary_search(&(at as u32))
            .map_or(Slot::NONE, |i| Slot(i as u32))
    }

    /// The file and byte in it of byte `at` of the unit's text (the end of the text maps to
    /// the end of its last piece; a byte inside a stand-in, to the stand-in's start).
    pub fn source(&self, at: usize) -> (FileId, u32) {
        let i = self.piece_at(at);
        let at = at as u32;
        let Some(p) = self.pieces.get(i) else {
            return (FileId(0), 0);
        };
        let off = at.saturating_sub(p.at);
        let mapped = if p.len == p.src_len {
            p.start + off.min(p.len)
        } else if off >= p.len {
            p.start + p.src_len
        } else {
            p.start
        };
        (p.file, mapped)
    }

    /// The span in a file of bytes `start..end` of the unit's text: where `start` lies, to
    /// where `end` lies if that is further in the same file, else to the end of `start`'s
    /// piece.
    pub fn span(&self, start: usize, end: usize) -> Span {
        let (file, s) = self.source(start);
        let last = end.max(start + 1) - 1;
        let (file_end, e) = self.source(last);
        let end_piece = self.pieces.get(self.piece_at(last));
        let e = if file_end == file && e + 1 >= s {
            match end_piece {
                // (A stand-in's bytes map to its start: the span ends where its source ends.)
                Some(p) if p.len != p.src_len => p.start + p.src_len,
                _ => e + 1,
            }
        } else {
            self.pieces
                .get(self.piece_at(start))
                .map_or(s + 1, |p| (p.start + p.src_len).max(s))
        };
        Span {
            file,
            start: s,
            end: e.max(s),
        }
    }

    /// The index of the piece holding byte `at` of the text (the one before, between pieces).
    pub(super) fn piece_at(&self, at: usize) -> usize {
        self.pieces
            .partition_point(|p| p.at <= at as u32)
            .saturating_sub(1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_map_back_to_the_pieces_files() {
        // "abc def" from file 0 at 10, then "xy" from file 1 at 5.
        let unit = Unit {
            text: "abc def xy".into(),
            pieces: vec![
                Piece {
                    at: 0,
                    len: 7,
                    file: FileId(0),
                    start: 10,
                    src_len: 7,
                },
                Piece {
                    at: 8,
                    len: 2,
                    file: FileId(1),
                    start: 5,
                    src_len: 2,
                },
            ],
            words: vec![0, 4, 8],
            lists: Vec::new(),
        };
        assert_eq!(unit.source(4), (FileId(0), 14));
        assert_eq!(unit.source(9), (FileId(1), 6));
        assert_eq!(unit.span(4, 7), Span::new(FileId(0), 14, 17));
        // Across files: the start's piece to its end.
        assert_eq!(unit.span(4, 10), Span::new(FileId(0), 14, 17));
        assert_eq!(unit.slot(8), Slot(2));
        assert_eq!(unit.slot(5), Slot::NONE);
    }
}
