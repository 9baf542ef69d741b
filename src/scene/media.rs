//! Participating media ready for transport: an interior's `media { … }` blocks and the
//! atmosphere, their densities placed in the world and what POV-Ray derives from them when the
//! scene is read (`Media::PostProcess`): the extinction, which effects are used, the
//! thresholds methods 1 and 2 take more samples by.

use super::{PlacedPigment, Rgb};
use crate::ir;
use glam::DVec3;

/// How a medium scatters light toward the viewer (POV-Ray's five phase functions, none
/// normalised by 1/(4π), the Mie ones not even to a mean of 1: POV-Ray's constants).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Phase {
    /// Type 1 (and any unknown type): the same in every direction.
    Isotropic,
    /// Type 2.
    MieHazy,
    /// Type 3.
    MieMurky,
    /// Type 4.
    Rayleigh,
    /// Type 5 with its eccentricity g (forward scattering for g > 0).
    HenyeyGreenstein(f64),
}

impl Phase {
    /// The phase value for `alpha`, the cosine between the direction toward the light and
    /// the ray's direction (1: the light shines straight at the viewer through the medium).
    pub fn value(self, alpha: f64) -> f64 {
        match self {
            Phase::Isotropic => 1.0,
            Phase::MieHazy => 0.576655375 * (1.0 + 9.0 * (0.5 * (1.0 + alpha)).powi(8)),
            Phase::MieMurky => 0.495714547 * (1.0 + 50.0 * (0.5 * (1.0 + alpha)).powi(32)),
            Phase::Rayleigh => 0.799372013 * (1.0 + alpha * alpha),
            Phase::HenyeyGreenstein(g) => (1.0 - g * g) / (1.0 + g * g - 2.0 * g * alpha).powf(1.5),
        }
    }
}

/// One `media { … }` block, placed in the world.
#[derive(Clone, Debug, PartialEq)]
pub struct Media {
    /// 1, 2 or 3.
    pub method: u32,
    /// `intervals`.
    pub intervals: u32,
    /// `samples` (least, most).
    pub samples: (u32, u32),
    /// `ratio`.
    pub ratio: f64,
    /// `jitter`.
    pub jitter: f64,
    /// `aa_threshold`.
    pub aa_threshold: f64,
    /// `aa_level`.
    pub aa_level: u32,
    /// Emission per unit length.
    pub emission: Rgb,
    /// Scattering per unit length.
    pub scattering: Rgb,
    /// Absorption plus `extinction` times scattering: what dims light per unit length.
    pub extinction: Rgb,
    /// The phase function.
    pub phase: Phase,
    /// The densities, multiplied (the last written first).
    pub densities: Vec<PlacedPigment>,
    /// Whether the medium dims light at all (absorption or scattering given, even with
    /// `extinction 0`: POV-Ray's test).
    pub dims: bool,
    /// Whether it scatters light.
    pub scatters: bool,
    /// Methods 1 and 2: the variance under which an interval with n samples takes no more
    /// (index n − 1).
    pub thresholds: Vec<f64>,
}

impl Media {
    /// The medium of an IR `media` block, its patterns using the scene's defaults.
    pub fn new(m: &ir::Media, scene: crate::pattern::SceneDefaults) -> Media {
        let phase = match m.scattering_type {
            2 => Phase::MieHazy,
            3 => Phase::MieMurky,
            4 => Phase::Rayleigh,
            5 => Phase::HenyeyGreenstein(m.eccentricity),
            _ => Phase::Isotropic,
        };
        let max = m.samples.1.max(1) as usize;
        let mut thresholds = vec![0.0; max];
        if max > 1 {
            let q = super::blur::chi_square_quantile((max - 1) as f64, m.confidence);
            let t = if q > 0.0 {
                m.variance / q
            } else {
                m.variance * 1e-10
            };
            for (i, th) in thresholds.iter_mut().enumerate() {
                *th = t * super::blur::chi_square_quantile((i + 1) as f64, m.confidence);
            }
        }
        Media {
            method: m.method,
            intervals: m.intervals,
            samples: m.samples,
            ratio: m.ratio,
            jitter: m.jitter,
            aa_threshold: m.aa_threshold,
            aa_level: m.aa_level,
            emission: m.emission,
            scattering: m.scattering,
            extinction: m.absorption + m.scattering * m.extinction,
            phase,
            densities: m.densities.iter().map(|d| d.placed(scene)).collect(),
            dims: m.absorption != Rgb::ZERO || m.scattering != Rgb::ZERO,
            scatters: m.scattering != Rgb::ZERO,
            thresholds,
        }
    }

    /// The density at world point `p`, per channel: the product of the densities (1
    /// without any).
    #[inline]
    pub fn density(&self, p: DVec3) -> Rgb {
        let mut d = Rgb::ONE;
        for pigment in &self.densities {
            d *= pigment.colour_at(p).rgb;
            // (Nothing multiplies a zero back: the densities after it are not looked at.)
            if d == Rgb::ZERO {
                break;
            }
        }
        d
    }

    /// Whether the medium has no density or its last-written density is a plain colour
    /// (POV-Ray then takes a shadow ray's optical depth from one sample per interval).
    pub fn plain_head(&self) -> bool {
        self.densities.first().is_none_or(PlacedPigment::is_solid)
    }

    /// Whether the density is the same everywhere (no `density` block).
    pub fn constant(&self) -> bool {
        self.densities.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::Phase;

    /// POV-Ray's values at α = −0.7071 (a parallel light behind the camera, 45° up),
    /// measured on its renders of boxes scattering 0.1 over a depth of 4: 0.4·k.
    #[test]
    fn phase_functions_give_povray_s_values() {
        let alpha = -std::f64::consts::FRAC_1_SQRT_2;
        let cases = [
            (Phase::Isotropic, 0.40000),
            (Phase::MieHazy, 0.23066),
            (Phase::MieMurky, 0.19829),
            (Phase::Rayleigh, 0.47962),
            (Phase::HenyeyGreenstein(0.5), 0.10958),
            (Phase::HenyeyGreenstein(-0.5), 0.74998),
            (Phase::HenyeyGreenstein(0.0), 0.40000),
        ];
        for (phase, povray) in cases {
            let v = 0.4 * phase.value(alpha);
            assert!(
                (v - povray).abs() < 2e-5,
                "{phase:?}: {v}, POV-Ray {povray}"
            );
        }
    }
}
