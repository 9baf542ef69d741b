//! Real roots of polynomials of degree ≤ 10 in an interval, by isolation: between consecutive
//! roots of the derivative a polynomial is monotonic, so each such interval holds at most one
//! root, found by safeguarded Newton iteration (a quadratic by its closed form in the way that
//! cancels nothing). No cubic or quartic formula's cancellation, so grazing rays and far
//! origins keep their accuracy.

/// Coefficients, lowest degree first: `c[0] + c[1]·t + … + c[n]·tⁿ` (degree ≤ 6; [`roots_in`]
/// takes any array length, up to degree [`MAX_DEGREE`]).
pub type Poly = [f64; 7];

/// The highest degree [`roots_in`] solves.
pub const MAX_DEGREE: usize = 10;

fn eval<const N: usize>(c: &[f64; N], degree: usize, t: f64) -> f64 {
    let mut v = 0.0;
    for i in (0..=degree).rev() {
        v = v * t + c[i];
    }
    v
}

/// The value of `c` at `t`, and the size of one rounding of its terms (ε times the sum of
/// their sizes): a value within that of zero is as near a root as the arithmetic can tell
/// (Horner's rule's worst case is 2·degree times that; a root refined until then moves by no
/// more than the rounding of the value itself).
fn eval_with_noise<const N: usize>(c: &[f64; N], degree: usize, t: f64) -> (f64, f64) {
    let (mut v, mut size) = (0.0, 0.0);
    let at = t.abs();
    for i in (0..=degree).rev() {
        v = v * t + c[i];
        size = size * at + c[i].abs();
    }
    (v, size * f64::EPSILON)
}

fn derivative<const N: usize>(c: &[f64; N], degree: usize) -> [f64; N] {
    let mut d = [0.0; N];
    for i in 1..=degree {
        d[i - 1] = c[i] * i as f64;
    }
    d
}

/// Up to ten roots in increasing order.
#[derive(Clone, Copy, Debug, Default)]
pub struct Roots {
    /// The roots; the first `len` are valid.
    pub t: [f64; MAX_DEGREE],
    /// How many.
    pub len: usize,
}

impl Roots {
    fn push(&mut self, t: f64) {
        if self.len < MAX_DEGREE {
            self.t[self.len] = t;
            self.len += 1;
        }
    }

    /// The roots found.
    pub fn as_slice(&self) -> &[f64] {
        &self.t[..self.len]
    }
}

/// Real roots of the polynomial `c` (of the given degree) in `[lo, hi]`, increasing.
pub fn roots_in<const N: usize>(c: &[f64; N], degree: usize, lo: f64, hi: f64) -> Roots {
    debug_assert!(degree < N && degree <= MAX_DEGREE);
    let mut out = Roots::default();
    if degree == 0 || lo > hi {
        return out;
    }
    if degree == 1 {
        if c[1] != 0.0 {
            let t = -c[0] / c[1];
            if (lo..=hi).contains(&t) {
                out.push(t);
            }
        }
        return out;
    }
    if c[degree] == 0.0 {
        return roots_in(c, degree - 1, lo, hi);
    }
    if degree == 2 {
        return quadratic_in(c[0], c[1], c[2], lo, hi);
    }
    let d = derivative(c, degree);
    monotonic_pieces(c, &d, degree, (lo, hi), |piece| {
        match piece {
            Piece::At(a) => {
                if out.len == 0 || out.t[out.len - 1] != a {
                    out.push(a);
                }
            }
            Piece::Bracket(a, b, fa, fb) => {
                out.push(refine(c, &d, degree, (a, b), (fa, fb)));
            }
        }
        false
    });
    out
}

/// Real roots of `c0 + c1·t + c2·t²` (c2 ≠ 0) in `[lo, hi]`, increasing: the closed form in
/// the way that cancels nothing (the larger root from `-b ∓ √disc` of the same sign, the other
/// from the product of the roots), each then polished by a Newton step.
fn quadratic_in(c0: f64, c1: f64, c2: f64, lo: f64, hi: f64) -> Roots {
    let mut out = Roots::default();
    let disc = c1 * c1 - 4.0 * c2 * c0;
    if disc < 0.0 {
        return out;
    }
    let q = -0.5 * (c1 + disc.sqrt().copysign(c1));
    let (mut r1, mut r2) = if q == 0.0 {
        (0.0, 0.0)
    } else {
        (q / c2, c0 / q)
    };
    if r1 > r2 {
        std::mem::swap(&mut r1, &mut r2);
    }
    let polish = |t: f64| {
        let slope = 2.0 * c2 * t + c1;
        if slope == 0.0 {
            t
        } else {
            t - ((c2 * t + c1) * t + c0) / slope
        }
    };
    for (i, t) in [r1, r2].into_iter().enumerate() {
        if i == 1 && disc == 0.0 {
            break;
        }
        let t = polish(t);
        if (lo..=hi).contains(&t) && (out.len == 0 || out.t[out.len - 1] < t) {
            out.push(t);
        }
    }
    out
}

/// What [`monotonic_pieces`] meets.
enum Piece {
    /// A root at the end of a piece.
    At(f64),
    /// A piece `[a, b]` whose ends differ in sign (the values at `a` and `b` given).
    Bracket(f64, f64, f64, f64),
}

/// `[lo, hi]` split at the critical points of `c` (degree ≥ 2, `d` its derivative) into
/// pieces where it is monotonic: `visit` sees each root at a piece's end and each piece whose
/// ends differ in sign, in increasing order, until it returns true; whether it did.
fn monotonic_pieces<const N: usize>(
    c: &[f64; N],
    d: &[f64; N],
    degree: usize,
    (lo, hi): (f64, f64),
    mut visit: impl FnMut(Piece) -> bool,
) -> bool {
    let critical = roots_in(d, degree - 1, lo, hi);
    let mut a = lo;
    let mut fa = eval(c, degree, a);
    for &b in critical.as_slice().iter().chain(std::iter::once(&hi)) {
        let fb = eval(c, degree, b);
        let stop = if fa == 0.0 {
            visit(Piece::At(a))
        } else {
            fa.signum() != fb.signum() && fb != 0.0 && visit(Piece::Bracket(a, b, fa, fb))
        };
        if stop {
            return true;
        }
        a = b;
        fa = fb;
    }
    fa == 0.0 && visit(Piece::At(a))
}

/// Whether the polynomial `c` has a real root in `[lo, hi]` that `accept` takes, for shadow
/// rays: the same roots [`roots_in`] finds, but a root whose bracket lies inside `sure` (where
/// every root is taken) is not refined, and the search stops at the first root taken.
pub fn any_root_in<const N: usize>(
    c: &[f64; N],
    degree: usize,
    (lo, hi): (f64, f64),
    sure: (f64, f64),
    accept: impl Fn(f64) -> bool,
) -> bool {
    if degree <= 1 || lo > hi || c[degree] == 0.0 {
        return roots_in(c, degree, lo, hi)
            .as_slice()
            .iter()
            .any(|&t| accept(t));
    }
    let d = derivative(c, degree);
    monotonic_pieces(c, &d, degree, (lo, hi), |piece| match piece {
        Piece::At(a) => accept(a),
        Piece::Bracket(a, b, fa, fb) => {
            (sure.0 < a && b < sure.1) || accept(refine(c, &d, degree, (a, b), (fa, fb)))
        }
    })
}

/// The root in `[a, b]` where `c` changes sign (`fa`, `fb` its values at the ends): Newton
/// steps from where the chord crosses zero, falling back to bisection whenever a step leaves
/// the bracket, until the step or the bracket is a few ulps or the value is within one
/// rounding of its terms of zero (without that, a root near 0, whose ulps are tiny, or at an
/// inflection, where Newton crawls, could take a hundred steps).
fn refine<const N: usize>(
    c: &[f64; N],
    d: &[f64; N],
    degree: usize,
    (mut a, mut b): (f64, f64),
    (fa, fb): (f64, f64),
) -> f64 {
    let rising = fa < 0.0;
    let chord = a - fa * (b - a) / (fb - fa);
    let mut t = if chord > a && chord < b {
        chord
    } else {
        0.5 * (a + b)
    };
    for _ in 0..100 {
        let (f, noise) = eval_with_noise(c, degree, t);
        if f.abs() <= noise {
            // (As near the root as the value can tell.)
            return t;
        }
        if (f < 0.0) == rising {
            a = t;
        } else {
            b = t;
        }
        let slope = eval(d, degree - 1, t);
        let newton = t - f / slope;
        let next = if slope != 0.0 && newton > a && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        if (next - t).abs() <= 4.0 * f64::EPSILON * t.abs().max(1e-300)
            || b - a <= 4.0 * f64::EPSILON * t.abs()
        {
            return next;
        }
        t = next;
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn any_root_in_takes_the_roots_roots_in_finds() {
        // (t-1)(t-2)(t-3)(t-4), and shifted up so that it has two roots or none.
        let four = [24.0, -50.0, 35.0, -10.0, 1.0, 0.0, 0.0];
        for lift in [0.0, 0.5, 0.99, 1.1, 30.0] {
            let mut c = four;
            c[0] += lift;
            for (lo, hi) in [
                (0.0, 10.0),
                (1.5, 2.5),
                (2.2, 2.8),
                (-5.0, 0.5),
                (3.9, 3.95),
            ] {
                let found = roots_in(&c, 4, lo, hi);
                for sure in [(lo, hi), (lo + 0.3, hi - 0.3), (f64::MAX, f64::MIN)] {
                    for cut in [f64::MIN, 2.5, 3.5] {
                        let accept = |t: f64| t > cut;
                        let expected = found.as_slice().iter().any(|&t| accept(t));
                        // (`sure` must lie where every root is accepted.)
                        let sure = if cut > lo {
                            (cut.max(sure.0), sure.1)
                        } else {
                            sure
                        };
                        assert_eq!(
                            any_root_in(&c, 4, (lo, hi), sure, accept),
                            expected,
                            "{lift} {lo} {hi} {sure:?} {cut}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn quartic_with_four_roots() {
        // (t-1)(t-2)(t-3)(t-4) = t⁴ − 10t³ + 35t² − 50t + 24
        let r = roots_in(&[24.0, -50.0, 35.0, -10.0, 1.0, 0.0, 0.0], 4, 0.0, 10.0);
        let expected = [1.0, 2.0, 3.0, 4.0];
        assert_eq!(r.len, 4);
        for (a, b) in r.as_slice().iter().zip(expected) {
            assert!((a - b).abs() < 1e-12, "{:?}", r.as_slice());
        }
    }

    #[test]
    fn roots_outside_interval_are_ignored() {
        let r = roots_in(&[24.0, -50.0, 35.0, -10.0, 1.0, 0.0, 0.0], 4, 1.5, 3.5);
        assert_eq!(r.as_slice().len(), 2);
    }

    #[test]
    fn close_roots_are_separated() {
        // (t − 1)(t − 1.000001)(t² + 1)
        let (a, b) = (1.0, 1.000001);
        let c = [a * b, -(a + b), 1.0 + a * b, -(a + b), 1.0, 0.0, 0.0];
        let r = roots_in(&c, 4, 0.0, 2.0);
        assert_eq!(r.len, 2, "{:?}", r.as_slice());
        assert!((r.t[0] - a).abs() < 1e-9 && (r.t[1] - b).abs() < 1e-9);
    }

    #[test]
    fn quadratics_by_the_closed_form() {
        // Two roots, one far smaller than the other (no cancellation: 1e-9 to 1e-15).
        let r = roots_in(
            &[1e-9, -(1.0 + 1e-18), 1e-9, 0.0, 0.0, 0.0, 0.0],
            2,
            -1e12,
            1e12,
        );
        assert_eq!(r.len, 2, "{:?}", r.as_slice());
        assert!((r.t[0] - 1e-9).abs() < 1e-23 && (r.t[1] - 1e9).abs() < 1e-3);
        // A double root, none, and the interval's filter.
        assert_eq!(
            roots_in(&[1.0, -2.0, 1.0, 0.0, 0.0, 0.0, 0.0], 2, 0.0, 2.0).as_slice(),
            [1.0]
        );
        assert_eq!(
            roots_in(&[1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0], 2, -9.0, 9.0).len,
            0
        );
        assert_eq!(
            roots_in(&[-4.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0], 2, 0.0, 9.0).as_slice(),
            [2.0]
        );
    }

    #[test]
    fn a_root_where_newton_crawls_is_still_found() {
        // (t − 1e-7)³ (t − 2): a triple root near 0, where the step criterion alone, relative
        // to |t|, would not be met before the iteration limit.
        let a = 1e-7;
        let c = [
            2.0 * a * a * a,
            -(a * a * a + 6.0 * a * a),
            6.0 * a + 3.0 * a * a,
            -(3.0 * a + 2.0),
            1.0,
            0.0,
            0.0,
        ];
        let r = roots_in(&c, 4, -1.0, 3.0);
        assert_eq!(r.len, 2, "{:?}", r.as_slice());
        assert!(
            (r.t[0] - a).abs() < 1e-5 && (r.t[1] - 2.0).abs() < 1e-12,
            "{:?}",
            r.as_slice()
        );
    }

    #[test]
    fn sextic_with_six_roots() {
        // (t−1)(t−2)…(t−6), coefficients lowest first.
        let mut c = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        for r in 1..=6 {
            let mut next = [0.0; 7];
            for i in 0..6 {
                next[i + 1] += c[i];
                next[i] -= r as f64 * c[i];
            }
            c = next;
        }
        let roots = roots_in(&c, 6, 0.0, 10.0);
        assert_eq!(roots.len, 6);
        for (i, t) in roots.as_slice().iter().enumerate() {
            assert!((t - (i + 1) as f64).abs() < 1e-9, "{:?}", roots.as_slice());
        }
    }

    /// Degree 10 (the sphere sweep's tube equation): ten roots in [0, 1].
    #[test]
    fn degree_ten() {
        let mut c = [0.0; 11];
        c[0] = 1.0;
        for r in 1..=10 {
            let mut next = [0.0; 11];
            for i in 0..10 {
                next[i + 1] += c[i];
                next[i] -= r as f64 * 0.09 * c[i];
            }
            c = next;
        }
        let roots = roots_in(&c, 10, 0.0, 1.0);
        assert_eq!(roots.len, 10, "{:?}", roots.as_slice());
        for (i, t) in roots.as_slice().iter().enumerate() {
            assert!(
                (t - (i + 1) as f64 * 0.09).abs() < 1e-9,
                "{:?}",
                roots.as_slice()
            );
        }
    }

    #[test]
    fn no_real_roots() {
        let r = roots_in(&[1.0, 0.0, 2.0, 0.0, 1.0, 0.0, 0.0], 4, -10.0, 10.0);
        assert_eq!(r.len, 0);
    }
}
