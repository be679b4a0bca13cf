//! The exact rational oracles the integration tests compare the engine with: every value
//! computed in `BigRational` from the `f64` inputs, so nothing is rounded.
#![allow(dead_code)] // each test file uses its own subset

use num_rational::BigRational;
use num_traits::Zero;

/// `x` as an exact rational.
pub fn rational(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

/// The orientation determinant of `a → b → c`: positive when counterclockwise.
pub fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> BigRational {
    let [ax, ay, bx, by, cx, cy] = [a[0], a[1], b[0], b[1], c[0], c[1]].map(rational);
    (&bx - &ax) * (&cy - &ay) - (&by - &ay) * (&cx - &ax)
}

/// Positive iff `d` is strictly inside the circle through the counterclockwise `a, b, c`.
pub fn incircle(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> BigRational {
    let row = |p: [f64; 2]| {
        let (x, y) = (
            rational(p[0]) - rational(d[0]),
            rational(p[1]) - rational(d[1]),
        );
        let lift = &x * &x + &y * &y;
        (x, y, lift)
    };
    let ((ax, ay, al), (bx, by, bl), (cx, cy, cl)) = (row(a), row(b), row(c));
    &al * (&bx * &cy - &by * &cx) - &bl * (&ax * &cy - &ay * &cx) + &cl * (&ax * &by - &ay * &bx)
}

/// The squared distance of `p` and `q`.
pub fn squared_distance(p: [f64; 2], q: [f64; 2]) -> BigRational {
    let (dx, dy) = (
        rational(p[0]) - rational(q[0]),
        rational(p[1]) - rational(q[1]),
    );
    &dx * &dx + &dy * &dy
}

/// Twice the signed area of the ring through `ring` (positive when counterclockwise); a
/// ring that repeats its first position at the end gives the same.
pub fn twice_area(ring: &[[f64; 2]]) -> BigRational {
    let v: Vec<[BigRational; 2]> = ring.iter().map(|p| p.map(rational)).collect();
    (0..v.len()).fold(BigRational::zero(), |acc, i| {
        let (a, b) = (&v[i], &v[(i + 1) % v.len()]);
        acc + (&a[0] * &b[1] - &a[1] * &b[0])
    })
}
