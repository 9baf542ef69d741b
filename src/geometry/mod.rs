//! Rays and the analytic shapes: intersection in object space, normals, inside tests.
//!
//! Material-agnostic and IR-agnostic: shapes here are plain geometry. All arithmetic is `f64`,
//! so that a scene moved far from the origin keeps the precision of one at the origin.
//!
//! Each shape has two phases: `intersect` computes only the distances; `normal` runs once, for
//! the winning hit.

pub mod bezier;
mod blob;
mod cone;
pub mod counters;
mod cuboid;
mod disc;
mod height_field;
mod isosurface;
mod julia;
mod lathe;
pub mod mesh;
mod ovus;
mod parametric;
mod plane;
pub mod poly;
mod polygon;
mod polynomial;
mod prism;
mod quadric;
pub mod shape;
mod sor;
mod sphere;
mod sphere_sweep;
mod spline;
mod superellipsoid;
mod text;
mod torus;
pub mod triangle;
pub(crate) mod wide;

pub use blob::{Blob, BlobElement};
pub use cone::Cone;
pub use cuboid::Cuboid;
pub use disc::Disc;
pub use height_field::HeightField;
pub use isosurface::{Container, Isosurface};
pub use julia::JuliaFractal;
pub use lathe::Lathe;
pub use mesh::TriangleMesh;
pub use ovus::Ovus;
pub use parametric::Parametric;
pub use plane::Plane;
pub use polygon::Polygon;
pub use polynomial::Polynomial;
pub use prism::Prism;
pub use quadric::Quadric;
pub use shape::{Shape, Surface};
pub use sor::{Sor, SorPiece};
pub use sphere::Sphere;
pub use sphere_sweep::{SphereSweep, SweepCurve};
pub use spline::CurveSegment;
pub use superellipsoid::Superellipsoid;
pub use text::{Edge, Text};
pub use torus::Torus;

use glam::{DMat4, DVec3};

/// A ray `origin + t·direction` for `t` in `(tmin, tmax)`. The direction need not be unit
/// length (rays moved into object space keep their `t`).
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    /// Start point.
    pub origin: DVec3,
    /// Direction (not necessarily normalised).
    pub direction: DVec3,
    /// Hits at or below this distance are ignored.
    pub tmin: f64,
    /// Hits at or beyond this distance are ignored.
    pub tmax: f64,
}

impl Ray {
    /// A ray over `(0, ∞)`.
    pub fn new(origin: DVec3, direction: DVec3) -> Ray {
        debug_assert!(
            origin.is_finite() && direction.is_finite(),
            "ray must be finite"
        );
        Ray {
            origin,
            direction,
            tmin: 0.0,
            tmax: f64::INFINITY,
        }
    }

    /// The point at distance `t`.
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + t * self.direction
    }

    /// The same ray in the space that `m` maps into (direction not renormalised, so `t` is kept).
    pub fn transformed(&self, m: &DMat4) -> Ray {
        Ray {
            origin: m.transform_point3(self.origin),
            direction: m.transform_vector3(self.direction),
            tmin: self.tmin,
            tmax: self.tmax,
        }
    }

    /// Whether `t` lies in the ray's open interval.
    pub fn contains(&self, t: f64) -> bool {
        self.tmin < t && t < self.tmax
    }
}

/// Up to four crossings of a ray with a surface, nearest first.
///
/// Each crossing carries a `part` tag that the shape's `normal` uses to tell which of its
/// surfaces was hit (a cone's side or caps, a mesh's triangle); 0 where a shape has one surface.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Crossings {
    ts: [f64; 4],
    parts: [u32; 4],
    len: usize,
}

impl Crossings {
    /// No crossing.
    pub const NONE: Crossings = Crossings {
        ts: [0.0; 4],
        parts: [0; 4],
        len: 0,
    };

    /// Keeps the candidates (given nearest first) that lie within the ray's interval.
    pub fn within(ray: &Ray, candidates: &[f64]) -> Crossings {
        let mut c = Crossings::NONE;
        for &t in candidates {
            if ray.contains(t) {
                c.push(t, 0);
            }
        }
        c
    }

    /// Adds a crossing (callers add them in increasing `t`, or call [`Crossings::sort`]).
    pub fn push(&mut self, t: f64, part: u32) {
        if self.len < 4 {
            self.ts[self.len] = t;
            self.parts[self.len] = part;
            self.len += 1;
        }
    }

    /// Adds a crossing given in any order, keeping the nearest four sorted.
    pub fn keep_nearest(&mut self, t: f64, part: u32) {
        let mut i = self.len;
        if i == 4 {
            if t >= self.ts[3] {
                return;
            }
            i = 3;
        } else {
            self.len += 1;
        }
        while i > 0 && self.ts[i - 1] > t {
            self.ts[i] = self.ts[i - 1];
            self.parts[i] = self.parts[i - 1];
            i -= 1;
        }
        self.ts[i] = t;
        self.parts[i] = part;
    }

    /// The nearest crossing of a shape that reports its crossings in increasing distance to
    /// `walk`'s callback (which stops the walk by returning false).
    pub fn first_of(walk: impl FnOnce(&mut dyn FnMut(f64) -> bool)) -> Crossings {
        let mut out = Crossings::NONE;
        walk(&mut |t| {
            out.push(t, 0);
            false
        });
        out
    }

    /// The nearest four crossings of a shape that reports them in any order to `walk`'s
    /// callback.
    pub fn nearest_of(walk: impl FnOnce(&mut dyn FnMut(f64, u32))) -> Crossings {
        let mut out = Crossings::NONE;
        walk(&mut |t, part| out.keep_nearest(t, part));
        out
    }

    /// Sorts the crossings by distance.
    pub fn sort(&mut self) {
        for i in 1..self.len {
            let mut j = i;
            while j > 0 && self.ts[j - 1] > self.ts[j] {
                self.ts.swap(j - 1, j);
                self.parts.swap(j - 1, j);
                j -= 1;
            }
        }
    }

    /// The distances, nearest first.
    pub fn as_slice(&self) -> &[f64] {
        &self.ts[..self.len]
    }

    /// The part tags, in the order of [`Crossings::as_slice`].
    pub fn parts(&self) -> &[u32] {
        &self.parts[..self.len]
    }

    /// The nearest crossing.
    pub fn first(&self) -> Option<f64> {
        self.as_slice().first().copied()
    }

    /// The nearest crossing with its part tag.
    pub fn first_part(&self) -> Option<(f64, u32)> {
        (self.len > 0).then(|| (self.ts[0], self.parts[0]))
    }

    /// Number of crossings.
    #[cfg(any(test, feature = "internals"))]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there is no crossing.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
}

/// A ray as a line of unit speed measured from the point nearest a shape's centre, so that a
/// far origin costs the shape's equations no precision (the stability suite's S11).
#[derive(Clone, Copy, Debug)]
pub struct UnitLine {
    /// The line's point nearest the centre.
    pub origin: DVec3,
    /// Unit direction.
    pub direction: DVec3,
    /// That point's distance from the ray's origin, along the unit direction.
    pub shift: f64,
    /// The ray direction's length.
    pub length: f64,
}

impl UnitLine {
    /// The ray parameter of the point `k` along the line from its origin.
    pub fn t(&self, k: f64) -> f64 {
        (k + self.shift) / self.length
    }
}

impl Ray {
    /// This ray as a [`UnitLine`] about `centre`.
    pub fn about(&self, centre: DVec3) -> UnitLine {
        let length = self.direction.length();
        let direction = self.direction / length;
        let shift = (centre - self.origin).dot(direction);
        UnitLine {
            origin: self.origin + shift * direction,
            direction,
            shift,
            length,
        }
    }
}

/// POV-Ray's longitude of (x, z) for surface coordinates: the angle from +x towards +z as a
/// fraction of a turn, 0 to 1; 0 where x² + z² ≤ 1e-10 (at a pole any value would do).
pub fn longitude(x: f64, z: f64) -> f64 {
    let flat = x * x + z * z;
    if flat <= 1e-10 {
        return 0.0;
    }
    let flat = flat.sqrt();
    let theta = if z == 0.0 {
        if x > 0.0 { 0.0 } else { std::f64::consts::PI }
    } else {
        let a = (x / flat).acos();
        if z < 0.0 {
            std::f64::consts::TAU - a
        } else {
            a
        }
    };
    theta / std::f64::consts::TAU
}

/// Secondary-ray origin for a ray leaving the surface at `p` (geometric normal `ng`, either
/// side) in direction `dir`: `p` pushed off the surface, to the side `dir` goes, by a distance
/// proportional to the magnitude of the coordinates involved.
///
/// Rounding error in a computed hit point is a few ulps of the largest coordinate in the
/// computation (the ray origin or the point), so a relative offset of 2⁻⁴⁰ (≈ 4096 ulps in
/// `f64`) clears it at any distance from the origin while staying far below any object size
/// trace supports (see README, "Numerical range").
pub fn offset_origin(p: DVec3, ng: DVec3, dir: DVec3, scale: f64) -> DVec3 {
    const RELATIVE_OFFSET: f64 = 1.0 / (1u64 << 40) as f64;
    const ABSOLUTE_FLOOR: f64 = 1e-12;
    let magnitude = p.abs().max_element().max(scale);
    let offset = (magnitude * RELATIVE_OFFSET).max(ABSOLUTE_FLOOR);
    let side = if ng.dot(dir) < 0.0 { -ng } else { ng };
    p + side * offset
}
