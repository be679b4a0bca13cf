//! The `threads=N` keyword: the size of the worker pool a call runs in, as the command
//! line's `--threads N`. Results do not depend on it, only the wall time does.

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use crate::errors::engine_error;
use crate::points::with_points;

/// The pool of `threads` workers, or `None` (rayon's global pool: all cores, or
/// `RAYON_NUM_THREADS`) when no number is given.
pub fn pool(threads: Option<i64>) -> PyResult<Option<rayon::ThreadPool>> {
    let Some(count) = threads else {
        return Ok(None);
    };
    // rayon reads 0 as "the default": refused, as on the command line.
    let count = usize::try_from(count)
        .ok()
        .filter(|&n| n >= 1)
        .ok_or_else(|| {
            PyValueError::new_err(format!(
                "threads must be a whole number of at least 1, got {count}"
            ))
        })?;
    rayon::ThreadPoolBuilder::new()
        .num_threads(count)
        .build()
        .map(Some)
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start {count} threads: {e}")))
}

/// Runs `job` in `pool`, or in rayon's global pool.
pub fn run_in<T: Send>(pool: Option<&rayon::ThreadPool>, job: impl FnOnce() -> T + Send) -> T {
    match pool {
        Some(pool) => pool.install(job),
        None => job(),
    }
}

/// Runs the engine's `job` on the points of `points` (see [`with_points`]) without the GIL,
/// in the pool of `threads` workers; an engine error becomes a `ValueError`.
pub fn on_points<R: Send>(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    threads: Option<i64>,
    job: impl FnOnce(&[[f64; 2]]) -> Result<R, wdm_crust::Error> + Send,
) -> PyResult<R> {
    let pool = pool(threads)?;
    with_points(points, |points| {
        py.detach(|| run_in(pool.as_ref(), || job(points)))
            .map_err(engine_error)
    })
}
