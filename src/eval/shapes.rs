//! The evaluator's shape table: a shape keyword of the generic `shape` rule and its values,
//! made into an IR shape. Adding a shape: its word in the grammar's `shape_kw`, an arm here,
//! its IR variant and its geometry (`geometry/`, one file and one line in `shape.rs`).

use super::{Evaluator, Result, Value, expr::type_error};
use crate::diag::Diagnostic;
use crate::ir::{Polynomial, Quadric, Shape};
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
                Shape::Quadric(Box::new(Quadric {
                    square: self.vec3(&args[0])?,
                    mixed: self.vec3(&args[1])?,
                    linear: self.vec3(&args[2])?,
                    constant: self.float(&args[3])?,
                }))
            }
            "cubic" | "quartic" | "poly" => {
                let form = match node.word.as_str() {
                    "poly" => "poly { N, <coefficients> }",
                    "cubic" => "cubic { <20 coefficients> }",
                    _ => "quartic { <35 coefficients> }",
                };
                let poly = node.word == "poly";
                count(if poly { 2 } else { 1 }, form)?;
                let degree = match node.word.as_str() {
                    "cubic" => 3,
                    "quartic" => 4,
                    _ => {
                        let n = self.float(&args[0])?;
                        if !(2.0..=4.0).contains(&n) {
                            return Err(Diagnostic::error(
                                "unsupported: a poly of degree other than 2 to 4 (trace's root solver goes to 4)",
                                args[0].span,
                            ));
                        }
                        n as u8
                    }
                };
                let list = &args[usize::from(poly)];
                // The coefficients: a literal list of any length (POV-Ray reads it so).
                let coefficients = match &list.kind {
                    crate::syntax::ExprKind::Vector(items) => items
                        .iter()
                        .map(|e| self.float(e))
                        .collect::<Result<Vec<f64>>>()?,
                    _ => match self.eval(list)? {
                        Value::Vector(v) => v.c[..v.len].to_vec(),
                        other => return Err(type_error("a list of coefficients", &other, list.span)),
                    },
                };
                let polynomial = Polynomial::from_povray(degree, &coefficients).ok_or_else(|| {
                    let n = degree as usize;
                    Diagnostic::error(
                        format!(
                            "a polynomial of degree {degree} has {} coefficients, this list has {}",
                            (n + 1) * (n + 2) * (n + 3) / 6,
                            coefficients.len()
                        ),
                        list.span,
                    )
                })?;
                Shape::Polynomial(Box::new(polynomial))
            }
            "polygon" => {
                let n = match args.first() {
                    Some(e) => self.float(e)?,
                    None => return Err(count(1, "polygon { N, P1, …, PN }").unwrap_err()),
                };
                if n < 3.0 {
                    return Err(Diagnostic::error("a polygon needs at least three points", args[0].span));
                }
                if args.len() - 1 != n as usize {
                    return Err(Diagnostic::error(
                        format!("this polygon announces {} points and lists {}", n as usize, args.len() - 1),
                        args[0].span,
                    ));
                }
                let mut points = args[1..]
                    .iter()
                    .map(|e| self.vec3(e))
                    .collect::<Result<Vec<_>>>()?;
                // POV-Ray's closing: a point equal (within 1e-10) to its sub-polygon's first
                // closes it and starts the next; an open last one is closed with a warning.
                let mut first = points[0];
                let mut closed = false;
                let mut i = 1;
                while i < points.len() {
                    closed = false;
                    if (points[i] - first).abs().max_element() < 1e-10 {
                        points[i] = first;
                        i += 1;
                        if i < points.len() {
                            first = points[i];
                        }
                        closed = true;
                    }
                    i += 1;
                }
                if !closed {
                    self.warn(Diagnostic::warning(
                        "polygon not closed: closing it (as POV-Ray does)",
                        node.word_span,
                    ));
                    points.push(first);
                }
                Shape::Polygon(Box::new(points))
            }
            _ => return Err(self.unknown_word(&node.word, node.word_span)),
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::ir::Polynomial;

    /// POV-Ray's order of a polynomial's terms: by the power of x, then of y, then of z, each
    /// descending (`x⁴, x³y, x³z, x³, x²y², x²yz, …, z, 1`).
    #[test]
    fn polynomial_coefficients_follow_povrays_order() {
        let all = |degree: u8, n: usize| {
            Polynomial::from_povray(degree, &(1..=n).map(|v| v as f64).collect::<Vec<_>>())
                .expect("the right count")
        };
        assert_eq!(all(2, 10).terms.len(), 10);
        assert_eq!(all(3, 20).terms.len(), 20);
        let q = all(4, 35);
        let powers: Vec<[u8; 3]> = q.terms.iter().map(|t| t.1).collect();
        assert_eq!(&powers[..6], &[[4, 0, 0], [3, 1, 0], [3, 0, 1], [3, 0, 0], [2, 2, 0], [2, 1, 1]]);
        assert_eq!(powers[20], [0, 4, 0]);
        assert_eq!(&powers[33..], &[[0, 0, 1], [0, 0, 0]]);
        assert!(Polynomial::from_povray(4, &[1.0; 34]).is_none());
        // Zero terms are left out.
        let mut c = [0.0; 35];
        c[34] = -1.0;
        assert_eq!(Polynomial::from_povray(4, &c).unwrap().terms, vec![(-1.0, [0, 0, 0])]);
    }
}
