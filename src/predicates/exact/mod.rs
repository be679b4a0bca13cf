//! Exact predicates on constructed points: circumcenters of triangles with `f64` vertices.
//!
//! The water-flow labeling decides things about Voronoi vertices, which are circumcenters
//! and not input points: on which side of a line a circumcenter lies
//! ([`orient2d_circumcenter`]), on which side of the line through a sample orthogonal to its
//! source direction ([`dot_sign_circumcenters`]), which of two circumradii is larger
//! ([`compare_circumradius`]) and whether a circumcenter lies in the convex hull
//! ([`circumcenter_in_convex_hull`]). Every answer here is the one exact arithmetic on the
//! `f64` inputs gives.
//!
//! # Method
//!
//! Each predicate is one polynomial in the coordinate differences of its inputs (no
//! divisions: a circumcenter `O = t0 + u/d` enters as `d·(O − p) = d·(t0 − p) + u`, its sign
//! corrected by the sign of `d`), written once and evaluated in up to three stages:
//!
//! 1. A semi-static filter: the polynomial in plain `f64`, and beside it the same polynomial
//!    on absolute values (the permanent `Â`); the sign is certain when
//!    `|v̂| > (K + 1)·2^-53·Â + c0`, `K` the length of the longest chain of operations and `c0`
//!    an absolute term for underflow, with the leaves below a fixed bound. The bound is proven
//!    in the `filter` module (private) and its constants are recomputed from the evaluated
//!    code by a test. Inputs whose differences are huge or tiny are first scaled by a power of
//!    two (exactly; no sign changes) and filtered again.
//! 2. A running-error filter: the same polynomial with a rigorous error bound propagated
//!    through every operation, with upward-rounded bounds and exact `TwoProduct` errors where
//!    the operands are exact, after scaling the points by a power of two. Tighter than stage 1;
//!    in particular it certifies exact zeros when every operation was exact in `f64`.
//! 3. Exact evaluation: all `f64` inputs of the call are written as integers times one common
//!    power of two (every `f64` is a dyadic rational), so exact rational arithmetic reduces to
//!    [`BigInt`] arithmetic.
//!
//! Ordinary input is decided by stage 1 alone; exact zeros (right angles, cocircular and
//! symmetric configurations) always reach stage 2 and, unless all its operations were exact,
//! stage 3. [`fallback_counts`] reports how often that happens.
//!
//! # Degenerate input
//!
//! A collinear triangle (including one with repeated vertices) has no circumcenter: every
//! predicate then returns an unspecified answer, deterministically and without panicking.
//! The same holds for non-finite coordinates. No function here panics on any input.
//!
//! ```
//! use std::cmp::Ordering;
//! use wdm_crust::predicates::exact::{circumcenter, compare_circumradius};
//!
//! // A right triangle: the circumcenter is the midpoint of the hypotenuse.
//! assert_eq!(circumcenter([0.0, 0.0], [4.0, 0.0], [0.0, 2.0]), Some([2.0, 1.0]));
//! // Congruent triangles (one translated and reflected) have equal circumradii.
//! let t1 = [[0.0, 0.0], [3.0, 0.0], [1.0, 2.0]];
//! let t2 = [[10.0, 5.0], [10.0, 8.0], [12.0, 6.0]];
//! assert_eq!(compare_circumradius(t1, t2), Ordering::Equal);
//! ```

mod arith;
mod filter;
mod poly;

use std::cmp::Ordering;
use std::sync::atomic::{AtomicU64, Ordering as AtomicOrdering};

use num_bigint::{BigInt, Sign as BigSign};
use num_rational::BigRational;
use num_traits::Zero;

use self::arith::{
    integer_sign, lift_exact, lift_filter, pow2, ratio_to_f64, rational_to_f64, Arith, Bounded,
};
use self::poly::{circ, dot_terms, orient_terms, radius_terms, Circ};
use super::{orient2d, Orientation};

/// The sign of an exactly evaluated expression.
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
    fn times(self, other: Sign) -> Sign {
        match (self, other) {
            (Sign::Zero, _) | (_, Sign::Zero) => Sign::Zero,
            (a, b) if a == b => Sign::Positive,
            _ => Sign::Negative,
        }
    }
}

/// Where a point lies relative to a closed convex polygon.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HullPosition {
    /// In the interior.
    Inside,
    /// Exactly on the boundary (an edge or a vertex).
    OnBoundary,
    /// Strictly outside.
    Outside,
}

/// A point with exact rational coordinates, such as a circumcenter of `f64` points.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExactPoint {
    /// The x coordinate.
    pub x: BigRational,
    /// The y coordinate.
    pub y: BigRational,
}

impl ExactPoint {
    /// Both coordinates correctly rounded to the nearest `f64` (ties to even); a coordinate
    /// beyond the `f64` range becomes infinite.
    ///
    /// ```
    /// use wdm_crust::predicates::exact::circumcenter_exact;
    /// let o = circumcenter_exact([0.0, 0.0], [1.0, 0.0], [0.0, 3.0]).unwrap();
    /// assert_eq!(o.to_f64(), [0.5, 1.5]);
    /// ```
    pub fn to_f64(&self) -> [f64; 2] {
        [rational_to_f64(&self.x), rational_to_f64(&self.y)]
    }
}

// ---------------------------------------------------------------------------------------
// Fallback statistics.

/// How often one predicate was called and how often its fast filter could not decide.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PredicateCounts {
    /// Number of calls.
    pub calls: u64,
    /// Number of calls the fast (semi-static) filter could not decide on the input as given:
    /// they were rescaled, or went on to the running-error filter.
    pub slow: u64,
    /// Number of calls that needed exact rational arithmetic (a subset of `slow`).
    pub exact: u64,
}

/// Global call and fallback counts of the filtered predicates, since the start of the
/// process or the last [`reset_fallback_counts`].
///
/// The counters are relaxed atomics shared by all threads, so a snapshot taken while other
/// threads run predicates mixes their calls in.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct FallbackCounts {
    /// [`orient2d_circumcenter`] (direct calls only, not those made by the hull test).
    pub orient2d_circumcenter: PredicateCounts,
    /// [`dot_sign_circumcenters`].
    pub dot_sign_circumcenters: PredicateCounts,
    /// [`compare_circumradius`].
    pub compare_circumradius: PredicateCounts,
    /// [`circumcenter_in_convex_hull`]; a call counts as slow (exact) if any of its
    /// orientation tests was.
    pub circumcenter_in_convex_hull: PredicateCounts,
    /// [`circumcenter`]; a call counts as exact if the coordinates were rounded from the exact
    /// circumcenter.
    pub circumcenter: PredicateCounts,
}

impl FallbackCounts {
    /// The counts accumulated between `earlier` and `self` (saturating at zero).
    pub fn since(&self, earlier: &FallbackCounts) -> FallbackCounts {
        let d = |a: PredicateCounts, b: PredicateCounts| PredicateCounts {
            calls: a.calls.saturating_sub(b.calls),
            slow: a.slow.saturating_sub(b.slow),
            exact: a.exact.saturating_sub(b.exact),
        };
        FallbackCounts {
            orient2d_circumcenter: d(self.orient2d_circumcenter, earlier.orient2d_circumcenter),
            dot_sign_circumcenters: d(self.dot_sign_circumcenters, earlier.dot_sign_circumcenters),
            compare_circumradius: d(self.compare_circumradius, earlier.compare_circumradius),
            circumcenter_in_convex_hull: d(
                self.circumcenter_in_convex_hull,
                earlier.circumcenter_in_convex_hull,
            ),
            circumcenter: d(self.circumcenter, earlier.circumcenter),
        }
    }
}

/// Which stage decided a call.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Stage {
    /// The semi-static filter, possibly after rescaling.
    Filter,
    /// The running-error filter.
    Bounded,
    /// Exact arithmetic.
    Exact,
}

struct Counter {
    calls: AtomicU64,
    slow: AtomicU64,
    exact: AtomicU64,
}

impl Counter {
    const fn new() -> Counter {
        Counter {
            calls: AtomicU64::new(0),
            slow: AtomicU64::new(0),
            exact: AtomicU64::new(0),
        }
    }

    #[inline(always)]
    fn call(&self) {
        self.calls.fetch_add(1, AtomicOrdering::Relaxed);
    }

    /// Records a call that left the fast filter, decided by `stage`.
    #[cold]
    fn slow(&self, stage: Stage) {
        self.slow.fetch_add(1, AtomicOrdering::Relaxed);
        if stage == Stage::Exact {
            self.exact.fetch_add(1, AtomicOrdering::Relaxed);
        }
    }

    fn read(&self) -> PredicateCounts {
        PredicateCounts {
            calls: self.calls.load(AtomicOrdering::Relaxed),
            slow: self.slow.load(AtomicOrdering::Relaxed),
            exact: self.exact.load(AtomicOrdering::Relaxed),
        }
    }

    fn reset(&self) {
        self.calls.store(0, AtomicOrdering::Relaxed);
        self.slow.store(0, AtomicOrdering::Relaxed);
        self.exact.store(0, AtomicOrdering::Relaxed);
    }
}

static ORIENT: Counter = Counter::new();
static DOT: Counter = Counter::new();
static RADIUS: Counter = Counter::new();
static HULL: Counter = Counter::new();
static CIRCUMCENTER: Counter = Counter::new();

/// A snapshot of the global call and fallback counters.
///
/// ```
/// use wdm_crust::predicates::exact::{fallback_counts, orient2d_circumcenter};
/// let before = fallback_counts();
/// orient2d_circumcenter([5.0, 0.0], [5.0, 1.0], [[0.0, 0.0], [3.0, 0.0], [0.0, 4.0]]);
/// let delta = fallback_counts().since(&before);
/// assert!(delta.orient2d_circumcenter.calls >= 1);
/// ```
pub fn fallback_counts() -> FallbackCounts {
    FallbackCounts {
        orient2d_circumcenter: ORIENT.read(),
        dot_sign_circumcenters: DOT.read(),
        compare_circumradius: RADIUS.read(),
        circumcenter_in_convex_hull: HULL.read(),
        circumcenter: CIRCUMCENTER.read(),
    }
}

/// Sets all counters of [`fallback_counts`] to zero.
pub fn reset_fallback_counts() {
    for c in [&ORIENT, &DOT, &RADIUS, &HULL, &CIRCUMCENTER] {
        c.reset();
    }
}

// ---------------------------------------------------------------------------------------
// Scaling by powers of two.

/// `floor(log2 |x|)` for a normal `x`; `-1023` for zero and subnormals.
fn exponent(x: f64) -> i32 {
    ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023
}

/// The points times `2^-k`, if every product is exact (no overflow, no bits lost below the
/// normal range).
fn scale<const N: usize>(points: [[f64; 2]; N], k: i32) -> Option<[[f64; 2]; N]> {
    let (down, back) = (pow2(-k), pow2(k));
    let mut scaled = points;
    for c in scaled.iter_mut().flatten() {
        let s = *c * down;
        // Scaling back by 2^k is exact here, so a round trip detects any rounding.
        if s * back != *c {
            return None;
        }
        *c = s;
    }
    Some(scaled)
}

/// For the semi-static filter: the points scaled by `2^-k` where `2^k` is the largest
/// coordinate difference from the first point rounded down to a power of two (every leaf of
/// the scaled polynomials is then below 4), and `k`; `None` if that difference is already
/// in `[2^lo, 2^(hi − 1))` (rescaling would not help), zero or not finite, or if the
/// scaling is not exact.
fn rescale<const N: usize>(
    points: [[f64; 2]; N],
    (lo, hi): (i32, i32),
) -> Option<([[f64; 2]; N], i32)> {
    let p0 = points[0];
    let spread = points.iter().fold(0.0f64, |m, p| {
        m.max((p[0] - p0[0]).abs()).max((p[1] - p0[1]).abs())
    });
    if !(spread > 0.0 && spread < f64::INFINITY) {
        return None;
    }
    let k = exponent(spread);
    if (lo..hi - 1).contains(&k) {
        return None;
    }
    scale(points, k).map(|s| (s, k))
}

/// Magnitudes in this range are evaluated unscaled by the running-error filter: even
/// degree-10 terms of coordinate differences then stay far from overflow, and far from
/// underflow unless the differences themselves are tiny.
const UNSCALED_MIN: f64 = 9.094947017729282e-13; // 2^-40
const UNSCALED_MAX: f64 = 1099511627776.0; // 2^40

/// For the running-error filter: scales all points by one power of two `2^-k` such that
/// the largest coordinate magnitude falls in `[1, 2)`, when their magnitudes are outside
/// `[2^-40, 2^40]` and the scaling is exact for every coordinate. Returns the points and `k`
/// (original = scaled · 2^k).
fn normalize<const N: usize>(points: [[f64; 2]; N]) -> ([[f64; 2]; N], i32) {
    let max = points.iter().flatten().fold(0.0f64, |m, c| m.max(c.abs()));
    if !max.is_finite() || max == 0.0 || (UNSCALED_MIN..=UNSCALED_MAX).contains(&max) {
        return (points, 0);
    }
    let k = exponent(max);
    match scale(points, k) {
        Some(scaled) => (scaled, k),
        None => (points, 0),
    }
}

// ---------------------------------------------------------------------------------------
// The slower stages.

/// The signs of `terms` evaluated by the running-error filter on `filtered`, or else exactly
/// on `exact`, and the stage that decided.
fn signs<const K: usize>(
    filtered: [Bounded; K],
    exact: impl FnOnce() -> [BigInt; K],
) -> ([Sign; K], Stage) {
    let mut out = [Sign::Zero; K];
    let mut decided = true;
    for (o, b) in out.iter_mut().zip(filtered.iter()) {
        match b.sign() {
            Some(s) => *o = s,
            None => decided = false,
        }
    }
    if decided {
        return (out, Stage::Bounded);
    }
    let values = exact();
    for (o, v) in out.iter_mut().zip(values.iter()) {
        *o = integer_sign(v);
    }
    (out, Stage::Exact)
}

/// `p == q`, without the slice comparison machinery.
#[inline(always)]
fn same(p: [f64; 2], q: [f64; 2]) -> bool {
    (p[0] == q[0]) & (p[1] == q[1])
}

/// Puts `p` first if it is a vertex of `t` (a cyclic shift keeps the orientation): the
/// translation `t0 − p` is then an exact zero and the filters sharper.
#[inline(always)]
fn rotate_to(t: [[f64; 2]; 3], p: [f64; 2]) -> [[f64; 2]; 3] {
    if same(t[1], p) {
        [t[1], t[2], t[0]]
    } else if same(t[2], p) {
        [t[2], t[0], t[1]]
    } else {
        t
    }
}

fn orientation_of(s: Sign) -> Orientation {
    match s {
        Sign::Positive => Orientation::CounterClockwise,
        Sign::Negative => Orientation::Clockwise,
        Sign::Zero => Orientation::Collinear,
    }
}

/// Orientation of `(a, b, O(tri))` after the fast filter failed, `None` if `tri` is
/// collinear; and the stage that decided.
#[cold]
#[inline(never)]
fn orient_slow(a: [f64; 2], b: [f64; 2], tri: [[f64; 2]; 3]) -> (Option<Orientation>, Stage) {
    let tri = rotate_to(tri, a);
    let points = [a, b, tri[0], tri[1], tri[2]];
    if let Some(([a, b, t0, t1, t2], _)) = rescale(points, filter::LEAF_RANGE) {
        if let Some(s) = filter::orient(a, b, &[t0, t1, t2]) {
            return (Some(orientation_of(s)), Stage::Filter);
        }
    }
    let [fa, fb, f0, f1, f2] = lift_filter(normalize(points).0);
    let ([d, v], stage) = signs(orient_terms(&fa, &fb, &[f0, f1, f2]), || {
        let ([ea, eb, e0, e1, e2], _) = lift_exact(points);
        orient_terms(&ea, &eb, &[e0, e1, e2])
    });
    if d == Sign::Zero {
        return (None, stage);
    }
    (Some(orientation_of(v.times(d))), stage)
}

/// [`dot_sign_circumcenters`] after the fast filter failed (`s`, `o` rotated to `p`).
#[cold]
#[inline(never)]
fn dot_slow(p: [f64; 2], s: [[f64; 2]; 3], o: [[f64; 2]; 3]) -> (Sign, Stage) {
    let points = [p, s[0], s[1], s[2], o[0], o[1], o[2]];
    if let Some(([p, s0, s1, s2, o0, o1, o2], _)) = rescale(points, filter::LEAF_RANGE) {
        if let Some(sign) = filter::dot(p, &[s0, s1, s2], &[o0, o1, o2]) {
            return (sign, Stage::Filter);
        }
    }
    let [fp, f0, f1, f2, g0, g1, g2] = lift_filter(normalize(points).0);
    let ([ds, dother, v], stage) = signs(dot_terms(&fp, &[f0, f1, f2], &[g0, g1, g2]), || {
        let ([ep, e0, e1, e2, h0, h1, h2], _) = lift_exact(points);
        dot_terms(&ep, &[e0, e1, e2], &[h0, h1, h2])
    });
    (v.times(ds).times(dother), stage)
}

/// [`compare_circumradius`] after the fast filter failed: the sign of `R1 − R2`.
#[cold]
#[inline(never)]
fn radius_slow(t1: [[f64; 2]; 3], t2: [[f64; 2]; 3]) -> (Sign, Stage) {
    let points = [t1[0], t1[1], t1[2], t2[0], t2[1], t2[2]];
    if let Some(([a0, a1, a2, b0, b1, b2], _)) = rescale(points, filter::LEAF_RANGE_RADIUS) {
        if let Some(sign) = filter::radius(&[a0, a1, a2], &[b0, b1, b2]) {
            return (sign, Stage::Filter);
        }
    }
    let [f0, f1, f2, g0, g1, g2] = lift_filter(normalize(points).0);
    let ([v], stage) = signs(radius_terms(&[f0, f1, f2], &[g0, g1, g2]), || {
        let ([e0, e1, e2, h0, h1, h2], _) = lift_exact(points);
        radius_terms(&[e0, e1, e2], &[h0, h1, h2])
    });
    (v, stage)
}

/// Every coordinate of [`circumcenter`] is within this many units in the last place of the
/// larger output coordinate magnitude of the exact circumcenter.
const CIRCUMCENTER_ULPS: f64 = 256.0;

/// The unit in the last place of a positive normal `x`.
fn ulp_of_normal(x: f64) -> f64 {
    f64::from_bits(x.to_bits() & 0x7ff0_0000_0000_0000) * f64::EPSILON
}

/// `o · 2^k` if that is exact and its larger coordinate is normal, so that the relative
/// error bound and its ulp reading carry over.
fn scale_back(o: [f64; 2], k: i32) -> Option<[f64; 2]> {
    let [out] = scale([o], -k)?;
    (out[0].abs().max(out[1].abs())).is_normal().then_some(out)
}

/// The circumcenter `t0 + u/d` from running-error values of points scaled by `2^-k`,
/// rescaled, if its proven error is within 256 units in the last place of its larger
/// coordinate magnitude.
fn fast_circumcenter(c: &Circ<Bounded>, t0: [f64; 2], k: i32) -> Option<[f64; 2]> {
    let x = Bounded::from_f64(t0[0]).add(&c.ux.div(&c.d)?);
    let y = Bounded::from_f64(t0[1]).add(&c.uy.div(&c.d)?);
    let norm = x.v.abs().max(y.v.abs());
    if norm == 0.0 {
        return (x.e == 0.0 && y.e == 0.0).then_some([0.0, 0.0]);
    }
    if !(x.v.is_finite() && y.v.is_finite() && norm.is_normal()) {
        return None;
    }
    let tolerance = CIRCUMCENTER_ULPS * ulp_of_normal(norm);
    let accurate = x.e <= tolerance && y.e <= tolerance; // false for NaN
    if !accurate {
        return None;
    }
    scale_back([x.v, y.v], k)
}

/// The exact circumcenter of `a, b, c`, correctly rounded, or `None` iff they are collinear
/// (or a coordinate is not finite). The same as `circumcenter_exact(a, b, c)?.to_f64()`,
/// without reducing the fractions.
fn circumcenter_rounded(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<[f64; 2]> {
    if [a, b, c].iter().flatten().any(|x| !x.is_finite()) {
        return None;
    }
    // In integer units of 2^shift: O = t0 + u/d.
    let ([t0, t1, t2], shift) = lift_exact([a, b, c]);
    let circ = circ(&[t0.clone(), t1, t2]);
    if circ.d.is_zero() {
        return None;
    }
    let d_negative = circ.d.sign() == BigSign::Minus;
    let round = |t: &BigInt, u: &BigInt| {
        let numer = t * &circ.d + u;
        let negative = (numer.sign() == BigSign::Minus) != d_negative;
        ratio_to_f64(
            negative,
            numer.magnitude(),
            circ.d.magnitude(),
            i64::from(shift),
        )
    };
    Some([round(&t0[0], &circ.ux), round(&t0[1], &circ.uy)])
}

/// [`circumcenter`] after the fast filter failed.
#[cold]
#[inline(never)]
fn circumcenter_slow(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> (Option<[f64; 2]>, Stage) {
    if let Some((s, k)) = rescale([a, b, c], filter::LEAF_RANGE) {
        if let Some(o) = filter::circumcenter(&s).and_then(|o| scale_back(o, k)) {
            return (Some(o), Stage::Filter);
        }
    }
    if !filter::circumcenter_cancels(&[a, b, c]) {
        let ([sa, sb, sc], k) = normalize([a, b, c]);
        let circ = circ(&lift_filter([sa, sb, sc]));
        match circ.d.sign() {
            Some(Sign::Zero) => return (None, Stage::Bounded),
            Some(_) => {
                if let Some(o) = fast_circumcenter(&circ, sa, k) {
                    return (Some(o), Stage::Bounded);
                }
            }
            None => {}
        }
    }
    (circumcenter_rounded(a, b, c), Stage::Exact)
}

// ---------------------------------------------------------------------------------------
// Public predicates and constructions.

/// The exact circumcenter of `a, b, c`, or `None` iff they are collinear (or a coordinate is
/// not finite).
///
/// ```
/// use num_rational::BigRational;
/// use wdm_crust::predicates::exact::circumcenter_exact;
/// let o = circumcenter_exact([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]).unwrap();
/// assert_eq!(o.x, BigRational::from_float(0.5).unwrap());
/// assert!(circumcenter_exact([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]).is_none());
/// ```
pub fn circumcenter_exact(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<ExactPoint> {
    if [a, b, c].iter().flatten().any(|x| !x.is_finite()) {
        return None;
    }
    // In integer units of 2^shift: O = t0 + u/d.
    let ([t0, t1, t2], shift) = lift_exact([a, b, c]);
    let circ = circ(&[t0.clone(), t1, t2]);
    if circ.d.is_zero() {
        return None;
    }
    let coordinate = |t: &BigInt, u: &BigInt| {
        let numer = t * &circ.d + u;
        if shift >= 0 {
            BigRational::new(numer << shift.unsigned_abs(), circ.d.clone())
        } else {
            BigRational::new(numer, &circ.d << shift.unsigned_abs())
        }
    };
    Some(ExactPoint {
        x: coordinate(&t0[0], &circ.ux),
        y: coordinate(&t0[1], &circ.uy),
    })
}

/// The circumcenter of `a, b, c` in `f64`, or `None` iff they are exactly collinear.
///
/// Each coordinate is within 256 units in the last place of `N` of the exact circumcenter
/// `O`, where `N` is the larger magnitude of the two returned coordinates (a normwise
/// relative error below `2^-44`). This is proven per call, by an a priori error bound of the
/// floating-point formula translated to `a` (one division) or, where that is too coarse, by
/// a running error bound; where neither proves it (nearly collinear triangles, a circumcenter
/// much closer to the origin than to `a`, results near the ends of the `f64` range) the exact
/// circumcenter is computed and correctly rounded instead. A coordinate beyond the `f64`
/// range (a nearly collinear triangle of huge points) is infinite.
///
/// ```
/// use wdm_crust::predicates::exact::circumcenter;
/// assert_eq!(circumcenter([1.0, 1.0], [3.0, 1.0], [1.0, 5.0]), Some([2.0, 3.0]));
/// assert_eq!(circumcenter([0.0, 0.0], [1.0, 2.0], [2.0, 4.0]), None);
/// ```
#[inline]
pub fn circumcenter(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<[f64; 2]> {
    CIRCUMCENTER.call();
    circumcenter_uncounted(a, b, c)
}

/// [`circumcenter`] without counting the call, for loops that count once at the end
/// ([`count_circumcenter_calls`]): the shared atomic counter is a measurable share of the
/// cost of a cheap call. Fallbacks are still counted.
#[inline]
pub(crate) fn circumcenter_uncounted(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<[f64; 2]> {
    if let Some(o) = filter::circumcenter(&[a, b, c]) {
        return Some(o);
    }
    let (o, stage) = circumcenter_slow(a, b, c);
    CIRCUMCENTER.slow(stage);
    o
}

/// Adds `calls` calls of [`circumcenter_uncounted`] to the counters of [`fallback_counts`].
pub(crate) fn count_circumcenter_calls(calls: u64) {
    CIRCUMCENTER.calls.fetch_add(calls, AtomicOrdering::Relaxed);
}

/// Exact orientation of `(a, b, O)` where `O` is the circumcenter of `tri`: on which side of
/// the directed line `a → b` the circumcenter lies.
///
/// `tri` may be given in either orientation. If `tri` is collinear (no circumcenter) the
/// answer is unspecified. If `a == b` the answer is [`Orientation::Collinear`].
///
/// ```
/// use wdm_crust::predicates::{exact::orient2d_circumcenter, Orientation};
/// // Right angle at (0, 0): the circumcenter (1, 1) is the midpoint of the hypotenuse.
/// let tri = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
/// assert_eq!(orient2d_circumcenter([2.0, 0.0], [0.0, 2.0], tri), Orientation::Collinear);
/// assert_eq!(orient2d_circumcenter([0.0, 0.0], [2.0, 0.0], tri), Orientation::CounterClockwise);
/// ```
pub fn orient2d_circumcenter(a: [f64; 2], b: [f64; 2], tri: [[f64; 2]; 3]) -> Orientation {
    ORIENT.call();
    if let Some(s) = filter::orient(a, b, &tri) {
        return orientation_of(s);
    }
    let (o, stage) = orient_slow(a, b, tri);
    ORIENT.slow(stage);
    o.unwrap_or(Orientation::Collinear)
}

/// Exact sign of `(O(other) − p) · (O(source) − p)`, where `O(t)` is the circumcenter of `t`.
///
/// This is the test of the water flow's state transition: [`Sign::Negative`] means that the
/// circumcenter of `other` lies strictly on the far side of the line through `p` orthogonal
/// to `O(source) − p`. Triangles may be given in either orientation; if either is collinear
/// the answer is unspecified.
///
/// ```
/// use wdm_crust::predicates::exact::{dot_sign_circumcenters, Sign};
/// let p = [0.0, 0.0];
/// let source = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]; // circumcenter (2, 2)
/// let other = [[0.0, 0.0], [-4.0, 0.0], [0.0, 4.0]]; // circumcenter (-2, 2)
/// assert_eq!(dot_sign_circumcenters(p, source, other), Sign::Zero);
/// ```
#[inline]
pub fn dot_sign_circumcenters(p: [f64; 2], source: [[f64; 2]; 3], other: [[f64; 2]; 3]) -> Sign {
    DOT.call();
    let (s, o) = (rotate_to(source, p), rotate_to(other, p));
    if let Some(sign) = filter::dot(p, &s, &o) {
        return sign;
    }
    let (sign, stage) = dot_slow(p, s, o);
    DOT.slow(stage);
    sign
}

/// Exact comparison of the circumradii of `t1` and `t2` (`Greater` iff `t1`'s is larger).
///
/// Triangles may be given in either orientation; if either is collinear the answer is
/// unspecified.
///
/// ```
/// use std::cmp::Ordering;
/// use wdm_crust::predicates::exact::compare_circumradius;
/// let small = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
/// let large = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]];
/// assert_eq!(compare_circumradius(small, large), Ordering::Less);
/// ```
pub fn compare_circumradius(t1: [[f64; 2]; 3], t2: [[f64; 2]; 3]) -> Ordering {
    RADIUS.call();
    let sign = match filter::radius(&t1, &t2) {
        Some(sign) => sign,
        None => {
            let (sign, stage) = radius_slow(t1, t2);
            RADIUS.slow(stage);
            sign
        }
    };
    match sign {
        Sign::Negative => Ordering::Less,
        Sign::Zero => Ordering::Equal,
        Sign::Positive => Ordering::Greater,
    }
}

/// Exact position of the circumcenter of `tri` relative to the closed convex polygon `hull`.
///
/// `hull` lists the vertices counterclockwise, at least 3 of them, not all collinear; it may
/// contain collinear boundary points (also next to `hull[0]`). [`HullPosition::OnBoundary`]
/// means the circumcenter lies exactly on an edge or a vertex. The search takes `O(log h)`
/// orientation tests in the fan of `hull[0]`. If `tri` is collinear the answer is
/// [`HullPosition::Outside`] (its "circumcenter" is at infinity); if `hull` violates the
/// requirements above the answer is unspecified.
///
/// ```
/// use wdm_crust::predicates::exact::{circumcenter_in_convex_hull, HullPosition};
/// let hull = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
/// // Circumcenter (2, 0): the midpoint of the hypotenuse, on the bottom edge.
/// let tri = [[0.0, 0.0], [4.0, 0.0], [2.0, 2.0]];
/// assert_eq!(circumcenter_in_convex_hull(&hull, tri), HullPosition::OnBoundary);
/// ```
pub fn circumcenter_in_convex_hull(hull: &[[f64; 2]], tri: [[f64; 2]; 3]) -> HullPosition {
    HULL.call();
    // The circumcenter's filter values are computed once for all orientation tests.
    let mut fast = filter::CircFilter::new(&tri);
    let mut slowest: Option<Stage> = None;
    let position = hull_position(hull, |a, b| {
        if let Some(s) = fast.orient(a, b) {
            return Some(orientation_of(s));
        }
        let (o, stage) = orient_slow(a, b, tri);
        slowest = slowest.max(Some(stage));
        o
    });
    if let Some(stage) = slowest {
        HULL.slow(stage);
    }
    position
}

/// Whether `p` lies on the open ray from `o` through `dir` (`dir ≠ o`), exactly.
fn on_ray(o: [f64; 2], dir: [f64; 2], p: [f64; 2]) -> bool {
    if orient2d(o, dir, p) != Orientation::Collinear {
        return false;
    }
    // p − o = t·(dir − o); the sign of t shows in any coordinate where dir differs from o.
    let axis = usize::from(dir[0] == o[0]);
    p[axis] != o[axis] && (p[axis] > o[axis]) == (dir[axis] > o[axis])
}

/// Position of a point `q` relative to the closed convex CCW polygon `hull`, where
/// `side(a, b)` is the exact orientation of `(a, b, q)` (`None` if `q` does not exist).
fn hull_position(
    hull: &[[f64; 2]],
    mut side: impl FnMut([f64; 2], [f64; 2]) -> Option<Orientation>,
) -> HullPosition {
    use Orientation::{Clockwise as Cw, Collinear, CounterClockwise as Ccw};
    let n = hull.len();
    if n < 3 {
        return HullPosition::Outside;
    }
    let h0 = hull[0];
    // The lines through h0 and its two neighbours support the polygon (they coincide when h0
    // is in the middle of an edge).
    let Some(first) = side(h0, hull[1]) else {
        return HullPosition::Outside;
    };
    let Some(last) = side(h0, hull[n - 1]) else {
        return HullPosition::Outside;
    };
    if first == Cw || last == Ccw {
        return HullPosition::Outside;
    }
    if first == Ccw && last == Cw {
        // q is strictly inside the cone at h0, where the ray directions of the fan are
        // ordered by angle: find the fan triangle (h0, h_i, h_i+1) whose sector holds q.
        // Invariant: q is not right of h0 → h_lo and strictly right of h0 → h_hi.
        let (mut lo, mut hi) = (1, n - 1);
        while hi - lo > 1 {
            let mid = lo + (hi - lo) / 2;
            if side(h0, hull[mid]) == Some(Cw) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return match side(hull[lo], hull[lo + 1]) {
            Some(Ccw) => HullPosition::Inside,
            Some(Collinear) => HullPosition::OnBoundary,
            _ => HullPosition::Outside,
        };
    }
    // q lies on the line of the first or the last edge. The polygon meets those lines in the
    // runs of boundary points collinear with h0: h0, h1, …, h_k on the first ray and
    // h_m, …, h_n-1, h0 on the last one. q is in the polygon iff it is on the inner side of
    // the edges leaving those runs, (h_k, h_k+1) and (h_m-1, h_m).
    let (a, b) = (hull[1], hull[n - 1]);
    if on_ray(h0, a, b) || on_ray(h0, b, a) {
        return HullPosition::Outside; // all points on one ray: not a valid hull
    }
    let (mut lo, mut hi) = (1, n - 1); // on_ray(h0, a, h_lo) and not on_ray(h0, a, h_hi)
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if on_ray(h0, a, hull[mid]) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let k = lo;
    let (mut lo, mut hi) = (1, n - 1); // not on_ray(h0, b, h_lo) and on_ray(h0, b, h_hi)
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if on_ray(h0, b, hull[mid]) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let m = hi;
    let inner = |s: Option<Orientation>| matches!(s, Some(Ccw | Collinear));
    if inner(side(hull[k], hull[k + 1])) && inner(side(hull[m - 1], hull[m])) {
        HullPosition::OnBoundary
    } else {
        HullPosition::Outside
    }
}

#[cfg(test)]
mod tests;
