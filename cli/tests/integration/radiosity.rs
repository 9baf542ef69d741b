//! Radiosity (docs/radiosity.md): the settings as POV-Ray reads them, the picture against
//! POV-Ray's, the same bytes for any thread count or region, and what radiosity changes in
//! POV-Ray 3.7's lighting (ambient dropped, `no_radiosity`).
//!
//! The references (golden/radiosity, made by scripts/radiosity.sh) are POV-Ray 3.7 with one
//! thread, the only way its radiosity reproduces. POV-Ray's own renders with two threads differ
//! from it (their samples depend on the threads' timing); the script measures by how much,
//! and that spread (golden/radiosity/spread.txt) is the tolerance: trace's picture must be as
//! close to POV-Ray's one-thread picture as POV-Ray's own runs are to each other.

use crate::{load_text, povray_includes, root};
use trace::{Antialias, Film, RenderOptions};

/// POV-Ray's spread for a scene, from spread.txt.
fn spread(name: &str) -> f32 {
    let text = std::fs::read_to_string(root().join("golden/radiosity/spread.txt"))
        .expect("golden/radiosity/spread.txt (scripts/radiosity.sh)");
    text.lines()
        .find_map(|l| {
            let (n, v) = l.split_once(' ')?;
            (n == name).then(|| v.trim().parse().ok())?
        })
        .unwrap_or_else(|| panic!("no spread for {name} (run scripts/radiosity.sh {name})"))
}

/// Renders tests/radiosity/NAME.pov at 160×120 without anti-aliasing.
fn render_scene(name: &str, threads: usize, region: Option<trace::film::Region>) -> Film {
    render_scene_in(name, threads, region, false)
}

/// The same, in POV-Ray's one-thread order if `povray_order`.
fn render_scene_in(
    name: &str,
    threads: usize,
    region: Option<trace::film::Region>,
    povray_order: bool,
) -> Film {
    rendered_scene(name, threads, region, povray_order).film
}

/// The render of tests/radiosity/NAME.pov, with its statistics.
fn rendered_scene(
    name: &str,
    threads: usize,
    region: Option<trace::film::Region>,
    povray_order: bool,
) -> trace::Rendered {
    let path = root().join("tests/radiosity").join(format!("{name}.pov"));
    let options = trace::LoadOptions {
        width: 160,
        height: 120,
        include_paths: vec![povray_includes()],
        ..Default::default()
    };
    let scene = trace::load(&path, &options).expect("loads").scene;
    let render = RenderOptions {
        width: 160,
        height: 120,
        antialias: Antialias::Off,
        threads: Some(threads),
        region,
        radiosity_povray_order: povray_order,
        ..Default::default()
    };
    trace::render(&scene, &render).expect("renders")
}

#[test]
fn in_povray_order_radiosity_takes_povray_s_samples_pass_by_pass_and_depth_by_depth() {
    // POV-Ray 3.7's statistics (`povray +WT1 +W160 +H120 -A`, its table of samples by pass
    // and depth), and the same counts from trace.
    type Counts = trace::SamplesByDepth;
    let cases: [(&str, &[Counts], Counts); 2] = [
        (
            "room",
            &[[125, 150, 0, 0, 0], [126, 26, 0, 0, 0]],
            [1, 0, 0, 0, 0],
        ),
        (
            "settings",
            &[[133, 0, 0, 0, 0], [485, 0, 0, 0, 0], [1123, 0, 0, 0, 0]],
            [795, 0, 0, 0, 0],
        ),
    ];
    for (name, passes, last) in cases {
        let stats = rendered_scene(name, 2, None, true).stats;
        assert_eq!(
            stats.pretrace.samples, passes,
            "{name}: the pretrace's passes"
        );
        assert_eq!(stats.radiosity_samples, last, "{name}: the final render");
    }
}

#[test]
fn in_povray_order_radiosity_reproduces_povray_with_one_thread() {
    // The pretrace and the final render block after block, every sample seeing all taken
    // before it and drawing the pool's next directions, as one POV-Ray thread does: the
    // picture is POV-Ray's own. In `settings` a box has an importance below 1 and a mirror
    // ball gathers samples: its reflections then stop at the box as POV-Ray's do (0.041
    // before they did). `pool` draws from POV-Ray's older table of 1600 directions (the
    // Halton pool there comes to 0.063). `importance` gives a default importance.
    for name in ["room", "settings", "legacy", "pool", "importance"] {
        let actual = render_scene_in(name, 2, None, true);
        let expected = Film::read(&root().join(format!("golden/radiosity/{name}.exr")))
            .expect("reference (scripts/radiosity.sh)");
        let c = trace::film::compare(&expected, &actual).expect("same size");
        assert!(c.mean_flip <= 0.01, "{name}: mean FLIP {}", c.mean_flip);
    }
}

/// The mean of a film's values.
fn mean(film: &Film) -> f64 {
    let sum: f64 = film
        .pixels
        .iter()
        .map(|p| p.iter().map(|&v| f64::from(v)).sum::<f64>())
        .sum();
    sum / (3 * film.pixels.len()) as f64
}

#[test]
fn radiosity_scenes_are_as_close_to_povray_as_its_own_runs_are_to_each_other() {
    let mut failures = Vec::new();
    for name in ["room", "settings", "legacy", "pool", "importance"] {
        let actual = render_scene(name, 2, None);
        let expected = Film::read(&root().join(format!("golden/radiosity/{name}.exr")))
            .expect("reference (scripts/radiosity.sh)");
        let c = trace::film::compare(&expected, &actual).expect("same size");
        let tolerance = spread(name).max(0.01);
        // And no bias: the picture's mean within 2 % of POV-Ray's (the noise of either
        // moves it by less).
        let (m, e) = (mean(&actual), mean(&expected));
        if c.mean_flip > tolerance || (m - e).abs() > 0.02 * e {
            failures.push(format!(
                "{name}: mean FLIP {:.4} (POV-Ray's spread {tolerance:.4}), mean {m:.4} against {e:.4}",
                c.mean_flip
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn radiosity_gives_the_same_bytes_for_any_thread_count_and_region() {
    let one = render_scene("room", 1, None);
    let two = render_scene("room", 2, None);
    assert!(one.pixels == two.pixels, "1 and 2 threads differ");
    // A region is the same pixels as the whole render's.
    let region = trace::film::Region {
        x0: 40,
        y0: 30,
        x1: 110,
        y1: 100,
    };
    let part = render_scene("room", 2, Some(region));
    for y in region.y0..region.y1 {
        for x in region.x0..region.x1 {
            assert_eq!(
                part.get(x - region.x0, y - region.y0),
                two.get(x, y),
                "({x}, {y})"
            );
        }
    }
}

/// A white room lit by one light, with radiosity and `extra` in the scene.
fn room(version: &str, radiosity: &str, extra: &str) -> String {
    format!(
        "#version {version};
        global_settings {{ assumed_gamma 1 {radiosity} }}
        camera {{ location <0, 1, -2.5> look_at <0, 1, 0> angle 70 }}
        light_source {{ <0, 1.8, -1> rgb 1 }}
        #default {{ finish {{ ambient 0.3 diffuse 0.7 }} }}
        box {{ <-1.5, 0, -3>, <1.5, 2, 1.5> hollow pigment {{ rgb 0.8 }} }}
        {extra}"
    )
}

fn rendered(text: &str) -> Film {
    let scene = load_text(text, 48, 36);
    let options = RenderOptions {
        width: 48,
        height: 36,
        antialias: Antialias::Off,
        ..Default::default()
    };
    trace::render(&scene, &options).expect("renders").film
}

#[test]
fn radiosity_replaces_ambient_from_version_3_7_and_not_before() {
    let on = "radiosity { count 20 }";
    // 3.7: ambient no longer lights anything once radiosity is on: 0.3 or 0.9, the same.
    let a = rendered(&room("3.7", on, ""));
    let b = rendered(&room("3.7", on, "").replace("ambient 0.3", "ambient 0.9"));
    assert!(a.pixels == b.pixels);
    // Before 3.7 it still does.
    let c = rendered(&room("3.6", on, ""));
    let d = rendered(&room("3.6", on, "").replace("ambient 0.3", "ambient 0.9"));
    assert!(mean(&d) > mean(&c) * 1.2, "{} {}", mean(&d), mean(&c));
    // And radiosity lights the room more than the light alone would.
    let off = rendered(&room("3.7", "", "").replace("ambient 0.3", "ambient 0"));
    assert!(mean(&a) > mean(&off) * 1.2, "{} {}", mean(&a), mean(&off));
}

#[test]
fn no_radiosity_hides_an_object_from_radiosity_alone() {
    let on = "radiosity { count 30 }";
    // A glowing wall behind the camera lights the room through radiosity alone.
    let panel =
        "box { <-1.4, 0.1, -2.95>, <1.4, 1.9, -2.9> pigment { rgb 1 } finish { emission 3 } }";
    let lit = rendered(&room("3.7", on, panel));
    let hidden = rendered(&room(
        "3.7",
        on,
        &panel.replace("pigment", "no_radiosity pigment"),
    ));
    let without = rendered(&room("3.7", on, ""));
    assert!(
        mean(&lit) > mean(&without) * 1.15,
        "{} {}",
        mean(&lit),
        mean(&without)
    );
    // Hidden from radiosity, it lights nothing (its shadows on the direct light aside).
    assert!(
        mean(&hidden) <= mean(&without) * 1.001,
        "{} {}",
        mean(&hidden),
        mean(&without)
    );
}

#[test]
fn the_radiosity_settings_are_read_as_povray_reads_them() {
    let scene = load_text(
        "global_settings { radiosity {
            count 50, 2000 nearest_count 8, 4 error_bound 0.9 recursion_limit 3
            low_error_factor 0.4 gray_threshold 0.2 brightness 1.3 minimum_reuse 0.01
            maximum_reuse 0.1 adc_bailout 0.005 always_sample on max_sample 2
            pretrace_start 0.1 pretrace_end 0.01 normal on media off } }
        sphere { 0, 1 pigment { rgb 1 } }",
        32,
        24,
    );
    let r = scene.settings.radiosity.expect("radiosity on");
    assert_eq!((r.count, r.directions), (50, 2000));
    assert_eq!((r.nearest_count, r.pretrace_count), (8, 4));
    assert_eq!(r.recursion_limit, 3);
    assert!(r.always_sample && r.normal && !r.media);
    assert_eq!(
        [
            r.error_bound,
            r.low_error_factor,
            r.gray_threshold,
            r.brightness,
            r.minimum_reuse,
            r.maximum_reuse,
            r.adc_bailout,
            r.max_sample,
            r.pretrace_start,
            r.pretrace_end
        ],
        [0.9, 0.4, 0.2, 1.3, 0.01, 0.1, 0.005, 2.0, 0.1, 0.01]
    );
    // An empty block turns radiosity on with POV-Ray's defaults.
    let r = load_text(
        "#version 3.7; global_settings { radiosity { } } sphere { 0, 1 pigment { rgb 1 } }",
        32,
        24,
    )
    .settings
    .radiosity
    .expect("radiosity on");
    assert_eq!(r, trace::ir::Radiosity::default());
    assert_eq!((r.count, r.directions, r.nearest_count), (35, 1600, 5));
    // A maximum_reuse given below twice the default minimum_reuse lowers the minimum (as
    // POV-Ray does, with a warning).
    let r = load_text(
        "global_settings { radiosity { maximum_reuse 0.02 } } sphere { 0, 1 }",
        32,
        24,
    )
    .settings
    .radiosity
    .expect("radiosity on");
    assert_eq!(r.minimum_reuse, 0.01);
}

#[test]
fn an_objects_radiosity_importance_is_read_and_changes_what_samples_see() {
    let text = |importance: &str| {
        format!(
            "#version 3.7;
            global_settings {{ assumed_gamma 1 radiosity {{ count 40 }} }}
            camera {{ location <0, 1, -2.5> look_at <0, 1, 0> angle 70 }}
            light_source {{ <0, 1.8, -1> rgb 1 }}
            box {{ <-1.5, 0, -3>, <1.5, 2, 1.5> hollow pigment {{ rgb 0.8 }} }}
            box {{ <-1.4, 0.1, -2.95>, <1.4, 1.9, -2.9> pigment {{ rgb 1 }} finish {{ emission 3 }}
                  {importance} }}"
        )
    };
    // `#default { radiosity { importance } }` gives the importance of objects that give
    // none (the last given counts).
    let defaulted = load_text(
        &format!(
            "#default {{ radiosity {{ importance 0.5 }} }}\n#default {{ radiosity {{ importance 0.3 }} }}\n{}",
            text("")
        ),
        32,
        24,
    );
    let r = defaulted.settings.radiosity.as_ref().expect("radiosity on");
    assert_eq!(r.default_importance, 0.3);
    assert_eq!(
        load_text(&text(""), 32, 24)
            .settings
            .radiosity
            .expect("on")
            .default_importance,
        1.0
    );
    let scene = load_text(&text("radiosity { importance 0.25 }"), 32, 24);
    let panel = scene.objects.last().expect("the panel");
    let extras = panel.extras.as_ref().expect("extras");
    assert_eq!(extras.importance, Some(0.25));
    // A quarter of a sample's rays go on from the glowing panel, each counting four times:
    // the light it sends is about the same, not the same pixels.
    let all = rendered(&text(""));
    let quarter = rendered(&text("radiosity { importance 0.25 }"));
    assert!(all.pixels != quarter.pixels);
    assert!(
        (mean(&all) - mean(&quarter)).abs() < 0.1 * mean(&all),
        "{} {}",
        mean(&all),
        mean(&quarter)
    );
}
