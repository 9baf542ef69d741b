//! Image files written row by row: EXR (float channels), PNG (8 or 16-bit sRGB, with alpha)
//! and PPM (8 or 16-bit sRGB). Rows arrive as interleaved linear values, `Layout::channels`
//! a pixel: red, green, blue, then alpha if asked for, then the AOV channels.

use super::{ImageError, linear_to_srgb};
use std::borrow::Cow;
use std::io::Write;
use std::path::Path;

/// Image file formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// OpenEXR, linear float channels.
    Exr,
    /// PNG, 8 or 16-bit sRGB (alpha straight, not premultiplied).
    Png,
    /// PPM (binary P6), 8 or 16-bit sRGB.
    Ppm,
}

impl Format {
    /// The format a path's extension names.
    pub fn of(path: &Path) -> Option<Format> {
        match path.extension()?.to_str()?.to_ascii_lowercase().as_str() {
            "exr" => Some(Format::Exr),
            "png" => Some(Format::Png),
            "ppm" => Some(Format::Ppm),
            _ => None,
        }
    }

    /// The extension a file of this format gets.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Exr => "exr",
            Format::Png => "png",
            Format::Ppm => "ppm",
        }
    }
}

/// What a pixel of an output file holds besides its colour, and the note it carries.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// An alpha channel (PNG and EXR).
    pub alpha: bool,
    /// Bits per channel of PNG and PPM files: 8 or 16; 16 makes an EXR's channels half
    /// floats (POV-Ray's EXR), any other value 32-bit floats.
    pub bits: u8,
    /// Names of the EXR channels after R, G, B (and A): the AOVs.
    pub aovs: Vec<String>,
    /// A text stored in the file's metadata (trace's record of a part of an image).
    pub note: Option<String>,
}

impl Default for Layout {
    fn default() -> Layout {
        Layout {
            alpha: false,
            bits: 8,
            aovs: Vec::new(),
            note: None,
        }
    }
}

impl Layout {
    /// Values a pixel of the rows holds.
    pub fn channels(&self) -> usize {
        3 + usize::from(self.alpha) + self.aovs.len()
    }
}

/// The name of the metadata entry holding [`Layout::note`] (a PNG tEXt keyword, an EXR
/// attribute, a PPM comment's prefix).
pub const NOTE_KEY: &str = "trace-part";

/// Consecutive finished rows of an image, starting at row `y0`: `values` holds whole rows,
/// left to right, top row first, each pixel `Layout::channels` values.
#[derive(Clone, Debug)]
pub struct Rows<'a> {
    /// The first row.
    pub y0: u32,
    /// The rows' values (linear).
    pub values: Cow<'a, [f32]>,
}

/// Rows handed out one at a time from bands that arrive in order.
pub(super) struct RowFeed<'a, F> {
    /// Values a row holds.
    row_len: usize,
    next_band: F,
    band: Rows<'a>,
}

impl<'a, F: FnMut(Vec<f32>) -> Option<Rows<'a>>> RowFeed<'a, F> {
    pub(super) fn new(row_len: usize, next_band: F) -> Self {
        RowFeed {
            row_len,
            next_band,
            band: Rows {
                y0: 0,
                values: Cow::Borrowed(&[]),
            },
        }
    }

    /// Row `y`, which is the row asked for last or a later one; zero if the bands end before
    /// it (they do not, for a renderer that covers the image, unless it was stopped).
    pub(super) fn row(&mut self, y: u32) -> &[f32] {
        let rows_in = |band: &Rows| (band.values.len() / self.row_len.max(1)) as u32;
        while y >= self.band.y0 + rows_in(&self.band) {
            // (The band done with is handed back, for the next one's values if it owns them.)
            let spare = match std::mem::take(&mut self.band.values) {
                Cow::Owned(values) => values,
                Cow::Borrowed(_) => Vec::new(),
            };
            match (self.next_band)(spare) {
                Some(band) => self.band = band,
                None => {
                    self.band = Rows {
                        y0: y,
                        values: Cow::Owned(vec![0.0; self.row_len]),
                    };
                }
            }
        }
        let start = (y - self.band.y0) as usize * self.row_len;
        &self.band.values[start..start + self.row_len]
    }
}

/// Writes a `width` × `height` image whose rows come from `next_band`, in bands of any height,
/// top first; the extension of `path` picks the format. `next_band` is handed the values of
/// the band before (empty at first, or if borrowed), for its own. Only the current band and the
/// encoder's buffers are held. EXR blocks are compressed on all cores unless `threads` is
/// `Some(1)` (the file is the same).
pub fn write_streamed<'a>(
    path: &Path,
    width: u32,
    height: u32,
    layout: &Layout,
    threads: Option<usize>,
    next_band: impl FnMut(Vec<f32>) -> Option<Rows<'a>>,
) -> Result<(), ImageError> {
    let format = Format::of(path).ok_or_else(|| ImageError::UnknownFormat(path.to_path_buf()))?;
    let tmp = crate::output::TempFile::new(path);
    let mut feed = RowFeed::new(width as usize * layout.channels(), next_band);
    let file = std::fs::File::create(tmp.path()).map_err(|source| ImageError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let out = std::io::BufWriter::new(file);
    let size = (width, height);
    match format {
        Format::Exr => {
            let mut names = vec!["R".to_string(), "G".into(), "B".into()];
            if layout.alpha {
                names.push("A".into());
            }
            names.extend(layout.aovs.iter().cloned());
            let mut row = |y: u32, values: &mut Vec<f32>| values.extend_from_slice(feed.row(y));
            write_exr(
                out,
                size,
                &names,
                (layout.note.as_deref(), layout.bits == 16),
                threads != Some(1),
                &mut row,
            )
        }
        Format::Png => write_png(out, size, layout, &mut |y, bytes| {
            encode_row(feed.row(y), layout, true, bytes)
        }),
        Format::Ppm => write_ppm(out, size, layout, &mut |y, bytes| {
            encode_row(feed.row(y), layout, false, bytes)
        }),
    }
    .map_err(|e| e.naming(path))?;
    tmp.persist().map_err(|source| ImageError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// A row of linear values as PNG or PPM samples: sRGB colour, linear alpha (PNG only, with
/// the colour straight), 8 or 16 bits big-endian.
fn encode_row(row: &[f32], layout: &Layout, with_alpha: bool, bytes: &mut Vec<u8>) {
    let c = layout.channels();
    if layout.bits == 8 && !(layout.alpha && with_alpha) {
        // The common case, by table: the same bytes as below.
        let table = srgb8_table();
        for px in row.chunks_exact(c) {
            bytes.extend(px[..3].iter().map(|&v| table.byte(v)));
        }
        return;
    }
    for px in row.chunks_exact(c) {
        let mut put = |v: f64| match layout.bits {
            16 => bytes.extend_from_slice(&quantise(v, 65535.0).to_be_bytes()),
            _ => bytes.push(quantise(v, 255.0) as u8),
        };
        // (PNG's alpha is straight: the premultiplied colour over its alpha.)
        let alpha = if layout.alpha { px[3] as f64 } else { 1.0 };
        let straight = if with_alpha && alpha > 0.0 {
            1.0 / alpha
        } else {
            1.0
        };
        for &v in &px[..3] {
            put(linear_to_srgb((v as f64 * straight).clamp(0.0, 1.0)));
        }
        if layout.alpha && with_alpha {
            put(alpha.clamp(0.0, 1.0));
        }
    }
}

/// `floor(max·v + 0.5)`, as POV-Ray rounds; an exact tie within the film's single precision
/// rounds up as there (POV-Ray's values are exact doubles: `Gray30` of a scene without gamma,
/// 0.3, is 76.5 and POV-Ray writes 77).
fn quantise(v: f64, max: f64) -> u16 {
    const FILM_PRECISION: f64 = 1e-5;
    (max * v + 0.5 + FILM_PRECISION).floor().clamp(0.0, max) as u16
}

/// An 8-bit sRGB byte of a linear value, as [`encode_row`] writes it.
pub(super) fn srgb8(v: f32) -> u8 {
    quantise(linear_to_srgb((v as f64).clamp(0.0, 1.0)), 255.0) as u8
}

/// [`srgb8`] by table: `thresholds[k]` is the least linear value whose byte exceeds k, so a
/// value's byte is the number of thresholds at or below it (a binary search instead of a
/// power per channel; the PNG writer spent half its time in `powf`).
struct Srgb8Table {
    thresholds: [f32; 255],
}

impl Srgb8Table {
    fn byte(&self, v: f32) -> u8 {
        self.thresholds.partition_point(|&t| t <= v) as u8
    }
}

fn srgb8_table() -> &'static Srgb8Table {
    static TABLE: std::sync::OnceLock<Srgb8Table> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let mut thresholds = [0.0f32; 255];
        for (k, t) in thresholds.iter_mut().enumerate() {
            // The least non-negative f32 (ordered as its bits) whose byte exceeds k.
            let (mut lo, mut hi) = (0u32, 1.0f32.to_bits());
            while lo < hi {
                let mid = lo + (hi - lo) / 2;
                if usize::from(srgb8(f32::from_bits(mid))) > k {
                    hi = mid;
                } else {
                    lo = mid + 1;
                }
            }
            *t = f32::from_bits(lo);
        }
        Srgb8Table { thresholds }
    })
}

/// An EXR of float channels `names` (sorted in the file as EXR asks; R, G, B and A in half
/// floats if `half`, values beyond their range written as the largest), zip-compressed in blocks of 16
/// scanlines, top first, filled from `row(y)` (interleaved values in `names`' order) in file
/// order, then compressed on all cores if `parallel`.
pub(super) fn write_exr(
    out: impl Write + std::io::Seek,
    (width, height): (u32, u32),
    names: &[String],
    (note, half): (Option<&str>, bool),
    parallel: bool,
    row: &mut dyn FnMut(u32, &mut Vec<f32>),
) -> Result<(), ImageError> {
    use exr::block::UncompressedBlock;
    use exr::block::writer::ChunksWriter;
    use exr::meta::Headers;
    use exr::meta::header::Header;
    use exr::prelude::*;
    let format = |e: exr::error::Error| ImageError::Format {
        path: Default::default(),
        message: e.to_string(),
    };
    let mut order: Vec<usize> = (0..names.len()).collect();
    order.sort_by(|&a, &b| names[a].as_bytes().cmp(names[b].as_bytes()));
    // (The AOV layers stay 32-bit: depths and object numbers need more than a half's
    // precision.)
    let colour = |i: usize| matches!(names[i].as_str(), "R" | "G" | "B" | "A");
    let channels: Vec<ChannelDescription> = order
        .iter()
        .map(|&i| {
            let kind = if half && colour(i) {
                SampleType::F16
            } else {
                SampleType::F32
            };
            ChannelDescription::named(names[i].as_str(), kind)
        })
        .collect();
    let encoding = Encoding::SMALL_LOSSLESS;
    let mut header = Header::new(
        Text::from(""),
        (width as usize, height as usize),
        SmallVec::from_vec(channels),
    )
    .with_encoding(
        encoding.compression,
        exr::meta::BlockDescription::ScanLines,
        encoding.line_order,
    );
    if let Some(note) = note {
        header
            .own_attributes
            .other
            .insert(Text::from(NOTE_KEY), AttributeValue::Text(Text::from(note)));
    }
    let headers: Headers = SmallVec::from_vec(vec![header]);
    let channel_list = headers[0].channels.clone();
    let stride = names.len();
    let width = width as usize;
    // (Each row is asked for once a channel: the last one is kept, split into one line of
    // values a channel, and the colour's halves converted a line at a time.)
    let (mut values, mut last) = (Vec::new(), None);
    let mut lines = vec![0.0f32; width * stride];
    let mut halves = vec![f16::ZERO; width * stride];
    let max = f16::MAX.to_f32();
    exr::block::write(out, headers, true, |meta, chunks| {
        let blocks = meta.collect_ordered_block_data(|block| {
            UncompressedBlock::collect_block_data_from_lines(&channel_list, block, |line| {
                let (x0, y) = (line.location.position.x(), line.location.position.y());
                let c = order[line.location.channel];
                if last != Some(y) {
                    values.clear();
                    row(y as u32, &mut values);
                    for (x, pixel) in values.chunks_exact(stride).enumerate() {
                        for (k, &v) in pixel.iter().enumerate() {
                            lines[k * width + x] = v;
                        }
                    }
                    for k in (0..stride).filter(|&k| half && colour(k)) {
                        let line = &mut lines[k * width..(k + 1) * width];
                        line.iter_mut().for_each(|v| *v = v.clamp(-max, max));
                        use half::slice::HalfFloatSliceExt;
                        halves[k * width..(k + 1) * width].convert_from_f32_slice(line);
                    }
                    last = Some(y);
                }
                let span = c * width + x0..c * width + x0 + line.location.sample_count;
                if half && colour(c) {
                    line.write_samples_from_slice(&halves[span])
                } else {
                    line.write_samples_from_slice(&lines[span])
                }
                .expect("a line holds sample_count samples");
            })
        });
        // Compressed a batch at a time, in parallel if `parallel` while the next batch is
        // read (which may render it), and written in order.
        let batch = if parallel {
            4 * rayon::current_num_threads()
        } else {
            1
        };
        let mut blocks = blocks;
        let mut current: Vec<_> = blocks.by_ref().take(batch).collect();
        while !current.is_empty() {
            let compress = |blocks: Vec<(usize, exr::block::UncompressedBlock)>| {
                use rayon::prelude::*;
                let zip = |(i, b)| (i, zip_block(b));
                if parallel {
                    blocks.into_par_iter().map(zip).collect()
                } else {
                    blocks.into_iter().map(zip).collect::<Vec<_>>()
                }
            };
            let (done, next) = if parallel {
                let mut done = Vec::new();
                let next = rayon::in_place_scope(|s| {
                    s.spawn(|_| done = compress(current));
                    blocks.by_ref().take(batch).collect()
                });
                (done, next)
            } else {
                (compress(current), blocks.by_ref().take(batch).collect())
            };
            for (i, chunk) in done {
                chunks.write_chunk(i, chunk)?;
            }
            current = next;
        }
        Ok(())
    })
    .map_err(format)
}

/// A block of scanlines as EXR's ZIP compression stores it (the bytes of its little-endian
/// samples split into the even and the odd ones, each byte then the difference from the one
/// before plus 128, deflated into a zlib stream), or the samples as they are where that is
/// no smaller, as the format asks. Deflated at miniz's fastest level, not the `exr` crate's
/// level 4: at 640×480 a picture's blocks take 9 ms instead of 26 ms on one core, for a file
/// 15 % larger.
fn zip_block(block: exr::block::UncompressedBlock) -> exr::block::chunk::Chunk {
    use exr::block::chunk::{Chunk, CompressedBlock, CompressedScanLineBlock};
    let raw = block.data;
    // (The samples are in the machine's order, which is the file's on the little-endian
    // machines this writer is built for.)
    const _: () = assert!(cfg!(target_endian = "little"));
    let n = raw.len();
    let mut split = vec![0u8; n];
    let (even, odd) = split.split_at_mut(n.div_ceil(2));
    for (k, &byte) in raw.iter().enumerate() {
        if k % 2 == 0 {
            even[k / 2] = byte;
        } else {
            odd[k / 2] = byte;
        }
    }
    let mut previous = split.first().copied().unwrap_or(0);
    for byte in split.iter_mut().skip(1) {
        let here = *byte;
        *byte = here.wrapping_sub(previous).wrapping_add(128);
        previous = here;
    }
    let deflated = miniz_oxide::deflate::compress_to_vec_zlib(&split, 1);
    Chunk {
        layer_index: block.index.layer,
        compressed_block: CompressedBlock::ScanLine(CompressedScanLineBlock {
            y_coordinate: block.index.pixel_position.y() as i32,
            compressed_pixels_le: if deflated.len() < n { deflated } else { raw },
        }),
    }
}

/// A PNG, RGB or RGBA, 8 or 16 bits, rows from `row(y, bytes)`: adaptive filter, and the png
/// crate's fast compression (fdeflate), which wrote `lights.rt` at 1280×960 in 0.03 s where
/// its balanced setting took 0.09 s (−5 % of the whole run), for a file 39 % larger.
pub(super) fn write_png(
    out: impl Write,
    (width, height): (u32, u32),
    layout: &Layout,
    row: &mut dyn FnMut(u32, &mut Vec<u8>),
) -> Result<(), ImageError> {
    let format = |e: png::EncodingError| ImageError::Format {
        path: Default::default(),
        message: e.to_string(),
    };
    let mut encoder = png::Encoder::new(out, width, height);
    encoder.set_color(if layout.alpha {
        png::ColorType::Rgba
    } else {
        png::ColorType::Rgb
    });
    encoder.set_depth(if layout.bits == 16 {
        png::BitDepth::Sixteen
    } else {
        png::BitDepth::Eight
    });
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::Filter::Adaptive);
    if let Some(note) = &layout.note {
        encoder
            .add_text_chunk(NOTE_KEY.into(), note.clone())
            .map_err(format)?;
    }
    let mut writer = encoder.write_header().map_err(format)?;
    let mut stream = writer.stream_writer().map_err(format)?;
    let mut bytes = Vec::new();
    for y in 0..height {
        bytes.clear();
        row(y, &mut bytes);
        stream.write_all(&bytes).map_err(|source| ImageError::Io {
            path: Default::default(),
            source,
        })?;
    }
    stream.finish().map_err(format)?;
    writer.finish().map_err(format)
}

/// A binary PPM (P6), 8 or 16 bits, with the note as a comment.
pub(super) fn write_ppm(
    mut out: impl Write,
    (width, height): (u32, u32),
    layout: &Layout,
    row: &mut dyn FnMut(u32, &mut Vec<u8>),
) -> Result<(), ImageError> {
    let io = |source| ImageError::Io {
        path: Default::default(),
        source,
    };
    let max = if layout.bits == 16 { 65535 } else { 255 };
    let note = match &layout.note {
        Some(n) => format!("# {NOTE_KEY}: {n}\n"),
        None => String::new(),
    };
    write!(out, "P6\n{note}{width} {height}\n{max}\n").map_err(io)?;
    let mut bytes = Vec::new();
    for y in 0..height {
        bytes.clear();
        row(y, &mut bytes);
        out.write_all(&bytes).map_err(io)?;
    }
    out.flush().map_err(io)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The file `write_streamed` makes of `values` (one band) and what reading it back gives.
    fn written(
        (w, h): (u32, u32),
        layout: &Layout,
        threads: Option<usize>,
        values: &[f32],
        name: &str,
    ) -> (Vec<u8>, crate::film::raster::Raster) {
        let path = std::env::temp_dir().join(format!(
            "trace-{name}-{}-{threads:?}.exr",
            std::process::id()
        ));
        let mut sent = false;
        write_streamed(&path, w, h, layout, threads, |_| {
            (!std::mem::replace(&mut sent, true)).then(|| Rows {
                y0: 0,
                values: values.into(),
            })
        })
        .unwrap();
        let bytes = std::fs::read(&path).unwrap();
        let read = crate::film::raster::Raster::read(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        (bytes, read)
    }

    #[test]
    fn a_half_float_exr_holds_each_channel_rounded_and_the_aovs_whole() {
        use half::f16;
        // Colour and alpha in halves (each value rounded to the nearest, beyond the half range
        // the largest half, not infinity), the AOV channel in full floats; an odd width, and
        // values that differ by channel and pixel, so that a channel or a pixel out of place
        // shows.
        let (w, h) = (19, 21);
        let layout = Layout {
            alpha: true,
            bits: 16,
            aovs: vec!["Z".into()],
            note: None,
        };
        let value = |x: u32, y: u32, c: u32| match (x + y + c) % 7 {
            0 => 1e6 * if c % 2 == 0 { 1.0 } else { -1.0 },
            _ => (x * 131 + y * 17 + c * 5) as f32 / 97.0 + 1.0 / 3.0,
        };
        let values: Vec<f32> = (0..h)
            .flat_map(|y| (0..w).flat_map(move |x| (0..5).map(move |c| value(x, y, c))))
            .collect();
        let (_, read) = written((w, h), &layout, None, &values, "half");
        for y in 0..h {
            for x in 0..w {
                for (c, name) in ["R", "G", "B", "A", "Z"].into_iter().enumerate() {
                    let v = value(x, y, c as u32);
                    let want = if name == "Z" {
                        v
                    } else {
                        let max = f16::MAX.to_f32();
                        f16::from_f32(v.clamp(-max, max)).to_f32()
                    };
                    assert_eq!(read.sample(x, y, name), Some(want), "{name} at ({x}, {y})");
                }
            }
        }
    }

    /// The EXR's blocks read back exactly where they were compressed (smooth rows) and where
    /// compressing them would not have made them smaller, so they are stored as they are
    /// (rows of noise), with a last block of fewer lines; compressed on all cores and on one,
    /// the file is the same.
    #[test]
    fn zip_blocks_read_back_whether_compressed_or_stored() {
        let (w, h) = (37, 50);
        let layout = Layout {
            alpha: false,
            bits: 32,
            aovs: vec![],
            note: None,
        };
        let mut random = crate::testing::Xorshift(0x5eed);
        let values: Vec<f32> = (0..w * h * 3)
            .map(|k| {
                if k / (3 * w) < 32 {
                    (k % 97) as f32 / 8.0
                } else {
                    f32::from_bits(random.next_u64() as u32 & 0x3fff_ffff)
                }
            })
            .collect();
        let write = |threads: Option<usize>| {
            let (bytes, read) = written((w, h), &layout, threads, &values, "zip");
            for y in 0..h {
                for x in 0..w {
                    for (c, name) in ["R", "G", "B"].into_iter().enumerate() {
                        let want = values[((y * w + x) * 3) as usize + c];
                        let got = read.sample(x, y, name).unwrap();
                        assert_eq!(got.to_bits(), want.to_bits(), "{name} at ({x}, {y})");
                    }
                }
            }
            bytes
        };
        let (all, one) = (write(None), write(Some(1)));
        assert_eq!(all, one);
        // The smooth rows were compressed: the file is well below the samples' own size.
        assert!(
            all.len() < (w * h * 12) as usize * 3 / 4,
            "{} bytes",
            all.len()
        );
    }

    #[test]
    fn the_srgb_table_gives_the_bytes_of_the_formula() {
        let table = srgb8_table();
        let check = |v: f32| assert_eq!(table.byte(v), srgb8(v), "{v:e} ({:#x})", v.to_bits());
        // Every 997th float from 0 to 1, each threshold and the float below it, and the rest.
        for bits in (0..=1.0f32.to_bits()).step_by(997) {
            check(f32::from_bits(bits));
        }
        for &t in &table.thresholds {
            check(t);
            check(f32::from_bits(t.to_bits() - 1));
        }
        for v in [
            -1.0,
            -0.0,
            0.0,
            1.0,
            1.5,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            1e-30,
            0.5,
        ] {
            check(v);
        }
    }
}
