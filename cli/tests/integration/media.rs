//! Participating media against values measured on POV-Ray 3.7.0.10's renders of the same
//! scenes (docs/media.md): each scene renders at 160×120 with an orthographic camera that
//! maps pixel (px, py) to x = −8 + (px + ½)/10, y = 6 − (py + ½)/10, and each check reads the
//! pixel 0.05 off an object's centre. The expected values are POV-Ray's, to the five
//! digits it was read to (its output is 16-bit), where its quirks (method 3's step of
//! 1/(S+1), the left Riemann attenuation) move them off the exact integral.

use crate::render_text;
use trace::Antialias;

const CAMERA: &str = "#version 3.7; global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-10> direction z right 16*x up 12*y }\n";

/// The pixel whose centre is at (x, y) + (0.05, 0.05).
fn pixel(film: &trace::Film, x: f64, y: f64) -> [f32; 3] {
    let px = ((x + 8.05) * 10.0 - 0.5).round() as u32;
    let py = ((6.0 - y - 0.05) * 10.0 - 0.5).round() as u32;
    film.get(px, py)
}

fn render(body: &str) -> trace::Film {
    render_text(&format!("{CAMERA}{body}"), 160, 120, Antialias::Off)
}

/// Each channel within 1e-4 of POV-Ray's (its values were read from 16-bit PNGs).
fn assert_povray(actual: [f32; 3], povray: [f64; 3], what: &str) {
    crate::assert_near(actual, povray, 1.2e-4, what);
}

#[test]
fn an_absorbing_slab_lets_through_e_to_the_minus_optical_depth() {
    let film = render(
        "background { rgb 1 }
         #macro Slab(X, T) box { <X-1.5,-4,0>, <X+1.5,4,T> pigment { rgbt 1 } hollow
           interior { media { absorption <0.5,1,2> } } } #end
         Slab(-6,0.5) Slab(-2,1) Slab(2,2) Slab(6,4)",
    );
    let povray = [
        (-6.0, [0.77881, 0.60653, 0.36788]),
        (-2.0, [0.60653, 0.36788, 0.13533]),
        (2.0, [0.36788, 0.13533, 0.01831]),
        (6.0, [0.13533, 0.01831, 0.00034]),
    ];
    for (x, v) in povray {
        assert_povray(pixel(&film, x, 0.0), v, &format!("slab at x = {x}"));
    }
}

#[test]
fn method_3_emission_follows_povray_370s_sampling() {
    let film = render(
        "background { rgb 0 }
         #macro Ball(X, Y, Hollow, I) sphere { <X,Y,0>, 1 pigment { rgbt 1 }
           #if (Hollow) hollow #end interior { I } } #end
         Ball(-6, 3, 1, interior { media { emission 0.25 } })
         Ball(-2, 3, 0, interior { media { emission 0.25 } })
         Ball(2, 3, 1, interior { media { emission 0.5 absorption 1 } })
         Ball(6, 3, 1, interior { media { emission 0.5 absorption 1 samples 1 } })
         Ball(-6, -3, 1, interior { media { emission 0.5 absorption 1 samples 4 } })
         Ball(-2, -3, 1, interior { media { emission 0.5 absorption 1 samples 30 } })
         Ball(2, -3, 1, interior { media { emission 0.5 absorption 1 intervals 2 } })
         Ball(6, -3, 1, interior { media { emission 0.25 }
           media { emission <0.25,0,0> absorption <0,1,0> } })",
    );
    let cases = [
        (
            -6.0,
            3.0,
            [0.49874; 3],
            "emission alone: 0.25 times the chord",
        ),
        (
            -2.0,
            3.0,
            [0.0; 3],
            "a solid (not hollow) object shows no media",
        ),
        (
            2.0,
            3.0,
            [0.50779; 3],
            "S = 6, left Riemann (exact: 0.43199)",
        ),
        (6.0, 3.0, [0.68269; 3], "samples 1: S = 2"),
        (-6.0, -3.0, [0.59144; 3], "samples 4: S = 3"),
        (-2.0, -3.0, [0.45948; 3], "samples 30: S = 16"),
        (
            2.0,
            -3.0,
            [0.50779; 3],
            "intervals 2 without light: one interval",
        ),
        (6.0, -3.0, [0.99750, 0.25389, 0.49874], "two media add up"),
    ];
    for (x, y, v, what) in cases {
        assert_povray(pixel(&film, x, y), v, what);
    }
}

#[test]
fn a_light_brings_intervals_into_play_and_method_2_takes_midpoints() {
    let film = render(
        "background { rgb 0 }
         light_source { <0,100,0> color rgb 1 }
         sphere { <-3,0,0>, 1 pigment { rgbt 1 } hollow interior { media { emission 0.5 absorption 1 } } }
         sphere { <3,0,0>, 1 pigment { rgbt 1 } hollow
           interior { media { emission 0.5 absorption 1 intervals 2 } } }
         sphere { <0,4,0>, 1 pigment { rgbt 1 } hollow
           interior { media { emission 0.5 absorption 1 method 2 samples 4, 4 } } }",
    );
    assert_povray(pixel(&film, -3.0, 0.0), [0.50779; 3], "one interval");
    assert_povray(
        pixel(&film, 3.0, 0.0),
        [0.46889; 3],
        "two intervals of S = 6",
    );
    assert_povray(
        pixel(&film, 0.0, 4.0),
        [0.42754; 3],
        "method 2: the midpoint rule",
    );
}

#[test]
fn densities_multiply_and_an_empty_one_is_zero() {
    let film = render(
        "background { rgb 1 }
         #macro Slab(X, Y, I) box { <X-1.5,Y-2,0>, <X+1.5,Y+2,1> pigment { rgbt 1 } hollow
           interior { I } } #end
         Slab(-6, 3, interior { media { absorption 1 density { } } })
         Slab(-2, 3, interior { media { absorption 1 density { rgb 0.5 } } })
         Slab(2, 3, interior { media { absorption 1 density { rgb 0.5 } density { rgb <0.5,1,2> } } })
         Slab(6, 3, interior { media { absorption 1 density { gradient x } } })
         Slab(-6, -3, interior { media { absorption 1
           density { gradient x color_map { [0 rgb 0][1 rgb <1,0,0>] } } } })
         Slab(-2, -3, interior { media { absorption 1
           density { spherical scale 2 translate <-2,-3,0> } } })
         Slab(6, -3, interior { media { absorption 1 } media { absorption <0,1,2> } })",
    );
    let cases = [
        (-6.0, 3.0, [1.0; 3], "density { } is zero"),
        (-2.0, 3.0, [0.60653; 3], "a plain density"),
        (2.0, 3.0, [0.77881, 0.60653, 0.36788], "densities multiply"),
        (4.5, 3.0, [0.57694; 3], "a pattern's grey default map"),
        (-5.5, -3.0, [0.57693, 1.0, 1.0], "a colour map, per channel"),
        (
            -2.0,
            -3.0,
            [0.45847; 3],
            "a varying density: 3.7.0's steps (exact: 0.47464)",
        ),
        (6.0, -3.0, [0.36788, 0.13533, 0.04979], "media add up"),
    ];
    for (x, y, v, what) in cases {
        assert_povray(pixel(&film, x, y), v, what);
    }
}

/// A cylinder light down through scattering boxes: each type's phase at 90°, the light
/// dimmed on its way down by the box's own media (media_attenuation off does not matter for
/// interior media), the beam's lit interval.
#[test]
fn scattering_lights_the_beam_by_each_phase_function() {
    let film = render(
        "background { rgb 0 }
         #macro BeamBox(X, T, E)
           light_source { <X,10,0> color rgb 1 cylinder point_at <X,0,0> radius 0.5 falloff 0.5 tightness 0 }
           box { <X-1,-3,-2>, <X+1,3,2> pigment { rgbt 1 } hollow
             interior { media { scattering { T, 0.2 #if (T=5) eccentricity E #end } } } }
         #end
         BeamBox(-6, 1, 0) BeamBox(-3, 2, 0) BeamBox(0, 3, 0) BeamBox(3, 4, 0) BeamBox(6, 5, 0.5)",
    );
    // POV-Ray's values 0.25 off the beam's axis; the model behind them: the view ray enters
    // at z = −2, the lit part is ±h around z = 0, the light comes down through 3 − y of
    // the medium, and method 3 sums six steps left-Riemann.
    let cases = [
        (-6.0_f64, 0.06407),
        (-3.0, 0.03825),
        (0.0, 0.03177),
        (3.0, 0.05122),
        (6.0, 0.03439),
    ];
    let film_y: f64 = -0.05;
    for (x, povray) in cases {
        let px = ((x + 0.25 + 8.0) * 10.0 - 0.5).round() as u32;
        let py = ((6.0 - film_y) * 10.0 - 0.5).round() as u32;
        let v = film.get(px, py);
        assert!(
            (f64::from(v[0]) - povray).abs() <= 1.2e-4,
            "beam at x = {x}: got {v:?}, POV-Ray gives {povray}"
        );
    }
}

#[test]
fn the_atmosphere_reaches_rays_in_hollow_space_only_and_dims_shadows_on_request() {
    let atmosphere = |body: &str| {
        render_text(
            &format!(
                "#version 3.7; global_settings {{ assumed_gamma 1.0 }}
                 camera {{ orthographic location <0,0,0> direction z right 16*x up 12*y }}
                 {body}"
            ),
            160,
            120,
            Antialias::Off,
        )
    };
    let centre = |f: &trace::Film| f.get(80, 60);
    // A ray that hits nothing runs 2e10 units.
    let f = atmosphere("background { rgb 0 } media { emission 1e-11 }");
    assert_povray(centre(&f), [0.2; 3], "emission over 2e10 units");
    let f = atmosphere("background { rgb 1 } media { absorption 1e-11 }");
    assert_povray(centre(&f), [0.81874; 3], "absorption over 2e10 units");
    // The camera inside a solid object: no atmosphere until its rays leave it.
    let inside = |hollow: &str| {
        atmosphere(&format!(
            "background {{ rgb 0 }} media {{ absorption 0.03 }}
             sphere {{ 0, 100 pigment {{ rgbt 1 }} hollow {hollow} }}
             plane {{ -z, -10 pigment {{ rgb 1 }} finish {{ ambient 1 diffuse 0 }} }}"
        ))
    };
    assert_povray(centre(&inside("off")), [1.0; 3], "inside a solid sphere");
    assert_povray(
        centre(&inside("on")),
        [0.74083; 3],
        "inside a hollow sphere",
    );
    let wall = "background { rgb 0 } media { absorption 0.03 }
        plane { -z, -10 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }";
    let f = atmosphere(&format!("{wall} light_source {{ <0,0,0> color rgb 1 }}"));
    assert_povray(
        centre(&f),
        [0.74079; 3],
        "the light is not dimmed by default",
    );
    assert_povray(f.get(0, 0), [0.52567; 3], "a corner");
    let f = atmosphere(&format!(
        "{wall} light_source {{ <0,0,0> color rgb 1 media_attenuation on }}"
    ));
    assert_povray(centre(&f), [0.54879; 3], "media_attenuation on");
    assert_povray(f.get(0, 0), [0.34443; 3], "a corner, attenuated");
    // Fog dims such a light's shadow rays too, without adding its colour to them:
    // 0.5·(1 − e⁻¹) + e⁻¹·e⁻¹ (POV-Ray: 0.45139; with the colour added it would be 0.568).
    let f = atmosphere(
        "background { rgb 0 } fog { distance 10 color rgb 0.5 }
         light_source { <0,0,0> color rgb 1 media_attenuation on }
         plane { -z, -10 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }",
    );
    assert_povray(centre(&f), [0.45139; 3], "fog on a shadow ray");
}

#[test]
fn media_renders_the_same_at_any_thread_count() {
    let scene = format!(
        "{CAMERA} background {{ rgb 0 }}
         light_source {{ <0,10,0> color rgb 1 spotlight point_at 0 radius 15 falloff 20 }}
         box {{ <-6,-4,-3>, <6,4,3> pigment {{ rgbt 1 }} hollow
           interior {{ media {{ scattering {{ 2, 0.05 }} method 1 samples 2, 5
             density {{ bozo scale 2 }} }} }} }}"
    );
    let scene = crate::load_text(&scene, 160, 120);
    crate::render_at_one_and_two_threads(&scene, 160, 120);
}

#[test]
fn media_items_povray_refuses_are_errors_at_their_place() {
    let cases = [
        ("media { method 4 }", "method must be 1, 2 or 3"),
        ("media { intervals 0 }", "at least one interval"),
        ("media { samples 5, 2 }", "the most is below the least"),
        ("media { confidence 1 }", "confidence"),
        ("media { aa_threshold 0 }", "aa_threshold"),
        (
            "media { scattering { 1, 0.2 eccentricity 0.5 } }",
            "eccentricity",
        ),
        ("media { emission 1, 2 }", "takes one value"),
    ];
    for (media, message) in cases {
        let text = format!("#version 3.7; {media}");
        let options = trace::LoadOptions::default();
        let error = match trace::load_str(std::path::Path::new("m.pov"), text, &options) {
            Ok(_) => panic!("{media}: accepted"),
            Err(e) => e.to_string(),
        };
        assert!(error.contains(message), "{media}: {error}");
        assert!(error.contains("m.pov:1:"), "{media}: no place in {error}");
    }
}

#[test]
fn light_media_flags_read_as_povray_reads_them() {
    let scene = crate::load_text(
        "light_source { 0, 1 media_interaction off media_attenuation }
         light_source { 0, 1 media_interaction 0 media_attenuation on }
         light_source { 0, 1 }",
        8,
        8,
    );
    let flags: Vec<(bool, bool)> = scene
        .lights
        .iter()
        .map(|l| (l.media_interaction, l.media_attenuation))
        .collect();
    assert_eq!(flags, [(false, true), (false, true), (true, false)]);
}

/// A medium lit by an area light sees the light's grid from each sample, as POV-Ray traces it
/// (sampling the light's centre alone differed by mean FLIP 0.026 on this scene).
#[test]
fn an_area_light_scatters_through_its_grid() {
    let film = render_text(
        "#version 3.7; global_settings { assumed_gamma 1.0 }
         camera { location <0, 2, -8> look_at <0, 1.5, 0> angle 50 }
         background { rgb 0 }
         light_source { <0, 6, 0> color rgb 2 area_light 2*x, 2*z, 4, 4 adaptive 1 }
         plane { y, 0 pigment { rgb 0.7 } }
         sphere { <0, 3, 0>, 0.6 pigment { rgb <1, 0.3, 0.2> } }
         box { <-4, 0.01, -4>, <4, 5, 4> pigment { rgbt 1 } hollow
           interior { media { scattering { 1, 0.05 } } } }",
        160,
        120,
        Antialias::Off,
    );
    // POV-Ray's values (its 16-bit linear PNG).
    let povray = [
        ((80, 20), [0.50805, 0.35019, 0.32764]),
        ((80, 40), [0.37755, 0.32004, 0.31183]),
        ((60, 40), [0.56841; 3]),
        ((100, 50), [0.59724; 3]),
        ((80, 70), [0.74392; 3]),
        ((40, 30), [0.6033; 3]),
    ];
    for ((x, y), v) in povray {
        assert_povray(film.get(x, y), v, &format!("pixel ({x}, {y})"));
    }
}
