//! trace: a Whitted ray tracer whose scene language is (a subset of) POV-Ray 3.7's.
//!
//! ```text
//! scene.rt ──pest──▶ syntax tree ──eval──▶ IR ──build──▶ render scene ──trace──▶ film ──▶ EXR/PNG
//!            syntax/               eval/    ir/   scene/                 render/        film/
//! ```
//!
//! Each stage takes the previous stage's output and nothing else: `ir` knows nothing of pest,
//! `render` nothing of syntax or IR (a test, `layers.rs`, checks the direction).
//!
//! The interface is small:
//! - the pipeline: [`load`] (or [`load_str`]) a scene into the [`ir`], then [`render`] it to
//!   a [`Film`] in memory, or [`render_to_file`] band by band into an EXR or PNG file (memory
//!   independent of the image size), or [`prepare`] it once and render it several times
//!   (`trace watch`'s passes); a [`Cancel`] token stops a load or a render, and a [`Preview`]
//!   shows a render's blocks as they finish;
//! - [`ir`], the evaluated scene as plain data (a test may build one by hand and render it);
//! - [`film`], images: reading, writing, comparing (FLIP with the default feature `flip`);
//! - what the command line needs besides: [`memory`] (the allocator that enforces
//!   `--max-memory`), [`output`] (temporary output files removed on failure or interrupt),
//!   [`meshfile`] (OBJ/PLY reading and `trace convert`), [`diag`] (located diagnostics), and a
//!   few constants and statistics names re-exported here.
//!
//! The pipeline's inner stages (`syntax`, `eval`, `scene`, `geometry`, `render`) are private.
//! The feature `internals` makes them public for the stability suite (`stability/`) and the
//! BVH benchmarks, which measure shapes and acceleration structures directly; they are not a
//! stable interface and nothing installed by `cargo install` turns that feature on.

#![warn(missing_docs)]

pub mod cancel;
pub mod diag;
pub mod film;
pub mod font;
pub mod func;
pub mod ir;
pub mod memory;
pub mod meshfile;
pub mod noise;
pub mod output;
pub mod pattern;

// The pipeline's inner stages: public with the feature `internals` (for the stability suite
// and the BVH benchmarks), private without. Each is declared twice, plainly, so that rustfmt
// and every other tool sees the modules (a macro declaring them hid them from rustfmt).

/// Directives, declarations, expressions and includes: syntax → IR.
#[cfg(feature = "internals")]
pub mod eval;
#[cfg(not(feature = "internals"))]
mod eval;
/// Rays, shapes, intersections, bounds.
#[cfg(feature = "internals")]
pub mod geometry;
#[cfg(not(feature = "internals"))]
mod geometry;
/// The tracer: camera rays, shading, anti-aliasing, in parallel.
#[cfg(feature = "internals")]
pub mod render;
#[cfg(not(feature = "internals"))]
mod render;
/// IR → the render-ready scene (transforms, materials, acceleration structures).
#[cfg(feature = "internals")]
pub mod scene;
#[cfg(not(feature = "internals"))]
mod scene;
/// pest's parse of scene text into syntax trees.
#[cfg(feature = "internals")]
pub mod syntax;
#[cfg(not(feature = "internals"))]
mod syntax;
#[cfg(test)]
mod testing;

use diag::{Diagnostic, SourceMap};
use std::path::Path;

pub use cancel::Cancel;
pub use eval::{Clock, DEFAULT_MAX_STEPS, LoadOptions, standard_include_folder};
pub use film::Film;
pub use geometry::counters::{KINDS as SHAPE_KINDS, Tests as ShapeTests};
pub use render::{
    Antialias, Aov, Preview, Progress, RayCounts, RenderOptions, RenderStats, Rendered,
    SamplesByDepth, bytes_needed,
};
pub use scene::Reuse;
pub use syntax::bulk::ListCache;
pub use syntax::{MAX_NESTING, is_identifier};

/// POV-Ray 3.7's reserved words, each with what trace does with it, as the Markdown table of
/// `docs/keywords.md`.
pub fn keyword_table() -> String {
    eval::keywords::markdown()
}

/// A scene that failed to load: the diagnostic and the sources it points into.
#[derive(Debug)]
pub struct LoadError {
    /// What went wrong, and where.
    pub diagnostic: Diagnostic,
    /// The files read, for rendering the diagnostic.
    pub sources: SourceMap,
    /// Every file the scene read before it failed, the scene first (see [`Loaded::files`]).
    pub files: Vec<std::path::PathBuf>,
    /// The files it looked for in vain (see [`Loaded::missing`]).
    pub missing: Vec<std::path::PathBuf>,
}

impl std::fmt::Display for LoadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.diagnostic.render(&self.sources).trim_end())
    }
}

impl std::error::Error for LoadError {}

/// A loaded scene with the warnings met, rendered as text.
#[derive(Debug)]
pub struct Loaded {
    /// The scene.
    pub scene: ir::Scene,
    /// Warnings, each rendered with its source excerpt.
    pub warnings: Vec<String>,
    /// What the scene's `#debug` directives printed.
    pub debug_output: String,
    /// A key of the texts read (the scene and its includes): equal texts, equal keys.
    pub sources_key: u64,
    /// Every file the scene read, each once, the scene first: includes, images, meshes,
    /// fonts, data files, and files whose existence it asked about (what `trace watch`
    /// watches).
    pub files: Vec<std::path::PathBuf>,
    /// Where each file the scene looked for and did not find would stand in its folder
    /// (`file_exists` of a missing file, an include found only as `NAME.inc`): one appearing
    /// there changes what the scene reads, so `trace watch` watches these too.
    pub missing: Vec<std::path::PathBuf>,
}

/// Errors of the whole pipeline.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The scene file could not be read.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The scene path.
        path: std::path::PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// The scene is invalid or outside the subset.
    #[error("{0}")]
    Scene(#[from] Box<LoadError>),
    /// The thread pool could not be built.
    #[error("cannot start worker threads: {0}")]
    Threads(#[from] rayon::ThreadPoolBuildError),
    /// An image could not be read or written.
    #[error(transparent)]
    Image(#[from] film::ImageError),
}

/// Reads and evaluates a scene file into the IR.
pub fn load(path: &Path, options: &LoadOptions) -> Result<Loaded, Error> {
    let text = diag::read_source(path).map_err(|source| Error::Read {
        path: path.to_path_buf(),
        source,
    })?;
    load_str(path, text, options)
}

/// Stack for parsing and evaluation: both recurse once per nesting level (bounded by
/// [`syntax::MAX_NESTING`]) and per macro call; the pages are only committed when used.
const LOAD_STACK_BYTES: usize = 1 << 30;

/// Evaluates scene text (`path` names it in messages).
pub fn load_str(path: &Path, text: String, options: &LoadOptions) -> Result<Loaded, Error> {
    std::thread::scope(|scope| {
        let worker = std::thread::Builder::new()
            .name("trace-load".into())
            .stack_size(LOAD_STACK_BYTES)
            .spawn_scoped(scope, || load_on_this_thread(path, text, options));
        match worker {
            Ok(handle) => handle
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic)),
            Err(e) => Err(Error::Read {
                path: path.to_path_buf(),
                source: e,
            }),
        }
    })
}

fn load_on_this_thread(path: &Path, text: String, options: &LoadOptions) -> Result<Loaded, Error> {
    let mut sources = SourceMap::default();
    let file = sources.add(path, text);
    let services = eval::Services {
        object_query: scene::object_query,
    };
    let mut seen = eval::FilesSeen::default();
    let outcome = eval::evaluate(&mut sources, file, options, services, &mut seen);
    let scene_file = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
    seen.read.retain(|f| *f != scene_file);
    let files = std::iter::once(path.to_path_buf())
        .chain(seen.read)
        .collect();
    let missing = seen.missing;
    match outcome {
        Ok(evaluated) => Ok(Loaded {
            scene: evaluated.scene,
            warnings: evaluated
                .warnings
                .iter()
                .map(|w| w.render(&sources))
                .collect(),
            debug_output: evaluated.debug_output,
            sources_key: sources.key(),
            files,
            missing,
        }),
        Err(diagnostic) => Err(Error::Scene(Box::new(LoadError {
            diagnostic,
            sources,
            files,
            missing,
        }))),
    }
}

/// Renders a scene (building the render-ready scene inside) into a film held in memory.
pub fn render(scene: &ir::Scene, options: &RenderOptions) -> Result<Rendered, Error> {
    let pool = render::thread_pool(options.threads)?;
    let start = std::time::Instant::now();
    let built = pool.install(|| scene::Scene::build(scene));
    let prepared = Prepared {
        built,
        pool,
        build_time: start.elapsed(),
    };
    Ok(prepared.render(options))
}

/// A scene built for rendering (shapes, materials, acceleration structures) with its worker
/// threads, to render more than once: `trace watch` renders a quick small pass, then the
/// picture, then its anti-aliasing, from one build.
pub struct Prepared {
    built: scene::Scene,
    pool: rayon::ThreadPool,
    /// What building took.
    pub build_time: std::time::Duration,
}

/// What one build of a scene keeps for the next ([`prepare`]): its meshes, built with their
/// trees, taken again where the next scene has the same mesh data (a save that moves the
/// camera or edits a material does not build a big mesh again).
#[derive(Default)]
pub struct BuildCache(scene::MeshCache);

impl BuildCache {
    /// Meshes kept now.
    pub fn meshes(&self) -> usize {
        self.0.count()
    }
}

/// Builds a scene for rendering on `threads` worker threads (`None`: one per core); meshes
/// come from `cache` where it has them, and the cache keeps this build's meshes for the next.
pub fn prepare(
    scene: &ir::Scene,
    threads: Option<usize>,
    cache: &BuildCache,
) -> Result<Prepared, Error> {
    let pool = render::thread_pool(threads)?;
    let start = std::time::Instant::now();
    let built = pool.install(|| scene::Scene::build_cached(scene, &cache.0));
    Ok(Prepared {
        built,
        pool,
        build_time: start.elapsed(),
    })
}

impl Prepared {
    /// Puts the camera of `scene` in place, where `scene` is the IR this was prepared from
    /// but for its camera ([`ir::Scene::same_but_camera`]): a camera edit builds nothing else.
    pub fn set_camera(&mut self, scene: &ir::Scene) {
        self.built.set_camera(scene);
    }

    /// Builds `scene` for rendering in place of this preparation, which was made from
    /// `previous`: objects of unchanged geometry keep their built shapes and, where no
    /// object's bounds moved, the top-level tree stays ([`scene::Scene::rebuild`]; a light or
    /// material edit builds no geometry). The result renders as [`prepare`]'s does.
    pub fn rebuild(
        self,
        scene: &ir::Scene,
        previous: &ir::Scene,
        cache: &BuildCache,
    ) -> (Prepared, Reuse) {
        let start = std::time::Instant::now();
        let Prepared { built, pool, .. } = self;
        let (built, reuse) =
            pool.install(|| scene::Scene::rebuild(scene, previous, built, &cache.0));
        let prepared = Prepared {
            built,
            pool,
            build_time: start.elapsed(),
        };
        (prepared, reuse)
    }

    /// Renders into a film held in memory, on the prepared threads (`options.threads` is not
    /// read); the statistics' build time is the preparation's.
    pub fn render(&self, options: &RenderOptions) -> Rendered {
        let mut rendered = render::render(&self.built, options, &self.pool);
        rendered.stats.build_time = self.build_time;
        rendered
    }
}

/// Renders a scene straight into the image file `path` (the extension picks EXR or PNG),
/// band by band: only one band of rows is in memory at a time, whatever the image size, and
/// the IR is freed once the render-ready scene is built. The pixels are those of [`render`];
/// the file appears at `path` only when complete.
pub fn render_to_file(
    scene: ir::Scene,
    options: &RenderOptions,
    layout: &film::Layout,
    path: &Path,
) -> Result<RenderStats, Error> {
    let pool = render::thread_pool(options.threads)?;
    let start = std::time::Instant::now();
    let built = pool.install(|| scene::Scene::build_owned(scene, None));
    let build_time = start.elapsed();
    let mut bands = render::Bands::new(&built, options, &pool);
    let region = options.region();
    film::write_streamed(
        path,
        region.width(),
        region.height(),
        layout,
        options.threads,
        |spare| bands.next_band(spare),
    )?;
    let mut stats = bands.stats;
    stats.build_time = build_time;
    Ok(stats)
}
