//! Ground-truth inputs for reconstruction tests and quality benchmarks.
//!
//! **Dev-only; not part of the published `wdm-crust` library.** This small path crate
//! (`publish = false`, no dependencies, not even on `wdm-crust`) is shared by the
//! integration tests, examples and benches (as a dev-dependency), by the library's own
//! `#[cfg(test)]` unit tests, and by the fuzz crate. It lives in `tests/testkit/` and is left
//! out of the published package.
//!
//! * [`Rng`]: a small deterministic PRNG (xoshiro256**), so every input is reproducible
//!   from a `u64` seed.
//! * Curves: smooth closed curves ([`Ellipse`], [`Star`], [`Peanut`], [`Superellipse`], or
//!   any [`ClosedCurve`]), polygons and polylines with sharp corners, and SVG paths
//!   ([`parse_svg`]), all turned into [`DenseCurve`]s: dense polylines with normals.
//! * [`local_feature_size`]: the lfs of a set of dense curves, computed from tangent medial
//!   balls with a k-d tree, independently of the crate's Delaunay/Voronoi code.
//! * [`CurveSet::eps_sample`]: random, irregular ε-samples with known adjacency
//!   ([`Sample`]), which can be merged (several or nested curves), moved by a random
//!   [`Similarity`], shuffled, and spoiled with noise or outliers.
//!
//! ```
//! use wdm_crust_testkit::{ClosedCurve, CurveSet, Ellipse, Rng, Star};
//!
//! let mut rng = Rng::new(42);
//! // Two disjoint curves: an ellipse and a star moved beside it.
//! let star = Star { a: 0.2, k: 5 }.dense(4000);
//! let star = star.transformed(&wdm_crust_testkit::Similarity::translation([4.0, 0.0]));
//! let set = CurveSet::new(vec![Ellipse { a: 2.0, b: 1.0 }.dense(4000), star]);
//!
//! let sample = set.eps_sample(0.3, &mut rng);
//! assert!(set.coverage(&sample.points, 0.0) <= 0.3);
//! assert_eq!(sample.curves.len(), 2);
//! assert_eq!(sample.edges().len(), sample.len()); // two closed curves: one edge per point
//!
//! // Random rotation, scale, translation and order; the adjacency follows the points.
//! let scrambled = sample.randomized(&mut rng);
//! assert_eq!(scrambled.edge_set().len(), sample.edge_set().len());
//! ```

#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod arctree;
mod curve;
mod eps;
mod kdtree;
mod lfs;
mod noise;
mod rng;
mod shapes;
mod svg;
mod vec2;

pub use curve::{ClosedCurve, DenseCurve, Similarity};
pub use eps::{CurveSet, Sample, SampleConfig, SampledCurve};
pub use lfs::{local_feature_size, medial_balls, MedialBall};
pub use noise::{add_gaussian_noise, noisy_curve_sample, uniform_outliers};
pub use rng::Rng;
pub use shapes::{Ellipse, FourierBlob, Peanut, Star, Superellipse};
pub use svg::{parse_path_data, parse_svg, svg_dense_curves, Segment, SvgError, SvgSubpath};
pub use vec2::{bbox, segment_distance};
