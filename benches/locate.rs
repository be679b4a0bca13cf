//! Point location and nearest point, side by side with spade on the same points and queries.
//!
//! For each point set (uniform, clusters) and size, both libraries triangulate the same
//! points (outside the timing) and answer the same 10^4 queries per iteration:
//!
//! * `random`: queries uniform over the points' bounding box, in random order (every walk
//!   starts far from its target);
//! * `coherent`: the same queries sorted along a Hilbert-like serpentine (each walk starts
//!   near its target, as when tracing a path or rasterising).
//!
//! wdm-crust answers with a [`wdm_crust::delaunay::Locator`] (each walk starts from a coarse
//! grid of start triangles, built when the locator is made: outside the timing, like spade's
//! structures). spade answers with `locate` and `nearest_neighbor` twice: with its default
//! hint (the last vertex used: `spade`) and with its hierarchy of hint triangulations
//! (`spade_hierarchy`). Both libraries decide with exact orientation tests. Compare ratios
//! within one run.
//!
//! `cargo bench --bench locate` (filter with e.g. `-- locate/uniform/random`; add
//! `WDM_BENCH_HUGE=1` for 10^6 points).

mod common;

use common::{PointSet, Rng};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use spade::{
    DelaunayTriangulation, HierarchyHintGenerator, HintGenerator, Point2, PositionInTriangulation,
    Triangulation as _,
};

/// spade with its hierarchy of hint triangulations (its fast option for scattered queries).
type SpadeHierarchy = DelaunayTriangulation<Point2<f64>, (), (), (), HierarchyHintGenerator<f64>>;

const QUERIES: usize = 10_000;

/// Queries uniform over the box of `points`, in random order, and the same sorted into
/// serpentine rows (100 strips) so that consecutive queries are near each other.
fn queries(points: &[[f64; 2]], seed: u64) -> (Vec<[f64; 2]>, Vec<[f64; 2]>) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let mut rng = Rng::new(seed);
    let random: Vec<[f64; 2]> = (0..QUERIES)
        .map(|_| [0, 1].map(|k| lo[k] + rng.uniform() * (hi[k] - lo[k])))
        .collect();
    let strips = 100.0;
    let strip = |q: &[f64; 2]| (((q[1] - lo[1]) / (hi[1] - lo[1]) * strips) as i64).min(99);
    let mut coherent = random.clone();
    coherent.sort_by(|a, b| {
        let (sa, sb) = (strip(a), strip(b));
        let along = |q: &[f64; 2], s: i64| if s % 2 == 0 { q[0] } else { -q[0] };
        sa.cmp(&sb).then(along(a, sa).total_cmp(&along(b, sb)))
    });
    (random, coherent)
}

/// How many of `qs` spade locates in the closed hull.
fn spade_inside<L: HintGenerator<f64>>(
    dt: &DelaunayTriangulation<Point2<f64>, (), (), (), L>,
    qs: &[[f64; 2]],
) -> usize {
    qs.iter()
        .filter(|q| {
            !matches!(
                dt.locate(Point2::new(q[0], q[1])),
                PositionInTriangulation::OutsideOfConvexHull(_)
                    | PositionInTriangulation::NoTriangulation
            )
        })
        .count()
}

/// The sum of the indices of spade's nearest vertices to `qs` (something to return).
fn spade_nearest<L: HintGenerator<f64>>(
    dt: &DelaunayTriangulation<Point2<f64>, (), (), (), L>,
    qs: &[[f64; 2]],
) -> u64 {
    qs.iter()
        .map(|q| {
            dt.nearest_neighbor(Point2::new(q[0], q[1]))
                .map_or(0, |v| v.fix().index() as u64)
        })
        .sum()
}

fn bench_locate(c: &mut Criterion) {
    for set in [PointSet::Uniform, PointSet::Clusters] {
        for n in [10_000, 100_000, 1_000_000] {
            if n == 1_000_000 && std::env::var_os("WDM_BENCH_HUGE").is_none() {
                continue; // spade's last-vertex hint takes seconds per batch there
            }
            let points = set.points(n, 42);
            let tri = wdm_crust::triangulate(&points).expect("valid points");
            let spade_points: Vec<Point2<f64>> =
                points.iter().map(|p| Point2::new(p[0], p[1])).collect();
            let dt = DelaunayTriangulation::<Point2<f64>>::bulk_load(spade_points.clone()).unwrap();
            let dth = SpadeHierarchy::bulk_load(spade_points).unwrap();
            let (random, coherent) = queries(&points, 7);
            // The same questions get the same answers: inside or outside the hull.
            let inside_wdm = random
                .iter()
                .filter(|&&q| tri.locate(q).unwrap() != wdm_crust::delaunay::Location::Outside)
                .count();
            let inside_spade = spade_inside(&dth, &random);
            assert_eq!(inside_wdm, inside_spade, "{} {n}", set.name());
            for (order, qs) in [("random", &random), ("coherent", &coherent)] {
                let mut group = c.benchmark_group(format!("locate/{}/{order}", set.name()));
                group.throughput(Throughput::Elements(QUERIES as u64));
                group.sample_size(if n >= 1_000_000 { 10 } else { 20 });
                group.bench_with_input(BenchmarkId::new("wdm_crust", n), qs, |b, qs| {
                    let mut locator = tri.locator();
                    b.iter(|| {
                        let mut inside = 0usize;
                        for &q in qs {
                            let at = locator.locate(q).expect("valid query");
                            inside += usize::from(at != wdm_crust::delaunay::Location::Outside);
                        }
                        inside
                    })
                });
                // spade's last-vertex hint walks across the whole triangulation for each random
                // query: seconds per batch from 10^5 points on, so only below that.
                let slow = order == "random" && n >= 100_000;
                if !slow {
                    group.bench_with_input(BenchmarkId::new("spade", n), qs, |b, qs| {
                        b.iter(|| spade_inside(&dt, qs))
                    });
                }
                group.bench_with_input(BenchmarkId::new("spade_hierarchy", n), qs, |b, qs| {
                    b.iter(|| spade_inside(&dth, qs))
                });
                group.finish();
                let mut group = c.benchmark_group(format!("nearest/{}/{order}", set.name()));
                group.throughput(Throughput::Elements(QUERIES as u64));
                group.sample_size(if n >= 1_000_000 { 10 } else { 20 });
                group.bench_with_input(BenchmarkId::new("wdm_crust", n), qs, |b, qs| {
                    let mut locator = tri.locator();
                    b.iter(|| {
                        let mut sum = 0u64;
                        for &q in qs {
                            sum += u64::from(locator.nearest(q).expect("valid query").unwrap_or(0));
                        }
                        sum
                    })
                });
                if !slow {
                    group.bench_with_input(BenchmarkId::new("spade", n), qs, |b, qs| {
                        b.iter(|| spade_nearest(&dt, qs))
                    });
                }
                group.bench_with_input(BenchmarkId::new("spade_hierarchy", n), qs, |b, qs| {
                    b.iter(|| spade_nearest(&dth, qs))
                });
                group.finish();
            }
        }
    }
}

criterion_group!(benches, bench_locate);
criterion_main!(benches);
