//! The polynomials of the derived predicates, written once and generic over the number type.
//!
//! Divisions are avoided: with a triangle translated to its first vertex `t0`,
//! `b = t1 − t0`, `c = t2 − t0`, the circumcenter is `O = t0 + (ux, uy) / d` with
//! `d = 2 (bx·cy − by·cx)`, `ux = cy·|b|² − by·|c|²`, `uy = bx·|c|² − cx·|b|²`; a predicate on
//! `O − p` is evaluated on `d·(O − p) = d·(t0 − p) + u` and its sign corrected by the sign of
//! `d`, which is the triangle's orientation.
//!
//! Input coordinates enter only through differences of two inputs ([`Arith::leaf_sub`]), the
//! leaves of every expression: the floating-point filter bounds its error in terms of them.

use super::arith::Arith;
pub(super) use super::circumcenter::{circ, circ_half, Circ};

/// A point in the number type `T`.
pub(super) type Pt<T> = [T; 2];

/// `p − q`, coordinates of input points: the leaves of every expression.
#[inline(always)]
pub(super) fn diff<T: Arith>(p: &Pt<T>, q: &Pt<T>) -> Pt<T> {
    [p[0].leaf_sub(&q[0]), p[1].leaf_sub(&q[1])]
}

#[inline(always)]
pub(super) fn norm2<T: Arith>(v: &Pt<T>) -> T {
    v[0].mul(&v[0]).add(&v[1].mul(&v[1]))
}

#[inline(always)]
pub(super) fn cross<T: Arith>(v: &Pt<T>, w: &Pt<T>) -> T {
    v[0].mul(&w[1]).sub(&v[1].mul(&w[0]))
}

/// `d·(O − p)` for the circumcenter `O = t0 + u/d` described by `c`.
#[inline(always)]
pub(super) fn scaled_offset<T: Arith>(c: &Circ<T>, t0: &Pt<T>, p: &Pt<T>) -> Pt<T> {
    let [dx, dy] = diff(t0, p);
    [c.d.mul(&dx).add(&c.ux), c.d.mul(&dy).add(&c.uy)]
}

/// `(b − a) × n` for `n = d·(O − a)` from [`scaled_offset`].
#[inline(always)]
pub(super) fn orient_from_offset<T: Arith>(n: &Pt<T>, a: &Pt<T>, b: &Pt<T>) -> T {
    cross(&diff(b, a), n)
}

/// `(b − a) × d·(O − a)` (degree 4) for the circumcenter `c` of a triangle with first vertex
/// `t0`: times the sign of `d`, the orientation of `(a, b, O)`.
#[inline(always)]
pub(super) fn orient_from_circ<T: Arith>(c: &Circ<T>, t0: &Pt<T>, a: &Pt<T>, b: &Pt<T>) -> T {
    orient_from_offset(&scaled_offset(c, t0, a), a, b)
}

/// `[d, (b − a) × d·(O − a)]` (degrees 2 and 4): the orientation of `(a, b, O)` is the sign
/// of the product.
#[inline(always)]
pub(super) fn orient_terms<T: Arith>(a: &Pt<T>, b: &Pt<T>, tri: &[Pt<T>; 3]) -> [T; 2] {
    let c = circ(tri);
    let v = orient_from_circ(&c, &tri[0], a, b);
    [c.d, v]
}

/// `[d_s, d_o, d_s·(O_s − p) · d_o·(O_o − p)]` (degrees 2, 2 and 6).
#[inline(always)]
pub(super) fn dot_terms<T: Arith>(p: &Pt<T>, source: &[Pt<T>; 3], other: &[Pt<T>; 3]) -> [T; 3] {
    let cs = circ(source);
    let co = circ(other);
    let ns = scaled_offset(&cs, &source[0], p);
    let no = scaled_offset(&co, &other[0], p);
    let v = ns[0].mul(&no[0]).add(&ns[1].mul(&no[1]));
    [cs.d, co.d, v]
}

/// [`dot_terms`] when `p` is the first vertex of both triangles (the offsets `t0 − p`
/// vanish), halved: `[d_s/2, d_o/2, u_s · u_o]` (degrees 2, 2 and 6), the same signs.
#[inline(always)]
pub(super) fn dot_terms_at_vertex<T: Arith>(source: &[Pt<T>; 3], other: &[Pt<T>; 3]) -> [T; 3] {
    let (xs, uxs, uys) = circ_half(source);
    let (xo, uxo, uyo) = circ_half(other);
    let v = uxs.mul(&uxo).add(&uys.mul(&uyo));
    [xs, xo, v]
}

/// `(|t1 − t0|²·|t2 − t0|²·|t2 − t1|², (d/2)²)`: the squared circumradius is their quotient
/// divided by 4 (`R = |a||b||c| / (4·area)` and `|d| = 4·area`).
#[inline(always)]
fn radius_parts<T: Arith>(t: &[Pt<T>; 3]) -> (T, T) {
    let b = diff(&t[1], &t[0]);
    let c = diff(&t[2], &t[0]);
    let a = diff(&t[2], &t[1]);
    let n = norm2(&b).mul(&norm2(&c)).mul(&norm2(&a));
    let x = cross(&b, &c);
    (n, x.mul(&x))
}

/// `4·(R1² − R2²)·(d1/2)²·(d2/2)²` (degree 10), the sign of `R1 − R2`.
#[inline(always)]
pub(super) fn radius_terms<T: Arith>(t1: &[Pt<T>; 3], t2: &[Pt<T>; 3]) -> [T; 1] {
    let (n1, xx1) = radius_parts(t1);
    let (n2, xx2) = radius_parts(t2);
    [n1.mul(&xx2).sub(&n2.mul(&xx1))]
}

// ---------------------------------------------------------------------------------------
// Predicates on points in homogeneous coordinates `(X, Y, W)`, `W > 0`, the point
// `(X/W, Y/W)`: input samples (`W = 1`) and circumcenters alike (the crust's mixed points).

/// `(P, Q, R)` with `(P, Q) / R = p − o` and `R = W_p·W_o > 0`. With `W = 1` (the bounded
/// stage's points) this is the plain difference: multiplying by an exact 1 is exact.
#[inline(always)]
fn translated<T: Arith>(p: &[T; 3], o: &[T; 3]) -> [T; 3] {
    [
        p[0].mul(&o[2]).sub(&o[0].mul(&p[2])),
        p[1].mul(&o[2]).sub(&o[1].mul(&p[2])),
        p[2].mul(&o[2]),
    ]
}

/// `(b − a) × (c − a)` times the positive `R_b·R_c`: the orientation of `a → b → c`.
#[inline(always)]
pub(super) fn orient_homogeneous<T: Arith>(a: &[T; 3], b: &[T; 3], c: &[T; 3]) -> T {
    let [pb, qb, _] = translated(b, a);
    let [pc, qc, _] = translated(c, a);
    pb.mul(&qc).sub(&qb.mul(&pc))
}

/// The in-circle determinant of `a, b, c, d` translated to `d`, each row `(x, y, x² + y²)`
/// scaled by the positive `R²`: positive iff `d` is inside the circle through the
/// counterclockwise `a, b, c`.
#[inline(always)]
pub(super) fn incircle_homogeneous<T: Arith>(a: &[T; 3], b: &[T; 3], c: &[T; 3], d: &[T; 3]) -> T {
    // (x, y)/r is the point minus d: the row (x/r, y/r, (x² + y²)/r²) times r².
    let row = |p: &[T; 3]| {
        let [x, y, r] = translated(p, d);
        ([x.mul(&r), y.mul(&r)], norm2(&[x, y]))
    };
    let [(a, la), (b, lb), (c, lc)] = [row(a), row(b), row(c)];
    la.mul(&cross(&b, &c))
        .add(&lb.mul(&cross(&c, &a)))
        .add(&lc.mul(&cross(&a, &b)))
}

// ---------------------------------------------------------------------------------------
// Metric comparisons of input points (the NN-crust).

/// `|p − a|² − |p − b|² = (a − b)·((a − p) + (b − p))` (degree 2): the sign of the
/// comparison of the distances from `p` to `a` and `b`.
#[inline(always)]
pub(super) fn distance_terms<T: Arith>(p: &Pt<T>, a: &Pt<T>, b: &Pt<T>) -> [T; 1] {
    let (ab, ap, bp) = (diff(a, b), diff(a, p), diff(b, p));
    let sum = [ap[0].add(&bp[0]), ap[1].add(&bp[1])];
    [ab[0].mul(&sum[0]).add(&ab[1].mul(&sum[1]))]
}

/// `|p − q|² − |r − s|²` (degree 2): the order of the lengths of two segments.
#[inline(always)]
pub(super) fn length_terms<T: Arith>(p: &Pt<T>, q: &Pt<T>, r: &Pt<T>, s: &Pt<T>) -> [T; 1] {
    [norm2(&diff(p, q)).sub(&norm2(&diff(r, s)))]
}

/// `|p − q|² − 4^doublings · |r − s|²` (degree 2): the order of a length and a length scaled
/// by a power of two (each doubling of the square is an exact addition).
#[inline(always)]
pub(super) fn scaled_length_terms<T: Arith>(
    p: &Pt<T>,
    q: &Pt<T>,
    r: &Pt<T>,
    s: &Pt<T>,
    doublings: u32,
) -> [T; 1] {
    let mut scaled = norm2(&diff(r, s));
    for _ in 0..2 * doublings {
        scaled = scaled.add(&scaled);
    }
    [norm2(&diff(p, q)).sub(&scaled)]
}

/// `(s − p)·(q − p)` (degree 2).
#[inline(always)]
pub(super) fn dot_points_terms<T: Arith>(p: &Pt<T>, s: &Pt<T>, q: &Pt<T>) -> [T; 1] {
    let (sp, qp) = (diff(s, p), diff(q, p));
    [sp[0].mul(&qp[0]).add(&sp[1].mul(&qp[1]))]
}

// ---------------------------------------------------------------------------------------
// Orientation and in-circle of input points, for their exact stage outside the range of the
// adaptive predicates (`super::wide`).

/// `(a − c) × (b − c)` (degree 2): positive iff `a → b → c` is counterclockwise.
#[inline(always)]
pub(super) fn orient_terms_points<T: Arith>(a: &Pt<T>, b: &Pt<T>, c: &Pt<T>) -> [T; 1] {
    [cross(&diff(a, c), &diff(b, c))]
}

/// The in-circle determinant of `a, b, c, d` translated to `d` (degree 4): positive iff `d`
/// is inside the circle through the counterclockwise `a, b, c`.
#[inline(always)]
pub(super) fn incircle_terms_points<T: Arith>(
    a: &Pt<T>,
    b: &Pt<T>,
    c: &Pt<T>,
    d: &Pt<T>,
) -> [T; 1] {
    let (ad, bd, cd) = (diff(a, d), diff(b, d), diff(c, d));
    [norm2(&ad)
        .mul(&cross(&bd, &cd))
        .add(&norm2(&bd).mul(&cross(&cd, &ad)))
        .add(&norm2(&cd).mul(&cross(&ad, &bd)))]
}
