//! The triangulation does not depend on the number of threads: every array of the result is
//! the same in thread pools of 1, 2, 3 and 7 threads, on inputs large enough to split at
//! the parallel top of the recursion several times.
#![cfg(feature = "parallel")]

#[path = "../benches/common/mod.rs"]
mod sets;

use sets::{PointSet, Rng};
use wdm_crust::Triangulation;

/// The thread counts compared; 1 runs the sequential construction.
const THREADS: [usize; 4] = [1, 2, 3, 7];

/// Runs `f` in a pool of `threads` workers.
fn in_pool<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool")
        .install(f)
}

/// Every field of the triangulation: the points in their construction order with their
/// caller indices, the triangles and twins by id, the hull, the duplicates. `Debug` prints
/// floats in their shortest exact form, so equal text means equal bits.
fn everything(tri: &Triangulation) -> String {
    format!("{tri:?}")
}

/// The public arrays too, so that a failure says which one differs.
fn assert_same(a: &Triangulation, b: &Triangulation, what: &str) {
    assert_eq!(
        a.triangles().collect::<Vec<_>>(),
        b.triangles().collect::<Vec<_>>(),
        "{what}: triangles"
    );
    assert_eq!(a.halfedges(), b.halfedges(), "{what}: twins");
    assert_eq!(
        a.hull().collect::<Vec<_>>(),
        b.hull().collect::<Vec<_>>(),
        "{what}: hull"
    );
    assert_eq!(a.duplicates(), b.duplicates(), "{what}: duplicates");
    assert!(everything(a) == everything(b), "{what}: point order");
}

fn assert_thread_count_independent(points: &[[f64; 2]], what: &str) {
    let reference = in_pool(1, || wdm_crust::triangulate(points)).expect("valid points");
    reference.validate().expect("a Delaunay triangulation");
    for threads in &THREADS[1..] {
        let tri = in_pool(*threads, || wdm_crust::triangulate(points)).expect("valid points");
        assert_same(&reference, &tri, &format!("{what} on {threads} threads"));
    }
}

#[test]
fn uniform_clusters_grid_and_curve_are_the_same_on_any_thread_count() {
    for set in PointSet::ALL {
        // 2^14 points or more are split at the parallel top: 5 levels of it here.
        let points = set.points(300_001, 7);
        assert_thread_count_independent(&points, set.name());
    }
}

#[test]
fn a_curve_with_duplicates_is_the_same_on_any_thread_count() {
    let mut rng = Rng::new(11);
    let mut points = sets::curve_points(120_000, &mut rng);
    // Every tenth point again, somewhere later in the input.
    let copies: Vec<[f64; 2]> = points.iter().step_by(10).copied().collect();
    points.extend(copies);
    rng.shuffle(&mut points);
    let tri = in_pool(2, || wdm_crust::triangulate(&points)).expect("valid points");
    assert_eq!(tri.duplicates().len(), 12_000);
    assert_thread_count_independent(&points, "curve with duplicates");
}

#[test]
fn a_large_cluster_finer_than_the_grid_is_the_same_on_any_thread_count() {
    // 10^5 points in a box of side 2^-30 beside far outliers: the cluster's keys on the
    // global grid are all equal, so it is re-keyed at the parallel top.
    let mut rng = Rng::new(5);
    let mut points: Vec<[f64; 2]> = (0..100_000)
        .map(|_| {
            [
                0.5 + rng.uniform() * 2f64.powi(-30),
                0.25 + rng.uniform() * 2f64.powi(-30),
            ]
        })
        .collect();
    points.extend([[1.5, -0.75], [-3.0, 2.0], [40.0, 41.0]]);
    assert_thread_count_independent(&points, "cluster");
}

/// An annulus (two noisy nested loops) with scattered outliers: peeling runs, points are
/// left unassigned, and the pruned axis triangulates the loops' points on their own.
fn annulus_with_outliers(n: usize, rng: &mut Rng) -> Vec<[f64; 2]> {
    let mut points: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = i as f64 / n as f64 * std::f64::consts::TAU;
            let r = if i % 3 == 0 { 0.5 } else { 1.0 } * (1.0 + 1e-4 * rng.normal());
            [r * t.cos(), 0.8 * r * t.sin()]
        })
        .collect();
    points.extend((0..n / 100).map(|_| [3.0 * rng.uniform() - 1.5, 2.0 * rng.uniform() - 1.0]));
    rng.shuffle(&mut points);
    points
}

#[test]
fn the_reconstruction_is_the_same_on_any_thread_count() {
    use wdm_crust::reconstruct::{MedialAxisMode, Options};
    let inputs = [
        ("curve", PointSet::Curve.points(60_000, 3)),
        (
            "annulus with outliers",
            annulus_with_outliers(90_000, &mut Rng::new(9)),
        ),
    ];
    for (what, points) in &inputs {
        for mode in [MedialAxisMode::Pruned, MedialAxisMode::Raw] {
            let options = Options::new().with_medial_axis(mode);
            let run = |threads| {
                in_pool(threads, || {
                    wdm_crust::reconstruct::reconstruct_with(points, &options)
                })
                .expect("valid points")
            };
            let reference = run(1);
            assert!(!reference.curves().is_empty(), "{what}");
            assert!(!reference.medial_axis().edges.is_empty(), "{what}");
            if what.starts_with("annulus") {
                // The paths this input is for: a second pass, points on no curve.
                assert!(reference.passes() > 1, "{what}");
                assert!(!reference.unassigned().is_empty(), "{what}");
            }
            for threads in &THREADS[1..] {
                let other = run(*threads);
                let at = format!("{what}, {mode:?}, {threads} threads");
                assert_eq!(other.labels(), reference.labels(), "{at}: labels");
                assert_eq!(other.edges(), reference.edges(), "{at}: edges");
                assert_eq!(other.curves(), reference.curves(), "{at}: curves");
                assert_eq!(
                    other.unassigned(),
                    reference.unassigned(),
                    "{at}: unassigned"
                );
                assert_eq!(other.passes(), reference.passes(), "{at}: passes");
                assert_eq!(
                    format!("{:?}", other.medial_axis()),
                    format!("{:?}", reference.medial_axis()),
                    "{at}: medial axis"
                );
            }
        }
    }
}
