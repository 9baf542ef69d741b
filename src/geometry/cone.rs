//! Truncated cone (and cylinder) in a canonical frame: the axis runs along z from 0 to 1, and
//! the radius goes linearly from `r0` at z = 0 to `r1` at z = 1 (x and y are not scaled). The
//! scene maps the frame onto the user's end points.

use super::{Crossings, Ray};
use glam::DVec3;

/// Part tags of the crossings.
const SIDE: u32 = 0;
const BASE_CAP: u32 = 1;
const TOP_CAP: u32 = 2;

/// A canonical truncated cone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone {
    /// Radius at z = 0.
    pub r0: f64,
    /// Radius at z = 1.
    pub r1: f64,
    /// No end caps.
    pub open: bool,
}

impl Cone {
    /// Normal (not unit length, canonical frame) at `p` on the given part.
    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match part {
            BASE_CAP => -DVec3::Z,
            TOP_CAP => DVec3::Z,
            _ => {
                let k = self.r1 - self.r0;
                DVec3::new(p.x, p.y, -k * (self.r0 + k * p.z))
            }
        }
    }
}

impl super::shape::Surface for Cone {
    const NAME: &'static str = "Cone/Cylinder";

    #[inline]
    fn intersect(&self, ray: &Ray) -> Crossings {
        let (o, d) = (ray.origin, ray.direction);
        let k = self.r1 - self.r0;
        let r_o = self.r0 + k * o.z;
        // Side: (ox + t dx)² + (oy + t dy)² = (r_o + k dz t)².
        let a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
        let half_b = o.x * d.x + o.y * d.y - k * d.z * r_o;
        let c = o.x * o.x + o.y * o.y - r_o * r_o;
        let mut out = Crossings::NONE;
        let side = |t: f64, out: &mut Crossings| {
            let z = o.z + t * d.z;
            if (0.0..=1.0).contains(&z) && self.r0 + k * z >= 0.0 && ray.contains(t) {
                out.push(t, SIDE);
            }
        };
        if a.abs() > f64::EPSILON * (d.length_squared()) {
            let disc = half_b * half_b - a * c;
            if disc >= 0.0 {
                let q = -(half_b + disc.sqrt().copysign(half_b));
                if q != 0.0 {
                    side(c / q, &mut out);
                    side(q / a, &mut out);
                }
            }
        } else if half_b != 0.0 {
            // Ray parallel to a generatrix of the cone: one crossing.
            side(-c / (2.0 * half_b), &mut out);
        }
        if !self.open && d.z != 0.0 {
            for (z, r, tag) in [(0.0, self.r0, BASE_CAP), (1.0, self.r1, TOP_CAP)] {
                if r > 0.0 {
                    let t = (z - o.z) / d.z;
                    let p = o + t * d;
                    if p.x * p.x + p.y * p.y <= r * r && ray.contains(t) {
                        out.push(t, tag);
                    }
                }
            }
        }
        out.sort();
        out
    }

    #[inline]
    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        let n = self.normal(p, part);
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        let r = self.r0 + (self.r1 - self.r0) * p.z;
        (0.0..=1.0).contains(&p.z) && p.x * p.x + p.y * p.y < r * r
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let r = self.r0.max(self.r1);
        Some((DVec3::new(-r, -r, 0.0), DVec3::new(r, r, 1.0)))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    fn cylinder(open: bool) -> Cone {
        Cone {
            r0: 1.0,
            r1: 1.0,
            open,
        }
    }

    #[test]
    fn cylinder_ray_across_hits_side_twice() {
        let r = Ray::new(DVec3::new(-5.0, 0.0, 0.5), DVec3::X);
        let c = cylinder(false).intersect(&r);
        assert_eq!(c.as_slice(), &[4.0, 6.0]);
        assert_eq!(c.first_part(), Some((4.0, SIDE)));
    }

    #[test]
    fn cylinder_ray_along_axis_hits_caps() {
        let r = Ray::new(DVec3::new(0.0, 0.0, -1.0), DVec3::Z);
        let c = cylinder(false).intersect(&r);
        assert_eq!(c.as_slice(), &[1.0, 2.0]);
        assert_eq!(c.first_part(), Some((1.0, BASE_CAP)));
    }

    #[test]
    fn open_cylinder_along_axis_is_missed() {
        let r = Ray::new(DVec3::new(0.0, 0.0, -1.0), DVec3::Z);
        assert!(cylinder(true).intersect(&r).is_empty());
    }

    #[test]
    fn open_cylinder_seen_from_inside_hits_far_wall() {
        let r = Ray::new(DVec3::new(0.0, 0.0, 0.5), DVec3::X);
        assert_eq!(cylinder(true).intersect(&r).as_slice(), &[1.0]);
    }

    #[test]
    fn cylinder_ray_above_misses() {
        let r = Ray::new(DVec3::new(-5.0, 0.0, 1.5), DVec3::X);
        assert!(cylinder(false).intersect(&r).is_empty());
    }

    #[test]
    fn cone_with_point_end_has_no_cap_there() {
        let cone = Cone {
            r0: 1.0,
            r1: 0.0,
            open: false,
        };
        // Along the axis from above the apex: enters at the apex, leaves through the base cap.
        let r = Ray::new(DVec3::new(0.0, 0.0, 2.0), -DVec3::Z);
        let c = cone.intersect(&r);
        assert_eq!(c.as_slice().last(), Some(&2.0));
        // Halfway up the radius is 0.5.
        let r = Ray::new(DVec3::new(-5.0, 0.0, 0.5), DVec3::X);
        let c = cone.intersect(&r);
        assert!((c.as_slice()[0] - 4.5).abs() < 1e-12 && (c.as_slice()[1] - 5.5).abs() < 1e-12);
    }

    #[test]
    fn cone_side_normal_leans_toward_the_narrow_end() {
        let cone = Cone {
            r0: 1.0,
            r1: 0.0,
            open: false,
        };
        let n = cone.normal(DVec3::new(0.5, 0.0, 0.5), SIDE).normalize();
        assert!(n.x > 0.0 && n.z > 0.0);
        assert!((n - DVec3::new(1.0, 0.0, 1.0).normalize()).length() < 1e-12);
    }

    #[test]
    fn cone_behind_origin_is_not_hit() {
        let r = Ray::new(DVec3::new(5.0, 0.0, 0.5), DVec3::X);
        assert!(cylinder(false).intersect(&r).is_empty());
    }
}

#[cfg(test)]
mod properties {
    use super::super::shape::Surface;
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn cone_hits_lie_on_side_or_caps(
            r0 in 0.1..2.0f64, r1 in 0.0..2.0f64,
            ox in -5.0..5.0f64, oy in -5.0..5.0f64, oz in -5.0..5.0f64,
            tx in -0.5..0.5f64, ty in -0.5..0.5f64, tz in 0.05..0.95f64,
        ) {
            let cone = Cone { r0, r1, open: false };
            let origin = DVec3::new(ox, oy, oz) + DVec3::new(0.0, 0.0, 0.5);
            let r = Ray::new(origin, DVec3::new(tx * r0.min(r1.max(0.1)), ty * r0.min(r1.max(0.1)), tz) - origin);
            for (k, &t) in cone.intersect(&r).as_slice().iter().enumerate() {
                let p = r.at(t);
                let radius = r0 + (r1 - r0) * p.z;
                let side = ((p.x * p.x + p.y * p.y).sqrt() - radius).abs();
                let cap = p.z.abs().min((p.z - 1.0).abs());
                prop_assert!(side < 1e-9 || cap < 1e-9, "crossing {} off the surface: side {}, cap {}", k, side, cap);
            }
        }
    }
}
