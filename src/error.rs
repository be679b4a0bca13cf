//! The one error type of the library.

use std::fmt;

/// Smallest non-zero coordinate magnitude accepted: 2^-142.
///
/// Below it the adaptive predicates could underflow and lose exactness.
pub const MIN_MAGNITUDE: f64 = 1.793662034335766e-43; // 2^-142
/// Largest coordinate magnitude accepted: 2^201.
///
/// Above it the adaptive predicates could overflow.
pub const MAX_MAGNITUDE: f64 = 3.2138760885179806e60; // 2^201

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
    /// A non-zero coordinate is smaller in magnitude than [`MIN_MAGNITUDE`].
    TooSmall {
        /// Index of the point in the caller's slice.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// A coordinate is larger in magnitude than [`MAX_MAGNITUDE`].
    TooLarge {
        /// Index of the point in the caller's slice.
        index: usize,
        /// The offending value.
        value: f64,
    },
    /// The input has more points than the 32-bit indices used internally can address.
    TooManyPoints {
        /// Number of points given.
        count: usize,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::NotFinite { index, value } => {
                write!(f, "point {index}: coordinate {value} is not a finite number")
            }
            Error::TooSmall { index, value } => write!(
                f,
                "point {index}: coordinate {value:e} is non-zero but below 2^-142, where exact predicates could underflow"
            ),
            Error::TooLarge { index, value } => write!(
                f,
                "point {index}: coordinate {value:e} is above 2^201, where exact predicates could overflow"
            ),
            Error::TooManyPoints { count } => {
                write!(f, "{count} points are more than the 2^32 - 2 supported")
            }
        }
    }
}

impl std::error::Error for Error {}

/// Checks one coordinate against the exact envelope: finite and zero or within
/// [`MIN_MAGNITUDE`]..=[`MAX_MAGNITUDE`] in magnitude.
pub fn check_coordinate(index: usize, value: f64) -> Result<(), Error> {
    if !value.is_finite() {
        return Err(Error::NotFinite { index, value });
    }
    let magnitude = value.abs();
    if magnitude != 0.0 && magnitude < MIN_MAGNITUDE {
        return Err(Error::TooSmall { index, value });
    }
    if magnitude > MAX_MAGNITUDE {
        return Err(Error::TooLarge { index, value });
    }
    Ok(())
}

/// Checks every coordinate of every point; the first failure names its point.
pub fn check_points(points: &[[f64; 2]]) -> Result<(), Error> {
    if points.len() > (u32::MAX - 1) as usize {
        return Err(Error::TooManyPoints {
            count: points.len(),
        });
    }
    for (index, p) in points.iter().enumerate() {
        check_coordinate(index, p[0])?;
        check_coordinate(index, p[1])?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn envelope_constants_are_the_powers_of_two() {
        assert_eq!(MIN_MAGNITUDE, 2f64.powi(-142));
        assert_eq!(MAX_MAGNITUDE, 2f64.powi(201));
    }

    #[test]
    fn envelope_boundaries() {
        assert!(check_coordinate(0, 0.0).is_ok());
        assert!(check_coordinate(0, -0.0).is_ok());
        assert!(check_coordinate(0, MIN_MAGNITUDE).is_ok());
        assert!(check_coordinate(0, -MAX_MAGNITUDE).is_ok());
        assert!(matches!(
            check_coordinate(3, MIN_MAGNITUDE / 2.0),
            Err(Error::TooSmall { index: 3, .. })
        ));
        assert!(matches!(
            check_coordinate(4, MAX_MAGNITUDE * 2.0),
            Err(Error::TooLarge { index: 4, .. })
        ));
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
