//! The reconstruction, top to bottom: triangulate, dual, label, extract, peel, assemble.

use super::curves;
use super::extract::{chain_edges, medial_axis, wdm_crust_edges};
use super::options::{Algorithm, Options};
use super::peel::{hole_edges, parity_inside, peel, Peeling};
use super::result::{MedialAxis, Reconstruction};
use super::wdm::{self, Label};
use super::{crust, nn_crust};
use crate::delaunay::{triangulate, Triangulation};
use crate::error::Error;

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
#[non_exhaustive]
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
    if options.algorithm() != Algorithm::Wdm {
        let edges = if triangulation.is_degenerate() {
            chain_edges(&triangulation)
        } else if options.algorithm() == Algorithm::Crust {
            crust::crust_edges(&triangulation)
        } else {
            nn_crust::nn_crust_edges(&triangulation)
        };
        let axis = MedialAxis::default();
        let rec = finish(
            options.algorithm(),
            triangulation,
            Vec::new(),
            edges,
            axis,
            1,
        );
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
        let flow = wdm::label_vertices(&vor, options.label_rule());
        lap(Phase::Label);
        let mut edges = if triangulation.is_degenerate() {
            chain_edges(&triangulation)
        } else {
            wdm_crust_edges(&vor, &flow.labels)
        };
        let first_pass_len = edges.len();
        let peeling = if options.peeling() {
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
        algorithm: options.algorithm(),
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
                let options = Options::new().with_peeling(peeling);
                let rec = reconstruct_with(&points, &options).unwrap();

                let tri = triangulate(&points).unwrap();
                let vor = tri.voronoi();
                let flow = wdm::label_vertices(&vor, options.label_rule());
                assert_eq!(rec.labels(), &flow.labels[..], "round {round}");
                let mut edges = wdm_crust_edges(&vor, &flow.labels);
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
