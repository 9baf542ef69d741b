//! Parsing ahead: helper threads parse the later parts of a big file while the caller
//! evaluates the earlier ones.
//!
//! Which statements a file holds does not depend on evaluation (declarations, macros and
//! includes are resolved later), so the statements after any statement end can be parsed on
//! their own. A part starts at a guessed statement end, the end of a top-level `{ … }` block
//! that [`check_nesting`](super::check_nesting) found; [`Statements`](super::Statements) uses
//! the part only if the statement before it ends exactly there, which makes the result the
//! same as one thread's whatever the guesses.

use super::{Diagnostic, Lower, Node, next_statement};
use crate::diag::FileId;
use std::collections::VecDeque;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;

/// Files smaller than this are parsed by one thread (a helper would not pay for itself).
const MIN_BYTES: usize = 1 << 18;

/// Helpers at most: the caller evaluates every statement, so beyond a few parts its own
/// evaluation is the limit.
const MAX_HELPERS: usize = 3;

/// Stack for a helper: parsing recurses a few frames per nesting level, and nesting is bounded
/// by [`MAX_NESTING`](super::MAX_NESTING). Only the pages used are committed.
const STACK_BYTES: usize = 256 << 20;

/// One part of the file being parsed by a helper thread.
pub(super) struct Part {
    /// Byte offset where the part starts (a guessed statement end).
    pub start: usize,
    cancel: Arc<AtomicBool>,
    handle: Option<JoinHandle<Parsed>>,
}

/// What a helper read.
pub(super) struct Parsed {
    /// The statements, in order; an error, if any, is the last.
    pub statements: Vec<Result<Node, Diagnostic>>,
    /// Where the last statement ends.
    pub end: usize,
    /// The file ends (or has a syntax error) there: no statement follows.
    pub last: bool,
}

impl Part {
    /// Waits for the helper and takes its statements.
    pub fn finish(mut self) -> Parsed {
        let handle = self.handle.take().expect("a part is finished once");
        handle
            .join()
            .unwrap_or_else(|panic| std::panic::resume_unwind(panic))
    }
}

impl Drop for Part {
    /// An unused part (a wrong guess, or evaluation stopped early): the helper stops after
    /// its current statement.
    fn drop(&mut self) {
        if let Some(handle) = self.handle.take() {
            self.cancel.store(true, Ordering::Relaxed);
            let _ = handle.join();
        }
    }
}

/// Starts up to `helpers` threads on later parts of `source`, given where its top-level blocks
/// end. The caller parses the first part itself.
pub(super) fn start(
    source: &Arc<str>,
    file: FileId,
    block_ends: &[usize],
    helpers: usize,
) -> VecDeque<Part> {
    let helpers = helpers.min(MAX_HELPERS);
    if helpers == 0 || source.len() < MIN_BYTES {
        return VecDeque::new();
    }
    // The caller also evaluates, but a helper reads a statement about 1.4× slower than the
    // caller (it keeps what it read in fresh memory until the caller arrives), so the caller
    // takes the larger share: 0.6 of the file with one helper, which on 100k spheres has the
    // caller arrive within a millisecond of the helper's end.
    let parts = helpers + 1;
    let first = 1.2 / parts as f64;
    let mut starts: Vec<usize> = Vec::new();
    for i in 0..helpers {
        let fraction = first + (1.0 - first) * i as f64 / helpers as f64;
        let target = (fraction * source.len() as f64) as usize;
        let at = block_ends.partition_point(|&end| end < target);
        let start = block_ends[at..]
            .iter()
            .copied()
            .find(|&end| !followed_by_semicolon(source.as_bytes(), end));
        match start {
            Some(start) if starts.last().is_none_or(|&last| start > last) => starts.push(start),
            _ => {}
        }
    }
    spawn(source, file, &starts)
}

/// Starts a helper at each of `starts` (increasing byte offsets), each reading up to the next.
pub(super) fn spawn(source: &Arc<str>, file: FileId, starts: &[usize]) -> VecDeque<Part> {
    let mut ahead = VecDeque::new();
    for (i, &start) in starts.iter().enumerate() {
        let stop = starts.get(i + 1).copied().unwrap_or(usize::MAX);
        let cancel = Arc::new(AtomicBool::new(false));
        let (source, flag) = (Arc::clone(source), Arc::clone(&cancel));
        let spawned = std::thread::Builder::new()
            .name("trace-parse".into())
            .stack_size(STACK_BYTES)
            .spawn(move || parse_part(&source, file, start, stop, &flag));
        // (Without a helper, the caller reads that part itself.)
        if let Ok(handle) = spawned {
            ahead.push_back(Part {
                start,
                cancel,
                handle: Some(handle),
            });
        }
    }
    ahead
}

/// `declare X = sphere {…};`: the statement ends after the `;`, not after the `}`.
fn followed_by_semicolon(bytes: &[u8], at: usize) -> bool {
    bytes[at..]
        .iter()
        .find(|b| !b.is_ascii_whitespace())
        .is_some_and(|&b| b == b';')
}

/// Parses the statements from `start` until one ends at or after `stop`, or the file ends.
fn parse_part(
    source: &str,
    file: FileId,
    start: usize,
    stop: usize,
    cancel: &AtomicBool,
) -> Parsed {
    let mut lower = Lower {
        file,
        offset: start,
        bulk: Default::default(),
    };
    let mut statements = Vec::new();
    let mut pos = start;
    while pos < stop && !cancel.load(Ordering::Relaxed) {
        match next_statement(source, pos, &mut lower) {
            None => {
                return Parsed {
                    statements,
                    end: pos,
                    last: true,
                };
            }
            Some(Err(e)) => {
                statements.push(Err(e));
                return Parsed {
                    statements,
                    end: pos,
                    last: true,
                };
            }
            Some(Ok((node, end))) => {
                statements.push(Ok(node));
                pos = end;
            }
        }
    }
    Parsed {
        statements,
        end: pos,
        last: false,
    }
}
