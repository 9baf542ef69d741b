//! Rendering allocates per block, not per ray or sample: a counting allocator (this test
//! binary's own, so no other test's allocations are counted) counts the allocations of
//! renders of examples that use most of the shading (area lights, glass, metal, media,
//! blobs, isosurfaces, textures, focal blur, meshes, text), each built once and rendered at
//! two sizes with anti-aliasing. The larger render adds 8 blocks and tens of thousands of
//! samples and rays: what it allocates beyond the smaller one must stay below 16 an added
//! block (measured: 3 a block, 9 with media) and far below one an added pixel.

use std::alloc::{GlobalAlloc, Layout, System};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

struct Counting;

static ALLOCATIONS: AtomicU64 = AtomicU64::new(0);

// SAFETY: every call is passed on to the system allocator unchanged; only a counter is added.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Relaxed);
        // SAFETY: the caller's layout, as GlobalAlloc::alloc requires.
        unsafe { System.alloc(layout) }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Relaxed);
        // SAFETY: as above.
        unsafe { System.alloc_zeroed(layout) }
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: `ptr` came from this allocator (the system's) with `layout`.
        unsafe { System.dealloc(ptr, layout) }
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Relaxed);
        // SAFETY: as for dealloc; the new size is the caller's.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static COUNTING: Counting = Counting;

/// Allocations made by one render of `prepared` at `width` × `height`, and its samples.
fn allocations(prepared: &trace::Prepared, width: u32, height: u32) -> (u64, u64) {
    let options = trace::RenderOptions {
        width,
        height,
        antialias: trace::Antialias::Sampled {
            threshold: 0.1,
            depth: 3,
        },
        ..trace::RenderOptions::default()
    };
    let before = ALLOCATIONS.load(Relaxed);
    let rendered = prepared.render(&options);
    (ALLOCATIONS.load(Relaxed) - before, rendered.stats.samples)
}

#[test]
fn renders_allocate_per_block_not_per_ray() {
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples");
    let mut report = Vec::new();
    for name in [
        "area_glass_metal",
        "media_atmosphere",
        "media_shadow",
        "blobs",
        "isosurfaces",
        "texture_maps",
        "normal_maps",
        "camera_focal_blur",
        "meshes",
        "text",
        "dispersion",
        "fog",
    ] {
        let options = trace::LoadOptions {
            width: 128,
            height: 96,
            ..Default::default()
        };
        let loaded = trace::load(&examples.join(format!("{name}.rt")), &options)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let prepared = trace::prepare(&loaded.scene, Some(1), &trace::BuildCache::default())
            .expect("a thread");
        let (small, _) = allocations(&prepared, 64, 48);
        let (large, samples) = allocations(&prepared, 128, 96);
        let added_blocks = 4 * 3 - 2 * 2;
        let added_pixels = 128 * 96 - 64 * 48;
        let added = large.saturating_sub(small);
        report.push(format!(
            "{name}: {small} and {large} allocations ({samples} samples at 128x96)"
        ));
        assert!(
            added <= 16 * added_blocks && added * 20 < added_pixels,
            "{name}: {added} allocations more for {added_pixels} more pixels in {added_blocks} more blocks\n{}",
            report.join("\n")
        );
    }
    eprintln!("{}", report.join("\n"));
}
