//! Rendering: camera rays, anti-aliasing, and the parallel loop over image blocks.
//!
//! Uses `scene`, `geometry` and `film` only. The image is cut into 32×32 blocks (POV-Ray's
//! default block size, which its adaptive anti-aliasing depends on); rayon renders blocks in
//! parallel, and every pixel depends only on the scene and its own block, so the output is
//! the same for any number of threads.

mod antialias;
mod block;
mod camera;
mod pretrace;
mod sampler;
mod transport;

pub use antialias::Antialias;
pub use pretrace::PretraceStats;

/// Radiosity samples taken, by the depth of the bounce they serve (POV-Ray's recursion depth:
/// 0 for a surface the camera sees; the last entry counts depth 4 and deeper), as POV-Ray
/// counts them in its statistics.
pub type SamplesByDepth = [u64; 5];

/// Adds the counts of `more` to `sum`, depth by depth.
fn add_samples(sum: &mut SamplesByDepth, more: &SamplesByDepth) {
    sum.iter_mut().zip(more).for_each(|(s, m)| *s += m);
}
pub use transport::RayCounts;
/// The shadow test, for the stability suite's counts of light leaking through surfaces.
#[cfg(feature = "internals")]
pub use transport::transmittance;

use crate::cancel::Cancel;
use crate::film::{Film, Region, Rows};
use crate::geometry::counters;
use crate::scene::{Gamma, Rgb, Scene};
use block::Tile;

/// A sample: its colour (x, y, z) and how much of it is the transparent background seen
/// straight through (w: one minus its alpha).
type Px = glam::DVec4;
use rayon::prelude::*;
use transport::MediumStack;

/// POV-Ray's render block size (`+BS`), in pixels.
const BLOCK_SIZE: u32 = 32;

/// How to render.
#[derive(Clone, Debug)]
pub struct RenderOptions {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Anti-aliasing.
    pub antialias: Antialias,
    /// Worker threads; `None` uses every core.
    pub threads: Option<usize>,
    /// The rectangle of the image to render (`None`: all of it). Its pixels are those of the
    /// whole render: every block is rendered whole, as in the whole image.
    pub region: Option<Region>,
    /// Counters of the work done, for a progress display (read while the render runs).
    pub progress: Option<std::sync::Arc<Progress>>,
    /// Rows carry an alpha channel after the colour (POV-Ray's +UA): one minus how much of
    /// the pixel is the transparent background seen straight through; the colour is
    /// premultiplied by it (a transparent background adds nothing).
    pub alpha: bool,
    /// Layers after the colour (and alpha) of what each pixel's centre ray first meets.
    pub aovs: Vec<Aov>,
    /// With method 3 ([`Antialias::Sampled`]): area lights take their points from each
    /// pixel's sequence, anywhere on the light (converging on the whole light as a pixel's
    /// samples grow), instead of POV-Ray's grid. Ignored by the other methods.
    pub sampled_lights: bool,
    /// With method 3: focal blur looks through lens points drawn from each pixel's sequence
    /// (the pixel's sampling decides how many) instead of POV-Ray's adaptive batches. Ignored
    /// by the other methods.
    pub sampled_blur: bool,
    /// Stops the render when cancelled (a clone kept by the caller, e.g. for Ctrl-C).
    pub cancel: Cancel,
    /// Radiosity's ground truth instead of its cache: each pixel's centre ray traced this
    /// many times, every radiosity query answered afresh by one ray in a random direction
    /// (the nested mean POV-Ray's samples estimate, converging as the count grows). Ignored
    /// for a scene without radiosity; anti-aliasing is not done.
    pub radiosity_reference: Option<u32>,
    /// Radiosity in POV-Ray's order with one thread (`+WT1`) instead of the reproducible
    /// schedule: every pass of the pretrace, then the final render, block after block on one
    /// thread, each sample seeing all taken before it and drawing the next directions of the
    /// pool. Slower (one thread); for comparing with `povray +WT1`.
    pub radiosity_povray_order: bool,
    /// A picture of the render as it goes, each block copied in as it finishes (a live view,
    /// `trace watch`): the pixels are the output's, the order of blocks the threads'.
    pub preview: Option<std::sync::Arc<Preview>>,
}

/// The picture of a render in progress: the region's output values, each block written in
/// when it is finished over whatever the picture held before (a caller may fill it with a
/// coarser pass first), and a count of the blocks written.
#[derive(Debug)]
pub struct Preview {
    film: std::sync::Mutex<Film>,
    blocks: std::sync::atomic::AtomicU64,
}

impl Preview {
    /// A black picture of `width` × `height` (the region's size).
    pub fn new(width: u32, height: u32) -> Preview {
        Preview {
            film: std::sync::Mutex::new(Film::new(width, height)),
            blocks: Default::default(),
        }
    }

    /// Replaces the whole picture (of the same size).
    pub fn fill(&self, film: Film) {
        let mut mine = self.film.lock().unwrap_or_else(|e| e.into_inner());
        if (film.width, film.height) == (mine.width, mine.height) {
            *mine = film;
        }
    }

    /// A copy of the picture now.
    pub fn picture(&self) -> Film {
        self.film.lock().unwrap_or_else(|e| e.into_inner()).clone()
    }

    /// Blocks written so far.
    pub fn blocks(&self) -> u64 {
        self.blocks.load(std::sync::atomic::Ordering::Relaxed)
    }

    /// Writes a finished block's output values (a tile of a band of `region` whose pixels
    /// hold `stride` values, the colour first).
    fn write(&self, tile: &block::Tile, region: Region, stride: usize) {
        let mut film = self.film.lock().unwrap_or_else(|e| e.into_inner());
        for (j, row) in tile.rows.iter().enumerate() {
            for (i, v) in row.chunks_exact(stride).enumerate() {
                let (x, y) = (tile.x0 + i as u32, tile.y0 + j as u32);
                film.set(x - region.x0, y - region.y0, [v[0], v[1], v[2]]);
            }
        }
        drop(film);
        self.blocks
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    }
}

/// An arbitrary output value layer: what the camera ray through a pixel's centre first meets,
/// for denoisers and compositing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Aov {
    /// Distance along the ray (`Z`; infinite where it meets nothing).
    Depth,
    /// World-space shading normal facing the camera (`Ns.X`, `Ns.Y`, `Ns.Z`, as pbrt names
    /// it).
    Normal,
    /// The surface's pigment colour, linear (`Albedo.R`, `Albedo.G`, `Albedo.B`).
    Albedo,
    /// The object's number in scene order from 1, 0 for none (`ObjectID`).
    Object,
}

impl Aov {
    /// The EXR channels of this layer.
    pub fn channels(self) -> &'static [&'static str] {
        match self {
            Aov::Depth => &["Z"],
            Aov::Normal => &["Ns.X", "Ns.Y", "Ns.Z"],
            Aov::Albedo => &["Albedo.R", "Albedo.G", "Albedo.B"],
            Aov::Object => &["ObjectID"],
        }
    }

    /// The layer a name (`depth`, `normal`, `albedo`, `object`) names.
    pub fn named(name: &str) -> Option<Aov> {
        match name {
            "depth" => Some(Aov::Depth),
            "normal" => Some(Aov::Normal),
            "albedo" => Some(Aov::Albedo),
            "object" => Some(Aov::Object),
            _ => None,
        }
    }
}

impl Default for RenderOptions {
    /// 800 × 600, POV-Ray's anti-aliasing defaults (+A0.3 +R3), every core, the whole image.
    fn default() -> RenderOptions {
        RenderOptions {
            width: 800,
            height: 600,
            antialias: Antialias::Adaptive {
                threshold: 0.3,
                depth: 3,
            },
            threads: None,
            region: None,
            progress: None,
            alpha: false,
            aovs: Vec::new(),
            sampled_lights: false,
            sampled_blur: false,
            cancel: Cancel::new(),
            radiosity_reference: None,
            radiosity_povray_order: false,
            preview: None,
        }
    }
}

impl RenderOptions {
    /// The rectangle rendered.
    pub fn region(&self) -> Region {
        self.region
            .unwrap_or_else(|| Region::full(self.width, self.height))
    }
}

/// Work done so far by a render: pixels finished (of the region) and rays traced.
#[derive(Debug, Default)]
pub struct Progress {
    /// Pixels of the region finished.
    pub pixels: std::sync::atomic::AtomicU64,
    /// Rays traced (camera, shadow, reflected and refracted).
    pub rays: std::sync::atomic::AtomicU64,
}

/// A rendered image with its statistics.
#[derive(Debug)]
pub struct Rendered {
    /// Linear output values.
    pub film: Film,
    /// What it took.
    pub stats: RenderStats,
}

/// What a render took: rays, samples, intersection tests, time.
#[derive(Debug, Default)]
pub struct RenderStats {
    /// Rays traced, by kind.
    pub counts: RayCounts,
    /// Camera samples taken (centre samples plus supersamples).
    pub samples: u64,
    /// Ray–shape intersection tests, by kind of shape.
    pub tests: counters::Tests,
    /// Time spent building the render-ready scene (acceleration structures included).
    pub build_time: std::time::Duration,
    /// Time spent tracing (the bands' rendering, without the writing between them).
    pub trace_time: std::time::Duration,
    /// Pixels whose value overflowed to NaN or infinity (only from extreme inputs, such as a
    /// filter of 1e300, where POV-Ray's pixels are NaN too): written black, and reported.
    pub non_finite: u64,
    /// Radiosity's pretrace (zero without radiosity).
    pub pretrace: PretraceStats,
    /// Radiosity samples the final render took, by depth.
    pub radiosity_samples: SamplesByDepth,
    /// The rays they shot.
    pub radiosity_rays: u64,
    /// Radiosity queries the final render answered from the cache.
    pub radiosity_reused: u64,
    /// Rows of the region finished when the render was stopped ([`RenderOptions::cancel`]);
    /// `None` if it ran to the end. The rows after them are written black.
    pub stopped: Option<u32>,
}

/// `threads` worker threads (`None`: one per core).
pub fn thread_pool(
    threads: Option<usize>,
) -> Result<rayon::ThreadPool, rayon::ThreadPoolBuildError> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
}

/// Pixels rendered at a time at most, unless one row of blocks holds more: with the
/// writer's buffers, the memory a render holds whatever the image size (12 bytes a pixel,
/// the band's output values, which each block writes as it finishes).
const BAND_PIXELS: usize = 1 << 19;

/// Pixels a band holds at most when its blocks share method 3's centre samples (see
/// `antialias::BandCentres`), which are kept, 56 bytes a pixel, until its blocks are done:
/// more would touch more new memory than the rays saved are worth (measured: 14 MB of them
/// cost a 640×480 render 7 %), and wider images, whose one row of blocks would hold more,
/// do not share (nor, to keep the memory budget of such images, do method 1's).
const SHARED_BAND_PIXELS: usize = 1 << 17;

/// Rows of blocks a band holds at most when its blocks share method 3's centre samples: the
/// rows just above and below a band are traced twice (1.6 % more centre samples at four).
const SHARED_BAND_BLOCK_ROWS: u32 = 4;

/// Rows of blocks in a band of `width` pixels whose blocks share method 3's centre samples,
/// or `None` if a band that wide does not share (with either method).
fn shared_band_block_rows(width: u32) -> Option<u32> {
    let row_pixels = width as usize * BLOCK_SIZE as usize;
    (row_pixels <= SHARED_BAND_PIXELS)
        .then(|| ((SHARED_BAND_PIXELS / row_pixels.max(1)) as u32).min(SHARED_BAND_BLOCK_ROWS))
}

/// Rows of blocks rendered together: as many as fit in `band_pixels`, at least one.
fn band_block_rows(width: u32, band_pixels: usize) -> u32 {
    let row_pixels = width as usize * BLOCK_SIZE as usize;
    (band_pixels / row_pixels.max(1)).clamp(1, u32::MAX as usize) as u32
}

/// The memory a render of `width` × `height` pixels holds at its peak, whatever the scene:
/// one band of rows being traced and converted, and the writer's buffers (up to 64 rows of
/// output values: EXR's blocks of 16 scanlines queued for compression), and the centre
/// samples of a band whose blocks share them (method 3's, or method 1's edges of blocks).
pub fn bytes_needed(width: u32, height: u32) -> usize {
    let band_rows = (band_block_rows(width, BAND_PIXELS) * BLOCK_SIZE).min(height) as usize;
    let per_pixel = std::mem::size_of::<[f32; 3]>();
    let band = (width as usize * band_rows).saturating_mul(per_pixel);
    let writer =
        (width as usize * 64.min(height as usize)).saturating_mul(std::mem::size_of::<[f32; 3]>());
    // (Method 3's centre samples of a band that shares them, with the rows and columns
    // just outside it.)
    let centres = shared_band_block_rows(width).map_or(0, |rows| {
        let sample = std::mem::size_of::<(Px, Rgb)>();
        let method_3 = (width as usize + 2) * ((rows * BLOCK_SIZE).min(height) as usize + 2);
        // (Method 1's: each block's bottom row and right column, and the row above and the
        // column left of the band.)
        let blocks = width.div_ceil(BLOCK_SIZE) as usize * band_rows.div_ceil(BLOCK_SIZE as usize);
        let method_1 = blocks * 2 * BLOCK_SIZE as usize + width as usize + band_rows;
        method_3.max(method_1) * sample
    });
    band.saturating_add(writer).saturating_add(centres)
}

/// The image in bands of whole rows of blocks, top first, each rendered in parallel when it
/// is asked for: a writer that takes the bands as they come holds one band, not the image.
/// The pixels do not depend on the band size (each block depends only on itself).
pub struct Bands<'a> {
    scene: &'a Scene,
    options: &'a RenderOptions,
    pool: &'a rayon::ThreadPool,
    camera_media: Option<MediumStack>,
    region: Region,
    /// The next row of blocks to render.
    next_block_row: u32,
    /// Rows of blocks (past the last one the region touches) and columns of blocks the
    /// region touches.
    block_rows: u32,
    blocks_x: std::ops::Range<u32>,
    /// Rows of blocks a band holds.
    band_block_rows: u32,
    /// Radiosity's cache after the pretrace, if the scene has radiosity.
    radiosity: Option<transport::radiosity::Shared>,
    /// In POV-Ray's order: the samples the final render took so far and the next directions,
    /// carried from block to block.
    carry: Option<block::Carry>,
    /// Statistics of the bands rendered so far.
    pub stats: RenderStats,
    /// The centre-sample buffers of the band before, for this band's blocks.
    spare_centres: Vec<Vec<(Px, Rgb)>>,
    /// Whether bands may share their centre samples (tests turn it off).
    share_centres: bool,
}

impl<'a> Bands<'a> {
    /// The bands of `scene` rendered with `options`, on the threads of `pool`.
    pub fn new(scene: &'a Scene, options: &'a RenderOptions, pool: &'a rayon::ThreadPool) -> Self {
        // The rays of a camera with one eye point all start inside the same objects: found once.
        let camera_media =
            camera::one_eye_point(scene.camera()).map(|eye| MediumStack::at(scene, eye));
        let region = options.region();
        let mut stats = RenderStats::default();
        // Radiosity's pretrace, before the first band (its cache is shared by all blocks).
        let start = std::time::Instant::now();
        let radiosity = scene.radiosity().and_then(|settings| {
            if options.radiosity_reference.is_some() {
                return Some(transport::radiosity::Shared::new(
                    settings,
                    scene.camera().location,
                ));
            }
            let (shared, pretrace) = pretrace::pretrace(scene, options, pool, camera_media)?;
            stats.pretrace = pretrace;
            Some(shared)
        });
        if scene.radiosity().is_some() && radiosity.is_none() {
            stats.stopped = Some(0);
        }
        stats.trace_time += start.elapsed();
        let mut bands = Bands {
            scene,
            options,
            pool,
            camera_media,
            carry: (radiosity.is_some() && options.radiosity_povray_order)
                .then(block::Carry::default),
            radiosity,
            region,
            next_block_row: region.y0 / BLOCK_SIZE,
            block_rows: region.y1.div_ceil(BLOCK_SIZE),
            blocks_x: region.x0 / BLOCK_SIZE..region.x1.div_ceil(BLOCK_SIZE),
            band_block_rows: band_block_rows(region.width(), BAND_PIXELS),
            stats,
            spare_centres: Vec::new(),
            share_centres: true,
        };
        if bands.shares_centres() {
            // (Method 3's band keeps all its centre samples until its blocks are done: smaller
            // bands keep fewer, and pass their memory on to the next band. Method 1's keeps
            // its blocks' edges only, whatever the band's height.)
            let method_3 = matches!(options.antialias, Antialias::Sampled { .. });
            match shared_band_block_rows(bands.blocks_x.len() as u32 * BLOCK_SIZE) {
                Some(rows) if method_3 => bands.band_block_rows = bands.band_block_rows.min(rows),
                Some(_) => {}
                None => bands.share_centres = false,
            }
        }
        bands
    }

    /// Whether bands trace their centre samples first (methods 1 and 3), for their blocks to
    /// share (see `antialias::BandCentres`): not with radiosity, where each block gathers
    /// its own samples in the order its rays are traced.
    fn shares_centres(&self) -> bool {
        self.share_centres
            && matches!(
                self.options.antialias,
                Antialias::Adaptive { .. } | Antialias::Sampled { .. }
            )
            && self.radiosity.is_none()
            && self.options.radiosity_reference.is_none()
    }

    /// The same bands, each block tracing its own centre samples and border (for tests).
    #[cfg(test)]
    fn without_shared_centres(mut self) -> Self {
        self.share_centres = false;
        self
    }

    /// The same bands, each at most `rows` rows of blocks high (tests split small images).
    #[cfg(test)]
    fn with_band_block_rows(mut self, rows: u32) -> Self {
        self.band_block_rows = rows.max(1);
        self
    }

    /// Renders the next band: its rows' output values (of the region), or `None` after the
    /// last row or once the render is stopped ([`RenderOptions::cancel`]: the band being
    /// rendered is dropped, and `stats.stopped` says how many rows were finished).
    pub fn next_band(&mut self, reuse: Vec<f32>) -> Option<Rows<'static>> {
        if self.next_block_row >= self.block_rows || self.stats.stopped.is_some() {
            return None;
        }
        let start = std::time::Instant::now();
        let region = self.region;
        let first = self.next_block_row;
        let last = (first + self.band_block_rows).min(self.block_rows);
        self.next_block_row = last;
        let y0 = (first * BLOCK_SIZE).max(region.y0);
        let mut y1 = (last * BLOCK_SIZE).min(region.y1);
        let (scene, options, media, blocks_x) = (
            self.scene,
            self.options,
            self.camera_media,
            self.blocks_x.clone(),
        );
        let w = region.width() as usize;
        let stride = 3 + usize::from(options.alpha) + aov_values(&options.aovs);
        let row_len = stride * w;
        // The band's values, written by each block into its own tiles. (A buffer handed back
        // is reused: its pages are already the process's. A new one is left to the blocks to
        // touch, in parallel.)
        let len = row_len * (y1 - y0) as usize;
        let mut values = if reuse.capacity() >= len {
            let mut v = reuse;
            v.resize(len, 0.0);
            v
        } else {
            vec![0.0_f32; len]
        };
        let columns = blocks_x.len() as u32;
        let mut tiles: Vec<Tile> = (first..last)
            .flat_map(|by| {
                blocks_x.clone().map(move |bx| Tile {
                    x0: (bx * BLOCK_SIZE).max(region.x0),
                    y0: (by * BLOCK_SIZE).max(y0),
                    rows: Vec::new(),
                })
            })
            .collect();
        for (j, mut row) in values.chunks_exact_mut(row_len.max(1)).enumerate() {
            let by = (y0 + j as u32) / BLOCK_SIZE - first;
            for tile in &mut tiles[(by * columns) as usize..][..columns as usize] {
                let x1 = (tile.x0 / BLOCK_SIZE + 1) * BLOCK_SIZE;
                let n = (x1.min(region.x1) - tile.x0) as usize * stride;
                let (mine, rest) = row.split_at_mut(n);
                tile.rows.push(mine);
                row = rest;
            }
        }
        let radiosity = self.radiosity.as_ref();
        let progress = options.progress.as_deref();
        let gamma = scene.gamma();
        // Methods 1 and 3: the band's centre samples first, each traced once, for its blocks'
        // comparisons to share (see `antialias::BandCentres`); each block then goes on with
        // the tracer that traced its own.
        let mut tracers: Vec<Option<transport::Tracer>> = Vec::new();
        let centres = self.shares_centres().then(|| {
            let rows = first..last;
            let count = ((last - first) * columns) as usize;
            let mut buffers = std::mem::take(&mut self.spare_centres);
            buffers.resize_with(count, Vec::new);
            let blocks: Vec<Option<(antialias::Centres, transport::Tracer)>> =
                self.pool.install(|| {
                    (buffers.into_par_iter().enumerate())
                        .with_max_len(1)
                        .map(|(i, buffer)| {
                            if options.cancel.is_cancelled() {
                                return None;
                            }
                            let i = i as u32;
                            let (bx, by) = (blocks_x.start + i % columns, first + i / columns);
                            let (rectangles, n) = antialias::BandCentres::rectangles(
                                (bx, by),
                                (blocks_x.clone(), rows.clone()),
                                (options.width, options.height),
                                &options.antialias,
                            );
                            Some(block::block_centres(
                                scene,
                                options,
                                media,
                                &rectangles[..n],
                                buffer,
                            ))
                        })
                        .collect()
                });
            // (A band stopped part-way has no shared samples: its blocks stop too.)
            let blocks: Option<Vec<_>> = blocks.into_iter().collect();
            blocks.map(|blocks| {
                let (blocks, kept): (Vec<_>, Vec<_>) = blocks.into_iter().unzip();
                tracers = kept.into_iter().map(Some).collect();
                antialias::BandCentres::new(blocks, columns, (blocks_x.start, first))
            })
        });
        tracers.resize_with(tiles.len(), || None);
        let one = |i: u32,
                   mut tile: Tile,
                   carry: Option<&mut block::Carry>,
                   tracer: Option<transport::Tracer<'a>>| {
            if options.cancel.is_cancelled() || centres.as_ref().is_some_and(Option::is_none) {
                return None;
            }
            let (bx, by) = (blocks_x.start + i % columns, first + i / columns);
            let band = centres.as_ref().and_then(Option::as_ref);
            let mut block = block::render_block(
                scene,
                options,
                (media, radiosity, carry),
                (band.map(|b| (b, b.block(i))), tracer),
                bx * BLOCK_SIZE,
                by * BLOCK_SIZE,
            );
            block.put(&mut tile, gamma, options.alpha);
            if let Some(p) = progress {
                use std::sync::atomic::Ordering::Relaxed;
                let inside =
                    |a: u32, n: u32, lo: u32, hi: u32| (a + n).min(hi).saturating_sub(a.max(lo));
                let pixels = inside(block.x0, block.width, region.x0, region.x1)
                    * inside(block.y0, block.height(), region.y0, region.y1);
                p.pixels.fetch_add(u64::from(pixels), Relaxed);
                p.rays.fetch_add(block.counts.total(), Relaxed);
            }
            if let Some(preview) = &options.preview {
                preview.write(&tile, region, stride);
            }
            // (The block's pixels are freed here, on its thread, for its next block.)
            block.pixels = Vec::new();
            block.aov = Vec::new();
            Some(block)
        };
        let blocks: Vec<Option<block::BlockResult>> = match self.carry.as_mut() {
            // (Radiosity in POV-Ray's order: the blocks one after another, on this thread.)
            Some(carry) => (tiles.into_iter().enumerate())
                .map(|(i, tile)| one(i as u32, tile, Some(&mut *carry), None))
                .collect(),
            // (One block per task: costly blocks often sit together, around one object, and
            // rayon's default chunks of many blocks left a core idle; measured 133 % of 2 cores
            // on examples/parametric.rt before, see the commit.)
            None => self.pool.install(|| {
                (tiles.into_par_iter().zip(tracers).enumerate())
                    .with_max_len(1)
                    .map(|(i, (tile, tracer))| one(i as u32, tile, None, tracer))
                    .collect()
            }),
        };
        if blocks.iter().any(Option::is_none) {
            // Stopped: the band keeps its leading rows of blocks that were all finished.
            let whole_rows = blocks
                .chunks(columns as usize)
                .take_while(|row| row.iter().all(Option::is_some))
                .count() as u32;
            y1 = ((first + whole_rows) * BLOCK_SIZE).clamp(y0, region.y1);
            self.stats.stopped = Some(y1 - region.y0);
            if y1 == y0 {
                self.stats.trace_time += start.elapsed();
                return None;
            }
            values.truncate(row_len * (y1 - y0) as usize);
        }
        // (The band's sample buffers go to the next band's blocks: memory already touched.)
        if let Some(Some(band)) = centres {
            self.spare_centres = band.into_buffers().collect();
        }
        for b in blocks.iter().flatten().filter(|b| b.y0 < y1) {
            self.stats.non_finite += b.non_finite;
            self.stats.counts.add(&b.counts);
            self.stats.tests.add(&b.tests);
            self.stats.samples += b.samples;
            add_samples(&mut self.stats.radiosity_samples, &b.radiosity.0);
            self.stats.radiosity_rays += b.radiosity.1;
            self.stats.radiosity_reused += b.radiosity.2;
        }
        self.stats.trace_time += start.elapsed();
        Some(Rows {
            y0: y0 - region.y0,
            values: values.into(),
        })
    }
}

/// Renders `scene` into a film of linear values, on the threads of `pool`.
pub fn render(scene: &Scene, options: &RenderOptions, pool: &rayon::ThreadPool) -> Rendered {
    let region = options.region();
    let mut film = Film::new(region.width(), region.height());
    let mut bands = Bands::new(scene, options, pool);
    let mut spare = Vec::new();
    while let Some(band) = bands.next_band(spare) {
        let start = band.y0 as usize * region.width() as usize;
        let stride = 3 + usize::from(options.alpha) + aov_values(&options.aovs);
        let pixels = band.values.chunks_exact(stride).map(|v| [v[0], v[1], v[2]]);
        for (dst, v) in film.pixels[start..].iter_mut().zip(pixels) {
            *dst = v;
        }
        spare = band.values.into_owned();
    }
    Rendered {
        film,
        stats: bands.stats,
    }
}

/// A working-space colour as the linear value written to the film (POV-Ray §2).
fn output_value(c: Rgb, gamma: Gamma) -> [f32; 3] {
    let decode = |v: f64| -> f64 {
        match gamma {
            Gamma::Working(1.0) => v,
            Gamma::Working(g) => v.signum() * v.abs().powf(g),
            Gamma::Off => crate::film::srgb_to_linear(v),
        }
    };
    // A value past the f32 range (a colour of 1e39) is written as the largest float, not as
    // infinity.
    let out = |v: f64| decode(v).clamp(-f64::from(f32::MAX), f64::from(f32::MAX)) as f32;
    [out(c.x), out(c.y), out(c.z)]
}

/// Values a pixel's AOV layers hold.
fn aov_values(aovs: &[Aov]) -> usize {
    aovs.iter().map(|a| a.channels().len()).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scene with reflections, refraction and shadows, so that blocks differ in work.
    const SCENE: &str = "camera { location <0, 2, -6> look_at <0, 0.5, 0> }\n\
        light_source { <4, 8, -5>, rgb 1 }\n\
        plane { y, 0 pigment { checker rgb 1, rgb 0.2 } finish { reflection 0.3 } }\n\
        sphere { <-1, 1, 0>, 1 pigment { rgbf <0.9, 0.9, 1, 0.8> } interior { ior 1.5 } }\n\
        sphere { <1.2, 0.7, 1>, 0.7 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.8 } }\n";

    fn built(width: u32, height: u32) -> Scene {
        let options = crate::LoadOptions {
            width,
            height,
            ..crate::LoadOptions::default()
        };
        let loaded = crate::load_str(std::path::Path::new("bands.rt"), SCENE.into(), &options)
            .expect("the scene loads");
        Scene::build(&loaded.scene)
    }

    #[test]
    fn a_cancelled_token_stops_its_render_and_no_other() {
        let scene = built(40, 30);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let stopped = RenderOptions {
            width: 40,
            height: 30,
            antialias: Antialias::Off,
            ..RenderOptions::default()
        };
        stopped.cancel.cancel();
        let r = render(&scene, &stopped, &pool);
        assert_eq!(r.stats.stopped, Some(0));
        assert_eq!(r.stats.samples, 0);
        // A render of the same process with its own token runs to the end.
        let whole = RenderOptions {
            cancel: Cancel::new(),
            ..stopped.clone()
        };
        let r = render(&scene, &whole, &pool);
        assert_eq!(r.stats.stopped, None);
        assert_eq!(r.stats.samples, 40 * 30);
    }

    /// The blocks write every value of their band themselves: a band handed a used buffer
    /// (here full of NaN) gives the values of one handed nothing, for a region that starts
    /// and ends inside blocks, with alpha and AOV layers after the colour.
    #[test]
    fn every_value_of_a_band_is_its_blocks_own() {
        let (w, h) = (75, 70);
        let scene = built(w, h);
        let pool = thread_pool(Some(2)).expect("a pool");
        let options = RenderOptions {
            width: w,
            height: h,
            antialias: Antialias::Off,
            region: Some(Region {
                x0: 5,
                y0: 17,
                x1: 71,
                y1: 66,
            }),
            alpha: true,
            aovs: vec![Aov::Depth, Aov::Normal],
            ..RenderOptions::default()
        };
        let bands = |used: bool| {
            let mut bands = Bands::new(&scene, &options, &pool).with_band_block_rows(1);
            let mut all = Vec::new();
            while let Some(band) = bands.next_band(if used {
                vec![f32::NAN; 1 << 16]
            } else {
                Vec::new()
            }) {
                all.extend_from_slice(&band.values);
            }
            all
        };
        let (fresh, used) = (bands(false), bands(true));
        assert_eq!(fresh.len(), (66 - 17) * (71 - 5) * (3 + 1 + 1 + 3));
        assert!(used.iter().all(|v| !v.is_nan()), "a value left unwritten");
        assert_eq!(
            fresh.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            used.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        );
    }

    /// Blocks of methods 1 and 3, sharing their band's centre samples, give the picture of
    /// blocks that each trace their own and their border, with fewer camera rays: for bands
    /// of one to three rows of blocks (so rows just outside bands are traced twice), a
    /// region that starts and ends inside blocks, alpha and AOV layers.
    #[test]
    fn shared_centre_samples_change_no_value() {
        let (w, h) = (75, 100);
        let scene = built(w, h);
        let pool = thread_pool(Some(2)).expect("a pool");
        for antialias in [
            Antialias::Adaptive {
                threshold: 0.1,
                depth: 2,
            },
            Antialias::Sampled {
                threshold: 0.1,
                depth: 2,
            },
        ] {
            let options = RenderOptions {
                width: w,
                height: h,
                antialias,
                region: Some(Region {
                    x0: 5,
                    y0: 17,
                    x1: 71,
                    y1: 96,
                }),
                alpha: true,
                aovs: vec![Aov::Depth],
                ..RenderOptions::default()
            };
            let run = |rows: u32, share: bool| {
                let mut bands = Bands::new(&scene, &options, &pool).with_band_block_rows(rows);
                if !share {
                    bands = bands.without_shared_centres();
                }
                let mut all = Vec::new();
                while let Some(band) = bands.next_band(Vec::new()) {
                    all.extend(band.values.iter().map(|v| v.to_bits()));
                }
                (all, bands.stats)
            };
            let (own, own_stats) = run(1, false);
            assert_eq!(run(3, false).0, own);
            for rows in [1, 2, 3] {
                let (shared, stats) = run(rows, true);
                assert!(
                    shared == own,
                    "{antialias:?}, bands of {rows} rows of blocks"
                );
                assert!(
                    stats.counts.camera < own_stats.counts.camera,
                    "{antialias:?}: {} camera rays, {} without sharing",
                    stats.counts.camera,
                    own_stats.counts.camera
                );
                // (Method 1 counts a block's own samples, not the border it compares with.)
                if matches!(antialias, Antialias::Adaptive { .. }) {
                    assert_eq!(stats.samples, own_stats.samples);
                }
            }
        }
    }

    #[test]
    fn the_preview_ends_as_the_film_whatever_it_held() {
        let (w, h) = (70, 45);
        let scene = built(w, h);
        let pool = thread_pool(Some(2)).expect("a pool");
        let preview = std::sync::Arc::new(Preview::new(w, h));
        // (A coarser picture put there first is overwritten block by block.)
        let mut grey = Film::new(w, h);
        grey.pixels.fill([0.5; 3]);
        preview.fill(grey);
        let options = RenderOptions {
            width: w,
            height: h,
            antialias: Antialias::Sampled {
                threshold: 0.1,
                depth: 3,
            },
            preview: Some(preview.clone()),
            ..RenderOptions::default()
        };
        let rendered = render(&scene, &options, &pool);
        assert_eq!(preview.picture(), rendered.film);
        assert_eq!(preview.blocks(), 3 * 2, "a count of 32x32 blocks");
    }

    #[test]
    fn bands_of_any_height_give_the_same_pixels_and_counts() {
        let (w, h) = (70, 100);
        let scene = built(w, h);
        for antialias in [
            Antialias::Off,
            Antialias::Adaptive {
                threshold: 0.1,
                depth: 3,
            },
            Antialias::Recursive {
                threshold: 0.1,
                depth: 3,
            },
            Antialias::Sampled {
                threshold: 0.1,
                depth: 3,
            },
        ] {
            let options = RenderOptions {
                width: w,
                height: h,
                antialias,
                threads: Some(2),
                ..RenderOptions::default()
            };
            let pool = thread_pool(options.threads).expect("a pool");
            let whole = render(&scene, &options, &pool);
            for rows in [1, 2, 3] {
                let mut bands = Bands::new(&scene, &options, &pool).with_band_block_rows(rows);
                let mut pixels = Vec::new();
                let mut count = 0;
                while let Some(band) = bands.next_band(Vec::new()) {
                    assert_eq!(
                        band.y0 as usize,
                        pixels.len() / w as usize,
                        "bands in order"
                    );
                    pixels.extend(band.values.chunks_exact(3).map(|v| [v[0], v[1], v[2]]));
                    count += 1;
                }
                assert_eq!(
                    count,
                    h.div_ceil(BLOCK_SIZE * rows),
                    "{rows} rows of blocks a band"
                );
                assert!(
                    pixels == whole.film.pixels,
                    "{antialias:?}, {rows} rows of blocks"
                );
                // (Bands that share their centre samples trace the rows just outside them
                // again (method 1's above, method 3's above and below): their rays depend
                // on the bands' height, and method 3's samples, which count them; the
                // pixels do not.)
                match antialias {
                    Antialias::Sampled { .. } => {}
                    Antialias::Adaptive { .. } => {
                        assert_eq!(bands.stats.samples, whole.stats.samples)
                    }
                    _ => {
                        assert_eq!(bands.stats.samples, whole.stats.samples);
                        assert_eq!(bands.stats.counts.shadow, whole.stats.counts.shadow);
                    }
                }
            }
        }
    }

    /// Method 3 (with an area light and focal blur, whose points it draws from each pixel's
    /// sequence) gives the same pixels for any thread count and any region, and spends more
    /// samples where the picture changes.
    #[test]
    fn method_3_is_the_same_for_any_threads_and_region() {
        let (w, h) = (90, 70);
        let lit = SCENE.replace(
            "light_source { <4, 8, -5>, rgb 1 }",
            "light_source { <4, 8, -5>, rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 4, 4 adaptive 1 }",
        );
        let blurred = lit.replace(
            "look_at <0, 0.5, 0> }",
            "look_at <0, 0.5, 0> focal_point <1.2, 0.7, 1> aperture 0.4 blur_samples 8 }",
        );
        // (Samples a pixel on average: more than one, fewer than the most; the blur's noise
        // sends nearly every pixel on.)
        for (text, per_pixel_range) in [(lit, 1.2..8.0), (blurred, 4.0..17.0)] {
            let options = crate::LoadOptions {
                width: w,
                height: h,
                ..crate::LoadOptions::default()
            };
            let loaded =
                crate::load_str(std::path::Path::new("m3.rt"), text, &options).expect("loads");
            let scene = Scene::build(&loaded.scene);
            let render_with = |threads: usize, region: Option<Region>| {
                let options = RenderOptions {
                    width: w,
                    height: h,
                    antialias: Antialias::Sampled {
                        threshold: 0.2,
                        depth: 3,
                    },
                    threads: Some(threads),
                    region,
                    sampled_lights: true,
                    sampled_blur: true,
                    ..RenderOptions::default()
                };
                let pool = thread_pool(options.threads).expect("a pool");
                render(&scene, &options, &pool)
            };
            let one = render_with(1, None);
            let two = render_with(2, None);
            assert!(one.film.pixels == two.film.pixels, "1 and 2 threads");
            assert_eq!(one.stats.samples, two.stats.samples);
            assert_eq!(one.stats.counts.shadow, two.stats.counts.shadow);
            let per_pixel = one.stats.samples as f64 / f64::from(w * h);
            assert!(
                per_pixel_range.contains(&per_pixel),
                "{per_pixel} samples a pixel"
            );
            for region in [
                Region {
                    x0: 0,
                    y0: 32,
                    x1: 90,
                    y1: 64,
                },
                Region {
                    x0: 17,
                    y0: 5,
                    x1: 61,
                    y1: 70,
                },
            ] {
                let part = render_with(2, Some(region));
                for y in region.y0..region.y1 {
                    for x in region.x0..region.x1 {
                        let whole = one.film.pixels[(y * w + x) as usize];
                        let here = part.film.pixels
                            [((y - region.y0) * region.width() + x - region.x0) as usize];
                        assert_eq!(whole, here, "pixel ({x}, {y}) of region {region:?}");
                    }
                }
            }
        }
    }

    /// A pixel of method 3 at threshold 0 converges on the pixel's true average: on a
    /// straight edge (white beyond the line n·p = 0.3, n at 30°, one unit a pixel), its mean
    /// error against the exact covered area falls with the sample budget and ends small.
    #[test]
    fn method_3_converges_on_an_edge() {
        let n = 24u32;
        let text = format!(
            "#version 3.7;\nglobal_settings {{ assumed_gamma 1.0 }}\n\
             camera {{ orthographic location <0, 0, -5> look_at <0, 0, 0> right x*{n} up y*{n} }}\n\
             background {{ rgb 0 }}\n\
             box {{ <0, -100, -1>, <100, 100, 1> rotate z*30 translate <0.3*cos(pi/6), 0.3*sin(pi/6), 0> \
                    pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} }}\n"
        );
        let options = crate::LoadOptions {
            width: n,
            height: n,
            ..crate::LoadOptions::default()
        };
        let loaded =
            crate::load_str(std::path::Path::new("edge.rt"), text, &options).expect("loads");
        let scene = Scene::build(&loaded.scene);
        // The covered fraction of pixel (i, j), by a 256 × 256 grid of points.
        let (c, s) = (
            std::f64::consts::FRAC_PI_6.cos(),
            std::f64::consts::FRAC_PI_6.sin(),
        );
        let exact = |i: u32, j: u32| {
            let (x0, y0) = (
                f64::from(i) - f64::from(n) / 2.0,
                f64::from(n) / 2.0 - f64::from(j),
            );
            let mut inside = 0;
            for a in 0..256 {
                for b in 0..256 {
                    let (x, y) = (
                        x0 + (f64::from(a) + 0.5) / 256.0,
                        y0 - (f64::from(b) + 0.5) / 256.0,
                    );
                    inside += usize::from(c * x + s * y > 0.3);
                }
            }
            inside as f64 / 65536.0
        };
        let error = |antialias| {
            let options = RenderOptions {
                width: n,
                height: n,
                antialias,
                threads: Some(1),
                ..RenderOptions::default()
            };
            let pool = thread_pool(options.threads).expect("a pool");
            let film = render(&scene, &options, &pool).film;
            // The mean error over the pixels the edge crosses.
            let (mut sum, mut count) = (0.0, 0);
            for j in 0..n {
                for i in 0..n {
                    let truth = exact(i, j);
                    if truth > 0.0 && truth < 1.0 {
                        sum += (f64::from(film.pixels[(j * n + i) as usize][0]) - truth).abs();
                        count += 1;
                    }
                }
            }
            sum / f64::from(count)
        };
        // (Measured: 0.020 at depth 3, 0.0096 at 5, 0.0043 at 7; method 1's grid, with a
        // like number of samples, 0.018 at depth 4 (17), 0.010 at 6 (37), 0.0049 at 8 (65): on
        // a straight edge a regular grid does as well, the nets win where a pattern is finer
        // than the pixels and the grid aliases, as on the chart's scenes.)
        let coarse = error(Antialias::Sampled {
            threshold: 0.0,
            depth: 3,
        });
        let fine = error(Antialias::Sampled {
            threshold: 0.0,
            depth: 7,
        });
        assert!(fine < 0.006, "method 3 at depth 7: mean error {fine}");
        assert!(
            fine < coarse / 3.0,
            "depth 7 {fine} against depth 3 {coarse}"
        );
    }

    #[test]
    fn a_band_holds_whole_rows_of_blocks_within_the_pixel_budget() {
        assert_eq!(band_block_rows(640, BAND_PIXELS), 25);
        assert_eq!(band_block_rows(7680, BAND_PIXELS), 2);
        assert_eq!(band_block_rows(32768, BAND_PIXELS), 1);
        // Bands that share method 3's centre samples are smaller, and wide ones do not share.
        assert_eq!(shared_band_block_rows(640), Some(4));
        assert_eq!(shared_band_block_rows(1280), Some(3));
        assert_eq!(shared_band_block_rows(4096), Some(1));
        assert_eq!(shared_band_block_rows(4097), None);
        // The memory asked for is the band's and the writer's (and, up to 4,096 pixels wide,
        // the shared centre samples of a band), not the image's: an 8K image
        // needs about 12 MB, a 32k × 32k one about 38 MB (it would hold 12 GB as a film).
        assert!(bytes_needed(7680, 4320) < 12 << 20);
        assert!(bytes_needed(32768, 32768) < 38 << 20);
    }
}
