//! Axis-aligned box (POV-Ray `box`).

use super::{Crossings, Ray};
use glam::DVec3;

/// A box in object space, `min ≤ p ≤ max` per axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cuboid {
    /// Least corner.
    pub min: DVec3,
    /// Greatest corner.
    pub max: DVec3,
}

impl Cuboid {
    /// Outward unit normal at `p` on the face of axis `part` (from [`Cuboid::intersect`]).
    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        let axis = (part as usize).min(2);
        let centre = (self.min[axis] + self.max[axis]) * 0.5;
        let mut n = DVec3::ZERO;
        n[axis] = if p[axis] >= centre { 1.0 } else { -1.0 };
        n
    }
}

impl super::shape::Surface for Cuboid {
    const NAME: &'static str = "Box";

    #[inline]
    fn intersect(&self, ray: &Ray) -> Crossings {
        let inv = ray.direction.recip();
        let t0 = (self.min - ray.origin) * inv;
        let t1 = (self.max - ray.origin) * inv;
        let (mut near, mut near_axis) = (f64::NEG_INFINITY, 0);
        let (mut far, mut far_axis) = (f64::INFINITY, 0);
        for i in 0..3 {
            let (a, b) = (t0[i], t1[i]);
            let (lo, hi) = if a <= b {
                (a, b)
            } else if b < a {
                (b, a)
            } else {
                continue; // NaN: the origin is on this slab's plane
            };
            if lo > near {
                (near, near_axis) = (lo, i as u32);
            }
            if hi < far {
                (far, far_axis) = (hi, i as u32);
            }
        }
        // NaN bounds (no finite slab) miss as well as an empty interval.
        if near.partial_cmp(&far).is_none_or(std::cmp::Ordering::is_gt) || far == f64::INFINITY {
            return Crossings::NONE;
        }
        let mut c = Crossings::NONE;
        for (t, axis) in [(near, near_axis), (far, far_axis)] {
            if ray.contains(t) {
                c.push(t, axis);
            }
        }
        c
    }

    #[inline]
    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        let n = self.normal(p, part);
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        p.cmpgt(self.min).all() && p.cmplt(self.max).all()
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some((self.min, self.max))
    }

    /// POV-Ray's cube map: the six faces unfolded in a 4 × 3 cross, none mirrored seen from
    /// outside.
    fn uv(&self, p: DVec3, part: u32) -> Option<glam::DVec2> {
        let q = (p - self.min) / (self.max - self.min);
        let axis = (part as usize).min(2);
        let high = p[axis] >= (self.min[axis] + self.max[axis]) * 0.5;
        let (u, v) = match (axis, high) {
            (0, false) => (q.z / 4.0, 1.0 / 3.0 + q.y / 3.0),
            (0, true) => (3.0 / 4.0 - q.z / 4.0, 1.0 / 3.0 + q.y / 3.0),
            (1, false) => (1.0 / 4.0 + q.x / 4.0, q.z / 3.0),
            (1, true) => (1.0 / 4.0 + q.x / 4.0, 1.0 - q.z / 3.0),
            (_, false) => (1.0 - q.x / 4.0, 1.0 / 3.0 + q.y / 3.0),
            (_, true) => (1.0 / 4.0 + q.x / 4.0, 1.0 / 3.0 + q.y / 3.0),
        };
        Some(glam::DVec2::new(u, v))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    fn unit() -> Cuboid {
        Cuboid {
            min: DVec3::splat(-1.0),
            max: DVec3::splat(1.0),
        }
    }

    #[test]
    fn box_ray_through_hits_two_faces() {
        let r = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        let hits = unit().intersect(&r);
        assert_eq!(hits.as_slice(), &[4.0, 6.0]);
        assert_eq!(unit().normal(r.at(4.0), hits.parts()[0]), -DVec3::Z);
    }

    #[test]
    fn a_ray_along_a_face_hits_as_in_povray() {
        // Origin on the min and on the max x face, direction with a zero x component: the
        // closed slab holds the ray (it missed before: the NaN slab swapped its ends).
        for x in [-1.0, 1.0] {
            let r = Ray::new(DVec3::new(x, 0.0, -5.0), DVec3::Z);
            let hits = unit().intersect(&r);
            assert_eq!(hits.as_slice(), &[4.0, 6.0], "x = {x}");
            // The ray enters through the z face it looks at, not the x face it runs along
            // (the |x| = |z| tie at the edge made these lines dark).
            assert_eq!(
                unit().normal(r.at(4.0), hits.parts()[0]),
                -DVec3::Z,
                "x = {x}"
            );
        }
    }

    #[test]
    fn box_ray_beside_misses() {
        let r = Ray::new(DVec3::new(2.0, 0.0, -5.0), DVec3::Z);
        assert!(unit().intersect(&r).first().is_none());
    }

    #[test]
    fn box_ray_from_inside_hits_far_face() {
        let r = Ray::new(DVec3::ZERO, DVec3::Y);
        let hits = unit().intersect(&r);
        assert_eq!(hits.as_slice(), &[1.0]);
        assert_eq!(unit().normal(r.at(1.0), hits.parts()[0]), DVec3::Y);
    }

    #[test]
    fn box_behind_origin_is_not_hit() {
        let r = Ray::new(DVec3::new(0.0, 0.0, 5.0), DVec3::Z);
        assert!(unit().intersect(&r).first().is_none());
    }

    #[test]
    fn box_ray_in_face_plane_with_zero_component_does_not_nan() {
        // Origin exactly on the x = 1 slab plane, direction with zero x component.
        let r = Ray::new(DVec3::new(1.0, 0.0, -5.0), DVec3::Z);
        let hits = unit().intersect(&r);
        assert!(hits.as_slice().iter().all(|t| t.is_finite()));
    }

    #[test]
    fn box_tangent_along_edge_is_hit_or_missed_without_nan() {
        let r = Ray::new(DVec3::new(1.0, 1.0, -5.0), DVec3::Z);
        assert!(
            unit()
                .intersect(&r)
                .as_slice()
                .iter()
                .all(|t| t.is_finite())
        );
    }

    #[test]
    fn box_diagonal_ray_hits_corner_region() {
        let r = Ray::new(DVec3::splat(-5.0), DVec3::ONE);
        assert_eq!(unit().intersect(&r).as_slice(), &[4.0, 6.0]);
    }
}

#[cfg(test)]
mod properties {
    use super::super::shape::Surface;
    use super::*;
    use crate::geometry::offset_origin;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn box_hits_lie_on_surface_and_leaving_rays_do_not_return(
            cx in -1e5..1e5f64, size in prop::sample::select(vec![1e-3, 1.0, 1e3]),
            ox in -1.0..1.0f64, oy in -1.0..1.0f64, oz in -1.0..1.0f64,
            tx in -0.9..0.9f64, ty in -0.9..0.9f64, tz in -0.9..0.9f64,
        ) {
            let c = DVec3::splat(cx);
            let b = Cuboid { min: c - size, max: c + size };
            let origin = c + DVec3::new(ox, oy, oz).normalize_or(DVec3::X) * size * 4.0;
            let r = Ray::new(origin, c + DVec3::new(tx, ty, tz) * size - origin);
            let hits = b.intersect(&r);
            let t = hits.first();
            prop_assert!(t.is_some());
            let p = r.at(t.unwrap());
            let q = ((p - c).abs() - size).abs().min_element();
            prop_assert!(q <= 1e-12 * (cx.abs() + size), "off surface by {}", q);
            // Leave the surface along a direction with a positive component along the normal.
            let n = b.normal(p, hits.parts()[0]);
            let d = (n + DVec3::new(ty, tz, tx) * 0.5).normalize();
            let out = Ray::new(offset_origin(p, n, d, 0.0), d);
            prop_assert!(b.intersect(&out).is_empty());
        }
    }
}
