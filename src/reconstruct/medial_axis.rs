//! The pruned medial axis: the interior medial axis of the reconstructed closed curves, with
//! the branches that noise grows removed by a scale-invariant rule.
//!
//! # What is pruned, and from what
//!
//! The paper's WDM_MAT ([`MedialAxisMode::Raw`](super::MedialAxisMode::Raw)) is read off the
//! Voronoi diagram of *all* the points. Noisy input leaves points on no curve, and each of
//! them puts its own cell, hence cycles and whiskers, into that axis. The pruned axis starts
//! instead from the points of the final closed curves alone:
//!
//! 1. **The loops' points alone.** The axis is that of the Delaunay triangulation of the
//!    points of the closed curves. Every curve edge is a Delaunay edge of all the points,
//!    and an empty circle through its ends stays empty when points are taken away, so it is
//!    a Delaunay edge of the subset too. The subset's triangles are read off the diagram
//!    already built: they are its triangles except around the points off the loops that
//!    lie inside the region, where [`cavity`] replaces them (a second triangulation of all
//!    the loops' points only where that cannot be decided, see there).
//! 2. **Inside, by parity.** A face of the subset's Voronoi diagram (a Voronoi vertex) is
//!    inside when an odd number of curve edges separate it from infinity. The closed curves
//!    are vertex-disjoint simple loops of a plane graph, so the count does not depend on the
//!    path. This is the face parity of the triangles (not where a circumcenter happens to
//!    lie), so the inside faces are exactly the triangles of a triangulation of the region the
//!    curves bound, and the finite Voronoi edges between inside faces are the dual graph of
//!    that triangulation: a tree for a simply connected region, a graph with one independent
//!    cycle per hole otherwise, one component per region. (Exactly cocircular points can
//!    put a curve edge inside a merged face, where no Voronoi edge crosses it: such a face
//!    lies on the curve and is taken as neither inside nor a path for the parity.)
//! 3. **Pruning leaves.** Leaves are taken off one at a time, the one with the smallest ball
//!    first (ties by position); a leaf is tested again when its branch grows (a junction near
//!    it loses a branch), until no leaf goes. A leaf `u` goes
//!    when its ball is *covered*: some ball `B_w` among the vertices of its branch (up to the
//!    first junction) and the nearest beyond that junction in the tree, 64 in all, satisfies
//!
//!    ```text
//!    |c_u − c_w| ≤ s · (r_w − r_u),   s = 1 / cos(θ/2)      (c circumcenters, r radii)
//!    ```
//!
//!    with `θ` = [`PRUNE_ANGLE_DEGREES`] (60°), or, for noise, when such a ball is at least
//!    twice as large and `B_u` sticks out of it by no more than a few noise amplitudes of
//!    its own samples:
//!
//!    ```text
//!    r_w ≥ 2 r_u   and   |c_u − c_w| + r_u − r_w ≤ k · η_u,   k = 8
//!    ```
//!
//!    (`η_u` the largest noise amplitude, estimated from the curve samples alone by
//!    [`noise`], among the points of `u`'s face; [`NOISE_TOLERANCE`], [`NOISE_RADIUS_RATIO`]);
//!    against a ball at or beyond its junction the ratio is not asked of a branch that ends
//!    in at most [`NOISE_TIP_SAMPLES`] = 3 samples (see "Noise tips" below).
//!    A *clean* leaf, one whose face's samples do not zig-zag on a loop that does not
//!    (see "Clean leaves" below), is tested at `θ` = [`CLEAN_PRUNE_ANGLE_DEGREES`] (20°)
//!    instead, without the slack.
//!    A noisy leaf whose samples spread wide for its ball and their noise
//!    (`λ² ≥ k·r_u·η_u`, `λ` half the longest side of its triangle, `k` =
//!    [`SPREAD_SIGNIFICANCE`]) is never covered (see "Spread" below).
//!    A leaf whose circumcenter lies beyond one of
//!    its own curve edges (an obtuse triangle on the curve: its ball is no ball of the shape)
//!    always goes. The last
//!    edge of a component never goes. Cycles are never touched and nothing is disconnected:
//!    the result is still one tree per simply connected region.
//!
//! # Why this rule
//!
//! The classical scale-invariant filters are the object angle (θ-SMA: keep medial points
//! whose two nearest boundary points subtend at least θ), the λ-medial axis (keep where the
//! nearest boundary points' enclosing circle has radius at least λ) and the scale axis (drop a
//! ball when its `s`-fold enlargement lies in the enlargement of other balls). The test above
//! is the scale axis's containment `s·B_u ⊂ s·B_w`, and also an object-angle test: along the
//! medial axis the radius changes at the rate `cos(φ/2)`, `φ` the object angle, so
//! `(r_w − r_u) / |c_u − c_w|` is the mean of `cos(φ/2)` between the two centres. Unlike the
//! object angle at a point it is *directed* and non-local, and both matter on noisy input
//! (measured in `tests/medial_axis.rs`):
//!
//! * A whisker toward a noise wiggle starts at a small ball through three nearby samples,
//!   which can see them under a wide angle (the leaf-to-neighbour rate was 0.7–0.86 on
//!   σ = 0.3 × spacing), and grows at a rate near 1 toward the trunk. Comparing the leaf with
//!   its neighbour alone left most whiskers; comparing it with the whole branch and the trunk
//!   balls near its junction removes them.
//! * The λ-medial axis needs a length (a fraction of the shape), so it depends on the sampling
//!   density relative to the shape; the rate compares balls only with each other.
//! * Only leaves are removed, because a low-angle stretch in the middle of the axis (the
//!   waist of a peanut) is part of the trunk.
//!
//! The angle is a trade-off, measured over six shapes (`tests/medial_axis.rs`): a smooth end
//! of the shape is where the object angle falls to 0, and the rounded corner of a
//! superellipse carries a branch at about 90°. At 90° no whisker survived noise of 0.3 × the
//! spacing, but clean samples lost about 5 % of the shape's diameter at every smooth end and
//! the corner branches entirely; at 60° clean ends lose under 3 % (rounded corners about
//! 6 %), noise of 0.1 × the spacing leaves no whisker, and at 0.3 × the spacing the angle
//! alone left whiskers on the narrow arms of a star, which the noise slack below removes.
//! At 45° with the slack the superellipse's corners keep more (trunk gap 4.5 % instead of
//! 6.4 %, still not 3 %) but whiskers come back at 0.3 × the spacing (8 of 12 trials of
//! the two shapes within 3 % at `k = 8`, 10 of 12 at `k = 14`), so 60° stays for leaves
//! on noisy samples and clean ones get 20° ("Clean leaves" below). (Also measured and left: a second, wider
//! angle for branches bounded by at most 4–6 curve edges removed the star's whiskers but cut
//! the smooth ends of sparse clean samples, which have that few samples there.)
//!
//! # The noise slack
//!
//! What survives the angle at 60° on noise of 0.3 × the spacing (drawn and measured in
//! `tests/medial_axis.rs`) is not a side branch but a hook: the end of a narrow arm (the
//! star's tips, about 8 spacings wide) bent toward a dent of the samples, and spokes from
//! the ring around a hole to a dent of the hole. Along such a hook the balls shrink toward a
//! ball `B_u` through dented samples, which sticks out of the arm's end ball `B_w` (limited by
//! the samples that noise pushed inward) by an excess `e` of about a spacing. The angle test
//! allows `|c_u − c_w| ≥ e·s/(s − 1) ≈ 7.5 e`, more than the arm is wide. No angle fixes
//! this without cutting clean ends (at 90° clean smooth ends lose 5 % of the diameter and the
//! superellipse its corner branches); the excess is a matter of noise, so the tolerance for
//! it is measured from the noise:
//!
//! * `η` ([`noise::loop_estimates`]) is a length computed from the samples of each closed curve,
//!   the part of each sample's offset from its neighbours' chord that the neighbours'
//!   curvature does not explain: about 2σ under Gaussian noise of σ, under a hundredth of
//!   the spacing on clean evenly spaced samples (unit test). Clean input is pruned as before (the
//!   clean rows of the tests did not change in any digit), and the rule stays
//!   scale-invariant: the slack is a length of the input, the factors are pure numbers.
//! * The slack applies only against a ball at least twice as large. Balls of similar size
//!   follow each other along every branch, a step apart; an additive slack between them
//!   takes off any branch, step by step (measured with `k = 3` and no such condition: the
//!   trunk gap of clean ellipses went from 2.7 % to 5.9 % of the diameter, of noisy stars
//!   to 41 %). Against a ball twice as large, a branch of object angle `φ` loses only balls of
//!   radius up to about `k·η / (1/cos(φ/2) − 1)`, a few spacings on noisy input.
//! * `k` was measured on the six shapes at σ = 0.3 × the spacing (trials with every segment
//!   within 3 % of the diameter, star / two shapes / hole): `k = 2`: 10, 9, 12 of 12; `k = 4`:
//!   12, 11, 12; `k = 6`: 12, 11, 12; `k = 8`: 12, 12, 12, worst 2.4 %, with every trunk gap
//!   as before; also on a second set of seeds. A ratio of 1.5 instead of 2 at `k = 4` cut
//!   into the superellipse's corner branches (trunk gap 11 %).
//! * What it costs: samples too sparse for their sharp features look noisy to `η`. The
//!   README's mushroom (a loop of 33 hand-digitised points, a sharp corner at nearly every
//!   sample) loses the two branches into the thin brim of its cap (27 → 23 segments). Also
//!   measured and left: the median of `ψ` over the window instead of its root mean square
//!   (blind to isolated corners; with the factor scaled to match, the mushroom kept 12
//!   segments), and a zig-zag measure (`max(0, −d_i·d_{i+1})`, only sign-alternating
//!   offsets; 16 or 24 of it left a 3.6 % hook on the two shapes and the mushroom kept 26
//!   and 23 segments), and capping the slack at the leaf's own radius (the mushroom kept
//!   its 27 segments, but hooks came back: two shapes 7/12, star 10/12, hole 10/12).
//!
//! # Noise tips
//!
//! On sparse noisy samples (an ε-sample, noise a fraction of each sample's spacing) one
//! displaced sample on a sparse stretch is a corner of the loop, and the axis grows a branch
//! toward it whose balls are nearly as large as the trunk's: the ratio condition above never
//! lets the slack apply, and the branch sees its samples under a wide angle (whiskers up to
//! 24 % of the diameter). What tells it from a branch of the shape is how little it
//! explains: the Delaunay edge dual to its last axis edge cuts off at most a few samples, and
//! its ball sticks out of the balls at its junction by no more than the noise. So a noisy
//! leaf whose branch cuts off at most [`NOISE_TIP_SAMPLES`] samples is also covered by a ball
//! at or beyond its junction that it sticks out of by at most its slack, whatever their
//! sizes. The count is kept by the pruning (a leaf cuts off its face's third corner and what
//! the leaves taken off it cut off); only balls past the junction count, so a branch is not
//! eaten ball by ball along itself. Measured (thresholds module): whiskers beyond 3 % of the
//! diameter in 130 instead of 267 of 432 sparse noisy trials, at the cost of lobes of three
//! samples at ε = 0.5; evenly spaced samples unchanged.
//!
//! # Spread
//!
//! A broad lobe of a shape carries a branch whose object angle stays under 60° all along,
//! and whose tip ball sticks out of the ball at the branch's junction by under 2 `η`: in
//! the terms of the rule above it is a whisker, and it went (trunk gaps of 14 % of the
//! diameter on random Fourier blobs, noise 0.1–0.3 × the spacing). What tells it from a
//! whisker is where its balls touch the samples, the λ of the λ-medial axis: a lobe's
//! triangles span its two flanks, many spacings apart, while a whisker's span the dent it
//! grew into, whose width is set by the noise: a ball of radius `r` meets noise of `σ` over
//! a width of about `√(2rσ)`, so `λ² / (r·η)` is a pure number about 1 for a whisker
//! (`η ≈ 2σ`). A noisy leaf with `λ² ≥ k·r·η`, `k` = [`SPREAD_SIGNIFICANCE`] = 12, is kept;
//! its branch is then cut back only to where its contacts close in. Measured (thresholds
//! module): trunk gaps 5.9 / 11.3 / 14.4 % at σ = 0.1 / 0.2 / 0.3 × the spacing instead of
//! 14 %, every segment within 2.7 %, the six shapes of `tests/medial_axis.rs` within their
//! limits. Clean leaves are not given it (their `η` is no length of the input).
//!
//! # Clean leaves
//!
//! At 60° the rounded corners of a superellipse (p = 4) lose their branches where the
//! object angle falls below 60° while the radius is still large: the clean trunk gap was
//! 6.4 % of the diameter; at 45° 4.5 %, at 30° 2.5 %, at 20° 2.5 %. Random Fourier blobs
//! evenly sampled without noise carry branches into broad lobes whose object angle falls
//! under 30° while their balls are still large: at 30° they lost up to 5.5 % of the
//! diameter of their trunk, at 20° 1.9 % (thresholds module). Smaller angles let whiskers
//! through on noise, so the smaller angle is given only where there is no noise to grow one.
//! `η` cannot tell that: it reads the quickly changing curvature of sparse clean corners
//! as noise. [`noise::loop_estimates`] can: a smooth curve bends one way between
//! inflections, so consecutive offsets of the samples from their neighbours' chords keep
//! their sign (exactly 0 on a clean convex stretch, however sparse), while noise makes
//! them anticorrelated (about `σ / spacing`). A leaf is clean when the oscillation at each
//! of its face's points is below [`CLEAN_OSCILLATION`] = 0.02, about that of noise of
//! 0.02 × the spacing; a whisker needs noise, so its leaf is never clean, and a branch of a
//! clean leaf is a branch of the shape, kept down to 20°. Clean leaves get no slack either
//! (there is no noise to tolerate).
//!
//! Noise of 0.1 × the spacing leaves a stretch of a few samples whose offsets happen to keep
//! their sign: read face by face, its leaves were clean and a whisker there was kept at the
//! clean angle (a sparse 3-armed star grew one of 8.6 % of the diameter). Noise is a property
//! of the scan, so a loop whose median oscillation reaches the threshold (half its samples
//! zig-zag) is noisy at every point; a clean loop keeps its clean points clean beside a
//! noisy stretch.
//!
//! Measured on the six shapes (`tests/medial_axis.rs`): the threshold at 0.015, 0.02 and
//! 0.03 leaves every noisy row as it was in every digit and takes the clean superellipse's
//! trunk gap from 6.4 % to 2.5 % (the other clean shapes' smooth ends keep more too: ellipse
//! 2.7 → 1.3 %, star 1.9 → 0.8 %); at 0.06 whiskers come through at σ = 0.1 × the spacing
//! (star 9/12, ellipse and star 6/12 within 3 %, worst 6 %). Measured before and not kept:
//! the angle chosen by `η < τ·r` (the corners look noisy to `η`) and protecting leaves
//! whose dual Delaunay edge cuts off at least 4 or 6 loop samples (the superellipse gap
//! unchanged, precision under noise collapsed). The README's mushroom does not gain its
//! brim branches back: hand-digitised samples zig-zag, so its leaves count as noisy.
//!
//! # Exactness
//!
//! The subset's triangles (the cavity's walk and its in-circle tests), its merged faces,
//! the parity and the "beyond its own edge" test (`orient2d_circumcenter`) are exact, as
//! everywhere in the crate. The coverage test compares lengths computed from the
//! circumcenters rounded to `f64` in the reconstruction's frame (`super::frame`: the same
//! numbers under any exact power-of-two scaling of the input, none of them subnormal), and
//! the noise slack and the oscillation are `f64` estimates: the angles, the slack and the clean threshold are tolerances of the *rule*
//! (a branch at 59.9999° or 60.0001° is equally a whisker), and the rounding moves the decision only for balls within about `10⁻¹⁵`
//! (relative) of the threshold. The order of the removals, and every tie, is decided by radius and then by
//! coordinates, so the result depends on the points, never on their order.

mod cavity;
mod first_use;
mod noise;
mod pruning;

use self::cavity::Cavity;
use super::bits::{Bits, RankedBits};
use super::curves::LocalCurve;
use super::frame::Frame;
use super::lengths::distance;
use super::parity::parity_from_infinity;
use super::result::MedialAxis;
use super::segment_walk::faces_across;
use super::thresholds::medial_axis::{
    CLEAN_OSCILLATION, CLEAN_PRUNE_ANGLE_DEGREES, NEIGHBOURHOOD, NOISE_RADIUS_RATIO,
    NOISE_TIP_SAMPLES, NOISE_TOLERANCE, PRUNE_ANGLE_DEGREES, SPREAD_SIGNIFICANCE,
};
use crate::delaunay::triangulate;
use crate::delaunay::{HalfEdge, Triangulation, NO_TWIN};
use crate::ids::{LocalPoint, VertexId};
use crate::kernel::metric::dot_sign;
use crate::kernel::Sign;
use crate::parallel;
use crate::prefetch::prefetch;
use crate::voronoi::{rounded_circumcenter, smallest_corner, Voronoi};

/// The `slack` of a clean ball ([`Ball`]): the angle [`CLEAN_PRUNE_ANGLE_DEGREES`] applies,
/// and no noise slack.
const CLEAN: f32 = -1.0;

/// The `slack` of a noisy ball whose samples spread wide for it ([`SPREAD_SIGNIFICANCE`]):
/// a ball of the shape, which stays as a leaf without being tested (`pruning::prune`'s `stays`).
const SPREAD: f32 = f32::INFINITY;

/// The pruned medial axis of the closed curves among `curves` (local indices of the
/// points of `vor`); empty when there are none. See the module docs. `vor` is in `frame`;
/// the vertices come out in the caller's coordinates.
///
/// Read off `vor` itself, with the triangles around points off the loops inside the region
/// replaced ([`cavity`]); where that cannot be decided on `vor` (exactly cocircular points
/// there), the loops' points are triangulated on their own.
pub(super) fn pruned_medial_axis(
    mut vor: Voronoi<'_>,
    curves: &[LocalCurve],
    frame: Frame,
) -> MedialAxis {
    let tri = vor.triangulation();
    let loops: Vec<&LocalCurve> = curves.iter().filter(|c| c.closed).collect();
    if loops.is_empty() || tri.is_degenerate() {
        return MedialAxis::default();
    }
    let edges = loop_edges(&loops);
    let mut marks = LoopMarks::new(&vor, &edges, false);
    if marks.unresolved {
        drop((marks, edges));
        return subset_axis(vor, &loops, frame);
    }
    let mut inside = marks.inside_faces(&vor);
    // Points off the loops change the region's triangles only where they lie inside it
    // ([`cavity`]): when none does (always when the loops use every point), the region's
    // triangles of all the points are the subset's; when some do, the triangles around
    // them are replaced, and only where the diagram cannot decide that is the subset
    // triangulated again.
    let off_loop = off_loop_points_inside(&vor, &edges, &inside);
    // 8 bytes a point, not held through the graph's balls.
    drop(edges);
    let cavity = if off_loop.is_empty() {
        None
    } else if let Some(cavity) = Cavity::around(&vor, &off_loop) {
        for &v in &cavity.replaced {
            inside[v.index()] = false;
        }
        Some(cavity)
    } else {
        drop((marks, inside));
        return subset_axis(vor, &loops, frame);
    };
    let noise = noise_at_points(&loops, &tri.points);
    // The positions of all vertices (16 bytes each, 32 a point) are not held through the
    // graph's balls, the memory peak: the balls' centres are computed again, the same way
    // (a few per cent of the axis phase).
    vor.forget_positions();
    let axis = Graph::inside_edges(&vor, inside, &marks, &noise, cavity.as_ref(), frame);
    // Nothing below reads the diagram (4 bytes a point).
    drop((vor, marks, noise, cavity));
    axis.pruned()
}

/// [`pruned_medial_axis`] on a triangulation of the points of `loops` alone. `vor` is
/// freed first (the caller has no more use for it), so that the two diagrams' vertex
/// positions never coexist at the memory peak.
fn subset_axis(vor: Voronoi<'_>, loops: &[&LocalCurve], frame: Frame) -> MedialAxis {
    let tri = vor.triangulation();
    drop(vor);
    // The subset is a selection of already validated distinct points: `axis_through`
    // cannot refuse it.
    let at = |p: LocalPoint| tri.points[p.index()];
    axis_through(loops, at, None::<fn(LocalPoint) -> [f64; 2]>, frame).unwrap_or_default()
}

/// The pruned medial axis of the closed curves among `curves` (local indices of the
/// reconstruction) drawn through the positions `at` gives their points instead of the
/// samples (`sample` gives those): with smoothing, the axis of the fitted curves the result
/// returns. `None` when those positions draw no plane region (two coincide, one is not
/// finite, or a loop edge runs through another loop point): the caller then takes the
/// axis of the samples.
///
/// The pruning's noise amplitudes are read off the samples, not off the fitted positions:
/// a fitted loop's error is smooth along it (each vertex is fitted to much the same samples
/// as its neighbours), so the estimate, which reads the disagreement of neighbouring
/// curvatures, finds almost none, and the fitted loop was pruned as a clean one, at the
/// clean angle with no slack for the bumps its fit left (whiskers up to 28 % of the
/// diameter on noisy blobs at 0.3 × the spacing).
pub(super) fn fitted_medial_axis(
    curves: &[LocalCurve],
    at: impl Fn(LocalPoint) -> [f64; 2],
    sample: impl Fn(LocalPoint) -> [f64; 2],
    frame: Frame,
) -> Option<MedialAxis> {
    let loops: Vec<&LocalCurve> = curves.iter().filter(|c| c.closed).collect();
    if loops.is_empty() {
        return Some(MedialAxis::default());
    }
    axis_through(&loops, at, Some(sample), frame)
}

/// The pruned axis of `loops` on a triangulation of the positions `at` gives their points,
/// every loop's point a site of its own. `samples` is `None` when those positions are the
/// samples; when they are fitted ones, it gives the samples, and the pruning reads the
/// noise amplitudes of the loops drawn through them. `None` when the positions are not
/// distinct finite points, all collinear, or the loops' edges through them no plane drawing
/// (an edge through another loop point), or, fitted, when a loop edge is no Delaunay edge of
/// the fitted vertices.
fn axis_through(
    loops: &[&LocalCurve],
    at: impl Fn(LocalPoint) -> [f64; 2],
    samples: Option<impl Fn(LocalPoint) -> [f64; 2]>,
    frame: Frame,
) -> Option<MedialAxis> {
    let points: Vec<[f64; 2]> = loops
        .iter()
        .flat_map(|c| c.points.iter().map(|&p| at(p)))
        .collect();
    let sub = triangulate(&points).ok()?;
    if !sub.duplicates().is_empty() {
        return None;
    }
    if sub.is_degenerate() {
        return None;
    }
    // The subset's caller indices are positions in `points`, which lists the loops one
    // after the other: the loops in the subset's local indices.
    let mut position = 0u32;
    let renumbered: Vec<LocalCurve> = loops
        .iter()
        .map(|c| {
            let positions = position..position + c.points.len() as u32;
            position += c.points.len() as u32;
            LocalCurve {
                points: positions.map(|i| sub.local_index(i)).collect(),
                closed: true,
            }
        })
        .collect();
    let renumbered: Vec<&LocalCurve> = renumbered.iter().collect();
    let edges = loop_edges(&renumbered);
    let noise = match &samples {
        None => noise_at_points(&renumbered, &sub.points),
        Some(sample) => {
            // The samples by the subset's local index.
            let mut measured = vec![[0.0; 2]; sub.points.len()];
            for (original, local) in loops.iter().zip(&renumbered) {
                for (&p, &q) in original.points.iter().zip(&local.points) {
                    measured[q.index()] = sample(p);
                }
            }
            noise_at_points(&renumbered, &measured)
        }
    };
    let vor = sub.voronoi();
    // A fitted loop edge that is no Delaunay edge of the fitted vertices has a vertex of
    // another stretch of the loops in its every empty circle: the fit drew two stretches
    // closer than their spacing (a fitted loop's axis then crossed its own curve). Samples'
    // loops may have such edges only where a later pass closed a loop by a chord, which
    // the marks below read along the faces the chord crosses.
    if samples.is_some() && edges.iter().any(|&[a, b]| !vor.is_delaunay_edge(a, b)) {
        return None;
    }
    let axis = {
        let mut marks = LoopMarks::new(&vor, &edges, true);
        if marks.unresolved {
            // A loop edge through another sample point: these are no curves of a plane
            // drawing, and they bound no region to take an axis of.
            return None;
        }
        let inside = marks.inside_faces(&vor);
        drop(edges);
        Graph::inside_edges(&vor, inside, &marks, &noise, None, frame)
    };
    Some(axis.pruned())
}

/// The noise amplitude ([`noise::loop_estimates`]) at every point of `loops` (local
/// indices of `points`), by local index, negated (its sign bit set, `-0.0` too) where the
/// samples zig-zag: oscillation at least [`CLEAN_OSCILLATION`] at the point, or in the
/// median over its loop (a noisy loop has stretches that look clean by chance). One `f32`
/// per point, as before the oscillation was read (the memory peak).
fn noise_at_points(loops: &[&LocalCurve], points: &[[f64; 2]]) -> Vec<f32> {
    let mut noise = vec![0.0f32; points.len()];
    for c in loops {
        let n = c.points.len();
        let at = |k: usize| points[c.points[k].index()];
        // In parallel over stretches of the loop (each value reads only its neighbours).
        let mut along = vec![0.0f32; n];
        parallel::fill_chunks(&mut along, |stretch, out| {
            let first = stretch.start;
            noise::loop_estimates(n, at, stretch, |k, estimate| {
                out[k - first] = if estimate.oscillation >= CLEAN_OSCILLATION {
                    -estimate.amplitude
                } else {
                    estimate.amplitude
                };
            });
        });
        // The loop's median oscillation reaches the threshold when at least half its
        // points do.
        let zigzagging = along.iter().filter(|a| a.is_sign_negative()).count();
        let noisy_loop = zigzagging >= n - n / 2;
        for (&p, value) in c.points.iter().zip(along) {
            noise[p.index()] = if noisy_loop { -value.abs() } else { value };
        }
    }
    noise
}

/// The edges of `loops` as pairs, smaller first, in the loops' order. Not
/// sorted: what reads them marks sets, and along a loop the points are neighbours in
/// memory too (sorting cost more than it saved in the half-edge search).
fn loop_edges(loops: &[&LocalCurve]) -> Vec<[LocalPoint; 2]> {
    let mut edges = Vec::with_capacity(loops.iter().map(|c| c.points.len()).sum());
    for c in loops {
        let n = c.points.len();
        for k in 0..n {
            let (a, b) = (c.points[k], c.points[(k + 1) % n]);
            edges.push([a.min(b), a.max(b)]);
        }
    }
    edges
}

/// The points of `vor` on none of the loops `edges` with a face `inside` them. No loop
/// edge ends at such a point, so all its faces have one parity.
fn off_loop_points_inside(
    vor: &Voronoi<'_>,
    edges: &[[LocalPoint; 2]],
    inside: &[bool],
) -> Vec<LocalPoint> {
    let mut on_loop = vec![false; vor.triangulation().distinct_point_count()];
    for &[a, b] in edges {
        on_loop[a.index()] = true;
        on_loop[b.index()] = true;
    }
    (vor.triangulation().local_points())
        .filter(|&p| !on_loop[p.index()] && vor.cell_vertices(p).any(|v| inside[v.index()]))
        .collect()
}

/// Which Delaunay half-edges lie on a loop (both directions), and which faces a loop passes
/// through (a loop edge without a dual, or no edge of this triangulation): marks per
/// half-edge and per face, so that the walks below test an edge in O(1).
struct LoopMarks {
    /// One bit per half-edge (six per point: a byte each was 5 bytes a point more at the
    /// memory peak).
    on_loop: Bits,
    on_chord: Vec<bool>,
    /// Some loop edge is no Delaunay edge of these points nor a chord of a merged face, and
    /// its faces were not marked (or it runs through another sample point, which no curve
    /// does): the loops do not divide this diagram's faces.
    unresolved: bool,
}

impl LoopMarks {
    /// `across`: whether a loop edge that is no edge of `vor`'s triangulation (nor a chord
    /// of a merged face) marks the faces it passes through, or leaves the marks
    /// `unresolved`.
    fn new(vor: &Voronoi<'_>, edges: &[[LocalPoint; 2]], across: bool) -> LoopMarks {
        let tri = vor.triangulation();
        let halfedges = tri.halfedges();
        let mut on_loop = Bits::new(halfedges.len());
        let mut on_chord = vec![false; vor.vertex_count()];
        let mut unresolved = false;
        // Finding a loop edge's half-edge walks around its end: in parallel.
        let found = parallel::map_range(edges.len(), |i| {
            let [a, b] = edges[i];
            vor.delaunay_halfedge(a, b)
        });
        for (&edge, found) in edges.iter().zip(found) {
            let [a, b] = edge;
            match found {
                Some(e) => {
                    on_loop.set(e.index());
                    if let Some(&twin) = halfedges.get(e.index()).filter(|&&t| t != NO_TWIN) {
                        on_loop.set(twin.index());
                    }
                    if !vor.has_dual(e) {
                        on_chord[vor.vertex_of_halfedge(e).index()] = true;
                    }
                }
                // Not an edge of this triangulation: a chord of the merged face that holds
                // both ends (two faces sharing two corners share the edge between them), or
                // an edge that a later pass of the peeling drew on its own points.
                None => {
                    let mut shared = false;
                    for v in vor.cell_vertices(a) {
                        if vor.cell_vertices(b).any(|w| w == v) {
                            on_chord[v.index()] = true;
                            shared = true;
                        }
                    }
                    if !shared {
                        // The faces the edge passes through lie on the loop, as a merged
                        // face under a chord does (marking nothing, the loop would stay
                        // open, and which faces are inside would depend on the order of
                        // the search: found on `fish.txt`). Where that is not asked for,
                        // the caller takes the loops' points alone instead.
                        match faces_across(vor, a, b).filter(|_| across) {
                            Some(faces) => {
                                for v in faces {
                                    on_chord[v.index()] = true;
                                }
                            }
                            None => unresolved = true,
                        }
                    }
                }
            }
        }
        LoopMarks {
            on_loop,
            on_chord,
            unresolved,
        }
    }

    /// Every Voronoi vertex: inside the loops? A face holding a loop edge without a dual
    /// lies on the loop: it is neither inside nor passed through, so the parity of every
    /// other face is still well defined. The faces on a chord are read here only: their
    /// marks become the search's (a copy was 2 bytes a point at the memory peak).
    fn inside_faces(&mut self, vor: &Voronoi<'_>) -> Vec<bool> {
        let on_chord = std::mem::take(&mut self.on_chord);
        parity_from_infinity(vor, on_chord, |e| self.on_loop.get(e.index()))
    }
}

/// The axis as a graph on the Voronoi vertices it uses: balls and edges.
struct Graph {
    /// The ball of every used vertex.
    ball: Vec<Ball>,
    /// `[a, b]`, indices into `ball`, `a` the end used first (see `into_medial_axis`).
    edges: Vec<[u32; 2]>,
    /// The frame the balls are in, and the caller's coordinates of the centres that are not
    /// their frame's value rescaled ([`Frame::rounds_like_the_caller`]), by first-use
    /// number, sorted. Empty on all but extreme input.
    frame: Frame,
    caller_centres: Vec<(u32, [f64; 2])>,
}

/// What the pruning reads of a vertex, in one record (half a cache line).
///
/// The balls are numbered in the order the pruning tests leaves: smallest radius first,
/// then by centre, then by first use. Leaves are then taken in increasing number, so the
/// pruning's reads of the ball and node arrays run forward through memory (in the order of
/// first use they jumped all over it: a cache miss per leaf, most of the run at 10^6 noisy
/// points), and a leaf's priority is its number.
struct Ball {
    /// Rounded circumcenter.
    centre: [f64; 2],
    /// Distance from the rounded circumcenter to a corner of the face.
    radius: f64,
    /// How far the ball may stick out of a ball that covers it: [`NOISE_TOLERANCE`] × the
    /// largest noise amplitude among the face's points; [`CLEAN`] (negative) when none of
    /// them zig-zags; [`SPREAD`] (infinite) when they spread wide for the ball (never
    /// covered).
    slack: f32,
    /// The vertex's number in order of first use (low 31 bits: there are fewer than
    /// `2 · MAX_POINTS < 2^31` vertices), and in the top bit whether the circumcenter lies
    /// beyond one of the face's own loop edges, outside the region (an obtuse triangle on
    /// the curve): its ball is no ball of the shape. One word, so that the record stays 32
    /// bytes and sorts in place (see `inside_edges`).
    first_use_and_beyond: u32,
}

/// The top bit of [`Ball::first_use_and_beyond`].
const BEYOND: u32 = 1 << 31;

impl Ball {
    fn beyond(&self) -> bool {
        self.first_use_and_beyond & BEYOND != 0
    }

    fn first_use(&self) -> u32 {
        self.first_use_and_beyond & !BEYOND
    }
}

impl Graph {
    /// The finite Voronoi edges between two inside vertices, and those of the `cavity`'s new
    /// triangles (numbered after the diagram's vertices), the vertices numbered in the order
    /// the edges first use them.
    fn inside_edges(
        vor: &Voronoi<'_>,
        inside: Vec<bool>,
        loops: &LoopMarks,
        noise: &[f32],
        cavity: Option<&Cavity>,
        frame: Frame,
    ) -> Graph {
        let tri = vor.triangulation();
        let vertex_count = vor.vertex_count() as u32;
        let new_triangles = cavity.map_or(&[][..], |c| &c.triangles[..]);
        // A face lies on the left of its boundary half-edges; the circumcenter is beyond
        // a loop edge when it lies strictly on its right. By the inscribed angle, that is
        // when the angle at `c`, a corner of the face on the edge's left, is obtuse: an
        // exact sign of input points (the orientation of the constructed circumcenter, of
        // higher degree, took a fifth of the balls' time).
        let beyond_edge = |e: HalfEdge, c: LocalPoint| {
            loops.on_loop.get(e.index()) && beyond_of_corner(tri, e, c)
        };
        let beyond = |v: VertexId| {
            vor.face_edges(v).any(|edge| {
                let e = edge.halfedge;
                beyond_edge(e, tri.org(e.prev()))
            })
        };
        // The slack: `CLEAN` when the face's samples do not zig-zag, `SPREAD` when they
        // spread wide for the ball and its noise (measured on the face's triangle: for a
        // merged face, one of its triangles), else the noise slack.
        let slack =
            |sites: &mut dyn Iterator<Item = LocalPoint>, face: [[f64; 2]; 3], radius: f64| {
                let (amplitude, noisy) = sites
                    .map(|p| noise[p.index()])
                    .fold((0.0f32, false), |(a, noisy), n| {
                        (a.max(n.abs()), noisy || n.is_sign_negative())
                    });
                if !noisy {
                    return CLEAN;
                }
                let [a, b, c] = face;
                let spread = distance(a, b).max(distance(b, c)).max(distance(c, a)) / 2.0;
                if spread * spread >= SPREAD_SIGNIFICANCE * radius * f64::from(amplitude) {
                    SPREAD
                } else {
                    NOISE_TOLERANCE as f32 * amplitude
                }
            };
        let slots = vertex_count as usize + new_triangles.len();
        let mut numbered = first_use::inside_edges(vor, &inside, slots);
        let mut new_beyond = vec![false; new_triangles.len()];
        if let Some(cavity) = cavity {
            for &[s, t] in &cavity.shared {
                numbered.add(vertex_count + s, vertex_count + t);
            }
            for &(k, e) in &cavity.boundary {
                let ends = [tri.org(e), tri.dest(e)];
                if let Some(&c) = new_triangles[k as usize].iter().find(|p| !ends.contains(p)) {
                    new_beyond[k as usize] |= beyond_edge(e, c);
                }
                let twin = tri.halfedges()[e.index()];
                if twin == NO_TWIN || loops.on_loop.get(e.index()) {
                    continue;
                }
                let w = vor.vertex_of_halfedge(twin);
                if inside[w.index()] {
                    numbered.add(vertex_count + k, w.get());
                }
            }
        }
        let first_use::Numbered {
            index,
            used,
            mut edges,
        } = numbered;
        drop((index, inside));
        // Computed in order of first use, which follows the triangulation's locality. The
        // radius is measured to the face's smallest corner, as its position is computed from
        // it: the same value whichever triangulation the face came from.
        // Fewer than 2^31 balls: at most two vertices per point, and `MAX_POINTS < 2^30`.
        debug_assert!(used.len() < BEYOND as usize);
        let tag = |i: usize, beyond: bool| i as u32 | if beyond { BEYOND } else { 0 };
        let mut ball = parallel::map_range(used.len(), |i| {
            let v = used[i];
            if v < vertex_count {
                let v = VertexId::new(v);
                let face = vor.vertex_triangle(v);
                let centre = vor.vertex_position(v);
                let radius = distance(centre, face[smallest_corner(face)]);
                Ball {
                    centre,
                    radius,
                    slack: slack(&mut vor.face_corners(v), face, radius),
                    first_use_and_beyond: tag(i, beyond(v)),
                }
            } else {
                let k = (v - vertex_count) as usize;
                let face = new_triangles[k].map(|p| tri.position(p));
                let centre = rounded_circumcenter(face);
                let radius = distance(centre, face[smallest_corner(face)]);
                Ball {
                    centre,
                    radius,
                    slack: slack(&mut new_triangles[k].iter().copied(), face, radius),
                    first_use_and_beyond: tag(i, new_beyond[k]),
                }
            }
        });
        // The centres whose value in the caller's coordinates is not the frame's rescaled
        // are computed on the caller's coordinates of their triangle, as the diagram's
        // positions are (in first-use order).
        let caller_centres = parallel::flat_map_chunks(ball.len(), |range, out| {
            for i in range {
                let centre = ball[i].centre;
                let v = used[i];
                let triangle = || {
                    if v < vertex_count {
                        vor.canonical_triangle(VertexId::new(v))
                    } else {
                        new_triangles[(v - vertex_count) as usize].map(|p| tri.position(p))
                    }
                };
                if frame.rounds_like_the_caller(centre, triangle) {
                    continue;
                }
                out.push((i as u32, frame.circumcenter_to_caller(centre, triangle)));
            }
        });
        // Then numbered in the order the pruning tests leaves (see `Ball`): sorted in place
        // on the radius as an integer key (its `total_cmp` order), the rare runs of equal
        // radii then by centre and first use. In place and by whole records: sorting
        // (radius, number) pairs and then moving the balls to their numbers, cycle by cycle,
        // followed each cycle one cache miss at a time (1.45 s of 10.3 at 10^7 noisy points,
        // measured), and the pairs were 16 more bytes per ball at the memory peak.
        parallel::sort_unstable_by(&mut ball, |p, q| {
            total_order_key(p.radius)
                .cmp(&total_order_key(q.radius))
                .then_with(|| {
                    (p.centre[0].total_cmp(&q.centre[0]))
                        .then(p.centre[1].total_cmp(&q.centre[1]))
                        .then(p.first_use().cmp(&q.first_use()))
                })
        });
        let mut rank = used;
        for (new, b) in ball.iter().enumerate() {
            rank[b.first_use() as usize] = new as u32;
        }
        // The edge list keeps its order and each edge its ends' order (smaller first-use
        // number first), so the axis returned numbers its vertices as before.
        for [a, b] in &mut edges {
            (*a, *b) = (rank[*a as usize], rank[*b as usize]);
        }
        Graph {
            ball,
            edges,
            frame,
            caller_centres,
        }
    }

    /// Removes leaves by the rule of the module docs: the axis that remains.
    fn pruned(self) -> MedialAxis {
        let scale = [
            1.0 / (PRUNE_ANGLE_DEGREES.to_radians() / 2.0).cos(),
            1.0 / (CLEAN_PRUNE_ANGLE_DEGREES.to_radians() / 2.0).cos(),
        ];
        let Graph {
            ball,
            edges,
            frame,
            caller_centres,
        } = self;
        let tree = pruning::prune(
            ball.len(),
            edges,
            |u| ball[u as usize].beyond(),
            |u| ball[u as usize].slack == SPREAD,
            |w, u, reach| covers(&ball[w as usize], &ball[u as usize], scale, reach),
            |w| prefetch(&ball, w as usize),
        );
        let edges: Vec<[u32; 2]> = tree.edges().collect();
        drop(tree);
        axis_of(&ball, edges, frame, &caller_centres)
    }
}

/// Whether the ball of `w` covers `u`'s: `s·B_u ⊂ s·B_w` (the ball of `w` is at least
/// as far ahead of `u`'s, in radius, as `1/s` of the distance between their centres), or
/// `B_u` sticks out of `B_w` by no more than `u`'s noise slack where `B_w` is at least
/// [`NOISE_RADIUS_RATIO`] times larger, or where `w` is past `u`'s junction and `u`'s
/// branch ends in at most [`NOISE_TIP_SAMPLES`] samples. `scale`: `s` for noisy leaves,
/// then for clean ones.
fn covers(w: &Ball, u: &Ball, scale: [f64; 2], reach: pruning::Reach) -> bool {
    let (apart, gain) = (distance(u.centre, w.centre), w.radius - u.radius);
    if u.slack < 0.0 {
        return apart <= scale[1] * gain;
    }
    let noise_tip = reach.past_junction && reach.samples_cut_off <= NOISE_TIP_SAMPLES;
    apart <= scale[0] * gain
        || ((noise_tip || w.radius >= NOISE_RADIUS_RATIO * u.radius)
            && apart - gain <= f64::from(u.slack))
}

/// The axis of the `edges` that remain between `ball`s: the vertices on them numbered in
/// their order of first use (which follows the triangulation's locality), the edges sorted.
///
/// A vertex's number is the rank of its first use among those of the vertices kept (a bit
/// set with counts): on clean samples nearly every ball stays, and the axis' vertices are
/// allocated beside all the balls at the end of the phase, the memory peak, where a number
/// per ball was 4 bytes a point more. The centres are read in the balls' order and written
/// to their numbers, in the caller's coordinates (`caller_centres`, else the frame's
/// rescaled).
fn axis_of(
    ball: &[Ball],
    mut edges: Vec<[u32; 2]>,
    frame: Frame,
    caller_centres: &[(u32, [f64; 2])],
) -> MedialAxis {
    let mut kept = Bits::new(ball.len());
    for &[a, b] in &edges {
        kept.set(ball[a as usize].first_use() as usize);
        kept.set(ball[b as usize].first_use() as usize);
    }
    let number = RankedBits::new(kept);
    let mut vertices = vec![[0.0; 2]; number.len()];
    for b in ball {
        if let Some(k) = number.rank(b.first_use() as usize) {
            let given = if caller_centres.is_empty() {
                None
            } else {
                let at = caller_centres.binary_search_by_key(&b.first_use(), |&(i, _)| i);
                at.ok().map(|at| caller_centres[at].1)
            };
            vertices[k as usize] = given.unwrap_or_else(|| frame.to_caller(b.centre));
        }
    }
    let number_of = |v: u32| number.rank(ball[v as usize].first_use() as usize);
    for edge in &mut edges {
        // Both ends are kept: they were marked above.
        let [a, b] = edge.map(|v| number_of(v).unwrap_or(u32::MAX));
        *edge = [a.min(b), a.max(b)];
    }
    parallel::sort_unstable(&mut edges);
    MedialAxis { vertices, edges }
}

/// Whether the circumcenter of the triangle of half-edge `e` (local, of `tri`) and corner
/// `c`, which lies on its left, lies strictly on its right: the angle at `c` is obtuse,
/// `(a − c)·(b − c) < 0` (exact).
fn beyond_of_corner(tri: &Triangulation, e: HalfEdge, c: LocalPoint) -> bool {
    let at = |p: LocalPoint| tri.position(p);
    dot_sign(at(c), at(tri.org(e)), at(tri.dest(e))) == Sign::Negative
}

/// An integer key whose order is `f64::total_cmp`'s.
fn total_order_key(x: f64) -> u64 {
    let bits = x.to_bits();
    if bits >> 63 == 1 {
        !bits
    } else {
        bits | 1 << 63
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reconstruct::Curve;
    use wdm_crust_testkit::Rng;

    /// The obtuse-angle test is the orientation of the circumcenter against the edge, on
    /// every half-edge of triangulations with right angles (integer points, a grid) and
    /// without.
    #[test]
    fn beyond_is_the_circumcenters_side() {
        use crate::predicates::{orient2d_circumcenter, Orientation};
        let mut rng = Rng::new(13);
        let mut sets: Vec<Vec<[f64; 2]>> = (0..20)
            .map(|_| {
                (0..60)
                    .map(|_| [rng.below(12) as f64, rng.below(12) as f64])
                    .collect()
            })
            .collect();
        sets.push((0..100).map(|_| [rng.f64(), rng.f64()]).collect());
        sets.push(
            (0..49)
                .map(|i| [(i % 7) as f64, (i / 7) as f64 * 0.5])
                .collect(),
        );
        let (mut beyond, mut on) = (0, 0);
        for points in sets {
            let tri = triangulate(&points).unwrap();
            for e in tri.halfedge_ids() {
                let c = tri.org(e.prev());
                let at = |p: LocalPoint| tri.position(p);
                let face = [at(tri.org(e)), at(tri.dest(e)), at(c)];
                let side = orient2d_circumcenter(face[0], face[1], face);
                beyond += usize::from(side == Orientation::Clockwise);
                on += usize::from(side == Orientation::Collinear);
                assert_eq!(beyond_of_corner(&tri, e, c), side == Orientation::Clockwise);
            }
        }
        assert!(beyond > 50 && on > 50, "{beyond} beyond, {on} on the edge");
    }

    /// A loop whose samples mostly zig-zag is noisy everywhere, even along a stretch that
    /// looks clean (there a whisker would be pruned at the clean angle); a loop that mostly
    /// does not keeps its clean points clean beside a noisy stretch.
    #[test]
    fn a_loop_is_noisy_everywhere_when_most_of_it_zigzags() {
        let mut rng = Rng::new(5);
        let n = 400;
        let spacing = std::f64::consts::TAU / n as f64;
        let curve = LocalCurve {
            closed: true,
            points: (0..n as u32).map(LocalPoint::new).collect(),
        };
        for (noisy_share, loop_noisy) in [(0.75, true), (0.25, false)] {
            let cut = (noisy_share * n as f64) as usize;
            let points: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let t = i as f64 * spacing;
                    let f = if i < cut { 0.3 * spacing } else { 0.0 };
                    [t.cos() + f * rng.normal(), t.sin() + f * rng.normal()]
                })
                .collect();
            let noise = noise_at_points(&[&curve], &points);
            let zigzag = |range: std::ops::Range<usize>| {
                noise[range].iter().filter(|a| a.is_sign_negative()).count()
            };
            // Away from where the stretches meet (the estimates read 3 samples either side).
            let (noisy, clean) = (8..cut - 8, cut + 8..n - 8);
            assert!(zigzag(noisy.clone()) > noisy.len() / 2, "{noisy_share}");
            let expected = if loop_noisy { clean.len() } else { 0 };
            assert_eq!(zigzag(clean), expected, "{noisy_share}");
        }
    }

    /// `curves` (caller indices) in the local indices of `tri`, as the pipeline hands
    /// them to the axis.
    fn local_curves(tri: &Triangulation, curves: &[Curve]) -> Vec<LocalCurve> {
        curves
            .iter()
            .map(|c| LocalCurve::from_caller(c, |i| tri.local_index(i)))
            .collect()
    }

    /// Points on two separate closed curves (a squashed star and a circle), in scrambled
    /// order, with the loops through them.
    fn two_shapes(rng: &mut Rng, n: usize) -> (Vec<[f64; 2]>, Vec<Curve>) {
        let mut points = Vec::new();
        let mut curves = Vec::new();
        for (centre, star) in [([0.0, 0.0], true), ([4.0, 0.5], false)] {
            let start = points.len() as u32;
            for i in 0..n {
                let t = (i as f64 + 0.3 * rng.f64()) / n as f64 * std::f64::consts::TAU;
                let r = if star {
                    1.0 + 0.3 * (5.0 * t).cos()
                } else {
                    0.8
                };
                points.push([centre[0] + r * t.cos(), centre[1] + 0.7 * r * t.sin()]);
            }
            curves.push(Curve {
                closed: true,
                points: (start..start + n as u32).collect(),
            });
        }
        (points, curves)
    }

    /// The axis as a set of segments, ends in order: comparable across diagrams, which
    /// number the axis vertices differently.
    fn segments(axis: &MedialAxis) -> Vec<[[u64; 2]; 2]> {
        let key = |v: u32| axis.vertices[v as usize].map(f64::to_bits);
        let mut segments: Vec<[[u64; 2]; 2]> = axis
            .edges
            .iter()
            .map(|&[a, b]| {
                let (p, q) = (key(a), key(b));
                [p.min(q), p.max(q)]
            })
            .collect();
        segments.sort_unstable();
        segments
    }

    /// The axis is that of the loops' points alone: on the full diagram when the loops use
    /// every point, on the diagram of all the points with the triangles around the points
    /// inside replaced (here scattered points inside and around the shapes), and on a
    /// triangulation of the loops' points alone. All three give the same axis.
    #[test]
    fn points_off_the_loops_do_not_change_the_axis() {
        let mut rng = Rng::new(5);
        let mut replaced = 0;
        for round in 0..20 {
            let (points, curves) = two_shapes(&mut rng, 60 + 10 * round);
            let tri = triangulate(&points).unwrap();
            let direct =
                pruned_medial_axis(tri.voronoi(), &local_curves(&tri, &curves), Frame::CALLER);
            assert!(direct.edges.len() > 20, "round {round}");

            let mut noisy = points.clone();
            noisy.extend((0..5 + round).map(|_| [rng.range(-2.0, 6.0), rng.range(-1.5, 1.5)]));
            let tri = triangulate(&noisy).unwrap();
            let curves = local_curves(&tri, &curves);
            let with_cavity = pruned_medial_axis(tri.voronoi(), &curves, Frame::CALLER);
            let loops: Vec<&LocalCurve> = curves.iter().collect();
            let via_subset = subset_axis(tri.voronoi(), &loops, Frame::CALLER);
            assert_eq!(segments(&direct), segments(&with_cavity), "round {round}");
            assert_eq!(segments(&direct), segments(&via_subset), "round {round}");

            let edges = loop_edges(&loops);
            let vor = tri.voronoi();
            let inside = LoopMarks::new(&vor, &edges, false).inside_faces(&vor);
            let off_loop = off_loop_points_inside(&vor, &edges, &inside);
            replaced += usize::from(
                Cavity::around(&vor, &off_loop).is_some_and(|c| !c.replaced.is_empty()),
            );
        }
        // The cavity path ran (points inside, no cocircular ones) in most rounds.
        assert!(replaced >= 15, "{replaced}");
    }

    /// Integer points: the loop (a rectangle's boundary) and the points inside it are
    /// cocircular in many ways, faces merge, and the axis is the subset's all the same.
    #[test]
    fn cocircular_points_inside_give_the_subset_axis() {
        let (w, h) = (10, 6);
        let mut points: Vec<[f64; 2]> = Vec::new();
        points.extend((0..w).map(|x| [f64::from(x), 0.0]));
        points.extend((0..h).map(|y| [f64::from(w), f64::from(y)]));
        points.extend((0..w).map(|x| [f64::from(w - x), f64::from(h)]));
        points.extend((0..h).map(|y| [0.0, f64::from(h - y)]));
        let curves = vec![Curve {
            closed: true,
            points: (0..points.len() as u32).collect(),
        }];
        let tri = triangulate(&points).unwrap();
        let direct = pruned_medial_axis(tri.voronoi(), &local_curves(&tri, &curves), Frame::CALLER);
        assert!(!direct.edges.is_empty());
        for inside in [vec![[3.0, 3.0]], vec![[2.0, 2.0], [5.0, 3.0], [7.5, 4.0]]] {
            let mut with_inside = points.clone();
            with_inside.extend(inside);
            let tri = triangulate(&with_inside).unwrap();
            let axis =
                pruned_medial_axis(tri.voronoi(), &local_curves(&tri, &curves), Frame::CALLER);
            assert_eq!(segments(&direct), segments(&axis));
        }
    }
}
