//! POV-Ray's built-in functions (`internal(N)`; functions.inc names them `f_sphere`,
//! `f_torus` …), written from POV-Ray 3.7's formulas and giving its values: the same
//! arithmetic in the same order, and its quirks kept (functions that move the point before
//! using it, C's integer divisions that are 0, C++'s `min`/`max`, C's `fmod`).

use super::MAX_LOOP_TERMS;
use crate::noise::{noise, trunc_i32};
use glam::DVec3;
use std::f64::consts::PI;

/// POV-Ray's built-in functions, numbered as POV-Ray numbers them (`internal(N)`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Internal {
    AlgbrCyl1 = 0,
    AlgbrCyl2,
    AlgbrCyl3,
    AlgbrCyl4,
    Bicorn,
    Bifolia,
    Blob,
    Blob2,
    BoySurface,
    Comma,
    CrossEllipsoids,
    CrossedTrough,
    CubicSaddle,
    Cushion,
    DevilsCurve,
    DevilsCurve2d,
    DupinCyclid,
    Ellipsoid,
    Enneper,
    FlangeCover,
    FoliumSurface,
    FoliumSurface2d,
    Glob,
    Heart,
    HelicalTorus,
    Helix1,
    Helix2,
    HexX,
    HexY,
    HeteroMf,
    HuntSurface,
    HyperbolicTorus,
    IsectEllipsoids,
    KampyleOfEudoxus,
    KampyleOfEudoxus2d,
    KleinBottle,
    KummerSurfaceV1,
    KummerSurfaceV2,
    LemniscateOfGerono,
    LemniscateOfGerono2d,
    Mesh1,
    Mitre,
    NodalCubic,
    Odd,
    OvalsOfCassini,
    Paraboloid,
    ParabolicTorus,
    Ph,
    Pillow,
    Piriform,
    Piriform2d,
    Poly4,
    Polytubes,
    Quantum,
    QuarticParaboloid,
    QuarticSaddle,
    QuarticCylinder,
    R,
    Ridge,
    RidgedMf,
    RoundedBox,
    Sphere,
    Spikes,
    Spikes2d,
    Spiral,
    SteinersRoman,
    Strophoid,
    Strophoid2d,
    Superellipsoid,
    Th,
    Torus,
    Torus2,
    TorusGumdrop,
    Umbrella,
    WitchOfAgnesi,
    WitchOfAgnesi2d,
    Noise3d,
    /// The pattern functions' own entry, which POV-Ray gives a pattern to: called as
    /// `internal(77)`, without one, it is 0, as in POV-Ray.
    Pattern,
    NoiseGenerator,
}

/// Every function in POV-Ray's order (its number is its place), with its parameter count
/// (beyond x, y, z).
const TABLE: [(Internal, usize); 79] = {
    use Internal::*;
    [
        (AlgbrCyl1, 5),
        (AlgbrCyl2, 5),
        (AlgbrCyl3, 5),
        (AlgbrCyl4, 5),
        (Bicorn, 2),
        (Bifolia, 2),
        (Blob, 5),
        (Blob2, 4),
        (BoySurface, 2),
        (Comma, 1),
        (CrossEllipsoids, 4),
        (CrossedTrough, 1),
        (CubicSaddle, 1),
        (Cushion, 1),
        (DevilsCurve, 1),
        (DevilsCurve2d, 6),
        (DupinCyclid, 6),
        (Ellipsoid, 3),
        (Enneper, 1),
        (FlangeCover, 4),
        (FoliumSurface, 3),
        (FoliumSurface2d, 6),
        (Glob, 1),
        (Heart, 1),
        (HelicalTorus, 10),
        (Helix1, 7),
        (Helix2, 7),
        (HexX, 1),
        (HexY, 1),
        (HeteroMf, 6),
        (HuntSurface, 1),
        (HyperbolicTorus, 3),
        (IsectEllipsoids, 4),
        (KampyleOfEudoxus, 3),
        (KampyleOfEudoxus2d, 6),
        (KleinBottle, 1),
        (KummerSurfaceV1, 1),
        (KummerSurfaceV2, 4),
        (LemniscateOfGerono, 1),
        (LemniscateOfGerono2d, 6),
        (Mesh1, 5),
        (Mitre, 1),
        (NodalCubic, 1),
        (Odd, 1),
        (OvalsOfCassini, 4),
        (Paraboloid, 1),
        (ParabolicTorus, 3),
        (Ph, 0),
        (Pillow, 1),
        (Piriform, 1),
        (Piriform2d, 7),
        (Poly4, 5),
        (Polytubes, 6),
        (Quantum, 1),
        (QuarticParaboloid, 1),
        (QuarticSaddle, 1),
        (QuarticCylinder, 3),
        (R, 0),
        (Ridge, 6),
        (RidgedMf, 6),
        (RoundedBox, 4),
        (Sphere, 1),
        (Spikes, 5),
        (Spikes2d, 4),
        (Spiral, 6),
        (SteinersRoman, 1),
        (Strophoid, 4),
        (Strophoid2d, 7),
        (Superellipsoid, 2),
        (Th, 0),
        (Torus, 2),
        (Torus2, 3),
        (TorusGumdrop, 1),
        (Umbrella, 1),
        (WitchOfAgnesi, 2),
        (WitchOfAgnesi2d, 6),
        (Noise3d, 0),
        (Pattern, 0),
        (NoiseGenerator, 1),
    ]
};

/// POV-Ray's π/180 and 2π.
const PI_180: f64 = PI / 180.0;
const TWO_PI: f64 = 2.0 * PI;

/// C++'s `std::max`: the first unless it is less than the second (so a NaN first stays).
fn max(a: f64, b: f64) -> f64 {
    if a < b { b } else { a }
}

/// C++'s `std::min`: the first unless the second is less (so a NaN first stays).
fn min(a: f64, b: f64) -> f64 {
    if b < a { b } else { a }
}

/// The scaled value `s r` kept within ±`limit`, as most of these functions end.
fn clamp(s: f64, r: f64, limit: f64) -> f64 {
    min(limit, max(s * r, -limit))
}

/// The ±10 clamp.
fn clamp10(s: f64, r: f64) -> f64 {
    clamp(s, r, 10.0)
}

/// The 2D functions' turn (when `on` > 0): the point's distance from the y axis less `d`
/// becomes x, and (x, y) turns by `angle` degrees. Gives the new x, y and their squares.
fn rot2d(x: f64, y: f64, z: f64, on: f64, d: f64, angle: f64) -> (f64, f64, f64, f64) {
    let (x, y) = if on > 0.0 {
        let r = (x * x + z * z).sqrt() - d;
        let th = angle * PI_180;
        if th != 0.0 {
            (r * th.cos() - y * th.sin(), r * th.sin() + y * th.cos())
        } else {
            (r, y)
        }
    } else {
        (x, y)
    };
    (x, y, x * x, y * y)
}

/// The helices' cross section of (a, b): a superellipse of exponent 2/`shape`, or a square
/// where `shape` is 0.
fn cross_section(a: f64, b: f64, shape: f64) -> f64 {
    if shape != 0.0 {
        let e = 2.0 / shape;
        (a.abs().powf(e) + b.abs().powf(e)).powf(shape * 0.5)
    } else {
        max(a.abs(), b.abs())
    }
}

/// The hexagonal cells' offsets (u, v) from the nearest cell centre in (x, y), folded into
/// one quadrant, and whether the angle of (u, v) is below 30°.
fn hex_cell(x: f64, y: f64) -> (f64, f64, bool) {
    let w = 3f64.sqrt();
    let u = ((x.abs() % w) - w / 2.0).abs();
    let v = ((y.abs() % 3.0) - 1.5).abs();
    let (u2, v2) = (w / 2.0 - u, 1.5 - v);
    let (u, v) = if u * u + v * v > u2 * u2 + v2 * v2 {
        (u2, v2)
    } else {
        (u, v)
    };
    (u, v, v.atan2(u) < PI / 6.0)
}

/// C's `(int)v` as a loop bound, at most [`MAX_LOOP_TERMS`] (a hostile count stops there).
fn count(v: f64) -> i32 {
    trunc_i32(v).min(MAX_LOOP_TERMS as i32)
}

/// The noise generator a parameter names: `(int)g & 3`.
fn generator_of(g: f64) -> u8 {
    (trunc_i32(g) & 3) as u8
}

/// x, or `nudge` where x and z are both 0 (as POV-Ray moves the point off the y axis before
/// taking an angle about it).
fn off_axis(x: f64, z: f64, nudge: f64) -> f64 {
    if x == 0.0 && z == 0.0 { nudge } else { x }
}

impl Internal {
    /// POV-Ray's number `n` (functions.inc's `internal(n)`), if it is one.
    pub fn numbered(n: i64) -> Option<Internal> {
        let f = TABLE.get(usize::try_from(n).ok()?)?.0;
        debug_assert_eq!(f as i64, n);
        Some(f)
    }

    /// How many values it takes (x, y, z and its parameters).
    pub fn arity(self) -> usize {
        3 + TABLE[self as usize].1
    }

    /// Its value for `a` (x, y, z, then its parameters), noise from `generator` where it
    /// takes no generator of its own.
    pub(super) fn apply(self, a: &[f64], generator: u8) -> f64 {
        use Internal::*;
        let (x, y, z) = (a[0], a[1], a[2]);
        let p = |i: usize| a[3 + i];
        let (x2, y2, z2) = (x * x, y * y, z * z);
        match self {
            AlgbrCyl1 => {
                let (x, _, x2, y2) = rot2d(x, y, z, p(2), p(3), p(4));
                let x = x.abs();
                -clamp(p(0), -(x2 * x - x2 + y2), p(1))
            }
            AlgbrCyl2 => {
                let (_, y, x2, y2) = rot2d(x, y, z, p(2), p(3), p(4));
                clamp(
                    p(0),
                    -(2.0 * x2 * x2 - 3.0 * x2 * y + y2 - 2.0 * y2 * y + y2 * y2),
                    p(1),
                )
            }
            AlgbrCyl3 => {
                let (x, y, x2, y2) = rot2d(x, y, z, p(2), p(3), p(4));
                clamp(
                    p(0),
                    -(x2 * x2 + x2 * y2 - 2.0 * x2 * y - x * y2 + y2),
                    p(1),
                )
            }
            AlgbrCyl4 => {
                let (_, y, x2, y2) = rot2d(x, y, z, p(2), p(3), p(4));
                clamp(
                    p(0),
                    -(x2 * x2 + y2 * y2 + 2.0 * x2 * y2 + 3.0 * x2 * y - y2 * y),
                    p(1),
                )
            }
            Bicorn => {
                let r = p(1) * p(1);
                let s = x2 + z2 + 2.0 * p(1) * y - r;
                clamp10(p(0), y2 * (r - (x2 + z2)) - s * s)
            }
            Bifolia => {
                let r = x2 + y * y + z2;
                clamp10(p(0), -(r * r - p(1) * (x2 + z2) * y))
            }
            Blob => {
                let h = p(0) * 0.5;
                let near = min(((x + h) * (x + h) + y2 + z2) * p(2) * p(2), 1.0);
                let far = min(((x - h) * (x - h) + y2 + z2) * p(4) * p(4), 1.0);
                -(p(1) * (1.0 - near) * (1.0 - near) + p(3) * (1.0 - far) * (1.0 - far))
            }
            Blob2 => {
                let r = (-(x2 + y2 + z2) * p(1)).exp()
                    + (-((x - p(0)) * (x - p(0)) + y2 + z2) * p(1)).exp();
                p(3) - r * p(2)
            }
            BoySurface => {
                let (w, ph) = (1.0 - z, x2 + y2);
                let s2 = 2f64.sqrt();
                let r = p(1)
                    * (64.0 * w * w * w * z2 * z
                        - 48.0 * w * w * z2 * (3.0 * x2 + 3.0 * y2 + 2.0 * z2)
                        + 12.0
                            * w
                            * z
                            * (27.0 * ph * ph - 24.0 * z2 * ph
                                + 36.0 * s2 * y * z * (y2 - 3.0 * x2)
                                + 4.0 * z2 * z2)
                        + (9.0 * x2 + 9.0 * y2 - 2.0 * z2)
                            * (-81.0 * ph * ph - 72.0 * z2 * ph
                                + 108.0 * s2 * x * z * (x2 - 3.0 * y2)
                                + 4.0 * z2 * z2));
                clamp10(p(0), r)
            }
            Comma => {
                let x = off_axis(x, z, 0.0001);
                let th = z.atan2(x);
                let q = p(0) * 0.25;
                let r = ((x + q) * (x + q) + z * z).sqrt();
                let t = p(0) * 0.75;
                let tail = (th * 0.5).cos() * p(0) * 0.5 - ((r - t) * (r - t) + y * y).sqrt();
                let tail = min(z, tail);
                let h = p(0) * 0.5;
                let head = h - ((x - h) * (x - h) + z * z + y * y).sqrt();
                -max(tail, head)
            }
            CrossEllipsoids => {
                let r = max(
                    (-(x2 * p(0) + y2 * p(0) + z2) * p(1)).exp(),
                    (-(x2 * p(0) + y2 + z2 * p(0)) * p(1)).exp(),
                );
                let r = max(r, (-(x2 + y2 * p(0) + z2 * p(0)) * p(1)).exp());
                p(3) - r * p(2)
            }
            CrossedTrough => clamp10(p(0), x * x * z * z - y),
            CubicSaddle => clamp10(p(0), -(x * x * x - y * y * y - z)),
            Cushion => clamp10(
                p(0),
                z2 * x2 - z2 * z2 - 2.0 * z * x2 + 2.0 * z2 * z + x2
                    - z2
                    - (x2 - z) * (x2 - z)
                    - y2 * y2
                    - 2.0 * x2 * y2
                    - y2 * z2
                    + 2.0 * y2 * z
                    + y2,
            ),
            DevilsCurve => clamp10(
                p(0),
                -(x2 * x2 + 2.0 * x2 * z2 - 0.36 * x2 - y2 * y2 + 0.25 * y2 + z2 * z2),
            ),
            DevilsCurve2d => {
                let (_, _, x2, y2) = rot2d(x, y, z, p(3), p(4), p(5));
                clamp10(p(0), -(x2 * (x2 - p(1) * p(1)) - y2 * (y2 - p(2) * p(2))))
            }
            DupinCyclid => {
                let (a, b, c, d) = (p(1), p(2), p(3), p(4));
                let r2 = p(5) * p(5);
                let (b2, d2) = (b * b, d * d);
                let e = b2 - d2 - (c + a) * (c + a);
                let f = b2 - d2 - (c - a) * (c - a);
                let (c2, a2) = (c * c, a * a);
                let r = -(e * f * (x2 * x2 + y2 * y2 + z2 * z2)
                    + 2.0 * (e * f * (x2 * y2 + x2 * z2 + y2 * z2))
                    + 2.0
                        * r2
                        * ((-d2 - c2 + b2 + a2) * (2.0 * x * c + 2.0 * y * d - r2)
                            - 4.0 * d * b2 * y)
                        * (x2 + y2 + z2)
                    + 4.0 * r2 * r2 * (c * x + d * y) * (-r2 + d * y + c * x)
                    + 4.0 * r2 * r2 * a2 * y2
                    + r2 * r2 * r2 * r2);
                clamp10(p(0), r)
            }
            Ellipsoid => (x2 * p(0) * p(0) + y2 * p(1) * p(1) + z2 * p(2) * p(2)).sqrt(),
            Enneper => {
                let z = if z.abs() < 0.2 { 0.2 } else { z };
                // POV-Ray writes 2/3, 1/4, 8/9 and 2/9 here: integer divisions, all 0.
                let zero = 0.0;
                let r = (y2 - x2) / (2.0 * z) + 2.0 * z2 / 9.0 + zero;
                let s = (y2 - x2) / (4.0 * z) - zero * (x2 + y2 + zero * z2) + zero;
                clamp10(p(0), -(r * r * r - 6.0 * s * s))
            }
            FlangeCover => {
                let r = (-(x2 * p(0) + y2 * p(0) + z2) * p(1)).exp()
                    + (-(x2 * p(0) + y2 + z2 * p(0)) * p(1)).exp()
                    + (-(x2 + y2 * p(0) + z2 * p(0)) * p(1)).exp();
                p(3) - r * p(2)
            }
            FoliumSurface => clamp10(
                p(0),
                (y2 + z2) * (1.0 + (p(2) - 4.0 * p(1)) * x) + x2 * (1.0 + p(2)),
            ),
            FoliumSurface2d => {
                let (x, _, x2, y2) = rot2d(x, y, z, p(3), p(4), p(5));
                clamp10(
                    p(0),
                    -(y2 * (1.0 + (p(2) - 4.0 * p(1)) * x) + x2 * (1.0 + p(2))),
                )
            }
            Glob => clamp10(p(0), 0.5 * x2 * x2 * x + 0.5 * x2 * x2 - (y * y + z * z)),
            Heart => {
                let s = 2.0 * x2 + y2 + z2 - 1.0;
                clamp10(p(0), -(s * s * s - 0.1 * x2 * z2 * z - y2 * z2 * z))
            }
            HelicalTorus => {
                let rxz = (x2 + z2).sqrt();
                let x = off_axis(x, z, 0.000001);
                let ph = x.atan2(z);
                let around = (rxz - p(0)).atan2(y);
                let r = ((rxz - p(0)) * (rxz - p(0)) + y * y).sqrt();
                let mut th = (ph * p(1) + around * p(2)) % TWO_PI;
                if th < 0.0 {
                    th += TWO_PI;
                }
                let t = ((th - PI) * p(8)).atan2(r - p(5));
                let t = (t * p(7) + ph * p(9)).cos() * p(3) + p(4);
                let inner = p(4) + p(5) - p(0) - rxz;
                let th = th - PI;
                let t = t - min(((r - p(5)) * (r - p(5)) + th * th * p(6)).sqrt(), r + p(5));
                -max(inner, t)
            }
            Helix1 => {
                let r = (x2 + z2).sqrt();
                let x = off_axis(x, z, 0.000001);
                let mut th = (z.atan2(x) * p(0) + y * p(1) * p(0)) % TWO_PI;
                if th < 0.0 {
                    th += TWO_PI;
                }
                let mut v = (th - PI) / p(4) / (p(1) * p(0));
                let mut u = r - p(3);
                let d = if p(5) == 1.0 {
                    (u * u + v * v).sqrt()
                } else {
                    if p(6) != 0.0 {
                        let (c, s) = ((p(6) * PI_180).cos(), (p(6) * PI_180).sin());
                        (u, v) = (u * c - v * s, u * s + v * c);
                    }
                    cross_section(u, v, p(5))
                };
                -p(2) + min(p(3) + r, d)
            }
            Helix2 => {
                let t = y * p(1);
                let (c, s) = (t.cos(), t.sin());
                let (dx, dz) = (x - p(3) * c, z - p(3) * s);
                let (u, v) = (dx * c + dz * s, -dx * s + dz * c);
                if p(5) == 1.0 {
                    (u * u + v * v).sqrt() - p(2)
                } else {
                    cross_section(u, v, p(5)) - p(2)
                }
            }
            HexX => match hex_cell(x, y) {
                (u, _, true) => u,
                (u, v, false) => (PI / 3.0).cos() * u + (PI / 3.0).sin() * v,
            },
            HexY => match hex_cell(x, y) {
                (_, v, true) => v,
                (u, v, false) => (-(PI / 3.0).sin() * u + (PI / 3.0).cos() * v).abs(),
            },
            HeteroMf => {
                let g = generator_of(p(5));
                let mut q = DVec3::new(x, y, z);
                let mut signal = (noise(q, g) * 2.0 - 1.0) + p(3);
                q *= p(1);
                let step = p(1).powf(-p(0));
                let mut weight = step;
                let mut i = 1;
                while f64::from(i) < p(2) && i < MAX_LOOP_TERMS as i32 {
                    let mut inc = ((noise(q, g) * 2.0 - 1.0) + p(3)) * weight;
                    for _ in 0..count(p(4)) {
                        inc *= signal;
                    }
                    signal += inc;
                    q *= p(1);
                    weight *= step;
                    i += 1;
                }
                let rem = p(2) - f64::from(trunc_i32(p(2)));
                if rem != 0.0 {
                    let inc = ((noise(q, g) * 2.0 - 1.0) + p(3)) * weight;
                    signal += rem * inc * signal;
                }
                signal
            }
            HuntSurface => {
                let s = x2 + y2 + z2 - 13.0;
                let t = 3.0 * x2 + y2 - 4.0 * z2 - 12.0;
                clamp10(p(0), -(4.0 * s * s * s + 27.0 * t * t))
            }
            HyperbolicTorus => {
                let (a, b) = (p(1) * p(1), p(2) * p(2));
                let r = -(x2 * x2 + 2.0 * x2 * y2 - 2.0 * x2 * z2 - 2.0 * (a + b) * x2 + y2 * y2
                    - 2.0 * y2 * z2
                    + 2.0 * (a - b) * y2
                    + z2 * z2
                    + 2.0 * (a + b) * z2
                    + (a - b) * (a - b));
                clamp10(p(0), r)
            }
            IsectEllipsoids => {
                let r = min(
                    (-(x2 * p(0) + y2 * p(0) + z2) * p(1)).exp(),
                    (-(x2 * p(0) + y2 + z2 * p(0)) * p(1)).exp(),
                );
                let r = min(r, (-(x2 + y2 * p(0) + z2 * p(0)) * p(1)).exp());
                p(3) - r * p(2)
            }
            KampyleOfEudoxus => clamp10(
                p(0),
                -((y * y + z * z) - p(2) * p(2) * x2 * x2 + p(2) * p(2) * p(1) * p(1) * x2),
            ),
            KampyleOfEudoxus2d => {
                let (_, _, x2, y2) = rot2d(x, y, z, p(3), p(4), p(5));
                // (p1 p2 where the 3D function has p1 p1, as in POV-Ray.)
                clamp10(
                    p(0),
                    -(y2 - p(2) * p(2) * x2 * x2 + p(2) * p(2) * p(1) * p(2) * x2),
                )
            }
            KleinBottle => {
                let s = x2 + y2 + z2;
                let r = -((s + 2.0 * y - 1.0)
                    * ((s - 2.0 * y - 1.0) * (s - 2.0 * y - 1.0) - 8.0 * z2)
                    + 16.0 * x * z * (s - 2.0 * y - 1.0));
                clamp10(p(0), r)
            }
            KummerSurfaceV1 => clamp10(
                p(0),
                -(x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2 - x2 * y2 - x2 * z2 - y2 * z2 + 1.0),
            ),
            KummerSurfaceV2 => clamp10(
                p(0),
                -(x2 * x2
                    + y2 * y2
                    + z2 * z2
                    + p(1) * (x2 + y2 + z2)
                    + p(2) * (x2 * y2 + x2 * z2 + y2 * z2)
                    + p(3) * x * y * z
                    - 1.0),
            ),
            LemniscateOfGerono => clamp10(p(0), -(x2 * x2 - x2 + y2 + z2)),
            LemniscateOfGerono2d => {
                let (_, _, x2, y2) = rot2d(x, y, z, p(3), p(4), p(5));
                clamp10(
                    p(0),
                    -(y2 - p(2) * p(2) * p(1) * p(1) * x2 + p(2) * p(2) * x2 * x2),
                )
            }
            Mesh1 => {
                let (dx, dz) = (p(0), p(1));
                let (fx, fz) = (PI / dx, PI / dz);
                // The distance to one family of threads: across the cells (period 2 `d`
                // along `u`, offset `shift`), and along y from a cosine wave.
                let thread = |u: f64, shift: f64, d: f64, wave: f64| {
                    let mut r = (u - shift) % (d * 2.0);
                    if r < 0.0 {
                        r += d * 2.0;
                    }
                    let r = (r - d).abs() * p(2);
                    let h = (y + wave) * p(4);
                    -(h * h + r * r).sqrt()
                };
                let t = thread(x, 0.0, dx, -(z * fz).cos() * p(3));
                let t = max(thread(x, dx, dx, (z * fz).cos() * p(3)), t);
                let t = max(thread(z, 0.0, dz, (x * fx).cos() * p(3)), t);
                -max(thread(z, dz, dz, -(x * fx).cos() * p(3)), t)
            }
            Mitre => clamp10(p(0), -(4.0 * x2 * (x2 + y2 + z2) - y2 * (1.0 - y2 - z2))),
            NodalCubic => clamp10(p(0), -(y * y * y + z * z * z - 6.0 * y * z)),
            Odd => clamp10(
                p(0),
                z2 * x2 - z2 * z2 - 2.0 * z * x2 + 2.0 * z2 * z + x2
                    - z2
                    - (x2 - z) * (x2 - z)
                    - y2 * y2
                    - 2.0 * y2 * x2
                    - y2 * z2
                    + 2.0 * y2 * z
                    + y2,
            ),
            OvalsOfCassini => {
                let s = x2 + y2 + z2 + p(1) * p(1);
                clamp10(
                    p(0),
                    -(s * s - p(3) * p(1) * p(1) * (x2 + z2) - p(2) * p(2)),
                )
            }
            Paraboloid => clamp10(p(0), -(x * x - y + z * z)),
            ParabolicTorus => {
                let (a, b) = (p(1) * p(1), p(2) * p(2));
                let r = -(x2 * x2 + 2.0 * x2 * y2 - 2.0 * x2 * z - (a + b) * x2 + y2 * y2
                    - 2.0 * y2 * z
                    + (a - b) * y2
                    + z2
                    + (a + b) * z
                    + (a - b) * (a - b));
                clamp10(p(0), r)
            }
            Ph => (x2 + z2).sqrt().atan2(y),
            Pillow => clamp10(p(0), x2 * x2 + y2 * y2 + z2 * z2 - (x2 + y2 + z2)),
            Piriform => -clamp10(p(0), -((x2 * x2 - x2 * x) + y * y + z * z)),
            Piriform2d => {
                let (x, y, x2, _) = rot2d(x, y, z, p(4), p(5), p(6));
                clamp10(
                    p(0),
                    -(y * y - p(1) * p(3) * p(3) * x2 * x - p(2) * p(3) * p(3) * x2 * x2),
                )
            }
            Poly4 => {
                let h = p(0) + p(1) * y + p(2) * y2 + p(3) * y2 * y + p(4) * y2 * y2;
                let h = if h < -5.0 { -5.0 } else { h };
                -h + (x * x + z * z).sqrt()
            }
            Polytubes => {
                let r = p(1) + p(2) * y + p(3) * y2 + p(4) * y2 * y + p(5) * y2 * y2;
                let mut d = -10000.0;
                for i in 0..count(p(0)) {
                    let angle = 2.0 * PI / p(0) * f64::from(i);
                    let (u, v) = (x - r * angle.sin(), z - r * angle.cos());
                    d = max(d, -(u * u + v * v).sqrt());
                }
                -d
            }
            Quantum => {
                let x = off_axis(x, z, 1e-6);
                let r = (x * x + z * z).sqrt();
                let c = r.atan2(y).cos();
                let r = (r * r + y * y).sqrt() * 2.0;
                let t = r * r * (-r * 0.33333333).exp() * (3.0 * c * c - 1.0);
                (t * t - 12.0) * -0.1
            }
            QuarticParaboloid => clamp10(p(0), -(x2 * x2 + z2 * z2 - y)),
            QuarticSaddle => clamp10(p(0), -(x2 * x2 - z2 * z2 - y)),
            QuarticCylinder => clamp10(
                p(0),
                -((x2 + z2) * y * y + p(2) * p(2) * (x2 + z2) - p(2) * p(2) * p(1) * p(1)),
            ),
            R => (x2 + y2 + z2).sqrt(),
            Ridge => {
                let g = generator_of(p(5));
                let q = DVec3::new(x, y, z);
                let (lambda, omega, off, ridge) = (p(0), p(2), p(3), p(4));
                let octaves = trunc_i32(p(1));
                let rscale = 1.0 / max(ridge, 1.0 - ridge);
                let scale = 1.0 / max(off, 1.0 - off);
                let resid = p(1) - f64::from(octaves);
                let octave = |q: DVec3| (noise(q, g) - ridge).abs() * rscale - off;
                let (mut l, mut o, mut total) = (lambda, omega, 1.0);
                let mut value = octave(q);
                for _ in 2..=octaves.min(MAX_LOOP_TERMS as i32) {
                    value += o * octave(q * l);
                    total += o;
                    l *= lambda;
                    o *= omega;
                }
                if resid != 0.0 {
                    value += o * octave(q * l) * resid;
                    total += o * resid;
                }
                value * scale / total
            }
            RidgedMf => {
                let g = generator_of(p(5));
                let (h, lacunarity, octaves, offset, gain) = (p(0), p(1), p(2), p(3), p(4));
                let signal_at = |q: DVec3| {
                    let s = (noise(q, g) * 2.0 - 1.0).abs();
                    (offset - s) * (offset - s)
                };
                let mut q = DVec3::new(x, y, z);
                let mut signal = signal_at(q);
                let mut result = signal;
                let mut frequency = 1.0;
                let mut i = 1;
                while f64::from(i) < octaves && i < MAX_LOOP_TERMS as i32 {
                    q *= lacunarity;
                    frequency *= lacunarity;
                    let weight = signal * gain;
                    let weight = if weight > 1.0 { 1.0 } else { weight };
                    let weight = if weight < 0.0 { 0.0 } else { weight };
                    signal = signal_at(q) * weight;
                    result += signal * frequency.powf(-h);
                    i += 1;
                }
                result
            }
            RoundedBox => {
                let r = p(0);
                let far = DVec3::new(p(1), p(2), p(3)) - DVec3::splat(r);
                let q = DVec3::new(x, y, z);
                let above = (q - far).max(DVec3::ZERO);
                let below = (-far - q).max(DVec3::ZERO);
                -r + above.max(below).length() - 1e-6
            }
            Sphere => -p(0) + (x2 + y2 + z2).sqrt(),
            Spikes => {
                let r = (-(x2 + y2 + z2) * p(3)).exp() * p(4)
                    - (-(x2 * p(0) + y2 * p(0) + z2) * p(1)).exp()
                    - (-(x2 * p(0) + y2 + z2 * p(0)) * p(1)).exp()
                    - (-(x2 + y2 * p(0) + z2 * p(0)) * p(1)).exp();
                -r * p(2)
            }
            Spikes2d => {
                -(p(0) * (p(1) * x).cos() * (p(2) * z).cos() * (-p(3) * (x * x + z * z)).exp() - y)
            }
            Spiral => {
                let r = (x2 + z2).sqrt();
                let x = off_axis(x, z, 0.000001);
                let r = r + p(0) * z.atan2(x) / TWO_PI;
                let mut d = r % p(0) - p(0) * 0.5;
                d = if p(5) == 1.0 {
                    (d * d + y * y).sqrt()
                } else if p(5) != 0.0 {
                    let e = 2.0 / p(5);
                    (d.abs().powf(e) + y.abs().powf(e)).powf(1.0 / e)
                } else {
                    max(d.abs(), y.abs())
                };
                let r = (x * x + y * y + z * z).sqrt();
                -min(p(2) - r, p(1) - min(d, r))
            }
            SteinersRoman => clamp10(p(0), -(x2 * y2 + x2 * z2 + y2 * z2 + x * y * z)),
            Strophoid => {
                let s = p(3) * p(3);
                clamp10(
                    p(0),
                    -((p(2) - x) * (y * y + z * z) - s * p(1) * x2 - s * x2 * x),
                )
            }
            Strophoid2d => {
                let (x, _, x2, y2) = rot2d(x, y, z, p(4), p(5), p(6));
                let s = p(3) * p(3);
                clamp10(p(0), -((p(2) - x) * y2 - s * p(1) * x2 - s * x2 * x))
            }
            Superellipsoid => {
                let (e, n) = (p(0), p(1));
                let (pe, pn) = (2.0 / e, 1.0 / n);
                1.0 - ((x.abs().powf(pe) + y.abs().powf(pe)).powf(e * pn) + z.abs().powf(2.0 * pn))
                    .powf(n * 0.5)
            }
            Th => x.atan2(z),
            Torus => {
                let h = (x2 + z2).sqrt() - p(0);
                -p(1) + (h * h + y2).sqrt()
            }
            Torus2 => {
                let (a2, b2) = (p(1) * p(1), p(2) * p(2));
                clamp10(
                    p(0),
                    -(x2 * x2 + y2 * y2 + z2 * z2 + 2.0 * x2 * y2 + 2.0 * x2 * z2 + 2.0 * y2 * z2
                        - 2.0 * (a2 + b2) * x2
                        + 2.0 * (a2 - b2) * y2
                        - 2.0 * (a2 + b2) * z2
                        + (a2 - b2) * (a2 - b2)),
                )
            }
            TorusGumdrop => clamp10(
                p(0),
                -(4.0 * (x2 * x2 + (y2 + z2) * (y2 + z2)) + 17.0 * x2 * (y2 + z2)
                    - 20.0 * (x2 + y2 + z2)
                    + 17.0),
            ),
            Umbrella => clamp10(p(0), -(x * x - y * z * z)),
            WitchOfAgnesi => clamp10(p(0), -(p(1) * (y - 1.0) + (x2 + z2) * y)),
            WitchOfAgnesi2d => {
                let (_, y, x2, _) = rot2d(x, y, z, p(3), p(4), p(5));
                clamp10(p(0), -(p(1) * p(1) * y + x2 * y - p(2)))
            }
            Noise3d => noise(DVec3::new(x, y, z), generator),
            Pattern => 0.0,
            NoiseGenerator => noise(DVec3::new(x, y, z), generator_of(p(0))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_arities() {
        for (n, (f, params)) in TABLE.iter().enumerate() {
            assert_eq!(Internal::numbered(n as i64), Some(*f));
            assert_eq!(f.arity(), 3 + params);
        }
        assert_eq!(Internal::numbered(79), None);
        assert_eq!(Internal::numbered(-1), None);
        assert_eq!(Internal::HelicalTorus.arity(), 13);
    }
}
