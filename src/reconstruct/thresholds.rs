//! Every tuned constant of the reconstruction, in one place: the tolerances of its rules and
//! the few cutoffs chosen for speed. Each is scale-invariant (a count, an angle, or a ratio
//! of two lengths of the input) and compared in rounded arithmetic; no exact decision
//! depends on one. Each doc comment gives the value and its unit, what it decides, the
//! measurement that chose it (`quality` is `examples/quality.rs`, `noise_failures`
//! `examples/noise_failures.rs`, `medial_axis` `tests/medial_axis.rs`) and the module that
//! uses it; the design note named at each group argues the rule
//! ([`docs/design/thresholds.md`](../../docs/design/thresholds.md) indexes them).
//!
//! Changing a value is a change of behaviour: rerun `quality` and the tests named in its
//! design note. The kernel's constants are error bounds with proofs, not tunings, and are
//! not here.

/// Peeling: the later passes on the points no curve reached (`docs/design/peeling.md`).
pub(crate) mod peel {
    /// How close to a curve already found a left-over point may lie and still be taken for a sample
    /// of another curve: its distance to a curve edge, in units of that edge's length. The
    /// leftovers of a noise band sit within about the noise amplitude of the curve, which is of the
    /// order of the sample spacing, while a curve separate from it (a hole) lies at least about 1/ε
    /// sample spacings away for an ε-sample (ε < 1): see `peel::peel`.
    ///
    /// Measurement: `NEAR_CURVE` 2: animal drawings recall 88.4 against 89.6 %, multi-curve
    /// drawings 92.0 against 92.5 %. Used by `reconstruct/repairs/peel.rs`.
    pub(crate) const NEAR_CURVE: f64 = 1.5;

    /// How much sparser than the curves found before it a later pass's loop may be sampled: the
    /// median of its edge lengths, in units of the median over the curves found before. A nested
    /// curve in a scan is sampled like the rest of it; a loop drawn through scattered outliers
    /// inside a shape has edges of the outliers' spacing, many sample spacings long.
    ///
    /// Measurement: 2×: drawings recall 88.7 %, a real scan loses a loop. Used by
    /// `reconstruct/repairs/peel.rs` and `reconstruct/repairs/beside.rs`.
    pub(crate) const SPARSER_LOOP: f64 = 3.0;

    /// How far apart two left-over points may lie and still be linked into one group
    /// (`peel::isolated_leftovers`), in units of the longer of their nearest-neighbour distances:
    /// [`SPARSER_LOOP`], the sparsest sampling a kept loop may have relative to its surroundings.
    ///
    /// Measurement: by the shorter distance instead: with a hole 39 / 45 / 57 right of 100 (noise
    /// 0.5 / 0.7 / 1). Used by `reconstruct/repairs/peel.rs`.
    pub(crate) const LINK: f64 = SPARSER_LOOP;

    /// The fewest left-over points of a group that takes part in a later pass
    /// (`peel::isolated_leftovers`): three, the fewest that bound anything.
    ///
    /// Measurement: 7: survey noise 0.5 with a hole right 100 → 90 %. Used by
    /// `reconstruct/repairs/peel.rs`.
    pub(crate) const MIN_GROUP: usize = 3;

    /// The largest median turning angle of a later pass's curve: 20°, about the turn per sample of
    /// an ε-sample with ε = 0.35 (see `peel::is_a_curve`).
    ///
    /// Measurement: no alternative recorded. Used by `reconstruct/repairs/peel.rs`.
    pub(crate) const MAX_MEDIAN_TURN: f64 = 20.0 * std::f64::consts::PI / 180.0;

    /// The fewest points of a closed loop a later pass keeps: a closed curve turns by 2π, and an
    /// ε-sample of it by about ε per sample, so a loop of fewer than 7 points is no ε-sample for
    /// any ε < 1 (see `peel::is_a_curve`).
    ///
    /// Measurement: 3: one curve at noise 1 right 90 against 95 %; 10–70 % outliers 93 / 87 / 70 /
    /// 63 against 97 / 93 / 83 / 80 %. Used by `reconstruct/repairs/peel.rs` and
    /// `reconstruct/repairs/ears.rs`.
    pub(crate) const MIN_LOOP_POINTS: usize = 7;

    /// The fewest points of a loop that the loops beside curves (`repairs/beside.rs`) call clean
    /// (no vertex zigzags), both the loop a pass keeps and the loop it lies beside: the turns of a
    /// loop through noise have about random signs, and each vertex zigzags with probability about
    /// 1/4, so a loop of `k` noise points looks clean with probability about `(3/4)^k`: 1e-3 at 24.
    ///
    /// Measurement: a noisy star of 10^6 points at random positions (noise 0.1 and 0.3 of the
    /// mean step) leaves 27 loops of 7–10 points that do not zigzag, none of 24 or more. Used by
    /// `reconstruct/repairs/beside.rs`.
    pub(crate) const CLEAN_LOOP_POINTS: usize = 24;

    /// How far, in its own sample spacings, a loop closed by chords (`peel::loops_by_chords`,
    /// `peel::close_by_chord`) must
    /// keep from the curves found before: two curves of an ε-sample (ε < 1) lie at least twice the
    /// local feature size apart, and a sample spacing is at most ε times it, so a loop closer than
    /// 2 of its spacings to an earlier curve is no separate curve of the sample (see
    /// `shared::lies_apart`).
    ///
    /// Measurement: without it: 70 % outliers right 63 against 80 %. Used by
    /// `reconstruct/repairs/shared.rs` (peeling's loops and the islets of `ears.rs`).
    pub(crate) const APART: f64 = 2.0;

    /// The fewest points of an open chain a later pass keeps (see `peel::is_a_curve`).
    ///
    /// Measurement: no alternative recorded. Used by `reconstruct/repairs/peel.rs`.
    pub(crate) const MIN_CHAIN_POINTS: usize = 8;
}

/// Corridors: walls of the water flow mistaken for curve (`docs/design/corridors.md`).
pub(crate) mod corridors {
    /// A crust edge this many times the median crust edge may be a corridor wall.
    ///
    /// Measurement: walls on the failing trials 4.5–25 median edges; rare on clean samples. Used by
    /// `reconstruct/repairs/corridors.rs`.
    pub(crate) const CHORD: f64 = 4.0;

    /// A wall is at least this many times longer than the width of the way the water came by.
    ///
    /// Measurement: walls 2.9–12× the width on the failing trials; on clean samples a long crust
    /// edge's outer vertex is reached by a way at least half as wide. Used by
    /// `reconstruct/repairs/corridors.rs`.
    pub(crate) const NARROW: f64 = 2.0;
}

/// Detours: stretches of curve routed through outliers (`docs/design/detours.md`).
pub(crate) mod detours {
    /// The most inner points of a detour a swap removes. Measured on the outlier rows of
    /// `examples/quality.rs` (recall at 40 / 70 % outliers): 8, 12, 16, 24 inner points gave 89.3 /
    /// 80.5, 90.2 / 78.6, 90.2 / 80.6, 89.8 / 77.2 %; longer bounds let true stretches go.
    ///
    /// Used by `reconstruct/repairs/detours.rs`.
    pub(crate) const MAX_DETOUR_POINTS: usize = 16;

    /// The most points on a curve one group may touch for its pairs to be tried (a bound on the
    /// work: a group of noise leftovers along a whole curve touches many). Outliers inside the
    /// shape link several stretches into one group: 6 instead of 12 cost 4 points of recall at 70 %
    /// outliers; 64 gave the same rows as 24.
    ///
    /// Used by `reconstruct/repairs/detours.rs`.
    pub(crate) const MAX_ANCHORS: usize = 24;

    /// The most rounds of steps 1–2: one reached 85.5 / 73.6 % recall at 40 / 70 % outliers, three
    /// 90.2 / 80.6 %, five 90.2 / 80.4 %.
    ///
    /// Used by `reconstruct/repairs/detours.rs`.
    pub(crate) const ROUNDS: usize = 3;

    /// The least share of unassigned points for step 4 (spikes) to run: a sample with fewer points
    /// off the curves shows no outliers to look for (as one with none: then the repair does not run
    /// at all). It bounds the cost on large, nearly clean inputs (the benches' noisy curve leaves 3
    /// of 10^6 points off, and its noise of a tenth of a spacing has tens of turns sharp enough to
    /// pass for spikes); 0, 0.5 % and 1 % gave the same rows of `examples/quality.rs`.
    ///
    /// Used by `reconstruct/repairs/detours.rs`.
    pub(crate) const MIN_UNASSIGNED_FOR_SPIKES: f64 = 0.01;
}

/// Spikes: outliers woven into a curve (`docs/design/spikes.md`).
pub(crate) mod spikes {
    /// The least turn of a spike (60°). Measured on `examples/quality.rs` with the contrasts below,
    /// recall at 10 / 20 / 40 / 70 % outliers: 60° 98.0 / 95.7 / 92.3 / 82.8; 90° (an exact
    /// dot-product sign for one point) 97.7 / 95.2 / 91.2 / 81.7 without pairs.
    ///
    /// Used by `reconstruct/repairs/spikes.rs`.
    pub(crate) const MIN_SPIKE_TURN: f64 = std::f64::consts::FRAC_PI_3;

    /// How many times a spike must turn more than each point of the run around it, without it. 3
    /// instead of 4 gained 0.2–0.5 points of recall on the outlier rows and lost samples of the
    /// survey's noisy curves (noise 0.3 spacing: "on" 96.9 → 96.7 %).
    ///
    /// Used by `reconstruct/repairs/spikes.rs`.
    pub(crate) const LOCAL_CONTRAST: f64 = 4.0;

    /// How many times a spike must turn more than the median point of the curves. 3 instead of 4:
    /// survey noise 0.3 spacing "on" 96.9 → 96.8 %, the real `drill.txt` 96.5 → 96.0 %.
    ///
    /// Used by `reconstruct/repairs/spikes.rs`.
    pub(crate) const GLOBAL_CONTRAST: f64 = 4.0;

    /// Both contrasts are this much higher for a spike of two points (1: survey noise 0.3 spacing
    /// "on" 96.9 → 96.5 %, the real `vase.txt` 98.1 → 97.2 %).
    ///
    /// Used by `reconstruct/repairs/spikes.rs`.
    pub(crate) const PAIR_FACTOR: f64 = 1.5;

    /// The most points whose turns estimate the median (a bound on its cost on large inputs).
    ///
    /// Measurement: a bound on cost. Used by `reconstruct/repairs/spikes.rs`.
    pub(crate) const MEDIAN_SAMPLE: usize = 8192;
}

/// Open curves: sure loops kept, the other points chained by proximity
/// (`docs/design/open-curves.md`).
pub(crate) mod open_curves {
    /// A loop edge longer than `2^CHORD_DOUBLINGS` times the two loop edges on each side of it is a
    /// chord across an open curve, not a step along a closed one.
    ///
    /// Measurement: 2 (4×): bot.txt 287 → 4 points on curves, Monitor0 621 → 275; a window or loop
    /// median instead of the neighbours: fish.txt 285 → 19. Used by `reconstruct/open_curves.rs`.
    pub(crate) const CHORD_DOUBLINGS: u32 = 3;

    /// A loop edge `2^CHORD_DOUBLINGS` times the two loop edges on one side of it needs to be only
    /// `2^CHORD_SIDE_DOUBLINGS` times the two on the other to be long against its neighbours: the
    /// flow's loop around a closed curve and strokes beside it runs from the curve's short steps
    /// across a chord to a stroke sampled 2–5 times more sparsely, whose steps the chord is only
    /// 5–7 times. The loop's longest ordinary edge ([`CHORD_OUTLIER_DOUBLINGS`]) still guards
    /// noisy closed loops.
    ///
    /// Measurement: 3 (the same on both sides): clean strokes beside a loop, 100 trials of other
    /// seeds, right 89 → 91 with 2, noisy (0.3 steps) 78 → 79; a clean trial came back as two
    /// polygons of chords. The quality benchmark's default rows unchanged (the noisy strokes' H
    /// 2.65 → 2.10). Used by `reconstruct/open_curves.rs`.
    pub(crate) const CHORD_SIDE_DOUBLINGS: u32 = 2;

    /// A loop edge long against its neighbours ([`CHORD_DOUBLINGS`]) is a chord only when it is
    /// also longer than `2^CHORD_OUTLIER_DOUBLINGS` times the loop's longest ordinary edge (one
    /// not `2^CHORD_DOUBLINGS` times any of its four neighbours): a chord across an open curve
    /// stands out of the whole loop, whereas a closed curve sampled at random positions has
    /// gaps 8× their neighbours here and there (about 2 edges in 1000 for exponential gaps),
    /// among ordinary gaps of up to 6–9 mean spacings (simulated, 10^4–10^6 gaps) and a longest
    /// gap of about `ln n` of them; a varying speed along the curve stretches both.
    ///
    /// Measurement: 1 (2×): random-position ellipses of 20 000 points one loop in 5 of 6 (one
    /// gap 12.8 mean steps beside a longest ordinary 6.3); 2: 6 of 6, and 12 of 12 clean
    /// ellipses and 5-lobed stars (0 of 12 without the rule); the open-curve rows of the quality
    /// benchmark unchanged. Used by `reconstruct/open_curves.rs`.
    pub(crate) const CHORD_OUTLIER_DOUBLINGS: u32 = 2;

    /// A loop's edge longer than `2^LONE_CHORD_DOUBLINGS` times every other edge of the loop is a
    /// chord too, whatever its neighbours: noise shortens and lengthens the steps beside an open
    /// curve's gap, so the gap need not be 8× its four neighbours, but a closed curve's loop has
    /// no edge standing alone (the `loop-across-gap` warning's bound, measured on right noisy
    /// loops: none warned).
    ///
    /// Measurement (with the same test on the loops that proximity closes): the quality
    /// benchmark's noisy open rows (0.3 steps) right: arcs 90 → 95 %, spirals 70 → 85 %,
    /// ε-samples of open curves 30 → 50 %, every closed-curve row unchanged, its
    /// `loop-across-gap` warnings 10 → 0; on other seeds (100 trials of each open family) 449 →
    /// 483 of 600 right; sparse noisy closed sets of 12 shapes (noise 0.1–1 spacing, 1 200
    /// trials) and random-position ellipses and stars (clean, 0.25 and 1 step) unchanged.
    /// Used by `reconstruct/open_curves.rs`.
    pub(crate) const LONE_CHORD_DOUBLINGS: u32 = 2;

    /// A loop dissolved because a chain runs or ends beside it is restored when proximity
    /// leaves its points in more than this many pieces (or a quarter of them on none): the
    /// dissolution expected them to continue the chain (one curve, or the chain and a closed
    /// curve the flow had joined to it), and a clean loop whose noise leftovers formed the
    /// chain falls apart into many instead (proximity cannot follow a randomly spaced noisy
    /// sample).
    ///
    /// Measurement: random-position ellipses and 5-lobed stars of 20 000 points with noise of
    /// 0.25 and 1 mean step, 6 seeds each: one closed loop in 22 of 24 (0 of 24 before, with
    /// 280–560 chains each); the open-curve rows of the quality benchmark unchanged. Used by
    /// `reconstruct/open_curves.rs`.
    pub(crate) const MAX_DISSOLVED_PIECES: usize = 4;

    /// A proposed chain edge longer than `2^GAP_DOUBLINGS` times the nearest-neighbour distance at
    /// each of its two ends bridges a gap between two curves.
    ///
    /// Measurement: at either end instead of both: two strokes beside a loop no longer joined
    /// end to end across 5–7 of the sparser one's steps (strokes beside a loop, 100 trials of
    /// other seeds, right clean 91 → 97, noisy 79 → 92), but clean random-position arcs of
    /// 20 000 points one chain in 7 of 12 instead of 12 (a random cluster of samples at an end
    /// closes into a loop of 7 points); 8× at one end and 4× at the other: 1 280 to 20 000
    /// points 1–3 in 20 lost. Used by `reconstruct/open_curves.rs`.
    pub(crate) const GAP_DOUBLINGS: u32 = 3;

    /// The fewest points of an open chain or a loop made of proposals; smaller pieces are junk.
    ///
    /// Measurement: 4: 70 % outliers right 100 → 80 %. Used by `reconstruct/open_curves.rs`.
    pub(crate) const MIN_CHAIN_POINTS: usize = 5;

    /// A join of two chain ends is at most `2^JOIN_DOUBLINGS` times the step at each of them (the
    /// longer of its last two edges): a break that noise made in one curve, not the gap between
    /// two.
    ///
    /// Measurement: 3: two strokes 6.5 steps apart joined (clean strokes exact 100 → 95 %); none:
    /// noisy open rows right 5–35 % instead of 70–95 %. Used by `reconstruct/open_curves.rs`.
    pub(crate) const JOIN_DOUBLINGS: u32 = 2;

    /// A join of two chain ends is also a break of one curve when it is at most
    /// `2^GAP_JOIN_DOUBLINGS` times the longest step of each chain it joins: samples at random
    /// positions leave gaps many times the steps beside them (the longest of `n` exponential
    /// gaps is about `ln n` mean steps), each about as long as the longest gaps elsewhere on the
    /// same curve, whereas two evenly sampled strokes apart are farther than twice any step of
    /// either.
    ///
    /// Measurement (with the bound of either chain, pieces under `MIN_CHAIN_POINTS` setting
    /// none, rounds of joins, and no end choosing the other end of its own short chain):
    /// clean random-position arcs of 90–330°, 5 seeds each, one chain in 16 of 20 at 160 points
    /// (the misses: 330° arcs closed by their chord) and 20 of 20 at 320, 640, 1 280, 2 560 and
    /// 5 120 (3 / 0 / – / – / 0 / – before); quality benchmark: S-curves at noise 0.3 right
    /// 90 → 95 %, every other row unchanged. Noisy random-position arcs (0.3 mean steps) still
    /// break: 4 of 45 right.
    /// Used by `reconstruct/open_curves.rs`.
    pub(crate) const GAP_JOIN_DOUBLINGS: u32 = 1;

    /// The fewest points of a loop that proximity closes: a closed curve turns by 2π, an ε-sample
    /// by about ε a sample, so fewer than 7 points are no ε-sample for ε < 1 (the bound of
    /// peeling's loops).
    ///
    /// Used by `reconstruct/open_curves.rs`.
    pub(crate) const MIN_CLOSED_POINTS: usize = 7;

    /// A point of a chain is isolated when everything off its chain is farther than
    /// `2^ISOLATION_DOUBLINGS` times its longer step along the chain.
    ///
    /// Measurement: no alternative recorded. Used by `reconstruct/open_curves.rs`.
    pub(crate) const ISOLATION_DOUBLINGS: u32 = 1;
}

/// A scatter read off the first pass (`reconstruct/scatter.rs`).
/// Facing corners: two long loop edges across a gap swapped for the short links between their
/// ends (`docs/design/facing-corners.md`).
pub(crate) mod facing {
    /// A loop edge is long when it is at least this many times each loop edge beside it, and a
    /// link replacing it at most its length over this.
    ///
    /// Measurement (clean pairs 1.5 spacings apart, 20 trials each): 1.5 / 2: offset squares
    /// exact 20 / 0, wedges tip to tip 18 / 6; at 1.5 without the zigzag test 7 of 480 noisy
    /// curves came back worse, with it none (`docs/design/facing-corners.md`). Used by
    /// `reconstruct/repairs/facing.rs`.
    pub(crate) const FACING_RATIO: f64 = 1.5;

    /// A loop whose long edges (by [`FACING_RATIO`]) are more than one in this many of its edges,
    /// and more than [`FACING_FEWEST`], is sampled too irregularly for them to mark a gap: samples
    /// at random positions have gaps of exponential length, and about one edge in six is twice
    /// both its neighbours.
    ///
    /// Measurement: 10^6 samples of a star at random parameters: the swap's search over every
    /// such edge cost 0.07 s (a sixth of the curves phase); skipped, nothing. Used by
    /// `reconstruct/repairs/facing.rs`.
    pub(crate) const FACING_SHARE: usize = 100;

    /// Long edges a loop may always have: two facing corners make two on each loop they join.
    ///
    /// Used by `reconstruct/repairs/facing.rs`.
    pub(crate) const FACING_FEWEST: usize = 8;
}

pub(crate) mod scatter {
    /// The first pass read a scatter only when it put fewer than this share of the points on an
    /// edge (and most of those are crowded, and the thinning's probes read an area): the water flow's loops through a uniform scatter
    /// reach about `4.7 √n` points (8.6 % of 3 000, 4.7 % of 10^4, 1.5 % of 10^5, 0.47 % of
    /// 10^6), whereas sparse noisy samples (noise of one spacing: a third of the points left
    /// over, most curve points crowded) and curves among 70 % outliers reach a quarter or
    /// more, and their later passes find holes. Small scatters, cheap anyway, go through the
    /// whole pipeline as before (a circle of 400 points among 4 000 outliers keeps its
    /// partial loop).
    ///
    /// Measurement: a third (the `scatter` warning's share): noise 1 × spacing rows of the
    /// quality benchmark right 95 → 50 % and 100 → 0 % with a hole, 70 % outliers 100 → 93 %;
    /// an eighth: every quality row unchanged, but that circle among outliers lost. Without the
    /// probes' area reading, a 90 000-point annulus with noise of one spacing (first pass: a
    /// few % of the points) lost both its curves. Used by `reconstruct/scatter.rs`.
    pub(crate) const MAX_TOUCHED_SHARE: f64 = 0.05;
}

/// Thinning: dense noisy bands to representatives (`docs/design/thinning.md`).
pub(crate) mod thinning {
    /// Below this many distinct points nothing is thinned: a band needs hundreds of points (its
    /// neighbourhoods hold up to `thinning::LADDER`'s last size), and small inputs are the sparse
    /// samples WDM is made for.
    ///
    /// Measurement: no alternative recorded. Used by `reconstruct/thinning.rs`.
    pub(crate) const MIN_THINNED_POINTS: usize = 400;

    /// At most this many probes (spread over the locality order): the decision is a median, and 512
    /// probes put it within a few percent of its value over all points.
    ///
    /// Measurement: 10^6-point bands: the test and the cover 0.35–0.5 s against 0.6 s for the
    /// triangulation. Used by `reconstruct/thinning.rs`.
    pub(crate) const PROBES: usize = 512;

    /// The probes look at a subsample of at most about this many points (every point kept with the
    /// same chance, by a hash of its local index): a band of a million points is thousands of
    /// spacings wide, and its neighbourhoods turn thin only at sizes no probe can afford. The
    /// subsample's spacing is known (the full one times the sampling rate), and the noise is the
    /// same.
    ///
    /// Measurement: 10^6-point bands: the test and the cover 0.35–0.5 s against 0.6 s for the
    /// triangulation. Used by `reconstruct/thinning.rs`.
    pub(crate) const SUBSAMPLE: usize = 8192;

    /// Where the probes read a subsample as a band, each banded probe is confirmed on all the
    /// points around it, through at most this many rungs of the neighbourhood ladder (8 … 128
    /// points; see [`QUIET_SPACINGS`]): a subsample's neighbourhoods span `rate` times more
    /// curve than the same number of all the points, so that an arc's sagitta reads as noise.
    /// A band too wide to turn thin by then is confirmed as read.
    ///
    /// Measurement: a clean 5-lobed star of 10^6 points at random positions (the `stress
    /// curve` set) was thinned to 254 000 representatives (746 000 points on no curve, no
    /// warning); confirmed, one loop through every point. Bands of 10^6 points at 1 % of the
    /// diagonal and at about 5 mean steps thinned as before. 128 points: a clean stretch
    /// turns thin at 8, a band of 5 mean steps at about 48. Used by
    /// `reconstruct/thinning.rs`.
    pub(crate) const CONFIRM_RUNGS: usize = 9;

    /// How many times a seed's disk is re-centred on the point nearest its centroid before that
    /// point becomes the candidate representative (a mean-shift step toward the band's middle).
    /// The first centroid is pulled toward the seed's side of the band (the disk reaches past
    /// the band on that side only): representatives 1.5 noise deviations apart scattered 0.70 σ
    /// across the band, and an open band read them as a sample with noise of half a spacing.
    ///
    /// Measurement: the representatives of a 270° arc band (20 000 points, σ = 0.003 of a unit
    /// radius) scatter 0.70 σ / 0.40 σ / 0.34 σ across it with 0 / 1 / 2 re-centrings; such
    /// arcs of 20 000 and 60 000 points at σ 0.003 and 0.01 gave 3–18 chains on 5 of 6 inputs
    /// with none, one chain each with one; generated bands (ellipse, star, arc, ellipse with
    /// a hole, square; 2 000–60 000 points; σ 0.003–0.03; two seeds) right 77 → 82 of 90. The
    /// quality benchmark's dense bands: right 71 → 72 of 72 (an ellipse with a hole at σ 2 %
    /// kept its hole), the curve through the representatives (no smoothing) nearer the truth
    /// (RMS summed over the rows 25.3 → 21.9, Hausdorff 90 → 69), the smoothed curves'
    /// median RMS over the noise 0.33 → 0.34 (fewer vertices on the star's tips); two steps:
    /// no better (21.9 → 22.1, smoothed 0.34). Cost: a second disk per seed, offset at 5 mean
    /// steps of noise by a cheaper repair of cleaner representatives (10^6 points 0.81 →
    /// 0.78 s); a band of 1 % of the diagonal 0.41 → 0.52 s. Used by
    /// `reconstruct/thinning.rs`.
    pub(crate) const RECENTRINGS: usize = 1;

    /// A banded subsample probe is a quiet curve, and does not count for the band, where all the
    /// points around it ([`CONFIRM_RUNGS`]) turn thin with a deviation under this share of their
    /// spacing. The nearest-first neighbourhood of 8 points reads about 0.86 of the noise (in
    /// steps): a quarter step reads about 0.2, half a step 0.43.
    ///
    /// Measurement (ratios at the probes, 10th / 50th / 90th percentile): clean gears of 200 000
    /// points with 40 and 80 teeth and a clean 5-lobed star of 10^6 points at random positions at
    /// most 0.08 (all vetoed: one loop through every point, where all three were thinned to a
    /// quarter of their points); a circle of 40 000 points with noise of half a mean step 0.25 /
    /// 0.43 / 0.74 (thinned, as before: one loop). The band threshold itself (0.35) vetoed a
    /// third of that circle's probes and left it unthinned. Used by `reconstruct/thinning.rs`.
    pub(crate) const QUIET_SPACINGS: f64 = 0.2;

    /// A neighbourhood is a piece of curve when its smaller principal variance is at most this
    /// share of its larger (the smoothing's `MAX_ASPECT`): a strip of noise σ over a length `2r`
    /// has variances σ² and r²/3, so it is thin once `r` exceeds about 3.5 σ.
    ///
    /// Used by `reconstruct/thinning.rs`.
    pub(crate) const MAX_ASPECT: f64 = 0.25;

    /// A probe is in a band when its noise (the smaller principal deviation where its neighbourhood
    /// turns thin) is at least this many spacings along the curve (the neighbourhood's length over
    /// its number of points). Below, WDM with its repairs reconstructs the noisy sample as it is
    /// (the sparse noise rows up to one spacing).
    ///
    /// Measurement: 3: dense-band rows right 60 / 72 against 70 / 72; every other quality row
    /// unchanged at 1.5. Used by `reconstruct/thinning.rs`.
    pub(crate) const BAND_SPACINGS: f64 = 1.5;

    /// A sample whose probes read at least this many spacings of noise, short of a band
    /// ([`BAND_SPACINGS`], or [`LARGE_BAND_SPACINGS`] from [`LARGE_SAMPLE`] on), is uncertain:
    /// it is reconstructed as it is, and where that result is doubtful (a warning or an open
    /// chain, on curves that zigzag), through the representatives of a band of its noise
    /// too, whose result is taken where it is better (`reconstruct/thinning/uncertain.rs`).
    ///
    /// Measurement (a scratch probe of 11 shapes, open and closed, 200–5000 points per 2π of
    /// length, noise 0.1–1.3 spacings, even and random positions, 1 056 inputs): right curve
    /// counts 575 before, 814 at 0.3, 857 at 0.2, 858 at 0.1; no input right before wrong
    /// after at any. Large samples read a fifth of a spacing as quiet ([`QUIET_SPACINGS`]),
    /// so below 0.2 only small ones change. Used by `reconstruct/thinning.rs`.
    pub(crate) const UNCERTAIN_SPACINGS: f64 = 0.2;

    /// An uncertain sample's reconstruction through representatives is taken only where at
    /// most this share of the points on the curves of its reconstruction as it is lie beyond
    /// [`REACH_STEPS`] of the representatives' curves.
    ///
    /// Measurement: without it, a real scan in the single pass (the drill case, 3 loops and
    /// a chain) came back as the representatives' one loop: the quality benchmark's real
    /// components' row fell from 91.9 to 39.3 % recall in the single pass (restored with
    /// it) and from 94.4 to 41.5 % with the `literal` labels (62.8 % with it), and the
    /// probe's 857 right counts unchanged (its wrong results with no warning 54 → 50).
    /// Junk inside a band is covered entirely; a lost outline is a share of a curve's
    /// points (the drill case's: 21 %). Used by `reconstruct/thinning/uncertain.rs`.
    pub(crate) const MAX_UNCOVERED_SHARE: f64 = 0.02;

    /// How far, in median steps of the representatives' curves, a point of the other result's
    /// curves may lie from them and still be covered: junk inside a band lies within a step or
    /// two of the curve through it.
    ///
    /// Measurement: representatives lie a cover radius or two apart along the curve and
    /// the band is about two noise deviations wide on each side, within a step; 2 leaves
    /// every generated band's junk covered (the dense-band rows and the scratch probe above
    /// unchanged from no reach test at all). No other value measured. Used by
    /// `reconstruct/thinning/uncertain.rs`.
    pub(crate) const REACH_STEPS: f64 = 2.0;

    /// From this many points on, [`LARGE_BAND_SPACINGS`] replaces [`BAND_SPACINGS`]: the
    /// inputs where the chance of a local failure of the flow adds up to junk, and above every
    /// line drawing and sparse noisy set the rules were tuned on (under 10 000 points).
    ///
    /// Measurement: random-position ellipses and stars of 20 000 points with noise of one mean
    /// step: 12 of 12 exactly one loop (10 of 12 one loop among 0–16 chains below the size).
    /// Used by `reconstruct/thinning.rs`.
    pub(crate) const LARGE_SAMPLE: usize = 20_000;

    /// A probe of a large sample ([`LARGE_SAMPLE`]) is in a band from this much noise on, in
    /// spacings: each stretch of a noisy sample fails the water flow with some chance, and over
    /// 10^5 points noise of half a spacing leaves tens of junk chains beside the loop (evenly
    /// spaced) or hundreds (random positions), where the sparse rows of a few hundred points
    /// are right up to one spacing.
    ///
    /// Measurement: an ellipse of 10^5 points evenly spaced, noise 0.3 / 0.5 / 0.7 spacings
    /// (probes read 0.24 / 0.40 / 0.56): one loop / one loop and 54 chains / one loop as it is,
    /// one loop each thinned from 0.35; at random positions 0.25 / 0.5 / 1 / 1.5 mean steps
    /// (probes 0.21 / 0.43 / 0.87 / 1.3): one loop / 290 / 53 / 1 532 pieces as it is, one loop
    /// each at 0.35 (0.25 unthinned); 0.5 was the line drawings' undoing when applied to all
    /// sizes (f1–f7 precision 35 %). Every quality row unchanged. Used by
    /// `reconstruct/thinning.rs`.
    pub(crate) const LARGE_BAND_SPACINGS: f64 = 0.35;

    /// The cover's disks have a radius of this many noise deviations: wide enough that one disk
    /// spans the band (about ±2 σ), so that the representatives run along its middle in a single
    /// file, and no wider, so that curves a few band widths apart stay apart.
    ///
    /// Measurement: with Voronoi clusters instead of disk centroids: 3 / 4 / 5 σ̂ gave dense rows
    /// 70 / 68 / 65 of 72 and other-shape bands 13 / 16 / 16 of 18; disk centroids with the dedupe:
    /// 69 / 72 and 15 + 17 of 18 at 3 σ̂ (3.5 and 4: 15 of 18). Used by `reconstruct/thinning.rs`.
    pub(crate) const COVER_RADIUS: f64 = 3.0;

    /// A disk with fewer points than this share of the median disk's is not represented: its points
    /// are outliers or the band's frayed edge.
    ///
    /// Measurement: no alternative recorded. Used by `reconstruct/thinning.rs`.
    pub(crate) const MIN_CLUSTER_SHARE: f64 = 0.25;
}

/// The pruned medial axis (`docs/design/pruned-medial-axis.md`).
pub(crate) mod medial_axis {
    /// The object angle `θ` of the pruning rule: a leaf is removed when some ball near it grows out
    /// of its ball at least at the rate `cos(θ/2)` of the distance (see the module docs).
    ///
    /// Measurement: 90°: clean ends lose 5 % of the diameter; 45°: hooks at σ = 0.3 (8/12 within 3
    /// %). Used by `reconstruct/medial_axis.rs`.
    pub(crate) const PRUNE_ANGLE_DEGREES: f64 = 60.0;

    /// The object angle of the rule for a leaf of a clean loop whose samples do not zig-zag
    /// ([`CLEAN_OSCILLATION`]): no noise there can grow a whisker, so only branches narrower than
    /// this go (see the module docs).
    ///
    /// Measurement: superellipse trunk gap 60° / 30°: 6.4 / 2.5 %. Random Fourier blobs, 300
    /// evenly spaced clean points, 8 blobs × 4 trials on each of 4 seeds, worst trunk gap at 30°:
    /// 3.3 / 5.5 / 3.1 / 2.3 % of the diameter; at 20°: 1.2 / 1.9 / 1.9 / 0.9 %; at 10°: 0.3 /
    /// 0.5 % (2 seeds), more branches kept into shallow bumps. Every segment within 0.06 % of
    /// the true axis at each angle. At 20° with cleanliness read at each face alone, whiskers
    /// came through at σ = 0.1 × the spacing (star 9/12 within 3 %): cleanliness is also a
    /// property of the loop ([`CLEAN_OSCILLATION`]). Used by `reconstruct/medial_axis.rs`.
    pub(crate) const CLEAN_PRUNE_ANGLE_DEGREES: f64 = 20.0;

    /// The relative oscillation (`medial_axis::noise::noise::loop_estimates`) below which a face's
    /// samples are clean: about that of Gaussian noise of 0.02 × the spacing (see the module docs).
    /// A loop whose median oscillation reaches it is noisy at every point.
    ///
    /// Measurement: 0.015–0.03: same noisy rows; 0.06: whiskers at σ = 0.1 (star 9/12). The
    /// loop's median: sparse noisy samples (80 points a curve, σ = 0.1 × the spacing, 6 shapes
    /// × 6 trials on each of 4 seeds) had 10 of 144 trials with a segment farther than 3 % of
    /// the diameter from the true axis, worst 9.9 %, from stretches that looked clean by
    /// chance; with it 3, worst 4.9 %. Every row of `tests/medial_axis.rs` unchanged or better.
    /// Used by `reconstruct/medial_axis.rs`.
    pub(crate) const CLEAN_OSCILLATION: f32 = 0.02;

    /// How many vertices (along its branch, then beyond the junction) a leaf is compared with.
    ///
    /// Measurement: no alternative recorded. Used by `reconstruct/medial_axis.rs`.
    pub(crate) const NEIGHBOURHOOD: usize = 64;

    /// How many times the noise amplitude of its samples (`medial_axis::noise`) a leaf's ball may
    /// stick out of a much larger ball that then covers it (see the module docs).
    ///
    /// Measurement: 2 / 4 / 6 / 8: star 10 / 12 / 12 / 12, two shapes 9 / 11 / 11 / 12 of 12. Used
    /// by `reconstruct/medial_axis.rs`.
    pub(crate) const NOISE_TOLERANCE: f64 = 8.0;

    /// How much larger than a leaf's ball a ball must be to cover it within the noise slack: the
    /// slack never applies between balls of similar size, which follow each other along every
    /// branch (see the module docs).
    ///
    /// Measurement: 1.5: superellipse trunk gap 11 % under noise. Used by
    /// `reconstruct/medial_axis.rs`.
    pub(crate) const NOISE_RADIUS_RATIO: f64 = 2.0;

    /// A noisy branch that ends in at most this many curve samples (those beyond the
    /// Delaunay edge dual to its last axis edge) goes when its ball sticks out of a ball at or
    /// beyond its junction by no more than the noise slack, however large that ball: on sparse
    /// noisy samples a single displaced sample grows a branch of balls as large as the trunk's,
    /// which [`NOISE_RADIUS_RATIO`] kept (see the module docs, "Noise tips").
    ///
    /// Measurement: ε-samples (ε = 0.2 / 0.3 / 0.5) of six shapes other than the tests' with
    /// Gaussian noise of 0.1 / 0.3 × each sample's nearest-neighbour distance, 6 trials each,
    /// two seeds (432 trials): trials with a segment farther than 3 % of the diameter from the
    /// true axis 267 → 130 (at 2 samples 171), worst 24 → 15 %; trials whose trunk is missed by
    /// more than 10 % 90 → 127 (2: 108), nearly all of the loss at ε = 0.5 (40 → 65), where a
    /// lobe may have three samples. At ε ≤ 0.3: 169 → 63 imprecise, 50 → 62 trunk misses. Evenly
    /// spaced samples (random blobs and six shapes, 80–300 points, σ = 0.1–0.3, 23 rows):
    /// unchanged but for 80 points at σ = 0.3 (imprecise 13 → 10 of 24). Without the limit (every branch, against balls past its junction): trunk
    /// misses on evenly spaced blobs at σ = 0.3 × the spacing 5 → 12 of 32, whole lobes lost.
    pub(crate) const NOISE_TIP_SAMPLES: u8 = 3;

    /// A noisy leaf whose samples spread wide for its ball and their noise stays: `λ² ≥ k·r·η`
    /// (`λ` half the largest distance between the face's samples, `r` the ball's radius, `η` the
    /// largest noise amplitude among them; see the module docs, "Spread").
    ///
    /// Measurement (random Fourier blobs, a 7-star, a peanut and an ellipse, 300 evenly spaced
    /// points a curve, 4 trials each): worst trunk gap at σ = 0.1 / 0.2 / 0.3 × the spacing, 14 /
    /// 14 / 14 % of the diameter without it; k = 4: precision lost (whiskers up to 28 %); k = 8:
    /// a whisker of 16 % at σ = 0.1; k = 12: 5.9 / 11.3 / 14.4 %, every segment within 2.7 %.
    /// On blobs of another seed at σ = 0.1 / 0.2: k = 12: gaps 5.7 / 14.2 %, one trial of 27 at
    /// σ = 0.1 with a 3.9 % whisker (a peanut); k = 16: no whisker, but a 13 % gap on the first
    /// blobs at σ = 0.1 and 14.3 % at 0.2. Used by `reconstruct/medial_axis.rs`.
    pub(crate) const SPREAD_SIGNIFICANCE: f64 = 12.0;

    /// Samples on either side of a sample that its amplitude averages over.
    ///
    /// Measurement: no alternative recorded. Used by `reconstruct/medial_axis/noise.rs`.
    pub(crate) const HALF_WINDOW: usize = 3;

    /// Samples whose estimates are computed together: the temporaries are those of a block (about
    /// 170 KiB), not of the loop (40 bytes a sample were the memory peak of the pruned axis at 10^6
    /// points on one loop).
    ///
    /// Used by `reconstruct/medial_axis/noise.rs`.
    pub(crate) const BLOCK: usize = 4096;

    /// How many leaves ahead of the one being tested `medial_axis::pruning::Lookahead` fetches: a
    /// fetch needs about as long as a few tests, and what is fetched too early leaves the
    /// first-level cache again. At 10^7 noisy points (one thread) 2, 4, 6, 8, 12 and 16 took the
    /// pruning from 2.16 s without to 1.32, 1.20, 1.13, 1.11, 1.44 and 1.44 s.
    ///
    /// Used by `reconstruct/medial_axis/pruning.rs`.
    pub(crate) const LOOKAHEAD: usize = 8;

    /// How far past the last leaf it found `medial_axis::pruning::Lookahead` looks for the next,
    /// per leaf tested: where the leaves are sparse, a search to the end of the set for every leaf
    /// would cost more than it saves.
    ///
    /// Used by `reconstruct/medial_axis/pruning.rs`.
    pub(crate) const LOOKAHEAD_REACH: usize = 512;
}

/// Smoothing: curve vertices fitted to the samples around them (`docs/design/smoothing.md`).
pub(crate) mod smooth {
    /// Window radii grow by this factor: a fit's residual is compared with that of a window of half
    /// its area (√2: the residual of a corner grows by as much per step, and two steps double it,
    /// which [`RESIDUAL_GROWTH`] catches).
    ///
    /// Measurement: 12 radii: dense bands stopped at the cap (one noisy circle's moved vertices
    /// 0.39 σ against 0.35 σ). Used by `reconstruct/smooth.rs`.
    pub(crate) const SCALE_STEP: f64 = std::f64::consts::SQRT_2;

    /// The gathering walks Delaunay edges at most this many times the nearest-neighbour distance at
    /// one of their ends: along the samples of one curve piece, graded sampling included, not
    /// across the inside of a sparse curve (an ε-sample's two sides lie at least `2/ε` spacings
    /// apart, 5 at ε = 0.39) nor from one noise band to the next.
    ///
    /// Used by `reconstruct/smooth.rs`.
    pub(crate) const LINK: f64 = 3.0;

    /// At most this many radii: the largest is `2^11.5 ≈ 2900` times the vertex's longer curve step
    /// (in a dense band the step is a small fraction of the noise; the windows stop long before, at
    /// [`MAX_WINDOW_POINTS`]).
    ///
    /// Measurement: 12 radii: dense bands stopped at the cap (one noisy circle's moved vertices
    /// 0.39 σ against 0.35 σ). Used by `reconstruct/smooth.rs`.
    pub(crate) const WINDOWS: usize = 24;

    /// A window grows no further once it holds this many samples (a bound on work: the error of a
    /// fit over `N` samples falls as `1/√N`, 4 % of the noise here).
    ///
    /// Measurement: 12 radii: dense bands stopped at the cap (one noisy circle's moved vertices
    /// 0.39 σ against 0.35 σ). Used by `reconstruct/smooth.rs`.
    pub(crate) const MAX_WINDOW_POINTS: usize = 512;

    /// Where the samples are many to a curve vertex (a band's representatives), the windows keep
    /// one sample in `⌈this × samples per vertex / MAX_WINDOW_POINTS⌉` (by a hash of the local
    /// index), so that [`MAX_WINDOW_POINTS`] of them span this many curve steps. A window is a
    /// curve piece only once it is thin (about 3.5 noise deviations long each way): in a band of
    /// 20 000 points a curve at σ = 1–2 % of the diagonal that is 650–1 300 samples, and taking
    /// every sample the windows stopped at the cap while still round, and no vertex moved.
    ///
    /// Measurement (bands of an ellipse, a 5-star, a blob and an ellipse with a hole, 20 000
    /// points a curve, σ = 0.5 / 1 / 2 % of the diagonal, 2 trials, a scratch copy of the
    /// quality benchmark's dense-band table): smoothed RMS over the input's noise, median over
    /// the rows, 0.19 before (unfitted at 1–2 %), 0.11 at 8, 0.13 at 4; every sample kept up
    /// to 8 steps' worth instead, 0.13, and the 10^6-point band of `stress band` took 3.3 s to
    /// smooth (1.2 s at 8 subsampled, 0.65 s at 4). Rows of 2 000 points a curve unchanged.
    /// Used by `reconstruct/smooth.rs`.
    pub(crate) const WINDOW_STEPS: usize = 8;

    /// A window grows no further once it spans this many of the curve's own vertices. Where the
    /// curve is no thinned band its samples are its vertices, and without this bound every vertex
    /// would average hundreds of its neighbours: the work per vertex grows with the window and the
    /// curve's with both. 64 vertices put the fit's error at an eighth of the noise; 32 averages
    /// too few where a curve is noisy but no band.
    ///
    /// Measurement: 32 / 64 / 128 on the dense-band rows: median ratio 0.31 each; the 600-point
    /// polygons' nearest fitted vertex to a square's corner 1.17 / 1.37 / 1.84 σ; a 10^5-point
    /// noisy curve 2.8 / 4.0 / 6.8 s (36 s without the bound). Used by `reconstruct/smooth.rs`.
    pub(crate) const MAX_WINDOW_VERTICES: usize = 64;

    /// The fewest samples (with positive weight) of a window that is fitted: a quadratic has three
    /// parameters, and its residual needs a few more samples to mean anything.
    ///
    /// Measurement: 6 a side: clean polygons' graded sides unfitted next to corners. Used by
    /// `reconstruct/smooth.rs`.
    pub(crate) const MIN_FIT_POINTS: usize = 6;

    /// The fewest samples of a one-sided window (a line: two parameters). Near a corner of a clean
    /// polygon a side may hold few samples within the window's reach; they lie on its line exactly,
    /// and the vertex stays on it.
    ///
    /// Measurement: 6 a side: clean polygons' graded sides unfitted next to corners. Used by
    /// `reconstruct/smooth.rs`.
    pub(crate) const MIN_LINE_POINTS: usize = 4;

    /// A window whose smaller principal variance is more than this share of its larger one is a
    /// blob, not a curve piece (a straight band of half-length `R` and noise `σ` has an aspect of
    /// about `3 (σ/R)²`, so this admits windows of more than about 3.5 σ).
    ///
    /// Measurement: no alternative recorded. Used by `reconstruct/smooth.rs`.
    pub(crate) const MAX_ASPECT: f64 = 0.25;

    /// A family of windows grows while the vertex's offset of its next window agrees with that of
    /// every smaller window within this many standard errors of their difference (for nested
    /// windows `√(s_small² − s_large²)`, the larger averaging the smaller's samples and more; 3 and
    /// 4 measured, dense-band median ratios 0.652 / 0.647): on a noise band the offsets of growing
    /// windows scatter within their errors, which shrink as the windows take more samples; where a
    /// window reaches a corner or a bend the fit cannot follow, its offset drifts away by more (the
    /// intersection-of-confidence-intervals rule).
    ///
    /// Measurement: 3 / 4: dense-band median 0.652 / 0.647 (one trial a row, all trials); the plain
    /// sum of the two errors: one noisy circle's moved vertices at 0.40–0.53 σ against 0.35 σ. Used
    /// by `reconstruct/smooth.rs`.
    pub(crate) const AGREEMENT: f64 = 4.0;

    /// The centred fit is replaced by a one-sided one when its residual is more than this times the
    /// one-sided one's: noise alone makes the residuals of the three families differ by less.
    ///
    /// Measurement: 1.25 / 1.5 / 2: dense-band median 0.78 / 0.75 / 0.64 (with the sides compared
    /// at their own windows, before the present rule). Used by `reconstruct/smooth.rs`.
    pub(crate) const SIDED_PREFERENCE: f64 = 2.0;

    /// A curve is smoothed when more than this share of its vertices zigzag (turn against both
    /// neighbours): about a quarter do where noise sets the turns, none on clean samples.
    ///
    /// Measurement: clean ε-samples (ε = 0.2, 0.39) and polygons: no vertex moves; without the test
    /// they moved by up to 0.45 spacings. Used by `reconstruct/curves.rs` (`zigzags`, read by
    /// smoothing and by the loops beside curves, `reconstruct/repairs/beside.rs`).
    pub(crate) const ZIGZAG_SHARE: f64 = 0.05;

    /// Turns (sines) below this are no turns to the zigzag test: the rounding of a moved or scaled
    /// straight run of clean samples turns them by about `1e-16`.
    ///
    /// Measurement: without it clean polygons zigzag (rounding's random signs). Used by
    /// `reconstruct/curves.rs` (`zigzags`).
    pub(crate) const FLAT: f64 = 1e-9;

    /// A family grows only while its residual stays within this factor of that of its window of
    /// half the radius: on noise the residual stays level as the window grows; where the window
    /// takes in a corner, another piece of the curve or the whole of a small one, the residual
    /// grows with the radius (a corner's doubles in two steps).
    ///
    /// Measurement: against the smallest residual so far: the same dense-band rows to three
    /// decimals. Used by `reconstruct/smooth.rs`.
    pub(crate) const RESIDUAL_GROWTH: f64 = 1.5;

    /// A fit that moves the vertex by more than this many of its residuals is not of the vertex's
    /// own samples (a Gaussian sample lies that far out once in 16 000).
    ///
    /// Measurement: without: a clean vertex beside a sharp corner projected onto the other leg (1.9
    /// spacings). Used by `reconstruct/smooth.rs`.
    pub(crate) const SHIFT_RESIDUALS: f64 = 4.0;

    /// Reweightings of a one-sided line fit (Tukey's biweight on the residuals): three settle it on
    /// a side's samples where a few of the other side's were in its half disk.
    ///
    /// Used by `reconstruct/smooth.rs`.
    pub(crate) const ROBUST_ITERATIONS: usize = 3;

    /// Tukey's constant (95 % efficiency on Gaussian noise), in units of the residuals' scale.
    ///
    /// Used by `reconstruct/smooth.rs`.
    pub(crate) const TUKEY: f64 = 4.685;

    /// The median absolute residual times this is the noise's standard deviation (Gaussian).
    ///
    /// Used by `reconstruct/smooth.rs`.
    pub(crate) const MAD_TO_SIGMA: f64 = 1.4826;

    /// A circle of fewer than this many window radii is not taken: on a short noisy arc the
    /// circle's curvature is unstable and the projection far from linear in the noise (the
    /// quadratic's standard error then says nothing about it).
    ///
    /// Measurement: circle at any radius: offsets of small windows jumped by 1.5 σ. Used by
    /// `reconstruct/smooth.rs`.
    pub(crate) const MIN_CIRCLE_RADIUS: f64 = 2.0;

    /// A circle of more than this many window radii is a line to the fit (the quadratic then fits
    /// it as well, and the circle's centre is ill-conditioned).
    ///
    /// Measurement: circle at any radius: offsets of small windows jumped by 1.5 σ. Used by
    /// `reconstruct/smooth.rs`.
    pub(crate) const LINE_RADIUS: f64 = 1e3;

    /// At most this many rounds of tests; then every move is undone (the unsmoothed curves are
    /// simple). Undoing spreads by a few points a round; the measurements never needed more than a
    /// handful.
    ///
    /// Measurement: undoing at once: 14 % of a dense ellipse's vertices back at their noisy
    /// positions. Used by `reconstruct/smooth/crossings.rs`.
    pub(crate) const MAX_ROUNDS: usize = 64;

    /// A move that makes a curve cross is shortened to this share of itself, then to its square,
    /// and so on, [`STAGES`] times, then undone: most crossings in a dense band come from two
    /// neighbouring vertices projected past each other along the fit, and half the move usually
    /// keeps them apart while keeping half the gain.
    ///
    /// Measurement: undoing at once: 14 % of a dense ellipse's vertices back at their noisy
    /// positions. Used by `reconstruct/smooth/crossings.rs`.
    pub(crate) const SHORTENED: f64 = 0.5;

    /// Shortenings before a move is undone.
    ///
    /// Measurement: undoing at once: 14 % of a dense ellipse's vertices back at their noisy
    /// positions. Used by `reconstruct/smooth/crossings.rs`.
    pub(crate) const STAGES: u8 = 2;
}

/// Warnings: signs that a result is not what was wanted (`docs/design/warnings.md`).
pub(crate) mod warnings {
    /// Two open chains whose ends are at most `2^CLOSE_ENDS_DOUBLINGS` times the step at each of
    /// those ends apart (the longer of its last two edges) may be one curve: noise or a sharp
    /// corner broke it where the samples of its two sides interleave, so that the ends are no
    /// Delaunay neighbours and the open-curve stage could not join them under its own bound
    /// (`open_curves::JOIN_DOUBLINGS`, the same 4×).
    ///
    /// Measurement: 1 200 trials of the quality benchmark's six open-curve families on other
    /// seeds (clean and noise 0.3 steps): spoke on 29 of the 109 wrong results (50 of 126
    /// before the swap of interleaved ends fixed most broken corners), none of the 1 091 right
    /// ones; the quality benchmark's right results warned 1 in 1 056, its wrong ones 32 of 215
    /// (30 of 218 without the code). At 1 (2×) a noisy polyline's corner whose ends were 1.9
    /// and 2.4 of their steps apart was not named. Used by `reconstruct/diagnose.rs`.
    pub(crate) const CLOSE_ENDS_DOUBLINGS: u32 = 2;

    /// Two open chains whose ends are at most `2^CLOSE_ENDS_LONGEST_DOUBLINGS` times the longest
    /// edge of each chain apart may be one curve too: samples at random positions leave gaps
    /// far longer than the steps beside them (the largest of 5 000 is about 8 mean steps), and
    /// a curve broken at such a gap ended in two chains without a warning.
    ///
    /// Measurement (a scratch probe: 11 open and closed shapes, 200–5 000 points per 2π of
    /// length, noise 0.1–1.3 spacings, even and random positions, two seeds, 1 056 inputs):
    /// wrong results with no warning 50 → 36 at 0 (1×), → 27 at 1 (2×); right results warned
    /// 10 at either, as without the rule. The quality benchmark: right results warned 1 of
    /// 1 056 as before, wrong ones 36 → 38 of 215. Used by `reconstruct/diagnose.rs`.
    pub(crate) const CLOSE_ENDS_LONGEST_DOUBLINGS: u32 = 1;

    /// An edge is *long* when it is more than `2^LONG_EDGE_DOUBLINGS` times each of the (up to
    /// four) curve edges within two steps of it. The open-curve stage already opens a loop at such
    /// a chord, and its chains never take an edge that long; what remains is a chord of the
    /// baselines, or of a loop whose neighbours are as sparse as the gap.
    ///
    /// Measurement: against the two adjacent edges only: 7 right noisy loops of `quality` warned;
    /// as now, none. Used by `reconstruct/diagnose.rs`.
    pub(crate) const LONG_EDGE_DOUBLINGS: u32 = 3;

    /// A long edge is warned only when it is also more than `2^LONG_EDGE_OUTLIER_DOUBLINGS` times
    /// its curve's longest ordinary edge (one not long by [`LONG_EDGE_DOUBLINGS`]), as the
    /// open-curve stage's chords must be (`open_curves::CHORD_OUTLIER_DOUBLINGS`, same value,
    /// same argument): random positions put a gap several mean steps long beside four short
    /// ones about once in 200 edges, and such gaps are the curve.
    ///
    /// Measurement: clean 5-lobed stars at random positions, one loop each and right, were
    /// warned `long-edge` at 56 / 200 / 616 edges (30 000 / 100 000 / 300 000 points); as now,
    /// not. The quality benchmark's warnings table: right results warned 1 as before, wrong
    /// ones warned 32 as before (`long-edge` left 3 line-drawing trials that other warnings
    /// name too). Used by `reconstruct/diagnose.rs`.
    pub(crate) const LONG_EDGE_OUTLIER_DOUBLINGS: u32 = 2;

    /// A closed loop whose longest edge is more than `2^GAP_EDGE_DOUBLINGS` times its next longest
    /// (and not long already) may close across the gap of an open curve. Noise and uneven sampling
    /// vary the edges of a right loop, but its two longest edges stay within a small factor of each
    /// other; a chord joining the ends of an open curve is alone.
    ///
    /// Measurement: as 4–8× the edges beside it: 30 right noisy loops (noise 0.3–1 × spacing)
    /// warned; as now, none; a 355° arc of 300 points (ends 4.2 steps apart) warned. Used by
    /// `reconstruct/diagnose.rs`.
    pub(crate) const GAP_EDGE_DOUBLINGS: u32 = 2;

    /// Two curve points closer than their curve edges are *too close* when they lie on different
    /// curves or more than this many steps apart along one curve. A sharp corner of angle θ brings
    /// the points of its two sides within one step of each other up to about `1 / sin(θ/2)` steps
    /// apart along the curve (11 at 10°, 23 at 5°): well inside the bound.
    ///
    /// Measurement: sharp-corner rows of `quality` (10–90°): no warning; drawings of touching
    /// curves: 24 of 30 warned. Used by `reconstruct/diagnose.rs`.
    pub(crate) const CLOSE_CURVE_STEPS: usize = 32;
}
