//! The construction's static filter: per merge, one error bound for every test of points in
//! a known box, so that a test costs one floating-point evaluation and a comparison. The
//! bounds are those of `basic` (Shewchuk's), evaluated on the box extents; undecided tests go
//! to [`super::basic`]'s semi-static filter and exact stages.

use super::basic::{
    incircle_in, orient_in, CCW_BOUND, INCIRCLE_BOUND, INCIRCLE_SLACK, ORIENT_SLACK,
};
use super::Sign;

/// Error bounds valid for points in a box of width `w` and height `h`.
///
/// Rounding is monotone: with every coordinate difference at most the (rounded) box extent
/// in magnitude, every rounded product, sum and permanent of the evaluation is at most the
/// same expression evaluated on the extents. So the static bound is at least the semi-static
/// one of any test inside the box, underflow terms included, and deciding with it is as
/// safe. Extents that overflow make the bounds infinite: nothing is decided here then.
///
/// `IN_RANGE`: every coordinate is zero or of an exponent in the adaptive predicates' range
/// (`scale::ADAPTIVE_EXPONENTS`); then no product underflows, the bounds need no underflow
/// terms and the fallbacks skip the exact stage's range check (`basic::orient_in`).
#[derive(Debug, Clone, Copy)]
pub struct StaticFilter<const IN_RANGE: bool> {
    ccw: f64,
    incircle: f64,
}

impl<const IN_RANGE: bool> StaticFilter<IN_RANGE> {
    /// `w`, `h`: the extents `max − min` of the coordinates, evaluated in floating point.
    #[inline]
    pub fn for_box(w: f64, h: f64) -> StaticFilter<IN_RANGE> {
        let wh = w * h; // bounds |Δx·Δy| for any two differences
        let lift = w * w + h * h; // bounds Δx² + Δy²
        let pair = wh + wh;
        let permanent = pair * lift + pair * lift + pair * lift;
        if IN_RANGE {
            return StaticFilter {
                ccw: CCW_BOUND * pair,
                incircle: INCIRCLE_BOUND * permanent,
            };
        }
        // The underflow terms of `basic`, on the lifts' bound: every test's are at most these.
        let lifts = lift + lift + lift;
        StaticFilter {
            ccw: CCW_BOUND * pair + ORIENT_SLACK,
            incircle: INCIRCLE_BOUND * permanent + (lifts * INCIRCLE_SLACK + ORIENT_SLACK),
        }
    }

    /// [`super::basic::orient`] for points of this filter's input: the fallback of the
    /// static tests.
    #[inline(always)]
    pub fn orient_fallback(&self, a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
        orient_in::<IN_RANGE>(a, b, c)
    }

    /// [`super::basic::incircle`] for points of this filter's input.
    #[inline(always)]
    pub fn incircle_fallback(&self, a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Sign {
        incircle_in::<IN_RANGE>(a, b, c, d)
    }

    /// [`super::basic::orient`] for points in the box.
    #[inline(always)]
    pub fn orient(&self, a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Sign {
        let det = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
        if det > self.ccw {
            Sign::Positive
        } else if -det > self.ccw {
            Sign::Negative
        } else {
            self.orient_fallback(a, b, c)
        }
    }

    /// The sign of an orientation determinant `r × a` of [`Lifted`] differences (Shewchuk's
    /// evaluation of `orient2d(r, a, origin)`), if the bound decides it: `Positive` for
    /// counterclockwise `origin, r, a`.
    #[inline(always)]
    pub fn orientation(&self, cross: f64) -> Option<Sign> {
        if cross > self.ccw {
            Some(Sign::Positive)
        } else if -cross > self.ccw {
            Some(Sign::Negative)
        } else {
            None
        }
    }

    /// The in-circle sign of `b` and the circle through the counterclockwise `origin, r, a`
    /// (`Positive`: inside), if the bound decides it. All three are [`Lifted`] differences to the origin and `cross_ra = r × a`.
    ///
    /// This is Shewchuk's evaluation of the in-circle determinant with the origin as the
    /// fourth point: `incircle(origin, r, a, b) = −det[r; a; b]`, the rows lifted (a cyclic
    /// shift of the four rows flips the sign), evaluated in his order, so his bound holds.
    #[inline(always)]
    pub fn in_circle(&self, r: &Lifted, a: &Lifted, b: &Lifted, cross_ra: f64) -> Option<Sign> {
        let det =
            r.lift * (a.x * b.y - b.x * a.y) + a.lift * (b.x * r.y - r.x * b.y) + b.lift * cross_ra;
        if det > self.incircle {
            Some(Sign::Negative)
        } else if -det > self.incircle {
            Some(Sign::Positive)
        } else {
            None
        }
    }
}

/// A point as a difference to an origin, with its lifting `x² + y²`.
#[derive(Debug, Clone, Copy)]
pub struct Lifted {
    pub x: f64,
    pub y: f64,
    pub lift: f64,
}

impl Lifted {
    #[inline(always)]
    pub fn new(p: [f64; 2], origin: [f64; 2]) -> Lifted {
        let (x, y) = (p[0] - origin[0], p[1] - origin[1]);
        Lifted {
            x,
            y,
            lift: x * x + y * y,
        }
    }

    /// `self × a`, evaluated as Shewchuk's `orient2d(self, a, origin)`.
    #[inline(always)]
    pub fn cross(&self, a: &Lifted) -> f64 {
        self.x * a.y - self.y * a.x
    }
}
