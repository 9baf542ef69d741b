//! `ovus { bottom_radius, top_radius }`: an egg made of a sphere at the origin, a smaller or
//! larger sphere centred one bottom radius above it, and the band of a spindle torus about the
//! y axis that joins them smoothly (POV-Ray's Ovus, with its constants and filters).

use super::poly::roots_in;
use super::{Crossings, Ray};
use glam::DVec3;

/// POV-Ray's tolerances: hits, the torus band's test, tiny values.
const DEPTH_TOLERANCE: f64 = 1e-4;
const ROOT_TOLERANCE: f64 = 1e-4;
const EPSILON: f64 = 1e-10;

/// An ovus in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Ovus {
    bottom: f64,
    top: f64,
    /// The joining torus: tube radius, the (negative-side) distance of its tube's centre from
    /// the axis, the height of its centre, and the heights where it takes over from the spheres.
    connecting: f64,
    horizontal: f64,
    vertical: f64,
    bottom_vertical: f64,
    top_vertical: f64,
}

/// Part tags.
const BOTTOM: u32 = 0;
const TOP: u32 = 1;
const BAND: u32 = 2;

impl Ovus {
    /// POV-Ray's ovus of radii `bottom` and `top` (`top < 2·bottom`; POV-Ray draws a sphere
    /// otherwise, which the evaluator makes).
    pub fn new(bottom: f64, top: f64) -> Ovus {
        let (b, t) = (bottom, top);
        let (connecting, vertical, horizontal, bottom_vertical, top_vertical);
        if b > t {
            connecting = 2.0 * b;
            vertical = 2.0 * t - b - t * t / (2.0 * b);
            horizontal = (b * b - vertical * vertical).sqrt();
            bottom_vertical = -vertical;
            top_vertical = (b - vertical) * t / (connecting - t) + b;
        } else {
            connecting = 2.0 * t;
            vertical = -2.0 * t + b + 1.5 * t * t / b;
            horizontal = (t * t - (vertical - b) * (vertical - b)).sqrt();
            top_vertical = 2.0 * b - vertical;
            bottom_vertical = -vertical * b / (connecting - b);
        }
        Ovus {
            bottom,
            top,
            connecting,
            horizontal,
            vertical,
            bottom_vertical,
            top_vertical,
        }
    }

    /// The two crossings of the unit-direction ray `o + k·d` with a sphere, as POV-Ray finds
    /// them (none when the ray starts outside and points away).
    fn sphere(o: DVec3, d: DVec3, centre: DVec3, r: f64) -> Option<(f64, f64)> {
        let oc = centre - o;
        let (oc2, closest) = (oc.length_squared(), oc.dot(d));
        if oc2 < r * r || closest > EPSILON {
            let half2 = r * r - oc2 + closest * closest;
            if half2 > EPSILON {
                let half = half2.sqrt();
                return Some((closest - half, closest + half));
            }
        }
        None
    }

    /// Calls `f` with each crossing (distance, part) until it returns true (an any-hit query
    /// needs only one: the others, the spindle's quartic among them, are then not sought).
    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64, u32) -> bool) {
        let len = ray.direction.length();
        let (o, d) = (ray.origin, ray.direction / len);
        let mut hit = |k: f64, part: u32| {
            let t = k / len;
            k > EPSILON && t > DEPTH_TOLERANCE && ray.contains(t) && f(t, part)
        };
        let y = |k: f64| o.y + k * d.y;
        let mut below = 0;
        let lower = Self::sphere(o, d, DVec3::ZERO, self.bottom);
        if let Some((k1, k2)) = lower {
            below = usize::from(y(k1) < self.bottom_vertical)
                + usize::from(y(k2) < self.bottom_vertical);
            for k in [k1, k2] {
                if y(k) < self.bottom_vertical && hit(k, BOTTOM) {
                    return;
                }
            }
        }
        // (POV-Ray looks no further when both crossings are on the bottom sphere.)
        if below > 1 {
            return;
        }
        let mut above = below;
        if let Some((k3, k4)) = Self::sphere(o, d, DVec3::new(0.0, self.bottom, 0.0), self.top) {
            for k in [k3, k4] {
                if y(k) > self.top_vertical {
                    above += 1;
                    if hit(k, TOP) {
                        return;
                    }
                }
            }
        }
        if above > 1 {
            return;
        }
        // The band's points lie within (h + horizontal)² ≤ connecting² + tolerance of the
        // axis, h their distance from it: a ray whose line passes farther from the axis has
        // no root to keep, and its quartic is not solved (a margin covers the rounding).
        let (dh2, ph_dot) = (d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z);
        let nearest2 = if dh2 > 0.0 {
            o.x * o.x + o.z * o.z - ph_dot * ph_dot / dh2
        } else {
            o.x * o.x + o.z * o.z
        };
        let reach_h = (self.connecting * self.connecting + ROOT_TOLERANCE).sqrt() - self.horizontal;
        let margin = 1e-9 * (1.0 + self.connecting + self.horizontal + o.abs().max_element());
        if reach_h < 0.0 || nearest2.max(0.0).sqrt() > reach_h + margin {
            return;
        }
        // The spindle torus, formed about the ray's point nearest its centre.
        let centre = DVec3::new(0.0, self.vertical, 0.0);
        let line = ray.about(centre);
        let (shift, p) = (line.shift, line.origin - centre);
        let small2 = self.connecting * self.connecting;
        let spindle = super::Torus {
            major: self.horizontal,
            minor: self.connecting,
        };
        let c = spindle.quartic(p, d);
        // The roots worth seeking: within the band's sphere (its points lie within
        // `connecting` of its centre), between its heights, and ahead on the ray (with room
        // for rounding: every root found is tested again below).
        let room = 1e-9 * (self.connecting + self.horizontal + shift.abs());
        let half = (small2 - p.length_squared()).max(0.0).sqrt();
        let (mut lo, mut hi) = (-half - room, half + room);
        if d.y != 0.0 {
            let to = |y: f64| (y - centre.y - p.y) / d.y;
            let (a, b) = (to(self.bottom_vertical), to(self.top_vertical));
            lo = lo.max(a.min(b) - room);
            hi = hi.min(a.max(b) + room);
        }
        lo = lo.max(ray.tmin * len - shift - room);
        hi = hi.min(ray.tmax * len - shift + room);
        for &s in roots_in(&c, 4, lo, hi).as_slice() {
            let q = p + s * d + centre;
            if q.y > self.bottom_vertical && q.y < self.top_vertical {
                let h = (q.x * q.x + q.z * q.z).sqrt();
                let band = (h + self.horizontal).powi(2) + (q.y - self.vertical).powi(2);
                if (band - small2).abs() < ROOT_TOLERANCE && hit(s + shift, BAND) {
                    return;
                }
            }
        }
    }
}

impl super::shape::Surface for Ovus {
    const NAME: &'static str = "Ovus";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::nearest_of(|f| {
            self.crossings(ray, |t, part| {
                f(t, part);
                false
            })
        })
    }

    fn occludes(&self, ray: &Ray) -> bool {
        let mut any = false;
        self.crossings(ray, |_, _| {
            any = true;
            true
        });
        any
    }

    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        let n = match part {
            BOTTOM => p / self.bottom,
            TOP => (p - DVec3::new(0.0, self.bottom, 0.0)) / self.top,
            _ => {
                let h = (p.x * p.x + p.z * p.z).sqrt();
                let k = if h > 0.0 { self.horizontal / h } else { 0.0 };
                DVec3::new(p.x + p.x * k, p.y - self.vertical, p.z + p.z * k)
            }
        };
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        if p.length_squared() < self.bottom * self.bottom
            || (p - DVec3::new(0.0, self.bottom, 0.0)).length_squared() < self.top * self.top
        {
            return true;
        }
        if p.y > self.bottom_vertical && p.y < self.top_vertical {
            let h = (p.x * p.x + p.z * p.z).sqrt();
            return (h + self.horizontal).powi(2) + (p.y - self.vertical).powi(2)
                < self.connecting.powi(2);
        }
        false
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let r = self.bottom.max(self.top);
        Some((
            DVec3::new(-r, -self.bottom, -r),
            DVec3::new(r, self.bottom + self.top, r),
        ))
    }

    fn for_each_crossing(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        self.crossings(ray, |t, part| {
            f(t, part);
            false
        })
    }

    /// POV-Ray's ovus coordinates: those of a sphere around the point half the top radius up
    /// the axis.
    fn uv(&self, p: DVec3, _part: u32) -> Option<glam::DVec2> {
        let d = DVec3::new(p.x, p.y - self.top / 2.0, p.z);
        let len = d.length();
        if len == 0.0 {
            return Some(glam::DVec2::ZERO);
        }
        let d = d / len;
        Some(glam::DVec2::new(
            super::longitude(d.x, d.z),
            0.5 + d.y.asin() / std::f64::consts::PI,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// An egg of radii 1 and 0.6: down its axis it spans y = −1 to 1.6; sideways at the
    /// origin it is the bottom sphere; its surface is continuous where the parts meet.
    #[test]
    fn egg() {
        let e = Ovus::new(1.0, 0.6);
        let c = e.intersect(&Ray::new(DVec3::new(0.0, 5.0, 0.001), DVec3::NEG_Y));
        assert_eq!(c.len(), 2, "{:?}", c.as_slice());
        assert!((c.as_slice()[0] - 3.4).abs() < 1e-6 && (c.as_slice()[1] - 6.0).abs() < 1e-6);
        let c = e.intersect(&Ray::new(DVec3::new(-5.0, -0.5, 0.0), DVec3::X));
        assert!((c.first().unwrap() - (5.0 - 0.75f64.sqrt())).abs() < 1e-9);
        assert!(e.contains(DVec3::new(0.0, 0.8, 0.0)));
        assert!(!e.contains(DVec3::new(0.9, 1.2, 0.0)));
        // Horizontal rays at every height between the bottom and the top meet it once going in.
        for i in 1..26 {
            let y = -0.95 + i as f64 * 0.1;
            let c = e.intersect(&Ray::new(DVec3::new(-5.0, y, 0.0), DVec3::X));
            assert!(c.len() >= 2, "height {y}: {:?}", c.as_slice());
            let q = Ray::new(DVec3::new(-5.0, y, 0.0), DVec3::X).at(c.first().unwrap());
            assert!(q.x < 0.0 && q.x > -1.0001, "height {y}: {q}");
        }
    }
}
