//! Infinite plane: `normal·p = distance`; the inside is `normal·p < distance`.

use super::{Crossings, Ray};
use glam::DVec3;

/// A plane in object space (unit normal).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// Unit normal, pointing outside.
    pub normal: DVec3,
    /// Offset along the normal.
    pub distance: f64,
}

impl super::shape::Surface for Plane {
    const NAME: &'static str = "Plane";

    #[inline]
    fn intersect(&self, ray: &Ray) -> Crossings {
        // Solve n·(o + t·d) = distance.
        // POV-Ray's plane: a ray within 1e-10 of parallel misses, and so does a hit farther
        // than its MAX_DISTANCE, 1e7 (trace() scatter macros meet both).
        let denom = self.normal.dot(ray.direction);
        if denom.abs() < 1e-10 {
            return Crossings::NONE;
        }
        let t = (self.distance - self.normal.dot(ray.origin)) / denom;
        if t > 1e7 {
            return Crossings::NONE;
        }
        Crossings::within(ray, &[t])
    }

    #[inline]
    fn normals(&self, _p: DVec3, _part: u32) -> (DVec3, DVec3) {
        (self.normal, self.normal)
    }

    fn contains(&self, p: DVec3) -> bool {
        self.normal.dot(p) < self.distance
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    fn floor() -> Plane {
        Plane {
            normal: DVec3::Y,
            distance: -1.0,
        }
    }

    #[test]
    fn plane_ray_down_hits() {
        let r = Ray::new(DVec3::new(0.0, 2.0, 0.0), -DVec3::Y);
        assert_eq!(floor().intersect(&r).as_slice(), &[3.0]);
    }

    #[test]
    fn plane_parallel_ray_misses() {
        let r = Ray::new(DVec3::new(0.0, 2.0, 0.0), DVec3::X);
        assert!(floor().intersect(&r).first().is_none());
    }

    #[test]
    fn plane_ray_pointing_away_misses() {
        let r = Ray::new(DVec3::new(0.0, 2.0, 0.0), DVec3::Y);
        assert!(floor().intersect(&r).first().is_none());
    }

    #[test]
    fn plane_ray_from_inside_hits_from_below() {
        let r = Ray::new(DVec3::new(0.0, -3.0, 0.0), DVec3::Y);
        assert_eq!(floor().intersect(&r).as_slice(), &[2.0]);
        assert!(floor().contains(r.origin));
    }

    #[test]
    fn plane_grazing_ray_far_away_still_hits() {
        let r = Ray::new(DVec3::new(0.0, 0.0, 0.0), DVec3::new(1.0, -1e-6, 0.0));
        let t = floor().intersect(&r).first().expect("hit");
        assert!((r.at(t).y + 1.0).abs() < 1e-9);
    }
}
