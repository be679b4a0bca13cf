//! Unit tests of the filter internals and known answers; the property tests against an
//! independent rational reference live in `tests/predicates_exact.rs`.

use super::arith::{lift_exact, lift_filter, pow2, rational_to_f64, Arith, Bounded};
use super::*;
use num_bigint::BigInt;
use num_traits::{Pow, Signed, ToPrimitive};
use proptest::prelude::*;
use Orientation::{Clockwise, Collinear, CounterClockwise};

fn rat(x: f64) -> BigRational {
    BigRational::from_float(x).unwrap()
}

fn scale_tri(t: [[f64; 2]; 3], s: f64) -> [[f64; 2]; 3] {
    t.map(|p| [p[0] * s, p[1] * s])
}

// ----------------------------------------------------------------------------------------
// Known answers.

#[test]
fn right_triangles_at_every_scale() {
    for k in [-140, -77, -1, 0, 1, 40, 41, 100, 190] {
        let s = pow2(k);
        // Right angle at c; the hypotenuse a–b has midpoint (5, 3).
        let (a, b, c) = ([3.0 * s, 1.0 * s], [7.0 * s, 5.0 * s], [3.0 * s, 5.0 * s]);
        let mid = [5.0 * s, 3.0 * s];
        assert_eq!(circumcenter(a, b, c), Some(mid), "k = {k}");
        assert_eq!(circumcenter(b, a, c), Some(mid), "k = {k}");
        assert_eq!(circumcenter_exact(c, a, b).unwrap().to_f64(), mid);
        for tri in [[a, b, c], [a, c, b], [c, b, a]] {
            assert_eq!(orient2d_circumcenter(a, b, tri), Collinear, "k = {k}");
            assert_eq!(orient2d_circumcenter(b, a, tri), Collinear);
            // The line x = 3 upwards has the circumcenter (x = 5) on its right.
            assert_eq!(orient2d_circumcenter(a, c, tri), Clockwise);
            assert_eq!(orient2d_circumcenter(c, a, tri), CounterClockwise);
        }
        // One ulp off the hypotenuse line, on either side: opposite strict answers.
        let up = [a[0], f64::from_bits(a[1].to_bits() + 1)];
        let down = [a[0], f64::from_bits(a[1].to_bits() - 1)];
        let (ou, od) = (
            orient2d_circumcenter(up, b, [a, b, c]),
            orient2d_circumcenter(down, b, [a, b, c]),
        );
        assert_ne!(ou, Collinear);
        assert_ne!(od, Collinear);
        assert_ne!(ou, od);
    }
}

#[test]
fn collinear_and_non_finite_input_never_panics() {
    let line = [[0.0, 0.0], [1.0, 1.0], [3.0, 3.0]];
    let dup = [[1.0, 2.0], [1.0, 2.0], [5.0, 0.0]];
    let good = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
    for t in [line, dup] {
        assert_eq!(circumcenter(t[0], t[1], t[2]), None);
        assert_eq!(circumcenter_exact(t[0], t[1], t[2]), None);
        assert_eq!(orient2d_circumcenter([0.0, 0.0], [1.0, 0.0], t), Collinear);
        let _ = dot_sign_circumcenters([0.0, 0.0], t, good);
        let _ = dot_sign_circumcenters([0.0, 0.0], good, t);
        let _ = compare_circumradius(t, good);
        let _ = compare_circumradius(t, t);
        assert_eq!(
            circumcenter_in_convex_hull(&[[-9.0, -9.0], [9.0, -9.0], [0.0, 9.0]], t),
            HullPosition::Outside
        );
    }
    let weird = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::MAX,
        f64::MIN_POSITIVE / 8.0,
        -0.0,
    ];
    for &w in &weird {
        let t = [[w, 0.0], [1.0, w], [0.5, 2.0]];
        let _ = circumcenter(t[0], t[1], t[2]);
        let _ = circumcenter_exact(t[0], t[1], t[2]);
        let _ = orient2d_circumcenter([w, w], [1.0, 0.0], t);
        let _ = dot_sign_circumcenters([w, 1.0], t, good);
        let _ = compare_circumradius(t, good);
        let _ = circumcenter_in_convex_hull(&[[w, 0.0], [1.0, 0.0], [0.0, 1.0]], t);
    }
    // Degenerate hulls.
    for hull in [
        &[][..],
        &[[0.0, 0.0]][..],
        &[[0.0, 0.0], [1.0, 0.0]][..],
        &[[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [3.0, 0.0]][..],
        &[[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]][..],
        &[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]][..],
    ] {
        let _ = circumcenter_in_convex_hull(hull, good);
    }
}

#[test]
fn congruent_triangles_have_equal_circumradii() {
    let t = [[0.0, 0.0], [3.0, 0.0], [1.0, 2.0]];
    let rotated = t.map(|p| [-p[1] + 7.0, p[0] - 2.5]);
    let reflected = t.map(|p| [p[0], -p[1]]);
    let reordered = [t[2], t[1], t[0]];
    for u in [rotated, reflected, reordered] {
        assert_eq!(compare_circumradius(t, u), Ordering::Equal);
        assert_eq!(compare_circumradius(u, t), Ordering::Equal);
    }
    let doubled = scale_tri(t, 2.0);
    assert_eq!(compare_circumradius(t, doubled), Ordering::Less);
    assert_eq!(compare_circumradius(doubled, t), Ordering::Greater);
    // At the ends of the envelope, where the degree-10 terms leave the f64 range.
    for k in [-140, 190] {
        let (a, b) = (scale_tri(t, pow2(k)), scale_tri(rotated, pow2(k)));
        assert_eq!(compare_circumradius(a, b), Ordering::Equal);
        let mut c = b;
        c[0][0] = f64::from_bits(c[0][0].to_bits() + 1);
        assert_ne!(compare_circumradius(a, c), Ordering::Equal);
    }
    // Different triangles on one circle (center 0, radius 5).
    let t1 = [[3.0, 4.0], [-5.0, 0.0], [0.0, -5.0]];
    let t2 = [[4.0, -3.0], [-3.0, -4.0], [0.0, 5.0]];
    assert_eq!(compare_circumradius(t1, t2), Ordering::Equal);
}

#[test]
fn dot_sign_known_answers() {
    let p = [0.0, 0.0];
    let source = [[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]; // O = (2, 2)
    let perpendicular = [[0.0, 0.0], [-4.0, 0.0], [0.0, 4.0]]; // O = (-2, 2)
    let same_side = [[0.0, 0.0], [6.0, 0.0], [0.0, 2.0]]; // O = (3, 1)
    let far_side = [[0.0, 0.0], [-6.0, 0.0], [0.0, -2.0]]; // O = (-3, -1)
    assert_eq!(dot_sign_circumcenters(p, source, perpendicular), Sign::Zero);
    assert_eq!(dot_sign_circumcenters(p, perpendicular, source), Sign::Zero);
    assert_eq!(dot_sign_circumcenters(p, source, same_side), Sign::Positive);
    assert_eq!(dot_sign_circumcenters(p, source, far_side), Sign::Negative);
    // Orientation of the triangles does not matter.
    let rev = |t: [[f64; 2]; 3]| [t[0], t[2], t[1]];
    assert_eq!(
        dot_sign_circumcenters(p, rev(source), far_side),
        Sign::Negative
    );
    assert_eq!(
        dot_sign_circumcenters(p, rev(source), rev(far_side)),
        Sign::Negative
    );
    // p not a vertex: p = (1, 1), O_s − p = (1, 1), O(same_side) − p = (2, 0).
    assert_eq!(
        dot_sign_circumcenters([1.0, 1.0], source, same_side),
        Sign::Positive
    );
    // p = O(source): the dot product vanishes.
    assert_eq!(
        dot_sign_circumcenters([2.0, 2.0], source, far_side),
        Sign::Zero
    );
}

#[test]
fn hull_known_answers() {
    // A square with collinear boundary points, also around hull[0].
    let hull = [
        [2.0, 0.0],
        [4.0, 0.0],
        [4.0, 2.0],
        [4.0, 4.0],
        [2.0, 4.0],
        [0.0, 4.0],
        [0.0, 2.0],
        [0.0, 0.0],
    ];
    let tri_with_center = |c: [f64; 2]| {
        [
            [c[0] + 3.0, c[1] + 4.0],
            [c[0] - 5.0, c[1]],
            [c[0], c[1] - 5.0],
        ]
    };
    let cases = [
        ([2.0, 2.0], HullPosition::Inside),
        ([3.0, 0.0], HullPosition::OnBoundary),
        ([1.0, 0.0], HullPosition::OnBoundary),
        ([2.0, 0.0], HullPosition::OnBoundary),
        ([0.0, 0.0], HullPosition::OnBoundary),
        ([4.0, 3.0], HullPosition::OnBoundary),
        ([4.0, 4.0], HullPosition::OnBoundary),
        ([5.0, 0.0], HullPosition::Outside),
        ([-1.0, 0.0], HullPosition::Outside),
        ([2.0, -1.0], HullPosition::Outside),
        ([4.0, 5.0], HullPosition::Outside),
        ([0.0, 3.0], HullPosition::OnBoundary),
    ];
    for (center, expected) in cases {
        assert_eq!(
            circumcenter(
                tri_with_center(center)[0],
                tri_with_center(center)[1],
                tri_with_center(center)[2]
            ),
            Some(center)
        );
        assert_eq!(
            circumcenter_in_convex_hull(&hull, tri_with_center(center)),
            expected,
            "{center:?}"
        );
    }
    // A right triangle whose hypotenuse is a hull edge.
    let right = [[0.0, 0.0], [4.0, 0.0], [2.0, 2.0]];
    assert_eq!(
        circumcenter_in_convex_hull(&hull, right),
        HullPosition::OnBoundary
    );
}

/// Brute-force position of `q` in the closed CCW polygon `hull`.
fn brute_force_hull(hull: &[[f64; 2]], q: [f64; 2]) -> HullPosition {
    let mut on_line = false;
    for i in 0..hull.len() {
        match orient2d(hull[i], hull[(i + 1) % hull.len()], q) {
            Clockwise => return HullPosition::Outside,
            Collinear => on_line = true,
            CounterClockwise => {}
        }
    }
    if on_line {
        HullPosition::OnBoundary
    } else {
        HullPosition::Inside
    }
}

/// The fan search agrees with the brute force on polygons full of collinear boundary points,
/// for every choice of the start vertex and every query point of a fine lattice.
#[test]
fn hull_search_matches_brute_force_exhaustively() {
    let mut polygons: Vec<Vec<[f64; 2]>> = Vec::new();
    // Boundary lattice points of rectangles (collinear runs on every side).
    for (w, h) in [(1, 1), (2, 1), (3, 2), (4, 4)] {
        let mut p = Vec::new();
        for x in 0..w {
            p.push([x as f64, 0.0]);
        }
        for y in 0..h {
            p.push([w as f64, y as f64]);
        }
        for x in (1..=w).rev() {
            p.push([x as f64, h as f64]);
        }
        for y in (1..=h).rev() {
            p.push([0.0, y as f64]);
        }
        polygons.push(p);
    }
    // Triangles with collinear points on their sides, and a general convex polygon.
    polygons.push(vec![
        [0.0, 0.0],
        [1.0, 0.0],
        [2.0, 0.0],
        [3.0, 0.0],
        [0.0, 3.0],
    ]);
    polygons.push(vec![
        [0.0, 0.0],
        [2.0, 0.0],
        [4.0, 0.0],
        [3.0, 1.0],
        [2.0, 2.0],
        [1.0, 3.0],
        [0.0, 4.0],
        [0.0, 2.0],
    ]);
    polygons.push(vec![
        [0.0, 0.0],
        [3.0, 1.0],
        [4.0, 3.0],
        [2.0, 4.0],
        [-1.0, 2.0],
    ]);
    polygons.push(vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    let mut checked = 0;
    for poly in &polygons {
        for start in 0..poly.len() {
            let hull: Vec<[f64; 2]> = (0..poly.len())
                .map(|i| poly[(start + i) % poly.len()])
                .collect();
            for qx in -3..=11 {
                for qy in -3..=11 {
                    let q = [qx as f64 / 2.0, qy as f64 / 2.0];
                    let got = hull_position(&hull, |a, b| Some(orient2d(a, b, q)));
                    assert_eq!(got, brute_force_hull(&hull, q), "hull {hull:?}, q {q:?}");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 5000);
}

// ----------------------------------------------------------------------------------------
// The error bound itself: the exact value always lies within `e` of `v`.

fn within_bound(b: &Bounded, exact: &BigRational) -> bool {
    if !(b.v.is_finite() && b.e.is_finite()) {
        return true; // undecided: no claim made
    }
    let dist = (exact - rat(b.v)).abs();
    dist <= rat(b.e)
}

/// Coordinates of mixed magnitudes, signs and low-order bits.
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-1000i64..1000).prop_map(|i| i as f64),
        (-1.0e3f64..1.0e3),
        (-1.0f64..1.0, -200i32..200).prop_map(|(m, k)| m * pow2(k)),
        (-3i64..4, 0u64..3).prop_map(|(m, ulps)| f64::from_bits((m as f64 + 1e6).to_bits() + ulps)),
    ]
}

fn triangle() -> impl Strategy<Value = [[f64; 2]; 3]> {
    prop::array::uniform3(prop::array::uniform2(coordinate()))
}

fn lift_rational<const N: usize>(points: [[f64; 2]; N]) -> [[BigRational; 2]; N] {
    points.map(|p| p.map(rat))
}

/// The value of a term of degree `degree` evaluated on points lifted by `lift_exact`.
fn unlift(x: &BigInt, degree: i32, shift: i32) -> BigRational {
    let x = BigRational::from_integer(x.clone());
    let power = rat(2.0).pow(degree * shift);
    x * power
}

/// One polynomial's terms in the filter, in rationals and in lifted integers, their degrees
/// and its name.
type Evaluations = (
    Vec<Bounded>,
    Vec<BigRational>,
    Vec<BigInt>,
    Vec<i32>,
    &'static str,
);

/// Evaluates every polynomial on `points` = `[p, q, t1, t2]` in the filter, in rationals
/// and in lifted integers; checks the filter's bound and the lifting.
fn check_evaluations(points: [[f64; 2]; 8]) -> Result<(), TestCaseError> {
    let [fp, fq, f0, f1, f2, g0, g1, g2] = lift_filter(points);
    let [rp, rq, r0, r1, r2, s0, s1, s2] = lift_rational(points);
    let ([ip, iq, i0, i1, i2, j0, j1, j2], shift) = lift_exact(points);
    let (ft1, ft2) = ([f0, f1, f2], [g0, g1, g2]);
    let (rt1, rt2) = ([r0, r1, r2], [s0, s1, s2]);
    let (it1, it2) = ([i0, i1, i2], [j0, j1, j2]);

    let checks: Vec<Evaluations> = vec![
        (
            orient_terms(&fp, &fq, &ft1).to_vec(),
            orient_terms(&rp, &rq, &rt1).to_vec(),
            orient_terms(&ip, &iq, &it1).to_vec(),
            vec![2, 4],
            "orient",
        ),
        (
            dot_terms(&fp, &ft1, &ft2).to_vec(),
            dot_terms(&rp, &rt1, &rt2).to_vec(),
            dot_terms(&ip, &it1, &it2).to_vec(),
            vec![2, 2, 6],
            "dot",
        ),
        (
            radius_terms(&ft1, &ft2).to_vec(),
            radius_terms(&rt1, &rt2).to_vec(),
            radius_terms(&it1, &it2).to_vec(),
            vec![10],
            "radius",
        ),
    ];
    for (filtered, exact, lifted, degrees, name) in checks {
        for i in 0..filtered.len() {
            prop_assert!(
                within_bound(&filtered[i], &exact[i]),
                "{name}: {:?} vs {}",
                filtered[i],
                exact[i]
            );
            prop_assert_eq!(
                &unlift(&lifted[i], degrees[i], shift),
                &exact[i],
                "{}",
                name
            );
        }
    }
    // Division, as used by the circumcenter construction.
    let cf = circ(&ft1);
    let cx = circ(&rt1);
    if let Some(q) = cf.ux.div(&cf.d) {
        prop_assert!(!cx.d.is_zero());
        prop_assert!(within_bound(&q, &(&cx.ux / &cx.d)), "quotient {q:?}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn running_error_bound_holds(
        p in prop::array::uniform2(coordinate()),
        q in prop::array::uniform2(coordinate()),
        t1 in triangle(),
        t2 in triangle(),
    ) {
        let points = [p, q, t1[0], t1[1], t1[2], t2[0], t2[1], t2[2]];
        check_evaluations(points)?;
        check_evaluations(normalize(points).0)?;
    }

    #[test]
    fn rational_to_f64_round_trips_and_rounds_to_nearest(bits in any::<u64>(), num in 1u64..u64::MAX, den in 1u64..u64::MAX) {
        let x = f64::from_bits(bits);
        if x.is_finite() {
            prop_assert_eq!(rational_to_f64(&rat(x)).to_bits(), if x == 0.0 { 0.0f64.to_bits() } else { x.to_bits() });
            if x.abs() < f64::MAX {
                // The midpoint between x and its upper neighbour rounds to the even one.
                let next = f64::from_bits(x.to_bits() + 1);
                if next.is_finite() && x != 0.0 {
                    let mid = (rat(x) + rat(next)) / BigRational::from_integer(BigInt::from(2));
                    let even = if x.to_bits() % 2 == 0 { x } else { next };
                    prop_assert_eq!(rational_to_f64(&mid), even);
                }
            }
        }
        // Against num-rational's own correctly rounded conversion.
        let r = BigRational::new(BigInt::from(num) * BigInt::from(num), BigInt::from(den));
        prop_assert_eq!(Some(rational_to_f64(&r)), r.to_f64());
        let r = BigRational::new(BigInt::from(den), BigInt::from(num) << 1100u32);
        prop_assert_eq!(Some(rational_to_f64(&r)), r.to_f64());
        prop_assert_eq!(Some(rational_to_f64(&-r.clone())), (-r).to_f64());
    }
}

#[test]
fn rational_to_f64_edges() {
    let two = BigRational::from_integer(BigInt::from(2));
    let tiny = rat(f64::from_bits(1));
    assert_eq!(rational_to_f64(&(&tiny / &two)), 0.0); // tie between 0 and 2^-1074: even
    assert_eq!(rational_to_f64(&(&tiny * rat(0.75))), f64::from_bits(1));
    assert_eq!(rational_to_f64(&(&tiny * rat(1.5))), f64::from_bits(2)); // tie: even
    let max = rat(f64::MAX);
    let half_ulp = rat(pow2(970));
    assert_eq!(rational_to_f64(&(&max + &half_ulp)), f64::INFINITY);
    assert_eq!(rational_to_f64(&(&max + &half_ulp / &two)), f64::MAX);
    assert_eq!(rational_to_f64(&-(&max * &two)), f64::NEG_INFINITY);
    assert_eq!(
        rational_to_f64(&BigRational::new(BigInt::from(1), BigInt::from(3))),
        1.0 / 3.0
    );
}

#[test]
fn filter_certifies_exact_integer_zeros_without_fallback() {
    // Every operation is exact in f64 for small integers, so the zero is certified.
    let tri = [[0.0, 0.0], [4.0, 0.0], [0.0, 2.0]];
    let [a, b, t0, t1, t2] = lift_filter([[4.0, 0.0], [0.0, 2.0], tri[0], tri[1], tri[2]]);
    let [d, v] = orient_terms(&a, &b, &[t0, t1, t2]);
    assert_eq!(d.sign(), Some(Sign::Positive));
    assert_eq!(v.sign(), Some(Sign::Zero));
}

#[test]
fn normalize_is_exact_and_leaves_ordinary_input_alone() {
    let pts = [[1.5, -3.0], [0.25, 7.0]];
    assert_eq!(normalize(pts), (pts, 0));
    let big = [[pow2(200) * 1.5, -pow2(150)], [pow2(-140), 0.0]];
    let (s, k) = normalize(big);
    assert_eq!(k, 200);
    assert_eq!(s[0][0], 1.5);
    assert_eq!(s[1][0] * pow2(k), pow2(-140));
    // Subnormal coordinates that would not survive the scaling are left alone.
    let mixed = [[pow2(100), f64::from_bits(3)], [1.0, 1.0]];
    assert_eq!(normalize(mixed), (mixed, 0));
}

/// The fast construction is accepted on almost all random triangles, and what it returns is
/// within its documented bound of the exact circumcenter; otherwise the exact value is
/// rounded correctly.
#[test]
fn circumcenter_is_accurate_and_mostly_fast() {
    let mut state = 0x2545_f491_4f6c_dd1du64;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64 * 200.0 - 100.0
    };
    let mut fallbacks = 0;
    let cases = 1000;
    for i in 0..cases {
        let offset = if i % 2 == 0 { 0.0 } else { 1000.0 };
        let t = [[next(), next()], [next(), next()], [next(), next()]];
        let t = t.map(|p| [p[0] + offset, p[1]]);
        let fast = fast_circumcenter(&circ(&lift_filter(t)), t[0], 0);
        let exact = circumcenter_exact(t[0], t[1], t[2]).unwrap();
        let got = circumcenter(t[0], t[1], t[2]).unwrap();
        if let Some(fast) = fast {
            assert_eq!(fast, got);
            let tolerance = rat(CIRCUMCENTER_ULPS * ulp(got[0].abs().max(got[1].abs())));
            for (g, e) in [(got[0], &exact.x), (got[1], &exact.y)] {
                assert!((rat(g) - e).abs() <= tolerance, "{got:?} vs {exact:?}");
            }
        } else {
            fallbacks += 1;
            assert_eq!(got, exact.to_f64());
        }
    }
    assert!(fallbacks * 100 < cases, "{fallbacks} of {cases} fell back");
}
