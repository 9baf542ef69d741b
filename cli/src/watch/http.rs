//! The watch server: a small HTTP/1.1 server on std's sockets, one thread a connection, one
//! request a connection (`Connection: close`).
//!
//! - `GET /`: the page (no other file is served: nothing of the disk is reachable);
//! - `GET /image.png`: the picture shown now (404 before the first);
//! - `GET /status`: the status as JSON;
//! - `GET /events`: the status again at every change, as server-sent events;
//! - `POST /settings?width=…&height=…&aa=…&depth=…&clock=…`: new settings, a new render.
//!
//! Requests must name this machine as their host (`127.0.0.1`, `localhost`, `[::1]`) unless
//! `--bind` chose the address: a page elsewhere cannot reach the server through a name that
//! resolves here (DNS rebinding).

use super::{Session, lock};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Connections served at once at most: more are closed at once.
const MAX_CONNECTIONS: usize = 64;

/// The largest request head read.
const MAX_HEAD: usize = 16 * 1024;

const PAGE: &str = include_str!("page.html");

/// Serves until the process ends.
pub fn serve(listener: TcpListener, port: u16, session: Arc<Session>) {
    let open = Arc::new(AtomicUsize::new(0));
    for stream in listener.incoming() {
        let Ok(stream) = stream else { continue };
        if open.load(Ordering::SeqCst) >= MAX_CONNECTIONS {
            continue; // (dropped: closed)
        }
        open.fetch_add(1, Ordering::SeqCst);
        let (session, counted) = (session.clone(), open.clone());
        let spawned = std::thread::Builder::new()
            .name("trace-watch-http".into())
            .spawn(move || {
                // (A client gone mid-answer is an error here and nothing more.)
                let _ = answer(stream, port, &session);
                counted.fetch_sub(1, Ordering::SeqCst);
            });
        if spawned.is_err() {
            open.fetch_sub(1, Ordering::SeqCst);
        }
    }
}

/// A request's method, path and query.
struct Request {
    method: String,
    path: String,
    query: String,
    host: Option<String>,
}

/// Reads a request head: the request line and the headers, at most [`MAX_HEAD`] bytes.
fn read_head(stream: &TcpStream) -> std::io::Result<Option<Request>> {
    let mut reader = BufReader::new(stream.take(MAX_HEAD as u64));
    let mut line = String::new();
    if reader.read_line(&mut line)? == 0 {
        return Ok(None);
    }
    let mut words = line.split_whitespace();
    let (Some(method), Some(target)) = (words.next(), words.next()) else {
        return Ok(None);
    };
    let (path, query) = target.split_once('?').unwrap_or((target, ""));
    let mut request = Request {
        method: method.to_string(),
        path: path.to_string(),
        query: query.to_string(),
        host: None,
    };
    loop {
        let mut header = String::new();
        if reader.read_line(&mut header)? == 0 {
            return Ok(None); // cut short, or longer than MAX_HEAD
        }
        let header = header.trim_end();
        if header.is_empty() {
            return Ok(Some(request));
        }
        if let Some((name, value)) = header.split_once(':') {
            if name.trim().eq_ignore_ascii_case("host") {
                request.host = Some(value.trim().to_ascii_lowercase());
            }
        }
    }
}

/// Whether `host` (a Host header) names this machine at `port`.
fn local_host(host: &str, port: u16) -> bool {
    ["127.0.0.1", "localhost", "[::1]"]
        .iter()
        .any(|name| host == *name || host == format!("{name}:{port}"))
}

fn respond(
    stream: &mut TcpStream,
    status: &str,
    kind: &str,
    body: &[u8],
    head_only: bool,
) -> std::io::Result<()> {
    let head = format!(
        "HTTP/1.1 {status}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n",
        body.len()
    );
    stream.write_all(head.as_bytes())?;
    if !head_only {
        stream.write_all(body)?;
    }
    stream.flush()
}

fn answer(mut stream: TcpStream, port: u16, session: &Session) -> std::io::Result<()> {
    stream.set_read_timeout(Some(Duration::from_secs(5)))?;
    stream.set_write_timeout(Some(Duration::from_secs(10)))?;
    let Some(request) = read_head(&stream)? else {
        return respond(
            &mut stream,
            "400 Bad Request",
            "text/plain",
            b"bad request\n",
            false,
        );
    };
    let host_ok =
        session.options.bind_given || request.host.as_deref().is_some_and(|h| local_host(h, port));
    if !host_ok {
        return respond(
            &mut stream,
            "403 Forbidden",
            "text/plain",
            b"this server answers only requests for 127.0.0.1 or localhost\n",
            false,
        );
    }
    let head_only = request.method == "HEAD";
    match (request.method.as_str(), request.path.as_str()) {
        ("GET" | "HEAD", "/") => respond(
            &mut stream,
            "200 OK",
            "text/html; charset=utf-8",
            PAGE.as_bytes(),
            head_only,
        ),
        ("GET" | "HEAD", "/status") => respond(
            &mut stream,
            "200 OK",
            "application/json",
            session.status_json().as_bytes(),
            head_only,
        ),
        ("GET" | "HEAD", "/image.png") => match session.picture_png() {
            Some((_, png)) => respond(&mut stream, "200 OK", "image/png", &png, head_only),
            None => respond(
                &mut stream,
                "404 Not Found",
                "text/plain",
                b"no picture yet\n",
                head_only,
            ),
        },
        ("GET", "/events") => events(stream, session),
        ("POST", "/settings") => {
            let current = lock(&session.request).settings.clone();
            match current.updated(&request.query) {
                Ok(settings) => {
                    if settings != current {
                        session.ask(Some(settings));
                    }
                    respond(
                        &mut stream,
                        "200 OK",
                        "application/json",
                        session.status_json().as_bytes(),
                        false,
                    )
                }
                Err(e) => respond(
                    &mut stream,
                    "400 Bad Request",
                    "text/plain; charset=utf-8",
                    format!("{e}\n").as_bytes(),
                    false,
                ),
            }
        }
        (_, "/" | "/status" | "/image.png" | "/events" | "/settings") => respond(
            &mut stream,
            "405 Method Not Allowed",
            "text/plain",
            b"method not allowed\n",
            false,
        ),
        _ => respond(
            &mut stream,
            "404 Not Found",
            "text/plain",
            b"not found\n",
            false,
        ),
    }
}

/// The event stream: the status whenever it changes (at most twenty times a second while
/// blocks come in), and a comment every ten seconds otherwise; ends when the client goes.
fn events(mut stream: TcpStream, session: &Session) -> std::io::Result<()> {
    stream.write_all(
        b"HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n",
    )?;
    let mut last = String::new();
    let mut spoke = Instant::now();
    loop {
        let json = session.status_json();
        if json != last {
            stream.write_all(format!("data: {json}\n\n").as_bytes())?;
            stream.flush()?;
            last = json;
            spoke = Instant::now();
        } else if spoke.elapsed() > Duration::from_secs(10) {
            stream.write_all(b": still here\n\n")?;
            stream.flush()?;
            spoke = Instant::now();
        }
        // Woken by a status change, or after 50 ms to see blocks come in.
        let status = lock(&session.status);
        let _ = session
            .changed
            .wait_timeout(status, Duration::from_millis(50));
    }
}

#[cfg(test)]
mod tests {
    use super::local_host;

    #[test]
    fn only_this_machine_is_a_local_host() {
        for host in [
            "127.0.0.1:8080",
            "localhost:8080",
            "[::1]:8080",
            "localhost",
        ] {
            assert!(local_host(host, 8080), "{host}");
        }
        for host in [
            "evil.example:8080",
            "127.0.0.1:9090",
            "localhost.evil.example:8080",
            "192.168.1.2:8080",
        ] {
            assert!(!local_host(host, 8080), "{host}");
        }
    }
}
