//! Guibas–Stolfi quad-edge store: pure topology, no geometry.
//!
//! An undirected edge is a quad of four directed records with consecutive ids `4q..4q+3`:
//! `4q` and `4q+2` are the primal edge in its two directions, `4q+1` and `4q+3` the dual
//! edge. So `rot` and `sym` are arithmetic on the id, and only `onext` is stored. Deleted
//! quads go to a free list and are reused, so the store never holds more than the live edges
//! plus the few deleted since.

/// A directed edge record id.
pub type EdgeId = u32;

/// Sentinel for "no vertex" in the origin table (dual records, freed quads).
const NO_VERTEX: u32 = u32::MAX;

#[derive(Debug, Default)]
pub struct QuadEdgeStore {
    /// `onext` of every directed record.
    next: Vec<EdgeId>,
    /// Origin vertex of the two primal records of each quad: index `2q + (direction)`.
    origin: Vec<u32>,
    free: Vec<u32>,
}

#[inline]
pub fn rot(e: EdgeId) -> EdgeId {
    (e & !3) | (e.wrapping_add(1) & 3)
}

#[inline]
pub fn rot_inv(e: EdgeId) -> EdgeId {
    (e & !3) | (e.wrapping_add(3) & 3)
}

#[inline]
pub fn sym(e: EdgeId) -> EdgeId {
    e ^ 2
}

impl QuadEdgeStore {
    pub fn with_capacity(edges: usize) -> Self {
        QuadEdgeStore {
            next: Vec::with_capacity(4 * edges),
            origin: Vec::with_capacity(2 * edges),
            free: Vec::new(),
        }
    }

    /// Number of quads ever allocated (live and freed).
    pub fn quad_capacity(&self) -> usize {
        self.origin.len() / 2
    }

    /// True when the quad of `e` has been deleted.
    #[inline]
    pub fn is_deleted(&self, e: EdgeId) -> bool {
        self.origin[(e >> 1) as usize & !1] == NO_VERTEX
    }

    #[inline]
    pub fn onext(&self, e: EdgeId) -> EdgeId {
        self.next[e as usize]
    }

    #[inline]
    pub fn oprev(&self, e: EdgeId) -> EdgeId {
        rot(self.onext(rot(e)))
    }

    #[inline]
    pub fn lnext(&self, e: EdgeId) -> EdgeId {
        rot(self.onext(rot_inv(e)))
    }

    #[inline]
    pub fn rprev(&self, e: EdgeId) -> EdgeId {
        self.onext(sym(e))
    }

    #[inline]
    pub fn org(&self, e: EdgeId) -> u32 {
        self.origin[(e >> 1) as usize]
    }

    #[inline]
    pub fn dest(&self, e: EdgeId) -> u32 {
        self.org(sym(e))
    }

    /// A new isolated edge from `a` to `b`; returns the primal record `a → b`.
    pub fn make_edge(&mut self, a: u32, b: u32) -> EdgeId {
        let q = match self.free.pop() {
            Some(q) => q,
            None => {
                let q = self.quad_capacity() as u32;
                self.next.extend_from_slice(&[0; 4]);
                self.origin.extend_from_slice(&[NO_VERTEX; 2]);
                q
            }
        };
        let e = q << 2;
        let i = e as usize;
        self.next[i] = e;
        self.next[i + 1] = e + 3;
        self.next[i + 2] = e + 2;
        self.next[i + 3] = e + 1;
        self.origin[2 * q as usize] = a;
        self.origin[2 * q as usize + 1] = b;
        e
    }

    /// Guibas–Stolfi splice: exchanges the origin rings of `a` and `b` (and their duals).
    pub fn splice(&mut self, a: EdgeId, b: EdgeId) {
        let alpha = rot(self.onext(a));
        let beta = rot(self.onext(b));
        self.next.swap(a as usize, b as usize);
        self.next.swap(alpha as usize, beta as usize);
    }

    /// A new edge from the destination of `a` to the origin of `b`, such that `a`, the new
    /// edge and `b` share a left face.
    pub fn connect(&mut self, a: EdgeId, b: EdgeId) -> EdgeId {
        let e = self.make_edge(self.dest(a), self.org(b));
        self.splice(e, self.lnext(a));
        self.splice(sym(e), b);
        e
    }

    /// Detaches `e` from the subdivision and frees its quad.
    pub fn delete_edge(&mut self, e: EdgeId) {
        self.splice(e, self.oprev(e));
        self.splice(sym(e), self.oprev(sym(e)));
        let q = e >> 2;
        self.origin[2 * q as usize] = NO_VERTEX;
        self.origin[2 * q as usize + 1] = NO_VERTEX;
        self.free.push(q);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rot_algebra() {
        for e in 0..16u32 {
            assert_eq!(rot(rot(e)), sym(e));
            assert_eq!(rot(rot_inv(e)), e);
            assert_eq!(rot(rot(rot(rot(e)))), e);
            assert_eq!(e >> 2, rot(e) >> 2);
        }
    }

    #[test]
    fn make_edge_is_isolated() {
        let mut s = QuadEdgeStore::default();
        let e = s.make_edge(7, 9);
        assert_eq!(s.org(e), 7);
        assert_eq!(s.dest(e), 9);
        assert_eq!(s.onext(e), e);
        assert_eq!(s.onext(sym(e)), sym(e));
        assert_eq!(s.lnext(e), sym(e));
        assert_eq!(s.onext(rot(e)), rot_inv(e));
    }

    #[test]
    fn connect_makes_a_triangle_and_delete_frees() {
        let mut s = QuadEdgeStore::default();
        let a = s.make_edge(0, 1);
        let b = s.make_edge(1, 2);
        s.splice(sym(a), b);
        let c = s.connect(b, a);
        assert_eq!((s.org(c), s.dest(c)), (2, 0));
        // The left face of a is the triangle a, b, c.
        assert_eq!(s.lnext(a), b);
        assert_eq!(s.lnext(b), c);
        assert_eq!(s.lnext(c), a);
        s.delete_edge(c);
        assert!(s.is_deleted(c));
        assert_eq!(s.lnext(b), sym(b));
        let d = s.make_edge(3, 4);
        assert_eq!(d >> 2, c >> 2, "freed quad is reused");
    }
}
