//! The media a ray is in (the medium stack, POV-Ray's interior list), what crossing a surface
//! does to it (refraction's and Fresnel's ratios of indices), and the interior fade.

use crate::scene::{Interior, ObjectId, Queries, Rgb, Scene};
use glam::DVec3;

/// |η − 1| below this counts as "no change of medium" (POV-Ray's test).
pub(super) const SAME_IOR: f64 = 1e-10;

/// Most media a ray can be inside at once (deeper nesting is not tracked).
pub(super) const MAX_NESTING: usize = 8;

/// The media a ray is inside, in the order it entered them (POV-Ray's interior list): what
/// transmitted and reflected rays carry, what decides refraction's indices and whether fog
/// reaches the ray, and what participating media will read. Each entry is an object standing
/// for its medium: objects that share a medium (members of a union) share one entry, so a ray
/// inside one member that meets another's surface leaves. Entering and leaving happen only in
/// [`Refraction::new`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MediumStack {
    ids: [u32; MAX_NESTING],
    len: usize,
}

impl MediumStack {
    /// The objects of `scene` whose inside contains `p` (a camera ray's list). The order is
    /// POV-Ray's: scene order for fewer than three objects and lights; otherwise, as its
    /// bounding does, unbounded objects (planes) first. Like POV-Ray, which splits unions
    /// into their members, a medium is listed once per member that contains `p`.
    pub fn at(scene: &Scene, p: DVec3) -> MediumStack {
        let mut list = MediumStack::default();
        let mut later = MediumStack::default();
        let bounded_last = scene.bounded_last();
        // (The unbounded ones first when the bounded come last.)
        scene.enclosing(p, |id| match bounded_last && scene.object(id).bounded {
            false => list.push(id),
            true => later.push(id),
        });
        for &i in &later.ids[..later.len] {
            list.push(ObjectId(i));
        }
        list
    }

    pub(super) fn push(&mut self, id: ObjectId) {
        if self.len < MAX_NESTING {
            self.ids[self.len] = id.0;
            self.len += 1;
        }
    }

    /// Where the medium of object `id` is in the list.
    pub(super) fn position(&self, scene: &Scene, id: ObjectId) -> Option<usize> {
        let medium = |i: u32| scene.object(ObjectId(i)).medium;
        self.ids[..self.len]
            .iter()
            .position(|&i| medium(i) == medium(id.0))
    }

    pub(super) fn remove(&mut self, index: usize) {
        self.ids.copy_within(index + 1..self.len, index);
        self.len -= 1;
    }

    pub(super) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The objects listed, in the order entered.
    pub(super) fn objects(&self) -> impl Iterator<Item = ObjectId> + '_ {
        self.ids[..self.len].iter().map(|&i| ObjectId(i))
    }

    pub(super) fn last(&self) -> Option<ObjectId> {
        (self.len > 0).then(|| ObjectId(self.ids[self.len - 1]))
    }

    /// Whether a ray here travels through hollow space only (fog and media reach it):
    /// inside no object, or inside hollow ones only.
    pub(super) fn hollow_space(&self, scene: &Scene) -> bool {
        self.ids[..self.len]
            .iter()
            .all(|&i| scene.object(ObjectId(i)).hollow)
    }
}

/// POV-Ray's interior fade over a distance `d` inside (§9.2).
pub(super) fn interior_fade(interior: &Interior, d: f64) -> Rgb {
    let fc = interior.fade_colour;
    if interior.fade_power >= 1000.0 {
        let k = d / interior.fade_distance;
        Rgb::new(
            (-(1.0 - fc.x) * k).exp(),
            (-(1.0 - fc.y) * k).exp(),
            (-(1.0 - fc.z) * k).exp(),
        )
    } else {
        fc + (Rgb::ONE - fc) / (1.0 + (d / interior.fade_distance).powf(interior.fade_power))
    }
}

/// What crossing one object's surface means for a ray (POV-Ray §9.1).
pub(super) struct Refraction {
    /// The ray was inside the object.
    pub(super) inside: bool,
    /// n_from / n_to for the refraction direction.
    pub(super) refraction_eta: f64,
    /// The dispersions' ratio, from / to, as [`Refraction::refraction_eta`] (1: none).
    pub(super) dispersion: f64,
    /// How many wavelengths a dispersing refraction traces.
    pub(super) bands: u32,
    /// n_to / n_from as POV-Ray's `ComputeRelativeIOR` gives it to the Fresnel term.
    pub(super) fresnel_eta: f64,
    /// The interior list of the transmitted ray.
    pub(super) after: MediumStack,
}

impl Refraction {
    pub(super) fn new(scene: &Scene, list: &MediumStack, o: ObjectId) -> Refraction {
        let interior = |id: ObjectId| scene.interior(scene.object(id));
        let ior = |id: ObjectId| interior(id).ior;
        let n_o = ior(o);
        let (d_o, bands_o) = (interior(o).dispersion, interior(o).dispersion_samples);
        let mut after = *list;
        let position = list.position(scene, o);
        // The medium entered last is `o`'s (POV-Ray compares interiors, not objects).
        let innermost = list
            .last()
            .is_some_and(|l| scene.object(l).medium == scene.object(o).medium);
        let (refraction_eta, dispersion, bands) = match (position, list.last()) {
            // Entering from air.
            (None, None) => {
                after.push(o);
                (1.0 / n_o, 1.0 / d_o, bands_o)
            }
            // Entering while inside others.
            (None, Some(last)) => {
                after.push(o);
                (ior(last) / n_o, interior(last).dispersion / d_o, bands_o)
            }
            // Leaving the innermost medium (into another: the more bands of the two).
            (Some(i), Some(_)) if innermost => {
                after.remove(i);
                match after.last() {
                    None => (n_o, d_o, bands_o),
                    Some(next) => (
                        n_o / ior(next),
                        d_o / interior(next).dispersion,
                        bands_o.max(interior(next).dispersion_samples),
                    ),
                }
            }
            // Leaving an object that is not the innermost: no bending.
            (Some(i), _) => {
                after.remove(i);
                (1.0, 1.0, bands_o)
            }
        };
        let fresnel_eta = match (position.is_some(), list.last()) {
            (_, None) => n_o,
            (true, Some(_)) if list.len == 1 => 1.0 / n_o,
            (true, Some(last)) => ior(last) / n_o,
            (false, Some(last)) => n_o / ior(last),
        };
        Refraction {
            inside: position.is_some(),
            refraction_eta,
            dispersion,
            bands,
            fresnel_eta,
            after,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The objects a point starts in, found through the object tree's boxes, are those (in
    /// the same order, the unbounded ones first) that testing every object finds.
    #[test]
    fn starting_objects_through_the_tree_are_those_of_a_scan() {
        // Ten nested spheres (bounded: the scene has a tree), a plane below (unbounded) and a
        // disc whose inside is a half-space but whose box is flat.
        let mut text = String::from("#version 3.7;\nplane { y, -20 }\ndisc { 0, y, 30 }\n");
        for k in 1..=10 {
            text += &format!("sphere {{ <0.1, 0, 0>, {k} pigment {{ rgb 1 }} }}\n");
        }
        let loaded = crate::load_str(
            std::path::Path::new("nest.rt"),
            text,
            &crate::LoadOptions::default(),
        )
        .expect("loads");
        let scene = crate::scene::Scene::build(&loaded.scene);
        assert!(scene.has_index());
        let scan = |p: DVec3| {
            let mut list = MediumStack::default();
            for pass in [false, true] {
                for i in 0..scene.object_count() {
                    let object = scene.object(ObjectId(i as u32));
                    let second = scene.bounded_last() && object.bounded;
                    if second == pass && scene.starts_inside(ObjectId(i as u32), p) {
                        list.push(ObjectId(i as u32));
                    }
                }
            }
            list.ids[..list.len].to_vec()
        };
        for p in [
            DVec3::ZERO,
            DVec3::new(0.0, 3.5, 0.0),
            DVec3::new(7.2, -1.0, 2.0),
            DVec3::new(0.0, -25.0, 0.0),
            DVec3::splat(40.0),
        ] {
            let found = MediumStack::at(&scene, p);
            assert_eq!(found.ids[..found.len].to_vec(), scan(p), "{p}");
        }
    }
}
