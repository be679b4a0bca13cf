//! Ears: a small loop of the crust hanging off a curve at one point. Repaired on the labels,
//! before the curves are assembled (all indices local to the triangulation at hand).
//!
//! On noisy samples the water flow sometimes leaves a lone Delaunay face just outside the
//! curve inner: a curve sample `p` and two points of the noise band whose circumcenter a
//! state transition deactivated. Its three edges are then crust edges, `p` has degree 4, and
//! the curve through `p` falls apart into open chains. Of 100 trials per noise level and shape
//! (0.5 / 0.7 / 1 sample spacing, `examples/noise_failures.rs`), 25 of the 29 failures in the
//! first pass were such ears (a triangle in 21), and most holes lost at 1 spacing were lost
//! the same way: the hole's own pass grew an ear. A polygon sampled at ε = 0.6 shows them
//! too, at a sharp corner, with true samples in the ear.
//!
//! The rule works on the labels, so that labels, crust and medial axis stay one reading. An
//! *inner component* is a connected set of inner Voronoi vertices (joined by finite Voronoi
//! edges), its *boundary points* the sites of the crust edges dual to its inner–outer edges.
//! An **ear** is an inner component with fewer than [`MIN_LOOP_POINTS`] boundary points that
//! meets a component with at least as many at a point `p` (crust degree 4 or more), and
//! touches the rest of the crust nowhere else (its other boundary points have degree 2). Fewer
//! than 7 points: a closed curve turns by 2π and an ε-sample of it by about ε per point, so
//! such a loop is no ε-sample of a closed curve for any ε < 1 (the bound peeling uses for its
//! loops); a region between crossing strokes of a drawing has junctions all around and is no
//! ear. An ear is then
//! * **rejoined** (first pass, [`Ears::Rejoin`]) when a single outer vertex `o` of `p`'s cell,
//!   a triangle whose third neighbour is outer, separates it from the large component: `o`
//!   becomes inner, `p` keeps two edges and the triangle's far edge joins the ear's loop to
//!   the curve, which keeps every point (a sharp corner keeps its tip). Of two such vertices
//!   the one with the smaller circumcircle (the narrower gap; compared exactly);
//! * otherwise **dropped**: relabelled outer, its edges go and its other points are left
//!   without edges (unassigned, or leftovers for peeling).
//!
//! Every decision is combinatorial on the exact labels (and one exact circumradius
//! comparison), taken on the labels as the water flow left them, so neither the order of the
//! points nor that of the pinch points matters. A well-formed reconstruction has no point of
//! degree 4: clean samples never reach the rule.
//!
//! An **islet** ([`drop_islets`], first pass) is the same small loop standing alone in the
//! noise band of a curve instead of hanging off it: dropped.

use crate::ids::{ids, LocalPoint, VertexId};
use std::cmp::Ordering;
use std::collections::HashMap;

use super::shared::{degrees, edges_near, lies_apart, median_length};
use crate::delaunay::NO_TWIN;
use crate::predicates::compare_circumradius;
use crate::reconstruct::thresholds::peel::MIN_LOOP_POINTS;
use crate::reconstruct::wdm::Label;
use crate::voronoi::{EdgeEnd, Voronoi};

/// What to do with an ear that a single outer vertex separates from the curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Ears {
    /// Join it to the curve through that vertex (drop it when there is none).
    Rejoin,
    /// Drop it always.
    Drop,
}

/// No component found yet (in `component_of`).
const UNKNOWN: u32 = u32::MAX;

/// The root vertex at infinity, closing the open cell of a hull point.
const ROOT: u32 = u32::MAX;

/// No pinch point (in `ear_at`): the component is no ear.
const NO_PINCH: LocalPoint = LocalPoint::new(u32::MAX);

/// Repairs the ears of `labels` (see the module docs) and updates `edges`, the crust of
/// `labels` (`[min, max]`, any order; the order of the edges kept is kept, new ones come at
/// the end). Returns the number of vertices relabelled.
pub(crate) fn repair_ears(
    vor: &Voronoi<'_>,
    labels: &mut [Label],
    edges: &mut Vec<[LocalPoint; 2]>,
    mode: Ears,
) -> usize {
    let degree = degrees(vor.triangulation().points.len(), edges);
    let pinches: Vec<LocalPoint> = ids::<LocalPoint>(degree.len())
        .filter(|&p| degree[p.index()] >= 4)
        .collect();
    if pinches.is_empty() {
        return 0;
    }
    let mut search = Components::default();
    // The pinch point of every ear, by component (NO_PINCH: no ear).
    let mut ear_at: Vec<LocalPoint> = Vec::new();
    for &p in &pinches {
        let at_p: Vec<u32> = vor
            .cell_vertices(p)
            .map(VertexId::get)
            .filter(|&v| labels[v as usize] == Label::Inner)
            .map(|v| search.component(vor, labels, v))
            .collect();
        ear_at.resize(search.list.len(), NO_PINCH);
        // Beside a large component a small one may be an ear; small ones meeting only each
        // other (a tiny input's bow tie) stay as they are.
        if at_p.iter().all(|&c| search.list[c as usize].is_small()) {
            continue;
        }
        for &c in &at_p {
            let component = &search.list[c as usize];
            if component.is_small() && component.hangs_at(p, &degree) {
                ear_at[c as usize] = p;
            }
        }
    }
    let mut change = Change::default();
    for (c, &p) in ear_at.iter().enumerate().filter(|(_, &p)| p != NO_PINCH) {
        let gap = (mode == Ears::Rejoin && degree[p.index()] == 4)
            .then(|| rejoining_vertex(vor, labels, &search, c as u32, p))
            .flatten();
        match gap {
            Some(o) => change.rejoin(vor, p, o),
            None => change.drop(&search.list[c]),
        }
    }
    change.apply(labels, edges)
}

/// Drops the *islets* of `labels`: small loops of the crust that stand alone in the noise
/// band of a curve. Updates `edges`, the crust of `labels`, like [`repair_ears`] (first pass
/// only); returns the number of vertices relabelled.
///
/// An islet is an inner component with fewer than [`MIN_LOOP_POINTS`] boundary points whose
/// loop touches no other crust edge (all its points have degree 2) and does not lie apart
/// from the rest of the crust: some point of it closer than peeling's `APART` (2) of the
/// loop's own spacings (its median edge) to a crust edge at a Delaunay neighbour off the loop
/// (peeling's [`lies_apart`]). On a noisy curve the water flow sometimes leaves such a small
/// region inner just outside it, three to six points of its band around a face the water
/// deactivated. Fewer than 7 points are no ε-sample of a closed curve (ε < 1, see the module
/// docs), and two curves of an ε-sample lie farther apart than 2 spacings, so the islet is
/// noise: relabelled outer, its points left without edges (leftovers for peeling, which has
/// no loop of fewer than 7 points either). A small loop of a drawing away from other strokes
/// stays; clean samples have none beside a curve (ARCHITECTURE.md, "Ears", measures both).
///
/// Decided on the labels as the water flow left them and on the crust they give: the
/// islets are disjoint loops, each judged against the same crust, so the order of the points
/// does not matter.
pub(crate) fn drop_islets(
    vor: &Voronoi<'_>,
    labels: &mut [Label],
    edges: &mut Vec<[LocalPoint; 2]>,
) -> usize {
    let n = vor.triangulation().points.len();
    let loops = small_loops(n, edges);
    if loops.is_empty() {
        return 0;
    }
    // The crust edges at the loops' Delaunay neighbours: all that `lies_apart` reads (an
    // adjacency of every edge was most of this step's time on large inputs).
    let loop_points: Vec<LocalPoint> = loops.iter().flatten().copied().collect();
    let curve = edges_near(vor, &loop_points, edges);
    let mut search = Components::default();
    let mut change = Change::default();
    for points in &loops {
        let own: Vec<[LocalPoint; 2]> = (0..points.len())
            .map(|i| {
                let (a, b) = (points[i], points[(i + 1) % points.len()]);
                [a.min(b), a.max(b)]
            })
            .collect();
        let spacing = median_length(&vor.triangulation().points, &own);
        let beside_a_curve = !lies_apart(
            vor,
            |q| curve.neighbours(q),
            points,
            spacing,
            |q| !points.contains(&q),
        );
        if !beside_a_curve {
            continue;
        }
        // The inner side of its first edge: the islet's component when the loop encloses it
        // (a loop around an outer pocket of a large region has the large one there).
        let [a, b] = [points[0], points[1]];
        let Some(e) = vor.delaunay_halfedge(a, b) else {
            continue;
        };
        let twin = vor.triangulation().halfedges()[e.index()];
        let sides = [e, twin]
            .into_iter()
            .filter(|&h| h != NO_TWIN)
            .map(|h| vor.vertex_of_halfedge(h).get());
        let Some(inner) = sides
            .into_iter()
            .find(|&v| labels[v as usize] == Label::Inner)
        else {
            continue;
        };
        let c = search.component(vor, labels, inner);
        let component = &search.list[c as usize];
        if component.is_small() && component.boundary_points.iter().all(|q| points.contains(q)) {
            change.drop(component);
        }
    }
    change.apply(labels, edges)
}

/// The closed loops of `edges` with fewer than [`MIN_LOOP_POINTS`] points, all of degree 2
/// (their points, in order along the loop). This runs on every first pass, so it keeps no
/// adjacency lists: a point of degree 2 keeps the XOR of its two neighbours, and a walk goes
/// on from `prev` to `at` by `xor[at] ^ prev`. Each walk starts along an edge, stops after
/// [`MIN_LOOP_POINTS`] points or at a point walked over before, so every point is walked over
/// once (a walked point's degree is set to 0).
fn small_loops(point_count: usize, edges: &[[LocalPoint; 2]]) -> Vec<Vec<LocalPoint>> {
    let mut degree = degrees(point_count, edges);
    // The XOR of two local points' numbers: no point itself.
    let mut xor = vec![0u32; point_count];
    for &[a, b] in edges {
        xor[a.index()] ^= b.get();
        xor[b.index()] ^= a.get();
    }
    let mut loops = Vec::new();
    for &[start, next] in edges {
        if degree[start.index()] != 2 {
            continue;
        }
        degree[start.index()] = 0;
        let mut path = vec![start];
        let (mut prev, mut at) = (start, next);
        while at != start && path.len() < MIN_LOOP_POINTS && degree[at.index()] == 2 {
            degree[at.index()] = 0;
            path.push(at);
            (prev, at) = (at, LocalPoint::new(xor[at.index()] ^ prev.get()));
        }
        if at == start && path.len() >= 3 {
            loops.push(path);
        }
    }
    loops
}

/// An inner component, whole when small; a large one only as far as it was explored.
struct Component {
    vertices: Vec<u32>,
    /// The crust edges dual to its inner–outer Voronoi edges, `[min, max]`.
    boundary: Vec<[LocalPoint; 2]>,
    /// Its distinct boundary points, up to [`MIN_LOOP_POINTS`].
    boundary_points: Vec<LocalPoint>,
}

impl Component {
    fn is_small(&self) -> bool {
        self.boundary_points.len() < MIN_LOOP_POINTS
    }

    /// Does its loop touch the rest of the crust at `p` only (every other boundary point of
    /// degree 2)? Where strokes of a drawing cross, a small region between them has several
    /// junctions on its boundary.
    fn hangs_at(&self, p: LocalPoint, degree: &[u8]) -> bool {
        self.boundary_points
            .iter()
            .all(|&q| q == p || degree[q.index()] == 2)
    }
}

/// The inner components found so far.
#[derive(Default)]
struct Components {
    /// The component of every vertex seen. A map: the searches stop early in large
    /// components, so they see few vertices (an array over all vertices was a pass over
    /// them, for every input).
    seen: HashMap<u32, u32>,
    list: Vec<Component>,
}

impl Components {
    /// The component of `v`, or [`UNKNOWN`] where no search has seen it.
    fn of(&self, v: u32) -> u32 {
        self.seen.get(&v).copied().unwrap_or(UNKNOWN)
    }

    /// The component of the inner vertex `start`, explored breadth first over finite
    /// Voronoi edges between inner vertices if not seen before, until it shows
    /// [`MIN_LOOP_POINTS`] boundary points or reaches a vertex of a component found before (a
    /// large one: a small one is explored whole, so it would hold `start`).
    fn component(&mut self, vor: &Voronoi<'_>, labels: &[Label], start: u32) -> u32 {
        if self.of(start) != UNKNOWN {
            return self.of(start);
        }
        let id = self.list.len() as u32;
        let mut component = Component {
            vertices: vec![start],
            boundary: Vec::new(),
            boundary_points: Vec::new(),
        };
        self.seen.insert(start, id);
        let mut found = id;
        let mut next = 0;
        'search: while next < component.vertices.len() {
            let v = component.vertices[next];
            next += 1;
            for edge in vor.face_edges(VertexId::new(v)) {
                match edge.to {
                    EdgeEnd::Vertex(u) if labels[u.index()] == Label::Inner => {
                        let u = u.get();
                        let known = self.of(u);
                        if known == UNKNOWN {
                            self.seen.insert(u, id);
                            component.vertices.push(u);
                        } else if known != id {
                            found = known;
                            break 'search;
                        }
                    }
                    _ => {
                        let [a, b] = edge.sites;
                        component.boundary.push([a.min(b), a.max(b)]);
                        for q in [a, b] {
                            if !component.boundary_points.contains(&q) {
                                component.boundary_points.push(q);
                            }
                        }
                        if !component.is_small() {
                            break 'search;
                        }
                    }
                }
            }
        }
        if found != id {
            for &v in &component.vertices {
                self.seen.insert(v, found);
            }
            return found;
        }
        self.list.push(component);
        id
    }

    /// Is `v` (possibly the root) an inner vertex of a large component other than `ear`?
    fn is_large_beside(&self, labels: &[Label], v: u32, ear: u32) -> bool {
        v != ROOT
            && labels[v as usize] == Label::Inner
            && self.of(v) != ear
            && self.of(v) != UNKNOWN
            && !self.list[self.of(v) as usize].is_small()
    }
}

/// The outer vertex of `p`'s cell that alone separates the ear `ear` from a large inner
/// component there and whose face is a triangle with an outer third neighbour (see the
/// module docs); of two, the one with the smaller circumcircle.
fn rejoining_vertex(
    vor: &Voronoi<'_>,
    labels: &[Label],
    search: &Components,
    ear: u32,
    p: LocalPoint,
) -> Option<u32> {
    // Around p; an open cell (a hull point) is closed by the root, outer and never relabelled.
    let mut cell: Vec<u32> = (vor.cell_vertices(p)).map(VertexId::get).collect();
    if !vor.is_interior(p) {
        cell.push(ROOT);
    }
    let k = cell.len();
    let at = |i: usize| cell[i % k];
    let in_ear = |v: u32| v != ROOT && labels[v as usize] == Label::Inner && search.of(v) == ear;
    // The ear's vertices at p are one run (p has two edges of the ear): from `first` to `last`.
    let first = (0..k).find(|&i| in_ear(at(i)) && !in_ear(at(i + k - 1)))?;
    let last = (first..first + k).find(|&i| !in_ear(at(i + 1)))?;
    let gap = |o: u32, beyond: u32| {
        let far_side_outer = || {
            vor.face_edges(VertexId::new(o)).all(|edge| {
                edge.sites.contains(&p)
                    || match edge.to {
                        EdgeEnd::Infinity => true,
                        EdgeEnd::Vertex(u) => labels[u.index()] == Label::Outer,
                    }
            })
        };
        (o != ROOT
            && labels[o as usize] == Label::Outer
            && vor.degree(VertexId::new(o)) == 3
            && search.is_large_beside(labels, beyond, ear)
            && far_side_outer())
        .then_some(o)
    };
    let before = gap(at(first + k - 1), at(first + 2 * k - 2));
    let after = gap(at(last + 1), at(last + 2));
    match (before, after) {
        (Some(a), Some(b)) => {
            let triangle = |v: u32| vor.vertex_triangle(VertexId::new(v));
            let order = compare_circumradius(triangle(a), triangle(b));
            Some(if order == Ordering::Greater { b } else { a })
        }
        (a, b) => a.or(b),
    }
}

/// The relabelling and edge changes of all ears, applied at once.
#[derive(Default)]
struct Change {
    to_outer: Vec<u32>,
    to_inner: Vec<u32>,
    dropped: Vec<[LocalPoint; 2]>,
    added: Vec<[LocalPoint; 2]>,
}

impl Change {
    /// The triangle `o` at `p` becomes inner: its two edges at `p` stop being crust, its far
    /// edge becomes crust.
    fn rejoin(&mut self, vor: &Voronoi<'_>, p: LocalPoint, o: u32) {
        let others: Vec<LocalPoint> = (vor.face_corners(VertexId::new(o)))
            .filter(|&q| q != p)
            .collect();
        let [x, y] = [others[0], others[1]];
        self.dropped
            .extend([[p.min(x), p.max(x)], [p.min(y), p.max(y)]]);
        self.added.push([x.min(y), x.max(y)]);
        self.to_inner.push(o);
    }

    /// The ear becomes outer: its boundary edges stop being crust.
    fn drop(&mut self, ear: &Component) {
        self.to_outer.extend_from_slice(&ear.vertices);
        self.dropped.extend_from_slice(&ear.boundary);
    }

    fn apply(mut self, labels: &mut [Label], edges: &mut Vec<[LocalPoint; 2]>) -> usize {
        for &v in &self.to_outer {
            labels[v as usize] = Label::Outer;
        }
        self.to_inner.sort_unstable();
        self.to_inner.dedup();
        for &v in &self.to_inner {
            labels[v as usize] = Label::Inner;
        }
        if !self.dropped.is_empty() {
            self.dropped.sort_unstable();
            edges.retain(|e| self.dropped.binary_search(e).is_err());
        }
        self.added.sort_unstable();
        self.added.dedup();
        edges.extend(self.added);
        self.to_outer.len() + self.to_inner.len()
    }
}
