//! Whether the first pass read a scatter: the thinning's probes saw an area (their
//! neighbourhoods never turn thin, `thinning::Reading::Area`), the water flow reached few of
//! the points, and most of those have another point as close as their curve neighbours.
//!
//! A curve sample's points have their curve neighbours nearest; in a uniform scatter or a
//! filled area every edge the water flow draws is one path among many equally short, and
//! most points are left over. Peeling and the open-curve stage look for more curves among
//! those leftovers, and in a scatter each of their passes finds one more such path at the
//! cost of a whole reconstruction: 10^6 uniform points took 5 peeling passes, a detour repair
//! over junk and 7 s where the first pass took 0.4 s. So a scatter keeps the first pass's
//! sure loops that read as curves (most of their points not crowded) and nothing else,
//! without repairs (`pipeline`); `diagnose` warns of it with the same reading of the final
//! curves. The probes' reading is what tells a scatter from dense curves with noise of about
//! their spacing, where the first pass also reaches few points, crowded, but the later
//! passes find the curves: their neighbourhoods turn thin.
//!
//! Every comparison is exact (the kernel's `length_order`); which points count is decided on
//! the Delaunay graph without the diagonals of cocircular groups, so the answer does not
//! depend on how the triangulation split them.

use std::cmp::Ordering;

use super::thresholds::scatter::MAX_TOUCHED_SHARE;
use crate::ids::{ids, LocalPoint};
use crate::kernel::metric::length_order;
use crate::voronoi::Voronoi;

/// No point.
const NO_POINT: LocalPoint = LocalPoint::new(u32::MAX);

/// Where `edges` (local, distinct) read as a scatter (see the module docs), which points
/// are *crowded*: on an edge, with a Delaunay neighbour that is none of their edge
/// neighbours no farther than their longest edge (a point on three edges or more counts as
/// crowded by its own). A scatter: fewer than [`MAX_TOUCHED_SHARE`] of the points on an
/// edge, and more than half of those crowded. `None` otherwise.
pub(super) fn crowding(vor: &Voronoi<'_>, edges: &[[LocalPoint; 2]]) -> Option<Vec<bool>> {
    let points = &vor.triangulation().points;
    let n = points.len();
    if vor.triangulation().is_degenerate() {
        return None;
    }
    let at = |p: LocalPoint| points[p.index()];
    // How many points are on an edge, before anything is compared: on curve samples nearly
    // all, and the answer is no.
    let mut degree = vec![0u8; n];
    for &[a, b] in edges {
        degree[a.index()] = degree[a.index()].saturating_add(1);
        degree[b.index()] = degree[b.index()].saturating_add(1);
    }
    let on_curves = degree.iter().filter(|&&d| d > 0).count();
    if on_curves as f64 >= MAX_TOUCHED_SHARE * n as f64 {
        return None;
    }
    // Each point's longest edge, by its far end, and its first two edge neighbours.
    let mut far = vec![NO_POINT; n];
    let mut along = vec![[NO_POINT; 2]; n];
    for &[a, b] in edges {
        for (p, q) in [(a, b), (b, a)] {
            let slot = &mut along[p.index()];
            if slot[0] == NO_POINT {
                slot[0] = q;
            } else if slot[1] == NO_POINT {
                slot[1] = q;
            }
            let f = far[p.index()];
            if f == NO_POINT || length_order(at(p), at(q), at(p), at(f)) == Ordering::Greater {
                far[p.index()] = q;
            }
        }
    }
    let crowded: Vec<bool> = ids::<LocalPoint>(n)
        .map(|p| {
            let f = far[p.index()];
            f != NO_POINT
                && (degree[p.index()] > 2
                    || vor.dual_neighbours(p).any(|q| {
                        !along[p.index()].contains(&q)
                            && length_order(at(p), at(q), at(p), at(f)) != Ordering::Greater
                    }))
        })
        .collect();
    let count = crowded.iter().filter(|&&c| c).count();
    (2 * count > on_curves).then_some(crowded)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::triangulate;
    use crate::reconstruct::extract::wdm_crust_edges;
    use crate::reconstruct::wdm::{self, LabelRule};
    use wdm_crust_testkit::Rng;

    fn first_pass_crowding(points: &[[f64; 2]]) -> Option<Vec<bool>> {
        let tri = triangulate(points).unwrap();
        let vor = tri.voronoi();
        let labels = wdm::labels(&vor, LabelRule::WaterReached);
        let edges = wdm_crust_edges(&vor, &labels);
        crowding(&vor, &edges)
    }

    #[test]
    fn a_uniform_scatter_reads_as_one_and_curve_samples_do_not() {
        let mut rng = Rng::new(5);
        let scatter: Vec<[f64; 2]> = (0..20_000).map(|_| [rng.f64(), rng.f64()]).collect();
        assert!(first_pass_crowding(&scatter).is_some());
        // A clean curve, and a noisy one: the first pass reaches most points.
        for noise in [0.0, 0.5] {
            let n = 5_000;
            let spacing = std::f64::consts::TAU / n as f64;
            let curve: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let t = i as f64 * spacing;
                    let r = 1.0 + 0.2 * (3.0 * t).cos() + noise * spacing * rng.normal();
                    [r * t.cos(), r * t.sin()]
                })
                .collect();
            assert!(first_pass_crowding(&curve).is_none(), "noise {noise}");
        }
    }
}
