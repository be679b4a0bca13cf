//! Corridors: water that leaked through a gap of a noisy curve into the region it bounds.
//! Repaired on the labels of the first pass, before the ears (all indices local).
//!
//! On noise of half a sample spacing and more, the band of an outer curve sometimes has a gap
//! two to four spacings wide whose Voronoi vertices the state transitions leave ACTIVATED. The
//! water passes it and runs on across the region inside (between the outer curve and a hole)
//! up to the hole. The first pass's loop is then the outer curve, a long chord along one wall
//! of the wet corridor, an arc of the hole and a chord back; the hole's other samples are left
//! to a later pass that cannot close them (`examples/noise_failures.rs`, "corridor").
//!
//! The corridor is recognised by the width of the way the water took. The *width* of an outer
//! vertex is the widest way from infinity to it through outer vertices: the largest, over
//! such paths, of the shortest Delaunay edge dual to a Voronoi edge on the path (a ray has
//! infinite width). Water reaches a region outside a curve through gaps between samples, and
//! the crust edges it then draws are sample gaps of the same curve: a crust edge far longer
//! than the way the water came by ([`NARROW`] times) is a wall of a corridor, not a gap of a
//! curve seen from outside. The **corridor** is then every outer vertex joined to the wall's
//! outer vertex by outer vertices no wider than it: the pocket behind the narrow gap. It is
//! relabelled inner; the gap's Delaunay edges become crust and close the outer curve, the
//! walls and the hole's arc stop being crust, and the hole's samples are left whole for
//! peeling.
//!
//! Only crust edges at least [`CHORD`] times the median crust edge are looked at (a corridor's
//! walls are 4.5–25 of them; a clean sample has none, so the widths are computed only when some
//! crust edge is that long). Lengths are compared in rounded arithmetic, as tolerances of the
//! rule (like peeling's); the widths are a maximin over the Voronoi graph, the same whatever
//! order the vertices are explored in, so the input order does not matter.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use super::shared::degrees;
use crate::delaunay::NO_TWIN;
use crate::ids::{ids, LocalPoint, VertexId};
use crate::reconstruct::extract::wdm_crust_edges;
use crate::reconstruct::thresholds::corridors::{CHORD, NARROW};
use crate::reconstruct::wdm::Label;
use crate::voronoi::{EdgeEnd, Voronoi};

/// Relabels the corridors of `labels` inner (see the module docs) and recomputes `edges`, the
/// crust of `labels`, when any is found. Returns the number of vertices relabelled.
pub(crate) fn repair_corridors(
    vor: &Voronoi<'_>,
    labels: &mut [Label],
    edges: &mut Vec<[LocalPoint; 2]>,
) -> usize {
    let points = &vor.triangulation().points;
    if every_point_on_two_edges(points.len(), edges) {
        return 0;
    }
    let length = |[a, b]: [LocalPoint; 2]| {
        let (p, q) = (points[a.index()], points[b.index()]);
        ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt()
    };
    // Squared lengths for the screen, which runs on every first pass (no square roots).
    let squared = |[a, b]: [LocalPoint; 2]| {
        let (p, q) = (points[a.index()], points[b.index()]);
        (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)
    };
    let mut lengths: Vec<f64> = edges.iter().map(|&e| squared(e)).collect();
    let bound = CHORD * CHORD * median(&mut lengths);
    let chords: Vec<[LocalPoint; 2]> = edges
        .iter()
        .copied()
        .filter(|&e| squared(e) > bound)
        .collect();
    if chords.is_empty() {
        return 0;
    }
    let width = widths(vor, labels, &length);
    let mut walls: Vec<VertexId> = chords
        .into_iter()
        .filter_map(|chord| {
            let o = outer_side(vor, labels, chord)?;
            (width[o.index()] * NARROW < length(chord)).then_some(o)
        })
        .collect();
    // Widest first: a pocket behind a narrower gap inside a wider one's is part of it, and
    // two pockets are otherwise disjoint, so the union does not depend on the chords' order.
    walls.sort_unstable_by(|&a, &b| {
        width[b.index()]
            .total_cmp(&width[a.index()])
            .then(a.cmp(&b))
    });
    let mut corridor = vec![false; labels.len()];
    let mut relabelled = 0;
    for o in walls {
        if !corridor[o.index()] {
            relabelled += flood(vor, labels, &width, o, &mut corridor);
        }
    }
    if relabelled == 0 {
        return 0;
    }
    for (label, &wet) in labels.iter_mut().zip(&corridor) {
        if wet {
            *label = Label::Inner;
        }
    }
    *edges = wdm_crust_edges(vor, labels);
    relabelled
}

/// Whether every point lies on exactly two of `edges`: the crust is then closed curves
/// through every sample, and no water leaked through a gap (a corridor strands the samples of
/// the hole beyond it). Such a first pass is left as it is, which also keeps the widths off
/// clean samples whose spacing varies (random parameters: crust edges of 4 median ones are
/// common there, and the widths cost 0.16 s at 10^6 points, measured).
fn every_point_on_two_edges(point_count: usize, edges: &[[LocalPoint; 2]]) -> bool {
    edges.len() == point_count && degrees(point_count, edges).iter().all(|&d| d == 2)
}

/// The median of `lengths` (0 when empty); reorders them.
fn median(lengths: &mut [f64]) -> f64 {
    if lengths.is_empty() {
        return 0.0;
    }
    let mid = lengths.len() / 2;
    *lengths.select_nth_unstable_by(mid, |a, b| a.total_cmp(b)).1
}

/// The finite outer vertex on the outer side of the crust edge `[a, b]` (none when that side
/// is infinity: a hull edge).
fn outer_side(vor: &Voronoi<'_>, labels: &[Label], [a, b]: [LocalPoint; 2]) -> Option<VertexId> {
    let e = vor.delaunay_halfedge(a, b)?;
    let twin = vor.triangulation().halfedges()[e.index()];
    if twin == NO_TWIN {
        return None;
    }
    [e, twin]
        .into_iter()
        .map(|h| vor.vertex_of_halfedge(h))
        .find(|&v| labels[v.index()] == Label::Outer)
}

/// The width of every outer vertex (0 for inner ones): widest paths from infinity, by a
/// Dijkstra search that takes the widest vertex first.
fn widths(
    vor: &Voronoi<'_>,
    labels: &[Label],
    length: &dyn Fn([LocalPoint; 2]) -> f64,
) -> Vec<f64> {
    let mut width = vec![0.0f64; labels.len()];
    let mut heap = BinaryHeap::new();
    for v in ids::<VertexId>(labels.len()) {
        let open = vor.face_edges(v).any(|edge| edge.to == EdgeEnd::Infinity);
        if labels[v.index()] == Label::Outer && open {
            width[v.index()] = f64::INFINITY;
            heap.push(Widest(f64::INFINITY, v));
        }
    }
    let mut done = vec![false; labels.len()];
    while let Some(Widest(w, v)) = heap.pop() {
        if done[v.index()] {
            continue;
        }
        done[v.index()] = true;
        for edge in vor.face_edges(v) {
            let EdgeEnd::Vertex(u) = edge.to else {
                continue;
            };
            if labels[u.index()] != Label::Outer || done[u.index()] {
                continue;
            }
            let through = w.min(length(edge.sites));
            if through > width[u.index()] {
                width[u.index()] = through;
                heap.push(Widest(through, u));
            }
        }
    }
    width
}

/// The outer vertices joined to `start` through outer vertices no wider than it, marked in
/// `corridor`; returns how many were newly marked.
fn flood(
    vor: &Voronoi<'_>,
    labels: &[Label],
    width: &[f64],
    start: VertexId,
    corridor: &mut [bool],
) -> usize {
    let limit = width[start.index()];
    let mut stack = vec![start];
    corridor[start.index()] = true;
    let mut marked = 1;
    while let Some(v) = stack.pop() {
        for edge in vor.face_edges(v) {
            let EdgeEnd::Vertex(u) = edge.to else {
                continue;
            };
            if labels[u.index()] == Label::Outer
                && !corridor[u.index()]
                && width[u.index()] <= limit
            {
                corridor[u.index()] = true;
                marked += 1;
                stack.push(u);
            }
        }
    }
    marked
}

/// A vertex and its width, ordered by width (then by vertex, for a total order).
#[derive(PartialEq)]
struct Widest(f64, VertexId);

impl Eq for Widest {}

impl PartialOrd for Widest {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Widest {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0).then(other.1.cmp(&self.1))
    }
}
