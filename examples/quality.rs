//! Reconstruction quality of WDM_CRUST against the crust and the NN-crust.
//!
//! ```text
//! cargo run --release --example quality [-- DATA_DIR]
//! ```
//!
//! For point sets with known ground-truth edges it reports, per algorithm, the recall and
//! precision of the edges (pooled over the trials of a row), the rate of exact polygons (the
//! output equals the ground truth), and for noisy sets the symmetric Hausdorff distance and the
//! RMS distance (output → truth) between the output edges and the true curve, in % of the
//! bounding-box diagonal of the truth. Inputs:
//! * ε-samples of smooth analytic curves at ε = 0.2, 0.39 (within the theory) and 0.5, 0.8,
//!   1.2 (beyond it), randomly moved, scaled and shuffled;
//! * polygons with sharp corners, several disjoint curves, nested curves, 10–40 % outliers,
//!   Gaussian noise proportional to the local feature size;
//! * ε-samples of the SVG drawings of `sampling2d`, and the real point sets whose file order
//!   gives the ground truth;
//! * smoothing (`Options::with_smoothing`): dense noisy bands (ellipse, 5-star, Fourier blob,
//!   an ellipse with a hole; 300–2000 points a curve, σ 0.5–2 % of the diagonal) against
//!   the input's own noise and a FitConnect-style projection, clean ε-samples, noisy
//!   polygons' corners.
//!
//! The real data (GPL-3.0 point sets and SVG drawings, see `tests/data/README.md`) is read from
//! `DATA_DIR`, else from the environment variable `WDM_CRUST_DATA`, else from the repository's
//! `tests/data`. A missing file stops the run with an error; nothing is skipped.
//!
//! Every random choice comes from fixed seeds: the output is deterministic.

use std::collections::BTreeMap;
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Instant;

use wdm_crust::reconstruct::{reconstruct_with, Algorithm, LabelRule, Options};
use wdm_crust::Reconstruction;
use wdm_crust_testkit::{
    bbox, segment_distance, ClosedCurve, CurveSet, DenseCurve, Ellipse, Peanut, Rng, Sample,
    SampleConfig, Similarity, Star, Superellipse,
};

const ALGORITHMS: [Algorithm; 3] = [Algorithm::Wdm, Algorithm::Crust, Algorithm::NnCrust];

/// A named reconstruction method.
struct Method {
    name: &'static str,
    options: Options,
}

/// The three algorithms with their default options.
fn algorithms() -> Vec<Method> {
    ALGORITHMS
        .iter()
        .map(|&algorithm| Method {
            name: algorithm.name(),
            options: Options::new().with_algorithm(algorithm),
        })
        .collect()
}

/// WDM_CRUST with peeling on and off, without the detour repair, and with the three label
/// rules.
fn wdm_variants() -> Vec<Method> {
    let wdm = |peeling, label_rule| {
        Options::new()
            .with_algorithm(Algorithm::Wdm)
            .with_peeling(peeling)
            .with_label_rule(label_rule)
    };
    vec![
        Method {
            name: "wdm (default)",
            options: wdm(true, LabelRule::WaterReached),
        },
        Method {
            name: "wdm no detour repair",
            options: wdm(true, LabelRule::WaterReached).with_detour_repair(false),
        },
        Method {
            name: "wdm 1 pass",
            options: wdm(false, LabelRule::WaterReached),
        },
        Method {
            name: "wdm literal",
            options: wdm(true, LabelRule::Literal),
        },
        Method {
            name: "wdm complement",
            options: wdm(true, LabelRule::Complement),
        },
    ]
}
/// Default directory of the real data: the copies inside the repository.
const DEFAULT_DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data");
/// The real-data directory chosen in `main`.
static DATA: std::sync::OnceLock<PathBuf> = std::sync::OnceLock::new();
/// Dense points per analytic curve.
const DENSE: usize = 4000;

// ---------------------------------------------------------------------------------------
// Cases and scores.

/// One input with its ground truth.
#[derive(Clone)]
struct Case {
    points: Vec<[f64; 2]>,
    /// Ground-truth edges `(min, max)`.
    truth: HashSet<(u32, u32)>,
    /// The true curves as dense polylines, when known (for distances).
    curves: Vec<DenseCurve>,
}

impl Case {
    fn from_sample(sample: &Sample, curves: Vec<DenseCurve>) -> Case {
        Case {
            points: sample.points.clone(),
            truth: sample
                .edge_set()
                .into_iter()
                .map(|(a, b)| (a as u32, b as u32))
                .collect(),
            curves,
        }
    }
}

/// Sums over the trials of one row for one algorithm.
#[derive(Default, Clone)]
struct Tally {
    trials: usize,
    exact: usize,
    true_positives: usize,
    truth: usize,
    output: usize,
    hausdorff: f64,
    rms: f64,
    distances: usize,
    seconds: f64,
}

impl Tally {
    fn add(&mut self, case: &Case, edges: &[[u32; 2]], seconds: f64, distances: bool) {
        let output: HashSet<(u32, u32)> = edges.iter().map(|&[a, b]| (a, b)).collect();
        let tp = output.intersection(&case.truth).count();
        self.trials += 1;
        self.true_positives += tp;
        self.truth += case.truth.len();
        self.output += output.len();
        self.exact += usize::from(output == case.truth);
        self.seconds += seconds;
        if distances && !case.curves.is_empty() {
            let (h, r) = curve_distances(&case.points, edges, &case.curves);
            self.hausdorff += h;
            self.rms += r;
            self.distances += 1;
        }
    }

    fn recall(&self) -> f64 {
        percent(self.true_positives, self.truth)
    }

    fn precision(&self) -> f64 {
        percent(self.true_positives, self.output)
    }

    fn exact_rate(&self) -> f64 {
        percent(self.exact, self.trials)
    }
}

fn percent(a: usize, b: usize) -> f64 {
    if b == 0 {
        100.0
    } else {
        100.0 * a as f64 / b as f64
    }
}

/// One table row: a label and a tally per algorithm.
struct Row {
    label: String,
    points: usize,
    tallies: Vec<Tally>,
}

/// Runs every method on every case of a row.
fn run_row(label: &str, cases: &[Case], methods: &[Method], distances: bool) -> Row {
    let mut tallies = vec![Tally::default(); methods.len()];
    for case in cases {
        for (tally, method) in tallies.iter_mut().zip(methods) {
            let start = Instant::now();
            let edges = match reconstruct_with(&case.points, &method.options) {
                Ok(rec) => {
                    let exact = rec.edges().len() == case.truth.len()
                        && rec
                            .edges()
                            .iter()
                            .all(|&[a, b]| case.truth.contains(&(a, b)));
                    record_warnings(label, method, exact, &rec);
                    rec.edges().to_vec()
                }
                Err(e) => {
                    eprintln!("{label}: {} failed: {e}", method.name);
                    Vec::new()
                }
            };
            tally.add(case, &edges, start.elapsed().as_secs_f64(), distances);
        }
    }
    let points = cases.iter().map(|c| c.points.len()).sum::<usize>() / cases.len().max(1);
    Row {
        label: label.to_string(),
        points,
        tallies,
    }
}

fn print_table(title: &str, rows: &[Row], methods: &[Method], distances: bool) {
    println!("\n### {title}\n");
    let mut header = String::from("| category | trials | n |");
    let mut rule = String::from("|---|---:|---:|");
    for method in methods {
        let name = method.name;
        header += &format!(" {name} R | {name} P | {name} exact |");
        rule += "---:|---:|---:|";
        if distances {
            header += &format!(" {name} Hausdorff | {name} RMS |");
            rule += "---:|---:|";
        }
    }
    println!("{header}\n{rule}");
    for row in rows {
        let trials = row.tallies.first().map_or(0, |t| t.trials);
        let mut line = format!("| {} | {} | {} |", row.label, trials, row.points);
        for t in &row.tallies {
            line += &format!(
                " {:.1} | {:.1} | {:.0} % |",
                t.recall(),
                t.precision(),
                t.exact_rate()
            );
            if distances {
                let d = t.distances.max(1) as f64;
                line += &format!(" {:.2} | {:.3} |", t.hausdorff / d, t.rms / d);
            }
        }
        println!("{line}");
    }
}

// ---------------------------------------------------------------------------------------
// Distances between output edges and the true curves.

/// A uniform grid over segments, for nearest-segment queries.
struct SegmentGrid {
    segments: Vec<[[f64; 2]; 2]>,
    origin: [f64; 2],
    cell: f64,
    size: [usize; 2],
    cells: Vec<Vec<u32>>,
}

impl SegmentGrid {
    fn new(segments: Vec<[[f64; 2]; 2]>, lo: [f64; 2], hi: [f64; 2]) -> SegmentGrid {
        let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-300);
        let per_side = ((segments.len() as f64).sqrt().ceil() as usize).clamp(1, 512);
        let cell = extent / per_side as f64 * (1.0 + 1e-9);
        let size = [
            (((hi[0] - lo[0]) / cell) as usize + 1).max(1),
            (((hi[1] - lo[1]) / cell) as usize + 1).max(1),
        ];
        let mut grid = SegmentGrid {
            segments,
            origin: lo,
            cell,
            size,
            cells: vec![Vec::new(); size[0] * size[1]],
        };
        for (i, s) in grid.segments.iter().enumerate() {
            let (a, b) = (grid.index(s[0]), grid.index(s[1]));
            for x in a[0].min(b[0])..=a[0].max(b[0]) {
                for y in a[1].min(b[1])..=a[1].max(b[1]) {
                    grid.cells[y * size[0] + x].push(i as u32);
                }
            }
        }
        grid
    }

    fn index(&self, p: [f64; 2]) -> [usize; 2] {
        let c = |k: usize| {
            let f = ((p[k] - self.origin[k]) / self.cell).floor();
            (f.max(0.0) as usize).min(self.size[k] - 1)
        };
        [c(0), c(1)]
    }

    /// Distance from `p` to the nearest segment (infinite if there are none).
    fn distance(&self, p: [f64; 2]) -> f64 {
        if self.segments.is_empty() {
            return f64::INFINITY;
        }
        let [cx, cy] = self.index(p);
        let mut best = f64::INFINITY;
        let reach = self.size[0].max(self.size[1]);
        for r in 0..=reach {
            let (x0, x1) = (cx.saturating_sub(r), (cx + r).min(self.size[0] - 1));
            let (y0, y1) = (cy.saturating_sub(r), (cy + r).min(self.size[1] - 1));
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let ring = x.abs_diff(cx).max(y.abs_diff(cy));
                    if ring != r {
                        continue;
                    }
                    for &s in &self.cells[y * self.size[0] + x] {
                        let [a, b] = self.segments[s as usize];
                        best = best.min(segment_distance(p, a, b));
                    }
                }
            }
            // Cells beyond ring r are at least r cells away from p's cell.
            if best <= r as f64 * self.cell {
                break;
            }
        }
        best
    }
}

/// `(Hausdorff, RMS)` in % of the truth's bounding-box diagonal: Hausdorff is symmetric
/// (points along the output edges to the curves, dense curve points to the output edges); RMS
/// is over points along the output edges. No output edges: 100 % for both.
fn curve_distances(points: &[[f64; 2]], edges: &[[u32; 2]], curves: &[DenseCurve]) -> (f64, f64) {
    let mut truth_segments = Vec::new();
    for c in curves {
        let n = c.points.len();
        let count = if c.closed { n } else { n.saturating_sub(1) };
        truth_segments.extend((0..count).map(|i| [c.points[i], c.points[(i + 1) % n]]));
    }
    let (lo, hi) = bbox(curves.iter().flat_map(|c| c.points.iter().copied()));
    let diag = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2)).sqrt();
    if edges.is_empty() || diag == 0.0 {
        return (100.0, 100.0);
    }
    let out_segments: Vec<[[f64; 2]; 2]> = edges
        .iter()
        .map(|&[a, b]| [points[a as usize], points[b as usize]])
        .collect();
    let (olo, ohi) = bbox(out_segments.iter().flatten().copied());
    let all_lo = [lo[0].min(olo[0]), lo[1].min(olo[1])];
    let all_hi = [hi[0].max(ohi[0]), hi[1].max(ohi[1])];
    let truth = SegmentGrid::new(truth_segments, all_lo, all_hi);
    let output = SegmentGrid::new(out_segments.clone(), all_lo, all_hi);
    let step = diag / 1000.0;
    let (mut forward_max, mut sum2, mut count) = (0.0f64, 0.0, 0usize);
    for [a, b] in &out_segments {
        let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
        let pieces = ((len / step).ceil() as usize).clamp(1, 1000);
        for k in 0..=pieces {
            let t = k as f64 / pieces as f64;
            let p = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
            let d = truth.distance(p);
            forward_max = forward_max.max(d);
            sum2 += d * d;
            count += 1;
        }
    }
    let backward_max = curves
        .iter()
        .flat_map(|c| c.points.iter())
        .map(|&p| output.distance(p))
        .fold(0.0f64, f64::max);
    let hausdorff = forward_max.max(backward_max);
    let rms = (sum2 / count.max(1) as f64).sqrt();
    (100.0 * hausdorff / diag, 100.0 * rms / diag)
}

// ---------------------------------------------------------------------------------------
// Synthetic inputs.

fn smooth_shapes() -> Vec<(&'static str, DenseCurve)> {
    vec![
        ("ellipse", Ellipse { a: 2.0, b: 1.0 }.dense(DENSE)),
        ("star5", Star { a: 0.25, k: 5 }.dense(DENSE)),
        ("star3", Star { a: 0.3, k: 3 }.dense(DENSE)),
        ("peanut", Peanut { a: 0.3, b: 0.15 }.dense(DENSE)),
        (
            "superellipse",
            Superellipse {
                a: 1.5,
                b: 1.0,
                p: 4.0,
            }
            .dense(DENSE),
        ),
    ]
}

/// `trials` randomized ε-samples of each curve set (lfs floor as a fraction of the bounding
/// box diagonal, for sharp corners), transformed by `spoil`.
fn sampled_cases(
    sets: &[CurveSet],
    eps: f64,
    floor_fraction: f64,
    trials: usize,
    seed: u64,
    spoil: &dyn Fn(Sample, &mut Rng) -> Sample,
) -> Vec<Case> {
    let mut rng = Rng::new(seed);
    let mut cases = Vec::new();
    for set in sets {
        let (lo, hi) = bbox(set.curves.iter().flat_map(|c| c.points.iter().copied()));
        let diag = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2)).sqrt();
        let config = SampleConfig {
            eps,
            min_step_fraction: 0.5,
            lfs_floor: floor_fraction * diag,
        };
        for _ in 0..trials {
            let sample = set.eps_sample_with(&config, &mut rng);
            let similarity = Similarity::random(&mut rng);
            let moved = sample.transformed(&similarity).shuffled(&mut rng);
            let spoiled = spoil(moved, &mut rng);
            let curves = set
                .curves
                .iter()
                .map(|c| c.transformed(&similarity))
                .collect();
            cases.push(Case::from_sample(&spoiled, curves));
        }
    }
    cases
}

fn keep(sample: Sample, _: &mut Rng) -> Sample {
    sample
}

fn translated(curve: &DenseCurve, offset: [f64; 2], scale: f64) -> DenseCurve {
    curve.transformed(&Similarity::scaling(scale).then(&Similarity::translation(offset)))
}

fn polygons() -> Vec<(&'static str, Vec<[f64; 2]>)> {
    let star: Vec<[f64; 2]> = (0..10)
        .map(|i| {
            let r = if i % 2 == 0 { 1.0 } else { 0.45 };
            let t = i as f64 * std::f64::consts::PI / 5.0 + std::f64::consts::FRAC_PI_2;
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    let mut comb = vec![[0.0, 0.0], [4.0, 0.0]];
    for k in (0..4).rev() {
        let x = k as f64;
        comb.extend([[x + 1.0, 2.0], [x + 0.5, 1.0]]);
    }
    comb.push([0.0, 2.0]);
    vec![
        ("triangle", vec![[0.0, 0.0], [3.0, 0.0], [1.0, 2.0]]),
        (
            "square",
            vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
        ),
        (
            "L-shape",
            vec![
                [0.0, 0.0],
                [3.0, 0.0],
                [3.0, 1.0],
                [1.0, 1.0],
                [1.0, 3.0],
                [0.0, 3.0],
            ],
        ),
        ("star polygon", star),
        ("comb", comb),
    ]
}

// ---------------------------------------------------------------------------------------
// Real data.

/// Stops the run with a message: the real data is required, never skipped.
fn data_error(path: &Path, error: impl std::fmt::Display) -> ! {
    eprintln!(
        "error: real data {}: {error}\n(pass the data directory as the first argument or in \
         WDM_CRUST_DATA; default {DEFAULT_DATA})",
        path.display()
    );
    std::process::exit(2)
}

fn read_points(path: &Path) -> Vec<[f64; 2]> {
    wdm_crust::io::read_points_from_path(path).unwrap_or_else(|e| data_error(path, e))
}

/// Ground truth from the file order: components split where the step to the next point
/// exceeds `jump` times the median step (`None`: one component); a component is closed when
/// its last point is within `jump` median steps of its first (always, for one component).
fn ordered_case(points: Vec<[f64; 2]>, jump: Option<f64>) -> Case {
    let n = points.len();
    let step = |i: usize, j: usize| {
        let (a, b) = (points[i], points[j]);
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
    };
    let mut steps: Vec<f64> = (1..n).map(|i| step(i - 1, i)).collect();
    steps.sort_by(f64::total_cmp);
    let median = steps.get(steps.len() / 2).copied().unwrap_or(0.0);
    let mut components: Vec<(usize, usize)> = Vec::new();
    let mut first = 0;
    for i in 1..=n {
        let split = i == n || jump.is_some_and(|j| step(i - 1, i) > j * median);
        if split {
            components.push((first, i));
            first = i;
        }
    }
    let mut truth = HashSet::new();
    let mut add = |a: usize, b: usize| {
        if a != b && points[a] != points[b] {
            truth.insert((a.min(b) as u32, a.max(b) as u32));
        }
    };
    for &(s, e) in &components {
        for i in s + 1..e {
            add(i - 1, i);
        }
        let closed = match jump {
            None => true,
            Some(j) => e - s >= 3 && step(e - 1, s) <= j * median,
        };
        if closed && e - s >= 3 {
            add(e - 1, s);
        }
    }
    Case {
        points,
        truth,
        curves: Vec::new(),
    }
}

fn data(path: &str) -> PathBuf {
    DATA.get().expect("set in main").join(path)
}

/// Structure of a reconstruction without ground truth.
fn structure_line(name: &str, points: &[[f64; 2]]) -> String {
    let mut line = format!("| {name} | {} |", points.len());
    for algorithm in ALGORITHMS {
        let options = Options::new().with_algorithm(algorithm);
        let start = Instant::now();
        match reconstruct_with(points, &options) {
            Ok(rec) => {
                let seconds = start.elapsed().as_secs_f64();
                let closed = rec.curves().iter().filter(|c| c.closed).count();
                let open = rec.curves().len() - closed;
                line += &format!(
                    " {} | {closed} / {open} | {} | {:.0} |",
                    rec.edges().len(),
                    rec.irregular_points().len(),
                    seconds * 1e3
                );
            }
            Err(e) => line += &format!(" error: {e} | | | |"),
        }
    }
    line
}

// ---------------------------------------------------------------------------------------

fn main() {
    let started = Instant::now();
    let data_dir = std::env::args_os()
        .nth(1)
        .or_else(|| std::env::var_os("WDM_CRUST_DATA"))
        .map_or_else(|| PathBuf::from(DEFAULT_DATA), PathBuf::from);
    if !data_dir.is_dir() {
        data_error(&data_dir, "not a directory");
    }
    DATA.set(data_dir).expect("set once");
    println!("# Reconstruction quality: WDM_CRUST vs crust vs NN-crust\n");
    println!(
        "`cargo run --release --example quality`. R = recall, P = precision (edges, % pooled \
         over the trials of a row), exact = share of trials whose output equals the ground \
         truth. Distances in % of the truth's bounding-box diagonal (Hausdorff symmetric, RMS \
         from the output edges to the true curve), averaged over trials. n = mean points."
    );

    let methods = algorithms();
    // Inputs rerun with the WDM variants at the end.
    let mut variant_inputs: Vec<(String, Vec<Case>)> = Vec::new();
    // Inputs judged by the survey's measures at the end.
    let mut survey_inputs: Vec<(String, Vec<Case>)> = Vec::new();

    // Smooth curves at several ε.
    let shapes = smooth_shapes();
    let sets: Vec<CurveSet> = shapes
        .iter()
        .map(|(_, c)| CurveSet::new(vec![c.clone()]))
        .collect();
    let mut rows = Vec::new();
    for (i, &eps) in [0.2, 0.39, 0.5, 0.8, 1.2].iter().enumerate() {
        let cases = sampled_cases(&sets, eps, 0.0, 8, 100 + i as u64, &keep);
        rows.push(run_row(
            &format!("smooth, ε = {eps}"),
            &cases,
            &methods,
            false,
        ));
        if eps > 0.5 {
            survey_inputs.push((format!("sparse: smooth, ε = {eps}"), cases.clone()));
        }
        if eps > 1.0 {
            variant_inputs.push((format!("smooth, ε = {eps}"), cases));
        }
    }
    print_table(
        "Smooth closed curves (ellipse, 2 stars, peanut, superellipse; 8 trials each)",
        &rows,
        &methods,
        false,
    );

    // Sharp corners.
    let mut rows = Vec::new();
    let mut corner_cases = Vec::new();
    for (i, (name, vertices)) in polygons().into_iter().enumerate() {
        let set = CurveSet::new(vec![DenseCurve::polygon(&vertices, DENSE)]);
        for (j, &eps) in [0.3, 0.6].iter().enumerate() {
            let cases = sampled_cases(
                std::slice::from_ref(&set),
                eps,
                0.02,
                10,
                200 + 10 * i as u64 + j as u64,
                &keep,
            );
            rows.push(run_row(
                &format!("{name}, ε = {eps}"),
                &cases,
                &methods,
                false,
            ));
            if eps > 0.5 {
                corner_cases.extend(cases);
            }
        }
    }
    print_table(
        "Polygons with sharp corners (lfs floor 2 % of the diagonal; 10 trials each)",
        &rows,
        &methods,
        false,
    );
    survey_inputs.push(("sharp: polygons, ε = 0.6".to_string(), corner_cases.clone()));
    variant_inputs.push(("polygons, ε = 0.6".to_string(), corner_cases));

    // Several disjoint curves, and nested curves.
    let ellipse = Ellipse { a: 2.0, b: 1.0 }.dense(DENSE);
    let star = Star { a: 0.25, k: 5 }.dense(DENSE);
    let peanut = Peanut { a: 0.3, b: 0.15 }.dense(DENSE);
    let circle = Ellipse::circle(1.0).dense(DENSE);
    let square = DenseCurve::polygon(&[[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]], DENSE);
    let multi = [
        (
            "2 curves",
            vec![ellipse.clone(), translated(&star, [4.5, 0.0], 1.0)],
        ),
        (
            "3 curves",
            vec![
                ellipse.clone(),
                translated(&star, [4.5, 0.0], 1.0),
                translated(&peanut, [1.0, 3.0], 1.0),
            ],
        ),
        (
            "4 curves, close",
            vec![
                circle.clone(),
                translated(&circle, [2.3, 0.0], 1.0),
                translated(&star, [0.0, 2.4], 1.0),
                translated(&peanut, [2.9, 2.5], 1.0),
            ],
        ),
    ];
    let nested = [
        (
            "1 hole",
            vec![ellipse.clone(), translated(&circle, [0.0, 0.0], 0.5)],
        ),
        (
            "2 holes",
            vec![
                translated(&ellipse, [0.0, 0.0], 1.5),
                translated(&circle, [-1.3, 0.0], 0.6),
                translated(&star, [1.3, 0.0], 0.6),
            ],
        ),
        (
            "3 levels",
            vec![
                translated(&circle, [0.0, 0.0], 3.0),
                translated(&peanut, [0.0, 0.0], 1.8),
                translated(&circle, [0.0, 0.0], 0.6),
            ],
        ),
        (
            "square in circle",
            vec![translated(&circle, [0.0, 0.0], 2.0), square.clone()],
        ),
    ];
    let mut rows = Vec::new();
    for (i, (name, curves)) in multi.iter().chain(nested.iter()).enumerate() {
        let set = CurveSet::new(curves.clone());
        // Only the square has corners (lfs → 0); the smooth sets are true ε-samples.
        let floor = if name.contains("square") { 0.02 } else { 0.0 };
        let cases = sampled_cases(&[set], 0.3, floor, 10, 300 + i as u64, &keep);
        rows.push(run_row(name, &cases, &methods, false));
        if i >= multi.len() || name.contains("close") {
            variant_inputs.push((name.to_string(), cases));
        }
    }
    print_table(
        "Several curves (first 3 rows; the 4 curves are 0.3–0.5 apart at radius 1) and nested \
         curves (last 4), ε = 0.3 (lfs floor 2 % for the square), 10 trials each",
        &rows,
        &methods,
        false,
    );

    // Outliers.
    let mut rows = Vec::new();
    for (i, &pct) in [10.0, 20.0, 40.0, 70.0].iter().enumerate() {
        let spoil = move |s: Sample, rng: &mut Rng| s.with_outliers(pct, rng);
        let cases = sampled_cases(&sets, 0.3, 0.0, 6, 400 + i as u64, &spoil);
        survey_inputs.push((format!("{pct} % outliers"), cases.clone()));
        rows.push(run_row(
            &format!("{pct} % outliers"),
            &cases,
            &methods,
            false,
        ));
        if pct == 20.0 {
            variant_inputs.push((format!("{pct} % outliers"), cases));
        }
    }
    print_table(
        "Smooth curves, ε = 0.3, with uniform outliers in the bounding box (edges to outliers \
         are false positives; 5 shapes × 6 trials)",
        &rows,
        &methods,
        false,
    );

    // Noise.
    let mut rows = Vec::new();
    for (i, &fraction) in [0.0, 0.02, 0.05, 0.1].iter().enumerate() {
        let spoil = move |s: Sample, rng: &mut Rng| s.with_lfs_noise(fraction, rng);
        let cases = sampled_cases(&sets, 0.3, 0.0, 6, 500 + i as u64, &spoil);
        rows.push(run_row(
            &format!("σ = {fraction} lfs"),
            &cases,
            &methods,
            true,
        ));
        if fraction == 0.1 {
            variant_inputs.push((format!("noise σ = {fraction} lfs"), cases));
        }
    }
    print_table(
        "Smooth curves, ε = 0.3, Gaussian noise σ proportional to lfs (5 shapes × 6 trials)",
        &rows,
        &methods,
        true,
    );

    // SVG drawings.
    let mut rows = Vec::new();
    let groups: [(&str, &[&str]); 3] = [
        ("closed drawings", &["simple", "blob2", "complex", "spiral"]),
        (
            "multi-curve f1–f7",
            &["f1", "f2", "f3", "f4", "f5", "f6", "f7"],
        ),
        (
            "animal line drawings",
            &[
                "Croco", "Deery", "Fishi", "Frog2", "Goldi", "Porpi", "Snail", "Spidy",
            ],
        ),
    ];
    for (g, (name, files)) in groups.iter().enumerate() {
        let mut sets = Vec::new();
        for file in *files {
            let path = data(&format!("sampling2d/data/{file}.svg"));
            let svg = std::fs::read_to_string(&path).unwrap_or_else(|e| data_error(&path, e));
            let curves = wdm_crust_testkit::svg_dense_curves(&svg, 8000)
                .unwrap_or_else(|e| data_error(&path, e));
            if curves.is_empty() {
                data_error(&path, "no curves");
            }
            sets.push(CurveSet::new(curves));
        }
        let cases = sampled_cases(&sets, 0.3, 0.005, 2, 600 + g as u64, &keep);
        let label = format!("{name} ({} files)", sets.len());
        rows.push(run_row(&label, &cases, &methods, false));
        variant_inputs.push((format!("SVG {name}"), cases));
    }
    print_table(
        "ε-samples (ε = 0.3, lfs floor 0.5 % of the diagonal) of the sampling2d SVG drawings, \
         2 samples per file",
        &rows,
        &methods,
        false,
    );

    // Real data with ground-truth order.
    let mut rows = Vec::new();
    let ordered = [
        ("hnn-crust-sgp16/mushroom.p2d", None),
        ("fitconnect/data/apple_2percent_noise.txt", None),
        ("fitconnect/data/butterfly_2percent_noise.txt", None),
        ("fitconnect/data/crab_2percent_noise.txt", None),
        ("fitconnect/data/dolphin_2percent_noise.txt", None),
        ("stretchdenoise/data/Circle0.txt", None),
        ("stretchdenoise/data/drill.txt", None),
        ("stretchdenoise/data/thing.txt", None),
        ("hnn-crust-sgp16/crocodile-conf.p2d", Some(5.0)),
        ("stretchdenoise/data/vase.txt", Some(20.0)),
        ("stretchdenoise/data/vase_xyz.txt", Some(20.0)),
        ("stretchdenoise/data/drill_xyz.txt", Some(20.0)),
        ("stretchdenoise/data/drillcase_xyz.txt", Some(20.0)),
    ];
    let (mut real_closed, mut real_components) = (Vec::new(), Vec::new());
    for (file, jump) in ordered {
        let points = read_points(&data(file));
        let case = ordered_case(points, jump);
        if jump.is_none() {
            real_closed.push(case.clone());
        } else {
            real_components.push(case.clone());
        }
        let name = file.rsplit('/').next().unwrap_or(file);
        let label = match jump {
            None => name.to_string(),
            Some(j) => format!("{name} (components, break > {j}× median step)"),
        };
        rows.push(run_row(&label, &[case], &methods, false));
    }
    print_table(
        "Real point sets with ground-truth order (tests/data; closed curves in file \
         order, multi-component files split at jumps; ventilator.p2d skipped: its order \
         interleaves components)",
        &rows,
        &methods,
        false,
    );

    variant_inputs.push(("real, one closed curve (8 files)".to_string(), real_closed));
    variant_inputs.push(("real, components (5 files)".to_string(), real_components));

    // The survey's measures (Ohrhallinger et al., CGF 2021): noise in sample spacings on
    // evenly spaced closed curves, single and with a hole, then the sets collected above.
    let mut rows = Vec::new();
    let single = [
        Peanut { a: 0.3, b: 0.15 }.dense(150),
        Star { a: 0.25, k: 5 }.dense(200),
    ];
    let annulus = vec![
        Ellipse { a: 1.5, b: 1.0 }.dense(200),
        Ellipse::circle(0.4)
            .dense(64)
            .transformed(&Similarity::translation([0.3, 0.0])),
    ];
    for (i, &noise) in [0.1, 0.3, 0.5, 1.0].iter().enumerate() {
        let mut rng = Rng::new(900 + i as u64);
        let cases: Vec<Case> = (0..10)
            .flat_map(|_| single.iter().map(|c| vec![c.clone()]).collect::<Vec<_>>())
            .map(|curves| spaced_case(curves, noise, &mut rng))
            .collect();
        rows.push(survey_row(
            &format!("noise {noise} × spacing, one curve"),
            &cases,
            &methods,
        ));
        let cases: Vec<Case> = (0..10)
            .map(|_| spaced_case(annulus.clone(), noise, &mut rng))
            .collect();
        rows.push(survey_row(
            &format!("noise {noise} × spacing, with a hole"),
            &cases,
            &methods,
        ));
    }
    for (label, cases) in &survey_inputs {
        rows.push(survey_row(label, cases, &methods));
    }
    print_survey_table(&rows, &methods);

    open_curves_table(&methods);

    // WDM variants.
    let variants = wdm_variants();
    let rows: Vec<Row> = variant_inputs
        .iter()
        .map(|(label, cases)| run_row(label, cases, &variants, false))
        .collect();
    print_table(
        "WDM_CRUST variants on inputs from the tables above: peeling on (default) and off (the \
         paper's single pass), and the three readings of the labels (ARCHITECTURE.md, water flow \
         step 6)",
        &rows,
        &variants,
        false,
    );

    // Real data without ground truth: structure and time.
    println!("\n### Real point sets without ground-truth order: structure of the output\n");
    let mut header = String::from("| file | n |");
    let mut rule = String::from("|---|---:|");
    for a in ALGORITHMS {
        let name = a.name();
        header += &format!(" {name} edges | {name} closed / open | {name} irregular | {name} ms |");
        rule += "---:|---:|---:|---:|";
    }
    println!("{header}\n{rule}");
    for file in [
        "fitconnect/data/fish.txt",
        "fitconnect/data/bot.txt",
        "fitconnect/data/Cup0.txt",
        "fitconnect/data/Keyboard0.txt",
        "fitconnect/data/Monitor0.txt",
        "fitconnect/data/Mouse0.txt",
        "stretchdenoise/data/stair.xy",
        "stretchdenoise/data/family.p2d",
        "hnn-crust-sgp16/ventilator.p2d",
    ] {
        let points = read_points(&data(file));
        let name = file.rsplit('/').next().unwrap_or(file);
        println!("{}", structure_line(name, &points));
    }

    // Scale.
    println!("\n### Running time on large inputs (ms)\n");
    println!("| input | n | wdm | crust | nn-crust |\n|---|---:|---:|---:|---:|");
    for &n in &[10_000usize, 100_000] {
        let mut rng = Rng::new(n as u64);
        let points: Vec<[f64; 2]> = (0..n)
            .map(|_| {
                let t = rng.f64() * std::f64::consts::TAU;
                let r = 1.0 + 0.25 * (5.0 * t).cos() + 1e-4 * rng.normal();
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let mut line = format!("| noisy star, random order | {n} |");
        for algorithm in ALGORITHMS {
            let options = Options::new().with_algorithm(algorithm);
            let start = Instant::now();
            let ok = reconstruct_with(&points, &options).is_ok();
            line += &format!(
                " {:.0}{} |",
                start.elapsed().as_secs_f64() * 1e3,
                if ok { "" } else { " (error)" }
            );
        }
        println!("{line}");
    }
    print_warnings_table();
    print_smoothing_tables();
    println!("\nTotal time: {:.1} s", started.elapsed().as_secs_f64());
}

// ---------------------------------------------------------------------------------------
// Warnings: how often the default's warnings speak on right and on wrong results.

/// Per row (in order of first appearance): trials, right, right and warned, wrong and
/// warned, and how often each code spoke.
type WarningRow = (usize, usize, usize, usize, BTreeMap<&'static str, usize>);

static WARNINGS: Mutex<Vec<(String, WarningRow)>> = Mutex::new(Vec::new());

/// Notes the warnings of the default WDM on one trial of row `label` (right or not by the
/// row's own measure: exact edges for the edge tables, the right curve count for the
/// survey and the open-curve tables).
fn record_warnings(label: &str, method: &Method, right: bool, rec: &Reconstruction) {
    if method.name != "wdm" {
        return;
    }
    let mut rows = WARNINGS.lock().unwrap_or_else(|e| e.into_inner());
    let at = match rows.iter().position(|(l, _)| l == label) {
        Some(at) => at,
        None => {
            rows.push((label.to_string(), Default::default()));
            rows.len() - 1
        }
    };
    let row = &mut rows[at].1;
    let warned = !rec.warnings().is_empty();
    row.0 += 1;
    row.1 += usize::from(right);
    row.2 += usize::from(right && warned);
    row.3 += usize::from(!right && warned);
    for w in rec.warnings() {
        *row.4.entry(w.code.name()).or_default() += 1;
    }
}

fn print_warnings_table() {
    println!(
        "\n### Warnings of the default (wdm)\n\nright = trials whose result is right by the row's \
         measure (exact edges, or the right number of curves); warned = trials with at least \
         one warning, among the right and among the wrong ones; codes = trials each code \
         spoke in.\n"
    );
    println!("| row | trials | right | right, warned | wrong | wrong, warned | codes |");
    println!("|---|---:|---:|---:|---:|---:|---|");
    let rows = WARNINGS.lock().unwrap_or_else(|e| e.into_inner());
    let (mut right_total, mut right_warned, mut wrong_total, mut wrong_warned) = (0, 0, 0, 0);
    for (label, (trials, right, rw, ww, codes)) in rows.iter() {
        let codes: Vec<String> = codes.iter().map(|(c, n)| format!("{c} {n}")).collect();
        println!(
            "| {label} | {trials} | {right} | {rw} | {} | {ww} | {} |",
            trials - right,
            codes.join(", ")
        );
        right_total += right;
        right_warned += rw;
        wrong_total += trials - right;
        wrong_warned += ww;
    }
    println!(
        "| **all** | {} | {right_total} | {right_warned} | {wrong_total} | {wrong_warned} | |",
        right_total + wrong_total
    );
}

// ---------------------------------------------------------------------------------------
// The survey's measures: is the output a valid set of curves, and how close to the truth.

/// Sums of the survey's measures over the trials of one row, for one method.
#[derive(Default, Clone)]
struct SurveyTally {
    trials: usize,
    /// Trials whose output is one closed curve per true closed curve and nothing else.
    right: usize,
    closed: usize,
    true_closed: usize,
    /// Open chains plus closed curves beyond the true count.
    junk: usize,
    /// Curve samples (not outliers) on an output curve, and all curve samples.
    on_curves: usize,
    samples: usize,
    hausdorff: f64,
}

struct SurveyRow {
    label: String,
    points: usize,
    tallies: Vec<SurveyTally>,
}

/// Evenly spaced samples of `curves` (in curve order, for the truth) with Gaussian noise of
/// `noise` × the mean sample spacing on each coordinate.
fn spaced_case(curves: Vec<DenseCurve>, noise: f64, rng: &mut Rng) -> Case {
    let n: usize = curves.iter().map(|c| c.points.len()).sum();
    let spacing = curves.iter().map(|c| c.length()).sum::<f64>() / n as f64;
    let mut points = Vec::with_capacity(n);
    let mut truth = HashSet::new();
    for c in &curves {
        let first = points.len() as u32;
        let k = c.points.len() as u32;
        for (i, p) in c.points.iter().enumerate() {
            points.push([
                p[0] + noise * spacing * rng.normal(),
                p[1] + noise * spacing * rng.normal(),
            ]);
            let (a, b) = (first + i as u32, first + (i as u32 + 1) % k);
            truth.insert((a.min(b), a.max(b)));
        }
    }
    Case {
        points,
        truth,
        curves,
    }
}

fn survey_row(label: &str, cases: &[Case], methods: &[Method]) -> SurveyRow {
    let mut tallies = vec![SurveyTally::default(); methods.len()];
    for case in cases {
        let true_closed = case.curves.iter().filter(|c| c.closed).count();
        let samples: HashSet<u32> = case.truth.iter().flat_map(|&(a, b)| [a, b]).collect();
        for (tally, method) in tallies.iter_mut().zip(methods) {
            let Ok(rec) = reconstruct_with(&case.points, &method.options) else {
                continue;
            };
            let closed = rec.curves().iter().filter(|c| c.closed).count();
            let open = rec.curves().len() - closed;
            tally.trials += 1;
            tally.closed += closed;
            tally.true_closed += true_closed;
            tally.junk += open + closed.saturating_sub(true_closed);
            tally.right += usize::from(open == 0 && closed == true_closed);
            record_warnings(label, method, open == 0 && closed == true_closed, &rec);
            let touched: HashSet<u32> = rec.edges().iter().flatten().copied().collect();
            tally.on_curves += samples.intersection(&touched).count();
            tally.samples += samples.len();
            tally.hausdorff += curve_distances(&case.points, rec.edges(), &case.curves).0;
        }
    }
    let points = cases.iter().map(|c| c.points.len()).sum::<usize>() / cases.len().max(1);
    SurveyRow {
        label: label.to_string(),
        points,
        tallies,
    }
}

fn print_survey_table(rows: &[SurveyRow], methods: &[Method]) {
    println!(
        "\n### The survey's measures (Ohrhallinger et al., CGF 2021)\n\nright = share of trials \
         whose output is exactly one closed curve per true curve (no open chains, no extra \
         loops); closed = mean closed curves (true count in brackets); junk = mean open chains \
         plus loops beyond the true count; on = share of the curve samples (outliers not \
         counted) on an output curve; H = symmetric Hausdorff distance to the true curves in % \
         of their bounding-box diagonal, mean over trials. Noise rows: evenly spaced samples \
         (peanut 150, star 200; ellipse 200 with a circular hole of 64), Gaussian noise of the \
         given multiple of the sample spacing, 10 trials per shape.\n"
    );
    let mut header = String::from("| input | trials | n |");
    let mut rule = String::from("|---|---:|---:|");
    for method in methods {
        let name = method.name;
        header += &format!(" {name} right | {name} closed | {name} junk | {name} on | {name} H |");
        rule += "---:|---:|---:|---:|---:|";
    }
    println!("{header}\n{rule}");
    for row in rows {
        let trials = row.tallies.first().map_or(0, |t| t.trials);
        let mut line = format!("| {} | {} | {} |", row.label, trials, row.points);
        for t in &row.tallies {
            let per = |x: usize| x as f64 / t.trials.max(1) as f64;
            line += &format!(
                " {:.0} % | {:.2} ({:.0}) | {:.2} | {:.1} % | {:.2} |",
                percent(t.right, t.trials),
                per(t.closed),
                per(t.true_closed),
                per(t.junk),
                percent(t.on_curves, t.samples),
                t.hausdorff / t.trials.max(1) as f64
            );
        }
        println!("{line}");
    }
}

// ---------------------------------------------------------------------------------------
// Open curves, alone and beside closed ones.

/// The pieces' points (each piece's `points` are its samples, in order) with Gaussian noise
/// of `noise` × the piece's mean step on each coordinate, shuffled; the truth joins each
/// piece's consecutive samples (and the last to the first of a closed one).
fn open_case(pieces: Vec<DenseCurve>, noise: f64, rng: &mut Rng) -> Case {
    let total: usize = pieces.iter().map(|c| c.points.len()).sum();
    let order = rng.permutation(total);
    let mut points = vec![[0.0; 2]; total];
    let mut truth = HashSet::new();
    let mut base = 0;
    for c in &pieces {
        let k = c.points.len();
        let steps = if c.closed { k } else { k - 1 };
        let spacing = c.length() / steps as f64;
        for (i, p) in c.points.iter().enumerate() {
            points[order[base + i]] = [
                p[0] + noise * spacing * rng.normal(),
                p[1] + noise * spacing * rng.normal(),
            ];
        }
        for i in 0..steps {
            let (a, b) = (order[base + i] as u32, order[base + (i + 1) % k] as u32);
            truth.insert((a.min(b), a.max(b)));
        }
        base += k;
    }
    Case {
        points,
        truth,
        curves: pieces,
    }
}

/// `n` samples of the arc of radius `r` about `centre` from `a0` to `a1`, with cos/sin.
fn arc_curve(centre: [f64; 2], r: f64, a0: f64, a1: f64, n: usize) -> DenseCurve {
    let points: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = a0 + (a1 - a0) * i as f64 / (n - 1) as f64;
            [centre[0] + r * t.cos(), centre[1] + r * t.sin()]
        })
        .collect();
    DenseCurve::from_points(&points, false, &[])
}

/// About `n` samples evenly spaced in arc length along `f` on [0, 1].
fn parametric_curve(f: impl Fn(f64) -> [f64; 2], n: usize) -> DenseCurve {
    let dense: Vec<[f64; 2]> = (0..DENSE)
        .map(|i| f(i as f64 / (DENSE - 1) as f64))
        .collect();
    let dense = DenseCurve::from_points(&dense, false, &[]);
    let step = dense.length() / (n - 1) as f64;
    let mut samples = vec![dense.points[0]];
    let mut walked = 0.0;
    for w in dense.points.windows(2) {
        walked += ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt();
        if walked >= step * samples.len() as f64 {
            samples.push(w[1]);
        }
    }
    if samples.last() != dense.points.last() {
        samples.push(*dense.points.last().unwrap_or(&[0.0; 2]));
    }
    DenseCurve::from_points(&samples, false, &[])
}

/// One trial's pieces of an open-curve family.
type Pieces = Box<dyn Fn(&mut Rng) -> Vec<DenseCurve>>;

/// The open-curve families: (label, generator of one trial's pieces).
fn open_families() -> Vec<(&'static str, Pieces)> {
    use std::f64::consts::{PI, TAU};
    vec![
        (
            "arcs of 20–340° (cos/sin)",
            Box::new(|rng: &mut Rng| {
                let degrees: f64 = rng.range(20.0, 340.0);
                let n = 20 + rng.below(200);
                let (centre, r, a0) = (
                    [rng.f64(), rng.f64()],
                    rng.range(0.5, 3.0),
                    rng.range(0.0, TAU),
                );
                vec![arc_curve(centre, r, a0, a0 + degrees.to_radians(), n)]
            }),
        ),
        (
            "spirals",
            Box::new(|rng: &mut Rng| {
                let (turns, inner) = (rng.range(1.0, 3.0), rng.range(0.1, 0.5));
                let n = 150 + rng.below(250);
                vec![parametric_curve(
                    |t| {
                        let (a, r) = (TAU * turns * t, inner + t);
                        [r * a.cos(), r * a.sin()]
                    },
                    n,
                )]
            }),
        ),
        (
            "S-curves and waves",
            Box::new(|rng: &mut Rng| {
                let (waves, height) = (rng.range(0.5, 3.0), rng.range(0.2, 1.0));
                let n = 100 + rng.below(200);
                vec![parametric_curve(
                    |t| [4.0 * t, height * (TAU * waves * t).sin()],
                    n,
                )]
            }),
        ),
        (
            "polylines, corners ≥ 60°",
            Box::new(|rng: &mut Rng| {
                // A random walk whose every turn is at most 120°.
                let mut vertices = vec![[0.0, 0.0]];
                let mut heading = rng.range(0.0, TAU);
                for _ in 0..2 + rng.below(5) {
                    let last = vertices[vertices.len() - 1];
                    let length = rng.range(0.5, 1.5);
                    vertices.push([
                        last[0] + length * heading.cos(),
                        last[1] + length * heading.sin(),
                    ]);
                    heading += rng.range(-2.0 * PI / 3.0, 2.0 * PI / 3.0);
                }
                vec![DenseCurve::polyline(&vertices, false, 60 + rng.below(150))]
            }),
        ),
        (
            "open strokes beside a closed loop",
            Box::new(|rng: &mut Rng| {
                let n = 60 + rng.below(100);
                let loop_ = Ellipse {
                    a: 1.0,
                    b: rng.range(0.5, 1.0),
                }
                .dense(n);
                let mut pieces = vec![DenseCurve::from_points(&loop_.points, true, &[])];
                for k in 0..1 + rng.below(3) {
                    let a0 = rng.range(0.0, TAU);
                    let r = 1.6 + 0.5 * k as f64;
                    pieces.push(arc_curve(
                        [0.0, 0.0],
                        r,
                        a0,
                        a0 + rng.range(0.5, 2.5),
                        20 + rng.below(60),
                    ));
                }
                pieces
            }),
        ),
        (
            "ε-samples of open curves, ε = 0.1",
            Box::new(|rng: &mut Rng| {
                let curve = if rng.chance(0.5) {
                    arc_curve([0.0, 0.0], 1.0, 0.0, rng.range(1.0, 5.0), DENSE)
                } else {
                    DenseCurve::polyline(&[[0.0, 0.0], [3.0, 0.5], [3.5, 2.0]], false, DENSE)
                };
                let sample = CurveSet::new(vec![curve]).eps_sample(0.1, rng);
                vec![DenseCurve::from_points(&sample.points, false, &[])]
            }),
        ),
    ]
}

/// Per method: exact edge sets, right counts of loops and chains, junk pieces, the largest
/// degree of any point, and the Hausdorff distance.
fn open_curves_table(methods: &[Method]) {
    println!(
        "\n### Open and mixed curves\n\nexact = share of trials whose edges are exactly the \
         truth; right = share whose loops and chains are as many as the true closed and open \
         curves; junk = mean pieces beyond the true count; deg = the largest number of edges \
         at any point over all trials (2 for curves); H = symmetric Hausdorff distance in % of \
         the bounding-box diagonal, mean over trials. 20 trials a row; noise is Gaussian of \
         the given multiple of the mean step on each coordinate.\n"
    );
    let mut header = String::from("| input | noise | n |");
    let mut rule = String::from("|---|---:|---:|");
    for method in methods {
        let name = method.name;
        header += &format!(" {name} exact | {name} right | {name} junk | {name} deg | {name} H |");
        rule += "---:|---:|---:|---:|---:|";
    }
    println!("{header}\n{rule}");
    for (f, (label, family)) in open_families().into_iter().enumerate() {
        for (j, &noise) in [0.0, 0.3].iter().enumerate() {
            let mut rng = Rng::new(1300 + 10 * f as u64 + j as u64);
            let cases: Vec<Case> = (0..20)
                .map(|_| {
                    let pieces = family(&mut rng);
                    open_case(pieces, noise, &mut rng)
                })
                .collect();
            let n = cases.iter().map(|c| c.points.len()).sum::<usize>() / cases.len();
            let mut line = format!("| {label} | {noise} | {n} |");
            for method in methods {
                let (mut exact, mut right, mut junk, mut degree, mut h) = (0, 0, 0, 0, 0.0);
                for case in &cases {
                    let Ok(rec) = reconstruct_with(&case.points, &method.options) else {
                        continue;
                    };
                    let output: HashSet<(u32, u32)> =
                        rec.edges().iter().map(|&[a, b]| (a, b)).collect();
                    exact += usize::from(output == case.truth);
                    let closed = rec.curves().iter().filter(|c| c.closed).count();
                    let open = rec.curves().len() - closed;
                    let true_closed = case.curves.iter().filter(|c| c.closed).count();
                    let true_open = case.curves.len() - true_closed;
                    right += usize::from(closed == true_closed && open == true_open);
                    record_warnings(
                        &format!("{label}, noise {noise}"),
                        method,
                        closed == true_closed && open == true_open,
                        &rec,
                    );
                    junk += (closed + open).saturating_sub(case.curves.len());
                    let mut at = vec![0usize; case.points.len()];
                    for &[a, b] in rec.edges() {
                        at[a as usize] += 1;
                        at[b as usize] += 1;
                    }
                    degree = degree.max(at.into_iter().max().unwrap_or(0));
                    h += curve_distances(&case.points, rec.edges(), &case.curves).0;
                }
                let trials = cases.len();
                line += &format!(
                    " {:.0} % | {:.0} % | {:.2} | {degree} | {:.2} |",
                    percent(exact, trials),
                    percent(right, trials),
                    junk as f64 / trials as f64,
                    h / trials as f64
                );
            }
            println!("{line}");
        }
    }
}

// ---------------------------------------------------------------------------------------
// Smoothing: dense noisy bands, clean samples, corners.

/// A smooth blob: `r(θ) = 1 + Σ a_k cos(kθ + φ_k)` over a few low harmonics.
struct Blob;

impl Blob {
    const TERMS: [(f64, f64, f64); 3] = [(2.0, 0.18, 0.3), (3.0, 0.1, 1.1), (5.0, 0.05, 2.0)];

    /// `r` and `dr/dθ`.
    fn radius(theta: f64) -> (f64, f64) {
        let (mut r, mut dr) = (1.0, 0.0);
        for (k, a, phi) in Self::TERMS {
            r += a * (k * theta + phi).cos();
            dr -= a * k * (k * theta + phi).sin();
        }
        (r, dr)
    }
}

impl ClosedCurve for Blob {
    fn point(&self, t: f64) -> [f64; 2] {
        let theta = std::f64::consts::TAU * t;
        let (r, _) = Self::radius(theta);
        [r * theta.cos(), r * theta.sin()]
    }

    fn derivative(&self, t: f64) -> [f64; 2] {
        let theta = std::f64::consts::TAU * t;
        let (r, dr) = Self::radius(theta);
        let (s, c) = theta.sin_cos();
        let tau = std::f64::consts::TAU;
        [tau * (dr * c - r * s), tau * (dr * s + r * c)]
    }
}

/// `n` points per curve at uniformly random arc-length positions, Gaussian noise of `sigma`
/// % of the truth's diagonal on each coordinate, shuffled; with the input's own noise RMS
/// (every point's distance to the true curves) in % of the diagonal.
fn dense_band(curves: &[DenseCurve], n: usize, sigma: f64, rng: &mut Rng) -> (Vec<[f64; 2]>, f64) {
    let (lo, hi) = bbox(curves.iter().flat_map(|c| c.points.iter().copied()));
    let diag = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2)).sqrt();
    let s = sigma / 100.0 * diag;
    let mut points = Vec::new();
    let mut truth = Vec::new();
    for c in curves {
        let k = c.points.len();
        let mut cumulative = vec![0.0];
        for i in 0..k {
            let (a, b) = (c.points[i], c.points[(i + 1) % k]);
            truth.push([a, b]);
            cumulative.push(cumulative[i] + ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt());
        }
        let total = cumulative[k];
        for _ in 0..n {
            let target = rng.f64() * total;
            let i = cumulative.partition_point(|&x| x <= target).clamp(1, k);
            let (a, b) = (c.points[i - 1], c.points[i % k]);
            let piece = cumulative[i] - cumulative[i - 1];
            let t = if piece > 0.0 {
                (target - cumulative[i - 1]) / piece
            } else {
                0.0
            };
            points.push([
                a[0] + t * (b[0] - a[0]) + s * rng.normal(),
                a[1] + t * (b[1] - a[1]) + s * rng.normal(),
            ]);
        }
    }
    rng.shuffle(&mut points);
    let (plo, phi) = bbox(points.iter().copied());
    let grid = SegmentGrid::new(
        truth,
        [lo[0].min(plo[0]), lo[1].min(plo[1])],
        [hi[0].max(phi[0]), hi[1].max(phi[1])],
    );
    let sum: f64 = points.iter().map(|&p| grid.distance(p).powi(2)).sum();
    let rms = (sum / points.len() as f64).sqrt();
    (points, 100.0 * rms / diag)
}

/// The curves of `rec` drawn through `vertex(curve, i)` as points and edges for
/// [`curve_distances`].
fn drawn(
    rec: &Reconstruction,
    vertex: &dyn Fn(&wdm_crust::reconstruct::Curve) -> Vec<[f64; 2]>,
) -> (Vec<[f64; 2]>, Vec<[u32; 2]>) {
    let (mut points, mut edges) = (Vec::new(), Vec::new());
    for c in rec.curves() {
        let first = points.len() as u32;
        let coords = vertex(c);
        let k = coords.len() as u32;
        points.extend(coords);
        let count = if c.closed { k } else { k.saturating_sub(1) };
        edges.extend((0..count).map(|i| [first + i, first + (i + 1) % k]));
    }
    (points, edges)
}

/// A FitConnect-style projection (our reading of its fit-and-project step, not the authors'
/// code): the vertex onto Taubin's algebraic circle fit of its `k` nearest input points,
/// `k` grown by half from 8 while the fit's RMS residual stays within 1.5 times the
/// smallest so far; onto the total-least-squares line where the circle is nearly straight.
fn fitconnect_project(points: &[[f64; 2]], p: [f64; 2]) -> [f64; 2] {
    let mut by_distance: Vec<(f64, [f64; 2])> = points
        .iter()
        .map(|&q| ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2), q))
        .collect();
    let cap = 400.min(by_distance.len());
    if cap < 8 {
        return p;
    }
    by_distance.select_nth_unstable_by(cap - 1, |a, b| a.0.total_cmp(&b.0));
    by_distance.truncate(cap);
    by_distance.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut k, mut best, mut smallest) = (8usize, p, f64::INFINITY);
    while k <= cap {
        let near: Vec<[f64; 2]> = by_distance[..k].iter().map(|x| x.1).collect();
        let Some((projected, rms)) = taubin_project(&near, p) else {
            break;
        };
        if rms > 1.5 * smallest {
            break;
        }
        smallest = smallest.min(rms);
        best = projected;
        k = k * 3 / 2;
    }
    best
}

/// Taubin's circle fit (Chernov's Newton form) of `pts`, `p` projected onto it, with the RMS
/// residual.
fn taubin_project(pts: &[[f64; 2]], p: [f64; 2]) -> Option<([f64; 2], f64)> {
    let n = pts.len() as f64;
    let mx = pts.iter().map(|q| q[0]).sum::<f64>() / n;
    let my = pts.iter().map(|q| q[1]).sum::<f64>() / n;
    let mut m = [0.0f64; 6]; // xx, yy, xy, xz, yz, zz
    for q in pts {
        let (x, y) = (q[0] - mx, q[1] - my);
        let z = x * x + y * y;
        for (acc, v) in m.iter_mut().zip([x * x, y * y, x * y, x * z, y * z, z * z]) {
            *acc += v / n;
        }
    }
    let [mxx, myy, mxy, mxz, myz, mzz] = m;
    let mz = mxx + myy;
    let cov_xy = mxx * myy - mxy * mxy;
    let var_z = mzz - mz * mz;
    let (a3, a2) = (4.0 * mz, -3.0 * mz * mz - mzz);
    let a1 = var_z * mz + 4.0 * cov_xy * mz - mxz * mxz - myz * myz;
    let a0 = mxz * (mxz * myy - myz * mxy) + myz * (myz * mxx - mxz * mxy) - var_z * cov_xy;
    let (mut x, mut y) = (0.0f64, a0);
    for _ in 0..99 {
        let next = x - y / (a1 + x * (2.0 * a2 + 3.0 * a3 * x));
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
    let (cx, cy) = (
        (mxz * (myy - x) - myz * mxy) / det / 2.0,
        (myz * (mxx - x) - mxz * mxy) / det / 2.0,
    );
    let r = (cx * cx + cy * cy + mz).sqrt();
    if !(r.is_finite() && det != 0.0) || r > 1e3 * mz.sqrt() {
        let half = 0.5 * (mxx + myy);
        let root = (0.25 * (mxx - myy).powi(2) + mxy * mxy).sqrt();
        let d = if mxx >= myy {
            [half + root - myy, mxy]
        } else {
            [mxy, half + root - mxx]
        };
        let norm = d[0].hypot(d[1]);
        if norm.is_nan() || norm <= 0.0 {
            return None;
        }
        let t = [d[0] / norm, d[1] / norm];
        let along = (p[0] - mx) * t[0] + (p[1] - my) * t[1];
        return Some((
            [mx + along * t[0], my + along * t[1]],
            (half - root).max(0.0).sqrt(),
        ));
    }
    let (ax, ay) = (cx + mx, cy + my);
    let sum2: f64 = pts
        .iter()
        .map(|q| ((q[0] - ax).hypot(q[1] - ay) - r).powi(2))
        .sum();
    let d = (p[0] - ax).hypot(p[1] - ay);
    if d.is_nan() || d <= 0.0 {
        return None;
    }
    Some((
        [ax + (p[0] - ax) / d * r, ay + (p[1] - ay) / d * r],
        (sum2 / n).sqrt(),
    ))
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    if values.is_empty() {
        f64::NAN
    } else {
        values[values.len() / 2]
    }
}

fn print_smoothing_tables() {
    let smoothing = Instant::now();
    println!(
        "\n### Smoothing (`--smooth`) on dense noisy bands\n\nEach curve sampled at n points at \
         uniformly random arc-length positions with Gaussian noise of σ (% of the truth's \
         diagonal) on each coordinate, 2 trials a row. noise = the input's own RMS distance to \
         the true curves; RMS and H (symmetric Hausdorff) of the output curves to the true \
         curves, all in % of the diagonal: `raw` through the input points, `smooth` through \
         the fitted ones, `fc` each vertex projected FitConnect-style (a Taubin circle fit of \
         its growing k nearest samples; our reading of the method). right = trials with one \
         closed curve per true curve and nothing else. ratio = smooth RMS / noise. wdm ms = the \
         default reconstruction with smoothing (dense bands are thinned first, \
         docs/design/thinning.md); unthinned right = the same with thinning off.\n"
    );
    println!("| input | n | σ % | wdm right | noise | raw RMS | smooth RMS | fc RMS | raw H | smooth H | fc H | ratio | wdm ms | unthinned right | crust right / ratio | nn-crust right / ratio |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let hole = Ellipse::circle(0.5).dense(DENSE);
    let shapes: Vec<(&str, Vec<DenseCurve>)> = vec![
        ("ellipse", vec![Ellipse { a: 2.0, b: 1.0 }.dense(DENSE)]),
        ("star5", vec![Star { a: 0.25, k: 5 }.dense(DENSE)]),
        ("blob", vec![Blob.dense(DENSE)]),
        (
            "ellipse with a hole",
            vec![Ellipse { a: 2.0, b: 1.0 }.dense(DENSE), hole],
        ),
    ];
    let (mut right_ratios, mut all_ratios, mut fc_ratios) = (Vec::new(), Vec::new(), Vec::new());
    let trials = 2;
    for (name, curves) in &shapes {
        for &n in &[300usize, 1000, 2000] {
            for &sigma in &[0.5, 1.0, 2.0] {
                let mut rng = Rng::new(7000 + n as u64 + (10.0 * sigma) as u64);
                let mut sums = [0.0f64; 7];
                let mut right = 0;
                let mut baselines = [(0usize, 0.0f64); 2];
                let (mut millis, mut unthinned) = (0.0f64, 0usize);
                for _ in 0..trials {
                    let (points, noise) = dense_band(curves, n, sigma, &mut rng);
                    let options = Options::new().with_smoothing(true);
                    let clock = Instant::now();
                    let Ok(rec) = reconstruct_with(&points, &options) else {
                        continue;
                    };
                    millis += clock.elapsed().as_secs_f64() * 1e3 / trials as f64;
                    if let Ok(plain) = reconstruct_with(&points, &options.with_thinning(false)) {
                        let closed = plain.curves().iter().filter(|c| c.closed).count();
                        unthinned +=
                            usize::from(closed == curves.len() && closed == plain.curves().len());
                    }
                    let closed = rec.curves().iter().filter(|c| c.closed).count();
                    let is_right = closed == curves.len() && closed == rec.curves().len();
                    right += usize::from(is_right);
                    let tri = rec.triangulation();
                    let input = |c: &wdm_crust::reconstruct::Curve| {
                        c.points.iter().map(|&i| tri.point(i)).collect()
                    };
                    let fitted = |c: &wdm_crust::reconstruct::Curve| rec.curve_coords(c);
                    let fc = |c: &wdm_crust::reconstruct::Curve| {
                        c.points
                            .iter()
                            .map(|&i| fitconnect_project(&points, tri.point(i)))
                            .collect()
                    };
                    let measure = |f: &dyn Fn(&wdm_crust::reconstruct::Curve) -> Vec<[f64; 2]>| {
                        let (pts, edges) = drawn(&rec, f);
                        curve_distances(&pts, &edges, curves)
                    };
                    let ((h0, r0), (h1, r1), (h2, r2)) =
                        (measure(&input), measure(&fitted), measure(&fc));
                    for (sum, v) in sums.iter_mut().zip([noise, r0, r1, r2, h0, h1, h2]) {
                        *sum += v / trials as f64;
                    }
                    all_ratios.push(r1 / noise);
                    if is_right {
                        right_ratios.push(r1 / noise);
                        fc_ratios.push(r2 / noise);
                    }
                    for (slot, algorithm) in baselines
                        .iter_mut()
                        .zip([Algorithm::Crust, Algorithm::NnCrust])
                    {
                        let options = options.with_algorithm(algorithm);
                        if let Ok(base) = reconstruct_with(&points, &options) {
                            let closed = base.curves().iter().filter(|c| c.closed).count();
                            slot.0 += usize::from(
                                closed == curves.len() && closed == base.curves().len(),
                            );
                            let (pts, edges) = drawn(&base, &|c| base.curve_coords(c));
                            slot.1 +=
                                curve_distances(&pts, &edges, curves).1 / noise / trials as f64;
                        }
                    }
                }
                let [noise, r0, r1, r2, h0, h1, h2] = sums;
                println!(
                    "| {name} | {n} | {sigma} | {right}/{trials} | {noise:.2} | {r0:.2} | {r1:.2} | {r2:.2} | {h0:.2} | {h1:.2} | {h2:.2} | {:.2} | {millis:.0} | {unthinned}/{trials} | {}/{trials} / {:.2} | {}/{trials} / {:.2} |",
                    r1 / noise, baselines[0].0, baselines[0].1, baselines[1].0, baselines[1].1
                );
            }
        }
    }
    println!(
        "\nMedian ratio (smoothed RMS / input noise), wdm: {:.2} over the right trials ({}), {:.2} over all ({}); FitConnect-style on the right trials: {:.2}.",
        median(right_ratios.clone()),
        right_ratios.len(),
        median(all_ratios.clone()),
        all_ratios.len(),
        median(fc_ratios)
    );

    // Clean ε-samples: how far any vertex moves, in units of its shorter curve step.
    let mut rng = Rng::new(7100);
    let mut worst = 0.0f64;
    let mut vertices = 0;
    let sets: Vec<CurveSet> = smooth_shapes()
        .into_iter()
        .map(|(_, c)| CurveSet::new(vec![c]))
        .collect();
    for &eps in &[0.2, 0.39] {
        for set in &sets {
            for _ in 0..3 {
                let sample = set
                    .eps_sample(eps, &mut rng)
                    .transformed(&Similarity::random(&mut rng))
                    .shuffled(&mut rng);
                let points = &sample.points;
                let Ok(rec) = reconstruct_with(points, &Options::new().with_smoothing(true)) else {
                    continue;
                };
                for c in rec.curves() {
                    let k = c.points.len();
                    for (i, q) in rec.curve_coords(c).iter().enumerate() {
                        let o = points[c.points[i] as usize];
                        let d = |x: [f64; 2]| (x[0] - o[0]).hypot(x[1] - o[1]);
                        let step = d(points[c.points[(i + 1) % k] as usize])
                            .min(d(points[c.points[(i + k - 1) % k] as usize]));
                        worst = worst.max(d(*q) / step);
                        vertices += 1;
                    }
                }
            }
        }
    }
    println!("\nClean ε-samples (ε = 0.2 and 0.39, 5 smooth shapes × 3 trials, {vertices} vertices): the largest move is {worst:.2e} of the vertex's shorter step.");

    // Corners: polygons with noise; the fitted vertex nearest each true corner, in units of σ.
    println!("\n| polygon (600 points, σ = 0.3 spacing, 5 trials) | corners | nearest fitted vertex to a corner, mean / max (σ) | input point nearest, mean / max (σ) | moved vertices |\n|---|---:|---:|---:|---:|");
    let polygons_with_corners: Vec<(&str, Vec<[f64; 2]>)> = vec![
        (
            "triangle 30°–75°–75°",
            vec![
                [0.0, 0.0],
                [4.0, 0.0],
                [
                    4.0 * 30f64.to_radians().cos(),
                    4.0 * 30f64.to_radians().sin(),
                ],
            ],
        ),
        (
            "square (90°)",
            vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
        ),
        (
            "L-shape (90°, one reflex)",
            vec![
                [0.0, 0.0],
                [3.0, 0.0],
                [3.0, 1.0],
                [1.0, 1.0],
                [1.0, 3.0],
                [0.0, 3.0],
            ],
        ),
    ];
    for (name, corners) in &polygons_with_corners {
        let mut rng = Rng::new(7200);
        let (mut fitted_sum, mut fitted_max, mut input_sum, mut input_max, mut count) =
            (0.0, 0.0f64, 0.0, 0.0f64, 0);
        let (mut moved, mut total) = (0, 0);
        for _ in 0..5 {
            let m = corners.len();
            let perimeter: f64 = (0..m)
                .map(|i| {
                    let (a, b) = (corners[i], corners[(i + 1) % m]);
                    (b[0] - a[0]).hypot(b[1] - a[1])
                })
                .sum();
            let spacing = perimeter / 600.0;
            let sigma = 0.3 * spacing;
            let mut points = Vec::new();
            for i in 0..m {
                let (a, b) = (corners[i], corners[(i + 1) % m]);
                let steps = ((b[0] - a[0]).hypot(b[1] - a[1]) / spacing).round() as usize;
                for s in 0..steps {
                    let t = s as f64 / steps as f64;
                    points.push([
                        a[0] + t * (b[0] - a[0]) + sigma * rng.normal(),
                        a[1] + t * (b[1] - a[1]) + sigma * rng.normal(),
                    ]);
                }
            }
            let Ok(rec) = reconstruct_with(&points, &Options::new().with_smoothing(true)) else {
                continue;
            };
            let coords: Vec<[f64; 2]> = rec
                .curves()
                .iter()
                .flat_map(|c| rec.curve_coords(c))
                .collect();
            let inputs: Vec<[f64; 2]> = rec
                .curves()
                .iter()
                .flat_map(|c| c.points.iter().map(|&i| points[i as usize]))
                .collect();
            moved += coords.iter().zip(&inputs).filter(|(a, b)| a != b).count();
            total += coords.len();
            for corner in corners {
                let nearest = |set: &[[f64; 2]]| {
                    set.iter()
                        .map(|q| (q[0] - corner[0]).hypot(q[1] - corner[1]) / sigma)
                        .fold(f64::INFINITY, f64::min)
                };
                let (f, i) = (nearest(&coords), nearest(&inputs));
                fitted_sum += f;
                fitted_max = fitted_max.max(f);
                input_sum += i;
                input_max = input_max.max(i);
                count += 1;
            }
        }
        let c = count.max(1) as f64;
        println!(
            "| {name} | {} | {:.2} / {:.2} | {:.2} / {:.2} | {:.0} % |",
            corners.len(),
            fitted_sum / c,
            fitted_max,
            input_sum / c,
            input_max,
            percent(moved, total)
        );
    }
    println!(
        "\nSmoothing tables: {:.1} s",
        smoothing.elapsed().as_secs_f64()
    );
}
