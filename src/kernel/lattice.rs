//! The in-circle determinant in `i128` for lattice input: the exact stage that decides
//! grids and their power-of-two scalings before the adaptive predicate's expensive stages.

/// The in-circle determinant in integers, when that is cheap: all eight coordinates are
/// integer multiples of one power of two `2^g`, below `2^62 · 2^g` in magnitude, and the
/// differences to `d` are below `2^30 · 2^g`. Then the determinant of the scaled differences
/// (positive scaling: same sign) is below `3 · 2^122` and `i128` holds it exactly.
///
/// Lattices (grids, cocircular integer points, their power-of-two scalings) give exact
/// zeros, which the adaptive predicate reaches only after its most expensive stages.
pub(super) fn lattice_incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Option<i128> {
    let coords = [a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]];
    // value = mantissa · 2^(exponent − 1075) with the implicit bit in the mantissa, for
    // normal values; subnormal ones (exponent field 0) are declined below.
    let parts = |x: f64| {
        let bits = x.to_bits();
        let mantissa = (bits & ((1 << 52) - 1)) | (1 << 52);
        let exponent = ((bits >> 52) & 0x7FF) as i32 - 1075;
        (mantissa, exponent)
    };
    let mut g = i32::MAX;
    for &x in &coords {
        if x != 0.0 {
            let (m, e) = parts(x);
            if e == -1075 {
                return None; // subnormal: the parts above would be wrong
            }
            g = g.min(e + m.trailing_zeros() as i32);
        }
    }
    if g == i32::MAX {
        return Some(0); // all zero
    }
    let mut int = [0i64; 8];
    for (k, &x) in coords.iter().enumerate() {
        if x != 0.0 {
            let (m, e) = parts(x);
            // x / 2^g = (m >> tz) · 2^(e + tz − g), an integer (g ≤ e + tz) below
            // 2^(53 + e − g): below 2^62 when e − g ≤ 9.
            if e - g > 9 {
                return None;
            }
            let tz = m.trailing_zeros();
            let v = ((m >> tz) << (e + tz as i32 - g)) as i64;
            int[k] = if x < 0.0 { -v } else { v };
        }
    }
    const LIMIT: i64 = 1 << 30;
    let mut diff = [0i64; 6];
    for k in 0..6 {
        diff[k] = int[k] - int[6 + k % 2];
        if diff[k].abs() >= LIMIT {
            return None;
        }
    }
    let [adx, ady, bdx, bdy, cdx, cdy] = diff.map(i128::from);
    let alift = adx * adx + ady * ady;
    let blift = bdx * bdx + bdy * bdy;
    let clift = cdx * cdx + cdy * cdy;
    Some(
        alift * (bdx * cdy - cdx * bdy)
            + blift * (cdx * ady - adx * cdy)
            + clift * (adx * bdy - bdx * ady),
    )
}
