//! The engine's errors as Python exceptions.

use pyo3::exceptions::PyValueError;
use pyo3::PyErr;

/// `ValueError` with the engine's message, which names the offending point's index
/// ("point 3: coordinate NaN is not a finite number").
pub fn engine_error(error: wdm_crust::Error) -> PyErr {
    PyValueError::new_err(error.to_string())
}
