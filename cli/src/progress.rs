//! A progress line on a terminal: pixels done, rays per second and the time left, redrawn
//! five times a second on stderr while a render runs.

use std::io::Write;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};
use std::time::{Duration, Instant};

/// The running progress line; dropping it stops it and clears the line.
pub struct Meter {
    done: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Meter {
    /// Shows the progress of a render of `total` pixels.
    pub fn start(progress: Arc<trace::Progress>, total: u64) -> Meter {
        let done = Arc::new(AtomicBool::new(false));
        let stop = done.clone();
        let thread = std::thread::spawn(move || {
            let start = Instant::now();
            while !stop.load(Relaxed) {
                let pixels = progress.pixels.load(Relaxed);
                let rays = progress.rays.load(Relaxed);
                eprint!("\r\x1b[K{}", line(pixels, total, rays, start.elapsed()));
                let _ = std::io::stderr().flush();
                std::thread::park_timeout(Duration::from_millis(200));
            }
            eprint!("\r\x1b[K");
        });
        Meter {
            done,
            thread: Some(thread),
        }
    }
}

impl Drop for Meter {
    fn drop(&mut self) {
        self.done.store(true, Relaxed);
        if let Some(t) = self.thread.take() {
            t.thread().unpark();
            let _ = t.join();
        }
    }
}

/// `trace: 37% (113664/307200 pixels), 2.1M rays/s, 0:04 left`.
fn line(pixels: u64, total: u64, rays: u64, elapsed: Duration) -> String {
    let secs = elapsed.as_secs_f64().max(1e-3);
    let share = pixels as f64 / total.max(1) as f64;
    let left = if pixels == 0 {
        "…".to_string()
    } else {
        let s = (secs / share - secs).max(0.0) as u64;
        format!("{}:{:02} left", s / 60, s % 60)
    };
    let rate = rays as f64 / secs;
    let rate = if rate >= 1e6 {
        format!("{:.1}M", rate / 1e6)
    } else {
        format!("{:.0}k", rate / 1e3)
    };
    format!(
        "trace: {:>3.0}% ({pixels}/{total} pixels), {rate} rays/s, {left}",
        100.0 * share
    )
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_line_says_share_rate_and_time_left() {
        let l = super::line(50, 200, 3_000_000, std::time::Duration::from_secs(2));
        assert_eq!(l, "trace:  25% (50/200 pixels), 1.5M rays/s, 0:06 left");
    }
}
