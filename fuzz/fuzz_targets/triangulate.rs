//! `triangulate` never panics; its result is the right error or a valid Delaunay
//! triangulation with every duplicate reported against its first occurrence; exact scaling by
//! a power of two changes nothing; the Voronoi dual is consistent both ways, exactly.
#![no_main]

use libfuzzer_sys::fuzz_target;
use wdm_crust_fuzz::checks::{check_same_triangulation, check_triangulate, check_voronoi, scaled};
use wdm_crust_fuzz::fail;
use wdm_crust_fuzz::scene::Scene;

/// Large enough for deep recursion and long merges, small enough for many runs per second.
const MAX_POINTS: usize = 1500;

fuzz_target!(|scene: Scene| {
    let points = scene.points(MAX_POINTS);
    let result = wdm_crust::triangulate(&points);
    if let Err(e) = check_triangulate(&points, &result) {
        fail("triangulate", &points, &e);
    }
    let Ok(tri) = result else { return };
    if let Err(e) = check_voronoi(&tri.voronoi()) {
        fail("voronoi", &points, &e);
    }
    // Sorting and exact predicates are invariant under scaling by 2^k, anywhere in the
    // f64 range.
    let k = (scene.order % 2045) as i32 - 1022;
    if let Some(moved) = scaled(&points, k) {
        match wdm_crust::triangulate(&moved) {
            Ok(other) => {
                if let Err(e) = check_same_triangulation(&tri, &other) {
                    fail(
                        "triangulate scaled by 2^k",
                        &points,
                        &format!("k = {k}: {e}"),
                    );
                }
            }
            Err(e) => fail("triangulate scaled", &points, &format!("k = {k}: {e}")),
        }
    }
});
