//! Exact predicates on constructed points: circumcenters of triangles with `f64` vertices.
//!
//! The water-flow labeling decides things about Voronoi vertices, which are circumcenters
//! and not input points: on which side of a line a circumcenter lies
//! ([`orient_circumcenter`]), on which side of the line through a sample orthogonal to its
//! source direction ([`dot_sign_circumcenters`]), which of two circumradii is larger
//! ([`compare_circumradius`]) and whether a circumcenter lies in the convex hull
//! ([`circumcenter_in_convex_hull`]).
//!
//! Each predicate is one polynomial in the coordinate differences of its inputs (`poly`; no
//! divisions: a circumcenter `O = t0 + u/d` enters as `d·(O − p) = d·(t0 − p) + u`, its sign
//! corrected by the sign of `d`), evaluated by the kernel's stages: the semi-static filter
//! (`filter`), retried on inputs rescaled by a power of two, then the running-error filter
//! (`bounded`), then exactly (`exact`). Ordinary input is decided by the first stage alone;
//! exact zeros (right angles, cocircular and symmetric configurations) always reach the
//! second and, unless all its operations were exact, the third.
//!
//! A collinear triangle (including one with repeated vertices) has no circumcenter: every
//! predicate then returns an unspecified answer, deterministically and without panicking.
//! The same holds for non-finite coordinates. No function here panics on any input.

use super::basic::orient;
use super::bounded::lift_filter;
use super::exact::{lift_exact, signs};
use super::filter;
use super::poly::{dot_terms, orient_terms, radius_terms};
use super::scale::{normalize, rescale};
use super::stats::{self, Stage, Which};
use super::Sign;

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

/// `p == q`, without the slice comparison machinery.
#[inline(always)]
fn same(p: [f64; 2], q: [f64; 2]) -> bool {
    (p[0] == q[0]) & (p[1] == q[1])
}

/// Puts `p` first if it is a vertex of `t` (a cyclic shift keeps the orientation): the
/// translation `t0 − p` is then an exact zero and the filters sharper.
#[inline(always)]
pub(super) fn rotate_to(t: [[f64; 2]; 3], p: [f64; 2]) -> [[f64; 2]; 3] {
    if same(t[1], p) {
        [t[1], t[2], t[0]]
    } else if same(t[2], p) {
        [t[2], t[0], t[1]]
    } else {
        t
    }
}

/// Orientation of `(a, b, O(tri))` after the fast filter failed, `None` if `tri` is
/// collinear; and the stage that decided.
#[cold]
#[inline(never)]
fn orient_slow(a: [f64; 2], b: [f64; 2], tri: [[f64; 2]; 3]) -> (Option<Sign>, Stage) {
    let tri = rotate_to(tri, a);
    let points = [a, b, tri[0], tri[1], tri[2]];
    if let Some(([a, b, t0, t1, t2], _)) = rescale(points, filter::LEAF_RANGE) {
        if let Some(s) = filter::orient(a, b, &[t0, t1, t2]) {
            return (Some(s), Stage::Filter);
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
    (Some(v.times(d)), stage)
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

/// The orientation of `(a, b, O)` where `O` is the circumcenter of `tri` (`Positive`: `O`
/// left of `a → b`). `tri` in either orientation; `Zero` if `a == b`; unspecified if `tri`
/// is collinear.
#[inline]
pub(crate) fn orient_circumcenter(a: [f64; 2], b: [f64; 2], tri: [[f64; 2]; 3]) -> Sign {
    stats::calls(Which::Orient, 1);
    if let Some(s) = filter::orient(a, b, &tri) {
        return s;
    }
    let (o, stage) = orient_slow(a, b, tri);
    stats::slow(Which::Orient, stage);
    o.unwrap_or(Sign::Zero)
}

/// Exact sign of `(O(other) − p) · (O(source) − p)`, where `O(t)` is the circumcenter of `t`.
///
/// This is the test of the water flow's state transition: [`Sign::Negative`] means that the
/// circumcenter of `other` lies strictly on the far side of the line through `p` orthogonal
/// to `O(source) − p`. Triangles may be given in either orientation; if either is collinear
/// the answer is unspecified.
///
/// ```
/// use wdm_crust::predicates::{dot_sign_circumcenters, Sign};
/// let p = [0.0, 0.0];
/// let source = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]; // circumcenter (2, 2)
/// let other = [[0.0, 0.0], [-4.0, 0.0], [0.0, 4.0]]; // circumcenter (-2, 2)
/// assert_eq!(dot_sign_circumcenters(p, source, other), Sign::Zero);
/// ```
#[inline]
pub fn dot_sign_circumcenters(p: [f64; 2], source: [[f64; 2]; 3], other: [[f64; 2]; 3]) -> Sign {
    stats::calls(Which::Dot, 1);
    let (s, o) = (rotate_to(source, p), rotate_to(other, p));
    if let Some(sign) = filter::dot(p, &s, &o) {
        return sign;
    }
    let (sign, stage) = dot_slow(p, s, o);
    stats::slow(Which::Dot, stage);
    sign
}

/// The sign of `R1 − R2`, the circumradii of `t1` and `t2` (either orientation;
/// unspecified if either is collinear).
#[inline]
pub(crate) fn compare_circumradius(t1: [[f64; 2]; 3], t2: [[f64; 2]; 3]) -> Sign {
    stats::calls(Which::Radius, 1);
    filter::radius(&t1, &t2).unwrap_or_else(|| {
        let (sign, stage) = radius_slow(t1, t2);
        stats::slow(Which::Radius, stage);
        sign
    })
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
/// use wdm_crust::predicates::{circumcenter_in_convex_hull, HullPosition};
/// let hull = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
/// // Circumcenter (2, 0): the midpoint of the hypotenuse, on the bottom edge.
/// let tri = [[0.0, 0.0], [4.0, 0.0], [2.0, 2.0]];
/// assert_eq!(circumcenter_in_convex_hull(&hull, tri), HullPosition::OnBoundary);
/// ```
pub fn circumcenter_in_convex_hull(hull: &[[f64; 2]], tri: [[f64; 2]; 3]) -> HullPosition {
    stats::calls(Which::Hull, 1);
    // The circumcenter's filter values are computed once for all orientation tests.
    let mut fast = filter::CircFilter::new(&tri);
    let mut slowest: Option<Stage> = None;
    let position = hull_position(hull, |a, b| {
        if let Some(s) = fast.orient(a, b) {
            return Some(s);
        }
        let (o, stage) = orient_slow(a, b, tri);
        slowest = slowest.max(Some(stage));
        o
    });
    if let Some(stage) = slowest {
        stats::slow(Which::Hull, stage);
    }
    position
}

/// Whether `p` lies on the open ray from `o` through `dir` (`dir ≠ o`), exactly.
fn on_ray(o: [f64; 2], dir: [f64; 2], p: [f64; 2]) -> bool {
    if orient(o, dir, p) != Sign::Zero {
        return false;
    }
    // p − o = t·(dir − o); the sign of t shows in any coordinate where dir differs from o.
    let axis = usize::from(dir[0] == o[0]);
    p[axis] != o[axis] && (p[axis] > o[axis]) == (dir[axis] > o[axis])
}

/// Position of a point `q` relative to the closed convex CCW polygon `hull`, where
/// `side(a, b)` is the exact orientation of `(a, b, q)` (`None` if `q` does not exist).
pub(super) fn hull_position(
    hull: &[[f64; 2]],
    mut side: impl FnMut([f64; 2], [f64; 2]) -> Option<Sign>,
) -> HullPosition {
    use Sign::{Negative as Cw, Positive as Ccw, Zero as Collinear};
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
    let inner = |s: Option<Sign>| matches!(s, Some(Ccw | Collinear));
    if inner(side(hull[k], hull[k + 1])) && inner(side(hull[m - 1], hull[m])) {
        HullPosition::OnBoundary
    } else {
        HullPosition::Outside
    }
}
