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
//! exactly ([`Frame::restore`]), each medial-axis vertex as
//! [`Voronoi::vertex_position`](crate::Voronoi::vertex_position) gives it on them
//! ([`Frame::circumcenter_to_caller`]).
//!
//! Every zero of the copy is `+0.0`: a duplicate keeps its first occurrence's coordinates,
//! and `-0.0` and `0.0` order differently where coordinates break ties (`total_cmp`, the
//! corner a circumcenter is computed from), so the sign of a zero would let the input order
//! reach the rounded values. The triangulation a reconstruction returns keeps them `+0.0`.
//!
//! Input whose exponents spread wider than that range (`1e-100` beside `1e100`) has no
//! centred copy; it runs on the caller's coordinates (zeros made positive), as the
//! triangulation does.

use crate::delaunay::{triangulate, Triangulation};
use crate::error::{scan_points, Error};
use crate::kernel::scale::{scale_rounded, shift_by};
use crate::parallel;
use crate::voronoi::rounded_circumcenter;

/// The frame: the caller's coordinates times `2^shift`, every zero `+0.0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Frame {
    shift: i32,
}

impl Frame {
    /// The caller's coordinates themselves (for the stages' own tests).
    #[cfg(test)]
    pub(super) const CALLER: Frame = Frame { shift: 0 };

    /// The triangulation of `points` in their frame, and the frame.
    ///
    /// # Errors
    /// As [`triangulate`]: a coordinate that is not finite, or too many points.
    pub(super) fn triangulate(points: &[[f64; 2]]) -> Result<(Triangulation, Frame), Error> {
        let shift = scan_points(points)?.centring_shift().unwrap_or(0);
        let frame = Frame { shift };
        let negative_zero = || {
            points
                .iter()
                .flatten()
                .any(|x| x.to_bits() == (-0.0f64).to_bits())
        };
        if shift == 0 && !negative_zero() {
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

    /// Puts the caller's coordinates back into a triangulation built in this frame,
    /// exactly (every intermediate of the two halves of the product lies between the
    /// frame's value and the caller's, both exact); zeros stay `+0.0`.
    pub(super) fn restore(self, tri: &mut Triangulation) {
        if self.shift != 0 {
            for x in tri.points.iter_mut().flatten() {
                *x = shift_by(*x, -self.shift);
            }
        }
    }

    /// A frame point in the caller's coordinates, each coordinate rounded once.
    pub(super) fn to_caller(self, p: [f64; 2]) -> [f64; 2] {
        if self.shift == 0 {
            p
        } else {
            p.map(|x| scale_rounded(x, -self.shift))
        }
    }

    /// The frame's rounded circumcenter `centre` in the caller's coordinates, when that is
    /// the exact product and its larger coordinate is normal: then it is what the
    /// circumcenter computed on the caller's coordinates is (the same certified evaluation,
    /// which the circumcenter rescales per call where it must: the same numbers). `None`
    /// otherwise (a result in the subnormal range, or beyond the `f64` range), where only
    /// the computation on the caller's coordinates gives their value
    /// ([`circumcenter_to_caller`](Self::circumcenter_to_caller)).
    pub(super) fn exact_to_caller(self, centre: [f64; 2]) -> Option<[f64; 2]> {
        if self.shift == 0 {
            return Some(centre);
        }
        let out = self.to_caller(centre);
        let exact = (0..2).all(|i| scale_rounded(out[i], self.shift) == centre[i]);
        (exact && out[0].abs().max(out[1].abs()).is_normal()).then_some(out)
    }

    /// The rounded circumcenter `centre` of the frame triangle `triangle()` (the three
    /// points it was computed from, [`rounded_circumcenter`]), in the caller's coordinates:
    /// the value computed on the caller's coordinates of that triangle, which
    /// [`Voronoi::vertex_position`](crate::Voronoi::vertex_position) of the returned
    /// triangulation gives.
    pub(super) fn circumcenter_to_caller(
        self,
        centre: [f64; 2],
        triangle: impl FnOnce() -> [[f64; 2]; 3],
    ) -> [f64; 2] {
        self.exact_to_caller(centre).unwrap_or_else(|| {
            let caller = triangle().map(|p| p.map(|x| shift_by(x, -self.shift)));
            rounded_circumcenter(caller)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The frame's triangulation restored is the caller's, point for point (zeros made
    /// positive); the shift is the same for every exact power-of-two scaling, up to it.
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
            let scaled: Vec<[f64; 2]> = base
                .iter()
                .map(|p| p.map(|x| shift_by(x, k) + 0.0))
                .collect();
            let (mut t, f) = Frame::triangulate(&scaled).unwrap();
            assert_eq!(f.shift(), frame.shift() - k, "2^{k}");
            assert_eq!(t.points, tri.points, "2^{k}: the same frame");
            f.restore(&mut t);
            for (i, p) in scaled.iter().enumerate() {
                let got = t.point(i as u32);
                assert_eq!(got.map(f64::to_bits), p.map(f64::to_bits), "2^{k}");
            }
        }
    }

    /// A circumcenter comes back as the caller's-coordinates computation gives it: the
    /// exact product where that is normal, the computation itself where it is subnormal.
    #[test]
    fn circumcenters_come_back_as_the_callers() {
        let unit = f64::from_bits(1);
        for (triangle, scale) in [
            ([[0.0, 0.0], [3.0, 1.0], [1.0, 5.0]], 1.0),
            ([[0.0, 0.0], [3.0, 1.0], [1.0, 5.0]], unit),
            ([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], unit),
            ([[7.0, 2.0], [11.0, 3.0], [5.0, 13.0]], unit * 1024.0),
            ([[7.0, 2.0], [11.0, 3.0], [5.0, 13.0]], 2f64.powi(1000)),
        ] {
            let caller = triangle.map(|p| p.map(|x| x * scale));
            let (_, frame) = Frame::triangulate(&caller).unwrap();
            let in_frame = caller.map(|p| p.map(|x| shift_by(x, frame.shift())));
            let centre = rounded_circumcenter(in_frame);
            let back = frame.circumcenter_to_caller(centre, || in_frame);
            assert_eq!(back, rounded_circumcenter(caller), "{caller:?}");
        }
    }
}
