//! Peeling: nested curves (holes) by further passes on the points the crust left untouched,
//! and which inner Voronoi vertices those holes take away from the medial axis. All point
//! indices here are local to the full triangulation, except the curves' (see [`hole_edges`]).

use super::curves::{Adjacency, Curve};
use super::extract::wdm_crust_edges;
use super::medial_axis::parity_from_infinity;
use super::options::Options;
use super::wdm;
use crate::delaunay::{triangulate, Triangulation};
use crate::voronoi::Voronoi;

/// Points without an edge (local indices: duplicates are not points here).
fn untouched(tri: &Triangulation, edges: &[[u32; 2]]) -> Vec<u32> {
    let n = tri.points.len();
    let mut touched = vec![false; n];
    for &[a, b] in edges {
        touched[a as usize] = true;
        touched[b as usize] = true;
    }
    (0..n as u32).filter(|&p| !touched[p as usize]).collect()
}

/// Reruns WDM_CRUST on the points the crust left untouched, adding what each pass finds,
/// until a pass finds nothing, fewer than three points remain, or the next pass would exceed
/// [`Options::with_peeling_budget`].
///
/// Only edges of the full Delaunay triangulation are taken from a later pass. A nested
/// curve's edges are Delaunay edges of all the points (so they never cross an earlier
/// curve), whereas the leftovers of a noisy band would otherwise be joined by long chords
/// across the curve already found.
pub(super) fn peel(full: &Voronoi<'_>, edges: &mut Vec<[u32; 2]>, options: &Options) -> Peeling {
    let tri = full.triangulation();
    let points = &tri.points;
    let mut budget = options.peeling_budget().saturating_mul(points.len());
    let mut extra = 0;
    loop {
        let rest = untouched(tri, edges);
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
        if found.is_empty() {
            return Peeling::done(extra);
        }
        edges.extend(found);
        extra += 1;
    }
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
