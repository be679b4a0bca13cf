//! Smoothing (on demand, [`Options::with_smoothing`](super::Options::with_smoothing)):
//! every curve vertex placed on a local fit of the samples around it, the last stage, on the
//! assembled curves (the pruned medial axis is then taken of the fitted curves). The design note is
//! `docs/design/smoothing.md`; every tolerance below is a named constant with its argument.
//!
//! # Which curves
//!
//! A curve is smoothed when it [zigzags](super::curves::zigzags): more than
//! [`ZIGZAG_SHARE`](super::thresholds::smooth::ZIGZAG_SHARE) of its vertices turn against both
//! neighbours (exact orientations, turns below [`FLAT`](super::thresholds::smooth::FLAT)
//! counted as none). Where
//! noise sets the turns, about a quarter of the vertices do; clean ε-samples and polygons
//! turn one way along every run between inflections, and are left exactly as they are.
//! Junctions (points on three or more edges) stay too.
//!
//! # The samples around a vertex
//!
//! Every input point, on a curve or not, within a radius `R` of the vertex `p`, gathered in
//! order of distance along Delaunay edges at most [`LINK`] nearest-neighbour distances long
//! (in a dense noise band most points are on no curve, and they are what the fit averages;
//! the short edges keep the gathering off the other side of a sparse curve and off another
//! band). Each sample is weighted by the biweight `(1 − (d/R)²)²` of its distance and takes
//! the side of its nearest curve vertex around `p`: ahead, behind, or `p` itself (both).
//!
//! # The fit
//!
//! The radius grows from the vertex's longer curve step by [`SCALE_STEP`] (at most
//! [`WINDOWS`] radii and [`MAX_WINDOW_POINTS`] samples), and three families of windows are
//! fitted at each radius:
//!
//! * the *centred* window: Taubin's algebraic circle fit where its radius is between
//!   [`MIN_CIRCLE_RADIUS`] and [`LINE_RADIUS`] windows, else a quadratic over the window's
//!   total-least-squares line; the vertex goes onto it along its normal;
//! * the *one-sided* windows, the samples of each side: a total-least-squares line,
//!   reweighted robustly (Tukey's biweight on the residuals), the vertex projected onto it.
//!
//! A window is fitted once it is a curve piece, not a blob: [`MIN_FIT_POINTS`] samples
//! ([`MIN_LINE_POINTS`] a side) and an aspect of at most [`MAX_ASPECT`]. A family grows
//! while its next window's offset of the vertex agrees with every smaller window's within
//! [`AGREEMENT`] standard errors of their difference (the intersection of confidence
//! intervals rule, with the difference's error of nested estimates), its residual stays
//! within [`RESIDUAL_GROWTH`] of its window of half the radius, and (a side) it moves the
//! vertex by at most [`SHIFT_RESIDUALS`] residuals. On a noise band the offsets scatter
//! within their shrinking errors and the window grows; where it reaches a bend the fit
//! cannot follow, a corner, or another piece of the curve, the offset drifts or the
//! residual grows, and the growth stops. The centred family's last fit is taken unless a
//! side's last fit has less than 1/[`SIDED_PREFERENCE`] of the centred residual at the same
//! radius: at a corner the centred fit rounds it off and its residual shows it, while each
//! side is straight, and the vertex stays on its own side's line.
//!
//! # Simple curves, exactly
//!
//! The fit is rounded arithmetic; whether the moved curves are simple is decided exactly
//! ([`crossings`]): every pair of curve segments (of all curves) is tested with the
//! kernel's exact orientation, two segments that share an end may not fold over each
//! other, and a closed curve must still run counterclockwise. Where a test fails, the moves
//! of the points involved are halved, then undone, and the test runs again until nothing
//! fails; the unsmoothed curves are edges of one triangulation, so the loop ends.
//!
//! Everything runs in the reconstruction's frame (the points exactly rescaled) on the
//! triangulation's local indices, the samples of every sum in local order: the result is
//! the same in any input order and for every exact power-of-two scaling.

mod crossings;

use std::collections::{BinaryHeap, HashMap, HashSet};

use super::curves::{zigzags, LocalCurve};
use super::delaunay_graph::{mix, FastHash, Graph, Waiting};
use super::lengths::distance;
use super::thresholds::smooth::{
    AGREEMENT, LINE_RADIUS, LINK, MAD_TO_SIGMA, MAX_ASPECT, MAX_WINDOW_POINTS, MAX_WINDOW_VERTICES,
    MIN_CIRCLE_RADIUS, MIN_FIT_POINTS, MIN_LINE_POINTS, RESIDUAL_GROWTH, ROBUST_ITERATIONS,
    SCALE_STEP, SHIFT_RESIDUALS, SIDED_PREFERENCE, TUKEY, WINDOWS, WINDOW_STEPS,
};
use crate::delaunay::Triangulation;
use crate::ids::LocalPoint;
use crate::parallel;

/// Residuals and standard errors below this share of the radius are rounding, not noise:
/// on samples exactly on a line every fit's are about `1e-16 R`.
const RESIDUAL_FLOOR: f64 = 1e-12;

/// Which curves are fitted.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Fitted {
    /// Those that zigzag: noise is read off the curve itself.
    Zigzagging,
    /// Every curve: the curves of a band's representatives, which run smoothly along the
    /// band's middle (they zigzag less the more points a band has) and lie off the true
    /// curve by a share of the band's noise that the fit to all its samples takes back.
    Every,
}

/// The fitted position of every point of `curves` (local indices, in the frame of `tri`),
/// `None` for a point that stays where it is; indexed by local point.
pub(super) fn fitted_positions(
    tri: &Triangulation,
    curves: &[LocalCurve],
    which: Fitted,
) -> Vec<Option<[f64; 2]>> {
    let n = tri.points.len();
    let mut moved = vec![None; n];
    if tri.is_degenerate() || curves.is_empty() {
        return moved;
    }
    let graph = Graph::new(tri);
    // Every curve vertex with its two curve neighbours (a chain end: one), junctions left
    // out: the vertices are the points of degree 1 or 2.
    let mut degree = vec![0u8; n];
    for c in curves {
        let k = c.points.len();
        let edges = if c.closed { k } else { k.saturating_sub(1) };
        for i in 0..edges {
            for p in [c.points[i], c.points[(i + 1) % k]] {
                degree[p.index()] = degree[p.index()].saturating_add(1);
            }
        }
    }
    let mut vertices: Vec<(usize, usize)> = Vec::new();
    for (j, c) in curves.iter().enumerate() {
        if c.points.len() < 2 || (which == Fitted::Zigzagging && !zigzags(&tri.points, c)) {
            continue;
        }
        for (i, &p) in c.points.iter().enumerate() {
            if degree[p.index()] <= 2 {
                vertices.push((j, i));
            }
        }
    }
    // Where the samples are many to a curve vertex (a band's representatives: hundreds of
    // samples a step), the windows keep one sample in `rate`, so that MAX_WINDOW_POINTS of
    // them span WINDOW_STEPS steps: taking every sample, a window was still round at the
    // cap (no curve piece), and the curves of bands of 20 000 points a curve did not move.
    let vertex_count = curves.iter().map(|c| c.points.len()).sum::<usize>().max(1);
    let rate = WINDOW_STEPS
        .saturating_mul(n.div_ceil(vertex_count))
        .div_ceil(MAX_WINDOW_POINTS)
        .max(1) as u64;
    let fits = parallel::map_range(vertices.len(), |v| {
        let (j, i) = vertices[v];
        fit_vertex(tri, &graph, &curves[j], i, rate)
    });
    for (&(j, i), fit) in vertices.iter().zip(fits) {
        moved[curves[j].points[i].index()] = fit;
    }
    crossings::undo_crossings(&tri.points, curves, &mut moved);
    moved
}

/// One fit of one window, in the frame's units: where it puts the vertex, its normal
/// there, its residual (the samples' weighted RMS distance from it, corrected for the
/// fitted parameters) and the standard error of the vertex's offset along the normal.
#[derive(Clone, Copy, Debug)]
struct Fit {
    position: [f64; 2],
    /// How far the vertex moves.
    shift: f64,
    normal: [f64; 2],
    residual: f64,
    error: f64,
}

/// What one family of windows has found so far: the fits it accepted, the last one best.
#[derive(Default)]
struct Family {
    accepted: Vec<Fit>,
    stopped: bool,
    /// The residual of every window offered (accepted or not), `None` where it was no
    /// curve piece.
    residuals: Vec<Option<f64>>,
    /// The window of the last accepted fit.
    last: usize,
}

impl Family {
    /// The family's next (larger) window: accepted while its offset agrees with every
    /// smaller window's within [`AGREEMENT`] standard errors of the two (the intersection
    /// of confidence intervals rule); the family stops at the first that does not, and at
    /// a window that is no curve piece after one that was.
    fn offer(&mut self, fit: Option<Fit>, radius: f64, sided: bool) {
        let fit = fit.map(|f| Fit {
            residual: f.residual.max(RESIDUAL_FLOOR * radius),
            ..f
        });
        self.residuals.push(fit.map(|f| f.residual));
        if self.stopped {
            return;
        }
        let Some(fit) = fit else {
            self.stopped = !self.accepted.is_empty();
            return;
        };
        let along = |p: [f64; 2]| p[0] * fit.normal[0] + p[1] * fit.normal[1];
        let smallest = self
            .accepted
            .iter()
            .map(|f| f.residual)
            .fold(f64::INFINITY, f64::min);
        // The vertex is one of the samples a side's fit describes: its distance from the
        // fit is one of theirs. A side's fit that puts it much further is one of something
        // else (the other leg of a sharp corner beside it).
        let level = fit.residual <= RESIDUAL_GROWTH * smallest
            && (!sided || fit.shift <= SHIFT_RESIDUALS * fit.residual);
        let agrees = level
            && self.accepted.iter().all(|earlier| {
                (along(fit.position) - along(earlier.position)).abs()
                    <= AGREEMENT
                        * (earlier.error * earlier.error - fit.error * fit.error)
                            .max(0.0)
                            .sqrt()
            });
        if agrees {
            self.accepted.push(fit);
            self.last = self.residuals.len() - 1;
        } else {
            self.stopped = true;
        }
    }

    fn best(&self) -> Option<Fit> {
        self.accepted.last().copied()
    }
}

/// The fitted position of the `i`-th vertex of `curve` (local indices); `None` where no
/// window is a curve piece, the samples are clean, or the arithmetic fails.
fn fit_vertex(
    tri: &Triangulation,
    graph: &Graph,
    curve: &LocalCurve,
    i: usize,
    rate: u64,
) -> Option<[f64; 2]> {
    let at = |q: LocalPoint| tri.points[q.index()];
    let k = curve.points.len();
    // The vertex `offset` places along the curve (`None` past a chain's end; on a loop,
    // the two directions never meet).
    let along = |offset: isize| -> Option<LocalPoint> {
        let j = i as isize + offset;
        if curve.closed {
            (2 * offset.unsigned_abs() < k).then(|| curve.points[j.rem_euclid(k as isize) as usize])
        } else {
            (0..k as isize)
                .contains(&j)
                .then(|| curve.points[j as usize])
        }
    };
    let p = curve.points[i];
    let o = at(p);
    let step = [-1, 1]
        .into_iter()
        .filter_map(&along)
        .map(|q| distance(o, at(q)))
        .fold(0.0f64, f64::max);
    if !(step.is_finite() && step > 0.0) {
        return None;
    }
    // The side of a sample is that of its nearest vertex of the curve around `p`, walked
    // in both directions as far as the windows reach: ahead (1), behind (-1) or `p` itself
    // (0, on both sides). At a corner the samples of each leg are nearest to that leg's
    // vertices, whatever the corner's angle and however unequal the steps.
    // A sample that is a guide vertex takes its side at once (on a clean curve every
    // sample is, and a search of the guide for each would cost the window's size squared).
    let mut guide: Vec<(LocalPoint, i8)> = vec![(p, 0)];
    let mut guide_side: HashMap<LocalPoint, i8, FastHash> = HashMap::default();
    guide_side.insert(p, 0);
    let mut walked = [0isize; 2];
    let mut extend = |guide: &mut Vec<(LocalPoint, i8)>,
                      guide_side: &mut HashMap<LocalPoint, i8, FastHash>,
                      radius: f64| {
        for (d, sign) in [(0, 1isize), (1, -1)] {
            while guide.len() < MAX_WINDOW_POINTS {
                let Some(q) = along(sign * (walked[d] + 1)) else {
                    break;
                };
                walked[d] += 1;
                guide.push((q, sign as i8));
                guide_side.entry(q).or_insert(sign as i8);
                if !at_most(distance(o, at(q)), radius) {
                    break;
                }
            }
        }
    };
    let side_of = |guide: &[(LocalPoint, i8)],
                   guide_side: &HashMap<LocalPoint, i8, FastHash>,
                   q: LocalPoint|
     -> i8 {
        if let Some(&side) = guide_side.get(&q) {
            return side;
        }
        let x = at(q);
        guide
            .iter()
            .map(|&(g, side)| (distance(x, at(g)), side))
            .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.abs().cmp(&b.1.abs())))
            .map_or(0, |(_, side)| side)
    };
    let mut seen: HashSet<LocalPoint, FastHash> = HashSet::default();
    let mut waiting = BinaryHeap::new();
    let mut window: Vec<(f64, LocalPoint, i8)> = Vec::new();
    // The window by local index, merged as it grows.
    let mut sorted: Vec<(f64, LocalPoint, i8)> = Vec::new();
    seen.insert(p);
    waiting.push(Waiting(0.0, p));
    let mut families: [Family; 3] = Default::default();
    let mut radius = step;
    let mut fitted_size = 0;
    for _ in 0..WINDOWS {
        extend(&mut guide, &mut guide_side, radius);
        // Every sample within `radius` reachable through such samples, in distance order.
        while let Some(Waiting(d, q)) = waiting.peek() {
            if *d >= radius || window.len() >= MAX_WINDOW_POINTS {
                break;
            }
            let (d, q) = (*d, *q);
            waiting.pop();
            if rate == 1 || q == p || mix(q.get() as u64) % rate == 0 {
                window.push((d, q, side_of(&guide, &guide_side, q)));
            }
            for &w in graph.of(q) {
                // Along the curve's samples only: not across the inside of a sparse curve,
                // nor from one noise band to the next.
                let reach = LINK * graph.nearest[q.index()].max(graph.nearest[w.index()]);
                if !at_most(distance(at(q), at(w)), reach) {
                    continue;
                }
                if seen.insert(w) {
                    let dw = distance(o, at(w));
                    if dw.is_finite() {
                        waiting.push(Waiting(dw, w));
                    }
                }
            }
        }
        // A window of the same samples as the last one fitted is no new evidence (only its
        // weights differ); once nothing is left to reach, the windows are done.
        if window.len() == fitted_size {
            if waiting.is_empty() {
                break;
            }
            radius *= SCALE_STEP;
            continue;
        }
        fitted_size = window.len();
        // The samples in a fixed order (by local index), so that the sums are the same
        // however they were reached.
        let mut fresh = window[sorted.len()..].to_vec();
        fresh.sort_unstable_by_key(|&(_, q, _)| q);
        sorted = merged_by_index(&sorted, &fresh);
        let samples = &sorted;
        let offsets: Vec<Sample> = samples
            .iter()
            .map(|&(d, q, side)| {
                let x = at(q);
                let u = [(x[0] - o[0]) / radius, (x[1] - o[1]) / radius];
                let t = d / radius;
                let w = (1.0 - t * t).max(0.0);
                Sample {
                    at: u,
                    weight: w * w,
                    side,
                }
            })
            .collect();
        let unscale = |fit: Option<Fit>| {
            fit.map(|f| Fit {
                position: [o[0] + f.position[0] * radius, o[1] + f.position[1] * radius],
                shift: f.position[0].hypot(f.position[1]) * radius,
                normal: f.normal,
                residual: f.residual * radius,
                error: (f.error.max(RESIDUAL_FLOOR)) * radius,
            })
        };
        // A stopped side needs no more fits; the centred family's residuals are read at
        // the sides' windows, so it is fitted while either side grows.
        families[0].offer(unscale(quadratic_fit(&offsets, |_| true)), radius, false);
        for (family, ahead) in families[1..].iter_mut().zip([true, false]) {
            if family.stopped {
                family.residuals.push(None);
                continue;
            }
            let use_side = |s: i8| if ahead { s >= 0 } else { s <= 0 };
            family.offer(unscale(line_fit(&offsets, use_side)), radius, true);
        }
        if families.iter().all(|f| f.stopped)
            || window.len() >= MAX_WINDOW_POINTS
            || guide.len() >= MAX_WINDOW_VERTICES
        {
            break;
        }
        radius *= SCALE_STEP;
    }
    // A corner: at the centred family's last window, a side fits much better than the
    // whole disk. The residuals are compared at one window, where they average as many
    // samples: a small window's residual is a poor estimate.
    let [centred, ahead, behind] = &families;
    // A corner: a side fits much better than the whole disk at the side's own last window
    // (where the two average about as many samples: a small window's residual alone is a
    // poor estimate), and of such sides the better one is taken.
    let sided = [ahead, behind]
        .into_iter()
        .filter_map(|side| {
            let fit = side.best()?;
            let whole = centred.residuals.get(side.last).copied().flatten()?;
            (whole > SIDED_PREFERENCE * fit.residual).then_some((side, fit))
        })
        .min_by(|x, y| x.1.residual.total_cmp(&y.1.residual));
    let (_, chosen) = match (sided, centred.best()) {
        (Some(side), _) => side,
        (None, Some(c)) => (centred, c),
        (None, None) => [ahead, behind]
            .into_iter()
            .filter_map(|f| Some((f, f.best()?)))
            .min_by(|x, y| x.1.residual.total_cmp(&y.1.residual))?,
    };
    let position = chosen.position;
    (position[0].is_finite() && position[1].is_finite() && position != o).then_some(position)
}

/// Two lists of window samples, each by local index, as one by local index.
fn merged_by_index(
    a: &[(f64, LocalPoint, i8)],
    b: &[(f64, LocalPoint, i8)],
) -> Vec<(f64, LocalPoint, i8)> {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        if a[i].1 < b[j].1 {
            out.push(a[i]);
            i += 1;
        } else {
            out.push(b[j]);
            j += 1;
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

/// A sample of a window: its offset from the vertex in units of the radius, its weight,
/// and its side (1 ahead, -1 behind, 0 the vertex itself).
struct Sample {
    at: [f64; 2],
    weight: f64,
    side: i8,
}

/// The weighted principal frame of the samples of the sides `use_side`.
struct Frame {
    centroid: [f64; 2],
    /// The unit direction of the larger variance.
    tangent: [f64; 2],
    /// The smaller variance (weighted mean).
    small: f64,
    /// Σw(u − ū)² along the tangent, Σw²(u − ū)².
    spread: f64,
    spread2: f64,
    /// Σw and Σw².
    sw: f64,
    sw2: f64,
}

/// The weighted principal frame of the samples `use_side(side)`; `None` with fewer than
/// [`MIN_FIT_POINTS`] samples of positive weight or an aspect above [`MAX_ASPECT`].
fn principal_frame(
    samples: &[Sample],
    use_side: &impl Fn(i8) -> bool,
    fewest: usize,
) -> Option<Frame> {
    let used = || {
        samples
            .iter()
            .filter(|s| s.weight > 0.0 && use_side(s.side))
    };
    let (mut count, mut sw, mut sw2, mut sx, mut sy) = (0, 0.0, 0.0, 0.0, 0.0);
    for s in used() {
        count += 1;
        sw += s.weight;
        sw2 += s.weight * s.weight;
        sx += s.weight * s.at[0];
        sy += s.weight * s.at[1];
    }
    if count < fewest || !positive(sw) {
        return None;
    }
    let m = [sx / sw, sy / sw];
    let (mut cxx, mut cxy, mut cyy) = (0.0, 0.0, 0.0);
    for s in used() {
        let (dx, dy) = (s.at[0] - m[0], s.at[1] - m[1]);
        cxx += s.weight * dx * dx;
        cxy += s.weight * dx * dy;
        cyy += s.weight * dy * dy;
    }
    let (cxx, cxy, cyy) = (cxx / sw, cxy / sw, cyy / sw);
    let half_trace = 0.5 * (cxx + cyy);
    let root = (0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy).sqrt();
    let (large, small) = (half_trace + root, (half_trace - root).max(0.0));
    if !positive(large) || small > MAX_ASPECT * large {
        return None;
    }
    // The eigenvector of the larger eigenvalue, from the better conditioned of the two
    // forms.
    let direction = if cxx >= cyy {
        [large - cyy, cxy]
    } else {
        [cxy, large - cxx]
    };
    let norm = direction[0].hypot(direction[1]);
    if !positive(norm) {
        return None;
    }
    let t = [direction[0] / norm, direction[1] / norm];
    let (mut spread, mut spread2) = (0.0, 0.0);
    for s in used() {
        let u = (s.at[0] - m[0]) * t[0] + (s.at[1] - m[1]) * t[1];
        spread += s.weight * u * u;
        spread2 += s.weight * s.weight * u * u;
    }
    Some(Frame {
        centroid: m,
        tangent: t,
        small,
        spread,
        spread2,
        sw,
        sw2,
    })
}

/// The residual variance `mean` (weighted) corrected for `parameters` fitted with the
/// effective sample count `(Σw)² / Σw²`, as a residual; `None` when the count does not
/// exceed the parameters by more than one.
fn corrected(mean: f64, sw: f64, sw2: f64, parameters: f64) -> Option<f64> {
    let effective = sw * sw / sw2;
    (effective > parameters + 1.0).then(|| (mean * effective / (effective - parameters)).sqrt())
}

/// The vertex (at the origin) projected onto the total-least-squares line of the samples
/// of the sides `use_side`; `None` where the samples are no curve piece.
fn line_fit(samples: &[Sample], use_side: impl Fn(i8) -> bool) -> Option<Fit> {
    let mut f = principal_frame(samples, &use_side, MIN_LINE_POINTS)?;
    // Robustly: a side's half disk may take in a few samples of the other side of a corner
    // far from the vertex; Tukey's biweight on the residuals (scale from their median)
    // gives them no weight, and noise its ordinary one.
    // One buffer each for the residuals and the reweighted samples, refilled every round.
    let mut residuals: Vec<f64> = Vec::with_capacity(samples.len());
    let mut robust: Vec<Sample> = Vec::with_capacity(samples.len());
    for _ in 0..ROBUST_ITERATIONS {
        let (m, t) = (f.centroid, f.tangent);
        let across = |s: &Sample| ((s.at[0] - m[0]) * -t[1] + (s.at[1] - m[1]) * t[0]).abs();
        residuals.clear();
        residuals.extend(
            samples
                .iter()
                .filter(|s| s.weight > 0.0 && use_side(s.side))
                .map(across),
        );
        let middle = residuals.len() / 2;
        let median = *residuals.select_nth_unstable_by(middle, f64::total_cmp).1;
        let scale = TUKEY * (MAD_TO_SIGMA * median).max(RESIDUAL_FLOOR);
        robust.clear();
        robust.extend(samples.iter().map(|s| {
            let r = across(s) / scale;
            let w = (1.0 - r * r).max(0.0);
            Sample {
                at: s.at,
                weight: s.weight * w * w,
                side: s.side,
            }
        }));
        match principal_frame(&robust, &use_side, MIN_LINE_POINTS) {
            Some(next) => f = next,
            None => break,
        }
    }
    let (m, t) = (f.centroid, f.tangent);
    // The origin's projection: m + ((0 − m)·t) t.
    let along = -(m[0] * t[0] + m[1] * t[1]);
    let position = [m[0] + along * t[0], m[1] + along * t[1]];
    let residual = corrected(f.small, f.sw, f.sw2, 2.0)?;
    // The offset's variance: the centroid's across the line, and the direction's times
    // the distance along it.
    let factor = f.sw2 / (f.sw * f.sw) + along * along * f.spread2 / (f.spread * f.spread);
    Some(Fit {
        position,
        shift: 0.0,
        normal: [-t[1], t[0]],
        residual,
        error: residual * factor.sqrt(),
    })
}

/// The vertex (at the origin) moved along the normal of the samples' total-least-squares
/// line onto the weighted quadratic `v = c₀ + c₁u + c₂u²` over it (`u` along the line, `v`
/// across, from the origin): the moving-least-squares projection; the line's projection
/// where the quadratic is ill-conditioned.
fn quadratic_fit(samples: &[Sample], use_side: impl Fn(i8) -> bool + Copy) -> Option<Fit> {
    let f = principal_frame(samples, &use_side, MIN_FIT_POINTS)?;
    let t = f.tangent;
    let n = [-t[1], t[0]];
    let used = || {
        samples
            .iter()
            .filter(|s| s.weight > 0.0 && use_side(s.side))
    };
    let coordinates = |s: &Sample| {
        let u = s.at[0] * t[0] + s.at[1] * t[1];
        let v = s.at[0] * n[0] + s.at[1] * n[1];
        (u, v)
    };
    // Normal equations of the weighted least squares in (1, u, u²), and Σw² b bᵀ for the
    // variance of c₀.
    let mut a = [[0.0f64; 3]; 3];
    let mut b2 = [[0.0f64; 3]; 3];
    let mut rhs = [0.0f64; 3];
    for s in used() {
        let (u, v) = coordinates(s);
        let basis = [1.0, u, u * u];
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] += s.weight * basis[i] * basis[j];
                b2[i][j] += s.weight * s.weight * basis[i] * basis[j];
            }
            rhs[i] += s.weight * basis[i] * v;
        }
    }
    let (Some(c), Some(g)) = (solve3(a, rhs), solve3(a, [1.0, 0.0, 0.0])) else {
        return line_fit(samples, use_side);
    };
    let mut residual = 0.0;
    for s in used() {
        let (u, v) = coordinates(s);
        let r = v - (c[0] + c[1] * u + c[2] * u * u);
        residual += s.weight * r * r;
    }
    let residual = corrected(residual / f.sw, f.sw, f.sw2, 3.0)?;
    // Var c₀ = σ² gᵀ B g with g the first column of A⁻¹.
    let mut factor = 0.0;
    for i in 0..3 {
        for j in 0..3 {
            factor += g[i] * b2[i][j] * g[j];
        }
    }
    // Within the window, or the fit is not to be trusted.
    if !(c[0].abs() <= 1.0 && factor >= 0.0) {
        return None;
    }
    let quadratic = Fit {
        position: [c[0] * n[0], c[0] * n[1]],
        shift: 0.0,
        normal: n,
        residual,
        error: residual * factor.sqrt(),
    };
    // The circle where it is one: the quadratic's fourth-order error on an arc grows as
    // the window does, the circle's only with the change of curvature.
    Some(
        circle_fit(samples, use_side, &f).map_or(quadratic, |(position, normal, residual)| Fit {
            position,
            shift: 0.0,
            normal,
            residual,
            error: residual * factor.sqrt(),
        }),
    )
}

/// The vertex (at the origin) projected onto the weighted algebraic circle fit of the
/// samples (Taubin's, in Chernov's Newton form), with the normal there and the residual;
/// `None` where the circle is nearly a line (radius above [`LINE_RADIUS`] window radii:
/// the quadratic fits it) or the arithmetic fails.
fn circle_fit(
    samples: &[Sample],
    use_side: impl Fn(i8) -> bool,
    frame: &Frame,
) -> Option<([f64; 2], [f64; 2], f64)> {
    let used = || {
        samples
            .iter()
            .filter(|s| s.weight > 0.0 && use_side(s.side))
    };
    let (sw, m) = (frame.sw, frame.centroid);
    let (mut mxx, mut myy, mut mxy, mut mxz, mut myz, mut mzz) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for s in used() {
        let (x, y) = (s.at[0] - m[0], s.at[1] - m[1]);
        let z = x * x + y * y;
        let w = s.weight;
        mxx += w * x * x;
        myy += w * y * y;
        mxy += w * x * y;
        mxz += w * x * z;
        myz += w * y * z;
        mzz += w * z * z;
    }
    let [mxx, myy, mxy, mxz, myz, mzz] = [mxx, myy, mxy, mxz, myz, mzz].map(|v| v / sw);
    let mz = mxx + myy;
    let cov_xy = mxx * myy - mxy * mxy;
    let var_z = mzz - mz * mz;
    let a3 = 4.0 * mz;
    let a2 = -3.0 * mz * mz - mzz;
    let a1 = var_z * mz + 4.0 * cov_xy * mz - mxz * mxz - myz * myz;
    let a0 = mxz * (mxz * myy - myz * mxy) + myz * (myz * mxx - mxz * mxy) - var_z * cov_xy;
    let (mut x, mut y) = (0.0f64, a0);
    for _ in 0..TAUBIN_ITERATIONS {
        let slope = a1 + x * (2.0 * a2 + 3.0 * a3 * x);
        let next = x - y / slope;
        if next == x || !next.is_finite() {
            break;
        }
        let value = a0 + next * (a1 + next * (a2 + next * a3));
        if value.abs() >= y.abs() {
            break;
        }
        (x, y) = (next, value);
    }
    let det = x * x - x * mz + cov_xy;
    let centre = [
        (mxz * (myy - x) - myz * mxy) / det / 2.0,
        (myz * (mxx - x) - mxz * mxy) / det / 2.0,
    ];
    let radius = (centre[0] * centre[0] + centre[1] * centre[1] + mz).sqrt();
    if !(radius.is_finite() && (MIN_CIRCLE_RADIUS..=LINE_RADIUS).contains(&radius)) {
        return None;
    }
    let centre = [centre[0] + m[0], centre[1] + m[1]];
    let mut residual = 0.0;
    for s in used() {
        let r = (s.at[0] - centre[0]).hypot(s.at[1] - centre[1]) - radius;
        residual += s.weight * r * r;
    }
    let residual = corrected(residual / sw, sw, frame.sw2, 3.0)?;
    // The origin, radially onto the circle.
    let away = [-centre[0], -centre[1]];
    let length = away[0].hypot(away[1]);
    if !positive(length) {
        return None;
    }
    let normal = [away[0] / length, away[1] / length];
    let position = [
        centre[0] + normal[0] * radius,
        centre[1] + normal[1] * radius,
    ];
    (position[0].abs() <= 1.0 && position[1].abs() <= 1.0).then_some((position, normal, residual))
}

/// A Cholesky pivot must exceed this share of its diagonal entry: below, the quadratic's
/// normal equations are too ill-conditioned (samples nearly on one vertical of the frame),
/// and the line's projection is taken.
const PIVOT: f64 = 1e-12;

/// `x > 0`, false for NaN.
fn positive(x: f64) -> bool {
    x > 0.0
}

/// `x ≤ limit`, false for NaN.
fn at_most(x: f64, limit: f64) -> bool {
    x <= limit
}

/// Newton steps on Taubin's characteristic polynomial (Chernov's bound; it converges in a
/// few from zero).
const TAUBIN_ITERATIONS: usize = 99;

/// The solution of the symmetric positive 3 × 3 system `a x = b` (Cholesky), `None` when a
/// pivot is not clearly positive (relative to the diagonal).
fn solve3(a: [[f64; 3]; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    let mut l = [[0.0f64; 3]; 3];
    for i in 0..3 {
        for j in 0..=i {
            let s = a[i][j] - (0..j).map(|k| l[i][k] * l[j][k]).sum::<f64>();
            if i == j {
                if !positive(s - PIVOT * a[i][i]) {
                    return None;
                }
                l[i][i] = s.sqrt();
            } else {
                l[i][j] = s / l[j][j];
            }
        }
    }
    let mut y = [0.0f64; 3];
    for i in 0..3 {
        let mut s = b[i];
        for k in 0..i {
            s -= l[i][k] * y[k];
        }
        y[i] = s / l[i][i];
    }
    let mut x = [0.0f64; 3];
    for i in (0..3).rev() {
        let mut s = y[i];
        for k in i + 1..3 {
            s -= l[k][i] * x[k];
        }
        x[i] = s / l[i][i];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}
