//! Helpers shared by the unit tests.

use crate::scene::Scene;

/// Marsaglia's xorshift64: a fixed-seed stream of numbers for randomised tests.
pub struct Xorshift(pub u64);

impl Xorshift {
    /// The next 64 bits.
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.0;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.0 = x;
        x
    }

    /// The next number in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// The render-ready scene of the scene text `text` (which must load).
pub fn scene(text: String) -> Scene {
    let loaded = crate::load_str(
        std::path::Path::new("test.rt"),
        text,
        &crate::LoadOptions::default(),
    )
    .expect("loads");
    Scene::build(&loaded.scene)
}
