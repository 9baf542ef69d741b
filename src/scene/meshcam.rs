//! POV-Ray 3.7's `mesh_camera`: a pixel's rays leave faces of meshes instead of an eye point.
//!
//! The face is picked from the pixel as POV-Ray picks it (`tracepixel.cpp`): its sample
//! position, moved as for every camera (x + ½, y − ½) and clipped to the image, cut to whole
//! pixels, numbers the face (row by row) of mesh k for ray k (distribution 0), of the meshes
//! numbered on (1), of the mesh whose strip of the image holds the pixel (2), or is the first
//! face whose `uv_vectors` triangle holds the pixel's (u, v) (3). The ray leaves the face's
//! centroid (for 3, the point of those barycentric weights) along the face's normal,
//! `offset` further along it, reversed on request, and is carried to the world by the mesh's
//! transformation (the direction as a normal is, then made unit). Each ray starts inside the
//! objects that hold its own origin (POV-Ray 3.7 works that out once per thread, at the
//! thread's first ray, and 3.8 per ray, as trace does).

use crate::geometry::Ray;
use crate::ir;
use glam::{DMat3, DVec3};
use std::sync::Arc;

/// A mesh camera ready to make rays.
#[derive(Debug)]
pub struct MeshCamera {
    camera: Arc<ir::MeshCamera>,
    /// Per mesh: the transformation of points and of normals to the world, if any.
    transforms: Vec<Option<(glam::DMat4, DMat3)>>,
    /// Per mesh, the faces of the meshes before it (distribution 1), and the total.
    first_face: Vec<u64>,
    total_faces: u64,
    /// Distribution 3, as POV-Ray indexes the first mesh's faces: for each tenth of u (and
    /// of v) the set (one bit a face, in order) of faces whose (u, v) extent reaches it; a
    /// pixel's candidates are the faces in both its u's and its v's set (2.5 bytes a face
    /// whatever their extents).
    u_sets: Vec<Vec<u64>>,
    v_sets: Vec<Vec<u64>>,
}

/// POV-Ray's cell of a (u, v) coordinate: tenths, cut towards zero, at most 9.
fn cell(x: f64) -> usize {
    let t = (x * 10.0).trunc();
    if t >= 9.0 {
        9
    } else if t <= 0.0 {
        0
    } else {
        t as usize
    }
}

impl MeshCamera {
    /// The camera of the IR's mesh camera, with its lookups prepared.
    pub fn new(camera: &Arc<ir::MeshCamera>) -> MeshCamera {
        let transforms = camera
            .meshes
            .iter()
            .map(|(_, t)| t.map(|t| (t.matrix, DMat3::from_mat4(t.matrix).inverse().transpose())))
            .collect();
        let mut first_face = Vec::with_capacity(camera.meshes.len());
        let mut total_faces = 0u64;
        for (mesh, _) in &camera.meshes {
            first_face.push(total_faces);
            total_faces += faces(mesh);
        }
        let (mut u_sets, mut v_sets) = (Vec::new(), Vec::new());
        if camera.distribution == 3 {
            let mesh = &camera.meshes[0].0;
            let words = mesh.uv_indices.len().div_ceil(64);
            (u_sets, v_sets) = (vec![vec![0u64; words]; 10], vec![vec![0u64; words]; 10]);
            for (k, corners) in mesh.uv_indices.iter().enumerate() {
                let uv = corners.map(|i| mesh.uvs[i as usize]);
                // (POV-Ray's tenths of a corner: cut towards zero; a face's run from its
                // corners' least to their greatest, each at most 9.)
                let tenth = |x: f64| ((x * 10.0) as i64).min(9);
                let (u, v) = (uv.map(|p| tenth(p.x)), uv.map(|p| tenth(p.y)));
                let bit = 1u64 << (k % 64);
                for (sets, t) in [(&mut u_sets, u), (&mut v_sets, v)] {
                    let (lo, hi) = (
                        t.into_iter().min().unwrap_or(0),
                        t.into_iter().max().unwrap_or(-1),
                    );
                    for cell in lo.max(0)..=hi {
                        sets[cell as usize][k / 64] |= bit;
                    }
                }
            }
        }
        MeshCamera {
            camera: Arc::clone(camera),
            transforms,
            first_face,
            total_faces,
            u_sets,
            v_sets,
        }
    }

    /// Rays a pixel may average: distribution 1 gives only ray 0 a face (POV-Ray numbers
    /// ray k's face from k times the total count), so its further rays are never made.
    pub fn rays_per_pixel(&self) -> u32 {
        if self.camera.distribution == 1 {
            1
        } else {
            self.camera.rays_per_pixel
        }
    }

    /// Ray `k` of the sample at image position (x, y) (pixel units, as the other cameras
    /// take them), or `None` where POV-Ray traces no ray.
    pub fn ray(&self, x: f64, y: f64, width: u32, height: u32, k: u32) -> Option<Ray> {
        let c = &*self.camera;
        let (w, h) = (width as f64, height as f64);
        let px = (x + 0.5).clamp(0.0, w - 1.0);
        let py = (y - 0.5).clamp(0.0, h - 1.0);
        let pixel = py as u64 * u64::from(width) + px as u64;
        let (mesh, face) = match c.distribution {
            0 => (k as usize, pixel),
            1 => {
                let face = pixel + u64::from(k) * self.total_faces;
                if face >= self.total_faces {
                    return None;
                }
                let mesh = self.first_face.partition_point(|&f| f <= face) - 1;
                (mesh, face - self.first_face[mesh])
            }
            2 => {
                let n = c.meshes.len();
                let mesh = ((px / (w / n as f64)) as usize).min(n - 1);
                // (POV-Ray numbers the face from the whole image's column, not the strip's.)
                (mesh, py as u64 * (u64::from(width) / n as u64) + px as u64)
            }
            _ => return self.uv_ray(px, py, w, h),
        };
        let (m, _) = c.meshes.get(mesh)?;
        let corners = m.triangles.get(kept(m, face)?)?;
        let p = corners.map(|i| m.vertices[i as usize].as_dvec3());
        let centroid = (p[0] + p[1] + p[2]) / 3.0;
        self.leave(mesh, centroid, face_normal(&p))
    }

    /// Distribution 3: the first face of the first mesh whose (u, v) triangle holds the
    /// pixel's (u, v).
    fn uv_ray(&self, px: f64, py: f64, w: f64, h: f64) -> Option<Ray> {
        let c = &*self.camera;
        let (u, v) = ((px - 0.5) / w, 1.0 - (py + 0.5) / h);
        let m = &c.meshes[0].0;
        let (us, vs) = (&self.u_sets[cell(u)], &self.v_sets[cell(v)]);
        let candidates = us.iter().zip(vs).enumerate().flat_map(|(word, (a, b))| {
            let mut bits = a & b;
            std::iter::from_fn(move || {
                (bits != 0).then(|| {
                    let k = word * 64 + bits.trailing_zeros() as usize;
                    bits &= bits - 1;
                    k
                })
            })
        });
        for k in candidates {
            let uv = m.uv_indices[k].map(|i| m.uvs[i as usize]);
            let (a, b, d) = (uv[0], uv[1], uv[2]);
            let scale = (b.x - a.x) * (d.y - a.y) - (d.x - a.x) * (b.y - a.y);
            let w1 = ((b.x - u) * (d.y - v) - (d.x - u) * (b.y - v)) / scale;
            let w2 = ((d.x - u) * (a.y - v) - (a.x - u) * (d.y - v)) / scale;
            let w3 = ((a.x - u) * (b.y - v) - (b.x - u) * (a.y - v)) / scale;
            // (A face of no area in (u, v) gives NaN weights: skipped, where POV-Ray would
            // make a ray of NaN.)
            if !(w1 >= 0.0 && w2 >= 0.0 && w3 >= 0.0) {
                continue;
            }
            let p = m.triangles[k].map(|i| m.vertices[i as usize].as_dvec3());
            let point = p[0] * w1 + p[1] * w2 + p[2] * w3;
            let normal = match m.normal_indices.get(k) {
                Some(n) if c.smooth && *n != ir::FLAT => {
                    let n = n.map(|i| m.normals[i as usize].as_dvec3());
                    n[0] * w1 + n[1] * w2 + n[2] * w3
                }
                _ => face_normal(&p),
            };
            return self.leave(0, point, normal);
        }
        None
    }

    /// The ray from `point` on mesh `mesh` along `normal` (both in the mesh's space).
    fn leave(&self, mesh: usize, point: DVec3, normal: DVec3) -> Option<Ray> {
        let c = &*self.camera;
        let mut origin = point + c.offset * normal;
        let mut direction = if c.reversed { -normal } else { normal };
        if let Some((points, normals)) = &self.transforms[mesh] {
            origin = points.transform_point3(origin);
            direction = *normals * direction;
        }
        let direction = direction.try_normalize()?;
        let mut ray = Ray::new(origin, direction);
        if c.max_distance > 0.0 {
            ray.tmax = c.max_distance;
        }
        Some(ray)
    }
}

/// The faces of a mesh as POV-Ray numbers them: a `mesh2`'s faces of no area count.
fn faces(m: &ir::Mesh) -> u64 {
    (m.triangles.len() + m.dropped_faces.len()) as u64
}

/// Where face `face` (POV-Ray's number) is among the mesh's triangles; `None` for a face of
/// no area (POV-Ray's ray from it has no direction) or past the last.
fn kept(m: &ir::Mesh, face: u64) -> Option<usize> {
    let f = u32::try_from(face).ok()?;
    let before = m.dropped_faces.partition_point(|&d| d < f);
    if m.dropped_faces.get(before) == Some(&f) {
        return None;
    }
    Some(f as usize - before)
}

/// A face's unit normal as POV-Ray stores it: (p₃ − p₁) × (p₂ − p₁).
fn face_normal(p: &[DVec3; 3]) -> DVec3 {
    (p[2] - p[0]).cross(p[1] - p[0]).normalize_or_zero()
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DVec2, Vec3};

    /// A grid of `w` × `h` unit squares in the plane z = 0 (two triangles each, facing +z
    /// by POV-Ray's (p₃ − p₁) × (p₂ − p₁)), row by row from the top, with uv over [0, 1]².
    fn grid(w: u32, h: u32) -> ir::Mesh {
        let mut m = ir::Mesh::default();
        for j in 0..=h {
            for i in 0..=w {
                m.vertices.push(Vec3::new(i as f32, -(j as f32), 0.0));
                m.uvs.push(DVec2::new(
                    f64::from(i) / f64::from(w),
                    1.0 - f64::from(j) / f64::from(h),
                ));
            }
        }
        for j in 0..h {
            for i in 0..w {
                let k = j * (w + 1) + i;
                m.triangles.push([k, k + 1, k + w + 1]);
                m.triangles.push([k + 1, k + w + 2, k + w + 1]);
            }
        }
        m.uv_indices = m.triangles.clone();
        m
    }

    fn camera(
        distribution: u8,
        rays: u32,
        meshes: Vec<(ir::Mesh, Option<ir::Transform>)>,
    ) -> MeshCamera {
        MeshCamera::new(&Arc::new(ir::MeshCamera {
            rays_per_pixel: rays,
            distribution,
            max_distance: 0.0,
            meshes: meshes.into_iter().map(|(m, t)| (Arc::new(m), t)).collect(),
            smooth: false,
            offset: 0.0,
            reversed: false,
        }))
    }

    /// The centroid of face `k` of `mesh`.
    fn centroid(mesh: &ir::Mesh, k: usize) -> DVec3 {
        mesh.triangles[k]
            .map(|i| mesh.vertices[i as usize].as_dvec3())
            .iter()
            .sum::<DVec3>()
            / 3.0
    }

    #[test]
    fn distribution_0_numbers_faces_by_pixel_with_povray_row_shift() {
        // 4 × 3 pixels, 12 faces: the face of pixel (x, y) is y' · 4 + x with y' the row of
        // POV-Ray's sample point y − ½ cut to whole pixels (rows 0 and 1 both take row 0).
        let mesh = grid(3, 2);
        let cam = camera(0, 1, vec![(mesh.clone(), None)]);
        for (x, y, face) in [(0, 0, 0), (3, 0, 3), (0, 1, 0), (2, 1, 2), (1, 2, 5)] {
            let ray = cam.ray(x as f64, y as f64, 4, 3, 0).expect("a face");
            assert!(
                (ray.origin - centroid(&mesh, face)).length() < 1e-9,
                "pixel ({x}, {y})"
            );
            assert!((ray.direction - DVec3::Z).length() < 1e-12);
        }
        // 12 faces for 4 × 4 pixels: the last row's faces do not exist.
        assert!(cam.ray(0.0, 3.0, 4, 4, 0).is_some());
        assert!(cam.ray(0.0, 4.0, 4, 5, 0).is_none());
    }

    #[test]
    fn distribution_0_takes_ray_k_from_mesh_k_and_1_numbers_the_meshes_on() {
        let (a, b) = (grid(1, 1), grid(2, 1));
        let moved = ir::Transform {
            matrix: glam::DMat4::from_translation(DVec3::new(0.0, 0.0, 5.0)),
        };
        let cam = camera(0, 2, vec![(a.clone(), None), (b.clone(), Some(moved))]);
        let second = cam.ray(1.0, 0.0, 2, 1, 1).expect("face 1 of mesh 1");
        assert!((second.origin - (centroid(&b, 1) + DVec3::new(0.0, 0.0, 5.0))).length() < 1e-9);
        // Distribution 1: 2 + 4 faces numbered on; pixel 4 of a 6 × 1 image is mesh 1's
        // face 2; a second ray has no face (POV-Ray adds the face count for each ray).
        let cam = camera(1, 2, vec![(a, None), (b.clone(), Some(moved))]);
        let ray = cam.ray(4.0, 0.0, 6, 1, 0).expect("a face");
        assert!((ray.origin - (centroid(&b, 2) + DVec3::new(0.0, 0.0, 5.0))).length() < 1e-9);
        assert!(cam.ray(0.0, 0.0, 6, 1, 1).is_none());
        assert_eq!(cam.rays_per_pixel(), 1);
    }

    #[test]
    fn faces_of_no_area_keep_their_numbers() {
        // A mesh2's face of no area (dropped by trace, kept by POV-Ray) still takes its
        // number: the faces after it are where POV-Ray finds them, and its own pixel has no ray.
        let full = grid(3, 1);
        let mut m = full.clone();
        m.triangles.remove(2);
        m.dropped_faces = vec![2];
        let cam = camera(0, 1, vec![(m, None)]);
        assert!(cam.ray(2.0, 0.0, 6, 1, 0).is_none());
        for x in [1u32, 3, 5] {
            let ray = cam.ray(f64::from(x), 0.0, 6, 1, 0).expect("a face");
            assert!(
                (ray.origin - centroid(&full, x as usize)).length() < 1e-9,
                "pixel {x}"
            );
        }
    }

    #[test]
    fn distribution_2_puts_meshes_side_by_side() {
        // Two meshes across an 8-pixel-wide image: pixel 5 is in the second strip, whose face
        // POV-Ray numbers from the whole image's column (5), not the strip's.
        let (a, b) = (grid(4, 1), grid(4, 1));
        let moved = ir::Transform {
            matrix: glam::DMat4::from_translation(DVec3::new(10.0, 0.0, 0.0)),
        };
        let cam = camera(2, 1, vec![(a, None), (b.clone(), Some(moved))]);
        let ray = cam.ray(5.0, 0.0, 8, 1, 0).expect("a face");
        assert!((ray.origin - (centroid(&b, 5) + DVec3::new(10.0, 0.0, 0.0))).length() < 1e-9);
    }

    #[test]
    fn offset_reversal_and_transformation_move_the_ray() {
        let mesh = grid(1, 1);
        let scale = ir::Transform {
            matrix: glam::DMat4::from_scale(DVec3::new(1.0, 1.0, 2.0)),
        };
        let cam = MeshCamera::new(&Arc::new(ir::MeshCamera {
            rays_per_pixel: 1,
            distribution: 0,
            max_distance: 7.0,
            meshes: vec![(Arc::new(mesh.clone()), Some(scale))],
            smooth: false,
            offset: 0.5,
            reversed: true,
        }));
        let ray = cam.ray(0.0, 0.0, 2, 1, 0).expect("a face");
        // 0.5 along the face normal (+z) in the mesh's space, then scaled; reversed: −z.
        let expected = centroid(&mesh, 0) + DVec3::new(0.0, 0.0, 1.0);
        assert!((ray.origin - expected).length() < 1e-9);
        assert!((ray.direction - DVec3::NEG_Z).length() < 1e-12);
        assert_eq!(ray.tmax, 7.0);
    }

    #[test]
    fn distribution_3_finds_the_face_holding_the_pixels_uv() {
        // A 2 × 2 grid with uv over [0, 1]²: pixel (x, y) of a 4 × 4 image looks at
        // u = (x' − ½) / 4, v = 1 − (y' + ½) / 4 with x' = x + ½, y' = y − ½ (clipped to the
        // image, not cut to whole pixels here): the point of the grid at those coordinates.
        let mesh = grid(2, 2);
        let cam = camera(3, 1, vec![(mesh, None)]);
        for (x, y) in [(0u32, 0u32), (1, 1), (2, 3), (3, 2)] {
            let ray = cam
                .ray(f64::from(x), f64::from(y), 4, 4, 0)
                .expect("a face");
            let yy = (f64::from(y) - 0.5).max(0.0);
            let xx = (f64::from(x) + 0.5).min(3.0);
            let (u, v) = ((xx - 0.5) / 4.0, 1.0 - (yy + 0.5) / 4.0);
            let expected = DVec3::new(2.0 * u, -2.0 * (1.0 - v), 0.0);
            assert!(
                (ray.origin - expected).length() < 1e-9,
                "pixel ({x}, {y}): {} against {expected}",
                ray.origin
            );
        }
        // A sheet covering only u < ½ sees nothing on the right.
        let mut half = grid(2, 2);
        for uv in &mut half.uvs {
            uv.x *= 0.5;
        }
        let cam = camera(3, 1, vec![(half, None)]);
        assert!(cam.ray(1.0, 1.0, 4, 4, 0).is_some());
        assert!(cam.ray(3.0, 1.0, 4, 4, 0).is_none());
    }
}
