//! Result arrays: engine indices (u32) as int64 rows, coordinates as float64 rows.

use numpy::ndarray::Array2;
use numpy::{Element, IntoPyArray, PyArray1, PyArray2};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// Index rows (`[i, j]`, `[a, b, c]`, ...) as int64, computed without the GIL.
pub fn index_rows<const N: usize>(rows: &[[u32; N]]) -> Vec<[i64; N]> {
    rows.iter().map(|row| row.map(i64::from)).collect()
}

/// Indices as int64.
pub fn indices(values: impl IntoIterator<Item = u32>) -> Vec<i64> {
    values.into_iter().map(i64::from).collect()
}

/// An (m, N) numpy array that takes over `rows` without a copy.
pub fn rows_array<'py, T: Element, const N: usize>(
    py: Python<'py>,
    rows: Vec<[T; N]>,
) -> PyResult<Bound<'py, PyArray2<T>>> {
    let m = rows.len();
    let array = Array2::from_shape_vec((m, N), rows.into_flattened()).map_err(|e| {
        PyRuntimeError::new_err(format!("internal: result of shape ({m}, {N}): {e}"))
    })?;
    Ok(array.into_pyarray(py))
}

/// A one-dimensional numpy array that takes over `values` without a copy.
pub fn vector<'py, T: Element>(py: Python<'py>, values: Vec<T>) -> Bound<'py, PyArray1<T>> {
    values.into_pyarray(py)
}
