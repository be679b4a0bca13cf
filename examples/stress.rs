//! Resource stress driver: one large or pathological input through `triangulate`, the Voronoi
//! dual and `reconstruct`, with the time of each stage and the peak resident memory.
//!
//! ```text
//! cargo build --release --example stress
//! /usr/bin/time -v target/release/examples/stress <set> <n> [stages]
//! ```
//!
//! Point sets (`n` points each, in shuffled order, seed fixed):
//! * `uniform`: uniform in the unit square;
//! * `curve`: on a smooth closed star-shaped curve `r = 1 + 0.3 cos 5t`, random parameters;
//! * `even-curve`: the benches' workload: that star squashed to 0.7 in y, at jittered even
//!   spacing, with radial noise of a tenth of the spacing;
//! * `band`: a dense noisy scan, an ellipse 2 × 1.2 at random positions with Gaussian noise
//!   across it of 1 % of its bounding box's diagonal (the environment variable `BAND` sets
//!   another share: `BAND=0.00001` is about 5 mean steps at 10^6 points);
//! * `circle`: on the unit circle, random angles (nearly cocircular: exact fallbacks galore);
//! * `grid`: the integer grid `⌈√n⌉ × ⌈√n⌉` truncated to `n` (every cell cocircular);
//! * `two-lines`: half on `y = 0`, half on `y = 1`, integer x (every quad cocircular);
//! * `crossing-lines`: half on `y = x`, half on `y = −x` (two lines through one point);
//! * `dup3`: `n` copies of three points;
//! * `collinear`: `n` distinct points on the line `y = 3x + 1`, irregular spacing.
//!
//! Stages: a comma-separated subset of
//! `points,triangulate,voronoi,single,reconstruct,raw,curves,smooth` (default: all but `raw`,
//! `curves` and `smooth`); `single` is the reconstruction without peeling (one water-flow pass),
//! `reconstruct` the default one, `raw` the default one with the paper's raw medial axis
//! (`MedialAxisMode::Raw`), `curves` the default one without a medial axis
//! (`MedialAxisMode::Omitted`), `smooth` the curves alone fitted to the samples
//! (`Options::with_smoothing`). `points` alone only generates the input (the baseline for
//! memory). Each run prints one line
//! per stage and a final line with the peak resident set size read from `/proc/self/status`
//! (`VmHWM`, the same figure as `/usr/bin/time -v`'s "Maximum resident set size").

use std::time::Instant;

use wdm_crust::reconstruct::{reconstruct_observed, MedialAxisMode, Options};
use wdm_crust_testkit::Rng;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (Some(set), Some(n)) = (
        args.first(),
        args.get(1).and_then(|s| s.parse::<usize>().ok()),
    ) else {
        eprintln!("usage: stress <uniform|curve|even-curve|band|circle|grid|two-lines|crossing-lines|dup3|collinear> <n> [points,triangulate,voronoi,single,reconstruct,raw,curves,smooth]");
        std::process::exit(2);
    };
    let stages: Vec<&str> = args
        .get(2)
        .map_or(
            "points,triangulate,voronoi,single,reconstruct",
            String::as_str,
        )
        .split(',')
        .collect();
    let stage = |name: &str| stages.contains(&name);
    let start = Instant::now();
    let Some(points) = generate(set, n) else {
        eprintln!("unknown point set {set}");
        std::process::exit(2);
    };
    println!(
        "{set} n={} generated in {:.2}s",
        points.len(),
        start.elapsed().as_secs_f64()
    );
    if stage("triangulate") || stage("voronoi") {
        let t = Instant::now();
        let tri = wdm_crust::triangulate(&points).expect("valid points");
        println!(
            "triangulate: {:.3}s ({:.1} ns per point per log2 n), {} distinct, {} triangles, hull {}",
            t.elapsed().as_secs_f64(),
            t.elapsed().as_secs_f64() * 1e9 / (n as f64 * (n.max(2) as f64).log2()),
            tri.distinct_point_count(),
            tri.triangle_count(),
            tri.hull().len()
        );
        if stage("voronoi") {
            let t = Instant::now();
            let vor = tri.voronoi();
            let built = t.elapsed().as_secs_f64();
            let merged = vor.vertex_ids().filter(|&v| vor.degree(v) > 3).count();
            println!(
                "voronoi: {built:.2}s, {} vertices ({merged} merged), {} finite edges",
                vor.vertex_count(),
                vor.finite_edges().count()
            );
        }
    }
    for (name, peeling, axis, smoothing) in [
        ("single", false, MedialAxisMode::Pruned, false),
        ("reconstruct", true, MedialAxisMode::Pruned, false),
        ("raw", true, MedialAxisMode::Raw, false),
        ("curves", true, MedialAxisMode::Omitted, false),
        ("smooth", true, MedialAxisMode::Omitted, true),
    ] {
        if !stage(name) {
            continue;
        }
        let options = Options::new()
            .with_peeling(peeling)
            .with_medial_axis(axis)
            .with_smoothing(smoothing);
        let t = Instant::now();
        let (mut phases, mut peaks) = (Vec::new(), Vec::new());
        let rec = reconstruct_observed(&points, &options, &mut |phase, time| {
            phases.push(format!("{} {:.3}", phase.name(), time.as_secs_f64()));
            peaks.push(format!(
                "{} {}",
                phase.name(),
                peak_rss_kib() * 1024 / n.max(1) as u64
            ));
        })
        .expect("valid points");
        println!(
            "{name}: {:.2}s, {} edges, {} curves, {} passes{}, {} untouched, {} medial-axis segments",
            t.elapsed().as_secs_f64(),
            rec.edges().len(),
            rec.curves().len(),
            rec.passes(),
            if rec.peeling_budget_exhausted() {
                " (budget reached)"
            } else {
                ""
            },
            rec.untouched_points().len(),
            rec.medial_axis().edges.len()
        );
        println!("  phases (s): {}", phases.join(", "));
        println!("  peak RSS after each phase (B/pt): {}", peaks.join(", "));
    }
    let peak = peak_rss_kib();
    println!(
        "total {:.2}s, peak RSS {} KiB = {:.0} bytes/point",
        start.elapsed().as_secs_f64(),
        peak,
        peak as f64 * 1024.0 / points.len().max(1) as f64
    );
}

/// `VmHWM` of this process in KiB, 0 if unavailable.
fn peak_rss_kib() -> u64 {
    std::fs::read_to_string("/proc/self/status")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmHWM:"))
                .and_then(|l| l.split_whitespace().nth(1))
                .and_then(|v| v.parse().ok())
        })
        .unwrap_or(0)
}

fn generate(set: &str, n: usize) -> Option<Vec<[f64; 2]>> {
    let mut rng = Rng::new(0x5eed_0000 + n as u64);
    let tau = std::f64::consts::TAU;
    let mut points: Vec<[f64; 2]> = match set {
        "uniform" => (0..n).map(|_| [rng.f64(), rng.f64()]).collect(),
        "curve" => (0..n)
            .map(|_| {
                let t = rng.range(0.0, tau);
                let r = 1.0 + 0.3 * (5.0 * t).cos();
                [r * t.cos(), r * t.sin()]
            })
            .collect(),
        "even-curve" => {
            // The benches' reconstruction workload: the squashed star at jittered even
            // spacing with radial noise of a tenth of the spacing.
            let spacing = tau / n as f64;
            (0..n)
                .map(|i| {
                    let t = (i as f64 + 0.5 * rng.f64()) * spacing;
                    let r = 1.0 + 0.3 * (5.0 * t).cos() + 0.1 * spacing * rng.normal();
                    [r * t.cos(), 0.7 * r * t.sin()]
                })
                .collect()
        }
        "band" => {
            // A dense noisy scan: an ellipse 2 × 1.2 with Gaussian noise across it of a share
            // of its bounding box's diagonal (`BAND`, default 1 %: σ ≈ 0.023).
            let sigma = std::env::var("BAND")
                .ok()
                .and_then(|s| s.parse().ok())
                .unwrap_or(0.01)
                * (4.0f64 + 1.44).sqrt();
            (0..n)
                .map(|_| {
                    let t = rng.range(0.0, tau);
                    let (c, s) = (t.cos(), t.sin());
                    let (x, y) = (c, 0.6 * s);
                    let normal = [0.6 * c, s];
                    let len = (normal[0] * normal[0] + normal[1] * normal[1]).sqrt();
                    let d = sigma * rng.normal() / len;
                    [x + d * normal[0], y + d * normal[1]]
                })
                .collect()
        }
        "circle" => (0..n)
            .map(|_| {
                let t = rng.range(0.0, tau);
                [t.cos(), t.sin()]
            })
            .collect(),
        "grid" => {
            let side = (n as f64).sqrt().ceil() as usize;
            (0..n)
                .map(|i| [(i % side) as f64, (i / side) as f64])
                .collect()
        }
        "two-lines" => (0..n).map(|i| [(i / 2) as f64, (i % 2) as f64]).collect(),
        "crossing-lines" => (0..n)
            .map(|i| {
                let x = (i / 2) as f64 - (n / 4) as f64;
                [x, if i % 2 == 0 { x } else { -x }]
            })
            .collect(),
        "dup3" => {
            let three = [[0.0, 0.0], [1.0, 0.0], [0.25, 0.75]];
            (0..n).map(|i| three[i % 3]).collect()
        }
        "collinear" => {
            let mut x = 0.0;
            (0..n)
                .map(|_| {
                    x += 1.0 + (rng.below(16) as f64);
                    [x, 3.0 * x + 1.0]
                })
                .collect()
        }
        _ => return None,
    };
    rng.shuffle(&mut points);
    Some(points)
}
