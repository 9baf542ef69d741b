//! Mesh BVH benchmarks: build time, and rays per second for coherent camera rays, incoherent
//! random rays, and shadow (any-hit) rays, on height-field meshes of 10k to 1M triangles
//! (10M with `TRACE_BENCH_10M=1`; it needs about 3 GB; `TRACE_BENCH_SIZES=10000` runs one).
//!
//! Run: `cargo bench --bench bvh`. Divan prints the time per iteration and, for the ray
//! benchmarks, the throughput (rays per second, "item/s").

use divan::{Bencher, black_box, counter::ItemsCount};
use glam::{DVec3, Vec3};
use std::sync::OnceLock;
use trace::geometry::Ray;
use trace::geometry::mesh::TriangleMesh;

fn main() {
    divan::main();
}

const SIZES: &[usize] = &[10_000, 100_000, 1_000_000];
const RAYS: usize = 20_000;

/// Triangle counts to run: the standard sizes, plus 10M on request, or those listed in
/// `TRACE_BENCH_SIZES` (e.g. `10000,1000000`; for profiling one size).
fn sizes() -> Vec<usize> {
    if let Some(list) = std::env::var_os("TRACE_BENCH_SIZES") {
        return list
            .to_string_lossy()
            .split(',')
            .filter_map(|n| n.trim().parse().ok())
            .collect();
    }
    let mut s = SIZES.to_vec();
    if std::env::var_os("TRACE_BENCH_10M").is_some() {
        s.push(10_000_000);
    }
    s
}

/// A height field of about `triangles` triangles over [-10, 10]².
fn terrain(triangles: usize) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let side = ((triangles as f64 / 2.0).sqrt().round() as usize + 1).max(2);
    let mut vertices = Vec::with_capacity(side * side);
    for j in 0..side {
        for i in 0..side {
            let x = 20.0 * (i as f64 / (side - 1) as f64 - 0.5);
            let z = 20.0 * (j as f64 / (side - 1) as f64 - 0.5);
            let y = 0.8 * (0.9 * x).sin() * (0.7 * z).cos() + 0.3 * (2.3 * x + 1.7 * z).sin();
            vertices.push(DVec3::new(x, y, z).as_vec3());
        }
    }
    let mut faces = Vec::with_capacity(2 * (side - 1) * (side - 1));
    for j in 0..side - 1 {
        for i in 0..side - 1 {
            let a = (j * side + i) as u32;
            let s = side as u32;
            faces.push([a, a + s, a + 1]);
            faces.push([a + 1, a + s, a + s + 1]);
        }
    }
    (vertices, faces)
}

/// The mesh of each size, built once per process.
fn mesh(triangles: usize) -> &'static TriangleMesh {
    static MESHES: OnceLock<std::sync::Mutex<Vec<(usize, &'static TriangleMesh)>>> =
        OnceLock::new();
    let cache = MESHES.get_or_init(Default::default);
    let mut cache = cache.lock().expect("not poisoned");
    if let Some((_, m)) = cache.iter().find(|(n, _)| *n == triangles) {
        return m;
    }
    let (v, t) = terrain(triangles);
    let m: &'static TriangleMesh = Box::leak(Box::new(TriangleMesh::new(
        v,
        t,
        vec![],
        vec![],
        vec![],
        vec![],
    )));
    cache.push((triangles, m));
    m
}

/// A small deterministic generator (xorshift) for the random rays.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Camera rays from above the terrain through a 2D grid of image positions.
fn camera_rays() -> Vec<Ray> {
    let side = (RAYS as f64).sqrt() as usize;
    let eye = DVec3::new(0.0, 12.0, -18.0);
    let mut rays = Vec::with_capacity(side * side);
    for j in 0..side {
        for i in 0..side {
            let target = DVec3::new(
                20.0 * (i as f64 / side as f64 - 0.5),
                0.0,
                20.0 * (j as f64 / side as f64 - 0.5),
            );
            rays.push(Ray::new(eye, target - eye));
        }
    }
    rays
}

/// Rays with random origins above the terrain and random downward-ish directions.
fn random_rays() -> Vec<Ray> {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    (0..RAYS)
        .map(|_| {
            let o = DVec3::new(
                20.0 * rng.next() - 10.0,
                3.0 * rng.next() + 1.5,
                20.0 * rng.next() - 10.0,
            );
            let d = DVec3::new(
                2.0 * rng.next() - 1.0,
                -rng.next() - 0.05,
                2.0 * rng.next() - 1.0,
            );
            Ray::new(o, d)
        })
        .collect()
}

/// Shadow rays from the points the camera rays hit towards a light (ending at the light).
fn shadow_rays(m: &TriangleMesh) -> Vec<Ray> {
    let light = DVec3::new(-20.0, 30.0, -10.0);
    camera_rays()
        .iter()
        .filter_map(|r| {
            let t = m.intersect(r).as_slice().first().copied()?;
            let p = r.at(t);
            let mut s = Ray::new(p, light - p);
            s.tmin = 1e-6;
            s.tmax = 1.0;
            Some(s)
        })
        .collect()
}

#[divan::bench(args = sizes(), sample_count = 5)]
fn build(bencher: Bencher, triangles: usize) {
    let (v, t) = terrain(triangles);
    bencher
        .with_inputs(|| (v.clone(), t.clone()))
        .bench_values(|(v, t)| TriangleMesh::new(v, t, vec![], vec![], vec![], vec![]));
}

#[divan::bench(args = sizes())]
fn camera(bencher: Bencher, triangles: usize) {
    let m = mesh(triangles);
    let rays = camera_rays();
    bencher.counter(ItemsCount::new(rays.len())).bench(|| {
        for r in &rays {
            black_box(m.intersect(r));
        }
    });
}

#[divan::bench(args = sizes())]
fn random(bencher: Bencher, triangles: usize) {
    let m = mesh(triangles);
    let rays = random_rays();
    bencher.counter(ItemsCount::new(rays.len())).bench(|| {
        for r in &rays {
            black_box(m.intersect(r));
        }
    });
}

#[divan::bench(args = sizes())]
fn shadow(bencher: Bencher, triangles: usize) {
    let m = mesh(triangles);
    let rays = shadow_rays(m);
    bencher.counter(ItemsCount::new(rays.len())).bench(|| {
        for r in &rays {
            black_box(m.occluded(r));
        }
    });
}
