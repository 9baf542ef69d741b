//! Every keyword of POV-Ray 3.7 (its reserved words, from its parser's word table) and what
//! trace does with it: supported, or unsupported with the reason given in the error. A word in
//! neither list is not a POV-Ray keyword, so "unknown" in a message is always a true unknown.
//! docs/keywords.md is generated from this table (tests/integration/keywords.rs checks it).
//!
//! Anything POV-Ray would accept but trace cannot render faithfully must be an error that
//! names the construct, never a silent skip.

/// The reserved words of POV-Ray 3.7.0, sorted.
pub const POVRAY_KEYWORDS: &[&str] = &[
    "aa_level",
    "aa_threshold",
    "abs",
    "absorption",
    "accuracy",
    "acos",
    "acosh",
    "adaptive",
    "adc_bailout",
    "agate",
    "agate_turb",
    "albedo",
    "all",
    "all_intersections",
    "alpha",
    "altitude",
    "always_sample",
    "ambient",
    "ambient_light",
    "angle",
    "anisotropy",
    "aoi",
    "aperture",
    "append",
    "arc_angle",
    "area_illumination",
    "area_light",
    "array",
    "asc",
    "ascii",
    "asin",
    "asinh",
    "assumed_gamma",
    "atan",
    "atan2",
    "atanh",
    "autostop",
    "average",
    "b_spline",
    "background",
    "bezier_spline",
    "bicubic_patch",
    "bitwise_and",
    "bitwise_or",
    "bitwise_xor",
    "black_hole",
    "blob",
    "blue",
    "blur_samples",
    "bmp",
    "bokeh",
    "bounded_by",
    "box",
    "boxed",
    "bozo",
    "break",
    "brick",
    "brick_size",
    "brilliance",
    "bump_map",
    "bump_size",
    "bumps",
    "camera",
    "case",
    "caustics",
    "ceil",
    "cells",
    "charset",
    "checker",
    "chr",
    "circular",
    "clipped_by",
    "clock",
    "clock_on",
    "collect",
    "color",
    "color_map",
    "colour",
    "colour_map",
    "component",
    "composite",
    "concat",
    "cone",
    "confidence",
    "conic_sweep",
    "conserve_energy",
    "contained_by",
    "control0",
    "control1",
    "cos",
    "cosh",
    "crackle",
    "crand",
    "cube",
    "cubic",
    "cubic_spline",
    "cubic_wave",
    "cutaway_textures",
    "cylinder",
    "cylindrical",
    "datetime",
    "debug",
    "declare",
    "default",
    "defined",
    "degrees",
    "density",
    "density_file",
    "density_map",
    "dents",
    "deprecated",
    "df3",
    "difference",
    "diffuse",
    "dimension_size",
    "dimensions",
    "direction",
    "disc",
    "dispersion",
    "dispersion_samples",
    "dist_exp",
    "distance",
    "div",
    "double_illuminate",
    "dtag",
    "eccentricity",
    "else",
    "elseif",
    "emission",
    "end",
    "error",
    "evaluate",
    "exp",
    "expand_thresholds",
    "exponent",
    "exr",
    "exterior",
    "extinction",
    "face_indices",
    "facets",
    "fade_color",
    "fade_colour",
    "fade_distance",
    "fade_power",
    "falloff",
    "falloff_angle",
    "false",
    "fclose",
    "file_exists",
    "filter",
    "finish",
    "fisheye",
    "flatness",
    "flip",
    "floor",
    "focal_point",
    "fog",
    "fog_alt",
    "fog_offset",
    "fog_type",
    "fopen",
    "for",
    "form",
    "frequency",
    "fresnel",
    "function",
    "gamma",
    "gather",
    "gif",
    "global",
    "global_lights",
    "gradient",
    "granite",
    "gray",
    "green",
    "hdr",
    "height_field",
    "hexagon",
    "hierarchy",
    "hollow",
    "hypercomplex",
    "if",
    "ifdef",
    "iff",
    "ifndef",
    "image_map",
    "image_pattern",
    "importance",
    "include",
    "inside",
    "inside_vector",
    "int",
    "interior",
    "interior_texture",
    "internal",
    "interpolate",
    "intersection",
    "intervals",
    "inverse",
    "ior",
    "irid",
    "irid_wavelength",
    "isosurface",
    "jitter",
    "jpeg",
    "julia",
    "julia_fractal",
    "lambda",
    "lathe",
    "leopard",
    "light_group",
    "light_source",
    "linear_spline",
    "linear_sweep",
    "ln",
    "load_file",
    "local",
    "location",
    "log",
    "look_at",
    "looks_like",
    "macro",
    "magnet",
    "major_radius",
    "mandel",
    "map_type",
    "marble",
    "material",
    "material_map",
    "matrix",
    "max",
    "max_extent",
    "max_gradient",
    "max_intersections",
    "max_iteration",
    "max_sample",
    "max_trace",
    "max_trace_level",
    "media",
    "media_attenuation",
    "media_interaction",
    "merge",
    "mesh",
    "mesh2",
    "mesh_camera",
    "metallic",
    "method",
    "min",
    "mm_per_unit",
    "mod",
    "mortar",
    "natural_spline",
    "no",
    "no_bump_scale",
    "no_image",
    "no_radiosity",
    "no_reflection",
    "no_shadow",
    "noise_generator",
    "normal",
    "normal_indices",
    "normal_map",
    "normal_vectors",
    "now",
    "number_of_sides",
    "number_of_tiles",
    "number_of_waves",
    "object",
    "octaves",
    "off",
    "offset",
    "omega",
    "omnimax",
    "on",
    "once",
    "onion",
    "open",
    "orient",
    "orientation",
    "orthographic",
    "ovus",
    "panoramic",
    "parallel",
    "parametric",
    "pass_through",
    "pattern",
    "pavement",
    "perspective",
    "pgm",
    "phase",
    "phong",
    "phong_size",
    "photons",
    "pi",
    "pigment",
    "pigment_map",
    "pigment_pattern",
    "planar",
    "plane",
    "png",
    "point_at",
    "poly",
    "poly_wave",
    "polygon",
    "polynomial",
    "pot",
    "pow",
    "ppm",
    "precision",
    "precompute",
    "premultiplied",
    "pretrace_end",
    "pretrace_start",
    "prism",
    "prod",
    "projected_through",
    "pwr",
    "quadratic_spline",
    "quadric",
    "quartic",
    "quaternion",
    "quick_color",
    "quick_colour",
    "quilted",
    "radial",
    "radians",
    "radius",
    "rainbow",
    "ramp_wave",
    "rand",
    "range",
    "ratio",
    "read",
    "red",
    "reflection",
    "reflection_exponent",
    "refraction",
    "render",
    "repeat",
    "rgb",
    "rgbf",
    "rgbft",
    "rgbt",
    "right",
    "ripples",
    "rotate",
    "roughness",
    "samples",
    "save_file",
    "sblue",
    "scale",
    "scallop_wave",
    "scattering",
    "seed",
    "select",
    "sgreen",
    "shadowless",
    "sin",
    "sine_wave",
    "sinh",
    "sint16be",
    "sint16le",
    "sint32be",
    "sint32le",
    "sint8",
    "sky",
    "sky_sphere",
    "slice",
    "slope",
    "slope_map",
    "smooth",
    "smooth_triangle",
    "sor",
    "spacing",
    "specular",
    "sphere",
    "sphere_sweep",
    "spherical",
    "spiral1",
    "spiral2",
    "spline",
    "split_union",
    "spotlight",
    "spotted",
    "sqr",
    "sqrt",
    "square",
    "sred",
    "srgb",
    "srgbf",
    "srgbft",
    "srgbt",
    "statistics",
    "steps",
    "str",
    "strcmp",
    "strength",
    "strlen",
    "strlwr",
    "strupr",
    "sturm",
    "substr",
    "subsurface",
    "sum",
    "superellipsoid",
    "switch",
    "sys",
    "t",
    "tan",
    "tanh",
    "target",
    "text",
    "texture",
    "texture_list",
    "texture_map",
    "tga",
    "thickness",
    "threshold",
    "tiff",
    "tightness",
    "tile2",
    "tiles",
    "tiling",
    "tolerance",
    "toroidal",
    "torus",
    "trace",
    "transform",
    "translate",
    "translucency",
    "transmit",
    "triangle",
    "triangle_wave",
    "triangular",
    "true",
    "ttf",
    "turb_depth",
    "turbulence",
    "type",
    "u",
    "u_steps",
    "uint16be",
    "uint16le",
    "uint8",
    "ultra_wide_angle",
    "undef",
    "union",
    "up",
    "use_alpha",
    "use_color",
    "use_colour",
    "use_index",
    "utf8",
    "uv_indices",
    "uv_mapping",
    "uv_vectors",
    "v",
    "v_steps",
    "val",
    "variance",
    "vaxis_rotate",
    "vcross",
    "vdot",
    "version",
    "vertex_vectors",
    "vlength",
    "vnormalize",
    "vrotate",
    "vstr",
    "vturbulence",
    "warning",
    "warp",
    "water_level",
    "waves",
    "while",
    "width",
    "wood",
    "wrinkles",
    "write",
    "x",
    "xyz",
    "y",
    "yes",
    "z",
];

/// The POV-Ray keywords trace reads (somewhere: a keyword in the wrong place is still an
/// error), sorted.
const SUPPORTED: &[&str] = &[
    "abs",
    "acos",
    "acosh",
    "adaptive",
    "adc_bailout",
    "ambient",
    "ambient_light",
    "angle",
    "area_light",
    "array",
    "asc",
    "asin",
    "asinh",
    "assumed_gamma",
    "atan",
    "atan2",
    "atanh",
    "background",
    "bitwise_and",
    "bitwise_or",
    "bitwise_xor",
    "blue",
    "box",
    "break",
    "brilliance",
    "camera",
    "case",
    "ceil",
    "checker",
    "chr",
    "circular",
    "clock",
    "clock_on",
    "color",
    "color_map",
    "colour",
    "colour_map",
    "concat",
    "cone",
    "conserve_energy",
    "cos",
    "cosh",
    "cylinder",
    "datetime",
    "debug",
    "declare",
    "default",
    "defined",
    "degrees",
    "deprecated",
    "diffuse",
    "dimension_size",
    "dimensions",
    "direction",
    "disc",
    "distance",
    "div",
    "else",
    "elseif",
    "emission",
    "end",
    "error",
    "exp",
    "exponent",
    "face_indices",
    "fade_color",
    "fade_colour",
    "fade_distance",
    "fade_power",
    "falloff",
    "false",
    "file_exists",
    "filter",
    "finish",
    "floor",
    "fog",
    "fog_alt",
    "fog_offset",
    "fog_type",
    "for",
    "fresnel",
    "gradient",
    "gray",
    "green",
    "hollow",
    "if",
    "ifdef",
    "ifndef",
    "image_map",
    "include",
    "inside_vector",
    "int",
    "interior",
    "interpolate",
    "inverse",
    "ior",
    "jitter",
    "light_source",
    "ln",
    "local",
    "location",
    "log",
    "look_at",
    "macro",
    "map_type",
    "material",
    "matrix",
    "max",
    "max_trace_level",
    "mesh",
    "mesh2",
    "metallic",
    "min",
    "mod",
    "no",
    "no_shadow",
    "normal_indices",
    "normal_vectors",
    "object",
    "off",
    "on",
    "once",
    "open",
    "orient",
    "orthographic",
    "parallel",
    "perspective",
    "phong",
    "phong_size",
    "pi",
    "pigment",
    "plane",
    "png",
    "point_at",
    "pow",
    "radians",
    "radius",
    "rand",
    "range",
    "red",
    "reflection",
    "rgb",
    "rgbf",
    "rgbft",
    "rgbt",
    "right",
    "rotate",
    "roughness",
    "scale",
    "seed",
    "select",
    "shadowless",
    "sin",
    "sinh",
    "sky",
    "sky_sphere",
    "smooth_triangle",
    "specular",
    "sphere",
    "spotlight",
    "sqrt",
    "srgb",
    "srgbf",
    "srgbft",
    "srgbt",
    "str",
    "strcmp",
    "strlen",
    "strlwr",
    "strupr",
    "sturm",
    "substr",
    "switch",
    "t",
    "tan",
    "tanh",
    "texture",
    "tightness",
    "torus",
    "transform",
    "translate",
    "transmit",
    "triangle",
    "true",
    "u",
    "undef",
    "union",
    "up",
    "v",
    "val",
    "vaxis_rotate",
    "vcross",
    "vdot",
    "version",
    "vertex_vectors",
    "vlength",
    "vnormalize",
    "vrotate",
    "vstr",
    "warning",
    "while",
    "x",
    "y",
    "yes",
    "z",
];

/// What trace does with a POV-Ray keyword.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Read where POV-Ray reads it.
    Supported,
    /// Refused with this reason.
    Unsupported(&'static str),
}

/// What trace does with `word`, or `None` if it is not a POV-Ray keyword.
pub fn status(word: &str) -> Option<Status> {
    match reason(word) {
        Some(r) => Some(Status::Unsupported(r)),
        None => SUPPORTED
            .binary_search(&word)
            .is_ok()
            .then_some(Status::Supported),
    }
}

/// Whether `word` is one of POV-Ray's functions that trace does not support yet (called in
/// an expression; other unsupported keywords there are simply unknown functions).
pub fn is_unsupported_function(word: &str) -> bool {
    matches!(
        word,
        "min_extent"
            | "max_extent"
            | "trace"
            | "inside"
            | "eval_pigment"
            | "vturbulence"
            | "prod"
            | "sum"
            | "function"
            | "spline"
            | "fopen"
            | "fclose"
            | "read"
            | "write"
    )
}

/// Why trace rejects a POV-Ray keyword, or `None` if trace supports it or it is not a POV-Ray
/// keyword.
pub fn reason(word: &str) -> Option<&'static str> {
    const LATER: &str = "not supported by trace yet";
    Some(match word {
        "difference" | "intersection" | "merge" => "CSG is outside trace's subset",
        "blob" | "height_field" | "isosurface" | "julia_fractal" | "lathe" | "prism" | "sor"
        | "superellipsoid" | "text" | "polygon" | "bicubic_patch" | "quadric" | "cubic"
        | "quartic" | "poly" | "polynomial" | "sphere_sweep" | "ovus" | "parametric"
        | "light_group" | "lemon" => "this shape is not supported by trace yet",
        "media" | "rainbow" | "photons" | "radiosity" | "subsurface" | "scattering"
        | "absorption" | "density" | "emission_media" | "mm_per_unit" => "outside trace's subset",
        "dispersion" | "caustics" => "this interior item is outside trace's subset",
        "normal" | "bump_map" | "bumps" | "dents" | "wrinkles" | "ripples" | "waves" => {
            "surface normal perturbation is not supported by trace yet"
        }
        "irid" | "crand" | "albedo" => "this finish item is outside trace's subset",
        "looks_like" | "projected_through" | "media_interaction" | "media_attenuation" => {
            "this light_source item is outside trace's subset"
        }
        "pigment_map" | "texture_map" | "normal_map" | "slope_map" | "density_map" => LATER,
        "gif" | "tga" | "iff" | "ppm" | "pgm" | "jpeg" | "tiff" | "sys" | "exr" | "hdr" => {
            "only png image files are read by trace"
        }
        "agate" | "average" | "boxed" | "brick" | "bozo" | "cells" | "crackle" | "cylindrical"
        | "density_file" | "facets" | "function" | "granite" | "hexagon" | "julia" | "leopard"
        | "magnet" | "mandel" | "marble" | "onion" | "pavement" | "planar" | "quilted"
        | "radial" | "spherical" | "spiral1" | "spiral2" | "spotted" | "square" | "tiling"
        | "triangular" | "wood" | "object_pattern" | "slope" | "aoi" | "turbulence" | "warp"
        | "frequency" | "phase" | "ramp_wave" | "sine_wave" | "noise_generator" | "octaves"
        | "omega" | "lambda" | "uv_mapping" | "quick_color" | "quick_colour" | "material_map" => {
            "this pattern or pattern modifier is not supported by trace yet"
        }
        "no_image" | "no_reflection" | "double_illuminate" | "clipped_by" | "bounded_by"
        | "split_union" | "cutaway_textures" | "uv_vectors" => LATER,
        "fisheye" | "ultra_wide_angle" | "omnimax" | "panoramic" | "spherical_camera"
        | "cylinder_camera" | "focal_point" | "aperture" | "blur_samples" | "confidence"
        | "variance" | "mesh_camera" => "this camera type or item is not supported by trace yet",
        "fopen" | "fclose" | "read" | "write" | "render" | "statistics" => {
            "file input/output is not supported by trace yet"
        }
        "min_extent" | "max_extent" | "trace" | "inside" | "eval_pigment" | "spline" => LATER,
        "charset" | "hf_gray_16" | "irid_wavelength" | "max_intersections"
        | "noise_generator_gs" | "number_of_waves" | "subsurface_gs" => {
            "this global setting is outside trace's subset"
        }
        "aa_level" | "aa_threshold" | "always_sample" | "anisotropy" | "autostop" | "collect"
        | "dispersion_samples" | "eccentricity" | "expand_thresholds" | "extinction" | "gather"
        | "global" | "importance" | "intervals" | "load_file" | "max_sample" | "method"
        | "no_radiosity" | "pass_through" | "pretrace_end" | "pretrace_start" | "samples"
        | "save_file" | "spacing" | "steps" | "target" | "exterior" | "arc_angle"
        | "falloff_angle" => {
            "media, radiosity, photons and subsurface scattering are outside trace's subset"
        }
        "accuracy" | "all_intersections" | "b_spline" | "bezier_spline" | "component"
        | "conic_sweep" | "contained_by" | "cubic_spline" | "evaluate" | "flatness"
        | "hypercomplex" | "linear_spline" | "linear_sweep" | "max_gradient" | "max_trace"
        | "precision" | "pwr" | "quadratic_spline" | "quaternion" | "slice" | "smooth" | "sqr"
        | "strength" | "threshold" | "tolerance" | "ttf" | "u_steps" | "v_steps"
        | "water_level" | "offset" | "thickness" => {
            "this shape or shape item is not supported by trace yet"
        }
        "agate_turb" | "altitude" | "black_hole" | "brick_size" | "bump_size" | "cube"
        | "cubic_wave" | "dist_exp" | "flip" | "form" | "image_pattern" | "major_radius"
        | "max_iteration" | "mortar" | "no_bump_scale" | "number_of_sides" | "number_of_tiles"
        | "orientation" | "pigment_pattern" | "poly_wave" | "ratio" | "repeat" | "scallop_wave"
        | "tile2" | "tiles" | "toroidal" | "triangle_wave" | "turb_depth" | "use_alpha"
        | "use_color" | "use_colour" | "use_index" | "width" => {
            "this pattern or pattern modifier is not supported by trace yet"
        }
        "internal" | "pattern" | "precompute" | "prod" | "sum" | "vturbulence" => {
            "user functions are not supported by trace yet"
        }
        "append" | "sint16be" | "sint16le" | "sint32be" | "sint32le" | "sint8" | "uint16be"
        | "uint16le" | "uint8" | "df3" => "file input/output is not supported by trace yet",
        "bmp" | "pot" => "only png image files are read by trace",
        "all" | "alpha" | "gamma" | "premultiplied" => {
            "this image_map item is not supported by trace yet"
        }
        "control0" | "control1" | "natural_spline" => "splines are not supported by trace yet",
        "reflection_exponent" | "refraction" | "translucency" => {
            "this finish item is outside trace's subset"
        }
        "interior_texture" | "texture_list" | "uv_indices" | "hierarchy" => {
            "this object item is not supported by trace yet"
        }
        "area_illumination" | "global_lights" => {
            "this light_source item is not supported by trace yet"
        }
        "bokeh" | "type" => "this camera item is not supported by trace yet",
        "ascii" | "utf8" => "this global setting is outside trace's subset",
        "sred" | "sgreen" | "sblue" | "xyz" | "composite" | "dtag" | "now" => {
            "not supported by trace yet"
        }
        _ => return None,
    })
}

/// docs/keywords.md: every POV-Ray 3.7 keyword with what trace does with it.
pub fn markdown() -> String {
    let mut out = String::from(
        "# POV-Ray 3.7's keywords in trace\n\n\
         Generated from `src/eval/keywords.rs` (run `TRACE_UPDATE_DOCS=1 cargo test keywords` after\n\
         changing it). Every reserved word of POV-Ray 3.7.0 is listed once: trace reads it, or\n\
         refuses it with the reason below (an error that names the word, with a caret under it).\n\
         A word that is not here is not a POV-Ray keyword: trace calls it unknown. A supported\n\
         keyword in a place where trace does not read it is an error that says it cannot stand\n\
         there; `docs/language.md` says where each is read.\n\n",
    );
    let supported: Vec<&str> = POVRAY_KEYWORDS
        .iter()
        .copied()
        .filter(|w| status(w) == Some(Status::Supported))
        .collect();
    out += &format!("## Supported ({} words)\n\n", supported.len());
    out += &supported
        .iter()
        .map(|w| format!("`{w}`"))
        .collect::<Vec<_>>()
        .join(" ");
    out += "\n\n## Refused, by reason\n\n| reason | words |\n|---|---|\n";
    let mut reasons: Vec<&str> = Vec::new();
    for w in POVRAY_KEYWORDS {
        if let Some(r) = reason(w) {
            if !reasons.contains(&r) {
                reasons.push(r);
            }
        }
    }
    reasons.sort_unstable();
    for r in reasons {
        let words: Vec<String> = POVRAY_KEYWORDS
            .iter()
            .filter(|w| reason(w) == Some(r))
            .map(|w| format!("`{w}`"))
            .collect();
        out += &format!("| {r} | {} |\n", words.join(" "));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_povray_keyword_has_a_status_and_the_lists_are_sorted() {
        assert!(POVRAY_KEYWORDS.windows(2).all(|w| w[0] < w[1]));
        assert!(SUPPORTED.windows(2).all(|w| w[0] < w[1]));
        for word in POVRAY_KEYWORDS {
            assert!(status(word).is_some(), "{word}");
        }
        for word in SUPPORTED {
            assert_eq!(
                reason(word),
                None,
                "{word} is both supported and unsupported"
            );
        }
    }
}
