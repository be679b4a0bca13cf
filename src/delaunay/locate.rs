//! Point location and nearest input point, exact, by walking the triangulation.
//!
//! # Which triangle holds a point
//!
//! A *visibility walk*: from a start triangle, cross any edge that has the query point
//! strictly on its far side, until no edge does (the point is in the closed triangle) or
//! the edge to cross is on the convex hull (the point is outside the hull: a hull edge's
//! line bounds the hull). On a Delaunay triangulation this walk never visits a triangle
//! twice, whatever edge it picks (Edelsbrunner's acyclicity theorem: each step lowers the
//! power of the query point with respect to the circumcircles), so it ends within as many
//! steps as there are triangles; a step budget of that size backs the argument with a scan
//! of all triangles, so even a cycle could only cost time. Every side test is the exact
//! orientation of the kernel, so the answer is the one exact arithmetic gives: strictly
//! inside a triangle, on the relative interior of an edge, on a vertex, or outside the hull.
//!
//! The walk starts at a hint: for repeated queries, a triangle from a coarse grid built once
//! (or the previous query's triangle, [`Locator`]); a triangle the caller names
//! ([`Triangulation::locate_from`]); or for a single query the nearest of a sample of about
//! ∛T triangles (jump and walk, [`Triangulation::locate`]).
//!
//! # Which input point is nearest
//!
//! A greedy walk on the Delaunay graph: from a start point (the previous answer, or a corner
//! of a start triangle), move to the neighbour nearest the query while it is strictly
//! nearer than where the walk stands. If `v` is not a nearest point,
//! the segment from `v` to the query leaves `v`'s Voronoi cell through an edge or a vertex
//! of the diagram at some point `x`; the site `w` of a cell on the other side (one at
//! distance `|x − v|` from `x`, so a Delaunay neighbour of `v`: across a Voronoi edge, or
//! around a vertex shared by cocircular sites, a neighbour along their circle) has
//! `|q − w| ≤ |q − x| + |x − w| = |q − v|`, with equality only for `w = v`. So the walk ends
//! at a nearest point. Distances are compared exactly (the kernel's `distance_order`:
//! a filter, then exact integers), never computed.
//!
//! Degenerate triangulations (all points collinear, or fewer than three distinct) have no
//! triangle to walk: location then checks the chain of points along the line and the
//! nearest point is found by an exact scan.

use std::sync::Arc;

use super::triangulation::{Triangulation, NO_TWIN};
use crate::error::{check_coordinate, Error};
use crate::ids::{HalfEdge, LocalPoint, TriangleId};
use crate::kernel::metric::distance_order;
use crate::kernel::{orient, Sign};

/// Where a query point lies in a [`Triangulation`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Location {
    /// Strictly inside triangle `t` (an id for [`Triangulation::triangle`]).
    Triangle(TriangleId),
    /// On the relative interior of the edge of half-edge `e` (see [`Triangulation`] for
    /// half-edge ids; its twin, if any, is the same edge seen from the other triangle).
    Edge(HalfEdge),
    /// On input point `i` (a caller index; the first occurrence for duplicated coordinates).
    Vertex(u32),
    /// Strictly between the consecutive points `[a, b]` (caller indices) of a degenerate
    /// triangulation's chain: all points collinear, so there are no triangles.
    OnChain([u32; 2]),
    /// Outside the closed convex hull of the points.
    Outside,
}

/// The end of a walk, in the triangulation's local terms.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Walked {
    /// In the closed triangle.
    Inside(TriangleId),
    /// Strictly right of this hull half-edge.
    Beyond(HalfEdge),
}

/// Repeated queries on one triangulation. Each walk starts from a coarse grid of start
/// triangles (about one cell per 8 triangles, built once in O(T) when the locator is made)
/// or from where the previous walk ended, whichever is nearer: random queries walk a few
/// triangles each, as queries near each other do. A clone shares the grid, so a locator per
/// thread or per batch of queries costs one grid in all.
///
/// ```
/// use wdm_crust::delaunay::Location;
///
/// let points = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [2.0, 1.0]];
/// let tri = wdm_crust::triangulate(&points)?;
/// let mut locator = tri.locator();
/// match locator.locate([2.0, 3.0])? {
///     Location::Triangle(t) => assert!(tri.triangle(t).contains(&2)),
///     other => panic!("expected a triangle, got {other:?}"),
/// }
/// assert_eq!(locator.locate([2.0, 1.0])?, Location::Vertex(4));
/// assert_eq!(locator.locate([5.0, 1.0])?, Location::Outside);
/// assert_eq!(locator.nearest([3.9, 0.2])?, Some(1));
/// # Ok::<(), wdm_crust::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct Locator<'a> {
    tri: &'a Triangulation,
    /// The triangle the last location walk ended in.
    last: Option<TriangleId>,
    /// A half-edge leaving the last nearest point found.
    last_nearest: Option<HalfEdge>,
    /// Shared by the clones, so that a clone (a locator per thread or per batch of queries)
    /// costs nothing.
    grid: Arc<StartGrid>,
}

impl<'a> Locator<'a> {
    /// A locator for `tri`, with its grid of start triangles.
    pub fn new(tri: &'a Triangulation) -> Self {
        Locator {
            tri,
            last: None,
            last_nearest: None,
            grid: Arc::new(StartGrid::new(tri)),
        }
    }

    /// Where `q` lies; see [`Triangulation::locate`].
    ///
    /// # Errors
    /// A coordinate of `q` that is NaN or infinite: [`Error::NotFinite`] with index 0 (every
    /// finite query is answered exactly, as for input points).
    pub fn locate(&mut self, q: [f64; 2]) -> Result<Location, Error> {
        check_query(q)?;
        if self.tri.is_degenerate() {
            return Ok(self.tri.locate_on_chain(q));
        }
        let walked = self.tri.walk(q, self.start(q));
        self.remember(walked);
        Ok(self.tri.classify(q, walked))
    }

    /// One of the input points nearest to `q` (a caller index; the first occurrence for
    /// duplicated coordinates), or `None` when there are no points. When several are equally
    /// near, which one is returned depends on where the walk came from.
    ///
    /// # Errors
    /// As [`locate`](Self::locate).
    pub fn nearest(&mut self, q: [f64; 2]) -> Result<Option<u32>, Error> {
        check_query(q)?;
        if self.tri.is_degenerate() {
            return Ok(self.tri.nearest_by_scan(q));
        }
        // The greedy walk works from any point: from the nearer (in floating point, only a
        // start) of the last answer and the grid's start.
        let tri = self.tri;
        let grid = self.grid.start(q).map(|t| t.halfedge(0));
        let start = match (grid, self.last_nearest) {
            (Some(g), Some(l)) => tri.nearer_start(q, g, l),
            (Some(e), None) | (None, Some(e)) => e,
            (None, None) => tri.sampled_start(q).halfedge(0),
        };
        let (v, outgoing) = tri.greedy_nearest(q, start);
        self.last_nearest = Some(outgoing);
        Ok(Some(tri.input_index(v)))
    }

    /// A triangle whose closed region holds `q` (an id for [`Triangulation::triangle`]), or
    /// `None` when `q` is outside the closed convex hull or there are no triangles (all
    /// points collinear, or fewer than three distinct). On an edge or an input point, the
    /// triangle is one of those around it, the one the walk ends in. Decided exactly, by the
    /// same walk as [`locate`](Self::locate).
    ///
    /// # Errors
    /// As [`locate`](Self::locate).
    ///
    /// ```
    /// let points = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
    /// let tri = wdm_crust::triangulate(&points)?;
    /// let mut locator = tri.locator();
    /// let t = locator.triangle_containing([1.0, 3.0])?.expect("inside the square");
    /// assert!(tri.triangle(t).contains(&3));
    /// // On the shared diagonal or a corner: a triangle on it.
    /// let t = locator.triangle_containing([4.0, 4.0])?.expect("a corner");
    /// assert!(tri.triangle(t).contains(&2));
    /// assert_eq!(locator.triangle_containing([5.0, 1.0])?, None);
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn triangle_containing(&mut self, q: [f64; 2]) -> Result<Option<TriangleId>, Error> {
        check_query(q)?;
        if self.tri.is_degenerate() {
            return Ok(None);
        }
        let walked = self.tri.walk(q, self.start(q));
        self.remember(walked);
        Ok(match walked {
            Walked::Inside(t) => Some(t),
            Walked::Beyond(_) => None,
        })
    }

    /// The start of a location walk: the grid's triangle or the last one, whichever has its
    /// first corner nearer (in floating point: only a start).
    fn start(&self, q: [f64; 2]) -> TriangleId {
        let tri = self.tri;
        match (self.grid.start(q), self.last) {
            (Some(g), Some(l)) => (tri.nearer_start(q, g.halfedge(0), l.halfedge(0))).triangle(),
            (Some(t), None) | (None, Some(t)) => t,
            (None, None) => tri.sampled_start(q),
        }
    }

    fn remember(&mut self, walked: Walked) {
        self.last = Some(match walked {
            Walked::Inside(t) => t,
            Walked::Beyond(e) => e.triangle(),
        });
    }
}

/// Start triangles on a uniform grid over the points' bounding box: for each cell, a
/// triangle whose centroid lies in it, or else one of the nearest such cell. Only a start
/// for the walk (floating point is fine here: no answer depends on it).
#[derive(Debug, Clone, Default)]
struct StartGrid {
    origin: [f64; 2],
    /// Cells per unit length, in x and y.
    scale: [f64; 2],
    side: usize,
    cells: Vec<TriangleId>,
}

impl StartGrid {
    const EMPTY: TriangleId = TriangleId::new(u32::MAX);

    fn new(tri: &Triangulation) -> StartGrid {
        let count = tri.triangles.len();
        if count < 64 {
            return StartGrid::default();
        }
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in &tri.points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let side = ((count / 8) as f64).sqrt().ceil() as usize;
        let scale = [0, 1].map(|k| {
            let span = hi[k] - lo[k];
            if span > 0.0 && (side as f64 / span).is_finite() {
                side as f64 / span
            } else {
                0.0
            }
        });
        let mut grid = StartGrid {
            origin: lo,
            scale,
            side,
            cells: vec![Self::EMPTY; side * side],
        };
        // Each triangle in the cell of its centroid (so large triangles over empty space
        // land there too), then every empty cell takes a triangle of the nearest filled cell
        // (a breadth-first fill over the grid), so that no query starts far away.
        let mut queue = std::collections::VecDeque::new();
        for t in tri.triangle_ids() {
            let [a, b, c] = tri.triangle_points(t);
            let centroid = [0, 1].map(|k| a[k] / 3.0 + b[k] / 3.0 + c[k] / 3.0);
            if let Some(cell) = grid.cell(centroid) {
                if grid.cells[cell] == Self::EMPTY {
                    queue.push_back(cell);
                }
                grid.cells[cell] = t;
            }
        }
        while let Some(cell) = queue.pop_front() {
            let (x, y) = (cell % side, cell / side);
            let neighbours = [
                (x > 0).then(|| cell - 1),
                (x + 1 < side).then(|| cell + 1),
                (y > 0).then(|| cell - side),
                (y + 1 < side).then(|| cell + side),
            ];
            for next in neighbours.into_iter().flatten() {
                if grid.cells[next] == Self::EMPTY {
                    grid.cells[next] = grid.cells[cell];
                    queue.push_back(next);
                }
            }
        }
        grid
    }

    fn cell(&self, q: [f64; 2]) -> Option<usize> {
        if self.side == 0 {
            return None;
        }
        let index = |k: usize| {
            let x = (q[k] - self.origin[k]) * self.scale[k];
            // Outside the box (or NaN-free overflow): clamp to the border cells.
            (x.max(0.0) as usize).min(self.side - 1)
        };
        Some(index(1) * self.side + index(0))
    }

    fn start(&self, q: [f64; 2]) -> Option<TriangleId> {
        let t = *self.cells.get(self.cell(q)?)?;
        (t != Self::EMPTY).then_some(t)
    }
}

fn check_query(q: [f64; 2]) -> Result<(), Error> {
    check_coordinate(0, q[0])?;
    check_coordinate(0, q[1])
}

impl Triangulation {
    /// Where `q` lies: strictly inside a triangle, on an edge, on an input point, or outside
    /// the convex hull, decided exactly (see [`locate`](crate::delaunay::locate) for the
    /// walk and why it is exact). The walk starts at the nearest of a small sample of
    /// triangles; for many queries, a [`Locator`] starts each walk where the last one ended.
    ///
    /// # Errors
    /// A coordinate of `q` that is NaN or infinite: see
    /// [`Locator::locate`].
    ///
    /// ```
    /// use wdm_crust::delaunay::Location;
    ///
    /// let tri = wdm_crust::triangulate(&[[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])?;
    /// assert_eq!(tri.locate([0.5, 0.5])?, Location::Triangle(wdm_crust::TriangleId::new(0)));
    /// let Location::Edge(e) = tri.locate([1.0, 1.0])? else { panic!("on an edge") };
    /// let mut ends = [tri.halfedge_origin(e), tri.halfedge_destination(e)];
    /// ends.sort();
    /// assert_eq!(ends, [1, 2]);
    /// assert_eq!(tri.locate([2.0, 0.0])?, Location::Vertex(1));
    /// assert_eq!(tri.locate([1.0, 1.5])?, Location::Outside);
    /// assert!(tri.locate([f64::NAN, 0.0]).is_err());
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn locate(&self, q: [f64; 2]) -> Result<Location, Error> {
        self.locate_from(q, None)
    }

    /// [`locate`](Self::locate) with the walk starting at triangle `hint` (`None` or an id
    /// out of range: a start of its own).
    ///
    /// # Errors
    /// As [`locate`](Self::locate).
    pub fn locate_from(&self, q: [f64; 2], hint: Option<TriangleId>) -> Result<Location, Error> {
        check_query(q)?;
        if self.is_degenerate() {
            return Ok(self.locate_on_chain(q));
        }
        let start = match hint {
            Some(t) if t.index() < self.triangles.len() => t,
            _ => self.sampled_start(q),
        };
        Ok(self.classify(q, self.walk(q, start)))
    }

    /// One of the input points nearest to `q`, exactly (see [`Locator::nearest`]); `None`
    /// when there are no points.
    ///
    /// # Errors
    /// As [`locate`](Self::locate).
    ///
    /// ```
    /// let points = [[0.0, 0.0], [10.0, 0.0], [5.0, 8.0], [5.0, 3.0]];
    /// let tri = wdm_crust::triangulate(&points)?;
    /// assert_eq!(tri.nearest_point([5.0, 4.0])?, Some(3));
    /// assert_eq!(tri.nearest_point([-7.0, -1.0])?, Some(0));
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn nearest_point(&self, q: [f64; 2]) -> Result<Option<u32>, Error> {
        check_query(q)?;
        if self.is_degenerate() {
            return Ok(self.nearest_by_scan(q));
        }
        let (v, _) = self.greedy_nearest(q, self.sampled_start(q).halfedge(0));
        Ok(Some(self.input_index(v)))
    }

    /// Of the half-edges `a` and `b`, the one whose origin is nearer `q` in floating point.
    fn nearer_start(&self, q: [f64; 2], a: HalfEdge, b: HalfEdge) -> HalfEdge {
        let distance = |e: HalfEdge| {
            let p = self.position(self.org(e));
            (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)
        };
        if distance(b) < distance(a) {
            b
        } else {
            a
        }
    }

    /// A [`Locator`] for repeated queries (its setup is one pass over the triangles).
    pub fn locator(&self) -> Locator<'_> {
        Locator::new(self)
    }

    /// The nearest (by the first corner, in floating point: only a start, not a decision)
    /// of about ∛T triangles spread over the ids, which follow the points' Z order.
    fn sampled_start(&self, q: [f64; 2]) -> TriangleId {
        let count = self.triangles.len();
        let samples = ((count as f64).cbrt() as usize).max(1);
        let stride = (count / samples).max(1);
        let distance = |t: TriangleId| {
            let p = self.position(self.corners(t)[0]);
            (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)
        };
        (self.triangle_ids())
            .step_by(stride)
            .min_by(|&a, &b| distance(a).total_cmp(&distance(b)))
            .unwrap_or(TriangleId::new(0))
    }

    /// The visibility walk from triangle `start` (a valid id; the triangulation has
    /// triangles).
    fn walk(&self, q: [f64; 2], start: TriangleId) -> Walked {
        let mut t = start;
        // The half-edge the walk entered `t` by: `q` is strictly left of it.
        let mut entered = NO_TWIN;
        for _ in 0..=self.triangles.len() {
            match self.exit(q, t, entered) {
                None => return Walked::Inside(t),
                Some(e) => {
                    let Some(twin) = self.twin(e) else {
                        return Walked::Beyond(e);
                    };
                    entered = twin;
                    t = entered.triangle();
                }
            }
        }
        self.scan(q)
    }

    /// A half-edge of triangle `t` other than `entered` with `q` strictly on its right.
    #[inline]
    fn exit(&self, q: [f64; 2], t: TriangleId, entered: HalfEdge) -> Option<HalfEdge> {
        let [a, b, c] = self.triangle_points(t);
        let [ab, bc, ca] = t.halfedges();
        let edges = [(ab, a, b), (bc, b, c), (ca, c, a)];
        edges
            .into_iter()
            .find(|&(e, from, to)| e != entered && orient(from, to, q) == Sign::Negative)
            .map(|(e, _, _)| e)
    }

    /// Every triangle tested: the walk's fallback, never needed on a Delaunay triangulation.
    #[cold]
    fn scan(&self, q: [f64; 2]) -> Walked {
        for t in self.triangle_ids() {
            if self.exit(q, t, NO_TWIN).is_none() {
                return Walked::Inside(t);
            }
        }
        let hull_edge = self.halfedge_ids().find(|&e| {
            self.halfedges[e.index()] == NO_TWIN
                && orient(self.position(self.org(e)), self.position(self.dest(e)), q)
                    == Sign::Negative
        });
        // A point in no closed triangle is strictly right of some hull edge.
        Walked::Beyond(hull_edge.unwrap_or(HalfEdge::new(0)))
    }

    /// The public answer for the end of a walk.
    fn classify(&self, q: [f64; 2], walked: Walked) -> Location {
        let t = match walked {
            Walked::Beyond(_) => return Location::Outside,
            Walked::Inside(t) => t,
        };
        let corners = self.corners(t);
        let p = corners.map(|c| self.position(c));
        // Side of edge k (from corner k to corner k + 1); none is negative.
        let on_line = [0, 1, 2].map(|k| orient(p[k], p[(k + 1) % 3], q) == Sign::Zero);
        match on_line {
            [false, false, false] => Location::Triangle(t),
            // On two edges: their shared corner (edge k − 1 ends where edge k starts).
            [true, true, _] => Location::Vertex(self.input_index(corners[1])),
            [_, true, true] => Location::Vertex(self.input_index(corners[2])),
            [true, _, true] => Location::Vertex(self.input_index(corners[0])),
            [true, false, false] => Location::Edge(t.halfedge(0)),
            [false, true, false] => Location::Edge(t.halfedge(1)),
            [false, false, true] => Location::Edge(t.halfedge(2)),
        }
    }

    /// Location in a degenerate triangulation: on a point, strictly between consecutive
    /// points of the chain along the line, or outside.
    fn locate_on_chain(&self, q: [f64; 2]) -> Location {
        if let Some(p) = self.points.iter().position(|&p| p == q) {
            return Location::Vertex(self.input_index(LocalPoint::new(p as u32)));
        }
        for pair in self.hull.windows(2) {
            let (a, b) = (self.position(pair[0]), self.position(pair[1]));
            let within = |k: usize| a[k].min(b[k]) <= q[k] && q[k] <= a[k].max(b[k]);
            if within(0) && within(1) && orient(a, b, q) == Sign::Zero {
                return Location::OnChain([self.input_index(pair[0]), self.input_index(pair[1])]);
            }
        }
        Location::Outside
    }

    /// The nearest distinct point by exact comparison with every one (a caller index).
    fn nearest_by_scan(&self, q: [f64; 2]) -> Option<u32> {
        (self.local_points())
            .reduce(|best, p| {
                if distance_order(q, self.position(p), self.position(best)) == Sign::Negative {
                    p
                } else {
                    best
                }
            })
            .map(|p| self.input_index(p))
    }

    /// The greedy walk on the Delaunay graph from the origin of half-edge `outgoing`: the
    /// local index of the point reached, with a half-edge leaving it.
    fn greedy_nearest(&self, q: [f64; 2], mut outgoing: HalfEdge) -> (LocalPoint, HalfEdge) {
        loop {
            let v = self.org(outgoing);
            let mut best = (v, outgoing);
            self.for_each_neighbour(outgoing, |w, from_w| {
                if distance_order(q, self.position(w), self.position(best.0)) == Sign::Negative {
                    best = (w, from_w);
                }
            });
            if best.0 == v {
                return best;
            }
            outgoing = best.1;
        }
    }

    /// Calls `visit(w, e)` once for each neighbour `w` of the origin `v` of `outgoing`, with
    /// a half-edge `e` leaving `w`.
    fn for_each_neighbour(&self, outgoing: HalfEdge, mut visit: impl FnMut(LocalPoint, HalfEdge)) {
        // Every half-edge e leaving v names the neighbour dest(e), left by next(e).
        let mut e = outgoing;
        loop {
            visit(self.dest(e), e.next());
            // Counterclockwise around v: twin(prev(e)) leaves v again.
            let p = e.prev();
            let Some(twin) = self.twin(p) else {
                // v is on the hull: prev(e) comes from the last neighbour, which no half-edge
                // leaving v reaches.
                visit(self.org(p), p);
                break;
            };
            e = twin;
            if e == outgoing {
                return;
            }
        }
        // The rest of the fan, clockwise from `outgoing`.
        let mut e = outgoing;
        while let Some(twin) = self.twin(e) {
            e = twin.next();
            visit(self.dest(e), e.next());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::triangulate;

    #[test]
    fn every_answer_on_a_small_square() {
        // Two triangles sharing the diagonal; the centre lies on it.
        let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let tri = triangulate(&pts).unwrap();
        let centre = tri.locate([1.0, 1.0]).unwrap();
        let Location::Edge(e) = centre else {
            panic!("{centre:?}")
        };
        let ends = [tri.halfedge_origin(e), tri.halfedge_destination(e)];
        assert!(ends == [0, 2] || ends == [2, 0] || ends == [1, 3] || ends == [3, 1]);
        for (i, &p) in pts.iter().enumerate() {
            assert_eq!(tri.locate(p).unwrap(), Location::Vertex(i as u32));
            for hint in 0..3 {
                assert_eq!(
                    tri.locate_from(p, Some(TriangleId::new(hint))).unwrap(),
                    Location::Vertex(i as u32)
                );
            }
        }
        assert!(matches!(
            tri.locate([0.5, 0.1]).unwrap(),
            Location::Triangle(_)
        ));
        assert_eq!(tri.locate([1.0, 0.0]).unwrap(), {
            let e = (tri.halfedge_ids())
                .find(|&e| {
                    let mut ends = [tri.halfedge_origin(e), tri.halfedge_destination(e)];
                    ends.sort();
                    ends == [0, 1]
                })
                .unwrap();
            Location::Edge(e)
        });
        assert_eq!(tri.locate([3.0, 1.0]).unwrap(), Location::Outside);
        assert_eq!(tri.locate([2.0, 3.0]).unwrap(), Location::Outside); // on the hull's line
    }

    #[test]
    fn degenerate_triangulations() {
        let line = [[0.0, 0.0], [2.0, 2.0], [1.0, 1.0], [1.0, 1.0]];
        let tri = triangulate(&line).unwrap();
        assert_eq!(tri.locate([1.0, 1.0]).unwrap(), Location::Vertex(2));
        let on = tri.locate([0.5, 0.5]).unwrap();
        assert!(
            on == Location::OnChain([0, 2]) || on == Location::OnChain([2, 0]),
            "{on:?}"
        );
        assert_eq!(tri.locate([3.0, 3.0]).unwrap(), Location::Outside);
        assert_eq!(tri.locate([0.5, 0.6]).unwrap(), Location::Outside);
        assert_eq!(tri.nearest_point([1.9, 1.0]).unwrap(), Some(2));
        let empty = triangulate(&[]).unwrap();
        assert_eq!(empty.locate([0.0, 0.0]).unwrap(), Location::Outside);
        assert_eq!(empty.nearest_point([0.0, 0.0]).unwrap(), None);
        let one = triangulate(&[[1.0, 1.0], [1.0, 1.0]]).unwrap();
        assert_eq!(one.nearest_point([5.0, 0.0]).unwrap(), Some(0));
        assert_eq!(one.locate([1.0, 1.0]).unwrap(), Location::Vertex(0));
    }

    #[test]
    fn bad_queries_are_errors() {
        let tri = triangulate(&[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]).unwrap();
        for q in [[f64::NAN, 0.0], [0.0, f64::INFINITY]] {
            assert!(tri.locate(q).is_err(), "{q:?}");
            assert!(tri.nearest_point(q).is_err(), "{q:?}");
        }
        // Every finite query is answered exactly, whatever its magnitude.
        assert_eq!(tri.locate([1e300, 0.0]).unwrap(), Location::Outside);
        assert_eq!(tri.nearest_point([1e300, 0.0]).unwrap(), Some(1));
        assert!(matches!(
            tri.locate([1e-300, 0.0]).unwrap(),
            Location::Edge(_)
        ));
        assert_eq!(tri.nearest_point([1e-300, 1e-300]).unwrap(), Some(0));
        // An out-of-range hint is ignored.
        assert!(tri
            .locate_from([0.1, 0.1], Some(TriangleId::new(99)))
            .is_ok());
    }
}
