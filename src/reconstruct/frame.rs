//! The frame a reconstruction runs in: the caller's points times the power of two that
//! centres the exponents of their coordinates in the adaptive predicates' range.
//!
//! Every combinatorial decision is exact, so it is the same on the points and on any exact
//! power-of-two scaling of them. The rules that are tolerances (the pruned axis's coverage
//! and its order, the noise estimates, peeling's spacings) read rounded values, and rounded
//! arithmetic commutes with a power of two only where nothing underflows or overflows: on
//! subnormal input distinct circumcenters round to one value. So everything from the
//! triangulation to the medial axis runs on the centred copy
//! ([`Magnitudes::centring_shift`](crate::kernel::scale::Magnitudes::centring_shift)): the
//! same numbers for the points and for every exact power-of-two scaling of them, far from
//! both ends of the `f64` range, where the construction also runs at the speed of ordinary
//! input. The caller's coordinates come back once, at the end: the triangulation's points
//! exactly ([`Frame::restore`], the sign of a zero included), each medial-axis vertex as
//! [`Voronoi::vertex_position`](crate::Voronoi::vertex_position) gives it on them
//! ([`Frame::circumcenter_to_caller`]).
//!
//! Every zero of the copy is `+0.0`: a duplicate keeps its first occurrence's coordinates,
//! and `-0.0` and `0.0` order differently where coordinates break ties (`total_cmp`, the
//! corner a circumcenter is computed from), so the sign of a zero would let the input order
//! reach the rounded values (the diagram's positions read a zero as `0.0` for the same
//! reason, [`rounded_circumcenter`]).
//!
//! Input whose exponents spread wider than that range (`1e-100` beside `1e100`) has no
//! centred copy; it runs on the caller's coordinates (zeros made positive), as the
//! triangulation does.

use crate::delaunay::{triangulate, Triangulation};
use crate::error::{scan_points, Error};
use crate::kernel::scale::{log2_floor, pow2, scale_rounded, shift_by, TWO_52};
use crate::parallel;
use crate::voronoi::rounded_circumcenter;

/// The frame: the caller's coordinates times `2^shift`, every zero `+0.0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Frame {
    shift: i32,
    /// Some coordinate is `-0.0` (made `0.0` in the frame, put back by `restore`).
    negative_zero: bool,
    /// Some coordinate is at least `2^1022`: differences of the caller's coordinates may
    /// overflow there.
    reaches_top: bool,
}

impl Frame {
    /// The caller's coordinates themselves (for the stages' own tests).
    #[cfg(test)]
    pub(super) const CALLER: Frame = Frame {
        shift: 0,
        negative_zero: false,
        reaches_top: false,
    };

    /// The triangulation of `points` in their frame, and the frame.
    ///
    /// # Errors
    /// As [`triangulate`]: a coordinate that is not finite, or too many points.
    pub(super) fn triangulate(points: &[[f64; 2]]) -> Result<(Triangulation, Frame), Error> {
        let magnitudes = scan_points(points)?;
        let shift = magnitudes.centring_shift().unwrap_or(0);
        let negative_zero = points
            .iter()
            .flatten()
            .any(|x| x.to_bits() == (-0.0f64).to_bits());
        let frame = Frame {
            shift,
            negative_zero,
            reaches_top: magnitudes.max() >= pow2(1022),
        };
        if shift == 0 && !negative_zero {
            return Ok((triangulate(points)?, frame));
        }
        // Exact: the centred copy is normal and finite (or zero) throughout. `+ 0.0` turns
        // `-0.0` into `0.0` and changes nothing else.
        let scaled = parallel::map_range(points.len(), |i| {
            points[i].map(|x| shift_by(x, shift) + 0.0)
        });
        let tri = triangulate(&scaled)?;
        Ok((tri, frame))
    }

    /// The power of two: frame coordinates are the caller's times `2^shift`.
    #[cfg(test)]
    pub(super) fn shift(self) -> i32 {
        self.shift
    }

    /// Puts the caller's coordinates (`points`) back into a triangulation built in this
    /// frame, exactly: each is the frame's times a power of two, representable, and a zero
    /// is read back from the caller's point (the first occurrence: the sign of its zero).
    pub(super) fn restore(self, tri: &mut Triangulation, points: &[[f64; 2]]) {
        if self.shift == 0 && !self.negative_zero {
            return;
        }
        let Triangulation {
            points: local,
            input_of,
            ..
        } = tri;
        for (p, &input) in local.iter_mut().zip(input_of.iter()) {
            for (x, &caller) in p.iter_mut().zip(&points[input as usize]) {
                // A zero (rare) is read in the caller's order, a cache miss at most.
                *x = if *x == 0.0 {
                    caller
                } else {
                    scale_rounded(*x, -self.shift)
                };
            }
        }
    }

    /// The smoothing's fitted positions `moved` (by local point, in this frame) as the curve
    /// vertices of the restored triangulation `tri`, in the caller's coordinates: a moved
    /// point rounded once ([`to_caller`](Self::to_caller)), every other one exactly the
    /// caller's.
    pub(super) fn fitted_to_caller(
        self,
        tri: &Triangulation,
        moved: Vec<Option<[f64; 2]>>,
    ) -> Vec<[f64; 2]> {
        moved
            .into_iter()
            .zip(&tri.points)
            .map(|(m, &p)| m.map_or(p, |q| self.to_caller(q)))
            .collect()
    }

    /// A frame point in the caller's coordinates, each coordinate rounded once.
    pub(super) fn to_caller(self, p: [f64; 2]) -> [f64; 2] {
        if self.shift == 0 {
            p
        } else {
            p.map(|x| scale_rounded(x, -self.shift))
        }
    }

    /// Whether [`to_caller`](Self::to_caller) of the frame's rounded circumcenter `centre`
    /// of the frame triangle `triangle()` is what the circumcenter computed on the caller's
    /// coordinates is (the value [`Voronoi::vertex_position`](crate::Voronoi::vertex_position)
    /// gives there), decided without arithmetic on subnormal numbers (each costs a
    /// microcode assist):
    ///
    /// * where both coordinates land in the normal range (or on zero, not both), the
    ///   product is exact, and the certified evaluation on the caller's coordinates is
    ///   this one (it rescales the triangle per call where it must: the same numbers),
    ///   unless the triangle's differences overflow there (coordinates near `f64::MAX`:
    ///   then it cannot rescale, and rounds the exact value);
    /// * where both land in the subnormal range, the caller's computation rounds the
    ///   exact circumcenter correctly (no filter proves a subnormal result), and so does
    ///   rounding `centre` when no midpoint of the caller's grid (units of `2^-1074`) lies
    ///   within `centre`'s certified error ([`CIRCUMCENTER_ULPS`] ulps of its larger
    ///   coordinate) and a coordinate that rounds to zero is farther than that from zero
    ///   (its sign then is the exact one's).
    ///
    /// Elsewhere (a midpoint within the error, a normal coordinate beside a subnormal one,
    /// both zero, beyond the `f64` range) only the computation on the caller's coordinates
    /// gives their value: [`circumcenter_to_caller`](Self::circumcenter_to_caller).
    pub(super) fn rounds_like_the_caller(
        self,
        centre: [f64; 2],
        triangle: impl Fn() -> [[f64; 2]; 3],
    ) -> bool {
        let s = self.shift;
        if s == 0 {
            return true;
        }
        if !(centre[0].is_finite() && centre[1].is_finite()) || centre == [0.0, 0.0] {
            return false;
        }
        // The caller's normal range, `[2^-1022, 2^1024)`, in frame units, where the frame's
        // value is normal too.
        let normal_from = if s >= -52 { pow2(s - 1022) } else { 0.0 };
        let normal_below = if s < 0 { pow2(1024 + s) } else { f64::INFINITY };
        let normal = |x: f64| {
            x == 0.0 || (normal_from.max(f64::MIN_POSITIVE)..normal_below).contains(&x.abs())
        };
        if centre.iter().all(|&x| normal(x)) {
            // In the caller's coordinates every difference is below `2^1023` (so finite,
            // whatever its rounding) where this holds in the frame's, with a binade to spare.
            // (Near the top the shift is below -800: `2^(1022 + s)` is a normal number.)
            if !self.reaches_top {
                return true;
            }
            let t = triangle();
            let near =
                |i: usize, j: usize| (0..2).all(|c| (t[i][c] - t[j][c]).abs() < pow2(1022 + s));
            return near(0, 1) && near(1, 2) && near(2, 0);
        }
        // The caller's subnormal grid: its unit 2^-1074 is `2^(s - 1074)` in frame units,
        // normal there (`s ≥ 52`); `per_unit` is its inverse, at most `2^1022`.
        if s < 52 || !centre.iter().all(|&x| x.abs() < normal_from) {
            return false;
        }
        let per_unit = pow2(1074 - s);
        let larger = centre[0].abs().max(centre[1].abs());
        let error = CIRCUMCENTER_ULPS * pow2(log2_floor(larger) - 52);
        // In grid units: exact products, the nearest integer (ties to even: `units` below
        // `2^52`) and the exact distance to it (Sterbenz, or `units` itself below 1/2),
        // and the margin to the midpoint widened for the rounding of the sum.
        let margin = (2.0 * error * per_unit).max(ROUNDING_SLACK);
        centre.iter().all(|&x| {
            let units = x.abs() * per_unit;
            let nearest = (units + TWO_52) - TWO_52;
            let off = (units - nearest).abs();
            off + margin < 0.5 && (nearest != 0.0 || x.abs() > error)
        })
    }

    /// The rounded circumcenter `centre` of the frame triangle `triangle()` (the three
    /// points it was computed from by [`rounded_circumcenter`]), in the caller's
    /// coordinates: the value computed on the caller's coordinates of that triangle, which
    /// [`Voronoi::vertex_position`](crate::Voronoi::vertex_position) of the returned
    /// triangulation gives.
    pub(super) fn circumcenter_to_caller(
        self,
        centre: [f64; 2],
        triangle: impl Fn() -> [[f64; 2]; 3],
    ) -> [f64; 2] {
        if self.rounds_like_the_caller(centre, &triangle) {
            self.to_caller(centre)
        } else {
            let caller = triangle().map(|p| p.map(|x| shift_by(x, -self.shift)));
            rounded_circumcenter(caller)
        }
    }
}

/// The accuracy of a rounded circumcenter in ulps of its larger coordinate
/// (`predicates::circumcenter`: 256), with one more for the rounding of the bound.
const CIRCUMCENTER_ULPS: f64 = 257.0;

/// The smallest margin to a midpoint of the caller's grid, in grid units: above the
/// rounding error of the margin's own sum with a distance below 1/2 (`2^-54`).
const ROUNDING_SLACK: f64 = 1.0 / 4503599627370496.0; // 2^-52

#[cfg(test)]
mod tests {
    use super::*;

    /// The frame's triangulation restored is the caller's, point for point, the sign of a
    /// zero included; the shift is the same for every exact power-of-two scaling, up to
    /// it.
    #[test]
    fn the_frame_is_exact_and_the_same_up_to_scale() {
        let base: Vec<[f64; 2]> = vec![
            [0.0, -0.0],
            [3.0, 1.0],
            [-2.5, 4.0],
            [1.0, -3.0],
            [-0.0, 2.0],
            [3.0, 1.0],
            [0.75, 0.5],
        ];
        let (tri, frame) = Frame::triangulate(&base).unwrap();
        for k in [-1070, -1000, -600, -143, -1, 0, 1, 150, 600, 1000, 1021] {
            let scaled: Vec<[f64; 2]> = base.iter().map(|p| p.map(|x| shift_by(x, k))).collect();
            let (mut t, f) = Frame::triangulate(&scaled).unwrap();
            assert_eq!(f.shift(), frame.shift() - k, "2^{k}");
            assert_eq!(t.points, tri.points, "2^{k}: the same frame");
            f.restore(&mut t, &scaled);
            for (i, p) in scaled.iter().enumerate() {
                let got = t.point(i as u32);
                assert_eq!(got.map(f64::to_bits), p.map(f64::to_bits), "2^{k}");
            }
        }
    }

    /// A circumcenter comes back as the caller's-coordinates computation gives it, on
    /// random triangles at scales from the subnormals to near the top: through the frame's
    /// value wherever [`Frame::rounds_like_the_caller`] says so (most subnormal results
    /// included), else computed there.
    #[test]
    fn circumcenters_come_back_as_the_callers() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move |below: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % below
        };
        let (mut fast, mut subnormal) = (0, 0);
        for round in 0..6000 {
            let bits = 1 + next(40);
            let k = [-1074, -1060, -1030, -600, 0, 400, 1000][round % 7];
            let caller: [[f64; 2]; 3] = std::array::from_fn(|_| {
                std::array::from_fn(|_| {
                    let m = next(1 << bits) as f64 - (1u64 << (bits - 1)) as f64;
                    shift_by(m, k - bits.min(20) as i32 + 20)
                })
            });
            let Some(expected) = crate::predicates::circumcenter(caller[0], caller[1], caller[2])
            else {
                continue;
            };
            let (_, frame) = Frame::triangulate(&caller).unwrap();
            let in_frame = caller.map(|p| p.map(|x| shift_by(x, frame.shift()) + 0.0));
            let centre = rounded_circumcenter(in_frame);
            let back = frame.circumcenter_to_caller(centre, || in_frame);
            let reference = rounded_circumcenter(caller);
            assert_eq!(back, reference, "{caller:?}");
            let tiny = expected.iter().all(|x| x.abs() < f64::MIN_POSITIVE);
            subnormal += usize::from(tiny);
            fast += usize::from(tiny && frame.rounds_like_the_caller(centre, || in_frame));
        }
        // Coarse lattices put many circumcenters on midpoints of the caller's grid exactly:
        // those are computed there.
        assert!(
            subnormal > 500 && fast * 4 > subnormal * 3,
            "{fast} of {subnormal}"
        );
    }
}
