//! `prism`: closed spline curves in the x-z plane swept along y, straight (`linear_sweep`,
//! between two heights) or towards the origin (`conic_sweep`, the curve drawn at y = 1 and
//! scaled by y), filled by the even-odd rule, with end faces unless `open` (POV-Ray's Prism).

use super::poly::roots_in;
use super::spline::{CurveSegment, at, poly, slope};
use super::{Crossings, Ray};
use glam::{DVec2, DVec3};

/// POV-Ray's tolerance for parallel rays and zero heights.
const EPSILON: f64 = 1e-10;

/// A prism in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Prism {
    conic: bool,
    degree: usize,
    h1: f64,
    h2: f64,
    closed: bool,
    segments: Box<[CurveSegment]>,
    /// The curve's box in the plane (for conic sweeps, the curve at y = 1).
    lo: DVec2,
    hi: DVec2,
}

/// Part tags: the face at the top height, the one at the bottom, then one per segment.
const CAP: u32 = 0;
const BASE: u32 = 1;
const SIDE: u32 = 2;

impl Prism {
    /// A prism of `degree` (1 to 3) segments between heights `h1 ≤ h2`.
    pub fn new(
        conic: bool,
        degree: u8,
        (h1, h2): (f64, f64),
        closed: bool,
        segments: Vec<CurveSegment>,
    ) -> Prism {
        let (lo, hi) = segments.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), s| (lo.min(s.lo), hi.max(s.hi)),
        );
        Prism {
            conic,
            degree: degree.into(),
            h1,
            h2,
            closed,
            segments: segments.into_boxed_slice(),
            lo,
            hi,
        }
    }

    /// POV-Ray's even-odd test of plane point (u, v): crossings of the ray towards +u.
    fn in_curve(&self, u: f64, v: f64) -> bool {
        if u < self.lo.x || v < self.lo.y || u > self.hi.x || v > self.hi.y {
            return false;
        }
        let mut inside = false;
        for s in self.segments.iter() {
            if v < s.lo.y || v > s.hi.y || u > s.hi.x {
                continue;
            }
            let mut c = poly(s.v);
            c[0] -= v;
            for &t in roots_in(&c, self.degree, 0.0, 1.0).as_slice() {
                if at(&s.u, t) - u >= 0.0 {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// Calls `f` with every crossing (distance along the ray, part).
    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        if self.segments.is_empty() {
            return;
        }
        let len = ray.direction.length();
        let (p, d) = (ray.origin, ray.direction / len);
        let mut hit = |k: f64, part: u32| {
            let t = k / len;
            if k > 1e-4 * len && ray.contains(t) {
                f(t, part);
            }
        };
        let (h1, h2) = (self.h1, self.h2);
        if d.y.abs() < EPSILON && (p.y < h1 || p.y > h2) {
            return;
        }
        if self.closed && d.y.abs() >= EPSILON {
            for (h, part) in [(h2, CAP), (h1, BASE)] {
                if self.conic && h.abs() <= EPSILON {
                    continue;
                }
                let k = (h - p.y) / d.y;
                let q = p + k * d;
                let (u, v) = if self.conic {
                    (q.x / h, q.z / h)
                } else {
                    (q.x, q.z)
                };
                if self.in_curve(u, v) {
                    hit(k, part);
                }
            }
        }
        if d.x.abs() <= EPSILON && d.z.abs() <= EPSILON {
            return;
        }
        let (k1, k2, k3) = (
            p.z * d.y - p.y * d.z,
            p.y * d.x - p.x * d.y,
            p.x * d.z - p.z * d.x,
        );
        for (j, s) in self.segments.iter().enumerate() {
            let c: [f64; 4] = if self.conic {
                std::array::from_fn(|i| s.u[i] * k1 + s.v[i] * k2 + if i == 3 { k3 } else { 0.0 })
            } else {
                std::array::from_fn(|i| {
                    s.u[i] * d.z - s.v[i] * d.x - if i == 3 { d.z * p.x - d.x * p.z } else { 0.0 }
                })
            };
            // A straight segment parallel to the ray (POV-Ray's threshold).
            if self.degree == 1 && c[2].abs() <= EPSILON {
                continue;
            }
            for &t in roots_in(&poly(c), self.degree, 0.0, 1.0).as_slice() {
                let k = if self.conic {
                    let a = at(&s.u, t);
                    let h = d.x - a * d.y;
                    if h.abs() > EPSILON {
                        (a * p.y - p.x) / h
                    } else {
                        let b = at(&s.v, t);
                        let h = d.z - b * d.y;
                        if h.abs() <= EPSILON {
                            continue;
                        }
                        (b * p.y - p.z) / h
                    }
                } else if d.x.abs() > EPSILON {
                    (at(&s.u, t) - p.x) / d.x
                } else {
                    (at(&s.v, t) - p.z) / d.z
                };
                let y = p.y + k * d.y;
                if (h1..=h2).contains(&y) {
                    hit(k, SIDE + j as u32);
                }
            }
        }
    }
}

impl super::shape::Surface for Prism {
    const NAME: &'static str = "Prism";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::nearest_of(|f| self.crossings(ray, f))
    }

    /// POV-Ray's raw normals: +y on both faces; on the sides the tangent turned to the
    /// right (its sense follows the order of the points).
    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        if part < SIDE {
            return (DVec3::Y, DVec3::Y);
        }
        let s = &self.segments[(part - SIDE) as usize];
        let q = if self.conic {
            if p.y.abs() <= EPSILON {
                return (DVec3::Y, DVec3::Y);
            }
            DVec2::new(p.x / p.y, p.z / p.y)
        } else {
            DVec2::new(p.x, p.z)
        };
        let t = s.nearest(q, self.degree);
        let (du, dv) = (slope(&s.u, t), slope(&s.v, t));
        let n = if self.conic {
            DVec3::new(dv, -(p.x * dv - p.z * du) / p.y, -du)
        } else {
            DVec3::new(dv, 0.0, -du)
        };
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        if p.y < self.h1 || p.y >= self.h2 {
            return false;
        }
        if self.conic {
            p.y.abs() > EPSILON && self.in_curve(p.x / p.y, p.z / p.y)
        } else {
            self.in_curve(p.x, p.z)
        }
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        if self.segments.is_empty() {
            return Some((DVec3::ZERO, DVec3::ZERO));
        }
        let (lo, hi) = if self.conic {
            // The curve scaled by each end height.
            let corners = [
                self.lo * self.h1,
                self.hi * self.h1,
                self.lo * self.h2,
                self.hi * self.h2,
            ];
            corners
                .iter()
                .fold((corners[0], corners[0]), |(lo, hi), c| {
                    (lo.min(*c), hi.max(*c))
                })
        } else {
            (self.lo, self.hi)
        };
        Some((
            DVec3::new(lo.x, self.h1, lo.y),
            DVec3::new(hi.x, self.h2, hi.y),
        ))
    }

    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        self.crossings(ray, f)
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// A unit square (x, z in [0, 1]) of straight segments, counter-clockwise seen from +y.
    fn square(conic: bool, heights: (f64, f64)) -> Prism {
        let pts = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)];
        let segments = pts
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                CurveSegment::new([0.0, 0.0, b.0 - a.0, a.0], [0.0, 0.0, b.1 - a.1, a.1])
            })
            .collect();
        Prism::new(conic, 1, heights, true, segments)
    }

    #[test]
    fn linear_sweep_hits_faces_and_sides() {
        let p = square(false, (0.0, 2.0));
        // Down through the top face and out the bottom.
        let c = p.intersect(&Ray::new(DVec3::new(0.5, 5.0, 0.5), DVec3::NEG_Y));
        assert_eq!(c.as_slice(), &[3.0, 5.0]);
        assert_eq!(c.parts(), &[CAP, BASE]);
        // Sideways through two walls.
        let c = p.intersect(&Ray::new(DVec3::new(-1.0, 1.0, 0.5), DVec3::X * 2.0));
        assert_eq!(c.as_slice(), &[0.5, 1.0]);
        let (n, _) = p.normals(DVec3::new(0.0, 1.0, 0.5), c.parts()[0]);
        assert!(n.normalize().dot(DVec3::X).abs() > 0.999);
        // Misses: above the top going sideways, and beside it.
        assert!(
            p.intersect(&Ray::new(DVec3::new(-1.0, 3.0, 0.5), DVec3::X))
                .is_empty()
        );
        assert!(
            p.intersect(&Ray::new(DVec3::new(2.0, 5.0, 0.5), DVec3::NEG_Y))
                .is_empty()
        );
        // Inside is half-open in y.
        assert!(p.contains(DVec3::new(0.5, 0.0, 0.5)));
        assert!(!p.contains(DVec3::new(0.5, 2.0, 0.5)));
        assert!(!p.contains(DVec3::new(1.5, 1.0, 0.5)));
    }

    #[test]
    fn conic_sweep_scales_by_height() {
        let p = square(true, (0.0, 2.0));
        // At y = 2 the square spans [0, 2]: a ray down at x = 1.5 meets the top face, and (as
        // in POV-Ray) no wall, since walls are tested only for rays not parallel to y.
        let c = p.intersect(&Ray::new(DVec3::new(1.5, 5.0, 0.2), DVec3::NEG_Y));
        assert_eq!(c.as_slice(), &[3.0]);
        // At y = 1.5 a ray along x crosses the walls x = 0 and x = y.
        let c = p.intersect(&Ray::new(DVec3::new(-5.0, 1.5, 0.2), DVec3::X));
        assert_eq!(c.len(), 2, "{:?}", c.as_slice());
        assert!((c.as_slice()[0] - 5.0).abs() < 1e-12 && (c.as_slice()[1] - 6.5).abs() < 1e-12);
        // No base face at height 0.
        assert!(p.contains(DVec3::new(1.5, 1.8, 0.2)));
        assert!(!p.contains(DVec3::new(1.5, 1.2, 0.2)));
        // Transformed: a prism moved up one unit is a translated object; its bounds.
        let (lo, hi) = p.bounds().unwrap();
        assert_eq!(
            (lo, hi),
            (DVec3::new(0.0, 0.0, 0.0), DVec3::new(2.0, 2.0, 2.0))
        );
    }

    /// Catmull-Rom circle-like curve: a ray along its axis of symmetry meets it twice.
    #[test]
    fn cubic_segments() {
        let pts = [
            DVec2::new(-1.0, 0.0),
            DVec2::new(0.0, 1.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(0.0, -1.0),
            DVec2::new(-1.0, 0.0),
            DVec2::new(0.0, 1.0),
            DVec2::new(1.0, 0.0),
        ];
        let segments = (0..4)
            .map(|i| {
                let c = |f: fn(DVec2) -> f64| {
                    let (p0, p1, p2, p3) = (f(pts[i]), f(pts[i + 1]), f(pts[i + 2]), f(pts[i + 3]));
                    [
                        -0.5 * p0 + 1.5 * p1 - 1.5 * p2 + 0.5 * p3,
                        p0 - 2.5 * p1 + 2.0 * p2 - 0.5 * p3,
                        0.5 * (p2 - p0),
                        p1,
                    ]
                };
                CurveSegment::new(c(|p| p.x), c(|p| p.y))
            })
            .collect();
        let p = Prism::new(false, 3, (0.0, 1.0), true, segments);
        // Through two joints: each is a root of both its segments (POV-Ray counts it twice).
        let c = p.intersect(&Ray::new(DVec3::new(-5.0, 0.5, 0.0), DVec3::X));
        assert_eq!(c.as_slice(), &[4.0, 4.0, 6.0, 6.0]);
        let c = p.intersect(&Ray::new(DVec3::new(0.1, 0.5, -5.0), DVec3::Z));
        assert_eq!(c.len(), 2, "{:?}", c.as_slice());
        assert!(p.contains(DVec3::new(0.0, 0.5, 0.1)));
    }
}
