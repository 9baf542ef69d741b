//! The top-level structure over objects: an obvhs `Bvh2` over the world boxes of the bounded
//! objects, with unbounded ones (planes) kept in a list beside it. Scenes with few objects
//! skip it and test every object (see [`MIN_OBJECTS_FOR_BVH`]).

use crate::geometry::Ray;
use crate::geometry::mesh::{bvh_ray, outward_aabb};
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb;
use obvhs::bvh2::Bvh2;
use obvhs::ray::RayHit;
use std::time::Duration;

/// Below this many bounded objects a linear scan (with a box test per object) is as fast as
/// a BVH (measured with `benches/`-style runs on sphere grids: 8 spheres ran at parity).
pub const MIN_OBJECTS_FOR_BVH: usize = 8;

/// Objects organised for ray queries.
pub struct ObjectIndex {
    bvh: Bvh2,
    /// Object ids in BVH primitive order.
    bounded: Vec<u32>,
    /// Objects without bounds, tested for every ray.
    pub unbounded: Vec<u32>,
}

impl std::fmt::Debug for ObjectIndex {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ObjectIndex")
            .field("bounded", &self.bounded.len())
            .field("unbounded", &self.unbounded.len())
            .finish()
    }
}

/// The boxes an index will be built over (see [`ObjectIndex::prepare`]).
pub struct Prepared {
    /// The boxes of the bounded objects, slightly grown.
    boxes: Vec<Aabb>,
    /// The object of each box.
    ids: Vec<u32>,
    unbounded: Vec<u32>,
}

impl ObjectIndex {
    /// The boxes for an index over objects of the given world bounds, if the scene is big
    /// enough to gain from one (the bounds may be freed before [`Prepared::build`]).
    pub fn prepare(bounds: &[Option<(glam::DVec3, glam::DVec3)>]) -> Option<Prepared> {
        // A box too big for f32 (or not finite) goes to the unbounded list: the builder
        // cannot place it.
        let as_box = |b: &Option<(glam::DVec3, glam::DVec3)>| {
            b.map(|(lo, hi)| outward_aabb(lo, hi))
                .filter(|a| a.min.is_finite() && a.max.is_finite())
        };
        let bounded = bounds.iter().filter(|b| as_box(b).is_some()).count();
        if bounded < MIN_OBJECTS_FOR_BVH {
            return None;
        }
        let mut prepared = Prepared {
            boxes: Vec::with_capacity(bounded),
            ids: Vec::with_capacity(bounded),
            unbounded: Vec::new(),
        };
        for (i, b) in bounds.iter().enumerate() {
            match as_box(b) {
                // Each box grows by its own tiny fraction (below 1e-4 of its size; growing is
                // always safe): equal boxes at equal spacing (spheres made in a loop along a
                // line) tie in PLOC's nearest-neighbour search, so that only one pair merged
                // per pass and the build took quadratic time (100k spheres in a row: over
                // 100 s; found by the fuzzer).
                Some(b) => {
                    let k = prepared.boxes.len() as u32;
                    let grow = (b.max - b.min) * (1e-4 * tie_breaker(k));
                    prepared.boxes.push(Aabb {
                        min: b.min - grow,
                        max: b.max + grow,
                    });
                    prepared.ids.push(i as u32);
                }
                None => prepared.unbounded.push(i as u32),
            }
        }
        Some(prepared)
    }
}

impl Prepared {
    /// Builds the index.
    pub fn build(self) -> ObjectIndex {
        // Object tests cost more than box tests (transforms, several shape kinds): small leaves.
        let params = BvhBuildParams {
            max_prims_per_leaf: 1,
            ..BvhBuildParams::fast_build()
        };
        let mut bvh =
            obvhs::bvh2::builder::build_bvh2(&self.boxes, params, &mut Duration::default());
        drop(self.boxes);
        // (A ray's walk reads nodes scattered over megabytes at a million objects.)
        bvh.nodes = crate::memory::into_huge_pages(std::mem::take(&mut bvh.nodes));
        let mut bounded = crate::memory::with_huge_pages(bvh.primitive_indices.len());
        bounded.extend(bvh.primitive_indices.iter().map(|&k| self.ids[k as usize]));
        ObjectIndex {
            bvh,
            bounded,
            unbounded: self.unbounded,
        }
    }
}

impl ObjectIndex {
    /// Closest-hit traversal: `f(object, tmax)` returns the object's nearest distance below
    /// `tmax`, if any; the best is kept and prunes the rest.
    pub fn closest(&self, ray: &Ray, mut f: impl FnMut(u32, f64) -> Option<f64>) {
        let mut tmax = ray.tmax;
        self.bvh
            .ray_traverse(bvh_ray(ray, tmax), &mut RayHit::none(), |_, k| {
                match f(self.bounded[k], tmax) {
                    Some(t) => {
                        tmax = t;
                        ((t * (1.0 + 1e-6)) as f32).next_up()
                    }
                    None => f32::INFINITY,
                }
            });
    }

    /// Visits every bounded object whose box the ray meets, stopping when `f` returns true.
    pub fn any(&self, ray: &Ray, mut f: impl FnMut(u32) -> bool) -> bool {
        !self.bvh.ray_traverse_miss(bvh_ray(ray, ray.tmax), |_, k| {
            if f(self.bounded[k]) {
                0.0
            } else {
                f32::INFINITY
            }
        })
    }

    /// Visits every bounded object in a leaf whose box `keep(min, max)` keeps, descending only
    /// into nodes it keeps (the node boxes hold their objects' boxes, rounded outward).
    pub fn each_kept(
        &self,
        keep: impl Fn(glam::DVec3, glam::DVec3) -> bool,
        mut f: impl FnMut(u32),
    ) {
        let nodes = &self.bvh.nodes;
        let Some(root) = nodes.first() else { return };
        let kept = |n: &obvhs::bvh2::node::Bvh2Node| {
            let a = n.aabb();
            keep(a.min.as_dvec3(), a.max.as_dvec3())
        };
        if !kept(root) {
            return;
        }
        // (Called for every shading point under an area light: the stack is kept per thread.)
        thread_local! {
            static STACK: std::cell::RefCell<Vec<u32>> = const { std::cell::RefCell::new(Vec::new()) };
        }
        STACK.with_borrow_mut(|stack| {
            stack.clear();
            stack.push(0);
            while let Some(i) = stack.pop() {
                let node = &nodes[i as usize];
                if node.is_leaf() {
                    let first = node.first_index as usize;
                    for k in first..first + node.prim_count as usize {
                        f(self.bounded[k]);
                    }
                    continue;
                }
                for child in [node.first_index, node.first_index + 1] {
                    if kept(&nodes[child as usize]) {
                        stack.push(child);
                    }
                }
            }
        });
    }
}

/// A number in [0, 1) that differs from one `k` to the next (a 32-bit integer hash).
fn tie_breaker(k: u32) -> f32 {
    let mut h = k.wrapping_mul(0x9E37_79B9);
    h ^= h >> 16;
    h = h.wrapping_mul(0x85EB_CA6B);
    h ^= h >> 13;
    (h >> 8) as f32 / (1u32 << 24) as f32
}
