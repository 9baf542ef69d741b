//! Focal blur as POV-Ray 3.7 samples it: nothing random. Each pixel traces batches of rays
//! through points of a hexagonal grid on the lens (filled out by a Halton sequence for more
//! samples than the grid has), each point moved by a jitter hashed from the sub-pixel
//! position, itself hashed from the pixel; it stops after a batch once the variance of the
//! mean of every channel is below a threshold from the chi-square quantile at the scene's
//! `confidence`, scaled by its `variance`.

use crate::ir::FocalBlur;
use crate::noise::pseudo_random;
use glam::{DVec2, DVec3};

/// POV-Ray's jitter table: 256 offsets in [−0.5, 0.5] (data).
#[rustfmt::skip]
const JITTER: [f32; 256] = [
    -0.500000, 0.005890, 0.011749, -0.490234, 0.023468, -0.470703, -0.480469, 0.017609,
    0.046906, -0.447266, -0.441406, 0.056671, -0.460938, 0.044952, 0.035187, -0.466797,
    0.093781, -0.400391, -0.394531, 0.103546, -0.382813, 0.123077, 0.113312, -0.388672,
    -0.421875, 0.084015, 0.089874, -0.412109, 0.070343, -0.423828, -0.433594, 0.064484,
    0.187531, -0.306641, -0.300781, 0.197296, -0.289063, 0.216827, 0.207062, -0.294922,
    -0.265625, 0.240265, 0.246124, -0.255859, 0.226593, -0.267578, -0.277344, 0.220734,
    -0.343750, 0.162140, 0.167999, -0.333984, 0.179718, -0.314453, -0.324219, 0.173859,
    0.140656, -0.353516, -0.347656, 0.150421, -0.367188, 0.138702, 0.128937, -0.373047,
    0.375031, -0.119141, -0.113281, 0.384796, -0.101563, 0.404327, 0.394562, -0.107422,
    -0.078125, 0.427765, 0.433624, -0.068359, 0.414093, -0.080078, -0.089844, 0.408234,
    -0.031250, 0.474640, 0.480499, -0.021484, 0.492218, -0.001953, -0.011719, 0.486359,
    0.453156, -0.041016, -0.035156, 0.462921, -0.054688, 0.451202, 0.441437, -0.060547,
    -0.187500, 0.318390, 0.324249, -0.177734, 0.335968, -0.158203, -0.167969, 0.330109,
    0.359406, -0.134766, -0.128906, 0.369171, -0.148438, 0.357452, 0.347687, -0.154297,
    0.281281, -0.212891, -0.207031, 0.291046, -0.195313, 0.310577, 0.300812, -0.201172,
    -0.234375, 0.271515, 0.277374, -0.224609, 0.257843, -0.236328, -0.246094, 0.251984,
    -0.249969, 0.255859, 0.261719, -0.240204, 0.273438, -0.220673, -0.230438, 0.267578,
    0.296875, -0.197235, -0.191376, 0.306641, -0.210907, 0.294922, 0.285156, -0.216766,
    0.343750, -0.150360, -0.144501, 0.353516, -0.132782, 0.373047, 0.363281, -0.138641,
    -0.171844, 0.333984, 0.339844, -0.162079, 0.320313, -0.173798, -0.183563, 0.314453,
    0.437500, -0.056610, -0.050751, 0.447266, -0.039032, 0.466797, 0.457031, -0.044891,
    -0.015594, 0.490234, 0.496094, -0.005829, 0.476563, -0.017548, -0.027313, 0.470703,
    -0.093719, 0.412109, 0.417969, -0.083954, 0.429688, -0.064423, -0.074188, 0.423828,
    0.390625, -0.103485, -0.097626, 0.400391, -0.117157, 0.388672, 0.378906, -0.123016,
    0.125000, -0.369110, -0.363251, 0.134766, -0.351532, 0.154297, 0.144531, -0.357391,
    -0.328094, 0.177734, 0.183594, -0.318329, 0.164063, -0.330048, -0.339813, 0.158203,
    -0.281219, 0.224609, 0.230469, -0.271454, 0.242188, -0.251923, -0.261688, 0.236328,
    0.203125, -0.290985, -0.285126, 0.212891, -0.304657, 0.201172, 0.191406, -0.310516,
    -0.437469, 0.068359, 0.074219, -0.427704, 0.085938, -0.408173, -0.417938, 0.080078,
    0.109375, -0.384735, -0.378876, 0.119141, -0.398407, 0.107422, 0.097656, -0.404266,
    0.031250, -0.462860, -0.457001, 0.041016, -0.445282, 0.060547, 0.050781, -0.451141,
    -0.484344, 0.021484, 0.027344, -0.474579, 0.007813, -0.486298, -0.496063, 0.001953,
];

/// POV-Ray's lens grids: the points in the order they are sampled, and the batch sizes.
const SQUARE: [(f64, f64); 4] = [(-0.25, 0.25), (0.25, 0.25), (-0.25, -0.25), (0.25, -0.25)];
const HEX7: [(f64, f64); 7] = [
    (-0.288675, 0.0),
    (0.0, 0.0),
    (0.288675, 0.0),
    (-0.144338, 0.25),
    (-0.144338, -0.25),
    (0.144338, 0.25),
    (0.144338, -0.25),
];
const HEX19: [(f64, f64); 19] = [
    (-0.192450, 0.333333),
    (-0.192450, -0.333333),
    (0.192450, 0.333333),
    (0.192450, -0.333333),
    (0.384900, 0.0),
    (-0.384900, 0.0),
    (0.0, 0.0),
    (0.0, 0.333333),
    (0.0, -0.333333),
    (-0.288675, 0.166667),
    (-0.288675, -0.166667),
    (0.288675, 0.166667),
    (0.288675, -0.166667),
    (-0.096225, 0.166667),
    (-0.096225, -0.166667),
    (0.096225, 0.166667),
    (0.096225, -0.166667),
    (-0.192450, 0.0),
    (0.192450, 0.0),
];
const HEX37: [(f64, f64); 37] = [
    (0.0, 0.0),
    (-0.216506, 0.375),
    (0.216506, -0.375),
    (-0.216506, -0.375),
    (0.216506, 0.375),
    (-0.433013, 0.0),
    (0.433013, 0.0),
    (-0.144338, 0.25),
    (0.144338, -0.25),
    (-0.144338, -0.25),
    (0.144338, 0.25),
    (-0.288675, 0.0),
    (0.288675, 0.0),
    (-0.072169, 0.125),
    (0.072169, -0.125),
    (-0.072169, -0.125),
    (0.072169, 0.125),
    (-0.144338, 0.0),
    (0.144338, 0.0),
    (-0.360844, 0.125),
    (-0.360844, -0.125),
    (0.360844, 0.125),
    (0.360844, -0.125),
    (-0.288675, 0.25),
    (-0.288675, -0.25),
    (0.288675, 0.25),
    (0.288675, -0.25),
    (-0.072169, 0.375),
    (-0.072169, -0.375),
    (0.072169, 0.375),
    (0.072169, -0.375),
    (-0.216506, 0.125),
    (-0.216506, -0.125),
    (0.216506, 0.125),
    (0.216506, -0.125),
    (0.0, 0.25),
    (0.0, -0.25),
];

/// A scene's focal blur, ready to sample.
#[derive(Clone, Debug)]
pub struct Blur {
    /// Half the aperture.
    pub radius: f64,
    /// Lens points (in a disc of radius ½), in sampling order.
    pub grid: Vec<DVec2>,
    /// Batch sizes (then batches of 4).
    pub batches: &'static [u32],
    /// Largest lens jitter.
    pub max_jitter: f64,
    /// Threshold on the variance of the mean after n samples (index n − 1).
    pub thresholds: Vec<f64>,
    /// Fewest and most samples.
    pub min: u32,
    /// Most samples.
    pub max: u32,
    /// Lens axes and the sharp plane's distance over the direction's length.
    pub x_perp: DVec3,
    /// Second lens axis.
    pub y_perp: DVec3,
    /// Focal distance over |direction|.
    pub focal_ratio: f64,
}

impl Blur {
    /// The blur of a camera with final `direction` and `up`.
    pub fn new(b: &FocalBlur, direction: DVec3, up: DVec3) -> Blur {
        let n = b.max_samples.max(1) as usize;
        let (table, batches, jitter): (&[(f64, f64)], &'static [u32], f64) = if n >= 37 {
            (&HEX37, &[7, 6, 6, 4, 4, 4, 4, 2], 0.0721688)
        } else if n >= 19 {
            (&HEX19, &[7, 6, 6], 0.096225)
        } else if n >= 7 {
            (&HEX7, &[7], 0.144338)
        } else {
            (&SQUARE, &[], 0.0)
        };
        let max_jitter = match n {
            7 | 19 | 37 => jitter,
            _ => 0.5 / (n as f64).sqrt(),
        };
        let mut grid: Vec<DVec2> = table
            .iter()
            .take(n)
            .map(|&(x, y)| DVec2::new(x, y))
            .collect();
        if n > grid.len() {
            fill_halton(&mut grid, n);
        }
        let q = |df: usize| chi_square_quantile(df as f64, b.confidence);
        let thresholds = if n == 1 {
            vec![0.0]
        } else {
            let t1 = b.variance / q(n - 1);
            (0..n).map(|i| t1 * q(i + 1)).collect()
        };
        let x_perp = up.cross(direction).normalize();
        let y_perp = direction.cross(x_perp).normalize();
        Blur {
            radius: b.aperture / 2.0,
            grid,
            batches,
            max_jitter,
            thresholds,
            min: b.min_samples,
            max: n as u32,
            x_perp,
            y_perp,
            focal_ratio: b.focal_distance / direction.length(),
        }
    }
}

/// Fills the lens grid beyond POV-Ray's tables with points of a Halton sequence on the disc,
/// each in a cell of a coarse grid no earlier point took (while draws remain).
fn fill_halton(grid: &mut Vec<DVec2>, n: usize) {
    let g = 2 * ((n as f64 / std::f64::consts::PI).sqrt().ceil() as usize) + 1;
    let cell = |v: DVec2| {
        let c = |t: f64| (((t + 0.5) * g as f64).floor().max(0.0) as usize).min(g - 1);
        c(v.y) * g + c(v.x)
    };
    let mut taken = vec![false; g * g];
    for p in grid.iter() {
        taken[cell(*p)] = true;
    }
    let radical = |mut k: usize, base: usize| {
        let (mut inv, mut f) = (0.0, 1.0 / base as f64);
        while k > 0 {
            inv += (k % base) as f64 * f;
            k /= base;
            f /= base as f64;
        }
        inv
    };
    let period = 10 * n;
    let mut k = 0usize;
    let mut remain = 10 * n;
    let mut draw = || {
        k = k % period + 1;
        let r = (radical(k, 2) * 0.25).sqrt();
        let theta = radical(k, 3) * 2.0 * std::f64::consts::PI;
        DVec2::new(r * theta.cos(), r * theta.sin())
    };
    for i in grid.len()..n {
        let mut v = draw();
        remain = remain.saturating_sub(1);
        while taken[cell(v)] && remain > n - i {
            v = draw();
            remain = remain.saturating_sub(1);
        }
        taken[cell(v)] = true;
        grid.push(v);
    }
}

impl Blur {
    /// The `n`-th sample's offset within the pixel whose hash seed is `seed`: the centre of
    /// one of 16 × 16 cells, moved by a hashed jitter (POV-Ray's, with its −1/32 bias).
    pub fn subpixel(seed: i32, n: i32) -> (f64, f64) {
        let cell = |v: i32| f64::from(2 * (pseudo_random(v) % 16) + 1) / 32.0 - 0.5;
        let (dx, dy) = (cell(seed + n), cell(seed + n + 1));
        let (rx, ry) = jitter2d(dx, dy);
        (dx + (rx - 0.5) / 16.0, dy + (ry - 0.5) / 16.0)
    }

    /// The lens offset of the `n`-th sample of a ray through image position (x, y) (POV-Ray's
    /// shifted coordinates): the grid point, jittered, on the lens axes.
    pub fn lens(&self, n: usize, x: f64, y: f64) -> DVec3 {
        let (jx, jy) = jitter2d(x, y);
        let g = self.grid[n];
        let a = self.radius * (g.x + jx * 2.0 * self.max_jitter);
        let b = self.radius * (g.y + jy * 2.0 * self.max_jitter);
        a * self.x_perp - b * self.y_perp
    }
}

/// POV-Ray's `Jitter2d`: two offsets in [−½, ½] hashed from a position.
pub fn jitter2d(x: f64, y: f64) -> (f64, f64) {
    let h = |a: f64, b: f64| {
        let i = pseudo_random(pseudo_random(a as i32) ^ b as i32);
        f64::from(JITTER[(i & 0xFF) as usize])
    };
    (h(1021.0 * x, 1019.0 * y), h(1019.0 * x, 1021.0 * y))
}

/// `ln Γ(a)` (Lanczos, g = 7).
fn ln_gamma(a: f64) -> f64 {
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if a < 0.5 {
        return (std::f64::consts::PI / (std::f64::consts::PI * a).sin()).ln() - ln_gamma(1.0 - a);
    }
    let a = a - 1.0;
    let t = a + 7.5;
    let sum = C[0] + (1..9).map(|i| C[i] / (a + i as f64)).sum::<f64>();
    0.5 * (2.0 * std::f64::consts::PI).ln() + (a + 0.5) * t.ln() - t + sum.ln()
}

/// The regularised upper incomplete gamma function Q(a, x) (series below a + 1, continued
/// fraction above).
fn upper_gamma(a: f64, x: f64) -> f64 {
    if x <= 0.0 {
        return 1.0;
    }
    let lead = (-x + a * x.ln() - ln_gamma(a)).exp();
    if x < a + 1.0 {
        let (mut term, mut sum, mut n) = (1.0 / a, 1.0 / a, a);
        for _ in 0..500 {
            n += 1.0;
            term *= x / n;
            sum += term;
            if term.abs() < sum.abs() * 1e-16 {
                break;
            }
        }
        1.0 - sum * lead
    } else {
        // Lentz's method on the continued fraction.
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..500 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let step = d * c;
            h *= step;
            if (step - 1.0).abs() < 1e-16 {
                break;
            }
        }
        lead * h
    }
}

/// The x with P(χ²_df > x) = `p` (Cephes' `chdtri`, as POV-Ray calls it).
pub fn chi_square_quantile(df: f64, p: f64) -> f64 {
    let tail = |x: f64| upper_gamma(df / 2.0, x / 2.0);
    let (mut lo, mut hi) = (0.0, df.max(1.0));
    while tail(hi) > p {
        hi *= 2.0;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if tail(mid) > p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Chi-square quantiles at POV-Ray's default confidence 0.9 (upper-tail probability).
    #[test]
    fn chi_square_quantiles() {
        for (df, q) in [(1.0, 0.0158), (2.0, 0.2107), (6.0, 2.204), (36.0, 25.643)] {
            let x = chi_square_quantile(df, 0.9);
            assert!((x - q).abs() < 2e-3 * q.max(1.0), "df {df}: {x}");
        }
    }

    /// More samples than the 37-point grid: the rest come from the Halton disc, inside it.
    #[test]
    fn lens_grids() {
        let b = |n| {
            let f = FocalBlur {
                aperture: 1.0,
                min_samples: 0,
                max_samples: n,
                focal_distance: 5.0,
                confidence: 0.9,
                variance: 1e-4,
            };
            Blur::new(&f, DVec3::Z, DVec3::Y)
        };
        assert_eq!(b(7).grid.len(), 7);
        let big = b(100);
        assert_eq!(big.grid.len(), 100);
        assert!(big.grid.iter().all(|p| p.length() <= 0.5 + 1e-9));
        assert_eq!(big.thresholds.len(), 100);
        assert!(big.thresholds.windows(2).all(|w| w[0] < w[1]));
        let (jx, jy) = jitter2d(0.3, -1.7);
        assert!(jx.abs() <= 0.5 && jy.abs() <= 0.5);
    }
}
