//! Same run, same points, same machine: the quad-edge store of wdm-crust 79d15e6 against the
//! triangle store, once driven by 79d15e6's pipeline and once by the current crate.
//!
//! Groups `{set}/{n}` with set in {uniform, noisy_ellipse} and n in {10^4, 10^5, 10^6};
//! throughput is in points. Before a group is timed, the three stores must give the same
//! triangles (compared as sorted coordinate triples), outside the timed loop.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use quadedge_compare::{noisy_ellipse, uniform, Store};

fn compare(c: &mut Criterion) {
    type Gen = fn(usize, u64) -> Vec<[f64; 2]>;
    let sets: [(&str, Gen); 2] = [("uniform", uniform), ("noisy_ellipse", noisy_ellipse)];
    for (set, generate) in sets {
        for n in [10_000usize, 100_000, 1_000_000] {
            let pts = generate(n, 0x5EED ^ n as u64);
            let reference = Store::QuadEdge.canonical(&pts);
            for store in [Store::TriangleLex, Store::Current] {
                let t = store.canonical(&pts);
                assert_eq!(
                    t.len(),
                    reference.len(),
                    "{set}/{n}: triangle count of {store:?}"
                );
                assert!(t == reference, "{set}/{n}: triangles of {store:?} differ");
            }
            drop(reference);
            let mut group = c.benchmark_group(set);
            group.throughput(Throughput::Elements(n as u64));
            group.sample_size(match n {
                1_000_000 => 10,
                100_000 => 20,
                _ => 50,
            });
            for store in Store::ALL {
                group.bench_with_input(BenchmarkId::new(store.name(), n), &pts, |b, pts| {
                    b.iter(|| black_box(store.run(black_box(pts))))
                });
            }
            group.finish();
        }
    }
}

criterion_group!(benches, compare);
criterion_main!(benches);
