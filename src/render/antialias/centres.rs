//! A band's centre samples, traced once and shared by its blocks' comparisons (methods 1
//! and 3): each block first traces the centre samples its neighbours' comparisons read (and,
//! at the band's edges, those just outside the band), and then compares and samples reading
//! them.

use super::{Antialias, Block, aa_encoded};
use crate::geometry::counters;
use crate::render::transport::{RayCounts, Tracer};
use crate::render::{BLOCK_SIZE, Px, camera, sampler};
use crate::scene::Rgb;
use std::ops::Range;

/// A rectangle of pixels (columns, rows).
pub(in crate::render) type Rect = (Range<u32>, Range<u32>);

/// The most rectangles a block traces for its band.
const MOST_STRIPS: usize = 4;

/// One rectangle of a block's centre samples: where it lies, and where its samples start in
/// [`Centres::values`] (row by row).
#[derive(Clone, Copy, Default)]
struct Strip {
    x0: u32,
    y0: u32,
    width: u32,
    height: u32,
    start: usize,
}

impl Strip {
    fn holds(&self, x: u32, y: u32) -> bool {
        x.wrapping_sub(self.x0) < self.width && y.wrapping_sub(self.y0) < self.height
    }
}

/// The centre samples (the value, and its comparison encoding) of up to four rectangles of
/// pixels, traced by one block for the band's blocks to share, and what tracing them
/// counted.
pub(in crate::render) struct Centres {
    strips: [Strip; MOST_STRIPS],
    count: usize,
    values: Vec<(Px, Rgb)>,
    pub(in crate::render) counts: RayCounts,
    pub(in crate::render) tests: counters::Tests,
}

impl Centres {
    /// The rectangle holding pixel (x, y), if one does.
    #[inline]
    fn strip(&self, x: u32, y: u32) -> Option<&Strip> {
        self.strips[..self.count].iter().find(|s| s.holds(x, y))
    }

    /// Whether pixel (x, y) lies in one of the rectangles.
    #[inline]
    pub(super) fn holds(&self, x: u32, y: u32) -> bool {
        self.strip(x, y).is_some()
    }

    /// The sample of pixel (x, y), which lies in one of the rectangles.
    #[inline]
    pub(super) fn at(&self, x: u32, y: u32) -> (Px, Rgb) {
        let s = self.strip(x, y).expect("a pixel of the block's rectangles");
        self.values[s.start + ((y - s.y0) * s.width + (x - s.x0)) as usize]
    }

    /// The samples traced.
    pub(super) fn samples(&self) -> u64 {
        self.values.len() as u64
    }

    /// The samples' buffer, emptied, for the next band's block.
    fn into_buffer(self) -> Vec<(Px, Rgb)> {
        let mut values = self.values;
        values.clear();
        values
    }
}

/// A band's centre samples for the comparisons of method 1 (a pixel's left and top
/// neighbours) or method 3 (its eight neighbours): traced once for the band, each by one
/// block, instead of again by every block whose border they lie on (for blocks of 32×32,
/// 6 % more centre rays for method 1's row above and column left, 13 % for method 3's
/// ring). Method 3's blocks trace all their pixels first; method 1's only their bottom row
/// and right column (what the blocks below and right of them read), the rest of their
/// pixels in turn as they compare them. On the sides where no block of the band lies beyond
/// (method 1: top and left; method 3: all four), a block traces the pixels along the side too,
/// so that each pixel a block's comparisons read lies in one block's rectangles.
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

    /// The rectangles block (`bx`, `by`) (in blocks) traces for the band `columns` (in
    /// blocks) × `rows` (in blocks) of a `width` × `height` image with `method`: method 3's
    /// pixels, grown by one on each side with no block of the band beyond; method 1's row
    /// above and column left where no block of the band lies there, and its bottom row and
    /// right column.
    pub(in crate::render) fn rectangles(
        (bx, by): (u32, u32),
        (columns, rows): (Range<u32>, Range<u32>),
        (width, height): (u32, u32),
        method: &Antialias,
    ) -> ([Rect; MOST_STRIPS], usize) {
        let (x0, y0) = (bx * BLOCK_SIZE, by * BLOCK_SIZE);
        let (x1, y1) = ((x0 + BLOCK_SIZE).min(width), (y0 + BLOCK_SIZE).min(height));
        let (top, left) = (by == rows.start && y0 > 0, bx == columns.start && x0 > 0);
        let mut out: [Rect; MOST_STRIPS] = Default::default();
        let mut n = 0;
        let mut push = |r: Rect| {
            out[n] = r;
            n += 1;
        };
        if let Antialias::Sampled { .. } = method {
            let (bottom, right) = (
                by + 1 == rows.end && y1 < height,
                bx + 1 == columns.end && x1 < width,
            );
            let grow = |edge: bool| u32::from(edge);
            push((
                x0 - grow(left)..x1 + grow(right),
                y0 - grow(top)..y1 + grow(bottom),
            ));
        } else {
            if top {
                push((x0..x1, y0 - 1..y0));
            }
            if left {
                push((x0 - 1..x0, y0..y1));
            }
            push((x0..x1, y1 - 1..y1));
            if y1 - y0 > 1 {
                push((x1 - 1..x1, y0..y1 - 1));
            }
        }
        (out, n)
    }

    /// The centre sample of pixel (x, y), which lies in a block's rectangles.
    #[inline]
    pub(super) fn at(&self, x: u32, y: u32) -> (Px, Rgb) {
        let (bx0, by0) = self.first;
        let bx = (x / BLOCK_SIZE).clamp(bx0, bx0 + self.columns - 1) - bx0;
        let by = (y / BLOCK_SIZE).clamp(by0, by0 + self.rows - 1) - by0;
        self.blocks[(by * self.columns + bx) as usize].at(x, y)
    }
}

/// The centre samples of pixels `xs` of row `y` and their comparison encodings, appended to
/// `out` (method 3's draw their area lights' and lens's points from the first of each
/// pixel's sequence when it samples them; the other methods' are the rays of
/// [`Block::centre`]), their nearest hits found a packet at a time.
pub(super) fn centre_row(
    block: &Block,
    tracer: &mut Tracer,
    (xs, y): (std::ops::Range<u32>, u32),
    out: &mut Vec<(Px, Rgb)>,
) {
    let options = block.options;
    let sampled = matches!(options.antialias, Antialias::Sampled { .. });
    let gamma = tracer.scene.gamma();
    let size = (options.width, options.height);
    let mut points = [(0.0, 0.0); ROW];
    for x0 in xs.clone().step_by(ROW) {
        let run = x0..(x0 + ROW as u32).min(xs.end);
        for (point, x) in points.iter_mut().zip(run.clone()) {
            *point = (x as f64, y as f64);
        }
        let streams = |tracer: &mut Tracer, k: usize| {
            let seed = sampler::pixel_seed(x0 + k as u32, y, 0);
            tracer.light_stream = (sampled && options.sampled_lights).then_some((seed, 0));
            tracer.lens_stream = (sampled && options.sampled_blur).then_some((seed, 0));
        };
        let points = &points[..run.len()];
        camera::sample_many(
            tracer,
            block.camera_media,
            size,
            points,
            streams,
            |_, _, v| out.push((v, aa_encoded(v.truncate(), gamma))),
        );
    }
}

/// Pixels [`centre_row`] traces at once.
const ROW: usize = 32;

/// The centre samples of the pixels of `rectangles` (up to four: see [`BandCentres`]),
/// traced for the band's blocks to share, into `values` (an emptied buffer); `block` gives
/// the render's settings.
pub(in crate::render) fn centres(
    block: &Block,
    tracer: &mut Tracer,
    rectangles: &[Rect],
    mut values: Vec<(Px, Rgb)>,
) -> Centres {
    counters::take(); // (the counts start from zero)
    let mut strips = [Strip::default(); MOST_STRIPS];
    values.reserve(rectangles.iter().map(|(xs, ys)| xs.len() * ys.len()).sum());
    for (strip, (xs, ys)) in strips.iter_mut().zip(rectangles) {
        *strip = Strip {
            x0: xs.start,
            y0: ys.start,
            width: xs.len() as u32,
            height: ys.len() as u32,
            start: values.len(),
        };
        for y in ys.clone() {
            centre_row(block, tracer, (xs.clone(), y), &mut values);
        }
    }
    tracer.light_stream = None;
    tracer.lens_stream = None;
    Centres {
        strips,
        count: rectangles.len().min(MOST_STRIPS),
        values,
        counts: std::mem::take(&mut tracer.counts),
        tests: counters::take(),
    }
}
