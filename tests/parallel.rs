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
    assert_eq!(a.triangles(), b.triangles(), "{what}: triangles");
    assert_eq!(a.halfedges(), b.halfedges(), "{what}: twins");
    assert_eq!(a.hull(), b.hull(), "{what}: hull");
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

#[test]
fn the_reconstruction_is_the_same_on_any_thread_count() {
    let points = PointSet::Curve.points(60_000, 3);
    let reference = in_pool(1, || wdm_crust::reconstruct(&points)).expect("valid points");
    assert!(!reference.curves().is_empty());
    for threads in [2, 3] {
        let other = in_pool(threads, || wdm_crust::reconstruct(&points)).expect("valid points");
        assert_eq!(other.edges(), reference.edges(), "{threads} threads: edges");
        assert_eq!(
            other.curves(),
            reference.curves(),
            "{threads} threads: curves"
        );
        assert_eq!(
            other.unassigned(),
            reference.unassigned(),
            "{threads} threads: unassigned"
        );
        assert_eq!(
            format!("{:?}", other.medial_axis()),
            format!("{:?}", reference.medial_axis()),
            "{threads} threads: medial axis"
        );
    }
}
