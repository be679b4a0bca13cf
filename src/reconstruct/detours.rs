//! Detour repair: outliers just outside a curve can make the water flow take a detour through
//! them and skip a stretch of true samples; this puts the skipped stretch back and drops the
//! detour. All point indices are local to the full triangulation.
//!
//! What goes wrong (seen on the outlier rows of `examples/quality.rs`): a few outliers outside
//! a concave stretch of the curve get water from outside, and their state transitions
//! deactivate the Voronoi vertices between them and the curve. The water never reaches the
//! stretch, its samples get no crust edge (they are reported unassigned), and the crust runs
//! `a → o₁ → … → b` through the outliers instead of along the stretch from `a` to `b`.
//!
//! The skipped samples still know their curve neighbours: the two curve edges of a sample are
//! its nearest neighbour and its *half neighbour* (the NN-crust of Dey and Kumar), and
//! consecutive samples name each other. The repair:
//! 1. **Stretches.** Candidate edges: named from both ends with at least one end unassigned,
//!    or named from one end between two unassigned points (an outlier beside the stretch can
//!    take one name of a sample; a one-sided name still links the stretch). Branches that end
//!    at an unassigned point are pruned; what is left is grouped by connectivity.
//! 2. **Swaps.** A group touching 2 to [`MAX_ANCHORS`] points already on a curve offers, for
//!    each pair `a < b` of them in order, the path `a → s₁ → … → b` with fewest edges through
//!    its unassigned points. The first pair whose swap is clean is used: each of `a` and `b`
//!    has two curve edges of which it names exactly one, and the other two edges are the ends
//!    of one chain `a → o₁ → … → b` of at most [`MAX_DETOUR_POINTS`] inner points, and at
//!    both ends the stretch's first point is strictly closer than the detour's. The chain
//!    is removed (its points become unassigned), the path added. Groups are tried in the
//!    order of their smallest point, each against the curves as the groups before it left
//!    them.
//!
//! A swap keeps every point's degree (the ends keep two edges, the path's points get two, the
//! detour's none), so it never turns a closed curve into chains or junctions: on noisy samples
//! a group of leftovers that offers no clean swap changes nothing. Every decision is exact:
//! nearest and half neighbours are decided by the kernel's exact distance comparison and
//! dot-product sign (ties by coordinates, as in the NN-crust); the rest is combinatorics on
//! the edges, in an order fixed by the points (local indices follow the coordinates), so the
//! result depends on neither the input order nor the thread count. When every point is on a
//! curve (a clean sample) nothing runs.

use std::collections::{BTreeMap, BTreeSet};

use super::curves::Adjacency;
use super::nn_crust::closer;
use crate::kernel::metric::{distance_order, dot_sign};
use crate::kernel::Sign;
use crate::voronoi::Voronoi;

/// The most inner points of a detour a swap removes. A detour runs through a few outliers;
/// replacing a longer piece of curve would take more than outliers away (a bound of 8 gave
/// the same outlier rows, 16 and 32 lower recall).
const MAX_DETOUR_POINTS: usize = 4;

/// The most points on a curve one group may touch for its pairs to be tried (a bound on the
/// work: a group of noise leftovers along a whole curve touches many).
const MAX_ANCHORS: usize = 6;

/// What the repair changes: edges to add and edges to remove, each sorted.
pub(super) struct Repair {
    /// The reattached stretches.
    pub(super) added: Vec<[u32; 2]>,
    /// The detours.
    pub(super) removed: Vec<[u32; 2]>,
}

impl Repair {
    pub(super) fn none() -> Repair {
        Repair {
            added: Vec::new(),
            removed: Vec::new(),
        }
    }

    /// Applies the repair to the edges it was computed on.
    pub(super) fn apply(&self, edges: &mut Vec<[u32; 2]>) {
        if !self.removed.is_empty() {
            edges.retain(|e| self.removed.binary_search(e).is_err());
        }
        edges.extend_from_slice(&self.added);
    }
}

/// The repair (module docs) of `edges` (distinct, `[min, max]`, any order), as edges to add
/// and to remove.
pub(super) fn repair_detours(vor: &Voronoi<'_>, edges: &[[u32; 2]]) -> Repair {
    let n = vor.triangulation().points.len();
    let mut on_curve = vec![false; n];
    for &[a, b] in edges {
        on_curve[a as usize] = true;
        on_curve[b as usize] = true;
    }
    if on_curve.iter().all(|&t| t) {
        return Repair::none();
    }
    let mut named = NeighbourNames::new(vor);
    let groups = stretches(&mut named, &on_curve);
    if groups.is_empty() {
        return Repair::none();
    }
    let mut curves = EditedCurves::new(n, edges);
    for group in &groups {
        if let Some(swap) = clean_swap(&mut named, &curves, &on_curve, group) {
            curves.swap(&swap);
        }
    }
    curves.into_repair()
}

/// A clean swap: the stretch's edges replace the detour's.
struct Swap {
    stretch: Vec<[u32; 2]>,
    detour: Vec<[u32; 2]>,
}

/// A group of step 1 as its edges, sorted.
type Group = Vec<[u32; 2]>;

/// Step 1: the candidate edges, without loose ends, in groups ordered by their smallest
/// point; only the groups that touch between 2 and [`MAX_ANCHORS`] points on a curve.
fn stretches(named: &mut NeighbourNames<'_, '_>, on_curve: &[bool]) -> Vec<Group> {
    let mut candidates = candidate_edges(named, on_curve);
    without_loose_ends(&mut candidates, on_curve);
    let mut groups = UnionFind::new(on_curve.len());
    for &[a, b] in &candidates {
        groups.union(a, b);
    }
    // Sorted by root, the smallest point of the group: the groups in the order of it.
    let mut keyed: Vec<(u32, [u32; 2])> =
        candidates.iter().map(|&e| (groups.find(e[0]), e)).collect();
    keyed.sort_unstable();
    keyed
        .chunk_by(|x, y| x.0 == y.0)
        .map(|group| group.iter().map(|&(_, e)| e).collect::<Group>())
        .filter(|group| (2..=MAX_ANCHORS).contains(&anchors(group, on_curve).len()))
        .collect()
}

/// The points of a group that are on a curve, sorted.
fn anchors(group: &[[u32; 2]], on_curve: &[bool]) -> Vec<u32> {
    let mut anchors: Vec<u32> = group
        .iter()
        .flatten()
        .copied()
        .filter(|&p| on_curve[p as usize])
        .collect();
    anchors.sort_unstable();
    anchors.dedup();
    anchors
}

/// Step 2 for one group: the first pair of its points on a curve, in order, whose path through
/// the group (fewest edges, through unassigned points) offers a clean swap; that path and the
/// detour it replaces, as edges. A group is a path in the common case; an outlier that names a
/// stretch sample can add a branch to a third point on a curve, which the pair skips.
fn clean_swap(
    named: &mut NeighbourNames<'_, '_>,
    curves: &EditedCurves,
    on_curve: &[bool],
    group: &Group,
) -> Option<Swap> {
    let mut around: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for &[a, b] in group {
        around.entry(a).or_default().push(b);
        around.entry(b).or_default().push(a);
    }
    for neighbours in around.values_mut() {
        neighbours.sort_unstable();
    }
    let anchors = anchors(group, on_curve);
    for (i, &a) in anchors.iter().enumerate() {
        for &b in &anchors[i + 1..] {
            let Some(detour) = detour_between(named, curves, a, b) else {
                continue;
            };
            let Some(path) = shortest_path(&around, on_curve, a, b) else {
                continue;
            };
            if steps_in_closer(named.vor, &path, &detour, a)
                && steps_in_closer(named.vor, &path, &detour, b)
            {
                return Some(Swap {
                    stretch: path,
                    detour,
                });
            }
        }
    }
    None
}

/// Is the stretch's first point from `end` strictly closer to `end` than the detour's? (A
/// detour runs out to outliers; in a noise band the two are alike.)
fn steps_in_closer(vor: &Voronoi<'_>, stretch: &[[u32; 2]], detour: &[[u32; 2]], end: u32) -> bool {
    let other = |edges: &[[u32; 2]]| {
        edges
            .iter()
            .find(|e| e.contains(&end))
            .map(|&[x, y]| if x == end { y } else { x })
    };
    let points = &vor.triangulation().points;
    let at = |i: u32| points[i as usize];
    match (other(stretch), other(detour)) {
        (Some(s), Some(o)) => distance_order(at(end), at(s), at(o)) == Sign::Negative,
        _ => false,
    }
}

/// The path from `a` to `b` with fewest edges whose inner points are unassigned (breadth
/// first, neighbours in increasing order), as sorted edges.
fn shortest_path(
    around: &BTreeMap<u32, Vec<u32>>,
    on_curve: &[bool],
    a: u32,
    b: u32,
) -> Option<Vec<[u32; 2]>> {
    let mut came_from: BTreeMap<u32, u32> = BTreeMap::from([(a, a)]);
    let mut queue = std::collections::VecDeque::from([a]);
    while let Some(p) = queue.pop_front() {
        if p == b {
            break;
        }
        if p != a && on_curve[p as usize] {
            continue;
        }
        for &q in around.get(&p).into_iter().flatten() {
            if let std::collections::btree_map::Entry::Vacant(slot) = came_from.entry(q) {
                slot.insert(p);
                queue.push_back(q);
            }
        }
    }
    came_from.get(&b)?;
    let mut path = Vec::new();
    let mut at = b;
    while at != a {
        let previous = came_from[&at];
        path.push([at.min(previous), at.max(previous)]);
        at = previous;
    }
    path.sort_unstable();
    Some(path)
}

/// The detour a swap between `a` and `b` replaces, when clean: each of `a` and `b` has two
/// curve edges and names exactly one, and the other two are the ends of one chain through at
/// most [`MAX_DETOUR_POINTS`] points of degree 2.
fn detour_between(
    named: &mut NeighbourNames<'_, '_>,
    curves: &EditedCurves,
    a: u32,
    b: u32,
) -> Option<Vec<[u32; 2]>> {
    let (from_a, into_b) = (
        unnamed_edge(named, curves, a)?,
        unnamed_edge(named, curves, b)?,
    );
    let mut detour = vec![[a.min(from_a), a.max(from_a)]];
    let (mut previous, mut at) = (a, from_a);
    while at != b {
        // `detour.len()` is the number of inner points so far.
        if at == a || detour.len() > MAX_DETOUR_POINTS {
            return None;
        }
        let &[x, y] = curves.neighbours(at).as_slice() else {
            return None;
        };
        let next = if x == previous { y } else { x };
        detour.push([at.min(next), at.max(next)]);
        (previous, at) = (at, next);
    }
    // The walk must arrive through the edge `b` does not name.
    (previous == into_b).then_some(detour)
}

/// The one curve neighbour of `p` that `p` does not name, when `p` has two curve neighbours
/// and names the other.
fn unnamed_edge(named: &mut NeighbourNames<'_, '_>, curves: &EditedCurves, p: u32) -> Option<u32> {
    let &[x, y] = curves.neighbours(p).as_slice() else {
        return None;
    };
    let names = named.of(p);
    match (names.contains(&Some(x)), names.contains(&Some(y))) {
        (true, false) => Some(y),
        (false, true) => Some(x),
        _ => None,
    }
}

/// The curve edges with the swaps made so far: the original edges, less those removed, plus
/// those added (few, so kept in ordered sets).
struct EditedCurves {
    original: Adjacency,
    removed: BTreeSet<[u32; 2]>,
    added: BTreeSet<[u32; 2]>,
    added_around: BTreeMap<u32, Vec<u32>>,
}

impl EditedCurves {
    fn new(n: usize, edges: &[[u32; 2]]) -> Self {
        EditedCurves {
            original: Adjacency::new(n, edges),
            removed: BTreeSet::new(),
            added: BTreeSet::new(),
            added_around: BTreeMap::new(),
        }
    }

    /// The current curve neighbours of `p`.
    fn neighbours(&self, p: u32) -> Vec<u32> {
        let original = self.original.neighbours(p).iter().map(|&(_, q)| q);
        let added = self.added_around.get(&p).into_iter().flatten().copied();
        original
            .filter(|&q| !self.removed.contains(&[p.min(q), p.max(q)]))
            .chain(added.filter(|&q| self.added.contains(&[p.min(q), p.max(q)])))
            .collect()
    }

    fn swap(&mut self, swap: &Swap) {
        for &e in &swap.detour {
            if !self.added.remove(&e) {
                self.removed.insert(e);
            }
        }
        for &[a, b] in &swap.stretch {
            self.added.insert([a, b]);
            self.added_around.entry(a).or_default().push(b);
            self.added_around.entry(b).or_default().push(a);
        }
    }

    fn into_repair(self) -> Repair {
        Repair {
            added: self.added.into_iter().collect(),
            removed: self.removed.into_iter().collect(),
        }
    }
}

/// Candidate edges of step 1 (module docs), sorted.
fn candidate_edges(named: &mut NeighbourNames<'_, '_>, on_curve: &[bool]) -> Vec<[u32; 2]> {
    let mut candidates = Vec::new();
    for p in 0..on_curve.len() as u32 {
        if on_curve[p as usize] {
            continue;
        }
        let names = named.of(p);
        for q in named.around(p) {
            let (p_names_q, q_names_p) = (names.contains(&Some(q)), named.of(q).contains(&Some(p)));
            let both_unassigned = !on_curve[q as usize];
            if (p_names_q && q_names_p) || (both_unassigned && (p_names_q || q_names_p)) {
                candidates.push([p.min(q), p.max(q)]);
            }
        }
    }
    candidates.sort_unstable();
    candidates.dedup();
    candidates
}

/// Removes, repeatedly, the edges with an unassigned end that no other edge touches: what is
/// left of a group joins points on curves through unassigned points.
fn without_loose_ends(edges: &mut Vec<[u32; 2]>, on_curve: &[bool]) {
    let adjacency = Adjacency::new(on_curve.len(), edges);
    let mut removed = vec![false; edges.len()];
    let mut degree: Vec<u32> = (0..on_curve.len() as u32)
        .map(|p| adjacency.neighbours(p).len() as u32)
        .collect();
    let mut loose: Vec<u32> = (0..on_curve.len() as u32)
        .filter(|&p| !on_curve[p as usize] && degree[p as usize] == 1)
        .collect();
    // Peeling a loose end may leave its neighbour loose: the order does not change what is
    // left (the edges on no path between two curve points or around a cycle).
    while let Some(p) = loose.pop() {
        let Some(&(e, q)) = adjacency
            .neighbours(p)
            .iter()
            .find(|&&(e, _)| !removed[e as usize])
        else {
            continue;
        };
        removed[e as usize] = true;
        degree[p as usize] -= 1;
        degree[q as usize] -= 1;
        if !on_curve[q as usize] && degree[q as usize] == 1 {
            loose.push(q);
        }
    }
    let mut index = 0;
    edges.retain(|_| {
        index += 1;
        !removed[index - 1]
    });
}

/// Every point's nearest neighbour and half neighbour (NN-crust), computed on demand: only
/// the unassigned points and those they name are ever asked.
struct NeighbourNames<'v, 't> {
    vor: &'v Voronoi<'t>,
    cache: Vec<Option<[Option<u32>; 2]>>,
}

impl<'v, 't> NeighbourNames<'v, 't> {
    fn new(vor: &'v Voronoi<'t>) -> Self {
        let n = vor.triangulation().points.len();
        NeighbourNames {
            vor,
            cache: vec![None; n],
        }
    }

    /// The Delaunay neighbours of `p` along edges with a dual Voronoi edge.
    fn around(&self, p: u32) -> impl Iterator<Item = u32> + Clone + 'v {
        self.vor.dual_neighbours_local(p)
    }

    /// `[nearest, half]` neighbour of `p` among its Delaunay neighbours along edges with a
    /// dual Voronoi edge (the NN-crust's candidates, so cocircular diagonals never count).
    fn of(&mut self, p: u32) -> [Option<u32>; 2] {
        if let Some(names) = self.cache[p as usize] {
            return names;
        }
        let points = &self.vor.triangulation().points;
        let at = |i: u32| points[i as usize];
        let around = self.around(p);
        let nearest = |candidates: &mut dyn Iterator<Item = u32>| {
            candidates.min_by(|&a, &b| closer(at(p), at(a), at(b)))
        };
        let q = nearest(&mut around.clone());
        let half = q.and_then(|q| {
            nearest(&mut around.filter(|&s| dot_sign(at(p), at(s), at(q)) == Sign::Negative))
        });
        self.cache[p as usize] = Some([q, half]);
        [q, half]
    }
}

/// Union–find over point indices; the root of a group is its smallest member, so it does
/// not depend on the order of the unions.
struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    fn new(n: usize) -> Self {
        UnionFind {
            parent: (0..n as u32).collect(),
        }
    }

    fn find(&mut self, p: u32) -> u32 {
        let mut root = p;
        while self.parent[root as usize] != root {
            root = self.parent[root as usize];
        }
        let mut at = p;
        while at != root {
            at = std::mem::replace(&mut self.parent[at as usize], root);
        }
        root
    }

    fn union(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.find(a), self.find(b));
        self.parent[ra.max(rb) as usize] = ra.min(rb);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::triangulate;
    use std::f64::consts::TAU;

    /// 24 points on the unit circle, then `extra` points.
    fn circle_with(extra: &[[f64; 2]]) -> Vec<[f64; 2]> {
        let mut points: Vec<[f64; 2]> = (0..24)
            .map(|i| {
                let t = i as f64 * TAU / 24.0;
                [t.cos(), t.sin()]
            })
            .collect();
        points.extend_from_slice(extra);
        points
    }

    fn edge(a: u32, b: u32) -> [u32; 2] {
        [a.min(b), a.max(b)]
    }

    /// The circle's polygon, with the stretch `from → … → to` replaced by a path through
    /// `detour` (caller indices).
    fn polygon_with_detour(from: u32, to: u32, detour: &[u32]) -> Vec<[u32; 2]> {
        let mut edges: Vec<[u32; 2]> = (0..24)
            .filter(|&i| i < from || i >= to)
            .map(|i| edge(i, (i + 1) % 24))
            .collect();
        let path: Vec<u32> = std::iter::once(from)
            .chain(detour.iter().copied())
            .chain(std::iter::once(to))
            .collect();
        edges.extend(path.windows(2).map(|w| edge(w[0], w[1])));
        edges
    }

    /// Runs the repair on caller-index `edges` and returns the repaired edges, sorted, in
    /// caller indices.
    fn repaired(points: &[[f64; 2]], edges: &[[u32; 2]]) -> Vec<[u32; 2]> {
        let tri = triangulate(points).unwrap();
        let vor = tri.voronoi();
        let mut local: Vec<[u32; 2]> = edges
            .iter()
            .map(|&[a, b]| edge(tri.local_index(a), tri.local_index(b)))
            .collect();
        repair_detours(&vor, &local).apply(&mut local);
        let mut result: Vec<[u32; 2]> = local
            .iter()
            .map(|&[a, b]| edge(tri.input_index(a), tri.input_index(b)))
            .collect();
        result.sort_unstable();
        result
    }

    fn circle_polygon() -> Vec<[u32; 2]> {
        let mut edges: Vec<[u32; 2]> = (0..24).map(|i| edge(i, (i + 1) % 24)).collect();
        edges.sort_unstable();
        edges
    }

    #[test]
    fn a_detour_through_outliers_is_swapped_for_the_skipped_stretch() {
        // Two outliers outside the arc 3 … 8; the curve runs 3 → 24 → 25 → 8.
        let out = |t: f64, r: f64| [r * (t * TAU / 24.0).cos(), r * (t * TAU / 24.0).sin()];
        let points = circle_with(&[out(4.0, 1.7), out(7.0, 1.7)]);
        let edges = polygon_with_detour(3, 8, &[24, 25]);
        assert_eq!(repaired(&points, &edges), circle_polygon());
    }

    #[test]
    fn nothing_changes_without_a_clean_swap() {
        let out = |t: f64, r: f64| [r * (t * TAU / 24.0).cos(), r * (t * TAU / 24.0).sin()];
        // A clean circle with two outliers inside that name each other: their group touches
        // no curve, nothing is added.
        let points = circle_with(&[[0.05, 0.0], [-0.05, 0.02]]);
        assert_eq!(repaired(&points, &circle_polygon()), circle_polygon());
        // A detour of more than MAX_DETOUR_POINTS points is not a detour through outliers:
        // the skipped stretch stays unassigned.
        let far: Vec<[f64; 2]> = (0..=MAX_DETOUR_POINTS)
            .map(|k| out(3.0 + 5.0 * k as f64 / MAX_DETOUR_POINTS as f64, 2.0))
            .collect();
        let points = circle_with(&far);
        let detour: Vec<u32> = (24..24 + far.len() as u32).collect();
        let mut edges = polygon_with_detour(3, 8, &detour);
        edges.sort_unstable();
        assert_eq!(repaired(&points, &edges), edges);
    }

    #[test]
    fn the_repair_does_not_depend_on_the_input_order() {
        let out = |t: f64, r: f64| [r * (t * TAU / 24.0).cos(), r * (t * TAU / 24.0).sin()];
        let points = circle_with(&[out(4.0, 1.7), out(7.0, 1.7), [0.1, 0.1]]);
        let edges = polygon_with_detour(3, 8, &[24, 25]);
        let expected = repaired(&points, &edges);
        let mut rng = wdm_crust_testkit::Rng::new(5);
        for _ in 0..10 {
            let order = rng.permutation(points.len());
            // Point `i` of the original is point `position[i]` of the shuffled input.
            let mut position = vec![0u32; points.len()];
            for (k, &i) in order.iter().enumerate() {
                position[i] = k as u32;
            }
            let shuffled: Vec<[f64; 2]> = order.iter().map(|&i| points[i]).collect();
            let renamed: Vec<[u32; 2]> = edges
                .iter()
                .map(|&[a, b]| edge(position[a as usize], position[b as usize]))
                .collect();
            let mut back: Vec<[u32; 2]> = repaired(&shuffled, &renamed)
                .iter()
                .map(|&[a, b]| edge(order[a as usize] as u32, order[b as usize] as u32))
                .collect();
            back.sort_unstable();
            assert_eq!(back, expected);
        }
    }
}
