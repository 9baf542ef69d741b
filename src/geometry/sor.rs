//! `sor`: a surface of revolution about y whose squared radius is a cubic in the height, piece
//! by piece (POV-Ray's Sor), with discs at the lowest and highest height unless `open`.

use super::poly::roots_in;
use super::{Crossings, Ray};
use glam::DVec3;

/// POV-Ray's tolerance for horizontal rays.
const EPSILON: f64 = 1e-10;

/// One piece: `r² = A y³ + B y² + C y + D` for y in [y1, y2], and its greatest radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SorPiece {
    /// `[A, B, C, D]`.
    pub c: [f64; 4],
    /// Lowest height.
    pub y1: f64,
    /// Highest height.
    pub y2: f64,
    radius: f64,
}

impl SorPiece {
    /// The piece with coefficients `c` over heights `y1 ≤ y2`.
    pub fn new(c: [f64; 4], y1: f64, y2: f64) -> SorPiece {
        let mut piece = SorPiece {
            c,
            y1,
            y2,
            radius: 0.0,
        };
        let d = [c[2], 2.0 * c[1], 3.0 * c[0], 0.0, 0.0, 0.0, 0.0];
        let turning = roots_in(&d, 2, y1, y2);
        let most = turning
            .as_slice()
            .iter()
            .chain(&[y1, y2])
            .map(|&y| piece.r2(y))
            .fold(0.0, f64::max);
        piece.radius = most.sqrt();
        piece
    }

    /// The squared radius at height `y`.
    fn r2(&self, y: f64) -> f64 {
        ((self.c[0] * y + self.c[1]) * y + self.c[2]) * y + self.c[3]
    }

    /// Its derivative.
    fn r2_slope(&self, y: f64) -> f64 {
        (3.0 * self.c[0] * y + 2.0 * self.c[1]) * y + self.c[2]
    }
}

/// A surface of revolution in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Sor {
    pieces: Box<[SorPiece]>,
    closed: bool,
    /// Squared radii of the base and cap discs.
    base2: f64,
    cap2: f64,
    radius: f64,
}

/// Part tags: the base disc, the cap disc, then one per piece.
const BASE: u32 = 0;
const CAP: u32 = 1;
const CURVE: u32 = 2;

impl Sor {
    /// A sor of pieces by increasing height, capped unless `!closed`.
    pub fn new(pieces: Vec<SorPiece>, closed: bool) -> Sor {
        let base2 = pieces.first().map_or(0.0, |p| p.r2(p.y1).max(0.0));
        let cap2 = pieces.last().map_or(0.0, |p| p.r2(p.y2).max(0.0));
        let radius = pieces.iter().map(|p| p.radius).fold(0.0, f64::max);
        Sor {
            pieces: pieces.into_boxed_slice(),
            closed,
            base2,
            cap2,
            radius,
        }
    }

    fn heights(&self) -> (f64, f64) {
        (
            self.pieces.first().map_or(0.0, |p| p.y1),
            self.pieces.last().map_or(0.0, |p| p.y2),
        )
    }

    fn crossings(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        if self.pieces.is_empty() {
            return;
        }
        // Distances k from the ray's point nearest the axis's middle.
        let (h1, h2) = self.heights();
        let line = ray.about(DVec3::new(0.0, 0.5 * (h1 + h2), 0.0));
        let (p, d, shift) = (line.origin, line.direction, line.shift);
        let mut hit = |k: f64, part: u32| {
            let t = line.t(k);
            if t > 1e-4 && ray.contains(t) {
                f(t, part);
            }
        };
        if self.closed && d.y.abs() > EPSILON {
            // Discs only when their radius exceeds 0.01 (POV-Ray's test on the square).
            for (h, r2, part) in [(h1, self.base2, BASE), (h2, self.cap2, CAP)] {
                if r2 > 1e-4 {
                    let k = (h - p.y) / d.y;
                    let (x, z) = (p.x + k * d.x, p.z + k * d.z);
                    if x * x + z * z <= r2 {
                        hit(k, part);
                    }
                }
            }
        }
        let a = d.x * d.x + d.z * d.z;
        let b = p.x * d.x + p.z * d.z;
        let rho2 = p.x * p.x + p.z * p.z;
        for (j, s) in self.pieces.iter().enumerate() {
            // The distances where the ray is inside the piece's cylinder and height range.
            let Some((lo, hi)) = span(p, d, s.radius, s.y1, s.y2, -shift) else {
                continue;
            };
            let [ca, cb, cc, _] = s.c;
            let (py, dy) = (p.y, d.y);
            // x² + z² = f(y) along the ray, as a cubic in the distance k.
            let c = [
                s.r2(py) - rho2,
                dy * (3.0 * ca * py * py + 2.0 * cb * py + cc) - 2.0 * b,
                dy * dy * (3.0 * ca * py + cb) - a,
                ca * dy * dy * dy,
                0.0,
                0.0,
                0.0,
            ];
            for &k in roots_in(&c, 3, lo, hi).as_slice() {
                let y = py + k * dy;
                if (s.y1..=s.y2).contains(&y) {
                    hit(k, CURVE + j as u32);
                }
            }
        }
    }
}

/// The distances along the ray (unit direction) within the box of radius `r` about the axis
/// between heights `y1` and `y2`, widened a little, from `start` on.
fn span(p: DVec3, d: DVec3, r: f64, y1: f64, y2: f64, start: f64) -> Option<(f64, f64)> {
    let pad = 1e-9 * (r + y2.abs() + y1.abs() + 1.0);
    let (lo, hi) = (DVec3::new(-r, y1, -r) - pad, DVec3::new(r, y2, r) + pad);
    let (mut enter, mut exit) = (f64::NEG_INFINITY, f64::INFINITY);
    for i in 0..3 {
        if d[i] == 0.0 {
            if p[i] < lo[i] || p[i] > hi[i] {
                return None;
            }
            continue;
        }
        let (a, b) = ((lo[i] - p[i]) / d[i], (hi[i] - p[i]) / d[i]);
        enter = enter.max(a.min(b));
        exit = exit.min(a.max(b));
    }
    (enter <= exit && exit > start).then_some((enter.max(start), exit))
}

impl super::shape::Surface for Sor {
    const NAME: &'static str = "Sor";

    fn intersect(&self, ray: &Ray) -> Crossings {
        Crossings::nearest_of(|f| self.crossings(ray, f))
    }

    /// The outward gradient of `x² + z² − f(y)`; the discs face down and up.
    fn normals(&self, p: DVec3, part: u32) -> (DVec3, DVec3) {
        let n = match part {
            BASE => DVec3::NEG_Y,
            CAP => DVec3::Y,
            _ => {
                let s = &self.pieces[(part - CURVE) as usize];
                DVec3::new(p.x, -0.5 * s.r2_slope(p.y), p.z)
            }
        };
        (n, n)
    }

    /// POV-Ray's test: within the heights, inside the first piece covering the height.
    fn contains(&self, p: DVec3) -> bool {
        let (h1, h2) = self.heights();
        let rho2 = p.x * p.x + p.z * p.z;
        if p.y < h1 || p.y > h2 || rho2 > self.radius * self.radius {
            return false;
        }
        self.pieces
            .iter()
            .find(|s| (s.y1..=s.y2).contains(&p.y))
            .is_some_and(|s| rho2 <= s.r2(p.y))
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        let (h1, h2) = self.heights();
        let r = self.radius;
        Some((DVec3::new(-r, h1, -r), DVec3::new(r, h2, r)))
    }

    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        self.crossings(ray, f)
    }

    /// POV-Ray's sor coordinates: u the longitude; v up the pieces (each an equal share of
    /// 0 to 1, by height within it), and on the base and cap discs by the distance from the
    /// axis (−1 to 0 and 1 to 2).
    fn uv(&self, p: DVec3, part: u32) -> Option<glam::DVec2> {
        let u = super::longitude(p.x, p.z);
        let rho = (p.x * p.x + p.z * p.z).sqrt();
        let n = self.pieces.len() as f64;
        let v = match part {
            BASE => rho / self.base2.sqrt() - 1.0,
            CAP => -rho / self.cap2.sqrt() + 2.0,
            _ => {
                let i = (part - CURVE) as usize;
                let s = &self.pieces[i];
                (p.y - s.y1) / (s.y2 - s.y1) / n + i as f64 / n
            }
        };
        Some(glam::DVec2::new(u, v))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// A cylinder of radius 1 between y = 0 and 2 (r² = 1), capped.
    fn can(closed: bool) -> Sor {
        Sor::new(vec![SorPiece::new([0.0, 0.0, 0.0, 1.0], 0.0, 2.0)], closed)
    }

    #[test]
    fn curve_and_discs() {
        let s = can(true);
        let c = s.intersect(&Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X));
        assert_eq!(c.len(), 2);
        assert!((c.as_slice()[0] - 4.0).abs() < 1e-12 && (c.as_slice()[1] - 6.0).abs() < 1e-12);
        let (n, _) = s.normals(DVec3::new(-1.0, 1.0, 0.0), c.parts()[0]);
        assert_eq!(n, DVec3::NEG_X);
        let c = s.intersect(&Ray::new(DVec3::new(0.2, 5.0, 0.0), DVec3::NEG_Y));
        assert_eq!(c.as_slice(), &[3.0, 5.0]);
        assert_eq!(c.parts(), &[CAP, BASE]);
        assert!(
            can(false)
                .intersect(&Ray::new(DVec3::new(0.2, 5.0, 0.0), DVec3::NEG_Y))
                .is_empty()
        );
        assert!(s.contains(DVec3::new(0.5, 1.0, 0.5)));
        assert!(!s.contains(DVec3::new(0.9, 1.0, 0.9)));
        assert!(!s.contains(DVec3::new(0.0, 2.5, 0.0)));
    }

    /// A cone r = y (r² = y²) from y = 0.5 to 1.5: an oblique ray's crossings lie on it.
    #[test]
    fn cubic_in_distance() {
        let s = Sor::new(vec![SorPiece::new([0.0, 1.0, 0.0, 0.0], 0.5, 1.5)], false);
        let ray = Ray::new(DVec3::new(-3.0, 0.6, 0.1), DVec3::new(1.0, 0.15, 0.0));
        let c = s.intersect(&ray);
        assert_eq!(c.len(), 2, "{:?}", c.as_slice());
        for &t in c.as_slice() {
            let q = ray.at(t);
            assert!(((q.x * q.x + q.z * q.z).sqrt() - q.y).abs() < 1e-9);
        }
    }
}
