//! Dispersion against POV-Ray 3.7.0.10's render of the same scene (values read from its
//! 16-bit linear PNG), and the rules of when POV-Ray disperses.

use crate::render_text;
use trace::Antialias;

/// A ball of dispersing glass filling the view, over white stripes on black: each pixel sees
/// the stripes through seven bands of the spectrum, each bent by its own index.
const SCENE: &str = "#version 3.7; global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0,0,-4> direction z right 4/3*x up y }
background { rgb 0 }
box { <-20,-20,3>, <20,20,3.1>
  pigment { gradient x colour_map { [0 rgb 1] [0.2 rgb 1] [0.2 rgb 0] [1 rgb 0] } scale 0.5 }
  finish { ambient 1 diffuse 0 } }
sphere { 0, 1.5 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } INTERIOR }";

fn render(interior: &str) -> trace::Film {
    render_text(&SCENE.replace("INTERIOR", interior), 80, 60, Antialias::Off)
}

#[test]
fn a_dispersing_ball_splits_the_stripes_as_povray_does() {
    let film = render("interior { ior 1.5 dispersion 1.2 }");
    // (pixel, POV-Ray's value)
    let povray = [
        ((22, 30), [0.00000, 0.10950, 0.32700]),
        ((25, 30), [0.29351, 0.00000, 0.20470]),
        // All seven bands on white: the spectrum's own white, a little off.
        ((40, 30), [0.99380, 1.00000, 0.99620]),
        ((43, 30), [0.04930, 0.47070, 0.99620]),
        ((52, 30), [0.03951, 0.00000, 0.57121]),
        ((58, 30), [0.27080, 0.37870, 0.00000]),
        ((43, 20), [0.32010, 0.84939, 0.99620]),
        ((55, 20), [0.28060, 0.73989, 0.09799]),
        ((58, 20), [0.26000, 0.00000, 0.36651]),
        ((52, 40), [0.00980, 0.47070, 0.42499]),
        ((31, 30), [0.00000, 0.00000, 0.00000]),
    ];
    for ((x, y), v) in povray {
        crate::assert_near(film.get(x, y), v, 1.2e-4, &format!("pixel ({x}, {y})"));
    }
}

#[test]
fn povray_keeps_a_dispersion_only_with_an_ior() {
    let film = |interior: &str| {
        let f = render(interior);
        (0..60)
            .flat_map(|y| (0..80).map(move |x| (x, y)))
            .map(|(x, y)| f.get(x, y))
            .collect::<Vec<_>>()
    };
    // No ior: the air's, and no dispersion (nothing bends).
    assert_eq!(film("interior { dispersion 1.2 }"), film(""));
    // An ior from a declared interior, or added to one without, keeps it.
    let declared = "#declare I = interior { dispersion 1.2 }";
    let with_ior = film("interior { ior 1.5 dispersion 1.2 }");
    let text = SCENE.replace("INTERIOR", "interior { I ior 1.5 }");
    let later = render_text(&format!("{declared}\n{text}"), 80, 60, Antialias::Off);
    assert_eq!(
        (0..60)
            .flat_map(|y| (0..80).map(move |x| (x, y)))
            .map(|(x, y)| later.get(x, y))
            .collect::<Vec<_>>(),
        with_ior
    );
    assert_ne!(with_ior, film("interior { ior 1.5 }"));
    // An ior of exactly 1, given, disperses all the same.
    assert_ne!(film("interior { ior 1 dispersion 1.2 }"), film(""));
}

#[test]
fn dispersion_items_povray_refuses_are_errors() {
    for (interior, message) in [
        (
            "interior { ior 1.5 dispersion_samples 1 }",
            "dispersion_samples must be at least 2",
        ),
        (
            "interior { ior 1.5 dispersion 0 }",
            "dispersion must be positive",
        ),
    ] {
        let text = SCENE.replace("INTERIOR", interior);
        let e = trace::load_str(
            std::path::Path::new("d.rt"),
            text.clone(),
            &trace::LoadOptions::default(),
        )
        .map(|_| ())
        .expect_err(interior)
        .to_string();
        assert!(
            e.contains(message) && e.contains("d.rt:"),
            "{interior}: {e}"
        );
    }
}
