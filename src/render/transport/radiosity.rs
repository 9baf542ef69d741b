//! POV-Ray 3.7's radiosity (Ward, Rubinstein and Clear's irradiance cache, as Jim McElhiney
//! built it into POV-Ray and Christoph Lipka reworked it for 3.7): where a surface needs the
//! light other surfaces send it, a nearby sample of that light is reused if the cache holds
//! one close enough (by position and normal), else a new sample shoots rays over the
//! hemisphere and is kept. The cache's rules are POV-Ray's: its octree's cells, its weights
//! (linear during the pretrace and at deeper bounces, a smooth step at the top level of the
//! final render), its reach (the harmonic mean distance of a sample's rays, bounded by
//! `minimum_reuse` and `maximum_reuse` times the distance to the camera, shortened toward the
//! nearest surface a ray met), its settings per bounce, and its cosine-weighted Halton
//! directions drawn in turn from a pool.
//!
//! What differs from POV-Ray is the schedule (see `render::pretrace`): work is cut into units
//! (a block of a pass) that each see the samples of earlier passes and their own, never
//! another unit's of the same pass, so the picture is the same for any thread count.

use super::Tracer;
use crate::scene::{Radiosity as Settings, Rgb, Seer, SurfaceHit};
use glam::DVec3;

/// POV-Ray's `OT_BIAS`: the octree's cells are counted from here, so that they are positive.
const BIAS: f64 = 10_000_000.0;
/// Samples of a weight this small are left out (`RAD_EPSILON`).
const WEIGHT_EPSILON: f64 = 0.001;
/// Below this distance a cached sample counts as at the point itself (`AVG_NEAR_EPSILON`).
const NEAR_EPSILON: f64 = 0.000001;
/// A cached sample in front of the point by more than this (over the distance) is not used,
/// and one in front by less counts less (`IN_FRONT_LIMIT`).
const IN_FRONT_LIMIT: f64 = -0.05;
/// Rays of a weight below this raise the error bound of their query (POV-Ray's
/// `WEIGHT_ERROR_BOUND_OFFSET`).
const WEIGHT_OFFSET: f64 = 0.25;

/// What one bounce of radiosity uses, from the settings (POV-Ray's
/// `RadiosityRecursionSettings`).
#[derive(Clone, Copy, Debug)]
pub(in crate::render) struct Bounce {
    /// Rays a sample shoots: `count` halved at each bounce, at least 5.
    rays: u32,
    /// Samples found near a point that let it reuse them: `nearest_count`, then 2, then 1.
    reuse_count: f64,
    /// The error bound's factor: 2 to the bounce.
    error_bound_factor: f64,
    /// `minimum_reuse` and `maximum_reuse`, doubled at each bounce.
    min_reuse: f64,
    max_reuse: f64,
    /// The size of a sample's octree cell over its reach (1 at the top, 1/8 deeper: deeper
    /// samples are sometimes missed, for speed, as in POV-Ray).
    address_factor: f64,
    /// The trace level a sample's rays start from, and their weight.
    trace_level: u32,
    weight: f64,
}

impl Bounce {
    /// The settings of each bounce, from the top.
    pub(in crate::render) fn all(s: &Settings) -> Vec<Bounce> {
        (0..s.recursion_limit)
            .map(|depth| {
                let d = f64::from(depth);
                let error_bound_factor = 2f64.powf(d);
                let overfill = if depth == 0 { 1.0 } else { 8.0 };
                Bounce {
                    rays: ((f64::from(s.count) * 0.5f64.powf(d)) as u32).max(5),
                    reuse_count: f64::from(match depth {
                        0 => s.nearest_count,
                        1 => s.nearest_count.min(2),
                        _ => 1,
                    }),
                    error_bound_factor,
                    min_reuse: s.minimum_reuse * 2f64.powf(d),
                    max_reuse: s.maximum_reuse * 2f64.powf(d),
                    address_factor: s.error_bound * error_bound_factor / overfill,
                    trace_level: (1.5 * (d + 1.0)) as u32,
                    weight: (0.5 * s.brightness).powf(d + 1.0),
                }
            })
            .collect()
    }
}

/// The cosine-weighted directions samples draw their rays from, around +y: POV-Ray's pool of
/// `n` (`count`'s second value). Below 1600 it is the start of POV-Ray 3.6's table; otherwise
/// the first `n` points of the 2-D Halton sequence in bases 2 and 3.
pub(in crate::render) fn directions(n: u32) -> Vec<DVec3> {
    if (n as usize) < super::radiosity_legacy::LEGACY.len() {
        return super::radiosity_legacy::LEGACY[..n as usize]
            .iter()
            .map(|&[x, y, z]| {
                let unpack = |b: u8| f64::from(b) * (1.0 / 255.0);
                DVec3::new(unpack(x) * 2.0 - 1.0, unpack(y), unpack(z) * 2.0 - 1.0).normalize()
            })
            .collect();
    }
    fn halton(base: u64, index: u64) -> f64 {
        let (mut i, mut h, mut q) = (index + 1, 0.0, 1.0 / base as f64);
        while i > 0 {
            h += (i % base) as f64 * q;
            i /= base;
            q /= base as f64;
        }
        h
    }
    (0..u64::from(n))
        .map(|i| {
            let r = halton(2, i).sqrt();
            let theta = halton(3, i) * (2.0 * std::f64::consts::PI);
            let (x, z) = (r * theta.cos(), r * theta.sin());
            DVec3::new(x, (1.0 - x * x - z * z).sqrt(), z)
        })
        .collect()
}

/// A cell of the octree: its position in cells of its size, and its size as the exponent
/// of an IEEE single (127 for a size of 1), as POV-Ray names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct CellId {
    x: i32,
    y: i32,
    z: i32,
    size: i32,
}

impl CellId {
    /// The cell one size up that holds this one (POV-Ray's rounding for negative cells).
    fn parent(self) -> CellId {
        let up = |v: i32| if v >= 0 { v >> 1 } else { (v + 1) / 2 };
        CellId {
            x: up(self.x),
            y: up(self.y),
            z: up(self.z),
            size: self.size + 1,
        }
    }

    fn side(self) -> f64 {
        f64::from(f32::from_bits(((self.size as u32) & 0xff) << 23))
    }

    /// Whether `p` lies within the cell grown by half its size on every side.
    fn holds(self, p: DVec3) -> bool {
        let s = self.side();
        let near = |v: f64, i: i32| (v + BIAS - (f64::from(i) + 0.5) * s).abs() < s;
        near(p.x, self.x) && near(p.y, self.y) && near(p.z, self.z)
    }

    /// The child slot of this cell in its parent.
    fn slot(self) -> usize {
        ((self.x & 1) * 4 + (self.y & 1) * 2 + (self.z & 1)) as usize
    }

    /// The smallest cell that holds a sphere of `radius` at `centre` with at most half its
    /// size hanging over (POV-Ray's `ot_index_sphere`).
    fn of_sphere(centre: DVec3, radius: f64) -> CellId {
        let (lo, hi) = (centre - radius, centre + radius);
        let extent = (hi - lo).max_element();
        // A power of two at most the extent (the float's mantissa cleared).
        let mut side = f64::from(f32::from_bits((extent as f32).to_bits() & 0xff80_0000));
        if side == 0.0 {
            side = 1.0;
        }
        let farthest = lo.abs().max_element() + BIAS;
        while farthest / side > 1e9 {
            side *= 2.0;
        }
        let mid = (lo + hi) / 2.0;
        let cell = |v: f64| ((v + BIAS) / side).floor() as i32;
        let mut id = CellId {
            x: cell(mid.x),
            y: cell(mid.y),
            z: cell(mid.z),
            size: (((side as f32).to_bits() & 0x7f80_0000) >> 23) as i32,
        };
        while !id.holds(lo) || !id.holds(hi) {
            id = id.parent();
        }
        id
    }
}

/// A sample kept in the cache (POV-Ray's `ot_block`).
#[derive(Clone, Copy, Debug)]
struct Sample {
    point: DVec3,
    normal: DVec3,
    /// The direction of the nearest surface its rays met.
    to_nearest: DVec3,
    light: Rgb,
    /// Its reach: the harmonic mean distance of its rays, bounded (kept as a single, as in
    /// POV-Ray).
    reach: f32,
    nearest: f32,
    quality: f32,
    bounce: u32,
}

struct Node {
    id: CellId,
    /// The cell's centre (plus POV-Ray's bias) and size, for the test of a point.
    centre: DVec3,
    side: f64,
    kids: [u32; 8],
    /// The samples filed here, newest last.
    samples: Vec<u32>,
}

impl Node {
    /// Whether `p` lies within the cell grown by half its size on every side.
    #[inline]
    fn holds(&self, p: DVec3) -> bool {
        let s = self.side;
        (p.x + BIAS - self.centre.x).abs() < s
            && (p.y + BIAS - self.centre.y).abs() < s
            && (p.z + BIAS - self.centre.z).abs() < s
    }
}

/// One bounce's octree.
#[derive(Default)]
struct Tree {
    nodes: Vec<Node>,
    root: Option<u32>,
}

/// Samples filed in POV-Ray's octree (one for each bounce): each in the cell of its reach's
/// size, found by the points within that cell grown by half.
#[derive(Default)]
pub(in crate::render) struct Cache {
    samples: Vec<Sample>,
    trees: Vec<Tree>,
}

/// No child (the root is never a child).
const NONE: u32 = u32::MAX;

impl Tree {
    fn node(&mut self, id: CellId) -> u32 {
        let side = id.side();
        self.nodes.push(Node {
            id,
            centre: DVec3::new(
                (f64::from(id.x) + 0.5) * side,
                (f64::from(id.y) + 0.5) * side,
                (f64::from(id.z) + 0.5) * side,
            ),
            side,
            kids: [NONE; 8],
            samples: Vec::new(),
        });
        (self.nodes.len() - 1) as u32
    }

    /// A root one size up, holding the old one.
    fn grow(&mut self, root: u32) -> u32 {
        let old = self.nodes[root as usize].id;
        let new = self.node(old.parent());
        self.nodes[new as usize].kids[old.slot()] = root;
        new
    }

    /// Files sample `index` in cell `id` (POV-Ray's `GetNode`: the tree grows up to hold it,
    /// then down to its cell).
    fn file(&mut self, index: u32, id: CellId) {
        let Some(mut root) = self.root else {
            let node = self.node(id);
            self.nodes[node as usize].samples.push(index);
            self.root = Some(node);
            return;
        };
        while self.nodes[root as usize].id.size < id.size {
            root = self.grow(root);
        }
        let mut up = id;
        while up.size < self.nodes[root as usize].id.size {
            up = up.parent();
        }
        while {
            let r = self.nodes[root as usize].id;
            (up.x, up.y, up.z) != (r.x, r.y, r.z)
        } {
            root = self.grow(root);
            up = up.parent();
        }
        self.root = Some(root);
        let mut node = root;
        while self.nodes[node as usize].id.size > id.size {
            let target = self.nodes[node as usize].id.size - 1;
            let mut kid_id = id;
            while kid_id.size < target {
                kid_id = kid_id.parent();
            }
            let slot = kid_id.slot();
            let mut kid = self.nodes[node as usize].kids[slot];
            if kid == NONE {
                kid = self.node(kid_id);
                self.nodes[node as usize].kids[slot] = kid;
            }
            node = kid;
        }
        self.nodes[node as usize].samples.push(index);
    }
}

impl Cache {
    fn file(&mut self, sample: Sample, address_factor: f64) {
        let index = self.samples.len() as u32;
        self.samples.push(sample);
        let id = CellId::of_sphere(sample.point, f64::from(sample.reach) * address_factor);
        let bounce = sample.bounce as usize;
        if self.trees.len() <= bounce {
            self.trees.resize_with(bounce + 1, Tree::default);
        }
        self.trees[bounce].file(index, id);
    }

    /// Calls `f` with every sample of `bounce` whose cell (grown by half) holds `p`.
    #[inline]
    fn near(&self, p: DVec3, bounce: u32, f: &mut impl FnMut(&Sample)) {
        let Some(tree) = self.trees.get(bounce as usize) else {
            return;
        };
        if let Some(root) = tree.root {
            self.visit(tree, root, p, f);
        }
    }

    /// The samples of node `at` and of its children that hold `p`, the children first.
    fn visit(&self, tree: &Tree, at: u32, p: DVec3, f: &mut impl FnMut(&Sample)) {
        let node = &tree.nodes[at as usize];
        for &k in &node.kids {
            if k != NONE && tree.nodes[k as usize].holds(p) {
                self.visit(tree, k, p, f);
            }
        }
        for &s in node.samples.iter().rev() {
            f(&self.samples[s as usize]);
        }
    }

    /// Files every sample of `other` here, in the order they were taken.
    pub(in crate::render) fn merge(&mut self, other: &Cache, bounces: &[Bounce]) {
        for s in &other.samples {
            self.file(*s, bounces[s.bounce as usize].address_factor);
        }
    }
}

/// The pass being rendered: one of the pretrace's, or the final render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(in crate::render) enum Pass {
    Pretrace,
    Final,
}

/// What every unit of work shares: the settings and what follows from them, the camera's
/// position, and the samples of the passes finished.
pub(in crate::render) struct Shared {
    pub(in crate::render) settings: Settings,
    pub(in crate::render) bounces: Vec<Bounce>,
    pub(in crate::render) directions: Vec<DVec3>,
    pub(in crate::render) cache: Cache,
    pub(in crate::render) camera: DVec3,
}

impl Shared {
    /// Radiosity with `settings`, seen from `camera`, with an empty cache.
    pub(in crate::render) fn new(settings: &Settings, camera: DVec3) -> Shared {
        Shared {
            bounces: Bounce::all(settings),
            directions: directions(settings.directions),
            settings: settings.clone(),
            cache: Cache::default(),
            camera,
        }
    }
}

/// What a tracer needs for radiosity: what all share, its own samples of this pass, and
/// where it is in the direction pool.
pub(in crate::render) struct Gathering<'a> {
    shared: &'a Shared,
    /// The samples this unit of work took (its block, in this pass).
    pub(in crate::render) own: Cache,
    pass: Pass,
    /// `error_bound`, times `low_error_factor` during the pretrace.
    error_bound: f64,
    /// The next direction of the pool, for each bounce.
    pub(in crate::render) next: Vec<usize>,
    /// The bounce being gathered (0 for the surfaces rays from the camera meet).
    pub(in crate::render) depth: u32,
    /// The quality of the light gathered along the path being traced (POV-Ray's ticket's
    /// `radiosityQuality`): below 1 where a deeper bounce reused fewer samples than it wanted.
    quality: f64,
    /// Top-level queries and the samples they found (×4), for the adaptive pretrace.
    pub(in crate::render) queries: u64,
    pub(in crate::render) found: f64,
    /// Samples taken, rays they shot, and queries answered from the cache.
    pub(in crate::render) taken: super::super::SamplesByDepth,
    pub(in crate::render) rays: u64,
    pub(in crate::render) reused: u64,
    /// Ground truth instead of the cache: the state of the random stream that picks each
    /// query's one direction.
    stream: Option<u64>,
}

impl<'a> Gathering<'a> {
    /// Ground truth: every query answered afresh by one ray in a random cosine-weighted
    /// direction (from the stream `seed` starts), no cache.
    pub(in crate::render) fn reference(shared: &'a Shared, seed: u64) -> Self {
        let mut g = Gathering::new(shared, Pass::Final, 0);
        g.restart(seed);
        g
    }

    /// Starts ground truth's random stream again from `seed` (a new path), keeping the rest.
    pub(in crate::render) fn restart(&mut self, seed: u64) {
        self.stream = Some(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0xD1B5_4A32_D192_ED03);
    }

    /// The next number of the stream, uniform in [0, 1) (SplitMix64).
    fn uniform(&mut self) -> f64 {
        let state = self.stream.get_or_insert(0);
        *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = *state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A unit of work of `pass`, drawing directions from `start` on in the pool.
    pub(in crate::render) fn new(shared: &'a Shared, pass: Pass, start: usize) -> Self {
        let s = &shared.settings;
        Gathering {
            shared,
            own: Cache::default(),
            pass,
            error_bound: match pass {
                Pass::Final => s.error_bound,
                Pass::Pretrace => s.error_bound * s.low_error_factor,
            },
            next: vec![start % shared.directions.len().max(1); shared.bounces.len()],
            depth: 0,
            quality: 1.0,
            queries: 0,
            found: 0.0,
            taken: [0; 5],
            rays: 0,
            reused: 0,
            stream: None,
        }
    }

    /// The weighted light of the cached samples near `p` (normal `n`) that its error bound
    /// lets it reuse, and their total weight (POV-Ray's `FindReusableBlock`).
    fn reusable(&self, bound: f64, p: DVec3, n: DVec3) -> (Rgb, f64) {
        let final_top = self.pass == Pass::Final && self.depth == 0;
        let (mut sum, mut weights) = (Rgb::ZERO, 0.0);
        let mut add = |s: &Sample| {
            let delta = p - s.point;
            let square = delta.length_squared();
            let quick = f64::from(s.reach) * bound;
            if square >= quick * quick {
                return;
            }
            let dist = square.sqrt();
            let mut reach = f64::from(s.reach);
            let apart = dist > NEAR_EPSILON;
            let unit = if apart { delta / dist } else { DVec3::ZERO };
            if apart {
                // Shorter toward the nearest surface the sample's rays met.
                let toward = s.to_nearest.dot(unit);
                if toward > 0.0 {
                    reach = toward * f64::from(s.nearest) + (1.0 - toward) * reach;
                }
            }
            if dist >= reach * bound {
                return;
            }
            let error = dist / reach + 2.0 * (1.0 - n.dot(s.normal)).abs().sqrt();
            if error >= bound {
                return;
            }
            let in_front = if apart {
                let half = n + s.normal;
                unit.dot(half) / half.length()
            } else {
                1.0
            };
            if in_front <= IN_FRONT_LIMIT {
                return;
            }
            let t = error / bound;
            let mut weight = if !final_top {
                1.0 - t
            } else if t < 0.5 {
                1.0 - (t * 2.0) * (t * 2.0) / 2.0
            } else {
                ((1.0 - t) * 2.0) * ((1.0 - t) * 2.0) / 2.0
            };
            if in_front <= 0.0 {
                weight *= 1.0 - in_front / IN_FRONT_LIMIT;
            }
            if weight > WEIGHT_EPSILON {
                weight *= f64::from(s.quality);
                sum += s.light * weight;
                weights += weight;
            }
        };
        self.shared.cache.near(p, self.depth, &mut add);
        self.own.near(p, self.depth, &mut add);
        if weights > 0.0 {
            (sum / weights, weights)
        } else {
            (Rgb::ZERO, 0.0)
        }
    }
}

impl Tracer<'_> {
    /// The light other surfaces send to `hit` at `point`, whose unperturbed normal facing the
    /// ray is `raw` and perturbed one `layer` (POV-Ray's `ComputeAmbient`): reused from the
    /// cache where enough samples lie near, else gathered anew. `weight` is how much it can
    /// add to the pixel.
    pub(super) fn ambient(
        &mut self,
        hit: &SurfaceHit,
        raw: DVec3,
        layer: DVec3,
        weight: f64,
    ) -> Rgb {
        let Some(g) = self.gathering.as_mut() else {
            return Rgb::ZERO;
        };
        let shared = g.shared;
        let s = &shared.settings;
        let bounce = shared.bounces[g.depth as usize];
        let n = if s.normal { layer } else { raw };
        if g.stream.is_some() {
            let light = self.one_ray(hit, raw, n, bounce);
            let grey = super::grey(light);
            return (light * (1.0 - s.gray_threshold) + Rgb::splat(s.gray_threshold * grey))
                * s.brightness;
        }
        let mut bound = g.error_bound;
        if weight < WEIGHT_OFFSET {
            bound += WEIGHT_OFFSET - weight;
        }
        let (mut light, mut reuse) = g.reusable(bound * bounce.error_bound_factor, hit.point, n);
        if g.depth == 0 {
            g.queries += 1;
            g.found += reuse * 4.0;
        }
        let enough = reuse * 4.0 >= bounce.reuse_count
            || (g.pass == Pass::Final && !s.always_sample && reuse > 0.0);
        if enough {
            g.reused += 1;
        } else {
            let (gathered, quality) = self.gather(hit, raw, n, bounce);
            light = if reuse > 0.0 {
                (light * reuse + gathered * quality) / (reuse + quality)
            } else {
                gathered
            };
            reuse += quality;
        }
        let Some(g) = self.gathering.as_mut() else {
            return Rgb::ZERO;
        };
        g.quality = g.quality.min(4.0 * reuse / bounce.reuse_count);
        let grey = super::grey(light);
        light = light * (1.0 - s.gray_threshold) + Rgb::splat(s.gray_threshold * grey);
        light * s.brightness
    }

    /// A new sample at the hit (POV-Ray's `GatherLight`): rays over the hemisphere of normal
    /// `n` (directions that would leave below the unperturbed normal `raw` skipped), the mean
    /// of what they see, kept in the cache with its reach. Returns the light and its quality.
    fn gather(&mut self, hit: &SurfaceHit, raw: DVec3, n: DVec3, bounce: Bounce) -> (Rgb, f64) {
        let Some(g) = self.gathering.as_mut() else {
            return (Rgb::ZERO, 0.0);
        };
        let shared = g.shared;
        let s = &shared.settings;
        let to_eye = (shared.camera - hit.point).length();
        let (reuse_min, reuse_max) = (to_eye * bounce.min_reuse, to_eye * bounce.max_reuse);
        let pool = shared.directions.len();
        let count = (bounce.rays as usize).min(pool);
        let depth = g.depth as usize;
        let saved = (self.max_level, self.bailout, self.seer, g.quality);
        let level = bounce.trace_level + 1;
        self.max_level = self.max_level.max(level);
        self.bailout = s.adc_bailout;
        let weight = (s.adc_bailout + 1e-10).max(bounce.weight);

        let mut frame = Frame::new(n, raw, similar(raw, n), count, pool);
        let (mut sum, mut quality_sum) = (Rgb::ZERO, 0.0);
        let (mut inverse_sum, mut smallest, mut toward) = (0.0, 2e10, DVec3::ZERO);
        let (mut ok, mut ok_raw) = (0u32, 0u32);
        for i in 0..count {
            let Some(g) = self.gathering.as_mut() else {
                break;
            };
            let mut dir = frame.next(&shared.directions, &mut g.next[depth]);
            if dir.is_none() && !frame.raw_mode {
                frame = Frame::new(raw, raw, true, count, pool);
                dir = frame.next(&shared.directions, &mut g.next[depth]);
            }
            let Some(dir) = dir else {
                break;
            };
            ok += 1;
            if frame.raw_mode {
                ok_raw += 1;
            }
            g.quality = 1.0;
            g.depth += 1;
            let ray = self.scene.spawn(hit, hit.point, dir);
            self.seer = Seer {
                reflected: false,
                radiosity: true,
                sample: true,
            };
            // (The ray's share of the sample, against the importance of what it meets.)
            let share = i as f64 / (count as f64 - 1.0).max(1.0);
            // (The share stays set after the loop, as in POV-Ray: see `Tracer::trace`.)
            self.importance_query = share;
            let mut colour = self.trace(&ray, level, weight, &super::MediumStack::default());
            let (distance, found) = (self.distance, self.importance_found);
            let Some(g) = self.gathering.as_mut() else {
                break;
            };
            g.depth -= 1;
            if found >= share {
                let mut quality = g.quality;
                if found < 1.0 {
                    // (Fewer rays go on to such an object: each counts for more.)
                    let last = (found * (count as f64 - 1.0)).floor();
                    quality *= count as f64 / (last + 1.0);
                }
                let brightest = colour.max_element();
                if s.max_sample > 0.0 && brightest > s.max_sample {
                    colour *= s.max_sample / brightest;
                }
                quality_sum += quality;
                sum += colour * quality;
            }
            if distance < smallest {
                smallest = distance;
                toward = dir;
            }
            inverse_sum += 1.0 / distance;
        }
        (self.max_level, self.bailout, self.seer) = (saved.0, saved.1, saved.2);
        let Some(g) = self.gathering.as_mut() else {
            return (Rgb::ZERO, 0.0);
        };
        g.taken[(g.depth as usize).min(4)] += 1;
        g.rays += u64::from(ok);
        let light = if quality_sum == 0.0 {
            sum
        } else {
            sum / quality_sum
        };
        let quality = quality_sum / f64::from(ok.max(1));
        let mut mean = f64::from(ok) / inverse_sum;
        // (A sample whose nearest ray almost grazed another surface is not kept.)
        if smallest > reuse_max * 0.0001 {
            mean = mean.max(reuse_min).min(reuse_max);
            let raw_most = ok_raw > ok - ok_raw;
            let sample = Sample {
                point: hit.point,
                normal: if raw_most { raw } else { n },
                to_nearest: toward,
                light,
                reach: mean as f32,
                nearest: smallest as f32,
                quality: quality as f32,
                bounce: g.depth,
            };
            g.own.file(sample, bounce.address_factor);
        }
        g.quality = saved.3.max(quality);
        (light, quality)
    }
}

impl Tracer<'_> {
    /// Ground truth's answer to a query: the light seen by one ray in a random direction,
    /// cosine-weighted about `n` and above the unperturbed normal `raw` (drawn again until it
    /// is), as a sample's rays see it.
    fn one_ray(&mut self, hit: &SurfaceHit, raw: DVec3, n: DVec3, bounce: Bounce) -> Rgb {
        let Some(g) = self.gathering.as_mut() else {
            return Rgb::ZERO;
        };
        let s = &g.shared.settings;
        let frame = Frame::new(n, raw, false, 0, 0);
        let mut dir = raw;
        for _ in 0..64 {
            let (u, v) = (g.uniform(), g.uniform());
            let (r, theta) = (u.sqrt(), v * (2.0 * std::f64::consts::PI));
            let (x, z) = (r * theta.cos(), r * theta.sin());
            let d = frame.x * x + frame.y * (1.0 - u).max(0.0).sqrt() + frame.z * z;
            if d.dot(raw) > 0.0 {
                dir = d;
                break;
            }
        }
        g.taken[(g.depth as usize).min(4)] += 1;
        g.rays += 1;
        g.depth += 1;
        let (max_sample, bailout) = (s.max_sample, s.adc_bailout);
        let saved = (self.max_level, self.bailout, self.seer);
        let level = bounce.trace_level + 1;
        self.max_level = self.max_level.max(level);
        self.bailout = bailout;
        self.seer = Seer {
            reflected: false,
            radiosity: true,
            sample: true,
        };
        let ray = self.scene.spawn(hit, hit.point, dir);
        let weight = (bailout + 1e-10).max(bounce.weight);
        let mut colour = self.trace(&ray, level, weight, &super::MediumStack::default());
        (self.max_level, self.bailout, self.seer) = saved;
        if let Some(g) = self.gathering.as_mut() {
            g.depth -= 1;
        }
        let brightest = colour.max_element();
        if max_sample > 0.0 && brightest > max_sample {
            colour *= max_sample / brightest;
        }
        colour
    }
}

/// POV-Ray's `similar`: two vectors whose coordinates differ by less than 1e-10 in all.
fn similar(a: DVec3, b: DVec3) -> bool {
    (a - b).abs().element_sum() < 1e-10
}

/// The frame the pool's directions (around +y) are turned into, about a normal, and how many
/// may still be drawn (POV-Ray's `SampleDirectionGenerator`).
struct Frame {
    x: DVec3,
    y: DVec3,
    z: DVec3,
    raw: DVec3,
    raw_mode: bool,
    remaining: usize,
}

impl Frame {
    fn new(n: DVec3, raw: DVec3, raw_mode: bool, count: usize, pool: usize) -> Frame {
        let off = if n.z.abs() > 0.9 { DVec3::Y } else { DVec3::Z };
        let x = n.cross(off).normalize();
        let z = x.cross(n).normalize();
        Frame {
            x,
            y: n,
            z,
            raw,
            raw_mode,
            remaining: if raw_mode {
                pool
            } else {
                (count * 5).min(pool)
            },
        }
    }

    /// The next direction of the pool that leaves above the unperturbed normal.
    fn next(&mut self, pool: &[DVec3], index: &mut usize) -> Option<DVec3> {
        while self.remaining > 0 {
            let v = pool[*index];
            *index = (*index + 1) % pool.len();
            self.remaining -= 1;
            let d = if self.y.y > 1.0 - WEIGHT_EPSILON {
                v
            } else if self.y.y < -1.0 + WEIGHT_EPSILON {
                -v
            } else {
                self.x * v.x + self.y * v.y + self.z * v.z
            };
            if self.raw_mode || d.dot(self.raw) > 0.0 {
                return Some(d);
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether every direction is a unit vector above the plane y = 0, and their mean
    /// cosine about +y (2/3 for a cosine-weighted hemisphere).
    fn upper_units(d: &[DVec3]) -> (bool, f64) {
        let unit_up = d
            .iter()
            .all(|v| (v.length() - 1.0).abs() < 1e-12 && v.y >= 0.0);
        (unit_up, d.iter().map(|v| v.y).sum::<f64>() / d.len() as f64)
    }

    #[test]
    fn the_pool_is_cosine_weighted_around_y() {
        let d = directions(1600);
        assert_eq!(d.len(), 1600);
        let (unit_up, mean) = upper_units(&d);
        assert!(unit_up);
        assert!((mean - 2.0 / 3.0).abs() < 0.01, "{mean}");
        // The first point: Halton(2) = 1/2, Halton(3) = 1/3.
        let r = 0.5f64.sqrt();
        let t = 2.0 * std::f64::consts::PI / 3.0;
        assert!(d[0].abs_diff_eq(DVec3::new(r * t.cos(), r, r * t.sin()), 1e-12));
    }

    #[test]
    fn a_pool_below_1600_is_the_start_of_the_old_table() {
        let d = directions(400);
        assert_eq!(d.len(), 400);
        assert!(upper_units(&d).0);
        // The table's first entry is (250, 71, 127).
        let first = DVec3::new(
            250.0 / 255.0 * 2.0 - 1.0,
            71.0 / 255.0,
            127.0 / 255.0 * 2.0 - 1.0,
        );
        assert!(d[0].abs_diff_eq(first.normalize(), 1e-12));
        // It is cosine-weighted too, and not the Halton pool.
        let (unit_up, mean) = upper_units(&directions(1599));
        assert!(unit_up);
        assert!((mean - 2.0 / 3.0).abs() < 0.02, "{mean}");
        assert!(!d[0].abs_diff_eq(directions(1600)[0], 1e-3));
    }

    #[test]
    fn a_sample_is_filed_in_the_smallest_cell_that_holds_its_reach() {
        // Reach 0.3 about (1.25, 2.25, 3.25): a box 0.6 wide, so cells of size 0.5 (exponent
        // 126), the one from 1 to 1.5 on x (grown by half: 0.75 to 1.75).
        let id = CellId::of_sphere(DVec3::new(1.25, 2.25, 3.25), 0.3);
        assert_eq!(id.size, 126);
        assert!(id.holds(DVec3::new(1.7, 2.3, 2.8)));
        assert!(!id.holds(DVec3::new(1.8, 2.25, 3.25)));
        // About (1, 2, 3) the box straddles the cells of 0.5: it goes one size up.
        assert_eq!(CellId::of_sphere(DVec3::new(1.0, 2.0, 3.0), 0.3).size, 127);
        // Tiny reaches stop at POV-Ray's smallest cell near the origin (1/64).
        assert_eq!(CellId::of_sphere(DVec3::ZERO, 1e-6).size, 127 - 6);
    }

    #[test]
    fn the_cache_finds_what_it_filed_near_and_only_near() {
        let mut cache = Cache::default();
        let at = |p: DVec3, reach: f32, bounce| Sample {
            point: p,
            normal: DVec3::Y,
            to_nearest: DVec3::X,
            light: Rgb::ONE,
            reach,
            nearest: reach,
            quality: 1.0,
            bounce,
        };
        for i in 0..100 {
            let p = DVec3::new(f64::from(i) * 0.37 - 10.0, 0.0, f64::from(i % 7));
            cache.file(at(p, 0.2 + (i % 5) as f32 * 0.3, 0), 1.8);
        }
        cache.file(at(DVec3::new(1.0, 0.0, 1.0), 0.5, 1), 1.8);
        let mut found = 0;
        cache.near(DVec3::new(1.0, 0.0, 1.0), 1, &mut |_| found += 1);
        assert_eq!(found, 1);
        // Every sample whose reach (times the error bound) holds the point is found.
        for probe in [DVec3::new(-3.0, 0.1, 2.0), DVec3::new(5.5, 0.0, 4.0)] {
            let mut seen = Vec::new();
            cache.near(probe, 0, &mut |s| seen.push(s.point));
            for s in &cache.samples[..100] {
                if (s.point - probe).length() < f64::from(s.reach) * 1.8 {
                    assert!(seen.contains(&s.point), "{probe} missed {}", s.point);
                }
            }
        }
    }
}
