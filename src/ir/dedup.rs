//! Deduplication, a pass over the IR: the scene's distinct textures and interiors, and which
//! of them each object has. The build stores each distinct value once (and so does the
//! evaluation for finishes and interiors as it reads them).

use super::{Interior, PigmentKind, Scene, Texture, Transform};
use rayon::prelude::*;

/// A cheap hash of the parts of a texture that most often differ (pattern kind, colour, main
/// finish amounts); textures with equal fingerprints are then compared in full.
fn fingerprint(t: &Texture) -> u64 {
    let (kind, colour) = match &t.pigment.kind {
        PigmentKind::Solid(c) => (0, Some(c)),
        PigmentKind::Pattern(_) => (1, None),
        PigmentKind::ImageMap(_) => (2, None),
    };
    let f = &t.finish;
    // (A placed pattern, or a placed normal, tells textures apart: a hundred thousand boxes
    // with one pattern, each moved, would otherwise all be compared with one another.)
    let placed = |m: &Option<Box<Transform>>| {
        m.as_ref().map_or(0u64, |m| {
            m.matrix
                .to_cols_array()
                .iter()
                .fold(0u64, |h, v| (h ^ v.to_bits()).rotate_left(7))
        })
    };
    let mut moved = t.normal.as_ref().map_or(0, |n| placed(&n.transform));
    if colour.is_none() {
        moved ^= placed(&t.pigment.transform).rotate_left(1);
    }
    let mut words = [kind, 0, 0, 0, 0, 0, 0, 0, 0, moved];
    for (w, v) in words[1..]
        .iter_mut()
        .zip([f.ambient.x, f.diffuse, f.phong, f.specular])
    {
        *w = v.to_bits();
    }
    if let Some(c) = colour {
        for (w, v) in words[5..9]
            .iter_mut()
            .zip([c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit])
        {
            *w = v.to_bits();
        }
    }
    // A multiply–rotate mix (the keys are not adversarial; SipHash was a third of the
    // per-object build time).
    words.iter().fold(0u64, |h, &w| {
        (h ^ w).wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(29)
    })
}

/// Ids for `values`, equal values sharing one (hash-consing), numbered in order of first
/// appearance, and the value of each id. `fingerprint` must give equal values equal keys;
/// values with equal keys are compared in full. (Sorting by key on all cores, rather than a
/// hash table filled in order: with a million distinct values most lookups missed the cache.)
pub(crate) fn shared_ids<'a, T: Sync>(
    values: &[&'a T],
    fingerprint: impl Fn(&T) -> u64 + Sync,
    same: impl Fn(&T, &T) -> bool,
) -> (Vec<u32>, Vec<&'a T>) {
    // Positions sorted by key, then position: equal values lie together, the first one first.
    let mut order: Vec<(u64, u32)> = values
        .par_iter()
        .enumerate()
        .map(|(i, v)| (fingerprint(v), i as u32))
        .collect();
    order.par_sort_unstable();
    // For each position, the first position holding an equal value.
    let mut first = vec![0u32; values.len()];
    let mut distinct_in_group: Vec<u32> = Vec::new();
    for group in order.chunk_by(|a, b| a.0 == b.0) {
        distinct_in_group.clear();
        for &(_, i) in group {
            let same = distinct_in_group
                .iter()
                .copied()
                .find(|&d| same(values[d as usize], values[i as usize]));
            first[i as usize] = same.unwrap_or_else(|| {
                distinct_in_group.push(i);
                i
            });
        }
    }
    // Ids in order of first appearance.
    let mut ids: Vec<u32> = Vec::with_capacity(values.len());
    let mut distinct = Vec::new();
    for (i, &f) in first.iter().enumerate() {
        let id = if f as usize == i {
            distinct.push(values[i]);
            distinct.len() as u32 - 1
        } else {
            ids[f as usize]
        };
        ids.push(id);
    }
    (ids, distinct)
}

/// Whether two textures render alike: equal, or equal but for where their solid pigments
/// were moved (a solid colour is the same wherever it is placed).
fn same_material(a: &Texture, b: &Texture) -> bool {
    match (&a.pigment.kind, &b.pigment.kind) {
        (PigmentKind::Solid(ca), PigmentKind::Solid(cb)) => {
            ca == cb
                && a.finish == b.finish
                && a.normal == b.normal
                && a.under == b.under
                && a.map == b.map
        }
        _ => a == b,
    }
}

/// The distinct textures and interiors of a scene, and each object's.
pub struct Shared<'a> {
    /// For each object, the ids of its texture outside and inside (the same without an
    /// interior texture): indices into `textures`.
    pub sides: Vec<(u32, u32)>,
    /// The distinct textures, in order of first appearance (outside textures first, then
    /// interior textures).
    pub textures: Vec<&'a Texture>,
    /// For each object, its interior: an index into `interiors`.
    pub interior_ids: Vec<u32>,
    /// The distinct interiors, in order of first appearance.
    pub interiors: Vec<&'a Interior>,
}

impl Scene {
    /// The scene's distinct textures and interiors, equal values sharing one id (textures
    /// equal but for where their solid pigments were moved are equal).
    pub fn shared(&self) -> Shared<'_> {
        let mut textures: Vec<&Texture> = self.objects.iter().map(|o| &o.texture).collect();
        textures.extend(self.objects.iter().filter_map(|o| o.interior_texture()));
        let (ids, textures) = shared_ids(&textures, fingerprint, same_material);
        let mut inside = ids[self.objects.len()..].iter();
        let sides = self
            .objects
            .iter()
            .zip(&ids)
            .map(|(o, &id)| match o.interior_texture() {
                Some(_) => (id, *inside.next().expect("one id per interior texture")),
                None => (id, id),
            })
            .collect();
        let (interior_ids, interiors) = shared_ids(
            &self
                .objects
                .iter()
                .map(|o| &*o.interior)
                .collect::<Vec<_>>(),
            Interior::key,
            |a, b| a == b,
        );
        Shared {
            sides,
            textures,
            interior_ids,
            interiors,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::{DMat4, DVec3};

    #[test]
    fn shared_ids_number_equal_values_once_in_order_of_first_appearance() {
        let v = [5.0, 7.0, 5.0, 9.0, 7.0, 1.0];
        let refs: Vec<&f64> = v.iter().collect();
        // A fingerprint that gives every value the same key: all compared in full.
        let (ids, distinct) = shared_ids(&refs, |_| 42, |a, b| a == b);
        assert_eq!(ids, [0, 1, 0, 2, 1, 3]);
        assert_eq!(distinct, [&5.0, &7.0, &9.0, &1.0]);
        // And one that tells them apart.
        let (ids, _) = shared_ids(&refs, |x| x.to_bits(), |a, b| a == b);
        assert_eq!(ids, [0, 1, 0, 2, 1, 3]);
    }

    /// Objects with one solid colour, each moved (the texture moving with it), share one
    /// material; moved patterns are told apart by their fingerprints, not compared all with
    /// all (a Menger sponge of 160 000 such boxes took 110 s to build).
    #[test]
    fn moved_solid_textures_share_a_material_and_moved_patterns_do_not() {
        let text = "#declare B = box { 0, 1 pigment { rgb <1, 0, 0> } }
                    #declare P = box { 0, 1 pigment { checker } }
                    #for (i, 0, 999) object { B translate i*x } #end
                    #for (i, 0, 2) object { P translate i*y } #end
                    object { P translate 2*y }";
        let loaded = crate::load_str(
            std::path::Path::new("t.rt"),
            text.to_string(),
            &Default::default(),
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let shared = loaded.scene.shared();
        let (ids, textures) = (shared.sides, shared.textures);
        assert!(
            ids[..1000].iter().all(|&(a, b)| a == ids[0].0 && b == a),
            "one material for the red boxes"
        );
        assert_eq!(
            textures.len(),
            1 + 3,
            "the checkers moved three ways are three materials"
        );
        assert_eq!(ids[1003], ids[1002], "equally moved checkers share one");
        let t = std::time::Instant::now();
        let many: Vec<Texture> = (0..20_000)
            .map(|i| {
                let mut t = loaded.scene.objects[1000].texture.clone();
                t.transform(Transform {
                    matrix: DMat4::from_translation(DVec3::splat(f64::from(i))),
                });
                t
            })
            .collect();
        let refs: Vec<&Texture> = many.iter().collect();
        let (_, distinct) = shared_ids(&refs, fingerprint, same_material);
        assert_eq!(distinct.len(), 20_000);
        assert!(
            t.elapsed().as_secs_f64() < 5.0,
            "not compared all with all: {:?}",
            t.elapsed()
        );
    }
}
