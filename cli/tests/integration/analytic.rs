//! Closed-form scenes: each checks one rule of POV-Ray's model against a value computed by hand.

use crate::render_text;
use trace::Antialias;

/// The single centre pixel of a 1×1 render.
fn centre_pixel(scene: &str) -> [f32; 3] {
    render_text(scene, 1, 1, Antialias::Off).get(0, 0)
}

/// Compares a film pixel (f32, so about 1e-7 relative precision) with a value computed by hand.
fn assert_close(actual: [f32; 3], expected: [f64; 3], tolerance: f64) {
    crate::assert_near(actual, expected, tolerance, "pixel");
}

const HEADER: &str = "#version 3.7; global_settings { assumed_gamma 1.0 }\n";

#[test]
fn lambert_plane_facing_light_is_ambient_plus_diffuse() {
    // 0.5·0.1 (ambient) + 0.5·1·0.6·cos 0 (diffuse) = 0.35.
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }}
         light_source {{ <0,0,-5>, rgb 1 }}
         plane {{ -z, 0 pigment {{ rgb 0.5 }} }}"
    );
    assert_close(centre_pixel(&scene), [0.35; 3], 1e-6);
}

#[test]
fn brilliance_raises_the_diffuse_cosine() {
    // Light at 45°: cos = √½, brilliance 2 → ½. 0.05 + 0.5·0.6·0.5 = 0.2.
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }}
         light_source {{ <0,5,-5>, rgb 1 }}
         plane {{ -z, 0 pigment {{ rgb 0.5 }} finish {{ brilliance 2 }} }}"
    );
    assert_close(centre_pixel(&scene), [0.2; 3], 1e-6);
}

#[test]
fn phong_peak_with_light_at_camera_adds_exactly_one() {
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }}
         light_source {{ <0,0,-5>, rgb 1 }}
         plane {{ -z, 0 pigment {{ rgb 0.5 }} finish {{ ambient 0 diffuse 0 phong 1 }} }}"
    );
    assert_close(centre_pixel(&scene), [1.0; 3], 1e-6);
}

#[test]
fn shadowed_point_gets_ambient_only() {
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }}
         light_source {{ <0,0,-10>, rgb 1 }}
         sphere {{ <0,0,-7>, 0.5 pigment {{ rgb 1 }} }}
         plane {{ -z, 0 pigment {{ rgb 0.5 }} }}"
    );
    // The camera ray passes beside the sphere? No: the sphere is behind the camera (z = -7).
    assert_close(centre_pixel(&scene), [0.05; 3], 1e-6);
}

#[test]
fn shadow_through_filter_and_transmit_is_tinted_at_each_crossing() {
    // A transparent slab (box) between light and plane is crossed twice:
    // light × (rgb·f + t)² = (<1,.5,0>·.5 + .25)² = <.75,.5,.25>² per channel.
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }}
         light_source {{ <0,0,-10>, rgb 1 }}
         box {{ <-1,-1,-8>, <1,1,-7.5> pigment {{ rgbft <1,0.5,0,0.5,0.25> }} }}
         plane {{ -z, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}"
    );
    assert_close(centre_pixel(&scene), [0.5625, 0.25, 0.0625], 1e-6);
}

#[test]
fn facing_mirrors_give_one_minus_point_nine_to_the_trace_level() {
    for level in [1, 3, 5, 10] {
        let scene = format!(
            "#version 3.7; global_settings {{ assumed_gamma 1.0 max_trace_level {level} }}
             camera {{ location 0 look_at z }}
             #declare M = finish {{ ambient 0.1 diffuse 0 reflection 0.9 }}
             plane {{ z, 1 pigment {{ rgb 1 }} finish {{ M }} }}
             plane {{ -z, 1 pigment {{ rgb 1 }} finish {{ M }} }}"
        );
        let expected = 1.0 - 0.9f64.powi(level);
        assert_close(centre_pixel(&scene), [expected; 3], 1e-6);
    }
}

#[test]
fn transparent_surface_at_max_trace_level_one_shows_black() {
    let scene = |level: u32| {
        format!(
            "#version 3.7; global_settings {{ assumed_gamma 1.0 max_trace_level {level} }}
             background {{ rgb 1 }}
             camera {{ location <0,0,-5> look_at 0 }}
             sphere {{ 0, 1 pigment {{ rgbt <1,1,1,1> }} finish {{ ambient 0 diffuse 0 }} }}"
        )
    };
    assert_close(centre_pixel(&scene(1)), [0.0; 3], 1e-9);
    // Crossing ior-1 surfaces costs no trace level: level 2 already sees the background.
    assert_close(centre_pixel(&scene(2)), [1.0; 3], 1e-9);
}

#[test]
fn object_without_texture_is_black_except_highlights() {
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }}
         light_source {{ <0,0,-5>, rgb 1 }}
         plane {{ -z, 0 }}"
    );
    assert_close(centre_pixel(&scene), [0.0; 3], 1e-9);
}

#[test]
fn gamma_modes_match_povray_table() {
    let body = "camera { location <0,0,-5> look_at 0 }
                plane { -z, 0 pigment { rgb <0.5, 0.2, 0.8> } finish { ambient 1 diffuse 0 } }";
    let linear = centre_pixel(&format!(
        "#version 3.7; global_settings {{ assumed_gamma 1.0 }} {body}"
    ));
    assert_close(linear, [0.5, 0.2, 0.8], 1e-6);
    let implied = centre_pixel(&format!("#version 3.7; {body}"));
    assert_close(implied, [0.5, 0.2, 0.8], 1e-6);
    let gamma22 = centre_pixel(&format!(
        "#version 3.7; global_settings {{ assumed_gamma 2.2 }} {body}"
    ));
    assert_close(gamma22, [0.218, 0.029, 0.612], 1e-3);
    // No #version: "gamma off", the values are display values (sRGB-decoded for EXR).
    let off = centre_pixel(body);
    assert_close(off, [0.214, 0.033, 0.604], 1e-3);
}

#[test]
fn output_is_identical_for_one_and_two_threads() {
    let text = std::fs::read_to_string(crate::root().join("examples/mirrors.rt")).expect("example");
    let scene = crate::load_text(&text, 96, 72);
    let film = |threads, antialias| {
        let options = trace::RenderOptions {
            width: 96,
            height: 72,
            antialias,
            threads: Some(threads),
            ..Default::default()
        };
        trace::render(&scene, &options).expect("renders").film
    };
    for aa in [
        Antialias::Adaptive {
            threshold: 0.3,
            depth: 3,
        },
        // (Method 2's blocks trace the corners on their borders again: same rays, same colours.)
        Antialias::Recursive {
            threshold: 0.1,
            depth: 3,
        },
    ] {
        assert_eq!(film(1, aa), film(2, aa), "{aa:?}");
    }
}

#[test]
fn adaptive_antialiasing_supersamples_only_where_colours_differ() {
    // A flat background has no differing neighbours: one sample per pixel.
    let flat = "#version 3.7; global_settings { assumed_gamma 1.0 } background { rgb 0.5 }";
    let scene = crate::load_text(flat, 40, 40);
    let aa = Antialias::Adaptive {
        threshold: 0.3,
        depth: 3,
    };
    let options = trace::RenderOptions {
        width: 40,
        height: 40,
        antialias: aa,
        threads: Some(1),
        ..Default::default()
    };
    let rendered = trace::render(&scene, &options).expect("renders");
    assert_eq!(rendered.stats.samples, 40 * 40);
    // Threshold 0 supersamples every pixel: the centre, then the 3×3 grid, whose middle ray is
    // the centre ray again (its colour is reused, not traced): 1 + 8 rays each.
    let aa = Antialias::Adaptive {
        threshold: 0.0,
        depth: 3,
    };
    let options = trace::RenderOptions {
        antialias: aa,
        ..options
    };
    assert_eq!(
        trace::render(&scene, &options)
            .expect("renders")
            .stats
            .samples,
        40 * 40 * 9
    );
}

// ---- POV-Ray 3.7 behaviours trace reproduces on purpose (docs/povray-behaviours.md) ----

const GLASS_BALL: &str = "sphere { 0, 1 pigment { rgbt <1,1,1,1> } finish { ambient 0 diffuse 0 } ";

#[test]
fn fade_distance_without_fade_power_is_a_constant_half() {
    // The documentation says fade is off; POV-Ray 3.7 applies fade_color + (1 − fade_color)/2
    // whatever the distance.
    for distance in [1.0, 100.0] {
        let scene = format!(
            "{HEADER} background {{ rgb 1 }} camera {{ location <0,0,-5> look_at 0 }}
             {GLASS_BALL} interior {{ fade_distance {distance} }} }}"
        );
        assert_close(centre_pixel(&scene), [0.5; 3], 1e-6);
    }
}

#[test]
fn fade_power_1000_or_more_is_exponential() {
    // Through the centre the ray runs 2 units inside: exp(−2).
    let scene = format!(
        "{HEADER} background {{ rgb 1 }} camera {{ location <0,0,-5> look_at 0 }}
         {GLASS_BALL} interior {{ fade_distance 1 fade_power 1001 }} }}"
    );
    assert_close(centre_pixel(&scene), [(-2.0f64).exp(); 3], 1e-6);
}

#[test]
fn fresnel_inside_two_interiors_loses_the_exit_reflection() {
    // A glass ball before an emitting plane. When the plane's inside holds the camera, the ray
    // is inside two interiors at the exit and POV-Ray computes no Fresnel loss there: 0.96.
    // The same surface written the other way round gives both losses: 0.96².
    let ball = "sphere { 0, 1 pigment { rgbt <1,1,1,1> }
                 finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } conserve_energy }
                 interior { ior 1.5 } }";
    let wall = |plane: &str| {
        format!(
            "#version 3.7; global_settings {{ assumed_gamma 1.0 max_trace_level 10 }}
             camera {{ location <0,0,-5> look_at 0 }} {ball}
             plane {{ {plane} pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 0 emission 1 }} }}"
        )
    };
    assert_close(centre_pixel(&wall("z, 3")), [0.96; 3], 1e-6);
    assert_close(centre_pixel(&wall("-z, -3")), [0.9216; 3], 1e-6);
}

#[test]
fn highlights_ignore_transparency() {
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }} light_source {{ <0,0,-5>, rgb 1 }}
         plane {{ -z, 0 pigment {{ rgbt <1,1,1,0.9> }} finish {{ ambient 0 diffuse 0 phong 1 }} }}"
    );
    assert_close(centre_pixel(&scene), [1.0; 3], 1e-6);
}

#[test]
fn shadowless_lights_make_no_highlights() {
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }} light_source {{ <0,0,-5>, rgb 1 shadowless }}
         plane {{ -z, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 0 phong 1 }} }}"
    );
    assert_close(centre_pixel(&scene), [0.0; 3], 1e-6);
}

#[test]
fn spotlight_edge_follows_povray_smooth_step() {
    // Light at the camera pointing at the plane; the centre ray sees the axis (full light),
    // so the centre pixel is the plain diffuse value; a light aimed 15° away falls in the
    // smooth edge between radius 10° and falloff 20°.
    let at = |target: &str| {
        format!(
            "{HEADER} camera {{ location <0,0,-5> look_at 0 }}
             light_source {{ <0,0,-5>, rgb 1 spotlight point_at {target} radius 10 falloff 20 }}
             plane {{ -z, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}"
        )
    };
    assert_close(centre_pixel(&at("0")), [1.0; 3], 1e-6);
    let off = 5.0 * 15f64.to_radians().tan();
    let (lo, hi, p) = (
        20f64.to_radians().cos(),
        10f64.to_radians().cos(),
        15f64.to_radians().cos(),
    );
    let s = (p - lo) / (hi - lo);
    assert_close(
        centre_pixel(&at(&format!("<{off}, 0, 0>"))),
        [s * s * (3.0 - 2.0 * s); 3],
        1e-6,
    );
}

#[test]
fn light_fade_needs_both_distance_and_power() {
    // 2 / (1 + (d / fade_distance)^fade_power) at d = 5, fade_distance 5: exactly 1; at
    // fade_distance 2.5 with power 2: 2/5.
    let scene = |fade: &str| {
        format!(
            "{HEADER} camera {{ location <0,0,-5> look_at 0 }} light_source {{ <0,0,-5>, rgb 1 {fade} }}
             plane {{ -z, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}"
        )
    };
    assert_close(
        centre_pixel(&scene("fade_distance 5 fade_power 2")),
        [1.0; 3],
        1e-6,
    );
    assert_close(
        centre_pixel(&scene("fade_distance 2.5 fade_power 2")),
        [0.4; 3],
        1e-6,
    );
    assert_close(centre_pixel(&scene("fade_distance 2.5")), [1.0; 3], 1e-6);
}

#[test]
fn back_side_diffuse_lights_a_surface_from_behind() {
    // Light behind a disc at |N·L| = 1: the back-side value 0.3, no highlight.
    let scene = format!(
        "{HEADER} camera {{ location <0,0,-5> look_at 0 }} light_source {{ <0,0,5>, rgb 1 }}
         disc {{ 0, z, 2 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 0.6, 0.3 phong 1 }} }}"
    );
    assert_close(centre_pixel(&scene), [0.3; 3], 1e-6);
}

#[test]
fn lights_in_a_union_move_with_it() {
    // A spotlight in a rotated, translated union, against the same light placed by hand.
    let grouped = "union { light_source { <1, 2, 3> rgb 1 spotlight point_at <1, 0, 3> \
                   area_light x, z, 2, 2 } sphere { 0, 1 } rotate 90*y translate <0, 5, 0> }";
    let placed = "light_source { <3, 7, -1> rgb 1 spotlight point_at <3, 5, -1> \
                  area_light -z, x, 2, 2 } sphere { 0, 1 translate <0, 5, 0> }";
    let a = crate::load_text(grouped, 8, 8);
    let b = crate::load_text(placed, 8, 8);
    assert_eq!(a.lights.len(), 1);
    let close = |u: glam::DVec3, v: glam::DVec3| (u - v).length() < 1e-12;
    assert!(
        close(a.lights[0].position, b.lights[0].position),
        "{:?}",
        a.lights[0]
    );
    let (
        trace::ir::LightKind::Spot { point_at: pa, .. },
        trace::ir::LightKind::Spot { point_at: pb, .. },
    ) = (&a.lights[0].kind, &b.lights[0].kind)
    else {
        panic!("spotlights expected")
    };
    assert!(close(*pa, *pb));
    let (aa, ab) = (
        a.lights[0].area.as_ref().unwrap(),
        b.lights[0].area.as_ref().unwrap(),
    );
    assert!(close(aa.axis1, ab.axis1) && close(aa.axis2, ab.axis2));
    // The union's sphere is placed too; a light alone in `object {}` moves as well.
    assert_eq!(a.objects.len(), 1);
    let lone = crate::load_text(
        "object { light_source { 0, rgb 1 } translate <1, 2, 3> }",
        8,
        8,
    );
    assert!(close(
        lone.lights[0].position,
        glam::DVec3::new(1.0, 2.0, 3.0)
    ));
}

#[test]
fn old_colour_map_ranges_are_two_entries_each() {
    let old = "plane { z, 0 pigment { gradient x color_map { [0.2, 0.6 color rgb x color rgb z] \
               [0.6, 1 color rgb y color rgb 1] } } }";
    let new = "plane { z, 0 pigment { gradient x color_map { [0.2 color rgb x] [0.6 color rgb z] \
               [0.6 color rgb y] [1 color rgb 1] } } }";
    let (a, b) = (crate::load_text(old, 8, 8), crate::load_text(new, 8, 8));
    assert_eq!(a.objects[0].texture, b.objects[0].texture);
}

#[test]
fn fog_fills_hollow_space_only() {
    // Centre ray: 4 units of fog to a clear sphere (transmit 1, ior 1), 2 inside it, 4 more to
    // a black wall. White fog of distance 10 leaves 1 − e^(−L/10) of white over L units of fog.
    let scene = |hollow: &str| {
        format!(
            "{HEADER} camera {{ location 0 look_at z }} fog {{ colour rgb 1 distance 10 }} \
             sphere {{ 5*z, 1 pigment {{ rgbt 1 }} finish {{ ambient 0 diffuse 0 }} {hollow} }} \
             plane {{ -z, -10 pigment {{ rgb 0 }} finish {{ ambient 0 diffuse 0 }} }}"
        )
    };
    let solid = 1.0 - (-0.8f64).exp(); // the 2 units inside a solid object have no fog
    assert_close(centre_pixel(&scene("")), [solid; 3], 1e-6);
    let hollow = 1.0 - (-1.0f64).exp();
    assert_close(centre_pixel(&scene("hollow")), [hollow; 3], 1e-6);
    // A ray that hits nothing is entirely fog; fog's transmit lets the background through.
    let sky = format!(
        "{HEADER} background {{ rgb <0, 0, 1> }} fog {{ rgbt <1, 0, 0, 0.25> distance 1 }}"
    );
    assert_close(centre_pixel(&sky), [0.75, 0.0, 0.25], 1e-6);
}

#[test]
fn a_glass_box_standing_on_the_floor_shows_the_floor_through_its_bottom() {
    // Rays leave the box's bottom face exactly where they meet the floor plane: the two hits
    // are one point, and POV-Ray hits the object first in its test order, here the plane (with
    // three or more objects and lights, unbounded objects come first). Rounding used to pick
    // the box at random, and those rays left the glass below the floor: red background dots.
    // POV-Ray renders this view all green, alone or with the box in a union.
    for glass in [
        "box { -1, 1 material { Clear } rotate 45*y }",
        "union { box { -1, 1 rotate 45*y } sphere { 4*y, 1 } material { Clear } }",
    ] {
        let scene = format!(
            "{HEADER} #declare Clear = material {{ texture {{ pigment {{ rgbf 1 }} \
             finish {{ ambient 0 diffuse 0 }} }} interior {{ ior 1.5 }} }} \
             camera {{ location <0.3, 5, 0.2> look_at <0.3, 0, 0.21> angle 20 }} \
             background {{ rgb x }} light_source {{ <-10, 20, -10>, rgb 1 }} \
             plane {{ y, -1 pigment {{ rgb y }} finish {{ ambient 1 diffuse 0 }} }} {glass}"
        );
        let film = crate::render_text(&scene, 24, 24, Antialias::Off);
        for y in 0..24 {
            for x in 0..24 {
                let [r, g, _] = film.get(x, y);
                assert!(
                    g > 0.5 && r < 0.1,
                    "{glass}: pixel ({x}, {y}) is {:?}",
                    film.get(x, y)
                );
            }
        }
    }
}

#[test]
fn hollow_is_the_last_given_and_a_union_passes_it_to_members_without_their_own() {
    let scene = crate::load_text(
        "#declare S = sphere { 0, 1 hollow }
         object { S hollow off }
         sphere { 0, 1 hollow off hollow }
         union { sphere { 0, 1 hollow off } sphere { x, 1 } hollow }
         sphere { 0, 1 }
         union { sphere { 0, 1 hollow off } hollow }",
        8,
        8,
    );
    let hollow: Vec<bool> = scene.objects.iter().map(|o| o.hollow).collect();
    assert_eq!(hollow, [false, true, false, true, false, false]);
}

/// `checker normal {A}, normal {B}` (POV-Ray's list of normals, commas optional): each
/// square is bumped exactly as by A or B alone; with one normal given, the other squares are
/// flat (the default texture's normal).
#[test]
fn a_discrete_pattern_with_a_list_of_normals_bumps_each_square_by_its_entry() {
    let (a, b) = ("bumps 0.8 scale 0.15", "wrinkles 1 scale 0.3");
    // An orthographic view of the plane z = 0, 4 units on 64 pixels: squares of 16 pixels.
    let scene = |normal: &str| {
        format!(
            "{HEADER} camera {{ orthographic location <0,0,-5> look_at 0 right 4*x up 4*y }}
             light_source {{ <-3,4,-6>, rgb 1 }}
             plane {{ -z, 0 pigment {{ rgb 0.7 }} {normal} }}"
        )
    };
    let render = |normal: &str| crate::render_text(&scene(normal), 64, 64, Antialias::Off);
    let both = render(&format!(
        "normal {{ checker normal {{ {a} }}, normal {{ {b} }} }}"
    ));
    let both_no_comma = render(&format!(
        "normal {{ checker normal {{ {a} }} normal {{ {b} }} }}"
    ));
    let first_only = render(&format!("normal {{ checker normal {{ {a} }} }}"));
    let (only_a, only_b, flat) = (
        render(&format!("normal {{ {a} }}")),
        render(&format!("normal {{ {b} }}")),
        render(""),
    );
    let mut seen = [0; 2];
    for y in 0..64u32 {
        for x in 0..64u32 {
            // Away from the squares' borders (pixel centres 1.5 pixels or more inside).
            let (px, py) = (x % 16, y % 16);
            if !(2..14).contains(&px) || !(2..14).contains(&py) {
                continue;
            }
            // World x = −2 + (x + ½)/16, y = 2 − (y + ½)/16: squares of checker are the
            // integer cells; the entry is the parity of their sum.
            let (cx, cy) = ((x / 16) as i32 - 2, 1 - (y / 16) as i32);
            let entry = (cx + cy).rem_euclid(2) as usize;
            seen[entry] += 1;
            let (want, want_first) = if entry == 0 {
                (only_a.get(x, y), only_a.get(x, y))
            } else {
                (only_b.get(x, y), flat.get(x, y))
            };
            assert_eq!(both.get(x, y), want, "pixel ({x}, {y}), entry {entry}");
            assert_eq!(
                both_no_comma.get(x, y),
                want,
                "pixel ({x}, {y}) without the comma"
            );
            assert_eq!(
                first_only.get(x, y),
                want_first,
                "pixel ({x}, {y}) with one normal"
            );
        }
    }
    assert!(seen[0] > 1000 && seen[1] > 1000, "{seen:?}");
    // The bumps do show: the two normals differ from each other and from flat.
    assert_ne!(only_a.get(24, 24), flat.get(24, 24));
}

/// Commas may separate a list pattern's pigments and textures, as POV-Ray reads them.
#[test]
fn lists_of_pigments_and_textures_take_commas() {
    let scene = |body: &str| {
        format!(
            "{HEADER} camera {{ orthographic location <0,0,-5> look_at 0 right 4*x up 4*y }}
             light_source {{ <-3,4,-6>, rgb 1 }}
             plane {{ -z, 0 {body} }}"
        )
    };
    let render = |body: &str| crate::render_text(&scene(body), 16, 16, Antialias::Off);
    let colours = render("pigment { checker rgb <1,0,0>, rgb <0,0,1> }");
    let pigments = render("pigment { checker pigment { rgb <1,0,0> }, pigment { rgb <0,0,1> } }");
    let textures = render(
        "texture { checker texture { pigment { rgb <1,0,0> } }, texture { pigment { rgb <0,0,1> } } }",
    );
    for y in 0..16 {
        for x in 0..16 {
            assert_eq!(pigments.get(x, y), colours.get(x, y));
            assert_eq!(textures.get(x, y), colours.get(x, y));
        }
    }
    assert_ne!(colours.get(2, 2), colours.get(6, 2), "two colours");
}

/// A `cylinder` light (POV-Ray's cylindrical spot): parallel rays down its axis, full within
/// `radius` of it, a smooth step (POV-Ray's cubic) to zero at `falloff`, nothing beyond.
/// Checked against POV-Ray's render of a similar scene (mean FLIP 0).
#[test]
fn a_cylinder_light_lights_a_disc_with_a_soft_edge() {
    // Orthographic view straight down on the plane y = 0: 8 units on 64 pixels.
    let scene = format!(
        "{HEADER} camera {{ orthographic location <0,10,0> look_at 0 right 8*x up 8*z }}
         light_source {{ <0,5,0>, rgb 1 cylinder point_at <0,0,0> radius 1.5 falloff 2.5 }}
         plane {{ y, 0 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}"
    );
    let film = crate::render_text(&scene, 64, 64, Antialias::Off);
    // Pixel column x has its centre at world x = −4 + (x + ½)/8 (row 32: z = −1/16).
    let at = |x: u32| {
        let (wx, wz) = (-4.0 + (f64::from(x) + 0.5) / 8.0, -1.0 / 16.0);
        (wx * wx + wz * wz).sqrt()
    };
    for x in 0..64 {
        let d = at(x);
        let expected = if d < 1.5 {
            1.0
        } else if d >= 2.5 {
            0.0
        } else {
            let inside = 1.0 - d / 2.5;
            let s = inside / (1.0 - 1.5 / 2.5);
            s * s * (3.0 - 2.0 * s)
        };
        assert_close(film.get(x, 32), [expected; 3], 1e-5);
    }
    // Rays are parallel: the plane is lit the same wherever the light sits on its axis, and
    // not at all behind the light's plane.
    let higher = scene.replace("<0,5,0>, rgb 1", "<0,50,0>, rgb 1");
    assert_eq!(
        crate::render_text(&higher, 64, 64, Antialias::Off).get(20, 32),
        film.get(20, 32)
    );
    let below = scene.replace(
        "<0,5,0>, rgb 1 cylinder point_at <0,0,0>",
        "<0,-1,0>, rgb 1 cylinder point_at <0,-2,0>",
    );
    assert_eq!(
        crate::render_text(&below, 64, 64, Antialias::Off).get(32, 32),
        [0.0; 3]
    );
}

/// Two boxes with coplanar faces, each alone in the scene: POV-Ray tests objects as the ray
/// enters their bounding boxes, so at the shared face the box whose box the ray enters first
/// is seen, whichever comes first in the file (both orders checked against POV-Ray's renders:
/// the green box at every pixel of the shared face).
#[test]
fn at_coplanar_faces_the_box_entered_first_is_seen_as_in_povray() {
    let red = "box { <-2,-0.5,-0.5>, <2,0.5,0.5> pigment { rgb <1,0,0> } finish { ambient 1 diffuse 0 } rotate 45*x }";
    let green = "box { <-0.5,-0.5,-2>, <0.5,0.5,2> pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } rotate 45*x }";
    let render = |objects: &str| {
        let scene = format!(
            "{HEADER} camera {{ location <0,2,-10> look_at <0,0.3,0> angle 20 }}
             light_source {{ <0,10,-10>, rgb 1 }}
             {objects}"
        );
        crate::render_text(&scene, 32, 32, Antialias::Off)
    };
    let (only_red, only_green) = (render(red), render(green));
    let (red_first, green_first) = (
        render(&format!("{red}\n{green}")),
        render(&format!("{green}\n{red}")),
    );
    let mut shared = 0;
    for y in 0..32 {
        for x in 0..32 {
            // Pixels where each box alone shows its face: the shared face.
            if only_red.get(x, y) == [1.0, 0.0, 0.0] && only_green.get(x, y) == [0.0, 1.0, 0.0] {
                shared += 1;
                assert_eq!(red_first.get(x, y), [0.0, 1.0, 0.0], "pixel ({x}, {y})");
                assert_eq!(green_first.get(x, y), [0.0, 1.0, 0.0], "pixel ({x}, {y})");
            }
        }
    }
    assert!(shared > 20, "{shared} pixels of the shared face");
}

/// A mesh's triangles with textures of their own (`texture { T }` in a mesh, a mesh2's
/// `texture_list` with one index per face or one per corner): each triangle shows its own,
/// moved with the object; three per corner blend across it; a triangle without one takes
/// the object's (checked against POV-Ray's renders of the same scenes: mean FLIP 0 and
/// 0.00003).
#[test]
fn mesh_triangles_take_their_own_textures() {
    let view = "camera { orthographic location <1,0.5,-3> look_at <1,0.5,0> right 2.4*x up 1.2*y }
                light_source { <0,0,-10>, rgb 1 }";
    let flat = "finish { ambient 1 diffuse 0 }";
    let render =
        |body: &str| crate::render_text(&format!("{HEADER} {view} {body}"), 48, 24, Antialias::Off);
    let mesh = render(&format!(
        "mesh {{ triangle {{ <0,0,0>, <1,0,0>, <0,1,0> texture {{ pigment {{ rgb <1,0,0> }} {flat} }} }}
                 triangle {{ <1,0,0>, <2,0,0>, <1,1,0> }}
                 pigment {{ rgb <0,0,1> }} finish {{ ambient 1 diffuse 0 }} translate 0.1*x }}"
    ));
    // Centres of the two triangles (world x = 0.4 and 1.4 after the move, y = 0.3).
    let pixel = |x: f64, y: f64| {
        (
            ((x + 0.2) / 2.4 * 48.0) as u32,
            ((1.1 - y) / 1.2 * 24.0) as u32,
        )
    };
    let (a, b) = (pixel(0.4, 0.3), pixel(1.4, 0.3));
    assert_eq!(mesh.get(a.0, a.1), [1.0, 0.0, 0.0]);
    assert_eq!(mesh.get(b.0, b.1), [0.0, 0.0, 1.0]);
    let mesh2 = render(&format!(
        "mesh2 {{ vertex_vectors {{ 4, <0,0,0>, <1,0,0>, <0,1,0>, <2,0,0> }}
                  texture_list {{ 3, texture {{ pigment {{ rgb <1,0,0> }} {flat} }}
                                     texture {{ pigment {{ rgb <0,1,0> }} {flat} }}
                                     texture {{ pigment {{ rgb <0,0,1> }} {flat} }} }}
                  face_indices {{ 2, <0,1,2>, 1, <1,3,2>, 0, 1, 2 }} }}"
    ));
    assert_eq!(
        mesh2.get(pixel(0.3, 0.3).0, pixel(0.3, 0.3).1),
        [0.0, 1.0, 0.0]
    );
    // Blended: at each corner its own colour, between them a mix summing to 1.
    let [r, g, bl] = mesh2.get(pixel(1.2, 0.2).0, pixel(1.2, 0.2).1);
    assert!(r > 0.1 && g > 0.1 && bl > 0.1, "{r} {g} {bl}");
    assert!((r + g + bl - 1.0).abs() < 1e-3, "{r} {g} {bl}");
}

#[test]
fn a_light_on_a_surface_shines_out_of_it() {
    // POV-Ray's SHADOW_TOLERANCE: a surface within 0.001 of the light casts no shadow. The light
    // sits on the near face of a box (z = -1) and lights a plane at z = -3 through that face:
    // 0.05 + 0.5·0.6 = 0.35, as in POV-Ray (values read from its 16-bit render); from 0.002
    // inside the box it does not.
    let scene = |z: f64| {
        format!(
            "{HEADER} camera {{ location <0,0,-2> look_at <0,0,-3> }}
             light_source {{ <0,0,{z}>, rgb 1 }}
             box {{ <-1,-1,-1>, <1,1,1> pigment {{ rgb 1 }} }}
             plane {{ z, -3 pigment {{ rgb 0.5 }} }}"
        )
    };
    assert_close(centre_pixel(&scene(-1.0)), [0.35; 3], 1e-6);
    // (0.0005 inside the box is still within the tolerance: lit, in POV-Ray too.)
    assert_close(centre_pixel(&scene(-0.9995)), [0.35; 3], 1e-6);
    assert_close(centre_pixel(&scene(-0.998)), [0.05; 3], 1e-6);
}
