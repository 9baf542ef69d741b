//! Whole image files as trace writes them, read back sample for sample (PNG and PPM bytes
//! as stored, EXR channels as floats), for assembling parts of an image into the whole
//! (`trace merge`, continuing an interrupted render): a merged file holds exactly the
//! samples of the parts, so it equals the whole render's file pixel for pixel.

use super::ImageError;
use super::write::{Format, Layout, NOTE_KEY, write_exr, write_png, write_ppm};
use std::path::Path;

/// A rectangle of an image in pixels: columns `x0..x1`, rows `y0..y1` (ends exclusive).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    /// First column.
    pub x0: u32,
    /// First row.
    pub y0: u32,
    /// Column past the last.
    pub x1: u32,
    /// Row past the last.
    pub y1: u32,
}

impl Region {
    /// The whole of a `width` × `height` image.
    pub fn full(width: u32, height: u32) -> Region {
        Region {
            x0: 0,
            y0: 0,
            x1: width,
            y1: height,
        }
    }

    /// Columns.
    pub fn width(&self) -> u32 {
        self.x1 - self.x0
    }

    /// Rows.
    pub fn height(&self) -> u32 {
        self.y1 - self.y0
    }

    fn area(&self) -> u64 {
        u64::from(self.width()) * u64::from(self.height())
    }

    fn overlaps(&self, o: &Region) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }
}

impl std::fmt::Display for Region {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{},{},{},{}", self.x0, self.y0, self.x1, self.y1)
    }
}

/// What a file holding part of an image records of it: the whole image's size, the part's
/// region, and a key of the scene and settings it was rendered from (parts merge only with
/// parts of equal keys).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Part {
    /// The whole image's width.
    pub width: u32,
    /// The whole image's height.
    pub height: u32,
    /// The part's rectangle.
    pub region: Region,
    /// The key of the scene and settings.
    pub key: String,
}

impl Part {
    /// The note stored in the file ([`Layout::note`]).
    pub fn note(&self) -> String {
        format!(
            "image={}x{} region={} key={}",
            self.width, self.height, self.region, self.key
        )
    }

    /// Reads a note back.
    pub fn parse(note: &str) -> Option<Part> {
        let mut image = None;
        let mut region = None;
        let mut key = None;
        for field in note.split_whitespace() {
            let (name, value) = field.split_once('=')?;
            match name {
                "image" => {
                    let (w, h) = value.split_once('x')?;
                    image = Some((w.parse().ok()?, h.parse().ok()?));
                }
                "region" => {
                    let v: Vec<u32> = value
                        .split(',')
                        .map(|n| n.parse().ok())
                        .collect::<Option<_>>()?;
                    let [x0, y0, x1, y1] = v[..] else { return None };
                    region = Some(Region { x0, y0, x1, y1 });
                }
                "key" => key = Some(value.to_string()),
                _ => {}
            }
        }
        let ((width, height), region, key) = (image?, region?, key?);
        let ok = region.x0 < region.x1
            && region.y0 < region.y1
            && region.x1 <= width
            && region.y1 <= height;
        ok.then_some(Part {
            width,
            height,
            region,
            key,
        })
    }
}

/// An image file's samples.
#[derive(Clone, Debug, PartialEq)]
enum Samples {
    /// PNG or PPM samples as stored, `bpp` bytes a pixel.
    Bytes { data: Vec<u8>, bpp: usize },
    /// EXR channels (R, G, B, then the others), interleaved.
    Floats { data: Vec<f32>, names: Vec<String> },
}

/// An image file trace wrote, read whole.
#[derive(Clone, Debug, PartialEq)]
pub struct Raster {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The file's format.
    pub format: Format,
    /// Alpha, bits and AOV channel names, and the file's note.
    pub layout: Layout,
    samples: Samples,
}

fn format_error(path: &Path, message: impl ToString) -> ImageError {
    ImageError::Format {
        path: path.to_path_buf(),
        message: message.to_string(),
    }
}

fn io_error(path: &Path, source: std::io::Error) -> ImageError {
    ImageError::Io {
        path: path.to_path_buf(),
        source,
    }
}

impl Raster {
    /// Reads a PNG (RGB or RGBA, 8 or 16 bits), PPM (P6) or EXR (float or half channels) file.
    pub fn read(path: &Path) -> Result<Raster, ImageError> {
        let format =
            Format::of(path).ok_or_else(|| ImageError::UnknownFormat(path.to_path_buf()))?;
        let bytes = std::fs::read(path).map_err(|e| io_error(path, e))?;
        match format {
            Format::Png => read_png(path, &bytes),
            Format::Ppm => read_ppm(path, &bytes),
            Format::Exr => read_exr(path),
        }
    }

    /// The value of channel `name` (R, G, B, A or an AOV's channel) at pixel (x, y): as
    /// stored (0 to 1 for PNG and PPM samples, straight colour; linear floats for EXR).
    pub fn sample(&self, x: u32, y: u32, name: &str) -> Option<f32> {
        let p = (y as usize * self.width as usize + x as usize) * self.stride();
        match &self.samples {
            Samples::Floats { data, names } => {
                let c = names.iter().position(|n| n == name)?;
                data.get(p + c).copied()
            }
            Samples::Bytes { data, .. } => {
                let c = ["R", "G", "B", "A"].iter().position(|n| *n == name)?;
                if c == 3 && !self.layout.alpha {
                    return None;
                }
                Some(match self.layout.bits {
                    16 => {
                        u16::from_be_bytes([data[p + 2 * c], data[p + 2 * c + 1]]) as f32 / 65535.0
                    }
                    _ => data[p + c] as f32 / 255.0,
                })
            }
        }
    }

    /// The part of an image this file records, if it is one.
    pub fn part(&self) -> Option<Part> {
        self.layout.note.as_deref().and_then(Part::parse)
    }

    /// A blank image of the same kind, `width` × `height`.
    fn blank(&self, width: u32, height: u32) -> Raster {
        let n = width as usize * height as usize;
        let samples = match &self.samples {
            Samples::Bytes { bpp, .. } => Samples::Bytes {
                data: vec![0; n * bpp],
                bpp: *bpp,
            },
            Samples::Floats { names, .. } => Samples::Floats {
                data: vec![0.0; n * names.len()],
                names: names.clone(),
            },
        };
        Raster {
            width,
            height,
            format: self.format,
            layout: Layout {
                note: None,
                ..self.layout.clone()
            },
            samples,
        }
    }

    /// Values a pixel holds (bytes or floats).
    fn stride(&self) -> usize {
        match &self.samples {
            Samples::Bytes { bpp, .. } => *bpp,
            Samples::Floats { names, .. } => names.len(),
        }
    }

    /// Copies `from` (whole) into this image with its top-left corner at (x, y).
    fn paste(&mut self, from: &Raster, x: u32, y: u32) {
        let s = self.stride();
        let (w, fw) = (self.width as usize, from.width as usize);
        for row in 0..from.height as usize {
            let dst = ((y as usize + row) * w + x as usize) * s;
            let src = row * fw * s;
            match (&mut self.samples, &from.samples) {
                (Samples::Bytes { data: d, .. }, Samples::Bytes { data: f, .. }) => {
                    d[dst..dst + fw * s].copy_from_slice(&f[src..src + fw * s])
                }
                (Samples::Floats { data: d, .. }, Samples::Floats { data: f, .. }) => {
                    d[dst..dst + fw * s].copy_from_slice(&f[src..src + fw * s])
                }
                _ => unreachable!("pasted images are of one kind (checked by merge)"),
            }
        }
    }

    /// The rows `y0..y1` of this image.
    pub fn rows(&self, y0: u32, y1: u32) -> Raster {
        let mut out = self.blank(self.width, y1 - y0);
        let s = self.stride() * self.width as usize;
        let (a, b) = (y0 as usize * s, y1 as usize * s);
        match (&mut out.samples, &self.samples) {
            (Samples::Bytes { data: d, .. }, Samples::Bytes { data: f, .. }) => {
                d.copy_from_slice(&f[a..b])
            }
            (Samples::Floats { data: d, .. }, Samples::Floats { data: f, .. }) => {
                d.copy_from_slice(&f[a..b])
            }
            _ => unreachable!("blank keeps the kind"),
        }
        out
    }

    /// Writes the image (its format, layout and note) to `path`, through a temporary file.
    pub fn write(&self, path: &Path) -> Result<(), ImageError> {
        let tmp = crate::output::TempFile::new(path);
        let file = std::fs::File::create(tmp.path()).map_err(|e| io_error(path, e))?;
        let out = std::io::BufWriter::new(file);
        let size = (self.width, self.height);
        let row_len = self.width as usize * self.stride();
        match &self.samples {
            Samples::Bytes { data, .. } => {
                let mut row = |y: u32, bytes: &mut Vec<u8>| {
                    bytes.extend_from_slice(&data[y as usize * row_len..(y as usize + 1) * row_len])
                };
                match self.format {
                    Format::Ppm => write_ppm(out, size, &self.layout, &mut row),
                    _ => write_png(out, size, &self.layout, &mut row),
                }
            }
            Samples::Floats { data, names } => {
                let mut row = |y: u32, values: &mut Vec<f32>| {
                    values
                        .extend_from_slice(&data[y as usize * row_len..(y as usize + 1) * row_len])
                };
                write_exr(
                    out,
                    size,
                    names,
                    (self.layout.note.as_deref(), self.layout.bits == 16),
                    true,
                    &mut row,
                )
            }
        }
        .map_err(|e| e.naming(path))?;
        tmp.persist().map_err(|e| io_error(path, e))
    }
}

fn read_png(path: &Path, bytes: &[u8]) -> Result<Raster, ImageError> {
    // (No decoder limit of its own: a merged image is as big as the render it equals, and
    // trace's memory cap, `--max-memory`, bounds it.)
    let limits = png::Limits { bytes: usize::MAX };
    let mut decoder = png::Decoder::new_with_limits(std::io::Cursor::new(bytes), limits);
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(|e| format_error(path, e))?;
    let info = reader.info();
    let (width, height) = (info.width, info.height);
    let alpha = match info.color_type {
        png::ColorType::Rgb => false,
        png::ColorType::Rgba => true,
        other => {
            return Err(format_error(
                path,
                format!("a {other:?} PNG is not an image trace writes"),
            ));
        }
    };
    let bits = match info.bit_depth {
        png::BitDepth::Eight => 8,
        png::BitDepth::Sixteen => 16,
        other => {
            return Err(format_error(
                path,
                format!("{other:?}-bit PNG is not an image trace writes"),
            ));
        }
    };
    let note = info
        .uncompressed_latin1_text
        .iter()
        .find(|t| t.keyword == NOTE_KEY)
        .map(|t| t.text.clone());
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| format_error(path, "too large"))?;
    let mut data = vec![0; size];
    reader
        .next_frame(&mut data)
        .map_err(|e| format_error(path, e))?;
    let bpp = (3 + usize::from(alpha)) * usize::from(bits / 8);
    data.truncate(width as usize * height as usize * bpp);
    Ok(Raster {
        width,
        height,
        format: Format::Png,
        layout: Layout {
            alpha,
            bits,
            aovs: Vec::new(),
            note,
        },
        samples: Samples::Bytes { data, bpp },
    })
}

fn read_ppm(path: &Path, bytes: &[u8]) -> Result<Raster, ImageError> {
    let bad = || format_error(path, "not a binary PPM (P6) as trace writes it");
    let mut at = 0;
    let mut note = None;
    let mut fields = Vec::new();
    while fields.len() < 4 {
        while at < bytes.len() && bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        if bytes.get(at) == Some(&b'#') {
            let end = bytes[at..]
                .iter()
                .position(|&b| b == b'\n')
                .map_or(bytes.len(), |e| at + e);
            let comment = String::from_utf8_lossy(&bytes[at + 1..end])
                .trim()
                .to_string();
            if let Some(n) = comment.strip_prefix(&format!("{NOTE_KEY}:")) {
                note = Some(n.trim().to_string());
            }
            at = end;
            continue;
        }
        let start = at;
        while at < bytes.len() && !bytes[at].is_ascii_whitespace() {
            at += 1;
        }
        if start == at {
            return Err(bad());
        }
        fields.push(String::from_utf8_lossy(&bytes[start..at]).to_string());
    }
    at += 1;
    let num = |s: &str| s.parse::<u32>().map_err(|_| bad());
    if fields[0] != "P6" {
        return Err(bad());
    }
    let (width, height, max) = (num(&fields[1])?, num(&fields[2])?, num(&fields[3])?);
    let bits = if max > 255 { 16 } else { 8 };
    let bpp = 3 * usize::from(bits / 8);
    // (The header's size is checked against the bytes there are before anything is made.)
    let len = (width as usize)
        .checked_mul(height as usize)
        .and_then(|n| n.checked_mul(bpp))
        .ok_or_else(bad)?;
    let data = at
        .checked_add(len)
        .and_then(|end| bytes.get(at..end))
        .ok_or_else(bad)?
        .to_vec();
    Ok(Raster {
        width,
        height,
        format: Format::Ppm,
        layout: Layout {
            alpha: false,
            bits,
            aovs: Vec::new(),
            note,
        },
        samples: Samples::Bytes { data, bpp },
    })
}

fn read_exr(path: &Path) -> Result<Raster, ImageError> {
    use exr::prelude::*;
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_file(path)
        .map_err(|e| format_error(path, e))?;
    let layer = &image.layer_data;
    let (width, height) = (layer.size.width() as u32, layer.size.height() as u32);
    let list = &layer.channel_data.list;
    let name = |c: &AnyChannel<FlatSamples>| c.name.to_string();
    // R, G, B, A first, then the others in the file's order.
    let rank = |n: &str| {
        ["R", "G", "B", "A"]
            .iter()
            .position(|c| *c == n)
            .unwrap_or(4)
    };
    let mut order: Vec<usize> = (0..list.len()).collect();
    order.sort_by_key(|&i| rank(&name(&list[i])));
    let names: Vec<String> = order.iter().map(|&i| name(&list[i])).collect();
    if names.len() < 3 || names[..3] != ["R", "G", "B"] {
        return Err(format_error(path, "an EXR without R, G and B channels"));
    }
    let n = width as usize * height as usize;
    let mut data = vec![0.0f32; n * names.len()];
    for (k, &i) in order.iter().enumerate() {
        let samples = &list[i].sample_data;
        for p in 0..n {
            data[p * names.len() + k] = samples.value_by_flat_index(p).to_f32();
        }
    }
    let note = layer
        .attributes
        .other
        .get(&Text::from(NOTE_KEY))
        .and_then(|v| match v {
            AttributeValue::Text(t) => Some(t.to_string()),
            _ => None,
        });
    let alpha = names.get(3).is_some_and(|n| n == "A");
    let aovs = names[3 + usize::from(alpha)..].to_vec();
    // Half-float colour channels are written back as halves (a part of an image keeps its
    // precision when the parts are merged).
    let half = order[..3]
        .iter()
        .all(|&i| matches!(list[i].sample_data, FlatSamples::F16(_)));
    Ok(Raster {
        width,
        height,
        format: Format::Exr,
        layout: Layout {
            alpha,
            bits: if half { 16 } else { 32 },
            aovs,
            note,
        },
        samples: Samples::Floats { data, names },
    })
}

/// Assembles `parts` (files of parts of one image, from one scene and settings) into `out`:
/// the whole image, or, if they cover only a rectangle of it, a part covering that
/// rectangle. The parts must not overlap and must tile their rectangle exactly.
pub fn merge(parts: &[&Path], out: &Path) -> Result<Raster, String> {
    let mut read = Vec::new();
    for path in parts {
        let raster = Raster::read(path).map_err(|e| e.to_string())?;
        let part = raster.part().ok_or_else(|| {
            format!(
                "{}: not a part of an image (no trace region recorded in it)",
                path.display()
            )
        })?;
        if (raster.width, raster.height) != (part.region.width(), part.region.height()) {
            return Err(format!(
                "{}: its size differs from its recorded region",
                path.display()
            ));
        }
        read.push((path, raster, part));
    }
    let Some((first_path, first, first_part)) = read.first() else {
        return Err("no parts to merge".into());
    };
    let kind = |r: &Raster| {
        (
            r.format,
            r.layout.alpha,
            r.layout.bits,
            r.layout.aovs.clone(),
        )
    };
    for (path, raster, part) in &read[1..] {
        if (part.width, part.height) != (first_part.width, first_part.height)
            || part.key != first_part.key
        {
            return Err(format!(
                "{} and {} are parts of different renders (scene, settings or image size differ)",
                first_path.display(),
                path.display()
            ));
        }
        if kind(raster) != kind(first) {
            return Err(format!(
                "{} and {} differ in format, alpha, bits or channels",
                first_path.display(),
                path.display()
            ));
        }
    }
    if Format::of(out) != Some(first.format) {
        return Err(format!(
            "{}: the merged image keeps the parts' format (.{})",
            out.display(),
            first.format.extension()
        ));
    }
    for (i, (a, _, pa)) in read.iter().enumerate() {
        for (b, _, pb) in &read[i + 1..] {
            if pa.region.overlaps(&pb.region) {
                return Err(format!(
                    "{} ({}) and {} ({}) overlap",
                    a.display(),
                    pa.region,
                    b.display(),
                    pb.region
                ));
            }
        }
    }
    let bounds = read.iter().fold(first_part.region, |b, (_, _, p)| Region {
        x0: b.x0.min(p.region.x0),
        y0: b.y0.min(p.region.y0),
        x1: b.x1.max(p.region.x1),
        y1: b.y1.max(p.region.y1),
    });
    let covered: u64 = read.iter().map(|(_, _, p)| p.region.area()).sum();
    if covered != bounds.area() {
        return Err(format!(
            "the parts leave gaps: they cover {covered} of the {} pixels of {bounds}",
            bounds.area()
        ));
    }
    let mut whole = first.blank(bounds.width(), bounds.height());
    for (_, raster, part) in &read {
        whole.paste(
            raster,
            part.region.x0 - bounds.x0,
            part.region.y0 - bounds.y0,
        );
    }
    if bounds != Region::full(first_part.width, first_part.height) {
        whole.layout.note = Some(
            Part {
                region: bounds,
                ..first_part.clone()
            }
            .note(),
        );
    }
    whole.write(out).map_err(|e| e.to_string())?;
    Ok(whole)
}
