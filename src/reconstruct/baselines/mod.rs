//! The baselines WDM_CRUST is compared with, on the same triangulation and the same exact
//! predicates: the crust of Amenta, Bern and Eppstein and the nearest-neighbour crust of Dey
//! and Kumar.

pub mod crust;
pub mod nn_crust;

/// The exact references both baselines' tests compare with, in rationals and by brute force,
/// independent of the triangulation code.
#[cfg(test)]
mod reference {
    use num_rational::BigRational;
    use num_traits::{Signed, Zero};

    pub(super) type Q = BigRational;

    /// The first occurrence of each distinct point of `points`, and its coordinates exactly.
    pub(super) fn distinct(points: &[[f64; 2]]) -> (Vec<usize>, Vec<[Q; 2]>) {
        let mut ids: Vec<usize> = Vec::new();
        for i in 0..points.len() {
            if !ids.iter().any(|&j| points[j] == points[i]) {
                ids.push(i);
            }
        }
        let exact = |x: f64| Q::from_float(x).expect("finite");
        let s = ids
            .iter()
            .map(|&i| [exact(points[i][0]), exact(points[i][1])])
            .collect();
        (ids, s)
    }

    /// The squared distance of `a` and `b`.
    pub(super) fn d2(a: &[Q; 2], b: &[Q; 2]) -> Q {
        let (dx, dy) = (&a[0] - &b[0], &a[1] - &b[1]);
        &dx * &dx + &dy * &dy
    }

    /// Whether some circle through `p` and `q` keeps every point of `others` other than `p`
    /// and `q` strictly outside: the interval of the centres on their bisector that do is
    /// not empty (a strict Delaunay edge of the points).
    pub(super) fn strictly_delaunay<'a>(
        p: &[Q; 2],
        q: &[Q; 2],
        others: impl IntoIterator<Item = &'a [Q; 2]>,
    ) -> bool {
        let two = Q::from_integer(2.into());
        let m = [(&p[0] + &q[0]) / &two, (&p[1] + &q[1]) / &two];
        let n = [&p[1] - &q[1], &q[0] - &p[0]]; // left normal of p → q
        let mp = d2(&m, p);
        let (mut lo, mut hi): (Option<Q>, Option<Q>) = (None, None);
        for x in others {
            if x == p || x == q {
                continue;
            }
            let side = &n[0] * (&x[0] - &m[0]) + &n[1] * (&x[1] - &m[1]);
            let k = d2(&m, x) - &mp;
            if side.is_zero() {
                if k.is_negative() {
                    return false;
                }
                continue;
            }
            let t = k / (&side * &two);
            if side.is_positive() {
                hi = Some(hi.map_or(t.clone(), |h| if t < h { t.clone() } else { h }));
            } else {
                lo = Some(lo.map_or(t.clone(), |l| if t > l { t.clone() } else { l }));
            }
        }
        match (lo, hi) {
            (Some(l), Some(h)) => l < h,
            _ => true,
        }
    }
}
