//! The running-error filter: [`Bounded`], an `f64` value with a proven bound on its distance
//! from the exact value. Used where the semi-static filter has no precomputed constants
//! (deep or mixed expressions) or could not decide; when its bound cannot decide a sign
//! either, the caller evaluates exactly (`super::exact`).
//!
//! # The error bound of [`Bounded`]
//!
//! A `Bounded { v, e }` stands for a real number `x` with `|x − v| ≤ e`. Every input `f64` is
//! exact (`e = 0`). For an operation `∘` on `a = (va, ea)` and `b = (vb, eb)` the result is
//! `v = fl(va ∘ vb)` and
//!
//! * rounding: round-to-nearest gives `|fl(va ∘ vb) − va ∘ vb| ≤ u·|v|` with `u = 2^-53` when
//!   `v` is normal; a subnormal product or quotient adds at most `2^-1075 < η = 2^-1074`
//!   (sums are exact in the subnormal range). When both operands are exact the rounding error
//!   is computed exactly instead (Knuth's TwoSum, Dekker's TwoProduct, in the ranges where
//!   they are proven exact), so results that are exactly representable keep `e = 0`;
//! * propagation: `ea + eb` for sums and differences, `|va|·eb + |vb|·ea + ea·eb` for products
//!   (from `(va + α)(vb + β) − va·vb = va·β + vb·α + α·β`).
//!
//! The error terms themselves are sums and products of non-negative `f64`s; each such
//! operation is rounded to nearest and then stepped one ulp up (`up`), which is an upper
//! bound of the exact result (the exact value lies within half a gap of the rounded one), so
//! `e` is a true upper bound, never an estimate. Overflow makes `v` or `e` infinite or NaN and
//! the sign is then reported undecided. Hence: if `v` is finite and `|v| > e`, the exact value
//! has the sign of `v`; if `v = e = 0`, the exact value is zero; otherwise the caller falls
//! back to exact arithmetic.

use super::arith::{Arith, U};
use super::Sign;

/// Smallest positive subnormal: 2^-1074.
pub(super) const ETA: f64 = f64::MIN_POSITIVE * f64::EPSILON;
/// Below this magnitude of a product, Dekker's TwoProduct is not proven exact (underflow).
pub(super) const TWO_PRODUCT_MIN: f64 = 1.2882297539194267e-271; // 2^-900
/// Above this magnitude of a factor, Dekker's splitting could overflow.
const TWO_PRODUCT_MAX_FACTOR: f64 = 1.0463951242053392e298; // 2^990
/// Above this magnitude of a sum, TwoSum is not used (no overflow risk below it).
const TWO_SUM_MAX: f64 = 1.0715086071862673e301; // 2^1000

/// The smallest `f64` above `x`, for `x ≥ 0`; infinities and NaN are returned unchanged.
#[inline]
pub(super) fn up(x: f64) -> f64 {
    if x < f64::INFINITY {
        if x == 0.0 {
            ETA
        } else {
            f64::from_bits(x.to_bits() + 1)
        }
    } else {
        x
    }
}

/// An upper bound of `x + y` for `x, y ≥ 0` (exact zero stays zero).
#[inline]
pub(super) fn add_up(x: f64, y: f64) -> f64 {
    let s = x + y;
    if s == 0.0 {
        0.0
    } else {
        up(s)
    }
}

/// An upper bound of `x · y` for `x, y ≥ 0` (a zero factor gives an exact zero).
#[inline]
pub(super) fn mul_up(x: f64, y: f64) -> f64 {
    if x == 0.0 || y == 0.0 {
        0.0
    } else {
        up(x * y)
    }
}

/// A lower bound of `x − y` for `x ≥ y ≥ 0`, or `None` if it is not certainly positive.
#[inline]
pub(super) fn sub_down_positive(x: f64, y: f64) -> Option<f64> {
    let d = x - y;
    if d > 0.0 && d < f64::INFINITY {
        // The exact difference is above the predecessor of its rounding.
        let below = f64::from_bits(d.to_bits() - 1);
        (below > 0.0).then_some(below)
    } else {
        None
    }
}

/// An upper bound of `x / y` for `x ≥ 0`, `y > 0`.
#[inline]
pub(super) fn div_up(x: f64, y: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        up(x / y)
    }
}

/// Dekker's splitting of `x` into two halves of at most 26 significant bits.
#[inline]
fn split(x: f64) -> (f64, f64) {
    const SPLITTER: f64 = 134_217_729.0; // 2^27 + 1
    let c = SPLITTER * x;
    let hi = c - (c - x);
    (hi, x - hi)
}

/// The exact rounding error `a·b − p` of `p = fl(a·b)`, if it is proven exact here.
#[inline]
fn two_product_error(a: f64, b: f64, p: f64) -> Option<f64> {
    if a == 0.0 || b == 0.0 {
        return Some(0.0);
    }
    let ok = a.abs() < TWO_PRODUCT_MAX_FACTOR
        && b.abs() < TWO_PRODUCT_MAX_FACTOR
        && p.abs() >= TWO_PRODUCT_MIN
        && p.is_finite();
    ok.then(|| dekker_error(a, b, p))
}

/// Dekker's TwoProduct: the rounding error `a·b − p` of `p = fl(a·b)`, exact when no step
/// overflows and `|p| ≥ 2^-900` (no underflow: the exponents of `a` and `b` sum to at least
/// `−1022 + 52`). A step that overflows makes the result infinite or NaN: every later step
/// subtracts or multiplies it, and all of them feed the result.
#[inline(always)]
pub(super) fn dekker_error(a: f64, b: f64, p: f64) -> f64 {
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let err1 = p - ah * bh;
    let err2 = err1 - al * bh;
    let err3 = err2 - ah * bl;
    al * bl - err3
}

/// A real number known to lie within `e` of the `f64` value `v` (see the module docs).
#[derive(Debug, Clone, Copy)]
pub(super) struct Bounded {
    /// The floating-point approximation.
    pub(super) v: f64,
    /// A rigorous upper bound of the distance between `v` and the exact value.
    pub(super) e: f64,
}

impl Bounded {
    /// The exact value `x`.
    #[inline]
    pub(super) fn from_f64(x: f64) -> Bounded {
        Bounded { v: x, e: 0.0 }
    }

    /// `self + other`, or `self − other` if `negate`.
    #[inline]
    fn add_signed(&self, other: &Bounded, negate: bool) -> Bounded {
        let b = if negate { -other.v } else { other.v };
        // An exact zero operand leaves the other one unchanged.
        if other.v == 0.0 && other.e == 0.0 {
            return *self;
        }
        if self.v == 0.0 && self.e == 0.0 {
            return Bounded { v: b, e: other.e };
        }
        let v = self.v + b;
        if self.e == 0.0 && other.e == 0.0 && v.abs() < TWO_SUM_MAX {
            // Knuth's TwoSum: the exact rounding error of `v` (no overflow below 2^1000).
            let bv = v - self.v;
            let err = (self.v - (v - bv)) + (b - bv);
            return Bounded { v, e: err.abs() };
        }
        let rounding = mul_up(U, v.abs());
        Bounded {
            v,
            e: add_up(add_up(self.e, other.e), rounding),
        }
    }

    /// `self / other`, or `None` if `other` is not certainly non-zero.
    pub(super) fn div(&self, other: &Bounded) -> Option<Bounded> {
        let den = sub_down_positive(other.v.abs(), other.e)?;
        if self.v == 0.0 && self.e == 0.0 {
            return Some(*self);
        }
        let q = self.v / other.v;
        if !q.is_finite() {
            return None;
        }
        // An exact quotient of exact operands stays exact (grid circumcenters): `q·b = a`
        // with a zero TwoProduct error.
        if self.e == 0.0 && other.e == 0.0 {
            let p = q * other.v;
            if p == self.v && two_product_error(q, other.v, p) == Some(0.0) {
                return Some(Bounded { v: q, e: 0.0 });
            }
        }
        // |q − va/vb| ≤ u|q| + η, so |va/vb| ≤ |q| + u|q| + η.
        let rounding = add_up(mul_up(U, q.abs()), ETA);
        let quotient_bound = add_up(q.abs(), rounding);
        // |x/y − va/vb| = |(x − va)·vb − va·(y − vb)| / |y·vb| ≤ (ea + |va/vb|·eb) / (|vb| − eb).
        let propagated = div_up(add_up(self.e, mul_up(quotient_bound, other.e)), den);
        Some(Bounded {
            v: q,
            e: add_up(propagated, rounding),
        })
    }
}

impl Arith for Bounded {
    #[inline]
    fn add(&self, other: &Self) -> Self {
        self.add_signed(other, false)
    }

    #[inline]
    fn sub(&self, other: &Self) -> Self {
        self.add_signed(other, true)
    }

    #[inline]
    fn mul(&self, other: &Self) -> Self {
        // An exact 1 (the weight of a point in homogeneous coordinates) changes nothing.
        if other.e == 0.0 && other.v == 1.0 {
            return *self;
        }
        if self.e == 0.0 && self.v == 1.0 {
            return *other;
        }
        let (a, b) = (self.v, other.v);
        let v = a * b;
        let exact_error = if self.e == 0.0 && other.e == 0.0 {
            two_product_error(a, b, v)
        } else {
            None
        };
        let rounding = match exact_error {
            Some(err) => err.abs(),
            None if v.abs() >= f64::MIN_POSITIVE => mul_up(U, v.abs()),
            None if a == 0.0 || b == 0.0 => 0.0,
            None => ETA,
        };
        let propagated = add_up(
            add_up(mul_up(a.abs(), other.e), mul_up(b.abs(), self.e)),
            mul_up(self.e, other.e),
        );
        Bounded {
            v,
            e: add_up(propagated, rounding),
        }
    }

    #[inline]
    fn sign(&self) -> Option<Sign> {
        if self.v.is_finite() && self.v.abs() > self.e {
            Some(if self.v > 0.0 {
                Sign::Positive
            } else {
                Sign::Negative
            })
        } else if self.v == 0.0 && self.e == 0.0 {
            Some(Sign::Zero)
        } else {
            None
        }
    }
}

/// The points as exact filter values.
pub(super) fn lift_filter<const N: usize>(points: [[f64; 2]; N]) -> [[Bounded; 2]; N] {
    points.map(|p| p.map(Bounded::from_f64))
}

/// The unit in the last place of a finite `v`: the gap from `|v|` to the next larger `f64`
/// (a bound of the error of a correctly rounded `v`; infinite for infinite `v`).
pub(super) fn ulp(v: f64) -> f64 {
    let a = v.abs();
    f64::from_bits(a.to_bits() + 1) - a
}
