//! A bounding-volume hierarchy over dense curve points in curve order, for the tangent-disc
//! query of the lfs computation; private to the sampling module.
//!
//! A node is a contiguous index range, i.e. a piece of curve, bounded by a box aligned with
//! the chord of that piece. Such boxes are as thin as the piece's sagitta, whereas axis-aligned
//! boxes of a diagonal piece are as fat as the piece is long. The difference decides the cost
//! on near-circular arcs, where the empty tangent disc hugs the curve over long stretches and
//! every fat box would intersect it.
//!
//! Range `[lo, hi)` splits at `mid = (lo + hi) / 2` into `[lo, mid)` and `[mid, hi)`.

use super::vec2::{add, dot, left, mul, sub, unit, P2};

/// Ranges at most this long are leaves, scanned linearly.
const LEAF: usize = 8;

/// A box in the frame of a chord: origin, unit direction, and extents along and across.
#[derive(Clone, Copy)]
struct ChordBox {
    origin: P2,
    dir: P2,
    along: [f64; 2],
    across: [f64; 2],
}

impl ChordBox {
    fn dist2(&self, q: P2) -> f64 {
        let v = sub(q, self.origin);
        let (s, t) = (dot(v, self.dir), dot(v, left(self.dir)));
        let ds = (self.along[0] - s).max(s - self.along[1]).max(0.0);
        let dt = (self.across[0] - t).max(t - self.across[1]).max(0.0);
        ds * ds + dt * dt
    }
}

/// A node: its index range, its box, and its children (none for a leaf).
struct Node {
    lo: usize,
    hi: usize,
    bounds: ChordBox,
    children: Option<[usize; 2]>,
}

pub(crate) struct ArcTree {
    points: Vec<P2>,
    /// Node 0 is the root (absent when there are no points).
    nodes: Vec<Node>,
}

impl ArcTree {
    /// Builds the hierarchy over `points` taken in the given order (O(n log n)).
    pub(crate) fn new(points: &[P2]) -> Self {
        let mut tree = ArcTree {
            points: points.to_vec(),
            nodes: Vec::new(),
        };
        if !points.is_empty() {
            tree.build(0, points.len());
        }
        tree
    }

    /// Adds the node of the non-empty range `[lo, hi)` and its subtree; returns its index.
    fn build(&mut self, lo: usize, hi: usize) -> usize {
        let index = self.nodes.len();
        let bounds = self.chord_box(lo, hi);
        self.nodes.push(Node {
            lo,
            hi,
            bounds,
            children: None,
        });
        if hi - lo > LEAF {
            let mid = (lo + hi) / 2;
            let left = self.build(lo, mid);
            let right = self.build(mid, hi);
            self.nodes[index].children = Some([left, right]);
        }
        index
    }

    fn chord_box(&self, lo: usize, hi: usize) -> ChordBox {
        let origin = self.points[lo];
        let chord = sub(self.points[hi - 1], origin);
        let dir = if chord == [0.0, 0.0] {
            [1.0, 0.0]
        } else {
            unit(chord)
        };
        let mut b = ChordBox {
            origin,
            dir,
            along: [f64::INFINITY, f64::NEG_INFINITY],
            across: [f64::INFINITY, f64::NEG_INFINITY],
        };
        for &p in &self.points[lo..hi] {
            let v = sub(p, origin);
            let (s, t) = (dot(v, dir), dot(v, left(dir)));
            b.along = [b.along[0].min(s), b.along[1].max(s)];
            b.across = [b.across[0].min(t), b.across[1].max(t)];
        }
        b
    }

    /// Branch and bound for the smallest `|y−x|² / (2 (y−x)·n)` over the points `y` with
    /// `(y−x)·n > 0`, assuming it is below `r`, up to a relative tolerance `tol`: returns the
    /// smallest value found below `r·(1−tol)`, or `r` if there is none.
    ///
    /// A point's value is below `ρ` exactly when it lies inside the disc of radius `ρ`
    /// tangent at `x` on the side of `n`. These discs shrink monotonically (they are nested),
    /// so a node whose box misses the current disc can be pruned for good.
    pub(crate) fn min_tangent_radius(&self, x: P2, n: P2, r: f64, tol: f64) -> f64 {
        let mut best = r;
        if let Some(root) = self.nodes.first() {
            let rho = r * (1.0 - tol);
            let d2 = root.bounds.dist2(add(x, mul(n, rho)));
            if d2 < rho * rho {
                self.search(0, x, n, tol, &mut best);
            }
        }
        best
    }

    /// Visits a node whose box meets the current disc.
    fn search(&self, node: usize, x: P2, n: P2, tol: f64, best: &mut f64) {
        let node = &self.nodes[node];
        let Some([a, b]) = node.children else {
            for &p in &self.points[node.lo..node.hi] {
                let v = sub(p, x);
                let along = dot(v, n);
                if along > 0.0 {
                    let f = dot(v, v) / (2.0 * along);
                    if f < *best * (1.0 - tol) {
                        *best = f;
                    }
                }
            }
            return;
        };
        let rho = *best * (1.0 - tol);
        let centre = add(x, mul(n, rho));
        let (da, db) = (
            self.nodes[a].bounds.dist2(centre),
            self.nodes[b].bounds.dist2(centre),
        );
        // Descend first into the child whose box is nearer the disc centre: it is the more
        // likely to shrink the disc and so prune the other.
        let ((first, d_first), (second, d_second)) = if da <= db {
            ((a, da), (b, db))
        } else {
            ((b, db), (a, da))
        };
        if d_first < rho * rho {
            self.search(first, x, n, tol, best);
        }
        // A box that missed the disc misses every smaller one (they are nested); a box that
        // met it is tested again only if the disc shrank meanwhile.
        if d_second < rho * rho {
            let now = *best * (1.0 - tol);
            if now == rho || self.nodes[second].bounds.dist2(add(x, mul(n, now))) < now * now {
                self.search(second, x, n, tol, best);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Rng;

    #[test]
    fn min_tangent_radius_matches_brute_force() {
        let mut rng = Rng::new(2);
        // A wiggly closed curve, so the tangent discs are limited by near and far points.
        let pts: Vec<P2> = (0..2000)
            .map(|i| {
                let t = i as f64 / 2000.0 * std::f64::consts::TAU;
                let r = 1.0 + 0.3 * (5.0 * t).cos();
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let tree = ArcTree::new(&pts);
        for _ in 0..200 {
            let i = rng.below(pts.len());
            let x = pts[i];
            let n = unit(left(sub(pts[(i + 1) % 2000], pts[(i + 1999) % 2000])));
            for n in [n, [-n[0], -n[1]]] {
                let brute = pts
                    .iter()
                    .map(|&y| {
                        let v = sub(y, x);
                        let along = dot(v, n);
                        if along > 0.0 {
                            dot(v, v) / (2.0 * along)
                        } else {
                            f64::INFINITY
                        }
                    })
                    .fold(100.0, f64::min);
                let fast = tree.min_tangent_radius(x, n, 100.0, 1e-9);
                assert!(
                    fast >= brute && fast <= brute * (1.0 + 1e-8),
                    "{fast} vs {brute}"
                );
            }
        }
    }
}
