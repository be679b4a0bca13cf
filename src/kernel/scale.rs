//! Exact scaling of inputs by powers of two: it changes no sign, and brings inputs whose
//! differences are huge or tiny back into the range where the filters' bounds hold.

/// `2^k` for `k` in `-1074..=1023` (exactly representable).
pub(super) fn pow2(k: i32) -> f64 {
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
