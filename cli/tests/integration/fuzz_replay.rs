//! Replays every input the fuzzer (scripts/fuzz.py) saved in tests/fuzz/crashers, in the
//! same surroundings and with the same options (but a tenth of the evaluation budget: the
//! tests run a debug build), and holds each to the fuzzer's rules: exit
//! 0, 1 or 2, never a panic, a message on failure, no NaN or infinite pixel in an image, and
//! never a line of the file outside the scene's folder.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const MARKER: &str = "FUZZ_SECRET_MARKER";
const OPTIONS: [&str; 9] = [
    "--width",
    "24",
    "--height",
    "18",
    "--quiet",
    "--max-memory",
    "2G",
    "--max-steps",
    "200000",
];

/// The fuzzer's workspace: a scene folder with the examples' data files and a link out, and
/// secret files beside it.
fn workspace() -> PathBuf {
    let top = std::env::temp_dir().join(format!("trace-fuzz-replay-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&top);
    let scene_dir = top.join("scene");
    std::fs::create_dir_all(scene_dir.join("meshes")).unwrap();
    for name in ["secret.inc", "secret.png", "secret.obj"] {
        std::fs::write(top.join(name), format!("{MARKER} private line\n")).unwrap();
    }
    #[cfg(unix)]
    std::os::unix::fs::symlink(top.join("secret.inc"), scene_dir.join("link.inc")).unwrap();
    let root = crate::root();
    for (from, to) in [
        ("examples/trace_logo.png", "trace_logo.png"),
        ("examples/language.inc", "language.inc"),
        ("examples/meshes/knot.obj", "meshes/knot.obj"),
        ("examples/meshes/terrain.ply", "meshes/terrain.ply"),
        (
            "tests/scenes/err/meshes/bad_index.obj",
            "meshes/bad_index.obj",
        ),
        (
            "tests/scenes/err/meshes/short_vertex.ply",
            "meshes/short_vertex.ply",
        ),
    ] {
        std::fs::copy(root.join(from), scene_dir.join(to)).unwrap();
    }
    scene_dir
}

fn replay(scene_dir: &Path, input: &Path) -> Result<(), String> {
    let scene = scene_dir.join("input.rt");
    let image = scene_dir.join("out.exr");
    let _ = std::fs::remove_file(&image);
    std::fs::copy(input, &scene).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_trace"))
        .arg(&scene)
        .arg("-o")
        .arg(&image)
        .args(OPTIONS)
        .current_dir(scene_dir)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            return Err("still running after 120 s".into());
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut err = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
    if err.contains(MARKER) {
        return Err(format!("printed the secret:\n{err}"));
    }
    match status.code() {
        Some(0) => {
            let film = trace::Film::read(&image).map_err(|e| e.to_string())?;
            match film.non_finite_pixels() {
                0 => Ok(()),
                n => Err(format!("{n} pixels are NaN or infinite")),
            }
        }
        Some(1 | 2) if err.starts_with("error") && !err.contains("panicked") => Ok(()),
        other => Err(format!("exit {other:?}:\n{err}")),
    }
}

#[test]
fn every_saved_fuzz_input_is_handled() {
    let scene_dir = workspace();
    let mut inputs: Vec<PathBuf> = std::fs::read_dir(crate::root().join("tests/fuzz/crashers"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "rt"))
        .collect();
    inputs.sort();
    assert!(!inputs.is_empty(), "no saved inputs to replay");
    let failures: Vec<String> = inputs
        .iter()
        .filter_map(|input| {
            replay(&scene_dir, input)
                .err()
                .map(|e| format!("{}: {e}", input.display()))
        })
        .collect();
    let _ = std::fs::remove_dir_all(scene_dir.parent().unwrap());
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}
