//! POV-Ray's method 2 (`+AM2`): pixel corners shared between pixels, squares split where
//! their corners differ.

use super::{Block, aa_encoded, differ};
use crate::render::transport::{MediumStack, Tracer};
use crate::render::{Px, RenderOptions, camera};
use crate::scene::{Rgb, Scene};

/// The pixels of `block` with method 2, and the samples they took.
pub(super) fn pixels(
    block: &Block,
    tracer: &mut Tracer,
    threshold: f64,
    depth: u32,
) -> (Vec<Px>, u64) {
    let level = depth.clamp(1, 9) - 1;
    let mut corners = Corners {
        scene: block.scene,
        options: block.options,
        camera_media: block.camera_media,
        steps: 1 << level,
        threshold,
        points: std::collections::HashMap::new(),
        inner: std::collections::HashMap::new(),
        samples: 0,
    };
    let s = corners.steps;
    let pixels = block.pixels(&mut |x, y| {
        let colour = corners.square(tracer, i64::from(x) * s, i64::from(y) * s, s, level);
        corners.inner.clear();
        colour
    });
    (pixels, corners.samples)
}

/// Method 2's samples: points of a grid `steps` times finer than the pixels, traced once each
/// (a block traces the corners on its border again: the same rays, so the same colours).
pub(super) struct Corners<'a> {
    scene: &'a Scene,
    options: &'a RenderOptions,
    camera_media: &'a Option<MediumStack>,
    /// Grid points per pixel along each axis (2^(depth − 1)).
    steps: i64,
    threshold: f64,
    /// Colour and encoded colour at each traced grid point on a pixel's border (shared with
    /// the neighbours) …
    points: std::collections::HashMap<(i64, i64), (Px, Rgb)>,
    /// … and inside the current pixel (dropped after it: at depth 9 a pixel has 65k).
    inner: std::collections::HashMap<(i64, i64), (Px, Rgb)>,
    samples: u64,
}

impl Corners<'_> {
    /// The colour at grid point (gx, gy): pixel coordinates gx/steps − ½, gy/steps − ½.
    fn point(&mut self, tracer: &mut Tracer, gx: i64, gy: i64) -> (Px, Rgb) {
        let border = gx % self.steps == 0 || gy % self.steps == 0;
        let known = if border { &self.points } else { &self.inner };
        if let Some(&known) = known.get(&(gx, gy)) {
            return known;
        }
        let s = self.steps as f64;
        let (w, h) = (self.options.width, self.options.height);
        self.samples += 1;
        let value = camera::sample(
            tracer,
            self.camera_media,
            w,
            h,
            gx as f64 / s - 0.5,
            gy as f64 / s - 0.5,
        );
        let traced = (value, aa_encoded(value.truncate(), self.scene.gamma()));
        let known = if border {
            &mut self.points
        } else {
            &mut self.inner
        };
        known.insert((gx, gy), traced);
        traced
    }

    /// The colour of the square with top-left grid point (gx, gy) and side `size`, split at
    /// most `level` more times.
    fn square(&mut self, tracer: &mut Tracer, gx: i64, gy: i64, size: i64, level: u32) -> Px {
        let c = [
            (gx, gy),
            (gx + size, gy),
            (gx, gy + size),
            (gx + size, gy + size),
        ]
        .map(|(x, y)| self.point(tracer, x, y));
        let differs =
            level > 0 && (0..4).any(|i| (i + 1..4).any(|j| differ(c[i].1, c[j].1, self.threshold)));
        if !differs {
            return (c[0].0 + c[1].0 + c[2].0 + c[3].0) / 4.0;
        }
        let half = size / 2;
        let quadrants = [
            (gx, gy),
            (gx + half, gy),
            (gx, gy + half),
            (gx + half, gy + half),
        ];
        quadrants
            .iter()
            .map(|&(x, y)| self.square(tracer, x, y, half, level - 1))
            .fold(Px::ZERO, |sum, v| sum + v)
            / 4.0
    }
}
