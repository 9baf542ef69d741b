//! Output files that appear whole or not at all.
//!
//! Every file trace writes (rendered images, FLIP maps, converted meshes) is written to a
//! hidden temporary file beside its target and renamed into place once complete, so an
//! existing file is never left half-written. The temporary files being written are kept in
//! a list, so that an interrupt (SIGINT, SIGTERM) or running out of memory can remove them
//! before the process ends ([`remove_pending`]).

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};

/// Temporary files being written now.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// A temporary file beside `target`, removed on drop unless [`TempFile::persist`]ed.
#[derive(Debug)]
pub struct TempFile {
    tmp: PathBuf,
    target: PathBuf,
    done: bool,
}

impl TempFile {
    /// Reserves `.NAME.PID.tmp` beside `target` (nothing is created yet).
    pub fn new(target: &Path) -> TempFile {
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let tmp = target.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
        if let Ok(mut pending) = PENDING.lock() {
            pending.push(tmp.clone());
        }
        TempFile {
            tmp,
            target: target.to_path_buf(),
            done: false,
        }
    }

    /// Where to write.
    pub fn path(&self) -> &Path {
        &self.tmp
    }

    /// Renames the finished file onto its target (not after an interrupt: the file is then
    /// removed).
    pub fn persist(mut self) -> std::io::Result<()> {
        if interrupted() {
            return Err(std::io::Error::new(
                std::io::ErrorKind::Interrupted,
                "interrupted",
            ));
        }
        std::fs::rename(&self.tmp, &self.target)?;
        self.done = true;
        Ok(())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.done {
            let _ = std::fs::remove_file(&self.tmp);
        }
        if let Ok(mut pending) = PENDING.lock() {
            pending.retain(|p| p != &self.tmp);
        }
    }
}

/// Whether the process was interrupted (set by [`interrupt`]).
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// For an interrupt (SIGINT, SIGTERM), before the process ends: from now on no temporary file
/// is renamed onto its target ([`TempFile::persist`] fails), and the ones being written are
/// removed, twice 50 ms apart. (A signal that interrupts a thread blocked opening its
/// temporary file, a FIFO or a slow disk, restarts that open when the handler returns, which
/// can create the file again after the first removal: seen with SIGINT and a FIFO.)
pub fn interrupt() {
    INTERRUPTED.store(true, Ordering::SeqCst);
    remove_pending();
    std::thread::sleep(std::time::Duration::from_millis(50));
    remove_pending();
}

/// Whether [`interrupt`] was called.
pub fn interrupted() -> bool {
    INTERRUPTED.load(Ordering::SeqCst)
}

/// Removes every temporary file being written (for an interrupt or a fatal error; the
/// process is about to end). Never blocks: if the list is busy, it is left alone.
pub fn remove_pending() {
    if let Ok(pending) = PENDING.try_lock() {
        for tmp in pending.iter() {
            let _ = std::fs::remove_file(tmp);
        }
    }
}

/// Checks before any work that `target` can be written: its folder exists and is a folder.
pub fn check_writable(target: &Path) -> Result<(), String> {
    let folder = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    match std::fs::metadata(folder) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => return Err(format!("{} is not a folder", folder.display())),
        Err(e) => return Err(format!("cannot write into {}: {e}", folder.display())),
    }
    if target.is_dir() {
        return Err(format!("{} is a folder", target.display()));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dropped_temp_file_is_removed_and_a_persisted_one_renamed() {
        let dir = std::env::temp_dir().join(format!("trace-output-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let target = dir.join("out.txt");
        let t = TempFile::new(&target);
        std::fs::write(t.path(), "partial").unwrap();
        let tmp = t.path().to_path_buf();
        drop(t);
        assert!(!tmp.exists() && !target.exists());

        let t = TempFile::new(&target);
        std::fs::write(t.path(), "whole").unwrap();
        // (remove_pending is tested through the CLI: it would race other tests' writes here.)
        t.persist().unwrap();
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "whole");
        assert!(check_writable(&target).is_ok());
        assert!(check_writable(&dir.join("missing/out.png")).is_err());
        assert!(check_writable(&dir).is_err());
        std::fs::remove_dir_all(dir).unwrap();
    }
}
