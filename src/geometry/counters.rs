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
    /// Per kind: tests made and tests that found a crossing, side by side (one address).
    static COUNTS: [[Cell<u64>; 2]; KINDS.len()] =
        const { [const { [const { Cell::new(0) }, const { Cell::new(0) }] }; KINDS.len()] };
}

/// Counts one test of kind `kind`. (Without a branch on `hit`: whether a test finds a
/// crossing is what the branch predictor cannot guess.)
#[inline]
pub fn record(kind: usize, hit: bool) {
    COUNTS.with(|c| {
        let [tried, found] = &c[kind];
        tried.set(tried.get() + 1);
        found.set(found.get() + u64::from(hit));
    });
}

/// This thread's counts since the last call, resetting them.
pub fn take() -> Tests {
    COUNTS.with(|c| Tests {
        tried: std::array::from_fn(|k| c[k][0].replace(0)),
        hit: std::array::from_fn(|k| c[k][1].replace(0)),
    })
}
