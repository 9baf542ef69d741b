//! Patterns: POV-Ray 3.7's functions from a point of pattern space to a number.
//!
//! A pattern says only *where* things change, never *what* they change to: a pigment looks its
//! value up in a colour map, a normal takes its slope, and later a texture map or a slope map
//! will look up the same value. Most patterns give a value in [0, 1] that then goes through
//! the pattern's wave (frequency, phase and wave shape); the discrete ones (`checker`,
//! `hexagon`, `brick`, `square`, `triangular`) give the index of an entry of their list
//! (0, 1, …). The formulas are POV-Ray 3.7.0.10's, in the same order of operations, so that
//! the values are the same to the last bit (unit tests compare with values POV-Ray printed).
//!
//! Adding a pattern: a variant of [`PatternKind`] and its arm in [`Pattern::raw`] (a function
//! here or in a file of this module), and the keyword's arm in the evaluator's pattern table
//! (`eval::build::material::pattern_kind`).

pub mod density;
pub mod fractal;
pub mod image;
pub mod pavement;
pub mod pigment;
pub mod tiling;

use crate::noise::{self, Turbulence, dnoise, noise, trunc_i32};
use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, PI};
use std::sync::OnceLock;

pub use pigment::{Colour, PigmentFunction, PlacedPigment, Rgb, lookup};

/// POV-Ray's `EPSILON`.
const EPSILON: f64 = 1.0e-10;

/// POV-Ray's `TWO_M_PI` (the same double as τ).
const TWO_PI: f64 = std::f64::consts::TAU;

/// Most wave sources for `ripples` and `waves` (`number_of_waves`; POV-Ray's default is 10).
pub const MAX_WAVES: usize = 64;

/// A pattern with its modifiers, in pattern space (the pigment or normal carries the
/// transformation into it).
#[derive(Clone, Debug, PartialEq)]
pub struct Pattern {
    /// Which function.
    pub kind: PatternKind,
    /// What happens to the function's value before it is looked up.
    pub wave: Wave,
    /// `turbulence …`: POV-Ray's classic turbulence, applied after the transformations. It
    /// displaces the point, except for `marble` and `wood`, whose formulas use it instead
    /// (and `agate`, which always has one, uses it both ways).
    pub turbulence: Option<Box<Turbulence>>,
    /// `noise_generator` 1, 2 or 3; 0 is the scene's (`global_settings`, default 2).
    pub noise_generator: u8,
    /// Wave sources of `ripples` and `waves` (`number_of_waves`, 1 ..= [`MAX_WAVES`]); 0 is
    /// the scene's (default 10).
    pub number_of_waves: u8,
    /// `warp { … }`s and the transformations between them, in the order they apply to a
    /// point (the last written first). The transformations after the last warp are the
    /// pigment's or normal's placement, applied before these.
    pub warps: Vec<Warp>,
}

/// What a scene's `global_settings` give the patterns that name nothing themselves.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneDefaults {
    /// `noise_generator` (1, 2 or 3).
    pub generator: u8,
    /// `number_of_waves` (1 ..= [`MAX_WAVES`]).
    pub waves: u8,
}

/// A warp of pattern space.
#[derive(Clone, Debug, PartialEq)]
pub enum Warp {
    /// Transformations written before a later warp: pattern space from the space outside.
    Transform(glam::DMat4),
    /// `warp { turbulence … }`: the point moves by the vector turbulence times the amount.
    Turbulence(Box<Turbulence>),
    /// `warp { repeat V offset O flip F }`: the slab [0, width) along one axis repeats, each
    /// copy shifted by `offset` times its number and, for odd copies, mirrored on the axes of
    /// `flip`.
    Repeat {
        /// 0, 1 or 2.
        axis: usize,
        /// The slab's width (single precision, as POV-Ray keeps it).
        width: f32,
        /// `offset`.
        offset: DVec3,
        /// −1 on the mirrored axes, 1 elsewhere.
        flip: DVec3,
    },
    /// `warp { black_hole C, R … }`: points within R of the centre are pulled towards it
    /// (pushed with `inverse`).
    BlackHole(Box<BlackHole>),
    /// The mapping warps: pattern space wrapped around a shape, `(angle, height or second
    /// angle, distance)` before the orientation turns it.
    Mapping(Box<MappingWarp>),
}

/// `warp { black_hole … }` (POV-Ray's type 0, the only one it implements).
#[derive(Clone, Debug, PartialEq)]
pub struct BlackHole {
    /// The centre (of the first copy, with `repeat`).
    pub center: DVec3,
    /// The radius of the region it affects.
    pub radius: f64,
    /// `strength` (1): how far a point moves, as a fraction of its distance from the centre.
    pub strength: f64,
    /// `falloff` (2): the power of the fall-off towards the edge.
    pub falloff: f64,
    /// `inverse`: push instead of pull.
    pub inverse: bool,
    /// `type` other than 0 leaves points where they are, as in POV-Ray.
    pub kind: i32,
    /// `repeat V`: a copy in every cell of this size (0 on an axis: no repeat along it).
    pub repeat: Option<DVec3>,
    /// `turbulence V`: each copy's centre moves by up to this, by its cell's random numbers.
    pub uncertainty: Option<DVec3>,
}

impl BlackHole {
    /// POV-Ray's parse-time checks of a repeating black hole: the centre at least a radius
    /// in, and cells wide enough for the hole and its uncertainty (a cell under 1e-10 does
    /// not repeat).
    pub fn checked(mut self) -> BlackHole {
        let Some(repeat) = self.repeat.as_mut() else {
            return self;
        };
        let u = self.uncertainty.unwrap_or(DVec3::ZERO);
        for i in 0..3 {
            if repeat[i] > 0.0 {
                if self.center[i] < self.radius {
                    self.center[i] = self.radius;
                }
                let least = self.center[i] + self.radius + u[i];
                if repeat[i] < least {
                    repeat[i] = least;
                }
                if repeat[i] < EPSILON {
                    repeat[i] = 0.0;
                }
            }
        }
        self
    }

    fn apply(&self, q: DVec3) -> DVec3 {
        let mut center = self.center;
        if let Some(repeat) = self.repeat {
            let mut block = [0i32; 3];
            for i in 0..3 {
                if repeat[i] >= EPSILON {
                    block[i] = trunc_i32((q[i] / repeat[i]).floor());
                }
            }
            if let Some(u) = self.uncertainty {
                let seed = noise::hash3d(block[0], block[1], block[2]);
                let r = pattern_rands();
                center += DVec3::new(r[seed] * u.x, r[seed + 1] * u.y, r[seed + 2] * u.z);
            }
            center += repeat * DVec3::new(block[0] as f64, block[1] as f64, block[2] as f64);
        }
        let delta = q - center;
        let length = delta.length();
        if length >= self.radius || self.kind != 0 {
            return q;
        }
        let near = (self.radius - length) / self.radius;
        let strength = (near.powf(self.falloff) * self.strength).min(1.0);
        q + delta * if self.inverse { -strength } else { strength }
    }
}

/// Which shape a mapping warp wraps pattern space around.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mapping {
    /// `cylindrical`: (angle around y, y, distance from the y axis).
    Cylindrical,
    /// `spherical`: (longitude, latitude, distance from the origin).
    Spherical,
    /// `toroidal`: (angle around y, angle around the ring, distance from the ring) for a ring
    /// of `major_radius`.
    Toroidal {
        /// `major_radius` (1).
        major_radius: f64,
    },
    /// `planar V, offset`: (x, y, offset).
    Planar {
        /// The offset that becomes z.
        offset: f64,
    },
    /// `cubic`: a cube's six faces unfolded on the xy square as a box's uv map does.
    Cubic,
}

/// A mapping warp with its modifiers.
#[derive(Clone, Debug, PartialEq)]
pub struct MappingWarp {
    /// The shape.
    pub mapping: Mapping,
    /// `orientation V` (normalised; z by default): which axis the mapped coordinates turn to.
    pub orientation: DVec3,
    /// `dist_exp E` (0): the angles are scaled by the distance to this power.
    pub dist_exp: f64,
}

impl MappingWarp {
    fn apply(&self, q: DVec3) -> DVec3 {
        let (x, y, z) = (q.x, q.y, q.z);
        // The angle of (x, z) from +x, a fraction of a turn in [0, 1).
        let turn = |x: f64, z: f64, len: f64| {
            if z == 0.0 {
                if x > 0.0 { 0.0 } else { PI }
            } else {
                let t = (x / len).acos();
                if z < 0.0 { TWO_PI - t } else { t }
            }
        };
        let scaled = |v: f64, d: f64| {
            if self.dist_exp == 1.0 {
                v * d
            } else if self.dist_exp != 0.0 {
                v * d.powf(self.dist_exp)
            } else {
                v
            }
        };
        let mapped = match self.mapping {
            Mapping::Planar { offset } => DVec3::new(x, y, offset),
            Mapping::Cylindrical => {
                let len = (x * x + z * z).sqrt();
                if len == 0.0 {
                    return q;
                }
                DVec3::new(scaled(turn(x, z, len) / TWO_PI, len), y, len)
            }
            Mapping::Spherical => {
                let dist = (x * x + y * y + z * z).sqrt();
                if dist == 0.0 {
                    return q;
                }
                let (x, y, z) = (x / dist, y / dist, z / dist);
                let phi = 0.5 + y.asin() / PI;
                let len = (x * x + z * z).sqrt();
                let theta = if len == 0.0 {
                    0.0
                } else {
                    turn(x, z, len) / TWO_PI
                };
                DVec3::new(scaled(theta, dist), scaled(phi, dist), dist)
            }
            Mapping::Toroidal { major_radius } => {
                let len = (x * x + z * z).sqrt();
                if len == 0.0 {
                    return q;
                }
                let theta = 0.0 - turn(x, z, len);
                let x = len - major_radius;
                let len = (x * x + y * y).sqrt();
                let mut phi = (-x / len).acos();
                if y > 0.0 {
                    phi = TWO_PI - phi;
                }
                let (theta, phi) = (theta / -TWO_PI, phi / TWO_PI);
                DVec3::new(scaled(theta, len), scaled(phi, len), len)
            }
            Mapping::Cubic => return cubic_warp(q),
        };
        let o = self.orientation;
        if o == DVec3::Z {
            return mapped;
        }
        let (x, y, z) = (mapped.x, mapped.y, mapped.z);
        DVec3::new(
            o.x * z + o.y * x + o.z * x,
            o.x * y + o.y * -z + o.z * y,
            o.x * -x + o.y * y + o.z * z,
        )
    }
}

/// `warp { cubic }`: the point's face of the origin-centred cube it lies on, unfolded.
fn cubic_warp(q: DVec3) -> DVec3 {
    let (x, y, z) = (q.x, q.y, q.z);
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    let third = 1.0 / 3.0;
    if x >= 0.0 && x >= ay && x >= az {
        DVec3::new(
            0.75 - 0.25 * (z / x + 1.0) / 2.0,
            third + third * (y / x + 1.0) / 2.0,
            x,
        )
    } else if y >= 0.0 && y >= ax && y >= az {
        DVec3::new(
            0.25 + 0.25 * (x / y + 1.0) / 2.0,
            1.0 - third * (z / y + 1.0) / 2.0,
            y,
        )
    } else if z >= 0.0 && z >= ax && z >= ay {
        DVec3::new(
            0.25 + 0.25 * (x / z + 1.0) / 2.0,
            third + third * (y / z + 1.0) / 2.0,
            z,
        )
    } else if x < 0.0 && x <= -ay && x <= -az {
        let x = -x;
        DVec3::new(
            0.25 * (z / x + 1.0) / 2.0,
            third + third * (y / x + 1.0) / 2.0,
            x,
        )
    } else if y < 0.0 && y <= -ax && y <= -az {
        let y = -y;
        DVec3::new(
            0.25 + 0.25 * (x / y + 1.0) / 2.0,
            third * (z / y + 1.0) / 2.0,
            y,
        )
    } else {
        let z = -z;
        DVec3::new(
            1.0 - 0.25 * (x / z + 1.0) / 2.0,
            third + third * (y / z + 1.0) / 2.0,
            z,
        )
    }
}

impl Warp {
    fn apply(&self, q: DVec3) -> DVec3 {
        match self {
            Warp::Transform(m) => m.transform_point3(q),
            Warp::Turbulence(t) => {
                let d = t.vector(q);
                DVec3::new(
                    q.x + d.x * t.amount.x,
                    q.y + d.y * t.amount.y,
                    q.z + d.z * t.amount.z,
                )
            }
            Warp::Repeat {
                axis,
                width,
                offset,
                flip,
            } => {
                let block = (q[*axis] / f64::from(*width)).floor() as f32;
                let mut r = q;
                r[*axis] = q[*axis] - f64::from(block * width);
                if (block as i32) & 1 != 0 {
                    r *= *flip;
                    if flip[*axis] < 0.0 {
                        r[*axis] += f64::from(*width);
                    }
                }
                r + f64::from(block) * *offset
            }
            Warp::BlackHole(b) => b.apply(q),
            Warp::Mapping(m) => m.apply(q),
        }
    }
}

impl Pattern {
    /// A pattern with POV-Ray's defaults for its kind (wave, frequency, turbulence).
    pub fn new(kind: PatternKind) -> Pattern {
        let mut wave = Wave::default();
        match kind {
            PatternKind::Marble
            | PatternKind::Wood
            | PatternKind::Spiral1(_)
            | PatternKind::Spiral2(_) => wave.shape = WaveShape::Triangle,
            // POV-Ray skips the frequency step for these (a `frequency` after the pattern
            // turns it back on).
            PatternKind::Quilted { .. }
            | PatternKind::Image(..)
            | PatternKind::MaterialIndex(..) => wave.frequency = 0.0,
            _ if kind.list_len().is_some() => wave.frequency = 0.0,
            _ => {}
        }
        let turbulence = matches!(kind, PatternKind::Agate { .. }).then(Box::default);
        Pattern {
            kind,
            wave,
            turbulence,
            noise_generator: 0,
            number_of_waves: 0,
            warps: Vec::new(),
        }
    }

    /// The pattern with the scene's noise generator and number of waves where it names none.
    pub fn with_scene(&self, scene: SceneDefaults) -> Pattern {
        let mut p = self.clone();
        if p.noise_generator == 0 {
            p.noise_generator = scene.generator;
        }
        if p.number_of_waves == 0 {
            p.number_of_waves = scene.waves;
        }
        p
    }

    /// The wave sources `ripples` and `waves` use.
    pub fn waves(&self) -> &'static [(DVec3, f64)] {
        let n = if self.number_of_waves == 0 {
            10
        } else {
            self.number_of_waves as usize
        };
        &wave_sources()[..n.min(MAX_WAVES)]
    }

    /// The value at point `p` of pattern space: an entry index for a discrete pattern, else
    /// (usually) a value in [0, 1].
    pub fn value(&self, p: DVec3) -> f64 {
        self.wave.apply(self.raw(self.warp(p)))
    }

    /// The value at pattern point `p` of `surface` (see [`Pattern::raw_on`]).
    pub fn value_on(&self, p: DVec3, surface: &Surface) -> f64 {
        self.wave.apply(self.raw_on(self.warp(p), surface))
    }

    /// The value before the wave at warped point `p` of `surface`: what [`Pattern::raw`]
    /// gives, except for the patterns that look at the surface (`slope`, `aoi`), which give
    /// 0 without one.
    pub fn raw_on(&self, p: DVec3, surface: &Surface) -> f64 {
        match &self.kind {
            PatternKind::Slope(slope) => slope.value(p, surface),
            PatternKind::Aoi if surface.normal == DVec3::ZERO => 0.0,
            PatternKind::Aoi => {
                let cos = surface
                    .normal
                    .normalize()
                    .dot(surface.direction.normalize());
                cos.clamp(-1.0, 1.0).acos() / PI
            }
            _ => self.raw(p),
        }
    }

    /// The point after the pattern's warps (its classic turbulence last, if it displaces).
    pub fn warp(&self, p: DVec3) -> DVec3 {
        let mut q = p;
        for w in &self.warps {
            q = w.apply(q);
        }
        let turbulent = !matches!(self.kind, PatternKind::Marble | PatternKind::Wood);
        if let Some(t) = self
            .turbulence
            .as_ref()
            .filter(|t| turbulent && t.amount != DVec3::ZERO)
        {
            let d = t.vector(q);
            q = DVec3::new(
                q.x + d.x * t.amount.x,
                q.y + d.y * t.amount.y,
                q.z + d.z * t.amount.z,
            );
        }
        q.clamp(DVec3::splat(-1e17), DVec3::splat(1e17))
    }

    /// The noise generator used (the scene's default, 2, if none was given).
    pub fn generator(&self) -> u8 {
        if self.noise_generator == 0 {
            2
        } else {
            self.noise_generator
        }
    }

    /// The classic turbulence's scalar sum at `p` times its x amount, or 0 without one.
    fn scalar_turbulence(&self, p: DVec3) -> f64 {
        self.turbulence
            .as_ref()
            .map_or(0.0, |t| t.amount.x * t.scalar(p, self.generator()))
    }

    /// The function's own value at the warped point `p`, before the wave.
    pub fn raw(&self, p: DVec3) -> f64 {
        let generator = self.generator();
        let DVec3 { x, y, z } = p;
        match &self.kind {
            PatternKind::Agate { turb } => {
                let t = turb
                    * self
                        .turbulence
                        .as_ref()
                        .map_or(0.0, |t| t.scalar(p, generator));
                let n = 0.5 * (cycloidal(1.3 * t + 1.1 * z) + 1.0);
                if n < 0.0 { 0.0 } else { n.min(1.0).powf(0.77) }
            }
            PatternKind::Average => 0.0,
            PatternKind::Pigment(f) => {
                let c = f.0.eval(&[x, y, z], generator);
                0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2]
            }
            PatternKind::Function(f) => {
                let v = f.at(p, generator);
                if v > 1.0 { v % 1.0 } else { v }
            }
            PatternKind::Boxed => clip(x.abs().max(y.abs().max(z.abs()))),
            PatternKind::Fractal(f) => f.value([x, y, z]),
            PatternKind::Pavement(pv) => pv.value([x, y, z]),
            PatternKind::Tiling(n) => tiling::tiling(i32::from(*n), [x, y, z]),
            PatternKind::Object(inside) => inside.0.eval(&[x, y, z], generator)[0],
            PatternKind::Density(d) => d.value(p),
            PatternKind::MaterialIndex(image, textures) => {
                // POV-Ray wraps a number above the count (the count itself is the last one).
                let k = image.material(p);
                let n = f64::from(*textures);
                if k > n { k % n } else { k }
            }
            // (Without a surface: POV-Ray's value when there is no intersection.)
            PatternKind::Slope(_) | PatternKind::Aoi | PatternKind::UvMapping => 0.0,
            PatternKind::Bozo | PatternKind::Bumps | PatternKind::Spotted => noise(p, generator),
            PatternKind::Brick { size, mortar } => brick(p, *size, *mortar),
            PatternKind::Cells => {
                let cell = |c: f64| (c + EPSILON).floor() as i32;
                let k = noise::hash3d(cell(x), cell(y), cell(z));
                pattern_rands()[k].min(1.0)
            }
            PatternKind::Checker => {
                let k =
                    ((x + EPSILON).floor() + (y + EPSILON).floor() + (z + EPSILON).floor()) as i64;
                if k & 1 != 0 { 1.0 } else { 0.0 }
            }
            PatternKind::Crackle(c) => crackle(p, c, generator),
            PatternKind::Cylindrical => clip((x * x + z * z).sqrt()),
            // Normals only (the evaluator refuses them elsewhere).
            PatternKind::Facets(_) | PatternKind::BumpMap(_) => 0.0,
            PatternKind::Image(image, use_) => image.value(p, *use_),
            PatternKind::Dents => {
                let n = noise(p, generator);
                n * n * n
            }
            PatternKind::Gradient(axis) => {
                // Values above 1 wrap with fmod 1 (so 1.0 stays 1.0); the wave wraps the rest.
                let r = (x * axis.x + y * axis.y) + z * axis.z;
                if r > 1.0 { r % 1.0 } else { r }
            }
            PatternKind::Granite => {
                let q = p * 4.0;
                let (mut s, mut f) = (0.0, 1.0);
                for _ in 0..6 {
                    let r = q * f;
                    let t = if generator == 1 {
                        (0.5 - noise(r, 1)).abs()
                    } else {
                        (1.0 - 2.0 * noise(r, generator)).abs().min(0.5)
                    };
                    s += t / f;
                    f *= 2.0;
                }
                s
            }
            PatternKind::Hexagon => hexagon(x, z),
            PatternKind::Leopard => {
                let v = ((x.sin() + y.sin()) + z.sin()) / 3.0;
                v * v
            }
            PatternKind::Marble => x + self.scalar_turbulence(p),
            PatternKind::Onion => ((x * x + y * y) + z * z).sqrt() % 1.0,
            PatternKind::Planar => clip(y.abs()),
            PatternKind::Quilted { control0, control1 } => {
                let q = quilt_offset(p);
                let t = quilt_cubic(q.length_povray(), *control0, *control1);
                let q = q * t;
                ((q.x.abs() + q.y.abs()) + q.z.abs()) / 3.0
            }
            PatternKind::Radial => {
                if x.abs() < 0.001 && z.abs() < 0.001 {
                    0.25
                } else {
                    0.25 + (x.atan2(z) + PI) / TWO_PI
                }
            }
            PatternKind::Ripples => {
                let mut s = 0.0;
                let waves = self.waves();
                for (src, _) in waves {
                    s +=
                        cycloidal(source_distance(p, *src) * self.wave.frequency + self.wave.phase);
                }
                0.5 * (1.0 + s / waves.len() as f64)
            }
            PatternKind::Spherical => clip(((x * x + y * y) + z * z).sqrt()),
            PatternKind::Spiral1(arms) | PatternKind::Spiral2(arms) => {
                let turb = self.scalar_turbulence(p);
                let rad = (x * x + y * y).sqrt();
                let phi = if rad == 0.0 {
                    0.0
                } else if x < 0.0 {
                    3.0 * FRAC_PI_2 - (y / rad).asin()
                } else {
                    FRAC_PI_2 + (y / rad).asin()
                };
                let v = ((z + rad) + arms * phi / TWO_PI) + turb;
                if matches!(self.kind, PatternKind::Spiral1(_)) {
                    v
                } else {
                    triangle_wave(rad) + triangle_wave(v)
                }
            }
            PatternKind::Square => {
                let (vx, vz) = (x.floor() as i64, z.floor() as i64);
                match (vx & 1 != 0, vz & 1 != 0) {
                    (true, true) => 2.0,
                    (true, false) => 3.0,
                    (false, true) => 1.0,
                    (false, false) => 0.0,
                }
            }
            PatternKind::Triangular => triangular(x, z),
            PatternKind::Waves => {
                let mut s = 0.0;
                let waves = self.waves();
                for (src, f) in waves {
                    let len = source_distance(p, *src);
                    s += cycloidal(len * self.wave.frequency * f + self.wave.phase) / f;
                }
                0.2 * (2.5 + s / waves.len() as f64)
            }
            PatternKind::Wood => {
                let (mut px, mut py) = (0.0, 0.0);
                if let Some(t) = &self.turbulence {
                    let d = t.vector(p);
                    px = cycloidal((x + d.x) * t.amount.x);
                    py = cycloidal((y + d.y) * t.amount.y);
                }
                let (px, py) = (px + x, py + y);
                (px * px + py * py + 0.0 * 0.0).sqrt()
            }
            PatternKind::Wrinkles => {
                let octave = |q: DVec3| {
                    let n = noise(q, generator);
                    if generator > 1 {
                        (n * 2.0 - 0.5).clamp(0.0, 1.0)
                    } else {
                        n
                    }
                };
                let mut v = octave(p);
                let (mut lambda, mut omega) = (2.0, 0.5);
                for _ in 1..10 {
                    v += omega * octave(p * lambda);
                    lambda *= 2.0;
                    omega *= 0.5;
                }
                v / 2.0
            }
        }
    }
}

/// `function { pattern { … } }`: a pattern's value as a function of x, y, z (the point
/// taken into the pattern's space first).
#[derive(Debug, PartialEq)]
pub struct PatternFunction {
    /// The pattern, with the scene's defaults filled in.
    pub pattern: Pattern,
    /// Pattern space from world space (`None`: the identity).
    pub from_world: Option<glam::DMat4>,
}

impl crate::func::Native for PatternFunction {
    fn params(&self) -> usize {
        3
    }

    fn size(&self) -> usize {
        1
    }

    fn eval(&self, args: &[f64], _generator: u8) -> [f64; 5] {
        let p = DVec3::new(args[0], args[1], args[2]);
        let q = self.from_world.map_or(p, |m| m.transform_point3(p));
        [self.pattern.value(q), 0.0, 0.0, 0.0, 0.0]
    }

    fn same(&self, other: &dyn crate::func::Native) -> bool {
        crate::func::same_data(self, other)
    }
}

/// The pattern functions.
#[derive(Clone, Debug, PartialEq)]
pub enum PatternKind {
    /// `agate`: turbulent bands; `agate_turb` (default 1) scales the turbulence.
    Agate {
        /// `agate_turb`.
        turb: f64,
    },
    /// `average`: no value of its own; a pigment averages its `pigment_map`'s pigments,
    /// weighted by their entries' values.
    Average,
    /// `boxed`: 1 at the origin down to 0 on the unit cube's surface.
    Boxed,
    /// `bozo`: noise.
    Bozo,
    /// `brick`: 1 in bricks of `brick_size`, 0 in mortar of width `mortar` (two entries).
    Brick {
        /// `brick_size` (default <8, 3, 4.5>).
        size: DVec3,
        /// `mortar` (default 0.5), as POV-Ray keeps it.
        mortar: f64,
    },
    /// `bumps`: noise (as a normal: its slope, from the vector noise).
    Bumps,
    /// `cells`: one random value per unit cube.
    Cells,
    /// `checker`: unit cubes, 0 where ⌊x⌋ + ⌊y⌋ + ⌊z⌋ is even, else 1 (two entries).
    Checker,
    /// `crackle`: distances to random points, one per unit cube.
    Crackle(Box<Crackle>),
    /// `cylindrical`: 1 on the y axis down to 0 at radius 1.
    Cylindrical,
    /// `dents`: noise cubed.
    Dents,
    /// `image_pattern { … }`: the grey (or transparency) of an image's pixels.
    Image(std::sync::Arc<image::ImageMap>, image::ImageUse),
    /// `bump_map { … }` (normals only): an image's grey as a height field.
    BumpMap(std::sync::Arc<image::ImageMap>),
    /// `facets` (normals only): flat facets, the normal replaced by the nearest of random
    /// points around it (or, with `coords`, tilted by the noise at the nearest random point
    /// around the surface point).
    Facets(Facets),
    /// `gradient V`: the fraction of `p·V̂` (unit `V̂`).
    Gradient(DVec3),
    /// `granite`: six octaves of folded noise.
    Granite,
    /// `hexagon`: hexagons in the x-z plane (three entries).
    Hexagon,
    /// `leopard`: regular spots, `((sin x + sin y + sin z) / 3)²`.
    Leopard,
    /// `marble`: bands along x, disturbed by the turbulence.
    Marble,
    /// `onion`: concentric spheres.
    Onion,
    /// `planar`: 1 on the x-z plane down to 0 at |y| = 1.
    Planar,
    /// `quilted`: rounded cubes; `control0`, `control1` shape the rounding.
    Quilted {
        /// `control0` (default 1).
        control0: f64,
        /// `control1` (default 1).
        control1: f64,
    },
    /// `radial`: the angle around the y axis.
    Radial,
    /// `ripples`: concentric waves from ten sources.
    Ripples,
    /// `spherical`: 1 at the origin down to 0 at radius 1.
    Spherical,
    /// `spiral1 N`: an N-armed spiral around the z axis.
    Spiral1(f64),
    /// `spiral2 N`: two crossed N-armed spirals.
    Spiral2(f64),
    /// `spotted`: noise.
    Spotted,
    /// `square`: squares in the x-z plane (four entries).
    Square,
    /// `triangular`: triangles in the x-z plane (six entries).
    Triangular,
    /// `waves`: waves of ten frequencies from ten sources.
    Waves,
    /// `wood`: concentric cylinders around the z axis, disturbed by the turbulence.
    Wood,
    /// `wrinkles`: ten octaves of clamped noise.
    Wrinkles,
    /// `function { … }`: a user function of the point (POV-Ray keeps values up to 1 and
    /// wraps larger ones with `mod 1`; the wave then wraps negative ones).
    Function(std::sync::Arc<crate::func::Function>),
    /// `pigment_pattern { … }`: the grey of a pigment's colour (0.297 R + 0.589 G + 0.114 B),
    /// the pigment evaluated as a function of the point.
    Pigment(crate::func::NativeRef),
    /// `mandel`, `julia`, `magnet`: escape-time fractals in the x-y plane.
    Fractal(Box<fractal::Fractal>),
    /// `pavement`: tilings of the x-z plane by polyominoes, polyiamonds and polyhexes.
    Pavement(pavement::Pavement),
    /// `tiling N` (1 to 27): POV-Ray's periodic and Penrose tilings of the x-z plane.
    Tiling(u8),
    /// `slope`: the surface's steepness along a direction (or towards a point), optionally
    /// mixed with the altitude along another.
    Slope(Box<Slope>),
    /// `aoi`: the angle between the surface's normal and the ray, 0 to 1 for 0 to 180°.
    Aoi,
    /// `material_map { image … }`: the number of the texture an image's pixel picks (its
    /// palette index, else its red × 255; above the number of textures, modulo it), 0 off a
    /// `once` image.
    MaterialIndex(std::sync::Arc<image::ImageMap>, u32),
    /// `density_file df3 "file"`: a DF3 file's voxels over the unit cube.
    Density(std::sync::Arc<density::DensityFile>),
    /// `object { … }`: 1 inside the object, 0 outside (two entries).
    Object(crate::func::NativeRef),
    /// `uv_mapping`: no value of its own; its map's one entry sees the surface's (u, v, 0)
    /// instead of the point.
    UvMapping,
}

/// What a pattern may see of the surface besides its point (POV-Ray's intersection and ray):
/// `slope`, `aoi` and `uv_mapping` use it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Surface {
    /// The point, in the world.
    pub point: DVec3,
    /// The surface's unit normal there as the shape gives it, turned to face the ray (world
    /// space); zero where there is no surface (functions, the sky, shadow rays).
    pub normal: DVec3,
    /// The ray's direction.
    pub direction: DVec3,
    /// The surface's (u, v) coordinates, where a uv-mapped texture asked for them.
    pub uv: glam::DVec2,
    /// On a mesh whose triangles have textures of their own: the material entries of the
    /// triangle's corners and the point's weights for them.
    pub corners: ([u32; 3], DVec3),
}

/// `slope`'s parameters, as POV-Ray keeps them after parsing.
#[derive(Clone, Debug, PartialEq)]
pub struct Slope {
    /// The unit direction whose steepness counts, or with `point_at` the point looked at.
    pub direction: DVec3,
    /// `point_at`: the slope towards a point.
    pub point_at: bool,
    /// `LOW, HIGH` after the direction, as (low, high − low); (0, 0) when not given.
    pub slope_range: (f64, f64),
    /// The unit altitude direction (zero without `altitude`).
    pub altitude: DVec3,
    /// `LOW, HIGH` after the altitude, as (low, high − low).
    pub altitude_range: (f64, f64),
    /// The weights of slope and altitude (their vectors' lengths, summing to 1).
    pub weights: (f64, f64),
}

impl Slope {
    /// The value at pattern point `p` on `surface` (0 without a surface, as in POV-Ray).
    fn value(&self, p: DVec3, surface: &Surface) -> f64 {
        if surface.normal == DVec3::ZERO {
            return 0.0;
        }
        let toward = if self.point_at {
            (self.direction - surface.point).normalize()
        } else {
            self.direction
        };
        let mut slope = surface.normal.dot(toward).clamp(-1.0, 1.0);
        slope = (slope.asin() / PI * 2.0 + 1.0) * 0.5;
        let scaled =
            |v: f64, (low, span): (f64, f64)| if span != 0.0 { (v - low) / span } else { v };
        slope = scaled(slope, self.slope_range);
        let wrap = |v: f64| if v < 0.0 { 1.0 + v % 1.0 } else { v % 1.0 };
        if self.weights.1 == 0.0 {
            return if slope == 1.0 {
                slope - EPSILON
            } else {
                wrap(slope)
            };
        }
        let altitude = scaled(p.dot(self.altitude), self.altitude_range);
        let v = self.weights.0 * slope + self.weights.1 * altitude;
        if v - 1.0 < EPSILON && v >= 1.0 {
            v - EPSILON
        } else {
            wrap(v)
        }
    }
}

/// `crackle`'s parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Crackle {
    /// `form` (default <−1, 1, 0>): weights of the nearest three distances.
    pub form: DVec3,
    /// `metric` (default 2, Euclidean).
    pub metric: f64,
    /// `offset` (default 0).
    pub offset: f64,
    /// `solid`: the noise at the nearest point instead of distances.
    pub solid: bool,
}

/// `facets`' parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Facets {
    /// `size` (0.1): the facets' size.
    pub size: f64,
    /// `coords` (0): facets by position, with this much tilt; 0 for facets by direction.
    pub coords: f64,
    /// `metric` (2): the distance's exponent.
    pub metric: f64,
}

impl Default for Facets {
    fn default() -> Facets {
        Facets {
            size: 0.1,
            coords: 0.0,
            metric: 2.0,
        }
    }
}

/// The random point of unit cell `cell` (POV-Ray's `PickInCube` for a point in that cell).
fn cell_point(cell: [i32; 3]) -> DVec3 {
    let seed = noise::hash3d(cell[0], cell[1], cell[2]);
    let r = pattern_rands();
    DVec3::new(cell[0] as f64, cell[1] as f64, cell[2] as f64)
        + DVec3::new(r[seed], r[seed + 1], r[seed + 2])
}

/// The random points of a cell and of the 80 cells around it within a knight's move, in
/// POV-Ray's order.
fn facet_candidates(cell: [i32; 3]) -> [DVec3; 81] {
    let mut points = [DVec3::ZERO; 81];
    let mut k = 0;
    for ax in -2..=2i32 {
        for ay in -2..=2i32 {
            for az in -2..=2i32 {
                if (ax.abs() > 1) as u8 + (ay.abs() > 1) as u8 + (az.abs() > 1) as u8 > 1 {
                    continue;
                }
                points[k] = cell_point([cell[0] + ax, cell[1] + ay, cell[2] + az]);
                k += 1;
            }
        }
    }
    points
}

/// The `facets` normal at pattern point `p` for the unit normal `n` in pattern space (not
/// normalised), as POV-Ray's facets normal computes it.
pub fn facets_normal(p: DVec3, n: DVec3, f: &Facets) -> DVec3 {
    thread_local! {
        /// The last cell's candidates (POV-Ray keeps the same cache per thread; neighbouring
        /// samples mostly fall in one cell).
        static LAST: std::cell::RefCell<Option<([i32; 3], [DVec3; 81])>> =
            const { std::cell::RefCell::new(None) };
    }
    let scale = if f.size < 1e-6 { 1e6 } else { 1.0 / f.size };
    let t = if f.coords != 0.0 { p } else { n } * scale;
    let distance = |d: DVec3| {
        if f.metric == 2.0 {
            d.length_squared()
        } else if f.metric == 1.0 {
            // (POV-Ray sums the differences without their signs here.)
            d.x + d.y + d.z
        } else {
            d.x.abs().powf(f.metric) + d.y.abs().powf(f.metric) + d.z.abs().powf(f.metric)
        }
    };
    let flo = (t - DVec3::splat(EPSILON)).floor();
    let cell = [trunc_i32(flo.x), trunc_i32(flo.y), trunc_i32(flo.z)];
    let nearest = LAST.with_borrow_mut(|last| {
        let points = match last {
            Some((c, points)) if *c == cell => points,
            _ => &mut last.insert((cell, facet_candidates(cell))).1,
        };
        let mut best = (distance(points[0] - t), points[0]);
        for &c in &points[1..] {
            let d = distance(c - t);
            if d < best.0 {
                best = (d, c);
            }
        }
        best.1
    });
    if f.coords != 0.0 {
        let pert = dnoise(nearest);
        let pert = pert - n * pert.dot(n);
        n + f.coords * pert
    } else {
        nearest
    }
}

impl Default for Crackle {
    fn default() -> Crackle {
        Crackle {
            form: DVec3::new(-1.0, 1.0, 0.0),
            metric: 2.0,
            offset: 0.0,
            solid: false,
        }
    }
}

impl PatternKind {
    /// For a discrete pattern, how many entries its list has (its values are 0, 1, …).
    pub fn list_len(&self) -> Option<usize> {
        match self {
            PatternKind::Checker | PatternKind::Brick { .. } | PatternKind::Object(_) => Some(2),
            PatternKind::Hexagon => Some(3),
            PatternKind::Square => Some(4),
            PatternKind::Triangular => Some(6),
            _ => None,
        }
    }
}

/// How a value pattern's raw value becomes the value looked up: scaled by `frequency`,
/// shifted by `phase`, wrapped into [0, 1], then shaped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wave {
    /// The wave's shape.
    pub shape: WaveShape,
    /// `frequency` (default 1; 0 skips the wrapping). POV-Ray keeps it in single precision.
    pub frequency: f64,
    /// `phase` (default 0), in single precision as POV-Ray keeps it.
    pub phase: f64,
}

impl Default for Wave {
    fn default() -> Wave {
        Wave {
            shape: WaveShape::Ramp,
            frequency: 1.0,
            phase: 0.0,
        }
    }
}

/// Wave shapes (`ramp_wave` is the default).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WaveShape {
    /// `ramp_wave`: the wrapped value as it is.
    Ramp,
    /// `triangle_wave`: up and down again.
    Triangle,
    /// `sine_wave`.
    Sine,
    /// `scallop_wave`: |sin| of half the value.
    Scallop,
    /// `cubic_wave`: the smooth step 3v² − 2v³.
    Cubic,
    /// `poly_wave E`: v to the power E.
    Poly(f64),
}

impl Wave {
    /// The looked-up value for raw value `v`.
    pub fn apply(&self, v: f64) -> f64 {
        let mut v = v;
        if self.frequency != 0.0 {
            // POV-Ray wraps with fmod 1.00001 (so 1.0 stays 1.0): values drift by 1e-5 a unit.
            v = (v * self.frequency + self.phase) % 1.00001;
        }
        if v < 0.0 {
            v -= v.floor();
        }
        match self.shape {
            WaveShape::Ramp => v,
            WaveShape::Triangle => triangle_wave(v),
            WaveShape::Sine => (1.0 + cycloidal(v)) * 0.5,
            WaveShape::Scallop => cycloidal(v * 0.5).abs(),
            WaveShape::Cubic => (v * v) * ((-2.0 * v) + 3.0),
            WaveShape::Poly(e) => v.powf(e),
        }
    }
}

/// POV-Ray's `cycloidal`: sin(2πv) of the fraction of v, quantised as POV-Ray does.
pub fn cycloidal(v: f64) -> f64 {
    if v >= 0.0 {
        (((v - v.floor()) * 50000.0) / 50000.0 * TWO_PI).sin()
    } else {
        0.0 - (((0.0 - (v + (0.0 - v).floor())) * 50000.0) / 50000.0 * TWO_PI).sin()
    }
}

/// POV-Ray's `Triangle_Wave`: 0 → 1 → 0 over each unit.
pub fn triangle_wave(v: f64) -> f64 {
    let off = if v >= 0.0 {
        v - v.floor()
    } else {
        v + 1.0 + v.abs().floor()
    };
    if off >= 0.5 {
        2.0 * (1.0 - off)
    } else {
        2.0 * off
    }
}

/// 1 − r within [0, 1], 1 below, 0 above.
fn clip(r: f64) -> f64 {
    if r < 0.0 {
        1.0
    } else if r > 1.0 {
        0.0
    } else {
        1.0 - r
    }
}

/// `|v|` summed in POV-Ray's order.
trait PovLength {
    fn length_povray(self) -> f64;
}

impl PovLength for DVec3 {
    fn length_povray(self) -> f64 {
        ((self.x * self.x + self.y * self.y) + self.z * self.z).sqrt()
    }
}

/// Distance from wave source `src` (1 at the source itself).
fn source_distance(p: DVec3, src: DVec3) -> f64 {
    let len = (p - src).length_povray();
    if len == 0.0 { 1.0 } else { len }
}

/// POV-Ray's ten wave sources for `ripples` and `waves`: unit directions from the vector
/// noise and frequencies from its integer generator.
pub fn wave_sources() -> &'static [(DVec3, f64); MAX_WAVES] {
    static SOURCES: OnceLock<[(DVec3, f64); MAX_WAVES]> = OnceLock::new();
    SOURCES.get_or_init(|| {
        let mut seed: i32 = -560_851_967;
        std::array::from_fn(|i| {
            let d = dnoise(DVec3::new(i as f64, 0.0, 0.0));
            let len = d.length_povray();
            let src = if len == 0.0 {
                d
            } else {
                DVec3::new(d.x / len, d.y / len, d.z / len)
            };
            seed = seed.wrapping_mul(1_812_433_253).wrapping_add(12345);
            let f = f64::from((seed >> 16) & 0x7FFF) * 0.000030518509476 + 0.01;
            (src, f)
        })
    })
}

/// POV-Ray's random table for `cells` and `crackle`: the first outputs of the Mersenne
/// Twister MT19937 with its default seed, divided by 2³².
fn pattern_rands() -> &'static [f64] {
    static RANDS: OnceLock<Vec<f64>> = OnceLock::new();
    RANDS.get_or_init(|| {
        crate::noise::mt19937(4100)
            .into_iter()
            .map(|y| f64::from(y) / 4294967296.0)
            .collect()
    })
}

/// `brick`: 0 in the mortar, 1 in the bricks (running bond, courses along x and z).
fn brick(p: DVec3, size: DVec3, mortar: f64) -> f64 {
    let fud = 1e-10 + mortar;
    let (x, y, z) = (p.x + fud, p.y + fud, p.z + fud);
    let (mw, mh, md) = (mortar / size.x, mortar / size.y, mortar / size.z);
    let frac = |a: f64| {
        let f = a - f64::from(trunc_i32(a));
        if f < 0.0 { f + 1.0 } else { f }
    };
    if frac(y / size.y) <= mh {
        return 0.0;
    }
    let by = frac((y / size.y) * 0.5);
    if frac(x / size.x) <= mw && by <= 0.5 {
        return 0.0;
    }
    if frac((x / size.x) + 0.5) <= mw && by > 0.5 {
        return 0.0;
    }
    if frac(z / size.z) <= md && by > 0.5 {
        return 0.0;
    }
    if frac((z / size.z) + 0.5) <= md && by <= 0.5 {
        return 0.0;
    }
    1.0
}

/// `hexagon`: which of three colours tiles the hexagon around (x, z).
fn hexagon(x: f64, z: f64) -> f64 {
    let x = x.abs();
    let z = if z < 0.0 { 5.196152424 - z.abs() } else { z };
    let mut xs = x / 0.5;
    let mut zs = z / 0.866025404;
    xs -= (xs / 6.0).floor() * 6.0;
    zs -= (zs / 6.0).floor() * 6.0;
    let xm = (xs.floor() as i64) % 6;
    let zm = (zs.floor() as i64) % 6;
    let v = match xm {
        0 | 5 => match zm {
            0 | 5 => 0,
            1 | 2 => 1,
            _ => 2,
        },
        2 | 3 => match zm {
            0 | 1 => 2,
            2 | 3 => 0,
            _ => 1,
        },
        _ => {
            let mut xl = xs - xm as f64;
            let zl = zs - zm as f64;
            if (xm + zm) % 2 == 1 {
                xl = 1.0 - xl;
            }
            if xl == 0.0 {
                xl = 0.0001;
            }
            if zl / xl < 1.0 {
                match zm {
                    0 | 3 => 0,
                    2 | 5 => 1,
                    _ => 2,
                }
            } else {
                match zm {
                    0 | 3 => 2,
                    2 | 5 => 0,
                    _ => 1,
                }
            }
        }
    };
    f64::from(v) % 3.0
}

/// `triangular`: which of six colours tiles the triangle around (x, z).
fn triangular(x: f64, z: f64) -> f64 {
    const SQRT3: f64 = 1.7320508075688772;
    const SQRT3_2: f64 = 0.8660254037844386;
    let mut xs = x - 3.0 * (x / 3.0).floor();
    let mut zs = z - SQRT3 * (z / SQRT3).floor();
    let a = xs.floor() as i64;
    xs -= a as f64;
    let b = zs >= SQRT3_2;
    if b {
        zs = SQRT3 - zs;
    }
    let k = 1.0 - xs;
    let ans: f64 = if xs != 0.0 && k != 0.0 {
        let c = u8::from(zs / xs < SQRT3) + 2 * u8::from(zs / k < SQRT3);
        match c {
            3 => 0.0,
            2 => 1.0,
            1 => 3.0,
            _ => 0.0,
        }
    } else {
        1.0
    };
    let a = a as f64;
    let ans = if ans as i64 % 2 == 1 {
        (ans + 2.0 * a) % 6.0
    } else {
        (6.0 + ans - 2.0 * a) % 6.0
    };
    if b { 5.0 - ans } else { ans }
}

/// POV-Ray's `FLOOR` macro (which gives −3 for −2.0).
fn floor_povray(a: f64) -> f64 {
    if a >= 0.0 {
        a.floor()
    } else {
        0.0 - (0.0 - a).floor() - 1.0
    }
}

/// `quilted`'s offset from the centre of the point's unit cube.
pub fn quilt_offset(p: DVec3) -> DVec3 {
    let f = |c: f64| (c - floor_povray(c)) - 0.5;
    DVec3::new(f(p.x), f(p.y), f(p.z))
}

/// `quilted`'s rounding curve.
pub fn quilt_cubic(t: f64, p1: f64, p2: f64) -> f64 {
    let it = 1.0 - t;
    let it2 = it * it;
    let t2 = t * t;
    let t3 = t * t2;
    ((t3 + 3.0 * t * it2 * p1) + 3.0 * t2 * it * p2) * 1.154700538
}

/// The 81 neighbour cubes `crackle` searches: offsets −2..=2 on each axis, at most one of
/// them ±2, in POV-Ray's order.
fn crackle_offsets() -> &'static [[i32; 3]] {
    static OFFSETS: OnceLock<Vec<[i32; 3]>> = OnceLock::new();
    OFFSETS.get_or_init(|| {
        let mut v = Vec::with_capacity(81);
        for dx in -2..=2 {
            for dy in -2..=2 {
                for dz in -2..=2 {
                    let twos = [dx, dy, dz].iter().filter(|c: &&i32| c.abs() == 2).count();
                    if twos <= 1 {
                        v.push([dx, dy, dz]);
                    }
                }
            }
        }
        v
    })
}

/// `crackle`: the nearest three random points (one per unit cube) weighted by `form`, or the
/// noise at the nearest (`solid`).
fn crackle(p: DVec3, c: &Crackle, generator: u8) -> f64 {
    let rands = pattern_rands();
    let cell = [
        (p.x - EPSILON).floor() as i32,
        (p.y - EPSILON).floor() as i32,
        (p.z - EPSILON).floor() as i32,
    ];
    let point = |o: &[i32; 3]| {
        let n = [cell[0] + o[0], cell[1] + o[1], cell[2] + o[2]];
        let seed = noise::hash3d(n[0] & 0xFFF, n[1] & 0xFFF, n[2] & 0xFFF);
        DVec3::new(
            f64::from(n[0]) + rands[seed],
            f64::from(n[1]) + rands[seed + 1],
            f64::from(n[2]) + rands[seed + 2],
        )
    };
    let dist = |q: DVec3| {
        let d = q - p;
        if c.metric == 2.0 {
            (d.x * d.x + d.y * d.y) + d.z * d.z
        } else if c.metric == 1.0 {
            (d.x.abs() + d.y.abs()) + d.z.abs()
        } else {
            (d.x.abs().powf(c.metric) + d.y.abs().powf(c.metric)) + d.z.abs().powf(c.metric)
        }
    };
    // The 81 points around a cell depend on the cell alone; neighbouring samples mostly fall
    // in a cell met lately (as POV-Ray, each thread keeps cells' points): a few cells kept,
    // each in its slot by a hash of the cell, so that two crackle patterns sampled in turn
    // (two media densities) do not keep replacing each other's.
    const SLOTS: usize = 64;
    type Slot = ([i32; 3], [DVec3; 81]);
    thread_local! {
        static CELLS: std::cell::RefCell<Vec<Slot>> = const { std::cell::RefCell::new(Vec::new()) };
    }
    let (mut m1, mut m2, mut m3, nearest) = CELLS.with_borrow_mut(|cells| {
        if cells.is_empty() {
            cells.resize(SLOTS, ([i32::MIN; 3], [DVec3::ZERO; 81]));
        }
        let h =
            (cell[0] as u32 as u64) << 42 ^ (cell[1] as u32 as u64) << 21 ^ cell[2] as u32 as u64;
        let slot = (h.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 58) as usize;
        let (key, points) = &mut cells[slot];
        if *key != cell {
            let offsets = crackle_offsets();
            for (q, o) in points.iter_mut().zip(offsets.iter()) {
                *q = point(o);
            }
            *key = cell;
        }
        let (mut m1, mut m2, mut m3) = (dist(points[0]), dist(points[1]), dist(points[2]));
        let mut nearest = 0;
        if m2 < m1 {
            std::mem::swap(&mut m1, &mut m2);
            nearest = 1;
        }
        if m3 < m1 {
            std::mem::swap(&mut m1, &mut m3);
            nearest = 2;
        }
        if m3 < m2 {
            std::mem::swap(&mut m2, &mut m3);
        }
        for (i, q) in points.iter().enumerate().skip(3) {
            let s = dist(*q);
            if s < m1 {
                (m3, m2, m1) = (m2, m1, s);
                nearest = i;
            } else if s < m2 {
                (m3, m2) = (m2, s);
            } else if s < m3 {
                m3 = s;
            }
        }
        (m1, m2, m3, points[nearest])
    });
    if c.offset != 0.0 {
        let o = if c.metric == 2.0 {
            c.offset * c.offset
        } else if c.metric == 1.0 {
            c.offset
        } else {
            c.offset.powf(c.metric)
        };
        m1 += o;
        m2 += o;
        m3 += o;
    }
    let v = if c.solid {
        noise(nearest, generator)
    } else if c.metric == 2.0 {
        (c.form.x * m1.sqrt() + c.form.y * m2.sqrt()) + c.form.z * m3.sqrt()
    } else if c.metric == 1.0 {
        (c.form.x * m1 + c.form.y * m2) + c.form.z * m3
    } else {
        let e = 1.0 / c.metric;
        (c.form.x * m1.powf(e) + c.form.y * m2.powf(e)) + c.form.z * m3.powf(e)
    };
    v.clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checker_alternates_by_unit_cube() {
        let p = Pattern::new(PatternKind::Checker);
        assert_eq!(p.value(DVec3::new(0.5, 0.5, 0.5)), 0.0);
        assert_eq!(p.value(DVec3::new(1.5, 0.5, 0.5)), 1.0);
        assert_eq!(p.value(DVec3::new(-0.5, 0.5, 0.5)), 1.0);
        assert_eq!(p.value(DVec3::new(1.5, 1.5, 0.5)), 0.0);
    }

    #[test]
    fn gradient_wraps_negative_values() {
        let p = Pattern::new(PatternKind::Gradient(DVec3::Y));
        assert!((p.value(DVec3::new(0.0, -0.25, 0.0)) - 0.75).abs() < 1e-4);
        // POV-Ray's drift on the negative side: −50.5 gives 0.5005.
        assert!((p.value(DVec3::new(0.0, -50.5, 0.0)) - 0.5005).abs() < 1e-9);
        assert!((p.value(DVec3::new(0.0, 1.0, 0.0)) - 1.0).abs() < 1e-12);
        assert!((p.value(DVec3::new(0.0, 1.25, 0.0)) - 0.25).abs() < 1e-12);
    }

    #[test]
    fn povrays_tables_are_rebuilt_exactly() {
        // MT19937's first output with the default seed, and entries 4096 and 4097 (the last
        // that cells and crackle reach).
        let r = pattern_rands();
        assert_eq!(r[0], 3499211612.0 / 4294967296.0);
        assert_eq!(r[4096], 1069229844.0 / 4294967296.0);
        assert_eq!(r[4097], 1097566470.0 / 4294967296.0);
        let w = wave_sources();
        assert_eq!(
            w[0].0,
            DVec3::new(-0.6043782132577583, 0.4920484080339806, -0.6265902484802848)
        );
        assert_eq!(w[0].1, 0.9191158787805639);
        assert_eq!(w[9].1, 0.168513138218344);
        assert_eq!(crackle_offsets().len(), 81);
        assert_eq!(crackle_offsets()[0], [-2, -1, -1]);
    }
}
