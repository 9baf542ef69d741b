//! Evaluation: syntax tree → IR.
//!
//! Runs the directives and declarations, evaluates expressions, applies POV-Ray's defaults and
//! fixed evaluation orders (camera, texture attachment), and rejects by name anything outside
//! trace's subset. Uses `syntax`, `ir` and `diag`; knows nothing of rendering.

mod expr;
mod object;
mod transform;
mod unsupported;
mod value;

use crate::diag::{Diagnostic, FileId, SourceMap, Span};
use crate::ir::{self, Gamma, Rgb, Texture, Transform};
use crate::syntax::{self, Node, NodeKind};
use glam::DVec3;
pub use object::ObjectValue;
use std::collections::HashMap;
use value::{Value, colour5, rgb, to_colour};

type Result<T> = std::result::Result<T, Diagnostic>;

/// What evaluation needs from outside the scene file.
#[derive(Clone, Debug)]
pub struct LoadOptions {
    /// Image width in pixels (`image_width` in expressions).
    pub width: u32,
    /// Image height in pixels (`image_height`).
    pub height: u32,
}

impl Default for LoadOptions {
    fn default() -> LoadOptions {
        LoadOptions {
            width: 800,
            height: 600,
        }
    }
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
    up_or_right_given: bool,
    transform: Option<Transform>,
    span: Span,
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
            up_or_right_given: false,
            transform: None,
            span: Span::default(),
        }
    }
}

/// The result of evaluating a scene: the IR plus the warnings met on the way.
pub struct Evaluated {
    /// The scene.
    pub scene: ir::Scene,
    /// Warnings, in source order.
    pub warnings: Vec<Diagnostic>,
}

/// Evaluates the file `file` of `sources` into a scene.
pub fn evaluate(sources: &SourceMap, file: FileId, options: &LoadOptions) -> Result<Evaluated> {
    let nodes = syntax::parse_scene(&sources.file(file).text, file)?;
    let mut ev = Evaluator::new(options);
    for node in &nodes {
        ev.statement(node)?;
    }
    ev.finish()
}

/// The evaluation state: declarations, defaults and the scene gathered so far.
pub(crate) struct Evaluator<'a> {
    options: &'a LoadOptions,
    env: HashMap<String, Value>,
    version: Option<f64>,
    assumed_gamma: Option<f64>,
    settings: ir::Settings,
    camera: Option<CameraItems>,
    lights: Vec<ir::Light>,
    objects: Vec<ir::Object>,
    background: Rgb,
    default_texture: Texture,
    warnings: Vec<Diagnostic>,
}

impl<'a> Evaluator<'a> {
    fn new(options: &'a LoadOptions) -> Evaluator<'a> {
        Evaluator {
            options,
            env: HashMap::new(),
            version: None,
            assumed_gamma: None,
            settings: ir::Settings::default(),
            camera: None,
            lights: Vec::new(),
            objects: Vec::new(),
            background: Rgb::ZERO,
            default_texture: Texture::default(),
            warnings: Vec::new(),
        }
    }

    fn warn(&mut self, d: Diagnostic) {
        self.warnings.push(d);
    }

    /// The error for a word that is not valid where it stands.
    fn unknown_word(&self, word: &str, span: Span) -> Diagnostic {
        match unsupported::reason(word) {
            Some(reason) => Diagnostic::error(format!("unsupported: `{word}` ({reason})"), span),
            None => Diagnostic::error(format!("unknown identifier `{word}`"), span),
        }
    }

    /// The error for an unknown item inside a block.
    fn unknown_item(&self, node: &Node, context: &str) -> Diagnostic {
        match unsupported::reason(&node.word) {
            Some(_) => self.unknown_word(&node.word, node.word_span),
            None if self.env.contains_key(&node.word) => Diagnostic::error(
                format!(
                    "`{}` cannot stand here in {context} (wrap it, e.g. `texture {{ {} }}`)",
                    node.word, node.word
                ),
                node.word_span,
            ),
            None => Diagnostic::error(
                format!("unknown keyword `{}` in {context}", node.word),
                node.word_span,
            ),
        }
    }

    fn lookup(&self, ident: &Node) -> Result<Value> {
        self.env
            .get(&ident.word)
            .cloned()
            .ok_or_else(|| self.unknown_word(&ident.word, ident.span))
    }

    fn statement(&mut self, node: &Node) -> Result<()> {
        match node.kind {
            NodeKind::Version => {
                let v = self.float(&node.args[0])?;
                self.version = Some(v);
            }
            NodeKind::Declare | NodeKind::Local => {
                let name = node.children[0].word.clone();
                let value = match node.children.get(1) {
                    Some(item) => self.item_value(item)?,
                    None => self.eval(&node.args[0])?,
                };
                self.env.insert(name, value);
            }
            NodeKind::Default => {
                for child in &node.children {
                    match child.kind {
                        NodeKind::Texture => self.default_texture = self.texture(child)?,
                        NodeKind::Pigment => {
                            let base = self.default_texture.pigment.clone();
                            self.default_texture.pigment = self.pigment(child, base)?;
                        }
                        NodeKind::Finish => {
                            let base = self.default_texture.finish.clone();
                            self.default_texture.finish = self.finish_block(child, base)?;
                        }
                        _ => return Err(self.unknown_item(child, "#default")),
                    }
                }
            }
            NodeKind::UnknownDirective => {
                let span = Span {
                    start: node.span.start,
                    ..node.word_span
                };
                return Err(match unsupported::reason(&node.word) {
                    Some(reason) => {
                        Diagnostic::error(format!("unsupported: `#{}` ({reason})", node.word), span)
                    }
                    None => Diagnostic::error(format!("unknown directive `#{}`", node.word), span),
                });
            }
            NodeKind::Camera => {
                let items = self.camera_items(node, CameraItems::default())?;
                self.camera = Some(items);
            }
            NodeKind::LightSource => {
                let light = self.light(node)?;
                self.lights.push(light);
            }
            NodeKind::Background => {
                let v = self.eval(&node.args[0])?;
                let c = colour5(&v)
                    .ok_or_else(|| expr::type_error("a colour", &v, node.args[0].span))?;
                // Without alpha output POV-Ray stores rgb·(1 − transmit) and ignores filter.
                self.background = Rgb::new(c[0], c[1], c[2]) * (1.0 - c[4]);
            }
            NodeKind::GlobalSettings => self.global_settings(node)?,
            _ if object::is_object(node.kind) => {
                let object = self.object(node)?;
                self.place(object);
            }
            NodeKind::Unknown => {
                return Err(match unsupported::reason(&node.word) {
                    Some(_) => self.unknown_word(&node.word, node.word_span),
                    None => Diagnostic::error(
                        format!(
                            "expected a statement (an object, camera, light_source, #declare …), found `{}`",
                            node.word
                        ),
                        node.word_span,
                    ),
                });
            }
            _ => unreachable!("{:?} is not a statement", node.kind),
        }
        Ok(())
    }

    /// The value of a declared item (`#declare X = sphere { … }` and the like).
    fn item_value(&mut self, node: &Node) -> Result<Value> {
        Ok(match node.kind {
            _ if object::is_object(node.kind) => Value::Object(Box::new(self.object(node)?)),
            NodeKind::Pigment => {
                let base = self.default_texture.pigment.clone();
                Value::Pigment(self.pigment(node, base)?)
            }
            NodeKind::Finish => {
                let base = self.default_texture.finish.clone();
                Value::Finish(self.finish_block(node, base)?)
            }
            NodeKind::Texture => Value::Texture(self.texture(node)?),
            NodeKind::Transform => Value::Transform(self.transform(node)?),
            NodeKind::Camera => {
                Value::Camera(Box::new(self.camera_items(node, CameraItems::default())?))
            }
            _ => unreachable!("{:?} is not a declarable item", node.kind),
        })
    }

    fn global_settings(&mut self, node: &Node) -> Result<()> {
        for item in &node.children {
            match item.kind {
                NodeKind::AssumedGamma => {
                    let g = self.float(&item.args[0])?;
                    if self.assumed_gamma.is_some() {
                        self.warn(Diagnostic::warning(
                            "a second assumed_gamma is ignored (as in POV-Ray)",
                            item.span,
                        ));
                    } else if g <= 0.0 {
                        return Err(Diagnostic::error(
                            "assumed_gamma must be positive",
                            item.args[0].span,
                        ));
                    } else {
                        self.assumed_gamma = Some(g);
                    }
                }
                NodeKind::MaxTraceLevel => {
                    let n = self.float(&item.args[0])?;
                    self.settings.max_trace_level = (n as i64).clamp(1, 256) as u32;
                }
                NodeKind::AdcBailout => self.settings.adc_bailout = self.float(&item.args[0])?,
                NodeKind::AmbientLight => {
                    let v = self.eval(&item.args[0])?;
                    self.settings.ambient_light = rgb(&v)
                        .ok_or_else(|| expr::type_error("a colour", &v, item.args[0].span))?;
                }
                _ => return Err(self.unknown_item(item, "global_settings")),
            }
        }
        Ok(())
    }

    fn light(&mut self, node: &Node) -> Result<ir::Light> {
        let mut position = self.vec3(&node.args[0])?;
        // A light without a colour is black (POV-Ray accepts it silently).
        let colour = match node.args.get(1) {
            Some(e) => {
                let v = self.eval(e)?;
                rgb(&v).ok_or_else(|| expr::type_error("a colour", &v, e.span))?
            }
            None => Rgb::ZERO,
        };
        for item in &node.children {
            if Self::is_transform(item) {
                position = self.transform(item)?.matrix.transform_point3(position);
            } else {
                return Err(self.unknown_item(item, "light_source"));
            }
        }
        Ok(ir::Light { position, colour })
    }

    fn camera_items(&mut self, node: &Node, mut c: CameraItems) -> Result<CameraItems> {
        c.span = node.word_span;
        for item in &node.children {
            match item.kind {
                NodeKind::Perspective => c.projection = ir::Projection::Perspective,
                NodeKind::Orthographic => c.projection = ir::Projection::Orthographic,
                NodeKind::Location => c.location = self.vec3(&item.args[0])?,
                NodeKind::LookAt => c.look_at = Some(self.vec3(&item.args[0])?),
                NodeKind::Direction => c.direction = self.vec3(&item.args[0])?,
                NodeKind::Up => {
                    c.up = self.vec3(&item.args[0])?;
                    c.up_or_right_given = true;
                }
                NodeKind::Right => {
                    c.right = self.vec3(&item.args[0])?;
                    c.up_or_right_given = true;
                }
                NodeKind::Sky => c.sky = self.vec3(&item.args[0])?,
                NodeKind::Angle => {
                    let a = self.float(&item.args[0])?;
                    if !(a > 0.0 && a < 180.0) {
                        return Err(Diagnostic::error(
                            "camera angle must be between 0 and 180 degrees",
                            item.args[0].span,
                        ));
                    }
                    c.angle = Some((a, item.span));
                }
                NodeKind::IdentRef => match self.lookup(item)? {
                    Value::Camera(declared) => c = *declared,
                    other => return Err(expr::type_error("a camera", &other, item.span)),
                },
                _ if Self::is_transform(item) => {
                    let t = self.transform(item)?;
                    c.transform = Some(c.transform.unwrap_or(Transform::IDENTITY).then(t));
                }
                _ => return Err(self.unknown_item(item, "camera")),
            }
        }
        Ok(c)
    }

    /// `texture { [Name] pigment {…} finish {…} transforms }`, starting from the default texture.
    fn texture(&mut self, node: &Node) -> Result<Texture> {
        let mut texture = self.default_texture.clone();
        for item in &node.children {
            match item.kind {
                NodeKind::IdentRef => match self.lookup(item)? {
                    Value::Texture(t) => texture = t,
                    other => return Err(expr::type_error("a texture", &other, item.span)),
                },
                NodeKind::Pigment => {
                    texture.pigment = self.pigment(item, texture.pigment.clone())?
                }
                NodeKind::Finish => {
                    texture.finish = self.finish_block(item, texture.finish.clone())?
                }
                _ if Self::is_transform(item) => {
                    let t = self.transform(item)?;
                    texture.transform =
                        Some(texture.transform.unwrap_or(Transform::IDENTITY).then(t));
                }
                _ => return Err(self.unknown_item(item, "texture")),
            }
        }
        Ok(texture)
    }

    /// `pigment { [colour | Name] transforms }`.
    fn pigment(&mut self, node: &Node, mut pigment: ir::Pigment) -> Result<ir::Pigment> {
        if let Some(e) = node.args.first() {
            let v = self.eval(e)?;
            pigment = match v {
                Value::Pigment(p) => p,
                other => match colour5(&other) {
                    Some(c) => ir::Pigment::Solid(to_colour(c)),
                    None => return Err(expr::type_error("a colour or pigment", &other, e.span)),
                },
            };
        }
        for item in &node.children {
            if Self::is_transform(item) {
                self.transform(item)?;
            } else {
                return Err(self.unknown_item(item, "pigment"));
            }
        }
        Ok(pigment)
    }

    /// `finish { [Name] items }`, modifying `finish`.
    fn finish_block(&mut self, node: &Node, mut f: ir::Finish) -> Result<ir::Finish> {
        for item in &node.children {
            let arg = |i: usize| &item.args[i];
            match item.kind {
                NodeKind::IdentRef => match self.lookup(item)? {
                    Value::Finish(declared) => f = declared,
                    other => return Err(expr::type_error("a finish", &other, item.span)),
                },
                NodeKind::Ambient => f.ambient = self.rgb_arg(arg(0))?,
                NodeKind::Emission => f.emission = self.rgb_arg(arg(0))?,
                NodeKind::Diffuse | NodeKind::Phong | NodeKind::Specular
                    if item.children.iter().any(|c| c.kind == NodeKind::Albedo) =>
                {
                    return Err(self.unknown_word("albedo", item.children[0].word_span));
                }
                NodeKind::Diffuse => {
                    f.diffuse = self.float(arg(0))?;
                    if let Some(back) = item.args.get(1) {
                        f.diffuse_back = self.float(back)?;
                        if f.diffuse_back != 0.0 {
                            return Err(Diagnostic::error(
                                "unsupported: back-side `diffuse` (not supported by trace yet)",
                                back.span,
                            ));
                        }
                    }
                }
                NodeKind::Brilliance => f.brilliance = self.float(arg(0))?,
                NodeKind::Phong => f.phong = self.float(arg(0))?,
                NodeKind::PhongSize => f.phong_size = self.float(arg(0))?,
                NodeKind::Specular => f.specular = self.float(arg(0))?,
                NodeKind::Roughness => {
                    let r = self.float(arg(0))?;
                    if r == 0.0 {
                        self.warn(Diagnostic::warning(
                            "zero roughness: using 0.0001 instead",
                            item.span,
                        ));
                    }
                    f.roughness = if r == 0.0 { 1e-4 } else { r };
                }
                NodeKind::Metallic => f.metallic = self.optional_float(item, 1.0)?,
                NodeKind::ConserveEnergy => f.conserve_energy = true,
                NodeKind::Reflection => self.reflection(item, &mut f.reflection)?,
                _ => return Err(self.unknown_item(item, "finish")),
            }
        }
        Ok(f)
    }

    fn reflection(&mut self, node: &Node, r: &mut ir::Reflection) -> Result<()> {
        let first = self.rgb_arg(&node.args[0])?;
        match node.args.get(1) {
            Some(second) => {
                r.min = first;
                r.max = self.rgb_arg(second)?;
            }
            None => {
                r.min = first;
                r.max = first;
            }
        }
        let single = node.args.len() == 1;
        for item in &node.children {
            match item.kind {
                NodeKind::Falloff => r.falloff = self.float(&item.args[0])?,
                NodeKind::Exponent => r.exponent = self.float(&item.args[0])?,
                NodeKind::Metallic => r.metallic = self.optional_float(item, 1.0)?,
                NodeKind::Fresnel => r.fresnel = self.optional_float(item, 1.0)? != 0.0,
                _ => return Err(self.unknown_item(item, "reflection")),
            }
        }
        // With `fresnel` and a single colour, POV-Ray resets the minimum to 0.
        if r.fresnel && single {
            r.min = Rgb::ZERO;
        }
        Ok(())
    }

    fn optional_float(&mut self, node: &Node, default: f64) -> Result<f64> {
        match node.args.first() {
            Some(e) => self.float(e),
            None => Ok(default),
        }
    }

    fn rgb_arg(&mut self, e: &syntax::Expr) -> Result<Rgb> {
        let v = self.eval(e)?;
        rgb(&v).ok_or_else(|| expr::type_error("a colour", &v, e.span))
    }

    fn finish(mut self) -> Result<Evaluated> {
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
        Ok(Evaluated {
            scene: ir::Scene {
                camera,
                lights: self.lights,
                objects: self.objects,
                background: self.background,
                settings: self.settings,
            },
            warnings: self.warnings,
        })
    }
}

/// Resolves the camera items in POV-Ray's fixed order (§4.2): angle → look_at (with sky) →
/// orthographic rescale → transformations.
fn resolve_camera(c: &CameraItems, warnings: &mut Vec<Diagnostic>) -> Result<ir::Camera> {
    let mut direction = c.direction;
    let mut right = c.right;
    let mut up = c.up;
    let mut location = c.location;
    if let Some((angle, _)) = c.angle {
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
            direction = dl * d;
            up = ul * d.cross(right.normalize_or_zero()).normalize_or_zero();
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
    Ok(ir::Camera {
        projection: c.projection,
        location,
        direction,
        right,
        up,
    })
}
