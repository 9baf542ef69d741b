//! POV-Ray's command line and what it leads to: switches, INI files, default output names,
//! regions and merging, alpha, AOV layers, animation frames, continuing a stopped render.

use std::path::{Path, PathBuf};
use std::process::Command;
use trace::film::Raster;

fn trace() -> Command {
    Command::new(env!("CARGO_BIN_EXE_trace"))
}

/// A fresh scratch folder, removed at the end of the test.
fn scratch(name: &str) -> crate::Scratch {
    crate::Scratch::new("povcli", name)
}

/// Runs trace in `dir` with `args`; panics with its stderr if it fails.
fn run(dir: &Path, args: &[&str]) -> String {
    let out = trace().current_dir(dir).args(args).output().expect("runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "trace {args:?} failed:\n{stderr}");
    stderr
}

/// Runs trace expecting failure; returns stderr.
fn fails(dir: &Path, args: &[&str]) -> String {
    let out = trace().current_dir(dir).args(args).output().expect("runs");
    assert!(!out.status.success(), "trace {args:?} should fail");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

const SCENE: &str = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n\
    camera { location <0, 1, -4> look_at <0, 0.5, 0> }\nlight_source { <-3, 5, -4> rgb 1 }\n\
    plane { y, 0 pigment { checker rgb 1 rgb 0.3 } finish { reflection 0.2 } }\n\
    sphere { <0, 0.7, 0>, 0.7 pigment { rgbf <1, 0.6, 0.4, 0.6> } interior { ior 1.5 } }\n\
    sphere { <1.3, 0.4, 0.8>, 0.4 pigment { rgb <0.2, 0.5, 1> } }\n";

fn bytes(path: PathBuf) -> Vec<u8> {
    std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn povray_switches_and_ini_files_read_as_trace_options() {
    let dir = scratch("switches");
    std::fs::write(dir.join("s.pov"), SCENE).unwrap();
    run(
        &dir,
        &[
            "s.pov", "--width", "48", "--height", "36", "--aa", "off", "-o", "own.png", "-q",
        ],
    );
    // The same settings as POV-Ray switches (any case); no +O: s.png beside the scene.
    run(&dir, &["s.pov", "+w48", "-H36", "-A0.1", "-D", "+V", "-q"]);
    assert_eq!(bytes(dir.join("own.png")), bytes(dir.join("s.png")));
    // An INI file with comments, a section and a switch; the lines before the first section
    // are read with any section.
    std::fs::write(
        dir.join("r.ini"),
        "; render settings\nInput_File_Name = s.pov\nOutput_File_Name=ini # a comment\n\
         Antialias=Off\n+W48\nHeight=36\n[Big]\nWidth=96\nheight=72\n",
    )
    .unwrap();
    run(&dir, &["r.ini", "-q"]);
    assert_eq!(bytes(dir.join("own.png")), bytes(dir.join("ini.png")));
    run(&dir, &["r.ini[big]", "+Obig", "-q"]);
    let big = Raster::read(&dir.join("big.png")).unwrap();
    assert_eq!((big.width, big.height), (96, 72));
    // Declare and +O without an extension.
    std::fs::write(
        dir.join("d.pov"),
        format!("{SCENE}sphere {{ <-1.3, 0.4, 0>, Size pigment {{ rgb 1 }} }}\n"),
    )
    .unwrap();
    run(
        &dir,
        &[
            "d.pov",
            "Declare=Size=0.3",
            "+W32",
            "+H24",
            "-A",
            "+Od",
            "-q",
        ],
    );
    assert!(dir.join("d.png").exists());
    let e = fails(&dir, &["s.pov", "+Z3"]);
    assert!(e.contains("unknown POV-Ray switch `+Z3`"), "{e}");
    let e = fails(&dir, &["s.pov", "Frobnicate=1"]);
    assert!(e.contains("unknown POV-Ray option `frobnicate`"), "{e}");
    let e = fails(&dir, &["s.pov", "+FT"]);
    assert!(
        e.contains("trace writes PNG (N), OpenEXR (E) and PPM (P)"),
        "{e}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn povray_exr_option_writes_half_floats_as_povray() {
    // +FE names an EXR as POV-Ray writes it (half floats); trace's own -o x.exr keeps 32-bit
    // floats unless --bits 16.
    let dir = scratch("fe");
    std::fs::write(dir.join("s.pov"), SCENE).unwrap();
    run(&dir, &["+Is.pov", "+FE", "+Opov", "+W40", "+H30", "-q"]);
    // (POV-Ray's bit depth does not change its EXR.)
    run(&dir, &["+Is.pov", "+FE8", "+Opov8", "+W40", "+H30", "-q"]);
    run(
        &dir,
        &[
            "s.pov", "-o", "own.exr", "--width", "40", "--height", "30", "-q",
        ],
    );
    let bits = |name: &str| Raster::read(&dir.join(name)).unwrap().layout.bits;
    assert_eq!(bits("pov.exr"), 16);
    assert_eq!(bits("pov8.exr"), 16);
    assert_eq!(bits("own.exr"), 32);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn regions_merge_into_the_whole_image_byte_for_byte() {
    let dir = scratch("merge");
    std::fs::write(dir.join("s.pov"), SCENE).unwrap();
    let size = ["--width", "80", "--height", "70", "--aa", "0.1", "-q"];
    for (ext, extra) in [
        ("png", vec!["--alpha", "--bits", "16"]),
        (
            "exr",
            vec!["--alpha", "--aov", "depth,normal,albedo,object"],
        ),
        // (Half-float colour, 32-bit AOVs.)
        ("exr", vec!["--bits", "16", "--aov", "depth"]),
        ("ppm", vec![]),
    ] {
        let with = |args: &[&str]| -> Vec<String> {
            args.iter()
                .chain(&size)
                .chain(&extra)
                .map(|s| s.to_string())
                .collect()
        };
        let whole = format!("whole.{ext}");
        let a = with(&["s.pov", "-o", &format!("a.{ext}"), "--region", "0,0,80,33"]);
        let b = with(&[
            "s.pov",
            "-o",
            &format!("b.{ext}"),
            "+SC1",
            "+EC50",
            "+SR34",
            "+ER70",
        ]);
        let c = with(&[
            "s.pov",
            "-o",
            &format!("c.{ext}"),
            "--region",
            "50,33,80,70",
        ]);
        for args in [with(&["s.pov", "-o", &whole]), a, b, c] {
            let args: Vec<&str> = args.iter().map(String::as_str).collect();
            run(&dir, &args);
        }
        let part = Raster::read(&dir.join(format!("b.{ext}")))
            .unwrap()
            .part()
            .expect("a part");
        assert_eq!(part.region.to_string(), "0,33,50,70");
        let (a, b, c) = (format!("a.{ext}"), format!("b.{ext}"), format!("c.{ext}"));
        run(&dir, &["merge", "-o", &format!("m.{ext}"), &c, &a, &b]);
        assert!(
            bytes(dir.join(&whole)) == bytes(dir.join(format!("m.{ext}"))),
            "{ext}"
        );
        // Two parts merge into a bigger part.
        run(&dir, &["merge", "-o", &format!("bc.{ext}"), &b, &c]);
        let bc = Raster::read(&dir.join(format!("bc.{ext}")))
            .unwrap()
            .part()
            .expect("a part");
        assert_eq!(bc.region.to_string(), "0,33,80,70");
        let e = fails(&dir, &["merge", "-o", &format!("x.{ext}"), &a, &b]);
        assert!(e.contains("leave gaps"), "{e}");
        let e = fails(&dir, &["merge", "-o", &format!("x.{ext}"), &a, &a]);
        assert!(e.contains("overlap"), "{e}");
    }
    // Parts of another scene do not merge.
    std::fs::write(dir.join("t.pov"), SCENE.replace("0.2, 0.5, 1", "1, 0, 0")).unwrap();
    run(
        &dir,
        &[
            "t.pov",
            "-o",
            "t.png",
            "--region",
            "0,33,80,70",
            "--width",
            "80",
            "--height",
            "70",
            "-q",
        ],
    );
    run(
        &dir,
        &[
            "s.pov",
            "-o",
            "s.png",
            "--region",
            "0,0,80,33",
            "--width",
            "80",
            "--height",
            "70",
            "-q",
        ],
    );
    let e = fails(&dir, &["merge", "-o", "x.png", "s.png", "t.png"]);
    assert!(e.contains("parts of different renders"), "{e}");
    let e = fails(
        &dir,
        &[
            "s.pov",
            "-o",
            "x.png",
            "--region",
            "0,0,90,10",
            "--width",
            "80",
            "--height",
            "70",
        ],
    );
    assert!(e.contains("not a rectangle inside the 80x70 image"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// On a terminal, a progress line; not with --quiet.
#[cfg(unix)]
#[test]
fn a_terminal_shows_progress() {
    let dir = scratch("progress");
    std::fs::write(
        dir.join("s.pov"),
        SCENE.replace("rgb 1 }\nplane", "rgb 1 area_light x, z, 6, 6 }\nplane"),
    )
    .unwrap();
    let command = format!(
        "{} s.pov -o p.png --width 200 --height 150 --aa 0 --threads 1",
        env!("CARGO_BIN_EXE_trace")
    );
    // `script` runs the command on a pseudo-terminal and copies what it shows.
    let Ok(out) = Command::new("script")
        .current_dir(&dir)
        .args(["-qec", &command, "/dev/null"])
        .output()
    else {
        eprintln!("no `script` here: skipped");
        return;
    };
    let shown = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{shown}");
    assert!(
        shown.contains("pixels), ") && shown.contains("rays/s"),
        "{shown}"
    );
    let quiet = Command::new("script")
        .current_dir(&dir)
        .args(["-qec", &format!("{command} --quiet"), "/dev/null"])
        .output()
        .unwrap();
    assert!(!String::from_utf8_lossy(&quiet.stdout).contains("rays/s"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// POV-Ray's +UA, pixel for pixel: a transparent default background, straight colour in PNG.
#[test]
fn alpha_is_povrays() {
    let dir = scratch("alpha");
    let scene = crate::root().join("tests/povray_cli/alpha.pov");
    let out = dir.join("alpha.png");
    run(
        &dir,
        &[
            scene.to_str().unwrap(),
            "+W64",
            "+H48",
            "-A",
            "+UA",
            "-o",
            out.to_str().unwrap(),
            "-q",
        ],
    );
    let ours = Raster::read(&out).unwrap();
    let povray = Raster::read(&crate::root().join("tests/povray_cli/alpha.povray.png")).unwrap();
    assert!(ours.layout.alpha);
    let mut worst = 0.0f32;
    let mut see_through = 0;
    for y in 0..48 {
        for x in 0..64 {
            for c in ["R", "G", "B", "A"] {
                let (a, b) = (
                    ours.sample(x, y, c).unwrap(),
                    povray.sample(x, y, c).unwrap(),
                );
                worst = worst.max((a - b).abs());
            }
            let a = ours.sample(x, y, "A").unwrap();
            see_through += usize::from(a > 0.0 && a < 1.0);
        }
    }
    assert!(worst <= 1.0 / 255.0, "largest difference {worst}");
    assert!(see_through > 100, "{see_through} pixels partly transparent");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn aov_layers_hold_what_the_centre_ray_meets() {
    let dir = scratch("aov");
    std::fs::write(
        dir.join("s.pov"),
        "camera { location <0, 0, -5> look_at 0 }\nlight_source { <5, 5, -5> rgb 1 }\n\
         plane { z, 3 pigment { rgb 0.5 } }\nsphere { 0, 1 pigment { rgb <0.25, 0.5, 1> } }\n",
    )
    .unwrap();
    run(
        &dir,
        &[
            "s.pov",
            "-o",
            "a.exr",
            "--width",
            "33",
            "--height",
            "33",
            "--aa",
            "off",
            "--aov",
            "depth,normal,albedo,object",
            "-q",
        ],
    );
    let a = Raster::read(&dir.join("a.exr")).unwrap();
    let at = |x, y, c| a.sample(x, y, c).unwrap();
    // The centre pixel's ray meets the sphere head on, 4 units away.
    assert!((at(16, 16, "Z") - 4.0).abs() < 1e-4);
    assert!((at(16, 16, "Ns.Z") + 1.0).abs() < 1e-4);
    assert_eq!(
        [
            at(16, 16, "Albedo.R"),
            at(16, 16, "Albedo.G"),
            at(16, 16, "Albedo.B")
        ],
        [0.25, 0.5, 1.0]
    );
    assert_eq!(at(16, 16, "ObjectID"), 2.0);
    // A corner's meets the plane behind.
    assert_eq!(at(0, 0, "ObjectID"), 1.0);
    assert!(at(0, 0, "Z") > 8.0);
    let e = fails(&dir, &["s.pov", "-o", "a.png", "--aov", "depth"]);
    assert!(e.contains("AOV layers need an EXR output"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Frames named and clocked as POV-Ray names and clocks them (its values in anim.pov).
#[test]
fn animation_frames_are_povrays() {
    let dir = scratch("anim");
    let scene = crate::root().join("tests/povray_cli/anim.pov");
    let scene = scene.to_str().unwrap();
    let out = run(
        &dir,
        &[
            scene,
            "+W16",
            "+H12",
            "-A",
            "+KFI1",
            "+KFF10",
            "+SF9",
            "+EF10",
            "+Oanim.png",
        ],
    );
    assert!(
        out.contains("F 9 c 0.888889 d 0.111111 on 1 if 1 ff 10 ic 0.000 fc 1.000"),
        "{out}"
    );
    assert!(
        out.contains("F 10 c 1.000000 d 0.111111 on 1 if 1 ff 10 ic 0.000 fc 1.000"),
        "{out}"
    );
    assert!(dir.join("anim09.png").exists() && dir.join("anim10.png").exists());
    assert!(!dir.join("anim08.png").exists());
    // The frames are POV-Ray's frames.
    run(
        &dir,
        &[
            scene,
            "+W64",
            "+H48",
            "-A",
            "+KFI1",
            "+KFF10",
            "+SF9",
            "+EF10",
            "+Oframe.png",
            "-q",
        ],
    );
    for n in ["09", "10"] {
        let ours = trace::Film::read(&dir.join(format!("frame{n}.png"))).unwrap();
        let theirs =
            trace::Film::read(&crate::root().join(format!("tests/povray_cli/anim.povray{n}.png")))
                .unwrap();
        let c = trace::film::compare(&theirs, &ours).unwrap();
        assert!(c.mean_flip < 0.001, "frame {n}: mean FLIP {}", c.mean_flip);
    }
    let out = run(
        &dir,
        &[
            scene, "+W16", "+H12", "-A", "+KFI1", "+KFF3", "+KC", "+SF3", "-o", "c.png",
        ],
    );
    assert!(
        out.contains("F 3 c 0.666667 d 0.333333 on 1 if 1 ff 4 ic 0.000 fc 1.000"),
        "{out}"
    );
    assert!(dir.join("c3.png").exists());
    // A frame rendered alone (as a farm renders it) is the frame of the whole animation.
    run(
        &dir,
        &[
            scene, "--width", "16", "--height", "12", "--frames", "1..3", "-o", "w.png", "-q",
        ],
    );
    run(
        &dir,
        &[
            scene, "--width", "16", "--height", "12", "--frames", "1..3", "--subset", "2..2", "-o",
            "s.png", "-q",
        ],
    );
    assert_eq!(bytes(dir.join("w2.png")), bytes(dir.join("s2.png")));
    // A still: every animation value 0.
    let out = run(&dir, &[scene, "+W16", "+H12", "-A", "-o", "still.png"]);
    assert!(
        out.contains("F 0 c 0.000000 d 0.000000 on 0 if 0 ff 0 ic 0.000 fc 0.000"),
        "{out}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--continue` renders what a part of the image (as a stopped render leaves it) lacks, and
/// the result is the uninterrupted render's file; a SIGINT stops a render and leaves such a
/// part (or nothing, if no row was finished).
#[cfg(unix)]
#[test]
fn a_stopped_render_continues_to_the_whole_image() {
    let dir = scratch("continue");
    std::fs::write(dir.join("s.pov"), SCENE).unwrap();
    let size = ["--width", "96", "--height", "80", "--aa", "0", "-q"];
    let with = |args: &[&'static str]| -> Vec<&'static str> {
        args.iter().chain(&size).copied().collect()
    };
    run(&dir, &with(&["s.pov", "-o", "whole.png"]));
    run(
        &dir,
        &with(&["s.pov", "-o", "out.png", "--region", "0,0,96,32"]),
    );
    run(&dir, &with(&["s.pov", "-o", "out.png", "--continue"]));
    assert_eq!(bytes(dir.join("whole.png")), bytes(dir.join("out.png")));
    let again = run(
        &dir,
        &[
            "s.pov",
            "-o",
            "out.png",
            "--continue",
            "--width",
            "96",
            "--height",
            "80",
            "--aa",
            "0",
        ],
    );
    assert!(again.contains("is complete"), "{again}");
    // Another scene's part is not continued.
    run(
        &dir,
        &with(&["s.pov", "-o", "other.png", "--region", "0,0,96,32", "+K0.5"]),
    );
    let e = fails(&dir, &with(&["s.pov", "-o", "other.png", "--continue"]));
    assert!(e.contains("part of another render"), "{e}");

    // A real interruption, at whatever row it comes (a slower scene: an area light).
    let slow = SCENE.replace("rgb 1 }\nplane", "rgb 1 area_light x, z, 8, 8 }\nplane");
    std::fs::write(dir.join("slow.pov"), slow).unwrap();
    let big = [
        "--width",
        "240",
        "--height",
        "180",
        "--aa",
        "0",
        "--threads",
        "1",
        "-q",
    ];
    let mut child = trace()
        .current_dir(&dir)
        .args(["slow.pov", "-o", "int.png"])
        .args(big)
        .spawn()
        .expect("runs");
    std::thread::sleep(std::time::Duration::from_millis(500));
    Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    let status = child.wait().unwrap();
    if status.code() == Some(130) {
        // The rows finished, from the top, as a part; or nothing if none was.
        if let Ok(part) = Raster::read(&dir.join("int.png")) {
            let region = part.part().expect("a part").region;
            assert_eq!((region.x0, region.y0, region.x1), (0, 0, 240));
            assert!(
                region.y1 > 0 && region.y1 < 180 && region.y1 % 32 == 0,
                "{region}"
            );
        }
    } else {
        assert!(status.success(), "{status:?}");
    }
    run(
        &dir,
        &[&["slow.pov", "-o", "int.png", "--continue"][..], &big].concat(),
    );
    run(
        &dir,
        &[&["slow.pov", "-o", "intwhole.png"][..], &big].concat(),
    );
    assert_eq!(
        bytes(dir.join("int.png")),
        bytes(dir.join("intwhole.png")),
        "status {status:?}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A 32-bit BMP's alpha, as POV-Ray reads it (the image crate ignores it), pixel for pixel.
#[test]
fn a_32_bit_bmp_has_povrays_alpha() {
    let dir = scratch("bmp");
    let folder = crate::root().join("tests/povray_cli");
    let out = dir.join("bmp.png");
    let out = out.to_str().unwrap();
    let scene = folder.join("bmp_alpha.pov");
    let status = trace()
        .current_dir(&folder)
        .args([scene.to_str().unwrap(), "+W8", "+H8", "-A", "-o", out, "-q"])
        .status()
        .expect("runs");
    assert!(status.success());
    let ours = Raster::read(Path::new(out)).unwrap();
    let povray = Raster::read(&folder.join("bmp_alpha.povray.png")).unwrap();
    for y in 0..8 {
        for x in 0..8 {
            for c in ["R", "G", "B"] {
                assert_eq!(
                    ours.sample(x, y, c),
                    povray.sample(x, y, c),
                    "({x}, {y}) {c}"
                );
            }
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Light through a transparent parametric surface is filtered at every crossing, as POV-Ray's
/// shadow walk meets them (the surface's search finds the nearest only): against POV-Ray's
/// render of tests/povray_cli/parametric_shadow.pov (mean FLIP 0.035 when only the first
/// crossing filtered).
#[test]
fn shadows_through_a_parametric_surface_match_povray() {
    let dir = scratch("parametric_shadow");
    let folder = crate::root().join("tests/povray_cli");
    let out = dir.join("p.exr");
    let scene = folder.join("parametric_shadow.pov");
    let status = trace()
        .args([
            scene.to_str().unwrap(),
            "+W64",
            "+H48",
            "-A",
            "-o",
            out.to_str().unwrap(),
            "-q",
        ])
        .status()
        .expect("runs");
    assert!(status.success());
    let ours = trace::Film::read(&out).unwrap();
    let povray = trace::Film::read(&folder.join("parametric_shadow.povray.exr")).unwrap();
    let c = trace::film::compare(&povray, &ours).unwrap();
    assert!(c.mean_flip <= 0.01, "mean FLIP {}", c.mean_flip);
    std::fs::remove_dir_all(&dir).unwrap();
}
