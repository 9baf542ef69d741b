//! trace's own sampler (method 3): stratified samples from each pixel's scrambled Sobol
//! sequence where a pixel differs from a neighbour, until their estimated error is small.

use super::{Block, SAMPLED_TOLERANCE, aa_encoded, differ};
use crate::geometry::counters;
use crate::render::transport::{RayCounts, Tracer};
use crate::render::{BLOCK_SIZE, Px, camera, sampler};
use crate::scene::Rgb;
use std::ops::Range;

/// The centre samples (the value, and its comparison encoding) of a rectangle of pixels,
/// row by row, traced by one block for the band's blocks to share, and what tracing them
/// counted.
pub(in crate::render) struct Centres {
    x0: u32,
    y0: u32,
    width: u32,
    height: u32,
    values: Vec<(Px, Rgb)>,
    pub(in crate::render) counts: RayCounts,
    pub(in crate::render) tests: counters::Tests,
}

impl Centres {
    /// Whether pixel (x, y) lies in the rectangle.
    #[inline]
    fn holds(&self, x: u32, y: u32) -> bool {
        x.wrapping_sub(self.x0) < self.width && y.wrapping_sub(self.y0) < self.height
    }

    /// The sample of pixel (x, y), in the rectangle.
    #[inline]
    fn at(&self, x: u32, y: u32) -> (Px, Rgb) {
        self.values[((y - self.y0) * self.width + (x - self.x0)) as usize]
    }

    /// The samples traced.
    pub(in crate::render) fn samples(&self) -> u64 {
        self.values.len() as u64
    }

    /// The samples' buffer, emptied, for the next band's block.
    pub(in crate::render) fn into_buffer(self) -> Vec<(Px, Rgb)> {
        let mut values = self.values;
        values.clear();
        values
    }
}

/// A band's centre samples for method 3's comparisons (a pixel's eight neighbours): traced
/// once for the band, each by the block it belongs to, instead of again by every block whose
/// one-pixel border it lies on (13 % more centre rays for blocks of 32×32). Each block's
/// rectangle is its pixels and, where no block of the band lies beyond one of its sides,
/// the pixels along that side (the rows above and below the band, the columns beside it),
/// so each pixel a block's comparisons need lies in exactly one rectangle.
pub(in crate::render) struct BandCentres {
    /// Each block's, row by row of blocks.
    blocks: Vec<Centres>,
    /// Blocks a row of the band holds, and rows of blocks.
    columns: u32,
    rows: u32,
    /// The first block's column and row, in blocks.
    first: (u32, u32),
}

impl BandCentres {
    /// The band of blocks `blocks` (row by row, `columns` a row; the first at `first`, in
    /// blocks).
    pub(in crate::render) fn new(
        blocks: Vec<Centres>,
        columns: u32,
        first: (u32, u32),
    ) -> BandCentres {
        let rows = blocks.len() as u32 / columns.max(1);
        BandCentres {
            blocks,
            columns,
            rows,
            first,
        }
    }

    /// Block `i`'s (row by row).
    pub(in crate::render) fn block(&self, i: u32) -> &Centres {
        &self.blocks[i as usize]
    }

    /// The blocks' sample buffers, emptied, for the next band.
    pub(in crate::render) fn into_buffers(self) -> impl Iterator<Item = Vec<(Px, Rgb)>> {
        self.blocks.into_iter().map(Centres::into_buffer)
    }

    /// The rectangle block (`bx`, `by`) (in blocks) traces for the band `columns` (in blocks)
    /// × `rows` (in blocks) of a `width` × `height` image: its pixels, grown by one on the
    /// sides with no block of the band beyond them.
    pub(in crate::render) fn rectangle(
        (bx, by): (u32, u32),
        (columns, rows): (Range<u32>, Range<u32>),
        (width, height): (u32, u32),
    ) -> (Range<u32>, Range<u32>) {
        let (x0, y0) = (bx * BLOCK_SIZE, by * BLOCK_SIZE);
        let (x1, y1) = ((x0 + BLOCK_SIZE).min(width), (y0 + BLOCK_SIZE).min(height));
        let grow = |edge: bool| u32::from(edge);
        (
            x0 - grow(bx == columns.start && x0 > 0)
                ..x1 + grow(bx + 1 == columns.end && x1 < width),
            y0 - grow(by == rows.start && y0 > 0)..y1 + grow(by + 1 == rows.end && y1 < height),
        )
    }

    /// The centre sample of pixel (x, y), which lies in a block's rectangle.
    #[inline]
    fn at(&self, x: u32, y: u32) -> (Px, Rgb) {
        let (bx0, by0) = self.first;
        let bx = (x / BLOCK_SIZE).clamp(bx0, bx0 + self.columns - 1) - bx0;
        let by = (y / BLOCK_SIZE).clamp(by0, by0 + self.rows - 1) - by0;
        self.blocks[(by * self.columns + bx) as usize].at(x, y)
    }
}

/// The centre sample of pixel (x, y) and its comparison encoding.
fn centre_sample(block: &Block, tracer: &mut Tracer, x: u32, y: u32) -> (Px, Rgb) {
    let options = block.options;
    let seed = sampler::pixel_seed(x, y, 0);
    tracer.light_stream = options.sampled_lights.then_some((seed, 0));
    tracer.lens_stream = options.sampled_blur.then_some((seed, 0));
    let (w, h) = (options.width, options.height);
    let v = camera::sample(tracer, block.camera_media, w, h, x as f64, y as f64);
    (v, aa_encoded(v.truncate(), tracer.scene.gamma()))
}

/// The centre samples of the pixels of `block` (its rectangle: see [`BandCentres`]), traced
/// for the band's blocks to share, into `values` (an emptied buffer).
pub(in crate::render) fn centres(
    block: &Block,
    tracer: &mut Tracer,
    mut values: Vec<(Px, Rgb)>,
) -> Centres {
    counters::take(); // (the counts start from zero)
    let (xs, ys) = (block.xs.clone(), block.ys.clone());
    values.reserve(xs.len() * ys.len());
    for y in ys.clone() {
        for x in xs.clone() {
            values.push(centre_sample(block, tracer, x, y));
        }
    }
    tracer.light_stream = None;
    tracer.lens_stream = None;
    Centres {
        x0: xs.start,
        y0: ys.start,
        width: xs.len() as u32,
        height: ys.len() as u32,
        values,
        counts: std::mem::take(&mut tracer.counts),
        tests: counters::take(),
    }
}

/// The pixels of a block (row by row) with method 3 ([`super::Antialias::Sampled`]): centre
/// samples for the block and a one-pixel border (the band's, shared, when the band traced
/// them first: see [`BandCentres`]; else traced here, the border again by the neighbouring
/// block: the same rays), then stratified samples in the pixels that differ from a
/// neighbour. (A first sample at the first point of the pixel's sequence instead of its
/// centre was tried: it turns moiré into noise, but on smooth shading its error is the
/// gradient's across the pixel, and the chart's scenes came out worse: basic_spheres 0.0093
/// against 0.0042.)
pub(super) fn pixels(
    block: &Block,
    tracer: &mut Tracer,
    threshold: f64,
    depth: u32,
) -> (Vec<Px>, u64) {
    let (options, camera_media) = (block.options, block.camera_media);
    let (xs, ys) = (block.xs.clone(), block.ys.clone());
    let mut samples = 0u64;
    let (w, h) = (options.width, options.height);
    let gamma = tracer.scene.gamma();
    let (gx0, gy0) = (xs.start.saturating_sub(1), ys.start.saturating_sub(1));
    let (gx1, gy1) = ((xs.end + 1).min(w), (ys.end + 1).min(h));
    let gw = (gx1 - gx0) as usize;
    let at = |x: u32, y: u32| (y - gy0) as usize * gw + (x - gx0) as usize;
    let mut own = Vec::new();
    if block.centres.is_none() {
        own.reserve(gw * (gy1 - gy0) as usize);
        for y in gy0..gy1 {
            for x in gx0..gx1 {
                own.push(centre_sample(block, tracer, x, y));
            }
        }
        samples += own.len() as u64;
    }
    // (The block's own rectangle first: it holds all but the border.)
    let centre = |x: u32, y: u32| match block.centres {
        Some((_, mine)) if mine.holds(x, y) => mine.at(x, y),
        Some((band, _)) => band.at(x, y),
        None => own[at(x, y)],
    };
    let tolerance = threshold * SAMPLED_TOLERANCE;
    let most = sampler::max_samples(depth);
    let mut encoded: Vec<Rgb> = Vec::with_capacity(most as usize);
    let mut pixels = Vec::with_capacity(xs.len() * ys.len());
    for y in ys {
        for x in xs.clone() {
            let (value, e) = centre(x, y);
            // The eight neighbours inside the image.
            let flagged = (y.saturating_sub(1)..(y + 2).min(h)).any(|ny| {
                (x.saturating_sub(1)..(x + 2).min(w))
                    .any(|nx| (nx, ny) != (x, y) && differ(centre(nx, ny).1, e, threshold))
            });
            if !flagged {
                pixels.push(value);
                continue;
            }
            let seed = sampler::pixel_seed(x, y, 0);
            // The centre sample counts in the mean, not in the error estimate.
            let (mut n, mut batch, mut sum) = (0u32, 4u32, value);
            encoded.clear();
            loop {
                while n < batch {
                    let (dx, dy) = sampler::offset(seed, n);
                    tracer.light_stream = options.sampled_lights.then_some((seed, n + 1));
                    tracer.lens_stream = options.sampled_blur.then_some((seed, n + 1));
                    let v =
                        camera::sample(tracer, camera_media, w, h, x as f64 + dx, y as f64 + dy);
                    sum += v;
                    encoded.push(aa_encoded(v.truncate(), gamma));
                    n += 1;
                }
                if n >= most {
                    break;
                }
                let half = encoded.len() / 2;
                let mean = |e: &[Rgb]| e.iter().fold(Rgb::ZERO, |s, &v| s + v) / half as f64;
                let error = (mean(&encoded[..half]) - mean(&encoded[half..]))
                    .abs()
                    .element_sum()
                    / 2.0;
                if error < tolerance {
                    break;
                }
                batch = (2 * batch).min(most);
            }
            samples += u64::from(n);
            pixels.push(sum / f64::from(n + 1));
        }
    }
    tracer.light_stream = None;
    tracer.lens_stream = None;
    (pixels, samples)
}
