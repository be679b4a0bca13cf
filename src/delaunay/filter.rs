//! Filtered predicates for the construction: one floating-point evaluation with Shewchuk's
//! proven error bound, and the exact adaptive predicate ([`crate::predicates`]) only when
//! the bound cannot decide. Every answer equals the exact one.
//!
//! The bounds are Shewchuk's `ccwerrboundA` and `iccerrboundA` for exactly this evaluation
//! order. They assume no intermediate underflow or overflow, which the input envelope
//! guarantees: coordinate differences are 0 or in [2^-194, 2^202], so products of up to four
//! of them and their sums stay between 2^-776 and 2^812.

use crate::predicates::{incircle, orient2d, CirclePosition, Orientation};

/// 2^-53: half an ulp of 1.
const EPSILON: f64 = 1.0 / 9_007_199_254_740_992.0;
const CCW_BOUND: f64 = (3.0 + 16.0 * EPSILON) * EPSILON;
const INCIRCLE_BOUND: f64 = (10.0 + 96.0 * EPSILON) * EPSILON;

/// Is `c` strictly left of the directed line `a → b`?
#[inline(always)]
pub fn ccw(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    let det = left - right;
    let bound = CCW_BOUND * (left.abs() + right.abs());
    if det > bound {
        true
    } else if -det > bound {
        false
    } else {
        exact_ccw(a, b, c)
    }
}

#[inline(never)]
fn exact_ccw(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    orient2d(a, b, c) == Orientation::CounterClockwise
}

/// Is `d` strictly inside the circle through the counterclockwise `a, b, c`?
#[inline(always)]
pub fn inside(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
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
    let bound = INCIRCLE_BOUND * permanent;
    if det > bound {
        true
    } else if -det > bound {
        false
    } else {
        exact_inside(a, b, c, d)
    }
}

#[inline(never)]
fn exact_inside(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    incircle(a, b, c, d) == CirclePosition::Inside
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ulp_step(x: f64, k: i64) -> f64 {
        f64::from_bits((x.to_bits() as i64 + k) as u64)
    }

    #[test]
    fn agrees_with_the_exact_predicates_near_degeneracy() {
        let mut s = 3u64;
        let mut next = || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..20_000 {
            // Nearly collinear: c on the line a→b, nudged by a few ulps.
            let a = [next(), next()];
            let b = [next() * 1e3, next() * 1e-3];
            let t = next();
            let c = [
                ulp_step(a[0] + t * (b[0] - a[0]), (next() * 9.0) as i64 - 4),
                ulp_step(a[1] + t * (b[1] - a[1]), (next() * 9.0) as i64 - 4),
            ];
            assert_eq!(ccw(a, b, c), orient2d(a, b, c) == Orientation::CounterClockwise);
            // Nearly cocircular: four points on the unit circle, nudged.
            let ang = |u: f64| [u.cos(), u.sin()];
            let (u, v, w) = (next(), next() + 2.0, next() + 4.0);
            let d = ang(next() * 6.0);
            let d = [ulp_step(d[0], (next() * 5.0) as i64 - 2), d[1]];
            let (pa, pb, pc) = (ang(u), ang(v), ang(w));
            assert_eq!(
                inside(pa, pb, pc, d),
                incircle(pa, pb, pc, d) == CirclePosition::Inside
            );
            let grid = |x: f64| (x * 4.0).floor();
            let (pa, pb, pc, d) = (
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
            );
            assert_eq!(ccw(pa, pb, pc), orient2d(pa, pb, pc) == Orientation::CounterClockwise);
            if ccw(pa, pb, pc) {
                assert_eq!(
                    inside(pa, pb, pc, d),
                    incircle(pa, pb, pc, d) == CirclePosition::Inside
                );
            }
        }
    }
}
