//! Peeling: nested curves (holes) by further passes on the points the crust left untouched,
//! and which inner Voronoi vertices those holes take away from the medial axis. All point
//! indices here are local to the full triangulation, except the curves' (see [`hole_edges`]).

use super::curves::{assemble_named, Adjacency, Curve};
use super::extract::wdm_crust_edges;
use super::medial_axis::parity_from_infinity;
use super::options::Options;
use super::wdm;
use crate::delaunay::triangulate;
use crate::voronoi::Voronoi;

/// How close to a curve already found a left-over point may lie and still be taken for a
/// sample of another curve: its distance to a curve edge, in units of that edge's length.
/// The leftovers of a noise band sit within about the noise amplitude of the curve, which
/// is of the order of the sample spacing, while a curve separate from it (a hole) lies at
/// least about 1/ε sample spacings away for an ε-sample (ε < 1): see [`peel`].
const NEAR_CURVE: f64 = 1.5;

/// How much sparser than the curves found before it a later pass's loop may be sampled: the
/// median of its edge lengths, in units of the median over the curves found before. A
/// nested curve in a scan is sampled like the rest of it; a loop drawn through scattered
/// outliers inside a shape has edges of the outliers' spacing, many sample spacings long.
const SPARSER_LOOP: f64 = 3.0;

/// The largest median turning angle of a later pass's curve: 20°, about the turn per
/// sample of an ε-sample with ε = 0.35 (see [`is_a_curve`]).
const MAX_MEDIAN_TURN: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// The fewest points of an open chain a later pass keeps (see [`is_a_curve`]).
const MIN_CHAIN_POINTS: usize = 8;

/// Reruns WDM_CRUST on the points no curve has taken, to find nested curves (holes),
/// until a pass finds no new closed curve, fewer than three points remain, or the next pass
/// would exceed [`Options::with_peeling_budget`].
///
/// What a later pass keeps, and why (the paper stops after one pass; this is the reading
/// of DESIGN.md's "peeling that keeps holes and drops noise"):
/// * only edges of the full Delaunay triangulation: a nested curve's edges are Delaunay
///   edges of all the points (they never cross an earlier curve), whereas the leftovers of
///   a noisy band would otherwise be joined by long chords across the curve already found;
/// * only pieces that read as sampled curves ([`is_a_curve`]): sampled no more than
///   [`SPARSER_LOOP`] times as sparsely as the curves before, smooth, and open chains only
///   when long: short and zigzag chains, junction stubs and loops through scattered points
///   are the pass's reading of noise, not curves;
/// * no point within [`NEAR_CURVE`] edge lengths of a curve already found takes part in a
///   later pass: such a point is a leftover of that curve's noise band.
///
/// Points excluded by these rules stay without edges: the reconstruction reports them as
/// unassigned. On clean samples nothing changes: a hole's samples are far from the outer
/// curve relative to the sample spacing, and its loop is all the pass finds.
pub(super) fn peel(full: &Voronoi<'_>, edges: &mut Vec<[u32; 2]>, options: &Options) -> Peeling {
    let tri = full.triangulation();
    let points = &tri.points;
    let n = points.len();
    // A clean sample leaves fewer than three points to peel: return before building anything.
    let mut touched = vec![false; n];
    for &[a, b] in edges.iter() {
        touched[a as usize] = true;
        touched[b as usize] = true;
    }
    if touched.iter().filter(|&&t| !t).nth(2).is_none() {
        return Peeling::done(0);
    }
    drop(touched);
    let mut budget = options.peeling_budget().saturating_mul(n);
    // Points that can no longer start a curve: noise leftovers and what a pass could only
    // read as noise.
    let mut spent = vec![false; n];
    let mut extra = 0;
    loop {
        let curve = Adjacency::new(n, edges);
        for p in 0..n as u32 {
            if !spent[p as usize] && curve.neighbours(p).is_empty() && near_a_curve(full, &curve, p)
            {
                spent[p as usize] = true;
            }
        }
        let rest: Vec<u32> = (0..n as u32)
            .filter(|&p| !spent[p as usize] && curve.neighbours(p).is_empty())
            .collect();
        if rest.len() < 3 {
            return Peeling::done(extra);
        }
        if rest.len() > budget {
            return Peeling {
                extra_passes: extra,
                budget_exhausted: true,
            };
        }
        budget -= rest.len();
        let subset: Vec<[f64; 2]> = rest.iter().map(|&i| points[i as usize]).collect();
        // The subset is a selection of already validated points: this cannot fail.
        let Ok(sub) = triangulate(&subset) else {
            return Peeling::done(extra);
        };
        if sub.is_degenerate() {
            return Peeling::done(extra);
        }
        let vor = sub.voronoi();
        let flow = wdm::label_vertices_local(&vor, options.label_rule());
        // `sub`'s caller indices are positions in `rest`.
        let found: Vec<[u32; 2]> = wdm_crust_edges(&vor, &flow.labels)
            .iter()
            .map(|&[a, b]| {
                let at = |p: u32| rest[sub.input_index(p) as usize];
                let (a, b) = (at(a), at(b));
                [a.min(b), a.max(b)]
            })
            .filter(|&[a, b]| full.is_delaunay_edge(a, b))
            .collect();
        let scale = median_length(points, edges);
        let mut new_curves = Vec::new();
        for piece in assemble_named(n, &found, points, |p| p) {
            if is_a_curve(points, &piece, scale) {
                new_curves.extend(piece_edges(&piece));
            } else {
                for &p in &piece.points {
                    spent[p as usize] = true;
                }
            }
        }
        if found.is_empty() {
            return Peeling::done(extra);
        }
        // A pass that found only noise still made progress: its points are spent, and what
        // the noise hid from the water (a hole inside a ring of leftovers) is next.
        edges.extend(new_curves);
        extra += 1;
    }
}

/// The edges `[min, max]` of a curve (a closed one includes its closing edge).
fn piece_edges(curve: &Curve) -> Vec<[u32; 2]> {
    let p = &curve.points;
    let closing = curve.closed.then(|| [p[p.len() - 1], p[0]]);
    p.windows(2)
        .map(|w| [w[0], w[1]])
        .chain(closing)
        .map(|[a, b]| [a.min(b), a.max(b)])
        .collect()
}

/// Does a piece a later pass found read as a sampled curve, not as noise?
/// * sampled like the curves found before it: the median edge at most [`SPARSER_LOOP`]
///   times theirs (`scale`);
/// * a closed loop is a curve by that alone: noise leaves no closed loop far from every
///   curve found before (a hole's own noise does not stop it being a loop);
/// * an open chain has at least [`MIN_CHAIN_POINTS`] points and is smooth: the median
///   turning angle between consecutive edges at most [`MAX_MEDIAN_TURN`] (an ε-sample of a
///   smooth curve turns by about ε radians per sample, a path through noise points
///   zigzags).
fn is_a_curve(points: &[[f64; 2]], curve: &Curve, scale: f64) -> bool {
    let p = &curve.points;
    if !curve.closed && p.len() < MIN_CHAIN_POINTS {
        return false;
    }
    if median_length(points, &piece_edges(curve)) > SPARSER_LOOP * scale {
        return false;
    }
    if curve.closed {
        return true;
    }
    let at = |i: usize| points[p[i] as usize];
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

/// The median length of `edges` (0 for none). A rounded length: it only sets the scale of a
/// rule's threshold, never an exact decision.
fn median_length(points: &[[f64; 2]], edges: &[[u32; 2]]) -> f64 {
    let mut lengths: Vec<f64> = edges
        .iter()
        .map(|&[a, b]| distance(points[a as usize], points[b as usize]))
        .collect();
    if lengths.is_empty() {
        return 0.0;
    }
    let mid = lengths.len() / 2;
    *lengths.select_nth_unstable_by(mid, f64::total_cmp).1
}

fn distance(a: [f64; 2], b: [f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// Distance from `p` to the segment `ab`.
fn segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    distance(p, [a[0] + t * dx, a[1] + t * dy])
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
fn near_a_curve(full: &Voronoi<'_>, curve: &Adjacency, p: u32) -> bool {
    let points = &full.triangulation().points;
    let at = |i: u32| points[i as usize];
    full.delaunay_neighbours_local(p).any(|q| {
        // The sample spacing at q: its shortest curve edge (a long edge, where a curve
        // bridges a gap, says nothing about how far its noise reaches).
        let spacing = curve
            .neighbours(q)
            .iter()
            .map(|&(_, r)| distance(at(q), at(r)))
            .fold(f64::INFINITY, f64::min);
        curve
            .neighbours(q)
            .iter()
            .any(|&(_, r)| segment_distance(at(p), at(q), at(r)) < NEAR_CURVE * spacing)
    })
}

/// How peeling ended.
pub(super) struct Peeling {
    pub(super) extra_passes: usize,
    pub(super) budget_exhausted: bool,
}

impl Peeling {
    pub(super) fn done(extra_passes: usize) -> Peeling {
        Peeling {
            extra_passes,
            budget_exhausted: false,
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
/// The curves are the final ones, in caller indices; `first_pass` (sorted) and the result
/// are in local indices.
pub(super) fn hole_edges(
    vor: &Voronoi<'_>,
    curves: &[Curve],
    first_pass: &[[u32; 2]],
) -> Vec<[u32; 2]> {
    let tri = vor.triangulation();
    let mut holes = Vec::new();
    for curve in curves.iter().filter(|c| c.closed) {
        let local = |i: &u32| tri.local_index(*i);
        let loop_edges = curve
            .points
            .iter()
            .map(local)
            .zip(curve.points.iter().cycle().skip(1).map(local))
            .map(|(a, b)| [a.min(b), a.max(b)]);
        let is_hole = loop_edges.clone().all(|[a, b]| {
            first_pass.binary_search(&[a, b]).is_err()
                && vor.delaunay_halfedge(a, b).is_some_and(|e| vor.has_dual(e))
        });
        if is_hole {
            holes.extend(loop_edges);
        }
    }
    holes
}

/// Every Voronoi vertex: is it separated from infinity by an odd number of the given edges
/// (breadth first from the rays)? Well defined only for a set of closed loops, see
/// [`hole_edges`].
pub(super) fn parity_inside(vor: &Voronoi<'_>, edges: &[[u32; 2]]) -> Vec<bool> {
    let tri = vor.triangulation();
    // Crust neighbours of every point (two for most): a lookup touches one short row
    // instead of a binary search over all edges.
    let crust = Adjacency::new(tri.points.len(), edges);
    let is_crust = |e: u32| {
        let b = tri.dest(e as usize);
        crust
            .neighbours(tri.org(e as usize))
            .iter()
            .any(|&(_, q)| q == b)
    };
    parity_from_infinity(vor, vec![false; vor.vertex_count()], is_crust)
}
