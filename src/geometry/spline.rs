//! Plane curves made of polynomial spline segments, shared by the shapes drawn from them
//! (`prism`, `lathe`): evaluation, a box per segment, the nearest point of a segment.

use super::poly::roots_in;
use glam::DVec2;

/// One spline segment: `u(t)` and `v(t)` for t in [0, 1] (a prism's x and z, a lathe's
/// radius and height), each as the coefficients `[A, B, C, D]` of `A t³ + B t² + C t + D`, and
/// its box in the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveSegment {
    /// First coordinate.
    pub u: [f64; 4],
    /// Second coordinate.
    pub v: [f64; 4],
    /// The box of the segment.
    pub lo: DVec2,
    /// Its far corner.
    pub hi: DVec2,
}

/// `A t³ + B t² + C t + D`.
pub fn at(c: &[f64; 4], t: f64) -> f64 {
    ((c[0] * t + c[1]) * t + c[2]) * t + c[3]
}

/// The derivative of [`at`].
pub fn slope(c: &[f64; 4], t: f64) -> f64 {
    (3.0 * c[0] * t + 2.0 * c[1]) * t + c[2]
}

/// The coefficients lowest first, as the root finder takes them.
pub fn poly(c: [f64; 4]) -> [f64; 7] {
    [c[3], c[2], c[1], c[0], 0.0, 0.0, 0.0]
}

impl CurveSegment {
    /// A segment from its coefficients (its box from its ends and turning points).
    pub fn new(u: [f64; 4], v: [f64; 4]) -> CurveSegment {
        let point = |t: f64| DVec2::new(at(&u, t), at(&v, t));
        let (mut lo, mut hi) = (point(0.0).min(point(1.0)), point(0.0).max(point(1.0)));
        for c in [&u, &v] {
            let d = [c[2], 2.0 * c[1], 3.0 * c[0], 0.0, 0.0, 0.0, 0.0];
            for &t in roots_in(&d, 2, 0.0, 1.0).as_slice() {
                lo = lo.min(point(t));
                hi = hi.max(point(t));
            }
        }
        CurveSegment { u, v, lo, hi }
    }

    /// The point at parameter `t`.
    pub fn point(&self, t: f64) -> DVec2 {
        DVec2::new(at(&self.u, t), at(&self.v, t))
    }

    /// The parameter of the point nearest `q` (the segment's polynomials are of `degree`).
    pub fn nearest(&self, q: DVec2, degree: usize) -> f64 {
        // d/dt |P(t) − q|² / 2 = (P(t) − q)·P'(t), of degree 2·degree − 1.
        let mut c = [0.0; 7];
        for (coef, target) in [(&self.u, q.x), (&self.v, q.y)] {
            let mut p = poly(*coef);
            p[0] -= target;
            let d = [coef[2], 2.0 * coef[1], 3.0 * coef[0]];
            for (i, pi) in p.iter().take(4).enumerate() {
                for (j, dj) in d.iter().enumerate() {
                    c[i + j] += pi * dj;
                }
            }
        }
        let mut best = (f64::INFINITY, 0.0);
        let candidates = roots_in(&c, 2 * degree - 1, 0.0, 1.0);
        for t in candidates.as_slice().iter().copied().chain([0.0, 1.0]) {
            let dist = (self.point(t) - q).length_squared();
            if dist < best.0 {
                best = (dist, t);
            }
        }
        best.1
    }
}
