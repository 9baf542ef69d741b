//! Parts of an image: the key that tells which parts belong together, continuing a part
//! (`--continue`), and putting a render's file into place, whole or cut where it stopped.

use crate::job::{Frame, Job};
use std::path::{Path, PathBuf};
use trace::film::{Raster, Region};

/// A key of the scene's sources and of every setting that changes the pixels: parts merge
/// only with parts of the same key.
pub fn key(sources: u64, job: &Job, frame: &Frame) -> String {
    let settings = format!(
        "{} {} {:?} {} {} {:?} {:?} {} {} {:?}{}",
        job.width,
        job.height,
        job.antialias,
        job.sampled_lights,
        job.sampled_blur,
        frame.clock,
        job.declares,
        job.alpha,
        job.bits,
        job.aovs,
        // (Added only when given, so that keys of other parts stay as they were.)
        job.radiosity_reference
            .map_or(String::new(), |n| format!(" reference {n}"))
            + if job.radiosity_povray_order {
                " povray order"
            } else {
                ""
            }
    );
    let mut h = sources;
    for b in settings.bytes() {
        h = (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3);
    }
    format!("{h:016x}")
}

/// What is left to render of `wanted` when `output` already holds a part of it (`--continue`):
/// `None` if it is complete, or the rows after those it holds.
pub fn continuation(
    output: &Path,
    wanted: Region,
    (width, height): (u32, u32),
    key: &str,
) -> Result<Option<Region>, String> {
    let raster = Raster::read(output).map_err(|e| e.to_string())?;
    let Some(part) = raster.part() else {
        if (raster.width, raster.height) == (width, height) && wanted == Region::full(width, height)
        {
            return Ok(None);
        }
        return Err(format!(
            "{} is not a part of this render (remove it, or leave out --continue)",
            output.display()
        ));
    };
    if part.key != key || (part.width, part.height) != (width, height) {
        return Err(format!(
            "{} holds a part of another render (the scene or settings differ): remove it, or leave out --continue",
            output.display()
        ));
    }
    let r = part.region;
    if r == wanted {
        return Ok(None);
    }
    if (r.x0, r.x1, r.y0) == (wanted.x0, wanted.x1, wanted.y0) && r.y1 < wanted.y1 {
        return Ok(Some(Region { y0: r.y1, ..wanted }));
    }
    Err(format!(
        "{} holds region {r}, which does not start the region asked for ({wanted})",
        output.display()
    ))
}

/// A file beside `output` to render into, removed when dropped if still there.
pub struct Scratch(pub PathBuf);

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// The scratch file for `output` (hidden, same folder and extension).
pub fn scratch_path(output: &Path) -> Scratch {
    let name = output
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = output
        .extension()
        .map(|e| e.to_string_lossy().into_owned())
        .unwrap_or_default();
    Scratch(output.with_file_name(format!(".{name}.{}.partial.{ext}", std::process::id())))
}

/// Puts the render in `rendered` (of region `asked`, finished up to `finished`) into place at
/// `output`: moved if whole; cut to its finished rows (a part, noted `note(region)`) if
/// stopped; merged after the rows of `kept` (the output it continues).
pub fn settle(
    rendered: &Path,
    asked: Region,
    finished: Region,
    note: &dyn Fn(Region) -> String,
    kept: Option<&Path>,
    output: &Path,
) -> Result<(), String> {
    let io = |e: std::io::Error| format!("{}: {e}", output.display());
    if finished.height() == 0 {
        return Ok(());
    }
    if finished != asked {
        let mut cut = Raster::read(rendered)
            .map_err(|e| e.to_string())?
            .rows(0, finished.height());
        cut.layout.note = Some(note(finished));
        cut.write(rendered).map_err(|e| e.to_string())?;
    }
    match kept {
        None => std::fs::rename(rendered, output).map_err(io),
        // (The rows rendered, a part of the region continued, merged after the rows kept.)
        Some(kept) => trace::film::merge(&[kept, rendered], output).map(|_| ()),
    }
}
