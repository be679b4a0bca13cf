//! Exact evaluation: every finite `f64` is `m·2^e` with an integer `m`, so the inputs of one
//! call, taken in units of the smallest `2^e` among them ([`lift_exact`]), are integers, and
//! the (homogeneous) polynomials are evaluated in [`BigInt`] with no rational normalization
//! at all. Also the correctly rounded conversion of exact ratios back to `f64`.

use num_bigint::{BigInt, BigUint, Sign as BigSign};
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

use super::arith::Arith;
use super::bounded::Bounded;
use super::scale::pow2;
use super::stats::Stage;
use super::Sign;

/// The signs of `terms` evaluated by the running-error filter on `filtered`, or else exactly
/// on `exact`, and the stage that decided: the tail every filtered kernel predicate shares.
pub(super) fn signs<const K: usize>(
    filtered: [Bounded; K],
    exact: impl FnOnce() -> [BigInt; K],
) -> ([Sign; K], Stage) {
    let mut out = [Sign::Zero; K];
    let mut decided = true;
    for (o, b) in out.iter_mut().zip(filtered.iter()) {
        match b.sign() {
            Some(s) => *o = s,
            None => decided = false,
        }
    }
    if decided {
        return (out, Stage::Bounded);
    }
    let values = exact();
    for (o, v) in out.iter_mut().zip(values.iter()) {
        *o = integer_sign(v);
    }
    (out, Stage::Exact)
}

/// The ring operations of an exact number type by its operators; `$sign` maps a value to
/// its sign.
macro_rules! exact_arith {
    ($t:ty, $sign:expr) => {
        impl Arith for $t {
            fn add(&self, other: &Self) -> Self {
                self + other
            }

            fn sub(&self, other: &Self) -> Self {
                self - other
            }

            fn mul(&self, other: &Self) -> Self {
                self * other
            }

            fn sign(&self) -> Option<Sign> {
                Some($sign(self))
            }
        }
    };
}

exact_arith!(BigInt, integer_sign);

// Exact rationals, for the tests: an evaluation independent of `lift_exact`.
#[cfg(test)]
exact_arith!(BigRational, |x: &BigRational| integer_sign(x.numer()));

/// The exact sign of an integer.
pub(super) fn integer_sign(x: &BigInt) -> Sign {
    match x.sign() {
        BigSign::Minus => Sign::Negative,
        BigSign::NoSign => Sign::Zero,
        BigSign::Plus => Sign::Positive,
    }
}

/// `x = ±m·2^e` with an odd `m` (or `m = 0`); non-finite values give an unspecified result.
fn decompose(x: f64) -> (bool, u64, i32) {
    let bits = x.to_bits();
    let negative = bits >> 63 == 1;
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let fraction = bits & ((1u64 << 52) - 1);
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1u64 << 52), biased - 1075)
    };
    if m == 0 {
        return (negative, 0, 0);
    }
    let zeros = m.trailing_zeros();
    (negative, m >> zeros, e + zeros as i32)
}

/// The points as integers in units of `2^shift`, the smallest power of two among their
/// coordinates: `x = X · 2^shift` exactly. Non-finite coordinates become zero.
pub(super) fn lift_exact<const N: usize>(points: [[f64; 2]; N]) -> ([[BigInt; 2]; N], i32) {
    let parts = points.map(|p| {
        p.map(|x| {
            if x.is_finite() {
                decompose(x)
            } else {
                (false, 0, 0)
            }
        })
    });
    let shift = parts
        .iter()
        .flatten()
        .filter(|&&(_, m, _)| m != 0)
        .map(|&(_, _, e)| e)
        .min()
        .unwrap_or(0);
    let lifted = parts.map(|p| {
        p.map(|(negative, m, e)| {
            if m == 0 {
                return BigInt::zero();
            }
            let magnitude = BigInt::from(m) << (e - shift).unsigned_abs();
            if negative {
                -magnitude
            } else {
                magnitude
            }
        })
    });
    (lifted, shift)
}

/// `x` rounded to the nearest `f64`, ties to even (infinite beyond the `f64` range).
pub(super) fn rational_to_f64(x: &BigRational) -> f64 {
    let negative = x.numer().sign() == BigSign::Minus;
    ratio_to_f64(negative, x.numer().magnitude(), x.denom().magnitude(), 0)
}

/// `±(n / d)·2^e` (`d > 0`, not necessarily in lowest terms) rounded to the nearest `f64`,
/// ties to even (infinite beyond the `f64` range).
pub(super) fn ratio_to_f64(negative: bool, n: &BigUint, d: &BigUint, e: i64) -> f64 {
    let signed = |m: f64| if negative { -m } else { m };
    if n.is_zero() {
        return 0.0;
    }
    if d.is_zero() {
        return signed(f64::INFINITY); // unreachable for the callers: d > 0
    }
    // |x| lies in [2^(e0 − 1), 2^(e0 + 1)).
    let e0 = n.bits() as i64 - d.bits() as i64 + e;
    if e0 > 1025 {
        return signed(f64::INFINITY);
    }
    if e0 < -1080 {
        return signed(0.0);
    }
    // q = floor(|x| · 2^s) has 55 or 56 bits; `sticky` tells whether the floor dropped anything.
    let s = 55 - e0;
    let t = s + e;
    let (num, den) = if t >= 0 {
        (n << (t as usize), d.clone())
    } else {
        (n.clone(), d << ((-t) as usize))
    };
    let q = &num / &den;
    let r = &num - &q * &den;
    let Some(q) = q.to_u64() else {
        return signed(f64::NAN); // unreachable: q < 2^56
    };
    let sticky = !r.is_zero();
    let q_bits = 64 - i64::from(q.leading_zeros());
    let exponent = q_bits - 1 - s; // floor(log2 |x|)
    if exponent > 1023 {
        return signed(f64::INFINITY);
    }
    // The result is a multiple of 2^(exponent − 52), or of 2^-1074 when subnormal.
    let quantum = exponent.max(-1022) - 52;
    let shift = quantum + s; // ≥ 2
    if shift >= 60 {
        return signed(0.0); // |x| < 2^-1076: below half the smallest subnormal
    }
    let kept = q >> shift;
    let dropped = q & ((1u64 << shift) - 1);
    let half = 1u64 << (shift - 1);
    let round_up = dropped > half || (dropped == half && (sticky || kept & 1 == 1));
    // The mantissa is at most 2^53 (exact as f64) and `quantum` lies in -1074..=971: the
    // product is exact or overflows to infinity, as rounding to nearest requires.
    let mantissa = kept + u64::from(round_up);
    signed(mantissa as f64 * pow2(quantum as i32))
}
