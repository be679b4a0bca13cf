//! The compact, finished triangulation: flat arrays over local point indices, and the one
//! translation between those and the caller's indices.
//!
//! The divide and conquer puts the distinct points in Z order (duplicates merged into their
//! first occurrence); that order is also the one later passes want (neighbours close in
//! memory), so the topology stays in it: the *local* index of a point is its position in
//! that order. Everything inside the crate (the Voronoi dual, the water flow, extraction,
//! peeling, the baselines) works on local indices; every public method speaks the caller's
//! indices and translates at the boundary. Triangle and half-edge ids need no translation.

/// Marks a half-edge without a twin (a convex hull edge) in [`Triangulation::halfedges`].
pub const NO_TWIN: u32 = u32::MAX;

/// A finished Delaunay triangulation.
///
/// Half-edge `e` belongs to triangle `e / 3` and runs from `triangle(e / 3)[e % 3]` to
/// `triangle(e / 3)[(e % 3 + 1) % 3]`; its twin runs the other way in the neighbouring
/// triangle, or is [`NO_TWIN`] on the convex hull. Every point index taken or returned by a
/// public method is an index into the caller's slice; internally the points are stored
/// once each, in a locality order (see the module docs), and translated on the way out.
///
/// Memory: 20 bytes per distinct point (coordinates, caller index), 4 per input point (its
/// local index), 8 per duplicate, 24 per triangle (corners and twins), 4 per hull point.
#[derive(Debug, Clone)]
pub struct Triangulation {
    /// Coordinates of the distinct points, by local index.
    pub(crate) points: Vec<[f64; 2]>,
    /// Corners in local indices.
    pub(crate) triangles: Vec<[u32; 3]>,
    pub(crate) halfedges: Vec<u32>,
    /// The hull in local indices.
    pub(crate) hull: Vec<u32>,
    /// Local index → caller index (of the first occurrence).
    pub(crate) input_of: Vec<u32>,
    /// Caller index → local index (a duplicate maps to its kept point).
    pub(crate) local_of: Vec<u32>,
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
        self.points[self.local_of[i as usize] as usize]
    }

    /// Number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.triangles.len()
    }

    /// Corners of triangle `t`, counterclockwise, as caller indices.
    #[inline]
    pub fn triangle(&self, t: usize) -> [u32; 3] {
        self.triangles[t].map(|p| self.input_of[p as usize])
    }

    /// All triangles as counterclockwise triples of caller indices, by triangle id (a new
    /// `Vec`: see [`triangle`](Self::triangle) and [`triangle_count`](Self::triangle_count)
    /// to avoid the copy). Every distinct point is a corner of at least one triangle unless
    /// all points are collinear (then there are none).
    pub fn triangles(&self) -> Vec<[u32; 3]> {
        (0..self.triangles.len())
            .map(|t| self.triangle(t))
            .collect()
    }

    /// Twin of every half-edge (three per triangle, see the type docs), or [`NO_TWIN`].
    pub fn halfedges(&self) -> &[u32] {
        &self.halfedges
    }

    /// The convex hull as caller indices (a new `Vec`), counterclockwise from the
    /// lexicographically smallest point, listing every distinct point on its boundary
    /// (collinear ones included). For collinear input: the points in order along the line.
    pub fn hull(&self) -> Vec<u32> {
        self.to_input(&self.hull)
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
        self.input_of[self.local_of[i as usize] as usize] != i
    }

    /// Caller index of local point `p`.
    #[inline]
    pub(crate) fn input_index(&self, p: u32) -> u32 {
        self.input_of[p as usize]
    }

    /// Local index of caller point `i` (its kept point for a duplicate).
    #[inline]
    pub(crate) fn local_index(&self, i: u32) -> u32 {
        self.local_of[i as usize]
    }

    /// Local points to caller indices.
    pub(crate) fn to_input(&self, local: &[u32]) -> Vec<u32> {
        local.iter().map(|&p| self.input_index(p)).collect()
    }

    /// Local edges to caller indices, each `[min, max]`, sorted and deduplicated.
    pub(crate) fn to_input_edges(&self, mut edges: Vec<[u32; 2]>) -> Vec<[u32; 2]> {
        for edge in &mut edges {
            let [a, b] = edge.map(|p| self.input_index(p));
            *edge = [a.min(b), a.max(b)];
        }
        edges.sort_unstable();
        edges.dedup();
        edges
    }

    /// Local start point of half-edge `e`.
    #[inline]
    pub(crate) fn org(&self, e: usize) -> u32 {
        self.triangles[e / 3][e % 3]
    }

    /// Local end point of half-edge `e`.
    #[inline]
    pub(crate) fn dest(&self, e: usize) -> u32 {
        self.triangles[e / 3][next_in_triangle(e) % 3]
    }

    /// Start point of half-edge `e` (a caller index).
    #[inline]
    pub fn halfedge_origin(&self, e: usize) -> u32 {
        self.input_index(self.org(e))
    }

    /// End point of half-edge `e` (a caller index).
    #[inline]
    pub fn halfedge_destination(&self, e: usize) -> u32 {
        self.input_index(self.dest(e))
    }

    /// The point coordinates of triangle `t`.
    #[inline]
    pub fn triangle_points(&self, t: usize) -> [[f64; 2]; 3] {
        let [a, b, c] = self.triangles[t];
        [
            self.points[a as usize],
            self.points[b as usize],
            self.points[c as usize],
        ]
    }
}

/// The next half-edge counterclockwise inside the same triangle.
#[inline]
pub fn next_in_triangle(e: usize) -> usize {
    if e % 3 == 2 {
        e - 2
    } else {
        e + 1
    }
}

/// The previous half-edge counterclockwise inside the same triangle.
#[inline]
pub fn prev_in_triangle(e: usize) -> usize {
    if e % 3 == 0 {
        e + 2
    } else {
        e - 1
    }
}
