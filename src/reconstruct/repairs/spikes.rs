//! Woven spikes: an outlier just beside a curve that the crust runs through, `a → o → b`
//! where the curve runs `a → b`. The outlier is dropped from the curve (it becomes
//! unassigned) and `a → b` takes its place; likewise two consecutive outliers
//! `a → o₁ → o₂ → b`. Step 4 of the detour repair, on its edited curves. All point indices
//! are local to the full triangulation.
//!
//! What it looks like (the diagnostic in ARCHITECTURE.md, "Outliers"): `o` lies within about
//! one sample spacing of the true edge `ab`; the water flow labelled the sliver triangle
//! `a o b` inner, so `ao` and `ob` are crust edges and `ab` is not. The swaps of the detour
//! repair do not see it (no sample is skipped, and `max(|ao|, |ob|) < |ab|`). Around it the
//! curve is a smooth run `a'' → a' → a → b → b' → b''` and `o` is a spike off it. A *spike*
//! (one point, or two consecutive points, of the curves) is dropped when all of these hold:
//!
//! 1. `ab` is a Delaunay edge with a dual Voronoi edge (one the crust could have chosen);
//! 2. **the spike turns against its neighbours**: every point of the spike turns the same
//!    way, and `a` (`a' → a → o`) and `b` (`o → b → b'`) the other way, all nonzero (exact
//!    orientations). On a convex stretch of a smooth curve all turns have one sign;
//! 3. **dropping it straightens the curve at both ends**: `a' → a → b` turns by less than
//!    `a' → a → o`, and `a → b → b'` by less than `o → b → b'`. At a sharp corner `o` of a
//!    polygon the neighbours continue straight (`a' → a → o` does not turn) and dropping the
//!    corner would make `a` and `b` turn: the corner stays;
//! 4. **it is the one sharp turn of its run**: its turn (the sum over its points) is more
//!    than [`MIN_SPIKE_TURN`], more than [`LOCAL_CONTRAST`] times every turn of the run
//!    without it (at `a'`, `a`, `b`, `b'`), and more than [`GLOBAL_CONTRAST`] times the
//!    median turn of the points of all curves; a spike of two points needs
//!    [`PAIR_FACTOR`] times both contrasts. A noisy sample zigzags with its neighbours, and on
//!    a noisy curve sharp turns are common: the median measures how common.
//!
//! Clean ε-samples of smooth curves never get here (the repair runs only when a point is
//! unassigned), and would not pass 2–4 for ε below about 0.5 (the turn at a sample is a
//! fraction of a radian, the same sign along a convex stretch).
//!
//! Exactness: conditions 1 and 2 are exact (the Delaunay structure, the kernel's
//! orientation). The angles of 3 and 4 are tolerances of the rule, compared in rounded
//! arithmetic: turning angles are scale-invariant, a rounding error can only move a case
//! that sits on a threshold, and the same coordinates give the same answer in any order (the
//! turn of `p → q → r` and of `r → q → p` are computed bit for bit alike). The points are
//! visited in local order, which follows the coordinates, and each test reads the curves as
//! edited so far, so neither the input order nor the thread count matters. A drop keeps the
//! degrees of `a` and `b` (2) and takes the spike's points from 2 to 0, like a swap.

use super::shared::{EditedCurves, Swap};
use crate::ids::{ids, LocalPoint};
use crate::kernel::{orient, Sign};
use crate::reconstruct::thresholds::spikes::{
    GLOBAL_CONTRAST, LOCAL_CONTRAST, MEDIAN_SAMPLE, MIN_SPIKE_TURN, PAIR_FACTOR,
};
use crate::voronoi::Voronoi;

/// Drops every woven spike (module docs) from `curves`; how many points were dropped.
/// `median` is the median turn of the curves, computed on first need and kept for later
/// calls (the rounds of the repair change few points).
pub(crate) fn drop_woven_spikes(
    vor: &Voronoi<'_>,
    curves: &mut EditedCurves,
    median: &mut Option<f64>,
) -> usize {
    let points = &vor.triangulation().points;
    let at = |i: LocalPoint| points[i.index()];
    let mut dropped = 0;
    for o in ids::<LocalPoint>(points.len()) {
        let Some([x, y]) = curves.two_neighbours(o) else {
            continue;
        };
        // Cheap first: a spike of one point turns by more than MIN_SPIKE_TURN, one of two
        // points at one of them by more than half of it; most points of a curve by far less.
        if !turns_more_than(at(x), at(o), at(y), MIN_SPIKE_TURN / 2.0) {
            continue;
        }
        // The point alone, then with either neighbour.
        for spike in [&[o][..], &[o, x], &[o, y]] {
            let Some(found) = spike_candidate(points, curves, spike) else {
                continue;
            };
            if !vor.dual_neighbours(found.a).any(|q| q == found.b) {
                continue;
            }
            let median = *median.get_or_insert_with(|| median_turn(points, curves));
            if found.turn <= contrast(GLOBAL_CONTRAST, spike) * median {
                continue;
            }
            curves.swap(&Swap {
                stretch: vec![edge(found.a, found.b)],
                detour: path_edges(found.a, spike, found.b),
            });
            dropped += spike.len();
            break;
        }
    }
    dropped
}

/// A spike that passes the tests of the module docs on its run, all but the median's.
struct Candidate {
    /// The curve points before and after the spike.
    a: LocalPoint,
    b: LocalPoint,
    /// The turn of the spike: the sum of its points' turns.
    turn: f64,
}

/// `spike` (one point, or two consecutive points of the curves) when it passes conditions
/// 2–4 of the module docs but the median's: the run `a'' → a' → a → spike → b → b' → b''` has
/// distinct points, each with two curve edges.
fn spike_candidate(
    points: &[[f64; 2]],
    curves: &EditedCurves,
    spike: &[LocalPoint],
) -> Option<Candidate> {
    let at = |i: LocalPoint| points[i.index()];
    let beyond = |from: LocalPoint, p: LocalPoint| -> Option<LocalPoint> {
        let [x, y] = curves.two_neighbours(p)?;
        Some(if x == from { y } else { x })
    };
    let (a, b) = match *spike {
        [o] => curves.two_neighbours(o).map(|[a, b]| (a, b))?,
        [o1, o2] => (beyond(o2, o1)?, beyond(o1, o2)?),
        _ => return None,
    };
    // `a → spike → b` on the stack: this runs for every sharply turning point.
    let mut path = [a; 4];
    path[1..=spike.len()].copy_from_slice(spike);
    path[spike.len() + 1] = b;
    let chain = &path[..spike.len() + 2];
    let corners = || chain.windows(3).map(|w| [at(w[0]), at(w[1]), at(w[2])]);
    // Cheap first: most points of a curve turn by far less than a spike.
    let least = MIN_SPIKE_TURN / spike.len() as f64;
    if !corners().any(|[p, q, r]| turns_more_than(p, q, r, least)) {
        return None;
    }
    let (first, last) = (spike[0], spike[spike.len() - 1]);
    let a1 = beyond(first, a)?;
    let a2 = beyond(a, a1)?;
    let b1 = beyond(last, b)?;
    let b2 = beyond(b, b1)?;
    let mut all = [a2; 8];
    all[1..4].copy_from_slice(&[a1, b1, b2]);
    all[4..4 + chain.len()].copy_from_slice(chain);
    let run = &mut all[..4 + chain.len()];
    run.sort_unstable();
    if run.windows(2).any(|w| w[0] == w[1]) {
        return None;
    }
    // Condition 2: the spike turns one way, its two neighbours on the curve the other.
    let sign = orient(at(a), at(first), at(chain[2]));
    let opposes = |s: Sign| s.times(sign) == Sign::Negative;
    if sign == Sign::Zero
        || corners().any(|[p, q, r]| orient(p, q, r) != sign)
        || !opposes(orient(at(a1), at(a), at(first)))
        || !opposes(orient(at(last), at(b), at(b1)))
    {
        return None;
    }
    // Condition 3: without the spike, `a` and `b` turn less.
    let without = [turn(at(a1), at(a), at(b)), turn(at(a), at(b), at(b1))];
    if without[0] >= turn(at(a1), at(a), at(first)) || without[1] >= turn(at(last), at(b), at(b1)) {
        return None;
    }
    // Condition 4, but the median: the one sharp turn of its run.
    let total: f64 = corners().map(|[p, q, r]| turn(p, q, r)).sum();
    let around = without[0]
        .max(without[1])
        .max(turn(at(a2), at(a1), at(a)))
        .max(turn(at(b), at(b1), at(b2)));
    let sharp = total > MIN_SPIKE_TURN && contrast(LOCAL_CONTRAST, spike) * around < total;
    sharp.then_some(Candidate { a, b, turn: total })
}

/// A contrast of condition 4 for `spike`: higher for two points.
fn contrast(base: f64, spike: &[LocalPoint]) -> f64 {
    if spike.len() == 2 {
        base * PAIR_FACTOR
    } else {
        base
    }
}

fn edge(a: LocalPoint, b: LocalPoint) -> [LocalPoint; 2] {
    [a.min(b), a.max(b)]
}

/// The edges of `a → spike → b`, sorted.
fn path_edges(a: LocalPoint, spike: &[LocalPoint], b: LocalPoint) -> Vec<[LocalPoint; 2]> {
    let path: Vec<LocalPoint> = std::iter::once(a)
        .chain(spike.iter().copied())
        .chain(std::iter::once(b))
        .collect();
    let mut edges: Vec<[LocalPoint; 2]> = path.windows(2).map(|w| edge(w[0], w[1])).collect();
    edges.sort_unstable();
    edges
}

/// The absolute turning angle at `q` of `p → q → r`, in `[0, π]`. The same bits for
/// `r → q → p`: the cross product only changes sign, the dot product not at all.
fn turn(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> f64 {
    let (u, v) = ([q[0] - p[0], q[1] - p[1]], [r[0] - q[0], r[1] - q[1]]);
    (u[0] * v[1] - u[1] * v[0])
        .abs()
        .atan2(u[0] * v[0] + u[1] * v[1])
}

/// Whether `p → q → r` turns by more than `angle` (in `(0, π/2)`), without a square root or
/// an arc tangent: the cosine of the turn is below `cos(angle)`. A prefilter of [`turn`]
/// comparisons (a rounding difference at the threshold only lets a case through to them).
fn turns_more_than(p: [f64; 2], q: [f64; 2], r: [f64; 2], angle: f64) -> bool {
    let (u, v) = ([q[0] - p[0], q[1] - p[1]], [r[0] - q[0], r[1] - q[1]]);
    let dot = u[0] * v[0] + u[1] * v[1];
    let c = angle.cos();
    let lengths = (u[0] * u[0] + u[1] * u[1]) * (v[0] * v[0] + v[1] * v[1]);
    dot <= 0.0 || dot * dot < 1.000_001 * c * c * lengths
}

/// The median turn of the points with two curve edges (0 when there are none), over at most
/// about [`MEDIAN_SAMPLE`] points taken at even steps of the local order (which follows the
/// coordinates, so the estimate does not depend on the input order).
fn median_turn(points: &[[f64; 2]], curves: &EditedCurves) -> f64 {
    let at = |i: LocalPoint| points[i.index()];
    let step = points.len().div_ceil(MEDIAN_SAMPLE).max(1);
    let mut turns: Vec<f64> = ids::<LocalPoint>(points.len())
        .step_by(step)
        .filter_map(|p| {
            let [a, b] = curves.two_neighbours(p)?;
            Some(turn(at(a), at(p), at(b)))
        })
        .collect();
    if turns.is_empty() {
        return 0.0;
    }
    let middle = turns.len() / 2;
    *turns.select_nth_unstable_by(middle, f64::total_cmp).1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::triangulate;
    use crate::reconstruct::repairs::detours::tests::{
        assert_repaired_alike_in_any_order, repaired,
    };
    use std::f64::consts::TAU;

    /// `k` points on the ellipse with half-axes 1 and `b`, counterclockwise from angle 0.
    fn ellipse(k: usize, b: f64) -> Vec<[f64; 2]> {
        (0..k)
            .map(|i| {
                let t = i as f64 * TAU / k as f64;
                [t.cos(), b * t.sin()]
            })
            .collect()
    }

    /// The edge between the caller indices `a` and `b`, smaller first.
    fn edge(a: u32, b: u32) -> [u32; 2] {
        [a.min(b), a.max(b)]
    }

    /// The closed polygon through `order` (caller indices).
    fn polygon(order: &[u32]) -> Vec<[u32; 2]> {
        (0..order.len())
            .map(|i| edge(order[i], order[(i + 1) % order.len()]))
            .collect()
    }

    /// Runs the spike step on the curves `edges` (caller indices); what it adds and removes,
    /// sorted, in caller indices.
    fn spikes_of(points: &[[f64; 2]], edges: &[[u32; 2]]) -> (Vec<[u32; 2]>, Vec<[u32; 2]>) {
        let tri = triangulate(points).unwrap();
        let vor = tri.voronoi();
        let local: Vec<[LocalPoint; 2]> = edges
            .iter()
            .map(|&[a, b]| super::edge(tri.local_index(a), tri.local_index(b)))
            .collect();
        let mut curves = EditedCurves::new(points.len(), &local);
        drop_woven_spikes(&vor, &mut curves, &mut None);
        let repair = curves.into_repair();
        let caller = |edges: Vec<[LocalPoint; 2]>| {
            let mut edges: Vec<[u32; 2]> = edges
                .into_iter()
                .map(|[a, b]| edge(tri.input_index(a), tri.input_index(b)))
                .collect();
            edges.sort_unstable();
            edges
        };
        (caller(repair.added), caller(repair.removed))
    }

    /// A point beside the edge `from → from + 1` of a 40-point ellipse, `height` spacings
    /// out, at `along` of the way (caller index 40).
    fn beside(points: &[[f64; 2]], from: usize, along: f64, height: f64) -> [f64; 2] {
        let (p, q) = (points[from], points[from + 1]);
        let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
        // Outward: to the right of the counterclockwise direction.
        [
            p[0] + along * dx + height * dy,
            p[1] + along * dy - height * dx,
        ]
    }

    #[test]
    fn a_woven_outlier_is_dropped() {
        let mut points = ellipse(40, 0.7);
        points.push(beside(&points, 10, 0.5, 0.6));
        let mut order: Vec<u32> = (0..40).collect();
        order.insert(11, 40);
        let (added, removed) = spikes_of(&points, &polygon(&order));
        assert_eq!(added, vec![[10, 11]]);
        assert_eq!(removed, vec![[10, 40], [11, 40]]);
    }

    #[test]
    fn two_woven_outliers_are_dropped() {
        let mut points = ellipse(40, 0.7);
        points.push(beside(&points, 10, 0.3, 0.6));
        points.push(beside(&points, 10, 0.7, 0.6));
        let mut order: Vec<u32> = (0..40).collect();
        order.splice(11..11, [40, 41]);
        let (added, removed) = spikes_of(&points, &polygon(&order));
        assert_eq!(added, vec![[10, 11]]);
        assert_eq!(removed, vec![[10, 40], [11, 41], [40, 41]]);
    }

    #[test]
    fn a_clean_smooth_sample_and_a_shallow_bump_stay() {
        // A clean ε-sample of an ellipse: every turn has one sign.
        let points = ellipse(40, 0.7);
        let order: Vec<u32> = (0..40).collect();
        assert_eq!(spikes_of(&points, &polygon(&order)), (vec![], vec![]));
        // A point a tenth of a spacing off the curve: a turn of a few degrees, no spike.
        let mut points = ellipse(40, 0.7);
        points.push(beside(&points, 10, 0.5, 0.1));
        let mut order: Vec<u32> = (0..40).collect();
        order.insert(11, 40);
        assert_eq!(spikes_of(&points, &polygon(&order)), (vec![], vec![]));
    }

    #[test]
    fn sharp_corners_stay() {
        // A triangle with a 20° tip, a square and an L-shape, sampled along their sides (8
        // points a side), turned by 0.3 rad so that the sides' samples are only nearly
        // collinear: their turns have either sign, the corners' neighbours run straight.
        let shapes: [&[[f64; 2]]; 3] = [
            &[[0.0, 0.0], [3.0, 0.0], [1.5, 8.5]],
            &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
            &[
                [0.0, 0.0],
                [3.0, 0.0],
                [3.0, 1.0],
                [1.0, 1.0],
                [1.0, 3.0],
                [0.0, 3.0],
            ],
        ];
        let (sin, cos) = 0.3f64.sin_cos();
        for corners in shapes {
            let mut points = Vec::new();
            for (i, &p) in corners.iter().enumerate() {
                let q = corners[(i + 1) % corners.len()];
                for k in 0..8 {
                    let t = k as f64 / 8.0;
                    let (x, y) = (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]));
                    points.push([cos * x - sin * y, sin * x + cos * y]);
                }
            }
            let order: Vec<u32> = (0..points.len() as u32).collect();
            assert_eq!(spikes_of(&points, &polygon(&order)), (vec![], vec![]));
        }
    }

    #[test]
    fn the_turn_is_the_same_both_ways_and_the_prefilter_agrees() {
        let mut rng = wdm_crust_testkit::Rng::new(9);
        for _ in 0..1000 {
            let mut point = || [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
            let (p, q, r) = (point(), point(), point());
            assert_eq!(turn(p, q, r).to_bits(), turn(r, q, p).to_bits());
            // The prefilter lets every turn above the threshold through.
            let t = turn(p, q, r);
            if t > MIN_SPIKE_TURN {
                assert!(turns_more_than(p, q, r, MIN_SPIKE_TURN));
            }
        }
    }

    /// Through the whole repair (which looks for spikes when at least 1 % of the points are
    /// unassigned: here a far point), in any input order: the same edges.
    #[test]
    fn the_repair_drops_the_same_spike_in_any_input_order() {
        let mut points = ellipse(40, 0.7);
        points.push(beside(&points, 10, 0.5, 0.6));
        points.push(beside(&points, 25, 0.4, 0.8));
        points.push([0.05, 0.02]);
        let mut order: Vec<u32> = (0..40).collect();
        order.insert(26, 41);
        order.insert(11, 40);
        let edges = polygon(&order);
        let expected = repaired(&points, &edges);
        let mut clean: Vec<[u32; 2]> = polygon(&(0..40).collect::<Vec<u32>>());
        clean.sort_unstable();
        assert_eq!(expected, clean);
        assert_repaired_alike_in_any_order(&points, &edges, &expected, 4);
    }
}
