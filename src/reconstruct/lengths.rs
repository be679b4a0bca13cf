//! Rounded lengths, for the rules that are tolerances (the pruning's coverage, the noise
//! estimate, peeling's spacings), never for a combinatorial decision of the exactness
//! contract.

/// `|p − q|`, rounded: `sqrt(dx² + dy²)` (within about 2 ulps) where the sum of squares is
/// far from overflow and underflow, `hypot` otherwise. `hypot` is several times slower and
/// was the hottest arithmetic of the pruned axis (3 % of a noisy 10^6-point run). The
/// value depends on `|dx|` and `|dy|` alone, so on neither the order of `p` and `q` nor the
/// input order.
#[inline]
pub(crate) fn distance(p: [f64; 2], q: [f64; 2]) -> f64 {
    let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
    let squares = dx * dx + dy * dy;
    if (1e-300..1e300).contains(&squares) {
        squares.sqrt()
    } else {
        dx.hypot(dy)
    }
}

#[cfg(test)]
mod tests {
    use super::distance;

    #[test]
    fn the_fast_form_agrees_with_hypot_and_handles_every_range() {
        let cases = [
            ([0.0, 0.0], [3.0, 4.0], 5.0),
            ([1e200, 0.0], [-1e200, 0.0], 2e200),
            ([1e-200, 0.0], [0.0, 0.0], 1e-200),
            ([f64::MAX, 0.0], [-f64::MAX, 0.0], f64::INFINITY),
            ([0.0, 0.0], [0.0, 0.0], 0.0),
        ];
        for (p, q, expected) in cases {
            assert_eq!(distance(p, q), expected, "{p:?} {q:?}");
            assert_eq!(distance(q, p), expected);
        }
        let mut x = 0.1f64;
        for _ in 0..1000 {
            x = (x * 3.7 + 0.31) % 1.0;
            let (p, q) = ([x, 1.0 - x], [x * x, x / 3.0]);
            let (fast, reference) = (distance(p, q), (p[0] - q[0]).hypot(p[1] - q[1]));
            assert!((fast - reference).abs() <= 4.0 * f64::EPSILON * reference);
        }
        assert!(distance([f64::NAN, 0.0], [0.0, 0.0]).is_nan());
    }
}
