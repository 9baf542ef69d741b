//! The render-ready scene: IR → dense arrays the tracer reads without interpretation.
//!
//! Transformations are composed and inverted here, once; materials are resolved and stored
//! once per distinct value; lights are collected. The renderer sees only this module's types.

use crate::geometry::{
    Cone, Crossings, Cuboid, Disc, Plane, Ray, Shape, Sphere, Torus, TriangleMesh, offset_origin,
};
use crate::ir;
use glam::{DMat3, DMat4, DVec3};
use rayon::prelude::*;
use std::cell::RefCell;
use std::collections::HashMap;
use std::sync::Arc;

mod accel;
mod normal;
mod pigment;

pub use crate::ir::{
    AreaLight, Colour, Finish, Fog, FogKind, Gamma, Interior, LightFade, LightKind, Projection,
    Rgb,
};
pub use normal::Normal;
pub use pigment::Pigment;

/// Index into [`Scene::materials`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MaterialId(pub u32);

/// Index into [`Scene::objects`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ObjectId(pub u32);

/// The scene as the tracer reads it.
#[derive(Debug)]
pub struct Scene {
    /// The camera.
    pub camera: Camera,
    /// Point lights.
    pub lights: Vec<Light>,
    /// Objects.
    pub objects: Vec<Object>,
    /// Distinct materials.
    pub materials: Vec<Material>,
    /// Distinct interiors.
    pub interiors: Vec<Interior>,
    /// Colour of escaped rays.
    pub background: Rgb,
    /// `sky_sphere`: the colour of escaped rays by direction.
    pub sky_sphere: Option<SkySphere>,
    /// Fogs with a positive distance (POV-Ray skips the others).
    pub fogs: Vec<Fog>,
    /// POV-Ray's bounding is on (three or more top-level objects and lights): it then tests
    /// unbounded objects first.
    pub bounded_last: bool,
    /// Rays at a deeper level return black.
    pub max_trace_level: u32,
    /// Rays of lower weight return black.
    pub adc_bailout: f64,
    /// Multiplies every finish's ambient.
    pub ambient_light: Rgb,
    /// Pre-3.7 surface attenuation.
    pub legacy_transparency: bool,
    /// The scene's noise generator (fog turbulence; patterns carry their own).
    pub noise_generator: u8,
    /// `irid_wavelength`: the wavelengths of thin-film interference (`irid`).
    pub irid_wavelength: Rgb,
    /// Working gamma (applied when the film is written).
    pub gamma: Gamma,
    /// Top-level BVH over the objects (`None` for small scenes).
    index: Option<accel::ObjectIndex>,
    /// Without an index, the world bounds of each object (`None` for unbounded ones), tested
    /// before the object; empty with an index, which holds them.
    scan_bounds: Vec<Option<(DVec3, DVec3)>>,
    /// Whether any object may let light through to a shadow ray (else shadow rays stop at
    /// the any-hit test for opaque blockers).
    pub any_transparent: bool,
    /// Whether any object that may let light through to a shadow ray has an interior that
    /// fades: shadow rays then walk their crossings in order (see [`Scene::transmittance`]).
    pub shadow_fades: bool,
}

/// The camera's four vectors.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// Projection.
    pub projection: Projection,
    /// Eye point.
    pub location: DVec3,
    /// Image-plane centre relative to the eye.
    pub direction: DVec3,
    /// Full image width vector.
    pub right: DVec3,
    /// Full image height vector.
    pub up: DVec3,
}

/// A point light.
#[derive(Clone, Debug)]
pub struct Light {
    /// World position.
    pub position: DVec3,
    /// Colour.
    pub colour: Rgb,
    /// Point, spot or parallel.
    pub kind: LightKind,
    /// No shadows, no highlights.
    pub shadowless: bool,
    /// Distance attenuation.
    pub fade: Option<LightFade>,
    /// Soft-shadow grid.
    pub area: Option<AreaLight>,
}

/// The sky: pigments of the ray's direction, the last on top.
#[derive(Clone, Debug, PartialEq)]
pub struct SkySphere {
    /// Bottom layer first.
    pub pigments: Vec<Pigment>,
    /// Multiplies the pigments' colours.
    pub emission: Rgb,
}

/// A resolved surface material.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Pigment.
    pub pigment: Pigment,
    /// Normal perturbation, if any.
    pub normal: Option<Box<Normal>>,
    /// Layered textures: the layers beneath, bottom first (each with none of its own).
    pub under: Box<[Material]>,
    /// A pattern of materials: when given, the surface is these (and the rest unused).
    pub map: Option<Box<MaterialMap>>,
    /// Whether light may pass through somewhere (asked for every shadow ray's candidates).
    see_through: bool,
    /// Finish.
    pub finish: Arc<Finish>,
}

impl Material {
    /// The material of a texture (with its layers), its patterns using noise generator
    /// `generator` unless they name their own.
    pub fn new(t: &ir::Texture, scene: crate::pattern::SceneDefaults) -> Material {
        let mut m = Material {
            pigment: Pigment::new(&t.pigment, scene),
            normal: t
                .normal
                .as_deref()
                .map(|n| Box::new(Normal::new(n, scene))),
            under: t.under.iter().map(|l| Material::new(l, scene)).collect(),
            map: t.map.as_deref().map(|m| {
                Box::new(MaterialMap {
                    pattern: m.pattern.with_scene(scene),
                    pattern_from_world: m.transform.as_ref().map(|t| t.matrix.inverse()),
                    world_from_pattern: m.transform.as_ref().map(|t| t.matrix),
                    entries: m
                        .entries
                        .iter()
                        .map(|(v, e)| {
                            // The entries lie in the pattern's space: placed in the world.
                            let mut e = e.clone();
                            if let Some(t) = &m.transform {
                                e.transform(**t);
                            }
                            (*v, Material::new(&e, scene))
                        })
                        .collect(),
                })
            }),
            finish: Arc::clone(&t.finish),
            see_through: false,
        };
        m.see_through = match &m.map {
            Some(map) => map.entries.iter().any(|(_, e)| e.may_be_transparent()),
            None => m.layers().all(|l| l.pigment.may_be_transparent()),
        };
        m
    }

    /// The layers, top first.
    pub fn layers(&self) -> impl Iterator<Item = &Material> {
        std::iter::once(self).chain(self.under.iter().rev())
    }

    /// Whether light may pass through somewhere (through every layer, or some material of
    /// a pattern of materials).
    pub fn may_be_transparent(&self) -> bool {
        self.see_through
    }

    /// What the surface lets through at `p`: the product over the layers of
    /// `rgb·filter + transmit` (POV-Ray's shadow texture), blended for a pattern of materials.
    pub fn filter_at(&self, p: DVec3) -> Rgb {
        if let Some(m) = &self.map {
            if m.averages() {
                let p = m.entry_point(p);
                let total: f64 = m.entries.iter().map(|(w, _)| w).sum();
                return m
                    .entries
                    .iter()
                    .map(|(w, e)| e.filter_at(p) * *w)
                    .fold(Rgb::ZERO, |a, b| a + b)
                    / total;
            }
            let (prev, cur, t, p) = m.at(p);
            let f = m.entries[cur].1.filter_at(p);
            return if prev == cur {
                f
            } else {
                m.entries[prev].1.filter_at(p) * (1.0 - t) + f * t
            };
        }
        self.layers()
            .map(|l| filter_colour(&l.pigment.colour_at(p)))
            .fold(Rgb::ONE, |a, b| a * b)
    }
}

/// A pattern of materials (`texture_map`, `checker texture {…} texture {…}`).
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialMap {
    pattern: crate::pattern::Pattern,
    pattern_from_world: Option<DMat4>,
    world_from_pattern: Option<DMat4>,
    /// (value, material), each placed in the world.
    pub entries: Box<[(f64, Material)]>,
}

impl MaterialMap {
    /// Whether the map averages its materials (`average`) instead of picking by value.
    pub fn averages(&self) -> bool {
        self.pattern.kind == crate::pattern::PatternKind::Average
    }

    /// The entries around the pattern's value at world point `p`, the fraction of the way
    /// from the first to the second (the same entry twice: that one alone), and the point
    /// where the entries are evaluated.
    pub fn at(&self, p: DVec3) -> (usize, usize, f64, DVec3) {
        let q = self.pattern_from_world.map_or(p, |m| m.transform_point3(p));
        let warped = self.pattern.warp(q);
        let v = self.pattern.wave.apply(self.pattern.raw(warped));
        let (prev, cur, t) = pigment::search(&self.entries, v);
        (prev, cur, t, self.world_point(q, warped, p))
    }

    /// Where the entries are evaluated for world point `p` (`average` has no value to look up).
    pub fn entry_point(&self, p: DVec3) -> DVec3 {
        let q = self.pattern_from_world.map_or(p, |m| m.transform_point3(p));
        self.world_point(q, self.pattern.warp(q), p)
    }

    /// The entries see the pattern's warped point: placed in the world as they are, that is
    /// the warped point taken back out of the pattern's space (`p` itself if nothing moved).
    fn world_point(&self, q: DVec3, warped: DVec3, p: DVec3) -> DVec3 {
        if warped == q {
            return p;
        }
        self.world_from_pattern.map_or(warped, |m| m.transform_point3(warped))
    }
}

/// `rgb·filter + transmit`: what a surface of colour `c` lets through, per channel.
pub fn filter_colour(c: &Colour) -> Rgb {
    c.rgb * c.filter + Rgb::splat(c.transmit)
}

/// Per thread, for a shadow ray through fading interiors: its crossings (distance, object, part)
/// and the list of media it is in.
type ShadowScratch = (Vec<(f64, u32, u32)>, Vec<u32>);

/// Whether an interior fades light along shadow rays (POV-Ray: positive `fade_power` and a
/// `fade_distance` that is not zero).
fn fades(interior: &Interior) -> bool {
    interior.fade_power > 0.0 && interior.fade_distance.abs() > 1e-10
}

/// POV-Ray's interior fade over a distance `d` inside (§9.2).
pub fn interior_fade(interior: &Interior, d: f64) -> Rgb {
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

/// Object-to-world transformation with what the tracer needs precomputed.
#[derive(Clone, Copy, Debug)]
pub struct ObjectTransform {
    /// Object → world.
    pub world_from_object: DMat4,
    /// World → object.
    pub object_from_world: DMat4,
    /// Inverse transpose of the linear part: takes object normals to world normals.
    pub normal_to_world: DMat3,
}

impl ObjectTransform {
    fn new(m: DMat4) -> ObjectTransform {
        let inverse = m.inverse();
        ObjectTransform {
            world_from_object: m,
            object_from_world: inverse,
            normal_to_world: DMat3::from_mat4(inverse).transpose(),
        }
    }
}

/// A placed object.
#[derive(Clone, Debug)]
pub struct Object {
    /// Geometry in object space.
    pub shape: Shape,
    /// Whether it has a world-space bounding box (planes do not).
    pub bounded: bool,
    /// `None` is the identity (the shape is in world space).
    pub transform: Option<Box<ObjectTransform>>,
    /// Its material.
    pub material: MaterialId,
    /// Its material seen from inside (`interior_texture`; else `material`).
    pub back_material: MaterialId,
    /// Casts no shadow.
    pub no_shadow: bool,
    /// Inside swapped with outside.
    pub inverse: bool,
    /// Fog reaches rays inside it.
    pub hollow: bool,
    /// Place in POV-Ray's test order, which decides between two hits at the same distance
    /// (see [`Scene::intersect`]; lower first).
    pub rank: u64,
    /// Index of refraction and fade: an index into [`Scene::interiors`] (equal interiors are
    /// stored once).
    pub interior: u32,
    /// Objects with equal media share one interior (see [`ir::Object::medium`]).
    pub medium: u32,
}

impl Object {
    /// The material seen along `direction` at a surface of unit normal `normal` (outward,
    /// before any `inverse`): the interior texture where the normal faces away from the ray,
    /// as POV-Ray picks it.
    #[inline]
    fn side(&self, normal: DVec3, direction: DVec3) -> MaterialId {
        if self.back_material == self.material {
            return self.material;
        }
        let outward = if self.inverse { -normal } else { normal };
        if outward.dot(direction) > 0.0 {
            self.back_material
        } else {
            self.material
        }
    }

    /// The world-space bounding box, `None` for unbounded shapes. Bounds that overflowed (a
    /// huge scale) make the object unbounded, tested for every ray, rather than a box no
    /// structure can hold.
    fn world_bounds(&self) -> Option<(DVec3, DVec3)> {
        let m = self.transform.as_ref().map(|t| &t.world_from_object);
        self.shape
            .bounds()
            .map(|(lo, hi)| world_bounds(lo, hi, m))
            .filter(|(lo, hi)| lo.is_finite() && hi.is_finite())
    }
}

/// The nearest hit of a ray: cheap, no surface details yet.
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    /// Distance along the ray (in units of the ray's direction length).
    pub t: f64,
    /// The object hit.
    pub object: ObjectId,
    /// Which part of the shape (a cone's cap, a mesh's triangle).
    pub part: u32,
}

/// Relative difference below which two hit distances count as the same point (far above
/// rounding, which is ~1e-15 relative; far below any feature trace supports).
const TIE: f64 = 1e-10;

/// Surface details at a hit, computed once for the winning hit.
#[derive(Clone, Copy, Debug)]
pub struct SurfaceHit {
    /// World-space point.
    pub point: DVec3,
    /// Where the surface's patterns are evaluated: the point itself, except inside a warped
    /// pattern of materials, whose entries see the warped point (POV-Ray passes the point
    /// its warps made on to the entries).
    pub texture_point: DVec3,
    /// Unit shading normal in world space (interpolated on smooth triangles).
    pub normal: DVec3,
    /// Unit geometric normal in world space (same side as `normal`).
    pub geometric_normal: DVec3,
    /// The object's material.
    pub material: MaterialId,
    /// The object hit.
    pub object: ObjectId,
}

/// A cheap hash of the parts of a texture that most often differ (pattern kind, colour, main
/// finish amounts); textures with equal fingerprints are then compared in full.
fn fingerprint(t: &ir::Texture) -> u64 {
    let (kind, colour) = match &t.pigment.kind {
        ir::PigmentKind::Solid(c) => (0, Some(c)),
        ir::PigmentKind::Pattern(_) => (1, None),
        ir::PigmentKind::ImageMap(_) => (2, None),
    };
    let f = &t.finish;
    let mut words = [kind, 0, 0, 0, 0, 0, 0, 0, 0, 0];
    for (w, v) in words[1..]
        .iter_mut()
        .zip([f.ambient.x, f.diffuse, f.phong, f.specular])
    {
        *w = v.to_bits();
    }
    if let Some(c) = colour {
        for (w, v) in words[5..]
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
fn shared_ids<'a, T: PartialEq + Sync>(
    values: &[&'a T],
    fingerprint: impl Fn(&T) -> u64 + Sync,
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
                .find(|&d| values[d as usize] == values[i as usize]);
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

/// Material ids for the objects of `ir` (outside, inside), equal textures sharing one, and
/// the texture of each id. Without an interior texture both sides have the same id.
#[allow(clippy::type_complexity)]
fn material_ids(ir: &ir::Scene) -> (Vec<(MaterialId, MaterialId)>, Vec<&ir::Texture>) {
    let mut textures: Vec<&ir::Texture> = ir.objects.iter().map(|o| &o.texture).collect();
    textures.extend(ir.objects.iter().filter_map(|o| o.interior_texture.as_deref()));
    let (ids, textures) = shared_ids(&textures, fingerprint);
    let mut inside = ids[ir.objects.len()..].iter();
    let sides = ir
        .objects
        .iter()
        .zip(&ids)
        .map(|(o, &id)| {
            let back = match &o.interior_texture {
                Some(_) => *inside.next().expect("one id per interior texture"),
                None => id,
            };
            (MaterialId(id), MaterialId(back))
        })
        .collect();
    (sides, textures)
}

/// What the scene's settings give patterns that name nothing themselves.
fn pattern_defaults(ir: &ir::Scene) -> crate::pattern::SceneDefaults {
    crate::pattern::SceneDefaults {
        generator: ir.settings.noise_generator,
        waves: ir.settings.number_of_waves,
    }
}

/// The bits of an interior, as a key for sharing equal ones.
fn interior_key(i: &Interior) -> u64 {
    [i.ior, i.fade_distance, i.fade_power, i.fade_colour.x, i.fade_colour.y, i.fade_colour.z]
        .iter()
        .fold(0u64, |h, v| {
            (h ^ v.to_bits()).wrapping_mul(0x9E37_79B9_7F4A_7C15).rotate_left(29)
        })
}

impl Scene {
    /// Builds the render-ready scene from the IR (in parallel, on the current rayon pool).
    pub fn build(ir: &ir::Scene) -> Scene {
        let (scene, bounds) = Scene::build_objects(ir);
        scene.with_index(bounds)
    }

    /// Like [`Scene::build`], but frees the IR's objects before building the acceleration
    /// structure, which needs the most memory.
    pub fn build_owned(ir: ir::Scene) -> Scene {
        let (scene, bounds) = Scene::build_objects(&ir);
        drop(ir);
        scene.with_index(bounds)
    }

    /// Everything but the acceleration structure, and the world bounds of each object.
    fn build_objects(ir: &ir::Scene) -> (Scene, Vec<Option<(DVec3, DVec3)>>) {
        let (ids, textures) = material_ids(ir);
        let (interior_ids, interiors) =
            shared_ids(&ir.objects.iter().map(|o| &*o.interior).collect::<Vec<_>>(), interior_key);
        let interiors: Vec<Interior> = interiors.into_iter().copied().collect();
        let materials = textures
            .into_iter()
            .map(|t| Material::new(t, pattern_defaults(ir)))
            .collect();
        // Each distinct mesh is built once, for all its instances (keyed by address).
        let mut meshes: HashMap<usize, Arc<TriangleMesh>> = HashMap::new();
        for o in &ir.objects {
            if let ir::Shape::Mesh(mesh) = &o.shape {
                meshes
                    .entry(Arc::as_ptr(mesh) as usize)
                    .or_insert_with(|| Arc::new(build_mesh(mesh)));
            }
        }
        let (objects, bounds): (Vec<Object>, Vec<_>) = ir
            .objects
            .par_iter()
            .zip(ids)
            .zip(interior_ids)
            .map(|((o, (material, back_material)), interior)| {
                let (shape, transform) =
                    build_shape(&o.shape, o.transform.as_ref().map(|t| t.matrix), &meshes);
                let mut object = Object {
                    shape,
                    bounded: false,
                    transform: transform.map(|m| Box::new(ObjectTransform::new(m))),
                    material,
                    back_material,
                    no_shadow: o.no_shadow,
                    inverse: o.inverse,
                    hollow: o.hollow,
                    rank: 0,
                    interior,
                    medium: o.medium,
                };
                let bounds = object.world_bounds();
                object.bounded = bounds.is_some();
                (object, bounds)
            })
            .unzip();
        let c = &ir.camera;
        let mut scene = Scene {
            camera: Camera {
                projection: c.projection,
                location: c.location,
                direction: c.direction,
                right: c.right,
                up: c.up,
            },
            lights: ir
                .lights
                .iter()
                .map(|l| Light {
                    position: l.position,
                    colour: l.colour,
                    kind: l.kind.clone(),
                    shadowless: l.shadowless,
                    fade: l.fade,
                    area: l.area.clone(),
                })
                .collect(),
            objects,
            materials,
            interiors,
            background: ir.background,
            sky_sphere: ir.sky_sphere.as_ref().map(|s| SkySphere {
                pigments: s
                    .pigments
                    .iter()
                    .map(|p| Pigment::new(p, pattern_defaults(ir)))
                    .collect(),
                emission: s.emission,
            }),
            fogs: ir
                .fogs
                .iter()
                .filter(|f| f.distance.abs() > 1e-10)
                .cloned()
                .collect(),
            max_trace_level: ir.settings.max_trace_level,
            adc_bailout: ir.settings.adc_bailout,
            ambient_light: ir.settings.ambient_light,
            legacy_transparency: ir.settings.legacy_transparency,
            noise_generator: ir.settings.noise_generator,
            irid_wavelength: ir.settings.irid_wavelength,
            gamma: ir.settings.gamma,
            index: None,
            scan_bounds: Vec::new(),
            any_transparent: false,
            shadow_fades: false,
            bounded_last: false,
        };
        // POV-Ray tests objects in scene order when there are fewer than three objects and
        // lights, and otherwise (bounding on) the unbounded ones (planes) first; a union is one
        // object to it, bounded if all its members are, and among the members the later one
        // takes a tie (its intersections are taken from a stack).
        let top_level = ir.objects.iter().filter(|o| o.member == 0).count();
        scene.bounded_last = top_level + scene.lights.len() >= 3;
        let n = scene.objects.len() as u64;
        let mut start = 0;
        for group in ir.objects.chunk_by(|_, next| next.member != 0) {
            let objects = &mut scene.objects[start..start + group.len()];
            let later = scene.bounded_last && objects.iter().all(|o| o.bounded);
            let base = start as u64 + if later { n } else { 0 };
            for (o, member) in objects.iter_mut().zip(group) {
                o.rank = (base << 32) | u64::from(u32::MAX - member.member);
            }
            start += group.len();
        }
        let see_through = |o: &Object| {
            [o.material, o.back_material]
                .iter()
                .any(|m| scene.materials[m.0 as usize].may_be_transparent())
        };
        scene.any_transparent = scene.objects.iter().any(|o| !o.no_shadow && see_through(o));
        scene.shadow_fades = scene.objects.iter().any(|o| {
            !o.no_shadow && fades(&scene.interiors[o.interior as usize]) && see_through(o)
        });
        (scene, bounds)
    }

    /// The scene with its top-level index over objects of the given world bounds (or, for
    /// few objects, the bounds to test each object against).
    fn with_index(mut self, bounds: Vec<Option<(DVec3, DVec3)>>) -> Scene {
        match accel::ObjectIndex::prepare(&bounds) {
            Some(prepared) => {
                drop(bounds);
                self.index = Some(prepared.build());
            }
            None => self.scan_bounds = bounds,
        }
        self
    }

    /// Whether a top-level BVH serves the ray queries (scenes of few objects test every
    /// object for every ray instead).
    pub fn has_index(&self) -> bool {
        self.index.is_some()
    }

    /// The same scene without its top-level BVH, testing every object for every ray: the
    /// stability suite compares its pictures with the BVH's.
    #[cfg(feature = "internals")]
    pub fn without_index(mut self) -> Scene {
        self.index = None;
        self.scan_bounds = self.objects.iter().map(Object::world_bounds).collect();
        self
    }

    /// The interior of `object`.
    pub fn interior(&self, object: &Object) -> &Interior {
        &self.interiors[object.interior as usize]
    }

    /// The material with id `id`.
    pub fn material(&self, id: MaterialId) -> &Material {
        &self.materials[id.0 as usize]
    }

    /// Crossings of a world ray with one object (object space when transformed; `t` is the
    /// same in both spaces because the direction is not renormalised).
    fn crossings(object: &Object, ray: &Ray) -> Crossings {
        match &object.transform {
            None => object.shape.intersect(ray),
            Some(t) => object
                .shape
                .intersect(&ray.transformed(&t.object_from_world)),
        }
    }

    /// The nearest hit along `ray`.
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        let mut ray = *ray;
        // Two hits within rounding of each other (a glass box standing on the floor plane: the
        // ray leaves the glass where it meets the floor) are one point, and the object first in
        // POV-Ray's test order is hit, as in POV-Ray, whose depths there are exactly equal;
        // rounding would otherwise pick either at random from pixel to pixel. So each hit
        // leaves room for a tie just beyond it.
        let mut test = |i: u32, ray: &Ray| -> Option<f64> {
            let object = &self.objects[i as usize];
            let (t, part) = Self::crossings(object, ray).first_part()?;
            if let Some(b) = &best {
                let tied = (t - b.t).abs() <= TIE * b.t.abs();
                if tied && self.objects[b.object.0 as usize].rank < object.rank {
                    return None;
                }
            }
            best = Some(Hit {
                t,
                object: ObjectId(i),
                part,
            });
            Some(t + TIE * t.abs())
        };
        match &self.index {
            Some(index) => {
                for &i in &index.unbounded {
                    if let Some(t) = test(i, &ray) {
                        ray.tmax = t;
                    }
                }
                index.closest(&ray, |i, tmax| test(i, &Ray { tmax, ..ray }));
            }
            None => {
                let inv = ray.direction.recip();
                for (i, &bounds) in self.scan_bounds.iter().enumerate() {
                    if may_hit(bounds, &ray, inv) {
                        if let Some(t) = test(i as u32, &ray) {
                            ray.tmax = t;
                        }
                    }
                }
            }
        }
        best
    }

    /// Surface details for a hit found by [`Scene::intersect`].
    #[inline]
    pub fn surface(&self, ray: &Ray, hit: &Hit) -> SurfaceHit {
        let object = &self.objects[hit.object.0 as usize];
        let point = ray.at(hit.t);
        let (normal, geometric) = match &object.transform {
            None => object.shape.normals(point, hit.part),
            Some(t) => {
                let local = t.object_from_world.transform_point3(point);
                let (n, g) = object.shape.normals(local, hit.part);
                (t.normal_to_world * n, t.normal_to_world * g)
            }
        };
        let normal = normal.normalize();
        let mut geometric_normal = geometric.normalize();
        if geometric_normal.dot(normal) < 0.0 {
            geometric_normal = -geometric_normal;
        }
        SurfaceHit {
            point,
            texture_point: point,
            normal,
            geometric_normal,
            material: object.side(normal, ray.direction),
            object: hit.object,
        }
    }

    /// What reaches the end of a shadow ray: 1 when nothing blocks it, 0 behind an opaque
    /// object, and the product of `rgb·filter + transmit` over every crossing of transparent
    /// objects (POV-Ray filters at each surface crossing), times the interior fade of the
    /// segments run inside objects whose fade_power is positive (see
    /// `faded_crossings`). Objects with `no_shadow` are skipped; refraction is
    /// ignored, as in POV-Ray.
    pub fn transmittance(&self, ray: &Ray) -> Rgb {
        let opaque_blocks = |i: u32| {
            let object = &self.objects[i as usize];
            !object.no_shadow
                && !self.material(object.material).may_be_transparent()
                && object.shape.occludes(&Self::local_ray(object, ray))
        };
        let mut through = Rgb::ONE;
        match &self.index {
            Some(index) => {
                // First any opaque blocker (stops at the first), then the transparent ones.
                if index.unbounded.iter().any(|&i| opaque_blocks(i))
                    || index.any(ray, opaque_blocks)
                {
                    return Rgb::ZERO;
                }
                if !self.any_transparent {
                    return through;
                }
                if self.shadow_fades {
                    return self.faded_crossings(ray, |f| {
                        index.unbounded.iter().for_each(|&i| f(i));
                        index.each(ray, f);
                    });
                }
                for &i in &index.unbounded {
                    self.filter_through(i, ray, &mut through);
                }
                index.each(ray, |i| self.filter_through(i, ray, &mut through));
            }
            None => {
                let inv = ray.direction.recip();
                let candidates = || {
                    self.scan_bounds
                        .iter()
                        .enumerate()
                        .filter(move |(_, b)| may_hit(**b, ray, inv))
                        .map(|(i, _)| i as u32)
                };
                if candidates().any(opaque_blocks) {
                    return Rgb::ZERO;
                }
                if self.shadow_fades {
                    return self.faded_crossings(ray, |f| candidates().for_each(f));
                }
                for i in candidates() {
                    self.filter_through(i, ray, &mut through);
                }
            }
        }
        through
    }

    fn local_ray(object: &Object, ray: &Ray) -> Ray {
        match &object.transform {
            None => *ray,
            Some(t) => ray.transformed(&t.object_from_world),
        }
    }

    /// Whether object `i` can let light through to a shadow ray.
    fn filters_shadows(&self, i: u32) -> bool {
        let object = &self.objects[i as usize];
        !object.no_shadow
            && (self.material(object.material).may_be_transparent()
                || self.material(object.back_material).may_be_transparent())
    }

    /// POV-Ray's thin-film interference (`irid`): the factor on the light arriving from unit
    /// direction `to` and leaving along `d` at a surface of normal `n`, point `p`.
    pub fn irid(&self, finish: &Finish, to: DVec3, d: DVec3, n: DVec3, p: DVec3) -> Rgb {
        let irid = &finish.irid;
        let mut thickness = irid.thickness;
        if irid.turbulence != 0.0 {
            // A fixed turbulence (5 octaves), from 0..1 to 1 ± the amount.
            let t = crate::pattern::noise::Turbulence {
                amount: DVec3::ONE,
                octaves: 5,
                omega: 0.5,
                lambda: 2.0,
            };
            let noise = 2.0 * t.scalar(p, self.noise_generator) - 1.0;
            thickness *= 1.0 + noise * irid.turbulence;
        }
        let w = self.irid_wavelength;
        let cos_light = n.dot(to).abs();
        let cos_eye = n.dot(d.normalize()).abs();
        let interference = 2.0 * std::f64::consts::PI * thickness * (cos_light + cos_eye);
        Rgb::new(
            1.0 + irid.amount * (interference / w.x).cos(),
            1.0 + irid.amount * (interference / w.y).cos(),
            1.0 + irid.amount * (interference / w.z).cos(),
        )
    }

    /// The material a ray meets where it crosses `object` at distance `t` on `part`: its
    /// interior texture where the surface faces away from the ray.
    fn crossing_material(&self, object: &Object, ray: &Ray, t: f64, part: u32) -> &Material {
        if object.back_material == object.material {
            return self.material(object.material);
        }
        let point = ray.at(t);
        let normal = match &object.transform {
            None => object.shape.normals(point, part).0,
            Some(tr) => {
                let local = tr.object_from_world.transform_point3(point);
                tr.normal_to_world * object.shape.normals(local, part).0
            }
        };
        self.material(object.side(normal, ray.direction))
    }

    /// Multiplies `through` by the filter colour at each crossing of a transparent object
    /// with a shadow ray (the order of crossings does not matter when no interior fades).
    fn filter_through(&self, i: u32, ray: &Ray, through: &mut Rgb) {
        if !self.filters_shadows(i) {
            return;
        }
        let object = &self.objects[i as usize];
        object
            .shape
            .for_each_crossing(&Self::local_ray(object, ray), |t, part| {
                *through *= self.crossing_material(object, ray, t, part).filter_at(ray.at(t));
            });
    }

    /// What a shadow ray lets through when interiors fade: POV-Ray's walk from the surface to
    /// the light, one crossing after the other, with a list of the media the ray is in. At a
    /// crossing of an object whose medium is listed, the ray leaves it, and the medium's fade
    /// applies over the distance from the previous crossing of any object (so a medium
    /// shared by overlapping union members fades only between their surfaces, and an object
    /// around another fades only from the inner one's exit); otherwise it enters. The list
    /// starts with the media of the crossed objects that contain the ray's origin.
    /// `candidates` calls its argument with every object the ray may cross.
    fn faded_crossings(&self, ray: &Ray, candidates: impl FnOnce(&mut dyn FnMut(u32))) -> Rgb {
        thread_local! {
            /// Per thread: the crossings (distance, object) and the list of media.
            static SCRATCH: RefCell<ShadowScratch> = const { RefCell::new((Vec::new(), Vec::new())) };
        }
        SCRATCH.with_borrow_mut(|(crossings, media)| {
            crossings.clear();
            media.clear();
            candidates(&mut |i| {
                if self.filters_shadows(i) {
                    let object = &self.objects[i as usize];
                    object
                        .shape
                        .for_each_crossing(&Self::local_ray(object, ray), |t, part| {
                            crossings.push((t, i, part))
                        });
                }
            });
            crossings.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            for &(_, i, _) in crossings.iter() {
                let object = &self.objects[i as usize];
                if !media.contains(&object.medium) && self.contains(object, ray.origin) {
                    media.push(object.medium);
                }
            }
            let length = ray.direction.length();
            let (mut through, mut last_t) = (Rgb::ONE, 0.0);
            for &(t, i, part) in crossings.iter() {
                let object = &self.objects[i as usize];
                through *= self.crossing_material(object, ray, t, part).filter_at(ray.at(t));
                match media.iter().position(|&m| m == object.medium) {
                    Some(k) => {
                        let interior = self.interior(object);
                        if fades(interior) {
                            through *= interior_fade(interior, (t - last_t) * length);
                        }
                        media.remove(k);
                    }
                    None => media.push(object.medium),
                }
                last_t = t;
            }
            through
        })
    }

    /// Whether world point `p` is inside `object` (POV-Ray's inside test; thin shapes have no
    /// inside; `inverse` swaps).
    pub fn contains(&self, object: &Object, p: DVec3) -> bool {
        let local = object
            .transform
            .as_ref()
            .map_or(p, |t| t.object_from_world.transform_point3(p));
        object.shape.contains(local) != object.inverse
    }

    /// A ray leaving the surface at `hit` in direction `dir` (origin offset off the surface).
    pub fn spawn(&self, hit: &SurfaceHit, from: DVec3, dir: DVec3) -> Ray {
        Ray::new(
            offset_origin(
                hit.point,
                hit.geometric_normal,
                dir,
                from.abs().max_element(),
            ),
            dir,
        )
    }
}

/// If `m` is a translation plus uniform scale, the sphere it maps `s` to.
fn similarity_sphere(s: &Sphere, m: &DMat4) -> Option<(DVec3, f64)> {
    let linear = DMat3::from_mat4(*m);
    let k = linear.x_axis.x;
    let is_uniform_scale = k > 0.0 && linear == DMat3::from_diagonal(DVec3::splat(k));
    is_uniform_scale.then(|| (m.transform_point3(s.centre), s.radius * k))
}

/// Whether the ray may meet a box (slab test); unbounded objects always may.
fn may_hit(bounds: Option<(DVec3, DVec3)>, ray: &Ray, inv: DVec3) -> bool {
    let Some((lo, hi)) = bounds else { return true };
    let t0 = (lo - ray.origin) * inv;
    let t1 = (hi - ray.origin) * inv;
    let near = t0.min(t1).max_element().max(ray.tmin);
    let far = t0.max(t1).min_element().min(ray.tmax);
    // NaN (origin on a slab plane with a zero direction component) must not reject.
    near.partial_cmp(&far) != Some(std::cmp::Ordering::Greater)
}

/// The world box around an object-space box (its eight corners transformed), padded a little.
fn world_bounds(lo: DVec3, hi: DVec3, m: Option<&DMat4>) -> (DVec3, DVec3) {
    let (mut wlo, mut whi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
    for i in 0..8 {
        let c = DVec3::new(
            if i & 1 == 0 { lo.x } else { hi.x },
            if i & 2 == 0 { lo.y } else { hi.y },
            if i & 4 == 0 { lo.z } else { hi.z },
        );
        let w = m.map_or(c, |m| m.transform_point3(c));
        wlo = wlo.min(w);
        whi = whi.max(w);
    }
    let pad = 1e-9 * (wlo.abs().max(whi.abs()).max_element() + (whi - wlo).max_element());
    (wlo - pad, whi + pad)
}

/// The render shape for an IR shape, with its (possibly extended) object transform. Meshes
/// are built once per distinct IR mesh and shared.
fn build_shape(
    shape: &ir::Shape,
    transform: Option<DMat4>,
    meshes: &HashMap<usize, Arc<TriangleMesh>>,
) -> (Shape, Option<DMat4>) {
    match shape {
        ir::Shape::Sphere { centre, radius } => {
            let s = Sphere {
                centre: *centre,
                radius: *radius,
            };
            // Fold translations and uniform scales into the sphere: no matrix per ray.
            match transform.map(|m| similarity_sphere(&s, &m)) {
                Some(Some((centre, radius))) => (Shape::Sphere(Sphere { centre, radius }), None),
                _ => (Shape::Sphere(s), transform),
            }
        }
        ir::Shape::Plane { normal, distance } => (
            Shape::Plane(Plane {
                normal: *normal,
                distance: *distance,
            }),
            transform,
        ),
        ir::Shape::Box { min, max } => (
            Shape::Box(Cuboid {
                min: *min,
                max: *max,
            }),
            transform,
        ),
        ir::Shape::Cone {
            base,
            base_radius,
            cap,
            cap_radius,
            open,
        } => {
            // Canonical frame: x, y unit vectors across the axis, z the axis from base to cap.
            let axis = *cap - *base;
            let w = axis.normalize();
            let u = w.any_orthonormal_vector();
            let v = w.cross(u);
            let frame = DMat4::from_cols(
                u.extend(0.0),
                v.extend(0.0),
                axis.extend(0.0),
                base.extend(1.0),
            );
            let cone = Cone {
                r0: *base_radius,
                r1: *cap_radius,
                open: *open,
            };
            (
                Shape::Cone(cone),
                Some(transform.unwrap_or(DMat4::IDENTITY) * frame),
            )
        }
        ir::Shape::Disc {
            centre,
            normal,
            radius,
            hole_radius,
        } => (
            Shape::Disc(Box::new(Disc {
                centre: *centre,
                normal: *normal,
                radius: *radius,
                hole_radius: *hole_radius,
            })),
            transform,
        ),
        ir::Shape::Torus { major, minor } => (
            Shape::Torus(Torus {
                major: *major,
                minor: *minor,
            }),
            transform,
        ),
        ir::Shape::Mesh(mesh) => {
            let built = &meshes[&(Arc::as_ptr(mesh) as usize)];
            (Shape::Mesh(Arc::clone(built)), transform)
        }
    }
}

fn build_mesh(mesh: &ir::Mesh) -> TriangleMesh {
    let mut built = TriangleMesh::new(
        mesh.vertices.iter().map(|v| v.as_dvec3()).collect(),
        mesh.triangles.clone(),
        mesh.normals.iter().map(|n| n.as_dvec3()).collect(),
        mesh.normal_indices.clone(),
    );
    built.inside_vector = mesh.inside_vector;
    built
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shared_ids_number_equal_values_once_in_order_of_first_appearance() {
        let v = [5.0, 7.0, 5.0, 9.0, 7.0, 1.0];
        let refs: Vec<&f64> = v.iter().collect();
        // A fingerprint that gives every value the same key: all compared in full.
        let (ids, distinct) = shared_ids(&refs, |_| 42);
        assert_eq!(ids, [0, 1, 0, 2, 1, 3]);
        assert_eq!(distinct, [&5.0, &7.0, &9.0, &1.0]);
        // And one that tells them apart.
        let (ids, _) = shared_ids(&refs, |x| x.to_bits());
        assert_eq!(ids, [0, 1, 0, 2, 1, 3]);
    }

    fn scene_with(shape: ir::Shape, transform: DMat4) -> Scene {
        let ir = ir::Scene {
            camera: ir::Camera::default(),
            lights: vec![],
            objects: vec![ir::Object {
                shape,
                transform: Some(Box::new(ir::Transform { matrix: transform })),
                texture: ir::Texture::default(),
                interior_texture: None,
                interior: Default::default(),
                no_shadow: false,
                inverse: false,
                hollow: false,
                member: 0,
                medium: 0,
            }],
            background: Rgb::ZERO,
            sky_sphere: None,
            fogs: vec![],
            settings: ir::Settings::default(),
        };
        Scene::build(&ir)
    }

    #[test]
    fn transformed_sphere_equals_analytic_sphere() {
        let m = DMat4::from_translation(DVec3::new(1.0, 2.0, 3.0))
            * DMat4::from_scale(DVec3::new(2.0, 1.0, 1.0));
        let s = scene_with(
            ir::Shape::Sphere {
                centre: DVec3::ZERO,
                radius: 1.0,
            },
            m,
        );
        // Along x through the centre the ellipsoid extends ±2.
        let r = Ray::new(DVec3::new(-10.0, 2.0, 3.0), DVec3::X);
        let hit = s.intersect(&r).expect("hit");
        assert!((hit.t - 9.0).abs() < 1e-12);
        let surf = s.surface(&r, &hit);
        assert!((surf.normal - -DVec3::X).length() < 1e-12);
        // Off-axis normal follows the inverse transpose: at (x, y) on the ellipse x²/4 + y² = 1
        // the normal is ∝ (x/4, y).
        let r = Ray::new(DVec3::new(1.0 + 2.0f64.sqrt(), 10.0, 3.0), -DVec3::Y);
        let hit = s.intersect(&r).expect("hit");
        let surf = s.surface(&r, &hit);
        let expected = DVec3::new(2.0f64.sqrt() / 4.0, 1.0 / 2.0f64.sqrt(), 0.0).normalize();
        assert!(
            (surf.normal - expected).length() < 1e-9,
            "{:?}",
            surf.normal
        );
    }

    #[test]
    fn rotated_box_is_hit_at_rotated_face() {
        let m = DMat4::from_rotation_y(std::f64::consts::FRAC_PI_4);
        let s = scene_with(
            ir::Shape::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::splat(1.0),
            },
            m,
        );
        let r = Ray::new(DVec3::new(0.0, 0.0, -10.0), DVec3::Z);
        let hit = s.intersect(&r).expect("hit");
        assert!((hit.t - (10.0 - 2.0f64.sqrt())).abs() < 1e-12);
    }

    #[test]
    fn scaled_plane_keeps_t_in_world_units() {
        let m = DMat4::from_scale(DVec3::splat(3.0));
        let s = scene_with(
            ir::Shape::Plane {
                normal: DVec3::Y,
                distance: 1.0,
            },
            m,
        );
        let r = Ray::new(DVec3::new(0.0, 10.0, 0.0), -DVec3::Y);
        let hit = s.intersect(&r).expect("hit");
        assert!((hit.t - 7.0).abs() < 1e-12);
    }

    #[test]
    fn uniformly_scaled_sphere_is_folded_into_its_shape() {
        let m = DMat4::from_translation(DVec3::X) * DMat4::from_scale(DVec3::splat(2.0));
        let s = scene_with(
            ir::Shape::Sphere {
                centre: DVec3::ZERO,
                radius: 1.0,
            },
            m,
        );
        assert!(s.objects[0].transform.is_none());
        let Shape::Sphere(sphere) = s.objects[0].shape else {
            panic!("sphere expected")
        };
        assert_eq!((sphere.centre, sphere.radius), (DVec3::X, 2.0));
    }
}
