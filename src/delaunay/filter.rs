//! Filtered predicates for the construction. Every answer equals the exact one.
//!
//! Two filters in front of the exact adaptive predicates ([`crate::predicates`]):
//! - [`StaticFilter`]: all points of a merge lie in a known box, so every coordinate
//!   difference, product and sum of the evaluation has a bound computed once per merge, and
//!   with it the error bound. A test then costs one floating-point evaluation.
//! - [`ccw`] and [`inside`]: Shewchuk's semi-static filter, the error bound scaled by the
//!   permanent of this evaluation.
//!
//! The bounds are Shewchuk's `ccwerrboundA` and `iccerrboundA` for exactly this evaluation
//! order. They assume no intermediate underflow or overflow, which the input envelope
//! guarantees: coordinate differences are 0 or in [2^-194, 2^202], so products of up to four
//! of them and their sums stay between 2^-776 and 2^812.

use crate::predicates::{incircle, orient2d, CirclePosition, Orientation};

/// 2^-53: half an ulp of 1.
const EPSILON: f64 = 1.0 / 9_007_199_254_740_992.0;
const CCW_BOUND: f64 = (3.0 + 16.0 * EPSILON) * EPSILON;
const INCIRCLE_BOUND: f64 = (10.0 + 96.0 * EPSILON) * EPSILON;

/// Is `c` strictly left of the directed line `a → b`?
#[inline(always)]
pub fn ccw(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    let det = left - right;
    let bound = CCW_BOUND * (left.abs() + right.abs());
    if det > bound {
        true
    } else if -det > bound {
        false
    } else {
        exact_ccw(a, b, c)
    }
}

#[inline(never)]
fn exact_ccw(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    orient2d(a, b, c) == Orientation::CounterClockwise
}

/// Shewchuk's floating-point in-circle determinant and its error bound: when `|det|`
/// exceeds the bound, its sign is the exact one.
#[inline(always)]
fn incircle_with_bound(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> (f64, f64) {
    let adx = a[0] - d[0];
    let bdx = b[0] - d[0];
    let cdx = c[0] - d[0];
    let ady = a[1] - d[1];
    let bdy = b[1] - d[1];
    let cdy = c[1] - d[1];

    let bdxcdy = bdx * cdy;
    let cdxbdy = cdx * bdy;
    let alift = adx * adx + ady * ady;
    let cdxady = cdx * ady;
    let adxcdy = adx * cdy;
    let blift = bdx * bdx + bdy * bdy;
    let adxbdy = adx * bdy;
    let bdxady = bdx * ady;
    let clift = cdx * cdx + cdy * cdy;

    let det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    let permanent = (bdxcdy.abs() + cdxbdy.abs()) * alift
        + (cdxady.abs() + adxcdy.abs()) * blift
        + (adxbdy.abs() + bdxady.abs()) * clift;
    (det, INCIRCLE_BOUND * permanent)
}

/// Is `d` strictly inside the circle through the counterclockwise `a, b, c`?
#[inline(always)]
pub fn inside(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let (det, bound) = incircle_with_bound(a, b, c, d);
    if det > bound {
        true
    } else if -det > bound {
        false
    } else {
        exact_inside(a, b, c, d)
    }
}

/// Are `a, b, c, d` exactly cocircular (`a, b, c` counterclockwise)? The same filter as
/// [`inside`]; nearly every call is decided by it, since exact cocircularity is rare outside
/// lattices, where [`lattice_incircle`] decides it cheaply.
#[inline(always)]
pub fn cocircular(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let (det, bound) = incircle_with_bound(a, b, c, d);
    if det.abs() > bound {
        false
    } else {
        exact_cocircular(a, b, c, d)
    }
}

#[inline(never)]
fn exact_cocircular(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    match lattice_incircle(a, b, c, d) {
        Some(det) => det == 0,
        None => incircle(a, b, c, d) == CirclePosition::On,
    }
}

#[inline(never)]
fn exact_inside(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    match lattice_incircle(a, b, c, d) {
        Some(det) => det > 0,
        None => incircle(a, b, c, d) == CirclePosition::Inside,
    }
}

/// The in-circle determinant in integers, when that is cheap: all eight coordinates are
/// integer multiples of one power of two `2^g`, below `2^62 · 2^g` in magnitude, and the
/// differences to `d` are below `2^30 · 2^g`. Then the determinant of the scaled differences
/// (positive scaling: same sign) is below `3 · 2^122` and `i128` holds it exactly.
///
/// Lattices (grids, cocircular integer points, their power-of-two scalings) give exact
/// zeros, which the adaptive predicate reaches only after its most expensive stages.
fn lattice_incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Option<i128> {
    let coords = [a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]];
    // Coordinates are zero or normal (the envelope excludes subnormals): value =
    // mantissa · 2^(exponent − 1075) with the implicit bit in the mantissa.
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

/// Error bounds valid for points in a box of width `w` and height `h`.
///
/// Rounding is monotone: with every coordinate difference at most the (rounded) box extent
/// in magnitude, every rounded product, sum and permanent of the evaluation is at most the
/// same expression evaluated on the extents. So the static bound is at least the semi-static
/// one of any test inside the box, and deciding with it is as safe.
#[derive(Debug, Clone, Copy)]
pub struct StaticFilter {
    ccw: f64,
    incircle: f64,
}

impl StaticFilter {
    /// `w`, `h`: the extents `max − min` of the coordinates, evaluated in floating point.
    #[inline]
    pub fn for_box(w: f64, h: f64) -> StaticFilter {
        let wh = w * h; // bounds |Δx·Δy| for any two differences
        let lift = w * w + h * h; // bounds Δx² + Δy²
        let pair = wh + wh;
        let permanent = pair * lift + pair * lift + pair * lift;
        StaticFilter {
            ccw: CCW_BOUND * pair,
            incircle: INCIRCLE_BOUND * permanent,
        }
    }

    /// [`ccw`] for points in the box.
    #[inline(always)]
    pub fn ccw(&self, a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
        let det = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]);
        if det > self.ccw {
            true
        } else if -det > self.ccw {
            false
        } else {
            ccw(a, b, c)
        }
    }

    /// The sign of an orientation determinant `r × a` of [`Lifted`] differences (Shewchuk's
    /// evaluation of `orient2d(r, a, origin)`), if the bound decides it: `Some(true)` for
    /// counterclockwise `origin, r, a`.
    #[inline(always)]
    pub fn orientation(&self, cross: f64) -> Option<bool> {
        if cross > self.ccw {
            Some(true)
        } else if -cross > self.ccw {
            Some(false)
        } else {
            None
        }
    }

    /// Is `b` inside the circle through the counterclockwise `origin, r, a`, if the bound
    /// decides it? All three are [`Lifted`] differences to the origin and `cross_ra = r × a`.
    ///
    /// This is Shewchuk's evaluation of the in-circle determinant with the origin as the
    /// fourth point: `incircle(origin, r, a, b) = −det[r; a; b]`, the rows lifted (a cyclic
    /// shift of the four rows flips the sign), evaluated in his order, so his bound holds.
    #[inline(always)]
    pub fn in_circle(&self, r: &Lifted, a: &Lifted, b: &Lifted, cross_ra: f64) -> Option<bool> {
        let det =
            r.lift * (a.x * b.y - b.x * a.y) + a.lift * (b.x * r.y - r.x * b.y) + b.lift * cross_ra;
        if det > self.incircle {
            Some(false)
        } else if -det > self.incircle {
            Some(true)
        } else {
            None
        }
    }
}

/// A point as a difference to an origin, with its lifting `x² + y²`.
#[derive(Debug, Clone, Copy)]
pub struct Lifted {
    pub x: f64,
    pub y: f64,
    pub lift: f64,
}

impl Lifted {
    #[inline(always)]
    pub fn new(p: [f64; 2], origin: [f64; 2]) -> Lifted {
        let (x, y) = (p[0] - origin[0], p[1] - origin[1]);
        Lifted {
            x,
            y,
            lift: x * x + y * y,
        }
    }

    /// `self × a`, evaluated as Shewchuk's `orient2d(self, a, origin)`.
    #[inline(always)]
    pub fn cross(&self, a: &Lifted) -> f64 {
        self.x * a.y - self.y * a.x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic stream of uniform numbers in [0, 1) (a 64-bit LCG's high bits).
    fn uniform_stream(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed;
        move || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    fn ulp_step(x: f64, k: i64) -> f64 {
        f64::from_bits((x.to_bits() as i64 + k) as u64)
    }

    #[test]
    fn the_static_filter_agrees_with_the_exact_predicates() {
        let mut next = uniform_stream(5);
        for round in 0..20_000 {
            // A box at some offset and scale; points inside it, some snapped to a coarse grid
            // (exact degeneracies), some nudged off a circle through three of them.
            let scale = [1e-6, 1.0, 1e6][round % 3];
            let (x0, y0) = (next() * 100.0, next() * -100.0);
            let mut pick = || {
                let (u, v) = (next(), next());
                if round % 2 == 0 {
                    [
                        x0 + (u * 4.0).floor() * scale / 4.0,
                        y0 + (v * 4.0).floor() * scale / 4.0,
                    ]
                } else {
                    [x0 + u * scale, y0 + v * scale]
                }
            };
            let pts = [pick(), pick(), pick(), pick()];
            let lo = |k: usize| pts.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
            let hi = |k: usize| pts.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
            let f = StaticFilter::for_box(hi(0) - lo(0), hi(1) - lo(1));
            let [a, b, c, d] = pts;
            let exact = orient2d(a, b, c);
            assert_eq!(f.ccw(a, b, c), exact == Orientation::CounterClockwise);
            // The same tests relative to a: orient(a, b, c) is b' × c'.
            let (rb, rc, rd) = (Lifted::new(b, a), Lifted::new(c, a), Lifted::new(d, a));
            if let Some(ccw) = f.orientation(rb.cross(&rc)) {
                assert_eq!(ccw, exact == Orientation::CounterClockwise);
            }
            let (a, b) = if exact == Orientation::Clockwise {
                (b, a)
            } else {
                (a, b)
            };
            let (rb, rc, rd) = if exact == Orientation::Clockwise {
                (Lifted::new(b, a), Lifted::new(c, a), Lifted::new(d, a))
            } else {
                (rb, rc, rd)
            };
            if exact != Orientation::Collinear {
                let inside_exact = incircle(a, b, c, d) == CirclePosition::Inside;
                if let Some(inside) = f.in_circle(&rb, &rc, &rd, rb.cross(&rc)) {
                    assert_eq!(inside, inside_exact, "{a:?} {b:?} {c:?} {d:?}");
                }
            }
        }
    }

    #[test]
    fn the_lattice_path_is_exact_or_declines() {
        let mut s = 9u64;
        let mut next = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            s >> 11
        };
        let mut decided = 0;
        for round in 0..50_000 {
            let span = [4, 1 << 20, 1 << 29, 1 << 31, 1 << 40][round % 5];
            let offset = [0.0, 1e6, -3.5, 2f64.powi(60)][round / 5 % 4];
            let scale = 2f64.powi([0, -40, 30, -120][round / 20 % 4]);
            let mut pick = || {
                [
                    (offset + (next() % span) as f64 - (span / 2) as f64) * scale,
                    (offset + (next() % span) as f64) * scale,
                ]
            };
            let (a, b, c, d) = (pick(), pick(), pick(), pick());
            if let Some(det) = lattice_incircle(a, b, c, d) {
                decided += 1;
                let expected = match incircle(a, b, c, d) {
                    CirclePosition::Inside => 1,
                    CirclePosition::On => 0,
                    CirclePosition::Outside => -1,
                };
                assert_eq!(det.signum(), expected, "{a:?} {b:?} {c:?} {d:?}");
            }
        }
        assert!(decided > 10_000, "the lattice path decides small lattices");
    }

    #[test]
    fn agrees_with_the_exact_predicates_near_degeneracy() {
        let mut next = uniform_stream(3);
        for _ in 0..20_000 {
            // Nearly collinear: c on the line a→b, nudged by a few ulps.
            let a = [next(), next()];
            let b = [next() * 1e3, next() * 1e-3];
            let t = next();
            let c = [
                ulp_step(a[0] + t * (b[0] - a[0]), (next() * 9.0) as i64 - 4),
                ulp_step(a[1] + t * (b[1] - a[1]), (next() * 9.0) as i64 - 4),
            ];
            assert_eq!(
                ccw(a, b, c),
                orient2d(a, b, c) == Orientation::CounterClockwise
            );
            // Nearly cocircular: four points on the unit circle, nudged.
            let ang = |u: f64| [u.cos(), u.sin()];
            let (u, v, w) = (next(), next() + 2.0, next() + 4.0);
            let d = ang(next() * 6.0);
            let d = [ulp_step(d[0], (next() * 5.0) as i64 - 2), d[1]];
            let (pa, pb, pc) = (ang(u), ang(v), ang(w));
            assert_eq!(
                inside(pa, pb, pc, d),
                incircle(pa, pb, pc, d) == CirclePosition::Inside
            );
            assert_eq!(
                cocircular(pa, pb, pc, d),
                incircle(pa, pb, pc, d) == CirclePosition::On
            );
            let grid = |x: f64| (x * 4.0).floor();
            let (pa, pb, pc, d) = (
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
                [grid(next()), grid(next())],
            );
            assert_eq!(
                ccw(pa, pb, pc),
                orient2d(pa, pb, pc) == Orientation::CounterClockwise
            );
            if ccw(pa, pb, pc) {
                assert_eq!(
                    inside(pa, pb, pc, d),
                    incircle(pa, pb, pc, d) == CirclePosition::Inside
                );
                assert_eq!(
                    cocircular(pa, pb, pc, d),
                    incircle(pa, pb, pc, d) == CirclePosition::On
                );
            }
        }
    }
}
