//! trace's own sampler (method 3): stratified samples from each pixel's scrambled Sobol
//! sequence where a pixel differs from a neighbour, until their estimated error is small.

use super::centres::centre_row;
use super::{Block, SAMPLED_TOLERANCE, aa_encoded, differ};
use crate::render::transport::Tracer;
use crate::render::{Px, camera, sampler};
use crate::scene::Rgb;

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
    // (Shared centre samples count here, with the border the block traced for its band.)
    if let Some((_, mine)) = block.centres {
        samples += mine.samples();
    } else {
        own.reserve(gw * (gy1 - gy0) as usize);
        for y in gy0..gy1 {
            centre_row(block, tracer, (gx0..gx1, y), &mut own);
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
                // The batch's samples traced together, each with its own streams, up to
                // 32 at a time.
                while n < batch {
                    let count = (batch - n).min(32);
                    let mut points = [(0.0, 0.0); 32];
                    for (k, point) in points.iter_mut().enumerate().take(count as usize) {
                        let (dx, dy) = sampler::offset(seed, n + k as u32);
                        *point = (x as f64 + dx, y as f64 + dy);
                    }
                    let first = n;
                    let streams = |tracer: &mut Tracer, k: usize| {
                        let stream = Some((seed, first + k as u32 + 1));
                        tracer.light_stream = stream.filter(|_| options.sampled_lights);
                        tracer.lens_stream = stream.filter(|_| options.sampled_blur);
                    };
                    let (size, points) = ((w, h), &points[..count as usize]);
                    camera::sample_many(tracer, camera_media, size, points, streams, |_, _, v| {
                        sum += v;
                        encoded.push(aa_encoded(v.truncate(), gamma));
                    });
                    n += count;
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
