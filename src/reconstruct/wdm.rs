//! WDM labeling (Section 3 of the paper, made precise in ARCHITECTURE.md, "The water flow").
//!
//! Water is pumped in from the root vertex at infinity. The finite vertices carrying a ray
//! (FVVs) outside the convex hull are the inlets, largest circumradius first. From each inlet
//! the water runs depth first along finite Voronoi edges through ACTIVATED vertices. The first
//! vertex to bring water to a bounded cell becomes its source `B_p`; the state transition of
//! Definition 3 then DEACTIVATES every vertex of that cell strictly beyond the line `L`
//! through `p` orthogonal to `B_p − p`. All geometric decisions are exact.

use std::cmp::Ordering;

use crate::ids::{LocalPoint, VertexId};
use crate::kernel::{compare_radius_rounded, dot_sign_rounded};
use crate::parallel;
use crate::predicates::{
    circumcenter_in_convex_hull, compare_circumradius, dot_sign_circumcenters, HullPosition, Sign,
};
use crate::voronoi::{EdgeEnd, Voronoi};

/// Inside or outside the curve, for a Voronoi vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "lowercase"))]
pub enum Label {
    /// Inside the reconstructed curve: a medial-axis vertex.
    Inner,
    /// Outside the curve.
    Outer,
}

/// How water-flow states become inner/outer labels. The paper is ambiguous here; the
/// default is the one ARCHITECTURE.md argues for, the others are kept so tests can compare.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[non_exhaustive]
pub enum LabelRule {
    /// Outer = reached by the water and still ACTIVATED; inner = everything else.
    #[default]
    WaterReached,
    /// The paper's literal reading: outer = ACTIVATED, whether the water came or not.
    Literal,
    /// The authors' C++ convention: everything starts inner; the vertices of a cell strictly
    /// on its source's side of `L` become outer, and water moves only through outer vertices.
    Complement,
}

/// The water-flow state of every Voronoi vertex after labeling.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub struct WaterFlow {
    /// Label of every finite Voronoi vertex.
    pub labels: Vec<Label>,
    /// Source vertex `B_p` of every point whose cell is bounded and received water.
    pub sources: Vec<Option<VertexId>>,
    /// Vertices the water reached.
    pub visited: Vec<bool>,
}

/// Runs the water flow on `vor` and labels every vertex.
pub fn label_vertices(vor: &Voronoi<'_>, rule: LabelRule) -> WaterFlow {
    let flow = flow(vor, rule);
    let tri = vor.triangulation();
    let sources = (0..tri.point_count() as u32)
        .map(|i| {
            let local = flow.sources[tri.local_index(i).index()];
            (local != NO_SOURCE && !tri.is_duplicate(i)).then_some(local)
        })
        .collect();
    WaterFlow {
        labels: flow.labels(rule),
        sources,
        visited: flow.state.iter().map(|&s| s & VISITED != 0).collect(),
    }
}

/// The labels of [`label_vertices`], without the sources and visits.
pub(crate) fn labels(vor: &Voronoi<'_>, rule: LabelRule) -> Vec<Label> {
    flow(vor, rule).labels(rule)
}

/// A vertex's water-flow state, as bits of one byte: the walk tests both for every neighbour
/// it might push, and one array is one cache miss where two arrays of flags were two.
const ACTIVATED: u8 = 1;
const VISITED: u8 = 2;

/// No source (yet): the point's cell is unbounded, or no water reached it.
const NO_SOURCE: VertexId = VertexId::new(u32::MAX);

/// The state of every vertex and the source of every (local) point after the water flow.
struct Flow {
    state: Vec<u8>,
    sources: Vec<VertexId>,
}

impl Flow {
    fn labels(&self, rule: LabelRule) -> Vec<Label> {
        let outer = |state: u8| match rule {
            LabelRule::WaterReached => state == ACTIVATED | VISITED,
            LabelRule::Literal | LabelRule::Complement => state & ACTIVATED != 0,
        };
        parallel::map_range(self.state.len(), |v| {
            if outer(self.state[v]) {
                Label::Outer
            } else {
                Label::Inner
            }
        })
    }
}

/// The water flow of the module docs on `vor`, sources indexed by local point.
fn flow(vor: &Voronoi<'_>, rule: LabelRule) -> Flow {
    let tri = vor.triangulation();
    let complement = rule == LabelRule::Complement;
    // In the complement convention "activated" means "marked outer": all start unmarked.
    let mut state = vec![if complement { 0 } else { ACTIVATED }; vor.vertex_count()];
    let mut sources = vec![NO_SOURCE; tri.points.len()];
    // Every vertex of a watered cell is tested against the cell's source: round each
    // circumcenter once (kept in the diagram for the medial axis and the output).
    let positions = vor.vertex_positions();

    for inlet in inlets(vor, positions, &mut state, complement) {
        if complement {
            state[inlet.index()] |= ACTIVATED;
        }
        // Activated and not visited: the only state water enters.
        if state[inlet.index()] != ACTIVATED {
            continue;
        }
        let mut stack = vec![inlet];
        while let Some(v) = stack.pop() {
            // The state is checked when a vertex is taken, not when it was pushed: a vertex
            // deactivated meanwhile blocks the water.
            if state[v.index()] != ACTIVATED {
                continue;
            }
            state[v.index()] |= VISITED;
            for p in vor.face_corners(v) {
                // The source first: most sites have one already, and it is the cheaper test.
                if sources[p.index()] == NO_SOURCE && vor.is_interior(p) {
                    sources[p.index()] = v;
                    transition(vor, positions, p, v, &mut state, complement);
                }
            }
            // Pushed in reverse so the neighbours are taken counterclockwise.
            let before = stack.len();
            for edge in vor.face_edges(v) {
                if let EdgeEnd::Vertex(u) = edge.to {
                    if state[u.index()] == ACTIVATED {
                        stack.push(u);
                    }
                }
            }
            stack[before..].reverse();
        }
    }
    Flow { state, sources }
}

/// The list L_F: vertices carrying a ray, strictly outside the convex hull, sorted by
/// circumradius (largest first; ties by the lexicographically smallest site, which does not
/// depend on the input order). FVVs inside the closed hull are deactivated.
fn inlets(
    vor: &Voronoi<'_>,
    positions: &[[f64; 2]],
    state: &mut [u8],
    complement: bool,
) -> Vec<VertexId> {
    let tri = vor.triangulation();
    let hull: Vec<[f64; 2]> = tri.hull.iter().map(|&p| tri.position(p)).collect();
    // Every vertex with a ray, and for those outside the hull their smallest site. On all
    // threads: each hull test is a binary search of the hull, and samples of a curve can
    // put a sixth of their points on the hull (half of the labels' time at 10^7 such
    // points, on one thread, was here). The workers return one flag per ray vertex, and the
    // smallest sites are read here: a record per ray vertex (24 bytes per hull point, 4 per
    // point on such samples) collected from the workers stayed in their allocators.
    let rays = vor.ray_vertices();
    let outside: Vec<bool> = parallel::map_range(rays.len(), |i| {
        circumcenter_in_convex_hull(&hull, vor.vertex_triangle(rays[i])) == HullPosition::Outside
    });
    let mut list: Vec<(VertexId, [f64; 2])> = Vec::new();
    for (&v, outside) in rays.iter().zip(outside) {
        if outside {
            let smallest_site = vor
                .face_corners(v)
                .map(|p| tri.position(p))
                .min_by(|a, b| lexicographic(*a, *b))
                .unwrap_or([0.0; 2]);
            list.push((v, smallest_site));
        } else if !complement {
            state[v.index()] &= !ACTIVATED;
        }
    }
    // Largest circumradius first: decided on the rounded circumcenters where their bound
    // allows, exactly otherwise (the same total order either way).
    let radius_order = |a: VertexId, b: VertexId| {
        let (ta, tb) = (vor.vertex_triangle(a), vor.vertex_triangle(b));
        match compare_radius_rounded(positions[b.index()], tb[0], positions[a.index()], ta[0]) {
            Some(sign) => sign.into(),
            None => compare_circumradius(tb, ta),
        }
    };
    list.sort_by(|&(a, sa), &(b, sb)| radius_order(a, b).then_with(|| lexicographic(sa, sb)));
    list.into_iter().map(|(v, _)| v).collect()
}

fn lexicographic(a: [f64; 2], b: [f64; 2]) -> Ordering {
    a[0].partial_cmp(&b[0])
        .unwrap_or(Ordering::Equal)
        .then(a[1].partial_cmp(&b[1]).unwrap_or(Ordering::Equal))
}

/// Definition 3 on the cell of `p` with source `source`: vertices strictly on the other side
/// of `L` are deactivated (or, in the complement convention, vertices strictly on the
/// source's side are marked outer).
///
/// The test is decided on the rounded circumcenters where their error bound allows (nearly
/// always), and by the exact predicate on the triangles otherwise.
fn transition(
    vor: &Voronoi<'_>,
    positions: &[[f64; 2]],
    p: LocalPoint,
    source: VertexId,
    state: &mut [u8],
    complement: bool,
) {
    let point = vor.triangulation().position(p);
    let source_position = positions[source.index()];
    for v in vor.cell_vertices(p) {
        if v == source {
            continue;
        }
        let side =
            dot_sign_rounded(point, source_position, positions[v.index()]).unwrap_or_else(|| {
                dot_sign_circumcenters(point, vor.vertex_triangle(source), vor.vertex_triangle(v))
            });
        if complement {
            if side == Sign::Positive {
                state[v.index()] |= ACTIVATED;
            }
        } else if side == Sign::Negative {
            state[v.index()] &= !ACTIVATED;
        }
    }
}
