//! `light_source`: every kind, its items in POV-Ray's order, a light made of a declared one.

use crate::diag::{Diagnostic, Span};
use crate::eval::build::object;
use crate::eval::value::Value;
use crate::eval::{Evaluator, Result, malformed};
use crate::ir::{self, Rgb, Transform};
use crate::syntax::{self, Expr, Node, NodeKind, View};
use glam::DVec3;
use std::sync::Arc;

pub(in crate::eval) fn transform_light(light: &mut ir::Light, m: &glam::DMat4) {
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

impl Evaluator<'_> {
    pub(in crate::eval) fn light(
        &mut self,
        node: &Node,
    ) -> Result<(ir::Light, Option<object::ObjectValue>)> {
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
        let (mut media_interaction, mut media_attenuation) = (true, false);
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
                (NodeKind::LightMedia, _) => {
                    let on = ev.optional_float(item, 1.0)? > 0.0;
                    match item.word.as_str() {
                        "media_interaction" => media_interaction = on,
                        _ => media_attenuation = on,
                    }
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
            media_interaction,
            media_attenuation,
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
    pub(in crate::eval) fn declared_light(
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
}
