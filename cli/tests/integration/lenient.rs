//! What POV-Ray's parser lets pass that a strict grammar would not: optional commas, legacy
//! keywords, directives at token boundaries, numbers and colours read loosely … one scene
//! each in tests/lenient/ (its first lines say what it exercises and what POV-Ray warns).
//! Each renders at 64×48 without anti-aliasing and matches POV-Ray 3.7's render
//! (tests/lenient/povray/, made by scripts/lenient.sh) within mean FLIP 0.01.

use crate::root;

#[test]
fn leniency_scenes_render_as_povray_renders_them() {
    let dir = root().join("tests/lenient");
    // (A scene may write a file next to it: each renders from a copy of the folder.)
    let work = std::env::temp_dir().join(format!("trace-lenient-{}", std::process::id()));
    std::fs::create_dir_all(&work).unwrap();
    let mut scenes = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_file() {
            std::fs::copy(&path, work.join(path.file_name().unwrap())).unwrap();
            if path.extension().is_some_and(|e| e == "pov") {
                scenes.push(path.file_stem().unwrap().to_string_lossy().to_string());
            }
        }
    }
    scenes.sort();
    assert!(scenes.len() >= 90, "{} scenes", scenes.len());
    let options = trace::LoadOptions {
        width: 64,
        height: 48,
        include_paths: vec![crate::povray_includes()],
        ..Default::default()
    };
    let mut failures = Vec::new();
    for name in &scenes {
        let loaded = match trace::load(&work.join(format!("{name}.pov")), &options) {
            Ok(l) => l,
            Err(e) => {
                failures.push(format!("{name}: {e}"));
                continue;
            }
        };
        let render = trace::RenderOptions {
            width: 64,
            height: 48,
            antialias: trace::Antialias::Off,
            threads: None,
            ..Default::default()
        };
        let actual = trace::render(&loaded.scene, &render).unwrap().film;
        let expected = trace::Film::read(&dir.join("povray").join(format!("{name}.png")))
            .unwrap_or_else(|e| {
                panic!("{name}: no POV-Ray reference ({e}): run scripts/lenient.sh")
            });
        let c = trace::film::compare(&expected, &actual).unwrap();
        if c.mean_flip > 0.01 {
            failures.push(format!("{name}: mean FLIP {:.4}", c.mean_flip));
        }
    }
    let _ = std::fs::remove_dir_all(&work);
    assert!(failures.is_empty(), "{failures:#?}");
}
