//! Merging vertices of the clipped cells that rounding put within a few ulps of each other.
//!
//! Exactly, every clipped cell is convex. Nearly cocircular sites (decimal grids) have Voronoi
//! vertices a few `1e-15` apart; rounded to `f64` independently, three such vertices `A, B, C`
//! of one cell can come out as `A', B', A'`: a spike, which GIS tools reject as a ring
//! self-intersection. So every edge of the subdivision whose rounded ends lie within
//! [`CLOSE_ULPS`] units in the last place of each other is contracted, in all cells at once
//! (union–find over the rounded coordinates), to one representative: a box corner if the
//! group holds one, else a point on a box side, else the lexicographically smallest. Shared
//! vertices stay shared, so the cells still tile the box and their signed areas still add up
//! to the box's exactly; a vertex moves by at most the length of the chain of short edges
//! it was merged along.

use std::collections::HashMap;

use super::BoundingBox;

/// Edges whose ends differ by at most this many ulps of their larger coordinate magnitude,
/// in both coordinates, are contracted.
pub(crate) const CLOSE_ULPS: f64 = 16.0;

/// Union–find with path halving over vertex ids.
fn find(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// Whether the rounded points `a` and `b` are within [`CLOSE_ULPS`] of each other.
fn close(a: [f64; 2], b: [f64; 2]) -> bool {
    let m = a[0].abs().max(a[1].abs()).max(b[0].abs()).max(b[1].abs());
    let ulp = f64::from_bits(m.to_bits() + 1) - m;
    let tolerance = CLOSE_ULPS * ulp;
    (a[0] - b[0]).abs() <= tolerance && (a[1] - b[1]).abs() <= tolerance
}

/// How many box sides `p` lies on (2 for a corner).
fn box_sides(p: [f64; 2], bbox: &BoundingBox) -> usize {
    let (lo, hi) = (bbox.min(), bbox.max());
    (0..2)
        .map(|a| usize::from(p[a] == lo[a] || p[a] == hi[a]))
        .sum()
}

/// Contracts the short edges of `rings` (see the module docs), drops the repetitions this
/// creates, and empties a ring left with fewer than three vertices.
pub(crate) fn merge_close_vertices(rings: &mut [Vec<[f64; 2]>], bbox: &BoundingBox) {
    let key = |p: [f64; 2]| (p[0].to_bits(), p[1].to_bits());
    let mut id: HashMap<(u64, u64), usize> = HashMap::new();
    let mut coords: Vec<[f64; 2]> = Vec::new();
    let mut parent: Vec<usize> = Vec::new();
    let mut any = false;
    for ring in rings.iter() {
        for (k, &a) in ring.iter().enumerate() {
            let b = ring[(k + 1) % ring.len()];
            if a != b && close(a, b) {
                let mut node = |p: [f64; 2]| {
                    *id.entry(key(p)).or_insert_with(|| {
                        coords.push(p);
                        parent.push(parent.len());
                        parent.len() - 1
                    })
                };
                let (i, j) = (node(a), node(b));
                let (ri, rj) = (find(&mut parent, i), find(&mut parent, j));
                if ri != rj {
                    parent[ri.max(rj)] = ri.min(rj);
                }
                any = true;
            }
        }
    }
    if !any {
        return;
    }
    // The representative of every group: most box sides, then lexicographically smallest.
    let rank = |p: [f64; 2]| (std::cmp::Reverse(box_sides(p, bbox)), p[0], p[1]);
    let mut best: HashMap<usize, [f64; 2]> = HashMap::new();
    for (i, &p) in coords.iter().enumerate() {
        let root = find(&mut parent, i);
        best.entry(root)
            .and_modify(|q| {
                if rank(p).partial_cmp(&rank(*q)) == Some(std::cmp::Ordering::Less) {
                    *q = p;
                }
            })
            .or_insert(p);
    }
    for ring in rings.iter_mut() {
        for p in ring.iter_mut() {
            if let Some(&i) = id.get(&key(*p)) {
                let root = find(&mut parent, i);
                *p = best[&root];
            }
        }
        ring.dedup();
        while ring.len() > 1 && ring.first() == ring.last() {
            ring.pop();
        }
        if ring.len() < 3 {
            ring.clear();
        }
    }
}
