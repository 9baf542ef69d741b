//! Stanford PLY, ASCII or binary (either byte order): the `vertex` element's `x y z` (and
//! `nx ny nz` when all three are present) and the `face` element's index list
//! (`vertex_indices` or `vertex_index`). Other elements and properties are skipped.

use super::{MeshData, ParseError, fan};
use glam::DVec3;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(name: &str) -> Option<Scalar> {
        Some(match name {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }
}

#[derive(Debug)]
struct Property {
    name: String,
    /// `Some(count type)` for a list property.
    list: Option<Scalar>,
    value: Scalar,
}

#[derive(Debug)]
struct Element {
    name: String,
    count: usize,
    properties: Vec<Property>,
}

#[derive(Clone, Copy, PartialEq)]
enum Encoding {
    Ascii,
    Little,
    Big,
}

pub(super) fn parse(bytes: &[u8]) -> Result<MeshData, ParseError> {
    let Header {
        elements,
        encoding,
        body,
        lines: header_lines,
    } = header(bytes)?;
    let mut reader = match encoding {
        Encoding::Ascii => Reader::Ascii(AsciiReader::new(body, header_lines)?),
        _ => Reader::Binary {
            bytes: body,
            pos: 0,
            big: encoding == Encoding::Big,
        },
    };
    let mut mesh = MeshData::default();
    let mut polygon: Vec<u32> = Vec::new();
    for element in &elements {
        let find = |name: &str| element.properties.iter().position(|p| p.name == name);
        let (xyz, normal) = if element.name == "vertex" {
            let xyz = [find("x"), find("y"), find("z")];
            let Some(xyz) = xyz.iter().copied().collect::<Option<Vec<_>>>() else {
                return Err((None, "the vertex element lacks x, y or z".into()));
            };
            let normal: Option<Vec<usize>> =
                [find("nx"), find("ny"), find("nz")].into_iter().collect();
            (xyz, normal)
        } else {
            (Vec::new(), None)
        };
        let indices = if element.name == "face" {
            let k = find("vertex_indices").or_else(|| find("vertex_index"));
            match k {
                Some(k) if element.properties[k].list.is_some() => Some(k),
                _ => return Err((None, "the face element lacks a vertex_indices list".into())),
            }
        } else {
            None
        };
        let mut values = vec![0.0f64; element.properties.len()];
        for item in 0..element.count {
            let at =
                |line: Option<usize>, e: String| (line, format!("{} {item}: {e}", element.name));
            for (k, p) in element.properties.iter().enumerate() {
                match p.list {
                    None => values[k] = reader.scalar(p.value).map_err(|e| at(reader.line(), e))?,
                    Some(count_type) => {
                        let n = reader
                            .scalar(count_type)
                            .map_err(|e| at(reader.line(), e))?;
                        if !(0.0..=1e6).contains(&n) || n.fract() != 0.0 {
                            return Err(at(reader.line(), format!("bad list length {n}")));
                        }
                        polygon.clear();
                        for _ in 0..n as usize {
                            let v = reader.scalar(p.value).map_err(|e| at(reader.line(), e))?;
                            if Some(k) == indices {
                                if v < 0.0 || v.fract() != 0.0 || v >= mesh.vertices.len() as f64 {
                                    return Err(at(
                                        reader.line(),
                                        format!(
                                            "vertex index {v} out of range (the file has {} vertices)",
                                            mesh.vertices.len()
                                        ),
                                    ));
                                }
                                polygon.push(v as u32);
                            }
                        }
                        if Some(k) == indices {
                            if polygon.len() < 3 {
                                return Err(at(
                                    reader.line(),
                                    format!("a face needs 3 vertices, found {}", polygon.len()),
                                ));
                            }
                            fan(&polygon, &mut mesh.faces);
                        }
                    }
                }
            }
            if !xyz.is_empty() {
                let v = DVec3::new(values[xyz[0]], values[xyz[1]], values[xyz[2]]);
                let n = normal
                    .as_ref()
                    .map(|n| DVec3::new(values[n[0]], values[n[1]], values[n[2]]));
                if !v.is_finite() || n.is_some_and(|n| !n.is_finite()) {
                    return Err(at(
                        reader.line(),
                        "a coordinate or normal is not a finite number".into(),
                    ));
                }
                mesh.vertices.push(v);
                mesh.normals.extend(n);
            }
            reader.end_item().map_err(|e| at(reader.line(), e))?;
        }
    }
    if !mesh.normals.is_empty() {
        // Per-vertex normals: the normal indices are the vertex indices.
        mesh.normal_faces = mesh.faces.clone();
    }
    Ok(mesh)
}

/// What the header says, and where the data starts.
struct Header<'a> {
    elements: Vec<Element>,
    encoding: Encoding,
    /// The bytes after `end_header`.
    body: &'a [u8],
    /// The header's line count.
    lines: usize,
}

fn header(bytes: &[u8]) -> Result<Header<'_>, ParseError> {
    let mut pos = 0;
    let mut line_no = 0;
    let mut next_line = || -> Option<(usize, &str)> {
        if pos >= bytes.len() {
            return None;
        }
        let end = bytes[pos..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(bytes.len(), |k| pos + k);
        let line = std::str::from_utf8(&bytes[pos..end]).unwrap_or("\u{FFFD}");
        pos = (end + 1).min(bytes.len());
        line_no += 1;
        Some((line_no, line.trim_end_matches('\r')))
    };
    match next_line() {
        Some((_, "ply")) => {}
        _ => return Err((Some(1), "not a PLY file (it must start with `ply`)".into())),
    }
    let mut elements: Vec<Element> = Vec::new();
    let mut encoding = None;
    loop {
        let Some((n, line)) = next_line() else {
            return Err((None, "the header has no `end_header`".into()));
        };
        let at = Some(n);
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["end_header"] => break,
            ["comment", ..] | ["obj_info", ..] | [] => {}
            ["format", kind, _version] => {
                encoding = Some(match *kind {
                    "ascii" => Encoding::Ascii,
                    "binary_little_endian" => Encoding::Little,
                    "binary_big_endian" => Encoding::Big,
                    other => return Err((at, format!("unknown PLY format `{other}`"))),
                });
            }
            ["element", name, count] => {
                let count = count
                    .parse()
                    .map_err(|_| (at, format!("`{count}` is not an element count")))?;
                elements.push(Element {
                    name: name.to_string(),
                    count,
                    properties: Vec::new(),
                });
            }
            ["property", "list", count, value, name] => {
                let (Some(c), Some(v)) = (Scalar::parse(count), Scalar::parse(value)) else {
                    return Err((at, format!("unknown property type in `{line}`")));
                };
                let Some(e) = elements.last_mut() else {
                    return Err((at, "a property before any element".into()));
                };
                e.properties.push(Property {
                    name: name.to_string(),
                    list: Some(c),
                    value: v,
                });
            }
            ["property", value, name] => {
                let Some(v) = Scalar::parse(value) else {
                    return Err((at, format!("unknown property type `{value}`")));
                };
                let Some(e) = elements.last_mut() else {
                    return Err((at, "a property before any element".into()));
                };
                e.properties.push(Property {
                    name: name.to_string(),
                    list: None,
                    value: v,
                });
            }
            [word, ..] if matches!(*word, "element" | "property" | "format") => {
                return Err((at, format!("cannot read header line `{line}`")));
            }
            // Some exporters write free text without `comment`; it carries no structure.
            _ => {}
        }
    }
    let encoding = encoding.ok_or((None, "the header has no `format` line".to_string()))?;
    Ok(Header {
        elements,
        encoding,
        body: &bytes[pos..],
        lines: line_no,
    })
}

enum Reader<'a> {
    Ascii(AsciiReader<'a>),
    Binary {
        bytes: &'a [u8],
        pos: usize,
        big: bool,
    },
}

impl Reader<'_> {
    fn line(&self) -> Option<usize> {
        match self {
            Reader::Ascii(r) => Some(r.line),
            Reader::Binary { .. } => None,
        }
    }

    fn scalar(&mut self, t: Scalar) -> Result<f64, String> {
        match self {
            Reader::Ascii(r) => r.number(),
            Reader::Binary { bytes, pos, big } => {
                let n = t.size();
                let Some(raw) = bytes.get(*pos..*pos + n) else {
                    return Err("the file ends early".into());
                };
                *pos += n;
                let mut b = [0u8; 8];
                b[..n].copy_from_slice(raw);
                if *big {
                    b[..n].reverse();
                }
                Ok(match t {
                    Scalar::I8 => f64::from(b[0] as i8),
                    Scalar::U8 => f64::from(b[0]),
                    Scalar::I16 => f64::from(i16::from_le_bytes([b[0], b[1]])),
                    Scalar::U16 => f64::from(u16::from_le_bytes([b[0], b[1]])),
                    Scalar::I32 => f64::from(i32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                    Scalar::U32 => f64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                    Scalar::F32 => f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                    Scalar::F64 => f64::from_le_bytes(b),
                })
            }
        }
    }

    /// In ASCII, an element item is one line: nothing may be left on it.
    fn end_item(&mut self) -> Result<(), String> {
        match self {
            Reader::Ascii(r) => r.end_line(),
            Reader::Binary { .. } => Ok(()),
        }
    }
}

/// ASCII data: one element item per line.
struct AsciiReader<'a> {
    lines: std::iter::Peekable<std::str::Lines<'a>>,
    words: std::str::SplitWhitespace<'a>,
    line: usize,
    /// Whether the current item has not read its line yet.
    fresh: bool,
}

impl<'a> AsciiReader<'a> {
    fn new(body: &'a [u8], header_lines: usize) -> Result<AsciiReader<'a>, ParseError> {
        let text = std::str::from_utf8(body)
            .map_err(|_| (None, "the ASCII data is not text (UTF-8)".to_string()))?;
        Ok(AsciiReader {
            lines: text.lines().peekable(),
            words: "".split_whitespace(),
            line: header_lines,
            fresh: true,
        })
    }

    fn number(&mut self) -> Result<f64, String> {
        loop {
            if let Some(w) = self.words.next() {
                return w.parse().map_err(|_| format!("`{w}` is not a number"));
            }
            if !self.fresh {
                return Err("too few values on the line".into());
            }
            // Start the item's line (blank lines are skipped).
            let Some(l) = self.lines.next() else {
                return Err("the file ends early".into());
            };
            self.line += 1;
            self.words = l.split_whitespace();
            self.fresh = l.trim().is_empty();
        }
    }

    fn end_line(&mut self) -> Result<(), String> {
        match self.words.next() {
            Some(w) => Err(format!("unexpected `{w}` after the element's values")),
            None => {
                self.words = "".split_whitespace();
                self.fresh = true;
                Ok(())
            }
        }
    }
}
