//! Stage 1: a semi-static floating-point filter (plain `f64`, no branches inside the
//! polynomial, ~20–100 flops per call).
//!
//! Each polynomial of [`super::poly`] is evaluated in `f64` on the type [`Sf`], which carries
//! beside each value `v̂` the same expression evaluated on absolute values, `Â` (the
//! "permanent": leaves `|δ̂|`, every `−` replaced by `+`). The sign of `v̂` is certified when
//!
//! ```text
//! m̂ ≤ 2^H   and   |v̂| > fl(fl(c1·Â) + c0),     c1 = (K + 1)·u,
//! ```
//!
//! where `m̂` is the largest computed leaf `|δ̂|`, `K` the depth of the expression and `c0` an
//! absolute term covering underflow; `K`, the degree `D`, the underflow weight `W` and `c0`
//! are listed per expression below and re-derived mechanically from the very code that is
//! evaluated by a unit test (`filter_constants_match_the_expressions`).
//!
//! # The bound (a proof)
//!
//! Notation: `u = 2^-53` (unit roundoff), `λ = 2^-1022` (smallest normal), `η = u·λ = 2^-1075`,
//! `γ_k = k·u / (1 − k·u)`. Round to nearest, no fused multiply-add (Rust never contracts).
//!
//! **Model.** For `f64` operands and a result that does not overflow:
//! `fl(a ± b) = (a ± b)(1 + ε)`, `|ε| ≤ u` (also for subnormal results, which are exact since
//! both operands are multiples of `2^-1074`); `fl(a·b) = a·b·(1 + ε) + η'`, `|ε| ≤ u`,
//! `|η'| ≤ η` (`η' ≠ 0` only if `|a·b| < λ`).
//!
//! **Expressions.** The leaves are differences `δ = x − y` of two input coordinates, computed
//! as `δ̂ = fl(x − y) = δ(1 + ε)`; inner nodes are `+`, `−`, `·` (doubling counts as `+`).
//! For a node `n` define: the depth `k(n)` (leaf 1; `x ± y`: `1 + max(k(x), k(y))`;
//! `x·y`: `1 + k(x) + k(y)`), the degree `d(n)` (leaf 1; `±`: max; `·`: sum), the permanent
//! `Π(n)` (leaf `|δ|`; `±`: `Π(x) + Π(y)`; `·`: `Π(x)·Π(y)`), and the underflow part `Λ(n)`
//! of the floored permanent `Π' = Π + Λ` (leaf 0; `±`: `Λ(x) + Λ(y)`;
//! `·`: `Π'(x)·Π'(y) + λ − Π(x)·Π(y)`).
//!
//! **Lemma 1.** Without overflow, `|n̂ − n| ≤ γ_k(n) · Π'(n)`.
//! *Proof.* Expand `n` into signed monomials of leaves and `Π'(n)` into the same monomials
//! plus "λ-monomials". By induction, `n̂ = Σ s_j μ_j (1 + θ_j) + Σ ν_l φ_l` over the monomials
//! `μ_j` of `n` and the λ-monomials `ν_l`, with `|θ_j|, |φ_l| ≤ γ_k(n)`: a leaf has `θ = ε`;
//! `x ± y` multiplies every factor by one `(1 + ε)` and `(1 + γ_a)(1 + u) ≤ 1 + γ_(a+1)`;
//! `x·y` multiplies the expansions and one `(1 + ε)`, with `(1 + θ)(1 + θ')(1 + ε)` within
//! `γ_(a+b+1)` of 1 and `φ(1 + θ')(1 + ε)`, `φφ'(1 + ε)` within `γ_(a+b+1)` of 0 (Higham,
//! *Accuracy and Stability*, Lemma 3.3), and its `η'` is a new λ-monomial `λ` with
//! `φ = η'/λ`, `|φ| ≤ u`. Then `|n̂ − n| ≤ γ_k (Σ|μ_j| + Σ ν_l) = γ_k Π'(n)`. ∎
//!
//! **Lemma 2 (the underflow part).** Let every leaf satisfy `|δ| ≤ m*` with `m* ≥ 1`. Then
//! `Λ(n) ≤ λ·W(n)·m*^(d(n) − 2)`, where `W` is computed like `Λ` with every leaf and `λ` set
//! to 1: leaf 0; `±`: `W(x) + W(y)`; `·`: `W(x)·P(y) + P(x)·W(y) + W(x)·W(y) + 1` with
//! `P(n) = Π(n)` at all leaves 1. *Proof:* induction; `Π(x) ≤ P(x)·m*^d(x)`, `λ ≤ 1 ≤ m*`,
//! and `d ≥ 2` for every node above a product. ∎
//!
//! **The computed permanent.** The filter computes `Â` on the leaves `|δ̂|` (exact inputs,
//! so its depth is `K − 1`). Lemma 1 on that tree, whose monomials are all positive, gives
//! `Â ≥ (1 − γ_(K−1))·Π(|δ̂|) − γ_(K−1)·Λ(|δ̂|)`, and `|δ| ≤ |δ̂| / (1 − u)` gives
//! `Π(|δ|) ≤ (1 − u)^-D·Π(|δ̂|)` for a polynomial of degree `D`.
//!
//! **Theorem.** Let `m̂ = max |δ̂| ≤ 2^H` (`H ≥ 0`), `K` the depth, `D` the degree and `W` the
//! weight of the root. If `c1 = (K + 1)·u` and `c0 ≥ η·(1 + 3(K + 1)·W·2^(H(D − 2)))`, then
//! `|v̂ − v| ≤ fl(fl(c1·Â) + c0)`, so `|v̂| > fl(fl(c1·Â) + c0)` implies `sign v = sign v̂`.
//! *Proof.* All leaves (exact and computed) are at most `m* = 2^H/(1 − u)`. By Lemmas 1–2
//! and the bound on `Â`, `|v̂ − v| ≤ α·Â + 2γ_K·λ·W·m*^(D−2)/(1 − u)` with
//! `α = γ_K (1 − u)^-D / (1 − γ_(K−1)) ≤ K·u·(1 + (2K + D + 1)·u)`. The threshold is
//! computed as `fl(fl(c1·Â) + c0) ≥ (1 − u)²·c1·Â + (1 − u)(c0 − η)` (an underflowing
//! product loses at most `η`; the sum of non-negatives only `(1 − u)`), and
//! `(1 − u)²(K + 1)·u ≥ α` for `K < 2^20`, while `(1 − u)(c0 − η) ≥ 3(K + 1)·u·λ·W·2^(H(D−2))
//! ·(1 − u) ≥ 2γ_K·λ·W·m*^(D−2)/(1 − u)` since `(1 − u)^-(D−2)` and `γ_K/(K·u)` are below
//! `1.001`. ∎
//!
//! **Overflow.** With `m̂ ≤ 2^H` every computed node satisfies `|n̂| ≤ Â_n` (rounding is
//! monotonic) and `Â_n ≤ (1 + γ_K)·(P(n) + W(n))·2^(H·d(n))`, below `2^1000` for the `H`
//! chosen here; the test checks it. No overflow, so the model applies everywhere. A NaN or
//! infinite input makes `m̂` or `v̂` NaN or infinite and every comparison false: undecided.
//!
//! **The leaves.** The error of the initial differences is the leaf factor `(1 + ε)` above:
//! inputs far from the origin with small differences lose nothing but that one rounding,
//! and the bound is relative to the differences, not to the coordinates.
//!
//! # The constants
//!
//! | expression                              | K  | D  | W    | H  | c1    | c0        |
//! |-----------------------------------------|----|----|------|----|-------|-----------|
//! | orientation `bx·cy − by·cx`             | 4  | 2  | 2    | 64 | 5u    | 2^-1070   |
//! | `d = 2 (bx·cy − by·cx)`                 | 5  | 2  | 4    | 64 | 6u    | 2^-1068   |
//! | orient: `(b − a) × (d·(t0 − a) + u)`    | 11 | 4  | 24   | 64 | 12u   | 2^-930    |
//! | dot, `p` a vertex of both: `u_s · u_o`  | 16 | 6  | 170  | 64 | 17u   | 2^-800    |
//! | dot, general: `n_s · n_o`               | 18 | 6  | 596  | 64 | 19u   | 2^-800    |
//! | radius: `n1·x2² − n2·x1²`               | 25 | 10 | 2284 | 48 | 26u   | 2^-670    |
//! | circumcenter numerator `ux`, `uy`       | 7  | 3  | 6    | 64 | 8u    | 2^-1000   |
//! | NN-crust distance `(a − b)·(a−p + b−p)` | 5  | 2  | 2    | 64 | 6u    | 2^-1069   |
//! | NN-crust dot `(s − p)·(q − p)`          | 4  | 2  | 2    | 64 | 5u    | 2^-1070   |
//!
//! Inputs whose leaves exceed `2^H`, or are so small that the values sink towards `c0`, are
//! rescaled by a power of two (exactly, which leaves every sign unchanged) and filtered again
//! by the caller; only then do they go to the slower stages.

use super::arith::{Arith, U};
use super::poly::{
    circ, distance_terms, dot_points_terms, dot_terms, dot_terms_at_vertex, orient_from_circ,
    orient_from_offset, radius_terms, scaled_offset, Circ,
};
use super::Sign;

/// A value and its permanent, evaluated side by side in `f64`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Sf {
    /// The value `v̂`.
    pub(super) v: f64,
    /// The permanent `Â ≥ |v̂|`.
    pub(super) a: f64,
}

impl Sf {
    /// An input coordinate (used only through differences).
    #[inline(always)]
    pub(super) fn input(x: f64) -> Sf {
        Sf { v: x, a: x.abs() }
    }
}

impl Arith for Sf {
    #[inline(always)]
    fn add(&self, other: &Self) -> Self {
        Sf {
            v: self.v + other.v,
            a: self.a + other.a,
        }
    }

    #[inline(always)]
    fn sub(&self, other: &Self) -> Self {
        Sf {
            v: self.v - other.v,
            a: self.a + other.a,
        }
    }

    #[inline(always)]
    fn mul(&self, other: &Self) -> Self {
        Sf {
            v: self.v * other.v,
            a: self.a * other.a,
        }
    }

    #[inline(always)]
    fn leaf_sub(&self, other: &Self) -> Self {
        let v = self.v - other.v;
        Sf { v, a: v.abs() }
    }

    fn sign(&self) -> Option<Sign> {
        None // certified only against a term's constants, by `Term::sure`
    }
}

/// The filter constants of one expression (see the table in the module docs); the fields
/// besides `c1` and `c0` document them and are checked by the tests.
#[derive(Debug, Clone, Copy)]
#[cfg_attr(not(test), allow(dead_code))]
pub(super) struct Term {
    /// Depth `K` of the expression.
    pub(super) depth: u32,
    /// Degree `D` in the leaves.
    pub(super) degree: u32,
    /// Underflow weight `W` (Lemma 2).
    pub(super) weight: f64,
    /// `log2` of the largest leaf magnitude the constants allow.
    pub(super) h: i32,
    /// `(K + 1)·u`.
    pub(super) c1: f64,
    /// The absolute term.
    pub(super) c0: f64,
}

impl Term {
    /// Whether the sign of `x.v` is certified (false for NaN and infinities).
    #[inline(always)]
    fn sure(&self, x: Sf) -> bool {
        x.v.abs() > self.c1 * x.a + self.c0
    }
}

pub(super) const ORIENTATION: Term = Term {
    depth: 4,
    degree: 2,
    weight: 2.0,
    h: 64,
    c1: 5.0 * U,
    c0: 8e-323, // 2^-1070
};
pub(super) const D: Term = Term {
    depth: 5,
    degree: 2,
    weight: 4.0,
    h: 64,
    c1: 6.0 * U,
    c0: 3.16e-322, // 2^-1068
};
pub(super) const ORIENT: Term = Term {
    depth: 11,
    degree: 4,
    weight: 24.0,
    h: 64,
    c1: 12.0 * U,
    c0: 1.101803207925311e-280, // 2^-930
};
pub(super) const DOT_AT_VERTEX: Term = Term {
    depth: 16,
    degree: 6,
    weight: 170.0,
    h: 64,
    c1: 17.0 * U,
    c0: 1.499696813895631e-241, // 2^-800
};
pub(super) const DOT: Term = Term {
    depth: 18,
    degree: 6,
    weight: 596.0,
    h: 64,
    c1: 19.0 * U,
    c0: 1.499696813895631e-241, // 2^-800
};
pub(super) const RADIUS: Term = Term {
    depth: 25,
    degree: 10,
    weight: 2284.0,
    h: 48,
    c1: 26.0 * U,
    c0: 2.041281525984782e-202, // 2^-670
};
/// `(a − b)·((a − p) + (b − p))`, the NN-crust's distance comparison. (Its dot product
/// `(s − p)·(q − p)` has the shape, and so the constants, of [`ORIENTATION`].)
pub(super) const DISTANCE: Term = Term {
    depth: 5,
    degree: 2,
    weight: 2.0,
    h: 64,
    c1: 6.0 * U,
    c0: 1.6e-322, // 2^-1069
};
pub(super) const CIRC_U: Term = Term {
    depth: 7,
    degree: 3,
    weight: 6.0,
    h: 64,
    c1: 8.0 * U,
    c0: 9.332636185032189e-302, // 2^-1000
};

/// `2^64`: the leaf limit of the degree-2 to degree-6 expressions.
pub(super) const LEAF_MAX: f64 = 18446744073709551616.0;
/// `2^48`: the leaf limit of the radius comparison.
pub(super) const LEAF_MAX_RADIUS: f64 = 281474976710656.0;

/// `(lo, hi)`: when the filter fails on points whose spread (largest coordinate difference
/// from the first point) lies outside `[2^lo, 2^(hi − 1))`, the caller scales them by a
/// power of two to a spread in `[1, 2)` and filters again.
pub(super) const LEAF_RANGE: (i32, i32) = (-64, 64);
/// The same for the radius comparison.
pub(super) const LEAF_RANGE_RADIUS: (i32, i32) = (-48, 48);

#[inline(always)]
fn max(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

/// The largest `|t_i − t_0|` coordinate (the leaves of [`circ`]). A NaN may be dropped; the
/// callers' polynomials then are NaN themselves.
#[inline(always)]
fn spread3(t: &[[f64; 2]; 3]) -> f64 {
    let b = max((t[1][0] - t[0][0]).abs(), (t[1][1] - t[0][1]).abs());
    let c = max((t[2][0] - t[0][0]).abs(), (t[2][1] - t[0][1]).abs());
    max(b, c)
}

#[inline(always)]
fn spread2(p: [f64; 2], q: [f64; 2]) -> f64 {
    max((p[0] - q[0]).abs(), (p[1] - q[1]).abs())
}

/// Written out rather than with `array::map`, which the compiler sometimes leaves as a call
/// to `try_map` depending on how the crate is split into codegen units (three calls per
/// circumcenter and two per side test made the labels 0.3 s slower at 10^7 points).
#[inline(always)]
fn lift(t: &[[f64; 2]; 3]) -> [[Sf; 2]; 3] {
    [input(&t[0]), input(&t[1]), input(&t[2])]
}

/// A point in filter values (written out: see [`lift`]).
#[inline(always)]
fn input(p: &[f64; 2]) -> [Sf; 2] {
    [Sf::input(p[0]), Sf::input(p[1])]
}

/// The circumcenter of one triangle in filter values, for repeated orientation tests.
pub(super) struct CircFilter {
    t0: [f64; 2],
    c: Circ<Sf>,
    /// Largest leaf of the triangle.
    spread: f64,
    /// Whether the sign of `d` is certified.
    d_sure: bool,
    /// The last line origin `a` (NaN initially), `d·(O − a)` and the largest leaf so far.
    a: [f64; 2],
    n: [Sf; 2],
    spread_a: f64,
}

impl CircFilter {
    #[inline]
    pub(super) fn new(t: &[[f64; 2]; 3]) -> CircFilter {
        let c = circ(&lift(t));
        let zero = Sf { v: 0.0, a: 0.0 };
        CircFilter {
            t0: t[0],
            d_sure: D.sure(c.d),
            c,
            spread: spread3(t),
            a: [f64::NAN; 2],
            n: [zero; 2],
            spread_a: f64::NAN,
        }
    }

    /// The sign of the orientation of `(a, b, O)`, if certified. Consecutive calls with the
    /// same `a` (the fan of a hull search) share `d·(O − a)`: the same operations as
    /// [`orient_from_circ`], so the same bound.
    #[inline]
    pub(super) fn orient(&mut self, a: [f64; 2], b: [f64; 2]) -> Option<Sign> {
        let a2 = input(&a);
        if (a[0] != self.a[0]) | (a[1] != self.a[1]) {
            self.a = a;
            self.n = scaled_offset(&self.c, &input(&self.t0), &a2);
            self.spread_a = max(self.spread, spread2(self.t0, a));
        }
        let spread = max(self.spread_a, spread2(b, a));
        let v = orient_from_offset(&self.n, &a2, &input(&b));
        let sure = self.d_sure & (spread <= LEAF_MAX) & ORIENT.sure(v);
        sure.then(|| Sign::of_nonzero((v.v < 0.0) ^ (self.c.d.v < 0.0)))
    }
}

/// The sign of the orientation of `(a, b, O(tri))`, if certified.
#[inline]
pub(super) fn orient(a: [f64; 2], b: [f64; 2], tri: &[[f64; 2]; 3]) -> Option<Sign> {
    let spread = max(max(spread3(tri), spread2(tri[0], a)), spread2(b, a));
    let c = circ(&lift(tri));
    let v = orient_from_circ(&c, &input(&tri[0]), &input(&a), &input(&b));
    let sure = (spread <= LEAF_MAX) & D.sure(c.d) & ORIENT.sure(v);
    sure.then(|| Sign::of_nonzero((v.v < 0.0) ^ (c.d.v < 0.0)))
}

/// The sign of `(O_o − p)·(O_s − p)`, if certified; `s` and `o` have `p` first when it is a
/// vertex of theirs.
#[inline]
pub(super) fn dot(p: [f64; 2], s: &[[f64; 2]; 3], o: &[[f64; 2]; 3]) -> Option<Sign> {
    let at_vertex = (s[0][0] == p[0]) & (s[0][1] == p[1]) & (o[0][0] == p[0]) & (o[0][1] == p[1]);
    let spread = max(spread3(s), spread3(o));
    let [xs, xo, v] = if at_vertex {
        let [xs, xo, v] = dot_terms_at_vertex(&lift(s), &lift(o));
        let sure = (spread <= LEAF_MAX)
            & DOT_AT_VERTEX.sure(v)
            & ORIENTATION.sure(xs)
            & ORIENTATION.sure(xo);
        if !sure {
            return None;
        }
        [xs, xo, v]
    } else {
        let spread = max(max(spread, spread2(s[0], p)), spread2(o[0], p));
        let [ds, d_o, v] = dot_terms(&[Sf::input(p[0]), Sf::input(p[1])], &lift(s), &lift(o));
        let sure = (spread <= LEAF_MAX) & DOT.sure(v) & D.sure(ds) & D.sure(d_o);
        if !sure {
            return None;
        }
        [ds, d_o, v]
    };
    Some(Sign::of_nonzero((v.v < 0.0) ^ (xs.v < 0.0) ^ (xo.v < 0.0)))
}

/// The sign of `R1 − R2`, if certified.
#[inline]
pub(super) fn radius(t1: &[[f64; 2]; 3], t2: &[[f64; 2]; 3]) -> Option<Sign> {
    let third = |t: &[[f64; 2]; 3]| spread2(t[2], t[1]);
    let spread = max(max(spread3(t1), spread3(t2)), max(third(t1), third(t2)));
    let [v] = radius_terms(&lift(t1), &lift(t2));
    let sure = (spread <= LEAF_MAX_RADIUS) & RADIUS.sure(v);
    sure.then(|| Sign::of_nonzero(v.v < 0.0))
}

/// The sign of `|p − a|² − |p − b|²`, if certified.
#[inline]
pub(super) fn distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> Option<Sign> {
    let spread = max(max(spread2(a, b), spread2(a, p)), spread2(b, p));
    let [v] = distance_terms(&input(&p), &input(&a), &input(&b));
    let sure = (spread <= LEAF_MAX) & DISTANCE.sure(v);
    sure.then(|| Sign::of_nonzero(v.v < 0.0))
}

/// The sign of `(s − p)·(q − p)`, if certified.
#[inline]
pub(super) fn dot_points(p: [f64; 2], s: [f64; 2], q: [f64; 2]) -> Option<Sign> {
    let spread = max(spread2(s, p), spread2(q, p));
    let [v] = dot_points_terms(&input(&p), &input(&s), &input(&q));
    let sure = (spread <= LEAF_MAX) & ORIENTATION.sure(v);
    sure.then(|| Sign::of_nonzero(v.v < 0.0))
}

/// `2^-20`: the largest relative uncertainty of the denominator `d` accepted.
const RHO_MAX: f64 = 9.5367431640625e-7;
/// `2^-900`: below this circumcenter magnitude the absolute underflow terms are not
/// negligible; such circumcenters take the slower stages.
const NORM_MIN: f64 = 1.1830521861667747e-271;
/// `2^-44·(1 − 2^-12)`: the accepted bound relative to the larger output coordinate
/// rounded down to a power of two (256 ulps of it, with a margin).
const TAU: f64 = 5.68295410730002e-14;
/// The exponent bits of an `f64`.
const EXPONENT_MASK: u64 = 0x7ff0_0000_0000_0000;

/// The circumcenter of `t` in `f64` if its proven error is below 256 units in the last place
/// of its larger coordinate magnitude `N`, in each coordinate.
///
/// With `d̂`, `û` from [`circ`] and their error bounds `E_d = fl(6u·D̂ + c0_d)`,
/// `E_u = fl(8u·Û + c0_u)` (the theorem above, `d` and `u` rows of the table), the output
/// is `ô = fl(t0 + fl(û/d̂))`. Write `q = u/d`, `s = fl(1/|d̂|)`, `ρ = E_d/|d̂|`. Then
/// `|û/d̂ − q| = |−(û/d̂)(d̂ − d) + (û − u)|/|d| ≤ (|û/d̂|·ρ + E_u/|d̂|)/(1 − ρ)`, as `d̂ − d`
/// and `û − u` are within `E_d`, `E_u` and `|d| ≥ |d̂|(1 − ρ)`; the rounding of `fl(û/d̂)`
/// adds `u·|û/d̂| + η`, the final sum `u·|ô|/(1 − u)`. With `1/|d̂| ≤ s/(1 − u)`,
/// `ρ ≤ (fl(E_d·s) + η)/(1 − u)²` and `|û/d̂| ≤ (|q̂| + η)/(1 − u)`, requiring
/// `ρ̂ = fl(E_d·s) ≤ 2^-20` gives, per coordinate,
/// `|ô − O| ≤ uN/(1 − u) + η + |û/d̂|·(u + ρ/(1 − ρ)) + E_u/(|d̂|(1 − ρ))
/// ≤ (1 + 2^-14)·B + 8η` with `B = u·N + (3u + ρ̂)·Q + E·s` computed in `f64` (`Q`, `E`: the
/// larger of the two `|q̂|` and `E_u`): the roundings of `B` (`u·N` is exact), the `(1 − u)`
/// and `(1 − ρ)` factors fit in the `2^-14`, the `η` terms multiplying `Q` in the spare
/// `2u·Q` (an `η·Q` is below `2^-1000·u·Q`), the other `η` terms and underflows of `B`'s
/// products in the `8η`. Accepting `B ≤ fl(TAU·P)`, where `P ≤ N < 2P` is a power of two
/// (so `TAU·P` is exact and `256·ulp(N) = 2^-44·P`), with `N ≥ 2^-900` finite, then gives
/// `|ô − O| ≤ 2^-44·P·(1 − 2^-12)(1 + 2^-14) + 8η < 2^-44·P = 256·ulp(N)`.
#[inline]
pub(super) fn circumcenter(t: &[[f64; 2]; 3]) -> Option<[f64; 2]> {
    let spread = spread3(t);
    let c = circ(&lift(t));
    let ed = D.c1 * c.d.a + D.c0;
    let eux = CIRC_U.c1 * c.ux.a + CIRC_U.c0;
    let euy = CIRC_U.c1 * c.uy.a + CIRC_U.c0;
    // Quotients rather than products with `1/d̂`: exact whenever the quotient is
    // representable (right triangles give the exact midpoint of the hypotenuse).
    let (qx, qy) = (c.ux.v / c.d.v, c.uy.v / c.d.v);
    let (ox, oy) = (t[0][0] + qx, t[0][1] + qy);
    let s = 1.0 / c.d.v.abs();
    let n = max(ox.abs(), oy.abs());
    let q = max(qx.abs(), qy.abs());
    let e = max(eux, euy);
    let rho = ed * s;
    let b = U * n + q * (3.0 * U + rho) + e * s;
    let p = f64::from_bits(n.to_bits() & EXPONENT_MASK);
    let sure = (spread <= LEAF_MAX)
        & ox.is_finite()
        & oy.is_finite()
        & (rho <= RHO_MAX)
        & (n >= NORM_MIN)
        & (b <= TAU * p);
    sure.then_some([ox, oy])
}
