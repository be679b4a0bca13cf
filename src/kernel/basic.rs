//! Orientation and in-circle tests of input points: the triangulation's inner loop.
//!
//! [`orient`] and [`incircle`] are Shewchuk's semi-static filters (his error bounds
//! `ccwerrboundA` and `iccerrboundA` for exactly this evaluation order, scaled by the
//! permanent of the evaluation) in front of the exact stages: the `robust` crate's adaptive
//! predicates, and for in-circle first the `i128` lattice evaluation (`super::lattice`).
//! Both are inlined into their callers, so that a comparison of the answer (`== Positive`)
//! folds into the filter's branches.
//!
//! Shewchuk's bounds assume that no product underflows. Inputs of any finite magnitude are
//! accepted here, so each bound carries an absolute term for underflow (below): with it a
//! filter never decides wrongly, and where it cannot decide the exact stage answers, by
//! `robust` inside its exact range and otherwise by `super::wide` (a power-of-two rescale
//! into that range, or integers). Overflow needs no term: it makes the value or the bound
//! infinite or NaN, and such a comparison fails, so the exact stage answers.
//!
//! # The underflow terms
//!
//! In the model of `super::filter` (`fl(x·y) = x·y·(1 + ε) + η'`, `|η'| ≤ η = 2^-1075`, sums
//! exact in the subnormal range), every rounding that Shewchuk's analysis accounts for is
//! relative, and each product adds an absolute `η'` that his bound does not cover. Carried
//! to the root (Lemma 1 there: `|v̂ − v| ≤ γ_K·(Π + Λ)`, `Λ` the sum of the `λ = 2^-1022`
//! monomials), it adds at most `γ_K·Λ`:
//!
//! * orientation, `K = 4`: two products, `Λ = 2λ`, so `γ_4·2λ < 9η`; the bound's own
//!   product may underflow by another `η`. So `10η` suffice.
//! * in-circle, `K = 11`: each of the six cross products `bdx·cdy, …` is multiplied by a
//!   lift (`λ·A`, with `A, B, C` the lifts `adx² + ady²`, …), each of the six squares by a
//!   cross difference, itself at most the sum of the other two lifts
//!   (`|bdx·cdy| ≤ (bdx² + cdy²)/2`), and the three top products add `λ` each:
//!   `Λ ≤ λ·(6·(A + B + C) + 4)` and `γ_11·Λ < (2^-1068·(A + B + C) + 2^-1069)`. The
//!   computed lifts are within a factor `1 + 4u` (plus underflows of `η`) of the exact ones,
//!   and the computation of the term itself may lose `η`s to underflow.
//!
//! The terms used are far larger than these, and normal numbers: arithmetic on subnormal
//! constants costs a microcode assist per operation on x86 (a 4× slower in-circle filter,
//! measured), and a larger term only makes the filter decline a little more often:
//! [`ORIENT_SLACK`] `= λ = 2^-1022` (`2^53·η`) for orientation, and for in-circle
//! [`INCIRCLE_SLACK`] `= 2^-960` per unit of the computed `A + B + C` plus `λ`. Both are far
//! below Shewchuk's relative bound (`≈ 10u` of the permanent) unless the determinant is
//! within `2^-900` of its permanent's scale or the permanent itself is near `2^-970`: such
//! tests are nearly degenerate and go to the exact stage anyway; ordinary input is decided
//! exactly as before. A product `S·2^-960` is subnormal only for lifts below `2^-62`
//! (coordinates differing by less than `2^-31`), where its cost is paid.
//!
//! # The orientation filter: a floored permanent
//!
//! [`orient`] tests `|det| > B̃ = fl(C′·max(Q̂, F))` with `Q̂ = |fl(l̂ + r̂)|` (`l̂, r̂` the
//! computed products `left`, `right`), `C′ = fl(C·(1 + 2^-10))` and the floor
//! `F = 2^-950` ([`ORIENT_PERMANENT_FLOOR`]): one sum, one `max` and one product, as many
//! operations as Shewchuk's filter (which adds `|l̂| + |r̂|`).
//!
//! * If `l̂` and `r̂` have strictly opposite signs (either may be infinite), the exact
//!   products do too: a difference of floats is rounded with its sign and is 0 only when
//!   exact, and a product keeps its sign unless it underflows to 0, which `l̂, r̂ ≠ 0` rules
//!   out. So the exact determinant `L − R` has the sign of `l̂`, and so has
//!   `det = fl(l̂ − r̂)` (a sum of two magnitudes of one sign): any passing test answers right.
//!   This is Shewchuk's own shortcut for opposite signs, here without a branch.
//! * Otherwise `Q̂ = fl(|l̂| + |r̂|) = P̂`, rounding being symmetric. Let `M = max(P̂, F)`;
//!   `C·M ≥ 2^-1002` is normal, so `B̃ ≥ C·M·(1 + 2^-10)(1 − u)²` and the proven test's
//!   `T = fl(fl(C·P̂) + λ) ≤ (1 + u)(C·M·(1 + u) + λ)`. Their difference is at least
//!   `C·M·2^-11 − (1 + u)·λ ≥ 0` because `M ≥ F ≥ 2^11·(1 + u)·λ/C` (`C > 2^-52`). So
//!   `|det| > B̃` implies `|det| > T`.
//!
//! Infinite or NaN values fail the comparison (`B̃ = ∞` when `P̂` is) except where the first
//! case answers; a NaN sum takes the floor. The floor declines only tests whose permanent is
//! below `2^-950`, coordinates differing by less than about `2^-475`, which the exact stage
//! then answers. Measured against the two-comparison form below (random points, a loop of
//! 1024 calls, the best of 400 timings): 1.38 against 1.49 ns per call; Shewchuk's filter
//! without any underflow term, 1.36 ns.
//!
//! # The in-circle filter: two stages
//!
//! [`incircle`] computes Shewchuk's determinant `det` as he does, and bounds its error first
//! by the **pair bound** `B₁ = fl(C′·fl(fl(B̃·C̃) + fl(Â·fl(B̃ + C̃))))`, with `Â, B̂, Ĉ` the
//! computed lifts, `B̃ = fl(B̂ + κ)`, `C̃ = fl(Ĉ + κ)`, `κ = 2^-475` ([`LIFT_FLOOR`]) and
//! `C′ = fl(C·(1 + 2^-10))`. It is computed from the lifts alone, beside the determinant
//! rather than after the six cross products, in half the operations of Shewchuk's permanent,
//! and it carries the underflow term (added to his bound, the term alone cost 0.45 ns of a
//! 4.5 ns test, measured). Where it declines, a **second stage** tests the floored permanent
//! (below) on the products already computed, and then the exact stage answers. On random
//! points (`examples/predicate_timing.rs`, the best of 400 timings) the whole test costs
//! 4.14 ns against 4.46 for Shewchuk's filter without any underflow term and 4.93 for the
//! separate comparison of the term it replaced; on the Delaunay tests of curve samples 4.25
//! against 4.45–4.49 and 5.02.
//!
//! *The pair bound is proven.* Let `A, B, C` be the exact lifts of the computed differences,
//! `Q = AB + BC + CA` and `S = A + B + C`. Each row of Shewchuk's permanent is at most
//! `(|bdx·cdy| + |cdx·bdy|)·A ≤ (B + C)/2·A` (`|xy| ≤ (x² + y²)/2`), so in the model above
//! `P̂ ≤ (1 + u)^7·Q + 7η·S + 4η`, and `Q ≤ (1 − u)^-4·Q(Â, B̂, Ĉ) + 5η·Ŝ + η` with `Ŝ` the sum
//! of the computed lifts. On the other side `B̃·C̃ ≥ κ²(1 − u)² ≥ 2^-951` is normal, so
//! `fl(…) ≥ (1 − u)^4·(Q(Â, B̂, Ĉ) + κ·(2Â + B̂ + Ĉ) + κ²) − η` and `B₁ ≥ C′(1 − u)` of
//! that. Matching the terms: the `Q` terms because `(1 + 2^-10)(1 − u)^10 > (1 + u)^7`; the
//! `S` terms because `C′·κ > 2^-525` is far above the `2^-1067` per unit of `Ŝ` that
//! `C·P̂` and the underflow term `2^-1068·S + 2^-1069` need; the constants because
//! `C′·κ² > 2^-1000`. So `B₁ ≥ C·P̂ + 2^-1068·S + 2^-1069`, and `|det| > B₁` decides
//! rightly.
//!
//! *What it costs.* `Q` is rotation-invariant and `P` is not: where `b, c, d` lie nearly on a
//! line (thin triangles, curve samples) `Q` can be many times `P`, and the pair bound declines
//! where Shewchuk's would not: on the locally-Delaunay tests of 2·10^5 samples of a
//! random-parameter star, 1.4 % against 0.5 % (measured). The second stage decides every
//! test that Shewchuk's bound with the underflow term decides, for the cost of the permanent;
//! on random points neither declines. And `κ` sends every test with a lift below about
//! `2^-475` (coordinates differing by less than `2^-237`) to the second stage, which
//! declines where the determinant is below about `2^-1000`.
//!
//! *The second stage* is Shewchuk's permanent with `κ₂ = 2^-900` ([`ROW_FLOOR`]) added to each
//! row's sum of cross products, floored at `F = 2^-950` ([`INCIRCLE_PERMANENT_FLOOR`]):
//! `B₂ = fl(C′·max(P̂_κ, F))`. Rounding is monotone, so `P̂_κ ≥ P̂`, and
//! `P̂_κ ≥ (1 − u)^5·κ₂·Ŝ − 3η`. With `M = max(P̂_κ, F)`, `B₂ ≥ C·M·(1 + 2^-11)`; `M` covers
//! `C·P̂`, and `C·M·2^-11 ≥ C·2^-12·(F + (1 − u)^5·κ₂·Ŝ − 3η)` covers the underflow term
//! (`C·2^-12·κ₂ > 2^-962`, `C·2^-12·F > 2^-1012`).
//!
//! *Overflow.* Where a bound is finite, every intermediate of it is, and so is `Q(Â, B̂, Ĉ)`
//! up to a factor `1 + 5u` of `f64::MAX`; the three terms of the determinant then sum in
//! magnitude to less than `f64::MAX·(1 + 11u)`, so an infinite `det` comes from one term or
//! partial sum that dominates the rest, and has the sign that unbounded-exponent arithmetic
//! gives, whose `|det|` exceeds the finite bound. An infinite bound, or NaN, fails both
//! comparisons.
//!
//! The forms `*_in` keep Shewchuk's bound with one comparison: with the underflow term added
//! for `false` (the static filter's fallback, and the benchmarks' baseline), without it for
//! `true` (below).
//!
//! Callers that know every coordinate to be zero or of an exponent in
//! `scale::ADAPTIVE_EXPONENTS` (the construction, on validated or rescaled input) use the
//! `*_in::<true>` forms, without the terms: there differences are 0 or in [2^-194, 2^202],
//! so products of up to four of them and their sums stay between 2^-776 and 2^812, no
//! product underflows and Shewchuk's bounds hold as they are.

use super::lattice::lattice_incircle;
use super::{double_word, wide, Sign};

/// 2^-53: half an ulp of 1.
const EPSILON: f64 = 1.0 / 9_007_199_254_740_992.0;
pub(super) const CCW_BOUND: f64 = (3.0 + 16.0 * EPSILON) * EPSILON;
pub(super) const INCIRCLE_BOUND: f64 = (10.0 + 96.0 * EPSILON) * EPSILON;
/// `2^-1022`, the smallest normal `f64`: the absolute underflow term of the orientation
/// bound, and the absolute part of the in-circle one (module docs).
pub(super) const ORIENT_SLACK: f64 = f64::MIN_POSITIVE;
/// `2^-960`: the underflow term of the in-circle bound per unit of the sum of the three
/// lifts (module docs).
pub(super) const INCIRCLE_SLACK: f64 = 1.0261342003245941e-289;
/// `1 + 2^-10`: the margin of the relative bounds whose underflow terms are covered by a
/// floor (module docs).
const WIDENING: f64 = 1.0 + 1.0 / 1024.0;
const CCW_BOUND_WIDENED: f64 = CCW_BOUND * WIDENING;
const INCIRCLE_BOUND_WIDENED: f64 = INCIRCLE_BOUND * WIDENING;
/// `2^-950`: the floor of the permanent in [`orient`]'s filter, large enough that its
/// relative margin covers the underflow term (module docs, "The orientation filter").
const ORIENT_PERMANENT_FLOOR: f64 = 1.0507614211323843e-286;
/// `2^-475`: added to two lifts in [`incircle`]'s pair bound (module docs, "The in-circle
/// filter").
const LIFT_FLOOR: f64 = 1.0250665447337477e-143;
/// `2^-900`: added to each row's sum of cross products in the second stage's permanent.
const ROW_FLOOR: f64 = 1.1830521861667747e-271;
/// `2^-950`: the floor of the second stage's permanent.
const INCIRCLE_PERMANENT_FLOOR: f64 = ORIENT_PERMANENT_FLOOR;

/// The sign of `det` where it exceeds `bound` (which no NaN does), else `exact()`: the
/// answers branched to straight from the comparisons (an `Option` between filter and exact
/// stage cost 0.2 ns a call in a loop, measured: the answer was then converted after a join).
#[inline(always)]
fn decide(det: f64, bound: f64, exact: impl FnOnce() -> Sign) -> Sign {
    if det > bound {
        Sign::Positive
    } else if -det > bound {
        Sign::Negative
    } else {
        exact()
    }
}

/// The sign of the orientation determinant of `a → b → c`: `Positive` iff `c` lies strictly
/// left of the directed line `a → b` (counterclockwise), `Zero` iff collinear. Any finite
/// input.
#[inline(always)]
pub(crate) fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    let (det, bound) = orient_floored_bound(a, b, c);
    decide(det, bound, || exact_orient::<false>(a, b, c))
}

/// The orientation determinant in floating point and its permanent `|left| + |right|`.
#[inline(always)]
fn orient_terms(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> (f64, f64) {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    (left - right, left.abs() + right.abs())
}

/// The orientation determinant and [`orient`]'s bound on it.
#[inline(always)]
fn orient_floored_bound(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> (f64, f64) {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    let det = left - right;
    let sum = (left + right).abs();
    // Written as a comparison so that it compiles to one `maxsd`; a NaN sum (opposite
    // infinities, or a NaN product whose `det` is NaN too) takes the floor.
    let floored = if sum > ORIENT_PERMANENT_FLOOR {
        sum
    } else {
        ORIENT_PERMANENT_FLOOR
    };
    (det, CCW_BOUND_WIDENED * floored)
}

/// [`orient`] with the underflow term added to the bound (the proven form, module docs);
/// with `IN_RANGE` the caller guarantees that every coordinate is zero or of an exponent in
/// the adaptive predicates' range (`scale::ADAPTIVE_EXPONENTS`), there is no underflow term,
/// and the exact stage goes to them without checking (the construction on such input, where
/// exact zeros are frequent).
#[inline(always)]
pub(crate) fn orient_in<const IN_RANGE: bool>(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    let (det, bound) = orient_with_bound::<IN_RANGE>(a, b, c);
    decide(det, bound, || exact_orient::<IN_RANGE>(a, b, c))
}

/// The orientation determinant and Shewchuk's bound, with the underflow term unless
/// `IN_RANGE` (in range, the envelope rules out harmful underflow: module docs).
#[inline(always)]
fn orient_with_bound<const IN_RANGE: bool>(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> (f64, f64) {
    let (det, permanent) = orient_terms(a, b, c);
    let slack = if IN_RANGE { 0.0 } else { ORIENT_SLACK };
    (det, CCW_BOUND * permanent + slack)
}

/// The exact stage of the orientation tests, on the points' coordinates.
#[inline(always)]
fn exact_orient<const IN_RANGE: bool>(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    exact_orient_coordinates::<IN_RANGE>(a[0], a[1], b[0], b[1], c[0], c[1])
}

/// Out of line, and taking six scalars rather than three arrays: the arrays would be passed
/// by reference, so the inlined filter would first store its points to the stack and the
/// exact stage load them back, a round trip on every call even though the filter nearly
/// always decides (0.45 ns of a 1.95 ns orientation test, measured); scalars travel in
/// registers.
#[inline(never)]
fn exact_orient_coordinates<const IN_RANGE: bool>(
    ax: f64,
    ay: f64,
    bx: f64,
    by: f64,
    cx: f64,
    cy: f64,
) -> Sign {
    let (a, b, c) = ([ax, ay], [bx, by], [cx, cy]);
    if IN_RANGE || wide::fits([ax, ay, bx, by, cx, cy]) {
        wide::adaptive_orient(a, b, c)
    } else {
        wide::orient(a, b, c)
    }
}

/// Shewchuk's floating-point in-circle determinant (his evaluation order, which his error
/// bound is for), the three rows of his permanent before their lifts (`|bdx·cdy| +
/// |cdx·bdy|`, …) and the three lifts. Callers take what they need; the rest is never
/// computed once inlined.
#[inline(always)]
fn incircle_terms(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> (f64, [f64; 3], [f64; 3]) {
    let adx = a[0] - d[0];
    let bdx = b[0] - d[0];
    let cdx = c[0] - d[0];
    let ady = a[1] - d[1];
    let bdy = b[1] - d[1];
    let cdy = c[1] - d[1];

    let bdxcdy = bdx * cdy;
    let cdxbdy = cdx * bdy;
    let alift = adx * adx + ady * ady;
    let cdxady = cdx * ady;
    let adxcdy = adx * cdy;
    let blift = bdx * bdx + bdy * bdy;
    let adxbdy = adx * bdy;
    let bdxady = bdx * ady;
    let clift = cdx * cdx + cdy * cdy;

    let det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    let rows = [
        bdxcdy.abs() + cdxbdy.abs(),
        cdxady.abs() + adxcdy.abs(),
        adxbdy.abs() + bdxady.abs(),
    ];
    (det, rows, [alift, blift, clift])
}

/// Shewchuk's permanent from [`incircle_terms`]' rows and lifts.
#[inline(always)]
fn permanent(rows: [f64; 3], lifts: [f64; 3]) -> f64 {
    rows[0] * lifts[0] + rows[1] * lifts[1] + rows[2] * lifts[2]
}

/// Shewchuk's floating-point in-circle determinant and its error bound, with the underflow
/// term unless `IN_RANGE`: when `|det|` exceeds the bound, its sign is the exact one.
#[inline(always)]
fn incircle_with_bound<const IN_RANGE: bool>(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
    d: [f64; 2],
) -> (f64, f64) {
    let (det, rows, lifts) = incircle_terms(a, b, c, d);
    let permanent = permanent(rows, lifts);
    if IN_RANGE {
        return (det, INCIRCLE_BOUND * permanent);
    }
    let slack = (lifts[0] + lifts[1] + lifts[2]) * INCIRCLE_SLACK + ORIENT_SLACK;
    (det, INCIRCLE_BOUND * permanent + slack)
}

/// The sign of the in-circle determinant: `Positive` iff `d` lies strictly inside the circle
/// through `a, b, c` when they are counterclockwise (mirrored when clockwise; for collinear
/// `a, b, c` the side of their line), `Zero` iff the four points are cocircular. Any finite
/// input.
#[inline(always)]
pub(crate) fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Sign {
    let (det, bound) = incircle_pair_bound(a, b, c, d);
    decide(det, bound, || incircle_second_stage(a, b, c, d))
}

/// Shewchuk's in-circle determinant and the pair bound on its error (module docs, "The
/// in-circle filter"): from the lifts alone, so that it is computed beside the determinant.
#[inline(always)]
fn incircle_pair_bound(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> (f64, f64) {
    let (det, _, [alift, blift, clift]) = incircle_terms(a, b, c, d);
    let (b_floored, c_floored) = (blift + LIFT_FLOOR, clift + LIFT_FLOOR);
    let pairs = b_floored * c_floored + alift * (b_floored + c_floored);
    (det, INCIRCLE_BOUND_WIDENED * pairs)
}

/// Where the pair bound declines (thin triangles, tiny lifts): Shewchuk's permanent with
/// floored rows, then the exact stage. Inlined, so that it shares the differences and cross
/// products already computed for the determinant and only adds the permanent: on random
/// points that made the whole test 4.14 ns against 4.42 out of line, on the Delaunay tests
/// of curve samples 4.25 against 4.54 (`examples/predicate_timing.rs`).
#[inline(always)]
fn incircle_second_stage(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Sign {
    let (det, bound) = incircle_floored_permanent_bound(a, b, c, d);
    decide(det, bound, || exact_incircle::<false>(a, b, c, d))
}

/// The in-circle determinant and the second stage's bound: Shewchuk's permanent with
/// [`ROW_FLOOR`] in each row, floored at [`INCIRCLE_PERMANENT_FLOOR`] (module docs).
#[inline(always)]
fn incircle_floored_permanent_bound(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
    d: [f64; 2],
) -> (f64, f64) {
    let (det, rows, lifts) = incircle_terms(a, b, c, d);
    let permanent = permanent(rows.map(|row| row + ROW_FLOOR), lifts);
    // As in `orient_floored_bound`: one `maxsd`, and a NaN permanent takes the floor.
    let floored = if permanent > INCIRCLE_PERMANENT_FLOOR {
        permanent
    } else {
        INCIRCLE_PERMANENT_FLOOR
    };
    (det, INCIRCLE_BOUND_WIDENED * floored)
}

/// [`incircle`] with the underflow term added to the bound, and `IN_RANGE` as in
/// [`orient_in`].
#[inline(always)]
pub(crate) fn incircle_in<const IN_RANGE: bool>(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
    d: [f64; 2],
) -> Sign {
    let (det, bound) = incircle_with_bound::<IN_RANGE>(a, b, c, d);
    decide(det, bound, || exact_incircle::<IN_RANGE>(a, b, c, d))
}

/// The exact stage of the in-circle tests, on the points' coordinates.
#[inline(always)]
fn exact_incircle<const IN_RANGE: bool>(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
    d: [f64; 2],
) -> Sign {
    exact_incircle_coordinates::<IN_RANGE>(a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1])
}

/// Out of line on eight scalars, for the reason given at [`exact_orient_coordinates`].
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn exact_incircle_coordinates<const IN_RANGE: bool>(
    ax: f64,
    ay: f64,
    bx: f64,
    by: f64,
    cx: f64,
    cy: f64,
    dx: f64,
    dy: f64,
) -> Sign {
    let (a, b, c, d) = ([ax, ay], [bx, by], [cx, cy], [dx, dy]);
    if let Some(det) = lattice_incircle(a, b, c, d) {
        return Sign::of_f64(det.signum() as f64);
    }
    if let Some(sign) = double_word::incircle(a, b, c, d) {
        return sign;
    }
    if IN_RANGE || wide::fits([ax, ay, bx, by, cx, cy, dx, dy]) {
        wide::adaptive_incircle(a, b, c, d)
    } else {
        wide::incircle(a, b, c, d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::scale;
    use crate::kernel::static_filter::{Lifted, StaticFilter};
    use crate::predicates::{CirclePosition, Orientation};

    fn coord(p: [f64; 2]) -> robust::Coord<f64> {
        robust::Coord { x: p[0], y: p[1] }
    }

    #[test]
    fn slack_constants_are_the_powers_of_two() {
        assert_eq!(ORIENT_SLACK, 2f64.powi(-1022));
        assert_eq!(INCIRCLE_SLACK, 2f64.powi(-960));
        assert!(ORIENT_SLACK.is_normal() && INCIRCLE_SLACK.is_normal());
        assert_eq!(ORIENT_PERMANENT_FLOOR, 2f64.powi(-950));
        assert_eq!(INCIRCLE_PERMANENT_FLOOR, 2f64.powi(-950));
        assert_eq!(LIFT_FLOOR, 2f64.powi(-475));
        assert_eq!(ROW_FLOOR, 2f64.powi(-900));
        assert_eq!(WIDENING, 1.0 + 2f64.powi(-10));
    }

    // The references: the adaptive predicates alone, without the filters under test.
    fn orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Orientation {
        exact_orient::<false>(a, b, c).into()
    }

    fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> CirclePosition {
        Sign::of_f64(robust::incircle(coord(a), coord(b), coord(c), coord(d))).into()
    }

    /// A deterministic stream of uniform numbers in [0, 1) (the test kit's generator).
    fn uniform_stream(seed: u64) -> impl FnMut() -> f64 {
        let mut rng = wdm_crust_testkit::Rng::new(seed);
        move || rng.f64()
    }

    /// The filtered predicates under test agree with the references.
    fn check_orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) {
        assert_eq!(Orientation::from(super::orient(a, b, c)), orient2d(a, b, c));
    }

    fn check_incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) {
        let got = CirclePosition::from(super::incircle(a, b, c, d));
        assert_eq!(got, incircle(a, b, c, d), "{a:?} {b:?} {c:?} {d:?}");
    }

    fn ulp_step(x: f64, k: i64) -> f64 {
        f64::from_bits((x.to_bits() as i64 + k) as u64)
    }

    #[test]
    fn the_static_filter_agrees_with_the_exact_predicates() {
        let mut next = uniform_stream(5);
        for round in 0..20_000 {
            // A box at some offset and scale; points inside it, some snapped to a coarse grid
            // (exact degeneracies), some nudged off a circle through three of them.
            let scale = [1e-6, 1.0, 1e6][round % 3];
            let (x0, y0) = (next() * 100.0, next() * -100.0);
            let mut pick = || {
                let (u, v) = (next(), next());
                if round % 2 == 0 {
                    [
                        x0 + (u * 4.0).floor() * scale / 4.0,
                        y0 + (v * 4.0).floor() * scale / 4.0,
                    ]
                } else {
                    [x0 + u * scale, y0 + v * scale]
                }
            };
            let pts = [pick(), pick(), pick(), pick()];
            let lo = |k: usize| pts.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
            let hi = |k: usize| pts.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
            let f = StaticFilter::<true>::for_box(hi(0) - lo(0), hi(1) - lo(1));
            let [a, b, c, d] = pts;
            let exact = orient2d(a, b, c);
            assert_eq!(Orientation::from(f.orient(a, b, c)), exact);
            // The same tests relative to a: orient(a, b, c) is b' × c'.
            let (rb, rc, rd) = (Lifted::new(b, a), Lifted::new(c, a), Lifted::new(d, a));
            if let Some(s) = f.orientation(rb.cross(&rc)) {
                assert_eq!(Orientation::from(s), exact);
            }
            let (a, b) = if exact == Orientation::Clockwise {
                (b, a)
            } else {
                (a, b)
            };
            let (rb, rc, rd) = if exact == Orientation::Clockwise {
                (Lifted::new(b, a), Lifted::new(c, a), Lifted::new(d, a))
            } else {
                (rb, rc, rd)
            };
            if exact != Orientation::Collinear {
                if let Some(s) = f.in_circle(&rb, &rc, &rd, rb.cross(&rc)) {
                    let exact = incircle(a, b, c, d);
                    assert_eq!(CirclePosition::from(s), exact, "{a:?} {b:?} {c:?} {d:?}");
                }
            }
        }
    }

    /// The sign a filter's determinant and bound certify, if any.
    fn decided((det, bound): (f64, f64)) -> Option<Sign> {
        if det > bound {
            Some(Sign::Positive)
        } else if -det > bound {
            Some(Sign::Negative)
        } else {
            None
        }
    }

    /// The fast filters certify only where the proven tests (the underflow term added to
    /// Shewchuk's bound) do, with the exact sign, and decline no more often for coordinates
    /// down to `2^-230`. Below, they decline more only where the module docs say: the
    /// orientation filter where its permanent is under the floor; the in-circle stages where
    /// the lifts are under about `2^-475` or the determinant under about `2^-1000`.
    #[test]
    fn the_fast_filters_imply_the_proven_ones() {
        let mut next = uniform_stream(17);
        let (mut orient_fast, mut orient_proven) = ([0; 2], [0; 2]);
        let (mut incircle_fast, mut incircle_proven) = ([0; 2], [0; 2]);
        for round in 0..48_000 {
            // Scales from ordinary to deep in the subnormals; some points on a coarse grid
            // (exact zeros).
            let exponent = [0, -230, -250, -500, -540, -1000, -1040, -1070][round % 8];
            let scale = scale::pow2(exponent);
            let tiny = usize::from(exponent < -230);
            let grid = round % 3 == 0;
            let mut pick = || {
                let (u, v) = (next(), next());
                if grid {
                    [(u * 8.0).floor() * scale, (v * 8.0).floor() * scale]
                } else {
                    [u * scale, v * scale]
                }
            };
            let [a, b, c, d] = [pick(), pick(), pick(), pick()];
            let proven = decided(orient_with_bound::<false>(a, b, c)).is_some();
            orient_proven[tiny] += usize::from(proven);
            let fast = decided(orient_floored_bound(a, b, c));
            if let Some(sign) = fast {
                orient_fast[tiny] += 1;
                assert!(proven, "{a:?} {b:?} {c:?}");
                assert_eq!(sign, exact_orient::<false>(a, b, c));
            } else if proven && tiny == 1 {
                let (_, permanent) = orient_terms(a, b, c);
                assert!(permanent < ORIENT_PERMANENT_FLOOR, "{a:?} {b:?} {c:?}");
            }
            let proven = decided(incircle_with_bound::<false>(a, b, c, d)).is_some();
            incircle_proven[tiny] += usize::from(proven);
            let first = decided(incircle_pair_bound(a, b, c, d));
            let second = decided(incircle_floored_permanent_bound(a, b, c, d));
            for sign in [first, second].into_iter().flatten() {
                assert!(proven, "{a:?} {b:?} {c:?} {d:?}");
                assert_eq!(sign, exact_incircle::<false>(a, b, c, d));
            }
            incircle_fast[tiny] += usize::from(first.or(second).is_some());
            if first.or(second).is_none() && proven {
                let (det, _, lifts) = incircle_terms(a, b, c, d);
                let small_lifts = lifts.iter().any(|&lift| lift < 2f64.powi(-470));
                assert!(
                    small_lifts || det.abs() < 2f64.powi(-990),
                    "{a:?} {b:?} {c:?} {d:?}"
                );
            }
        }
        assert_eq!(incircle_fast[0], incircle_proven[0]);
        // The orientation filter's bound is wider by `2^-10` than the proven one's (module
        // docs), which declines a handful of nearly degenerate grid tests more.
        assert!(orient_fast[0] * 1000 >= orient_proven[0] * 999);
        assert!(orient_fast[0] > 10_000 && incircle_fast[0] > 10_000);
    }

    /// Four points close together on a large circle, nudged off it (thin, nearly cocircular
    /// quadruples, as the Delaunay tests of sampled curves are): the pair bound declines
    /// more often than Shewchuk's, the second stage decides what his bound with the
    /// underflow term decides, and every answer is exact.
    #[test]
    fn the_second_stage_decides_thin_triangles() {
        let mut next = uniform_stream(23);
        let (mut pair_declined, mut second_decided, mut proven) = (0, 0, 0);
        let quadruples = 20_000;
        for _ in 0..quadruples {
            let centre = [next() * 10.0 - 5.0, next() * 10.0 - 5.0];
            let radius = 10f64.powf(next() * 4.0);
            // Near an axis, where the chords run nearly along the other one: there `Q` is
            // many times Shewchuk's permanent (module docs).
            let start = (next() * 4.0).floor() * std::f64::consts::FRAC_PI_2 + next() * 0.01;
            let arc = 10f64.powf(-0.5 - next());
            let mut on_arc = || {
                let angle = start + next() * arc;
                let nudge = 1.0 + (next() - 0.5) * 10f64.powf(-12.0 - 4.0 * next());
                [
                    centre[0] + radius * nudge * angle.cos(),
                    centre[1] + radius * nudge * angle.sin(),
                ]
            };
            let [a, b, c, d] = [on_arc(), on_arc(), on_arc(), on_arc()];
            let exact = exact_incircle::<false>(a, b, c, d);
            assert_eq!(
                super::incircle(a, b, c, d),
                exact,
                "{a:?} {b:?} {c:?} {d:?}"
            );
            proven += usize::from(decided(incircle_with_bound::<false>(a, b, c, d)).is_some());
            if decided(incircle_pair_bound(a, b, c, d)).is_none() {
                pair_declined += 1;
                let second = decided(incircle_floored_permanent_bound(a, b, c, d));
                second_decided += usize::from(second.is_some());
            }
        }
        assert!(second_decided > 100, "{second_decided}");
        // Everything Shewchuk's bound decides is decided by one of the stages.
        assert_eq!(quadruples - pair_declined + second_decided, proven);
    }

    /// Products that overflow keep their signs: with opposite signs the orientation filter
    /// answers from the infinite determinant, and rightly; with equal signs (a NaN
    /// determinant or an infinite bound) it declines.
    #[test]
    fn the_orientation_filter_on_overflowing_products() {
        let big = f64::MAX / 2.0;
        let opposite = [
            // left = +inf, right = -inf, and mirrored.
            ([big, big], [-big, big], [0.0, 0.0]),
            ([-big, big], [big, big], [0.0, 0.0]),
        ];
        for (a, b, c) in opposite {
            assert_eq!(
                decided(orient_floored_bound(a, b, c)),
                Some(exact_orient::<false>(a, b, c))
            );
        }
        let declined = [
            // Both +inf: NaN determinant.
            ([big, big], [-big, -big], [-big, big]),
            // One product overflows, the other is small: an infinite bound.
            ([big, 1.0], [-big, 1.0 + 2f64.powi(-40)], [0.0, 0.5]),
            (
                [f64::MAX, f64::MIN_POSITIVE],
                [-f64::MAX, 0.0],
                [0.0, -f64::MIN_POSITIVE],
            ),
        ];
        for (a, b, c) in opposite.into_iter().chain(declined) {
            for [p, q, r] in [[a, b, c], [b, c, a], [c, a, b], [b, a, c]] {
                let exact = exact_orient::<false>(p, q, r);
                if let Some(sign) = decided(orient_floored_bound(p, q, r)) {
                    assert_eq!(sign, exact, "{p:?} {q:?} {r:?}");
                }
                assert_eq!(orient(p, q, r), exact, "{p:?} {q:?} {r:?}");
            }
        }
    }

    #[test]
    fn the_lattice_path_is_exact_or_declines() {
        let mut s = 9u64;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            s >> 11
        };
        let mut decided = 0;
        for round in 0..50_000 {
            let span = [4, 1 << 20, 1 << 29, 1 << 31, 1 << 40][round % 5];
            let offset = [0.0, 1e6, -3.5, 2f64.powi(60)][round / 5 % 4];
            let scale = 2f64.powi([0, -40, 30, -120][round / 20 % 4]);
            let mut pick = || {
                [
                    (offset + (next() % span) as f64 - (span / 2) as f64) * scale,
                    (offset + (next() % span) as f64) * scale,
                ]
            };
            let (a, b, c, d) = (pick(), pick(), pick(), pick());
            if let Some(det) = lattice_incircle(a, b, c, d) {
                decided += 1;
                let expected = match incircle(a, b, c, d) {
                    CirclePosition::Inside => 1,
                    CirclePosition::On => 0,
                    CirclePosition::Outside => -1,
                };
                assert_eq!(det.signum(), expected, "{a:?} {b:?} {c:?} {d:?}");
            }
        }
        assert!(decided > 10_000, "the lattice path decides small lattices");
    }

    #[test]
    fn agrees_with_the_exact_predicates_near_degeneracy() {
        let mut next = uniform_stream(3);
        for _ in 0..20_000 {
            // Nearly collinear: c on the line a→b, nudged by a few ulps.
            let a = [next(), next()];
            let b = [next() * 1e3, next() * 1e-3];
            let t = next();
            let c = [
                ulp_step(a[0] + t * (b[0] - a[0]), (next() * 9.0) as i64 - 4),
                ulp_step(a[1] + t * (b[1] - a[1]), (next() * 9.0) as i64 - 4),
            ];
            check_orient(a, b, c);
            // Nearly cocircular: four points on the unit circle, nudged.
            let ang = |u: f64| [u.cos(), u.sin()];
            let (u, v, w) = (next(), next() + 2.0, next() + 4.0);
            let d = ang(next() * 6.0);
            let d = [ulp_step(d[0], (next() * 5.0) as i64 - 2), d[1]];
            check_incircle(ang(u), ang(v), ang(w), d);
            let grid = |x: f64| (x * 4.0).floor();
            let (pa, pb, pc, d) = (
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
            );
            check_orient(pa, pb, pc);
            check_incircle(pa, pb, pc, d);
        }
    }
}
