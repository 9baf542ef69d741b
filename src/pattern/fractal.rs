//! The escape-time fractal patterns `mandel`, `julia` and `magnet`, as POV-Ray 3.7.0 computes
//! them.
//!
//! All of them look at the x-y plane only: the point's x and y are the real and imaginary
//! parts of a complex number and z is ignored. The orbit of the iteration is followed for at
//! most `iterations` steps. A point whose orbit escapes gets the *exterior* value, computed
//! from the step at which it escaped and from the orbit's last point; a point whose orbit
//! stays bounded gets the *interior* value, computed from the orbit's last point and from the
//! smallest squared distance to the origin seen along the way.
//!
//! * `mandel N`: z₀ = p, z → zᵉ + p; escape when |z|² > 4.
//! * `julia <cr, ci>, N`: z₀ = p, z → zᵉ + c; escape when |z|² > 4.
//! * `magnet 1 mandel N`, `magnet 2 mandel N`: z₀ = 0 with parameter p; `magnet 1 julia <c>, N`
//!   and `magnet 2 julia <c>, N`: z₀ = p with parameter c. Formula 1 iterates
//!   z → ((z² + c − 1) / (2z + c − 2))², formula 2 iterates
//!   z → ((z³ + 3(c − 1)z + (c − 1)(c − 2)) / (3z² + 3(c − 2)z + (c − 1)(c − 2) + 1))².
//!   The orbit escapes when |z|² > 10000 or when it comes within 0.01 of the fixed point 1.
//!
//! The expressions keep POV-Ray's order of operations, so the values are the same doubles as
//! POV-Ray's (the exponents above 4 use the C library's `pow`, as POV-Ray does). The value is
//! the raw one: like any pattern's, it then goes through the pattern's wave (frequency,
//! phase, wrapping into [0, 1]).
//!
//! What POV-Ray's parser does before these numbers reach the pattern:
//! * the iteration count, the exponent and the two type numbers are truncated toward zero
//!   (`exponent 3.9` is 3); the types are then kept in a byte, so `exterior 257, f` is
//!   exterior type 1 and `interior -250, f` is interior type 6;
//! * `interior` accepts types 0 ..= 6; `exterior` accepts 0 ..= 8 in pigments, normals,
//!   textures and densities but only 0 ..= 6 in `function { pattern { … } }`;
//! * an exponent outside 2 ..= 33 draws a warning and means 2; `exponent` after `magnet` is
//!   an error, and `magnet` accepts only formulas 1 and 2;
//! * in a pigment (not in a pattern function) a second `exponent` after one of 5 ..= 33 is a
//!   parse error.

/// The largest `exponent` of `mandel` and `julia`; a value outside
/// [`MIN_EXPONENT`]`..=`[`MAX_EXPONENT`] means exponent 2 (POV-Ray warns and uses 2).
pub const MAX_EXPONENT: i32 = 33;

/// The smallest `exponent` of `mandel` and `julia`.
pub const MIN_EXPONENT: i32 = 2;

/// The largest interior type (`interior 0 ..= 6, factor`).
pub const MAX_INTERIOR_TYPE: i32 = 6;

/// The largest exterior type (`exterior 0 ..= 8, factor`).
pub const MAX_EXTERIOR_TYPE: i32 = 8;

/// Row `n` holds the coefficients of the terms aⁿ⁻ᵏ·bᵏ of (a + bi)ⁿ with the sign of iᵏ folded
/// in: C(n, k) when k mod 4 is 0 or 1, −C(n, k) when it is 2 or 3. The even k make up the
/// real part, the odd k the imaginary part. C(33, 16) still fits an `i32`.
const SIGNED_BINOMIALS: [[i32; 34]; 34] = signed_binomials();

const fn signed_binomials() -> [[i32; 34]; 34] {
    let mut rows = [[0; 34]; 34];
    let mut n = 0;
    while n < 34 {
        rows[n][0] = 1;
        rows[n][n] = 1;
        let mut k = 1;
        while k < n {
            rows[n][k] = rows[n - 1][k - 1] + rows[n - 1][k];
            k += 1;
        }
        n += 1;
    }
    let mut n = 0;
    while n < 34 {
        let mut k = 0;
        while k <= n {
            if k & 2 != 0 {
                rows[n][k] = -rows[n][k];
            }
            k += 1;
        }
        n += 1;
    }
    rows
}

/// Which fractal, with its complex parameter where it has one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FractalKind {
    /// `mandel N`.
    Mandel,
    /// `julia <cr, ci>, N`.
    Julia {
        /// The constant added at each step (real, imaginary).
        c: [f64; 2],
    },
    /// `magnet 1|2 mandel N` (`julia` is `None`) or `magnet 1|2 julia <cr, ci>, N`.
    Magnet {
        /// The formula: 2 for magnet 2, anything else (POV-Ray accepts only 1) for magnet 1.
        kind: u8,
        /// The julia variant's constant (real, imaginary).
        julia: Option<[f64; 2]>,
    },
}

/// A fractal pattern with its options.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fractal {
    /// The fractal.
    pub kind: FractalKind,
    /// The most steps followed (POV-Ray truncates the number it reads toward zero). A negative
    /// count gives 0 everywhere (POV-Ray returns an uninitialised value there).
    pub iterations: i32,
    /// `exponent E` of `mandel` and `julia`: 2 ..= 33, any other value meaning 2. POV-Ray sets
    /// it to 2 for these and refuses `exponent` with `magnet`, which ignores it.
    pub exponent: i32,
    /// `interior TYPE, FACTOR` (default 0, 1):
    /// 0: factor; 1: √(smallest |z|²) · factor; 2: re z · factor; 3: im z · factor;
    /// 4: (re z)² · factor; 5: (im z)² · factor; 6: (re z)² + (im z)² · factor (only the
    /// imaginary part is scaled, as in POV-Ray). Another type gives 0.
    pub interior: (i32, f64),
    /// `exterior TYPE, FACTOR` (default 1, 1), with n the 0-based step at which the orbit
    /// escaped and z its point there:
    /// 0: factor; 1: n / iterations; 2: re z · factor; 3: im z · factor; 4: (re z)² · factor;
    /// 5: (im z)² · factor; 6: |z| · factor; 7: (n mod ⌊factor⌋) / factor;
    /// 8: (n mod ⌊1 + factor⌋) / factor. For 7 and 8 the modulus is truncated to an unsigned
    /// 32-bit integer as POV-Ray's x86-64 build does it (a negative one wraps around, leaving
    /// n as it is); a modulus of 0 gives 0 (POV-Ray dies of a division by zero). Another type
    /// gives 0.
    pub exterior: (i32, f64),
}

/// How an orbit ended.
enum Orbit {
    /// It escaped at 0-based step `step`, at `z`.
    Escaped { step: i32, z: [f64; 2] },
    /// It stayed bounded; `z` is its last point and `closest` the smallest |z|² seen.
    Bounded { z: [f64; 2], closest: f64 },
}

impl Fractal {
    /// A fractal with POV-Ray's defaults: exponent 2 (0 for `magnet`, which has none),
    /// interior type 0 with factor 1, exterior type 1 with factor 1.
    pub fn new(kind: FractalKind, iterations: i32) -> Fractal {
        let exponent = match kind {
            FractalKind::Magnet { .. } => 0,
            _ => 2,
        };
        Fractal {
            kind,
            iterations,
            exponent,
            interior: (0, 1.0),
            exterior: (1, 1.0),
        }
    }

    /// The pattern's value at `p` (z is ignored). Not confined to [0, 1]: types 2 to 6 of
    /// the interior and exterior can give any value.
    pub fn value(&self, p: [f64; 3]) -> f64 {
        if self.iterations < 0 {
            return 0.0;
        }
        let point = [p[0], p[1]];
        let orbit = match self.kind {
            FractalKind::Mandel => self.power_orbit(point, point),
            FractalKind::Julia { c } => self.power_orbit(point, c),
            FractalKind::Magnet { kind, julia } => {
                let (start, c, closest) = match julia {
                    Some(c) => (point, c, point[0] * point[0] + point[1] * point[1]),
                    None => ([0.0, 0.0], point, 10000.0),
                };
                if kind == 2 {
                    let constants = MagnetTwoConstants::new(c);
                    self.orbit(
                        start,
                        closest,
                        |z, sq| constants.step(z, sq),
                        magnet_escaped,
                    )
                } else {
                    self.orbit(
                        start,
                        closest,
                        |z, sq| magnet_one_step(z, sq, c),
                        magnet_escaped,
                    )
                }
            }
        };
        match orbit {
            Orbit::Escaped { step, z } => self.exterior_value(step, z),
            Orbit::Bounded { z, closest } => self.interior_value(z, closest),
        }
    }

    /// The orbit of z → zᵉ + c from `start`.
    fn power_orbit(&self, start: [f64; 2], c: [f64; 2]) -> Orbit {
        let closest = start[0] * start[0] + start[1] * start[1];
        let escaped = |_: [f64; 2], _: [f64; 2], dist2: f64| dist2 > 4.0;
        match self.exponent {
            3 => self.orbit(start, closest, |z, sq| cube_step(z, sq, c), escaped),
            4 => self.orbit(start, closest, |z, sq| fourth_power_step(z, sq, c), escaped),
            e @ 5..=MAX_EXPONENT => {
                // The range pattern guarantees 5 <= e <= 33.
                let coefficients = &SIGNED_BINOMIALS[e as usize];
                self.orbit(
                    start,
                    closest,
                    |z, _| power_step(z, e, coefficients, c),
                    escaped,
                )
            }
            _ => self.orbit(start, closest, |z, sq| square_step(z, sq, c), escaped),
        }
    }

    /// Follows the orbit from `start` for at most `iterations` steps. `step` maps a point and
    /// its squared components to the next point; `escaped` judges a new point from itself,
    /// its squared components and its squared modulus.
    fn orbit(
        &self,
        start: [f64; 2],
        mut closest: f64,
        step: impl Fn([f64; 2], [f64; 2]) -> [f64; 2],
        escaped: impl Fn([f64; 2], [f64; 2], f64) -> bool,
    ) -> Orbit {
        let mut z = start;
        let mut sq = [z[0] * z[0], z[1] * z[1]];
        for n in 0..self.iterations {
            z = step(z, sq);
            sq = [z[0] * z[0], z[1] * z[1]];
            let dist2 = sq[0] + sq[1];
            if dist2 < closest {
                closest = dist2;
            }
            if escaped(z, sq, dist2) {
                return Orbit::Escaped { step: n, z };
            }
        }
        Orbit::Bounded { z, closest }
    }

    /// The value of a point whose orbit stayed bounded.
    fn interior_value(&self, [a, b]: [f64; 2], closest: f64) -> f64 {
        let (kind, factor) = self.interior;
        match kind {
            0 => factor,
            1 => closest.sqrt() * factor,
            2 => a * factor,
            3 => b * factor,
            4 => a * a * factor,
            5 => b * b * factor,
            6 => a * a + b * b * factor,
            _ => 0.0,
        }
    }

    /// The value of a point whose orbit escaped at 0-based step `step`.
    fn exterior_value(&self, step: i32, [a, b]: [f64; 2]) -> f64 {
        let (kind, factor) = self.exterior;
        match kind {
            0 => factor,
            1 => f64::from(step) / f64::from(self.iterations),
            2 => a * factor,
            3 => b * factor,
            4 => a * a * factor,
            5 => b * b * factor,
            6 => (a * a + b * b).sqrt() * factor,
            7 => step_cycle(step, factor, factor),
            8 => step_cycle(step, 1.0 + factor, factor),
            _ => 0.0,
        }
    }
}

/// (step mod m) / divisor, where m is `modulus` converted to an unsigned 32-bit integer the
/// way POV-Ray's x86-64 build converts it (truncation, a negative value wrapping around).
fn step_cycle(step: i32, modulus: f64, divisor: f64) -> f64 {
    // The step is never negative, and the wrapping of the modulus is intended.
    let m = modulus as i64 as u32;
    match (step as u32).checked_rem(m) {
        Some(r) => f64::from(r) / divisor,
        None => 0.0,
    }
}

/// z² + c, given z's squared components.
fn square_step([a, b]: [f64; 2], [a2, b2]: [f64; 2], [cr, ci]: [f64; 2]) -> [f64; 2] {
    let im = 2.0 * a * b + ci;
    let re = a2 - b2 + cr;
    [re, im]
}

/// z³ + c, given z's squared components.
fn cube_step([a, b]: [f64; 2], [a2, b2]: [f64; 2], [cr, ci]: [f64; 2]) -> [f64; 2] {
    let im = 3.0 * a2 * b - b2 * b + ci;
    let re = a2 * a - 3.0 * a * b2 + cr;
    [re, im]
}

/// z⁴ + c, given z's squared components.
fn fourth_power_step([a, b]: [f64; 2], [a2, b2]: [f64; 2], [cr, ci]: [f64; 2]) -> [f64; 2] {
    let im = 4.0 * (a2 * a * b - a * b2 * b) + ci;
    let re = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
    [re, im]
}

/// zᵉ + c by the binomial expansion, each power through `pow`; `coefficients` is row `e` of
/// [`SIGNED_BINOMIALS`].
fn power_step([a, b]: [f64; 2], e: i32, coefficients: &[i32; 34], [cr, ci]: [f64; 2]) -> [f64; 2] {
    let term = |k: i32| {
        // 0 <= k <= e <= 33.
        let coefficient = f64::from(coefficients[k as usize]);
        coefficient * a.powf(f64::from(e - k)) * b.powf(f64::from(k))
    };
    let mut re = a.powf(f64::from(e));
    for k in (2..=e).step_by(2) {
        re += term(k);
    }
    let mut im = 0.0;
    for k in (1..=e).step_by(2) {
        im += term(k);
    }
    [re + cr, im + ci]
}

/// The square of the quotient w = u / v as the magnet formulas form it.
fn squared_quotient([ur, ui]: [f64; 2], [vr, vi]: [f64; 2]) -> [f64; 2] {
    let norm = vr * vr + vi * vi;
    let wr = (ur * vr + ui * vi) / norm;
    let wi = (ui * vr - ur * vi) / norm;
    let wi2 = wi * wi;
    let im = 2.0 * wr * wi;
    [wr * wr - wi2, im]
}

/// One step of magnet formula 1 with parameter c, given z's squared components.
fn magnet_one_step([a, b]: [f64; 2], [a2, b2]: [f64; 2], [cr, ci]: [f64; 2]) -> [f64; 2] {
    let numerator = [a2 - b2 + cr - 1.0, 2.0 * a * b + ci];
    let denominator = [2.0 * a + cr - 2.0, 2.0 * b + ci];
    squared_quotient(numerator, denominator)
}

/// The parts of magnet formula 2 that depend on its parameter c only.
struct MagnetTwoConstants {
    /// Re(c − 1).
    c1: f64,
    /// Re(c − 2).
    c2: f64,
    /// Im c (the same for c − 1 and c − 2).
    ci: f64,
    /// (c − 1)(c − 2).
    product: [f64; 2],
}

impl MagnetTwoConstants {
    fn new([cr, ci]: [f64; 2]) -> MagnetTwoConstants {
        let c1 = cr - 1.0;
        let c2 = cr - 2.0;
        MagnetTwoConstants {
            c1,
            c2,
            ci,
            product: [c1 * c2 - ci * ci, (c1 + c2) * ci],
        }
    }

    /// One step of magnet formula 2, given z's squared components.
    fn step(&self, [a, b]: [f64; 2], [a2, b2]: [f64; 2]) -> [f64; 2] {
        let (c1, c2, ci) = (self.c1, self.c2, self.ci);
        let [pr, pi] = self.product;
        let numerator = [
            a2 * a - 3.0 * a * b2 + 3.0 * (a * c1 - b * ci) + pr,
            3.0 * a2 * b - b2 * b + 3.0 * (a * ci + b * c1) + pi,
        ];
        let denominator = [
            3.0 * (a2 - b2) + 3.0 * (a * c2 - b * ci) + pr + 1.0,
            6.0 * a * b + 3.0 * (a * ci + b * c2) + pi,
        ];
        squared_quotient(numerator, denominator)
    }
}

/// The magnet formulas' escape test: far out, or within 0.01 of the fixed point 1.
fn magnet_escaped([a, _]: [f64; 2], [_, b2]: [f64; 2], dist2: f64) -> bool {
    let d = a - 1.0;
    dist2 > 10000.0 || d * d + b2 < 1.0 / 10000.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_close(got: f64, want: f64) {
        assert!(
            (got - want).abs() <= 1e-12 * want.abs().max(1.0),
            "got {got:e}, want {want:e}"
        );
    }

    fn with(kind: FractalKind, iterations: i32, change: impl Fn(&mut Fractal)) -> Fractal {
        let mut f = Fractal::new(kind, iterations);
        change(&mut f);
        f
    }

    /// Expected values are POV-Ray 3.7.0's (`function { pattern { … frequency 0 } }` printed
    /// with 20 decimals), at points with z = 0.5.
    #[test]
    fn values_match_povray() {
        let mandel = FractalKind::Mandel;
        let cases = [
            // mandel 30
            (Fractal::new(mandel, 30), [-0.1175, 0.95125], 0.4),
            // mandel 25 exponent 3 interior 1, 0.7
            (
                with(mandel, 25, |f| {
                    f.exponent = 3;
                    f.interior = (1, 0.7);
                }),
                [0.1875, 0.39625],
                0.268_636_540_455_190_75,
            ),
            // mandel 20 exponent 4 exterior 6, 0.55
            (
                with(mandel, 20, |f| {
                    f.exponent = 4;
                    f.exterior = (6, 0.55);
                }),
                [0.71375, 0.7625],
                1.573_641_036_548_165_5,
            ),
            // mandel 15 exponent 7 interior 6, 0.45
            (
                with(mandel, 15, |f| {
                    f.exponent = 7;
                    f.interior = (6, 0.45);
                }),
                [0.285, 0.02625],
                0.081_609_230_371_705_8,
            ),
            // julia <-0.4, 0.6>, 30 interior 2, 2.5
            (
                with(FractalKind::Julia { c: [-0.4, 0.6] }, 30, |f| {
                    f.interior = (2, 2.5)
                }),
                [0.57, -0.42125],
                0.150_881_697_554_342_83,
            ),
            // julia <0.35, -0.3>, 12 exponent 33 exterior 4, 0.3
            (
                with(FractalKind::Julia { c: [0.35, -0.3] }, 12, |f| {
                    f.exponent = 33;
                    f.exterior = (4, 0.3);
                }),
                [-0.97375, 0.2425],
                504_771.622_944_873_3,
            ),
            // magnet 1 mandel 30 exterior 3, 0.65
            (
                with(
                    FractalKind::Magnet {
                        kind: 1,
                        julia: None,
                    },
                    30,
                    |f| {
                        f.exterior = (3, 0.65);
                    },
                ),
                [1.93625, -1.97375],
                0.000_177_768_797_675_812_93,
            ),
            // magnet 2 julia <1.1, 0.3>, 30 interior 4, 0.6
            (
                with(
                    FractalKind::Magnet {
                        kind: 2,
                        julia: Some([1.1, 0.3]),
                    },
                    30,
                    |f| f.interior = (4, 0.6),
                ),
                [1.9675, 2.285],
                0.006_516_345_516_545_996,
            ),
            // magnet 1 julia <1.3, 0.4>, 30 exterior 5, 2.2
            (
                with(
                    FractalKind::Magnet {
                        kind: 1,
                        julia: Some([1.3, 0.4]),
                    },
                    30,
                    |f| f.exterior = (5, 2.2),
                ),
                [-0.8475, -2.2725],
                8_234_633.303_686_945,
            ),
            // magnet 2 mandel 30
            (
                Fractal::new(
                    FractalKind::Magnet {
                        kind: 2,
                        julia: None,
                    },
                    30,
                ),
                [1.69375, 0.27625],
                1.0 / 3.0,
            ),
        ];
        for (fractal, [x, y], want) in cases {
            assert_close(fractal.value([x, y, 0.5]), want);
        }
    }

    #[test]
    fn defaults_and_unsupported_exponents() {
        let f = Fractal::new(FractalKind::Mandel, 30);
        assert_eq!(
            (f.exponent, f.interior, f.exterior),
            (2, (0, 1.0), (1, 1.0))
        );
        // Exponents outside 2 ..= 33 fall back to 2.
        for e in [0, 1, 34, -3] {
            let g = with(FractalKind::Mandel, 30, |g| g.exponent = e);
            assert_eq!(
                g.value([-0.1175, 0.95125, 0.0]),
                f.value([-0.1175, 0.95125, 0.0])
            );
        }
    }

    #[test]
    fn signed_binomial_rows() {
        assert_eq!(SIGNED_BINOMIALS[5][..6], [1, 5, -10, -10, 5, 1]);
        assert_eq!(SIGNED_BINOMIALS[33][16], 1_166_803_110);
        assert_eq!(SIGNED_BINOMIALS[33][18], -1_037_158_320);
    }
}
