//! Renders every example at 320×240 and compares it with POV-Ray 3.7's render of the same
//! file (golden/povray, made by scripts/golden.sh).
//!
//! Tolerance: mean FLIP ≤ 0.01 (the project's bar for "renders like POV-Ray") and no NaN or
//! infinite pixel; ≤ 0.005 for anti-aliasing method 2, so that it tells the two methods apart
//! (method 1 against the method-2 references gives 0.005–0.028 on 13 of the 15 examples). On failure the actual, expected and FLIP images are written to
//! target/golden-failures/ for a person to look at.

use crate::root;
use trace::{Antialias, Film};

const MAX_MEAN_FLIP: f32 = 0.01;

fn check(
    stem: &str,
    antialias: Antialias,
    reference_name: &str,
    max_mean_flip: f32,
) -> Result<f32, String> {
    let scene_path = root().join("examples").join(format!("{stem}.rt"));
    let options = trace::LoadOptions {
        width: 320,
        height: 240,
        include_paths: trace::standard_include_folder().into_iter().collect(),
        ..Default::default()
    };
    let loaded = trace::load(&scene_path, &options).map_err(|e| e.to_string())?;
    let render = trace::RenderOptions {
        width: 320,
        height: 240,
        antialias,
        threads: None,
        ..Default::default()
    };
    let actual = trace::render(&loaded.scene, &render)
        .map_err(|e| e.to_string())?
        .film;
    let expected = Film::read(&root().join("golden/povray").join(reference_name))
        .map_err(|e| e.to_string())?;
    let c = trace::film::compare(&expected, &actual).map_err(|e| e.to_string())?;
    let nan = actual.non_finite_pixels();
    if c.mean_flip <= max_mean_flip && nan == 0 {
        return Ok(c.mean_flip);
    }
    let dir = root().join("target/golden-failures");
    std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
    let base = reference_name.trim_end_matches(".exr");
    actual
        .write(&dir.join(format!("{base}.actual.png")))
        .map_err(|e| e.to_string())?;
    expected
        .write(&dir.join(format!("{base}.expected.png")))
        .map_err(|e| e.to_string())?;
    trace::film::write_rgb8_png(&dir.join(format!("{base}.flip.png")), 320, 240, c.flip_map)
        .map_err(|e| e.to_string())?;
    Err(format!(
        "{reference_name}: mean FLIP {:.4} (max {max_mean_flip}), RMSE {:.5}, {nan} NaN pixels; images in {}",
        c.mean_flip,
        c.rmse,
        dir.display()
    ))
}

/// What marks an example that needs POV-Ray's include files (fonts) installed.
const NEEDS_INCLUDES: &str = "Needs POV-Ray's include files installed.";

/// The examples to render here: all of them. One that needs POV-Ray's include files fails
/// where they are not installed, rather than passing without running.
fn examples() -> Vec<String> {
    let examples = all_examples();
    for stem in &examples {
        let text = std::fs::read_to_string(root().join("examples").join(format!("{stem}.rt")))
            .unwrap_or_default();
        if text.contains(NEEDS_INCLUDES) {
            crate::povray_includes();
        }
    }
    examples
}

fn all_examples() -> Vec<String> {
    let mut stems: Vec<String> = std::fs::read_dir(root().join("examples"))
        .expect("examples folder")
        .filter_map(|e| {
            let p = e.ok()?.path();
            if p.extension()? != "rt" {
                return None;
            }
            Some(p.file_stem()?.to_string_lossy().into_owned())
        })
        .collect();
    stems.sort();
    stems
}

/// Every example against its POV-Ray reference `NAME{suffix}`.
fn examples_match(antialias: Antialias, suffix: &str, max_mean_flip: f32) {
    let failures: Vec<String> = examples()
        .iter()
        .filter_map(|s| check(s, antialias, &format!("{s}{suffix}"), max_mean_flip).err())
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn examples_match_povray_without_antialiasing() {
    examples_match(Antialias::Off, ".exr", MAX_MEAN_FLIP);
}

#[test]
fn examples_match_povray_with_antialiasing_threshold_0() {
    let aa = Antialias::Adaptive {
        threshold: 0.0,
        depth: 3,
    };
    examples_match(aa, ".aa.exr", MAX_MEAN_FLIP);
}

#[test]
fn examples_match_povray_with_antialiasing_method_2() {
    let aa = Antialias::Recursive {
        threshold: 0.1,
        depth: 3,
    };
    examples_match(aa, ".am2.exr", 0.005);
}

#[test]
fn every_example_has_povray_references() {
    for stem in all_examples() {
        for suffix in [".exr", ".aa.exr", ".am2.exr"] {
            let p = root().join("golden/povray").join(format!("{stem}{suffix}"));
            assert!(
                p.exists(),
                "missing {} (run scripts/golden.sh {stem})",
                p.display()
            );
        }
    }
}
