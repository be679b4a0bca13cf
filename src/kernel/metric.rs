//! Metric comparisons of input points, for the NN-crust: which of two points is closer to a
//! third, and on which side of the line orthogonal to `q − p` through `p` a point lies.
//! Degree-2 polynomials through the same stages as every kernel predicate.

use super::bounded::lift_filter;
use super::exact::{lift_exact, signs};
use super::filter;
use super::poly::{distance_terms, dot_points_terms, length_terms, scaled_length_terms};
use super::scale::normalize;
use super::Sign;

/// The sign of `|p − a|² − |p − b|²`: `Negative` iff `a` is strictly closer to `p`.
#[inline]
pub(crate) fn distance_order(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> Sign {
    filter::distance(p, a, b).unwrap_or_else(|| distance_slow([p, a, b]))
}

/// The sign of `(s − p)·(q − p)`.
#[inline]
pub(crate) fn dot_sign(p: [f64; 2], s: [f64; 2], q: [f64; 2]) -> Sign {
    filter::dot_points(p, s, q).unwrap_or_else(|| dot_slow([p, s, q]))
}

#[cold]
#[inline(never)]
fn distance_slow(points: [[f64; 2]; 3]) -> Sign {
    let [fp, fa, fb] = lift_filter(normalize(points).0);
    let ([s], _) = signs(distance_terms(&fp, &fa, &fb), || {
        let ([ep, ea, eb], _) = lift_exact(points);
        distance_terms(&ep, &ea, &eb)
    });
    s
}

#[cold]
#[inline(never)]
fn dot_slow(points: [[f64; 2]; 3]) -> Sign {
    let [fp, fs, fq] = lift_filter(normalize(points).0);
    let ([s], _) = signs(dot_points_terms(&fp, &fs, &fq), || {
        let ([ep, es, eq], _) = lift_exact(points);
        dot_points_terms(&ep, &es, &eq)
    });
    s
}

/// The order of `|p − q|²` and `|r − s|²` (`Less` iff the segment `pq` is strictly shorter),
/// exact: rounded arithmetic where its error bound decides, the kernel's exact stages
/// otherwise.
pub(crate) fn length_order(
    p: [f64; 2],
    q: [f64; 2],
    r: [f64; 2],
    s: [f64; 2],
) -> std::cmp::Ordering {
    let squared = |a: [f64; 2], b: [f64; 2]| {
        let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
        dx * dx + dy * dy
    };
    let (first, second) = (squared(p, q), squared(r, s));
    // Each squared length is within 4 rounding units (u = 2^-53) of the exact one when no
    // step overflows and the sum is far above the subnormal range (a square that underflows
    // is then negligible); the margin covers both lengths and the subtraction.
    const U: f64 = f64::EPSILON / 2.0;
    let normal = |d: f64| d.is_finite() && (d == 0.0 || d > 1e-280);
    if normal(first) && normal(second) {
        let difference = first - second;
        if difference.abs() > 8.0 * U * (first + second) {
            return difference
                .partial_cmp(&0.0)
                .unwrap_or(std::cmp::Ordering::Equal);
        }
    }
    length_order_exact(p, q, r, s)
}

/// The order of `|p − q|` and `2^doublings · |r − s|` (`Greater` iff the segment `pq` is
/// strictly longer than `rs` scaled by that power of two), exact: scaling a length by a
/// power of two is exact in every stage, so the ratio tests of the reconstruction ("an edge
/// more than 8 times its neighbour's length") are decided like any other predicate.
pub(crate) fn scaled_length_order(
    p: [f64; 2],
    q: [f64; 2],
    r: [f64; 2],
    s: [f64; 2],
    doublings: u32,
) -> std::cmp::Ordering {
    let squared = |a: [f64; 2], b: [f64; 2]| {
        let (dx, dy) = (a[0] - b[0], a[1] - b[1]);
        dx * dx + dy * dy
    };
    // The square of the scaled length: 4^doublings times |r − s|², exact in rounded
    // arithmetic unless it overflows (which `normal` sends to the exact stages).
    let factor = f64::from(4u32.pow(doublings.min(15)));
    let (first, second) = (squared(p, q), squared(r, s) * factor);
    const U: f64 = f64::EPSILON / 2.0;
    let normal = |d: f64| d.is_finite() && (d == 0.0 || d > 1e-280);
    if doublings <= 15 && normal(first) && normal(second) {
        let difference = first - second;
        if difference.abs() > 8.0 * U * (first + second) {
            return difference
                .partial_cmp(&0.0)
                .unwrap_or(std::cmp::Ordering::Equal);
        }
    }
    scaled_length_order_exact(p, q, r, s, doublings)
}

/// The exact stages of [`scaled_length_order`].
#[cold]
#[inline(never)]
fn scaled_length_order_exact(
    p: [f64; 2],
    q: [f64; 2],
    r: [f64; 2],
    s: [f64; 2],
    doublings: u32,
) -> std::cmp::Ordering {
    let points = [p, q, r, s];
    let [fp, fq, fr, fs] = lift_filter(normalize(points).0);
    let ([sign], _) = signs(scaled_length_terms(&fp, &fq, &fr, &fs, doublings), || {
        let ([ep, eq, er, es], _) = lift_exact(points);
        scaled_length_terms(&ep, &eq, &er, &es, doublings)
    });
    match sign {
        Sign::Negative => std::cmp::Ordering::Less,
        Sign::Zero => std::cmp::Ordering::Equal,
        Sign::Positive => std::cmp::Ordering::Greater,
    }
}

/// The exact stages of [`length_order`]: the running-error filter, then integers (the
/// same stages as every kernel predicate; rationals, whose every step takes a gcd, made
/// a fuzz input of many equal lengths take seconds).
#[cold]
#[inline(never)]
fn length_order_exact(p: [f64; 2], q: [f64; 2], r: [f64; 2], s: [f64; 2]) -> std::cmp::Ordering {
    let points = [p, q, r, s];
    let [fp, fq, fr, fs] = lift_filter(normalize(points).0);
    let ([sign], _) = signs(length_terms(&fp, &fq, &fr, &fs), || {
        let ([ep, eq, er, es], _) = lift_exact(points);
        length_terms(&ep, &eq, &er, &es)
    });
    match sign {
        Sign::Negative => std::cmp::Ordering::Less,
        Sign::Zero => std::cmp::Ordering::Equal,
        Sign::Positive => std::cmp::Ordering::Greater,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;
    use std::cmp::Ordering;

    fn reference(p: [f64; 2], q: [f64; 2], r: [f64; 2], s: [f64; 2]) -> Ordering {
        let rational = |x: f64| BigRational::from_float(x).unwrap();
        let squared = |a: [f64; 2], b: [f64; 2]| {
            let (dx, dy) = (
                rational(a[0]) - rational(b[0]),
                rational(a[1]) - rational(b[1]),
            );
            &dx * &dx + &dy * &dy
        };
        squared(p, q).cmp(&squared(r, s))
    }

    /// Equal lengths (3-4-5 against 5-0), then each endpoint nudged by one ulp either way, at
    /// scales where the rounded squares tie or underflow: the exact answer every time.
    #[test]
    fn length_order_is_exact_near_ties_and_at_extreme_scales() {
        let nudge = |x: f64, up: bool| {
            let bits = x.to_bits();
            let away = (x >= 0.0) == up;
            f64::from_bits(if x == 0.0 {
                1
            } else if away {
                bits + 1
            } else {
                bits - 1
            })
        };
        for scale in [1.0, 1e-160, 1e-300, 3e150, 0.1] {
            let base = [[0.0, 0.0], [3.0, 4.0], [1.0, 1.0], [6.0, 1.0]]
                .map(|[x, y]: [f64; 2]| [x * scale, y * scale]);
            assert_eq!(
                length_order(base[0], base[1], base[2], base[3]),
                reference(base[0], base[1], base[2], base[3])
            );
            for point in 0..4 {
                for axis in 0..2 {
                    for up in [false, true] {
                        let mut moved = base;
                        moved[point][axis] = nudge(moved[point][axis], up);
                        let [p, q, r, s] = moved;
                        assert_eq!(
                            length_order(p, q, r, s),
                            reference(p, q, r, s),
                            "scale {scale}, point {point}, axis {axis}, up {up}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn length_order_matches_rationals_on_random_segments() {
        let mut rng = wdm_crust_testkit::Rng::new(11);
        for _ in 0..20_000 {
            let scale = 10f64.powi(rng.below(40) as i32 - 20);
            let point =
                |rng: &mut wdm_crust_testkit::Rng| [rng.normal() * scale, rng.normal() * scale];
            let (p, q, r) = (point(&mut rng), point(&mut rng), point(&mut rng));
            // Half the time a segment of nearly the same length as pq.
            let s = if rng.below(2) == 0 {
                let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
                [r[0] + dy, r[1] - dx]
            } else {
                point(&mut rng)
            };
            assert_eq!(length_order(p, q, r, s), reference(p, q, r, s));
        }
    }
}
