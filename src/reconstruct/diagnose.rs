//! Warnings: the signs that a reconstruction is probably not what its user wanted, each with
//! what to try.
//!
//! A reconstruction is always exactly what its rules say, but samples that are too noisy,
//! too sparse, curves closer together than the spacing, or points that are no curve at all
//! give a result that is *valid* and yet not the curves the user had in mind. The checks
//! here look at the result beside its Delaunay graph and say so:
//!
//! | code | fires when |
//! |---|---|
//! | `most-unassigned` | more than half of the distinct points are on no curve (or no curve was found) |
//! | `scatter` | most curve points have a point that is not their curve neighbour as close as their curve edges, and over a third of the points are on no curve: a uniform scatter, a filled area or a wide band of noise |
//! | `long-edge` | a curve edge is more than 8 × each curve edge within two steps of it (at a chain's end: the end's nearest-neighbour distance) |
//! | `loop-across-gap` | a closed loop's longest edge is more than 4 × its next longest: the loop may close across the gap of an open curve |
//! | `chain-ends-close` | two open chains end at most 4 × the step at each of those ends apart: they may be one curve, broken by noise or at a sharp corner |
//! | `curves-too-close` | two curve points as close as their curve edges lie on different curves, or more than 32 steps apart on one: the sampling cannot tell the curves apart there |
//! | `peeling-budget` | peeling stopped at its budget: curves may remain among the points on no curve |
//!
//! Every comparison of lengths is exact (the kernel's metric predicates; a ratio is a power
//! of two, exact in every stage), so the warnings do not depend on the input order or on
//! the scale; only the numbers quoted in the messages are rounded. The thresholds are listed
//! with their measurements in `docs/design/thresholds.md`.

use std::cmp::Ordering;

use super::curves::lone_longest_edge;
use super::lengths::distance;
use super::proximity::closer;
use super::result::{Reconstruction, Warning, WarningCode};
use super::thresholds::warnings::{
    CLOSE_CURVE_STEPS, CLOSE_ENDS_DOUBLINGS, CLOSE_ENDS_LONGEST_DOUBLINGS, GAP_EDGE_DOUBLINGS,
    LONG_EDGE_DOUBLINGS, LONG_EDGE_OUTLIER_DOUBLINGS,
};
use crate::delaunay::{triangulate, NO_TWIN};
use crate::ids::LocalPoint;
use crate::kernel::metric::{length_order, scaled_length_order};
use crate::predicates::{incircle, CirclePosition};

impl Reconstruction {
    /// The signs that this result is probably not what was wanted (most points on no curve,
    /// a scatter rather than curves, an edge far longer than its neighbours, a loop closed
    /// across a gap, curves closer than the spacing, peeling stopped at its budget), each
    /// with what to try; empty when there is nothing to say. Computed on the first call, in
    /// time linear in the points (about a tenth of the reconstruction's), then kept.
    ///
    /// ```
    /// let points: Vec<[f64; 2]> = (0..64)
    ///     .map(|k| {
    ///         let t = k as f64 * std::f64::consts::TAU / 64.0;
    ///         [t.cos(), t.sin()]
    ///     })
    ///     .collect();
    /// let rec = wdm_crust::reconstruct(&points)?;
    /// assert!(rec.warnings().is_empty());
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn warnings(&self) -> &[Warning] {
        self.warnings.get_or_init(|| warnings(self))
    }
}

/// The warnings of `rec`, in the order of [`WarningCode::ALL`], at most one per code.
pub(super) fn warnings(rec: &Reconstruction) -> Vec<Warning> {
    let tri = &rec.triangulation;
    let distinct = tri.distinct_point_count();
    let mut found = Vec::new();
    if rec.budget_exhausted {
        found.push(peeling_budget(rec));
    }
    if distinct < 3 {
        return found;
    }
    let view = CurveView::new(rec);
    let survey = Survey::of(rec, &view);
    let unassigned = rec.unassigned.len();
    if view.curve_points == 0 {
        found.push(Warning {
            code: WarningCode::MostUnassigned,
            message: format!(
                "no curve passes through any of the {distinct} points: they may be too sparse, \
                 or a scatter rather than samples along curves; try --algorithm nn-crust"
            ),
            points: Vec::new(),
        });
    } else if 2 * unassigned > distinct {
        found.push(Warning {
            code: WarningCode::MostUnassigned,
            message: format!(
                "{unassigned} of {distinct} points ({}) are on no curve: if they are outliers the \
                 curves may be right; if they are samples of curves, those are too noisy or too \
                 sparse here (look at the picture; try --algorithm nn-crust)",
                percent(unassigned, distinct)
            ),
            points: Vec::new(),
        });
    }
    // In a scatter every curve is one path among many: its edges and near misses say
    // nothing more.
    if let Some(w) = scatter(&view, &survey, unassigned, distinct) {
        found.push(w);
        found.sort_by_key(|w| WarningCode::ALL.iter().position(|&c| c == w.code));
        return found;
    }
    found.extend(edge_warnings(rec, &view, &survey));
    found.extend(chain_ends_close(rec, &view));
    if let Some(w) = curves_too_close(rec, &survey) {
        found.push(w);
    }
    found.sort_by_key(|w| WarningCode::ALL.iter().position(|&c| c == w.code));
    found
}

fn peeling_budget(rec: &Reconstruction) -> Warning {
    let untouched = rec.untouched_points().len();
    Warning {
        code: WarningCode::PeelingBudget,
        message: format!(
            "peeling stopped after {} passes at its budget; {untouched} points are on no curve \
             and may still hold curves: raise --peeling-budget",
            rec.passes
        ),
        points: Vec::new(),
    }
}

/// The curves in local indices: each point's curve neighbours, and its curve and position
/// in it where that is one curve.
struct CurveView {
    /// For every local point: its curve and position in it; `(NO_CURVE, 0)` when on none,
    /// `(JUNCTION, 0)` at a point of three or more edges (a baseline's or the water flow's
    /// junction), which ends several chains.
    place: Vec<(u32, u32)>,
    /// Each curve's local points in order, and whether it is closed.
    curves: Vec<(Vec<LocalPoint>, bool)>,
    /// Every point's edge neighbours, in compressed rows: the curve neighbours of a point
    /// are those of its edges, whichever curves they were assembled into (that split at a
    /// junction follows the caller's indices; the edges do not).
    start: Vec<u32>,
    targets: Vec<LocalPoint>,
    curve_points: usize,
}

const NO_CURVE: u32 = u32::MAX;
const JUNCTION: u32 = u32::MAX - 1;

/// No point: no curve neighbour, no chain end.
const NO_POINT: LocalPoint = LocalPoint::new(u32::MAX);

impl CurveView {
    fn new(rec: &Reconstruction) -> Self {
        let tri = &rec.triangulation;
        let n = tri.distinct_point_count();
        let edges: Vec<[LocalPoint; 2]> = rec
            .edges
            .iter()
            .map(|e| e.map(|i| tri.local_index(i)))
            .collect();
        let mut start = vec![0u32; n + 1];
        for &[a, b] in &edges {
            start[a.index() + 1] += 1;
            start[b.index() + 1] += 1;
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut targets = vec![LocalPoint::new(0); 2 * edges.len()];
        for &[a, b] in &edges {
            for (p, q) in [(a, b), (b, a)] {
                targets[fill[p.index()] as usize] = q;
                fill[p.index()] += 1;
            }
        }
        let degree = |p: usize| start[p + 1] - start[p];
        let mut place = vec![(NO_CURVE, 0); n];
        let mut curves = Vec::with_capacity(rec.curves.len());
        for (c, curve) in rec.curves.iter().enumerate() {
            let local: Vec<LocalPoint> =
                (curve.points.iter()).map(|&i| tri.local_index(i)).collect();
            for (k, &p) in local.iter().enumerate() {
                place[p.index()] = if degree(p.index()) > 2 {
                    (JUNCTION, 0)
                } else {
                    (c as u32, k as u32)
                };
            }
            curves.push((local, curve.closed));
        }
        let curve_points = (0..n).filter(|&p| degree(p) > 0).count();
        CurveView {
            place,
            curves,
            start,
            targets,
            curve_points,
        }
    }

    /// The curve neighbours of `p`: the other ends of its edges.
    fn neighbours(&self, p: LocalPoint) -> impl Iterator<Item = LocalPoint> + '_ {
        let p = p.index();
        self.targets[self.start[p] as usize..self.start[p + 1] as usize]
            .iter()
            .copied()
    }

    /// The steps along one curve between `p` and `q`: `None` on different curves, `Some(0)`
    /// at a junction (it ends several chains, so it is near all of them).
    fn steps_apart(&self, p: LocalPoint, q: LocalPoint) -> Option<usize> {
        let ((cp, kp), (cq, kq)) = (self.place[p.index()], self.place[q.index()]);
        if cp == JUNCTION || cq == JUNCTION {
            return Some(0);
        }
        if cp != cq {
            return None;
        }
        let (points, closed) = &self.curves[cp as usize];
        let apart = kp.abs_diff(kq) as usize;
        Some(if *closed {
            apart.min(points.len() - apart)
        } else {
            apart
        })
    }
}

/// What one pass over the Delaunay edges finds, for the warnings that compare a curve
/// point with the points around it. An edge is looked at from both ends; the diagonals of
/// cocircular groups are left out where they matter (the triangulation's split of such a
/// group is arbitrary, and no warning may depend on it).
struct Survey {
    /// Curve points with a Delaunay neighbour, not a curve neighbour, as close as their
    /// longer curve edge.
    crowded: usize,
    /// For each open chain's end, its nearest Delaunay neighbour (`NO_POINT` elsewhere).
    nearest_of_end: Vec<LocalPoint>,
    /// Pairs of curve points closer than both their longer curve edges, on different curves
    /// or far apart along one, and the smallest such pair in caller indices.
    close_pairs: usize,
    first_close: Option<[u32; 2]>,
}

impl Survey {
    fn of(rec: &Reconstruction, view: &CurveView) -> Survey {
        let tri = &rec.triangulation;
        let points = &tri.points;
        let at = |i: LocalPoint| points[i.index()];
        let n = points.len();
        // Each curve point's longer curve edge, by its far end.
        let mut far = vec![NO_POINT; n];
        let mut nearest_of_end = vec![NO_POINT; n];
        let mut end = vec![false; n];
        for (curve, closed) in &view.curves {
            for &p in curve {
                far[p.index()] = view
                    .neighbours(p)
                    .max_by(|&a, &b| closer(at(p), at(a), at(b)))
                    .unwrap_or(NO_POINT);
            }
            if !closed {
                if let (Some(&first), Some(&last)) = (curve.first(), curve.last()) {
                    end[first.index()] = true;
                    end[last.index()] = true;
                }
            }
        }
        let mut crowded = vec![false; n];
        let (mut close_pairs, mut first_close) = (0usize, None::<[u32; 2]>);
        // Two curve points as close as both their longer curve edges, on different curves
        // or far apart along one.
        let mut close = |a: LocalPoint, b: LocalPoint| {
            if view
                .steps_apart(a, b)
                .is_none_or(|steps| steps > CLOSE_CURVE_STEPS)
            {
                close_pairs += 1;
                let (i, j) = (tri.input_index(a), tri.input_index(b));
                let named = [i.min(j), i.max(j)];
                if first_close.is_none_or(|f| named < f) {
                    first_close = Some(named);
                }
            }
        };
        let mut skipped: Vec<(LocalPoint, LocalPoint)> = Vec::new();
        let halfedges = tri.halfedges();
        for (e, &twin) in tri.halfedge_ids().zip(halfedges) {
            if twin != NO_TWIN && twin < e {
                continue;
            }
            let (a, b) = (tri.org(e), tri.dest(e));
            for (p, q) in [(a, b), (b, a)] {
                if end[p.index()] {
                    let best = &mut nearest_of_end[p.index()];
                    if *best == NO_POINT || closer(at(p), at(q), at(*best)) == Ordering::Less {
                        *best = q;
                    }
                }
            }
            // A curve edge is no crowding neighbour (and comparing it with itself would
            // take the exact stages every time).
            if view.neighbours(a).any(|x| x == b) {
                continue;
            }
            // Within the longer curve edge of `p`.
            let within = |p: LocalPoint| {
                let f = far[p.index()];
                f != NO_POINT && length_order(at(a), at(b), at(p), at(f)) != Ordering::Greater
            };
            let (a_within, b_within) = (within(a), within(b));
            if !(a_within || b_within) {
                continue;
            }
            if twin != NO_TWIN {
                let c = tri.org(e.prev());
                let d = tri.org(twin.prev());
                if incircle(at(a), at(b), at(c), at(d)) == CirclePosition::On {
                    continue;
                }
            }
            crowded[a.index()] |= a_within;
            crowded[b.index()] |= b_within;
            // A point on no curve within the longer curve edge of a curve point: a sample
            // the curves may have skipped there.
            for (u, p, p_within) in [(a, b, b_within), (b, a, a_within)] {
                if p_within && far[u.index()] == NO_POINT && far[p.index()] != NO_POINT {
                    skipped.push((u, p));
                }
            }
            if a_within && b_within {
                close(a, b);
            }
        }
        // Two curve points within their longer curve edges of one skipped sample are as
        // close as the curves come there: two walls a few spacings apart whose corridor
        // the flow closed across, leaving the samples between on no curve.
        skipped.sort_unstable();
        for run in skipped.chunk_by(|x, y| x.0 == y.0) {
            for (k, &(_, p)) in run.iter().enumerate() {
                for &(_, q) in &run[k + 1..] {
                    close(p, q);
                }
            }
        }
        Survey {
            crowded: crowded.iter().filter(|&&c| c).count(),
            nearest_of_end,
            close_pairs,
            first_close,
        }
    }
}

/// `scatter`: most curve points have another point that is not their curve neighbour as
/// close as their longer curve edge, and over a third of the points are on no curve. A
/// curve sample's points have their curve neighbours nearest; in a scatter, a lattice or a
/// band of noise the curves drawn are one path among many equally short.
fn scatter(
    view: &CurveView,
    survey: &Survey,
    unassigned: usize,
    distinct: usize,
) -> Option<Warning> {
    if 3 * unassigned <= distinct || 2 * survey.crowded <= view.curve_points {
        return None;
    }
    Some(Warning {
        code: WarningCode::Scatter,
        message: format!(
            "the points look like a scatter, a filled area or a band of noise wider than the \
             spacing rather than samples along curves: {} of the {} curve points have another \
             point as close as their curve neighbours, and {} of all points are on no curve; \
             the curves drawn are one path among many (thin the points, or sample the outline only)",
            percent(survey.crowded, view.curve_points),
            view.curve_points,
            percent(unassigned, distinct)
        ),
        points: Vec::new(),
    })
}

/// `long-edge` and `loop-across-gap`: curve edges far longer than the curve edges near
/// them.
fn edge_warnings(rec: &Reconstruction, view: &CurveView, survey: &Survey) -> Vec<Warning> {
    let tri = &rec.triangulation;
    let points = &tri.points;
    let at = |i: LocalPoint| points[i.index()];
    let length = |[a, b]: [LocalPoint; 2]| distance(at(a), at(b));
    let longer = |e: [LocalPoint; 2], f: [LocalPoint; 2], doublings| {
        scaled_length_order(at(e[0]), at(e[1]), at(f[0]), at(f[1]), doublings) == Ordering::Greater
    };
    // The worst edge of each kind (ratio, ends), and how many there are.
    let mut long: (usize, f64, [u32; 2]) = (0, 0.0, [0, 0]);
    let mut gap: (usize, f64, [u32; 2]) = (0, 0.0, [0, 0]);
    for (curve, &closed) in view.curves.iter().map(|(c, closed)| (c, closed)) {
        let n = curve.len();
        if n < 2 {
            continue;
        }
        let edge = |k: usize| [curve[k % n], curve[(k + 1) % n]];
        let edges = if closed { n } else { n - 1 };
        let mut long_here = vec![false; edges];
        let mut ratios = vec![0.0; edges];
        for (k, flagged) in long_here.iter_mut().enumerate() {
            let ab = edge(k);
            // Up to two curve edges on each side; at a chain's end, the end's
            // nearest-neighbour pair stands for the missing side.
            let nearest = |p: LocalPoint| match survey.nearest_of_end[p.index()] {
                NO_POINT => None,
                q => Some([p, q]),
            };
            let along = |side: i64| {
                let j = k as i64 + side;
                (closed || (0..edges as i64).contains(&j))
                    .then(|| j.rem_euclid(n as i64) as usize)
                    .filter(|&j| j != k)
                    .map(edge)
            };
            let candidates = [
                along(-2),
                along(-1),
                along(1),
                along(2),
                (!closed && k == 0).then(|| nearest(ab[0])).flatten(),
                (!closed && k + 1 == edges)
                    .then(|| nearest(ab[1]))
                    .flatten(),
            ];
            let mut beside = [[LocalPoint::new(0); 2]; 6];
            let mut sides = 0;
            for f in candidates.into_iter().flatten() {
                beside[sides] = f;
                sides += 1;
            }
            let beside = &beside[..sides];
            if beside.is_empty() || !beside.iter().all(|&f| longer(ab, f, LONG_EDGE_DOUBLINGS)) {
                continue;
            }
            *flagged = true;
            let side = beside.iter().map(|&f| length(f)).fold(0.0, f64::max);
            ratios[k] = length(ab) / side;
        }
        // Random positions put gaps far longer than their neighbours here and there (a
        // long gap beside four short ones); a chord is also far longer than the curve's
        // longest ordinary edge, as the open-curve stage's chords are.
        let ordinary = (0..edges).filter(|&k| !long_here[k]).max_by(|&i, &j| {
            let ([a, b], [c, d]) = (edge(i), edge(j));
            length_order(at(a), at(b), at(c), at(d))
        });
        for k in 0..edges {
            if long_here[k]
                && ordinary.is_none_or(|o| longer(edge(k), edge(o), LONG_EDGE_OUTLIER_DOUBLINGS))
            {
                note(&mut long, ratios[k], edge(k).map(|p| tri.input_index(p)));
            }
        }
        // A loop whose longest edge is far longer than every other one: an open curve whose
        // ends were joined.
        if closed && n >= 4 {
            let lone = lone_longest_edge(points, curve, GAP_EDGE_DOUBLINGS);
            if let Some((longest, second)) = lone.filter(|&(longest, _)| !long_here[longest]) {
                note(
                    &mut gap,
                    length(edge(longest)) / length(edge(second)),
                    edge(longest).map(|p| tri.input_index(p)),
                );
            }
        }
    }
    let mut out = Vec::new();
    if long.0 > 0 {
        let [i, j] = long.2;
        out.push(Warning {
            code: WarningCode::LongEdge,
            message: format!(
                "{} ({}× the curve edges beside it, between points {i} and {j} at {}): it may \
                 bridge a gap between two curves or close an open one; if so, sample the gap \
                 more densely or try --algorithm crust",
                count(
                    long.0,
                    "curve edge is far longer",
                    "curve edges are far longer"
                ),
                round_ratio(long.1),
                position(at(tri.local_index(i)))
            ),
            points: vec![i, j],
        });
    }
    if gap.0 > 0 {
        let [i, j] = gap.2;
        out.push(Warning {
            code: WarningCode::LoopAcrossGap,
            message: format!(
                "{} across a gap: the edge between points {i} and {j} at {} is {}× the loop's \
                 next longest; if the curve is open there, try --algorithm crust",
                count(gap.0, "closed loop closes", "closed loops close"),
                position(at(tri.local_index(i))),
                round_ratio(gap.1)
            ),
            points: vec![i, j],
        });
    }
    out
}

/// `chain-ends-close`: two open chains whose ends are at most `2^CLOSE_ENDS_DOUBLINGS` times
/// the step at each end apart, or at most `2^CLOSE_ENDS_LONGEST_DOUBLINGS` times the longest
/// edge of each chain. The pairs looked at are the edges of the Delaunay
/// triangulation of the chain ends alone: an end's nearest other end is among them.
fn chain_ends_close(rec: &Reconstruction, view: &CurveView) -> Option<Warning> {
    let tri = &rec.triangulation;
    let points = &tri.points;
    let at = |i: LocalPoint| points[i.index()];
    // Each end, its chain, and its step (the longer of its last two edges, as a pair).
    let mut ends: Vec<(LocalPoint, usize, [LocalPoint; 2])> = Vec::new();
    for (c, (curve, closed)) in view.curves.iter().enumerate() {
        let k = curve.len();
        if *closed || k < 2 {
            continue;
        }
        for (end, next, after) in [
            (curve[0], curve[1], curve.get(2)),
            (
                curve[k - 1],
                curve[k - 2],
                k.checked_sub(3).map(|i| &curve[i]),
            ),
        ] {
            let step = match after {
                Some(&a)
                    if length_order(at(next), at(a), at(end), at(next)) == Ordering::Greater =>
                {
                    [next, a]
                }
                _ => [end, next],
            };
            ends.push((end, c, step));
        }
    }
    if ends.len() < 4 {
        return None;
    }
    // Each chain's longest edge: samples at random positions leave gaps far longer than the
    // steps at the ends beside them, as long as the longest gaps the chain itself spans.
    let mut longest: Vec<[LocalPoint; 2]> = vec![[LocalPoint::new(0); 2]; view.curves.len()];
    for (c, (curve, closed)) in view.curves.iter().enumerate() {
        if *closed || curve.len() < 2 {
            continue;
        }
        let mut best = [curve[0], curve[1]];
        for w in curve.windows(2) {
            if length_order(at(w[0]), at(w[1]), at(best[0]), at(best[1])) == Ordering::Greater {
                best = [w[0], w[1]];
            }
        }
        longest[c] = best;
    }
    // One site per end point: a junction is the end of several chains (in the single
    // pass), and which of them a merged duplicate would stand for followed the input order.
    ends.sort_unstable_by_key(|&(p, c, _)| (p, c));
    let mut sites: Vec<LocalPoint> = ends.iter().map(|&(p, _, _)| p).collect();
    sites.dedup();
    let of_site = |p: LocalPoint| {
        let from = ends.partition_point(|e| e.0 < p);
        let to = ends.partition_point(|e| e.0 <= p);
        &ends[from..to]
    };
    let coords: Vec<[f64; 2]> = sites.iter().map(|&p| at(p)).collect();
    let Ok(among) = triangulate(&coords) else {
        return None;
    };
    let within = |p: LocalPoint, q: LocalPoint, [a, b]: [LocalPoint; 2]| {
        scaled_length_order(at(p), at(q), at(a), at(b), CLOSE_ENDS_DOUBLINGS) != Ordering::Greater
    };
    let (mut pairs, mut first) = (0usize, None::<[u32; 2]>);
    for (e, &twin) in among.halfedge_ids().zip(among.halfedges()) {
        if twin != NO_TWIN && twin < e {
            continue;
        }
        let (p, q) = (
            sites[among.input_index(among.org(e)) as usize],
            sites[among.input_index(among.dest(e)) as usize],
        );
        let within_longest = |[a, b]: [LocalPoint; 2]| {
            scaled_length_order(at(p), at(q), at(a), at(b), CLOSE_ENDS_LONGEST_DOUBLINGS)
                != Ordering::Greater
        };
        let close = of_site(p).iter().any(|x| {
            of_site(q).iter().any(|y| {
                x.1 != y.1
                    && ((within(p, q, x.2) && within(p, q, y.2))
                        || (within_longest(longest[x.1]) && within_longest(longest[y.1])))
            })
        });
        if !close {
            continue;
        }
        pairs += 1;
        let (i, j) = (tri.input_index(p), tri.input_index(q));
        let named = [i.min(j), i.max(j)];
        if first.is_none_or(|f| named < f) {
            first = Some(named);
        }
    }
    let [i, j] = first?;
    Some(Warning {
        code: WarningCode::ChainEndsClose,
        message: format!(
            "{} within a few steps of each other (points {i} and {j} at {}): if they are one curve, \
             noise, a gap in the samples or a corner sharper than the spacing allows broke it \
             there; sample it more densely or with less noise",
            count(pairs, "pair of open chains ends", "pairs of open chains end"),
            position(at(tri.local_index(i)))
        ),
        points: vec![i, j],
    })
}

/// Counts one more flagged edge, keeping the worst.
fn note(worst: &mut (usize, f64, [u32; 2]), ratio: f64, ends: [u32; 2]) {
    worst.0 += 1;
    if ratio > worst.1 || worst.0 == 1 {
        worst.1 = ratio;
        worst.2 = ends;
    }
}

/// `curves-too-close`: Delaunay neighbours on curves, not neighbours along them, as close as
/// both their longer curve edges, on different curves or far apart along one.
fn curves_too_close(rec: &Reconstruction, survey: &Survey) -> Option<Warning> {
    let tri = &rec.triangulation;
    let [i, j] = survey.first_close?;
    Some(Warning {
        code: WarningCode::CurvesTooClose,
        message: format!(
            "curves pass within the sample spacing of each other at {} (e.g. points {i} and {j} \
             at {}): the samples cannot tell them apart there, so they may be merged or split \
             wrongly; sample more densely where curves nearly touch",
            count(survey.close_pairs, "place", "places"),
            position(tri.point(i))
        ),
        points: vec![i, j],
    })
}

fn percent(part: usize, whole: usize) -> String {
    format!("{:.0} %", 100.0 * part as f64 / whole.max(1) as f64)
}

fn count(n: usize, one: &str, many: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

fn round_ratio(r: f64) -> String {
    if r.is_finite() && r < 1e6 {
        format!("{:.1}", r)
    } else {
        format!("{r:e}")
    }
}

/// `(x, y)` in the shortest form that reads back, with an exponent beyond 1e15 and below
/// 1e-4 (Rust's `{}` writes every digit of 1e187).
fn position(p: [f64; 2]) -> String {
    let one = |x: f64| {
        if x == 0.0 || (1e-4..1e15).contains(&x.abs()) {
            format!("{x}")
        } else {
            format!("{x:e}")
        }
    };
    format!("({}, {})", one(p[0]), one(p[1]))
}
