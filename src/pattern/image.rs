//! Images as patterns: POV-Ray's planar image mapping (`map_pos`) and pixel lookup, shared by
//! `image_map` (colours), `image_pattern` (a value) and `bump_map` (a normal).

use glam::DVec3;

/// POV-Ray's weights for the grey of a colour (`Colour::greyscale`).
const GREY: [f32; 3] = [0.297, 0.589, 0.114];

/// A decoded image.
#[derive(Clone, PartialEq)]
pub struct ImageMap {
    /// The file as named in the scene.
    pub file: String,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Pixels, top row first: rgb and transmit (1 − alpha). For `image_map` the rgb is linear
    /// (working gamma); for `image_pattern` and `bump_map` it is the file's values, as POV-Ray
    /// reads them there without gamma.
    pub pixels: Vec<[f32; 4]>,
    /// For `bump_map … use_index` on a palette image: each pixel's palette index, the height
    /// POV-Ray takes then (without interpolation).
    pub indices: Option<Vec<u8>>,
    /// Whether the file has an alpha channel (`use_alpha` reads red otherwise).
    pub has_alpha: bool,
    /// `once`: no tiling; outside the unit square the image is absent.
    pub once: bool,
    /// `interpolate 2` (bilinear) or none (nearest pixel).
    pub bilinear: bool,
}

impl std::fmt::Debug for ImageMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ImageMap")
            .field("file", &self.file)
            .field("size", &(self.width, self.height))
            .field("once", &self.once)
            .field("bilinear", &self.bilinear)
            .finish()
    }
}

/// Which number of a pixel `image_pattern` takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageUse {
    /// `use_color` (the default; `use_index` reads the same in POV-Ray 3.7): the grey.
    Colour,
    /// `use_alpha`: the transparency (1 − alpha), or red in an image without alpha.
    Alpha,
}

impl ImageMap {
    /// POV-Ray's planar `map_pos`: the pixel coordinates (x right, y down, in [0, width) ×
    /// [0, height)) of pattern point `q`, whose unit square of the x-y plane holds the image
    /// (row 0 at y = 1), tiled unless `once`; `None` off a `once` image.
    pub fn pixel_coords(&self, q: DVec3) -> Option<(f64, f64)> {
        const EDGE: f64 = 1e-10;
        if self.once && !((0.0..=1.0).contains(&q.x) && (0.0..=1.0).contains(&q.y)) {
            return None;
        }
        let (w, h) = (self.width as f64, self.height as f64);
        let mut u = (q.x * w) % w + EDGE;
        if u < 0.0 {
            u += w;
        }
        let mut y = h - ((q.y * h) % h + EDGE);
        if y < 0.0 {
            y += h;
        } else if y >= h {
            y -= h;
        }
        Some((u, y))
    }

    /// The pixel value at pixel coordinates `(u, y)`: the nearest pixel, or the bilinear blend
    /// of the four around (tiling, or clamped at the edges of a `once` image).
    pub fn texel(&self, u: f64, y: f64) -> [f32; 4] {
        let (iw, ih) = (self.width as i64, self.height as i64);
        let at = |x: i64, y: i64| {
            let (x, y) = if self.once {
                (x.clamp(0, iw - 1), y.clamp(0, ih - 1))
            } else {
                (x.rem_euclid(iw), y.rem_euclid(ih))
            };
            self.pixels[y as usize * self.width as usize + x as usize]
        };
        if self.bilinear {
            // Pixel centres at integer + ½: blend pixel i−1 and i with the fraction of u + ½.
            let (x, yy) = (u + 0.5, y + 0.5);
            let (i, j) = (x.floor() as i64, yy.floor() as i64);
            let (p, r) = ((x - x.floor()) as f32, (yy - yy.floor()) as f32);
            let mix = |a: [f32; 4], b: [f32; 4], t: f32| {
                std::array::from_fn::<f32, 4, _>(|k| a[k] + (b[k] - a[k]) * t)
            };
            let top = mix(at(i - 1, j - 1), at(i, j - 1), p);
            let bottom = mix(at(i - 1, j), at(i, j), p);
            mix(top, bottom, r)
        } else {
            at(
                (u.floor() as i64).min(iw - 1),
                (y.floor() as i64).min(ih - 1),
            )
        }
    }

    /// The pixel at pattern point `q`, `None` off a `once` image.
    pub fn at(&self, q: DVec3) -> Option<[f32; 4]> {
        self.pixel_coords(q).map(|(u, y)| self.texel(u, y))
    }

    /// `image_pattern`: the grey (or the transparency) of the pixel at `q`, in [0, 1]; 0 off
    /// a `once` image.
    pub fn value(&self, q: DVec3, use_: ImageUse) -> f64 {
        let Some(px) = self.at(q) else {
            return 0.0;
        };
        let v = match use_ {
            ImageUse::Alpha if self.has_alpha => px[3],
            ImageUse::Alpha => px[0],
            ImageUse::Colour => grey(px),
        };
        f64::from(v).clamp(0.0, 1.0)
    }

    /// `bump_map`: the unit normal `n` (pattern space) tilted by the slope of the image's
    /// grey, `amount` times, from three pixels (POV-Ray's bump_map); `n` off a `once` image.
    pub fn bump(&self, q: DVec3, amount: f64, n: DVec3) -> DVec3 {
        let Some((mut x, mut y)) = self.pixel_coords(q) else {
            return n;
        };
        let (w, h) = (self.width as f64, self.height as f64);
        // The height at pixel coordinates: the palette index (use_index, no interpolation),
        // else the grey.
        let height = |x: f64, y: f64| match &self.indices {
            Some(indices) if !self.bilinear => {
                let (iw, ih) = (self.width as usize, self.height as usize);
                let (i, j) = ((x as usize).min(iw - 1), (y as usize).min(ih - 1));
                f64::from(indices[j * iw + i])
            }
            _ => f64::from(grey(self.texel(x, y))),
        };
        let g1 = height(x, y);
        x -= 1.0;
        y += 1.0;
        let wrap = |v: f64, size: f64| {
            if v < 0.0 {
                v + size
            } else if v >= size {
                v - size
            } else {
                v
            }
        };
        (x, y) = (wrap(x, w), wrap(y, h));
        let g2 = height(x, y);
        x = wrap(x + 2.0, w);
        let g3 = height(x, y);
        let p1 = DVec3::new(0.0, amount * g1, 0.0);
        let p2 = DVec3::new(-1.0, amount * g2, 1.0);
        let p3 = DVec3::new(1.0, amount * g3, 1.0);
        let bump = (p3 - p2).cross(p1 - p2).normalize();
        // A frame around the normal: y along it, x across it and the world's y.
        let (mut xp, mut yp) = (n.cross(DVec3::Y), n);
        let mut length = xp.length();
        if length < 1e-10 {
            yp = if (n.y - 1.0).abs() < 1e-10 {
                DVec3::Y
            } else {
                DVec3::NEG_Y
            };
            xp = DVec3::X;
            length = 1.0;
        }
        xp /= length;
        let zp = xp.cross(yp).normalize();
        xp * bump.x + yp * bump.y - zp * bump.z
    }
}

/// POV-Ray's grey of a pixel.
fn grey(px: [f32; 4]) -> f32 {
    GREY[0] * px[0] + GREY[1] * px[1] + GREY[2] * px[2]
}
