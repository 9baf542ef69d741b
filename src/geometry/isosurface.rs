//! `isosurface`: where a user function equals its threshold, inside a container box or
//! sphere (POV-Ray's IsoSurface with R. Suzuki's method 2: the ray's span in the container is
//! halved while the function's values at both ends could, at slope `max_gradient`, reach the
//! surface between them; spans shorter than `accuracy` end the search).

use super::{Crossings, Ray};
use crate::func::Function;
use glam::DVec3;
use std::sync::Arc;

/// POV-Ray's tiny value.
const EPSILON: f64 = 1e-10;
/// POV-Ray's box tests: the nearest far side kept.
const BOX_DEPTH_TOLERANCE: f64 = 1e-6;
/// POV-Ray's "infinitely far".
const BOUND_HUGE: f64 = 2e10;

/// What holds an isosurface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Container {
    /// A box between two corners.
    Box(DVec3, DVec3),
    /// A sphere: centre and radius.
    Sphere(DVec3, f64),
}

impl Container {
    /// The ray's span in the container (distances and the box sides they cross, or
    /// [`SURFACE`] for a sphere or no side), as POV-Ray's box and sphere tests give it: the
    /// box's span starts at 0 at the earliest, the sphere's may start behind the origin.
    pub(super) fn span(&self, ray: &Ray) -> Option<(f64, f64, u32, u32)> {
        match *self {
            Container::Box(lo, hi) => {
                let (p, d) = (ray.origin, ray.direction);
                let (mut tmin, mut tmax) = (0.0f64, BOUND_HUGE);
                let (mut smin, mut smax) = (SURFACE, SURFACE);
                for axis in 0..3 {
                    let side = |high: bool| 1 + 2 * axis as u32 + u32::from(high);
                    if d[axis].abs() > EPSILON {
                        let negative = d[axis] < 0.0;
                        let (far, near) = if negative {
                            (lo[axis], hi[axis])
                        } else {
                            (hi[axis], lo[axis])
                        };
                        let t = (far - p[axis]) / d[axis];
                        if t < tmin {
                            return None;
                        }
                        if t <= tmax {
                            smax = side(!negative);
                            tmax = t;
                        }
                        let t = (near - p[axis]) / d[axis];
                        if t >= tmin {
                            if t > tmax {
                                return None;
                            }
                            smin = side(negative);
                            tmin = t;
                        }
                    } else if p[axis] < lo[axis] || p[axis] > hi[axis] {
                        return None;
                    }
                }
                (tmax >= BOX_DEPTH_TOLERANCE).then_some((tmin, tmax, smin, smax))
            }
            Container::Sphere(c, r) => {
                let length = ray.direction.length();
                let d = ray.direction / length;
                let oc = c - ray.origin;
                let (oc2, closest) = (oc.length_squared(), oc.dot(d));
                if oc2 >= r * r && closest < EPSILON {
                    return None;
                }
                let half2 = r * r - oc2 + closest * closest;
                if half2 <= EPSILON {
                    return None;
                }
                let half = half2.sqrt();
                Some((
                    (closest - half) / length,
                    (closest + half) / length,
                    SURFACE,
                    SURFACE,
                ))
            }
        }
    }

    /// Its box.
    pub(super) fn bounds(&self) -> (DVec3, DVec3) {
        match *self {
            Container::Box(lo, hi) => (lo, hi),
            Container::Sphere(c, r) => (c - DVec3::splat(r), c + DVec3::splat(r)),
        }
    }
}

/// An isosurface in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Isosurface {
    function: Arc<Function>,
    generator: u8,
    container: Container,
    threshold: f64,
    accuracy: f64,
    max_gradient: f64,
    /// Whether the container closes the surface where the function is below the threshold
    /// (not `open`).
    closed: bool,
    max_trace: u32,
}

/// Part tags: 0 the function's surface (or a sphere container's), 1 + 2·axis + (1 at the
/// greater side) a box container's side.
const SURFACE: u32 = 0;

impl Isosurface {
    /// The isosurface `function(p) = threshold` within `container`, searched to `accuracy`
    /// assuming slopes up to `max_gradient`, at most `max_trace` crossings a ray; noise
    /// functions use `generator`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        function: Arc<Function>,
        generator: u8,
        container: Container,
        threshold: f64,
        accuracy: f64,
        max_gradient: f64,
        closed: bool,
        max_trace: u32,
    ) -> Isosurface {
        Isosurface {
            function,
            generator,
            container,
            threshold,
            accuracy,
            max_gradient,
            closed,
            max_trace,
        }
    }

    /// The function less the threshold.
    fn value(&self, p: DVec3) -> f64 {
        self.function.at(p, self.generator) - self.threshold
    }

    /// Calls `f` with each crossing in increasing distance (POV-Ray's All_Intersections).
    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        let Some((mut depth1, mut depth2, side1, side2)) = self.container.span(ray) else {
            return;
        };
        depth1 = depth1.max(0.0);
        let at = |t: f64| ray.origin + t * ray.direction;
        let (acc, maxg) = (self.accuracy, self.max_gradient);
        // Crossings found before the search (container walls), given out only once the span
        // proves long enough (POV-Ray takes its one back otherwise).
        let mut found: [(f64, u32); 2] = [(0.0, 0); 2];
        let mut count = 0;
        let mut traced = 0;
        let mut sign = 1.0;
        if self.closed {
            let v = self.value(at(depth1));
            if depth1 > acc {
                if v < 0.0 {
                    // The function is below the threshold where the ray enters: the
                    // container's wall is the surface there.
                    found[count] = (depth1, side1);
                    count += 1;
                    traced += 1;
                    sign = -sign;
                }
            } else {
                if v < maxg * acc * 4.0 {
                    depth1 = acc * 5.0;
                    if self.value(at(depth1)) < 0.0 {
                        sign = -1.0;
                    }
                }
                if self.value(at(depth2)) < 0.0 {
                    found[count] = (depth2, side2);
                    count += 1;
                }
            }
        }
        depth2 = depth2.min(BOUND_HUGE);
        depth1 = depth1.min(depth2);
        let (mut tmin, tmax) = (depth1, depth2);
        if tmax - tmin < acc {
            return;
        }
        if depth1 < acc && sign == 1.0 && self.value(at(tmin)).abs() < maxg * acc * 4.0 {
            // Starting on the surface: step in, and search from the other side.
            tmin = acc * 5.0;
            if self.value(at(tmin)) < 0.0 {
                sign = -1.0;
            }
        }
        let give = |t: f64, part: u32, f: &mut dyn FnMut(f64, u32)| {
            if ray.contains(t) {
                f(t, part);
            }
        };
        for &(t, part) in &found[..count] {
            give(t, part, &mut f);
        }
        let vlength = ray.direction.length();
        while traced < self.max_trace {
            let Some(t) = self.find_root(ray, tmin, tmax, &mut sign, vlength) else {
                break;
            };
            give(t, SURFACE, &mut f);
            traced += 1;
            tmin = t + acc * 5.0;
            if tmax - tmin < acc {
                break;
            }
            sign = -sign;
        }
    }

    /// POV-Ray's Function_Find_Root: the first crossing in `[t1, t2]` of the signed function.
    fn find_root(&self, ray: &Ray, t1: f64, t2: f64, sign: &mut f64, vlength: f64) -> Option<f64> {
        let value = |t: f64, s: f64| s * self.value(ray.origin + t * ray.direction);
        let mut f1 = value(t1, *sign);
        if !self.closed && f1 < 0.0 {
            *sign = -*sign;
            f1 = -f1;
        }
        let f2 = value(t2, *sign);
        let span = t2 - t1;
        let dt = self.max_gradient * vlength * span;
        let s = *sign;
        self.find_root_in((t1, f1), (t2, f2), dt, span, &|t| value(t, s))
    }

    fn find_root_in<F: Fn(f64) -> f64>(
        &self,
        a: (f64, f64),
        b: (f64, f64),
        dt: f64,
        span: f64,
        value: &F,
    ) -> Option<f64> {
        if span < self.accuracy {
            return (b.1 < 0.0).then_some(b.0);
        }
        if a.1 + b.1 - dt < 0.0 {
            let (span, dt) = (span * 0.5, dt * 0.5);
            let t = a.0 + span;
            let mid = (t, value(t));
            self.find_root_in(a, mid, dt, span, value)
                .or_else(|| self.find_root_in(mid, b, dt, span, value))
        } else {
            None
        }
    }
}

impl super::shape::Surface for Isosurface {
    const NAME: &'static str = "Isosurface";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::nearest_of(|f| self.crossings(ray, f))
    }

    /// A box container's side, a sphere container's surface, else POV-Ray's forward
    /// differences of the function with step `accuracy`.
    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        if part != SURFACE {
            let axis = ((part - 1) / 2) as usize;
            let mut n = DVec3::ZERO;
            n[axis] = if (part - 1) % 2 == 1 { 1.0 } else { -1.0 };
            return (n, n);
        }
        if let Container::Sphere(c, r) = self.container {
            let v = p - c;
            if (v.length() - r).abs() < EPSILON {
                return (v, v);
            }
        }
        let f = |q: DVec3| self.function.at(q, self.generator);
        let here = f(p);
        let acc = self.accuracy;
        let mut n = DVec3::new(
            f(p + DVec3::X * acc) - here,
            f(p + DVec3::Y * acc) - here,
            f(p + DVec3::Z * acc) - here,
        );
        if n == DVec3::ZERO {
            n = DVec3::X;
        }
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        let within = match self.container {
            Container::Box(lo, hi) => p.cmpge(lo).all() && p.cmple(hi).all(),
            Container::Sphere(c, r) => (c - p).length_squared() <= r * r,
        };
        within && self.value(p) <= 0.0
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some(self.container.bounds())
    }

    /// Every crossing, whatever `max_trace`: POV-Ray walks a shadow ray from crossing to
    /// crossing, searching the surface anew from each (at most `max_trace` crossings a
    /// search), so it meets them all.
    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        super::shape::walk(ray, f, |from, give| self.crossings(from, give));
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;
    use crate::func::{Internal, Op};

    fn sphere_of(r: f64) -> Arc<Function> {
        // f_sphere(x, y, z, r)
        Arc::new(
            Function::new(
                3,
                vec![
                    Op::Arg(0),
                    Op::Arg(1),
                    Op::Arg(2),
                    Op::Const(r),
                    Op::Internal(Internal::Sphere, 4),
                ],
            )
            .unwrap(),
        )
    }

    /// The function sphere of radius 1 in the box ±`half`, closed or `open`.
    fn unit_sphere_in_box(half: f64, closed: bool) -> Isosurface {
        let container = Container::Box(DVec3::splat(-half), DVec3::splat(half));
        Isosurface::new(sphere_of(1.0), 2, container, 0.0, 0.001, 1.1, closed, 1)
    }

    /// A function sphere of radius 1 in the default box: hit within the accuracy, its
    /// normal outward, the inside test right.
    #[test]
    fn function_sphere() {
        let iso = unit_sphere_in_box(2.0, true);
        let ray = Ray::new(DVec3::new(0.1, 0.2, -5.0), DVec3::Z);
        let (t, part) = iso.intersect(&ray).first_part().unwrap();
        let p = ray.at(t);
        assert!((p.length() - 1.0).abs() < 0.002, "{p}");
        let n = iso.normals(p, part).0.normalize();
        assert!(n.dot(p.normalize()) > 0.999, "{n}");
        assert!(iso.contains(DVec3::ZERO) && !iso.contains(DVec3::splat(1.5)));
        assert!(
            iso.intersect(&Ray::new(DVec3::new(1.5, 0.0, -5.0), DVec3::Z))
                .is_empty()
        );
    }

    /// A container that cuts the surface shows its wall where the function is inside.
    #[test]
    fn container_wall() {
        let iso = unit_sphere_in_box(0.5, true);
        let ray = Ray::new(DVec3::new(0.1, 0.2, -5.0), DVec3::Z);
        let (t, part) = iso.intersect(&ray).first_part().unwrap();
        assert!((t - 4.5).abs() < 1e-12 && part != SURFACE);
        assert_eq!(iso.normals(ray.at(t), part).0, DVec3::NEG_Z);
        // Open, there is no wall: the ray passes through.
        let open = unit_sphere_in_box(0.5, false);
        assert!(open.intersect(&ray).is_empty());
    }
}
