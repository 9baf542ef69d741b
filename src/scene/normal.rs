//! Normal perturbation (POV-Ray's `Perturb_Normal`): a pattern tilts the surface normal.
//!
//! Six patterns have a perturbation of their own (bumps, dents and wrinkles from the vector
//! noise, ripples and waves from their wave sources, quilted from its rounded cubes); every
//! other pattern tilts the normal by its slope, sampled at the four corners of a small
//! tetrahedron around the point (`accuracy` apart). The normal goes into pattern space and
//! back as a normal (scaling the pattern by s scales the bumps' slopes by 1/s).

use crate::ir;
use crate::noise::{dnoise, noise};
use crate::pattern::{
    Pattern, PatternKind, Surface, cycloidal, facets_normal, quilt_cubic, quilt_offset,
};
use glam::{DMat3, DMat4, DVec3};

/// POV-Ray's sampling directions for the slope of a pattern: a regular tetrahedron.
const PYRAMID: [DVec3; 4] = [
    DVec3::new(0.942809041, -0.333333333, 0.0),
    DVec3::new(-0.471404521, -0.333333333, 0.816496581),
    DVec3::new(-0.471404521, -0.333333333, -0.816496581),
    DVec3::new(0.0, 1.0, 0.0),
];

/// A slope map's entry: value, and the height and slope there.
type SlopeEntry = (f64, [f64; 2]);

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
    /// The distance between slope samples (`accuracy`).
    accuracy: f64,
    /// `no_bump_scale`: the normal is not normalised on its way into pattern space and back.
    no_bump_scale: bool,
    /// `slope_map` entries: value, (height, slope).
    slope_map: Option<Box<[SlopeEntry]>>,
    /// `normal_map` entries: value, normal placed in this pattern's space.
    map: Option<Box<[(f64, Normal)]>>,
}

impl Normal {
    /// Whether the normal (or one in its map) is uv-mapped.
    pub fn uses_uv(&self) -> bool {
        matches!(self.pattern.kind, PatternKind::UvMapping)
            || self
                .map
                .as_ref()
                .is_some_and(|m| m.iter().any(|(_, n)| n.uses_uv()))
    }

    /// The perturbation as placed by the IR, its pattern using noise generator `generator`
    /// unless it names its own.
    pub fn new(n: &ir::Normal, scene: crate::pattern::SceneDefaults) -> Normal {
        // The placement, then the transformations among the pattern's warps.
        let mut world_from_pattern = n.transform.as_ref().map_or(DMat4::IDENTITY, |t| t.matrix);
        for w in &n.pattern.warps {
            if let crate::pattern::Warp::Transform(m) = w {
                world_from_pattern *= m.inverse();
            }
        }
        let linear = DMat3::from_mat4(world_from_pattern);
        Normal {
            pattern: n.pattern.with_scene(scene),
            amount: f64::from(n.amount as f32),
            pattern_from_world: n.transform.as_ref().map(|t| t.matrix.inverse()),
            to_pattern: linear.transpose(),
            to_world: linear.inverse().transpose(),
            accuracy: n.accuracy,
            no_bump_scale: n.no_bump_scale,
            slope_map: n.slope_map.as_ref().map(|m| m.clone().into_boxed_slice()),
            map: n
                .map
                .as_ref()
                .map(|m| m.iter().map(|(v, e)| (*v, Normal::new(e, scene))).collect()),
        }
    }

    /// The perturbed unit normal at world point `p`, for the unit normal `n` (facing the ray),
    /// off any surface.
    pub fn perturb(&self, p: DVec3, n: DVec3) -> DVec3 {
        self.perturb_on(p, n, &Surface::default())
    }

    /// The perturbed unit normal at world point `p` of `surface`, for the unit normal `n`
    /// (facing the ray).
    pub fn perturb_on(&self, p: DVec3, n: DVec3, surface: &Surface) -> DVec3 {
        // `uv_mapping`: the entry perturbs at the surface's (u, v, 0), whatever moved the normal.
        if matches!(self.pattern.kind, PatternKind::UvMapping) {
            if let Some(map) = &self.map {
                return map[0]
                    .1
                    .perturb_on(surface.uv.extend(0.0), n, surface)
                    .normalize();
            }
        }
        let q = self.pattern_from_world.map_or(p, |m| m.transform_point3(p));
        let tp = self.pattern.warp(q);
        let unit = |v: DVec3| if self.no_bump_scale { v } else { v.normalize() };
        let mut n = unit(self.to_pattern * unit(n));
        let a = self.amount;
        let pattern = &self.pattern;
        if let Some(map) = &self.map {
            // A normal_map: the entries' normals at the pattern's point, blended by the
            // pattern's value (averaged for `average`), as POV-Ray's Perturb_Normal does.
            n = if pattern.kind == crate::pattern::PatternKind::Average {
                let total: f64 = map.iter().map(|(w, _)| w).sum();
                map.iter()
                    .map(|(w, e)| e.perturb_on(tp, n, surface) * *w)
                    .fold(DVec3::ZERO, |a, b| a + b)
                    / total
            } else {
                let v = pattern.wave.apply(pattern.raw_on(tp, surface));
                let (prev, cur, t) = crate::pattern::pigment::search(map, v);
                let c = map[cur].1.perturb_on(tp, n, surface);
                if prev == cur {
                    c
                } else {
                    map[prev].1.perturb_on(tp, n, surface) * (1.0 - t) + c * t
                }
            };
            return (self.to_world * unit(n)).normalize();
        }
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
                    r += DVec3::new(
                        (d.x / scale).abs(),
                        (d.y / scale).abs(),
                        (d.z / scale).abs(),
                    );
                    scale *= 2.0;
                }
                n += a * r;
            }
            PatternKind::Ripples | PatternKind::Waves => {
                let waves = pattern.waves();
                let count = waves.len() as f64;
                for (src, f) in waves {
                    let d = tp - *src;
                    let len = d.length();
                    let len = if len == 0.0 { 1.0 } else { len };
                    let s = if matches!(pattern.kind, PatternKind::Ripples) {
                        cycloidal(len * pattern.wave.frequency + pattern.wave.phase) * a
                    } else {
                        (cycloidal(len * pattern.wave.frequency * f + pattern.wave.phase) * a) / f
                    };
                    n += (s / (len * count)) * d;
                }
            }
            PatternKind::Facets(f) => n = facets_normal(tp, n, f),
            PatternKind::BumpMap(image) => n = image.bump(tp, a, n),
            PatternKind::Quilted { control0, control1 } => {
                let q = quilt_offset(tp);
                let t = quilt_cubic(q.length(), *control0, *control1);
                n += a * (q * t);
            }
            _ => {
                // The slope, from the pattern (its wave included) at four points around.
                let k = a * -5.0 * (0.02 / self.accuracy);
                for v in PYRAMID {
                    let mut value = pattern.wave.apply(pattern.raw(tp + self.accuracy * v));
                    if let Some(map) = &self.slope_map {
                        value = slope(map, value);
                    }
                    n += (value * k) * v;
                }
            }
        }
        (self.to_world * unit(n)).normalize()
    }
}

/// POV-Ray's slope map: the height at `v`, a cubic between the entries around it through
/// their heights with their slopes.
fn slope(map: &[SlopeEntry], v: f64) -> f64 {
    let (prev, cur, t) = crate::pattern::pigment::search(map, v);
    let [p2, s2] = map[cur].1;
    if prev == cur {
        return p2;
    }
    let [p1, s1] = map[prev].1;
    let (tt, ttt) = (t * t, t * t * t);
    let mut rv = ttt * (s1 + s2 + 2.0 * (p1 - p2));
    rv += -tt * (2.0 * s1 + s2 + 3.0 * (p1 - p2));
    rv += t * s1 + p1;
    rv
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The normal of `plane { z, 0 normal { BODY } }`, as evaluated and compiled.
    fn normal_of(body: &str) -> Normal {
        let text = format!("plane {{ z, 0 normal {{ {body} }} }}");
        let loaded = crate::load_str(
            std::path::Path::new("normal.rt"),
            text,
            &crate::LoadOptions::default(),
        )
        .unwrap_or_else(|e| panic!("{body}: {e}"));
        let n = loaded.scene.objects[0]
            .texture
            .normal
            .as_deref()
            .expect("a normal");
        Normal::new(
            n,
            crate::pattern::SceneDefaults {
                generator: 2,
                waves: 10,
            },
        )
    }

    /// Perturbed normals of a plane facing −z against POV-Ray's, for every setup of the test
    /// vectors (from the reference that reproduced POV-Ray's renders of the slopes pixel for
    /// pixel at 16 bits): the dedicated perturbations, the slope method, `accuracy`,
    /// `no_bump_scale`, turbulence and scaled patterns.
    #[test]
    fn perturbed_normals_match_povray() {
        let text = include_str!("../pattern/testdata/normals.txt");
        let (mut checked, mut setups) = (0, 0);
        for block in text.split("\n@ ").skip(1) {
            let mut lines = block.lines();
            let body = lines.next().expect("a setup");
            let normal = normal_of(body);
            setups += 1;
            for line in lines.filter(|l| !l.trim().is_empty()) {
                let v: Vec<f64> = line
                    .split_whitespace()
                    .map(|x| x.parse().unwrap())
                    .collect();
                let got = normal.perturb(DVec3::new(v[0], v[1], v[2]), DVec3::NEG_Z);
                let expected = DVec3::new(v[3], v[4], v[5]).normalize();
                assert!(
                    (got - expected).length() < 1e-9,
                    "{body} at {:?}: {got} vs {expected}",
                    &v[..3]
                );
                checked += 1;
            }
        }
        assert_eq!(setups, 15);
        assert!(checked >= 200, "{checked}");
    }

    #[test]
    fn a_slope_map_is_povrays_cubic() {
        let map = [(0.0, [0.0, 1.0]), (0.5, [1.0, 0.0]), (1.0, [0.0, -1.0])];
        // At the entries: their heights; between: Hermite with the entries' slopes.
        assert_eq!(slope(&map, 0.0), 0.0);
        assert_eq!(slope(&map, 0.5), 1.0);
        let t: f64 = 0.5;
        let expected = t.powi(3) * (1.0 + 0.0 + 2.0 * (0.0 - 1.0))
            - t.powi(2) * (2.0 + 0.0 + 3.0 * (0.0 - 1.0))
            + t * 1.0;
        assert!((slope(&map, 0.25) - expected).abs() < 1e-15);
        assert_eq!(slope(&map, 2.0), 0.0);
    }
}
