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
//! Callers that know every coordinate to be zero or of an exponent in
//! `scale::ADAPTIVE_EXPONENTS` (the construction, on validated or rescaled input) use the
//! `*_in::<true>` forms, without the terms: there differences are 0 or in [2^-194, 2^202],
//! so products of up to four of them and their sums stay between 2^-776 and 2^812, no
//! product underflows and Shewchuk's bounds hold as they are.

use super::lattice::lattice_incircle;
use super::{wide, Sign};

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

/// The sign of the orientation determinant of `a → b → c`: `Positive` iff `c` lies strictly
/// left of the directed line `a → b` (counterclockwise), `Zero` iff collinear.
#[inline(always)]
pub(crate) fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    orient_in::<false>(a, b, c)
}

/// [`orient`]; with `IN_RANGE` the caller guarantees that every coordinate is zero or of
/// an exponent in the adaptive predicates' range (`scale::ADAPTIVE_EXPONENTS`), and the
/// exact stage goes to them without checking (the construction on such input, where exact
/// zeros are frequent).
#[inline(always)]
pub(crate) fn orient_in<const IN_RANGE: bool>(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    let det = left - right;
    // In range, the envelope rules out harmful underflow (module docs): no slack needed.
    let slack = if IN_RANGE { 0.0 } else { ORIENT_SLACK };
    let bound = CCW_BOUND * (left.abs() + right.abs()) + slack;
    if det > bound {
        Sign::Positive
    } else if -det > bound {
        Sign::Negative
    } else {
        exact_orient::<IN_RANGE>(a, b, c)
    }
}

#[inline(never)]
fn exact_orient<const IN_RANGE: bool>(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    if IN_RANGE {
        wide::adaptive_orient(a, b, c)
    } else {
        wide::orient(a, b, c)
    }
}

/// Shewchuk's floating-point in-circle determinant and its error bound: when `|det|`
/// exceeds the bound, its sign is the exact one.
#[inline(always)]
fn incircle_with_bound<const IN_RANGE: bool>(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
    d: [f64; 2],
) -> (f64, f64) {
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
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * alift
        + (cdxady.abs() + adxcdy.abs()) * blift
        + (adxbdy.abs() + bdxady.abs()) * clift;
    if IN_RANGE {
        return (det, INCIRCLE_BOUND * permanent);
    }
    let slack = (alift + blift + clift) * INCIRCLE_SLACK + ORIENT_SLACK;
    (det, INCIRCLE_BOUND * permanent + slack)
}

/// The sign of the in-circle determinant: `Positive` iff `d` lies strictly inside the circle
/// through `a, b, c` when they are counterclockwise (mirrored when clockwise; for collinear
/// `a, b, c` the side of their line), `Zero` iff the four points are cocircular.
#[inline(always)]
pub(crate) fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Sign {
    incircle_in::<false>(a, b, c, d)
}

/// [`incircle`], with `IN_RANGE` as in [`orient_in`].
#[inline(always)]
pub(crate) fn incircle_in<const IN_RANGE: bool>(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
    d: [f64; 2],
) -> Sign {
    let (det, bound) = incircle_with_bound::<IN_RANGE>(a, b, c, d);
    if det > bound {
        Sign::Positive
    } else if -det > bound {
        Sign::Negative
    } else {
        exact_incircle::<IN_RANGE>(a, b, c, d)
    }
}

#[inline(never)]
fn exact_incircle<const IN_RANGE: bool>(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
    d: [f64; 2],
) -> Sign {
    match lattice_incircle(a, b, c, d) {
        Some(det) => Sign::of_f64(det.signum() as f64),
        None if IN_RANGE => wide::adaptive_incircle(a, b, c, d),
        None => wide::incircle(a, b, c, d),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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
    }

    // The references: the adaptive predicates alone, without the filters under test.
    fn orient2d(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Orientation {
        exact_orient::<false>(a, b, c).into()
    }

    fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> CirclePosition {
        Sign::of_f64(robust::incircle(coord(a), coord(b), coord(c), coord(d))).into()
    }

    /// A deterministic stream of uniform numbers in [0, 1) (a 64-bit LCG's high bits).
    fn uniform_stream(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed;
        move || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        }
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
