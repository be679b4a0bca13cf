//! Uncertain samples: the reconstruction of the points as they are, or through the
//! representatives of a band of their noise.
//!
//! Between clean samples and clear bands lies noise of a fifth of a spacing to a band
//! ([`UNCERTAIN_SPACINGS`](crate::reconstruct::thresholds::thinning::UNCERTAIN_SPACINGS)):
//! there the water flow may reconstruct the points exactly or break their curves into
//! pieces, close open ones and leave junk loops, and which happens depends on the chance of
//! a few noisy stretches. Such a sample is reconstructed as it is first; the representatives
//! are reconstructed only when that result is [`doubtful`], and taken only when
//! [`preferred`]. Both tests read the results, not the points: a warning, open chains, the
//! curves' own zigzag, and where the representatives' curves run.

use std::collections::HashMap;

use crate::reconstruct::curves::{self, LocalCurve};
use crate::reconstruct::delaunay_graph::FastHash;
use crate::reconstruct::lengths::distance;
use crate::reconstruct::result::Reconstruction;
use crate::reconstruct::thresholds::thinning::{MAX_UNCOVERED_SHARE, REACH_STEPS};

/// Whether the reconstruction of an uncertain sample as it is may be junk: it carries a
/// warning or an open chain (the pieces a noisy stretch breaks into), and most of its
/// curves' points lie on curves that zigzag ([`curves::zigzags`]), or it has no curve and a
/// warning. Clean samples whose curves run close together (line drawings) read as noisy to
/// the probes too, and their warned results are better than any cover of them: their
/// curves do not zigzag.
pub(in crate::reconstruct) fn doubtful(given: &Reconstruction) -> bool {
    if given.warnings().is_empty() && given.curves.iter().all(|c| c.closed) {
        return false;
    }
    let tri = &given.triangulation;
    let (mut zigzagging, mut all) = (0usize, 0usize);
    for curve in &given.curves {
        let curve = LocalCurve::from_caller(curve, |i| tri.local_index(i));
        all += curve.points.len();
        if curves::zigzags(&tri.points, &curve) {
            zigzagging += curve.points.len();
        }
    }
    2 * zigzagging >= all
}

/// Whether the reconstruction `through` the representatives of an uncertain sample is
/// taken over the doubtful one of the points `given`: it carries no warning, either the
/// other does or it has fewer curves (the same curves without the junk), and it runs where
/// the other's curves ran ([`uncovered_share`]): a cover drops small curves and holes
/// whose disks hold few points, and fewer curves is then a loss, not a mend.
pub(in crate::reconstruct) fn preferred(through: &Reconstruction, given: &Reconstruction) -> bool {
    through.warnings().is_empty()
        && (!given.warnings().is_empty() || through.curves.len() < given.curves.len())
        && uncovered_share(through, given) <= MAX_UNCOVERED_SHARE
}

/// The share of the points on `given`'s curves farther than [`REACH_STEPS`] median steps
/// of `through`'s curves from every point on them (1 when `through` has no curve). Junk of
/// a noisy sample lies inside its band, within a step or two of the representatives' curve
/// through it; a curve the cover lost lies as far away as it lay from the other curves.
///
/// A statistic in rounded arithmetic (rounded distances, a grid of cells a reach wide): it
/// chooses between two exact results and decides nothing in either.
fn uncovered_share(through: &Reconstruction, given: &Reconstruction) -> f64 {
    let at = |rec: &Reconstruction, i: u32| rec.triangulation.point(i);
    let mut steps: Vec<f64> = through
        .curves
        .iter()
        .flat_map(|c| {
            let k = c.points.len();
            let edges = if c.closed { k } else { k.saturating_sub(1) };
            (0..edges).map(move |e| (c.points[e], c.points[(e + 1) % k]))
        })
        .map(|(a, b)| distance(at(through, a), at(through, b)))
        .collect();
    if steps.is_empty() {
        return 1.0;
    }
    steps.sort_by(f64::total_cmp);
    let reach = REACH_STEPS * steps[steps.len() / 2];
    if !(reach.is_finite() && reach > 0.0) {
        return 1.0;
    }
    // Casts saturate: at the ends of the range cells merge, which only finds more
    // neighbours to measure.
    let cell = |p: [f64; 2]| ((p[0] / reach).floor() as i64, (p[1] / reach).floor() as i64);
    let mut grid: HashMap<(i64, i64), Vec<[f64; 2]>, FastHash> = HashMap::default();
    for &i in through.curves.iter().flat_map(|c| c.points.iter()) {
        let p = at(through, i);
        grid.entry(cell(p)).or_default().push(p);
    }
    let covered = |p: [f64; 2]| {
        let (x, y) = cell(p);
        (x.saturating_sub(1)..=x.saturating_add(1)).any(|cx| {
            (y.saturating_sub(1)..=y.saturating_add(1)).any(|cy| {
                grid.get(&(cx, cy))
                    .is_some_and(|near| near.iter().any(|&q| distance(p, q) <= reach))
            })
        })
    };
    let on_curves: Vec<u32> = given
        .curves
        .iter()
        .flat_map(|c| c.points.iter().copied())
        .collect();
    let uncovered = on_curves
        .iter()
        .filter(|&&i| !covered(at(given, i)))
        .count();
    uncovered as f64 / on_curves.len().max(1) as f64
}
