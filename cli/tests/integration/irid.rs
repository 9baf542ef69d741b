//! Iridescence against POV-Ray 3.7.0.10's render of the same scene (values read from its
//! 16-bit linear PNG).

use crate::render_text;
use trace::Antialias;

/// A glass cube on its edge, lit only through `irid`: its back faces reflect the view totally
/// (glass to air beyond 41.8°), and POV-Ray tints that mirror ray by the film's interference
/// as it tints any reflection (ComputeReflection), so the cube's top and sides turn coloured.
const SCENE: &str = "#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at 0 angle 40 }
light_source { <-20, 30, -30> rgb 1 }
background { rgb <0.3, 0.5, 0.7> }
plane { y, -2 pigment { checker rgb 0.9 rgb 0.2 } }
box { -1, 1 rotate <0, 45, 0> rotate <20, 0, 0>
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 irid { 0.6 thickness 0.5 } }
  interior { ior 1.5 } }";

#[test]
fn irid_tints_totally_reflected_rays_as_povray_does() {
    let film = render_text(SCENE, 80, 60, Antialias::Off);
    // (pixel, POV-Ray's value); without the tint these differ by up to a quarter.
    let povray = [
        ((56, 18), [0.16695, 0.28777, 0.35073]),
        ((29, 11), [0.16147, 0.23098, 0.29519]),
        ((23, 29), [0.24509, 0.71884, 0.98682]),
        ((21, 16), [0.14865, 0.28365, 0.35329]),
        ((22, 44), [0.27536, 0.72068, 0.93791]),
        ((59, 47), [0.28859, 0.71614, 0.90919]),
        // The background and the floor, untouched.
        ((5, 5), [0.3, 0.5, 0.7]),
        ((40, 55), [0.43642, 0.43642, 0.43642]),
    ];
    for ((x, y), v) in povray {
        crate::assert_near(film.get(x, y), v, 1e-3, &format!("pixel ({x}, {y})"));
    }
}
