//! Text the grammar cannot read whole because its directives work on tokens, read as POV-Ray's
//! token reader reads it.
//!
//! POV-Ray executes a directive where its reader meets it, so a branch of `#if` may open a
//! block that the text after its `#end` closes, and a directive may stand where a value does.
//! When the grammar cannot read a file's statement or a macro's body, the rest of that text is
//! read here statement by statement, choosing conditionals the grammar could not take in
//! ([`syntax::tokens`]):
//!
//! - a conditional at the start of a statement whose branches open or close blocks is chosen
//!   there, when the reader reaches it, exactly as POV-Ray chooses it;
//! - a `#while` or `#for` loop met here whose body holds a conditional runs pass by pass, its
//!   body read this way at each pass (at most 32 loops deep);
//! - a conditional inside a statement (`sphere { 0, #if (B) 1 #else 2 #end }`) is chosen as
//!   the statement starts: the same choice as POV-Ray's unless the statement itself changes
//!   what the condition reads (a `#declare` inside it before the `#if`; a condition that cannot
//!   be evaluated yet is reported). One inside a loop of the statement is not chosen (it would
//!   have to be chosen pass by pass): the grammar's error stands.
//!
//! The branches not taken are blanked in a copy of the text, so positions in messages are the
//! file's. Text the grammar reads whole never comes here and costs nothing more.

use super::{Evaluator, Result, flow::Handler};
use crate::diag::{Diagnostic, FileId, Span};
use crate::syntax::{self, NodeKind, tokens};
use std::ops::Range;

/// Deepest nesting of loops read pass by pass here.
const MAX_LOOPS: usize = 32;

impl<'a> Evaluator<'a> {
    /// Runs bytes `region` of file `file` (statements, or a macro body's `items`), whose
    /// reading as a whole failed with `failed`, as POV-Ray's token reader would; `failed` if
    /// the text has no directive that could explain it. With `resume`, stops after a
    /// statement past every blanked branch and returns where the grammar can go on reading
    /// the file whole (`None`: the region is done).
    pub(super) fn run_spliced(
        &mut self,
        file: FileId,
        region: Range<usize>,
        items: bool,
        failed: Diagnostic,
        f: &mut Handler<'_, 'a>,
        resume: bool,
    ) -> Result<Option<usize>> {
        let text = &self.sources.file(file).text[region.clone()];
        // (Only a conditional makes text the grammar cannot read that this reading can: a loop
        // is read here only for a conditional inside it.)
        if !text.contains("#if") {
            return Err(failed);
        }
        let text = text.to_owned();
        let resumed = self.read_spliced(text, file, region.start, (items, 0), f, resume)?;
        Ok(resumed.map(|at| region.start + at))
    }

    /// Reads `text`, the part of file `file` from byte `base`, statement by statement (with
    /// `resume`, only until a statement ends past every blanked branch: where that is).
    fn read_spliced(
        &mut self,
        mut text: String,
        file: FileId,
        base: usize,
        (items, loops): (bool, usize),
        f: &mut Handler<'_, 'a>,
        resume: bool,
    ) -> Result<Option<usize>> {
        let mut pos = 0;
        // Where the last blanked branch ends.
        let mut blanked_to = 0;
        loop {
            pos = tokens::skip_blanks(&text, pos);
            if pos >= text.len() {
                return Ok(None);
            }
            if resume && pos > 0 && pos >= blanked_to {
                return Ok(Some(pos));
            }
            if let Some(c) =
                tokens::conditional_at(&text, pos).filter(|c| !tokens::balanced(&text, c))
            {
                let chosen = self.choose(&text, &c, file, base)?;
                blanked_to = blanked_to.max(keep(&mut text, &c, chosen));
                continue;
            }
            // A loop holding a conditional is read pass by pass (not first by the grammar,
            // which for loops nested in loops would read the inner ones again at every level),
            // at most MAX_LOOPS deep.
            if let Some(l) = tokens::loop_at(&text, pos)
                .filter(|l| loops < MAX_LOOPS && text[l.body.clone()].contains("#if"))
            {
                self.spliced_loop(&text, &l, file, base, (items, loops + 1), f)?;
                pos = l.end.end;
                continue;
            }
            let (failed, read) = match syntax::statement_in(&text, pos, file, base, items) {
                None => return Ok(None),
                Some(Ok((node, end))) => {
                    match tokens::directive_after_unknown(&node, &text, base) {
                        None => {
                            self.one_item(&node, f)?;
                            pos = end;
                            continue;
                        }
                        // (Read, but with a directive where a value is: chosen below, or, if it
                        // cannot be, the statement is evaluated as read, whose message names the
                        // item.)
                        Some(at) => (directive_in_value_error(file, base + at), Some((node, end))),
                    }
                }
                Some(Err(e)) => (e, None),
            };
            if let Some(c) = tokens::conditional_at(&text, pos) {
                let chosen = self.choose(&text, &c, file, base)?;
                blanked_to = blanked_to.max(keep(&mut text, &c, chosen));
                continue;
            }
            let at = failed
                .span
                .map_or(pos, |s| (s.start as usize).saturating_sub(base))
                .clamp(pos, text.len());
            let culprit = match tokens::culprit(&text, pos, at) {
                Some(tokens::Culprit::Choose(start)) => tokens::conditional_at(&text, start),
                Some(tokens::Culprit::InLoop(start)) if read.is_none() => {
                    return Err(failed.with_note(format!(
                        "the directive at {} stands inside a loop within a statement: trace reads a directive there only with its #else where a value is read (`#if (C) A #else B #end`), or, outside loops, chooses it as the statement starts",
                        self.location(Span::new(file, base + start, base + start + 1))
                    )));
                }
                _ => None,
            };
            let chosen = culprit
                .as_ref()
                .map(|c| (c, self.choose(&text, c, file, base)));
            match (chosen, read) {
                (Some((c, Ok(chosen))), _) => {
                    blanked_to = blanked_to.max(keep(&mut text, c, chosen))
                }
                (_, Some((node, end))) => {
                    self.one_item(&node, f)?;
                    pos = end;
                }
                (None, None) => return Err(failed),
                (Some((c, Err(why))), None) => {
                    let head = Span::new(
                        file,
                        base + c.branches[0].head.start,
                        base + c.branches[0].head.end,
                    );
                    return Err(failed.with_note(format!(
                        "the directive at {} stands inside a statement, where trace chooses its branch as the statement starts, and it cannot be chosen there: {}",
                        self.location(head),
                        why.message
                    )));
                }
            }
        }
    }

    /// The branch of conditional `c` (in `text`, the part of `file` from byte `base`) that its
    /// conditions choose, if any.
    fn choose(
        &mut self,
        text: &str,
        c: &tokens::Conditional,
        file: FileId,
        base: usize,
    ) -> Result<Option<usize>> {
        for (i, branch) in c.branches.iter().enumerate() {
            let head = &text[branch.head.clone()];
            let at = base + branch.head.start;
            self.charge(1, "directive", Span::new(file, at, at + 1))?;
            // The head alone, closed, is a conditional the grammar reads (an `#elseif` as an
            // `#if` of the same length, so positions stay).
            let directive = match branch.kind {
                tokens::BranchKind::Else => return Ok(Some(i)),
                tokens::BranchKind::ElseIf => format!("#if    {} #end", &head["#elseif".len()..]),
                _ => format!("{head} #end"),
            };
            let nodes = syntax::parse_fragment_items(&directive, file, at)?;
            let holds = match nodes.first() {
                Some(node) if node.kind == NodeKind::If => self.truth(&node.args[0])?,
                Some(node) if node.kind == NodeKind::IfDef => self.ifdef_holds(node)?,
                _ => {
                    return Err(Diagnostic::error(
                        "expected a condition here",
                        Span::new(file, at, at + 1),
                    ));
                }
            };
            if holds {
                return Ok(Some(i));
            }
        }
        Ok(None)
    }

    /// Runs loop `l` of `text` (the part of `file` from byte `base`), reading its body anew
    /// at each pass.
    fn spliced_loop(
        &mut self,
        text: &str,
        l: &tokens::Loop,
        file: FileId,
        base: usize,
        (items, loops): (bool, usize),
        f: &mut Handler<'_, 'a>,
    ) -> Result<()> {
        let directive = format!("{} #end", &text[l.head.clone()]);
        let at = base + l.head.start;
        let nodes = syntax::parse_fragment_items(&directive, file, at)?;
        let Some(node) = nodes
            .first()
            .filter(|n| matches!(n.kind, NodeKind::While | NodeKind::For))
        else {
            return Err(Diagnostic::error(
                "expected a loop here",
                Span::new(file, at, at + 1),
            ));
        };
        let body = &text[l.body.clone()];
        let body_base = base + l.body.start;
        let mut pass = |ev: &mut Evaluator<'a>| {
            ev.read_spliced(body.to_owned(), file, body_base, (items, loops), f, false)
                .map(|_| ())
        };
        match node.kind {
            NodeKind::While => {
                while self.truth(&node.args[0])? {
                    self.charge(1, "#while", node.word_span)?;
                    pass(self)?;
                }
                Ok(())
            }
            _ => self.for_loop_with(node, &mut pass),
        }
    }
}

/// Blanks what conditional `c` leaves out when `chosen` is taken; where its `#end` ends.
fn keep(text: &mut String, c: &tokens::Conditional, chosen: Option<usize>) -> usize {
    tokens::keep_branch(text, c, chosen);
    c.end.end
}

/// The error of a statement the grammar read with a conditional directive where a value is,
/// at byte `at` of `file`.
pub(super) fn directive_in_value_error(file: FileId, at: usize) -> Diagnostic {
    Diagnostic::error(
        "a directive stands where a value is read here",
        Span::new(file, at, at + 1),
    )
}

impl Evaluator<'_> {
    /// Where `statement`, read by the grammar from its file, has a conditional directive where
    /// a value is (only statements holding a `#` are looked through).
    pub(super) fn directive_in_value(&self, statement: &crate::syntax::Node) -> Option<usize> {
        let text = &self.sources.file(statement.span.file).text;
        let own = &text[statement.span.start as usize..statement.span.end as usize];
        if !own.contains('#') {
            return None;
        }
        tokens::directive_after_unknown(statement, text, 0)
    }
}
