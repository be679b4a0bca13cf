//! The Voronoi diagram as a view over a finished [`Triangulation`].
//!
//! One Voronoi vertex per Delaunay face **after merging** adjacent triangles that share their
//! circumcircle (exact `incircle == 0` across the common edge): a cocircular set gives one
//! vertex of degree k > 3 instead of a cluster of zero-length edges. Delaunay edges inside a
//! merged face have no Voronoi edge.
//!
//! Every Voronoi edge is named by a Delaunay half-edge on the boundary of a merged face (its
//! dual): that half-edge's face is one end; the face across its twin is the other end, or
//! infinity when the half-edge is on the convex hull (a ray). So the dual relation is O(1)
//! both ways and nothing of the triangulation is copied.
//!
//! Collinear input (or fewer than three distinct points) has no Voronoi vertex: the diagram
//! is then `n − 1` parallel lines, the bisectors of consecutive points of
//! [`Triangulation::hull`], which this vertex/edge/ray model does not represent; every cell
//! iterator is empty and [`Voronoi::collinear_bisectors`] lists the bisected pairs.
//!
//! [`Voronoi::clipped_cells`] gives every cell, hull cells and collinear input included, as a
//! polygon in coordinates clipped to a [`BoundingBox`], so that the cells tile the box.

mod bounding_box;
mod cells;
mod merge;

pub use bounding_box::{BoundingBox, BoxError};

use crate::delaunay::{Triangulation, NO_TWIN};
use crate::ids::{ids, HalfEdge, LocalPoint, TriangleId, VertexId};
use crate::kernel::{circumcenter, circumcenter_exact, incircle, ExactPoint, Sign};
use crate::parallel;
use crate::predicates::{orient2d, Orientation};

/// The far end of a Voronoi edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EdgeEnd {
    /// A finite Voronoi vertex.
    Vertex(VertexId),
    /// Infinity: the edge is a ray (its dual is a convex hull edge).
    Infinity,
}

/// A Voronoi edge seen from one of its finite ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct VoronoiEdge {
    /// The dual Delaunay half-edge, on the boundary of `from`'s face.
    pub halfedge: HalfEdge,
    /// The vertex the edge is seen from.
    pub from: VertexId,
    /// The other end.
    pub to: EdgeEnd,
    /// The two points whose cells the edge separates: origin and destination of `halfedge`.
    /// The cell of `sites[0]` lies to the left of the edge when walking from `from` to `to`.
    pub sites: [u32; 2],
}

/// A [`VoronoiEdge`] inside the crate: its sites are local points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct DualEdge {
    /// The dual Delaunay half-edge, on the boundary of `from`'s face.
    pub halfedge: HalfEdge,
    /// The vertex the edge is seen from.
    pub from: VertexId,
    /// The other end.
    pub to: EdgeEnd,
    /// Origin and destination of `halfedge`: the cell of `sites[0]` lies to its left.
    pub sites: [LocalPoint; 2],
}

/// The Voronoi diagram of the distinct points of a triangulation.
///
/// Memory: 4 bytes per distinct point, plus, only when some neighbouring triangles are
/// cocircular, the merged faces (about 24 bytes per triangle), plus, once
/// [`vertex_positions`](Voronoi::vertex_positions) is first called, 16 bytes per vertex.
/// The labeler decides everything on the exact circumcenters of triangles and never needs
/// the rounded positions of all vertices.
#[derive(Debug, Clone)]
pub struct Voronoi<'a> {
    tri: &'a Triangulation,
    vertex_count: usize,
    /// The f64 circumcenters of all vertices, computed on first use.
    positions: std::sync::OnceLock<Vec<[f64; 2]>>,
    /// One half-edge out of every local point (the outgoing hull edge for hull points);
    /// `NO_TWIN` in degenerate input.
    out_halfedge: Vec<HalfEdge>,
    /// `None` when no two neighbouring triangles share their circumcircle (the common case
    /// for real-valued input): then vertex `v` is triangle `v` and its face is that triangle.
    merged: Option<MergedFaces>,
}

/// The faces of the diagram when some of them merge several triangles.
#[derive(Debug, Clone)]
struct MergedFaces {
    vertex_of_triangle: Vec<VertexId>,
    /// The smallest triangle of every vertex's face: the one its position is computed from.
    first_triangle: Vec<TriangleId>,
    /// `boundary[boundary_start[v]..boundary_start[v + 1]]`: the half-edges around the face
    /// of `v`, counterclockwise from the smallest. Empty for a single-triangle face, whose
    /// boundary is its three half-edges.
    boundary_start: Vec<u32>,
    boundary: Vec<HalfEdge>,
}

/// The boundary half-edges of one face, counterclockwise.
#[derive(Debug, Clone)]
enum FaceBoundary<'v> {
    Triangle(std::ops::Range<u32>),
    Merged(std::slice::Iter<'v, HalfEdge>),
}

impl Iterator for FaceBoundary<'_> {
    type Item = HalfEdge;

    #[inline]
    fn next(&mut self) -> Option<HalfEdge> {
        match self {
            FaceBoundary::Triangle(range) => range.next().map(HalfEdge::new),
            FaceBoundary::Merged(iter) => iter.next().copied(),
        }
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        match self {
            FaceBoundary::Triangle(range) => range.size_hint(),
            FaceBoundary::Merged(iter) => iter.size_hint(),
        }
    }
}

impl ExactSizeIterator for FaceBoundary<'_> {}

impl Triangulation {
    /// The Voronoi dual of this triangulation, with cocircular faces merged.
    ///
    /// ```
    /// // A square and its centre: four triangles, four distinct circumcircles.
    /// let pts = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0], [1.0, 0.5]];
    /// let tri = wdm_crust::triangulate(&pts)?;
    /// let vor = tri.voronoi();
    /// assert_eq!(vor.vertex_count(), 4);
    /// assert!(vor.is_cell_bounded(4));
    /// assert_eq!(vor.cell(4).count(), 4);
    /// let centre = wdm_crust::VertexId::new(0);
    /// // Without the centre the square's four corners are cocircular: one vertex, four rays.
    /// let tri = wdm_crust::triangulate(&pts[..4])?;
    /// let vor = tri.voronoi();
    /// assert_eq!(vor.vertex_count(), 1);
    /// assert_eq!(vor.vertex_position(centre), [1.0, 1.0]);
    /// assert_eq!(vor.rays().count(), 4);
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn voronoi(&self) -> Voronoi<'_> {
        Voronoi::new(self)
    }
}

/// The outgoing half-edge of every point as `Voronoi::new`'s one pass over the triangles
/// finds it — the one on the hull if the point is on it, else the first (smallest) — on all
/// threads: an atomic minimum per point over its interior half-edges, then the hull
/// half-edges (a point on the hull starts exactly one) written over it. The atomics are the
/// result's own memory, 4 bytes a point. (At 10^7 curve points the sequential pass took
/// 0.15 s of the dual's 0.49 s on two threads, this one 0.12 s; it shares out on more
/// cores, the sequential one does not. A first version kept 64-bit keys that put the hull
/// half-edge first, then copied them out: 12 bytes a point of fresh memory instead of 4.)
#[cfg(feature = "parallel")]
fn outgoing_halfedges(tri: &Triangulation) -> Vec<HalfEdge> {
    use rayon::prelude::*;
    use std::sync::atomic::{AtomicU32, Ordering::Relaxed};
    let halfedges = tri.halfedges();
    let out: Vec<AtomicU32> = (0..tri.points.len())
        .into_par_iter()
        .map(|_| AtomicU32::new(NO_TWIN.get()))
        .collect();
    // Reserved on this thread: worker-grown vectors would stay in the workers' allocators
    // (a sixth of a curve sample's points are on its hull).
    let hull_halfedges =
        parallel::flat_map_chunks_reserved(tri.triangles.len(), 3, |range, hull| {
            for t in range {
                let t = TriangleId::new(t as u32);
                for (e, origin) in t.halfedges().into_iter().zip(tri.corners(t)) {
                    if halfedges[e.index()] == NO_TWIN {
                        hull.push(e);
                    } else {
                        out[origin.index()].fetch_min(e.get(), Relaxed);
                    }
                }
            }
        });
    for e in hull_halfedges {
        out[tri.org(e).index()].store(e.get(), Relaxed);
    }
    // In place: an atomic has the layout of its value, and so has a half-edge.
    out.into_iter()
        .map(|e| HalfEdge::new(e.into_inner()))
        .collect()
}

/// Without the `parallel` feature (where `parallel::pays` is false and `Voronoi::new` takes
/// its one pass instead): the same array, one pass.
#[cfg(not(feature = "parallel"))]
fn outgoing_halfedges(tri: &Triangulation) -> Vec<HalfEdge> {
    let mut out = vec![NO_TWIN; tri.points.len()];
    for t in tri.triangle_ids() {
        note_outgoing(tri, t, &mut out);
    }
    out
}

/// The sequential rule for the half-edges of triangle `t`: a hull half-edge replaces what a
/// point has, an interior one only fills an empty entry (so the first stays).
fn note_outgoing(tri: &Triangulation, t: TriangleId, out: &mut [HalfEdge]) {
    let halfedges = tri.halfedges();
    for (e, origin) in t.halfedges().into_iter().zip(tri.corners(t)) {
        let entry = &mut out[origin.index()];
        if halfedges[e.index()] == NO_TWIN || *entry == NO_TWIN {
            *entry = e;
        }
    }
}

impl<'a> Voronoi<'a> {
    /// One pass over the triangles finds the outgoing half-edge of every point and the
    /// cocircular neighbours; the faces are merged only if there are any.
    fn new(tri: &'a Triangulation) -> Self {
        let triangles = &tri.triangles;
        let halfedges = tri.halfedges();
        let points = &tri.points;
        let out_halfedge;
        // The neighbours across the edges of triangle `t` that share its circumcircle (each
        // interior edge once, from its lower half-edge).
        let cocircular_at = |t: TriangleId, pairs: &mut Vec<[TriangleId; 2]>| {
            let [a, b, c] = tri.triangle_points(t);
            for e in t.halfedges() {
                let twin = halfedges[e.index()];
                if twin != NO_TWIN && twin > e {
                    let opposite = points[tri.org(twin.prev()).index()];
                    if incircle(a, b, c, opposite) == Sign::Zero {
                        pairs.push([t, twin.triangle()]);
                    }
                }
            }
        };
        let cocircular_pairs = if parallel::pays(triangles.len()) {
            // The in-circle tests, the bulk of the work, and the outgoing half-edges, in a
            // pass of their own, on all threads.
            out_halfedge = outgoing_halfedges(tri);
            parallel::flat_map_chunks(triangles.len(), |range, pairs| {
                range.for_each(|t| cocircular_at(TriangleId::new(t as u32), pairs))
            })
        } else {
            // One pass over the triangles: each is read once.
            let mut out = vec![NO_TWIN; points.len()];
            let mut pairs = Vec::new();
            for t in tri.triangle_ids() {
                note_outgoing(tri, t, &mut out);
                cocircular_at(t, &mut pairs);
            }
            out_halfedge = out;
            pairs
        };
        let merged =
            (!cocircular_pairs.is_empty()).then(|| MergedFaces::new(tri, &cocircular_pairs));
        let vertex_count = merged
            .as_ref()
            .map_or(triangles.len(), |m| m.first_triangle.len());
        Voronoi {
            tri,
            vertex_count,
            positions: std::sync::OnceLock::new(),
            out_halfedge,
            merged,
        }
    }

    /// The triangulation this diagram is the dual of.
    pub fn triangulation(&self) -> &'a Triangulation {
        self.tri
    }

    /// Number of finite Voronoi vertices (merged Delaunay faces).
    pub fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    /// The vertex ids `0..vertex_count()`.
    pub fn vertex_ids(
        &self,
    ) -> impl DoubleEndedIterator<Item = VertexId> + ExactSizeIterator + Clone {
        ids(self.vertex_count)
    }

    /// Circumcenters of all vertices, rounded to f64 as [`vertex_position`] rounds them, by
    /// [`VertexId::index`].
    /// Computed on the first call (a filtered circumcenter per vertex, some tens of
    /// nanoseconds each) and kept.
    ///
    /// [`vertex_position`]: Voronoi::vertex_position
    pub fn vertex_positions(&self) -> &[[f64; 2]] {
        self.positions.get_or_init(|| {
            parallel::map_range(self.vertex_count, |v| {
                self.compute_position(VertexId::new(v as u32))
            })
        })
    }

    /// Frees the positions [`vertex_positions`](Voronoi::vertex_positions) computed (they are
    /// computed again on the next call): for a caller done with them before a
    /// memory-hungry step.
    pub(crate) fn forget_positions(&mut self) {
        self.positions.take();
    }

    /// Circumcenter of vertex `v`, rounded to f64: within 256 ulps of the exact one, see
    /// [`crate::predicates::circumcenter`].
    pub fn vertex_position(&self, v: VertexId) -> [f64; 2] {
        match self.positions.get() {
            Some(positions) => positions[v.index()],
            None => self.compute_position(v),
        }
    }

    fn compute_position(&self, v: VertexId) -> [f64; 2] {
        rounded_circumcenter(self.canonical_triangle(v))
    }

    /// Three sites of the face of `v`, chosen by their coordinates alone, counterclockwise
    /// ([`rounded_circumcenter`] then starts from the smallest): the rounded circumcenter
    /// depends on which triangle and which corner it starts from, and those depend on the
    /// input order where points tie in the Z-order (points much closer together than the
    /// spread of the input). A single triangle is its own; a merged face gives its three
    /// lexicographically smallest sites (distinct points on one circle: never collinear).
    pub(crate) fn canonical_triangle(&self, v: VertexId) -> [[f64; 2]; 3] {
        if self.degree(v) == 3 {
            return self.vertex_triangle(v);
        }
        let mut sites: Vec<[f64; 2]> = self.face_corners(v).map(|p| self.tri.position(p)).collect();
        sites.sort_unstable_by(|p, q| lexicographic(*p, *q));
        let (a, mut b, mut c) = (sites[0], sites[1], sites[2]);
        if orient2d(a, b, c) == Orientation::Clockwise {
            std::mem::swap(&mut b, &mut c);
        }
        [a, b, c]
    }

    /// Circumcenter of vertex `v` as an exact rational point.
    pub fn vertex_exact(&self, v: VertexId) -> ExactPoint {
        let [a, b, c] = self.vertex_triangle(v);
        // Delaunay triangles are never collinear, so the circumcenter exists.
        circumcenter_exact(a, b, c).unwrap_or_else(|| ExactPoint::from_f64(a))
    }

    /// Three points of the face of `v` (a Delaunay triangle of it): the input the exact
    /// circumcenter predicates take.
    pub fn vertex_triangle(&self, v: VertexId) -> [[f64; 2]; 3] {
        self.tri.triangle_points(self.vertex_triangle_id(v))
    }

    /// A Delaunay triangle of the face of `v` (the one [`vertex_triangle`](Self::vertex_triangle) reads).
    pub(crate) fn vertex_triangle_id(&self, v: VertexId) -> TriangleId {
        match &self.merged {
            None => TriangleId::new(v.get()),
            Some(m) => m.first_triangle[v.index()],
        }
    }

    /// The Voronoi vertex of Delaunay triangle `t`.
    #[inline]
    pub fn vertex_of_triangle(&self, t: TriangleId) -> VertexId {
        match &self.merged {
            None => VertexId::new(t.get()),
            Some(m) => m.vertex_of_triangle[t.index()],
        }
    }

    /// The Voronoi vertex on the left of Delaunay half-edge `e` (the face containing it).
    #[inline]
    pub fn vertex_of_halfedge(&self, e: HalfEdge) -> VertexId {
        self.vertex_of_triangle(e.triangle())
    }

    /// Whether any two neighbouring Delaunay triangles share their circumcircle (then some
    /// vertex has degree above 3 and some Delaunay edges have no dual).
    pub fn has_merged_faces(&self) -> bool {
        self.merged.is_some()
    }

    #[inline]
    fn boundary_of(&self, v: VertexId) -> FaceBoundary<'_> {
        if let Some(m) = &self.merged {
            let row = &m.boundary
                [m.boundary_start[v.index()] as usize..m.boundary_start[v.index() + 1] as usize];
            if !row.is_empty() {
                return FaceBoundary::Merged(row.iter());
            }
            let e = m.first_triangle[v.index()].halfedge(0).get();
            return FaceBoundary::Triangle(e..e + 3);
        }
        let e = 3 * v.get();
        FaceBoundary::Triangle(e..e + 3)
    }

    /// Number of Voronoi edges (finite and rays) at `v`: the corners of its merged face.
    pub fn degree(&self, v: VertexId) -> usize {
        self.boundary_of(v).len()
    }

    /// The points whose cells meet at `v` (the corners of its Delaunay face), counterclockwise.
    pub fn vertex_sites(&self, v: VertexId) -> impl Iterator<Item = u32> + '_ {
        self.face_corners(v).map(|p| self.tri.input_index(p))
    }

    /// The corners of the Delaunay face of `v` (the sites of [`vertex_sites`](Self::vertex_sites)).
    #[inline]
    pub(crate) fn face_corners(&self, v: VertexId) -> impl Iterator<Item = LocalPoint> + '_ {
        self.boundary_of(v).map(|e| self.tri.org(e))
    }

    /// The Voronoi edges at `v`, counterclockwise around its face.
    pub fn vertex_edges(&self, v: VertexId) -> impl Iterator<Item = VoronoiEdge> + '_ {
        self.face_edges(v).map(|edge| self.with_caller_sites(edge))
    }

    /// The edges of [`vertex_edges`](Self::vertex_edges), with local sites.
    #[inline]
    pub(crate) fn face_edges(&self, v: VertexId) -> impl Iterator<Item = DualEdge> + '_ {
        self.boundary_of(v).map(|e| self.dual_edge(e))
    }

    /// The Voronoi edge dual to the boundary half-edge `e`, seen from the face of `e`.
    pub fn edge(&self, e: HalfEdge) -> VoronoiEdge {
        self.with_caller_sites(self.dual_edge(e))
    }

    /// The public face of a [`DualEdge`].
    fn with_caller_sites(&self, edge: DualEdge) -> VoronoiEdge {
        VoronoiEdge {
            halfedge: edge.halfedge,
            from: edge.from,
            to: edge.to,
            sites: edge.sites.map(|p| self.tri.input_index(p)),
        }
    }

    /// [`edge`](Self::edge), with local sites.
    #[inline]
    pub(crate) fn dual_edge(&self, e: HalfEdge) -> DualEdge {
        DualEdge {
            halfedge: e,
            from: self.vertex_of_halfedge(e),
            to: match self.tri.twin(e) {
                None => EdgeEnd::Infinity,
                Some(twin) => EdgeEnd::Vertex(self.vertex_of_halfedge(twin)),
            },
            sites: [self.tri.org(e), self.tri.dest(e)],
        }
    }

    /// True when the Delaunay half-edge `e` has a dual Voronoi edge (its two sides are in
    /// different merged faces, or it is on the hull).
    pub fn has_dual(&self, e: HalfEdge) -> bool {
        let twin = self.tri.halfedges()[e.index()];
        twin == NO_TWIN
            || self.merged.is_none()
            || self.vertex_of_halfedge(e) != self.vertex_of_halfedge(twin)
    }

    /// The vertices that carry a ray, sorted, each once: the faces of the hull edges, read
    /// off the hull's points (each starts one hull edge, its outgoing half-edge here),
    /// without a pass over all vertices.
    pub(crate) fn ray_vertices(&self) -> Vec<VertexId> {
        let mut rays: Vec<VertexId> = (self.tri.hull.iter())
            .map(|&p| self.out_halfedge[p.index()])
            .filter(|&e| e != NO_TWIN)
            .map(|e| self.vertex_of_halfedge(e))
            .collect();
        rays.sort_unstable();
        rays.dedup();
        rays
    }

    /// Does `v` carry at least one ray (is its face on the convex hull)?
    pub fn has_ray(&self, v: VertexId) -> bool {
        self.boundary_of(v)
            .any(|e| self.tri.halfedges()[e.index()] == NO_TWIN)
    }

    /// Finite Voronoi edges, each once, by increasing dual half-edge:
    /// `(dual half-edge, vertex, vertex)`.
    pub fn finite_edges(&self) -> impl Iterator<Item = (HalfEdge, VertexId, VertexId)> + '_ {
        let halfedges = self.tri.halfedges();
        self.tri.halfedge_ids().filter_map(move |e| {
            let twin = halfedges[e.index()];
            (twin != NO_TWIN && e < twin && self.has_dual(e))
                .then(|| (e, self.vertex_of_halfedge(e), self.vertex_of_halfedge(twin)))
        })
    }

    /// Rays, by increasing dual half-edge: `(dual hull half-edge, vertex, outward direction)`.
    /// The direction is the outward normal of the hull edge, `(b − a)` turned clockwise,
    /// rounded to f64; halved where a difference of coordinates near `f64::MAX` would
    /// overflow (a direction, not a length: always finite).
    pub fn rays(&self) -> impl Iterator<Item = (HalfEdge, VertexId, [f64; 2])> + '_ {
        let halfedges = self.tri.halfedges();
        (self.tri.halfedge_ids())
            .filter(move |&e| halfedges[e.index()] == NO_TWIN)
            .map(move |e| (e, self.vertex_of_halfedge(e), self.ray_direction(e)))
    }

    /// Outward normal of the hull half-edge `e` (interior on its left): `(b − a)` turned
    /// clockwise, rounded to f64, or half of it where that overflows (see [`rays`](Self::rays)).
    pub fn ray_direction(&self, e: HalfEdge) -> [f64; 2] {
        let a = self.tri.position(self.tri.org(e));
        let b = self.tri.position(self.tri.dest(e));
        let direction = [b[1] - a[1], a[0] - b[0]];
        if direction.iter().all(|d| d.is_finite()) {
            return direction;
        }
        // Differences of finite numbers overflow only near `f64::MAX`, where halving is
        // exact; the halves' differences are then finite and round once.
        [b[1] / 2.0 - a[1] / 2.0, a[0] / 2.0 - b[0] / 2.0]
    }

    /// Is the cell of point `p` bounded (is `p` strictly inside the convex hull)?
    /// False for hull points, duplicates and degenerate input.
    pub fn is_cell_bounded(&self, p: u32) -> bool {
        !self.tri.is_duplicate(p) && self.is_interior(self.tri.local_index(p))
    }

    /// Is local point `p` strictly inside the convex hull (is its cell bounded)? False for
    /// degenerate input.
    #[inline]
    pub(crate) fn is_interior(&self, p: LocalPoint) -> bool {
        let e = self.out_halfedge[p.index()];
        e != NO_TWIN && self.tri.halfedges()[e.index()] != NO_TWIN
    }

    /// The vertices of the cell of point `p`, counterclockwise. For a hull point the cell
    /// is open: it starts at the vertex carrying the ray of the outgoing hull edge and ends at
    /// the one carrying the ray of the incoming hull edge. Empty for a duplicate (its cell is
    /// its original's: ask for that one) and for degenerate input.
    pub fn cell(&self, p: u32) -> CellVertices<'_, 'a> {
        if self.tri.is_duplicate(p) {
            return CellVertices {
                voronoi: self,
                first: NO_TWIN,
                next: None,
                last_vertex: None,
            };
        }
        self.cell_vertices(self.tri.local_index(p))
    }

    /// The vertices of the cell of local point `p`, as [`cell`](Self::cell) gives them.
    #[inline]
    pub(crate) fn cell_vertices(&self, p: LocalPoint) -> CellVertices<'_, 'a> {
        let start = self.out_halfedge[p.index()];
        let mut first = start;
        if start != NO_TWIN && self.tri.halfedges()[start.index()] != NO_TWIN {
            // Interior point: start right after a change of face, so that a merged face is
            // not split across the wrap-around.
            let v = self.vertex_of_halfedge(start);
            while let Some(prev) = self.rotate_clockwise(first) {
                if self.vertex_of_halfedge(prev) != v || prev == start {
                    break;
                }
                first = prev;
            }
        }
        CellVertices {
            voronoi: self,
            first,
            next: (first != NO_TWIN).then_some(first),
            last_vertex: None,
        }
    }

    /// Is `[a, b]` (local indices) an edge of the triangulation? Walks the triangles around `a`: O(degree).
    pub(crate) fn is_delaunay_edge(&self, a: LocalPoint, b: LocalPoint) -> bool {
        self.delaunay_halfedge(a, b).is_some()
    }

    /// The half-edge from local point `a` to `b`, or from `b` to `a` when `a → b` is a hull edge seen
    /// from outside; `None` when `[a, b]` is no edge of the triangulation. O(degree of `a`).
    pub(crate) fn delaunay_halfedge(&self, a: LocalPoint, b: LocalPoint) -> Option<HalfEdge> {
        let start = self.out_halfedge[a.index()];
        if start == NO_TWIN || a == b {
            return None;
        }
        let mut e = start;
        loop {
            if self.tri.dest(e) == b {
                return Some(e);
            }
            // The incoming half-edge of this triangle ends at `a`; on the hull it is the
            // only way to meet the last neighbour clockwise.
            let incoming = e.prev();
            if self.tri.org(incoming) == b {
                return Some(incoming);
            }
            match self.rotate_counterclockwise(e) {
                Some(next) if next != start => e = next,
                _ => return None,
            }
        }
    }

    /// The Delaunay neighbours of local point `p`, counterclockwise (from the outgoing hull
    /// edge for a hull point); none for degenerate input. O(degree), nothing stored. (The
    /// clipped cells' `neighbour_vertices` also pairs each neighbour with a vertex,
    /// allocates, and gives collinear input its line neighbours; peeling wants neither.)
    pub(crate) fn delaunay_neighbours(
        &self,
        p: LocalPoint,
    ) -> impl Iterator<Item = LocalPoint> + '_ {
        self.neighbours_through(p, |_| true)
    }

    /// The Delaunay neighbours of local point `p` along edges with a dual Voronoi edge (the
    /// Delaunay graph without the diagonals inside merged cocircular faces), counterclockwise
    /// like [`Self::delaunay_neighbours`]. O(degree).
    pub(crate) fn dual_neighbours(
        &self,
        p: LocalPoint,
    ) -> impl Iterator<Item = LocalPoint> + Clone + '_ {
        self.neighbours_through(p, |e| self.has_dual(e))
    }

    /// The neighbours of `p` counterclockwise along its out-going half-edges `e` with
    /// `keep(e)`; past the hull, the incoming hull edge's origin (always kept: a hull edge has
    /// a dual ray).
    fn neighbours_through<'s>(
        &'s self,
        p: LocalPoint,
        keep: impl Fn(HalfEdge) -> bool + Clone + 's,
    ) -> impl Iterator<Item = LocalPoint> + Clone + 's {
        let start = self.out_halfedge[p.index()];
        let mut next = (start != NO_TWIN).then_some(start);
        let mut last = None;
        std::iter::from_fn(move || loop {
            let Some(e) = next else {
                return last.take();
            };
            next = match self.rotate_counterclockwise(e) {
                Some(after) if after != start => Some(after),
                Some(_) => None,
                None => {
                    last = Some(self.tri.org(e.prev()));
                    None
                }
            };
            if keep(e) {
                return Some(self.tri.dest(e));
            }
        })
    }

    /// The half-edge out of the same point, one triangle counterclockwise; `None` past the hull.
    #[inline]
    fn rotate_counterclockwise(&self, e: HalfEdge) -> Option<HalfEdge> {
        self.tri.twin(e.prev())
    }

    /// The half-edge out of the same point, one triangle clockwise; `None` past the hull.
    #[inline]
    fn rotate_clockwise(&self, e: HalfEdge) -> Option<HalfEdge> {
        self.tri.twin(e).map(HalfEdge::next)
    }

    /// Pairs of consecutive points along the line when the input is collinear: the diagram is
    /// their perpendicular bisectors. Empty otherwise.
    pub fn collinear_bisectors(&self) -> Vec<[u32; 2]> {
        if self.tri.is_degenerate() {
            let hull = &self.tri.hull;
            (hull.windows(2))
                .map(|w| [w[0], w[1]].map(|p| self.tri.input_index(p)))
                .collect()
        } else {
            Vec::new()
        }
    }
}

/// The rounded circumcenter of a Delaunay triangle (never collinear), started from its
/// corner [`smallest_corner`]: the value [`Voronoi::vertex_position`] gives its face, from
/// the coordinates' values alone. A zero is read as `0.0`: a duplicate keeps its first
/// occurrence's coordinates, and the sign of a zero would let the input order choose the
/// corner (and the sign of a zero result).
pub(crate) fn rounded_circumcenter(t: [[f64; 2]; 3]) -> [f64; 2] {
    let mut t = t.map(|p| p.map(|x| x + 0.0));
    let first = smallest_corner(t);
    t.rotate_left(first);
    let [a, b, c] = t;
    // Delaunay triangles are never collinear; the fallback is unreachable.
    circumcenter(a, b, c).unwrap_or(a)
}

/// The lexicographically smallest corner of `t`.
pub(crate) fn smallest_corner(t: [[f64; 2]; 3]) -> usize {
    (0..3)
        .min_by(|&i, &j| lexicographic(t[i], t[j]))
        .unwrap_or(0)
}

/// Orders points by x, then y, `-0.0` as `0.0` (see [`rounded_circumcenter`]).
fn lexicographic(p: [f64; 2], q: [f64; 2]) -> std::cmp::Ordering {
    let key = |x: f64| x + 0.0;
    key(p[0])
        .total_cmp(&key(q[0]))
        .then(key(p[1]).total_cmp(&key(q[1])))
}

/// Iterator over the vertices of one Voronoi cell, counterclockwise.
#[derive(Debug, Clone)]
pub struct CellVertices<'v, 'a> {
    voronoi: &'v Voronoi<'a>,
    first: HalfEdge,
    next: Option<HalfEdge>,
    last_vertex: Option<VertexId>,
}

impl Iterator for CellVertices<'_, '_> {
    type Item = VertexId;

    #[inline]
    fn next(&mut self) -> Option<VertexId> {
        while let Some(e) = self.next {
            let v = self.voronoi.vertex_of_halfedge(e);
            self.next = self
                .voronoi
                .rotate_counterclockwise(e)
                .filter(|&n| n != self.first);
            if self.last_vertex != Some(v) {
                self.last_vertex = Some(v);
                return Some(v);
            }
        }
        None
    }
}

impl MergedFaces {
    /// Merges the faces joined by `cocircular_pairs` of triangles.
    fn new(tri: &Triangulation, cocircular_pairs: &[[TriangleId; 2]]) -> MergedFaces {
        let vertex_of_triangle = union_cocircular(tri.triangle_count(), cocircular_pairs);
        let vertex_count = (vertex_of_triangle.iter())
            .map(|&v| v.index() + 1)
            .max()
            .unwrap_or(0);
        let unset = TriangleId::new(u32::MAX);
        let mut first_triangle = vec![unset; vertex_count];
        for (t, &v) in tri.triangle_ids().zip(&vertex_of_triangle) {
            if first_triangle[v.index()] == unset {
                first_triangle[v.index()] = t;
            }
        }
        let (boundary_start, boundary) = merged_boundaries(tri, &vertex_of_triangle, vertex_count);
        MergedFaces {
            vertex_of_triangle,
            first_triangle,
            boundary_start,
            boundary,
        }
    }
}

/// Union–find over `triangle_count` triangles joined by `pairs`. Returns the vertex id of
/// every triangle, numbered by first appearance.
fn union_cocircular(triangle_count: usize, pairs: &[[TriangleId; 2]]) -> Vec<VertexId> {
    let mut parent: Vec<u32> = (0..triangle_count as u32).collect();
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            let up = parent[parent[x as usize] as usize];
            parent[x as usize] = up; // path halving
            x = up;
        }
        x
    }
    for &[s, t] in pairs {
        let (rs, rt) = (find(&mut parent, s.get()), find(&mut parent, t.get()));
        if rs != rt {
            parent[rs.max(rt) as usize] = rs.min(rt);
        }
    }
    // Roots are linked under the smaller root and path halving only shortens chains, so
    // every parent is smaller than its child and a root is its set's smallest member. In
    // increasing order, the parent of a non-root is therefore already relabelled, with its
    // set's label; relabelling in place is safe.
    let mut vertex = parent;
    let mut count = 0u32;
    for i in 0..triangle_count {
        let up = vertex[i] as usize;
        vertex[i] = if up == i {
            count += 1;
            count - 1
        } else {
            vertex[up]
        };
    }
    // In place: a vertex id is a `u32`.
    vertex.into_iter().map(VertexId::new).collect()
}

/// For every merged vertex, the half-edges on the boundary of its face, counterclockwise,
/// in compressed rows; single-triangle vertices get an empty row.
fn merged_boundaries(
    tri: &Triangulation,
    vertex_of_triangle: &[VertexId],
    vertex_count: usize,
) -> (Vec<u32>, Vec<HalfEdge>) {
    let halfedges = tri.halfedges();
    let mut triangles_of = vec![0u32; vertex_count];
    for &v in vertex_of_triangle {
        triangles_of[v.index()] += 1;
    }
    let face = |e: HalfEdge| vertex_of_triangle[e.triangle().index()];
    let merged = |e: HalfEdge| triangles_of[face(e).index()] > 1;
    let on_boundary = |e: HalfEdge| {
        let twin = halfedges[e.index()];
        twin == NO_TWIN || face(twin) != face(e)
    };
    let mut start = vec![0u32; vertex_count + 1];
    for e in (tri.halfedge_ids()).filter(|&e| merged(e) && on_boundary(e)) {
        start[face(e).index() + 1] += 1;
    }
    for v in 0..vertex_count {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut boundary = vec![NO_TWIN; start[vertex_count] as usize];
    for e in (tri.halfedge_ids()).filter(|&e| merged(e) && on_boundary(e)) {
        let v = face(e).index();
        boundary[fill[v] as usize] = e;
        fill[v] += 1;
    }
    // Rows are chained by matching each half-edge's destination with the next one's origin.
    for v in 0..vertex_count {
        let row = &mut boundary[start[v] as usize..start[v + 1] as usize];
        if !row.is_empty() {
            order_face_cycle(tri, row);
        }
    }
    (start, boundary)
}

/// Reorders the boundary half-edges of one merged face into a counterclockwise cycle that
/// starts at the smallest half-edge id: the triangle arrays do not depend on the order of the
/// input points, so neither does the cycle (a start chosen by point index would).
fn order_face_cycle(tri: &Triangulation, row: &mut [HalfEdge]) {
    let mut by_origin: Vec<(LocalPoint, HalfEdge)> = row.iter().map(|&e| (tri.org(e), e)).collect();
    by_origin.sort_unstable();
    let Some(mut e) = row.iter().copied().min() else {
        return;
    };
    for slot in row.iter_mut() {
        *slot = e;
        let dest = tri.dest(e);
        if let Ok(i) = by_origin.binary_search_by_key(&dest, |&(o, _)| o) {
            e = by_origin[i].1;
        }
    }
}

#[cfg(test)]
mod tests {
    /// The outgoing half-edges found on several threads are the sequential pass's: the hull
    /// one for hull points, else the first, on points with a hull of many points, and on a
    /// lattice (collinear runs on the hull, merged faces).
    #[cfg(feature = "parallel")]
    #[test]
    fn the_outgoing_halfedges_are_the_same_on_any_thread_count() {
        let mut rng = wdm_crust_testkit::Rng::new(4);
        let mut points: Vec<[f64; 2]> = (0..30_000).map(|_| [rng.f64(), rng.f64()]).collect();
        points.extend((0..3000).map(|k| {
            let t = k as f64 * std::f64::consts::TAU / 3000.0;
            [0.5 + t.cos(), 0.5 + t.sin()]
        }));
        let lattice: Vec<[f64; 2]> = (0..40_000)
            .map(|_| [rng.below(150) as f64, rng.below(120) as f64])
            .collect();
        for points in [points, lattice] {
            let tri = crate::delaunay::triangulate(&points).unwrap();
            let in_pool = |threads: usize| {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap();
                pool.install(|| super::Voronoi::new(&tri).out_halfedge)
            };
            let one = in_pool(1);
            assert!(tri.hull.len() > 300);
            for threads in [2, 3] {
                assert!(in_pool(threads) == one, "{threads} threads");
            }
        }
    }

    use crate::triangulate;
    use std::collections::BTreeSet;
    use wdm_crust_testkit::Rng;

    /// Every point's neighbours are the other ends of its Delaunay edges, each once.
    #[test]
    fn neighbours_are_the_delaunay_edges() {
        let mut rng = wdm_crust_testkit::Rng::new(4);
        for n in [3, 4, 10, 200] {
            let points: Vec<[f64; 2]> = (0..n).map(|_| [rng.f64(), rng.f64()]).collect();
            let tri = crate::triangulate(&points).unwrap();
            let vor = tri.voronoi();
            let mut expected = vec![Vec::new(); tri.points.len()];
            for e in tri.halfedge_ids() {
                let (a, b) = (tri.org(e), tri.dest(e));
                expected[a.index()].push(b);
                expected[b.index()].push(a);
            }
            for (p, want) in tri.local_points().zip(&mut expected) {
                want.sort_unstable();
                want.dedup();
                let mut got: Vec<_> = vor.delaunay_neighbours(p).collect();
                got.sort_unstable();
                assert_eq!(&got, want, "n {n}, point {p}");
            }
        }
    }

    /// The ray vertices read off the hull are those of a pass over every vertex: random
    /// points, lattices (collinear runs on the hull, merged faces on it), collinear input.
    #[test]
    fn the_ray_vertices_are_those_with_a_ray() {
        let mut rng = Rng::new(24);
        for round in 0..80 {
            let n = 1 + rng.below(80);
            let points: Vec<[f64; 2]> = (0..n)
                .map(|i| match round % 3 {
                    0 => [rng.f64(), rng.f64()],
                    1 => [rng.below(5) as f64, rng.below(5) as f64],
                    _ => [i as f64, 2.0 * i as f64],
                })
                .collect();
            let tri = triangulate(&points).unwrap();
            let vor = tri.voronoi();
            let expected: Vec<_> = vor.vertex_ids().filter(|&v| vor.has_ray(v)).collect();
            assert_eq!(vor.ray_vertices(), expected, "round {round}");
        }
    }

    #[test]
    fn is_delaunay_edge_agrees_with_the_edge_list() {
        let mut rng = Rng::new(23);
        for round in 0..60 {
            let n = 3 + rng.below(60);
            // Random points, or a small lattice (collinear hull runs, merged faces).
            let points: Vec<[f64; 2]> = (0..n)
                .map(|_| {
                    if round % 2 == 0 {
                        [rng.f64(), rng.f64()]
                    } else {
                        [rng.below(6) as f64, rng.below(6) as f64]
                    }
                })
                .collect();
            let tri = triangulate(&points).unwrap();
            let vor = tri.voronoi();
            let edges: BTreeSet<[u32; 2]> = (tri.halfedge_ids())
                .map(|e| {
                    let (a, b) = (tri.halfedge_origin(e), tri.halfedge_destination(e));
                    [a.min(b), a.max(b)]
                })
                .collect();
            let kept = |a: u32| !tri.is_duplicate(a);
            for a in (0..n as u32).filter(|&a| kept(a)) {
                for b in (0..n as u32).filter(|&b| kept(b)) {
                    let l = |i| tri.local_index(i);
                    assert_eq!(
                        vor.is_delaunay_edge(l(a), l(b)),
                        edges.contains(&[a.min(b), a.max(b)]),
                        "round {round}: {a}-{b}"
                    );
                }
            }
        }
    }
}
