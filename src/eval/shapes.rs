//! The evaluator's shape table: a shape keyword of the generic `shape` rule and its values,
//! made into an IR shape. Adding a shape: its word in the grammar's `shape_kw`, an arm here,
//! its IR variant and its geometry (`geometry/`, one file and one line in `shape.rs`).

use super::{Evaluator, Result};
use crate::diag::Diagnostic;
use crate::ir::Shape;
use crate::syntax::Node;

impl Evaluator<'_> {
    /// The IR shape of a `shape` node (`quadric { … }` …).
    pub(super) fn shape_table(&mut self, node: &Node) -> Result<Shape> {
        let args = node.args.as_slice();
        // The values a shape takes, in order, or a located error naming what is missing.
        let count = |n: usize, form: &str| -> Result<()> {
            if args.len() == n {
                return Ok(());
            }
            let at = args.get(n).map_or(node.word_span, |e| e.span);
            Err(Diagnostic::error(
                format!("`{}` takes {n} values: {form}", node.word),
                at,
            ))
        };
        Ok(match node.word.as_str() {
            "quadric" => {
                count(4, "quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }")?;
                Shape::Quadric {
                    square: self.vec3(&args[0])?,
                    mixed: self.vec3(&args[1])?,
                    linear: self.vec3(&args[2])?,
                    constant: self.float(&args[3])?,
                }
            }
            _ => return Err(self.unknown_word(&node.word, node.word_span)),
        })
    }
}
