//! Voronoi cells clipped to a box, as polygons in coordinates.
//!
//! The clipped cell of a site `p` is the box cut by the half-planes `H_q = {x : |x − p| ≤ |x − q|}`
//! of its Voronoi neighbours `q` (the sites across the edges of its cell; for collinear input
//! the previous and next point on the line). Each cut is a Sutherland–Hodgman step on a
//! polygon whose vertices are kept **symbolically**: a box corner, the crossing of a
//! neighbour's bisector with a box side, or the crossing of two neighbours' bisectors (a
//! circumcenter). Which side of a bisector each of them lies on is decided exactly:
//!
//! * a corner `c`: the sign of `|c − q|² − |c − p|²` (`metric::distance_order`);
//! * a circumcenter `O(p, q1, q2)`: the in-circle test of `q` against `p, q1, q2`;
//! * the crossing `P` of the bisector of `p, q1` with the side `x[a] = v`: along that
//!   bisector the distance difference to `q` changes sign at `O(p, q1, q)`, so its sign is
//!   `sign(O[a] − v) · sign(d1[a]) · orient(p, q1, q)` with `d1` the bisector's direction
//!   `(q1 − p)` turned counterclockwise (`kernel::circumcenter_side`, exact); when `p, q1, q`
//!   are collinear the bisectors are parallel and it is the sign of `(p − q)·(q1 − q)`.
//!
//! So the combinatorial result is the exact intersection; vertices in the middle of an edge
//! (on the same line as both neighbours) are dropped. Coordinates are constructed only for
//! the final vertices, each correctly rounded from the exact point
//! (`kernel::circumcenter_nearest`, `kernel::bisector_crossing`; corners are exact), so a
//! vertex shared by several cells gets the same coordinates in each and the cells tile the
//! box: every vertex on a box side keeps that side's coordinate exactly, and the rounding
//! moves interior vertices by at most half an ulp per coordinate.
//!
//! Most cells take a shortcut: a bounded cell whose Voronoi vertices all lie strictly inside
//! the box (four exact tests per vertex) is its own clipped cell, read off the dual in `O(k)`
//! for `k` edges. The others (hull cells, cells reaching the box boundary) cost `O(k²)` exact
//! side tests, since each cut scans the polygon: `k` is 6 on average, but a hull site with
//! thousands of Voronoi neighbours would make its own cell quadratic.
//!
//! [`Voronoi::clipped_cells`] then merges vertices that rounding left within 16 ulps of each
//! other, consistently in all cells (`merge`).

use super::bounding_box::BoundingBox;
use super::merge::merge_close_vertices;
use super::Voronoi;
use crate::delaunay::NO_TWIN;
use crate::ids::{LocalPoint, VertexId};
use crate::kernel::metric::{distance_order, dot_sign};
use crate::kernel::{
    bisector_crossing, circumcenter_nearest, circumcenter_side, circumcenter_strictly_inside,
    incircle, orient, Sign,
};

/// What is known of the Voronoi vertices, by vertex id (empty vectors: nothing is kept, for
/// a single cell). Each vertex is a corner of three or more cells.
#[derive(Default)]
struct KnownVertices {
    /// The rounded position (NaN until computed): a certified or exact rounding.
    position: Vec<[f64; 2]>,
    /// Whether it lies strictly inside the box, once decided.
    inside: Vec<Option<bool>>,
}

impl KnownVertices {
    fn for_all(count: usize) -> KnownVertices {
        KnownVertices {
            position: vec![[f64::NAN; 2]; count],
            inside: vec![None; count],
        }
    }

    /// The rounded position of `v`, from `compute` on first use.
    fn position(&mut self, v: VertexId, compute: impl FnOnce() -> [f64; 2]) -> [f64; 2] {
        match self.position.get_mut(v.index()) {
            Some(slot) if !slot[0].is_nan() => *slot,
            Some(slot) => {
                *slot = compute();
                *slot
            }
            None => compute(),
        }
    }

    /// Whether `v` lies strictly inside the box, from `decide` on first use.
    fn inside(&mut self, v: VertexId, decide: impl FnOnce() -> bool) -> bool {
        match self.inside.get_mut(v.index()) {
            Some(Some(known)) => *known,
            Some(slot) => *slot.insert(decide()),
            None => decide(),
        }
    }
}

/// No Voronoi vertex: after the last neighbour of a hull point in
/// [`Voronoi::cell_neighbours`] (out of range of every [`KnownVertices`]).
const NO_VERTEX: VertexId = VertexId::new(u32::MAX);

/// A line carrying an edge of the polygon being clipped.
#[derive(Debug, Clone, Copy)]
enum Line {
    /// The box side `x[axis] = value`.
    Side { axis: usize, value: f64 },
    /// The perpendicular bisector of the site and neighbour `q` (local index).
    Bisector(LocalPoint),
}

/// A polygon vertex, kept symbolically so that every decision on it is exact.
#[derive(Debug, Clone, Copy)]
enum Vertex {
    /// A box corner (exact).
    Corner([f64; 2]),
    /// The point of the bisector of the site and `q` on the box side `x[axis] = value`.
    Crossing {
        axis: usize,
        value: f64,
        q: LocalPoint,
    },
    /// The circumcenter of the site, `q1` and `q2`: where their bisectors cross.
    Circumcenter { q1: LocalPoint, q2: LocalPoint },
}

/// A polygon vertex and the line of the edge from it to the next vertex.
#[derive(Debug, Clone, Copy)]
struct Node {
    vertex: Vertex,
    next: Line,
}

/// Buffers of [`Clipper::cut`]: the sides of the polygon's vertices, and the cut polygon with
/// a flag per vertex telling whether it lies on the cut line.
#[derive(Default)]
struct Scratch {
    signs: Vec<Sign>,
    nodes: Vec<(Node, bool)>,
}

/// One site's clipping: its coordinates and the coordinates of all distinct points.
struct Clipper<'p> {
    points: &'p [[f64; 2]],
    p: [f64; 2],
}

impl Clipper<'_> {
    fn point(&self, q: LocalPoint) -> [f64; 2] {
        self.points[q.index()]
    }

    /// `Positive` iff `v` is strictly closer to the site than to `q`, `Zero` iff equally
    /// close: exactly.
    fn side(&self, v: &Vertex, q: LocalPoint) -> Sign {
        let (p, qq) = (self.p, self.point(q));
        match *v {
            Vertex::Corner(c) => distance_order(c, qq, p),
            Vertex::Crossing { q: q1, .. } | Vertex::Circumcenter { q1, q2: _ } if q1 == q => {
                Sign::Zero
            }
            Vertex::Circumcenter { q2, .. } if q2 == q => Sign::Zero,
            Vertex::Crossing { axis, value, q: q1 } => {
                let q1p = self.point(q1);
                match orient(p, q1p, qq) {
                    Sign::Zero => dot_sign(qq, p, q1p),
                    turn => {
                        let direction = if axis == 0 {
                            p[1] - q1p[1]
                        } else {
                            q1p[0] - p[0]
                        };
                        circumcenter_side([p, q1p, qq], axis, value)
                            .times(Sign::of_f64(direction))
                            .times(turn)
                    }
                }
            }
            Vertex::Circumcenter { q1, q2 } => {
                let (a, b) = (self.point(q1), self.point(q2));
                let inside = incircle(p, a, b, qq).times(orient(p, a, b));
                match inside {
                    Sign::Positive => Sign::Negative,
                    Sign::Negative => Sign::Positive,
                    Sign::Zero => Sign::Zero,
                }
            }
        }
    }

    /// Where the edge line `line` meets the bisector of the site and `q`.
    fn crossing(line: Line, q: LocalPoint) -> Vertex {
        match line {
            Line::Side { axis, value } => Vertex::Crossing { axis, value, q },
            Line::Bisector(q1) => Vertex::Circumcenter { q1, q2: q },
        }
    }

    /// Cuts `polygon` (convex, counterclockwise, positive area) by the half-plane of `q`.
    /// Returns false when nothing of positive area is left.
    fn cut(&self, polygon: &mut Vec<Node>, q: LocalPoint, scratch: &mut Scratch) -> bool {
        let Scratch { signs, nodes } = scratch;
        signs.clear();
        signs.extend(polygon.iter().map(|n| self.side(&n.vertex, q)));
        if !signs.contains(&Sign::Negative) {
            return true;
        }
        if !signs.contains(&Sign::Positive) {
            polygon.clear();
            return false;
        }
        let clip = Line::Bisector(q);
        nodes.clear();
        let n = polygon.len();
        for i in 0..n {
            let (a, sa, sb) = (polygon[i], signs[i], signs[(i + 1) % n]);
            if sa != Sign::Negative {
                // From a vertex on the line whose successor is cut off, the edge runs along it.
                let next = if sa == Sign::Zero && sb == Sign::Negative {
                    clip
                } else {
                    a.next
                };
                nodes.push((Node { next, ..a }, sa == Sign::Zero));
            }
            let crosses = (sa == Sign::Positive && sb == Sign::Negative)
                || (sa == Sign::Negative && sb == Sign::Positive);
            if crosses {
                let vertex = Clipper::crossing(a.next, q);
                let next = if sa == Sign::Positive { clip } else { a.next };
                nodes.push((Node { vertex, next }, true));
            }
        }
        // The vertices on the cut line form one run; only its ends are corners.
        let m = nodes.len();
        polygon.clear();
        polygon.extend((0..m).filter_map(|i| {
            let (node, on) = nodes[i];
            let redundant = on && nodes[(i + m - 1) % m].1 && nodes[(i + 1) % m].1;
            (!redundant).then_some(node)
        }));
        true
    }

    /// The coordinates of `v`, correctly rounded from the exact point. A circumcenter of the
    /// site and two consecutive neighbours is the Voronoi vertex between their edges
    /// (`neighbours` pairs each neighbour with the vertex after it): it is kept in `known`.
    fn coordinates(
        &self,
        v: &Vertex,
        neighbours: &[(LocalPoint, VertexId)],
        known: &mut KnownVertices,
    ) -> [f64; 2] {
        if let Vertex::Circumcenter { q1, q2 } = *v {
            let k = neighbours.len();
            let id = (0..k).find_map(|i| {
                let (a, face) = neighbours[i];
                let b = neighbours[(i + 1) % k].0;
                ((a, b) == (q1, q2) || (a, b) == (q2, q1)).then_some(face)
            });
            if let Some(id) = id {
                return known.position(id, || self.coordinates_of(v));
            }
        }
        self.coordinates_of(v)
    }

    fn coordinates_of(&self, v: &Vertex) -> [f64; 2] {
        match *v {
            Vertex::Corner(c) => c,
            Vertex::Crossing { axis, value, q } => {
                let q = self.point(q);
                let w = 1 - axis;
                // A crossing is only created on a side the bisector is not parallel to.
                let other =
                    bisector_crossing(self.p, q, axis, value).unwrap_or(0.5 * (self.p[w] + q[w]));
                let mut out = [value; 2];
                out[w] = other;
                out
            }
            Vertex::Circumcenter { q1, q2 } => {
                // Two crossing bisectors of the site: never collinear.
                circumcenter_nearest(self.p, self.point(q1), self.point(q2)).unwrap_or(self.p)
            }
        }
    }
}

/// Rotates `ring` to start at its lexicographically smallest vertex.
fn start_at_smallest(ring: &mut [[f64; 2]]) {
    if let Some(start) = (0..ring.len()).min_by(|&i, &j| {
        let (a, b) = (ring[i], ring[j]);
        a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1]))
    }) {
        ring.rotate_left(start);
    }
}

/// The box as a counterclockwise polygon of its corners and sides.
fn box_polygon(bbox: &BoundingBox) -> Vec<Node> {
    let corners = bbox.corners();
    let side = |axis: usize, value: f64| Line::Side { axis, value };
    let (lo, hi) = (bbox.min(), bbox.max());
    let sides = [
        side(1, lo[1]),
        side(0, hi[0]),
        side(1, hi[1]),
        side(0, lo[0]),
    ];
    corners
        .iter()
        .zip(sides)
        .map(|(&c, next)| Node {
            vertex: Vertex::Corner(c),
            next,
        })
        .collect()
}

impl Voronoi<'_> {
    /// The cell of point `p` (the caller's index) clipped to `bbox`: a convex polygon,
    /// counterclockwise, as its vertices in coordinates (the ring is not closed: the first
    /// vertex is not repeated), starting at its lexicographically smallest vertex.
    ///
    /// Hull points included: their unbounded cells are clipped like the others, so the
    /// cells of all distinct points tile the box (see [`clipped_cells`](Self::clipped_cells)).
    /// Empty for a duplicate point (its original has the cell), for an index out of range,
    /// and when the cell meets the box in no more than a segment or a point — as it does for
    /// some sites outside the box; the cell of a site outside the box may also be non-empty.
    ///
    /// Which side of the box sides and of the other bisectors every vertex lies on is decided
    /// exactly; each output coordinate is the exact one correctly rounded (box sides exactly,
    /// Voronoi vertices and crossings to the nearest `f64`). A vertex in the middle of an edge
    /// is not listed. Should two distinct exact vertices round to the same coordinates (a cell
    /// thinner than the rounding), the repetition is dropped.
    ///
    /// ```
    /// use wdm_crust::BoundingBox;
    /// let pts = [[0.0, 0.0], [2.0, 0.0], [0.0, 2.0], [2.0, 2.0]];
    /// let tri = wdm_crust::triangulate(&pts)?;
    /// let vor = tri.voronoi();
    /// let bbox = BoundingBox::new([-1.0, -1.0], [3.0, 3.0])?;
    /// // The square's corners split the box into four quarters at (1, 1).
    /// assert_eq!(vor.clipped_cell(0, &bbox), vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn clipped_cell(&self, p: u32, bbox: &BoundingBox) -> Vec<[f64; 2]> {
        self.clipped_cell_with(p, bbox, &mut KnownVertices::default())
    }

    /// [`clipped_cell`](Self::clipped_cell), reusing the Voronoi vertices in `known`.
    fn clipped_cell_with(
        &self,
        p: u32,
        bbox: &BoundingBox,
        known: &mut KnownVertices,
    ) -> Vec<[f64; 2]> {
        if p as usize >= self.tri.point_count() || self.tri.is_duplicate(p) {
            return Vec::new();
        }
        self.clip_cell(self.tri.local_index(p), bbox, known)
    }

    /// [`clipped_cell`](Self::clipped_cell) of every point, by the caller's index, with the
    /// vertices that rounding left within 16 ulps of each other merged, consistently in all
    /// cells (see below).
    ///
    /// The cells of the distinct points tile the box: their signed areas add up to the box's
    /// area (exactly, when computed exactly from the returned coordinates, since every vertex
    /// is shared by the cells around it and box sides keep their coordinates), no two
    /// overlap, and the cell of a site in the box contains it. Duplicates get an empty cell.
    ///
    /// Nearly cocircular sites (decimal grids) have distinct Voronoi vertices a few `1e-15`
    /// apart; rounded independently, they could make a ring touch itself (`A, B, A`), which
    /// GIS tools reject. So a Voronoi edge whose rounded ends are within 16 ulps is contracted
    /// in every cell to one of its ends (a box corner or side point if there is one), and a
    /// cell thinner than that disappears; [`clipped_cell`](Self::clipped_cell) alone does not
    /// do this, as it needs the neighbouring cells.
    ///
    /// ```
    /// use wdm_crust::BoundingBox;
    /// let pts = [[0.0, 0.0], [3.0, 0.5], [1.0, 2.0], [0.0, 0.0], [2.5, 2.5]];
    /// let tri = wdm_crust::triangulate(&pts)?;
    /// let bbox = BoundingBox::around(&pts).unwrap();
    /// let cells = tri.voronoi().clipped_cells(&bbox);
    /// assert!(cells[3].is_empty()); // a duplicate of point 0
    /// let area = |ring: &Vec<[f64; 2]>| {
    ///     (0..ring.len()).map(|i| {
    ///         let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
    ///         a[0] * b[1] - a[1] * b[0]
    ///     }).sum::<f64>() / 2.0
    /// };
    /// let total: f64 = cells.iter().map(area).sum();
    /// assert!((total - bbox.area()).abs() <= 1e-12 * bbox.area());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn clipped_cells(&self, bbox: &BoundingBox) -> Vec<Vec<[f64; 2]>> {
        let mut known = KnownVertices::for_all(self.vertex_count);
        let mut rings: Vec<Vec<[f64; 2]>> = vec![Vec::new(); self.tri.point_count()];
        // In local (Z) order: neighbouring cells are near each other in memory.
        for p in self.tri.local_points() {
            let ring = self.clip_cell(p, bbox, &mut known);
            rings[self.tri.input_index(p) as usize] = ring;
        }
        merge_close_vertices(&mut rings, bbox);
        for ring in &mut rings {
            start_at_smallest(ring);
        }
        rings
    }

    /// [`clipped_cell`](Self::clipped_cell) of local point `p`.
    fn clip_cell(
        &self,
        p: LocalPoint,
        bbox: &BoundingBox,
        known: &mut KnownVertices,
    ) -> Vec<[f64; 2]> {
        if let Some(ring) = self.cell_inside_box(p, bbox, known) {
            return ring;
        }
        let clipper = Clipper {
            points: &self.tri.points,
            p: self.tri.position(p),
        };
        let mut polygon = box_polygon(bbox);
        let mut scratch = Scratch::default();
        let neighbours = self.cell_neighbours(p);
        for &(q, _) in &neighbours {
            if !clipper.cut(&mut polygon, q, &mut scratch) {
                return Vec::new();
            }
        }
        let mut ring: Vec<[f64; 2]> = polygon
            .iter()
            .map(|n| clipper.coordinates(&n.vertex, &neighbours, known))
            .collect();
        ring.dedup();
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        start_at_smallest(&mut ring);
        ring
    }

    /// The fast path of most cells: a bounded cell whose Voronoi vertices all lie strictly
    /// inside the box (decided exactly) is its own clipped cell; its vertices are distinct and
    /// in strictly convex position. `None` otherwise.
    fn cell_inside_box(
        &self,
        p: LocalPoint,
        bbox: &BoundingBox,
        known: &mut KnownVertices,
    ) -> Option<Vec<[f64; 2]>> {
        if !self.is_interior(p) {
            return None;
        }
        let mut ring = Vec::new();
        for v in self.cell_vertices(p) {
            let t = self.vertex_triangle(v);
            if !known.inside(v, || {
                circumcenter_strictly_inside(t, bbox.min(), bbox.max())
            }) {
                return None;
            }
            // Collinear Delaunay triangles do not exist: the fallback is unreachable.
            ring.push(known.position(v, || circumcenter_nearest(t[0], t[1], t[2]).unwrap_or(t[0])));
        }
        ring.dedup();
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        start_at_smallest(&mut ring);
        Some(ring)
    }

    /// The sites across the edges of the cell of local point `p`, counterclockwise around it,
    /// each with the Voronoi vertex between its edge and the next one ([`NO_VERTEX`] after
    /// the last neighbour of a hull point, and for collinear input, where the neighbours are
    /// the previous and next point on the line).
    fn cell_neighbours(&self, p: LocalPoint) -> Vec<(LocalPoint, VertexId)> {
        if self.tri.is_degenerate() {
            let line = &self.tri.hull;
            let Some(at) = line.iter().position(|&i| i == p) else {
                return Vec::new();
            };
            let before = at.checked_sub(1).map(|i| line[i]);
            return before
                .into_iter()
                .chain(line.get(at + 1).copied())
                .map(|q| (q, NO_VERTEX))
                .collect();
        }
        let start = self.out_halfedge[p.index()];
        let mut neighbours = Vec::new();
        if start == NO_TWIN {
            return neighbours;
        }
        let mut e = start;
        loop {
            if self.has_dual(e) {
                // The face left of p → q lies between q's edge and the next one.
                neighbours.push((self.tri.dest(e), self.vertex_of_halfedge(e)));
            }
            match self.rotate_counterclockwise(e) {
                Some(next) if next != start => e = next,
                Some(_) => break,
                None => {
                    // A hull point: the incoming hull edge comes from the last neighbour.
                    neighbours.push((self.tri.org(e.prev()), NO_VERTEX));
                    break;
                }
            }
        }
        neighbours
    }
}
