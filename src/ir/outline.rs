//! Shapes drawn from 2-D curves: `text` (glyph outlines extruded along z), `prism` (spline
//! segments swept along y), `lathe` and `sor` (profiles turned about y). The IR holds the
//! curves resolved (glyphs laid out, spline segments as polynomial coefficients), not the
//! points or the font the scene named.

use glam::{DMat4, DVec2, DVec3};

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

/// One spline segment in the plane: `u(t)` and `v(t)` for t in [0, 1] (a prism's x and z, a
/// lathe's radius and height), each as the coefficients `[A, B, C, D]` of
/// `A t³ + B t² + C t + D`.
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

/// `lathe { [spline] N, <r, y>… }`: a profile in the (radius, height) plane turned about y.
#[derive(Clone, Debug, PartialEq)]
pub struct Lathe {
    /// The degree of the segments (1 to 3).
    pub degree: u8,
    /// The profile's segments (radius, height).
    pub segments: Vec<Segment>,
    /// `sturm`: accepted; trace's root finder is the same either way.
    pub sturm: bool,
}

impl Lathe {
    /// The segments POV-Ray builds from a lathe's points: linear and quadratic curves pass
    /// through every point but a quadratic's first (a control point), cubic ones (Catmull-Rom)
    /// through all but the first and last, Bézier segments take four points each (from their
    /// first point at t = 0).
    pub fn segments(spline: Spline, p: &[DVec2]) -> Vec<Segment> {
        let seg = |f: &dyn Fn(f64, f64, f64, f64) -> [f64; 4], q: [DVec2; 4]| Segment {
            u: f(q[0].x, q[1].x, q[2].x, q[3].x),
            v: f(q[0].y, q[1].y, q[2].y, q[3].y),
        };
        let four = |i: usize| std::array::from_fn(|k| p.get(i + k).copied().unwrap_or_default());
        match spline {
            Spline::Linear => (0..p.len().saturating_sub(1))
                .map(|i| seg(&|a, b, _, _| [0.0, 0.0, b - a, a], four(i)))
                .collect(),
            Spline::Quadratic => (0..p.len().saturating_sub(2))
                .map(|i| {
                    seg(
                        &|a, b, c, _| [0.0, 0.5 * a - b + 0.5 * c, 0.5 * (c - a), b],
                        four(i),
                    )
                })
                .collect(),
            Spline::Cubic => (0..p.len().saturating_sub(3))
                .map(|i| {
                    seg(
                        &|a, b, c, d| {
                            [
                                -0.5 * a + 1.5 * b - 1.5 * c + 0.5 * d,
                                a - 2.5 * b + 2.0 * c - 0.5 * d,
                                0.5 * (c - a),
                                b,
                            ]
                        },
                        four(i),
                    )
                })
                .collect(),
            Spline::Bezier => (0..p.len() / 4)
                .map(|s| {
                    seg(
                        &|a, b, c, d| {
                            [
                                d - 3.0 * c + 3.0 * b - a,
                                3.0 * c - 6.0 * b + 3.0 * a,
                                3.0 * b - 3.0 * a,
                                a,
                            ]
                        },
                        four(4 * s),
                    )
                })
                .collect(),
        }
    }
}

/// One piece of a surface of revolution: `r² = A y³ + B y² + C y + D` for y in `heights`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SorSegment {
    /// `[A, B, C, D]`.
    pub coefficients: [f64; 4],
    /// The heights it covers (increasing).
    pub heights: (f64, f64),
}

/// `sor { N, <r, y>… [open] }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Sor {
    /// The pieces, by increasing height.
    pub segments: Vec<SorSegment>,
    /// Whether the end discs are there (not `open`).
    pub closed: bool,
    /// `sturm`: accepted; trace's root finder is the same either way.
    pub sturm: bool,
}

impl Sor {
    /// POV-Ray's pieces through points `p` (radius, height): piece i joins points i + 1 and
    /// i + 2 by the cubic in y whose value is the squared radius at both ends and whose slope
    /// there comes from the neighbouring points; coefficients below 1e-10 are zero. `Err`
    /// when two heights a piece divides by are equal.
    pub fn segments(p: &[DVec2]) -> Result<Vec<SorSegment>, &'static str> {
        let mut out = Vec::new();
        for i in 0..p.len().saturating_sub(3) {
            let (a, b, c, d) = (p[i], p[i + 1], p[i + 2], p[i + 3]);
            if (c.y - a.y).abs() < 1e-10 || (d.y - b.y).abs() < 1e-10 {
                return Err("two points of this surface of revolution are at the same height");
            }
            let (y1, y2) = (b.y, c.y);
            let (f1, f2) = (b.x * b.x, c.x * c.x);
            let k1 = 2.0 * b.x * (c.x - a.x) / (c.y - a.y);
            let k2 = 2.0 * c.x * (d.x - b.x) / (d.y - b.y);
            // Hermite form in s = (y − y1) / h, then expanded in powers of y.
            let h = y2 - y1;
            let s3 = 2.0 * (f1 - f2) + h * (k1 + k2);
            let s2 = 3.0 * (f2 - f1) - h * (2.0 * k1 + k2);
            let s1 = h * k1;
            let (a3, a2, a1) = (s3 / (h * h * h), s2 / (h * h), s1 / h);
            let mut coefficients = [
                a3,
                a2 - 3.0 * a3 * y1,
                a1 - 2.0 * a2 * y1 + 3.0 * a3 * y1 * y1,
                f1 - a1 * y1 + a2 * y1 * y1 - a3 * y1 * y1 * y1,
            ];
            for c in &mut coefficients {
                if c.abs() < 1e-10 {
                    *c = 0.0;
                }
            }
            out.push(SorSegment {
                coefficients,
                heights: (y1, y2),
            });
        }
        Ok(out)
    }
}

/// Where a blob component's field acts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BlobReach {
    /// Around a point.
    Sphere(DVec3),
    /// Around the segment between two points (with half-sphere ends).
    Cylinder(DVec3, DVec3),
}

/// One component of a blob: `strength (1 − r²/radius²)²` within `radius` of its centre.
#[derive(Clone, Debug, PartialEq)]
pub struct BlobComponent {
    /// Its centre point or segment.
    pub reach: BlobReach,
    /// Radius of influence.
    pub radius: f64,
    /// Strength (negative: it takes away).
    pub strength: f64,
    /// The component's own transformations (a stretched sphere is an ellipsoid).
    pub transform: Option<DMat4>,
    /// The component's own texture, in blob space (moved by the component's transformations
    /// that follow it); where components with textures act, the surface blends them by
    /// their fields, as POV-Ray does.
    pub texture: Option<Box<super::Texture>>,
}

/// `blob { threshold T components… }`: where the components' fields add up to the threshold.
#[derive(Clone, Debug, PartialEq)]
pub struct Blob {
    /// The field's value on the surface.
    pub threshold: f64,
    /// The components, in the scene's order.
    pub components: Vec<BlobComponent>,
}

/// What holds an isosurface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Container {
    /// A box between its least and greatest corners.
    Box(DVec3, DVec3),
    /// A sphere: centre and radius.
    Sphere(DVec3, f64),
}

/// `isosurface { function {…} … }`: where the function reaches its threshold within the
/// container.
#[derive(Clone, Debug, PartialEq)]
pub struct Isosurface {
    /// The function of x, y, z.
    pub function: std::sync::Arc<crate::func::Function>,
    /// `contained_by { box {…} | sphere {…} }` (default the box from <-1,-1,-1> to <1,1,1>).
    pub container: Container,
    /// `threshold` (default 0).
    pub threshold: f64,
    /// `accuracy` (default 0.001).
    pub accuracy: f64,
    /// `max_gradient` (default 1.1).
    pub max_gradient: f64,
    /// Not `open`: the container closes the surface.
    pub closed: bool,
    /// `max_trace` (default 1; `all_intersections` 10).
    pub max_trace: u32,
}

/// `parametric { … }`: the surface (fx(u, v), fy(u, v), fz(u, v)) over a (u, v) rectangle.
#[derive(Clone, Debug, PartialEq)]
pub struct Parametric {
    /// fx, fy, fz, each a function of u and v.
    pub functions: [std::sync::Arc<crate::func::Function>; 3],
    /// The (u, v) rectangle's corners.
    pub uv: (glam::DVec2, glam::DVec2),
    /// `contained_by` (default the box ±1).
    pub container: Container,
    /// `accuracy` (default 0.001).
    pub accuracy: f64,
    /// `max_gradient` (default 1).
    pub max_gradient: f64,
    /// `precompute D, x, y, z`: the depth and which functions.
    pub precompute: Option<(u32, [bool; 3])>,
}

/// How a `sphere_sweep` passes from one sphere to the next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepSpline {
    /// `linear_spline`: straight between consecutive spheres.
    Linear,
    /// `cubic_spline`: a Catmull-Rom curve through all but the first and last spheres.
    CatmullRom,
    /// `b_spline`: a uniform cubic B-spline the spheres control (it need not pass through them).
    BSpline,
}

/// `sphere_sweep { spline N, <centre>, radius … [tolerance T] }`: the volume a sphere sweeps
/// along a spline of centres and radii.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereSweep {
    /// The spline.
    pub spline: SweepSpline,
    /// The modelling spheres (centre, radius), in order.
    pub spheres: Vec<(DVec3, f64)>,
    /// Hits at or below this distance are ignored (POV-Ray's depth tolerance, default 1e-6).
    pub tolerance: f64,
}

/// `height_field { png "file" [smooth] [water_level W] }`: heights on a grid, in POV-Ray's
/// raw units (the object's transformation takes the grid to the unit box).
#[derive(Clone, PartialEq)]
pub struct HeightField {
    /// Grid points across (x).
    pub width: u32,
    /// Grid points deep (z).
    pub depth: u32,
    /// The 16-bit heights, row z = 0 (the image's bottom row) first.
    pub heights: std::sync::Arc<Vec<u16>>,
    /// Normals blended between grid points.
    pub smooth: bool,
    /// The water level in raw units (0 to 65536): nothing below it is drawn.
    pub water_level: f64,
}

/// `bicubic_patch { type T flatness F u_steps U v_steps V P00 … P33 }`: POV-Ray draws the
/// triangles of its subdivision, made after the object's transformation (scene building).
#[derive(Clone, Debug, PartialEq)]
pub struct BicubicPatch {
    /// The 16 control points, u index first.
    pub points: [[DVec3; 4]; 4],
    /// Halvings in u.
    pub u_steps: u32,
    /// Halvings in v.
    pub v_steps: u32,
    /// A piece whose control points lie this close to a plane is not halved further.
    pub flatness: f64,
    /// `uv_vectors C0 C1 C2 C3`: the uv corners the patch's unit square maps to (bilinearly),
    /// when not POV-Ray's default (0, 0), (1, 0), (1, 1), (0, 1).
    pub uv_corners: Option<[[f64; 2]; 4]>,
}

/// `julia_fractal { <c> [quaternion|hypercomplex] [sqr|cube] [max_iteration N] [precision P]
/// [slice <s>, d] }`.
#[derive(Clone, Debug, PartialEq)]
pub struct JuliaFractal {
    /// The 4-D parameter.
    pub c: glam::DVec4,
    /// Hypercomplex rather than quaternion algebra.
    pub hypercomplex: bool,
    /// `cube` rather than `sqr`.
    pub cube: bool,
    /// Iterations.
    pub iterations: u32,
    /// Marching steps per unit.
    pub precision: f64,
    /// The 3-D slice's normal in 4-D and its distance.
    pub slice: (glam::DVec4, f64),
}

/// The grid in short: its size, range and a checksum of the heights (FNV-1a), so that IR
/// snapshots show a change of any height without listing them all.
impl std::fmt::Debug for HeightField {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (lo, hi) = self
            .heights
            .iter()
            .fold((u16::MAX, 0), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        let sum = self.heights.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &v| {
            (h ^ u64::from(v)).wrapping_mul(0x0100_0000_01b3)
        });
        f.debug_struct("HeightField")
            .field("width", &self.width)
            .field("depth", &self.depth)
            .field("lowest", &lo)
            .field("highest", &hi)
            .field("checksum", &format_args!("{sum:016x}"))
            .field("smooth", &self.smooth)
            .field("water_level", &self.water_level)
            .finish()
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

    /// A sor piece takes the squared radii at its ends and the neighbours' slopes.
    #[test]
    fn sor_pieces_interpolate_squared_radii() {
        let p = [
            v(0.5, -1.0),
            v(1.0, 0.0),
            v(2.0, 1.0),
            v(1.0, 2.0),
            v(0.5, 3.0),
        ];
        let s = Sor::segments(&p).unwrap();
        assert_eq!(s.len(), 2);
        let f = |c: [f64; 4], y: f64| ((c[0] * y + c[1]) * y + c[2]) * y + c[3];
        assert!((f(s[0].coefficients, 0.0) - 1.0).abs() < 1e-12);
        assert!((f(s[0].coefficients, 1.0) - 4.0).abs() < 1e-12);
        assert!((f(s[1].coefficients, 2.0) - 1.0).abs() < 1e-12);
        // Slope at y = 1 on piece 0: 2·r·(r₂ − r₀)/(y₂ − y₀) = 2·2·(1 − 1)/2 = 0.
        let c = s[0].coefficients;
        assert!((3.0 * c[0] + 2.0 * c[1] + c[2]).abs() < 1e-12);
        assert!(Sor::segments(&[v(1.0, 0.0), v(1.0, 1.0), v(1.0, 0.0), v(1.0, 3.0)]).is_err());
    }

    /// Lathe Bézier segments run forwards; cubic ones skip the first and last point.
    #[test]
    fn lathe_segments() {
        let p = [v(0.0, 0.0), v(1.0, 2.0), v(2.0, 2.0), v(3.0, 0.0)];
        let b = Lathe::segments(Spline::Bezier, &p);
        assert_eq!((b.len(), b[0].u[3]), (1, 0.0));
        assert_eq!(Lathe::segments(Spline::Cubic, &p).len(), 1);
        assert_eq!(Lathe::segments(Spline::Quadratic, &p).len(), 2);
        assert_eq!(Lathe::segments(Spline::Linear, &p).len(), 3);
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
