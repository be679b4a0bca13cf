//! Clean loops beside curves: a closed curve that lies within about
//! [`NEAR_CURVE`](crate::reconstruct::thresholds::peel::NEAR_CURVE) sample spacings of
//! another (two nested outlines a spacing or two apart, an island beside a coast) is, point
//! by point, what peeling takes for the other curve's noise: its points come back
//! unassigned, or in open pieces where some of them lie a little farther. After the
//! open-curve stage, passes run over the unassigned points and the short open pieces beside
//! clean loops, and of each pass's loops those are kept that noise does not draw: loops of
//! Delaunay edges of all the points, of at least [`CLEAN_LOOP_POINTS`] points, beside a clean
//! loop, sampled like the curves (median edge at most [`SPARSER_LOOP`] times theirs), without
//! a chord, and clean — they do not [zigzag](zigzags) (exact orientations). A loop through a
//! noise band's leftovers zigzags: their offsets from the curve, and with them the signs of
//! its turns, are random. The open pieces through a kept loop's points give way to it. The
//! rule and its measurements: `docs/design/peeling.md`, "Clean loops beside curves".
//!
//! Every index here is local to the full triangulation.

use std::ops::ControlFlow;

use super::peel::{later_pass, leftover_groups};
use super::shared::{curve_edges, degrees, median_length};
use crate::ids::{ids, LocalPoint};
use crate::reconstruct::curves::{assemble_unnamed, zigzags, Adjacency};
use crate::reconstruct::open_curves;
use crate::reconstruct::options::Options;
use crate::reconstruct::segment_walk::crosses_a_curve;
use crate::reconstruct::thresholds::peel::{CLEAN_LOOP_POINTS, SPARSER_LOOP};
use crate::voronoi::Voronoi;

/// The role of a point in a pass: on no curve or on a short open piece beside a clean loop
/// (both in the pass), on a clean closed loop, or on any other curve (these two kept as
/// they are).
const FREE: u8 = 0;
const ON_PIECE: u8 = 1;
const ON_CLEAN_LOOP: u8 = 2;
const KEPT: u8 = 3;

/// What one pass of [`clean_loops_beside`] did.
pub(crate) enum Beside {
    /// No clean loop: nothing changed.
    Nothing,
    /// The pass would have run on more points than the budget left: nothing changed.
    OverBudget,
    /// These loops' edges (sorted) were added.
    Added(Vec<[LocalPoint; 2]>),
}

/// One pass: adds to `edges` the clean loops beside its closed curves (see the module
/// docs), taking out the open pieces through their points. The pass runs on the points on
/// no closed loop, and takes their number off `budget` (peeling's).
///
/// The new loops' edges are Delaunay edges of all the points, so they cross none of the
/// curve edges that are too; a curve edge that is no Delaunay edge (a chord peeling closed
/// a hole's loop with) is walked through the triangulation against each new loop, exactly.
pub(crate) fn clean_loops_beside(
    full: &Voronoi<'_>,
    edges: &mut Vec<[LocalPoint; 2]>,
    options: &Options,
    budget: &mut usize,
) -> Beside {
    let points = &full.triangulation().points;
    let n = points.len();
    if edges.is_empty() {
        return Beside::Nothing;
    }
    // A kept loop has more unassigned points than points of open pieces: on clean samples
    // (every point on a loop) there is nothing to assemble.
    let degree = degrees(n, edges);
    let unassigned = degree.iter().filter(|&&d| d == 0).count();
    if 2 * unassigned <= CLEAN_LOOP_POINTS || !has_a_run(full, &degree, CLEAN_LOOP_POINTS / 2) {
        return Beside::Nothing;
    }
    // Which points the pass runs on: the unassigned ones and those of the open pieces that
    // touch a clean closed loop (a Delaunay neighbour on it) and are no longer than there
    // are unassigned points (a longer piece could not be most of a kept loop's points).
    // Beside a noisy loop, points at a spacing or two are its noise: no pass runs there.
    let curves = assemble_unnamed(n, edges, points, LocalPoint::get);
    let mut role = vec![FREE; n];
    let mut clean_loops = 0;
    for curve in curves.iter().filter(|c| c.closed) {
        let clean = curve.points.len() >= CLEAN_LOOP_POINTS && !zigzags(points, curve);
        clean_loops += usize::from(clean);
        for &p in &curve.points {
            role[p.index()] = if clean { ON_CLEAN_LOOP } else { KEPT };
        }
    }
    if clean_loops == 0 {
        return Beside::Nothing;
    }
    let beside_a_clean_loop = |p: LocalPoint, role: &[u8]| {
        full.delaunay_neighbours(p)
            .any(|q| role[q.index()] == ON_CLEAN_LOOP)
    };
    for curve in curves.iter().filter(|c| !c.closed) {
        let mark = if curve.points.len() <= unassigned
            && curve.points.iter().any(|&p| beside_a_clean_loop(p, &role))
        {
            ON_PIECE
        } else {
            KEPT
        };
        for &p in &curve.points {
            // A junction stays with its loop.
            if role[p.index()] == FREE {
                role[p.index()] = mark;
            }
        }
    }
    let rest: Vec<LocalPoint> = ids::<LocalPoint>(n)
        .filter(|&p| role[p.index()] <= ON_PIECE)
        .collect();
    if rest.len() < CLEAN_LOOP_POINTS {
        return Beside::Nothing;
    }
    if rest.len() > *budget {
        return Beside::OverBudget;
    }
    *budget -= rest.len();
    // The pass's chords (no Delaunay edges) are not looked at: a kept loop is made of
    // Delaunay edges only.
    let pass = later_pass(full, &rest, options);
    if pass.edges.is_empty() {
        return Beside::Nothing;
    }
    let scale = median_length(points, edges);
    let not_delaunay: Vec<[LocalPoint; 2]> = edges
        .iter()
        .filter(|&&[a, b]| !full.is_delaunay_edge(a, b))
        .copied()
        .collect();
    let clean: Vec<Vec<[LocalPoint; 2]>> =
        assemble_unnamed(n, &pass.edges, points, LocalPoint::get)
            .into_iter()
            .filter(|piece| piece.closed && piece.points.len() >= CLEAN_LOOP_POINTS)
            .map(|piece| (curve_edges(&piece), piece))
            .filter(|(loop_edges, piece)| {
                let on_pieces = piece.points.iter().filter(|p| role[p.index()] == ON_PIECE);
                2 * on_pieces.count() < piece.points.len()
                    && piece.points.iter().any(|&p| beside_a_clean_loop(p, &role))
                    && median_length(points, loop_edges) <= SPARSER_LOOP * scale
                    && !zigzags(points, piece)
                    && open_curves::chords(points, &piece.points).is_empty()
            })
            .map(|(loop_edges, _)| loop_edges)
            .collect();
    // The curve edges that are no Delaunay edges and cross any of the loops (one walk each
    // over all of them), then each loop against those alone.
    let all: Vec<[LocalPoint; 2]> = clean.iter().flatten().copied().collect();
    let crossing: Vec<[LocalPoint; 2]> = if not_delaunay.is_empty() {
        Vec::new()
    } else {
        let drawn = Adjacency::new(n, &all);
        not_delaunay
            .into_iter()
            .filter(|&[a, b]| crosses_a_curve(full, &drawn, a, b))
            .collect()
    };
    let mut kept = Vec::new();
    for loop_edges in clean {
        if !crossing.is_empty() {
            let drawn = Adjacency::new(n, &loop_edges);
            if crossing
                .iter()
                .any(|&[a, b]| crosses_a_curve(full, &drawn, a, b))
            {
                continue;
            }
        }
        kept.extend(loop_edges);
    }
    if kept.is_empty() {
        return Beside::Nothing;
    }
    let mut taken = vec![false; n];
    for &[a, b] in &kept {
        taken[a.index()] = true;
        taken[b.index()] = true;
    }
    edges.retain(|&[a, b]| !taken[a.index()] && !taken[b.index()]);
    edges.extend_from_slice(&kept);
    kept.sort_unstable();
    Beside::Added(kept)
}

/// Do at least `fewest` unassigned points (`degree` 0) hang together, linked as peeling links
/// its leftovers ([`leftover_groups`])? A kept loop has more unassigned points than others,
/// and they run along it; a noise band's leftovers lie in small groups, and a noisy input
/// then costs no assembly of its curves.
fn has_a_run(full: &Voronoi<'_>, degree: &[u8], fewest: usize) -> bool {
    let unassigned: Vec<LocalPoint> = ids::<LocalPoint>(degree.len())
        .filter(|p| degree[p.index()] == 0)
        .collect();
    let mut found = false;
    leftover_groups(full, &unassigned, |group| {
        found = group.len() >= fewest;
        if found {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    });
    found
}
