//! The top-level structure over objects: the world boxes of the bounded objects in a tree
//! obvhs builds, collapsed into eight children a node (the meshes' [`WideTree`]), with
//! unbounded ones (planes) kept in a list beside it. Scenes with few objects skip it and
//! test every object (see [`MIN_OBJECTS_FOR_BVH`]).

use crate::geometry::Ray;
use crate::geometry::mesh::{outward_aabb, prune_value};
use crate::geometry::wide::{PACKET, WideTree, bits};
use glam::DVec3;
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb;
use std::time::Duration;

/// Below this many bounded objects a linear scan (with a box test per object) is as fast as
/// a BVH (measured with `benches/`-style runs on sphere grids: 8 spheres ran at parity).
pub const MIN_OBJECTS_FOR_BVH: usize = 8;

/// Objects organised for ray queries.
pub struct ObjectIndex {
    tree: WideTree,
    /// Object ids in the leaves' order, a leaf's last one marked with [`LAST`]; a leaf's
    /// payload is the position of its first.
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

/// The bit that marks the last object of a leaf in [`ObjectIndex::bounded`].
const LAST: u32 = 1 << 31;

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
        let bvh = obvhs::bvh2::builder::build_bvh2(&self.boxes, params, &mut Duration::default());
        drop(self.boxes);
        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        if let Some(root) = bvh.nodes.first() {
            (lo, hi) = (root.aabb.min.as_dvec3(), root.aabb.max.as_dvec3());
        }
        let mut bounded = crate::memory::with_huge_pages(bvh.primitive_indices.len());
        let tree = WideTree::collapse(&bvh, (lo, hi), |range| {
            let first = bounded.len() as u32;
            let ids = &bvh.primitive_indices[range];
            bounded.extend(ids.iter().map(|&k| self.ids[k as usize]));
            *bounded.last_mut().expect("a leaf holds an object") |= LAST;
            first
        });
        ObjectIndex {
            tree,
            bounded,
            unbounded: self.unbounded,
        }
    }
}

impl ObjectIndex {
    /// Calls `f` with each object of the leaf at `first` until it returns true; whether it
    /// did.
    #[inline(always)]
    fn leaf(&self, first: u32, mut f: impl FnMut(u32) -> bool) -> bool {
        for &id in &self.bounded[first as usize..] {
            if f(id & !LAST) {
                return true;
            }
            if id & LAST != 0 {
                break;
            }
        }
        false
    }

    /// Closest-hit traversal: `f(object, tmax)` returns the object's nearest distance below
    /// `tmax`, if any; the best is kept and prunes the rest.
    pub fn closest(&self, ray: &Ray, mut f: impl FnMut(u32, f64) -> Option<f64>) {
        let mut tmax = ray.tmax;
        let visit = |first: u32, _| {
            let mut hit = false;
            self.leaf(first, |i| {
                if let Some(t) = f(i, tmax) {
                    tmax = t;
                    hit = true;
                }
                false
            });
            if hit {
                prune_value(tmax)
            } else {
                f32::INFINITY
            }
        };
        self.tree
            .walk::<true>(ray, prune_value(ray.tmax), |_| {}, visit);
    }

    /// Visits every bounded object whose box the ray meets, stopping when `f` returns true;
    /// whether it did.
    /// [`ObjectIndex::closest`] for a packet of up to [`PACKET`] rays walked together:
    /// `f(rays, i, tmax)` offers object `i` to the rays of mask `rays` (ray `k` is bit `k`),
    /// ray `k`'s nearest hit so far being at `tmax[k]` (at first as given, not beyond its
    /// end), which it lowers where it finds one nearer.
    pub fn closest_packet(
        &self,
        rays: &[Ray],
        tmax: &[f64; PACKET],
        mut f: impl FnMut(u32, u32, &mut [f64; PACKET]),
    ) {
        let mut tmax = *tmax;
        let limits = &mut tmax.map(prune_value);
        self.tree
            .walk_packet(rays, limits, |rays_in, first, limits| {
                self.leaf(first, |i| {
                    f(rays_in, i, &mut tmax);
                    false
                });
                for k in bits(rays_in) {
                    limits[k] = limits[k].min(prune_value(tmax[k]));
                }
            });
    }

    pub fn any(&self, ray: &Ray, mut f: impl FnMut(u32) -> bool) -> bool {
        let mut found = false;
        let visit = |first: u32, _| {
            if self.leaf(first, &mut f) {
                found = true;
                -1.0
            } else {
                f32::INFINITY
            }
        };
        self.tree
            .walk::<false>(ray, prune_value(ray.tmax), |_| {}, visit);
        found
    }

    /// Visits every bounded object in a leaf whose box `keep(min, max)` keeps, descending only
    /// into nodes it keeps (the node boxes hold their objects' boxes, rounded outward).
    pub fn each_kept(&self, keep: impl Fn(DVec3, DVec3) -> bool, mut f: impl FnMut(u32)) {
        self.tree.each_kept(keep, |first| {
            self.leaf(first, |i| {
                f(i);
                false
            });
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::Xorshift;

    /// A point of the cube of side `size` around the origin.
    fn point(r: &mut Xorshift, size: f64) -> DVec3 {
        DVec3::new(r.unit() - 0.5, r.unit() - 0.5, r.unit() - 0.5) * size
    }

    /// The distance at which the ray enters box `(lo, hi)` within [0, tmax], by exact slabs
    /// in double precision (None if it misses it).
    fn entry(ray: &Ray, (lo, hi): (DVec3, DVec3)) -> Option<f64> {
        let (mut near, mut far) = (0.0f64, ray.tmax);
        for axis in 0..3 {
            let (o, d) = (ray.origin[axis], ray.direction[axis]);
            if d == 0.0 {
                if o < lo[axis] || o > hi[axis] {
                    return None;
                }
                continue;
            }
            let (a, b) = ((lo[axis] - o) / d, (hi[axis] - o) / d);
            near = near.max(a.min(b));
            far = far.min(a.max(b));
        }
        // (Clear of the exact slabs' own rounding.)
        (near < far * (1.0 - 1e-12)).then_some(near)
    }

    /// The index answers as testing every object's box does: a walk visits every object
    /// whose box the ray enters, the nearest-first walk finds the nearest of them, a
    /// stopping walk stops, and a point query keeps every box that holds the point: with
    /// boxes near the origin and far from it, large and tiny, unbounded ones beside them,
    /// rays from inside and outside, axis-aligned and grazing, shadow-like with an end. So
    /// do packets of rays walked together (incoherent ones, and rays from one point in
    /// nearly one direction, some of mixed signs), with and without AVX2: each ray visits
    /// every box it enters and finds the nearest.
    #[test]
    fn index_finds_what_every_box_finds() {
        let mut r = Xorshift(0x9E37_79B9_7F4A_7C15);
        let mut checked = 0;
        let mut packet_hits = 0;
        for (case, (offset, size, count)) in [
            (0.0, 10.0, 9),
            (0.0, 10.0, 300),
            (1e5, 1.0, 100),
            (-3e3, 1e-3, 50),
            (20.0, 1e4, 1000),
        ]
        .into_iter()
        .enumerate()
        {
            let centre = DVec3::new(offset, 0.5 * offset, -offset);
            let mut bounds = Vec::new();
            for k in 0..count {
                if k % 17 == 5 {
                    bounds.push(None);
                    continue;
                }
                let lo = centre + point(&mut r, size);
                let extent = point(&mut r, size * [0.2, 0.01, 1e-6][k % 3]).abs();
                bounds.push(Some((lo, lo + extent)));
            }
            let index = ObjectIndex::prepare(&bounds)
                .expect("enough objects")
                .build();
            assert_eq!(
                index.unbounded,
                (0..count as u32)
                    .filter(|&k| k % 17 == 5)
                    .collect::<Vec<_>>()
            );
            let mut rays = Vec::new();
            for k in 0..2000 {
                let origin = centre + point(&mut r, size * [0.5, 3.0, 100.0][k % 3]);
                // Half the rays aimed at a point inside a box.
                let target = match bounds[(k * 13) % count] {
                    Some((lo, hi)) if k % 2 == 0 => lo + (hi - lo) * r.unit(),
                    _ => centre + point(&mut r, size),
                };
                let mut direction = target - origin;
                if k % 7 == 0 {
                    direction[k % 3] = 0.0;
                }
                if k % 11 == 0 {
                    direction[(k + 1) % 3] *= 1e-9;
                }
                if direction == DVec3::ZERO {
                    continue;
                }
                let mut ray = Ray::new(origin, direction);
                if k % 4 == 0 {
                    ray.tmax = r.unit() * 1.5;
                }
                rays.push(ray);
                let hit: Vec<(u32, f64)> = (bounds.iter().enumerate())
                    .filter_map(|(i, b)| Some((i as u32, entry(&ray, (*b)?)?)))
                    .collect();
                checked += hit.len();
                let what = format!("case {case}, ray {k}");
                // Every box entered is visited.
                let mut seen = vec![false; count];
                assert!(!index.any(&ray, |i| {
                    seen[i as usize] = true;
                    false
                }));
                for &(i, _) in &hit {
                    assert!(seen[i as usize], "{what}: object {i} not visited");
                }
                // The walk stops when asked.
                if let Some(&(stop, _)) = hit.first() {
                    assert!(index.any(&ray, |i| i == stop), "{what}");
                }
                // The nearest entry, with each object answering its own box's entry.
                let mut best: Option<f64> = None;
                index.closest(&ray, |i, tmax| {
                    let t = entry(&ray, bounds[i as usize]?)?;
                    if t < tmax && best.is_none_or(|b| t < b) {
                        best = Some(t);
                        return Some(t);
                    }
                    None
                });
                let nearest = hit.iter().map(|&(_, t)| t).reduce(f64::min);
                assert_eq!(best, nearest, "{what}");
            }
            // Packets: the rays above eight at a time (and fewer), then packets of rays from
            // one point in nearly one direction (some with mixed signs), walked together.
            let mut packets: Vec<Vec<Ray>> = rays.chunks(8).map(|c| c.to_vec()).collect();
            packets.extend(rays.chunks(3).take(50).map(|c| c.to_vec()));
            for k in 0..300 {
                let origin = centre + point(&mut r, size * 2.0);
                let target = centre + point(&mut r, size);
                let base = target - origin;
                let spread = [1e-3, 0.05, 1e-9][k % 3] * base.length();
                let packet = (0..8)
                    .map(|_| {
                        let mut d = base + point(&mut r, spread);
                        if k % 5 == 0 {
                            // Around a sign change along x.
                            d.x = point(&mut r, spread).x;
                        }
                        Ray::new(origin, d)
                    })
                    .collect();
                packets.push(packet);
            }
            for avx2 in [true, false] {
                let mut index = ObjectIndex::prepare(&bounds)
                    .expect("enough objects")
                    .build();
                index.tree.use_avx2(avx2);
                for (p, packet) in packets.iter().enumerate() {
                    let what = format!("case {case}, packet {p}, avx2 {avx2}");
                    // Every box a ray enters is visited for that ray.
                    let mut seen = vec![vec![false; count]; packet.len()];
                    let ends = std::array::from_fn(|k| packet.get(k).map_or(0.0, |r| r.tmax));
                    index.closest_packet(packet, &ends, |rays, i, _| {
                        for k in bits(rays) {
                            seen[k][i as usize] = true;
                        }
                    });
                    // The nearest entry of each ray.
                    let mut best = vec![None::<f64>; packet.len()];
                    index.closest_packet(packet, &ends, |rays, i, tmax| {
                        for k in bits(rays) {
                            let Some(t) = bounds[i as usize].and_then(|b| entry(&packet[k], b))
                            else {
                                continue;
                            };
                            if t < tmax[k] && best[k].is_none_or(|b| t < b) {
                                best[k] = Some(t);
                                tmax[k] = t;
                            }
                        }
                    });
                    for (k, ray) in packet.iter().enumerate() {
                        let hit = bounds
                            .iter()
                            .enumerate()
                            .filter_map(|(i, b)| Some((i, entry(ray, (*b)?)?)));
                        let mut nearest = None::<f64>;
                        for (i, t) in hit {
                            assert!(seen[k][i], "{what}: ray {k} did not visit object {i}");
                            nearest = Some(nearest.map_or(t, |n| n.min(t)));
                        }
                        assert_eq!(best[k], nearest, "{what}: ray {k}");
                        packet_hits += usize::from(nearest.is_some());
                    }
                }
            }
            // Point queries: every box holding the point is kept.
            for k in 0..500 {
                let p = if k % 2 == 0 {
                    centre + point(&mut r, size)
                } else {
                    // A box's corner, exactly.
                    let (lo, hi) = bounds[(k * 7) % count].unwrap_or((centre, centre));
                    if k % 4 == 1 { lo } else { hi }
                };
                let holds = |lo: DVec3, hi: DVec3| p.cmpge(lo).all() && p.cmple(hi).all();
                let mut kept = vec![false; count];
                index.each_kept(holds, |i| kept[i as usize] = true);
                for (i, b) in bounds.iter().enumerate() {
                    if b.is_some_and(|(lo, hi)| holds(lo, hi)) {
                        assert!(kept[i], "case {case}, point {k}: object {i} not kept");
                    }
                }
            }
        }
        assert!(checked > 4_000, "only {checked} boxes entered");
        assert!(packet_hits > 10_000, "only {packet_hits} packet rays hit");
    }
}
