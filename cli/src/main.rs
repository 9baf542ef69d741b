//! The `trace` command line: render a scene, or compare two images.
//!
//! Exit codes: 0 success, 1 render or I/O failure, 2 bad scene or bad arguments.

use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::{Duration, Instant};
use trace::{Antialias, Error, LoadOptions, RenderOptions};

/// Counts memory against `--max-memory`, so running out ends with a message and exit 1.
#[global_allocator]
static ALLOCATOR: trace::memory::Limited = trace::memory::Limited;

/// Render POV-Ray 3.7 scenes (a CSG-free subset) with a Whitted ray tracer.
#[derive(Parser, Debug)]
#[command(
    name = "trace",
    version,
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true
)]
#[command(after_help = "Compare two images: trace compare REFERENCE TEST [--diff MAP.png]")]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    render: RenderArgs,
}

#[derive(Args, Debug)]
struct RenderArgs {
    /// Scene file (.rt or .pov).
    #[arg(required = true)]
    scene: Option<PathBuf>,
    /// Output image; the extension picks the format: .exr (linear float) or .png (8-bit sRGB).
    #[arg(short, long, required = true)]
    output: Option<PathBuf>,
    /// Image width in pixels.
    #[arg(long, default_value_t = 800, value_parser = clap::value_parser!(u32).range(1..=65536))]
    width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 600, value_parser = clap::value_parser!(u32).range(1..=65536))]
    height: u32,
    /// Anti-aliasing: `off` (one ray per pixel centre, POV-Ray -A) or a threshold (POV-Ray
    /// +A<threshold> -J; 0 supersamples every pixel).
    #[arg(long, default_value = "0.3", value_parser = parse_aa)]
    aa: AaSetting,
    /// Anti-aliasing depth, 1..=9 (POV-Ray +R): the grid size per axis for method 1, the
    /// number of levels for method 2.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=9))]
    aa_depth: u32,
    /// Anti-aliasing method (POV-Ray +AM): 1, a grid in pixels that differ from a neighbour;
    /// 2, corners shared between pixels, squares split where their corners differ.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=2))]
    aa_method: u32,
    /// Worker threads for parsing big files, building and rendering (default: one per core).
    /// The image is the same for any count.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Print nothing but errors and warnings.
    #[arg(short, long)]
    quiet: bool,
    /// Print render statistics (rays by kind, samples, time per phase).
    #[arg(long)]
    stats: bool,
    /// A folder to search for `#include` files, fonts and images, after the scene's own folder
    /// (repeatable). POV-Ray's standard include folder comes last by itself when installed
    /// (/usr/share/povray-3.7/include, or the folder POVRAY_INCLUDE names).
    #[arg(short = 'L', long = "include-path", value_name = "DIR")]
    include_path: Vec<PathBuf>,
    /// Most evaluation steps the scene may take (statements, loop passes, macro calls), all
    /// together: an endless loop stops here with an error.
    #[arg(long, default_value_t = trace::DEFAULT_MAX_STEPS, value_name = "N")]
    max_steps: u64,
    /// Most memory trace may use, e.g. 512M or 8G (default: the memory available at start).
    #[arg(long, value_name = "SIZE", value_parser = parse_memory)]
    max_memory: Option<usize>,
}

fn parse_memory(s: &str) -> Result<usize, String> {
    trace::memory::parse_size(s)
        .ok_or_else(|| format!("expected a size such as 512M or 8G, found `{s}`"))
}

#[derive(Clone, Copy, Debug)]
enum AaSetting {
    Off,
    Threshold(f64),
}

fn parse_aa(s: &str) -> Result<AaSetting, String> {
    if s.eq_ignore_ascii_case("off") {
        return Ok(AaSetting::Off);
    }
    match s.parse::<f64>() {
        Ok(t) if t >= 0.0 && t.is_finite() => Ok(AaSetting::Threshold(t)),
        _ => Err(format!("expected `off` or a threshold ≥ 0, found `{s}`")),
    }
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Compare a test image against a reference (EXR or PNG): prints mean FLIP and RMSE.
    #[cfg(feature = "flip")]
    Compare {
        /// Reference image.
        reference: PathBuf,
        /// Image to test.
        test: PathBuf,
        /// Write the FLIP error map here (PNG).
        #[arg(long)]
        diff: Option<PathBuf>,
    },
    /// Convert a mesh file (OBJ or PLY) to a POV-Ray include declaring it as a mesh2, so a
    /// scene using trace's `mesh_file` extension can be rendered by POV-Ray too.
    Convert {
        /// Mesh file (.obj or .ply).
        mesh: PathBuf,
        /// The include file to write.
        #[arg(short, long)]
        output: PathBuf,
        /// The declared name (default: from the file name, e.g. `Bunny` for bunny.obj).
        #[arg(long)]
        name: Option<String>,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    // An interrupted write leaves no temporary file behind.
    let _ = ctrlc::set_handler(|| {
        trace::output::interrupt();
        eprintln!("trace: interrupted");
        std::process::exit(130);
    });
    let result = match cli.command {
        #[cfg(feature = "flip")]
        Some(Command::Compare {
            reference,
            test,
            diff,
        }) => compare(&reference, &test, diff.as_deref()),
        Some(Command::Convert { mesh, output, name }) => convert(&mesh, &output, name),
        None => render(&cli.render),
    };
    match result {
        // (The work ended while an interrupt was being handled: the handler's code.)
        _ if trace::output::interrupted() => ExitCode::from(130),
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            eprintln!("{}", failure.message);
            ExitCode::from(failure.code)
        }
    }
}

/// An error message with the exit code it maps to.
struct Failure {
    message: String,
    code: u8,
}

impl From<Error> for Failure {
    fn from(e: Error) -> Failure {
        let code = match e {
            Error::Scene(_) => 2,
            Error::Read { .. } | Error::Threads(_) | Error::Image(_) => 1,
        };
        let message = match e {
            Error::Scene(_) => e.to_string(),
            _ => format!("error: {e}"),
        };
        Failure { message, code }
    }
}

fn usage(message: String) -> Failure {
    Failure {
        message: format!("error: {message}"),
        code: 2,
    }
}

fn render(args: &RenderArgs) -> Result<(), Failure> {
    let (Some(scene_path), Some(output)) = (&args.scene, &args.output) else {
        return Err(usage("a scene and -o OUTPUT are required".into()));
    };
    if trace::film::Format::of(output).is_none() {
        return Err(usage(format!(
            "{}: unknown output format (use .exr or .png)",
            output.display()
        )));
    }
    trace::output::check_writable(output).map_err(|e| Failure {
        message: format!("error: cannot write {}: {e}", output.display()),
        code: 1,
    })?;
    let memory = args
        .max_memory
        .or_else(trace::memory::available)
        .unwrap_or(usize::MAX);
    trace::memory::set_limit(memory);
    let film_bytes = trace::bytes_needed(args.width, args.height);
    if film_bytes > memory {
        return Err(Failure {
            message: format!(
                "error: a {}x{} image needs about {} of memory, more than the limit of {} (--max-memory)",
                args.width,
                args.height,
                trace::memory::format_size(film_bytes),
                trace::memory::format_size(memory)
            ),
            code: 1,
        });
    }
    let start = Instant::now();
    let load_options = LoadOptions {
        width: args.width,
        height: args.height,
        // POV-Ray's standard include folder last, as POV-Ray's configuration has it.
        include_paths: args
            .include_path
            .iter()
            .cloned()
            .chain(trace::standard_include_folder())
            .collect(),
        threads: args.threads.map(|t| t as usize),
        max_steps: args.max_steps,
    };
    let loaded = trace::load(scene_path, &load_options)?;
    if !args.quiet {
        eprint!("{}", loaded.debug_output);
    }
    for warning in &loaded.warnings {
        eprint!("{warning}");
    }
    let parsed = Instant::now();
    let antialias = match args.aa {
        AaSetting::Off => Antialias::Off,
        AaSetting::Threshold(threshold) if args.aa_method == 2 => Antialias::Recursive {
            threshold,
            depth: args.aa_depth,
        },
        AaSetting::Threshold(threshold) => Antialias::Adaptive {
            threshold,
            depth: args.aa_depth,
        },
    };
    let options = RenderOptions {
        width: args.width,
        height: args.height,
        antialias,
        threads: args.threads.map(|t| t as usize),
    };
    let stats = trace::render_to_file(loaded.scene, &options, output)?;
    if stats.non_finite > 0 {
        eprintln!(
            "warning: {} pixels overflowed to NaN or infinity (extreme values in the scene, such as a colour component of 1e300) and are written black",
            stats.non_finite
        );
    }
    let done = Instant::now();
    if args.stats {
        // Tracing and writing interleave (each band is written as it is finished): the
        // write time is what the render took beyond building and tracing.
        let write = (done - parsed).saturating_sub(stats.build_time + stats.trace_time);
        eprint!(
            "{}",
            stats_block(
                args,
                &stats,
                [parsed - start, stats.build_time, stats.trace_time, write]
            )
        );
    }
    if !args.quiet {
        eprintln!(
            "trace: wrote {} ({}x{}) in {:.2} s",
            output.display(),
            args.width,
            args.height,
            (done - start).as_secs_f64()
        );
    }
    Ok(())
}

fn convert(
    mesh: &std::path::Path,
    output: &std::path::Path,
    name: Option<String>,
) -> Result<(), Failure> {
    let name = name.unwrap_or_else(|| trace::meshfile::identifier_for(mesh));
    if !trace::is_identifier(&name) {
        return Err(usage(format!("`{name}` is not a valid identifier")));
    }
    let data = trace::meshfile::read(mesh).map_err(|e| Failure {
        message: format!("error: {e}"),
        code: 2,
    })?;
    trace::meshfile::write_mesh2_file(&data, &name, output).map_err(|e| Failure {
        message: format!("error: cannot write {}: {e}", output.display()),
        code: 1,
    })?;
    eprintln!(
        "trace: wrote {} ({name}: {} vertices, {} triangles)",
        output.display(),
        data.vertices.len(),
        data.faces.len()
    );
    Ok(())
}

/// POV-Ray-style statistics: resolution, rays by kind, intersection tests by shape, and the
/// time of each phase (parse, build, trace, write).
fn stats_block(args: &RenderArgs, r: &trace::RenderStats, phases: [Duration; 4]) -> String {
    use std::fmt::Write;
    let line = "-".repeat(76);
    let c = &r.counts;
    let pixels = u64::from(args.width) * u64::from(args.height);
    let rays = c.camera + c.reflected + c.transmitted + c.shadow;
    let mut out = String::new();
    let _ = writeln!(out, "Render Statistics");
    let _ = writeln!(out, "Image Resolution {} x {}", args.width, args.height);
    let _ = writeln!(out, "{line}");
    let _ = writeln!(
        out,
        "Pixels:    {pixels:>12}   Samples:   {:>12}   Smpls/Pxl: {:.2}",
        r.samples,
        r.samples as f64 / pixels.max(1) as f64
    );
    let _ = writeln!(
        out,
        "Rays:      {rays:>12}   Camera:    {:>12}   Shadow:    {:>12}",
        c.camera, c.shadow
    );
    let _ = writeln!(
        out,
        "Reflected: {:>12}   Refracted: {:>12}   Cut at max_trace_level: {}",
        c.reflected, c.transmitted, c.depth_limited
    );
    let _ = writeln!(out, "{line}");
    let _ = writeln!(
        out,
        "{:<28}{:>16}{:>16}{:>12}",
        "Ray->Shape Intersection", "Tests", "Succeeded", "Percentage"
    );
    let _ = writeln!(out, "{line}");
    for (k, name) in trace::SHAPE_KINDS.iter().enumerate() {
        let (tried, hit) = (r.tests.tried[k], r.tests.hit[k]);
        if tried > 0 {
            let pct = 100.0 * hit as f64 / tried as f64;
            let _ = writeln!(out, "{name:<28}{tried:>16}{hit:>16}{pct:>12.2}");
        }
    }
    let _ = writeln!(out, "{line}");
    let names = ["Parse Time", "Build Time", "Trace Time", "Write Time"];
    for (name, d) in names.iter().zip(phases) {
        let _ = writeln!(out, "{name:<12}{:>10.3} s", d.as_secs_f64());
    }
    let total: Duration = phases.iter().sum();
    let _ = writeln!(out, "{:<12}{:>10.3} s", "Total Time", total.as_secs_f64());
    let trace_s = phases[2].as_secs_f64().max(1e-9);
    let _ = writeln!(out, "{:<12}{:>10.0} rays/s", "Speed", rays as f64 / trace_s);
    let _ = writeln!(out, "{line}");
    out
}

#[cfg(feature = "flip")]
fn compare(
    reference: &std::path::Path,
    test: &std::path::Path,
    diff: Option<&std::path::Path>,
) -> Result<(), Failure> {
    let a = trace::Film::read(reference).map_err(Error::from)?;
    let b = trace::Film::read(test).map_err(Error::from)?;
    let c = trace::film::compare(&a, &b).map_err(|e| match e {
        trace::film::ImageError::SizeMismatch(..) => usage(e.to_string()),
        other => Failure::from(Error::from(other)),
    })?;
    let report = format!(
        "mean FLIP  {:.6}\nRMSE       {:.6}\nmax |diff| {:.6}\nNaN/inf    {} / {}\n",
        c.mean_flip,
        c.rmse,
        c.max_abs,
        a.non_finite_pixels(),
        b.non_finite_pixels()
    );
    // A closed pipe (e.g. `| head`) is not an error worth a panic.
    let _ = std::io::Write::write_all(&mut std::io::stdout(), report.as_bytes());
    if let Some(path) = diff {
        trace::film::write_rgb8_png(path, a.width, a.height, c.flip_map).map_err(Error::from)?;
    }
    Ok(())
}
