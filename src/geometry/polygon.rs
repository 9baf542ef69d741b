//! `polygon { N, P1, …, PN }`: flat polygons (several, each closed by repeating its first
//! point) in the plane of the points, inside by the even-odd rule (POV-Ray's Polygon).

use super::{Crossings, Ray};
use glam::DVec3;

/// Below this a coordinate is zero (POV-Ray's `ZERO_TOLERANCE`).
const ZERO_TOLERANCE: f64 = 1e-10;

/// A polygon in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    /// The plane's frame: origin (the first point) and unit axes u, v in the plane, w along
    /// its normal.
    origin: DVec3,
    u: DVec3,
    v: DVec3,
    w: DVec3,
    /// The points in (u, v) coordinates, sub-polygons closed by repeating their first point.
    points: Box<[[f64; 2]]>,
    /// The box of the points.
    bounds: (DVec3, DVec3),
}

impl Polygon {
    /// The polygon through `points` (closed sub-polygons); one that no ray hits when they are
    /// collinear or not in one plane (POV-Ray ignores such a polygon).
    pub fn new(points: &[DVec3]) -> Polygon {
        Polygon::flat(points).unwrap_or(Polygon {
            origin: DVec3::ZERO,
            u: DVec3::X,
            v: DVec3::Y,
            w: DVec3::Z,
            points: Box::new([]),
            bounds: (DVec3::ZERO, DVec3::ZERO),
        })
    }

    /// The polygon if its points lie in a plane they span.
    fn flat(points: &[DVec3]) -> Option<Polygon> {
        let o = *points.first()?;
        // POV-Ray's frame: the first edge not of zero length, the first later point off its
        // line, then u = v × w, v = w × u.
        let mut rest = points[1..].iter().map(|p| *p - o);
        let u0 = rest.find(|u| u.length_squared() > 1e-10)?;
        let (v0, w) = rest
            .map(|v| (v, u0.cross(v)))
            .find(|(v, w)| v.length_squared() > 1e-10 && w.length_squared() > 1e-10)?;
        let u = v0.cross(w);
        let v = w.cross(u);
        let (u, v, w) = (u.normalize(), v.normalize(), w.normalize());
        let mut flat = Vec::with_capacity(points.len());
        for p in points {
            let d = *p - o;
            if d.dot(w).abs() > ZERO_TOLERANCE {
                return None;
            }
            flat.push([d.dot(u), d.dot(v)]);
        }
        let (lo, hi) = points.iter().fold(
            (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        Some(Polygon {
            origin: o,
            u,
            v,
            w,
            points: flat.into_boxed_slice(),
            bounds: (lo, hi),
        })
    }

    /// POV-Ray's even-odd test of plane point (x, y), sub-polygon by sub-polygon.
    fn inside(&self, x: f64, y: f64) -> bool {
        let p = &self.points;
        let n = p.len();
        if n < 2 {
            return false;
        }
        let (mut v0, mut first) = (p[0], p[0]);
        let mut above0 = v0[1] >= y;
        let mut inside = false;
        let mut i = 1;
        while i < n {
            let v1 = p[i];
            let above1 = v1[1] >= y;
            if above0 != above1
                && (((v1[1] - y) * (v0[0] - v1[0]) >= (v1[0] - x) * (v0[1] - v1[1])) == above1)
            {
                inside = !inside;
            }
            if i + 2 < n && v1 == first {
                // A sub-polygon closed: the next starts after it.
                v0 = p[i + 1];
                first = v0;
                above0 = v0[1] >= y;
                i += 2;
            } else {
                v0 = v1;
                above0 = above1;
                i += 1;
            }
        }
        inside
    }
}

impl super::shape::Surface for Polygon {
    const NAME: &'static str = "Polygon";

    fn intersect(&self, ray: &Ray) -> Crossings {
        let rel = ray.origin - self.origin;
        let (pz, dz) = (rel.dot(self.w), ray.direction.dot(self.w));
        if (dz / ray.direction.length()).abs() < ZERO_TOLERANCE {
            return Crossings::NONE;
        }
        let t = -pz / dz;
        let q = rel + t * ray.direction;
        if self.inside(q.dot(self.u), q.dot(self.v)) {
            Crossings::within(ray, &[t])
        } else {
            Crossings::NONE
        }
    }

    fn normals(&self, _p: DVec3, _part: u32) -> (DVec3, DVec3) {
        (self.w, self.w)
    }

    fn contains(&self, _p: DVec3) -> bool {
        // (A polygon has no inside.)
        false
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some(self.bounds)
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    fn square_with_hole() -> Polygon {
        let p = |x: f64, y: f64| DVec3::new(x, y, 0.0);
        Polygon::new(&[
            p(0.0, 0.0),
            p(4.0, 0.0),
            p(4.0, 4.0),
            p(0.0, 4.0),
            p(0.0, 0.0),
            p(1.0, 1.0),
            p(3.0, 1.0),
            p(3.0, 3.0),
            p(1.0, 3.0),
            p(1.0, 1.0),
        ])
    }

    #[test]
    fn a_square_with_a_hole_is_hit_on_its_ring_only() {
        let s = square_with_hole();
        let down = |x: f64, y: f64| Ray::new(DVec3::new(x, y, -5.0), DVec3::Z);
        assert_eq!(s.intersect(&down(0.5, 0.5)).as_slice(), &[5.0]);
        assert!(s.intersect(&down(2.0, 2.0)).is_empty(), "the hole");
        assert!(s.intersect(&down(5.0, 2.0)).is_empty(), "outside");
        assert!(
            s.intersect(&Ray::new(DVec3::new(-1.0, 2.0, 0.0), DVec3::X))
                .is_empty()
        );
        assert_eq!(s.normals(DVec3::ZERO, 0).0.abs(), DVec3::Z);
        // Collinear or not flat: never hit.
        let z = Ray::new(DVec3::new(0.2, 0.1, -5.0), DVec3::Z);
        assert!(
            Polygon::new(&[DVec3::ZERO, DVec3::X, 2.0 * DVec3::X, DVec3::ZERO])
                .intersect(&z)
                .is_empty()
        );
        let bent = [DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z, DVec3::ZERO];
        assert!(Polygon::new(&bent).intersect(&z).is_empty());
    }
}
