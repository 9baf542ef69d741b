//! Images as patterns: POV-Ray's image mappings (`map_pos`) and pixel lookup, shared by
//! `image_map` (colours), `image_pattern` (a value) and `bump_map` (a normal).

use glam::DVec3;
use std::sync::Arc;

/// POV-Ray's weights for the grey of a colour (`Colour::greyscale`).
const GREY: [f32; 3] = [0.297, 0.589, 0.114];

/// How an image wraps around pattern space (`map_type`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapType {
    /// `map_type 0`: the unit square of the x-y plane, repeated.
    Planar,
    /// `map_type 1`: around the origin, longitude from +x towards +z, latitude by y.
    Spherical,
    /// `map_type 2`: around the y axis, one image per unit of height.
    Cylindrical,
    /// `map_type 5`: around a torus of major radius 1 about the y axis.
    Torus,
}

/// How pixels are blended between their centres (`interpolate`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    /// No blending (0): the pixel the point falls in.
    Nearest,
    /// `interpolate 2`: bilinear, between the four nearest pixels.
    Bilinear,
    /// `interpolate 3`: bicubic (Catmull-Rom weights) over the sixteen nearest pixels.
    Bicubic,
    /// `interpolate 4`: the four nearest pixels weighted by their inverse squared distance.
    NormalizedDistance,
}

/// A decoded image.
#[derive(Clone, PartialEq)]
pub struct ImageMap {
    /// The file as named in the scene.
    pub file: String,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Pixels, top row first: rgb, filter and transmit (1 − alpha, plus the image_map's
    /// `filter`/`transmit` settings). For `image_map` the rgb is linear (working gamma); for
    /// `image_pattern` and `bump_map` it is the file's values, as POV-Ray reads them there.
    /// Shared by every use of the same file with the same settings.
    pub texels: Arc<Texels>,
    /// For `bump_map … use_index` on a palette image: each pixel's palette index, the height
    /// POV-Ray takes then (without interpolation).
    pub indices: Option<Vec<u8>>,
    /// Whether the file has an alpha channel (`use_alpha` reads red otherwise).
    pub has_alpha: bool,
    /// `once`: no tiling; outside the mapped area the image is absent.
    pub once: bool,
    /// `map_type`.
    pub map_type: MapType,
    /// `interpolate`.
    pub interpolation: Interpolation,
}

impl std::fmt::Debug for ImageMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ImageMap")
            .field("file", &self.file)
            .field("size", &(self.width, self.height))
            .field("once", &self.once)
            .field("map_type", &self.map_type)
            .field("interpolation", &self.interpolation)
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

/// POV-Ray's margin added to image coordinates before the lookup.
const EDGE: f64 = 1e-10;

/// `v` wrapped into [0, size) (a value that lands on `size` by rounding becomes 0).
fn wrap(v: f64, size: f64) -> f64 {
    let mut w = v % size;
    if w < 0.0 {
        w += size;
    }
    if w >= size { 0.0 } else { w }
}

/// The angle of (x, z) around the y axis, from +x towards +z, in [0, 2π).
fn longitude(x: f64, z: f64, len: f64) -> f64 {
    if z == 0.0 {
        if x > 0.0 { 0.0 } else { std::f64::consts::PI }
    } else {
        let theta = (x / len).acos();
        if z < 0.0 {
            std::f64::consts::TAU - theta
        } else {
            theta
        }
    }
}

/// An image's pixels as its patterns read them (rgb, filter, transmit), stored at the file's
/// own precision: an 8- or 16-bit file keeps its codes (4 or 8 bytes a pixel) with the value
/// each code stands for, worked out once; other files keep the values (20 bytes a pixel).
pub struct Texels(Store);

impl std::fmt::Debug for Texels {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let store = match &self.0 {
            Store::Bytes(_) => "8-bit codes",
            Store::Words(_) => "16-bit codes",
            Store::Values(_) => "values",
        };
        write!(f, "Texels({} pixels, {store})", self.len())
    }
}

impl PartialEq for Texels {
    /// The same pixel values (bit for bit), however stored.
    fn eq(&self, other: &Texels) -> bool {
        std::ptr::eq(self, other)
            || self.len() == other.len()
                && (0..self.len())
                    .all(|i| self.get(i).map(f32::to_bits) == other.get(i).map(f32::to_bits))
    }
}

enum Store {
    /// 8-bit red, green, blue and alpha codes.
    Bytes(Codes<u8>),
    /// 16-bit codes.
    Words(Codes<u16>),
    /// The values themselves.
    Values(Vec<[f32; 5]>),
}

/// Codes with what they stand for: a colour code's value (the same table for red, green and
/// blue), an alpha code's transmit, and the one filter of every pixel.
struct Codes<T> {
    codes: Vec<[T; 4]>,
    colour: Box<[f32]>,
    transmit: Box<[f32]>,
    filter: f32,
}

impl<T: Copy + Into<usize>> Codes<T> {
    #[inline]
    fn get(&self, i: usize) -> [f32; 5] {
        let [r, g, b, a] = self.codes[i].map(Into::into);
        [
            self.colour[r],
            self.colour[g],
            self.colour[b],
            self.filter,
            self.transmit[a],
        ]
    }
}

impl Texels {
    /// Texels holding `values` as they are.
    pub fn values(values: Vec<[f32; 5]>) -> Texels {
        Texels(Store::Values(values))
    }

    /// The texels of `pixels` (rgba, each channel `code / max` for a file of `bits` bits a
    /// channel) whose colours are `colour(channel)`, transmit `transmit(alpha)` and filter
    /// `filter`; `None` unless every channel of every pixel is exactly such a code, 8 or 16
    /// bits (the caller then keeps the values).
    pub fn coded(
        pixels: &[[f32; 4]],
        bits: u32,
        colour: impl Fn(f32) -> f32,
        transmit: impl Fn(f32) -> f32,
        filter: f32,
    ) -> Option<Texels> {
        fn codes<T: Copy + TryFrom<u32>>(pixels: &[[f32; 4]], max: u32) -> Option<Vec<[T; 4]>> {
            let scale = max as f32;
            let mut out = Vec::with_capacity(pixels.len());
            for p in pixels {
                let mut px = [None; 4];
                for (c, &v) in px.iter_mut().zip(p) {
                    let k = (v * scale).round();
                    if !(0.0..=scale).contains(&k) || k as u32 as f32 / scale != v {
                        return None;
                    }
                    *c = T::try_from(k as u32).ok();
                }
                out.push([px[0]?, px[1]?, px[2]?, px[3]?]);
            }
            Some(out)
        }
        let table = |max: u32, f: &dyn Fn(f32) -> f32| -> Box<[f32]> {
            (0..=max).map(|k| f(k as f32 / max as f32)).collect()
        };
        Some(Texels(match bits {
            8 => Store::Bytes(Codes {
                codes: codes::<u8>(pixels, 255)?,
                colour: table(255, &colour),
                transmit: table(255, &transmit),
                filter,
            }),
            16 => Store::Words(Codes {
                codes: codes::<u16>(pixels, 65535)?,
                colour: table(65535, &colour),
                transmit: table(65535, &transmit),
                filter,
            }),
            _ => return None,
        }))
    }

    /// Pixel `i` (top row first).
    #[inline]
    pub fn get(&self, i: usize) -> [f32; 5] {
        match &self.0 {
            Store::Bytes(codes) => codes.get(i),
            Store::Words(codes) => codes.get(i),
            Store::Values(values) => values[i],
        }
    }

    /// How many pixels.
    pub fn len(&self) -> usize {
        match &self.0 {
            Store::Bytes(c) => c.codes.len(),
            Store::Words(c) => c.codes.len(),
            Store::Values(v) => v.len(),
        }
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The bytes they take.
    pub fn bytes(&self) -> usize {
        match &self.0 {
            Store::Bytes(c) => c.codes.len() * 4 + (c.colour.len() + c.transmit.len()) * 4,
            Store::Words(c) => c.codes.len() * 8 + (c.colour.len() + c.transmit.len()) * 4,
            Store::Values(v) => v.len() * 20,
        }
    }
}

impl ImageMap {
    /// The image coordinates (x right, y up, in pixels, before wrapping) of pattern point
    /// `q` by the map type; `None` where the mapping has no point (off a `once` band, or at
    /// the centre of a sphere).
    fn map(&self, q: DVec3) -> Option<(f64, f64)> {
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let outside = |t: f64| self.once && !(0.0..=1.0).contains(&t);
        match self.map_type {
            MapType::Planar => {
                if outside(q.x) || outside(q.y) {
                    return None;
                }
                Some(((q.x * w) % w, (q.y * h) % h))
            }
            MapType::Spherical => {
                let len = q.length();
                if len == 0.0 {
                    return None;
                }
                let d = q / len;
                let phi = 0.5 + d.y.asin() / std::f64::consts::PI;
                let flat = (d.x * d.x + d.z * d.z).sqrt();
                let theta = if flat == 0.0 {
                    0.0
                } else {
                    longitude(d.x, d.z, flat) / std::f64::consts::TAU
                };
                Some((theta * w, phi * h))
            }
            MapType::Cylindrical => {
                if outside(q.y) {
                    return None;
                }
                let v = (q.y * h) % h;
                let len = q.length();
                if len == 0.0 {
                    return None;
                }
                let (x, z) = (q.x / len, q.z / len);
                let flat = (x * x + z * z).sqrt();
                if flat == 0.0 {
                    return None;
                }
                Some((longitude(x, z, flat) / std::f64::consts::TAU * w, v))
            }
            MapType::Torus => {
                let len = (q.x * q.x + q.z * q.z).sqrt();
                if len == 0.0 {
                    return None;
                }
                let theta = -longitude(q.x, q.z, len);
                let x = len - 1.0;
                let tube = (x * x + q.y * q.y).sqrt();
                let mut phi = (-x / tube).acos();
                if q.y > 0.0 {
                    phi = std::f64::consts::TAU - phi;
                }
                let (theta, phi) = (theta / std::f64::consts::TAU, phi / std::f64::consts::TAU);
                Some((-theta * w, phi * h))
            }
        }
    }

    /// POV-Ray's `map_pos`: the pixel coordinates (x right, y down, in [0, width) ×
    /// [0, height)) of pattern point `q`; `None` off a `once` image or where the mapping has
    /// no point.
    pub fn pixel_coords(&self, q: DVec3) -> Option<(f64, f64)> {
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let (u, v) = self.map(q)?;
        let (u, v) = (u + EDGE, v + EDGE);
        if self.once && (u >= w || v >= h || u < 0.0 || v < 0.0) {
            return None;
        }
        Some((wrap(u, w), wrap(-v, h)))
    }

    /// The pixel holding pixel coordinates (x, y): wrapped around the image, or clamped to
    /// the edge of a `once` image.
    fn pixel(&self, x: f64, y: f64) -> [f32; 5] {
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        let index = |v: f64, size: f64, n: u32| {
            if self.once {
                if v < 0.0 {
                    0
                } else if v >= size {
                    n as usize - 1
                } else {
                    v as usize
                }
            } else {
                wrap(v, size) as usize
            }
        };
        let (i, j) = (index(x, w, self.width), index(y, h, self.height));
        self.texels.get(j * self.width as usize + i)
    }

    /// The pixel value at pixel coordinates `(u, y)`, blended as `interpolate` says.
    pub fn texel(&self, u: f64, y: f64) -> [f32; 5] {
        if self.interpolation == Interpolation::Nearest {
            return self.pixel(u, y);
        }
        // Pixel centres at integer + ½.
        let (x, yy) = (u + 0.5, y + 0.5);
        let (i, j) = (x.trunc(), yy.trunc());
        let (p, q) = (x - i, yy - j);
        let mut sum = [0.0f64; 5];
        let mut add = |px: [f32; 5], weight: f64| {
            for (s, c) in sum.iter_mut().zip(px) {
                *s += f64::from(c) * weight;
            }
        };
        match self.interpolation {
            Interpolation::Bicubic => {
                let (fx, fy) = (cubic_weights(p), cubic_weights(q));
                for (a, wx) in fx.iter().enumerate() {
                    for (b, wy) in fy.iter().enumerate() {
                        add(self.pixel(i + a as f64 - 2.0, j + b as f64 - 2.0), wx * wy);
                    }
                }
            }
            _ => {
                let weights = if self.interpolation == Interpolation::Bilinear {
                    [p * q, (1.0 - p) * q, p * (1.0 - q), (1.0 - p) * (1.0 - q)]
                } else {
                    let inverse = |a: f64, b: f64| 1.0 / (a * a + b * b);
                    let raw = [
                        inverse(1.0 - p, 1.0 - q),
                        inverse(p, 1.0 - q),
                        inverse(1.0 - p, q),
                        inverse(p, q),
                    ];
                    let total: f64 = raw.iter().sum();
                    raw.map(|r| r / total)
                };
                add(self.pixel(i, j), weights[0]);
                add(self.pixel(i - 1.0, j), weights[1]);
                add(self.pixel(i, j - 1.0), weights[2]);
                add(self.pixel(i - 1.0, j - 1.0), weights[3]);
            }
        }
        sum.map(|s| s as f32)
    }

    /// `material_map`: the texture number at pattern point `q`: the pixel's palette index,
    /// else its red × 255 (truncated); 0 off a `once` image.
    pub fn material(&self, q: DVec3) -> f64 {
        let Some((u, y)) = self.pixel_coords(q) else {
            return 0.0;
        };
        match &self.indices {
            Some(indices) => {
                let (w, h) = (self.width as usize, self.height as usize);
                let (i, j) = ((u as usize).min(w - 1), (y as usize).min(h - 1));
                f64::from(indices[j * w + i])
            }
            None => f64::from((self.texel(u, y)[0] * 255.0) as i32),
        }
    }

    /// The pixel at pattern point `q`, `None` off a `once` image.
    pub fn at(&self, q: DVec3) -> Option<[f32; 5]> {
        self.pixel_coords(q).map(|(u, y)| self.texel(u, y))
    }

    /// `image_pattern`: the grey (or the transparency) of the pixel at `q`, in [0, 1]; 0 off
    /// a `once` image.
    pub fn value(&self, q: DVec3, use_: ImageUse) -> f64 {
        let Some(px) = self.at(q) else {
            return 0.0;
        };
        let v = match use_ {
            ImageUse::Alpha if self.has_alpha => px[4],
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
            Some(indices) if self.interpolation == Interpolation::Nearest => {
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
fn grey(px: [f32; 5]) -> f32 {
    GREY[0] * px[0] + GREY[1] * px[1] + GREY[2] * px[2]
}

/// POV-Ray's bicubic weights of the four pixels around fraction `p` (Catmull-Rom).
fn cubic_weights(p: f64) -> [f64; 4] {
    let q = 1.0 - p;
    [
        -0.5 * p * q * q,
        0.5 * q * (q * (3.0 * p + 1.0) + 1.0),
        0.5 * p * (p * (3.0 * q + 1.0) + 1.0),
        -0.5 * q * p * p,
    ]
}
