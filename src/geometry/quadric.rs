//! `quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }`: the points where
//! `A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0`, inside where it is ≤ 0
//! (POV-Ray's quadric, with its formulas).

use super::{Crossings, Ray};
use glam::DVec3;

/// A quadric surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quadric {
    /// `<A, B, C>`: the x², y², z² terms.
    pub square: DVec3,
    /// `<D, E, F>`: the xy, xz, yz terms.
    pub mixed: DVec3,
    /// `<G, H, I>`: the x, y, z terms.
    pub linear: DVec3,
    /// `J`.
    pub constant: f64,
}

impl Quadric {
    /// The quadric's value at `p` (negative inside).
    pub fn value(&self, p: DVec3) -> f64 {
        let (s, m, l) = (self.square, self.mixed, self.linear);
        p.x * (s.x * p.x + m.x * p.y + l.x)
            + p.y * (s.y * p.y + m.z * p.z + l.y)
            + p.z * (s.z * p.z + m.y * p.x + l.z)
            + self.constant
    }

    /// The bounding box of an axis-aligned ellipsoid (no mixed terms, positive squares, a
    /// real surface); every other quadric is unbounded, as POV-Ray leaves it.
    fn ellipsoid_bounds(&self) -> Option<(DVec3, DVec3)> {
        let (s, l) = (self.square, self.linear);
        if self.mixed != DVec3::ZERO || s.min_element() <= 0.0 {
            return None;
        }
        // A(x + G/2A)² + … = G²/4A + … − J
        let centre = -l / (2.0 * s);
        let k = (l * l / (4.0 * s)).element_sum() - self.constant;
        if k < 0.0 {
            return None;
        }
        let half = (DVec3::splat(k) / s).powf(0.5);
        Some((centre - half, centre + half))
    }
}

impl super::shape::Surface for Quadric {
    const NAME: &'static str = "Quadric";

    fn intersect(&self, ray: &Ray) -> Crossings {
        let (s, m, l) = (self.square, self.mixed, self.linear);
        let (o, d) = (ray.origin, ray.direction);
        // POV-Ray's half-b form.
        let a = d.x * (s.x * d.x + m.x * d.y + m.y * d.z)
            + d.y * (s.y * d.y + m.z * d.z)
            + d.z * s.z * d.z;
        let b = d.x * (s.x * o.x + 0.5 * (m.x * o.y + m.y * o.z + l.x))
            + d.y * (s.y * o.y + 0.5 * (m.x * o.x + m.z * o.z + l.y))
            + d.z * (s.z * o.z + 0.5 * (m.y * o.x + m.z * o.y + l.z));
        let c = self.value(o);
        if a != 0.0 {
            let disc = b * b - a * c;
            if disc <= 0.0 {
                return Crossings::NONE;
            }
            let root = disc.sqrt();
            let (t1, t2) = ((-b + root) / a, (-b - root) / a);
            Crossings::within(ray, &[t1.min(t2), t1.max(t2)])
        } else if b != 0.0 {
            Crossings::within(ray, &[-0.5 * c / b])
        } else {
            Crossings::NONE
        }
    }

    fn normals(&self, p: DVec3, _part: u32) -> (DVec3, DVec3) {
        let (s, m, l) = (self.square, self.mixed, self.linear);
        let n = DVec3::new(
            2.0 * s.x * p.x + m.x * p.y + m.y * p.z + l.x,
            m.x * p.x + 2.0 * s.y * p.y + m.z * p.z + l.y,
            m.y * p.x + m.z * p.y + 2.0 * s.z * p.z + l.z,
        );
        // (Undefined at a singular point: POV-Ray takes x.)
        let n = if n == DVec3::ZERO { DVec3::X } else { n };
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        self.value(p) <= 0.0
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        self.ellipsoid_bounds()
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// x² + y² + z² − 1: the unit sphere.
    fn sphere() -> Quadric {
        Quadric {
            square: DVec3::ONE,
            mixed: DVec3::ZERO,
            linear: DVec3::ZERO,
            constant: -1.0,
        }
    }

    #[test]
    fn a_sphere_quadric_is_hit_where_the_sphere_is() {
        let r = Ray::new(DVec3::new(0.3, 0.2, -5.0), DVec3::Z);
        let c = sphere().intersect(&r);
        let expect = (1.0f64 - 0.13).sqrt();
        assert_eq!(c.as_slice().len(), 2);
        assert!((c.as_slice()[0] - (5.0 - expect)).abs() < 1e-12);
        assert!((c.as_slice()[1] - (5.0 + expect)).abs() < 1e-12);
        let p = r.at(c.as_slice()[0]);
        assert!((sphere().normals(p, 0).0.normalize() - p).length() < 1e-9);
        // Misses, tangent and inside.
        assert!(
            sphere()
                .intersect(&Ray::new(DVec3::new(2.0, 0.0, -5.0), DVec3::Z))
                .is_empty()
        );
        assert!(
            sphere()
                .intersect(&Ray::new(DVec3::new(1.0, 0.0, -5.0), DVec3::Z))
                .is_empty()
        );
        assert_eq!(
            sphere()
                .intersect(&Ray::new(DVec3::ZERO, DVec3::Z))
                .as_slice(),
            &[1.0]
        );
        assert!(sphere().contains(DVec3::splat(0.5)));
        assert!(!sphere().contains(DVec3::splat(0.6)));
    }

    #[test]
    fn a_linear_quadric_is_a_plane_and_a_cylinder_is_unbounded() {
        // y − 1 = 0 (no square terms): one crossing.
        let plane = Quadric {
            square: DVec3::ZERO,
            mixed: DVec3::ZERO,
            linear: DVec3::Y,
            constant: -1.0,
        };
        let c = plane.intersect(&Ray::new(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0)));
        assert_eq!(c.as_slice(), &[0.5]);
        assert!(plane.bounds().is_none());
        // x² + z² − 1 (shapes.inc's Cylinder_Y): unbounded; a ray along y never crosses it.
        let cylinder = Quadric {
            square: DVec3::new(1.0, 0.0, 1.0),
            ..sphere()
        };
        assert!(cylinder.bounds().is_none());
        assert!(
            cylinder
                .intersect(&Ray::new(DVec3::ZERO, DVec3::Y))
                .is_empty()
        );
        assert_eq!(
            cylinder
                .intersect(&Ray::new(DVec3::new(-3.0, 7.0, 0.0), DVec3::X))
                .as_slice(),
            &[2.0, 4.0]
        );
    }

    #[test]
    fn an_ellipsoid_is_bounded_by_its_box() {
        // 4(x − 1)² + y² + z² − 4 = 0: centre (1, 0, 0), half axes (1, 2, 2).
        let e = Quadric {
            square: DVec3::new(4.0, 1.0, 1.0),
            mixed: DVec3::ZERO,
            linear: DVec3::new(-8.0, 0.0, 0.0),
            constant: 0.0,
        };
        let (lo, hi) = e.bounds().expect("an ellipsoid is bounded");
        assert!((lo - DVec3::new(0.0, -2.0, -2.0)).length() < 1e-12, "{lo}");
        assert!((hi - DVec3::new(2.0, 2.0, 2.0)).length() < 1e-12, "{hi}");
    }
}
