//! The `trace` binary as a user runs it: files written, exit codes, messages.

use std::process::Command;

fn trace() -> Command {
    Command::new(env!("CARGO_BIN_EXE_trace"))
}

fn temp_dir(name: &str) -> crate::Scratch {
    crate::Scratch::new("cli", name)
}

#[test]
fn renders_png_and_exr() {
    let dir = temp_dir("render");
    for ext in ["png", "exr"] {
        let out = dir.join(format!("img.{ext}"));
        let status = trace()
            .args(["examples/basic_spheres.rt", "-o"])
            .arg(&out)
            .args(["--width", "32", "--height", "24", "--quiet"])
            .current_dir(crate::root())
            .status()
            .expect("runs");
        assert!(status.success());
        let film = trace::Film::read(&out).expect("readable image");
        assert_eq!((film.width, film.height), (32, 24));
    }
}

#[test]
fn exr_in_half_floats_with_bits_16() {
    // `--bits 16` writes an EXR's channels as half floats (POV-Ray's EXR): the same pixels
    // to half precision, in a much smaller file.
    let dir = temp_dir("half");
    let mut films = Vec::new();
    for bits in [None, Some("16")] {
        let out = dir.join(format!("img{}.exr", bits.unwrap_or("")));
        let mut cmd = trace();
        cmd.args(["examples/basic_spheres.rt", "-o"])
            .arg(&out)
            .args(["--width", "64", "--height", "48", "--quiet"]);
        if let Some(b) = bits {
            cmd.args(["--bits", b]);
        }
        assert!(
            cmd.current_dir(crate::root())
                .status()
                .expect("runs")
                .success()
        );
        let size = std::fs::metadata(&out).expect("written").len();
        films.push((trace::Film::read(&out).expect("readable image"), size));
    }
    let ((full, full_size), (half, half_size)) = (&films[0], &films[1]);
    assert!(
        half_size * 3 < *full_size,
        "{half_size} bytes against {full_size}"
    );
    assert_eq!((half.width, half.height), (64, 48));
    let mut differ = 0;
    for (a, b) in full.pixels.iter().zip(&half.pixels) {
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() <= 1e-3 * x.abs().max(1e-3), "{x} against {y}");
            differ += usize::from(x != y);
        }
    }
    assert!(differ > 0, "the half-float file holds the full floats");
}

#[test]
fn bad_scene_exits_2_with_location_and_keeps_existing_output() {
    let dir = temp_dir("bad");
    let scene = dir.join("bad.rt");
    std::fs::write(&scene, "#version 3.7;\ndifference { sphere { 0, 1 } }\n").expect("write");
    let out = dir.join("out.png");
    std::fs::write(&out, b"previous").expect("write");
    let output = trace()
        .arg(&scene)
        .arg("-o")
        .arg(&out)
        .output()
        .expect("runs");
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("bad.rt:2:1"), "{stderr}");
    assert!(stderr.contains("^^^^^^^^^^"), "{stderr}");
    assert!(stderr.contains("unsupported: `difference`"), "{stderr}");
    assert_eq!(std::fs::read(&out).expect("read"), b"previous");
}

#[test]
fn missing_scene_file_exits_1() {
    let output = trace()
        .args(["no/such/scene.rt", "-o", "x.png"])
        .output()
        .expect("runs");
    assert_eq!(output.status.code(), Some(1));
}

#[test]
fn unknown_output_format_exits_2() {
    let output = trace()
        .args(["examples/basic_spheres.rt", "-o", "x.tiff"])
        .current_dir(crate::root())
        .output()
        .expect("runs");
    assert_eq!(output.status.code(), Some(2));
}

#[test]
fn bad_arguments_exit_2() {
    for bad in [["--aa", "sometimes"], ["--aa-method", "4"]] {
        let output = trace()
            .args(["examples/basic_spheres.rt", "-o", "x.png"])
            .args(bad)
            .output()
            .expect("runs");
        assert_eq!(output.status.code(), Some(2), "{bad:?}");
    }
}

#[test]
fn aa_methods_2_and_3_render_as_the_library_does() {
    let dir = temp_dir("methods");
    for (method, antialias) in [
        (
            "2",
            trace::Antialias::Recursive {
                threshold: 0.1,
                depth: 3,
            },
        ),
        (
            "3",
            trace::Antialias::Sampled {
                threshold: 0.1,
                depth: 3,
            },
        ),
    ] {
        let out = dir.join(format!("m{method}.exr"));
        let status = trace()
            .args(["examples/mirrors.rt", "-o"])
            .arg(&out)
            .args([
                "--width",
                "48",
                "--height",
                "36",
                "--aa",
                "0.1",
                "--aa-method",
                method,
                "--quiet",
            ])
            .current_dir(crate::root())
            .status()
            .expect("runs");
        assert!(status.success());
        let text = std::fs::read_to_string(crate::root().join("examples/mirrors.rt")).unwrap();
        let scene = crate::load_text(&text, 48, 36);
        let options = trace::RenderOptions {
            width: 48,
            height: 36,
            antialias,
            threads: None,
            ..Default::default()
        };
        let expected = trace::render(&scene, &options).expect("renders").film;
        assert_eq!(
            trace::Film::read(&out).expect("readable"),
            expected,
            "method {method}"
        );
    }
}

#[test]
fn unwritable_output_exits_1_without_leaving_a_file() {
    let dir = temp_dir("unwritable");
    let out = dir.join("missing-folder").join("img.png");
    let output = trace()
        .args([
            "examples/basic_spheres.rt",
            "--width",
            "8",
            "--height",
            "6",
            "-o",
        ])
        .arg(&out)
        .current_dir(crate::root())
        .output()
        .expect("runs");
    assert_eq!(output.status.code(), Some(1));
    assert!(!out.exists());
}

#[test]
fn compare_prints_flip_and_rmse() {
    let root = crate::root();
    let output = trace()
        .args([
            "compare",
            "golden/povray/mirrors.exr",
            "golden/povray/mirrors.exr",
        ])
        .current_dir(&root)
        .output()
        .expect("runs");
    assert!(output.status.success());
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(stdout.contains("mean FLIP  0.000000"), "{stdout}");
    assert!(stdout.contains("RMSE       0.000000"), "{stdout}");
}

#[test]
fn convert_writes_a_mesh2_include_that_evaluates_to_the_same_mesh() {
    let dir = temp_dir("convert");
    for file in ["knot.obj", "terrain.ply"] {
        let inc = dir.join(format!("{file}.inc"));
        let output = trace()
            .args(["convert", &format!("examples/meshes/{file}"), "-o"])
            .arg(&inc)
            .args(["--name", "Converted"])
            .current_dir(crate::root())
            .output()
            .expect("runs");
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        // The same object through the extension and through the include.
        // (The mesh folder is given with -L: a scene reads only its own and those folders.)
        let direct = format!("mesh_file {{ \"{file}\" }}");
        let included = format!("#include \"{}\"\nobject {{ Converted }}", inc.display());
        let options = trace::LoadOptions {
            include_paths: vec![crate::root().join("examples/meshes")],
            ..Default::default()
        };
        let load = |text: String| {
            let path = dir.join("scene.rt");
            trace::load_str(&path, text, &options)
                .unwrap_or_else(|e| panic!("{e}"))
                .scene
        };
        let (a, b) = (load(direct), load(included));
        assert_eq!(
            format!("{:?}", a.objects),
            format!("{:?}", b.objects),
            "{file}"
        );
        assert!(format!("{:?}", a.objects).contains("triangles"), "{file}");
    }
}

#[test]
fn convert_reports_a_malformed_file_with_its_line_and_writes_nothing() {
    let dir = temp_dir("convert-bad");
    let bad = dir.join("bad.obj");
    std::fs::write(&bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n").expect("write");
    let out = dir.join("bad.inc");
    let output = trace()
        .args(["convert"])
        .arg(&bad)
        .arg("-o")
        .arg(&out)
        .output()
        .expect("runs");
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("bad.obj:4: vertex index 9 is out of range"),
        "{stderr}"
    );
    assert!(!out.exists());
}

/// A render does not keep the lists of a big mesh2 through the scene build: the load's
/// cache of lists (kept by `trace watch` for its next load) is let go once the scene is
/// read, so the build frees a mesh's lists before it makes the mesh's tree. A 180,000-
/// triangle height field needs at most 58 MB at 1 to 4 threads (measured); with the cache
/// kept it needed 70 MB.
#[test]
fn a_big_mesh2_renders_without_its_lists_kept() {
    let dir = temp_dir("mesh_memory");
    let side = 301;
    let mut text = String::from(
        "camera { location <0, 12, -18> look_at 0 }\nlight_source { <-20, 30, -10>, rgb 1 }\n\
         mesh2 {\nvertex_vectors { ",
    );
    text += &format!("{},\n", side * side);
    for j in 0..side {
        for i in 0..side {
            let (x, z) = (
                20.0 * (i as f64 / (side - 1) as f64 - 0.5),
                20.0 * (j as f64 / (side - 1) as f64 - 0.5),
            );
            let y = 0.8 * (0.9 * x).sin() * (0.7 * z).cos();
            text += &format!("<{x:.5},{y:.5},{z:.5}>,");
        }
        text += "\n";
    }
    text.pop();
    text.pop();
    text += &format!("}}\nface_indices {{ {},\n", 2 * (side - 1) * (side - 1));
    for j in 0..side - 1 {
        for i in 0..side - 1 {
            let a = j * side + i;
            let (b, c, d) = (a + side, a + 1, a + side + 1);
            text += &format!("<{a},{b},{c}>,<{c},{b},{d}>,");
        }
        text += "\n";
    }
    text.pop();
    text.pop();
    text += "}\npigment { rgb <0.5, 0.7, 0.4> } }\n";
    let scene = dir.join("terrain.rt");
    std::fs::write(&scene, text).unwrap();
    let out = trace()
        .arg(&scene)
        .arg("-o")
        .arg(dir.join("terrain.png"))
        .args(["--width", "32", "--height", "24", "--aa", "off", "--quiet"])
        .args(["--threads", "2", "--max-memory", "64M"])
        .output()
        .expect("runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
