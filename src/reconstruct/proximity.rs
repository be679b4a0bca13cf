//! Proximity on the Delaunay graph: each point's nearest neighbour and its *half
//! neighbour*, the nearest point on the far side of the line through it orthogonal to its
//! nearest neighbour (Dey and Kumar's NN-crust). The NN-crust baseline takes both edges
//! of every point; the open-curve stage takes them as proposals (see `open_curves`).
//!
//! Candidates are the neighbours of a point in the Delaunay graph: the edges with a dual
//! Voronoi edge (hull edges, and interior edges whose two triangles are not cocircular).
//! The nearest neighbour is always among them (its diametral disk holds no other point);
//! leaving out the diagonals of cocircular groups makes every answer independent of how
//! the triangulation split them.
//!
//! # Exactness and determinism
//!
//! Both tests are degree-2 polynomials in the input coordinates, decided exactly by the
//! kernel: `|p − a|² − |p − b|²` compares two distances, `(s − p)·(q − p)` is the
//! half-plane test. Equal distances are broken by the candidates' coordinates (smaller `x`,
//! then smaller `y`), never by index, so nothing depends on the order of the input.

use std::cmp::Ordering;

use crate::delaunay::{Triangulation, NO_TWIN};
use crate::ids::LocalPoint;
use crate::kernel::metric::{distance_order, dot_sign};
use crate::kernel::Sign;
use crate::predicates::{incircle, CirclePosition};
use crate::voronoi::Voronoi;

/// Adjacency lists of the Delaunay graph in compressed rows.
pub(super) struct DelaunayGraph {
    /// Where each point's row starts in `targets`; with `row_of`, where the `p`-th listed
    /// point's row starts.
    start: Vec<usize>,
    targets: Vec<LocalPoint>,
    /// For a graph of some points' rows only (`of_points`), each point's row, `u32::MAX`
    /// when not listed; empty when every point has its row.
    row_of: Vec<u32>,
}

/// A point's nearest neighbour and half neighbour among the admitted candidates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(super) struct Proposal {
    /// The nearest neighbour, if any candidate was admitted.
    pub nearest: Option<LocalPoint>,
    /// The nearest candidate strictly more than 90° away from the nearest neighbour.
    pub half: Option<LocalPoint>,
}

impl Proposal {
    /// The proposed neighbours: the nearest, then the half neighbour.
    pub fn iter(self) -> impl Iterator<Item = LocalPoint> {
        self.nearest.into_iter().chain(self.half)
    }

    /// Whether `q` is one of the proposed neighbours.
    pub fn contains(self, q: LocalPoint) -> bool {
        self.nearest == Some(q) || self.half == Some(q)
    }
}

impl DelaunayGraph {
    /// The neighbours of every point of `tri` along edges with a dual Voronoi edge.
    pub fn of(tri: &Triangulation) -> DelaunayGraph {
        Self::of_rows(tri, |_| true)
    }

    /// [`of`](Self::of).
    fn of_rows(tri: &Triangulation, row: impl Fn(LocalPoint) -> bool) -> DelaunayGraph {
        let points = &tri.points;
        let halfedges = tri.halfedges();
        let mut pairs: Vec<(LocalPoint, LocalPoint)> = Vec::new();
        for (e, &twin) in tri.halfedge_ids().zip(halfedges) {
            let (a, b) = (tri.org(e), tri.dest(e));
            let mut push = |p: LocalPoint, q: LocalPoint| {
                if row(p) {
                    pairs.push((p, q));
                }
            };
            if twin == NO_TWIN {
                push(a, b);
                push(b, a);
                continue;
            }
            // Each interior edge from the half-edge with the smaller index; kept unless the
            // triangles on its two sides share their circumcircle.
            if twin < e {
                continue;
            }
            let c = tri.org(e.prev());
            let d = tri.org(twin.prev());
            let at = |i: LocalPoint| points[i.index()];
            if (row(a) || row(b)) && incircle(at(a), at(b), at(c), at(d)) != CirclePosition::On {
                push(a, b);
                push(b, a);
            }
            debug_assert_eq!(tri.org(e.next()), b);
        }
        pairs.sort_unstable();
        let mut start = vec![0usize; points.len() + 1];
        for &(a, _) in &pairs {
            start[a.index() + 1] += 1;
        }
        for i in 0..points.len() {
            start[i + 1] += start[i];
        }
        DelaunayGraph {
            start,
            targets: pairs.into_iter().map(|(_, b)| b).collect(),
            row_of: Vec::new(),
        }
    }

    /// The rows of the points `listed` alone, read off the dual around each of them: work in
    /// the number of listed points and their degrees, not in the size of the triangulation.
    pub fn of_points(vor: &Voronoi<'_>, listed: &[LocalPoint]) -> DelaunayGraph {
        let n = vor.triangulation().points.len();
        let mut row_of = vec![u32::MAX; n];
        let mut start = Vec::with_capacity(listed.len() + 1);
        let mut targets = Vec::new();
        for (r, &p) in listed.iter().enumerate() {
            row_of[p.index()] = r as u32;
            start.push(targets.len());
            targets.extend(vor.dual_neighbours(p));
        }
        start.push(targets.len());
        DelaunayGraph {
            start,
            targets,
            row_of,
        }
    }

    /// The Delaunay neighbours of `p` (none when its row was not built).
    pub fn neighbours(&self, p: LocalPoint) -> &[LocalPoint] {
        let r = if self.row_of.is_empty() {
            p.index()
        } else {
            match self.row_of[p.index()] {
                u32::MAX => return &[],
                r => r as usize,
            }
        };
        &self.targets[self.start[r]..self.start[r + 1]]
    }

    /// The nearest and the half neighbour of `p` among its Delaunay neighbours `s` with
    /// `admit(s)`.
    pub fn proposal(
        &self,
        points: &[[f64; 2]],
        p: LocalPoint,
        admit: impl Fn(LocalPoint) -> bool,
    ) -> Proposal {
        let around = self.neighbours(p);
        let pp = points[p.index()];
        let nearest = |candidates: &mut dyn Iterator<Item = LocalPoint>| {
            candidates.min_by(|&a, &b| closer(pp, points[a.index()], points[b.index()]))
        };
        let Some(q) = nearest(&mut around.iter().copied().filter(|&s| admit(s))) else {
            return Proposal::default();
        };
        let pq = points[q.index()];
        let half = nearest(
            &mut around
                .iter()
                .copied()
                .filter(|&s| admit(s) && dot_sign(pp, points[s.index()], pq) == Sign::Negative),
        );
        Proposal {
            nearest: Some(q),
            half,
        }
    }
}

/// Orders `a` before `b` if it is strictly closer to `p`, or equally close and smaller in
/// `(x, y)`; exact.
pub(super) fn closer(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> Ordering {
    Ordering::from(distance_order(p, a, b)).then_with(|| {
        a[0].partial_cmp(&b[0])
            .unwrap_or(Ordering::Equal)
            .then(a[1].partial_cmp(&b[1]).unwrap_or(Ordering::Equal))
    })
}
