//! Rainbows against POV-Ray 3.7.0.10's render of the same scene (values read from its 16-bit
//! linear PNG), and what POV-Ray refuses in them.

use crate::render_text;
use trace::Antialias;

/// A ring 15° to 25° round the view direction, its colours filtering and transmitting, fading
/// past 50° from up (half the falloff_angle) towards 100° (half the arc_angle), over the
/// background (above the horizon) and over a checkered wall 30 to 60 units away (below it),
/// which a `distance` of 50 lets partly through.
const SCENE: &str = "#version 3.7; global_settings { assumed_gamma 1.0 }
camera { location 0 direction z right 4/3*x up y }
background { rgb <0.2, 0.4, 0.6> }
box { <-100, -100, 30>, <100, 0, 31>
  pigment { checker rgb <0.9,0.5,0.1> rgb <0.1,0.5,0.9> } finish { ambient 1 diffuse 0 } }
rainbow { angle 20 width 10 distance 50 direction z arc_angle 200 falloff_angle 100
  colour_map { [0 rgbft <1,0,0,0.5,0.2>] [0.5 rgbft <0,1,0,0,0>] [1 rgbft <0,0,1,0.2,0.5>] }
  JITTER }";

#[test]
fn a_rainbow_blends_as_povray_blends_it() {
    let film = render_text(&SCENE.replace("JITTER", ""), 80, 60, Antialias::Off);
    // (pixel, POV-Ray's value)
    let povray = [
        ((40, 6), [0.02652, 0.67588, 0.32049]),
        ((48, 6), [0.04820, 0.45316, 0.53684]),
        ((40, 12), [0.66265, 0.26104, 0.06114]),
        ((48, 12), [0.38828, 0.57488, 0.03970]),
        ((56, 12), [0.03467, 0.58689, 0.40728]),
        ((56, 18), [0.28400, 0.67845, 0.04488]),
        ((64, 18), [0.10141, 0.27022, 0.71160]),
        ((56, 24), [0.48464, 0.28550, 0.23650]),
        ((64, 24), [0.13266, 0.41318, 0.57536]),
        ((56, 30), [0.14876, 0.46290, 0.82325]),
        ((64, 30), [0.09303, 0.50246, 0.86798]),
        // Outside the ring: the background and the wall as they are.
        ((40, 0), [0.2, 0.4, 0.6]),
        ((0, 59), [0.1, 0.5, 0.9]),
    ];
    for ((x, y), v) in povray {
        crate::assert_near(film.get(x, y), v, 1.2e-4, &format!("pixel ({x}, {y})"));
    }
}

#[test]
fn a_jittered_rainbow_renders_the_same_at_any_thread_count() {
    let scene = crate::load_text(&SCENE.replace("JITTER", "jitter 0.2"), 80, 60);
    let jittered = crate::render_at_one_and_two_threads(&scene, 80, 60);
    let plain = render_text(&SCENE.replace("JITTER", ""), 80, 60, Antialias::Off);
    let mut moved = 0;
    for y in 0..60 {
        for x in 0..80 {
            moved += usize::from(jittered.get(x, y) != plain.get(x, y));
        }
    }
    // Jitter moves the ring's colours (and its edges) from pixel to pixel.
    assert!(moved > 100, "jitter changed only {moved} pixels");
}

#[test]
fn a_rainbow_copied_from_a_declared_one_warns_of_povrays_second_conversion() {
    let text = "camera { location 0 direction z }
        #declare R = rainbow { angle 40 width 8 direction z colour_map { [0 rgb 1] [1 rgb 0] } }
        rainbow { R }";
    let options = trace::LoadOptions::default();
    let loaded =
        trace::load_str(std::path::Path::new("r.rt"), text.to_string(), &options).expect("loads");
    assert_eq!(loaded.warnings.len(), 1, "{:?}", loaded.warnings);
    assert!(loaded.warnings[0].contains("radians again"));
    // The copy's angle and width are converted once more, as POV-Ray does: 36° and 8° become
    // radians, then those numbers are read as degrees.
    let r = &loaded.scene.rainbows[0];
    let first = (40.0f64 - 4.0).to_radians();
    let width = 8.0f64.to_radians();
    assert!((r.angle - (first - width / 2.0).to_radians()).abs() < 1e-15);
    assert!((r.width - width.to_radians()).abs() < 1e-15);
}

#[test]
fn rainbow_items_povray_refuses_are_errors_at_their_place() {
    let cases = [
        (
            "rainbow { angle 40 width 5 direction z arc_angle 50 falloff_angle 60 }",
            "arc_angle is smaller than its falloff_angle",
            "rainbow",
        ),
        (
            "rainbow { angle 40 width 5 }",
            "direction vector is zero",
            "rainbow",
        ),
        (
            "rainbow { direction y up <0,2,0> }",
            "up and direction vectors are parallel",
            "rainbow",
        ),
        (
            "rainbow { direction z falloff_angle -1 }",
            "falloff_angle must be from 0 to 360",
            "-1",
        ),
        (
            "rainbow { direction z translate x }",
            "`translate` cannot stand here in rainbow",
            "translate",
        ),
    ];
    for (text, message, culprit) in cases {
        let text = format!("camera {{ location 0 direction z }}\n{text}");
        let e = trace::load_str(
            std::path::Path::new("r.rt"),
            text.clone(),
            &trace::LoadOptions::default(),
        )
        .map(|_| ())
        .expect_err(&text)
        .to_string();
        assert!(e.contains(message), "{text}: {e}");
        let line = text.lines().nth(1).expect("second line");
        let caret = e
            .lines()
            .find(|l| l.trim_start().starts_with('|') && l.contains('^'))
            .expect("a caret line");
        let col = caret.find('^').expect("caret") - caret.find('|').expect("bar") - 2;
        assert!(
            line[col..].starts_with(culprit),
            "{text}: caret at {col} in\n{e}"
        );
    }
}
