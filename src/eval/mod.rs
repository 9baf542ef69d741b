//! Evaluation: syntax tree → IR.
//!
//! Runs the directives and declarations, evaluates expressions, applies POV-Ray's defaults and
//! fixed evaluation orders (camera, texture attachment), and rejects by name anything outside
//! trace's subset. Uses `syntax`, `ir` and `diag`; knows nothing of rendering.

mod array;
mod datetime;
mod expr;
mod files;
mod flow;
mod function;
mod heightfield;
mod images;
pub mod keywords;
mod material;
mod object;
mod reader;
mod sandbox;
mod shapes;
mod transform;
mod value;

use crate::diag::{Diagnostic, FileId, SourceMap, Span};
use crate::ir::{self, Gamma, Rgb, Texture, Transform};
use crate::syntax::{self, Expr, Node, NodeKind, View};
use glam::DVec3;
pub use object::ObjectValue;
use std::collections::HashMap;
use std::sync::Arc;
use value::{Value, colour5, rgb};

type Result<T> = std::result::Result<T, Diagnostic>;

/// What evaluation needs from outside the scene file.
#[derive(Clone, Debug)]
pub struct LoadOptions {
    /// Image width in pixels (`image_width` in expressions).
    pub width: u32,
    /// Image height in pixels (`image_height`).
    pub height: u32,
    /// Folders searched for `#include` files after the scene's own folder (`-L`).
    pub include_paths: Vec<std::path::PathBuf>,
    /// Threads for reading big files (`None`: one per core). The scene is the same for any count.
    pub threads: Option<usize>,
    /// Most evaluation steps a scene may take, all together: statements and block items run,
    /// loop passes, and macro calls (one step per 16 bytes of the macro's body).
    pub max_steps: u64,
    /// The animation clock (`clock`, `frame_number` and friends).
    pub clock: Clock,
    /// Identifiers declared before the scene is read (POV-Ray's `Declare=NAME=VALUE`).
    pub declares: Vec<(String, f64)>,
}

/// The animation values a scene reads (POV-Ray's `clock`, `clock_delta`, `clock_on`,
/// `frame_number`, `initial_frame`, `final_frame`, `initial_clock`, `final_clock`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Clock {
    /// `clock`: the frame's clock value.
    pub clock: f64,
    /// `clock_delta`: the clock's step from one frame to the next.
    pub delta: f64,
    /// `clock_on`: whether this is a frame of an animation.
    pub on: bool,
    /// `frame_number`.
    pub frame: i64,
    /// `initial_frame` and `final_frame`.
    pub frames: (i64, i64),
    /// `initial_clock` and `final_clock`.
    pub clocks: (f64, f64),
}

impl Clock {
    /// A still image with `clock` at `value` (POV-Ray's values without animation options: the
    /// frame numbers and clock bounds are 0, and `clock_on` says whether a clock was given).
    pub fn still(value: Option<f64>) -> Clock {
        Clock {
            clock: value.unwrap_or(0.0),
            delta: 0.0,
            on: value.is_some(),
            frame: 0,
            frames: (0, 0),
            clocks: (0.0, 0.0),
        }
    }

    /// Frame `frame` of an animation of frames `first..=last` whose clock runs from `c0` to
    /// `c1` (POV-Ray: evenly, the last frame at `c1`; `cyclic`, the frame after the last at
    /// `c1`, and `final_frame` one more).
    pub fn frame(
        frame: i64,
        (first, last): (i64, i64),
        (c0, c1): (f64, f64),
        cyclic: bool,
    ) -> Clock {
        let last = if cyclic { last + 1 } else { last };
        let delta = if last > first {
            (c1 - c0) / (last - first) as f64
        } else {
            0.0
        };
        Clock {
            clock: c0 + delta * (frame - first) as f64,
            delta,
            on: true,
            frame,
            frames: (first, last),
            clocks: (c0, c1),
        }
    }
}

/// The default of [`LoadOptions::max_steps`]: about a minute of evaluation at most on every
/// loop measured (0.17 to 0.35 µs a step: a `#declare` loop, objects made in a loop, macros
/// called in a loop, a ray tracer written in macros; README, "Limits on work and memory").
pub const DEFAULT_MAX_STEPS: u64 = 200_000_000;

/// POV-Ray's standard include folder where it is installed (Debian's and a source build's
/// places, or the folder `POVRAY_INCLUDE` names): `trace` searches it after the `-L` folders,
/// as POV-Ray searches the `Library_Path` of its configuration.
pub fn standard_include_folder() -> Option<std::path::PathBuf> {
    let named = std::env::var_os("POVRAY_INCLUDE").map(std::path::PathBuf::from);
    named
        .into_iter()
        .chain(
            [
                "/usr/share/povray-3.7/include",
                "/usr/local/share/povray-3.7/include",
            ]
            .map(std::path::PathBuf::from),
        )
        .find(|p| p.is_dir())
}

impl Default for LoadOptions {
    fn default() -> LoadOptions {
        LoadOptions {
            width: 800,
            height: 600,
            include_paths: Vec::new(),
            threads: None,
            max_steps: DEFAULT_MAX_STEPS,
            clock: Clock::still(None),
            declares: Vec::new(),
        }
    }
}

/// A light's type as POV-Ray's parser keeps it: the last type keyword wins.
#[derive(Clone, Copy, Debug, PartialEq)]
enum LightType {
    Point,
    Spot,
    /// `cylinder`: a spot of parallel rays.
    Cylinder,
    /// `shadowless`: POV-Ray's fill light.
    Fill,
}

/// The camera items as written; resolved in POV-Ray's fixed order by [`resolve_camera`].
#[derive(Clone, Debug)]
pub struct CameraItems {
    projection: ir::Projection,
    location: DVec3,
    look_at: Option<DVec3>,
    direction: DVec3,
    up: DVec3,
    right: DVec3,
    sky: DVec3,
    angle: Option<(f64, Span)>,
    /// The second value of `angle` (`spherical`'s vertical angle).
    v_angle: Option<f64>,
    up_or_right_given: bool,
    transform: Option<Transform>,
    span: Span,
    /// Focal blur: aperture, (min, max) samples, focal point, confidence, variance.
    aperture: f64,
    blur_samples: (u32, u32),
    focal_point: Option<DVec3>,
    confidence: f64,
    variance: f64,
    normal: Option<Box<ir::Normal>>,
    /// `mesh_camera { … }`: what it gives before the camera's location and direction are
    /// known (offset and reversal are left for `resolve_camera`).
    mesh: Option<ir::MeshCamera>,
}

impl Default for CameraItems {
    fn default() -> CameraItems {
        let d = ir::Camera::default();
        CameraItems {
            projection: d.projection,
            location: d.location,
            look_at: None,
            direction: d.direction,
            up: d.up,
            right: d.right,
            sky: DVec3::Y,
            angle: None,
            v_angle: None,
            up_or_right_given: false,
            transform: None,
            aperture: 0.0,
            blur_samples: (0, 0),
            focal_point: None,
            confidence: 0.9,
            variance: 1.0 / 10000.0,
            normal: None,
            mesh: None,
            span: Span::default(),
        }
    }
}

/// The result of evaluating a scene: the IR plus the warnings met on the way.
pub struct Evaluated {
    /// The scene.
    pub scene: ir::Scene,
    /// What the scene's `#debug` directives printed.
    pub debug_output: String,
    /// Warnings, in source order.
    pub warnings: Vec<Diagnostic>,
}

/// Makes a pigment's function (`function { pigment { … } }`: its colour at a point). The
/// scene layer evaluates pigments and evaluation may not use it, so the library hands
/// evaluation this maker (`scene::pigment_function`).
pub type PigmentFunctionMaker =
    fn(&ir::Pigment, crate::pattern::SceneDefaults) -> std::sync::Arc<dyn crate::func::Native>;

/// Builds an object made of placed parts for `trace()`, `inside()`, `min_extent` and
/// `max_extent` (the scene layer's, handed to evaluation by the library).
pub type ObjectQueryMaker = fn(Vec<ir::Object>) -> Box<dyn ir::ObjectQuery>;

/// What evaluation needs from the layers after it, handed in by the library.
#[derive(Clone, Copy)]
pub struct Services {
    /// Makes pigment functions.
    pub pigment_function: PigmentFunctionMaker,
    /// Makes objects that answer trace() and its kin.
    pub object_query: ObjectQueryMaker,
}

/// Evaluates the file `file` of `sources` into a scene.
pub fn evaluate(
    sources: &mut SourceMap,
    file: FileId,
    options: &LoadOptions,
    services: Services,
) -> Result<Evaluated> {
    let scene_dir = sources
        .file(file)
        .path
        .parent()
        .map(|p| p.to_path_buf())
        .unwrap_or_default();
    let sandbox = sandbox::Sandbox::new(&scene_dir, &options.include_paths);
    let input_file_name = sources.file(file).path.display().to_string();
    let mut ev = Evaluator::new(options, sandbox, sources, services);
    ev.input_file_name = input_file_name;
    for (name, value) in &options.declares {
        ev.set(name.clone(), value::Value::Float(*value));
    }
    ev.read_scene(file)?;
    ev.finish()
}

/// `d` with a note naming the keyword `word` is probably a misspelling of, if one is near.
/// The value of a pattern modifier (`turbulence 0.5`), if it has one.
pub(super) fn modifier_value(node: &Node) -> Option<&Expr> {
    match node.view() {
        View::PatternModifier { value, .. } => value,
        _ => None,
    }
}

/// The error for a node whose values do not have its kind's layout (which the grammar does
/// not make: `syntax::view`), where `what` was expected.
pub(super) fn malformed(node: &Node, what: &str) -> Diagnostic {
    Diagnostic::error(
        format!(
            "internal error: `{}` read as {what} has values out of place",
            node.word
        ),
        node.word_span,
    )
}

fn suggest(d: Diagnostic, word: &str) -> Diagnostic {
    match keywords::suggestion(word) {
        Some(k) => d.with_note(format!("did you mean `{k}`?")),
        None => d,
    }
}

/// A key of the bits of `values` (equal values, equal keys).
fn bits_key(values: impl IntoIterator<Item = f64>) -> u64 {
    values.into_iter().fold(0u64, |h, v| {
        (h ^ v.to_bits())
            .wrapping_mul(0x9E37_79B9_7F4A_7C15)
            .rotate_left(29)
    })
}

impl Evaluator<'_> {
    /// `finish`, shared with an equal finish made before if there is one.
    pub(crate) fn shared_finish(&mut self, finish: ir::Finish) -> std::sync::Arc<ir::Finish> {
        let r = &finish.reflection;
        let key = bits_key([
            finish.ambient.x,
            finish.ambient.y,
            finish.ambient.z,
            finish.emission.x,
            finish.emission.y,
            finish.emission.z,
            finish.diffuse,
            finish.diffuse_back,
            finish.brilliance,
            finish.phong,
            finish.phong_size,
            finish.specular,
            finish.roughness,
            finish.metallic,
            r.min.x,
            r.min.y,
            r.min.z,
            r.max.x,
            r.max.y,
            r.max.z,
            r.falloff,
            r.exponent,
            r.metallic,
            f64::from(u8::from(r.fresnel) + 2 * u8::from(finish.conserve_energy)),
        ]);
        share(&mut self.finishes, key, finish)
    }

    /// `interior`, shared with an equal interior made before if there is one.
    pub(crate) fn shared_interior(
        &mut self,
        interior: ir::Interior,
    ) -> std::sync::Arc<ir::Interior> {
        let i = &interior;
        let key = bits_key([
            i.ior,
            i.fade_distance,
            i.fade_power,
            i.fade_colour.x,
            i.fade_colour.y,
            i.fade_colour.z,
        ]);
        share(&mut self.interiors, key, interior)
    }
}

/// The value kept under `key` if it equals `value`, else `value` (kept if the key is free).
fn share<T: PartialEq>(
    kept: &mut HashMap<u64, std::sync::Arc<T>>,
    key: u64,
    value: T,
) -> std::sync::Arc<T> {
    match kept.get(&key) {
        Some(same) if **same == value => std::sync::Arc::clone(same),
        Some(_) => std::sync::Arc::new(value),
        None => {
            let value = std::sync::Arc::new(value);
            kept.insert(key, std::sync::Arc::clone(&value));
            value
        }
    }
}

/// Moves a light: its position, the point it aims at and its area-light axes.
pub(crate) fn transform_light(light: &mut ir::Light, m: &glam::DMat4) {
    light.position = m.transform_point3(light.position);
    if let Some(parts) = &mut light.projected_through {
        for part in Arc::make_mut(parts) {
            Transform { matrix: *m }.append_to(&mut part.transform);
        }
    }
    match &mut light.kind {
        ir::LightKind::Point => {}
        ir::LightKind::Spot { point_at, .. }
        | ir::LightKind::Parallel { point_at }
        | ir::LightKind::Cylinder { point_at, .. } => {
            *point_at = m.transform_point3(*point_at);
        }
    }
    if let Some(a) = &mut light.area {
        a.axis1 = m.transform_vector3(a.axis1);
        a.axis2 = m.transform_vector3(a.axis2);
    }
}

/// A fog's items as written (a declared fog keeps them all, fog_alt of a constant fog too,
/// since a fog made from it may turn into ground fog).
#[derive(Clone, Debug)]
pub(crate) struct FogItems {
    distance: f64,
    colour: ir::Colour,
    ground: bool,
    offset: f64,
    alt: f64,
    alt_span: Span,
    turbulence: Option<crate::noise::Turbulence>,
    turb_depth: f64,
    /// Where the distance was given (for the check of its sign).
    distance_span: Span,
    up: DVec3,
}

/// A table by name: the reader looks a word up in two of them for every word it reads, so the
/// hash is a quick one (FNV-1a; names are short, and chosen by the scene, which is trusted
/// not to attack its own load time).
type Names<V> = HashMap<String, V, std::hash::BuildHasherDefault<NameHasher>>;

/// FNV-1a, for [`Names`].
#[derive(Default)]
struct NameHasher(u64);

impl std::hash::Hasher for NameHasher {
    fn write(&mut self, bytes: &[u8]) {
        let mut h = if self.0 == 0 {
            0xcbf2_9ce4_8422_2325
        } else {
            self.0
        };
        for &b in bytes {
            h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
        }
        self.0 = h;
    }

    fn finish(&self) -> u64 {
        self.0
    }
}

/// The evaluation state: declarations, defaults and the scene gathered so far.
pub(crate) struct Evaluator<'a> {
    options: &'a LoadOptions,
    sources: &'a mut SourceMap,
    macros: Names<flow::Macro>,
    frames: Vec<flow::Frame>,
    /// The directive reader's state: what is being read, the directive blocks open.
    reader: reader::Reader,
    /// The values of the words of the unit being evaluated, by slot (see `reader.rs`).
    bindings: Vec<Option<Arc<Value>>>,
    /// Added to slots while an expression read again is evaluated (`ExprKind::Shifted`).
    slot_shift: u32,
    include_depth: usize,
    /// Evaluation steps so far (see [`LoadOptions::max_steps`]).
    steps: u64,
    /// What `#debug` printed.
    debug_output: String,
    /// The folders the scene may read files from.
    sandbox: sandbox::Sandbox,
    sky_sphere: Option<ir::SkySphere>,
    fogs: Vec<ir::Fog>,
    /// The declared names, as the reader sees them.
    env: Names<Arc<Value>>,
    version: Option<f64>,
    /// `global_settings { noise_generator N }`, if given.
    noise_generator: Option<u8>,
    assumed_gamma: Option<f64>,
    settings: ir::Settings,
    camera: Option<CameraItems>,
    lights: Vec<ir::Light>,
    objects: Vec<ir::Object>,
    /// The next unused [`ir::Object::medium`].
    next_medium: u32,
    /// The next `light_group`'s number.
    next_light_group: u32,
    /// `input_file_name`: the scene file as named.
    input_file_name: String,
    /// The amount of a normal that gives none (`#default { normal { bump_size B } }`).
    default_bump_size: f64,
    background: Rgb,
    background_alpha: f64,
    default_texture: Texture,
    /// The interior of objects without one, shared by all of them.
    default_interior: std::sync::Arc<ir::Interior>,
    /// Finishes and interiors made so far, by the bits of their values: an equal one made
    /// again is shared (a million spheres each with `finish { phong 0.5 }` hold one finish).
    finishes: HashMap<u64, std::sync::Arc<ir::Finish>>,
    interiors: HashMap<u64, std::sync::Arc<ir::Interior>>,
    warnings: Vec<Diagnostic>,
    /// The warnings given, by message and place (each is said once).
    warned: std::collections::HashSet<(String, Option<Span>)>,
    /// POV-Ray's standard include folder, whose files draw no warnings.
    standard_includes: Option<std::path::PathBuf>,
    /// The state of each `seed()` stream, read and advanced by `rand()`.
    rand_streams: Vec<u32>,
    /// Names declared `deprecated`, with their message: the first use warns.
    deprecated: HashMap<String, String>,
    /// Mesh files read so far: a file used twice is read and stored once.
    mesh_files: HashMap<std::path::PathBuf, std::sync::Arc<ir::Mesh>>,
    /// How `text` reads its strings (`global_settings { charset … }`).
    charset: crate::font::Charset,
    /// Font files read, by path (`text`).
    fonts: HashMap<std::path::PathBuf, std::sync::Arc<Vec<u8>>>,
    /// Files opened by `#fopen`.
    files: files::Files,
    /// Makes pigment functions.
    pigment_function: PigmentFunctionMaker,
    /// Makes objects that answer trace() and its kin.
    object_query: ObjectQueryMaker,
    /// The id of the last object made (see `ObjectValue::id`).
    next_object_id: u64,
    /// Objects asked by trace() and its kin so far, by id (a scatter loop asks one object
    /// thousands of times).
    queries: HashMap<u64, Arc<dyn ir::ObjectQuery>>,
}

impl<'a> Evaluator<'a> {
    fn new(
        options: &'a LoadOptions,
        sandbox: sandbox::Sandbox,
        sources: &'a mut SourceMap,
        services: Services,
    ) -> Evaluator<'a> {
        Evaluator {
            options,
            sources,
            macros: Names::default(),
            frames: Vec::new(),
            reader: Default::default(),
            bindings: Vec::new(),
            slot_shift: 0,
            include_depth: 0,
            steps: 0,
            debug_output: String::new(),
            sandbox,
            sky_sphere: None,
            fogs: Vec::new(),
            env: Names::default(),
            version: None,
            assumed_gamma: None,
            noise_generator: None,
            settings: ir::Settings::default(),
            camera: None,
            lights: Vec::new(),
            objects: Vec::new(),
            next_medium: 0,
            next_light_group: 0,
            input_file_name: String::new(),
            default_bump_size: material::DEFAULT_BUMP_SIZE,
            background: Rgb::ZERO,
            background_alpha: 0.0,
            default_texture: Texture::default(),
            default_interior: Default::default(),
            finishes: HashMap::new(),
            interiors: HashMap::new(),
            warnings: Vec::new(),
            warned: Default::default(),
            standard_includes: standard_include_folder().and_then(|f| f.canonicalize().ok()),
            rand_streams: Vec::new(),
            deprecated: HashMap::new(),
            mesh_files: HashMap::new(),
            fonts: HashMap::new(),
            charset: crate::font::Charset::Ascii,
            files: files::Files::default(),
            pigment_function: services.pigment_function,
            object_query: services.object_query,
            next_object_id: 0,
            queries: HashMap::new(),
        }
    }

    /// A file named in the scene (`what`: "include file", "image", …): like POV-Ray, the
    /// scene's folder, then the include paths; never outside them (see [`sandbox`]).
    fn find_file(&self, file: &str, what: &str, span: Span) -> Result<std::path::PathBuf> {
        self.sandbox.locate(file, what, span)
    }

    /// Adds a warning: once for each message and place (a warning about a declaration used a
    /// thousand times is said once), and not at all about a file of POV-Ray's standard include
    /// folder, which the user cannot change (POV-Ray says nothing about them either).
    fn warn(&mut self, d: Diagnostic) {
        if let Some(span) = d.span {
            let path = &self.sources.file(span.file).path;
            if self
                .standard_includes
                .as_ref()
                .is_some_and(|folder| path.starts_with(folder))
            {
                return;
            }
        }
        let key = (d.message.clone(), d.span);
        if self.warned.insert(key) {
            self.warnings.push(d);
        }
    }

    /// The error for a word that is not valid where it stands.
    fn unknown_word(&self, word: &str, span: Span) -> Diagnostic {
        match keywords::reason(word) {
            Some(reason) => Diagnostic::error(format!("unsupported: `{word}` ({reason})"), span),
            None => {
                let d = Diagnostic::error(format!("unknown identifier `{word}`"), span);
                // A declared name it is probably a misspelling of, else a keyword.
                match keywords::nearest(word, self.env.keys().map(String::as_str)) {
                    Some(name) => d.with_note(format!("did you mean `{name}`?")),
                    None => suggest(d, word),
                }
            }
        }
    }

    /// The error for an unknown item inside a block.
    fn unknown_item(&self, node: &Node, context: &str) -> Diagnostic {
        if node.kind == NodeKind::Value {
            return Diagnostic::error(
                format!(
                    "the value `{}` cannot stand here in {context} (a bare value stands only among a shape's values)",
                    node.word
                ),
                node.span,
            );
        }
        if node.kind == NodeKind::ColourItem {
            return Diagnostic::error(
                format!("a colour cannot stand here in {context} (only in a pigment)"),
                node.span,
            );
        }
        if context == "pigment"
            && matches!(
                node.word.as_str(),
                "rgb"
                    | "rgbf"
                    | "rgbt"
                    | "rgbft"
                    | "srgb"
                    | "srgbf"
                    | "srgbt"
                    | "srgbft"
                    | "color"
                    | "colour"
            )
        {
            return Diagnostic::error(
                "a second colour cannot stand here: a pigment takes one colour, as its first item (POV-Ray refuses this too)",
                node.word_span,
            );
        }
        if node.word == "pigment" && context == "pigment" {
            return Diagnostic::error(
                "unsupported: a pigment inside a pigment (a checker, map or pattern of pigments is not supported by trace yet)",
                node.word_span,
            );
        }
        if matches!(
            (context, node.word.as_str()),
            ("pigment", "pigment_map" | "color_map" | "colour_map")
                | ("normal", "normal_map")
                | ("texture", "texture_map")
        ) {
            // A map the grammar could not read (it reads maps where they may stand): an entry
            // holds what trace does not read yet, such as a function pattern.
            return Diagnostic::error(
                format!(
                    "unsupported: an entry of this `{}` that trace cannot read yet (a construct outside the subset)",
                    node.word
                ),
                node.word_span,
            );
        }
        match keywords::status(&node.word) {
            Some(keywords::Status::Unsupported(_)) => self.unknown_word(&node.word, node.word_span),
            // A keyword trace reads elsewhere: say that it is misplaced, not unknown.
            Some(keywords::Status::Supported) => Diagnostic::error(
                format!("`{}` cannot stand here in {context}", node.word),
                node.word_span,
            ),
            None if self.bound(node.slot).is_some() => Diagnostic::error(
                format!(
                    "`{}` cannot stand here in {context} (wrap it, e.g. `texture {{ {} }}`)",
                    node.word, node.word
                ),
                node.word_span,
            ),
            None => suggest(
                Diagnostic::error(
                    format!("unknown keyword `{}` in {context}", node.word),
                    node.word_span,
                ),
                &node.word,
            ),
        }
    }

    /// The value the word in `slot` of the unit being evaluated was bound to where it was
    /// read (see `reader.rs`).
    pub(super) fn bound(&self, slot: syntax::Slot) -> Option<&Value> {
        if slot == syntax::Slot::NONE {
            return None;
        }
        self.bindings
            .get(slot.0 as usize + self.slot_shift as usize)?
            .as_deref()
    }

    fn lookup(&mut self, ident: &Node) -> Result<Value> {
        self.item_ref(ident)
    }

    /// A declared value, or the error of a declaration that was outside the subset.
    fn usable(&mut self, name: &str, v: Value, span: Span) -> Result<Value> {
        if let Some(message) = self.deprecated.remove(name) {
            self.warnings.push(Diagnostic::warning(
                format!("`{name}` is deprecated: {message}"),
                span,
            ));
        }
        match v {
            Value::Unsupported(d) => {
                let mut e =
                    Diagnostic::error(format!("`{name}` cannot be used: {}", d.message), span);
                if let Some(s) = d.span {
                    e = e.with_note(format!(
                        "`{name}` is declared using it at {}",
                        self.location(s)
                    ));
                }
                Err(e)
            }
            v => Ok(v),
        }
    }

    fn statement(&mut self, node: &Node) -> Result<()> {
        match (node.kind, node.view()) {
            // A declared object standing alone: placed, as POV-Ray does.
            (NodeKind::IdentRef, _) => match self.lookup(node)? {
                Value::Object(object) => self.place(*object, node.word_span)?,
                other => {
                    return Err(Diagnostic::error(
                        format!(
                            "{} `{}` cannot stand alone here (only a declared object can)",
                            other.kind_name(),
                            node.word
                        ),
                        node.word_span,
                    ));
                }
            },
            (NodeKind::Default, _) => {
                self.each_item(&node.children, &mut |ev, child| {
                    match child.kind {
                        NodeKind::Texture => ev.default_texture = ev.texture(child)?,
                        NodeKind::Pigment => {
                            let base = ev.default_texture.pigment.clone();
                            ev.default_texture.pigment = ev.pigment(child, base)?;
                        }
                        NodeKind::Finish => {
                            let base = std::sync::Arc::clone(&ev.default_texture.finish);
                            ev.default_texture.finish = ev.shared_finish_block(child, &base)?;
                        }
                        // A default normal of `bump_size` alone: the amount of the normals
                        // made after it (POV-Ray copies the default normal into each).
                        NodeKind::Normal
                            if child.children.iter().all(|c| c.kind == NodeKind::BumpSize)
                                && !child.children.is_empty() =>
                        {
                            for c in &child.children {
                                if let View::BumpSize(size) = c.view() {
                                    ev.default_bump_size = f64::from(ev.float(size)? as f32);
                                }
                            }
                        }
                        NodeKind::Normal => {
                            let base = ev.default_texture.normal.take();
                            ev.default_texture.normal = Some(Box::new(ev.normal(child, base)?));
                        }
                        _ => return Err(ev.unknown_item(child, "#default")),
                    }
                    Ok(())
                })?;
            }
            (NodeKind::Camera, _) => {
                let items = self.camera_items(node, CameraItems::default())?;
                self.camera = Some(items);
            }
            (NodeKind::LightSource, _) => {
                let (light, looks) = self.light(node)?;
                self.lights.push(light);
                if let Some(object) = looks {
                    self.place(object, node.word_span)?;
                }
            }
            (NodeKind::Fog, _) => {
                let fog = self.fog(node)?;
                self.fogs.push(fog);
            }
            (_, View::Background(value)) => {
                let v = self.eval(value)?;
                let c = colour5(&v).ok_or_else(|| expr::type_error("a colour", &v, value.span))?;
                // Without alpha output POV-Ray stores rgb·(1 − transmit) and ignores filter.
                self.background = Rgb::new(c[0], c[1], c[2]) * (1.0 - c[4]);
                self.background_alpha = 1.0 - c[4];
            }
            (NodeKind::GlobalSettings, _) => self.global_settings(node)?,
            // POV-Ray's old places of these global settings, outside global_settings.
            (_, View::MaxTraceLevel(level)) => {
                self.warn(Diagnostic::warning(
                    "`max_trace_level` belongs in global_settings { … }: read there (POV-Ray warns too)",
                    node.word_span,
                ));
                self.max_trace_level(level)?;
            }
            (_, View::MaxIntersections(value)) => self.max_intersections(node, value)?,
            (NodeKind::SkySphere, _) => self.sky_sphere = Some(self.sky_sphere(node)?),
            _ if object::is_object(node.kind) => {
                let object = self.object(node)?;
                self.place(object, node.word_span)?;
            }
            (NodeKind::Unknown, _) => {
                return Err(match keywords::reason(&node.word) {
                    Some(_) => self.unknown_word(&node.word, node.word_span),
                    None => suggest(
                        Diagnostic::error(
                            format!(
                                "expected a statement (an object, camera, light_source, #declare …), found `{}`",
                                node.word
                            ),
                            node.word_span,
                        ),
                        &node.word,
                    ),
                });
            }
            _ => return Err(self.unknown_item(node, "the scene's top level")),
        }
        Ok(())
    }

    /// `sky_sphere { [Name] pigment {…}… [emission C] transforms }`. The transformations move
    /// the whole sky, pigments given after them included (as in POV-Ray).
    fn sky_sphere(&mut self, node: &Node) -> Result<ir::SkySphere> {
        let mut sky = ir::SkySphere {
            pigments: Vec::new(),
            emission: Rgb::ONE,
        };
        let mut moved = ir::Transform::IDENTITY;
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::SkySphere(s) => sky = s,
                    other => return Err(expr::type_error("a sky_sphere", &other, item.span)),
                },
                (NodeKind::Pigment, _) => sky
                    .pigments
                    .push(ev.pigment(item, ir::Pigment::solid(ir::Colour::default()))?),
                (_, View::Emission(value)) => {
                    let v = ev.eval(value)?;
                    sky.emission =
                        rgb(&v).ok_or_else(|| expr::type_error("a colour", &v, value.span))?;
                }
                _ if Self::is_transform(item) => moved = moved.then(ev.transform(item)?),
                _ => return Err(ev.unknown_item(item, "sky_sphere")),
            }
            Ok(())
        })?;
        if sky.pigments.is_empty() {
            return Err(Diagnostic::error(
                "this sky_sphere has no pigment (POV-Ray: empty sky_sphere statement)",
                node.word_span,
            ));
        }
        if moved != ir::Transform::IDENTITY {
            for p in &mut sky.pigments {
                moved.append_to(&mut p.transform);
            }
        }
        Ok(sky)
    }

    /// The value of a declared item (`#declare X = sphere { … }` and the like).
    pub(super) fn item_value(&mut self, node: &Node) -> Result<Value> {
        Ok(match node.kind {
            _ if object::is_object(node.kind) => Value::Object(Box::new(self.object(node)?)),
            // A declared light: an object made of it (`object { L }` places it).
            NodeKind::LightSource => {
                let (light, looks) = self.light(node)?;
                let mut object = looks.unwrap_or_else(object::ObjectValue::empty);
                object.lights.push(light);
                Value::Object(Box::new(object))
            }
            NodeKind::Pigment => {
                let base = self.default_texture.pigment.clone();
                Value::Pigment(Box::new(self.pigment(node, base)?))
            }
            NodeKind::Normal => Value::Normal(Box::new(self.normal(node, None)?)),
            NodeKind::SkySphere => Value::SkySphere(self.sky_sphere(node)?),
            NodeKind::Finish => {
                let base = (*self.default_texture.finish).clone();
                Value::Finish(Box::new(self.finish_block(node, base)?))
            }
            NodeKind::Texture => Value::Texture(Box::new(self.texture(node)?)),
            NodeKind::LayeredTexture => self.layered_texture(node)?,
            NodeKind::Function => Value::Function(self.function(node)?),
            NodeKind::Spline => Value::Spline(Arc::new(self.spline(node)?)),
            NodeKind::Interior => {
                Value::Interior(Box::new(self.interior(node, ir::Interior::default())?))
            }
            NodeKind::Material => Value::Material(Box::new(self.material(node)?)),
            NodeKind::ColourMap => Value::ColourMap(self.colour_map(node)?),
            NodeKind::PigmentMap => Value::PigmentMap(self.pigment_map(node, false)?),
            NodeKind::TextureMap => Value::TextureMap(self.texture_map(node, false)?),
            NodeKind::NormalMap => Value::NormalMap(self.normal_map(node, false)?),
            NodeKind::SlopeMap => Value::SlopeMap(self.slope_map(node)?),
            NodeKind::Fog => Value::Fog(Box::new(self.fog_items(node)?)),
            NodeKind::Transform => Value::Transform(Box::new(self.transform(node)?)),
            NodeKind::Camera => {
                Value::Camera(Box::new(self.camera_items(node, CameraItems::default())?))
            }
            _ => return Err(self.unknown_item(node, "a declaration")),
        })
    }

    /// `max_trace_level N`.
    fn max_trace_level(&mut self, level: &Expr) -> Result<()> {
        let n = self.float(level)?;
        self.settings.max_trace_level = (n as i64).clamp(1, 256) as u32;
        Ok(())
    }

    /// `max_intersections N`: no longer needed, ignored with a warning as in POV-Ray 3.7.
    fn max_intersections(&mut self, item: &Node, count: &Expr) -> Result<()> {
        self.float(count)?;
        self.warn(Diagnostic::warning(
            "`max_intersections` is no longer needed and has no effect (POV-Ray 3.7 says so too)",
            item.word_span,
        ));
        Ok(())
    }

    fn global_settings(&mut self, node: &Node) -> Result<()> {
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                // (`#default { … }` may stand here too, as POV-Ray reads it anywhere.)
                (NodeKind::Default, _) => ev.statement(item)?,
                (NodeKind::Charset, _) => {
                    ev.charset = if item.word.ends_with("ascii") {
                        crate::font::Charset::Ascii
                    } else {
                        crate::font::Charset::Utf8
                    };
                }
                (_, View::AssumedGamma(value)) => {
                    let g = ev.float(value)?;
                    if ev.assumed_gamma.is_some() {
                        ev.warn(Diagnostic::warning(
                            "a second assumed_gamma is ignored (as in POV-Ray)",
                            item.span,
                        ));
                    } else if g <= 0.0 {
                        return Err(Diagnostic::error(
                            "assumed_gamma must be positive",
                            value.span,
                        ));
                    } else {
                        ev.assumed_gamma = Some(g);
                    }
                }
                (_, View::MaxTraceLevel(level)) => ev.max_trace_level(level)?,
                (_, View::MaxIntersections(count)) => ev.max_intersections(item, count)?,
                (_, View::AdcBailout(value)) => ev.settings.adc_bailout = ev.float(value)?,
                (_, View::AmbientLight(value)) => {
                    let v = ev.eval(value)?;
                    ev.settings.ambient_light =
                        rgb(&v).ok_or_else(|| expr::type_error("a colour", &v, value.span))?;
                }
                (_, View::IridWavelength(value)) => {
                    let v = ev.eval(value)?;
                    ev.settings.irid_wavelength =
                        rgb(&v).ok_or_else(|| expr::type_error("a colour", &v, value.span))?;
                }
                (NodeKind::PatternModifier, _) if item.word == "number_of_waves" => {
                    let e = modifier_value(item).ok_or_else(|| {
                        Diagnostic::error("`number_of_waves` needs a value", item.word_span)
                    })?;
                    let n = ev.float(e)?.trunc();
                    // (POV-Ray reads 0 or less as 1.)
                    if n > crate::pattern::MAX_WAVES as f64 {
                        return Err(Diagnostic::error(
                            format!("unsupported: more than {} waves", crate::pattern::MAX_WAVES),
                            e.span,
                        ));
                    }
                    ev.settings.number_of_waves = n.max(1.0) as u8;
                }
                (NodeKind::PatternModifier, _) if item.word == "noise_generator" => {
                    let e = modifier_value(item).ok_or_else(|| {
                        Diagnostic::error("`noise_generator` needs a value", item.word_span)
                    })?;
                    let n = ev.float(e)?;
                    if !(1.0..=3.0).contains(&n) {
                        return Err(Diagnostic::error(
                            "noise_generator must be 1, 2 or 3",
                            e.span,
                        ));
                    }
                    ev.noise_generator = Some(n as u8);
                }
                // `hf_gray_16 [on|off]`: POV-Ray 3.7 writes the same PNG with or without it
                // (8 or 16-bit RGB, measured), so it has nothing to change here.
                _ if item.word == "hf_gray_16" => {}
                _ => return Err(ev.unknown_item(item, "global_settings")),
            }
            Ok(())
        })?;
        Ok(())
    }

    /// `fog { [F] items }` as written, from POV-Ray's defaults (distance 0: no fog; black;
    /// constant) or a declared fog's items.
    fn fog_items(&mut self, node: &Node) -> Result<FogItems> {
        let mut items = FogItems {
            distance: 0.0,
            colour: ir::Colour::default(),
            ground: false,
            offset: 0.0,
            alt: 0.0,
            alt_span: node.word_span,
            turbulence: None,
            turb_depth: 0.5,
            distance_span: node.word_span,
            up: DVec3::Y,
        };
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::Fog(declared) => items = *declared,
                    // A declared colour or float (POV-Ray copies only fogs this way).
                    Value::Float(d) => {
                        items.distance = d;
                        items.distance_span = item.span;
                    }
                    other => {
                        let c = colour5(&other).ok_or_else(|| {
                            expr::type_error("a fog or a colour", &other, item.span)
                        })?;
                        items.colour = value::to_colour(c);
                    }
                },
                (_, View::FogDistance(value)) => {
                    items.distance = ev.float(value)?;
                    items.distance_span = value.span;
                }
                (_, View::FogType(value)) => {
                    let t = ev.float(value)?.trunc();
                    if t != 1.0 && t != 2.0 {
                        ev.warn(Diagnostic::warning(
                            "unknown fog_type: constant fog is used (as POV-Ray does)",
                            value.span,
                        ));
                    }
                    items.ground = t == 2.0;
                }
                (_, View::FogAlt(value)) => {
                    items.alt = ev.float(value)?;
                    items.alt_span = value.span;
                }
                (_, View::FogOffset(value)) => items.offset = ev.float(value)?,
                (_, View::TurbDepth(value)) => items.turb_depth = ev.float(value)?,
                (NodeKind::PatternModifier, _)
                    if matches!(
                        item.word.as_str(),
                        "turbulence" | "octaves" | "omega" | "lambda"
                    ) =>
                {
                    let e = modifier_value(item).ok_or_else(|| {
                        Diagnostic::error(format!("`{}` needs a value", item.word), item.word_span)
                    })?;
                    let t = items.turbulence.get_or_insert_with(Default::default);
                    let single = |v: f64| f64::from(v as f32);
                    match item.word.as_str() {
                        "turbulence" => t.amount = ev.vec3(e)?,
                        "octaves" => t.octaves = (ev.float(e)? as i64).clamp(1, 10) as u32,
                        "omega" => t.omega = single(ev.float(e)?),
                        _ => t.lambda = single(ev.float(e)?),
                    }
                }
                (_, View::Up(value)) => items.up = ev.vec3(value)?,
                (NodeKind::Translate, _) => ev.warn(Diagnostic::warning(
                    "a fog's up vector can't be translated (ignored, as in POV-Ray)",
                    item.word_span,
                )),
                _ if Self::is_transform(item) => {
                    let t = ev.transform(item)?;
                    items.up = t.matrix.transform_vector3(items.up);
                }
                (_, View::FogColour(value)) => {
                    let v = ev.eval(value)?;
                    if let Value::Float(d) = v {
                        ev.warn(Diagnostic::warning(
                            "should use the distance keyword (a bare number is the fog's distance)",
                            value.span,
                        ));
                        items.distance = d;
                    } else {
                        let c = colour5(&v)
                            .ok_or_else(|| expr::type_error("a colour", &v, value.span))?;
                        items.colour = value::to_colour(c);
                    }
                }
                _ => return Err(ev.unknown_item(item, "fog")),
            }
            Ok(())
        })?;
        Ok(items)
    }

    /// A `fog` statement: its items resolved (the fog_alt check happens here, where the fog is
    /// used, so a declared fog may leave fog_alt to its user).
    fn fog(&mut self, node: &Node) -> Result<ir::Fog> {
        let items = self.fog_items(node)?;
        if items.distance < 0.0 {
            return Err(Diagnostic::error(
                "a fog's distance must not be negative (POV-Ray renders NaN pixels with one)",
                items.distance_span,
            ));
        }
        let kind = if items.ground {
            if items.alt == 0.0 {
                return Err(Diagnostic::error(
                    "ground fog (fog_type 2) needs a non-zero fog_alt (POV-Ray divides by it)",
                    items.alt_span,
                ));
            }
            if items.up.length() == 0.0 {
                return Err(Diagnostic::error(
                    "a fog's up vector must not be zero",
                    node.word_span,
                ));
            }
            ir::FogKind::Ground {
                offset: items.offset,
                alt: items.alt,
                up: items.up.normalize(),
            }
        } else {
            ir::FogKind::Constant
        };
        Ok(ir::Fog {
            distance: items.distance,
            colour: items.colour,
            kind,
            turbulence: items.turbulence.map(|turbulence| {
                Box::new(ir::FogTurbulence {
                    turbulence,
                    depth: items.turb_depth,
                })
            }),
        })
    }

    /// A `light_source`, and its `looks_like` object (placed at the light, casting no
    /// shadow).
    fn light(&mut self, node: &Node) -> Result<(ir::Light, Option<object::ObjectValue>)> {
        // `light_source { L transformations }` with a declared light `L`.
        let View::LightSource { location, colour } = node.view() else {
            return Err(malformed(node, "a light_source"));
        };
        if let syntax::ExprKind::Ident(_, slot) = &location.kind {
            if let Some(Value::Object(o)) = self.bound(*slot).cloned() {
                return self.declared_light(node, location, colour, *o);
            }
        }
        let position = self.vec3(location)?;
        // A light without a colour is black (POV-Ray accepts it silently).
        let colour = match colour {
            Some(e) => self.rgb_arg(e)?,
            None => Rgb::ZERO,
        };
        // POV-Ray keeps one light type, set by the last of `spotlight` and `shadowless` (a
        // fill light); `parallel` is a separate flag. `spotlight` resets the cone to its
        // defaults, and the cone's items need a spotlight before them.
        let mut light_type = LightType::Point;
        let mut parallel = false;
        let mut point_at = DVec3::Z;
        let (mut radius, mut falloff, mut tightness) = (None, None, None);
        let (mut fade_distance, mut fade_power) = (0.0, 0.0);
        let mut area: Option<ir::AreaLight> = None;
        // Area-light modifiers may come before or after `area_light`; the first one is kept
        // for the error if there is no area_light at all.
        let (mut jitter, mut circular, mut orient, mut illumination) = (false, false, false, false);
        let mut adaptive = 100;
        // Every area-light modifier given, in order (POV-Ray accepts them before `area_light`).
        let mut area_modifiers: Vec<(String, Span)> = Vec::new();
        let mut transform: Option<Transform> = None;
        // `looks_like` and `projected_through` objects, with the light's transformations
        // that follow them (those before are the light's place, which a looks_like object
        // moves to).
        let mut looks: Option<(object::ObjectValue, Transform)> = None;
        let mut through: Option<(object::ObjectValue, Transform, Span)> = None;
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (NodeKind::LooksLike, _) if item.word == "looks_like" => {
                    if looks.is_some() {
                        return Err(Diagnostic::error("only one looks_like per light_source", item.word_span));
                    }
                    let mut object = ev.object(item)?;
                    let centre = transform.as_ref().map_or(position, |t| t.matrix.transform_point3(position));
                    object.transform(Transform { matrix: glam::DMat4::from_translation(centre) }, false);
                    looks = Some((object, Transform::IDENTITY));
                }
                (NodeKind::LooksLike, _) => {
                    if through.is_some() {
                        return Err(Diagnostic::error("only one projected_through per light_source", item.word_span));
                    }
                    through = Some((ev.object(item)?, Transform::IDENTITY, item.word_span));
                }
                (NodeKind::LightFlag, _) => match item.word.as_str() {
                    "spotlight" => {
                        light_type = LightType::Spot;
                        (radius, falloff, tightness) = (None, None, None);
                    }
                    "cylinder" => {
                        light_type = LightType::Cylinder;
                        (radius, falloff, tightness) = (None, None, None);
                    }
                    "parallel" => parallel = true,
                    "shadowless" => light_type = LightType::Fill,
                    flag => {
                        area_modifiers.push((item.word.to_string(), item.word_span));
                        match flag {
                            "jitter" => jitter = true,
                            "circular" => circular = true,
                            _ => orient = true,
                        }
                    }
                },
                (NodeKind::PointAt | NodeKind::Radius | NodeKind::Falloff | NodeKind::Tightness, _)
                    if !(matches!(light_type, LightType::Spot | LightType::Cylinder)
                        || parallel && item.kind == NodeKind::PointAt) =>
                {
                    return Err(Diagnostic::error(
                        format!(
                            "`{}` needs `spotlight` or `cylinder` before it (POV-Ray refuses it on a {} light)",
                            item.word,
                            if light_type == LightType::Fill {
                                "shadowless"
                            } else {
                                "point"
                            }
                        ),
                        item.word_span,
                    ));
                }
                (_, View::PointAt(value)) => point_at = ev.vec3(value)?,
                (_, View::Radius(value)) => radius = Some(ev.float(value)?),
                (_, View::Falloff(value)) => falloff = Some(ev.float(value)?),
                (_, View::Tightness(value)) => tightness = Some(ev.float(value)?),
                (_, View::FadeDistance(value)) => fade_distance = ev.float(value)?,
                (_, View::FadePower(value)) => fade_power = ev.float(value)?,
                (_, View::AreaLight { axis1, axis2, size1, size2 }) => {
                    let axis1 = ev.vec3(axis1)?;
                    let axis2 = ev.vec3(axis2)?;
                    let size = |ev: &mut Self, e: &Expr| -> Result<u32> {
                        let n = ev.float(e)?;
                        if !(1.0..=1024.0).contains(&n) {
                            return Err(Diagnostic::error(
                                "area_light sizes must be between 1 and 1024",
                                e.span,
                            ));
                        }
                        Ok(n as u32)
                    };
                    let (size1, size2) = (size(ev, size1)?, size(ev, size2)?);
                    area = Some(ir::AreaLight {
                        axis1,
                        axis2,
                        size1,
                        size2,
                        adaptive,
                        jitter,
                        circular,
                        orient,
                        area_illumination: illumination,
                    });
                }
                (_, View::Adaptive(value)) => {
                    area_modifiers.push((item.word.to_string(), item.word_span));
                    adaptive = ev.float(value)?.max(0.0) as u32;
                }
                (NodeKind::AreaIllumination, _) => {
                    area_modifiers.push((item.word.to_string(), item.word_span));
                    illumination = ev.optional_float(item, 1.0)? != 0.0;
                }
                _ if Self::is_transform(item) => {
                    let t = ev.transform(item)?;
                    for after in [looks.as_mut().map(|l| &mut l.1), through.as_mut().map(|p| &mut p.1)]
                        .into_iter()
                        .flatten()
                    {
                        *after = after.then(t);
                    }
                    transform = Some(transform.unwrap_or(Transform::IDENTITY).then(t));
                }
                _ => return Err(ev.unknown_item(item, "light_source")),
            }
            Ok(())
        })?;
        let modifier = |word: &str| area_modifiers.iter().find(|(w, _)| w == word).map(|m| m.1);
        match &mut area {
            Some(a) => {
                (
                    a.jitter,
                    a.circular,
                    a.orient,
                    a.adaptive,
                    a.area_illumination,
                ) = (jitter, circular || orient, orient, adaptive, illumination);
                if a.circular && (a.size1 < 2 || a.size2 < 2) {
                    let span = modifier("circular")
                        .or(modifier("orient"))
                        .unwrap_or(node.word_span);
                    return Err(Diagnostic::error(
                        "a circular area_light must have more than 1 point per axis",
                        span,
                    ));
                }
                if illumination {
                    return Err(Diagnostic::error(
                        "unsupported: `area_illumination` (not supported by trace yet)",
                        modifier("area_illumination").unwrap_or(node.word_span),
                    ));
                }
            }
            // Without an area_light POV-Ray refuses `circular` (a one-point light cannot be
            // circular) and ignores the others, warning about `orient` and
            // `area_illumination` only.
            None => {
                if let Some(span) = modifier("circular") {
                    return Err(Diagnostic::error(
                        "`circular` needs an area_light with more than 1 point per axis (POV-Ray refuses it here)",
                        span,
                    ));
                }
                for (word, span) in &area_modifiers {
                    self.warn(Diagnostic::warning(
                        format!("`{word}` only affects an area_light: ignored, as in POV-Ray"),
                        *span,
                    ));
                }
            }
        }
        // (A cylinder light's rays are parallel whatever `parallel` says.)
        let kind = if light_type == LightType::Cylinder {
            ir::LightKind::Cylinder {
                point_at,
                radius: radius.unwrap_or(0.75),
                falloff: falloff.unwrap_or(1.0),
                tightness: tightness.unwrap_or(0.0),
            }
        } else if parallel {
            ir::LightKind::Parallel { point_at }
        } else if light_type == LightType::Spot {
            ir::LightKind::Spot {
                point_at,
                radius_deg: radius.unwrap_or(30.0),
                falloff_deg: falloff.unwrap_or(45.0),
                tightness: tightness.unwrap_or(0.0),
            }
        } else {
            ir::LightKind::Point
        };
        // Fade applies only when both are given and positive (POV-Ray §8.1).
        let fade = (fade_power > 0.0 && fade_distance.abs() > 1e-10).then_some(ir::LightFade {
            distance: fade_distance,
            power: fade_power,
        });
        let mut light = ir::Light {
            position,
            colour,
            kind,
            shadowless: light_type == LightType::Fill,
            fade,
            area,
            projected_through: None,
            group: None,
        };
        if let Some(t) = transform {
            transform_light(&mut light, &t.matrix);
        }
        if let Some((mut object, after, span)) = through {
            object.transform(after, false);
            let parts = self.placed_parts(&object, span)?;
            light.projected_through = Some(Arc::new(parts));
        }
        let looks = looks.map(|(mut object, after)| {
            object.transform(after, false);
            object.cast_no_shadow();
            object.outside_light_groups();
            object
        });
        Ok((light, looks))
    }

    /// `light_source { L … }` with `L` a declared light (an object holding one light):
    /// the light moved by the transformations that follow.
    fn declared_light(
        &mut self,
        node: &Node,
        name: &Expr,
        colour: Option<&Expr>,
        mut object: object::ObjectValue,
    ) -> Result<(ir::Light, Option<object::ObjectValue>)> {
        let Some(light) = object.lights.pop().filter(|_| object.lights.is_empty()) else {
            return Err(Diagnostic::error(
                "a light_source takes a declared light here (not another object)",
                name.span,
            ));
        };
        if let Some(extra) = colour {
            return Err(Diagnostic::error(
                "unsupported: a colour after a declared light (give the light's colour where it is declared)",
                extra.span,
            ));
        }
        let mut moves = Transform::IDENTITY;
        self.each_item(&node.children, &mut |ev, item| {
            if !Self::is_transform(item) {
                return Err(Diagnostic::error(
                    format!("unsupported: `{}` on a declared light (only transformations may follow its name)", item.word),
                    item.word_span,
                ));
            }
            moves = moves.then(ev.transform(item)?);
            Ok(())
        })?;
        object.lights.push(light);
        object.transform(moves, false);
        let light = object.lights.pop().expect("the light pushed above");
        let looks = (!object.parts_is_empty()).then_some(object);
        Ok((light, looks))
    }

    fn camera_items(&mut self, node: &Node, mut c: CameraItems) -> Result<CameraItems> {
        c.span = node.word_span;
        let mut declared = false;
        self.each_item(&node.children, &mut |ev, item| {
            if declared && !Self::is_transform(item) {
                ev.warn(Diagnostic::warning(
                    format!(
                        "POV-Ray 3.7 refuses `{}` after a declared camera (only transformations may follow its name): trace applies it, but this scene does not render in POV-Ray",
                        item.word
                    ),
                    item.word_span,
                ));
            }
            match (item.kind, item.view()) {
                (NodeKind::Perspective, _) => c.projection = ir::Projection::Perspective,
                (NodeKind::Orthographic, _) => c.projection = ir::Projection::Orthographic,
                (_, View::Location(value)) => c.location = ev.vec3(value)?,
                (_, View::LookAt(value)) => c.look_at = Some(ev.vec3(value)?),
                (_, View::Direction(value)) => c.direction = ev.vec3(value)?,
                (_, View::Up(value)) => {
                    c.up = ev.vec3(value)?;
                    c.up_or_right_given = true;
                }
                (_, View::Right(value)) => {
                    c.right = ev.vec3(value)?;
                    c.up_or_right_given = true;
                }
                (_, View::Sky(value)) => c.sky = ev.vec3(value)?,
                (_, View::CameraBlur { value, max }) => ev.camera_blur(item, value, max, &mut c)?,
                (NodeKind::MeshCamera, _) => {
                    c.mesh = Some(ev.mesh_camera(item)?);
                    c.projection = ir::Projection::Mesh;
                }
                (NodeKind::Normal, _) => {
                    let base = c.normal.take();
                    c.normal = Some(Box::new(ev.normal(item, base)?));
                }
                (_, View::Angle { angle, vertical }) => {
                    let a = ev.float(angle)?;
                    // (`angle 0` on a perspective or orthographic camera changes nothing, as
                    // in POV-Ray.)
                    if c.projection.is_planar() && a == 0.0 {
                        return Ok(());
                    }
                    if c.projection.is_planar() && !(a > 0.0 && a < 180.0) {
                        return Err(Diagnostic::error(
                            "camera angle must be between 0 and 180 degrees",
                            angle.span,
                        ));
                    }
                    if a < 0.0 {
                        return Err(Diagnostic::error(
                            "camera angle must not be negative",
                            angle.span,
                        ));
                    }
                    c.angle = Some((a, item.span));
                    c.v_angle = match vertical {
                        Some(v) if matches!(c.projection, ir::Projection::Spherical { .. }) => {
                            Some(ev.float(v)?)
                        }
                        Some(v) => {
                            return Err(Diagnostic::error(
                                "only a spherical camera takes a second angle",
                                v.span,
                            ));
                        }
                        None => None,
                    };
                }
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::Camera(camera) => {
                        c = *camera;
                        declared = true;
                    }
                    other => return Err(expr::type_error("a camera", &other, item.span)),
                },
                _ if Self::is_transform(item) => {
                    let t = ev.transform(item)?;
                    c.transform = Some(c.transform.unwrap_or(Transform::IDENTITY).then(t));
                }
                (_, View::Unknown { values }) if item.word == "cylinder" => {
                    let [e, ..] = values else {
                        return Err(Diagnostic::error("`cylinder` needs its type, 1 to 4", item.word_span));
                    };
                    let n = ev.float(e)?;
                    if !(1.0..5.0).contains(&n) {
                        return Err(Diagnostic::error(
                            "invalid cylinder camera type: valid are types 1 to 4",
                            e.span,
                        ));
                    }
                    c.projection = ir::Projection::Cylinder {
                        kind: n as u8,
                        angle: 90.0,
                    };
                }
                (NodeKind::CameraType, _)
                    if matches!(
                        item.word.as_str(),
                        "fisheye" | "ultra_wide_angle" | "omnimax" | "panoramic" | "spherical"
                    ) =>
                {
                    c.projection = match item.word.as_str() {
                        "fisheye" => ir::Projection::Fisheye { angle: 90.0 },
                        "ultra_wide_angle" => ir::Projection::UltraWideAngle { angle: 90.0 },
                        "omnimax" => ir::Projection::Omnimax,
                        "panoramic" => ir::Projection::Panoramic,
                        _ => ir::Projection::Spherical { h: 360.0, v: 180.0 },
                    };
                }
                (NodeKind::CameraType | NodeKind::Unknown, _) if item.word == "mesh_camera" => {
                    return Err(Diagnostic::error(
                        "`mesh_camera` takes a block: `mesh_camera { RAYS DISTRIBUTION mesh { … } }`",
                        item.word_span,
                    ));
                }
                (NodeKind::CameraType | NodeKind::Unknown, _) if item.word == "user_defined" => {
                    return Err(Diagnostic::error(
                        "unsupported: the user_defined camera (this camera type is not supported by trace yet)",
                        item.word_span,
                    ));
                }
                _ => return Err(ev.unknown_item(item, "camera")),
            }
            Ok(())
        })?;
        Ok(c)
    }

    /// The value of `metallic [F]`, `fresnel [B]` or `area_illumination [B]`, or `default`
    /// without one.
    fn optional_float(&mut self, node: &Node, default: f64) -> Result<f64> {
        let value = match node.view() {
            View::Metallic { amount } => amount,
            View::Fresnel { on } | View::AreaIllumination { on } => on,
            _ => return Err(malformed(node, "a flag with an optional value")),
        };
        value.map_or(Ok(default), |e| self.float(e))
    }

    fn rgb_arg(&mut self, e: &syntax::Expr) -> Result<Rgb> {
        let v = self.eval(e)?;
        rgb(&v).ok_or_else(|| expr::type_error("a colour", &v, e.span))
    }

    fn finish(mut self) -> Result<Evaluated> {
        // Files the scene left open are written out now (POV-Ray closes them at the end).
        self.files.flush().map_err(|e| Diagnostic {
            severity: crate::diag::Severity::Error,
            message: format!("cannot write a file the scene opened with #fopen: {e}"),
            span: None,
            notes: Vec::new(),
        })?;
        let camera = match self.camera.take() {
            Some(items) => resolve_camera(&items, &mut self.warnings)?,
            None => ir::Camera::default(),
        };
        let version = self.version.unwrap_or(3.62);
        self.settings.gamma = match self.assumed_gamma {
            Some(g) => Gamma::Working(g),
            None if version >= 3.7 - 1e-9 => Gamma::Working(1.0),
            None => Gamma::Off,
        };
        self.settings.legacy_transparency = version < 3.7 - 1e-9;
        // (POV-Ray's default generator is 2 unless the scene declares a version before 3.5.)
        self.settings.noise_generator =
            self.noise_generator
                .unwrap_or(if self.version.is_some_and(|v| v < 3.5 - 1e-9) {
                    1
                } else {
                    2
                });
        Ok(Evaluated {
            scene: ir::Scene {
                camera,
                lights: self.lights,
                objects: self.objects,
                background: self.background,
                background_alpha: self.background_alpha,
                sky_sphere: self.sky_sphere,
                fogs: self.fogs,
                settings: self.settings,
            },
            warnings: self.warnings,
            debug_output: self.debug_output,
        })
    }
}

/// Resolves the camera items in POV-Ray's fixed order (§4.2): angle → look_at (with sky) →
/// orthographic rescale → transformations.
impl Evaluator<'_> {
    /// One focal blur item of a camera, with POV-Ray's checks.
    fn camera_blur(
        &mut self,
        item: &Node,
        first: &Expr,
        max: Option<&Expr>,
        c: &mut CameraItems,
    ) -> Result<()> {
        match item.word.as_str() {
            "aperture" => c.aperture = self.float(first)?,
            "focal_point" => c.focal_point = Some(self.vec3(first)?),
            "blur_samples" => {
                let a = self.float(first)?;
                if a <= 0.0 {
                    return Err(Diagnostic::error(
                        "blur_samples must be greater than 0",
                        first.span,
                    ));
                }
                c.blur_samples = match max {
                    Some(e) => {
                        let b = self.float(e)?;
                        if a > b {
                            return Err(Diagnostic::error(
                                "blur_samples: the least number of samples is above the most",
                                e.span,
                            ));
                        }
                        (a as u32, (b as u32).min(MAX_BLUR_SAMPLES))
                    }
                    None => (0, (a as u32).min(MAX_BLUR_SAMPLES)),
                };
            }
            word => {
                let v = self.float(first)?;
                let (ok, slot) = if word == "confidence" {
                    (v > 0.0 && v < 1.0, &mut c.confidence)
                } else {
                    ((0.0..=1.0).contains(&v), &mut c.variance)
                };
                if ok {
                    *slot = v;
                } else {
                    self.warn(Diagnostic::warning(
                        format!("`{word}` out of range: ignored (as POV-Ray ignores it)"),
                        first.span,
                    ));
                }
            }
        }
        if let Some(extra) = max.filter(|_| item.word != "blur_samples") {
            return Err(Diagnostic::error(
                format!("`{}` takes one value", item.word),
                extra.span,
            ));
        }
        Ok(())
    }
}

/// The most focal blur samples a pixel may take (POV-Ray has no limit; 4096 is far beyond the
/// 10 to 400 scenes use).
const MAX_BLUR_SAMPLES: u32 = 4096;

fn resolve_camera(c: &CameraItems, warnings: &mut Vec<Diagnostic>) -> Result<ir::Camera> {
    let mut direction = c.direction;
    let mut right = c.right;
    let mut up = c.up;
    let mut location = c.location;
    if let Some((angle, _)) = c.angle.filter(|_| c.projection.is_planar()) {
        // `angle` is the horizontal field of view across `right`.
        direction = direction.normalize_or_zero() * (right.length() / 2.0)
            / (angle.to_radians() / 2.0).tan();
    }
    if let Some(target) = c.look_at {
        let (dl, ul, rl) = (direction.length(), up.length(), right.length());
        // POV-Ray keeps `right` only when (up × direction)·right > 0: zero (e.g. `up z` with the
        // default direction) mirrors the image, as in POV-Ray.
        let handedness = if up.cross(direction).dot(right) > 0.0 {
            1.0
        } else {
            -1.0
        };
        let d = (target - location).normalize_or_zero();
        if d == DVec3::ZERO {
            return Err(Diagnostic::error(
                "camera look_at equals its location",
                c.span,
            ));
        }
        let r = c.sky.cross(d);
        if r.length_squared() < 1e-20 {
            warnings.push(Diagnostic::warning(
                "camera sky is parallel to the viewing direction; right kept",
                c.span,
            ));
            // POV-Ray keeps the direction of `right`, with the same handedness rule.
            let r = right.normalize_or_zero();
            direction = dl * d;
            right = handedness * rl * r;
            up = ul * d.cross(r);
        } else {
            let r = r.normalize();
            direction = dl * d;
            right = handedness * rl * r;
            up = ul * d.cross(r);
        }
    }
    if c.projection == ir::Projection::Orthographic && (!c.up_or_right_given || c.angle.is_some()) {
        let target = c.look_at.unwrap_or(DVec3::Z);
        let factor = (target - location).length() / direction.length();
        right *= factor;
        up *= factor;
    }
    if let Some(t) = c.transform {
        location = t.matrix.transform_point3(location);
        direction = t.matrix.transform_vector3(direction);
        right = t.matrix.transform_vector3(right);
        up = t.matrix.transform_vector3(up);
    }
    if direction.length_squared() == 0.0
        || right.length_squared() == 0.0
        || up.length_squared() == 0.0
    {
        return Err(Diagnostic::error(
            "camera direction, right and up must not be zero",
            c.span,
        ));
    }
    // The other projections keep their angle (POV-Ray's defaults: 90; spherical 360 by 180).
    let mut projection = c.projection;
    if let Some((a, _)) = c.angle {
        match &mut projection {
            ir::Projection::Fisheye { angle }
            | ir::Projection::UltraWideAngle { angle }
            | ir::Projection::Cylinder { angle, .. } => *angle = a,
            ir::Projection::Spherical { h, v } => (*h, *v) = (a, c.v_angle.unwrap_or(a * 0.5)),
            _ => {}
        }
    }
    // Focal blur: the sharp plane at the focal point's distance from the eye (before the
    // camera's transformations), or at the image plane's.
    let blur = (c.aperture != 0.0 && c.blur_samples.1 > 0).then(|| {
        let before = c.transform.map_or(direction, |t| {
            t.matrix.inverse().transform_vector3(direction)
        });
        let mut focal_distance = match c.focal_point {
            Some(p) => (p - c.location).length(),
            None => before.length(),
        };
        if focal_distance == 0.0 {
            focal_distance = 1.0;
        }
        ir::FocalBlur {
            aperture: c.aperture,
            min_samples: c.blur_samples.0,
            max_samples: c.blur_samples.1,
            focal_distance,
            confidence: c.confidence,
            variance: c.variance,
        }
    });
    // The mesh camera's meshes, unless a later projection replaced it. POV-Ray reads its
    // offset and direction from the location's and the direction's z, after the camera's
    // transformations.
    let mesh = c
        .mesh
        .as_ref()
        .filter(|_| projection == ir::Projection::Mesh)
        .map(|m| {
            Arc::new(ir::MeshCamera {
                offset: location.z,
                reversed: direction.z < -1e-10,
                ..m.clone()
            })
        });
    if mesh.is_some() && blur.is_some() {
        warnings.push(Diagnostic::warning(
            "focal blur is not applied to a mesh camera's rays by trace (POV-Ray blurs them)",
            c.span,
        ));
    }
    Ok(ir::Camera {
        projection,
        location,
        direction,
        right,
        up,
        blur,
        normal: c.normal.clone(),
        mesh,
    })
}

impl Evaluator<'_> {
    /// `mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh { … } … [smooth] }`, with
    /// POV-Ray's checks.
    fn mesh_camera(&mut self, node: &Node) -> Result<ir::MeshCamera> {
        let View::MeshCamera {
            rays: rays_expr,
            distribution: distribution_expr,
            max_distance,
        } = node.view()
        else {
            return Err(malformed(node, "a mesh_camera"));
        };
        let rays = self.float(rays_expr)?;
        if rays.is_nan() || rays < 1.0 {
            return Err(Diagnostic::error(
                "mesh_camera: rays per pixel may not be 0",
                rays_expr.span,
            ));
        }
        let distribution = self.float(distribution_expr)?;
        if !(0.0..4.0).contains(&distribution) {
            return Err(Diagnostic::error(
                "mesh_camera: unrecognized distribution method (0 to 3)",
                distribution_expr.span,
            ));
        }
        let (rays, distribution) = (rays.min(u32::MAX as f64) as u32, distribution as u8);
        if distribution >= 2 && rays != 1 {
            return Err(Diagnostic::error(
                "mesh_camera: rays per pixel must be 1 for distribution method 2 or 3",
                rays_expr.span,
            ));
        }
        let max_distance = match max_distance {
            Some(e) => self.float(e)?,
            None => 0.0,
        };
        let mut meshes = Vec::new();
        let mut smooth = None;
        self.each_item(&node.children, &mut |ev, item| {
            if item.kind == NodeKind::MeshCameraSmooth {
                smooth = Some(item.word_span);
                return Ok(());
            }
            if !matches!(item.word.as_str(), "mesh" | "mesh2") {
                return Err(Diagnostic::error(
                    format!("mesh_camera takes `mesh` or `mesh2`, not `{}`", item.word),
                    item.word_span,
                ));
            }
            let object = ev.object(item)?;
            match object.as_mesh() {
                Some(mesh) => meshes.push(mesh),
                None => {
                    return Err(Diagnostic::error(
                        "mesh_camera takes meshes only (this names another kind of object)",
                        item.word_span,
                    ));
                }
            }
            Ok(())
        })?;
        if let Some(span) = smooth.filter(|_| distribution != 3) {
            return Err(Diagnostic::error(
                "mesh_camera: `smooth` can only be used with distribution method 3",
                span,
            ));
        }
        if meshes.is_empty() {
            return Err(Diagnostic::error(
                "mesh_camera needs a mesh or mesh2",
                node.word_span,
            ));
        }
        if distribution == 0 && rays as usize > meshes.len() {
            return Err(Diagnostic::error(
                "mesh_camera: rays per pixel must be at most the number of meshes for distribution method 0",
                rays_expr.span,
            ));
        }
        if distribution == 3 && meshes.len() > 1 {
            self.warn(Diagnostic::warning(
                "mesh_camera: meshes after the first are ignored for distribution method 3 (as in POV-Ray)",
                node.word_span,
            ));
        }
        Ok(ir::MeshCamera {
            rays_per_pixel: rays,
            distribution,
            max_distance,
            meshes,
            smooth: smooth.is_some(),
            offset: 0.0,
            reversed: false,
        })
    }
}
