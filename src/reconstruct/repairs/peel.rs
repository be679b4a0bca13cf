//! Peeling: nested curves (holes) by further passes on the points the crust left untouched,
//! and which inner Voronoi vertices those holes take away from the medial axis. All point
//! indices here are local to the full triangulation.

use std::ops::ControlFlow;

use super::ears::{repair_ears, Ears};
use super::shared::{curve_edges, edges_near, lies_apart, median_length, segment_distance};
use crate::delaunay::triangulate;
use crate::ids::{ids, HalfEdge, LocalPoint};
use crate::reconstruct::curves::{assemble_unnamed, Adjacency, LocalCurve};
use crate::reconstruct::extract::wdm_crust_edges;
use crate::reconstruct::lengths::distance;
use crate::reconstruct::options::Options;
use crate::reconstruct::parity::parity_from_infinity;
use crate::reconstruct::segment_walk::crosses_a_curve;
use crate::reconstruct::thresholds::peel::{
    LINK, MAX_MEDIAN_TURN, MIN_CHAIN_POINTS, MIN_GROUP, MIN_LOOP_POINTS, NEAR_CURVE, SPARSER_LOOP,
};
use crate::reconstruct::wdm;
use crate::voronoi::Voronoi;

/// Reruns WDM_CRUST on the points no curve has taken, to find nested curves (holes),
/// until a pass finds no new closed curve, fewer than three points remain, or the next pass
/// would exceed [`Options::with_peeling_budget`].
///
/// What a later pass keeps, and why (the paper stops after one pass; this is the reading
/// of DESIGN.md's "peeling that keeps holes and drops noise"):
/// * only edges of the full Delaunay triangulation: a nested curve's edges are Delaunay
///   edges of all the points (they never cross an earlier curve), whereas the leftovers of
///   a noisy band would otherwise be joined by long chords across the curve already found.
///   One exception: chords that cross no earlier curve (decided exactly) may close a loop
///   that lies apart from the earlier curves ([`loops_by_chords`], [`close_by_chord`]);
/// * only pieces that read as sampled curves ([`is_a_curve`]): sampled no more than
///   [`SPARSER_LOOP`] times as sparsely as the curves before, loops of at least
///   [`MIN_LOOP_POINTS`] points, smooth open chains only when long: short and zigzag
///   chains, junction stubs, small loops and loops through scattered points are the pass's
///   reading of noise, not curves;
/// * no point within [`NEAR_CURVE`] edge lengths of a curve already found takes part in a
///   later pass: such a point is a leftover of that curve's noise band; nor does a point
///   with fewer than two other leftovers within a few local spacings
///   ([`isolated_leftovers`]): the water of the pass would run around it.
///
/// Points excluded by these rules stay without edges: the reconstruction reports them as
/// unassigned. On clean samples nothing changes: a hole's samples are far from the outer
/// curve relative to the sample spacing, and its loop is all the pass finds.
pub(crate) fn peel(
    full: &Voronoi<'_>,
    edges: &mut Vec<[LocalPoint; 2]>,
    options: &Options,
) -> Peeling {
    let tri = full.triangulation();
    let points = &tri.points;
    let n = points.len();
    // A clean sample leaves fewer than three points to peel, and a nearly clean one only
    // leftovers of its noise: return before building anything over all the points.
    let mut budget = options.peeling_budget().saturating_mul(n);
    if !first_pass_may_run(full, edges) {
        return Peeling::done(0, budget);
    }
    // Points that can no longer start a curve: noise leftovers and what a pass could only
    // read as noise.
    let mut spent = vec![false; n];
    let mut extra = 0;
    loop {
        let curve = Adjacency::new(n, edges);
        for p in ids::<LocalPoint>(n) {
            if !spent[p.index()]
                && curve.neighbours(p).is_empty()
                && near_a_curve(full, |q| curve.neighbours(q), p)
            {
                spent[p.index()] = true;
            }
        }
        let rest: Vec<LocalPoint> = ids::<LocalPoint>(n)
            .filter(|&p| !spent[p.index()] && curve.neighbours(p).is_empty())
            .collect();
        for p in isolated_leftovers(full, &rest) {
            spent[p.index()] = true;
        }
        let rest: Vec<LocalPoint> = rest.into_iter().filter(|&p| !spent[p.index()]).collect();
        if rest.len() < 3 {
            return Peeling::done(extra, budget);
        }
        if rest.len() > budget {
            return Peeling {
                extra_passes: extra,
                budget_exhausted: true,
                budget_left: budget,
            };
        }
        budget -= rest.len();
        let scale = median_length(points, edges);
        let mut pass = later_pass(full, &rest, options);
        pass.chords
            .retain(|&[a, b]| !crosses_a_curve(full, &curve, a, b));
        let chord_loops = loops_by_chords(full, &curve, &mut pass);
        let found = Adjacency::new(n, &pass.edges);
        let mut new_curves = Vec::new();
        let pieces = assemble_unnamed(n, &pass.edges, points, LocalPoint::get);
        for mut piece in chord_loops.into_iter().chain(pieces) {
            close_by_chord(full, &curve, &found, &pass.chords, &mut piece);
            if is_a_curve(points, &piece, scale) {
                new_curves.extend(curve_edges(&piece));
            } else {
                for &p in &piece.points {
                    spent[p.index()] = true;
                }
            }
        }
        if pass.edges.is_empty() && new_curves.is_empty() {
            return Peeling::done(extra, budget);
        }
        // A pass that found only noise still made progress: its points are spent, and what
        // the noise hid from the water (a hole inside a ring of leftovers) is next.
        edges.extend(new_curves);
        extra += 1;
    }
}

/// Would the first round of [`peel`]'s loop go on to a later pass: are three or more
/// untouched points neither near a curve nor isolated? Decided as that round decides it,
/// but with the curve edges at the untouched points' Delaunay neighbours alone: a large,
/// nearly clean sample leaves a handful of untouched points, and the loop's structures
/// over all points (an adjacency of every edge) were then most of the phase's time.
fn first_pass_may_run(full: &Voronoi<'_>, edges: &[[LocalPoint; 2]]) -> bool {
    let n = full.triangulation().points.len();
    // A flag per point, not a bit: consecutive edges set bits of one word, and each of
    // those read-modify-writes waited for the one before (twice as slow at 10^7).
    let mut touched = vec![false; n];
    for &[a, b] in edges {
        touched[a.index()] = true;
        touched[b.index()] = true;
    }
    let untouched: Vec<LocalPoint> = ids::<LocalPoint>(n)
        .filter(|&p| !touched[p.index()])
        .collect();
    if untouched.len() < 3 {
        return false;
    }
    // Every curve edge at a neighbour of an untouched point: all that `near_a_curve` reads.
    let curve = edges_near(full, &untouched, edges);
    let rest: Vec<LocalPoint> = untouched
        .into_iter()
        .filter(|&p| !near_a_curve(full, |q| curve.neighbours(q), p))
        .collect();
    let isolated = isolated_leftovers(full, &rest);
    rest.len() - isolated.len() >= 3
}

/// The left-over points that lie apart from every other left-over point: in connected
/// groups of fewer than [`MIN_GROUP`] points, where a point is linked to a Delaunay
/// neighbour (of all the points) in `rest` no farther than [`LINK`] times the longer of
/// their nearest-neighbour distances. Such points are the scattered leftovers of a noise
/// band that [`near_a_curve`] missed: no curve can be drawn through them, yet in a later
/// pass they lie on the convex hull and the water runs around them, so a hole's loop is
/// drawn through them across the empty inside of the shape, with chords that are no
/// Delaunay edges, and is lost. Measured in local spacings (the nearest-neighbour
/// distances), so that the sparse parts of a drawing keep their strokes.
///
/// The groups are sets of points: the result does not depend on the input order. `rest` is
/// sorted.
fn isolated_leftovers(full: &Voronoi<'_>, rest: &[LocalPoint]) -> Vec<LocalPoint> {
    let mut isolated = Vec::new();
    leftover_groups(full, rest, |group| {
        if group.len() < MIN_GROUP {
            isolated.extend(group.iter().map(|&i| rest[i]));
        }
        ControlFlow::Continue(())
    });
    isolated
}

/// The groups of `rest` (sorted), as positions in it, each handed to `each` as it is found
/// (which may stop the search): points linked to a Delaunay neighbour (of all the points) in
/// `rest` no farther than [`LINK`] times the longer of their nearest-neighbour distances,
/// and the points linked to those. Groups are sets: which are found does not depend on the
/// input order.
pub(super) fn leftover_groups(
    full: &Voronoi<'_>,
    rest: &[LocalPoint],
    mut each: impl FnMut(&[usize]) -> ControlFlow<()>,
) {
    let points = &full.triangulation().points;
    let at = |p: LocalPoint| points[p.index()];
    // Position in `rest` (sorted) of a point, or none: an array over all points, or for
    // few leftovers a binary search (the array alone would be a pass over all points).
    let slots = (rest.len() >= points.len() / 64).then(|| {
        let mut slots = vec![u32::MAX; points.len()];
        for (i, &p) in rest.iter().enumerate() {
            slots[p.index()] = i as u32;
        }
        slots
    });
    let slot = |q: LocalPoint| match &slots {
        Some(slots) => Some(slots[q.index()] as usize).filter(|&j| j != u32::MAX as usize),
        None => rest.binary_search(&q).ok(),
    };
    let nearest: Vec<f64> = rest
        .iter()
        .map(|&p| {
            full.delaunay_neighbours(p)
                .map(|q| distance(at(p), at(q)))
                .fold(f64::INFINITY, f64::min)
        })
        .collect();
    let mut grouped = vec![false; rest.len()];
    for start in 0..rest.len() {
        if grouped[start] {
            continue;
        }
        grouped[start] = true;
        let mut group = vec![start];
        let mut next = 0;
        while next < group.len() {
            let i = group[next];
            next += 1;
            let p = rest[i];
            for q in full.delaunay_neighbours(p) {
                let Some(j) = slot(q) else {
                    continue;
                };
                if !grouped[j] && distance(at(p), at(q)) <= LINK * nearest[i].max(nearest[j]) {
                    grouped[j] = true;
                    group.push(j);
                }
            }
        }
        if each(&group).is_break() {
            return;
        }
    }
}

/// What a later pass found: its WDM_CRUST edges that are edges of the full triangulation
/// (`[min, max]`, local indices of the full triangulation, sorted), and the other ones
/// (sorted): [`peel`] keeps those that cross no curve found before, candidates for
/// [`close_by_chord`].
pub(super) struct LaterPass {
    pub(super) edges: Vec<[LocalPoint; 2]>,
    pub(super) chords: Vec<[LocalPoint; 2]>,
}

/// WDM_CRUST on the points `rest` alone (see [`peel`]).
pub(super) fn later_pass(full: &Voronoi<'_>, rest: &[LocalPoint], options: &Options) -> LaterPass {
    let points = &full.triangulation().points;
    let subset: Vec<[f64; 2]> = rest.iter().map(|&i| points[i.index()]).collect();
    let nothing = LaterPass {
        edges: Vec::new(),
        chords: Vec::new(),
    };
    // The subset is a selection of already validated points: this cannot fail.
    let Ok(sub) = triangulate(&subset) else {
        return nothing;
    };
    if sub.is_degenerate() {
        return nothing;
    }
    let vor = sub.voronoi();
    let mut labels = wdm::labels(&vor, options.label_rule());
    let mut crust = wdm_crust_edges(&vor, &labels);
    // Dropped, never rejoined: rejoining here too lost more holes than it kept (likely: the
    // rejoining edge is the pass's, not always a Delaunay edge of all the points, and the
    // rule below opens the loop there; ARCHITECTURE.md, "Ears").
    repair_ears(&vor, &mut labels, &mut crust, Ears::Drop);
    // `sub`'s local points are its own; its caller indices are positions in `rest`.
    let (mut edges, mut chords): (Vec<[LocalPoint; 2]>, Vec<[LocalPoint; 2]>) = crust
        .iter()
        .map(|&[a, b]| {
            let at = |p: LocalPoint| rest[sub.input_index(p) as usize];
            let (a, b) = (at(a), at(b));
            [a.min(b), a.max(b)]
        })
        .partition(|&[a, b]| full.is_delaunay_edge(a, b));
    edges.sort_unstable();
    chords.sort_unstable();
    LaterPass { edges, chords }
}

/// Closes an open chain of a later pass into a loop when the pass joined its two ends
/// (both of degree 1) by a chord that is no Delaunay edge of all the points but crosses no
/// curve found before, and the loop lies apart from those curves ([`lies_apart`]).
///
/// Why: around a noisy hole the pass's own noise leaves points inside the hole's band that
/// its loop passes by; the water of a pass on the leftovers alone comes from all sides, so
/// the loop may bridge such a pocket by a chord whose every empty circle, among all the
/// points, holds a point of the outer curve. Dropping the chord (the Delaunay rule, kept for
/// all other edges) left an open chain that reads as noise, and the hole was lost. The
/// separation test keeps a chain of noise leftovers near a curve from being closed instead.
fn close_by_chord(
    full: &Voronoi<'_>,
    earlier: &Adjacency,
    found: &Adjacency,
    chords: &[[LocalPoint; 2]],
    piece: &mut LocalCurve,
) {
    let p = &piece.points;
    if piece.closed || p.len() < 3 {
        return;
    }
    let (u, v) = (p[0], p[p.len() - 1]);
    let is_end = |w: LocalPoint| found.neighbours(w).len() == 1;
    if chords.binary_search(&[u.min(v), u.max(v)]).is_err() || !is_end(u) || !is_end(v) {
        return;
    }
    piece.closed = true;
    let points = &full.triangulation().points;
    let spacing = median_length(points, &curve_edges(piece));
    if !lies_apart(
        full,
        |q| earlier.neighbours(q),
        &piece.points,
        spacing,
        |_| true,
    ) {
        piece.closed = false;
    }
}

/// Takes out of `pass` the loops it drew across pockets of noise: the cycles of its edges
/// and chords together that use at least one chord and lie apart from the curves found
/// before (`earlier`, see [`lies_apart`]). Their edges and chords leave `pass`; the loops
/// are returned, each starting at its smallest point.
///
/// Why: [`close_by_chord`] closes a chain whose two ends one chord joins, but at heavy noise
/// (about one sample spacing) the pass bridges two or more such pockets around a hole, and
/// the Delaunay rule cuts its loop into chains that each read as noise. Every chord crosses
/// no earlier curve (decided exactly), and the pass's edges and chords are edges of one
/// triangulation, so they cross no other curve either: the loop is a curve of a plane
/// drawing. The separation test keeps chains of a noise band's leftovers near a curve
/// from being closed this way.
fn loops_by_chords(
    full: &Voronoi<'_>,
    earlier: &Adjacency,
    pass: &mut LaterPass,
) -> Vec<LocalCurve> {
    if pass.chords.is_empty() {
        return Vec::new();
    }
    let points = &full.triangulation().points;
    let mut both: Vec<[LocalPoint; 2]> = pass.edges.iter().chain(&pass.chords).copied().collect();
    both.sort_unstable();
    let is_chord = |e: &[LocalPoint; 2]| pass.chords.binary_search(e).is_ok();
    let mut loops = Vec::new();
    for piece in assemble_unnamed(points.len(), &both, points, LocalPoint::get) {
        if !piece.closed {
            continue;
        }
        let edges = curve_edges(&piece);
        if !edges.iter().any(is_chord) {
            continue;
        }
        let spacing = median_length(points, &edges);
        if lies_apart(
            full,
            |q| earlier.neighbours(q),
            &piece.points,
            spacing,
            |_| true,
        ) {
            loops.push((piece, edges));
        }
    }
    let mut taken: Vec<[LocalPoint; 2]> =
        loops.iter().flat_map(|(_, e)| e.iter().copied()).collect();
    taken.sort_unstable();
    let kept = |e: &[LocalPoint; 2]| taken.binary_search(e).is_err();
    pass.edges.retain(kept);
    pass.chords.retain(kept);
    loops.into_iter().map(|(piece, _)| piece).collect()
}

/// Does a piece a later pass found read as a sampled curve, not as noise?
/// * sampled like the curves found before it: the median edge at most [`SPARSER_LOOP`]
///   times theirs (`scale`);
/// * a closed loop has at least [`MIN_LOOP_POINTS`] points: noise leaves no such loop far
///   from every curve found before (a hole's own noise does not stop it being a loop), but
///   three to six leftovers of a noise band close into a small one;
/// * an open chain has at least [`MIN_CHAIN_POINTS`] points and is smooth: the median
///   turning angle between consecutive edges at most [`MAX_MEDIAN_TURN`] (an ε-sample of a
///   smooth curve turns by about ε radians per sample, a path through noise points
///   zigzags).
fn is_a_curve(points: &[[f64; 2]], curve: &LocalCurve, scale: f64) -> bool {
    let p = &curve.points;
    let fewest = if curve.closed {
        MIN_LOOP_POINTS
    } else {
        MIN_CHAIN_POINTS
    };
    if p.len() < fewest || median_length(points, &curve_edges(curve)) > SPARSER_LOOP * scale {
        return false;
    }
    if curve.closed {
        return true;
    }
    let at = |i: usize| points[p[i].index()];
    let mut turns: Vec<f64> = (1..p.len() - 1)
        .map(|i| turning_angle(at(i - 1), at(i), at(i + 1)))
        .collect();
    let mid = turns.len() / 2;
    *turns.select_nth_unstable_by(mid, f64::total_cmp).1 <= MAX_MEDIAN_TURN
}

/// The angle (radians, in `[0, π]`) by which the path `a → b → c` turns at `b`.
fn turning_angle(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
    (u[0] * v[1] - u[1] * v[0])
        .atan2(u[0] * v[0] + u[1] * v[1])
        .abs()
}

/// Is `p` a leftover of a curve's noise band: closer to a curve edge at one of its Delaunay
/// neighbours than [`NEAR_CURVE`] times the sample spacing there? The nearest curve point is
/// always among the Delaunay neighbours when the curve is the only thing around.
///
/// The price of the rule: a separate curve closer to another than 1.5 of the other's sample
/// spacings is taken for noise (the gills under the sparse cap of `mushroom.p2d`). Keeping
/// points that lie closer to each other than to the curve instead lost the hole of a noisy
/// annulus in most trials at noise of one spacing (its leftovers pair up), and a scan's noise
/// is the common case.
///
/// `curve(q)` gives the curve edges at `q`, as [`Adjacency::neighbours`] does.
fn near_a_curve<'a>(
    full: &Voronoi<'_>,
    curve: impl Fn(LocalPoint) -> &'a [(u32, LocalPoint)],
    p: LocalPoint,
) -> bool {
    let points = &full.triangulation().points;
    let at = |i: LocalPoint| points[i.index()];
    full.delaunay_neighbours(p).any(|q| {
        // The sample spacing at q: its shortest curve edge (a long edge, where a curve
        // bridges a gap, says nothing about how far its noise reaches).
        let spacing = curve(q)
            .iter()
            .map(|&(_, r)| distance(at(q), at(r)))
            .fold(f64::INFINITY, f64::min);
        curve(q)
            .iter()
            .any(|&(_, r)| segment_distance(at(p), at(q), at(r)) < NEAR_CURVE * spacing)
    })
}

/// How peeling ended.
pub(crate) struct Peeling {
    pub(crate) extra_passes: usize,
    pub(crate) budget_exhausted: bool,
    /// How many more points later passes may run on ([`Options::with_peeling_budget`]
    /// times the input's, less what the passes took): the loops beside curves
    /// (`beside.rs`) spend it too.
    pub(crate) budget_left: usize,
}

impl Peeling {
    pub(crate) fn done(extra_passes: usize, budget_left: usize) -> Peeling {
        Peeling {
            extra_passes,
            budget_exhausted: false,
            budget_left,
        }
    }
}

/// The edges of the holes peeling found: closed loops made only of later-pass edges, each
/// with a dual Voronoi edge. The first pass never reaches inside a hole (water from
/// infinity), so its labels already say what lies inside the outer curves; the hole loops
/// say what to take away.
///
/// Only such loops are counted because only they make the parity below well defined: they
/// are disjoint cycles of degree-2 points, so every closed walk in the Voronoi graph crosses
/// them an even number of times, and the parity of a vertex does not depend on the path by
/// which it is reached. Open chains and junctions (noise) have no inside; counting them made
/// the result depend on the search order, hence on the input order (a fuzz finding). A
/// loop through an edge without a dual (inside a merged cocircular face) cannot separate
/// that face's vertex and is not counted either.
///
/// The curves (the final ones), `not_first_pass` (which tells the curves' edges the first
/// pass did not find) and the result are in local indices.
pub(crate) fn hole_edges(
    vor: &Voronoi<'_>,
    curves: &[LocalCurve],
    not_first_pass: impl Fn(&[LocalPoint; 2]) -> bool,
) -> Vec<[LocalPoint; 2]> {
    let mut holes = Vec::new();
    for curve in curves.iter().filter(|c| c.closed) {
        let loop_edges = curve
            .points
            .iter()
            .zip(curve.points.iter().cycle().skip(1))
            .map(|(&a, &b)| [a.min(b), a.max(b)]);
        let is_hole = loop_edges.clone().all(|[a, b]| {
            not_first_pass(&[a, b]) && vor.delaunay_halfedge(a, b).is_some_and(|e| vor.has_dual(e))
        });
        if is_hole {
            holes.extend(loop_edges);
        }
    }
    holes
}

/// Every Voronoi vertex: is it separated from infinity by an odd number of the given edges
/// (searched from the rays)? Well defined only for a set of closed loops, see
/// [`hole_edges`].
pub(crate) fn parity_inside(vor: &Voronoi<'_>, edges: &[[LocalPoint; 2]]) -> Vec<bool> {
    let tri = vor.triangulation();
    // Crust neighbours of every point (two for most): a lookup touches one short row
    // instead of a binary search over all edges.
    let crust = Adjacency::new(tri.points.len(), edges);
    let is_crust = |e: HalfEdge| {
        let b = tri.dest(e);
        crust.neighbours(tri.org(e)).iter().any(|&(_, q)| q == b)
    };
    parity_from_infinity(vor, vec![false; vor.vertex_count()], is_crust)
}
