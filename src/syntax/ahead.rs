//! Plain statements read ahead on a second thread.
//!
//! The fast lane ([`super::plain`]) reads a statement from the text and the byte it starts at,
//! nothing else, so the statements of a big file can be read before the directive reader gets
//! to them: a helper thread follows the chain of plain statements (each starts where the one
//! before it ended) while the reader evaluates, and the reader takes each tree at exactly the
//! byte it asks for. Where the reader asks elsewhere (after a directive, a statement the lane
//! does not read, a loop going back), it reads that statement itself and the helper starts
//! again after it. The trees are the lane's own, so what the reader sees does not depend on
//! the helper; the helper only saves time.
//!
//! Trees go back to the helper to be freed, one before each statement it reads: memory is
//! freed best by the thread that allocated it (glibc's allocator takes the allocating
//! thread's arena lock for a block another thread frees, and the two threads then wait on
//! each other), and a tree freed just before the next is made gives that tree its blocks at
//! once (256 trees freed together overflow the allocator's per-thread cache, and the
//! helper then spent a third of its time in `free`).

use super::Node;
use super::plain::{self, Plain};
use crate::diag::FileId;
use std::collections::VecDeque;
use std::sync::Arc;
use std::sync::mpsc::{Receiver, Sender, SyncSender};

/// Statements in the helper's first batch after a start; batches then double up to
/// [`MOST_IN_BATCH`], so that a reader waiting for a new start waits for a few statements
/// only, and a long run costs one message per many statements.
const FIRST_BATCH: usize = 4;
const MOST_IN_BATCH: usize = 512;
/// Batches the helper may have ready before it waits for the reader (its lead, bounded).
const BATCHES_AHEAD: usize = 4;
/// Trees the reader gathers before handing them back to be freed.
const FREED_TOGETHER: usize = 256;

/// What the reader asks of the helper.
enum Command {
    /// Read the chain of plain statements from byte `from` (a new start, `epoch`).
    Read { epoch: u64, from: usize },
    /// Free these trees.
    Free(Vec<Node>),
}

/// Statements of one chain read by the helper: each starts where the one before ended, the
/// first at `from`.
struct Batch {
    epoch: u64,
    from: usize,
    statements: Vec<Plain>,
    /// The chain stops after these statements (the next is not plain, or is past the end).
    last: bool,
}

/// The plain statements of one file, read ahead where a helper thread is at hand.
pub struct Ahead {
    text: Arc<String>,
    file: FileId,
    /// Where the file's statements end.
    end: usize,
    helper: Option<Helper>,
}

struct Helper {
    commands: Sender<Command>,
    batches: Receiver<Batch>,
    thread: Option<std::thread::JoinHandle<()>>,
    /// The current chain's number; batches of earlier ones are stale.
    epoch: u64,
    /// Whether the helper is reading a chain the reader follows.
    following: bool,
    /// Where the next statement of the chain starts (the first of `ready`, or of the next
    /// batch).
    next: usize,
    /// Statements of the chain received and not yet taken.
    ready: VecDeque<Plain>,
    /// The chain's last batch has been received.
    ended: bool,
    /// Trees taken and evaluated, to go back to the helper.
    freed: Vec<Node>,
}

impl Ahead {
    /// Reads the plain statements of `text` (file `file`) up to byte `end`, on a helper
    /// thread if `helper` (else each as it is asked for).
    pub fn new(text: Arc<String>, file: FileId, end: usize, helper: bool) -> Ahead {
        let helper = if helper {
            Helper::start(Arc::clone(&text), file, end)
        } else {
            None
        };
        Ahead {
            text,
            file,
            end,
            helper,
        }
    }

    /// The file read.
    pub fn file(&self) -> FileId {
        self.file
    }

    /// Whether this reads `text` to `end` (the same file text, the same end).
    pub fn reads(&self, text: &Arc<String>, end: usize) -> bool {
        Arc::ptr_eq(&self.text, text) && self.end == end
    }

    /// The plain statement starting after the blanks at byte `pos`, as [`plain::read`]
    /// reads it (ending by the file's end, its names given their slots).
    pub fn statement(&mut self, pos: usize) -> Option<Plain> {
        let Some(h) = &mut self.helper else {
            return plain::read(&self.text, pos, self.file, self.end);
        };
        if h.following && h.next == pos {
            if h.ready.is_empty() && !h.ended {
                h.receive();
            }
            if let Some(plain) = h.ready.pop_front() {
                h.next = plain.end;
                return Some(plain);
            }
            // The chain ended here: the statement is not plain.
            h.following = false;
            return None;
        }
        // Somewhere else: read it here, and the helper goes on after it.
        let read = plain::read(&self.text, pos, self.file, self.end);
        if let Some(plain) = &read {
            h.restart(plain.end);
        }
        read
    }

    /// Hands back a tree taken from [`Ahead::statement`] and evaluated: it is freed by the
    /// thread that made it.
    pub fn free(&mut self, node: Node) {
        if let Some(h) = &mut self.helper {
            h.freed.push(node);
            if h.freed.len() >= FREED_TOGETHER {
                let trees = std::mem::take(&mut h.freed);
                let _ = h.commands.send(Command::Free(trees));
            }
        }
    }
}

impl Helper {
    fn start(text: Arc<String>, file: FileId, end: usize) -> Option<Helper> {
        let (commands, orders) = std::sync::mpsc::channel();
        let (sender, batches) = std::sync::mpsc::sync_channel(BATCHES_AHEAD);
        let thread = std::thread::Builder::new()
            .name("trace-ahead".into())
            .spawn(move || help(&text, file, end, &orders, &sender))
            .ok()?;
        Some(Helper {
            commands,
            batches,
            thread: Some(thread),
            epoch: 0,
            following: false,
            next: 0,
            ready: VecDeque::new(),
            ended: true,
            freed: Vec::new(),
        })
    }

    /// Starts a new chain at `from`: what is ready of the old one goes back to be freed.
    fn restart(&mut self, from: usize) {
        self.freed.extend(self.ready.drain(..).map(|p| p.node));
        self.epoch += 1;
        self.following = true;
        self.next = from;
        self.ended = false;
        let sent = self.commands.send(Command::Read {
            epoch: self.epoch,
            from,
        });
        if sent.is_err() {
            self.following = false;
        }
    }

    /// Waits for the chain's next batch (stale batches go back to be freed).
    fn receive(&mut self) {
        loop {
            let Ok(batch) = self.batches.recv() else {
                // (The helper is gone: the chain ends here.)
                self.ended = true;
                return;
            };
            if batch.epoch != self.epoch {
                self.freed
                    .extend(batch.statements.into_iter().map(|p| p.node));
                continue;
            }
            debug_assert_eq!(batch.from, self.next, "batches follow their chain");
            self.ended = batch.last;
            self.ready.extend(batch.statements);
            return;
        }
    }
}

impl Drop for Helper {
    fn drop(&mut self) {
        let trees = std::mem::take(&mut self.freed);
        let _ = self.commands.send(Command::Free(trees));
        // Closing both channels ends the helper whether it waits to send or for an order.
        let (none, _) = std::sync::mpsc::channel();
        drop(std::mem::replace(&mut self.commands, none));
        let (_, nothing) = std::sync::mpsc::sync_channel(0);
        drop(std::mem::replace(&mut self.batches, nothing));
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

/// The helper thread: reads chains as ordered, frees what it is given.
fn help(
    text: &str,
    file: FileId,
    end: usize,
    orders: &Receiver<Command>,
    batches: &SyncSender<Batch>,
) {
    // The chain being read: its number, where its next statement starts, the batch size.
    let mut chain: Option<(u64, usize, usize)> = None;
    // Trees handed back, freed one before each statement read: the allocator hands their
    // blocks straight to the next tree (freed all at once, most would go the slow way).
    let mut dead: VecDeque<Node> = VecDeque::new();
    loop {
        let order = match chain {
            None => {
                // (Idle: free what is left first.)
                dead.clear();
                match orders.recv() {
                    Ok(order) => Some(order),
                    Err(_) => return,
                }
            }
            Some(_) => match orders.try_recv() {
                Ok(order) => Some(order),
                Err(std::sync::mpsc::TryRecvError::Empty) => None,
                Err(std::sync::mpsc::TryRecvError::Disconnected) => return,
            },
        };
        // Orders first: a newer chain replaces this one, and trees are freed early.
        match order {
            Some(Command::Read { epoch, from }) => {
                chain = Some((epoch, from, FIRST_BATCH));
                continue;
            }
            Some(Command::Free(trees)) => {
                dead.extend(trees);
                continue;
            }
            None => {}
        }
        let Some((epoch, from, size)) = chain else {
            continue;
        };
        let mut statements = Vec::with_capacity(size);
        let mut at = from;
        let mut last = false;
        while statements.len() < size {
            drop(dead.pop_front());
            match plain::read(text, at, file, end) {
                Some(plain) => {
                    at = plain.end;
                    statements.push(plain);
                }
                None => {
                    last = true;
                    break;
                }
            }
        }
        let batch = Batch {
            epoch,
            from,
            statements,
            last,
        };
        if batches.send(batch).is_err() {
            return;
        }
        chain = (!last).then_some((epoch, at, (size * 2).min(MOST_IN_BATCH)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lane(text: &str, pos: usize) -> Option<Plain> {
        plain::read(text, pos, FileId(0), text.len())
    }

    /// A file of `n` plain statements with a directive every `every`.
    fn file(n: usize, every: usize) -> String {
        let mut s = String::new();
        for i in 0..n {
            if i % every == every - 1 {
                s.push_str("#declare A = 1;\n");
            }
            s.push_str(&format!(
                "sphere {{ <{i}, 0, 1>, 0.5 pigment {{ rgb <0.{i}, 0, 0> }} }} // {i}\n"
            ));
        }
        s
    }

    /// Every statement the helper hands over is the lane's own reading at that byte, whatever
    /// the order the reader asks in: in turn, jumping back (a loop), skipping (a directive).
    #[test]
    fn statements_read_ahead_are_the_lanes_own() {
        let text = file(3000, 97);
        let arc = Arc::new(text.clone());
        // The reader's starts: every statement in turn, then back to the start twice.
        let mut starts = Vec::new();
        let mut pos = 0;
        while pos < text.len() {
            starts.push(pos);
            pos = match lane(&text, pos) {
                Some(plain) => plain.end,
                // A directive: skip its line, as the reader runs it.
                None => text[pos..].find('\n').map_or(text.len(), |i| pos + i + 1),
            };
        }
        let mut asked = starts.clone();
        asked.extend(starts.iter().take(500));
        asked.extend(starts.iter().step_by(3));
        for helper in [false, true] {
            let mut ahead = Ahead::new(Arc::clone(&arc), FileId(0), text.len(), helper);
            for &pos in &asked {
                let got = ahead.statement(pos);
                let want = lane(&text, pos);
                assert_eq!(
                    format!("{got:?}"),
                    format!("{want:?}"),
                    "at byte {pos} (helper: {helper})"
                );
                if let Some(plain) = got {
                    ahead.free(plain.node);
                }
            }
        }
    }

    /// A statement running past the end given is not read, ahead or not.
    #[test]
    fn statements_stop_at_the_end_given() {
        let text = file(50, 1000);
        let arc = Arc::new(text.clone());
        let cut = text.len() / 2;
        let mut ahead = Ahead::new(arc, FileId(0), cut, true);
        let mut pos = 0;
        let mut read = 0;
        while let Some(Plain { node, end, .. }) = ahead.statement(pos) {
            assert!(end <= cut);
            pos = end;
            read += 1;
            ahead.free(node);
        }
        assert!(
            read > 20 && read < 26,
            "{read} statements before byte {cut}"
        );
    }
}
