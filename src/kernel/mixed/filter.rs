//! The first stage of the mixed predicates: a semi-static filter for points known only
//! within a radius (plain `f64`, ~3 × 25 flops for an in-circle test).
//!
//! A point is a centre `(x̂, ŷ)` in `f64` and a radius per coordinate: the exact point lies
//! within `r_x` of `x̂` and `r_y` of `ŷ` (a sample: radii 0; a circumcenter: the bound of its
//! running-error or correctly rounded coordinates). A polynomial of [`super::super::poly`]
//! is evaluated on the type [`Sr`], which carries three lanes: the value `v̂` at the computed
//! leaves, the permanent `Â` at the computed leaves and the permanent `B̂` at upper bounds of
//! the exact leaves. The sign of `v̂` is the sign of the exact value when
//!
//! ```text
//! β̂ ≤ 2^H for every leaf   and   |v̂| > fl(fl(fl(B̂ − Â) + fl(c1·B̂)) + c0),   c1 = (4K + 8)·u.
//! ```
//!
//! # The bound (a proof)
//!
//! Notation and the Lemmas 1 and 2 are those of the semi-static filter (`kernel::filter`):
//! `u = 2^-53`, `λ = 2^-1022`, `η = u·λ`, `γ_k = k·u / (1 − k·u)`, depth `K`, degree `D`,
//! permanent `Π`, floored permanent `Π' = Π + Λ`, underflow weight `W`.
//!
//! **Leaves.** A leaf is the difference `δ = x − y` of two exact coordinates, computed as
//! `δ̂ = fl(x̂ − ŷ)`. Round to nearest gives `fl(s) = s / (1 + ε)`, `|ε| ≤ u` (Higham, (2.5);
//! a subnormal difference is exact), so `|δ − δ̂| ≤ r_x + r_y + u·|δ̂|`. The leaf bound
//! `β̂ = fl(fl(|δ̂| + fl(r_x + r_y))·(1 + 8u))` satisfies `β̂ ≥ |δ̂| + |δ − δ̂|`: if the sum
//! `t̂ = fl(|δ̂| + fl(r_x + r_y))` is subnormal, the subtraction and both sums were exact
//! and `β̂ ≥ t̂` (rounding is monotonic and `t̂` is a float); otherwise
//! `t̂ ≥ (1 − u)²·s` with `s = |δ̂| + r_x + r_y ≥ t̂/(1 + u)² ≥ λ/3`, and
//! `β̂ ≥ (1 − u)³(1 + 8u)·s − η ≥ (1 + 4u)·s − η ≥ s + u·|δ̂|` since `3u·s ≥ η`.
//!
//! **The value.** Write `P` for the polynomial, `δ̂` and `δ` for the vectors of leaves. The
//! lane `v̂` evaluates `P` on the floating-point numbers `δ̂` without rounding them again,
//! so Lemma 1 gives `|v̂ − P(δ̂)| ≤ γ_K·Π'(|δ̂|)`. Expanding each monomial,
//! `|Π(δ̂_i + ζ_i) − Π δ̂_i| ≤ Π(|δ̂_i| + |ζ_i|) − Π |δ̂_i|`, so
//! `|P(δ) − P(δ̂)| ≤ Π(β̂) − Π(|δ̂|)` (the permanent is increasing in every leaf).
//!
//! **The permanents.** `Â` and `B̂` evaluate the positive polynomial `Π` at `|δ̂|` and `β̂`.
//! Lemma 1 gives `Π(|δ̂|) ≥ (Â − γ_K·Λ_a) / (1 + γ_K)` and `Π(β̂) ≤ (B̂ + γ_K·Λ_b) / (1 − γ_K)`,
//! and `Â ≤ B̂` because rounding is monotonic and `|δ̂| ≤ β̂` leaf by leaf. Hence the error
//! `E = |v̂ − P(δ)| ≤ Π(β̂) − (1 − γ_K)·Π(|δ̂|) + γ_K·Λ_a ≤ (B̂ − Â) + 3.02·K·u·B̂ + Υ`,
//! using `(1 − γ)/(1 + γ) ≥ 1 − 2γ`, `γ/(1 − γ) + 2γ ≤ 3.01·γ_K ≤ 3.02·K·u` (`K < 2^20`), and
//! with the underflow part `Υ = γ_K·Λ_b/(1 − γ_K) + 2γ_K·Λ_a ≤ 3.02·K·W·η·2^(H(D − 2))` by
//! Lemma 2 (every leaf and leaf bound at most `2^H`).
//!
//! **Theorem.** If `c1 = (4K + 8)·u` and `c0 ≥ η·(2 + 7(K + 1)·W·2^(H(D − 2)))`, the threshold
//! `T̂ = fl(fl(fl(B̂ − Â) + fl(c1·B̂)) + c0)` is at least `E`. *Proof.* With `Δ = B̂ − Â ≥ 0`:
//! `fl(Δ) ≥ (1 − u)·Δ`, `fl(c1·B̂) ≥ (1 − u)·c1·B̂ − η`, and a sum of non-negatives loses at
//! most a factor `1 − u`, so `T̂ ≥ (1 − u)³·(Δ + c1·B̂) − η + (1 − u)·c0
//! ≥ Δ − 3u·B̂ + (1 − 3u)·c1·B̂ − η + (1 − u)·c0` (as `Δ ≤ B̂`), and
//! `(1 − 3u)·c1 − 3u ≥ 3.02·K·u`, `(1 − u)·c0 − η ≥ Υ`. ∎
//!
//! **Overflow.** Every node satisfies `|n̂| ≤ Â_n ≤ B̂_n`; an infinite node makes `B̂` (and so
//! `T̂`) infinite or NaN, and an infinite or NaN `v̂` or `T̂` never certifies. So a certified
//! sign comes from an evaluation without overflow, where the model above holds.
//!
//! # The constants
//!
//! | expression                           | K  | D | W  | H  | c1   | c0       |
//! |--------------------------------------|----|---|----|----|------|----------|
//! | orientation `(a − c) × (b − c)`      | 4  | 2 | 2  | 64 | 24u  | 2^-1060  |
//! | in-circle, rows translated to `d`    | 11 | 4 | 39 | 64 | 52u  | 2^-900   |
//!
//! A test recomputes `K`, `D` and `W` from the evaluated code and checks `c1` and `c0`.

use super::super::arith::{Arith, U};
use super::super::poly::{incircle_terms_points, orient_terms_points};
use super::super::Sign;

/// `1 + 8u`, the factor of the leaf bound.
const LEAF_FACTOR: f64 = 1.0 + 4.0 * f64::EPSILON;

/// A value of the filter: `v` at the computed leaves, `a` and `b` the permanents at the
/// computed leaves and at the leaf bounds, `m` the largest leaf bound below it. An input
/// coordinate (used only through differences) is its centre in `v` and its radius in `b`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sr {
    v: f64,
    a: f64,
    b: f64,
    m: f64,
}

impl Sr {
    /// An input coordinate with centre `x` and radius `r`.
    #[inline(always)]
    pub(super) fn input(x: f64, r: f64) -> Sr {
        Sr {
            v: x,
            a: 0.0,
            b: r,
            m: 0.0,
        }
    }
}

#[inline(always)]
fn max(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

impl Arith for Sr {
    #[inline(always)]
    fn add(&self, other: &Self) -> Self {
        Sr {
            v: self.v + other.v,
            a: self.a + other.a,
            b: self.b + other.b,
            m: max(self.m, other.m),
        }
    }

    #[inline(always)]
    fn sub(&self, other: &Self) -> Self {
        Sr {
            v: self.v - other.v,
            a: self.a + other.a,
            b: self.b + other.b,
            m: max(self.m, other.m),
        }
    }

    #[inline(always)]
    fn mul(&self, other: &Self) -> Self {
        Sr {
            v: self.v * other.v,
            a: self.a * other.a,
            b: self.b * other.b,
            m: max(self.m, other.m),
        }
    }

    #[inline(always)]
    fn leaf_sub(&self, other: &Self) -> Self {
        let v = self.v - other.v;
        let a = v.abs();
        let b = (a + (self.b + other.b)) * LEAF_FACTOR;
        Sr { v, a, b, m: b }
    }

    fn sign(&self) -> Option<Sign> {
        None // certified only against a term's constants, by `Term::decide`
    }
}

/// The constants of one expression (see the table in the module docs).
#[derive(Debug, Clone, Copy)]
#[cfg_attr(not(test), allow(dead_code))]
pub(in crate::kernel) struct Term {
    /// Depth `K` of the expression.
    pub(in crate::kernel) depth: u32,
    /// Degree `D` in the leaves.
    pub(in crate::kernel) degree: u32,
    /// Underflow weight `W`.
    pub(in crate::kernel) weight: f64,
    /// `log2` of the largest leaf bound allowed.
    pub(in crate::kernel) h: i32,
    /// `(4K + 8)·u`.
    pub(in crate::kernel) c1: f64,
    /// The absolute term.
    pub(in crate::kernel) c0: f64,
}

impl Term {
    /// The sign of `x`'s exact value, if certified.
    #[inline(always)]
    fn decide(&self, x: Sr) -> Option<Sign> {
        let threshold = ((x.b - x.a) + self.c1 * x.b) + self.c0;
        let sure = (x.m <= LEAF_MAX) & (x.v.abs() > threshold);
        sure.then(|| Sign::of_nonzero(x.v < 0.0))
    }
}

pub(in crate::kernel) const ORIENTATION: Term = Term {
    depth: 4,
    degree: 2,
    weight: 2.0,
    h: 64,
    c1: 24.0 * U,
    c0: 8.095e-320, // 2^-1060
};

pub(in crate::kernel) const INCIRCLE: Term = Term {
    depth: 11,
    degree: 4,
    weight: 39.0,
    h: 64,
    c1: 52.0 * U,
    c0: 1.1830521861667747e-271, // 2^-900
};

/// `2^64`: the largest leaf bound of both expressions.
pub(in crate::kernel) const LEAF_MAX: f64 = 18446744073709551616.0;

/// The orientation of `a → b → c`, if certified.
#[inline]
pub(super) fn orient(a: &[Sr; 2], b: &[Sr; 2], c: &[Sr; 2]) -> Option<Sign> {
    let [v] = orient_terms_points(a, b, c);
    ORIENTATION.decide(v)
}

/// Whether `d` is inside the circle through the counterclockwise `a, b, c`, if certified.
#[inline]
pub(super) fn incircle(a: &[Sr; 2], b: &[Sr; 2], c: &[Sr; 2], d: &[Sr; 2]) -> Option<Sign> {
    let [v] = incircle_terms_points(a, b, c, d);
    INCIRCLE.decide(v)
}
