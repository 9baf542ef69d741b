//! Disc: the part of the plane through `centre` with normal `normal` between `hole_radius`
//! and `radius` from the centre. Infinitely thin and two-sided.

use super::{Crossings, Ray};
use glam::DVec3;

/// A disc in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disc {
    /// Centre.
    pub centre: DVec3,
    /// Unit normal.
    pub normal: DVec3,
    /// Outer radius.
    pub radius: f64,
    /// Hole radius (0 for none).
    pub hole_radius: f64,
}

impl super::shape::Surface for Disc {
    const NAME: &'static str = "Disc";

    #[inline]
    fn intersect(&self, ray: &Ray) -> Crossings {
        let denom = self.normal.dot(ray.direction);
        if denom == 0.0 {
            return Crossings::NONE;
        }
        let t = self.normal.dot(self.centre - ray.origin) / denom;
        let r2 = (ray.at(t) - self.centre).length_squared();
        if r2 > self.radius * self.radius || r2 < self.hole_radius * self.hole_radius {
            return Crossings::NONE;
        }
        Crossings::within(ray, &[t])
    }

    #[inline]
    fn normals(&self, _p: DVec3, _part: u32) -> (DVec3, DVec3) {
        (self.normal, self.normal)
    }

    fn contains(&self, p: DVec3) -> bool {
        // POV-Ray: the half-space on the disc's back side.
        (p - self.centre).dot(self.normal) < 0.0
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some((self.centre - self.radius, self.centre + self.radius))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    fn disc() -> Disc {
        Disc {
            centre: DVec3::ZERO,
            normal: DVec3::Y,
            radius: 2.0,
            hole_radius: 1.0,
        }
    }

    #[test]
    fn disc_ring_is_hit() {
        let r = Ray::new(DVec3::new(1.5, 3.0, 0.0), -DVec3::Y);
        assert_eq!(disc().intersect(&r).as_slice(), &[3.0]);
    }

    #[test]
    fn disc_hole_is_missed() {
        let r = Ray::new(DVec3::new(0.5, 3.0, 0.0), -DVec3::Y);
        assert!(disc().intersect(&r).is_empty());
    }

    #[test]
    fn disc_outside_radius_is_missed() {
        let r = Ray::new(DVec3::new(2.5, 3.0, 0.0), -DVec3::Y);
        assert!(disc().intersect(&r).is_empty());
    }

    #[test]
    fn disc_is_hit_from_below_too() {
        let r = Ray::new(DVec3::new(1.5, -3.0, 0.0), DVec3::Y);
        assert_eq!(disc().intersect(&r).as_slice(), &[3.0]);
    }

    #[test]
    fn disc_edge_on_ray_misses() {
        let r = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        assert!(disc().intersect(&r).is_empty());
    }
}
