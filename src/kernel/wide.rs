//! The exact stage of orientation and in-circle for inputs of any finite magnitude.
//!
//! `robust`'s adaptive predicates are exact only while their expansions neither underflow nor
//! overflow: for non-zero coordinates of exponents in [`ADAPTIVE_EXPONENTS`]. The predicates
//! are homogeneous, so inputs outside that range whose exponents span no more than it are
//! multiplied by one power of two (exactly, which changes no sign) and handed to them;
//! inputs spread wider than that (`1e-300` beside `1e300`, subnormals beside large values)
//! are evaluated exactly in integers (`super::exact`): every `f64` is a dyadic rational.

use super::exact::{integer_sign, lift_exact};
use super::poly::{incircle_terms_points, orient_terms_points};
use super::scale::{shift_by, Magnitudes};
use super::Sign;

#[inline]
fn coord(p: [f64; 2]) -> robust::Coord<f64> {
    robust::Coord { x: p[0], y: p[1] }
}

/// The points times the power of two that puts them in the adaptive predicates' range, or
/// `None` if no single power of two does (or a coordinate is not finite).
fn fitted<const N: usize>(points: [[f64; 2]; N]) -> Option<[[f64; 2]; N]> {
    if points.iter().flatten().any(|x| !x.is_finite()) {
        return None;
    }
    match Magnitudes::of(&points).adaptive_shift()? {
        0 => Some(points),
        s => Some(points.map(|p| p.map(|x| shift_by(x, s)))),
    }
}

/// The exact sign of the orientation determinant of `a → b → c`.
pub(super) fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    if let Some([a, b, c]) = fitted([a, b, c]) {
        return Sign::of_f64(robust::orient2d(coord(a), coord(b), coord(c)));
    }
    let ([a, b, c], _) = lift_exact([a, b, c]);
    let [v] = orient_terms_points(&a, &b, &c);
    integer_sign(&v)
}

/// The exact sign of the in-circle determinant of `a, b, c, d`.
pub(super) fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Sign {
    if let Some([a, b, c, d]) = fitted([a, b, c, d]) {
        return Sign::of_f64(robust::incircle(coord(a), coord(b), coord(c), coord(d)));
    }
    let ([a, b, c, d], _) = lift_exact([a, b, c, d]);
    let [v] = incircle_terms_points(&a, &b, &c, &d);
    integer_sign(&v)
}
