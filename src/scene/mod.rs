//! The render-ready scene: IR → dense arrays the tracer reads without interpretation.
//!
//! Transformations are composed and inverted here, once; materials are resolved and stored
//! once per distinct value; lights are collected. The renderer sees only this module's types.
//! This file holds the types; `build` makes them from the IR, `query` answers the tracer's
//! ray queries (through `accel`, the one place that knows the BVH), `material`, `pigment` and
//! `normal` evaluate surfaces. Shapes themselves are `geometry::Shape`.

use crate::geometry::{BlobElement, Crossings, Ray, Shape, TriangleMesh, offset_origin};
use crate::ir;
use glam::{DMat3, DMat4, DVec3};
use std::sync::Arc;

mod accel;
pub mod blur;
mod build;
mod material;
mod media;
pub mod meshcam;
mod normal;
mod probe;
mod query;

pub use crate::ir::{
    AreaLight, Colour, Finish, Fog, FogKind, Gamma, Interior, LightFade, LightKind, Projection,
    Radiosity, Rainbow, Rgb,
};
pub use crate::noise::mt19937;
/// What patterns may see of the surface at a hit (the renderer passes it on).
pub use crate::pattern::Surface as PatternSurface;
pub use crate::pattern::{PlacedPigment, lookup as colour_map_at};
pub use build::{MeshCache, Reuse};
pub use material::{Material, filter_colour};
pub use media::Media;
pub use normal::Normal;
pub use probe::object_query;
pub use query::{Queries, Seer, ShadowCrossing, ShadowHull, fades};

/// A material of the scene (an index into its distinct materials).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MaterialId(pub u32);

/// An object of the scene (an index into its objects, in scene order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ObjectId(pub u32);

/// The scene as the tracer reads it.
#[derive(Debug)]
pub struct Scene {
    /// The camera.
    camera: Camera,
    /// The camera's focal blur, if any.
    blur: Option<blur::Blur>,
    /// The camera's `normal`, bending its rays, if any.
    camera_normal: Option<Normal>,
    /// The `mesh_camera`, if the camera is one.
    mesh_camera: Option<meshcam::MeshCamera>,
    /// Point lights.
    lights: Vec<Light>,
    /// Objects.
    objects: Vec<Object>,
    /// Distinct materials.
    materials: Vec<Material>,
    /// Distinct interiors.
    interiors: Vec<Interior>,
    /// The media of each of `interiors` (most have none).
    interior_media: Vec<Vec<Media>>,
    /// Top-level `media`: the atmosphere.
    atmosphere: Vec<Media>,
    /// Whether any interior holds media (asked by every shadow ray).
    any_interior_media: bool,
    /// Colour of escaped rays.
    background: Rgb,
    /// The background's opacity in an alpha channel.
    background_alpha: f64,
    /// `sky_sphere`: the colour of escaped rays by direction.
    sky_sphere: Option<SkySphere>,
    /// Fogs with a positive distance (POV-Ray skips the others).
    fogs: Vec<Fog>,
    /// Rainbows, seen on rays in hollow space.
    rainbows: Vec<Rainbow>,
    /// POV-Ray's bounding is on (three or more top-level objects and lights): it then tests
    /// unbounded objects first.
    bounded_last: bool,
    /// Rays at a deeper level return black.
    max_trace_level: u32,
    /// Rays of lower weight return black.
    adc_bailout: f64,
    /// Multiplies every finish's ambient.
    ambient_light: Rgb,
    /// Pre-3.7 surface attenuation.
    legacy_transparency: bool,
    /// The scene's noise generator (fog turbulence; patterns carry their own).
    noise_generator: u8,
    /// `irid_wavelength`: the wavelengths of thin-film interference (`irid`).
    irid_wavelength: Rgb,
    radiosity: Option<Radiosity>,
    /// Working gamma (applied when the film is written).
    gamma: Gamma,
    /// Top-level BVH over the objects (`None` for small scenes).
    index: Option<accel::ObjectIndex>,
    /// Without an index, the world bounds of each object (`None` for unbounded ones), tested
    /// before the object; empty with an index, which holds them.
    scan_bounds: Vec<Option<(DVec3, DVec3)>>,
    /// Whether any object may let light through to a shadow ray (else shadow rays stop at
    /// the any-hit test for opaque blockers).
    any_transparent: bool,
    /// Whether any object that may let light through to a shadow ray has an interior that
    /// fades: shadow rays then walk their crossings in order (transport's shadow walk).
    shadow_fades: bool,
    /// Whether area lights first find what may block their shadow rays (on; off only to
    /// test that the pictures are the same without).
    cull_shadow_rays: bool,
    /// Whether any object is hidden from some rays (`no_image`, `no_reflection`): only then
    /// does the nearest-hit search look at the rays' kind.
    any_hidden: bool,
}

/// What the renderer reads of the scene besides its [`Queries`]: the camera, lights, sky and
/// settings (the fields are the scene's own).
impl Scene {
    /// The camera.
    #[inline]
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    /// The camera's focal blur, if any.
    #[inline]
    pub fn blur(&self) -> Option<&blur::Blur> {
        self.blur.as_ref()
    }

    /// The camera's `normal`, bending its rays, if any.
    #[inline]
    pub fn camera_normal(&self) -> Option<&Normal> {
        self.camera_normal.as_ref()
    }

    /// The `mesh_camera`, if the camera is one.
    #[inline]
    pub fn mesh_camera(&self) -> Option<&meshcam::MeshCamera> {
        self.mesh_camera.as_ref()
    }

    /// Point lights.
    #[inline]
    pub fn lights(&self) -> &[Light] {
        &self.lights
    }

    /// Colour of escaped rays.
    #[inline]
    pub fn background(&self) -> Rgb {
        self.background
    }

    /// The background's opacity in an alpha channel.
    #[inline]
    pub fn background_alpha(&self) -> f64 {
        self.background_alpha
    }

    /// `sky_sphere`: the colour of escaped rays by direction.
    #[inline]
    pub fn sky_sphere(&self) -> Option<&SkySphere> {
        self.sky_sphere.as_ref()
    }

    /// Fogs with a positive distance (POV-Ray skips the others).
    #[inline]
    pub fn fogs(&self) -> &[Fog] {
        &self.fogs
    }

    /// Rainbows, seen on rays in hollow space (not on shadow rays).
    #[inline]
    pub fn rainbows(&self) -> &[Rainbow] {
        &self.rainbows
    }

    /// The atmosphere: top-level media, seen on rays in hollow space.
    #[inline]
    pub fn atmosphere(&self) -> &[Media] {
        &self.atmosphere
    }

    /// The media inside object `id` (seen by rays inside it when it is hollow).
    #[inline]
    pub fn media_in(&self, id: ObjectId) -> &[Media] {
        &self.interior_media[self.objects[id.0 as usize].interior as usize]
    }

    /// Whether any object holds media.
    #[inline]
    pub fn any_interior_media(&self) -> bool {
        self.any_interior_media
    }

    /// POV-Ray's bounding is on (three or more top-level objects and lights): it then tests
    /// unbounded objects first.
    #[inline]
    pub fn bounded_last(&self) -> bool {
        self.bounded_last
    }

    /// Rays at a deeper level return black.
    #[inline]
    pub fn max_trace_level(&self) -> u32 {
        self.max_trace_level
    }

    /// Rays of lower weight return black.
    #[inline]
    pub fn adc_bailout(&self) -> f64 {
        self.adc_bailout
    }

    /// Multiplies every finish's ambient.
    #[inline]
    pub fn ambient_light(&self) -> Rgb {
        self.ambient_light
    }

    /// Pre-3.7 surface attenuation.
    #[inline]
    pub fn legacy_transparency(&self) -> bool {
        self.legacy_transparency
    }

    /// `radiosity { … }`, if on.
    pub fn radiosity(&self) -> Option<&Radiosity> {
        self.radiosity.as_ref()
    }

    /// The scene's noise generator (fog turbulence; patterns carry their own).
    #[inline]
    pub fn noise_generator(&self) -> u8 {
        self.noise_generator
    }

    /// Working gamma (applied when the film is written).
    #[inline]
    pub fn gamma(&self) -> Gamma {
        self.gamma
    }

    /// Whether any object may let light through to a shadow ray (else shadow rays stop at
    /// the any-hit test for opaque blockers).
    #[inline]
    pub fn any_transparent(&self) -> bool {
        self.any_transparent
    }

    /// Whether any object that may let light through to a shadow ray has an interior that
    /// fades: shadow rays then walk their crossings in order (transport's shadow walk).
    #[inline]
    pub fn shadow_fades(&self) -> bool {
        self.shadow_fades
    }

    /// Whether area lights first find what may block their shadow rays (on; off only to
    /// test that the pictures are the same without).
    #[inline]
    pub fn cull_shadow_rays(&self) -> bool {
        self.cull_shadow_rays
    }

    /// Whether the scene tests every object for every ray (it has too few for a top-level
    /// index): finding what may block a point light from a pyramid then costs about what one
    /// shadow ray does, and the pyramid serves the points around its apex too.
    #[inline]
    pub fn scans_objects(&self) -> bool {
        self.index.is_none()
    }
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
    /// The unit axis of a spot or cylinder light, toward its `point_at` (zero for others).
    pub axis: DVec3,
    /// A spotlight's cos(radius) (1 for other lights).
    pub cos_radius: f64,
    /// A spotlight's cos(falloff) (1 for other lights).
    pub cos_falloff: f64,
    /// No shadows, no highlights.
    pub shadowless: bool,
    /// Distance attenuation.
    pub fade: Option<LightFade>,
    /// Soft-shadow grid.
    pub area: Option<AreaLight>,
    /// An area light's grid points as offsets along its axes ([`grid_offset`]), row by row
    /// (`v · size1 + u`), worked out once: empty for a jittered light (its points move with
    /// the shaded point) or a grid of more than [`GRID_TABLE_POINTS`] points.
    pub grid: Box<[(f64, f64)]>,
    /// `projected_through`: the shapes light must cross to reach a point.
    pub through: Option<Box<[BoundShape]>>,
    /// The `light_group` it lights alone.
    pub group: Option<u32>,
    /// It scatters in media (`media_interaction`).
    pub media_interaction: bool,
    /// The atmosphere dims its shadow rays (`media_attenuation`).
    pub media_attenuation: bool,
}

/// Area lights of up to this many grid points keep their points' offsets ([`Light::grid`]).
pub const GRID_TABLE_POINTS: u32 = 4096;

/// The offsets in [−½, ½]² along an area light's axes of its grid point (u, v) moved by
/// `(ju, jv)` cells (its jitter), mapped onto the disc for a `circular` or `orient`ed light.
pub fn grid_offset(area: &AreaLight, (u, v): (u32, u32), (ju, jv): (f64, f64)) -> (f64, f64) {
    let along = |i: u32, j: f64, size: u32| {
        if size > 1 {
            (i as f64 + j) / (size - 1) as f64 - 0.5
        } else {
            0.0
        }
    };
    disc_offset(area, (along(u, ju, area.size1), along(v, jv, area.size2)))
}

/// Offsets in [−½, ½]² as a light places them: mapped onto the disc for a `circular` or
/// `orient`ed light, as they are otherwise.
pub fn disc_offset(area: &AreaLight, (s1, s2): (f64, f64)) -> (f64, f64) {
    if area.circular || area.orient {
        square_to_disc(s1, s2)
    } else {
        (s1, s2)
    }
}

/// POV-Ray's `circular` mapping of grid offsets in [−½, ½]²: square shells onto circles
/// (with its constant 0.001 bias, so the centre point is slightly off centre).
fn square_to_disc(x: f64, y: f64) -> (f64, f64) {
    const BIAS: f64 = 0.001;
    let (a, b) = (x + BIAS, y + BIAS);
    let s = a.abs().max(b.abs()) / (a * a + b * b).sqrt();
    (a * s, b * s)
}

/// An area light's table of grid offsets ([`Light::grid`]).
pub(crate) fn grid_table(area: Option<&AreaLight>) -> Box<[(f64, f64)]> {
    match area {
        Some(a) if !a.jitter && a.size1.saturating_mul(a.size2) <= GRID_TABLE_POINTS => (0..a
            .size2)
            .flat_map(|v| (0..a.size1).map(move |u| grid_offset(a, (u, v), (0.0, 0.0))))
            .collect(),
        _ => Box::new([]),
    }
}

/// The sky: pigments of the ray's direction, the last on top.
#[derive(Clone, Debug, PartialEq)]
pub struct SkySphere {
    /// Bottom layer first.
    pub pigments: Vec<PlacedPigment>,
    /// Multiplies the pigments' colours.
    pub emission: Rgb,
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
    /// What it does to shadow rays (`no_shadow`, its materials' transparency).
    pub shadow: ShadowRole,
    /// Inside swapped with outside.
    pub inverse: bool,
    /// Fog reaches rays inside it.
    pub hollow: bool,
    /// Place in POV-Ray's test order, which decides between two hits at the same distance
    /// (see [`Scene::intersect`]; lower first).
    pub rank: u64,
    /// Index of refraction and fade: an index into the scene's distinct interiors (equal interiors are
    /// stored once).
    pub interior: u32,
    /// Objects with equal media share one interior (see [`ir::Object::medium`]).
    pub medium: u32,
    /// What few objects have (an interior texture, `bounded_by`), boxed to keep the others
    /// small.
    pub extra: Option<Box<ObjectExtra>>,
}

/// What an object does to shadow rays, from `no_shadow` and whether its materials (outside
/// and inside) may let light through: worked out with the scene, so that a shadow ray's test
/// of an object reads no material.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadowRole {
    /// `no_shadow`: shadow rays pass as if it were not there.
    None,
    /// Opaque: it blocks any shadow ray it lies on.
    Blocks,
    /// Its outside may let light through: a shadow ray is filtered where it crosses it.
    Filters,
    /// An opaque outside with an inside that may let light through: it blocks, and a
    /// shadow ray's crossings of it are listed.
    FiltersAndBlocks,
}

impl ShadowRole {
    /// The role of an object with `no_shadow` or not whose outside and inside materials may
    /// or may not let light through.
    pub fn new(no_shadow: bool, outside_clear: bool, inside_clear: bool) -> ShadowRole {
        match (no_shadow, outside_clear, inside_clear) {
            (true, _, _) => ShadowRole::None,
            (false, true, _) => ShadowRole::Filters,
            (false, false, true) => ShadowRole::FiltersAndBlocks,
            (false, false, false) => ShadowRole::Blocks,
        }
    }

    /// Whether shadow rays see it at all.
    #[inline]
    pub fn casts(self) -> bool {
        self != ShadowRole::None
    }

    /// Whether it blocks a shadow ray that meets it.
    #[inline]
    pub fn blocks(self) -> bool {
        matches!(self, ShadowRole::Blocks | ShadowRole::FiltersAndBlocks)
    }

    /// Whether light may pass through it filtered (its crossings are listed).
    #[inline]
    pub fn filters(self) -> bool {
        matches!(self, ShadowRole::Filters | ShadowRole::FiltersAndBlocks)
    }
}

/// The parts of an object that few objects have.
#[derive(Clone, Debug, Default)]
pub struct ObjectExtra {
    /// Its material seen from inside (`interior_texture`).
    pub back_material: Option<MaterialId>,
    /// `bounded_by`: the shapes whose box bounds the object.
    pub bounds: Box<[BoundShape]>,
    /// `no_image`, `no_reflection`, `double_illuminate`.
    pub sight: crate::ir::Sight,
    /// For an object in a `light_group`: which lights light it.
    pub light_group: Option<crate::ir::LightGroup>,
    /// `radiosity { importance F }` (1 when not given).
    pub importance: f64,
    /// Whether a ray must also cross each bounding shape (or start inside it) to reach the
    /// object.
    pub test_rays: bool,
}

/// A `bounded_by` shape in the world.
#[derive(Clone, Debug)]
pub struct BoundShape {
    shape: Shape,
    transform: Option<ObjectTransform>,
}

impl BoundShape {
    /// The nearest crossing of `ray` with the shape within the ray's range.
    pub fn first_hit(&self, ray: &Ray) -> Option<f64> {
        let local = match &self.transform {
            None => *ray,
            Some(t) => ray.transformed(&t.object_from_world),
        };
        self.shape.intersect(&local).first()
    }

    /// POV-Ray's `Ray_In_Bound` for one bound: the ray (anywhere ahead) crosses it, or starts
    /// inside it.
    fn admits(&self, ray: &Ray) -> bool {
        let mut ahead = *ray;
        ahead.tmax = f64::INFINITY;
        let (local, origin) = match &self.transform {
            None => (ahead, ray.origin),
            Some(t) => (
                ahead.transformed(&t.object_from_world),
                t.object_from_world.transform_point3(ray.origin),
            ),
        };
        !self.shape.intersect(&local).is_empty() || self.shape.contains(origin)
    }

    /// The world box around the bound, `None` when unbounded.
    fn world_bounds(&self) -> Option<(DVec3, DVec3)> {
        let m = self.transform.as_ref().map(|t| &t.world_from_object);
        self.shape.bounds().map(|(lo, hi)| world_bounds(lo, hi, m))
    }
}

impl Object {
    /// The material seen along `direction` at a surface of unit normal `normal` (outward,
    /// before any `inverse`): the interior texture where the normal faces away from the ray,
    /// as POV-Ray picks it.
    #[inline]
    fn side(&self, normal: DVec3, direction: DVec3) -> MaterialId {
        let Some(back) = self.extra.as_ref().and_then(|e| e.back_material) else {
            return self.material;
        };
        let outward = if self.inverse { -normal } else { normal };
        if outward.dot(direction) > 0.0 {
            back
        } else {
            self.material
        }
    }

    /// Its material seen from inside (the outside one if it has no interior texture).
    pub fn back_material(&self) -> MaterialId {
        self.extra
            .as_ref()
            .and_then(|e| e.back_material)
            .unwrap_or(self.material)
    }

    /// The world-space bounding box, `None` for unbounded shapes. Bounds that overflowed (a
    /// huge scale) make the object unbounded, tested for every ray, rather than a box no
    /// structure can hold.
    fn world_bounds(&self) -> Option<(DVec3, DVec3)> {
        let m = self.transform.as_ref().map(|t| &t.world_from_object);
        // A bounded object's box is its bound's (the common part of several), as in POV-Ray.
        let own = self.shape.bounds().map(|(lo, hi)| world_bounds(lo, hi, m));
        let bound = self
            .extra
            .iter()
            .flat_map(|e| e.bounds.iter())
            .filter_map(BoundShape::world_bounds)
            .reduce(|(alo, ahi), (blo, bhi)| (alo.max(blo), ahi.min(bhi)));
        bound
            .or(own)
            .filter(|(lo, hi)| lo.is_finite() && hi.is_finite())
    }

    /// Whether a ray may reach the object through its `bounded_by` shapes.
    #[inline]
    /// The surface's (u, v) at world point `p` of part `part` (`uv_mapping`): the shape's own
    /// coordinates, or POV-Ray's default, the world point's x and y.
    pub fn uv(&self, p: DVec3, part: u32) -> glam::DVec2 {
        let local = match &self.transform {
            None => p,
            Some(t) => t.object_from_world.transform_point3(p),
        };
        self.shape
            .uv(local, part)
            .unwrap_or(glam::DVec2::new(p.x, p.y))
    }

    /// The material entries of the corners of mesh triangle `part` and the weights world
    /// point `p` gives them (none for other shapes).
    pub fn corners(&self, p: DVec3, part: u32) -> ([u32; 3], DVec3) {
        let Shape::Mesh(mesh) = &self.shape else {
            return Default::default();
        };
        let local = match &self.transform {
            None => p,
            Some(t) => t.object_from_world.transform_point3(p),
        };
        mesh.corners(local, part).unwrap_or_default()
    }

    /// `no_image`, `no_reflection`, `double_illuminate`.
    pub fn sight(&self) -> crate::ir::Sight {
        self.extra
            .as_ref()
            .map_or_else(Default::default, |e| e.sight)
    }

    /// `radiosity { importance F }` (default 1).
    pub fn importance(&self) -> f64 {
        self.extra.as_ref().map_or(1.0, |e| e.importance)
    }

    /// Whether `light` lights the object (a group's lights light only its members, whom
    /// the other lights light only with `global_lights`).
    pub fn lit_by(&self, light: &Light) -> bool {
        let group = self.extra.as_ref().and_then(|e| e.light_group.as_ref());
        match (light.group, group) {
            (None, None) => true,
            (None, Some(g)) => g.global_lights,
            (Some(id), Some(g)) => g.groups.contains(&id),
            (Some(_), None) => false,
        }
    }

    /// Whether a ray of kind `seer` sees the object.
    fn seen_by(&self, seer: Seer) -> bool {
        let sight = self.sight();
        let image = !seer.reflected && !seer.sample;
        !((image && sight.no_image)
            || (seer.reflected && sight.no_reflection)
            || (seer.radiosity && sight.no_radiosity))
    }

    fn admits(&self, ray: &Ray) -> bool {
        self.extra
            .as_ref()
            .is_none_or(|e| !e.test_rays || e.bounds.iter().all(|b| b.admits(ray)))
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
    /// What patterns may see of the surface (`slope`, `aoi`, `uv_mapping`).
    pub surface: crate::pattern::Surface,
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Each object's part in shadow rays comes from `no_shadow` and its materials: an opaque
    /// object blocks, a clear one filters, an opaque one with a clear inside does both, a
    /// `no_shadow` one neither; and the scene's flags follow from them.
    #[test]
    fn shadow_roles_come_from_no_shadow_and_both_sides() {
        let opaque = "pigment { rgb 1 }";
        let clear = "pigment { rgbf <1, 1, 1, 0.9> }";
        let scene = crate::testing::scene(format!(
            "sphere {{ 0, 1 {opaque} }}\n\
             sphere {{ 0, 1 {clear} }}\n\
             sphere {{ 0, 1 texture {{ {opaque} }} interior_texture {{ {clear} }} }}\n\
             sphere {{ 0, 1 {clear} no_shadow }}\n\
             sphere {{ 0, 1 {opaque} no_shadow }}\n"
        ));
        let roles: Vec<ShadowRole> = (0..5).map(|i| scene.object(ObjectId(i)).shadow).collect();
        use ShadowRole::*;
        assert_eq!(roles, [Blocks, Filters, FiltersAndBlocks, None, None]);
        assert!(scene.any_transparent());
        let opaque_only = crate::testing::scene(format!(
            "sphere {{ 0, 1 {opaque} }}\nsphere {{ 0, 1 {clear} no_shadow }}\n"
        ));
        assert!(!opaque_only.any_transparent());
    }

    #[test]
    fn circular_grid_keeps_direction_at_shell_radius() {
        let (x, y) = square_to_disc(0.5 - 0.001, 0.5 - 0.001);
        assert!(((x * x + y * y).sqrt() - 0.5).abs() < 1e-12);
        let (x, y) = square_to_disc(0.5 - 0.001, -0.001);
        assert!((x - 0.5).abs() < 1e-12 && y.abs() < 1e-12);
    }

    /// The table holds each grid point's offsets as worked out point by point.
    #[test]
    fn grid_table_holds_each_points_offsets() {
        for (circular, jitter) in [(false, false), (true, false), (true, true)] {
            let area = AreaLight {
                axis1: DVec3::X,
                axis2: DVec3::Z,
                size1: 5,
                size2: 3,
                adaptive: 1,
                jitter,
                circular,
                orient: false,
                area_illumination: false,
            };
            let table = grid_table(Some(&area));
            if jitter {
                assert!(table.is_empty());
                continue;
            }
            assert_eq!(table.len(), 15);
            for v in 0..3 {
                for u in 0..5 {
                    let (s1, s2) = grid_offset(&area, (u, v), (0.0, 0.0));
                    assert_eq!(table[(v * 5 + u) as usize], (s1, s2));
                }
            }
            assert_eq!(table[0], disc_offset(&area, (-0.5, -0.5)));
        }
    }
}
