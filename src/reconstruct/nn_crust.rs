//! The nearest-neighbour crust of Dey and Kumar (1999). Being written: returns no edges yet.

use crate::delaunay::Triangulation;

/// NN-crust edges of the distinct points of `tri`, `[i, j]` with `i < j`.
pub fn nn_crust_edges(_tri: &Triangulation) -> Vec<[u32; 2]> {
    Vec::new()
}
