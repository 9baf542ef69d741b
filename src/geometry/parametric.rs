//! `parametric`: the surface `(fx(u, v), fy(u, v), fz(u, v))` over a rectangle of (u, v),
//! inside a container (POV-Ray's Parametric): the (u, v) rectangle is split in halves, longer
//! side first, while the box each function's values may span (bounded with `max_gradient`)
//! still meets the ray; a piece smaller than `accuracy` that does is a hit at its nearest
//! distance. One hit per ray; no inside.

use super::isosurface::Container;
use super::{Crossings, Ray};
use crate::func::Function;
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// POV-Ray's tiny value and the cap of its sector numbers.
const EPSILON: f64 = 1e-10;
const MAX_SECTOR: u32 = 10_000_000;
/// The deepest split kept on the stack (POV-Ray's holds 32; deeper pieces are taken whole).
const STACK: usize = 64;
/// Most pieces one ray examines: a (u, v) rectangle whose functions' bounds never part from
/// the ray is halved into a full binary tree, 2^64 pieces for a range 10^20 times the
/// accuracy (a fuzzed scene; POV-Ray's search would take as long). The examples need at most
/// 5 491 (measured, examples/parametric.rt at 640x480 supersampled); past this the ray keeps
/// the nearest hit found so far.
const MAX_PIECES: u32 = 1 << 16;

/// A function's values at a piece's four corners (see `Parametric::corners`).
type Corners = [f64; 4];

/// Bounds of the functions' values over the pieces of a fixed split (`precompute`).
#[derive(Clone, Debug, PartialEq)]
struct Precomputed {
    /// Which of x, y, z are precomputed.
    axes: [bool; 3],
    /// 2^depth.
    count: u32,
    low: [Vec<f64>; 3],
    high: [Vec<f64>; 3],
}

/// A parametric surface in object space.
#[derive(Clone, Debug, PartialEq)]
pub struct Parametric {
    functions: [Arc<Function>; 3],
    generator: u8,
    container: Container,
    uv_min: DVec2,
    uv_max: DVec2,
    accuracy: f64,
    max_gradient: f64,
    precomputed: Option<Precomputed>,
}

impl Parametric {
    /// The surface of `functions` (of u, v) over `[uv_min, uv_max]` in `container`; with
    /// `precompute` (depth, which of x, y, z), POV-Ray's table of bounds.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        functions: [Arc<Function>; 3],
        generator: u8,
        container: Container,
        uv_min: DVec2,
        uv_max: DVec2,
        accuracy: f64,
        max_gradient: f64,
        precompute: Option<(u32, [bool; 3])>,
    ) -> Parametric {
        let mut p = Parametric {
            functions,
            generator,
            container,
            uv_min,
            uv_max,
            accuracy,
            max_gradient,
            precomputed: None,
        };
        if let Some((depth, axes)) = precompute {
            let count = 1u32 << depth.clamp(1, 20);
            let mut table = Precomputed {
                axes,
                count,
                low: [
                    vec![0.0; count as usize],
                    vec![0.0; count as usize],
                    vec![0.0; count as usize],
                ],
                high: [
                    vec![0.0; count as usize],
                    vec![0.0; count as usize],
                    vec![0.0; count as usize],
                ],
            };
            p.precompute(&mut table, 1, count / 2, uv_min, uv_max);
            p.precomputed = Some(table);
        }
        p
    }

    fn value(&self, axis: usize, uv: DVec2) -> f64 {
        let f = &self.functions[axis];
        let mut args = [0.0; 3];
        args[0] = uv.x;
        args[1] = uv.y;
        f.eval(&args[..f.params.clamp(2, 3)], self.generator)
    }

    /// One function's values, less the accuracy (POV-Ray passes it as a threshold), at a
    /// (u, v) piece's corners: `(low.x, low.y)`, `(low.x, high.y)`, `(high.x, low.y)`,
    /// `(high.x, high.y)`.
    fn corners(&self, axis: usize, low: DVec2, high: DVec2) -> Corners {
        let f = |u, v| self.corner(axis, u, v);
        [
            f(low.x, low.y),
            f(low.x, high.y),
            f(high.x, low.y),
            f(high.x, high.y),
        ]
    }

    /// One function's value at a corner (u, v), less the accuracy.
    fn corner(&self, axis: usize, u: f64, v: f64) -> f64 {
        self.value(axis, DVec2::new(u, v)) - self.accuracy
    }

    /// POV-Ray's bound of one function over a (u, v) piece: from its corners' values, widened
    /// by what `max_gradient` allows.
    fn bound(&self, [f00, f01, f10, f11]: Corners, low: DVec2, high: DVec2) -> (f64, f64) {
        let g = self.max_gradient;
        let widen = |dx: f64, a: f64, b: f64| {
            let ofs = (g * (dx - (a - b).abs() / g) / 2.0).max(0.0);
            (a.min(b) - ofs, a.max(b) + ofs)
        };
        let dv = high.y - low.y;
        let (min0, max0) = widen(dv, f00, f01);
        let (min1, max1) = widen(dv, f10, f11);
        let du = high.x - low.x;
        (widen(du, min0, min1).0, widen(du, max0, max1).1)
    }

    /// The two halves' corners of a piece split at `mid` along `split` (0: u, 1: v), from the
    /// piece's corners and the function's values at the two new corners: (lower half, upper
    /// half).
    fn halves(
        &self,
        axis: usize,
        c: Corners,
        split: usize,
        lo: DVec2,
        hi: DVec2,
        mid: f64,
    ) -> (Corners, Corners) {
        let f = |u, v| self.corner(axis, u, v);
        if split == 0 {
            let (m0, m1) = (f(mid, lo.y), f(mid, hi.y));
            ([c[0], c[1], m0, m1], [m0, m1, c[2], c[3]])
        } else {
            let (m0, m1) = (f(lo.x, mid), f(hi.x, mid));
            ([c[0], m0, c[2], m1], [m0, c[1], m1, c[3]])
        }
    }

    fn precompute(&self, table: &mut Precomputed, sector: u32, last: u32, low: DVec2, high: DVec2) {
        let s = sector as usize;
        if sector >= last {
            for axis in 0..3 {
                if table.axes[axis] {
                    let (lo, hi) = self.bound(self.corners(axis, low, high), low, high);
                    table.low[axis][s] = lo;
                    table.high[axis][s] = hi;
                }
            }
            return;
        }
        if high.x - low.x < high.y - low.y {
            let mid = (low.y + high.y) / 2.0;
            self.precompute(table, 2 * sector, last, low, DVec2::new(high.x, mid));
            self.precompute(table, 2 * sector + 1, last, DVec2::new(low.x, mid), high);
        } else {
            let mid = (low.x + high.x) / 2.0;
            self.precompute(table, 2 * sector, last, low, DVec2::new(mid, high.y));
            self.precompute(table, 2 * sector + 1, last, DVec2::new(mid, low.y), high);
        }
        for axis in 0..3 {
            if table.axes[axis] {
                table.high[axis][s] = table.high[axis][2 * s].max(table.high[axis][2 * s + 1]);
                table.low[axis][s] = table.low[axis][2 * s].min(table.low[axis][2 * s + 1]);
            }
        }
    }

    /// The hit (distance and the (u, v) of its piece), POV-Ray's All_Intersections.
    fn hit(&self, ray: &Ray) -> Option<(f64, DVec2)> {
        let (mut depth1, depth2, _, _) = self.container.span(ray)?;
        let (p, d) = (ray.origin, ray.direction);
        if depth1 == depth2 {
            depth1 = 0.0;
        }
        depth1 += 4.0 * self.accuracy;
        if depth1 > depth2 {
            return None;
        }
        let mut low = [DVec2::ZERO; STACK];
        let mut high = [DVec2::ZERO; STACK];
        let mut sector = [0u32; STACK];
        // Each piece's corner values, per function, where bit `axis` of `known` is set: a
        // half shares two corners with its piece, so a split evaluates two new ones.
        let mut corners = [[[0.0; 4]; 3]; STACK];
        let mut known = [0u8; STACK];
        low[0] = self.uv_min;
        high[0] = self.uv_max;
        sector[0] = 1;
        let table = self.precomputed.as_ref();
        let precomputed = |axis: usize| table.filter(|t| t.axes[axis]).map_or(0, |t| t.count);
        let max_pre = [precomputed(0), precomputed(1), precomputed(2)];
        let mut best: Option<(f64, DVec2)> = None;
        let mut i: isize = 0;
        let mut examined = 0u32;
        'pieces: while i >= 0 && examined < MAX_PIECES {
            examined += 1;
            let k = i as usize;
            let (lo, hi) = (low[k], high[k]);
            let (mut len, mut split) = (hi.x - lo.x, 0);
            if hi.y - lo.y > len {
                len = hi.y - lo.y;
                split = 1;
            }
            let mut ranges: [Option<(f64, f64)>; 3] = [None; 3];
            let mut tlen: f64 = 0.0;
            let mut potential = f64::INFINITY;
            for axis in 0..3 {
                let s = sector[k];
                let use_table = s < max_pre[axis] && (axis < 2 || s > 0);
                let (a, b) = match table {
                    Some(t) if use_table => (t.low[axis][s as usize], t.high[axis][s as usize]),
                    _ => {
                        if known[k] & (1 << axis) == 0 {
                            corners[k][axis] = self.corners(axis, lo, hi);
                            known[k] |= 1 << axis;
                        }
                        self.bound(corners[k][axis], lo, hi)
                    }
                };
                if d[axis].abs() < EPSILON {
                    if b < p[axis] || a > p[axis] {
                        i -= 1;
                        continue 'pieces;
                    }
                    continue;
                }
                let (t1, t2) = {
                    let (x, y) = ((b - p[axis]) / d[axis], (a - p[axis]) / d[axis]);
                    (x.min(y), x.max(y))
                };
                if t1 > depth2 || t2 < depth1 {
                    i -= 1;
                    continue 'pieces;
                }
                potential = t1;
                if best.is_some_and(|(t, _)| potential > t) {
                    i -= 1;
                    continue 'pieces;
                }
                for other in ranges.iter().flatten() {
                    if t1 > other.1 || t2 < other.0 {
                        i -= 1;
                        continue 'pieces;
                    }
                }
                ranges[axis] = Some((t1, t2));
                tlen = tlen.max(t2 - t1);
            }
            if len > tlen {
                len = tlen;
            }
            if len < self.accuracy || k + 1 >= STACK {
                if best.is_none_or(|(t, _)| t > potential) && potential > depth1 {
                    best = Some((potential, lo));
                }
                i -= 1;
            } else {
                sector[k] = (sector[k] * 2).min(MAX_SECTOR);
                sector[k + 1] = sector[k];
                sector[k] += 1;
                low[k + 1] = lo;
                high[k + 1] = hi;
                let mid = (hi[split] + lo[split]) / 2.0;
                high[k + 1][split] = mid;
                low[k][split] = mid;
                known[k + 1] = known[k];
                let (piece, rest) = corners[k..].split_at_mut(1);
                for (axis, (upper, lower)) in piece[0].iter_mut().zip(&mut rest[0]).enumerate() {
                    if known[k] & (1 << axis) != 0 {
                        (*lower, *upper) = self.halves(axis, *upper, split, lo, hi, mid);
                    }
                }
                i += 1;
            }
        }
        best.filter(|&(t, _)| t < depth2)
    }

    /// The (u, v) of a hit kept in a crossing's part: 16 bits each across the rectangle.
    fn encode(&self, uv: DVec2) -> u32 {
        let q = ((uv - self.uv_min) / (self.uv_max - self.uv_min)).clamp(DVec2::ZERO, DVec2::ONE)
            * 65535.0;
        ((q.x.round() as u32) << 16) | q.y.round() as u32
    }

    fn decode(&self, part: u32) -> DVec2 {
        let q = DVec2::new(f64::from(part >> 16), f64::from(part & 0xffff)) / 65535.0;
        self.uv_min + q * (self.uv_max - self.uv_min)
    }
}

impl super::shape::Surface for Parametric {
    const NAME: &'static str = "Parametric";

    fn intersect(&self, ray: &Ray) -> Crossings {
        let mut c = Crossings::NONE;
        if let Some((t, uv)) = self.hit(ray) {
            if ray.contains(t) {
                c.push(t, self.encode(uv));
            }
        }
        c
    }

    /// Every crossing: the search finds the nearest, so the walk searches again from each.
    fn for_each_crossing(&self, ray: &Ray, f: impl FnMut(f64, u32)) {
        super::shape::walk(ray, f, |from, give| {
            let c = self.intersect(from);
            for (&t, &part) in c.as_slice().iter().zip(c.parts()) {
                give(t, part);
            }
        });
    }

    /// POV-Ray's normal: the cross product of the forward differences along u and v (step
    /// `accuracy`) at the hit's (u, v).
    fn normals(&self, _: DVec3, part: u32) -> (DVec3, DVec3) {
        let uv = self.decode(part);
        let at = |q: DVec2| DVec3::new(self.value(0, q), self.value(1, q), self.value(2, q));
        let here = at(uv);
        let du = at(uv + DVec2::new(self.accuracy, 0.0)) - here;
        let dv = at(uv + DVec2::new(0.0, self.accuracy)) - here;
        let n = du.cross(dv);
        (n, n)
    }

    /// POV-Ray's parametric uv: the (u, v) of the hit, in the parameters' own range.
    fn uv(&self, _: DVec3, part: u32) -> Option<DVec2> {
        Some(self.decode(part))
    }

    /// POV-Ray's parametric has no inside.
    fn contains(&self, _: DVec3) -> bool {
        false
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        Some(self.container.bounds())
    }
}

#[cfg(test)]
mod tests {
    use super::super::shape::Surface;
    use super::*;
    use crate::func::Op;

    /// The plane z = 0 over the unit square: hit where the ray crosses it, within the
    /// accuracy, normal along z.
    #[test]
    fn flat_square() {
        let f = |code: Vec<Op>| Arc::new(Function::new(3, code).unwrap());
        let p = Parametric::new(
            [
                f(vec![Op::Arg(0)]),
                f(vec![Op::Arg(1)]),
                f(vec![Op::Const(0.0)]),
            ],
            2,
            Container::Box(DVec3::splat(-2.0), DVec3::splat(2.0)),
            DVec2::ZERO,
            DVec2::ONE,
            0.001,
            1.1,
            None,
        );
        let ray = Ray::new(DVec3::new(0.3, 0.6, -5.0), DVec3::Z);
        let (t, part) = p.intersect(&ray).first_part().expect("hit");
        assert!((t - 5.0).abs() < 0.01, "{t}");
        let n = p.normals(ray.at(t), part).0.normalize();
        assert!(n.z.abs() > 0.999, "{n}");
        assert!(
            p.intersect(&Ray::new(DVec3::new(1.3, 0.6, -5.0), DVec3::Z))
                .is_empty()
        );
    }

    /// A split's halves carry their corners' values: the two kept from the piece and the two
    /// evaluated at the split equal the values evaluated afresh at the halves' corners, for
    /// both directions of split (the search reads only carried values).
    #[test]
    fn halves_carry_their_corners() {
        use crate::func::Math1;
        let f = |code: Vec<Op>| Arc::new(Function::new(3, code).unwrap());
        // x = sin(3u) + v², y = u·v, z = cos(u − 2v)
        let p = Parametric::new(
            [
                f(vec![
                    Op::Arg(0),
                    Op::Const(3.0),
                    Op::Mul,
                    Op::Math1(Math1::Sin),
                    Op::Arg(1),
                    Op::Arg(1),
                    Op::Mul,
                    Op::Add,
                ]),
                f(vec![Op::Arg(0), Op::Arg(1), Op::Mul]),
                f(vec![
                    Op::Arg(0),
                    Op::Arg(1),
                    Op::Const(2.0),
                    Op::Mul,
                    Op::Sub,
                    Op::Math1(Math1::Cos),
                ]),
            ],
            2,
            Container::Box(DVec3::splat(-2.0), DVec3::splat(2.0)),
            DVec2::ZERO,
            DVec2::ONE,
            0.01,
            3.0,
            None,
        );
        let pieces = [
            (DVec2::new(0.0, 0.0), DVec2::new(1.0, 1.0)),
            (DVec2::new(0.25, 0.5), DVec2::new(0.375, 0.5625)),
            (DVec2::new(-1.5, 0.1), DVec2::new(0.7, 2.3)),
        ];
        for (lo, hi) in pieces {
            for axis in 0..3 {
                let c = p.corners(axis, lo, hi);
                for split in 0..2 {
                    let mid = (lo[split] + hi[split]) / 2.0;
                    let (lower, upper) = p.halves(axis, c, split, lo, hi, mid);
                    let mut lower_hi = hi;
                    lower_hi[split] = mid;
                    let mut upper_lo = lo;
                    upper_lo[split] = mid;
                    assert_eq!(lower, p.corners(axis, lo, lower_hi), "{axis} {split}");
                    assert_eq!(upper, p.corners(axis, upper_lo, hi), "{axis} {split}");
                }
            }
        }
    }
}
