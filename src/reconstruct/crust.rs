//! The crust of Amenta, Bern and Eppstein (1998). Being written: returns no edges yet.

use crate::delaunay::Triangulation;

/// Crust edges of the distinct points of `tri`, `[i, j]` with `i < j`.
pub fn crust_edges(_tri: &Triangulation) -> Vec<[u32; 2]> {
    Vec::new()
}
