//! The exact-arithmetic kernel: every geometric predicate of the crate, written once.
//!
//! # Evaluation scheme
//!
//! Each predicate is the sign of one polynomial in its `f64` inputs, evaluated in stages
//! that stop at the first certain answer:
//!
//! 1. **A floating-point filter with a proven error bound.** The polynomial in plain `f64`
//!    and a bound on its rounding error; if `|value| > bound` the sign is exact. For
//!    orientation and in-circle on input points this is Shewchuk's semi-static filter
//!    (`basic`, and per merge of the construction a static bound, `static_filter`); for the
//!    predicates on circumcenters and the NN-crust's metric tests it is the semi-static
//!    filter of `filter`, whose bound is proven there and whose constants a test recomputes
//!    from the evaluated code. Inputs with huge or tiny differences are retried after an exact
//!    power-of-two rescaling (`scale`), and a running-error filter (`bounded`, rigorous
//!    bounds propagated through every operation) catches exact zeros whose operations were
//!    all exact in `f64`. The crust's mixed predicates start at the running-error filter.
//!    The circumcenter construction instead evaluates its formula once more with exact
//!    products and an a priori bound (`thin`), then in double-word arithmetic with a running
//!    error bound (`double_word`): they decide the nearly collinear triangles that defeat the
//!    `f64` filter.
//! 2. **Exact evaluation.** For orientation and in-circle of input points: the `robust`
//!    crate's adaptive predicates (after an `i128` evaluation for lattice input, `lattice`)
//!    on inputs in their exact range, or after a power-of-two rescale into it; inputs spread
//!    wider than that range go to the integers below (`wide`).
//!    For everything else: every `f64` is a dyadic rational, so the inputs of one call are
//!    integers in units of one power of two and the polynomial is evaluated in `BigInt`
//!    without any fraction (`exact`).
//!
//! Each polynomial is written once, generic over the ring (`arith::Arith`), in `poly` and,
//! for the circumcenter (`O = t0 + u/d`), in `circumcenter`.
//!
//! # Sign convention
//!
//! Every predicate returns [`Sign`], the sign of its determinant:
//!
//! | predicate | `Positive` means |
//! |---|---|
//! | `orient(a, b, c)` | `c` strictly left of `a → b` (counterclockwise) |
//! | `incircle(a, b, c, d)` | `d` strictly inside the circle through counterclockwise `a, b, c` (mirrored if clockwise) |
//! | `orient_circumcenter(a, b, t)` | the circumcenter of `t` strictly left of `a → b` |
//! | [`dot_sign_circumcenters`]`(p, s, o)` | `(O(o) − p)·(O(s) − p) > 0` |
//! | `compare_circumradius(t1, t2)` | the circumradius of `t1` is the larger |
//! | `metric::distance_order(p, a, b)` | `a` is strictly farther from `p` than `b` |
//! | `metric::dot_sign(p, s, q)` | `(s − p)·(q − p) > 0` |
//! | `MixedPoints::{orient, incircle}` | as `orient`, `incircle`, on samples and circumcenters |
//! | `box_side::circumcenter_side(t, axis, v)` | the circumcenter of `t` has `axis` coordinate strictly above `v` |
//!
//! `Zero` is always the exact degenerate case (collinear, cocircular, equal).
//!
//! # Every finite input
//!
//! All predicates are exact on every finite `f64`: each filter's bound covers underflow
//! (an absolute term) and fails on overflow (an infinite or NaN bound never certifies), and
//! each exact stage works at any exponent. See `basic` for the terms added to Shewchuk's
//! bounds and `wide` for the exact stage of orientation and in-circle.
//!
//! # Why hand-written
//!
//! Exactness: every answer is the one exact real arithmetic on the `f64` inputs gives, which
//! the combinatorial algorithms above rely on (a wrong sign breaks a triangulation). Speed:
//! the filters decide almost every call in a few dozen flops without allocating; a generic
//! exact number type would be orders of magnitude slower, and the construction's filters are
//! its inner loop.

mod arith;
pub(crate) mod basic;
mod bounded;
mod box_side;
mod circumcenter;
mod derived;
mod double_word;
mod exact;
mod filter;
mod lattice;
pub(crate) mod metric;
pub(crate) mod mixed;
mod poly;
mod rounded;
pub(crate) mod scale;
mod sign;
pub(crate) mod static_filter;
pub(crate) mod stats;
mod thin;
mod wide;

pub(crate) use basic::{incircle, orient};
pub(crate) use box_side::{
    bisector_crossing, circumcenter_nearest, circumcenter_side, circumcenter_strictly_inside,
};
pub use circumcenter::{circumcenter, circumcenter_exact, ExactPoint};
pub use derived::{circumcenter_in_convex_hull, dot_sign_circumcenters, HullPosition};
pub(crate) use derived::{compare_circumradius, orient_circumcenter};
pub(crate) use rounded::{compare_radius_rounded, dot_sign_rounded};
pub use sign::Sign;

#[cfg(test)]
mod tests;
