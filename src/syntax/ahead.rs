//! Parsing ahead: helper threads parse a big file in chunks while the caller evaluates the
//! statements already parsed.
//!
//! Which statements a file holds does not depend on evaluation (declarations, macros and
//! includes are resolved later), so the statements after any statement end can be parsed on
//! their own. The file is cut into chunks at guessed statement ends, the ends of top-level
//! `{ … }` blocks that [`check_nesting`](super::check_nesting) found; helpers parse the chunks
//! in file order (helper `h` of `H` takes chunks `h`, `h + H`, …) and hand each over through
//! a channel that holds one finished chunk, so at most two chunks a helper wait in memory
//! whatever the file's size. [`Statements`](super::Statements) uses a chunk only if the
//! statement before it ends exactly at its start, which makes the result the same as one
//! thread's whatever the guesses.

use super::{Diagnostic, Lower, Node, next_statement, plain, statement_batch};
use crate::diag::FileId;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, Sender, SyncSender, channel, sync_channel};
use std::thread::JoinHandle;

/// Files smaller than this are parsed by one thread (a helper would not pay for itself).
const MIN_BYTES: usize = 1 << 18;

/// Chunk size: big enough that handing a chunk over costs nothing next to parsing it, small
/// enough that the chunks waiting in memory stay small (about 3,000 plain statements).
const CHUNK_BYTES: usize = 1 << 18;

/// Helpers at most: evaluating a statement takes about a sixth of the time parsing it through
/// the grammar does, so beyond six helpers the evaluating thread would be the limit (measured
/// on two cores only, where two helpers run).
const MAX_HELPERS: usize = 6;

/// Evaluated statements handed back to their helper at a time.
const GIVE_BACK_BATCH: usize = 256;

/// Stack for a helper: parsing recurses a few frames per nesting level, and nesting is bounded
/// by [`MAX_NESTING`](super::MAX_NESTING). Only the pages used are committed.
const STACK_BYTES: usize = 256 << 20;

/// What a helper read of one chunk.
pub(super) struct Parsed {
    /// The statements, in order; an error, if any, is the last.
    pub statements: Vec<Result<Node, Diagnostic>>,
    /// Where the last statement ends.
    pub end: usize,
    /// The file ends (or has a syntax error) there: no statement follows.
    pub last: bool,
}

/// The chunks being parsed by helper threads, handed over in file order.
#[derive(Default)]
pub(super) struct Ahead {
    /// Where each chunk starts (increasing byte offsets).
    starts: Vec<usize>,
    /// The next chunk to hand over.
    next: usize,
    /// Helper `h` sends chunks `h`, `h + H`, … in order.
    from_helpers: Vec<Receiver<Parsed>>,
    /// Evaluated statements going back to the helper that parsed them, to be freed there,
    /// in batches.
    to_helpers: Vec<Sender<Vec<Node>>>,
    spent: Vec<Node>,
    spent_from: usize,
    cancel: Arc<AtomicBool>,
    helpers: Vec<JoinHandle<()>>,
}

impl Ahead {
    /// Where the next chunk starts, if there is one.
    pub fn next_start(&self) -> Option<usize> {
        self.starts.get(self.next).copied()
    }

    /// Waits for the next chunk and takes it, with the helper that parsed it (`None` if that
    /// helper could not parse it, which leaves that part to the caller).
    pub fn take(&mut self) -> (usize, Option<Parsed>) {
        let k = self.next;
        self.next += 1;
        let helper = k % self.from_helpers.len().max(1);
        let parsed = self.from_helpers.get(helper).and_then(|r| r.recv().ok());
        (helper, parsed)
    }

    /// Hands a statement that `helper` parsed back to it, to be freed on its thread.
    pub fn give_back(&mut self, helper: usize, statement: Node) {
        if helper != self.spent_from || self.spent.len() >= GIVE_BACK_BATCH {
            self.flush_spent();
            self.spent_from = helper;
        }
        self.spent.push(statement);
    }

    fn flush_spent(&mut self) {
        if self.spent.is_empty() {
            return;
        }
        let batch = std::mem::take(&mut self.spent);
        if let Some(to_helper) = self.to_helpers.get(self.spent_from) {
            // (A helper that has finished frees nothing more: the batch is freed here.)
            let _ = to_helper.send(batch);
        }
    }
}

impl Drop for Ahead {
    /// Evaluation stopped early (an error, or the caller is done): the helpers stop after
    /// their current statement.
    fn drop(&mut self) {
        self.flush_spent();
        self.cancel.store(true, Ordering::Relaxed);
        // (Dropping the receivers unblocks a helper waiting to hand a chunk over.)
        self.from_helpers.clear();
        self.to_helpers.clear();
        for handle in self.helpers.drain(..) {
            let _ = handle.join();
        }
    }
}

/// Starts up to `helpers` threads parsing `source` from byte `from` (where a statement
/// starts) in chunks, given where its top-level blocks end after `from`. With helpers, the first chunk
/// starts at `from`: the caller only evaluates.
pub(super) fn start(
    source: &Arc<str>,
    file: FileId,
    block_ends: &[usize],
    helpers: usize,
    from: usize,
) -> Ahead {
    if helpers == 0 || source.len() - from < MIN_BYTES {
        return Ahead::default();
    }
    // Parsing through the grammar takes about six times as long as evaluating, so every
    // core parses (the evaluating thread mostly waits; 1M spheres on two cores: 1.66 s
    // against 2.77 s with one helper). Statements of the fast lane take less time to parse
    // than to evaluate: then the evaluating thread is the limit and gets a core of its own
    // (100 MB of spheres on two cores: 0.83 s against 0.96-1.34 s with two helpers).
    let helpers = if mostly_plain(source, file, block_ends, from) {
        helpers - 1
    } else {
        helpers
    };
    let helpers = helpers.clamp(1, MAX_HELPERS);
    let mut starts = vec![from];
    let mut target = from + CHUNK_BYTES;
    let bytes = source.as_bytes();
    for &end in block_ends {
        if end >= target && !followed_by_semicolon(bytes, end) {
            starts.push(end);
            target = end + CHUNK_BYTES;
        }
    }
    spawn_helpers(source, file, &starts, helpers)
}

/// Helpers parsing the chunks that start at each of `starts` (increasing byte offsets), one
/// helper a chunk up to the most helpers (tests choose the starts).
#[cfg(test)]
pub(super) fn spawn(source: &Arc<str>, file: FileId, starts: &[usize]) -> Ahead {
    spawn_helpers(source, file, starts, starts.len().min(MAX_HELPERS))
}

fn spawn_helpers(source: &Arc<str>, file: FileId, starts: &[usize], helpers: usize) -> Ahead {
    let cancel = Arc::new(AtomicBool::new(false));
    let mut ahead = Ahead {
        starts: starts.to_vec(),
        next: 0,
        from_helpers: Vec::new(),
        to_helpers: Vec::new(),
        spent: Vec::new(),
        spent_from: 0,
        cancel: Arc::clone(&cancel),
        helpers: Vec::new(),
    };
    let starts: Arc<[usize]> = starts.into();
    for h in 0..helpers {
        let (to_caller, from_helper) = sync_channel(1);
        let (to_helper, from_caller) = channel::<Vec<Node>>();
        let (source, starts, cancel) =
            (Arc::clone(source), Arc::clone(&starts), Arc::clone(&cancel));
        let spawned = std::thread::Builder::new()
            .name("trace-parse".into())
            .stack_size(STACK_BYTES)
            .spawn(move || {
                let channels = (to_caller, from_caller);
                parse_chunks(&source, file, &starts, (h, helpers), &cancel, &channels)
            });
        match spawned {
            Ok(handle) => {
                ahead.from_helpers.push(from_helper);
                ahead.to_helpers.push(to_helper);
                ahead.helpers.push(handle);
            }
            // Without that helper its chunks are left to the caller; the others' chunks
            // still come in order, so no helper at all then.
            Err(_) => {
                drop(ahead);
                return Ahead::default();
            }
        }
    }
    ahead
}

/// Top-level blocks probed at the start of a file by [`mostly_plain`].
const PROBE: usize = 32;

/// Whether at least three quarters of the first [`PROBE`] top-level blocks from byte `from`
/// on are statements the fast lane ([`plain`]) reads.
fn mostly_plain(source: &str, file: FileId, block_ends: &[usize], from: usize) -> bool {
    let (mut start, mut taken) = (from, 0);
    for &end in block_ends.iter().take(PROBE) {
        taken += usize::from(plain::statement(source, start, file).is_some_and(|(_, e)| e == end));
        start = end;
    }
    taken * 4 >= block_ends.len().min(PROBE) * 3
}

/// `declare X = sphere {…};`: the statement ends after the `;`, not after the `}`.
fn followed_by_semicolon(bytes: &[u8], at: usize) -> bool {
    bytes[at..]
        .iter()
        .find(|b| !b.is_ascii_whitespace())
        .is_some_and(|&b| b == b';')
}

/// Helper `h` of `helpers`: parses chunks `h`, `h + helpers`, … and sends each in turn,
/// freeing the statements the caller hands back meanwhile.
fn parse_chunks(
    source: &str,
    file: FileId,
    starts: &[usize],
    (h, helpers): (usize, usize),
    cancel: &AtomicBool,
    (to_caller, from_caller): &(SyncSender<Parsed>, Receiver<Vec<Node>>),
) {
    for k in (h..starts.len()).step_by(helpers) {
        let stop = starts.get(k + 1).copied().unwrap_or(usize::MAX);
        let parsed = parse_chunk(source, file, starts[k], stop, cancel);
        while let Ok(spent) = from_caller.try_recv() {
            drop(spent);
        }
        if cancel.load(Ordering::Relaxed) || to_caller.send(parsed).is_err() {
            return;
        }
    }
    // The last chunks' statements, once evaluated (until the caller is done).
    while let Ok(spent) = from_caller.recv() {
        drop(spent);
    }
}

/// Parses the statements from `start` until one ends at or after `stop`, or the file ends.
fn parse_chunk(
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
    // A plain statement takes the fast lane ([`plain`]). The others are parsed in batches
    // (one parse each), 8 at first and near the chunk's end (statements parsed past it are
    // dropped), else 64; after a batch that fails, one at a time (a statement that makes the
    // parser backtrack long is not parsed again and again).
    let mut batched = true;
    while pos < stop && !cancel.load(Ordering::Relaxed) {
        if let Some((node, end)) = plain::statement(source, pos, file) {
            statements.push(Ok(node));
            pos = end;
            continue;
        }
        if batched {
            let read = (pos - start).max(1);
            let mean = read / statements.len().max(1);
            let batch = if statements.len() >= 8 && stop - pos > 64 * mean {
                64
            } else {
                8
            };
            match statement_batch(source, pos, batch, &mut lower) {
                Some(batch) => {
                    for (node, end) in batch {
                        if pos >= stop {
                            break;
                        }
                        statements.push(Ok(node));
                        pos = end;
                    }
                    continue;
                }
                None => batched = false,
            }
        }
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
