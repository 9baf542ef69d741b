//! Radiosity's pretrace (POV-Ray's `RadiosityTask`): before the picture, passes over the
//! image on ever finer grids of jittered points fill the cache with samples, so that the
//! final render finds most of what it needs.
//!
//! POV-Ray's grid, jitter and adaptive rule, and the schedule of its reproducible mode
//! (`+HR`): pass k (from 0) deals POV-Ray's 32×32 blocks out to 2^k groups, block n to group
//! n mod 2^k; the groups run in parallel, each taking its blocks in order and seeing the
//! samples of the earlier passes and its own; at the end of a pass every group's samples join
//! the cache, in group order. So the first pass takes samples as one thread would, the finer
//! ones in parallel, and the cache (and the picture) is the same for any number of threads.

use super::camera;
use super::transport::radiosity::{Gathering, Pass, Shared};
use super::transport::{MediumStack, Tracer};
use super::{BLOCK_SIZE, RenderOptions};
use crate::scene::{Scene, mt19937};
use rayon::prelude::*;

/// Where a block stands in the pretrace: the parts of it still refined (POV-Ray's adaptive
/// pretrace splits a block into sub-blocks and stops those whose points find enough samples),
/// as (column, row) among `split` × `split.1` parts.
#[derive(Clone, Debug)]
struct Progress {
    open: Vec<(u32, u32)>,
    split: (u32, u32),
}

/// What the pretrace did, for statistics.
#[derive(Clone, Debug, Default)]
pub struct PretraceStats {
    /// Passes over the image.
    pub passes: u32,
    /// Points traced.
    pub points: u64,
    /// Samples taken in each pass, by depth.
    pub samples: Vec<super::SamplesByDepth>,
    /// The rays they shot.
    pub rays: u64,
    /// The time it took.
    pub time: std::time::Duration,
}

impl PretraceStats {
    /// Samples taken in all passes.
    pub fn total_samples(&self) -> u64 {
        self.samples.iter().flatten().sum()
    }
}

/// POV-Ray's table of jitter values: 2047 numbers from −1 to 1 (MT19937, default seed).
fn jitter_table() -> Vec<f64> {
    mt19937(2047)
        .into_iter()
        .map(|y| f64::from(y) / 4294967296.0 * 2.0 - 1.0)
        .collect()
}

/// A start in the direction pool for a unit of work (a block of a pass), so that neighbouring
/// blocks draw different directions first.
pub(super) fn pool_start(block: u32, pass: u32) -> usize {
    let mut h = u64::from(block) << 32 | u64::from(pass);
    h = (h ^ (h >> 33)).wrapping_mul(0xff51_afd7_ed55_8ccd);
    h = (h ^ (h >> 33)).wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    (h ^ (h >> 33)) as usize
}

/// Runs the pretrace of `scene` (which has radiosity) for an image of `options`' size (the
/// whole image, whatever the region, so that a region's pixels are the whole render's):
/// the radiosity every block of the final render starts from. `None` if cancelled.
pub(super) fn pretrace(
    scene: &Scene,
    options: &RenderOptions,
    pool: &rayon::ThreadPool,
    camera_media: Option<MediumStack>,
) -> Option<(Shared, PretraceStats)> {
    let settings = scene.radiosity()?;
    let began = std::time::Instant::now();
    let mut shared = Shared::new(settings, scene.camera().location);
    let (width, height) = (options.width, options.height);
    let largest = f64::from(width.max(height));
    let mut start = largest * settings.pretrace_start;
    let end = (largest * settings.pretrace_end).max(1.0);
    let mut steps = ((start / end).ln() / 2f64.ln() + (1.0 - 1e-10)).floor() as i64 + 1;
    if steps > 251 {
        steps = 251;
        start = end * 2f64.powi(251);
    }
    let steps = steps.max(1) as u32;
    let jitter = jitter_table();
    let (bx, by) = (width.div_ceil(BLOCK_SIZE), height.div_ceil(BLOCK_SIZE));
    let mut blocks: Vec<Option<Progress>> = vec![
        Some(Progress {
            open: vec![(0, 0)],
            split: (1, 1),
        });
        (bx * by) as usize
    ];
    let mut stats = PretraceStats::default();
    let mut carried_next: Option<Vec<usize>> = None;
    for pass in 0..steps {
        if blocks.iter().all(Option::is_none) {
            break;
        }
        let size = (start * 0.5f64.powi(pass as i32)).max(end);
        let next_size = (start * 0.5f64.powi(pass as i32 + 1)).max(end);
        let last = pass + 1 == steps;
        // (In POV-Ray's order: one group, drawing on in the pool from the last pass.)
        let groups = if options.radiosity_povray_order {
            1
        } else {
            (1u32 << pass.min(20)).min(bx * by)
        };
        let carried = carried_next.take();
        let shared_now = &shared;
        let blocks_now = &blocks;
        let done: Vec<_> = pool.install(|| {
            (0..groups)
                .into_par_iter()
                .with_max_len(1)
                .map(|group| {
                    let mut tracer = Tracer::new(scene);
                    tracer.pretrace = true;
                    let mut g = Gathering::new(shared_now, Pass::Pretrace, pool_start(group, pass));
                    if options.radiosity_povray_order {
                        g.next = carried.clone().unwrap_or_else(|| vec![0; g.next.len()]);
                    }
                    tracer.gathering = Some(g);
                    let mut rand = Jitter {
                        table: &jitter,
                        index: 0,
                    };
                    let mut after = Vec::new();
                    let mut points = 0;
                    for serial in (group..bx * by).step_by(groups as usize) {
                        let Some(progress) = &blocks_now[serial as usize] else {
                            continue;
                        };
                        if options.cancel.is_cancelled() {
                            return None;
                        }
                        let unit = Unit {
                            scene,
                            options,
                            camera_media,
                            size,
                            next_size,
                            left: (serial % bx) * BLOCK_SIZE,
                            top: (serial / bx) * BLOCK_SIZE,
                        };
                        // POV-Ray's jitter: the table read on from a seed of the pass and the
                        // block.
                        rand.index = ((pass as usize + 1) * 17 + serial as usize * 13) % 2047;
                        let (progress, n) = unit.run(&mut tracer, &mut rand, progress, last);
                        after.push((serial, progress));
                        points += n;
                    }
                    let g = tracer.gathering?;
                    Some((g.own, after, points, (g.taken, g.rays), g.next))
                })
                .collect()
        });
        if options.cancel.is_cancelled() {
            return None;
        }
        stats.passes += 1;
        stats.samples.push([0; 5]);
        for (cache, after, points, (samples, rays), next) in done.into_iter().flatten() {
            carried_next = Some(next);
            shared.cache.merge(&cache, &shared.bounces);
            for (serial, progress) in after {
                blocks[serial as usize] = progress;
            }
            stats.points += points;
            let pass = stats.samples.last_mut().expect("this pass's counts");
            super::add_samples(pass, &samples);
            stats.rays += rays;
        }
    }
    stats.time = began.elapsed();
    Some((shared, stats))
}

/// POV-Ray's jitter generator: the table read on, one entry a call.
struct Jitter<'a> {
    table: &'a [f64],
    index: usize,
}

impl Jitter<'_> {
    fn next(&mut self) -> f64 {
        self.index = (self.index + 1) % self.table.len();
        self.table[self.index]
    }
}

/// One block of one pass.
struct Unit<'a> {
    scene: &'a Scene,
    options: &'a RenderOptions,
    camera_media: Option<MediumStack>,
    size: f64,
    next_size: f64,
    left: u32,
    top: u32,
}

impl Unit<'_> {
    /// Traces the block's points of the pass with `tracer` (whose gathering is its group's);
    /// returns where the block stands after it (`None`: done) and the points it traced.
    fn run(
        &self,
        tracer: &mut Tracer,
        rand: &mut Jitter,
        progress: &Progress,
        last: bool,
    ) -> (Option<Progress>, u64) {
        let (w, h) = (self.options.width, self.options.height);
        let right = (self.left + BLOCK_SIZE).min(w) - 1;
        let bottom = (self.top + BLOCK_SIZE).min(h) - 1;
        let (bw, bh) = (
            f64::from(right - self.left + 1),
            f64::from(bottom - self.top + 1),
        );
        let size = self.size;
        let adaptive_count = self.scene.radiosity().map_or(0, |r| r.pretrace_count);
        let across = |extent: f64, s: f64| ((extent + s - 1.0) / s) as u32;
        let (next_x, next_y) = (across(bw, self.next_size), across(bh, self.next_size));
        let adaptive = adaptive_count != 0;
        let (divide_x, divide_y) = if adaptive {
            (
                (f64::from(next_x) / f64::from(progress.split.0 * 4))
                    .floor()
                    .max(1.0) as u32,
                (f64::from(next_y) / f64::from(progress.split.1 * 4))
                    .floor()
                    .max(1.0) as u32,
            )
        } else {
            (1, 1)
        };
        let start_x = ((f64::from(self.left) - 0.5) / size).ceil() * size;
        let start_y = ((f64::from(self.top) - 0.5) / size).ceil() * size;
        let jitter = (size / 2.0).min(1.0);
        let offset = (size - 1.0) / 2.0;
        let mut open = Vec::new();
        let mut points = 0;
        for &(sx, sy) in &progress.open {
            if let Some(g) = tracer.gathering.as_mut() {
                g.queries = 0;
                g.found = 0.0;
            }
            let (cx, cy) = (f64::from(progress.split.0), f64::from(progress.split.1));
            let sub_x0 = f64::from(self.left) + bw * f64::from(sx) / cx;
            let sub_x1 = sub_x0 + bw / cx;
            let sub_y0 = f64::from(self.top) + bh * f64::from(sy) / cy;
            let sub_y1 = sub_y0 + bh / cy;
            let mut count = 0;
            let mut y = start_y;
            while y < sub_y1 {
                if y >= sub_y0 {
                    let mut x = start_x;
                    while x < sub_x1 {
                        if x >= sub_x0 {
                            // (POV-Ray's build evaluates the two jitters right to left.)
                            let jy = rand.next();
                            let jx = rand.next();
                            let (px, py) = (x + offset + jitter * jx, y + offset + jitter * jy);
                            let ray = camera::camera_ray(self.scene, w, h, px, py);
                            camera::trace_primary(tracer, &self.camera_media, ray);
                            count += 1;
                        }
                        x += size;
                    }
                }
                y += size;
            }
            points += count;
            let (queries, found) = tracer
                .gathering
                .as_ref()
                .map_or((0, 0.0), |g| (g.queries, g.found));
            let again = count < 9
                || (queries != 0
                    && !(adaptive && found / queries as f64 >= f64::from(adaptive_count)));
            if again {
                for dy in 0..divide_y {
                    for dx in 0..divide_x {
                        open.push((sx * divide_x + dx, sy * divide_y + dy));
                    }
                }
            }
        }
        let progress = (!last && !open.is_empty()).then(|| Progress {
            open,
            split: (progress.split.0 * divide_x, progress.split.1 * divide_y),
        });
        (progress, points)
    }
}
