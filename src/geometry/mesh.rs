//! Triangle meshes: vertices, triangles, optional vertex normals, and a BVH (obvhs `Bvh2`)
//! over the triangles. A mesh is built once and shared by all its instances, which intersect
//! it in their own object space.

use super::triangle::{ShearedRay, barycentric};
use super::wide::{Corners, Lane, PACKET, bits};
use super::{Crossings, Ray, counters};
use glam::{DVec3, Vec3, Vec3A};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb;
use rayon::prelude::*;
use std::time::Duration;

/// Marker for a flat triangle in the normal indices.
const FLAT: [u32; 3] = [u32::MAX; 3];

/// A mesh ready for intersection.
pub struct TriangleMesh {
    /// Single precision, as POV-Ray keeps a mesh's vertices and normals.
    vertices: Vec<Vec3>,
    /// Triangles in BVH primitive order.
    triangles: Vec<[u32; 3]>,
    normals: Vec<Vec3>,
    /// Per triangle (BVH order), indices into `normals`, or [`FLAT`]; empty if all flat.
    normal_indices: Vec<[u32; 3]>,
    /// The 8-wide tree over the triangles.
    tree: super::wide::WideBvh,
    /// `uv_vectors`: the corners' surface coordinates.
    uvs: Vec<glam::DVec2>,
    /// Per triangle (BVH order), indices into `uvs`; empty when the mesh has none.
    uv_indices: Vec<[u32; 3]>,
    /// Per triangle (BVH order), the entries of the object's material its corners take (a
    /// mesh's own textures); empty when the triangles have none.
    corner_entries: Vec<[u32; 3]>,
    /// `inside_vector`, if given.
    pub inside_vector: Option<DVec3>,
    /// Without `uv_vectors`, POV-Ray's default coordinates (a stand-alone triangle's) instead
    /// of (0, 0).
    pub world_uv: bool,
    /// Bounding box in object space.
    pub bounds: (DVec3, DVec3),
}

impl std::fmt::Debug for TriangleMesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("TriangleMesh")
            .field("triangles", &self.triangles.len())
            .finish()
    }
}

/// An f32 box that contains the f64 box (rounded outward, padded).
pub fn outward_aabb(min: DVec3, max: DVec3) -> Aabb {
    let pad = |v: DVec3| 1e-7 * v.abs().max_element() + 1e-30;
    let (pmin, pmax) = (pad(min), pad(max));
    let lo = |x: f64, p: f64| ((x - p) as f32).next_down();
    let hi = |x: f64, p: f64| ((x + p) as f32).next_up();
    Aabb {
        min: Vec3A::new(lo(min.x, pmin), lo(min.y, pmin), lo(min.z, pmin)),
        max: Vec3A::new(hi(max.x, pmax), hi(max.y, pmax), hi(max.z, pmax)),
    }
}

/// A distance as the tree's pruning value: never below the true distance.
pub(crate) fn prune_value(t: f64) -> f32 {
    if t.is_finite() {
        ((t * (1.0 + 1e-6)) as f32).next_up()
    } else {
        f32::INFINITY
    }
}

/// Whether a crossing at `t` with triangle `index` is nearer than `best` (the nearest so far),
/// or than the ray's end `tmax` when there is none: at an equal distance (a ray through the
/// edge two triangles share) the lower index wins, so that the answer does not depend on the
/// order the walk meets them in.
fn closer(t: f64, index: u32, best: Option<(f64, u32)>, tmax: f64) -> bool {
    match best {
        None => t < tmax,
        Some((b, i)) => t < b || (t == b && index < i),
    }
}

/// Triangles a leaf holds at most: one block of the tree, tested together.
const LEAF_SIZE: u32 = 4;

impl TriangleMesh {
    /// Builds the BVH over the triangles. `normal_indices` is empty or parallel to `triangles`.
    pub fn new(
        vertices: Vec<Vec3>,
        triangles: Vec<[u32; 3]>,
        normals: Vec<Vec3>,
        normal_indices: Vec<[u32; 3]>,
        uvs: Vec<glam::DVec2>,
        uv_indices: Vec<[u32; 3]>,
    ) -> TriangleMesh {
        Self::with_corner_entries(
            vertices,
            triangles,
            normals,
            normal_indices,
            uvs,
            uv_indices,
            Vec::new(),
        )
    }

    /// [`TriangleMesh::new`] with, per triangle, the material entries its corners take
    /// (empty, or parallel to `triangles`).
    pub fn with_corner_entries(
        vertices: Vec<Vec3>,
        triangles: Vec<[u32; 3]>,
        normals: Vec<Vec3>,
        normal_indices: Vec<[u32; 3]>,
        uvs: Vec<glam::DVec2>,
        uv_indices: Vec<[u32; 3]>,
        corner_entries: Vec<[u32; 3]>,
    ) -> TriangleMesh {
        // (In parallel: at a million triangles each of these passes is tens of milliseconds.)
        let empty = || (Vec3::INFINITY, Vec3::NEG_INFINITY);
        let (lo, hi) = vertices
            .par_iter()
            .fold(empty, |(lo, hi), v| (lo.min(*v), hi.max(*v)))
            .reduce(empty, |(a, b), (c, d)| (a.min(c), b.max(d)));
        let (lo, hi) = (lo.as_dvec3(), hi.as_dvec3());
        let corners = |t: &[u32; 3]| t.map(|i| vertices[i as usize].as_dvec3());
        let boxes: Vec<Aabb> = triangles
            .par_iter()
            .map(|t| {
                let [p, q, r] = corners(t);
                outward_aabb(p.min(q).min(r), p.max(q).max(r))
            })
            .collect();
        // Leaves of up to four triangles, where the builder's surface-area cost finds them
        // worth it. (Before 2026-11-30 the builder was handed groups of up to four triangles
        // consecutive in Morton order, one per leaf: on meshes as flat as a terrain most
        // groups held one triangle, and the rays were 13-80 % slower.)
        let params = BvhBuildParams {
            max_prims_per_leaf: LEAF_SIZE,
            ..BvhBuildParams::fast_build()
        };
        let bvh = obvhs::bvh2::builder::build_bvh2(&boxes, params, &mut Duration::default());
        drop(boxes);
        // Triangles in the tree's order, as it lists its primitives.
        let order = &bvh.primitive_indices;
        let pick = |list: &[[u32; 3]]| -> Vec<[u32; 3]> {
            if list.is_empty() {
                Vec::new()
            } else {
                order.par_iter().map(|&k| list[k as usize]).collect()
            }
        };
        let triangles_ordered = pick(&triangles);
        let normal_ordered = pick(&normal_indices);
        let uv_ordered = pick(&uv_indices);
        let entries_ordered = pick(&corner_entries);
        // (The input's copies go before the tree is built: at 1M triangles they are 40 MB.)
        drop((triangles, normal_indices, uv_indices, corner_entries));
        let tree = super::wide::WideBvh::new(
            bvh,
            |i| triangles_ordered[i].map(|v| vertices[v as usize]),
            (lo, hi),
        );
        TriangleMesh {
            vertices,
            triangles: triangles_ordered,
            normals,
            normal_indices: normal_ordered,
            tree,
            uvs,
            uv_indices: uv_ordered,
            corner_entries: entries_ordered,
            inside_vector: None,
            world_uv: false,
            bounds: (lo, hi),
        }
    }

    /// The same mesh, its tree walked without AVX2 (for tests of that path).
    #[cfg(test)]
    pub fn without_avx2(mut self) -> TriangleMesh {
        self.tree = self.tree.without_avx2();
        self
    }

    fn corners_of(&self, triangle: usize) -> [DVec3; 3] {
        self.triangles[triangle].map(|i| self.vertices[i as usize].as_dvec3())
    }

    /// The exact (double-precision, watertight) test of lane `lane` of a block the tree's
    /// filter kept, counted for `--stats`.
    fn exact(
        sheared: &ShearedRay,
        corners: &Corners,
        lane: usize,
        tmin: f64,
        tmax: f64,
    ) -> Option<f64> {
        let crossing = sheared.intersect_corners(&Lane(corners, lane), tmin, tmax);
        counters::record(super::shape::TRIANGLE, crossing.is_some());
        crossing
    }

    /// The nearest crossing (part = triangle index).
    pub fn intersect(&self, ray: &Ray) -> Crossings {
        let sheared = ShearedRay::new(ray.origin, ray.direction);
        let mut best: Option<(f64, u32)> = None;
        let mut tmax = ray.tmax;
        self.tree.walk::<true>(
            ray,
            &sheared,
            prune_value(ray.tmax),
            |first, lanes, corners| {
                let mut hit = false;
                for i in bits(lanes) {
                    let crossing = Self::exact(&sheared, corners, i, ray.tmin, tmax.next_up());
                    if let Some(t) = crossing.filter(|&t| closer(t, first + i as u32, best, tmax)) {
                        tmax = t;
                        best = Some((t, first + i as u32));
                        hit = true;
                    }
                }
                if hit {
                    prune_value(tmax)
                } else {
                    f32::INFINITY
                }
            },
        );
        let mut out = Crossings::NONE;
        if let Some((t, i)) = best {
            out.push(t, i);
        }
        out
    }

    /// [`TriangleMesh::intersect`] of up to eight rays (a packet), walked together, into
    /// `out`.
    pub fn intersect_packet(&self, rays: &[Ray], out: &mut [Crossings]) {
        let sheared: [ShearedRay; PACKET] = std::array::from_fn(|k| {
            let ray = &rays[if k < rays.len() { k } else { 0 }];
            ShearedRay::new(ray.origin, ray.direction)
        });
        let mut best: [Option<(f64, u32)>; PACKET] = [None; PACKET];
        let mut tmax = [f64::INFINITY; PACKET];
        let mut limits = [f32::INFINITY; PACKET];
        for (k, ray) in rays.iter().enumerate() {
            tmax[k] = ray.tmax;
            limits[k] = prune_value(ray.tmax);
        }
        self.tree
            .walk_packet(rays, &sheared, &mut limits, |k, first, lanes, corners| {
                let mut hit = false;
                for i in bits(lanes) {
                    let crossing =
                        Self::exact(&sheared[k], corners, i, rays[k].tmin, tmax[k].next_up());
                    if let Some(t) =
                        crossing.filter(|&t| closer(t, first + i as u32, best[k], tmax[k]))
                    {
                        tmax[k] = t;
                        best[k] = Some((t, first + i as u32));
                        hit = true;
                    }
                }
                if hit {
                    prune_value(tmax[k])
                } else {
                    f32::INFINITY
                }
            });
        for (k, crossings) in out.iter_mut().enumerate().take(rays.len()) {
            *crossings = Crossings::NONE;
            if let Some((t, i)) = best[k] {
                crossings.push(t, i);
            }
        }
    }

    /// Calls `f` with the distance of every crossing along the ray (in no particular order).
    pub fn for_each_crossing(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        let sheared = ShearedRay::new(ray.origin, ray.direction);
        self.tree.walk::<false>(
            ray,
            &sheared,
            prune_value(ray.tmax),
            |first, lanes, corners| {
                for i in bits(lanes) {
                    let crossing = Self::exact(&sheared, corners, i, ray.tmin, ray.tmax);
                    if let Some(t) = crossing {
                        f(t, first + i as u32);
                    }
                }
                f32::INFINITY
            },
        );
    }

    /// The number of crossings along the ray.
    pub fn count_crossings(&self, ray: &Ray) -> usize {
        let mut n = 0;
        self.for_each_crossing(ray, |_, _| n += 1);
        n
    }

    /// Whether any triangle lies on the ray.
    pub fn occluded(&self, ray: &Ray) -> bool {
        let sheared = ShearedRay::new(ray.origin, ray.direction);
        let mut found = false;
        self.tree
            .walk::<false>(ray, &sheared, prune_value(ray.tmax), |_, lanes, corners| {
                for i in bits(lanes) {
                    let crossing = Self::exact(&sheared, corners, i, ray.tmin, ray.tmax);
                    if crossing.is_some() {
                        found = true;
                        return -1.0;
                    }
                }
                f32::INFINITY
            });
        found
    }

    /// The geometric normal of a triangle (not unit length; orientation from the winding).
    pub fn geometric_normal(&self, triangle: u32) -> DVec3 {
        let [a, b, c] = self.corners_of(triangle as usize);
        // POV-Ray's orientation, (c − a) × (b − a), which decides the side that shows an
        // interior texture.
        (c - a).cross(b - a)
    }

    /// The shading normal at `p` on a triangle: interpolated vertex normals for a smooth
    /// triangle (POV-Ray: normalize(Σ bᵢ·Nᵢ)), the geometric normal otherwise (and where the
    /// interpolated normals cancel).
    pub fn normal(&self, p: DVec3, triangle: u32) -> DVec3 {
        let ng = self.geometric_normal(triangle);
        match self.normal_indices.get(triangle as usize) {
            Some(ni) if *ni != FLAT => {
                let [a, b, c] = self.corners_of(triangle as usize);
                let w = barycentric(p, a, b, c);
                let n = ni.map(|i| self.normals[i as usize].as_dvec3());
                let smooth = w[0] * n[0] + w[1] * n[1] + w[2] * n[2];
                // Normals on both sides of the face (POV-Ray keeps such triangles) can cancel.
                if smooth.length_squared() > 1e-20 {
                    smooth
                } else {
                    ng
                }
            }
            _ => ng,
        }
    }

    /// The surface coordinates at `p` on `triangle`: its corners' `uv_vectors` weighted by
    /// POV-Ray's barycentric weights (each corner's, from the distance to the opposite side);
    /// (0, 0) without uv_vectors.
    pub fn uv(&self, p: DVec3, triangle: u32) -> glam::DVec2 {
        let Some(indices) = self.uv_indices.get(triangle as usize) else {
            return glam::DVec2::ZERO;
        };
        let w = self.corner_weights(p, triangle).to_array();
        let uv = indices.map(|i| self.uvs[i as usize]);
        w[0] * uv[0] + w[1] * uv[1] + w[2] * uv[2]
    }

    /// The material entries of triangle `triangle`'s corners and the weights point `p` gives
    /// them (barycentric), for a mesh whose triangles have textures of their own.
    pub fn corners(&self, p: DVec3, triangle: u32) -> Option<([u32; 3], DVec3)> {
        let entries = *self.corner_entries.get(triangle as usize)?;
        if entries[0] == entries[1] && entries[1] == entries[2] {
            return Some((entries, DVec3::X));
        }
        Some((entries, self.corner_weights(p, triangle)))
    }

    /// The barycentric weights of point `p` on triangle `triangle`.
    fn corner_weights(&self, p: DVec3, triangle: u32) -> DVec3 {
        let [a, b, c] = self.corners_of(triangle as usize);
        // The weight of corner `p0`, with `p1` and `p2` the other two: the projection of the
        // point onto the height from the side p1–p2 (1 at the corner, 0 on that side).
        let weight = |p0: DVec3, p1: DVec3, p2: DVec3| {
            let (side, adjacent) = (p2 - p1, p2 - p0);
            let height = side * (adjacent.dot(side) / side.dot(side)) - adjacent;
            1.0 + (p - p0).dot(height) / height.dot(height)
        };
        DVec3::new(weight(a, b, c), weight(b, a, c), weight(c, a, b))
    }

    /// Whether a point is inside: only a mesh with an `inside_vector` has an inside (an odd
    /// number of crossings along that vector), as in POV-Ray.
    pub fn contains(&self, p: DVec3) -> bool {
        match self.inside_vector {
            Some(dir) => self.count_crossings(&Ray::new(p, dir)) % 2 == 1,
            None => false,
        }
    }
}

impl super::shape::Surface for TriangleMesh {
    const NAME: &'static str = "Mesh";

    #[inline]
    fn intersect(&self, ray: &Ray) -> Crossings {
        self.intersect(ray)
    }

    #[inline]
    fn normals(&self, p: DVec3, triangle: u32) -> (DVec3, DVec3) {
        (self.normal(p, triangle), self.geometric_normal(triangle))
    }

    fn contains(&self, p: DVec3) -> bool {
        self.contains(p)
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some(self.bounds)
    }

    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        self.for_each_crossing(ray, f)
    }

    fn occludes(&self, ray: &Ray) -> bool {
        self.occluded(ray)
    }

    fn uv(&self, p: DVec3, triangle: u32) -> Option<glam::DVec2> {
        (!self.world_uv || !self.uv_indices.is_empty()).then(|| TriangleMesh::uv(self, p, triangle))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Corner `i` (0..8) of the cube [−1, 1]³.
    fn cube_corner(i: u32) -> DVec3 {
        let bit = |k: u32| ((i >> k) & 1) as f64 * 2.0 - 1.0;
        DVec3::new(bit(0), bit(1), bit(2))
    }

    /// A closed unit cube (12 triangles) centred at `c` with half-size `h`.
    fn cube(c: DVec3, h: f64) -> TriangleMesh {
        let mut v = Vec::new();
        for i in 0..8 {
            v.push(c + cube_corner(i) * h);
        }
        let quads = [
            [0, 1, 3, 2],
            [4, 6, 7, 5],
            [0, 4, 5, 1],
            [2, 3, 7, 6],
            [0, 2, 6, 4],
            [1, 5, 7, 3],
        ];
        let mut t = Vec::new();
        for q in quads {
            t.push([q[0], q[1], q[2]]);
            t.push([q[0], q[2], q[3]]);
        }
        let v = v.iter().map(|p| p.as_vec3()).collect();
        TriangleMesh::new(v, t, Vec::new(), Vec::new(), Vec::new(), Vec::new())
    }

    #[test]
    fn mesh_cube_ray_hits_front_face() {
        let m = cube(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::new(0.2, 0.3, -5.0), DVec3::Z);
        assert_eq!(m.intersect(&r).first(), Some(4.0));
        assert_eq!(m.count_crossings(&r), 2);
        assert!(m.occluded(&r));
    }

    #[test]
    fn mesh_cube_ray_beside_misses() {
        let m = cube(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::new(1.5, 0.3, -5.0), DVec3::Z);
        assert!(m.intersect(&r).is_empty());
        assert!(!m.occluded(&r));
    }

    #[test]
    fn mesh_from_inside_hits_once() {
        let m = cube(DVec3::ZERO, 1.0);
        let r = Ray::new(DVec3::ZERO, DVec3::new(0.3, 0.2, 1.0));
        assert_eq!(m.count_crossings(&r), 1);
        let mut m = m;
        assert!(!m.contains(DVec3::ZERO));
        m.inside_vector = Some(DVec3::new(0.3, 0.2, 1.0));
        assert!(m.contains(DVec3::ZERO));
    }

    #[test]
    fn closed_mesh_has_no_leak_at_vertices_and_edges_far_from_origin() {
        // Rays through the centre of a closed cube, aimed exactly at each vertex, each edge
        // midpoint and points along the edges: they enter the solid there, so each must hit,
        // at offsets 0, 1e3 and 1e5 from the origin.
        for offset in [0.0, 1e3, 1e5] {
            let c = DVec3::new(offset, -offset, offset);
            let m = cube(c, 1.0);
            let mut targets = Vec::new();
            for i in 0..8 {
                let s = cube_corner(i);
                targets.push(s);
                for axis in 0..3 {
                    for k in 1..8 {
                        let mut e = s;
                        e[axis] = -1.0 + k as f64 / 4.0;
                        targets.push(e);
                    }
                }
            }
            for target in targets {
                // Along the line from far outside through the target and the centre.
                let origin = c + target * 5.0;
                let r = Ray::new(origin, (c + target) - origin);
                let t = m.intersect(&r).first();
                assert!(
                    t.is_some_and(|t| (t - 1.0).abs() < 1e-9),
                    "leak at offset {offset}, target {target}: {t:?}"
                );
                assert!(
                    m.count_crossings(&r) >= 2,
                    "no exit at offset {offset}, target {target}"
                );
            }
        }
    }
}
