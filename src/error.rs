//! The one error type of the library.
//!
//! Every finite `f64` coordinate is accepted: the predicates are exact on all of them (see
//! the crate docs, "Exactness"). Only NaN, infinities and more points than 32-bit indices
//! address are refused.

use std::fmt;

use crate::kernel::scale::Magnitudes;

/// The most points one call accepts: `(2^32 − 4) / 6`, 715 827 882.
///
/// Points, triangles and half-edges are numbered with `u32` (half the memory of `usize`
/// indices, and the store's speed). The construction's store holds `2n − 2` triangles, ghosts
/// included, so `6n − 6` half-edges, and `u32::MAX` is reserved ("no twin", "no vertex"):
/// every half-edge index stays below it up to this count. Larger input is refused with
/// [`Error::TooManyPoints`] before anything is allocated; it never wraps around.
pub const MAX_POINTS: usize = 715_827_882;

/// Everything that can go wrong in the library. No public function panics instead.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A coordinate is NaN or infinite.
    NotFinite {
        /// Index of the point in the caller's slice.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// The input has more than [`MAX_POINTS`] points, more than the 32-bit indices used
    /// internally can address.
    TooManyPoints {
        /// Number of points given.
        count: usize,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NotFinite { index, value } => {
                write!(
                    f,
                    "point {index}: coordinate {value} is not a finite number"
                )
            }
            Error::TooManyPoints { count } => write!(
                f,
                "{count} points are more than the {MAX_POINTS} one run supports (32-bit indices)"
            ),
        }
    }
}

impl std::error::Error for Error {}

/// Checks one coordinate: every finite value is accepted, NaN and infinities are
/// [`Error::NotFinite`].
pub fn check_coordinate(index: usize, value: f64) -> Result<(), Error> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::NotFinite { index, value })
    }
}

/// Checks that `count` points fit the 32-bit indices: at most [`MAX_POINTS`].
pub(crate) fn check_count(count: usize) -> Result<(), Error> {
    if count > MAX_POINTS {
        Err(Error::TooManyPoints { count })
    } else {
        Ok(())
    }
}

/// Checks every coordinate of every point; the first failure names its point.
pub fn check_points(points: &[[f64; 2]]) -> Result<(), Error> {
    scan_points(points).map(|_| ())
}

/// [`check_points`], and the magnitudes of the coordinates: whether and how the
/// construction rescales them.
pub(crate) fn scan_points(points: &[[f64; 2]]) -> Result<Magnitudes, Error> {
    check_count(points.len())?;
    let mut magnitudes = Magnitudes::NONE;
    for (index, p) in points.iter().enumerate() {
        check_coordinate(index, p[0])?;
        check_coordinate(index, p[1])?;
        magnitudes.include(p[0]);
        magnitudes.include(p[1]);
    }
    Ok(magnitudes)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest count leaves the number of half-edges of the store (ghosts included),
    /// and so every index, below the reserved `u32::MAX`; one more point is refused with a
    /// message naming the limit.
    #[test]
    fn the_point_limit_is_the_index_width() {
        let half_edges = |n: usize| 3 * (2 * n - 2);
        assert_eq!(6 * MAX_POINTS, (1usize << 32) - 4);
        assert!(half_edges(MAX_POINTS) < u32::MAX as usize);
        assert_eq!(check_count(MAX_POINTS), Ok(()));
        let err = check_count(MAX_POINTS + 1).unwrap_err();
        assert_eq!(
            err,
            Error::TooManyPoints {
                count: MAX_POINTS + 1
            }
        );
        assert!(err.to_string().contains("715827882"), "{err}");
    }

    #[test]
    fn every_finite_coordinate_is_accepted() {
        for x in [
            0.0,
            -0.0,
            f64::from_bits(1),
            -f64::MIN_POSITIVE,
            // Outside the adaptive predicates' range, 2^-142 ..= 2^201.
            2f64.powi(-143),
            2f64.powi(202),
            f64::MAX,
            f64::MIN,
        ] {
            assert_eq!(check_coordinate(7, x), Ok(()), "{x:e}");
        }
        assert!(matches!(
            check_coordinate(5, f64::NAN),
            Err(Error::NotFinite { index: 5, .. })
        ));
        assert!(matches!(
            check_coordinate(6, f64::NEG_INFINITY),
            Err(Error::NotFinite { index: 6, .. })
        ));
    }

    #[test]
    fn first_bad_point_is_named() {
        let pts = [
            [0.0, 0.0],
            [1.0, 2.0],
            [f64::NAN, 0.0],
            [f64::INFINITY, 1.0],
        ];
        assert!(matches!(
            check_points(&pts),
            Err(Error::NotFinite { index: 2, .. })
        ));
    }
}
