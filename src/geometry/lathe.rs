//! `lathe`: a spline profile in the (radius, height) plane turned about the y axis (POV-Ray's
//! Lathe). Along a ray, the squared distance from the axis equals the profile's squared radius
//! where the ray's height meets the profile's: a polynomial of twice the spline's degree in
//! the spline parameter.

use super::poly::roots_in;
use super::spline::{CurveSegment, at, poly, slope};
use super::{Crossings, Ray};
use glam::{DVec2, DVec3};

/// POV-Ray's tolerance for horizontal rays and the axis.
const EPSILON: f64 = 1e-10;

/// A lathe in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Lathe {
    degree: usize,
    segments: Box<[CurveSegment]>,
    /// Least and greatest radius and height of the profile.
    lo: DVec2,
    hi: DVec2,
}

impl Lathe {
    /// A lathe of segments (radius, height) of `degree` (1 to 3).
    pub fn new(degree: u8, segments: Vec<CurveSegment>) -> Lathe {
        let (lo, hi) = segments.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), s| (lo.min(s.lo), hi.max(s.hi)),
        );
        Lathe {
            degree: degree.into(),
            segments: segments.into_boxed_slice(),
            lo,
            hi,
        }
    }

    /// The greatest distance from the axis (end radii may be negative: the surface is at
    /// their magnitude).
    fn radius(&self) -> f64 {
        self.hi.x.max(-self.lo.x)
    }

    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        if self.segments.is_empty() {
            return;
        }
        // Distances k from the ray's point nearest the profile's middle on the axis.
        let line = ray.about(DVec3::new(0.0, 0.5 * (self.lo.y + self.hi.y), 0.0));
        let (p, d) = (line.origin, line.direction);
        let mut hit = |k: f64, part: u32| {
            let t = line.t(k);
            if t > 1e-4 && ray.contains(t) {
                f(t, part);
            }
        };
        let r = d.x * d.x + d.z * d.z;
        let m = p.x * d.x + p.z * d.z;
        let rho2 = p.x * p.x + p.z * p.z;
        // The ray's distance from the axis, and its height range, against the profile's.
        let big = self.radius();
        if r > 0.0 && (p.x * d.z - p.z * d.x).abs() / r.sqrt() > big {
            return;
        }
        let horizontal = d.y.abs() <= EPSILON;
        for (j, s) in self.segments.iter().enumerate() {
            let part = j as u32;
            if horizontal {
                // The ray's height meets the profile's; then both radial crossings.
                if p.y < s.lo.y || p.y > s.hi.y {
                    continue;
                }
                let mut c = poly(s.v);
                c[0] -= p.y;
                for &t in roots_in(&c, self.degree, 0.0, 1.0).as_slice() {
                    let w = at(&s.u, t);
                    // r k² + 2 m k + (ρ² − w²) = 0
                    let disc = m * m - r * (rho2 - w * w);
                    if r > 0.0 && disc >= 0.0 {
                        let root = disc.sqrt();
                        hit((-m - root) / r, part);
                        hit((-m + root) / r, part);
                    }
                }
                continue;
            }
            // G(t) = r·e² + 2·Dy·m·e + Dy²·(ρ² − w²), e = height(t) − Py, w = radius(t).
            let mut e = poly(s.v);
            e[0] -= p.y;
            let w = poly(s.u);
            let mut g = [0.0; 7];
            for i in 0..4 {
                for k in 0..4 {
                    g[i + k] += r * e[i] * e[k] - d.y * d.y * w[i] * w[k];
                }
                g[i] += 2.0 * d.y * m * e[i];
            }
            g[0] += d.y * d.y * rho2;
            for &t in roots_in(&g, 2 * self.degree, 0.0, 1.0).as_slice() {
                hit((at(&s.v, t) - p.y) / d.y, part);
            }
        }
    }
}

impl super::shape::Surface for Lathe {
    const NAME: &'static str = "Lathe";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::nearest_of(|f| self.crossings(ray, f))
    }

    /// POV-Ray's raw normal `(h'·x, −r'·ρ, h'·z)` from the profile's tangent (r', h') at the
    /// point (its sense follows the order of the points).
    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        let rho2 = p.x * p.x + p.z * p.z;
        if rho2 <= EPSILON {
            return (DVec3::Y, DVec3::Y);
        }
        let rho = rho2.sqrt();
        let s = &self.segments[part as usize];
        let t = s.nearest(DVec2::new(rho, p.y), self.degree);
        // A negative end radius draws the profile mirrored: match the point's side.
        let t = if at(&s.u, t) < 0.0 {
            s.nearest(DVec2::new(-rho, p.y), self.degree)
        } else {
            t
        };
        let (dr, dh) = (slope(&s.u, t), slope(&s.v, t));
        let n = DVec3::new(dh * p.x, -dr * rho, dh * p.z);
        (n, n)
    }

    /// POV-Ray's even-odd count of the profile's crossings outwards from the point, at its
    /// height, within the profile's box.
    fn contains(&self, p: DVec3) -> bool {
        let rho = (p.x * p.x + p.z * p.z).sqrt();
        if p.y < self.lo.y || p.y > self.hi.y || rho < self.lo.x || rho > self.hi.x {
            return false;
        }
        let mut inside = false;
        for s in self.segments.iter() {
            if p.y < s.lo.y - EPSILON || p.y > s.hi.y + EPSILON {
                continue;
            }
            let mut c = poly(s.v);
            c[0] -= p.y;
            for &t in roots_in(&c, self.degree, 0.0, 1.0).as_slice() {
                if at(&s.u, t) >= rho {
                    inside = !inside;
                }
            }
        }
        inside
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        if self.segments.is_empty() {
            return Some((DVec3::ZERO, DVec3::ZERO));
        }
        let r = self.radius();
        Some((DVec3::new(-r, self.lo.y, -r), DVec3::new(r, self.hi.y, r)))
    }

    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        self.crossings(ray, f)
    }

    /// POV-Ray's lathe coordinates: u the longitude, v the spline parameter along the whole
    /// profile (segment index plus the parameter within it, over the number of segments).
    fn uv(&self, p: DVec3, part: u32) -> Option<DVec2> {
        let u = super::longitude(p.x, p.z);
        let rho = (p.x * p.x + p.z * p.z).sqrt();
        let s = &self.segments[part as usize];
        let t = s.nearest(DVec2::new(rho, p.y), self.degree);
        let t = if at(&s.u, t) < 0.0 {
            s.nearest(DVec2::new(-rho, p.y), self.degree)
        } else {
            t
        };
        let v = (t + part as f64) / self.segments.len() as f64;
        Some(DVec2::new(u, v.min(1.0)))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// A cylinder of radius 1 from y = 0 to 2, drawn as one straight profile segment.
    fn tube() -> Lathe {
        Lathe::new(
            1,
            vec![CurveSegment::new(
                [0.0, 0.0, 0.0, 1.0],
                [0.0, 0.0, 2.0, 0.0],
            )],
        )
    }

    #[test]
    fn hits_misses_and_inside() {
        let l = tube();
        let c = l.intersect(&Ray::new(
            DVec3::new(-5.0, 1.0, 0.0),
            DVec3::new(1.0, 0.1, 0.0),
        ));
        assert_eq!(c.len(), 2, "{:?}", c.as_slice());
        assert!((c.as_slice()[0] - 4.0).abs() < 1e-9 && (c.as_slice()[1] - 6.0).abs() < 1e-9);
        // Horizontal: both crossings of the tube.
        let c = l.intersect(&Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X));
        assert_eq!(c.as_slice(), &[4.0, 6.0]);
        let (n, _) = l.normals(DVec3::new(-1.0, 1.0, 0.0), c.parts()[0]);
        assert!(n.normalize().dot(DVec3::X).abs() > 0.999, "{n}");
        // Tangent and missing rays.
        assert!(
            l.intersect(&Ray::new(DVec3::new(-5.0, 1.0, 1.5), DVec3::X))
                .is_empty()
        );
        assert!(
            l.intersect(&Ray::new(DVec3::new(-5.0, 3.0, 0.0), DVec3::X))
                .is_empty()
        );
        // Down the axis: an open tube has no caps.
        assert!(
            l.intersect(&Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::NEG_Y))
                .is_empty()
        );
        // A profile that does not reach the axis encloses nothing nearer the axis than its
        // least radius (POV-Ray's test), and nothing beyond its greatest.
        assert!(!l.contains(DVec3::new(0.5, 1.0, 0.2)));
        assert!(!l.contains(DVec3::new(1.5, 1.0, 0.0)));
        assert!(!l.contains(DVec3::new(0.5, 2.5, 0.0)));
    }

    /// A closed profile (a capped cylinder drawn as three segments) encloses its inside.
    #[test]
    fn closed_profile_inside() {
        let seg = |a: (f64, f64), b: (f64, f64)| {
            CurveSegment::new([0.0, 0.0, b.0 - a.0, a.0], [0.0, 0.0, b.1 - a.1, a.1])
        };
        let l = Lathe::new(
            1,
            vec![
                seg((0.0, 0.0), (1.0, 0.0)),
                seg((1.0, 0.0), (1.0, 2.0)),
                seg((1.0, 2.0), (0.0, 2.0)),
            ],
        );
        assert!(l.contains(DVec3::new(0.5, 1.0, 0.2)));
        assert!(!l.contains(DVec3::new(0.9, 1.0, 0.9)));
        let c = l.intersect(&Ray::new(DVec3::new(0.3, 5.0, 0.0), DVec3::NEG_Y));
        assert_eq!(c.len(), 2, "{:?}", c.as_slice());
    }

    /// A quadratic profile: the degree-4 equation along an oblique ray.
    #[test]
    fn curved_profile() {
        // r(t) = 1 + t(1 − t)·2 (bulging to 1.5), y = 2t.
        let l = Lathe::new(
            2,
            vec![CurveSegment::new(
                [0.0, -2.0, 2.0, 1.0],
                [0.0, 0.0, 2.0, 0.0],
            )],
        );
        let c = l.intersect(&Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X));
        assert_eq!(c.len(), 2);
        assert!((c.as_slice()[0] - 3.5).abs() < 1e-9, "{:?}", c.as_slice());
        let o = Ray::new(DVec3::new(-5.0, 0.2, 0.3), DVec3::new(1.0, 0.12, 0.0));
        for &t in l.intersect(&o).as_slice() {
            let q = o.at(t);
            let s = q.y / 2.0;
            let r = 1.0 + 2.0 * s * (1.0 - s);
            assert!(((q.x * q.x + q.z * q.z).sqrt() - r).abs() < 1e-9);
        }
    }
}
