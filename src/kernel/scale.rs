//! Exact scaling of inputs by powers of two: it changes no sign, and brings inputs whose
//! differences are huge or tiny back into the range where the filters' bounds hold.

/// `2^k` for `k` in `-1074..=1023` (exactly representable).
pub(crate) fn pow2(k: i32) -> f64 {
    if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        f64::from_bits(1u64 << (k + 1074).max(0))
    }
}

/// `floor(log2 |x|)` for a normal `x`; `-1023` for zero and subnormals.
pub(super) fn exponent(x: f64) -> i32 {
    ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023
}

/// The points times `2^-k`, if every product is exact (no overflow, no bits lost below the
/// normal range).
pub(super) fn scale<const N: usize>(points: [[f64; 2]; N], k: i32) -> Option<[[f64; 2]; N]> {
    let (down, back) = (pow2(-k), pow2(k));
    let mut scaled = points;
    for c in scaled.iter_mut().flatten() {
        let s = *c * down;
        // Scaling back by 2^k is exact here, so a round trip detects any rounding.
        if s * back != *c {
            return None;
        }
        *c = s;
    }
    Some(scaled)
}

/// For the semi-static filter: the points scaled by `2^-k` where `2^k` is the largest
/// coordinate difference from the first point rounded down to a power of two (every leaf of
/// the scaled polynomials is then below 4), and `k`; `None` if that difference is already
/// in `[2^lo, 2^(hi − 1))` (rescaling would not help), zero or not finite, or if the
/// scaling is not exact.
pub(super) fn rescale<const N: usize>(
    points: [[f64; 2]; N],
    (lo, hi): (i32, i32),
) -> Option<([[f64; 2]; N], i32)> {
    let p0 = points[0];
    let spread = points.iter().fold(0.0f64, |m, p| {
        m.max((p[0] - p0[0]).abs()).max((p[1] - p0[1]).abs())
    });
    if !(spread > 0.0 && spread < f64::INFINITY) {
        return None;
    }
    let k = exponent(spread);
    if (lo..hi - 1).contains(&k) {
        return None;
    }
    scale(points, k).map(|s| (s, k))
}

/// Magnitudes in this range are evaluated unscaled by the running-error filter: even
/// degree-10 terms of coordinate differences then stay far from overflow, and far from
/// underflow unless the differences themselves are tiny.
const UNSCALED_MIN: f64 = 9.094947017729282e-13; // 2^-40
const UNSCALED_MAX: f64 = 1099511627776.0; // 2^40

/// For the running-error filter: scales all points by one power of two `2^-k` such that
/// the largest coordinate magnitude falls in `[1, 2)`, when their magnitudes are outside
/// `[2^-40, 2^40]` and the scaling is exact for every coordinate. Returns the points and `k`
/// (original = scaled · 2^k).
pub(super) fn normalize<const N: usize>(points: [[f64; 2]; N]) -> ([[f64; 2]; N], i32) {
    let max = points.iter().flatten().fold(0.0f64, |m, c| m.max(c.abs()));
    if !max.is_finite() || max == 0.0 || (UNSCALED_MIN..=UNSCALED_MAX).contains(&max) {
        return (points, 0);
    }
    let k = exponent(max);
    match scale(points, k) {
        Some(scaled) => (scaled, k),
        None => (points, 0),
    }
}

/// `floor(log2 |x|)` for a finite non-zero `x`, subnormals included.
pub(crate) fn log2_floor(x: f64) -> i32 {
    let bits = x.to_bits() & !(1u64 << 63);
    let biased = (bits >> 52) as i32;
    if biased == 0 {
        // Subnormal: x = fraction · 2^-1074, its leading bit gives the exponent.
        63 - bits.leading_zeros() as i32 - 1074
    } else {
        biased - 1023
    }
}

/// The exponents `floor(log2 |x|)` of non-zero coordinates for which the adaptive
/// predicates of `robust` are exact (no underflow or overflow in their expansions):
/// magnitudes 2^-142 ..= 2^201, the upper bound one binade short.
pub(super) const ADAPTIVE_EXPONENTS: (i32, i32) = (-142, 200);

/// The smallest non-zero and the largest coordinate magnitude of a set of finite points:
/// what decides whether they fit the adaptive predicates' range, after which power of two.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Magnitudes {
    /// Smallest non-zero `|x|` (infinite if every coordinate is zero).
    min: f64,
    /// Largest `|x|`.
    max: f64,
}

impl Magnitudes {
    /// No coordinate yet.
    pub(crate) const NONE: Magnitudes = Magnitudes {
        min: f64::INFINITY,
        max: 0.0,
    };

    /// Takes one finite coordinate into account.
    #[inline(always)]
    pub(crate) fn include(&mut self, x: f64) {
        let a = x.abs();
        if a != 0.0 && a < self.min {
            self.min = a;
        }
        if a > self.max {
            self.max = a;
        }
    }

    /// The largest magnitude.
    pub(crate) fn max(&self) -> f64 {
        self.max
    }

    /// Of a few points.
    pub(super) fn of<const N: usize>(points: &[[f64; 2]; N]) -> Magnitudes {
        let mut m = Magnitudes::NONE;
        for &x in points.iter().flatten() {
            m.include(x);
        }
        m
    }

    /// The power of two `2^s` that brings every non-zero magnitude into the adaptive
    /// predicates' exponent range [`ADAPTIVE_EXPONENTS`]: `Some(0)` if they already lie in
    /// it, otherwise the shift that centres the exponents in the range, or `None` if their
    /// spread is wider than the range. Multiplying by that `2^s` is exact: every product is
    /// normal and finite, at least `2^-142` and below `2^201`.
    pub(crate) fn adaptive_shift(&self) -> Option<i32> {
        if self.max == 0.0 || !self.max.is_finite() {
            return (self.max == 0.0).then_some(0);
        }
        let (lo, hi) = (log2_floor(self.min), log2_floor(self.max));
        let (min_e, max_e) = ADAPTIVE_EXPONENTS;
        if lo >= min_e && hi <= max_e {
            return Some(0);
        }
        self.centring_shift()
    }

    /// The power of two `2^s` that centres the exponents of every non-zero magnitude in the
    /// adaptive predicates' range [`ADAPTIVE_EXPONENTS`], whether or not they already lie in
    /// it: `None` if their spread is wider than the range, `Some(0)` if every coordinate is
    /// zero. A function of the points up to scale: the points times `2^k` (exactly) get
    /// `s − k`, so the centred copies are the same numbers. Multiplying by `2^s` is exact,
    /// as for [`adaptive_shift`](Self::adaptive_shift).
    pub(crate) fn centring_shift(&self) -> Option<i32> {
        if self.max == 0.0 || !self.max.is_finite() {
            return (self.max == 0.0).then_some(0);
        }
        let (lo, hi) = (log2_floor(self.min), log2_floor(self.max));
        let (min_e, max_e) = ADAPTIVE_EXPONENTS;
        if hi - lo > max_e - min_e {
            return None;
        }
        // Centre [lo, hi] in [min_e, max_e]; the floor division keeps both ends inside.
        Some((min_e + max_e - lo - hi).div_euclid(2))
    }
}

/// `x · 2^s` rounded once to the nearest `f64` (ties to even), for any `x` and any `s` in
/// `-2000..=2000`: exact wherever the product is normal (or zero), infinite beyond the
/// `f64` range, and a subnormal result rounded from the exact product, never twice (a
/// product by `2^s` in two halves would round in both where the first lands below the
/// normal range). A subnormal result is built from its integer number of units of
/// `2^-1074`, without arithmetic on subnormal numbers (each costs a microcode assist).
pub(crate) fn scale_rounded(x: f64, s: i32) -> f64 {
    if x == 0.0 || !x.is_finite() || s >= 0 {
        // Upwards every step is exact until the result overflows, which it then rounds
        // to infinity as the exact product does (53 bits beyond `f64::MAX` are at least
        // `2^1024`).
        return if s >= 0 { shift_by(x, s) } else { x };
    }
    let e = log2_floor(x);
    if e + s >= -1022 {
        return shift_by(x, s);
    }
    // The result in units of 2^-1074, `q < 2^52`: below 1/2 it rounds to zero; otherwise
    // it is normal and exact (every intermediate lies between `x` and `q`, both exact).
    if e + s + 1074 < -1 {
        return 0.0f64.copysign(x);
    }
    let q = shift_by(x.abs(), s + 1074);
    // The nearest integer, ties to even: the sum's unit is 1 (`2^52 ≤ q + 2^52 < 2^53`).
    let units = (q + TWO_52) - TWO_52;
    // Up to 2^52 units, which are the bits of the smallest normal number, 2^-1022.
    f64::from_bits(units as u64).copysign(x)
}

/// `2^52`.
pub(crate) const TWO_52: f64 = 4503599627370496.0;

/// `x · 2^s` for a shift from [`Magnitudes::adaptive_shift`] (exact there).
#[inline(always)]
pub(crate) fn shift_by(x: f64, s: i32) -> f64 {
    // 2^s may itself be outside the f64 range (s up to ±1100): apply it in two halves,
    // each exact, since the final product is normal and every intermediate lies between
    // the input and the result.
    let half = s / 2;
    x * pow2(half) * pow2(s - half)
}
