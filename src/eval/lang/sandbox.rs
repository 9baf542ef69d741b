//! Which files a scene may read.
//!
//! Every file a scene names (`#include`, `image_map`, `mesh_file`, `file_exists`) is looked
//! up in the scene's folder, then in the `-L` folders, in that order. The file found is
//! resolved to its canonical path (`..` and symbolic links followed) and must lie inside one
//! of those folders, so a scene cannot read `/etc/passwd`, `../secret` or a symbolic link
//! pointing out of its folder, and an error never shows a line of such a file (a plain name
//! found in a `-L` folder, which the user chose, may be a link: Debian links POV-Ray's fonts
//! into its include folder). This is the
//! policy of POV-Ray's `povray.conf` with reading restricted to the scene and library paths;
//! users widen it by giving more folders with `-L DIR`.

use crate::diag::{Diagnostic, Span};
use std::path::{Path, PathBuf};

/// The folders a scene may read, in search order, with their canonical forms.
#[derive(Debug)]
pub(crate) struct Sandbox {
    /// The folders as given (the scene's folder first), for messages and searching.
    search: Vec<PathBuf>,
    /// Canonical forms of the folders that exist: a file must lie under one of these.
    roots: Vec<PathBuf>,
    /// Every file found, in the order first found (what a scene read, for `trace watch`).
    found: std::cell::RefCell<Vec<PathBuf>>,
    /// Where each name looked for and not found would be in the scene's folder (a file that
    /// appears there changes what the scene reads).
    missing: std::cell::RefCell<Vec<PathBuf>>,
}

/// Why a name gave no readable file.
#[derive(Debug, PartialEq)]
pub(crate) enum Refusal {
    /// No folder holds a file of that name.
    NotFound,
    /// The file found lies outside every allowed folder (after following links).
    Outside,
}

impl Sandbox {
    /// The scene's folder (`""` for the current one) and the `-L` folders.
    pub(crate) fn new(scene_dir: &Path, include_paths: &[PathBuf]) -> Sandbox {
        let scene_dir = if scene_dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            scene_dir
        };
        let search: Vec<PathBuf> = std::iter::once(scene_dir.to_path_buf())
            .chain(include_paths.iter().cloned())
            .collect();
        let roots = search
            .iter()
            .filter_map(|dir| dir.canonicalize().ok())
            .collect();
        Sandbox {
            search,
            roots,
            found: Default::default(),
            missing: Default::default(),
        }
    }

    /// The files found so far, each once, in the order first found.
    pub(crate) fn found(&self) -> Vec<PathBuf> {
        self.found.borrow().clone()
    }

    /// Where the names looked for and not found would stand in the scene's folder, each once.
    pub(crate) fn missing(&self) -> Vec<PathBuf> {
        self.missing.borrow().clone()
    }

    /// The canonical path of the file `name` names: the first folder that has it decides.
    pub(crate) fn find(&self, name: &str) -> Result<PathBuf, Refusal> {
        let Some((folder, found)) = self
            .search
            .iter()
            .map(|dir| dir.join(name))
            .enumerate()
            .find(|(_, p)| p.is_file())
        else {
            let mut missing = self.missing.borrow_mut();
            let there = self.search[0].join(name);
            if !missing.contains(&there) {
                missing.push(there);
            }
            return Err(Refusal::NotFound);
        };
        let canonical = found.canonicalize().map_err(|_| Refusal::NotFound)?;
        // A plain name found in a folder the user gave (not the scene's own) may be a link
        // placed there by whoever set the folder up (Debian links POV-Ray's fonts into its
        // include folder): the user chose that folder, links and all.
        let plain = Path::new(name)
            .components()
            .all(|c| matches!(c, std::path::Component::Normal(_)));
        if self.roots.iter().any(|root| canonical.starts_with(root)) || (folder > 0 && plain) {
            let mut found = self.found.borrow_mut();
            if !found.contains(&canonical) {
                found.push(canonical.clone());
            }
            Ok(canonical)
        } else {
            Err(Refusal::Outside)
        }
    }

    /// Where the scene may write the file `name` (`#fopen … write`): inside the scene's own
    /// folder only, after following `..` and links (of the folder and of the file if it
    /// exists), never a folder or a file outside.
    pub(crate) fn writable(&self, name: &str) -> Result<PathBuf, &'static str> {
        let folder = &self.search[0];
        let root = folder
            .canonicalize()
            .map_err(|_| "the scene's folder cannot be found")?;
        let path = folder.join(name);
        let file_name = path.file_name().ok_or("it names no file")?;
        let parent = path
            .parent()
            .and_then(|p| p.canonicalize().ok())
            .ok_or("its folder does not exist")?;
        let target = match std::fs::symlink_metadata(&path) {
            Ok(meta) if meta.is_dir() => return Err("it is a folder"),
            Ok(meta) if meta.file_type().is_symlink() => {
                path.canonicalize().map_err(|_| "it is a link to nothing")?
            }
            _ => parent.join(file_name),
        };
        if target.starts_with(&root) && !target.is_dir() {
            Ok(target)
        } else {
            Err("it lies outside the scene's folder")
        }
    }

    /// Like [`Sandbox::find`], with the refusal as a located error naming the file as the
    /// scene wrote it (`what` says what kind of file: "include file", "image", …).
    pub(crate) fn locate(&self, name: &str, what: &str, span: Span) -> Result<PathBuf, Diagnostic> {
        let folders = self
            .search
            .iter()
            .map(|p| format!("`{}`", p.display()))
            .collect::<Vec<_>>()
            .join(", ");
        match self.find(name) {
            Ok(path) => Ok(path),
            Err(Refusal::NotFound) => Err(Diagnostic::error(
                format!("cannot find {what} \"{name}\""),
                span,
            )
            .with_note(format!("searched {folders}"))
            .with_note(
                "add folders with -L DIR (e.g. -L /usr/share/povray-3.7/include for POV-Ray's own)",
            )),
            Err(Refusal::Outside) => Err(Diagnostic::error(
                format!("{what} \"{name}\" lies outside the folders this scene may read"),
                span,
            )
            .with_note(format!(
                "a scene reads files only from {folders} (links followed)"
            ))
            .with_note("to allow another folder, add it with -L DIR")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A scratch folder holding `scene/inc.inc`, `scene/sub/x.inc`, `outside/secret.inc`,
    /// and (on Unix) `scene/link.inc` pointing at the secret.
    fn layout(tag: &str) -> PathBuf {
        let root = std::env::temp_dir().join(format!("trace-sandbox-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(root.join("scene/sub")).unwrap();
        std::fs::create_dir_all(root.join("outside")).unwrap();
        std::fs::write(root.join("scene/inc.inc"), "").unwrap();
        std::fs::write(root.join("scene/sub/x.inc"), "").unwrap();
        std::fs::write(root.join("outside/secret.inc"), "").unwrap();
        #[cfg(unix)]
        std::os::unix::fs::symlink(root.join("outside/secret.inc"), root.join("scene/link.inc"))
            .unwrap();
        root
    }

    #[test]
    fn files_inside_the_scene_folder_are_found() {
        let root = layout("inside");
        let sandbox = Sandbox::new(&root.join("scene"), &[]);
        assert!(sandbox.find("inc.inc").is_ok());
        assert!(sandbox.find("sub/x.inc").is_ok());
        assert!(sandbox.find("sub/../inc.inc").is_ok());
        assert_eq!(sandbox.find("missing.inc"), Err(Refusal::NotFound));
        let _ = std::fs::remove_dir_all(root);
    }

    #[test]
    fn files_outside_are_refused_however_named() {
        let root = layout("outside");
        let sandbox = Sandbox::new(&root.join("scene"), &[]);
        assert_eq!(sandbox.find("../outside/secret.inc"), Err(Refusal::Outside));
        let absolute = root.join("outside/secret.inc");
        assert_eq!(
            sandbox.find(absolute.to_str().unwrap()),
            Err(Refusal::Outside)
        );
        #[cfg(unix)]
        assert_eq!(sandbox.find("link.inc"), Err(Refusal::Outside));
        assert_eq!(sandbox.find("/etc/passwd"), Err(Refusal::Outside));
        // Allowing the folder with -L lets all of them through.
        let widened = Sandbox::new(&root.join("scene"), &[root.join("outside")]);
        assert!(widened.find("../outside/secret.inc").is_ok());
        assert!(widened.find("secret.inc").is_ok());
        #[cfg(unix)]
        assert!(widened.find("link.inc").is_ok());
        let _ = std::fs::remove_dir_all(root);
    }

    #[test]
    fn files_are_written_inside_the_scene_folder_only() {
        let root = layout("write");
        let sandbox = Sandbox::new(&root.join("scene"), &[root.join("outside")]);
        let scene = root.join("scene").canonicalize().unwrap();
        assert_eq!(sandbox.writable("new.txt"), Ok(scene.join("new.txt")));
        assert_eq!(
            sandbox.writable("sub/../sub/y.txt"),
            Ok(scene.join("sub/y.txt"))
        );
        // Not into a -L folder, not through `..`, an absolute path, a link or a folder.
        assert!(sandbox.writable("../outside/secret.inc").is_err());
        assert!(sandbox.writable("/tmp/x.txt").is_err());
        assert!(sandbox.writable("missing/x.txt").is_err());
        assert!(sandbox.writable("sub").is_err());
        #[cfg(unix)]
        assert!(sandbox.writable("link.inc").is_err());
        let _ = std::fs::remove_dir_all(root);
    }

    /// A link in a `-L` folder is the user's (Debian's include folder links its fonts); a link
    /// in the scene's folder, or a name climbing out of the `-L` folder, is not.
    #[cfg(unix)]
    #[test]
    fn links_in_include_folders_are_followed() {
        let root = layout("links");
        std::fs::create_dir_all(root.join("lib")).unwrap();
        std::os::unix::fs::symlink(root.join("outside/secret.inc"), root.join("lib/font.ttf"))
            .unwrap();
        let sandbox = Sandbox::new(&root.join("scene"), &[root.join("lib")]);
        assert!(sandbox.find("font.ttf").is_ok());
        assert_eq!(sandbox.find("link.inc"), Err(Refusal::Outside));
        assert_eq!(sandbox.find("../outside/secret.inc"), Err(Refusal::Outside));
        let _ = std::fs::remove_dir_all(root);
    }
}
