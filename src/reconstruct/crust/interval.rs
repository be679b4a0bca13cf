//! Outward-rounded interval arithmetic, and exact predicates on points that are either input
//! samples (`f64` pairs) or Voronoi vertices (exact rational circumcenters of input triangles).
//!
//! # Why intervals are a proven filter
//!
//! An [`Iv`] `[lo, hi]` stands for a real number known to lie in it. Every operation computes
//! its endpoints with round-to-nearest and then steps each one a unit in the last place
//! outward ([`next_down`] / [`next_up`]). Round-to-nearest is off by at most half a gap between
//! neighbouring floats (also for subnormal and underflowing results), so the stepped endpoint
//! is a true lower / upper bound of the exact endpoint operation; by monotonicity of `+` and
//! of `·` over the four endpoint products, the exact result of the operation on any numbers in
//! the operand intervals lies in the result interval. Overflow gives an infinite endpoint
//! (still a bound) and an undefined operation gives NaN, for which [`Iv::sign`] answers `None`.
//! Hence a sign reported by [`Iv::sign`] is the sign of the exact value.
//!
//! Point intervals (`lo == hi`) whose operation is exact in `f64` stay point intervals: sums
//! are checked with Knuth's TwoSum, products and quotients with a fused multiply-add residual,
//! only where those residuals are proven exact (no overflow, no underflow). This certifies the
//! exact zeros of symmetric inputs (grids, regular polygons) without rational arithmetic.
//!
//! Round-to-nearest returns one of the two floats that bracket the exact result, so the exact
//! result lies between the neighbours of the returned float; that is the whole proof.
//!
//! When the interval cannot decide, the predicate is evaluated exactly: every finite `f64` is
//! a dyadic rational and a circumcenter of three `f64` points is the rational
//! [`circumcenter_exact`]; [`MixedPoints`] turns them into homogeneous integer coordinates
//! once and evaluates integer determinants (the NN-crust's degree-2 tests use
//! [`BigRational`] directly).

use std::cell::OnceCell;
use std::cmp::Ordering;

use num_bigint::{BigInt, Sign as BigSign};
use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::predicates::exact::{circumcenter_exact, ExactPoint};
use crate::predicates::{incircle as incircle_f64, orient2d, CirclePosition, Orientation};

/// Below this magnitude a product's or quotient's rounding residual may underflow, so its
/// exactness is not checked (the interval is widened instead).
const TINY: f64 = 1.0e-270; // about 2^-897

/// The smallest `f64` above `x` (`x` itself for `+∞` and NaN).
pub(crate) fn next_up(x: f64) -> f64 {
    if x.is_nan() || x == f64::INFINITY {
        return x;
    }
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let bits = x.to_bits();
    if x > 0.0 {
        f64::from_bits(bits + 1)
    } else {
        f64::from_bits(bits - 1)
    }
}

/// The largest `f64` below `x` (`x` itself for `−∞` and NaN).
pub(crate) fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// A closed interval of reals with `f64` endpoints; see the module docs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Iv {
    /// Lower bound.
    pub(crate) lo: f64,
    /// Upper bound.
    pub(crate) hi: f64,
}

/// The undecidable interval.
const NAN: Iv = Iv {
    lo: f64::NAN,
    hi: f64::NAN,
};

impl Iv {
    /// The exact value `x` (finite).
    pub(crate) fn point(x: f64) -> Iv {
        Iv { lo: x, hi: x }
    }

    /// `[next_down(x), next_up(x)]`: the interval of a correctly rounded `x`.
    fn around(x: f64) -> Iv {
        Iv {
            lo: next_down(x),
            hi: next_up(x),
        }
    }

    fn is_point(&self) -> bool {
        self.lo == self.hi
    }

    fn is_finite(&self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    /// `self + o`.
    pub(crate) fn add(self, o: Iv) -> Iv {
        if self.is_point() && o.is_point() {
            let (a, b) = (self.lo, o.lo);
            let s = a + b;
            if s.is_finite() {
                // TwoSum: the exact rounding error of a + b.
                let bb = s - a;
                let err = (a - (s - bb)) + (b - bb);
                if err == 0.0 {
                    return Iv::point(s);
                }
            }
            return Iv::around(s);
        }
        Iv {
            lo: next_down(self.lo + o.lo),
            hi: next_up(self.hi + o.hi),
        }
    }

    /// `−self`.
    pub(crate) fn neg(self) -> Iv {
        Iv {
            lo: -self.hi,
            hi: -self.lo,
        }
    }

    /// `self − o`.
    pub(crate) fn sub(self, o: Iv) -> Iv {
        self.add(o.neg())
    }

    /// `self · o`.
    pub(crate) fn mul(self, o: Iv) -> Iv {
        if !self.is_finite() || !o.is_finite() {
            return NAN;
        }
        if self.is_point() && o.is_point() {
            let (a, b) = (self.lo, o.lo);
            if a == 0.0 || b == 0.0 {
                return Iv::point(0.0);
            }
            let p = a * b;
            // With |p| ≥ TINY the residual a·b − p is a multiple of a float far above the
            // subnormal range, so the fused multiply-add computes it exactly.
            if p.is_finite() && p.abs() >= TINY && a.mul_add(b, -p) == 0.0 {
                return Iv::point(p);
            }
            return Iv::around(p);
        }
        let c = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        let (mut lo, mut hi) = (c[0], c[0]);
        for &x in &c[1..] {
            lo = lo.min(x);
            hi = hi.max(x);
        }
        Iv {
            lo: next_down(lo),
            hi: next_up(hi),
        }
    }

    /// `self / o`; undecidable (NaN) when `o` contains zero.
    pub(crate) fn div(self, o: Iv) -> Iv {
        if !self.is_finite() || !o.is_finite() || !(o.lo > 0.0 || o.hi < 0.0) {
            return NAN;
        }
        if self.is_point() && o.is_point() {
            let (a, b) = (self.lo, o.lo);
            if a == 0.0 {
                return Iv::point(0.0);
            }
            let q = a / b;
            // a − q·b is then computed exactly by the fused multiply-add (as for `mul`).
            if q.is_finite() && q.abs() >= TINY && (-q).mul_add(b, a) == 0.0 {
                return Iv::point(q);
            }
            return Iv::around(q);
        }
        let c = [
            self.lo / o.lo,
            self.lo / o.hi,
            self.hi / o.lo,
            self.hi / o.hi,
        ];
        let (mut lo, mut hi) = (c[0], c[0]);
        for &x in &c[1..] {
            lo = lo.min(x);
            hi = hi.max(x);
        }
        Iv {
            lo: next_down(lo),
            hi: next_up(hi),
        }
    }

    /// The sign of every real in the interval, if they all share one.
    pub(crate) fn sign(&self) -> Option<Ordering> {
        if self.lo > 0.0 {
            Some(Ordering::Greater)
        } else if self.hi < 0.0 {
            Some(Ordering::Less)
        } else if self.lo == 0.0 && self.hi == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

/// The sign of an exact rational.
pub(crate) fn rational_sign(x: &BigRational) -> Ordering {
    if x.is_zero() {
        Ordering::Equal
    } else if x.is_positive() {
        Ordering::Greater
    } else {
        Ordering::Less
    }
}

/// An `f64` as an exact rational (`0` for non-finite input, which validated points exclude).
pub(crate) fn rational(x: f64) -> BigRational {
    BigRational::from_float(x).unwrap_or_default()
}

/// A point in homogeneous integer coordinates: `(x / w, y / w)` with `w > 0`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Homogeneous {
    x: BigInt,
    y: BigInt,
    w: BigInt,
}

impl Homogeneous {
    /// The exact point `(x, y)` (reduced rationals, positive denominators).
    fn from_rationals(x: &BigRational, y: &BigRational) -> Homogeneous {
        Homogeneous {
            x: x.numer() * y.denom(),
            y: y.numer() * x.denom(),
            w: x.denom() * y.denom(),
        }
    }
}

/// `det [[a0, a1, a2], [b0, b1, b2], [c0, c1, c2]]`.
fn det3(a: [&BigInt; 3], b: [&BigInt; 3], c: [&BigInt; 3]) -> BigInt {
    a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        + a[2] * (b[0] * c[1] - b[1] * c[0])
}

fn integer_sign(x: &BigInt) -> Ordering {
    match x.sign() {
        BigSign::Minus => Ordering::Less,
        BigSign::NoSign => Ordering::Equal,
        BigSign::Plus => Ordering::Greater,
    }
}

/// The samples of a triangulation together with its Voronoi vertices, addressed by one index
/// space: `i < n` is sample `i` (the caller's index), `n + v` is Voronoi vertex `v`.
///
/// Exact evaluation uses homogeneous integer coordinates, computed once per point: then an
/// orientation is the sign of a 3 × 3 integer determinant of rows `(x, y, w)`, and an incircle
/// test, after translating to the fourth point, of rows `(P·R, Q·R, P² + Q²)` where
/// `(P, Q) / R` is the translated point. Scaling a row by a positive factor keeps the sign, so
/// no division and no gcd is ever needed.
pub(crate) struct MixedPoints<'a> {
    samples: &'a [[f64; 2]],
    /// Defining triangle of every Voronoi vertex (its circumcenter is the vertex).
    triangles: Vec<[[f64; 2]; 3]>,
    /// Enclosing intervals of the Voronoi vertices.
    approx: Vec<[Iv; 2]>,
    /// Exact points (samples first, then Voronoi vertices), computed when first needed.
    exact: Vec<OnceCell<Box<Homogeneous>>>,
}

/// Enclosing intervals of the circumcenter `t0 + u / d` of `t` (see
/// [`crate::predicates::exact`] for the formula), or `None` if the filter cannot bound it.
fn circumcenter_interval(t: [[f64; 2]; 3]) -> Option<[Iv; 2]> {
    let p = |x: f64| Iv::point(x);
    let (bx, by) = (p(t[1][0]).sub(p(t[0][0])), p(t[1][1]).sub(p(t[0][1])));
    let (cx, cy) = (p(t[2][0]).sub(p(t[0][0])), p(t[2][1]).sub(p(t[0][1])));
    let d = bx.mul(cy).sub(by.mul(cx));
    let d = d.add(d);
    let b2 = bx.mul(bx).add(by.mul(by));
    let c2 = cx.mul(cx).add(cy.mul(cy));
    let ux = cy.mul(b2).sub(by.mul(c2));
    let uy = bx.mul(c2).sub(cx.mul(b2));
    let x = p(t[0][0]).add(ux.div(d));
    let y = p(t[0][1]).add(uy.div(d));
    // Keep only tight enclosures; loose ones are replaced by the rounded exact point.
    let tight = |i: &Iv| {
        i.is_finite() && (i.hi - i.lo) <= 1e-9 * i.lo.abs().max(i.hi.abs()).max(f64::MIN_POSITIVE)
    };
    (tight(&x) && tight(&y)).then_some([x, y])
}

/// The exact circumcenter of a (non-collinear) Delaunay triangle.
fn exact_circumcenter(t: [[f64; 2]; 3]) -> ExactPoint {
    circumcenter_exact(t[0], t[1], t[2]).unwrap_or(ExactPoint {
        x: rational(t[0][0]),
        y: rational(t[0][1]),
    })
}

impl<'a> MixedPoints<'a> {
    /// Samples `samples` and Voronoi vertices that are the circumcenters of `triangles`
    /// (each non-collinear).
    pub(crate) fn new(samples: &'a [[f64; 2]], triangles: Vec<[[f64; 2]; 3]>) -> Self {
        let n = samples.len();
        let exact: Vec<OnceCell<Box<Homogeneous>>> =
            (0..n + triangles.len()).map(|_| OnceCell::new()).collect();
        let approx = triangles
            .iter()
            .zip(&exact[n..])
            .map(|(&t, cell)| {
                circumcenter_interval(t).unwrap_or_else(|| {
                    // Rounded to nearest, so the exact value is within one step each way.
                    let e = exact_circumcenter(t);
                    let [x, y] = e.to_f64();
                    let _ = cell.set(Box::new(Homogeneous::from_rationals(&e.x, &e.y)));
                    [Iv::around(x), Iv::around(y)]
                })
            })
            .collect();
        MixedPoints {
            samples,
            triangles,
            approx,
            exact,
        }
    }

    /// Is `i` a sample?
    pub(crate) fn is_sample(&self, i: u32) -> bool {
        (i as usize) < self.samples.len()
    }

    /// Enclosing intervals of point `i`.
    pub(crate) fn interval(&self, i: u32) -> [Iv; 2] {
        let i = i as usize;
        match self.samples.get(i) {
            Some(&[x, y]) => [Iv::point(x), Iv::point(y)],
            None => self.approx[i - self.samples.len()],
        }
    }

    /// The exact point `i`.
    fn exact(&self, i: u32) -> &Homogeneous {
        let i = i as usize;
        self.exact[i].get_or_init(|| {
            Box::new(match self.samples.get(i) {
                Some(&[x, y]) => Homogeneous::from_rationals(&rational(x), &rational(y)),
                None => {
                    let e = exact_circumcenter(self.triangles[i - self.samples.len()]);
                    Homogeneous::from_rationals(&e.x, &e.y)
                }
            })
        })
    }

    /// The exact coordinates of point `i`.
    #[cfg(test)]
    pub(crate) fn exact_rational(&self, i: u32) -> [BigRational; 2] {
        let h = self.exact(i);
        [
            BigRational::new(h.x.clone(), h.w.clone()),
            BigRational::new(h.y.clone(), h.w.clone()),
        ]
    }

    /// Exact orientation of `a → b → c`.
    pub(crate) fn orient(&self, a: u32, b: u32, c: u32) -> Orientation {
        if self.is_sample(a) && self.is_sample(b) && self.is_sample(c) {
            let s = self.samples;
            return orient2d(s[a as usize], s[b as usize], s[c as usize]);
        }
        let [pa, pb, pc] = [self.interval(a), self.interval(b), self.interval(c)];
        let sign = orient_expr(&pa, &pb, &pc, Iv::sub, Iv::mul)
            .sign()
            .unwrap_or_else(|| {
                let [ea, eb, ec] = [self.exact(a), self.exact(b), self.exact(c)];
                integer_sign(&det3(
                    [&ea.x, &ea.y, &ea.w],
                    [&eb.x, &eb.y, &eb.w],
                    [&ec.x, &ec.y, &ec.w],
                ))
            });
        match sign {
            Ordering::Greater => Orientation::CounterClockwise,
            Ordering::Less => Orientation::Clockwise,
            Ordering::Equal => Orientation::Collinear,
        }
    }

    /// Exact position of `d` relative to the circle through the counterclockwise `a, b, c`.
    pub(crate) fn incircle(&self, a: u32, b: u32, c: u32, d: u32) -> CirclePosition {
        if [a, b, c, d].iter().all(|&i| self.is_sample(i)) {
            let s = self.samples;
            return incircle_f64(s[a as usize], s[b as usize], s[c as usize], s[d as usize]);
        }
        let [pa, pb, pc, pd] = [a, b, c, d].map(|i| self.interval(i));
        let sign = incircle_expr(&pa, &pb, &pc, &pd, Iv::add, Iv::sub, Iv::mul)
            .sign()
            .unwrap_or_else(|| {
                let ed = self.exact(d);
                // (P, Q) / R = point − d, with R = w·w_d > 0; row (P·R, Q·R, P² + Q²).
                let row = |i: u32| {
                    let e = self.exact(i);
                    let p = &e.x * &ed.w - &ed.x * &e.w;
                    let q = &e.y * &ed.w - &ed.y * &e.w;
                    let r = &e.w * &ed.w;
                    [&p * &r, &q * &r, &p * &p + &q * &q]
                };
                let [ra, rb, rc] = [row(a), row(b), row(c)];
                integer_sign(&det3(
                    [&ra[0], &ra[1], &ra[2]],
                    [&rb[0], &rb[1], &rb[2]],
                    [&rc[0], &rc[1], &rc[2]],
                ))
            });
        match sign {
            Ordering::Greater => CirclePosition::Inside,
            Ordering::Less => CirclePosition::Outside,
            Ordering::Equal => CirclePosition::On,
        }
    }
}

/// `(b − a) × (c − a)`.
fn orient_expr<T: Clone>(
    a: &[T; 2],
    b: &[T; 2],
    c: &[T; 2],
    sub: impl Fn(T, T) -> T,
    mul: impl Fn(T, T) -> T,
) -> T {
    let (bx, by) = (
        sub(b[0].clone(), a[0].clone()),
        sub(b[1].clone(), a[1].clone()),
    );
    let (cx, cy) = (
        sub(c[0].clone(), a[0].clone()),
        sub(c[1].clone(), a[1].clone()),
    );
    sub(mul(bx, cy), mul(by, cx))
}

/// The incircle determinant of `a, b, c, d` translated to `d`: positive iff `d` is inside the
/// circle through the counterclockwise `a, b, c`.
fn incircle_expr<T: Clone>(
    a: &[T; 2],
    b: &[T; 2],
    c: &[T; 2],
    d: &[T; 2],
    add: impl Fn(T, T) -> T,
    sub: impl Fn(T, T) -> T,
    mul: impl Fn(T, T) -> T,
) -> T {
    let rel = |p: &[T; 2]| {
        [
            sub(p[0].clone(), d[0].clone()),
            sub(p[1].clone(), d[1].clone()),
        ]
    };
    let [ax, ay] = rel(a);
    let [bx, by] = rel(b);
    let [cx, cy] = rel(c);
    let norm = |x: &T, y: &T| add(mul(x.clone(), x.clone()), mul(y.clone(), y.clone()));
    let cross = |px: &T, py: &T, qx: &T, qy: &T| {
        sub(mul(px.clone(), qy.clone()), mul(py.clone(), qx.clone()))
    };
    let t1 = mul(norm(&ax, &ay), cross(&bx, &by, &cx, &cy));
    let t2 = mul(norm(&bx, &by), cross(&cx, &cy, &ax, &ay));
    let t3 = mul(norm(&cx, &cy), cross(&ax, &ay, &bx, &by));
    add(add(t1, t2), t3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_steps_are_outward() {
        assert!(next_up(1.0) > 1.0 && next_down(1.0) < 1.0);
        assert_eq!(next_up(0.0), f64::from_bits(1));
        assert_eq!(next_down(0.0), -f64::from_bits(1));
        assert_eq!(next_up(-f64::from_bits(1)), 0.0);
        assert_eq!(next_up(f64::INFINITY), f64::INFINITY);
        assert_eq!(next_down(f64::MAX), f64::from_bits(f64::MAX.to_bits() - 1));
    }

    #[test]
    fn exact_operations_stay_points() {
        let s = Iv::point(0.5).add(Iv::point(0.25));
        assert_eq!(s, Iv::point(0.75));
        let p = Iv::point(3.0).mul(Iv::point(-7.0));
        assert_eq!(p, Iv::point(-21.0));
        let q = Iv::point(1.0).div(Iv::point(4.0));
        assert_eq!(q, Iv::point(0.25));
        // Inexact: 0.1 + 0.2 and 1/3 are widened, and contain the exact value.
        let s = Iv::point(0.1).add(Iv::point(0.2));
        assert!(!s.is_point() && s.lo < 0.30000000000000004 && s.hi >= 0.30000000000000004);
        let q = Iv::point(1.0).div(Iv::point(3.0));
        assert!(q.lo < 1.0 / 3.0 && q.hi > 1.0 / 3.0);
        assert_eq!(
            Iv::point(1.0).sub(Iv::point(1.0)).sign(),
            Some(Ordering::Equal)
        );
        assert_eq!(Iv::point(1.0).div(Iv::point(0.0)).sign(), None);
    }

    #[test]
    fn grid_circumcenters_are_exact() {
        let t = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
        assert_eq!(
            circumcenter_interval(t).unwrap(),
            [Iv::point(1.0), Iv::point(1.0)]
        );
        let samples = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, -1.0]];
        // Point 5: the centre (1, 1) of the square.
        let mp = MixedPoints::new(&samples, vec![[samples[0], samples[1], samples[3]]]);
        assert_eq!(mp.incircle(0, 1, 2, 5), CirclePosition::Inside);
        assert_eq!(mp.orient(0, 2, 5), Orientation::Collinear);
        // (0,0), (1,-1), (2,0) and the centre (1,1) are cocircular (circle about (1,0)).
        assert_eq!(mp.incircle(0, 4, 1, 5), CirclePosition::On);
        assert_eq!(mp.incircle(0, 4, 5, 3), CirclePosition::Outside);
    }

    #[test]
    fn exact_path_decides_what_intervals_cannot() {
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
        assert_eq!(mp.incircle(0, 1, 2, 5), CirclePosition::Inside);
        // Both answers agree with a direct rational evaluation.
        for (a, b, c, d) in [(0, 4, 1, 5), (0, 4, 5, 3), (4, 1, 5, 2), (0, 1, 5, 2)] {
            let [pa, pb, pc, pd] = [a, b, c, d].map(|i| mp.exact_rational(i));
            let value = incircle_expr(&pa, &pb, &pc, &pd, |x, y| x + y, |x, y| x - y, |x, y| x * y);
            let orientation = orient_expr(&pa, &pb, &pc, |x, y| x - y, |x, y| x * y);
            let expected = match rational_sign(&(value * orientation.signum())) {
                Ordering::Greater => CirclePosition::Inside,
                Ordering::Less => CirclePosition::Outside,
                Ordering::Equal => CirclePosition::On,
            };
            // `incircle` wants a counterclockwise triangle.
            let got = match mp.orient(a, b, c) {
                Orientation::Clockwise => mp.incircle(a, c, b, d),
                _ => mp.incircle(a, b, c, d),
            };
            assert_eq!(got, expected, "{a} {b} {c} {d}");
        }
        for (a, b, c) in [(0, 2, 5), (1, 3, 5), (4, 5, 0), (4, 5, 2)] {
            let [pa, pb, pc] = [a, b, c].map(|i| mp.exact_rational(i));
            let expected =
                match rational_sign(&orient_expr(&pa, &pb, &pc, |x, y| x - y, |x, y| x * y)) {
                    Ordering::Greater => Orientation::CounterClockwise,
                    Ordering::Less => Orientation::Clockwise,
                    Ordering::Equal => Orientation::Collinear,
                };
            assert_eq!(mp.orient(a, b, c), expected, "{a} {b} {c}");
        }
    }
}
