//! Metric comparisons of input points, for the NN-crust: which of two points is closer to a
//! third, and on which side of the line orthogonal to `q − p` through `p` a point lies.
//! Degree-2 polynomials through the same stages as every kernel predicate.

use super::bounded::lift_filter;
use super::exact::{lift_exact, signs};
use super::filter;
use super::poly::{distance_terms, dot_points_terms};
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
