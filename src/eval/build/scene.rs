//! The scene's own statements: global settings, fog, sky sphere, `#default`, and the IR
//! handed on at the end (with POV-Ray's version-dependent settings).

use crate::diag::{Diagnostic, Span};
use crate::eval::build::camera::{CameraItems, resolve_camera};
use crate::eval::build::object;
use crate::eval::lang::expr;
use crate::eval::value::{self, Value, colour5, rgb};
use crate::eval::{Evaluated, Evaluator, Result, malformed, modifier_value};
use crate::ir::{self, Gamma, Rgb};
use crate::syntax::{self, Expr, Node, NodeKind, View};
use glam::DVec3;
use std::collections::HashMap;
use std::sync::Arc;

/// A key of the bits of `values` (equal values, equal keys).
pub(in crate::eval) fn bits_key(values: impl IntoIterator<Item = f64>) -> u64 {
    values.into_iter().fold(0u64, |h, v| {
        (h ^ v.to_bits())
            .wrapping_mul(0x9E37_79B9_7F4A_7C15)
            .rotate_left(29)
    })
}

impl Evaluator<'_> {
    /// `finish`, shared with an equal finish made before if there is one.
    pub(in crate::eval) fn shared_finish(
        &mut self,
        finish: ir::Finish,
    ) -> std::sync::Arc<ir::Finish> {
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
        share(&mut self.scene.finishes, key, finish)
    }

    /// `interior`, shared with an equal interior made before if there is one.
    pub(in crate::eval) fn shared_interior(
        &mut self,
        interior: ir::Interior,
    ) -> std::sync::Arc<ir::Interior> {
        let key = interior.key();
        share(&mut self.scene.interiors, key, interior)
    }
}

/// The value kept under `key` if it equals `value`, else `value` (kept if the key is free).
pub(in crate::eval) fn share<T: PartialEq>(
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
/// A fog's items as written (a declared fog keeps them all, fog_alt of a constant fog too,
/// since a fog made from it may turn into ground fog).
#[derive(Clone, Debug)]
pub(in crate::eval) struct FogItems {
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

/// A rainbow as POV-Ray holds it once read. A declared rainbow is held so, and a rainbow that
/// starts from one reads its items over it and is finished again, as POV-Ray does (which
/// converts its angle and width to radians a second time).
#[derive(Clone, Debug)]
pub(in crate::eval) struct RainbowItems {
    angle: f64,
    width: f64,
    distance: f64,
    jitter: f64,
    arc_angle: f64,
    falloff_angle: f64,
    antisolar: DVec3,
    up: DVec3,
    right: DVec3,
    colours: Option<ir::ColourMap>,
}

impl Default for RainbowItems {
    /// POV-Ray's defaults: no colours, no width, distance 1e7, arc and falloff 180
    /// (unconverted), up y.
    fn default() -> RainbowItems {
        RainbowItems {
            angle: 0.0,
            width: 0.0,
            distance: 1.0e7,
            jitter: 0.0,
            arc_angle: 180.0,
            falloff_angle: 180.0,
            antisolar: DVec3::ZERO,
            up: DVec3::Y,
            right: DVec3::X,
            colours: None,
        }
    }
}

impl RainbowItems {
    /// The rainbow as the renderer sees it, if it can be seen (POV-Ray skips one without a
    /// colour map, a distance or a width).
    pub(in crate::eval) fn seen(self) -> Option<ir::Rainbow> {
        if self.distance == 0.0 || self.width == 0.0 {
            return None;
        }
        Some(ir::Rainbow {
            angle: self.angle,
            width: self.width,
            distance: self.distance,
            jitter: self.jitter,
            arc_angle: self.arc_angle,
            falloff_angle: self.falloff_angle,
            antisolar: self.antisolar,
            up: self.up,
            right: self.right,
            colours: self.colours?,
        })
    }
}

impl Evaluator<'_> {
    /// `rainbow { [Name] items }`, read and finished as POV-Ray's Parse_Rainbow does: the
    /// falloff angle defaults to the arc angle when only that is given, both are halved and
    /// converted to radians, up is made perpendicular to the direction, and the angle moves
    /// to the ring's inner edge.
    pub(in crate::eval) fn rainbow_items(&mut self, node: &Node) -> Result<RainbowItems> {
        let mut r = RainbowItems::default();
        let (mut falloff_given, mut arc_given) = (false, false);
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::Rainbow(declared) => {
                        ev.warn(Diagnostic::warning(
                            "POV-Ray 3.7 converts a copied rainbow's angle and width to radians \
                             again (its ring shrinks to the centre, as here) and frees its colours \
                             before rendering (it draws the ring black, then crashes)",
                            item.span,
                        ));
                        r = *declared;
                    }
                    other => return Err(expr::type_error("a rainbow", &other, item.span)),
                },
                (_, View::RainbowSetting(value)) => {
                    let v = ev.float(value)?;
                    let half_angle = |what: &str| {
                        if (0.0..=360.0).contains(&v) {
                            Ok(v * (std::f64::consts::PI / 360.0))
                        } else {
                            Err(Diagnostic::error(
                                format!("a rainbow's {what} must be from 0 to 360 degrees"),
                                value.span,
                            ))
                        }
                    };
                    match item.word.as_str() {
                        "angle" => r.angle = v,
                        "width" => r.width = v,
                        "distance" => r.distance = v,
                        "jitter" => r.jitter = v,
                        "falloff_angle" => {
                            r.falloff_angle = half_angle("falloff_angle")?;
                            falloff_given = true;
                        }
                        _ => {
                            r.arc_angle = half_angle("arc_angle")?;
                            arc_given = true;
                        }
                    }
                }
                (_, View::Direction(value)) => r.antisolar = ev.vec3(value)?,
                (_, View::Up(value)) => r.up = ev.vec3(value)?,
                (NodeKind::ColourMap, _) => r.colours = Some(ev.colour_map(item)?),
                _ => return Err(ev.unknown_item(item, "rainbow")),
            }
            Ok(())
        })?;
        if arc_given && !falloff_given {
            r.falloff_angle = r.arc_angle;
        }
        let fail = |message: &str| Err(Diagnostic::error(message.to_string(), node.word_span));
        if r.arc_angle < r.falloff_angle {
            return fail("a rainbow's arc_angle is smaller than its falloff_angle");
        }
        const EPSILON: f64 = 1e-10;
        if r.antisolar.length_squared() < EPSILON {
            return fail("a rainbow's direction vector is zero (or missing)");
        }
        if r.up.length_squared() < EPSILON {
            return fail("a rainbow's up vector is zero");
        }
        r.antisolar = r.antisolar.normalize();
        r.up = r.up.normalize();
        if (1.0 - r.up.dot(r.antisolar).abs()).abs() < EPSILON {
            return fail("a rainbow's up and direction vectors are parallel");
        }
        r.right = r.up.cross(r.antisolar).normalize();
        r.up = r.antisolar.cross(r.right).normalize();
        r.angle = (r.angle - 0.5 * r.width).to_radians();
        r.width = r.width.to_radians();
        Ok(r)
    }

    /// `sky_sphere { [Name] pigment {…}… [emission C] transforms }`. The transformations move
    /// the whole sky, pigments given after them included (as in POV-Ray).
    pub(in crate::eval) fn sky_sphere(&mut self, node: &Node) -> Result<ir::SkySphere> {
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
    pub(in crate::eval) fn item_value(&mut self, node: &Node) -> Result<Value> {
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
                let base = self.scene.default_texture.pigment.clone();
                Value::Pigment(Box::new(self.pigment(node, base)?))
            }
            NodeKind::Normal => Value::Normal(Box::new(self.normal(node, None)?)),
            NodeKind::SkySphere => Value::SkySphere(self.sky_sphere(node)?),
            NodeKind::Finish => {
                let base = (*self.scene.default_texture.finish).clone();
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
            NodeKind::Rainbow => Value::Rainbow(Box::new(self.rainbow_items(node)?)),
            NodeKind::Media => Value::Media(Box::new(self.media(node)?)),
            NodeKind::Density => Value::Pigment(Box::new(self.density(node)?)),
            NodeKind::Transform => Value::Transform(Box::new(self.transform(node)?)),
            NodeKind::Camera => {
                Value::Camera(Box::new(self.camera_items(node, CameraItems::default())?))
            }
            _ => return Err(self.unknown_item(node, "a declaration")),
        })
    }

    /// `max_trace_level N`.
    pub(in crate::eval) fn max_trace_level(&mut self, level: &Expr) -> Result<()> {
        let n = self.float(level)?;
        self.scene.settings.max_trace_level = (n as i64).clamp(1, 256) as u32;
        Ok(())
    }

    /// `max_intersections N`: no longer needed, ignored with a warning as in POV-Ray 3.7.
    pub(in crate::eval) fn max_intersections(&mut self, item: &Node, count: &Expr) -> Result<()> {
        self.float(count)?;
        self.warn(Diagnostic::warning(
            "`max_intersections` is no longer needed and has no effect (POV-Ray 3.7 says so too)",
            item.word_span,
        ));
        Ok(())
    }

    /// `radiosity { … }` in global_settings: turns radiosity on and sets what it gives, as
    /// POV-Ray 3.7's parser reads it (each value checked by its rules).
    pub(in crate::eval) fn radiosity(&mut self, node: &Node) -> Result<()> {
        let mut r = self.scene.settings.radiosity.take().unwrap_or_default();
        self.scene.reuse_given.2 = Some(node.word_span);
        self.each_item(&node.children, &mut |ev, item| {
            let View::RadiositySetting { value, second } = item.view() else {
                return Err(ev.unknown_item(item, "radiosity"));
            };
            let word = item.word.as_str();
            if second.is_some() && !matches!(word, "count" | "nearest_count") {
                return Err(Diagnostic::error(
                    format!("`{word}` takes one value"),
                    item.span,
                ));
            }
            if matches!(word, "load_file" | "save_file") {
                ev.eval(value)?;
                ev.warn(Diagnostic::warning(
                    format!(
                        "`{word}` is ignored here (POV-Ray 3.7 takes it from the command line only, and says so too)"
                    ),
                    item.word_span,
                ));
                return Ok(());
            }
            if word == "subsurface" {
                return Err(Diagnostic::error(
                    "unsupported: `subsurface` (subsurface scattering is outside trace's subset)",
                    item.word_span,
                ));
            }
            let v = ev.float(value)?;
            let bad = |rule: &str| Err(Diagnostic::error(format!("radiosity {rule}"), value.span));
            match word {
                "adc_bailout" if v <= 0.0 => return bad("adc_bailout must be positive"),
                "adc_bailout" => r.adc_bailout = v,
                "always_sample" => r.always_sample = v as i64 != 0,
                "brightness" if v <= 0.0 => return bad("brightness must be positive"),
                "brightness" => r.brightness = v,
                "count" => {
                    if (v as i64) <= 0 {
                        return bad("count must be positive");
                    }
                    r.count = (v as i64).min(i64::from(u32::MAX)) as u32;
                    let pool = match second {
                        Some(e) => ev.float(e)? as i64,
                        None => i64::from(r.count.max(1600)),
                    };
                    if pool < i64::from(r.count) {
                        return Err(Diagnostic::error(
                            "radiosity count cannot be more than its directions (count's second value)",
                            second.map_or(value.span, |e| e.span),
                        ));
                    }
                    // (The pool is built in memory, 24 bytes a direction: 24 MiB at most.)
                    if pool > 1 << 20 {
                        return Err(Diagnostic::error(
                            "unsupported: more than 1048576 radiosity directions",
                            second.map_or(value.span, |e| e.span),
                        ));
                    }
                    r.directions = pool as u32;
                }
                "error_bound" if v <= 0.0 => return bad("error_bound must be positive"),
                "error_bound" => r.error_bound = v,
                "gray_threshold" if !(0.0..=1.0).contains(&v) => {
                    return bad("gray_threshold must be from 0 to 1");
                }
                "gray_threshold" => r.gray_threshold = v,
                "low_error_factor" if v <= 0.0 => return bad("low_error_factor must be positive"),
                "low_error_factor" => r.low_error_factor = v,
                "max_sample" => r.max_sample = v,
                "maximum_reuse" if v <= 0.0 => return bad("maximum_reuse must be positive"),
                "maximum_reuse" => {
                    r.maximum_reuse = v;
                    ev.scene.reuse_given.1 = true;
                }
                "minimum_reuse" if v < 0.0 => return bad("minimum_reuse cannot be negative"),
                "minimum_reuse" => {
                    r.minimum_reuse = v;
                    ev.scene.reuse_given.0 = true;
                }
                "nearest_count" => {
                    let n = v as i64;
                    if !(1..=20).contains(&n) {
                        return bad("nearest_count must be from 1 to 20");
                    }
                    r.nearest_count = n as u32;
                    let adaptive = match second {
                        Some(e) => ev.float(e)? as i64,
                        None => 0,
                    };
                    if adaptive < 0 || adaptive >= n {
                        return Err(Diagnostic::error(
                            "radiosity nearest_count's second value (the adaptive pretrace's) must be at least 0 and less than the first",
                            second.map_or(value.span, |e| e.span),
                        ));
                    }
                    r.pretrace_count = adaptive as u32;
                }
                "recursion_limit" => {
                    let n = v as i64;
                    if !(1..=20).contains(&n) {
                        return bad("recursion_limit must be from 1 to 20");
                    }
                    r.recursion_limit = n as u32;
                }
                "media" => r.media = v as i64 != 0,
                "normal" => r.normal = v as i64 != 0,
                "pretrace_start" if v <= 0.0 || v > 1.0 => {
                    return bad("pretrace_start must be above 0 and at most 1");
                }
                "pretrace_start" => r.pretrace_start = v,
                "pretrace_end" if v <= 0.0 || v > 1.0 => {
                    return bad("pretrace_end must be above 0 and at most 1");
                }
                "pretrace_end" => r.pretrace_end = v,
                _ => return Err(ev.unknown_item(item, "radiosity")),
            }
            Ok(())
        })?;
        self.scene.settings.radiosity = Some(r);
        Ok(())
    }

    /// POV-Ray's checks of the radiosity settings once the whole scene is read: the
    /// pretrace's passes in order, and a `minimum_reuse` not above half `maximum_reuse` (the
    /// one not given moves, with a warning).
    fn radiosity_checked(&mut self, version: f64) -> Result<()> {
        let (min_given, max_given, span) = self.scene.reuse_given;
        let span = span.unwrap_or_default();
        let Some(r) = &mut self.scene.settings.radiosity else {
            return Ok(());
        };
        r.keeps_ambient = version < 3.7 - 1e-9;
        r.default_importance = self.scene.default_importance.unwrap_or(1.0);
        if r.pretrace_end > r.pretrace_start {
            return Err(Diagnostic::error(
                "radiosity pretrace_end must not be above pretrace_start",
                span,
            ));
        }
        if r.minimum_reuse > r.maximum_reuse * 0.5 {
            let message = if !min_given {
                r.minimum_reuse = r.maximum_reuse * 0.5;
                format!(
                    "radiosity maximum_reuse should be well above minimum_reuse: minimum_reuse lowered to {} from its default (as POV-Ray does)",
                    r.minimum_reuse
                )
            } else if !max_given {
                r.maximum_reuse = r.minimum_reuse * 2.0;
                format!(
                    "radiosity maximum_reuse should be well above minimum_reuse: maximum_reuse raised to {} from its default (as POV-Ray does)",
                    r.maximum_reuse
                )
            } else if r.minimum_reuse >= r.maximum_reuse {
                return Err(Diagnostic::error(
                    "radiosity maximum_reuse must be above minimum_reuse",
                    span,
                ));
            } else {
                "radiosity maximum_reuse should be well above minimum_reuse".to_string()
            };
            self.warn(Diagnostic::warning(message, span));
        }
        Ok(())
    }

    pub(in crate::eval) fn global_settings(&mut self, node: &Node) -> Result<()> {
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                // (`#default { … }` may stand here too, as POV-Ray reads it anywhere.)
                (NodeKind::Default, _) => ev.statement(item)?,
                (NodeKind::Charset, _) => {
                    ev.scene.charset = if item.word.ends_with("ascii") {
                        crate::font::Charset::Ascii
                    } else {
                        crate::font::Charset::Utf8
                    };
                }
                (_, View::AssumedGamma(value)) => {
                    let g = ev.float(value)?;
                    if ev.lang.assumed_gamma.is_some() {
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
                        ev.lang.assumed_gamma = Some(g);
                    }
                }
                (NodeKind::Radiosity, _) => ev.radiosity(item)?,
                (_, View::MaxTraceLevel(level)) => ev.max_trace_level(level)?,
                (_, View::MaxIntersections(count)) => ev.max_intersections(item, count)?,
                (_, View::AdcBailout(value)) => ev.scene.settings.adc_bailout = ev.float(value)?,
                (_, View::AmbientLight(value)) => {
                    let v = ev.eval(value)?;
                    ev.scene.settings.ambient_light =
                        rgb(&v).ok_or_else(|| expr::type_error("a colour", &v, value.span))?;
                }
                (_, View::IridWavelength(value)) => {
                    let v = ev.eval(value)?;
                    ev.scene.settings.irid_wavelength =
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
                    ev.scene.settings.number_of_waves = n.max(1.0) as u8;
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
                    ev.lang.noise_generator = Some(n as u8);
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
    pub(in crate::eval) fn fog_items(&mut self, node: &Node) -> Result<FogItems> {
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
    pub(in crate::eval) fn fog(&mut self, node: &Node) -> Result<ir::Fog> {
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
    /// The value of `metallic [F]`, `fresnel [B]` or `area_illumination [B]`, or `default`
    /// without one.
    pub(in crate::eval) fn optional_float(&mut self, node: &Node, default: f64) -> Result<f64> {
        let value = match node.view() {
            View::Metallic { amount } => amount,
            View::Fresnel { on } | View::AreaIllumination { on } | View::LightMedia { on } => on,
            _ => return Err(malformed(node, "a flag with an optional value")),
        };
        value.map_or(Ok(default), |e| self.float(e))
    }

    pub(in crate::eval) fn rgb_arg(&mut self, e: &syntax::Expr) -> Result<Rgb> {
        let v = self.eval(e)?;
        rgb(&v).ok_or_else(|| expr::type_error("a colour", &v, e.span))
    }

    pub(in crate::eval) fn finish(mut self) -> Result<Evaluated> {
        // Files the scene left open are written out now (POV-Ray closes them at the end).
        self.lang.files.flush().map_err(|e| Diagnostic {
            severity: crate::diag::Severity::Error,
            message: format!("cannot write a file the scene opened with #fopen: {e}"),
            span: None,
            notes: Vec::new(),
        })?;
        let camera = match self.scene.camera.take() {
            Some(items) => resolve_camera(&items, &mut self.warnings)?,
            None => ir::Camera::default(),
        };
        let version = self.lang.version.unwrap_or(3.62);
        self.scene.settings.gamma = match self.lang.assumed_gamma {
            Some(g) => Gamma::Working(g),
            None if version >= 3.7 - 1e-9 => Gamma::Working(1.0),
            None => Gamma::Off,
        };
        self.scene.settings.legacy_transparency = version < 3.7 - 1e-9;
        self.radiosity_checked(version)?;
        // (POV-Ray's default generator is 2 unless the scene declares a version before 3.5.)
        self.scene.settings.noise_generator = self.lang.noise_generator.unwrap_or(
            if self.lang.version.is_some_and(|v| v < 3.5 - 1e-9) {
                1
            } else {
                2
            },
        );
        Ok(Evaluated {
            scene: ir::Scene {
                camera,
                lights: self.scene.lights,
                objects: self.scene.objects,
                background: self.scene.background,
                background_alpha: self.scene.background_alpha,
                sky_sphere: self.scene.sky_sphere,
                fogs: self.scene.fogs,
                atmosphere: self.scene.atmosphere,
                rainbows: self.scene.rainbows,
                settings: self.scene.settings,
            },
            warnings: self.warnings,
            debug_output: self.lang.debug_output,
        })
    }
}
