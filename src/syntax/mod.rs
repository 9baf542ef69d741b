//! The pest front end: scene text → syntax tree with spans.
//!
//! This is the only module that names pest's `Rule`. The tree it produces is deliberately
//! uniform: every construct is a [`Node`] (a keyword with its expressions and child nodes), and
//! every expression an [`Expr`]. What the constructs *mean* is decided in `eval`.

pub mod ahead;
pub mod bulk;
mod incremental;
pub mod keywords;
pub mod lexer;
pub mod plain;
mod unit;
pub mod view;

pub use unit::{Piece, Slot, Unit};
pub use view::View;

mod grammar {
    #[derive(pest_derive::Parser)]
    #[grammar = "grammar/scene.pest"]
    pub struct SceneParser;
}

use crate::diag::{Diagnostic, FileId, Span};
use grammar::{Rule, SceneParser};
use pest::Parser;
use pest::iterators::Pair;

/// What a node is: one variant per construct of the grammar.
#[allow(missing_docs)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NodeKind {
    // Directives and scene-wide items.
    Declare,
    Default,
    Camera,
    LightSource,
    Background,
    Fog,
    FogDistance,
    FogType,
    FogAlt,
    FogOffset,
    TurbDepth,
    FogColour,
    /// `media { … }`: in an interior, or (standing alone) the atmosphere.
    Media,
    /// A media setting (`samples 10, 20`, `absorption C`): its word and values.
    MediaSetting,
    /// `scattering { TYPE, COLOUR … }`.
    Scattering,
    /// `eccentricity G` or `extinction E` in a scattering block.
    ScatteringSetting,
    /// `density { … }`: a pigment's body whose colour is a medium's density.
    Density,
    /// `media_interaction B` or `media_attenuation B` of a light.
    LightMedia,
    /// `dispersion D` or `dispersion_samples N` of an interior.
    Dispersion,
    /// `rainbow { … }`.
    Rainbow,
    /// A rainbow's `angle`, `width`, `distance`, `jitter`, `arc_angle` or `falloff_angle`.
    RainbowSetting,
    GlobalSettings,
    AssumedGamma,
    MaxTraceLevel,
    AdcBailout,
    AmbientLight,
    /// `max_intersections N` (read and ignored, as POV-Ray 3.7 does).
    MaxIntersections,
    // Camera items.
    Perspective,
    /// A camera type other than perspective, orthographic and cylinder: its keyword is the word.
    CameraType,
    /// `mesh_camera { RAYS DISTRIBUTION [MAX] meshes… [smooth] }`: args the numbers,
    /// children the meshes (and directives) and the `smooth` flag.
    MeshCamera,
    /// `smooth` at the end of a `mesh_camera`.
    MeshCameraSmooth,
    Orthographic,
    Location,
    LookAt,
    Direction,
    Up,
    Right,
    Sky,
    Angle,
    // Objects.
    Sphere,
    Plane,
    Box,
    ObjectRef,
    Cylinder,
    Cone,
    Disc,
    Torus,
    /// A shape of the evaluator's shape table (`quadric { … }`): its keyword is the word.
    Shape,
    /// A focal blur item of a camera (`aperture 0.5`): its word and values.
    CameraBlur,
    /// `charset ascii|utf8|sys` in global_settings: the word is the whole item.
    Charset,
    /// `blob { … }`.
    Blob,
    /// `function [(params)] { expression }`: the parameters (`FunctionParams`, its text in
    /// `word`) and the body in `args`.
    Function,
    /// `pattern { PATTERN modifiers }` in `function { }`: a pattern's value as a function.
    PatternFunction,
    /// `spline { … }`: kinds as IdentRef children, the rest (a declared spline, then the
    /// entries' parameters and values) as args.
    Spline,
    /// `pigment_pattern { PIGMENT }` (a pattern's child).
    PigmentPattern,
    /// `(a, b, …)` of a function: the text, in `word`.
    FunctionParams,
    /// A value standing in a directive's body (a shape's values made in a loop): the
    /// expression in `args`, its text in `word`.
    Value,
    /// `function W, H { … }` as a height field's image: W, H and the body in `args`.
    FunctionImage,
    /// `isosurface { … }`.
    Isosurface,
    /// `parametric { … }`: its three functions (children), the (u, v) corners in `args`.
    Parametric,
    /// `contained_by { box {…} | sphere {…} }`.
    ContainedBy,
    /// An isosurface setting: its word and values.
    IsoSetting,
    /// `threshold T` in a blob.
    BlobThreshold,
    /// `component S, R, C` in a blob.
    BlobComponent,
    Triangle,
    SmoothTriangle,
    Union,
    Mesh,
    Mesh2,
    /// `mesh_file { "file.obj" }` (trace's extension).
    MeshFile,
    InsideVector,
    VertexVectors,
    NormalVectors,
    FaceIndices,
    NormalIndices,
    Flag,
    // Transformations.
    Translate,
    Rotate,
    Scale,
    Matrix,
    Transform,
    Inverse,
    // Materials.
    Texture,
    Pigment,
    /// `normal { PATTERN [amount] … }`.
    Normal,
    /// `pigment_map { [v PIGMENT] … }`.
    PigmentMap,
    /// `texture_map { [v TEXTURE] … }`.
    TextureMap,
    /// `warp { … }`.
    Warp,
    /// `slope_map { [v <height, slope>] … }`.
    SlopeMap,
    /// `normal_map { [v NORMAL] … }`.
    NormalMap,
    /// An item of a warp: its keyword (`word`) and values.
    WarpItem,
    BumpSize,
    Finish,
    /// `material { texture interior }`.
    Material,
    Ambient,
    Emission,
    Diffuse,
    Brilliance,
    Phong,
    PhongSize,
    Specular,
    Roughness,
    Metallic,
    ConserveEnergy,
    Crand,
    Irid,
    Thickness,
    IridWavelength,
    Radiosity,
    RadiositySetting,
    ObjectRadiosity,
    Importance,
    Albedo,
    Reflection,
    Falloff,
    /// `reflection_exponent E` in a finish (POV-Ray's old spelling).
    ReflectionExponent,
    /// A vector before an image_map's file (POV-Ray's old orientation, ignored).
    ImageOrientation,
    Exponent,
    Fresnel,
    // Lights, patterns, interiors.
    SkySphere,
    LightFlag,
    PointAt,
    Radius,
    Tightness,
    AreaLight,
    Adaptive,
    AreaIllumination,
    /// A pattern: its keyword (`word`) and arguments (`gradient y`, `checker C0, C1`).
    Pattern,
    /// A pattern modifier: keyword and optional value (`turbulence 0.5`, `sine_wave`).
    PatternModifier,
    ColourMap,
    MapEntry,
    ImageMap,
    ImageType,
    /// `gamma G` or `gamma srgb` in an image_map: the file's encoding.
    ImageGamma,
    /// `looks_like { … }` or `projected_through { … }` in a light_source.
    LooksLike,
    /// `slope { … }`: its direction (or point) and ranges.
    SlopeBlock,
    /// `point_at` in `slope { … }`.
    SlopePointAt,
    /// `altitude A [, LOW, HIGH]` in `slope { … }`.
    SlopeAltitude,
    /// `uv_vectors { n, UV… }` of a mesh2.
    UvVectors,
    /// A mesh2's `texture_list { N, texture {…} … }`.
    TextureList,
    /// `uv_indices { n, <a, b, c>… }` of a mesh2.
    UvIndices,
    /// `uv_vectors UV1, UV2, UV3` of a mesh's triangle.
    TriangleUv,
    /// `uv_mapping` in a pigment, normal, texture or object.
    UvMapping,
    /// The `object { … }` pattern.
    ObjectPattern,
    /// `material_map { image textures }` in a texture.
    MaterialMap,
    /// `tiles { textures tile2 textures }` in a texture.
    Tiles,
    /// The textures before `tile2`.
    TilesFirst,
    /// `mandel` or `julia` after `magnet N`.
    MagnetForm,
    /// `filter all F` or `filter I, F` (or `transmit`) in an image_map.
    ImageSeeThrough,
    MapType,
    Once,
    Interpolate,
    /// `use_color`, `use_index`, `use_alpha` in an image pattern or bump map.
    ImageUse,
    Interior,
    /// `bounded_by { objects }`.
    BoundedBy,
    /// `interior_texture { … }` (a texture's items).
    InteriorTexture,
    Ior,
    /// `refraction F` (POV-Ray's old item, of a finish or an interior).
    Refraction,
    FadeDistance,
    FadePower,
    /// `caustics F` of an interior.
    Caustics,
    FadeColour,
    // Directives.
    IfDef,
    For,
    RangeHead,
    /// `#fopen F "name" read|write|append`: children the file's name and the mode word.
    FileOpen,
    /// `#fclose F`.
    FileClose,
    /// `#read (F, A, …)`: children the file, then the variables.
    FileRead,
    /// `#write (F, …)`: children the file, then one [`NodeKind::WriteItem`] per value.
    FileWrite,
    /// One value of `#write`: an optional binary kind (`uint8` …) as a child, the value in args.
    WriteItem,
    MacroDef,
    /// `#declare X = texture {…} texture {…}`: layered textures.
    LayeredTexture,
    /// `[i]` after a declared name (an array element).
    Subscript,
    /// A reference to a declared identifier where an item may stand (`texture { T }`); its
    /// children are the subscripts of an array element (`object { A[i] }`).
    IdentRef,
    /// `deprecated [once] "message"` in a declaration.
    Deprecation,
    /// `array[N]…` with an optional [`NodeKind::ArrayInit`] child after the subscripts.
    Array,
    /// `{ a, b, … }`: the elements of an array, one [`NodeKind::ArrayElem`] each.
    ArrayInit,
    /// One element of an array initializer: an expression (in `args`), an item, or a nested
    /// [`NodeKind::ArrayInit`] (in `children`).
    ArrayElem,
    /// A word the grammar does not know at this place (see `name`).
    Unknown,
    /// A colour standing alone among items (from a directive's or a macro's body).
    ColourItem,
    /// A union's member a loop made again: the member as first read, shared, and how far its
    /// words' slots move ([`Node::again`]).
    Again,
}

/// A construct: keyword, expressions, children.
#[derive(Clone, Debug)]
pub struct Node {
    /// Which construct.
    pub kind: NodeKind,
    /// The whole construct.
    pub span: Span,
    /// The leading keyword or word (for [`NodeKind::Unknown`] and flags, the word itself).
    pub word: Word,
    /// Span of that word.
    pub word_span: Span,
    /// The construct's expressions in source order (e.g. a sphere's centre and radius).
    pub args: Vec<Expr>,
    /// Nested constructs in source order (modifiers, items of a block).
    pub children: Vec<Node>,
    /// For a declared name ([`NodeKind::IdentRef`]): its binding in the unit read.
    pub slot: Slot,
}

/// A node's leading word: a keyword is one of the grammar's own strings (no copy, nothing to
/// free: a big file's statements are mostly keywords), any other word a copy of its text.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Word(std::borrow::Cow<'static, str>);

impl Word {
    /// The word `text` as written: the keyword table's own string when it is a keyword.
    pub fn new(text: &str) -> Word {
        match keywords::reserved_str(text) {
            Some(keyword) => Word(std::borrow::Cow::Borrowed(keyword)),
            None => Word(std::borrow::Cow::Owned(text.to_string())),
        }
    }

    /// A word known when trace is built.
    pub const fn fixed(text: &'static str) -> Word {
        Word(std::borrow::Cow::Borrowed(text))
    }

    /// The word's text.
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl std::ops::Deref for Word {
    type Target = str;
    fn deref(&self) -> &str {
        &self.0
    }
}

impl std::borrow::Borrow<str> for Word {
    fn borrow(&self) -> &str {
        &self.0
    }
}

impl PartialEq<str> for Word {
    fn eq(&self, other: &str) -> bool {
        *self.0 == *other
    }
}

impl PartialEq<&str> for Word {
    fn eq(&self, other: &&str) -> bool {
        *self.0 == **other
    }
}

impl std::fmt::Display for Word {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl Node {
    /// For a member a loop made again ([`NodeKind::Again`]): the member as first read, and how
    /// many words later this one's words are bound.
    pub fn again(&self) -> Option<(&Node, u32)> {
        match (self.kind, self.args.as_slice()) {
            (NodeKind::Again, [shared]) => match &shared.kind {
                ExprKind::Shifted(inner, by) => match &inner.kind {
                    ExprKind::Item(node) => Some((node, *by)),
                    _ => None,
                },
                _ => None,
            },
            _ => None,
        }
    }
}

/// An expression with its span.
#[derive(Clone, Debug)]
pub struct Expr {
    /// What kind of expression.
    pub kind: ExprKind,
    /// Its extent in the source.
    pub span: Span,
}

/// Binary operators.
#[allow(missing_docs)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
    And,
    Or,
}

/// Unary operators.
#[allow(missing_docs)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnOp {
    Neg,
    Plus,
    Not,
}

/// A part of a colour expression (`rgb <..>`, `filter .5`, or the bare base value).
#[derive(Clone, Debug)]
pub enum ColourPart {
    /// A bare value after `color`: `color White`, `color 1`.
    Base(Expr),
    /// `rgb V`, `rgbf V`, `srgb V` …; the keyword as written.
    Typed(String, Expr),
    /// `red F`, `filter F` …; the keyword as written.
    Channel(String, Expr),
}

/// Expression forms.
#[derive(Clone, Debug)]
pub enum ExprKind {
    /// A literal number.
    Number(f64),
    /// `<a, b, ...>`.
    Vector(Vec<Expr>),
    /// An identifier or built-in constant, with its binding in the unit read.
    Ident(String, Slot),
    /// `-a`, `!a`.
    Unary(UnOp, Box<Expr>),
    /// `a + b` …
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `c ? a : b`.
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `f(a, b)`; the function name, its span and its binding in the unit read.
    Call(String, Span, Slot, Vec<Expr>),
    /// `a[i]`: an array element.
    Index(Box<Expr>, Box<Expr>),
    /// `v.x`; the member name and its span.
    Member(Box<Expr>, String, Span),
    /// `color rgb <...> filter 0.5`.
    Colour(Vec<ColourPart>),
    /// A string literal (without the quotes).
    Str(String),
    /// An item passed as a macro argument (`Align(text {…}, x, 0)`).
    Item(Box<Node>),
    /// A `mesh2` list body read by the fast path ([`bulk`]): count and entries.
    Bulk(Box<bulk::BulkList>),
    /// A vector of plain number literals (`<1, -2.5, 3>`), read without building a tree: the
    /// bulk of a large mesh. `len` components (2..=5) are used.
    PlainVector([f64; 5], u8),
    /// An expression read before, read again where a loop made its text again (a big mesh2
    /// list's entries, src/syntax/incremental.rs): its words' slots are the first reading's
    /// moved on by this many words.
    Shifted(std::sync::Arc<Expr>, u32),
}

pub use keywords::is_keyword;

/// Whether `word` can name a declaration (a word that is not a keyword).
pub fn is_identifier(word: &str) -> bool {
    SceneParser::parse(Rule::ident, word)
        .is_ok_and(|mut p| p.next().is_some_and(|k| k.as_str() == word))
}

/// Most rule calls pest may make for one statement (or fragment): a backstop against inputs
/// that make the grammar backtrack exponentially (the fuzzer found several, each fixed in the
/// grammar), ending with a located syntax error in seconds instead of running for hours. A
/// plain statement takes a few hundred calls; a 100k-entry list of expressions about 10⁷.
const MAX_PARSER_CALLS: usize = 200_000_000;

/// Installs [`MAX_PARSER_CALLS`] (pest's limit is process-wide).
fn limit_parser_work() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| pest::set_call_limit(std::num::NonZeroUsize::new(MAX_PARSER_CALLS)));
}

/// What the directive reader asks the grammar to read a unit as (see [`Unit`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Head {
    /// `[deprecated [once] "message"] Name[i]… =` after `#declare` or `#local`.
    Declare,
    /// `(I, start, end [, step])` after `#for`.
    For,
    /// `(low, high)` after `#range`.
    Range,
    /// `(Name)` or `(A[i])` after `#ifdef` or `#ifndef`.
    Ifdef,
    /// `Name(A, B …)` after `#macro`.
    Macro,
    /// `Name "file" read|write|append` after `#fopen`.
    Fopen,
    /// `(F, A, B[i] …)` after `#read`.
    Read,
    /// `(F, values …)` after `#write`.
    Write,
    /// `{ … }` after `#default`.
    Default,
    /// `Name[i]…` after `#undef`.
    Element,
}

/// A declared value's syntax: an item (`pigment {…}`, `array[3]`, `function {…}`, layered
/// textures) or an expression.
pub enum ValueSyntax {
    /// An item.
    Item(Node),
    /// An expression (a number, vector, colour, string, declared name …).
    Expr(Expr),
}

/// Parses `unit` with `rule`: the pairs of the entry rule's top pair and the lowering to use.
fn parse_unit_with<T>(
    unit: &Unit,
    rule: Rule,
    f: impl FnOnce(Pair<'_, Rule>, &Lower<'_>) -> T,
) -> Result<T, Diagnostic> {
    limit_parser_work();
    check_nesting(unit)?;
    let mut pairs = SceneParser::parse(rule, &unit.text).map_err(|e| unit_error(e, unit))?;
    let top = pairs.next().expect("an entry rule yields one pair");
    Ok(f(top, &Lower::of_unit(unit)))
}

/// A syntax error in a unit, at the place in the file its position maps to.
fn unit_error(e: pest::error::Error<Rule>, unit: &Unit) -> Diagnostic {
    let mut d = syntax_error(e, FileId(0));
    if let Some(span) = &mut d.span {
        *span = unit.span(span.start as usize, span.end as usize);
    }
    d
}

/// The inner pairs of an entry rule's top pair, less its end of input.
fn inner(top: Pair<'_, Rule>) -> impl Iterator<Item = Pair<'_, Rule>> {
    top.into_inner().filter(|p| p.as_rule() != Rule::EOI)
}

/// Reads a statement unit (a top-level statement).
pub fn parse_statement(unit: &Unit) -> Result<Node, Diagnostic> {
    if let Some(node) = incremental::statement(unit) {
        return Ok(node);
    }
    parse_unit_with(unit, Rule::unit_statement, |top, lower| {
        lower.node(inner(top).next().expect("a statement"))
    })
}

/// Reads a declared value's unit.
pub fn parse_value(unit: &Unit) -> Result<ValueSyntax, Diagnostic> {
    if let Some(node) = incremental::statement(unit) {
        return Ok(ValueSyntax::Item(node));
    }
    parse_unit_with(unit, Rule::unit_value, |top, lower| {
        let p = inner(top).next().expect("a value");
        if is_expr(p.as_rule()) {
            ValueSyntax::Expr(lower.expr(p))
        } else {
            ValueSyntax::Item(lower.node(p))
        }
    })
}

/// Reads a macro's arguments (with their parentheses).
pub fn parse_args(unit: &Unit) -> Result<Vec<Expr>, Diagnostic> {
    parse_unit_with(unit, Rule::unit_args, |top, lower| {
        inner(top).map(|p| lower.expr(p)).collect()
    })
}

/// Reads an expression unit (a condition, an included file's name …).
pub fn parse_expr(unit: &Unit) -> Result<Expr, Diagnostic> {
    parse_unit_with(unit, Rule::unit_expr, |top, lower| {
        lower.expr(inner(top).next().expect("an expression"))
    })
}

/// Reads a directive's head as a node (see [`Head`] for each one's children and values).
pub fn parse_head(unit: &Unit, head: Head) -> Result<Node, Diagnostic> {
    let rule = match head {
        Head::Declare => Rule::declare_head,
        Head::For => Rule::for_head,
        Head::Range => Rule::range_args,
        Head::Ifdef => Rule::ifdef_head,
        Head::Macro => Rule::macro_head,
        Head::Fopen => Rule::fopen_head,
        Head::Read => Rule::read_args,
        Head::Write => Rule::write_args,
        Head::Default => Rule::default_body,
        Head::Element => Rule::element_head,
    };
    parse_unit_with(unit, rule, |top, lower| lower.node(top))
}

/// Deepest nesting of brackets, braces, parentheses, vector brackets and `?:` in one file.
pub const MAX_NESTING: usize = 1000;

/// Rejects a unit nested deeper than [`MAX_NESTING`] (the parser and evaluator recurse once
/// per level, so unbounded nesting could exhaust the stack): brackets, braces, parentheses,
/// and `<`, `>`, `?`, `:` within one expression (the count of these restarts at `{ } ;`).
fn check_nesting(unit: &Unit) -> Result<(), Diagnostic> {
    let text = &unit.text;
    let mut lexer = lexer::Lexer::new(text, 0..text.len());
    let (mut blocks, mut inline) = (0usize, 0usize);
    // (A unit's text was lexed by the reader already: a lexing error cannot happen here.)
    while let Ok(Some(t)) = lexer.next() {
        if t.kind != lexer::TokenKind::Punct {
            continue;
        }
        match t.text(text) {
            "(" | "[" => blocks += 1,
            "{" => {
                blocks += 1;
                inline = 0;
            }
            ")" | "]" => blocks = blocks.saturating_sub(1),
            "}" => {
                blocks = blocks.saturating_sub(1);
                inline = 0;
            }
            "<" | "?" => inline += 1,
            ">" | ":" => inline = inline.saturating_sub(1),
            ";" => inline = 0,
            _ => {}
        }
        if blocks + inline > MAX_NESTING {
            let at = t.start as usize;
            return Err(Diagnostic::error(
                format!("nested more than {MAX_NESTING} levels deep"),
                unit.span(at, at + 1),
            ));
        }
    }
    Ok(())
}

fn syntax_error(e: pest::error::Error<Rule>, file: FileId) -> Diagnostic {
    use pest::error::{ErrorVariant, InputLocation};
    let (start, end) = match e.location {
        InputLocation::Pos(p) => (p, p + 1),
        InputLocation::Span((s, e)) => (s, e),
    };
    let message = match &e.variant {
        ErrorVariant::ParsingError { positives, .. } => {
            let mut names: Vec<&str> = positives.iter().filter_map(|r| describe(*r)).collect();
            names.sort_unstable();
            names.dedup();
            match names.len() {
                0 => "syntax error".to_string(),
                1 => format!("syntax error: expected {}", names[0]),
                _ => {
                    let last = names.pop().unwrap_or_default();
                    format!("syntax error: expected {} or {}", names.join(", "), last)
                }
            }
        }
        ErrorVariant::CustomError { message } if message == "call limit reached" => {
            "syntax error: the parser gave up here (the text nests in a way that would take it too long; look for a missing `}` or `#end`)".to_string()
        }
        ErrorVariant::CustomError { message } => format!("syntax error: {message}"),
    };
    Diagnostic::error(message, Span::new(file, start, end))
}

/// Human wording of a rule for "expected ..." messages; `None` hides the rule from the list.
fn describe(rule: Rule) -> Option<&'static str> {
    use Rule::*;
    Some(match rule {
        EOI => "end of file",
        expr | logical | relation | sum | product | unary | postfix | colour_base | macro_arg => {
            "an expression"
        }
        number => "a number",
        vector => "a vector `<...>`",
        paren => "`(`",
        colour | colour_typed | colour_channel => "a colour",
        call => "a function call",
        ident => "an identifier",
        word => "a keyword or identifier",
        logic_op | rel_op | add_op | mul_op => "an operator",
        unary_op => "a unary operator",
        member => "`.`",
        object | sphere | plane | box_shape | object_ref => "an object",
        camera => "`camera`",
        light_source => "`light_source`",
        background => "`background`",
        global_settings => "`global_settings`",
        default_block => "`default`",
        unknown_item | misplaced_item | unknown_tail | balanced | leftover => "a statement",
        flag | translate | rotate | scale | matrix | transform | texture | pigment | normal
        | finish => "an object modifier",
        rbrace => "`}`",
        kw_face_indices => {
            "`face_indices` (a mesh2's lists come in POV-Ray's order: vertex_vectors, normal_vectors, uv_vectors, face_indices, normal_indices, uv_indices)"
        }
        _ => return None,
    })
}

/// Lowering from pest pairs to the syntax tree, one method per family of rules.
/// Whether a comma stands between two pairs of one parse (comments aside).
fn comma_between(a: &Pair<'_, Rule>, b: &Pair<'_, Rule>) -> bool {
    let text = a.as_span().get_input().as_bytes();
    let (start, end) = (a.as_span().end(), b.as_span().start());
    let at = lexer::skip_trivia(text, start, end).unwrap_or(start);
    at < end && text[at] == b','
}

struct Lower<'u> {
    file: FileId,
    /// Byte offset of the parsed text in its file.
    offset: usize,
    /// List bodies read by the fast path, by file offset (by offset in the unit's text when
    /// reading a unit).
    bulk: std::cell::RefCell<std::collections::HashMap<usize, bulk::BulkList>>,
    /// The unit read, if the text is one: spans map through its pieces, words have slots.
    unit: Option<&'u Unit>,
}

impl<'u> Lower<'u> {
    /// The lowering of a unit's text (from its start).
    fn of_unit(unit: &'u Unit) -> Lower<'u> {
        Lower {
            file: FileId(0),
            offset: 0,
            bulk: std::cell::RefCell::new(
                unit.lists
                    .iter()
                    .map(|(at, l)| (*at as usize, l.clone()))
                    .collect(),
            ),
            unit: Some(unit),
        }
    }

    fn span(&self, pair: &Pair<'_, Rule>) -> Span {
        let s = pair.as_span();
        let (start, end) = (s.start() + self.offset, s.end() + self.offset);
        match self.unit {
            Some(unit) => unit.span(start, end),
            None => Span::new(self.file, start, end),
        }
    }

    /// A vector's components. POV-Ray reads at most five: past the fifth, a component written
    /// without a comma before it takes the fifth's place (`<1 2 3 4 5 6 7>` is `<1, 2, 3, 4,
    /// 7>`; the components it replaces are not evaluated here, nor is their text checked
    /// further than the grammar did), while a comma there is an error (left for evaluation to
    /// report, as a vector of more than five).
    fn vector_items(&self, pair: Pair<'_, Rule>) -> Vec<Expr> {
        let pairs: Vec<Pair<'_, Rule>> = pair.into_inner().collect();
        let replaced = pairs.len() > 5
            && pairs
                .windows(2)
                .skip(4)
                .all(|w| !comma_between(&w[0], &w[1]));
        let mut items = Vec::with_capacity(pairs.len().min(5));
        let last = pairs.len() - 1;
        for (i, p) in pairs.into_iter().enumerate() {
            if !replaced || i < 4 || i == last {
                items.push(self.expr(p));
            }
        }
        items
    }

    /// The binding slot of the word starting where `pair` starts.
    fn slot(&self, pair: &Pair<'_, Rule>) -> Slot {
        match self.unit {
            Some(unit) => unit.slot(pair.as_span().start() + self.offset),
            None => Slot::NONE,
        }
    }

    fn node(&self, pair: Pair<'_, Rule>) -> Node {
        let span = self.span(&pair);
        let rule = pair.as_rule();
        if rule == Rule::layered_texture {
            // One texture is a plain texture (the grammar reads both with one rule, so that a
            // texture that fails to parse is not tried twice).
            let mut textures = pair
                .clone()
                .into_inner()
                .filter(|p| p.as_rule() == Rule::texture);
            if let (Some(only), None) = (textures.next(), textures.next()) {
                return self.node(only);
            }
        }
        let kind = match rule {
            Rule::declare_head => NodeKind::Declare,
            Rule::for_head => NodeKind::For,
            Rule::range_args => NodeKind::RangeHead,
            Rule::ifdef_head => NodeKind::IfDef,
            Rule::macro_head => NodeKind::MacroDef,
            Rule::fopen_head => NodeKind::FileOpen,
            Rule::read_args => NodeKind::FileRead,
            Rule::write_args => NodeKind::FileWrite,
            Rule::default_body => NodeKind::Default,
            Rule::element_head => NodeKind::IdentRef,
            Rule::default_block => NodeKind::Default,
            Rule::camera => NodeKind::Camera,
            Rule::light_source => NodeKind::LightSource,
            Rule::background => NodeKind::Background,
            Rule::fog => NodeKind::Fog,
            Rule::media => NodeKind::Media,
            Rule::media_setting => NodeKind::MediaSetting,
            Rule::rainbow => NodeKind::Rainbow,
            Rule::dispersion => NodeKind::Dispersion,
            Rule::rainbow_setting => NodeKind::RainbowSetting,
            Rule::scattering => NodeKind::Scattering,
            Rule::scattering_setting => NodeKind::ScatteringSetting,
            Rule::density => NodeKind::Density,
            Rule::light_media => NodeKind::LightMedia,
            Rule::fog_distance => NodeKind::FogDistance,
            Rule::fog_type => NodeKind::FogType,
            Rule::fog_alt => NodeKind::FogAlt,
            Rule::fog_offset => NodeKind::FogOffset,
            Rule::turb_depth => NodeKind::TurbDepth,
            Rule::fog_colour => NodeKind::FogColour,
            Rule::global_settings => NodeKind::GlobalSettings,
            Rule::assumed_gamma => NodeKind::AssumedGamma,
            Rule::max_trace_level => NodeKind::MaxTraceLevel,
            Rule::max_intersections => NodeKind::MaxIntersections,
            Rule::adc_bailout => NodeKind::AdcBailout,
            Rule::ambient_light => NodeKind::AmbientLight,
            Rule::perspective => NodeKind::Perspective,
            Rule::camera_projection => NodeKind::CameraType,
            Rule::mesh_camera => NodeKind::MeshCamera,
            Rule::mesh_camera_smooth => NodeKind::MeshCameraSmooth,
            Rule::orthographic => NodeKind::Orthographic,
            Rule::location => NodeKind::Location,
            Rule::look_at => NodeKind::LookAt,
            Rule::direction => NodeKind::Direction,
            Rule::up => NodeKind::Up,
            Rule::right => NodeKind::Right,
            Rule::sky => NodeKind::Sky,
            Rule::angle => NodeKind::Angle,
            Rule::sphere => NodeKind::Sphere,
            Rule::plane => NodeKind::Plane,
            Rule::box_shape => NodeKind::Box,
            Rule::object_ref | Rule::shape_ref => NodeKind::ObjectRef,
            Rule::looks_like => NodeKind::LooksLike,
            Rule::cylinder => NodeKind::Cylinder,
            Rule::cone => NodeKind::Cone,
            Rule::disc => NodeKind::Disc,
            Rule::torus => NodeKind::Torus,
            Rule::shape => NodeKind::Shape,
            Rule::shape_word => NodeKind::Flag,
            Rule::blob => NodeKind::Blob,
            Rule::function_value => NodeKind::Function,
            Rule::pattern_function => NodeKind::PatternFunction,
            Rule::spline => NodeKind::Spline,
            Rule::pigment_pattern => NodeKind::PigmentPattern,
            Rule::function_image => NodeKind::FunctionImage,
            Rule::function_params => NodeKind::FunctionParams,
            Rule::isosurface => NodeKind::Isosurface,
            Rule::parametric => NodeKind::Parametric,
            Rule::contained_by => NodeKind::ContainedBy,
            Rule::iso_setting => NodeKind::IsoSetting,
            Rule::charset => NodeKind::Charset,
            Rule::camera_blur => NodeKind::CameraBlur,
            Rule::blob_threshold => NodeKind::BlobThreshold,
            Rule::blob_component => NodeKind::BlobComponent,
            Rule::triangle => NodeKind::Triangle,
            Rule::smooth_triangle => NodeKind::SmoothTriangle,
            Rule::union => NodeKind::Union,
            Rule::mesh => NodeKind::Mesh,
            Rule::mesh2 => NodeKind::Mesh2,
            Rule::mesh_file => NodeKind::MeshFile,
            Rule::inside_vector => NodeKind::InsideVector,
            Rule::vertex_vectors => NodeKind::VertexVectors,
            Rule::normal_vectors => NodeKind::NormalVectors,
            Rule::face_indices => NodeKind::FaceIndices,
            Rule::normal_indices => NodeKind::NormalIndices,
            Rule::mesh_uv_vectors => NodeKind::UvVectors,
            Rule::texture_list => NodeKind::TextureList,
            Rule::uv_indices => NodeKind::UvIndices,
            Rule::triangle_uv => NodeKind::TriangleUv,
            Rule::flag => NodeKind::Flag,
            Rule::translate => NodeKind::Translate,
            Rule::rotate => NodeKind::Rotate,
            Rule::scale => NodeKind::Scale,
            Rule::matrix => NodeKind::Matrix,
            Rule::transform => NodeKind::Transform,
            Rule::inverse => NodeKind::Inverse,
            Rule::texture => NodeKind::Texture,
            Rule::pigment => NodeKind::Pigment,
            Rule::normal => NodeKind::Normal,
            Rule::map_pigment => NodeKind::Pigment,
            Rule::pigment_map => NodeKind::PigmentMap,
            Rule::pigment_map_entry => NodeKind::MapEntry,
            Rule::texture_map => NodeKind::TextureMap,
            Rule::warp => NodeKind::Warp,
            Rule::slope_map => NodeKind::SlopeMap,
            Rule::normal_map => NodeKind::NormalMap,
            Rule::normal_map_entry => NodeKind::MapEntry,
            Rule::map_normal => NodeKind::Normal,
            Rule::slope_entry => NodeKind::MapEntry,
            Rule::warp_item => NodeKind::WarpItem,
            Rule::texture_map_entry => NodeKind::MapEntry,
            Rule::map_texture => NodeKind::Texture,
            Rule::bump_size => NodeKind::BumpSize,
            Rule::finish => NodeKind::Finish,
            Rule::material => NodeKind::Material,
            Rule::ambient => NodeKind::Ambient,
            Rule::emission => NodeKind::Emission,
            Rule::diffuse => NodeKind::Diffuse,
            Rule::brilliance => NodeKind::Brilliance,
            Rule::phong => NodeKind::Phong,
            Rule::phong_size => NodeKind::PhongSize,
            Rule::specular => NodeKind::Specular,
            Rule::roughness => NodeKind::Roughness,
            Rule::metallic => NodeKind::Metallic,
            Rule::conserve_energy => NodeKind::ConserveEnergy,
            Rule::crand => NodeKind::Crand,
            Rule::irid => NodeKind::Irid,
            Rule::thickness => NodeKind::Thickness,
            Rule::irid_wavelength => NodeKind::IridWavelength,
            Rule::radiosity => NodeKind::Radiosity,
            Rule::radiosity_setting => NodeKind::RadiositySetting,
            Rule::object_radiosity => NodeKind::ObjectRadiosity,
            Rule::importance => NodeKind::Importance,
            Rule::albedo => NodeKind::Albedo,
            Rule::reflection => NodeKind::Reflection,
            Rule::falloff => NodeKind::Falloff,
            Rule::reflection_exponent => NodeKind::ReflectionExponent,
            Rule::image_orientation => NodeKind::ImageOrientation,
            Rule::exponent => NodeKind::Exponent,
            Rule::fresnel => NodeKind::Fresnel,
            Rule::sky_sphere => NodeKind::SkySphere,
            Rule::light_flag => NodeKind::LightFlag,
            Rule::point_at => NodeKind::PointAt,
            Rule::radius => NodeKind::Radius,
            Rule::tightness => NodeKind::Tightness,
            Rule::area_light => NodeKind::AreaLight,
            Rule::adaptive => NodeKind::Adaptive,
            Rule::area_illumination => NodeKind::AreaIllumination,
            Rule::pattern => NodeKind::Pattern,
            Rule::pattern_modifier => NodeKind::PatternModifier,
            Rule::colour_map => NodeKind::ColourMap,
            Rule::map_entry => NodeKind::MapEntry,
            Rule::image_map => NodeKind::ImageMap,
            Rule::image_use => NodeKind::ImageUse,
            Rule::image_type => NodeKind::ImageType,
            Rule::image_gamma => NodeKind::ImageGamma,
            Rule::magnet_form => NodeKind::MagnetForm,
            Rule::material_map => NodeKind::MaterialMap,
            Rule::tiles => NodeKind::Tiles,
            Rule::tiles_first => NodeKind::TilesFirst,
            Rule::object_pattern => NodeKind::ObjectPattern,
            Rule::uv_mapping => NodeKind::UvMapping,
            Rule::slope_block => NodeKind::SlopeBlock,
            Rule::slope_point_at => NodeKind::SlopePointAt,
            Rule::slope_altitude => NodeKind::SlopeAltitude,
            Rule::image_see_through => NodeKind::ImageSeeThrough,
            Rule::map_type => NodeKind::MapType,
            Rule::once => NodeKind::Once,
            Rule::interpolate => NodeKind::Interpolate,
            Rule::interior => NodeKind::Interior,
            Rule::bounded_by => NodeKind::BoundedBy,
            Rule::interior_texture => NodeKind::InteriorTexture,
            Rule::ior => NodeKind::Ior,
            Rule::refraction => NodeKind::Refraction,
            Rule::fade_distance => NodeKind::FadeDistance,
            Rule::fade_power => NodeKind::FadePower,
            Rule::caustics => NodeKind::Caustics,
            Rule::fade_colour => NodeKind::FadeColour,
            Rule::write_item => NodeKind::WriteItem,
            Rule::layered_texture => NodeKind::LayeredTexture,
            Rule::colour_item => NodeKind::ColourItem,
            Rule::subscript => NodeKind::Subscript,
            Rule::ident
            | Rule::name_ref
            | Rule::item_ref
            | Rule::file_word
            | Rule::spline_kind
            | Rule::bare_name => NodeKind::IdentRef,
            Rule::array_value => NodeKind::Array,
            Rule::deprecation => NodeKind::Deprecation,
            Rule::array_init => NodeKind::ArrayInit,
            Rule::array_elem => NodeKind::ArrayElem,
            Rule::unknown_item
            | Rule::misplaced_item
            | Rule::leftover
            | Rule::cylinder_camera
            | Rule::texture_pattern => NodeKind::Unknown,
            other => unreachable!("rule {other:?} is not a node"),
        };
        let mut node = Node {
            kind,
            span,
            word: Word::default(),
            word_span: span,
            args: Vec::new(),
            children: Vec::new(),
            slot: Slot::NONE,
        };
        if matches!(
            rule,
            Rule::ident
                | Rule::name_ref
                | Rule::shape_word
                | Rule::charset
                | Rule::function_params
                | Rule::file_word
                | Rule::spline_kind
                | Rule::image_type
                | Rule::magnet_form
        ) {
            // A name, as written.
            node.word = Word::new(pair.as_str().trim());
            node.slot = self.slot(&pair);
            return node;
        }
        if matches!(rule, Rule::item_ref | Rule::bare_name | Rule::element_head) {
            let mut inner = pair.into_inner().filter(|p| p.as_rule() != Rule::EOI);
            let name = inner.next().expect("item_ref starts with a name");
            node.word = Word::new(name.as_str());
            node.word_span = self.span(&name);
            node.slot = self.slot(&name);
            node.children = inner.map(|p| self.node(p)).collect();
            return node;
        }
        if rule == Rule::leftover {
            // Named by its first token.
            let text = pair.as_str();
            // At least the first character (which may be a blank such as U+00A0, or any
            // character of several bytes).
            let first = text.chars().next().map_or(0, char::len_utf8);
            let len = text
                .find(|c: char| c.is_whitespace() || c == '{' || c == '<')
                .unwrap_or(text.len())
                .max(first);
            node.word = Word::new(&text[..len]);
            node.word_span = Span {
                end: span.start + len as u32,
                ..span
            };
            return node;
        }
        let mut first_word = true;
        // A shape's values and its own words stand in one list, in order: each value as a
        // `Value` child (its expression the child's one argument).
        let values_in_order = rule == Rule::shape;
        for inner in pair.into_inner() {
            let r = inner.as_rule();
            if is_expr(r) && values_in_order {
                let e = self.expr(inner);
                node.children.push(Node {
                    kind: NodeKind::Value,
                    span: e.span,
                    word: Word::default(),
                    word_span: e.span,
                    args: vec![e],
                    children: Vec::new(),
                    slot: Slot::NONE,
                });
            } else if is_expr(r) {
                node.args.push(self.expr(inner));
            } else if is_word(r) {
                // The construct's own keyword (or, for an unknown item, the word itself).
                if first_word {
                    node.word = Word::new(inner.as_str());
                    node.word_span = self.span(&inner);
                    node.slot = self.slot(&inner);
                    first_word = false;
                }
            } else if r == Rule::flag_value {
                let on = matches!(inner.as_str(), "on" | "true" | "yes");
                let span = self.span(&inner);
                node.args.push(Expr {
                    kind: ExprKind::Number(if on { 1.0 } else { 0.0 }),
                    span,
                });
            } else if !matches!(
                r,
                Rule::EOI | Rule::unknown_tail | Rule::balanced | Rule::rbrace
            ) {
                // (The body of something unsupported is dropped: evaluation stops at its word.)
                node.children.push(self.node(inner));
            }
        }
        node
    }

    fn expr(&self, pair: Pair<'_, Rule>) -> Expr {
        let span = self.span(&pair);
        match pair.as_rule() {
            Rule::expr | Rule::full_expr => {
                let mut inner = pair.into_inner();
                let cond = self.expr(inner.next().expect("expr has a first operand"));
                match (inner.next(), inner.next()) {
                    (Some(a), Some(b)) => Expr {
                        kind: ExprKind::Ternary(
                            Box::new(cond),
                            Box::new(self.expr(a)),
                            Box::new(self.expr(b)),
                        ),
                        span,
                    },
                    _ => cond,
                }
            }
            Rule::logical | Rule::relation | Rule::sum | Rule::product => {
                let mut inner = pair.into_inner();
                let mut left = self.expr(inner.next().expect("binary chain has an operand"));
                while let (Some(op), Some(right)) = (inner.next(), inner.next()) {
                    let op = match op.as_str() {
                        "+" => BinOp::Add,
                        "-" => BinOp::Sub,
                        "*" => BinOp::Mul,
                        "/" => BinOp::Div,
                        "<" => BinOp::Lt,
                        "<=" => BinOp::Le,
                        ">" => BinOp::Gt,
                        ">=" => BinOp::Ge,
                        "=" => BinOp::Eq,
                        "!=" => BinOp::Ne,
                        "&" => BinOp::And,
                        _ => BinOp::Or,
                    };
                    let right = self.expr(right);
                    let span = Span {
                        end: right.span.end,
                        ..left.span
                    };
                    left = Expr {
                        kind: ExprKind::Binary(op, Box::new(left), Box::new(right)),
                        span,
                    };
                }
                left
            }
            Rule::unary => {
                let parts: Vec<_> = pair.into_inner().collect();
                let (ops, operand) = parts.split_at(parts.len() - 1);
                let mut e = self.expr(operand[0].clone());
                for op in ops.iter().rev() {
                    let op_kind = match op.as_str() {
                        "-" => UnOp::Neg,
                        "+" => UnOp::Plus,
                        _ => UnOp::Not,
                    };
                    let span = Span {
                        start: self.span(op).start,
                        ..e.span
                    };
                    e = Expr {
                        kind: ExprKind::Unary(op_kind, Box::new(e)),
                        span,
                    };
                }
                e
            }
            Rule::postfix => {
                let mut inner = pair.into_inner();
                let mut e = self.expr(inner.next().expect("postfix has a primary"));
                for member in inner {
                    let name = member.into_inner().next().expect("member has a name");
                    let name_span = self.span(&name);
                    let span = Span {
                        end: name_span.end,
                        ..e.span
                    };
                    e = Expr {
                        kind: ExprKind::Member(Box::new(e), name.as_str().to_string(), name_span),
                        span,
                    };
                }
                e
            }
            Rule::bulk_list => {
                // (Lists are kept by where they stand in the text read: the file's offset,
                // or the unit's.)
                let at = match self.unit {
                    Some(_) => pair.as_span().start() + self.offset,
                    None => span.start as usize,
                };
                let list = self.bulk.borrow_mut().remove(&at);
                Expr {
                    // (Only a stray marker byte in the source has no list.)
                    kind: list.map_or_else(
                        || ExprKind::Ident("\u{1}".into(), Slot::NONE),
                        |l| ExprKind::Bulk(Box::new(l)),
                    ),
                    span,
                }
            }
            Rule::indexed => {
                let mut inner = pair.into_inner();
                let mut e = self.expr(inner.next().expect("indexed starts with a name"));
                for sub in inner {
                    let end = self.span(&sub).end;
                    let index = self.expr(sub.into_inner().next().expect("subscript has a value"));
                    let span = Span { end, ..e.span };
                    e = Expr {
                        kind: ExprKind::Index(Box::new(e), Box::new(index)),
                        span,
                    };
                }
                e
            }
            Rule::macro_arg => {
                let inner = pair.into_inner().next().expect("macro_arg has a value");
                if matches!(inner.as_rule(), Rule::expr | Rule::full_expr) {
                    self.expr(inner)
                } else {
                    Expr {
                        kind: ExprKind::Item(Box::new(self.node(inner))),
                        span,
                    }
                }
            }
            Rule::paren | Rule::colour_base | Rule::colour_named => {
                self.expr(pair.into_inner().next().expect("parenthesised expression"))
            }
            Rule::plain_vector => {
                let text = pair.as_str();
                // Each number, and whether a comma stands before it.
                let mut numbers: Vec<f64> = Vec::new();
                let mut commas: Vec<bool> = Vec::new();
                let mut comma = false;
                for piece in text[1..text.len() - 1].split_inclusive(',') {
                    for n in piece.split(|c: char| c == ',' || c.is_whitespace()) {
                        if !n.is_empty() {
                            numbers.push(lexer::number_value(n));
                            commas.push(comma);
                            comma = false;
                        }
                    }
                    comma = piece.ends_with(',');
                }
                // Past the fifth, a number without a comma takes the fifth's place (see
                // `vector_items`).
                if numbers.len() > 5 && !commas[5..].contains(&true) {
                    numbers[4] = numbers[numbers.len() - 1];
                    numbers.truncate(5);
                }
                if numbers.len() <= 5 {
                    let mut c = [0.0; 5];
                    c[..numbers.len()].copy_from_slice(&numbers);
                    Expr {
                        kind: ExprKind::PlainVector(c, numbers.len() as u8),
                        span,
                    }
                } else {
                    let items = numbers
                        .into_iter()
                        .map(|n| Expr {
                            kind: ExprKind::Number(n),
                            span,
                        })
                        .collect();
                    Expr {
                        kind: ExprKind::Vector(items),
                        span,
                    }
                }
            }
            Rule::string => {
                let text = pair.as_str();
                Expr {
                    kind: ExprKind::Str(text[1..text.len() - 1].to_string()),
                    span,
                }
            }
            Rule::plain_float | Rule::number => Expr {
                kind: ExprKind::Number(lexer::number_value(pair.as_str())),
                span,
            },
            Rule::vector => Expr {
                kind: ExprKind::Vector(self.vector_items(pair)),
                span,
            },
            Rule::ident => Expr {
                kind: ExprKind::Ident(pair.as_str().to_string(), self.slot(&pair)),
                span,
            },
            Rule::call => {
                let mut inner = pair.into_inner();
                let name = inner.next().expect("call has a name");
                let name_span = self.span(&name);
                let slot = self.slot(&name);
                let args = inner.map(|p| self.expr(p)).collect();
                Expr {
                    kind: ExprKind::Call(name.as_str().to_string(), name_span, slot, args),
                    span,
                }
            }
            Rule::colour => {
                let mut parts = Vec::new();
                for part in pair.into_inner() {
                    match part.as_rule() {
                        Rule::colour_base | Rule::colour_named => {
                            parts.push(ColourPart::Base(self.expr(part)))
                        }
                        Rule::colour_typed | Rule::colour_channel => {
                            let rule = part.as_rule();
                            let mut inner = part.into_inner();
                            let kw = inner.next().expect("colour keyword").as_str().to_string();
                            let value = self.expr(inner.next().expect("colour value"));
                            parts.push(if rule == Rule::colour_typed {
                                ColourPart::Typed(kw, value)
                            } else {
                                ColourPart::Channel(kw, value)
                            });
                        }
                        _ => {}
                    }
                }
                Expr {
                    kind: ExprKind::Colour(parts),
                    span,
                }
            }
            other => unreachable!("rule {other:?} is not an expression"),
        }
    }
}

fn is_expr(rule: Rule) -> bool {
    matches!(
        rule,
        Rule::expr
            | Rule::full_expr
            | Rule::sum
            | Rule::plain_vector
            | Rule::plain_float
            | Rule::string
            | Rule::macro_arg
            | Rule::bulk_list
    )
}

fn is_word(rule: Rule) -> bool {
    use Rule::*;
    matches!(
        rule,
        word | keyword
            | kw_adc_bailout
            | kw_gamma
            | kw_material_map
            | kw_tiles
            | kw_tile2
            | kw_uv_vectors
            | kw_uv_indices
            | kw_texture_list
            | kw_uv_mapping
            | kw_altitude
            | kw_light_object
            | fractal_side
            | kw_image_channel
            | kw_all
            | kw_srgb
            | kw_blob
            | kw_function
            | kw_pattern
            | kw_spline
            | kw_pigment_pattern
            | kw_isosurface
            | kw_parametric
            | kw_contained_by
            | iso_word
            | camera_blur_kw
            | media_kw
            | scattering_kw
            | light_media_kw
            | rainbow_kw
            | radiosity_kw
            | kw_radiosity
            | kw_importance
            | dispersion_kw
            | kw_rainbow
            | kw_media
            | kw_scattering
            | kw_density
            | kw_density_map
            | kw_threshold
            | kw_component
            | kw_strength
            | kw_fog
            | kw_fog_type
            | kw_fog_alt
            | kw_fog_offset
            | kw_distance
            | kw_turb_depth
            | kw_array
            | kw_deprecated
            | kw_albedo
            | kw_ambient
            | kw_ambient_light
            | kw_angle
            | kw_assumed_gamma
            | kw_background
            | kw_box
            | kw_brilliance
            | kw_camera
            | kw_color
            | kw_colour
            | kw_conserve_energy
            | kw_crand
            | kw_irid
            | kw_irid_wavelength
            | kw_thickness
            | kw_declare
            | kw_default
            | kw_diffuse
            | kw_direction
            | kw_double_illuminate
            | kw_emission
            | kw_exponent
            | kw_falloff
            | kw_finish
            | kw_fresnel
            | kw_global_settings
            | kw_hollow
            | kw_inverse
            | kw_light_source
            | kw_local
            | kw_location
            | kw_look_at
            | kw_matrix
            | kw_material
            | kw_mesh_file
            | kw_max_trace_level
            | kw_max_intersections
            | kw_metallic
            | kw_no_image
            | kw_no_radiosity
            | kw_no_reflection
            | kw_no_shadow
            | kw_normal
            | kw_pigment_map
            | kw_texture_map
            | kw_warp
            | kw_slope_map
            | kw_normal_map
            | warp_kw
            | kw_bump_size
            | kw_object
            | kw_orthographic
            | kw_perspective
            | camera_type
            | kw_phong
            | kw_phong_size
            | kw_pigment
            | kw_plane
            | kw_reflection
            | kw_right
            | kw_rotate
            | kw_roughness
            | kw_scale
            | kw_sky
            | kw_specular
            | kw_sphere
            | kw_texture
            | kw_transform
            | kw_translate
            | kw_up
            | kw_version
            | kw_cone
            | kw_cylinder
            | kw_disc
            | kw_face_indices
            | kw_inside_vector
            | kw_mesh
            | kw_mesh2
            | kw_normal_indices
            | kw_normal_vectors
            | kw_open
            | kw_smooth_triangle
            | kw_sturm
            | kw_hierarchy
            | kw_torus
            | kw_triangle
            | kw_union
            | kw_composite
            | kw_reflection_exponent
            | kw_light_group
            | kw_global_lights
            | kw_vertex_vectors
            | kw_spotlight
            | kw_parallel
            | kw_shadowless
            | kw_jitter
            | kw_circular
            | kw_orient
            | kw_point_at
            | kw_radius
            | kw_tightness
            | kw_area_light
            | kw_adaptive
            | kw_area_illumination
            | kw_sky_sphere
            | pattern_kw
            | shape_kw
            | shape_ref_kw
            | kw_mesh_camera
            | kw_smooth
            | modifier_kw
            | kw_color_map
            | kw_colour_map
            | kw_image_map
            | kw_image_pattern
            | kw_bump_map
            | kw_use_colour
            | kw_use_color
            | kw_use_index
            | kw_use_alpha
            | kw_png
            | kw_map_type
            | kw_once
            | kw_interpolate
            | kw_interior
            | kw_bounded_by
            | kw_interior_texture
            | kw_ior
            | kw_refraction
            | kw_fade_distance
            | kw_fade_power
            | kw_caustics
            | kw_fade_color
            | kw_fade_colour
            | kw_if
            | kw_ifdef
            | kw_ifndef
            | kw_elseif
            | kw_else
            | kw_end
            | kw_while
            | kw_for
            | kw_switch
            | kw_case
            | kw_range
            | kw_break
            | kw_macro
            | kw_undef
            | kw_include
            | kw_fopen
            | kw_fclose
            | kw_read
            | kw_write
            | kw_debug
            | kw_warning
            | kw_error
    )
}

#[cfg(test)]
mod tests;
