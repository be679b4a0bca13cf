//! The middle stage of the circumcenter construction: double-word arithmetic with a running
//! error bound, between the `f64` filters and exact `BigInt` arithmetic.
//!
//! A nearly collinear triangle (three consecutive samples of a noisy curve) has a
//! denominator `d = 2 (bx·cy − by·cx)` far smaller than its two products: in `f64` their
//! rounding errors, a few `u = 2^-53` of the products, swamp `d`, the circumcenter's error
//! grows by the same factor, and the filters cannot prove 256 ulps. Evaluated on
//! [`DoubleWord`]s — a value as the unevaluated sum `hi + lo` of two `f64`s, about 106
//! significant bits — each rounding is of the order `u²` of its operands instead, so the
//! same formula (`circumcenter::circ`, written once over [`Arith`]) proves 256 ulps unless
//! the triangle is within about `2^-60` of collinear. The differences of the input
//! coordinates, the leaves of the formula, are exact. The bound is computed beside the
//! value, operation by operation, so it holds for every call whatever the input; it costs
//! about a quarter of the `BigInt` construction on thin triangles.
//!
//! # The bound (a proof)
//!
//! A `DoubleWord { hi, lo, e }` stands for a real number `x` with `|x − (hi + lo)| ≤ e`, where
//! `hi + lo` is the exact real sum. An input `f64` `x` is `{x, 0, 0}`. Notation: `u = 2^-53`,
//! `η = 2^-1074` (the smallest subnormal), round to nearest, `fl(·)` one rounded operation;
//! no operation is fused except the explicit `mul_add` in TwoProduct.
//!
//! * (R1) A sum or difference of `f64`s that does not overflow satisfies
//!   `|fl(x ± y) − (x ± y)| ≤ u·|fl(x ± y)|`: if `|x ± y|` lies in `[2^k, 2^(k+1))`,
//!   `k ≥ −1022`, the `f64`s there are `2^(k−52)` apart, so the rounding error is at most
//!   `2^(k−53) = u·2^k ≤ u·|fl(x ± y)|` (rounding is monotonic and `2^k` is an `f64`); below
//!   `2^-1022` the sum is exact, both operands being multiples of `η`.
//! * (R2) A product or quotient: `|fl(x∘y) − x∘y| ≤ u·|fl(x∘y)| + η/2` (the same argument in
//!   the normal range; below it the result is within half the subnormal spacing).
//! * (T1) TwoSum (Knuth): `(s, t)` with `s = fl(a + b)` and `s + t = a + b` exactly.
//! * (T2) TwoProduct: `(p, q)` with `p = fl(a·b)` and `|p + q − a·b| ≤ η/2`. For
//!   `|p| ≥ 2^-900` Dekker's product (`bounded::dekker_error`), exact; otherwise
//!   `q = fl(a·b − p)` by one fused multiply-add (`f64::mul_add`, correctly rounded on every
//!   platform), exact unless it lies below `2^-1022`.
//!
//! With `ã = a.hi + a.lo`, `x = ã + α`, `|α| ≤ a.e` (and `b̃`, `y`, `β` alike):
//!
//! * **Sum** `a ± b`: `(s, t) = TwoSum(a.hi, ±b.hi)`, `w = fl(a.lo ± b.lo)`,
//!   `z = fl(t + w)`, `(hi, lo) = TwoSum(s, z)`. Then `hi + lo = s + z` and
//!   `ã ± b̃ = s + t + (a.lo ± b.lo)`, so by (R1) the new error is at most `u·(|w| + |z|)`:
//!   `e = a.e + b.e + u·(|w| + |z|)`.
//! * **Product**: `(p, q) = TwoProduct(a.hi, b.hi)`, `m1 = fl(a.hi·b.lo)`, `m2 = fl(a.lo·b.hi)`,
//!   `w = fl(m1 + m2)`, `z = fl(q + w)`, `(hi, lo) = TwoSum(p, z)`. `ã·b̃` is
//!   `a.hi·b.hi + a.hi·b.lo + a.lo·b.hi + a.lo·b.lo` and `hi + lo = p + z`, so by (T2), (R1),
//!   (R2) the new error is at most `u·(|m1| + |m2| + |w| + |z|) + 3η + |a.lo|·|b.lo|`; the
//!   operands' errors add `|ã|·b.e + |b̃|·a.e + a.e·b.e` (from
//!   `x·y − ã·b̃ = ã·β + b̃·α + α·β`), with `|ã| ≤ |a.hi| + |a.lo|`.
//! * **Quotient** `a / b`, only when a lower bound `b_low` of `|b.hi| − |b.lo| ≤ |b̃|` exceeds
//!   `b.e`, so that `y ≠ 0` and `|y| ≥ den`, a lower bound of `b_low − b.e` (both by
//!   `bounded::sub_down_positive`): `q1 = fl(a.hi / b.hi)`, `(p, p') = TwoProduct(q1, b.hi)`,
//!   `r = fl(fl(fl(a.hi − p) − p') + fl(a.lo − fl(q1·b.lo)))`, `q2 = fl(r / b.hi)`,
//!   `(hi, lo) = TwoSum(q1, q2)`. The remainder `ρ = ã − q1·b̃` is
//!   `(a.hi − q1·b.hi) + (a.lo − q1·b.lo)`, so `|r − ρ| ≤ ε_r = u·Σ|r_i| + 2η` over the five
//!   rounded intermediates `r_i` (the two `η/2` from `p'` and `q1·b.lo`), and
//!   `ã/b̃ = q1 + ρ/b̃`. As `1/b.hi − 1/b̃ = b.lo / (b.hi·b̃)`,
//!   `|hi + lo − ã/b̃| = |q2 − ρ/b̃| ≤ |q2 − r/b.hi| + |r − ρ|/|b.hi| + |ρ|·|1/b.hi − 1/b̃|
//!   ≤ u·|q2| + η + ε_r/|b.hi| + (|r| + ε_r)·|b.lo| / (|b.hi|·b_low) = ε_q`. The operands'
//!   errors add `|x/y − ã/b̃| = |α − (ã/b̃)·β| / |y| ≤ (a.e + (|hi| + |lo| + ε_q)·b.e) / den`.
//! * **Doubling** is exact: `{2hi, 2lo, 2e}`; **a leaf** `x − y` of two inputs is
//!   `TwoSum(x, −y)` with `e = 0`.
//! * **A circumcenter coordinate** `O = t0 + Q` from the input `t0` and `q` for `Q = u/d`:
//!   `(s, t) = TwoSum(t0, q.hi)`, `w = fl(t + q.lo)`, `o = fl(s + w)`, and
//!   `|o − O| ≤ u·|o| + u·|w| + q.e` by (R1).
//!
//! **The bounds in floating point.** Each bound `F` above is a sum of non-negative terms:
//! operands' bounds, magnitudes, multiples of `η`, and products or quotients of such. It is
//! evaluated in `f64`, each product or quotient as `fl(fl(x∘y) + η)` ([`mul_term`],
//! [`div_term`]), which is at least `(1 − u)·x∘y` (B1: in the normal range
//! `fl(x∘y) ≥ x∘y / (1 + u)` and adding `η` cannot round below it; below `2^-1022`,
//! `fl(x∘y) ≥ x∘y − η/2` and adding `η` is exact there); a sum of non-negative values is at
//! least `(1 − u)` times the exact sum (exact below `2^-1022`). By induction the computed
//! `F̂ ≥ (1 − u)^k·F`, where `k` counts the rounded operations along the deepest path, the
//! depths of a product's factors added (at most 15 here). [`widen`] returns
//! `fl(fl(F̂·(1 + 2^-45)) + η) ≥ F` (B2) for `k ≤ 64`: `F ≤ F̂·(1 + 65u)`, and
//! `(1 + 2^-45) / (1 + u) ≥ 1 + 65u` in the normal range, while below it the `η` covers the
//! product's rounding. Divisors in a bound are the lower bounds above, so the quotients only
//! grow. Every `e` is therefore a true bound of the distance from `hi + lo` to the exact
//! value.
//!
//! [`circumcenter`] accepts `o` when both coordinates are finite, their larger magnitude `N`
//! is normal, and each bound is at most `256·ulp(N) = 2^-44·P` (`P ≤ N < 2P` a power of two):
//! exactly the promise of `predicates::circumcenter`.
//!
//! **Overflow and non-finite values.** The facts above hold for finite results. A step that
//! overflows makes a component infinite or NaN (for TwoSum and TwoProduct: every step of
//! theirs feeds their result, and no step turns an infinity back into a finite value), and
//! every later operation carries a non-finite `hi`, `lo` or `e` into its own result: the
//! quotient refuses non-finite operands, and the result is accepted only when finite. An
//! infinite or NaN bound fails the final test.

use super::arith::{Arith, U};
use super::bounded::{dekker_error, sub_down_positive, ETA, TWO_PRODUCT_MIN};
use super::circumcenter::{circ, Circ};
use super::poly::incircle_terms_points;
use super::Sign;

/// `2^-44`: 256 units in the last place of a power of two `P` are `2^-44·P`.
const TOLERANCE: f64 = 5.684341886080802e-14;
/// The exponent bits of an `f64`.
pub(super) const EXPONENT_MASK: u64 = 0x7ff0_0000_0000_0000;
/// `1 + 2^-45`: see [`widen`].
const WIDEN: f64 = 1.0 + 2.842170943040401e-14;

/// A real number known to lie within `e` of the exact sum `hi + lo` (see the module docs).
#[derive(Debug, Clone, Copy)]
pub(super) struct DoubleWord {
    pub(super) hi: f64,
    pub(super) lo: f64,
    /// A rigorous upper bound of the distance from `hi + lo` to the exact value.
    pub(super) e: f64,
}

/// Knuth's TwoSum (T1): `s = fl(a + b)` and `t` with `s + t = a + b` exactly.
#[inline(always)]
pub(super) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

/// TwoProduct (T2): `p = fl(a·b)` and `q` with `|p + q − a·b| ≤ η/2`, or a non-finite `p`
/// or `q`.
#[inline(always)]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    // Dekker's product costs no function call; the fused multiply-add is a call to libm on
    // targets built without FMA, and only the rare tiny products need it.
    let q = if p.abs() >= TWO_PRODUCT_MIN {
        dekker_error(a, b, p)
    } else {
        a.mul_add(b, -p)
    };
    (p, q)
}

/// A product term of a bound: `fl(fl(x·y) + η) ≥ (1 − u)·x·y` for `x, y ≥ 0` (B1).
#[inline(always)]
fn mul_term(x: f64, y: f64) -> f64 {
    x * y + ETA
}

/// A quotient term of a bound: `fl(fl(x/y) + η) ≥ (1 − u)·x/y` for `x ≥ 0`, `y > 0` (B1).
#[inline(always)]
fn div_term(x: f64, y: f64) -> f64 {
    x / y + ETA
}

/// An upper bound of a bound formula from its value computed in at most 64 rounded steps
/// (B2).
#[inline(always)]
fn widen(x: f64) -> f64 {
    x * WIDEN + ETA
}

impl DoubleWord {
    /// The exact value `x`.
    #[inline(always)]
    pub(super) fn from_f64(x: f64) -> DoubleWord {
        DoubleWord {
            hi: x,
            lo: 0.0,
            e: 0.0,
        }
    }

    /// `|hi| + |lo|`, rounded: a bound's term.
    #[inline(always)]
    fn magnitude(&self) -> f64 {
        self.hi.abs() + self.lo.abs()
    }

    /// `self + other`, or `self − other` if `negate`.
    #[inline(always)]
    fn add_signed(&self, other: &DoubleWord, negate: bool) -> DoubleWord {
        let (bh, bl) = if negate {
            (-other.hi, -other.lo)
        } else {
            (other.hi, other.lo)
        };
        let (s, t) = two_sum(self.hi, bh);
        let w = self.lo + bl;
        let z = t + w;
        let (hi, lo) = two_sum(s, z);
        let new = mul_term(U, w.abs() + z.abs());
        DoubleWord {
            hi,
            lo,
            e: widen((self.e + other.e) + new),
        }
    }

    /// `self / other`, or `None` if `other` is not certainly non-zero or a component is not
    /// finite.
    pub(super) fn div(&self, other: &DoubleWord) -> Option<DoubleWord> {
        let finite = [self.hi, self.lo, self.e, other.hi, other.lo, other.e]
            .iter()
            .all(|x| x.is_finite());
        if !finite {
            return None;
        }
        let (bh, bl) = (other.hi, other.lo);
        let b_low = sub_down_positive(bh.abs(), bl.abs())?;
        let den = sub_down_positive(b_low, other.e)?;
        let q1 = self.hi / bh;
        let (p, p_err) = two_product(q1, bh);
        let r1 = self.hi - p;
        let r2 = r1 - p_err;
        let m = q1 * bl;
        let r3 = self.lo - m;
        let r = r2 + r3;
        let q2 = r / bh;
        let (hi, lo) = two_sum(q1, q2);
        let intermediates = ((r1.abs() + r2.abs()) + (m.abs() + r3.abs())) + r.abs();
        let eps_r = mul_term(U, intermediates) + 2.0 * ETA;
        let through_bh = div_term(eps_r, bh.abs());
        let through_bl = div_term(
            div_term(mul_term(r.abs() + eps_r, bl.abs()), bh.abs()),
            b_low,
        );
        let eps_q = ((mul_term(U, q2.abs()) + ETA) + through_bh) + through_bl;
        let quotient_bound = (hi.abs() + lo.abs()) + eps_q;
        let propagated = div_term(self.e + mul_term(quotient_bound, other.e), den);
        let e = widen(eps_q + propagated);
        (hi.is_finite() && lo.is_finite() && e.is_finite()).then_some(DoubleWord { hi, lo, e })
    }

    /// `t0 + self` rounded to one `f64`, and a bound of its distance from the exact value.
    #[inline]
    fn plus_input(&self, t0: f64) -> (f64, f64) {
        let (s, t) = two_sum(t0, self.hi);
        let w = t + self.lo;
        let o = s + w;
        (o, widen(self.e + mul_term(U, w.abs() + o.abs())))
    }
}

impl Arith for DoubleWord {
    #[inline(always)]
    fn add(&self, other: &Self) -> Self {
        self.add_signed(other, false)
    }

    #[inline(always)]
    fn sub(&self, other: &Self) -> Self {
        self.add_signed(other, true)
    }

    #[inline(always)]
    fn mul(&self, other: &Self) -> Self {
        let (p, q) = two_product(self.hi, other.hi);
        let m1 = self.hi * other.lo;
        let m2 = self.lo * other.hi;
        let w = m1 + m2;
        let z = q + w;
        let (hi, lo) = two_sum(p, z);
        let sums = (m1.abs() + m2.abs()) + (w.abs() + z.abs());
        let new = (mul_term(U, sums) + 3.0 * ETA) + mul_term(self.lo.abs(), other.lo.abs());
        let propagated = (mul_term(self.magnitude(), other.e)
            + mul_term(other.magnitude(), self.e))
            + mul_term(self.e, other.e);
        DoubleWord {
            hi,
            lo,
            e: widen(propagated + new),
        }
    }

    /// Two exact inputs: their difference is exact (T1).
    #[inline(always)]
    fn leaf_sub(&self, other: &Self) -> Self {
        let exact_inputs = self.lo == 0.0 && other.lo == 0.0 && self.e == 0.0 && other.e == 0.0;
        if !exact_inputs {
            return self.sub(other);
        }
        let (hi, lo) = two_sum(self.hi, -other.hi);
        DoubleWord { hi, lo, e: 0.0 }
    }

    #[inline(always)]
    fn twice(&self) -> Self {
        DoubleWord {
            hi: 2.0 * self.hi,
            lo: 2.0 * self.lo,
            e: 2.0 * self.e,
        }
    }

    fn sign(&self) -> Option<Sign> {
        // |fl(hi + lo) − (hi + lo)| ≤ u·|fl(hi + lo)| (R1).
        let value = self.hi + self.lo;
        let margin = widen(self.e + mul_term(U, value.abs()));
        (value.is_finite() && value.abs() > margin).then(|| Sign::of_f64(value))
    }
}

/// A point's exact coordinates as double words. Written out: `array::map` here was left as
/// calls to `try_map` (see ARCHITECTURE.md, "Inlining in the kernel").
#[inline(always)]
fn words(p: [f64; 2]) -> [DoubleWord; 2] {
    [DoubleWord::from_f64(p[0]), DoubleWord::from_f64(p[1])]
}

/// The circumcenter of `t` in double-word arithmetic, if its proven error is within 256
/// units in the last place of its larger coordinate magnitude (module docs).
pub(super) fn circumcenter(t: &[[f64; 2]; 3]) -> Option<[f64; 2]> {
    let Circ { d, ux, uy } = circ(&[words(t[0]), words(t[1]), words(t[2])]);
    let (x, ex) = ux.div(&d)?.plus_input(t[0][0]);
    let (y, ey) = uy.div(&d)?.plus_input(t[0][1]);
    within_promise((x, ex), (y, ey))
}

/// The sign of the in-circle determinant of `a, b, c, d` (positive iff `d` is inside the
/// circle through the counterclockwise `a, b, c`) if the double-word value's bound decides
/// it: for any finite input, since the bound holds for every finite result and a non-finite
/// one decides nothing.
///
/// The stage between the `f64` filters and the adaptive expansions. Dense random samples of
/// a smooth curve put four nearby samples within about `κ'·h²` (relative) of a common
/// circle, `h` their spacing: at 10^8 samples of a star that is within a few `u` of the
/// filters' bounds, and the expansions' stage had become an eighth of the triangulation.
/// Here the error is of the order `u²` of the permanent, so only determinants that are zero
/// or within about `2^-100` of it go further.
pub(super) fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Option<Sign> {
    let [det] = incircle_terms_points(&words(a), &words(b), &words(c), &words(d));
    det.sign()
}

/// `[x, y]` if both are finite, their larger magnitude `N` is normal and both error bounds are
/// at most `256·ulp(N)`: the promise of `predicates::circumcenter`.
pub(super) fn within_promise((x, ex): (f64, f64), (y, ey): (f64, f64)) -> Option<[f64; 2]> {
    let norm = x.abs().max(y.abs());
    if !(x.is_finite() && y.is_finite() && norm.is_normal()) {
        return None;
    }
    let tolerance = TOLERANCE * f64::from_bits(norm.to_bits() & EXPONENT_MASK);
    (ex <= tolerance && ey <= tolerance).then_some([x, y]) // false for NaN
}

#[cfg(test)]
mod tests;
