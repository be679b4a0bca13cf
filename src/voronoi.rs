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

use crate::delaunay::{Triangulation, NO_TWIN};
use crate::predicates::exact::{circumcenter, circumcenter_exact, ExactPoint};
use crate::predicates::{incircle, CirclePosition};
use num_rational::BigRational;

/// The far end of a Voronoi edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EdgeEnd {
    /// A finite Voronoi vertex.
    Vertex(u32),
    /// Infinity: the edge is a ray (its dual is a convex hull edge).
    Infinity,
}

/// A Voronoi edge seen from one of its finite ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct VoronoiEdge {
    /// The dual Delaunay half-edge, on the boundary of `from`'s face.
    pub halfedge: u32,
    /// The vertex the edge is seen from.
    pub from: u32,
    /// The other end.
    pub to: EdgeEnd,
    /// The two points whose cells the edge separates: origin and destination of `halfedge`.
    /// The cell of `sites[0]` lies to the left of the edge when walking from `from` to `to`.
    pub sites: [u32; 2],
}

/// The Voronoi diagram of the distinct points of a triangulation.
#[derive(Debug, Clone)]
pub struct Voronoi<'a> {
    tri: &'a Triangulation,
    vertex_of_triangle: Vec<u32>,
    /// `boundary[boundary_start[v]..boundary_start[v + 1]]`: the half-edges around the merged
    /// face of vertex `v`, counterclockwise.
    boundary_start: Vec<u32>,
    boundary: Vec<u32>,
    circumcenters: Vec<[f64; 2]>,
    /// One half-edge out of every distinct point (the outgoing hull edge for hull points);
    /// `NO_TWIN` for duplicates and in degenerate input.
    out_halfedge: Vec<u32>,
}

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
    /// // Without the centre the square's four corners are cocircular: one vertex, four rays.
    /// let tri = wdm_crust::triangulate(&pts[..4])?;
    /// let vor = tri.voronoi();
    /// assert_eq!(vor.vertex_count(), 1);
    /// assert_eq!(vor.vertex_position(0), [1.0, 1.0]);
    /// assert_eq!(vor.rays().count(), 4);
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn voronoi(&self) -> Voronoi<'_> {
        Voronoi::new(self)
    }
}

impl<'a> Voronoi<'a> {
    fn new(tri: &'a Triangulation) -> Self {
        let vertex_of_triangle = merge_cocircular_triangles(tri);
        let vertex_count = vertex_of_triangle.iter().map(|&v| v + 1).max().unwrap_or(0) as usize;
        let (boundary_start, boundary) = face_boundaries(tri, &vertex_of_triangle, vertex_count);
        let mut circumcenters = vec![[0.0; 2]; vertex_count];
        for (v, c) in circumcenters.iter_mut().enumerate() {
            let e = boundary[boundary_start[v] as usize] as usize;
            let [a, b, c3] = tri.triangle_points(e / 3);
            // Delaunay triangles are never collinear; the fallback is unreachable.
            *c = circumcenter(a, b, c3).unwrap_or(a);
        }
        let mut out_halfedge = vec![NO_TWIN; tri.points().len()];
        for (e, &twin) in tri.halfedges().iter().enumerate() {
            let p = tri.halfedge_origin(e) as usize;
            if twin == NO_TWIN || out_halfedge[p] == NO_TWIN {
                out_halfedge[p] = e as u32;
            }
        }
        Voronoi {
            tri,
            vertex_of_triangle,
            boundary_start,
            boundary,
            circumcenters,
            out_halfedge,
        }
    }

    /// The triangulation this diagram is the dual of.
    pub fn triangulation(&self) -> &'a Triangulation {
        self.tri
    }

    /// Number of finite Voronoi vertices (merged Delaunay faces).
    pub fn vertex_count(&self) -> usize {
        self.circumcenters.len()
    }

    /// Circumcenters of all vertices, rounded to f64.
    pub fn vertex_positions(&self) -> &[[f64; 2]] {
        &self.circumcenters
    }

    /// Circumcenter of vertex `v`, rounded to f64.
    pub fn vertex_position(&self, v: u32) -> [f64; 2] {
        self.circumcenters[v as usize]
    }

    /// Circumcenter of vertex `v` as an exact rational point.
    pub fn vertex_exact(&self, v: u32) -> ExactPoint {
        let [a, b, c] = self.vertex_triangle(v);
        // Delaunay triangles are never collinear, so the circumcenter exists.
        circumcenter_exact(a, b, c).unwrap_or_else(|| ExactPoint {
            x: BigRational::from_float(a[0]).unwrap_or_default(),
            y: BigRational::from_float(a[1]).unwrap_or_default(),
        })
    }

    /// Three points of the face of `v` (a Delaunay triangle of it): the input the exact
    /// circumcenter predicates take.
    pub fn vertex_triangle(&self, v: u32) -> [[f64; 2]; 3] {
        let e = self.boundary[self.boundary_start[v as usize] as usize] as usize;
        self.tri.triangle_points(e / 3)
    }

    /// The Voronoi vertex of Delaunay triangle `t`.
    pub fn vertex_of_triangle(&self, t: usize) -> u32 {
        self.vertex_of_triangle[t]
    }

    /// The Voronoi vertex on the left of Delaunay half-edge `e` (the face containing it).
    pub fn vertex_of_halfedge(&self, e: u32) -> u32 {
        self.vertex_of_triangle[e as usize / 3]
    }

    fn boundary_of(&self, v: u32) -> &[u32] {
        let v = v as usize;
        &self.boundary[self.boundary_start[v] as usize..self.boundary_start[v + 1] as usize]
    }

    /// Number of Voronoi edges (finite and rays) at `v`: the corners of its merged face.
    pub fn degree(&self, v: u32) -> usize {
        self.boundary_of(v).len()
    }

    /// The points whose cells meet at `v` (the corners of its Delaunay face), counterclockwise.
    pub fn vertex_sites(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        self.boundary_of(v)
            .iter()
            .map(|&e| self.tri.halfedge_origin(e as usize))
    }

    /// The Voronoi edges at `v`, counterclockwise around its face.
    pub fn vertex_edges(&self, v: u32) -> impl Iterator<Item = VoronoiEdge> + '_ {
        self.boundary_of(v).iter().map(|&e| self.edge(e))
    }

    /// The Voronoi edge dual to the boundary half-edge `e`, seen from the face of `e`.
    pub fn edge(&self, e: u32) -> VoronoiEdge {
        let twin = self.tri.halfedges()[e as usize];
        VoronoiEdge {
            halfedge: e,
            from: self.vertex_of_halfedge(e),
            to: if twin == NO_TWIN {
                EdgeEnd::Infinity
            } else {
                EdgeEnd::Vertex(self.vertex_of_halfedge(twin))
            },
            sites: [
                self.tri.halfedge_origin(e as usize),
                self.tri.halfedge_destination(e as usize),
            ],
        }
    }

    /// True when the Delaunay half-edge `e` has a dual Voronoi edge (its two sides are in
    /// different merged faces, or it is on the hull).
    pub fn has_dual(&self, e: u32) -> bool {
        let twin = self.tri.halfedges()[e as usize];
        twin == NO_TWIN || self.vertex_of_halfedge(e) != self.vertex_of_halfedge(twin)
    }

    /// Does `v` carry at least one ray (is its face on the convex hull)?
    pub fn has_ray(&self, v: u32) -> bool {
        self.boundary_of(v)
            .iter()
            .any(|&e| self.tri.halfedges()[e as usize] == NO_TWIN)
    }

    /// Finite Voronoi edges, each once: `(dual half-edge, vertex, vertex)`.
    pub fn finite_edges(&self) -> impl Iterator<Item = (u32, u32, u32)> + '_ {
        self.boundary.iter().filter_map(move |&e| {
            let twin = self.tri.halfedges()[e as usize];
            (twin != NO_TWIN && e < twin)
                .then(|| (e, self.vertex_of_halfedge(e), self.vertex_of_halfedge(twin)))
        })
    }

    /// Rays: `(dual hull half-edge, vertex, outward direction)`. The direction is the
    /// outward normal of the hull edge, `(b − a)` turned clockwise, rounded to f64.
    pub fn rays(&self) -> impl Iterator<Item = (u32, u32, [f64; 2])> + '_ {
        self.boundary
            .iter()
            .filter(move |&&e| self.tri.halfedges()[e as usize] == NO_TWIN)
            .map(move |&e| (e, self.vertex_of_halfedge(e), self.ray_direction(e)))
    }

    /// Outward normal of the hull half-edge `e` (interior on its left).
    pub fn ray_direction(&self, e: u32) -> [f64; 2] {
        let a = self.tri.points()[self.tri.halfedge_origin(e as usize) as usize];
        let b = self.tri.points()[self.tri.halfedge_destination(e as usize) as usize];
        [b[1] - a[1], a[0] - b[0]]
    }

    /// Is the cell of point `p` bounded (is `p` strictly inside the convex hull)?
    /// False for hull points, duplicates and degenerate input.
    pub fn is_cell_bounded(&self, p: u32) -> bool {
        let e = self.out_halfedge[p as usize];
        e != NO_TWIN && self.tri.halfedges()[e as usize] != NO_TWIN
    }

    /// The vertices of the cell of point `p`, counterclockwise. For a hull point the cell
    /// is open: it starts at the vertex carrying the ray of the outgoing hull edge and ends at
    /// the one carrying the ray of the incoming hull edge. Empty for a duplicate (its cell is
    /// its original's: ask for that one) and for degenerate input.
    pub fn cell(&self, p: u32) -> CellVertices<'_, 'a> {
        let start = self.out_halfedge[p as usize];
        let mut first = start;
        if start != NO_TWIN && self.tri.halfedges()[start as usize] != NO_TWIN {
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

    /// The half-edge out of the same point, one triangle counterclockwise; `None` past the hull.
    fn rotate_counterclockwise(&self, e: u32) -> Option<u32> {
        let incoming = crate::delaunay::prev_in_triangle(e as usize);
        let twin = self.tri.halfedges()[incoming];
        (twin != NO_TWIN).then_some(twin)
    }

    /// The half-edge out of the same point, one triangle clockwise; `None` past the hull.
    fn rotate_clockwise(&self, e: u32) -> Option<u32> {
        let twin = self.tri.halfedges()[e as usize];
        (twin != NO_TWIN).then(|| crate::delaunay::next_in_triangle(twin as usize) as u32)
    }

    /// Pairs of consecutive points along the line when the input is collinear: the diagram is
    /// their perpendicular bisectors. Empty otherwise.
    pub fn collinear_bisectors(&self) -> Vec<[u32; 2]> {
        if self.tri.is_degenerate() {
            self.tri.hull().windows(2).map(|w| [w[0], w[1]]).collect()
        } else {
            Vec::new()
        }
    }
}

/// Iterator over the vertices of one Voronoi cell, counterclockwise.
#[derive(Debug, Clone)]
pub struct CellVertices<'v, 'a> {
    voronoi: &'v Voronoi<'a>,
    first: u32,
    next: Option<u32>,
    last_vertex: Option<u32>,
}

impl Iterator for CellVertices<'_, '_> {
    type Item = u32;

    fn next(&mut self) -> Option<u32> {
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

/// Union–find over triangles: neighbours that share their circumcircle exactly end up in one
/// set. Returns the vertex id of every triangle, numbered by first appearance.
fn merge_cocircular_triangles(tri: &Triangulation) -> Vec<u32> {
    let t = tri.triangles().len();
    let mut parent: Vec<u32> = (0..t as u32).collect();
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            let up = parent[parent[x as usize] as usize];
            parent[x as usize] = up; // path halving
            x = up;
        }
        x
    }
    for (e, &twin) in tri.halfedges().iter().enumerate() {
        if twin == NO_TWIN || (twin as usize) < e {
            continue;
        }
        let [a, b, c] = tri.triangle_points(e / 3);
        let opposite = tri.points()
            [tri.halfedge_origin(crate::delaunay::prev_in_triangle(twin as usize)) as usize];
        if incircle(a, b, c, opposite) == CirclePosition::On {
            let (ra, rb) = (
                find(&mut parent, (e / 3) as u32),
                find(&mut parent, twin / 3),
            );
            if ra != rb {
                parent[ra.max(rb) as usize] = ra.min(rb);
            }
        }
    }
    let mut vertex = vec![u32::MAX; t];
    let mut count = 0u32;
    for i in 0..t {
        let root = find(&mut parent, i as u32) as usize;
        if vertex[root] == u32::MAX {
            vertex[root] = count;
            count += 1;
        }
        vertex[i] = vertex[root];
    }
    vertex
}

/// For every vertex, the half-edges on the boundary of its merged face, counterclockwise,
/// in compressed rows.
fn face_boundaries(
    tri: &Triangulation,
    vertex_of_triangle: &[u32],
    vertex_count: usize,
) -> (Vec<u32>, Vec<u32>) {
    let halfedges = tri.halfedges();
    let on_boundary = |e: usize| {
        let twin = halfedges[e];
        twin == NO_TWIN || vertex_of_triangle[twin as usize / 3] != vertex_of_triangle[e / 3]
    };
    let mut start = vec![0u32; vertex_count + 1];
    for e in (0..halfedges.len()).filter(|&e| on_boundary(e)) {
        start[vertex_of_triangle[e / 3] as usize + 1] += 1;
    }
    for v in 0..vertex_count {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut boundary = vec![0u32; start[vertex_count] as usize];
    for e in (0..halfedges.len()).filter(|&e| on_boundary(e)) {
        let v = vertex_of_triangle[e / 3] as usize;
        boundary[fill[v] as usize] = e as u32;
        fill[v] += 1;
    }
    // Single triangles are already in order (3t, 3t+1, 3t+2); merged faces are chained by
    // matching each half-edge's destination with the next one's origin.
    for v in 0..vertex_count {
        let row = &mut boundary[start[v] as usize..start[v + 1] as usize];
        if row.len() > 3 {
            order_face_cycle(tri, row);
        }
    }
    (start, boundary)
}

/// Reorders the boundary half-edges of one merged face into a counterclockwise cycle that
/// starts at the smallest half-edge id: the triangle arrays do not depend on the order of the
/// input points, so neither does the cycle (a start chosen by point index would).
fn order_face_cycle(tri: &Triangulation, row: &mut [u32]) {
    let mut by_origin: Vec<(u32, u32)> = row
        .iter()
        .map(|&e| (tri.halfedge_origin(e as usize), e))
        .collect();
    by_origin.sort_unstable();
    let Some(mut e) = row.iter().copied().min() else {
        return;
    };
    for slot in row.iter_mut() {
        *slot = e;
        let dest = tri.halfedge_destination(e as usize);
        if let Ok(i) = by_origin.binary_search_by_key(&dest, |&(o, _)| o) {
            e = by_origin[i].1;
        }
    }
}
