//! Triangulation throughput, side by side with spade and delaunator on the same points.
//!
//! `cargo bench --bench triangulate`

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};

/// SplitMix64: a tiny deterministic generator so the bench needs no extra dependency.
fn uniform_points(n: usize, mut seed: u64) -> Vec<[f64; 2]> {
    let mut next = move || {
        seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = seed;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n).map(|_| [next(), next()]).collect()
}

fn bench_uniform(c: &mut Criterion) {
    let mut group = c.benchmark_group("triangulate_uniform");
    group.sample_size(10);
    for &n in &[10_000usize, 100_000, 1_000_000] {
        let points = uniform_points(n, 42);
        group.throughput(Throughput::Elements(n as u64));
        group.bench_with_input(BenchmarkId::new("wdm_crust", n), &points, |b, p| {
            b.iter(|| wdm_crust::triangulate(p).unwrap())
        });
        let spade_points: Vec<spade::Point2<f64>> = points
            .iter()
            .map(|p| spade::Point2::new(p[0], p[1]))
            .collect();
        group.bench_with_input(BenchmarkId::new("spade_bulk", n), &spade_points, |b, p| {
            use spade::Triangulation as _;
            b.iter(|| {
                spade::DelaunayTriangulation::<spade::Point2<f64>>::bulk_load(p.clone()).unwrap()
            })
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

criterion_group!(benches, bench_uniform);
criterion_main!(benches);
