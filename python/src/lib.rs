//! `wdm_crust` for Python: the exact Delaunay triangulation, Voronoi diagram, curve
//! reconstruction (WDM_CRUST, crust, NN-crust) and medial axis of the `wdm-crust` engine, on
//! numpy arrays.
//!
//! One module per job: [`points`] turns any (n, 2) array-like into the engine's
//! `&[[f64; 2]]` (a view of a C-contiguous float64 array, no copy), [`arrays`] builds the
//! result arrays, [`errors`] maps the engine's errors to `ValueError`, and one module per
//! entry point ([`triangulation`], [`voronoi`], [`reconstruction`], [`predicates`]). Every
//! engine call runs with the GIL released.
#![forbid(unsafe_code)]

mod arrays;
mod errors;
mod points;
mod predicates;
mod reconstruction;
mod triangulation;
mod voronoi;

use pyo3::prelude::*;

/// The module's public names.
const PUBLIC_NAMES: [&str; 10] = [
    "__version__",
    "triangulate",
    "voronoi",
    "reconstruct",
    "orient2d",
    "incircle",
    "Triangulation",
    "Voronoi",
    "Reconstruction",
    "Curve",
];

/// Exact 2D Delaunay triangulation, Voronoi diagram, curve reconstruction (WDM_CRUST) and
/// medial axis for numpy arrays of points.
///
/// Points are any (n, 2) array-like of real numbers: a C-contiguous float64 array is read
/// in place (no copy); other float or integer arrays, and lists, are converted to float64
/// first. Every index in a result is a row of that array; index arrays are int64.
/// Every combinatorial decision is the one exact arithmetic on the float64 inputs makes.
#[pymodule]
#[pyo3(name = "wdm_crust")]
fn wdm_crust_python(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add("__version__", env!("CARGO_PKG_VERSION"))?;
    module.add_function(wrap_pyfunction!(triangulation::triangulate, module)?)?;
    module.add_function(wrap_pyfunction!(voronoi::voronoi, module)?)?;
    module.add_function(wrap_pyfunction!(reconstruction::reconstruct, module)?)?;
    module.add_function(wrap_pyfunction!(predicates::orient2d, module)?)?;
    module.add_function(wrap_pyfunction!(predicates::incircle, module)?)?;
    module.add_class::<triangulation::Triangulation>()?;
    module.add_class::<voronoi::Voronoi>()?;
    module.add_class::<reconstruction::Reconstruction>()?;
    module.add_class::<reconstruction::Curve>()?;
    // What `from wdm_crust import *` (and maturin's package __init__) takes, __version__
    // included.
    module.add("__all__", PUBLIC_NAMES)?;
    Ok(())
}
