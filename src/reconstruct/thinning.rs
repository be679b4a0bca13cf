//! Dense noisy bands: the points thinned to representatives before the labelling.
//!
//! WDM assumes the samples lie on the curve, at most a fraction of a spacing off it. A dense
//! scan is the other way round: thousands of points in a band many spacings wide, where the
//! water flow draws the band's ragged envelope, closes loops inside it or loses a hole.
//! Such an input is recognised by how its neighbourhoods look (below), covered by disks of a
//! radius of a few band widths, and each disk's points are represented by one of them: the
//! one nearest their centroid, which lies near the middle of the band. The representatives
//! are a sparse sample with little noise, the kind WDM is exact on, and the reconstruction
//! runs on them; every other point is left unassigned (the smoothing still fits the curves
//! to all of them).
//!
//! **Recognising a band.** Around a probe point its nearest neighbours are taken in order
//! of distance (a nearest-first walk of the Delaunay graph, exact), and the covariance of
//! the first `k` is read at `k` = 8, 12, 16, …, 256: on a curve sample it is thin from the
//! start (the smaller principal variance at most [`MAX_ASPECT`] of the larger); in a band
//! it is round while the neighbourhood is narrower than the band and turns thin once it is
//! a few band widths long, at `k` ≈ 7 × (noise / spacing along the curve). The input is a
//! band when at least half the probes turn thin only at [`BAND_NEIGHBOURS`] or later; the
//! band's noise is the median over those of the smaller principal deviation where they
//! turned. A scatter that never turns thin is no band (its probes do not count for it).
//!
//! Everything here is a statistic in rounded arithmetic, computed in a fixed order (local
//! indices, the triangulation's locality order, which depends on the points only), so the
//! representatives are the same for any input order; which points they are is all that
//! leaves this module, and the exact engine reconstructs them as given.

use std::collections::{HashMap, HashSet};

use super::delaunay_graph::{FastHash, Graph, Waiting};
use super::lengths::distance;
use super::thresholds::thinning::{
    BAND_SPACINGS, COVER_RADIUS, LARGE_BAND_SPACINGS, LARGE_SAMPLE, MAX_ASPECT, MIN_CLUSTER_SHARE,
    MIN_THINNED_POINTS, PROBES, SUBSAMPLE,
};
use crate::delaunay::Triangulation;
use crate::ids::{ids, LocalPoint};
use crate::parallel;

/// The neighbourhood sizes at which the covariance is read (steps of about 1.5).
const LADDER: [usize; 15] = [
    8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768, 1024,
];

/// What the probes read the points as.
pub(super) enum Reading {
    /// A dense noisy band, and its representatives (local indices, ascending).
    Band(Vec<LocalPoint>),
    /// An area: at least half the probes' neighbourhoods never turn thin (a uniform
    /// scatter, a filled region), up to the ladder's last size.
    Area,
    /// Neither (curve samples, small or degenerate inputs).
    Neither,
}

/// How the probes read the points: a band with its representatives, an area, or neither.
pub(super) fn read(tri: &Triangulation) -> Reading {
    let n = tri.points.len();
    if n < MIN_THINNED_POINTS || tri.is_degenerate() {
        return Reading::Neither;
    }
    let sigma = match band_noise(tri) {
        Noise::Band(sigma) => sigma,
        Noise::Area => return Reading::Area,
        Noise::Neither => return Reading::Neither,
    };
    let radius = COVER_RADIUS * sigma;
    if !(radius.is_finite() && radius > 0.0) {
        return Reading::Neither;
    }
    Reading::Band(cover(&tri.points, radius))
}

/// The noise of a band, or what else the probes saw.
enum Noise {
    /// The band's across deviation, in the frame's units.
    Band(f64),
    Area,
    Neither,
}

/// The noise of the band (its across deviation, in the frame's units), or what else the
/// probes saw.
fn band_noise(tri: &Triangulation) -> Noise {
    let n = tri.points.len();
    let rate = n.div_ceil(SUBSAMPLE).max(1);
    let subsample;
    let (probed, graph) = if rate == 1 {
        (tri, Graph::adjacency(tri))
    } else {
        let kept: Vec<[f64; 2]> = (0..n as u64)
            .filter(|&i| mix(i) % rate as u64 == 0)
            .map(|i| tri.points[i as usize])
            .collect();
        subsample = match crate::delaunay::triangulate(&kept) {
            Ok(sub) if !sub.is_degenerate() => sub,
            _ => return Noise::Neither,
        };
        (&subsample, Graph::adjacency(&subsample))
    };
    let m = probed.points.len();
    // Large samples: local failures of the water flow add up (see `LARGE_BAND_SPACINGS`).
    let threshold = if n >= LARGE_SAMPLE {
        LARGE_BAND_SPACINGS
    } else {
        BAND_SPACINGS
    };
    let stride = m.div_ceil(PROBES).max(1);
    let probes = m.div_ceil(stride);
    let turns = parallel::map_range(probes, |i| {
        turn(probed, &graph, LocalPoint::new((i * stride) as u32))
    });
    let mut banded: Vec<f64> = turns
        .iter()
        .flatten()
        .filter(|t| {
            // The spacing along the curve of all the points, not only the subsample's.
            let spacing = 2.0 * t.radius / (t.size * rate) as f64;
            t.deviation >= threshold * spacing
        })
        .map(|t| t.deviation)
        .collect();
    if 2 * banded.len() < probes {
        let never_thin = turns.iter().filter(|t| t.is_none()).count();
        return if 2 * never_thin >= probes {
            Noise::Area
        } else {
            Noise::Neither
        };
    }
    banded.sort_by(f64::total_cmp);
    Noise::Band(banded[banded.len() / 2])
}

/// SplitMix64's finaliser: a subsample that owes nothing to the locality order's pattern.
fn mix(i: u64) -> u64 {
    let mut z = i.wrapping_add(0x9e37_79b9_7f4a_7c15);
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Where a probe's neighbourhood turned thin.
struct Turn {
    /// How many neighbours it holds.
    size: usize,
    /// The distance to the farthest of them.
    radius: f64,
    /// Its smaller principal deviation: the noise across the curve.
    deviation: f64,
}

/// Where the neighbourhood of `p` turns thin; `None` if none up to the ladder's last size
/// is.
fn turn(tri: &Triangulation, graph: &Graph, p: LocalPoint) -> Option<Turn> {
    let o = tri.points[p.index()];
    let mut seen: HashSet<LocalPoint, FastHash> = HashSet::default();
    seen.insert(p);
    let mut waiting = std::collections::BinaryHeap::new();
    for &q in graph.of(p) {
        seen.insert(q);
        waiting.push(Waiting(distance(o, tri.points[q.index()]), q));
    }
    let mut moments = Moments::default();
    let mut rung = 0;
    while let Some(Waiting(d, q)) = waiting.pop() {
        let x = tri.points[q.index()];
        moments.add([x[0] - o[0], x[1] - o[1]]);
        if moments.count == LADDER[rung] {
            let (small, large) = moments.principal();
            if small <= MAX_ASPECT * large {
                return Some(Turn {
                    size: LADDER[rung],
                    radius: d,
                    deviation: small.sqrt(),
                });
            }
            rung += 1;
            if rung == LADDER.len() {
                return None;
            }
        }
        for &w in graph.of(q) {
            if seen.insert(w) {
                waiting.push(Waiting(distance(o, tri.points[w.index()]), w));
            }
        }
    }
    None
}

/// Running sums for a covariance.
#[derive(Default)]
struct Moments {
    count: usize,
    sum: [f64; 2],
    xx: f64,
    yy: f64,
    xy: f64,
}

impl Moments {
    fn add(&mut self, d: [f64; 2]) {
        self.count += 1;
        self.sum[0] += d[0];
        self.sum[1] += d[1];
        self.xx += d[0] * d[0];
        self.yy += d[1] * d[1];
        self.xy += d[0] * d[1];
    }

    /// The smaller and the larger principal variance.
    fn principal(&self) -> (f64, f64) {
        let k = self.count as f64;
        let (mx, my) = (self.sum[0] / k, self.sum[1] / k);
        let (a, c, b) = (
            self.xx / k - mx * mx,
            self.yy / k - my * my,
            self.xy / k - mx * my,
        );
        let half = 0.5 * (a + c);
        let root = (0.25 * (a - c) * (a - c) + b * b).sqrt();
        ((half - root).max(0.0), half + root)
    }
}

/// A cell of the cover's grid.
type Cell = (i64, i64);

type Grid = HashMap<Cell, Vec<LocalPoint>, FastHash>;

/// The cell `c` and its eight neighbours, each once. Far out (a radius tiny against the
/// coordinates) the cell indices saturate at the ends of `i64`: neighbouring cells may then
/// coincide, and a point's disk still lies within these cells, since saturation keeps
/// indices that differ by at most one within one.
fn neighbourhood(c: Cell) -> impl Iterator<Item = Cell> {
    let mut cells = [(0i64, 0i64); 9];
    for (k, slot) in cells.iter_mut().enumerate() {
        let (i, j) = (k as i64 / 3 - 1, k as i64 % 3 - 1);
        *slot = (c.0.saturating_add(i), c.1.saturating_add(j));
    }
    cells.sort_unstable();
    let mut count = 1;
    for k in 1..9 {
        if cells[k] != cells[count - 1] {
            cells[count] = cells[k];
            count += 1;
        }
    }
    cells.into_iter().take(count)
}

/// The representatives of the points covered by disks of `radius` (local indices,
/// ascending).
///
/// 1. Seeds, greedily in local order: a point becomes a seed when no seed lies within
///    `radius`.
/// 2. Each seed's disk: the point nearest the centroid of the points within `radius` of the
///    seed. The centroid of a disk that spans the band lies near its middle, wherever in
///    the band the seed was; so two seeds side by side across the band (they can be, in a
///    band wider than `radius`) give candidates close together. A disk with fewer points
///    than [`MIN_CLUSTER_SHARE`] of the median disk's gives none (outliers, frayed edges).
/// 3. Candidates in seed order, each kept unless a kept one lies within half the radius:
///    one file of representatives along the band.
fn cover(points: &[[f64; 2]], radius: f64) -> Vec<LocalPoint> {
    let cell = |p: [f64; 2]| -> Cell {
        (
            (p[0] / radius).floor() as i64,
            (p[1] / radius).floor() as i64,
        )
    };
    let around = neighbourhood;
    let within = |grid: &Grid, x: [f64; 2], r: f64| -> bool {
        around(cell(x)).any(|k| {
            grid.get(&k)
                .is_some_and(|list| list.iter().any(|&q| distance(x, points[q.index()]) < r))
        })
    };
    let mut seeds = Grid::default();
    let mut seed_order: Vec<LocalPoint> = Vec::new();
    let mut all = Grid::default();
    for (p, &x) in ids::<LocalPoint>(points.len()).zip(points) {
        all.entry(cell(x)).or_default().push(p);
        if !within(&seeds, x, radius) {
            seeds.entry(cell(x)).or_default().push(p);
            seed_order.push(p);
        }
    }
    // Each seed's disk: its size and the point nearest its centroid.
    let disks = parallel::map_range(seed_order.len(), |k| {
        let o = points[seed_order[k].index()];
        let members: Vec<LocalPoint> = around(cell(o))
            .filter_map(|c| all.get(&c))
            .flatten()
            .copied()
            .filter(|&q| distance(o, points[q.index()]) < radius)
            .collect();
        // In local order, relative to the seed: the same sums for any input order.
        let mut sorted = members;
        sorted.sort_unstable();
        let mut sum = [0.0f64; 2];
        for &q in &sorted {
            sum[0] += points[q.index()][0] - o[0];
            sum[1] += points[q.index()][1] - o[1];
        }
        let count = sorted.len();
        let centroid = [o[0] + sum[0] / count as f64, o[1] + sum[1] / count as f64];
        let nearest = sorted
            .iter()
            .map(|&q| (distance(centroid, points[q.index()]), q))
            .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)))
            .map_or(seed_order[k], |(_, q)| q);
        (count, nearest)
    });
    let mut sizes: Vec<usize> = disks.iter().map(|d| d.0).collect();
    sizes.sort_unstable();
    let median = sizes.get(sizes.len() / 2).copied().unwrap_or(0);
    let least = ((MIN_CLUSTER_SHARE * median as f64).ceil() as usize).max(2);
    let mut kept = Grid::default();
    let mut reps = Vec::new();
    for &(count, candidate) in &disks {
        let x = points[candidate.index()];
        if count >= least && !within(&kept, x, 0.5 * radius) {
            kept.entry(cell(x)).or_default().push(candidate);
            reps.push(candidate);
        }
    }
    reps.sort_unstable();
    reps
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::triangulate;
    use wdm_crust_testkit::Rng;

    fn band(n: usize, sigma: f64, seed: u64) -> Vec<[f64; 2]> {
        let mut rng = Rng::new(seed);
        (0..n)
            .map(|_| {
                let t = std::f64::consts::TAU * rng.f64();
                let r = 1.0 + sigma * rng.normal();
                [r * t.cos(), r * t.sin()]
            })
            .collect()
    }

    #[test]
    fn a_wide_band_is_thinned_and_a_clean_sample_is_not() {
        let clean: Vec<[f64; 2]> = (0..2000)
            .map(|k| {
                let t = std::f64::consts::TAU * k as f64 / 2000.0;
                [t.cos(), t.sin()]
            })
            .collect();
        assert!(matches!(
            read(&triangulate(&clean).unwrap()),
            Reading::Neither
        ));
        // 4000 points, spacing along the circle 0.0016, noise 0.03: about 19 spacings.
        let tri = triangulate(&band(4000, 0.03, 7)).unwrap();
        let Reading::Band(reps) = read(&tri) else {
            panic!("a band");
        };
        // Disks of 3 σ along a circle of length 2π: between one and two radii apart.
        let radius = COVER_RADIUS * 0.03;
        let expected = std::f64::consts::TAU / radius;
        assert!(
            (reps.len() as f64) > 0.5 * expected && (reps.len() as f64) < 1.5 * expected,
            "{} representatives, about {expected:.0} expected",
            reps.len()
        );
        // They lie near the middle of the band.
        let off: f64 = reps
            .iter()
            .map(|&p| (tri.points[p.index()][0].hypot(tri.points[p.index()][1]) - 1.0).powi(2))
            .sum::<f64>()
            / reps.len() as f64;
        assert!(off.sqrt() < 0.7 * 0.03, "RMS {} off the circle", off.sqrt());
    }

    #[test]
    fn a_uniform_scatter_is_an_area_and_no_band() {
        let mut rng = Rng::new(11);
        let scatter: Vec<[f64; 2]> = (0..3000).map(|_| [rng.f64(), rng.f64()]).collect();
        assert!(matches!(
            read(&triangulate(&scatter).unwrap()),
            Reading::Area
        ));
        // A dense noisy circle whose noise is about its spacing is no area (its
        // neighbourhoods turn thin), whether or not it is read as a band.
        let noisy = band(20_000, 0.0003, 12);
        assert!(!matches!(
            read(&triangulate(&noisy).unwrap()),
            Reading::Area
        ));
    }

    #[test]
    fn cells_far_out_saturate_and_are_listed_once() {
        let corner: Vec<Cell> = neighbourhood((i64::MAX, i64::MIN)).collect();
        assert_eq!(
            corner,
            [
                (i64::MAX - 1, i64::MIN),
                (i64::MAX - 1, i64::MIN + 1),
                (i64::MAX, i64::MIN),
                (i64::MAX, i64::MIN + 1)
            ]
        );
        assert_eq!(neighbourhood((0, 0)).count(), 9);
        // Two tight clusters 2e300 apart, a radius 1e-20 of their coordinates: every cell
        // index saturates, and each cluster is still one disk with one representative.
        let points: Vec<[f64; 2]> = (0..40)
            .map(|k| {
                let spot = if k < 20 { 1e300 } else { 3e300 };
                [spot + (k % 20) as f64 * 1e278, spot]
            })
            .collect();
        let reps = cover(&points, 1e280);
        assert_eq!(reps.len(), 2, "{reps:?}");
        assert!(reps[0].get() < 20 && reps[1].get() >= 20);
    }
}
