//! The `threads=N` keyword: the size of the worker pool a call runs in, as the command
//! line's `--threads N`. Results do not depend on it, only the wall time does.

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::PyResult;

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
