//! The reconstruction, top to bottom: triangulate, thin (a noisy band, or an uncertain sample
//! whose result is junk), dual, label, extract, peel, assemble.

use super::curves;
use super::curves::chain_edges;
use super::extract::{medial_axis, wdm_crust_edges};
use super::frame::Frame;
use super::medial_axis::{fitted_medial_axis, pruned_medial_axis};
use super::open_curves;
use super::options::{Algorithm, MedialAxisMode, Options};
use super::repairs::beside::{clean_loops_beside, Beside};
use super::repairs::corridors::repair_corridors;
use super::repairs::detours::repair_detours;
use super::repairs::ears::{drop_islets, repair_ears, Ears};
use super::repairs::facing::swap_facing_corners;
use super::repairs::peel::{hole_edges, parity_inside, peel, Peeling};
use super::repairs::shared::Repair;
use super::result::{untouched_points, MedialAxis, Reconstruction};
use super::scatter;
use super::smooth::{self, Fitted};
use super::thinning::{self, uncertain};
use super::wdm::{self, Label, LabelRule};
use super::{crust, nn_crust};
use crate::delaunay::Triangulation;
use crate::error::Error;
use crate::ids::LocalPoint;
use crate::voronoi::Voronoi;

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

/// When the phase being timed began. `wasm32-unknown-unknown` has no clock (`Instant::now`
/// panics there): there every phase lasts zero.
struct PhaseClock {
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    start: std::time::Instant,
}

impl PhaseClock {
    fn start() -> Self {
        PhaseClock {
            #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
            start: std::time::Instant::now(),
        }
    }

    fn elapsed(&self) -> std::time::Duration {
        #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
        return self.start.elapsed();
        #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
        return std::time::Duration::ZERO;
    }
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
    /// The crust edges of the first pass (or a baseline's edges).
    Extract,
    /// Further passes for nested curves (WDM with peeling).
    Peel,
    /// The loops the water flow is sure of kept, every other point joined into open chains
    /// (WDM with [`Options::with_open_curves`]); then, with peeling, the clean loops beside
    /// curves that peeling took for noise.
    OpenCurves,
    /// Curve assembly (WDM: with the facing-corner swaps) and the unassigned points (with a
    /// baseline algorithm, also the translation to the caller's indices).
    Curves,
    /// The medial axis (WDM; none with [`MedialAxisMode::Omitted`]); then the curves'
    /// translation to the caller's indices, and the edges read off them (not held through
    /// the axis, the memory peak).
    MedialAxis,
    /// Smoothing ([`Options::with_smoothing`]): the curve vertices fitted to the samples
    /// around them; then the coordinates' way back to the caller's.
    Smooth,
    /// Thinning ([`Options::with_thinning`], WDM): recognising a dense noisy band and
    /// choosing its representatives. When it chose some, the phases of their reconstruction
    /// follow (from [`Triangulate`](Self::Triangulate) on), then [`Curves`](Self::Curves)
    /// again for the way back to all the points. An uncertain sample (noisy, short of a
    /// band) reports the phases of its reconstruction as it is first, and where that is
    /// doubtful those of the representatives' after them.
    Thin,
}

impl Phase {
    /// The phase's lower-case name (`"triangulate"`, `"medial-axis"`, ...), also its
    /// [`Display`](std::fmt::Display): what timing and progress reports print.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Triangulate => "triangulate",
            Phase::Voronoi => "voronoi",
            Phase::Label => "label",
            Phase::Extract => "extract",
            Phase::Peel => "peel",
            Phase::OpenCurves => "open-curves",
            Phase::Curves => "curves",
            Phase::MedialAxis => "medial-axis",
            Phase::Smooth => "smooth",
            Phase::Thin => "thin",
        }
    }
}

impl std::fmt::Display for Phase {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// [`reconstruct_with`], calling `on_phase` with the wall time of each [`Phase`] as it ends
/// (for timings and progress reports).
///
/// On `wasm32-unknown-unknown`, which has no clock, every duration is zero; the phases are
/// still reported as they end, so that a caller can time them with a clock of its own.
pub fn reconstruct_observed(
    points: &[[f64; 2]],
    options: &Options,
    on_phase: &mut dyn FnMut(Phase, std::time::Duration),
) -> Result<Reconstruction, Error> {
    let mut clock = PhaseClock::start();
    let mut lap = |phase: Phase| {
        on_phase(phase, clock.elapsed());
        clock = PhaseClock::start();
    };
    // Everything runs in the frame (the points exactly rescaled, see `frame`) and on the
    // triangulation's local indices (its locality order); the coordinates, curves and
    // edges come out in the caller's.
    let (triangulation, frame) = Frame::triangulate(points)?;
    lap(Phase::Triangulate);
    // Whether the probes read an area: a scatter is then possible (see `scatter`).
    let mut area = false;
    if options.algorithm() == Algorithm::Wdm && options.thinning() {
        let reading = thinning::read(&triangulation);
        lap(Phase::Thin);
        match reading {
            thinning::Reading::Band(local) => {
                return thinned(points, triangulation, frame, &local, options, on_phase);
            }
            thinning::Reading::Uncertain(local) => {
                let given = as_given(points, triangulation, frame, options, false, &mut lap);
                if !uncertain::doubtful(&given) {
                    return Ok(given);
                }
                // The same triangulation again, in the frame (the result holds its own in
                // the caller's coordinates): built only where it is needed, it is not held
                // through the first reconstruction's memory peak.
                let (triangulation, frame) = Frame::triangulate(points)?;
                let through = thinned(points, triangulation, frame, &local, options, on_phase)?;
                return Ok(if uncertain::preferred(&through, &given) {
                    through
                } else {
                    given
                });
            }
            thinning::Reading::Area => area = true,
            thinning::Reading::Neither => {}
        }
    }
    Ok(as_given(
        points,
        triangulation,
        frame,
        options,
        area,
        &mut lap,
    ))
}

/// The reconstruction of the points as they are (no thinning); `area` when the thinning's
/// probes read an area.
fn as_given(
    points: &[[f64; 2]],
    mut triangulation: Triangulation,
    frame: Frame,
    options: &Options,
    area: bool,
    lap: &mut dyn FnMut(Phase),
) -> Reconstruction {
    let mut outcome = if options.algorithm() == Algorithm::Wdm {
        wdm_crust(&triangulation, frame, options, area, lap)
    } else {
        let mut outcome = baseline(&triangulation, options, lap);
        outcome.fitted = smoothing(&triangulation, &outcome.curves, options, Fitted::Zigzagging);
        if options.smoothing() {
            lap(Phase::Smooth);
        }
        outcome
    };
    frame.restore(&mut triangulation, points);
    let fitted = outcome
        .fitted
        .take()
        .map(|moved| frame.fitted_to_caller(&triangulation, moved));
    Reconstruction {
        algorithm: options.algorithm(),
        triangulation,
        labels: outcome.labels,
        edges: outcome.edges,
        curves: outcome.curves,
        medial_axis: outcome.medial_axis,
        medial_axis_mode: (options.algorithm() == Algorithm::Wdm).then_some(options.medial_axis()),
        unassigned: outcome.unassigned,
        passes: 1 + outcome.peeling.extra_passes,
        budget_exhausted: outcome.peeling.budget_exhausted,
        fitted,
        warnings: Default::default(),
        thinned: None,
    }
}

/// What a run of one algorithm leaves for the [`Reconstruction`]: the curves, edges and
/// unassigned points in the caller's indices, the labels and the axis over the Voronoi
/// diagram's vertices.
struct Outcome {
    labels: Vec<Label>,
    edges: Vec<[u32; 2]>,
    curves: Vec<curves::Curve>,
    medial_axis: MedialAxis,
    unassigned: Vec<u32>,
    peeling: Peeling,
    /// With smoothing: the fitted positions by local index, in the frame (see
    /// [`smooth::fitted_positions`]).
    fitted: Option<Vec<Option<[f64; 2]>>>,
}

/// A baseline (crust, NN-crust): its edges assembled into curves; one pass, no labels, no
/// axis.
fn baseline(tri: &Triangulation, options: &Options, lap: &mut dyn FnMut(Phase)) -> Outcome {
    let edges = if tri.is_degenerate() {
        chain_edges(tri)
    } else if options.algorithm() == Algorithm::Crust {
        crust::edges_of(tri)
    } else {
        nn_crust::edges_of(tri)
    };
    lap(Phase::Extract);
    let curves = assemble(tri, &edges);
    let unassigned = untouched_points(tri, edges.iter().copied());
    let edges = tri.to_input_edges(edges);
    lap(Phase::Curves);
    Outcome {
        labels: Vec::new(),
        edges,
        curves,
        medial_axis: MedialAxis::default(),
        unassigned,
        peeling: Peeling::done(0, 0),
        fitted: None,
    }
}

/// WDM_CRUST and its medial axis, step by step; `area` when the thinning's probes read the
/// points as an area, where the first pass may read a scatter (see `scatter`).
fn wdm_crust(
    tri: &Triangulation,
    frame: Frame,
    options: &Options,
    area: bool,
    lap: &mut dyn FnMut(Phase),
) -> Outcome {
    let mut run = WdmRun::first_pass(tri, options, lap);
    if area {
        run.scatter = scatter::crowding(&run.vor, &run.edges);
    }
    run.repairs(options);
    run.peeling(options);
    lap(Phase::Peel);
    let assembly = run.assembly(options, lap);
    lap(Phase::Curves);
    // Before the axis, which is then that of the fitted curves.
    let fitted = options
        .smoothing()
        .then(|| smooth::fitted_positions(tri, &assembly.curves, Fitted::Zigzagging));
    if fitted.is_some() {
        lap(Phase::Smooth);
    }
    let outcome = run.axis(assembly, options, frame, fitted);
    lap(Phase::MedialAxis);
    outcome
}

/// A WDM run between its steps, in the frame and on the triangulation's local indices.
struct WdmRun<'t> {
    tri: &'t Triangulation,
    vor: Voronoi<'t>,
    labels: Vec<Label>,
    /// The edges so far: the first pass's, then the repairs' and peeling's changes.
    edges: Vec<[LocalPoint; 2]>,
    /// What the detour repair changed.
    repair: Repair,
    /// How many edges there were after the repairs: those after them are peeling's.
    repaired_len: usize,
    peeling: Peeling,
    /// Where the first pass read a scatter, which of its points are crowded: then no repair,
    /// no later pass and no proximity chains (see `scatter`).
    scatter: Option<Vec<bool>>,
}

/// The curves of a WDM run in local indices (until the axis has read them), its unassigned
/// points, and for the raw axis the edges of the later passes and those of the holes.
struct Assembly {
    curves: Vec<curves::LocalCurve>,
    unassigned: Vec<u32>,
    later_pass: Vec<[LocalPoint; 2]>,
    holes: Vec<[LocalPoint; 2]>,
}

impl<'t> WdmRun<'t> {
    /// The Voronoi diagram, the water flow's labels and the paper's edges, with the repairs
    /// of the labels (corridors, ears, islets).
    fn first_pass(tri: &'t Triangulation, options: &Options, lap: &mut dyn FnMut(Phase)) -> Self {
        let mut vor = tri.voronoi();
        lap(Phase::Voronoi);
        // Only the labels go on: the sources and the visit marks are freed here (10 bytes per
        // point at the memory peak, which is later).
        let mut labels = wdm::labels(&vor, options.label_rule());
        // The water flow's rounded circumcenters of all vertices (32 bytes a point): nothing
        // up to the pruned axis reads them, and it computes its balls' centres again, so they
        // are not held through the repairs and peeling. The raw axis reads them back.
        if options.medial_axis() != MedialAxisMode::Raw {
            vor.forget_positions();
        }
        lap(Phase::Label);
        let edges = if tri.is_degenerate() {
            chain_edges(tri)
        } else {
            let mut edges = wdm_crust_edges(&vor, &labels);
            // The widths assume the default reading (outer = wet); the others are compared
            // as they are.
            if options.label_rule() == LabelRule::WaterReached {
                repair_corridors(&vor, &mut labels, &mut edges);
            }
            repair_ears(&vor, &mut labels, &mut edges, Ears::Rejoin);
            // The C++ convention leaves islets on clean samples too (ε = 1.2): its reading,
            // which the variants compare, stays as it is.
            if options.label_rule() != LabelRule::Complement {
                drop_islets(&vor, &mut labels, &mut edges);
            }
            edges
        };
        lap(Phase::Extract);
        WdmRun {
            tri,
            vor,
            labels,
            edges,
            repair: Repair::none(),
            repaired_len: 0,
            peeling: Peeling::done(0, 0),
            scatter: None,
        }
    }

    /// The detour repair. It runs on the first pass, before peeling: the stretches it
    /// reattaches are then no leftovers for the later passes, which otherwise closed small
    /// loops through some of them (measured in ARCHITECTURE.md, "Outliers: detour repair").
    fn repairs(&mut self, options: &Options) {
        if options.detour_repair() && !self.tri.is_degenerate() && self.scatter.is_none() {
            self.repair = repair_detours(&self.vor, &self.edges);
        }
        self.repair.apply(&mut self.edges);
        self.repaired_len = self.edges.len();
    }

    /// The later passes on the points no curve reached (holes, nested curves).
    fn peeling(&mut self, options: &Options) {
        if options.peeling() && self.scatter.is_none() {
            self.peeling = peel(&self.vor, &mut self.edges, options);
        }
    }

    /// Open curves settled, the edges assembled into curves; the edges are not held
    /// further.
    fn assembly(&mut self, options: &Options, lap: &mut dyn FnMut(Phase)) -> Assembly {
        let tri = self.tri;
        let mut edges = std::mem::take(&mut self.edges);
        // Edges the first pass did not find (reattached stretches, peeling's): holes may be
        // among them, and the raw medial axis must not cross them (the pruned one takes the
        // inside of the final loops by itself).
        let mut holes_possible = (self.peeling.extra_passes > 0 || !self.repair.added.is_empty())
            && options.medial_axis() == MedialAxisMode::Raw;
        let mut later_pass = Vec::new();
        if holes_possible {
            later_pass.extend_from_slice(&edges[self.repaired_len..]);
            later_pass.extend_from_slice(&self.repair.added);
            later_pass.sort_unstable();
        }
        // Sure loops kept, every other point joined into chains by proximity.
        if options.open_curves() && !tri.is_degenerate() {
            edges = match &self.scatter {
                // A scatter keeps the sure loops that read as curves.
                Some(crowded) => open_curves::sure_loop_edges(&tri.points, &edges, |cycle| {
                    2 * cycle.iter().filter(|p| crowded[p.index()]).count() < cycle.len()
                }),
                None => open_curves::settle(tri, &self.vor, &edges),
            };
        }
        // Closed curves beside others, which peeling takes for their noise: a pass at a
        // time (each finds the outermost of nested ones), within peeling's budget. Like the
        // facing-corner swap below, a part of settling the curves: without the open-curve
        // stage the result is the flow's and peeling's alone.
        let peeling = &mut self.peeling;
        while options.peeling()
            && options.open_curves()
            && self.scatter.is_none()
            && !tri.is_degenerate()
            && !peeling.budget_exhausted
        {
            match clean_loops_beside(&self.vor, &mut edges, options, &mut peeling.budget_left) {
                Beside::Nothing => break,
                Beside::OverBudget => peeling.budget_exhausted = true,
                Beside::Added(loops) => {
                    peeling.extra_passes += 1;
                    if options.medial_axis() == MedialAxisMode::Raw {
                        holes_possible = true;
                        later_pass.extend(loops);
                        later_pass.sort_unstable();
                    }
                }
            }
        }
        lap(Phase::OpenCurves);
        // In local indices until the axis has read them (see `assemble_unnamed`).
        let assemble = |edges: &[[LocalPoint; 2]]| {
            curves::assemble_unnamed(tri.points.len(), edges, &tri.points, |p| tri.input_index(p))
        };
        let mut curves = assemble(&edges);
        // Two closed curves joined across a gap at facing corners, split again.
        if options.open_curves() && self.scatter.is_none() && !tri.is_degenerate() {
            if let Some(swapped) = swap_facing_corners(&self.vor, &curves) {
                edges = swapped;
                curves = assemble(&edges);
            }
        }
        let unassigned = untouched_points(tri, edges.iter().copied());
        let holes = if holes_possible {
            // The edges are distinct: those of the first pass the repair kept, then the
            // later ones. So a final edge is none of the first pass's exactly when it is a
            // later one that the repair had not taken out of the first pass (a later pass
            // may draw again an edge between points a swap left off the curves).
            let removed = &self.repair.removed;
            let not_first_pass = |e: &[LocalPoint; 2]| {
                later_pass.binary_search(e).is_ok() && removed.binary_search(e).is_err()
            };
            hole_edges(&self.vor, &curves, not_first_pass)
        } else {
            Vec::new()
        };
        // The edges (8 bytes a point) are not held through the axis, the memory peak: every
        // edge is in exactly one curve, and they are read off the curves after the axis.
        drop(edges);
        Assembly {
            curves,
            unassigned,
            later_pass,
            holes,
        }
    }

    /// The medial axis of the run's mode (the pruned one of the `fitted` curves where
    /// smoothing moved a loop); then the curves in the caller's indices and the edges read
    /// off them.
    fn axis(
        self,
        assembly: Assembly,
        options: &Options,
        frame: Frame,
        fitted: Option<Vec<Option<[f64; 2]>>>,
    ) -> Outcome {
        let Assembly {
            curves,
            unassigned,
            later_pass,
            holes,
        } = assembly;
        let WdmRun {
            tri,
            vor,
            labels,
            peeling,
            ..
        } = self;
        let medial_axis = match options.medial_axis() {
            MedialAxisMode::Omitted => MedialAxis::default(),
            MedialAxisMode::Pruned => fitted
                .as_deref()
                .and_then(|moved| axis_of_fitted(tri, &curves, moved, frame))
                .unwrap_or_else(|| pruned_medial_axis(vor, &curves, frame)),
            MedialAxisMode::Raw if holes.is_empty() => {
                medial_axis(&vor, &labels, &later_pass, frame)
            }
            MedialAxisMode::Raw => {
                // A vertex is inside the shape when it is inner in the first pass and not
                // inside a hole: an even number of hole loops separate it from infinity.
                let in_hole = parity_inside(&vor, &holes);
                let combined: Vec<Label> = labels
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
                medial_axis(&vor, &combined, &later_pass, frame)
            }
        };
        let curves: Vec<curves::Curve> = curves
            .into_iter()
            .map(|c| c.named(|p| tri.input_index(p)))
            .collect();
        let edges = curves::edges_of(&curves);
        Outcome {
            labels,
            edges,
            curves,
            medial_axis,
            unassigned,
            peeling,
            fitted,
        }
    }
}

/// The pruned medial axis of the closed `curves` (local indices of `tri`) at their `moved`
/// positions ([`smooth::fitted_positions`]); `None` when smoothing moved no point of a
/// loop (the axis of the samples is then that of the curves returned) or when the fitted
/// loops draw no region (see [`fitted_medial_axis`]).
fn axis_of_fitted(
    tri: &Triangulation,
    curves: &[curves::LocalCurve],
    moved: &[Option<[f64; 2]>],
    frame: Frame,
) -> Option<MedialAxis> {
    let mut on_loops = curves.iter().filter(|c| c.closed).flat_map(|c| &c.points);
    if on_loops.all(|&p| moved[p.index()].is_none()) {
        return None;
    }
    let at = |p: LocalPoint| moved[p.index()].unwrap_or(tri.points[p.index()]);
    fitted_medial_axis(curves, at, |p| tri.points[p.index()], frame)
}

/// The reconstruction of a dense band through its `representatives` (local indices of
/// `tri`, ascending), lifted to all the points: the curves, edges, axis and warnings of the
/// representatives' reconstruction in the caller's indices, every other point unassigned,
/// the triangulation of all points, no labels (they belong to the representatives'
/// Voronoi diagram), the smoothing fitted to all the samples.
fn thinned(
    points: &[[f64; 2]],
    mut tri: Triangulation,
    frame: Frame,
    representatives: &[LocalPoint],
    options: &Options,
    on_phase: &mut dyn FnMut(Phase, std::time::Duration),
) -> Result<Reconstruction, Error> {
    let mut ids: Vec<u32> = representatives
        .iter()
        .map(|&p| tri.input_index(p))
        .collect();
    ids.sort_unstable();
    let chosen: Vec<[f64; 2]> = ids.iter().map(|&i| points[i as usize]).collect();
    let inner_options = options.with_thinning(false).with_smoothing(false);
    let inner = reconstruct_observed(&chosen, &inner_options, on_phase)?;
    let clock = PhaseClock::start();
    // `ids` is ascending, so the translation keeps every order: edges `[i, j]` with `i < j`,
    // sorted; curves starting where they started.
    let id = |k: u32| ids[k as usize];
    let curves: Vec<curves::Curve> = inner
        .curves
        .iter()
        .map(|c| curves::Curve {
            closed: c.closed,
            points: c.points.iter().map(|&k| id(k)).collect(),
        })
        .collect();
    let edges: Vec<[u32; 2]> = inner.edges.iter().map(|e| [id(e[0]), id(e[1])]).collect();
    let mut on_curve = vec![false; points.len()];
    for &p in curves.iter().flat_map(|c| c.points.iter()) {
        on_curve[p as usize] = true;
    }
    // Every kept point on no curve, ascending: marked through `input_of` (in local order)
    // and read off in caller order, which a sort of most of the points cost 4 % of a
    // thinned run.
    let mut off_curve = vec![false; points.len()];
    for &i in &tri.input_of {
        off_curve[i as usize] = !on_curve[i as usize];
    }
    let unassigned: Vec<u32> = (0..points.len() as u32)
        .filter(|&i| off_curve[i as usize])
        .collect();
    let warnings: Vec<super::Warning> = inner
        .warnings()
        .iter()
        .map(|w| super::Warning {
            code: w.code,
            message: w.message.clone(),
            points: w.points.iter().map(|&k| id(k)).collect(),
        })
        .collect();
    let fitted = smoothing(&tri, &curves, options, Fitted::Every);
    // With smoothing, the axis of the fitted curves (fitted to all the samples) instead of
    // the representatives' loops.
    let fitted_axis = match &fitted {
        Some(moved) if options.medial_axis() == MedialAxisMode::Pruned => {
            axis_of_fitted(&tri, &local_curves(&tri, &curves), moved, frame)
        }
        _ => None,
    };
    let medial_axis = fitted_axis.unwrap_or(inner.medial_axis);
    frame.restore(&mut tri, points);
    let fitted = fitted.map(|moved| frame.fitted_to_caller(&tri, moved));
    on_phase(Phase::Curves, clock.elapsed());
    let cell = std::sync::OnceLock::new();
    let _ = cell.set(warnings);
    Ok(Reconstruction {
        algorithm: options.algorithm(),
        triangulation: tri,
        labels: Vec::new(),
        edges,
        curves,
        medial_axis,
        medial_axis_mode: Some(options.medial_axis()),
        unassigned,
        passes: inner.passes,
        budget_exhausted: inner.budget_exhausted,
        fitted,
        warnings: cell,
        thinned: Some(ids.len()),
    })
}

/// With [`Options::with_smoothing`], the fitted positions of the points of `curves` by
/// local index, in the frame of `tri` (the curves in caller indices).
fn smoothing(
    tri: &Triangulation,
    curves: &[curves::Curve],
    options: &Options,
    which: Fitted,
) -> Option<Vec<Option<[f64; 2]>>> {
    if !options.smoothing() {
        return None;
    }
    Some(smooth::fitted_positions(
        tri,
        &local_curves(tri, curves),
        which,
    ))
}

/// `curves` (caller indices) in the local indices of `tri`.
fn local_curves(tri: &Triangulation, curves: &[curves::Curve]) -> Vec<curves::LocalCurve> {
    curves
        .iter()
        .map(|c| curves::LocalCurve::from_caller(c, |i| tri.local_index(i)))
        .collect()
}

/// The curves of distinct local `edges`, in caller indices (see
/// [`curves::assemble_named`]).
fn assemble(tri: &Triangulation, edges: &[[LocalPoint; 2]]) -> Vec<curves::Curve> {
    curves::assemble_named(tri.points.len(), edges, &tri.points, |p| tri.input_index(p))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::triangulate;
    use crate::reconstruct::extract::EdgeClass;
    use crate::reconstruct::MedialAxisMode;
    use crate::voronoi::{EdgeEnd, Voronoi};
    use std::collections::BTreeSet;
    use wdm_crust_testkit::Rng;

    /// WDM_CRUST edges off the public view of the dual (caller indices).
    fn public_crust_edges(vor: &Voronoi<'_>, labels: &[Label]) -> Vec<[u32; 2]> {
        let mut edges = Vec::new();
        for v in vor.vertex_ids() {
            for edge in vor.vertex_edges(v) {
                let far = match edge.to {
                    EdgeEnd::Vertex(u) => labels[u.index()],
                    EdgeEnd::Infinity => Label::Outer,
                };
                if EdgeClass::of(labels[v.index()], far) == EdgeClass::Branch {
                    let [a, b] = edge.sites;
                    edges.push([a.min(b), a.max(b)]);
                }
            }
        }
        edges.sort_unstable();
        edges.dedup();
        edges
    }

    /// What the detour repair may change: it swaps a detour for a stretch of unassigned
    /// points, so every point keeps degree 2 or goes between degrees 0 and 2, the irregular
    /// points stay, and every edge it adds is a Delaunay edge.
    fn assert_swaps_only(plain: &Reconstruction, repaired: &Reconstruction, round: usize) {
        let tri = plain.triangulation();
        let degrees = |edges: &[[u32; 2]]| {
            let mut degree = vec![0usize; tri.point_count()];
            for &[a, b] in edges {
                degree[a as usize] += 1;
                degree[b as usize] += 1;
            }
            degree
        };
        let (before, after) = (degrees(plain.edges()), degrees(repaired.edges()));
        for (p, (&d0, &d1)) in before.iter().zip(&after).enumerate() {
            let swapped = (d0 == 0 || d0 == 2) && (d1 == 0 || d1 == 2);
            assert!(d0 == d1 || swapped, "round {round}: point {p}: {d0} → {d1}");
        }
        assert_eq!(plain.irregular_points(), repaired.irregular_points());
        let vor = tri.voronoi();
        for &[a, b] in repaired.edges() {
            let (a, b) = (tri.local_index(a), tri.local_index(b));
            assert!(vor.is_delaunay_edge(a, b), "round {round}: {a}–{b}");
        }
    }

    /// The pipeline runs on local indices and translates once; its result must be what the
    /// same steps give through the public API alone, on the caller's indices: the first pass
    /// exactly, and what peeling adds only Delaunay edges between points the first pass left
    /// untouched (which of them is peel.rs's rule, tested there).
    #[test]
    fn the_pipeline_equals_its_steps_on_caller_indices() {
        let mut rng = Rng::new(3);
        let mut peeled = 0;
        let mut ears_repaired = 0;
        for round in 0..40 {
            let n = 20 + rng.below(400);
            // Two nested noisy loops (so peeling runs) plus a few scattered points and
            // duplicates, shuffled.
            let mut points: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let t = i as f64 / n as f64 * std::f64::consts::TAU;
                    let r = if i % 3 == 0 { 0.5 } else { 1.0 } + 0.01 * rng.normal();
                    [r * t.cos(), 0.8 * r * t.sin()]
                })
                .collect();
            points.extend((0..rng.below(5)).map(|_| [rng.range(-1.5, 1.5), rng.f64()]));
            for _ in 0..rng.below(4) {
                let p = points[rng.below(points.len())];
                points.push(p);
            }
            rng.shuffle(&mut points);
            for peeling in [false, true] {
                // The steps without the detour repair; what the repair changes is checked
                // below.
                // The water flow's own result: the open-curve stage, which reads it, is
                // tested in open_curves.rs and tests/open_curves.rs.
                let options = Options::new()
                    .with_peeling(peeling)
                    .with_detour_repair(false)
                    .with_open_curves(false)
                    .with_medial_axis(MedialAxisMode::Raw);
                let rec = reconstruct_with(&points, &options).unwrap();
                let repaired =
                    reconstruct_with(&points, &options.with_detour_repair(true)).unwrap();
                assert_swaps_only(&rec, &repaired, round);

                let tri = triangulate(&points).unwrap();
                let vor = tri.voronoi();
                let mut labels = wdm::label_vertices(&vor, options.label_rule()).labels;
                // The ear repair on local edges; its labels then give the same edges through
                // the public view.
                let mut local = wdm_crust_edges(&vor, &labels);
                let repaired = repair_corridors(&vor, &mut labels, &mut local)
                    + repair_ears(&vor, &mut labels, &mut local, Ears::Rejoin)
                    + drop_islets(&vor, &mut labels, &mut local);
                assert_eq!(options.label_rule(), LabelRule::WaterReached);
                ears_repaired += usize::from(repaired > 0);
                assert_eq!(rec.labels(), &labels[..], "round {round}");
                let first_pass = public_crust_edges(&vor, &labels);
                assert_eq!(tri.to_input_edges(local), first_pass, "round {round}");
                let delaunay: BTreeSet<[u32; 2]> = tri
                    .halfedge_ids()
                    .map(|e| {
                        let (a, b) = (tri.halfedge_origin(e), tri.halfedge_destination(e));
                        [a.min(b), a.max(b)]
                    })
                    .collect();
                let edges = rec.edges().to_vec();
                // The first pass exactly; later passes only add Delaunay edges between
                // points the first pass left untouched (their selection is peel.rs's).
                let first_touched: BTreeSet<u32> = first_pass.iter().flatten().copied().collect();
                let first_set: BTreeSet<[u32; 2]> = first_pass.iter().copied().collect();
                assert!(first_set.iter().all(|e| edges.contains(e)), "round {round}");
                for e in edges.iter().filter(|&e| !first_set.contains(e)) {
                    assert!(peeling, "round {round}: {e:?} without peeling");
                    assert!(delaunay.contains(e), "round {round}: {e:?}");
                    assert!(
                        e.iter().all(|p| !first_touched.contains(p)),
                        "round {round}"
                    );
                }
                let grew = edges.len() > first_pass.len();
                assert!(peeling || rec.passes() == 1, "round {round}");
                assert!(!grew || rec.passes() > 1, "round {round}");
                peeled += usize::from(grew);
                assert_eq!(rec.edges(), &edges[..], "round {round}");
                let curves = curves::assemble(points.len(), &edges, &points);
                assert_eq!(rec.curves(), &curves[..], "round {round}");
                assert!(rec.triangulation().triangles().eq(tri.triangles()));
                assert!(rec.triangulation().hull().eq(tri.hull()));
                let untouched: Vec<u32> = (0..points.len() as u32)
                    .filter(|&i| !tri.is_duplicate(i) && !edges.iter().flatten().any(|&p| p == i))
                    .collect();
                assert_eq!(rec.untouched_points(), untouched, "round {round}");
                assert_eq!(rec.unassigned(), untouched, "round {round}");
                if !grew {
                    let axis = medial_axis(&vor, &labels, &[], Frame::CALLER);
                    assert_eq!(rec.medial_axis(), &axis, "round {round}");
                }
            }
        }
        assert!(peeled > 5, "peeling ran in only {peeled} rounds");
        assert!(ears_repaired > 0, "no ear in any round");
    }
}
