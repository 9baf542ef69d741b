//! `trace watch`: its HTTP interface (the picture, the status, the event stream, settings,
//! who may ask), saves of the scene and of what it includes, a flood of saves, a scene that
//! never finishes loading; and the page itself in real browsers, headless: Chromium driven
//! through its DevTools protocol and Firefox through WebDriver BiDi. Each runs where its
//! browser is installed and is required when TRACE_REQUIRE_BROWSER names it (CI installs
//! both and names both).

use serde_json::Value;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A scene of one sphere lit by its ambient only, so the picture's centre is exactly the
/// sphere's colour; `pigment` is the pigment keyword as written (a misspelling breaks it on
/// line 4, column 17).
fn scene(pigment: &str, colour: &str) -> String {
    format!(
        "camera {{ location <0, 0, -5> look_at 0 angle 40 }}\n\
         light_source {{ <4, 8, -5>, rgb 1 }}\n\
         // the sphere\n\
         sphere {{ 0, 1.5 {pigment} {{ rgb {colour} }} finish {{ ambient 1 diffuse 0 }} }}\n"
    )
}

/// A scratch folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("trace-watch-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Writes a file as an editor saves it: the new text written beside it, then renamed into
/// place, so the watcher never reads half a file (a save written in place can be seen half
/// done, rendered, and rendered again when finished: a test waiting for the first render
/// after it would see the half one).
fn save(path: &Path, text: &str) {
    let beside = path.with_extension("saving");
    std::fs::write(&beside, text).unwrap();
    std::fs::rename(&beside, path).unwrap();
}

/// A running `trace watch`, stopped when dropped.
struct Watch {
    child: Child,
    port: u16,
}

impl Watch {
    fn start(dir: &Path, args: &[&str]) -> Watch {
        let mut child = Command::new(env!("CARGO_BIN_EXE_trace"))
            .arg("watch")
            .args(args)
            .current_dir(dir)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .expect("trace runs");
        let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
        let first = lines.next().expect("a first line").unwrap();
        let port = first
            .split("http://127.0.0.1:")
            .nth(1)
            .and_then(|rest| rest.split('/').next())
            .and_then(|p| p.parse().ok())
            .unwrap_or_else(|| panic!("no local address in {first:?}"));
        // (The rest of standard error is read so that trace never waits on a full pipe.)
        std::thread::spawn(move || for _ in lines {});
        Watch { child, port }
    }

    /// A request's status code and body.
    fn request(&self, method: &str, path: &str, host: &str) -> (u16, Vec<u8>) {
        http(self.port, method, path, host)
    }

    fn get(&self, path: &str) -> (u16, Vec<u8>) {
        self.request("GET", path, &format!("127.0.0.1:{}", self.port))
    }

    fn status(&self) -> Value {
        let (code, body) = self.get("/status");
        assert_eq!(code, 200);
        serde_json::from_slice(&body).expect("the status is JSON")
    }

    /// The status once `done` says so (within a minute).
    fn wait(&self, what: &str, done: impl Fn(&Value) -> bool) -> Value {
        poll(
            &format!("the status to show {what}"),
            || self.status(),
            done,
        )
    }

    /// The picture shown now, decoded.
    fn picture(&self, dir: &Path) -> trace::Film {
        let (code, png) = self.get("/image.png");
        assert_eq!(code, 200, "{}", String::from_utf8_lossy(&png));
        let path = dir.join("shown.png");
        std::fs::write(&path, png).unwrap();
        trace::Film::read(&path).unwrap()
    }
}

impl Drop for Watch {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// What `look` sees once `done` says so, looking every 20 ms for a minute at most.
fn poll(what: &str, mut look: impl FnMut() -> Value, done: impl Fn(&Value) -> bool) -> Value {
    let start = Instant::now();
    loop {
        let seen = look();
        if done(&seen) {
            return seen;
        }
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "waited a minute for {what}; saw {seen:#}"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// One HTTP/1.1 request to 127.0.0.1:`port`; the status code and the body.
fn http(port: u16, method: &str, path: &str, host: &str) -> (u16, Vec<u8>) {
    let mut stream = TcpStream::connect(("127.0.0.1", port)).expect("the server is there");
    stream
        .set_read_timeout(Some(Duration::from_secs(30)))
        .unwrap();
    write!(
        stream,
        "{method} {path} HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    // The head, then as many bytes as it announces (Chromium keeps the connection open), or
    // all there is.
    let mut reader = BufReader::new(stream);
    let mut head = String::new();
    loop {
        let mut line = String::new();
        reader.read_line(&mut line).unwrap();
        if line.trim().is_empty() {
            break;
        }
        head += &line;
    }
    let code = head
        .split_whitespace()
        .nth(1)
        .and_then(|c| c.parse().ok())
        .expect("a status code");
    let length = head.lines().find_map(|l| {
        let (name, value) = l.split_once(':')?;
        name.eq_ignore_ascii_case("content-length")
            .then(|| value.trim().parse::<usize>().ok())?
    });
    let mut body = Vec::new();
    match length {
        Some(n) => {
            body.resize(n, 0);
            reader.read_exact(&mut body).unwrap();
        }
        None => {
            reader.read_to_end(&mut body).unwrap();
        }
    }
    (code, body)
}

/// What `trace scene.rt -o NAME --width W --height H` writes in `dir`, read back.
fn rendered(dir: &Path, name: &str, (width, height): (u32, u32)) -> trace::Film {
    let out = Command::new(env!("CARGO_BIN_EXE_trace"))
        .args(["scene.rt", "-o", name])
        .args([
            "--width",
            &width.to_string(),
            "--height",
            &height.to_string(),
        ])
        .current_dir(dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    trace::Film::read(&dir.join(name)).unwrap()
}

fn state(s: &Value) -> &str {
    s["state"].as_str().unwrap_or("")
}

/// The picture's centre pixel, in 8-bit sRGB.
fn centre(film: &trace::Film) -> [u8; 3] {
    let p = film.get(film.width / 2, film.height / 2);
    p.map(|v| (255.0 * trace::film::linear_to_srgb(f64::from(v)) + 0.5) as u8)
}

#[test]
fn the_page_s_picture_is_the_render_and_follows_saves_and_errors() {
    let dir = scratch("follow");
    let path = dir.join("scene.rt");
    save(&path, &scene("pigment", "<1, 0, 0>"));
    let watch = Watch::start(&dir, &["scene.rt", "--width", "64", "--height", "48"]);
    let first = watch.wait("the first render", |s| state(s) == "done");
    assert_eq!(first["settings"]["width"], 64);

    // The picture served is the picture `trace` renders with the same settings.
    let shown = watch.picture(&dir);
    let reference = rendered(&dir, "reference.png", (64, 48));
    assert_eq!((shown.width, shown.height), (64, 48));
    assert_eq!(shown.pixels, reference.pixels);
    assert_eq!(centre(&shown), [255, 0, 0]);

    // A broken save: the error with its place; the last picture stays.
    let (_, before) = watch.get("/image.png");
    save(&path, &scene("pigmnt", "<0, 0, 1>"));
    let broken = watch.wait("the error", |s| state(s) == "error");
    let error = &broken["errors"][0];
    assert_eq!(
        (error["line"].as_u64(), error["column"].as_u64()),
        (Some(4), Some(17))
    );
    assert!(
        error["file"].as_str().unwrap().ends_with("scene.rt"),
        "{error}"
    );
    let text = error["text"].as_str().unwrap();
    assert!(text.contains("pigmnt") && text.contains("^^^^^^"), "{text}");
    assert!(text.contains("did you mean `pigment`"), "{text}");
    assert_eq!(watch.get("/image.png"), (200, before));

    // Fixed: rendered again, the error gone.
    save(&path, &scene("pigment", "<0, 0, 1>"));
    let fixed = watch.wait("the fixed render", |s| {
        state(s) == "done" && s["id"].as_u64() > broken["id"].as_u64()
    });
    assert_eq!(fixed["errors"].as_array().map(Vec::len), Some(0));
    assert_eq!(centre(&watch.picture(&dir)), [0, 0, 255]);
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_camera_move_builds_nothing_else_and_a_light_edit_no_shape() {
    let dir = scratch("camera");
    let path = dir.join("scene.rt");
    let text = |camera: &str| {
        scene("pigment", "<1, 0, 0>").replace("location <0, 0, -5> look_at 0", camera)
            + "plane { y, -1.5 pigment { checker rgb 1, rgb 0.2 } }\n"
    };
    save(&path, &text("location <0, 0, -5> look_at 0"));
    let watch = Watch::start(&dir, &["scene.rt", "--width", "48", "--height", "36"]);
    let first = watch.wait("the first render", |s| state(s) == "done");
    assert_eq!(first["built"], true);
    save(&path, &text("location <1, 2, -5> look_at 0"));
    let moved = watch.wait("the moved camera's render", |s| {
        state(s) == "done" && s["id"].as_u64() > first["id"].as_u64()
    });
    assert_eq!(moved["built"], false, "only the camera changed: {moved}");
    assert_eq!(
        watch.picture(&dir).pixels,
        rendered(&dir, "moved.png", (48, 36)).pixels
    );
    // Anything else (a light) builds again, keeping the shapes whose geometry is unchanged
    // (all of them here) and the top-level tree.
    save(
        &path,
        &(text("location <1, 2, -5> look_at 0") + "light_source { <-3, 3, -3>, rgb 0.5 }\n"),
    );
    let lit = watch.wait("the render with another light", |s| {
        state(s) == "done" && s["id"].as_u64() > moved["id"].as_u64()
    });
    assert_eq!(lit["built"], true);
    assert_eq!(lit["kept"]["shapes"], 2, "{lit}");
    assert_eq!(lit["kept"]["objects"], 2, "{lit}");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_saved_include_renders_again() {
    let dir = scratch("include");
    save(
        &dir.join("colour.inc"),
        "#declare Colour = rgb <1, 0, 0>;\n",
    );
    save(
        &dir.join("scene.rt"),
        &format!("#include \"colour.inc\"\n{}", scene("pigment", "Colour")),
    );
    let watch = Watch::start(&dir, &["scene.rt", "--width", "32", "--height", "24"]);
    let first = watch.wait("the first render", |s| state(s) == "done");
    let files: Vec<&str> = first["files"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(Value::as_str)
        .collect();
    assert!(files.iter().any(|f| f.ends_with("colour.inc")), "{files:?}");
    assert_eq!(centre(&watch.picture(&dir)), [255, 0, 0]);
    save(
        &dir.join("colour.inc"),
        "#declare Colour = rgb <0, 1, 0>;\n",
    );
    watch.wait("the render after the include's save", |s| {
        state(s) == "done" && s["id"].as_u64() > first["id"].as_u64()
    });
    assert_eq!(centre(&watch.picture(&dir)), [0, 255, 0]);
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_file_the_scene_looked_for_renders_again_when_it_appears() {
    let dir = scratch("missing");
    save(
        &dir.join("scene.rt"),
        &format!(
            "#declare Colour = rgb <1, 0, 0>;\n\
             #if (file_exists(\"extra.inc\")) #include \"extra.inc\" #end\n{}",
            scene("pigment", "Colour")
        ),
    );
    let watch = Watch::start(&dir, &["scene.rt", "--width", "32", "--height", "24"]);
    let first = watch.wait("the first render", |s| state(s) == "done");
    assert_eq!(centre(&watch.picture(&dir)), [255, 0, 0]);
    save(&dir.join("extra.inc"), "#declare Colour = rgb <0, 0, 1>;\n");
    watch.wait("the render after the file appeared", |s| {
        state(s) == "done" && s["id"].as_u64() > first["id"].as_u64()
    });
    assert_eq!(centre(&watch.picture(&dir)), [0, 0, 255]);
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_flood_of_saves_ends_with_the_last_one_rendered() {
    let dir = scratch("flood");
    let path = dir.join("scene.rt");
    save(&path, &scene("pigment", "<1, 1, 1>"));
    let watch = Watch::start(&dir, &["scene.rt", "--width", "96", "--height", "72"]);
    watch.wait("the first render", |s| state(s) == "done");
    // Forty saves, 5 ms apart, every second one broken; the last green.
    for i in 0..40 {
        let text = if i % 2 == 1 {
            scene("pigmnt", "<1, 0, 0>")
        } else {
            scene("pigment", &format!("<{}, 0, 1>", i as f64 / 40.0))
        };
        save(&path, &text);
        std::thread::sleep(Duration::from_millis(5));
    }
    save(&path, &scene("pigment", "<0, 1, 0>"));
    let start = Instant::now();
    loop {
        let s = watch.wait("a finished render", |s| state(s) == "done");
        if centre(&watch.picture(&dir)) == [0, 255, 0] {
            assert_eq!(s["errors"].as_array().map(Vec::len), Some(0));
            break;
        }
        assert!(start.elapsed() < Duration::from_secs(60), "{s:#}");
        std::thread::sleep(Duration::from_millis(20));
    }
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_save_cancels_the_render_in_progress_at_once() {
    let dir = scratch("cancel");
    let path = dir.join("scene.rt");
    save(&path, &scene("pigment", "<1, 0, 0>"));
    // Every pixel supersampled to depth 9 (up to 1024 samples each): minutes of work.
    let watch = Watch::start(
        &dir,
        &[
            "scene.rt",
            "--width",
            "320",
            "--height",
            "240",
            "--aa",
            "0",
            "--aa-depth",
            "9",
        ],
    );
    let first = watch.wait("the anti-aliasing pass", |s| s["pass"] == "anti-aliasing");
    let saved = Instant::now();
    save(&path, &scene("pigment", "<0, 0, 1>"));
    // The new render's own pictures come while the old one would still be running.
    let second = watch.wait("the new render's pictures", |s| {
        s["picture_id"].as_u64() > first["id"].as_u64() && s["pass"] != "quick"
    });
    assert!(
        saved.elapsed() < Duration::from_secs(20),
        "the new render began {:?} after the save",
        saved.elapsed()
    );
    assert_ne!(
        state(&second),
        "done",
        "the second render is as long: still going"
    );
    assert_eq!(centre(&watch.picture(&dir)), [0, 0, 255]);
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_scene_that_never_finishes_loading_stops_at_its_budget() {
    let dir = scratch("endless");
    let path = dir.join("scene.rt");
    save(
        &path,
        "#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n#end\n",
    );
    let watch = Watch::start(&dir, &["scene.rt", "--max-steps", "100000"]);
    let s = watch.wait("the budget's error", |s| state(s) == "error");
    let message = s["errors"][0]["message"].as_str().unwrap();
    assert!(message.contains("budget"), "{message}");
    assert_eq!(watch.get("/image.png").0, 404, "no picture yet");
    save(&path, &scene("pigment", "<1, 0, 0>"));
    watch.wait("the render after the fix", |s| state(s) == "done");
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn the_server_answers_this_machine_and_outlives_its_clients() {
    let dir = scratch("server");
    let path = dir.join("scene.rt");
    save(&path, &scene("pigment", "<1, 0, 0>"));
    let watch = Watch::start(&dir, &["scene.rt", "--width", "40", "--height", "30"]);
    watch.wait("the first render", |s| state(s) == "done");
    let (code, page) = watch.get("/");
    assert_eq!(code, 200);
    assert!(String::from_utf8_lossy(&page).contains("EventSource"));
    // Another host name (a page elsewhere, through DNS rebinding), another path, another
    // method, a bad setting.
    let elsewhere = watch.request("GET", "/status", "evil.example");
    assert_eq!(elsewhere.0, 403);
    assert_eq!(watch.get("/../scene.rt").0, 404);
    assert_eq!(watch.get("/scene.rt").0, 404);
    let local = format!("localhost:{}", watch.port);
    assert_eq!(watch.request("DELETE", "/status", &local).0, 405);
    assert_eq!(watch.request("POST", "/settings?width=0", &local).0, 400);

    // Clients that leave: event streams dropped after their first event, and one that
    // never finishes its request.
    for _ in 0..5 {
        let mut stream = TcpStream::connect(("127.0.0.1", watch.port)).unwrap();
        write!(stream, "GET /events HTTP/1.1\r\nHost: {local}\r\n\r\n").unwrap();
        let mut first = [0u8; 64];
        stream.read_exact(&mut first).unwrap();
        assert!(first.starts_with(b"HTTP/1.1 200 OK"));
    }
    let mut idle = TcpStream::connect(("127.0.0.1", watch.port)).unwrap();
    idle.write_all(b"GET /sta").unwrap();

    // New settings: a new render at the new size.
    let (code, _) = watch.request("POST", "/settings?width=20&height=10&aa=off", &local);
    assert_eq!(code, 200);
    let s = watch.wait("the render at the new size", |s| {
        state(s) == "done" && s["settings"]["width"] == 20
    });
    assert_eq!(s["settings"]["aa"], "off");
    let film = watch.picture(&dir);
    assert_eq!((film.width, film.height), (20, 10));
    drop(idle);
    let _ = std::fs::remove_dir_all(dir);
}

/// The browser: Chromium headless, or `None` (where it is not installed).
/// The browsers the page is tested in.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// Driven through its DevTools protocol.
    Chromium,
    /// Driven through WebDriver BiDi (Firefox's remote protocol).
    Firefox,
}

impl Kind {
    /// The browser's program: `TRACE_CHROMIUM` or `TRACE_FIREFOX` if set, else Debian's.
    fn program(self) -> Option<PathBuf> {
        let (variable, installed) = match self {
            Kind::Chromium => (
                "TRACE_CHROMIUM",
                ["/usr/bin/chromium", "/usr/bin/chromium-browser"],
            ),
            Kind::Firefox => (
                "TRACE_FIREFOX",
                ["/usr/bin/firefox-esr", "/usr/bin/firefox"],
            ),
        };
        let named = std::env::var_os(variable).map(PathBuf::from);
        named
            .into_iter()
            .chain(installed.map(PathBuf::from))
            .find(|p| p.is_file())
    }
}

/// A WebSocket client, enough for Chromium's DevTools protocol and Firefox's WebDriver BiDi
/// (JSON commands with ids, answered by id): text frames, masked as a client's must be.
struct DevTools {
    reader: BufReader<TcpStream>,
    writer: TcpStream,
    next: u64,
    /// Under WebDriver BiDi, the browsing context (tab) scripts run in.
    context: Option<String>,
}

impl DevTools {
    fn connect(url: &str) -> DevTools {
        let rest = url.strip_prefix("ws://").expect("a ws:// address");
        let (host, path) = rest.split_at(rest.find('/').unwrap());
        let writer = TcpStream::connect(host).unwrap();
        writer
            .set_read_timeout(Some(Duration::from_secs(30)))
            .unwrap();
        let mut reader = BufReader::new(writer.try_clone().unwrap());
        let mut w = writer.try_clone().unwrap();
        write!(
            w,
            "GET {path} HTTP/1.1\r\nHost: {host}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n\
             Sec-WebSocket-Key: dHJhY2Ugd2F0Y2ggdGVzdA==\r\nSec-WebSocket-Version: 13\r\n\r\n"
        )
        .unwrap();
        let mut line = String::new();
        reader.read_line(&mut line).unwrap();
        assert!(line.contains(" 101 "), "the handshake: {line}");
        loop {
            line.clear();
            reader.read_line(&mut line).unwrap();
            if line.trim().is_empty() {
                break;
            }
        }
        DevTools {
            reader,
            writer,
            next: 1,
            context: None,
        }
    }

    fn send(&mut self, text: &str) {
        let bytes = text.as_bytes();
        let mut frame = vec![0x81u8];
        match bytes.len() {
            n if n < 126 => frame.push(0x80 | n as u8),
            n if n < 65536 => {
                frame.push(0x80 | 126);
                frame.extend((n as u16).to_be_bytes());
            }
            n => {
                frame.push(0x80 | 127);
                frame.extend((n as u64).to_be_bytes());
            }
        }
        let mask = [0x5a, 0x13, 0xc7, 0x2e];
        frame.extend(mask);
        frame.extend(bytes.iter().enumerate().map(|(i, b)| b ^ mask[i % 4]));
        self.writer.write_all(&frame).unwrap();
    }

    /// The next whole text message.
    fn receive(&mut self) -> String {
        let mut message = Vec::new();
        loop {
            let mut head = [0u8; 2];
            self.reader.read_exact(&mut head).unwrap();
            let len = match head[1] & 0x7f {
                126 => {
                    let mut n = [0u8; 2];
                    self.reader.read_exact(&mut n).unwrap();
                    u64::from(u16::from_be_bytes(n))
                }
                127 => {
                    let mut n = [0u8; 8];
                    self.reader.read_exact(&mut n).unwrap();
                    u64::from_be_bytes(n)
                }
                n => u64::from(n),
            };
            let mut payload = vec![0u8; len as usize];
            self.reader.read_exact(&mut payload).unwrap();
            if head[0] & 0x0f <= 2 {
                message.extend(payload);
                if head[0] & 0x80 != 0 {
                    return String::from_utf8(message).unwrap();
                }
            }
        }
    }

    /// Calls a method of the protocol and returns its result.
    fn call(&mut self, method: &str, params: Value) -> Value {
        let id = self.next;
        self.next += 1;
        let request = serde_json::json!({ "id": id, "method": method, "params": params });
        self.send(&request.to_string());
        loop {
            let reply: Value = serde_json::from_str(&self.receive()).unwrap();
            if reply["id"].as_u64() == Some(id) {
                assert!(reply.get("error").is_none(), "{method}: {reply}");
                return reply["result"].clone();
            }
        }
    }

    /// What the page shows: its state, the error box's text, and the centre pixel of the
    /// picture on screen (read back through a canvas).
    fn page(&mut self) -> Value {
        const LOOK: &str = "(() => {
            const img = document.getElementById('picture');
            let centre = null;
            if (!img.hidden && img.complete && img.naturalWidth > 0) {
                const c = document.createElement('canvas');
                c.width = img.naturalWidth; c.height = img.naturalHeight;
                const g = c.getContext('2d');
                g.drawImage(img, 0, 0);
                centre = Array.from(g.getImageData(c.width >> 1, c.height >> 1, 1, 1).data).slice(0, 3);
            }
            const error = document.getElementById('error');
            return JSON.stringify({
                state: document.body.dataset.state,
                error: error.hidden ? '' : error.textContent,
                centre,
            });
        })()";
        let r = match self.context.clone() {
            None => self.call(
                "Runtime.evaluate",
                serde_json::json!({ "expression": LOOK, "returnByValue": true }),
            ),
            Some(context) => self.call(
                "script.evaluate",
                serde_json::json!({
                    "expression": LOOK,
                    "target": { "context": context },
                    "awaitPromise": false,
                }),
            ),
        };
        // (Both protocols answer with the value at result.value.)
        serde_json::from_str(r["result"]["value"].as_str().unwrap_or("{}")).unwrap()
    }

    /// The page once `done` says so (within a minute).
    fn wait(&mut self, what: &str, done: impl Fn(&Value) -> bool) -> Value {
        poll(&format!("the page to show {what}"), || self.page(), done)
    }

    /// Opens `url` in a headless `kind` (its profile in `dir`): the browser and a client of
    /// its protocol driving the page.
    fn open(kind: Kind, program: &Path, dir: &Path, url: &str) -> (Browser, DevTools) {
        let profile = dir.join(format!("{kind:?}-profile"));
        std::fs::create_dir_all(&profile).unwrap();
        let mut command = Command::new(program);
        match kind {
            Kind::Chromium => command.args([
                "--headless=new".to_string(),
                "--no-sandbox".into(),
                "--disable-gpu".into(),
                "--no-first-run".into(),
                "--remote-debugging-port=0".into(),
                format!("--user-data-dir={}", profile.display()),
                "about:blank".into(),
            ]),
            Kind::Firefox => command
                .args([
                    "--headless",
                    "--no-remote",
                    "--remote-debugging-port=0",
                    "--profile",
                ])
                .arg(&profile)
                .arg("about:blank"),
        };
        let mut child = command
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap_or_else(|e| panic!("{kind:?} starts: {e}"));
        let stderr = child.stderr.take().unwrap();
        let browser = Browser(child);
        let mut lines = BufReader::new(stderr).lines();
        let said = match kind {
            Kind::Chromium => "DevTools listening on ",
            Kind::Firefox => "WebDriver BiDi listening on ",
        };
        let endpoint = lines
            .by_ref()
            .map_while(Result::ok)
            .find_map(|l| l.split(said).nth(1).map(|s| s.trim().to_string()))
            .unwrap_or_else(|| panic!("{kind:?} says where its protocol listens"));
        std::thread::spawn(move || for _ in lines {});
        let port: u16 = endpoint
            .trim_start_matches("ws://127.0.0.1:")
            .split('/')
            .next()
            .and_then(|p| p.parse().ok())
            .expect("a local port");
        let devtools = match kind {
            Kind::Chromium => {
                // The page target's own socket, from the browser's list of targets.
                let (_, list) = http(port, "GET", "/json/list", &format!("127.0.0.1:{port}"));
                let targets: Value = serde_json::from_slice(&list).unwrap();
                let page_socket = targets
                    .as_array()
                    .unwrap()
                    .iter()
                    .find(|t| t["type"] == "page")
                    .and_then(|t| t["webSocketDebuggerUrl"].as_str())
                    .expect("a page target")
                    .to_string();
                let mut devtools = DevTools::connect(&page_socket);
                devtools.call("Page.navigate", serde_json::json!({ "url": url }));
                devtools
            }
            Kind::Firefox => {
                let mut bidi = DevTools::connect(&format!("ws://127.0.0.1:{port}/session"));
                bidi.call("session.new", serde_json::json!({ "capabilities": {} }));
                let tree = bidi.call("browsingContext.getTree", serde_json::json!({}));
                let context = tree["contexts"][0]["context"]
                    .as_str()
                    .expect("a browsing context")
                    .to_string();
                bidi.call(
                    "browsingContext.navigate",
                    serde_json::json!({ "context": context, "url": url, "wait": "complete" }),
                );
                bidi.context = Some(context);
                bidi
            }
        };
        (browser, devtools)
    }
}

/// A headless browser, killed when dropped.
struct Browser(Child);

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

#[test]
fn the_page_in_chromium_shows_the_picture_the_error_and_the_fix() {
    the_page_shows_the_picture_the_error_and_the_fix(Kind::Chromium);
}

#[test]
fn the_page_in_firefox_shows_the_picture_the_error_and_the_fix() {
    the_page_shows_the_picture_the_error_and_the_fix(Kind::Firefox);
}

/// The page in a real browser: the picture, a broken save's located error over the last
/// picture, the fix. Where the browser is missing the test is skipped, unless
/// `TRACE_REQUIRE_BROWSER` names it (`chromium firefox`, as CI sets it) or is `1`.
fn the_page_shows_the_picture_the_error_and_the_fix(kind: Kind) {
    // (`1` requires every browser; otherwise the names of those required.)
    let required = std::env::var("TRACE_REQUIRE_BROWSER").is_ok_and(|v| {
        v == "1" || (v.split_whitespace()).any(|b| b.eq_ignore_ascii_case(&format!("{kind:?}")))
    });
    let Some(program) = kind.program() else {
        assert!(
            !required,
            "TRACE_REQUIRE_BROWSER requires {kind:?}, which is not installed"
        );
        eprintln!(
            "the {kind:?} test is skipped: install Debian's chromium and firefox-esr to run it"
        );
        return;
    };
    let dir = scratch(&format!("browser-{kind:?}"));
    let path = dir.join("scene.rt");
    save(&path, &scene("pigment", "<1, 0, 0>"));
    let watch = Watch::start(&dir, &["scene.rt", "--width", "96", "--height", "72"]);
    let url = format!("http://127.0.0.1:{}/", watch.port);
    let (browser, mut devtools) = DevTools::open(kind, &program, &dir, &url);

    // The picture.
    devtools.wait("the red sphere", |p| {
        p["state"] == "done" && p["centre"] == serde_json::json!([255, 0, 0])
    });
    // A broken save: the error with its line and caret above the last picture.
    save(&path, &scene("pigmnt", "<0, 0, 1>"));
    let p = devtools.wait("the error", |p| p["state"] == "error");
    let error = p["error"].as_str().unwrap();
    assert!(
        error.contains("scene.rt:4:17") && error.contains("^^^^^^"),
        "{error}"
    );
    assert_eq!(
        p["centre"],
        serde_json::json!([255, 0, 0]),
        "the last picture stays"
    );
    // Fixed: the new picture, no error.
    save(&path, &scene("pigment", "<0, 0, 1>"));
    let p = devtools.wait("the blue sphere", |p| {
        p["state"] == "done" && p["centre"] == serde_json::json!([0, 0, 255])
    });
    assert_eq!(p["error"], "");
    drop(devtools);
    drop(browser);
    let _ = std::fs::remove_dir_all(dir);
}

/// One tev packet read from `stream`: its type and body (after the type byte).
fn tev_packet(stream: &mut TcpStream) -> (u8, Vec<u8>) {
    let mut length = [0u8; 4];
    stream.read_exact(&mut length).unwrap();
    let length = u32::from_le_bytes(length) as usize;
    assert!((5..1 << 28).contains(&length), "a packet of {length} bytes");
    let mut body = vec![0u8; length - 4];
    stream.read_exact(&mut body).unwrap();
    (body[0], body[1..].to_vec())
}

/// Reads a NUL-ended string at `*at`.
fn tev_string(body: &[u8], at: &mut usize) -> String {
    let end = *at + body[*at..].iter().position(|&b| b == 0).expect("a NUL");
    let s = String::from_utf8(body[*at..end].to_vec()).unwrap();
    *at = end + 1;
    s
}

fn tev_i32(body: &[u8], at: &mut usize) -> i32 {
    let v = i32::from_le_bytes(body[*at..*at + 4].try_into().unwrap());
    *at += 4;
    v
}

#[test]
fn tev_is_sent_the_picture_as_its_protocol_says() {
    // A stand-in for tev: it accepts one connection and reads packets.
    let tev = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    let address = tev.local_addr().unwrap().to_string();
    let dir = scratch("tev");
    save(&dir.join("scene.rt"), &scene("pigment", "<1, 0.5, 0.25>"));
    let watch = Watch::start(
        &dir,
        &[
            "scene.rt", "--width", "150", "--height", "40", "--tev", &address,
        ],
    );
    watch.wait("the first render", |s| state(s) == "done");
    let (mut stream, _) = tev.accept().unwrap();
    stream
        .set_read_timeout(Some(Duration::from_secs(30)))
        .unwrap();
    // First the image, 150 x 40 with channels R, G, B, named after the scene, focused.
    let (kind, body) = tev_packet(&mut stream);
    assert_eq!(kind, 4, "create image first");
    assert_eq!(body[0], 1, "grab focus");
    let mut at = 1;
    assert_eq!(tev_string(&body, &mut at), "scene.rt");
    let size = [
        tev_i32(&body, &mut at),
        tev_i32(&body, &mut at),
        tev_i32(&body, &mut at),
    ];
    assert_eq!(size, [150, 40, 3]);
    let channels: Vec<String> = (0..3).map(|_| tev_string(&body, &mut at)).collect();
    assert_eq!(channels, ["R", "G", "B"]);
    assert_eq!(at, body.len());
    // Then tiles of each channel: read until every pixel holds the finished picture, the
    // linear values `trace` writes to an EXR with the same settings.
    let reference = rendered(&dir, "reference.exr", (150, 40));
    let mut image = vec![[f32::NAN; 3]; 150 * 40];
    let start = Instant::now();
    while image != reference.pixels {
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "tev never got the picture"
        );
        let (kind, body) = tev_packet(&mut stream);
        assert_eq!(kind, 3, "then updates");
        assert_eq!(body[0], 0, "updates do not grab focus");
        let mut at = 1;
        assert_eq!(tev_string(&body, &mut at), "scene.rt");
        let channel = tev_string(&body, &mut at);
        let c = ["R", "G", "B"]
            .iter()
            .position(|n| *n == channel)
            .expect("a channel of the image");
        let [x, y, w, h] = [0; 4].map(|_| tev_i32(&body, &mut at) as usize);
        assert!(
            x + w <= 150 && y + h <= 40 && w <= 128 && h <= 128,
            "{x} {y} {w} {h}"
        );
        assert_eq!(body.len() - at, 4 * w * h, "one float a pixel");
        for (k, v) in body[at..].chunks_exact(4).enumerate() {
            image[(y + k / w) * 150 + x + k % w][c] = f32::from_le_bytes(v.try_into().unwrap());
        }
    }
    let _ = std::fs::remove_dir_all(dir);
}
