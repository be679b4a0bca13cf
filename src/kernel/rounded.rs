//! A filter on circumcenters already rounded by [`circumcenter`](super::circumcenter): when
//! many tests share the same circumcenters (the water flow tests every vertex of a cell
//! against the cell's source), each is rounded once and a test costs a dot product and a
//! bound, instead of two circumcenters' polynomials per call.
//!
//! [`circumcenter`](super::circumcenter) proves per call that each coordinate of its result
//! `ô` is within 256 units in the last place of `N = max(|ôx|, |ôy|)` of the exact
//! circumcenter `O`. An ulp of `N` is at most `N·2^-52` when `N` is normal and `2^-1074`
//! otherwise, so `|O_i − ô_i| ≤ e(ô) = 2^-44·N + 2^-1066` for both coordinates.
//!
//! For `A = O_o − p`, `B = O_s − p` and the computed `a_i = fl(ô_o,i − p_i)` (an exact
//! subtraction but for one rounding, `|a_i − (ô_o,i − p_i)| ≤ u|a_i|`, `u = 2^-53`):
//! `|A_i − a_i| ≤ δa_i = e(ô_o) + u|a_i|`, and likewise `δb_i`. Then
//!
//! ```text
//! |A·B − a·b| ≤ Σ_i (|a_i|·δb_i + |b_i|·δa_i + δa_i·δb_i)
//! ```
//!
//! and the rounded `fl(a·b)` is within `γ_2·(|ax·bx| + |ay·by|) + 2^-1073` of `a·b`
//! (`γ_2 = 2u/(1 − 2u)`, the last term for products that underflow). Every term is
//! non-negative; evaluated in `f64` their sum is low by at most a relative `8u`, which the
//! final factor `1 + 2^-40` covers. If `|fl(a·b)|` exceeds the bound, its sign is exact.
//! Anything infinite or NaN (overflowing input) fails the comparison: no answer, and the
//! caller takes the exact predicate.

use super::Sign;

/// `2^-44`: 256 ulps of a normal `N`, relative to `N`.
const ULPS_256: f64 = 5.684341886080802e-14;
/// `2^-1066`: 256 ulps of a subnormal.
const ULPS_256_SUBNORMAL: f64 = 256.0 * f64::from_bits(1);
/// `u = 2^-53`.
const U: f64 = 1.1102230246251565e-16;
/// `γ_2` rounded up, with room to spare: `2u/(1 − 2u) < 2.0000001u`.
const GAMMA_2: f64 = 2.0000001 * U;
/// `2^-1073`: the underflow of two products.
const UNDERFLOW: f64 = 2.0 * f64::from_bits(1);
/// `1 + 2^-40`: covers the rounding of the bound's own evaluation.
const BOUND_MARGIN: f64 = 1.0 + 9.094947017729282e-13;

/// The bound on the error of a rounded circumcenter's coordinates.
#[inline(always)]
fn position_error(o: [f64; 2]) -> f64 {
    ULPS_256 * o[0].abs().max(o[1].abs()) + ULPS_256_SUBNORMAL
}

/// The sign of `(O_o − p)·(O_s − p)` from `o` and `s`, circumcenters rounded by
/// [`circumcenter`](super::circumcenter) (within 256 ulps), if the bound of the module docs
/// certifies it: the same answer as [`dot_sign_circumcenters`](super::dot_sign_circumcenters)
/// on the triangles they were rounded from. `None` near zero and on non-finite values.
#[inline]
pub(crate) fn dot_sign_rounded(p: [f64; 2], s: [f64; 2], o: [f64; 2]) -> Option<Sign> {
    let (eo, es) = (position_error(o), position_error(s));
    let a = [o[0] - p[0], o[1] - p[1]];
    let b = [s[0] - p[0], s[1] - p[1]];
    let dot = a[0] * b[0] + a[1] * b[1];
    let mut bound = UNDERFLOW + GAMMA_2 * ((a[0] * b[0]).abs() + (a[1] * b[1]).abs());
    for i in 0..2 {
        let (ai, bi) = (a[i].abs(), b[i].abs());
        let (da, db) = (eo + U * ai, es + U * bi);
        bound += ai * db + bi * da + da * db;
    }
    let bound = bound * BOUND_MARGIN;
    if dot > bound {
        Some(Sign::Positive)
    } else if -dot > bound {
        Some(Sign::Negative)
    } else {
        None
    }
}

/// The sign of `R_1 − R_2`, the circumradii of two triangles, from their circumcenters
/// `o1`, `o2` rounded by [`circumcenter`](super::circumcenter) and a vertex `a1`, `a2` of
/// each, if certified: the answer of
/// [`compare_circumradius`](super::compare_circumradius) on the triangles.
///
/// `R_k = |O_k − a_k|` is within `√2·e(ô_k)` of `|ô_k − a_k|`, and the computed
/// `fl(hypot(fl(ô_k − a_k)))` within a relative `3u` of that (two subtractions and a
/// correctly rounded hypot, which libm's is to within an ulp: bounded by `4u` here). The
/// difference is certified when it exceeds the sum of both bounds with the margin.
#[inline]
pub(crate) fn compare_radius_rounded(
    o1: [f64; 2],
    a1: [f64; 2],
    o2: [f64; 2],
    a2: [f64; 2],
) -> Option<Sign> {
    let r1 = (o1[0] - a1[0]).hypot(o1[1] - a1[1]);
    let r2 = (o2[0] - a2[0]).hypot(o2[1] - a2[1]);
    let bound =
        (1.5 * (position_error(o1) + position_error(o2)) + 4.0 * U * (r1 + r2)) * BOUND_MARGIN;
    let difference = r1 - r2;
    if difference > bound {
        Some(Sign::Positive)
    } else if -difference > bound {
        Some(Sign::Negative)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::super::{circumcenter, compare_circumradius, dot_sign_circumcenters};
    use super::*;
    use wdm_crust_testkit::Rng;

    /// Triangles of every shape the diagrams produce, at every scale: random, thin (three
    /// nearly collinear points), tiny beside a far point, and of huge or tiny magnitude.
    fn triangle(rng: &mut Rng, scale: f64) -> [[f64; 2]; 3] {
        let p = |rng: &mut Rng| [rng.range(-1.0, 1.0) * scale, rng.range(-1.0, 1.0) * scale];
        let (a, b) = (p(rng), p(rng));
        match rng.below(3) {
            0 => [a, b, p(rng)],
            1 => {
                let t = rng.f64();
                let off = scale * 1e-9 * rng.range(-1.0, 1.0);
                [
                    a,
                    b,
                    [a[0] + t * (b[0] - a[0]) + off, a[1] + t * (b[1] - a[1])],
                ]
            }
            _ => {
                let d = scale * 1e-7;
                [a, [a[0] + d, a[1]], [a[0], a[1] + d * rng.range(0.5, 2.0)]]
            }
        }
    }

    /// Wherever the rounded filter answers, its answer is the exact predicate's; and where
    /// the dot product neither overflows nor underflows it answers nearly always.
    #[test]
    fn agrees_with_the_exact_predicate() {
        let mut rng = Rng::new(17);
        // Decided and total per scale.
        let (mut decided, mut total) = ([0usize; 5], [0usize; 5]);
        for round in 0..40_000 {
            let scale = [1.0, 1e-150, 1e150, 1e-300, 3e300][round % 5];
            let k = round % 5;
            let (s, o) = (triangle(&mut rng, scale), triangle(&mut rng, scale));
            let p = match rng.below(3) {
                0 => s[0],
                1 => o[1],
                _ => [rng.range(-1.0, 1.0) * scale, rng.range(-1.0, 1.0) * scale],
            };
            let (Some(cs), Some(co)) = (
                circumcenter(s[0], s[1], s[2]),
                circumcenter(o[0], o[1], o[2]),
            ) else {
                continue;
            };
            total[k] += 1;
            if let Some(sign) = dot_sign_rounded(p, cs, co) {
                decided[k] += 1;
                assert_eq!(
                    sign,
                    dot_sign_circumcenters(p, s, o),
                    "round {round}: {p:?} {s:?} {o:?}"
                );
            }
        }
        // Scales 1 and 1e-150 keep the products in range; the others over- or underflow
        // and are left to the exact predicate (what matters there is only that no answer
        // is wrong).
        for k in [0, 1] {
            assert!(
                decided[k] * 10 > total[k] * 9,
                "decided {decided:?} of {total:?}"
            );
        }
    }

    /// Wherever the rounded radius comparison answers, it is the exact one's; it answers
    /// on nearly every pair of distinct radii of ordinary magnitude.
    #[test]
    fn radius_comparison_agrees_with_the_exact_predicate() {
        let mut rng = Rng::new(23);
        let (mut decided, mut total) = ([0usize; 5], [0usize; 5]);
        for round in 0..40_000 {
            let k = round % 5;
            let scale = [1.0, 1e-150, 1e150, 1e-300, 3e300][k];
            let (t1, t2) = (triangle(&mut rng, scale), triangle(&mut rng, scale));
            // Every other pair shares a circle: equal radii must never be decided.
            let t2 = if round % 2 == 0 {
                t2
            } else {
                [t1[1], t1[2], t1[0]]
            };
            let (Some(o1), Some(o2)) = (
                circumcenter(t1[0], t1[1], t1[2]),
                circumcenter(t2[0], t2[1], t2[2]),
            ) else {
                continue;
            };
            total[k] += 1;
            if let Some(sign) = compare_radius_rounded(o1, t1[0], o2, t2[0]) {
                decided[k] += 1;
                assert_eq!(
                    sign,
                    compare_circumradius(t1, t2),
                    "round {round}: {t1:?} {t2:?}"
                );
            }
        }
        for k in [0, 1] {
            // Half the pairs are equal: at most half can be decided.
            assert!(
                decided[k] * 20 > total[k] * 9,
                "decided {decided:?} of {total:?}"
            );
        }
    }

    /// Exact zeros (a right angle at `p`) are never decided, and neither is overflow.
    #[test]
    fn zeros_and_overflow_are_left_to_the_exact_predicate() {
        // Circumcenters (2, 2) and (−2, 2) seen from the origin: a right angle.
        let s = circumcenter([0.0, 0.0], [4.0, 0.0], [0.0, 4.0]).unwrap();
        let o = circumcenter([0.0, 0.0], [-4.0, 0.0], [0.0, 4.0]).unwrap();
        assert_eq!(dot_sign_rounded([0.0, 0.0], s, o), None);
        assert_eq!(dot_sign_rounded([0.0, 0.0], [f64::INFINITY, 0.0], o), None);
        assert_eq!(
            dot_sign_rounded([0.0, 0.0], [1e300, 1e300], [1e300, 1e300]),
            None
        );
        assert_eq!(dot_sign_rounded([0.0, 0.0], [f64::NAN, 0.0], o), None);
        // Far from zero it answers.
        assert_eq!(dot_sign_rounded([0.0, 0.0], s, s), Some(Sign::Positive));
    }
}
