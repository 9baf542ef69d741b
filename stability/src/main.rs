//! The stability report: runs the sweeps of `trace::stability` and writes docs/stability.md
//! (tables), docs/stability.csv (every count) and docs/stability.svg (failures against
//! distance per method).
//!
//! Run: `cargo run --release -p trace-stability [-- --rays N] [--out DIR]`.

use std::fmt::Write as _;
use std::time::Instant;
use trace_stability::{
    Count, OffsetMethod, SphereMethod, TriangleMethod, black_pixels, box_grid_failures,
    contact_shadow, ellipsoid_normals, far_shape, far_sphere, far_torus, glass_sphere_nan, grazing,
    grazing_shape, grid_leaks, media_slab, mesh_leaks, pane_scene, pane_stack, s11_shapes,
    s12_shapes, scale_invariance, sphere_acne, thin_wall, thread_determinism,
};

const RADII: [f64; 3] = [1e-3, 1.0, 1e3];
const DISTANCES: [f64; 6] = [0.0, 1e1, 1e2, 1e3, 1e4, 1e5];
const FAR: [f64; 9] = [1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9];
const SCALES: [f64; 3] = [1e-3, 1.0, 1e3];
const SHIFTS: [f64; 3] = [0.0, 1e3, 1e5];
const TORUS_DISTANCES: [f64; 6] = [3.0, 30.0, 300.0, 3e3, 3e4, 3e5];
const SHAPE_DISTANCES: [f64; 6] = [4.5, 45.0, 450.0, 4.5e3, 4.5e4, 4.5e5];
const GRAZING_ANGLES: [f64; 6] = [1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6];
const SCENE_SCALES: [f64; 5] = [1e-3, 1e-2, 1.0, 1e2, 1e3];
const SCENE_SHIFTS: [f64; 3] = [0.0, 1e3, 1e5];
const PANES: [u32; 6] = [1, 2, 3, 4, 8, 12];
const MEDIA_ANGLES: [f64; 5] = [90.0, 10.0, 1.0, 0.1, 0.01];
const MEDIA_SHIFTS: [f64; 4] = [0.0, 1e3, 1e5, 1e6];

/// One measured row: experiment, method, parameters, failures, rays, nanoseconds per ray.
struct Row {
    experiment: &'static str,
    counter: &'static str,
    method: &'static str,
    a: f64,
    b: f64,
    count: Count,
    ns_per_ray: f64,
}

fn timed(f: impl FnOnce() -> Count) -> (Count, f64) {
    let start = Instant::now();
    let c = f();
    (c, start.elapsed().as_nanos() as f64 / c.rays.max(1) as f64)
}

/// Runs the stability suite (docs/stability.md) and writes its report.
#[derive(clap::Parser, Debug)]
#[command(
    version,
    about = "Runs trace's numerical stability suite and writes docs/stability.md"
)]
struct Args {
    /// Rays per cell (S4 uses a quarter).
    #[arg(long, default_value_t = 20_000)]
    rays: u64,
    /// Folder to write stability.md into (default: the repository's docs/).
    #[arg(long)]
    out: Option<String>,
}

fn main() {
    let args = <Args as clap::Parser>::parse();
    let rays = args.rays.max(1);
    let out_dir = args
        .out
        .unwrap_or_else(|| concat!(env!("CARGO_MANIFEST_DIR"), "/../docs").to_string());
    let mut rows = Vec::new();

    for m in OffsetMethod::ALL {
        for r in RADII {
            for d in DISTANCES {
                let start = Instant::now();
                let a = sphere_acne(m, r, d, rays);
                let ns = start.elapsed().as_nanos() as f64 / rays as f64;
                for (counter, count) in [("acne", a.acne), ("leaks", a.leaks)] {
                    rows.push(Row {
                        experiment: "S1",
                        counter,
                        method: m.label(),
                        a: r,
                        b: d,
                        count,
                        ns_per_ray: ns,
                    });
                }
            }
        }
    }
    eprintln!("S1 done");
    for m in OffsetMethod::ALL {
        for side in RADII {
            let start = Instant::now();
            let (gaps, acne) = contact_shadow(m, side, rays / 4);
            let ns = start.elapsed().as_nanos() as f64 / (2 * gaps.rays.max(1)) as f64;
            let wall = thin_wall(m, side, rays / 4);
            for (counter, count) in [("gap", gaps), ("acne", acne), ("wall leak", wall)] {
                rows.push(Row {
                    experiment: "S2",
                    counter,
                    method: m.label(),
                    a: side,
                    b: 0.0,
                    count,
                    ns_per_ray: ns,
                });
            }
        }
    }
    eprintln!("S2 done");
    for m in SphereMethod::ALL {
        for d in FAR {
            let (count, ns) = timed(|| far_sphere(m, d, rays));
            rows.push(Row {
                experiment: "S3",
                counter: "misclassified",
                method: m.label(),
                a: 1.0,
                b: d,
                count,
                ns_per_ray: ns,
            });
        }
    }
    eprintln!("S3 done");
    for m in TriangleMethod::ALL {
        for s in SCALES {
            for t in SHIFTS {
                let (count, ns) = timed(|| mesh_leaks(m, s, t, rays / 4));
                rows.push(Row {
                    experiment: "S4",
                    counter: "leaks",
                    method: m.label(),
                    a: s,
                    b: t,
                    count,
                    ns_per_ray: ns,
                });
            }
        }
    }
    eprintln!("S4 done");
    for (label, shift) in [
        ("trace (origin moved to the bounding sphere)", true),
        ("quartic at the ray origin", false),
    ] {
        for d in TORUS_DISTANCES {
            let (count, ns) = timed(|| far_torus(shift, d, rays / 4));
            rows.push(Row {
                experiment: "S6",
                counter: "wrong",
                method: label,
                a: 1.0,
                b: d,
                count,
                ns_per_ray: ns,
            });
        }
    }
    eprintln!("S6 done");
    // S11 and S12: each shape against each distance or angle.
    let mut shape_rows =
        |experiment: &'static str,
         counter: &'static str,
         shapes: Vec<(&'static str, trace::geometry::Shape)>,
         values: &[f64],
         run: fn(&trace::geometry::Shape, f64, u64) -> trace_stability::Count| {
            for (label, shape) in shapes {
                for &b in values {
                    let (count, ns) = timed(|| run(&shape, b, rays / 4));
                    rows.push(Row {
                        experiment,
                        counter,
                        method: label,
                        a: 1.5,
                        b,
                        count,
                        ns_per_ray: ns,
                    });
                }
            }
        };
    shape_rows("S11", "wrong", s11_shapes(), &SHAPE_DISTANCES, far_shape);
    eprintln!("S11 done");
    shape_rows("S12", "odd", s12_shapes(), &GRAZING_ANGLES, grazing_shape);
    eprintln!("S12 done");
    for angle in MEDIA_ANGLES {
        for shift in MEDIA_SHIFTS {
            let (count, ns) = timed(|| media_slab(angle, shift, 64, 64));
            rows.push(Row {
                experiment: "S13",
                counter: "wrong",
                method: "trace",
                a: angle,
                b: shift,
                count,
                ns_per_ray: ns,
            });
        }
    }
    eprintln!("S13 done");
    for k in SCENE_SCALES {
        for t in SCENE_SHIFTS {
            let (count, ns) = timed(|| scale_invariance(k, t, 160, 120));
            rows.push(Row {
                experiment: "S7",
                counter: "pixels",
                method: "trace",
                a: k,
                b: t,
                count,
                ns_per_ray: ns,
            });
        }
    }
    if let Some(dir) = povray_dir() {
        let reference = povray_render(&dir, &trace_stability::scale_scene(1.0, 0.0), 160, 120);
        for k in SCENE_SCALES {
            for t in SCENE_SHIFTS {
                let start = Instant::now();
                let test = povray_render(&dir, &trace_stability::scale_scene(k, t), 160, 120);
                let mut count = Count::default();
                for (a, b) in reference.chunks(3).zip(test.chunks(3)) {
                    count.rays += 1;
                    count.failures += u64::from(a.iter().zip(b).any(|(x, y)| x.abs_diff(*y) > 2));
                }
                rows.push(Row {
                    experiment: "S7",
                    counter: "pixels",
                    method: "POV-Ray 3.7",
                    a: k,
                    b: t,
                    count,
                    ns_per_ray: start.elapsed().as_nanos() as f64 / count.rays as f64,
                });
            }
        }
    }
    eprintln!("S7 done");
    let start = Instant::now();
    let room = grazing(256, 192);
    let ns = start.elapsed().as_nanos() as f64 / room[0].rays as f64;
    for (counter, count) in ["NaN pixels", "background pixels", "BVH ≠ brute force"]
        .into_iter()
        .zip(room)
    {
        rows.push(Row {
            experiment: "S5",
            counter,
            method: "trace",
            a: 256.0,
            b: 192.0,
            count,
            ns_per_ray: ns,
        });
    }
    for offset in [0.0, 1e3, 1e5] {
        for (as_mesh, structure) in [(true, "mesh BVH"), (false, "top-level BVH")] {
            let (count, ns) = timed(|| grid_leaks(offset, as_mesh));
            rows.push(Row {
                experiment: "S5",
                counter: Box::leak(
                    format!("grid background pixels, {structure}, offset {offset:e}")
                        .into_boxed_str(),
                ),
                method: "trace",
                a: offset,
                b: 17.0,
                count,
                ns_per_ray: ns,
            });
        }
        let start = Instant::now();
        let counts = box_grid_failures(offset);
        let ns = start.elapsed().as_nanos() as f64 / counts[0].rays as f64;
        for (what, count) in ["background", "dark"].into_iter().zip(counts) {
            rows.push(Row {
                experiment: "S5",
                counter: Box::leak(
                    format!("box grid {what} pixels, offset {offset:e}").into_boxed_str(),
                ),
                method: "trace",
                a: offset,
                b: 17.0,
                count,
                ns_per_ray: ns,
            });
        }
    }
    let (count, ns) = timed(|| ellipsoid_normals(rays));
    rows.push(Row {
        experiment: "S8",
        counter: "normal off by > 0.01°",
        method: "trace",
        a: 4.0,
        b: 1.0,
        count,
        ns_per_ray: ns,
    });
    let (count, ns) = timed(|| thread_determinism(160, 120));
    rows.push(Row {
        experiment: "S10",
        counter: "pixels differing from 1 thread",
        method: "trace",
        a: 1.0,
        b: 3.0,
        count,
        ns_per_ray: ns,
    });
    eprintln!("S5, S8, S10 done");
    let (count, ns) = timed(|| glass_sphere_nan(160, 120));
    rows.push(Row {
        experiment: "S9a",
        counter: "NaN pixels",
        method: "trace",
        a: 1.5,
        b: 0.0,
        count,
        ns_per_ray: ns,
    });
    let pov = povray_dir();
    for n in PANES {
        for (label, level) in [
            ("trace, max_trace_level 5 (POV-Ray's default)", None),
            ("trace, max_trace_level 20", Some(20)),
        ] {
            let start = Instant::now();
            let (count, cut) = pane_stack(n, level, 80, 60);
            let _ = cut;
            rows.push(Row {
                experiment: "S9c",
                counter: "black pixels",
                method: label,
                a: f64::from(n),
                b: 0.0,
                count,
                ns_per_ray: start.elapsed().as_nanos() as f64 / count.rays as f64,
            });
        }
        if let Some(dir) = &pov {
            let start = Instant::now();
            let count = black_pixels(&povray_render(dir, &pane_scene(n, None), 80, 60));
            rows.push(Row {
                experiment: "S9c",
                counter: "black pixels",
                method: "POV-Ray 3.7, default",
                a: f64::from(n),
                b: 0.0,
                count,
                ns_per_ray: start.elapsed().as_nanos() as f64 / count.rays as f64,
            });
        }
    }
    eprintln!("S9 done");

    std::fs::create_dir_all(&out_dir).expect("output folder");
    let path = |name: &str| std::path::Path::new(&out_dir).join(name);
    std::fs::write(path("stability.csv"), csv(&rows)).expect("write csv");
    std::fs::write(path("stability.md"), report(&rows, rays)).expect("write report");
    std::fs::write(path("stability.svg"), chart(&rows)).expect("write chart");
    eprintln!("wrote {out_dir}/stability.md, .csv, .svg");
}

/// A scratch folder for POV-Ray's renders, if `povray` is installed.
fn povray_dir() -> Option<std::path::PathBuf> {
    let found = std::process::Command::new("povray")
        .arg("--version")
        .output()
        .is_ok();
    if !found {
        eprintln!("povray not found: S7 without POV-Ray's column");
        return None;
    }
    let dir = std::env::temp_dir().join(format!("trace-stability-{}", std::process::id()));
    std::fs::create_dir_all(&dir).ok()?;
    Some(dir)
}

/// POV-Ray's render of a suite scene (no anti-aliasing) as sRGB bytes.
fn povray_render(dir: &std::path::Path, text: &str, width: u32, height: u32) -> Vec<u8> {
    let scene = dir.join("suite.pov");
    let out = dir.join("suite.exr");
    std::fs::write(&scene, text).expect("write scene");
    let status = std::process::Command::new("povray")
        .arg(format!("+I{}", scene.display()))
        .arg(format!("+O{}", out.display()))
        .args([
            "+FE",
            &format!("+W{width}"),
            &format!("+H{height}"),
            "-D",
            "-GA",
            "-A",
        ])
        .output()
        .expect("povray runs");
    assert!(status.status.success(), "povray failed on:\n{text}");
    trace::Film::read(&out).expect("POV-Ray's image").to_srgb8()
}

fn csv(rows: &[Row]) -> String {
    let mut s =
        String::from("experiment,counter,method,param_a,param_b,failures,rays,ns_per_ray\n");
    for r in rows {
        let _ = writeln!(
            s,
            "{},{},\"{}\",{},{},{},{},{:.1}",
            r.experiment,
            r.counter,
            r.method,
            r.a,
            r.b,
            r.count.failures,
            r.count.rays,
            r.ns_per_ray
        );
    }
    s
}

fn pct(c: Count) -> String {
    if c.failures == 0 {
        "0".into()
    } else {
        format!("**{:.3} %**", 100.0 * c.rate())
    }
}

/// A table of one experiment's counter: a row per method and first parameter, a column per
/// second parameter.
fn table(
    rows: &[Row],
    experiment: &str,
    counter: &str,
    a_name: &str,
    b_name: &str,
    b_values: &[f64],
) -> String {
    let mut s = format!("| method | {a_name} |");
    for b in b_values {
        if b_name.is_empty() {
            s.push_str(" failures |");
        } else {
            let _ = write!(s, " {b_name} = {b:e} |");
        }
    }
    s.push_str(" ns/ray |\n|---|---:|");
    s.push_str(&"---:|".repeat(b_values.len() + 1));
    s.push('\n');
    let mut keys: Vec<(&str, f64)> = Vec::new();
    for r in rows
        .iter()
        .filter(|r| r.experiment == experiment && r.counter == counter)
    {
        if !keys.contains(&(r.method, r.a)) {
            keys.push((r.method, r.a));
        }
    }
    for (method, a) in keys {
        let _ = write!(s, "| {method} | {a:e} |");
        let mut ns = 0.0;
        for b in b_values {
            if let Some(r) = rows.iter().find(|r| {
                r.experiment == experiment
                    && r.counter == counter
                    && r.method == method
                    && r.a == a
                    && r.b == *b
            }) {
                let _ = write!(s, " {} |", pct(r.count));
                ns += r.ns_per_ray / b_values.len() as f64;
            }
        }
        let _ = writeln!(s, " {ns:.0} |");
    }
    s
}

fn report(rows: &[Row], rays: u64) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# Numerical stability: where methods fail\n\n\
         Made by `cargo run --release -p trace-stability` ({rays} rays per cell; S4 uses a quarter).\n\
         Each experiment builds its geometry in code and knows every ray's right answer\n\
         (`stability/src/lib.rs`); a cell is the share of wrong answers, **bold** where not zero.\n\
         trace's own method is the first row of each table; the others are the textbook methods\n\
         it replaced, kept in the suite to show that the counters find failures where the\n\
         literature says they happen (acne, leaks, cracks, far from the origin, grazing rays). `ns/ray` is the cost of the\n\
         whole experiment per ray, on one thread: compare methods within a table.\n\n\
         Covered so far: S1 (acne and leaks of shadow rays), S2 (contact shadows), S3 (far\n\
         small spheres), S4 (leaks through mesh seams), S5 (axis-aligned grazing rays), S6 (the\n\
         torus far away), S7 (scale and translation invariance of a whole render), S8 (normals\n\
         under non-uniform scale), S9 (total internal reflection, stacked glass), S10\n\
         (determinism across thread counts), S11 (the spline, blob and superellipsoid shapes far away), S12 (grazing lines on them),\n\
         S13 (participating media far away and at grazing angles).\n\
         Not yet: S9b (nested media with coincident surfaces: trace follows POV-Ray's interior\n\
         rules, which have no priorities, on purpose).\n\
         POV-Ray renders the S7 and S9c scene files too (when it is installed).\n"
    );
    let _ = writeln!(
        s,
        "## S1: shadow acne and leaks (sphere of radius R, centre at distance D)\n\n\
         Camera rays hit the sphere; a shadow ray leaves each hit towards a random light.\n\
         On the lit side any hit on the sphere is acne; on the unlit side the ray must cross\n\
         the sphere, and a miss is a leak. The sphere drops a root within its own rounding\n\
         error of zero (the surface a ray starts on), so even no offset (`none`) gives no acne\n\
         (before that test, 35–50 %); the offset still guards the other shapes.\n\n### Acne\n"
    );
    s += &table(rows, "S1", "acne", "R", "D", &DISTANCES);
    s += "\n### Leaks\n\n";
    s += &table(rows, "S1", "leaks", "R", "D", &DISTANCES);
    let _ = writeln!(
        s,
        "\n## S2: contact shadows (a cube of side s on a plane, light at a grazing angle)\n\n\
         Floor points at distance δ (1e-9 s to 4.9 s) from the cube, through the renderer's own\n\
         shadow test: on the shadow side a ray that gets through is a gap between the cube and\n\
         its shadow; on the lit side a blocked ray is acne.\n"
    );
    s += "### Gaps\n\n";
    s += &table(rows, "S2", "gap", "s", "", &[0.0]);
    s += "\n### Acne\n\n";
    s += &table(rows, "S2", "acne", "s", "", &[0.0]);
    s += "\n### Thin wall (1e-3 s thick) between the floor and the light: shadow rays let through\n\n";
    s += &table(rows, "S2", "wall leak", "s", "", &[0.0]);
    let _ = writeln!(
        s,
        "\n## S3: a small sphere far away (unit sphere at distance D)\n\n\
         Rays aimed at random points within 1.5 radii of the centre; a wrong hit/miss answer\n\
         counts (rays within 0.1 % of tangency are skipped).\n"
    );
    s += &table(rows, "S3", "misclassified", "R", "D", &FAR);
    let _ = writeln!(
        s,
        "\n## S4: leaks through a closed mesh (integer cube, scaled by S, moved by T)\n\n\
         Rays from random outside points aimed exactly at the mesh's vertices and edge\n\
         midpoints (shared by two to six triangles); a ray that meets no triangle leaks.\n"
    );
    s += &table(rows, "S4", "leaks", "S", "T", &SHIFTS);
    let _ = writeln!(
        s,
        "\n## S6: the torus far away (R = 1, r = 0.25, seen from distance D)\n\n\
         Each ray's line is fixed near the torus; the answer from 3 bounding radii away is the\n\
         reference, and the same line from D away must give the same hit or miss and the same\n\
         point within 1e-6·r (lines within 1e-3 of tangency are skipped).\n"
    );
    s += &table(rows, "S6", "wrong", "R", "D", &TORUS_DISTANCES);
    let _ = writeln!(
        s,
        "\n## S11: the spline, blob and superellipsoid shapes far away (within radius B = 1.5)\n\n\
         As S6, for a cubic prism, a quadratic lathe, a sor, a blob of two spheres and a cylinder,\n\
         a superellipsoid <0.2, 0.2> and a B-spline sphere sweep: the same line seen from 4.5 and from D away must give\n\
         the same hit or miss and the same point within 1e-6. Their equations are formed about\n\
         the ray's point nearest the shape: formed at the ray's origin, as POV-Ray forms them,\n\
         the blob got 25 % of the lines wrong from 450 away, the sor 4 % from 4500 and the lathe\n\
         3 % from 45000 (this experiment found it). The sphere sweep's equation is formed about\n\
         each segment's middle.\n"
    );
    s += &table(rows, "S11", "wrong", "B", "D", &SHAPE_DISTANCES);
    let _ = writeln!(
        s,
        "\n## S12: grazing lines on the closed spline, blob and superellipsoid shapes (radius B = 1.5)\n\n\
         Lines that meet the surface at a random point at angle α to it (a tangent tilted by α\n\
         into the shape), from outside to outside: a closed surface is crossed an even number\n\
         of times, so an odd count (one crossing of a close pair found and its partner lost,\n\
         which breaks the inside/outside bookkeeping of glass) or a NaN is a failure. Losing\n\
         both crossings of a pair (a missed sliver) is not counted. The superellipsoid's and the\n\
         sphere sweep's failures are POV-Ray's methods, which trace follows to draw what POV-Ray\n\
         draws: between two of its nine planes a superellipsoid piece whose ends are both\n\
         outside is probed for one crossing only, so a grazing pair inside one piece loses its\n\
         second crossing; a cubic sweep takes both crossings of the sphere touching the tube,\n\
         and POV-Ray's count of entries and exits, which assumes the first crossing enters one\n\
         part only, then keeps the sphere's inner crossing where the line leaves the tube\n\
         through an end disc. Both only matter where a ray goes on inside (glass): the first\n\
         crossing is right. The lathe's own failures (0.3 % at 1e-6) are pairs of roots of its\n\
         equation in the spline parameter closer than the root finder separates.\n"
    );
    s += &table(rows, "S12", "odd", "B", "α", &GRAZING_ANGLES);
    let _ = writeln!(
        s,
        "\n## S7: one scene at every scale and place (scale k, moved by T along (1, 1, 1))\n\n\
         Spheres, a box, a torus, a cylinder and a mesh on a checkered slab, with shadows and a\n\
         mirror; camera and light transformed with the scene. A cell is the share of pixels\n\
         (160×120, no anti-aliasing) that differ by more than 2/255 from the same renderer's\n\
         k = 1, T = 0 render. POV-Ray renders the same scene files (when it is installed).\n"
    );
    s += &table(rows, "S7", "pixels", "k", "T", &SCENE_SHIFTS);
    let _ = writeln!(
        s,
        "\n## S13: participating media far away and at grazing angles\n\n\
         A slab of absorbing media 0.1 thick (a hollow box with a clear surface) seen at angle α\n\
         to its plane by an orthographic camera, the whole moved by T along (1, 1, 1); a cell is\n\
         the share of pixels (64×64, no anti-aliasing) whose transmittance is off e^(−0.1/sin α)\n\
         by more than 1e-4 of it: a ray that skips a face, starts its medium late, or enters and\n\
         never leaves is far off. At α = 0.01° a ray runs 573 units inside the medium.\n"
    );
    s += &table(rows, "S13", "wrong", "α", "T", &MEDIA_SHIFTS);
    let _ = writeln!(
        s,
        "\n## S9: glass\n\n\
         S9c: N clear glass panes (ior 1.5) in front of a self-lit checkerboard, 80×60; a cell is\n\
         the share of black pixels. Each pane costs two trace levels, so with POV-Ray's default\n\
         `max_trace_level 5` three panes already turn the picture black, in POV-Ray and (on\n\
         purpose, to render what POV-Ray renders) in trace; `--stats` reports the rays cut\n\
         there (\"Cut at max_trace_level\"). Raising the limit removes the black.\n"
    );
    s += &table(rows, "S9c", "black pixels", "panes", "", &[0.0]);
    let _ = writeln!(
        s,
        "\nS9a: a glass sphere (ior 1.5, Fresnel reflection) seen whole in a white world, with\n\
         total internal reflection inside: {} NaN or infinite pixels of {}.",
        rows.iter()
            .find(|r| r.experiment == "S9a")
            .map_or(0, |r| r.count.failures),
        rows.iter()
            .find(|r| r.experiment == "S9a")
            .map_or(0, |r| r.count.rays)
    );
    let _ = writeln!(
        s,
        "\n## S5, S8, S10: grazing rays, non-uniform scale, threads\n\n\
         S5: a closed room of boxes with faces on integer planes, seen by an orthographic\n\
         camera whose pixel centres lie on quarter units (rays run exactly along faces, with\n\
         zero direction components), 256×192; and a flat 10×10 grid of unit cells seen straight\n\
         on at 17×17, pixel centres on its vertices and edges, as one mesh2 and as 200\n\
         triangles, at offsets 0, 1e3 and 1e5 from the origin. S8: random hits on a sphere\n\
         scaled (4, 1, 1);\n\
         the shading normal against the ellipsoid's exact normal. S10: the S7 scene rendered\n\
         with 1, 2 and 3 threads, compared bit for bit.\n\n\
         | scene | counter | failures | of |\n|---|---|---:|---:|"
    );
    for r in rows
        .iter()
        .filter(|r| matches!(r.experiment, "S5" | "S8" | "S10"))
    {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} |",
            r.experiment, r.counter, r.count.failures, r.count.rays
        );
    }
    s += "\n![failures against distance](stability.svg)\n";
    s
}

/// Failure rate (log, with 0 drawn at the bottom) against distance (log), for S1 (acne and
/// leaks over all radii) and S3, one line per method.
fn chart(rows: &[Row]) -> String {
    let (w, h) = (900.0, 380.0);
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    );
    let colours = ["#000000", "#d62728", "#1f77b4", "#2ca02c", "#9467bd"];
    let panels: [(&str, &str, f64, &[f64]); 2] = [
        (
            "S1: acne + leaks, R = 1e-3, 1, 1e3",
            "S1",
            0.0,
            &DISTANCES[1..],
        ),
        ("S3: misclassified, unit sphere", "S3", 450.0, &FAR),
    ];
    for (title, experiment, x0, xs) in panels {
        let (left, top, pw, ph) = (x0 + 55.0, 30.0, 300.0, 280.0);
        let (lx0, lx1) = (xs[0].log10(), xs[xs.len() - 1].log10());
        let sx = |d: f64| left + (d.log10() - lx0) / (lx1 - lx0) * pw;
        // Rates from 1e-5 (and 0, drawn at the bottom) to 1.
        let sy = |r: f64| {
            let v = if r <= 0.0 { -5.0 } else { r.log10().max(-5.0) };
            top + (-v) / 5.0 * ph
        };
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"18\" text-anchor=\"middle\" font-size=\"13\">{title}</text>",
            left + pw / 2.0
        );
        let _ = writeln!(
            s,
            "<rect x=\"{left}\" y=\"{top}\" width=\"{pw}\" height=\"{ph}\" fill=\"none\" stroke=\"#444\"/>"
        );
        for e in 0..=5 {
            let y = top + e as f64 / 5.0 * ph;
            let label = if e == 5 {
                "0".to_string()
            } else {
                format!("1e-{e}")
            };
            let _ = writeln!(
                s,
                "<line x1=\"{left}\" y1=\"{y}\" x2=\"{}\" y2=\"{y}\" stroke=\"#eee\"/><text x=\"{}\" y=\"{}\" text-anchor=\"end\">{label}</text>",
                left + pw,
                left - 4.0,
                y + 4.0
            );
        }
        for d in xs {
            let x = sx(*d);
            let _ = writeln!(
                s,
                "<text x=\"{x}\" y=\"{}\" text-anchor=\"middle\">{d:e}</text>",
                top + ph + 14.0
            );
        }
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">distance from the origin / ray origin</text>",
            left + pw / 2.0,
            top + ph + 30.0
        );
        let mut methods: Vec<&str> = Vec::new();
        for r in rows.iter().filter(|r| r.experiment == experiment) {
            if !methods.contains(&r.method) {
                methods.push(r.method);
            }
        }
        for (k, method) in methods.iter().enumerate() {
            let points: Vec<(f64, f64)> = xs
                .iter()
                .map(|d| {
                    let total = rows
                        .iter()
                        .filter(|r| r.experiment == experiment && r.method == *method && r.b == *d)
                        .fold(Count::default(), |acc, r| Count {
                            failures: acc.failures + r.count.failures,
                            rays: acc.rays + r.count.rays,
                        });
                    (sx(*d), sy(total.rate()))
                })
                .collect();
            let colour = colours[k % colours.len()];
            let dash = if k == 0 { "" } else { "5,3" };
            let path: Vec<String> = points
                .iter()
                .map(|(x, y)| format!("{x:.1},{y:.1}"))
                .collect();
            let _ = writeln!(
                s,
                "<polyline points=\"{}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"{}\" stroke-dasharray=\"{dash}\"/>",
                path.join(" "),
                if k == 0 { 3 } else { 2 }
            );
            let ly = top + 14.0 + k as f64 * 14.0;
            let _ = writeln!(
                s,
                "<text x=\"{}\" y=\"{ly}\" fill=\"{colour}\">{method}</text>",
                left + 6.0
            );
        }
    }
    s.push_str("</svg>\n");
    s
}
