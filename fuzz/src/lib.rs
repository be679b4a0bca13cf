//! Shared code of the wdm-crust fuzz targets: structured inputs ([`scene`]) and exact
//! oracles ([`checks`], also used by `tests/fuzz_regressions.rs`).

pub mod checks;
pub mod scene;

/// Panics with the points pasted as a Rust literal, ready for `tests/fuzz_regressions.rs`.
pub fn fail(what: &str, points: &[[f64; 2]], message: &str) -> ! {
    panic!(
        "{what} failed: {message}\nreproducer points ({} of them):\n{points:?}",
        points.len()
    );
}
