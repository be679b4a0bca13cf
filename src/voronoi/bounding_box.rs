//! The axis-aligned box that Voronoi cells are clipped to.

use std::fmt;

/// A closed axis-aligned box `[min[0], max[0]] × [min[1], max[1]]` with finite corners and
/// positive width and height.
///
/// ```
/// use wdm_crust::BoundingBox;
/// let b = BoundingBox::new([0.0, -1.0], [4.0, 1.0])?;
/// assert_eq!(b.area(), 8.0);
/// // The default clipping box: the points' bounds enlarged by 10 % of the larger side.
/// let b = BoundingBox::around(&[[0.0, 0.0], [10.0, 5.0]]).unwrap();
/// assert_eq!((b.min(), b.max()), ([-1.0, -1.0], [11.0, 6.0]));
/// assert!(BoundingBox::new([0.0, 0.0], [0.0, 1.0]).is_err());
/// # Ok::<(), wdm_crust::BoxError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundingBox {
    min: [f64; 2],
    max: [f64; 2],
}

/// Why [`BoundingBox::new`] refused its corners.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum BoxError {
    /// A coordinate is NaN or infinite.
    NotFinite {
        /// The offending value.
        value: f64,
    },
    /// The box has no interior: `min[axis] >= max[axis]`.
    Empty {
        /// 0 for `x`, 1 for `y`.
        axis: usize,
        /// `min[axis]`.
        min: f64,
        /// `max[axis]`.
        max: f64,
    },
}

impl fmt::Display for BoxError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BoxError::NotFinite { value } => {
                write!(f, "box coordinate {value} is not a finite number")
            }
            BoxError::Empty { axis, min, max } => {
                let name = ["x", "y"][usize::from(*axis != 0)];
                write!(
                    f,
                    "box has no interior: {name}min = {min} is not below {name}max = {max}"
                )
            }
        }
    }
}

impl std::error::Error for BoxError {}

impl BoundingBox {
    /// The box with lower-left corner `min` and upper-right corner `max`.
    ///
    /// # Errors
    /// [`BoxError::NotFinite`] for a NaN or infinite coordinate, [`BoxError::Empty`] unless
    /// `min` is strictly below `max` in both coordinates.
    pub fn new(min: [f64; 2], max: [f64; 2]) -> Result<BoundingBox, BoxError> {
        if let Some(&value) = min.iter().chain(&max).find(|c| !c.is_finite()) {
            return Err(BoxError::NotFinite { value });
        }
        for axis in 0..2 {
            if min[axis] >= max[axis] {
                return Err(BoxError::Empty {
                    axis,
                    min: min[axis],
                    max: max[axis],
                });
            }
        }
        Ok(BoundingBox { min, max })
    }

    /// The default clipping box of `points`: their bounding box enlarged on every side by
    /// 10 % of its larger side. If all points coincide, by 10 % of their larger coordinate
    /// magnitude, or by 1 at the origin. Where the margin is lost to rounding (a side far
    /// smaller than the coordinates) the bounds step to the neighbouring `f64`, so the box
    /// always has an interior and contains every point strictly inside. `None` for no points,
    /// a non-finite coordinate, or bounds that would overflow.
    pub fn around(points: &[[f64; 2]]) -> Option<BoundingBox> {
        let first = *points.first()?;
        let (mut min, mut max) = (first, first);
        for p in points {
            for axis in 0..2 {
                if !p[axis].is_finite() {
                    return None;
                }
                min[axis] = min[axis].min(p[axis]);
                max[axis] = max[axis].max(p[axis]);
            }
        }
        let side = (max[0] - min[0]).max(max[1] - min[1]);
        let margin = if side > 0.0 {
            0.1 * side
        } else {
            let magnitude = first[0].abs().max(first[1].abs());
            if magnitude > 0.0 {
                0.1 * magnitude
            } else {
                1.0
            }
        };
        for axis in 0..2 {
            let (lo, hi) = (min[axis] - margin, max[axis] + margin);
            min[axis] = if lo < min[axis] {
                lo
            } else {
                next_down(min[axis])
            };
            max[axis] = if hi > max[axis] {
                hi
            } else {
                next_up(max[axis])
            };
        }
        BoundingBox::new(min, max).ok()
    }

    /// The lower-left corner.
    pub fn min(&self) -> [f64; 2] {
        self.min
    }

    /// The upper-right corner.
    pub fn max(&self) -> [f64; 2] {
        self.max
    }

    /// Width times height (rounded; infinite if it overflows).
    pub fn area(&self) -> f64 {
        (self.max[0] - self.min[0]) * (self.max[1] - self.min[1])
    }

    /// Whether `p` lies in the closed box.
    pub fn contains(&self, p: [f64; 2]) -> bool {
        (0..2).all(|axis| self.min[axis] <= p[axis] && p[axis] <= self.max[axis])
    }

    /// The four corners counterclockwise from `min`.
    pub(crate) fn corners(&self) -> [[f64; 2]; 4] {
        let (a, b) = (self.min, self.max);
        [a, [b[0], a[1]], b, [a[0], b[1]]]
    }
}

/// The next `f64` above a finite `x`.
fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let bits = x.to_bits();
    f64::from_bits(if x > 0.0 { bits + 1 } else { bits - 1 })
}

/// The next `f64` below a finite `x`.
fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn around_always_has_an_interior_and_contains_the_points() {
        let cases: [&[[f64; 2]]; 6] = [
            &[[3.0, 4.0]],
            &[[0.0, 0.0]],
            &[[0.0, 0.0], [0.0, 0.0]],
            &[[1e300, 0.0], [1e300, 1e-300]],
            &[[-5.0, 2.0], [5.0, 2.0]],
            &[[-1e-310, 7.0], [0.0, 7.0]],
        ];
        for points in cases {
            let b = BoundingBox::around(points).unwrap();
            for axis in 0..2 {
                assert!(b.min()[axis] < b.max()[axis], "{points:?}");
            }
            for p in points {
                assert!((0..2).all(|a| b.min()[a] < p[a] && p[a] < b.max()[a]));
            }
        }
        assert_eq!(BoundingBox::around(&[]), None);
        assert_eq!(BoundingBox::around(&[[f64::NAN, 0.0]]), None);
        assert_eq!(
            BoundingBox::around(&[[f64::MAX, 0.0], [-f64::MAX, 0.0]]),
            None
        );
    }

    #[test]
    fn new_names_the_problem() {
        assert_eq!(
            BoundingBox::new([0.0, f64::NAN], [1.0, 1.0]).map_err(|e| e.to_string()),
            Err("box coordinate NaN is not a finite number".to_string())
        );
        assert_eq!(
            BoundingBox::new([0.0, 2.0], [1.0, 1.0]).map_err(|e| e.to_string()),
            Err("box has no interior: ymin = 2 is not below ymax = 1".to_string())
        );
    }
}
