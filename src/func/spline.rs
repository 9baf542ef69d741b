//! `spline { … }`: vectors of 2 to 5 values interpolated along a parameter, as POV-Ray 3.7
//! interpolates them (its `linear_spline`, `quadratic_spline`, `cubic_spline` (Catmull-Rom)
//! and `natural_spline`), with its rules at the ends: before the first and after the last
//! entry the end values (the second and last-but-one for `cubic_spline`, which cannot reach
//! further), one entry everywhere, two averaged for `cubic_spline`.

use super::Native;

/// How a spline interpolates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplineKind {
    /// `linear_spline` (the default): straight between entries.
    Linear,
    /// `quadratic_spline`: the parabola through an entry and its two neighbours.
    Quadratic,
    /// `cubic_spline`: Catmull-Rom, with tangents averaged from the neighbouring slopes.
    Cubic,
    /// `natural_spline`: the cubic with continuous second derivatives, zero at the ends.
    Natural,
}

impl SplineKind {
    /// The kind a keyword names.
    pub fn named(word: &str) -> Option<SplineKind> {
        Some(match word {
            "linear_spline" => SplineKind::Linear,
            "quadratic_spline" => SplineKind::Quadratic,
            "cubic_spline" => SplineKind::Cubic,
            "natural_spline" => SplineKind::Natural,
            _ => return None,
        })
    }
}

/// A spline: entries sorted by parameter (one per parameter value).
#[derive(Clone, Debug, PartialEq)]
pub struct Spline {
    kind: SplineKind,
    /// (parameter, values), by increasing parameter.
    entries: Vec<(f64, [f64; 5])>,
    /// How many values the spline gives (the most any entry was given, at least 2).
    pub terms: usize,
    /// `natural_spline`'s second derivatives at the entries (empty for the other kinds).
    second: Vec<[f64; 5]>,
}

impl Spline {
    /// An empty spline of `kind`.
    pub fn new(kind: SplineKind) -> Spline {
        Spline {
            kind,
            entries: Vec::new(),
            terms: 2,
            second: Vec::new(),
        }
    }

    /// Its kind.
    pub fn kind(&self) -> SplineKind {
        self.kind
    }

    /// How many entries it has.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Whether it has no entry.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The same entries interpolated as `kind`.
    pub fn with_kind(&self, kind: SplineKind) -> Spline {
        let mut s = self.clone();
        s.kind = kind;
        s.prepare();
        s
    }

    /// Adds an entry of `terms` values at `par` (an entry already at `par` is replaced, as in
    /// POV-Ray).
    pub fn insert(&mut self, par: f64, values: [f64; 5], terms: usize) {
        self.extend([(par, values, terms)]);
    }

    /// Adds entries (parameter, values, how many values), in order, as [`Spline::insert`]
    /// does, preparing the spline once at the end (a natural spline's coefficients cost a
    /// pass over all entries).
    pub fn extend(&mut self, entries: impl IntoIterator<Item = (f64, [f64; 5], usize)>) {
        for (par, values, terms) in entries {
            self.terms = self.terms.max(terms);
            let i = self.entries.partition_point(|(p, _)| *p < par);
            match self.entries.get_mut(i) {
                Some(e) if e.0 == par => e.1 = values,
                _ => self.entries.insert(i, (par, values)),
            }
        }
        self.prepare();
    }

    /// Precomputes what the kind needs (natural splines' second derivatives).
    // (The component index k runs over every entry's five values.)
    #[allow(clippy::needless_range_loop)]
    fn prepare(&mut self) {
        self.second.clear();
        let n = self.entries.len();
        if self.kind != SplineKind::Natural || n < 2 {
            return;
        }
        let e = &self.entries;
        let mut second = vec![[0.0; 5]; n];
        let h: Vec<f64> = (0..n - 1).map(|i| e[i + 1].0 - e[i].0).collect();
        for k in 0..5 {
            let b: Vec<f64> = (0..n - 1)
                .map(|i| (e[i + 1].1[k] - e[i].1[k]) / h[i])
                .collect();
            // The tridiagonal system of the inner entries, eliminated forwards …
            let (mut u, mut v) = (vec![0.0; n], vec![0.0; n]);
            if n > 2 {
                u[1] = 2.0 * (h[0] + h[1]);
                v[1] = 6.0 * (b[1] - b[0]);
                for i in 2..n - 1 {
                    u[i] = 2.0 * (h[i] + h[i - 1]) - h[i - 1] * h[i - 1] / u[i - 1];
                    v[i] = 6.0 * (b[i] - b[i - 1]) - h[i - 1] * v[i - 1] / u[i - 1];
                }
            }
            // … and solved backwards; zero at both ends.
            for i in (1..n - 1).rev() {
                second[i][k] = (v[i] - h[i] * second[i + 1][k]) / u[i];
            }
        }
        self.second = second;
    }

    /// The index of the first entry whose parameter is at least `t` (0 before the first, the
    /// entry count from the last on), as POV-Ray's `findt`.
    fn find(&self, t: f64) -> usize {
        let e = &self.entries;
        let n = e.len();
        if n == 0 || t <= e[0].0 {
            return 0;
        }
        if t >= e[n - 1].0 {
            return n;
        }
        e.partition_point(|(p, _)| *p < t)
    }

    /// The values at parameter `t` (those past [`Spline::terms`] meaningless).
    pub fn at(&self, t: f64) -> [f64; 5] {
        let e = &self.entries;
        let Some(last) = e.len().checked_sub(1) else {
            return [0.0; 5];
        };
        if last == 0 {
            return e[0].1;
        }
        let i = self.find(t);
        let mut v = [0.0; 5];
        for (k, out) in v.iter_mut().enumerate() {
            *out = match self.kind {
                SplineKind::Cubic => {
                    if last == 1 {
                        (e[0].1[k] + e[1].1[k]) / 2.0
                    } else if i < 2 {
                        e[1].1[k]
                    } else if i >= last {
                        e[last - 1].1[k]
                    } else {
                        self.catmull_rom(i - 1, k, t)
                    }
                }
                _ if i == 0 => e[0].1[k],
                _ if i > last => e[last].1[k],
                SplineKind::Linear => self.linear(i - 1, k, t),
                SplineKind::Quadratic if last == 1 => self.linear(i - 1, k, t),
                SplineKind::Quadratic => self.quadratic(if i > 1 { i - 1 } else { i }, k, t),
                SplineKind::Natural => self.natural(i - 1, k, t),
            };
        }
        v
    }

    fn linear(&self, i: usize, k: usize, t: f64) -> f64 {
        let ((p1, v1), (p2, v2)) = (self.entries[i], self.entries[i + 1]);
        (t - p1) * (v2[k] - v1[k]) / (p2 - p1) + v1[k]
    }

    /// The parabola through entries i − 1, i and i + 1, in POV-Ray's expanded form.
    fn quadratic(&self, i: usize, k: usize, t: f64) -> f64 {
        let e = &self.entries;
        let (p1, p2, p3) = (e[i - 1].0, e[i].0, e[i + 1].0);
        let (v1, v2, v3) = (e[i - 1].1[k], e[i].1[k], e[i + 1].1[k]);
        let n = (p2 - p1) * (p3 - p1) * (p3 - p2);
        let a = (-p2 * v1 + p3 * v1 + p1 * v2 - p3 * v2 - p1 * v3 + p2 * v3) / n;
        let b = (p2 * p2 * v1 - p3 * p3 * v1 - p1 * p1 * v2 + p3 * p3 * v2 + p1 * p1 * v3
            - p2 * p2 * v3)
            / n;
        let c = (-p2 * p2 * p3 * v1 + p2 * p3 * p3 * v1 + p1 * p1 * p3 * v2
            - p1 * p3 * p3 * v2
            - p1 * p1 * p2 * v3
            + p1 * p2 * p2 * v3)
            / n;
        (a * t + b) * t + c
    }

    fn natural(&self, i: usize, k: usize, t: f64) -> f64 {
        let e = &self.entries;
        let (c0, c1) = (self.second[i][k], self.second[i + 1][k]);
        let h = e[i + 1].0 - e[i].0;
        let d = t - e[i].0;
        let tmp = c0 / 2.0 + d * (c1 - c0) / (6.0 * h);
        let tmp = -(h / 6.0) * (c1 + 2.0 * c0) + (e[i + 1].1[k] - e[i].1[k]) / h + d * tmp;
        e[i].1[k] + d * tmp
    }

    /// Catmull-Rom between entries i and i + 1, tangents from the neighbours' slopes.
    fn catmull_rom(&self, i: usize, k: usize, t: f64) -> f64 {
        let e = &self.entries;
        let slope = |a: usize| (e[a + 1].1[k] - e[a].1[k]) / (e[a + 1].0 - e[a].0);
        let dt = e[i + 1].0 - e[i].0;
        let u = (t - e[i].0) / dt;
        let dp0 = (slope(i - 1) + slope(i)) / 2.0 * dt;
        let dp1 = (slope(i + 1) + slope(i)) / 2.0 * dt;
        let (u2, u3) = (u * u, u * u * u);
        e[i].1[k] * (2.0 * u3 - 3.0 * u2 + 1.0)
            + e[i + 1].1[k] * (3.0 * u2 - 2.0 * u3)
            + dp0 * (u3 - 2.0 * u2 + u)
            + dp1 * (u3 - u2)
    }
}

/// `function { spline { … } }`: the spline as a function of its parameter.
impl Native for Spline {
    fn params(&self) -> usize {
        1
    }

    fn size(&self) -> usize {
        self.terms
    }

    fn eval(&self, args: &[f64], _generator: u8) -> [f64; 5] {
        self.at(args[0])
    }

    fn same(&self, other: &dyn Native) -> bool {
        super::same_data(self, other)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spline(kind: SplineKind, points: &[(f64, f64)]) -> Spline {
        let mut s = Spline::new(kind);
        for (t, v) in points {
            s.insert(*t, [*v, 0.0, 0.0, 0.0, 0.0], 2);
        }
        s
    }

    #[test]
    fn ends_and_entries_follow_povray() {
        let pts = [(0.0, 1.0), (1.0, 3.0), (2.0, 2.0), (3.0, 5.0)];
        for kind in [
            SplineKind::Linear,
            SplineKind::Quadratic,
            SplineKind::Natural,
        ] {
            let s = spline(kind, &pts);
            assert_eq!(s.at(-1.0)[0], 1.0, "{kind:?}");
            assert_eq!(s.at(9.0)[0], 5.0, "{kind:?}");
            for (t, v) in pts {
                assert!((s.at(t)[0] - v).abs() < 1e-12, "{kind:?} at {t}");
            }
        }
        let c = spline(SplineKind::Cubic, &pts);
        // Catmull-Rom stops at the second and last-but-one entries.
        assert_eq!(c.at(0.5)[0], 3.0);
        assert_eq!(c.at(2.5)[0], 2.0);
        assert!((c.at(1.5)[0] - 2.4375).abs() < 1e-12);
        assert_eq!(spline(SplineKind::Linear, &pts).at(0.25)[0], 1.5);
    }

    #[test]
    fn an_entry_at_the_same_parameter_replaces_the_earlier() {
        let s = spline(SplineKind::Linear, &[(1.0, 2.0), (0.0, 0.0), (1.0, 4.0)]);
        assert_eq!(s.len(), 2);
        assert_eq!(s.at(0.5)[0], 2.0);
    }
}
