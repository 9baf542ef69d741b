//! Mesh files (an extension to POV-Ray's language): Wavefront OBJ and Stanford PLY, read into
//! the same lists a `mesh2` holds, so that `trace convert` can write them out as a `mesh2`
//! include that POV-Ray renders identically.
//!
//! Hand-written rather than through a crate so that every error names the line (or, in a
//! binary PLY, the element) where the file goes wrong.

mod obj;
mod ply;

use glam::DVec3;
use std::path::Path;

/// A mesh as `mesh2` lists: vertices, optional normals, and triangles as indices (polygons are
/// split into fans).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    /// Vertex positions.
    pub vertices: Vec<DVec3>,
    /// Normals; empty when the file gives none (or not for every face).
    pub normals: Vec<DVec3>,
    /// Triangles, indices into `vertices`.
    pub faces: Vec<[u32; 3]>,
    /// Per triangle, indices into `normals`; empty exactly when `normals` is.
    pub normal_faces: Vec<[u32; 3]>,
}

/// Why a mesh file could not be read.
#[derive(Debug, thiserror::Error)]
#[error("{}{}: {message}", path.display(), location.map(|l| format!(":{l}")).unwrap_or_default())]
pub struct MeshFileError {
    /// The file.
    pub path: std::path::PathBuf,
    /// The 1-based line (text formats), if the error has one.
    pub location: Option<usize>,
    /// What is wrong.
    pub message: String,
}

/// The mesh file formats trace reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Wavefront `.obj`.
    Obj,
    /// Stanford `.ply` (ASCII or binary).
    Ply,
}

impl Format {
    /// The format a file name's extension names.
    pub fn of(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "obj" => Some(Format::Obj),
            "ply" => Some(Format::Ply),
            _ => None,
        }
    }
}

/// Reads a mesh file (format from its extension).
pub fn read(path: &Path) -> Result<MeshData, MeshFileError> {
    let fail = |location, message: String| MeshFileError {
        path: path.to_path_buf(),
        location,
        message,
    };
    let format = Format::of(path).ok_or_else(|| {
        fail(
            None,
            "unknown mesh format (trace reads .obj and .ply)".into(),
        )
    })?;
    let bytes = std::fs::read(path).map_err(|e| fail(None, e.to_string()))?;
    let parsed = match format {
        Format::Obj => obj::parse(&bytes),
        Format::Ply => ply::parse(&bytes),
    };
    let mesh = parsed.map_err(|(location, message)| fail(location, message))?;
    if mesh.faces.is_empty() {
        return Err(fail(None, "the file holds no faces".into()));
    }
    Ok(mesh)
}

/// A parse failure: the line (if any) and the message.
type ParseError = (Option<usize>, String);

/// Splits a polygon (vertex index list) into a fan of triangles.
fn fan(polygon: &[u32], out: &mut Vec<[u32; 3]>) {
    for k in 1..polygon.len().saturating_sub(1) {
        out.push([polygon[0], polygon[k], polygon[k + 1]]);
    }
}

/// Writes `mesh` as a POV-Ray include declaring `name` as a `mesh2` (numbers in Rust's
/// shortest round-trip form, so both renderers read the same values).
pub fn write_mesh2<W: std::io::Write>(
    mesh: &MeshData,
    name: &str,
    out: &mut W,
) -> std::io::Result<()> {
    let vector = |v: DVec3| format!("<{},{},{}>", v.x, v.y, v.z);
    let index = |f: [u32; 3]| format!("<{},{},{}>", f[0], f[1], f[2]);
    writeln!(out, "// Written by `trace convert`.")?;
    writeln!(out, "#declare {name} = mesh2 {{")?;
    let section = |out: &mut W, title: &str, items: Vec<String>| -> std::io::Result<()> {
        writeln!(out, "  {title} {{ {},", items.len())?;
        let last = items.len().saturating_sub(1);
        for (k, item) in items.iter().enumerate() {
            writeln!(out, "    {item}{}", if k < last { "," } else { "" })?;
        }
        writeln!(out, "  }}")
    };
    section(
        out,
        "vertex_vectors",
        mesh.vertices.iter().map(|v| vector(*v)).collect(),
    )?;
    if !mesh.normals.is_empty() {
        section(
            out,
            "normal_vectors",
            mesh.normals.iter().map(|v| vector(*v)).collect(),
        )?;
    }
    section(
        out,
        "face_indices",
        mesh.faces.iter().map(|f| index(*f)).collect(),
    )?;
    if !mesh.normal_faces.is_empty() {
        section(
            out,
            "normal_indices",
            mesh.normal_faces.iter().map(|f| index(*f)).collect(),
        )?;
    }
    writeln!(out, "}}")
}

/// Writes the `mesh2` include to `path` through a temporary file in the same folder, so an
/// existing file is never left half-written.
pub fn write_mesh2_file(mesh: &MeshData, name: &str, path: &Path) -> std::io::Result<()> {
    let tmp = crate::output::TempFile::new(path);
    let f = std::fs::File::create(tmp.path())?;
    let mut w = std::io::BufWriter::new(f);
    write_mesh2(mesh, name, &mut w)?;
    std::io::Write::flush(&mut w)?;
    drop(w);
    tmp.persist()
}

/// A POV-Ray identifier made from a file name: `bunny-1.obj` → `Bunny_1`.
pub fn identifier_for(path: &Path) -> String {
    let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("Mesh");
    let mut id: String = stem
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if let Some(first) = id.get(..1) {
        id.replace_range(..1, &first.to_ascii_uppercase());
    }
    if !id.starts_with(|c: char| c.is_ascii_alphabetic()) {
        id.insert_str(0, "Mesh_");
    }
    id
}

#[cfg(test)]
mod tests;
