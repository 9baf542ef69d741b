//! trace's own sampler (anti-aliasing method 3): stratified sample positions in a pixel from a
//! scrambled low-discrepancy sequence, seeded by the pixel, spent where a measured error
//! estimate says the pixel needs them.
//!
//! The sequence is the first two dimensions of Sobol's sequence (dimension 0 is the base-2
//! radical inverse, dimension 1 the sequence whose generator matrix is Pascal's triangle mod
//! 2), each coordinate scrambled as Owen's nested uniform scrambling does: every bit is
//! flipped or not by a hash of the bits above it and the pixel's seed. Any first 2^k points
//! of a pixel are then a (0, k, 2)-net (one point in each of the 2^k elementary rectangles of
//! every shape), and the two halves of the first 2^(k+1) points are two such nets, whose means
//! differ by about twice the error of their common mean: the error estimate.
//!
//! Everything depends only on the pixel's coordinates, so the image is the same for any
//! thread count, block order or region.

/// A 32-bit integer hash with good avalanche (the "lowbias32" multipliers).
fn mix(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    x
}

/// The seed of pixel (x, y) for stream `stream` (different uses draw independent streams).
pub(super) fn pixel_seed(x: u32, y: u32, stream: u32) -> u32 {
    mix(x ^ mix(y ^ mix(stream.wrapping_add(0x9e37_79b9))))
}

/// The seed of stream `stream` of a pixel whose seed is `seed` (stream 0 is the pixel's
/// positions; each area light draws its own).
pub(super) fn stream_seed(seed: u32, stream: u32) -> u32 {
    mix(seed ^ mix(stream.wrapping_mul(0x68e3_1da4)))
}

/// The stream of lens points (area lights take streams 1, 2, … by their index + 1).
pub(super) const LENS_STREAM: u32 = u32::MAX;

/// Shirley and Chiu's concentric map of the square [−½, ½)² onto the disc of radius ½: equal
/// areas to equal areas, strata kept compact.
pub(super) fn square_to_disc(u: f64, v: f64) -> (f64, f64) {
    use std::f64::consts::FRAC_PI_4;
    let (a, b) = (2.0 * u, 2.0 * v);
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let (r, phi) = if a.abs() > b.abs() {
        (a, FRAC_PI_4 * (b / a))
    } else {
        (b, 2.0 * FRAC_PI_4 - FRAC_PI_4 * (a / b))
    };
    (0.5 * r * phi.cos(), 0.5 * r * phi.sin())
}

/// Point `i` of the two-dimensional Sobol sequence, as 32-bit fractions.
fn sobol(i: u32) -> (u32, u32) {
    let x = i.reverse_bits();
    let (mut y, mut v, mut bits) = (0u32, 1u32 << 31, i);
    while bits != 0 {
        if bits & 1 != 0 {
            y ^= v;
        }
        bits >>= 1;
        v ^= v >> 1;
    }
    (x, y)
}

/// Owen's nested uniform scrambling of a 32-bit fraction: bit b (from the top) is flipped by
/// a hash of the seed, b, and the bits above it. Only the top 24 bits are scrambled (finer
/// than any sample position needs); the rest are cleared.
fn owen(x: u32, seed: u32) -> u32 {
    let mut out = 0u32;
    for level in 0..24u32 {
        let bit = 31 - level;
        // The bits above `bit`, marked by a leading one so that prefixes of different
        // lengths differ.
        let prefix = ((x >> bit) >> 1) | (1 << level);
        let flip = mix(seed ^ mix(prefix)) >> 31;
        out |= (((x >> bit) & 1) ^ flip) << bit;
    }
    out
}

/// Sample `i` of a pixel whose seed is `seed`: an offset from the pixel's centre in
/// [−½, ½)².
pub(super) fn offset(seed: u32, i: u32) -> (f64, f64) {
    let (x, y) = sobol(i);
    let to_unit = |v: u32| f64::from(v) / 4_294_967_296.0 - 0.5;
    (
        to_unit(owen(x, seed)),
        to_unit(owen(y, mix(seed ^ 0x5bd1_e995))),
    )
}

/// The most samples a pixel may take at anti-aliasing depth `depth` (1..=9): 4·2^(depth−1),
/// so 16 at the default depth 3.
pub(super) fn max_samples(depth: u32) -> u32 {
    4 << (depth.clamp(1, 9) - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The elementary rectangles of [0,1)² with 2^k cells: one point in each.
    fn is_net(points: &[(f64, f64)], k: u32) -> bool {
        (0..=k).all(|a| {
            let (nx, ny) = (1usize << a, 1usize << (k - a));
            let mut seen = vec![false; nx * ny];
            points.iter().all(|&(x, y)| {
                let cell = ((y + 0.5) * ny as f64) as usize * nx + ((x + 0.5) * nx as f64) as usize;
                !std::mem::replace(&mut seen[cell], true)
            })
        })
    }

    #[test]
    fn every_power_of_two_prefix_and_half_is_a_net() {
        for seed in [0, 1, 12345, pixel_seed(17, 4, 0), pixel_seed(640, 480, 0)] {
            for k in 0..=8u32 {
                let n = 1u32 << k;
                let first: Vec<_> = (0..n).map(|i| offset(seed, i)).collect();
                let second: Vec<_> = (n..2 * n).map(|i| offset(seed, i)).collect();
                assert!(is_net(&first, k), "seed {seed}: first {n} points");
                assert!(is_net(&second, k), "seed {seed}: points {n}..{}", 2 * n);
            }
        }
    }

    #[test]
    fn offsets_are_in_the_pixel_and_differ_between_pixels() {
        let a: Vec<_> = (0..16).map(|i| offset(pixel_seed(3, 5, 0), i)).collect();
        let b: Vec<_> = (0..16).map(|i| offset(pixel_seed(4, 5, 0), i)).collect();
        assert!(
            a.iter()
                .chain(&b)
                .all(|&(x, y)| (-0.5..0.5).contains(&x) && (-0.5..0.5).contains(&y))
        );
        assert_ne!(a, b);
        assert_eq!(
            a,
            (0..16)
                .map(|i| offset(pixel_seed(3, 5, 0), i))
                .collect::<Vec<_>>()
        );
    }

    #[test]
    fn sobol_dimension_one_starts_as_its_direction_numbers_give() {
        // The second dimension's direction numbers ½, ¾, 5/8, … combined in binary (not Gray
        // code) order.
        let y: Vec<f64> = (0..8)
            .map(|i| f64::from(sobol(i).1) / 4_294_967_296.0)
            .collect();
        assert_eq!(y, [0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875]);
    }
}
