//! Polynomial root finding: the quartics a torus (and the ovus's spindle torus) gives for
//! rays that pass near it, solved by `poly::roots_in` over the shape's reach.
//!
//! Run: `cargo bench --bench roots --features internals`.

use divan::{Bencher, black_box, counter::ItemsCount};
use glam::DVec3;
use trace::geometry::Torus;
use trace::geometry::poly::{Poly, roots_in};

fn main() {
    divan::main();
}

const RAYS: usize = 10_000;

/// Rays from a sphere of radius 4 towards random points near the torus, each moved to its
/// point nearest the centre (as the shapes do before solving).
fn quartics() -> Vec<Poly> {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..RAYS)
        .map(|_| {
            let from = DVec3::new(next(), next(), next()).normalize_or(DVec3::X) * 4.0;
            let to = DVec3::new(next() * 1.4, next() * 0.4, next() * 1.4);
            let d = (to - from).normalize();
            let p = from + d * (-from.dot(d));
            Torus {
                major: 1.0,
                minor: 0.3,
            }
            .quartic(p, d)
        })
        .collect()
}

#[divan::bench]
fn torus_quartics(bencher: Bencher) {
    let polys = quartics();
    bencher.counter(ItemsCount::new(polys.len())).bench(|| {
        let mut n = 0;
        for c in &polys {
            n += roots_in(black_box(c), 4, -2.5, 2.5).len;
        }
        n
    });
}
