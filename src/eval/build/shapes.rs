//! The evaluator's shape table: a shape keyword of the generic `shape` rule and its values,
//! made into an IR shape. Adding a shape: its word in the grammar's `shape_kw`, an arm here,
//! its IR variant and its geometry (`geometry/`, one file and one line in `shape.rs`).

use crate::diag::{Diagnostic, Span};
use crate::eval::{Evaluator, Result, Value, lang::expr::type_error};
use crate::ir::{
    Lathe, Polynomial, Prism, Quadric, Shape, Sor, SphereSweep, Spline, Sweep, SweepSpline,
};
use crate::syntax::{Expr, Node, NodeKind, View};
use glam::DVec2;
use std::sync::Arc;

/// Whether `word` (a flag among a shape's items) is the shape's own, read by the shape table.
pub(in crate::eval) fn takes(shape: &str, word: &str) -> bool {
    match shape {
        "text" => matches!(word, "ttf" | "internal"),
        "prism" => matches!(
            word,
            "linear_spline"
                | "quadratic_spline"
                | "cubic_spline"
                | "bezier_spline"
                | "linear_sweep"
                | "conic_sweep"
                | "open"
                | "sturm"
        ),
        "lathe" => matches!(
            word,
            "linear_spline" | "quadratic_spline" | "cubic_spline" | "bezier_spline" | "sturm"
        ),
        "sor" => matches!(word, "open" | "sturm"),
        "sphere_sweep" => matches!(
            word,
            "linear_spline" | "cubic_spline" | "b_spline" | "tolerance"
        ),
        "bicubic_patch" => matches!(
            word,
            "type" | "flatness" | "u_steps" | "v_steps" | "accuracy" | "uv_vectors"
        ),
        "julia_fractal" => matches!(
            word,
            "quaternion"
                | "hypercomplex"
                | "sqr"
                | "cube"
                | "max_iteration"
                | "precision"
                | "slice"
        ),
        "height_field" => matches!(
            word,
            "water_level"
                | "hierarchy"
                | "smooth"
                | "png"
                | "pgm"
                | "ppm"
                | "gif"
                | "tga"
                | "pot"
                | "jpeg"
                | "tiff"
                | "sys"
                | "exr"
                | "hdr"
                | "bmp"
                | "iff"
        ),
        _ => false,
    }
}

/// A shape's values and own words in source order.
enum Item<'n> {
    Word(&'n Node),
    Value(&'n Expr),
}

fn items(node: &Node) -> Vec<Item<'_>> {
    node.children
        .iter()
        .filter_map(|c| match c.kind {
            NodeKind::Flag if takes(&node.word, &c.word) => Some(Item::Word(c)),
            _ => match c.view() {
                View::Value(value) => Some(Item::Value(value)),
                _ => None,
            },
        })
        .collect()
}

/// A shape's values, in order.
fn values(node: &Node) -> Vec<&Expr> {
    node.children
        .iter()
        .filter_map(|c| match c.view() {
            View::Value(value) => Some(value),
            _ => None,
        })
        .collect()
}

/// The spline a word names (`linear_spline` …).
fn spline_word(word: &str) -> Option<Spline> {
    Some(match word {
        "linear_spline" => Spline::Linear,
        "quadratic_spline" => Spline::Quadratic,
        "cubic_spline" => Spline::Cubic,
        "bezier_spline" => Spline::Bezier,
        _ => return None,
    })
}

/// The finest julia_fractal marching trace does (POV-Ray's scenes use 15 to 400).
const MAX_JULIA_PRECISION: f64 = 10_000.0;

/// The largest font file trace reads (POV-Ray's own fonts are below 100 kB).
const MAX_FONT_BYTES: u64 = 64 << 20;

impl<'a> Evaluator<'a> {
    /// The IR shape of a `shape` node (`quadric { … }` …).
    pub(in crate::eval) fn shape_table(&mut self, node: &Node) -> Result<Shape> {
        let args = values(node);
        // The values a shape takes, in order, or a located error naming what is missing.
        // (At the first value too many, or at the shape's word.)
        let count = |n: usize, form: &str| -> Diagnostic {
            let at = args.get(n).map_or(node.word_span, |e| e.span);
            Diagnostic::error(format!("`{}` takes {n} values: {form}", node.word), at)
        };
        Ok(match node.word.as_str() {
            "quadric" => {
                let &[square, mixed, linear, constant] = args.as_slice() else {
                    return Err(count(4, "quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }"));
                };
                Shape::Quadric(Box::new(Quadric {
                    square: self.vec3(square)?,
                    mixed: self.vec3(mixed)?,
                    linear: self.vec3(linear)?,
                    constant: self.float(constant)?,
                }))
            }
            "cubic" | "quartic" | "poly" => {
                let form = match node.word.as_str() {
                    "poly" => "poly { N, <coefficients> }",
                    "cubic" => "cubic { <20 coefficients> }",
                    _ => "quartic { <35 coefficients> }",
                };
                let (degree, list) = match (node.word.as_str(), args.as_slice()) {
                    ("cubic", &[list]) => (3, list),
                    ("quartic", &[list]) => (4, list),
                    ("poly", &[n_expr, list]) => {
                        let n = self.float(n_expr)?;
                        if !(2.0..=6.0).contains(&n) {
                            return Err(Diagnostic::error(
                                "unsupported: a poly of degree other than 2 to 6 (trace's root solver goes to 6)",
                                n_expr.span,
                            ));
                        }
                        (n as u8, list)
                    }
                    _ => return Err(count(if node.word == "poly" { 2 } else { 1 }, form)),
                };
                // The coefficients: a literal list of any length (POV-Ray reads it so).
                let coefficients = match &list.kind {
                    crate::syntax::ExprKind::Vector(items) => items
                        .iter()
                        .map(|e| self.float(e))
                        .collect::<Result<Vec<f64>>>()?,
                    _ => match self.eval(list)? {
                        Value::Vector(v) => v.c[..v.len].to_vec(),
                        other => {
                            return Err(type_error("a list of coefficients", &other, list.span));
                        }
                    },
                };
                let polynomial = Polynomial::from_povray(degree, &coefficients).ok_or_else(|| {
                    let n = degree as usize;
                    Diagnostic::error(
                        format!(
                            "a polynomial of degree {degree} has {} coefficients, this list has {}",
                            (n + 1) * (n + 2) * (n + 3) / 6,
                            coefficients.len()
                        ),
                        list.span,
                    )
                })?;
                Shape::Polynomial(Box::new(polynomial))
            }
            "polygon" => {
                let &[n_expr, ref listed @ ..] = args.as_slice() else {
                    return Err(count(1, "polygon { N, P1, …, PN }"));
                };
                let n = self.float(n_expr)?;
                if n < 3.0 {
                    return Err(Diagnostic::error(
                        "a polygon needs at least three points",
                        n_expr.span,
                    ));
                }
                if listed.len() != n as usize {
                    return Err(Diagnostic::error(
                        format!(
                            "this polygon announces {} points and lists {}",
                            n as usize,
                            listed.len()
                        ),
                        n_expr.span,
                    ));
                }
                let mut points = listed
                    .iter()
                    .map(|e| self.vec3(e))
                    .collect::<Result<Vec<_>>>()?;
                // POV-Ray's closing: a point equal (within 1e-10) to its sub-polygon's first
                // closes it and starts the next; an open last one is closed with a warning.
                let mut first = points[0];
                let mut closed = false;
                let mut i = 1;
                while i < points.len() {
                    closed = false;
                    if (points[i] - first).abs().max_element() < 1e-10 {
                        points[i] = first;
                        i += 1;
                        if i < points.len() {
                            first = points[i];
                        }
                        closed = true;
                    }
                    i += 1;
                }
                if !closed {
                    self.warn(Diagnostic::warning(
                        "polygon not closed: closing it (as POV-Ray does)",
                        node.word_span,
                    ));
                    points.push(first);
                }
                Shape::Polygon(Box::new(points))
            }
            "text" => self.text(node)?,
            "prism" => self.prism(node)?,
            "lathe" => self.lathe(node)?,
            "height_field" => self.height_field(node)?,
            "bicubic_patch" => self.bicubic_patch(node)?,
            "julia_fractal" => self.julia_fractal(node)?,
            "ovus" => {
                let &[bottom, top] = args.as_slice() else {
                    return Err(count(2, "ovus { bottom_radius, top_radius }"));
                };
                let (bottom, top) = (self.float(bottom)?, self.float(top)?);
                if bottom < 0.0 || top < 0.0 {
                    return Err(Diagnostic::error(
                        "both ovus radii must be positive",
                        node.word_span,
                    ));
                }
                if top >= 2.0 * bottom {
                    // POV-Ray draws the sphere such an ovus would be.
                    self.warn(Diagnostic::warning(
                        "ovus top radius not below twice the bottom one: a sphere is drawn (as POV-Ray draws it)",
                        node.word_span,
                    ));
                    Shape::Sphere {
                        centre: glam::DVec3::new(0.0, bottom, 0.0),
                        radius: top,
                    }
                } else {
                    Shape::Ovus { bottom, top }
                }
            }
            "sor" => self.sor(node)?,
            "sphere_sweep" => self.sphere_sweep(node)?,
            "superellipsoid" => {
                let &[exponents] = args.as_slice() else {
                    return Err(count(1, "superellipsoid { <e, n> }"));
                };
                let v = self.uv(exponents)?;
                Shape::Superellipsoid { e: v.x, n: v.y }
            }
            _ => return Err(self.unknown_word(&node.word, node.word_span)),
        })
    }

    /// `text { ttf "font" "string" thickness [,] offset }` or `internal N` for the font.
    fn text(&mut self, node: &Node) -> Result<Shape> {
        let form = "text { ttf \"font.ttf\" \"string\" thickness, offset }";
        let items = items(node);
        let (font, values) = match items.split_first() {
            Some((Item::Word(w), rest)) => (*w, rest),
            _ => {
                return Err(Diagnostic::error(
                    format!("`text` starts with the font: {form}"),
                    node.word_span,
                ));
            }
        };
        let values: Vec<&Expr> = values
            .iter()
            .map(|i| match i {
                Item::Value(e) => Ok(*e),
                Item::Word(w) => Err(Diagnostic::error(
                    format!("unexpected `{}` in {form}", w.word),
                    w.span,
                )),
            })
            .collect::<Result<_>>()?;
        if values.len() != 4 {
            let at = values.get(4).map_or(node.word_span, |e| e.span);
            return Err(Diagnostic::error(
                format!("`text` takes a font and three values: {form}"),
                at,
            ));
        }
        let (path, name) = if font.word == "ttf" {
            let name = self.string(values[0])?;
            (self.find_font(&name, values[0].span)?, name)
        } else {
            // POV-Ray's built-in fonts are its bundled files, read from the include folders.
            let name = match self.float(values[0])? as i64 {
                1 => "timrom.ttf",
                2 => "cyrvetic.ttf",
                3 => "crystal.ttf",
                _ => "povlogo.ttf",
            };
            let path = self.find_font(name, values[0].span).map_err(|e| {
                Diagnostic::error(
                    format!("{} (`internal` fonts are POV-Ray's bundled fonts: give -L with POV-Ray's include folder)", e.message),
                    values[0].span,
                )
            })?;
            (path, name.to_string())
        };
        let string = self.string(values[1])?;
        let thickness = self.float(values[2])?;
        let offset = self.vec3(values[3])?;
        let data = self.font_data(&path, &name, values[0].span)?;
        let codes: Vec<u32> = match self.scene.charset {
            // POV-Ray's default `charset ascii` reads the string's bytes: each byte beyond
            // ASCII is a space.
            crate::font::Charset::Ascii => string
                .chars()
                .flat_map(|c| {
                    let n = if c.is_ascii() { 1 } else { c.len_utf8() };
                    std::iter::repeat_n(if c.is_ascii() { u32::from(c) } else { 0x20 }, n)
                })
                .collect(),
            // `utf8` (and `sys`): characters, those beyond 16 bits as U+FFFD, as POV-Ray
            // keeps them.
            crate::font::Charset::Utf8 => string
                .chars()
                .map(|c| {
                    if u32::from(c) > 0xFFFF {
                        0xFFFD
                    } else {
                        u32::from(c)
                    }
                })
                .collect(),
        };
        let text = crate::font::layout(
            &data,
            &codes,
            thickness,
            offset.truncate(),
            self.scene.charset,
        )
        .map_err(|e| Diagnostic::error(format!("cannot read font {name}: {e}"), values[0].span))?;
        Ok(Shape::Text(Box::new(text)))
    }

    /// The font file `name` names, as POV-Ray looks for it: the name as given when it ends in
    /// `.ttf`, then with `.ttf` or `.TTF` added, then as given.
    fn find_font(&mut self, name: &str, span: Span) -> Result<std::path::PathBuf> {
        let lower = name.to_ascii_lowercase();
        let mut candidates = Vec::new();
        if lower.ends_with(".ttf") {
            candidates.push(name.to_string());
        }
        candidates.push(format!("{name}.ttf"));
        candidates.push(format!("{name}.TTF"));
        if !lower.ends_with(".ttf") {
            candidates.push(name.to_string());
        }
        for c in &candidates {
            if let Ok(path) = self.sandbox.find(c) {
                return Ok(path);
            }
        }
        self.find_file(name, "font", span)
    }

    /// A font file's bytes, read once per scene.
    fn font_data(
        &mut self,
        path: &std::path::Path,
        name: &str,
        span: Span,
    ) -> Result<Arc<Vec<u8>>> {
        if let Some(data) = self.scene.fonts.get(path) {
            return Ok(Arc::clone(data));
        }
        let cannot = |e: String| Diagnostic::error(format!("cannot read font {name}: {e}"), span);
        let size = std::fs::metadata(path)
            .map_err(|e| cannot(e.to_string()))?
            .len();
        if size > MAX_FONT_BYTES {
            return Err(cannot(format!(
                "{size} bytes; trace reads fonts up to {MAX_FONT_BYTES}"
            )));
        }
        let data = Arc::new(std::fs::read(path).map_err(|e| cannot(e.to_string()))?);
        self.scene
            .fonts
            .insert(path.to_path_buf(), Arc::clone(&data));
        Ok(data)
    }

    /// `prism { [spline] [sweep] h1, h2, N, <x, z>… [open] }`.
    fn prism(&mut self, node: &Node) -> Result<Shape> {
        let form = "prism { [linear_spline|quadratic_spline|cubic_spline|bezier_spline] [linear_sweep|conic_sweep] height1, height2, N, <x, z>… }";
        let (mut spline, mut sweep, mut open, mut sturm) =
            (Spline::Linear, Sweep::Linear, false, false);
        let mut values = Vec::new();
        for item in items(node) {
            match item {
                Item::Value(e) => values.push(e),
                Item::Word(w) if spline_word(&w.word).is_some() => {
                    spline = spline_word(&w.word).unwrap_or(spline);
                }
                Item::Word(w) => match w.word.as_str() {
                    "linear_sweep" => sweep = Sweep::Linear,
                    "conic_sweep" => sweep = Sweep::Conic,
                    "open" => open = true,
                    _ => sturm = true,
                },
            }
        }
        if values.len() < 3 {
            return Err(Diagnostic::error(
                format!("`prism` takes {form}"),
                node.word_span,
            ));
        }
        let (mut h1, mut h2) = (self.float(values[0])?, self.float(values[1])?);
        if h1 > h2 {
            std::mem::swap(&mut h1, &mut h2);
        }
        let n = self.float(values[2])?.max(0.0) as usize;
        let (minimum, message) = match spline {
            Spline::Linear => (3, "a prism with linear splines needs at least three points"),
            Spline::Quadratic => (
                5,
                "a prism with quadratic splines needs at least five points",
            ),
            Spline::Cubic => (6, "a prism with cubic splines needs at least six points"),
            Spline::Bezier => (
                4,
                "a prism with Bézier splines needs four points per segment",
            ),
        };
        if n < minimum || (spline == Spline::Bezier && n % 4 != 0) {
            return Err(Diagnostic::error(message, values[2].span));
        }
        if values.len() - 3 != n {
            return Err(Diagnostic::error(
                format!(
                    "this prism announces {n} points and lists {}",
                    values.len() - 3
                ),
                values[2].span,
            ));
        }
        let mut points = Vec::with_capacity(n);
        for e in &values[3..] {
            points.push(self.uv(e)?);
        }
        let same = |a: DVec2, b: DVec2| (a - b).abs().max_element() < 1e-10;
        // POV-Ray's closing check: the last point scanned must close its sub-curve.
        let closed = match spline {
            Spline::Bezier => {
                let mut start = points[0];
                let mut ok = true;
                for s in (4..n).step_by(4) {
                    if !same(points[s], points[s - 1]) {
                        ok &= same(points[s - 1], start);
                        start = points[s];
                    }
                }
                ok && same(points[n - 1], start)
            }
            _ => {
                let (mut first, mut i, lead) = match spline {
                    Spline::Linear => (points[0], 1, 0),
                    Spline::Quadratic => (points[1], 2, 1),
                    _ => (points[1], 2, 2),
                };
                let mut closed = false;
                while i < n {
                    closed = false;
                    if same(points[i], first) {
                        closed = true;
                        // The next sub-curve: its leading control points, then its start.
                        i += lead + 1;
                        if i < n {
                            first = points[i];
                        }
                    }
                    i += 1;
                }
                closed
            }
        };
        if !closed {
            if spline == Spline::Linear {
                self.warn(Diagnostic::warning(
                    "linear prism not closed: closing it (as POV-Ray does)",
                    node.word_span,
                ));
                let start = last_start(&points, same);
                points.push(start);
            } else if spline == Spline::Bezier {
                // POV-Ray warns and draws nothing.
                self.warn(Diagnostic::warning(
                    "prism not closed: ignoring it (as POV-Ray does)",
                    node.word_span,
                ));
                points.clear();
            } else {
                return Err(Diagnostic::error(
                    "this prism's last sub-curve is not closed (its last point must repeat its first, then the control points follow)",
                    node.word_span,
                ));
            }
        }
        let segments =
            Prism::segments(spline, &points).map_err(|m| Diagnostic::error(m, values[2].span))?;
        Ok(Shape::Prism(Box::new(Prism {
            sweep,
            degree: spline.degree(),
            heights: (h1, h2),
            closed: !open,
            segments,
            sturm,
        })))
    }

    /// The values and words of a `lathe` or `sor`: its count N, the N points, the last spline
    /// word and whether `open` and `sturm` were given.
    #[allow(clippy::type_complexity)]
    fn profile(
        &mut self,
        node: &Node,
        form: &str,
    ) -> Result<(Vec<DVec2>, Vec<Span>, Spline, bool, bool, Span)> {
        let (mut spline, mut open, mut sturm) = (Spline::Linear, false, false);
        let mut values = Vec::new();
        for item in items(node) {
            match item {
                Item::Value(e) => values.push(e),
                Item::Word(w) if spline_word(&w.word).is_some() => {
                    spline = spline_word(&w.word).unwrap_or(spline);
                }
                Item::Word(w) => match w.word.as_str() {
                    "open" => open = true,
                    _ => sturm = true,
                },
            }
        }
        let Some((count, points)) = values.split_first() else {
            return Err(Diagnostic::error(
                format!("`{}` takes {form}", node.word),
                node.word_span,
            ));
        };
        let n = self.float(count)?.max(0.0) as usize;
        if points.len() != n {
            return Err(Diagnostic::error(
                format!(
                    "this {} announces {n} points and lists {}",
                    node.word,
                    points.len()
                ),
                count.span,
            ));
        }
        let spans = points.iter().map(|e| e.span).collect();
        let points = points
            .iter()
            .map(|e| self.uv(e))
            .collect::<Result<Vec<_>>>()?;
        Ok((points, spans, spline, open, sturm, count.span))
    }

    /// `lathe { [spline] N, <r, y>… }`.
    fn lathe(&mut self, node: &Node) -> Result<Shape> {
        let form = "lathe { [linear_spline|quadratic_spline|cubic_spline|bezier_spline] N, <radius, height>… }";
        let (points, spans, spline, _, sturm, at) = self.profile(node, form)?;
        let n = points.len();
        let (minimum, message) = match spline {
            Spline::Linear => (2, "a lathe with linear splines needs at least two points"),
            Spline::Quadratic => (
                3,
                "a lathe with quadratic splines needs at least three points",
            ),
            Spline::Cubic => (4, "a lathe with cubic splines needs at least four points"),
            Spline::Bezier => (
                4,
                "a lathe with Bézier splines needs four points per segment",
            ),
        };
        if n < minimum || (spline == Spline::Bezier && n % 4 != 0) {
            return Err(Diagnostic::error(message, at));
        }
        // Only the end points may have a negative radius (POV-Ray's check).
        if let Some(i) = (1..n - 1).find(|&i| points[i].x < 0.0) {
            return Err(Diagnostic::error(
                format!(
                    "point {} of this lathe has a negative radius (only the first and last may)",
                    i + 1
                ),
                spans[i],
            ));
        }
        Ok(Shape::Lathe(Box::new(Lathe {
            degree: spline.degree(),
            segments: Lathe::segments(spline, &points),
            sturm,
        })))
    }

    /// `sor { N, <r, y>… [open] }`.
    fn sor(&mut self, node: &Node) -> Result<Shape> {
        let (points, spans, _, open, sturm, at) =
            self.profile(node, "sor { N, <radius, height>… [open] }")?;
        let n = points.len();
        if n < 4 {
            return Err(Diagnostic::error(
                "a surface of revolution needs at least four points",
                at,
            ));
        }
        // POV-Ray's checks: no negative radius, heights rising from the second point to the
        // last but one.
        for i in 0..n {
            if points[i].x < 0.0 || (i > 1 && i < n - 1 && points[i].y <= points[i - 1].y) {
                return Err(Diagnostic::error(
                    format!(
                        "point {} of this surface of revolution has a negative radius or is not above the one before",
                        i + 1
                    ),
                    spans[i],
                ));
            }
        }
        let segments = Sor::segments(&points).map_err(|m| Diagnostic::error(m, at))?;
        Ok(Shape::Sor(Box::new(Sor {
            segments,
            closed: !open,
            sturm,
        })))
    }

    /// `height_field { [png] "file" [smooth] [water_level W] [hierarchy on|off] }`.
    fn height_field(&mut self, node: &Node) -> Result<Shape> {
        let items = items(node);
        if let Some(f) = node
            .children
            .iter()
            .find(|c| c.kind == NodeKind::FunctionImage)
        {
            let (width, depth, heights) = self.function_heights(f)?;
            let (smooth, water_level) = self.height_field_options(&items, 0)?;
            return Ok(Shape::HeightField(Box::new(crate::ir::HeightField {
                width,
                depth,
                heights: Arc::new(heights),
                smooth,
                water_level: 65536.0 * water_level,
            })));
        }
        let mut i = 0;
        let mut kind = None;
        if let Some(Item::Word(w)) = items.first() {
            if !matches!(w.word.as_str(), "smooth" | "water_level" | "hierarchy") {
                kind = Some(*w);
                i = 1;
            }
        }
        let Some(Item::Value(file)) = items.get(i) else {
            return Err(Diagnostic::error(
                "`height_field` starts with its image: height_field { png \"file.png\" … }",
                node.word_span,
            ));
        };
        i += 1;
        let name = self.string(file)?;
        let file_type = match kind {
            Some(w) => Some(crate::eval::build::images::FileType::from_keyword(&w.word).ok_or_else(|| {
                Diagnostic::error(
                    format!("`{}` is not an image format (png, jpeg, gif, tga, ppm, pgm, tiff, bmp, exr, hdr)", w.word),
                    w.span,
                )
            })?),
            None => None,
        };
        let type_span = kind.map_or(file.span, |w| w.span);
        let (smooth, water_level) = self.height_field_options(&items, i)?;
        let (path, picture) = self.read_image(&name, file_type, type_span, file.span)?;
        let cannot = |e: String| {
            Diagnostic::error(format!("cannot read height field {name}: {e}"), file.span)
        };
        if picture.width < 2 || picture.height < 2 {
            return Err(cannot(format!(
                "{}×{} pixels: a height field needs at least 2×2",
                picture.width, picture.height
            )));
        }
        // PNG files go through POV-Ray's PNG reader's own conversions (heightfield.rs).
        let is_png = file_type.or_else(|| crate::eval::build::images::FileType::from_name(&name))
            == Some(crate::eval::build::images::FileType::Png);
        let (width, depth, heights) = if is_png {
            crate::eval::build::heightfield::read_png(&path).map_err(cannot)?
        } else {
            (picture.width, picture.height, picture.heights())
        };
        Ok(Shape::HeightField(Box::new(crate::ir::HeightField {
            width,
            depth,
            heights: Arc::new(heights),
            smooth,
            water_level: 65536.0 * water_level,
        })))
    }

    /// A height field's `smooth`, `water_level W` and `hierarchy` from item `i` on.
    fn height_field_options(&mut self, items: &[Item], mut i: usize) -> Result<(bool, f64)> {
        let (mut smooth, mut water_level) = (false, 0.0);
        while let Some(item) = items.get(i) {
            i += 1;
            match item {
                Item::Word(w) if w.word == "smooth" => smooth = true,
                Item::Word(w) if w.word == "water_level" => match items.get(i) {
                    Some(Item::Value(e)) => {
                        water_level = self.float(e)?;
                        i += 1;
                    }
                    _ => return Err(Diagnostic::error("`water_level` needs a value", w.span)),
                },
                // `hierarchy` is how POV-Ray speeds the search up: nothing to draw.
                Item::Word(w) if w.word == "hierarchy" => {
                    if let Some(Item::Value(e)) = items.get(i) {
                        self.float(e)?;
                        i += 1;
                    }
                }
                Item::Word(w) => {
                    return Err(Diagnostic::error(
                        format!("unexpected `{}` here", w.word),
                        w.span,
                    ));
                }
                Item::Value(e) => {
                    return Err(Diagnostic::error(
                        "unexpected value in this height_field",
                        e.span,
                    ));
                }
            }
        }
        Ok((smooth, water_level))
    }

    /// `function W, H { … }`: POV-Ray's W×H image of the function at x = column/(W − 1),
    /// y = row/(H − 1), z = 0, each value kept as POV-Ray keeps it in its 16-bit grey image
    /// (single precision times 65535, cut to an integer, wrapping outside 0..1); the field's
    /// row z is the image's row H − 1 − z, as for image files.
    fn function_heights(&mut self, f: &Node) -> Result<(u32, u32, Vec<u16>)> {
        let size = |ev: &mut Self, e: &Expr| -> Result<u32> {
            let v = (ev.float(e)? + 0.5).floor();
            if !(2.0..=4096.0).contains(&v) {
                return Err(Diagnostic::error(
                    "a function height field is 2 to 4096 points a side",
                    e.span,
                ));
            }
            Ok(v as u32)
        };
        let View::FunctionImage {
            width,
            height,
            body,
        } = f.view()
        else {
            return Err(crate::eval::malformed(f, "a function image"));
        };
        let (width, depth) = (size(self, width)?, size(self, height)?);
        let point = |x: u32, z: u32| {
            let y = f64::from(depth - 1 - z) / f64::from(depth - 1);
            glam::DVec3::new(f64::from(x) / f64::from(width - 1), y, 0.0)
        };
        // A pigment: POV-Ray keeps its colours in a 16-bit image, whose grey is the height.
        if let Some(p) = f.children.iter().find(|c| c.kind == NodeKind::Pigment) {
            let pigment =
                self.pigment(p, crate::ir::Pigment::solid(crate::ir::Colour::default()))?;
            let pigment = pigment.placed(self.scene_defaults());
            let mut heights = Vec::with_capacity((width * depth) as usize);
            for z in 0..depth {
                for x in 0..width {
                    let q = point(x, z);
                    let c = pigment.colour_at(q).rgb;
                    let channel = crate::eval::build::heightfield::channel16;
                    heights.push(crate::eval::build::heightfield::grey16([
                        channel(c.x),
                        channel(c.y),
                        channel(c.z),
                    ]));
                }
            }
            return Ok((width, depth, heights));
        }
        let body = Node {
            kind: NodeKind::Function,
            args: body.into_iter().cloned().collect(),
            children: Vec::new(),
            ..f.clone()
        };
        let function = self.function(&body)?;
        let generator = self.noise_generator();
        let mut heights = Vec::with_capacity((width * depth) as usize);
        for z in 0..depth {
            for x in 0..width {
                let v = function.at(point(x, z), generator);
                heights.push(crate::eval::build::heightfield::channel16(v));
            }
        }
        Ok((width, depth, heights))
    }

    /// `bicubic_patch { type T [flatness F] [u_steps U] [v_steps V] P00, P01, … P33 }`.
    fn bicubic_patch(&mut self, node: &Node) -> Result<Shape> {
        let (mut kind, mut flatness, mut steps) = (None, 0.0, [0u32, 0]);
        let mut uv_corners = None;
        let mut points = Vec::new();
        let items = items(node);
        let mut i = 0;
        while let Some(item) = items.get(i) {
            i += 1;
            match item {
                Item::Value(e) => points.push(self.vec3(e)?),
                Item::Word(w) => {
                    if w.word == "uv_vectors" {
                        let mut corners = [[0.0; 2]; 4];
                        for corner in &mut corners {
                            let Some(Item::Value(e)) = items.get(i) else {
                                return Err(Diagnostic::error(
                                    "`uv_vectors` takes 4 uv vectors",
                                    w.span,
                                ));
                            };
                            i += 1;
                            let v = self.vec3(e)?;
                            *corner = [v.x, v.y];
                        }
                        uv_corners = (corners != [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
                            .then_some(corners);
                        continue;
                    }
                    let Some(Item::Value(e)) = items.get(i) else {
                        return Err(Diagnostic::error(
                            format!("`{}` needs a value", w.word),
                            w.span,
                        ));
                    };
                    i += 1;
                    let v = self.float(e)?;
                    match w.word.as_str() {
                        "type" => kind = Some((v as i64, e.span)),
                        "flatness" => flatness = v,
                        "u_steps" => steps[0] = v.max(0.0) as u32,
                        "v_steps" => steps[1] = v.max(0.0) as u32,
                        _ => {} // `accuracy`: read and unused, as in POV-Ray.
                    }
                }
            }
        }
        match kind {
            None => {
                return Err(Diagnostic::error(
                    "a bicubic_patch needs its `type` (0 or 1)",
                    node.word_span,
                ));
            }
            Some((t, span)) if t > 1 => {
                self.warn(Diagnostic::warning(
                    "bicubic_patch type above 1: type 1 is used (as POV-Ray does)",
                    span,
                ));
            }
            _ => {}
        }
        if points.len() != 16 {
            return Err(Diagnostic::error(
                format!(
                    "a bicubic_patch takes 16 control points, this one has {}",
                    points.len()
                ),
                node.word_span,
            ));
        }
        Ok(Shape::BicubicPatch(Box::new(crate::ir::BicubicPatch {
            points: std::array::from_fn(|i| std::array::from_fn(|j| points[4 * i + j])),
            u_steps: steps[0],
            v_steps: steps[1],
            flatness,
            uv_corners,
        })))
    }

    /// `julia_fractal { <c> [quaternion|hypercomplex] [sqr|cube] [max_iteration N]
    /// [precision P] [slice <s>, d] }`.
    fn julia_fractal(&mut self, node: &Node) -> Result<Shape> {
        let items = items(node);
        let vec4 = |ev: &mut Self, e: &Expr| -> Result<glam::DVec4> {
            match ev.eval(e)? {
                Value::Vector(v) if v.len == 4 => {
                    Ok(glam::DVec4::new(v.c[0], v.c[1], v.c[2], v.c[3]))
                }
                other => Err(type_error("a 4-D vector", &other, e.span)),
            }
        };
        let Some(Item::Value(first)) = items.first() else {
            return Err(Diagnostic::error(
                "`julia_fractal` starts with its 4-D parameter <a, b, c, d>",
                node.word_span,
            ));
        };
        let mut j = crate::ir::JuliaFractal {
            c: vec4(self, first)?,
            hypercomplex: false,
            cube: false,
            iterations: 20,
            precision: 20.0,
            slice: (glam::DVec4::W, 0.0),
        };
        let mut i = 1;
        while let Some(item) = items.get(i) {
            i += 1;
            let Item::Word(w) = item else {
                let Item::Value(e) = item else { unreachable!() };
                let text = match &e.kind {
                    crate::syntax::ExprKind::Ident(name, _) => name.as_str(),
                    _ => "",
                };
                if matches!(
                    text,
                    "exp"
                        | "ln"
                        | "sin"
                        | "asin"
                        | "cos"
                        | "acos"
                        | "tan"
                        | "atan"
                        | "sinh"
                        | "asinh"
                        | "cosh"
                        | "acosh"
                        | "tanh"
                        | "atanh"
                ) {
                    return Err(Diagnostic::error(
                        format!(
                            "unsupported: the julia_fractal function `{text}` (trace draws sqr and cube)"
                        ),
                        e.span,
                    ));
                }
                return Err(Diagnostic::error(
                    "unexpected value in this julia_fractal",
                    e.span,
                ));
            };
            let mut value = |ev: &mut Self| -> Result<&Expr> {
                match items.get(i) {
                    Some(Item::Value(e)) => {
                        i += 1;
                        let _ = ev;
                        Ok(*e)
                    }
                    _ => Err(Diagnostic::error(
                        format!("`{}` needs a value", w.word),
                        w.span,
                    )),
                }
            };
            match w.word.as_str() {
                "quaternion" => j.hypercomplex = false,
                "hypercomplex" => j.hypercomplex = true,
                "sqr" => j.cube = false,
                "cube" => j.cube = true,
                "max_iteration" => {
                    let e = value(self)?;
                    j.iterations = self.float(e)?.floor().max(1.0) as u32;
                }
                "precision" => {
                    let e = value(self)?;
                    let p = self.float(e)?.max(1.0);
                    // Bounded: every unit of precision is a marching step a unit of ray.
                    if p > MAX_JULIA_PRECISION {
                        self.warn(Diagnostic::warning(
                            format!("julia_fractal precision above {MAX_JULIA_PRECISION}: {MAX_JULIA_PRECISION} is used"),
                            e.span,
                        ));
                    }
                    j.precision = p.min(MAX_JULIA_PRECISION);
                }
                _ => {
                    let e = value(self)?;
                    let s = vec4(self, e)?;
                    let d = value(self)?;
                    let d = self.float(d)?;
                    if s.length_squared() < 1e-10 || (s.w / s.length()).abs() < 1e-10 {
                        return Err(Diagnostic::error(
                            "a julia_fractal's slice needs a normal with a non-zero fourth component",
                            e.span,
                        ));
                    }
                    j.slice = (s, d);
                }
            }
        }
        // Bounded: POV-Ray sets no limit, but a million iterations a point is no picture.
        j.iterations = j.iterations.min(10_000);
        Ok(Shape::JuliaFractal(Box::new(j)))
    }

    /// `sphere_sweep { linear_spline|cubic_spline|b_spline N, <centre>, radius… [tolerance T] }`.
    fn sphere_sweep(&mut self, node: &Node) -> Result<Shape> {
        let form = "sphere_sweep { linear_spline|cubic_spline|b_spline N, <centre>, radius… [tolerance T] }";
        let items = items(node);
        let spline = match items.first() {
            Some(Item::Word(w)) if w.word == "linear_spline" => SweepSpline::Linear,
            Some(Item::Word(w)) if w.word == "cubic_spline" => SweepSpline::CatmullRom,
            Some(Item::Word(w)) if w.word == "b_spline" => SweepSpline::BSpline,
            _ => {
                return Err(Diagnostic::error(
                    format!("a sphere_sweep starts with its kind of spline: {form}"),
                    node.word_span,
                ));
            }
        };
        let mut values = Vec::new();
        let mut tolerance = 1e-6;
        let mut i = 1;
        while let Some(item) = items.get(i) {
            i += 1;
            match item {
                Item::Value(e) => values.push(*e),
                Item::Word(w) if w.word == "tolerance" && i == items.len() - 1 => {
                    if let Some(Item::Value(e)) = items.get(i) {
                        tolerance = self.float(e)?;
                        i += 1;
                    }
                }
                Item::Word(w) => {
                    return Err(Diagnostic::error(
                        format!("`{}` is out of place here: {form}", w.word),
                        w.span,
                    ));
                }
            }
        }
        let Some((count, rest)) = values.split_first() else {
            return Err(Diagnostic::error(
                format!("`sphere_sweep` takes {form}"),
                node.word_span,
            ));
        };
        let n = self.float(count)?;
        let least = if spline == SweepSpline::Linear {
            2.0
        } else {
            4.0
        };
        if n < least {
            return Err(Diagnostic::error(
                "too few spheres for this sphere_sweep's spline (linear needs 2, the cubic ones 4)",
                count.span,
            ));
        }
        let n = n as usize;
        if rest.len() % 2 != 0 || rest.len() / 2 != n {
            return Err(Diagnostic::error(
                format!(
                    "this sphere_sweep announces {n} spheres and gives {} values (a centre and a radius each)",
                    rest.len()
                ),
                count.span,
            ));
        }
        let mut spheres = Vec::with_capacity(n);
        for pair in rest.chunks(2) {
            spheres.push((self.vec3(pair[0])?, self.float(pair[1])?));
        }
        Ok(Shape::SphereSweep(Box::new(SphereSweep {
            spline,
            spheres,
            tolerance,
        })))
    }

    /// A 2-D point `<a, b>` (a float is `<f, f>`).
    pub(in crate::eval) fn uv(&mut self, e: &Expr) -> Result<DVec2> {
        match self.eval(e)? {
            Value::Float(f) => Ok(DVec2::splat(f)),
            Value::Vector(v) if v.len == 2 => Ok(DVec2::new(v.c[0], v.c[1])),
            other => Err(type_error("a 2-D vector <u, v>", &other, e.span)),
        }
    }
}

/// The first point of the last linear sub-polygon (where an unclosed prism closes).
fn last_start(points: &[DVec2], same: impl Fn(DVec2, DVec2) -> bool) -> DVec2 {
    let mut first = points[0];
    let mut i = 1;
    while i < points.len() {
        if same(points[i], first) {
            i += 1;
            if i < points.len() {
                first = points[i];
            }
        }
        i += 1;
    }
    first
}

#[cfg(test)]
mod tests {
    use crate::ir::Polynomial;

    /// POV-Ray's order of a polynomial's terms: by the power of x, then of y, then of z, each
    /// descending (`x⁴, x³y, x³z, x³, x²y², x²yz, …, z, 1`).
    #[test]
    fn polynomial_coefficients_follow_povrays_order() {
        let all = |degree: u8, n: usize| {
            Polynomial::from_povray(degree, &(1..=n).map(|v| v as f64).collect::<Vec<_>>())
                .expect("the right count")
        };
        assert_eq!(all(2, 10).terms.len(), 10);
        assert_eq!(all(3, 20).terms.len(), 20);
        let q = all(4, 35);
        let powers: Vec<[u8; 3]> = q.terms.iter().map(|t| t.1).collect();
        assert_eq!(
            &powers[..6],
            &[
                [4, 0, 0],
                [3, 1, 0],
                [3, 0, 1],
                [3, 0, 0],
                [2, 2, 0],
                [2, 1, 1]
            ]
        );
        assert_eq!(powers[20], [0, 4, 0]);
        assert_eq!(&powers[33..], &[[0, 0, 1], [0, 0, 0]]);
        assert!(Polynomial::from_povray(4, &[1.0; 34]).is_none());
        // Zero terms are left out.
        let mut c = [0.0; 35];
        c[34] = -1.0;
        assert_eq!(
            Polynomial::from_povray(4, &c).unwrap().terms,
            vec![(-1.0, [0, 0, 0])]
        );
    }
}
