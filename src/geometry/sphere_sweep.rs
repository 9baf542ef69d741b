//! `sphere_sweep`: the volume a sphere of varying radius sweeps along a spline (POV-Ray's
//! SphereSweep, with its way of finding and filtering crossings).
//!
//! Each segment is a centre `C(u)` and radius `r(u)`, polynomials in `u ∈ [0, 1]` (linear, or
//! cubic for Catmull-Rom and B-splines). A point `P` of the line `O + k·d` lies on the
//! segment's tube where some sphere `|P − C(u)|² = r(u)²` touches it: writing that as
//! `F(k, u) = k² + L(u)·k + G(u) = 0` with `∂F/∂u = L'(u)·k + G'(u) = 0` and eliminating `k`
//! gives `G'² − L·L'·G' + G·L'² = 0`, of degree 10 in `u` for a cubic segment (2 for a linear
//! one). As POV-Ray does, trace gathers, along the whole line, the crossings with the spheres
//! that join segments, with the end discs of every tube, and with the spheres at every root
//! `u`; sorts them; and keeps those that enter or leave the union (POV-Ray's count, which
//! keeps the first and last crossing whatever they are).

use super::poly::roots_in;
use super::{Crossings, Ray};
use glam::DVec3;
use std::cell::RefCell;

/// POV-Ray's constants: tiny values, the slope below which a linear tube's crossing is taken
/// from its sphere, and the farthest crossing kept.
const EPSILON: f64 = 1e-10;
const ZERO_TOLERANCE: f64 = 1e-4;
const MAX_DISTANCE: f64 = 1e7;

/// Part tags (the low two bits of a crossing's part; the rest is the sphere's or segment's
/// index).
const SPHERE: u32 = 0;
const START_DISC: u32 = 1;
const END_DISC: u32 = 2;
const TUBE: u32 = 3;

/// How the sweep passes between its spheres.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepCurve {
    /// Straight lines between consecutive spheres.
    Linear,
    /// Catmull-Rom: a cubic through every sphere but the first and last.
    CatmullRom,
    /// Uniform cubic B-spline controlled by the spheres.
    BSpline,
}

/// Rows: the coefficient of `u⁰ … u³` as weights of four consecutive spheres.
const CATMULL_ROM: [[f64; 4]; 4] = [
    [0.0, 1.0, 0.0, 0.0],
    [-0.5, 0.0, 0.5, 0.0],
    [1.0, -2.5, 2.0, -0.5],
    [-0.5, 1.5, -1.5, 0.5],
];
const B_SPLINE: [[f64; 4]; 4] = [
    [1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0],
    [-0.5, 0.0, 0.5, 0.0],
    [0.5, -1.0, 0.5, 0.0],
    [-1.0 / 6.0, 0.5, -0.5, 1.0 / 6.0],
];

/// One piece of the sweep: centre and radius as polynomials in `u`, lowest power first.
#[derive(Clone, Debug, PartialEq)]
struct Segment {
    centre: [DVec3; 4],
    radius: [f64; 4],
    degree: usize,
    /// A sphere that holds the whole piece (rays that miss it skip the piece).
    hull_centre: DVec3,
    hull_radius: f64,
}

impl Segment {
    fn new(centre: [DVec3; 4], radius: [f64; 4], degree: usize) -> Segment {
        // |C(u) − C(½)| ≤ Σ |c_k|·(1 − 2⁻ᵏ) and |r(u)| ≤ Σ |r_k| on [0, 1].
        let mut s = Segment {
            centre,
            radius,
            degree,
            hull_centre: DVec3::ZERO,
            hull_radius: 0.0,
        };
        s.hull_centre = s.centre_at(0.5);
        let reach: f64 = (1..=degree)
            .map(|k| centre[k].length() * (1.0 - 0.5f64.powi(k as i32)))
            .sum();
        let thickness: f64 = radius[..=degree].iter().map(|r| r.abs()).sum();
        s.hull_radius = (reach + thickness) * (1.0 + 1e-9) + 1e-12;
        // Often tighter: the centre curve lies in the hull of its Bézier control points and
        // the radius within its Bézier coefficients (both are weighted means of them).
        let (points, radii) = (bezier(&centre, degree), bezier(&radius, degree));
        let mean = points[..=degree].iter().sum::<DVec3>() / (degree + 1) as f64;
        let spread = (points[..=degree].iter())
            .map(|p| p.distance(mean))
            .fold(0.0, f64::max);
        let widest = radii[..=degree].iter().map(|r| r.abs()).fold(0.0, f64::max);
        let tight = (spread + widest) * (1.0 + 1e-9) + 1e-12;
        if tight < s.hull_radius {
            (s.hull_centre, s.hull_radius) = (mean, tight);
        }
        s
    }

    fn centre_at(&self, u: f64) -> DVec3 {
        (0..=self.degree)
            .rev()
            .fold(DVec3::ZERO, |acc, k| acc * u + self.centre[k])
    }

    fn radius_at(&self, u: f64) -> f64 {
        (0..=self.degree)
            .rev()
            .fold(0.0, |acc, k| acc * u + self.radius[k])
    }

    fn centre_slope(&self, u: f64) -> DVec3 {
        (1..=self.degree)
            .rev()
            .fold(DVec3::ZERO, |acc, k| acc * u + k as f64 * self.centre[k])
    }

    fn radius_slope(&self, u: f64) -> f64 {
        (1..=self.degree)
            .rev()
            .fold(0.0, |acc, k| acc * u + k as f64 * self.radius[k])
    }

    /// `G(u) = |p − C(u)|² − r(u)²`, negative where `p` is inside the sphere at `u`.
    fn gap(&self, p: DVec3) -> [f64; 11] {
        let mut a = self.centre.map(|c| -c);
        a[0] = p - self.centre[0];
        let mut g = [0.0; 11];
        for i in 0..=self.degree {
            for j in 0..=self.degree {
                g[i + j] += a[i].dot(a[j]) - self.radius[i] * self.radius[j];
            }
        }
        g
    }

    /// The `u` of the sphere that touches the tube at its surface point `p`: where `G` has its
    /// double root (or, for a crossing POV-Ray kept on a sphere's far side, a simple one).
    fn touching(&self, p: DVec3) -> f64 {
        let g = self.gap(p);
        let n = 2 * self.degree;
        let slope = derivative(&g, n);
        let value = |u: f64| eval(&g, n, u).abs();
        let mut best = (value(0.0), 0.0);
        let candidates = roots_in(&slope, n - 1, 0.0, 1.0);
        let crossings = roots_in(&g, n, 0.0, 1.0);
        for &u in candidates
            .as_slice()
            .iter()
            .chain(crossings.as_slice())
            .chain(&[1.0])
        {
            let v = value(u);
            if v < best.0 {
                best = (v, u);
            }
        }
        best.1
    }
}

fn eval(c: &[f64; 11], degree: usize, u: f64) -> f64 {
    (0..=degree).rev().fold(0.0, |acc, k| acc * u + c[k])
}

fn derivative(c: &[f64; 11], degree: usize) -> [f64; 11] {
    let mut d = [0.0; 11];
    for k in 1..=degree {
        d[k - 1] = k as f64 * c[k];
    }
    d
}

fn product(a: &[f64; 11], da: usize, b: &[f64; 11], db: usize) -> [f64; 11] {
    let mut p = [0.0; 11];
    for i in 0..=da {
        for j in 0..=db {
            p[i + j] += a[i] * b[j];
        }
    }
    p
}

/// The Bézier coefficients on [0, 1] of the polynomial of degree `degree` with power
/// coefficients `c` (lowest first): b_i = Σ_{k ≤ i} C(i, k) / C(degree, k) · c_k.
fn bezier<T>(c: &[T; 4], degree: usize) -> [T; 4]
where
    T: Copy + Default + std::ops::Add<Output = T> + std::ops::Mul<f64, Output = T>,
{
    let mut b = [T::default(); 4];
    for (i, b) in b.iter_mut().enumerate().take(degree + 1) {
        for (k, &c) in c.iter().enumerate().take(i + 1) {
            *b = *b + c * (BINOMIAL[i][k] / BINOMIAL[degree][k]);
        }
    }
    b
}

/// Pascal's triangle to row 10: `BINOMIAL[n][k]` = C(n, k).
const BINOMIAL: [[f64; 11]; 11] = {
    let mut t = [[0.0; 11]; 11];
    let mut n = 0;
    while n < 11 {
        t[n][0] = 1.0;
        let mut k = 1;
        while k <= n {
            t[n][k] = t[n - 1][k - 1] + if k < n { t[n - 1][k] } else { 0.0 };
            k += 1;
        }
        n += 1;
    }
    t
};

/// Whether the polynomial surely has no root in `(0, 1)`: its Bernstein coefficients on
/// `[0, 1]` all have one sign (POV-Ray's shortcut before solving).
fn no_root_inside(c: &[f64; 11], degree: usize) -> bool {
    // b_i = Σ_{j ≤ i} C(i, j) / C(n, j) · c_j, with the c_j / C(n, j) made once.
    let mut scaled = [0.0; 11];
    for j in 0..=degree {
        scaled[j] = c[j] / BINOMIAL[degree][j];
    }
    let (mut positive, mut negative) = (true, true);
    for row in &BINOMIAL[..=degree] {
        let b: f64 = row.iter().zip(&scaled).map(|(n, s)| n * s).sum();
        positive &= b >= 0.0;
        negative &= b <= 0.0;
        if !(positive || negative) {
            return false;
        }
    }
    true
}

/// A candidate crossing along the unit line: distance from the ray's origin, outward normal
/// (for the enter/leave count) and part.
#[derive(Clone, Copy, Debug)]
struct Candidate {
    k: f64,
    normal: DVec3,
    part: u32,
}

thread_local! {
    /// Per-thread room for a ray's candidates, so that no ray allocates.
    static CANDIDATES: RefCell<Vec<Candidate>> = const { RefCell::new(Vec::new()) };
}

/// A sphere sweep in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct SphereSweep {
    segments: Box<[Segment]>,
    /// The spheres where segments meet, and the two ends.
    joints: Box<[(DVec3, f64)]>,
    tolerance: f64,
    bounds: (DVec3, DVec3),
}

/// The line's frame for one piece: a point on it near the piece, the unit direction, that
/// point's distance from the ray's origin, and the origin itself.
struct Line {
    near: DVec3,
    d: DVec3,
    shift: f64,
    origin: DVec3,
}

impl Line {
    /// The two crossings with a sphere as distances from the ray's origin and outward
    /// normals, none when the origin is outside it and its centre is not ahead (POV-Ray).
    fn sphere(&self, centre: DVec3, r: f64) -> Option<[(f64, DVec3); 2]> {
        let oc = centre - self.near;
        let closest = oc.dot(self.d);
        if (centre - self.origin).length_squared() >= r * r && closest + self.shift < EPSILON {
            return None;
        }
        let w = oc - closest * self.d;
        let half2 = r * r - w.length_squared();
        if half2 <= EPSILON {
            return None;
        }
        let half = half2.sqrt();
        Some([
            (closest - half + self.shift, -half * self.d - w),
            (closest + half + self.shift, half * self.d - w),
        ])
    }
}

impl SphereSweep {
    /// The sweep of `spheres` (centre, radius) joined by `curve`; crossings at or below
    /// `tolerance` are ignored. Needs two spheres (four for the cubic curves).
    pub fn new(curve: SweepCurve, spheres: &[(DVec3, f64)], tolerance: f64) -> SphereSweep {
        let mut segments = Vec::new();
        match curve {
            SweepCurve::Linear => {
                for w in spheres.windows(2) {
                    let mut centre = [DVec3::ZERO; 4];
                    let mut radius = [0.0; 4];
                    centre[0] = w[0].0;
                    centre[1] = w[1].0 - w[0].0;
                    radius[0] = w[0].1;
                    radius[1] = w[1].1 - w[0].1;
                    segments.push(Segment::new(centre, radius, 1));
                }
            }
            SweepCurve::CatmullRom | SweepCurve::BSpline => {
                let m = if curve == SweepCurve::CatmullRom {
                    &CATMULL_ROM
                } else {
                    &B_SPLINE
                };
                for w in spheres.windows(4) {
                    let mut centre = [DVec3::ZERO; 4];
                    let mut radius = [0.0; 4];
                    for k in 0..4 {
                        for s in 0..4 {
                            centre[k] += m[k][s] * w[s].0;
                            radius[k] += m[k][s] * w[s].1;
                        }
                    }
                    segments.push(Segment::new(centre, radius, 3));
                }
            }
        }
        let mut joints: Vec<(DVec3, f64)> = segments
            .iter()
            .map(|s| (s.centre_at(0.0), s.radius_at(0.0)))
            .collect();
        if let Some(last) = segments.last() {
            joints.push((last.centre_at(1.0), last.radius_at(1.0)));
        }
        // POV-Ray's box: the modelling spheres, twice their radius for Catmull-Rom.
        let grow = if curve == SweepCurve::CatmullRom {
            2.0
        } else {
            1.0
        };
        let bounds = spheres.iter().fold(
            (DVec3::INFINITY, DVec3::NEG_INFINITY),
            |(lo, hi), &(c, r)| (lo.min(c - grow * r), hi.max(c + grow * r)),
        );
        SphereSweep {
            segments: segments.into_boxed_slice(),
            joints: joints.into_boxed_slice(),
            tolerance,
            bounds,
        }
    }

    /// Every candidate along the ray's line into `out`.
    fn candidates(&self, ray: &Ray, out: &mut Vec<Candidate>) {
        for (i, &(centre, r)) in self.joints.iter().enumerate() {
            let line = ray.about(centre);
            let line = Line {
                near: line.origin,
                d: line.direction,
                shift: line.shift,
                origin: ray.origin,
            };
            if let Some(pair) = line.sphere(centre, r) {
                for (k, normal) in pair {
                    if k.abs() < MAX_DISTANCE {
                        out.push(Candidate {
                            k,
                            normal,
                            part: (i as u32) << 2 | SPHERE,
                        });
                    }
                }
            }
        }
        for (i, s) in self.segments.iter().enumerate() {
            let unit = ray.about(s.hull_centre);
            if (unit.origin - s.hull_centre).length_squared() > s.hull_radius * s.hull_radius {
                continue;
            }
            let line = Line {
                near: unit.origin,
                d: unit.direction,
                shift: unit.shift,
                origin: ray.origin,
            };
            self.segment(&line, s, (i as u32) << 2, out);
        }
    }

    fn segment(&self, line: &Line, s: &Segment, index: u32, out: &mut Vec<Candidate>) {
        let (o, d) = (line.near, line.d);
        // The discs that close the tube at u = 0 and u = 1.
        for (u, tag, sign) in [(0.0, START_DISC, -1.0), (1.0, END_DISC, 1.0)] {
            let (c, r, dc, dr) = (
                s.centre_at(u),
                s.radius_at(u),
                s.centre_slope(u),
                s.radius_slope(u),
            );
            let along = d.dot(dc);
            if along.abs() > EPSILON {
                let k = -((o - c).dot(dc) + r * dr) / along;
                if (k + line.shift).abs() < MAX_DISTANCE
                    && ((o - c) + k * d).length_squared() < r * r
                {
                    out.push(Candidate {
                        k: k + line.shift,
                        normal: sign * dc,
                        part: index | tag,
                    });
                }
            }
        }
        // The tube: F(k, u) = k² + L(u)·k + G(u).
        let n = s.degree;
        let g = s.gap(o);
        let mut l = [0.0; 11];
        for (l, c) in l.iter_mut().zip(&s.centre).take(n + 1) {
            *l = -2.0 * d.dot(*c);
        }
        l[0] = 2.0 * d.dot(o - s.centre[0]);
        let (dg, dl) = (derivative(&g, 2 * n), derivative(&l, n));
        let a = product(&dg, 2 * n - 1, &dg, 2 * n - 1);
        let b = product(&product(&l, n, &dl, n - 1), 2 * n - 1, &dg, 2 * n - 1);
        let c = product(&g, 2 * n, &product(&dl, n - 1, &dl, n - 1), 2 * n - 2);
        let degree = 4 * n - 2;
        let mut h = [0.0; 11];
        for k in 0..=degree {
            h[k] = a[k] - b[k] + c[k];
        }
        if no_root_inside(&h, degree) {
            return;
        }
        for &u in roots_in(&h, degree, 0.0, 1.0).as_slice() {
            let slope = eval(&dl, n - 1, u);
            if n == 1 && slope.abs() > ZERO_TOLERANCE {
                let k = -eval(&dg, 1, u) / slope;
                if (k + line.shift).abs() < MAX_DISTANCE {
                    out.push(Candidate {
                        k: k + line.shift,
                        normal: (o - s.centre_at(u)) + k * d,
                        part: index | TUBE,
                    });
                }
            } else if let Some(pair) = line.sphere(s.centre_at(u), s.radius_at(u)) {
                // (POV-Ray takes both crossings of the sphere at u for cubic tubes.)
                for (k, normal) in pair {
                    out.push(Candidate {
                        k,
                        normal,
                        part: index | TUBE,
                    });
                }
            }
        }
    }

    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        CANDIDATES.with_borrow_mut(|list| {
            list.clear();
            self.candidates(ray, list);
            if list.is_empty() {
                return;
            }
            list.sort_by(|a, b| a.k.total_cmp(&b.k));
            // POV-Ray's filter: the first and last stay; between them a crossing stays when it
            // enters the union from outside or leaves it to the outside, counting from one.
            let d = ray.direction.normalize();
            let mut inside = 1;
            let mut i = 1;
            while i + 1 < list.len() {
                let enters = list[i].normal.dot(d) < 0.0;
                let keep = if enters { inside == 0 } else { inside == 1 };
                inside += if enters { 1 } else { -1 };
                if keep {
                    i += 1;
                } else {
                    list.remove(i);
                }
            }
            let length = ray.direction.length();
            for c in list.iter() {
                let t = c.k / length;
                if t > self.tolerance && ray.contains(t) {
                    f(t, c.part);
                }
            }
        });
    }
}

impl super::shape::Surface for SphereSweep {
    const NAME: &'static str = "Sphere sweep";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::nearest_of(|f| self.crossings(ray, f))
    }

    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        let index = (part >> 2) as usize;
        let n = match part & 3 {
            SPHERE => p - self.joints[index].0,
            START_DISC => -self.segments[index].centre_slope(0.0),
            END_DISC => self.segments[index].centre_slope(1.0),
            _ => {
                let s = &self.segments[index];
                p - s.centre_at(s.touching(p))
            }
        };
        (n, n)
    }

    /// POV-Ray's test: some segment's sphere boundary passes through `p`, that is `G` has a
    /// root in [0, 1] (so a point deeper than every sphere of a segment counts as outside, as
    /// in POV-Ray).
    fn contains(&self, p: DVec3) -> bool {
        self.segments
            .iter()
            .any(|s| roots_in(&s.gap(p), 2 * s.degree, 0.0, 1.0).len > 0)
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some(self.bounds)
    }

    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        self.crossings(ray, f)
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// A segment's hull sphere holds every sphere of its sweep (rays that miss it skip the
    /// segment): checked at 200 places along many Catmull-Rom and B-spline segments, with
    /// the Bézier coefficients equal to the power form's values.
    #[test]
    fn a_segment_s_hull_holds_its_spheres() {
        let mut state = 7u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64 * 10.0 - 5.0
        };
        for basis in [CATMULL_ROM, B_SPLINE] {
            for _ in 0..200 {
                let points: Vec<(DVec3, f64)> = (0..4)
                    .map(|_| (DVec3::new(next(), next(), next()), next().abs() * 0.3))
                    .collect();
                let mut centre = [DVec3::ZERO; 4];
                let mut radius = [0.0; 4];
                for (k, row) in basis.iter().enumerate() {
                    for (w, (p, r)) in row.iter().zip(&points) {
                        centre[k] += *w * *p;
                        radius[k] += w * r;
                    }
                }
                let s = Segment::new(centre, radius, 3);
                let b = bezier(&radius, 3);
                for i in 0..=200 {
                    let u = f64::from(i) / 200.0;
                    let reach = s.centre_at(u).distance(s.hull_centre) + s.radius_at(u).abs();
                    assert!(reach <= s.hull_radius, "{reach} > {}", s.hull_radius);
                    let v = 1.0 - u;
                    let bernstein = b[0] * v * v * v
                        + 3.0 * b[1] * u * v * v
                        + 3.0 * b[2] * u * u * v
                        + b[3] * u * u * u;
                    assert!((bernstein - s.radius_at(u)).abs() < 1e-12);
                }
            }
        }
    }

    fn hits(s: &SphereSweep, o: DVec3, d: DVec3) -> Vec<f64> {
        let mut v = Vec::new();
        s.for_each_crossing(&Ray::new(o, d), |t, _| v.push(t));
        v
    }

    /// A linear sweep of equal spheres is a capsule: across its middle the tube, past its
    /// ends the end spheres; normals point out; a point inside near the wall is inside.
    #[test]
    fn capsule() {
        let s = SphereSweep::new(
            SweepCurve::Linear,
            &[
                (DVec3::new(-1.0, 0.0, 0.0), 0.5),
                (DVec3::new(1.0, 0.0, 0.0), 0.5),
            ],
            1e-6,
        );
        let across = hits(&s, DVec3::new(0.3, 5.0, 0.0), DVec3::NEG_Y);
        assert_eq!(across.len(), 2, "{across:?}");
        assert!(
            (across[0] - 4.5).abs() < 1e-9 && (across[1] - 5.5).abs() < 1e-9,
            "{across:?}"
        );
        let c = s.intersect(&Ray::new(DVec3::new(0.3, 5.0, 0.0), DVec3::NEG_Y));
        let (t, part) = c.first_part().unwrap();
        let n = s.normals(DVec3::new(0.3, 5.0 - t, 0.0), part).0.normalize();
        assert!((n - DVec3::Y).length() < 1e-9, "{n}");
        // Along the axis: in at x = −1.5, out at 1.5.
        let along = hits(&s, DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        assert_eq!(along.len(), 2, "{along:?}");
        assert!(
            (along[0] - 3.5).abs() < 1e-9 && (along[1] - 6.5).abs() < 1e-9,
            "{along:?}"
        );
        // Past the end: only the end sphere.
        let cap = hits(&s, DVec3::new(1.3, 5.0, 0.0), DVec3::NEG_Y);
        let half = (0.25f64 - 0.09).sqrt();
        assert!((cap[0] - (5.0 - half)).abs() < 1e-9, "{cap:?}");
        assert!(hits(&s, DVec3::new(0.0, 5.0, 0.6), DVec3::NEG_Y).is_empty());
        assert!(s.contains(DVec3::new(0.0, 0.45, 0.0)));
        assert!(!s.contains(DVec3::new(0.0, 0.55, 0.0)));
    }

    /// A cone-like linear sweep (radius 1 to 0.25): its side's normal leans towards the thin end.
    #[test]
    fn tapered_tube_normal() {
        let s = SphereSweep::new(
            SweepCurve::Linear,
            &[(DVec3::ZERO, 1.0), (DVec3::new(4.0, 0.0, 0.0), 0.25)],
            1e-6,
        );
        let ray = Ray::new(DVec3::new(2.0, 5.0, 0.0), DVec3::NEG_Y);
        let (t, part) = s.intersect(&ray).first_part().unwrap();
        let p = ray.at(t);
        let n = s.normals(p, part).0.normalize();
        // The tube is tangent to spheres whose radius shrinks at 0.1875 per unit: the normal
        // tilts by asin(0.1875) towards +x.
        assert!((n.x - 0.1875).abs() < 1e-6 && n.y > 0.98, "{n} at {p}");
        // The surface point lies on the sphere the normal comes from.
        let u = s.segments[0].touching(p);
        assert!(
            ((p - s.segments[0].centre_at(u)).length() - s.segments[0].radius_at(u)).abs() < 1e-9
        );
    }

    /// A B-spline sweep through a straight row of equal spheres is a straight tube; a
    /// Catmull-Rom one bends through its middle spheres.
    #[test]
    fn cubic_sweeps() {
        let row: Vec<(DVec3, f64)> = (0..5)
            .map(|i| (DVec3::new(i as f64, 0.0, 0.0), 0.3))
            .collect();
        let s = SphereSweep::new(SweepCurve::BSpline, &row, 1e-6);
        for x in [1.2, 1.5, 2.0, 2.7] {
            let h = hits(&s, DVec3::new(x, 4.0, 0.0), DVec3::NEG_Y);
            assert!(!h.is_empty(), "x {x}");
            assert!((h[0] - 3.7).abs() < 1e-6, "x {x}: {h:?}");
        }
        let bent = [
            (DVec3::new(-1.0, 0.0, 0.0), 0.2),
            (DVec3::new(0.0, 0.0, 0.0), 0.2),
            (DVec3::new(1.0, 1.0, 0.0), 0.2),
            (DVec3::new(2.0, 0.0, 0.0), 0.2),
            (DVec3::new(3.0, 0.0, 0.0), 0.2),
        ];
        let s = SphereSweep::new(SweepCurve::CatmullRom, &bent, 1e-6);
        // It passes through (1, 1): a ray down x = 1 meets it just above.
        let h = hits(&s, DVec3::new(1.0, 4.0, 0.0), DVec3::NEG_Y);
        assert!((h[0] - 2.8).abs() < 1e-6, "{h:?}");
        assert!(hits(&s, DVec3::new(1.0, 4.0, 0.5), DVec3::NEG_Y).is_empty());
        // Transformed rays (unnormalised direction) keep their t.
        let h2 = hits(&s, DVec3::new(1.0, 4.0, 0.0), DVec3::new(0.0, -2.0, 0.0));
        assert!((h2[0] - 1.4).abs() < 1e-6, "{h2:?}");
    }

    #[test]
    fn bernstein_exclusion() {
        // (u − 2)(u − 3) has no root in [0, 1]; (u − 0.5)(u − 3) has one.
        let mut a = [0.0; 11];
        a[..3].copy_from_slice(&[6.0, -5.0, 1.0]);
        assert!(no_root_inside(&a, 2));
        a[..3].copy_from_slice(&[1.5, -3.5, 1.0]);
        assert!(!no_root_inside(&a, 2));
    }
}
