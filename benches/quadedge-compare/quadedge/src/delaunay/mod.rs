//! Delaunay triangulation: Guibas–Stolfi divide and conquer on a quad-edge store.
//!
//! The pipeline is `validate → sort and merge duplicates → divide and conquer → compact`.
//! The quad-edge store ([`quadedge`]) exists only while the triangulation is built; the
//! result is the compact, flat [`Triangulation`], which is all that later stages see.

mod divide_conquer;
mod quadedge;
mod triangulation;
mod validate;

pub use triangulation::{Triangulation, NO_TWIN};
pub use validate::ValidationError;

use crate::error::{check_points, Error};

/// Exact Delaunay triangulation of `points`.
///
/// Every combinatorial decision uses exact predicates. Duplicated points are merged into
/// their first occurrence and reported by [`Triangulation::duplicates`]; no point is dropped.
/// With fewer than three distinct points, or all of them on one line, there are no triangles
/// and the hull is the chain of points along the line.
///
/// # Errors
/// A coordinate that is NaN, infinite or outside the exact envelope (see [`crate::error`])
/// gives an [`Error`] naming the point.
///
/// ```
/// let points = [[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [4.0, 3.0], [0.0, 0.0]];
/// let tri = wdm_crust_quadedge::triangulate(&points)?;
/// assert_eq!(tri.triangles().len(), 2);
/// assert_eq!(tri.duplicates(), &[[4, 0]]);
/// tri.validate().expect("a Delaunay triangulation");
/// # Ok::<(), wdm_crust_quadedge::Error>(())
/// ```
pub fn triangulate(points: &[[f64; 2]]) -> Result<Triangulation, Error> {
    check_points(points)?;
    Ok(divide_conquer::build(points))
}
