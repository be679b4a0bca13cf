//! The typed index spaces: a half-edge, a triangle and a Voronoi vertex are each their own
//! `u32` newtype, and so is the crate-private *local* point index (the locality order of a
//! [`Triangulation`](crate::Triangulation)). A caller's point index stays a plain `u32`: it
//! is a position in the caller's own slice. Every type is `#[repr(transparent)]` over `u32`,
//! so a `Vec` of them is a `Vec<u32>` in memory; the spaces cannot be mixed up, and
//! `.index()` is the one way from an id to a position in an array.

/// Defines one index newtype over `u32`; `$vis` is its visibility.
macro_rules! index_type {
    ($(#[$doc:meta])* $vis:vis struct $name:ident;) => {
        $(#[$doc])*
        #[repr(transparent)]
        #[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
        #[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
        #[cfg_attr(feature = "serde", serde(transparent))]
        $vis struct $name(u32);

        impl $name {
            /// The id with number `i`.
            #[inline]
            pub const fn new(i: u32) -> Self {
                Self(i)
            }

            /// Its number.
            #[inline]
            pub const fn get(self) -> u32 {
                self.0
            }

            /// Its number as a position in an array indexed by this space.
            #[inline]
            pub const fn index(self) -> usize {
                self.0 as usize
            }
        }

        impl From<u32> for $name {
            #[inline]
            fn from(i: u32) -> Self {
                Self(i)
            }
        }

        impl From<$name> for u32 {
            #[inline]
            fn from(id: $name) -> u32 {
                id.0
            }
        }

        impl From<$name> for usize {
            #[inline]
            fn from(id: $name) -> usize {
                id.0 as usize
            }
        }

        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                self.0.fmt(f)
            }
        }
    };
}

index_type! {
    /// A half-edge of a [`Triangulation`](crate::Triangulation): half-edge `3t + k` belongs to
    /// triangle `t` and runs from its corner `k` to corner `(k + 1) % 3`. It also names the
    /// Voronoi edge dual to it. [`NO_TWIN`](crate::delaunay::NO_TWIN) is no half-edge.
    pub struct HalfEdge;
}

index_type! {
    /// A triangle of a [`Triangulation`](crate::Triangulation), by its position in
    /// [`Triangulation::triangles`](crate::Triangulation::triangles).
    pub struct TriangleId;
}

index_type! {
    /// A finite vertex of a [`Voronoi`](crate::Voronoi) diagram: one merged Delaunay face.
    pub struct VertexId;
}

index_type! {
    /// A distinct point in the locality order of a triangulation (crate-private: every
    /// public method takes and returns the caller's indices).
    pub(crate) struct LocalPoint;
}

impl HalfEdge {
    /// The triangle it belongs to.
    #[inline]
    pub const fn triangle(self) -> TriangleId {
        TriangleId(self.0 / 3)
    }

    /// The corner of its triangle it starts from (0, 1 or 2).
    #[inline]
    pub const fn corner(self) -> usize {
        (self.0 % 3) as usize
    }

    /// The next half-edge counterclockwise inside the same triangle.
    #[inline]
    pub const fn next(self) -> HalfEdge {
        HalfEdge(if self.0 % 3 == 2 {
            self.0 - 2
        } else {
            self.0 + 1
        })
    }

    /// The previous half-edge counterclockwise inside the same triangle.
    #[inline]
    pub const fn prev(self) -> HalfEdge {
        HalfEdge(if self.0 % 3 == 0 {
            self.0 + 2
        } else {
            self.0 - 1
        })
    }
}

impl TriangleId {
    /// Its three half-edges, `3t`, `3t + 1`, `3t + 2`: from corner 0, 1 and 2.
    #[inline]
    pub const fn halfedges(self) -> [HalfEdge; 3] {
        [
            HalfEdge(3 * self.0),
            HalfEdge(3 * self.0 + 1),
            HalfEdge(3 * self.0 + 2),
        ]
    }

    /// Its half-edge from corner `k` (0, 1 or 2).
    #[inline]
    pub const fn halfedge(self, k: usize) -> HalfEdge {
        HalfEdge(3 * self.0 + k as u32)
    }
}

/// The ids `0..count` of one space, in order.
#[inline]
pub(crate) fn ids<T: From<u32>>(
    count: usize,
) -> impl DoubleEndedIterator<Item = T> + ExactSizeIterator + Clone {
    (0..count as u32).map(T::from)
}
