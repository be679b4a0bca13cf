//! Point sets shared by the benches: deterministic, dependency-free, fast enough for 10^7.

#![allow(dead_code)] // each bench target uses a subset

use std::f64::consts::TAU;

pub mod baselines;

/// SplitMix64, so the benches need no extra dependency.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Standard normal (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let u = 1.0 - self.uniform(); // (0, 1]
        (-2.0 * u.ln()).sqrt() * (TAU * self.uniform()).cos()
    }

    pub fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            let j = (self.next_u64() % (i as u64 + 1)) as usize;
            v.swap(i, j);
        }
    }
}

/// The point sets of the benches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointSet {
    /// Uniform in the unit square.
    Uniform,
    /// 20 Gaussian clusters (σ = 0.02) with uniform centres.
    Clusters,
    /// The integer grid, row by row, shuffled: maximally cocircular.
    Grid,
    /// A closed smooth curve (five-armed star, squashed), sampled at jittered even spacing with
    /// radial noise of a tenth of the spacing, shuffled: the reconstruction workload.
    Curve,
}

impl PointSet {
    pub const ALL: [PointSet; 4] = [
        PointSet::Uniform,
        PointSet::Clusters,
        PointSet::Grid,
        PointSet::Curve,
    ];

    pub fn name(self) -> &'static str {
        match self {
            PointSet::Uniform => "uniform",
            PointSet::Clusters => "clusters",
            PointSet::Grid => "grid",
            PointSet::Curve => "curve",
        }
    }

    pub fn parse(name: &str) -> Option<PointSet> {
        PointSet::ALL.into_iter().find(|s| s.name() == name)
    }

    pub fn points(self, n: usize, seed: u64) -> Vec<[f64; 2]> {
        let mut rng = Rng::new(seed);
        match self {
            PointSet::Uniform => (0..n).map(|_| [rng.uniform(), rng.uniform()]).collect(),
            PointSet::Clusters => {
                let centres: Vec<[f64; 2]> =
                    (0..20).map(|_| [rng.uniform(), rng.uniform()]).collect();
                (0..n)
                    .map(|i| {
                        let c = centres[i % centres.len()];
                        [c[0] + 0.02 * rng.normal(), c[1] + 0.02 * rng.normal()]
                    })
                    .collect()
            }
            PointSet::Grid => {
                let side = (n as f64).sqrt().ceil() as usize;
                let mut pts: Vec<[f64; 2]> = (0..n)
                    .map(|i| [(i % side) as f64, (i / side) as f64])
                    .collect();
                rng.shuffle(&mut pts);
                pts
            }
            PointSet::Curve => curve_points(n, &mut rng),
        }
    }
}

/// `n` samples of the star `r(t) = 1 + 0.3 cos 5t`, squashed to 0.7 in y.
pub fn curve_points(n: usize, rng: &mut Rng) -> Vec<[f64; 2]> {
    let spacing = TAU / n as f64;
    let mut pts: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = (i as f64 + 0.5 * rng.uniform()) * spacing;
            let r = 1.0 + 0.3 * (5.0 * t).cos() + 0.1 * spacing * rng.normal();
            [r * t.cos(), 0.7 * r * t.sin()]
        })
        .collect();
    rng.shuffle(&mut pts);
    pts
}

/// `n` points of a dense noisy band around the same star: evenly spread along it, Gaussian
/// noise of `sigma` times the curve's bounding-box diagonal on each coordinate (a contour scan
/// or a traced raster: the band is many sample spacings wide), shuffled.
pub fn band_points(n: usize, sigma: f64, rng: &mut Rng) -> Vec<[f64; 2]> {
    // The star spans [-1.3, 1.3] × [-0.91, 0.91]: diagonal about 3.17.
    let noise = sigma * 3.17;
    let mut pts: Vec<[f64; 2]> = (0..n)
        .map(|_| {
            let t = TAU * rng.uniform();
            let r = 1.0 + 0.3 * (5.0 * t).cos();
            [
                r * t.cos() + noise * rng.normal(),
                0.7 * r * t.sin() + noise * rng.normal(),
            ]
        })
        .collect();
    rng.shuffle(&mut pts);
    pts
}

/// 10^3 … 10^6, and 10^7 when `WDM_BENCH_HUGE` is set (minutes per run).
pub fn sizes() -> Vec<usize> {
    let mut sizes = vec![1_000, 10_000, 100_000, 1_000_000];
    if std::env::var_os("WDM_BENCH_HUGE").is_some() {
        sizes.push(10_000_000);
    }
    sizes
}
