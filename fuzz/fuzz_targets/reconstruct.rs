//! `reconstruct` never panics. The single pass (no peeling) returns exactly the Delaunay edges
//! whose dual Voronoi edge joins an inner and an outer vertex, and exactly the inner–inner
//! finite Voronoi edges as medial axis; peeling only adds edges between points the first pass
//! left untouched; curves partition the edges; and the result does not depend on the order of
//! the input points (edges mapped back through the permutation, duplicates to their first
//! occurrence). Without the medial axis (`MedialAxisMode::Omitted`) everything else is the
//! default's.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wdm_crust::reconstruct::{reconstruct_with, MedialAxisMode, Options};
use wdm_crust_fuzz::checks::{
    check_default, check_peeled, check_permuted, check_single_pass, expected_error, permute,
    same_error,
};
use wdm_crust_fuzz::fail;
use wdm_crust_fuzz::scene::{permutation, Scene};

const MAX_POINTS: usize = 600;

/// Relaxes the order-independence check for the order dependences fixed in `order_face_cycle`
/// (src/voronoi.rs) and in the hole parity of peeling (tests
/// `merged_face_position_does_not_depend_on_the_input_order`,
/// `peeled_medial_axis_of_rotated_grids_does_not_depend_on_the_input_order`
/// and `medial_axis_of_noisy_chains_does_not_depend_on_the_input_order` in
/// tests/fuzz_regressions.rs): when `true`,
/// Voronoi vertex positions are compared within the accuracy of `circumcenter` instead of
/// bitwise, and the peeled medial axis is not compared. Kept as a switch in case another
/// index-dependent choice turns up.
const KNOWN_MERGED_FACE_ORDER_ISSUE: bool = false;

fuzz_target!(|scene: Scene| {
    let points = scene.points(MAX_POINTS);
    // The oracles check the paper's WDM_MAT and peeling, without the detour repair (which
    // swaps first-pass edges; its invariants are checked in the pipeline's tests), without
    // the open-curve stage (which reads the flow's result) and without thinning (which
    // reconstructs other points); the default, all included, is checked under permutation
    // and for points on three edges.
    let raw = Options::new()
        .with_medial_axis(MedialAxisMode::Raw)
        .with_detour_repair(false)
        .with_open_curves(false)
        .with_thinning(false);
    let single_options = raw.with_peeling(false);
    let single = reconstruct_with(&points, &single_options);
    let full = reconstruct_with(&points, &raw);
    let (single, full) = match (single, full, expected_error(&points)) {
        (Err(a), Err(b), Some(x)) => {
            if !same_error(&a, &x) || !same_error(&b, &x) {
                fail(
                    "reconstruct",
                    &points,
                    &format!("errors {a:?}, {b:?}, expected {x:?}"),
                );
            }
            return;
        }
        (Ok(single), Ok(full), None) => (single, full),
        (a, b, x) => fail(
            "reconstruct",
            &points,
            &format!(
                "results {:?} / {:?}, expected error {x:?}",
                a.err(),
                b.err()
            ),
        ),
    };
    if let Err(e) = check_single_pass(&points, &single) {
        fail("reconstruct (single pass)", &points, &e);
    }
    if let Err(e) = check_peeled(&points, &single, &full) {
        fail("reconstruct (peeling)", &points, &e);
    }
    let pruned = match wdm_crust::reconstruct(&points) {
        Ok(rec) => rec,
        Err(e) => fail("reconstruct (pruned axis)", &points, &format!("{e}")),
    };
    if let Err(e) = check_default(&points, &pruned) {
        fail("reconstruct (default)", &points, &e);
    }
    // Without the axis, everything else is the default's.
    let curves_only = Options::new().with_medial_axis(MedialAxisMode::Omitted);
    match reconstruct_with(&points, &curves_only) {
        Ok(rec) => {
            let same = rec.labels() == pruned.labels()
                && rec.edges() == pruned.edges()
                && rec.curves() == pruned.curves()
                && rec.unassigned() == pruned.unassigned()
                && rec.passes() == pruned.passes()
                && rec.medial_axis().edges.is_empty()
                && rec.medial_axis().vertices.is_empty();
            if !same {
                fail(
                    "reconstruct (no medial axis)",
                    &points,
                    "differs from the default beyond its empty axis",
                );
            }
        }
        Err(e) => fail("reconstruct (no medial axis)", &points, &format!("{e}")),
    }
    let perm = permutation(points.len(), scene.order);
    let shuffled = permute(&points, &perm);
    for (options, rec, what) in [
        (single_options, &single, "single pass"),
        (raw, &full, "peeling"),
        (Options::default(), &pruned, "pruned axis"),
    ] {
        let strict = !KNOWN_MERGED_FACE_ORDER_ISSUE;
        let axis = strict || !options.peeling();
        match reconstruct_with(&shuffled, &options) {
            Ok(other) => {
                if let Err(e) = check_permuted(&points, &perm, rec, &other, strict, axis) {
                    fail(
                        &format!("reconstruct ({what}) under permutation"),
                        &points,
                        &format!("{e}\npermutation: {perm:?}"),
                    );
                }
            }
            Err(e) => fail("reconstruct (permuted)", &points, &format!("{e}")),
        }
    }
});
