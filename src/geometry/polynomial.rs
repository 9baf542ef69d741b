//! `cubic`, `quartic` and `poly` (degree ≤ 6): the points where a polynomial in x, y, z is 0,
//! inside where it is negative (POV-Ray's Poly). Along a ray the polynomial is one in t, whose
//! roots come from the same isolating solver as the torus's.

use super::poly::{Poly, roots_in};
use super::{Crossings, Ray};
use glam::DVec3;

/// The farthest distance searched along a ray (POV-Ray's `MAX_DISTANCE`).
const MAX_DISTANCE: f64 = 1e7;

/// POV-Ray's tolerances for polynomials: crossings nearer than this (in object space) are the
/// surface the ray starts on, whose root the polynomial's rounding cannot place exactly (a
/// smaller bound shows acne), and points below this value are inside.
const DEPTH_TOLERANCE: f64 = 1e-4;
const INSIDE_TOLERANCE: f64 = 1e-4;

/// A polynomial surface.
#[derive(Clone, Debug, PartialEq)]
pub struct Polynomial {
    /// The degree (2 to 6).
    pub degree: u8,
    /// Its non-zero terms: coefficient and the powers of x, y and z.
    pub terms: Box<[(f64, [u8; 3])]>,
}

impl Polynomial {
    /// The value at `p`.
    pub fn value(&self, p: DVec3) -> f64 {
        self.terms
            .iter()
            .map(|(c, [i, j, k])| {
                c * p.x.powi(*i as i32) * p.y.powi(*j as i32) * p.z.powi(*k as i32)
            })
            .sum()
    }

    /// The coefficients in s of the polynomial along `o + s·d`.
    fn along(&self, o: DVec3, d: DVec3) -> Poly {
        // (Made for each degree, so that the powers' loops unroll.)
        match self.degree {
            0..=2 => self.along_to::<2>(o, d),
            3 => self.along_to::<3>(o, d),
            4 => self.along_to::<4>(o, d),
            5 => self.along_to::<5>(o, d),
            _ => self.along_to::<6>(o, d),
        }
    }

    /// `along` for a polynomial of degree at most `D`.
    fn along_to<const D: usize>(&self, o: DVec3, d: DVec3) -> Poly {
        // Powers n ≤ D of each coordinate's linear polynomial a + b·s: row n holds the
        // coefficients of s⁰ … sⁿ (those above are 0).
        let powers = |a: f64, b: f64| {
            let mut p = [[0.0; 7]; 7];
            p[0][0] = 1.0;
            for n in 1..=D {
                p[n][n] = p[n - 1][n - 1] * b;
                for m in (1..n).rev() {
                    p[n][m] = p[n - 1][m] * a + p[n - 1][m - 1] * b;
                }
                p[n][0] = p[n - 1][0] * a;
            }
            p
        };
        let (px, py, pz) = (powers(o.x, d.x), powers(o.y, d.y), powers(o.z, d.z));
        let mut out = [0.0; 7];
        for &(c, [i, j, k]) in self.terms.iter() {
            let (i, j, k) = (i as usize, j as usize, k as usize);
            let (a, b, e) = (&px[i][..=i], &py[j][..=j], &pz[k][..=k]);
            for (u, &au) in a.iter().enumerate().filter(|(_, v)| **v != 0.0) {
                for (v, &bv) in b.iter().enumerate().filter(|(_, v)| **v != 0.0) {
                    let cab = c * au * bv;
                    for (w, &ew) in e.iter().enumerate() {
                        out[u + v + w] += cab * ew;
                    }
                }
            }
        }
        out
    }
}

impl super::shape::Surface for Polynomial {
    const NAME: &'static str = "Polynomial";

    fn intersect(&self, ray: &Ray) -> Crossings {
        let length = ray.direction.length();
        let d = ray.direction / length;
        let c = self.along(ray.origin, d);
        let lo = (ray.tmin * length).max(DEPTH_TOLERANCE);
        let hi = (ray.tmax * length).min(MAX_DISTANCE);
        let roots = roots_in(&c, self.degree as usize, lo, hi);
        let mut out = Crossings::NONE;
        for &s in roots.as_slice() {
            let t = s / length;
            if ray.contains(t) {
                out.push(t, 0);
            }
        }
        out
    }

    fn normals(&self, p: DVec3, _part: u32) -> (DVec3, DVec3) {
        let mut n = DVec3::ZERO;
        for (c, [i, j, k]) in self.terms.iter() {
            let (i, j, k) = (*i as i32, *j as i32, *k as i32);
            let (x, y, z) = (p.x, p.y, p.z);
            if i > 0 {
                n.x += c * i as f64 * x.powi(i - 1) * y.powi(j) * z.powi(k);
            }
            if j > 0 {
                n.y += c * j as f64 * x.powi(i) * y.powi(j - 1) * z.powi(k);
            }
            if k > 0 {
                n.z += c * k as f64 * x.powi(i) * y.powi(j) * z.powi(k - 1);
            }
        }
        let n = if n == DVec3::ZERO { DVec3::X } else { n };
        (n, n)
    }

    fn contains(&self, p: DVec3) -> bool {
        self.value(p) < INSIDE_TOLERANCE
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        // (Unbounded, as POV-Ray leaves a polynomial without bounded_by.)
        None
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// A quartic of the given terms ((x, y, z powers), coefficient).
    fn quartic(set: &[([u8; 3], f64)]) -> Polynomial {
        Polynomial {
            degree: 4,
            terms: set.iter().map(|(p, c)| (*c, *p)).collect(),
        }
    }

    #[test]
    fn a_quartic_sphere_and_a_torus_are_hit_where_they_are() {
        // (x² + y² + z²)², whose terms both surfaces start with.
        let r4 = [
            ([4, 0, 0], 1.0),
            ([0, 4, 0], 1.0),
            ([0, 0, 4], 1.0),
            ([2, 2, 0], 2.0),
            ([2, 0, 2], 2.0),
            ([0, 2, 2], 2.0),
        ];
        // (x² + y² + z²)² − 1 = 0: the unit sphere again.
        let s = quartic(&[&r4[..], &[([0, 0, 0], -1.0)]].concat());
        let r = Ray::new(DVec3::new(0.0, 0.6, -4.0), DVec3::new(0.0, 0.0, 2.0));
        let c = s.intersect(&r);
        assert_eq!(c.as_slice().len(), 2);
        assert!(
            (c.as_slice()[0] - (4.0 - 0.8) / 2.0).abs() < 1e-12,
            "{:?}",
            c.as_slice()
        );
        assert!((c.as_slice()[1] - (4.0 + 0.8) / 2.0).abs() < 1e-12);
        let p = r.at(c.as_slice()[0]);
        assert!((s.normals(p, 0).0.normalize() - p).length() < 1e-9);
        assert!(s.contains(DVec3::splat(0.5)) && !s.contains(DVec3::ONE));
        assert!(
            s.intersect(&Ray::new(DVec3::new(2.0, 0.0, -4.0), DVec3::Z))
                .is_empty()
        );
        // The torus R = 1, r = 0.25: (x² + y² + z² + R² − r²)² − 4R²(x² + z²); a ray along x
        // through the centre crosses it four times, at ±0.75 and ±1.25.
        let k = 1.0 - 0.0625;
        let rest = [
            ([2, 0, 0], 2.0 * k - 4.0),
            ([0, 2, 0], 2.0 * k),
            ([0, 0, 2], 2.0 * k - 4.0),
            ([0, 0, 0], k * k),
        ];
        let t = quartic(&[&r4[..], &rest[..]].concat());
        let c = t.intersect(&Ray::new(DVec3::new(-3.0, 0.0, 0.0), DVec3::X));
        let expected = [1.75, 2.25, 3.75, 4.25];
        assert_eq!(c.as_slice().len(), 4);
        for (a, b) in c.as_slice().iter().zip(expected) {
            assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        }
    }

    /// The polynomial along a ray, for every degree: its value at s is the surface
    /// polynomial's at o + s·d (every term of each degree, with coefficients that differ).
    #[test]
    fn along_a_ray_is_the_polynomial_at_each_point() {
        for degree in 2..=6u8 {
            let mut terms = Vec::new();
            for i in 0..=degree {
                for j in 0..=degree - i {
                    for k in 0..=degree - i - j {
                        let c =
                            1.0 + f64::from(i) * 0.37 - f64::from(j) * 0.21 + f64::from(k) * 0.13;
                        terms.push((c, [i, j, k]));
                    }
                }
            }
            let p = Polynomial {
                degree,
                terms: terms.into(),
            };
            let (o, d) = (DVec3::new(0.3, -0.7, 1.1), DVec3::new(-0.4, 0.5, 0.9));
            let c = p.along(o, d);
            for s in [-1.3, -0.2, 0.0, 0.6, 1.7] {
                let along = c.iter().rev().fold(0.0, |acc, &ci| acc * s + ci);
                let direct = p.value(o + s * d);
                assert!(
                    (along - direct).abs() <= 1e-9 * direct.abs().max(1.0),
                    "degree {degree}, s {s}: {along} against {direct}"
                );
            }
        }
    }
}
