//! `blob`: the surface where a sum of fields reaches the threshold (POV-Ray's Blob). Each
//! component adds `S (1 − r²/R²)²` within its radius R of a point (a sphere, or an ellipsoid
//! when the component is transformed) or of a segment (a cylinder with two half-sphere ends).
//!
//! Along a ray each field is a quartic in the distance wherever it acts; between the
//! distances where components start or stop acting the sum is one quartic, solved there.

use super::poly::roots_in;
use super::{Crossings, Ray};
use glam::{DMat3, DMat4, DVec3};
use std::cell::RefCell;

/// POV-Ray's shortest hit distance for blobs.
const DEPTH_TOLERANCE: f64 = 0.01;
/// POV-Ray's margin of the inside test.
const INSIDE_TOLERANCE: f64 = 1e-6;

/// Where a component's field acts, in the component's own space.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Reach {
    /// Within the radius of `centre`.
    Sphere(DVec3),
    /// Within the radius of the z axis, for 0 ≤ z ≤ length.
    Cylinder(f64),
    /// Within the radius of the origin, for z ≤ 0 (a cylinder's base end).
    Base,
    /// Within the radius of (0, 0, length), for z ≥ length (a cylinder's far end).
    Apex(f64),
}

/// One field of the sum.
#[derive(Clone, Debug, PartialEq)]
pub struct BlobElement {
    reach: Reach,
    /// Squared radius.
    r2: f64,
    /// Strength.
    strength: f64,
    /// Blob space to the element's space (`None`: the same).
    to_local: Option<DMat4>,
    /// The element's normals back to blob space.
    normal_to_blob: DMat3,
}

/// A ray's line as one element sees it: the interval `lo..hi` of distances where the
/// element's field acts, and the offset `v` from the field's centre (point or axis) at the
/// line's origin with its change `w` per unit distance.
#[derive(Clone, Copy, Debug)]
struct Along {
    lo: f64,
    hi: f64,
    v: DVec3,
    w: DVec3,
}

impl BlobElement {
    /// A sphere component (`transform`: the component's own transformations).
    pub fn sphere(
        centre: DVec3,
        radius: f64,
        strength: f64,
        transform: Option<DMat4>,
    ) -> BlobElement {
        BlobElement::new(Reach::Sphere(centre), radius, strength, transform)
    }

    /// The three elements of a cylinder component from `a` to `b`: body and both ends.
    pub fn cylinder(
        a: DVec3,
        b: DVec3,
        radius: f64,
        strength: f64,
        transform: Option<DMat4>,
    ) -> [BlobElement; 3] {
        let axis = b - a;
        let length = axis.length();
        let w = axis / length;
        let u = w.any_orthonormal_vector();
        let v = w.cross(u);
        let frame = DMat4::from_cols(u.extend(0.0), v.extend(0.0), w.extend(0.0), a.extend(1.0));
        let m = Some(transform.unwrap_or(DMat4::IDENTITY) * frame);
        [
            BlobElement::new(Reach::Cylinder(length), radius, strength, m),
            BlobElement::new(Reach::Base, radius, strength, m),
            BlobElement::new(Reach::Apex(length), radius, strength, m),
        ]
    }

    fn new(reach: Reach, radius: f64, strength: f64, transform: Option<DMat4>) -> BlobElement {
        BlobElement {
            reach,
            r2: radius * radius,
            strength,
            to_local: transform.map(|m| m.inverse()),
            normal_to_blob: transform.map_or(DMat3::IDENTITY, |m| {
                DMat3::from_mat4(m).inverse().transpose()
            }),
        }
    }

    fn local(&self, p: DVec3) -> DVec3 {
        self.to_local.map_or(p, |m| m.transform_point3(p))
    }

    /// The vector from the field's centre (point or axis) to local point `p`, if the field
    /// acts there.
    fn offset(&self, p: DVec3) -> Option<DVec3> {
        let v = match self.reach {
            Reach::Sphere(c) => p - c,
            Reach::Cylinder(len) => {
                if p.z < 0.0 || p.z > len {
                    return None;
                }
                DVec3::new(p.x, p.y, 0.0)
            }
            Reach::Base => {
                if p.z > 0.0 {
                    return None;
                }
                p
            }
            Reach::Apex(len) => {
                if p.z < len {
                    return None;
                }
                p - DVec3::new(0.0, 0.0, len)
            }
        };
        (v.length_squared() <= self.r2).then_some(v)
    }

    /// The field at blob-space point `p`.
    pub fn density(&self, p: DVec3) -> f64 {
        match self.offset(self.local(p)) {
            Some(v) if v.length_squared() < self.r2 => {
                let k = 1.0 - v.length_squared() / self.r2;
                self.strength * k * k
            }
            _ => 0.0,
        }
    }

    /// Along `o + s·d` (blob space): the interval of s where the field acts, and the line in
    /// the element's frame ([`Along`]), from which [`BlobElement::quartic`] forms the field.
    fn along(&self, o: DVec3, d: DVec3) -> Option<Along> {
        let (a, b) = match self.to_local {
            Some(m) => (m.transform_point3(o), m.transform_vector3(d)),
            None => (o, d),
        };
        // r²(t) = q2 t² + q1 t + q0 and the interval where r² < R².
        let (centre, flat) = match self.reach {
            Reach::Sphere(c) => (c, false),
            Reach::Cylinder(_) => (DVec3::ZERO, true),
            Reach::Base => (DVec3::ZERO, false),
            Reach::Apex(len) => (DVec3::new(0.0, 0.0, len), false),
        };
        let (mut v, mut w) = (a - centre, b);
        if flat {
            v.z = 0.0;
            w.z = 0.0;
        }
        let (q2, q1, q0) = (w.dot(w), 2.0 * v.dot(w), v.dot(v));
        if q2 <= 0.0 {
            return None;
        }
        let disc = q1 * q1 - 4.0 * q2 * (q0 - self.r2);
        if disc <= 0.0 {
            return None;
        }
        let root = disc.sqrt();
        let (mut lo, mut hi) = ((-q1 - root) / (2.0 * q2), (-q1 + root) / (2.0 * q2));
        // The z range where this part of a cylinder acts.
        let (zlo, zhi) = match self.reach {
            Reach::Sphere(_) => (f64::NEG_INFINITY, f64::INFINITY),
            Reach::Cylinder(len) => (0.0, len),
            Reach::Base => (f64::NEG_INFINITY, 0.0),
            Reach::Apex(len) => (len, f64::INFINITY),
        };
        if b.z != 0.0 {
            let (t0, t1) = ((zlo - a.z) / b.z, (zhi - a.z) / b.z);
            lo = lo.max(t0.min(t1));
            hi = hi.min(t0.max(t1));
        } else if a.z < zlo || a.z > zhi {
            return None;
        }
        (lo < hi).then_some(Along { lo, hi, v, w })
    }

    /// The field along the line `along` describes, as a quartic in the distance from the
    /// point `by` further along it than its origin (lowest power first): the offset is moved
    /// there before it is squared, so no precision is lost to a distant origin.
    fn quartic(&self, along: &Along, by: f64) -> [f64; 5] {
        let (v, w) = (along.v + by * along.w, along.w);
        let (q2, q1, q0) = (w.dot(w), 2.0 * v.dot(w), v.dot(v));
        let c0 = self.strength / (self.r2 * self.r2);
        let c1 = -2.0 * self.strength / self.r2;
        let c2 = self.strength;
        [
            c0 * q0 * q0 + c1 * q0 + c2,
            c0 * 2.0 * q0 * q1 + c1 * q1,
            c0 * (q1 * q1 + 2.0 * q0 * q2) + c1 * q2,
            c0 * 2.0 * q1 * q2,
            c0 * q2 * q2,
        ]
    }

    /// The element's box in blob space (its reach).
    fn bounds(&self) -> (DVec3, DVec3) {
        let r = self.r2.sqrt();
        let (lo, hi) = match self.reach {
            Reach::Sphere(c) => (c - r, c + r),
            Reach::Cylinder(len) => (DVec3::new(-r, -r, 0.0), DVec3::new(r, r, len)),
            Reach::Base => (DVec3::splat(-r), DVec3::new(r, r, 0.0)),
            Reach::Apex(len) => (DVec3::new(-r, -r, len), DVec3::new(r, r, len + r)),
        };
        let Some(to_local) = self.to_local else {
            return (lo, hi);
        };
        let m = to_local.inverse();
        (0..8).fold((DVec3::INFINITY, DVec3::NEG_INFINITY), |(a, b), i| {
            let corner = DVec3::new(
                if i & 1 == 0 { lo.x } else { hi.x },
                if i & 2 == 0 { lo.y } else { hi.y },
                if i & 4 == 0 { lo.z } else { hi.z },
            );
            let p = m.transform_point3(corner);
            (a.min(p), b.max(p))
        })
    }
}

/// A blob in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Blob {
    threshold: f64,
    elements: Box<[BlobElement]>,
    bounds: (DVec3, DVec3),
}

/// Per-thread room for a ray's work, so that no ray allocates.
#[derive(Default)]
struct Scratch {
    /// The lines of the elements whose fields the ray meets, with their indices.
    lines: Vec<(u32, Along)>,
    /// Their quartics.
    polys: Vec<[f64; 5]>,
    /// Where each starts (2i) and stops (2i + 1) acting.
    events: Vec<(f64, u32)>,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

impl Blob {
    /// A blob of `elements` whose surface is where their sum equals `threshold`.
    pub fn new(threshold: f64, elements: Vec<BlobElement>) -> Blob {
        // POV-Ray's box counts only the components that add to the field.
        let bounds = elements
            .iter()
            .filter(|e| e.strength > 0.0)
            .map(BlobElement::bounds)
            .fold(
                (DVec3::INFINITY, DVec3::NEG_INFINITY),
                |(a, b), (lo, hi)| (a.min(lo), b.max(hi)),
            );
        let bounds = if bounds.0.x > bounds.1.x {
            (DVec3::ZERO, DVec3::ZERO)
        } else {
            bounds
        };
        Blob {
            threshold,
            elements: elements.into_boxed_slice(),
            bounds,
        }
    }

    fn field(&self, p: DVec3) -> f64 {
        self.elements.iter().map(|e| e.density(p)).sum()
    }

    /// Calls `f` with the crossings in increasing distance until it returns false.
    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64) -> bool) {
        SCRATCH.with_borrow_mut(|scratch| {
            let Scratch {
                lines,
                polys,
                events,
            } = scratch;
            events.clear();
            polys.clear();
            lines.clear();
            // The lines are first seen from where the ray enters the blob's box (or from
            // its origin if that is inside), so that a far ray origin costs no precision.
            let d = ray.direction;
            let entry = box_entry(ray.origin, d, self.bounds).max(0.0);
            let origin = ray.origin + entry * d;
            let lowest = ray.tmin.max(DEPTH_TOLERANCE);
            let (mut first, mut last) = (f64::INFINITY, f64::NEG_INFINITY);
            for (k, e) in self.elements.iter().enumerate() {
                if let Some(line) = e.along(origin, d) {
                    if line.hi + entry <= lowest || line.lo + entry >= ray.tmax {
                        continue;
                    }
                    first = first.min(line.lo);
                    last = last.max(line.hi);
                    lines.push((k as u32, line));
                }
            }
            // The quartics are formed about the point of the ray nearest the box's centre
            // where that lies where the fields act (the roots of a grazing pair are then
            // near it), else about the nearer end of that stretch: a tube 5000 long seen
            // across near one end is met far from the box's centre.
            let centre = 0.5 * (self.bounds.0 + self.bounds.1);
            let nearest = (centre - origin).dot(d) / d.length_squared();
            let by = nearest.clamp(first, last.max(first));
            let shift = entry + by;
            for (k, line) in lines.iter() {
                let e = &self.elements[*k as usize];
                let i = polys.len() as u32;
                polys.push(e.quartic(line, by));
                // Entries as 2i, exits as 2i + 1: at equal distances exits go first.
                events.push((line.lo + entry, 2 * i));
                events.push((line.hi + entry, 2 * i + 1));
            }
            if events.is_empty() {
                return;
            }
            events.sort_by(|a, b| a.0.total_cmp(&b.0).then((b.1 & 1).cmp(&(a.1 & 1))));
            let mut sum = [-self.threshold, 0.0, 0.0, 0.0, 0.0];
            let mut active = 0usize;
            for k in 0..events.len() {
                let (t, id) = events[k];
                let poly = &polys[(id / 2) as usize];
                let sign = if id & 1 == 0 { 1.0 } else { -1.0 };
                for (s, c) in sum.iter_mut().zip(poly) {
                    *s += sign * c;
                }
                if id & 1 == 0 {
                    active += 1;
                } else {
                    active -= 1;
                }
                let Some(&(next, _)) = events.get(k + 1) else {
                    break;
                };
                if active == 0 || next - t < 1e-10 {
                    continue;
                }
                let (lo, hi) = (t.max(lowest), next.min(ray.tmax));
                if lo > hi {
                    continue;
                }
                let c = [sum[0], sum[1], sum[2], sum[3], sum[4], 0.0, 0.0];
                for &root in roots_in(&c, 4, lo - shift, hi - shift).as_slice() {
                    let t = root + shift;
                    if t > lowest && ray.contains(t) && !f(t) {
                        return;
                    }
                }
            }
        });
    }
}

/// Where the line `o + t·d` enters the box `(lo, hi)` (its t; negative when `o` is inside or
/// past the box; 0 when the line misses it).
fn box_entry(o: DVec3, d: DVec3, (lo, hi): (DVec3, DVec3)) -> f64 {
    let inv = d.recip();
    let (t0, t1) = ((lo - o) * inv, (hi - o) * inv);
    let near = t0.min(t1);
    let (enter, exit) = (near.max_element(), t0.max(t1).min_element());
    if enter.is_finite() && enter <= exit {
        enter
    } else {
        0.0
    }
}

impl super::shape::Surface for Blob {
    const NAME: &'static str = "Blob";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::first_of(|f| self.crossings(ray, f))
    }

    /// −½ of the field's gradient: outward where the fields add.
    fn normals(&self, p: DVec3, _: u32) -> (DVec3, DVec3) {
        let mut g = DVec3::ZERO;
        for e in self.elements.iter() {
            if let Some(v) = e.offset(e.local(p)) {
                let k = 2.0 * e.strength / e.r2 * (1.0 - v.length_squared() / e.r2);
                g += e.normal_to_blob * (k * v);
            }
        }
        let n = if g == DVec3::ZERO { DVec3::X } else { g };
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        self.field(p) > self.threshold - INSIDE_TOLERANCE
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some(self.bounds)
    }

    fn for_each_crossing(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        self.crossings(ray, |t| {
            f(t, 0);
            true
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// One sphere component of radius 1 and strength 1 with threshold 0.25: the surface is
    /// where (1 − r²)² = 0.25, r = √0.5.
    #[test]
    fn single_sphere() {
        let b = Blob::new(0.25, vec![BlobElement::sphere(DVec3::ZERO, 1.0, 1.0, None)]);
        let c = b.intersect(&Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X));
        let r = 0.5f64.sqrt();
        assert!(
            (c.first().unwrap() - (5.0 - r)).abs() < 1e-9,
            "{:?}",
            c.as_slice()
        );
        let mut all = Vec::new();
        b.for_each_crossing(&Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X), |t, _| {
            all.push(t)
        });
        assert_eq!(all.len(), 2);
        assert!(b.contains(DVec3::new(0.5, 0.0, 0.0)));
        assert!(!b.contains(DVec3::new(0.8, 0.0, 0.0)));
        let (n, _) = b.normals(DVec3::new(-r, 0.0, 0.0), 0);
        assert!(n.normalize().dot(DVec3::NEG_X) > 0.9999);
        assert!(
            b.intersect(&Ray::new(DVec3::new(-5.0, 0.9, 0.0), DVec3::X))
                .is_empty()
        );
    }

    /// Two spheres that merge: a ray along their axis crosses the joined surface twice.
    #[test]
    fn merging_spheres_and_a_negative_one() {
        let two = vec![
            BlobElement::sphere(DVec3::new(-0.5, 0.0, 0.0), 1.0, 1.0, None),
            BlobElement::sphere(DVec3::new(0.5, 0.0, 0.0), 1.0, 1.0, None),
        ];
        let b = Blob::new(0.5, two.clone());
        let mut all = Vec::new();
        b.for_each_crossing(&Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X), |t, _| {
            all.push(t)
        });
        assert_eq!(all.len(), 2, "{all:?}");
        assert!(b.contains(DVec3::ZERO));
        // A negative component at the middle cuts them apart.
        let mut cut = two;
        cut.push(BlobElement::sphere(DVec3::ZERO, 0.6, -2.0, None));
        let b = Blob::new(0.5, cut);
        let mut all = Vec::new();
        b.for_each_crossing(&Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X), |t, _| {
            all.push(t)
        });
        assert_eq!(all.len(), 4, "{all:?}");
        assert!(!b.contains(DVec3::ZERO));
    }

    /// A cylinder component: the surface is a capsule around its segment.
    #[test]
    fn cylinder_component() {
        let parts = BlobElement::cylinder(DVec3::ZERO, DVec3::new(0.0, 2.0, 0.0), 1.0, 1.0, None);
        let b = Blob::new(0.25, parts.into_iter().collect());
        let r = 0.5f64.sqrt();
        let c = b.intersect(&Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X));
        assert!((c.first().unwrap() - (5.0 - r)).abs() < 1e-9);
        // Down the axis: the far end's half sphere.
        let c = b.intersect(&Ray::new(DVec3::new(0.0, 5.0, 0.0), DVec3::NEG_Y));
        assert!(
            (c.first().unwrap() - (3.0 - r)).abs() < 1e-9,
            "{:?}",
            c.as_slice()
        );
        // A transformed (stretched) sphere component is an ellipsoid.
        let m = DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0));
        let b = Blob::new(
            0.25,
            vec![BlobElement::sphere(DVec3::ZERO, 1.0, 1.0, Some(m))],
        );
        let c = b.intersect(&Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X));
        assert!((c.first().unwrap() - (5.0 - 2.0 * r)).abs() < 1e-9);
    }

    #[test]
    fn a_thin_tube_thousands_long_is_hit_where_it_is() {
        // Strength 1, threshold 0.25: the surface lies at r = R·√½ from the axis. A tube of
        // radius 0.2 and length 5000 seen across near its top end (the box's centre is 2500
        // away: the polynomials must not be formed about it).
        let top = DVec3::new(0.0, 0.0, 0.0);
        let parts = BlobElement::cylinder(top, DVec3::new(0.0, -5000.0, 0.0), 0.2, 1.0, None);
        let b = Blob::new(0.25, parts.into_iter().collect());
        let r = 0.2 * 0.5f64.sqrt();
        for k in 0..200 {
            let y = -0.1 - 0.05 * f64::from(k);
            let d = DVec3::new(1.0, 0.01 * f64::from(k % 7), 0.3).normalize();
            let origin = DVec3::new(0.0, y, 0.0) - 3.0 * d;
            let c = b.intersect(&Ray::new(origin, d));
            let t = c.first().expect("the ray meets the tube");
            // Where the ray is r from the axis (the y axis), on the way in.
            let p = origin + d * t;
            assert!(
                (p.x.hypot(p.z) - r).abs() < 1e-7,
                "ray {k}: hit {p} is {} from the axis",
                p.x.hypot(p.z)
            );
        }
    }
}
