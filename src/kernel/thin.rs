//! The circumcenter of a thin triangle with exact products and an a priori error bound: the
//! fast middle stage between the `f64` filter and the running-error double words.
//!
//! Three consecutive samples of a curve at 10^6 points form a triangle whose denominator
//! `d = 2 (bx·cy − by·cx)` is about `10^-5` of its products: the `f64` filter cannot prove
//! 256 ulps there, and on such a set nearly half of all circumcenters (every triangle along the
//! curve) used to go to [`super::double_word`], whose bound is carried operation by operation
//! (about 280 ns a call). Here the same formula is evaluated with every product split exactly
//! into two `f64`s (Dekker's TwoProduct) and every cancelling sum kept as two (TwoSum), and the
//! error is bounded once, in closed form, from the magnitudes of the products: about a fifth
//! of the cost. It declines (the caller goes on to the double words) unless its inputs meet
//! the precondition below, or when its bound does not prove 256 ulps.
//!
//! # Precondition
//!
//! With `t0` the first vertex, the six coordinate differences `bx = t1x − t0x, …` are exact in
//! one `f64` (TwoSum leaves no remainder: true whenever Sterbenz's lemma applies, that is for
//! nearby points away from the axes) and each is zero or of magnitude in `[2^-250, 2^250]`.
//! Then every product of two or three differences lies between `2^-750` and `2^752` or is
//! zero, and every value below is a multiple of `2^-906` (a difference is a multiple of
//! `2^-302`): nothing overflows, no nonzero product or sum is subnormal, so each rounded
//! operation has a relative error of at most `u = 2^-53` and TwoProduct is exact.
//!
//! # The bound (a proof)
//!
//! Exact values are plain, computed ones have hats; `x·y = p + q` exactly with `|q| ≤ u|p|`
//! (TwoProduct), `a + b = s + t` exactly with `|t| ≤ u|s|` (TwoSum), and each rounded sum or
//! product `ẑ` is within `u|ẑ|` of its exact operands' result.
//!
//! * **Squared lengths.** `bx² = p1 + q1`, `by² = p2 + q2`, `(s, t) = TwoSum(p1, p2)`,
//!   `w = fl(q1 + q2)`, `l = fl(t + w)`; then `|b|² = s + l + δ` with
//!   `|δ| ≤ u|l| + u|w| ≤ u(2.01u·s) + u(1.01u·s) ≤ 3.02u²·s` (`|w| ≤ 1.01u·s`,
//!   `|l| ≤ 2.01u·s`).
//! * **A numerator** `N = f·B − g·C` (`ux`: `f = cy`, `B = |b|²`, `g = by`, `C = |c|²`; `uy`
//!   alike) with `B = s_B + l_B + δ_B`: `f·s_B = p + q`, `g·s_C = p' + q'`, `m = fl(f·l_B)`,
//!   `m' = fl(g·l_C)`, `(σ, τ) = TwoSum(p, −p')`, `γ = fl(q − q')`, `h = fl(m − m')`,
//!   `k = fl(γ + h)`, `λ = fl(τ + k)`, and `N̂ = σ + λ`. The difference `N − N̂` is the sum
//!   of the six roundings of `λ, γ, k, h, m, m'` and of `f·δ_B − g·δ_C`. With
//!   `M = |f|·s_B + |g|·s_C`: `|γ| ≤ 1.01u·M`, `|m| + |m'| ≤ 2.02u·M`, `|h| ≤ 2.05u·M`,
//!   `|k| ≤ 3.1u·M`, `|τ| ≤ 1.01u·M`, `|λ| ≤ 4.2u·M`, so
//!   `|N − N̂| ≤ (4.2 + 1.01 + 3.1 + 2.05 + 2.02 + 3.02)·u²·M < 16u²·M = E_N`.
//! * **The cross product** `D = bx·cy − by·cx`: `bx·cy = p + q`, `by·cx = p' + q'`,
//!   `(σ, τ) = TwoSum(p, −p')`, `γ = fl(q − q')`, `λ = fl(τ + γ)`, `D̂ = σ + λ`:
//!   `|D − D̂| ≤ u|λ| + u|γ| ≤ 3.1u²·M_D < 4u²·M_D = E_D`, `M_D = |p| + |p'|`.
//! * **The quotient** `Q = N / (2D)` is computed as `q̂ = fl(fl(N̂) / (2·fl(D̂)))`. With
//!   `Ũ = N̂ / (2D̂)`: `|q̂ − Ũ| ≤ 3.01u·|Ũ|` and `|Ũ| ≤ (1 + 3.01u)·|q̂|`. If
//!   `ρ = E_D / |D̂| ≤ 2^-10`, then `|D| ≥ (1 − ρ)|D̂|` and
//!   `|Q − Ũ| ≤ E_N / (2|D̂|(1 − ρ)) + |Ũ|·ρ / (1 − ρ)`, so
//!   `|q̂ − Q| ≤ |q̂|·(3.02u + 1.002ρ) + 0.502·E_N / |fl(D̂)| ≤ |q̂|·(4u + 2r) + E_N / |fl(D̂)|`
//!   for the computed `r = fl(E_D / |fl(D̂)|) ≥ (1 − 3u)ρ`.
//! * **The coordinate** `o = fl(t0 + q̂)` is within `u|o| + |q̂ − Q|` of `t0 + Q`.
//!
//! **The bounds in floating point.** `E_N = 2^-102·fl(M)`, `E_D = 2^-104·fl(M_D)` (powers of two:
//! exact scalings of normal numbers) are at least the constants above, which were rounded up
//! with room for the few roundings of `M`; the final bound uses `2u|o|`, `4u` and `2r` where
//! the proof needs `u|o|`, `3.02u` and `1.002ρ`, which covers the roundings of its own
//! evaluation, and adds `4η` for products of tiny values rounding in the subnormal range.
//! The coordinate is accepted as [`super::double_word::circumcenter`] accepts it: finite,
//! and both bounds at most `256·ulp` of the larger magnitude.

use super::arith::U;
use super::bounded::{dekker_error, ETA};
#[cfg(test)]
use super::double_word::EXPONENT_MASK;
use super::double_word::{two_sum, within_promise};

/// The smallest nonzero coordinate difference admitted: `2^-250`.
const DIFFERENCE_MIN: f64 = 5.527147875260445e-76;
/// The largest coordinate difference admitted: `2^250`.
const DIFFERENCE_MAX: f64 = 1.8092513943330656e75;
/// `16u² = 2^-102`: the numerators' error per unit of their magnitude.
const NUMERATOR_ERROR: f64 = 1.9721522630525295e-31;
/// `4u² = 2^-104`: the cross product's error per unit of its magnitude.
const CROSS_ERROR: f64 = 4.930380657631324e-32;
/// `2^-10`: the largest relative error of the cross product the quotient's bound allows.
const CROSS_RELATIVE_MAX: f64 = 1.0 / 1024.0;

/// `x − y` if it is exact in one `f64` and zero or within the precondition's range.
#[inline(always)]
fn exact_difference(x: f64, y: f64) -> Option<f64> {
    let (s, t) = two_sum(x, -y);
    let in_range = s == 0.0 || (DIFFERENCE_MIN..=DIFFERENCE_MAX).contains(&s.abs());
    (t == 0.0 && in_range).then_some(s) // false for NaN
}

/// `x·y = p + q` exactly, under the precondition (module docs).
#[inline(always)]
fn two_product(x: f64, y: f64) -> (f64, f64) {
    let p = x * y;
    (p, dekker_error(x, y, p))
}

/// `x² + y²` as `(s, l)`: within `3.02u²·s` of `s + l` (module docs).
#[inline(always)]
fn squared_length(x: f64, y: f64) -> (f64, f64) {
    let (p1, q1) = two_product(x, x);
    let (p2, q2) = two_product(y, y);
    let (s, t) = two_sum(p1, p2);
    (s, t + (q1 + q2))
}

/// `f·B − g·C` for `B = (s_B, l_B)`, `C = (s_C, l_C)`: the leading `f64`, the rest, and the
/// magnitude `M` of the error bound `16u²·M` (module docs).
#[inline(always)]
fn numerator(f: f64, b: (f64, f64), g: f64, c: (f64, f64)) -> (f64, f64, f64) {
    let (p, q) = two_product(f, b.0);
    let (p2, q2) = two_product(g, c.0);
    let (m, m2) = (f * b.1, g * c.1);
    let (sigma, tau) = two_sum(p, -p2);
    let rest = tau + ((q - q2) + (m - m2));
    (sigma, rest, f.abs() * b.0 + g.abs() * c.0)
}

/// The circumcenter of `t` from exact products with an a priori bound, if the bound proves
/// 256 ulps of its larger coordinate magnitude (module docs); `None` to go on to the double
/// words.
pub(super) fn circumcenter(t: &[[f64; 2]; 3]) -> Option<[f64; 2]> {
    let [t0, t1, t2] = *t;
    let bx = exact_difference(t1[0], t0[0])?;
    let by = exact_difference(t1[1], t0[1])?;
    let cx = exact_difference(t2[0], t0[0])?;
    let cy = exact_difference(t2[1], t0[1])?;

    let (p, q) = two_product(bx, cy);
    let (p2, q2) = two_product(by, cx);
    let (sigma, tau) = two_sum(p, -p2);
    let cross = sigma + (tau + (q - q2));
    let cross_error = CROSS_ERROR * (p.abs() + p2.abs());
    let relative = cross_error / cross.abs();
    // Declines also a zero cross product (an infinite or NaN ratio) and non-finite values.
    if relative.is_nan() || relative > CROSS_RELATIVE_MAX {
        return None;
    }

    let b2 = squared_length(bx, by);
    let c2 = squared_length(cx, cy);
    let den = 2.0 * cross;
    let coordinate = |origin: f64, (lead, rest, magnitude): (f64, f64, f64)| {
        let quotient = (lead + rest) / den;
        let quotient_error = (quotient.abs() * (4.0 * U + 2.0 * relative) + 4.0 * ETA)
            + NUMERATOR_ERROR * magnitude / cross.abs();
        let o = origin + quotient;
        (o, quotient_error + 2.0 * U * o.abs())
    };
    within_promise(
        coordinate(t0[0], numerator(cy, b2, by, c2)),
        coordinate(t0[1], numerator(bx, c2, cx, b2)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::circumcenter::circumcenter_exact;

    /// Within 256 ulps of the larger magnitude of the exact circumcenter, rounded.
    fn within_promise(o: [f64; 2], t: &[[f64; 2]; 3]) -> bool {
        let exact = circumcenter_exact(t[0], t[1], t[2]).expect("not collinear");
        let rounded = exact.to_f64();
        let norm = rounded[0].abs().max(rounded[1].abs());
        let ulp = f64::from_bits(norm.to_bits() & EXPONENT_MASK) * f64::EPSILON;
        (0..2).all(|i| (o[i] - rounded[i]).abs() <= 255.0 * ulp)
    }

    fn stream(mut s: u64) -> impl FnMut() -> f64 {
        move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    /// Three consecutive samples of a circle of radius `r` around `center`, `h` apart in
    /// angle: the triangles that made this stage worth having.
    fn arc(center: [f64; 2], r: f64, start: f64, h: f64) -> [[f64; 2]; 3] {
        [0.0, 1.0, 2.0].map(|k| {
            let a = start + k * h;
            [center[0] + r * a.cos(), center[1] + r * a.sin()]
        })
    }

    #[test]
    fn thin_triangles_are_within_the_promise_and_mostly_decided() {
        let mut u = stream(0x7417_1a5e);
        let (mut decided, mut tried) = (0, 0);
        for scale in [1e-6, 1.0, 3e4, 1e9] {
            for _ in 0..2000 {
                let h = 10f64.powf(-2.0 - 5.0 * u());
                let center = [scale * (u() - 0.5), scale * (u() - 0.5)];
                let t = arc(center, scale * (0.1 + u()), 6.3 * u(), h);
                if circumcenter_exact(t[0], t[1], t[2]).is_none() {
                    continue;
                }
                tried += 1;
                if let Some(o) = circumcenter(&t) {
                    decided += 1;
                    assert!(within_promise(o, &t), "{t:?} -> {o:?}");
                }
            }
        }
        // Sterbenz's lemma fails for the few triangles that straddle an axis or sit far from
        // their centre in one coordinate; the rest must be decided.
        assert!(decided * 10 > tried * 8, "decided {decided} of {tried}");
    }

    #[test]
    fn near_collinear_triples_are_right_or_declined() {
        let mut u = stream(0x00c0_111e);
        let mut decided = 0;
        for _ in 0..20_000 {
            let a = [u(), u()];
            let b = [u(), u()];
            let s = u();
            let k = (u() * 64.0) as i64 - 32;
            let c0 = [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])];
            let c = [c0[0], f64::from_bits((c0[1].to_bits() as i64 + k) as u64)];
            let t = [a, b, c];
            match (circumcenter(&t), circumcenter_exact(a, b, c)) {
                (Some(o), Some(_)) => {
                    decided += 1;
                    assert!(within_promise(o, &t), "{t:?} -> {o:?}");
                }
                (Some(o), None) => panic!("collinear {t:?} gave {o:?}"),
                (None, _) => {}
            }
        }
        // Up to 32 ulps off a line of unit length, the cross product is still some 2^50
        // times its error bound: all but the exactly collinear triples are decided.
        assert!(decided > 19_000, "decided {decided}");
    }

    #[test]
    fn inputs_outside_the_precondition_are_declined() {
        let cases = [
            // A difference that is not exact in one f64.
            [[0.1, 0.0], [-1e-17, 1.0], [2.0, 0.5]],
            // A difference below 2^-250.
            [[0.0, 0.0], [1e-80, 1.0], [2.0, 0.5]],
            // A difference above 2^250.
            [[0.0, 0.0], [1e80, 1.0], [2.0, 0.5]],
            // Collinear: the cross product is zero.
            [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]],
            // Not finite.
            [[0.0, 0.0], [f64::NAN, 1.0], [2.0, 0.5]],
            [[0.0, 0.0], [f64::INFINITY, 1.0], [2.0, 0.5]],
        ];
        for t in cases {
            assert_eq!(circumcenter(&t), None, "{t:?}");
        }
        // An ordinary triangle in range is decided, and right.
        let t = [[1.0, 1.0], [3.0, 1.0], [1.0, 5.0]];
        assert_eq!(circumcenter(&t), Some([2.0, 3.0]));
    }
}
