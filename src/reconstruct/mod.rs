//! Curve reconstruction and medial axis from unordered points.
//!
//! [`reconstruct`] runs WDM_CRUST with the default [`Options`]: triangulate, build the merged
//! Voronoi dual, label its vertices by the water flow ([`wdm`]), keep the Delaunay edges whose
//! dual Voronoi edge joins an inner and an outer vertex (the crust) and the finite Voronoi
//! edges joining two inner vertices (the medial axis), assemble the crust into curves
//! ([`Curve`]). Shapes with holes are handled by peeling (see [`Options::with_peeling`]).
//!
//! One module per job, in wings that follow the pipeline (ARCHITECTURE.md has the map):
//! [`options`](Options) (what is asked), `pipeline` (the orchestration, top to bottom),
//! `frame` (the exactly rescaled coordinates it runs in), `thinning` (dense noisy bands to
//! representatives, before everything else); the paper's algorithm, [`wdm`] (the water flow)
//! and `extract` (crust and medial axis off the labels); `repairs` (`corridors`: water that
//! leaked through a gap of a noisy curve; `ears`: small loops hanging off a curve at one
//! point; `peel`: holes; `detours`: outliers the crust ran through; `spikes`: outliers woven
//! into a curve; `shared`: what more than one of them reads); `curves` (assembly), `smooth`
//! (on demand: the curve vertices fitted to the samples around them), the medial axis,
//! `delaunay_graph` (adjacency lists for the walks of both), `result` (what is returned),
//! `diagnose` (the warnings on a result), `thresholds` (every tuned constant with the
//! measurement that chose it); `baselines`: [`crust`] and [`nn_crust`], the classical
//! baselines on the same exact engine.

mod baselines;
mod bits;
mod curves;
mod delaunay_graph;
mod diagnose;
mod extract;
mod frame;
mod lengths;
mod medial_axis;
pub(crate) mod open_curves;
mod options;
mod parity;
mod pipeline;
pub mod polygons;
mod proximity;
mod repairs;
mod result;
mod scatter;
mod segment_walk;
mod smooth;
mod thinning;
mod thresholds;
pub mod wdm;

pub use baselines::{crust, nn_crust};
pub use curves::Curve;
pub use extract::EdgeClass;
pub use options::{Algorithm, MedialAxisMode, Options, OptionsConflict, WdmSetting};
pub use pipeline::{reconstruct, reconstruct_observed, reconstruct_with, Phase};
pub use polygons::Polygon;
pub use result::{MedialAxis, Reconstruction, Warning, WarningCode};
pub use wdm::{Label, LabelRule, WaterFlow};
