//! `wdm_crust.read_points`: a point file read by the command line's parser, with its
//! messages.

use std::fs::File;
use std::io::{self, BufReader};
use std::path::PathBuf;

use numpy::PyArray2;
use pyo3::exceptions::{
    PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyPermissionError, PyValueError,
};
use pyo3::prelude::*;
use pyo3::types::PyString;
use wdm_crust::io::{
    format_from_path, read_points_with, ColumnSelection, ParseError, ParseErrorKind, ReadOptions,
};

use crate::arrays::rows_array;

/// The points of a point file, read as the command line reads its INPUT.
///
/// Args:
///     path: the file (str or os.PathLike). Plain text (two numbers a line, separated by
///         white space and/or one comma; more columns ignored; blank lines and `#`
///         comments skipped), CSV with an optional header, or Triangle `.node` / Dey `.gtn`;
///         detected from the content, or by the extension (.csv, .node, .gtn).
///     columns: the columns to read as x and y, as the command line's --columns: a string
///         "X,Y" or a pair; each a header name (any case) or a 1-based position. None (the
///         default): a header picks x,y, lon,lat (lng, long or longitude with lat or
///         latitude) or easting,northing, else the first two columns.
///
/// Returns:
///     (n, 2) float64 array, one row per point in file order (point i is the i-th read).
///
/// Raises:
///     ValueError: the file is no point file, or a line is not a point: the command line's
///         message, "<path>:<line>: <problem>" (the path as given).
///     FileNotFoundError, PermissionError, IsADirectoryError, OSError: the file cannot be
///         opened or read ("<path>: cannot open: ...").
///
/// The GIL is released while the file is read.
#[pyfunction]
#[pyo3(signature = (path, columns = None))]
pub fn read_points<'py>(
    py: Python<'py>,
    path: PathBuf,
    columns: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let mut options = ReadOptions::new();
    if let Some(columns) = columns {
        options = options.with_columns(column_selection(columns)?);
    }
    let name = path.display().to_string();
    if path.is_dir() {
        return Err(PyIsADirectoryError::new_err(format!(
            "{name}: is a directory, not a point file"
        )));
    }
    if let Some(format) = format_from_path(&path) {
        options = options.with_format(format);
    }
    let points = py.detach(|| {
        let file =
            File::open(&path).map_err(|e| os_error(&e, format!("{name}: cannot open: {e}")))?;
        read_points_with(BufReader::with_capacity(1 << 16, file), &options)
            .map_err(|e| parse_error(&name, &e))
    })?;
    rows_array(py, points)
}

/// `columns` as a [`ColumnSelection`]: "X,Y", or a pair of names or 1-based positions.
fn column_selection(columns: &Bound<'_, PyAny>) -> PyResult<ColumnSelection> {
    let text = if let Ok(text) = columns.cast::<PyString>() {
        text.extract::<String>()?
    } else {
        let pair: Vec<Bound<'_, PyAny>> = columns.extract().map_err(|_| {
            PyValueError::new_err("columns must be a string \"X,Y\" or a pair (x, y) of column names or 1-based positions")
        })?;
        if pair.len() != 2 {
            return Err(PyValueError::new_err(format!(
                "columns must name two columns, x and y; got {}",
                pair.len()
            )));
        }
        let names = pair
            .iter()
            .map(|c| c.str()?.extract::<String>())
            .collect::<PyResult<Vec<String>>>()?;
        names.join(",")
    };
    text.parse()
        .map_err(|e| PyValueError::new_err(format!("columns: {e}")))
}

/// The command line's message for a file that cannot be read as points:
/// `<path>:<line>: <problem>`, an `OSError` for a failing read.
fn parse_error(name: &str, e: &ParseError) -> PyErr {
    let message = match e.line {
        Some(line) => format!("{name}:{line}: {}", e.kind),
        None => format!("{name}: {}", e.kind),
    };
    match &e.kind {
        ParseErrorKind::Io(io) => os_error(io, message),
        _ => PyValueError::new_err(message),
    }
}

/// The `OSError` subclass Python raises for this kind of error, with `message`.
fn os_error(e: &io::Error, message: String) -> PyErr {
    match e.kind() {
        io::ErrorKind::NotFound => PyFileNotFoundError::new_err(message),
        io::ErrorKind::PermissionDenied => PyPermissionError::new_err(message),
        _ => PyOSError::new_err(message),
    }
}
