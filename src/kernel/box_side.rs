//! Exact decisions and correctly rounded constructions against the sides of an axis-aligned
//! box, for clipping Voronoi cells.
//!
//! A box side is the line `x = X` or `y = Y` for an `f64` value. The decisions:
//!
//! * [`circumcenter_side`]: the sign of `O[axis] − value` for the circumcenter `O` of three
//!   `f64` points (a Voronoi vertex, never representable exactly in general). With
//!   `O = t0 + u/d` (see `circumcenter`) it is the sign of `d·(t0[axis] − value) + u[axis]`
//!   (degree 3 in the leaves) times the sign of `d` (degree 2). Stages: the filtered `f64`
//!   circumcenter, whose error is proven below 256 ulps of its larger coordinate
//!   ([`circumcenter`]), decides when `value` is farther than that; then the running-error
//!   filter (`bounded`, a proven bound, after an exact power-of-two normalization) on the
//!   polynomial; then the polynomial exactly in `BigInt` (`exact`).
//!
//! The constructions, each correctly rounded to the nearest `f64` so that one exact point
//! gets the same coordinates whichever cell or triangle computes it:
//!
//! * [`bisector_crossing`]: the point of the perpendicular bisector of `p` and `q` on the
//!   line `x[axis] = value`; only its other coordinate is constructed.
//! * [`circumcenter_nearest`]: the circumcenter.
//!
//! No function here panics on any input; degenerate input (a collinear triangle, a bisector
//! parallel to the line) gives a documented answer.

use num_bigint::{BigInt, Sign as BigSign};

use super::arith::Arith;
use super::bounded::{lift_filter, Bounded};
use super::circumcenter::{circumcenter, circumcenter_rounded};
use super::exact::{lift_exact, ratio_to_f64, signs};
use super::poly::{circ, diff, Pt};
use super::scale::normalize;
use super::Sign;

/// `[d, d·(t0[axis] − v[axis]) + u[axis]]` for the circumcenter `t0 + u/d` of `tri`: the sign
/// of `O[axis] − value` is the product of their signs (`v` holds the value in both
/// coordinates, so that it is one more "point" of the expression).
#[inline(always)]
fn side_terms<T: Arith>(tri: &[Pt<T>; 3], v: &Pt<T>, axis: usize) -> [T; 2] {
    let c = circ(tri);
    let offset = diff(&tri[0], v);
    let u = if axis == 0 { &c.ux } else { &c.uy };
    let n = c.d.mul(&offset[axis]).add(u);
    [c.d, n]
}

/// The exact sign of `O[axis] − value`, where `O` is the circumcenter of `tri` (either
/// orientation) and `axis` is 0 for `x`, anything else for `y`. `Zero` when `tri` is
/// collinear (it has no circumcenter) or a coordinate is not finite.
///
/// The running-error filter decides ordinary input; exact zeros whose operations were all
/// exact (grid input, a vertex on a box side at a round value) are certified there too; the
/// rest is evaluated exactly.
pub(crate) fn circumcenter_side(tri: [[f64; 2]; 3], axis: usize, value: f64) -> Sign {
    let axis = usize::from(axis != 0);
    if tri.iter().flatten().chain([&value]).any(|c| !c.is_finite()) {
        return Sign::Zero;
    }
    if let Some(sign) = side_from_circumcenter(tri, axis, value) {
        return sign;
    }
    let points = [tri[0], tri[1], tri[2], [value, value]];
    let [f0, f1, f2, fv] = lift_filter(normalize(points).0);
    let ([d, n], _) = signs(side_terms(&[f0, f1, f2], &fv, axis), || {
        let ([e0, e1, e2, ev], _) = lift_exact(points);
        side_terms(&[e0, e1, e2], &ev, axis)
    });
    n.times(d)
}

/// The sign of `O[axis] − value` from the `f64` circumcenter `ô`, if certain: `ô` is within
/// `E = 256·ulp(N)` of `O` in each coordinate (`N` the larger of `|ô|`'s coordinates, see
/// [`circumcenter`]), so `|ô[axis] − value| > E` decides; the computed difference `d̂` has the
/// exact difference's sign and `|d̂| ≤ (1 + u)·|ô[axis] − value|`, hence the test
/// `|d̂| > E·(1 + 4ε)`. `E` is a power of two times 256: exact.
#[inline]
fn side_from_circumcenter(tri: [[f64; 2]; 3], axis: usize, value: f64) -> Option<Sign> {
    certified_side(circumcenter(tri[0], tri[1], tri[2])?, axis, value)
}

/// [`side_from_circumcenter`] on the computed circumcenter `o`.
#[inline]
fn certified_side(o: [f64; 2], axis: usize, value: f64) -> Option<Sign> {
    let n = o[0].abs().max(o[1].abs());
    if !n.is_normal() {
        return None;
    }
    let ulp = f64::from_bits(n.to_bits() & 0x7ff0_0000_0000_0000) * f64::EPSILON;
    let d = o[axis] - value;
    (d.abs() > 256.0 * ulp * (1.0 + 4.0 * f64::EPSILON)).then(|| Sign::of_f64(d))
}

/// Whether the circumcenter of `tri` lies strictly inside the box `(min, max)`, exactly:
/// [`circumcenter_side`] against the four sides, with the filtered circumcenter computed once
/// for all of them. False for a collinear `tri`.
pub(crate) fn circumcenter_strictly_inside(
    tri: [[f64; 2]; 3],
    min: [f64; 2],
    max: [f64; 2],
) -> bool {
    let fast = circumcenter(tri[0], tri[1], tri[2]);
    let side = |axis: usize, value: f64| {
        fast.and_then(|o| certified_side(o, axis, value))
            .unwrap_or_else(|| circumcenter_side(tri, axis, value))
    };
    (0..2).all(|axis| {
        side(axis, min[axis]) == Sign::Positive && side(axis, max[axis]) == Sign::Negative
    })
}

/// The other coordinate (`y` for `axis == 0`, else `x`) of the point of the perpendicular
/// bisector of `p` and `q` whose `axis` coordinate is `value`, correctly rounded (ties to
/// even). Symmetric in `p` and `q`. `None` when the bisector is parallel to that line
/// (`p` and `q` have the same other coordinate) or a coordinate is not finite.
///
/// With `w` the other axis, the point solves `(q − p)·(p + q − 2x) = 0`:
/// `x[w] = ((q[w] − p[w])·(p[w] + q[w]) + (q[a] − p[a])·((p[a] − v) + (q[a] − v))) / (2·(q[w] − p[w]))`.
pub(crate) fn bisector_crossing(p: [f64; 2], q: [f64; 2], axis: usize, value: f64) -> Option<f64> {
    let a = usize::from(axis != 0);
    let w = 1 - a;
    if p.iter().chain(&q).chain([&value]).any(|c| !c.is_finite()) || p[w] == q[w] {
        return None;
    }
    let ([ep, eq, ev], shift) = lift_exact([p, q, [value, value]]);
    let dw = &eq[w] - &ep[w];
    let da = &eq[a] - &ep[a];
    let numer: BigInt = &dw * (&ep[w] + &eq[w]) + da * ((&ep[a] - &ev[a]) + (&eq[a] - &ev[a]));
    let denom: BigInt = dw << 1usize;
    // numer is in units of 2^(2·shift), denom in units of 2^shift.
    let negative = (numer.sign() == BigSign::Minus) != (denom.sign() == BigSign::Minus);
    Some(ratio_to_f64(
        negative,
        numer.magnitude(),
        denom.magnitude(),
        i64::from(shift),
    ))
}

/// The circumcenter of `a, b, c`, each coordinate the nearest `f64` to the exact one (ties to
/// even), or `None` iff they are collinear (or a coordinate is not finite).
///
/// Most calls are certified without exact arithmetic: with `q = u/d` from the running-error
/// filter (`q̂` within `e` of `q`) and `t0 + q̂ = s + r` exactly (Knuth's TwoSum), the exact
/// coordinate is `s + r + δ` with `|δ| ≤ e`; when `|r| + e` is below half the smaller gap
/// from `s` to its neighbouring `f64`s, `s` is the unique nearest `f64`. Otherwise (and for
/// a zero coordinate) the exact circumcenter is rounded.
pub(crate) fn circumcenter_nearest(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<[f64; 2]> {
    nearest_from_bounded([a, b, c]).or_else(|| circumcenter_rounded(a, b, c))
}

/// [`circumcenter_nearest`] when the running-error filter certifies it.
fn nearest_from_bounded(t: [[f64; 2]; 3]) -> Option<[f64; 2]> {
    let c = circ(&lift_filter(t));
    let x = nearest_sum(t[0][0], c.ux.div(&c.d)?)?;
    let y = nearest_sum(t[0][1], c.uy.div(&c.d)?)?;
    Some([x, y])
}

/// The `f64` nearest to `t0 + q` for `q` known within `q.e` of `q.v`, if certain.
fn nearest_sum(t0: f64, q: Bounded) -> Option<f64> {
    let s = t0 + q.v;
    let a = s.abs();
    if !(a.is_normal() && q.e.is_finite()) {
        return None;
    }
    // TwoSum: t0 + q.v = s + r exactly (no overflow: s is finite and normal).
    let bv = s - t0;
    let r = (t0 - (s - bv)) + (q.v - bv);
    let below = a - f64::from_bits(a.to_bits() - 1);
    let above = f64::from_bits(a.to_bits() + 1) - a;
    // Half the smaller gap: exact (a power of two). The sum is rounded, hence the margin.
    let half_gap = 0.5 * below.min(above);
    ((r.abs() + q.e) * (1.0 + 4.0 * f64::EPSILON) < half_gap).then_some(s)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational;
    use num_traits::{Signed, Zero};

    fn r(x: f64) -> BigRational {
        BigRational::from_float(x).unwrap()
    }

    /// The exact circumcenter by Cramer's rule on rationals: independent of `circ`.
    fn exact_circumcenter(t: [[f64; 2]; 3]) -> Option<[BigRational; 2]> {
        let [a, b, c] = t.map(|p| p.map(r));
        let (bx, by) = (&b[0] - &a[0], &b[1] - &a[1]);
        let (cx, cy) = (&c[0] - &a[0], &c[1] - &a[1]);
        let d = (&bx * &cy - &by * &cx) * r(2.0);
        if d.is_zero() {
            return None;
        }
        let b2 = &bx * &bx + &by * &by;
        let c2 = &cx * &cx + &cy * &cy;
        let ux = (&cy * &b2 - &by * &c2) / &d;
        let uy = (&bx * &c2 - &cx * &b2) / &d;
        Some([&a[0] + ux, &a[1] + uy])
    }

    fn sign_of(x: &BigRational) -> Sign {
        if x.is_zero() {
            Sign::Zero
        } else if x.is_positive() {
            Sign::Positive
        } else {
            Sign::Negative
        }
    }

    /// Deterministic xorshift values in [0, 1).
    struct Xs(u64);
    impl Xs {
        fn next(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    #[test]
    fn circumcenter_side_agrees_with_rationals() {
        let mut rng = Xs(0x9e37_79b9_7f4a_7c15);
        for round in 0..4000 {
            // Small lattices make exact zeros frequent; scales test the normalization.
            let scale = [1.0, 1e-120, 1e150, 3.0][round % 4];
            let lattice = round % 3 == 0;
            let mut coord = || {
                let v = rng.next();
                if lattice {
                    (v * 8.0).floor() * scale
                } else {
                    v * scale
                }
            };
            let t = [[coord(), coord()], [coord(), coord()], [coord(), coord()]];
            let o = exact_circumcenter(t);
            for axis in 0..2 {
                // The value: random, or the exact coordinate rounded (often exactly it).
                let value = match &o {
                    Some(o) if round % 2 == 0 => super::super::exact::rational_to_f64(&o[axis]),
                    _ => coord(),
                };
                let expected = o
                    .as_ref()
                    .map_or(Sign::Zero, |o| sign_of(&(&o[axis] - r(value))));
                assert_eq!(
                    circumcenter_side(t, axis, value),
                    expected,
                    "{t:?} axis {axis} value {value}"
                );
            }
        }
    }

    #[test]
    fn strictly_inside_agrees_with_the_four_sides() {
        let mut rng = Xs(0x0bad_cafe_f00d_d00d);
        for _ in 0..3000 {
            let mut c = || (rng.next() * 8.0).floor() / 2.0;
            let t = [[c(), c()], [c(), c()], [c(), c()]];
            let (min, max) = ([c() - 1.0, c() - 1.0], [c() + 1.0, c() + 1.0]);
            let expected = (0..2).all(|a| {
                circumcenter_side(t, a, min[a]) == Sign::Positive
                    && circumcenter_side(t, a, max[a]) == Sign::Negative
            });
            assert_eq!(circumcenter_strictly_inside(t, min, max), expected, "{t:?}");
        }
    }

    #[test]
    fn bisector_crossing_is_the_nearest_f64_and_symmetric() {
        let mut rng = Xs(0x2545_f491_4f6c_dd1d);
        for round in 0..4000 {
            let scale = [1.0, 1e-100, 1e120, 7.0][round % 4];
            let mut coord = || rng.next() * scale;
            let (p, q) = ([coord(), coord()], [coord(), coord()]);
            for axis in 0..2 {
                let value = coord();
                let w = 1 - axis;
                let got = bisector_crossing(p, q, axis, value).unwrap();
                assert_eq!(Some(got), bisector_crossing(q, p, axis, value));
                // The exact point is equidistant from p and q.
                let mut x = [r(0.0), r(0.0)];
                x[axis] = r(value);
                let (pr, qr) = (p.map(r), q.map(r));
                // Solve (q − p)·(p + q − 2x) = 0 for x[w].
                let rest = (&qr[axis] - &pr[axis]) * (&pr[axis] + &qr[axis] - r(2.0) * &x[axis]);
                let exact = (&pr[w] + &qr[w]) / r(2.0) + rest / (r(2.0) * (&qr[w] - &pr[w]));
                assert_eq!(got, super::super::exact::rational_to_f64(&exact));
            }
        }
        assert_eq!(bisector_crossing([0.0, 1.0], [4.0, 1.0], 0, 3.0), None);
        assert_eq!(bisector_crossing([0.0, 1.0], [4.0, 1.0], 1, 3.0), Some(2.0));
        assert_eq!(bisector_crossing([0.0, 0.0], [2.0, 2.0], 0, 0.0), Some(2.0));
    }

    #[test]
    fn circumcenter_nearest_is_correctly_rounded() {
        let mut rng = Xs(0x1234_5678_9abc_def1);
        let mut certified = 0;
        for round in 0..6000 {
            let scale = [1.0, 1e-100, 1e120, 0.1][round % 4];
            // Small triangles far from the origin (the common case), and large ones.
            let spread = [1e-3, 1.0, 1e-9][round % 3];
            let base = [rng.next() * scale, rng.next() * scale];
            let mut corner = || {
                [
                    base[0] + rng.next() * spread * scale,
                    base[1] + rng.next() * spread * scale,
                ]
            };
            let t = [corner(), corner(), corner()];
            let Some(o) = exact_circumcenter(t) else {
                continue;
            };
            let expected = [0, 1].map(|i| super::super::exact::rational_to_f64(&o[i]));
            assert_eq!(
                circumcenter_nearest(t[0], t[1], t[2]),
                Some(expected),
                "{t:?}"
            );
            certified += usize::from(nearest_from_bounded(t).is_some());
        }
        // About a third pass the filter here (mostly the small triangles); the rest is exact.
        assert!(certified > 1000, "the filter certified only {certified}");
        let t = [[0.0, 0.0], [1.0, 0.0], [0.1, 0.3]];
        let o = exact_circumcenter(t).unwrap();
        let expected = [0, 1].map(|i| super::super::exact::rational_to_f64(&o[i]));
        assert_eq!(circumcenter_nearest(t[0], t[1], t[2]), Some(expected));
        assert_eq!(circumcenter_nearest([0.0; 2], [1.0; 2], [2.0; 2]), None);
    }
}
