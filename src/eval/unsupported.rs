//! Words POV-Ray knows that trace does not support, with the reason given in the error.
//!
//! Anything POV-Ray would accept but trace cannot render faithfully must be an error that
//! names the construct, never a silent skip.

/// Why trace rejects a POV-Ray keyword, or `None` if the word is not one POV-Ray knows.
pub fn reason(word: &str) -> Option<&'static str> {
    const LATER: &str = "not supported by trace yet";
    Some(match word {
        "union" | "difference" | "intersection" | "merge" => "CSG is outside trace's subset",
        "blob" | "height_field" | "isosurface" | "julia_fractal" | "lathe" | "prism" | "sor"
        | "superellipsoid" | "text" | "polygon" | "bicubic_patch" | "quadric" | "cubic"
        | "quartic" | "poly" | "polynomial" | "sphere_sweep" | "ovus" | "parametric"
        | "light_group" | "lemon" => "this shape is outside trace's subset",
        "media" | "fog" | "rainbow" | "photons" | "radiosity" | "subsurface" | "scattering"
        | "absorption" | "density" | "emission_media" | "mm_per_unit" => "outside trace's subset",
        "dispersion" | "caustics" => "this interior item is outside trace's subset",
        "normal" | "bump_map" | "bumps" | "dents" | "wrinkles" | "ripples" | "waves" => {
            "surface normal perturbation is outside trace's subset"
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
            "this pattern or pattern modifier is outside trace's subset"
        }
        "no_image" | "no_reflection" | "double_illuminate" | "clipped_by" | "bounded_by"
        | "split_union" | "cutaway_textures" | "uv_vectors" => LATER,
        "fisheye" | "ultra_wide_angle" | "omnimax" | "panoramic" | "spherical_camera"
        | "cylinder_camera" | "focal_point" | "aperture" | "blur_samples" | "confidence"
        | "variance" | "mesh_camera" => "this camera type or item is outside trace's subset",
        "fopen" | "fclose" | "read" | "write" | "render" | "statistics" => {
            "file input/output is not supported by trace yet"
        }
        "min_extent" | "max_extent" | "trace" | "inside" | "eval_pigment" | "spline" => LATER,
        "charset" | "hf_gray_16" | "irid_wavelength" | "max_intersections"
        | "noise_generator_gs" | "number_of_waves" | "subsurface_gs" => {
            "this global setting is outside trace's subset"
        }
        _ => return None,
    })
}
