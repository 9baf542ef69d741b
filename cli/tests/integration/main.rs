//! Integration tests: one binary, one module per concern.

mod analytic;
mod cli;
mod directives;
mod dispersion;
mod errors;
mod farm;
mod fuzz_replay;
mod golden;
mod hostile;
mod ir_snapshots;
mod irid;
mod keywords;
mod layers;
mod lenient;
mod media;
mod parsing;
mod povray_cli;
mod radiosity;
mod rainbow;
mod rebuild;
mod watch;

use std::path::{Path, PathBuf};

/// A scratch folder of the system's temporary folder, named for the test's kind and name and
/// the process: fresh (emptied if a run before left it), and removed when dropped, so that
/// test runs leave nothing behind.
pub struct Scratch(PathBuf);

impl Scratch {
    pub fn new(kind: &str, name: &str) -> Scratch {
        let id = std::process::id();
        let dir = std::env::temp_dir().join(format!("trace-{kind}-{id}-{name}"));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("scratch folder");
        Scratch(dir)
    }
}

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl AsRef<Path> for Scratch {
    fn as_ref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The repository root (the workspace; this crate is cli/).
pub fn root() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// POV-Ray's standard include folder (Debian's `povray-includes`, or where `POVRAY_INCLUDE`
/// points). A test that reads its files calls this and fails where it is missing, rather than
/// passing without running; `.ci/run` installs it.
pub fn povray_includes() -> PathBuf {
    trace::standard_include_folder().expect(
        "POV-Ray's include files are not installed: `apt-get install povray-includes`, or set POVRAY_INCLUDE",
    )
}

/// Asserts each channel of a film pixel (f32) within `tolerance` of a value computed by hand
/// or read from POV-Ray's render of the same scene; `what` names the pixel in the message.
pub fn assert_near(actual: [f32; 3], expected: [f64; 3], tolerance: f64, what: &str) {
    for c in 0..3 {
        assert!(
            (f64::from(actual[c]) - expected[c]).abs() <= tolerance,
            "{what}: got {actual:?}, expected {expected:?}"
        );
    }
}

/// Loads scene text at a given image size, panicking with the rendered diagnostic on error.
pub fn load_text(text: &str, width: u32, height: u32) -> trace::ir::Scene {
    let options = trace::LoadOptions {
        width,
        height,
        ..Default::default()
    };
    match trace::load_str(Path::new("test.rt"), text.to_string(), &options) {
        Ok(loaded) => loaded.scene,
        Err(e) => panic!("{e}"),
    }
}

/// Renders scene text and returns the film.
pub fn render_text(
    text: &str,
    width: u32,
    height: u32,
    antialias: trace::Antialias,
) -> trace::Film {
    let scene = load_text(text, width, height);
    let options = trace::RenderOptions {
        width,
        height,
        antialias,
        threads: None,
        ..Default::default()
    };
    trace::render(&scene, &options).expect("renders").film
}

/// Renders a scene on one thread and on two without anti-aliasing, asserts the two films equal
/// pixel for pixel, and returns the film.
pub fn render_at_one_and_two_threads(
    scene: &trace::ir::Scene,
    width: u32,
    height: u32,
) -> trace::Film {
    let film = |threads| {
        let options = trace::RenderOptions {
            width,
            height,
            antialias: trace::Antialias::Off,
            threads: Some(threads),
            ..Default::default()
        };
        trace::render(scene, &options).expect("renders").film
    };
    let (one, two) = (film(1), film(2));
    for y in 0..height {
        for x in 0..width {
            assert_eq!(one.get(x, y), two.get(x, y), "pixel ({x}, {y})");
        }
    }
    one
}
