//! Every keyword of POV-Ray 3.7 (its reserved words, from its parser's word table) and what
//! trace does with it: supported, or unsupported with the reason given in the error. A word in
//! neither list is not a POV-Ray keyword, so "unknown" in a message is always a true unknown.
//! docs/keywords.md is generated from this table (tests/integration/keywords.rs checks it).
//!
//! Anything POV-Ray would accept but trace cannot render faithfully must be an error that
//! names the construct, never a silent skip.

pub use crate::syntax::keywords::POVRAY_KEYWORDS;

/// The POV-Ray keywords trace reads (somewhere: a keyword in the wrong place is still an
/// error), sorted.
const SUPPORTED: &[&str] = &[
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
    "all",
    "all_intersections",
    "alpha",
    "altitude",
    "always_sample",
    "ambient",
    "ambient_light",
    "angle",
    "aoi",
    "aperture",
    "append",
    "arc_angle",
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
    "bounded_by",
    "box",
    "boxed",
    "bozo",
    "break",
    "brick",
    "brick_size",
    "brightness",
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
    "coords",
    "cos",
    "cosh",
    "count",
    "crackle",
    "crand",
    "cube",
    "cubic",
    "cubic_spline",
    "cubic_wave",
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
    "eccentricity",
    "else",
    "elseif",
    "emission",
    "end",
    "error",
    "error_bound",
    "eval_pigment",
    "exp",
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
    "gif",
    "global_lights",
    "global_settings",
    "gradient",
    "granite",
    "gray",
    "gray_threshold",
    "green",
    "hdr",
    "height_field",
    "hexagon",
    "hf_gray_16",
    "hierarchy",
    "hollow",
    "hypercomplex",
    "if",
    "ifdef",
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
    "low_error_factor",
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
    "maximum_reuse",
    "media",
    "media_attenuation",
    "media_interaction",
    "mesh",
    "mesh2",
    "mesh_camera",
    "metallic",
    "method",
    "metric",
    "min",
    "min_extent",
    "minimum_reuse",
    "mod",
    "mortar",
    "natural_spline",
    "nearest_count",
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
    "pattern",
    "pavement",
    "perspective",
    "pgm",
    "phase",
    "phong",
    "phong_size",
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
    "pot",
    "pow",
    "ppm",
    "precision",
    "precompute",
    "pretrace_end",
    "pretrace_start",
    "prism",
    "prod",
    "projected_through",
    "quadratic_spline",
    "quadric",
    "quartic",
    "quaternion",
    "quick_color",
    "quick_colour",
    "quilted",
    "radial",
    "radians",
    "radiosity",
    "radius",
    "rainbow",
    "ramp_wave",
    "rand",
    "range",
    "ratio",
    "read",
    "recursion_limit",
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
    "scale",
    "scallop_wave",
    "scattering",
    "seed",
    "select",
    "shadowless",
    "sin",
    "sine_wave",
    "sinh",
    "sint16be",
    "sint16le",
    "sint32be",
    "sint32le",
    "sint8",
    "size",
    "sky",
    "sky_sphere",
    "slice",
    "slope",
    "slope_map",
    "smooth",
    "smooth_triangle",
    "solid",
    "sor",
    "specular",
    "sphere",
    "sphere_sweep",
    "spherical",
    "spiral1",
    "spiral2",
    "spline",
    "spotlight",
    "spotted",
    "sqr",
    "sqrt",
    "square",
    "srgb",
    "srgbf",
    "srgbft",
    "srgbt",
    "statistics",
    "str",
    "strcmp",
    "strength",
    "strlen",
    "strlwr",
    "strupr",
    "sturm",
    "substr",
    "sum",
    "superellipsoid",
    "switch",
    "sys",
    "t",
    "tan",
    "tanh",
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
    matches!(word, "function")
}

/// Why trace rejects a POV-Ray keyword, or `None` if trace supports it or it is not a POV-Ray
/// keyword.
pub fn reason(word: &str) -> Option<&'static str> {
    const LATER: &str = "not supported by trace yet";
    Some(match word {
        "difference" | "intersection" | "merge" => "CSG is outside trace's subset",
        "polynomial" | "lemon" => "this shape is not supported by trace yet",
        "photons" | "subsurface" | "emission_media" | "mm_per_unit" => "outside trace's subset",
        "albedo" => "this finish item is outside trace's subset",
        "iff" => "trace reads png, jpeg, gif, pot, tga, ppm, pgm, tiff, bmp, exr and hdr images",
        "clipped_by" | "split_union" | "cutaway_textures" => LATER,
        "spherical_camera" | "cylinder_camera" => {
            "this camera type or item is not supported by trace yet"
        }
        "noise_generator_gs" | "subsurface_gs" => "this global setting is outside trace's subset",
        "anisotropy" | "autostop" | "expand_thresholds" | "gather" | "global" | "pass_through"
        | "spacing" | "steps" | "target" | "distance_maximum" => {
            "photons and subsurface scattering are outside trace's subset"
        }
        "evaluate" | "pwr" | "reciprocal" => {
            "this shape or shape item is not supported by trace yet"
        }
        "premultiplied" => "this image_map item is not supported by trace yet",
        "translucency" => "this finish item is outside trace's subset",
        "area_illumination" => "this light_source item is not supported by trace yet",
        "bokeh" => "this camera item is not supported by trace yet",
        "sred" | "sgreen" | "sblue" | "xyz" | "dtag" => "not supported by trace yet",
        _ => return None,
    })
}

/// The keyword trace reads that `word` is probably a misspelling of (`pigmnt` → `pigment`):
/// the nearest by edits (a letter added, dropped, changed, or two swapped), at most one edit
/// for words of up to four letters and two for longer ones; `None` if none is that near.
pub fn suggestion(word: &str) -> Option<&'static str> {
    nearest(word, SUPPORTED.iter().copied())
}

/// The word of `words` nearest `word` by edits, as [`suggestion`] measures them.
pub fn nearest<'w>(word: &str, words: impl Iterator<Item = &'w str>) -> Option<&'w str> {
    let most = if word.chars().count() <= 4 { 1 } else { 2 };
    words
        .map(|k| (edits(word, k), k))
        .filter(|&(d, _)| d > 0 && d <= most)
        .min_by_key(|&(d, k)| (d, k.len().abs_diff(word.len())))
        .map(|(_, k)| k)
}

/// The optimal-string-alignment distance between `a` and `b` (Levenshtein with adjacent
/// swaps).
fn edits(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    if a.len().abs_diff(b.len()) > 2 {
        return usize::MAX;
    }
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            d[i][j] = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d[i][j] = d[i][j].min(d[i - 2][j - 2] + 1);
            }
        }
    }
    d[a.len()][b.len()]
}

/// docs/keywords.md: every POV-Ray 3.7 keyword with what trace does with it.
pub fn markdown() -> String {
    let mut out = String::from(
        "# POV-Ray 3.7's keywords in trace\n\n\
         Generated from `src/eval/lang/keywords.rs` (run `TRACE_UPDATE_DOCS=1 cargo test keywords` after\n\
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

    /// The identifiers quoted in `text` (`"word"`).
    fn quoted(text: &str) -> Vec<&str> {
        text.split('"')
            .skip(1)
            .step_by(2)
            .filter(|w| {
                w.starts_with(|c: char| c.is_ascii_lowercase())
                    && w.bytes()
                        .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_')
            })
            .collect()
    }

    #[test]
    fn the_grammar_reserves_the_tables_words_and_no_refused_one() {
        // The grammar's reserved words (syntax::keywords checks them against the grammar).
        let reserved = crate::syntax::keywords::reserved();
        assert!(reserved.len() > 150, "{}", reserved.len());
        use crate::syntax::keywords::EXTENSIONS;
        // Read by the grammar only to refuse where POV-Ray would do what trace does not:
        // `albedo` before a finish's number, `area_illumination` on an area light (without
        // one POV-Ray ignores it, and so does trace), an `iff` height field's image.
        const READ_TO_REFUSE: [&str; 3] = ["albedo", "area_illumination", "iff"];
        let wrong: Vec<String> = reserved
            .iter()
            .filter(|w| !EXTENSIONS.contains(w))
            .filter_map(|&word| match status(word) {
                Some(Status::Supported) => None,
                Some(Status::Unsupported(_)) if READ_TO_REFUSE.contains(&word) => None,
                other => Some(format!("`{word}` ({other:?})")),
            })
            .collect();
        assert!(
            wrong.is_empty(),
            "the grammar reserves, the table does not support: {wrong:?}"
        );
    }

    #[test]
    fn every_supported_word_is_read_by_the_grammar_or_the_evaluator() {
        // A supported word is named in the grammar, or by the evaluator, which reads
        // identifiers such as `vlength`, `x` or `clock` by name.
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut named: Vec<String> = quoted(include_str!("../../../grammar/scene.pest"))
            .into_iter()
            .map(str::to_string)
            .collect();
        let mut dirs = vec![root.join("src/eval"), root.join("src/syntax")];
        while let Some(dir) = dirs.pop() {
            for entry in std::fs::read_dir(&dir).expect("source folder") {
                let path = entry.expect("entry").path();
                if path.is_dir() {
                    dirs.push(path);
                } else if path.extension().is_some_and(|e| e == "rs")
                    && !path.ends_with("keywords.rs")
                {
                    let text = std::fs::read_to_string(&path).expect("source");
                    named.extend(quoted(&text).into_iter().map(str::to_string));
                }
            }
        }
        named.sort();
        named.dedup();
        let unread: Vec<&str> = SUPPORTED
            .iter()
            .copied()
            .filter(|w| named.binary_search(&w.to_string()).is_err())
            .collect();
        assert!(unread.is_empty(), "supported but named nowhere: {unread:?}");
        // And the table sorts (status() searches it).
        assert!(SUPPORTED.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn misspelt_keywords_find_the_keyword_meant() {
        assert_eq!(suggestion("pigmnt"), Some("pigment"));
        assert_eq!(suggestion("trasnlate"), Some("translate"));
        assert_eq!(suggestion("spere"), Some("sphere"));
        assert_eq!(suggestion("finsh"), Some("finish"));
        // Too far from every keyword, or a keyword already: nothing.
        assert_eq!(suggestion("MyTexture"), None);
        assert_eq!(suggestion("sphere"), None);
    }

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
