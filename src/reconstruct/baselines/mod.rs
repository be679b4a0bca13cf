//! The baselines WDM_CRUST is compared with, on the same triangulation and the same exact
//! predicates: the crust of Amenta, Bern and Eppstein and the nearest-neighbour crust of Dey
//! and Kumar.

pub mod crust;
pub mod nn_crust;
