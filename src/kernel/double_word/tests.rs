//! The double-word stage against exact rationals: its bounds hold operation by operation
//! (also where products underflow or overflow), and its circumcenters of thin and nearly
//! collinear triangles are within 256 ulps of the exact ones, and decided almost always.

use num_rational::BigRational;
use num_traits::Signed;

use super::super::bounded::ulp;
use super::super::circumcenter::{circumcenter, circumcenter_exact, circumcenter_slow};
use super::super::poly::incircle_terms_points;
use super::super::scale::pow2;
use super::super::stats::Stage;
use super::*;

fn rat(x: f64) -> BigRational {
    BigRational::from_float(x).unwrap()
}

/// The exact value `hi + lo`.
fn value(x: &DoubleWord) -> BigRational {
    rat(x.hi) + rat(x.lo)
}

/// xorshift64*: deterministic and dependency-free.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A random `f64` of either sign with a random significand and an exponent in `lo..=hi`
    /// (clamped to the `f64` range, subnormals included); now and then zero.
    fn float(&mut self, lo: i32, hi: i32) -> f64 {
        if self.next() % 16 == 0 {
            return 0.0;
        }
        let e = lo + (self.next() % (hi - lo + 1) as u64) as i32;
        let m = 1.0 + self.unit();
        let sign = if self.next() % 2 == 0 { 1.0 } else { -1.0 };
        let half = e / 2;
        sign * m * pow2(half.clamp(-1074, 1023)) * pow2((e - half).clamp(-1074, 1023))
    }
}

/// Whether the bound of `x` holds for the exact value; a non-finite component claims nothing.
fn bound_holds(x: &DoubleWord, exact: &BigRational) -> bool {
    if !(x.hi.is_finite() && x.lo.is_finite() && x.e.is_finite()) {
        return true;
    }
    (value(x) - exact).abs() <= rat(x.e)
}

#[test]
fn the_constants_are_the_powers_of_two() {
    assert_eq!(TOLERANCE, 2f64.powi(-44));
    assert_eq!(WIDEN - 1.0, 2f64.powi(-45));
}

/// Chains of sums, products and quotients, each checked against the exact rationals, with
/// operands at ordinary, underflowing and overflowing magnitudes.
#[test]
fn every_operation_bounds_its_error() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let exponent_ranges = [(-8, 8), (-60, 60), (-560, -480), (-1074, -1000), (480, 530)];
    let mut checked = 0;
    for round in 0..3000 {
        let (lo, hi) = exponent_ranges[round % exponent_ranges.len()];
        let mut pool: Vec<(DoubleWord, BigRational)> = (0..4)
            .map(|_| {
                let x = rng.float(lo, hi);
                (DoubleWord::from_f64(x), rat(x))
            })
            .collect();
        for _ in 0..6 {
            let i = (rng.next() % pool.len() as u64) as usize;
            let j = (rng.next() % pool.len() as u64) as usize;
            let ((a, ea), (b, eb)) = (pool[i].clone(), pool[j].clone());
            let (got, exact) = match rng.next() % 6 {
                0 => (a.add(&b), &ea + &eb),
                1 => (a.sub(&b), &ea - &eb),
                2 => (a.mul(&b), &ea * &eb),
                3 => (a.twice(), &ea * rat(2.0)),
                4 => (a.leaf_sub(&b), &ea - &eb),
                _ => match a.div(&b) {
                    // A quotient is only formed when the divisor is proven non-zero.
                    Some(q) => (q, &ea / &eb),
                    None => continue,
                },
            };
            assert!(
                bound_holds(&got, &exact),
                "{a:?} {b:?} -> {got:?}, exact {exact}"
            );
            if let Some(sign) = got.sign() {
                let expected = if exact.is_positive() {
                    Sign::Positive
                } else {
                    Sign::Negative
                };
                assert_eq!(sign, expected, "{got:?}");
            }
            checked += 1;
            pool.push((got, exact));
        }
    }
    assert!(checked > 15_000, "only {checked} operations checked");
}

/// Whether each coordinate of `got` is within 256 ulps of its larger magnitude of the exact
/// circumcenter of `t`.
fn within_ulps(got: [f64; 2], t: &[[f64; 2]; 3]) -> bool {
    let exact = circumcenter_exact(t[0], t[1], t[2]).expect("not collinear");
    let tolerance = rat(256.0 * ulp(got[0].abs().max(got[1].abs())));
    (rat(got[0]) - exact.x()).abs() <= tolerance && (rat(got[1]) - exact.y()).abs() <= tolerance
}

/// Three points `h` and `2h` apart along a direction bent by `bend` at the first: nearly
/// collinear for a small `bend`.
fn thin_triangle(a: [f64; 2], direction: f64, h: f64, bend: f64) -> [[f64; 2]; 3] {
    let step = |angle: f64, len: f64| [a[0] + len * angle.cos(), a[1] + len * angle.sin()];
    [a, step(direction, h), step(direction + bend, 2.0 * h)]
}

/// Thin triangles at scales from `2^-1000` to `2^1000`, near and far from the origin: the
/// public construction's slow path decides almost all of them in double words (not in
/// `BigInt`), always within 256 ulps; where the stage declines it is the exact answer.
#[test]
fn thin_triangles_are_decided_in_double_words() {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let scales = [0, -1000, -500, -60, 60, 500, 1000];
    let (mut slow, mut double_word, mut exact) = (0, 0, 0);
    for round in 0..7000 {
        let s = pow2(scales[round % scales.len()]);
        let far = [0.0, 1.0, 1e6][round / 7 % 3];
        let a = [(far + rng.unit()) * s, (rng.unit() - 0.5) * s];
        let h = s * 1e-6 * (1.0 + rng.unit());
        let bend = 10f64.powf(-13.0 + 11.0 * rng.unit());
        let t = thin_triangle(a, rng.unit() * 7.0, h, bend);
        if circumcenter_exact(t[0], t[1], t[2]).is_none() {
            continue;
        }
        if let Some(o) = super::circumcenter(&t) {
            assert!(within_ulps(o, &t), "{t:?}: {o:?}");
        }
        let public = circumcenter(t[0], t[1], t[2]).unwrap();
        assert!(within_ulps(public, &t), "{t:?}: {public:?}");
        if super::super::filter::circumcenter(&t).is_some() {
            continue;
        }
        slow += 1;
        match circumcenter_slow(t[0], t[1], t[2]) {
            (Some(o), Stage::DoubleWord) => {
                double_word += 1;
                assert!(within_ulps(o, &t));
            }
            (o, Stage::Exact) => {
                exact += 1;
                let rounded = circumcenter_exact(t[0], t[1], t[2]).unwrap().to_f64();
                assert_eq!(o, Some(rounded));
            }
            // Decided by the filter after a power-of-two rescale.
            _ => slow -= 1,
        }
    }
    assert!(slow > 3000, "only {slow} thin triangles failed the filter");
    assert!(exact * 1000 < slow, "{exact} of {slow} went to BigInt");
    assert!(double_word * 100 > 95 * slow, "{double_word} of {slow}");
}

/// Triples a few ulps off a line (and some on it): never a wrong circumcenter, and the
/// stage decides those that are not within about 2^-60 of collinear.
#[test]
fn nearly_collinear_triples_are_accurate() {
    let mut rng = Rng(0x0bad_cafe_f00d_d00d);
    let nudge = |x: f64, k: i64| f64::from_bits((x.to_bits() as i64 + k) as u64);
    let (mut tried, mut decided) = (0, 0);
    for round in 0..6000 {
        let scale = [1.0, 1e-3, 1e5, 3e-200, 7e250][round % 5];
        let a = [rng.unit() * scale, rng.unit() * scale];
        let b = [rng.unit() * scale, rng.unit() * scale];
        let u = rng.unit();
        let k = (rng.next() % 9) as i64 - 4;
        let c = [a[0] + u * (b[0] - a[0]), nudge(a[1] + u * (b[1] - a[1]), k)];
        let t = [a, b, c];
        if circumcenter_exact(a, b, c).is_none() {
            assert_eq!(super::circumcenter(&t), None);
            continue;
        }
        if let Some(o) = super::circumcenter(&t) {
            assert!(within_ulps(o, &t), "{t:?}: {o:?}");
        }
        // Through the construction's slow path, rescaled where the filter would be.
        if super::super::filter::circumcenter(&t).is_none() {
            match circumcenter_slow(a, b, c) {
                (Some(o), Stage::DoubleWord) => {
                    assert!(within_ulps(o, &t), "{t:?}: {o:?}");
                    tried += 1;
                    decided += 1;
                }
                (_, Stage::Exact) => tried += 1,
                _ => {}
            }
        }
    }
    assert!(decided * 100 > 90 * tried, "{decided} of {tried}");
}

/// Extreme and mixed magnitudes (subnormals, values near the largest `f64`, `1e-300` beside
/// `1e300`): the stage may decline, never errs.
#[test]
fn extreme_magnitudes_fail_safe() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for round in 0..6000 {
        let (lo, hi) = [(-1074, -1000), (1000, 1023), (-1074, 1023), (-30, 30)][round % 4];
        let t: [[f64; 2]; 3] = std::array::from_fn(|_| [rng.float(lo, hi), rng.float(lo, hi)]);
        if circumcenter_exact(t[0], t[1], t[2]).is_none() {
            continue;
        }
        if let Some(o) = super::circumcenter(&t) {
            assert!(within_ulps(o, &t), "{t:?}: {o:?}");
        }
    }
}

/// The exact in-circle sign of `a, b, c, d`, in rationals.
fn incircle_exact(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> Sign {
    let [a, b, c, d] = [a, b, c, d].map(|p| p.map(rat));
    let [det] = incircle_terms_points(&a, &b, &c, &d);
    det.sign().unwrap_or(Sign::Zero)
}

/// The configurations that reach the exact stages in the triangulation of 10^8 random
/// samples of a star `r = 1 + 0.3 cos 5t`: two samples `a`, `c` a spacing `h` apart, a
/// far sample `b`, and `d` on the circle through them near `b` (rounded to `f64`), where
/// the determinant is within `2^-48` of its permanent and the `f64` filters decline. The
/// double-word sign is the exact one and it is always decided; exactly cocircular points
/// (zero determinants) never are, and any magnitudes fail safe.
#[test]
fn nearly_cocircular_samples_are_decided_in_double_words() {
    let mut rng = Rng(0x51ed_2701_c0ff_ee11);
    let star = |t: f64| {
        let r = 1.0 + 0.3 * (5.0 * t).cos();
        [r * t.cos(), r * t.sin()]
    };
    let lift = |p: [f64; 2]| p[0] * p[0] + p[1] * p[1];
    let mut hard = 0;
    for round in 0..3000 {
        let h = [1e-6, 1e-7, 1e-8][round % 3];
        let (t0, t1) = (rng.unit() * 7.0, rng.unit() * 7.0);
        let (a, b, c) = (star(t0), star(t1), star(t0 + h * (0.2 + rng.unit())));
        // The circumcenter of a, b, c in f64, and d on that circle a little way from b.
        let ([bx, by], [cx, cy]) = ([b[0] - a[0], b[1] - a[1]], [c[0] - a[0], c[1] - a[1]]);
        let den = 2.0 * (bx * cy - by * cx);
        let (bb, cc) = (lift([bx, by]), lift([cx, cy]));
        let o = [
            a[0] + (cy * bb - by * cc) / den,
            a[1] + (bx * cc - cx * bb) / den,
        ];
        let radius = lift([b[0] - o[0], b[1] - o[1]]).sqrt();
        let angle = (b[1] - o[1]).atan2(b[0] - o[0]) + (rng.unit() - 0.5) * 1e-5 / radius;
        let d = [o[0] + radius * angle.cos(), o[1] + radius * angle.sin()];
        let rel = [a, b, c].map(|p| [p[0] - d[0], p[1] - d[1]]);
        let cross = |p: [f64; 2], q: [f64; 2]| p[0] * q[1] - p[1] * q[0];
        let cross_abs = |p: [f64; 2], q: [f64; 2]| (p[0] * q[1]).abs() + (p[1] * q[0]).abs();
        let [x, y, z] = rel;
        let det = lift(x) * cross(y, z) + lift(y) * cross(z, x) + lift(z) * cross(x, y);
        let permanent =
            lift(x) * cross_abs(y, z) + lift(y) * cross_abs(z, x) + lift(z) * cross_abs(x, y);
        if det.abs() < permanent * 2f64.powi(-48) {
            hard += 1;
        }
        let exact = incircle_exact(a, b, c, d);
        match incircle(a, b, c, d) {
            Some(sign) => assert_eq!(sign, exact, "{a:?} {b:?} {c:?} {d:?}"),
            None => panic!("undecided ({exact:?}): {a:?} {b:?} {c:?} {d:?}"),
        }
    }
    assert!(hard > 2500, "only {hard} of 3000 tests beyond the filters");

    // Exactly cocircular: the corners of a rectangle and lattice points on a circle.
    for scale in [1.0, 2f64.powi(-30), 2f64.powi(40), 2f64.powi(-1000)] {
        let s = |p: [f64; 2]| p.map(|x| x * scale);
        let on_circle = [[5.0, 0.0], [3.0, 4.0], [0.0, 5.0], [-4.0, -3.0]];
        let rect = [[0.0, 0.0], [3.0, 0.0], [3.0, 1.5], [0.0, 1.5]];
        for [a, b, c, d] in [on_circle, rect] {
            assert_eq!(incircle(s(a), s(b), s(c), s(d)), None, "scale {scale}");
        }
    }

    // Any finite magnitudes: a decided sign is the exact one.
    for round in 0..3000 {
        let (lo, hi) = [(-1074, -1000), (480, 530), (-300, 300)][round % 3];
        let p = |rng: &mut Rng| [rng.float(lo, hi), rng.float(lo, hi)];
        let [a, b, c] = [p(&mut rng), p(&mut rng), p(&mut rng)];
        let d = [a[0] + b[0] - c[0], a[1]];
        if [d[0], d[1]].iter().any(|x| !x.is_finite()) {
            continue;
        }
        if let Some(sign) = incircle(a, b, c, d) {
            assert_eq!(sign, incircle_exact(a, b, c, d), "{a:?} {b:?} {c:?} {d:?}");
        }
    }
}
