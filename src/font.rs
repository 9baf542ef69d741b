//! TrueType fonts for `text`: glyph outlines, advances and kerning (read with ttf-parser), laid
//! out by POV-Ray 3.7's rules so that a line of text lands where POV-Ray puts it.
//!
//! POV-Ray's rules, measured against its renders and extents: coordinates are font units
//! divided by the em size, the baseline is y = 0; the first glyph's left edge is moved to x = 0
//! and the pen then stands at its advance less its left bearing; each later glyph is placed at
//! the pen plus its left bearing less its box's left edge plus the pair's kerning (format-0
//! `kern` subtables only, never tighter than one em), and the pen moves by its advance plus the
//! kerning; after every character the offset's x and y are added. The character map is chosen
//! by platform only (Macintosh first for ASCII strings, Unicode first for UTF-8), and a
//! character whose glyph is empty draws the next glyph that has an outline, as POV-Ray's
//! reader does; only the space character draws nothing.

use crate::ir::{Curve, Glyph, Text};
use glam::DVec2;
use ttf_parser::{Face, GlyphId, PlatformId, cmap};

/// How the scene's strings map to character codes (`global_settings { charset … }`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Charset {
    /// `ascii` (POV-Ray's default): the Macintosh character map first.
    #[default]
    Ascii,
    /// `utf8` or `sys`: the Unicode character map first.
    Utf8,
}

/// Lays out `codes` (character codes) in the font `data`, extruded `thickness` deep, with
/// `offset` added after every character.
pub fn layout(
    data: &[u8],
    codes: &[u32],
    thickness: f64,
    offset: DVec2,
    charset: Charset,
) -> Result<Text, String> {
    let face = Face::parse(data, 0).map_err(|e| format!("not a TrueType font ({e})"))?;
    if face.tables().glyf.is_none() {
        return Err(
            "the font has no TrueType outlines (a CFF font; POV-Ray reads only `glyf` fonts)"
                .into(),
        );
    }
    let em = f64::from(face.units_per_em());
    let f = 1.0 / em;
    let kern = Kerning::new(&face);
    let mut glyphs = Vec::with_capacity(codes.len());
    // Glyphs by glyph index, as POV-Ray caches them (a space caches an empty glyph).
    let mut cache: std::collections::HashMap<u16, (Vec<Curve>, f64)> = Default::default();
    let (mut pen_x, mut pen_y) = (0.0, 0.0);
    let mut previous = 0u16;
    for (i, &code) in codes.iter().enumerate() {
        let g = glyph_index(&face, code, charset);
        let (curves, x_min) = cache
            .entry(g)
            .or_insert_with(|| {
                if code == 0x20 {
                    (Vec::new(), 0.0)
                } else {
                    outline(&face, g)
                }
            })
            .clone();
        let advance = f64::from(face.glyph_hor_advance(GlyphId(g)).unwrap_or(0));
        let bearing = f64::from(face.glyph_hor_side_bearing(GlyphId(g)).unwrap_or(0));
        let shift = if i == 0 {
            pen_x = (advance - bearing) * f;
            DVec2::new(-x_min * f, 0.0)
        } else {
            let (kx, ky) = kern.pair(previous, g, em);
            let at = DVec2::new(pen_x + (bearing - x_min + kx) * f, pen_y + ky * f);
            pen_x += (advance + kx) * f;
            at
        };
        pen_x += offset.x;
        pen_y += offset.y;
        previous = g;
        let place = |p: DVec2| p * f + shift;
        glyphs.push(Glyph {
            curves: curves
                .iter()
                .map(|c| match *c {
                    Curve::Line(a, b) => Curve::Line(place(a), place(b)),
                    Curve::Quad(a, b, c) => Curve::Quad(place(a), place(b), place(c)),
                })
                .collect(),
        });
    }
    Ok(Text { thickness, glyphs })
}

/// The glyph of character `code`: the first character map of the preferred platforms (by
/// platform alone, as POV-Ray compares them) in a format POV-Ray reads (0, 4, 6) decides, and
/// a symbol font's format-4 map is tried again at code + 0xF000.
fn glyph_index(face: &Face, code: u32, charset: Charset) -> u16 {
    let Some(cmap) = face.tables().cmap else {
        return 0;
    };
    let order = match charset {
        Charset::Ascii => [
            PlatformId::Macintosh,
            PlatformId::Windows,
            PlatformId::Unicode,
            PlatformId::Windows,
        ],
        Charset::Utf8 => [
            PlatformId::Unicode,
            PlatformId::Windows,
            PlatformId::Macintosh,
            PlatformId::Windows,
        ],
    };
    for platform in order {
        for table in cmap.subtables {
            if table.platform_id != platform {
                continue;
            }
            let lookup = |c: u32| table.glyph_index(c).map_or(0, |g| g.0);
            match table.format {
                cmap::Format::ByteEncodingTable(_) | cmap::Format::TrimmedTableMapping(_) => {
                    return lookup(code);
                }
                cmap::Format::SegmentMappingToDeltaValues(_) => {
                    let g = lookup(code);
                    return if g == 0 && code < 0x100 {
                        lookup(code + 0xF000)
                    } else {
                        g
                    };
                }
                _ => {}
            }
        }
    }
    0
}

/// Glyph `g`'s outline in font units and its box's left edge. An empty glyph reads the next
/// glyph that has an outline (POV-Ray reads the glyph's data where the next one begins).
fn outline(face: &Face, g: u16) -> (Vec<Curve>, f64) {
    for id in g..face.number_of_glyphs() {
        let mut pen = Outline::default();
        if let Some(bbox) = face.outline_glyph(GlyphId(id), &mut pen) {
            return (pen.curves, f64::from(bbox.x_min));
        }
    }
    (Vec::new(), 0.0)
}

/// Collects a glyph's contours as lines and quadratic curves.
#[derive(Default)]
struct Outline {
    curves: Vec<Curve>,
    start: DVec2,
    at: DVec2,
}

impl ttf_parser::OutlineBuilder for Outline {
    fn move_to(&mut self, x: f32, y: f32) {
        self.start = DVec2::new(x.into(), y.into());
        self.at = self.start;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let to = DVec2::new(x.into(), y.into());
        self.curves.push(Curve::Line(self.at, to));
        self.at = to;
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let to = DVec2::new(x.into(), y.into());
        self.curves
            .push(Curve::Quad(self.at, DVec2::new(x1.into(), y1.into()), to));
        self.at = to;
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        // Not in `glyf` outlines (only CFF ones, refused above); kept as its control polygon.
        self.line_to(x1, y1);
        self.line_to(x2, y2);
        self.line_to(x, y);
    }

    fn close(&mut self) {
        if self.at != self.start {
            self.curves.push(Curve::Line(self.at, self.start));
        }
        self.at = self.start;
    }
}

/// The font's kerning pairs as POV-Ray reads them: the Microsoft (version 0) `kern` table's
/// format-0 subtables, each scanned in file order for the first pair that matches (so pairs
/// need not be sorted by their right glyph), with the first subtable's coverage flags.
struct Kerning<'a> {
    /// Coverage of the first subtable (POV-Ray applies it to all of them).
    coverage: u16,
    /// Each format-0 subtable's pairs (6 bytes each: left, right, value).
    subtables: Vec<&'a [u8]>,
}

fn u16_at(data: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_be_bytes([*data.get(at)?, *data.get(at + 1)?]))
}

impl<'a> Kerning<'a> {
    fn new(face: &Face<'a>) -> Kerning<'a> {
        let mut k = Kerning {
            coverage: 0,
            subtables: Vec::new(),
        };
        let Some(table) = face.raw_face().table(ttf_parser::Tag::from_bytes(b"kern")) else {
            return k;
        };
        if u16_at(table, 0) != Some(0) {
            return k;
        }
        let count = u16_at(table, 2).unwrap_or(0);
        let mut at = 4;
        for i in 0..count {
            let (Some(length), Some(coverage)) = (u16_at(table, at + 2), u16_at(table, at + 4))
            else {
                break;
            };
            if i == 0 {
                k.coverage = coverage;
            }
            if coverage >> 8 == 0 {
                let pairs = usize::from(u16_at(table, at + 6).unwrap_or(0));
                let first = at + 14;
                let end = (first + 6 * pairs).min(table.len());
                k.subtables.push(table.get(first..end).unwrap_or(&[]));
            }
            at += usize::from(length.max(6));
        }
        k
    }

    /// (along, across) the line, in font units, for glyph `left` followed by `right`.
    fn pair(&self, left: u16, right: u16, em: f64) -> (f64, f64) {
        let (mut x, mut y) = (0.0, 0.0);
        let (mut min_x, mut min_y) = (-em, -em);
        let c = self.coverage;
        if c & 1 == 0 {
            return (0.0, 0.0);
        }
        for pairs in &self.subtables {
            // POV-Ray stops at the first pair whose left glyph is past `left`.
            let found = pairs
                .chunks_exact(6)
                .map(|p| {
                    let l = u16::from_be_bytes([p[0], p[1]]);
                    let r = u16::from_be_bytes([p[2], p[3]]);
                    (l, r, f64::from(i16::from_be_bytes([p[4], p[5]])))
                })
                .take_while(|&(l, _, _)| l <= left)
                .find(|&(l, r, _)| l == left && r == right)
                .map(|(_, _, v)| v);
            let Some(v) = found else { continue };
            let cross = c & 4 != 0;
            if c & 2 != 0 {
                if cross { min_y = v } else { min_x = v }
            } else if cross {
                y = if c & 8 != 0 { v } else { y + v };
            } else {
                x = if c & 8 != 0 { v } else { x + v };
            }
        }
        (x.max(min_x), y.max(min_y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TIMROM: &str = "/usr/share/povray-3.7/include/timrom.ttf";

    fn right_edge(t: &Text) -> f64 {
        let mut x = f64::NEG_INFINITY;
        for g in &t.glyphs {
            for c in &g.curves {
                match *c {
                    Curve::Line(a, b) => x = x.max(a.x).max(b.x),
                    Curve::Quad(a, b, c) => x = x.max(a.x).max(b.x).max(c.x),
                }
            }
        }
        x
    }

    /// timrom "AV" is kerned by −187 units: POV-Ray's max_extent puts V's right edge at 1.278.
    #[test]
    fn kerning_follows_povray() {
        let Ok(data) = std::fs::read(TIMROM) else {
            eprintln!("skipped: {TIMROM} is not installed");
            return;
        };
        let codes: Vec<u32> = "AV".chars().map(u32::from).collect();
        let t = layout(&data, &codes, 1.0, DVec2::ZERO, Charset::Ascii).unwrap();
        assert_eq!(t.glyphs.len(), 2);
        assert!((right_edge(&t) - 1.278).abs() < 1e-3, "{}", right_edge(&t));
        // A space draws nothing but moves the pen.
        let spaced: Vec<u32> = " A".chars().map(u32::from).collect();
        let s = layout(&data, &spaced, 1.0, DVec2::ZERO, Charset::Ascii).unwrap();
        assert!(s.glyphs[0].curves.is_empty() && !s.glyphs[1].curves.is_empty());
    }

    #[test]
    fn garbage_is_refused() {
        assert!(layout(b"not a font", &[65], 1.0, DVec2::ZERO, Charset::Ascii).is_err());
    }
}
