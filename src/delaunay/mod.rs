//! Delaunay triangulation: Guibas–Stolfi divide and conquer with Dwyer's alternating cuts.
//!
//! The pipeline is `validate → Z-order and merge duplicates → divide and conquer → compact`.
//! The construction store (`mesh`: triangles plus ghost triangles on the hull) exists only
//! while the triangulation is built and turns into the compact, flat [`Triangulation`] in
//! place; that is all later stages see.
//!
//! The points are renamed once, on the way in: the Z order (distinct points only,
//! duplicates merged into their first occurrence) is the construction's and also the
//! locality order every later pass wants, so the [`Triangulation`] keeps its topology in
//! those *local* indices together with the translation from and to the caller's indices.
//! The crate works on local indices throughout; the public API translates at the boundary,
//! and a reconstruction translates its edges once, at the end.

mod divide_conquer;
pub mod locate;
mod mesh;
mod triangulation;
mod validate;
mod zorder;

pub use crate::ids::{HalfEdge, TriangleId};
pub use locate::{Location, Locator};
pub use triangulation::{Triangulation, NO_TWIN};
pub use validate::ValidationError;

use crate::error::{scan_points, Error};

/// Exact Delaunay triangulation of `points`.
///
/// Every combinatorial decision uses exact predicates. Duplicated points are merged into
/// their first occurrence and reported by [`Triangulation::duplicates`]; no point is dropped.
/// With fewer than three distinct points, or all of them on one line, there are no triangles
/// and the hull is the chain of points along the line.
///
/// Every finite coordinate is accepted, subnormals and values near `f64::MAX` included, and
/// the result is exact for all of them: input whose magnitudes lie outside the adaptive
/// predicates' range (non-zero magnitudes 2^-142 ..= 2^201) is
/// triangulated on a copy scaled by a power of two (exact, and the triangles are the same),
/// or, where no single power of two brings all of it into that range (`1e-300` beside
/// `1e300`), with predicates that fall back to wide-exponent integer arithmetic. The
/// triangulation keeps the caller's coordinates.
///
/// # Errors
/// A coordinate that is NaN or infinite gives [`Error::NotFinite`] naming the point; more
/// than [`crate::error::MAX_POINTS`] points (715 827 882: the 32-bit indices) give
/// [`Error::TooManyPoints`].
///
/// ```
/// let points = [[0.0, 0.0], [4.0, 0.0], [0.0, 3.0], [4.0, 3.0], [0.0, 0.0]];
/// let tri = wdm_crust::triangulate(&points)?;
/// assert_eq!(tri.triangles().len(), 2);
/// assert_eq!(tri.hull().collect::<Vec<u32>>(), [0, 1, 3, 2]);
/// assert_eq!(tri.duplicates(), &[[4, 0]]);
/// tri.validate().expect("a Delaunay triangulation");
/// # Ok::<(), wdm_crust::Error>(())
/// ```
pub fn triangulate(points: &[[f64; 2]]) -> Result<Triangulation, Error> {
    let magnitudes = scan_points(points)?;
    Ok(divide_conquer::build(points, magnitudes.adaptive_shift()))
}
