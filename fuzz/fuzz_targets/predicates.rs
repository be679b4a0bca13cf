//! The exact predicates agree with a direct `BigRational` evaluation: `orient2d`, `incircle`,
//! and on circumcenters `orient2d_circumcenter`, `dot_sign_circumcenters`,
//! `compare_circumradius`, `circumcenter_in_convex_hull`; `circumcenter_exact` is exact and
//! `circumcenter` within 256 ulps of it. Points come from a structured scene (lattices,
//! circles, lines, every scale from the subnormals to the top of the `f64` range, ulp
//! nudges), so exact zeros and near-zeros are common. Every finite input is checked against
//! the reference; for NaN and infinities only "no panic" is required.
#![no_main]

use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use wdm_crust_fuzz::checks::{
    check_circumcenter, check_compare_circumradius, check_dot_sign, check_hull_position,
    check_orient2d_circumcenter, check_orient_incircle, exact_hull,
};
use wdm_crust_fuzz::scene::Scene;

#[derive(Debug, Arbitrary)]
enum Op {
    OrientIncircle([u16; 4]),
    OrientCircumcenter([u16; 2], [u16; 3]),
    Dot(u16, [u16; 3], [u16; 3]),
    /// The dot test as the water flow uses it: `p` is a vertex of both triangles.
    DotShared([u16; 5]),
    Radius([u16; 3], [u16; 3]),
    Hull {
        tri: [u16; 3],
        keep_collinear: bool,
        start: u16,
    },
    Circumcenter([u16; 3]),
}

#[derive(Debug, Arbitrary)]
struct Input {
    scene: Scene,
    ops: Vec<Op>,
}

const MAX_POINTS: usize = 48;

fuzz_target!(|input: Input| {
    let pts = input.scene.points(MAX_POINTS);
    if pts.is_empty() {
        return;
    }
    let p = |i: u16| pts[i as usize % pts.len()];
    let t = |i: [u16; 3]| [p(i[0]), p(i[1]), p(i[2])];
    for op in input.ops.iter().take(64) {
        let result = match *op {
            Op::OrientIncircle([a, b, c, d]) => check_orient_incircle(p(a), p(b), p(c), p(d))
                .and(check_orient_incircle(p(b), p(c), p(a), p(d)))
                .and(check_orient_incircle(p(c), p(b), p(a), p(d))),
            Op::OrientCircumcenter([a, b], tri) => check_orient2d_circumcenter(p(a), p(b), t(tri)),
            Op::Dot(q, s, o) => check_dot_sign(p(q), t(s), t(o)),
            Op::DotShared([q, a, b, c, d]) => {
                check_dot_sign(p(q), [p(a), p(q), p(b)], [p(c), p(d), p(q)])
            }
            Op::Radius(a, b) => {
                check_compare_circumradius(t(a), t(b)).and(check_compare_circumradius(t(b), t(a)))
            }
            Op::Hull {
                tri,
                keep_collinear,
                start,
            } => match exact_hull(&pts, keep_collinear) {
                Some(mut hull) => {
                    let n = hull.len();
                    hull.rotate_left(start as usize % n);
                    check_hull_position(&hull, t(tri))
                }
                None => Ok(()),
            },
            Op::Circumcenter(tri) => check_circumcenter(t(tri)),
        };
        if let Err(e) = result {
            panic!("{e}\npoints: {pts:?}");
        }
    }
});
