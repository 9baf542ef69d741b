//! `text`: glyph outlines (straight edges and quadratic curves in the x-y plane) extruded from
//! z = 0 to z = depth, each glyph filled by the even-odd rule (POV-Ray's TrueType object).
//!
//! A ray meets the two faces where they lie inside the outline (POV-Ray's crossing count,
//! with its tie rules) and the walls where it crosses an edge between the faces.

use super::poly::roots_in;
use super::{Crossings, Ray};
use glam::{DVec2, DVec3};

/// POV-Ray's tolerance for parallel rays and degenerate edges.
const EPSILON: f64 = 1e-10;

/// One edge of an outline: a line (`control` unused) or a quadratic Bézier.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Edge {
    /// Start point.
    pub start: DVec2,
    /// Control point of a curve.
    pub control: DVec2,
    /// End point.
    pub end: DVec2,
    /// Whether the edge is a curve.
    pub curved: bool,
}

impl Edge {
    /// (A, B) of the curve `A s² + B s + start`.
    fn coefficients(&self) -> (DVec2, DVec2) {
        (
            self.start - 2.0 * self.control + self.end,
            2.0 * (self.control - self.start),
        )
    }

    fn at(&self, s: f64) -> DVec2 {
        let (a, b) = self.coefficients();
        (a * s + b) * s + self.start
    }
}

/// A glyph: its edges' range and its box in the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
struct GlyphBox {
    first: u32,
    end: u32,
    lo: DVec2,
    hi: DVec2,
}

/// Extruded glyph outlines in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Text {
    depth: f64,
    edges: Box<[Edge]>,
    glyphs: Box<[GlyphBox]>,
}

/// Part tags: the face at z = 0, the face at z = depth, then one per edge.
const FRONT: u32 = 0;
const BACK: u32 = 1;
const WALL: u32 = 2;

impl Text {
    /// Text of the glyphs given as lists of edges, `depth` deep.
    pub fn new(depth: f64, glyphs: impl IntoIterator<Item = Vec<Edge>>) -> Text {
        let mut edges = Vec::new();
        let mut boxes = Vec::new();
        for glyph in glyphs {
            if glyph.is_empty() {
                continue;
            }
            let first = edges.len() as u32;
            let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
            // A curve lies within its control triangle (a line's control is its start).
            for e in &glyph {
                lo = lo.min(e.start).min(e.control).min(e.end);
                hi = hi.max(e.start).max(e.control).max(e.end);
            }
            edges.extend(glyph);
            boxes.push(GlyphBox {
                first,
                end: edges.len() as u32,
                lo,
                hi,
            });
        }
        Text {
            depth,
            edges: edges.into_boxed_slice(),
            glyphs: boxes.into_boxed_slice(),
        }
    }

    /// POV-Ray's even-odd test of plane point (x, y) against one glyph, counting crossings
    /// of the ray towards +x.
    fn inside_glyph(&self, g: &GlyphBox, x: f64, y: f64) -> bool {
        if x < g.lo.x || y < g.lo.y || x > g.hi.x || y > g.hi.y {
            return false;
        }
        let mut crossings = 0u32;
        for e in &self.edges[g.first as usize..g.end as usize] {
            if !e.curved {
                let (x0, y0, x1, y1) = (e.start.x, e.start.y, e.end.x, e.end.y);
                if y0 == y1 || (y0 < y) == (y1 < y) {
                    continue;
                }
                let (right0, right1) = (x0 > x, x1 > x);
                if right0 && right1 {
                    crossings += 1;
                } else if right0 || right1 {
                    let m = (y1 - y0) / (x1 - x0);
                    if (y1 - y - m * (x1 - x)) / m < EPSILON {
                        crossings += 1;
                    }
                }
                continue;
            }
            let (sy, cy, ey) = (e.start.y, e.control.y, e.end.y);
            if (sy < y && cy < y && ey < y) || (sy > y && cy > y && ey > y) {
                continue;
            }
            let (a, b) = e.coefficients();
            for s in quadratic_roots(a.y, b.y, sy - y).into_iter().flatten() {
                if s <= EPSILON && ((y <= sy && y < cy) || (y >= sy && y > cy)) {
                    continue;
                }
                if s >= 1.0 - EPSILON && ((y < ey && y < cy) || (y > ey && y > cy)) {
                    continue;
                }
                if e.at(s).x > x {
                    crossings += 1;
                }
            }
        }
        crossings % 2 == 1
    }

    /// Whether plane point (x, y) lies inside any glyph.
    fn inside_any(&self, x: f64, y: f64) -> bool {
        self.glyphs.iter().any(|g| self.inside_glyph(g, x, y))
    }

    /// Calls `f` with every crossing (distance, part).
    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        let (p, d) = (ray.origin, ray.direction);
        let (zlo, zhi) = (self.depth.min(0.0), self.depth.max(0.0));
        let keep = |t: f64| t > 1e-6 && ray.contains(t);
        for g in self.glyphs.iter() {
            if !slab_hit(ray, g.lo.extend(zlo), g.hi.extend(zhi)) {
                continue;
            }
            if d.z.abs() >= EPSILON {
                let t0 = -p.z / d.z;
                if keep(t0) && self.inside_glyph(g, p.x + t0 * d.x, p.y + t0 * d.y) {
                    f(t0, FRONT);
                }
                let t1 = t0 + self.depth / d.z;
                if keep(t1) && self.inside_glyph(g, p.x + t1 * d.x, p.y + t1 * d.y) {
                    f(t1, BACK);
                }
            }
            if d.x.abs() < EPSILON && d.y.abs() < EPSILON {
                continue;
            }
            let by_x = d.x.abs() >= EPSILON;
            let along = |q: DVec2| {
                if by_x {
                    (q.x - p.x) / d.x
                } else {
                    (q.y - p.y) / d.y
                }
            };
            let mut wall = |t: f64, i: usize| {
                let z = p.z + t * d.z;
                if (0.0..=self.depth).contains(&z) && keep(t) {
                    f(t, WALL + i as u32);
                }
            };
            for i in g.first as usize..g.end as usize {
                let e = &self.edges[i];
                if !e.curved {
                    let dv = e.end - e.start;
                    let den = dv.y * d.x - dv.x * d.y;
                    if den.abs() < EPSILON {
                        continue;
                    }
                    let u = (d.x * (p.y - e.start.y) - d.y * (p.x - e.start.x)) / den;
                    if (0.0..=1.0).contains(&u) {
                        wall(along(e.start + u * dv), i);
                    }
                    continue;
                }
                // The ray's line in the plane: a·x + b·y + c = 0.
                let (a, b, c) = (d.y, -d.x, p.y * d.x - p.x * d.y);
                let (qa, qb) = e.coefficients();
                let roots = quadratic_roots(
                    a * qa.x + b * qa.y,
                    a * qb.x + b * qb.y,
                    a * e.start.x + b * e.start.y + c,
                );
                for s in roots.into_iter().flatten() {
                    wall(along(e.at(s)), i);
                }
            }
        }
    }
}

/// POV-Ray's solver for `a s² + b s + c = 0` on [0, 1]: linear below 1e-20, no root for a
/// discriminant below 1e-10 (so tangencies drop out in pairs).
fn quadratic_roots(a: f64, b: f64, c: f64) -> [Option<f64>; 2] {
    let unit = |s: f64| (0.0..=1.0).contains(&s).then_some(s);
    if a.abs() < 1e-20 {
        if b.abs() < 1e-20 {
            return [None, None];
        }
        return [unit(-c / b), None];
    }
    let disc = b * b - 4.0 * a * c;
    if disc < EPSILON {
        return [None, None];
    }
    let root = disc.sqrt();
    [unit((-b + root) / (2.0 * a)), unit((-b - root) / (2.0 * a))]
}

/// Whether the ray meets the box (widened a little, so that edges on its sides count) within
/// its interval.
fn slab_hit(ray: &Ray, lo: DVec3, hi: DVec3) -> bool {
    let pad = 1e-9 * (hi - lo).max_element().max(1.0);
    let bound = super::Cuboid {
        min: lo - pad,
        max: hi + pad,
    };
    !super::shape::Surface::intersect(&bound, ray).is_empty()
}

impl super::shape::Surface for Text {
    const NAME: &'static str = "Text";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::nearest_of(|f| self.crossings(ray, f))
    }

    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        let n = match part {
            FRONT => DVec3::NEG_Z,
            BACK => DVec3::Z,
            _ => {
                let e = &self.edges[(part - WALL) as usize];
                let tangent = if e.curved {
                    let (a, b) = e.coefficients();
                    2.0 * a * nearest(e, p.truncate()) + b
                } else {
                    e.end - e.start
                };
                // POV-Ray's raw wall normal, the tangent turned to the right: into the solid
                // for TrueType's clockwise outer contours. Shading turns normals towards the
                // ray; which side an interior_texture shows follows POV-Ray's sense.
                DVec3::new(tangent.y, -tangent.x, 0.0)
            }
        };
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        (0.0..=self.depth).contains(&p.z) && self.inside_any(p.x, p.y)
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let (lo, hi) = self.glyphs.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), g| (lo.min(g.lo), hi.max(g.hi)),
        );
        if self.glyphs.is_empty() {
            return Some((DVec3::ZERO, DVec3::ZERO));
        }
        // (POV-Ray's glyph boxes reach its tolerance past the faces.)
        Some((
            lo.extend(self.depth.min(0.0) - 1e-6),
            hi.extend(self.depth.max(0.0) + 1e-6),
        ))
    }

    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        self.crossings(ray, f)
    }
}

/// The curve parameter of the point of `e` nearest `q`.
fn nearest(e: &Edge, q: DVec2) -> f64 {
    let (a, b) = e.coefficients();
    let w = e.start - q;
    // d/ds |Q(s) − q|² / 2 = (A s² + B s + w)·(2A s + B).
    let c = [
        b.dot(w),
        b.dot(b) + 2.0 * a.dot(w),
        3.0 * a.dot(b),
        2.0 * a.dot(a),
        0.0,
        0.0,
        0.0,
    ];
    let mut best = (f64::INFINITY, 0.0);
    let candidates = roots_in(&c, 3, 0.0, 1.0);
    for s in candidates.as_slice().iter().copied().chain([0.0, 1.0]) {
        let d = (e.at(s) - q).length_squared();
        if d < best.0 {
            best = (d, s);
        }
    }
    best.1
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    fn line(a: (f64, f64), b: (f64, f64)) -> Edge {
        let (start, end) = (DVec2::new(a.0, a.1), DVec2::new(b.0, b.1));
        Edge {
            start,
            control: start,
            end,
            curved: false,
        }
    }

    /// A clockwise unit square with a counter-clockwise square hole.
    fn ring() -> Text {
        let outer = vec![
            line((0.0, 0.0), (0.0, 1.0)),
            line((0.0, 1.0), (1.0, 1.0)),
            line((1.0, 1.0), (1.0, 0.0)),
            line((1.0, 0.0), (0.0, 0.0)),
        ];
        let hole = vec![
            line((0.25, 0.25), (0.75, 0.25)),
            line((0.75, 0.25), (0.75, 0.75)),
            line((0.75, 0.75), (0.25, 0.75)),
            line((0.25, 0.75), (0.25, 0.25)),
        ];
        Text::new(0.5, [outer.into_iter().chain(hole).collect::<Vec<_>>()])
    }

    #[test]
    fn faces_walls_and_hole() {
        let t = ring();
        // Straight through the solid part: front face then back face.
        let c = t.intersect(&Ray::new(DVec3::new(0.1, 0.1, -1.0), DVec3::Z));
        assert_eq!(c.as_slice(), &[1.0, 1.5]);
        assert_eq!(c.parts(), &[FRONT, BACK]);
        // Through the hole: nothing.
        assert!(
            t.intersect(&Ray::new(DVec3::new(0.5, 0.5, -1.0), DVec3::Z))
                .is_empty()
        );
        // Sideways at mid depth: outer wall, hole's walls, outer wall.
        let c = t.intersect(&Ray::new(DVec3::new(-1.0, 0.5, 0.25), DVec3::X));
        assert_eq!(c.as_slice(), &[1.0, 1.25, 1.75, 2.0]);
        let (n, _) = t.normals(DVec3::new(0.0, 0.5, 0.25), c.parts()[0]);
        assert!(n.normalize().dot(DVec3::X) > 0.999, "{n}");
        // Miss above, and a ray beyond the depth.
        assert!(
            t.intersect(&Ray::new(DVec3::new(-1.0, 1.5, 0.25), DVec3::X))
                .is_empty()
        );
        assert!(
            t.intersect(&Ray::new(DVec3::new(-1.0, 0.5, 0.75), DVec3::X))
                .is_empty()
        );
        assert!(t.contains(DVec3::new(0.1, 0.5, 0.25)));
        assert!(!t.contains(DVec3::new(0.5, 0.5, 0.25)));
        assert!(!t.contains(DVec3::new(0.1, 0.5, 0.6)));
    }

    /// A quadratic edge: the half-disc-like bump under the curve (0,0) → (1,0) with control
    /// (0.5, 1) reaches y = 0.5 at s = 0.5.
    #[test]
    fn curved_edges() {
        let start = DVec2::ZERO;
        let bump = vec![
            Edge {
                start,
                control: DVec2::new(0.5, 1.0),
                end: DVec2::X,
                curved: true,
            },
            line((1.0, 0.0), (0.0, 0.0)),
        ];
        let t = Text::new(1.0, [bump]);
        assert!(t.contains(DVec3::new(0.5, 0.49, 0.5)));
        assert!(!t.contains(DVec3::new(0.5, 0.51, 0.5)));
        let c = t.intersect(&Ray::new(DVec3::new(0.5, 2.0, 0.5), DVec3::NEG_Y));
        assert!(
            (c.first().unwrap() - 1.5).abs() < 1e-12,
            "{:?}",
            c.as_slice()
        );
        let (n, _) = t.normals(DVec3::new(0.5, 0.5, 0.5), c.first_part().unwrap().1);
        assert!(n.normalize().dot(DVec3::Y).abs() > 0.999, "{n}");
    }
}
