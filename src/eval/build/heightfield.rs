//! A `height_field`'s image read into POV-Ray's 16-bit heights.
//!
//! POV-Ray's conversions (checked against its source and renders): a palette image's height is
//! the palette index × 256 (not the colour); 16-bit grey is the value itself; 8-bit grey is the
//! value × 257 after POV-Ray's single-precision grey conversion (which takes one from 84 of the
//! 256 values); an 8-bit colour image is red × 256 + green; a 16-bit colour image is its grey
//! (0.297 r + 0.589 g + 0.114 b) × 65535.

use std::path::Path;

/// The largest image trace reads as a height field (pixels).
const MAX_PIXELS: u64 = 1 << 26;

/// Width, height and the heights with the image's bottom row first (POV-Ray's z = 0 is the
/// image's last row), each row left to right.
pub(in crate::eval) fn read_png(path: &Path) -> Result<(u32, u32, Vec<u16>), String> {
    let file = std::io::BufReader::new(std::fs::File::open(path).map_err(|e| e.to_string())?);
    let mut decoder = png::Decoder::new(file);
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let (w, h) = (reader.info().width, reader.info().height);
    if u64::from(w) * u64::from(h) > MAX_PIXELS {
        return Err(format!(
            "{w}×{h} pixels; trace reads height fields up to {MAX_PIXELS} pixels"
        ));
    }
    if w < 2 || h < 2 {
        return Err(format!("{w}×{h} pixels: a height field needs at least 2×2"));
    }
    let size = reader
        .output_buffer_size()
        .ok_or("the image is too large")?;
    let mut buf = vec![0; size];
    let out = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let bits = out.bit_depth as usize;
    let channels = out.color_type.samples();
    let (wu, hu) = (w as usize, h as usize);
    // Sample `c` of pixel `x` in `row`, at the image's bit depth.
    let sample = |row: &[u8], x: usize, c: usize| -> u32 {
        let i = x * channels + c;
        match bits {
            16 => u32::from(u16::from_be_bytes([row[2 * i], row[2 * i + 1]])),
            8 => u32::from(row[i]),
            _ => {
                let bit = i * bits;
                u32::from((row[bit / 8] >> (8 - bits - bit % 8)) & ((1u16 << bits) - 1) as u8)
            }
        }
    };
    let max = ((1u32 << bits) - 1) as f32;
    let mut heights = vec![0u16; wu * hu];
    for (y, row) in buf.chunks(out.line_size).take(hu).enumerate() {
        let z = hu - 1 - y;
        for x in 0..wu {
            let v = |c| sample(row, x, c);
            heights[z * wu + x] = match out.color_type {
                png::ColorType::Indexed => (v(0) * 256) as u16,
                png::ColorType::Grayscale if bits <= 8 => grey_byte(v(0) as f32 / max) * 257,
                png::ColorType::Grayscale | png::ColorType::GrayscaleAlpha if bits == 16 => {
                    v(0) as u16
                }
                png::ColorType::GrayscaleAlpha => (v(0) * 257) as u16,
                _ if bits == 16 => grey16([v(0) as u16, v(1) as u16, v(2) as u16]),
                _ => (v(0) * 256 + v(1)) as u16,
            };
        }
    }
    Ok((w, h, heights))
}

/// The height of a 16-bit colour pixel: POV-Ray's grey of it (0.297 r + 0.589 g + 0.114 b).
pub(in crate::eval) fn grey16(rgb: [u16; 3]) -> u16 {
    let c = |k: usize| f64::from(f32::from(rgb[k]) / 65535.0f32);
    ((0.297 * c(0) + 0.589 * c(1) + 0.114 * c(2)) * 65535.0) as u16
}

/// A value kept in a 16-bit channel as POV-Ray keeps it (single precision, truncated).
pub(in crate::eval) fn channel16(v: f64) -> u16 {
    ((v as f32) * 65535.0) as i32 as u16
}

/// POV-Ray's single-precision grey of a grey palette entry `e` (0 to 1), back to a byte.
fn grey_byte(e: f32) -> u16 {
    let g = e * 0.297f32 + e * 0.589f32 + e * 0.114f32;
    (g * 255.0f32) as u16
}

#[cfg(test)]
mod tests {
    use super::grey_byte;

    /// The 8-bit grey quirk: 3 becomes 2 × 257, 4 stays 4 × 257, 255 stays 65535.
    #[test]
    fn povrays_grey_conversion() {
        let grey8 = |v: u8| grey_byte(f32::from(v) / 255.0);
        assert_eq!(grey8(3), 2);
        assert_eq!(grey8(4), 4);
        assert_eq!(grey8(255), 255);
        let lowered = (0..=255u8)
            .filter(|&v| grey8(v) + 1 == u16::from(v))
            .count();
        assert_eq!(lowered, 84);
    }
}
