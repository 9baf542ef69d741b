//! Evaluation: syntax tree → IR.
//!
//! Runs the directives and declarations, evaluates expressions, applies POV-Ray's defaults and
//! fixed evaluation orders (camera, texture attachment), and rejects by name anything outside
//! trace's subset. Uses `syntax`, `ir` and `diag`; knows nothing of rendering.
//!
//! Two halves share one `Evaluator`: the language (`lang`: the directive reader, values,
//! expressions, macros, functions, files; its state in `lang::Language`) and the IR builder
//! (`build`: objects, shapes, materials, lights, camera, settings; its state in
//! `build::Builder`). The builder asks the language for values; the language names no IR
//! and hands each statement's blocks to the builder (this file: `Evaluator::statement`).

mod build;
mod lang;
mod value;

pub use lang::keywords;

use build::camera::CameraItems;
use build::{material, object};
use lang::{expr, files, sandbox};

use crate::diag::{Diagnostic, FileId, SourceMap, Span};
use crate::ir::{self, Rgb, Texture};
use crate::syntax::{Expr, Node, NodeKind, View};
pub use object::ObjectValue;
use std::collections::HashMap;
use value::{Value, colour5};

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
    /// Stops the load with an error when cancelled (checked every few thousand steps), for a
    /// caller that no longer wants the scene (`trace watch`, when the file is saved again).
    pub cancel: crate::cancel::Cancel,
    /// Big mesh2 lists read by earlier loads, taken from here where the text of a list is
    /// unchanged (`trace watch`: the lists of a 35 MB mesh are not read again at each save).
    pub lists: crate::syntax::bulk::ListCache,
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
            cancel: crate::cancel::Cancel::new(),
            lists: Default::default(),
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

/// Builds an object made of placed parts for `trace()`, `inside()`, `min_extent` and
/// `max_extent` (the scene layer's, handed to evaluation by the library).
pub type ObjectQueryMaker = fn(Vec<ir::Object>) -> Box<dyn ir::ObjectQuery>;

/// What evaluation needs from the layers after it, handed in by the library.
#[derive(Clone, Copy)]
pub struct Services {
    /// Makes objects that answer trace() and its kin.
    pub object_query: ObjectQueryMaker,
}

/// The files a load read besides the scene, and those it looked for in vain.
#[derive(Debug, Default)]
pub struct FilesSeen {
    /// Includes, images, meshes, fonts, data files: each once, in the order first read.
    pub read: Vec<std::path::PathBuf>,
    /// Where each name looked for and not found would stand in the scene's folder.
    pub missing: Vec<std::path::PathBuf>,
}

/// Evaluates the file `file` of `sources` into a scene. `seen` receives the files the scene
/// read and looked for, whether or not it loads.
pub fn evaluate(
    sources: &mut SourceMap,
    file: FileId,
    options: &LoadOptions,
    services: Services,
    seen: &mut FilesSeen,
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
    ev.lang.input_file_name = input_file_name;
    for (name, value) in &options.declares {
        ev.set(name.clone(), value::Value::Float(*value));
    }
    let outcome = ev.read_scene(file);
    *seen = FilesSeen {
        read: ev.sandbox.found(),
        missing: ev.sandbox.missing(),
    };
    options.lists.finish_load(outcome.is_ok());
    outcome?;
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
    /// The folders the scene may read files from.
    sandbox: sandbox::Sandbox,
    warnings: Vec<Diagnostic>,
    /// The warnings given, by message and place (each is said once).
    warned: std::collections::HashSet<(String, Option<Span>)>,
    /// POV-Ray's standard include folder, whose files draw no warnings.
    standard_includes: Option<std::path::PathBuf>,
    /// The language's state: declarations, macros, the directive reader.
    lang: lang::Language,
    /// The IR builder's state: the scene gathered so far and its defaults.
    scene: build::Builder,
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
            sandbox,
            warnings: Vec::new(),
            warned: Default::default(),
            standard_includes: standard_include_folder().and_then(|f| f.canonicalize().ok()),
            lang: lang::Language {
                assumed_gamma: None,
                noise_generator: None,
                macros: Names::default(),
                frames: Vec::new(),
                reader: Default::default(),
                bindings: Vec::new(),
                slot_shift: 0,
                include_depth: 0,
                steps: 0,
                debug_output: String::new(),
                env: Names::default(),
                version: None,
                input_file_name: String::new(),
                rand_streams: Vec::new(),
                deprecated: HashMap::new(),
                files: files::Files::default(),
            },
            scene: build::Builder {
                sky_sphere: None,
                fogs: Vec::new(),
                rainbows: Vec::new(),
                atmosphere: Vec::new(),
                settings: ir::Settings::default(),
                camera: None,
                lights: Vec::new(),
                objects: Vec::new(),
                next_medium: 0,
                reuse_given: (false, false, None),
                default_importance: None,
                next_light_group: 0,
                default_bump_size: material::DEFAULT_BUMP_SIZE,
                background: Rgb::ZERO,
                background_alpha: 0.0,
                default_texture: Texture::default(),
                default_interior: Default::default(),
                finishes: HashMap::new(),
                interiors: HashMap::new(),
                pictures: HashMap::new(),
                texels: HashMap::new(),
                mesh_files: HashMap::new(),
                fonts: HashMap::new(),
                charset: crate::font::Charset::Ascii,
                object_query: services.object_query,
                next_object_id: 0,
                queries: HashMap::new(),
            },
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
                match keywords::nearest(word, self.lang.env.keys().map(String::as_str)) {
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
                        NodeKind::Texture => ev.scene.default_texture = ev.texture(child)?,
                        NodeKind::Pigment => {
                            let base = ev.scene.default_texture.pigment.clone();
                            ev.scene.default_texture.pigment = ev.pigment(child, base)?;
                        }
                        NodeKind::Finish => {
                            let base = std::sync::Arc::clone(&ev.scene.default_texture.finish);
                            ev.scene.default_texture.finish =
                                ev.shared_finish_block(child, &base)?;
                        }
                        // A default normal of `bump_size` alone: the amount of the normals
                        // made after it (POV-Ray copies the default normal into each).
                        NodeKind::Normal
                            if child.children.iter().all(|c| c.kind == NodeKind::BumpSize)
                                && !child.children.is_empty() =>
                        {
                            for c in &child.children {
                                if let View::BumpSize(size) = c.view() {
                                    ev.scene.default_bump_size = f64::from(ev.float(size)? as f32);
                                }
                            }
                        }
                        NodeKind::Normal => {
                            let base = ev.scene.default_texture.normal.take();
                            ev.scene.default_texture.normal =
                                Some(Box::new(ev.normal(child, base)?));
                        }
                        NodeKind::ObjectRadiosity => {
                            let given = ev.radiosity_importance(child, "a default radiosity")?;
                            if given.is_some() {
                                ev.scene.default_importance = given;
                            }
                        }
                        _ => return Err(ev.unknown_item(child, "#default")),
                    }
                    Ok(())
                })?;
            }
            (NodeKind::Camera, _) => {
                let items = self.camera_items(node, CameraItems::default())?;
                self.scene.camera = Some(items);
            }
            (NodeKind::LightSource, _) => {
                let (light, looks) = self.light(node)?;
                self.scene.lights.push(light);
                if let Some(object) = looks {
                    self.place(object, node.word_span)?;
                }
            }
            (NodeKind::Fog, _) => {
                let fog = self.fog(node)?;
                self.scene.fogs.push(fog);
            }
            (NodeKind::Media, _) => {
                let media = self.media(node)?;
                self.scene.atmosphere.push(media);
            }
            (NodeKind::Rainbow, _) => {
                let rainbow = self.rainbow_items(node)?;
                self.scene.rainbows.extend(rainbow.seen());
            }
            (_, View::Background(value)) => {
                let v = self.eval(value)?;
                let c = colour5(&v).ok_or_else(|| expr::type_error("a colour", &v, value.span))?;
                // Without alpha output POV-Ray stores rgb·(1 − transmit) and ignores filter.
                self.scene.background = Rgb::new(c[0], c[1], c[2]) * (1.0 - c[4]);
                self.scene.background_alpha = 1.0 - c[4];
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
            (NodeKind::SkySphere, _) => self.scene.sky_sphere = Some(self.sky_sphere(node)?),
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
}
