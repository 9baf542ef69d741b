//! A cancel token: whoever holds a clone may stop the load or render it was given to.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

/// Stops a render where it is: blocks not yet started are not rendered, and the rows
/// finished are kept (`RenderStats::stopped`); stops a load at its next few thousand
/// evaluation steps with an error. Clones share one flag; a new token (or `Default`) is one
/// nobody else holds, so two renders in one process stop independently.
#[derive(Clone, Debug, Default)]
pub struct Cancel(Arc<AtomicBool>);

impl Cancel {
    /// A token not cancelled, shared with nobody yet.
    pub fn new() -> Cancel {
        Cancel::default()
    }

    /// Asks the render holding this token (or a clone) to stop.
    pub fn cancel(&self) {
        self.0.store(true, Ordering::SeqCst);
    }

    /// Whether [`Cancel::cancel`] was called on this token or a clone.
    pub fn is_cancelled(&self) -> bool {
        self.0.load(Ordering::SeqCst)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clones_share_the_flag_and_new_tokens_do_not() {
        let a = Cancel::new();
        let b = a.clone();
        let other = Cancel::new();
        assert!(!a.is_cancelled());
        b.cancel();
        assert!(a.is_cancelled() && b.is_cancelled());
        assert!(!other.is_cancelled());
    }
}
