//! Hostile input (issue 13): the sandbox, no panic or abort on any input, bounded work and
//! memory, non-finite values, bytes that are not UTF-8, interrupted writes.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn trace() -> Command {
    Command::new(env!("CARGO_BIN_EXE_trace"))
}

/// A fresh scratch folder, removed at the end of the test.
fn scratch(name: &str) -> crate::Scratch {
    crate::Scratch::new("hostile", name)
}

const CAMERA: &str =
    "camera { location <0, 0, -5> look_at 0 }\nlight_source { <5, 5, -5> rgb 1 }\n";

/// Renders scene text (written to `dir/scene.rt`) at 16×12; returns the output.
fn run_in(dir: &Path, text: &str, extra: &[&str]) -> Output {
    let scene = dir.join("scene.rt");
    std::fs::write(&scene, text).expect("write scene");
    trace()
        .arg(&scene)
        .arg("-o")
        .arg(dir.join("out.exr"))
        .args(["--width", "16", "--height", "12", "--quiet"])
        .args(extra)
        .output()
        .expect("runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Loads scene text through the library; the error message, or `None` if it loads.
pub(crate) fn load_error(text: &str) -> Option<String> {
    trace::load_str(
        Path::new("hostile.rt"),
        text.to_string(),
        &trace::LoadOptions::default(),
    )
    .err()
    .map(|e| e.to_string())
}

/// A secret outside the scene's folder, a scene folder with a link to it, and files the
/// scene may not read, each holding a marker that must never be printed: the scratch folder
/// holding both (removed when dropped), the scene's folder and the one outside it.
fn sandbox_layout(name: &str) -> (crate::Scratch, PathBuf, PathBuf) {
    let root = scratch(name);
    let (scene_dir, outside) = (root.join("scene"), root.join("outside"));
    std::fs::create_dir_all(&scene_dir).unwrap();
    std::fs::create_dir_all(&outside).unwrap();
    let secret = "SECRET_MARKER line of a private file\n";
    for file in ["x.inc", "x.png", "x.obj"] {
        std::fs::write(outside.join(file), secret).unwrap();
    }
    #[cfg(unix)]
    std::os::unix::fs::symlink(outside.join("x.inc"), scene_dir.join("link.inc")).unwrap();
    (root, scene_dir, outside)
}

#[test]
fn a_scene_reads_no_file_outside_its_folder_and_the_include_paths() {
    let (_root, scene_dir, outside) = sandbox_layout("sandbox");
    let absolute = outside.join("x.inc");
    let mut cases = vec![
        "#include \"/etc/passwd\"".to_string(),
        "#include \"/proc/self/environ\"".to_string(),
        "#include \"../outside/x.inc\"".to_string(),
        format!("#include \"{}\"", absolute.display()),
        format!("{CAMERA}sphere {{ 0, 1 pigment {{ image_map {{ png \"../outside/x.png\" }} }} }}"),
        format!("{CAMERA}mesh_file {{ \"../outside/x.obj\" }}"),
    ];
    if cfg!(unix) {
        cases.push("#include \"link.inc\"".to_string());
    }
    for text in &cases {
        let out = run_in(&scene_dir, text, &[]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{text}: {err}");
        assert!(
            err.contains("lies outside the folders this scene may read"),
            "{text}: {err}"
        );
        assert!(err.contains("scene.rt:"), "located: {err}");
        assert!(
            !err.contains("SECRET_MARKER") && !err.contains("root:"),
            "{text}: {err}"
        );
    }
    // `#fopen … read` reads only where `#include` does.
    let out = run_in(&scene_dir, "#fopen F \"../outside/x.inc\" read\n", &[]);
    assert!(
        stderr(&out).contains("lies outside the folders"),
        "{}",
        stderr(&out)
    );
    // `#fopen … write` and `append` write only inside the scene's folder, even with -L.
    let targets = [
        "../outside/new.txt".to_string(),
        "/tmp/trace-never-written.txt".to_string(),
        format!("{}", outside.join("x.inc").display()),
        "link.inc".to_string(),
    ];
    for target in &targets {
        for mode in ["write", "append"] {
            let text = format!("#fopen F \"{target}\" {mode}\n#write (F, \"overwritten\")\n");
            let out = run_in(&scene_dir, &text, &["-L", outside.to_str().unwrap()]);
            let err = stderr(&out);
            assert_eq!(out.status.code(), Some(2), "{text}: {err}");
            assert!(
                err.contains("lies outside the scene's folder") && err.contains("scene.rt:1:"),
                "{text}: {err}"
            );
        }
    }
    assert!(!outside.join("new.txt").exists());
    assert!(!Path::new("/tmp/trace-never-written.txt").exists());
    assert!(
        std::fs::read_to_string(outside.join("x.inc"))
            .unwrap()
            .starts_with("SECRET_MARKER")
    );
    // `file_exists` sees no file outside either.
    let probe = format!("#if (file_exists(\"../outside/x.inc\")) #error \"seen\" #end\n{CAMERA}");
    let out = run_in(&scene_dir, &probe, &[]);
    assert!(out.status.success(), "{}", stderr(&out));
    // A folder given with -L is allowed: the include is read (and, not being a scene, fails
    // to parse, which is the scene author's own doing).
    let out = run_in(&scene_dir, &cases[2], &["-L", outside.to_str().unwrap()]);
    assert!(stderr(&out).contains("x.inc:1:1"), "{}", stderr(&out));
}

#[test]
fn wrong_argument_counts_and_huge_widths_are_errors_not_crashes() {
    let cases = [
        ("#declare S = str(1);", "`str` takes 3 arguments, found 1"),
        ("#declare S = chr();", "`chr` takes 1 argument, found 0"),
        (
            "#declare S = substr(\"abc\", 1);",
            "`substr` takes 3 arguments, found 2",
        ),
        (
            "#declare S = strupr();",
            "`strupr` takes 1 argument, found 0",
        ),
        (
            "#declare S = strlwr(\"a\", \"b\");",
            "`strlwr` takes 1 argument, found 2",
        ),
        (
            "#declare S = vstr(3, x);",
            "`vstr` takes 5 arguments, found 2",
        ),
        (
            "#declare S = str(1, 65536, 0);",
            "width and precision are at most",
        ),
        (
            "#declare S = str(1, -1e6, 0);",
            "width and precision are at most",
        ),
        (
            "#declare S = str(1, 0, 1e9);",
            "width and precision are at most",
        ),
        (
            "#declare S = substr(\"abc\", 2, 1e30);",
            "outside the string",
        ),
    ];
    for (text, message) in cases {
        let err = load_error(text).unwrap_or_else(|| panic!("{text} should not load"));
        assert!(err.contains(message), "{text}: {err}");
        assert!(err.contains("hostile.rt:1:"), "{text}: {err}");
    }
}

#[test]
fn values_that_are_not_finite_are_located_errors() {
    for (text, culprit) in [
        ("sphere { 0, exp(1000) }", "exp(1000)"),
        ("sphere { 0, 1e400 }", "1e400"),
        ("sphere { 0, 1e308*10 - 1e308*10 }", "1e308*10"),
        ("#declare A = val(\"nan\");", "val(\"nan\")"),
        ("sphere { <1, 0, 1e308*10>, 1 }", "1e308*10"),
        (
            "mesh2 { vertex_vectors { 3, <0,0,0>, <1e400,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }",
            "<1e400",
        ),
    ] {
        let err = load_error(text).unwrap_or_else(|| panic!("{text} should not load"));
        assert!(err.contains("not a finite number"), "{text}: {err}");
        let column = text.find(culprit).unwrap() + 1;
        assert!(
            err.contains(&format!("hostile.rt:1:{column}")),
            "{text}: {err}"
        );
    }
    let err = load_error("sphere { 0, 1 scale 1e200 scale 1e200 }").expect("overflow");
    assert!(err.contains("transformations overflow"), "{err}");
    // A negative fog distance makes POV-Ray's pixels NaN: refused, at the distance.
    let err = load_error("fog { distance -1 rgb 1 }").expect("negative distance");
    assert!(
        err.contains("must not be negative") && err.contains("hostile.rt:1:16"),
        "{err}"
    );
}

#[test]
fn a_negative_brilliance_renders_without_nan() {
    // Lit so that some shading points see the light exactly at grazing incidence.
    let text = format!(
        "{CAMERA}plane {{ y, 0 pigment {{ rgb 1 }} finish {{ brilliance -1 }} }}\n\
         light_source {{ <0, 0, 10> rgb 1 }}\n\
         sphere {{ <0, 0, 0>, 1 pigment {{ rgb 1 }} finish {{ brilliance -2 }} }}"
    );
    let scene = trace::load_str(Path::new("b.rt"), text, &trace::LoadOptions::default())
        .expect("loads")
        .scene;
    let options = trace::RenderOptions {
        width: 32,
        height: 24,
        antialias: trace::Antialias::Off,
        threads: None,
        ..Default::default()
    };
    let film = trace::render(&scene, &options).expect("renders").film;
    assert_eq!(film.non_finite_pixels(), 0);
}

#[test]
fn an_object_with_unbounded_extent_among_many_renders() {
    // Bounds past f32 (a huge but finite sphere) among enough objects for a BVH: it is
    // tested for every ray instead.
    let mut text = String::from(CAMERA);
    for i in 0..12 {
        text += &format!("sphere {{ <{i}, 0, 0>, 0.5 pigment {{ rgb 1 }} }}\n");
    }
    text += "sphere { 0, 1e39 pigment { rgb 1 } hollow }\n";
    let dir = scratch("unbounded");
    let out = run_in(&dir, &text, &[]);
    assert!(out.status.success(), "{}", stderr(&out));
}

#[test]
fn work_and_memory_are_bounded() {
    let dir = scratch("bounds");
    // Nested loops share one budget.
    let loops =
        "#declare N = 0;\n#for (i, 0, 999999) #for (j, 0, 999999) #declare N = N + 1; #end #end\n";
    let out = run_in(&dir, loops, &["--max-steps", "5000"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("--max-steps"), "{}", stderr(&out));
    // Endless macro recursion that fans out is cut by the same budget.
    let fan = "#macro F(n) #if (n < 40) F(n+1) F(n+1) #end #end\nF(0)\n";
    let out = run_in(&dir, fan, &["--max-steps", "5000"]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("--max-steps"), "{}", stderr(&out));
    // A macro's body is charged for once (it is parsed once), each call 4 steps besides the
    // statements it runs: 1000 calls of a macro with a 16 KB body fit 10,000 steps (at a
    // charge by body length per call they would take a million), 3000 calls do not.
    let big_body = format!("#macro M() #local X = 1; // {}\n#end\n", "x".repeat(16_000));
    let calls = |n: usize| format!("{big_body}#for (i, 1, {n}) M() #end\n{CAMERA}");
    let macro_dir = scratch("bounds-macro");
    let out = run_in(&macro_dir, &calls(1000), &["--max-steps", "10000"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let out = run_in(&macro_dir, &calls(3000), &["--max-steps", "10000"]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("--max-steps"), "{}", stderr(&out));
    // A string doubled in a loop stops at the string limit.
    let doubling = "#declare S = \"ab\";\n#for (i, 0, 40) #declare S = concat(S, S); #end\n";
    let err = load_error(doubling).expect("too long");
    assert!(err.contains("trace allows at most"), "{err}");
    // A scene writing its files forever stops at the bound on bytes written.
    let writing = "#declare S = \"abcdefgh\";\n#for (i, 0, 16) #declare S = concat(S, S); #end\n\
                   #fopen F \"big.txt\" write\n#while (1) #write (F, S) #end\n";
    let out = run_in(&dir, writing, &[]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("writes more than"),
        "{}",
        stderr(&out)
    );
    let _ = std::fs::remove_file(dir.join("big.txt"));
    // A count announces more than the list holds: no allocation of the announced size.
    let announced = "mesh2 { vertex_vectors { 100000000, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }";
    let err = load_error(announced).expect("wrong count");
    assert!(
        err.contains("announces 100000000 entries but lists 3"),
        "{err}"
    );
    // An image whose band of rows does not fit the memory limit is refused before any
    // work (the image itself is written band by band: 65536 pixels a row need one band of
    // 32 rows at about 28 bytes a pixel and the writer's 64 rows, 109 MB).
    std::fs::write(dir.join("small.rt"), CAMERA).unwrap();
    let out = trace()
        .arg(dir.join("small.rt"))
        .arg("-o")
        .arg(dir.join("huge.exr"))
        .args([
            "--width",
            "65536",
            "--height",
            "65536",
            "--max-memory",
            "50M",
        ])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("more than the limit"),
        "{}",
        stderr(&out)
    );
    // Running out of memory mid-scene ends with exit 1 and a message, not an abort.
    let mut big = String::from(CAMERA);
    big += "#declare A = array[1000000];\n#for (i, 0, 999999) #declare A[i] = <i, i, i>; #end\n";
    let out = run_in(&dir, &big, &["--max-memory", "20M"]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("out of memory"), "{}", stderr(&out));
    assert!(!dir.join("out.exr").exists());
}

#[test]
fn latin1_bytes_read_as_in_povray() {
    let dir = scratch("latin1");
    let mut text = b"// caf\xe9 cr\xe8me\n#debug \"na\xefve\\n\"\n".to_vec();
    text.extend(CAMERA.bytes());
    text.extend(b"sphere { 0, 1 pigment { rgb 1 } }\n");
    let scene = dir.join("scene.rt");
    std::fs::write(&scene, text).unwrap();
    let out = trace()
        .arg(&scene)
        .args([
            "-o",
            dir.join("out.png").to_str().unwrap(),
            "--width",
            "8",
            "--height",
            "6",
        ])
        .output()
        .expect("runs");
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(stderr(&out).contains("naïve"), "{}", stderr(&out));
    // A word that starts with a blank of two bytes (U+00A0, Latin-1 0xA0) is named, not a
    // panic (found by the fuzzer).
    for text in [
        "sphere { 0, 1 pigment { r\u{a0}b 1 } }",
        "\u{a0}sphere { 0, 1 }",
    ] {
        let err = load_error(text).expect("an error");
        assert!(err.contains("hostile.rt:1:"), "{err}");
    }
}

#[test]
fn output_problems_are_found_before_rendering_and_name_the_output() {
    let dir = scratch("output");
    let out = trace()
        .arg(crate::root().join("examples/basic_spheres.rt"))
        .arg("-o")
        .arg(dir.join("missing/out.png"))
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(
        err.contains("missing/out.png") && !err.contains(".tmp"),
        "{err}"
    );
    // Before parsing: a broken scene still reports the output first.
    std::fs::write(dir.join("broken.rt"), "sphere {").unwrap();
    let out = trace()
        .arg(dir.join("broken.rt"))
        .arg("-o")
        .arg(dir.join("missing/x.exr"))
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
}

#[test]
fn compare_reports_a_nan_image_as_different() {
    let dir = scratch("nan");
    let mut film = trace::Film::new(4, 4);
    let clean = dir.join("clean.exr");
    film.write(&clean).unwrap();
    film.set(1, 1, [f32::NAN, 0.0, 0.0]);
    let nan = dir.join("nan.exr");
    film.write(&nan).unwrap();
    let out = trace()
        .arg("compare")
        .arg(&clean)
        .arg(&nan)
        .output()
        .expect("runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("max |diff| NaN"), "{stdout}");
    assert!(stdout.contains("NaN/inf    0 / 1"), "{stdout}");
}

/// An interrupt while the output is being written removes the temporary file. The write is
/// held open by a FIFO placed where the temporary file will be, so the signal lands in it.
#[cfg(unix)]
#[test]
fn an_interrupted_write_leaves_no_temporary_file() {
    let dir = scratch("interrupt");
    let out = dir.join("img.png");
    std::fs::write(&out, b"previous").unwrap();
    // A scene that spends about half a second evaluating before it renders, so the FIFO is
    // surely in place before the write (with a fast scene, a loaded machine could let the
    // render finish before mkfifo ran: the run then succeeded and the test failed).
    let scene = dir.join("slow.rt");
    std::fs::write(
        &scene,
        "#declare I = 0;\n#while (I < 1000000) #declare I = I + 1; #end\n\
         camera { location -3*z look_at 0 }\nsphere { 0, 1 pigment { rgb 1 } }\n",
    )
    .unwrap();
    for signal in ["INT", "TERM"] {
        let mut child = trace()
            .arg(&scene)
            .arg("-o")
            .arg(&out)
            .args(["--width", "160", "--height", "120", "--aa", "0", "--quiet"])
            .spawn()
            .expect("runs");
        // (The render goes to a scratch file beside the output, written through its own
        // temporary file.)
        let tmp = dir.join(format!("..img.png.{0}.partial.png.{0}.tmp", child.id()));
        let made = Command::new("mkfifo").arg(&tmp).status().expect("mkfifo");
        assert!(made.success());
        // The writer blocks opening the FIFO; wait until the render is done and it does.
        std::thread::sleep(std::time::Duration::from_millis(300));
        let mut waited = 0;
        while child.try_wait().unwrap().is_none() && waited < 1200 {
            if std::fs::read_to_string(format!("/proc/{}/wchan", child.id()))
                .is_ok_and(|w| w.contains("wait_for_partner"))
            {
                break;
            }
            std::thread::sleep(std::time::Duration::from_millis(100));
            waited += 1;
        }
        // The first signal asks the render to stop and write what it finished; the writer
        // being stuck, a second one ends it at once.
        for _ in 0..2 {
            Command::new("kill")
                .args([format!("-{signal}"), child.id().to_string()])
                .status()
                .expect("kill");
            std::thread::sleep(std::time::Duration::from_millis(300));
        }
        let status = child.wait().unwrap();
        assert_eq!(status.code(), Some(130), "SIG{signal}");
        assert!(!tmp.exists(), "SIG{signal} left {}", tmp.display());
        assert_eq!(std::fs::read(&out).unwrap(), b"previous");
    }
}

#[test]
fn pixels_that_overflow_are_written_black_with_a_warning() {
    // POV-Ray's own pixels are NaN or infinite here; trace writes no such pixel.
    let dir = scratch("overflow");
    let text = format!(
        "{CAMERA}sphere {{ 0, 1 pigment {{ rgbf <0.9, 1, 0.9, 1e300> }} interior {{ ior 1.5 }} }}\n\
         plane {{ y, -1 pigment {{ checker rgb 1 rgb 0 }} }}\n"
    );
    let out = run_in(&dir, &text, &[]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("overflowed to NaN or infinity"),
        "{}",
        stderr(&out)
    );
    let film = trace::Film::read(&dir.join("out.exr")).unwrap();
    assert_eq!(film.non_finite_pixels(), 0);
}

#[test]
fn broken_nesting_parses_in_linear_time() {
    // Each of these once made the parser retry a failed rule at every level: time doubled
    // with each level (found by the fuzzer). 40 levels would take days; now milliseconds.
    let cases = [
        "#declare T = texture { pigment { rgb 1 }\n".repeat(40),
        format!("#macro M()\n{}", "#if (1) #while (0)\n".repeat(40)),
        "#declare P = pigment { #declare T = texture { finish { phong 1 }\n".repeat(40),
        "#declare Ball = sphere { 0, 1 texture { pig\n".repeat(40),
    ];
    for text in cases {
        let start = std::time::Instant::now();
        assert!(load_error(&text).is_some());
        assert!(start.elapsed().as_secs() < 20, "{:?}", start.elapsed());
    }
}
