//! `height_field`: a grid of heights, two triangles a cell (split along the diagonal from
//! (x + 1, z) to (x, z + 1)), in POV-Ray's raw units: x and z count grid points, y runs over
//! the 16-bit heights (the object's transformation scales it to the unit box). POV-Ray's
//! HField: its triangle tolerances, its flat normals, and its smooth normals, which are the
//! quantised vertex normals blended after the object's transformation.

use super::{Crossings, Ray};
use glam::{DMat3, DMat4, DVec3};
use std::sync::Arc;

/// POV-Ray's tolerances for a point on a triangle and for a ray parallel to it.
const TOLERANCE: f64 = 1e-4;
const EPSILON: f64 = 1e-10;

/// A height field in raw units.
#[derive(Clone, Debug, PartialEq)]
pub struct HeightField {
    /// Grid points across (x) and deep (z).
    w: usize,
    d: usize,
    /// Heights, row z = 0 first.
    heights: Arc<Vec<u16>>,
    /// The box's floor (the lowest height or the water level) and top.
    floor: f64,
    top: f64,
    /// Smooth normals: per grid point, the unit normal × 32767 truncated (POV-Ray's storage),
    /// the object's linear map to the world and its normal matrix (they are blended in world
    /// orientation).
    smooth: Option<Smooth>,
}

/// Quantised vertex normals, the object's linear map and its normal matrix.
type Smooth = (Box<[[i16; 3]]>, DMat3, DMat3);

impl HeightField {
    /// A height field of `w × d` points (row z = 0 first); `water`: the water level in raw
    /// units; `smooth`: the object's transformation when normals are smoothed.
    pub fn new(
        w: usize,
        d: usize,
        heights: Arc<Vec<u16>>,
        water: f64,
        smooth: Option<DMat4>,
    ) -> HeightField {
        let (lo, hi) = heights
            .iter()
            .fold((u16::MAX, 0), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        let mut hf = HeightField {
            w,
            d,
            heights,
            floor: f64::from(lo).max(water) - 0.001,
            top: f64::from(hi) + 0.001,
            smooth: None,
        };
        if let Some(m) = smooth {
            let normals = (0..w * d).map(|i| hf.vertex_normal(i % w, i / w)).collect();
            let linear = DMat3::from_mat4(m);
            hf.smooth = Some((normals, linear, linear.inverse().transpose()));
        }
        hf
    }

    fn h(&self, x: usize, z: usize) -> f64 {
        f64::from(self.heights[z * self.w + x])
    }

    /// POV-Ray's smooth normal at a grid point: the sum of the unit normals of the four
    /// triangles around it (in raw units), normalised and stored as 16-bit integers.
    fn vertex_normal(&self, x: usize, z: usize) -> [i16; 3] {
        let v0 = DVec3::new(x as f64, self.h(x, z), z as f64);
        let at = |dx: i64, dz: i64| {
            let (x, z) = (x as i64 + dx, z as i64 + dz);
            (x >= 0 && z >= 0 && (x as usize) < self.w && (z as usize) < self.d)
                .then(|| DVec3::new(x as f64, self.h(x as usize, z as usize), z as f64))
        };
        let (right, up, left, down) = (at(1, 0), at(0, 1), at(-1, 0), at(0, -1));
        let mut sum = DVec3::ZERO;
        for (a, b) in [(right, up), (up, left), (left, down), (down, right)] {
            let (Some(a), Some(b)) = (a, b) else { continue };
            let n = (b - v0).cross(a - v0);
            let len = n.length();
            let mut n = if len <= EPSILON { DVec3::Y } else { n / len };
            if n.y < 0.0 {
                n = -n;
            }
            sum += n;
        }
        let n = sum.normalize_or(DVec3::Y);
        [
            (32767.0 * n.x) as i16,
            (32767.0 * n.y) as i16,
            (32767.0 * n.z) as i16,
        ]
    }

    /// The crossings with cell (x, z)'s two triangles within [lo, hi].
    fn cell(
        &self,
        ray: &Ray,
        x: usize,
        z: usize,
        lo: f64,
        hi: f64,
        f: &mut impl FnMut(f64),
    ) -> bool {
        let (x, z) = (x.min(self.w - 2), z.min(self.d - 2));
        let (y1, y2, y3, y4) = (
            self.h(x, z),
            self.h(x + 1, z),
            self.h(x, z + 1),
            self.h(x + 1, z + 1),
        );
        let (fx, fz) = (x as f64, z as f64);
        let mut found = false;
        let mut triangle = |n: DVec3, p0: DVec3, second: bool| {
            let dot = n.dot(ray.direction);
            if dot.abs() <= EPSILON {
                return;
            }
            let t = n.dot(p0 - ray.origin) / dot;
            if t < lo || t > hi {
                return;
            }
            let p = ray.at(t);
            let (s, u) = (p.x - fx, p.z - fz);
            let inside = if second {
                s <= 1.0 + TOLERANCE && u <= 1.0 + TOLERANCE && s + u >= 1.0 - TOLERANCE
            } else {
                s >= -TOLERANCE && u >= -TOLERANCE && s + u <= 1.0 + TOLERANCE
            };
            if inside {
                found = true;
                f(t);
            }
        };
        triangle(
            DVec3::new(y1 - y2, 1.0, y1 - y3),
            DVec3::new(fx, y1, fz),
            false,
        );
        triangle(
            DVec3::new(y3 - y4, 1.0, y2 - y4),
            DVec3::new(fx + 1.0, y4, fz + 1.0),
            true,
        );
        found
    }

    /// Calls `f` with the crossings, cell by cell along the ray; stops after the first cell
    /// with any when `all` is false.
    fn crossings(&self, ray: &Ray, all: bool, mut f: impl FnMut(f64)) {
        let lo_corner = DVec3::new(0.0, self.floor, 0.0);
        let hi_corner = DVec3::new((self.w - 1) as f64, self.top, (self.d - 1) as f64);
        let (o, d) = (ray.origin, ray.direction);
        // The span of the ray inside the box.
        let inv = d.recip();
        let (a, b) = ((lo_corner - o) * inv, (hi_corner - o) * inv);
        let mut enter = ray.tmin.max(1e-6);
        let mut exit = ray.tmax;
        for i in 0..3 {
            if d[i] == 0.0 {
                if o[i] < lo_corner[i] || o[i] > hi_corner[i] {
                    return;
                }
                continue;
            }
            enter = enter.max(a[i].min(b[i]));
            exit = exit.min(a[i].max(b[i]));
        }
        if enter > exit {
            return;
        }
        let start = ray.at(enter);
        let cell_of = |v: f64, n: usize| (v.max(0.0) as usize).min(n - 2);
        let (mut cx, mut cz) = (cell_of(start.x, self.w), cell_of(start.z, self.d));
        if d.x.abs() < EPSILON && d.z.abs() < EPSILON {
            self.cell(ray, cx, cz, enter, exit, &mut f);
            return;
        }
        // Walk the cells the ray crosses, in order (Amanatides and Woo).
        let step = |dv: f64| if dv > 0.0 { 1i64 } else { -1 };
        let (sx, sz) = (step(d.x), step(d.z));
        let next = |c: usize, s: i64, ov: f64, dv: f64| {
            if dv == 0.0 {
                f64::INFINITY
            } else {
                let edge = if s > 0 { c as f64 + 1.0 } else { c as f64 };
                (edge - ov) / dv
            }
        };
        let (mut tx, mut tz) = (next(cx, sx, o.x, d.x), next(cz, sz, o.z, d.z));
        let (dtx, dtz) = ((1.0 / d.x).abs(), (1.0 / d.z).abs());
        loop {
            if self.cell(ray, cx, cz, enter, exit, &mut f) && !all {
                return;
            }
            let t = tx.min(tz);
            if t > exit {
                return;
            }
            if tx <= tz {
                let n = cx as i64 + sx;
                if n < 0 || n > self.w as i64 - 2 {
                    return;
                }
                cx = n as usize;
                tx += dtx;
            } else {
                let n = cz as i64 + sz;
                if n < 0 || n > self.d as i64 - 2 {
                    return;
                }
                cz = n as usize;
                tz += dtz;
            }
        }
    }

    /// The grid cell of point `p` and the fractions within it.
    fn locate(&self, p: DVec3) -> (usize, usize, f64, f64) {
        let px = (p.x.max(0.0) as usize).min(self.w - 2);
        let pz = (p.z.max(0.0) as usize).min(self.d - 2);
        (px, pz, p.x - px as f64, p.z - pz as f64)
    }
}

impl super::shape::Surface for HeightField {
    const NAME: &'static str = "HeightField";

    fn intersect(&self, ray: &Ray) -> Crossings {
        let mut out = Crossings::NONE;
        self.crossings(ray, false, |t| out.keep_nearest(t, 0));
        out
    }

    fn normals(&self, p: DVec3, _: u32) -> (DVec3, DVec3) {
        let (px, pz, fx, fz) = self.locate(p);
        let flat = if fx + fz <= 1.0 {
            let y1 = self.h(px, pz);
            DVec3::new(y1 - self.h(px + 1, pz), 1.0, y1 - self.h(px, pz + 1))
        } else {
            let y4 = self.h(px + 1, pz + 1);
            DVec3::new(self.h(px, pz + 1) - y4, 1.0, self.h(px + 1, pz) - y4)
        };
        let Some((normals, m, to_world)) = &self.smooth else {
            return (flat, flat);
        };
        // POV-Ray blends the corner normals after carrying each into the world; the renderer
        // carries the result there again, so it is handed back in object terms.
        let corner = |x: usize, z: usize| {
            let [a, b, c] = normals[z * self.w + x];
            (to_world * DVec3::new(a.into(), b.into(), c.into())).normalize_or_zero()
        };
        let n = (1.0 - fz) * ((1.0 - fx) * corner(px, pz) + fx * corner(px + 1, pz))
            + fz * ((1.0 - fx) * corner(px, pz + 1) + fx * corner(px + 1, pz + 1));
        (m.transpose() * n.normalize_or(DVec3::Y), flat)
    }

    /// POV-Ray's test: below the surface of the cell's triangle (or the water level).
    fn contains(&self, p: DVec3) -> bool {
        if p.x < 0.0
            || p.z < 0.0
            || p.x >= (self.w - 1) as f64
            || p.z >= (self.d - 1) as f64
            || p.y >= self.top
        {
            return false;
        }
        if p.y < self.floor {
            return true;
        }
        let (px, pz, fx, fz) = self.locate(p);
        let h = |x, z| self.h(x, z).max(self.floor);
        let (v, n) = if fx + fz < 1.0 {
            let y1 = h(px, pz);
            (
                DVec3::new(px as f64, y1, pz as f64),
                DVec3::new(y1 - h(px + 1, pz), 1.0, y1 - h(px, pz + 1)),
            )
        } else {
            let (x, z) = (
                (p.x.ceil() as usize).min(self.w - 1),
                (p.z.ceil() as usize).min(self.d - 1),
            );
            let y1 = h(x, z);
            (
                DVec3::new(x as f64, y1, z as f64),
                DVec3::new(h(x - 1, z) - y1, 1.0, h(x, z - 1) - y1),
            )
        };
        p.dot(n) < v.dot(n)
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some((
            DVec3::new(0.0, self.floor, 0.0),
            DVec3::new((self.w - 1) as f64, self.top, (self.d - 1) as f64),
        ))
    }

    fn for_each_crossing(&self, ray: &Ray, mut f: impl FnMut(f64, u32)) {
        self.crossings(ray, true, |t| f(t, 0))
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;

    /// A 3 × 3 grid rising along x: heights 0, 100, 200.
    fn ramp() -> HeightField {
        let heights: Vec<u16> = (0..9).map(|i| (i % 3) as u16 * 100).collect();
        HeightField::new(3, 3, Arc::new(heights), 0.0, None)
    }

    #[test]
    fn ramp_hits_and_inside() {
        let hf = ramp();
        // Straight down at x = 0.5: height 50.
        let c = hf.intersect(&Ray::new(DVec3::new(0.5, 1000.0, 0.5), DVec3::NEG_Y));
        assert!(
            (c.first().unwrap() - 950.0).abs() < 1e-9,
            "{:?}",
            c.as_slice()
        );
        // Along x at height 150: meets the ramp at x = 1.5.
        let c = hf.intersect(&Ray::new(DVec3::new(-1.0, 150.0, 1.2), DVec3::X));
        assert!(
            (c.first().unwrap() - 2.5).abs() < 1e-9,
            "{:?}",
            c.as_slice()
        );
        let (n, _) = hf.normals(DVec3::new(1.5, 150.0, 1.2), 0);
        assert!(n.x < 0.0 && n.y > 0.0);
        // Above the top: nothing.
        assert!(
            hf.intersect(&Ray::new(DVec3::new(-1.0, 250.0, 1.2), DVec3::X))
                .is_empty()
        );
        assert!(hf.contains(DVec3::new(1.5, 100.0, 1.2)));
        assert!(!hf.contains(DVec3::new(1.5, 200.0, 1.2)));
        // Water at 120 raises the floor: the low part is not there.
        let wet = HeightField::new(
            3,
            3,
            Arc::new((0..9).map(|i| (i % 3) as u16 * 100).collect()),
            120.0,
            None,
        );
        let c = wet.intersect(&Ray::new(DVec3::new(0.5, 1000.0, 0.5), DVec3::NEG_Y));
        assert!(c.is_empty(), "{:?}", c.as_slice());
    }

    /// Smooth normals are the quantised vertex normals, blended.
    #[test]
    fn smooth_normals() {
        let heights: Vec<u16> = (0..9).map(|i| (i % 3) as u16 * 100).collect();
        let hf = HeightField::new(3, 3, Arc::new(heights), 0.0, Some(DMat4::IDENTITY));
        let (n, g) = hf.normals(DVec3::new(1.0, 100.0, 1.0), 0);
        assert!(n.normalize().dot(g.normalize()) > 0.999, "{n} {g}");
    }
}
