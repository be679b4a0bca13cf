//! Guibas–Stolfi divide-and-conquer Delaunay construction.
//!
//! Points are sorted lexicographically (x, then y), exact duplicates are merged into their
//! first occurrence, and the sorted run is split in halves recursively (depth log n). Each
//! half returns its two extreme convex-hull edges; the merge walks the lower common tangent
//! upwards, deleting left and right edges that fail the exact incircle test.

use std::cmp::Ordering;

use super::quadedge::{sym, EdgeId, QuadEdgeStore};
use super::triangulation::{Triangulation, NO_TWIN};
use crate::predicates::{incircle, orient2d, CirclePosition, Orientation};

/// Triangulates validated points (finite, inside the exact envelope).
pub(super) fn build(points: &[[f64; 2]]) -> Triangulation {
    let (sorted, duplicates) = sort_and_merge_duplicates(points);
    let mut dc = DivideConquer {
        points,
        sorted: &sorted,
        store: QuadEdgeStore::with_capacity(3 * sorted.len()),
    };
    let hull_edge = if sorted.len() >= 2 {
        Some(dc.triangulate(0, sorted.len()).0)
    } else {
        None
    };
    let store = dc.store;
    let (triangles, halfedges, hull) = match hull_edge {
        Some(e) => compact(&store, e, &sorted),
        None => (Vec::new(), Vec::new(), sorted.clone()),
    };
    Triangulation {
        points: points.to_vec(),
        triangles,
        halfedges,
        hull,
        duplicates,
    }
}

/// Lexicographic order of coordinates; `-0.0 == 0.0`, inputs are finite.
#[inline]
fn lexicographic(a: [f64; 2], b: [f64; 2]) -> Ordering {
    a[0].partial_cmp(&b[0])
        .unwrap_or(Ordering::Equal)
        .then(a[1].partial_cmp(&b[1]).unwrap_or(Ordering::Equal))
}

/// Sorted indices of the distinct points, and `[duplicate, kept]` pairs sorted by duplicate.
fn sort_and_merge_duplicates(points: &[[f64; 2]]) -> (Vec<u32>, Vec<[u32; 2]>) {
    let mut order: Vec<u32> = (0..points.len() as u32).collect();
    // Ties broken by index, so the first occurrence of a coordinate pair comes first.
    order.sort_unstable_by(|&i, &j| {
        lexicographic(points[i as usize], points[j as usize]).then(i.cmp(&j))
    });
    let mut duplicates = Vec::new();
    let mut distinct = Vec::with_capacity(order.len());
    for &i in &order {
        match distinct.last() {
            Some(&kept) if lexicographic(points[kept as usize], points[i as usize]).is_eq() => {
                duplicates.push([i, kept]);
            }
            _ => distinct.push(i),
        }
    }
    duplicates.sort_unstable();
    (distinct, duplicates)
}

struct DivideConquer<'a> {
    points: &'a [[f64; 2]],
    /// Distinct point indices in lexicographic order.
    sorted: &'a [u32],
    store: QuadEdgeStore,
}

impl DivideConquer<'_> {
    #[inline]
    fn point(&self, v: u32) -> [f64; 2] {
        self.points[v as usize]
    }

    /// Is point `v` strictly right of the directed edge `e`?
    #[inline]
    fn right_of(&self, v: u32, e: EdgeId) -> bool {
        orient2d(
            self.point(v),
            self.point(self.store.dest(e)),
            self.point(self.store.org(e)),
        ) == Orientation::CounterClockwise
    }

    /// Is point `v` strictly left of the directed edge `e`?
    #[inline]
    fn left_of(&self, v: u32, e: EdgeId) -> bool {
        orient2d(
            self.point(v),
            self.point(self.store.org(e)),
            self.point(self.store.dest(e)),
        ) == Orientation::CounterClockwise
    }

    /// Is `d` strictly inside the circle through `a, b, c` (given counterclockwise)?
    #[inline]
    fn in_circle(&self, a: u32, b: u32, c: u32, d: u32) -> bool {
        incircle(self.point(a), self.point(b), self.point(c), self.point(d))
            == CirclePosition::Inside
    }

    /// Triangulates `sorted[lo..hi]` (at least two points). Returns the counterclockwise
    /// hull edge out of the leftmost point and the clockwise hull edge out of the rightmost.
    fn triangulate(&mut self, lo: usize, hi: usize) -> (EdgeId, EdgeId) {
        let n = hi - lo;
        let s = &self.sorted[lo..hi];
        if n == 2 {
            let a = self.store.make_edge(s[0], s[1]);
            return (a, sym(a));
        }
        if n == 3 {
            let (p0, p1, p2) = (s[0], s[1], s[2]);
            let a = self.store.make_edge(p0, p1);
            let b = self.store.make_edge(p1, p2);
            self.store.splice(sym(a), b);
            return match orient2d(self.point(p0), self.point(p1), self.point(p2)) {
                Orientation::CounterClockwise => {
                    self.store.connect(b, a);
                    (a, sym(b))
                }
                Orientation::Clockwise => {
                    let c = self.store.connect(b, a);
                    (sym(c), c)
                }
                Orientation::Collinear => (a, sym(b)),
            };
        }
        let mid = lo + n / 2;
        let (mut ldo, mut ldi) = self.triangulate(lo, mid);
        let (mut rdi, mut rdo) = self.triangulate(mid, hi);
        self.merge(&mut ldo, &mut ldi, &mut rdi, &mut rdo);
        (ldo, rdo)
    }

    /// Merges two adjacent triangulations, updating the outer hull edges.
    fn merge(&mut self, ldo: &mut EdgeId, ldi: &mut EdgeId, rdi: &mut EdgeId, rdo: &mut EdgeId) {
        // Lower common tangent of the two hulls.
        loop {
            if self.left_of(self.store.org(*rdi), *ldi) {
                *ldi = self.store.lnext(*ldi);
            } else if self.right_of(self.store.org(*ldi), *rdi) {
                *rdi = self.store.rprev(*rdi);
            } else {
                break;
            }
        }
        let mut basel = self.store.connect(sym(*rdi), *ldi);
        if self.store.org(*ldi) == self.store.org(*ldo) {
            *ldo = sym(basel);
        }
        if self.store.org(*rdi) == self.store.org(*rdo) {
            *rdo = basel;
        }
        // Zip the halves together from the tangent upwards.
        loop {
            let lcand = self.left_candidate(basel);
            let rcand = self.right_candidate(basel);
            let l_valid = self.valid(lcand, basel);
            let r_valid = self.valid(rcand, basel);
            if !l_valid && !r_valid {
                break;
            }
            let take_right = !l_valid
                || (r_valid
                    && self.in_circle(
                        self.store.dest(lcand),
                        self.store.org(lcand),
                        self.store.org(rcand),
                        self.store.dest(rcand),
                    ));
            basel = if take_right {
                self.store.connect(rcand, sym(basel))
            } else {
                self.store.connect(sym(basel), sym(lcand))
            };
        }
    }

    /// A candidate edge is valid when its far end lies strictly above the base edge.
    #[inline]
    fn valid(&self, e: EdgeId, basel: EdgeId) -> bool {
        self.right_of(self.store.dest(e), basel)
    }

    /// First edge out of the left end of `basel` whose far end may join the merge, deleting
    /// left edges that the new triangle's circle would contain.
    fn left_candidate(&mut self, basel: EdgeId) -> EdgeId {
        let mut lcand = self.store.onext(sym(basel));
        if self.valid(lcand, basel) {
            while self.in_circle(
                self.store.dest(basel),
                self.store.org(basel),
                self.store.dest(lcand),
                self.store.dest(self.store.onext(lcand)),
            ) {
                let t = self.store.onext(lcand);
                self.store.delete_edge(lcand);
                lcand = t;
            }
        }
        lcand
    }

    /// Mirror of [`Self::left_candidate`] on the right half.
    fn right_candidate(&mut self, basel: EdgeId) -> EdgeId {
        let mut rcand = self.store.oprev(basel);
        if self.valid(rcand, basel) {
            while self.in_circle(
                self.store.dest(basel),
                self.store.org(basel),
                self.store.dest(rcand),
                self.store.dest(self.store.oprev(rcand)),
            ) {
                let t = self.store.oprev(rcand);
                self.store.delete_edge(rcand);
                rcand = t;
            }
        }
        rcand
    }
}

/// Converts the quad-edge subdivision into flat triangle and half-edge arrays plus the
/// counterclockwise hull. `hull_edge` is a hull edge with the interior on its left.
fn compact(
    store: &QuadEdgeStore,
    hull_edge: EdgeId,
    sorted: &[u32],
) -> (Vec<[u32; 3]>, Vec<u32>, Vec<u32>) {
    // Walking the outer face (left face of the reversed hull edge) visits the hull clockwise.
    let outer_start = sym(hull_edge);
    let mut outer_face_edges = Vec::new();
    let mut e = outer_start;
    loop {
        outer_face_edges.push(e);
        e = store.lnext(e);
        if e == outer_start {
            break;
        }
    }
    // With at least one triangle the hull has at most n < 2(n - 1) edges; only a chain of
    // n collinear points has an outer face of 2(n - 1) records (both sides of n - 1 edges).
    let collinear = outer_face_edges.len() == 2 * (sorted.len() - 1);
    if collinear {
        return (Vec::new(), Vec::new(), sorted.to_vec());
    }
    let mut hull: Vec<u32> = outer_face_edges.iter().map(|&e| store.org(e)).collect();
    hull.reverse();

    // Half-edge id of every primal directed record (two per quad), NO_TWIN if none yet.
    let quads = store.quad_capacity();
    let mut halfedge_of = vec![NO_TWIN; 2 * quads];
    for &e in &outer_face_edges {
        halfedge_of[(e >> 1) as usize] = NO_TWIN - 1; // marks the outer face
    }
    let mut triangles: Vec<[u32; 3]> = Vec::with_capacity(2 * sorted.len());
    let mut records: Vec<EdgeId> = Vec::with_capacity(6 * sorted.len());
    for q in 0..quads as u32 {
        let first = q << 2;
        if store.is_deleted(first) {
            continue;
        }
        for e in [first, sym(first)] {
            if halfedge_of[(e >> 1) as usize] != NO_TWIN {
                continue;
            }
            let e1 = store.lnext(e);
            let e2 = store.lnext(e1);
            let t = triangles.len() as u32;
            for (k, &r) in [e, e1, e2].iter().enumerate() {
                halfedge_of[(r >> 1) as usize] = 3 * t + k as u32;
                records.push(r);
            }
            triangles.push([store.org(e), store.org(e1), store.org(e2)]);
        }
    }
    let halfedges = records
        .iter()
        .map(|&r| {
            let twin = halfedge_of[(sym(r) >> 1) as usize];
            if twin == NO_TWIN - 1 {
                NO_TWIN
            } else {
                twin
            }
        })
        .collect();
    (triangles, halfedges, hull)
}
