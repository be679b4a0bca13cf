//! Triangulation throughput, side by side with spade (bulk load) and delaunator on the same
//! points, per point set and size, every library on one thread; and wdm-crust's own speed-up
//! on 1 and 2 threads at 10^5 and 10^6 points. Compare ratios within one run: the machine is
//! shared.
//!
//! `cargo bench --bench triangulate` (add `WDM_BENCH_HUGE=1` for 10^7 points; filter with
//! e.g. `-- curve/` or `-- /1000000`; `-- threads/` for the speed-up alone).

mod common;

use common::{sizes, PointSet};
use criterion::measurement::WallTime;
use criterion::{
    criterion_group, criterion_main, BatchSize, BenchmarkGroup, BenchmarkId, Criterion, Throughput,
};

/// A pool of `threads` workers for wdm-crust's `parallel` feature; the benchmark loop runs
/// inside it (`install` per iteration would time a thread hand-over).
#[cfg(feature = "parallel")]
fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
}

/// Runs `f` on one thread, as the peers run.
fn single_threaded(f: impl FnOnce() + Send) {
    #[cfg(feature = "parallel")]
    pool(1).install(f);
    #[cfg(not(feature = "parallel"))]
    f();
}

fn bench_point_sets(c: &mut Criterion) {
    for set in PointSet::ALL {
        let mut group = c.benchmark_group(format!("triangulate/{}", set.name()));
        for n in sizes() {
            // Large inputs take ~1 s per iteration: the minimum sample count is plenty.
            group.sample_size(if n >= 100_000 { 10 } else { 30 });
            let points = set.points(n, 42);
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::new("wdm_crust", n), &points, |b, p| {
                single_threaded(|| b.iter(|| wdm_crust::triangulate(p).expect("valid points")))
            });
            bench_peers(&mut group, n, &points);
        }
        group.finish();
    }
}

/// spade's bulk load and delaunator on `points`, in `group`.
fn bench_peers(group: &mut BenchmarkGroup<'_, WallTime>, n: usize, points: &[[f64; 2]]) {
    let spade_points: Vec<spade::Point2<f64>> = points
        .iter()
        .map(|p| spade::Point2::new(p[0], p[1]))
        .collect();
    group.bench_with_input(BenchmarkId::new("spade_bulk", n), &spade_points, |b, p| {
        use spade::Triangulation as _;
        // bulk_load takes its input by value: the copy is made outside the timing.
        b.iter_batched(
            || p.clone(),
            |p| spade::DelaunayTriangulation::<spade::Point2<f64>>::bulk_load(p).unwrap(),
            BatchSize::LargeInput,
        )
    });
    let del_points: Vec<delaunator::Point> = points
        .iter()
        .map(|p| delaunator::Point { x: p[0], y: p[1] })
        .collect();
    group.bench_with_input(BenchmarkId::new("delaunator", n), &del_points, |b, p| {
        b.iter(|| delaunator::triangulate(p))
    });
}

/// wdm-crust in pools of 1 and 2 threads on the same points in the same run: the parallel
/// speed-up; on uniform points the peers too (one thread), for the margin by which the
/// single-threaded construction stays ahead (on the curve set they are 5–100× behind and take 20 s an iteration
/// at 10^6: see `triangulate/curve`).
#[cfg(feature = "parallel")]
fn bench_threads(c: &mut Criterion) {
    for set in [PointSet::Uniform, PointSet::Curve] {
        let mut group = c.benchmark_group(format!("threads/{}", set.name()));
        group.sample_size(10);
        for n in [100_000, 1_000_000] {
            let points = set.points(n, 42);
            group.throughput(Throughput::Elements(n as u64));
            for threads in [1, 2] {
                let pool = pool(threads);
                let id = BenchmarkId::new(format!("wdm_crust_{threads}_threads"), n);
                group.bench_with_input(id, &points, |b, p| {
                    pool.install(|| b.iter(|| wdm_crust::triangulate(p).expect("valid points")))
                });
            }
            if set == PointSet::Uniform {
                bench_peers(&mut group, n, &points);
            }
        }
        group.finish();
    }
}

#[cfg(not(feature = "parallel"))]
fn bench_threads(_: &mut Criterion) {}

criterion_group!(benches, bench_point_sets, bench_threads);
criterion_main!(benches);
