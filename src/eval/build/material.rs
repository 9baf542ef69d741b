//! Materials: `texture`, `pigment` (colours and patterns), `finish`, `interior`.

use crate::diag::Diagnostic;
use crate::eval::build::images::ImageRole;
use crate::eval::value::{MaterialValue, colour5, to_colour};
use crate::eval::{Evaluator, Result, Value, lang::expr::type_error};
use crate::ir::{
    self, Colour, ColourMap, Interior, Pattern, PatternKind, PatternPigment, Pigment, PigmentKind,
    PigmentMap, Rgb, Texture, TextureMap, Transform, Warp, WaveShape,
};
use crate::noise;
use crate::pattern::fractal::{self, Fractal, FractalKind};
use crate::pattern::image::ImageUse;
use crate::pattern::pavement;
use crate::pattern::{BlackHole, Mapping, MappingWarp};
use crate::syntax::{Expr, Node, NodeKind, View};
use std::sync::Arc;

/// `mortar` as POV-Ray keeps it: 2e-10 less, in single precision.
fn brick_mortar(m: f64) -> f64 {
    f64::from((m - 2e-10) as f32)
}

/// POV-Ray's bump amount when a normal pattern gives none.
pub(in crate::eval) const DEFAULT_BUMP_SIZE: f64 = 0.5;

/// A number as POV-Ray keeps it in single precision (map keys, some pattern parameters).
fn single(v: f64) -> f64 {
    f64::from(v as f32)
}

impl Evaluator<'_> {
    /// `slope V` or `slope { [point_at] V [, LOW, HIGH] [altitude A [, LOW, HIGH]] }`, as
    /// POV-Ray's parser leaves it: ranges as (low, high − low), an empty range ignored with a
    /// warning, the two directions normalised and weighted by their lengths.
    fn slope(&mut self, item: &Node) -> Result<crate::pattern::Slope> {
        let block = item
            .children
            .iter()
            .find(|c| c.kind == NodeKind::SlopeBlock);
        type Range<'e> = (Option<&'e Expr>, Option<&'e Expr>);
        let (first, slope_limits, point_at): (_, Range<'_>, _) =
            match (block.map(Node::view), item.view()) {
                (
                    Some(View::SlopeBlock {
                        direction,
                        low,
                        high,
                    }),
                    _,
                ) => {
                    let point_at = block.is_some_and(|b| {
                        b.children.iter().any(|c| c.kind == NodeKind::SlopePointAt)
                    });
                    (direction, (low, high), point_at)
                }
                (
                    None,
                    View::Pattern {
                        values: [direction, rest @ ..],
                    },
                ) => {
                    let limits = match rest {
                        [] => (None, None),
                        [low] => (Some(low), None),
                        [low, high, ..] => (Some(low), Some(high)),
                    };
                    (direction, limits, false)
                }
                _ => {
                    return Err(Diagnostic::error(
                        "`slope` needs a direction: slope y",
                        item.span,
                    ));
                }
            };
        let range = |ev: &mut Self, (low, high): Range<'_>, what: &str| -> Result<(f64, f64)> {
            let low_value = low.map(|e| ev.float(e)).transpose()?.unwrap_or(0.0);
            let high_value = high.map(|e| ev.float(e)).transpose()?.unwrap_or(0.0);
            if let Some(high) = high.filter(|_| high_value != 0.0 && high_value == low_value) {
                ev.warn(Diagnostic::warning(
                    format!("zero {what} range, ignoring"),
                    high.span,
                ));
                return Ok((0.0, 0.0));
            }
            Ok((low_value, high_value - low_value))
        };
        let direction = self.vec3(first)?;
        let slope_range = range(self, slope_limits, "slope")?;
        let (mut altitude, mut altitude_range) = (glam::DVec3::ZERO, (0.0, 0.0));
        if let Some(alt) = block.and_then(|b| {
            b.children
                .iter()
                .find(|c| c.kind == NodeKind::SlopeAltitude)
        }) {
            if point_at {
                return Err(Diagnostic::error(
                    "`altitude` cannot be used with `point_at` in a slope pattern",
                    alt.word_span,
                ));
            }
            let View::SlopeAltitude {
                altitude: a,
                low,
                high,
            } = alt.view()
            else {
                return Err(crate::eval::malformed(alt, "altitude"));
            };
            altitude = self.vec3(a)?;
            altitude_range = range(self, (low, high), "gradient")?;
        }
        if point_at {
            return Ok(crate::pattern::Slope {
                direction,
                point_at,
                slope_range,
                altitude,
                altitude_range,
                weights: (1.0, 0.0),
            });
        }
        let (slope_len, altitude_len) = (direction.length(), altitude.length());
        let total = slope_len + altitude_len;
        if total == 0.0 {
            return Err(Diagnostic::error(
                "zero length for both slope and gradient",
                first.span,
            ));
        }
        let unit = |v: glam::DVec3, len: f64| if len != 0.0 { v / len } else { v };
        let slope_weight = slope_len / total;
        Ok(crate::pattern::Slope {
            direction: unit(direction, slope_len),
            point_at,
            slope_range,
            altitude: unit(altitude, altitude_len),
            altitude_range,
            weights: (slope_weight, 1.0 - slope_weight),
        })
    }
}

/// The `object` pattern's test: 1 inside the object, 0 outside. It is its object's parts
/// (what it equals by) and the query built of them.
struct InsideTest {
    parts: Vec<ir::Object>,
    query: Box<dyn ir::ObjectQuery>,
}

impl PartialEq for InsideTest {
    fn eq(&self, other: &InsideTest) -> bool {
        self.parts == other.parts
    }
}

impl std::fmt::Debug for InsideTest {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("InsideTest")
    }
}

impl crate::func::Native for InsideTest {
    fn params(&self) -> usize {
        3
    }

    fn size(&self) -> usize {
        1
    }

    fn eval(&self, args: &[f64], _generator: u8) -> [f64; 5] {
        let &[x, y, z, ..] = args else {
            return [0.0; 5];
        };
        let inside = self.query.inside(glam::DVec3::new(x, y, z));
        [f64::from(u8::from(inside)), 0.0, 0.0, 0.0, 0.0]
    }

    fn same(&self, other: &dyn crate::func::Native) -> bool {
        crate::func::same_data(self, other)
    }
}

/// With `uv_mapping` among a block's items: the block made of the items after it (what sees
/// the surface's (u, v, 0) instead of the point, as POV-Ray parses the rest of the block).
fn after_uv_mapping(node: &Node) -> Option<Node> {
    let i = node
        .children
        .iter()
        .position(|c| c.kind == NodeKind::UvMapping)?;
    Some(Node {
        kind: node.kind,
        span: node.span,
        word: node.word.clone(),
        word_span: node.word_span,
        args: Vec::new(),
        children: node.children.iter().skip(i + 1).cloned().collect(),
        slot: node.slot,
    })
}

impl Evaluator<'_> {
    /// `texture` seen at the surface's (u, v, 0): a pattern of one texture, `uv_mapping`.
    pub(in crate::eval) fn uv_texture(&self, texture: Texture) -> Texture {
        let mut outer = self.scene.default_texture.clone();
        outer.map = Some(Box::new(ir::TextureMap {
            pattern: Pattern::new(PatternKind::UvMapping),
            transform: None,
            entries: vec![(0.0, texture)],
        }));
        outer
    }
}

/// The texture a uv-mapped object's pigment, normal and finish go into: the one entry of a
/// `uv_mapping` texture, else the texture itself.
pub(in crate::eval) fn uv_entry(texture: &mut Texture) -> &mut Texture {
    let uv = texture
        .map
        .as_ref()
        .is_some_and(|m| m.pattern.kind == PatternKind::UvMapping);
    if uv {
        &mut texture.map.as_mut().expect("a uv_mapping texture").entries[0].1
    } else {
        texture
    }
}

/// The checks POV-Ray makes when a pattern's block ends: a `pavement`'s sides, tiles and
/// variant (its options then reduced as POV-Ray reduces them).
fn check_pattern(pattern: &mut Pattern, span: crate::diag::Span) -> Result<()> {
    if let PatternKind::Pavement(pv) = &mut pattern.kind {
        *pv = pv
            .checked()
            .map_err(|e| Diagnostic::error(e.to_string(), span))?;
    }
    Ok(())
}

/// `top` layered over `below` (POV-Ray's layered textures): the layers of both, `top`'s
/// last.
pub(in crate::eval) fn layer(mut top: Texture, below: Texture) -> Texture {
    let mut under = below.under;
    under.push(Texture {
        under: Vec::new(),
        ..below
    });
    under.append(&mut top.under);
    top.under = under;
    top
}

impl Evaluator<'_> {
    /// `texture { [Name] pigment {…} normal {…} finish {…} transforms }`, starting from the
    /// default texture; or a pattern of textures (`checker texture {…} texture {…}`,
    /// `gradient y texture_map {…}`).
    pub(in crate::eval) fn texture(&mut self, node: &Node) -> Result<Texture> {
        if let Some(inner) = after_uv_mapping(node) {
            let inner = self.texture(&inner)?;
            return Ok(self.uv_texture(inner));
        }
        let mut texture = self.scene.default_texture.clone();
        let mut list: Vec<(Texture, crate::diag::Span)> = Vec::new();
        let mut map: Option<(Vec<(f64, Texture)>, crate::diag::Span)> = None;
        let mut pattern_span = None;
        self.each_item(&node.children, &mut |ev, item| {
            match item.kind {
                NodeKind::IdentRef => match ev.lookup(item)? {
                    Value::Texture(t) => texture = *t,
                    // `texture { P }` with a declared pigment: POV-Ray takes it as the pigment.
                    Value::Pigment(p) => texture.pigment = *p,
                    // `texture { P F }`: POV-Ray's old texture of declared pigments, normals and
                    // finishes without their wrappers.
                    Value::Finish(f) => texture.finish = ev.shared_finish(*f),
                    Value::Normal(n) => texture.normal = Some(n),
                    other => return Err(type_error("a texture", &other, item.span)),
                },
                NodeKind::Pigment => texture.pigment = ev.pigment(item, texture.pigment.clone())?,
                NodeKind::Normal => {
                    texture.normal = Some(Box::new(ev.normal(item, texture.normal.take())?));
                }
                NodeKind::Finish => texture.finish = ev.shared_finish_block(item, &texture.finish)?,
                _ if Self::is_transform(item) => {
                    let t = ev.transform(item)?;
                    texture.transform(t);
                }
                NodeKind::Pattern => {
                    let (kind, rest) = ev.pattern_kind(item)?;
                    normal_only(&kind, item)?;
                    if let Some(extra) = rest.first() {
                        return Err(Diagnostic::error(
                            format!("a `{}` of textures takes textures, not values", item.word),
                            extra.span,
                        ));
                    }
                    texture.map = Some(Box::new(TextureMap {
                        pattern: Pattern::new(kind),
                        transform: None,
                        entries: Vec::new(),
                    }));
                    pattern_span = Some(item.word_span);
                }
                // `no_bump_scale` on a texture is its normal's (none: nothing), as in POV-Ray.
                NodeKind::PatternModifier if item.word == "no_bump_scale" && texture.map.is_none() => {
                    let on = match crate::eval::modifier_value(item) {
                        Some(e) => ev.float(e)? != 0.0,
                        None => true,
                    };
                    if let Some(n) = &mut texture.normal {
                        n.no_bump_scale = on;
                    }
                }
                NodeKind::PatternModifier => match &mut texture.map {
                    Some(m) => ev.pattern_modifier(item, &mut m.pattern)?,
                    None => {
                        return Err(Diagnostic::error(
                            format!("`{}` modifies a pattern, and this texture has none", item.word),
                            item.word_span,
                        ));
                    }
                },
                NodeKind::Warp => match &mut texture.map {
                    Some(m) => ev.warp(item, &mut m.pattern, &mut m.transform)?,
                    None => {
                        return Err(Diagnostic::error(
                            "a warp in a texture applies to its pattern, and this texture has none (a pigment's or normal's warp goes inside it)",
                            item.word_span,
                        ));
                    }
                },
                NodeKind::Texture => {
                    let t = ev.texture(item)?;
                    list.push((t, item.word_span));
                }
                NodeKind::TextureMap => {
                    let average = texture
                        .map
                        .as_ref()
                        .is_some_and(|m| m.pattern.kind == PatternKind::Average);
                    map = Some((ev.texture_map(item, average)?, item.word_span))
                }
                NodeKind::ImageMap if item.word == "image_pattern" => {
                    let read = ev.image_map(item)?;
                    let use_ = match read.kind {
                        ImageRole::Pattern(use_) => use_,
                        _ => ImageUse::Colour,
                    };
                    texture.map = Some(Box::new(TextureMap {
                        pattern: Pattern::new(PatternKind::Image(Arc::new(read.image), use_)),
                        transform: None,
                        entries: Vec::new(),
                    }));
                    pattern_span = Some(item.word_span);
                }
                NodeKind::ImageMap | NodeKind::Unknown if item.word == "image_map" => {
                    return Err(Diagnostic::error(
                        "an `image_map` is a pigment: a texture picked by an image is a `material_map`",
                        item.word_span,
                    ));
                }
                NodeKind::MaterialMap => {
                    texture.map = Some(Box::new(ev.material_map(item)?));
                    pattern_span = Some(item.word_span);
                }
                NodeKind::Tiles => {
                    // (A layered texture on either side.)
                    let layered = |ev: &mut Self, nodes: &[Node]| -> Result<Texture> {
                        let mut t: Option<Texture> = None;
                        for n in nodes.iter().filter(|n| n.kind == NodeKind::Texture) {
                            let top = ev.texture(n)?;
                            t = Some(match t {
                                Some(below) => layer(top, below),
                                None => top,
                            });
                        }
                        Ok(t.unwrap_or_else(|| ev.scene.default_texture.clone()))
                    };
                    let first = item.children.iter().find(|c| c.kind == NodeKind::TilesFirst);
                    let first = layered(ev, first.map_or(&[][..], |f| &f.children))?;
                    let second = layered(ev, &item.children)?;
                    texture.map = Some(Box::new(TextureMap {
                        pattern: Pattern::new(PatternKind::Checker),
                        transform: None,
                        // (POV-Ray's tiles puts the first textures on checker's second
                        // squares.)
                        entries: vec![(0.0, second), (1.0, first)],
                    }));
                    pattern_span = Some(item.word_span);
                }
                _ => return Err(ev.unknown_item(item, "texture")),
            }
            Ok(())
        })?;
        if let Some(m) = &mut texture.map {
            check_pattern(&mut m.pattern, node.word_span)?;
        }
        let Some(m) = &mut texture.map else {
            let stray = list.first().map(|(_, s)| *s).or(map.map(|(_, s)| s));
            return match stray {
                Some(span) => Err(Diagnostic::error(
                    "textures inside a texture follow a pattern (checker texture {…} texture {…}, or gradient y texture_map {…})",
                    span,
                )),
                None => Ok(texture),
            };
        };
        // A declared pattern of textures, modified (`texture { Mountain scale 2 }`): its
        // entries stay.
        if map.is_none() && list.is_empty() && !m.entries.is_empty() {
            return Ok(texture);
        }
        match (m.pattern.kind.list_len(), map) {
            (_, Some((entries, span))) => {
                if m.pattern.kind.list_len().is_some() || !list.is_empty() {
                    return Err(Diagnostic::error(
                        "texture_map applies only to a pattern such as gradient (checker takes a list of textures)",
                        span,
                    ));
                }
                m.entries = entries;
            }
            (Some(len), None) => {
                if let Some((_, extra)) = list.get(len) {
                    return Err(Diagnostic::error(
                        format!("this pattern takes at most {len} textures"),
                        *extra,
                    ));
                }
                if list.is_empty() {
                    return Err(Diagnostic::error(
                        "this pattern of textures has no textures",
                        pattern_span.unwrap_or(node.word_span),
                    ));
                }
                let mut entries: Vec<(f64, Texture)> = list
                    .into_iter()
                    .enumerate()
                    .map(|(i, (t, _))| (i as f64, t))
                    .collect();
                // (Entries not given are the default texture, as in POV-Ray.)
                while entries.len() < len {
                    entries.push((entries.len() as f64, self.scene.default_texture.clone()));
                }
                m.entries = entries;
            }
            (None, None) => {
                return Err(Diagnostic::error(
                    "this pattern of textures needs a texture_map",
                    pattern_span.unwrap_or(node.word_span),
                ));
            }
        }
        Ok(texture)
    }

    /// `texture_map { [v TEXTURE_ITEMS] … }` or `texture_map { Name }`.
    pub(in crate::eval) fn texture_map(
        &mut self,
        node: &Node,
        average: bool,
    ) -> Result<Vec<(f64, Texture)>> {
        self.map_entries(
            node,
            "texture_map",
            average,
            |v| match v {
                Value::TextureMap(m) => Ok(m),
                other => Err(Box::new(other)),
            },
            |ev, body| ev.texture(body),
        )
    }

    /// The entries of a `pigment_map`, `normal_map` or `texture_map` (`what`): `[v ITEMS]`
    /// each read by `entry`, or a declared map of the same kind (`declared` takes it out of
    /// its value). In the map of an `average` the weight `v` may be left out (1, as POV-Ray).
    fn map_entries<T>(
        &mut self,
        node: &Node,
        what: &str,
        average: bool,
        declared: impl Fn(Value) -> std::result::Result<Vec<(f64, T)>, Box<Value>>,
        mut entry: impl FnMut(&mut Self, &Node) -> Result<T>,
    ) -> Result<Vec<(f64, T)>> {
        if let Some(found) = self.declared_map(node, what, declared) {
            return found;
        }
        let mut entries = Vec::new();
        self.each_item(&node.children, &mut |ev, e| {
            if e.kind != NodeKind::MapEntry {
                return Err(ev.unknown_item(e, what));
            }
            let View::MapEntry { values, body: Some(body) } = e.view() else {
                return Err(crate::eval::malformed(e, "a map entry"));
            };
            let value = match values {
                [v] => single(ev.float(v)?),
                [] if average => 1.0,
                [_, _, ..] => return Err(crate::eval::malformed(e, "a map entry")),
                [] => {
                    return Err(Diagnostic::error(
                        format!("this {what} entry needs its value first (only an average's entries may leave it out)"),
                        e.span,
                    ));
                }
            };
            entries.push((value, entry(ev, body)?));
            Ok(())
        })?;
        if entries.is_empty() {
            return Err(Diagnostic::error(
                format!("{what} has no entries"),
                node.word_span,
            ));
        }
        Ok(entries)
    }

    /// `pigment { [colour | Name | checker … | gradient … | image_map {…}] [color_map] transforms }`.
    pub(in crate::eval) fn pigment(
        &mut self,
        node: &Node,
        mut pigment: Pigment,
    ) -> Result<Pigment> {
        if let Some(inner) = after_uv_mapping(node) {
            let inner = self.pigment(&inner, Pigment::solid(Colour::default()))?;
            return Ok(Pigment {
                kind: PigmentKind::Pattern(Box::new(PatternPigment {
                    pattern: Pattern::new(PatternKind::UvMapping),
                    map: PigmentMap::Pigments(vec![(0.0, inner)]),
                })),
                transform: None,
            });
        }
        if let View::Pigment { colour: Some(e) } | View::PigmentPattern { colour: Some(e) } =
            node.view()
        {
            pigment = self.pigment_value(e, pigment)?;
        }
        let mut map: Option<(PigmentMap, crate::diag::Span)> = None;
        let mut list: Vec<(Pigment, crate::diag::Span)> = Vec::new();
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                // A colour after a map entry's pattern (`[0.5 rgb 1]`).
                (_, View::ColourItem(value)) => {
                    pigment = ev.pigment_value(value, pigment.clone())?
                }
                // A declared colour or pigment standing alone among the items.
                (NodeKind::IdentRef | NodeKind::Unknown, _) if ev.names_colour_alone(item) => {
                    let v = ev.lookup(item)?;
                    ev.warn_bare_colour(&v, item.word_span, "in a pigment");
                    pigment = pigment_from(v, item.word_span, pigment.clone())?;
                }
                (NodeKind::Pattern, _) => {
                    let (kind, rest) = ev.pattern_kind(item)?;
                    normal_only(&kind, item)?;
                    let map = PigmentMap::Colours(ev.pattern_map(item, &kind, rest)?);
                    pigment.kind = PigmentKind::Pattern(Box::new(PatternPigment {
                        pattern: Pattern::new(kind),
                        map,
                    }));
                }
                // The colour of POV-Ray's low-quality previews: read, not used.
                (NodeKind::PatternModifier, _)
                    if matches!(item.word.as_str(), "quick_color" | "quick_colour") =>
                {
                    if let Some(e) = crate::eval::modifier_value(item) {
                        ev.eval(e)?;
                    }
                }
                (NodeKind::Warp, _) => match &mut pigment.kind {
                    PigmentKind::Pattern(p) => ev.warp(item, &mut p.pattern, &mut pigment.transform)?,
                    _ => {
                        return Err(Diagnostic::error(
                            "a warp bends a pattern, and this pigment has none",
                            item.word_span,
                        ));
                    }
                },
                (NodeKind::PatternModifier, _) => match &mut pigment.kind {
                    PigmentKind::Pattern(p) => ev.pattern_modifier(item, &mut p.pattern)?,
                    _ => {
                        return Err(Diagnostic::error(
                            format!("`{}` modifies a pattern, and this pigment has none", item.word),
                            item.word_span,
                        ));
                    }
                },
                (NodeKind::ImageMap, _) => {
                    let read = ev.image_map(item)?;
                    match read.kind {
                        ImageRole::Colours => {
                            pigment.kind = PigmentKind::ImageMap(Arc::new(read.image))
                        }
                        ImageRole::Pattern(use_) => {
                            let kind = PatternKind::Image(Arc::new(read.image), use_);
                            let map = PigmentMap::Colours(ev.pattern_map(item, &kind, &[])?);
                            pigment.kind = PigmentKind::Pattern(Box::new(PatternPigment {
                                pattern: Pattern::new(kind),
                                map,
                            }));
                        }
                        ImageRole::Bumps(_) => {
                            return Err(Diagnostic::error(
                                "`bump_map` can stand only in a normal (POV-Ray refuses it elsewhere too)",
                                item.word_span,
                            ));
                        }
                    }
                }
                (NodeKind::ColourMap, _) => {
                    map = Some((PigmentMap::Colours(ev.colour_map(item)?), item.word_span))
                }
                (NodeKind::PigmentMap, _) => {
                    let average = matches!(&pigment.kind,
                        PigmentKind::Pattern(p) if p.pattern.kind == PatternKind::Average);
                    map = Some((PigmentMap::Pigments(ev.pigment_map(item, average)?), item.word_span))
                }
                // `checker pigment {…} pigment {…}`: a discrete pattern's list of pigments.
                (NodeKind::Pigment, _) => {
                    let entry = ev.pigment(item, Pigment::solid(Colour::default()))?;
                    list.push((entry, item.word_span));
                }
                _ if Self::is_transform(item) => {
                    let t = ev.transform(item)?;
                    t.append_to(&mut pigment.transform);
                }
                _ => return Err(ev.unknown_item(item, "pigment")),
            }
            Ok(())
        })?;
        if let PigmentKind::Pattern(p) = &mut pigment.kind {
            check_pattern(&mut p.pattern, node.word_span)?;
        }
        if let Some((m, map_span)) = map {
            match &mut pigment.kind {
                PigmentKind::Pattern(p) if p.pattern.kind.list_len().is_none() => p.map = m,
                _ => {
                    return Err(Diagnostic::error(
                        "color_map and pigment_map apply only to a pattern such as gradient (checker takes a list of colours or pigments)",
                        map_span,
                    ));
                }
            }
        }
        if let Some((_, first_span)) = list.first() {
            let PigmentKind::Pattern(p) = &mut pigment.kind else {
                return Err(Diagnostic::error(
                    "a pigment inside a pigment follows a pattern such as checker (a list of pigments)",
                    *first_span,
                ));
            };
            let Some(len) = p.pattern.kind.list_len() else {
                return Err(Diagnostic::error(
                    "a list of pigments follows a pattern such as checker, hexagon or brick (give this pattern a pigment_map)",
                    *first_span,
                ));
            };
            if let Some((_, extra)) = list.get(len) {
                return Err(Diagnostic::error(
                    format!("this pattern takes at most {len} pigments"),
                    *extra,
                ));
            }
            // The entries not given are the default texture's pigment (black unless
            // `#default` says otherwise), as in POV-Ray: not the pattern's default colours.
            let PigmentMap::Colours(defaults) = &p.map else {
                unreachable!("a discrete pattern starts with its list of colours")
            };
            let mut entries: Vec<(f64, Pigment)> = defaults
                .entries
                .iter()
                .map(|(v, _)| (*v, self.scene.default_texture.pigment.clone()))
                .collect();
            for (slot, (entry, _)) in entries.iter_mut().zip(list) {
                slot.1 = entry;
            }
            p.map = PigmentMap::Pigments(entries);
        }
        Ok(pigment)
    }

    /// `warp { … }` on `pattern`, whose placement so far is `placement`: the placement
    /// becomes a warp applied after this one (POV-Ray applies the last-written warp or
    /// transformation first).
    pub(in crate::eval) fn warp(
        &mut self,
        item: &Node,
        pattern: &mut Pattern,
        placement: &mut Option<Box<Transform>>,
    ) -> Result<()> {
        // (A warp's first item says what it is; the others modify it.)
        let [first, modifiers @ ..] = item.children.as_slice() else {
            return Err(Diagnostic::error("this warp is empty", item.word_span));
        };
        fn values(it: &Node) -> &[Expr] {
            match it.view() {
                View::WarpItem { values } => values,
                _ => &[],
            }
        }
        let value = |ev: &mut Self, it: &Node| -> Result<glam::DVec3> {
            let [e, ..] = values(it) else {
                return Err(Diagnostic::error(
                    format!("`{}` needs a value", it.word),
                    it.word_span,
                ));
            };
            ev.vec3(e)
        };
        let first_values = values(first);
        let first_span = first_values.first().map_or(first.word_span, |e| e.span);
        let warp = match first.word.as_str() {
            "turbulence" | "octaves" | "omega" | "lambda" => {
                let mut t = noise::Turbulence::default();
                for it in &item.children {
                    let v = value(self, it)?;
                    match it.word.as_str() {
                        "turbulence" => t.amount = v,
                        "octaves" => t.octaves = (v.x as i64).clamp(1, 10) as u32,
                        "omega" => t.omega = single(v.x),
                        "lambda" => t.lambda = single(v.x),
                        _ => return Err(self.unknown_item(it, "a turbulence warp")),
                    }
                }
                Warp::Turbulence(Box::new(t))
            }
            "repeat" => {
                let v = value(self, first)?;
                let axes: Vec<usize> = (0..3).filter(|&i| v[i] != 0.0).collect();
                let axis = match axes.as_slice() {
                    [a] => *a,
                    [] => return Err(Diagnostic::error("no axis in repeat", first_span)),
                    _ => {
                        return Err(Diagnostic::error("repeat along one axis only", first_span));
                    }
                };
                let (mut offset, mut flip) = (glam::DVec3::ZERO, glam::DVec3::ONE);
                for it in modifiers {
                    let v = value(self, it)?;
                    match it.word.as_str() {
                        "offset" => offset = v,
                        "flip" => flip = v.map(|c| if c != 0.0 { -1.0 } else { 1.0 }),
                        _ => return Err(self.unknown_item(it, "a repeat warp")),
                    }
                }
                Warp::Repeat {
                    axis,
                    width: v[axis] as f32,
                    offset,
                    flip,
                }
            }
            "black_hole" => {
                let (center, radius) = match first_values {
                    [c, r] => (self.vec3(c)?, self.float(r)?),
                    _ => {
                        return Err(Diagnostic::error(
                            "`black_hole` takes a centre and a radius: `black_hole <x, y, z>, r`",
                            first.span,
                        ));
                    }
                };
                let mut b = BlackHole {
                    center,
                    radius,
                    strength: 1.0,
                    falloff: 2.0,
                    inverse: false,
                    kind: 0,
                    repeat: None,
                    uncertainty: None,
                };
                for it in modifiers {
                    match it.word.as_str() {
                        "inverse" if values(it).is_empty() => b.inverse = true,
                        "strength" => b.strength = value(self, it)?.x,
                        "falloff" => b.falloff = value(self, it)?.x,
                        "type" => b.kind = value(self, it)?.x as i32,
                        "repeat" => b.repeat = Some(value(self, it)?),
                        "turbulence" => b.uncertainty = Some(value(self, it)?),
                        _ => return Err(self.unknown_item(it, "a black_hole warp")),
                    }
                }
                Warp::BlackHole(Box::new(b.checked()))
            }
            "cylindrical" | "spherical" | "toroidal" | "planar" | "cubic" => {
                let mut m = MappingWarp {
                    mapping: match first.word.as_str() {
                        "cylindrical" => Mapping::Cylindrical,
                        "spherical" => Mapping::Spherical,
                        "toroidal" => Mapping::Toroidal { major_radius: 1.0 },
                        "cubic" => Mapping::Cubic,
                        _ => Mapping::Planar { offset: 0.0 },
                    },
                    orientation: glam::DVec3::Z,
                    dist_exp: 0.0,
                };
                match (first.word.as_str(), first_values) {
                    (_, []) => {}
                    ("planar", [v, offset]) => {
                        m.orientation = self.vec3(v)?.normalize_or_zero();
                        m.mapping = Mapping::Planar {
                            offset: self.float(offset)?,
                        };
                    }
                    _ => {
                        return Err(Diagnostic::error(
                            format!("`{}` takes no value here", first.word),
                            first_span,
                        ));
                    }
                }
                for it in modifiers {
                    match (it.word.as_str(), &mut m.mapping) {
                        (
                            "orientation",
                            Mapping::Cylindrical | Mapping::Spherical | Mapping::Toroidal { .. },
                        ) => {
                            m.orientation = value(self, it)?.normalize_or_zero();
                        }
                        (
                            "dist_exp",
                            Mapping::Cylindrical | Mapping::Spherical | Mapping::Toroidal { .. },
                        ) => {
                            m.dist_exp = value(self, it)?.x;
                        }
                        ("major_radius", Mapping::Toroidal { major_radius }) => {
                            *major_radius = value(self, it)?.x;
                        }
                        _ => return Err(self.unknown_item(it, &format!("a {} warp", first.word))),
                    }
                }
                Warp::Mapping(Box::new(m))
            }
            _ => return Err(self.unknown_item(first, "a warp")),
        };
        let mut warps = vec![warp];
        if let Some(t) = placement.take() {
            warps.push(Warp::Transform(t.matrix.inverse()));
        }
        warps.append(&mut pattern.warps);
        pattern.warps = warps;
        Ok(())
    }

    /// The evaluator's pattern table: the pattern `item` names, made from the arguments it
    /// takes, and the arguments left after them (a discrete pattern's colours in a pigment,
    /// the bump amount in a normal).
    pub(in crate::eval) fn pattern_kind<'n>(
        &mut self,
        item: &'n Node,
    ) -> Result<(PatternKind, &'n [crate::syntax::Expr])> {
        let View::Pattern { values: args } = item.view() else {
            return Err(crate::eval::malformed(item, "a pattern"));
        };
        // `function { … }`: a user function of the point.
        if let Some(f) = item.children.iter().find(|c| c.kind == NodeKind::Function) {
            return Ok((PatternKind::Function(self.function(f)?), args));
        }
        // `object { OBJECT C0, C1 }`: inside or outside the object.
        if let Some(o) = item
            .children
            .iter()
            .find(|c| c.kind == NodeKind::ObjectPattern)
        {
            let View::ObjectPattern { colours } = o.view() else {
                return Err(crate::eval::malformed(o, "an object pattern"));
            };
            let [first, ..] = o.children.as_slice() else {
                return Err(crate::eval::malformed(o, "an object pattern"));
            };
            let object = match first.kind {
                NodeKind::IdentRef => match self.lookup(first)? {
                    Value::Object(object) => *object,
                    other => return Err(type_error("an object", &other, first.span)),
                },
                _ => self.object(first)?,
            };
            let parts = self.placed_parts(&object, first.span)?;
            let query = (self.scene.object_query)(parts.clone());
            let inside = crate::func::NativeRef(Arc::new(InsideTest { parts, query }));
            return Ok((PatternKind::Object(inside), colours));
        }
        // `pigment_pattern { … }`: a pigment's grey.
        if let Some(p) = item
            .children
            .iter()
            .find(|c| c.kind == NodeKind::PigmentPattern)
        {
            let pigment = self.pigment(p, Pigment::solid(Colour::default()))?;
            let native = crate::pattern::PigmentFunction(pigment.placed(self.scene_defaults()));
            return Ok((
                PatternKind::Pigment(crate::func::NativeRef(Arc::new(native))),
                args,
            ));
        }
        // The patterns that take an argument: a number (spiral arms) or a direction; `rest`,
        // the values after it.
        let (first, rest) = match args {
            [first, rest @ ..] => (Ok(first), rest),
            [] => (
                Err(Diagnostic::error(
                    format!("`{}` needs a value after it", item.word),
                    item.span,
                )),
                args,
            ),
        };
        let first = || first.clone();
        let kind = match item.word.as_str() {
            "gradient" => {
                let e = first()?;
                let axis = self.vec3(e)?;
                if axis.length_squared() == 0.0 {
                    return Err(Diagnostic::error(
                        "gradient direction is the zero vector",
                        e.span,
                    ));
                }
                return Ok((PatternKind::Gradient(axis.normalize()), rest));
            }
            "spiral1" | "spiral2" => {
                // (POV-Ray keeps the number of arms as an integer.)
                let arms = self.float(first()?)?.trunc();
                let kind = if item.word == "spiral1" {
                    PatternKind::Spiral1(arms)
                } else {
                    PatternKind::Spiral2(arms)
                };
                return Ok((kind, rest));
            }
            "tiling" => {
                let e = first()?;
                let n = pavement::parameter_byte(self.float(e)?);
                if !(1..=27).contains(&n) {
                    return Err(Diagnostic::error(
                        "tiling number must be between 1 and 27",
                        e.span,
                    ));
                }
                return Ok((PatternKind::Tiling(n), rest));
            }
            "mandel" => {
                let n = self.float(first()?)? as i32;
                let f = Fractal::new(FractalKind::Mandel, n);
                return Ok((PatternKind::Fractal(Box::new(f)), rest));
            }
            "julia" => {
                let c = self.uv(first()?)?.to_array();
                let [n, rest @ ..] = rest else {
                    return Err(Diagnostic::error(
                        "`julia` needs its constant and a number of iterations: julia <0.3, 0.5>, 30",
                        item.span,
                    ));
                };
                let f = Fractal::new(FractalKind::Julia { c }, self.float(n)? as i32);
                return Ok((PatternKind::Fractal(Box::new(f)), rest));
            }
            "magnet" => {
                // `magnet 1|2 mandel N` or `magnet 1|2 julia <c>, N` (the second word reaches
                // here as a name).
                let kind_expr = first()?;
                let kind = self.float(kind_expr)? as i64;
                let Some(form) = item
                    .children
                    .iter()
                    .find(|c| c.kind == NodeKind::MagnetForm)
                else {
                    return Err(Diagnostic::error(
                        "invalid magnet pattern: `magnet 1 mandel N` or `magnet 1 julia <c>, N` (types 1 and 2)",
                        item.span,
                    ));
                };
                let which = form.word.as_str();
                if kind != 1 && kind != 2 {
                    return Err(Diagnostic::error(
                        format!("invalid magnet-{which} pattern type: valid types are 1 and 2"),
                        kind_expr.span,
                    ));
                }
                let (julia, rest) = if which == "julia" {
                    let [c, rest @ ..] = rest else {
                        return Err(Diagnostic::error(
                            "`magnet … julia` needs its constant: magnet 1 julia <0.3, 0.5>, 30",
                            item.span,
                        ));
                    };
                    (Some(self.uv(c)?.to_array()), rest)
                } else {
                    (None, rest)
                };
                let [n, rest @ ..] = rest else {
                    return Err(Diagnostic::error(
                        "`magnet` needs a number of iterations after it",
                        item.span,
                    ));
                };
                let f = Fractal::new(
                    FractalKind::Magnet {
                        kind: kind as u8,
                        julia,
                    },
                    self.float(n)? as i32,
                );
                return Ok((PatternKind::Fractal(Box::new(f)), rest));
            }
            "pavement" => PatternKind::Pavement(pavement::Pavement::default()),
            "aoi" => PatternKind::Aoi,
            "density_file" => {
                let [
                    Expr {
                        kind: crate::syntax::ExprKind::Ident(df3, _),
                        ..
                    },
                    file_expr,
                    rest @ ..,
                ] = args
                else {
                    return Err(Diagnostic::error(
                        "`density_file` reads a DF3 file: density_file df3 \"file.df3\"",
                        item.span,
                    ));
                };
                let true = df3 == "df3" else {
                    return Err(Diagnostic::error(
                        "`density_file` reads a DF3 file: density_file df3 \"file.df3\"",
                        item.span,
                    ));
                };
                let name = self.string(file_expr)?;
                let path = self.find_file(&name, "density file", file_expr.span)?;
                let cannot = |e: &dyn std::fmt::Display| {
                    Diagnostic::error(
                        format!("cannot read density file {}: {e}", path.display()),
                        file_expr.span,
                    )
                };
                let bytes = std::fs::read(&path).map_err(|e| cannot(&e))?;
                let data = crate::pattern::density::parse(&name, &bytes).map_err(|e| cannot(&e))?;
                return Ok((PatternKind::Density(Arc::new(data)), rest));
            }
            "slope" => return Ok((PatternKind::Slope(Box::new(self.slope(item)?)), &[])),
            "agate" => PatternKind::Agate { turb: 1.0 },
            "average" => PatternKind::Average,
            "boxed" => PatternKind::Boxed,
            "bozo" => PatternKind::Bozo,
            "brick" => PatternKind::Brick {
                size: glam::DVec3::new(8.0, 3.0, 4.5),
                mortar: brick_mortar(0.5),
            },
            "bumps" => PatternKind::Bumps,
            "cells" => PatternKind::Cells,
            "checker" => PatternKind::Checker,
            "crackle" => PatternKind::Crackle(Box::default()),
            "cylindrical" => PatternKind::Cylindrical,
            "dents" => PatternKind::Dents,
            "facets" => PatternKind::Facets(Default::default()),
            "granite" => PatternKind::Granite,
            "hexagon" => PatternKind::Hexagon,
            "leopard" => PatternKind::Leopard,
            "marble" => PatternKind::Marble,
            "onion" => PatternKind::Onion,
            "planar" => PatternKind::Planar,
            "quilted" => PatternKind::Quilted {
                control0: 1.0,
                control1: 1.0,
            },
            "radial" => PatternKind::Radial,
            "ripples" => PatternKind::Ripples,
            "spherical" => PatternKind::Spherical,
            "spotted" => PatternKind::Spotted,
            "square" => PatternKind::Square,
            "triangular" => PatternKind::Triangular,
            "waves" => PatternKind::Waves,
            "wood" => PatternKind::Wood,
            "wrinkles" => PatternKind::Wrinkles,
            _ => return Err(self.unknown_word(&item.word, item.word_span)),
        };
        Ok((kind, args))
    }

    /// A pigment pattern's colour map before any `color_map`: for a discrete pattern its list
    /// (the arguments left, in order, the rest from POV-Ray's default list), for a value
    /// pattern POV-Ray's default map for it (black to white for most).
    fn pattern_map(
        &mut self,
        item: &Node,
        kind: &PatternKind,
        rest: &[crate::syntax::Expr],
    ) -> Result<ColourMap> {
        let c = |r: f64, g: f64, b: f64| Colour {
            rgb: Rgb::new(r, g, b),
            ..Colour::default()
        };
        let map = |entries: &[(f64, Colour)]| ColourMap {
            entries: entries.to_vec(),
        };
        let (red, green, blue) = (c(1.0, 0.0, 0.0), c(0.0, 1.0, 0.0), c(0.0, 0.0, 1.0));
        let six = [
            red,
            green,
            blue,
            c(1.0, 1.0, 0.0),
            c(0.0, 1.0, 1.0),
            c(1.0, 0.0, 1.0),
        ];
        // Discrete patterns: POV-Ray's default entries, keyed 0, 1, ….
        let list: Vec<(f64, Colour)> = match kind {
            PatternKind::Checker | PatternKind::Object(_) => vec![(0.0, blue), (1.0, green)],
            PatternKind::Hexagon => vec![(0.0, blue), (1.0, green), (2.0, red)],
            PatternKind::Brick { .. } => vec![(0.0, c(0.5, 0.5, 0.5)), (1.0, c(0.6, 0.15, 0.15))],
            // (POV-Ray's tables key these 0, 1, 1, 1 …, but it picks a discrete pattern's
            // entry by its index: measured, its default square shows four colours.)
            PatternKind::Square => (0..4).map(f64::from).zip(six).collect(),
            PatternKind::Triangular => (0..6).map(f64::from).zip(six).collect(),
            _ => {
                if let Some(extra) = rest.first() {
                    return Err(Diagnostic::error(
                        format!("`{}` takes no colours (give it a color_map)", item.word),
                        extra.span,
                    ));
                }
                return Ok(match kind {
                    PatternKind::Bozo => map(&[
                        (0.4, c(1.0, 1.0, 1.0)),
                        (0.4, green),
                        (0.6, green),
                        (0.6, blue),
                        (0.8, blue),
                        (0.8, red),
                    ]),
                    PatternKind::Wood => {
                        map(&[(0.6, c(0.666, 0.312, 0.2)), (0.6, c(0.4, 0.1333, 0.066))])
                    }
                    PatternKind::Marble => map(&[
                        (0.0, c(0.9, 0.8, 0.8)),
                        (0.9, c(0.9, 0.08, 0.08)),
                        (0.9, c(0.0, 0.0, 0.0)),
                    ]),
                    PatternKind::Agate { .. } => map(&[
                        (0.0, c(1.0, 1.0, 1.0)),
                        (0.5, c(0.95, 0.75, 0.5)),
                        (0.5, c(0.9, 0.7, 0.5)),
                        (0.6, c(0.9, 0.7, 0.4)),
                        (0.6, c(1.0, 0.7, 0.4)),
                        (1.0, c(0.6, 0.3, 0.0)),
                    ]),
                    PatternKind::Radial => map(&[
                        (0.0, c(0.0, 1.0, 1.0)),
                        (0.333, c(1.0, 1.0, 0.0)),
                        (0.666, c(1.0, 0.0, 1.0)),
                        (1.0, c(0.0, 1.0, 1.0)),
                    ]),
                    _ => ColourMap::default(),
                });
            }
        };
        if rest.is_empty() {
            return Ok(ColourMap { entries: list });
        }
        if rest.len() > list.len() {
            return Err(Diagnostic::error(
                format!("`{}` takes at most {} colours", item.word, list.len()),
                rest[list.len()].span,
            ));
        }
        // A list given: entries numbered 0, 1, …, the colours not given from the defaults.
        let mut entries: Vec<(f64, Colour)> = list
            .iter()
            .enumerate()
            .map(|(i, (_, c))| (i as f64, *c))
            .collect();
        for (slot, e) in entries.iter_mut().zip(rest) {
            let v = self.eval(e)?;
            slot.1 = to_colour(colour5(&v).ok_or_else(|| type_error("a colour", &v, e.span))?);
        }
        Ok(ColourMap { entries })
    }

    /// `normal { [Name] [PATTERN [amount]] modifiers transforms }`, starting from `base` (the
    /// texture's normal, if it has one).
    pub(in crate::eval) fn normal(
        &mut self,
        node: &Node,
        base: Option<Box<ir::Normal>>,
    ) -> Result<ir::Normal> {
        if let Some(inner) = after_uv_mapping(node) {
            let inner = self.normal(&inner, None)?;
            let mut normal = ir::Normal::new(Pattern::new(PatternKind::UvMapping), 0.0);
            normal.map = Some(vec![(0.0, inner)]);
            return Ok(normal);
        }
        let mut normal: Option<ir::Normal> = base.map(|b| *b);
        // `checker normal {…}, normal {…}`: a discrete pattern's list of normals.
        let mut list: Vec<(ir::Normal, crate::diag::Span)> = Vec::new();
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::Normal(n) => normal = Some(*n),
                    other => return Err(type_error("a normal", &other, item.span)),
                },
                (NodeKind::Normal, _) => {
                    let entry = ev.normal(item, None)?;
                    list.push((entry, item.word_span));
                }
                (NodeKind::Pattern, _) => {
                    let (kind, rest) = ev.pattern_kind(item)?;
                    // (A discrete pattern without a list of normals bumps by the slope of its
                    // entry number, as in POV-Ray.)
                    let amount = match rest {
                        [] => ev.scene.default_bump_size,
                        [e] => ev.float(e)?,
                        [_, extra, ..] => {
                            return Err(Diagnostic::error(
                                format!("`{}` takes one bump amount", item.word),
                                extra.span,
                            ));
                        }
                    };
                    normal = Some(ir::Normal::new(Pattern::new(kind), amount));
                }
                (NodeKind::ImageMap, _) => {
                    let read = ev.image_map(item)?;
                    let (kind, amount) = match read.kind {
                        ImageRole::Bumps(size) => (
                            PatternKind::BumpMap(Arc::new(read.image)),
                            size.unwrap_or(ev.scene.default_bump_size),
                        ),
                        ImageRole::Pattern(use_) => {
                            (PatternKind::Image(Arc::new(read.image), use_), ev.scene.default_bump_size)
                        }
                        ImageRole::Colours => {
                            return Err(Diagnostic::error(
                                "an `image_map` is a pigment: a normal takes `bump_map` or `image_pattern`",
                                item.word_span,
                            ));
                        }
                    };
                    normal = Some(ir::Normal::new(Pattern::new(kind), amount));
                }
                (NodeKind::Unknown, _) => return Err(ev.unknown_item(item, "normal")),
                _ => {
                    let Some(n) = &mut normal else {
                        return Err(Diagnostic::error(
                            format!("`{}` needs a pattern before it in this normal", item.word),
                            item.word_span,
                        ));
                    };
                    match (item.kind, item.view()) {
                        (NodeKind::PatternModifier, _) if item.word == "accuracy" => {
                            let e = crate::eval::modifier_value(item).ok_or_else(|| {
                                Diagnostic::error("`accuracy` needs a value", item.word_span)
                            })?;
                            n.accuracy = f64::from(ev.float(e)? as f32);
                        }
                        (NodeKind::PatternModifier, _) if item.word == "no_bump_scale" => {
                            n.no_bump_scale = match crate::eval::modifier_value(item) {
                                Some(e) => ev.float(e)? != 0.0,
                                None => true,
                            };
                        }
                        (NodeKind::SlopeMap, _) => n.slope_map = Some(ev.slope_map(item)?),
                        (NodeKind::NormalMap, _) => {
                            let average = n.pattern.kind == PatternKind::Average;
                            n.map = Some(ev.normal_map(item, average)?)
                        }
                        (NodeKind::PatternModifier, _) => ev.pattern_modifier(item, &mut n.pattern)?,
                        (NodeKind::Warp, _) => ev.warp(item, &mut n.pattern, &mut n.transform)?,
                        (_, View::BumpSize(value)) => n.amount = ev.float(value)?,
                        _ if Self::is_transform(item) => {
                            let t = ev.transform(item)?;
                            t.append_to(&mut n.transform);
                        }
                        _ => return Err(ev.unknown_item(item, "normal")),
                    }
                }
            }
            Ok(())
        })?;
        let mut normal = normal
            .ok_or_else(|| Diagnostic::error("this normal has no pattern", node.word_span))?;
        check_pattern(&mut normal.pattern, node.word_span)?;
        if let Some((_, first_span)) = list.first() {
            let Some(len) = normal.pattern.kind.list_len() else {
                return Err(Diagnostic::error(
                    "a list of normals follows a pattern such as checker, hexagon or brick (give this pattern a normal_map)",
                    *first_span,
                ));
            };
            if let Some((_, extra)) = list.get(len) {
                return Err(Diagnostic::error(
                    format!("this pattern takes at most {len} normals"),
                    *extra,
                ));
            }
            // Entry i at value i; the entries not given are the default texture's normal
            // (flat unless `#default` gave one), as in POV-Ray.
            let flat = || {
                self.scene
                    .default_texture
                    .normal
                    .as_deref()
                    .cloned()
                    .unwrap_or_else(|| ir::Normal::new(Pattern::new(PatternKind::Checker), 0.0))
            };
            let mut entries: Vec<(f64, ir::Normal)> = Vec::with_capacity(len);
            let mut given = list.into_iter();
            for i in 0..len {
                let entry = given.next().map_or_else(flat, |(n, _)| n);
                entries.push((i as f64, entry));
            }
            normal.map = Some(entries);
        }
        if normal.pattern.kind == PatternKind::Average && normal.map.is_none() {
            return Err(Diagnostic::error(
                "an average of normals needs a normal_map",
                node.word_span,
            ));
        }
        Ok(normal)
    }

    /// A pattern modifier (`frequency 2`, `turbulence 0.5`, `sine_wave`, `agate_turb 0.3` …)
    /// applied to `pattern`, with POV-Ray's precision (several are single-precision there).
    pub(in crate::eval) fn pattern_modifier(
        &mut self,
        item: &Node,
        pattern: &mut Pattern,
    ) -> Result<()> {
        let (value, factor) = match item.view() {
            View::PatternModifier { value, factor } => (value, factor),
            _ => return Err(crate::eval::malformed(item, "a pattern modifier")),
        };
        let arg = || {
            value.ok_or_else(|| {
                Diagnostic::error(format!("`{}` needs a value", item.word), item.word_span)
            })
        };
        let misplaced = |what: &str| {
            Diagnostic::error(
                format!("`{}` applies only to {what}", item.word),
                item.word_span,
            )
        };
        // The classic turbulence: `octaves`, `omega` and `lambda` make one (of amount 0) if
        // the pattern has none yet.
        fn turbulence(p: &mut Pattern) -> &mut noise::Turbulence {
            p.turbulence.get_or_insert_with(Box::default)
        }
        match item.word.as_str() {
            "frequency" => pattern.wave.frequency = single(self.float(arg()?)?),
            "phase" => pattern.wave.phase = single(self.float(arg()?)?),
            "ramp_wave" => pattern.wave.shape = WaveShape::Ramp,
            "triangle_wave" => pattern.wave.shape = WaveShape::Triangle,
            "sine_wave" => pattern.wave.shape = WaveShape::Sine,
            "scallop_wave" => pattern.wave.shape = WaveShape::Scallop,
            "cubic_wave" => pattern.wave.shape = WaveShape::Cubic,
            "poly_wave" => {
                let e = match value {
                    Some(e) => single(self.float(e)?),
                    None => 1.0,
                };
                pattern.wave.shape = WaveShape::Poly(e);
            }
            "turbulence" => turbulence(pattern).amount = self.vec3(arg()?)?,
            "octaves" => {
                let n = self.float(arg()?)?;
                turbulence(pattern).octaves = (n as i64).clamp(1, 10) as u32;
            }
            "omega" => turbulence(pattern).omega = single(self.float(arg()?)?),
            "lambda" => turbulence(pattern).lambda = single(self.float(arg()?)?),
            "noise_generator" => {
                let n = self.float(arg()?)?;
                if !(1.0..=3.0).contains(&n) {
                    return Err(Diagnostic::error(
                        "noise_generator must be 1, 2 or 3",
                        arg()?.span,
                    ));
                }
                pattern.noise_generator = n as u8;
            }
            "agate_turb" => {
                let v = single(self.float(arg()?)?);
                turbulence(pattern);
                match &mut pattern.kind {
                    PatternKind::Agate { turb } => *turb = v,
                    _ => return Err(misplaced("agate")),
                }
            }
            "brick_size" => {
                let v = self.vec3(arg()?)?;
                match &mut pattern.kind {
                    PatternKind::Brick { size, .. } => *size = v,
                    _ => return Err(misplaced("brick")),
                }
            }
            "mortar" => {
                let v = brick_mortar(self.float(arg()?)?);
                match &mut pattern.kind {
                    PatternKind::Brick { mortar, .. } => *mortar = v,
                    _ => return Err(misplaced("brick")),
                }
            }
            "control0" | "control1" => {
                let v = single(self.float(arg()?)?);
                match &mut pattern.kind {
                    PatternKind::Quilted { control0, .. } if item.word == "control0" => {
                        *control0 = v
                    }
                    PatternKind::Quilted { control1, .. } => *control1 = v,
                    _ => return Err(misplaced("quilted")),
                }
            }
            "coords" | "size" | "metric" if matches!(pattern.kind, PatternKind::Facets(_)) => {
                // `metric` is a vector, of which POV-Ray uses x.
                let v = self.vec3(arg()?)?.x;
                if let PatternKind::Facets(f) = &mut pattern.kind {
                    match item.word.as_str() {
                        "coords" => f.coords = v,
                        "size" => f.size = v,
                        _ => f.metric = v,
                    }
                }
            }
            "coords" | "size" => return Err(misplaced("facets")),
            "interpolate" => {
                let n = self.float(arg()?)?;
                match &mut pattern.kind {
                    PatternKind::Density(d) => Arc::make_mut(d).interpolation = n.max(0.0) as u32,
                    _ => return Err(misplaced("density_file")),
                }
            }
            "exponent" => {
                let e = arg()?;
                let v = self.float(e)? as i32;
                match &mut pattern.kind {
                    PatternKind::Fractal(f) if !matches!(f.kind, FractalKind::Magnet { .. }) => {
                        if !(fractal::MIN_EXPONENT..=fractal::MAX_EXPONENT).contains(&v) {
                            self.warn(Diagnostic::warning(
                                "supported exponents are 2 to 33: using the default exponent 2",
                                e.span,
                            ));
                        }
                        f.exponent = v;
                    }
                    _ => return Err(misplaced("mandel or julia")),
                }
            }
            "interior" | "exterior" => {
                let interior = item.word == "interior";
                let e = arg()?;
                let v = self.float(e)?;
                match &mut pattern.kind {
                    PatternKind::Pavement(pv) if interior => {
                        pv.interior = pavement::parameter_byte(v)
                    }
                    PatternKind::Pavement(pv) => pv.exterior = pavement::parameter_byte(v),
                    PatternKind::Fractal(f) => {
                        let (kind, max) = if interior {
                            ("interior", fractal::MAX_INTERIOR_TYPE)
                        } else {
                            ("exterior", fractal::MAX_EXTERIOR_TYPE)
                        };
                        let t = v as i32;
                        if !(0..=max).contains(&t) {
                            return Err(Diagnostic::error(
                                format!(
                                    "invalid fractal pattern {kind} type: valid types are 0 to {max}"
                                ),
                                e.span,
                            ));
                        }
                        let Some(factor) = factor else {
                            return Err(Diagnostic::error(
                                format!("`{kind}` takes a type and a factor: {kind} {t}, 1"),
                                item.span,
                            ));
                        };
                        let factor = self.float(factor)?;
                        if interior {
                            f.interior = (t, factor);
                        } else {
                            f.exterior = (t, factor);
                        }
                    }
                    _ => return Err(misplaced("mandel, julia, magnet or pavement")),
                }
            }
            "number_of_sides" | "number_of_tiles" | "pattern" => {
                let v = pavement::parameter_byte(self.float(arg()?)?);
                let PatternKind::Pavement(pv) = &mut pattern.kind else {
                    return Err(misplaced("pavement"));
                };
                match item.word.as_str() {
                    "number_of_sides" => pv.sides = v,
                    "number_of_tiles" => pv.tiles = v,
                    _ => pv.pattern = v,
                }
            }
            "form" if matches!(pattern.kind, PatternKind::Pavement(_)) => {
                let v = pavement::parameter_byte(self.float(arg()?)?);
                if let PatternKind::Pavement(pv) = &mut pattern.kind {
                    pv.form = v;
                }
            }
            "form" | "metric" | "offset" | "solid" => {
                let PatternKind::Crackle(c) = &mut pattern.kind else {
                    return Err(misplaced("crackle"));
                };
                match item.word.as_str() {
                    "form" => c.form = self.vec3(arg()?)?,
                    "metric" => c.metric = self.vec3(arg()?)?.x,
                    "offset" => c.offset = self.float(arg()?)?,
                    _ => c.solid = true,
                }
            }
            _ => return Err(self.unknown_word(&item.word, item.word_span)),
        }
        Ok(())
    }

    /// Whether `item` is just the name of a declared colour or pigment (nothing after it).
    fn names_colour_alone(&self, item: &Node) -> bool {
        let text = &self.sources.file(item.span.file).text;
        let rest = text
            .get(item.word_span.end as usize..item.span.end as usize)
            .unwrap_or("x");
        rest.trim().is_empty()
            && matches!(
                self.bound(item.slot),
                Some(Value::Pigment(_) | Value::Colour(_) | Value::Vector(_) | Value::Float(_))
            )
    }

    /// The pigment a colour or pigment value `e` makes of `pigment`: a new colour keeps the
    /// placement of the pigment it replaces, as in POV-Ray (a pigment block modifies the
    /// current pigment).
    fn pigment_value(&mut self, e: &crate::syntax::Expr, pigment: Pigment) -> Result<Pigment> {
        let v = self.eval(e)?;
        self.warn_bare_colour(&v, e.span, "in a pigment");
        pigment_from(v, e.span, pigment)
    }

    /// POV-Ray wants a colour in a pigment or a `color_map` entry to start with a colour
    /// keyword (`rgb`, `color`, …) or a colour's name; a number or a vector there is a parse
    /// error in POV-Ray 3.7, which trace reads as a grey or an rgb colour with a warning.
    fn warn_bare_colour(&mut self, v: &Value, span: crate::diag::Span, place: &str) {
        let what = match v {
            Value::Float(_) => "a number",
            Value::Vector(_) => "a vector",
            _ => return,
        };
        self.warn(Diagnostic::warning(
            format!(
                "POV-Ray 3.7 refuses {what} as a colour {place} (write `rgb` before it): trace reads it as a colour, but this scene does not render in POV-Ray"
            ),
            span,
        ));
    }

    /// `pigment_map { [v PIGMENT] … }` or `pigment_map { Name }`: each entry's pigment starts
    /// black and unplaced (it is placed in the pattern's space).
    pub(in crate::eval) fn pigment_map(
        &mut self,
        node: &Node,
        average: bool,
    ) -> Result<Vec<(f64, Pigment)>> {
        self.map_entries(
            node,
            "pigment_map",
            average,
            |v| match v {
                Value::PigmentMap(m) => Ok(m),
                other => Err(Box::new(other)),
            },
            |ev, body| ev.pigment(body, Pigment::solid(Colour::default())),
        )
    }

    /// `slope_map { [v <height, slope>] … }`.
    /// `normal_map { [v NORMAL_ITEMS] … }` or `normal_map { Name }`.
    pub(in crate::eval) fn normal_map(
        &mut self,
        node: &Node,
        average: bool,
    ) -> Result<Vec<(f64, ir::Normal)>> {
        self.map_entries(
            node,
            "normal_map",
            average,
            |v| match v {
                Value::NormalMap(m) => Ok(m),
                other => Err(Box::new(other)),
            },
            |ev, body| ev.normal(body, None),
        )
    }

    /// A map given by name (`color_map { Name }`): its value if `take` accepts it, a type
    /// error naming `what` if not, `None` when the map lists its entries.
    fn declared_map<T>(
        &mut self,
        node: &Node,
        what: &str,
        take: impl FnOnce(Value) -> std::result::Result<T, Box<Value>>,
    ) -> Option<Result<T>> {
        let ident = node
            .children
            .iter()
            .find(|c| c.kind == NodeKind::IdentRef)?;
        Some(match self.lookup(ident) {
            Ok(v) => take(v).map_err(|other| type_error(&format!("a {what}"), &other, ident.span)),
            Err(e) => Err(e),
        })
    }

    /// `slope_map { [v <height, slope>] … }` or `slope_map { Name }`.
    pub(in crate::eval) fn slope_map(&mut self, node: &Node) -> Result<Vec<(f64, [f64; 2])>> {
        let take = |v| match v {
            Value::SlopeMap(m) => Ok(m),
            other => Err(Box::new(other)),
        };
        if let Some(found) = self.declared_map(node, "slope_map", take) {
            return found;
        }
        let mut entries = Vec::new();
        for e in &node.children {
            let View::MapEntry {
                values: [value, point_expr],
                ..
            } = e.view()
            else {
                return Err(crate::eval::malformed(e, "a slope_map entry"));
            };
            let value = single(self.float(value)?);
            let v = self.eval(point_expr)?;
            let point = match &v {
                Value::Vector(p) if p.len >= 2 => [p.c[0], p.c[1]],
                Value::Float(f) => [*f, *f],
                _ => {
                    return Err(type_error(
                        "a 2-vector <height, slope>",
                        &v,
                        point_expr.span,
                    ));
                }
            };
            entries.push((value, point));
        }
        if entries.is_empty() {
            return Err(Diagnostic::error(
                "slope_map has no entries",
                node.word_span,
            ));
        }
        Ok(entries)
    }

    /// `color_map { [v C] … }` or `color_map { Name }`.
    pub(in crate::eval) fn colour_map(&mut self, node: &Node) -> Result<ColourMap> {
        let take = |v| match v {
            Value::ColourMap(m) => Ok(m),
            other => Err(Box::new(other)),
        };
        if let Some(found) = self.declared_map(node, "color_map", take) {
            return found;
        }
        let mut entries = Vec::new();
        // (Directives among the entries run where they stand.)
        self.each_item(&node.children, &mut |ev, entry| {
            if entry.kind != NodeKind::MapEntry {
                return Err(ev.unknown_item(entry, "color_map"));
            }
            // `[v C]`, or the old range form `[v1, v2 C1 C2]`, which is `[v1 C1] [v2 C2]`.
            let points = match entry.view() {
                View::MapEntry { values: [v, c], .. } => vec![(v, c)],
                View::MapEntry { values: [v1, v2, c1, c2], .. } => vec![(v1, c1), (v2, c2)],
                _ => return Err(crate::eval::malformed(entry, "a color_map entry")),
            };
            for (value_expr, colour_expr) in points {
                // (POV-Ray keeps map keys in single precision.)
                let value = single(ev.float(value_expr)?);
                let v = ev.eval(colour_expr)?;
                ev.warn_bare_colour(&v, colour_expr.span, "in a color_map entry");
                let colour = to_colour(
                    colour5(&v).ok_or_else(|| type_error("a colour", &v, colour_expr.span))?,
                );
                if entries
                    .last()
                    .is_some_and(|(last, _): &(f64, Colour)| value < *last)
                {
                    // POV-Ray renders such a map without a word; its lookup (which trace
                    // follows) makes the result easy to misread, so say how it is read.
                    ev.warn(Diagnostic::warning(
                        "color_map value smaller than the one before: as in POV-Ray, a value at or above the last entry takes the last colour, and any other blends the first key not below it, scanning from the start, with the entry before",
                        value_expr.span,
                    ));
                }
                entries.push((value, colour));
            }
            Ok(())
        })?;
        if entries.is_empty() {
            return Err(Diagnostic::error(
                "color_map has no entries",
                node.word_span,
            ));
        }
        Ok(ColourMap { entries })
    }

    /// `finish { [Name] items }` applied to `base`, shared with an equal finish made before.
    pub(in crate::eval) fn shared_finish_block(
        &mut self,
        node: &Node,
        base: &ir::Finish,
    ) -> Result<Arc<ir::Finish>> {
        let finish = self.finish_block(node, base.clone())?;
        Ok(self.shared_finish(finish))
    }

    /// `finish { [Name] items }`, modifying `finish`.
    pub(in crate::eval) fn finish_block(
        &mut self,
        node: &Node,
        mut f: ir::Finish,
    ) -> Result<ir::Finish> {
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::Finish(declared) => f = *declared,
                    other => return Err(type_error("a finish", &other, item.span)),
                },
                (_, View::Ambient(value)) => f.ambient = ev.rgb_arg(value)?,
                (_, View::Emission(value)) => f.emission = ev.rgb_arg(value)?,
                (NodeKind::Diffuse | NodeKind::Phong | NodeKind::Specular, _)
                    if item.children.iter().any(|c| c.kind == NodeKind::Albedo) =>
                {
                    let albedo = item.children.iter().find(|c| c.kind == NodeKind::Albedo);
                    let span = albedo.map_or(item.word_span, |a| a.word_span);
                    return Err(ev.unknown_word("albedo", span));
                }
                (_, View::Diffuse { amount, back }) => {
                    f.diffuse = ev.float(amount)?;
                    if let Some(back) = back {
                        f.diffuse_back = ev.float(back)?;
                    }
                }
                (_, View::Brilliance(value)) => f.brilliance = ev.float(value)?,
                (_, View::Phong(value)) => f.phong = ev.float(value)?,
                (_, View::PhongSize(value)) => f.phong_size = ev.float(value)?,
                (_, View::Specular(value)) => f.specular = ev.float(value)?,
                (_, View::Roughness(value)) => {
                    let r = ev.float(value)?;
                    if r == 0.0 {
                        ev.warn(Diagnostic::warning(
                            "zero roughness: using 0.0001 instead",
                            item.span,
                        ));
                    }
                    f.roughness = if r == 0.0 { 1e-4 } else { r };
                }
                (NodeKind::Metallic, _) => f.metallic = ev.optional_float(item, 1.0)?,
                (NodeKind::ConserveEnergy, _) => f.conserve_energy = true,
                (_, View::Crand(value)) => f.crand = ev.float(value)?,
                (_, View::Irid(value)) => {
                    f.irid.amount = ev.float(value)?;
                    for it in &item.children {
                        match (it.view(), it.word.as_str()) {
                            (View::Thickness(thickness), _) => {
                                f.irid.thickness = ev.float(thickness)?;
                            }
                            (View::PatternModifier { value: Some(amount), .. }, "turbulence") => {
                                f.irid.turbulence = ev.vec3(amount)?.x;
                            }
                            _ => return Err(ev.unknown_item(it, "irid")),
                        }
                    }
                }
                (NodeKind::Reflection, _) => ev.reflection(item, &mut f.reflection)?,
                // POV-Ray's old spelling of `reflection { … exponent E }`.
                (_, View::ReflectionExponent(value)) => f.reflection.exponent = ev.float(value)?,
                // POV-Ray's old interior items in a finish: moved to the object's interior
                // when it is placed (`Evaluator::place`), with POV-Ray's warnings.
                (_, View::Caustics(value)) => {
                    f.legacy_caustics = Some(ev.float(value)?);
                    ev.warnings.push(Diagnostic::warning(
                        "caustics should be given in `interior { … }` (POV-Ray reads it from a finish too, but not times 45 as there)",
                        item.word_span,
                    ));
                }
                (_, View::Ior(value)) => {
                    let ior = ev.float(value)?;
                    if ior <= 0.0 {
                        return Err(Diagnostic::error("ior must be positive", value.span));
                    }
                    f.legacy_ior = Some(ior);
                    ev.warnings.push(Diagnostic::warning(
                        "an index of refraction should be given in `interior { … }` (POV-Ray reads it there from a finish too)",
                        item.word_span,
                    ));
                }
                (_, View::Refraction(value)) => {
                    f.legacy_refraction = ev.float(value)?;
                    ev.warnings.push(Diagnostic::warning(
                        "`refraction` is not needed to turn refraction on; it multiplies the light passing through (fade_distance and fade_power in `interior { … }` attenuate it)",
                        item.word_span,
                    ));
                }
                _ => return Err(ev.unknown_item(item, "finish")),
            }
            Ok(())
        })?;
        Ok(f)
    }

    fn reflection(&mut self, node: &Node, r: &mut ir::Reflection) -> Result<()> {
        let View::Reflection { first, max } = node.view() else {
            return Err(crate::eval::malformed(node, "a reflection"));
        };
        let first = self.rgb_arg(first)?;
        match max {
            Some(second) => {
                r.min = first;
                r.max = self.rgb_arg(second)?;
            }
            None => {
                r.min = first;
                r.max = first;
            }
        }
        let single = max.is_none();
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (_, View::Falloff(value)) => r.falloff = ev.float(value)?,
                (_, View::Exponent(value)) => r.exponent = ev.float(value)?,
                (NodeKind::Metallic, _) => r.metallic = ev.optional_float(item, 1.0)?,
                (NodeKind::Fresnel, _) => r.fresnel = ev.optional_float(item, 1.0)? != 0.0,
                _ => return Err(ev.unknown_item(item, "reflection")),
            }
            Ok(())
        })?;
        // With `fresnel` and a single colour, POV-Ray resets the minimum to 0.
        if r.fresnel && single {
            r.min = Rgb::ZERO;
        }
        Ok(())
    }

    /// `interior { [Name] ior fade_distance fade_power fade_color }`.
    pub(in crate::eval) fn interior(
        &mut self,
        node: &Node,
        mut interior: Interior,
    ) -> Result<Interior> {
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::Interior(i) => interior = *i,
                    other => return Err(type_error("an interior", &other, item.span)),
                },
                (_, View::Ior(value)) => {
                    interior.ior = ev.float(value)?;
                    if interior.ior <= 0.0 {
                        return Err(Diagnostic::error("ior must be positive", value.span));
                    }
                    interior.ior_given = true;
                }
                (_, View::Dispersion(value)) if item.word == "dispersion" => {
                    let d = ev.float(value)?;
                    if d <= 0.0 {
                        return Err(Diagnostic::error(
                            "dispersion must be positive (with zero or less, POV-Ray's indices of refraction become infinite or undefined)",
                            value.span,
                        ));
                    }
                    // (POV-Ray keeps it in single precision.)
                    interior.dispersion = f64::from(d as f32);
                }
                (_, View::Dispersion(value)) if item.word == "dispersion_samples" => {
                    let n = ev.float(value)? as i64;
                    if n < 2 {
                        return Err(Diagnostic::error(
                            "dispersion_samples must be at least 2",
                            value.span,
                        ));
                    }
                    interior.dispersion_samples = n.min(i64::from(u32::MAX)) as u32;
                }
                (_, View::FadeDistance(value)) => interior.fade_distance = ev.float(value)?,
                (_, View::FadePower(value)) => interior.fade_power = ev.float(value)?,
                // (POV-Ray keeps the value times 45: the exponent of the cosine.)
                (_, View::Caustics(value)) => interior.caustics = ev.float(value)? * 45.0,
                (_, View::FadeColour(value)) => interior.fade_colour = ev.rgb_arg(value)?,
                (NodeKind::Media, _) => interior.media.push(ev.media(item)?),
                // (Set again by a plain texture's finish when the object is placed.)
                (_, View::Refraction(value)) => {
                    interior.refraction = ev.float(value)?;
                    ev.warnings.push(Diagnostic::warning(
                        "`refraction` is not needed to turn refraction on; it multiplies the light passing through (fade_distance and fade_power attenuate it)",
                        item.word_span,
                    ));
                }
                _ => return Err(ev.unknown_item(item, "interior")),
            }
            Ok(())
        })?;
        Ok(interior)
    }

    /// `media { [Name] … }`: POV-Ray's defaults for the scene's `#version` unless it starts
    /// from a declared media (whose values it keeps), then its items in order.
    pub(in crate::eval) fn media(&mut self, node: &Node) -> Result<ir::Media> {
        let mut media = ir::Media::new(self.lang.version.unwrap_or(3.7));
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (NodeKind::IdentRef, _) => match ev.lookup(item)? {
                    Value::Media(m) => media = *m,
                    other => return Err(type_error("a media", &other, item.span)),
                },
                (_, View::MediaSetting { value, second }) => {
                    ev.media_setting(item, value, second, &mut media)?
                }
                (_, View::Scattering { kind, colour }) => {
                    let k = ev.float(kind)?;
                    media.scattering_type = k as i32;
                    if !(1..=5).contains(&media.scattering_type) {
                        ev.warnings.push(Diagnostic::warning(
                            "unknown scattering type: it scatters as type 1 (isotropic)",
                            kind.span,
                        ));
                    }
                    media.scattering = ev.rgb_arg(colour)?;
                    for setting in &item.children {
                        let View::ScatteringSetting(value) = setting.view() else {
                            return Err(ev.unknown_item(setting, "scattering"));
                        };
                        let v = ev.float(value)?;
                        match setting.word.as_str() {
                            "eccentricity" if media.scattering_type != 5 => {
                                return Err(Diagnostic::error(
                                    "eccentricity is for scattering type 5 (Henyey-Greenstein) only",
                                    setting.word_span,
                                ));
                            }
                            "eccentricity" => media.eccentricity = v,
                            "extinction" => media.extinction = v,
                            _ => return Err(ev.unknown_item(setting, "scattering")),
                        }
                    }
                }
                (NodeKind::Density, _) => {
                    let density = ev.density(item)?;
                    // (The last written is the head of POV-Ray's list.)
                    media.densities.insert(0, density);
                }
                // Transformations move the densities written before them only.
                _ if Self::is_transform(item) => {
                    let t = ev.transform(item)?;
                    media.transform(t);
                }
                _ => return Err(ev.unknown_item(item, "media")),
            }
            Ok(())
        })?;
        Ok(media)
    }

    /// One media setting (`intervals 2`, `samples 10, 20`, `absorption C` …), checked as
    /// POV-Ray checks it.
    fn media_setting(
        &mut self,
        item: &Node,
        value: &crate::syntax::Expr,
        second: Option<&crate::syntax::Expr>,
        media: &mut ir::Media,
    ) -> Result<()> {
        let word = item.word.as_str();
        if let Some(extra) = second.filter(|_| word != "samples") {
            return Err(Diagnostic::error(
                format!("`{word}` takes one value"),
                extra.span,
            ));
        }
        let fail = |message: &str| Err(Diagnostic::error(message.to_string(), value.span));
        match word {
            "absorption" => media.absorption = self.rgb_arg(value)?,
            "emission" => media.emission = self.rgb_arg(value)?,
            "collect" => {
                // (Photons only: read and ignored.)
                self.float(value)?;
            }
            _ => {
                let v = self.float(value)?;
                match word {
                    "method" => {
                        if !matches!(v as i32, 1..=3) {
                            return fail("media method must be 1, 2 or 3");
                        }
                        media.method = v as u32;
                    }
                    "intervals" => {
                        if (v as i64) < 1 {
                            return fail("media needs at least one interval");
                        }
                        media.intervals = v as u32;
                    }
                    "samples" => {
                        let min = v as i64;
                        let max = match second {
                            Some(e) => self.float(e)? as i64,
                            None => min,
                        };
                        if min < 1 {
                            return fail("media needs at least one sample per interval");
                        }
                        if max < min {
                            return fail("media samples: the most is below the least");
                        }
                        media.samples = (min as u32, max as u32);
                    }
                    "confidence" => {
                        if !(0.0..1.0).contains(&v) {
                            return fail("media confidence must be at least 0 and below 1");
                        }
                        media.confidence = v;
                    }
                    "variance" => media.variance = v,
                    "ratio" => media.ratio = v,
                    "jitter" => media.jitter = v,
                    "aa_threshold" => {
                        if v <= 0.0 {
                            return fail("media aa_threshold must be greater than 0");
                        }
                        media.aa_threshold = v;
                    }
                    "aa_level" => {
                        if (v as i64) < 1 {
                            return fail("media aa_level must be at least 1");
                        }
                        media.aa_level = v as u32;
                    }
                    _ => return Err(self.unknown_item(item, "media")),
                }
            }
        }
        Ok(())
    }

    /// `density { … }`: a pigment's body (an empty one is black: no density).
    pub(in crate::eval) fn density(&mut self, node: &Node) -> Result<ir::Pigment> {
        self.pigment(node, Pigment::solid(Colour::default()))
    }

    /// `material { [Name] texture {…} interior_texture {…} interior {…} transforms }`: what
    /// it sets, each only if given (transforms move the textures).
    pub(in crate::eval) fn material(&mut self, node: &Node) -> Result<MaterialValue> {
        let mut m = MaterialValue::default();
        self.each_item(&node.children, &mut |ev, item| {
            match item.kind {
                NodeKind::IdentRef => match ev.lookup(item)? {
                    Value::Material(v) => m = *v,
                    other => return Err(type_error("a material", &other, item.span)),
                },
                NodeKind::Texture => m.texture = Some(ev.texture(item)?),
                NodeKind::InteriorTexture => m.interior_texture = Some(ev.texture(item)?),
                NodeKind::Interior => {
                    let base = m.interior.take().unwrap_or_default();
                    m.interior = Some(ev.interior(item, base)?);
                }
                _ if Self::is_transform(item) => {
                    let t = ev.transform(item)?;
                    for texture in [&mut m.texture, &mut m.interior_texture]
                        .into_iter()
                        .flatten()
                    {
                        texture.transform(t);
                    }
                }
                _ => return Err(ev.unknown_item(item, "material")),
            }
            Ok(())
        })?;
        Ok(m)
    }
}

/// The pigment a colour or pigment value makes of `pigment` (see `Evaluator::pigment_value`).
fn pigment_from(v: Value, span: crate::diag::Span, pigment: Pigment) -> Result<Pigment> {
    Ok(match v {
        Value::Pigment(p) => *p,
        other => match colour5(&other) {
            Some(c) => Pigment {
                kind: PigmentKind::Solid(to_colour(c)),
                transform: pigment.transform,
            },
            None => return Err(type_error("a colour or pigment", &other, span)),
        },
    })
}

/// POV-Ray's refusal of a normal-only pattern (`facets`) in a pigment or a texture.
fn normal_only(kind: &PatternKind, item: &Node) -> Result<()> {
    if matches!(kind, PatternKind::Facets(_)) {
        return Err(Diagnostic::error(
            format!(
                "`{}` can stand only in a normal (POV-Ray refuses it elsewhere too)",
                item.word
            ),
            item.word_span,
        ));
    }
    Ok(())
}

/// What the language asks of materials: a layered texture as a value, a pigment or pattern as
/// a function.
impl Evaluator<'_> {
    /// `texture {…} texture {…} …`: each texture layered over the ones before it.
    pub(in crate::eval) fn layered_texture(&mut self, item: &Node) -> Result<Value> {
        let mut layered: Option<ir::Texture> = None;
        for t in item.children.iter().filter(|c| c.kind == NodeKind::Texture) {
            let t = self.texture(t)?;
            layered = Some(match layered {
                Some(below) => layer(t, below),
                None => t,
            });
        }
        Ok(Value::Texture(Box::new(
            layered.expect("a layered texture has textures"),
        )))
    }

    /// The scene's pattern defaults as they stand while the scene is read.
    pub(in crate::eval) fn scene_defaults(&self) -> crate::pattern::SceneDefaults {
        crate::pattern::SceneDefaults {
            generator: self.noise_generator(),
            waves: self.scene.settings.number_of_waves,
        }
    }

    /// The function of a `pigment { … }` or `pattern { … }` body.
    pub(in crate::eval) fn native_function(
        &mut self,
        body: &Node,
    ) -> Result<Arc<dyn crate::func::Native>> {
        let pigment = self.pigment(body, ir::Pigment::solid(ir::Colour::default()))?;
        if body.kind == NodeKind::Pigment {
            let placed = pigment.placed(self.scene_defaults());
            return Ok(Arc::new(crate::pattern::PigmentFunction(placed)));
        }
        let ir::PigmentKind::Pattern(p) = pigment.kind else {
            return Err(Diagnostic::error(
                "`pattern { }` needs a pattern (gradient x, granite …)",
                body.word_span,
            ));
        };
        Ok(Arc::new(crate::pattern::PatternFunction {
            pattern: p.pattern.with_scene(self.scene_defaults()),
            from_world: pigment.transform.map(|t| t.matrix.inverse()),
        }))
    }
}

#[cfg(test)]
mod tests {
    use crate::ir::PigmentKind;
    use glam::DVec3;

    /// The pattern of `pigment { BODY }` on a plane, as evaluated, with its inverse placement.
    fn pattern_of(body: &str) -> (crate::ir::Pattern, Option<glam::DMat4>) {
        let text = format!("plane {{ z, 0 pigment {{ {body} }} }}");
        let loaded = crate::load_str(
            std::path::Path::new("pattern.rt"),
            text,
            &crate::LoadOptions::default(),
        )
        .unwrap_or_else(|e| panic!("{body}: {e}"));
        let pigment = &loaded.scene.objects[0].texture.pigment;
        let PigmentKind::Pattern(p) = &pigment.kind else {
            panic!("{body}: not a pattern pigment")
        };
        let inverse = pigment.transform.as_ref().map(|t| t.matrix.inverse());
        (p.pattern.clone(), inverse)
    }

    /// The scene's noise generator: `global_settings`, else 1 before `#version 3.5`, else 2
    /// (measured: `#version 3.1` gives generator 1's values, no version generator 2's).
    #[test]
    fn the_scene_noise_generator_follows_povray() {
        let generator = |text: &str| {
            crate::load_str(
                std::path::Path::new("g.rt"),
                text.to_string(),
                &crate::LoadOptions::default(),
            )
            .unwrap()
            .scene
            .settings
            .noise_generator
        };
        assert_eq!(generator("global_settings { noise_generator 3 }"), 3);
        assert_eq!(
            generator("#version 3.1; global_settings { noise_generator 2 }"),
            2
        );
        assert_eq!(generator("#version 3.1;"), 1);
        assert_eq!(generator("#version 3.7;"), 2);
        assert_eq!(generator(""), 2);
    }

    /// Every pattern, with modifiers, against the values POV-Ray 3.7.0.10 printed for the same
    /// pattern (`function { pattern { … } }` evaluated at the same points): the same doubles,
    /// except where a transformation is involved (POV-Ray builds inverse matrices from their
    /// parts, trace inverts the matrix: the last bits may differ).
    #[test]
    fn patterns_match_povray_bit_for_bit() {
        let text = include_str!("../../pattern/testdata/patterns.txt");
        let (mut checked, mut blocks) = (0, Vec::new());
        let mut current: Option<(String, crate::ir::Pattern, Option<glam::DMat4>)> = None;
        for line in text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        {
            if let Some(body) = line.strip_prefix("@ ") {
                let (p, m) = pattern_of(body);
                blocks.push(body.to_string());
                current = Some((body.to_string(), p, m));
                continue;
            }
            let Some((body, pattern, inverse)) = &current else {
                continue;
            };
            let v: Vec<f64> = line
                .split_whitespace()
                .map(|x| x.parse().unwrap())
                .collect();
            let p = DVec3::new(v[0], v[1], v[2]);
            let q = inverse.map_or(p, |m| m.transform_point3(p));
            let got = pattern.value(q);
            if inverse.is_some() {
                assert!(
                    (got - v[3]).abs() < 1e-9,
                    "{body} at {p}: {got} vs POV-Ray {}",
                    v[3]
                );
            } else {
                assert_eq!(got, v[3], "{body} at {p}");
            }
            checked += 1;
        }
        assert!(blocks.len() >= 56, "{} pattern variants read", blocks.len());
        assert!(checked >= 1500, "{checked} values compared");
    }
}
