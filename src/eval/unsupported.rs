//! Words POV-Ray knows that trace does not support, with the reason given in the error.
//!
//! Anything POV-Ray would accept but trace cannot render faithfully must be an error that
//! names the construct, never a silent skip.

/// Why trace rejects a POV-Ray keyword, or `None` if the word is not one POV-Ray knows.
pub fn reason(word: &str) -> Option<&'static str> {
    const LATER: &str = "not supported by trace yet";
    Some(match word {
        "union" | "difference" | "intersection" | "merge" => "CSG is outside trace's subset",
        "cylinder" | "cone" | "disc" | "torus" | "triangle" | "smooth_triangle" | "mesh"
        | "mesh2" => LATER,
        "blob" | "height_field" | "isosurface" | "julia_fractal" | "lathe" | "prism" | "sor"
        | "superellipsoid" | "text" | "polygon" | "bicubic_patch" | "quadric" | "cubic"
        | "quartic" | "poly" | "polynomial" | "sphere_sweep" | "ovus" | "parametric"
        | "light_group" | "lemon" => "this shape is outside trace's subset",
        "media" | "fog" | "rainbow" | "photons" | "radiosity" | "subsurface" | "scattering"
        | "absorption" | "density" | "emission_media" | "mm_per_unit" => "outside trace's subset",
        "sky_sphere" | "interior" | "ior" | "fade_distance" | "fade_power" | "fade_color"
        | "fade_colour" | "dispersion" | "caustics" | "material" => LATER,
        "normal" | "bump_map" | "bumps" | "dents" | "wrinkles" | "ripples" | "waves" => {
            "surface normal perturbation is outside trace's subset"
        }
        "irid" | "crand" | "albedo" => "this finish item is outside trace's subset",
        "spotlight" | "parallel" | "shadowless" | "area_light" | "point_at" | "radius"
        | "tightness" | "adaptive" | "jitter" | "circular" | "orient" | "area_illumination" => {
            LATER
        }
        "looks_like" | "projected_through" | "media_interaction" | "media_attenuation" => {
            "this light_source item is outside trace's subset"
        }
        "checker" | "gradient" | "image_map" | "color_map" | "colour_map" | "pigment_map"
        | "texture_map" | "map_type" | "once" | "interpolate" | "png" => LATER,
        "agate" | "average" | "boxed" | "brick" | "bozo" | "cells" | "crackle" | "cylindrical"
        | "density_file" | "facets" | "function" | "granite" | "hexagon" | "julia" | "leopard"
        | "magnet" | "mandel" | "marble" | "onion" | "pavement" | "planar" | "quilted"
        | "radial" | "spherical" | "spiral1" | "spiral2" | "spotted" | "square" | "tiling"
        | "triangular" | "wood" | "object_pattern" | "slope" | "aoi" | "turbulence" | "warp"
        | "frequency" | "phase" | "ramp_wave" | "sine_wave" | "noise_generator" | "octaves"
        | "omega" | "lambda" | "uv_mapping" | "quick_color" | "quick_colour" | "material_map" => {
            "this pattern or pattern modifier is outside trace's subset"
        }
        "no_image" | "no_reflection" | "double_illuminate" | "clipped_by" | "bounded_by"
        | "sturm" | "split_union" | "cutaway_textures" | "uv_vectors" => LATER,
        "fisheye" | "ultra_wide_angle" | "omnimax" | "panoramic" | "spherical_camera"
        | "cylinder_camera" | "focal_point" | "aperture" | "blur_samples" | "confidence"
        | "variance" | "mesh_camera" => "this camera type or item is outside trace's subset",
        "include" | "if" | "ifdef" | "ifndef" | "else" | "elseif" | "end" | "while" | "for"
        | "switch" | "case" | "range" | "break" | "macro" | "undef" | "debug" | "warning"
        | "error" | "fopen" | "fclose" | "read" | "write" | "render" | "statistics" | "array"
        | "string" | "str" | "concat" | "chr" | "substr" | "strupr" | "strlwr" | "vstr" => LATER,
        "charset" | "hf_gray_16" | "irid_wavelength" | "max_intersections"
        | "noise_generator_gs" | "number_of_waves" | "subsurface_gs" => {
            "this global setting is outside trace's subset"
        }
        _ => return None,
    })
}
