//! The one answer type of every kernel predicate.

use std::cmp::Ordering;

/// The sign of an exactly evaluated expression.
///
/// Every predicate of the kernel answers with it; the public named enums
/// ([`Orientation`](crate::predicates::Orientation),
/// [`CirclePosition`](crate::predicates::CirclePosition)) are views converted from it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Sign {
    /// Strictly below zero.
    Negative,
    /// Exactly zero.
    Zero,
    /// Strictly above zero.
    Positive,
}

impl Sign {
    /// The sign of a product.
    #[inline]
    pub(crate) fn times(self, other: Sign) -> Sign {
        match (self, other) {
            (Sign::Zero, _) | (_, Sign::Zero) => Sign::Zero,
            (a, b) if a == b => Sign::Positive,
            _ => Sign::Negative,
        }
    }

    /// The sign of `x` (NaN counts as zero; the kernel's exact stages never produce one).
    #[inline]
    pub(crate) fn of_f64(x: f64) -> Sign {
        if x > 0.0 {
            Sign::Positive
        } else if x < 0.0 {
            Sign::Negative
        } else {
            Sign::Zero
        }
    }

    /// `Positive` if `negative` is false, else `Negative`: the sign of a certified non-zero
    /// value.
    #[inline(always)]
    pub(crate) fn of_nonzero(negative: bool) -> Sign {
        if negative {
            Sign::Negative
        } else {
            Sign::Positive
        }
    }
}

impl From<Sign> for Ordering {
    /// `Negative` → `Less`, `Zero` → `Equal`, `Positive` → `Greater`: the order of the
    /// expression's value against zero.
    #[inline]
    fn from(s: Sign) -> Ordering {
        match s {
            Sign::Negative => Ordering::Less,
            Sign::Zero => Ordering::Equal,
            Sign::Positive => Ordering::Greater,
        }
    }
}
