//! Profiles the derived exact predicates and the pipeline stages that call them.
//!
//! ```text
//! cargo run --release --features predicate-stats --example predicate_profile            # 200k points, 3 repetitions
//! cargo run --release --features predicate-stats --example predicate_profile -- 20000 1 # n points, repetitions
//! valgrind --tool=callgrind target/release/examples/predicate_profile 20000 1
//! ```
//!
//! The sample is the star `r(t) = 1 + 0.2 cos 5t` at random `t`. The program times
//! `triangulate`, `voronoi`, `label_vertices` and `reconstruct` (ns per point), then each
//! derived predicate in a loop over inputs taken from that diagram (ns per call), and prints
//! the exact-fallback counts. Every stage and loop is its own non-inlined function, so
//! callgrind's inclusive cost of `stage_*` / `loop_*` is the cost of that stage or loop.

use std::hint::black_box;
use std::time::Instant;

use wdm_crust::predicates::Orientation;
use wdm_crust::predicates::{
    circumcenter, circumcenter_in_convex_hull, compare_circumradius, dot_sign_circumcenters,
    fallback_counts, orient2d_circumcenter, reset_fallback_counts, HullPosition, Sign,
};
use wdm_crust::reconstruct::wdm::label_vertices;
use wdm_crust::{Triangulation, Voronoi};
use wdm_crust_testkit::Rng;

type P = [f64; 2];
type T = [P; 3];

fn star_sample(n: usize, seed: u64) -> Vec<P> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|_| {
            let t = rng.range(0.0, std::f64::consts::TAU);
            let r = 1.0 + 0.2 * (5.0 * t).cos();
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

/// Runs `f` `reps` times and returns the smallest wall time in nanoseconds.
fn best_of(reps: usize, mut f: impl FnMut()) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..reps.max(1) {
        let start = Instant::now();
        f();
        best = best.min(start.elapsed().as_nanos() as f64);
    }
    best
}

#[inline(never)]
fn stage_triangulate(points: &[P]) -> Triangulation {
    wdm_crust::triangulate(points).expect("valid sample")
}

#[inline(never)]
fn stage_voronoi(tri: &Triangulation) -> Voronoi<'_> {
    tri.voronoi()
}

#[inline(never)]
fn stage_label(vor: &Voronoi<'_>) -> usize {
    let flow = label_vertices(vor, Default::default());
    flow.visited.iter().filter(|&&v| v).count()
}

#[inline(never)]
fn stage_reconstruct(points: &[P]) -> usize {
    wdm_crust::reconstruct(points)
        .expect("valid sample")
        .edges()
        .len()
}

#[inline(never)]
fn loop_circumcenter(tris: &[T]) -> f64 {
    let mut acc = 0.0;
    for t in tris {
        let c = circumcenter(black_box(t[0]), t[1], t[2]).unwrap_or([0.0; 2]);
        acc += c[0] + c[1];
    }
    acc
}

#[inline(never)]
fn loop_dot(cases: &[(P, T, T)]) -> usize {
    let mut acc = 0;
    for (p, s, o) in cases {
        acc += usize::from(dot_sign_circumcenters(black_box(*p), *s, *o) == Sign::Negative);
    }
    acc
}

#[inline(never)]
fn loop_radius(tris: &[T]) -> usize {
    let mut acc = 0;
    for w in tris.windows(2) {
        acc += compare_circumradius(black_box(w[0]), w[1]) as i8 as usize;
    }
    acc
}

#[inline(never)]
fn loop_orient(cases: &[(P, P, T)]) -> usize {
    let mut acc = 0;
    for (a, b, t) in cases {
        acc += usize::from(orient2d_circumcenter(black_box(*a), *b, *t) == Orientation::Clockwise);
    }
    acc
}

#[inline(never)]
fn loop_hull(hull: &[P], tris: &[T]) -> usize {
    let mut acc = 0;
    for t in tris {
        acc +=
            usize::from(circumcenter_in_convex_hull(hull, black_box(*t)) == HullPosition::Inside);
    }
    acc
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(200_000);
    let reps: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(3);
    let points = star_sample(n, 42);

    let per_point = |ns: f64| ns / n as f64;
    let t_tri = best_of(reps, || {
        black_box(stage_triangulate(&points));
    });
    let tri = stage_triangulate(&points);
    let t_vor = best_of(reps, || {
        black_box(stage_voronoi(&tri));
    });
    let vor = stage_voronoi(&tri);
    reset_fallback_counts();
    let t_label = best_of(reps, || {
        black_box(stage_label(&vor));
    });
    let label_counts = fallback_counts();
    let t_rec = best_of(reps, || {
        black_box(stage_reconstruct(&points));
    });
    println!("n = {n}, {} Voronoi vertices", vor.vertex_count());
    println!("triangulate  {:8.1} ns/point", per_point(t_tri));
    println!("voronoi      {:8.1} ns/point", per_point(t_vor));
    println!("label        {:8.1} ns/point", per_point(t_label));
    println!(
        "reconstruct  {:8.1} ns/point ({:.2}x triangulate)",
        per_point(t_rec),
        t_rec / t_tri
    );
    println!("labeling fallbacks ({reps} runs): {label_counts:?}");

    // Inputs of the predicate loops, taken from the diagram.
    let vertex_tris: Vec<T> = vor.vertex_ids().map(|v| vor.vertex_triangle(v)).collect();
    let mut dot_cases = Vec::new();
    for p in 0..tri.point_count() as u32 {
        if !vor.is_cell_bounded(p) {
            continue;
        }
        let cell: Vec<wdm_crust::VertexId> = vor.cell(p).collect();
        let point = tri.point(p);
        let source = vor.vertex_triangle(cell[0]);
        for &v in &cell[1..] {
            dot_cases.push((point, source, vor.vertex_triangle(v)));
        }
    }
    let orient_cases: Vec<(P, P, T)> = vertex_tris
        .windows(2)
        .map(|w| (w[1][0], w[1][1], w[0]))
        .collect();
    let hull: Vec<P> = tri.hull().map(|i| tri.point(i)).collect();
    let ray_tris: Vec<T> = vor
        .vertex_ids()
        .filter(|&v| vor.has_ray(v))
        .map(|v| vor.vertex_triangle(v))
        .collect();
    let hull_cases: Vec<T> = ray_tris.iter().cycle().take(n).copied().collect();

    reset_fallback_counts();
    let report = |name: &str, ns: f64, calls: usize| {
        println!(
            "{name:<28} {:8.1} ns/call ({calls} calls)",
            ns / calls.max(1) as f64
        );
    };
    let ns = best_of(reps, || {
        black_box(loop_circumcenter(&vertex_tris));
    });
    report("circumcenter", ns, vertex_tris.len());
    let ns = best_of(reps, || {
        black_box(loop_dot(&dot_cases));
    });
    report("dot_sign_circumcenters", ns, dot_cases.len());
    let ns = best_of(reps, || {
        black_box(loop_radius(&vertex_tris));
    });
    report("compare_circumradius", ns, vertex_tris.len() - 1);
    let ns = best_of(reps, || {
        black_box(loop_orient(&orient_cases));
    });
    report("orient2d_circumcenter", ns, orient_cases.len());
    let ns = best_of(reps, || {
        black_box(loop_hull(&hull, &hull_cases));
    });
    report(
        &format!("circumcenter_in_convex_hull (h = {})", hull.len()),
        ns,
        hull_cases.len(),
    );
    let c = fallback_counts();
    let rate = |c: wdm_crust::predicates::PredicateCounts| {
        let pct = |x: u64| 100.0 * x as f64 / c.calls.max(1) as f64;
        format!(
            "exact {} / {} = {:.4} %, slow {} = {:.4} %",
            c.exact,
            c.calls,
            pct(c.exact),
            c.slow,
            pct(c.slow)
        )
    };
    println!("fallbacks in the loops ({reps} runs):");
    println!("  circumcenter                {}", rate(c.circumcenter));
    println!(
        "  dot_sign_circumcenters      {}",
        rate(c.dot_sign_circumcenters)
    );
    println!(
        "  compare_circumradius        {}",
        rate(c.compare_circumradius)
    );
    println!(
        "  orient2d_circumcenter       {}",
        rate(c.orient2d_circumcenter)
    );
    println!(
        "  circumcenter_in_convex_hull {}",
        rate(c.circumcenter_in_convex_hull)
    );
}
