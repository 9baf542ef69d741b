//! The intermediate representation: a scene as evaluated plain data.
//!
//! No identifiers, no expressions, no syntax: every default is filled in, every transformation
//! composed. The parser's evaluation produces it; `scene::build` consumes it. It knows nothing
//! of pest or of rendering state. Its `Debug` output is what the parse snapshots record.

use glam::{DMat4, DVec3, Vec3};
use std::sync::Arc;

pub use crate::pattern::{Colour, Pattern, PatternKind, Rgb, Warp, Wave, WaveShape};

mod dedup;
mod outline;
pub use dedup::Shared;
pub use outline::{
    BicubicPatch, Blob, BlobComponent, BlobReach, Container, Curve, Glyph, HeightField, Isosurface,
    JuliaFractal, Lathe, Parametric, Prism, Segment, Sor, SorSegment, SphereSweep, Spline, Sweep,
    SweepSpline, Text,
};

/// What evaluation asks of an object it has made (`trace()`, `inside()`, `min_extent`,
/// `max_extent`). The scene layer answers (it builds the object as a scene of its own);
/// evaluation receives the maker from the library.
pub trait ObjectQuery: Send + Sync {
    /// The first hit of the ray from `origin` along the unit `direction`: the point and the
    /// surface's unit normal (outward, reversed by `inverse`, not bent by a normal pattern).
    fn trace(&self, origin: DVec3, direction: DVec3) -> Option<(DVec3, DVec3)>;
    /// Whether `p` is inside the object.
    fn inside(&self, p: DVec3) -> bool;
    /// The object's bounding box (±1e10 along an unbounded side, as POV-Ray's), in single
    /// precision as POV-Ray keeps it.
    fn extent(&self) -> (DVec3, DVec3);
}

/// The whole scene.
#[derive(Clone, PartialEq)]
pub struct Scene {
    /// The camera (POV-Ray's default camera when the scene has none).
    pub camera: Camera,
    /// Light sources in scene order.
    pub lights: Vec<Light>,
    /// Objects in scene order.
    pub objects: Vec<Object>,
    /// Colour of rays that hit nothing (`background { color C }`), already multiplied by
    /// `1 − transmit` as POV-Ray does without alpha output.
    pub background: Rgb,
    /// The background's opacity in an alpha channel, `1 − transmit` (0 without a background
    /// statement: POV-Ray's default background is transparent).
    pub background_alpha: f64,
    /// `sky_sphere { pigment … }`: the colour of escaped rays by direction, over the
    /// background.
    pub sky_sphere: Option<SkySphere>,
    /// `fog { … }` statements (their order does not matter).
    pub fogs: Vec<Fog>,
    /// Top-level `media { … }` blocks: the atmosphere, in source order.
    pub atmosphere: Vec<Media>,
    /// `rainbow { … }` statements that can be seen (with a colour map, a width and a
    /// distance), in source order.
    pub rainbows: Vec<Rainbow>,
    /// Scene-wide settings.
    pub settings: Settings,
}

// (The atmosphere is shown only when there is one: scenes without read as before.)
impl std::fmt::Debug for Scene {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut d = f.debug_struct("Scene");
        d.field("camera", &self.camera)
            .field("lights", &self.lights)
            .field("objects", &self.objects)
            .field("background", &self.background)
            .field("background_alpha", &self.background_alpha)
            .field("sky_sphere", &self.sky_sphere)
            .field("fogs", &self.fogs);
        if !self.atmosphere.is_empty() {
            d.field("atmosphere", &self.atmosphere);
        }
        if !self.rainbows.is_empty() {
            d.field("rainbows", &self.rainbows);
        }
        d.field("settings", &self.settings).finish()
    }
}

/// `rainbow { … }`, as POV-Ray holds it once read: a ray of unit direction `d` whose angle to
/// `up` in the plane of `up` and `right` is within `arc_angle`, and whose angle θ to
/// `antisolar` is under 90°, takes the colour of `colours` at `(θ − angle) / width` when that
/// lies in [0, 1) (POV-Ray's ComputeRainbow).
#[derive(Clone, Debug, PartialEq)]
pub struct Rainbow {
    /// The ring's inner edge, in radians (POV-Ray's `angle − width/2`, converted).
    pub angle: f64,
    /// The ring's width, in radians.
    pub width: f64,
    /// `distance`: a surface at depth `t` keeps `e^(−t/distance)` of its colour.
    pub distance: f64,
    /// `jitter`: the map index moves by up to this much, at random.
    pub jitter: f64,
    /// Half the `arc_angle`, in radians (or POV-Ray's unconverted default, 180, which no
    /// angle reaches).
    pub arc_angle: f64,
    /// Half the `falloff_angle` in radians, past which the ring fades out towards
    /// `arc_angle` (by default equal to it: no fading).
    pub falloff_angle: f64,
    /// `direction`: the centre of the ring, unit length.
    pub antisolar: DVec3,
    /// `up`, made perpendicular to `antisolar`, unit length.
    pub up: DVec3,
    /// `up × antisolar`, unit length.
    pub right: DVec3,
    /// `color_map`: the ring's colours from inside out; filter and transmit let the scene
    /// through.
    pub colours: ColourMap,
}

/// `fog { … }`: along a ray segment of length `w` in hollow space, the colour `c` becomes
/// `(1 − a)·colour + A·c` summed over fogs, with `a = max(e^(−w·density/distance), transmit)`
/// and `A = a·(1 − filter + filter·colour)` (POV-Ray's ComputeFog).
#[derive(Clone, Debug, PartialEq)]
pub struct Fog {
    /// `distance`: the length over which the fog thickens by a factor e.
    pub distance: f64,
    /// `color`, with filter and transmit.
    pub colour: Colour,
    /// Constant or ground fog.
    pub kind: FogKind,
    /// `turbulence …` and `turb_depth`: the fog thins by POV-Ray's turbulence at the middle
    /// of each ray's path through it.
    pub turbulence: Option<Box<FogTurbulence>>,
}

/// A fog's turbulence.
#[derive(Clone, Debug, PartialEq)]
pub struct FogTurbulence {
    /// Amount (scales the point), octaves, omega, lambda.
    pub turbulence: crate::noise::Turbulence,
    /// `turb_depth` (default 0.5): how far the turbulence thins the fog.
    pub depth: f64,
}

/// POV-Ray's fog types.
#[derive(Clone, Debug, PartialEq)]
pub enum FogKind {
    /// `fog_type 1` (the default): the same density everywhere.
    Constant,
    /// `fog_type 2`: density 1 below `offset` along `up`, falling off as 1/(h² + 1) above it,
    /// with h the height above `offset` in units of `alt`.
    Ground {
        /// `fog_offset`.
        offset: f64,
        /// `fog_alt`.
        alt: f64,
        /// `up`, unit length.
        up: DVec3,
    },
}

impl Scene {
    /// Whether `other` is this scene but for its camera (every other part equal): the
    /// render-ready scene built from one serves the other with its camera swapped.
    pub fn same_but_camera(&self, other: &Scene) -> bool {
        // (Every field named, so that a new one is not forgotten here.)
        let Scene {
            camera: _,
            lights,
            objects,
            background,
            background_alpha,
            sky_sphere,
            fogs,
            rainbows,
            atmosphere,
            settings,
        } = self;
        *lights == other.lights
            && *background == other.background
            && *background_alpha == other.background_alpha
            && *sky_sphere == other.sky_sphere
            && *fogs == other.fogs
            && *rainbows == other.rainbows
            && *atmosphere == other.atmosphere
            && *settings == other.settings
            && *objects == other.objects
    }
}

/// `global_settings` and version-dependent behaviour.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// How working values become linear output values.
    pub gamma: Gamma,
    /// `max_trace_level` (default 5): rays at a deeper level return black.
    pub max_trace_level: u32,
    /// `adc_bailout` (default 1/255): rays of lower weight return black.
    pub adc_bailout: f64,
    /// `ambient_light` (default 1): multiplies every finish's ambient.
    pub ambient_light: Rgb,
    /// POV-Ray's pre-3.7 surface attenuation `1 − (filter·max(r,g,b) + transmit)` (scenes
    /// without `#version 3.7`) instead of `1 − filter − transmit`.
    pub legacy_transparency: bool,
    /// The noise generator of patterns that name none (`noise_generator`; default 2, or 1
    /// for scenes of `#version` before 3.5).
    pub noise_generator: u8,
    /// `number_of_waves` (default 10): the wave sources of `ripples` and `waves`.
    pub number_of_waves: u8,
    /// `irid_wavelength` (default <0.70, 0.52, 0.48>): the wavelengths `irid` uses.
    pub irid_wavelength: Rgb,
    /// `radiosity { … }`: POV-Ray 3.7's diffuse interreflection, if the scene turns it on.
    pub radiosity: Option<Radiosity>,
}

/// `global_settings { radiosity { … } }`: the settings of POV-Ray 3.7's radiosity (its
/// irradiance cache), POV-Ray's defaults filled in and its consistency rules applied.
#[derive(Clone, Debug, PartialEq)]
pub struct Radiosity {
    /// `adc_bailout` (default 0.01): the bailout of the rays a sample shoots.
    pub adc_bailout: f64,
    /// `always_sample` (default off): whether the final render takes new samples where
    /// it found some but fewer than `nearest_count`.
    pub always_sample: bool,
    /// `brightness` (default 1): multiplies the light gathered.
    pub brightness: f64,
    /// `count` (default 35): rays a sample shoots (halved at each deeper bounce, at least 5).
    pub count: u32,
    /// `count`'s second value (default 1600, at least `count`): the directions they are drawn
    /// from, in turn.
    pub directions: u32,
    /// `error_bound` (default 1.8): how far a sample is reused.
    pub error_bound: f64,
    /// `gray_threshold` (default 0): how much of the light gathered is made grey.
    pub gray_threshold: f64,
    /// `low_error_factor` (default 0.5): `error_bound`'s factor during the pretrace.
    pub low_error_factor: f64,
    /// `max_sample` (default none, any value not above 0): the brightest a ray's light may be.
    pub max_sample: f64,
    /// `maximum_reuse` (default 0.2): the largest a sample's reach may be, over its distance
    /// from the camera.
    pub maximum_reuse: f64,
    /// `minimum_reuse` (default 0.015): the smallest.
    pub minimum_reuse: f64,
    /// `nearest_count` (default 5, 1 to 20): samples a point needs to reuse, not sample.
    pub nearest_count: u32,
    /// `nearest_count`'s second value (default 0: off): the samples at which the adaptive
    /// pretrace stops refining part of the image.
    pub pretrace_count: u32,
    /// `recursion_limit` (default 2, 1 to 20): bounces of diffuse light.
    pub recursion_limit: u32,
    /// `media` (default off): whether the rays of a sample see media, fog and rainbows.
    pub media: bool,
    /// `normal` (default off): whether samples see the surface's perturbed normal.
    pub normal: bool,
    /// `pretrace_start` (default 0.08): the first pretrace pass's grid, over the image size.
    pub pretrace_start: f64,
    /// `pretrace_end` (default 0.04): the last pass's.
    pub pretrace_end: f64,
    /// Whether `ambient` still lights surfaces (scenes before `#version 3.7`); from 3.7
    /// only `emission` does once radiosity is on.
    pub keeps_ambient: bool,
    /// `#default { radiosity { importance F } }` (default 1): the importance of objects
    /// that give none, and of the sky.
    pub default_importance: f64,
}

impl Default for Radiosity {
    fn default() -> Radiosity {
        Radiosity {
            adc_bailout: 0.01,
            always_sample: false,
            brightness: 1.0,
            count: 35,
            directions: 1600,
            error_bound: 1.8,
            gray_threshold: 0.0,
            low_error_factor: 0.5,
            max_sample: -1.0,
            maximum_reuse: 0.2,
            minimum_reuse: 0.015,
            nearest_count: 5,
            pretrace_count: 0,
            recursion_limit: 2,
            media: false,
            normal: false,
            pretrace_start: 0.08,
            pretrace_end: 0.04,
            keeps_ambient: false,
            default_importance: 1.0,
        }
    }
}

/// The working-gamma mode (POV-Ray `assumed_gamma` and `#version`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Gamma {
    /// Values are in working gamma `g`: the linear output is `value^g`.
    Working(f64),
    /// "Gamma off" (no `#version 3.7` and no `assumed_gamma`): values are display-encoded
    /// sRGB; the linear output is their sRGB decode.
    Off,
}

/// A perspective or orthographic camera, resolved to its four vectors (POV-Ray §4.2 applied).
#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    /// Projection.
    pub projection: Projection,
    /// Eye point.
    pub location: DVec3,
    /// Centre of the image plane relative to `location`.
    pub direction: DVec3,
    /// Image-plane vector spanning the full width.
    pub right: DVec3,
    /// Image-plane vector spanning the full height.
    pub up: DVec3,
    /// Focal blur (`aperture` with `blur_samples`), if any.
    pub blur: Option<FocalBlur>,
    /// `normal { … }`: a pattern that bends the camera's rays, if any.
    pub normal: Option<Box<Normal>>,
    /// `mesh_camera { … }` (with [`Projection::Mesh`]): the meshes whose faces the rays leave.
    pub mesh: Option<Arc<MeshCamera>>,
}

/// A `mesh_camera`: each pixel's rays leave faces of meshes, as POV-Ray 3.7 picks them.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshCamera {
    /// Rays a pixel averages (the ones that exist).
    pub rays_per_pixel: u32,
    /// POV-Ray's face distribution: 0 (ray k of a pixel from mesh k), 1 (the meshes' faces
    /// numbered on, one ray a pixel), 2 (meshes side by side across the image), 3 (the face
    /// whose `uv_vectors` hold the pixel).
    pub distribution: u8,
    /// Longest distance a camera ray looks (0: no limit).
    pub max_distance: f64,
    /// The meshes, each with its transformation.
    pub meshes: Vec<(Arc<Mesh>, Option<Transform>)>,
    /// Method 3 only: the ray direction interpolates the face's vertex normals.
    pub smooth: bool,
    /// How far along its face's normal a ray starts (the camera location's z).
    pub offset: f64,
    /// Rays go against the face normals (the camera direction's z is negative).
    pub reversed: bool,
}

/// A camera's focal blur, as POV-Ray samples it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FocalBlur {
    /// Lens size (`aperture`).
    pub aperture: f64,
    /// Fewest samples a pixel takes before it may stop (`blur_samples MIN, MAX`; 0 for one
    /// number).
    pub min_samples: u32,
    /// Most samples a pixel takes.
    pub max_samples: u32,
    /// Distance from the eye to the sharp plane.
    pub focal_distance: f64,
    /// `confidence` (default 0.9).
    pub confidence: f64,
    /// `variance` (default 1/10000).
    pub variance: f64,
}

/// Camera projection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// `perspective` (default).
    Perspective,
    /// `orthographic`.
    Orthographic,
    /// `fisheye`: `angle` (degrees, default 90) across the image's circle (pixels outside
    /// it see nothing).
    Fisheye {
        /// Degrees.
        angle: f64,
    },
    /// `ultra_wide_angle`: `angle` (default 90) across the width, bent around both axes.
    UltraWideAngle {
        /// Degrees.
        angle: f64,
    },
    /// `omnimax`: POV-Ray's dome projection.
    Omnimax,
    /// `panoramic`: 180° across the width, the height along a tangent.
    Panoramic,
    /// `cylinder 1`–`4`, `angle` (default 90) around the axis: 1 and 3 curve across the width
    /// (3 with parallel rays vertically), 2 and 4 across the height (4 with parallel rays
    /// horizontally).
    Cylinder {
        /// 1 to 4.
        kind: u8,
        /// Degrees.
        angle: f64,
    },
    /// `mesh_camera`: rays from mesh faces ([`Camera::mesh`]).
    Mesh,
    /// `spherical`: `angle H, V` (default 360, 180): longitude across the width and
    /// latitude across the height.
    Spherical {
        /// Horizontal angle, degrees.
        h: f64,
        /// Vertical angle, degrees.
        v: f64,
    },
}

impl Projection {
    /// Whether rays start on an image plane (`direction`, `right` and `up` as given), which
    /// `angle` sets; the others keep their angle.
    pub fn is_planar(self) -> bool {
        matches!(self, Projection::Perspective | Projection::Orthographic)
    }
}

/// A point light. `.rt`: `light_source { <x, y, z>, color rgb <r, g, b> }`.
#[derive(Clone, PartialEq)]
pub struct Light {
    /// World position (after the light's transformations).
    pub position: DVec3,
    /// Colour (intensity; not clamped).
    pub colour: Rgb,
    /// Point, spot or parallel.
    pub kind: LightKind,
    /// `shadowless`: no shadow test and no highlights.
    pub shadowless: bool,
    /// `fade_distance`/`fade_power`, when both are given and positive.
    pub fade: Option<LightFade>,
    /// `area_light`: soft shadows from a grid of points.
    pub area: Option<AreaLight>,
    /// The `light_group` the light belongs to: it lights only that group's objects.
    pub group: Option<u32>,
    /// `media_interaction` (default on): the light scatters in media.
    pub media_interaction: bool,
    /// `media_attenuation` (default off): the atmosphere dims the light's shadow rays.
    pub media_attenuation: bool,
    /// `projected_through { … }`: the light reaches a point only along rays that cross this
    /// object (its parts, placed in the world); nothing between it and the light casts a
    /// shadow.
    pub projected_through: Option<Arc<Vec<Object>>>,
}

// (The media flags are shown only when not the defaults: scenes without them read as
// before.)
impl std::fmt::Debug for Light {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut d = f.debug_struct("Light");
        d.field("position", &self.position)
            .field("colour", &self.colour)
            .field("kind", &self.kind)
            .field("shadowless", &self.shadowless)
            .field("fade", &self.fade)
            .field("area", &self.area)
            .field("group", &self.group)
            .field("projected_through", &self.projected_through);
        if !self.media_interaction {
            d.field("media_interaction", &false);
        }
        if self.media_attenuation {
            d.field("media_attenuation", &true);
        }
        d.finish()
    }
}

/// How a light emits.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind {
    /// Equally in every direction.
    Point,
    /// `spotlight`: a cone toward `point_at`.
    Spot {
        /// Where the cone's axis points.
        point_at: DVec3,
        /// Full-intensity half angle (degrees, default 30).
        radius_deg: f64,
        /// Half angle where the light reaches zero (degrees, default 45).
        falloff_deg: f64,
        /// Exponent of the cosine fall-off inside the cone (default 0).
        tightness: f64,
    },
    /// `parallel`: every point lit from the direction `location − point_at`.
    Parallel {
        /// Target point.
        point_at: DVec3,
    },
    /// `cylinder`: parallel rays along `point_at − location` within a cylinder around that
    /// axis, on the side of the light's plane that `point_at` is on.
    Cylinder {
        /// Where the axis points.
        point_at: DVec3,
        /// Full intensity within this distance of the axis (default 0.75).
        radius: f64,
        /// Zero from this distance of the axis (default 1).
        falloff: f64,
        /// Exponent of the fall-off across the cylinder (default 0).
        tightness: f64,
    },
}

/// Light attenuation `2 / (1 + (d / distance)^power)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightFade {
    /// `fade_distance`.
    pub distance: f64,
    /// `fade_power`.
    pub power: f64,
}

/// `area_light <axis1>, <axis2>, size1, size2 [adaptive a] [jitter] [circular] [orient]`.
#[derive(Clone, Debug, PartialEq)]
pub struct AreaLight {
    /// First grid axis (full length).
    pub axis1: DVec3,
    /// Second grid axis.
    pub axis2: DVec3,
    /// Grid points along `axis1`.
    pub size1: u32,
    /// Grid points along `axis2`.
    pub size2: u32,
    /// `adaptive` level (default 100: the whole grid).
    pub adaptive: u32,
    /// `jitter`: grid points moved at random within their cell (deterministically in trace).
    pub jitter: bool,
    /// `circular`: the grid mapped onto a disc.
    pub circular: bool,
    /// `orient`: the grid turned to face the shaded point.
    pub orient: bool,
    /// `area_illumination`: each grid point also lights the surface on its own.
    pub area_illumination: bool,
}

/// A renderable object: a shape, where it is, and what it is made of.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Geometry in object space.
    pub shape: Shape,
    /// World from object; `None` is the identity.
    pub transform: Option<Box<Transform>>,
    /// The resolved surface.
    pub texture: Texture,
    /// What few objects have (`interior_texture`, `bounded_by`), boxed to keep the others
    /// small.
    pub extras: Option<Box<ObjectExtras>>,
    /// What is inside (index of refraction, fade).
    pub interior: Arc<Interior>,

    /// `no_shadow`: the object casts no shadow.
    pub no_shadow: bool,
    /// `inverse`: inside and outside swapped.
    pub inverse: bool,
    /// `hollow`: fog reaches rays inside it (it does not inside solid objects, the default).
    pub hollow: bool,
    /// Position among the members of its union (0 for the first, and for an object not in a
    /// union): between two hits at the same distance, POV-Ray takes the later member.
    pub member: u32,
    /// Objects with the same medium share one interior (POV-Ray's members of a union that
    /// have no interior of their own): a ray inside one that meets another's surface leaves
    /// the medium. Distinct for every other object.
    pub medium: u32,
}

/// The parts of an object that few objects have.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ObjectExtras {
    /// `interior_texture`: the surface seen from inside (where the normal faces away from
    /// the ray), if it differs.
    pub interior_texture: Option<Texture>,
    /// `bounded_by`: the object's box becomes its bound's (rays that miss it skip the object),
    /// and on unions, polynomials and unbounded quadrics rays that miss a bounding shape (and
    /// start outside it) skip the object too; POV-Ray removes the shapes of other bounds and
    /// keeps their box.
    pub bounds: Option<Arc<Bounds>>,
    /// `no_image`, `no_reflection`, `double_illuminate`.
    pub sight: Sight,
    /// For an object in a `light_group`: which lights light it.
    pub light_group: Option<LightGroup>,
    /// `radiosity { importance F }` (0 < F ≤ 1), if given: of a radiosity sample's rays
    /// that meet the object, only the first F go on (the others count for their distance).
    pub importance: Option<f64>,
}

/// Which rays see an object, and from which side lights reach it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sight {
    /// `no_image`: unseen by camera rays and by rays that reach it through transparent
    /// objects without a reflection on the way (it still casts shadows and is reflected).
    pub no_image: bool,
    /// `no_reflection`: unseen by rays that were reflected on their way.
    pub no_reflection: bool,
    /// `double_illuminate`: lit from both sides (a light behind the surface lights it as one
    /// in front, with `diffuse`).
    pub double_illuminate: bool,
    /// `no_radiosity`: unseen by the rays radiosity samples shoot (and the rays they spawn).
    pub no_radiosity: bool,
}

/// The lights of an object in a `light_group`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LightGroup {
    /// The groups whose lights light it (its own, and those of groups around it).
    pub groups: Vec<u32>,
    /// `global_lights on`: the lights outside every group light it too.
    pub global_lights: bool,
}

impl Object {
    /// `interior_texture`, if any.
    pub fn interior_texture(&self) -> Option<&Texture> {
        self.extras
            .as_ref()
            .and_then(|e| e.interior_texture.as_ref())
    }

    /// `bounded_by`, if any.
    pub fn bounds(&self) -> Option<&Bounds> {
        self.extras.as_ref().and_then(|e| e.bounds.as_deref())
    }

    /// `no_image`, `no_reflection` and `double_illuminate`.
    pub fn sight(&self) -> Sight {
        self.extras
            .as_ref()
            .map_or_else(Sight::default, |e| e.sight)
    }
}

/// An object's `bounded_by`.
#[derive(Clone, Debug, PartialEq)]
pub struct Bounds {
    /// The bounding shapes.
    pub shapes: Vec<Bound>,
    /// Whether rays are tested against the shapes (else only their box bounds the object).
    pub test_rays: bool,
}

/// A bounding shape of `bounded_by`, placed in the world.
#[derive(Clone, Debug, PartialEq)]
pub struct Bound {
    /// The shape.
    pub shape: Shape,
    /// World from its object space; `None` is the identity.
    pub transform: Option<Box<Transform>>,
}

/// Analytic shapes, in object space.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// `sphere { centre, radius }`.
    Sphere {
        /// Centre.
        centre: DVec3,
        /// Radius.
        radius: f64,
    },
    /// `plane { normal, distance }`: points with `normal·p = distance` (normal unit length).
    Plane {
        /// Unit normal (pointing outside).
        normal: DVec3,
        /// Offset along the normal.
        distance: f64,
    },
    /// `box { corner1, corner2 }` with the corners sorted per axis.
    Box {
        /// Least corner.
        min: DVec3,
        /// Greatest corner.
        max: DVec3,
    },
    /// `cylinder { base, cap, radius [open] }` and `cone { base, r0, cap, r1 [open] }`: a
    /// truncated cone whose radius goes linearly from `base_radius` to `cap_radius` (equal radii
    /// make a cylinder). A zero-radius end has no cap.
    Cone {
        /// Centre of the first end.
        base: DVec3,
        /// Radius there.
        base_radius: f64,
        /// Centre of the second end.
        cap: DVec3,
        /// Radius there.
        cap_radius: f64,
        /// `open`: no end caps.
        open: bool,
    },
    /// `disc { centre, normal, radius [, hole_radius] }`: flat, two-sided.
    Disc {
        /// Centre.
        centre: DVec3,
        /// Unit normal.
        normal: DVec3,
        /// Outer radius.
        radius: f64,
        /// Radius of the hole (0 for none).
        hole_radius: f64,
    },
    /// `torus { major, minor }`: around the y axis, in the x-z plane.
    Torus {
        /// Radius of the centre circle.
        major: f64,
        /// Radius of the tube.
        minor: f64,
    },
    /// `triangle` / `smooth_triangle`, and every mesh: shared between instances.
    Mesh(Arc<Mesh>),
    /// `quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }` (boxed: rare, and as big as three
    /// vectors).
    Quadric(Box<Quadric>),
    /// `cubic`, `quartic`, `poly N` (N ≤ 6): a polynomial in x, y, z equal to 0.
    Polynomial(Box<Polynomial>),
    /// `polygon { N, P1, … }`: the points, sub-polygons closed by repeating their first
    /// point (the last one closed by trace if the scene left it open, as POV-Ray does).
    Polygon(Box<Vec<DVec3>>),
    /// `text { ttf … }`: laid-out glyph outlines extruded along z.
    Text(Box<Text>),
    /// `prism { … }`: spline segments swept along y.
    Prism(Box<Prism>),
    /// `lathe { … }`: a spline profile turned about y.
    Lathe(Box<Lathe>),
    /// `sor { … }`: a surface of revolution, r² a cubic in y piece by piece.
    Sor(Box<Sor>),
    /// `julia_fractal { … }`.
    JuliaFractal(Box<JuliaFractal>),
    /// `ovus { bottom_radius, top_radius }` (top below twice bottom).
    Ovus {
        /// Radius of the sphere at the origin.
        bottom: f64,
        /// Radius of the sphere one bottom radius above it.
        top: f64,
    },
    /// `isosurface { … }`: where a function reaches its threshold.
    Isosurface(Box<Isosurface>),
    /// `parametric { … }`: a surface of two parameters.
    Parametric(Box<Parametric>),
    /// `sphere_sweep { … }`: a sphere swept along a spline.
    SphereSweep(Box<SphereSweep>),
    /// `bicubic_patch { … }`: a Bézier patch.
    BicubicPatch(Box<BicubicPatch>),
    /// `height_field { … }`: a grid of heights.
    HeightField(Box<HeightField>),
    /// `blob { … }`: where the components' fields reach the threshold.
    Blob(Box<Blob>),
    /// `superellipsoid { <e, n> }`: e shapes the x-y sections, n the profile along z.
    Superellipsoid {
        /// East-west exponent.
        e: f64,
        /// North-south exponent.
        n: f64,
    },
}

/// `Ax² + By² + Cz² + Dxy + Exz + Fyz + Gx + Hy + Iz + J = 0`.
#[derive(Clone, Debug, PartialEq)]
pub struct Quadric {
    /// `<A, B, C>`.
    pub square: DVec3,
    /// `<D, E, F>`.
    pub mixed: DVec3,
    /// `<G, H, I>`.
    pub linear: DVec3,
    /// `J`.
    pub constant: f64,
}

/// A polynomial surface's degree and non-zero terms.
#[derive(Clone, Debug, PartialEq)]
pub struct Polynomial {
    /// 2 to 6.
    pub degree: u8,
    /// Coefficient and the powers of x, y and z of each non-zero term.
    pub terms: Vec<(f64, [u8; 3])>,
}

impl Polynomial {
    /// The polynomial of `degree` from POV-Ray's list of coefficients: terms ordered by the
    /// power of x, then of y, then of z, each descending (`x⁴, x³y, x³z, x³, x²y², …, z, 1`
    /// for a quartic). `None` if the list's length is not the degree's.
    pub fn from_povray(degree: u8, coefficients: &[f64]) -> Option<Polynomial> {
        let mut powers = Vec::new();
        for i in (0..=degree).rev() {
            for j in (0..=degree - i).rev() {
                for k in (0..=degree - i - j).rev() {
                    powers.push([i, j, k]);
                }
            }
        }
        (powers.len() == coefficients.len()).then(|| Polynomial {
            degree,
            terms: powers
                .into_iter()
                .zip(coefficients)
                .filter(|(_, c)| **c != 0.0)
                .map(|(p, c)| (*c, p))
                .collect(),
        })
    }
}

/// A triangle mesh (`mesh`, `mesh2`, or a single `triangle`/`smooth_triangle`). Vertices and
/// normals are stored as 32-bit floats, as in POV-Ray.
#[derive(Clone, Default)]
pub struct Mesh {
    /// Vertex positions.
    pub vertices: Vec<Vec3>,
    /// Vertex normals (unit length, except for a transformed stand-alone `smooth_triangle`,
    /// whose lengths carry POV-Ray's renormalisation); empty for a flat mesh.
    pub normals: Vec<Vec3>,
    /// Triangles as indices into `vertices`.
    pub triangles: Vec<[u32; 3]>,
    /// Per triangle, indices into `normals`; empty for a flat mesh. A triangle whose three
    /// normal indices are `u32::MAX` is flat.
    pub normal_indices: Vec<[u32; 3]>,
    /// `inside_vector`: the direction used for inside tests, if given.
    pub inside_vector: Option<DVec3>,
    /// `uv_vectors`: the surface coordinates the triangles' corners take (`uv_mapping`).
    pub uvs: Vec<glam::DVec2>,
    /// Per triangle, indices into `uvs`; empty when the mesh has none (every point is then at
    /// (0, 0), as in POV-Ray).
    pub uv_indices: Vec<[u32; 3]>,
    /// A stand-alone `triangle` or `smooth_triangle`: its surface coordinates are POV-Ray's
    /// default (the world point's x and y), not a mesh's (0, 0).
    pub world_uv: bool,
    /// The triangles' own textures (`texture { T }` on a mesh's triangle, a mesh2's
    /// `texture_list`), in the mesh's space.
    pub textures: Vec<Texture>,
    /// Per triangle, its corners' indices into `textures` ([`OWN_TEXTURE`]: the object's
    /// texture); all three equal for one texture, else blended across the triangle. Empty
    /// when no triangle has a texture of its own.
    pub face_textures: Vec<[u32; 3]>,
    /// The numbers (in the order written, increasing) of a `mesh2`'s faces of no area: trace
    /// does not keep them, POV-Ray does, and a mesh camera numbers faces as POV-Ray does.
    pub dropped_faces: Vec<u32>,
}

/// Meshes are equal when their data are; a mesh is equal to itself at once (a mesh shared
/// by two reads of one text, as `trace watch` shares a big mesh2 whose lists did not
/// change, is not compared triangle by triangle).
impl PartialEq for Mesh {
    fn eq(&self, other: &Mesh) -> bool {
        // (Every field named, so that a new one is not forgotten here.)
        let Mesh {
            vertices,
            normals,
            triangles,
            normal_indices,
            inside_vector,
            uvs,
            uv_indices,
            world_uv,
            textures,
            face_textures,
            dropped_faces,
        } = self;
        std::ptr::eq(self, other)
            || (*vertices == other.vertices
                && *normals == other.normals
                && *triangles == other.triangles
                && *normal_indices == other.normal_indices
                && *inside_vector == other.inside_vector
                && *uvs == other.uvs
                && *uv_indices == other.uv_indices
                && *world_uv == other.world_uv
                && *textures == other.textures
                && *face_textures == other.face_textures
                && *dropped_faces == other.dropped_faces)
    }
}

/// In [`Mesh::face_textures`]: the corner takes the object's texture.
pub const OWN_TEXTURE: u32 = u32::MAX;

/// The marker for a flat triangle in [`Mesh::normal_indices`].
pub const FLAT: [u32; 3] = [u32::MAX; 3];

impl std::fmt::Debug for Mesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        // Large meshes would swamp a snapshot: show the sizes and a checksum of the data.
        let mut sum = 0.0f64;
        for (i, v) in self.vertices.iter().enumerate() {
            sum += (i as f64 + 1.0) * (v.x as f64 + 2.0 * v.y as f64 + 3.0 * v.z as f64);
        }
        let index_sum: u64 = self.triangles.iter().flatten().map(|&i| i as u64).sum();
        let smooth = self.normal_indices.iter().filter(|n| **n != FLAT).count();
        let mut d = f.debug_struct("Mesh");
        d.field("vertices", &self.vertices.len())
            .field("triangles", &self.triangles.len())
            .field("smooth_triangles", &smooth)
            .field("vertex_checksum", &format_args!("{sum:.4}"))
            .field("index_checksum", &index_sum)
            .field("inside_vector", &self.inside_vector);
        if !self.uvs.is_empty() {
            let uv_sum: f64 = self
                .uvs
                .iter()
                .enumerate()
                .map(|(i, v)| (i as f64 + 1.0) * (v.x + 2.0 * v.y))
                .sum();
            d.field("uvs", &self.uvs.len())
                .field("uv_checksum", &format_args!("{uv_sum:.4}"));
        }
        if !self.face_textures.is_empty() {
            let face_sum: u64 = (self.face_textures.iter().enumerate())
                .map(|(i, f)| {
                    (i as u64 + 1) * f.iter().map(|&t| u64::from(t.wrapping_add(1))).sum::<u64>()
                })
                .sum();
            d.field("textures", &self.textures)
                .field("face_texture_checksum", &face_sum);
        }
        d.finish()
    }
}

/// An affine transformation, composed from a list of `translate`/`rotate`/`scale`/`matrix`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// Column-vector matrix (glam convention) taking object space to world space.
    pub matrix: DMat4,
}

impl Transform {
    /// The identity.
    pub const IDENTITY: Transform = Transform {
        matrix: DMat4::IDENTITY,
    };

    /// `self` followed by `next`.
    pub fn then(self, next: Transform) -> Transform {
        Transform {
            matrix: next.matrix * self.matrix,
        }
    }

    /// Appends this transformation to a placement (`None` is the identity).
    pub fn append_to(self, placement: &mut Option<Box<Transform>>) {
        let before = placement.take().map_or(Transform::IDENTITY, |b| *b);
        *placement = Some(Box::new(before.then(self)));
    }

    /// The inverse transformation.
    pub fn inverse(self) -> Transform {
        Transform {
            matrix: self.matrix.inverse(),
        }
    }
}

/// A resolved texture: pigment, normal and finish, with the layers beneath it.
///
/// `.rt`: `texture { pigment { ... } finish { ... } }`, or `pigment`/`finish` on an object.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Colour at each point.
    pub pigment: Pigment,
    /// The perturbation of the surface normal, if any.
    pub normal: Option<Box<Normal>>,
    /// Layered textures (`texture {…} texture {…}`): the layers beneath this one, bottom
    /// first, each seen through the ones above by their filter and transmit (a layer's own
    /// `under` is empty).
    pub under: Vec<Texture>,
    /// A pattern of textures (`texture_map`, `checker texture {…} texture {…}`): when given,
    /// the surface is the map's textures and this texture's own items are not used.
    pub map: Option<Box<TextureMap>>,
    /// How light interacts with the surface (shared: most objects keep the default).
    pub finish: Arc<Finish>,
}

/// A pigment: colours placed in space.
///
/// `.rt`: `pigment { color rgb <..> }`, `pigment { checker C0, C1 scale 2 }`,
/// `pigment { gradient y color_map { [0 C0] [1 C1] } }`, `pigment { image_map { png "f.png" } }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Pigment {
    /// The colours.
    pub kind: PigmentKind,
    /// World from pattern space: the pigment's own transformations, then those of its texture
    /// and of its object made after it was attached (POV-Ray moves a texture with its object
    /// only if it was attached first). `None` is the identity.
    pub transform: Option<Box<Transform>>,
}

impl Pigment {
    /// Whether no point of the pigment lets light through (an image map may, by its alpha).
    pub fn is_opaque(&self) -> bool {
        let opaque = |c: &Colour| c.filter == 0.0 && c.transmit == 0.0;
        match &self.kind {
            PigmentKind::Solid(c) => opaque(c),
            PigmentKind::Pattern(p) => match &p.map {
                PigmentMap::Colours(m) => m.entries.iter().all(|(_, c)| opaque(c)),
                PigmentMap::Pigments(ps) => ps.iter().all(|(_, p)| p.is_opaque()),
            },
            PigmentKind::ImageMap(_) => false,
        }
    }

    /// A solid colour.
    pub fn solid(c: Colour) -> Pigment {
        Pigment {
            kind: PigmentKind::Solid(c),
            transform: None,
        }
    }

    /// The pigment placed for evaluation (the render's, and a pigment function's), its
    /// patterns using the scene's noise generator and waves unless they name their own.
    pub fn placed(&self, scene: crate::pattern::SceneDefaults) -> crate::pattern::PlacedPigment {
        use crate::pattern::{PlacedPigment, pigment::Map};
        let from_world = self.transform.as_ref().map(|t| t.matrix.inverse());
        match &self.kind {
            PigmentKind::Solid(c) => PlacedPigment::solid(*c, from_world),
            PigmentKind::Pattern(pp) => {
                let map = match &pp.map {
                    PigmentMap::Colours(m) => Map::Colours(m.entries.clone().into()),
                    PigmentMap::Pigments(ps) => {
                        Map::Pigments(ps.iter().map(|(v, p)| (*v, p.placed(scene))).collect())
                    }
                };
                PlacedPigment::mapped(pp.pattern.with_scene(scene), map, from_world)
            }
            PigmentKind::ImageMap(image) => PlacedPigment::image(Arc::clone(image), from_world),
        }
    }
}

/// A normal perturbation: a pattern whose slope tilts the surface normal.
///
/// `.rt`: `normal { bumps 0.5 scale 0.2 }`, `normal { gradient x, 1 }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Normal {
    /// The pattern (its wave and modifiers included).
    pub pattern: Pattern,
    /// The bump amount (`bumps 0.5`, `bump_size 0.5`).
    pub amount: f64,
    /// World from pattern space, as for a pigment. `None` is the identity.
    pub transform: Option<Box<Transform>>,
    /// `accuracy`: the distance between the samples of a pattern's slope (default 0.02,
    /// single precision as POV-Ray keeps it).
    pub accuracy: f64,
    /// `no_bump_scale`: the bumps keep their slope when the pattern is scaled.
    pub no_bump_scale: bool,
    /// `slope_map { [v <height, slope>] … }`: the pattern's value mapped to a height before
    /// its slope is taken (a cubic through the entries' heights and slopes).
    pub slope_map: Option<Vec<(f64, [f64; 2])>>,
    /// `normal_map { [v NORMAL] … }`: normals by the pattern's value (blended), or averaged
    /// for `average`; each placed in the pattern's space.
    pub map: Option<Vec<(f64, Normal)>>,
}

impl Normal {
    /// A normal of `pattern` bumped by `amount`, with POV-Ray's defaults for the rest.
    pub fn new(pattern: Pattern, amount: f64) -> Normal {
        Normal {
            pattern,
            amount,
            transform: None,
            accuracy: f64::from(0.02f32),
            no_bump_scale: false,
            slope_map: None,
            map: None,
        }
    }
}

/// `texture { PATTERN texture_map { [v TEXTURE] … } }` or a discrete pattern's list of
/// textures: the textures are lit each on its own and blended by the pattern's value.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureMap {
    /// Where the textures change.
    pub pattern: Pattern,
    /// World from pattern space (`None`: the identity).
    pub transform: Option<Box<Transform>>,
    /// (value, texture), each texture placed in the pattern's space.
    pub entries: Vec<(f64, Texture)>,
}

/// `sky_sphere { pigment {…} … emission C }`: pigments of the direction, layered (the last
/// on top, seen through by its filter and transmit), each placed by its own transformations
/// followed by the sky_sphere's.
#[derive(Clone, Debug, PartialEq)]
pub struct SkySphere {
    /// The pigments, bottom layer first.
    pub pigments: Vec<Pigment>,
    /// `emission` (default 1): multiplies the pigments' colours.
    pub emission: Rgb,
}

/// What a pigment's colours are.
#[derive(Clone, Debug, PartialEq)]
pub enum PigmentKind {
    /// One colour everywhere.
    Solid(Colour),
    /// A pattern's value at each point, looked up in a colour map.
    Pattern(Box<PatternPigment>),
    /// `image_map { png "file" … }`: planar projection onto the unit square of the x-y plane.
    ImageMap(Arc<ImageMap>),
}

/// `pigment { PATTERN color_map {…} }`, or a discrete pattern with its list of colours
/// (`checker C0, C1`: the map holds C0 at 0 and C1 at 1).
#[derive(Clone, Debug, PartialEq)]
pub struct PatternPigment {
    /// Where the colours change.
    pub pattern: Pattern,
    /// What the pattern's values give.
    pub map: PigmentMap,
}

/// What a pattern pigment looks its value up in.
#[derive(Clone, Debug, PartialEq)]
pub enum PigmentMap {
    /// `color_map`, or a discrete pattern's list of colours.
    Colours(ColourMap),
    /// `pigment_map { [v PIGMENT] … }`, or a discrete pattern's list of pigments
    /// (`checker pigment {…} pigment {…}`). Each pigment is placed in the pattern's space
    /// (after its warps): its transformation is relative to that space.
    Pigments(Vec<(f64, Pigment)>),
}

/// `color_map { [v C] … }`: colours at increasing values, interpolated between.
#[derive(Clone, Debug, PartialEq)]
pub struct ColourMap {
    /// (value, colour), by increasing value.
    pub entries: Vec<(f64, Colour)>,
}

impl Default for ColourMap {
    /// POV-Ray's default map: black at 0 to white at 1.
    fn default() -> ColourMap {
        let c = |v: f64| Colour {
            rgb: Rgb::splat(v),
            filter: 0.0,
            transmit: 0.0,
        };
        ColourMap {
            entries: vec![(0.0, c(0.0)), (1.0, c(1.0))],
        }
    }
}

/// A decoded image (`image_map`, `image_pattern`, `bump_map`).
pub use crate::pattern::image::ImageMap;

/// `interior { ior dispersion dispersion_samples fade_distance fade_power fade_color caustics
/// media {…} }`.
#[derive(Clone, PartialEq)]
pub struct Interior {
    /// Index of refraction (default 1).
    pub ior: f64,
    /// `dispersion`: the ratio of the index of refraction at the violet end of the spectrum
    /// to that at the red end (default 1: none; POV-Ray keeps it only with an `ior`, as
    /// single precision).
    pub dispersion: f64,
    /// `dispersion_samples`: how many wavelengths a dispersing refraction splits a ray into
    /// (default 7, at least 2).
    pub dispersion_samples: u32,
    /// Whether an `ior` was written for this interior (POV-Ray drops a dispersion without
    /// one when the object is placed; the reader's own bookkeeping).
    pub(crate) ior_given: bool,
    /// `fade_distance` (default 0: no fade).
    pub fade_distance: f64,
    /// `fade_power` (default 0).
    pub fade_power: f64,
    /// `fade_color` (default black).
    pub fade_colour: Rgb,
    /// What the light passing through the surface is multiplied by (default 1): POV-Ray's
    /// old `refraction` (of a finish, which a plain texture's finish sets; or of an interior).
    pub refraction: f64,
    /// Fake caustics (`caustics F`, stored as POV-Ray stores it: F·45, default 0): a shadow
    /// ray crossing the surface is brightened by 1 + |cos|^caustics for each texture layer.
    pub caustics: f64,
    /// `media { … }` blocks, in source order (seen only by rays inside a hollow object).
    pub media: Vec<Media>,
}

impl Default for Interior {
    fn default() -> Interior {
        Interior {
            ior: 1.0,
            dispersion: 1.0,
            dispersion_samples: 7,
            ior_given: false,
            fade_distance: 0.0,
            fade_power: 0.0,
            fade_colour: Rgb::ZERO,
            refraction: 1.0,
            caustics: 0.0,
            media: Vec::new(),
        }
    }
}

impl Interior {
    /// The bits of its values, as a key for sharing equal interiors (equal interiors, equal
    /// keys; the sharing still compares the values).
    pub fn key(&self) -> u64 {
        [
            self.ior,
            self.dispersion,
            self.fade_distance,
            self.fade_power,
            self.fade_colour.x,
            self.fade_colour.y,
            self.fade_colour.z,
            self.refraction,
            self.caustics,
            self.media.len() as f64,
        ]
        .iter()
        .fold(0u64, |h, v| {
            (h ^ v.to_bits())
                .wrapping_mul(0x9E37_79B9_7F4A_7C15)
                .rotate_left(29)
        })
    }
}

// (The old `refraction` is shown only when set: scenes without it read as before.)
impl std::fmt::Debug for Interior {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut d = f.debug_struct("Interior");
        d.field("ior", &self.ior)
            .field("fade_distance", &self.fade_distance)
            .field("fade_power", &self.fade_power)
            .field("fade_colour", &self.fade_colour);
        if self.refraction != 1.0 {
            d.field("refraction", &self.refraction);
        }
        if self.caustics != 0.0 {
            d.field("caustics", &self.caustics);
        }
        if self.dispersion != 1.0 {
            d.field("dispersion", &self.dispersion)
                .field("dispersion_samples", &self.dispersion_samples);
        }
        if !self.media.is_empty() {
            d.field("media", &self.media);
        }
        d.finish()
    }
}

/// POV-Ray's finish, every default filled in (`Create_Finish`).
///
/// `.rt`: `finish { ambient 0.1 diffuse 0.6 phong 1 ... }`.
#[derive(Clone, PartialEq)]
pub struct Finish {
    /// Ambient colour (default 0.1).
    pub ambient: Rgb,
    /// Emission colour (default 0).
    pub emission: Rgb,
    /// Diffuse amount (default 0.6).
    pub diffuse: f64,
    /// Back-side diffuse amount (default 0).
    pub diffuse_back: f64,
    /// Brilliance exponent on the diffuse cosine (default 1).
    pub brilliance: f64,
    /// Phong highlight amount (default 0).
    pub phong: f64,
    /// Phong exponent (default 40).
    pub phong_size: f64,
    /// Blinn specular amount (default 0).
    pub specular: f64,
    /// Specular roughness (default 0.05); the exponent is `1/roughness`.
    pub roughness: f64,
    /// Metallic highlights (default 0; keyword alone 1).
    pub metallic: f64,
    /// Mirror reflection.
    pub reflection: Reflection,
    /// `conserve_energy`: reflection reduces transmission.
    pub conserve_energy: bool,
    /// `crand` (default 0): each light's diffuse intensity less a random fraction up to this
    /// (a grainy surface).
    pub crand: f64,
    /// `irid { … }`: thin-film interference.
    pub irid: Irid,
    /// POV-Ray's old `ior` written in a finish (`None` if not given): the evaluator moves it
    /// to the interior of an object whose texture is plain (not a pattern of textures), as
    /// POV-Ray does; the renderer reads it there.
    pub legacy_ior: Option<f64>,
    /// POV-Ray's old `refraction` of a finish (default 1): moved to the interior likewise.
    pub legacy_refraction: f64,
    /// POV-Ray's old `caustics` of a finish (moved to the object's interior, as written: not
    /// times 45 as `interior { caustics }` is; a negative value is not moved).
    pub legacy_caustics: Option<f64>,
}

// (The old interior items are shown only when given: scenes without them read as before.)
impl std::fmt::Debug for Finish {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut d = f.debug_struct("Finish");
        d.field("ambient", &self.ambient)
            .field("emission", &self.emission)
            .field("diffuse", &self.diffuse)
            .field("diffuse_back", &self.diffuse_back)
            .field("brilliance", &self.brilliance)
            .field("phong", &self.phong)
            .field("phong_size", &self.phong_size)
            .field("specular", &self.specular)
            .field("roughness", &self.roughness)
            .field("metallic", &self.metallic)
            .field("reflection", &self.reflection)
            .field("conserve_energy", &self.conserve_energy)
            .field("crand", &self.crand)
            .field("irid", &self.irid);
        if let Some(ior) = self.legacy_ior {
            d.field("legacy_ior", &ior);
        }
        if self.legacy_refraction != 1.0 {
            d.field("legacy_refraction", &self.legacy_refraction);
        }
        if let Some(c) = self.legacy_caustics {
            d.field("legacy_caustics", &c);
        }
        d.finish()
    }
}

/// `irid { amount thickness T turbulence V }`: a thin film's interference colours.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Irid {
    /// The amount (0: none).
    pub amount: f64,
    /// `thickness` (default 0).
    pub thickness: f64,
    /// `turbulence` (the x of the vector given): the thickness varies by up to this fraction.
    pub turbulence: f64,
}

impl Default for Finish {
    fn default() -> Finish {
        Finish {
            ambient: Rgb::splat(0.1),
            emission: Rgb::ZERO,
            diffuse: 0.6,
            diffuse_back: 0.0,
            brilliance: 1.0,
            phong: 0.0,
            phong_size: 40.0,
            specular: 0.0,
            roughness: 0.05,
            metallic: 0.0,
            reflection: Reflection::default(),
            conserve_energy: false,
            crand: 0.0,
            irid: Irid::default(),
            legacy_ior: None,
            legacy_refraction: 1.0,
            legacy_caustics: None,
        }
    }
}

/// `reflection C` or `reflection { min, max falloff F exponent E fresnel metallic M }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Reflection {
    /// Reflectivity at normal incidence (or the Fresnel minimum).
    pub min: Rgb,
    /// Reflectivity at grazing incidence.
    pub max: Rgb,
    /// Exponent of the `(1 − cos)` blend from min to max (default 1).
    pub falloff: f64,
    /// `exponent`: the reflected colour is raised to `1/exponent` (default 1).
    pub exponent: f64,
    /// Fresnel blend instead of the falloff blend.
    pub fresnel: bool,
    /// Reflection tinted by the pigment (default 0).
    pub metallic: f64,
}

impl Default for Reflection {
    fn default() -> Reflection {
        Reflection {
            min: Rgb::ZERO,
            max: Rgb::ZERO,
            falloff: 1.0,
            exponent: 1.0,
            fresnel: false,
            metallic: 0.0,
        }
    }
}

impl Reflection {
    /// Whether this finish reflects at all.
    pub fn is_some(&self) -> bool {
        self.min.max_element() > 0.0 || self.max.max_element() > 0.0
    }
}

impl Interior {
    /// Moves the interior's media densities by `t` (an object's transformation: the media's
    /// coefficients stay per unit of world length, as in POV-Ray).
    pub fn transform(&mut self, t: Transform) {
        for m in &mut self.media {
            m.transform(t);
        }
    }
}

/// `media { … }`: participating media, POV-Ray 3.7's, every default filled in for the
/// scene's `#version` (method 3, one interval, 10 samples from 3.5 on; method 1, 10
/// intervals, 1 sample before).
///
/// `.rt`: `media { absorption 0.5 emission <1, 0.5, 0> scattering { 1, 0.2 } density { … } }`.
#[derive(Clone, Debug, PartialEq)]
pub struct Media {
    /// `method` 1 (random samples), 2 (stratified) or 3 (adaptive).
    pub method: u32,
    /// `intervals` (at least 1).
    pub intervals: u32,
    /// `samples Min, Max` (1 ≤ Min ≤ Max).
    pub samples: (u32, u32),
    /// `confidence` (default 0.9) and `variance` (default 1/128): when methods 1 and 2 take
    /// more samples.
    pub confidence: f64,
    /// See `confidence`.
    pub variance: f64,
    /// `ratio` (default 0.9): the share of intervals given to lit parts of a ray.
    pub ratio: f64,
    /// `jitter` (default 0).
    pub jitter: f64,
    /// `aa_threshold` (default 0.1) and `aa_level` (default 3): method 3's refinement.
    pub aa_threshold: f64,
    /// See `aa_threshold`.
    pub aa_level: u32,
    /// `absorption`, per unit of world length.
    pub absorption: Rgb,
    /// `emission`, per unit of world length.
    pub emission: Rgb,
    /// `scattering { TYPE, … }`: 1 isotropic, 2 Mie hazy, 3 Mie murky, 4 Rayleigh,
    /// 5 Henyey-Greenstein (any other number scatters as 1).
    pub scattering_type: i32,
    /// The scattering colour, per unit of world length.
    pub scattering: Rgb,
    /// `eccentricity` of type 5.
    pub eccentricity: f64,
    /// `extinction` (default 1): how much scattering also dims the light.
    pub extinction: f64,
    /// `density { … }` blocks, the last written first (POV-Ray's list order); the densities
    /// multiply, and a medium without one has density 1.
    pub densities: Vec<Pigment>,
}

impl Media {
    /// POV-Ray's defaults for a scene of `#version` `version` (3.5 changed four).
    pub fn new(version: f64) -> Media {
        let modern = version >= 3.5 - 1e-9;
        Media {
            method: if modern { 3 } else { 1 },
            intervals: if modern { 1 } else { 10 },
            samples: if modern { (10, 10) } else { (1, 1) },
            confidence: 0.9,
            variance: 1.0 / 128.0,
            ratio: 0.9,
            jitter: 0.0,
            aa_threshold: 0.1,
            aa_level: 3,
            absorption: Rgb::ZERO,
            emission: Rgb::ZERO,
            scattering_type: 1,
            scattering: Rgb::ZERO,
            eccentricity: 0.0,
            extinction: 1.0,
            densities: Vec::new(),
        }
    }

    /// Moves every density by `t` (after its own transformations).
    pub fn transform(&mut self, t: Transform) {
        for d in &mut self.densities {
            t.append_to(&mut d.transform);
        }
    }
}

impl Texture {
    /// Moves the texture by `t` (after its own transformations): its pigment and normal in
    /// every layer, and a pattern of textures with the textures in its space.
    pub fn transform(&mut self, t: Transform) {
        if let Some(m) = &mut self.map {
            t.append_to(&mut m.transform);
        }
        t.append_to(&mut self.pigment.transform);
        if let Some(n) = &mut self.normal {
            t.append_to(&mut n.transform);
        }
        for layer in &mut self.under {
            layer.transform(t);
        }
    }
}

impl Default for Texture {
    /// POV-Ray's default texture: black pigment, default finish.
    fn default() -> Texture {
        Texture {
            pigment: Pigment::solid(Colour::default()),
            normal: None,
            under: Vec::new(),
            map: None,
            finish: Arc::new(Finish::default()),
        }
    }
}

impl Default for Camera {
    /// POV-Ray's default camera: at the origin looking along +z, right `<1.33, 0, 0>`.
    fn default() -> Camera {
        Camera {
            projection: Projection::Perspective,
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            blur: None,
            normal: None,
            mesh: None,
        }
    }
}

impl Default for Settings {
    fn default() -> Settings {
        Settings {
            gamma: Gamma::Off,
            max_trace_level: 5,
            adc_bailout: 1.0 / 255.0,
            ambient_light: Rgb::ONE,
            legacy_transparency: true,
            noise_generator: 2,
            number_of_waves: 10,
            irid_wavelength: Rgb::new(0.70, 0.52, 0.48),
            radiosity: None,
        }
    }
}
