//! Intersection-test counters for `--stats`: how many ray–shape tests were made and how many
//! found a crossing, by kind of shape.
//!
//! Each thread counts in its own cells (no atomics or locks on the hot path); the renderer
//! collects a block's counts with [`take`] when the block is done, so the totals are the same
//! for any number of threads.

use std::cell::Cell;

pub use super::shape::KINDS;

/// Tests made and tests that found a crossing, by kind.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tests {
    /// Tests made.
    pub tried: [u64; KINDS.len()],
    /// Tests that found a crossing.
    pub hit: [u64; KINDS.len()],
}

impl Tests {
    /// Adds another set of counts.
    pub fn add(&mut self, o: &Tests) {
        for k in 0..KINDS.len() {
            self.tried[k] += o.tried[k];
            self.hit[k] += o.hit[k];
        }
    }
}

thread_local! {
    static TRIED: [Cell<u64>; KINDS.len()] = const { [const { Cell::new(0) }; KINDS.len()] };
    static HIT: [Cell<u64>; KINDS.len()] = const { [const { Cell::new(0) }; KINDS.len()] };
}

/// Counts one test of kind `kind`.
#[inline]
pub fn record(kind: usize, hit: bool) {
    TRIED.with(|c| c[kind].set(c[kind].get() + 1));
    if hit {
        HIT.with(|c| c[kind].set(c[kind].get() + 1));
    }
}

/// This thread's counts since the last call, resetting them.
pub fn take() -> Tests {
    let mut t = Tests::default();
    TRIED.with(|c| t.tried = std::array::from_fn(|k| c[k].replace(0)));
    HIT.with(|c| t.hit = std::array::from_fn(|k| c[k].replace(0)));
    t
}
