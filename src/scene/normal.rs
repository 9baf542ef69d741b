//! Normal perturbation (POV-Ray's `Perturb_Normal`): a pattern tilts the surface normal.
//!
//! Six patterns have a perturbation of their own (bumps, dents and wrinkles from the vector
//! noise, ripples and waves from their wave sources, quilted from its rounded cubes); every
//! other pattern tilts the normal by its slope, sampled at the four corners of a small
//! tetrahedron around the point (`accuracy` apart). The normal goes into pattern space and
//! back as a normal (scaling the pattern by s scales the bumps' slopes by 1/s).

use crate::ir;
use crate::pattern::noise::{dnoise, noise};
use crate::pattern::{Pattern, PatternKind, cycloidal, quilt_cubic, quilt_offset, wave_sources};
use glam::{DMat3, DMat4, DVec3};

/// POV-Ray's sampling directions for the slope of a pattern: a regular tetrahedron.
const PYRAMID: [DVec3; 4] = [
    DVec3::new(0.942809041, -0.333333333, 0.0),
    DVec3::new(-0.471404521, -0.333333333, 0.816496581),
    DVec3::new(-0.471404521, -0.333333333, -0.816496581),
    DVec3::new(0.0, 1.0, 0.0),
];

/// The distance between slope samples (`accuracy`, default 0.02; single precision in POV-Ray).
const ACCURACY: f64 = 0.02f32 as f64;

/// A normal perturbation placed in the world.
#[derive(Clone, Debug, PartialEq)]
pub struct Normal {
    pattern: Pattern,
    /// The bump amount (single precision, as POV-Ray keeps it).
    amount: f64,
    /// Pattern space from world space (points), if placed.
    pattern_from_world: Option<DMat4>,
    /// World normals into pattern space and back (the transposed linear parts of the
    /// placement and of its inverse).
    to_pattern: DMat3,
    to_world: DMat3,
}

impl Normal {
    /// The perturbation as placed by the IR, its pattern using noise generator `generator`
    /// unless it names its own.
    pub fn new(n: &ir::Normal, generator: u8) -> Normal {
        // The placement, then the transformations among the pattern's warps.
        let mut world_from_pattern = n.transform.as_ref().map_or(DMat4::IDENTITY, |t| t.matrix);
        for w in &n.pattern.warps {
            if let crate::pattern::Warp::Transform(m) = w {
                world_from_pattern *= m.inverse();
            }
        }
        let linear = DMat3::from_mat4(world_from_pattern);
        Normal {
            pattern: n.pattern.with_generator(generator),
            amount: f64::from(n.amount as f32),
            pattern_from_world: n.transform.as_ref().map(|t| t.matrix.inverse()),
            to_pattern: linear.transpose(),
            to_world: linear.inverse().transpose(),
        }
    }

    /// The perturbed unit normal at world point `p`, for the unit normal `n` (facing the ray).
    pub fn perturb(&self, p: DVec3, n: DVec3) -> DVec3 {
        let q = self.pattern_from_world.map_or(p, |m| m.transform_point3(p));
        let tp = self.pattern.warp(q);
        let mut n = (self.to_pattern * n.normalize()).normalize();
        let a = self.amount;
        let pattern = &self.pattern;
        match &pattern.kind {
            PatternKind::Bumps => n += a * dnoise(tp),
            PatternKind::Dents => {
                let v = noise(tp, pattern.generator());
                n += ((v * v) * v * a) * dnoise(tp);
            }
            PatternKind::Wrinkles => {
                let mut r = DVec3::ZERO;
                let mut scale = 1.0;
                for _ in 0..10 {
                    let d = dnoise(tp * scale);
                    r += DVec3::new((d.x / scale).abs(), (d.y / scale).abs(), (d.z / scale).abs());
                    scale *= 2.0;
                }
                n += a * r;
            }
            PatternKind::Ripples | PatternKind::Waves => {
                let waves = wave_sources();
                let count = waves.len() as f64;
                for (src, f) in waves {
                    let d = tp - *src;
                    let len = d.length();
                    let len = if len == 0.0 { 1.0 } else { len };
                    let s = if pattern.kind == PatternKind::Ripples {
                        cycloidal(len * pattern.wave.frequency + pattern.wave.phase) * a
                    } else {
                        (cycloidal(len * pattern.wave.frequency * f + pattern.wave.phase) * a) / f
                    };
                    n += (s / (len * count)) * d;
                }
            }
            PatternKind::Quilted { control0, control1 } => {
                let q = quilt_offset(tp);
                let t = quilt_cubic(q.length(), *control0, *control1);
                n += a * (q * t);
            }
            _ => {
                // The slope, from the pattern (its wave included) at four points around.
                let k = a * -5.0 * (0.02 / ACCURACY);
                for v in PYRAMID {
                    let value = pattern.wave.apply(pattern.raw(tp + ACCURACY * v));
                    n += (value * k) * v;
                }
            }
        }
        (self.to_world * n.normalize()).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pattern::noise::Turbulence;

    /// Perturbed normals of a plane facing −z against POV-Ray's (from the reference that
    /// reproduced POV-Ray's renders of the slopes pixel for pixel at 16 bits).
    #[test]
    fn perturbed_normals_match_povray() {
        let cases: Vec<(&str, Normal)> = vec![
            ("bumps 0.5", normal(PatternKind::Bumps, 0.5, |_| {})),
            ("dents 0.7", normal(PatternKind::Dents, 0.7, |_| {})),
            ("wrinkles 0.6", normal(PatternKind::Wrinkles, 0.6, |_| {})),
            ("ripples 0.4", normal(PatternKind::Ripples, 0.4, |_| {})),
            (
                "ripples 0.4 frequency 2 phase 0.3",
                normal(PatternKind::Ripples, 0.4, |p| {
                    p.wave.frequency = 2.0;
                    p.wave.phase = f64::from(0.3f32);
                }),
            ),
            (
                "waves 0.4 frequency 3",
                normal(PatternKind::Waves, 0.4, |p| p.wave.frequency = 3.0),
            ),
            (
                "quilted 0.6",
                normal(
                    PatternKind::Quilted {
                        control0: 1.0,
                        control1: 1.0,
                    },
                    0.6,
                    |_| {},
                ),
            ),
            ("granite 0.5", normal(PatternKind::Granite, 0.5, |_| {})),
            ("bozo 0.5", normal(PatternKind::Bozo, 0.5, |_| {})),
            (
                "marble 0.9 turbulence 0.5",
                normal(PatternKind::Marble, 0.9, |p| {
                    p.turbulence = Some(Box::new(Turbulence {
                        amount: DVec3::splat(0.5),
                        ..Turbulence::default()
                    }))
                }),
            ),
        ];
        let text = include_str!("../pattern/testdata/normals.txt");
        let mut checked = 0;
        for (name, normal) in &cases {
            let block = text
                .split("@ ")
                .find(|b| b.lines().next() == Some(*name))
                .unwrap_or_else(|| panic!("no vectors for {name}"));
            for line in block.lines().skip(1).filter(|l| !l.trim().is_empty()) {
                let v: Vec<f64> = line.split_whitespace().map(|x| x.parse().unwrap()).collect();
                let got = normal.perturb(DVec3::new(v[0], v[1], v[2]), DVec3::NEG_Z);
                let expected = DVec3::new(v[3], v[4], v[5]);
                assert!(
                    (got - expected).length() < 1e-12,
                    "{name} at {:?}: {got} vs {expected}",
                    &v[..3]
                );
                checked += 1;
            }
        }
        assert!(checked >= 150, "{checked}");
    }

    fn normal(kind: PatternKind, amount: f64, edit: impl FnOnce(&mut Pattern)) -> Normal {
        let mut pattern = Pattern::new(kind);
        edit(&mut pattern);
        Normal::new(
            &ir::Normal {
                pattern,
                amount,
                transform: None,
            },
            2,
        )
    }
}
