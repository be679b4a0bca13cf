//! ε-sampling of dense curves with known adjacency, and the resulting ground truth.

use super::curve::{DenseCurve, Similarity};
use super::kdtree::KdTree;
use super::lfs::local_feature_size;
use super::noise::{add_gaussian_noise, uniform_outliers};
use super::rng::Rng;
use super::vec2::{dist, P2};
use std::collections::BTreeSet;

/// Parameters of the ε-sampler.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampleConfig {
    /// Every dense point `x` gets a sample within `eps · max(lfs(x), lfs_floor)`.
    pub eps: f64,
    /// Each step is a uniformly random fraction in `[min_step_fraction, 1]` of the longest
    /// admissible step (by arc length). `1.0` gives the sparsest greedy sample.
    pub min_step_fraction: f64,
    /// Lower bound on the lfs used for spacing. The lfs tends to 0 at sharp corners, where a
    /// true ε-sample would grade geometrically down to the dense spacing; a floor stops that.
    pub lfs_floor: f64,
}

impl SampleConfig {
    /// `eps` with random steps in `[0.5, 1]` of the longest admissible one and no lfs floor.
    pub fn new(eps: f64) -> Self {
        SampleConfig {
            eps,
            min_step_fraction: 0.5,
            lfs_floor: 0.0,
        }
    }
}

/// A set of dense curves (disjoint, possibly nested) with the local feature size of their
/// union at every dense point.
#[derive(Debug, Clone, PartialEq)]
pub struct CurveSet {
    /// The curves.
    pub curves: Vec<DenseCurve>,
    /// `lfs[c][i]`: local feature size at dense point `i` of curve `c`.
    pub lfs: Vec<Vec<f64>>,
}

/// The samples of one curve, as indices into [`Sample::points`] in curve order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SampledCurve {
    /// Sample indices in curve order.
    pub indices: Vec<usize>,
    /// Whether the last sample connects back to the first.
    pub closed: bool,
}

/// Sample points with their ground-truth curve adjacency.
///
/// Freshly sampled, the points are in curve order, curve after curve; after
/// [`Sample::shuffled`] they are not, but [`Sample::curves`] and [`Sample::edges`] still give
/// the adjacency.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Sample {
    /// The points.
    pub points: Vec<[f64; 2]>,
    /// Local feature size of the curve at each point (`NaN` for outliers, which lie on no
    /// curve; noise does not change it).
    pub lfs: Vec<f64>,
    /// The curves through the points.
    pub curves: Vec<SampledCurve>,
}

impl CurveSet {
    /// Computes the local feature size of the union of `curves` (see
    /// [`local_feature_size`]).
    pub fn new(curves: Vec<DenseCurve>) -> Self {
        let lfs = local_feature_size(&curves);
        CurveSet { curves, lfs }
    }

    /// The image under a similarity; the lfs scales with it.
    pub fn transformed(&self, s: &Similarity) -> CurveSet {
        CurveSet {
            curves: self.curves.iter().map(|c| c.transformed(s)).collect(),
            lfs: self
                .lfs
                .iter()
                .map(|l| l.iter().map(|&f| f * s.scale).collect())
                .collect(),
        }
    }

    /// An ε-sample with the default configuration ([`SampleConfig::new`]).
    pub fn eps_sample(&self, eps: f64, rng: &mut Rng) -> Sample {
        self.eps_sample_with(&SampleConfig::new(eps), rng)
    }

    /// An ε-sample of every curve, merged in curve order.
    ///
    /// Samples are dense points. Corners and the ends of open curves are always samples; a
    /// closed curve without corners starts at a random dense point. From each sample the
    /// sampler finds the longest step to a later dense point such that every dense point in
    /// between is within `eps · max(lfs, lfs_floor)` of one of the two ends, then takes a
    /// random fraction of it; so every dense point is covered (by construction, not by luck),
    /// yet the sample is irregular and not much denser than needed. A closed curve gets at
    /// least 3 samples (steps are capped at a third of its dense points).
    ///
    /// The guarantee holds on the dense points; between two of them the curve is at most half
    /// a dense spacing farther from a sample.
    ///
    /// An `eps` that is not a positive number admits no sample: the result is then empty.
    pub fn eps_sample_with(&self, config: &SampleConfig, rng: &mut Rng) -> Sample {
        if config.eps.is_nan() || config.eps <= 0.0 {
            return Sample::default();
        }
        let parts = self
            .curves
            .iter()
            .zip(&self.lfs)
            .map(|(curve, lfs)| sample_curve(curve, lfs, config, rng));
        Sample::merge(parts)
    }

    /// The smallest `ε` for which `points` is an ε-sample, measured on the dense points:
    /// the maximum over dense `x` of `dist(x, nearest point) / max(lfs(x), lfs_floor)`.
    ///
    /// Returns infinity when `points` is empty and the curve set is not.
    pub fn coverage(&self, points: &[[f64; 2]], lfs_floor: f64) -> f64 {
        let tree = KdTree::new(points);
        let mut worst: f64 = 0.0;
        for (curve, lfs) in self.curves.iter().zip(&self.lfs) {
            for (&x, &f) in curve.points.iter().zip(lfs) {
                let d = tree.nearest(x).map_or(f64::INFINITY, |(_, d2)| d2.sqrt());
                worst = worst.max(d / f.max(lfs_floor));
            }
        }
        worst
    }
}

/// Walks one dense curve in an unrolled index space (`k` stands for point `k mod n`).
struct Walker<'a> {
    points: &'a [P2],
    /// Allowed distance to a sample at each dense point: `eps · max(lfs, floor)`.
    reach: Vec<f64>,
    /// Arc length from point 0 to point `k`, for `k ≤ n` (entry `n` is the full length).
    arc: Vec<f64>,
}

impl Walker<'_> {
    fn at(&self, k: usize) -> P2 {
        self.points[k % self.points.len()]
    }

    fn arc_at(&self, k: usize) -> f64 {
        let n = self.points.len();
        self.arc[k % n] + (k / n) as f64 * self.arc[n]
    }

    /// Whether samples at `i` and `j` cover every dense point strictly between them.
    fn admissible(&self, i: usize, j: usize) -> bool {
        let (a, b) = (self.at(i), self.at(j));
        (i + 1..j).all(|k| {
            let (x, r) = (self.at(k), self.reach[k % self.points.len()]);
            dist(x, a) <= r || dist(x, b) <= r
        })
    }

    /// The largest admissible `j` in `(i, hi]` found by doubling then bisection (`i + 1` is
    /// always admissible: nothing lies between). Every returned value was checked.
    fn longest_step(&self, i: usize, hi: usize) -> usize {
        let mut good = i + 1;
        let mut bad = None;
        let mut step = 2;
        while good < hi {
            let j = (i + step).min(hi);
            if self.admissible(i, j) {
                good = j;
                step *= 2;
            } else {
                bad = Some(j);
                break;
            }
        }
        if let Some(mut bad) = bad {
            while bad - good > 1 {
                let mid = good + (bad - good) / 2;
                if self.admissible(i, mid) {
                    good = mid;
                } else {
                    bad = mid;
                }
            }
        }
        good
    }

    /// Samples strictly after `from` up to and including `to` (unrolled indices).
    fn walk(
        &self,
        from: usize,
        to: usize,
        cap: usize,
        cfg: &SampleConfig,
        rng: &mut Rng,
    ) -> Vec<usize> {
        let mut out = Vec::new();
        let mut i = from;
        while i < to {
            let longest = self.longest_step(i, to.min(i + cap));
            let j = if longest == to {
                to
            } else {
                let u = rng.range(cfg.min_step_fraction.clamp(0.0, 1.0), 1.0);
                let target = self.arc_at(i) + u * (self.arc_at(longest) - self.arc_at(i));
                let j = (i + 1..=longest)
                    .find(|&k| self.arc_at(k) >= target)
                    .unwrap_or(longest);
                // Coverage is not monotone in the step in theory; fall back if it fails.
                if self.admissible(i, j) {
                    j
                } else {
                    longest
                }
            };
            out.push(j);
            i = j;
        }
        out
    }
}

/// ε-samples one curve; the result's indices are local (0-based) and points in curve order.
fn sample_curve(curve: &DenseCurve, lfs: &[f64], cfg: &SampleConfig, rng: &mut Rng) -> Sample {
    let n = curve.points.len();
    if n == 0 {
        return Sample::default();
    }
    let mut arc = Vec::with_capacity(n + 1);
    arc.push(0.0);
    for k in 0..n {
        let next = if k + 1 < n { k + 1 } else { 0 };
        let step = if k + 1 < n || curve.closed {
            dist(curve.points[k], curve.points[next])
        } else {
            0.0
        };
        arc.push(arc[k] + step);
    }
    let walker = Walker {
        points: &curve.points,
        reach: lfs
            .iter()
            .map(|&f| cfg.eps * f.max(cfg.lfs_floor))
            .collect(),
        arc,
    };
    let dense_indices = if curve.closed {
        closed_walk(&walker, &curve.corners, n, cfg, rng)
    } else {
        open_walk(&walker, &curve.corners, n, cfg, rng)
    };
    let len = dense_indices.len();
    Sample {
        points: dense_indices.iter().map(|&k| curve.points[k]).collect(),
        lfs: dense_indices.iter().map(|&k| lfs[k]).collect(),
        curves: vec![SampledCurve {
            indices: (0..len).collect(),
            closed: curve.closed && len >= 3,
        }],
    }
}

/// Dense indices of the samples of a closed curve, starting at a random corner (or a random
/// point if there are none).
fn closed_walk(
    w: &Walker,
    corners: &[usize],
    n: usize,
    cfg: &SampleConfig,
    rng: &mut Rng,
) -> Vec<usize> {
    let mut forced: Vec<usize> = corners.iter().copied().filter(|&c| c < n).collect();
    if forced.is_empty() {
        forced.push(rng.below(n));
    } else {
        let start = rng.below(forced.len());
        forced.rotate_left(start);
    }
    // Unroll so that the forced points increase, ending back at the start plus n.
    let first = forced[0];
    let mut stops: Vec<usize> = forced
        .iter()
        .map(|&f| if f >= first { f } else { f + n })
        .collect();
    stops.push(first + n);
    let cap = (n / 3).max(1);
    let mut out = vec![first];
    for pair in stops.windows(2) {
        out.extend(w.walk(pair[0], pair[1], cap, cfg, rng));
    }
    out.pop(); // the walk ended back at the start
    out.iter().map(|&k| k % n).collect()
}

/// Dense indices of the samples of an open curve, from its first to its last point.
fn open_walk(
    w: &Walker,
    corners: &[usize],
    n: usize,
    cfg: &SampleConfig,
    rng: &mut Rng,
) -> Vec<usize> {
    let mut stops: Vec<usize> = std::iter::once(0)
        .chain(corners.iter().copied().filter(|&c| c < n))
        .chain(std::iter::once(n - 1))
        .collect();
    stops.sort_unstable();
    stops.dedup();
    let mut out = vec![0];
    for pair in stops.windows(2) {
        out.extend(w.walk(pair[0], pair[1], n, cfg, rng));
    }
    out
}

impl Sample {
    /// Number of points (outliers included).
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether there are no points.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The ground-truth edges `[a, b]`: consecutive samples of each curve, plus the closing
    /// edge of closed curves, in curve order.
    pub fn edges(&self) -> Vec<[usize; 2]> {
        let mut edges = Vec::new();
        for c in &self.curves {
            edges.extend(c.indices.windows(2).map(|w| [w[0], w[1]]));
            if c.closed && c.indices.len() >= 3 {
                edges.push([c.indices[c.indices.len() - 1], c.indices[0]]);
            }
        }
        edges
    }

    /// The ground-truth edges as a set of index pairs `(min, max)`, for comparing with a
    /// reconstruction.
    pub fn edge_set(&self) -> BTreeSet<(usize, usize)> {
        self.edges()
            .iter()
            .map(|&[a, b]| (a.min(b), a.max(b)))
            .collect()
    }

    /// Concatenates samples (e.g. of disjoint or nested curves), offsetting each part's
    /// indices by the number of points before it.
    pub fn merge(parts: impl IntoIterator<Item = Sample>) -> Sample {
        let mut out = Sample::default();
        for part in parts {
            let offset = out.points.len();
            out.points.extend(part.points);
            out.lfs.extend(part.lfs);
            out.curves
                .extend(part.curves.into_iter().map(|c| SampledCurve {
                    indices: c.indices.iter().map(|&i| i + offset).collect(),
                    closed: c.closed,
                }));
        }
        out
    }

    /// The image under a similarity (the lfs scales with it).
    pub fn transformed(&self, s: &Similarity) -> Sample {
        Sample {
            points: self.points.iter().map(|&p| s.apply(p)).collect(),
            lfs: self.lfs.iter().map(|&f| f * s.scale).collect(),
            curves: self.curves.clone(),
        }
    }

    /// The same sample with the points in a random order; the curves are remapped, so the
    /// edges connect the same pairs of points.
    pub fn shuffled(&self, rng: &mut Rng) -> Sample {
        let order = rng.permutation(self.points.len());
        let mut new_index = vec![0; order.len()];
        for (new, &old) in order.iter().enumerate() {
            new_index[old] = new;
        }
        Sample {
            points: order.iter().map(|&o| self.points[o]).collect(),
            lfs: order.iter().map(|&o| self.lfs[o]).collect(),
            curves: self
                .curves
                .iter()
                .map(|c| SampledCurve {
                    indices: c.indices.iter().map(|&i| new_index[i]).collect(),
                    closed: c.closed,
                })
                .collect(),
        }
    }

    /// A random similarity ([`Similarity::random`]) followed by a shuffle.
    pub fn randomized(&self, rng: &mut Rng) -> Sample {
        let s = Similarity::random(rng);
        self.transformed(&s).shuffled(rng)
    }

    /// The same sample with independent Gaussian noise of standard deviation `sigma` added to
    /// each coordinate of each point.
    pub fn with_noise(&self, sigma: f64, rng: &mut Rng) -> Sample {
        let mut out = self.clone();
        add_gaussian_noise(&mut out.points, sigma, rng);
        out
    }

    /// The same sample with Gaussian noise whose standard deviation at each point is
    /// `fraction · lfs` there (outliers are left alone).
    pub fn with_lfs_noise(&self, fraction: f64, rng: &mut Rng) -> Sample {
        let mut out = self.clone();
        for (p, &f) in out.points.iter_mut().zip(&self.lfs) {
            if f.is_finite() {
                let sigma = fraction * f;
                p[0] += sigma * rng.normal();
                p[1] += sigma * rng.normal();
            }
        }
        out
    }

    /// The same sample with `percent`% of its point count (rounded) added as uniform random
    /// outliers in its bounding box, appended after the curve points (lfs `NaN`, on no curve).
    pub fn with_outliers(&self, percent: f64, rng: &mut Rng) -> Sample {
        let mut out = self.clone();
        let extra = uniform_outliers(&self.points, percent, rng);
        out.lfs.extend(extra.iter().map(|_| f64::NAN));
        out.points.extend(extra);
        out
    }
}
