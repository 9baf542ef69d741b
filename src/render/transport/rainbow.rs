//! Rainbows over a ray (POV-Ray's ComputeRainbow): each ring the ray looks through lays its
//! colour over what the ray sees, the more the farther that is.

use super::media::Numbers;
use crate::geometry::Ray;
use crate::scene::{Rainbow, Rgb, colour_map_at};

/// POV-Ray's `EPSILON`: a map index this close below 1 is past the ring.
const EPSILON: f64 = 1e-10;

/// `colour`, seen at `depth` along `ray` (unit direction, in hollow space), under
/// `rainbows`, and what is left of the ray's transmit (for the alpha channel). The rings the
/// ray looks through give the mean of their blends; a ray through none keeps its colour.
pub(super) fn rainbowed(rainbows: &[Rainbow], ray: &Ray, depth: f64, colour: Rgb) -> (Rgb, f64) {
    let d = ray.direction;
    let (mut sum, mut transmit, mut seen) = (Rgb::ZERO, 1.0, 0u32);
    let mut numbers = None;
    for r in rainbows {
        // The ray's angle from `up`, in the plane of `up` and `right`.
        let (x, mut y) = (d.dot(r.right), d.dot(r.up));
        let l = x * x + y * y;
        if l > 0.0 {
            y /= l.sqrt();
        }
        let angle = y.acos().abs();
        // (A NaN angle, from rounding past 1, is outside the arc, as in POV-Ray.)
        if angle.is_nan() || angle > r.arc_angle {
            continue;
        }
        let cos = d.dot(r.antisolar);
        if cos < 0.0 {
            continue;
        }
        let mut index = (cos.acos() - r.angle) / r.width;
        if r.jitter > 0.0 {
            let n = numbers.get_or_insert_with(|| Numbers::along(ray.origin, d));
            index += (2.0 * n.next() - 1.0) * r.jitter;
        }
        if !(0.0..=1.0 - EPSILON).contains(&index) {
            continue;
        }
        let c = colour_map_at(&r.colours.entries, index);
        let falloff_width = r.arc_angle - r.falloff_angle;
        let fade = if falloff_width > 0.0 && angle > r.falloff_angle {
            let f = (angle - r.falloff_angle) / falloff_width;
            (3.0 - 2.0 * f) * f * f
        } else {
            0.0
        };
        // What the ring lets through: the farther the surface the less, never below the
        // colour's transmit (more as the arc fades out).
        let k = (-depth / r.distance)
            .exp()
            .max(fade * (1.0 - c.transmit) + c.transmit);
        let ki = 1.0 - k;
        let filter = c.filter * ki;
        sum += k * colour * (Rgb::splat(1.0 - filter) + filter * c.rgb) + ki * c.rgb;
        transmit *= k * c.transmit;
        seen += 1;
    }
    if seen == 0 {
        return (colour, 1.0);
    }
    (sum / f64::from(seen), transmit)
}
