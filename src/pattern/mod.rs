//! Patterns: POV-Ray 3.7's functions from a point of pattern space to a number.
//!
//! A pattern says only *where* things change, never *what* they change to: a pigment looks its
//! value up in a colour map, and later a normal, a texture map or a slope map will look up the
//! same value. Most patterns give a value in [0, 1] that then goes through the pattern's wave
//! (frequency, phase and wave shape); the discrete ones (`checker`, and later `hexagon`,
//! `brick` …) give the index of an entry of their list (0, 1, …) and skip the wave.
//!
//! Adding a pattern: a variant of [`PatternKind`], its arm in [`PatternKind::raw`] (or a
//! function in a file of this module), and the keyword's arm in the evaluator's pattern table
//! (`eval::material::pattern_kind`).

use glam::DVec3;

/// POV-Ray's tolerance in the checker pattern: `floor(x + 1e-10)`.
const CHECKER_TOLERANCE: f64 = 1e-10;

/// A pattern with its modifiers, in pattern space (the pigment or normal carries the
/// transformation into it).
#[derive(Clone, Debug, PartialEq)]
pub struct Pattern {
    /// Which function.
    pub kind: PatternKind,
    /// What happens to the function's value before it is looked up (value patterns only).
    pub wave: Wave,
}

impl Pattern {
    /// A pattern with the default wave (ramp, frequency 1, phase 0).
    pub fn new(kind: PatternKind) -> Pattern {
        Pattern {
            kind,
            wave: Wave::default(),
        }
    }

    /// The value at point `p` of pattern space: an entry index for a discrete pattern, else a
    /// value in [0, 1].
    pub fn value(&self, p: DVec3) -> f64 {
        let v = self.kind.raw(p);
        if self.kind.list_len().is_some() {
            v
        } else {
            self.wave.apply(v)
        }
    }
}

/// The pattern functions.
#[derive(Clone, Debug, PartialEq)]
pub enum PatternKind {
    /// `checker`: unit cubes, 0 where ⌊x⌋ + ⌊y⌋ + ⌊z⌋ is even, else 1 (two entries).
    Checker,
    /// `gradient V`: the fraction of `p·V̂` (unit `V̂`).
    Gradient(DVec3),
}

impl PatternKind {
    /// For a discrete pattern, how many entries its list has (its values are 0, 1, …).
    pub fn list_len(&self) -> Option<usize> {
        match self {
            PatternKind::Checker => Some(2),
            PatternKind::Gradient(_) => None,
        }
    }

    /// The function's own value at `p`, before the wave.
    pub fn raw(&self, p: DVec3) -> f64 {
        match self {
            PatternKind::Checker => {
                let k = (p.x + CHECKER_TOLERANCE).floor()
                    + (p.y + CHECKER_TOLERANCE).floor()
                    + (p.z + CHECKER_TOLERANCE).floor();
                f64::from(k.rem_euclid(2.0) != 0.0)
            }
            PatternKind::Gradient(axis) => {
                // POV-Ray: values above 1 wrap with fmod 1 (so 1.0 stays 1.0); the wave then
                // wraps the rest.
                let v = p.dot(*axis);
                if v > 1.0 { v % 1.0 } else { v }
            }
        }
    }
}

/// How a value pattern's raw value becomes the value looked up: scaled by `frequency`,
/// shifted by `phase`, wrapped into [0, 1], then shaped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wave {
    /// The wave's shape.
    pub shape: WaveShape,
    /// `frequency` (default 1).
    pub frequency: f64,
    /// `phase` (default 0).
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
}

impl Wave {
    /// The looked-up value for raw value `v`.
    pub fn apply(&self, v: f64) -> f64 {
        // POV-Ray wraps with fmod 1.00001 (so 1.0 stays 1.0) and lifts negatives into [0, 1):
        // negative values drift by 1e-5 a unit, as in POV-Ray.
        let mut v = (v * self.frequency + self.phase) % 1.00001;
        if v < 0.0 {
            v -= v.floor();
        }
        match self.shape {
            WaveShape::Ramp => v,
        }
    }
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
}
