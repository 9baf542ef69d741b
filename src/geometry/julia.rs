//! `julia_fractal`: the points of a 3-D slice of 4-D space whose iteration `z → z² + c` (or
//! `z³ + c`) in the quaternions or the hypercomplex numbers stays bounded (POV-Ray's Fractal).
//!
//! POV-Ray's method: march along the ray inside the bounding sphere by steps no shorter than
//! 1/precision (longer where a distance estimate allows), then bisect the step where the
//! point's status changes down to 1e-7, keeping the point inside; the normal is the gradient
//! of |z_N|² by the chain rule through the iterations.

use super::{Crossings, Ray};
use glam::{DVec3, DVec4};

/// Bisection tolerance and shortest distance.
const TOLERANCE: f64 = 1e-7;

/// POV-Ray's shortest shadow-ray step (its SHADOW_TOLERANCE): a shadow ray (unit direction
/// in the world, so `t` is a distance) ignores what it meets closer than this to where it or
/// its last crossing was.
const SHADOW_TOLERANCE: f64 = 1e-3;

/// A julia fractal in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct JuliaFractal {
    c: DVec4,
    hypercomplex: bool,
    cube: bool,
    iterations: u32,
    /// The shortest marching step (1 / precision).
    step: f64,
    /// The slice's normal (unit) and distance: w = (d − s.xyz·p) / s.w.
    slice: DVec4,
    distance: f64,
    radius2: f64,
    exit: f64,
}

/// Quaternion (and hypercomplex) values as (x, y, z, w).
fn hmul(a: DVec4, b: DVec4) -> DVec4 {
    DVec4::new(
        a.x * b.x - a.y * b.y - a.z * b.z + a.w * b.w,
        a.x * b.y + a.y * b.x - a.z * b.w - a.w * b.z,
        a.x * b.z + a.z * b.x - a.y * b.w - a.w * b.y,
        a.x * b.w + a.w * b.x + a.y * b.z + a.z * b.y,
    )
}

impl JuliaFractal {
    /// A fractal of parameter `c`; `slice` need not be unit length (its w must not be 0).
    pub fn new(
        c: DVec4,
        hypercomplex: bool,
        cube: bool,
        iterations: u32,
        precision: f64,
        slice: DVec4,
        distance: f64,
    ) -> JuliaFractal {
        let (radius, exit) = if hypercomplex {
            (4.0, 16.0)
        } else {
            let r = (1.0 + c.length() + 1e-7).min(2.0);
            (r, r * r + 1e-7)
        };
        JuliaFractal {
            c,
            hypercomplex,
            cube,
            iterations: iterations.max(1),
            step: 1.0 / precision.max(1.0),
            slice: slice.normalize(),
            distance,
            radius2: radius * radius,
            exit,
        }
    }

    fn start(&self, p: DVec3) -> DVec4 {
        let s = self.slice;
        DVec4::new(
            p.x,
            p.y,
            p.z,
            (self.distance - s.x * p.x - s.y * p.y - s.z * p.z) / s.w,
        )
    }

    /// One iteration step.
    fn next(&self, z: DVec4) -> DVec4 {
        let c = self.c;
        if self.hypercomplex {
            // (POV-Ray's hypercomplex `cube` squares too.)
            return DVec4::new(
                z.x * z.x - z.y * z.y - z.z * z.z + z.w * z.w,
                2.0 * (z.x * z.y - z.z * z.w),
                2.0 * (z.x * z.z - z.w * z.y),
                2.0 * (z.x * z.w + z.y * z.z),
            ) + c;
        }
        let d = z.y * z.y + z.z * z.z + z.w * z.w;
        if self.cube {
            let k = 3.0 * z.x * z.x - d;
            DVec4::new(z.x * (z.x * z.x - 3.0 * d), z.y * k, z.z * k, z.w * k) + c
        } else {
            DVec4::new(
                z.x * z.x - d,
                2.0 * z.x * z.y,
                2.0 * z.x * z.z,
                2.0 * z.x * z.w,
            ) + c
        }
    }

    /// Whether the point stays bounded (z₀ … z_{N−1} within the exit radius).
    fn inside(&self, p: DVec3) -> bool {
        let mut z = self.start(p);
        for _ in 0..self.iterations {
            if z.length_squared() > self.exit {
                return false;
            }
            z = self.next(z);
        }
        true
    }

    /// Whether the point stays bounded, and the step POV-Ray may take from it along `dir`.
    fn estimate(&self, p: DVec3, dir: DVec3) -> (bool, f64) {
        let z0 = self.start(p);
        let mut z = z0;
        let mut product = 1.0;
        let k: f64 = if self.cube { 3.0 } else { 2.0 };
        for i in 1..=self.iterations {
            let norm = z.length_squared();
            if norm > self.exit {
                let dist = if self.hypercomplex {
                    let mut s = self.gradient(z0, i - 1).dot(dir);
                    if s < -1e-8 {
                        s *= -2.0;
                        if self.step * s < norm && norm < 30.0 * self.step * s {
                            return (false, norm / s);
                        }
                    }
                    self.step
                } else {
                    norm.sqrt() * norm.ln() / (k.powi(i as i32) * product * norm.sqrt())
                };
                return (false, dist);
            }
            product *= z.length();
            z = self.next(z);
        }
        (true, self.step)
    }

    /// The gradient (up to a positive factor) of |z_n|² in x, y, z, from z₀.
    fn gradient(&self, z0: DVec4, n: u32) -> DVec3 {
        if self.hypercomplex {
            let mut z = z0;
            let mut p = DVec4::new(1.0, 0.0, 0.0, 0.0);
            for _ in 0..n {
                p = hmul(p, z);
                z = self.next(z);
            }
            if n == 0 {
                p = z0;
            }
            let v = if self.cube {
                z
            } else {
                z * 2f64.powi(n as i32)
            };
            return DVec3::new(
                p.dot(v),
                DVec4::new(-p.y, p.x, -p.w, p.z).dot(v),
                DVec4::new(-p.z, -p.w, p.x, p.y).dot(v),
            );
        }
        let mut rows = [DVec4::X, DVec4::Y, DVec4::Z];
        let mut z = z0;
        for _ in 0..n {
            let (x, y, zz, w) = (z.x, z.y, z.z, z.w);
            for r in rows.iter_mut() {
                *r = if self.cube {
                    let d = y * y + zz * zz + w * w;
                    let (a, b) = (x * x - d, 3.0 * x * x - d);
                    let t = 2.0 * (r.y * y + r.z * zz + r.w * w);
                    let u = 6.0 * x * r.x - t;
                    DVec4::new(
                        3.0 * (r.x * a - x * t),
                        r.y * b + y * u,
                        r.z * b + zz * u,
                        r.w * b + w * u,
                    )
                } else {
                    DVec4::new(
                        r.x * x - r.y * y - r.z * zz - r.w * w,
                        r.x * y + x * r.y,
                        r.x * zz + x * r.z,
                        r.x * w + x * r.w,
                    )
                };
            }
            z = self.next(z);
        }
        DVec3::new(rows[0].dot(z), rows[1].dot(z), rows[2].dot(z))
    }

    /// Calls `f` with each crossing until it returns false.
    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64) -> bool) {
        let len = ray.direction.length();
        let (o, dir) = (ray.origin, ray.direction / len);
        // The bounding sphere.
        let b = o.dot(dir);
        let c = o.length_squared() - self.radius2;
        let half2 = b * b - c;
        if half2 <= 1e-10 || (c > 0.0 && -b < 1e-10) {
            return;
        }
        let half = half2.sqrt();
        let t1 = (-b + half).min(ray.tmax * len);
        if t1 < TOLERANCE {
            return;
        }
        let mut depth = (-b - half).max(TOLERANCE);
        let mut p = o + depth * dir;
        let (mut current, mut dist) = self.estimate(p, dir);
        if current {
            p += 2.0 * TOLERANCE * dir;
            depth += 2.0 * TOLERANCE;
            if depth > t1 {
                return;
            }
            (current, dist) = self.estimate(p, dir);
        }
        loop {
            // March until the status changes.
            let (mut a, mut step);
            loop {
                step = dist.max(self.step);
                depth += step;
                if depth > t1 {
                    return;
                }
                a = p;
                p += step * dir;
                let (next, next_dist) = self.estimate(p, dir);
                if next != current {
                    depth -= step;
                    current = next;
                    dist = next_dist;
                    break;
                }
                dist = next_dist;
            }
            // Bisect: `a` has the old status, `a + step` the new one.
            let old = !current;
            while step > TOLERANCE {
                step /= 2.0;
                let m = a + step * dir;
                if self.inside(m) == old {
                    a = m;
                    depth += step;
                    if depth > t1 {
                        return;
                    }
                }
            }
            // The reported point lies just inside.
            if !old {
                depth += step;
            }
            let t = depth / len;
            if ray.contains(t) && !f(t) {
                return;
            }
            depth = (p - o).dot(dir);
        }
    }
}

impl super::shape::Surface for JuliaFractal {
    const NAME: &'static str = "JuliaFractal";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::first_of(|f| self.crossings(ray, f))
    }

    fn normals(&self, p: DVec3, _: u32) -> (DVec3, DVec3) {
        let n = self.gradient(self.start(p), self.iterations);
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        p.length_squared() <= self.radius2 && self.inside(p)
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let r = self.radius2.sqrt();
        Some((DVec3::splat(-r), DVec3::splat(r)))
    }

    /// A shadow ray's crossings, as POV-Ray's walk meets them: its search reports the first
    /// crossing from where the walk stands, and a shadow ray passes what lies within
    /// `SHADOW_TOLERANCE` of its start, so a first crossing that near ends the walk through
    /// the set. (The surface is found to within the marching's precision and reported just
    /// inside, so a shadow ray leaving a lit point meets the surface it leaves at once.)
    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        super::shape::walk(ray, f, |from, give| {
            if let Some(t) = self.first_beyond_tolerance(from) {
                give(t, 0);
            }
        });
    }

    /// Whether a shadow ray is blocked: the first crossing lies beyond `SHADOW_TOLERANCE`.
    fn occludes(&self, ray: &Ray) -> bool {
        self.first_beyond_tolerance(ray).is_some()
    }
}

impl JuliaFractal {
    /// The first crossing of a shadow ray if it lies beyond `SHADOW_TOLERANCE`.
    fn first_beyond_tolerance(&self, ray: &Ray) -> Option<f64> {
        let mut first = None;
        self.crossings(ray, |t| {
            first = Some(t);
            false
        });
        first.filter(|&t| t > SHADOW_TOLERANCE)
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// With c = 0 the quaternion set z² is the unit ball: a ray meets it at distance 4 from 5.
    #[test]
    fn unit_ball() {
        let j = JuliaFractal::new(DVec4::ZERO, false, false, 20, 200.0, DVec4::W, 0.0);
        let t = j
            .intersect(&Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X))
            .first()
            .unwrap();
        assert!((t - 4.0).abs() < 1e-3, "{t}");
        let (n, _) = j.normals(DVec3::new(-1.0, 0.0, 0.0), 0);
        assert!(n.normalize().dot(DVec3::NEG_X) > 0.999, "{n}");
        assert!(j.contains(DVec3::new(0.5, 0.2, 0.1)));
        assert!(!j.contains(DVec3::new(1.2, 0.0, 0.0)));
        assert!(
            j.intersect(&Ray::new(DVec3::new(-5.0, 1.5, 0.0), DVec3::X))
                .is_empty()
        );
        // Cubes too: |z|³ stays bounded inside the unit ball.
        let c = JuliaFractal::new(DVec4::ZERO, false, true, 20, 200.0, DVec4::W, 0.0);
        let t = c
            .intersect(&Ray::new(DVec3::new(0.0, -5.0, 0.0), DVec3::Y))
            .first()
            .unwrap();
        assert!((t - 4.0).abs() < 1e-3, "{t}");
    }
}
