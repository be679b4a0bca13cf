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
#![forbid(unsafe_code)]
#![warn(missing_docs)]
#![deny(rustdoc::broken_intra_doc_links)]

pub mod delaunay;
pub mod error;
pub mod interop;
#[cfg(feature = "cli")]
pub mod io;
mod kernel;
pub mod predicates;
pub mod reconstruct;
pub mod voronoi;

pub use delaunay::{triangulate, Triangulation};
pub use error::Error;
pub use reconstruct::{reconstruct, reconstruct_observed, reconstruct_with, Reconstruction};
pub use voronoi::Voronoi;
pub use voronoi::{BoundingBox, BoxError};
