//! Exact orientation and in-circle tests on a mix of input samples and circumcenters of
//! input triangles, for the crust baseline, which inserts Voronoi vertices into the
//! triangulation of the samples.
//!
//! Every point is known in three forms: a centre in `f64` with a proven radius (a sample
//! exactly; a circumcenter as [`circumcenter`](super::circumcenter::circumcenter) rounds it,
//! within 256 units in the last place of its larger coordinate), a bounded one in homogeneous coordinates `(X, Y, W)`, `W = 1`
//! (coordinates with running error bounds, tighter and exact where the operations were),
//! and an exact one in integers, `W > 0`, computed on first need and kept. Each predicate is
//! decided in three stages: the semi-static filter of [`filter`] on the centres and radii
//! (the plain polynomials `poly::orient_terms_points` and `poly::incircle_terms_points`),
//! then the running-error filter (`bounded`) and exact evaluation of one polynomial in
//! homogeneous coordinates (`poly::orient_homogeneous`, `poly::incircle_homogeneous`). No
//! division and no gcd is ever needed.

use std::sync::OnceLock;

use num_bigint::{BigInt, Sign as BigSign};

use super::arith::Arith;
use super::basic::{incircle, orient};
use super::bounded::{ulp, Bounded};
use super::circumcenter::{circumcenter_bounded, circumcenter_homogeneous, point_homogeneous};
use super::exact::{integer_sign, ratio_to_f64};
use super::poly::{incircle_homogeneous, orient_homogeneous};
use super::Sign;

pub(super) mod filter;

use self::filter::Sr;

/// The samples of a triangulation together with its Voronoi vertices, addressed by one index
/// space: `i < n` is sample `i` (the caller's index), `n + v` is Voronoi vertex `v`.
pub(crate) struct MixedPoints<'a> {
    samples: &'a [[f64; 2]],
    /// Defining triangle of every Voronoi vertex (its circumcenter is the vertex).
    triangles: Vec<[[f64; 2]; 3]>,
    /// Every point (samples first, then Voronoi vertices) as `[x, y, r]`: each coordinate
    /// within `r` of the exact one (`r = 0` for a sample; a rounded circumcenter).
    centres: Vec<[f64; 3]>,
    /// Exact points (samples first, then Voronoi vertices), computed when first needed.
    exact: Vec<OnceLock<Box<[BigInt; 3]>>>,
}

impl<'a> MixedPoints<'a> {
    /// Samples `samples` and Voronoi vertices that are the circumcenters of `triangles`
    /// (each non-collinear).
    #[cfg(test)]
    pub(crate) fn new(samples: &'a [[f64; 2]], triangles: Vec<[[f64; 2]; 3]>) -> Self {
        let centres: Vec<[f64; 2]> = triangles
            .iter()
            .map(|&[a, b, c]| super::circumcenter::circumcenter(a, b, c).unwrap_or([f64::NAN; 2]))
            .collect();
        Self::with_centres(samples, triangles, &centres)
    }

    /// Samples `samples` and Voronoi vertices that are the circumcenters of `triangles`,
    /// rounded by the caller: `centres[v]` must be [`super::circumcenter::circumcenter`] of
    /// three points on the circle of `triangles[v]` (so within 256 units in the last place
    /// of its larger coordinate of the exact circumcenter), as the positions of
    /// [`crate::voronoi::Voronoi`] are.
    pub(crate) fn with_centres(
        samples: &'a [[f64; 2]],
        triangles: Vec<[[f64; 2]; 3]>,
        centres: &[[f64; 2]],
    ) -> Self {
        let n = samples.len();
        let exact: Vec<OnceLock<Box<[BigInt; 3]>>> =
            (0..n + triangles.len()).map(|_| OnceLock::new()).collect();
        // 256 units in the last place of the larger coordinate magnitude `N` (`ulp(0)` is the
        // smallest subnormal); an infinite centre has a NaN radius, which never certifies.
        let centres = samples
            .iter()
            .map(|&[x, y]| [x, y, 0.0])
            .chain(
                centres
                    .iter()
                    .map(|&[x, y]| [x, y, 256.0 * ulp(x.abs().max(y.abs()))]),
            )
            .collect();
        MixedPoints {
            samples,
            triangles,
            centres,
            exact,
        }
    }

    /// Is `i` a sample?
    pub(crate) fn is_sample(&self, i: u32) -> bool {
        (i as usize) < self.samples.len()
    }

    /// Point `i` for the first filter: its centre and radius.
    #[inline(always)]
    fn filter_point(&self, i: u32) -> [Sr; 2] {
        let [x, y, r] = self.centres[i as usize];
        [Sr::input(x, r), Sr::input(y, r)]
    }

    /// Point `i` with bounded coordinates, `W = 1`: for a circumcenter, the running-error
    /// one if it is tight, else the correctly rounded exact one.
    #[cold]
    fn bounded(&self, i: u32) -> [Bounded; 3] {
        let [x, y] = match self.samples.get(i as usize) {
            Some(&p) => p.map(Bounded::from_f64),
            None => {
                let t = self.triangles[i as usize - self.samples.len()];
                circumcenter_bounded(t).unwrap_or_else(|| {
                    // Within half an ulp (and an underflow to zero within the smallest
                    // subnormal).
                    rounded(self.exact(i)).map(|v| Bounded { v, e: ulp(v) })
                })
            }
        };
        [x, y, Bounded::from_f64(1.0)]
    }

    /// The exact point `i`.
    fn exact(&self, i: u32) -> &[BigInt; 3] {
        let i = i as usize;
        self.exact[i].get_or_init(|| {
            Box::new(match self.samples.get(i) {
                Some(&p) => point_homogeneous(p),
                None => {
                    let t = self.triangles[i - self.samples.len()];
                    circumcenter_homogeneous(t).unwrap_or_else(|| point_homogeneous(t[0]))
                }
            })
        })
    }

    /// The exact coordinates of point `i`.
    #[cfg(test)]
    pub(crate) fn exact_rational(&self, i: u32) -> [num_rational::BigRational; 2] {
        let [x, y, w] = self.exact(i);
        [
            num_rational::BigRational::new(x.clone(), w.clone()),
            num_rational::BigRational::new(y.clone(), w.clone()),
        ]
    }

    /// Exact orientation of `a → b → c` (`Positive`: counterclockwise).
    pub(crate) fn orient(&self, a: u32, b: u32, c: u32) -> Sign {
        if self.is_sample(a) && self.is_sample(b) && self.is_sample(c) {
            let s = self.samples;
            return orient(s[a as usize], s[b as usize], s[c as usize]);
        }
        // Written out rather than with `array::map`, which is not always inlined.
        let (pa, pb, pc) = (
            self.filter_point(a),
            self.filter_point(b),
            self.filter_point(c),
        );
        if let Some(sign) = filter::orient(&pa, &pb, &pc) {
            return sign;
        }
        self.orient_slow(a, b, c)
    }

    /// [`Self::orient`] after the first filter failed.
    #[cold]
    #[inline(never)]
    fn orient_slow(&self, a: u32, b: u32, c: u32) -> Sign {
        let [pa, pb, pc] = [a, b, c].map(|i| self.bounded(i));
        orient_homogeneous(&pa, &pb, &pc).sign().unwrap_or_else(|| {
            let [ea, eb, ec] = [a, b, c].map(|i| self.exact(i));
            integer_sign(&orient_homogeneous(ea, eb, ec))
        })
    }

    /// Exact position of `d` relative to the circle through the counterclockwise `a, b, c`
    /// (`Positive`: inside).
    pub(crate) fn incircle(&self, a: u32, b: u32, c: u32, d: u32) -> Sign {
        if self.is_sample(a) && self.is_sample(b) && self.is_sample(c) && self.is_sample(d) {
            let s = self.samples;
            return incircle(s[a as usize], s[b as usize], s[c as usize], s[d as usize]);
        }
        let (pa, pb, pc, pd) = (
            self.filter_point(a),
            self.filter_point(b),
            self.filter_point(c),
            self.filter_point(d),
        );
        if let Some(sign) = filter::incircle(&pa, &pb, &pc, &pd) {
            return sign;
        }
        self.incircle_slow(a, b, c, d)
    }

    /// [`Self::incircle`] after the first filter failed.
    #[cold]
    #[inline(never)]
    fn incircle_slow(&self, a: u32, b: u32, c: u32, d: u32) -> Sign {
        let [pa, pb, pc, pd] = [a, b, c, d].map(|i| self.bounded(i));
        incircle_homogeneous(&pa, &pb, &pc, &pd)
            .sign()
            .unwrap_or_else(|| {
                let [ea, eb, ec, ed] = [a, b, c, d].map(|i| self.exact(i));
                integer_sign(&incircle_homogeneous(ea, eb, ec, ed))
            })
    }
}

/// `(X/W, Y/W)` correctly rounded.
fn rounded(h: &[BigInt; 3]) -> [f64; 2] {
    let [x, y, w] = h;
    [x, y].map(|n| ratio_to_f64(n.sign() == BigSign::Minus, n.magnitude(), w.magnitude(), 0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;

    fn rational(x: f64) -> BigRational {
        BigRational::from_float(x).unwrap_or_default()
    }

    #[test]
    fn grid_circumcenters_are_exact() {
        let t = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
        let [x, y] = circumcenter_bounded(t).unwrap();
        assert_eq!((x.v, x.e, y.v, y.e), (1.0, 0.0, 1.0, 0.0));
        let samples = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, -1.0]];
        // Point 5: the centre (1, 1) of the square.
        let mp = MixedPoints::new(&samples, vec![[samples[0], samples[1], samples[3]]]);
        assert_eq!(mp.incircle(0, 1, 2, 5), Sign::Positive);
        assert_eq!(mp.orient(0, 2, 5), Sign::Zero);
        // (0,0), (1,-1), (2,0) and the centre (1,1) are cocircular (circle about (1,0)).
        assert_eq!(mp.incircle(0, 4, 1, 5), Sign::Zero);
        assert_eq!(mp.incircle(0, 4, 5, 3), Sign::Negative);
    }

    #[test]
    fn exact_path_decides_what_bounds_cannot() {
        // Scaled by 1/3 (not dyadic): the same cocircular and collinear configurations as in
        // the grid test, now only decidable exactly.
        let k = 1.0 / 3.0;
        let t = [[0.0, 0.0], [6.0 * k, 0.0], [0.0, 6.0 * k]];
        let samples = [t[0], t[1], [6.0 * k, 6.0 * k], t[2], [3.0 * k, -3.0 * k]];
        let mp = MixedPoints::new(&samples, vec![t]);
        let [ex, ey] = mp.exact_rational(5);
        let d2 = |i: usize| {
            let (x, y) = (rational(samples[i][0]), rational(samples[i][1]));
            (&x - &ex) * (&x - &ex) + (&y - &ey) * (&y - &ey)
        };
        assert_eq!(d2(0), d2(1));
        assert_eq!(d2(1), d2(3));
        assert_eq!(mp.incircle(0, 1, 2, 5), Sign::Positive);
        // Both answers agree with a direct rational evaluation (W = 1).
        let point = |i: u32| {
            let [x, y] = mp.exact_rational(i);
            [x, y, BigRational::from_integer(1.into())]
        };
        for (a, b, c, d) in [(0, 4, 1, 5), (0, 4, 5, 3), (4, 1, 5, 2), (0, 1, 5, 2)] {
            let [pa, pb, pc, pd] = [a, b, c, d].map(point);
            let value = incircle_homogeneous(&pa, &pb, &pc, &pd);
            let orientation = orient_homogeneous(&pa, &pb, &pc);
            let expected = value.sign().unwrap().times(orientation.sign().unwrap());
            // `incircle` wants a counterclockwise triangle.
            let got = match mp.orient(a, b, c) {
                Sign::Negative => mp.incircle(a, c, b, d),
                _ => mp.incircle(a, b, c, d),
            };
            assert_eq!(got, expected, "{a} {b} {c} {d}");
        }
        for (a, b, c) in [(0, 2, 5), (1, 3, 5), (4, 5, 0), (4, 5, 2)] {
            let [pa, pb, pc] = [a, b, c].map(point);
            let expected = orient_homogeneous(&pa, &pb, &pc).sign().unwrap();
            assert_eq!(mp.orient(a, b, c), expected, "{a} {b} {c}");
        }
    }
}
