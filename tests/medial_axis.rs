//! The pruned medial axis against the true one.
//!
//! The true interior medial axis is the set of centres of the maximal tangent balls of dense
//! curves (`wdm_crust_testkit::medial_balls`), computed without any Voronoi code. For clean
//! ε-samples and for evenly spaced samples with Gaussian noise of 0.1 and 0.3 × the spacing,
//! of single shapes, a shape with a hole and two separate shapes, each under a random
//! similarity, the tests check these numbers:
//!
//! * **precision**: no output segment lies farther than 3 % of the shape's diameter `D` from
//!   the true axis;
//! * **trunk coverage**: every true centre whose radius is at least 10 % of the largest lies
//!   within 3 % of `D` (clean) or 10 % of `D` (noisy) of the output;
//! * **topology**: one component per region the curves bound, one independent cycle per hole
//!   (`edges = vertices − components + holes`).
//!
//! The raw WDM_MAT is measured on the same inputs for comparison (printed, not asserted:
//! whiskers are what the paper's axis has).

use wdm_crust::reconstruct::{MedialAxis, MedialAxisMode, Options};
use wdm_crust::reconstruct_with;
use wdm_crust_testkit::{
    medial_balls, segment_distance, ClosedCurve, CurveSet, DenseCurve, Ellipse, FourierBlob,
    Peanut, Rng, Similarity, Star, Superellipse,
};

const DENSE: usize = 20_000;

/// A test shape: its curves, how many regions they bound and how many holes those have.
struct Shape {
    name: &'static str,
    curves: Vec<DenseCurve>,
    regions: usize,
    holes: usize,
}

fn shapes() -> Vec<Shape> {
    let single = |name, curve: DenseCurve| Shape {
        name,
        curves: vec![curve],
        regions: 1,
        holes: 0,
    };
    let hole = reversed(&Ellipse::circle(0.3).dense(DENSE / 2), [0.25, 0.1]);
    let star = Star { a: 0.25, k: 5 }
        .dense(DENSE)
        .transformed(&Similarity::translation([2.6, 0.0]));
    vec![
        single("ellipse", Ellipse { a: 1.0, b: 0.5 }.dense(DENSE)),
        single("peanut", Peanut { a: 0.3, b: 0.12 }.dense(DENSE)),
        single("star", Star { a: 0.25, k: 5 }.dense(DENSE)),
        single(
            "superellipse",
            Superellipse {
                a: 1.0,
                b: 0.6,
                p: 4.0,
            }
            .dense(DENSE),
        ),
        Shape {
            name: "hole",
            curves: vec![Ellipse { a: 1.0, b: 0.7 }.dense(DENSE), hole],
            regions: 1,
            holes: 1,
        },
        Shape {
            name: "two",
            curves: vec![Ellipse { a: 1.0, b: 0.6 }.dense(DENSE), star],
            regions: 2,
            holes: 0,
        },
    ]
}

/// A closed curve moved by `offset` and run clockwise (a hole: its left normals point out
/// of the hole, into the shape).
fn reversed(curve: &DenseCurve, offset: [f64; 2]) -> DenseCurve {
    let moved = curve.transformed(&Similarity::translation(offset));
    DenseCurve {
        points: moved.points.iter().rev().copied().collect(),
        normals: moved.normals.iter().rev().map(|n| [-n[0], -n[1]]).collect(),
        closed: true,
        corners: Vec::new(),
    }
}

/// The true interior medial axis and the scale it is measured in.
struct Truth {
    centres: Vec<[f64; 2]>,
    radii: Vec<f64>,
    /// Largest diameter of the curves (each region is measured against the largest).
    diameter: f64,
    grid: Grid,
}

impl Truth {
    /// The image under a similarity: centres move with it, lengths scale.
    fn transformed(&self, s: &Similarity) -> Truth {
        let centres: Vec<[f64; 2]> = self.centres.iter().map(|&c| s.apply(c)).collect();
        let diameter = self.diameter * s.scale;
        Truth {
            radii: self.radii.iter().map(|&r| r * s.scale).collect(),
            grid: Grid::new(&centres, diameter / 200.0),
            centres,
            diameter,
        }
    }

    fn new(curves: &[DenseCurve]) -> Truth {
        let balls: Vec<_> = medial_balls(curves)
            .into_iter()
            .filter(|b| b.interior)
            .collect();
        let centres: Vec<[f64; 2]> = balls.iter().map(|b| b.centre).collect();
        let diameter = curves
            .iter()
            .map(|c| diameter(&c.points))
            .fold(0.0, f64::max);
        Truth {
            radii: balls.iter().map(|b| b.radius).collect(),
            grid: Grid::new(&centres, diameter / 200.0),
            centres,
            diameter,
        }
    }
}

/// Largest distance between two points of a dense curve (on every 10th point: the error is
/// below a dense spacing).
fn diameter(points: &[[f64; 2]]) -> f64 {
    let some: Vec<[f64; 2]> = points.iter().step_by(10).copied().collect();
    let mut d: f64 = 0.0;
    for (i, p) in some.iter().enumerate() {
        for q in &some[i + 1..] {
            d = d.max(dist(*p, *q));
        }
    }
    d
}

fn dist(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

/// A uniform grid over points for nearest-point queries.
struct Grid {
    cell: f64,
    origin: [f64; 2],
    cols: usize,
    rows: usize,
    buckets: Vec<Vec<[f64; 2]>>,
}

impl Grid {
    fn new(points: &[[f64; 2]], cell: f64) -> Grid {
        let lo = points
            .iter()
            .fold([f64::MAX; 2], |m, p| [m[0].min(p[0]), m[1].min(p[1])]);
        let hi = points
            .iter()
            .fold([f64::MIN; 2], |m, p| [m[0].max(p[0]), m[1].max(p[1])]);
        let cols = ((hi[0] - lo[0]) / cell) as usize + 1;
        let rows = ((hi[1] - lo[1]) / cell) as usize + 1;
        let mut buckets = vec![Vec::new(); cols * rows];
        for &p in points {
            let (i, j) = (
                ((p[0] - lo[0]) / cell) as usize,
                ((p[1] - lo[1]) / cell) as usize,
            );
            buckets[j * cols + i].push(p);
        }
        Grid {
            cell,
            origin: lo,
            cols,
            rows,
            buckets,
        }
    }

    /// Distance from `p` to the nearest point (rings of cells until one is certain).
    fn nearest(&self, p: [f64; 2]) -> f64 {
        let ci = ((p[0] - self.origin[0]) / self.cell).floor() as i64;
        let cj = ((p[1] - self.origin[1]) / self.cell).floor() as i64;
        let mut best = f64::INFINITY;
        for ring in 0..(self.cols.max(self.rows) as i64 + 2 + ci.abs() + cj.abs()) {
            for j in cj - ring..=cj + ring {
                for i in ci - ring..=ci + ring {
                    let on_ring = (j - cj).abs() == ring || (i - ci).abs() == ring;
                    if !on_ring || i < 0 || j < 0 || i >= self.cols as i64 || j >= self.rows as i64
                    {
                        continue;
                    }
                    for &q in &self.buckets[j as usize * self.cols + i as usize] {
                        best = best.min(dist(p, q));
                    }
                }
            }
            // Every point not yet seen is at least `ring` cells away.
            if best <= ring as f64 * self.cell {
                break;
            }
        }
        best
    }
}

/// How an axis compares with the truth, in fractions of the diameter.
#[derive(Debug, Clone, Copy)]
struct Score {
    /// Largest distance from a point of an output segment to the true axis.
    deviation: f64,
    /// Largest distance from a trunk centre to the output.
    gap: f64,
    components: usize,
    cycles: usize,
}

fn score(axis: &MedialAxis, truth: &Truth) -> Score {
    let d = truth.diameter;
    let mut deviation: f64 = 0.0;
    for &[a, b] in &axis.edges {
        let (p, q) = (axis.vertices[a as usize], axis.vertices[b as usize]);
        let steps = (dist(p, q) / (d / 1000.0)).ceil().max(1.0) as usize;
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            let x = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            deviation = deviation.max(truth.grid.nearest(x));
        }
    }
    let largest = truth.radii.iter().copied().fold(0.0, f64::max);
    let mut gap: f64 = 0.0;
    for (c, &r) in truth.centres.iter().zip(&truth.radii).step_by(5) {
        if r >= 0.1 * largest {
            let near = axis
                .edges
                .iter()
                .map(|&[a, b]| {
                    segment_distance(*c, axis.vertices[a as usize], axis.vertices[b as usize])
                })
                .fold(f64::INFINITY, f64::min);
            gap = gap.max(near);
        }
    }
    let (components, cycles) = topology(axis);
    Score {
        deviation: deviation / d,
        gap: gap / d,
        components,
        cycles,
    }
}

/// Connected components and independent cycles of the axis graph (vertices without edges
/// do not occur in a `MedialAxis`).
fn topology(axis: &MedialAxis) -> (usize, usize) {
    let n = axis.vertices.len();
    let mut parent: Vec<usize> = (0..n).collect();
    fn find(parent: &mut [usize], mut v: usize) -> usize {
        while parent[v] != v {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        v
    }
    let mut components = n;
    for &[a, b] in &axis.edges {
        let (ra, rb) = (find(&mut parent, a as usize), find(&mut parent, b as usize));
        if ra != rb {
            parent[ra] = rb;
            components -= 1;
        }
    }
    (components, axis.edges.len() + components - n)
}

/// `n` points evenly spaced in arc length along a dense closed curve, from a random start.
fn evenly_spaced(curve: &DenseCurve, n: usize, rng: &mut Rng) -> (Vec<[f64; 2]>, f64) {
    let m = curve.points.len();
    let mut at = Vec::with_capacity(m + 1);
    let mut length = 0.0;
    for i in 0..=m {
        at.push(length);
        length += dist(curve.points[i % m], curve.points[(i + 1) % m]);
    }
    let total = at[m];
    let spacing = total / n as f64;
    let phase = rng.f64() * spacing;
    let mut points = Vec::with_capacity(n);
    let mut i = 0;
    for k in 0..n {
        let s = phase + k as f64 * spacing;
        while at[i + 1] < s {
            i += 1;
        }
        let t = (s - at[i]) / (at[i + 1] - at[i]);
        let (p, q) = (curve.points[i % m], curve.points[(i + 1) % m]);
        points.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
    }
    (points, spacing)
}

/// Input kinds: a clean ε-sample, evenly spaced points with noise `σ = f × spacing`, or an
/// ε-sample with noise `σ = f ×` each sample's distance to its nearest other sample.
#[derive(Debug, Clone, Copy)]
enum Input {
    Clean,
    Noisy(f64),
    NoisyEps(f64, f64),
}

/// One trial: the sample (moved by a random similarity), and the truth moved with it.
fn trial(
    shape: &Shape,
    set: &CurveSet,
    truth: &Truth,
    input: Input,
    rng: &mut Rng,
) -> (Vec<[f64; 2]>, Truth) {
    let s = Similarity::random(rng);
    let mut points = match input {
        Input::Clean => set.eps_sample(0.3, rng).points,
        Input::NoisyEps(eps, f) => {
            let clean = set.eps_sample(eps, rng).points;
            let mut noisy = clean.clone();
            for (i, p) in noisy.iter_mut().enumerate() {
                let nearest = clean
                    .iter()
                    .enumerate()
                    .filter(|&(j, _)| j != i)
                    .map(|(_, &q)| dist(clean[i], q))
                    .fold(f64::INFINITY, f64::min);
                p[0] += f * nearest * rng.normal();
                p[1] += f * nearest * rng.normal();
            }
            noisy
        }
        Input::Noisy(f) => {
            let mut all = Vec::new();
            // The same spacing on every curve: that of 300 points on the longest.
            let longest = shape.curves.iter().map(length).fold(0.0, f64::max);
            let spacing = longest / 300.0;
            for c in &shape.curves {
                let n = (length(c) / spacing).round() as usize;
                let (mut pts, h) = evenly_spaced(c, n, rng);
                for p in &mut pts {
                    p[0] += f * h * rng.normal();
                    p[1] += f * h * rng.normal();
                }
                all.extend(pts);
            }
            all
        }
    };
    for p in &mut points {
        *p = s.apply(*p);
    }
    rng.shuffle(&mut points);
    (points, truth.transformed(&s))
}

fn length(c: &DenseCurve) -> f64 {
    let m = c.points.len();
    (0..m)
        .map(|i| dist(c.points[i], c.points[(i + 1) % m]))
        .sum()
}

/// Pass counts of one mode over the trials of one shape and input kind.
#[derive(Default)]
struct Tally {
    trials: usize,
    precise: usize,
    covering: usize,
    topology: usize,
    worst_deviation: f64,
    worst_gap: f64,
}

impl Tally {
    fn add(&mut self, s: Score, gap_limit: f64, shape: &Shape) {
        self.trials += 1;
        self.precise += usize::from(s.deviation <= 0.03);
        self.covering += usize::from(s.gap <= gap_limit);
        self.topology += usize::from(s.components == shape.regions && s.cycles == shape.holes);
        self.worst_deviation = self.worst_deviation.max(s.deviation);
        self.worst_gap = self.worst_gap.max(s.gap);
    }

    fn row(&self) -> String {
        format!(
            "{:>3}/{:<3} {:>3}/{:<3} {:>3}/{:<3} dev {:.4} gap {:.4}",
            self.precise,
            self.trials,
            self.covering,
            self.trials,
            self.topology,
            self.trials,
            self.worst_deviation,
            self.worst_gap
        )
    }
}

/// Runs `trials` trials per shape of one input kind; returns (pruned, raw) tallies per
/// shape, counting only trials whose reconstruction found as many closed curves as there
/// are true curves (the axis of a wrong reconstruction is not the axis of the shape).
fn measure(input: Input, trials: usize, seed: u64) -> Vec<(&'static str, Tally, Tally, usize)> {
    measure_on(shapes(), input, trials, seed)
}

/// [`measure`] on other shapes.
fn measure_on(
    shapes: Vec<Shape>,
    input: Input,
    trials: usize,
    seed: u64,
) -> Vec<(&'static str, Tally, Tally, usize)> {
    let mut rng = Rng::new(seed);
    let gap_limit = match input {
        Input::Clean => 0.03,
        Input::Noisy(_) | Input::NoisyEps(..) => 0.10,
    };
    let mut rows = Vec::new();
    for shape in shapes {
        let set = CurveSet::new(shape.curves.clone());
        let truth = Truth::new(&shape.curves);
        let (mut pruned, mut raw) = (Tally::default(), Tally::default());
        let mut wrong_curves = 0;
        for _ in 0..trials {
            let (points, truth) = trial(&shape, &set, &truth, input, &mut rng);
            let rec = reconstruct_with(&points, &Options::new()).expect("valid points");
            let closed = rec.curves().iter().filter(|c| c.closed).count();
            if closed != shape.curves.len() {
                wrong_curves += 1;
                continue;
            }
            pruned.add(score(rec.medial_axis(), &truth), gap_limit, &shape);
            let rec_raw = reconstruct_with(
                &points,
                &Options::new().with_medial_axis(MedialAxisMode::Raw),
            )
            .expect("valid points");
            raw.add(score(rec_raw.medial_axis(), &truth), gap_limit, &shape);
        }
        eprintln!(
            "{input:?} {:<13} pruned {} | raw {} | curves wrong {wrong_curves}/{trials}",
            shape.name,
            pruned.row(),
            raw.row()
        );
        rows.push((shape.name, pruned, raw, wrong_curves));
    }
    rows
}

/// What each shape must meet: the largest trunk gap (fraction of the diameter) and whether
/// every trial must be within the 3 % precision.
struct Expect {
    min_trials: usize,
    gap: fn(&str) -> f64,
    all_precise: fn(&str) -> bool,
    /// The largest deviation any trial may have, for the shapes not all precise.
    worst_deviation: f64,
}

fn check(rows: &[(&'static str, Tally, Tally, usize)], expect: &Expect) {
    for (name, pruned, _, _) in rows {
        assert!(
            pruned.trials >= expect.min_trials,
            "{name}: only {} trials with the right curves",
            pruned.trials
        );
        assert_eq!(pruned.topology, pruned.trials, "{name}: topology");
        assert!(
            pruned.worst_gap <= (expect.gap)(name),
            "{name}: trunk gap {}",
            pruned.worst_gap
        );
        if (expect.all_precise)(name) {
            assert_eq!(pruned.precise, pruned.trials, "{name}: precision");
        }
        assert!(
            pruned.worst_deviation <= expect.worst_deviation,
            "{name}: deviation {}",
            pruned.worst_deviation
        );
    }
}

/// Clean ε-samples meet the module's numbers. The superellipse's rounded corners carry
/// branches whose object angle falls below 60° while the radius is still large: they keep
/// their length because clean samples are pruned at 20° (trunk gap 2.5 % of the diameter;
/// 6.4 % at 60°).
#[test]
fn clean_samples() {
    let rows = measure(Input::Clean, 12, 1);
    check(
        &rows,
        &Expect {
            min_trials: 12,
            gap: |_| 0.03,
            all_precise: |_| true,
            worst_deviation: 0.03,
        },
    );
}

#[test]
fn noise_of_a_tenth_of_the_spacing() {
    let rows = measure(Input::Noisy(0.1), 12, 2);
    check(
        &rows,
        &Expect {
            min_trials: 12,
            gap: |_| 0.10,
            all_precise: |_| true,
            worst_deviation: 0.03,
        },
    );
}

/// At 0.3 × the spacing the noise slack of the pruning takes off the hooks that the angle
/// alone left at the star's tips and around the hole (up to 12 % of the diameter before
/// it; the raw axis: 19–31 %): every trial is within 3 %, the worst at 2.4 %.
#[test]
fn noise_of_three_tenths_of_the_spacing() {
    let rows = measure(Input::Noisy(0.3), 12, 3);
    check(
        &rows,
        &Expect {
            min_trials: 12,
            gap: |_| 0.10,
            all_precise: |_| true,
            worst_deviation: 0.03,
        },
    );
    for (name, pruned, raw, _) in &rows {
        assert!(pruned.worst_deviation < raw.worst_deviation, "{name}");
    }
}

/// Six random Fourier blobs drawn from `seed`.
fn random_blobs(seed: u64) -> Vec<Shape> {
    let mut rng = Rng::new(seed);
    let names = ["blob 1", "blob 2", "blob 3", "blob 4", "blob 5", "blob 6"];
    names
        .into_iter()
        .map(|name| Shape {
            name,
            curves: vec![FourierBlob::random(&mut rng).dense(DENSE)],
            regions: 1,
            holes: 0,
        })
        .collect()
}

/// Random Fourier blobs: broad lobes whose branches have an object angle under 60° all
/// along and whose tip balls stick out of their junction's by under twice the noise; the
/// spread of their samples keeps them (a trunk gap of 14 % of the diameter without it).
#[test]
fn broad_lobes_of_noisy_blobs_keep_their_branches() {
    let rows = measure_on(random_blobs(11), Input::Noisy(0.1), 4, 2);
    check(
        &rows,
        &Expect {
            min_trials: 4,
            gap: |_| 0.10,
            all_precise: |_| true,
            worst_deviation: 0.03,
        },
    );
}

/// Random Fourier blobs evenly sampled without noise: their broad lobes carry branches
/// whose object angle falls under 30° while the balls are still large, and they keep them
/// (clean loops are pruned at 20°; at 30° these lost 3.3 % of the diameter, other blobs up
/// to 5.5 %).
#[test]
fn clean_blobs_keep_their_broad_lobes() {
    let rows = measure_on(random_blobs(101), Input::Noisy(0.0), 4, 102);
    check(
        &rows,
        &Expect {
            min_trials: 4,
            gap: |_| 0.03,
            all_precise: |_| true,
            worst_deviation: 0.03,
        },
    );
}

/// Sparse noisy ellipses (ε-samples at ε = 0.2, noise of 0.2 × each sample's
/// nearest-neighbour distance): a sample displaced on a sparse flat side grows a branch of
/// balls as large as the trunk's, which the noise slack takes off as a branch ending in at
/// most three samples (whiskers up to 13 % of the diameter before, in 13 of 40 trials).
#[test]
fn sparse_noisy_ellipses_grow_no_whiskers() {
    let single = |name, curve: DenseCurve| Shape {
        name,
        curves: vec![curve],
        regions: 1,
        holes: 0,
    };
    let ellipses = vec![
        single("ellipse 2:1", Ellipse { a: 1.0, b: 0.5 }.dense(DENSE)),
        single("ellipse 3:1", Ellipse { a: 1.0, b: 0.35 }.dense(DENSE)),
    ];
    let rows = measure_on(ellipses, Input::NoisyEps(0.2, 0.2), 20, 402);
    check(
        &rows,
        &Expect {
            min_trials: 20,
            gap: |_| 0.10,
            all_precise: |_| true,
            worst_deviation: 0.03,
        },
    );
}

/// The pruned axis depends on the points, not on their order.
#[test]
fn the_pruned_axis_does_not_depend_on_the_input_order() {
    let mut rng = Rng::new(7);
    for shape in shapes() {
        let set = CurveSet::new(shape.curves.clone());
        let truth = Truth::new(&shape.curves);
        let (points, _) = trial(&shape, &set, &truth, Input::Noisy(0.3), &mut rng);
        let segments = |pts: &[[f64; 2]]| {
            let rec = reconstruct_with(pts, &Options::new()).expect("valid points");
            let axis = rec.medial_axis();
            let mut segs: Vec<[[u64; 2]; 2]> = axis
                .edges
                .iter()
                .map(|&[a, b]| {
                    let key = |v: u32| axis.vertices[v as usize].map(f64::to_bits);
                    let (p, q) = (key(a), key(b));
                    [p.min(q), p.max(q)]
                })
                .collect();
            segs.sort_unstable();
            segs
        };
        let base = segments(&points);
        assert!(!base.is_empty(), "{}", shape.name);
        let mut permuted = points.clone();
        rng.shuffle(&mut permuted);
        assert_eq!(segments(&permuted), base, "{}", shape.name);
    }
}

/// Points evenly spaced on the boundary of an axis-parallel rectangle, counterclockwise.
fn rectangle(x0: f64, y0: f64, w: f64, h: f64, per_unit: f64) -> Vec<[f64; 2]> {
    let corners = [[x0, y0], [x0 + w, y0], [x0 + w, y0 + h], [x0, y0 + h]];
    let mut out = Vec::new();
    for k in 0..4 {
        let (p, q) = (corners[k], corners[(k + 1) % 4]);
        let n = (dist(p, q) * per_unit).round() as usize;
        for i in 0..n {
            let t = i as f64 / n as f64;
            out.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
        }
    }
    out
}

/// Lattice points on rectangles are full of exactly cocircular quadruples (merged faces):
/// the axis is still one tree per shape, with one cycle around a hole. (No curve edge is a
/// chord of a merged face here; that path of the parity is not exercised.)
#[test]
fn cocircular_rectangles_give_a_tree_and_a_cycle() {
    let outer = rectangle(0.0, 0.0, 8.0, 4.0, 4.0);
    let rec = reconstruct_with(&outer, &Options::new()).expect("valid points");
    assert_eq!(rec.curves().len(), 1);
    let axis = rec.medial_axis();
    assert!(axis.edges.len() > 4, "{} segments", axis.edges.len());
    assert_eq!(topology(axis), (1, 0));

    let mut ring = rectangle(0.0, 0.0, 12.0, 12.0, 2.0);
    ring.extend(rectangle(4.0, 4.0, 4.0, 4.0, 2.0));
    let rec = reconstruct_with(&ring, &Options::new()).expect("valid points");
    assert_eq!(rec.curves().iter().filter(|c| c.closed).count(), 2);
    let axis = rec.medial_axis();
    assert_eq!(topology(axis), (1, 1));
    // Every vertex lies between the two squares.
    for &[x, y] in &axis.vertices {
        let outside_hole = !(4.0..=8.0).contains(&x) || !(4.0..=8.0).contains(&y);
        assert!((0.0..=12.0).contains(&x) && (0.0..=12.0).contains(&y) && outside_hole);
    }
}
