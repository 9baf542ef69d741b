//! Typed views of the tree: each construct's values and items by name.
//!
//! The grammar keeps a construct's values in [`Node::args`] and its items in
//! [`Node::children`], in source order. Which value is which (a sphere's centre, then its
//! radius, then a blob's strength if one follows) is decided here, next to the lowering that
//! puts them there, and nowhere else: evaluation reads a node through [`Node::view`] and
//! names what it reads. The match below has an arm for every kind, so a new kind of node
//! must say what its values are; a node whose values do not have its kind's layout (which
//! the grammar does not make; `view_of_every_node_the_grammar_makes_is_well_formed` checks
//! it on every scene of the examples and tests) is [`View::Malformed`].

use super::bulk::BulkList;
use super::{Expr, ExprKind, Node, NodeKind};

/// A node's values (and the items read by place) by name; see the module's comment.
#[allow(missing_docs)]
#[derive(Clone, Copy, Debug)]
pub enum View<'a> {
    LightSource {
        location: &'a Expr,
        colour: Option<&'a Expr>,
    },
    Background(&'a Expr),
    FogDistance(&'a Expr),
    FogType(&'a Expr),
    FogAlt(&'a Expr),
    FogOffset(&'a Expr),
    TurbDepth(&'a Expr),
    FogColour(&'a Expr),
    AssumedGamma(&'a Expr),
    MaxTraceLevel(&'a Expr),
    AdcBailout(&'a Expr),
    AmbientLight(&'a Expr),
    MaxIntersections(&'a Expr),
    MeshCamera {
        rays: &'a Expr,
        distribution: &'a Expr,
        max_distance: Option<&'a Expr>,
    },
    Location(&'a Expr),
    LookAt(&'a Expr),
    Direction(&'a Expr),
    Up(&'a Expr),
    Right(&'a Expr),
    Sky(&'a Expr),
    Angle {
        angle: &'a Expr,
        vertical: Option<&'a Expr>,
    },
    Sphere {
        centre: &'a Expr,
        radius: &'a Expr,
        strength: Option<&'a Expr>,
    },
    Plane {
        normal: &'a Expr,
        distance: &'a Expr,
    },
    Box {
        corner1: &'a Expr,
        corner2: &'a Expr,
    },
    Cylinder {
        base: &'a Expr,
        cap: &'a Expr,
        radius: &'a Expr,
        strength: Option<&'a Expr>,
    },
    Cone {
        base: &'a Expr,
        base_radius: &'a Expr,
        cap: &'a Expr,
        cap_radius: &'a Expr,
    },
    Disc {
        centre: &'a Expr,
        normal: &'a Expr,
        radius: &'a Expr,
        holes: &'a [Expr],
    },
    Torus {
        major: &'a Expr,
        minor: &'a Expr,
    },
    CameraBlur {
        value: &'a Expr,
        max: Option<&'a Expr>,
    },
    /// A radiosity setting: its word is the node's; `second` only for `count` and
    /// `nearest_count`.
    RadiositySetting {
        value: &'a Expr,
        second: Option<&'a Expr>,
    },
    /// `importance F` in an object's `radiosity { }`.
    Importance(&'a Expr),
    /// A media setting: its word is the node's; `second` only for `samples Min, Max`.
    MediaSetting {
        value: &'a Expr,
        second: Option<&'a Expr>,
    },
    /// `scattering { TYPE, COLOUR … }` (eccentricity and extinction are its children).
    Scattering {
        kind: &'a Expr,
        colour: &'a Expr,
    },
    ScatteringSetting(&'a Expr),
    /// A rainbow's setting: its word is the node's.
    RainbowSetting(&'a Expr),
    /// `dispersion D` or `dispersion_samples N`: the word is the node's.
    Dispersion(&'a Expr),
    /// `media_interaction [B]` / `media_attenuation [B]` (the word says which).
    LightMedia {
        on: Option<&'a Expr>,
    },
    Function {
        body: Option<&'a Expr>,
    },
    Spline {
        values: &'a [Expr],
    },
    PigmentPattern {
        colour: Option<&'a Expr>,
    },
    Value(&'a Expr),
    FunctionImage {
        width: &'a Expr,
        height: &'a Expr,
        body: Option<&'a Expr>,
    },
    Parametric {
        uv_min: &'a Expr,
        uv_max: &'a Expr,
    },
    IsoSetting {
        values: &'a [Expr],
    },
    BlobThreshold(&'a Expr),
    BlobComponent {
        strength: &'a Expr,
        radius: &'a Expr,
        centre: &'a Expr,
    },
    Triangle {
        a: &'a Expr,
        b: &'a Expr,
        c: &'a Expr,
    },
    SmoothTriangle {
        a: &'a Expr,
        a_normal: &'a Expr,
        b: &'a Expr,
        b_normal: &'a Expr,
        c: &'a Expr,
        c_normal: &'a Expr,
    },
    MeshFile(&'a Expr),
    InsideVector(&'a Expr),
    TextureList(&'a Expr),
    Flag {
        on: Option<&'a Expr>,
    },
    Translate(&'a Expr),
    Rotate(&'a Expr),
    Scale(&'a Expr),
    Matrix(&'a Expr),
    Pigment {
        colour: Option<&'a Expr>,
    },
    WarpItem {
        values: &'a [Expr],
    },
    BumpSize(&'a Expr),
    Ambient(&'a Expr),
    Emission(&'a Expr),
    Diffuse {
        amount: &'a Expr,
        back: Option<&'a Expr>,
    },
    Brilliance(&'a Expr),
    Phong(&'a Expr),
    PhongSize(&'a Expr),
    Specular(&'a Expr),
    Roughness(&'a Expr),
    Metallic {
        amount: Option<&'a Expr>,
    },
    Crand(&'a Expr),
    Irid(&'a Expr),
    Thickness(&'a Expr),
    IridWavelength(&'a Expr),
    Reflection {
        first: &'a Expr,
        max: Option<&'a Expr>,
    },
    Falloff(&'a Expr),
    ReflectionExponent(&'a Expr),
    ImageOrientation(&'a Expr),
    Exponent(&'a Expr),
    Fresnel {
        on: Option<&'a Expr>,
    },
    PointAt(&'a Expr),
    Radius(&'a Expr),
    Tightness(&'a Expr),
    AreaLight {
        axis1: &'a Expr,
        axis2: &'a Expr,
        size1: &'a Expr,
        size2: &'a Expr,
    },
    Adaptive(&'a Expr),
    AreaIllumination {
        on: Option<&'a Expr>,
    },
    Pattern {
        values: &'a [Expr],
    },
    PatternModifier {
        value: Option<&'a Expr>,
        factor: Option<&'a Expr>,
    },
    ImageMap(&'a Expr),
    ImageGamma {
        gamma: Option<&'a Expr>,
    },
    SlopeBlock {
        direction: &'a Expr,
        low: Option<&'a Expr>,
        high: Option<&'a Expr>,
    },
    SlopeAltitude {
        altitude: &'a Expr,
        low: Option<&'a Expr>,
        high: Option<&'a Expr>,
    },
    TriangleUv {
        a: &'a Expr,
        b: &'a Expr,
        c: &'a Expr,
    },
    ObjectPattern {
        colours: &'a [Expr],
    },
    MaterialMap(&'a Expr),
    MapType(&'a Expr),
    Interpolate(&'a Expr),
    Ior(&'a Expr),
    Refraction(&'a Expr),
    FadeDistance(&'a Expr),
    FadePower(&'a Expr),
    Caustics(&'a Expr),
    FadeColour(&'a Expr),
    RangeHead {
        low: &'a Expr,
        high: &'a Expr,
    },
    Subscript(&'a Expr),
    Deprecation(&'a Expr),
    ColourItem(&'a Expr),
    Unknown {
        values: &'a [Expr],
    },
    VertexVectors(List<'a>),
    NormalVectors(List<'a>),
    UvVectors(List<'a>),
    FaceIndices(List<'a>),
    NormalIndices(List<'a>),
    UvIndices(List<'a>),
    /// `filter all F` (no index) or `filter I, F` in an image_map.
    ImageSeeThrough {
        index: Option<&'a Expr>,
        amount: &'a Expr,
    },
    /// `#for (counter, start, end [, step])`.
    For {
        counter: &'a Node,
        start: &'a Expr,
        end: &'a Expr,
        step: Option<&'a Expr>,
    },
    /// `#fopen name file mode`.
    FileOpen {
        name: &'a Node,
        file: &'a Expr,
        mode: &'a Node,
    },
    /// `#fclose name`.
    FileClose {
        name: &'a Node,
    },
    /// `#read (file, targets…)`.
    FileRead {
        file: &'a Node,
        targets: &'a [Node],
    },
    /// `#write (file, items…)`.
    FileWrite {
        file: &'a Node,
        items: &'a [Node],
    },
    /// One value of `#write`, with its binary kind (`uint8` …) if given.
    WriteItem {
        value: &'a Expr,
        kind: Option<&'a Node>,
    },
    /// `#macro name(params…)`.
    MacroDef {
        name: &'a Node,
        params: &'a [Node],
    },
    /// `#ifdef (name)`: `None` for something that is not a name (never defined).
    IfDef {
        name: Option<&'a Node>,
    },
    /// One element of an array's initializer.
    ArrayElem(Element<'a>),
    /// `#declare [deprecated …] name[subscripts…] =`.
    Declare {
        deprecation: Option<&'a Node>,
        name: &'a Node,
        subscripts: &'a [Node],
    },
    /// `contained_by { box {…} | sphere {…} }`.
    ContainedBy {
        shape: &'a Node,
    },
    /// `object { body modifiers… }` (and `sphere { Name … }`).
    ObjectRef {
        body: &'a Node,
        modifiers: &'a [Node],
    },
    /// `looks_like { body modifiers… }` or `projected_through { … }`.
    LooksLike {
        body: &'a Node,
        modifiers: &'a [Node],
    },
    /// An entry of a map: its values (`[v, C]`, `[v1, v2, C1, C2]`, `[v, <h, s>]`, `[v]`, or
    /// none in an average) and its body (`[v PIGMENT]`), if it has one.
    MapEntry {
        values: &'a [Expr],
        body: Option<&'a Node>,
    },
    /// `mesh2 { lists… [inside_vector] modifiers… }`.
    Mesh2(Mesh2Parts<'a>),
    /// A union's member a loop made again: the member as first read, its words' slots moved.
    Again {
        member: &'a Node,
        by: u32,
    },
    /// No values: a block of items, a word, or a reference (read by its word and items).
    Block,
    /// Values that do not have the layout of the node's kind (the grammar makes none).
    Malformed,
}

/// A mesh2's lists, in the order the grammar requires them, and what follows them.
#[derive(Clone, Copy, Debug)]
pub struct Mesh2Parts<'a> {
    /// `vertex_vectors`.
    pub vertices: &'a Node,
    /// `normal_vectors`.
    pub normals: Option<&'a Node>,
    /// `uv_vectors`.
    pub uvs: Option<&'a Node>,
    /// `texture_list`.
    pub textures: Option<&'a Node>,
    /// `face_indices`.
    pub faces: &'a Node,
    /// `normal_indices`.
    pub normal_indices: Option<&'a Node>,
    /// `uv_indices`.
    pub uv_indices: Option<&'a Node>,
    /// Its `inside_vector` and modifiers.
    pub rest: &'a [Node],
}

/// A mesh2 list's body.
#[allow(missing_docs)]
#[derive(Clone, Copy, Debug)]
pub enum List<'a> {
    /// The announced count and the entries (texture indices among the faces' after a
    /// texture_list).
    Entries {
        count: &'a Expr,
        entries: &'a [Expr],
    },
    /// Read by a fast lane into numbers.
    Bulk(&'a BulkList),
}

/// An array element as written: a value, or an item (a nested initializer, an object …).
#[allow(missing_docs)]
#[derive(Clone, Copy, Debug)]
pub enum Element<'a> {
    Value(&'a Expr),
    Item(&'a Node),
}

impl Node {
    /// The node's values and items by name.
    pub fn view(&self) -> View<'_> {
        let args = self.args.as_slice();
        let children = self.children.as_slice();
        match self.kind {
            NodeKind::LightSource => match args {
                [location, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::LightSource {
                        location,
                        colour: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Background => one(args).map_or(View::Malformed, View::Background),
            NodeKind::FogDistance => one(args).map_or(View::Malformed, View::FogDistance),
            NodeKind::FogType => one(args).map_or(View::Malformed, View::FogType),
            NodeKind::FogAlt => one(args).map_or(View::Malformed, View::FogAlt),
            NodeKind::FogOffset => one(args).map_or(View::Malformed, View::FogOffset),
            NodeKind::TurbDepth => one(args).map_or(View::Malformed, View::TurbDepth),
            NodeKind::FogColour => one(args).map_or(View::Malformed, View::FogColour),
            NodeKind::AssumedGamma => one(args).map_or(View::Malformed, View::AssumedGamma),
            NodeKind::MaxTraceLevel => one(args).map_or(View::Malformed, View::MaxTraceLevel),
            NodeKind::AdcBailout => one(args).map_or(View::Malformed, View::AdcBailout),
            NodeKind::AmbientLight => one(args).map_or(View::Malformed, View::AmbientLight),
            NodeKind::MaxIntersections => one(args).map_or(View::Malformed, View::MaxIntersections),
            NodeKind::MeshCamera => match args {
                [rays, distribution, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::MeshCamera {
                        rays,
                        distribution,
                        max_distance: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Location => one(args).map_or(View::Malformed, View::Location),
            NodeKind::LookAt => one(args).map_or(View::Malformed, View::LookAt),
            NodeKind::Direction => one(args).map_or(View::Malformed, View::Direction),
            NodeKind::Up => one(args).map_or(View::Malformed, View::Up),
            NodeKind::Right => one(args).map_or(View::Malformed, View::Right),
            NodeKind::Sky => one(args).map_or(View::Malformed, View::Sky),
            NodeKind::Angle => match args {
                [angle, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Angle {
                        angle,
                        vertical: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Sphere => match args {
                [centre, radius, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Sphere {
                        centre,
                        radius,
                        strength: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Plane => match args {
                [normal, distance] => View::Plane { normal, distance },
                _ => View::Malformed,
            },
            NodeKind::Box => match args {
                [corner1, corner2] => View::Box { corner1, corner2 },
                _ => View::Malformed,
            },
            NodeKind::Cylinder => match args {
                [base, cap, radius, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Cylinder {
                        base,
                        cap,
                        radius,
                        strength: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Cone => match args {
                [base, base_radius, cap, cap_radius] => View::Cone {
                    base,
                    base_radius,
                    cap,
                    cap_radius,
                },
                _ => View::Malformed,
            },
            NodeKind::Disc => match args {
                [centre, normal, radius, rest @ ..] => View::Disc {
                    centre,
                    normal,
                    radius,
                    holes: rest,
                },
                _ => View::Malformed,
            },
            NodeKind::Torus => match args {
                [major, minor] => View::Torus { major, minor },
                _ => View::Malformed,
            },
            NodeKind::RadiositySetting => match args {
                [value, rest @ ..] if rest.len() <= 1 => View::RadiositySetting {
                    value,
                    second: rest.first(),
                },
                _ => View::Malformed,
            },
            NodeKind::Importance => one(args).map_or(View::Malformed, View::Importance),
            NodeKind::MediaSetting => match args {
                [value, rest @ ..] if rest.len() <= 1 => View::MediaSetting {
                    value,
                    second: rest.first(),
                },
                _ => View::Malformed,
            },
            NodeKind::Scattering => match args {
                [kind, colour] => View::Scattering { kind, colour },
                _ => View::Malformed,
            },
            NodeKind::ScatteringSetting => {
                one(args).map_or(View::Malformed, View::ScatteringSetting)
            }
            NodeKind::RainbowSetting => one(args).map_or(View::Malformed, View::RainbowSetting),
            NodeKind::Dispersion => one(args).map_or(View::Malformed, View::Dispersion),
            NodeKind::LightMedia => match args {
                rest if rest.len() <= 1 => View::LightMedia { on: rest.first() },
                _ => View::Malformed,
            },
            NodeKind::CameraBlur => match args {
                [value, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::CameraBlur {
                        value,
                        max: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Function => match args {
                rest if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Function { body: rest.next() }
                }
                _ => View::Malformed,
            },
            NodeKind::Spline => View::Spline { values: args },
            NodeKind::PigmentPattern => match args {
                rest if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::PigmentPattern {
                        colour: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Value => one(args).map_or(View::Malformed, View::Value),
            NodeKind::FunctionImage => match args {
                [width, height, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::FunctionImage {
                        width,
                        height,
                        body: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Parametric => match args {
                [uv_min, uv_max] => View::Parametric { uv_min, uv_max },
                _ => View::Malformed,
            },
            NodeKind::IsoSetting => View::IsoSetting { values: args },
            NodeKind::BlobThreshold => one(args).map_or(View::Malformed, View::BlobThreshold),
            NodeKind::BlobComponent => match args {
                [strength, radius, centre] => View::BlobComponent {
                    strength,
                    radius,
                    centre,
                },
                _ => View::Malformed,
            },
            NodeKind::Triangle => match args {
                [a, b, c] => View::Triangle { a, b, c },
                _ => View::Malformed,
            },
            NodeKind::SmoothTriangle => match args {
                [a, a_normal, b, b_normal, c, c_normal] => View::SmoothTriangle {
                    a,
                    a_normal,
                    b,
                    b_normal,
                    c,
                    c_normal,
                },
                _ => View::Malformed,
            },
            NodeKind::MeshFile => one(args).map_or(View::Malformed, View::MeshFile),
            NodeKind::InsideVector => one(args).map_or(View::Malformed, View::InsideVector),
            NodeKind::TextureList => one(args).map_or(View::Malformed, View::TextureList),
            NodeKind::Flag => match args {
                rest if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Flag { on: rest.next() }
                }
                _ => View::Malformed,
            },
            NodeKind::Translate => one(args).map_or(View::Malformed, View::Translate),
            NodeKind::Rotate => one(args).map_or(View::Malformed, View::Rotate),
            NodeKind::Scale => one(args).map_or(View::Malformed, View::Scale),
            NodeKind::Matrix => one(args).map_or(View::Malformed, View::Matrix),
            NodeKind::Pigment | NodeKind::Density => match args {
                rest if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Pigment {
                        colour: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::WarpItem => View::WarpItem { values: args },
            NodeKind::BumpSize => one(args).map_or(View::Malformed, View::BumpSize),
            NodeKind::Ambient => one(args).map_or(View::Malformed, View::Ambient),
            NodeKind::Emission => one(args).map_or(View::Malformed, View::Emission),
            NodeKind::Diffuse => match args {
                [amount, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Diffuse {
                        amount,
                        back: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Brilliance => one(args).map_or(View::Malformed, View::Brilliance),
            NodeKind::Phong => one(args).map_or(View::Malformed, View::Phong),
            NodeKind::PhongSize => one(args).map_or(View::Malformed, View::PhongSize),
            NodeKind::Specular => one(args).map_or(View::Malformed, View::Specular),
            NodeKind::Roughness => one(args).map_or(View::Malformed, View::Roughness),
            NodeKind::Metallic => match args {
                rest if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Metallic {
                        amount: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Crand => one(args).map_or(View::Malformed, View::Crand),
            NodeKind::Irid => one(args).map_or(View::Malformed, View::Irid),
            NodeKind::Thickness => one(args).map_or(View::Malformed, View::Thickness),
            NodeKind::IridWavelength => one(args).map_or(View::Malformed, View::IridWavelength),
            NodeKind::Reflection => match args {
                [first, rest @ ..] if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Reflection {
                        first,
                        max: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::Falloff => one(args).map_or(View::Malformed, View::Falloff),
            NodeKind::ReflectionExponent => {
                one(args).map_or(View::Malformed, View::ReflectionExponent)
            }
            NodeKind::ImageOrientation => one(args).map_or(View::Malformed, View::ImageOrientation),
            NodeKind::Exponent => one(args).map_or(View::Malformed, View::Exponent),
            NodeKind::Fresnel => match args {
                rest if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::Fresnel { on: rest.next() }
                }
                _ => View::Malformed,
            },
            NodeKind::PointAt => one(args).map_or(View::Malformed, View::PointAt),
            NodeKind::Radius => one(args).map_or(View::Malformed, View::Radius),
            NodeKind::Tightness => one(args).map_or(View::Malformed, View::Tightness),
            NodeKind::AreaLight => match args {
                [axis1, axis2, size1, size2] => View::AreaLight {
                    axis1,
                    axis2,
                    size1,
                    size2,
                },
                _ => View::Malformed,
            },
            NodeKind::Adaptive => one(args).map_or(View::Malformed, View::Adaptive),
            NodeKind::AreaIllumination => match args {
                rest if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::AreaIllumination { on: rest.next() }
                }
                _ => View::Malformed,
            },
            NodeKind::Pattern => View::Pattern { values: args },
            NodeKind::PatternModifier => match args {
                rest if rest.len() <= 2 => {
                    let mut rest = rest.iter();
                    View::PatternModifier {
                        value: rest.next(),
                        factor: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::ImageMap => one(args).map_or(View::Malformed, View::ImageMap),
            NodeKind::ImageGamma => match args {
                rest if rest.len() <= 1 => {
                    let mut rest = rest.iter();
                    View::ImageGamma { gamma: rest.next() }
                }
                _ => View::Malformed,
            },
            NodeKind::SlopeBlock => match args {
                [direction, rest @ ..] if rest.len() <= 2 => {
                    let mut rest = rest.iter();
                    View::SlopeBlock {
                        direction,
                        low: rest.next(),
                        high: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::SlopeAltitude => match args {
                [altitude, rest @ ..] if rest.len() <= 2 => {
                    let mut rest = rest.iter();
                    View::SlopeAltitude {
                        altitude,
                        low: rest.next(),
                        high: rest.next(),
                    }
                }
                _ => View::Malformed,
            },
            NodeKind::TriangleUv => match args {
                [a, b, c] => View::TriangleUv { a, b, c },
                _ => View::Malformed,
            },
            NodeKind::ObjectPattern => View::ObjectPattern { colours: args },
            NodeKind::MaterialMap => one(args).map_or(View::Malformed, View::MaterialMap),
            NodeKind::MapType => one(args).map_or(View::Malformed, View::MapType),
            NodeKind::Interpolate => one(args).map_or(View::Malformed, View::Interpolate),
            NodeKind::Ior => one(args).map_or(View::Malformed, View::Ior),
            NodeKind::Refraction => one(args).map_or(View::Malformed, View::Refraction),
            NodeKind::FadeDistance => one(args).map_or(View::Malformed, View::FadeDistance),
            NodeKind::FadePower => one(args).map_or(View::Malformed, View::FadePower),
            NodeKind::Caustics => one(args).map_or(View::Malformed, View::Caustics),
            NodeKind::FadeColour => one(args).map_or(View::Malformed, View::FadeColour),
            NodeKind::RangeHead => match args {
                [low, high] => View::RangeHead { low, high },
                _ => View::Malformed,
            },
            NodeKind::Subscript => one(args).map_or(View::Malformed, View::Subscript),
            NodeKind::Deprecation => one(args).map_or(View::Malformed, View::Deprecation),
            NodeKind::ColourItem => one(args).map_or(View::Malformed, View::ColourItem),
            NodeKind::Unknown => View::Unknown { values: args },
            NodeKind::VertexVectors => list(args).map_or(View::Malformed, View::VertexVectors),
            NodeKind::NormalVectors => list(args).map_or(View::Malformed, View::NormalVectors),
            NodeKind::UvVectors => list(args).map_or(View::Malformed, View::UvVectors),
            NodeKind::FaceIndices => list(args).map_or(View::Malformed, View::FaceIndices),
            NodeKind::NormalIndices => list(args).map_or(View::Malformed, View::NormalIndices),
            NodeKind::UvIndices => list(args).map_or(View::Malformed, View::UvIndices),
            NodeKind::ImageSeeThrough => match args {
                [amount] => View::ImageSeeThrough {
                    index: None,
                    amount,
                },
                [index, amount] => View::ImageSeeThrough {
                    index: Some(index),
                    amount,
                },
                _ => View::Malformed,
            },
            NodeKind::For => match (children, args) {
                ([counter], [start, end, rest @ ..]) if rest.len() <= 1 => View::For {
                    counter,
                    start,
                    end,
                    step: rest.first(),
                },
                _ => View::Malformed,
            },
            NodeKind::FileOpen => match (children, args) {
                ([name, mode], [file]) => View::FileOpen { name, file, mode },
                _ => View::Malformed,
            },
            NodeKind::FileClose => match children {
                [name] => View::FileClose { name },
                _ => View::Malformed,
            },
            NodeKind::FileRead => match children {
                [file, targets @ ..] => View::FileRead { file, targets },
                _ => View::Malformed,
            },
            NodeKind::FileWrite => match children {
                [file, items @ ..] => View::FileWrite { file, items },
                _ => View::Malformed,
            },
            NodeKind::WriteItem => match (args, children) {
                ([value], [] | [_]) => View::WriteItem {
                    value,
                    kind: children.first(),
                },
                _ => View::Malformed,
            },
            NodeKind::MacroDef => match children {
                [name, params @ ..] => View::MacroDef { name, params },
                _ => View::Malformed,
            },
            NodeKind::IfDef => match (children, args) {
                ([name], []) => View::IfDef { name: Some(name) },
                ([], [_]) => View::IfDef { name: None },
                _ => View::Malformed,
            },
            NodeKind::ArrayElem => match (args, children) {
                ([value], []) => View::ArrayElem(Element::Value(value)),
                ([], [item]) => View::ArrayElem(Element::Item(item)),
                _ => View::Malformed,
            },
            NodeKind::Declare => {
                let (deprecation, rest) = match children {
                    [d, rest @ ..] if d.kind == NodeKind::Deprecation => (Some(d), rest),
                    _ => (None, children),
                };
                match rest {
                    [name, subscripts @ ..] => View::Declare {
                        deprecation,
                        name,
                        subscripts,
                    },
                    [] => View::Malformed,
                }
            }
            NodeKind::ContainedBy => match children {
                [shape] => View::ContainedBy { shape },
                _ => View::Malformed,
            },
            NodeKind::ObjectRef => match children {
                [body, modifiers @ ..] => View::ObjectRef { body, modifiers },
                [] => View::Malformed,
            },
            NodeKind::LooksLike => match children {
                [body, modifiers @ ..] => View::LooksLike { body, modifiers },
                [] => View::Malformed,
            },
            NodeKind::MapEntry => match children {
                [] | [_] => View::MapEntry {
                    values: args,
                    body: children.first(),
                },
                _ => View::Malformed,
            },
            NodeKind::Mesh2 => {
                let mut rest = children;
                let vertices = take(&mut rest, NodeKind::VertexVectors);
                let normals = take(&mut rest, NodeKind::NormalVectors);
                let uvs = take(&mut rest, NodeKind::UvVectors);
                let textures = take(&mut rest, NodeKind::TextureList);
                let faces = take(&mut rest, NodeKind::FaceIndices);
                let normal_indices = take(&mut rest, NodeKind::NormalIndices);
                let uv_indices = take(&mut rest, NodeKind::UvIndices);
                match (vertices, faces) {
                    (Some(vertices), Some(faces)) => View::Mesh2(Mesh2Parts {
                        vertices,
                        normals,
                        uvs,
                        textures,
                        faces,
                        normal_indices,
                        uv_indices,
                        rest,
                    }),
                    _ => View::Malformed,
                }
            }
            NodeKind::Again => match self.again() {
                Some((member, by)) => View::Again { member, by },
                None => View::Malformed,
            },
            NodeKind::Default
            | NodeKind::Camera
            | NodeKind::Fog
            | NodeKind::Media
            | NodeKind::Rainbow
            | NodeKind::Radiosity
            | NodeKind::ObjectRadiosity
            | NodeKind::GlobalSettings
            | NodeKind::Perspective
            | NodeKind::CameraType
            | NodeKind::MeshCameraSmooth
            | NodeKind::Orthographic
            | NodeKind::Shape
            | NodeKind::Charset
            | NodeKind::Blob
            | NodeKind::PatternFunction
            | NodeKind::FunctionParams
            | NodeKind::Isosurface
            | NodeKind::Union
            | NodeKind::Mesh
            | NodeKind::Transform
            | NodeKind::Inverse
            | NodeKind::Texture
            | NodeKind::Normal
            | NodeKind::PigmentMap
            | NodeKind::TextureMap
            | NodeKind::Warp
            | NodeKind::SlopeMap
            | NodeKind::NormalMap
            | NodeKind::Finish
            | NodeKind::Material
            | NodeKind::ConserveEnergy
            | NodeKind::Albedo
            | NodeKind::SkySphere
            | NodeKind::LightFlag
            | NodeKind::ColourMap
            | NodeKind::ImageType
            | NodeKind::SlopePointAt
            | NodeKind::UvMapping
            | NodeKind::Tiles
            | NodeKind::TilesFirst
            | NodeKind::MagnetForm
            | NodeKind::Once
            | NodeKind::ImageUse
            | NodeKind::Interior
            | NodeKind::BoundedBy
            | NodeKind::InteriorTexture
            | NodeKind::LayeredTexture
            | NodeKind::IdentRef
            | NodeKind::Array
            | NodeKind::ArrayInit => View::Block,
        }
    }
}

/// The value of a construct that takes exactly one.
fn one(args: &[Expr]) -> Option<&Expr> {
    match args {
        [value] => Some(value),
        _ => None,
    }
}

/// The first of `items` if it is of `kind` (and `items` then past it).
fn take<'a>(items: &mut &'a [Node], kind: NodeKind) -> Option<&'a Node> {
    match *items {
        [first, after @ ..] if first.kind == kind => {
            *items = after;
            Some(first)
        }
        _ => None,
    }
}

/// A mesh2 list's values: a fast lane's numbers, or the count and the entries.
fn list(args: &[Expr]) -> Option<List<'_>> {
    match args {
        [
            Expr {
                kind: ExprKind::Bulk(list),
                ..
            },
        ] => Some(List::Bulk(list)),
        [count, entries @ ..] => Some(List::Entries { count, entries }),
        [] => None,
    }
}
