//! Torus around the y axis: `(|p|² + R² − r²)² = 4R²(x² + z²)`.

use super::poly::{Poly, any_root_in, roots_in};
use super::{Crossings, Ray};
use glam::DVec3;

/// What a ray's search for crossings asks.
enum Search<F> {
    /// Each crossing in turn, until the function says stop.
    Each(F),
    /// Whether there is one (a shadow ray).
    Any,
}

/// A torus in object space (centre at the origin, in the x-z plane).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Torus {
    /// Radius of the centre circle.
    pub major: f64,
    /// Radius of the tube.
    pub minor: f64,
}

impl Torus {
    /// Coefficients of the quartic in `s` whose roots are where `o + s·d` (`|d| = 1`) meets the
    /// torus: with G = |p|² − R² − r², G² + 4R²(y² − r²) = 0. Their size grows with `|o|`, so
    /// [`Torus::intersect`] forms them near the torus.
    pub fn quartic(&self, o: DVec3, d: DVec3) -> Poly {
        let (big, small) = (self.major, self.minor);
        let e = o.length_squared() - big * big - small * small;
        let g = o.dot(d);
        let four_r2 = 4.0 * big * big;
        [
            e * e + four_r2 * (o.y * o.y - small * small),
            4.0 * g * e + 2.0 * four_r2 * o.y * d.y,
            4.0 * g * g + 2.0 * e + four_r2 * d.y * d.y,
            4.0 * g,
            1.0,
            0.0,
            0.0,
        ]
    }

    /// Calls `f` with each distance in the ray's range where it meets the torus, nearest
    /// first, until `f` returns true; returns whether it did. The quartic is solved only over
    /// the part of the ray inside the bounding sphere (radius R + r), the slab |y| ≤ r and the
    /// ray's own range, and formed at that part's start (its coefficients grow with the
    /// distance from the torus).
    fn each_root(&self, ray: &Ray, f: impl FnMut(f64) -> bool) -> bool {
        self.search(ray, Search::Each(f))
    }

    /// [`Torus::each_root`] for `Search::Each`; for `Search::Any`, whether the ray meets the
    /// torus in its range (a root known to lie well inside the range is not refined).
    fn search<F: FnMut(f64) -> bool>(&self, ray: &Ray, search: Search<F>) -> bool {
        let (big, small) = (self.major, self.minor);
        let length = ray.direction.length();
        let d = ray.direction / length;
        let bound = big + small;
        let along = ray.origin.dot(d);
        let perpendicular = ray.origin - along * d;
        let h2 = bound * bound - perpendicular.length_squared();
        if h2 < 0.0 {
            return false;
        }
        let h = h2.sqrt();
        let (mut lo, mut hi) = (-along - h, -along + h);
        // The ray's range, in unit-direction distances.
        lo = lo.max(ray.tmin * length);
        hi = hi.min(ray.tmax * length);
        // The slab |y| ≤ r.
        if d.y != 0.0 {
            let (a, b) = ((-small - ray.origin.y) / d.y, (small - ray.origin.y) / d.y);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        } else if ray.origin.y.abs() > small {
            return false;
        }
        let margin = 1e-9 * bound;
        // (NaN bounds, from a degenerate ray, are a miss.)
        if lo.is_nan() || hi.is_nan() || lo > hi + 2.0 * margin {
            return false;
        }
        let shift = lo.max(0.0).min(hi.max(0.0));
        let c = self.quartic(ray.origin + shift * d, d);
        let range = ((lo - shift) - margin, (hi - shift) + margin);
        let mut f = match search {
            Search::Any => {
                // Inside the ray's own range, with room for the rounding of t.
                let room = 1e-9 * (ray.tmax * length).abs().min(1e300).max(bound);
                let sure = (
                    ray.tmin * length - shift + room,
                    ray.tmax * length - shift - room,
                );
                let hit = |s: f64| ray.contains((shift + s) / length);
                return any_root_in(&c, 4, range, sure, hit);
            }
            Search::Each(f) => f,
        };
        let roots = roots_in(&c, 4, range.0, range.1);
        for &s in roots.as_slice() {
            let t = (shift + s) / length;
            if ray.contains(t) && f(t) {
                return true;
            }
        }
        false
    }

    /// Outward normal (not unit length) at `p`.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let g = p.length_squared() - self.major * self.major - self.minor * self.minor;
        g * p + DVec3::new(0.0, 2.0 * self.major * self.major * p.y, 0.0)
    }
}

impl super::shape::Surface for Torus {
    const NAME: &'static str = "Torus";

    #[inline]
    fn intersect(&self, ray: &Ray) -> Crossings {
        let mut out = Crossings::NONE;
        self.each_root(ray, |t| {
            out.push(t, 0);
            false
        });
        out
    }

    fn occludes(&self, ray: &Ray) -> bool {
        self.search(ray, Search::<fn(f64) -> bool>::Any)
    }

    #[inline]
    fn normals(&self, p: DVec3, _part: u32) -> (DVec3, DVec3) {
        let n = self.normal(p);
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        let ring = (p.x * p.x + p.z * p.z).sqrt() - self.major;
        ring * ring + p.y * p.y < self.minor * self.minor
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let (a, b) = (self.major + self.minor, self.minor);
        Some((DVec3::new(-a, -b, -a), DVec3::new(a, b, a)))
    }

    /// POV-Ray's torus coordinates: u around the y axis (decreasing from −x), v around the
    /// tube.
    fn uv(&self, p: DVec3, _part: u32) -> Option<glam::DVec2> {
        use std::f64::consts::{PI, TAU};
        let u = 1.0 - (p.z.atan2(p.x) + PI) / TAU;
        let x = (p.x * p.x + p.z * p.z).sqrt() - self.major;
        let v = (p.y.atan2(x) + PI) / TAU;
        Some(glam::DVec2::new(u, v))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;
    use proptest::prelude::*;

    fn torus() -> Torus {
        Torus {
            major: 2.0,
            minor: 0.5,
        }
    }

    #[test]
    fn torus_ray_through_both_tubes_hits_four_times() {
        let r = Ray::new(DVec3::new(-10.0, 0.0, 0.0), DVec3::X);
        let c = torus().intersect(&r);
        let expected = [7.5, 8.5, 11.5, 12.5];
        assert_eq!(c.len(), 4);
        for (a, b) in c.as_slice().iter().zip(expected) {
            assert!((a - b).abs() < 1e-9, "{:?}", c.as_slice());
        }
    }

    #[test]
    fn torus_ray_through_hole_misses() {
        let r = Ray::new(DVec3::new(0.0, 10.0, 0.0), -DVec3::Y);
        assert!(torus().intersect(&r).is_empty());
    }

    #[test]
    fn torus_ray_down_onto_tube_hits_top() {
        let r = Ray::new(DVec3::new(2.0, 10.0, 0.0), -DVec3::Y);
        let t = torus().intersect(&r).first().expect("hit");
        assert!((t - 9.5).abs() < 1e-9);
        assert!((torus().normal(r.at(t)).normalize() - DVec3::Y).length() < 1e-9);
    }

    #[test]
    fn torus_from_inside_tube_hits_once_going_out() {
        let r = Ray::new(DVec3::new(2.0, 0.0, 0.0), DVec3::Y);
        assert_eq!(torus().intersect(&r).len(), 1);
    }

    #[test]
    fn torus_far_origin_keeps_precision() {
        let r = Ray::new(DVec3::new(-1e5, 0.0, 0.0), DVec3::X);
        let t = torus().intersect(&r).first().expect("hit");
        assert!((t - (1e5 - 2.5)).abs() < 1e-7, "t = {t}");
    }

    #[test]
    fn torus_grazing_top_does_not_produce_nan() {
        // Tangent to the top of the tube along x.
        let r = Ray::new(DVec3::new(-10.0, 0.5, 0.0), DVec3::X);
        for &t in torus().intersect(&r).as_slice() {
            assert!(t.is_finite());
        }
    }

    proptest! {
        #[test]
        fn torus_hits_lie_on_surface(
            ox in -20.0..20.0f64, oy in -20.0..20.0f64, oz in -20.0..20.0f64,
            tx in -2.5..2.5f64, ty in -0.5..0.5f64, tz in -2.5..2.5f64,
        ) {
            let t = torus();
            let origin = DVec3::new(ox, oy, oz);
            let r = Ray::new(origin, DVec3::new(tx, ty, tz) - origin);
            for &s in t.intersect(&r).as_slice() {
                let p = r.at(s);
                let ring = (p.x * p.x + p.z * p.z).sqrt() - 2.0;
                let residual = ((ring * ring + p.y * p.y).sqrt() - 0.5).abs();
                prop_assert!(residual < 1e-7, "residual {}", residual);
            }
        }
    }
}
