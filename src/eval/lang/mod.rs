//! The language: values, expressions, directives, macros, functions, files.
//!
//! What POV-Ray's parser does before a scene's objects exist: reads the directives where they
//! stand (`reader`), evaluates expressions and the built-in functions (`expr`, `array`,
//! `datetime`), runs macros and user functions (`flow`, `function`), reads and writes data
//! files (`files`) inside the scene's folders (`sandbox`), and says why a word is refused
//! (`keywords`). It hands each statement's objects and materials to the IR builder
//! (`super::build`) and keeps none of the scene's IR itself.

pub(super) mod array;
pub(super) mod datetime;
pub(super) mod expr;
pub(super) mod files;
pub(super) mod flow;
pub(super) mod function;
pub mod keywords;
pub(super) mod reader;
pub(super) mod sandbox;

use crate::diag::{Diagnostic, Span};
use crate::eval::{Evaluator, Names, Result, Value};
use crate::syntax::{self, Node};
use std::collections::HashMap;
use std::sync::Arc;

/// What the language keeps while a scene is read: declarations, macros and their frames, the
/// directive reader, `#version`, random streams and open files.
pub(in crate::eval) struct Language {
    pub(in crate::eval) macros: Names<flow::Macro>,
    pub(in crate::eval) frames: Vec<flow::Frame>,
    /// The directive reader's state: what is being read, the directive blocks open.
    pub(in crate::eval) reader: reader::Reader,
    /// The values of the words of the unit being evaluated, by slot (see `reader.rs`).
    pub(in crate::eval) bindings: Vec<Option<Arc<Value>>>,
    /// Added to slots while an expression read again is evaluated (`ExprKind::Shifted`).
    pub(in crate::eval) slot_shift: u32,
    pub(in crate::eval) include_depth: usize,
    /// Evaluation steps so far (see [`LoadOptions::max_steps`]).
    pub(in crate::eval) steps: u64,
    /// What `#debug` printed.
    pub(in crate::eval) debug_output: String,
    /// The declared names, as the reader sees them.
    pub(in crate::eval) env: Names<Arc<Value>>,
    pub(in crate::eval) version: Option<f64>,
    /// `input_file_name`: the scene file as named.
    pub(in crate::eval) input_file_name: String,
    /// The state of each `seed()` stream, read and advanced by `rand()`.
    pub(in crate::eval) rand_streams: Vec<u32>,
    /// Names declared `deprecated`, with their message: the first use warns.
    pub(in crate::eval) deprecated: HashMap<String, String>,
    /// Files opened by `#fopen`.
    pub(in crate::eval) files: files::Files,
    /// `global_settings { noise_generator N }`, if given (functions' noise follows it).
    pub(in crate::eval) noise_generator: Option<u8>,
    /// `global_settings { assumed_gamma G }`, if given (how `srgb` colours are read).
    pub(in crate::eval) assumed_gamma: Option<f64>,
}

impl Evaluator<'_> {
    /// The value the word in `slot` of the unit being evaluated was bound to where it was
    /// read (see `reader.rs`).
    pub(in crate::eval) fn bound(&self, slot: syntax::Slot) -> Option<&Value> {
        if slot == syntax::Slot::NONE {
            return None;
        }
        self.lang
            .bindings
            .get(slot.0 as usize + self.lang.slot_shift as usize)?
            .as_deref()
    }

    pub(in crate::eval) fn lookup(&mut self, ident: &Node) -> Result<Value> {
        self.item_ref(ident)
    }

    /// A declared value, or the error of a declaration that was outside the subset.
    pub(in crate::eval) fn usable(&mut self, name: &str, v: Value, span: Span) -> Result<Value> {
        if let Some(message) = self.lang.deprecated.remove(name) {
            self.warnings.push(Diagnostic::warning(
                format!("`{name}` is deprecated: {message}"),
                span,
            ));
        }
        match v {
            Value::Unsupported(d) => {
                let mut e =
                    Diagnostic::error(format!("`{name}` cannot be used: {}", d.message), span);
                if let Some(s) = d.span {
                    e = e.with_note(format!(
                        "`{name}` is declared using it at {}",
                        self.location(s)
                    ));
                }
                Err(e)
            }
            v => Ok(v),
        }
    }
}
