//! The ring operations every stage evaluates a polynomial with: each polynomial of the
//! kernel is written once, generic over [`Arith`], and evaluated by the semi-static filter
//! (`filter::Sf`), the running-error filter (`bounded::Bounded`) and exactly (`BigInt`).

use super::Sign;

/// Unit roundoff of `f64`: 2^-53.
pub(super) const U: f64 = f64::EPSILON / 2.0;

/// Ring operations shared by the filter type and the exact type.
pub(super) trait Arith: Sized {
    /// `self + other`.
    fn add(&self, other: &Self) -> Self;
    /// `self − other`.
    fn sub(&self, other: &Self) -> Self;
    /// `self · other`.
    fn mul(&self, other: &Self) -> Self;
    /// `self − other` for two input coordinates: a leaf of the expression. The same as
    /// [`Arith::sub`] except in the semi-static filter, which bounds errors relative to the
    /// leaves.
    #[inline(always)]
    fn leaf_sub(&self, other: &Self) -> Self {
        self.sub(other)
    }
    /// `2 · self`.
    fn twice(&self) -> Self {
        self.add(self)
    }
    /// The sign, if this representation can certify it.
    fn sign(&self) -> Option<Sign>;
}
