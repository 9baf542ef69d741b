//! POV-Ray's method 1 (`+AM1`, its default): a grid of samples in each pixel that differs
//! from its left or top neighbour.

use super::{Block, aa_encoded, differ};
use crate::render::transport::Tracer;
use crate::render::{Px, camera};
use crate::scene::Rgb;

/// The pixels of `block` with POV-Ray's method-1 logic, and the samples they took: the row
/// above and the column left of the block are traced (centre samples; the band's, shared,
/// when it traced them first) for comparison, count as already supersampled and not as the
/// block's samples.
pub(super) fn pixels(
    block: &Block,
    tracer: &mut Tracer,
    threshold: f64,
    depth: u32,
) -> (Vec<Px>, u64) {
    let (scene, camera_media) = (block.scene, block.camera_media);
    let (w, h) = (block.options.width, block.options.height);
    let (x0, x1, y0, y1) = (block.xs.start, block.xs.end, block.ys.start, block.ys.end);
    // Local grid with one extra row above and one extra column on the left.
    let gw = (x1 - x0 + 1) as usize;
    let gh = (y1 - y0 + 1) as usize;
    let mut value = vec![Px::ZERO; gw * gh];
    // Each value encoded for comparisons, kept in step with `value`.
    let mut encoded = vec![Rgb::ZERO; gw * gh];
    let mut done = vec![false; gw * gh];
    let index = |x: u32, y: u32| (y + 1 - y0) as usize * gw + (x + 1 - x0) as usize;
    let mut samples = 0u64;

    // A centre sample and its encoding: where the band traced it first (the block's own
    // bottom row and right column, its neighbours' for its border: see `BandCentres`), from
    // there; else traced here (without the band's, the border again by the neighbouring
    // block: the same rays).
    let own = |x: u32, y: u32| (x0..x1).contains(&x) && (y0..y1).contains(&y);
    let shared = |x: u32, y: u32| match block.centres {
        Some((_, mine)) if mine.holds(x, y) => Some(mine.at(x, y)),
        Some((band, _)) if !own(x, y) => Some(band.at(x, y)),
        _ => None,
    };
    let encode = |c: Px| (c, aa_encoded(c.truncate(), scene.gamma()));
    let centre = |tracer: &mut Tracer, x: u32, y: u32| {
        shared(x, y).unwrap_or_else(|| encode(block.centre(tracer, x, y)))
    };
    if y0 > 0 {
        for x in x0..x1 {
            let i = index(x, y0 - 1);
            (value[i], encoded[i]) = centre(tracer, x, y0 - 1);
            done[i] = true;
        }
    }
    if x0 > 0 {
        for y in y0..y1 {
            let i = index(x0 - 1, y);
            (value[i], encoded[i]) = centre(tracer, x0 - 1, y);
            done[i] = true;
        }
    }

    let n = depth.clamp(1, 9);
    // Grid offsets −½ + (k + ½)/n, written so that the middle one of an odd grid is exactly 0.
    let offset = |k: u32| f64::from(2 * k + 1) / f64::from(2 * n) - 0.5;
    let supersample =
        |tracer: &mut Tracer, value: &mut [Px], encoded: &mut [Rgb], x: u32, y: u32| {
            // (centre + n×n grid) / (n² + 1): the centre sample counts once more.
            // The grid's points but the centre (no jitter: its colour is known), traced
            // together, then summed in the grid's order.
            let mut points = [(0.0, 0.0); 81];
            let mut traced = 0;
            for b in 0..n {
                for a in 0..n {
                    let (ox, oy) = (offset(a), offset(b));
                    if ox != 0.0 || oy != 0.0 {
                        points[traced] = (x as f64 + ox, y as f64 + oy);
                        traced += 1;
                    }
                }
            }
            let mut samples = [Px::ZERO; 81];
            camera::sample_many(
                tracer,
                camera_media,
                (w, h),
                &points[..traced],
                |_, _| {},
                |_, k, v| samples[k] = v,
            );
            let centre_value = value[index(x, y)];
            let mut sum = centre_value;
            let mut next = samples.iter();
            for b in 0..n {
                for a in 0..n {
                    sum += if offset(a) == 0.0 && offset(b) == 0.0 {
                        centre_value
                    } else {
                        *next.next().expect("a sample for each point")
                    };
                }
            }
            value[index(x, y)] = sum / (n * n + 1) as f64;
            encoded[index(x, y)] = aa_encoded(value[index(x, y)].truncate(), scene.gamma());
            traced as u64
        };

    for y in y0..y1 {
        // The row's centre samples first: the band's from there, runs of the others traced
        // together (the comparisons below read the pixels to the left and above, and each
        // pixel's centre before anything supersamples it, so the order changes nothing).
        let mut x = x0;
        while x < x1 {
            if let Some(v) = shared(x, y) {
                (value[index(x, y)], encoded[index(x, y)]) = v;
                x += 1;
                continue;
            }
            let end = (x..x1).find(|&x| shared(x, y).is_some()).unwrap_or(x1);
            let size = (w, h);
            camera::sample_row(tracer, camera_media, size, (x..end, y), |_, x, c| {
                (value[index(x, y)], encoded[index(x, y)]) = encode(c);
            });
            x = end;
        }
        for x in x0..x1 {
            let e = encoded[index(x, y)];
            samples += 1;
            let left_differs = x > 0 && differ(encoded[index(x - 1, y)], e, threshold);
            let top_differs = y > 0 && differ(encoded[index(x, y - 1)], e, threshold);
            if left_differs && !done[index(x - 1, y)] {
                samples += supersample(tracer, &mut value, &mut encoded, x - 1, y);
                done[index(x - 1, y)] = true;
            }
            if top_differs && !done[index(x, y - 1)] {
                samples += supersample(tracer, &mut value, &mut encoded, x, y - 1);
                done[index(x, y - 1)] = true;
            }
            if left_differs || top_differs {
                samples += supersample(tracer, &mut value, &mut encoded, x, y);
                done[index(x, y)] = true;
            }
        }
    }

    let pixels = block.pixels(&mut |x, y| value[index(x, y)]);
    (pixels, samples)
}
