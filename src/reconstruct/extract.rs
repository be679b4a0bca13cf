//! Reading the WDM result off the labelled Voronoi diagram: the crust (Delaunay edges dual
//! to inner–outer Voronoi edges) and the medial axis (inner–inner Voronoi edges).

use super::frame::Frame;
use super::result::MedialAxis;
use super::wdm::Label;
use crate::delaunay::{Triangulation, NO_TWIN};
use crate::ids::{HalfEdge, LocalPoint, TriangleId, VertexId};
use crate::parallel;
use crate::voronoi::{EdgeEnd, Voronoi};

/// The class of a Voronoi edge by the labels of its ends (Section 3.3 of the paper).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EdgeClass {
    /// Both ends outer: a pipe the water runs through.
    Carrier,
    /// One end inner, one outer: its dual Delaunay edge is a crust edge.
    Branch,
    /// Both ends inner: a medial-axis edge.
    Neutral,
}

impl EdgeClass {
    /// The class of an edge whose ends carry labels `a` and `b`.
    pub fn of(a: Label, b: Label) -> EdgeClass {
        match (a, b) {
            (Label::Outer, Label::Outer) => EdgeClass::Carrier,
            (Label::Inner, Label::Inner) => EdgeClass::Neutral,
            _ => EdgeClass::Branch,
        }
    }
}

/// Delaunay edges dual to branch edges, each once, unsorted, in local indices. A ray's far end is the root
/// vertex, always outer.
pub(super) fn wdm_crust_edges(vor: &Voronoi<'_>, labels: &[Label]) -> Vec<[LocalPoint; 2]> {
    if vor.has_merged_faces() {
        crust_edges_of_faces(vor, labels)
    } else {
        crust_edges_of_triangles(vor.triangulation(), labels)
    }
}

/// [`wdm_crust_edges`] on any diagram, merged faces included.
fn crust_edges_of_faces(vor: &Voronoi<'_>, labels: &[Label]) -> Vec<[LocalPoint; 2]> {
    // Reserved on this thread: 8 bytes a point, at the memory peak's scale. At most three
    // edges a vertex but at merged faces.
    parallel::flat_map_chunks_reserved(vor.vertex_count(), 3, |vertices, edges| {
        for v in vertices {
            let v = VertexId::new(v as u32);
            for edge in vor.face_edges(v) {
                let far = match edge.to {
                    EdgeEnd::Vertex(u) if u < v => continue, // each finite edge once
                    EdgeEnd::Vertex(u) => labels[u.index()],
                    EdgeEnd::Infinity => Label::Outer,
                };
                if EdgeClass::of(labels[v.index()], far) == EdgeClass::Branch {
                    let [a, b] = edge.sites;
                    edges.push([a.min(b), a.max(b)]);
                }
            }
        }
    })
}

/// [`wdm_crust_edges`] of a diagram without merged faces, the same edges in the same order:
/// vertex `t` is triangle `t`, its edges are the half-edges `3t..3t + 3`, the far end of one
/// is its twin's triangle. Read straight off the triangle store: the face iterator of the
/// general form cost 23 ns a vertex at 10^7 points (one thread), most of the extraction.
fn crust_edges_of_triangles(tri: &Triangulation, labels: &[Label]) -> Vec<[LocalPoint; 2]> {
    let halfedges = tri.halfedges();
    parallel::flat_map_chunks_reserved(labels.len(), 3, |triangles, edges| {
        for t in triangles {
            let own = labels[t];
            let t = TriangleId::new(t as u32);
            for e in t.halfedges() {
                let twin = halfedges[e.index()];
                let far = if twin == NO_TWIN {
                    Label::Outer
                } else if twin.triangle() < t {
                    continue; // each finite edge once, from its smaller triangle
                } else {
                    labels[twin.triangle().index()]
                };
                if own != far {
                    let (a, b) = (tri.org(e), tri.dest(e));
                    edges.push([a.min(b), a.max(b)]);
                }
            }
        }
    })
}

/// Finite Voronoi edges with both ends inner, with the used vertices renumbered; `vor` is
/// in `frame`, the vertices come out in the caller's coordinates.
///
/// A Voronoi edge whose dual is in `later_pass_crust` (sorted, local indices) is left out:
/// the axis never crosses a curve. (First-pass crust edges are inner–outer, never on the
/// axis; the curves peeling adds, such as the gills of a mushroom inside its cap, cut
/// through what the first pass called inside.)
pub(super) fn medial_axis(
    vor: &Voronoi<'_>,
    labels: &[Label],
    later_pass_crust: &[[LocalPoint; 2]],
    frame: Frame,
) -> MedialAxis {
    let tri = vor.triangulation();
    let mut index = vec![u32::MAX; vor.vertex_count()];
    let mut axis = MedialAxis::default();
    let mut renumber = |v: VertexId, axis: &mut MedialAxis| {
        if index[v.index()] == u32::MAX {
            index[v.index()] = axis.vertices.len() as u32;
            let centre = vor.vertex_position(v);
            let centre = frame.circumcenter_to_caller(centre, || vor.canonical_triangle(v));
            axis.vertices.push(centre);
        }
        index[v.index()]
    };
    let crosses_a_curve = |e: HalfEdge| {
        let (p, q) = (tri.org(e), tri.dest(e));
        !later_pass_crust.is_empty()
            && later_pass_crust
                .binary_search(&[p.min(q), p.max(q)])
                .is_ok()
    };
    for (e, a, b) in vor.finite_edges() {
        if labels[a.index()] == Label::Inner
            && labels[b.index()] == Label::Inner
            && !crosses_a_curve(e)
        {
            let (ia, ib) = (renumber(a, &mut axis), renumber(b, &mut axis));
            axis.edges.push([ia.min(ib), ia.max(ib)]);
        }
    }
    parallel::sort_unstable(&mut axis.edges);
    axis
}

#[cfg(test)]
mod tests {
    use super::*;
    use wdm_crust_testkit::Rng;

    /// The triangle store's reading gives the face iterator's edges in its order, on random
    /// points (no merged faces) with random labels and with the water flow's.
    #[test]
    fn the_triangles_give_the_faces_crust_edges() {
        let mut rng = Rng::new(5);
        for round in 0..40 {
            let n = 3 + rng.below(3000);
            let points: Vec<[f64; 2]> = (0..n).map(|_| [rng.f64(), rng.f64()]).collect();
            let tri = crate::triangulate(&points).unwrap();
            let vor = tri.voronoi();
            assert!(!vor.has_merged_faces(), "round {round}");
            let flow = crate::reconstruct::wdm::labels(&vor, Default::default());
            let random: Vec<Label> = vor
                .vertex_ids()
                .map(|_| {
                    if rng.f64() < 0.5 {
                        Label::Inner
                    } else {
                        Label::Outer
                    }
                })
                .collect();
            for labels in [&flow, &random] {
                let by_faces = crust_edges_of_faces(&vor, labels);
                assert!(!by_faces.is_empty(), "round {round}");
                assert_eq!(
                    crust_edges_of_triangles(&tri, labels),
                    by_faces,
                    "round {round}"
                );
            }
        }
    }
}
