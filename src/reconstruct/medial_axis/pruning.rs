//! Taking leaves off the axis graph by the rule of the parent module: the graph as the
//! pruning reads and changes it ([`Tree`]), the order the leaves are tested in
//! ([`LeafQueue`]), and the leaves that wait for their branch to grow ([`Waiting`]).

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap, VecDeque};

use super::super::thresholds::medial_axis::{LOOKAHEAD, LOOKAHEAD_REACH};
use super::NEIGHBOURHOOD;
use crate::prefetch::prefetch;
use crate::reconstruct::bits::Bits;

/// Where a ball a leaf is tested against lies, and what the leaf's branch cuts off.
#[derive(Clone, Copy)]
pub(super) struct Reach {
    /// The ball is the junction its branch ends at, or beyond it in the tree (not a ball of
    /// the leaf's own branch).
    pub(super) past_junction: bool,
    /// Curve samples on the leaf's side of the Delaunay edge dual to its remaining axis
    /// edge (saturating at `u8::MAX`; a merged face counts as a triangle).
    pub(super) samples_cut_off: u8,
}

/// Takes leaves off the graph of `vertices` vertices and `edges`, smallest number first,
/// and returns what remains. A leaf `u` goes when `beyond(u)`, or, unless `stays(u)`, when
/// `covers(w, u, reach)` for a vertex `w` of its neighbourhood
/// ([`Tree::neighbourhood_test`]); the last edge of a component stays; a leaf whose test
/// fails is tested again when its branch grows (one that stays is not: nothing can change
/// its answer). `fetch(w)` asks for what `covers(w, ..)` will read of `w` ([`Lookahead`]).
pub(super) fn prune(
    vertices: usize,
    edges: Vec<[u32; 2]>,
    beyond: impl Fn(u32) -> bool,
    stays: impl Fn(u32) -> bool,
    covers: impl Fn(u32, u32, Reach) -> bool,
    fetch: impl Fn(u32),
) -> Tree {
    let mut tree = Tree::new(vertices, &edges);
    // The tree holds them now (the edge list was 8 bytes a vertex at the memory peak).
    drop(edges);
    let mut waiting = Waiting::default();
    let mut queue = VecDeque::new();
    let mut leaves = LeafQueue::new(
        vertices,
        (0..vertices as u32).filter(|&v| tree.degree(v) == 1),
    );
    let mut lookahead = Lookahead::default();
    // Each vertex is a triangle of the region: as a leaf it cuts off its third corner and
    // what the neighbours taken off it had cut off. One byte a vertex: only small counts
    // are read.
    let mut cut_off = vec![1u8; vertices];
    while let Some(u) = leaves.pop() {
        lookahead.advance(u, &leaves.waiting, |leaf| {
            if let Some(w) = tree.around(leaf).next() {
                prefetch(&tree.near, w as usize);
                fetch(w);
            }
        });
        let Some(v) = tree.leaf_neighbour(u) else {
            continue;
        };
        // The last edge of a component stays: pruning removes branches, not shapes.
        if tree.degree(v) == 1 {
            continue;
        }
        if !beyond(u) {
            if stays(u) {
                continue;
            }
            let samples_cut_off = cut_off[u as usize];
            let test = tree.neighbourhood_test(u, &mut queue, |w, past_junction| {
                let reach = Reach {
                    past_junction,
                    samples_cut_off,
                };
                covers(w, u, reach)
            });
            match test {
                Test::Covered => {}
                Test::Uncovered { junction } => {
                    if let Some(j) = junction {
                        waiting.add(u, j);
                    }
                    continue;
                }
            }
        }
        tree.remove(u, v);
        cut_off[v as usize] = cut_off[v as usize].saturating_add(cut_off[u as usize]);
        match tree.degree(v) {
            1 => leaves.push(v),
            // A junction became a path vertex: the branches that ended at it grew, and
            // their leaves are tested again.
            2 => waiting.release(v, |leaf| leaves.push(leaf)),
            _ => {}
        }
    }
    tree
}

/// The next leaves [`LeafQueue`] will give from its set, found [`LOOKAHEAD`] tests ahead so
/// that what their tests read (the leaf's neighbour: its slots and its ball, each a cache
/// miss in arrays of hundreds of megabytes) is on its way while the leaves before them are
/// tested. The leaves are numbered in order of radius, not of position, so nothing else
/// brings those records close: this halves the pruning's time at 10^7 noisy points (at
/// 10^8 the page walks set the pace and it gains little: ARCHITECTURE.md, "Where the time
/// goes at 10^8").
///
/// A hint only, it changes no result: leaves pushed behind its search (a neighbour that
/// just became a leaf, read a moment ago anyway) are not fetched.
#[derive(Default)]
struct Lookahead {
    /// The leaves found and fetched, not yet tested, in order.
    upcoming: VecDeque<u32>,
    /// Where the search for the next leaf goes on.
    from: usize,
}

impl Lookahead {
    /// After `popped` was taken from the queue: `fetch` each leaf that comes into view.
    fn advance(&mut self, popped: u32, waiting: &Bits, mut fetch: impl FnMut(u32)) {
        while self.upcoming.front().is_some_and(|&f| f <= popped) {
            self.upcoming.pop_front();
        }
        self.from = self.from.max(popped as usize + 1);
        while self.upcoming.len() < LOOKAHEAD {
            let Some(leaf) = waiting.first_in(self.from, self.from + LOOKAHEAD_REACH) else {
                return;
            };
            self.from = leaf + 1;
            self.upcoming.push_back(leaf as u32);
            fetch(leaf as u32);
        }
    }
}

/// No neighbour in this slot: there never was one, or its edge was removed.
const EMPTY: u32 = u32::MAX;

/// In the first slot of a vertex of degree above three: its neighbours are the slots
/// `spill[start..start + count]`, the record reads `[SPILLED, start, count]`.
const SPILLED: u32 = u32::MAX - 1;

/// The axis graph while leaves are taken off: a vertex's neighbours, [`EMPTY`] where an
/// edge was removed.
///
/// A vertex of the axis of a triangulation has at most three neighbours (a triangle has
/// three edges), so its neighbours are the slots of one 12-byte record; only a face that
/// merges cocircular triangles has more, and keeps them in `spill`. The pruning tests
/// leaves in order of radius, all over the graph, so each vertex it reads is a cache miss:
/// one record per vertex, its degree counted from it, is one miss. (Records of offset and
/// degree, a list of (edge, neighbour) pairs, the edge list and removal marks took 37
/// bytes a vertex at the memory peak of the axis, and two misses.)
pub(super) struct Tree {
    near: Vec<[u32; 3]>,
    spill: Vec<u32>,
}

impl Tree {
    /// `vertices` vertices (fewer than [`SPILLED`]) and `edges` between them.
    fn new(vertices: usize, edges: &[[u32; 2]]) -> Tree {
        debug_assert!(vertices < SPILLED as usize);
        // The degrees first, counted in the first slot, to set aside the spilled ones.
        let mut near = vec![[0, EMPTY, EMPTY]; vertices];
        for &[a, b] in edges {
            near[a as usize][0] += 1;
            near[b as usize][0] += 1;
        }
        let mut spill = Vec::new();
        for slots in &mut near {
            let degree = slots[0];
            *slots = if degree > 3 {
                let start = spill.len() as u32;
                spill.resize(spill.len() + degree as usize, EMPTY);
                [SPILLED, start, degree]
            } else {
                [EMPTY; 3]
            };
        }
        let mut tree = Tree { near, spill };
        for &[a, b] in edges {
            tree.replace(a, EMPTY, b);
            tree.replace(b, EMPTY, a);
        }
        tree
    }

    fn slots(&self, v: u32) -> &[u32] {
        let near = &self.near[v as usize];
        if near[0] == SPILLED {
            &self.spill[near[1] as usize..(near[1] + near[2]) as usize]
        } else {
            near
        }
    }

    /// The first slot of `v` holding `old` becomes `new` (there is one: the degrees were
    /// counted, and an edge is removed once).
    fn replace(&mut self, v: u32, old: u32, new: u32) {
        let near = &mut self.near[v as usize];
        let slots = if near[0] == SPILLED {
            &mut self.spill[near[1] as usize..(near[1] + near[2]) as usize]
        } else {
            &mut near[..]
        };
        let slot = slots.iter_mut().find(|s| **s == old);
        debug_assert!(slot.is_some(), "no slot of {v} holds {old}");
        if let Some(slot) = slot {
            *slot = new;
        }
    }

    /// Edges remaining at `v`.
    pub(super) fn degree(&self, v: u32) -> u32 {
        self.slots(v).iter().filter(|&&w| w != EMPTY).count() as u32
    }

    /// The other ends of the edges remaining at `v`.
    fn around(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        self.slots(v).iter().copied().filter(|&w| w != EMPTY)
    }

    /// The edges remaining, each once, `[smaller, larger]`, by their smaller end.
    pub(super) fn edges(&self) -> impl Iterator<Item = [u32; 2]> + '_ {
        (0..self.near.len() as u32)
            .flat_map(move |v| self.around(v).filter(move |&w| v < w).map(move |w| [v, w]))
    }

    /// The one neighbour of `u`, when `u` is a leaf.
    fn leaf_neighbour(&self, u: u32) -> Option<u32> {
        (self.degree(u) == 1).then(|| self.around(u).next())?
    }

    fn remove(&mut self, u: u32, v: u32) {
        self.replace(u, v, EMPTY);
        self.replace(v, u, EMPTY);
    }

    /// The vertices after leaf `u` along its branch: up to and including the first one that
    /// is not of degree 2.
    fn branch(&self, u: u32) -> impl Iterator<Item = u32> + '_ {
        let mut step = self.around(u).next().map(|v| (u, v));
        std::iter::from_fn(move || {
            let (prev, cur) = step?;
            step = if self.degree(cur) == 2 {
                self.around(cur).find(|&w| w != prev).map(|w| (cur, w))
            } else {
                None
            };
            Some(cur)
        })
    }

    /// Whether `hit` holds for one of the balls a leaf's ball is tested against: its branch
    /// up to the junction, then the nearest vertices beyond it in the tree (breadth first),
    /// where the trunk passes the whisker's foot; [`NEIGHBOURHOOD`] vertices in all, so that
    /// a test costs O(1). Stops at the first hit: on noisy input the first ball tested
    /// nearly always covers, and the walk is then a step or two (the whole neighbourhood,
    /// visited for every leaf, was most of the run at 10^6 points: cache misses). When
    /// nothing covers, the junction its branch reached (if any) is returned: the leaf is
    /// tested again when that junction becomes a path vertex ([`Waiting`]). `hit` is told
    /// whether the vertex is the junction or beyond it.
    fn neighbourhood_test(
        &self,
        u: u32,
        queue: &mut VecDeque<(u32, u32)>,
        mut hit: impl FnMut(u32, bool) -> bool,
    ) -> Test {
        let mut count = 0;
        let (mut before, mut last) = (u, None);
        for v in self.branch(u).take(NEIGHBOURHOOD) {
            // The branch ends at the first vertex not of degree 2.
            if hit(v, self.degree(v) != 2) {
                return Test::Covered;
            }
            count += 1;
            if let Some(previous) = last {
                before = previous;
            }
            last = Some(v);
        }
        let Some(last) = last else {
            return Test::Uncovered { junction: None };
        };
        let uncovered = Test::Uncovered {
            junction: (self.degree(last) >= 3).then_some(last),
        };
        // Breadth first away from the branch; in a tree nothing is met twice (around a hole
        // a vertex may be, which changes nothing but the count).
        queue.clear();
        queue.push_back((last, before));
        while let Some((v, parent)) = queue.pop_front() {
            for w in self.around(v) {
                if count >= NEIGHBOURHOOD {
                    return uncovered;
                }
                if w != parent {
                    if hit(w, true) {
                        return Test::Covered;
                    }
                    count += 1;
                    queue.push_back((w, v));
                }
            }
        }
        uncovered
    }
}

/// What a leaf's test found.
enum Test {
    Covered,
    /// Nothing covers the leaf; `junction` is where its branch ended, within
    /// [`NEIGHBOURHOOD`] vertices (`None` when the branch is longer or ends at a leaf).
    Uncovered {
        junction: Option<u32>,
    },
}

/// The leaves whose test failed, listed at the junction their branch ended at.
///
/// A failed leaf's test changes only when its branch grows, that is when its junction
/// becomes a path vertex: nothing else on its branch can change while it stays a leaf (only
/// leaves lose edges). So the leaves to test again when a junction dissolves are exactly
/// those listed at it (a walk along the paths from the junction found the same leaves, plus
/// untested ones already waiting in the queue; it cost a cache miss per step, a quarter of
/// the pruning on 10^6 noisy points). Maps, not arrays over all vertices: few leaves fail
/// (arrays were 8 bytes a vertex at the memory peak of the axis).
#[derive(Default)]
struct Waiting {
    /// The last leaf listed at each junction.
    last: HashMap<u32, u32>,
    /// The leaf listed before this one at the same junction.
    before: HashMap<u32, u32>,
}

impl Waiting {
    fn add(&mut self, leaf: u32, junction: u32) {
        if let Some(before) = self.last.insert(junction, leaf) {
            self.before.insert(leaf, before);
        }
    }

    /// Hands over, and forgets, the leaves listed at `junction`.
    fn release(&mut self, junction: u32, mut each: impl FnMut(u32)) {
        let mut leaf = self.last.remove(&junction);
        while let Some(l) = leaf {
            each(l);
            leaf = self.before.remove(&l);
        }
    }
}

/// The leaves waiting to be tested, smallest ball first, which is smallest number first
/// (the parent module's `Ball`), as one min-heap over all of them would give them.
///
/// Numbers at or after the scan's position are bits of a set, read forward one word at a
/// time; a leaf pushed behind the scan (a neighbour with a smaller ball, or a leaf that
/// failed earlier and is tested again) is smaller than every bit, and waits in a small heap
/// that pops first. No leaf is ever waiting twice (a leaf is pushed when its degree drops to
/// one, or released once from the one junction it waits at), so a set loses nothing. (A
/// heap of the pushed leaves beside the list of the first ones was a fifth of the pruning at
/// 10^7 noisy points: a pop's sift-down misses the cache at every level of a heap of
/// millions; one heap of all the leaves had been a third of the run at 10^6.)
struct LeafQueue {
    /// The waiting leaves numbered at least `scan`.
    waiting: Bits,
    /// Every leaf in `waiting` is numbered at least this.
    scan: usize,
    /// Waiting leaves numbered below `scan`.
    behind: BinaryHeap<Reverse<u32>>,
}

impl LeafQueue {
    fn new(count: usize, leaves: impl Iterator<Item = u32>) -> LeafQueue {
        let mut waiting = Bits::new(count);
        for leaf in leaves {
            waiting.set(leaf as usize);
        }
        LeafQueue {
            waiting,
            scan: 0,
            behind: BinaryHeap::new(),
        }
    }

    fn push(&mut self, leaf: u32) {
        if leaf as usize >= self.scan {
            self.waiting.set(leaf as usize);
        } else {
            self.behind.push(Reverse(leaf));
        }
    }

    fn pop(&mut self) -> Option<u32> {
        if let Some(Reverse(leaf)) = self.behind.pop() {
            return Some(leaf);
        }
        let leaf = self.waiting.take_first_from(self.scan)?;
        self.scan = leaf + 1;
        Some(leaf as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wdm_crust_testkit::Rng;

    /// The leaf queue pops what one min-heap of the same leaves pops, pushes in front of and
    /// behind its scan interleaved, never a leaf that is already waiting.
    #[test]
    fn the_leaf_queue_pops_in_heap_order() {
        let mut rng = Rng::new(11);
        for round in 0..200 {
            let count = 1 + rng.below(300);
            let mut waiting = vec![false; count];
            for w in waiting.iter_mut() {
                *w = rng.f64() < 0.2;
            }
            let initial: Vec<u32> = (0..count as u32).filter(|&i| waiting[i as usize]).collect();
            let mut queue = LeafQueue::new(count, initial.iter().copied());
            let mut heap: BinaryHeap<Reverse<u32>> = initial.iter().map(|&i| Reverse(i)).collect();
            for step in 0.. {
                // Pushes for a while, then the queue drains.
                let pushes = if step < 2 * count { rng.below(4) } else { 0 };
                for _ in 0..pushes {
                    let leaf = rng.below(count) as u32;
                    if !waiting[leaf as usize] {
                        waiting[leaf as usize] = true;
                        queue.push(leaf);
                        heap.push(Reverse(leaf));
                    }
                }
                let popped = queue.pop();
                assert_eq!(popped, heap.pop().map(|r| r.0), "round {round}");
                match popped {
                    Some(leaf) => waiting[leaf as usize] = false,
                    None => break,
                }
            }
        }
    }

    /// The tree's records against a set of edges, on random graphs with vertices of every
    /// degree up to 8 (spilled above three), as edges are removed one by one.
    #[test]
    fn the_tree_keeps_the_edges_not_removed() {
        let mut rng = Rng::new(12);
        for round in 0..200 {
            let n = 2 + rng.below(30);
            let mut edges = std::collections::BTreeSet::new();
            for _ in 0..rng.below(3 * n) {
                let (a, b) = (rng.below(n) as u32, rng.below(n) as u32);
                if a != b
                    && [a, b]
                        .iter()
                        .all(|&v| edges.iter().filter(|e: &&[u32; 2]| e.contains(&v)).count() < 8)
                {
                    edges.insert([a.min(b), a.max(b)]);
                }
            }
            let list: Vec<[u32; 2]> = edges.iter().copied().collect();
            let mut tree = Tree::new(n, &list);
            let mut order = list.clone();
            for i in (1..order.len()).rev() {
                order.swap(i, rng.below(i + 1));
            }
            for &[a, b] in order.iter().take(rng.below(order.len() + 1)) {
                if rng.f64() < 0.5 {
                    tree.remove(a, b);
                } else {
                    tree.remove(b, a);
                }
                edges.remove(&[a, b]);
            }
            let mut left: Vec<[u32; 2]> = tree.edges().collect();
            left.sort_unstable();
            assert_eq!(
                left,
                edges.iter().copied().collect::<Vec<_>>(),
                "round {round}"
            );
            for v in 0..n as u32 {
                let mut around: Vec<u32> = tree.around(v).collect();
                around.sort_unstable();
                let expected: Vec<u32> = edges
                    .iter()
                    .filter_map(|&[a, b]| (a == v).then_some(b).or((b == v).then_some(a)))
                    .collect::<std::collections::BTreeSet<_>>()
                    .into_iter()
                    .collect();
                assert_eq!(around, expected, "round {round}, vertex {v}");
                assert_eq!(tree.degree(v) as usize, expected.len());
                assert_eq!(
                    tree.leaf_neighbour(v),
                    (expected.len() == 1).then(|| expected[0])
                );
            }
        }
    }
}
