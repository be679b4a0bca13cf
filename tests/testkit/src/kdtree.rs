//! A static 2D k-d tree for nearest-neighbour queries, private to the sampling module.
//!
//! Nodes are implicit: a node is an index range of `order`, split at its middle position,
//! and its bounding box is stored at that middle position (unique per non-empty range).
//! Pruning by bounding box, not just by the splitting line, keeps queries from far away
//! (tangent-ball centres of nearly flat parts) cheap.

use super::vec2::{dist2, P2};

/// Ranges at most this long are scanned linearly.
const LEAF: usize = 8;

pub(crate) struct KdTree {
    points: Vec<P2>,
    order: Vec<usize>,
    axis: Vec<u8>,
    boxes: Vec<[f64; 4]>,
}

impl KdTree {
    /// Builds the tree over a copy of `points` (O(n log n)).
    pub(crate) fn new(points: &[P2]) -> Self {
        let n = points.len();
        let mut tree = KdTree {
            points: points.to_vec(),
            order: (0..n).collect(),
            axis: vec![0; n],
            boxes: vec![[0.0; 4]; n],
        };
        tree.build(0, n);
        tree
    }

    fn build(&mut self, lo: usize, hi: usize) {
        if lo >= hi {
            return;
        }
        let mut b = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        for &i in &self.order[lo..hi] {
            let p = self.points[i];
            b = [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ];
        }
        let mid = (lo + hi) / 2;
        self.boxes[mid] = b;
        if hi - lo <= LEAF {
            return;
        }
        let axis = usize::from(b[3] - b[1] > b[2] - b[0]);
        self.axis[mid] = axis as u8;
        let points = &self.points;
        self.order[lo..hi].select_nth_unstable_by(mid - lo, |&i, &j| {
            points[i][axis].total_cmp(&points[j][axis])
        });
        self.build(lo, mid);
        self.build(mid + 1, hi);
    }

    /// Index (into the slice given to [`KdTree::new`]) and squared distance of the point
    /// nearest to `q`; `None` when the tree is empty.
    pub(crate) fn nearest(&self, q: P2) -> Option<(usize, f64)> {
        self.nearest_within(q, 0.0)
    }

    /// Like [`KdTree::nearest`], but the distance found may exceed the true nearest distance
    /// by a relative `tol`: boxes that cannot beat the best by that factor are pruned. This
    /// keeps tight clusters (e.g. thousands of nearly coincident medial centres of a circle)
    /// from being scanned point by point.
    pub(crate) fn nearest_within(&self, q: P2, tol: f64) -> Option<(usize, f64)> {
        let mut best = (usize::MAX, f64::INFINITY);
        let shrink = (1.0 - tol) * (1.0 - tol);
        self.search(0, self.order.len(), q, shrink, &mut best);
        (best.0 != usize::MAX).then_some(best)
    }

    fn search(&self, lo: usize, hi: usize, q: P2, shrink: f64, best: &mut (usize, f64)) {
        if lo >= hi {
            return;
        }
        let mid = (lo + hi) / 2;
        if box_dist2(&self.boxes[mid], q) >= best.1 * shrink {
            return;
        }
        if hi - lo <= LEAF {
            for &i in &self.order[lo..hi] {
                self.consider(i, q, best);
            }
            return;
        }
        let pivot = self.order[mid];
        self.consider(pivot, q, best);
        let axis = usize::from(self.axis[mid]);
        if q[axis] < self.points[pivot][axis] {
            self.search(lo, mid, q, shrink, best);
            self.search(mid + 1, hi, q, shrink, best);
        } else {
            self.search(mid + 1, hi, q, shrink, best);
            self.search(lo, mid, q, shrink, best);
        }
    }

    fn consider(&self, i: usize, q: P2, best: &mut (usize, f64)) {
        let d = dist2(self.points[i], q);
        if d < best.1 {
            *best = (i, d);
        }
    }
}

/// Squared distance from `q` to the box `[xmin, ymin, xmax, ymax]` (0 inside).
fn box_dist2(b: &[f64; 4], q: P2) -> f64 {
    let dx = (b[0] - q[0]).max(q[0] - b[2]).max(0.0);
    let dy = (b[1] - q[1]).max(q[1] - b[3]).max(0.0);
    dx * dx + dy * dy
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rng;

    #[test]
    fn nearest_matches_brute_force() {
        let mut rng = Rng::new(1);
        // Clustered and duplicated points exercise degenerate splits.
        let mut pts: Vec<P2> = (0..500).map(|_| [rng.f64(), rng.f64() * 1e-3]).collect();
        pts.extend_from_slice(&[[0.5, 0.5]; 20]);
        let tree = KdTree::new(&pts);
        for _ in 0..300 {
            let q = [rng.range(-1.0, 2.0), rng.range(-1.0, 2.0)];
            let brute = pts
                .iter()
                .map(|&p| dist2(p, q))
                .fold(f64::INFINITY, f64::min);
            let (i, d2) = tree.nearest(q).unwrap();
            assert_eq!(d2, brute);
            assert_eq!(dist2(pts[i], q), d2);
            let (_, approx) = tree.nearest_within(q, 0.01).unwrap();
            assert!(approx >= brute && approx.sqrt() <= brute.sqrt() / 0.99);
        }
        assert!(KdTree::new(&[]).nearest([0.0, 0.0]).is_none());
    }
}
