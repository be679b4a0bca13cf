//! Triangulation throughput, side by side with spade (bulk load) and delaunator on the same
//! points, per point set and size. Compare ratios within one run: the machine is shared.
//!
//! `cargo bench --bench triangulate` (add `WDM_BENCH_HUGE=1` for 10^7 points; filter with
//! e.g. `-- curve/` or `-- /1000000`).

mod common;

use common::{sizes, PointSet};
use criterion::{criterion_group, criterion_main, BatchSize, BenchmarkId, Criterion, Throughput};

fn bench_point_sets(c: &mut Criterion) {
    for set in PointSet::ALL {
        let mut group = c.benchmark_group(format!("triangulate/{}", set.name()));
        for n in sizes() {
            // Large inputs take ~1 s per iteration: the minimum sample count is plenty.
            group.sample_size(if n >= 100_000 { 10 } else { 30 });
            let points = set.points(n, 42);
            group.throughput(Throughput::Elements(n as u64));
            group.bench_with_input(BenchmarkId::new("wdm_crust", n), &points, |b, p| {
                b.iter(|| wdm_crust::triangulate(p).expect("valid points"))
            });
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
        group.finish();
    }
}

criterion_group!(benches, bench_point_sets);
criterion_main!(benches);
