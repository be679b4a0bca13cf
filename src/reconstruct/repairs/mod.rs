//! The repairs of WDM_CRUST's first pass where noise, outliers and nested curves defeat it:
//! corridors and ears (the labels), detours and spikes (curves routed through outliers),
//! peeling (the later passes that find holes), the loops beside curves (clean closed
//! curves that peeling took for another curve's noise) and facing corners (two loops the
//! flow joined across a gap). Each runs only where the crust shows the
//! failure it repairs; each rule's argument is a note in `docs/design/`.

pub(crate) mod beside;
pub(crate) mod corridors;
pub(crate) mod detours;
pub(crate) mod ears;
pub(crate) mod facing;
pub(crate) mod peel;
pub(crate) mod shared;
mod spikes;
