//! One block of the image: its pixels (by the anti-aliasing method), their AOV layers, and
//! the work they took.

use super::antialias::{self, Block};
use super::transport::{MediumStack, Tracer};
use super::{Aov, BLOCK_SIZE, Px, RayCounts, RenderOptions, aov_values, camera};
use crate::geometry::counters;
use crate::scene::{Rgb, Scene};

/// Renders the block whose top-left pixel is (x0, y0).
pub(super) fn render_block(
    scene: &Scene,
    options: &RenderOptions,
    camera_media: Option<MediumStack>,
    x0: u32,
    y0: u32,
) -> BlockResult {
    let (w, h) = (options.width, options.height);
    let x1 = (x0 + BLOCK_SIZE).min(w);
    let y1 = (y0 + BLOCK_SIZE).min(h);
    let mut tracer = Tracer::new(scene);
    counters::take(); // (this block's counts start from zero)
    let block = Block {
        scene,
        options,
        camera_media: &camera_media,
        xs: x0..x1,
        ys: y0..y1,
    };
    let (pixels, samples) = antialias::block_pixels(&block, &mut tracer);
    BlockResult {
        x0,
        y0,
        width: x1 - x0,
        // (Traced before the counts and tests are taken.)
        aov: block_aovs(&mut tracer, options, x0..x1, y0..y1),
        pixels,
        counts: tracer.counts,
        tests: counters::take(),
        samples,
    }
}

/// The AOV values of the pixels of a block, row by row (not counted as camera rays: they
/// are the centre rays again).
pub(super) fn block_aovs(
    tracer: &mut Tracer,
    options: &RenderOptions,
    xs: std::ops::Range<u32>,
    ys: std::ops::Range<u32>,
) -> Vec<f32> {
    if options.aovs.is_empty() {
        return Vec::new();
    }
    let mut out = Vec::with_capacity(xs.len() * ys.len() * aov_values(&options.aovs));
    for y in ys {
        for x in xs.clone() {
            let ray = camera::camera_ray(
                tracer.scene,
                options.width,
                options.height,
                x as f64,
                y as f64,
            );
            let (depth, n, albedo, object) = match ray {
                Some(ray) => tracer.first_hit(&ray),
                None => (f64::INFINITY, glam::DVec3::ZERO, Rgb::ZERO, 0),
            };
            for aov in &options.aovs {
                match aov {
                    Aov::Depth => out.push(depth as f32),
                    Aov::Normal => out.extend([n.x, n.y, n.z].map(|v| v as f32)),
                    Aov::Albedo => out.extend([albedo.x, albedo.y, albedo.z].map(|v| v as f32)),
                    Aov::Object => out.push(object as f32),
                }
            }
        }
    }
    out
}

/// One rendered block.
pub(super) struct BlockResult {
    pub(super) x0: u32,
    pub(super) y0: u32,
    pub(super) width: u32,
    pub(super) pixels: Vec<Px>,
    /// The AOV values of each pixel, in order.
    pub(super) aov: Vec<f32>,
    pub(super) counts: RayCounts,
    pub(super) tests: counters::Tests,
    pub(super) samples: u64,
}

impl BlockResult {
    pub(super) fn height(&self) -> u32 {
        self.pixels.len() as u32 / self.width.max(1)
    }
}
