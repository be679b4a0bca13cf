//! The circumcenter of three `f64` points: its formula, written once and generic over the
//! number type, and the constructions on it (the `f64` circumcenter — filtered, else in
//! double words, else exact and rounded —, the exact rational one, and the homogeneous exact
//! and bounded forms the mixed predicates take).
//!
//! With a triangle translated to its first vertex `t0`, `b = t1 − t0`, `c = t2 − t0`, the
//! circumcenter is `O = t0 + (ux, uy) / d` with `d = 2 (bx·cy − by·cx)`,
//! `ux = cy·|b|² − by·|c|²`, `uy = bx·|c|² − cx·|b|²`.

use num_bigint::{BigInt, Sign as BigSign};
use num_rational::BigRational;
use num_traits::Zero;

use super::arith::Arith;
use super::bounded::{lift_filter, Bounded};
use super::double_word;
use super::exact::{lift_exact, ratio_to_f64, rational_to_f64};
use super::filter;
use super::poly::{cross, diff, norm2, Pt};
use super::scale::{rescale, scale};
use super::stats::{self, Stage, Which};
use super::thin;

/// The circumcenter of a triangle in homogeneous form relative to its first vertex `t0`:
/// `O = t0 + (ux, uy) / d`.
pub(super) struct Circ<T> {
    /// `2 (bx·cy − by·cx)` with `b = t1 − t0`, `c = t2 − t0`: positive iff the triangle is CCW.
    pub(super) d: T,
    pub(super) ux: T,
    pub(super) uy: T,
}

/// `(bx·cy − by·cx, ux, uy)`: the circumcenter relative to `t0` is `u / (2·cross)`.
#[inline(always)]
pub(super) fn circ_half<T: Arith>(t: &[Pt<T>; 3]) -> (T, T, T) {
    let b = diff(&t[1], &t[0]);
    let c = diff(&t[2], &t[0]);
    let b2 = norm2(&b);
    let c2 = norm2(&c);
    let ux = c[1].mul(&b2).sub(&b[1].mul(&c2));
    let uy = b[0].mul(&c2).sub(&c[0].mul(&b2));
    (cross(&b, &c), ux, uy)
}

#[inline(always)]
pub(super) fn circ<T: Arith>(t: &[Pt<T>; 3]) -> Circ<T> {
    let (x, ux, uy) = circ_half(t);
    Circ {
        d: x.twice(),
        ux,
        uy,
    }
}

/// A point with exact rational coordinates, such as a circumcenter of `f64` points.
///
/// This is the crate's one exact accessor: [`ExactPoint::x`] and [`ExactPoint::y`] expose
/// the coordinates as `num_rational::BigRational`; everything else answers in `f64` or signs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExactPoint {
    x: BigRational,
    y: BigRational,
}

impl ExactPoint {
    /// The exact point `(x, y)`; `0` for a non-finite coordinate.
    pub(crate) fn from_f64(p: [f64; 2]) -> ExactPoint {
        let r = |x: f64| BigRational::from_float(x).unwrap_or_default();
        ExactPoint {
            x: r(p[0]),
            y: r(p[1]),
        }
    }

    /// The exact x coordinate.
    pub fn x(&self) -> &BigRational {
        &self.x
    }

    /// The exact y coordinate.
    pub fn y(&self) -> &BigRational {
        &self.y
    }

    /// Both coordinates correctly rounded to the nearest `f64` (ties to even); a coordinate
    /// beyond the `f64` range becomes infinite.
    ///
    /// ```
    /// use wdm_crust::predicates::circumcenter_exact;
    /// let o = circumcenter_exact([0.0, 0.0], [1.0, 0.0], [0.0, 3.0]).unwrap();
    /// assert_eq!(o.to_f64(), [0.5, 1.5]);
    /// ```
    pub fn to_f64(&self) -> [f64; 2] {
        [rational_to_f64(&self.x), rational_to_f64(&self.y)]
    }
}

/// `o · 2^k` if that is exact and its larger coordinate is normal, so that the relative
/// error bound and its ulp reading carry over.
fn scale_back(o: [f64; 2], k: i32) -> Option<[f64; 2]> {
    let [out] = scale([o], -k)?;
    (out[0].abs().max(out[1].abs())).is_normal().then_some(out)
}

/// The exact circumcenter `O = (t0·d + u) / d · 2^shift` of `t` in integer units of
/// `2^shift`: `([t0x·d + ux, t0y·d + uy], d, shift)`, or `None` iff `t` is collinear (or a
/// coordinate is not finite).
fn exact_parts(t: [[f64; 2]; 3]) -> Option<([BigInt; 2], BigInt, i32)> {
    if t.iter().flatten().any(|x| !x.is_finite()) {
        return None;
    }
    let ([t0, t1, t2], shift) = lift_exact(t);
    let circ = circ(&[t0.clone(), t1, t2]);
    if circ.d.is_zero() {
        return None;
    }
    let numer = [&t0[0] * &circ.d + &circ.ux, &t0[1] * &circ.d + &circ.uy];
    Some((numer, circ.d, shift))
}

/// The exact circumcenter of `t` in homogeneous integer coordinates `(X, Y, W)`, `W > 0`,
/// or `None` iff `t` is collinear (or a coordinate is not finite).
pub(super) fn circumcenter_homogeneous(t: [[f64; 2]; 3]) -> Option<[BigInt; 3]> {
    let ([x, y], w, shift) = exact_parts(t)?;
    let [x, y, w] = if w.sign() == BigSign::Minus {
        [-x, -y, -w]
    } else {
        [x, y, w]
    };
    let k = shift.unsigned_abs();
    Some(if shift >= 0 {
        [x << k, y << k, w]
    } else {
        [x, y, w << k]
    })
}

/// The input point `p` in homogeneous integer coordinates `(X, Y, W)`, `W > 0`.
pub(super) fn point_homogeneous(p: [f64; 2]) -> [BigInt; 3] {
    let ([[x, y]], shift) = lift_exact([p]);
    let k = shift.unsigned_abs();
    if shift >= 0 {
        [x << k, y << k, BigInt::from(1)]
    } else {
        [x, y, BigInt::from(1) << k]
    }
}

/// The exact circumcenter of `a, b, c`, correctly rounded, or `None` iff they are collinear
/// (or a coordinate is not finite). The same as `circumcenter_exact(a, b, c)?.to_f64()`,
/// without reducing the fractions.
pub(super) fn circumcenter_rounded(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<[f64; 2]> {
    let (numer, d, shift) = exact_parts([a, b, c])?;
    let d_negative = d.sign() == BigSign::Minus;
    Some(numer.map(|n| {
        let negative = (n.sign() == BigSign::Minus) != d_negative;
        ratio_to_f64(negative, n.magnitude(), d.magnitude(), i64::from(shift))
    }))
}

/// The circumcenter of `t` with running error bounds, if they are within `2^-30` of its
/// coordinates' magnitudes (looser ones would seldom decide a predicate: the caller takes
/// the exact point instead).
pub(super) fn circumcenter_bounded(t: [[f64; 2]; 3]) -> Option<[Bounded; 2]> {
    let c = circ(&lift_filter(t));
    let x = Bounded::from_f64(t[0][0]).add(&c.ux.div(&c.d)?);
    let y = Bounded::from_f64(t[0][1]).add(&c.uy.div(&c.d)?);
    let tight = |b: &Bounded| {
        b.v.is_finite() && b.e <= 9.313225746154785e-10 * b.v.abs().max(f64::MIN_POSITIVE)
    };
    (tight(&x) && tight(&y)).then_some([x, y])
}

/// [`circumcenter`] after the fast filter failed, and the stage that decided: the filter
/// again after an exact power-of-two rescale (huge or tiny spreads), then double words
/// (`double_word`: nearly collinear triangles), then the exact circumcenter rounded.
#[cold]
#[inline(never)]
pub(super) fn circumcenter_slow(
    a: [f64; 2],
    b: [f64; 2],
    c: [f64; 2],
) -> (Option<[f64; 2]>, Stage) {
    let rescaled = rescale([a, b, c], filter::LEAF_RANGE);
    if let Some((s, k)) = rescaled {
        if let Some(o) = filter::circumcenter(&s).and_then(|o| scale_back(o, k)) {
            return (Some(o), Stage::Filter);
        }
    }
    let (t, k) = rescaled.unwrap_or(([a, b, c], 0));
    // On the rescaled triangle, as every later stage: the result then scales exactly with
    // the input.
    if let Some(o) = widest_angle_first(t)
        .and_then(|r| filter::circumcenter(&r))
        .and_then(|o| scale_back(o, k))
    {
        return (Some(o), Stage::Filter);
    }
    if let Some(o) = thin::circumcenter(&t).and_then(|o| scale_back(o, k)) {
        return (Some(o), Stage::DoubleWord);
    }
    if let Some(o) = double_word::circumcenter(&t).and_then(|o| scale_back(o, k)) {
        return (Some(o), Stage::DoubleWord);
    }
    (circumcenter_rounded(a, b, c), Stage::Exact)
}

/// The triangle rotated to start at the vertex opposite its longest edge (its widest angle),
/// or `None` if it already does (or a length is NaN).
///
/// The formula translates the triangle to its first vertex. From the vertex of the
/// *narrowest* angle, the apex of a sliver (two close points and a far one: a pair of
/// consecutive curve samples and a sample across the shape), the two products of the cross
/// product nearly cancel, and the filter cannot prove its bound; from a vertex of the short
/// edge they do not. Such slivers were half of the triangles that left the filter on points
/// of a smooth curve (453 040 of 831 344 in one diagram of 10^6 points). The lengths are
/// rounded: they only choose which certified evaluation to try.
fn widest_angle_first([a, b, c]: [[f64; 2]; 3]) -> Option<[[f64; 2]; 3]> {
    let squared = |p: [f64; 2], q: [f64; 2]| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2);
    let (ab, bc, ca) = (squared(a, b), squared(b, c), squared(c, a));
    if ca > bc && ca >= ab {
        Some([b, c, a])
    } else if ab > bc && ab > ca {
        Some([c, a, b])
    } else {
        None
    }
}

/// The exact circumcenter of `a, b, c`, or `None` iff they are collinear (or a coordinate is
/// not finite).
///
/// ```
/// use num_rational::BigRational;
/// use wdm_crust::predicates::circumcenter_exact;
/// let o = circumcenter_exact([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]).unwrap();
/// assert_eq!(o.x(), &BigRational::from_float(0.5).unwrap());
/// assert!(circumcenter_exact([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]).is_none());
/// ```
pub fn circumcenter_exact(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<ExactPoint> {
    let [x, y, w] = circumcenter_homogeneous([a, b, c])?;
    Some(ExactPoint {
        x: BigRational::new(x, w.clone()),
        y: BigRational::new(y, w),
    })
}

/// The circumcenter of `a, b, c` in `f64`, or `None` iff they are exactly collinear.
///
/// Each coordinate is within 256 units in the last place of `N` of the exact circumcenter
/// `O`, where `N` is the larger magnitude of the two returned coordinates (a normwise
/// relative error below `2^-44`). This is proven per call: by an a priori error bound of the
/// floating-point formula translated to `a` (one division), or where that is too coarse
/// (nearly collinear triangles) by the same formula with exact products and a closed-form
/// bound, or in double-word arithmetic (about 106 bits) with a running error bound; where
/// none proves it (triangles within about `2^-60`
/// of collinear, results near the ends of the `f64` range) the exact circumcenter is computed
/// and correctly rounded instead. The result is a function of `a, b, c` alone. A coordinate
/// beyond the `f64` range (a nearly collinear triangle of huge points) is infinite.
///
/// ```
/// use wdm_crust::predicates::circumcenter;
/// assert_eq!(circumcenter([1.0, 1.0], [3.0, 1.0], [1.0, 5.0]), Some([2.0, 3.0]));
/// assert_eq!(circumcenter([0.0, 0.0], [1.0, 2.0], [2.0, 4.0]), None);
/// ```
#[inline]
pub fn circumcenter(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<[f64; 2]> {
    stats::calls(Which::Circumcenter, 1);
    if let Some(o) = filter::circumcenter(&[a, b, c]) {
        return Some(o);
    }
    let (o, stage) = circumcenter_slow(a, b, c);
    stats::slow(Which::Circumcenter, stage);
    o
}
