//! Any (n, 2) array-like of real numbers as the engine's `&[[f64; 2]]`.
//!
//! A C-contiguous float64 array is read in place: its buffer, seen as a flat `&[f64]`, is
//! split into `[x, y]` pairs by `as_chunks` (no copy, no unsafe code here). Anything else
//! goes through `numpy.asarray` and `astype(float64)` once, after its dtype and shape are
//! checked, so that nothing is silently misread (strings, booleans, complex numbers and
//! objects are refused, and so is any shape but (n, 2)).

use numpy::{PyArray2, PyArrayDescrMethods, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

/// Runs `f` on the points of `object`, an (n, 2) array-like of real numbers.
///
/// `f` gets a view of the caller's own buffer when `object` is a C-contiguous float64
/// array, and a converted copy otherwise (other dtypes, lists, strided or Fortran-ordered
/// arrays). While `f` runs, the array is borrowed read-only (rust-numpy's borrow flags).
pub fn with_points<R>(
    object: &Bound<'_, PyAny>,
    f: impl FnOnce(&[[f64; 2]]) -> PyResult<R>,
) -> PyResult<R> {
    with_rows(object, "points", f)
}

/// [`with_points`] for an (m, 2) array-like called `name` in the messages (`"queries"`).
pub fn with_rows<R>(
    object: &Bound<'_, PyAny>,
    name: &str,
    f: impl FnOnce(&[[f64; 2]]) -> PyResult<R>,
) -> PyResult<R> {
    let array = float64_array(object, name)?;
    let readonly = array
        .try_readonly()
        .map_err(|e| PyValueError::new_err(format!("{name}: {e}")))?;
    // `as_slice` also accepts Fortran order, whose memory order is not (x, y) pairs.
    if array.is_c_contiguous() {
        if let Ok(flat) = readonly.as_slice() {
            let (points, _) = flat.as_chunks::<2>();
            return f(points);
        }
    }
    let copied: Vec<[f64; 2]> = readonly
        .as_array()
        .rows()
        .into_iter()
        .map(|row| [row[0], row[1]])
        .collect();
    f(&copied)
}

/// `object` as a float64 array of shape (n, 2): itself if it already is one, else a
/// conversion by numpy.
fn float64_array<'py>(
    object: &Bound<'py, PyAny>,
    name: &str,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    if let Ok(array) = object.cast::<PyArray2<f64>>() {
        check_shape(array.shape(), name)?;
        return Ok(array.clone());
    }
    let numpy = object.py().import("numpy")?;
    let array = match object.cast::<PyUntypedArray>() {
        Ok(array) => array.clone(),
        Err(_) => numpy
            .call_method1("asarray", (object,))?
            .cast_into::<PyUntypedArray>()?,
    };
    let dtype = array.dtype();
    // f: floating point, i/u: integers; not b (bool), c (complex), U/S (text), O (objects).
    if !matches!(dtype.kind(), b'f' | b'i' | b'u') {
        return Err(PyTypeError::new_err(format!(
            "{name} must be real numbers, got an array of dtype {}",
            dtype.str()?
        )));
    }
    check_shape(array.shape(), name)?;
    let converted = array.call_method1("astype", (numpy.getattr("float64")?,))?;
    Ok(converted.cast_into::<PyArray2<f64>>()?)
}

/// Only (n, 2) is accepted: a single point `[x, y]` or rows of three coordinates could be
/// misread, so they are refused with the shape that was given.
fn check_shape(shape: &[usize], name: &str) -> PyResult<()> {
    if let [_, 2] = shape {
        return Ok(());
    }
    let shape = match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    let hint = if shape == "(2,)" {
        " (for a single point, pass [[x, y]])"
    } else {
        ""
    };
    Err(PyValueError::new_err(format!(
        "{name} must be an (n, 2) array, one (x, y) row per point; got shape {shape}{hint}"
    )))
}
