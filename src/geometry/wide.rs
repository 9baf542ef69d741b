//! The 8-wide tree a triangle mesh is traced through.
//!
//! obvhs builds a binary tree (`Bvh2`) with leaves of up to four triangles; here it is
//! collapsed into a tree of eight children a node, whose nodes hold the eight children's
//! boxes side by side (one AVX2 slab test for eight boxes, a fused multiply-subtract a
//! distance, or two SSE tests of four on a CPU without AVX2 and FMA, chosen when the tree
//! is built) and whose leaves hold their triangles' corners
//! side by side (one SIMD test for four triangles). Eight children a node make the tree about
//! two thirds as deep as four do, and a walk waits on each node's test before it can read the
//! next node, so depth is what a ray pays for. A mesh's vertices are single
//! precision, as POV-Ray stores them, so a leaf holds its corners exactly and the exact test
//! reads them there, not through the mesh's vertex indices. Both SIMD tests are conservative:
//! the box test pads for every rounding of the ray's f32 copy, and the triangle test is a
//! filter that passes every triangle the exact test might hit, by a bound on its own rounding
//! errors. The mesh's double-precision watertight test decides each triangle that passes, so
//! the crossings are those of the exact test alone.

use super::Ray;
use super::triangle::{ShearedRay, TriangleCorners};
use glam::{DVec3, Vec3, Vec3A, Vec4};
use obvhs::bvh2::Bvh2;
use rayon::prelude::*;
use std::mem::MaybeUninit;

/// A child slot that holds nothing.
const EMPTY: u32 = u32::MAX;
/// The bit that marks a child as a leaf (the rest is its first block).
const LEAF: u32 = 1 << 31;

/// Half an f32 ulp: the relative error of one rounding.
const UNIT: f32 = f32::EPSILON / 2.0;

/// Children a node has room for.
const WIDE: usize = 8;

/// An inner node: the boxes of its eight children, relative to the mesh's centre: their low
/// sides along x, y and z, then their high sides (`planes[side][child]`), each side's eight
/// values one AVX register (two SSE registers where AVX2 is missing).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(32))]
struct Node {
    planes: [[f32; WIDE]; 6],
    /// A node's index, `LEAF` | a leaf's first block, or `EMPTY`.
    child: [u32; WIDE],
}

/// Up to four consecutive triangles' corners, lane by lane: corner `k`'s coordinate `axis`
/// of lane `i` is `corner[k][axis][i]`, the mesh's vertex exactly.
pub type Corners = [[Vec4; 3]; 3];

/// A lane of a block's corners: one triangle, for the exact test.
pub struct Lane<'a>(pub &'a Corners, pub usize);

impl TriangleCorners for Lane<'_> {
    #[inline(always)]
    fn at(&self, k: usize, axis: usize) -> f64 {
        let Lane(corners, lane) = *self;
        corners[k][axis].as_ref()[lane] as f64
    }
}

/// Up to four consecutive triangles; the lanes past `count` hold NaN, which no test passes.
#[derive(Clone, Copy, Debug)]
struct Block {
    corner: Corners,
    /// The first triangle (in the mesh's order); lane `i` is triangle `first + i`.
    first: u32,
    /// The triangles in the block (1 to 4), plus `MORE` when the next block belongs to the
    /// same leaf.
    count: u32,
}

const MORE: u32 = 1 << 8;

impl Block {
    /// The mask of all its lanes.
    fn all_lanes(&self) -> u32 {
        (1 << (self.count & 7)) - 1
    }
}

/// Trees of at most this many blocks (16 triangles) hand every block over whole instead of
/// setting up a ray for their boxes and filter, which costs more than the exact tests it
/// spares (measured on POV-Ray's radiosity/cornell.pov, whose walls and blocks are unions of
/// 2 to 10 stand-alone triangles, meshes of their own).
const SMALL: usize = 4;

/// An 8-wide tree over boxes: its inner nodes and the frame they are stored in. A leaf is a
/// child entry `LEAF | payload`, the payload (below 2^31) what its owner put there: a mesh's
/// first block, the top-level index's first object.
pub struct WideTree {
    nodes: Vec<Node>,
    /// The root entry (as a node's child), `EMPTY` for a tree over nothing.
    root: u32,
    /// Nodes' boxes are stored relative to this point.
    centre: DVec3,
    /// The largest magnitude of a box coordinate.
    extent: f32,
    /// Whether this CPU has AVX2 and FMA, which test a node's eight boxes at once.
    avx2: bool,
}

/// A triangle mesh's tree: the boxes, and the leaves' blocks of triangles.
pub struct WideBvh {
    tree: WideTree,
    blocks: Vec<Block>,
}

/// Whether this CPU has AVX2 and FMA (always false off x86-64).
fn has_avx2_and_fma() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// The smallest f32 not below `x` and the largest not above it.
fn up(x: f64) -> f32 {
    let y = x as f32;
    if (y as f64) < x { y.next_up() } else { y }
}
fn down(x: f64) -> f32 {
    let y = x as f32;
    if (y as f64) > x { y.next_down() } else { y }
}

impl WideTree {
    /// Collapses `bvh`, whose boxes `(lo, hi)` bounds, into an 8-wide tree; `leaf(range)`
    /// gives the payload (below 2^31) of a leaf over the primitives at `range` of the binary
    /// tree's primitive list, called in the order the leaves are laid out.
    pub fn collapse(
        bvh: &Bvh2,
        (lo, hi): (DVec3, DVec3),
        mut leaf: impl FnMut(std::ops::Range<usize>) -> u32,
    ) -> WideTree {
        let centre = if lo.cmple(hi).all() {
            (lo + hi) * 0.5
        } else {
            DVec3::ZERO
        };
        let extent = lo.abs().max(hi.abs()).max_element();
        let extent = if extent.is_finite() { up(extent) } else { 0.0 };
        let mut tree = WideTree {
            nodes: crate::memory::with_huge_pages(bvh.nodes.len() / 3 + 1),
            root: EMPTY,
            centre,
            extent,
            avx2: has_avx2_and_fma(),
        };
        if bvh.nodes.is_empty() || bvh.primitive_indices.is_empty() {
            return tree;
        }
        // Work list: (Bvh2 node, the node slot to fill, or None for the root).
        let mut work: Vec<(usize, Option<(usize, usize)>)> = vec![(0, None)];
        while let Some((index, slot)) = work.pop() {
            let node = &bvh.nodes[index];
            let entry = if node.is_leaf() {
                let first = node.first_index as usize;
                let payload = leaf(first..first + node.prim_count as usize);
                debug_assert!(payload & LEAF == 0);
                LEAF | payload
            } else {
                // Open the widest inner child until there are eight.
                let mut kids = [0; WIDE];
                kids[0] = node.first_index as usize;
                kids[1] = node.first_index as usize + 1;
                let mut n = 2;
                while n < WIDE {
                    let area = |k: usize| bvh.nodes[k].aabb.half_area();
                    let Some(widest) = (0..n)
                        .filter(|&i| !bvh.nodes[kids[i]].is_leaf())
                        .max_by(|&a, &b| area(kids[a]).total_cmp(&area(kids[b])))
                    else {
                        break;
                    };
                    let k = bvh.nodes[kids[widest]].first_index as usize;
                    kids[widest] = k;
                    kids[n] = k + 1;
                    n += 1;
                }
                let at = tree.nodes.len();
                let mut new = Node {
                    planes: [[f32::NAN; WIDE]; 6],
                    child: [EMPTY; WIDE],
                };
                for (i, &k) in kids[..n].iter().enumerate() {
                    let b = &bvh.nodes[k].aabb;
                    for axis in 0..3 {
                        new.planes[axis][i] = down(b.min[axis] as f64 - centre[axis]);
                        new.planes[3 + axis][i] = up(b.max[axis] as f64 - centre[axis]);
                    }
                }
                tree.nodes.push(new);
                // Pushed in reverse so that the first child is laid out next (depth first).
                for (i, &k) in kids[..n].iter().enumerate().rev() {
                    work.push((k, Some((at, i))));
                }
                at as u32
            };
            match slot {
                Some((node, i)) => tree.nodes[node].child[i] = entry,
                None => tree.root = entry,
            }
        }
        tree
    }

    /// Whether to test boxes with AVX2 where the CPU has it (for tests of both paths).
    #[cfg(test)]
    pub fn use_avx2(&mut self, on: bool) {
        self.avx2 = on && has_avx2_and_fma();
    }

    /// Asks for a node's memory ahead of its test (`leaf` for a leaf's payload).
    #[inline(always)]
    fn prefetch(&self, entry: u32, leaf: &impl Fn(u32)) {
        if entry & LEAF != 0 {
            return leaf(entry & !LEAF);
        }
        #[cfg(target_arch = "x86_64")]
        {
            // (An address worked out without bounds checks: a prefetch never faults.)
            let node = self.nodes.as_ptr().wrapping_add(entry as usize);
            prefetch_lines(node as *const u8, 4);
        }
    }

    /// Visits, nearest box first when `ORDERED`, the leaves whose boxes the ray enters before
    /// `limit`: `visit(payload, limit)` is called for each and returns a new limit (it only
    /// ever lowers it; a negative limit ends the walk); `prefetch(payload)` may ask for a
    /// leaf's memory when its box is entered.
    #[inline(always)]
    pub fn walk<const ORDERED: bool>(
        &self,
        ray: &Ray,
        limit: f32,
        prefetch: impl Fn(u32),
        visit: impl FnMut(u32, f32) -> f32,
    ) {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is set only where the CPU has AVX2 and FMA.
            return unsafe { self.walk_avx2::<ORDERED>(ray, limit, prefetch, visit) };
        }
        self.walk_with::<ORDERED, false>(ray, limit, prefetch, visit)
    }

    /// [`WideTree::walk`] compiled for AVX2 and FMA (the box tests, and all that is inlined
    /// here: the leaves' own tests too).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn walk_avx2<const ORDERED: bool>(
        &self,
        ray: &Ray,
        limit: f32,
        prefetch: impl Fn(u32),
        visit: impl FnMut(u32, f32) -> f32,
    ) {
        self.walk_with::<ORDERED, true>(ray, limit, prefetch, visit)
    }

    /// The walk, testing a node's boxes with AVX2 when `AVX2` (with `AVX2` it is called only
    /// from [`WideTree::walk_avx2`], which it is inlined into).
    #[inline(always)]
    fn walk_with<const ORDERED: bool, const AVX2: bool>(
        &self,
        ray: &Ray,
        mut limit: f32,
        prefetch: impl Fn(u32),
        mut visit: impl FnMut(u32, f32) -> f32,
    ) {
        if self.root == EMPTY {
            return;
        }
        let r = BoxRay::new(ray, self.centre, self.extent);
        let mut stack = Stack::<(u32, f32), 64>::new();
        stack.push((self.root, 0.0));
        while let Some((mut entry, near)) = stack.pop() {
            if near > limit {
                continue;
            }
            // Descend through inner nodes, nearest child first.
            while entry & LEAF == 0 {
                let node = &self.nodes[entry as usize];
                let (entry_t, mut mask) = r.boxes::<AVX2>(node, limit);
                if mask == 0 {
                    break;
                }
                let mut m = mask;
                while m != 0 {
                    let i = m.trailing_zeros() as usize;
                    m &= m - 1;
                    self.prefetch(node.child[i], &prefetch);
                }
                let first = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                if !ORDERED || mask == 0 {
                    while mask != 0 {
                        let i = mask.trailing_zeros() as usize;
                        mask &= mask - 1;
                        stack.push((node.child[i], entry_t[i]));
                    }
                    entry = node.child[first];
                    continue;
                }
                let second = mask.trailing_zeros() as usize;
                mask &= mask - 1;
                if mask == 0 {
                    // Two children (the usual case): the nearer next, the other later.
                    let (near, far) = if entry_t[second] < entry_t[first] {
                        (second, first)
                    } else {
                        (first, second)
                    };
                    stack.push((node.child[far], entry_t[far]));
                    entry = node.child[near];
                    continue;
                }
                mask |= (1 << first) | (1 << second);
                // Sort the children hit by entry distance, farthest first, and go on with
                // the nearest.
                let mut hits = [(0.0f32, 0u32); WIDE];
                let mut n = 0;
                while mask != 0 {
                    let i = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    hits[n] = (entry_t[i], node.child[i]);
                    n += 1;
                }
                farthest_first(&mut hits[..n]);
                for &(t, child) in &hits[..n - 1] {
                    stack.push((child, t));
                }
                entry = hits[n - 1].1;
            }
            if entry & LEAF == 0 {
                continue;
            }
            limit = limit.min(visit(entry & !LEAF, limit));
            if limit < 0.0 {
                return;
            }
        }
    }

    /// Visits, for up to [`PACKET`] rays (a packet, such as the camera rays of a pixel's
    /// samples or of neighbouring pixels), the leaves whose boxes they enter before their
    /// limits, nearer boxes roughly first: `visit(rays, payload, limits)` is called with the
    /// mask of the rays that enter the leaf's box (ray `k` is bit `k`) and may lower their
    /// limits. Each node is read once for all the rays that enter it, and each of its
    /// children's boxes is tested against all of them at once.
    #[inline(always)]
    pub fn walk_packet(
        &self,
        rays: &[Ray],
        limits: &mut [f32; PACKET],
        visit: impl FnMut(u32, u32, &mut [f32; PACKET]),
    ) {
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: `avx2` is set only where the CPU has AVX2 and FMA.
            return unsafe { self.walk_packet_avx2(rays, limits, visit) };
        }
        self.walk_packet_with::<false>(rays, limits, visit)
    }

    /// [`WideTree::walk_packet`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn walk_packet_avx2(
        &self,
        rays: &[Ray],
        limits: &mut [f32; PACKET],
        visit: impl FnMut(u32, u32, &mut [f32; PACKET]),
    ) {
        self.walk_packet_with::<true>(rays, limits, visit)
    }

    /// The packet walk, testing a child's box against all the rays at once with AVX2 when
    /// `AVX2`. Rays whose directions differ in sign along an axis enter a box by different
    /// sides, so the rays are walked in groups of one sign along each axis (camera rays near
    /// the axis of a camera looking along an axis may differ).
    #[inline(always)]
    fn walk_packet_with<const AVX2: bool>(
        &self,
        rays: &[Ray],
        limits: &mut [f32; PACKET],
        mut visit: impl FnMut(u32, u32, &mut [f32; PACKET]),
    ) {
        assert!(rays.len() <= PACKET);
        if self.root == EMPTY || rays.is_empty() {
            return;
        }
        let packet = RayPacket::new(rays, self.centre, self.extent);
        let mut left = (1u32 << rays.len()) - 1;
        while left != 0 {
            let lead = left.trailing_zeros() as usize;
            let group = bits(left)
                .filter(|&k| packet.signs[k] == packet.signs[lead])
                .fold(0, |m, k| m | 1 << k);
            left &= !group;
            self.walk_group::<AVX2>(&packet, packet.sides(lead), group, limits, &mut visit);
        }
    }

    /// The packet walk of the rays in `group`, which enter boxes by the node planes `sides`.
    #[inline(always)]
    fn walk_group<const AVX2: bool>(
        &self,
        packet: &RayPacket,
        sides: [usize; 6],
        group: u32,
        limits: &mut [f32; PACKET],
        visit: &mut impl FnMut(u32, u32, &mut [f32; PACKET]),
    ) {
        // (Entries, the rays that enter them, and their entry distances.)
        let mut stack = Stack::<(u32, u32, [f32; PACKET]), 96>::new();
        stack.push((self.root, group, [0.0; PACKET]));
        while let Some((entry, rays_in, near)) = stack.pop() {
            // The rays that still may meet something in this box.
            let active = rays_in & below(&near, limits);
            if active == 0 {
                continue;
            }
            if entry & LEAF != 0 {
                visit(active, entry & !LEAF, limits);
                continue;
            }
            let node = &self.nodes[entry as usize];
            // Each child's rays and their entry distances, the children entered ordered
            // farthest first by their first ray's entry distance, so that the nearest is
            // walked next.
            let mut distance = [[0.0f32; PACKET]; WIDE];
            let mut order = [(0.0f32, (0usize, 0u32)); WIDE];
            let mut n = 0;
            for (i, slot) in distance.iter_mut().enumerate() {
                let (d, rays_in) = packet.child::<AVX2>(node, i, &sides, limits);
                let rays_in = rays_in & active;
                if rays_in != 0 {
                    self.prefetch(node.child[i], &|_| {});
                    *slot = d;
                    order[n] = (d[rays_in.trailing_zeros() as usize], (i, rays_in));
                    n += 1;
                }
            }
            farthest_first(&mut order[..n]);
            for &(_, (i, rays_in)) in &order[..n] {
                stack.push((node.child[i], rays_in, distance[i]));
            }
        }
    }

    /// Calls `f` with the payload of every leaf whose box `keep(lo, hi)` keeps (a box holding
    /// the leaf's, in world space), descending only into nodes it keeps; a leaf at the root
    /// is always visited.
    pub fn each_kept(&self, keep: impl Fn(DVec3, DVec3) -> bool, mut f: impl FnMut(u32)) {
        if self.root == EMPTY {
            return;
        }
        // The stored sides are rounded outward from the boxes less the centre, in double
        // precision (one rounding: 2^-53 of the larger magnitude), and the centre is added
        // back here (one more): a pad of 2^-50 of the magnitudes covers both.
        let pad = (self.extent as f64 + self.centre.abs().max_element()) * (2.0f64).powi(-50);
        // (Called for every shading point under an area light: the stack is kept per thread.)
        thread_local! {
            static STACK: std::cell::RefCell<Vec<u32>> = const { std::cell::RefCell::new(Vec::new()) };
        }
        STACK.with_borrow_mut(|stack| {
            stack.clear();
            stack.push(self.root);
            while let Some(entry) = stack.pop() {
                if entry & LEAF != 0 {
                    f(entry & !LEAF);
                    continue;
                }
                let node = &self.nodes[entry as usize];
                for i in 0..WIDE {
                    if node.child[i] == EMPTY {
                        continue;
                    }
                    let side = |s: usize| {
                        DVec3::new(
                            node.planes[s][i] as f64,
                            node.planes[s + 1][i] as f64,
                            node.planes[s + 2][i] as f64,
                        ) + self.centre
                    };
                    if keep(side(0) - DVec3::splat(pad), side(3) + DVec3::splat(pad)) {
                        stack.push(node.child[i]);
                    }
                }
            }
        });
    }
}

/// Asks for `lines` cache lines from `p` on (x86-64 only; elsewhere nothing).
#[inline(always)]
fn prefetch_lines(p: *const u8, lines: usize) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        for k in 0..lines {
            // SAFETY: a prefetch only hints the cache; it never faults, whatever the address.
            unsafe { _mm_prefetch::<_MM_HINT_T0>(p.wrapping_add(64 * k) as *const i8) };
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = (p, lines);
}

impl WideBvh {
    /// Collapses `bvh` (dropped as soon as it is read; its primitive at position `i` of its
    /// list is triangle `i`) into an 8-wide tree; `corners(i)` gives triangle `i`'s corners
    /// and `(lo, hi)` bounds them all.
    pub fn new(
        bvh: Bvh2,
        corners: impl Fn(usize) -> [Vec3; 3] + Sync + Send,
        bounds: (DVec3, DVec3),
    ) -> WideBvh {
        // The leaves' triangles, in the order their blocks are stored.
        let mut leaves: Vec<std::ops::Range<usize>> = Vec::new();
        let mut block_count = 0u32;
        let tree = WideTree::collapse(&bvh, bounds, |range| {
            let first = block_count;
            block_count += range.len().div_ceil(4) as u32;
            leaves.push(range);
            first
        });
        // The binary tree goes before the blocks are made (at 1M triangles it is 64 MB).
        drop(bvh);
        // The blocks' triangles (sequentially: cheap), then their corners (in parallel).
        let nan = Vec4::splat(f32::NAN);
        let mut blocks = crate::memory::with_huge_pages(block_count as usize);
        for range in leaves {
            for start in range.clone().step_by(4) {
                let count = (range.end - start).min(4);
                blocks.push(Block {
                    corner: [[nan; 3]; 3],
                    first: start as u32,
                    count: count as u32 | if start + count < range.end { MORE } else { 0 },
                });
            }
        }
        blocks.par_iter_mut().for_each(|block| {
            for lane in 0..(block.count & 7) as usize {
                for (k, p) in corners(block.first as usize + lane).into_iter().enumerate() {
                    for axis in 0..3 {
                        block.corner[k][axis][lane] = p[axis];
                    }
                }
            }
        });
        debug_assert_eq!(blocks.len(), block_count as usize);
        WideBvh { tree, blocks }
    }

    /// The same tree, walked without AVX2 (for tests of that path on CPUs that have it).
    #[cfg(test)]
    pub fn without_avx2(mut self) -> WideBvh {
        self.tree.use_avx2(false);
        self
    }

    /// Visits, nearest box first when `ORDERED`, the leaves whose boxes the ray enters before
    /// `limit`; `visit(first, lanes, corners)` is called for each block with a mask of the
    /// triangles that may cross the ray (lane `i` is triangle `first + i`) and their corners,
    /// and returns a new limit (it only ever lowers it; a negative limit ends the walk).
    pub fn walk<const ORDERED: bool>(
        &self,
        ray: &Ray,
        sheared: &ShearedRay,
        mut limit: f32,
        mut visit: impl FnMut(u32, u32, &Corners) -> f32,
    ) {
        // A small tree's blocks, whole and in their order: the walk's order when the root is
        // a leaf (it holds them all), so an ordered walk takes this only then.
        if self.blocks.len() <= SMALL && (!ORDERED || self.tree.root & LEAF != 0) {
            for block in &self.blocks {
                limit = limit.min(visit(block.first, block.all_lanes(), &block.corner));
                if limit < 0.0 {
                    return;
                }
            }
            return;
        }
        let filter = TriangleFilter::new(ray, sheared, self.tree.extent);
        let blocks = &self.blocks;
        let prefetch = |first: u32| {
            // (An address worked out without bounds checks: a prefetch never faults.)
            prefetch_lines(blocks.as_ptr().wrapping_add(first as usize) as *const u8, 3);
        };
        self.tree
            .walk::<ORDERED>(ray, limit, prefetch, |first, mut limit| {
                let mut b = first as usize;
                loop {
                    let block = &blocks[b];
                    let lanes = filter.triangles(block);
                    if lanes != 0 {
                        limit = limit.min(visit(block.first, lanes, &block.corner));
                        if limit < 0.0 {
                            return limit;
                        }
                    }
                    if block.count & MORE == 0 {
                        return limit;
                    }
                    b += 1;
                }
            });
    }
}

impl WideBvh {
    /// [`WideBvh::walk`], nearest box first, for up to [`PACKET`] rays walked together
    /// (`sheared[k]` is ray `k`'s exact test): `visit(k, first, lanes, corners)` is called for
    /// each block ray `k` reaches with the triangles that may cross it, and returns its new
    /// limit.
    pub fn walk_packet(
        &self,
        rays: &[Ray],
        sheared: &[ShearedRay],
        limits: &mut [f32; PACKET],
        mut visit: impl FnMut(usize, u32, u32, &Corners) -> f32,
    ) {
        let filters: [TriangleFilter; PACKET] = std::array::from_fn(|k| {
            let k = if k < rays.len() { k } else { 0 };
            TriangleFilter::new(&rays[k], &sheared[k], self.tree.extent)
        });
        let blocks = &self.blocks;
        self.tree
            .walk_packet(rays, limits, |rays_in, first, limits| {
                for k in bits(rays_in) {
                    let mut b = first as usize;
                    loop {
                        let block = &blocks[b];
                        let lanes = filters[k].triangles(block);
                        if lanes != 0 {
                            limits[k] = limits[k].min(visit(k, block.first, lanes, &block.corner));
                        }
                        if block.count & MORE == 0 {
                            break;
                        }
                        b += 1;
                    }
                }
            });
    }
}

/// A ray's f32 copy for the box tests.
struct BoxRay {
    /// Along each axis, the node plane (an index into [`Node::planes`], below 6) the ray
    /// enters a box by (the low side if it moves up or not at all, the high side if down),
    /// and the one it leaves by.
    enter: [usize; 3],
    leave: [usize; 3],
    /// Along each axis, the reciprocal of the direction (±10²⁰ where the direction is
    /// nearer zero than 10⁻²⁰, so that no distance is NaN or infinite); 0 where the slab
    /// cannot be bounded in f32 (it then holds every distance).
    inverse: [f32; 3],
    /// The origin relative to the boxes' centre times `inverse`, less a margin for the
    /// entry distance (`plane · inverse − offset`, with one rounding or two) and plus it
    /// for the exit, so that each slab holds the exact ray's: see [`BoxRay::new`].
    enter_offset: [f32; 3],
    leave_offset: [f32; 3],
}

/// A packet's rays, lane by lane, for testing a box against all of them at once: each
/// lane's reciprocal direction and offsets as [`BoxRay`]'s (lanes past the packet's rays
/// copy its first).
struct RayPacket {
    inverse: [[f32; PACKET]; 3],
    enter_offset: [[f32; PACKET]; 3],
    leave_offset: [[f32; PACKET]; 3],
    /// Each ray's direction signs (a bit an axis, set where it moves down).
    signs: [u32; PACKET],
}

impl RayPacket {
    #[inline(always)]
    fn new(rays: &[Ray], centre: DVec3, extent: f32) -> RayPacket {
        let mut packet = RayPacket {
            inverse: [[0.0; PACKET]; 3],
            enter_offset: [[0.0; PACKET]; 3],
            leave_offset: [[0.0; PACKET]; 3],
            signs: [0; PACKET],
        };
        for k in 0..PACKET {
            let r = BoxRay::new(&rays[if k < rays.len() { k } else { 0 }], centre, extent);
            for axis in 0..3 {
                packet.inverse[axis][k] = r.inverse[axis];
                packet.enter_offset[axis][k] = r.enter_offset[axis];
                packet.leave_offset[axis][k] = r.leave_offset[axis];
                if r.enter[axis] >= 3 {
                    packet.signs[k] |= 1 << axis;
                }
            }
        }
        packet
    }

    /// The node planes ray `k` enters (the first three) and leaves (the last three) a box
    /// by along each axis, as [`BoxRay`]'s.
    fn sides(&self, k: usize) -> [usize; 6] {
        let down = |axis: usize| self.signs[k] & (1 << axis) != 0;
        let side = |axis: usize, high: bool| if high { 3 + axis } else { axis };
        [
            side(0, down(0)),
            side(1, down(1)),
            side(2, down(2)),
            side(0, !down(0)),
            side(1, !down(1)),
            side(2, !down(2)),
        ]
    }

    /// The entry distances of every lane into child `i`'s box of `node` and the mask of the
    /// lanes that enter it at a distance in [0, their limit], for lanes that enter and leave
    /// boxes by the planes `sides`: as [`BoxRay::boxes`] computes each (the same values).
    #[inline(always)]
    fn child<const AVX2: bool>(
        &self,
        node: &Node,
        i: usize,
        sides: &[usize; 6],
        limits: &[f32; PACKET],
    ) -> ([f32; PACKET], u32) {
        #[cfg(target_arch = "x86_64")]
        if AVX2 {
            // SAFETY: `AVX2` is true only in the walk compiled for AVX2 and FMA, which runs
            // only where the CPU has them.
            return unsafe { self.child_avx2(node, i, sides, limits) };
        }
        let half = |h: usize| {
            let lanes = |v: &[f32; PACKET]| Vec4::from_slice(&v[4 * h..]);
            let distance = |side: usize, axis: usize, offset: &[[f32; PACKET]; 3]| {
                Vec4::splat(node.planes[side][i]) * lanes(&self.inverse[axis])
                    - lanes(&offset[axis])
            };
            let enter = |a: usize| distance(sides[a], a, &self.enter_offset);
            let leave = |a: usize| distance(sides[3 + a], a, &self.leave_offset);
            entries4(
                [enter(0), enter(1), enter(2)],
                [leave(0), leave(1), leave(2)],
                lanes(limits),
            )
        };
        halves(half(0), half(1))
    }

    /// [`RayPacket::child`] with AVX and FMA (inlined into the walk compiled for them).
    ///
    /// # Safety
    /// Only for a CPU with AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn child_avx2(
        &self,
        node: &Node,
        i: usize,
        sides: &[usize; 6],
        limits: &[f32; PACKET],
    ) -> ([f32; PACKET], u32) {
        use std::arch::x86_64::*;
        // SAFETY: the caller's CPU has AVX2 and FMA (this function's contract); every
        // array read holds eight f32s, `sides` are below 6 and `i` below 8.
        unsafe {
            let lanes = |v: &[f32; PACKET]| _mm256_loadu_ps(v.as_ptr());
            let distance = |side: usize, axis: usize, offset: &[[f32; PACKET]; 3]| {
                _mm256_fmsub_ps(
                    _mm256_set1_ps(*node.planes.get_unchecked(side).get_unchecked(i)),
                    lanes(self.inverse.get_unchecked(axis)),
                    lanes(offset.get_unchecked(axis)),
                )
            };
            let enter = |a: usize| distance(sides[a], a, &self.enter_offset);
            let leave = |a: usize| distance(sides[3 + a], a, &self.leave_offset);
            let (enter, leave) = (
                [enter(0), enter(1), enter(2)],
                [leave(0), leave(1), leave(2)],
            );
            entries8(enter, leave, lanes(limits))
        }
    }
}

/// Four lanes' box entry distances (at least 0) from their slabs' distances along the three
/// axes, `enter` and `leave`, and the mask of the lanes that enter their box at a distance up
/// to their `limit` (a lane of NaN sides, an empty slot, fails).
#[inline(always)]
fn entries4(enter: [Vec4; 3], leave: [Vec4; 3], limit: Vec4) -> (Vec4, u32) {
    // (As in `entries8`.)
    let near = enter[0].max(enter[1]).max(Vec4::ZERO.max(enter[2]));
    let far = leave[0].min(leave[1]).min(leave[2]);
    let mask = near.cmple(far) & near.cmple(limit);
    (near, mask.bitmask())
}

/// Two halves' [`entries4`] as eight lanes.
#[inline(always)]
fn halves((near0, mask0): (Vec4, u32), (near1, mask1): (Vec4, u32)) -> ([f32; 8], u32) {
    let mut near = [0.0; 8];
    near[..4].copy_from_slice(&near0.to_array());
    near[4..].copy_from_slice(&near1.to_array());
    (near, mask0 | mask1 << 4)
}

/// [`entries4`] for eight lanes with AVX.
///
/// # Safety
/// Only for a CPU with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn entries8(
    enter: [std::arch::x86_64::__m256; 3],
    leave: [std::arch::x86_64::__m256; 3],
    limit: std::arch::x86_64::__m256,
) -> ([f32; 8], u32) {
    use std::arch::x86_64::*;
    // SAFETY: the caller's CPU has AVX2 and FMA (this function's contract).
    unsafe {
        // As two short chains, not one long one: a walk waits on each node's test before it
        // can read the next node. (max and min return their second operand when either is
        // NaN: an empty slot's NaN sides reach the comparison below, which NaN fails.)
        let near = _mm256_max_ps(
            _mm256_max_ps(enter[0], enter[1]),
            _mm256_max_ps(_mm256_setzero_ps(), enter[2]),
        );
        let far = _mm256_min_ps(_mm256_min_ps(leave[0], leave[1]), leave[2]);
        let inside = _mm256_and_ps(
            _mm256_cmp_ps::<_CMP_LE_OQ>(near, far),
            _mm256_cmp_ps::<_CMP_LE_OQ>(near, limit),
        );
        let mut distances = [0.0; 8];
        _mm256_storeu_ps(distances.as_mut_ptr(), near);
        (distances, _mm256_movemask_ps(inside) as u32)
    }
}

/// The mask of the lanes whose `near` is at most their `limit`.
#[inline(always)]
fn below(near: &[f32; PACKET], limits: &[f32; PACKET]) -> u32 {
    let mut mask = 0;
    for k in 0..PACKET {
        mask |= u32::from(near[k] <= limits[k]) << k;
    }
    mask
}

/// A ray's f32 copy for the triangle filter.
struct TriangleFilter {
    /// The origin rounded to nearest (not relative to the centre: the corners are not).
    origin: [Vec4; 3],
    /// The shear of the watertight test: the axes and the shear factors (as the exact test's).
    kx: usize,
    ky: usize,
    kz: usize,
    sx: Vec4,
    sy: Vec4,
    /// A bound on the error of each sheared corner coordinate; infinite when the coordinates
    /// are too large for the bound to hold in f32 (every triangle then passes).
    error: f32,
}

impl TriangleFilter {
    /// The filter for a ray and its exact test, for corners no larger than `extent`.
    #[inline(always)]
    fn new(ray: &Ray, sheared: &ShearedRay, extent: f32) -> TriangleFilter {
        let origin = ray.origin;
        // The same axes and factors as the exact test's.
        let ((kx, ky, kz), (sx, sy)) = (sheared.axes(), sheared.factors());
        // Each sheared coordinate a[kx] − sx·a[kz] (|sx| ≤ 1) is off by at most: the origin's
        // rounding (the corners are exact), the subtraction, the factor's
        // rounding, the product and the difference: under 9 units of the largest magnitude;
        // 16 leaves room for the magnitude's own rounding (to nearest) and the exact test's
        // (double-precision) roundings.
        let magnitude = extent + origin.abs().max_element() as f32;
        let error = if magnitude < 1e15 {
            16.0 * UNIT * magnitude
        } else {
            f32::INFINITY
        };
        TriangleFilter {
            origin: [origin.x as f32, origin.y as f32, origin.z as f32].map(Vec4::splat),
            kx,
            ky,
            kz,
            sx: Vec4::splat(sx as f32),
            sy: Vec4::splat(sy as f32),
            error,
        }
    }
}

impl BoxRay {
    #[inline(always)]
    fn new(ray: &Ray, centre: DVec3, extent: f32) -> BoxRay {
        // The slabs, three axes at once in f32. A slab's distance is plane · i − offset for
        // the f32 reciprocal i of the f32 direction (±10²⁰ where that is nearer zero than
        // 10⁻²⁰, so that no distance is NaN or infinite; 2 units from the exact reciprocal)
        // and offset = o · i ± margin, with o the origin relative to the boxes' centre. With
        // |plane| ≤ extent, every distance is at most scale = (extent + |o|)·|i|, and the
        // roundings are: the reciprocal's error (2 units of scale), o's rounding to f32 (1),
        // the product o · i (1), adding the margin (1), and the product-difference (1 fused,
        // 2 without FMA): 7 units of scale, which a margin of 12 units holds (its own f32
        // roundings take under 3 units of it). Where scale is 10³⁶ or more (or NaN) the slab
        // cannot be bounded in f32 and holds every distance instead: i = 0 and offsets ∓∞
        // (plane · 0 − (+∞) is −∞ and plane · 0 − (−∞) is +∞).
        let o = (ray.origin - centre).as_vec3a();
        let d = ray.direction.as_vec3a();
        let tiny = d.abs().cmplt(Vec3A::splat(1e-20));
        let i = Vec3A::select(tiny, Vec3A::splat(1e20).copysign(d), d.recip());
        // (A zero component's sign picks the side as its reciprocal's does.)
        let down = i.is_negative_bitmask();
        let scale = (Vec3A::splat(extent) + o.abs()) * i.abs();
        let bounded = scale.cmplt(Vec3A::splat(1e36));
        let at = o * i;
        let margin = scale * (12.0 * UNIT);
        let enter_offset = Vec3A::select(bounded, at + margin, Vec3A::INFINITY);
        let leave_offset = Vec3A::select(bounded, at - margin, Vec3A::NEG_INFINITY);
        let inverse = Vec3A::select(bounded, i, Vec3A::ZERO);
        let side = |axis: usize, high: bool| if high { 3 + axis } else { axis };
        let high = |axis: usize| down & (1 << axis) != 0;
        BoxRay {
            enter: [0, 1, 2].map(|a| side(a, high(a))),
            leave: [0, 1, 2].map(|a| side(a, !high(a))),
            inverse: inverse.to_array(),
            enter_offset: enter_offset.to_array(),
            leave_offset: leave_offset.to_array(),
        }
    }

    /// The entry distances into a node's eight boxes and the mask of those the ray enters at a
    /// distance in [0, limit]: with AVX2 and FMA when `AVX2` (the caller's CPU has them), as
    /// two halves of four otherwise.
    #[inline(always)]
    fn boxes<const AVX2: bool>(&self, node: &Node, limit: f32) -> ([f32; WIDE], u32) {
        #[cfg(target_arch = "x86_64")]
        if AVX2 {
            // SAFETY: `AVX2` is true only in the walk compiled for AVX2 and FMA, which runs
            // only where the CPU has them.
            return unsafe { self.boxes_avx2(node, limit) };
        }
        let half = |h: usize| {
            let plane = |side: usize| Vec4::from_slice(&node.planes[side][4 * h..]);
            let distance = |side: usize, axis: usize, offset: f32| {
                plane(side) * Vec4::splat(self.inverse[axis]) - Vec4::splat(offset)
            };
            let enter = |a: usize| distance(self.enter[a], a, self.enter_offset[a]);
            let leave = |a: usize| distance(self.leave[a], a, self.leave_offset[a]);
            let (enter, leave) = (
                [enter(0), enter(1), enter(2)],
                [leave(0), leave(1), leave(2)],
            );
            entries4(enter, leave, Vec4::splat(limit))
        };
        halves(half(0), half(1))
    }

    /// [`BoxRay::boxes`] with AVX and FMA: one register a side, one fused
    /// product-difference a distance. Not itself compiled for AVX2 (a function that is
    /// cannot be inlined always): it is inlined into the walk compiled for AVX2 and FMA, and
    /// the intrinsics into that.
    ///
    /// # Safety
    /// Only for a CPU with AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn boxes_avx2(&self, node: &Node, limit: f32) -> ([f32; WIDE], u32) {
        use std::arch::x86_64::*;
        // SAFETY: the caller's CPU has AVX2 and FMA (this function's contract); each side is
        // eight f32s, 32-byte aligned (`Node`'s alignment, and a side's size), `enter` and
        // `leave` are below 6, and `distances` holds eight f32s.
        unsafe {
            let plane = |side: usize| _mm256_load_ps(node.planes.get_unchecked(side).as_ptr());
            let distance = |side: usize, axis: usize, offset: f32| {
                _mm256_fmsub_ps(
                    plane(side),
                    _mm256_set1_ps(self.inverse[axis]),
                    _mm256_set1_ps(offset),
                )
            };
            let enter = |a: usize| distance(self.enter[a], a, self.enter_offset[a]);
            let leave = |a: usize| distance(self.leave[a], a, self.leave_offset[a]);
            let (enter, leave) = (
                [enter(0), enter(1), enter(2)],
                [leave(0), leave(1), leave(2)],
            );
            entries8(enter, leave, _mm256_set1_ps(limit))
        }
    }
}

impl TriangleFilter {
    /// The lanes of a block whose triangle the exact test might find on the ray's line: the
    /// scaled barycentric coordinates are computed in f32 and a lane passes unless they have
    /// opposite signs by more than their error bound.
    #[inline(always)]
    fn triangles(&self, block: &Block) -> u32 {
        if self.error.is_infinite() {
            return block.all_lanes();
        }
        let (kx, ky, kz) = (self.kx, self.ky, self.kz);
        let shear = |c: &[Vec4; 3]| {
            let z = c[kz] - self.origin[kz];
            (
                c[kx] - self.origin[kx] - self.sx * z,
                c[ky] - self.origin[ky] - self.sy * z,
            )
        };
        let (ax, ay) = shear(&block.corner[0]);
        let (bx, by) = shear(&block.corner[1]);
        let (cx, cy) = shear(&block.corner[2]);
        let u = cx * by - cy * bx;
        let v = ax * cy - ay * cx;
        let w = bx * ay - by * ax;
        // |u − exact u| ≤ 4·E·S + 2·E² + 3·unit·2·S², with E the coordinate error and S the
        // largest sheared coordinate; rounded up generously.
        // (As a tree, not a chain: the walk waits on this test.)
        let s = (ax.abs().max(ay.abs())).max((bx.abs().max(by.abs())).max(cx.abs().max(cy.abs())));
        let e = self.error;
        let bound = s * (s * (8.0 * UNIT) + 5.0 * e) + 3.0 * e * e;
        let (lo, hi) = (-bound, bound);
        let positive = u.cmpge(lo) & v.cmpge(lo) & w.cmpge(lo);
        let negative = u.cmple(hi) & v.cmple(hi) & w.cmple(hi);
        (positive | negative).bitmask()
    }
}

/// A walk's stack (of entries and their entry distances): a fixed array of `N` items, left
/// uninitialised (a walk is short, and writing 64 slots it will not use cost a shadow ray
/// about 7 % of its instructions), spilling to the heap only for trees deeper than any a
/// real mesh gives.
struct Stack<T, const N: usize> {
    items: [MaybeUninit<T>; N],
    len: usize,
    spill: Vec<T>,
}

impl<T: Copy, const N: usize> Stack<T, N> {
    fn new() -> Self {
        Stack {
            items: [const { MaybeUninit::uninit() }; N],
            len: 0,
            spill: Vec::new(),
        }
    }

    #[inline(always)]
    fn push(&mut self, item: T) {
        if self.len < N {
            self.items[self.len] = MaybeUninit::new(item);
            self.len += 1;
        } else {
            self.spill.push(item);
        }
    }

    #[inline(always)]
    fn pop(&mut self) -> Option<T> {
        if let Some(item) = self.spill.pop() {
            return Some(item);
        }
        if self.len == 0 {
            return None;
        }
        self.len -= 1;
        // SAFETY: the slots below `len` were each written by `push`.
        Some(unsafe { self.items[self.len].assume_init() })
    }
}

/// Sorts a node's children entered by their entry distances, farthest first (a few items:
/// insertion sort).
#[inline(always)]
fn farthest_first<T: Copy>(items: &mut [(f32, T)]) {
    for i in 1..items.len() {
        let mut j = i;
        while j > 0 && items[j - 1].0 < items[j].0 {
            items.swap(j - 1, j);
            j -= 1;
        }
    }
}

/// The bits set in `mask`, lowest first (a block's lanes, a packet's rays).
#[inline(always)]
pub(crate) fn bits(mut mask: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (mask != 0).then(|| {
            let i = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            i
        })
    })
}

/// Rays a packet walk takes at most.
pub const PACKET: usize = 8;

#[cfg(test)]
mod tests {
    use super::super::Crossings;
    use super::super::mesh::TriangleMesh;
    use super::*;

    /// A small deterministic generator (xorshift), uniform in [0, 1).
    struct Rng(u64);
    impl Rng {
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
        fn point(&mut self, centre: DVec3, size: f64) -> DVec3 {
            centre + DVec3::new(self.next() - 0.5, self.next() - 0.5, self.next() - 0.5) * size
        }
    }

    /// Every triangle, tested exactly: the nearest crossing, whether any, and how many.
    fn brute(mesh: &[[DVec3; 3]], ray: &Ray) -> (Option<f64>, bool, usize) {
        let s = ShearedRay::new(ray.origin, ray.direction);
        let ts: Vec<f64> = mesh
            .iter()
            .filter_map(|&[a, b, c]| s.intersect(a, b, c, ray.tmin, ray.tmax))
            .collect();
        (
            ts.iter().copied().reduce(f64::min),
            !ts.is_empty(),
            ts.len(),
        )
    }

    /// A node's box test passes every box the ray's exact slabs (in double precision)
    /// enter before the limit, with an entry distance no greater than theirs, on both paths:
    /// boxes near the origin and far from it, large and tiny, rays from near and far,
    /// axis-aligned and grazing.
    #[test]
    fn box_test_keeps_every_box_the_exact_ray_enters() {
        let mut r = Rng(0x5851_F42D_4C95_7F2D);
        let mut checked = 0;
        for k in 0..40_000 {
            let scale = 10f64.powi((r.next() * 12.0) as i32 - 4);
            let centre = DVec3::new(r.next() - 0.5, r.next() - 0.5, r.next() - 0.5)
                * 10f64.powi((r.next() * 8.0) as i32 - 2);
            let mut node = Node {
                planes: [[f32::NAN; WIDE]; 6],
                child: [EMPTY; WIDE],
            };
            let mut boxes = Vec::new();
            for i in 0..WIDE - (k % 3) {
                let a = r.point(DVec3::ZERO, scale);
                let b = a + r.point(DVec3::ZERO, scale * [1.0, 1e-3, 1e-6][k % 3]).abs();
                for axis in 0..3 {
                    node.planes[axis][i] = down(a[axis]);
                    node.planes[3 + axis][i] = up(b[axis]);
                }
                boxes.push(i);
            }
            let origin = centre + r.point(DVec3::ZERO, scale * [1.0, 10.0, 1e4][k % 3]);
            let target = centre + r.point(DVec3::ZERO, scale);
            let mut direction = target - origin;
            match k % 5 {
                0 => direction[k % 3] = 0.0,
                1 => {
                    direction[k % 3] = 0.0;
                    direction[(k + 1) % 3] = 0.0
                }
                2 => direction[k % 3] *= 1e-9,
                _ => {}
            }
            if direction == DVec3::ZERO {
                continue;
            }
            let ray = Ray::new(origin, direction);
            let extent = (0..6)
                .flat_map(|side| node.planes[side])
                .filter(|p| !p.is_nan())
                .fold(0.0f32, |m, p| m.max(p.abs()));
            let f = BoxRay::new(&ray, centre, extent);
            let o = origin - centre;
            for avx2 in [false, has_avx2_and_fma()] {
                let (near, mask) = if avx2 {
                    f.boxes::<true>(&node, f32::INFINITY)
                } else {
                    f.boxes::<false>(&node, f32::INFINITY)
                };
                for &i in &boxes {
                    let (mut lo, mut hi) = (0.0f64, f64::INFINITY);
                    for axis in 0..3 {
                        let (a, b) = (node.planes[axis][i] as f64, node.planes[3 + axis][i] as f64);
                        if direction[axis] == 0.0 {
                            if o[axis] < a || o[axis] > b {
                                hi = f64::NEG_INFINITY;
                            }
                            continue;
                        }
                        let (t0, t1) = (
                            (a - o[axis]) / direction[axis],
                            (b - o[axis]) / direction[axis],
                        );
                        lo = lo.max(t0.min(t1));
                        hi = hi.min(t0.max(t1));
                    }
                    // (The exact slabs' own rounding: a relative 10⁻¹⁵.)
                    if lo < hi * (1.0 - 1e-12) {
                        checked += 1;
                        assert!(
                            mask & (1 << i) != 0,
                            "box {i} of ray {k} dropped (avx2 {avx2})"
                        );
                        assert!(
                            near[i] as f64 <= lo * (1.0 + 1e-12) + 1e-300,
                            "ray {k}: entry {} after {lo}",
                            near[i]
                        );
                    }
                }
                // Empty slots never pass.
                assert_eq!(mask >> boxes.len(), 0);
            }
        }
        assert!(checked > 10_000, "only {checked} boxes entered");
    }

    /// Test ray `k` around a mesh at `centre` of `size`: from a random point toward a random
    /// point, a corner, a point on an edge, or along the plane y = centre.y (grazing); every
    /// third a shadow ray ending at its target.
    fn test_ray(
        rng: &mut Rng,
        k: usize,
        (centre, size): (DVec3, f64),
        vertices: &[DVec3],
        soup: &[[DVec3; 3]],
    ) -> Ray {
        let origin = rng.point(centre, size * 3.0);
        let target = match k % 4 {
            0 => rng.point(centre, size),
            1 => vertices[(rng.next() * vertices.len() as f64) as usize],
            2 => {
                let f = soup[(rng.next() * soup.len() as f64) as usize];
                let s = rng.next();
                f[0] + (f[1] - f[0]) * s
            }
            _ => {
                let p = rng.point(centre, size);
                DVec3::new(p.x, centre.y, p.z)
            }
        };
        let mut ray = Ray::new(origin, target - origin);
        if k % 3 == 0 {
            ray.tmin = 1e-9;
            ray.tmax = 1.0;
        }
        if k % 5 == 4 {
            // A shadow ray: from a point on a triangle (as a hit point is, which the filter
            // passes and the exact test must turn down), with a small `tmin` and a `tmax`
            // anywhere along it.
            let f = soup[(rng.next() * soup.len() as f64) as usize];
            let (s, t) = (rng.next(), rng.next());
            let (s, t) = if s + t > 1.0 {
                (1.0 - s, 1.0 - t)
            } else {
                (s, t)
            };
            let start = f[0] + (f[1] - f[0]) * s + (f[2] - f[0]) * t;
            ray = Ray::new(start, target - start);
            ray.tmin = [1e-9, 1e-6, 1e-3][k % 3];
            ray.tmax = rng.next() * 2.0;
        }
        ray
    }

    /// The mesh's nearest crossing, whether any, and how many, as every triangle tested
    /// exactly finds them.
    fn agree_with_every_triangle(mesh: &TriangleMesh, soup: &[[DVec3; 3]], ray: &Ray, what: &str) {
        let (nearest, any, count) = brute(soup, ray);
        assert_eq!(mesh.intersect(ray).first(), nearest, "{what}");
        assert_eq!(mesh.occluded(ray), any, "{what}");
        assert_eq!(mesh.count_crossings(ray), count, "{what}");
    }

    /// A mesh of `vertices` and `faces`, and the same mesh walked without AVX2 (the same
    /// tree: on a CPU without AVX2 the two are the same walk).
    fn both_walks(vertices: &[DVec3], faces: &[[u32; 3]]) -> [TriangleMesh; 2] {
        let single: Vec<_> = vertices.iter().map(|v| v.as_vec3()).collect();
        let mesh = || {
            TriangleMesh::new(
                single.clone(),
                faces.to_vec(),
                vec![],
                vec![],
                vec![],
                vec![],
            )
        };
        [mesh(), mesh().without_avx2()]
    }

    #[test]
    fn stack_spills_and_pops_in_order() {
        let mut stack = Stack::<(u32, f32), 64>::new();
        for i in 0..200 {
            stack.push((i, i as f32));
        }
        for i in (0..200).rev() {
            assert_eq!(stack.pop(), Some((i, i as f32)));
        }
        assert_eq!(stack.pop(), None);
    }

    #[test]
    fn tree_finds_what_every_triangle_tested_exactly_finds() {
        // Triangle soups and closed grids, near and far from the origin, with rays through
        // random points, exactly through corners and along edges (where the f32 filter must
        // not drop a triangle the exact test hits), and grazing.
        let mut rng = Rng(0x2545_F491_4F6C_DD1D);
        for (offset, size) in [
            (0.0, 10.0),
            (1e4, 1.0),
            (1e6, 100.0),
            (3.0, 1e-4),
            (-2e5, 1e3),
        ] {
            let centre = DVec3::new(offset, -0.5 * offset, 0.25 * offset);
            // A grid of 24×24 cells (two triangles each), bumped, plus 300 random triangles.
            let n = 24;
            let mut vertices = Vec::new();
            for j in 0..=n {
                for i in 0..=n {
                    let (x, z) = (i as f64 / n as f64 - 0.5, j as f64 / n as f64 - 0.5);
                    let y = 0.1 * (7.0 * x).sin() * (5.0 * z).cos();
                    vertices.push(centre + DVec3::new(x, y, z) * size);
                }
            }
            let mut faces = Vec::new();
            for j in 0..n {
                for i in 0..n {
                    let a = (j * (n + 1) + i) as u32;
                    let s = (n + 1) as u32;
                    faces.push([a, a + s, a + 1]);
                    faces.push([a + 1, a + s, a + s + 1]);
                }
            }
            for _ in 0..300 {
                let p = rng.point(centre, size);
                let k = vertices.len() as u32;
                for _ in 0..3 {
                    vertices.push(p + rng.point(DVec3::ZERO, size * 0.1));
                }
                faces.push([k, k + 1, k + 2]);
            }
            // (A mesh's vertices are single precision.)
            for v in &mut vertices {
                *v = v.as_vec3().as_dvec3();
            }
            let soup: Vec<[DVec3; 3]> = faces
                .iter()
                .map(|f| f.map(|i| vertices[i as usize]))
                .collect();
            for mesh in both_walks(&vertices, &faces) {
                let mut rays = Vec::new();
                for k in 0..3000 {
                    let ray = test_ray(&mut rng, k, (centre, size), &vertices, &soup);
                    let what = format!("offset {offset}, ray {k}");
                    agree_with_every_triangle(&mesh, &soup, &ray, &what);
                    rays.push(ray);
                }
                // Packets: the rays above, 1 to 8 at a time, and rays from one point toward
                // the grid's corners and edges next to one another (ties between triangles).
                let mut start = 0;
                for p in 0.. {
                    let end = (start + 1 + p % PACKET).min(rays.len());
                    packets_agree(
                        &mesh,
                        &rays[start..end],
                        &format!("offset {offset}, packet {p}"),
                    );
                    start = end;
                    if start == rays.len() {
                        break;
                    }
                }
                for p in 0..300 {
                    let origin = rng.point(centre, size * 3.0);
                    let at = (rng.next() * (n * n) as f64) as usize;
                    let packet: Vec<Ray> = (0..PACKET)
                        .map(|k| {
                            let a = vertices[at + k / 2];
                            let b = vertices[at + k / 2 + 1];
                            let target = if k % 2 == 0 { a } else { (a + b) * 0.5 };
                            Ray::new(origin, target - origin)
                        })
                        .collect();
                    packets_agree(&mesh, &packet, &format!("offset {offset}, corners {p}"));
                }
            }
        }
    }

    /// Rays walked together as a packet find what each finds alone, and each finds the
    /// nearest crossing and, where triangles tie at it (a ray through the edge or corner
    /// they share), the lowest-numbered of them, whatever order a walk meets them in.
    fn packets_agree(mesh: &TriangleMesh, rays: &[Ray], what: &str) {
        let mut together = [Crossings::NONE; PACKET];
        mesh.intersect_packet(rays, &mut together[..rays.len()]);
        let key = |c: &Crossings| c.first_part().map(|(t, part)| (t.to_bits(), part));
        for (k, ray) in rays.iter().enumerate() {
            let alone = mesh.intersect(ray);
            assert_eq!(key(&together[k]), key(&alone), "{what}, ray {k}");
            let mut lowest: Option<(f64, u32)> = None;
            mesh.for_each_crossing(ray, |t, part| {
                if lowest.is_none_or(|(b, i)| t < b || (t == b && part < i)) {
                    lowest = Some((t, part));
                }
            });
            assert_eq!(
                key(&alone),
                lowest.map(|(t, part)| (t.to_bits(), part)),
                "{what}, ray {k}"
            );
        }
    }

    /// Small meshes (a tree of at most 4 blocks hands every block over whole, to a nearest-
    /// first walk only when its root is a leaf) answer as every triangle tested exactly does,
    /// on both sides of that size, with rays through corners and edges.
    #[test]
    fn small_meshes_answer_as_every_triangle_tested_exactly() {
        let mut rng = Rng(11);
        for n in [1, 2, 5, 16, 17, 24] {
            for _ in 0..20 {
                let mut vertices = Vec::new();
                let mut faces = Vec::new();
                for k in 0..n as u32 {
                    let p = rng.point(DVec3::ZERO, 4.0);
                    for _ in 0..3 {
                        vertices.push(p + rng.point(DVec3::ZERO, 2.0));
                    }
                    faces.push([3 * k, 3 * k + 1, 3 * k + 2]);
                }
                for v in &mut vertices {
                    *v = v.as_vec3().as_dvec3();
                }
                let soup: Vec<[DVec3; 3]> = faces
                    .iter()
                    .map(|f| f.map(|i| vertices[i as usize]))
                    .collect();
                for mesh in both_walks(&vertices, &faces) {
                    for k in 0..200 {
                        let ray = test_ray(&mut rng, k, (DVec3::ZERO, 4.0), &vertices, &soup);
                        let what = format!("{n} triangles, ray {k}");
                        agree_with_every_triangle(&mesh, &soup, &ray, &what);
                    }
                }
            }
        }
    }
}
