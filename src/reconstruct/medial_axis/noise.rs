//! How far the samples of a closed curve scatter about a smooth curve, estimated from the
//! samples alone: the pruning's tolerance for balls that noise pushes out of the shape.
//!
//! At sample `i` the circle through `p[i−1], p[i], p[i+1]` has the signed curvature `κ_i`,
//! and `p[i]` lies `d_i = κ_i·a·c/2` off the chord of its neighbours (`a`, `c` the lengths of
//! its two edges). On a smooth curve `κ` varies slowly along the samples whatever their
//! spacing, so the part of `d_i` that its neighbours' curvature does not explain,
//!
//! ```text
//! ψ_i = |κ_i − (κ_{i−1} + κ_{i+1}) / 2| · a·c / 2,
//! ```
//!
//! is of the order of the spacing³ × the curvature's derivative on clean samples (under a
//! hundredth of the spacing on an evenly spaced ellipse, unit test), while Gaussian noise of `σ` gives
//! `ψ ≈ 2σ` (the combination weighs five samples' normal offsets). The amplitude of a sample
//! is the root mean square of `ψ` over it and its [`HALF_WINDOW`] neighbours on either side,
//! so that one unlucky sample neither hides nor dominates its stretch of curve.
//!
//! Lengths only: the estimate scales with the input, and a similarity does not change it
//! relative to the shape. Each value is computed from its stretch of curve the same way in
//! either direction of the loop and from any start (sums are taken in symmetric pairs), so
//! the pruning that reads it does not depend on the order of the input points.

use std::ops::Range;

use super::super::thresholds::medial_axis::{BLOCK, HALF_WINDOW};
use crate::reconstruct::lengths::distance;

/// How far around a sample its estimates read: the amplitude averages `ψ` over
/// [`HALF_WINDOW`] samples on either side, and `ψ` reads the curvatures of the neighbours,
/// which read their neighbours' edges.
const MARGIN: usize = HALF_WINDOW + 2;

/// The noise amplitude and the relative oscillation ([`Estimate`]) at the `samples` (a
/// range of `0..n`) of the closed loop of `n` samples, sample `i` at `position(i)` (in loop
/// order), handed to `each(i, estimate)` in increasing `i`; zeros when the loop is too short to tell noise
/// from shape. Computed together (they share the edges and the curvatures) a block of
/// [`BLOCK`] samples at a time, each with its [`MARGIN`] on either side: every value is
/// computed from the same samples by the same operations as on the whole loop at once, so
/// it does not depend on the block it falls in.
pub(super) fn loop_estimates(
    n: usize,
    position: impl Fn(usize) -> [f64; 2],
    samples: Range<usize>,
    mut each: impl FnMut(usize, Estimate),
) {
    if n < 2 * HALF_WINDOW + 3 {
        samples.for_each(|i| each(i, Estimate::default()));
        return;
    }
    let mut points = Vec::with_capacity(BLOCK + 2 * MARGIN);
    let (mut edge, mut curvature, mut offset) = (Vec::new(), Vec::new(), Vec::new());
    let (mut unexplained, mut zig) = (Vec::new(), Vec::new());
    for first in samples.clone().step_by(BLOCK) {
        let count = BLOCK.min(samples.end - first);
        // Slot `s` holds sample `first + s − MARGIN` (around the loop: `n` exceeds
        // `MARGIN`).
        let len = count + 2 * MARGIN;
        points.clear();
        points.extend((0..len).map(|s| position((first + n + s - MARGIN) % n)));
        // `edge[s]` = |p_s p_s+1|, computed once for both samples it is an arm of (`hypot`,
        // which cannot overflow at any magnitude, is the costly part of this estimate).
        edge.clear();
        edge.extend((0..len - 1).map(|s| distance(points[s], points[s + 1])));
        let arms = |s: usize| edge[s - 1] * edge[s];
        // Curvatures at slots 1..len − 1 (slot 0 unused).
        curvature.clear();
        curvature.extend((0..len - 1).map(|s| {
            if s == 0 {
                return 0.0;
            }
            let (a, b, c) = (points[s - 1], points[s], points[s + 1]);
            signed_curvature(a, b, c, arms(s) * distance(a, c))
        }));
        unexplained.clear();
        unexplained.extend((0..len - 2).map(|s| {
            if s < 2 {
                return 0.0;
            }
            let neighbours = (curvature[s - 1] + curvature[s + 1]) / 2.0;
            let psi = (curvature[s] - neighbours).abs() * arms(s) / 2.0;
            psi * psi
        }));
        // The offsets `d_s = κ_s·a·c/2` from the neighbours' chords (negated exactly when
        // the loop is reversed), then `zig[s]`, of the pair `s, s + 1` (the product of two
        // offsets is not negated).
        offset.clear();
        offset.extend((0..len - 1).map(|s| {
            if s == 0 {
                0.0
            } else {
                curvature[s] * (arms(s) / 2.0)
            }
        }));
        zig.clear();
        zig.extend((0..len - 2).map(|s| (-offset[s] * offset[s + 1]).max(0.0)));
        let pairs = (2 * HALF_WINDOW) as f64;
        for s in MARGIN..MARGIN + count {
            let mut sum = 0.0;
            for k in 1..=HALF_WINDOW {
                // A pair at a time: the same sum whichever way the loop runs.
                sum += unexplained[s - k] + unexplained[s + k];
            }
            let amplitude = ((sum + unexplained[s]) / (2 * HALF_WINDOW + 1) as f64).sqrt();
            let (mut zigs, mut edges) = (0.0, 0.0);
            for k in 0..HALF_WINDOW {
                // The pairs and edges `s + k` and `s − 1 − k` swap when the loop runs the
                // other way: summed two at a time, the same value either way.
                zigs += zig[s + k] + zig[s - 1 - k];
                edges += edge[s + k] + edge[s - 1 - k];
            }
            let oscillation = if edges > 0.0 {
                (zigs / pairs).sqrt() / (edges / pairs)
            } else {
                0.0
            };
            each(
                first + s - MARGIN,
                Estimate {
                    amplitude: amplitude as f32,
                    oscillation: oscillation as f32,
                },
            );
        }
    }
}

/// What the pruning reads of the samples around a point.
#[derive(Clone, Copy, Default, Debug, PartialEq)]
pub(super) struct Estimate {
    /// The noise amplitude: the root mean square of `ψ` over the sample and its
    /// [`HALF_WINDOW`] neighbours on either side (module docs), in the units of the points.
    pub(super) amplitude: f32,
    /// How much the samples zig-zag, relative to their spacing: over the [`HALF_WINDOW`]
    /// pairs of consecutive samples on either side, the root mean square of
    /// `sqrt(max(0, −d_j·d_{j+1}))` (`d` the signed offset of a sample from its neighbours'
    /// chord), divided by the mean edge length there. A smooth curve bends one way between
    /// inflections, so consecutive offsets have one sign and this is exactly 0 on a clean
    /// convex stretch however sparse or quickly curving; noise of `σ` makes consecutive
    /// offsets anticorrelated (correlation −2/3) and reads as about `σ / spacing` (unit
    /// test).
    pub(super) oscillation: f32,
}

/// The signed curvature of the circle through `a`, `b`, `c` (positive when they turn
/// counterclockwise), given `lengths` = `(|ab|·|bc|)·|ac|`; 0 for collinear or repeated
/// points. Exactly negated when the three are taken in reverse (the product of the two arms
/// does not depend on their order, and `hypot` on the negated difference is the same).
fn signed_curvature(a: [f64; 2], b: [f64; 2], c: [f64; 2], lengths: f64) -> f64 {
    let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
    let cross = u[0] * v[1] - u[1] * v[0];
    if lengths > 0.0 {
        2.0 * cross / lengths
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wdm_crust_testkit::Rng;

    fn estimates(points: &[[f64; 2]]) -> Vec<Estimate> {
        estimates_of(points, 0..points.len())
    }

    fn estimates_of(points: &[[f64; 2]], samples: Range<usize>) -> Vec<Estimate> {
        let mut all = Vec::new();
        let first = samples.start;
        loop_estimates(
            points.len(),
            |i| points[i],
            samples,
            |i, e| {
                assert_eq!(i, first + all.len());
                all.push(e);
            },
        );
        all
    }

    fn loop_noise(points: &[[f64; 2]]) -> Vec<f64> {
        let estimates = estimates(points);
        estimates.iter().map(|e| f64::from(e.amplitude)).collect()
    }

    fn loop_oscillation(points: &[[f64; 2]]) -> Vec<f64> {
        let estimates = estimates(points);
        estimates.iter().map(|e| f64::from(e.oscillation)).collect()
    }

    /// The estimates on the whole loop at once (the form before blocks): the reference.
    fn whole_loop_estimates(points: &[[f64; 2]]) -> Vec<Estimate> {
        let n = points.len();
        if n < 2 * HALF_WINDOW + 3 {
            return vec![Estimate::default(); n];
        }
        let at = |i: usize, k: isize| (i as isize + k).rem_euclid(n as isize) as usize;
        // `edge[i]` = |p_i p_i+1|, computed once for both samples it is an arm of (`hypot`, which
        // cannot overflow at any magnitude, is the costly part of this estimate).
        let edge: Vec<f64> = (0..n)
            .map(|i| distance(points[i], points[at(i, 1)]))
            .collect();
        let arms = |i: usize| edge[at(i, -1)] * edge[i];
        let mut curvature: Vec<f64> = (0..n)
            .map(|i| {
                let (a, b, c) = (points[at(i, -1)], points[i], points[at(i, 1)]);
                signed_curvature(a, b, c, arms(i) * distance(a, c))
            })
            .collect();
        let unexplained: Vec<f64> = (0..n)
            .map(|i| {
                let neighbours = (curvature[at(i, -1)] + curvature[at(i, 1)]) / 2.0;
                let arms = arms(i);
                let psi = (curvature[i] - neighbours).abs() * arms / 2.0;
                psi * psi
            })
            .collect();
        // The curvatures become, in place, the offsets `d_i = κ_i·a·c/2` from the neighbours'
        // chords (negated exactly when the loop is reversed), then `zig[i]`, of the pair
        // `i, i + 1` (the product of two offsets is not negated).
        let zig = &mut curvature;
        for (i, d) in zig.iter_mut().enumerate() {
            *d *= arms(i) / 2.0;
        }
        let first = zig[0];
        for i in 0..n {
            let next = if i + 1 < n { zig[i + 1] } else { first };
            zig[i] = (-zig[i] * next).max(0.0);
        }
        let pairs = (2 * HALF_WINDOW) as f64;
        (0..n)
            .map(|i| {
                let mut sum = 0.0;
                for k in 1..=HALF_WINDOW as isize {
                    // A pair at a time: the same sum whichever way the loop runs.
                    sum += unexplained[at(i, -k)] + unexplained[at(i, k)];
                }
                let amplitude = ((sum + unexplained[i]) / (2 * HALF_WINDOW + 1) as f64).sqrt();
                let (mut zigs, mut edges) = (0.0, 0.0);
                for k in 0..HALF_WINDOW as isize {
                    // The pairs and edges `i + k` and `i − 1 − k` swap when the loop runs the
                    // other way: summed two at a time, the same value either way.
                    zigs += zig[at(i, k)] + zig[at(i, -1 - k)];
                    edges += edge[at(i, k)] + edge[at(i, -1 - k)];
                }
                let oscillation = if edges > 0.0 {
                    (zigs / pairs).sqrt() / (edges / pairs)
                } else {
                    0.0
                };
                Estimate {
                    amplitude: amplitude as f32,
                    oscillation: oscillation as f32,
                }
            })
            .collect()
    }

    /// Blocks change no value: loops shorter than a block, of a block and a few samples,
    /// and of several blocks, whole and in two stretches, against the whole-loop
    /// reference.
    #[test]
    fn the_blocks_give_the_whole_loops_estimates() {
        let mut rng = Rng::new(6);
        for n in [
            9,
            10,
            11,
            300,
            BLOCK,
            BLOCK + 1,
            BLOCK + 2 * MARGIN,
            3 * BLOCK + 7,
        ] {
            let points = ellipse(n, 0.2 / n as f64, &mut rng);
            let whole = whole_loop_estimates(&points);
            assert_eq!(estimates(&points), whole, "{n} samples");
            // And in stretches, as the threads take them.
            let cut = rng.below(n + 1);
            let mut stretches = estimates_of(&points, 0..cut);
            stretches.extend(estimates_of(&points, cut..n));
            assert_eq!(stretches, whole, "{n} samples cut at {cut}");
        }
    }

    fn ellipse(n: usize, jitter: f64, rng: &mut Rng) -> Vec<[f64; 2]> {
        (0..n)
            .map(|i| {
                let t = i as f64 / n as f64 * std::f64::consts::TAU;
                [
                    2.0 * t.cos() + jitter * rng.normal(),
                    t.sin() + jitter * rng.normal(),
                ]
            })
            .collect()
    }

    /// Clean samples read as nearly noiseless; Gaussian noise reads as about twice its σ.
    #[test]
    fn the_amplitude_tells_noise_from_curvature() {
        let mut rng = Rng::new(3);
        let n = 300;
        let spacing = 9.69 / n as f64;
        let clean = loop_noise(&ellipse(n, 0.0, &mut rng));
        let clean_max = clean.iter().copied().fold(0.0, f64::max);
        assert!(clean_max < 0.01 * spacing, "{clean_max}");
        let sigma = 0.3 * spacing;
        let noisy = loop_noise(&ellipse(n, sigma, &mut rng));
        let mean = noisy.iter().sum::<f64>() / n as f64;
        assert!(
            (1.5 * sigma..3.0 * sigma).contains(&mean),
            "{mean} vs {sigma}"
        );
    }

    /// Clean samples of a convex curve, however sparse and irregular, do not zig-zag at
    /// all; Gaussian noise of σ reads as about `σ / spacing` (the pruning's threshold,
    /// 0.02, is that of σ ≈ 0.02 × the spacing).
    #[test]
    fn the_oscillation_tells_noise_from_sparse_curvature() {
        let mut rng = Rng::new(5);
        // A superellipse-like squarish loop, 24 irregular samples: its curvature changes
        // quickly from sample to sample, but keeps its sign.
        let square: Vec<[f64; 2]> = (0..24)
            .map(|i| {
                let t = (i as f64 + 0.4 * rng.f64()) / 24.0 * std::f64::consts::TAU;
                let (c, s) = (t.cos(), t.sin());
                [
                    c.signum() * c.abs().sqrt(),
                    0.6 * s.signum() * s.abs().sqrt(),
                ]
            })
            .collect();
        assert!(loop_oscillation(&square).iter().all(|&o| o == 0.0));
        let n = 300;
        let spacing = 9.69 / n as f64;
        for f in [0.1, 0.3] {
            let noisy = loop_oscillation(&ellipse(n, f * spacing, &mut rng));
            let mean = noisy.iter().sum::<f64>() / n as f64;
            assert!((0.7 * f..1.3 * f).contains(&mean), "{mean} at {f}");
        }
    }

    /// The same values whichever way the loop runs and wherever it starts.
    #[test]
    fn the_amplitude_does_not_depend_on_the_loop_order() {
        let mut rng = Rng::new(4);
        let points = ellipse(50, 0.01, &mut rng);
        let base = loop_noise(&points);
        let mut turned = points.clone();
        turned.rotate_left(17);
        turned.reverse();
        let mut again = loop_noise(&turned);
        again.reverse();
        again.rotate_right(17);
        assert_eq!(base, again);
        let base = loop_oscillation(&points);
        let mut again = loop_oscillation(&turned);
        again.reverse();
        again.rotate_right(17);
        assert_eq!(base, again);
    }
}
