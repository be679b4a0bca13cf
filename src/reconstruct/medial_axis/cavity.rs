//! The region's triangles when points off the loops lie inside it, without a second
//! triangulation of all the loop points.
//!
//! The pruned axis is read off the Delaunay triangulation of the loops' points alone
//! (the subset). A triangle of all the points that has no off-loop point as a corner keeps
//! its empty circle when points are taken away, so it is a triangle of the subset too; the
//! only triangles that change are those around the off-loop points. Inside the region those
//! form the *cavity*: the triangles with an off-loop point inside the region as a corner
//! (all of them inside, as no loop edge ends at such a point). The subset's triangles that
//! fill it have their corners on the cavity's boundary, and their empty circles hold none of
//! those boundary points, so they are triangles of the Delaunay triangulation of the boundary
//! points alone: the cavity is refilled by triangulating a few points per off-loop point
//! instead of all of the loops' points (on 10⁶ noisy points, a handful of points instead of
//! a second full triangulation and its diagram: a third of the pruned axis's time).
//!
//! Which triangles of the boundary points fill the cavity is decided combinatorially: the
//! cavity's boundary edges are edges of both triangulations, and the cavity is what is
//! reached from their inner side without crossing one of them.
//!
//! Exactly cocircular points make the Delaunay triangulation non-unique and merge faces of
//! the diagram; where that touches the cavity (a merged face with an off-loop point, or a new
//! triangle cocircular with a neighbour, decided by the exact in-circle test) the caller
//! takes the second triangulation instead, as it also does when a count does not add up.

use std::collections::{HashMap, HashSet};

use crate::delaunay::{triangulate, HalfEdge, NO_TWIN};
use crate::ids::{LocalPoint, VertexId};
use crate::predicates::{incircle, CirclePosition};
use crate::voronoi::Voronoi;

/// The new triangles of a cavity and how they join each other and the rest of the region.
pub(super) struct Cavity {
    /// The faces of the diagram of all the points that the cavity replaces.
    pub(super) replaced: Vec<VertexId>,
    /// The new triangles, corners as local points of the diagram, counterclockwise.
    pub(super) triangles: Vec<[LocalPoint; 3]>,
    /// Pairs of new triangles sharing an edge, each pair once.
    pub(super) shared: Vec<[u32; 2]>,
    /// `(new triangle, e)`: a cavity boundary edge, `e` its half-edge in the diagram's
    /// triangulation on the cavity's side (so its twin lies on a face that stays).
    pub(super) boundary: Vec<(u32, HalfEdge)>,
}

impl Cavity {
    /// The cavity of the off-loop points `inside` (local points of `vor`, every one inside
    /// the region), or `None` where the diagram alone cannot decide it (see the module docs).
    pub(super) fn around(vor: &Voronoi<'_>, inside: &[LocalPoint]) -> Option<Cavity> {
        let tri = vor.triangulation();
        let halfedges = tri.halfedges();
        let mut replaced = Vec::new();
        let mut is_replaced = HashSet::new();
        for &p in inside {
            for v in vor.cell_vertices(p) {
                if vor.degree(v) != 3 {
                    return None;
                }
                if is_replaced.insert(v) {
                    replaced.push(v);
                }
            }
        }
        // The boundary: half-edges of replaced triangles whose twin is not replaced, with
        // the cavity on their left; keyed by their ends for the search in the new triangles.
        let mut boundary_of: HashMap<[LocalPoint; 2], usize> = HashMap::new();
        let mut boundary_halfedges = Vec::new();
        let mut corners = Vec::new();
        for &v in &replaced {
            for e in vor.vertex_triangle_id(v).halfedges() {
                // A hull edge (a loop edge: the face is inside) bounds the cavity too.
                let twin = halfedges[e.index()];
                if twin != NO_TWIN && is_replaced.contains(&vor.vertex_of_halfedge(twin)) {
                    continue;
                }
                let ends = [tri.org(e), tri.dest(e)];
                boundary_of.insert(ends, boundary_halfedges.len());
                boundary_halfedges.push(e);
                corners.extend(ends);
            }
        }
        corners.sort_unstable();
        corners.dedup();
        let sub =
            triangulate(&corners.iter().map(|&p| tri.position(p)).collect::<Vec<_>>()).ok()?;
        // Local points of the boundary triangulation to local points of the diagram.
        let point = |q: LocalPoint| corners[sub.input_index(q) as usize];
        let sub_halfedges = sub.halfedges();
        let mut boundary_at = vec![u32::MAX; sub_halfedges.len()];
        let mut found = 0;
        for (h, at) in sub.halfedge_ids().zip(&mut boundary_at) {
            let ends = [point(sub.org(h)), point(sub.dest(h))];
            if let Some(&i) = boundary_of.get(&ends) {
                *at = i as u32;
                found += 1;
            }
        }
        if found != boundary_halfedges.len() {
            return None;
        }
        // The new triangles: reached from the boundary's inner side, never across it.
        let mut number = vec![u32::MAX; sub.triangle_count()];
        let mut order = Vec::new();
        let mut stack: Vec<_> = (sub.halfedge_ids())
            .filter(|&h| boundary_at[h.index()] != u32::MAX)
            .map(HalfEdge::triangle)
            .collect();
        stack.reverse();
        while let Some(t) = stack.pop() {
            if number[t.index()] != u32::MAX {
                continue;
            }
            number[t.index()] = order.len() as u32;
            order.push(t);
            for h in t.halfedges() {
                if boundary_at[h.index()] != u32::MAX {
                    continue;
                }
                let twin = sub.twin(h)?;
                stack.push(twin.triangle());
            }
        }
        // Each off-loop point taken out of a triangulated disk takes two triangles with it.
        if order.len() + 2 * inside.len() != replaced.len() {
            return None;
        }
        let triangles: Vec<[LocalPoint; 3]> =
            order.iter().map(|&t| sub.corners(t).map(point)).collect();
        let mut shared = Vec::new();
        let mut boundary = Vec::new();
        for (k, &t) in order.iter().enumerate() {
            let corner = |q: LocalPoint| tri.position(q);
            let [a, b, c] = triangles[k].map(corner);
            for h in t.halfedges() {
                let apex_of = |twin: HalfEdge| twin.prev();
                let (apex, neighbour) = if boundary_at[h.index()] != u32::MAX {
                    let e = boundary_halfedges[boundary_at[h.index()] as usize];
                    boundary.push((k as u32, e));
                    let apex = tri.twin(e).map(|twin| tri.org(apex_of(twin)));
                    (apex, None)
                } else {
                    let twin = sub_halfedges[h.index()];
                    (
                        Some(point(sub.org(apex_of(twin)))),
                        Some(number[twin.triangle().index()]),
                    )
                };
                // Cocircular with a neighbour: the faces would merge (module docs).
                if apex.is_some_and(|q| incircle(a, b, c, corner(q)) == CirclePosition::On) {
                    return None;
                }
                if let Some(other) = neighbour.filter(|&other| other > k as u32) {
                    shared.push([k as u32, other]);
                }
            }
        }
        Some(Cavity {
            replaced,
            triangles,
            shared,
            boundary,
        })
    }
}
