//! Fog over a ray segment (POV-Ray's ComputeFog).

use crate::scene::{FogKind, Rgb, Scene};
use glam::DVec3;

/// POV-Ray's `BOUND_HUGE`: the depth of a ray that hits nothing, as fog sees it.
pub(super) const MISS_DEPTH: f64 = 2.0e10;

/// The fogs of `scene` over a ray segment from `origin` along the unit `direction`, `width`
/// long, applied to the colour `c` seen at its end (POV-Ray's ComputeFog: attenuations
/// multiply, fog colours add up, so the fogs' order does not matter).
pub(super) fn fogged(scene: &Scene, origin: DVec3, direction: DVec3, depth: f64, c: Rgb) -> Rgb {
    let (attenuation, added) = fog_terms(scene, origin, direction, depth);
    added + attenuation * c
}

/// What the fogs let through of a segment's light: [`fogged`] without the fogs' own colour
/// (what a shadow ray sees of them).
pub(super) fn fog_attenuation(scene: &Scene, origin: DVec3, direction: DVec3, depth: f64) -> Rgb {
    fog_terms(scene, origin, direction, depth).0
}

/// The fogs' attenuation of the light at a segment's end and the colour they add.
fn fog_terms(scene: &Scene, origin: DVec3, direction: DVec3, depth: f64) -> (Rgb, Rgb) {
    let (mut attenuation, mut added) = (Rgb::ONE, Rgb::ZERO);
    for fog in scene.fogs() {
        let mut width = depth;
        let density = match fog.kind {
            FogKind::Constant => 1.0,
            FogKind::Ground { offset, alt, up } => {
                // Mean over the segment of 1 below the offset and 1/(h² + 1) above it.
                let s = (origin.dot(up) - offset) / alt;
                let e = ((origin + direction * width).dot(up) - offset) / alt;
                match (s <= 0.0, e <= 0.0) {
                    (true, true) => 1.0,
                    (true, false) => (e.atan() - s) / (e - s),
                    (false, true) => (s.atan() - e) / (s - e),
                    (false, false) if (s - e).abs() > 1e-10 => (s.atan() - e.atan()) / (s - e),
                    (false, false) => 1.0 / (s * s + 1.0),
                }
            }
        };
        if let Some(t) = &fog.turbulence {
            // POV-Ray thins the fog by its turbulence at the middle of the path, the less the
            // longer the path.
            let p = (origin + direction * (width / 2.0)) * t.turbulence.amount;
            let k = (-width / fog.distance).exp();
            let turb = t.turbulence.scalar(p, scene.noise_generator());
            width *= 1.0 - k * (turb * t.depth).min(1.0);
        }
        let c = &fog.colour;
        let a = (-width * density / fog.distance).exp().max(c.transmit);
        attenuation *= a * (Rgb::splat(1.0 - c.filter) + c.rgb * c.filter);
        added += c.rgb * (1.0 - a);
    }
    (attenuation, added)
}
