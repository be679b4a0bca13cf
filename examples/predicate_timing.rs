//! The public `orient2d` / `incircle` against their baselines, timed so that a shared, loaded
//! machine still gives stable numbers: each predicate runs in a loop of 1024 calls on random
//! points, the loop is timed 400 times (20 repetitions each), and the best time is kept.
//! Interference only ever adds time, so the best of many short timings is what the code
//! costs; the spread between rounds is about 0.01 ns. (Criterion's means, in
//! `cargo bench --bench pipeline -- predicates/`, move by 5–30 % when other builds run.)
//!
//! ```text
//! cargo run --release --example predicate_timing
//! ```
//!
//! In-circle is also timed on the tests a Delaunay triangulation of curve samples makes (each
//! interior edge: its triangle and the opposite point; the Voronoi dual and `validate` make
//! exactly these): thin, nearly cocircular quadruples, where the filters decline more often.
//!
//! Baselines: the unguarded forms (Shewchuk's filters without an underflow
//! term, then `robust`), and the `robust` crate itself, compared with zero as its callers do
//! and classified into a sign as the public functions answer.

#[path = "../benches/common/mod.rs"]
mod common;

use std::hint::black_box;
use std::time::Instant;

use common::baselines::{incircle_unguarded, orient_unguarded, robust_incircle, robust_orient};
use common::{PointSet, Rng};
use wdm_crust::predicates::{incircle, incircle_added_slack, orient2d, orient2d_added_slack};

const CALLS: usize = 1024;

/// Nanoseconds per call of the best of 400 timings of `loop_once` (20 loops each).
fn best_ns(mut loop_once: impl FnMut() -> usize) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..400 {
        let start = Instant::now();
        for _ in 0..20 {
            black_box(loop_once());
        }
        best = best.min(start.elapsed().as_secs_f64() / 20.0);
    }
    best * 1e9 / CALLS as f64
}

/// [`best_ns`] of counting the tests among `tests` that `accepts` (every test is run).
fn per_call<T>(tests: &[T], accepts: impl Fn(&T) -> bool) -> f64 {
    best_ns(|| tests.iter().filter(|&t| accepts(t)).count())
}

fn classified(x: f64) -> u8 {
    if x > 0.0 {
        0
    } else if x < 0.0 {
        1
    } else {
        2
    }
}

/// `count` in-circle tests of the Delaunay triangulation of `points`, spread over all of
/// them: each interior edge's triangle and the point opposite it.
fn delaunay_tests(points: &[[f64; 2]], count: usize) -> Vec<[[f64; 2]; 4]> {
    let tri = wdm_crust::triangulate(points).expect("valid points");
    let twins = tri.halfedges();
    let tests: Vec<[[f64; 2]; 4]> = (tri.halfedge_ids())
        .filter(|&e| tri.twin(e).is_some_and(|twin| twin > e))
        .map(|e| {
            let twin = twins[e.index()];
            let opposite = tri.point(tri.halfedge_origin(twin.prev()));
            let [a, b, c] = tri.triangle_points(e.triangle());
            [a, b, c, opposite]
        })
        .collect();
    let step = (tests.len() / count).max(1);
    tests.into_iter().step_by(step).take(count).collect()
}

/// A five-armed star sampled at uniformly random parameters (uneven spacing, thin triangles).
fn random_parameter_star(n: usize, rng: &mut Rng) -> Vec<[f64; 2]> {
    (0..n)
        .map(|_| {
            let t = rng.uniform() * std::f64::consts::TAU;
            let r = 1.0 + 0.5 * (5.0 * t).cos();
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// One row per timing: the public `incircle`, the pre-17 one and `robust`, on `quads`.
fn time_incircle(name: &str, quads: &[[[f64; 2]; 4]]) {
    let quads = black_box(quads);
    let row = [
        per_call(quads, |p| incircle(p[0], p[1], p[2], p[3]) as u8 == 0),
        per_call(quads, |p| incircle_unguarded(p[0], p[1], p[2], p[3]) == 0),
        per_call(quads, |p| {
            classified(robust_incircle(p[0], p[1], p[2], p[3])) == 0
        }),
    ];
    let cells: Vec<String> = row.iter().map(|t| format!("{t:.3}")).collect();
    println!("| {name} | {} |", cells.join(" | "));
}

fn main() {
    let mut rng = Rng::new(7);
    let points: Vec<[[f64; 2]; 4]> = (0..CALLS)
        .map(|_| [0; 4].map(|_| [rng.uniform(), rng.uniform()]))
        .collect();
    let quads = black_box(&points);
    println!("ns per call, random points, best of 400 timings of {CALLS}-call loops");
    println!("| predicate | public | underflow term added to the bound (`*_added_slack`) | unguarded | robust, == 0 | robust, sign |");
    println!("|---|---:|---:|---:|---:|---:|");
    for round in 0..3 {
        let orient = [
            per_call(quads, |p| orient2d(p[0], p[1], p[2]) as u8 == 0),
            per_call(quads, |p| orient2d_added_slack(p[0], p[1], p[2]) as u8 == 0),
            per_call(quads, |p| orient_unguarded(p[0], p[1], p[2]) == 0),
            per_call(quads, |p| robust_orient(p[0], p[1], p[2]) == 0.0),
            per_call(quads, |p| classified(robust_orient(p[0], p[1], p[2])) == 0),
        ];
        let in_circle = [
            per_call(quads, |p| incircle(p[0], p[1], p[2], p[3]) as u8 == 0),
            per_call(quads, |p| {
                incircle_added_slack(p[0], p[1], p[2], p[3]) as u8 == 0
            }),
            per_call(quads, |p| incircle_unguarded(p[0], p[1], p[2], p[3]) == 0),
            per_call(quads, |p| robust_incircle(p[0], p[1], p[2], p[3]) == 0.0),
            per_call(quads, |p| {
                classified(robust_incircle(p[0], p[1], p[2], p[3])) == 0
            }),
        ];
        for (name, row) in [("orient2d", orient), ("incircle", in_circle)] {
            let cells: Vec<String> = row.iter().map(|t| format!("{t:.3}")).collect();
            println!("| {name} (round {round}) | {} |", cells.join(" | "));
        }
    }
    println!();
    println!("in-circle on the Delaunay tests of curve samples ({CALLS} tests from 2^16 points)");
    println!("| tests | public | unguarded | robust, sign |");
    println!("|---|---:|---:|---:|");
    let star = random_parameter_star(1 << 16, &mut rng);
    let even = PointSet::Curve.points(1 << 16, 7);
    for round in 0..2 {
        time_incircle(
            &format!("star, random parameters (round {round})"),
            &delaunay_tests(&star, CALLS),
        );
        time_incircle(
            &format!("benches' curve set (round {round})"),
            &delaunay_tests(&even, CALLS),
        );
    }
}
