//! Noise and outliers for quality benchmarks.

use super::curve::DenseCurve;
use super::rng::Rng;
use super::vec2::bbox;

/// Adds independent Gaussian noise with standard deviation `sigma` to each coordinate.
///
/// ```
/// use wdm_crust_testkit::{add_gaussian_noise, Rng};
/// let mut pts = vec![[0.0, 0.0]; 1000];
/// add_gaussian_noise(&mut pts, 0.1, &mut Rng::new(1));
/// let var = pts.iter().map(|p| p[0] * p[0]).sum::<f64>() / 1000.0;
/// assert!((var - 0.01).abs() < 0.002);
/// ```
pub fn add_gaussian_noise(points: &mut [[f64; 2]], sigma: f64, rng: &mut Rng) {
    for p in points {
        p[0] += sigma * rng.normal();
        p[1] += sigma * rng.normal();
    }
}

/// `round(percent / 100 · n)` points uniformly distributed in the bounding box of `points`
/// (`n = points.len()`); none if `points` is empty.
pub fn uniform_outliers(points: &[[f64; 2]], percent: f64, rng: &mut Rng) -> Vec<[f64; 2]> {
    if points.is_empty() {
        return Vec::new();
    }
    let count = (percent.max(0.0) / 100.0 * points.len() as f64).round() as usize;
    let (lo, hi) = bbox(points.iter().copied());
    (0..count)
        .map(|_| [rng.range(lo[0], hi[0]), rng.range(lo[1], hi[1])])
        .collect()
}

/// The points of `curves` (evenly spaced dense curves) with Gaussian noise of `noise` × the
/// mean sample spacing on each coordinate, shuffled: the noisy rows of the quality survey.
pub fn noisy_curve_sample(curves: &[DenseCurve], noise: f64, rng: &mut Rng) -> Vec<[f64; 2]> {
    let n: usize = curves.iter().map(|c| c.points.len()).sum();
    let spacing = curves.iter().map(|c| c.length()).sum::<f64>() / n as f64;
    let mut points: Vec<[f64; 2]> = curves
        .iter()
        .flat_map(|c| c.points.iter().copied())
        .map(|[x, y]| {
            [
                x + noise * spacing * rng.normal(),
                y + noise * spacing * rng.normal(),
            ]
        })
        .collect();
    rng.shuffle(&mut points);
    points
}
