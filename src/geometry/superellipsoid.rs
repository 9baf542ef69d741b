//! `superellipsoid { <e, n> }`: `[(|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n)]^(n/2) = 1`, e
//! shaping the x-y cross-sections and n the profile along z (POV-Ray's Superellipsoid).
//!
//! POV-Ray's method, followed step by step: the ray within the box [−1.01, 1.01]³ is cut at
//! the nine planes of symmetry through the origin, so that the function is mostly monotonic
//! on each piece; a piece whose ends differ in sign is solved by secant and bisection steps,
//! one without a sign change is probed by secant steps from its start.

use super::{Crossings, Ray};
use glam::DVec3;

/// POV-Ray's tolerances: a function value that counts as zero, directions parallel to a plane.
const ZERO_TOLERANCE: f64 = 1e-10;
const EPSILON: f64 = 1e-10;
/// Shortest distance of a hit, along the unit direction.
const DEPTH_TOLERANCE: f64 = 1e-4;
/// Iterations of either root search.
const MAX_ITERATIONS: usize = 20;
/// The planes of symmetry the ray is cut at.
const PLANES: [[f64; 3]; 9] = [
    [1.0, 1.0, 0.0],
    [1.0, -1.0, 0.0],
    [1.0, 0.0, 1.0],
    [1.0, 0.0, -1.0],
    [0.0, 1.0, 1.0],
    [0.0, 1.0, -1.0],
    [1.0, 0.0, 0.0],
    [0.0, 1.0, 0.0],
    [0.0, 0.0, 1.0],
];

/// A superellipsoid in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Superellipsoid {
    /// 2/e, e/n, 2/n.
    power: [f64; 3],
}

/// `x^p`, by multiplication for the small integer powers (as POV-Ray computes it).
fn power(x: f64, p: f64) -> f64 {
    match p {
        0.0 => 1.0,
        1.0 => x,
        2.0 => x * x,
        3.0 => x * x * x,
        4.0 => (x * x) * (x * x),
        5.0 => (x * x) * (x * x) * x,
        6.0 => (x * x) * (x * x) * (x * x),
        _ => x.powf(p),
    }
}

/// `(a^p + b^p)^(1/p)`, computed from the larger of a, b.
fn g(a: f64, b: f64, p: f64) -> f64 {
    let (big, small) = if a > b { (a, b) } else { (b, a) };
    if big == 0.0 {
        return 0.0;
    }
    let sum = 1.0 + power(small / big, p);
    if sum == 1.0 {
        big
    } else {
        big * power(sum, 1.0 / p)
    }
}

impl Superellipsoid {
    /// `superellipsoid { <e, n> }`.
    pub fn new(e: f64, n: f64) -> Superellipsoid {
        Superellipsoid {
            power: [2.0 / e, e / n, 2.0 / n],
        }
    }

    /// POV-Ray's function: negative inside, zero on the surface.
    fn f(&self, p: DVec3) -> f64 {
        g(
            g(p.x.abs(), p.y.abs(), self.power[0]),
            p.z.abs(),
            self.power[2],
        ) - 1.0
    }

    /// The crossing between `p0` (value `v0`) and `p1` (value `v1`) of opposite signs.
    fn solve_hit1(&self, mut v0: f64, mut p0: DVec3, mut v1: f64, mut p1: DVec3) -> DVec3 {
        for _ in 0..MAX_ITERATIONS {
            if v0.abs() < ZERO_TOLERANCE {
                return p0;
            }
            if v1.abs() < ZERO_TOLERANCE {
                return p1;
            }
            let p2 = p0 + (v0.abs() / (v1 - v0).abs()) * (p1 - p0);
            let v2 = self.f(p2);
            let p3 = p0 + 0.5 * (p1 - p0);
            let v3 = self.f(p3);
            if v2 * v3 < 0.0 {
                (v0, p0, v1, p1) = (v2, p2, v3, p3);
            } else {
                let (v, p) = if v2.abs() < v3.abs() {
                    (v2, p2)
                } else {
                    (v3, p3)
                };
                if v0 * v < 0.0 {
                    (v1, p1) = (v, p);
                } else {
                    (v0, p0) = (v, p);
                }
            }
        }
        if v0.abs() < v1.abs() { p0 } else { p1 }
    }

    /// A crossing on a piece whose ends have the same sign: secant steps from its start.
    fn check_hit2(
        &self,
        o: DVec3,
        d: DVec3,
        t0: f64,
        p0: DVec3,
        mut v0: f64,
        t1: f64,
    ) -> Option<f64> {
        let (mut dt0, mut dt1) = (t0, t0 + 1e-4 * (t1 - t0));
        let maxdelta = t1 - t0;
        let mut i = 0;
        while dt0 < t1 && i < MAX_ITERATIONS {
            i += 1;
            let p1 = o + dt1 * d;
            let v1 = self.f(p1);
            if v0 * v1 < 0.0 {
                return Some((self.solve_hit1(v0, p0, v1, p1) - o).length());
            }
            if v1.abs() < ZERO_TOLERANCE {
                return Some(dt1);
            }
            if (v0 > 0.0 && v1 > v0) || (v0 < 0.0 && v1 < v0) || v1 == v0 {
                return None;
            }
            let delta = v1 * (dt1 - dt0) / (v1 - v0);
            if delta.abs() > maxdelta {
                return None;
            }
            v0 = v1;
            dt0 = dt1;
            dt1 -= delta;
        }
        None
    }

    /// Calls `f` with each crossing in increasing distance until it returns false.
    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64) -> bool) {
        let len = ray.direction.length();
        let (o, d) = (ray.origin, ray.direction / len);
        let Some((t1, t2)) = box_span(o, d) else {
            return;
        };
        if t2 < DEPTH_TOLERANCE {
            return;
        }
        let t1 = t1.max(DEPTH_TOLERANCE);
        let mut dists = [0.0; 11];
        dists[0] = t1;
        dists[1] = t2;
        let mut count = 2;
        let pad = EPSILON * (t2 - t1);
        for n in PLANES {
            let n = DVec3::from_array(n);
            let dn = d.dot(n);
            if dn.abs() < EPSILON {
                continue;
            }
            let t = -o.dot(n) / dn;
            if t >= t1 - pad && t <= t2 + pad {
                dists[count] = t;
                count += 1;
            }
        }
        let dists = &mut dists[..count];
        dists.sort_by(f64::total_cmp);
        // Some(whether to go on) for a hit the ray's interval takes, None for one it refuses.
        let mut hit = |t: f64| {
            let t = t / len;
            (t > DEPTH_TOLERANCE && t < 1e7 && ray.contains(t)).then(|| f(t))
        };
        let mut p0 = o + dists[0] * d;
        let mut v0 = self.f(p0);
        if v0.abs() < ZERO_TOLERANCE && hit(dists[0]) == Some(false) {
            return;
        }
        for i in 1..dists.len() {
            let p1 = o + dists[i] * d;
            let v1 = self.f(p1);
            let found = if v1.abs() < ZERO_TOLERANCE {
                hit(dists[i])
            } else if v0 * v1 < 0.0 {
                hit((self.solve_hit1(v0, p0, v1, p1) - o).length())
            } else {
                // A probed hit the interval refuses ends the search (POV-Ray stops there).
                self.check_hit2(o, d, dists[i - 1], p0, v0, dists[i])
                    .map(|t| hit(t).unwrap_or(false))
            };
            if found == Some(false) {
                return;
            }
            (v0, p0) = (v1, p1);
        }
    }
}

/// The distances along unit direction `d` within [−1.01, 1.01]³, if the ray meets it ahead.
fn box_span(o: DVec3, d: DVec3) -> Option<(f64, f64)> {
    let (mut enter, mut exit) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..3 {
        if d[i].abs() <= EPSILON {
            if o[i].abs() > 1.01 {
                return None;
            }
            continue;
        }
        let (a, b) = ((-1.01 - o[i]) / d[i], (1.01 - o[i]) / d[i]);
        enter = enter.max(a.min(b));
        exit = exit.min(a.max(b));
    }
    (exit >= EPSILON && enter <= exit).then_some((enter, exit))
}

impl super::shape::Surface for Superellipsoid {
    const NAME: &'static str = "Superellipsoid";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::first_of(|f| self.crossings(ray, f))
    }

    /// POV-Ray's gradient, scaled for a point on the surface.
    fn normals(&self, p: DVec3, _: u32) -> (DVec3, DVec3) {
        let [e, _, n] = self.power;
        let mut out = DVec3::ZERO;
        let z2n = if p.z != 0.0 { power(p.z.abs(), n) } else { 0.0 };
        if p.z != 0.0 {
            out.z = z2n / p.z;
        }
        let mut r = 0.0;
        if p.x.abs() > p.y.abs() {
            r = power((p.y / p.x).abs(), e);
            out.x = (1.0 - z2n) / p.x;
            out.y = if p.y != 0.0 {
                (1.0 - z2n) * r / p.y
            } else {
                0.0
            };
        } else if p.y != 0.0 {
            r = power((p.x / p.y).abs(), e);
            out.x = if p.x != 0.0 {
                (1.0 - z2n) * r / p.x
            } else {
                0.0
            };
            out.y = (1.0 - z2n) / p.y;
        }
        if p.z != 0.0 {
            out.z *= 1.0 + r;
        }
        (out, out)
    }

    fn contains(&self, p: DVec3) -> bool {
        self.f(p) < ZERO_TOLERANCE
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some((DVec3::splat(-1.0001), DVec3::splat(1.0001)))
    }

    fn for_each_crossing(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        self.crossings(ray, |t| {
            f(t, 0);
            true
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    #[test]
    fn sphere_box_and_inside() {
        // <1, 1> is the unit sphere.
        let s = Superellipsoid::new(1.0, 1.0);
        let c = s.intersect(&Ray::new(DVec3::new(-5.0, 0.3, 0.2), DVec3::X));
        let expected = 5.0 - (1.0f64 - 0.09 - 0.04).sqrt();
        assert!(
            (c.first().unwrap() - expected).abs() < 1e-8,
            "{:?}",
            c.as_slice()
        );
        let mut all = Vec::new();
        s.for_each_crossing(&Ray::new(DVec3::new(-5.0, 0.3, 0.2), DVec3::X), |t, _| {
            all.push(t)
        });
        assert_eq!(all.len(), 2);
        let (n, _) = s.normals(DVec3::new(0.6, 0.0, 0.8), 0);
        assert!(n.normalize().dot(DVec3::new(0.6, 0.0, 0.8)) > 0.9999);
        assert!(s.contains(DVec3::new(0.5, 0.5, 0.5)));
        assert!(!s.contains(DVec3::new(0.7, 0.7, 0.2)));
        assert!(
            s.intersect(&Ray::new(DVec3::new(-5.0, 1.5, 0.0), DVec3::X))
                .is_empty()
        );
        // Small exponents: nearly a box, met near its face.
        let b = Superellipsoid::new(0.1, 0.1);
        let c = b.intersect(&Ray::new(DVec3::new(-5.0, 0.3, 0.2), DVec3::X));
        assert!(
            (c.first().unwrap() - 4.0).abs() < 1e-3,
            "{:?}",
            c.as_slice()
        );
        assert!(b.contains(DVec3::new(0.9, 0.9, 0.9)));
    }

    /// Exponents above 2: a concave star; a ray along a diagonal plane still finds it.
    #[test]
    fn concave_star() {
        let s = Superellipsoid::new(3.0, 1.0);
        let ray = Ray::new(DVec3::new(-5.0, -5.0, 0.0), DVec3::new(1.0, 1.0, 0.0));
        let t = s.intersect(&ray).first().expect("a hit");
        assert!(s.f(ray.at(t)).abs() < 1e-6);
    }
}
