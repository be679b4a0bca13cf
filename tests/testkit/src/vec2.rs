//! Tiny 2D vector functions on `[f64; 2]`, private to the sampling module.

pub(crate) type P2 = [f64; 2];

pub(crate) fn add(a: P2, b: P2) -> P2 {
    [a[0] + b[0], a[1] + b[1]]
}

pub(crate) fn sub(a: P2, b: P2) -> P2 {
    [a[0] - b[0], a[1] - b[1]]
}

pub(crate) fn mul(a: P2, s: f64) -> P2 {
    [a[0] * s, a[1] * s]
}

pub(crate) fn dot(a: P2, b: P2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

pub(crate) fn norm2(a: P2) -> f64 {
    dot(a, a)
}

pub(crate) fn norm(a: P2) -> f64 {
    a[0].hypot(a[1])
}

pub(crate) fn dist(a: P2, b: P2) -> f64 {
    norm(sub(a, b))
}

pub(crate) fn dist2(a: P2, b: P2) -> f64 {
    norm2(sub(a, b))
}

/// `a` scaled to unit length; the zero vector stays zero.
pub(crate) fn unit(a: P2) -> P2 {
    let n = norm(a);
    if n > 0.0 {
        mul(a, 1.0 / n)
    } else {
        a
    }
}

/// `a` turned a quarter turn counter-clockwise: the left normal of a direction.
pub(crate) fn left(a: P2) -> P2 {
    [-a[1], a[0]]
}

/// Unsigned angle between two non-zero directions, in `[0, π]`.
pub(crate) fn angle_between(a: P2, b: P2) -> f64 {
    let cross = a[0] * b[1] - a[1] * b[0];
    cross.atan2(dot(a, b)).abs()
}

/// Axis-aligned bounding box `(min, max)` of a non-empty point set.
pub fn bbox(points: impl IntoIterator<Item = P2>) -> (P2, P2) {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}

/// Distance from `p` to the segment `ab` (to `a` when the segment is a point).
///
/// ```
/// use wdm_crust_testkit::segment_distance;
/// assert_eq!(segment_distance([1.0, 1.0], [0.0, 0.0], [2.0, 0.0]), 1.0);
/// assert_eq!(segment_distance([3.0, 0.0], [0.0, 0.0], [2.0, 0.0]), 1.0);
/// ```
pub fn segment_distance(p: P2, a: P2, b: P2) -> f64 {
    let d = sub(b, a);
    let len2 = norm2(d);
    let t = if len2 > 0.0 {
        (dot(sub(p, a), d) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    dist(p, add(a, mul(d, t)))
}
