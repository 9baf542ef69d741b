//! Shapes drawn from 2-D curves: `text` (glyph outlines extruded along z) and `prism` (spline
//! segments swept along y). The IR holds the curves resolved (glyphs laid out, spline segments
//! as polynomial coefficients), not the points or the font the scene named.

use glam::DVec2;

/// One piece of a glyph outline, in the text's plane (em units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Curve {
    /// A straight edge from the first point to the second.
    Line(DVec2, DVec2),
    /// A quadratic Bézier: start, control, end.
    Quad(DVec2, DVec2, DVec2),
}

/// `text { ttf "font" "string" thickness, offset }`: the glyphs laid out by POV-Ray's rules,
/// filled by the even-odd rule and extruded from z = 0 to z = thickness.
#[derive(Clone, Debug, PartialEq)]
pub struct Text {
    /// Depth of the extrusion (negative: only the two faces, as in POV-Ray).
    pub thickness: f64,
    /// The glyphs in order, each with its own outline (glyphs may overlap; each is filled on
    /// its own).
    pub glyphs: Vec<Glyph>,
}

/// One laid-out glyph: its outline already moved to its place in the line.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Glyph {
    /// The outline's edges (every contour's, in any order: the fill rule is even-odd).
    pub curves: Vec<Curve>,
}

/// How a `prism`'s curve is swept.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sweep {
    /// `linear_sweep`: straight up along y, between the two heights.
    Linear,
    /// `conic_sweep`: the curve lies in the plane y = 1 and is scaled by y (a cone from the
    /// origin).
    Conic,
}

/// The kinds of spline that join a `prism`'s or `lathe`'s points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spline {
    /// `linear_spline`: straight segments.
    Linear,
    /// `quadratic_spline`: one leading control point per curve.
    Quadratic,
    /// `cubic_spline` (Catmull-Rom): one control point before and one after each curve.
    Cubic,
    /// `bezier_spline`: four points per segment.
    Bezier,
}

impl Spline {
    /// The degree of the spline's polynomials.
    pub fn degree(self) -> u8 {
        match self {
            Spline::Linear => 1,
            Spline::Quadratic => 2,
            Spline::Cubic | Spline::Bezier => 3,
        }
    }
}

/// One spline segment in the plane: `x(t)` and `z(t)` for t in [0, 1], each as the
/// coefficients `[A, B, C, D]` of `A t³ + B t² + C t + D`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// First coordinate.
    pub u: [f64; 4],
    /// Second coordinate.
    pub v: [f64; 4],
}

/// `prism { [spline] [sweep] h1, h2, N, points… [open] }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Prism {
    /// How the curve is swept.
    pub sweep: Sweep,
    /// The degree of the segments (1 to 3).
    pub degree: u8,
    /// Bottom and top heights (bottom ≤ top).
    pub heights: (f64, f64),
    /// Whether the two end faces are there (not `open`).
    pub closed: bool,
    /// The spline segments of every sub-curve (x, z).
    pub segments: Vec<Segment>,
    /// `sturm`: accepted; trace's root finder is the same either way.
    pub sturm: bool,
}

/// Two points equal within POV-Ray's tolerance.
fn same(a: DVec2, b: DVec2) -> bool {
    (a.x - b.x).abs() < 1e-10 && (a.y - b.y).abs() < 1e-10
}

impl Prism {
    /// The segments POV-Ray builds from a prism's points: sub-curves, each closed by repeating
    /// its first point (quadratic curves have one leading control point, cubic ones one before
    /// and one after; Bézier segments are four points each and are parametrised from their
    /// last point to their first, as in POV-Ray). `Err` when the points run out in a segment.
    pub fn segments(spline: Spline, p: &[DVec2]) -> Result<Vec<Segment>, &'static str> {
        let n = p.len();
        let mut out = Vec::new();
        let mut first = match spline {
            Spline::Linear => p.first().copied(),
            Spline::Quadratic | Spline::Cubic => p.get(1).copied(),
            Spline::Bezier => None,
        }
        .unwrap_or_default();
        let too_few =
            "too few points in this prism (is a sub-curve not closed, or a control point missing?)";
        let mut i = 0;
        while i + 1 < n {
            let need = match spline {
                Spline::Linear => 1,
                Spline::Quadratic => 2,
                Spline::Cubic | Spline::Bezier => 3,
            };
            if i + need >= n {
                return Err(too_few);
            }
            let (a, b) = (p[i], p[i + 1]);
            let pair = |f: &dyn Fn(f64, f64, f64, f64) -> [f64; 4]| -> Segment {
                let c = |k: usize| p.get(i + k).copied().unwrap_or_default();
                let (c0, c1, c2, c3) = (a, b, c(2), c(3));
                Segment {
                    u: f(c0.x, c1.x, c2.x, c3.x),
                    v: f(c0.y, c1.y, c2.y, c3.y),
                }
            };
            let segment = match spline {
                Spline::Linear => pair(&|p0, p1, _, _| [0.0, 0.0, p1 - p0, p0]),
                Spline::Quadratic => {
                    pair(&|p0, p1, p2, _| [0.0, 0.5 * p0 - p1 + 0.5 * p2, 0.5 * (p2 - p0), p1])
                }
                Spline::Cubic => pair(&|p0, p1, p2, p3| {
                    [
                        -0.5 * p0 + 1.5 * p1 - 1.5 * p2 + 0.5 * p3,
                        p0 - 2.5 * p1 + 2.0 * p2 - 0.5 * p3,
                        0.5 * (p2 - p0),
                        p1,
                    ]
                }),
                Spline::Bezier => pair(&|p0, p1, p2, p3| {
                    [
                        p0 - 3.0 * p1 + 3.0 * p2 - p3,
                        3.0 * p1 - 6.0 * p2 + 3.0 * p3,
                        3.0 * p2 - 3.0 * p3,
                        p3,
                    ]
                }),
            };
            out.push(segment);
            // The next segment: after a closing point the next sub-curve's points.
            match spline {
                Spline::Linear if same(p[i + 1], first) => {
                    i += 1;
                    if i + 1 < n {
                        first = p[i + 1];
                    }
                }
                Spline::Quadratic if same(p[i + 2], first) => {
                    i += 2;
                    if i + 2 < n {
                        first = p[i + 2];
                    }
                }
                Spline::Cubic if same(p[i + 2], first) => {
                    i += 3;
                    if i + 2 < n {
                        first = p[i + 2];
                    }
                }
                Spline::Bezier => i += 3,
                _ => {}
            }
            i += 1;
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64) -> DVec2 {
        DVec2::new(x, y)
    }

    /// Two closed squares make eight straight segments; the point after a closing one starts
    /// the next sub-polygon.
    #[test]
    fn linear_sub_polygons() {
        let sq = |o: f64| {
            [
                v(o, 0.0),
                v(o + 1.0, 0.0),
                v(o + 1.0, 1.0),
                v(o, 1.0),
                v(o, 0.0),
            ]
        };
        let points: Vec<DVec2> = sq(0.0).into_iter().chain(sq(3.0)).collect();
        let s = Prism::segments(Spline::Linear, &points).unwrap();
        assert_eq!(s.len(), 8);
        assert_eq!(s[4].u, [0.0, 0.0, 1.0, 3.0]);
    }

    /// A cubic curve needs a control point after its closing point.
    #[test]
    fn cubic_needs_its_trailing_control_point() {
        let ring = [
            v(0.0, 1.0),
            v(1.0, 0.0),
            v(0.0, -1.0),
            v(-1.0, 0.0),
            v(0.0, 1.0),
            v(1.0, 0.0),
        ];
        let closed = [&[v(-1.0, 0.0)][..], &ring].concat();
        assert_eq!(Prism::segments(Spline::Cubic, &closed).unwrap().len(), 4);
        assert!(Prism::segments(Spline::Cubic, &closed[..5]).is_err());
        // Catmull-Rom passes through its points: segment 0 runs from p1 to p2.
        let s = Prism::segments(Spline::Cubic, &closed).unwrap()[0];
        let at = |c: [f64; 4], t: f64| ((c[0] * t + c[1]) * t + c[2]) * t + c[3];
        assert_eq!((at(s.u, 0.0), at(s.v, 0.0)), (0.0, 1.0));
        assert!((at(s.u, 1.0) - 1.0).abs() < 1e-12 && at(s.v, 1.0).abs() < 1e-12);
    }

    /// A Bézier segment runs from its fourth point (t = 0) to its first (t = 1).
    #[test]
    fn bezier_runs_backwards() {
        let p = [v(0.0, 0.0), v(1.0, 2.0), v(2.0, 2.0), v(3.0, 0.0)];
        let s = Prism::segments(Spline::Bezier, &p).unwrap();
        assert_eq!(s.len(), 1);
        assert_eq!((s[0].u[3], s[0].v[3]), (3.0, 0.0));
        let sum = |c: [f64; 4]| c.iter().sum::<f64>();
        assert_eq!((sum(s[0].u), sum(s[0].v)), (0.0, 0.0));
    }
}
