//! The compact, finished triangulation: flat arrays over the caller's point indices.

/// Marks a half-edge without a twin (a convex hull edge) in [`Triangulation::halfedges`].
pub const NO_TWIN: u32 = u32::MAX;

/// A finished Delaunay triangulation.
///
/// Half-edge `e` belongs to triangle `e / 3` and runs from `triangles()[e / 3][e % 3]` to
/// `triangles()[e / 3][(e % 3 + 1) % 3]`; its twin runs the other way in the neighbouring
/// triangle, or is [`NO_TWIN`] on the convex hull. All indices refer to the caller's slice.
#[derive(Debug, Clone)]
pub struct Triangulation {
    pub(crate) points: Vec<[f64; 2]>,
    pub(crate) triangles: Vec<[u32; 3]>,
    pub(crate) halfedges: Vec<u32>,
    pub(crate) hull: Vec<u32>,
    /// `[duplicate, kept]`, sorted by duplicate.
    pub(crate) duplicates: Vec<[u32; 2]>,
}

impl Triangulation {
    /// The caller's points, duplicates included.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// Triangles as counterclockwise index triples. Every distinct point is a corner of at
    /// least one triangle unless all points are collinear (then there are none).
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Twin of every half-edge (three per triangle, see the type docs), or [`NO_TWIN`].
    pub fn halfedges(&self) -> &[u32] {
        &self.halfedges
    }

    /// The convex hull, counterclockwise, listing every distinct point on its boundary
    /// (collinear ones included). For collinear input: the points in order along the line.
    pub fn hull(&self) -> &[u32] {
        &self.hull
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
        self.points.len() - self.duplicates.len()
    }

    /// Start point of half-edge `e`.
    #[inline]
    pub fn halfedge_origin(&self, e: usize) -> u32 {
        self.triangles[e / 3][e % 3]
    }

    /// End point of half-edge `e`.
    #[inline]
    pub fn halfedge_destination(&self, e: usize) -> u32 {
        self.triangles[e / 3][next_in_triangle(e) % 3]
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
