//! The film: a linear RGB pixel buffer, its EXR and PNG files, and image metrics.
//!
//! Files are written to a temporary file in the target's folder and renamed into place, so
//! an interrupted write never leaves a broken file at the target path. A renderer need not
//! hold the whole image: [`write_streamed`] takes the rows in bands, top first, and writes
//! each as it comes (PNG rows and EXR scanline blocks), so memory follows the band, not the
//! image.

mod raster;
mod write;

pub use raster::{Part, Raster, Region, merge};
pub use write::{Format, Layout, NOTE_KEY, Rows, write_streamed};

use std::borrow::Cow;
use std::path::{Path, PathBuf};
use write::srgb8;

/// A linear-light RGB image, top row first.
#[derive(Clone, Debug, PartialEq)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row-major pixels, top row first.
    pub pixels: Vec<[f32; 3]>,
}

/// Errors reading or writing images.
#[derive(Debug, thiserror::Error)]
pub enum ImageError {
    /// File-system failure.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        source: std::io::Error,
    },
    /// Encoder or decoder failure.
    #[error("{path}: {message}")]
    Format {
        /// The file.
        path: PathBuf,
        /// What went wrong.
        message: String,
    },
    /// An extension other than .exr or .png.
    #[error("{0}: unknown image format (use .exr, .png or .ppm)")]
    UnknownFormat(PathBuf),
    /// Images of different sizes cannot be compared.
    #[error("image sizes differ: {0}x{1} and {2}x{3}")]
    SizeMismatch(u32, u32, u32, u32),
}

impl ImageError {
    /// The same error about `path` (a failure writing a temporary file names the target).
    pub(crate) fn naming(self, path: &Path) -> ImageError {
        match self {
            ImageError::Io { source, .. } => ImageError::Io {
                path: path.to_path_buf(),
                source,
            },
            ImageError::Format { message, .. } => ImageError::Format {
                path: path.to_path_buf(),
                message,
            },
            other => other,
        }
    }
}

/// sRGB encode (linear → display), the curve POV-Ray writes PNGs with.
pub fn linear_to_srgb(v: f64) -> f64 {
    if v <= 0.0031308 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    }
}

/// sRGB decode (display → linear).
pub fn srgb_to_linear(v: f64) -> f64 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

impl Film {
    /// A black film.
    pub fn new(width: u32, height: u32) -> Film {
        Film {
            width,
            height,
            pixels: vec![[0.0; 3]; width as usize * height as usize],
        }
    }

    /// Sets pixel (x, y).
    pub fn set(&mut self, x: u32, y: u32, v: [f32; 3]) {
        self.pixels[y as usize * self.width as usize + x as usize] = v;
    }

    /// Pixel (x, y).
    pub fn get(&self, x: u32, y: u32) -> [f32; 3] {
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// 8-bit sRGB bytes (clamped), as POV-Ray writes PNGs: `floor(255·srgb(v) + 0.5)`.
    pub fn to_srgb8(&self) -> Vec<u8> {
        self.pixels.iter().flat_map(|p| p.map(srgb8)).collect()
    }

    /// The film as an 8-bit sRGB PNG file's bytes, compressed quickly (for a live view).
    pub fn to_png(&self) -> Vec<u8> {
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, self.width, self.height);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_compression(png::Compression::Fast);
        let written = encoder
            .write_header()
            .and_then(|mut w| w.write_image_data(&self.to_srgb8()));
        written.expect("a PNG written to memory");
        bytes
    }

    /// Number of pixels with a NaN or infinite channel.
    pub fn non_finite_pixels(&self) -> usize {
        self.pixels
            .iter()
            .filter(|p| p.iter().any(|v| !v.is_finite()))
            .count()
    }

    /// Writes the film; the extension picks the format.
    pub fn write(&self, path: &Path) -> Result<(), ImageError> {
        self.write_with_threads(path, None)
    }

    /// Writes the film, compressing on one thread if `threads` is `Some(1)` (EXR blocks are
    /// otherwise compressed on all cores; the file is the same).
    pub fn write_with_threads(
        &self,
        path: &Path,
        threads: Option<usize>,
    ) -> Result<(), ImageError> {
        let mut whole = Some(Rows {
            y0: 0,
            values: Cow::Borrowed(self.pixels.as_flattened()),
        });
        let layout = Layout::default();
        write_streamed(path, self.width, self.height, &layout, threads, |_| {
            whole.take()
        })
    }

    /// Reads an EXR (any RGB(A) layer, half or float), PNG or PPM (sRGB-decoded) image.
    pub fn read(path: &Path) -> Result<Film, ImageError> {
        let format =
            Format::of(path).ok_or_else(|| ImageError::UnknownFormat(path.to_path_buf()))?;
        let fmt_err = |message: String| ImageError::Format {
            path: path.to_path_buf(),
            message,
        };
        match format {
            Format::Exr => {
                use exr::prelude::*;
                let image = read_first_rgba_layer_from_file(
                    path,
                    |res: Vec2<usize>, _: &RgbaChannels| {
                        Film::new(res.width() as u32, res.height() as u32)
                    },
                    |film: &mut Film, pos: Vec2<usize>, (r, g, b, _a): (f32, f32, f32, f32)| {
                        film.set(pos.x() as u32, pos.y() as u32, [r, g, b]);
                    },
                )
                .map_err(|e| fmt_err(e.to_string()))?;
                Ok(image.layer_data.channel_data.pixels)
            }
            Format::Png | Format::Ppm => {
                let img = image::ImageReader::open(path)
                    .map_err(|source| ImageError::Io {
                        path: path.to_path_buf(),
                        source,
                    })?
                    .decode()
                    .map_err(|e| fmt_err(e.to_string()))?
                    .into_rgb8();
                let pixels = img
                    .pixels()
                    .map(|p| p.0.map(|b| srgb_to_linear(b as f64 / 255.0) as f32))
                    .collect();
                Ok(Film {
                    width: img.width(),
                    height: img.height(),
                    pixels,
                })
            }
        }
    }
}

/// How different two images are.
#[cfg(feature = "flip")]
#[derive(Clone, Debug)]
pub struct Comparison {
    /// Mean FLIP (LDR, on the sRGB-encoded images, 67 pixels per degree): 0 identical, 1 worst.
    pub mean_flip: f32,
    /// Root mean square difference of the linear values over all channels.
    pub rmse: f64,
    /// Largest absolute channel difference.
    pub max_abs: f64,
    /// FLIP error map (magma colours), for a person to look at.
    pub flip_map: Vec<u8>,
}

/// Compares a test image against a reference.
#[cfg(feature = "flip")]
pub fn compare(reference: &Film, test: &Film) -> Result<Comparison, ImageError> {
    if (reference.width, reference.height) != (test.width, test.height) {
        return Err(ImageError::SizeMismatch(
            reference.width,
            reference.height,
            test.width,
            test.height,
        ));
    }
    let (w, h) = (reference.width, reference.height);
    let a = nv_flip::FlipImageRgb8::with_data(w, h, &reference.to_srgb8());
    let b = nv_flip::FlipImageRgb8::with_data(w, h, &test.to_srgb8());
    let error = nv_flip::flip(a, b, nv_flip::DEFAULT_PIXELS_PER_DEGREE);
    let mean_flip = nv_flip::FlipPool::from_image(&error).mean();
    let flip_map = error.apply_color_lut(&nv_flip::magma_lut()).to_vec();
    let mut sum = 0.0;
    let mut max_abs: f64 = 0.0;
    for (p, q) in reference.pixels.iter().zip(&test.pixels) {
        for c in 0..3 {
            let d = (p[c] - q[c]) as f64;
            sum += d * d;
            // NaN wins (f64::max would drop it): a NaN pixel must not look like a match.
            max_abs = if d.is_nan() || max_abs.is_nan() {
                f64::NAN
            } else {
                max_abs.max(d.abs())
            };
        }
    }
    let rmse = (sum / (reference.pixels.len() * 3).max(1) as f64).sqrt();
    Ok(Comparison {
        mean_flip,
        rmse,
        max_abs,
        flip_map,
    })
}

/// Writes an RGB8 buffer (such as a FLIP map) as PNG, atomically.
pub fn write_rgb8_png(
    path: &Path,
    width: u32,
    height: u32,
    bytes: Vec<u8>,
) -> Result<(), ImageError> {
    let tmp = crate::output::TempFile::new(path);
    let buffer: image::RgbImage = image::ImageBuffer::from_raw(width, height, bytes)
        .expect("buffer size matches width × height");
    buffer
        .save_with_format(tmp.path(), image::ImageFormat::Png)
        .map_err(|e| ImageError::Format {
            path: path.to_path_buf(),
            message: e.to_string(),
        })?;
    tmp.persist().map_err(|source| ImageError::Io {
        path: path.to_path_buf(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_image_written_in_bands_is_the_image_written_whole() {
        // An odd size, and bands of 5 rows: EXR's blocks of 16 scanlines straddle bands.
        let (w, h) = (37, 23);
        let mut film = Film::new(w, h);
        for y in 0..h {
            for x in 0..w {
                let v = (x * 7 + y * 13) as f32 / 400.0;
                film.set(x, y, [v, 1.0 - v, (x as f32 / w as f32).powi(2)]);
            }
        }
        let dir = std::env::temp_dir().join(format!("trace-bands-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for name in ["img.exr", "img.png"] {
            let (whole, banded) = (dir.join(format!("whole-{name}")), dir.join(name));
            film.write(&whole).unwrap();
            let mut y0 = 0;
            write_streamed(&banded, w, h, &Layout::default(), Some(1), |_| {
                (y0 < h).then(|| {
                    let rows = 5.min(h - y0);
                    let start = (y0 * w) as usize;
                    let band = Rows {
                        y0,
                        values: film.pixels[start..start + (rows * w) as usize]
                            .as_flattened()
                            .to_vec()
                            .into(),
                    };
                    y0 += rows;
                    band
                })
            })
            .unwrap();
            assert_eq!(
                Film::read(&banded).unwrap(),
                Film::read(&whole).unwrap(),
                "{name}"
            );
            if name.ends_with("exr") {
                assert_eq!(
                    std::fs::read(&banded).unwrap(),
                    std::fs::read(&whole).unwrap()
                );
            }
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn srgb_round_trip() {
        for i in 0..=100 {
            let v = i as f64 / 100.0;
            assert!((srgb_to_linear(linear_to_srgb(v)) - v).abs() < 1e-12);
        }
    }

    #[test]
    fn png_bytes_match_povray_rounding() {
        // POV-Ray: linear 0.5 → sRGB 0.7354 → 188.
        let f = Film {
            width: 1,
            height: 1,
            pixels: vec![[0.5, 0.2, 0.8]],
        };
        assert_eq!(f.to_srgb8(), vec![188, 124, 231]);
    }

    #[test]
    fn a_nan_pixel_is_a_difference() {
        let a = Film::new(2, 1);
        let mut b = Film::new(2, 1);
        b.set(1, 0, [f32::NAN, 0.0, 0.0]);
        let c = compare(&a, &b).unwrap();
        assert!(c.max_abs.is_nan() && c.rmse.is_nan());
        assert_eq!(b.non_finite_pixels(), 1);
    }
}
