//! Quick directives: a loop's `#declare X = X + 1;`, `#local V[I][J] = f(I, J);` and
//! `#while (I < N)` read without building their units token by token.
//!
//! Inside a loop or a macro body the same few directives run again and again, and reading
//! each one token by token (each word bound, each token copied into a unit, the unit looked
//! up in the parse cache) is most of a loop's cost. A directive whose text is plain (names,
//! numbers, strings, operators and brackets up to its `;` or its condition's `)`, no other
//! directive, no block, no macro named in it) has its parse kept by where it stands in its
//! file; a pass reads it by binding its words to their values, as the token reader would,
//! and evaluating the kept tree. Anything else (a macro call, `rand`, a value the token
//! reader would end elsewhere) takes the token reader's way.

use super::{Evaluator, FunctionState, InputKind, Statement};
use crate::diag::{Diagnostic, FileId};
use crate::eval::Value;
use crate::syntax::lexer::{Lexer, Token, TokenKind};
use crate::syntax::{self, Expr, Head, Node, Piece, Unit, ValueSyntax};
use std::rc::Rc;
use std::sync::Arc;

type Result<T> = std::result::Result<T, Diagnostic>;

/// A plain directive's reading, kept by where its text starts.
pub(super) enum Quick {
    /// `#declare`/`#local` `Name[…]… = value;`: the head, its words (the first, the name, is
    /// not bound), the value, its words, and where the `;` ends.
    Declare {
        head: Rc<Node>,
        head_words: Vec<Box<str>>,
        value: Rc<ValueSyntax>,
        words: Vec<Box<str>>,
        end: usize,
    },
    /// `(condition)`: the expression, its words, and where the `)` ends.
    Condition {
        expr: Rc<Expr>,
        words: Vec<Box<str>>,
        end: usize,
    },
    /// A top-level statement `word { … }`: its tree, its words, and where its `}` ends.
    Statement {
        node: Rc<Node>,
        words: Vec<Box<str>>,
        end: usize,
    },
    /// Not plain: read token by token.
    No,
}

/// The tokens of a plain stretch of text.
struct Scan<'t> {
    text: &'t str,
    lexer: Lexer<'t>,
    /// The word tokens met.
    words: Vec<Token>,
}

impl<'t> Scan<'t> {
    fn new(text: &'t str, pos: usize, end: usize) -> Scan<'t> {
        Scan {
            text,
            lexer: Lexer::new(text, pos..end),
            words: Vec::new(),
        }
    }

    /// The next token, if it may stand in a plain directive.
    fn next(&mut self) -> Option<Token> {
        let t = self.lexer.next().ok()??;
        match t.kind {
            TokenKind::Word => {
                if matches!(t.text(self.text), "rand" | "function" | "array" | "spline") {
                    return None;
                }
                self.words.push(t);
            }
            TokenKind::Number | TokenKind::Str => {}
            TokenKind::Punct => {}
            _ => return None,
        }
        Some(t)
    }

    /// After an opening `(` or `[`: the tokens to the bracket that closes it, and its end.
    fn group(&mut self) -> Option<usize> {
        let mut depth = 1;
        loop {
            let t = self.next()?;
            match t.text(self.text) {
                ";" | "{" | "}" => return None,
                "(" | "[" => depth += 1,
                ")" | "]" => {
                    depth -= 1;
                    if depth == 0 {
                        return Some(t.end as usize);
                    }
                }
                _ => {}
            }
        }
    }

    /// One operand as the token reader reads one (`Evaluator::operand_from`): signs, then a
    /// number, a string, a parenthesis, a vector, or a name with its call, subscripts and
    /// members; the token after it.
    fn operand(&mut self) -> Option<Token> {
        let mut t = self.next()?;
        while matches!(t.text(self.text), "+" | "-" | "!") {
            t = self.next()?;
        }
        match (t.kind, t.text(self.text)) {
            (TokenKind::Number | TokenKind::Str, _) => self.next(),
            (TokenKind::Punct, "(") => {
                self.group()?;
                self.next()
            }
            (TokenKind::Punct, "<") => {
                // A vector: to the `>` outside brackets (another `<` or `>` in it: not plain).
                let mut depth = 0;
                loop {
                    let t = self.next()?;
                    match t.text(self.text) {
                        "(" | "[" => depth += 1,
                        ")" | "]" => depth -= 1,
                        "<" | "<=" | ">=" | ";" | "{" | "}" => return None,
                        ">" if depth == 0 => break,
                        ">" => return None,
                        _ => {}
                    }
                }
                self.next()
            }
            (TokenKind::Word, w) => {
                if super::COLOUR_TYPES.contains(&w)
                    || super::CHANNELS.contains(&w)
                    || matches!(w, "color" | "colour")
                {
                    return None;
                }
                let mut after = self.next()?;
                if after.text(self.text) == "(" {
                    self.group()?;
                    after = self.next()?;
                }
                while after.text(self.text) == "[" {
                    self.group()?;
                    after = self.next()?;
                }
                while after.text(self.text) == "." {
                    let member = self.next()?;
                    if member.kind != TokenKind::Word {
                        return None;
                    }
                    after = self.next()?;
                }
                Some(after)
            }
            _ => None,
        }
    }
}

impl Evaluator<'_> {
    /// Whether the reader may read a plain directive here: at a directive's head in a loop or
    /// a macro body, nothing read ahead, no function open.
    fn quick_input(&self) -> Option<(FileId, usize)> {
        let r = &self.lang.reader;
        let input = r.inputs.last()?;
        let plain = input.pushback.is_empty()
            && !r.hold
            && !r.raw_words
            && r.functions.open.is_empty()
            && matches!(r.functions.state, FunctionState::Idle)
            && (r.loops > 0 || input.kind == InputKind::Macro);
        plain.then_some((input.file, input.pos))
    }

    /// The kept reading of the directive text at `at` of the current input (scanned with
    /// `scan` the first time).
    fn quick(
        &mut self,
        at: (FileId, usize),
        scan: impl FnOnce(&Arc<String>, usize, usize, FileId) -> Quick,
    ) -> Rc<Quick> {
        if let Some(q) = self.lang.reader.quick.get(&at) {
            return Rc::clone(q);
        }
        let input = self.lang.reader.inputs.last().expect("an input");
        let q = Rc::new(scan(&input.text, input.pos, input.end, input.file));
        self.lang.reader.quick.insert(at, Rc::clone(&q));
        q
    }

    /// The bindings of `words` as the token reader would make them; `None` if one names a
    /// macro (a call: read token by token).
    fn quick_bindings(
        &self,
        words: &[Box<str>],
        first_raw: bool,
    ) -> Option<Vec<Option<Arc<Value>>>> {
        let mut bindings = Vec::with_capacity(words.len());
        for (i, w) in words.iter().enumerate() {
            if i == 0 && first_raw {
                bindings.push(None);
                continue;
            }
            if self.lang.macros.contains_key(&**w) {
                return None;
            }
            bindings.push(self.lang.env.get(&**w).cloned());
        }
        Some(bindings)
    }

    /// `#declare`/`#local` read quickly, if its text is plain: whether it was.
    pub(super) fn quick_declare(&mut self, local: Option<usize>) -> Result<bool> {
        let Some(at) = self.quick_input() else {
            return Ok(false);
        };
        let q = self.quick(at, scan_declare);
        let Quick::Declare {
            head,
            head_words,
            value,
            words,
            end,
        } = &*q
        else {
            return Ok(false);
        };
        let (Some(head_bindings), Some(bindings)) = (
            self.quick_bindings(head_words, true),
            self.quick_bindings(words, false),
        ) else {
            return Ok(false);
        };
        self.lang.reader.inputs.last_mut().expect("an input").pos = *end;
        self.lang.reader.run += 1;
        let value = self
            .with_bindings(bindings, |ev| ev.declared_value(value))
            .map_err(|d| self.noted(d, None))?;
        self.with_bindings(head_bindings, |ev| ev.bind_declared(head, local, value))
            .map_err(|d| self.noted(d, None))?;
        Ok(true)
    }

    /// A statement of a loop's or macro's body read from its kept parse, if its text is
    /// plain (see [`scan_statement`]).
    pub(super) fn quick_statement(&mut self) -> Option<Statement> {
        let at = self.quick_input()?;
        let q = self.quick(at, scan_statement);
        let Quick::Statement { node, words, end } = &*q else {
            return None;
        };
        let bindings = self.quick_bindings(words, false)?;
        self.lang.reader.inputs.last_mut().expect("an input").pos = *end;
        self.lang.reader.run += 1;
        Some(Statement::Kept(Rc::clone(node), bindings))
    }

    /// A directive's `(condition)` read quickly, if its text is plain: its truth.
    pub(super) fn quick_condition(&mut self) -> Result<Option<bool>> {
        let Some(at) = self.quick_input() else {
            return Ok(None);
        };
        let q = self.quick(at, scan_condition);
        let Quick::Condition { expr, words, end } = &*q else {
            return Ok(None);
        };
        let Some(bindings) = self.quick_bindings(words, false) else {
            return Ok(None);
        };
        self.lang.reader.inputs.last_mut().expect("an input").pos = *end;
        self.lang.reader.run += 1;
        self.with_bindings(bindings, |ev| ev.truth(expr))
            .map(Some)
            .map_err(|d| self.noted(d, None))
    }
}

/// A unit of the file's text `start..end` as written, its words at `words`.
fn unit_of(text: &str, file: FileId, start: usize, end: usize, words: &[Token]) -> Unit {
    Unit {
        text: text[start..end].to_string(),
        pieces: vec![Piece {
            at: 0,
            len: (end - start) as u32,
            file,
            start: start as u32,
            src_len: (end - start) as u32,
        }],
        words: words.iter().map(|w| w.start - start as u32).collect(),
        lists: Vec::new(),
    }
}

fn names(text: &str, words: &[Token]) -> Vec<Box<str>> {
    words.iter().map(|w| w.text(text).into()).collect()
}

/// Scans `Name[…]… = value;` from `pos`.
fn scan_declare(text: &Arc<String>, pos: usize, end: usize, file: FileId) -> Quick {
    let mut s = Scan::new(text, pos, end);
    (|| {
        let name = s.next()?;
        if name.kind != TokenKind::Word || matches!(name.text(text), "deprecated" | "once") {
            return None;
        }
        let mut t = s.next()?;
        while t.text(text) == "[" {
            s.group()?;
            t = s.next()?;
        }
        if t.text(text) != "=" {
            return None;
        }
        let head_end = t.end as usize;
        let head_words = std::mem::take(&mut s.words);
        let value_start = s.lexer.position();
        let value_end = s.value_end()?;
        let semicolon_end = s.lexer.position();
        let head = syntax::parse_head(
            &unit_of(text, file, name.start as usize, head_end, &head_words),
            Head::Declare,
        )
        .ok()?;
        let first = lexer_start(text, value_start, value_end)?;
        let value = syntax::parse_value(&unit_of(text, file, first, value_end, &s.words)).ok()?;
        Some(Quick::Declare {
            head: Rc::new(head),
            head_words: names(text, &head_words),
            value: Rc::new(value),
            words: names(text, &s.words),
            end: semicolon_end,
        })
    })()
    .unwrap_or(Quick::No)
}

/// Texts of statements kept at most (a bigger one is read token by token).
const MAX_STATEMENT: usize = 64 * 1024;

/// Scans `word { … }` from `pos`: a statement with no directive, macro, `rand`, function or
/// mesh2 list the fast lane would read (the reader's bulk lane keeps those).
fn scan_statement(text: &Arc<String>, pos: usize, end: usize, file: FileId) -> Quick {
    let mut s = Scan::new(text, pos, end);
    (|| {
        let first = s.next()?;
        if first.kind != TokenKind::Word || s.next()?.text(text) != "{" {
            return None;
        }
        let mut depth = 1;
        let close = loop {
            let t = s.next()?;
            if t.end as usize - first.start as usize > MAX_STATEMENT {
                return None;
            }
            match (t.kind, t.text(text)) {
                (TokenKind::Punct, "{") => depth += 1,
                (TokenKind::Punct, "}") => {
                    depth -= 1;
                    if depth == 0 {
                        break t.end as usize;
                    }
                }
                (TokenKind::Word, w) if syntax::bulk::KEYWORDS.contains(&w) => return None,
                _ => {}
            }
        };
        let node =
            syntax::parse_statement(&unit_of(text, file, first.start as usize, close, &s.words))
                .ok()?;
        Some(Quick::Statement {
            node: Rc::new(node),
            words: names(text, &s.words),
            end: close,
        })
    })()
    .unwrap_or(Quick::No)
}

/// Scans `(condition)` from `pos`.
fn scan_condition(text: &Arc<String>, pos: usize, end: usize, file: FileId) -> Quick {
    let mut s = Scan::new(text, pos, end);
    (|| {
        let open = s.next()?;
        if open.text(text) != "(" {
            return None;
        }
        let close = s.group()?;
        let expr =
            syntax::parse_expr(&unit_of(text, file, open.start as usize, close, &s.words)).ok()?;
        Some(Quick::Condition {
            expr: Rc::new(expr),
            words: names(text, &s.words),
            end: close,
        })
    })()
    .unwrap_or(Quick::No)
}

/// Where the first token at or after `from` starts, if before `to`.
fn lexer_start(text: &str, from: usize, to: usize) -> Option<usize> {
    let t = Lexer::new(text, from..to).next().ok()??;
    Some(t.start as usize)
}

impl Scan<'_> {
    /// Operands joined by `+ - * /` up to a `;` (read): where the last operand ends.
    fn value_end(&mut self) -> Option<usize> {
        loop {
            let after = self.operand()?;
            match after.text(self.text) {
                "+" | "-" | "*" | "/" => {}
                ";" => return Some(after.start as usize),
                _ => return None,
            }
        }
    }
}
