//! Curve reconstruction and medial axis from unordered points.
//!
//! [`reconstruct`] runs WDM_CRUST with the default [`Options`]: triangulate, build the merged
//! Voronoi dual, label its vertices by the water flow ([`wdm`]), keep the Delaunay edges whose
//! dual Voronoi edge joins an inner and an outer vertex (the crust) and the finite Voronoi
//! edges joining two inner vertices (the medial axis), assemble the crust into curves
//! ([`Curve`]). Shapes with holes are handled by peeling (see [`Options::peeling`]).

pub mod crust;
mod curves;
pub mod nn_crust;
pub mod wdm;

pub use curves::Curve;
pub use wdm::{Label, LabelRule, WaterFlow};

use crate::delaunay::{triangulate, Triangulation};
use crate::error::Error;
use crate::voronoi::{EdgeEnd, Voronoi};

/// Which reconstruction algorithm to run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Algorithm {
    /// WDM_CRUST (Peethambaran, Parakkat, Muthuganapathy): water-flow labeling.
    #[default]
    Wdm,
    /// The crust of Amenta, Bern and Eppstein: Delaunay edges between samples that survive
    /// when the Voronoi vertices are added to the point set.
    Crust,
    /// The nearest-neighbour crust of Dey and Kumar: each sample's nearest neighbour, plus
    /// its nearest "half neighbour" on the other side.
    NnCrust,
}

impl Algorithm {
    /// The name used on the command line and in JSON output.
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Wdm => "wdm",
            Algorithm::Crust => "crust",
            Algorithm::NnCrust => "nn-crust",
        }
    }
}

/// Reconstruction options.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Options {
    /// The algorithm.
    pub algorithm: Algorithm,
    /// Nested curves (holes): rerun on the points the crust left untouched until none (or
    /// fewer than three) remain, and take the union. The paper's single pass never reaches
    /// a hole, so its inner curve would be lost. On by default.
    pub peeling: bool,
    /// How water-flow states become labels (see [`LabelRule`]).
    pub label_rule: LabelRule,
    /// Bounds the work of peeling: the extra passes together may run on at most this many
    /// times the input's point count (default 4), so a reconstruction costs at most about
    /// five single passes. Nested curves leave few points for the later passes and never
    /// meet the bound; inputs that are not curve samples do (uniform noise or a grid peel off
    /// a thin layer per pass and would take hundreds of passes).
    /// [`Reconstruction::peeling_budget_exhausted`] tells when it stopped the peeling.
    pub peeling_budget: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            algorithm: Algorithm::Wdm,
            peeling: true,
            label_rule: LabelRule::WaterReached,
            peeling_budget: 4,
        }
    }
}

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

/// The medial axis approximation: segments between inner Voronoi vertices.
#[derive(Debug, Clone, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct MedialAxis {
    /// Circumcenters (rounded to f64) of the inner vertices that have a medial-axis edge.
    pub vertices: Vec<[f64; 2]>,
    /// Segments as index pairs into `vertices`, `[a, b]` with `a < b`, sorted.
    pub edges: Vec<[u32; 2]>,
}

/// The result of a reconstruction.
#[derive(Debug, Clone)]
pub struct Reconstruction {
    algorithm: Algorithm,
    triangulation: Triangulation,
    labels: Vec<Label>,
    edges: Vec<[u32; 2]>,
    curves: Vec<Curve>,
    medial_axis: MedialAxis,
    passes: usize,
    budget_exhausted: bool,
}

impl Reconstruction {
    /// The algorithm that produced this result.
    pub fn algorithm(&self) -> Algorithm {
        self.algorithm
    }

    /// Reconstructed edges `[i, j]` with `i < j`, sorted, over the caller's indices.
    pub fn edges(&self) -> &[[u32; 2]] {
        &self.edges
    }

    /// Closed loops and open chains assembled from [`Self::edges`].
    pub fn curves(&self) -> &[Curve] {
        &self.curves
    }

    /// True when peeling stopped because the next pass would have exceeded
    /// [`Options::peeling_budget`]: the [`untouched_points`](Self::untouched_points) may
    /// then still hold curves.
    pub fn peeling_budget_exhausted(&self) -> bool {
        self.budget_exhausted
    }

    /// WDM_MAT: segments between inner Voronoi vertices.
    pub fn medial_axis(&self) -> &MedialAxis {
        &self.medial_axis
    }

    /// The Delaunay triangulation of all the points.
    pub fn triangulation(&self) -> &Triangulation {
        &self.triangulation
    }

    /// The label of every vertex of `self.triangulation().voronoi()` from the first pass
    /// (empty for the baseline algorithms, which do not label).
    pub fn labels(&self) -> &[Label] {
        &self.labels
    }

    /// Distinct points with a degree other than 0 or 2 in the reconstruction: curve ends and
    /// junctions.
    pub fn irregular_points(&self) -> Vec<u32> {
        curves::irregular_points(self.triangulation.points().len(), &self.edges)
    }

    /// Distinct points that no reconstructed edge touches.
    pub fn untouched_points(&self) -> Vec<u32> {
        untouched(&self.triangulation, &self.edges)
    }

    /// How many passes ran (more than one when peeling found nested curves).
    pub fn passes(&self) -> usize {
        self.passes
    }
}

/// WDM_CRUST and WDM_MAT of `points` with the default [`Options`].
///
/// ```
/// // Twelve points on a circle, in scrambled order: one closed curve through all of them.
/// let points: Vec<[f64; 2]> = [0, 5, 10, 3, 8, 1, 6, 11, 4, 9, 2, 7]
///     .iter()
///     .map(|&k| {
///         let t = k as f64 * std::f64::consts::TAU / 12.0;
///         [t.cos(), t.sin()]
///     })
///     .collect();
/// let rec = wdm_crust::reconstruct(&points)?;
/// assert_eq!(rec.edges().len(), 12);
/// assert_eq!(rec.curves().len(), 1);
/// assert!(rec.curves()[0].closed);
/// # Ok::<(), wdm_crust::Error>(())
/// ```
pub fn reconstruct(points: &[[f64; 2]]) -> Result<Reconstruction, Error> {
    reconstruct_with(points, &Options::default())
}

/// Reconstruction with explicit [`Options`].
pub fn reconstruct_with(points: &[[f64; 2]], options: &Options) -> Result<Reconstruction, Error> {
    reconstruct_observed(points, options, &mut |_, _| {})
}

/// A stage of the reconstruction pipeline, as reported to [`reconstruct_observed`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    /// Validation, duplicate merging and the Delaunay triangulation.
    Triangulate,
    /// The merged-face Voronoi dual.
    Voronoi,
    /// The water flow and the inner/outer labels.
    Label,
    /// Crust edges, peeling passes, medial axis and curve assembly (or a baseline's edges).
    Extract,
}

impl Phase {
    /// Lower-case name, as printed by `--timings`.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Triangulate => "triangulate",
            Phase::Voronoi => "voronoi",
            Phase::Label => "label",
            Phase::Extract => "extract",
        }
    }
}

/// [`reconstruct_with`], calling `on_phase` with the wall time of each [`Phase`] as it ends
/// (for timings and progress reports).
pub fn reconstruct_observed(
    points: &[[f64; 2]],
    options: &Options,
    on_phase: &mut dyn FnMut(Phase, std::time::Duration),
) -> Result<Reconstruction, Error> {
    let mut clock = std::time::Instant::now();
    let mut lap = |phase: Phase| {
        on_phase(phase, clock.elapsed());
        clock = std::time::Instant::now();
    };
    let mut triangulation = triangulate(points)?;
    lap(Phase::Triangulate);
    if options.algorithm != Algorithm::Wdm {
        let edges = if triangulation.is_degenerate() {
            chain_edges(&triangulation)
        } else if options.algorithm == Algorithm::Crust {
            crust::crust_edges(&triangulation)
        } else {
            nn_crust::nn_crust_edges(&triangulation)
        };
        let axis = MedialAxis::default();
        let rec = finish(options.algorithm, triangulation, Vec::new(), edges, axis, 1);
        lap(Phase::Extract);
        return Ok(rec);
    }
    // Everything after the triangulation runs on points renamed for locality (see
    // `Triangulation::locality_renaming`; 1.5–2× faster on shuffled input) and is renamed
    // back at the end. Triangle and half-edge ids, hence Voronoi vertex ids and labels, do
    // not change.
    let renaming = triangulation.locality_renaming();
    triangulation.rename_points(&renaming.new_of_old);
    let (labels, mut edges, medial_axis, peeling, local_curves) = {
        let vor = triangulation.voronoi();
        lap(Phase::Voronoi);
        let flow = wdm::label_vertices(&vor, options.label_rule);
        lap(Phase::Label);
        let mut edges = if triangulation.is_degenerate() {
            chain_edges(&triangulation)
        } else {
            crust_edges(&vor, &flow.labels)
        };
        let first_pass_len = edges.len();
        let peeling = if options.peeling {
            peel(&vor, &mut edges, options)
        } else {
            Peeling::done(0)
        };
        let holes_possible = peeling.extra_passes > 0;
        let mut first_pass = Vec::new();
        if holes_possible {
            first_pass.extend_from_slice(&edges[..first_pass_len]);
            first_pass.sort_unstable();
        }
        edges.sort_unstable();
        edges.dedup();
        let curves = curves::assemble(points.len(), &edges, triangulation.points());
        let holes = if holes_possible {
            hole_edges(&vor, &curves, &first_pass)
        } else {
            Vec::new()
        };
        let axis = if holes.is_empty() {
            medial_axis(&vor, &flow.labels)
        } else {
            // A vertex is inside the shape when it is inner in the first pass and not
            // inside a hole: an even number of hole loops separate it from infinity.
            let in_hole = parity_inside(&vor, &holes);
            let combined: Vec<Label> = flow
                .labels
                .iter()
                .zip(&in_hole)
                .map(|(&l, &h)| {
                    if l == Label::Inner && !h {
                        Label::Inner
                    } else {
                        Label::Outer
                    }
                })
                .collect();
            medial_axis(&vor, &combined)
        };
        (flow.labels, edges, axis, peeling, curves)
    };
    let old = &renaming.old_of_new;
    triangulation.rename_points(old);
    for edge in &mut edges {
        let [a, b] = edge.map(|p| old[p as usize]);
        *edge = [a.min(b), a.max(b)];
    }
    edges.sort_unstable();
    let curves = curves::rename(local_curves, old, points);
    let rec = Reconstruction {
        algorithm: options.algorithm,
        triangulation,
        labels,
        edges,
        curves,
        medial_axis,
        passes: 1 + peeling.extra_passes,
        budget_exhausted: peeling.budget_exhausted,
    };
    lap(Phase::Extract);
    Ok(rec)
}

/// Sorts the edges and assembles the curves.
fn finish(
    algorithm: Algorithm,
    triangulation: Triangulation,
    labels: Vec<Label>,
    mut edges: Vec<[u32; 2]>,
    medial_axis: MedialAxis,
    passes: usize,
) -> Reconstruction {
    edges.sort_unstable();
    edges.dedup();
    let points = triangulation.points();
    let curves = curves::assemble(points.len(), &edges, points);
    Reconstruction {
        algorithm,
        triangulation,
        labels,
        edges,
        curves,
        medial_axis,
        passes,
        budget_exhausted: false,
    }
}

/// Delaunay edges dual to branch edges, each once, unsorted. A ray's far end is the root
/// vertex, always outer.
fn crust_edges(vor: &Voronoi<'_>, labels: &[Label]) -> Vec<[u32; 2]> {
    let mut edges = Vec::new();
    for v in 0..vor.vertex_count() as u32 {
        for edge in vor.vertex_edges(v) {
            let far = match edge.to {
                EdgeEnd::Vertex(u) if u < v => continue, // each finite edge once
                EdgeEnd::Vertex(u) => labels[u as usize],
                EdgeEnd::Infinity => Label::Outer,
            };
            if EdgeClass::of(labels[v as usize], far) == EdgeClass::Branch {
                let [a, b] = edge.sites;
                edges.push([a.min(b), a.max(b)]);
            }
        }
    }
    edges
}

/// Finite Voronoi edges with both ends inner, with the used vertices renumbered.
fn medial_axis(vor: &Voronoi<'_>, labels: &[Label]) -> MedialAxis {
    let mut index = vec![u32::MAX; vor.vertex_count()];
    let mut axis = MedialAxis::default();
    let mut renumber = |v: u32, axis: &mut MedialAxis| {
        if index[v as usize] == u32::MAX {
            index[v as usize] = axis.vertices.len() as u32;
            axis.vertices.push(vor.vertex_position(v));
        }
        index[v as usize]
    };
    for (_, a, b) in vor.finite_edges() {
        if labels[a as usize] == Label::Inner && labels[b as usize] == Label::Inner {
            let (ia, ib) = (renumber(a, &mut axis), renumber(b, &mut axis));
            axis.edges.push([ia.min(ib), ia.max(ib)]);
        }
    }
    axis.edges.sort_unstable();
    axis
}

/// Collinear or tiny input: the chain along the line is the reconstruction.
fn chain_edges(tri: &Triangulation) -> Vec<[u32; 2]> {
    tri.hull()
        .windows(2)
        .map(|w| [w[0].min(w[1]), w[0].max(w[1])])
        .collect()
}

/// Distinct points without an edge.
fn untouched(tri: &Triangulation, edges: &[[u32; 2]]) -> Vec<u32> {
    let n = tri.points().len();
    let mut touched = vec![false; n];
    for &[a, b] in edges {
        touched[a as usize] = true;
        touched[b as usize] = true;
    }
    for &[dup, _] in tri.duplicates() {
        touched[dup as usize] = true;
    }
    (0..n as u32).filter(|&p| !touched[p as usize]).collect()
}

/// Reruns WDM_CRUST on the points the crust left untouched, adding what each pass finds,
/// until a pass finds nothing, fewer than three points remain, or the next pass would exceed
/// [`Options::peeling_budget`].
///
/// Only edges of the full Delaunay triangulation are taken from a later pass. A nested
/// curve's edges are Delaunay edges of all the points (so they never cross an earlier
/// curve), whereas the leftovers of a noisy band would otherwise be joined by long chords
/// across the curve already found.
fn peel(full: &Voronoi<'_>, edges: &mut Vec<[u32; 2]>, options: &Options) -> Peeling {
    let tri = full.triangulation();
    let points = tri.points();
    let mut budget = options.peeling_budget.saturating_mul(points.len());
    let mut extra = 0;
    loop {
        let rest = untouched(tri, edges);
        if rest.len() < 3 {
            return Peeling::done(extra);
        }
        if rest.len() > budget {
            return Peeling {
                extra_passes: extra,
                budget_exhausted: true,
            };
        }
        budget -= rest.len();
        let subset: Vec<[f64; 2]> = rest.iter().map(|&i| points[i as usize]).collect();
        // The subset is a selection of already validated points: this cannot fail.
        let Ok(sub) = triangulate(&subset) else {
            return Peeling::done(extra);
        };
        if sub.is_degenerate() {
            return Peeling::done(extra);
        }
        let vor = sub.voronoi();
        let flow = wdm::label_vertices(&vor, options.label_rule);
        let found: Vec<[u32; 2]> = crust_edges(&vor, &flow.labels)
            .iter()
            .map(|&[a, b]| {
                let (a, b) = (rest[a as usize], rest[b as usize]);
                [a.min(b), a.max(b)]
            })
            .filter(|&[a, b]| full.is_delaunay_edge(a, b))
            .collect();
        if found.is_empty() {
            return Peeling::done(extra);
        }
        edges.extend(found);
        extra += 1;
    }
}

/// How peeling ended.
struct Peeling {
    extra_passes: usize,
    budget_exhausted: bool,
}

impl Peeling {
    fn done(extra_passes: usize) -> Peeling {
        Peeling {
            extra_passes,
            budget_exhausted: false,
        }
    }
}

/// The edges of the holes peeling found: closed loops made only of later-pass edges, each
/// with a dual Voronoi edge. The first pass never reaches inside a hole (DESIGN: water from
/// infinity), so its labels already say what lies inside the outer curves; the hole loops
/// say what to take away.
///
/// Only such loops are counted because only they make the parity below well defined: they
/// are disjoint cycles of degree-2 points, so every closed walk in the Voronoi graph crosses
/// them an even number of times, and the parity of a vertex does not depend on the path by
/// which it is reached. Open chains and junctions (noise) have no inside; counting them made
/// the result depend on the search order, hence on the input order (a fuzz finding). A
/// loop through an edge without a dual (inside a merged cocircular face) cannot separate
/// that face's vertex and is not counted either.
fn hole_edges(vor: &Voronoi<'_>, curves: &[Curve], first_pass: &[[u32; 2]]) -> Vec<[u32; 2]> {
    let mut holes = Vec::new();
    for curve in curves.iter().filter(|c| c.closed) {
        let loop_edges = curve
            .points
            .iter()
            .zip(curve.points.iter().cycle().skip(1))
            .map(|(&a, &b)| [a.min(b), a.max(b)]);
        let is_hole = loop_edges.clone().all(|[a, b]| {
            first_pass.binary_search(&[a, b]).is_err()
                && vor.delaunay_halfedge(a, b).is_some_and(|e| vor.has_dual(e))
        });
        if is_hole {
            holes.extend(loop_edges);
        }
    }
    holes
}

/// Every Voronoi vertex: is it separated from infinity by an odd number of the given edges
/// (breadth first from the rays)? Well defined only for a set of closed loops, see
/// [`hole_edges`].
fn parity_inside(vor: &Voronoi<'_>, edges: &[[u32; 2]]) -> Vec<bool> {
    let tri = vor.triangulation();
    // Crust neighbours of every point (two for most): a lookup touches one short row
    // instead of a binary search over all edges.
    let crust = curves::Adjacency::new(tri.points().len(), edges);
    let is_crust = |e: u32| {
        let b = tri.halfedge_destination(e as usize);
        crust
            .neighbours(tri.halfedge_origin(e as usize))
            .iter()
            .any(|&(_, q)| q == b)
    };
    let n = vor.vertex_count();
    let mut inside = vec![false; n];
    let mut seen = vec![false; n];
    let mut queue = std::collections::VecDeque::new();
    for (e, v, _) in vor.rays() {
        if !seen[v as usize] {
            seen[v as usize] = true;
            inside[v as usize] = is_crust(e);
            queue.push_back(v);
        }
    }
    while let Some(v) = queue.pop_front() {
        for edge in vor.vertex_edges(v) {
            if let EdgeEnd::Vertex(u) = edge.to {
                if !seen[u as usize] {
                    seen[u as usize] = true;
                    inside[u as usize] = inside[v as usize] ^ is_crust(edge.halfedge);
                    queue.push_back(u);
                }
            }
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;
    use wdm_crust_testkit::Rng;

    /// The pipeline runs on renamed points; its result must be what the same steps give on
    /// the caller's indices directly.
    #[test]
    fn renamed_pipeline_equals_the_direct_one() {
        let mut rng = Rng::new(3);
        let mut peeled = 0;
        for round in 0..40 {
            let n = 20 + rng.below(400);
            // Two nested noisy loops (so peeling runs) plus a few scattered points, shuffled.
            let mut points: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let t = i as f64 / n as f64 * std::f64::consts::TAU;
                    let r = if i % 3 == 0 { 0.5 } else { 1.0 } + 0.01 * rng.normal();
                    [r * t.cos(), 0.8 * r * t.sin()]
                })
                .collect();
            points.extend((0..rng.below(5)).map(|_| [rng.range(-1.5, 1.5), rng.f64()]));
            rng.shuffle(&mut points);
            for peeling in [false, true] {
                let options = Options {
                    peeling,
                    ..Options::default()
                };
                let rec = reconstruct_with(&points, &options).unwrap();

                let tri = triangulate(&points).unwrap();
                let vor = tri.voronoi();
                let flow = wdm::label_vertices(&vor, options.label_rule);
                assert_eq!(rec.labels(), &flow.labels[..], "round {round}");
                let mut edges = crust_edges(&vor, &flow.labels);
                let passes = 1 + if peeling {
                    peel(&vor, &mut edges, &options).extra_passes
                } else {
                    0
                };
                edges.sort_unstable();
                edges.dedup();
                assert_eq!(rec.passes(), passes, "round {round}");
                peeled += usize::from(passes > 1);
                assert_eq!(rec.edges(), &edges[..], "round {round}");
                let curves = curves::assemble(points.len(), &edges, &points);
                assert_eq!(rec.curves(), &curves[..], "round {round}");
                assert_eq!(rec.triangulation().triangles(), tri.triangles());
                assert_eq!(rec.triangulation().hull(), tri.hull());
                if passes == 1 {
                    let axis = medial_axis(&vor, &flow.labels);
                    assert_eq!(rec.medial_axis(), &axis, "round {round}");
                }
            }
        }
        assert!(peeled > 5, "peeling ran in only {peeled} rounds");
    }
}
