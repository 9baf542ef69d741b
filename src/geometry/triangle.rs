//! Watertight ray/triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
//! Intersection", JCGT 2013).
//!
//! The ray is sheared so that it runs along +z from the origin; the triangle's vertices are
//! transformed the same way and the 2D edge functions decide the hit. A shared edge gets the
//! same edge-function value (up to sign, exactly) from both of its triangles, because each
//! vertex is transformed identically whatever triangle it belongs to: no ray passes between
//! two triangles of a closed mesh.

use glam::DVec3;

/// A ray prepared for triangle tests: the shear that maps its direction to +z.
#[derive(Clone, Copy, Debug)]
pub struct ShearedRay {
    /// The origin's coordinates along the shear's x, y and z axes.
    origin: [f64; 3],
    kx: usize,
    ky: usize,
    kz: usize,
    sx: f64,
    sy: f64,
    sz: f64,
}

impl ShearedRay {
    /// Prepares `origin + t·direction`.
    pub fn new(origin: DVec3, direction: DVec3) -> ShearedRay {
        let (kx, ky, kz) = shear_axes(direction);
        // (Indexed as arrays: a vector's own indexing is a branch on each index.)
        let (o, d) = (origin.to_array(), direction.to_array());
        ShearedRay {
            origin: [o[kx], o[ky], o[kz]],
            kx,
            ky,
            kz,
            sx: d[kx] / d[kz],
            sy: d[ky] / d[kz],
            sz: 1.0 / d[kz],
        }
    }

    /// The axes the ray is sheared along: x, y, and z (the direction's largest component).
    pub fn axes(&self) -> (usize, usize, usize) {
        (self.kx, self.ky, self.kz)
    }

    /// The shear factors: the direction's x and y components over its z component.
    pub fn factors(&self) -> (f64, f64) {
        (self.sx, self.sy)
    }

    /// Distance `t` to the triangle (v0, v1, v2), if the ray meets it (either side) at a `t` in
    /// `(tmin, tmax)`. (Meshes call [`ShearedRay::intersect_corners`] on their stored
    /// corners; this form is for tests and the stability suite.)
    #[cfg(any(test, feature = "internals"))]
    pub fn intersect(&self, v0: DVec3, v1: DVec3, v2: DVec3, tmin: f64, tmax: f64) -> Option<f64> {
        self.intersect_corners(&[v0, v1, v2], tmin, tmax)
    }

    /// [`ShearedRay::intersect`] for the triangle whose corner `k`'s coordinate `axis` is
    /// `corners.at(k, axis)`: read where the corners are stored, a coordinate at a time, with
    /// no copy of them to index.
    #[inline(always)]
    pub fn intersect_corners(
        &self,
        corners: &impl TriangleCorners,
        tmin: f64,
        tmax: f64,
    ) -> Option<f64> {
        let corner = |k: usize, axis: usize| corners.at(k, axis);
        let (kx, ky, kz) = (self.kx, self.ky, self.kz);
        let [ox, oy, oz] = self.origin;
        // Vertices relative to the origin, sheared.
        let sheared = |k: usize| {
            let z = corner(k, kz) - oz;
            (
                (corner(k, kx) - ox) - self.sx * z,
                (corner(k, ky) - oy) - self.sy * z,
                z,
            )
        };
        let (ax, ay, az) = sheared(0);
        let (bx, by, bz) = sheared(1);
        let (cx, cy, cz) = sheared(2);
        // Scaled barycentric coordinates (2D edge functions).
        let u = cx * by - cy * bx;
        let v = ax * cy - ay * cx;
        let w = bx * ay - by * ax;
        if (u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0) {
            return None;
        }
        let det = u + v + w;
        if det == 0.0 {
            return None;
        }
        // Scaled distance, then the real one.
        let t_scaled = u * self.sz * az + v * self.sz * bz + w * self.sz * cz;
        let t = t_scaled / det;
        (tmin < t && t < tmax).then_some(t)
    }
}

/// Where a triangle's corners are read from.
pub trait TriangleCorners {
    /// Corner `k`'s coordinate `axis` (each below 3).
    fn at(&self, k: usize, axis: usize) -> f64;
}

impl TriangleCorners for [DVec3; 3] {
    #[inline(always)]
    fn at(&self, k: usize, axis: usize) -> f64 {
        self[k][axis]
    }
}

/// The axes of the shear for `direction`: the one where it is largest becomes z, and x and y
/// are swapped when that component is negative, to keep the winding.
pub fn shear_axes(direction: DVec3) -> (usize, usize, usize) {
    let a = direction.abs();
    let kz = if a.x >= a.y && a.x >= a.z {
        0
    } else if a.y >= a.z {
        1
    } else {
        2
    };
    let mut kx = (kz + 1) % 3;
    let mut ky = (kx + 1) % 3;
    if direction[kz] < 0.0 {
        std::mem::swap(&mut kx, &mut ky);
    }
    (kx, ky, kz)
}

/// Barycentric coordinates of a point `p` on the plane of triangle (v0, v1, v2).
pub fn barycentric(p: DVec3, v0: DVec3, v1: DVec3, v2: DVec3) -> [f64; 3] {
    let (e1, e2, ep) = (v1 - v0, v2 - v0, p - v0);
    let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
    let (dp1, dp2) = (ep.dot(e1), ep.dot(e2));
    let denom = d11 * d22 - d12 * d12;
    let b1 = (d22 * dp1 - d12 * dp2) / denom;
    let b2 = (d11 * dp2 - d12 * dp1) / denom;
    [1.0 - b1 - b2, b1, b2]
}

#[cfg(test)]
mod tests {
    use super::*;

    const V0: DVec3 = DVec3::new(0.0, 0.0, 0.0);
    const V1: DVec3 = DVec3::new(1.0, 0.0, 0.0);
    const V2: DVec3 = DVec3::new(0.0, 1.0, 0.0);

    fn hit(o: DVec3, d: DVec3) -> Option<f64> {
        ShearedRay::new(o, d).intersect(V0, V1, V2, 0.0, f64::INFINITY)
    }

    #[test]
    fn triangle_ray_through_interior_hits() {
        assert_eq!(hit(DVec3::new(0.25, 0.25, -2.0), DVec3::Z), Some(2.0));
    }

    #[test]
    fn triangle_is_two_sided() {
        assert_eq!(hit(DVec3::new(0.25, 0.25, 2.0), -DVec3::Z), Some(2.0));
    }

    #[test]
    fn triangle_ray_outside_misses() {
        assert_eq!(hit(DVec3::new(0.75, 0.75, -2.0), DVec3::Z), None);
    }

    #[test]
    fn triangle_behind_origin_misses() {
        assert_eq!(hit(DVec3::new(0.25, 0.25, 2.0), DVec3::Z), None);
    }

    #[test]
    fn triangle_edge_on_ray_misses() {
        assert_eq!(hit(DVec3::new(-1.0, 0.25, 0.0), DVec3::X), None);
    }

    #[test]
    fn shared_edge_is_hit_by_one_of_two_triangles_at_any_offset() {
        // Two triangles sharing the diagonal of a unit square; rays aimed exactly at points of
        // the diagonal (and at its vertices) must hit at least one of them.
        for offset in [0.0, 1e3, 1e5] {
            let shift = DVec3::splat(offset);
            let (a, b, c, d) = (
                DVec3::new(0.0, 0.0, 0.0) + shift,
                DVec3::new(1.0, 0.0, 0.0) + shift,
                DVec3::new(1.0, 1.0, 0.0) + shift,
                DVec3::new(0.0, 1.0, 0.0) + shift,
            );
            for i in 0..=64 {
                let s = i as f64 / 64.0;
                let target = a + (c - a) * s;
                let origin = shift + DVec3::new(0.3, 0.7, -3.0) * (1.0 + s);
                let ray = ShearedRay::new(origin, target - origin);
                let h1 = ray.intersect(a, b, c, 0.0, f64::INFINITY);
                let h2 = ray.intersect(a, c, d, 0.0, f64::INFINITY);
                assert!(
                    h1.is_some() || h2.is_some(),
                    "leak at offset {offset}, s = {s}"
                );
            }
        }
    }

    #[test]
    fn barycentric_of_vertices() {
        assert_eq!(barycentric(V1, V0, V1, V2), [0.0, 1.0, 0.0]);
        let b = barycentric(DVec3::new(0.25, 0.25, 0.0), V0, V1, V2);
        assert!((b[0] - 0.5).abs() < 1e-12 && (b[1] - 0.25).abs() < 1e-12);
    }
}
