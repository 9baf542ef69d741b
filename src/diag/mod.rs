//! Source files, spans and diagnostics rendered with a source excerpt and a caret.
//!
//! Every error that input can cause, from the grammar or from evaluation, becomes a
//! [`Diagnostic`] anchored to a [`Span`]. This module depends on nothing else in the crate.

use std::fmt;
use std::path::{Path, PathBuf};

/// Index of a file in a [`SourceMap`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct FileId(pub u32);

/// A byte range in one source file.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Span {
    /// The file the range lies in.
    pub file: FileId,
    /// First byte.
    pub start: u32,
    /// One past the last byte.
    pub end: u32,
}

impl Span {
    /// A span from byte offsets in `file`.
    pub fn new(file: FileId, start: usize, end: usize) -> Span {
        Span {
            file,
            start: start as u32,
            end: end as u32,
        }
    }
}

impl fmt::Debug for Span {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}..{}", self.start, self.end)
    }
}

/// Largest source file: spans hold byte offsets as `u32`.
pub const MAX_SOURCE_BYTES: u64 = u32::MAX as u64;

/// Reads a scene or include file as text. Bytes that are not UTF-8 are read as Latin-1 (as
/// POV-Ray reads them: an `é` in a comment of an old scene is one byte), each becoming the
/// character of that code; UTF-8 text is kept as it is.
pub fn read_source(path: &Path) -> std::io::Result<String> {
    let size = std::fs::metadata(path)?.len();
    if size > MAX_SOURCE_BYTES {
        return Err(std::io::Error::other(format!(
            "the file has {size} bytes; trace reads at most {MAX_SOURCE_BYTES}"
        )));
    }
    Ok(decode_source(std::fs::read(path)?))
}

/// Scene text from bytes: UTF-8 where valid, Latin-1 for any other byte.
pub fn decode_source(bytes: Vec<u8>) -> String {
    match String::from_utf8(bytes) {
        Ok(text) => text,
        Err(e) => {
            let bytes = e.into_bytes();
            let mut text = String::with_capacity(bytes.len() + bytes.len() / 8);
            for chunk in bytes.utf8_chunks() {
                text.push_str(chunk.valid());
                text.extend(chunk.invalid().iter().map(|&b| char::from(b)));
            }
            text
        }
    }
}

/// One loaded source file.
#[derive(Debug, Clone)]
pub struct SourceFile {
    /// The path as the user (or an include) named it.
    pub path: PathBuf,
    /// Its whole text (shared: the parser reads it while the evaluator adds files).
    pub text: std::sync::Arc<String>,
}

/// Every file read while loading a scene; spans index into it.
#[derive(Debug, Clone, Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl SourceMap {
    /// A key of the texts read (each file's text in four interleaved lanes of eight bytes,
    /// mixed by multiply and rotate, then the lanes and the length, in the order read): equal
    /// sources give equal keys wherever they lie on the disk. (Byte by byte, FNV-1a, it took
    /// 0.15 s of a 120 MB scene's load; one lane of eight bytes, 42 ms: each step waited for
    /// the one before.)
    pub fn key(&self) -> u64 {
        let mix = |h: u64, w: u64| (h ^ w).wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(29);
        let word = |b: &[u8]| u64::from_le_bytes(b.try_into().expect("eight bytes"));
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        for f in &self.files {
            let bytes = f.text.as_bytes();
            let mut lanes = [h, h ^ 1, h ^ 2, h ^ 3];
            let mut blocks = bytes.chunks_exact(32);
            for b in &mut blocks {
                for (i, lane) in lanes.iter_mut().enumerate() {
                    *lane = mix(*lane, word(&b[8 * i..8 * i + 8]));
                }
            }
            let mut last = [0u8; 32];
            last[..blocks.remainder().len()].copy_from_slice(blocks.remainder());
            for (i, lane) in lanes.iter_mut().enumerate() {
                *lane = mix(*lane, word(&last[8 * i..8 * i + 8]));
            }
            h = lanes.into_iter().fold(bytes.len() as u64, mix);
        }
        h
    }

    /// Adds a file and returns its id.
    pub fn add(&mut self, path: &Path, text: String) -> FileId {
        self.files.push(SourceFile {
            path: path.to_path_buf(),
            // (Kept as read: a String into an Arc<str> would copy the whole file.)
            text: std::sync::Arc::new(text),
        });
        FileId(self.files.len() as u32 - 1)
    }

    /// The file with id `id`.
    pub fn file(&self, id: FileId) -> &SourceFile {
        &self.files[id.0 as usize]
    }

    /// 1-based line and column (in characters) of byte `offset` in `file`.
    pub fn line_col(&self, file: FileId, offset: u32) -> (usize, usize) {
        let text = &self.file(file).text;
        let offset = (offset as usize).min(text.len());
        let before = &text[..floor_char_boundary(text, offset)];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let col = before[line_start..].chars().count() + 1;
        (line, col)
    }

    /// `path:line:col` of a span's start.
    pub fn location(&self, span: Span) -> String {
        let (line, col) = self.line_col(span.file, span.start);
        format!("{}:{}:{}", self.file(span.file).path.display(), line, col)
    }
}

fn floor_char_boundary(text: &str, mut i: usize) -> usize {
    while i > 0 && !text.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// How serious a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Severity {
    /// Loading stops.
    Error,
    /// Loading goes on; the user is told.
    Warning,
}

/// A message about the input, anchored to a span, with notes (such as an include chain).
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// One line saying what is wrong.
    pub message: String,
    /// Where; `None` for errors about the input as a whole.
    pub span: Option<Span>,
    /// Further lines shown after the excerpt.
    pub notes: Vec<String>,
}

impl Diagnostic {
    /// An error at `span`.
    pub fn error(message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic {
            severity: Severity::Error,
            message: message.into(),
            span: Some(span),
            notes: Vec::new(),
        }
    }

    /// A warning at `span`.
    pub fn warning(message: impl Into<String>, span: Span) -> Diagnostic {
        Diagnostic {
            severity: Severity::Warning,
            message: message.into(),
            span: Some(span),
            notes: Vec::new(),
        }
    }

    /// Adds a note line (after eight, a single "…" line stands for the rest, so that deep
    /// macro recursion does not flood the message).
    pub fn with_note(mut self, note: impl Into<String>) -> Diagnostic {
        const MAX_NOTES: usize = 8;
        if self.notes.len() < MAX_NOTES {
            self.notes.push(note.into());
        } else if self.notes.len() == MAX_NOTES {
            self.notes
                .push("… (more calls and includes omitted)".to_string());
        }
        self
    }

    /// Renders the diagnostic as text: message, location, the source line and a caret line.
    ///
    /// ```text
    /// error: unsupported: `difference` (CSG is outside trace's subset)
    ///   --> scene.rt:3:1
    ///    |
    ///  3 | difference {
    ///    | ^^^^^^^^^^
    /// ```
    pub fn render(&self, sources: &SourceMap) -> String {
        let label = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        let mut out = format!("{label}: {}\n", self.message);
        if let Some(span) = self.span {
            let file = sources.file(span.file);
            let (line, col) = sources.line_col(span.file, span.start);
            let text = &file.text;
            let start = floor_char_boundary(text, (span.start as usize).min(text.len()));
            let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
            let line_end = text[start..].find('\n').map_or(text.len(), |i| start + i);
            let source_line = text[line_start..line_end].trim_end_matches('\r');
            let end = floor_char_boundary(text, (span.end as usize).clamp(start, line_end));
            let width = text[start..end].chars().count().max(1);
            let gutter = line.to_string().len();
            let pad = " ".repeat(gutter);
            // Tabs before the caret are kept so that the caret lines up under the culprit.
            let lead: String = text[line_start..start]
                .chars()
                .map(|c| if c == '\t' { '\t' } else { ' ' })
                .collect();
            out += &format!("{pad}--> {}:{line}:{col}\n", file.path.display());
            out += &format!("{pad} |\n");
            out += &format!("{line} | {source_line}\n");
            out += &format!("{pad} | {lead}{}\n", "^".repeat(width));
        }
        for note in &self.notes {
            out += &format!("  = {note}\n");
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::{SourceMap, decode_source};
    use std::path::Path;

    fn key_of(files: &[(&str, &str)]) -> u64 {
        let mut map = SourceMap::default();
        for (path, text) in files {
            map.add(Path::new(path), text.to_string());
        }
        map.key()
    }

    #[test]
    fn the_sources_key_follows_the_texts_not_the_paths() {
        let scene = "sphere { 0, 1 pigment { rgb 1 } }\n";
        assert_eq!(
            key_of(&[("a.pov", scene)]),
            key_of(&[("/elsewhere/b.pov", scene)])
        );
        // A byte changed, a byte added, a file split elsewhere, files in another order.
        let keys = [
            key_of(&[("a.pov", scene)]),
            key_of(&[("a.pov", "sphere { 0, 2 pigment { rgb 1 } }\n")]),
            key_of(&[("a.pov", "sphere { 0, 1 pigment { rgb 1 } }\n\0")]),
            key_of(&[("a.pov", "abcdefghij"), ("b.inc", "k")]),
            key_of(&[("a.pov", "abcdefghi"), ("b.inc", "jk")]),
            key_of(&[("b.inc", "jk"), ("a.pov", "abcdefghi")]),
        ];
        for i in 0..keys.len() {
            for j in i + 1..keys.len() {
                assert_ne!(keys[i], keys[j], "{i} {j}");
            }
        }
    }

    #[test]
    fn bytes_that_are_not_utf8_read_as_latin1() {
        assert_eq!(decode_source(b"// caf\xe9\n".to_vec()), "// café\n");
        // Valid UTF-8 around a stray byte is kept as UTF-8.
        assert_eq!(decode_source(b"\xc3\xa9 \xff \xc3\xa9".to_vec()), "é ÿ é");
        assert_eq!(decode_source(b"\"\xe9\" \xc3\xa9".to_vec()), "\"é\" é");
    }
}
