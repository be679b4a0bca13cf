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

pub(super) mod uncertain;

use std::collections::{HashMap, HashSet};

use super::delaunay_graph::{mix, FastHash, Graph, Waiting};
use super::lengths::distance;
use super::thresholds::thinning::{
    BAND_SPACINGS, CONFIRM_RUNGS, COVER_RADIUS, LARGE_BAND_SPACINGS, LARGE_SAMPLE, MAX_ASPECT,
    MIN_CLUSTER_SHARE, MIN_THINNED_POINTS, PROBES, QUIET_SPACINGS, RECENTRINGS, SUBSAMPLE,
    UNCERTAIN_SPACINGS,
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
    /// Noise of a large share of the spacing, short of a band ([`UNCERTAIN_SPACINGS`] up to
    /// the band's threshold): the water flow may reconstruct the points as they are or
    /// leave junk, and the representatives of a band of that noise (ascending) are the
    /// alternative the caller weighs against them.
    Uncertain(Vec<LocalPoint>),
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
    let (sigma, certain) = match band_noise(tri) {
        Noise::Band(sigma) => (sigma, true),
        Noise::Uncertain(sigma) => (sigma, false),
        Noise::Area => return Reading::Area,
        Noise::Neither => return Reading::Neither,
    };
    let radius = COVER_RADIUS * sigma;
    if !(radius.is_finite() && radius > 0.0) {
        return Reading::Neither;
    }
    let representatives = cover(&tri.points, radius);
    // A radius under the spacing leaves every disk one point, and no disk is kept: reading
    // such a sample as a band would return no curve at all.
    if representatives.len() < 3 {
        return Reading::Neither;
    }
    if certain {
        Reading::Band(representatives)
    } else {
        Reading::Uncertain(representatives)
    }
}

/// The noise of a band, or what else the probes saw.
enum Noise {
    /// A band: the noise its cover is drawn for (its across deviation, at least
    /// [`BAND_SPACINGS`] of its spacing), in the frame's units.
    Band(f64),
    /// Noise of at least [`UNCERTAIN_SPACINGS`] of the spacing, short of a band: the noise a
    /// cover of it is drawn for, as for a band.
    Uncertain(f64),
    Area,
    Neither,
}

/// The noise of the band or of the uncertain sample (see [`Noise`]), or what else the
/// probes saw.
fn band_noise(tri: &Triangulation) -> Noise {
    let n = tri.points.len();
    let rate = n.div_ceil(SUBSAMPLE).max(1);
    let subsample;
    // The full set's local index of each subsample point (by the subsample's input index).
    let mut kept_ids: Vec<LocalPoint> = Vec::new();
    let (probed, graph) = if rate == 1 {
        (tri, Graph::adjacency(tri))
    } else {
        kept_ids = ids::<LocalPoint>(n)
            .filter(|p| mix(p.get() as u64) % rate as u64 == 0)
            .collect();
        let kept: Vec<[f64; 2]> = kept_ids.iter().map(|p| tri.points[p.index()]).collect();
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
    let probe = |i: usize| LocalPoint::new((i * stride) as u32);
    let turns = parallel::map_range(probes, |i| turn(probed, &graph, probe(i)));
    // The probes whose noise is at least `threshold` spacings, when they are at least half
    // of them: their deviations, sorted.
    let banded = |threshold: f64| -> Option<Vec<f64>> {
        let banded_at: Vec<usize> = (0..probes)
            .filter(|&i| {
                turns[i].as_ref().is_some_and(|t| {
                    // The spacing along the curve of all the points, not only the subsample's.
                    t.deviation >= threshold * t.spacing(rate)
                })
            })
            .collect();
        // A subsample's neighbourhood spans `rate` times more curve than the same number of
        // all the points, and on a curved stretch its deviation is the arc's sagitta, not
        // noise: clean curves of 200 000 and 10^6 points read as bands. A subsample probe
        // counts for the band only where all the points around it do not turn thin, within
        // CONFIRM_RUNGS of the ladder, with a deviation under QUIET_SPACINGS of their spacing
        // (a band too wide to turn thin that soon is confirmed as it was read).
        let banded_at = if rate == 1 || 2 * banded_at.len() < probes {
            banded_at
        } else {
            let quiet = parallel::map_range(banded_at.len(), |k| {
                let at = kept_ids[probed.input_index(probe(banded_at[k])) as usize];
                turn_in_order(&tri.points, at)
                    .is_some_and(|t| t.deviation < QUIET_SPACINGS * t.spacing(1))
            });
            banded_at
                .iter()
                .zip(quiet)
                .filter(|&(_, quiet)| !quiet)
                .map(|(&i, _)| i)
                .collect()
        };
        let mut deviations: Vec<f64> = banded_at
            .iter()
            .filter_map(|&i| turns[i].as_ref().map(|t| t.deviation))
            .collect();
        if 2 * deviations.len() < probes {
            return None;
        }
        deviations.sort_by(f64::total_cmp);
        Some(deviations)
    };
    // The noise the cover is drawn for: the banded probes' median deviation, and never less
    // than BAND_SPACINGS of the sample's spacing (the median over the probes that turned),
    // the thinnest band read below LARGE_SAMPLE. Finer covers (large samples from a third
    // of a spacing, uncertain ones from a fifth) hold a few points a disk: their
    // representatives were spaced unevenly, in gaps five times their median step, and
    // the water flow left open curves in pieces and closed curves open.
    let cover_noise = |deviations: Vec<f64>| {
        let mut spacings: Vec<f64> = turns.iter().flatten().map(|t| t.spacing(rate)).collect();
        spacings.sort_by(f64::total_cmp);
        let spacing = spacings.get(spacings.len() / 2).copied().unwrap_or(0.0);
        deviations[deviations.len() / 2].max(BAND_SPACINGS * spacing)
    };
    if let Some(deviations) = banded(threshold) {
        return Noise::Band(cover_noise(deviations));
    }
    if let Some(deviations) = banded(UNCERTAIN_SPACINGS) {
        return Noise::Uncertain(cover_noise(deviations));
    }
    let never_thin = turns.iter().filter(|t| t.is_none()).count();
    if 2 * never_thin >= probes {
        Noise::Area
    } else {
        Noise::Neither
    }
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

impl Turn {
    /// The spacing along the curve of the points the neighbourhood was drawn from, when
    /// it holds one in every `rate` of them (a subsample's neighbourhood spans `rate` times
    /// more curve than as many of all the points).
    fn spacing(&self, rate: usize) -> f64 {
        2.0 * self.radius / (self.size * rate) as f64
    }
}

/// Where the neighbourhood of `p` (its Delaunay neighbours, nearest first) turns thin;
/// `None` if none up to the ladder's last size is.
fn turn(tri: &Triangulation, graph: &Graph, p: LocalPoint) -> Option<Turn> {
    let o = tri.points[p.index()];
    let mut seen: HashSet<LocalPoint, FastHash> = HashSet::default();
    seen.insert(p);
    let mut waiting = std::collections::BinaryHeap::new();
    for &q in graph.of(p) {
        seen.insert(q);
        waiting.push(Waiting(distance(o, tri.points[q.index()]), q));
    }
    let nearest_first = std::iter::from_fn(|| {
        let Waiting(d, q) = waiting.pop()?;
        for &w in graph.of(q) {
            if seen.insert(w) {
                waiting.push(Waiting(distance(o, tri.points[w.index()]), w));
            }
        }
        Some((d, tri.points[q.index()]))
    });
    first_thin(o, nearest_first, LADDER.len())
}

/// Where the neighbourhood of `p` turns thin within the ladder's first [`CONFIRM_RUNGS`]
/// sizes, its neighbours taken nearest first from the points within twice the last size of
/// it in the locality order (no Delaunay graph of all the points: building one cost as much
/// as the rest of the band test). The locality order keeps near points near, so these are
/// points around `p`; on a curve any of them lie on the curve and the neighbourhood is thin
/// from the start, in a band they fill a patch of it.
fn turn_in_order(points: &[[f64; 2]], p: LocalPoint) -> Option<Turn> {
    let o = points[p.index()];
    let reach = 2 * LADDER[CONFIRM_RUNGS - 1];
    let (low, high) = (
        p.index().saturating_sub(reach),
        (p.index() + reach + 1).min(points.len()),
    );
    let mut near: Vec<(f64, usize)> = (low..high)
        .filter(|&i| i != p.index())
        .map(|i| (distance(o, points[i]), i))
        .collect();
    near.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
    first_thin(o, near.iter().map(|&(d, i)| (d, points[i])), CONFIRM_RUNGS)
}

/// Where a neighbourhood of `o`, given nearest first as (distance, point), turns thin; `None`
/// if none of the ladder's first `rungs` sizes is.
fn first_thin(
    o: [f64; 2],
    nearest_first: impl Iterator<Item = (f64, [f64; 2])>,
    rungs: usize,
) -> Option<Turn> {
    let mut moments = Moments::default();
    let mut rung = 0;
    for (d, x) in nearest_first {
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
            if rung == rungs {
                return None;
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

/// No cell, no seed, no representative: the end of a list.
const NONE: u32 = u32::MAX;

/// The points bucketed by the cells of a grid of side `radius`: the non-empty cells
/// numbered in order of first use, each cell's points contiguous and ascending, and each
/// cell's neighbourhood as cell numbers (looked up once a cell, not once a point).
struct CellGrid {
    /// The cell number of every point.
    cell_of: Vec<u32>,
    /// The points of cell `c` are `members[start[c]..start[c + 1]]`.
    start: Vec<u32>,
    members: Vec<LocalPoint>,
    /// The non-empty cells among each cell's neighbourhood, `NONE` for the rest.
    around: Vec<[u32; 9]>,
}

impl CellGrid {
    fn new(points: &[[f64; 2]], radius: f64) -> Self {
        let cell = |p: [f64; 2]| -> Cell {
            (
                (p[0] / radius).floor() as i64,
                (p[1] / radius).floor() as i64,
            )
        };
        let mut number: HashMap<Cell, u32, FastHash> = HashMap::default();
        let mut cells: Vec<Cell> = Vec::new();
        let mut count: Vec<u32> = Vec::new();
        let cell_of: Vec<u32> = points
            .iter()
            .map(|&x| {
                let c = cell(x);
                let k = *number.entry(c).or_insert_with(|| {
                    cells.push(c);
                    count.push(0);
                    (cells.len() - 1) as u32
                });
                count[k as usize] += 1;
                k
            })
            .collect();
        drop(number);
        let mut start = Vec::with_capacity(cells.len() + 1);
        let mut total = 0u32;
        start.push(0);
        for &c in &count {
            total += c;
            start.push(total);
        }
        let mut fill: Vec<u32> = start[..cells.len()].to_vec();
        let mut members = vec![LocalPoint::new(0); points.len()];
        for (p, &k) in ids::<LocalPoint>(points.len()).zip(&cell_of) {
            members[fill[k as usize] as usize] = p;
            fill[k as usize] += 1;
        }
        let around = neighbour_cells(&cells);
        CellGrid {
            cell_of,
            start,
            members,
            around,
        }
    }

    /// The points of cell `c`, ascending.
    fn points(&self, c: u32) -> &[LocalPoint] {
        &self.members[self.start[c as usize] as usize..self.start[c as usize + 1] as usize]
    }

    /// The non-empty cells of `p`'s neighbourhood.
    fn cells_around(&self, p: LocalPoint) -> impl Iterator<Item = u32> + '_ {
        self.around[self.cell_of[p.index()] as usize]
            .into_iter()
            .filter(|&c| c != NONE)
    }
}

/// For every cell (numbered by its position in `cells`, all distinct), the numbers of the
/// cells of its neighbourhood (itself and the eight around it) that are in `cells` (its own
/// first), `NONE` for the rest. Far out (a radius tiny against the coordinates) the cell
/// indices saturate at the ends of `i64`: the cells beside one there are those that exist,
/// and a point's disk still lies within them, since saturation keeps indices that differ by
/// at most one within one.
/// The cells sorted by row and column, each row's neighbours in the rows beside it are
/// found by one forward sweep a row: linear after the sort, where a hash lookup for each of
/// the eight neighbours cost as much as bucketing all the points.
fn neighbour_cells(cells: &[Cell]) -> Vec<[u32; 9]> {
    let mut order: Vec<u32> = (0..cells.len() as u32).collect();
    order.sort_unstable_by_key(|&k| cells[k as usize]);
    let sorted = |i: usize| cells[order[i] as usize];
    // The rows: runs of equal first index in the sorted order.
    let mut rows: Vec<(i64, usize, usize)> = Vec::new();
    for i in 0..order.len() {
        let row = sorted(i).0;
        match rows.last_mut() {
            Some((r, _, end)) if *r == row => *end = i + 1,
            _ => rows.push((row, i, i + 1)),
        }
    }
    let mut around = vec![[NONE; 9]; cells.len()];
    for (r, &(row, begin, end)) in rows.iter().enumerate() {
        // This row and the rows just below and above, where present (saturated rows at
        // the ends of i64 can coincide: each row is swept once).
        let mut beside: Vec<(usize, usize)> = vec![(begin, end)];
        for other in [r.wrapping_sub(1), r + 1] {
            if let Some(&(o, b, e)) = rows.get(other) {
                if o.abs_diff(row) == 1 {
                    beside.push((b, e));
                }
            }
        }
        for &(b, e) in &beside {
            // Sweep the other row once along this one: both are sorted by column.
            let mut at = b;
            for i in begin..end {
                let (ci, cj) = sorted(i);
                let low = cj.saturating_sub(1);
                while at < e && sorted(at).1 < low {
                    at += 1;
                }
                let mut k = at;
                while k < e && sorted(k).1 <= cj.saturating_add(1) {
                    let (oi, oj) = sorted(k);
                    let slots = &mut around[order[i] as usize];
                    if (oi, oj) == (ci, cj) {
                        slots[0] = order[k];
                    } else {
                        let free = slots[1..].iter().position(|&c| c == NONE).map(|f| f + 1);
                        if let Some(f) = free {
                            slots[f] = order[k];
                        }
                    }
                    k += 1;
                }
            }
        }
    }
    around
}

/// Some of the points (seeds, representatives) kept as a list per cell of a [`CellGrid`].
struct Chosen {
    head: Vec<u32>,
    next: Vec<u32>,
    point: Vec<LocalPoint>,
}

impl Chosen {
    fn new(grid: &CellGrid) -> Self {
        Chosen {
            head: vec![NONE; grid.around.len()],
            next: Vec::new(),
            point: Vec::new(),
        }
    }

    fn push(&mut self, grid: &CellGrid, p: LocalPoint) {
        let c = grid.cell_of[p.index()] as usize;
        self.next.push(self.head[c]);
        self.point.push(p);
        self.head[c] = (self.point.len() - 1) as u32;
    }

    /// Whether a chosen point lies within `r` of point `p`.
    fn within(&self, grid: &CellGrid, points: &[[f64; 2]], p: LocalPoint, r: f64) -> bool {
        let x = points[p.index()];
        grid.cells_around(p).any(|c| {
            let mut k = self.head[c as usize];
            while k != NONE {
                if distance(x, points[self.point[k as usize].index()]) < r {
                    return true;
                }
                k = self.next[k as usize];
            }
            false
        })
    }
}

/// The representatives of the points covered by disks of `radius` (local indices,
/// ascending).
///
/// 1. Seeds, greedily in local order: a point becomes a seed when no seed lies within
///    `radius`.
/// 2. Each seed's disk: the point nearest the centroid of the points within `radius` of the
///    seed; then, [`RECENTRINGS`] times, the point nearest the centroid of the disk around
///    that point. The centroid of a disk that spans the band lies near its middle, wherever
///    in the band the seed was, and nearer it once re-centred; so two seeds side by side
///    across the band (they can be, in a band wider than `radius`) give candidates close
///    together. A seed's disk with fewer points than [`MIN_CLUSTER_SHARE`] of the median
///    disk's gives none (outliers, frayed edges).
/// 3. Candidates in seed order, each kept unless a kept one lies within half the radius:
///    one file of representatives along the band.
///
/// The points are bucketed once into a grid of side `radius` (a disk lies within its
/// seed's cell and the eight around it); seeds and kept candidates are lists per cell.
fn cover(points: &[[f64; 2]], radius: f64) -> Vec<LocalPoint> {
    let grid = CellGrid::new(points, radius);
    let mut seeds = Chosen::new(&grid);
    for p in ids::<LocalPoint>(points.len()) {
        if !seeds.within(&grid, points, p, radius) {
            seeds.push(&grid, p);
        }
    }
    let seed_order = &seeds.point;
    // Each seed's disk: its size and the point nearest its centroid.
    // The disk of radius `radius` around point `at`: its size and the point nearest its
    // centroid.
    let disk = |at: LocalPoint| -> (usize, LocalPoint) {
        let o = points[at.index()];
        let mut sorted: Vec<LocalPoint> = grid
            .cells_around(at)
            .flat_map(|c| grid.points(c))
            .copied()
            .filter(|&q| distance(o, points[q.index()]) < radius)
            .collect();
        // In local order, relative to the seed: the same sums for any input order.
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
            .map_or(at, |(_, q)| q);
        (count, nearest)
    };
    // The seed's disk counts; its candidate comes from the disk re-centred on the point
    // nearest its centroid (RECENTRINGS times): a mean-shift step toward the band's middle.
    let disks = parallel::map_range(seed_order.len(), |k| {
        let (count, mut nearest) = disk(seed_order[k]);
        for _ in 0..RECENTRINGS {
            nearest = disk(nearest).1;
        }
        (count, nearest)
    });
    let mut sizes: Vec<usize> = disks.iter().map(|d| d.0).collect();
    sizes.sort_unstable();
    let median = sizes.get(sizes.len() / 2).copied().unwrap_or(0);
    let least = ((MIN_CLUSTER_SHARE * median as f64).ceil() as usize).max(2);
    let mut kept = Chosen::new(&grid);
    for &(count, candidate) in &disks {
        if count >= least && !kept.within(&grid, points, candidate, 0.5 * radius) {
            kept.push(&grid, candidate);
        }
    }
    let mut reps = kept.point;
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
    fn a_cover_finer_than_the_spacing_keeps_no_representative() {
        // Points a unit apart, disks of half a unit: each holds its seed alone, the median
        // disk one point, and none is kept (which `read` takes for no band).
        let points: Vec<[f64; 2]> = (0..500).map(|k| [k as f64, (k % 2) as f64 * 0.1]).collect();
        assert!(cover(&points, 0.5).is_empty());
        assert!(!cover(&points, 3.0).is_empty());
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
    fn cells_list_their_neighbours_once_even_where_indices_saturate() {
        // Every cell's listed neighbours are exactly the listed cells within one row and
        // one column of it (saturating), its own first: checked against all pairs on cells
        // at the ends of i64 and in the middle, with gaps and rows of different lengths.
        let (max, min) = (i64::MAX, i64::MIN);
        let cells: Vec<Cell> = vec![
            (max, min),
            (max - 1, min),
            (max - 1, min + 1),
            (max, min + 2),
            (0, 0),
            (1, 1),
            (-1, 1),
            (0, 2),
            (2, 0),
            (0, -1),
            (1, 5),
            (0, 4),
            (-1, 3),
        ];
        let around = neighbour_cells(&cells);
        for (k, &(i, j)) in cells.iter().enumerate() {
            assert_eq!(around[k][0], k as u32);
            let mut listed: Vec<u32> = around[k].iter().copied().filter(|&c| c != NONE).collect();
            listed.sort_unstable();
            let expected: Vec<u32> = (0..cells.len() as u32)
                .filter(|&o| {
                    let (oi, oj) = cells[o as usize];
                    oi.abs_diff(i) <= 1 && oj.abs_diff(j) <= 1
                })
                .collect();
            assert_eq!(listed, expected, "cell {:?}", (i, j));
        }
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
