//! What the repairs share: the curves' edges, degrees and median edge, the curve edges near a set of
//! points and the distance test of a loop to the curves found before (peeling and the
//! islets), and the curves as edited by swaps with the repair that results (the detours and
//! the spikes). Kept here so that no repair borrows from another.

use std::collections::{BTreeMap, BTreeSet};

use crate::ids::LocalPoint;
use crate::reconstruct::bits::Bits;
use crate::reconstruct::curves::{Adjacency, LocalCurve, SomeAdjacency};
use crate::reconstruct::lengths::distance;
use crate::reconstruct::thresholds::peel::APART;
use crate::voronoi::Voronoi;

/// The edges `[min, max]` of a curve (a closed one includes its closing edge).
pub(crate) fn curve_edges(curve: &LocalCurve) -> Vec<[LocalPoint; 2]> {
    let p = &curve.points;
    let closing = curve.closed.then(|| [p[p.len() - 1], p[0]]);
    p.windows(2)
        .map(|w| [w[0], w[1]])
        .chain(closing)
        .map(|[a, b]| [a.min(b), a.max(b)])
        .collect()
}

/// The crust degree of every point (saturating at 255). Degrees are even: the labels change an
/// even number of times around a cell.
pub(crate) fn degrees(point_count: usize, edges: &[[LocalPoint; 2]]) -> Vec<u8> {
    let mut degree = vec![0u8; point_count];
    for &[a, b] in edges {
        degree[a.index()] = degree[a.index()].saturating_add(1);
        degree[b.index()] = degree[b.index()].saturating_add(1);
    }
    degree
}

/// The `edges` at the Delaunay neighbours of `points`: what peeling's `near_a_curve` and
/// [`lies_apart`] read of the curves around those points, without an adjacency of every
/// edge (a pass over all points).
pub(crate) fn edges_near(
    full: &Voronoi<'_>,
    points: &[LocalPoint],
    edges: &[[LocalPoint; 2]],
) -> SomeAdjacency {
    let mut asked = Bits::new(full.triangulation().points.len());
    for &p in points {
        for q in full.delaunay_neighbours(p) {
            asked.set(q.index());
        }
    }
    let near: Vec<[LocalPoint; 2]> = edges
        .iter()
        .copied()
        .filter(|&[a, b]| asked.get(a.index()) || asked.get(b.index()))
        .collect();
    SomeAdjacency::new(&near)
}

/// Does the loop `curve` keep at least [`APART`] of its own sample spacings (`spacing`,
/// its median edge) from the curves found before (`earlier`)? Measured from each of its
/// points to the earlier curves' edges at the point's Delaunay neighbours (where the
/// nearest curve is when no other point lies between).
///
/// Only the earlier curves' edges at the neighbours `q` with `counts(q)` are looked at (the
/// islets of `ears.rs` leave out their own points).
pub(crate) fn lies_apart<'a>(
    full: &Voronoi<'_>,
    earlier: impl Fn(LocalPoint) -> &'a [(u32, LocalPoint)],
    curve: &[LocalPoint],
    spacing: f64,
    counts: impl Fn(LocalPoint) -> bool,
) -> bool {
    let points = &full.triangulation().points;
    let at = |i: LocalPoint| points[i.index()];
    curve.iter().all(|&p| {
        full.delaunay_neighbours(p).filter(|&q| counts(q)).all(|q| {
            earlier(q)
                .iter()
                .all(|&(_, r)| segment_distance(at(p), at(q), at(r)) >= APART * spacing)
        })
    })
}

/// The median length of `edges` (0 for none). A rounded length: it only sets the scale of a
/// rule's threshold, never an exact decision.
pub(crate) fn median_length(points: &[[f64; 2]], edges: &[[LocalPoint; 2]]) -> f64 {
    let mut lengths: Vec<f64> = edges
        .iter()
        .map(|&[a, b]| distance(points[a.index()], points[b.index()]))
        .collect();
    if lengths.is_empty() {
        return 0.0;
    }
    let mid = lengths.len() / 2;
    *lengths.select_nth_unstable_by(mid, f64::total_cmp).1
}

/// Distance from `p` to the segment `ab`.
pub(crate) fn segment_distance(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    distance(p, [a[0] + t * dx, a[1] + t * dy])
}

/// What the repair changes: edges to add and edges to remove, each sorted.
pub(crate) struct Repair {
    /// The reattached stretches.
    pub(crate) added: Vec<[LocalPoint; 2]>,
    /// The detours.
    pub(crate) removed: Vec<[LocalPoint; 2]>,
}

impl Repair {
    pub(crate) fn none() -> Repair {
        Repair {
            added: Vec::new(),
            removed: Vec::new(),
        }
    }

    /// Applies the repair to the edges it was computed on.
    pub(crate) fn apply(&self, edges: &mut Vec<[LocalPoint; 2]>) {
        if let Some(largest) = self.removed.iter().map(|e| e[0]).max() {
            // A bit test on the smaller end first: a search of `removed` for every edge was
            // most of the time.
            let mut ends = Bits::new(largest.index() + 1);
            for &[a, _] in &self.removed {
                ends.set(a.index());
            }
            let may_be_removed = |a: LocalPoint| a <= largest && ends.get(a.index());
            edges.retain(|e| !may_be_removed(e[0]) || self.removed.binary_search(e).is_err());
        }
        edges.extend_from_slice(&self.added);
    }
}

/// A swap: the stretch's edges replace the detour's.
pub(crate) struct Swap {
    pub(crate) stretch: Vec<[LocalPoint; 2]>,
    pub(crate) detour: Vec<[LocalPoint; 2]>,
}

/// The curve edges with the swaps made so far: the original edges, and the current
/// neighbours of every point a swap touched (a flag per point says which, so that walking
/// untouched curves costs no lookup).
pub(crate) struct EditedCurves {
    original: Adjacency,
    touched: Vec<bool>,
    current: BTreeMap<LocalPoint, Vec<LocalPoint>>,
    removed: BTreeSet<[LocalPoint; 2]>,
    added: BTreeSet<[LocalPoint; 2]>,
}

impl EditedCurves {
    pub(crate) fn new(n: usize, edges: &[[LocalPoint; 2]]) -> Self {
        EditedCurves {
            original: Adjacency::new(n, edges),
            touched: vec![false; n],
            current: BTreeMap::new(),
            removed: BTreeSet::new(),
            added: BTreeSet::new(),
        }
    }

    /// The current curve neighbours of `p`, when there are exactly two.
    pub(crate) fn two_neighbours(&self, p: LocalPoint) -> Option<[LocalPoint; 2]> {
        if self.touched[p.index()] {
            match self.current[&p].as_slice() {
                &[x, y] => Some([x, y]),
                _ => None,
            }
        } else {
            match self.original.neighbours(p) {
                &[(_, x), (_, y)] => Some([x, y]),
                _ => None,
            }
        }
    }

    /// Which points have a curve edge now, given which had one in the original edges.
    pub(crate) fn on_curve(&self, original: &[bool]) -> Vec<bool> {
        let mut on_curve = original.to_vec();
        for (&p, neighbours) in &self.current {
            on_curve[p.index()] = !neighbours.is_empty();
        }
        on_curve
    }

    /// The current neighbours of `p`, to edit.
    pub(crate) fn neighbours_mut(&mut self, p: LocalPoint) -> &mut Vec<LocalPoint> {
        let original = &self.original;
        self.touched[p.index()] = true;
        self.current
            .entry(p)
            .or_insert_with(|| original.neighbours(p).iter().map(|&(_, q)| q).collect())
    }

    pub(crate) fn swap(&mut self, swap: &Swap) {
        for &[a, b] in &swap.detour {
            if !self.added.remove(&[a, b]) {
                self.removed.insert([a, b]);
            }
            self.neighbours_mut(a).retain(|&q| q != b);
            self.neighbours_mut(b).retain(|&q| q != a);
        }
        for &[a, b] in &swap.stretch {
            self.added.insert([a, b]);
            self.neighbours_mut(a).push(b);
            self.neighbours_mut(b).push(a);
        }
    }

    pub(crate) fn into_repair(self) -> Repair {
        Repair {
            added: self.added.into_iter().collect(),
            removed: self.removed.into_iter().collect(),
        }
    }
}
