//! `wdm_crust` for Python: the exact Delaunay triangulation, Voronoi diagram, curve
//! reconstruction (WDM_CRUST, crust, NN-crust) and medial axis of the `wdm-crust` engine, on
//! numpy arrays.
//!
//! This is the extension module `wdm_crust._native`; the package `wdm_crust` (in
//! `package/wdm_crust/`) re-exports all of it and adds the pure-Python `plot`.
//!
//! One module per job: [`points`] turns any (n, 2) array-like into the engine's
//! `&[[f64; 2]]` (a view of a C-contiguous float64 array, no copy), [`arrays`] builds the
//! result arrays, [`errors`] maps the engine's errors to `ValueError`, [`pool`] is the
//! `threads=N` keyword, and one module per entry point ([`triangulation`], [`voronoi`],
//! [`reconstruction`], [`predicates`], [`files`]). Every engine call runs with the GIL
//! released.
#![forbid(unsafe_code)]

mod arrays;
mod errors;
mod files;
mod points;
mod pool;
mod predicates;
mod reconstruction;
mod triangulation;
mod voronoi;

use pyo3::prelude::*;

/// The module's public names.
const PUBLIC_NAMES: [&str; 12] = [
    "__version__",
    "triangulate",
    "voronoi",
    "reconstruct",
    "read_points",
    "orient2d",
    "incircle",
    "Triangulation",
    "Voronoi",
    "Reconstruction",
    "Curve",
    "Polygon",
];

/// Exact 2D Delaunay triangulation, Voronoi diagram, curve reconstruction (WDM_CRUST) and
/// medial axis for numpy arrays of points.
///
/// Points are any (n, 2) array-like of real numbers: a C-contiguous float64 array is read
/// in place (no copy); other float or integer arrays, and lists, are converted to float64
/// first. Every index in a result is a row of that array; index arrays are int64.
/// Every combinatorial decision is the one exact arithmetic on the float64 inputs makes.
#[pymodule]
#[pyo3(name = "_native")]
fn wdm_crust_python(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add("__version__", env!("CARGO_PKG_VERSION"))?;
    module.add_function(wrap_pyfunction!(triangulation::triangulate, module)?)?;
    module.add_function(wrap_pyfunction!(voronoi::voronoi, module)?)?;
    module.add_function(wrap_pyfunction!(reconstruction::reconstruct, module)?)?;
    module.add_function(wrap_pyfunction!(files::read_points, module)?)?;
    module.add_function(wrap_pyfunction!(predicates::orient2d, module)?)?;
    module.add_function(wrap_pyfunction!(predicates::incircle, module)?)?;
    module.add_class::<triangulation::Triangulation>()?;
    module.add_class::<voronoi::Voronoi>()?;
    module.add_class::<reconstruction::Reconstruction>()?;
    module.add_class::<reconstruction::Curve>()?;
    module.add_class::<reconstruction::Polygon>()?;
    // What the package's `from ._native import *` takes, __version__ included.
    module.add("__all__", PUBLIC_NAMES)?;
    Ok(())
}
