//! `trace watch SCENE`: renders the scene again whenever it, or any file it read, is saved,
//! and serves a page (and a small HTTP interface) that shows the picture as it progresses
//! and the located error when the scene breaks (docs/watch.md).
//!
//! Three threads besides the server's: the renderer ([`Session::run`]) renders the newest
//! request, the watcher ([`Session::watch`]) looks at the files' stamps every 20 ms and
//! asks for a render when one changes, and the server ([`http`]) answers the page. A new
//! request cancels the render in progress at once (its load stops within a few thousand
//! evaluation steps, its render before the next block).

mod http;
mod tev;

use std::net::{IpAddr, SocketAddr, TcpListener};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::{Duration, Instant, SystemTime};
use trace::{Antialias, Cancel, Error, LoadOptions, Preview, Progress, RenderOptions};

/// What the page may change: the image's size, anti-aliasing and the clock.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    pub width: u32,
    pub height: u32,
    /// The anti-aliasing threshold (method 3, trace's default), `None` for off.
    pub aa: Option<f64>,
    /// Anti-aliasing depth, 1..=9 (the page's "quality").
    pub aa_depth: u32,
    /// The clock (`clock` in the scene); `None` for a still without one.
    pub clock: Option<f64>,
}

impl Settings {
    /// Settings from a query string (`width=320&height=240&aa=off&depth=3&clock=0.5`) over
    /// these; an error names the first value out of range.
    pub fn updated(&self, query: &str) -> Result<Settings, String> {
        let mut s = self.clone();
        for pair in query.split('&').filter(|p| !p.is_empty()) {
            let (key, value) = pair.split_once('=').unwrap_or((pair, ""));
            let size = |v: &str| match v.parse::<u32>() {
                Ok(n) if (1..=8192).contains(&n) => Ok(n),
                _ => Err(format!("{key} must be 1 to 8192, not `{v}`")),
            };
            match key {
                "width" => s.width = size(value)?,
                "height" => s.height = size(value)?,
                "aa" if value == "off" => s.aa = None,
                "aa" => match value.parse::<f64>() {
                    Ok(t) if t >= 0.0 && t.is_finite() => s.aa = Some(t),
                    _ => {
                        return Err(format!(
                            "aa must be `off` or a threshold ≥ 0, not `{value}`"
                        ));
                    }
                },
                "depth" => match value.parse::<u32>() {
                    Ok(d) if (1..=9).contains(&d) => s.aa_depth = d,
                    _ => return Err(format!("depth must be 1 to 9, not `{value}`")),
                },
                "clock" if value.is_empty() => s.clock = None,
                "clock" => match value.parse::<f64>() {
                    Ok(c) if c.is_finite() => s.clock = Some(c),
                    _ => return Err(format!("clock must be a number, not `{value}`")),
                },
                _ => return Err(format!("unknown setting `{key}`")),
            }
        }
        Ok(s)
    }
}

/// What `trace watch` was asked on its command line.
#[derive(Debug)]
pub struct Options {
    pub scene: PathBuf,
    pub bind: IpAddr,
    /// 0: a free port.
    pub port: u16,
    /// Whether `--bind` was given: the server then answers any host name.
    pub bind_given: bool,
    pub settings: Settings,
    pub include_paths: Vec<PathBuf>,
    pub declares: Vec<(String, f64)>,
    pub threads: Option<u32>,
    pub max_steps: u64,
    pub quiet: bool,
    /// Also stream the pictures to a running tev (HOST:PORT).
    pub tev: Option<String>,
}

/// Where a session is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    Parsing,
    Rendering,
    Done,
    Error,
}

impl Phase {
    fn name(self) -> &'static str {
        match self {
            Phase::Parsing => "parsing",
            Phase::Rendering => "rendering",
            Phase::Done => "done",
            Phase::Error => "error",
        }
    }
}

/// An error or warning with its place, for the page.
#[derive(Clone, Debug)]
struct Message {
    severity: &'static str,
    message: String,
    /// File, line and column (from 1), where the message has a place.
    place: Option<(String, usize, usize)>,
    /// The message as the command line prints it: the source line, the caret, the notes.
    text: String,
}

/// What the page shows, and the HTTP interface reports.
struct Status {
    /// The render asked for (a new one for each change).
    id: u64,
    phase: Phase,
    /// The pass being rendered: `quick` (a small picture), `picture`, `anti-aliasing`.
    pass: &'static str,
    /// The pass's counters, and the pixels it has.
    progress: Option<(Arc<Progress>, u64)>,
    /// The picture shown (the last good render's, or the one in progress), and how many
    /// times a new one was put in its place.
    preview: Option<Arc<Preview>>,
    pictures: u64,
    /// The id of the render the picture comes from.
    picture_id: u64,
    errors: Vec<Message>,
    warnings: Vec<Message>,
    /// What the scene's `#debug` printed.
    debug: String,
    /// Seconds from the change seen to the end of each step.
    timings: Vec<(&'static str, f64)>,
    /// Whether the render-ready scene was built anew (not the last one with another camera).
    built: bool,
    /// What a build took from the last one (shapes, the top-level tree), if it had one.
    kept: Option<trace::Reuse>,
    files: Vec<PathBuf>,
    settings: Settings,
    /// Bumped at every change, so the event stream knows when to speak.
    seq: u64,
}

/// A request for a render: the newest wins.
struct Request {
    id: u64,
    settings: Settings,
    /// The newest request's token: cancelled when another comes.
    cancel: Cancel,
    /// When the change that asked for it was seen.
    at: Instant,
}

/// A file's stamp: modification time and length (`None` when it cannot be read).
type Stamp = Option<(SystemTime, u64)>;

fn stamp(path: &Path) -> Stamp {
    let meta = std::fs::metadata(path).ok()?;
    Some((meta.modified().ok()?, meta.len()))
}

/// The state shared by the renderer, the watcher and the server.
pub struct Session {
    options: Options,
    status: Mutex<Status>,
    /// Signalled at every status change (the event streams wait on it).
    changed: Condvar,
    request: Mutex<Request>,
    /// Signalled at every new request (the renderer waits on it).
    asked: Condvar,
    /// The files the last load read, with their stamps when it began.
    watched: Mutex<Vec<(PathBuf, Stamp)>>,
    /// The last picture encoded, by its key.
    png: Mutex<(String, Arc<Vec<u8>>)>,
    /// What the last build keeps for the next (its meshes), and the last load (its big
    /// mesh2 lists).
    cache: trace::BuildCache,
    /// The last scene rendered and its render-ready form (used by the renderer only).
    last: Mutex<Option<(trace::ir::Scene, trace::Prepared)>>,
    lists: trace::ListCache,
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

impl Session {
    fn new(options: Options) -> Session {
        let settings = options.settings.clone();
        let scene = options.scene.clone();
        Session {
            status: Mutex::new(Status {
                id: 1,
                phase: Phase::Parsing,
                pass: "",
                progress: None,
                preview: None,
                pictures: 0,
                picture_id: 0,
                errors: Vec::new(),
                warnings: Vec::new(),
                debug: String::new(),
                timings: Vec::new(),
                built: false,
                kept: None,
                files: vec![scene.clone()],
                settings: settings.clone(),
                seq: 0,
            }),
            changed: Condvar::new(),
            request: Mutex::new(Request {
                id: 1,
                settings,
                cancel: Cancel::new(),
                at: Instant::now(),
            }),
            asked: Condvar::new(),
            watched: Mutex::new(vec![(scene.clone(), stamp(&scene))]),
            png: Mutex::new((String::new(), Arc::new(Vec::new()))),
            cache: trace::BuildCache::default(),
            last: Mutex::new(None),
            lists: trace::ListCache::default(),
            options,
        }
    }

    /// Asks for a new render (with new settings, if given): the one in progress is cancelled.
    fn ask(&self, settings: Option<Settings>) {
        let mut r = lock(&self.request);
        r.cancel.cancel();
        r.cancel = Cancel::new();
        r.id += 1;
        r.at = Instant::now();
        if let Some(s) = settings {
            r.settings = s;
        }
        drop(r);
        self.asked.notify_all();
    }

    /// Changes the status and wakes the event streams.
    fn update(&self, change: impl FnOnce(&mut Status)) {
        let mut s = lock(&self.status);
        change(&mut s);
        s.seq += 1;
        drop(s);
        self.changed.notify_all();
    }

    /// The watcher: every 20 ms, the stamps of the files the last load read; a change asks
    /// for a render (a flood of saves asks for many, and only the newest is rendered).
    fn watch(&self) {
        loop {
            std::thread::sleep(Duration::from_millis(20));
            let mut changed = false;
            for (path, seen) in lock(&self.watched).iter_mut() {
                let now = stamp(path);
                if now != *seen {
                    *seen = now;
                    changed = true;
                }
            }
            if changed {
                self.ask(None);
            }
        }
    }

    /// The renderer: waits for a request newer than the last one rendered and renders it.
    fn run(&self) {
        let mut last = 0;
        loop {
            let (id, settings, cancel, at) = {
                let mut r = lock(&self.request);
                while r.id == last {
                    r = self.asked.wait(r).unwrap_or_else(|e| e.into_inner());
                }
                (r.id, r.settings.clone(), r.cancel.clone(), r.at)
            };
            last = id;
            self.render(id, &settings, &cancel, at);
        }
    }

    /// One render: load, a quick small pass, the picture, its anti-aliasing; each step
    /// published as it ends. Returns early once cancelled (a newer request is waiting).
    fn render(&self, id: u64, settings: &Settings, cancel: &Cancel, at: Instant) {
        let o = &self.options;
        self.update(|s| {
            s.id = id;
            s.phase = Phase::Parsing;
            s.pass = "";
            s.progress = None;
            s.settings = settings.clone();
            s.timings.clear();
        });
        // The stamps of the files known now: a save while the scene loads is seen after.
        let before: Vec<(PathBuf, Stamp)> = lock(&self.watched)
            .iter()
            .map(|(p, _)| (p.clone(), stamp(p)))
            .collect();
        let load_options = LoadOptions {
            width: settings.width,
            height: settings.height,
            include_paths: o.include_paths.clone(),
            threads: o.threads.map(|t| t as usize),
            max_steps: o.max_steps,
            clock: trace::Clock::still(settings.clock),
            declares: o.declares.clone(),
            cancel: cancel.clone(),
            lists: self.lists.clone(),
        };
        let loaded = trace::load(&o.scene, &load_options);
        if cancel.is_cancelled() {
            return;
        }
        let (files, missing) = match &loaded {
            Ok(l) => (l.files.clone(), l.missing.clone()),
            Err(Error::Scene(e)) => (e.files.clone(), e.missing.clone()),
            Err(_) => (vec![o.scene.clone()], Vec::new()),
        };
        *lock(&self.watched) = (files.iter().chain(&missing))
            .map(|f| {
                let known = before.iter().find(|(p, _)| p == f).map(|(_, s)| *s);
                (f.clone(), known.unwrap_or_else(|| stamp(f)))
            })
            .collect();
        let parsed = at.elapsed().as_secs_f64();
        let loaded = match loaded {
            Ok(l) => l,
            Err(e) => {
                let message = error_message(&e);
                if !o.quiet {
                    eprintln!("{}", message.text);
                }
                self.update(|s| {
                    s.phase = Phase::Error;
                    s.errors = vec![message];
                    s.files = files;
                    s.timings = vec![("parse", parsed)];
                });
                return;
            }
        };
        let warnings: Vec<Message> = loaded.warnings.iter().map(|w| warning_message(w)).collect();
        let debug = loaded.debug_output.clone();
        self.update(|s| {
            s.phase = Phase::Rendering;
            s.pass = "quick";
            s.errors.clear();
            s.warnings = warnings;
            s.debug = debug;
            s.files = files;
            s.timings = vec![("parse", parsed)];
        });
        // The last render's scene serves again where only the camera changed; anything else
        // builds it anew (its meshes from the cache).
        let mut last = lock(&self.last);
        let scene = loaded.scene;
        let reused = last
            .as_ref()
            .is_some_and(|(old, _)| old.same_but_camera(&scene));
        let mut kept = None;
        if reused {
            let (old, prepared) = last.as_mut().expect("the last scene");
            if old.camera != scene.camera {
                prepared.set_camera(&scene);
            }
            *old = scene;
        } else {
            // Built again, taking from the last build what the edit left (shapes of unchanged
            // geometry, the top-level tree where no bounds moved).
            let rebuilt = match last.take() {
                Some((old, prepared)) => {
                    let (p, reuse) = prepared.rebuild(&scene, &old, &self.cache);
                    Ok((p, Some(reuse)))
                }
                None => trace::prepare(&scene, o.threads.map(|t| t as usize), &self.cache)
                    .map(|p| (p, None)),
            };
            match rebuilt {
                Ok((p, reuse)) => {
                    *last = Some((scene, p));
                    kept = reuse;
                }
                Err(e) => {
                    let message = error_message(&e);
                    self.update(|s| {
                        s.phase = Phase::Error;
                        s.errors = vec![message];
                    });
                    return;
                }
            }
        }
        let prepared = &last.as_ref().expect("a prepared scene").1;
        let step = if reused { "camera" } else { "build" };
        self.update(|s| {
            s.built = !reused;
            s.kept = kept;
            s.timings.push((step, at.elapsed().as_secs_f64()));
        });
        let (w, h) = (settings.width, settings.height);
        let options = |width, height, antialias, progress, preview| RenderOptions {
            width,
            height,
            antialias,
            threads: None,
            progress,
            preview,
            cancel: cancel.clone(),
            ..RenderOptions::default()
        };
        // A picture an eighth of the size first, stretched: it shows in a few milliseconds
        // where the whole one takes seconds.
        let (qw, qh) = ((w / 8).max(1), (h / 8).max(1));
        let quick = prepared.render(&options(qw, qh, Antialias::Off, None, None));
        if cancel.is_cancelled() {
            return;
        }
        let mut stretched = trace::Film::new(w, h);
        for y in 0..h {
            for x in 0..w {
                let (sx, sy) = (x * qw / w, y * qh / h);
                stretched.set(x, y, quick.film.get(sx, sy));
            }
        }
        let preview = Arc::new(Preview::new(w, h));
        preview.fill(stretched);
        let mut passes = vec![("picture", Antialias::Off)];
        if let Some(threshold) = settings.aa {
            passes.push((
                "anti-aliasing",
                Antialias::Sampled {
                    threshold,
                    depth: settings.aa_depth,
                },
            ));
        }
        self.update(|s| {
            s.preview = Some(preview.clone());
            s.pictures += 1;
            s.picture_id = id;
            s.timings.push(("quick", at.elapsed().as_secs_f64()));
        });
        for (pass, antialias) in passes {
            let progress = Arc::new(Progress::default());
            self.update(|s| {
                s.pass = pass;
                s.progress = Some((progress.clone(), u64::from(w) * u64::from(h)));
            });
            prepared.render(&options(
                w,
                h,
                antialias,
                Some(progress),
                Some(preview.clone()),
            ));
            if cancel.is_cancelled() {
                return;
            }
            self.update(|s| s.timings.push((pass, at.elapsed().as_secs_f64())));
        }
        if !o.quiet {
            eprintln!(
                "trace: rendered {} ({w}x{h}) in {:.2} s",
                o.scene.display(),
                at.elapsed().as_secs_f64()
            );
        }
        self.update(|s| {
            s.phase = Phase::Done;
            s.pass = "";
            s.progress = None;
        });
    }

    /// Streams the picture to tev at `address` four times a second while it changes (as
    /// pbrt-v4 does): reconnects every second while tev is not there, and says so once.
    fn stream_to_tev(&self, address: &str) {
        let name = self.options.scene.display().to_string();
        let mut display: Option<tev::Display> = None;
        let mut shown = String::new();
        let mut warned = false;
        loop {
            std::thread::sleep(Duration::from_millis(250));
            let (key, preview) = {
                let s = lock(&self.status);
                (picture_key(&s), s.preview.clone())
            };
            let Some(preview) = preview else { continue };
            if key == shown {
                continue;
            }
            if display.is_none() {
                match tev::Display::connect(address, &name) {
                    Ok(d) => display = Some(d),
                    Err(e) => {
                        if !warned {
                            eprintln!(
                                "warning: cannot reach tev at {address}: {e} (trying again every second)"
                            );
                            warned = true;
                        }
                        std::thread::sleep(Duration::from_millis(750));
                        continue;
                    }
                }
            }
            let shown_now = display.as_mut().map(|d| d.show(&preview.picture()));
            match shown_now {
                Some(Ok(())) => {
                    shown = key;
                    warned = false;
                }
                _ => display = None,
            }
        }
    }

    /// The status as JSON (`/status`, and each event of `/events`).
    fn status_json(&self) -> String {
        let s = lock(&self.status);
        let progress = match &s.progress {
            Some((p, total)) => {
                let done = p.pixels.load(std::sync::atomic::Ordering::Relaxed);
                done as f64 / (*total).max(1) as f64
            }
            None if s.phase == Phase::Done => 1.0,
            None => 0.0,
        };
        let messages = |list: &[Message]| {
            let items: Vec<String> = list
                .iter()
                .map(|m| {
                    let (file, line, column) = match &m.place {
                        Some((f, l, c)) => (json_string(f), l.to_string(), c.to_string()),
                        None => ("null".into(), "null".into(), "null".into()),
                    };
                    format!(
                        "{{\"severity\":{},\"message\":{},\"file\":{file},\"line\":{line},\"column\":{column},\"text\":{}}}",
                        json_string(m.severity),
                        json_string(&m.message),
                        json_string(&m.text)
                    )
                })
                .collect();
            format!("[{}]", items.join(","))
        };
        let timings: Vec<String> = s
            .timings
            .iter()
            .map(|(k, v)| format!("{}:{v:.4}", json_string(k)))
            .collect();
        let files: Vec<String> = s
            .files
            .iter()
            .map(|f| json_string(&f.display().to_string()))
            .collect();
        let st = &s.settings;
        format!(
            "{{\"id\":{},\"state\":\"{}\",\"pass\":\"{}\",\"progress\":{progress:.4},\"picture\":{},\"picture_id\":{},\"width\":{},\"height\":{},\"settings\":{{\"width\":{},\"height\":{},\"aa\":{},\"depth\":{},\"clock\":{}}},\"errors\":{},\"warnings\":{},\"debug\":{},\"timings\":{{{}}},\"built\":{},\"kept\":{},\"files\":[{}],\"scene\":{}}}",
            s.id,
            s.phase.name(),
            s.pass,
            json_string(&picture_key(&s)),
            s.picture_id,
            st.width,
            st.height,
            st.width,
            st.height,
            match st.aa {
                Some(t) => json_string(&t.to_string()),
                None => "\"off\"".into(),
            },
            st.aa_depth,
            match st.clock {
                Some(c) => c.to_string(),
                None => "null".into(),
            },
            messages(&s.errors),
            messages(&s.warnings),
            json_string(&s.debug),
            timings.join(","),
            s.built,
            match s.kept {
                Some(k) => format!(
                    "{{\"shapes\":{},\"objects\":{},\"tree\":{}}}",
                    k.shapes, k.objects, k.tree
                ),
                None => "null".into(),
            },
            files.join(","),
            json_string(&self.options.scene.display().to_string()),
        )
    }

    /// The picture shown, as PNG bytes, with its key; `None` before the first picture.
    fn picture_png(&self) -> Option<(String, Arc<Vec<u8>>)> {
        let (key, preview) = {
            let s = lock(&self.status);
            (picture_key(&s), s.preview.clone()?)
        };
        let mut cached = lock(&self.png);
        if cached.0 != key {
            *cached = (key.clone(), Arc::new(preview.picture().to_png()));
        }
        Some((key, cached.1.clone()))
    }
}

/// A key that changes whenever the picture shown does: which picture, and how many of its
/// blocks are in.
fn picture_key(s: &Status) -> String {
    match &s.preview {
        Some(p) => format!("{}-{}", s.pictures, p.blocks()),
        None => String::new(),
    }
}

/// A load or render error for the page, with its place.
fn error_message(e: &Error) -> Message {
    match e {
        Error::Scene(e) => {
            let d = &e.diagnostic;
            let place = d.span.map(|span| {
                let (line, column) = e.sources.line_col(span.file, span.start);
                let file = e.sources.file(span.file).path.display().to_string();
                (file, line, column)
            });
            Message {
                severity: "error",
                message: d.message.clone(),
                place,
                text: e.to_string(),
            }
        }
        other => Message {
            severity: "error",
            message: other.to_string(),
            place: None,
            text: format!("error: {other}"),
        },
    }
}

/// A warning (rendered by the loader) for the page: its place read back from its first line
/// (`warning: … --> file:line:column`).
fn warning_message(text: &str) -> Message {
    let message = text
        .lines()
        .next()
        .unwrap_or("")
        .trim_start_matches("warning: ")
        .to_string();
    let place = text.lines().find_map(|l| {
        let at = l.trim_start().strip_prefix("--> ")?;
        let mut parts = at.rsplitn(3, ':');
        let column = parts.next()?.trim().parse().ok()?;
        let line = parts.next()?.parse().ok()?;
        Some((parts.next()?.to_string(), line, column))
    });
    Message {
        severity: "warning",
        message,
        place,
        text: text.trim_end().to_string(),
    }
}

/// `s` as a JSON string.
fn json_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if (c as u32) < 0x20 || c == '\u{2028}' || c == '\u{2029}' => {
                out.push_str(&format!("\\u{:04x}", c as u32))
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Runs `trace watch` until the process is stopped: binds the server (an error if the
/// address is taken), prints its address, and serves.
pub fn run(options: Options) -> Result<(), String> {
    if !options.scene.is_file() {
        return Err(format!(
            "cannot read {}: no such file",
            options.scene.display()
        ));
    }
    let address = SocketAddr::new(options.bind, options.port);
    let listener =
        TcpListener::bind(address).map_err(|e| format!("cannot listen on {address}: {e}"))?;
    let bound = listener
        .local_addr()
        .map_err(|e| format!("cannot listen on {address}: {e}"))?;
    let host = match bound.ip() {
        IpAddr::V6(ip) => format!("[{ip}]"),
        IpAddr::V4(ip) => ip.to_string(),
    };
    // (The first line on standard error: scripts and tests read the address from it.)
    eprintln!(
        "trace: watching {} at http://{host}:{}/ (Ctrl-C stops)",
        options.scene.display(),
        bound.port()
    );
    let session = Arc::new(Session::new(options));
    let renderer = session.clone();
    std::thread::Builder::new()
        .name("trace-watch-render".into())
        .spawn(move || renderer.run())
        .map_err(|e| format!("cannot start a thread: {e}"))?;
    let watcher = session.clone();
    std::thread::Builder::new()
        .name("trace-watch-files".into())
        .spawn(move || watcher.watch())
        .map_err(|e| format!("cannot start a thread: {e}"))?;
    if let Some(address) = session.options.tev.clone() {
        let streamer = session.clone();
        std::thread::Builder::new()
            .name("trace-watch-tev".into())
            .spawn(move || streamer.stream_to_tev(&address))
            .map_err(|e| format!("cannot start a thread: {e}"))?;
    }
    http::serve(listener, bound.port(), session);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings() -> Settings {
        Settings {
            width: 320,
            height: 240,
            aa: Some(0.3),
            aa_depth: 3,
            clock: None,
        }
    }

    #[test]
    fn settings_are_read_from_a_query_and_checked() {
        let s = settings()
            .updated("width=64&height=48&aa=off&clock=0.5")
            .unwrap();
        assert_eq!(
            (s.width, s.height, s.aa, s.clock),
            (64, 48, None, Some(0.5))
        );
        let s = settings().updated("aa=0.1&depth=2&clock=").unwrap();
        assert_eq!((s.aa, s.aa_depth, s.clock), (Some(0.1), 2, None));
        assert!(settings().updated("width=0").is_err());
        assert!(settings().updated("width=9000").is_err());
        assert!(settings().updated("depth=10").is_err());
        assert!(settings().updated("aa=-1").is_err());
        assert!(settings().updated("clock=nan").is_err());
        assert!(settings().updated("colour=red").is_err());
    }

    #[test]
    fn json_strings_escape_what_json_needs() {
        assert_eq!(json_string("a\"b\\c\nd\u{1}"), "\"a\\\"b\\\\c\\nd\\u0001\"");
    }

    #[test]
    fn a_warning_keeps_its_place() {
        let m = warning_message("warning: odd\n  --> scenes/a b.rt:3:7\n   |\n");
        assert_eq!(m.message, "odd");
        assert_eq!(m.place, Some(("scenes/a b.rt".into(), 3, 7)));
    }
}
