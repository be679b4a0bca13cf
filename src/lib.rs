//! # wdm-crust
//!
//! A self-contained, exact 2D geometry engine that turns an unordered set of planar points
//! into the closed curves they were sampled from (WDM_CRUST) and into the medial axis of
//! those curves (WDM_MAT).
//!
//! ```
//! let points = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]];
//! let tri = wdm_crust::triangulate(&points).unwrap();
//! assert_eq!(tri.triangles().len(), 2);
//! ```
//!
//! # Exactness
//!
//! Every combinatorial decision (orientation, in-circle, and the predicates on
//! circumcenters) is the one exact arithmetic on the caller's `f64` values makes, for every
//! finite input: subnormals, values near `f64::MAX` whose differences overflow, and
//! magnitudes far apart (`1e-300` beside `1e300`) included. Only NaN and infinities are
//! refused ([`Error::NotFinite`], naming the point). Input whose magnitudes fit the adaptive
//! predicates' range after one power-of-two scaling is triangulated on such an exactly
//! scaled copy, at full speed; other input takes wide-exponent integer arithmetic where the
//! floating-point filters cannot decide. A reconstruction runs every stage on such a copy,
//! centred in that range whether or not the input lies in it, so that its rounded rules
//! (the pruned medial axis's) take the same decisions on an input and on any exact
//! power-of-two scaling of it. Results are always in the caller's coordinates.
//!
//! Constructed coordinates (Voronoi vertex positions, [`predicates::circumcenter`]) are
//! computed from the exact circumcenter once: within 256 units in the last place of the
//! larger coordinate, correctly rounded where that is subnormal, and infinite only where the
//! exact value lies beyond the `f64` range.
//!
//! ```
//! let points = [[1e-300, 0.0], [0.0, 1e-300], [1e300, 1e300], [-1e300, 5e-324]];
//! let tri = wdm_crust::triangulate(&points).unwrap();
//! tri.validate().unwrap();
//! // (0, 1e-300) lies inside the triangle of the other three.
//! assert_eq!(tri.triangles().len(), 3);
//! assert_eq!(tri.point(2), [1e300, 1e300]);
//! ```
// `deny`, not `forbid`: the prefetch hint alone is allowed it (see `prefetch`).
#![deny(unsafe_code)]
#![warn(missing_docs)]
#![deny(rustdoc::broken_intra_doc_links)]

pub mod delaunay;
pub mod error;
mod ids;
pub mod interop;
#[cfg(feature = "io")]
pub mod io;
mod kernel;
mod parallel;
pub mod predicates;
mod prefetch;
pub mod reconstruct;
pub mod voronoi;

pub use delaunay::{triangulate, Triangulation};
pub use error::Error;
pub use ids::{HalfEdge, TriangleId, VertexId};
pub use reconstruct::{
    reconstruct, reconstruct_observed, reconstruct_with, Reconstruction, Warning, WarningCode,
};
pub use voronoi::Voronoi;
pub use voronoi::{BoundingBox, BoxError};

// The README's Rust example runs with the doc tests (`cargo test --doc`).
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
