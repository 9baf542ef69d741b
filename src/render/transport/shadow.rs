//! Shadow rays: what reaches a light through the objects between (POV-Ray's shadow walk).
//! The scene answers where a shadow ray meets what ([`Queries`]); this decides what light
//! does there: blocked by an opaque object, filtered at each crossing of a transparent one,
//! faded along the segments inside interiors that fade.

use super::medium::interior_fade;
use crate::geometry::Ray;
use crate::scene::{Queries, Rgb, Scene, ShadowCrossing, fades};
use std::cell::RefCell;

/// Two crossings of a shadow ray closer than this, relative to the distances and coordinates
/// involved, are taken for the same point (a few thousand times the rounding of a double).
const COINCIDENT: f64 = 1.0 / (1u64 << 40) as f64;

/// POV-Ray's `SHADOW_TOLERANCE`: a surface closer than this to the light casts no shadow
/// (a light on an object's surface shines out of it), and the rest of a shadow ray shorter
/// than this sees no atmosphere.
pub(super) const SHADOW_TOLERANCE: f64 = 1e-3;

/// The part of the shadow ray `ray`, which ends at its light, where surfaces may block it:
/// all but the last [`SHADOW_TOLERANCE`] before the light.
pub(super) fn blocking_part(ray: &Ray) -> Ray {
    let mut part = *ray;
    part.tmax -= SHADOW_TOLERANCE * inverse_length(ray.direction);
    part
}

/// 1 / |d|. Shadow rays' directions are unit vectors but for rounding: for those, one
/// Newton step from 1 (1.5 − |d|²/2, off by under 4·10⁻¹⁹ of the value within 10⁻⁹ of
/// unit length) instead of a square root and a division on each ray's way.
fn inverse_length(d: glam::DVec3) -> f64 {
    let squared = d.length_squared();
    if (squared - 1.0).abs() < 1e-9 {
        1.5 - 0.5 * squared
    } else {
        1.0 / squared.sqrt()
    }
}

/// What reaches the end of a shadow ray: 1 when nothing blocks it, 0 behind an opaque
/// object, and the product of `rgb·filter + transmit` over every crossing of transparent
/// objects (POV-Ray filters at each surface crossing), times the interior fade of the
/// segments run inside objects whose fade_power is positive (see `walk`). Objects with
/// `no_shadow` are skipped; refraction is ignored, as in POV-Ray.
pub fn transmittance(scene: &Scene, ray: &Ray) -> Rgb {
    transmittance_and(scene, ray, |_| Rgb::ONE)
}

/// [`transmittance`] where only the objects `candidates` can meet the ray (an area light's
/// possible blockers, [`Queries::shadow_candidates`]): the same answer, from fewer tests.
pub(super) fn transmittance_among(scene: &Scene, ray: &Ray, candidates: &[u32]) -> Rgb {
    pass(scene, ray, Some(candidates), |_| Rgb::ONE)
}

/// [`transmittance`] times what `along` makes of the crossings, in order along the ray
/// (one per point; none without transparent objects), unless no light gets through them:
/// where media dim the ray between its crossings.
pub(super) fn transmittance_and(
    scene: &Scene,
    ray: &Ray,
    along: impl FnOnce(&[ShadowCrossing]) -> Rgb,
) -> Rgb {
    pass(scene, ray, None, along)
}

/// [`transmittance_and`] over the objects `among` (all if `None`).
fn pass(
    scene: &Scene,
    ray: &Ray,
    among: Option<&[u32]>,
    along: impl FnOnce(&[ShadowCrossing]) -> Rgb,
) -> Rgb {
    // Without transparent objects, any opaque blocker (the search stops at the first);
    // else the crossings of the transparent ones too, in the same pass.
    let ray = &blocking_part(ray);
    if !scene.any_transparent() {
        let blocked = match among {
            None => blocked(scene, ray, &mut None),
            Some(candidates) => scene.blocked_among(ray, candidates),
        };
        if blocked {
            return Rgb::ZERO;
        }
        return along(&[]);
    }
    thread_local! {
        /// Per thread: the crossings and the list of media.
        static SCRATCH: RefCell<(Vec<ShadowCrossing>, Vec<u32>)> =
            const { RefCell::new((Vec::new(), Vec::new())) };
    }
    SCRATCH.with_borrow_mut(|(crossings, media)| {
        crossings.clear();
        media.clear();
        let blocked = match among {
            None => scene.shadow_pass(ray, crossings),
            Some(candidates) => scene.shadow_pass_among(ray, candidates, crossings),
        };
        if blocked {
            return Rgb::ZERO;
        }
        if crossings.is_empty() {
            // (Most shadow rays cross nothing: the light arrives whole.)
            return along(&[]);
        }
        distinct(ray, crossings);
        let through = walk(scene, ray, crossings, media);
        if through == Rgb::ZERO {
            return through;
        }
        through * along(crossings)
    })
}

/// [`transmittance`] in a scene without transparent objects (0 or 1), testing first `last`,
/// the object that blocked the last blocked ray toward the same light, and leaving this
/// ray's blocker there: POV-Ray's shadow cache (neighbouring points are mostly shadowed by
/// the same object, found with one test instead of a walk through the object tree).
pub(super) fn opaque_transmittance(scene: &Scene, ray: &Ray, last: &mut Option<u32>) -> Rgb {
    debug_assert!(!scene.any_transparent());
    if blocked(scene, &blocking_part(ray), last) {
        Rgb::ZERO
    } else {
        Rgb::ONE
    }
}

/// Whether an opaque object blocks `part`, a shadow ray's blocking part, testing first the
/// object `last` holds (none for a ray without a cache) and leaving the blocker there.
fn blocked(scene: &Scene, part: &Ray, last: &mut Option<u32>) -> bool {
    if last.is_some_and(|i| scene.blocks(part, i)) {
        return true;
    }
    let blocker = scene.blocker(part, *last);
    if blocker.is_some() {
        *last = blocker;
    }
    blocker.is_some()
}

/// Sorts a shadow ray's crossings along it and drops each at the same point as the one
/// kept before (a duplicated surface): POV-Ray's walk starts each step at the crossing
/// before, so it meets such a surface once.
fn distinct(ray: &Ray, crossings: &mut Vec<ShadowCrossing>) {
    if crossings.len() < 2 {
        return;
    }
    crossings.sort_by(|a, b| a.t.total_cmp(&b.t).then(a.object.0.cmp(&b.object.0)));
    // (Crossings closer than rounding to the one kept before are the same point.)
    let length = ray.direction.length();
    let scale = ray.origin.abs().max_element().max(1.0);
    let mut kept = f64::NEG_INFINITY;
    crossings.retain(|c| {
        let world = c.t * length;
        let same = world - kept <= COINCIDENT * scale.max(world.abs());
        if !same {
            kept = world;
        }
        !same
    });
}

/// What a shadow ray lets through the transparent objects it crosses (in order, one per
/// point: [`distinct`]): POV-Ray's walk from the surface to the light, one crossing after
/// the other, each filtering the light. Where interiors fade, the walk also keeps a list of the media the ray is in. At a
/// crossing of an object whose medium is listed, the ray leaves it, and the medium's fade
/// applies over the distance from the previous crossing of any object (so a medium
/// shared by overlapping union members fades only between their surfaces, and an object
/// around another fades only from the inner one's exit); otherwise it enters. The list
/// starts with the media of the crossed objects that contain the ray's origin.
fn walk(scene: &Scene, ray: &Ray, crossings: &[ShadowCrossing], media: &mut Vec<u32>) -> Rgb {
    // (Where no crossed object's interior fades, the list of media changes nothing: the
    // product of the filters, in the same order.)
    let fading = |c: &ShadowCrossing| fades(scene.interior(scene.object(c.object)));
    if !scene.shadow_fades() || !crossings.iter().any(fading) {
        return crossings
            .iter()
            .map(|c| scene.crossing_filter(ray, c))
            .fold(Rgb::ONE, |a, b| a * b);
    }
    for c in crossings.iter() {
        let medium = scene.object(c.object).medium;
        if !media.contains(&medium) && scene.inside(c.object, ray.origin) {
            media.push(medium);
        }
    }
    let length = ray.direction.length();
    let (mut through, mut last_t) = (Rgb::ONE, 0.0);
    for c in crossings.iter() {
        let object = scene.object(c.object);
        through *= scene.crossing_filter(ray, c);
        match media.iter().position(|&m| m == object.medium) {
            Some(k) => {
                let interior = scene.interior(object);
                if fades(interior) {
                    through *= interior_fade(interior, (c.t - last_t) * length);
                }
                media.remove(k);
            }
            None => media.push(object.medium),
        }
        last_t = c.t;
    }
    through
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// The shadow cache changes no answer: whatever object it holds (none, one that blocks
    /// the ray, one that does not, a plane, a transformed object, one that casts no shadow),
    /// a ray's transmittance is the walk's, and a blocked ray leaves an object that blocks it
    /// there. Among many objects (an object tree) and few (a list).
    #[test]
    fn the_shadow_cache_gives_the_walks_answer() {
        for count in [6, 300] {
            let mut random = crate::testing::Xorshift(0xcace + count);
            let mut text = String::from("plane { y, -3 pigment { rgb 1 } }\n");
            for k in 0..count {
                let mut at = || (random.unit() * 2.0 - 1.0) * 6.0;
                let (x, y, z) = (at(), at(), at());
                let extra = match k % 5 {
                    0 => "scale <1, 0.3, 2> rotate 30*x",
                    1 => "no_shadow",
                    _ => "",
                };
                let r = 0.3 + random.unit() * 0.04 * 300.0 / count as f64;
                text += &format!("sphere {{ <{x}, {y}, {z}>, {r} pigment {{ rgb 1 }} {extra} }}\n");
            }
            let scene = crate::testing::scene(text);
            let objects = scene.object_count() as u32;
            let (mut blocked, mut cached) = (0, 0);
            let (mut from, mut to, mut prev) = (DVec3::ZERO, DVec3::X, None);
            for k in 0..4000 {
                let mut at = || (random.unit() * 2.0 - 1.0) * 9.0;
                // (Every other ray runs next to the one before, holding what that one left,
                // as the rays of neighbouring points do.)
                let held = if k % 2 == 0 {
                    (from, to) = (DVec3::new(at(), at(), at()), DVec3::new(at(), at(), at()));
                    let start = random.next_u64() % u64::from(objects + 1);
                    (start < u64::from(objects)).then_some(start as u32)
                } else {
                    from += DVec3::new(at(), at(), at()) * 0.002;
                    prev
                };
                let mut ray = Ray::new(from, (to - from).normalize());
                ray.tmax = (to - from).length();
                let walk = transmittance(&scene, &ray);
                let mut last = held;
                let seen = opaque_transmittance(&scene, &ray, &mut last);
                assert_eq!(seen, walk, "{from} to {to}, holding {held:?}");
                if walk == Rgb::ZERO {
                    blocked += 1;
                    let i = last.expect("a blocked ray leaves its blocker");
                    assert!(scene.blocks(&blocking_part(&ray), i));
                    cached += usize::from(last == held);
                } else {
                    assert_eq!(last, held);
                }
                prev = last;
            }
            assert!(
                blocked > 500 && cached > 300,
                "{count}: {blocked} blocked, {cached} by the cache"
            );
        }
    }

    /// The inverse length of a normalised direction (the shadow rays') is the division's to
    /// within a few units of rounding (parts in 10¹⁶), and that of any other vector is the
    /// division's.
    #[test]
    fn inverse_lengths_of_unit_and_other_directions() {
        let mut random = crate::testing::Xorshift(0x5eed_1e57);
        for _ in 0..100_000 {
            let v = DVec3::new(random.unit(), random.unit(), random.unit()) * 2.0 - 1.0;
            if v.length() < 1e-3 {
                continue;
            }
            let unit = v / v.length();
            let exact = 1.0 / unit.length();
            assert!((inverse_length(unit) - exact).abs() <= 4.0 * f64::EPSILON * exact);
            assert_eq!(inverse_length(v * 3.0), 1.0 / (v * 3.0).length());
        }
    }
}
