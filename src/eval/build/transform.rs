//! Transformations: `translate`, `rotate`, `scale`, `matrix`, `transform { … [inverse] }`.
//!
//! POV-Ray multiplies row vectors (`p' = p·M`) and composes in the order written; the IR uses
//! glam's column vectors, so each step multiplies on the left.

use crate::diag::Diagnostic;
use crate::eval::Evaluator;
use crate::ir::Transform;
use crate::syntax::{ExprKind, Node, NodeKind, View};
use glam::{DMat3, DMat4, DVec3};

impl Evaluator<'_> {
    /// Whether a node is a transformation.
    pub(in crate::eval) fn is_transform(node: &Node) -> bool {
        matches!(
            node.kind,
            NodeKind::Translate
                | NodeKind::Rotate
                | NodeKind::Scale
                | NodeKind::Matrix
                | NodeKind::Transform
        )
    }

    /// Evaluates one transformation node.
    pub(in crate::eval) fn transform(&mut self, node: &Node) -> Result<Transform, Diagnostic> {
        let matrix = match node.view() {
            View::Translate(v) => DMat4::from_translation(self.vec3(v)?),
            View::Rotate(v) => crate::eval::lang::expr::rotation(self.vec3(v)?),
            View::Scale(v) => {
                let mut s = self.vec3(v)?;
                // POV-Ray replaces a zero scale component by 1 (with a warning).
                for c in [&mut s.x, &mut s.y, &mut s.z] {
                    if *c == 0.0 {
                        *c = 1.0;
                        self.warn(Diagnostic::warning(
                            "zero scale component replaced by 1 (as POV-Ray does)",
                            v.span,
                        ));
                    }
                }
                DMat4::from_scale(s)
            }
            View::Matrix(arg) => {
                let ExprKind::Vector(items) = &arg.kind else {
                    return Err(Diagnostic::error(
                        "`matrix` needs a 12-component vector <m00, …, m32>",
                        arg.span,
                    ));
                };
                if items.len() != 12 {
                    return Err(Diagnostic::error(
                        format!("`matrix` needs 12 components, found {}", items.len()),
                        arg.span,
                    ));
                }
                let mut m = [0.0; 12];
                for (slot, item) in m.iter_mut().zip(items) {
                    *slot = self.float(item)?;
                }
                // Row i of POV-Ray's matrix is what the ith basis vector becomes.
                let linear =
                    DMat3::from_cols_array(&[m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]]);
                let matrix = DMat4::from_translation(DVec3::new(m[9], m[10], m[11]))
                    * DMat4::from_mat3(linear);
                if matrix.determinant().abs() < 1e-300 {
                    return Err(Diagnostic::error(
                        "`matrix` is singular (cannot be inverted)",
                        arg.span,
                    ));
                }
                matrix
            }
            View::Block if node.kind == NodeKind::Transform => return self.transform_block(node),
            _ => return Err(crate::eval::malformed(node, "a transformation")),
        };
        Ok(Transform { matrix })
    }

    /// `transform { items [inverse] }` or `transform Name`.
    fn transform_block(&mut self, node: &Node) -> Result<Transform, Diagnostic> {
        let mut t = Transform::IDENTITY;
        let mut inverse = false;
        // (Directives may stand among the items, as transforms.inc's macros write them.)
        self.each_item(&node.children, &mut |ev, child| {
            match child.kind {
                NodeKind::Inverse => inverse = true,
                NodeKind::IdentRef => t = t.then(ev.declared_transform(child)?),
                _ if Self::is_transform(child) => t = t.then(ev.transform(child)?),
                _ => return Err(ev.unknown_item(child, "transform")),
            }
            Ok(())
        })?;
        Ok(if inverse { t.inverse() } else { t })
    }

    fn declared_transform(&mut self, ident: &Node) -> Result<Transform, Diagnostic> {
        match self.lookup(ident)? {
            crate::eval::Value::Transform(t) => Ok(*t),
            other => Err(crate::eval::lang::expr::type_error(
                "a transform",
                &other,
                ident.span,
            )),
        }
    }
}
