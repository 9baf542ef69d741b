//! Wavefront OBJ: `v`, `vn` and `f` statements (other statements are ignored). Face corners
//! are `v`, `v/vt`, `v//vn` or `v/vt/vn`, 1-based or negative (relative to the end).

use super::{MeshData, ParseError, fan};
use glam::DVec3;

pub(super) fn parse(bytes: &[u8]) -> Result<MeshData, ParseError> {
    if bytes.starts_with(&[0xFE, 0xFF]) || bytes.starts_with(&[0xFF, 0xFE]) {
        return Err((
            Some(1),
            "the file is UTF-16 text; trace reads UTF-8 or ASCII OBJ".into(),
        ));
    }
    // Names (groups, materials) may be in any 8-bit encoding; only ASCII matters here.
    let text = String::from_utf8_lossy(bytes);
    let mut mesh = MeshData::default();
    // Whether every face so far gave a normal for each corner.
    let mut all_normals = true;
    let mut corners: Vec<(u32, Option<u32>)> = Vec::new();
    let mut polygon: Vec<u32> = Vec::new();
    let mut continued = String::new();
    let mut start_line = 0;
    for (i, raw) in text.lines().enumerate() {
        // A trailing backslash continues the statement on the next line.
        if continued.is_empty() {
            start_line = i + 1;
        }
        let raw = raw.split('#').next().unwrap_or("");
        if let Some(head) = raw.trim_end().strip_suffix('\\') {
            continued.push_str(head);
            continued.push(' ');
            continue;
        }
        continued.push_str(raw);
        let statement = std::mem::take(&mut continued);
        let line = Some(start_line);
        let mut tokens = statement.split_whitespace();
        let Some(keyword) = tokens.next() else {
            continue;
        };
        match keyword {
            "v" | "vn" => {
                let mut c = [0.0; 3];
                for (k, slot) in c.iter_mut().enumerate() {
                    let token = tokens
                        .next()
                        .ok_or_else(|| (line, format!("`{keyword}` needs 3 numbers, found {k}")))?;
                    *slot = number(token)
                        .ok_or_else(|| (line, format!("`{token}` is not a number")))?;
                }
                let v = DVec3::from_array(c);
                if keyword == "v" {
                    mesh.vertices.push(v);
                } else {
                    mesh.normals.push(v);
                }
            }
            "f" => {
                corners.clear();
                for token in tokens {
                    corners.push(corner(token, &mesh, line)?);
                }
                if corners.len() < 3 {
                    return Err((
                        line,
                        format!("a face needs 3 corners, found {}", corners.len()),
                    ));
                }
                polygon.clear();
                polygon.extend(corners.iter().map(|c| c.0));
                fan(&polygon, &mut mesh.faces);
                if corners.iter().all(|c| c.1.is_some()) {
                    polygon.clear();
                    polygon.extend(corners.iter().map(|c| c.1.unwrap_or(0)));
                    fan(&polygon, &mut mesh.normal_faces);
                } else {
                    all_normals = false;
                }
            }
            _ => {} // vt, g, o, s, usemtl, mtllib, l, p …: nothing trace renders.
        }
    }
    if !all_normals {
        // Some faces without normals: the mesh is flat (mesh2 has normals for all or none).
        mesh.normals.clear();
        mesh.normal_faces.clear();
    }
    if mesh.normal_faces.is_empty() {
        mesh.normals.clear();
    }
    Ok(mesh)
}

fn number(token: &str) -> Option<f64> {
    token.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// One face corner: the vertex index and the normal index, both 0-based.
fn corner(
    token: &str,
    mesh: &MeshData,
    line: Option<usize>,
) -> Result<(u32, Option<u32>), ParseError> {
    let mut parts = token.split('/');
    let v = parts.next().unwrap_or("");
    let _texture = parts.next();
    let n = parts.next().filter(|s| !s.is_empty());
    let vertex = index(v, mesh.vertices.len(), ("vertex", "vertices"), line)?;
    let normal = n
        .map(|n| index(n, mesh.normals.len(), ("normal", "normals"), line))
        .transpose()?;
    Ok((vertex, normal))
}

/// An OBJ index (1-based, or negative from the end of the list so far) as a 0-based index.
/// `what` names the list, in the singular and the plural.
fn index(
    token: &str,
    len: usize,
    (what, plural): (&str, &str),
    line: Option<usize>,
) -> Result<u32, ParseError> {
    let i: i64 = token
        .parse()
        .map_err(|_| (line, format!("`{token}` is not a {what} index")))?;
    let resolved = if i > 0 { i - 1 } else { len as i64 + i };
    if i == 0 || resolved < 0 || resolved >= len as i64 {
        return Err((
            line,
            format!("{what} index {i} is out of range (the file has {len} {plural} so far)"),
        ));
    }
    Ok(resolved as u32)
}
