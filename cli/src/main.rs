//! The `trace` command line: render a scene, or compare two images.
//!
//! Exit codes: 0 success, 1 render or I/O failure, 2 bad scene or bad arguments.

mod job;
mod parts;
mod povray;
mod progress;
mod watch;

use clap::{Args, CommandFactory, Parser, Subcommand};
use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};
use trace::film::Region;
use trace::{Error, LoadOptions, RenderOptions};

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
    /// Scene file (.rt or .pov). POV-Ray's switches (`+W320 +H240 -A +UA +KFF10 …`), its
    /// `Key=Value` options and INI files (`render.ini`, `render.ini[Section]`) may stand beside
    /// trace's options, which win where both are given (docs/command-line.md).
    scene: Option<PathBuf>,
    /// Output image; the extension picks the format: .png (8 or 16-bit sRGB), .exr (linear
    /// float), .ppm. Default: the scene's name beside it with POV-Ray's type (+F), .png.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Image width in pixels [default: 800].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=65536))]
    width: Option<u32>,
    /// Image height in pixels [default: 600].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=65536))]
    height: Option<u32>,
    /// Anti-aliasing: `off` (one ray per pixel centre, POV-Ray -A) or a threshold (POV-Ray
    /// +A<threshold> -J; 0 supersamples every pixel) [default: 0.3].
    #[arg(long, value_parser = parse_aa)]
    aa: Option<AaSetting>,
    /// Anti-aliasing depth, 1..=9 (POV-Ray +R): the grid size per axis for method 1, the
    /// number of levels for method 2, at most 4·2^(depth−1) samples for method 3
    /// [default: 3].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=9))]
    aa_depth: Option<u32>,
    /// Anti-aliasing method (POV-Ray +AM): 1, a grid in pixels that differ from a neighbour;
    /// 2, corners shared between pixels, squares split where their corners differ; 3, trace's
    /// own sampler: stratified samples in pixels that differ from a neighbour until their
    /// estimated error is small [default: 3; 1 with POV-Ray's -J].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=3))]
    aa_method: Option<u32>,
    /// Area lights: `pov`, POV-Ray's grid of points; `sampled` (method 3 only), points
    /// anywhere on the light from each pixel's sample sequence.
    #[arg(long, value_enum, default_value_t = Sampling::Pov)]
    area_lights: Sampling,
    /// Focal blur: `pov`, POV-Ray's adaptive batches of lens rays for every sample;
    /// `sampled` (method 3 only), lens points from each pixel's sample sequence.
    #[arg(long, value_enum, default_value_t = Sampling::Pov)]
    focal_blur: Sampling,
    /// Radiosity's ground truth instead of POV-Ray's cache: each pixel's centre ray traced N
    /// times, every radiosity query answered by one ray in a random direction; the average
    /// converges on what POV-Ray's radiosity estimates (docs/radiosity.md). Slow; for
    /// measuring, not for pictures.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    radiosity_reference: Option<u32>,
    /// Radiosity in the order of POV-Ray with one thread (`povray +WT1`): the pretrace and the
    /// final render block after block on one thread, every sample seeing all taken before it.
    /// For comparing with POV-Ray; the default schedule is parallel and as reproducible.
    #[arg(long)]
    radiosity_povray_order: bool,
    /// Render only this rectangle of the image, X0,Y0,X1,Y1 in pixels (ends exclusive): a
    /// part of the image, with the same pixels as the whole render, that `trace merge`
    /// assembles with the other parts (POV-Ray's +SC +EC +SR +ER map onto it).
    #[arg(long, value_name = "X0,Y0,X1,Y1", value_parser = parse_region)]
    region: Option<trace::film::Region>,
    /// An alpha channel: the background (where it is transparent) and what shows it through
    /// transparent objects (POV-Ray +UA).
    #[arg(long)]
    alpha: bool,
    /// AOV layers in the EXR, of what each pixel's centre ray first meets: `depth` (Z),
    /// `normal` (Ns.X/Y/Z, world-space shading normal), `albedo` (Albedo.R/G/B, the
    /// pigment's colour), `object` (ObjectID, from 1 in scene order), comma-separated.
    #[arg(long, value_name = "LAYERS", value_delimiter = ',', value_parser = parse_aov)]
    aov: Vec<trace::Aov>,
    /// Bits per channel of a PNG or PPM: 8 or 16 (POV-Ray +FN16); 16 writes an EXR in half
    /// floats, as POV-Ray writes its EXRs (32-bit floats otherwise).
    #[arg(long, value_parser = clap::value_parser!(u8).range(8..=16))]
    bits: Option<u8>,
    /// Declare a float identifier before the scene is read, NAME=VALUE (repeatable; POV-Ray's
    /// Declare=NAME=VALUE).
    #[arg(long, value_name = "NAME=VALUE", value_parser = parse_declare)]
    declare: Vec<(String, f64)>,
    /// The clock of a still image (POV-Ray +K).
    #[arg(long)]
    clock: Option<f64>,
    /// Render an animation's frames FIRST..LAST (POV-Ray +KFI +KFF): each output is numbered
    /// as POV-Ray numbers it (anim01.png …).
    #[arg(long, value_name = "FIRST..LAST", value_parser = parse_range::<i64>)]
    frames: Option<(i64, i64)>,
    /// The clock from the first frame to the last [default: 0..1] (POV-Ray +KI +KF).
    #[arg(long, value_name = "C0..C1", value_parser = parse_range::<f64>)]
    clock_range: Option<(f64, f64)>,
    /// Render only frames A..B of the animation (POV-Ray +SF +EF).
    #[arg(long, value_name = "A..B", value_parser = parse_range::<i64>)]
    subset: Option<(i64, i64)>,
    /// A cyclic animation: the frame after the last is at the final clock (POV-Ray +KC).
    #[arg(long)]
    cyclic: bool,
    /// Continue an interrupted render: keep the rows the output already holds and render the
    /// rest (POV-Ray +C).
    #[arg(long = "continue")]
    continue_trace: bool,
    /// Worker threads for parsing big files, building and rendering (default: one per core).
    /// The image is the same for any count.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Print nothing but errors and warnings (no progress line).
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

/// `trace watch`'s options.
#[derive(Args, Debug)]
struct WatchArgs {
    /// Scene file (.rt or .pov).
    scene: PathBuf,
    /// Port to serve the page on [default: a free one, printed].
    #[arg(long)]
    port: Option<u16>,
    /// Address to serve on [default: 127.0.0.1, this machine only]. Another address lets
    /// other machines see the page and the picture.
    #[arg(long, value_name = "ADDRESS")]
    bind: Option<std::net::IpAddr>,
    /// Image width in pixels (the page can change it).
    #[arg(long, default_value_t = 640, value_parser = clap::value_parser!(u32).range(1..=8192))]
    width: u32,
    /// Image height in pixels (the page can change it).
    #[arg(long, default_value_t = 480, value_parser = clap::value_parser!(u32).range(1..=8192))]
    height: u32,
    /// Anti-aliasing, rendered after the picture: `off` or a threshold (method 3)
    /// [default: 0.3].
    #[arg(long, value_parser = parse_aa)]
    aa: Option<AaSetting>,
    /// Anti-aliasing depth, 1..=9.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=9))]
    aa_depth: u32,
    /// The clock (the page has a slider for it).
    #[arg(long)]
    clock: Option<f64>,
    /// Also stream each picture to a running tev image viewer at HOST:PORT (tev listens on
    /// 127.0.0.1:14158).
    #[arg(long, value_name = "HOST:PORT")]
    tev: Option<String>,
    /// Declare a float identifier before the scene is read, NAME=VALUE (repeatable).
    #[arg(long, value_name = "NAME=VALUE", value_parser = parse_declare)]
    declare: Vec<(String, f64)>,
    /// A folder to search for `#include` files, fonts and images (repeatable).
    #[arg(short = 'L', long = "include-path", value_name = "DIR")]
    include_path: Vec<PathBuf>,
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Most evaluation steps a load may take: a scene that never finishes stops here with
    /// an error on the page.
    #[arg(long, default_value_t = trace::DEFAULT_MAX_STEPS, value_name = "N")]
    max_steps: u64,
    /// Print nothing but the address, errors and warnings.
    #[arg(short, long)]
    quiet: bool,
}

fn parse_region(s: &str) -> Result<trace::film::Region, String> {
    let v: Vec<u32> = s
        .split(',')
        .map(|n| n.trim().parse().ok())
        .collect::<Option<_>>()
        .ok_or_else(|| format!("expected X0,Y0,X1,Y1 in pixels, found `{s}`"))?;
    let [x0, y0, x1, y1] = v[..] else {
        return Err(format!("expected X0,Y0,X1,Y1 in pixels, found `{s}`"));
    };
    Ok(trace::film::Region { x0, y0, x1, y1 })
}

fn parse_aov(s: &str) -> Result<trace::Aov, String> {
    trace::Aov::named(s.trim())
        .ok_or_else(|| format!("unknown AOV `{s}` (depth, normal, albedo, object)"))
}

fn parse_declare(s: &str) -> Result<(String, f64), String> {
    let (name, value) = s
        .split_once('=')
        .ok_or_else(|| format!("expected NAME=VALUE, found `{s}`"))?;
    if !trace::is_identifier(name) {
        return Err(format!("`{name}` is not an identifier"));
    }
    let value = value
        .parse()
        .map_err(|_| format!("expected a number after `{name}=`, found `{value}`"))?;
    Ok((name.to_string(), value))
}

fn parse_range<T: std::str::FromStr>(s: &str) -> Result<(T, T), String> {
    let (a, b) = s
        .split_once("..")
        .ok_or_else(|| format!("expected A..B, found `{s}`"))?;
    match (a.trim().parse(), b.trim().parse()) {
        (Ok(a), Ok(b)) => Ok((a, b)),
        _ => Err(format!("expected A..B (two numbers), found `{s}`")),
    }
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

/// How area lights and focal blur are sampled (`--area-lights`, `--focal-blur`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum Sampling {
    /// POV-Ray's way: the area light's grid, the blur's batches of lens rays.
    Pov,
    /// Points drawn from each pixel's sample sequence (method 3).
    Sampled,
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
    /// Assemble parts of an image rendered with --region (or POV-Ray's +SC +EC +SR +ER) into
    /// the whole image: the parts must come from the same scene and settings and tile it
    /// exactly (or tile a rectangle of it, which gives a bigger part).
    Merge {
        /// The image to write (the parts' format).
        #[arg(short, long)]
        output: PathBuf,
        /// The parts.
        #[arg(required = true)]
        parts: Vec<PathBuf>,
    },
    /// Render a scene again whenever it, or a file it reads, is saved, and show it on a page
    /// served at http://127.0.0.1:PORT/ (printed): the picture as it progresses, the error
    /// with its place when the scene breaks (docs/watch.md).
    Watch(WatchArgs),
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

/// Whether a render is running (a first Ctrl-C then stops it and writes what is done).
static RENDERING: AtomicBool = AtomicBool::new(false);

/// The token every render of this process is given: Ctrl-C cancels it (the signal is the
/// process's, so the token is too; the library keeps no global).
static CANCEL: std::sync::LazyLock<trace::Cancel> = std::sync::LazyLock::new(trace::Cancel::new);

fn main() -> ExitCode {
    // A first Ctrl-C during a render stops it and writes the rows finished (a part that
    // `--continue` completes); another, or one at any other time, ends at once, leaving no
    // temporary file behind.
    let _ = ctrlc::set_handler(|| {
        if RENDERING.load(Ordering::SeqCst) && !CANCEL.is_cancelled() {
            CANCEL.cancel();
            eprintln!(
                "\ntrace: stopping: writing the rows finished (Ctrl-C again to quit at once)"
            );
            return;
        }
        trace::output::interrupt();
        eprintln!("trace: interrupted");
        std::process::exit(130);
    });
    let args: Vec<String> = std::env::args_os()
        .skip(1)
        .map(|a| a.to_string_lossy().into_owned())
        .collect();
    let result = match args.first().map(String::as_str) {
        Some("compare" | "convert" | "merge" | "help") | None => {
            let cli = Cli::parse_from(std::iter::once("trace".to_string()).chain(args));
            run(cli, povray::PovSettings::default())
        }
        _ => {
            let command = Cli::command();
            let takes_value = |long: &str| {
                command
                    .get_arguments()
                    .find(|a| a.get_long() == Some(long))
                    .is_some_and(|a| a.get_action().takes_values())
            };
            match povray::split(args, takes_value) {
                Ok((own, pov)) => {
                    let cli = Cli::parse_from(std::iter::once("trace".to_string()).chain(own));
                    run(cli, pov)
                }
                Err(e) => Err(usage(e)),
            }
        }
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

fn run(cli: Cli, pov: povray::PovSettings) -> Result<(), Failure> {
    match cli.command {
        #[cfg(feature = "flip")]
        Some(Command::Compare {
            reference,
            test,
            diff,
        }) => compare(&reference, &test, diff.as_deref()),
        Some(Command::Merge { output, parts }) => merge(&output, &parts),
        Some(Command::Convert { mesh, output, name }) => convert(&mesh, &output, name),
        Some(Command::Watch(args)) => watch(args),
        None => render(&cli.render, pov),
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

fn io_failure(message: String) -> Failure {
    Failure {
        message: format!("error: {message}"),
        code: 1,
    }
}

fn render(args: &RenderArgs, pov: povray::PovSettings) -> Result<(), Failure> {
    let own = job::Own {
        scene: args.scene.clone(),
        output: args.output.clone(),
        width: args.width,
        height: args.height,
        aa: args.aa.map(|a| match a {
            AaSetting::Off => None,
            AaSetting::Threshold(t) => Some(t),
        }),
        aa_depth: args.aa_depth,
        aa_method: args.aa_method,
        sampled_lights: args.area_lights == Sampling::Sampled,
        sampled_blur: args.focal_blur == Sampling::Sampled,
        radiosity_reference: args.radiosity_reference,
        radiosity_povray_order: args.radiosity_povray_order,
        threads: args.threads,
        include_paths: args.include_path.clone(),
        declares: args.declare.clone(),
        region: args.region,
        alpha: args.alpha,
        bits: args.bits,
        clock: args.clock,
        frames: args.frames,
        clocks: args.clock_range,
        subset: args.subset,
        cyclic: args.cyclic,
        continue_trace: args.continue_trace,
        aovs: args.aov.clone(),
    };
    let job = job::resolve(own, pov).map_err(usage)?;
    for warning in &job.warnings {
        eprintln!("warning: {warning}");
    }
    let memory = args
        .max_memory
        .or_else(trace::memory::available)
        .unwrap_or(usize::MAX);
    trace::memory::set_limit(memory);
    let film_bytes = trace::bytes_needed(job.width, job.height);
    if film_bytes > memory {
        return Err(io_failure(format!(
            "a {}x{} image needs about {} of memory, more than the limit of {} (--max-memory)",
            job.width,
            job.height,
            trace::memory::format_size(film_bytes),
            trace::memory::format_size(memory)
        )));
    }
    for frame in &job.frames {
        trace::output::check_writable(&frame.output)
            .map_err(|e| io_failure(format!("cannot write {}: {e}", frame.output.display())))?;
    }
    let animated = job.frames.len() > 1;
    for frame in &job.frames {
        if animated && !args.quiet {
            eprintln!(
                "trace: frame {} (clock {}) → {}",
                frame.clock.frame,
                frame.clock.clock,
                frame.output.display()
            );
        }
        render_frame(args, &job, frame)?;
        if CANCEL.is_cancelled() {
            break;
        }
    }
    Ok(())
}

/// Renders one frame into its output (or the rest of it, continuing).
fn render_frame(args: &RenderArgs, job: &job::Job, frame: &job::Frame) -> Result<(), Failure> {
    let start = Instant::now();
    let load_options = LoadOptions {
        width: job.width,
        height: job.height,
        include_paths: job.include_paths.clone(),
        threads: job.threads.map(|t| t as usize),
        max_steps: args.max_steps,
        clock: frame.clock,
        declares: job.declares.clone(),
        cancel: trace::Cancel::new(),
        lists: Default::default(),
    };
    let loaded = trace::load(&job.scene, &load_options)?;
    // (The options hold the cache of big mesh2 lists and the meshes made from them, for a
    // next load of the same text, which a render never makes: let go now, so that the scene
    // build can free a mesh's lists before it makes the mesh's tree.)
    drop(load_options);
    if !args.quiet {
        eprint!("{}", loaded.debug_output);
    }
    for warning in &loaded.warnings {
        eprint!("{warning}");
    }
    let parsed = Instant::now();
    let full = Region::full(job.width, job.height);
    let wanted = job.region.unwrap_or(full);
    // A key of the scene as read and of the settings that change pixels: parts merge only
    // with parts of the same key.
    let key = parts::key(loaded.sources_key, job, frame);
    let mut region = wanted;
    let mut kept: Option<PathBuf> = None;
    if job.continue_trace && frame.output.exists() {
        match parts::continuation(&frame.output, wanted, (job.width, job.height), &key)
            .map_err(usage)?
        {
            None => {
                if !args.quiet {
                    eprintln!("trace: {} is complete", frame.output.display());
                }
                return Ok(());
            }
            Some(rest) => {
                region = rest;
                kept = Some(frame.output.clone());
            }
        }
    }
    let note = |r: Region| {
        trace::film::Part {
            width: job.width,
            height: job.height,
            region: r,
            key: key.clone(),
        }
        .note()
    };
    let layout = trace::film::Layout {
        alpha: job.alpha,
        bits: job.bits,
        aovs: job
            .aovs
            .iter()
            .flat_map(|a| a.channels())
            .map(|c| c.to_string())
            .collect(),
        note: (region != full).then(|| note(region)),
    };
    let progress = Arc::new(trace::Progress::default());
    let options = RenderOptions {
        width: job.width,
        height: job.height,
        antialias: job.antialias,
        sampled_lights: job.sampled_lights,
        sampled_blur: job.sampled_blur,
        radiosity_reference: job.radiosity_reference,
        radiosity_povray_order: job.radiosity_povray_order,
        threads: job.threads.map(|t| t as usize),
        region: Some(region),
        progress: Some(progress.clone()),
        alpha: job.alpha,
        aovs: job.aovs.clone(),
        cancel: CANCEL.clone(),
        preview: None,
    };
    // Rendered beside the output, then moved (or cut, if stopped) into place: the output
    // only ever holds whole images and parts.
    let rendered = parts::scratch_path(&frame.output);
    RENDERING.store(true, Ordering::SeqCst);
    let meter = (!args.quiet && std::io::stderr().is_terminal()).then(|| {
        progress::Meter::start(
            progress.clone(),
            u64::from(region.width()) * u64::from(region.height()),
        )
    });
    let result = trace::render_to_file(loaded.scene, &options, &layout, &rendered.0);
    drop(meter);
    RENDERING.store(false, Ordering::SeqCst);
    let stats = result?;
    let done = stats.stopped.unwrap_or(region.height());
    let finished = Region {
        y1: region.y0 + done,
        ..region
    };
    parts::settle(
        &rendered.0,
        region,
        finished,
        &note,
        kept.as_deref(),
        &frame.output,
    )
    .map_err(io_failure)?;
    if stats.non_finite > 0 {
        eprintln!(
            "warning: {} pixels overflowed to NaN or infinity (extreme values in the scene, such as a colour component of 1e300) and are written black",
            stats.non_finite
        );
    }
    let end = Instant::now();
    if args.stats {
        // Tracing and writing interleave (each band is written as it is finished): the
        // write time is what the render took beyond building and tracing.
        let write = (end - parsed).saturating_sub(stats.build_time + stats.trace_time);
        eprint!(
            "{}",
            stats_block(
                (region.width(), region.height()),
                &stats,
                [parsed - start, stats.build_time, stats.trace_time, write]
            )
        );
    }
    if let Some(rows) = stats.stopped {
        if rows == 0 && kept.is_none() {
            eprintln!(
                "trace: stopped before a row was finished: {} is unchanged",
                frame.output.display()
            );
        } else {
            eprintln!(
                "trace: stopped after {rows} of {} rows: {} holds the rows finished (the same command with --continue renders the rest)",
                region.height(),
                frame.output.display()
            );
        }
        return Err(Failure {
            message: "trace: render stopped".into(),
            code: 130,
        });
    }
    if !args.quiet {
        eprintln!(
            "trace: wrote {} ({}x{}{}) in {:.2} s",
            frame.output.display(),
            job.width,
            job.height,
            match (region != full, kept.is_some()) {
                (_, true) => format!(", rows {} to {} added", region.y0, region.y1),
                (true, false) => format!(", region {region}"),
                _ => String::new(),
            },
            (end - start).as_secs_f64()
        );
    }
    Ok(())
}

fn watch(args: WatchArgs) -> Result<(), Failure> {
    let memory = trace::memory::available().unwrap_or(usize::MAX);
    trace::memory::set_limit(memory);
    let include_paths = std::iter::once(PathBuf::from("."))
        .chain(args.include_path)
        .chain(trace::standard_include_folder())
        .collect();
    let options = watch::Options {
        scene: args.scene,
        bind: args
            .bind
            .unwrap_or(std::net::IpAddr::V4(std::net::Ipv4Addr::LOCALHOST)),
        bind_given: args.bind.is_some(),
        port: args.port.unwrap_or(0),
        settings: watch::Settings {
            width: args.width,
            height: args.height,
            aa: match args.aa {
                Some(AaSetting::Off) => None,
                Some(AaSetting::Threshold(t)) => Some(t),
                None => Some(0.3),
            },
            aa_depth: args.aa_depth,
            clock: args.clock,
        },
        include_paths,
        declares: args.declare,
        threads: args.threads,
        max_steps: args.max_steps,
        quiet: args.quiet,
        tev: args.tev,
    };
    // (A scene that cannot be read, an address that cannot be served: I/O failures.)
    watch::run(options).map_err(io_failure)
}

fn merge(output: &std::path::Path, parts: &[PathBuf]) -> Result<(), Failure> {
    let paths: Vec<&std::path::Path> = parts.iter().map(PathBuf::as_path).collect();
    let merged = trace::film::merge(&paths, output).map_err(usage)?;
    eprintln!(
        "trace: wrote {} ({}x{}{}) from {} parts",
        output.display(),
        merged.width,
        merged.height,
        match merged.part() {
            Some(p) => format!(", still a part: region {}", p.region),
            None => String::new(),
        },
        parts.len()
    );
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
fn stats_block(
    (width, height): (u32, u32),
    r: &trace::RenderStats,
    phases: [Duration; 4],
) -> String {
    use std::fmt::Write;
    let line = "-".repeat(76);
    let c = &r.counts;
    let pixels = u64::from(width) * u64::from(height);
    let rays = c.camera + c.reflected + c.transmitted + c.shadow;
    let mut out = String::new();
    let _ = writeln!(out, "Render Statistics");
    let _ = writeln!(out, "Image Resolution {width} x {height}");
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
    // (POV-Ray's line, printed as it prints it: only when media were sampled.)
    if c.media_intervals > 0 {
        let _ = writeln!(
            out,
            "Media Intervals: {:>15}   Media Samples: {:>15} ({:4.2})",
            c.media_intervals,
            c.media_samples,
            c.media_samples as f64 / c.media_intervals as f64
        );
    }
    // (Radiosity's lines, only for a scene with radiosity.)
    let p = &r.pretrace;
    if p.passes > 0 {
        let _ = writeln!(
            out,
            "Radiosity pretrace: {} passes, {} points, {} samples of {} rays in {:.3} s",
            p.passes,
            p.points,
            p.total_samples(),
            p.rays,
            p.time.as_secs_f64()
        );
        let _ = writeln!(
            out,
            "Radiosity final:    {} samples of {} rays, {} reused",
            r.radiosity_samples.iter().sum::<u64>(),
            r.radiosity_rays,
            r.radiosity_reused
        );
        radiosity_table(&mut out, &p.samples, &r.radiosity_samples);
    }
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

/// POV-Ray's table of radiosity samples (`+V` statistics): a row for each pretrace pass (the
/// fifth and later together, `5+`) and the final render, a column for each depth that took
/// any (`Depth 4+` for the deeper), and their totals.
fn radiosity_table(
    out: &mut String,
    passes: &[trace::SamplesByDepth],
    last: &trace::SamplesByDepth,
) {
    use std::fmt::Write;
    let mut rows = [[0u64; 5]; 5];
    for (pass, counts) in passes.iter().enumerate() {
        for (depth, n) in counts.iter().enumerate() {
            rows[pass.min(4)][depth] += n;
        }
    }
    let mut by_depth = [0u64; 5];
    for counts in rows.iter().chain([last]) {
        for (depth, n) in counts.iter().enumerate() {
            by_depth[depth] += n;
        }
    }
    let used = |depth: usize| by_depth[depth] > 0;
    let cells = |out: &mut String, counts: &[u64; 5]| {
        for (depth, &n) in counts.iter().enumerate() {
            if n > 0 {
                let _ = write!(out, " {n:10}");
            } else if used(depth) {
                let _ = write!(out, "          -");
            }
        }
        let _ = writeln!(out, " {:15}", counts.iter().sum::<u64>());
    };
    let _ = write!(out, "  Pass ");
    for depth in (0..5).filter(|&d| used(d)) {
        let _ = if depth < 4 {
            write!(out, "    Depth {depth}")
        } else {
            write!(out, "   Depth 4+")
        };
    }
    let _ = writeln!(out, "           Total");
    for (pass, counts) in rows.iter().enumerate() {
        if counts.iter().sum::<u64>() > 0 {
            let _ = write!(out, "  {}{}   ", pass + 1, if pass < 4 { ' ' } else { '+' });
            cells(out, counts);
        }
    }
    if last.iter().sum::<u64>() > 0 {
        let _ = write!(out, "  Final");
        cells(out, last);
    }
    let _ = write!(out, "  Total");
    for depth in (0..5).filter(|&d| used(d)) {
        let _ = write!(out, " {:10}", by_depth[depth]);
    }
    let _ = writeln!(out, " {:15}", by_depth.iter().sum::<u64>());
}
