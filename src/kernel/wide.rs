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

/// `|x|` of 2^-142 and of the largest `f64` below 2^201, as bits: positive `f64`s are
/// ordered as their bit patterns.
const RANGE_BITS: (u64, u64) = (0x3710_0000_0000_0000, 0x4c7f_ffff_ffff_ffff);

/// Whether `x` is zero or its exponent lies in [`ADAPTIVE_EXPONENTS`] (on the bits: this
/// check runs on every exact zero of ordinary input).
#[inline(always)]
fn in_range(x: f64) -> bool {
    let magnitude = x.to_bits() & !(1 << 63);
    let (lo, hi) = RANGE_BITS;
    (magnitude.wrapping_sub(lo) <= hi - lo) | (magnitude == 0)
}

/// The points times the power of two that puts them in the adaptive predicates' range, or
/// `None` if no single power of two does (or a coordinate is not finite).
/// Whether every coordinate is zero or of an exponent in the adaptive predicates' range:
/// then they are exact on these values as they are.
#[inline(always)]
pub(super) fn fits<const N: usize>(coordinates: [f64; N]) -> bool {
    coordinates.iter().fold(true, |ok, &x| ok & in_range(x))
}

#[inline(always)]
fn fitted<const N: usize>(points: [[f64; 2]; N]) -> Option<[[f64; 2]; N]> {
    if points
        .iter()
        .flatten()
        .fold(true, |ok, &x| ok & in_range(x))
    {
        return Some(points);
    }
    fitted_slow(points)
}

#[cold]
#[inline(never)]
fn fitted_slow<const N: usize>(points: [[f64; 2]; N]) -> Option<[[f64; 2]; N]> {
    if points.iter().flatten().any(|x| !x.is_finite()) {
        return None;
    }
    match Magnitudes::of(&points).adaptive_shift()? {
        0 => Some(points),
        s => Some(points.map(|p| p.map(|x| shift_by(x, s)))),
    }
}

/// The adaptive orientation predicate, for coordinates in its range.
#[inline(always)]
pub(super) fn adaptive_orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    Sign::of_f64(robust::orient2d(coord(a), coord(b), coord(c)))
}

/// The adaptive in-circle predicate, for coordinates in its range.
#[inline(always)]
pub(super) fn adaptive_incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Sign {
    Sign::of_f64(robust::incircle(coord(a), coord(b), coord(c), coord(d)))
}

/// The exact sign of the orientation determinant of `a → b → c`.
pub(super) fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
    if let Some([a, b, c]) = fitted([a, b, c]) {
        return adaptive_orient(a, b, c);
    }
    let ([a, b, c], _) = lift_exact([a, b, c]);
    let [v] = orient_terms_points(&a, &b, &c);
    integer_sign(&v)
}

/// The exact sign of the in-circle determinant of `a, b, c, d`.
pub(super) fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Sign {
    if let Some([a, b, c, d]) = fitted([a, b, c, d]) {
        return adaptive_incircle(a, b, c, d);
    }
    let ([a, b, c, d], _) = lift_exact([a, b, c, d]);
    let [v] = incircle_terms_points(&a, &b, &c, &d);
    integer_sign(&v)
}

#[cfg(test)]
mod tests {
    use super::super::scale::ADAPTIVE_EXPONENTS;
    use super::*;

    #[test]
    fn the_range_bits_are_the_adaptive_exponents() {
        let (lo, hi) = ADAPTIVE_EXPONENTS;
        let low = 2f64.powi(lo);
        let top = 2f64.powi(hi + 1);
        assert_eq!(RANGE_BITS, (low.to_bits(), top.to_bits() - 1));
        for x in [
            0.0,
            -0.0,
            low,
            -low,
            f64::from_bits(top.to_bits() - 1),
            1.0,
            -3.5e50,
        ] {
            assert!(in_range(x), "{x:e}");
        }
        for x in [
            f64::from_bits(low.to_bits() - 1),
            -top,
            top,
            f64::MAX,
            5e-324,
            f64::NAN,
            f64::INFINITY,
        ] {
            assert!(!in_range(x), "{x:e}");
        }
    }
}
