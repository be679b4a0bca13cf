//! `wdm_crust.orient2d` and `wdm_crust.incircle`: the engine's exact predicates on single
//! points, as -1, 0 or +1.

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use wdm_crust::predicates::{CirclePosition, Orientation};

/// The point `value`, given as the argument `name` of `function`: two coordinates the engine
/// accepts (`check_coordinate`: finite, and inside the range its exact predicates support).
fn point_arg(function: &str, name: &str, value: &Bound<'_, PyAny>) -> PyResult<[f64; 2]> {
    let point: [f64; 2] = value.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "{function}: {name} must be a point (x, y) of two real numbers"
        ))
    })?;
    for coordinate in point {
        if let Err(e) = wdm_crust::error::check_coordinate(0, coordinate) {
            // The engine's message starts "point 0: "; here the point has a name.
            let message = e.to_string();
            let reason = message
                .split_once(": ")
                .map_or(message.as_str(), |(_, r)| r);
            return Err(PyValueError::new_err(format!(
                "{function}: {name}: {reason}"
            )));
        }
    }
    Ok(point)
}

/// Exact orientation of the triple a → b → c.
///
/// Args:
///     a, b, c: points (x, y), any two-element sequence of real numbers.
///
/// Returns:
///     +1 if c lies left of the directed line a → b (counterclockwise), -1 if right
///     (clockwise), 0 if the three points are collinear; the sign of the exact determinant
///     of the float64 values, never rounded.
///
/// Raises:
///     ValueError: the engine refuses a coordinate (NaN, infinite, or outside the range
///         its exact predicates support); the message names the argument.
///     TypeError: an argument is not a point of two real numbers.
#[pyfunction]
pub fn orient2d(a: &Bound<'_, PyAny>, b: &Bound<'_, PyAny>, c: &Bound<'_, PyAny>) -> PyResult<i32> {
    let [a, b, c] = [("a", a), ("b", b), ("c", c)].map(|(n, v)| point_arg("orient2d", n, v));
    Ok(match wdm_crust::predicates::orient2d(a?, b?, c?) {
        Orientation::CounterClockwise => 1,
        Orientation::Clockwise => -1,
        Orientation::Collinear => 0,
    })
}

/// Exact position of d relative to the circle through a, b, c.
///
/// Args:
///     a, b, c: the circle's points, counterclockwise; d: the point tested. Each any
///         two-element sequence of real numbers.
///
/// Returns:
///     +1 if d is strictly inside the circle, 0 if exactly on it, -1 if outside. If a, b, c
///     are clockwise the answer is mirrored (the sign of the exact in-circle determinant);
///     if they are collinear it tells on which side of their line d lies.
///
/// Raises:
///     ValueError: as `orient2d`.
///     TypeError: an argument is not a point of two real numbers.
#[pyfunction]
pub fn incircle(
    a: &Bound<'_, PyAny>,
    b: &Bound<'_, PyAny>,
    c: &Bound<'_, PyAny>,
    d: &Bound<'_, PyAny>,
) -> PyResult<i32> {
    let [a, b, c, d] =
        [("a", a), ("b", b), ("c", c), ("d", d)].map(|(n, v)| point_arg("incircle", n, v));
    Ok(match wdm_crust::predicates::incircle(a?, b?, c?, d?) {
        CirclePosition::Inside => 1,
        CirclePosition::Outside => -1,
        CirclePosition::On => 0,
    })
}
