//! A memory budget for the whole process.
//!
//! [`Limited`] wraps the system allocator, counts the bytes held, and refuses to go past a
//! limit set at start-up ([`set_limit`]). Past the limit, or when the system itself has no
//! memory left, it does what Rust's default would not: it prints a message naming the limit,
//! removes any output file being written ([`crate::output::remove_pending`]) and ends the
//! process with exit code 1, instead of aborting (exit 134) or being killed by the kernel.
//! The `trace` binary installs it as the global allocator; the library works without it.

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// The system allocator with a byte budget.
pub struct Limited;

/// Bytes taken from the budget: those allocated, plus each thread's unused credit.
static IN_USE: AtomicUsize = AtomicUsize::new(0);

/// Bytes a thread takes from the budget at a time, and gives back when it holds twice as
/// much unused: threads that allocate and free millions of small blocks (the parser and the
/// evaluator do, side by side) would otherwise contend for the shared counter's cache line on
/// every call, which made parsing on two threads slower than on one. The count is then
/// exact to within two grains a thread (a thread that ends leaves its unused credit counted:
/// at most two grains for each parsing helper of a load).
const GRAIN: usize = 1 << 20;

thread_local! {
    /// This thread's bytes taken from the budget and not allocated.
    static CREDIT: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}
static PEAK: AtomicUsize = AtomicUsize::new(0);
static LIMIT: AtomicUsize = AtomicUsize::new(usize::MAX);
static FAILING: AtomicBool = AtomicBool::new(false);

/// Sets the budget in bytes (the default is no budget).
pub fn set_limit(bytes: usize) {
    LIMIT.store(bytes, Ordering::Relaxed);
}

/// The budget in bytes.
pub fn limit() -> usize {
    LIMIT.load(Ordering::Relaxed)
}

/// Bytes allocated now (through [`Limited`], to within two grains a thread).
pub fn in_use() -> usize {
    IN_USE.load(Ordering::Relaxed)
}

/// The most bytes allocated at once so far (as [`in_use`] counts them).
pub fn peak() -> usize {
    PEAK.load(Ordering::Relaxed)
}

/// The memory this machine can give a process now: `MemAvailable` from `/proc/meminfo`
/// (physical memory not in use, counting caches that can be dropped), or less if the
/// process's control group (a container's, a Slurm job's) leaves less room under its limit.
pub fn available() -> Option<usize> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = info.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: usize = line.split_whitespace().nth(1)?.parse().ok()?;
    let machine = kib.checked_mul(1024)?;
    let cgroups = std::fs::read_to_string("/proc/self/cgroup").unwrap_or_default();
    Some(
        match cgroup_room(&cgroups, |p| std::fs::read_to_string(p).ok()) {
            Some(room) => machine.min(room),
            None => machine,
        },
    )
}

/// The room left under the memory limit of the control group `/proc/self/cgroup` names
/// (version 2: `memory.max` less `memory.current`; version 1: `memory.limit_in_bytes` less
/// `memory.usage_in_bytes`), `None` without a limit. `read` reads a file under /sys.
fn cgroup_room(cgroups: &str, read: impl Fn(&str) -> Option<String>) -> Option<usize> {
    let number = |text: Option<String>| -> Option<usize> { text?.trim().parse().ok() };
    // A limit this large is no limit (version 1 writes "unlimited" as 2^63 less a page).
    let limited = |limit: usize| limit < 1 << 60;
    for line in cgroups.lines() {
        let mut fields = line.splitn(3, ':');
        let (Some(id), Some(controllers), Some(path)) =
            (fields.next(), fields.next(), fields.next())
        else {
            continue;
        };
        let path = path.trim_end_matches('/');
        let (limit, usage) = if id == "0" && controllers.is_empty() {
            let dir = format!("/sys/fs/cgroup{path}");
            (format!("{dir}/memory.max"), format!("{dir}/memory.current"))
        } else if controllers.split(',').any(|c| c == "memory") {
            // (Inside a container the group's own folder is the mount's root.)
            let dir = if read(&format!(
                "/sys/fs/cgroup/memory{path}/memory.limit_in_bytes"
            ))
            .is_some()
            {
                format!("/sys/fs/cgroup/memory{path}")
            } else {
                "/sys/fs/cgroup/memory".to_string()
            };
            (
                format!("{dir}/memory.limit_in_bytes"),
                format!("{dir}/memory.usage_in_bytes"),
            )
        } else {
            continue;
        };
        if let Some(limit) = number(read(&limit)).filter(|&l| limited(l)) {
            let usage = number(read(&usage)).unwrap_or(0);
            return Some(limit.saturating_sub(usage));
        }
    }
    None
}

/// The size of a huge page (x86-64's and AArch64's 2 MiB).
const HUGE_PAGE: usize = 2 << 20;

/// An empty vector with room for `capacity` items, whose buffer the kernel is asked to back
/// with huge pages before anything touches it. A ray's walk through a big tree reads a few
/// nodes scattered over many megabytes; with 4 KiB pages nearly each read also misses the
/// TLB, and in a virtual machine each of those misses walks two sets of page tables. Linux
/// gives huge pages to memory so advised when its transparent huge pages are in `madvise`
/// mode (and to all memory in `always` mode). Only the 2 MiB-aligned stretches inside the
/// buffer are advised, so the process takes no memory the buffer does not; elsewhere (other
/// systems, Linux on other than x86-64 and AArch64), and for buffers of a few pages, this is
/// `Vec::with_capacity`.
pub fn with_huge_pages<T>(capacity: usize) -> Vec<T> {
    let v = Vec::with_capacity(capacity);
    // (MADV_HUGEPAGE is 14 on these; a few other architectures number it otherwise.)
    #[cfg(all(
        target_os = "linux",
        any(target_arch = "x86_64", target_arch = "aarch64")
    ))]
    {
        let bytes = v.capacity() * std::mem::size_of::<T>();
        let start = v.as_ptr() as usize;
        let first = start.next_multiple_of(HUGE_PAGE);
        let end = (start + bytes) / HUGE_PAGE * HUGE_PAGE;
        if bytes >= 2 * HUGE_PAGE && end > first {
            unsafe extern "C" {
                fn madvise(addr: *mut std::ffi::c_void, len: usize, advice: i32) -> i32;
            }
            const MADV_HUGEPAGE: i32 = 14;
            // SAFETY: the range lies inside the vector's own allocation, and this advice only
            // changes how the kernel backs it (pages not yet touched); its result, success or
            // not (a kernel without huge pages), changes nothing the program reads.
            unsafe { madvise(first as *mut std::ffi::c_void, end - first, MADV_HUGEPAGE) };
        }
    }
    v
}

/// `v` moved into a buffer advised as [`with_huge_pages`]' (for a vector some other code
/// built); `v` itself when it is too small to gain.
pub fn into_huge_pages<T: Copy>(v: Vec<T>) -> Vec<T> {
    if v.len() * std::mem::size_of::<T>() < 2 * HUGE_PAGE {
        return v;
    }
    let mut moved = with_huge_pages(v.len());
    moved.extend_from_slice(&v);
    moved
}

/// Parses a size such as `512M`, `8G`, `1.5G` or a plain number of bytes.
pub fn parse_size(text: &str) -> Option<usize> {
    let text = text.trim();
    let (number, unit) = match text.char_indices().find(|(_, c)| c.is_ascii_alphabetic()) {
        Some((i, _)) => (&text[..i], text[i..].to_ascii_uppercase()),
        None => (text, String::new()),
    };
    let scale = match unit.trim_end_matches("IB").trim_end_matches('B') {
        "" => 1.0,
        "K" => 1024.0,
        "M" => 1024.0 * 1024.0,
        "G" => 1024.0 * 1024.0 * 1024.0,
        "T" => 1024.0 * 1024.0 * 1024.0 * 1024.0,
        _ => return None,
    };
    let bytes = number.trim().parse::<f64>().ok()? * scale;
    (bytes.is_finite() && bytes >= 1.0 && bytes < usize::MAX as f64).then_some(bytes as usize)
}

/// A size for people: `1.5 GiB`, `300 MiB`.
pub fn format_size(bytes: usize) -> String {
    let b = bytes as f64;
    if b >= 1024.0 * 1024.0 * 1024.0 {
        format!("{:.1} GiB", b / (1024.0 * 1024.0 * 1024.0))
    } else {
        format!("{:.0} MiB", (b / (1024.0 * 1024.0)).ceil())
    }
}

impl Limited {
    /// Reserves `size` bytes of the budget, from this thread's credit when it holds enough;
    /// false (and nothing reserved) if over the budget.
    fn reserve(size: usize) -> bool {
        let from_credit = CREDIT.try_with(|credit| {
            let have = credit.get();
            if have >= size {
                credit.set(have - size);
                return true;
            }
            // Take what is missing and a grain more, or, near the limit, just what is missing.
            if Limited::reserve_shared(size - have + GRAIN) {
                credit.set(GRAIN);
                true
            } else if Limited::reserve_shared(size - have) {
                credit.set(0);
                true
            } else {
                false
            }
        });
        from_credit.unwrap_or_else(|_| Limited::reserve_shared(size))
    }

    /// Gives `size` freed bytes back: to this thread's credit, which returns what exceeds
    /// two grains to the budget.
    fn release(size: usize) {
        let kept = CREDIT.try_with(|credit| {
            let have = credit.get().saturating_add(size);
            if have > 2 * GRAIN {
                IN_USE.fetch_sub(have - GRAIN, Ordering::Relaxed);
                credit.set(GRAIN);
            } else {
                credit.set(have);
            }
        });
        if kept.is_err() {
            IN_USE.fetch_sub(size, Ordering::Relaxed);
        }
    }

    /// Reserves `size` bytes of the shared budget; false (and nothing reserved) if over it.
    fn reserve_shared(size: usize) -> bool {
        let before = IN_USE.fetch_add(size, Ordering::Relaxed);
        if before.saturating_add(size) <= LIMIT.load(Ordering::Relaxed) {
            PEAK.fetch_max(before + size, Ordering::Relaxed);
            return true;
        }
        IN_USE.fetch_sub(size, Ordering::Relaxed);
        false
    }

    /// Reserves `size` bytes, then allocates them with `allocate`; ends the process if either
    /// fails.
    fn within_budget(size: usize, allocate: impl FnOnce() -> *mut u8) -> *mut u8 {
        if !Limited::reserve(size) && !FAILING.load(Ordering::Relaxed) {
            Limited::out_of_memory(size);
        }
        let p = allocate();
        if p.is_null() {
            Limited::out_of_memory(size);
        }
        p
    }

    /// Ends the process: a message, no half-written output, exit code 1.
    #[cold]
    fn out_of_memory(size: usize) -> ! {
        // Allocations from here on (the message, removing files) pass the budget.
        FAILING.store(true, Ordering::Relaxed);
        let limit = LIMIT.load(Ordering::Relaxed);
        let message = if limit == usize::MAX {
            format!(
                "error: out of memory (the system refused {} more)\n",
                format_size(size)
            )
        } else {
            format!(
                "error: out of memory: the scene needs more than trace's limit of {} (raise it with --max-memory SIZE)\n",
                format_size(limit)
            )
        };
        let _ = std::io::Write::write_all(&mut std::io::stderr(), message.as_bytes());
        crate::output::remove_pending();
        // Not `exit`: other threads may hold locks that its clean-up would wait for.
        unsafe { libc_exit(1) }
    }
}

unsafe extern "C" {
    /// POSIX `_exit`: ends the process at once, without running clean-up handlers.
    #[link_name = "_exit"]
    fn libc_exit(status: i32) -> !;
}

// SAFETY: every method forwards to `System` with the same layout, and only counts the bytes;
// memory is never handed out twice or freed with another layout.
unsafe impl GlobalAlloc for Limited {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        Limited::within_budget(layout.size(), || unsafe { System.alloc(layout) })
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        Limited::within_budget(layout.size(), || unsafe { System.alloc_zeroed(layout) })
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        Limited::release(layout.size());
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let old = layout.size();
        if new_size > old && !Limited::reserve(new_size - old) && !FAILING.load(Ordering::Relaxed) {
            Limited::out_of_memory(new_size);
        }
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if p.is_null() {
            Limited::out_of_memory(new_size);
        }
        if new_size < old {
            Limited::release(old - new_size);
        }
        p
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Buffers asked for huge pages hold what they are given, small and large (8 MiB spans
    /// advised 2 MiB stretches), and grow as any vector does.
    #[test]
    fn vectors_on_huge_pages_hold_their_items() {
        for n in [0usize, 1, 1000, 1 << 20] {
            let v: Vec<u64> = with_huge_pages(n);
            assert!(v.is_empty() && v.capacity() >= n);
            let items: Vec<u64> = (0..n as u64).map(|i| i.wrapping_mul(0x9E37_79B9)).collect();
            let mut moved = into_huge_pages(items.clone());
            assert_eq!(moved, items);
            moved.extend([1, 2, 3]);
            assert_eq!(moved[n..], [1, 2, 3]);
        }
    }

    #[test]
    fn a_control_group_limit_bounds_the_memory_available() {
        let files = |entries: &'static [(&'static str, &'static str)]| {
            move |p: &str| {
                entries
                    .iter()
                    .find(|(k, _)| *k == p)
                    .map(|(_, v)| v.to_string())
            }
        };
        // Version 2: a Slurm job's or a container's group.
        let v2 = files(&[
            ("/sys/fs/cgroup/job/memory.max", "1073741824\n"),
            ("/sys/fs/cgroup/job/memory.current", "73741824\n"),
        ]);
        assert_eq!(cgroup_room("0::/job\n", v2), Some(1_000_000_000));
        let unlimited = files(&[("/sys/fs/cgroup/memory.max", "max\n")]);
        assert_eq!(cgroup_room("0::/\n", unlimited), None);
        // Version 1, inside a container (the group's folder is the mount's root).
        let v1 = files(&[
            ("/sys/fs/cgroup/memory/memory.limit_in_bytes", "2000\n"),
            ("/sys/fs/cgroup/memory/memory.usage_in_bytes", "500\n"),
        ]);
        assert_eq!(cgroup_room("4:memory:/docker/abc\n0::/\n", v1), Some(1500));
        let v1_unlimited = files(&[(
            "/sys/fs/cgroup/memory/memory.limit_in_bytes",
            "9223372036854771712",
        )]);
        assert_eq!(cgroup_room("4:memory:/x\n", v1_unlimited), None);
    }

    #[test]
    fn sizes_parse_with_binary_units() {
        assert_eq!(parse_size("512M"), Some(512 << 20));
        assert_eq!(parse_size("8G"), Some(8 << 30));
        assert_eq!(parse_size("8gib"), Some(8 << 30));
        assert_eq!(parse_size("1.5G"), Some(3 << 29));
        assert_eq!(parse_size("4096"), Some(4096));
        assert_eq!(parse_size("lots"), None);
        assert_eq!(parse_size("-1G"), None);
        assert_eq!(format_size(3 << 29), "1.5 GiB");
        assert_eq!(format_size(300 << 20), "300 MiB");
    }
}
