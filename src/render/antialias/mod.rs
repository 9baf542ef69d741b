//! Anti-aliasing: POV-Ray's methods 1 (`adaptive`) and 2 (`recursive`), trace's sampler
//! (method 3, `sampled`), and the colour comparison they share (POV-Ray's: output values,
//! gamma-2.5 encoded, channel differences summed).

mod adaptive;
mod centres;
mod recursive;
mod sampled;

pub(super) use centres::{BandCentres, Centres, Rect, centres};

use super::transport::{MediumStack, Tracer};
use super::{Px, RenderOptions, camera, output_value};
use crate::scene::{Gamma, Rgb, Scene};
use std::ops::Range;

/// POV-Ray's gamma for anti-aliasing colour comparisons (`+AG`).
pub(super) const AA_COMPARISON_GAMMA: f64 = 2.5;

/// Anti-aliasing (POV-Ray's methods 1 and 2, without jitter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Antialias {
    /// One ray through each pixel centre (POV-Ray `-A`).
    Off,
    /// Supersample pixels whose colour differs from a left or top neighbour by at least
    /// `threshold` (POV-Ray `+A<threshold> +R<depth> -J`): (centre + depth×depth grid) /
    /// (depth² + 1). Threshold 0 supersamples every pixel.
    Adaptive {
        /// Colour-difference threshold (sum over channels, gamma-2.5 encoded).
        threshold: f64,
        /// Grid size per axis (1..=9).
        depth: u32,
    },
    /// POV-Ray's method 2 (`+AM2 +A<threshold> +R<depth> -J`): the pixel corners are traced
    /// (shared with the neighbours); a square whose corners differ by at least `threshold` is
    /// split in four (edge mid-points and centre traced) down to `depth − 1` times, and the
    /// pixel is the mean of its squares, each the mean of its corners.
    Recursive {
        /// Colour-difference threshold (as for [`Antialias::Adaptive`]).
        threshold: f64,
        /// Subdivision depth (1..=9): at most `depth − 1` splits.
        depth: u32,
    },
    /// trace's own sampler (method 3): every pixel takes one sample at its centre; a pixel
    /// whose centre differs from one of its eight neighbours' by at least `threshold` takes
    /// stratified samples from a scrambled Sobol sequence seeded by the pixel, 4, then 8,
    /// 16, … until the estimated error of their mean (half the difference of the means of
    /// the two halves, in the comparison encoding) is below `threshold` ×
    /// 0.1 (`SAMPLED_TOLERANCE`), or it has taken 4·2^(depth−1). The pixel is the mean of the
    /// centre and those samples.
    Sampled {
        /// Colour-difference threshold (as for [`Antialias::Adaptive`]); 0 samples every
        /// pixel to the most.
        threshold: f64,
        /// Sample budget (1..=9): at most 4·2^(depth−1) samples per pixel (16 at 3).
        depth: u32,
    },
}

/// Method 3 stops sampling a pixel when its estimated error falls below the threshold times
/// this.
pub(super) const SAMPLED_TOLERANCE: f64 = 0.1;

/// A colour as POV-Ray's anti-aliasing compares it: the output value, gamma-2.5 encoded, in
/// single precision as POV-Ray encodes it (`pow(max(x, 0.0f), 1.0f/2.5f)` on floats; a
/// double-precision power cost method 1 about 2 % of its time).
pub(super) fn aa_encoded(c: Rgb, gamma: Gamma) -> Rgb {
    let v = output_value(c, gamma);
    let e = |x: f32| x.max(0.0).powf((1.0 / AA_COMPARISON_GAMMA) as f32) as f64;
    Rgb::new(e(v[0]), e(v[1]), e(v[2]))
}

/// POV-Ray's "colours differ" test for anti-aliasing: the sum over channels of the
/// differences of the encoded values ([`aa_encoded`]) reaches the threshold.
pub(super) fn differ(a: Rgb, b: Rgb, threshold: f64) -> bool {
    (a - b).abs().element_sum() >= threshold
}

/// A block of pixels being rendered, and what its samples need.
pub(super) struct Block<'a> {
    pub scene: &'a Scene,
    pub options: &'a RenderOptions,
    /// The objects every camera ray starts inside, for a camera with one eye point.
    pub camera_media: &'a Option<MediumStack>,
    /// The block's columns and rows.
    pub xs: Range<u32>,
    pub ys: Range<u32>,
    /// The centre samples of the block's band (methods 1 and 3), if the band traced them
    /// first, and the block's own among them.
    pub centres: Option<(&'a BandCentres, &'a Centres)>,
}

impl Block<'_> {
    /// The block's pixels in row order, each from `f(x, y)`.
    fn pixels(&self, f: &mut dyn FnMut(u32, u32) -> Px) -> Vec<Px> {
        let mut pixels = Vec::with_capacity(self.xs.len() * self.ys.len());
        for y in self.ys.clone() {
            for x in self.xs.clone() {
                pixels.push(f(x, y));
            }
        }
        pixels
    }

    /// The sample at the centre of pixel (x, y).
    fn centre(&self, tracer: &mut Tracer, x: u32, y: u32) -> Px {
        let (w, h) = (self.options.width, self.options.height);
        camera::sample(tracer, self.camera_media, w, h, x as f64, y as f64)
    }
}

/// The pixels of `block` (row by row) as `options.antialias` says, and the camera samples
/// they took.
pub(super) fn block_pixels(block: &Block, tracer: &mut Tracer) -> (Vec<Px>, u64) {
    match block.options.antialias {
        Antialias::Off => {
            let mut pixels = Vec::with_capacity(block.xs.len() * block.ys.len());
            let size = (block.options.width, block.options.height);
            for y in block.ys.clone() {
                let row = (block.xs.clone(), y);
                camera::sample_row(tracer, block.camera_media, size, row, |_, _, v| {
                    pixels.push(v)
                });
            }
            let samples = pixels.len() as u64;
            (pixels, samples)
        }
        Antialias::Adaptive { threshold, depth } => {
            adaptive::pixels(block, tracer, threshold, depth)
        }
        Antialias::Recursive { threshold, depth } => {
            recursive::pixels(block, tracer, threshold, depth)
        }
        Antialias::Sampled { threshold, depth } => sampled::pixels(block, tracer, threshold, depth),
    }
}
