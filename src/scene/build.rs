//! Building the render-ready scene from the IR: shapes in their object spaces, materials and
//! interiors stored once per distinct value, ranks for POV-Ray's tie order, the top-level index.

use super::query::fades;
use super::*;
use crate::geometry::{
    Blob, BlobElement, Cone, Cuboid, CurveSegment, Disc, Edge, HeightField, Lathe, Plane, Polygon,
    Polynomial, Prism, Quadric, Sor, SorPiece, Sphere, Superellipsoid, Text, Torus,
};
use rayon::iter::Either;
use rayon::prelude::*;
use std::collections::HashMap;

/// The material of a mesh whose triangles have textures of their own: entry 0 is the
/// object's texture, entry 1 + i the mesh's texture i placed in the world by the object's
/// transformation; each triangle's corners pick theirs.
fn mesh_material(o: &ir::Object, defaults: crate::pattern::SceneDefaults) -> Option<Material> {
    let ir::Shape::Mesh(m) = &o.shape else {
        return None;
    };
    if m.face_textures.is_empty() {
        return None;
    }
    let world = o.transform.as_ref().map(|t| **t);
    let mut entries = vec![Material::new(&o.texture, defaults)];
    for t in &m.textures {
        let mut t = t.clone();
        if let Some(w) = world {
            t.transform(w);
        }
        entries.push(Material::new(&t, defaults));
    }
    Some(Material::corner_blend(entries))
}

/// The material of a blob whose components have textures of their own: entry 0 is the
/// blob's texture, then one entry per textured component (placed in the world by the
/// object's transformation); each element brings its component's entry.
fn blob_material(o: &ir::Object, defaults: crate::pattern::SceneDefaults) -> Option<Material> {
    let ir::Shape::Blob(b) = &o.shape else {
        return None;
    };
    if b.components.iter().all(|c| c.texture.is_none()) {
        return None;
    }
    let world = o.transform.as_ref().map(|t| **t);
    let mut entries = vec![Material::new(&o.texture, defaults)];
    let mut elements = Vec::new();
    for c in &b.components {
        let entry = match &c.texture {
            Some(t) => {
                let mut t = (**t).clone();
                if let Some(w) = world {
                    t.transform(w);
                }
                entries.push(Material::new(&t, defaults));
                entries.len() as u32 - 1
            }
            None => 0,
        };
        match c.reach {
            ir::BlobReach::Sphere(centre) => elements.push((
                BlobElement::sphere(centre, c.radius, c.strength, c.transform),
                entry,
            )),
            ir::BlobReach::Cylinder(a, e) => elements.extend(
                BlobElement::cylinder(a, e, c.radius, c.strength, c.transform)
                    .map(|el| (el, entry)),
            ),
        }
    }
    let blob_from_world = world.map(|w| w.matrix.inverse());
    Some(Material::blob_blend(entries, elements, blob_from_world))
}

/// What the scene's settings give patterns that name nothing themselves.
fn pattern_defaults(ir: &ir::Scene) -> crate::pattern::SceneDefaults {
    crate::pattern::SceneDefaults {
        generator: ir.settings.noise_generator,
        waves: ir.settings.number_of_waves,
    }
}

/// Render-ready meshes kept from one build to the next (`trace watch` builds the scene again
/// at every save): a mesh whose data did not change is not built again (its tree included).
/// Each build keeps only the meshes it used.
#[derive(Default)]
pub struct MeshCache {
    meshes: std::sync::Mutex<KeptMeshes>,
}

/// The built meshes by their data's print, and the IR meshes they were built from with
/// their prints (an IR mesh shared by the next scene is not printed again).
type KeptMeshes = (HashMap<u128, Arc<TriangleMesh>>, Vec<(Arc<ir::Mesh>, u128)>);

impl MeshCache {
    /// Meshes kept now.
    pub fn count(&self) -> usize {
        self.meshes
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .0
            .len()
    }
}

/// A fingerprint of everything [`build_mesh`] reads of a mesh: two independent 64-bit mixes
/// of its values' bits and its lists' lengths (equal meshes, equal prints; a different mesh
/// with the same print is a 2^-128 chance).
fn mesh_print(mesh: &ir::Mesh) -> u128 {
    struct Mix(u64, u64);
    impl Mix {
        fn word(&mut self, w: u64) {
            self.0 = (self.0 ^ w)
                .wrapping_mul(0x9E37_79B9_7F4A_7C15)
                .rotate_left(31);
            self.1 = (self.1 ^ w.rotate_left(17))
                .wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
                .rotate_left(27);
        }
        fn list<T>(&mut self, items: &[T], words: impl Fn(&T) -> [u64; 2]) {
            self.word(items.len() as u64);
            for item in items {
                let [a, b] = words(item);
                self.word(a);
                self.word(b);
            }
        }
    }
    let mut m = Mix(0x243F_6A88_85A3_08D3, 0x1319_8A2E_0370_7344);
    let v3 = |v: &glam::Vec3| {
        [
            u64::from(v.x.to_bits()) << 32 | u64::from(v.y.to_bits()),
            u64::from(v.z.to_bits()),
        ]
    };
    let i3 = |t: &[u32; 3]| [u64::from(t[0]) << 32 | u64::from(t[1]), u64::from(t[2])];
    m.list(&mesh.vertices, v3);
    m.list(&mesh.normals, v3);
    m.list(&mesh.triangles, i3);
    m.list(&mesh.normal_indices, i3);
    m.list(&mesh.uvs, |uv| [uv.x.to_bits(), uv.y.to_bits()]);
    m.list(&mesh.uv_indices, i3);
    m.list(&mesh.face_textures, i3);
    match mesh.inside_vector {
        Some(v) => m.list(&[v], |v| {
            [v.x.to_bits() ^ v.z.to_bits().rotate_left(7), v.y.to_bits()]
        }),
        None => m.word(u64::MAX),
    }
    m.word(u64::from(mesh.world_uv));
    u128::from(m.0) << 64 | u128::from(m.1)
}

/// Built objects a build may take ([`Scene::rebuild`]): the IR objects of the last build
/// and, in the same order, each one's built shape and transformation.
#[derive(Default)]
struct Kept<'a> {
    ir: &'a [ir::Object],
    built: Vec<Option<Built>>,
}

/// A built object's shape and transformation.
type Built = (Shape, Option<Box<ObjectTransform>>);

impl Kept<'_> {
    /// The kept shape for each of `objects`, where one of the last build's objects had the
    /// same shape and transformation: the object in the same place, or the one as far from
    /// the end (objects added or removed in one place shift the rest). Each kept shape
    /// serves once. (Meshes are not compared here: the mesh cache finds their built meshes
    /// by their data's print, once for all their instances.)
    fn matched(self, objects: &[ir::Object]) -> Vec<Option<Built>> {
        let Kept { ir: old, mut built } = self;
        let (n, m) = (objects.len(), old.len().min(built.len()));
        let same = |o: &ir::Object, j: usize| {
            !matches!(o.shape, ir::Shape::Mesh(_))
                && o.shape == old[j].shape
                && o.transform == old[j].transform
        };
        // For each object, the places it may take its shape from: the same index, then the
        // same distance from the end.
        let candidates: Vec<[Option<u32>; 2]> = (objects.par_iter().enumerate())
            .map(|(i, o)| {
                let here = (i < m && same(o, i)).then_some(i as u32);
                let from_end = (i + m).checked_sub(n).filter(|&j| j != i && j < m);
                [here, from_end.filter(|&j| same(o, j)).map(|j| j as u32)]
            })
            .collect();
        let mut kept: Vec<Option<Built>> = Vec::with_capacity(n);
        for pair in candidates {
            let shape = pair
                .into_iter()
                .flatten()
                .find_map(|j| built[j as usize].take());
            kept.push(shape);
        }
        kept
    }
}

/// What [`Scene::rebuild`] took from the scene before.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Reuse {
    /// Objects whose built shape was kept.
    pub shapes: usize,
    /// Objects in the scene.
    pub objects: usize,
    /// Whether the top-level tree was kept (no object's bounds changed).
    pub tree: bool,
}

/// The camera's part of the render-ready scene: all a camera edit changes.
struct View {
    camera: Camera,
    blur: Option<super::blur::Blur>,
    normal: Option<Normal>,
    mesh_camera: Option<super::meshcam::MeshCamera>,
}

impl View {
    fn of(ir: &ir::Scene) -> View {
        let c = &ir.camera;
        View {
            camera: Camera {
                projection: c.projection,
                location: c.location,
                direction: c.direction,
                right: c.right,
                up: c.up,
            },
            blur: c
                .blur
                .as_ref()
                .map(|b| super::blur::Blur::new(b, c.direction, c.up)),
            normal: c
                .normal
                .as_deref()
                .map(|n| Normal::new(n, pattern_defaults(ir))),
            mesh_camera: c.mesh.as_ref().map(super::meshcam::MeshCamera::new),
        }
    }
}

impl Scene {
    /// Puts the camera of `ir` in place of this scene's, for a scene built from an IR equal to
    /// `ir` but for its camera (nothing else of the render-ready scene depends on the
    /// camera): a camera edit builds nothing else.
    pub fn set_camera(&mut self, ir: &ir::Scene) {
        let view = View::of(ir);
        self.camera = view.camera;
        self.blur = view.blur;
        self.camera_normal = view.normal;
        self.mesh_camera = view.mesh_camera;
    }

    /// Builds the render-ready scene from the IR (in parallel, on the current rayon pool).
    pub fn build(ir: &ir::Scene) -> Scene {
        let (scene, bounds, _) = Scene::build_objects(ir, None, Kept::default());
        scene.with_index(bounds)
    }

    /// Like [`Scene::build`], with meshes from `cache` where it has them.
    pub fn build_cached(ir: &ir::Scene, cache: &MeshCache) -> Scene {
        let (scene, bounds, _) = Scene::build_objects(ir, Some(cache), Kept::default());
        scene.with_index(bounds)
    }

    /// Like [`Scene::build_cached`], taking what it can from `old`, the scene built from
    /// `old_ir`: an object whose shape and transformation are unchanged keeps its built
    /// shape (in its place in the scene order), and the top-level tree stays when every
    /// object's world bounds are unchanged. Materials, lights and the rest are built anew
    /// (they cost little), so a light or material edit builds no geometry. The result is
    /// the scene [`Scene::build`] makes of `ir`.
    pub fn rebuild(
        ir: &ir::Scene,
        old_ir: &ir::Scene,
        old: Scene,
        cache: &MeshCache,
    ) -> (Scene, Reuse) {
        let old_bounds: Vec<_> = old.objects.iter().map(Object::world_bounds).collect();
        // (A shape's build reads only its IR shape, its transformation and the noise
        // generator; a mesh is rebuilt from the mesh cache, which compares its data once.)
        let kept = if ir.settings.noise_generator == old_ir.settings.noise_generator {
            Kept {
                ir: &old_ir.objects,
                built: (old.objects.into_iter())
                    .map(|o| Some((o.shape, o.transform)))
                    .collect(),
            }
        } else {
            Kept::default()
        };
        let (mut scene, bounds, shapes) = Scene::build_objects(ir, Some(cache), kept);
        let tree = bounds == old_bounds;
        let scene = if tree {
            match old.index {
                Some(index) => scene.index = Some(index),
                None => scene.scan_bounds = bounds,
            }
            scene
        } else {
            scene.with_index(bounds)
        };
        let reuse = Reuse {
            shapes,
            objects: ir.objects.len(),
            tree,
        };
        (scene, reuse)
    }

    /// Like [`Scene::build`], but frees the IR's objects before building the acceleration
    /// structure, which needs the most memory; meshes come from `cache` where it has them.
    pub fn build_owned(ir: ir::Scene, cache: Option<&MeshCache>) -> Scene {
        let (scene, bounds, _) = Scene::build_objects(&ir, cache, Kept::default());
        drop(ir);
        scene.with_index(bounds)
    }

    /// Everything but the acceleration structure, the world bounds of each object, and how
    /// many objects' built shapes were taken from `previous`.
    fn build_objects(
        ir: &ir::Scene,
        cache: Option<&MeshCache>,
        previous: Kept,
    ) -> (Scene, Vec<Option<(DVec3, DVec3)>>, usize) {
        let shared = ir.shared();
        let mut ids: Vec<(MaterialId, MaterialId)> = (shared.sides.iter())
            .map(|&(front, back)| (MaterialId(front), MaterialId(back)))
            .collect();
        let (textures, interior_ids) = (shared.textures, shared.interior_ids);
        let generator = ir.settings.noise_generator;
        let interiors: Vec<Interior> = shared.interiors.into_iter().cloned().collect();
        let mut materials: Vec<Material> = textures
            .into_iter()
            .map(|t| Material::new(t, pattern_defaults(ir)))
            .collect();
        // A blob whose components have textures gets a material of its own that blends them
        // (both sides: POV-Ray ignores an interior texture there).
        for (o, id) in ir.objects.iter().zip(&mut ids) {
            if let Some(m) = blob_material(o, pattern_defaults(ir))
                .or_else(|| mesh_material(o, pattern_defaults(ir)))
            {
                let own = MaterialId(materials.len() as u32);
                materials.push(m);
                *id = (own, own);
            }
        }
        // Each distinct mesh is built once, for all its instances (keyed by address), or
        // taken from the cache (keyed by its data).
        let mut meshes: HashMap<usize, Arc<TriangleMesh>> = HashMap::new();
        let mut kept = cache.map(|c| {
            let mut old = c.meshes.lock().unwrap_or_else(|e| e.into_inner());
            (std::mem::take(&mut *old), KeptMeshes::default())
        });
        for o in &ir.objects {
            if let ir::Shape::Mesh(mesh) = &o.shape {
                meshes
                    .entry(Arc::as_ptr(mesh) as usize)
                    .or_insert_with(|| match &mut kept {
                        Some(((old, old_prints), (used, prints))) => {
                            let print = (old_prints.iter())
                                .find(|(m, _)| Arc::ptr_eq(m, mesh))
                                .map_or_else(|| mesh_print(mesh), |&(_, print)| print);
                            prints.push((Arc::clone(mesh), print));
                            let built = used
                                .get(&print)
                                .or_else(|| old.get(&print))
                                .cloned()
                                .unwrap_or_else(|| Arc::new(build_mesh(mesh)));
                            used.insert(print, built.clone());
                            built
                        }
                        None => Arc::new(build_mesh(mesh)),
                    });
            }
        }
        if let (Some(cache), Some((_, used))) = (cache, kept) {
            *cache.meshes.lock().unwrap_or_else(|e| e.into_inner()) = used;
        }
        let default_importance = ir
            .settings
            .radiosity
            .as_ref()
            .map_or(1.0, |r| r.default_importance);
        // (Without a last build, no list of kept shapes: at a million objects it would be
        // 80 MB more at the build's peak.)
        let (old_shapes, taken) = if previous.built.is_empty() {
            let none = |_| None;
            (
                Either::Right((0..ir.objects.len()).into_par_iter().map(none)),
                0,
            )
        } else {
            let kept = previous.matched(&ir.objects);
            let taken = kept.iter().filter(|s| s.is_some()).count();
            (Either::Left(kept.into_par_iter()), taken)
        };
        // (The objects a ray tests are read scattered: huge pages, see `with_huge_pages`.)
        let mut objects: Vec<Object> = crate::memory::with_huge_pages(ir.objects.len());
        let mut bounds = Vec::with_capacity(ir.objects.len());
        ir.objects
            .par_iter()
            .zip(ids)
            .zip(interior_ids)
            .zip(old_shapes)
            .map(|(((o, (material, back_material)), interior), old)| {
                let (shape, transform) = old.unwrap_or_else(|| {
                    let (shape, transform) = build_shape(
                        &o.shape,
                        o.transform.as_ref().map(|t| t.matrix),
                        &meshes,
                        generator,
                    );
                    (shape, transform.map(|m| Box::new(ObjectTransform::new(m))))
                });
                let mut object = Object {
                    shape,
                    bounded: false,
                    transform,
                    material,
                    shadow: ShadowRole::new(
                        o.no_shadow,
                        materials[material.0 as usize].may_be_transparent(),
                        materials[back_material.0 as usize].may_be_transparent(),
                    ),
                    inverse: o.inverse,
                    hollow: o.hollow,
                    rank: 0,
                    interior,
                    medium: o.medium,
                    extra: None,
                };
                let back_material = (back_material != material).then_some(back_material);
                let bounds = o.bounds().map(|bounds| {
                    let shapes = bounds
                        .shapes
                        .iter()
                        .map(|b| bound_shape(&b.shape, b.transform.as_deref(), generator))
                        .collect();
                    (shapes, bounds.test_rays)
                });
                let sight = o.sight();
                let light_group = o.extras.as_ref().and_then(|e| e.light_group.clone());
                let importance = o
                    .extras
                    .as_ref()
                    .and_then(|e| e.importance)
                    .unwrap_or(default_importance);
                if back_material.is_some()
                    || bounds.is_some()
                    || sight != ir::Sight::default()
                    || light_group.is_some()
                    || importance != 1.0
                {
                    let (bounds, test_rays) = bounds.unwrap_or_default();
                    object.extra = Some(Box::new(ObjectExtra {
                        back_material,
                        bounds,
                        test_rays,
                        sight,
                        light_group,
                        importance,
                    }));
                }
                let bounds = object.world_bounds();
                object.bounded = bounds.is_some();
                (object, bounds)
            })
            .unzip_into_vecs(&mut objects, &mut bounds);
        let view = View::of(ir);
        let mut scene = Scene {
            camera: view.camera,
            blur: view.blur,
            camera_normal: view.normal,
            mesh_camera: view.mesh_camera,
            lights: ir
                .lights
                .iter()
                .map(|l| Light {
                    position: l.position,
                    colour: l.colour,
                    kind: l.kind.clone(),
                    axis: match l.kind {
                        LightKind::Spot { point_at, .. } | LightKind::Cylinder { point_at, .. } => {
                            (point_at - l.position).normalize_or_zero()
                        }
                        LightKind::Point | LightKind::Parallel { .. } => DVec3::ZERO,
                    },
                    cos_radius: match l.kind {
                        LightKind::Spot { radius_deg, .. } => radius_deg.to_radians().cos(),
                        _ => 1.0,
                    },
                    cos_falloff: match l.kind {
                        LightKind::Spot { falloff_deg, .. } => falloff_deg.to_radians().cos(),
                        _ => 1.0,
                    },
                    shadowless: l.shadowless,
                    fade: l.fade,
                    area: l.area.clone(),
                    grid: super::grid_table(l.area.as_ref()),
                    group: l.group,
                    media_interaction: l.media_interaction,
                    media_attenuation: l.media_attenuation,
                    through: l.projected_through.as_ref().map(|parts| {
                        parts
                            .iter()
                            .map(|p| bound_shape(&p.shape, p.transform.as_deref(), generator))
                            .collect()
                    }),
                })
                .collect(),
            objects,
            materials,
            interior_media: interiors
                .iter()
                .map(|i| {
                    (i.media.iter())
                        .map(|m| Media::new(m, pattern_defaults(ir)))
                        .collect()
                })
                .collect(),
            any_interior_media: interiors.iter().any(|i| !i.media.is_empty()),
            interiors,
            atmosphere: (ir.atmosphere.iter())
                .map(|m| Media::new(m, pattern_defaults(ir)))
                .collect(),
            background: ir.background,
            background_alpha: ir.background_alpha,
            sky_sphere: ir.sky_sphere.as_ref().map(|s| SkySphere {
                pigments: s
                    .pigments
                    .iter()
                    .map(|p| p.placed(pattern_defaults(ir)))
                    .collect(),
                emission: s.emission,
            }),
            fogs: ir
                .fogs
                .iter()
                .filter(|f| f.distance.abs() > 1e-10)
                .cloned()
                .collect(),
            rainbows: ir.rainbows.clone(),
            max_trace_level: ir.settings.max_trace_level,
            adc_bailout: ir.settings.adc_bailout,
            ambient_light: ir.settings.ambient_light,
            legacy_transparency: ir.settings.legacy_transparency,
            noise_generator: ir.settings.noise_generator,
            irid_wavelength: ir.settings.irid_wavelength,
            radiosity: ir.settings.radiosity.clone(),
            gamma: ir.settings.gamma,
            index: None,
            scan_bounds: Vec::new(),
            any_transparent: false,
            any_hidden: false,
            shadow_fades: false,
            cull_shadow_rays: true,
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
        scene.any_transparent = scene.objects.iter().any(|o| o.shadow.filters());
        scene.any_hidden = scene.objects.iter().any(|o| {
            let sight = o.sight();
            sight.no_image || sight.no_reflection || sight.no_radiosity
        });
        scene.shadow_fades = scene
            .objects
            .iter()
            .any(|o| o.shadow.filters() && fades(&scene.interiors[o.interior as usize]));
        (scene, bounds, taken)
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
    #[cfg(any(test, feature = "internals"))]
    pub fn has_index(&self) -> bool {
        self.index.is_some()
    }

    /// The same scene with area lights' shadow rays not culled (the tests check the pictures
    /// are the same without).
    #[cfg(test)]
    pub fn without_shadow_culling(mut self) -> Scene {
        self.cull_shadow_rays = false;
        self
    }

    /// How many objects the scene holds (their ids run from 0).
    #[cfg(test)]
    pub fn object_count(&self) -> usize {
        self.objects.len()
    }

    /// The same scene without its top-level BVH, testing every object for every ray: the
    /// stability suite compares its pictures with the BVH's.
    #[cfg(feature = "internals")]
    pub fn without_index(mut self) -> Scene {
        self.index = None;
        self.scan_bounds = self.objects.iter().map(Object::world_bounds).collect();
        self
    }
}

/// If `m` is a translation plus uniform scale, the sphere it maps `s` to.
fn similarity_sphere(s: &Sphere, m: &DMat4) -> Option<(DVec3, f64)> {
    let linear = DMat3::from_mat4(*m);
    let k = linear.x_axis.x;
    let is_uniform_scale = k > 0.0 && linear == DMat3::from_diagonal(DVec3::splat(k));
    is_uniform_scale.then(|| (m.transform_point3(s.centre), s.radius * k))
}

/// The render shape for an IR shape, with its (possibly extended) object transform. Meshes
/// are built once per distinct IR mesh and shared.
fn build_shape(
    shape: &ir::Shape,
    transform: Option<DMat4>,
    meshes: &HashMap<usize, Arc<TriangleMesh>>,
    generator: u8,
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
        ir::Shape::Quadric(q) => (
            Shape::Quadric(Box::new(Quadric {
                square: q.square,
                mixed: q.mixed,
                linear: q.linear,
                constant: q.constant,
            })),
            transform,
        ),
        ir::Shape::Polynomial(p) => (
            Shape::Polynomial(Box::new(Polynomial {
                degree: p.degree,
                terms: p.terms.clone().into_boxed_slice(),
            })),
            transform,
        ),
        ir::Shape::Polygon(points) => (Shape::Polygon(Box::new(Polygon::new(points))), transform),
        ir::Shape::Text(text) => (Shape::Text(Box::new(build_text(text))), transform),
        ir::Shape::Prism(p) => {
            let segments = p
                .segments
                .iter()
                .map(|s| CurveSegment::new(s.u, s.v))
                .collect();
            let prism = Prism::new(
                p.sweep == ir::Sweep::Conic,
                p.degree,
                p.heights,
                p.closed,
                segments,
            );
            (Shape::Prism(Box::new(prism)), transform)
        }
        ir::Shape::Lathe(l) => {
            let segments = l
                .segments
                .iter()
                .map(|s| CurveSegment::new(s.u, s.v))
                .collect();
            (
                Shape::Lathe(Box::new(Lathe::new(l.degree, segments))),
                transform,
            )
        }
        ir::Shape::Sor(s) => {
            let pieces = s
                .segments
                .iter()
                .map(|p| SorPiece::new(p.coefficients, p.heights.0, p.heights.1))
                .collect();
            (Shape::Sor(Box::new(Sor::new(pieces, s.closed))), transform)
        }
        ir::Shape::Blob(b) => {
            let mut elements = Vec::new();
            for c in &b.components {
                match c.reach {
                    ir::BlobReach::Sphere(centre) => elements.push(BlobElement::sphere(
                        centre,
                        c.radius,
                        c.strength,
                        c.transform,
                    )),
                    ir::BlobReach::Cylinder(a, e) => elements.extend(BlobElement::cylinder(
                        a,
                        e,
                        c.radius,
                        c.strength,
                        c.transform,
                    )),
                }
            }
            (
                Shape::Blob(Box::new(Blob::new(b.threshold, elements))),
                transform,
            )
        }
        ir::Shape::HeightField(h) => {
            let smooth = h.smooth.then(|| transform.unwrap_or(DMat4::IDENTITY));
            let hf = HeightField::new(
                h.width as usize,
                h.depth as usize,
                Arc::clone(&h.heights),
                h.water_level,
                smooth,
            );
            (Shape::HeightField(Box::new(hf)), transform)
        }
        ir::Shape::Isosurface(i) => {
            let iso = crate::geometry::Isosurface::new(
                std::sync::Arc::clone(&i.function),
                generator,
                match i.container {
                    ir::Container::Box(a, b) => crate::geometry::Container::Box(a, b),
                    ir::Container::Sphere(c, r) => crate::geometry::Container::Sphere(c, r),
                },
                i.threshold,
                i.accuracy,
                i.max_gradient,
                i.closed,
                i.max_trace,
            );
            (Shape::Isosurface(Box::new(iso)), transform)
        }
        ir::Shape::Parametric(p) => {
            let surface = crate::geometry::Parametric::new(
                p.functions.clone(),
                generator,
                match p.container {
                    ir::Container::Box(a, b) => crate::geometry::Container::Box(a, b),
                    ir::Container::Sphere(c, r) => crate::geometry::Container::Sphere(c, r),
                },
                p.uv.0,
                p.uv.1,
                p.accuracy,
                p.max_gradient,
                p.precompute,
            );
            (Shape::Parametric(Box::new(surface)), transform)
        }
        ir::Shape::SphereSweep(s) => {
            let curve = match s.spline {
                ir::SweepSpline::Linear => crate::geometry::SweepCurve::Linear,
                ir::SweepSpline::CatmullRom => crate::geometry::SweepCurve::CatmullRom,
                ir::SweepSpline::BSpline => crate::geometry::SweepCurve::BSpline,
            };
            let sweep = crate::geometry::SphereSweep::new(curve, &s.spheres, s.tolerance);
            (Shape::SphereSweep(Box::new(sweep)), transform)
        }
        ir::Shape::Ovus { bottom, top } => (
            Shape::Ovus(Box::new(crate::geometry::Ovus::new(*bottom, *top))),
            transform,
        ),
        ir::Shape::JuliaFractal(j) => {
            let fractal = crate::geometry::JuliaFractal::new(
                j.c,
                j.hypercomplex,
                j.cube,
                j.iterations,
                j.precision,
                j.slice.0,
                j.slice.1,
            );
            (Shape::JuliaFractal(Box::new(fractal)), transform)
        }
        ir::Shape::BicubicPatch(b) => {
            // Subdivided in the world, as POV-Ray subdivides it (its flatness is a world
            // distance, and its corner normals are world normals).
            let m = transform.unwrap_or(DMat4::IDENTITY);
            let points = b.points.map(|row| row.map(|p| m.transform_point3(p)));
            let mesh = crate::geometry::bezier::patch_mesh(
                &points,
                b.u_steps,
                b.v_steps,
                b.flatness,
                b.uv_corners,
            );
            (Shape::Mesh(Arc::new(mesh)), None)
        }
        ir::Shape::Superellipsoid { e, n } => (
            Shape::Superellipsoid(Superellipsoid::new(*e, *n)),
            transform,
        ),
        ir::Shape::Mesh(mesh) => {
            let built = &meshes[&(Arc::as_ptr(mesh) as usize)];
            (Shape::Mesh(Arc::clone(built)), transform)
        }
    }
}

fn build_mesh(mesh: &ir::Mesh) -> TriangleMesh {
    // Corner entries of the object's material (see `mesh_material`): 0 the object's own
    // texture, 1 + i the mesh's texture i.
    let entry = |t: u32| if t == ir::OWN_TEXTURE { 0 } else { t + 1 };
    let mut built = TriangleMesh::with_corner_entries(
        mesh.vertices.clone(),
        mesh.triangles.clone(),
        mesh.normals.clone(),
        mesh.normal_indices.clone(),
        mesh.uvs.clone(),
        mesh.uv_indices.clone(),
        mesh.face_textures.iter().map(|f| f.map(entry)).collect(),
    );
    built.inside_vector = mesh.inside_vector;
    built.world_uv = mesh.world_uv;
    built
}

/// The geometry of laid-out text: each glyph's curves as edges.
fn build_text(text: &ir::Text) -> Text {
    let edge = |c: &ir::Curve| match *c {
        ir::Curve::Line(start, end) => Edge {
            start,
            control: start,
            end,
            curved: false,
        },
        ir::Curve::Quad(start, control, end) => Edge {
            start,
            control,
            end,
            curved: true,
        },
    };
    Text::new(
        text.thickness,
        text.glyphs
            .iter()
            .map(|g| g.curves.iter().map(edge).collect()),
    )
}

/// A shape placed by `transform`, for ray tests outside the object index (`bounded_by`,
/// `projected_through`).
fn bound_shape(shape: &ir::Shape, transform: Option<&ir::Transform>, generator: u8) -> BoundShape {
    let meshes: HashMap<usize, Arc<TriangleMesh>> = match shape {
        ir::Shape::Mesh(m) => HashMap::from([(Arc::as_ptr(m) as usize, Arc::new(build_mesh(m)))]),
        _ => HashMap::new(),
    };
    let (shape, transform) = build_shape(shape, transform.map(|t| t.matrix), &meshes, generator);
    BoundShape {
        shape,
        transform: transform.map(ObjectTransform::new),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An object of `shape` with the defaults, placed by `transform`.
    fn ir_object(shape: ir::Shape, transform: Option<DMat4>) -> ir::Object {
        ir::Object {
            shape,
            transform: transform.map(|matrix| Box::new(ir::Transform { matrix })),
            texture: ir::Texture::default(),
            extras: None,
            interior: Default::default(),
            no_shadow: false,
            inverse: false,
            hollow: false,
            member: 0,
            medium: 0,
        }
    }

    /// A scene of `objects` and nothing else.
    fn ir_scene(objects: Vec<ir::Object>) -> ir::Scene {
        ir::Scene {
            camera: ir::Camera::default(),
            lights: vec![],
            objects,
            background: Rgb::ZERO,
            background_alpha: 0.0,
            sky_sphere: None,
            fogs: vec![],
            rainbows: vec![],
            atmosphere: vec![],
            settings: ir::Settings::default(),
        }
    }

    fn scene_with(shape: ir::Shape, transform: DMat4) -> Scene {
        Scene::build(&ir_scene(vec![ir_object(shape, Some(transform))]))
    }

    #[test]
    fn a_mesh_of_unchanged_data_is_taken_from_the_cache() {
        let mesh = |y: f32| ir::Mesh {
            vertices: vec![
                glam::Vec3::ZERO,
                glam::Vec3::X,
                glam::Vec3::new(0.0, y, 0.0),
            ],
            triangles: vec![[0, 1, 2]],
            ..ir::Mesh::default()
        };
        // (Two objects, each with its own copy of the mesh's data.)
        let scene = |m: ir::Mesh| {
            ir_scene(
                (0..2)
                    .map(|_| ir_object(ir::Shape::Mesh(Arc::new(m.clone())), None))
                    .collect(),
            )
        };
        let built = |s: &Scene| -> Vec<*const TriangleMesh> {
            (s.objects.iter())
                .map(|o| match &o.shape {
                    Shape::Mesh(m) => Arc::as_ptr(m),
                    _ => panic!("a mesh"),
                })
                .collect()
        };
        let cache = MeshCache::default();
        let first = Scene::build_owned(scene(mesh(1.0)), Some(&cache));
        // (Two objects of equal data share one built mesh, though their IR meshes differ.)
        assert_eq!(built(&first)[0], built(&first)[1]);
        assert_eq!(cache.count(), 1);
        let again = Scene::build_owned(scene(mesh(1.0)), Some(&cache));
        assert_eq!(built(&again), built(&first), "the same data: the same mesh");
        let moved = Scene::build_owned(scene(mesh(1.5)), Some(&cache));
        assert_ne!(
            built(&moved)[0],
            built(&first)[0],
            "a vertex moved: built again"
        );
        assert_eq!(
            cache.count(),
            1,
            "only the meshes of the last build are kept"
        );
        assert_ne!(mesh_print(&mesh(1.0)), mesh_print(&mesh(1.5)));
        let flat_uv = ir::Mesh {
            world_uv: true,
            ..mesh(1.0)
        };
        assert_ne!(mesh_print(&mesh(1.0)), mesh_print(&flat_uv));
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
