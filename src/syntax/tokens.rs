//! Directives as POV-Ray's token reader meets them: where a conditional's branches lie, and
//! the text with the branches not taken blanked.
//!
//! POV-Ray executes `#if`, `#while` … while it reads tokens, so a branch may open a block that
//! text after the `#end` closes (`#if (A) union { #else merge { #end … }`, a macro opening one
//! of several unions), and a directive may stand wherever a token may (`sphere { 0, #if (B) 1
//! #else 2 #end }`). trace's grammar reads whole items. When the grammar cannot read a
//! statement, the evaluator chooses such a conditional's branch itself and
//! asks for the statement again with the other branches and the directive's words blanked
//! here: every blanked byte becomes a space, so every byte position, and every message, still
//! points at the file as written.

use std::ops::Range;

/// Which directive opens or continues a conditional.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BranchKind {
    /// `#if (c)`.
    If,
    /// `#ifdef (Name)`.
    IfDef,
    /// `#ifndef (Name)`.
    IfNDef,
    /// `#elseif (c)`.
    ElseIf,
    /// `#else`.
    Else,
}

/// One branch of a conditional: the directive heading it and the text it holds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Branch {
    /// The directive heading it.
    pub kind: BranchKind,
    /// The directive: `#if (…)`, `#elseif (…)`, `#else`.
    pub head: Range<usize>,
    /// From the end of the head to the next `#elseif`, `#else` or `#end` of this conditional.
    pub body: Range<usize>,
}

/// `#if (c) … [#elseif (c) …]* [#else …] #end` (or `#ifdef`, `#ifndef`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Conditional {
    /// In order; an `#else` branch is the last.
    pub branches: Vec<Branch>,
    /// The `#end`.
    pub end: Range<usize>,
}

/// `#while (c) … #end` or `#for (I, a, b [, s]) … #end`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Loop {
    /// The directive with its parenthesis.
    pub head: Range<usize>,
    /// Between the head and the `#end`.
    pub body: Range<usize>,
    /// The `#end`.
    pub end: Range<usize>,
}

/// Directives that open a block closed by `#end`.
const OPENERS: [&str; 7] = ["if", "ifdef", "ifndef", "while", "for", "switch", "macro"];

/// A directive word met in the text: where its `#` stands, the word, where the word ends.
struct Directive<'t> {
    at: usize,
    word: &'t str,
    after: usize,
}

/// The directives of `text` from byte `from` on, in order (strings and comments passed over).
fn directives(text: &str, from: usize) -> impl Iterator<Item = Directive<'_>> {
    let b = text.as_bytes();
    code(b, from..b.len())
        .filter(|&(_, c)| c == b'#')
        .filter_map(move |(at, _)| {
            let word = &b[at + 1..];
            let len = word
                .iter()
                .position(|c| !(c.is_ascii_alphanumeric() || *c == b'_'))
                .unwrap_or(word.len());
            (len > 0).then(|| Directive {
                at,
                word: &text[at + 1..at + 1 + len],
                after: at + 1 + len,
            })
        })
}

/// Just after the string starting at `b[i]` (`"`).
fn string_end(b: &[u8], mut i: usize) -> usize {
    i += 1;
    while i < b.len() && b[i] != b'"' {
        i += if b[i] == b'\\' { 2 } else { 1 };
    }
    (i + 1).min(b.len())
}

/// Just after the comment starting at `b[i]` (`//` or `/*`; block comments nest, as in
/// trace's grammar).
fn comment_end(b: &[u8], i: usize) -> usize {
    if b[i + 1] == b'/' {
        return b[i..]
            .iter()
            .position(|&c| c == b'\n')
            .map_or(b.len(), |n| i + n);
    }
    super::bulk::skip_block_comment(b, i, usize::MAX).unwrap_or(b.len())
}

/// The first byte at or after `pos` that is neither a blank nor in a comment.
pub fn skip_blanks(text: &str, mut pos: usize) -> usize {
    let b = text.as_bytes();
    while pos < b.len() {
        if b[pos].is_ascii_whitespace() {
            pos += 1;
        } else if b[pos] == b'/' && matches!(b.get(pos + 1), Some(b'/' | b'*')) {
            pos = comment_end(b, pos);
        } else {
            break;
        }
    }
    pos
}

/// Just after the parenthesis that follows byte `pos` (blanks between), if one does and
/// closes.
fn parenthesis_end(text: &str, pos: usize) -> Option<usize> {
    let b = text.as_bytes();
    let start = skip_blanks(text, pos);
    if b.get(start) != Some(&b'(') {
        return None;
    }
    let mut depth = 0usize;
    for (i, c) in code(b, start..b.len()) {
        match c {
            b'(' => depth += 1,
            b')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i + 1);
                }
            }
            _ => {}
        }
    }
    None
}

/// The bytes of `b[range]` outside strings and comments, with their positions.
fn code(b: &[u8], range: Range<usize>) -> impl Iterator<Item = (usize, u8)> + '_ {
    let mut i = range.start;
    std::iter::from_fn(move || {
        while i < range.end {
            match b[i] {
                b'"' => i = string_end(b, i),
                b'/' if matches!(b.get(i + 1), Some(b'/' | b'*')) => i = comment_end(b, i),
                c => {
                    i += 1;
                    return Some((i - 1, c));
                }
            }
        }
        None
    })
}

/// The conditional whose `#if`, `#ifdef` or `#ifndef` stands at byte `pos`, if one does and
/// has its `#end`.
pub fn conditional_at(text: &str, pos: usize) -> Option<Conditional> {
    let mut found = directives(text, pos);
    let first = found.next().filter(|d| d.at == pos)?;
    let mut kind = match first.word {
        "if" => BranchKind::If,
        "ifdef" => BranchKind::IfDef,
        "ifndef" => BranchKind::IfNDef,
        _ => return None,
    };
    let mut head = pos..parenthesis_end(text, first.after)?;
    let head_end = head.end;
    let mut branches = Vec::new();
    let mut depth = 0usize;
    for d in found.filter(|d| d.at >= head_end) {
        let next = match (depth, d.word) {
            (_, w) if OPENERS.contains(&w) => {
                depth += 1;
                continue;
            }
            (0, "elseif") => Some((BranchKind::ElseIf, d.at..parenthesis_end(text, d.after)?)),
            (0, "else") => Some((BranchKind::Else, d.at..d.after)),
            (0, "end") => None,
            (_, "end") => {
                depth -= 1;
                continue;
            }
            _ => continue,
        };
        // (A branch after `#else` is not POV-Ray's; the grammar reports it.)
        if kind == BranchKind::Else && next.is_some() {
            return None;
        }
        branches.push(Branch {
            kind,
            head: head.clone(),
            body: head.end..d.at,
        });
        match next {
            Some((k, h)) => (kind, head) = (k, h),
            None => {
                return Some(Conditional {
                    branches,
                    end: d.at..d.after,
                });
            }
        }
    }
    None
}

/// The `#while` or `#for` loop standing at byte `pos`, if one does and has its `#end`.
pub fn loop_at(text: &str, pos: usize) -> Option<Loop> {
    let mut found = directives(text, pos);
    let first = found
        .next()
        .filter(|d| d.at == pos && matches!(d.word, "while" | "for"))?;
    let head = pos..parenthesis_end(text, first.after)?;
    let mut depth = 0usize;
    for d in found.filter(|d| d.at >= head.end) {
        match d.word {
            w if OPENERS.contains(&w) => depth += 1,
            "end" if depth == 0 => {
                return Some(Loop {
                    body: head.end..d.at,
                    head,
                    end: d.at..d.after,
                });
            }
            "end" => depth -= 1,
            _ => {}
        }
    }
    None
}

/// Whether every branch of `c` closes each block it opens and no other (counting `{` and
/// `}` outside strings and comments).
pub fn balanced(text: &str, c: &Conditional) -> bool {
    c.branches.iter().all(|branch| {
        let mut depth = 0i64;
        for (_, c) in code(text.as_bytes(), branch.body.clone()) {
            match c {
                b'{' => depth += 1,
                b'}' => {
                    depth -= 1;
                    if depth < 0 {
                        return false;
                    }
                }
                _ => {}
            }
        }
        depth == 0
    })
}

/// Blanks the directive words of `c` and the bodies of the branches other than `chosen`
/// (all of them if `None`): what is left is the text POV-Ray's reader would go on with.
pub fn keep_branch(text: &mut String, c: &Conditional, chosen: Option<usize>) {
    let mut blank = |r: Range<usize>| {
        let spaces = " ".repeat(r.len());
        text.replace_range(r, &spaces);
    };
    for (i, branch) in c.branches.iter().enumerate() {
        blank(branch.head.clone());
        if Some(i) != chosen {
            blank(branch.body.clone());
        }
    }
    blank(c.end.clone());
}

/// What [`culprit`] finds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Culprit {
    /// The conditional starting at this byte, to be chosen.
    Choose(usize),
    /// The conditional starting at this byte, inside a loop or macro of the statement.
    InLoop(usize),
}

/// The conditional to choose to read the statement that starts at byte `from` and that the
/// grammar stopped reading at byte `at`: the innermost conditional holding `at`, else the
/// last one before it (where the block it left open ends), if it is in the statement's own
/// text and not inside a loop or macro of it (a conditional there is chosen pass by pass,
/// which choosing once before the statement cannot do).
pub fn culprit(text: &str, from: usize, at: usize) -> Option<Culprit> {
    // Open directive blocks: where each starts and whether it is a conditional.
    let mut open: Vec<(usize, bool)> = Vec::new();
    let mut last_before = None;
    for d in directives(text, from) {
        if d.at > at && open.is_empty() {
            break;
        }
        match d.word {
            "if" | "ifdef" | "ifndef" => open.push((d.at, true)),
            w if OPENERS.contains(&w) => open.push((d.at, false)),
            "end" => {
                let Some((start, conditional)) = open.pop() else {
                    break; // (an `#end` of a block the statement is inside)
                };
                if d.after > at {
                    // `at` lies inside this block: the innermost holding it, if a conditional
                    // outside loops and macros.
                    if !conditional {
                        return last_before;
                    }
                    let outside = open.iter().all(|&(_, c)| c);
                    return Some(if outside {
                        Culprit::Choose(start)
                    } else {
                        Culprit::InLoop(start)
                    });
                }
                if conditional && open.is_empty() {
                    last_before = Some(Culprit::Choose(start));
                }
            }
            _ => {}
        }
    }
    last_before
}

/// Where a conditional directive stands in or right after an item the grammar could not read
/// in `node`'s tree (`pigment { rgb #if (A) x #else y #end }`: the grammar keeps `rgb …` as
/// an item it does not know, to be named by evaluation), as a byte of `text`, the part of the
/// file from byte `base`: a statement that needs POV-Ray's token reader although the grammar
/// read it.
pub fn directive_after_unknown(node: &super::Node, text: &str, base: usize) -> Option<usize> {
    if node.kind == super::NodeKind::Unknown {
        let start = (node.span.start as usize).checked_sub(base)?;
        let end = skip_blanks(text, (node.span.end as usize - base).min(text.len()));
        return directives(text, start)
            .take_while(|d| d.at <= end)
            .find(|d| matches!(d.word, "if" | "ifdef" | "ifndef"))
            .map(|d| d.at);
    }
    node.children
        .iter()
        .find_map(|c| directive_after_unknown(c, text, base))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_conditional_and_its_branches() {
        let t = "#if (A) x #elseif ((B)) y #else z #end w";
        let c = conditional_at(t, 0).unwrap();
        let parts: Vec<(&str, &str)> = c
            .branches
            .iter()
            .map(|b| (&t[b.head.clone()], &t[b.body.clone()]))
            .collect();
        assert_eq!(
            parts,
            [
                ("#if (A)", " x "),
                ("#elseif ((B))", " y "),
                ("#else", " z ")
            ]
        );
        assert_eq!(&t[c.end.clone()], "#end");
        assert_eq!(conditional_at(t, 1), None);
        assert_eq!(conditional_at("#if (A) x", 0), None);
        assert_eq!(conditional_at("#while (A) x #end", 0), None);
    }

    #[test]
    fn nested_blocks_strings_and_comments_are_passed_over() {
        let t = "#ifdef (A) #while (1) #else #end \"#end\" // #end\n /* #end */ #else q #end";
        let c = conditional_at(t, 0).unwrap();
        assert_eq!(c.branches.len(), 2);
        assert_eq!(&t[c.branches[1].body.clone()], " q ");
        assert_eq!(c.branches[0].kind, BranchKind::IfDef);
    }

    #[test]
    fn unbalanced_branches() {
        let t = "#if (A) union { #else merge { #end }";
        assert!(!balanced(t, &conditional_at(t, 0).unwrap()));
        let t = "#if (A) sphere { 0, 1 } #else } { #end";
        assert!(!balanced(t, &conditional_at(t, 0).unwrap()));
        let t = "#if (A) sphere { 0, 1 \"}\" } #end";
        assert!(balanced(t, &conditional_at(t, 0).unwrap()));
    }

    #[test]
    fn blanking_keeps_every_position() {
        let mut t = String::from("a #if (A) union { #else merge { #end b");
        let c = conditional_at(&t, 2).unwrap();
        let len = t.len();
        keep_branch(&mut t, &c, Some(0));
        assert_eq!(t.len(), len);
        assert_eq!(
            t.split_whitespace().collect::<Vec<_>>(),
            ["a", "union", "{", "b"]
        );
        let mut t = String::from("#if (A) x #else y #end");
        let c = conditional_at(&t, 0).unwrap();
        keep_branch(&mut t, &c, None);
        assert!(t.trim().is_empty());
    }

    #[test]
    fn loops() {
        let t = "#for (I, 0, 3) #if (I) a #end #end b";
        let l = loop_at(t, 0).unwrap();
        assert_eq!(&t[l.head.clone()], "#for (I, 0, 3)");
        assert_eq!(&t[l.body.clone()], " #if (I) a #end ");
        assert_eq!(l.end.end, t.len() - 2);
    }

    #[test]
    fn the_culprit_is_the_innermost_conditional_outside_loops() {
        let t = "sphere { #if (A) 0 #else x #end, 1 }";
        assert_eq!(culprit(t, 0, 9), Some(Culprit::Choose(9)));
        let t = "union { #if (A) #if (B) union { #else box { #end #end }";
        assert_eq!(culprit(t, 0, 38), Some(Culprit::Choose(16)));
        // Past the conditional: the last one before.
        let t = "union { #if (A) union { #end box {} }";
        assert_eq!(culprit(t, 0, 33), Some(Culprit::Choose(8)));
        // Inside a loop of the statement: not to be chosen.
        let t = "union { #while (I) sphere { #if (A) 0 #else x #end, 1 } #end }";
        assert_eq!(culprit(t, 0, 28), Some(Culprit::InLoop(28)));
        // No conditional at all.
        assert_eq!(culprit("sphere { 0 1 2 }", 0, 11), None);
    }
}
