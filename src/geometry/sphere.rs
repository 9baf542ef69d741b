//! Sphere: `|p − centre| = radius`.

use super::{Crossings, Ray};
use glam::DVec3;

/// A sphere in object space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Centre.
    pub centre: DVec3,
    /// Radius.
    pub radius: f64,
}

impl Sphere {
    /// Outward unit normal at a point on the sphere.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        (p - self.centre).normalize()
    }
}

/// The terms of a ray's quadratic with a sphere (see [`Sphere::terms`]).
struct Terms {
    f: DVec3,
    d: DVec3,
    a: f64,
    half_b: f64,
    ff: f64,
    rr: f64,
    c: f64,
}

impl Sphere {
    /// The terms of the ray's quadratic, `None` for a clear miss: the textbook discriminant
    /// half_b² − a·c is the same number as the one `intersect` uses but for rounding, which
    /// is under 20 units of a·(|f|² + r²) for each; below minus a millionth of that, both
    /// are negative. (Without the division `intersect` goes on to.)
    #[inline(always)]
    fn terms(&self, ray: &Ray) -> Option<Terms> {
        let f = ray.origin - self.centre;
        let d = ray.direction;
        let a = d.length_squared();
        let half_b = f.dot(d);
        let (ff, rr) = (f.length_squared(), self.radius * self.radius);
        let c = ff - rr;
        if half_b * half_b - a * c < -1e-6 * (a * (ff + rr)) {
            return None;
        }
        Some(Terms {
            f,
            d,
            a,
            half_b,
            ff,
            rr,
            c,
        })
    }

    /// Whether the ray clearly misses the sphere: `intersect` then finds nothing.
    #[inline(always)]
    pub fn clearly_missed(&self, ray: &Ray) -> bool {
        self.terms(ray).is_none()
    }
}

impl super::shape::Surface for Sphere {
    const NAME: &'static str = "Sphere";

    #[inline]
    fn intersect(&self, ray: &Ray) -> Crossings {
        let Some(Terms {
            f,
            d,
            a,
            half_b,
            ff,
            rr,
            c,
        }) = self.terms(ray)
        else {
            return Crossings::NONE;
        };
        // Δ/a = r² − |f − (f·d/a)·d|²: the squared half chord.
        let perpendicular = f - (half_b / a) * d;
        let discriminant = a * (rr - perpendicular.length_squared());
        if discriminant < 0.0 {
            return Crossings::NONE;
        }
        let q = -(half_b + discriminant.sqrt().copysign(half_b));
        if q == 0.0 {
            // Origin on the sphere and ray tangent to it: a single touching point at t = 0.
            return Crossings::NONE;
        }
        let (t0, t1) = (c / q, q / a);
        // c = |f|² − r² carries a rounding error of about ε(|f|² + r²), and f itself one of
        // ε(|origin| + |centre|) in each coordinate, so the root c/q is only known to within
        // their sum over |q|: a root that small is the surface the ray starts on, met again
        // by rounding (a sphere of radius 30000 seen from 1 unit off its surface: 10⁻⁹ and
        // more at grazing angles, beyond the spawned origin's offset).
        let far = ray.origin.abs().max_element() + self.centre.abs().max_element();
        let noise = 4.0 * f64::EPSILON * (ff + rr + 2.0 * f.abs().element_sum() * far) / q.abs();
        let t0 = if t0.abs() <= noise { f64::NAN } else { t0 };
        let (near, far) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
        Crossings::within(ray, &[near, far])
    }

    #[inline]
    fn normals(&self, p: DVec3, _part: u32) -> (DVec3, DVec3) {
        let n = self.normal(p);
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        (p - self.centre).length_squared() < self.radius * self.radius
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some((
            self.centre - self.radius.abs(),
            self.centre + self.radius.abs(),
        ))
    }

    /// POV-Ray's sphere coordinates: u the longitude from +x towards +z (0 to 1), v the
    /// latitude from the south pole (0) to the north (1).
    fn uv(&self, p: DVec3, _part: u32) -> Option<glam::DVec2> {
        let d = p - self.centre;
        let len = d.length();
        if len == 0.0 {
            return Some(glam::DVec2::ZERO);
        }
        let d = d / len;
        let v = 0.5 + d.y.asin() / std::f64::consts::PI;
        let u = super::longitude(d.x, d.z);
        Some(glam::DVec2::new(u, v))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;
    use proptest::prelude::*;

    fn unit() -> Sphere {
        Sphere {
            centre: DVec3::ZERO,
            radius: 1.0,
        }
    }

    /// A ray the early test turns away finds nothing in the full test, grazing rays among
    /// them; and the early test turns most missing rays away.
    #[test]
    fn clear_misses_find_nothing() {
        let mut random = crate::testing::Xorshift(0x5fe1e);
        let (mut missed, mut turned_away) = (0, 0);
        for _ in 0..200_000 {
            let v = |r: &mut crate::testing::Xorshift| {
                DVec3::new(r.unit(), r.unit(), r.unit()) * 2.0 - 1.0
            };
            let sphere = Sphere {
                centre: v(&mut random) * 5.0,
                radius: 0.1 + random.unit() * 3.0,
            };
            let origin = v(&mut random) * 10.0;
            // (Aimed near the rim: within a tenth of the radius of grazing it, either side.)
            let aim = sphere.centre - origin;
            let side = aim.any_orthogonal_vector().normalize();
            let off = sphere.radius * (0.9 + 0.2 * random.unit());
            let ray = Ray::new(
                origin,
                (aim + side * off).normalize() * (0.5 + random.unit()),
            );
            let found = sphere.intersect(&ray);
            if found.is_empty() {
                missed += 1;
            }
            if sphere.clearly_missed(&ray) {
                turned_away += 1;
                assert!(found.is_empty(), "{sphere:?} {ray:?}");
            }
        }
        assert!(
            turned_away > 0 && turned_away * 10 > missed * 9,
            "{turned_away} of {missed} misses turned away"
        );
    }

    #[test]
    fn a_ray_leaving_a_huge_sphere_does_not_meet_it_again() {
        // A sphere of radius 30000 whose surface passes 1 unit from the origin (a users'
        // scene of curved mirrors): rays reflected off it, from spawned origins, at every
        // angle down to grazing, must leave it; rounding in |f|² − r² once made them meet it
        // again at t ≈ 10⁻⁹ (speckles over the whole picture).
        let s = Sphere {
            centre: DVec3::new(-30001.0, 0.0, 0.0),
            radius: 30000.0,
        };
        let mut again = 0;
        for i in 0..2000 {
            let a = f64::from(i) * 0.000_77;
            let p = DVec3::new(-1.0, (a * 7.0).sin() * 0.9, (a * 5.0).cos() * 0.9);
            let n = s.normal(p);
            let on = s.centre + n * s.radius;
            let tangent = n.cross(DVec3::new(0.3, 0.7, 0.2)).normalize();
            let cos = 1e-4 + (f64::from(i % 100) / 100.0).powi(3);
            let dir = (n * cos + tangent * (1.0 - cos * cos).sqrt()).normalize();
            let origin = crate::geometry::offset_origin(on, n, dir, 1.0);
            if !s.intersect(&Ray::new(origin, dir)).is_empty() {
                again += 1;
            }
        }
        assert_eq!(again, 0);
    }

    #[test]
    fn sphere_ray_through_centre_hits_both_sides() {
        let r = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        assert_eq!(unit().intersect(&r).as_slice(), &[4.0, 6.0]);
    }

    #[test]
    fn sphere_ray_beside_misses() {
        let r = Ray::new(DVec3::new(1.5, 0.0, -5.0), DVec3::Z);
        assert!(unit().intersect(&r).first().is_none());
    }

    #[test]
    fn sphere_tangent_ray_touches_once_or_misses() {
        let r = Ray::new(DVec3::new(1.0, 0.0, -5.0), DVec3::Z);
        let hits = unit().intersect(&r);
        for &t in hits.as_slice() {
            assert!((t - 5.0).abs() < 1e-6, "tangent hit at {t}");
        }
    }

    #[test]
    fn sphere_ray_from_inside_hits_far_side_only() {
        let r = Ray::new(DVec3::ZERO, DVec3::X);
        assert_eq!(unit().intersect(&r).as_slice(), &[1.0]);
    }

    #[test]
    fn sphere_behind_origin_is_not_hit() {
        let r = Ray::new(DVec3::new(0.0, 0.0, 5.0), DVec3::Z);
        assert!(unit().intersect(&r).first().is_none());
    }

    #[test]
    fn sphere_respects_tmax() {
        let mut r = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        r.tmax = 4.5;
        assert_eq!(unit().intersect(&r).as_slice(), &[4.0]);
    }

    #[test]
    fn sphere_unnormalised_direction_keeps_t_meaning() {
        let r = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z * 2.0);
        assert_eq!(unit().intersect(&r).as_slice(), &[2.0, 3.0]);
    }

    #[test]
    fn sphere_far_and_small_keeps_precision() {
        // A 1 mm sphere 1e5 units away: the textbook discriminant cancels, this one does not.
        let s = Sphere {
            centre: DVec3::new(1e5, 0.0, 0.0),
            radius: 1e-3,
        };
        let r = Ray::new(DVec3::ZERO, DVec3::X);
        let t = s.intersect(&r).first().expect("hit");
        assert!((t - (1e5 - 1e-3)).abs() < 1e-9, "t = {t}");
    }

    proptest! {
        #[test]
        fn sphere_hit_lies_on_surface(
            cx in -1e3..1e3f64, cy in -1e3..1e3f64, cz in -1e3..1e3f64,
            radius in 1e-3..1e3f64,
            ox in -1.0..1.0f64, oy in -1.0..1.0f64, oz in -1.0..1.0f64,
            tx in -1.0..1.0f64, ty in -1.0..1.0f64, tz in -1.0..1.0f64,
        ) {
            let centre = DVec3::new(cx, cy, cz);
            let s = Sphere { centre, radius };
            // From a point outside, aim at a point inside the sphere.
            let dir_out = DVec3::new(ox, oy, oz).normalize_or(DVec3::X);
            let origin = centre + dir_out * radius * 3.0;
            let target = centre + DVec3::new(tx, ty, tz) * radius * 0.5;
            let r = Ray::new(origin, target - origin);
            let hits = s.intersect(&r);
            prop_assert_eq!(hits.as_slice().len(), 2);
            for &t in hits.as_slice() {
                let residual = ((r.at(t) - centre).length() - radius).abs();
                prop_assert!(residual <= 1e-12 * (radius + centre.abs().max_element()), "residual {}", residual);
            }
        }

        #[test]
        fn ray_leaving_sphere_does_not_hit_it_again(
            theta in 0.0..std::f64::consts::PI, phi in 0.0..std::f64::consts::TAU,
            dx in -1.0..1.0f64, dy in -1.0..1.0f64, dz in -1.0..1.0f64,
            scale in prop::sample::select(vec![1e-3, 1.0, 1e3]),
            offset in prop::sample::select(vec![0.0, 1e3, 1e5]),
        ) {
            let centre = DVec3::splat(offset);
            let s = Sphere { centre, radius: scale };
            let n = DVec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos());
            let p = centre + n * scale;
            let mut d = DVec3::new(dx, dy, dz).normalize_or(n);
            if d.dot(n) < 0.0 { d = -d; }
            if d.dot(n) < 1e-3 { d = (d + n).normalize(); }
            let origin = super::super::offset_origin(p, n, d, 0.0);
            let r = Ray::new(origin, d);
            prop_assert!(s.intersect(&r).first().is_none());
        }
    }
}
