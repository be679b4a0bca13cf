//! Facing corners: where two closed curves come within a few sample spacings of each other
//! at a corner (the tips of two wedges, a square's corner beside another square's side), the
//! water flow may join them across the gap: two long edges run from one curve to the other,
//! and each curve's own short step round its corner is missing (two curves become one loop,
//! or a loop of the corridor between them), with the corner samples sometimes left on no
//! curve. The swap puts the steps back: two long loop edges `p–q` and `r–s`, each at least
//! [`FACING_RATIO`] times the loop edges beside it, whose ends are pairwise near — `p` to `r`
//! and `q` to `s`, each by a Delaunay edge or through one unassigned point — become those
//! links, every link shorter than either long edge by the same factor.
//!
//! A long edge alone proves nothing (graded or oversampled samples have them); two whose
//! ends are pairwise a short step apart mean the loop folds back on itself within a step or
//! two, which a correct loop does only at a neck thinner than its sampling. The links are Delaunay
//! edges, so they cross no curve edge that is one; a curve edge that is none is walked
//! through the triangulation against them, exactly. The swaps are ordered by lengths and
//! coordinates, never by the curves' or the triangulation's order, so the result does not
//! depend on the input order. Part of settling the curves: it runs with the open-curve stage.
//! The rule and its measurements: `docs/design/facing-corners.md`.
//!
//! Every index here is local to the full triangulation.

use std::collections::HashMap;

use super::shared::curve_edges;
use crate::ids::LocalPoint;
use crate::reconstruct::curves::{lexicographic, zigzags, Adjacency, LocalCurve};
use crate::reconstruct::delaunay_graph::FastHash;
use crate::reconstruct::lengths::distance;
use crate::reconstruct::segment_walk::crosses_a_curve;
use crate::reconstruct::thresholds::facing::{FACING_FEWEST, FACING_RATIO, FACING_SHARE};
use crate::voronoi::Voronoi;

/// A long loop edge: its ends, its length, and where it is (the curve, an index into the
/// curves, and the position of its first end there).
#[derive(Clone, Copy)]
struct LongEdge {
    ends: [LocalPoint; 2],
    length: f64,
    curve: usize,
    position: usize,
}

/// A swap found: the long edges `a` (`p–q`) and `b` (`r–s`), and the links `p–r` and `q–s`,
/// each direct or through an unassigned point.
struct Swap {
    a: usize,
    b: usize,
    ends: [LocalPoint; 4],
    via: [Option<LocalPoint>; 2],
}

/// The edges of `curves` with every facing-corner swap made (see the module docs), or
/// `None` where there is none to make.
pub(crate) fn swap_facing_corners(
    full: &Voronoi<'_>,
    curves: &[LocalCurve],
) -> Option<Vec<[LocalPoint; 2]>> {
    let points = &full.triangulation().points;
    let n = points.len();
    let at = |p: LocalPoint| points[p.index()];
    let long = long_loop_edges(points, curves);
    if long.len() < 2 {
        return None;
    }
    // The long edge at each point (at most one: a long edge is longer than its neighbours), and
    // which points are on a curve.
    const NONE: u32 = u32::MAX;
    let mut long_at = vec![NONE; n];
    for (i, e) in long.iter().enumerate() {
        for p in e.ends {
            long_at[p.index()] = i as u32;
        }
    }
    let mut on_curve = vec![false; n];
    for c in curves {
        for &p in &c.points {
            on_curve[p.index()] = true;
        }
    }
    // The position of an end of a long edge on its curve.
    let position = |e: &LongEdge, p: LocalPoint| {
        let k = curves[e.curve].points.len();
        if p == e.ends[0] {
            e.position
        } else {
            (e.position + 1) % k
        }
    };
    // Are two ends of long edges steps of one curve?
    let steps_along = |e: &LongEdge, x: LocalPoint, f: &LongEdge, y: LocalPoint| {
        let k = curves[e.curve].points.len();
        let (i, j) = (position(e, x), position(f, y));
        e.curve == f.curve && ((i + 1) % k == j || (j + 1) % k == i)
    };
    // Every way from `p` to the end `target` of a long edge, or (with `target` None) to any
    // end of one, within `reach`: a Delaunay edge, or two through an unassigned point
    // other than `not_via`. All of them: which is taken is decided by coordinates below,
    // not by the order of the triangulation's neighbours.
    let links = |p: LocalPoint,
                 reach: f64,
                 target: Option<LocalPoint>,
                 not_via: Option<LocalPoint>|
     -> Vec<(LocalPoint, Option<LocalPoint>)> {
        let wanted = |r: LocalPoint| {
            r != p
                && match target {
                    Some(t) => r == t,
                    None => long_at[r.index()] != NONE,
                }
        };
        let near = |x: LocalPoint, y: LocalPoint| distance(at(x), at(y)) <= reach;
        let mut out = Vec::new();
        for u in full.delaunay_neighbours(p) {
            if !near(p, u) {
                continue;
            }
            if on_curve[u.index()] {
                if wanted(u) {
                    out.push((u, None));
                }
            } else if Some(u) != not_via {
                out.extend(
                    full.delaunay_neighbours(u)
                        .filter(|&r| on_curve[r.index()] && wanted(r) && near(u, r))
                        .map(|r| (r, Some(u))),
                );
            }
        }
        out
    };
    // Every swap of two long edges, each found from both of its edges.
    let mut found = Vec::new();
    for (a, e) in long.iter().enumerate() {
        for [p, q] in [e.ends, [e.ends[1], e.ends[0]]] {
            for (r, via_pr) in links(p, e.length / FACING_RATIO, None, None) {
                let b = long_at[r.index()] as usize;
                let f = &long[b];
                if b == a || steps_along(e, p, f, r) {
                    continue;
                }
                let s = if f.ends[0] == r { f.ends[1] } else { f.ends[0] };
                let reach = e.length.min(f.length) / FACING_RATIO;
                let legs_short = match via_pr {
                    None => distance(at(p), at(r)) <= reach,
                    Some(u) => distance(at(p), at(u)) <= reach && distance(at(u), at(r)) <= reach,
                };
                if !legs_short || [p, q].contains(&s) || steps_along(e, q, f, s) {
                    continue;
                }
                for (_, via_qs) in links(q, reach, Some(s), via_pr) {
                    found.push(Swap {
                        a,
                        b,
                        ends: [p, q, r, s],
                        via: [via_pr, via_qs],
                    });
                }
            }
        }
    }
    if found.is_empty() {
        return None;
    }
    // Made longest first, then those through unassigned points (a corner's own sample that
    // the long edges left out), then by coordinates: never by the curves' order (it follows
    // the input's) nor the triangulation's; each long edge and unassigned point in one swap
    // at most, and only between loops that do not zigzag: noise makes long edges beside
    // short ones, and its leftovers links (each loop tested once, exact orientations).
    let key = |w: &Swap| {
        let lengths = long[w.a].length.max(long[w.b].length);
        let skipped = w.via.iter().flatten().count();
        // The same swap found from either edge is one: its ends and links read from the
        // lexicographically smaller long edge.
        let [p, q, r, s] = w.ends.map(at);
        let ends = if by_coordinates(&[r, s], &[p, q]).is_lt() {
            [r, s, p, q]
        } else {
            [p, q, r, s]
        };
        let via = w.via.map(|v| v.map(at));
        (lengths, skipped, ends, via)
    };
    found.sort_by(|x, y| {
        let (kx, ky) = (key(x), key(y));
        ky.0.total_cmp(&kx.0)
            .then_with(|| ky.1.cmp(&kx.1))
            .then_with(|| by_coordinates(&kx.2, &ky.2))
            .then_with(|| {
                // A direct link first, then links through points by their coordinates.
                kx.3.iter()
                    .zip(&ky.3)
                    .map(|(x, y)| match (x, y) {
                        (Some(x), Some(y)) => lexicographic(*x, *y),
                        _ => x.is_some().cmp(&y.is_some()),
                    })
                    .find(|o| o.is_ne())
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
    });
    let mut used_edge = vec![false; long.len()];
    let mut used_point: Vec<LocalPoint> = Vec::new();
    let mut noisy: HashMap<usize, bool, FastHash> = HashMap::default();
    let mut removed: Vec<[LocalPoint; 2]> = Vec::new();
    let mut added: Vec<[LocalPoint; 2]> = Vec::new();
    for swap in found {
        let Swap { a, b, ends, via } = swap;
        if used_edge[a] || used_edge[b] || via.iter().flatten().any(|u| used_point.contains(u)) {
            continue;
        }
        let mut zigzagging = |j: usize| {
            *noisy
                .entry(j)
                .or_insert_with(|| zigzags(points, &curves[j]))
        };
        if zigzagging(long[a].curve) || zigzagging(long[b].curve) {
            continue;
        }
        used_edge[a] = true;
        used_edge[b] = true;
        let [p, q, r, s] = ends;
        removed.push(ordered([p, q]));
        removed.push(ordered([r, s]));
        for ([x, y], via) in [([p, r], via[0]), ([q, s], via[1])] {
            match via {
                None => added.push(ordered([x, y])),
                Some(u) => {
                    used_point.push(u);
                    added.push(ordered([x, u]));
                    added.push(ordered([u, y]));
                }
            }
        }
    }
    if added.is_empty() {
        return None;
    }
    let mut edges: Vec<[LocalPoint; 2]> = curves.iter().flat_map(curve_edges).collect();
    removed.sort_unstable();
    edges.retain(|e| removed.binary_search(e).is_err());
    // The links against the curve edges that are no Delaunay edges.
    let drawn = Adjacency::new(n, &added);
    if edges
        .iter()
        .any(|&[a, b]| !full.is_delaunay_edge(a, b) && crosses_a_curve(full, &drawn, a, b))
    {
        return None;
    }
    edges.extend(added);
    Some(edges)
}

/// The loop edges of `curves` at least [`FACING_RATIO`] times as long as each of the two
/// loop edges beside them (squared lengths: most edges are not), on loops where they are
/// rare: at most one in [`FACING_SHARE`], or [`FACING_FEWEST`].
fn long_loop_edges(points: &[[f64; 2]], curves: &[LocalCurve]) -> Vec<LongEdge> {
    let mut long = Vec::new();
    let squared_ratio = FACING_RATIO * FACING_RATIO;
    for (j, c) in curves.iter().enumerate() {
        if !c.closed || c.points.len() < 4 {
            continue;
        }
        let k = c.points.len();
        let at = |i: usize| points[c.points[i % k].index()];
        let squared = |i: usize| {
            let (a, b) = (at(i), at(i + 1));
            (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1])
        };
        let first = long.len();
        let (mut before, mut here) = (squared(k - 1), squared(0));
        for i in 0..k {
            let after = squared(i + 1);
            // Squared lengths that overflow or underflow (coordinates near the ends of the
            // `f64` range) decide nothing: such an edge is not taken for long.
            let measured = [before, here, after]
                .iter()
                .all(|&l| l.is_finite() && l >= f64::MIN_POSITIVE);
            if measured && here >= squared_ratio * before.max(after) {
                long.push(LongEdge {
                    ends: [c.points[i], c.points[(i + 1) % k]],
                    length: distance(at(i), at(i + 1)),
                    curve: j,
                    position: i,
                });
            }
            (before, here) = (here, after);
        }
        // On a loop sampled irregularly (at random positions) such edges are common and
        // say nothing of a gap.
        if long.len() - first > (k / FACING_SHARE).max(FACING_FEWEST) {
            long.truncate(first);
        }
    }
    long
}

/// Lists of points compared point by point, each by its coordinates
/// ([`lexicographic`]: by value, so that `-0.0` and `0.0`, one point, compare equal).
fn by_coordinates(a: &[[f64; 2]], b: &[[f64; 2]]) -> std::cmp::Ordering {
    a.iter()
        .zip(b)
        .map(|(&x, &y)| lexicographic(x, y))
        .find(|o| o.is_ne())
        .unwrap_or(std::cmp::Ordering::Equal)
}

/// An edge as `[min, max]`.
fn ordered([a, b]: [LocalPoint; 2]) -> [LocalPoint; 2] {
    [a.min(b), a.max(b)]
}
