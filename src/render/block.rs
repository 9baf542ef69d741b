//! One block of the image: its pixels (by the anti-aliasing method), their AOV layers, and
//! the work they took.

use super::antialias::{self, Block};
use super::transport::radiosity::{Gathering, Pass, Shared};
use super::transport::{MediumStack, Tracer};
use super::{Aov, BLOCK_SIZE, RayCounts, RenderOptions, aov_values, camera};
use crate::geometry::counters;
use crate::scene::{Gamma, Rgb, Scene};

/// What radiosity in POV-Ray's order carries from one block to the next: the final render's
/// samples so far and the next directions of the pool.
#[derive(Default)]
pub(super) struct Carry {
    samples: Option<(super::transport::radiosity::Cache, Vec<usize>)>,
}

/// Renders the block whose top-left pixel is (x0, y0), with the media camera rays start in
/// (if the same for all), radiosity's cache after the pretrace (if the scene has it) and, in
/// POV-Ray's order, what earlier blocks left.
///
/// With `centres` (methods 1 and 3, the band's centre samples traced first: see
/// [`antialias::BandCentres`]), the centre samples the block traced for its band and what
/// tracing them counted are taken from there, and `tracer` is the one that traced them.
pub(super) fn render_block<'a>(
    scene: &'a Scene,
    options: &RenderOptions,
    (camera_media, radiosity, mut carry): (
        Option<MediumStack>,
        Option<&Shared>,
        Option<&mut Carry>,
    ),
    (centres, tracer): (
        Option<(&antialias::BandCentres, &antialias::Centres)>,
        Option<Tracer<'a>>,
    ),
    x0: u32,
    y0: u32,
) -> BlockResult {
    let (w, h) = (options.width, options.height);
    let x1 = (x0 + BLOCK_SIZE).min(w);
    let y1 = (y0 + BLOCK_SIZE).min(h);
    let mut tracer = tracer.unwrap_or_else(|| Tracer::new(scene));
    // (Radiosity: the block adds its own samples to the pretrace's, seen by it alone.)
    let serial = (y0 / BLOCK_SIZE) * w.div_ceil(BLOCK_SIZE) + x0 / BLOCK_SIZE;
    tracer.gathering = radiosity.map(|shared| {
        match carry.as_mut() {
            // (POV-Ray's order: the directions start from the pool's first, and go on.)
            Some(c) => {
                let mut g = Gathering::new(shared, Pass::Final, 0);
                if let Some((own, next)) = c.samples.take() {
                    (g.own, g.next) = (own, next);
                }
                g
            }
            None => Gathering::new(
                shared,
                Pass::Final,
                super::pretrace::pool_start(serial, 255),
            ),
        }
    });
    counters::take(); // (this block's counts start from zero)
    let block = Block {
        scene,
        options,
        camera_media: &camera_media,
        xs: x0..x1,
        ys: y0..y1,
        centres,
    };
    let (pixels, samples) = match (radiosity, options.radiosity_reference) {
        (Some(shared), Some(paths)) => reference_pixels(&block, &mut tracer, shared, paths),
        _ => antialias::block_pixels(&block, &mut tracer),
    };
    let radiosity = tracer
        .gathering
        .as_ref()
        .map_or(([0; 5], 0, 0), |g| (g.taken, g.rays, g.reused));
    if let (Some(c), Some(g)) = (carry, tracer.gathering.take()) {
        c.samples = Some((g.own, g.next));
    }
    // (Traced before the counts and tests are taken.)
    let aov = block_aovs(&mut tracer, options, x0..x1, y0..y1);
    let mut tests = counters::take();
    if let Some((_, own)) = centres {
        tracer.counts.add(&own.counts);
        tests.add(&own.tests);
    }
    BlockResult {
        radiosity,
        x0,
        y0,
        width: x1 - x0,
        aov,
        pixels,
        counts: tracer.counts,
        tests,
        samples,
        non_finite: 0,
    }
}

/// The centre samples of `rectangles` (a block's, for its band: see
/// [`antialias::BandCentres`]), traced into `buffer` before the band's blocks are, for them
/// to share, and the tracer that traced them (for the block to go on with: the pyramids it
/// keeps for shadow rays are its own pixels').
pub(super) fn block_centres<'a>(
    scene: &'a Scene,
    options: &RenderOptions,
    camera_media: Option<MediumStack>,
    rectangles: &[antialias::Rect],
    buffer: Vec<(super::Px, Rgb)>,
) -> (antialias::Centres, Tracer<'a>) {
    let mut tracer = Tracer::new(scene);
    // (The render's settings only: `rectangles` say which pixels are traced.)
    let block = Block {
        scene,
        options,
        camera_media: &camera_media,
        xs: 0..0,
        ys: 0..0,
        centres: None,
    };
    let centres = antialias::centres(&block, &mut tracer, rectangles, buffer);
    (centres, tracer)
}

/// Radiosity's ground truth for the pixels of a block: each pixel's centre ray traced
/// `paths` times, each time with its own stream of random directions, and averaged.
fn reference_pixels<'a>(
    block: &Block,
    tracer: &mut Tracer<'a>,
    shared: &'a Shared,
    paths: u32,
) -> (Vec<super::Px>, u64) {
    let (w, h) = (block.options.width, block.options.height);
    let mut pixels = Vec::with_capacity(block.xs.len() * block.ys.len());
    // (One gathering for the block, its stream started again for each path; it counts the
    // block's rays.)
    tracer.gathering = Some(Gathering::reference(shared, 0));
    for y in block.ys.clone() {
        for x in block.xs.clone() {
            let mut sum = glam::DVec4::ZERO;
            for path in 0..paths.max(1) {
                let seed = (u64::from(y) * u64::from(w) + u64::from(x)) << 24 | u64::from(path);
                if let Some(g) = tracer.gathering.as_mut() {
                    g.restart(seed);
                }
                let ray = camera::camera_ray(block.scene, w, h, f64::from(x), f64::from(y));
                let c = camera::trace_primary(tracer, block.camera_media, ray);
                sum += c.extend(tracer.see_through);
            }
            pixels.push(sum / f64::from(paths.max(1)));
        }
    }
    let samples = pixels.len() as u64 * u64::from(paths.max(1));
    (pixels, samples)
}

/// The AOV values of the pixels of a block, row by row (not counted as camera rays: they
/// are the centre rays again).
pub(super) fn block_aovs(
    tracer: &mut Tracer,
    options: &RenderOptions,
    xs: std::ops::Range<u32>,
    ys: std::ops::Range<u32>,
) -> Vec<f32> {
    if options.aovs.is_empty() {
        return Vec::new();
    }
    let mut out = Vec::with_capacity(xs.len() * ys.len() * aov_values(&options.aovs));
    for y in ys {
        for x in xs.clone() {
            let ray = camera::camera_ray(
                tracer.scene,
                options.width,
                options.height,
                x as f64,
                y as f64,
            );
            let (depth, n, albedo, object) = match ray {
                Some(ray) => tracer.first_hit(&ray),
                None => (f64::INFINITY, glam::DVec3::ZERO, Rgb::ZERO, 0),
            };
            for aov in &options.aovs {
                match aov {
                    Aov::Depth => out.push(depth as f32),
                    Aov::Normal => out.extend([n.x, n.y, n.z].map(|v| v as f32)),
                    Aov::Albedo => out.extend([albedo.x, albedo.y, albedo.z].map(|v| v as f32)),
                    Aov::Object => out.push(object as f32),
                }
            }
        }
    }
    out
}

/// One rendered block.
pub(super) struct BlockResult {
    pub(super) x0: u32,
    pub(super) y0: u32,
    pub(super) width: u32,
    /// Each pixel's linear colour and how much of it is the background seen through.
    pub(super) pixels: Vec<super::Px>,
    /// The AOV values of each pixel, in order.
    pub(super) aov: Vec<f32>,
    pub(super) counts: RayCounts,
    pub(super) tests: counters::Tests,
    pub(super) samples: u64,
    /// Pixels whose colour came out not finite (written black by [`BlockResult::put`]).
    pub(super) non_finite: u64,
    /// Radiosity samples taken (by depth), their rays, and queries answered from the cache.
    pub(super) radiosity: (super::SamplesByDepth, u64, u64),
}

impl BlockResult {
    pub(super) fn height(&self) -> u32 {
        self.pixels.len() as u32 / self.width.max(1)
    }

    /// Writes the block's output values into its place in the band: each pixel's red, green
    /// and blue as written (black where the render went wrong, counted in `non_finite`),
    /// then its alpha if `alpha`, then its AOV values.
    pub(super) fn put(&mut self, tile: &mut Tile, gamma: Gamma, alpha: bool) {
        let extra = if self.pixels.is_empty() {
            0
        } else {
            self.aov.len() / self.pixels.len()
        };
        let stride = 3 + usize::from(alpha) + extra;
        let (dx, dy) = (tile.x0 - self.x0, tile.y0 - self.y0);
        let mut wrong = 0;
        for (j, row) in tile.rows.iter_mut().enumerate() {
            let first = (dy as usize + j) * self.width as usize + dx as usize;
            for (i, out) in row.chunks_exact_mut(stride).enumerate() {
                let k = first + i;
                let p = self.pixels[k];
                let v = super::output_value(p.truncate(), gamma);
                if v.iter().all(|c| c.is_finite()) {
                    out[..3].copy_from_slice(&v);
                } else {
                    out[..3].fill(0.0);
                    wrong += 1;
                }
                if alpha {
                    out[3] = (1.0 - p.w).clamp(0.0, 1.0) as f32;
                }
                if extra > 0 {
                    out[stride - extra..].copy_from_slice(&self.aov[k * extra..(k + 1) * extra]);
                }
            }
        }
        self.non_finite += wrong;
    }
}

/// A block's place in a band: for each of the block's rows inside the band, the values of
/// its pixels inside the region; `(x0, y0)` is the image pixel of the first value.
pub(super) struct Tile<'b> {
    pub(super) x0: u32,
    pub(super) y0: u32,
    pub(super) rows: Vec<&'b mut [f32]>,
}
