//! The directive reader: POV-Ray's token reader, in front of the grammar.
//!
//! POV-Ray executes a directive where its reader meets it, between any two tokens: `#if`
//! chooses tokens, `#while` and `#for` read their bodies again, a macro call reads the macro's
//! body in its place, `#include` reads another file there, and `#declare` binds a name before
//! the next token is read. This reader does the same, token by token (with the one lexer,
//! `syntax::lexer`), and cuts what is left — directive-free text — into *units* that the
//! grammar reads whole: a statement, a declared value, a macro's arguments, a directive's
//! condition or head ([`syntax::Unit`]). The grammar keeps no rule for directives.
//!
//! Each word of a unit is bound here to the value its name has at that point (a macro's
//! parameter, a loop's counter, a name a `#declare` inside a statement changes), as POV-Ray's
//! reader looks names up when it reads them; evaluation then finds values by slot, never by
//! name. `rand(…)` is evaluated where it is read too (it advances its stream, so the order of
//! its calls is the order of the text, a `#declare` between two of them included).
//!
//! Where a unit ends is decided on tokens, before the grammar reads it: a statement ends at
//! the `}` that closes its block; a declared value at the `}` of its item (textures layered
//! after it), or, for an expression, at the first token that cannot continue it (a `;`, a
//! word, a directive). The reading is linear: each token is lexed once per time it is read,
//! a skipped branch is lexed without being evaluated, and a loop or macro body's units are
//! parsed once per different text (cached by the places they were read from).

use crate::diag::{Diagnostic, FileId, Span};
use crate::eval::lang::flow::{Frame, MAX_INCLUDE_DEPTH, MAX_MACRO_DEPTH, Macro};
use crate::eval::{Evaluator, Result, Value};
use crate::syntax::ahead::Ahead;
use crate::syntax::lexer::{Lexer, Token, TokenKind};
use crate::syntax::{self, Head, Node, NodeKind, Piece, Unit, View};
use std::any::Any;
use std::collections::HashMap;
use std::rc::Rc;
use std::sync::Arc;

mod quick;

/// Evaluation steps a macro call costs (measured: a call of a one-line expression macro takes
/// about as long as four loop passes).
const MACRO_CALL_STEPS: u64 = 4;

/// Words that colour a value: each takes the value after it.
const COLOUR_TYPES: [&str; 8] = [
    "rgb", "rgbf", "rgbt", "rgbft", "srgb", "srgbf", "srgbt", "srgbft",
];
/// A colour's channels, each followed by its value.
const CHANNELS: [&str; 7] = [
    "red", "green", "blue", "filter", "transmit", "gray", "alpha",
];
/// Directives that open a block closed by `#end`.
const OPENERS: [&str; 7] = ["if", "ifdef", "ifndef", "while", "for", "switch", "macro"];

/// Where tokens are read from: the scene file, an included file, or a macro's body.
struct Input {
    file: FileId,
    text: Arc<String>,
    /// The next byte to read.
    pos: usize,
    /// Where the input ends (a macro body's `#end`).
    end: usize,
    kind: InputKind,
    /// The macro calls and includes that led here (for messages).
    context: Option<Arc<Context>>,
    /// Tokens of this input read ahead and handed back (the last is read first): they come
    /// after whatever a directive starts reading meanwhile (an included file's tokens).
    pushback: Vec<Tok>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum InputKind {
    Scene,
    Include,
    Macro,
}

/// A macro call or an include that led to the text being read, for messages ("in macro M,
/// called at …", "included from …").
#[derive(Debug)]
pub(in crate::eval) struct Context {
    parent: Option<Arc<Context>>,
    /// The macro's name; `None` for an include.
    macro_name: Option<String>,
    /// The call or the `#include`.
    at: Span,
}

/// A directive block being read: a branch taken, a loop, a `#switch`.
struct Block {
    kind: BlockKind,
    /// The input it was opened in (its `#end` must be there too).
    input: usize,
    /// The directive that opened it.
    at: Span,
}

enum BlockKind {
    /// A branch of `#if`/`#ifdef`/`#ifndef` being read: `#else` or `#elseif` ends it.
    If,
    /// `#while`: where its condition starts; where its `#end` ends, once met.
    While { cond: usize, end: Option<usize> },
    /// `#for`: the counter, its last value and step, where the body starts.
    For {
        var: String,
        last: f64,
        step: f64,
        body: usize,
    },
    /// A `#switch` whose clause is being read.
    Switch,
}

/// A token as the reader hands it on: where it was read, and what its word is bound to.
#[derive(Clone, Debug)]
pub(in crate::eval) struct Tok {
    kind: TokenKind,
    file: FileId,
    start: u32,
    end: u32,
    /// Tokens of one run follow each other in their file with only blanks and comments
    /// between them.
    run: u64,
    context: Option<Arc<Context>>,
    /// The value of a word that names one.
    binding: Option<Arc<Value>>,
    /// A value the reader computed in place of its text (`rand(…)`).
    stand_in: bool,
    /// Read inside a loop or a macro body: its unit may be read again.
    repeat: bool,
    /// A word read ahead while directives were held: not bound yet, no macro called.
    unread: bool,
}

impl Tok {
    /// Whether the token is the punctuation `p`.
    fn is(&self, ev: &Evaluator<'_>, p: &str) -> bool {
        self.kind == TokenKind::Punct && ev.text_of(self) == p
    }

    /// A directive token's word (`#  while` → `while`).
    fn word_of<'e>(&self, ev: &'e Evaluator<'_>) -> &'e str {
        ev.text_of(self)[1..].trim_start_matches([' ', '\t'])
    }

    fn span(&self) -> Span {
        Span {
            file: self.file,
            start: self.start,
            end: self.end,
        }
    }
}

/// Function parameters, which stand unbound inside their function's body
/// (`function (a, b) { a * b }`).
#[derive(Default)]
struct FunctionScopes {
    state: FunctionState,
    /// Open bodies: their parameters and the brace depth inside them.
    open: Vec<(Vec<String>, u32)>,
    depth: u32,
}

#[derive(Default)]
enum FunctionState {
    #[default]
    Idle,
    /// After `function`.
    Keyword,
    /// Reading the parameters.
    Params(Vec<String>),
    /// After the parameters' `)`.
    Closed(Vec<String>),
}

/// The reader's state (part of the evaluator).
#[derive(Default)]
pub(in crate::eval) struct Reader {
    inputs: Vec<Input>,
    blocks: Vec<Block>,
    /// Counts every jump of the reading (a directive, a skip, an input started or ended).
    run: u64,
    functions: FunctionScopes,
    /// While set, words are handed on as written: not bound, no macro called (a name being
    /// declared).
    raw_words: bool,
    /// While set, a directive met is handed on, not run (see `Evaluator::held`).
    hold: bool,
    /// Loops open (`#while`, `#for`): their bodies' units are read again.
    loops: usize,
    /// Parses of units read again and again (see `Evaluator::parsed`).
    parses: HashMap<(Parse, u64), CachedParse>,
    /// Plain directives' readings, by where their text starts (see `quick`).
    quick: HashMap<(FileId, usize), Rc<quick::Quick>>,
    /// The plain statements of the big file being read, read ahead (see `syntax::ahead`).
    ahead: Option<Ahead>,
}

/// Files from this size on have their plain statements read ahead on a second thread (a
/// smaller file is read before the thread would have started).
const AHEAD_FROM: usize = 1 << 20;

impl Reader {
    /// Frees a plain statement's tree, on the thread that read it ahead if one did.
    fn free(&mut self, node: Node) {
        match &mut self.ahead {
            Some(ahead) if ahead.file() == node.span.file => ahead.free(node),
            _ => drop(node),
        }
    }
}

/// A top-level statement read: a unit for the grammar, or a plain statement the fast lane
/// read (with the bindings of its names).
pub(in crate::eval) enum Statement {
    Unit(Emitted),
    Plain(Node, Vec<Option<Arc<Value>>>),
    /// A plain statement of a loop's or macro's body, read from its kept parse (see `quick`).
    Kept(Rc<Node>, Vec<Option<Arc<Value>>>),
}

/// What a unit was parsed as (part of the parse cache's key).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Parse {
    Statement,
    Value,
    Args,
    Expr,
    Head(Head),
}

/// A unit's parse kept for its next reading: the places its text came from, and the tree.
type CachedParse = (Vec<Piece>, Rc<dyn Any>);

/// Units parsed from a loop's or macro's body kept at most (the cache is emptied when full).
const MAX_CACHED_PARSES: usize = 4096;

/// A unit read, with each word's binding and what led to each piece.
pub(in crate::eval) struct Emitted {
    pub unit: Unit,
    pub bindings: Vec<Option<Arc<Value>>>,
    /// The context of each piece of the unit.
    contexts: Vec<Option<Arc<Context>>>,
    /// Some of it was read inside a loop or macro body.
    pub repeat: bool,
    /// A bracket the scene ended without closing.
    unclosed: Option<Span>,
}

/// Whether a word bound to `binding` ends a value where a `(` follows it. In POV-Ray only a
/// function or a spline is called with `(`: after any other declared value, a `(` starts the
/// next one (`sphere { Centre (R + 1) }`), so the grammar is shown a comma there.
fn ends_value(binding: Option<&Arc<Value>>) -> bool {
    binding.is_some_and(|v| !matches!(**v, Value::Function(_) | Value::Spline(_)))
}

/// Builds a unit from the tokens handed to it.
#[derive(Default)]
struct Emitter {
    unit: Unit,
    bindings: Vec<Option<Arc<Value>>>,
    contexts: Vec<Option<Arc<Context>>>,
    repeat: bool,
    /// The last token's file, end and run (`None` after a stand-in).
    last: Option<(FileId, u32, u64)>,
    /// A bracket the scene ended without closing.
    unclosed: Option<Span>,
    /// The last token was a word bound to a value that cannot be called (see [`ends_value`]).
    ends_value: bool,
}

/// The text a value computed by the reader stands as: a word, bound to the value.
const STAND_IN: &str = "__value";

impl Emitter {
    /// Appends `tok` (of file text `text`) to the unit.
    fn push(&mut self, tok: &Tok, text: &str) {
        self.repeat |= tok.repeat;
        if self.ends_value
            && !tok.stand_in
            && text.as_bytes().get(tok.start as usize) == Some(&b'(')
        {
            self.separate(tok);
        }
        self.ends_value =
            (tok.stand_in || tok.kind == TokenKind::Word) && ends_value(tok.binding.as_ref());
        let u = &mut self.unit;
        if tok.stand_in {
            if !u.text.is_empty() {
                u.text.push(' ');
            }
            let at = u.text.len() as u32;
            u.pieces.push(Piece {
                at,
                len: STAND_IN.len() as u32,
                file: tok.file,
                start: tok.start,
                src_len: tok.end - tok.start,
            });
            self.contexts.push(tok.context.clone());
            u.words.push(at);
            u.text.push_str(STAND_IN);
            self.bindings.push(tok.binding.clone());
            self.last = None;
            return;
        }
        // (Tokens read one after the other with only blanks and comments between them share a
        // piece: the unit keeps the file's text, and its offsets map back by one addition.)
        let adjacent = matches!(self.last, Some((f, end, run))
            if f == tok.file && run == tok.run && tok.start >= end
                && crate::syntax::lexer::skip_trivia(text.as_bytes(), end as usize, tok.start as usize)
                    == Ok(tok.start as usize));
        let at;
        if adjacent {
            let (_, end, _) = self.last.expect("adjacent");
            let piece = u.pieces.last_mut().expect("a piece");
            u.text.push_str(&text[end as usize..tok.end as usize]);
            let grown = tok.end - end;
            piece.len += grown;
            piece.src_len += grown;
            at = u.text.len() as u32 - (tok.end - tok.start);
        } else {
            if !u.text.is_empty() {
                u.text.push(' ');
            }
            at = u.text.len() as u32;
            u.pieces.push(Piece {
                at,
                len: tok.end - tok.start,
                file: tok.file,
                start: tok.start,
                src_len: tok.end - tok.start,
            });
            self.contexts.push(tok.context.clone());
            u.text.push_str(&text[tok.start as usize..tok.end as usize]);
        }
        if tok.kind == TokenKind::Word {
            u.words.push(at);
            self.bindings.push(tok.binding.clone());
        }
        self.last = Some((tok.file, tok.end, tok.run));
    }

    /// A comma before `tok` (a `(` after a value that cannot be called): a piece of its own,
    /// standing for no text of the file.
    fn separate(&mut self, tok: &Tok) {
        let u = &mut self.unit;
        u.text.push(' ');
        u.pieces.push(Piece {
            at: u.text.len() as u32,
            len: 1,
            file: tok.file,
            start: tok.start,
            src_len: 0,
        });
        self.contexts.push(tok.context.clone());
        u.text.push(',');
        self.last = None;
    }

    /// A run of tokens read in one pass (`Evaluator::plain_run`): the text of `run` (its
    /// start and end) with `words` at the file offsets given, each bound as given.
    fn push_run(&mut self, run: &Tok, text: &str, words: &mut Vec<(u32, Option<Arc<Value>>)>) {
        // The run as one token (its words added after).
        let as_token = Tok {
            kind: TokenKind::Punct,
            ..run.clone()
        };
        self.push(&as_token, text);
        let piece = *self.unit.pieces.last().expect("a piece");
        for (at, binding) in words.drain(..) {
            self.unit.words.push(piece.at + (at - piece.start));
            self.bindings.push(binding);
        }
    }

    /// A mesh2 list read by the fast lane: a marker in the unit, for the body at bytes
    /// `start..end` of `file`.
    fn push_list(&mut self, list: syntax::bulk::BulkList, file: FileId, start: usize, end: usize) {
        let u = &mut self.unit;
        u.text.push(' ');
        let at = u.text.len() as u32;
        u.pieces.push(Piece {
            at,
            len: syntax::bulk::MARKER.len() as u32,
            file,
            start: start as u32,
            src_len: (end - start) as u32,
        });
        self.contexts.push(None);
        u.text.push_str(syntax::bulk::MARKER);
        u.lists.push((at, list));
        self.last = None;
    }

    /// Where the last token pushed stands in its file.
    fn last_span(&self) -> Option<Span> {
        let end = self.unit.text.len().checked_sub(1)?;
        Some(self.unit.span(end, end + 1))
    }

    /// An empty emitter with the buffers of a unit read before.
    fn reusing(mut used: Emitted) -> Emitter {
        used.unit.text.clear();
        used.unit.pieces.clear();
        used.unit.words.clear();
        used.unit.lists.clear();
        used.bindings.clear();
        used.contexts.clear();
        Emitter {
            unit: used.unit,
            bindings: used.bindings,
            contexts: used.contexts,
            ..Emitter::default()
        }
    }

    fn finish(self) -> Emitted {
        Emitted {
            unit: self.unit,
            bindings: self.bindings,
            contexts: self.contexts,
            repeat: self.repeat,
            unclosed: self.unclosed,
        }
    }
}

impl Emitted {
    /// The context of the piece holding `span`, if any.
    fn context_of(&self, span: Span) -> Option<&Arc<Context>> {
        self.unit
            .pieces
            .iter()
            .zip(&self.contexts)
            .find(|(p, _)| {
                p.file == span.file && p.start <= span.start && span.start < p.start + p.src_len
            })
            .and_then(|(_, c)| c.as_ref())
    }
}

impl<'a> Evaluator<'a> {
    /// Starts reading the scene file `file`.
    pub(in crate::eval) fn read_scene(&mut self, file: FileId) -> Result<()> {
        let text = self.sources.file(file).text.clone();
        let end = text.len();
        self.lang.reader.inputs.push(Input {
            file,
            text,
            pos: 0,
            end,
            kind: InputKind::Scene,
            context: None,
            pushback: Vec::new(),
        });
        let read = (|| {
            while let Some(statement) = self.read_statement()? {
                self.run_statement(statement)?;
            }
            Ok(())
        })();
        read.map_err(|d| self.noted(d, None))
    }

    /// Parses and evaluates one statement unit.
    fn run_statement(&mut self, statement: Statement) -> Result<()> {
        match statement {
            Statement::Plain(node, bindings) => {
                let result = self.run_tree(&node, bindings, None);
                self.lang.reader.free(node);
                result
            }
            Statement::Kept(node, bindings) => self.run_tree(&node, bindings, None),
            Statement::Unit(mut em) => {
                let node = self.parsed(&em, Parse::Statement, syntax::parse_statement)?;
                let bindings = std::mem::take(&mut em.bindings);
                self.run_tree(&node, bindings, Some(&em))
            }
        }
    }

    /// Evaluates a statement's tree with the bindings of its names; `em`, the unit it was
    /// read from, places its errors.
    fn run_tree(
        &mut self,
        node: &Node,
        bindings: Vec<Option<Arc<Value>>>,
        em: Option<&Emitted>,
    ) -> Result<()> {
        let result = self.with_bindings(bindings, |ev| {
            ev.charge(1, "statement", node.word_span)?;
            ev.statement(node)
        });
        result.map_err(|d| self.noted(d, em))
    }

    /// The grammar's reading of `em` (by `parse`, as `what`): parsed once for each different
    /// text of a unit read again and again (a loop's or a macro's body), by the places its
    /// text came from.
    fn parsed<T: 'static>(
        &mut self,
        em: &Emitted,
        what: Parse,
        parse: impl FnOnce(&Unit) -> Result<T>,
    ) -> Result<Rc<T>> {
        if !em.repeat {
            return parse(&em.unit)
                .map(Rc::new)
                .map_err(|d| self.noted(d, Some(em)));
        }
        let key = (what, pieces_key(&em.unit.pieces));
        if let Some((pieces, hit)) = self.lang.reader.parses.get(&key) {
            if *pieces == em.unit.pieces {
                if let Ok(t) = Rc::clone(hit).downcast::<T>() {
                    return Ok(t);
                }
            }
        }
        let t = Rc::new(parse(&em.unit).map_err(|d| self.noted(d, Some(em)))?);
        if self.lang.reader.parses.len() >= MAX_CACHED_PARSES {
            self.lang.reader.parses.clear();
        }
        self.lang
            .reader
            .parses
            .insert(key, (em.unit.pieces.clone(), t.clone()));
        Ok(t)
    }

    /// Runs `f` with the bindings of the unit it evaluates.
    pub(in crate::eval) fn with_bindings<T>(
        &mut self,
        bindings: Vec<Option<Arc<Value>>>,
        f: impl FnOnce(&mut Self) -> T,
    ) -> T {
        let outer = std::mem::replace(&mut self.lang.bindings, bindings);
        let shift = std::mem::take(&mut self.lang.slot_shift);
        let result = f(self);
        self.lang.bindings = outer;
        self.lang.slot_shift = shift;
        result
    }

    /// The diagnostic with the macro calls and includes that led to where it points (those
    /// of `unit`'s piece holding it, or else those of the text being read).
    pub(in crate::eval) fn noted(&self, d: Diagnostic, unit: Option<&Emitted>) -> Diagnostic {
        // (Noted once: a diagnostic passing through several readers keeps the first notes.)
        if d.notes.iter().any(|n| is_context_note(n)) {
            return d;
        }
        let d = match unit.and_then(|u| u.unclosed) {
            Some(open) => d.with_note(format!(
                "the bracket at {} is never closed (the scene ends first)",
                self.location(open)
            )),
            None => d,
        };
        let context = d
            .span
            .and_then(|s| unit.and_then(|u| u.context_of(s)))
            .cloned()
            .or_else(|| {
                self.lang
                    .reader
                    .inputs
                    .last()
                    .and_then(|i| i.context.clone())
            });
        let mut d = d;
        let mut at = context;
        if at.is_none() {
            // (Marked as noted, with nothing to add.)
            return d;
        }
        while let Some(c) = at {
            d = d.with_note(match &c.macro_name {
                Some(name) => format!("in macro {name}, called at {}", self.location(c.at)),
                None => format!("included from {}", self.location(c.at)),
            });
            at = c.parent.clone();
        }
        d
    }

    // ---------------------------------------------------------------------------------------
    // Tokens

    /// The next token, directives carried out and macros called on the way; `None` at the end
    /// of the scene.
    fn next_token(&mut self) -> Result<Option<Tok>> {
        loop {
            if let Some(t) = self
                .lang
                .reader
                .inputs
                .last_mut()
                .and_then(|i| i.pushback.pop())
            {
                // A directive read ahead while held, now read where it may run.
                if t.kind == TokenKind::Directive && !self.held(&t) {
                    self.run_directive(&t)?;
                    continue;
                }
                // A word read ahead while held, now read.
                if t.unread && !self.lang.reader.hold && !self.lang.reader.raw_words {
                    let t = Tok { unread: false, ..t };
                    match self.word(t)? {
                        Some(t) => {
                            self.track_functions(&t);
                            return Ok(Some(t));
                        }
                        None => continue,
                    }
                }
                return Ok(Some(t));
            }
            let Some((raw, input)) = self.raw_token()? else {
                if self.lang.reader.inputs.is_empty() {
                    return Ok(None);
                }
                self.end_input()?;
                if self.lang.reader.inputs.is_empty() {
                    return Ok(None);
                }
                continue;
            };
            let tok = self.tok(raw, input);
            match raw.kind {
                TokenKind::Directive if self.held(&tok) => return Ok(Some(tok)),
                TokenKind::Directive => self.run_directive(&tok)?,
                // (A `#` with no word after it is nothing to POV-Ray.)
                TokenKind::Hash => {}
                // (While held, a word is handed on unread: it may call a macro, which waits
                // with the rest until the value before it is bound.)
                TokenKind::Word if self.lang.reader.hold => {
                    return Ok(Some(Tok {
                        unread: true,
                        ..tok
                    }));
                }
                TokenKind::Word if !self.lang.reader.raw_words => {
                    if let Some(tok) = self.word(tok)? {
                        self.track_functions(&tok);
                        return Ok(Some(tok));
                    }
                }
                _ => {
                    self.track_functions(&tok);
                    return Ok(Some(tok));
                }
            }
        }
    }

    /// Carries out the directive token `tok`.
    fn run_directive(&mut self, tok: &Tok) -> Result<()> {
        self.lang.reader.run += 1;
        let word = tok.word_of(self).to_string();
        // (Messages point at the directive's word.)
        let span = Span {
            start: tok.end - word.len() as u32,
            ..tok.span()
        };
        self.directive(&word, span)?;
        self.lang.reader.run += 1;
        Ok(())
    }

    /// Whether directive `tok` waits, read while a declared value is complete (POV-Ray reads
    /// no directive then: the value ends there, and the directive runs once it is bound). An
    /// `#else`, `#elseif` or `#end` of a conditional runs: it chooses no value
    /// (`#declare X = #if (c) A #else B #end`, as exporters write it).
    fn held(&self, tok: &Tok) -> bool {
        if !self.lang.reader.hold {
            return false;
        }
        match tok.word_of(self) {
            "else" | "elseif" => false,
            "end" => !matches!(
                self.lang.reader.blocks.last().map(|b| &b.kind),
                Some(BlockKind::If | BlockKind::Switch)
            ),
            _ => true,
        }
    }

    /// The next token, with directives held (see [`Evaluator::held`]), handed back.
    fn peek_held(&mut self) -> Result<Option<Tok>> {
        let outer = std::mem::replace(&mut self.lang.reader.hold, true);
        let t = self.peek_token();
        self.lang.reader.hold = outer;
        t
    }

    /// The next token without reading past it.
    fn peek_token(&mut self) -> Result<Option<Tok>> {
        let t = self.next_token()?;
        if let Some(t) = &t {
            self.unget(t.clone());
        }
        Ok(t)
    }

    /// Hands `t` back: the next token read is `t`.
    fn unget(&mut self, t: Tok) {
        if let Some(input) = self.lang.reader.inputs.last_mut() {
            input.pushback.push(t);
        }
    }

    /// The next token of the current input as the lexer reads it, with the input's index;
    /// `None` at the input's end.
    fn raw_token(&mut self) -> Result<Option<(Token, usize)>> {
        let index = self.lang.reader.inputs.len().checked_sub(1);
        let Some(index) = index else {
            return Ok(None);
        };
        let input = &mut self.lang.reader.inputs[index];
        let mut lexer = Lexer::new(&input.text, input.pos..input.end);
        let token = lexer
            .next()
            .map_err(|e| Diagnostic::error(e.message, Span::new(input.file, e.at, e.at + 1)))?;
        input.pos = lexer.position();
        Ok(token.map(|t| (t, index)))
    }

    /// A raw token of input `input` as the reader hands it on (unbound).
    fn tok(&self, raw: Token, input: usize) -> Tok {
        let i = &self.lang.reader.inputs[input];
        Tok {
            kind: raw.kind,
            file: i.file,
            start: raw.start,
            end: raw.end,
            run: self.lang.reader.run,
            context: i.context.clone(),
            binding: None,
            stand_in: false,
            repeat: i.kind == InputKind::Macro || self.lang.reader.loops > 0,
            unread: false,
        }
    }

    /// The text of `tok`.
    fn text_of(&self, tok: &Tok) -> &str {
        &self.sources.file(tok.file).text[tok.start as usize..tok.end as usize]
    }

    /// A word read: a macro's name calls the macro (`None`: read on); `rand(…)` is evaluated
    /// (a stand-in for its value); a declared name is bound to its value.
    fn word(&mut self, mut tok: Tok) -> Result<Option<Tok>> {
        let text = Arc::clone(&self.sources.file(tok.file).text);
        let word = &text[tok.start as usize..tok.end as usize];
        if self.in_function_params(word) {
            return Ok(Some(tok));
        }
        if self.lang.macros.contains_key(word) {
            self.call_macro(word, &tok)?;
            return Ok(None);
        }
        if word == "rand" && self.lang.reader.functions.open.is_empty() {
            if let Some(value) = self.rand_in_place(&tok)? {
                return Ok(Some(value));
            }
        }
        tok.binding = self.lang.env.get(word).cloned();
        Ok(Some(tok))
    }

    /// `rand(S)` read where it stands: a stand-in bound to its value.
    fn rand_in_place(&mut self, tok: &Tok) -> Result<Option<Tok>> {
        let Some(open) = self.next_token()? else {
            return Ok(None);
        };
        if !open.is(self, "(") {
            self.unget(open);
            return Ok(None);
        }
        let args = self.group_from(open)?;
        let exprs = self.parsed(&args, Parse::Args, syntax::parse_args)?;
        let end = args.unit.span(0, args.unit.text.len()).end;
        let span = Span { end, ..tok.span() };
        let value = self
            .with_bindings(args.bindings.clone(), |ev| {
                ev.call("rand", tok.span(), syntax::Slot::NONE, &exprs, span)
            })
            .map_err(|d| self.noted(d, Some(&args)))?;
        self.lang.reader.run += 1;
        Ok(Some(Tok {
            end: if span.file == tok.file {
                end.max(tok.end)
            } else {
                tok.end
            },
            binding: Some(Arc::new(value)),
            stand_in: true,
            ..tok.clone()
        }))
    }

    /// Whether `word` is a parameter of a function whose body (or parameter list) is being
    /// read: left unbound.
    fn in_function_params(&self, word: &str) -> bool {
        let f = &self.lang.reader.functions;
        if f.open.is_empty() && matches!(f.state, FunctionState::Idle) {
            return false;
        }
        matches!(f.state, FunctionState::Params(_))
            || f.open
                .iter()
                .any(|(params, _)| params.iter().any(|p| p == word))
    }

    /// Follows `function (params) { … }` through the tokens handed on.
    fn track_functions(&mut self, tok: &Tok) {
        let text = &self.sources.file(tok.file).text;
        let text = &text[tok.start as usize..tok.end as usize];
        let f = &mut self.lang.reader.functions;
        // (Outside functions only the word `function` matters.)
        if f.open.is_empty() && matches!(f.state, FunctionState::Idle) {
            if tok.kind == TokenKind::Word && text == "function" && !tok.stand_in {
                f.state = FunctionState::Keyword;
                f.depth = 0;
            }
            return;
        }
        let punct = |p: &str| tok.kind == TokenKind::Punct && text == p;
        if punct("{") {
            f.depth += 1;
            match std::mem::take(&mut f.state) {
                FunctionState::Keyword => f.open.push((Vec::new(), f.depth)),
                FunctionState::Closed(params) => f.open.push((params, f.depth)),
                _ => {}
            }
            return;
        }
        if punct("}") {
            if f.open.last().is_some_and(|(_, d)| *d == f.depth) {
                f.open.pop();
            }
            f.depth = f.depth.saturating_sub(1);
            f.state = FunctionState::Idle;
            return;
        }
        f.state = match std::mem::take(&mut f.state) {
            _ if tok.kind == TokenKind::Word && text == "function" && !tok.stand_in => {
                FunctionState::Keyword
            }
            FunctionState::Keyword if punct("(") => FunctionState::Params(Vec::new()),
            FunctionState::Params(mut params) if tok.kind == TokenKind::Word => {
                params.push(text.to_string());
                FunctionState::Params(params)
            }
            FunctionState::Params(params) if punct(",") => FunctionState::Params(params),
            FunctionState::Params(params) if punct(")") => FunctionState::Closed(params),
            _ => FunctionState::Idle,
        };
    }

    // ---------------------------------------------------------------------------------------
    // Units

    /// A plain statement where one starts (literal values only, as `syntax::plain` reads
    /// them), read in one pass with its names bound; `None` to read it the usual way.
    fn plain_statement(&mut self) -> Option<Statement> {
        let r = &mut self.lang.reader;
        let input = r.inputs.last()?;
        if !input.pushback.is_empty() || r.hold || r.raw_words || !r.functions.open.is_empty() {
            return None;
        }
        let plain = if input.kind != InputKind::Macro && input.text.len() >= AHEAD_FROM {
            if !r
                .ahead
                .as_ref()
                .is_some_and(|a| a.reads(&input.text, input.end))
            {
                let threads = self
                    .options
                    .threads
                    .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
                let text = Arc::clone(&input.text);
                r.ahead = Some(Ahead::new(text, input.file, input.end, threads > 1));
            }
            r.ahead.as_mut()?.statement(input.pos)?
        } else {
            syntax::plain::read(&input.text, input.pos, input.file, input.end)?
        };
        // The names' bindings, in the order of their slots; a name of a macro sends the
        // statement to the usual reading, which calls it.
        let mut bindings = Vec::with_capacity(plain.names.spans().len());
        for span in plain.names.spans() {
            let name = &input.text[span.start as usize..span.end as usize];
            if self.lang.macros.contains_key(name) {
                r.free(plain.node);
                return None;
            }
            bindings.push(self.lang.env.get(name).cloned());
        }
        let input = r.inputs.last_mut()?;
        input.pos = plain.end;
        r.run += 1;
        Some(Statement::Plain(plain.node, bindings))
    }

    /// Runs the directives before the next statement (a loop's `#end` that goes back to its
    /// body, the next `#declare` …), as reading its first token would, so that the statement
    /// starts where the fast lanes look for it.
    fn leading_directives(&mut self) -> Result<()> {
        loop {
            let Some(input) = self.lang.reader.inputs.last() else {
                return Ok(());
            };
            if !input.pushback.is_empty() || self.lang.reader.hold || self.lang.reader.raw_words {
                return Ok(());
            }
            let ahead = Lexer::new(&input.text, input.pos..input.end).next();
            let Ok(Some(raw)) = ahead else {
                return Ok(());
            };
            if raw.kind != TokenKind::Directive {
                return Ok(());
            }
            let index = self.lang.reader.inputs.len() - 1;
            self.lang.reader.inputs[index].pos = raw.end as usize;
            let tok = self.tok(raw, index);
            self.run_directive(&tok)?;
        }
    }

    /// The next top-level statement; `None` at the end of the scene.
    fn read_statement(&mut self) -> Result<Option<Statement>> {
        self.leading_directives()?;
        if let Some(kept) = self.quick_statement() {
            return Ok(Some(kept));
        }
        if let Some(plain) = self.plain_statement() {
            return Ok(Some(plain));
        }
        let Some(first) = self.next_token()? else {
            return Ok(None);
        };
        // Directives without their `#` (POV-Ray's older syntax), read at the top level as
        // POV-Ray reads them.
        if first.kind == TokenKind::Word && first.binding.is_none() && !first.stand_in {
            let word = self.text_of(&first).to_string();
            if matches!(word.as_str(), "declare" | "include" | "version" | "local") {
                return self.directive_without_hash(&word, first.span());
            }
        }
        let mut em = Emitter::default();
        self.emit(&mut em, &first);
        if first.binding.is_some() && !first.stand_in {
            // A declared object standing alone, or an array's element (`Cube[I]`).
            while self.peek_held_is("[")? {
                let open = self.next_token()?.expect("peeked");
                self.emit(&mut em, &open);
                self.rest_of_group(&mut em, 1)?;
            }
            return Ok(Some(Statement::Unit(em.finish())));
        }
        if first.kind == TokenKind::Word
            && first.binding.is_none()
            && matches!(
                self.text_of(&first),
                "max_trace_level" | "max_intersections"
            )
        {
            // Global settings POV-Ray reads outside global_settings: the word and its value.
            if let Some(t) = self.next_token()? {
                self.expression_from(&mut em, t)?;
            }
            return Ok(Some(Statement::Unit(em.finish())));
        }
        if first.kind == TokenKind::Word && first.binding.is_none() && !first.stand_in {
            if let Some(next) = self.peek_token()? {
                if next.is(self, "{") {
                    self.next_token()?;
                    self.emit(&mut em, &next);
                    self.rest_of_group(&mut em, 1)?;
                }
            }
        }
        Ok(Some(Statement::Unit(em.finish())))
    }

    fn emit(&self, em: &mut Emitter, tok: &Tok) {
        em.push(tok, &self.sources.file(tok.file).text);
    }

    /// The tokens of a group whose opening bracket (`{`, `(` or `[`) is `open`, read.
    fn group_from(&mut self, open: Tok) -> Result<Emitted> {
        let mut em = Emitter::default();
        self.emit(&mut em, &open);
        self.rest_of_group(&mut em, 1)?;
        Ok(em.finish())
    }

    /// Reads tokens into `em` until the brackets open (`depth` of them) close; at the scene's
    /// end first, the bracket left open is noted (the grammar says where the text stops
    /// making sense, as POV-Ray does).
    fn rest_of_group(&mut self, em: &mut Emitter, depth: usize) -> Result<()> {
        let mut open: Vec<Span> = vec![em.last_span().unwrap_or_default(); depth];
        while !open.is_empty() {
            if self.plain_run(em, &mut open, None)? {
                continue;
            }
            let Some(t) = self.next_token()? else {
                em.unclosed = open.last().copied();
                return Ok(());
            };
            if t.kind == TokenKind::Punct {
                match self.text_of(&t) {
                    "{" | "(" | "[" => open.push(t.span()),
                    "}" | ")" | "]" => {
                        open.pop();
                    }
                    _ => {}
                }
            }
            self.emit(em, &t);
            if t.kind == TokenKind::Word
                && t.binding.is_none()
                && t.end - t.start >= 10
                && syntax::bulk::KEYWORDS.contains(&self.text_of(&t))
                && !self.bulk_list(em)
            {
                self.evaluated_list(em)?;
            }
        }
        Ok(())
    }

    /// Reads a run of tokens that need nothing but their names bound and their brackets
    /// counted (no directive, macro, `rand`, `function` or mesh2 list among them) straight from
    /// the current input, up to the group's end or to the first token that needs more (left to
    /// be read the usual way): the same unit as token by token, in one pass. `false` when no
    /// token was read so.
    ///
    /// With `angles` (inside a vector, after its `<`): `<` and `>` outside brackets count as
    /// the vector's own, and the run ends with the `>` that closes it.
    fn plain_run(
        &mut self,
        em: &mut Emitter,
        open: &mut Vec<Span>,
        mut angles: Option<&mut usize>,
    ) -> Result<bool> {
        let r = &self.lang.reader;
        let Some(input) = r.inputs.last() else {
            return Ok(false);
        };
        if !input.pushback.is_empty()
            || r.hold
            || r.raw_words
            || !r.functions.open.is_empty()
            || !matches!(r.functions.state, FunctionState::Idle)
        {
            return Ok(false);
        }
        let text = Arc::clone(&input.text);
        let (file, end) = (input.file, input.end);
        let mut lexer = Lexer::new(&text, input.pos..end);
        // (first token's start, last token's end), the words read with their bindings.
        let mut run: Option<(usize, usize)> = None;
        let mut words: Vec<(u32, Option<Arc<Value>>)> = Vec::new();
        let mut stop = lexer.position();
        // Whether the last token was a word bound to a value that cannot be called.
        let mut last_ends_value = false;
        loop {
            let before = lexer.position();
            let t = match lexer.next() {
                Ok(Some(t)) => t,
                // (The usual reading reports what the lexer cannot read, and ends inputs.)
                Ok(None) | Err(_) => break,
            };
            let word = t.text(&text);
            let mut this_ends_value = false;
            match t.kind {
                TokenKind::Word => {
                    if self.lang.macros.contains_key(word)
                        || matches!(word, "rand" | "function")
                        || (word.len() >= 10 && syntax::bulk::KEYWORDS.contains(&word))
                    {
                        stop = before;
                        break;
                    }
                    let binding = self.lang.env.get(word).cloned();
                    this_ends_value = ends_value(binding.as_ref());
                    words.push((t.start, binding));
                }
                // (A `(` after a value that cannot be called is read the usual way: the
                // grammar is shown a comma before it.)
                TokenKind::Punct if word == "(" && last_ends_value => {
                    stop = before;
                    break;
                }
                TokenKind::Punct => match word {
                    "{" | "(" | "[" => open.push(Span::new(file, t.start as usize, t.end as usize)),
                    "}" | ")" | "]" => {
                        open.pop();
                    }
                    "<" | ">" if open.is_empty() => {
                        if let Some(a) = angles.as_deref_mut() {
                            *a = if word == "<" { *a + 1 } else { *a - 1 };
                        }
                    }
                    _ => {}
                },
                TokenKind::Number | TokenKind::Str | TokenKind::Unknown => {}
                TokenKind::Directive | TokenKind::Hash => {
                    stop = before;
                    break;
                }
            }
            run = Some((run.map_or(t.start as usize, |(s, _)| s), t.end as usize));
            last_ends_value = this_ends_value;
            stop = lexer.position();
            let done = match angles.as_deref() {
                Some(a) => *a == 0,
                None => open.is_empty(),
            };
            if done {
                break;
            }
        }
        let Some((start, run_end)) = run else {
            return Ok(false);
        };
        let input = self.lang.reader.inputs.last_mut().expect("an input");
        input.pos = stop;
        let first = Tok {
            kind: TokenKind::Punct,
            file,
            start: start as u32,
            end: run_end as u32,
            run: self.lang.reader.run,
            context: input.context.clone(),
            binding: None,
            stand_in: false,
            repeat: input.kind == InputKind::Macro || self.lang.reader.loops > 0,
            unread: false,
        };
        em.push_run(&first, &text, &mut words);
        // (A run ending with such a word: a `(` after it starts another value.)
        em.ends_value = last_ends_value;
        Ok(true)
    }

    /// After a mesh2 list's word: its `{ … }`, if it is a plain list of many entries, read by
    /// the fast lane (`syntax::bulk`) straight from the text, a marker standing for its body
    /// in the unit.
    fn bulk_list(&mut self, em: &mut Emitter) -> bool {
        let Some(input) = self.lang.reader.inputs.last() else {
            return false;
        };
        if !input.pushback.is_empty() {
            return false;
        }
        let b = input.text.as_bytes();
        let Ok(open) = crate::syntax::lexer::skip_trivia(b, input.pos, input.end) else {
            return false;
        };
        if b.get(open) != Some(&b'{') {
            return false;
        }
        let Some((list, close)) = self
            .options
            .lists
            .read_list(&input.text, open + 1, input.end)
        else {
            return false;
        };
        let at = |start: usize, end: usize| Tok {
            kind: TokenKind::Punct,
            file: input.file,
            start: start as u32,
            end: end as u32,
            run: self.lang.reader.run,
            context: input.context.clone(),
            binding: None,
            stand_in: false,
            repeat: false,
            unread: false,
        };
        let (open_tok, close_tok) = (at(open, open + 1), at(close, close + 1));
        let file = input.file;
        let text = input.text.clone();
        em.push(&open_tok, &text);
        em.push_list(list, file, open + 1, close);
        em.push(&close_tok, &text);
        self.lang.reader.inputs.last_mut().expect("an input").pos = close + 1;
        self.lang.reader.run += 1;
        true
    }

    /// After a mesh2 list's word whose body the fast lane left (entries a loop or a macro
    /// makes, expressions): its `{ … }` read entry by entry, each entry evaluated where it
    /// stands (as POV-Ray reads a list: the values its names have there are the values they
    /// would have when the statement is evaluated). A list of 3-vectors becomes a list of the
    /// fast lane's; in any other, each entry stands in the unit as one word bound to its value.
    /// Either way the unit holds no entry's tokens: a list of a million entries a loop made
    /// costs its values, not its text.
    fn evaluated_list(&mut self, em: &mut Emitter) -> Result<()> {
        if !self.peek_held_is("{")? {
            return Ok(());
        }
        let open = self.next_token()?.expect("peeked");
        let mut entries: Vec<(Value, Tok)> = Vec::new();
        // (One emitter's buffers for every entry.)
        let mut scratch = Emitter::default();
        let close = loop {
            let Some(t) = self.next_token()? else {
                em.unclosed = Some(open.span());
                break None;
            };
            if t.is(self, "}") {
                break Some(t);
            }
            if t.is(self, ",") && !entries.is_empty() {
                continue;
            }
            self.expression_from(&mut scratch, t.clone())?;
            let mut entry = std::mem::take(&mut scratch).finish();
            let expr = self.parsed(&entry, Parse::Expr, syntax::parse_expr)?;
            let bindings = std::mem::take(&mut entry.bindings);
            let (value, bindings) = self.with_bindings(bindings, |ev| {
                let value = ev.eval(&expr);
                (value, std::mem::take(&mut ev.lang.bindings))
            });
            let value = value.map_err(|d| self.noted(d, Some(&entry)))?;
            let span = entry.unit.span(0, entry.unit.text.len());
            entry.bindings = bindings;
            scratch = Emitter::reusing(entry);
            let stand_in = Tok {
                kind: TokenKind::Word,
                end: if span.file == t.file {
                    span.end.max(t.end)
                } else {
                    t.end
                },
                binding: None,
                stand_in: true,
                ..t
            };
            entries.push((value, stand_in));
        };
        self.lang.reader.run += 1;
        let text = Arc::clone(&self.sources.file(open.file).text);
        em.push(&open, &text);
        match close.as_ref().and_then(|c| vector_list(&entries, &open, c)) {
            Some(list) => em.push_list(
                list,
                open.file,
                open.end as usize,
                close.as_ref().expect("closed").start as usize,
            ),
            None => {
                for (value, mut tok) in entries {
                    tok.binding = Some(Arc::new(value));
                    em.push(&tok, &text);
                }
            }
        }
        if let Some(c) = &close {
            em.push(c, &text);
        }
        Ok(())
    }

    /// A required `(…)` group (a condition, a macro's arguments …); `what` names the
    /// directive for the message.
    fn parenthesis(&mut self, at: Span, what: &str) -> Result<Emitted> {
        match self.next_token()? {
            Some(t) if t.is(self, "(") => self.group_from(t),
            Some(t) => Err(Diagnostic::error(
                format!("expected `(` after {what}"),
                t.span(),
            )),
            None => Err(Diagnostic::error(
                format!("expected `(` after {what}, found the end of the file"),
                at,
            )),
        }
    }

    /// A declared value's unit: an item to its closing `}` (textures layered after a
    /// texture), `array[…]` with its elements, `function (…) {…}`, or an expression.
    fn value_unit(&mut self, at: Span) -> Result<Emitted> {
        let first = self.value_start(at)?;
        let mut em = Emitter::default();
        if first.kind == TokenKind::Word && first.binding.is_none() && !first.stand_in {
            let word = self.text_of(&first).to_string();
            match word.as_str() {
                "array" => {
                    self.emit(&mut em, &first);
                    while self.peek_held_is("[")? {
                        let open = self.next_token()?.expect("peeked");
                        self.emit(&mut em, &open);
                        self.rest_of_group(&mut em, 1)?;
                    }
                    if self.peek_held_is("{")? {
                        let open = self.next_token()?.expect("peeked");
                        self.emit(&mut em, &open);
                        self.rest_of_group(&mut em, 1)?;
                    }
                    return Ok(em.finish());
                }
                "function" => {
                    self.emit(&mut em, &first);
                    for open in ["(", "{"] {
                        if self.peek_is(open)? {
                            let t = self.next_token()?.expect("peeked");
                            self.emit(&mut em, &t);
                            self.rest_of_group(&mut em, 1)?;
                        }
                    }
                    return Ok(em.finish());
                }
                _ if self.peek_is("{")? => {
                    self.emit(&mut em, &first);
                    let open = self.next_token()?.expect("peeked");
                    self.emit(&mut em, &open);
                    self.rest_of_group(&mut em, 1)?;
                    // Textures layered: `texture {…} texture {…}`.
                    while word == "texture" && self.peek_word_is("texture")? {
                        let t = self.next_token()?.expect("peeked");
                        self.emit(&mut em, &t);
                        if self.peek_is("{")? {
                            let open = self.next_token()?.expect("peeked");
                            self.emit(&mut em, &open);
                            self.rest_of_group(&mut em, 1)?;
                        }
                    }
                    return Ok(em.finish());
                }
                _ => {}
            }
        }
        self.expression_from(&mut em, first)?;
        Ok(em.finish())
    }

    /// The first token of a value the directive at `at` reads (an error at the file's end).
    fn value_start(&mut self, at: Span) -> Result<Tok> {
        self.next_token()?
            .ok_or_else(|| Diagnostic::error("expected a value, found the end of the file", at))
    }

    /// An expression's unit whose first token is the next one (`#version`'s value).
    fn expression_unit(&mut self, at: Span) -> Result<Emitted> {
        let first = self.value_start(at)?;
        let mut em = Emitter::default();
        self.expression_from(&mut em, first)?;
        Ok(em.finish())
    }

    /// One operand's unit (`#include`'s file name, `#debug`'s text).
    fn operand_unit(&mut self, at: Span) -> Result<Emitted> {
        let first = self.value_start(at)?;
        let mut em = Emitter::default();
        self.operand_from(&mut em, first)?;
        Ok(em.finish())
    }

    /// Reads an expression whose first token is `first`: operands joined by `+ - * /` (the
    /// operators that may stand outside parentheses) and colour channels.
    /// (A declared value's lookahead after a complete operand holds directives.)
    fn expression_from(&mut self, em: &mut Emitter, first: Tok) -> Result<()> {
        self.operand_from(em, first)?;
        loop {
            let Some(t) = self.peek_held()? else {
                return Ok(());
            };
            let joins = match t.kind {
                TokenKind::Punct => matches!(self.text_of(&t), "+" | "-" | "*" | "/"),
                TokenKind::Word => {
                    t.binding.is_none() && !t.stand_in && CHANNELS.contains(&self.text_of(&t))
                }
                _ => false,
            };
            if !joins {
                return Ok(());
            }
            self.next_token()?;
            self.emit(em, &t);
            match self.next_token()? {
                Some(next) => self.operand_from(em, next)?,
                None => return Ok(()),
            }
        }
    }

    /// Reads one operand whose first token is `first`: signs, colour words and channels
    /// before it; a number, a string, a vector, a parenthesis, or a name with its call,
    /// subscripts and members.
    fn operand_from(&mut self, em: &mut Emitter, first: Tok) -> Result<()> {
        let mut tok = first;
        loop {
            let text = self.text_of(&tok);
            let prefix = match tok.kind {
                TokenKind::Punct => matches!(text, "+" | "-" | "!"),
                TokenKind::Word if tok.binding.is_none() && !tok.stand_in => {
                    matches!(text, "color" | "colour")
                        || COLOUR_TYPES.contains(&text)
                        || CHANNELS.contains(&text)
                }
                _ => false,
            };
            if !prefix {
                break;
            }
            self.emit(em, &tok);
            match self.next_token()? {
                Some(next) => tok = next,
                None => return Ok(()),
            }
        }
        match tok.kind {
            TokenKind::Number | TokenKind::Str => self.emit(em, &tok),
            TokenKind::Punct if tok.is(self, "(") => {
                self.emit(em, &tok);
                self.rest_of_group(em, 1)?;
            }
            TokenKind::Punct if tok.is(self, "<") => {
                // A vector: to its `>` (comparisons stand only in parentheses, which the
                // group keeps whole).
                self.emit(em, &tok);
                let mut angles = 1usize;
                let mut open = Vec::new();
                while angles > 0 {
                    if self.plain_run(em, &mut open, Some(&mut angles))? {
                        // (Stopped inside brackets: the rest of them the usual way.)
                        if !open.is_empty() {
                            self.rest_of_group(em, open.len())?;
                            open.clear();
                        }
                        continue;
                    }
                    let Some(t) = self.next_token()? else {
                        return Ok(());
                    };
                    match self.text_of(&t) {
                        "<" if t.kind == TokenKind::Punct => angles += 1,
                        ">" if t.kind == TokenKind::Punct => angles -= 1,
                        "(" | "[" | "{" if t.kind == TokenKind::Punct => {
                            self.emit(em, &t);
                            self.rest_of_group(em, 1)?;
                            continue;
                        }
                        _ => {}
                    }
                    self.emit(em, &t);
                }
            }
            TokenKind::Word => {
                self.emit(em, &tok);
                if self.peek_held_is("(")? {
                    let open = self.next_token()?.expect("peeked");
                    self.emit(em, &open);
                    self.rest_of_group(em, 1)?;
                }
                loop {
                    if self.peek_held_is("[")? {
                        let open = self.next_token()?.expect("peeked");
                        self.emit(em, &open);
                        self.rest_of_group(em, 1)?;
                    } else if self.peek_held_is(".")? {
                        let dot = self.next_token()?.expect("peeked");
                        self.emit(em, &dot);
                        // (The member's name is a word as written.)
                        self.lang.reader.raw_words = true;
                        let member = self.next_token();
                        self.lang.reader.raw_words = false;
                        if let Some(m) = member? {
                            self.emit(em, &m);
                        }
                    } else {
                        break;
                    }
                }
            }
            // Not an operand: the grammar says what it expected.
            _ => self.unget(tok),
        }
        Ok(())
    }

    /// Whether the next token is the punctuation `p`.
    fn peek_is(&mut self, p: &str) -> Result<bool> {
        Ok(self.peek_token()?.is_some_and(|t| t.is(self, p)))
    }

    /// Whether the next token is the punctuation `p`, directives held (after a complete
    /// value).
    fn peek_held_is(&mut self, p: &str) -> Result<bool> {
        Ok(self.peek_held()?.is_some_and(|t| t.is(self, p)))
    }

    /// Whether the next token is the keyword `w`, directives held (after a complete value).
    fn peek_word_is(&mut self, w: &str) -> Result<bool> {
        Ok(self.peek_held()?.is_some_and(|t| {
            t.kind == TokenKind::Word && t.binding.is_none() && self.text_of(&t) == w
        }))
    }

    /// Reads a `;` if one comes next (a directive there waits: POV-Ray reads none before a
    /// declaration's `;`).
    fn optional_semicolon(&mut self) -> Result<bool> {
        let is = self.peek_held_is(";")?;
        if is {
            self.next_token()?;
        }
        Ok(is)
    }

    /// The next word, as written (not bound, no macro called): a name being declared.
    fn raw_word(&mut self, at: Span, what: &str) -> Result<(String, Span)> {
        self.lang.reader.raw_words = true;
        let t = self.next_token();
        self.lang.reader.raw_words = false;
        match t? {
            Some(t) if t.kind == TokenKind::Word => Ok((self.text_of(&t).to_string(), t.span())),
            Some(t) => Err(Diagnostic::error(format!("expected {what}"), t.span())),
            None => Err(Diagnostic::error(
                format!("expected {what}, found the end of the file"),
                at,
            )),
        }
    }

    // ---------------------------------------------------------------------------------------
    // Directives

    /// Carries out the directive `#word` at `at`.
    fn directive(&mut self, word: &str, at: Span) -> Result<()> {
        match word {
            "declare" | "local" => self.declare_directive(word == "local", at),
            "if" => {
                let holds = self.condition(at, "#if")?;
                self.branch(holds, at)
            }
            "ifdef" | "ifndef" => {
                // (The name is read as written: a macro's name is not a call here.)
                let head = match self.next_token()? {
                    Some(open) if open.is(self, "(") => {
                        let mut em = Emitter::default();
                        self.emit(&mut em, &open);
                        self.lang.reader.raw_words = true;
                        let name = self.next_token();
                        self.lang.reader.raw_words = false;
                        let name = name?;
                        let closes = name.as_ref().is_some_and(|n| n.is(self, ")"));
                        if let Some(name) = name {
                            self.emit(&mut em, &name);
                        }
                        if !closes {
                            self.rest_of_group(&mut em, 1)?;
                        }
                        em.finish()
                    }
                    _ => {
                        return Err(Diagnostic::error(format!("expected `(` after #{word}"), at));
                    }
                };
                let node = self.parsed(&head, Parse::Head(Head::Ifdef), |u| {
                    syntax::parse_head(u, Head::Ifdef)
                })?;
                // (A number or other value is never declared.)
                let defined = match node.view() {
                    View::IfDef { name: Some(name) } => self
                        .with_bindings(head.bindings.clone(), |ev| ev.defined(name))
                        .map_err(|d| self.noted(d, Some(&head)))?,
                    _ => false,
                };
                self.branch(defined == (word == "ifdef"), at)
            }
            "elseif" | "else" => match self.lang.reader.blocks.last() {
                Some(b) if matches!(b.kind, BlockKind::If) && self.block_is_here(b) => {
                    // The branch read ends: the rest of the conditional is passed over.
                    self.skip_to(&["end"], at)?;
                    self.pop_block();
                    Ok(())
                }
                // `#else` of a `#switch` read into (after a clause without `#break`).
                Some(b) if matches!(b.kind, BlockKind::Switch) && word == "else" => Ok(()),
                _ => Err(Diagnostic::error(
                    format!("#{word} without an #if before it"),
                    at,
                )),
            },
            "end" => self.end_directive(at),
            "while" => {
                let cond = self.lang.reader.inputs.last().map_or(0, |i| i.pos);
                if self.condition(at, "#while")? {
                    self.charge(1, "#while", at)?;
                    self.push_block(BlockKind::While { cond, end: None }, at);
                } else {
                    self.skip_to(&["end"], at)?;
                }
                Ok(())
            }
            "for" => self.for_directive(at),
            "switch" => self.switch_directive(at),
            "case" | "range" => match self.lang.reader.blocks.last() {
                // A clause read into from the one before it (no `#break`): its test is passed
                // over.
                Some(b) if matches!(b.kind, BlockKind::Switch) && self.block_is_here(b) => {
                    self.parenthesis(at, &format!("#{word}"))?;
                    Ok(())
                }
                _ => Err(Diagnostic::error(format!("#{word} outside a #switch"), at)),
            },
            "break" => self.break_directive(at),
            "macro" => self.macro_directive(at),
            "include" => self.include_directive(at),
            "version" => self.version_directive(at),
            "undef" => self.undef_directive(at),
            "debug" | "warning" | "error" | "render" | "statistics" => {
                let unit = self.operand_unit(at)?;
                let text = self.string_of(&unit)?;
                if matches!(word, "render" | "statistics") {
                    self.warn(Diagnostic::warning(
                        format!("`#{word}` is read as `#debug`, as POV-Ray 3.7 reads it"),
                        at,
                    ));
                }
                match word {
                    "error" => Err(Diagnostic::error(format!("#error: {text}"), at)),
                    "warning" => {
                        self.warn(Diagnostic::warning(text, at));
                        Ok(())
                    }
                    _ => {
                        self.lang.debug_output.push_str(&text);
                        Ok(())
                    }
                }
            }
            "fopen" => {
                let mut em = Emitter::default();
                self.lang.reader.raw_words = true;
                let name = self.next_token();
                self.lang.reader.raw_words = false;
                if let Some(name) = name? {
                    self.emit(&mut em, &name);
                }
                if let Some(t) = self.next_token()? {
                    self.operand_from(&mut em, t)?;
                }
                self.lang.reader.raw_words = true;
                let mode = self.next_token();
                self.lang.reader.raw_words = false;
                if let Some(mode) = mode? {
                    self.emit(&mut em, &mode);
                }
                let em = em.finish();
                let node = self.parsed(&em, Parse::Head(Head::Fopen), |u| {
                    syntax::parse_head(u, Head::Fopen)
                })?;
                self.with_bindings(em.bindings.clone(), |ev| ev.file_directive(&node))
                    .map_err(|d| self.noted(d, Some(&em)))
            }
            "fclose" => {
                let (name, span) = self.raw_word(at, "a file's name after #fclose")?;
                let node = Node {
                    kind: NodeKind::FileClose,
                    span: Span {
                        start: at.start,
                        ..span
                    },
                    word: syntax::Word::fixed("fclose"),
                    word_span: at,
                    args: Vec::new(),
                    children: vec![Node {
                        kind: NodeKind::IdentRef,
                        span,
                        word: syntax::Word::new(&name),
                        word_span: span,
                        args: Vec::new(),
                        children: Vec::new(),
                        slot: syntax::Slot::NONE,
                    }],
                    slot: syntax::Slot::NONE,
                };
                self.file_directive(&node)
            }
            "read" | "write" => {
                let args = self.parenthesis(at, &format!("#{word}"))?;
                let head = if word == "read" {
                    Head::Read
                } else {
                    Head::Write
                };
                let parsed =
                    self.parsed(&args, Parse::Head(head), |u| syntax::parse_head(u, head))?;
                // (Messages about the directive point at its word.)
                let node = Node {
                    word_span: at,
                    ..(*parsed).clone()
                };
                self.with_bindings(args.bindings.clone(), |ev| ev.file_directive(&node))
                    .map_err(|d| self.noted(d, Some(&args)))
            }
            "default" => {
                let body = self.parenthesis_like(at, "{", "#default")?;
                let node = self.parsed(&body, Parse::Head(Head::Default), |u| {
                    syntax::parse_head(u, Head::Default)
                })?;
                self.with_bindings(body.bindings.clone(), |ev| ev.default_directive(&node))
                    .map_err(|d| self.noted(d, Some(&body)))
            }
            // A `#` before a word that is no directive is nothing to POV-Ray: the word is read
            // as if the `#` were not there (`#sphere { … }`).
            _ => {
                let input = self.lang.reader.inputs.last_mut().expect("an input");
                input.pos = at.start as usize;
                Ok(())
            }
        }
    }

    /// `declare`, `include`, `version` (and `local`) at the top level without their `#`.
    fn directive_without_hash(&mut self, word: &str, at: Span) -> Result<Option<Statement>> {
        let wants_hash = || {
            Diagnostic::warning(
                format!("`{word}` wants a `#` before it (`#{word}`; POV-Ray warns too)"),
                at,
            )
        };
        match word {
            "declare" => {
                self.warn(wants_hash());
                self.declare_directive(false, at)?;
            }
            "include" => {
                self.warn(wants_hash());
                self.include_directive(at)?;
            }
            "version" => {
                // `version V;` makes POV-Ray stop reading the scene there (it takes the `;`
                // for the end of the file); without the `;` it reads on.
                let unit = self.expression_unit(at)?;
                let expr = self.parsed(&unit, Parse::Expr, syntax::parse_expr)?;
                let v = self
                    .with_bindings(unit.bindings.clone(), |ev| ev.float(&expr))
                    .map_err(|d| self.noted(d, Some(&unit)))?;
                self.lang.version = Some(v);
                if self.peek_held_is(";")? {
                    self.warn(Diagnostic::warning(
                        "`version` without its `#` but with a `;`: POV-Ray stops reading the scene here, and so does trace (write `#version`)",
                        at,
                    ));
                    self.lang.reader.inputs.clear();
                    return Ok(None);
                }
                self.warn(wants_hash());
            }
            _ => {
                return Err(Diagnostic::error(
                    "`local` wants a `#` before it: `#local` (POV-Ray refuses it too)",
                    at,
                ));
            }
        }
        self.read_statement()
    }

    /// `#undef Name` (or `#undef A[i]`: the element has no value again). An unknown name is
    /// a warning, as in POV-Ray.
    fn undef_directive(&mut self, at: Span) -> Result<()> {
        let (name, name_span) = self.raw_word(at, "a name after #undef")?;
        // (A directive after the name waits until the name is undefined.)
        if self.peek_held_is("[")? {
            let mut em = Emitter::default();
            let name_tok = Tok {
                kind: TokenKind::Word,
                file: name_span.file,
                start: name_span.start,
                end: name_span.end,
                run: self.lang.reader.run,
                context: None,
                binding: None,
                stand_in: false,
                repeat: false,
                unread: false,
            };
            self.emit(&mut em, &name_tok);
            while self.peek_held_is("[")? {
                let open = self.next_token()?.expect("peeked");
                self.emit(&mut em, &open);
                self.rest_of_group(&mut em, 1)?;
            }
            let em = em.finish();
            let node = self.parsed(&em, Parse::Head(Head::Element), |u| {
                syntax::parse_head(u, Head::Element)
            })?;
            return self
                .with_bindings(em.bindings.clone(), |ev| ev.unassign_element(&node))
                .map_err(|d| self.noted(d, Some(&em)));
        }
        if self.lang.env.remove(&name).is_none() && self.lang.macros.remove(&name).is_none() {
            self.warn(Diagnostic::warning(
                format!("`#undef {name}`: `{name}` is not declared (POV-Ray warns too)"),
                name_span,
            ));
        }
        Ok(())
    }

    /// A required group opened by `open` (`{` of `#default`).
    fn parenthesis_like(&mut self, at: Span, open: &str, what: &str) -> Result<Emitted> {
        match self.next_token()? {
            Some(t) if t.is(self, open) => self.group_from(t),
            Some(t) => Err(Diagnostic::error(
                format!("expected `{open}` after {what}"),
                t.span(),
            )),
            None => Err(Diagnostic::error(
                format!("expected `{open}` after {what}, found the end of the file"),
                at,
            )),
        }
    }

    /// A directive's condition, `(…)`, evaluated.
    fn condition(&mut self, at: Span, what: &str) -> Result<bool> {
        if let Some(holds) = self.quick_condition()? {
            return Ok(holds);
        }
        let unit = self.parenthesis(at, what)?;
        let expr = self.parsed(&unit, Parse::Expr, syntax::parse_expr)?;
        self.with_bindings(unit.bindings.clone(), |ev| ev.truth(&expr))
            .map_err(|d| self.noted(d, Some(&unit)))
    }

    /// The string a unit holds (`#include`'s name, `#debug`'s text).
    fn string_of(&mut self, unit: &Emitted) -> Result<String> {
        let expr = self.parsed(unit, Parse::Expr, syntax::parse_expr)?;
        self.with_bindings(unit.bindings.clone(), |ev| ev.string(&expr))
            .map_err(|d| self.noted(d, Some(unit)))
    }

    /// After `#if`'s or `#ifdef`'s test: reads the branch taken (or passes over the others,
    /// testing each `#elseif`).
    fn branch(&mut self, holds: bool, at: Span) -> Result<()> {
        if holds {
            self.push_block(BlockKind::If, at);
            return Ok(());
        }
        loop {
            let (found, found_at) = self.skip_to(&["elseif", "else", "end"], at)?;
            match found.as_str() {
                "elseif" => {
                    if self.condition(found_at, "#elseif")? {
                        self.push_block(BlockKind::If, at);
                        return Ok(());
                    }
                }
                "else" => {
                    self.push_block(BlockKind::If, at);
                    return Ok(());
                }
                _ => return Ok(()),
            }
        }
    }

    fn push_block(&mut self, kind: BlockKind, at: Span) {
        let input = self.lang.reader.inputs.len() - 1;
        self.lang.reader.loops += usize::from(is_loop(&kind));
        self.lang.reader.blocks.push(Block { kind, input, at });
    }

    /// Closes the innermost block.
    fn pop_block(&mut self) {
        if let Some(b) = self.lang.reader.blocks.pop() {
            self.lang.reader.loops -= usize::from(is_loop(&b.kind));
        }
    }

    /// Closes the blocks from the `first`-th on.
    fn truncate_blocks(&mut self, first: usize) {
        while self.lang.reader.blocks.len() > first {
            self.pop_block();
        }
    }

    /// Whether block `b` was opened in the input being read.
    fn block_is_here(&self, b: &Block) -> bool {
        b.input + 1 == self.lang.reader.inputs.len()
    }

    /// `#end`: closes the innermost block (a loop goes round again if its test holds).
    fn end_directive(&mut self, at: Span) -> Result<()> {
        let Some(block) = self.lang.reader.blocks.last() else {
            return Err(Diagnostic::error("#end without a directive to end", at));
        };
        if !self.block_is_here(block) {
            return Err(Diagnostic::error(
                "#end without a directive to end (a block opened outside this file or macro)",
                at,
            ));
        }
        let input = block.input;
        let block_at = block.at;
        match &mut self.lang.reader.blocks.last_mut().expect("a block").kind {
            BlockKind::If | BlockKind::Switch => {
                self.pop_block();
            }
            BlockKind::While { cond, end } => {
                let cond = *cond;
                let after = self.lang.reader.inputs[input].pos;
                *end = Some(after);
                self.lang.reader.inputs[input].pos = cond;
                if self.condition(block_at, "#while")? {
                    self.charge(1, "#while", block_at)?;
                } else {
                    self.lang.reader.inputs[input].pos = after;
                    self.pop_block();
                }
            }
            BlockKind::For {
                var,
                last,
                step,
                body,
            } => {
                let (var, last, step, body) = (var.clone(), *last, *step, *body);
                // The body may change the counter, as in POV-Ray.
                let i = match self.lang.env.get(&var).map(|v| &**v) {
                    Some(Value::Float(v)) => *v,
                    _ => last,
                } + step;
                if (step > 0.0 && i <= last + 1e-10) || (step < 0.0 && i >= last - 1e-10) {
                    self.charge(1, "#for", block_at)?;
                    self.set(var, Value::Float(i));
                    self.lang.reader.inputs[input].pos = body;
                } else {
                    self.pop_block();
                }
            }
        }
        Ok(())
    }

    /// `#for (I, start, end [, step]) … #end`: inclusive, with POV-Ray's 1e-10 slack.
    fn for_directive(&mut self, at: Span) -> Result<()> {
        let head = self.parenthesis(at, "#for")?;
        let node = self.parsed(&head, Parse::Head(Head::For), |u| {
            syntax::parse_head(u, Head::For)
        })?;
        let View::For {
            counter,
            start,
            end,
            step,
        } = node.view()
        else {
            return Err(crate::eval::malformed(&node, "#for"));
        };
        let var = counter.word.to_string();
        let (start, last, step) = self
            .with_bindings(head.bindings.clone(), |ev| {
                let start = ev.float(start)?;
                let last = ev.float(end)?;
                let step = match step {
                    Some(e) => {
                        let step = ev.float(e)?;
                        if step == 0.0 {
                            return Err(Diagnostic::error("#for step must not be zero", e.span));
                        }
                        step
                    }
                    None => 1.0,
                };
                Ok((start, last, step))
            })
            .map_err(|d| self.noted(d, Some(&head)))?;
        self.set(var.clone(), Value::Float(start));
        if (step > 0.0 && start <= last + 1e-10) || (step < 0.0 && start >= last - 1e-10) {
            self.charge(1, "#for", at)?;
            let body = self.lang.reader.inputs.last().map_or(0, |i| i.pos);
            self.push_block(
                BlockKind::For {
                    var,
                    last,
                    step,
                    body,
                },
                at,
            );
        } else {
            self.skip_to(&["end"], at)?;
        }
        Ok(())
    }

    /// `#switch (v) #case (a) … #break #range (lo, hi) … #else … #end`: the first clause that
    /// matches is read, on into the next ones until a `#break`.
    fn switch_directive(&mut self, at: Span) -> Result<()> {
        let unit = self.parenthesis(at, "#switch")?;
        let expr = self.parsed(&unit, Parse::Expr, syntax::parse_expr)?;
        let v = self
            .with_bindings(unit.bindings.clone(), |ev| ev.float(&expr))
            .map_err(|d| self.noted(d, Some(&unit)))?;
        loop {
            let (found, found_at) = self.skip_to(&["case", "range", "else", "end"], at)?;
            let matches = match found.as_str() {
                "case" => {
                    let unit = self.parenthesis(found_at, "#case")?;
                    let expr = self.parsed(&unit, Parse::Expr, syntax::parse_expr)?;
                    let c = self
                        .with_bindings(unit.bindings.clone(), |ev| ev.float(&expr))
                        .map_err(|d| self.noted(d, Some(&unit)))?;
                    (c - v).abs() <= 1e-10
                }
                "range" => {
                    let unit = self.parenthesis(found_at, "#range")?;
                    let node = self.parsed(&unit, Parse::Head(Head::Range), |u| {
                        syntax::parse_head(u, Head::Range)
                    })?;
                    let View::RangeHead { low, high } = node.view() else {
                        return Err(crate::eval::malformed(&node, "#range"));
                    };
                    let (lo, hi) = self
                        .with_bindings(unit.bindings.clone(), |ev| {
                            Ok((ev.float(low)?, ev.float(high)?))
                        })
                        .map_err(|d| self.noted(d, Some(&unit)))?;
                    lo <= v && v <= hi
                }
                "else" => true,
                _ => return Ok(()),
            };
            if matches {
                self.push_block(BlockKind::Switch, at);
                return Ok(());
            }
        }
    }

    /// `#break`: leaves the innermost loop or `#switch` (the blocks inside it too), or else
    /// returns from the macro being read.
    fn break_directive(&mut self, at: Span) -> Result<()> {
        let here = self.lang.reader.inputs.len() - 1;
        let target = self
            .lang
            .reader
            .blocks
            .iter()
            .rposition(|b| b.input == here && !matches!(b.kind, BlockKind::If));
        let Some(target) = target else {
            // In a macro (outside its loops): the macro returns here, as in POV-Ray.
            if self.lang.reader.inputs[here].kind == InputKind::Macro {
                let first = self.lang.reader.blocks.partition_point(|b| b.input < here);
                self.truncate_blocks(first);
                let input = &mut self.lang.reader.inputs[here];
                input.pos = input.end;
                input.pushback.clear();
                self.lang.reader.run += 1;
                return Ok(());
            }
            return Err(Diagnostic::error(
                "#break outside a #while, #for, #switch or macro (POV-Ray refuses it too)",
                at,
            ));
        };
        // Blocks still open inside the target each have an `#end` to pass.
        let open = self.lang.reader.blocks.len() - target;
        for _ in 0..open {
            self.skip_to(&["end"], at)?;
        }
        self.truncate_blocks(target);
        Ok(())
    }

    /// Passes over the current input to the next of the directives `stops` at this level
    /// (nested blocks passed whole): the directive found and where it stands. The end of the
    /// input first is an error about the directive at `from`.
    fn skip_to(&mut self, stops: &[&str], from: Span) -> Result<(String, Span)> {
        self.lang.reader.run += 1;
        let Some(input) = self.lang.reader.inputs.last_mut() else {
            return Err(Diagnostic::error("no #end for this directive", from));
        };
        input.pushback.clear();
        let mut lexer = Lexer::new(&input.text, input.pos..input.end);
        let mut depth = 0usize;
        loop {
            let t = lexer
                .next()
                .map_err(|e| Diagnostic::error(e.message, Span::new(input.file, e.at, e.at + 1)))?;
            let Some(t) = t else {
                input.pos = lexer.position();
                return Err(Diagnostic::error(
                    "this directive has no #end (the file or macro ends first)",
                    from,
                ));
            };
            if t.kind != TokenKind::Directive {
                continue;
            }
            let word = t.word(&input.text);
            if OPENERS.contains(&word) {
                depth += 1;
                continue;
            }
            if word == "end" && depth > 0 {
                depth -= 1;
                continue;
            }
            if depth == 0 && stops.contains(&word) {
                input.pos = lexer.position();
                let span = Span::new(input.file, t.start as usize, t.end as usize);
                return Ok((word.to_string(), span));
            }
        }
    }

    /// `#macro Name(A, B …) body #end`: the body is kept where it stands, read at each call.
    fn macro_directive(&mut self, at: Span) -> Result<()> {
        let mut em = Emitter::default();
        self.lang.reader.raw_words = true;
        let head = self.macro_head(&mut em);
        self.lang.reader.raw_words = false;
        head?;
        let em = em.finish();
        let node = self.parsed(&em, Parse::Head(Head::Macro), |u| {
            syntax::parse_head(u, Head::Macro)
        })?;
        let input = self.lang.reader.inputs.last().expect("an input");
        let (file, start) = (input.file, input.pos);
        let (_, end_at) = self.skip_to(&["end"], at)?;
        let View::MacroDef { name, params } = node.view() else {
            return Err(crate::eval::malformed(&node, "#macro"));
        };
        let params = params.iter().map(|p| p.word.to_string()).collect();
        self.lang.macros.insert(
            name.word.to_string(),
            Macro {
                params,
                body: Span::new(file, start, end_at.start as usize),
                name_span: name.span,
            },
        );
        Ok(())
    }

    /// The tokens of `Name(A, B …)` after `#macro`, as written.
    fn macro_head(&mut self, em: &mut Emitter) -> Result<()> {
        let Some(name) = self.next_token()? else {
            return Ok(());
        };
        self.emit(em, &name);
        if let Some(open) = self.next_token()? {
            let is_open = open.is(self, "(");
            self.emit(em, &open);
            if is_open {
                self.rest_of_group(em, 1)?;
            }
        }
        Ok(())
    }

    /// Calls macro `name`, whose name is `tok`: reads the arguments, binds the parameters in
    /// a new frame and goes on reading in the body.
    fn call_macro(&mut self, name: &str, tok: &Tok) -> Result<()> {
        let m = self.lang.macros.get(name).cloned().expect("a macro");
        let args = self.parenthesis(tok.span(), &format!("macro `{name}`"))?;
        let exprs = self.parsed(&args, Parse::Args, syntax::parse_args)?;
        if exprs.len() != m.params.len() {
            return Err(self.noted(
                Diagnostic::error(
                    format!(
                        "macro `{name}` takes {} argument(s), found {}",
                        m.params.len(),
                        exprs.len()
                    ),
                    tok.span(),
                )
                .with_note(format!(
                    "`{name}` is declared at {}",
                    self.location(m.name_span)
                )),
                None,
            ));
        }
        self.charge(MACRO_CALL_STEPS, "macro call", tok.span())?;
        if self.lang.frames.len() >= MAX_MACRO_DEPTH {
            return Err(Diagnostic::error(
                format!("macros nested more than {MAX_MACRO_DEPTH} deep (endless recursion?)"),
                tok.span(),
            ));
        }
        let mut values = Vec::with_capacity(exprs.len());
        let mut by_reference = Vec::new();
        for (e, p) in exprs.iter().zip(&m.params) {
            let v = self
                .with_bindings(args.bindings.clone(), |ev| ev.eval(e))
                .map_err(|d| self.noted(d, Some(&args)))?;
            values.push(v);
            // An argument that is a declared name alone is passed by reference: its final
            // value is copied back when the macro returns.
            if let syntax::ExprKind::Ident(n, slot) = &e.kind {
                if args
                    .bindings
                    .get(slot.0 as usize)
                    .is_some_and(Option::is_some)
                {
                    by_reference.push((p.clone(), n.clone()));
                }
            }
        }
        self.lang.frames.push(Frame {
            saved: Vec::new(),
            by_reference,
        });
        for (param, value) in m.params.iter().zip(values) {
            self.shadow(param);
            self.set(param.clone(), value);
        }
        let text = self.sources.file(m.body.file).text.clone();
        let context = Some(Arc::new(Context {
            parent: self
                .lang
                .reader
                .inputs
                .last()
                .and_then(|i| i.context.clone()),
            macro_name: Some(name.to_string()),
            at: tok.span(),
        }));
        self.lang.reader.inputs.push(Input {
            file: m.body.file,
            text,
            pos: m.body.start as usize,
            end: m.body.end as usize,
            kind: InputKind::Macro,
            context,
            pushback: Vec::new(),
        });
        self.lang.reader.run += 1;
        Ok(())
    }

    /// Ends the macro bodies that nothing but blanks and comments remain of (what the next
    /// token read would do first), down to `floor` inputs open.
    fn settle(&mut self, floor: usize) {
        while let Some(input) = self.lang.reader.inputs.last() {
            if self.lang.reader.inputs.len() <= floor {
                return;
            }
            let rest =
                crate::syntax::lexer::skip_trivia(input.text.as_bytes(), input.pos, input.end);
            let here = self.lang.reader.inputs.len() - 1;
            if input.kind != InputKind::Macro
                || !input.pushback.is_empty()
                || rest != Ok(input.end)
                || self
                    .lang
                    .reader
                    .blocks
                    .last()
                    .is_some_and(|b| b.input == here)
            {
                return;
            }
            // (Cannot fail: no block is open in it.)
            let _ = self.end_input();
        }
    }

    /// The current input ends: its blocks must be closed; a macro returns, an included file's
    /// scope closes.
    fn end_input(&mut self) -> Result<()> {
        let here = self.lang.reader.inputs.len() - 1;
        if let Some(b) = self.lang.reader.blocks.last().filter(|b| b.input == here) {
            let at = b.at;
            return Err(Diagnostic::error(
                "this directive has no #end (the file or macro ends first)",
                at,
            ));
        }
        let input = self.lang.reader.inputs.pop().expect("an input");
        self.lang.reader.run += 1;
        match input.kind {
            InputKind::Scene => {}
            InputKind::Include => {
                self.return_from_macro();
                self.lang.include_depth -= 1;
            }
            InputKind::Macro => self.return_from_macro(),
        }
        Ok(())
    }

    /// `#include "file"`: read here, its `#local`s in a scope of their own.
    fn include_directive(&mut self, at: Span) -> Result<()> {
        let unit = self.operand_unit(at)?;
        let name = self.string_of(&unit)?;
        let span = unit.unit.span(0, unit.unit.text.len());
        if self.lang.include_depth >= MAX_INCLUDE_DEPTH {
            return Err(Diagnostic::error(
                format!("includes nested more than {MAX_INCLUDE_DEPTH} deep"),
                span,
            ));
        }
        // (A name without its extension finds the file with `.inc` after it, as in POV-Ray.)
        let path = match self.find_file(&name, "include file", span) {
            Err(e) if std::path::Path::new(&name).extension().is_none() => self
                .find_file(&format!("{name}.inc"), "include file", span)
                .map_err(|_| e)?,
            found => found?,
        };
        let text = crate::diag::read_source(&path)
            .map_err(|e| Diagnostic::error(format!("cannot read {}: {e}", path.display()), span))?;
        let file = self.sources.add(&path, text);
        let text = self.sources.file(file).text.clone();
        self.lang.include_depth += 1;
        self.lang.frames.push(Frame::default());
        let context = Some(Arc::new(Context {
            parent: self
                .lang
                .reader
                .inputs
                .last()
                .and_then(|i| i.context.clone()),
            macro_name: None,
            at: Span {
                start: at.start,
                ..span
            },
        }));
        let end = text.len();
        self.lang.reader.inputs.push(Input {
            file,
            text,
            pos: 0,
            end,
            kind: InputKind::Include,
            context,
            pushback: Vec::new(),
        });
        self.lang.reader.run += 1;
        Ok(())
    }

    /// `#version V;`.
    fn version_directive(&mut self, at: Span) -> Result<()> {
        let unit = self.expression_unit(at)?;
        let expr = self.parsed(&unit, Parse::Expr, syntax::parse_expr)?;
        let v = self
            .with_bindings(unit.bindings.clone(), |ev| ev.float(&expr))
            .map_err(|d| self.noted(d, Some(&unit)))?;
        self.lang.version = Some(v);
        if !self.optional_semicolon()? {
            self.warn(Diagnostic::warning(
                "`#version` wants a `;` after its number (POV-Ray warns too)",
                expr.span,
            ));
        }
        Ok(())
    }

    /// `#declare Name = value;` / `#local Name = value;` (also `Name[i]…`, and
    /// `deprecated [once] "message"` before the name).
    pub(in crate::eval) fn declare_directive(&mut self, local: bool, at: Span) -> Result<()> {
        // (A local name belongs to the macro or file the directive stands in.)
        let local = local.then_some(self.lang.frames.len());
        // (The inputs open here: a macro the value calls may end before the name is bound, not
        // these; a macro's parameter named here is bound in its caller.)
        let inputs = self.lang.reader.inputs.len();
        if self.quick_declare(local)? {
            return Ok(());
        }
        // The head, to the `=`: the name as written, its subscripts read.
        let mut em = Emitter::default();
        self.lang.reader.raw_words = true;
        let mut name_read = false;
        loop {
            let t = self.next_token();
            let Some(t) = t? else {
                break;
            };
            if t.is(self, "=") {
                self.emit(&mut em, &t);
                break;
            }
            if t.kind == TokenKind::Word && !matches!(self.text_of(&t), "deprecated" | "once") {
                name_read = true;
                // (Subscripts are read as values.)
                self.lang.reader.raw_words = false;
            }
            let open = t.is(self, "[");
            self.emit(&mut em, &t);
            if open {
                self.rest_of_group(&mut em, 1)?;
            }
            if !name_read && t.kind != TokenKind::Word && t.kind != TokenKind::Str {
                break;
            }
        }
        self.lang.reader.raw_words = false;
        let head = em.finish();
        let node = self.parsed(&head, Parse::Head(Head::Declare), |u| {
            syntax::parse_head(u, Head::Declare)
        })?;
        let value = self.value_unit(at)?;
        let value_span = value.unit.span(0, value.unit.text.len());
        let value = match self.parsed(&value, Parse::Value, syntax::parse_value) {
            Ok(syntax) => self
                .with_bindings(value.bindings.clone(), |ev| ev.declared_value(&syntax))
                .map_err(|d| self.noted(d, Some(&value)))?,
            // An item the grammar cannot read (standard include files declare many things
            // outside the subset) is kept, to be reported only if the scene uses it.
            Err(d) if value.unclosed.is_none() && is_item(&value.unit.text) => {
                Value::Unsupported(Box::new(self.why_unparsed(&value, d)))
            }
            Err(d) => return Err(self.why_unparsed(&value, d)),
        };
        let number = matches!(value, Value::Float(_) | Value::Vector(_) | Value::Colour(_));
        // (Bound before the `;` is looked for: reading on may run the next directive, which
        // may use the name. A macro whose body gave the value and ends there returns first,
        // as reading on would make it.)
        self.settle(inputs);
        self.with_bindings(head.bindings.clone(), |ev| {
            ev.bind_declared(&node, local, value)
        })
        .map_err(|d| self.noted(d, Some(&head)))?;
        if self.optional_semicolon()? {
            // (A second `;` is read too, as POV-Ray reads it.)
            self.optional_semicolon()?;
        } else if number {
            self.missing_semicolon(value_span)?;
        }
        Ok(())
    }

    /// Why a declared value's unit could not be read: an unsupported construct named by its
    /// first word, or the grammar's error.
    fn why_unparsed(&self, value: &Emitted, syntax_error: Diagnostic) -> Diagnostic {
        let text = &value.unit.text;
        let word: String = text
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if let Some(reason) = crate::eval::lang::keywords::reason(&word) {
            let span = value.unit.span(0, word.len().max(1));
            return self.noted(
                Diagnostic::error(format!("unsupported: `{word}` ({reason})"), span),
                Some(value),
            );
        }
        self.noted(syntax_error, Some(value))
    }
}

/// Whether a declared value's text is an item (a word and its block: `text {…}`,
/// `difference {…}`, `function (…) {…}`), which may be kept unread until it is used.
/// A list read entry by entry (`open` to `close`) as the fast lane's list, if its count is a
/// number and every entry a 3-vector, all written in the list's own file.
fn vector_list(
    entries: &[(Value, Tok)],
    open: &Tok,
    close: &Tok,
) -> Option<syntax::bulk::BulkList> {
    let ((count, count_tok), rest) = entries.split_first()?;
    let &Value::Float(count) = count else {
        return None;
    };
    if close.file != open.file || entries.iter().any(|(_, t)| t.file != open.file) {
        return None;
    }
    let mut values = Vec::with_capacity(rest.len());
    let mut spans = Vec::with_capacity(rest.len());
    for (value, tok) in rest {
        match value {
            Value::Vector(v) if v.len == 3 => values.push([v.c[0], v.c[1], v.c[2]]),
            _ => return None,
        }
        spans.push((tok.start, tok.end));
    }
    Some(syntax::bulk::BulkList::new(
        count,
        (count_tok.start, count_tok.end),
        values,
        spans,
    ))
}

fn is_item(text: &str) -> bool {
    let word_end = text
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(text.len());
    word_end > 0 && text[word_end..].trim_start().starts_with(['{', '('])
}

/// Whether a block is a loop (its body is read again).
fn is_loop(kind: &BlockKind) -> bool {
    matches!(kind, BlockKind::While { .. } | BlockKind::For { .. })
}

/// A key of the places a unit's text came from (FNV-1a over the pieces).
fn pieces_key(pieces: &[Piece]) -> u64 {
    pieces.iter().fold(0xcbf2_9ce4_8422_2325, |h, p| {
        [p.at, p.len, p.file.0, p.start, p.src_len]
            .into_iter()
            .fold(h, |h, x| (h ^ u64::from(x)).wrapping_mul(0x0100_0000_01b3))
    })
}

/// Whether a note says where the text came from (written by `Evaluator::noted`).
fn is_context_note(note: &str) -> bool {
    note.starts_with("in macro ")
        || note.starts_with("included from ")
        || note.starts_with("the bracket at ")
}
