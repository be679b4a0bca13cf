//! The compact, finished triangulation: flat arrays over local point indices, and the one
//! translation between those and the caller's indices.
//!
//! The divide and conquer puts the distinct points in Z order (duplicates merged into their
//! first occurrence); that order is also the one later passes want (neighbours close in
//! memory), so the topology stays in it: the *local* index of a point is its position in
//! that order. Everything inside the crate (the Voronoi dual, the water flow, extraction,
//! peeling, the baselines) works on local indices; every public method speaks the caller's
//! indices and translates at the boundary. Triangle and half-edge ids need no translation.

use crate::ids::{ids, HalfEdge, LocalPoint, TriangleId};

/// Marks a half-edge without a twin (a convex hull edge) in [`Triangulation::halfedges`].
pub const NO_TWIN: HalfEdge = HalfEdge::new(u32::MAX);

/// A finished Delaunay triangulation.
///
/// Half-edge `e` belongs to triangle `e.triangle()` and runs from its corner `e.corner()` to
/// the next one counterclockwise; its twin runs the other way in the neighbouring triangle,
/// or is [`NO_TWIN`] on the convex hull. Every point index taken or returned by a public
/// method is an index into the caller's slice; internally the points are stored once each,
/// in a locality order (see the module docs), and translated on the way out.
///
/// Memory: 20 bytes per distinct point (coordinates, caller index), 4 per input point (its
/// local index), 8 per duplicate, 24 per triangle (corners and twins), 4 per hull point.
#[derive(Debug, Clone)]
pub struct Triangulation {
    /// Coordinates of the distinct points, by local index.
    pub(crate) points: Vec<[f64; 2]>,
    /// Corners in local indices.
    pub(crate) triangles: Vec<[LocalPoint; 3]>,
    pub(crate) halfedges: Vec<HalfEdge>,
    /// The hull in local indices.
    pub(crate) hull: Vec<LocalPoint>,
    /// Local index → caller index (of the first occurrence).
    pub(crate) input_of: Vec<u32>,
    /// Caller index → local index (a duplicate maps to its kept point).
    pub(crate) local_of: Vec<LocalPoint>,
    /// `[duplicate, kept]` in caller indices, sorted by duplicate.
    pub(crate) duplicates: Vec<[u32; 2]>,
}

impl Triangulation {
    /// Number of the caller's points, duplicates included.
    pub fn point_count(&self) -> usize {
        self.local_of.len()
    }

    /// Coordinates of the caller's point `i` (a duplicate has those of its kept point).
    #[inline]
    pub fn point(&self, i: u32) -> [f64; 2] {
        self.position(self.local_index(i))
    }

    /// Coordinates of local point `p`.
    #[inline]
    pub(crate) fn position(&self, p: LocalPoint) -> [f64; 2] {
        self.points[p.index()]
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// The triangle ids `0..triangle_count()`.
    pub fn triangle_ids(
        &self,
    ) -> impl DoubleEndedIterator<Item = TriangleId> + ExactSizeIterator + Clone {
        ids(self.triangles.len())
    }

    /// Corners of triangle `t`, counterclockwise, as caller indices.
    #[inline]
    pub fn triangle(&self, t: TriangleId) -> [u32; 3] {
        self.corners(t).map(|p| self.input_index(p))
    }

    /// Corners of triangle `t`, counterclockwise, in local indices.
    #[inline]
    pub(crate) fn corners(&self, t: TriangleId) -> [LocalPoint; 3] {
        self.triangles[t.index()]
    }

    /// All triangles as counterclockwise triples of caller indices, by triangle id (nothing
    /// is copied: each triple is translated as it is read). Every distinct point is a corner
    /// of at least one triangle unless all points are collinear (then there are none).
    pub fn triangles(&self) -> impl ExactSizeIterator<Item = [u32; 3]> + Clone + '_ {
        self.triangles
            .iter()
            .map(|t| t.map(|p| self.input_index(p)))
    }

    /// Twin of every half-edge (three per triangle, see the type docs), or [`NO_TWIN`].
    pub fn halfedges(&self) -> &[HalfEdge] {
        &self.halfedges
    }

    /// The half-edge ids `0..halfedges().len()`.
    pub fn halfedge_ids(
        &self,
    ) -> impl DoubleEndedIterator<Item = HalfEdge> + ExactSizeIterator + Clone {
        ids(self.halfedges.len())
    }

    /// The twin of half-edge `e`: the same edge run the other way, in the neighbouring
    /// triangle; `None` for a convex hull edge.
    #[inline]
    pub fn twin(&self, e: HalfEdge) -> Option<HalfEdge> {
        let twin = self.halfedges[e.index()];
        (twin != NO_TWIN).then_some(twin)
    }

    /// The convex hull as caller indices, counterclockwise from the lexicographically
    /// smallest point, listing every distinct point on its boundary (collinear ones
    /// included). For collinear input: the points in order along the line.
    pub fn hull(&self) -> impl ExactSizeIterator<Item = u32> + Clone + '_ {
        self.hull.iter().map(|&p| self.input_index(p))
    }

    /// Pairs `[duplicate, kept]`: `duplicate` has the same coordinates as the earlier point
    /// `kept` and takes no part in the triangulation. Sorted by `duplicate`.
    pub fn duplicates(&self) -> &[[u32; 2]] {
        &self.duplicates
    }

    /// True when there are no triangles: fewer than three distinct points, or all on a line.
    pub fn is_degenerate(&self) -> bool {
        self.triangles.is_empty()
    }

    /// Number of distinct points (the caller's points less the duplicates).
    pub fn distinct_point_count(&self) -> usize {
        self.points.len()
    }

    /// Is caller index `i` a duplicate (merged into an earlier point)?
    #[inline]
    pub fn is_duplicate(&self, i: u32) -> bool {
        self.input_index(self.local_index(i)) != i
    }

    /// Caller index of local point `p`.
    #[inline]
    pub(crate) fn input_index(&self, p: LocalPoint) -> u32 {
        self.input_of[p.index()]
    }

    /// Local index of caller point `i` (its kept point for a duplicate).
    #[inline]
    pub(crate) fn local_index(&self, i: u32) -> LocalPoint {
        self.local_of[i as usize]
    }

    /// The local points `0..distinct_point_count()`.
    pub(crate) fn local_points(
        &self,
    ) -> impl DoubleEndedIterator<Item = LocalPoint> + ExactSizeIterator + Clone {
        ids(self.points.len())
    }

    /// Local edges to caller indices, each `[min, max]`, sorted and deduplicated.
    pub(crate) fn to_input_edges(&self, edges: Vec<[LocalPoint; 2]>) -> Vec<[u32; 2]> {
        // In place: a local point is a `u32`.
        let mut edges: Vec<[u32; 2]> = edges
            .into_iter()
            .map(|edge| {
                let [a, b] = edge.map(|p| self.input_index(p));
                [a.min(b), a.max(b)]
            })
            .collect();
        edges.sort_unstable();
        edges.dedup();
        edges
    }

    /// Local start point of half-edge `e`.
    #[inline]
    pub(crate) fn org(&self, e: HalfEdge) -> LocalPoint {
        self.triangles[e.triangle().index()][e.corner()]
    }

    /// Local end point of half-edge `e`.
    #[inline]
    pub(crate) fn dest(&self, e: HalfEdge) -> LocalPoint {
        self.org(e.next())
    }

    /// Start point of half-edge `e` (a caller index).
    #[inline]
    pub fn halfedge_origin(&self, e: HalfEdge) -> u32 {
        self.input_index(self.org(e))
    }

    /// End point of half-edge `e` (a caller index).
    #[inline]
    pub fn halfedge_destination(&self, e: HalfEdge) -> u32 {
        self.input_index(self.dest(e))
    }

    /// The point coordinates of triangle `t`.
    #[inline]
    pub fn triangle_points(&self, t: TriangleId) -> [[f64; 2]; 3] {
        self.corners(t).map(|p| self.position(p))
    }
}
