//! Image files as POV-Ray 3.7 reads them, for `image_map`, `image_pattern`, `bump_map` and
//! `height_field`: the formats it names (`png`, `jpeg`, `gif`, `tga`, `ppm`, `pgm`, `tiff`,
//! `bmp`, `exr`, `hdr`, and `sys`), found from the keyword or the file's extension, and
//! each format's own idea of how its numbers are encoded when the scene gives no `gamma`
//! (checked against POV-Ray's readers and renders):
//!
//! - PNG: an `sRGB` chunk means sRGB, a `gAMA` chunk a power law, neither sRGB;
//! - JPEG, GIF, TGA and BMP: sRGB;
//! - PPM, PGM and TIFF: no encoding known, the numbers are taken as working-gamma values;
//! - HDR and EXR: linear.
//!
//! Decoding uses the image crate with only these formats enabled; palette indices (a
//! palette image's height field, `use_index` and per-entry `filter`/`transmit`) come from the
//! png and gif decoders and, for BMP (1, 4, 8 bits) and colour-mapped TGA, from the file.

use crate::diag::Diagnostic;
use crate::eval::lang::expr::type_error;
use crate::eval::value::Value;
use crate::ir::{self, ImageMap, Pattern, PatternKind};
use crate::pattern::image::{ImageUse, Interpolation, MapType, Texels as ImageTexels};
use crate::syntax::{Node, NodeKind, View};
use std::path::Path;
use std::sync::Arc;

/// The largest image trace reads (pixels): 8192 × 8192.
const MAX_PIXELS: u64 = 1 << 26;

/// An image file format, as a scene names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(in crate::eval) enum FileType {
    Png,
    Jpeg,
    Gif,
    /// Fractint's continuous-potential file: a GIF twice as wide as the picture, each
    /// pixel's index in the left half the high byte of a 16-bit grey, the right half's the
    /// low byte (POV-Ray's `pot`).
    Pot,
    Tga,
    Ppm,
    Pgm,
    Tiff,
    Bmp,
    Exr,
    Hdr,
    /// `sys`: POV-Ray's platform format (none on Unix; trace reads the file's own format).
    Sys,
    /// `iff` (Amiga): named by POV-Ray, not read by trace.
    Unread(&'static str),
}

impl FileType {
    /// The format a keyword names.
    pub(in crate::eval) fn from_keyword(word: &str) -> Option<FileType> {
        Some(match word {
            "png" => FileType::Png,
            "jpeg" => FileType::Jpeg,
            "gif" => FileType::Gif,
            "tga" => FileType::Tga,
            "ppm" => FileType::Ppm,
            "pgm" => FileType::Pgm,
            "tiff" => FileType::Tiff,
            "bmp" => FileType::Bmp,
            "exr" => FileType::Exr,
            "hdr" => FileType::Hdr,
            "sys" => FileType::Sys,
            "iff" => FileType::Unread("iff"),
            "pot" => FileType::Pot,
            _ => return None,
        })
    }

    /// The format POV-Ray infers from a file name's extension (any case); `None` for an
    /// extension it does not know. A name without an extension is PNG (POV-Ray takes its
    /// output format, PNG unless told otherwise).
    pub(in crate::eval) fn from_name(name: &str) -> Option<FileType> {
        let Some((stem, ext)) = name.rsplit_once('.') else {
            return Some(FileType::Png);
        };
        if stem.is_empty() && !name.contains('/') || ext.contains('/') {
            return Some(FileType::Png);
        }
        Some(match ext.to_ascii_lowercase().as_str() {
            "png" => FileType::Png,
            "jpg" | "jpeg" => FileType::Jpeg,
            "gif" => FileType::Gif,
            "tga" => FileType::Tga,
            "ppm" => FileType::Ppm,
            "pgm" => FileType::Pgm,
            "tif" | "tiff" => FileType::Tiff,
            "bmp" => FileType::Bmp,
            "exr" => FileType::Exr,
            "hdr" => FileType::Hdr,
            "iff" => FileType::Unread("iff"),
            _ => return None,
        })
    }

    /// The extensions POV-Ray tries after a name that is not found as given.
    pub(in crate::eval) fn extensions(self) -> &'static [&'static str] {
        match self {
            FileType::Png => &[".png"],
            FileType::Jpeg => &[".jpg", ".jpeg"],
            FileType::Gif | FileType::Pot => &[".gif"],
            FileType::Tga => &[".tga"],
            FileType::Ppm => &[".ppm"],
            FileType::Pgm => &[".pgm"],
            FileType::Tiff => &[".tif", ".tiff"],
            FileType::Bmp => &[".bmp"],
            FileType::Exr => &[".exr"],
            FileType::Hdr => &[".hdr"],
            FileType::Sys | FileType::Unread(_) => &[],
        }
    }

    fn format(self) -> Option<image::ImageFormat> {
        use image::ImageFormat as F;
        Some(match self {
            FileType::Png => F::Png,
            FileType::Jpeg => F::Jpeg,
            FileType::Gif | FileType::Pot => F::Gif,
            FileType::Tga => F::Tga,
            FileType::Ppm | FileType::Pgm => F::Pnm,
            FileType::Tiff => F::Tiff,
            FileType::Bmp => F::Bmp,
            FileType::Exr => F::OpenExr,
            FileType::Hdr => F::Hdr,
            FileType::Sys | FileType::Unread(_) => return None,
        })
    }
}

/// How a file's numbers encode light, when the scene does not say (`gamma G` does).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::eval) enum Encoding {
    /// The sRGB transfer function.
    Srgb,
    /// A power law: linear = value^g (g is the decoding exponent, 2.2 for most files).
    Power(f64),
    /// Linear light (HDR, EXR): converted to the working gamma like any other.
    Linear,
    /// Unknown (PPM, PGM, TIFF): POV-Ray takes the numbers as working-gamma values.
    AsWorking,
}

impl Encoding {
    /// Linear light from a file value.
    pub(in crate::eval) fn decode(self, v: f64) -> f64 {
        match self {
            Encoding::Srgb => crate::eval::value::srgb_decode(v),
            Encoding::Power(g) => v.max(0.0).powf(g),
            Encoding::Linear | Encoding::AsWorking => v,
        }
    }
}

/// A decoded image file: its pixels as the file holds them.
pub(in crate::eval) struct Picture {
    pub width: u32,
    pub height: u32,
    /// Red, green, blue and alpha (1 opaque), top row first: 0 to 1 for integer files, as
    /// stored for floating-point ones.
    pub pixels: Vec<[f32; 4]>,
    /// Each pixel's palette index, for palette PNG and GIF files.
    pub indices: Option<Vec<u8>>,
    /// A grey file (one channel, with or without alpha).
    pub grey: bool,
    /// More than 8 bits per integer channel.
    pub deep: bool,
    /// Whether the file has an alpha channel (or a transparent palette entry).
    pub has_alpha: bool,
    /// The file's own encoding.
    pub encoding: Encoding,
    /// An interlaced GIF (POV-Ray 3.7 reads its rows in the file's order, not de-interlaced).
    pub interlaced: bool,
}

/// Reads `path` as a file of type `ty`.
pub(in crate::eval) fn read(path: &Path, ty: FileType) -> Result<Picture, String> {
    if let FileType::Unread(word) = ty {
        return Err(format!(
            "`{word}` images are not read by trace (PNG, JPEG, GIF, TGA, PPM, PGM, TIFF, BMP, EXR and HDR are)"
        ));
    }
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let mut reader = image::ImageReader::new(std::io::BufReader::new(file));
    match ty.format() {
        Some(format) => reader.set_format(format),
        None => reader = reader.with_guessed_format().map_err(|e| e.to_string())?,
    }
    let format = reader.format();
    let (w, h) = reader.into_dimensions().map_err(|e| e.to_string())?;
    if u64::from(w) * u64::from(h) > MAX_PIXELS {
        return Err(format!(
            "{w}×{h} pixels; trace reads images up to {MAX_PIXELS} pixels"
        ));
    }
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    let mut reader = image::ImageReader::new(std::io::BufReader::new(file));
    if let Some(format) = format {
        reader.set_format(format);
    }
    let mut limits = image::Limits::default();
    limits.max_alloc = Some(MAX_PIXELS * 16);
    reader.limits(limits);
    let decoded = reader.decode().map_err(|e| e.to_string())?;
    use image::DynamicImage as D;
    let grey = matches!(
        decoded,
        D::ImageLuma8(_) | D::ImageLumaA8(_) | D::ImageLuma16(_) | D::ImageLumaA16(_)
    );
    let deep = matches!(
        decoded,
        D::ImageLuma16(_) | D::ImageLumaA16(_) | D::ImageRgb16(_) | D::ImageRgba16(_)
    );
    let mut deep = deep;
    let mut has_alpha = decoded.color().has_alpha();
    let mut pixels: Vec<[f32; 4]> = decoded.into_rgba32f().pixels().map(|p| p.0).collect();
    match format {
        Some(image::ImageFormat::Hdr) => pixels.iter_mut().for_each(rgbe_midpoint),
        // POV-Ray reads 16 bits a sample of a TIFF file as their high byte.
        Some(image::ImageFormat::Tiff) if deep => {
            for p in &mut pixels {
                *p = p.map(|c| f32::from(((c * 65535.0).round() as u16) >> 8) / 255.0);
            }
            deep = false;
        }
        // POV-Ray reads an EXR file's channels as half floats, whatever the file holds.
        Some(image::ImageFormat::OpenExr) => {
            for p in &mut pixels {
                *p = p.map(|c| half::f16::from_f32(c).to_f32());
            }
        }
        _ => {}
    }
    let mut encoding = match format {
        Some(image::ImageFormat::Pnm) | Some(image::ImageFormat::Tiff) => Encoding::AsWorking,
        Some(image::ImageFormat::OpenExr) | Some(image::ImageFormat::Hdr) => Encoding::Linear,
        _ => Encoding::Srgb,
    };
    let (mut indices, mut interlaced) = (None, false);
    match format {
        Some(image::ImageFormat::Png) => {
            let (png_encoding, png_indices) = png_details(path)?;
            encoding = png_encoding;
            indices = png_indices;
        }
        Some(image::ImageFormat::Gif) => {
            let (gif_indices, transparent, gif_interlaced) = gif_indices(path)?;
            indices = Some(gif_indices);
            has_alpha |= transparent;
            interlaced = gif_interlaced;
        }
        Some(image::ImageFormat::Bmp) => {
            indices = bmp_indices(path, w, h);
            if let Some(alphas) = bmp_alpha(path, w, h)? {
                for (p, a) in pixels.iter_mut().zip(alphas) {
                    p[3] = a;
                }
                has_alpha = true;
            }
        }
        Some(image::ImageFormat::Tga) => indices = tga_indices(path, w, h),
        _ => {}
    }
    if ty == FileType::Pot {
        return pot(indices.as_deref().unwrap_or_default(), w, h);
    }
    Ok(Picture {
        width: w,
        height: h,
        pixels,
        indices,
        grey,
        deep,
        has_alpha,
        encoding,
        interlaced,
    })
}

/// A Fractint POT file from its GIF's palette indices (`w` × `h`, top row first): a 16-bit
/// grey picture half as wide, its palette ignored.
fn pot(indices: &[u8], w: u32, h: u32) -> Result<Picture, String> {
    if w % 2 != 0 {
        return Err(format!(
            "a POT file is twice as wide as its picture; this one is {w} pixels wide"
        ));
    }
    let (half, wide) = (w as usize / 2, w as usize);
    let pixels = (0..h as usize * half)
        .map(|i| {
            let (y, x) = (i / half, i % half);
            let v = u16::from(indices[y * wide + x]) << 8 | u16::from(indices[y * wide + x + half]);
            let g = f32::from(v) / 65535.0;
            [g, g, g, 1.0]
        })
        .collect();
    Ok(Picture {
        width: w / 2,
        height: h,
        pixels,
        indices: None,
        grey: true,
        deep: true,
        has_alpha: false,
        encoding: Encoding::AsWorking,
        interlaced: false,
    })
}

/// POV-Ray's decoding of a Radiance RGBE pixel: the middle of the mantissa's step,
/// (m + 0.5) × 2^(e − 136), where the decoder gives m × 2^(e − 136). The shared exponent is
/// found again from the largest channel, whose mantissa lies in [128, 256).
fn rgbe_midpoint(p: &mut [f32; 4]) {
    let largest = f64::from(p[0].max(p[1]).max(p[2]));
    if largest > 0.0 {
        let step = (largest.log2().floor() - 7.0).exp2();
        for c in &mut p[..3] {
            *c = (f64::from(*c) + 0.5 * step) as f32;
        }
    }
}

/// A PNG's encoding (its `sRGB` or `gAMA` chunk) and, for a palette file, each pixel's index.
/// The alpha of each pixel (top row first) of a 32-bit uncompressed BMP: POV-Ray reads the
/// fourth byte of every pixel as its alpha (the image crate, as the format's specification
/// has it, ignores it). `None` for any other BMP.
fn bmp_alpha(path: &Path, w: u32, h: u32) -> Result<Option<Vec<f32>>, String> {
    let bytes = std::fs::read(path).map_err(|e| e.to_string())?;
    let u32_at = |i: usize| {
        bytes
            .get(i..i + 4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    let u16_at = |i: usize| {
        bytes
            .get(i..i + 2)
            .map(|b| u16::from_le_bytes([b[0], b[1]]))
    };
    let (Some(offset), Some(info), Some(height), Some(depth), Some(compression)) =
        (u32_at(10), u32_at(14), u32_at(22), u16_at(28), u32_at(30))
    else {
        return Ok(None);
    };
    // (The old OS/2 header has no 32-bit form; BI_RGB is compression 0.)
    if info < 40 || depth != 32 || compression != 0 {
        return Ok(None);
    }
    let top_down = (height as i32) < 0;
    let (w, h) = (w as usize, h as usize);
    let start = offset as usize;
    let Some(data) = bytes.get(start..start + 4 * w * h) else {
        return Ok(None);
    };
    let mut alphas = vec![0.0f32; w * h];
    for row in 0..h {
        let y = if top_down { row } else { h - 1 - row };
        for x in 0..w {
            alphas[y * w + x] = f32::from(data[4 * (row * w + x) + 3]) / 255.0;
        }
    }
    Ok(Some(alphas))
}

/// Each pixel's palette index (top row first) of an uncompressed 1-, 4- or 8-bit BMP, which
/// POV-Ray reads as a palette image (`None` for any other BMP, or one it cannot read).
fn bmp_indices(path: &Path, w: u32, h: u32) -> Option<Vec<u8>> {
    let bytes = std::fs::read(path).ok()?;
    let u32_at = |i: usize| {
        bytes
            .get(i..i + 4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
    };
    let u16_at = |i: usize| {
        bytes
            .get(i..i + 2)
            .map(|b| u16::from_le_bytes([b[0], b[1]]))
    };
    let (offset, info, height, depth, compression) = (
        u32_at(10)?,
        u32_at(14)?,
        u32_at(22)?,
        u16_at(28)?,
        u32_at(30)?,
    );
    if info < 40 || !matches!(depth, 1 | 4 | 8) || compression != 0 {
        return None;
    }
    let (w, h, bits) = (w as usize, h as usize, usize::from(depth));
    let row_bytes = (w * bits).div_ceil(32) * 4;
    let data = bytes.get(offset as usize..offset as usize + row_bytes * h)?;
    let top_down = (height as i32) < 0;
    let mut indices = vec![0u8; w * h];
    for (k, row) in data.chunks(row_bytes).enumerate() {
        let y = if top_down { k } else { h - 1 - k };
        for x in 0..w {
            let bit = x * bits;
            indices[y * w + x] =
                (row[bit / 8] >> (8 - bits - bit % 8)) & ((1u16 << bits) - 1) as u8;
        }
    }
    Some(indices)
}

/// Each pixel's palette index (top row first) of a colour-mapped TGA with 8-bit indices,
/// uncompressed (type 1) or run-length encoded (type 9), which POV-Ray reads as a palette
/// image (`None` for any other TGA).
fn tga_indices(path: &Path, w: u32, h: u32) -> Option<Vec<u8>> {
    let bytes = std::fs::read(path).ok()?;
    let u16_at = |i: usize| {
        bytes
            .get(i..i + 2)
            .map(|b| usize::from(u16::from_le_bytes([b[0], b[1]])))
    };
    let (id_len, map_type, kind) = (usize::from(*bytes.first()?), *bytes.get(1)?, *bytes.get(2)?);
    let (map_len, entry_bits) = (u16_at(5)?, usize::from(*bytes.get(7)?));
    let (depth, descriptor) = (*bytes.get(16)?, *bytes.get(17)?);
    if map_type != 1 || !matches!(kind, 1 | 9) || depth != 8 {
        return None;
    }
    let (w, h) = (w as usize, h as usize);
    let mut data = bytes
        .get(18 + id_len + map_len * entry_bits.div_ceil(8)..)?
        .iter();
    // Pixels in file order, then placed by the origin bit (set: the first row is the top).
    let mut file_order = Vec::with_capacity(w * h);
    while file_order.len() < w * h {
        if kind == 1 {
            file_order.push(*data.next()?);
            continue;
        }
        let head = *data.next()?;
        let count = usize::from(head & 0x7f) + 1;
        if head & 0x80 != 0 {
            let v = *data.next()?;
            file_order.extend(std::iter::repeat_n(v, count));
        } else {
            for _ in 0..count {
                file_order.push(*data.next()?);
            }
        }
    }
    file_order.truncate(w * h);
    if descriptor & 0x20 != 0 {
        return Some(file_order);
    }
    Some(file_order.chunks(w).rev().flatten().copied().collect())
}

fn png_details(path: &Path) -> Result<(Encoding, Option<Vec<u8>>), String> {
    let file = std::io::BufReader::new(std::fs::File::open(path).map_err(|e| e.to_string())?);
    let mut decoder = png::Decoder::new(file);
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let info = reader.info();
    let encoding = if info.srgb.is_some() {
        Encoding::Srgb
    } else if let Some(g) = info.gama_chunk.or(info.source_gamma) {
        Encoding::Power(1.0 / f64::from(g.into_value()))
    } else {
        Encoding::Srgb
    };
    if info.color_type != png::ColorType::Indexed {
        return Ok((encoding, None));
    }
    let size = reader
        .output_buffer_size()
        .ok_or("the image is too large")?;
    let mut buf = vec![0; size];
    let out = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let bits = out.bit_depth as usize;
    let (w, h) = (out.width as usize, out.height as usize);
    let mut indices = Vec::with_capacity(w * h);
    for row in buf.chunks(out.line_size).take(h) {
        for x in 0..w {
            let bit = x * bits;
            let shift = 8 - bits - bit % 8;
            indices.push((row[bit / 8] >> shift) & ((1u16 << bits) - 1) as u8);
        }
    }
    Ok((encoding, Some(indices)))
}

/// A GIF's first frame as palette indices (top row first), whether it has a transparent
/// index, and whether it is interlaced.
fn gif_indices(path: &Path) -> Result<(Vec<u8>, bool, bool), String> {
    let file = std::io::BufReader::new(std::fs::File::open(path).map_err(|e| e.to_string())?);
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options.read_info(file).map_err(|e| e.to_string())?;
    let (w, h) = (usize::from(decoder.width()), usize::from(decoder.height()));
    let frame = decoder
        .next_frame_info()
        .map_err(|e| e.to_string())?
        .ok_or("the file holds no image")?;
    let (left, top) = (usize::from(frame.left), usize::from(frame.top));
    let fw = usize::from(frame.width);
    let (transparent, interlaced) = (frame.transparent.is_some(), frame.interlaced);
    let mut buffer = vec![0u8; decoder.buffer_size()];
    decoder
        .read_into_buffer(&mut buffer)
        .map_err(|e| e.to_string())?;
    // The frame sits at its offset on the logical screen; the rest is index 0.
    let mut indices = vec![0u8; w * h];
    for (y, row) in buffer.chunks(fw.max(1)).enumerate() {
        for (x, &i) in row.iter().enumerate() {
            if let Some(p) = indices
                .get_mut((top + y) * w + left + x)
                .filter(|_| left + x < w)
            {
                *p = i;
            }
        }
    }
    Ok((indices, transparent, interlaced))
}

impl Picture {
    /// POV-Ray's 16-bit heights of the image, bottom row first (its z = 0 is the image's last
    /// row): a palette image's index × 256; a grey image's grey × 65535; a colour image of
    /// more than 8 bits its grey (0.297 r + 0.589 g + 0.114 b) × 65535; any other colour
    /// image red × 256 + green in bytes ((r × 256 + g) × 255, r and g from 0 to 1).
    pub(in crate::eval) fn heights(&self) -> Vec<u16> {
        let (w, h) = (self.width as usize, self.height as usize);
        let mut heights = vec![0u16; w * h];
        for y in 0..h {
            let z = h - 1 - y;
            for x in 0..w {
                let i = y * w + x;
                let [r, g, b, _] = self.pixels[i];
                heights[z * w + x] = if let Some(indices) = &self.indices {
                    u16::from(indices[i]) * 256
                } else if self.grey {
                    // POV-Ray's arithmetic on the stored integer: (v / max) × 65535 in f32,
                    // truncated (so some 16-bit greys lose one unit, as in POV-Ray).
                    let max = if self.deep { 65535.0f32 } else { 255.0 };
                    let v = (r * max).round();
                    (v / max * 65535.0) as i64 as u16
                } else if self.deep {
                    crate::eval::build::heightfield::grey16(
                        [r, g, b].map(|c| (c * 65535.0).round() as u16),
                    )
                } else {
                    // (Above 1, as in a float image, POV-Ray's 16-bit height wraps around.)
                    ((f64::from(r) * 256.0 + f64::from(g)) * 255.0) as i64 as u16
                };
            }
        }
        heights
    }
}

impl crate::eval::Evaluator<'_> {
    /// Finds and reads the image file `name`, of type `ty` (named by a keyword at
    /// `type_span`) or else inferred from the name. Like POV-Ray, a name not found as given
    /// is tried with the format's extensions.
    pub(in crate::eval) fn read_image(
        &mut self,
        name: &str,
        ty: Option<FileType>,
        type_span: crate::diag::Span,
        name_span: crate::diag::Span,
    ) -> crate::eval::Result<(std::path::PathBuf, Arc<Picture>)> {
        use crate::diag::Diagnostic;
        let ty = match ty.or_else(|| FileType::from_name(name)) {
            Some(ty) => ty,
            None => {
                return Err(Diagnostic::error(
                    format!("cannot tell the format of image \"{name}\" from its extension"),
                    name_span,
                )
                .with_note(
                    "name it before the file: png, jpeg, gif, tga, ppm, pgm, tiff, bmp, exr or hdr",
                ));
            }
        };
        if let FileType::Unread(word) = ty {
            return Err(Diagnostic::error(
                format!(
                    "unsupported: `{word}` images (trace reads png, jpeg, gif, tga, ppm, pgm, tiff, bmp, exr and hdr)"
                ),
                type_span,
            ));
        }
        let path = match self.sandbox.find(name) {
            Err(crate::eval::lang::sandbox::Refusal::NotFound) => ty
                .extensions()
                .iter()
                .find_map(|ext| self.sandbox.find(&format!("{name}{ext}")).ok()),
            found => found.ok(),
        };
        let path = match path {
            Some(path) => path,
            None => self.find_file(name, "image", name_span)?,
        };
        // A file is decoded once, however many maps and height fields use it.
        let key = (path.clone(), ty);
        if let Some(picture) = self.scene.pictures.get(&key) {
            return Ok((path, picture.clone()));
        }
        let picture = Arc::new(read(&path, ty).map_err(|e| {
            Diagnostic::error(
                format!("cannot read image {}: {e}", path.display()),
                name_span,
            )
        })?);
        self.scene.pictures.insert(key, picture.clone());
        if picture.interlaced {
            self.warn(Diagnostic::warning(
                "an interlaced GIF: trace reads it as the picture it is; POV-Ray 3.7 reads its rows in the file's interlaced order, a scrambled picture",
                name_span,
            ));
        }
        Ok((path, picture))
    }
}

/// An image read for `image_map`, `image_pattern` or `bump_map`.
pub(in crate::eval) struct ImageRead {
    pub(in crate::eval) image: ImageMap,
    pub(in crate::eval) kind: ImageRole,
}

/// What an image is read for.
pub(in crate::eval) enum ImageRole {
    /// `image_map`: its colours.
    Colours,
    /// `image_pattern`: a value pattern.
    Pattern(ImageUse),
    /// `bump_map`: heights, with the `bump_size` given inside.
    Bumps(Option<f64>),
}

impl crate::eval::Evaluator<'_> {
    /// `image_map { [png] "file" … }`, `image_pattern { … }` or `bump_map { … }`: the image
    /// (the colours of an image_map decoded to working gamma; the others' numbers as the file
    /// holds them, as POV-Ray reads them) and what it is for.
    pub(in crate::eval) fn image_map(&mut self, node: &Node) -> crate::eval::Result<ImageRead> {
        let (View::ImageMap(file_expr) | View::MaterialMap(file_expr)) = node.view() else {
            return Err(crate::eval::malformed(node, "an image"));
        };
        let file = &match self.eval(file_expr)? {
            Value::Str(s) => s,
            other => return Err(type_error("a file name (a string)", &other, file_expr.span)),
        };
        let role = node.word.as_str();
        let (mut once, mut map_type, mut interpolation) =
            (false, MapType::Planar, Interpolation::Nearest);
        let (mut use_, mut use_index, mut bump_size) = (ImageUse::Colour, false, None);
        let mut see_through: Vec<SeeThrough> = Vec::new();
        let (mut file_type, mut type_span, mut gamma) = (None, file_expr.span, None);
        self.each_item(&node.children, &mut |ev, item| {
            match (item.kind, item.view()) {
                (_, View::ImageOrientation(value)) => {
                    ev.eval(value)?;
                    ev.warn(Diagnostic::warning(
                        "an old orientation vector before the image (POV-Ray's syntax before 3.0): ignored, as POV-Ray ignores it",
                        item.span,
                    ));
                }
                (NodeKind::ImageType, _) => {
                    file_type = FileType::from_keyword(&item.word);
                    type_span = item.span;
                }
                (_, View::ImageGamma { gamma: given }) => {
                    gamma = Some(match given {
                        None => Encoding::Srgb,
                        Some(g) => {
                            let g_value = ev.float(g)?;
                            if g_value <= 0.0 {
                                return Err(Diagnostic::error("gamma value must be positive", g.span));
                            }
                            Encoding::Power(g_value)
                        }
                    })
                }
                (NodeKind::Once, _) => once = true,
                (_, View::MapType(value)) => {
                    let t = ev.float(value)?;
                    map_type = match t as i64 {
                        1 => MapType::Spherical,
                        2 => MapType::Cylindrical,
                        5 => MapType::Torus,
                        0 => MapType::Planar,
                        // (POV-Ray refuses the others in an image_map, and maps planar elsewhere.)
                        _ if role != "image_map" => MapType::Planar,
                        _ => {
                            return Err(Diagnostic::error(
                                "invalid map_type: an image_map takes 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus)",
                                value.span,
                            ));
                        }
                    };
                }
                (_, View::Interpolate(value)) => {
                    let n = ev.float(value)?;
                    interpolation = match n as i64 {
                        0 | 1 => {
                            // (POV-Ray 3.7 stops with "Cannot parse input" here; trace reads
                            // the scene and says so.)
                            ev.warn(Diagnostic::warning(
                                format!("`interpolate {}` is refused by POV-Ray 3.7 (it takes 2, 3 or 4); read as no interpolation", n as i64),
                                value.span,
                            ));
                            Interpolation::Nearest
                        }
                        2 => Interpolation::Bilinear,
                        3 => Interpolation::Bicubic,
                        4 => Interpolation::NormalizedDistance,
                        _ => {
                            return Err(Diagnostic::error(
                                "invalid interpolate value: 2 (bilinear), 3 (bicubic) or 4 (normalised distance)",
                                value.span,
                            ));
                        }
                    };
                }
                (_, View::ImageSeeThrough { index, amount }) if role == "image_map" => {
                    let filter = item.word == "filter";
                    let index = match index {
                        Some(i) => Some(((ev.float(i)? + 0.01) as i64, i.span)),
                        None => None,
                    };
                    let value = ev.float(amount)?;
                    see_through.push((filter, index, value as f32));
                }
                (NodeKind::ImageUse, _) if role != "image_map" => match item.word.as_str() {
                    "use_alpha" if role == "image_pattern" => use_ = ImageUse::Alpha,
                    "use_alpha" => return Err(ev.unknown_item(item, role)),
                    "use_index" => (use_, use_index) = (ImageUse::Colour, true),
                    _ => (use_, use_index) = (ImageUse::Colour, false),
                },
                (_, View::BumpSize(size)) if role == "bump_map" => {
                    bump_size = Some(ev.float(size)?)
                }
                _ => return Err(ev.unknown_item(item, role)),
            }
            Ok(())
        })?;
        let (path, picture) = self.read_image(file, file_type, type_span, file_expr.span)?;
        // An image_map's colours are decoded to linear light (by the scene's `gamma`, else by
        // the file's own encoding), then put in the working gamma; image_pattern and bump_map
        // take the numbers as they are, unless the scene gives a `gamma`.
        let working = self.lang.assumed_gamma.unwrap_or(1.0);
        let colours = role == "image_map";
        let encoding = gamma.unwrap_or(picture.encoding);
        // In a scene of a version before 3.7 (or of none), POV-Ray takes an image's numbers as
        // they are unless the image_map names a `gamma`: without `assumed_gamma` it corrects
        // no gamma at all, and with one the file's default gamma is the working gamma, which
        // puts the numbers back where they were.
        let uncorrected = self.lang.version.unwrap_or(3.62) < 3.7 - 1e-9;
        // (The same file read with the same settings shares its texels; where a setting is
        // written does not matter.)
        let settings: Vec<_> = see_through
            .iter()
            .map(|&(filter, index, amount)| (filter, index.map(|(i, _)| i), amount.to_bits()))
            .collect();
        let key = format!(
            "{path:?} {file_type:?} {colours} {gamma:?} {} {uncorrected} {settings:?}",
            working.to_bits()
        );
        let texels = match self.scene.texels.get(&key) {
            Some(texels) => texels.clone(),
            None => {
                let texels = Arc::new(texels(&picture, &see_through, &|v: f32| {
                    let v = f64::from(v);
                    let linear = match (colours, gamma) {
                        (false, None) => return v as f32,
                        (true, None) if uncorrected => return v as f32,
                        (true, None) if encoding == Encoding::AsWorking => return v as f32,
                        _ => encoding.decode(v),
                    };
                    (if working == 1.0 || !colours {
                        linear
                    } else {
                        linear.powf(1.0 / working)
                    }) as f32
                })?);
                self.scene.texels.insert(key, texels.clone());
                texels
            }
        };
        // `use_index` on a palette image: bump heights are the pixels' indices; a
        // material_map picks its textures by them.
        let indices = if use_index && role == "bump_map" || role == "material_map" {
            picture.indices.clone()
        } else {
            None
        };
        let image = ImageMap {
            file: file.clone(),
            width: picture.width,
            height: picture.height,
            texels,
            indices,
            has_alpha: picture.has_alpha,
            once,
            map_type,
            interpolation,
        };
        let kind = match role {
            "image_map" => ImageRole::Colours,
            "image_pattern" => ImageRole::Pattern(use_),
            _ => ImageRole::Bumps(bump_size),
        };
        Ok(ImageRead { image, kind })
    }
}

/// `filter`/`transmit` settings of an image_map: filter (else transmit), the palette entry
/// and where it is named (all entries when absent), the amount.
type SeeThrough = (bool, Option<(i64, crate::diag::Span)>, f32);

/// The texels of `picture`, its colour channels through `to_working`, with the image_map's
/// `filter`/`transmit` settings: a palette image's entries take them (all, or one by index);
/// another image adds `all`'s amount to every pixel, as POV-Ray does. An 8- or 16-bit file
/// keeps its codes when no palette entry has a setting of its own.
fn texels(
    picture: &Picture,
    see_through: &[SeeThrough],
    to_working: &dyn Fn(f32) -> f32,
) -> crate::eval::Result<ImageTexels> {
    let by_entry = picture.indices.is_some() && !see_through.is_empty();
    let is_float = matches!(picture.encoding, Encoding::Linear);
    if !by_entry && !is_float {
        let add = |start: f32, filter: bool| {
            see_through
                .iter()
                .filter(|(f, _, _)| *f == filter)
                .fold(start, |v, (_, _, amount)| v + amount)
        };
        let bits = if picture.deep { 16 } else { 8 };
        let coded = ImageTexels::coded(
            &picture.pixels,
            bits,
            to_working,
            |alpha| add(1.0 - alpha, false),
            add(0.0, true),
        );
        if let Some(texels) = coded {
            return Ok(texels);
        }
    }
    texel_values(picture, see_through, to_working).map(ImageTexels::values)
}

/// The texels of [`texels`] as values (20 bytes a pixel).
fn texel_values(
    picture: &Picture,
    see_through: &[SeeThrough],
    to_working: &dyn Fn(f32) -> f32,
) -> crate::eval::Result<Vec<[f32; 5]>> {
    let mut pixels: Vec<[f32; 5]> = picture
        .pixels
        .iter()
        .map(|p| {
            [
                to_working(p[0]),
                to_working(p[1]),
                to_working(p[2]),
                0.0,
                1.0 - p[3],
            ]
        })
        .collect();
    for &(filter, index, value) in see_through {
        let channel = if filter { 3 } else { 4 };
        match (&picture.indices, index) {
            (Some(indices), index) => {
                if let Some((i, span)) = index {
                    if !(0..256).contains(&i) {
                        return Err(Diagnostic::error(
                            format!("palette entry {i} is out of range for this image"),
                            span,
                        ));
                    }
                }
                for (px, &k) in pixels.iter_mut().zip(indices) {
                    if index.is_none_or(|(i, _)| i == i64::from(k)) {
                        px[channel] = value;
                    }
                }
            }
            (None, None) => pixels.iter_mut().for_each(|px| px[channel] += value),
            (None, Some((_, span))) => {
                return Err(Diagnostic::error(
                    format!(
                        "`{} N, V` sets a palette entry: this image has no palette (use `{} all V`)",
                        if filter { "filter" } else { "transmit" },
                        if filter { "filter" } else { "transmit" },
                    ),
                    span,
                ));
            }
        }
    }
    Ok(pixels)
}

impl crate::eval::Evaluator<'_> {
    /// `material_map { [TYPE] "file" [map_type N] [once] [interpolate N] texture {…}… }`: the
    /// textures numbered 0, 1, … picked by the image's pixels (their palette index, or red).
    pub(in crate::eval) fn material_map(
        &mut self,
        node: &Node,
    ) -> crate::eval::Result<ir::TextureMap> {
        let image_node = Node {
            slot: node.slot,
            kind: NodeKind::ImageMap,
            span: node.span,
            word: crate::syntax::Word::fixed("material_map"),
            word_span: node.word_span,
            args: node.args.clone(),
            children: node
                .children
                .iter()
                .filter(|c| c.kind != NodeKind::Texture)
                .cloned()
                .collect(),
        };
        let read = self.image_map(&image_node)?;
        let mut entries = Vec::new();
        for t in node.children.iter().filter(|c| c.kind == NodeKind::Texture) {
            entries.push((entries.len() as f64, self.texture(t)?));
        }
        if entries.is_empty() {
            return Err(Diagnostic::error(
                "a material_map needs at least one texture",
                node.word_span,
            ));
        }
        Ok(ir::TextureMap {
            pattern: Pattern::new(PatternKind::MaterialIndex(
                Arc::new(read.image),
                entries.len() as u32,
            )),
            transform: None,
            entries,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 8- and 16-bit files keep their codes, and every pixel reads back bit for bit the value
    /// the value path computes, through a gamma and with filter and transmit added; float
    /// files and palette entries with their own settings keep the values.
    #[test]
    fn coded_texels_read_back_the_values() {
        let span = crate::diag::Span::default();
        let gamma = |v: f32| f64::from(v).powf(2.2) as f32;
        let see = [(true, None, 0.25f32), (false, None, 0.125)];
        let cases: [(&str, FileType, &[SeeThrough], usize); 7] = [
            ("logo.jpg", FileType::Jpeg, &see, 4),
            ("trace_logo.png", FileType::Png, &[], 4),
            ("spots_alpha.png", FileType::Png, &see, 4),
            ("hills16.pgm", FileType::Pgm, &see, 8),
            ("logo16.png", FileType::Png, &[], 4),
            ("sky.exr", FileType::Exr, &[], 20),
            (
                "logo.gif",
                FileType::Gif,
                &[(true, Some((1, span)), 0.5)],
                20,
            ),
        ];
        for (name, ty, see_through, bytes) in cases {
            let path = Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("examples")
                .join(name);
            let path = if path.exists() { path } else { example(name) };
            let picture = read(&path, ty).expect("reads");
            let texels = texels(&picture, see_through, &gamma).expect("texels");
            let values = texel_values(&picture, see_through, &gamma).expect("values");
            let n = values.len();
            assert_eq!(texels.len(), n, "{name}");
            assert!(
                texels.bytes() >= n * bytes && texels.bytes() < n * bytes + 600_000,
                "{name}: {} bytes for {n} pixels",
                texels.bytes()
            );
            for (i, v) in values.iter().enumerate() {
                assert_eq!(
                    texels.get(i).map(f32::to_bits),
                    v.map(f32::to_bits),
                    "{name}, pixel {i}"
                );
            }
        }
    }

    fn example(name: &str) -> std::path::PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("examples/images")
            .join(name)
    }

    /// A POT file (examples/images/hills16.pot, made by scripts/make_images.py) holds the
    /// same 16-bit heights as the PGM beside it: high bytes in the left half, low bytes in
    /// the right.
    #[test]
    fn pot_files_are_sixteen_bit_greys_from_two_halves() {
        let pot = read(&example("hills16.pot"), FileType::Pot).expect("reads the POT file");
        let pgm = read(&example("hills16.pgm"), FileType::Pgm).expect("reads the PGM file");
        assert_eq!((pot.width, pot.height), (pgm.width, pgm.height));
        assert!(pot.grey && pot.deep && pot.indices.is_none());
        assert_eq!(pot.heights(), pgm.heights());
        assert!(
            pot.heights().iter().any(|&h| h & 0xff != 0),
            "low bytes are read"
        );
        // An odd width cannot be split in two halves.
        assert!(super::pot(&[0; 6], 3, 2).is_err_and(|e| e.contains("twice as wide")));
    }

    /// A palette BMP and a run-length encoded colour-mapped TGA give the same palette indices
    /// as the PNG of the same picture (examples/images/logo16.*, made by make_images.py), as
    /// POV-Ray reads them (checked against its renders with per-entry filter and transmit).
    #[test]
    fn palette_bmp_and_tga_files_give_their_indices() {
        let png = read(&example("logo16.png"), FileType::Png).expect("reads the PNG file");
        let want = png.indices.expect("a palette PNG");
        assert!(want.iter().any(|&i| i > 1), "several entries");
        for (name, ty) in [("logo16.bmp", FileType::Bmp), ("logo16.tga", FileType::Tga)] {
            let picture = read(&example(name), ty).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(picture.indices.as_ref(), Some(&want), "{name}");
        }
        // A true-colour BMP has none.
        let rgb = read(&example("logo.bmp"), FileType::Bmp).expect("reads the BMP file");
        assert!(rgb.indices.is_none());
    }
}
