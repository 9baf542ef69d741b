//! `bicubic_patch`: POV-Ray draws a Bézier patch as the triangles of its subdivision, made
//! from the control points already carried into the world (so `flatness` is judged in world
//! units), so trace makes the same triangles into a mesh.
//!
//! POV-Ray's subdivision (both patch types give the same triangles): halve the patch by de
//! Casteljau steps, in u while fewer than `u_steps` halvings were made and in v while fewer
//! than `v_steps`, unless its 16 control points lie closer than `flatness` to the plane of its
//! corners; each piece is two triangles split along its (u0, v0)–(u1, v1) diagonal, shaded by
//! blending the exact surface normals at their corners (a corner where the surface has no
//! normal, as at a pole, takes POV-Ray's <1, 0, 0>). Its uv coordinates (for `uv_mapping`) are
//! the patch's parameters interpolated across each triangle, v first, as POV-Ray's.

use super::TriangleMesh;
use glam::DVec3;

/// A patch's control points, u index first.
pub type Net = [[DVec3; 4]; 4];

/// The most halvings a side trace makes (512 pieces; POV-Ray sets no limit, and scenes use
/// up to 5 or 6).
const MAX_STEPS: u32 = 9;

fn half(a: DVec3, b: DVec3) -> DVec3 {
    0.5 * (a + b)
}

/// One row of four control points split at its middle (POV-Ray's order of halvings).
fn split_row(q: [DVec3; 4]) -> ([DVec3; 4], [DVec3; 4]) {
    let l1 = half(q[0], q[1]);
    let m = half(q[1], q[2]);
    let l2 = half(l1, m);
    let r2 = half(q[2], q[3]);
    let r1 = half(m, r2);
    let mid = half(l2, r1);
    ([q[0], l1, l2, mid], [mid, r1, r2, q[3]])
}

/// The net split in u (its first index).
fn split_u(p: &Net) -> (Net, Net) {
    let (mut a, mut b) = (*p, *p);
    for j in 0..4 {
        let (l, r) = split_row([p[0][j], p[1][j], p[2][j], p[3][j]]);
        for i in 0..4 {
            a[i][j] = l[i];
            b[i][j] = r[i];
        }
    }
    (a, b)
}

/// The net split in v (its second index).
fn split_v(p: &Net) -> (Net, Net) {
    let (mut a, mut b) = (*p, *p);
    for i in 0..4 {
        let (l, r) = split_row(p[i]);
        a[i] = l;
        b[i] = r;
    }
    (a, b)
}

/// POV-Ray's flatness test: every control point within `flatness` of the corners' plane.
fn flat_enough(p: &Net, flatness: f64) -> bool {
    let eps = 1e-10;
    let (a, b, c) = if (p[0][0] - p[0][3]).length() >= eps {
        (p[0][0], p[0][3], p[3][0])
    } else {
        (p[0][0], p[3][3], p[3][0])
    };
    if (a - b).length() < eps || (b - c).length() < eps {
        return false;
    }
    let (ab, cb) = (a - b, c - b);
    let n = ab.cross(cb);
    if n.length_squared() <= 1e-10 * ab.length_squared() * cb.length_squared() {
        return false;
    }
    let n = n.normalize();
    let d = -n.dot(a);
    let dist = p
        .iter()
        .flatten()
        .map(|q| (n.dot(*q) + d).abs())
        .fold(0.0, f64::max);
    dist < flatness
}

fn bernstein(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t]
}

fn bernstein_slope(t: f64) -> [f64; 4] {
    let s = 1.0 - t;
    [
        -3.0 * s * s,
        3.0 * s * s - 6.0 * t * s,
        6.0 * t * s - 3.0 * t * t,
        3.0 * t * t,
    ]
}

/// The patch's unit normal at (u, v), or POV-Ray's <1, 0, 0> where it has none.
fn normal_at(p: &Net, u: f64, v: f64) -> DVec3 {
    let (bu, bv, du, dv) = (
        bernstein(u),
        bernstein(v),
        bernstein_slope(u),
        bernstein_slope(v),
    );
    let (mut su, mut sv) = (DVec3::ZERO, DVec3::ZERO);
    for i in 0..4 {
        for j in 0..4 {
            su += du[i] * bv[j] * p[i][j];
            sv += bu[i] * dv[j] * p[i][j];
        }
    }
    let n = su.cross(sv);
    if n.length_squared() > 1e-10 * su.length_squared() * sv.length_squared() {
        n.normalize()
    } else {
        DVec3::X
    }
}

/// The triangles of a patch: corners, each with the patch's normal and uv there.
#[derive(Default)]
struct Pieces {
    vertices: Vec<DVec3>,
    normals: Vec<DVec3>,
    uvs: Vec<glam::DVec2>,
}

/// The mesh POV-Ray renders for the patch with control points `points` (u index first).
/// `uv_corners` map the patch's unit square of (v, u) bilinearly to its uv (POV-Ray's
/// `uv_vectors`); trace maps the triangles' corners and interpolates across each triangle,
/// where POV-Ray maps each point: the same when the corners form a parallelogram (the map is
/// then affine), a hair off otherwise.
pub fn patch_mesh(
    points: &Net,
    u_steps: u32,
    v_steps: u32,
    flatness: f64,
    uv_corners: Option<[[f64; 2]; 4]>,
) -> TriangleMesh {
    let mut pieces = Pieces::default();
    subdivide(
        points,
        points,
        (0.0, 1.0),
        (0.0, 1.0),
        0,
        (u_steps, v_steps),
        flatness,
        &mut pieces,
    );
    if let Some(st) = uv_corners {
        let st = st.map(|c| glam::DVec2::new(c[0], c[1]));
        for p in &mut pieces.uvs {
            // (POV-Ray's Compute_Texture_UV: along the first coordinate, then the second.)
            let low = st[0] + p.x * (st[1] - st[0]);
            let high = st[3] + p.x * (st[2] - st[3]);
            *p = low + p.y * (high - low);
        }
    }
    let n = pieces.vertices.len() as u32 / 3;
    let triangles: Vec<[u32; 3]> = (0..n).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]).collect();
    // (In single precision, as a mesh's: the patch moves by under 1e-7 of its size.)
    TriangleMesh::new(
        pieces.vertices.iter().map(|v| v.as_vec3()).collect(),
        triangles.clone(),
        pieces.normals.iter().map(|n| n.as_vec3()).collect(),
        triangles.clone(),
        pieces.uvs,
        triangles,
    )
}

#[allow(clippy::too_many_arguments)]
fn subdivide(
    whole: &Net,
    p: &Net,
    (u0, u1): (f64, f64),
    (v0, v1): (f64, f64),
    depth: u32,
    (us, vs): (u32, u32),
    flatness: f64,
    mesh: &mut Pieces,
) {
    // Bounded: a scene asking for more halvings gets `MAX_STEPS`.
    let (us, vs) = (us.min(MAX_STEPS), vs.min(MAX_STEPS));
    if flat_enough(p, flatness) || (depth >= us && depth >= vs) {
        leaf(whole, p, (u0, u1), (v0, v1), mesh);
        return;
    }
    let (um, vm) = (0.5 * (u0 + u1), 0.5 * (v0 + v1));
    let next = depth + 1;
    if depth >= us {
        let (a, b) = split_v(p);
        subdivide(
            whole,
            &a,
            (u0, u1),
            (v0, vm),
            next,
            (us, vs),
            flatness,
            mesh,
        );
        subdivide(
            whole,
            &b,
            (u0, u1),
            (vm, v1),
            next,
            (us, vs),
            flatness,
            mesh,
        );
    } else if depth >= vs {
        let (a, b) = split_u(p);
        subdivide(
            whole,
            &a,
            (u0, um),
            (v0, v1),
            next,
            (us, vs),
            flatness,
            mesh,
        );
        subdivide(
            whole,
            &b,
            (um, u1),
            (v0, v1),
            next,
            (us, vs),
            flatness,
            mesh,
        );
    } else {
        let (left, right) = split_u(p);
        let (ll, ul) = split_v(&left);
        let (lr, ur) = split_v(&right);
        subdivide(
            whole,
            &ll,
            (u0, um),
            (v0, vm),
            next,
            (us, vs),
            flatness,
            mesh,
        );
        subdivide(
            whole,
            &ul,
            (u0, um),
            (vm, v1),
            next,
            (us, vs),
            flatness,
            mesh,
        );
        subdivide(
            whole,
            &lr,
            (um, u1),
            (v0, vm),
            next,
            (us, vs),
            flatness,
            mesh,
        );
        subdivide(
            whole,
            &ur,
            (um, u1),
            (vm, v1),
            next,
            (us, vs),
            flatness,
            mesh,
        );
    }
}

/// A piece's two triangles, (Q00, Q03, Q33) and (Q00, Q33, Q30), each with the patch's
/// normals at its corners; POV-Ray skips degenerate ones.
fn leaf(whole: &Net, q: &Net, (u0, u1): (f64, f64), (v0, v1): (f64, f64), mesh: &mut Pieces) {
    let corners = [
        (q[0][0], u0, v0),
        (q[0][3], u0, v1),
        (q[3][3], u1, v1),
        (q[3][0], u1, v0),
    ];
    for tri in [[0, 1, 2], [0, 2, 3]] {
        let [a, b, c] = tri.map(|k| corners[k]);
        let (e0, e1) = (b.0 - a.0, c.0 - a.0);
        let cross = e0.cross(e1);
        if cross.length_squared() <= 1e-10 * e0.length_squared() * e1.length_squared()
            || cross.length() < 1e-10
        {
            continue;
        }
        for (p, u, v) in [a, b, c] {
            mesh.vertices.push(p);
            mesh.normals.push(normal_at(whole, u, v));
            // (POV-Ray's uv of a patch: the second parameter first.)
            mesh.uvs.push(glam::DVec2::new(v, u));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat patch (z = 0 over the unit square) gives 2 triangles when flat enough, and
    /// 2 · 4^n with n halvings each way otherwise.
    #[test]
    fn flat_patch_subdivision() {
        let mut net = [[DVec3::ZERO; 4]; 4];
        for (i, row) in net.iter_mut().enumerate() {
            for (j, p) in row.iter_mut().enumerate() {
                *p = DVec3::new(i as f64 / 3.0, j as f64 / 3.0, 0.0);
            }
        }
        let count = |u, v, f| {
            let mut pieces = Pieces::default();
            subdivide(
                &net,
                &net,
                (0.0, 1.0),
                (0.0, 1.0),
                0,
                (u, v),
                f,
                &mut pieces,
            );
            pieces.vertices.len() / 3
        };
        assert_eq!(count(3, 3, 0.01), 2);
        assert_eq!(count(3, 3, 0.0), 2 * 64);
        assert_eq!(count(2, 1, 0.0), 2 * 8);
        assert!((normal_at(&net, 0.3, 0.6) - DVec3::Z).length() < 1e-12);
        // A pole: all of row 0 at one point; its corner normal is POV-Ray's <1, 0, 0>.
        for p in net[0].iter_mut() {
            *p = DVec3::ZERO;
        }
        assert_eq!(normal_at(&net, 0.0, 0.5), DVec3::X);
    }
}
