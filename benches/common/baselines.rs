//! The predicates the public `orient2d` / `incircle` are compared with: the `robust` crate,
//! and the *unguarded* forms, Shewchuk's filters without an underflow term, then `robust`
//! (exact only where no product underflows; the cost the guarded public functions must
//! match).

fn coord(p: [f64; 2]) -> robust::Coord<f64> {
    robust::Coord { x: p[0], y: p[1] }
}

pub fn robust_orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    robust::orient2d(coord(a), coord(b), coord(c))
}

pub fn robust_incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> f64 {
    robust::incircle(coord(a), coord(b), coord(c), coord(d))
}

/// Shewchuk's error bound for his floating-point orientation determinant (`ccwerrboundA`).
const CCW_ERRBOUND_A: f64 = (3.0 + 16.0 * f64::EPSILON / 2.0) * f64::EPSILON / 2.0;
/// The same for the in-circle determinant (`iccerrboundA`).
const ICC_ERRBOUND_A: f64 = (10.0 + 96.0 * f64::EPSILON / 2.0) * f64::EPSILON / 2.0;

fn sign_of(x: f64) -> u8 {
    // The same numbering as `Orientation` / `CirclePosition`: positive first.
    if x > 0.0 {
        0
    } else if x < 0.0 {
        1
    } else {
        2
    }
}

/// The unguarded orientation: Shewchuk's filter without an underflow term, then `robust`.
/// Exact only where no product underflows; the baseline of "no measurable slowdown" for the
/// public `orient2d`, which is exact for any finite input.
#[inline(always)]
pub fn orient_unguarded(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> u8 {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    let det = left - right;
    let bound = CCW_ERRBOUND_A * (left.abs() + right.abs());
    if det > bound {
        0
    } else if -det > bound {
        1
    } else {
        sign_of(robust_orient(a, b, c))
    }
}

/// The unguarded in-circle test, as [`orient_unguarded`].
#[inline(always)]
pub fn incircle_unguarded(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> u8 {
    let [adx, ady] = [a[0] - d[0], a[1] - d[1]];
    let [bdx, bdy] = [b[0] - d[0], b[1] - d[1]];
    let [cdx, cdy] = [c[0] - d[0], c[1] - d[1]];
    let (bdxcdy, cdxbdy) = (bdx * cdy, cdx * bdy);
    let alift = adx * adx + ady * ady;
    let (cdxady, adxcdy) = (cdx * ady, adx * cdy);
    let blift = bdx * bdx + bdy * bdy;
    let (adxbdy, bdxady) = (adx * bdy, bdx * ady);
    let clift = cdx * cdx + cdy * cdy;
    let det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * alift
        + (cdxady.abs() + adxcdy.abs()) * blift
        + (adxbdy.abs() + bdxady.abs()) * clift;
    let bound = ICC_ERRBOUND_A * permanent;
    if det > bound {
        0
    } else if -det > bound {
        1
    } else {
        sign_of(robust_incircle(a, b, c, d))
    }
}
