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
//! 1. **Stretches.** Candidate edges are the Delaunay edges named by an unassigned end, or by
//!    either end when both are unassigned. One name is enough: an outlier beside the stretch
//!    can take one name of a sample, and the curve point where the stretch ends may name an
//!    outlier beside it instead of the stretch's last sample. Branches that end at an
//!    unassigned point are pruned; what is left is grouped by connectivity.
//! 2. **Swaps.** A group touching 2 to [`MAX_ANCHORS`] points already on a curve offers, for
//!    each pair `a < b` of them in order, the path `a → s₁ → … → b` through its unassigned
//!    points whose longest edge is shortest (a *bottleneck* path: along the densely sampled
//!    stretch, not across the sparse outliers its points also name). It is swapped for the
//!    detour when `a` and `b` are joined along the curves, in exactly one direction, by a
//!    chain `a → o₁ → … → b` of at most [`MAX_DETOUR_POINTS`] inner points, and the path's
//!    longest edge is strictly shorter than the chain's (a detour reaches out to outliers, a
//!    spacing or more away; a true stretch is the shorter way). The chain is removed (its
//!    points become unassigned), the path added; the group's further pairs are tried
//!    against the edited curves, with the path's points taken.
//! 3. **Rounds.** A swap frees the detour's points and can complete a stretch that the
//!    outliers split, so steps 1 and 2 (and 4) run again on the edited curves, up to
//!    [`ROUNDS`] times or until a round changes nothing.
//! 4. **Woven spikes.** At the end of each round, outliers woven into a curve beside a true
//!    edge (`a → o → b` where the curve runs `a → b`, no sample skipped) are dropped
//!    (`super::spikes`), when at least [`MIN_UNASSIGNED_FOR_SPIKES`] of the points are
//!    unassigned.
//!
//! A swap keeps every point's degree (the ends keep two edges, the path's points get two, the
//! detour's none), so it never turns a closed curve into chains or junctions: on noisy samples
//! a group of leftovers that offers no swap changes nothing. Every decision is exact: nearest
//! and half neighbours by the kernel's distance comparison and dot-product sign (ties by
//! coordinates, as in the NN-crust), edge lengths by its exact length comparison (ties by the
//! points); the rest is combinatorics on the edges, in an order fixed by the points (local
//! indices follow the coordinates), so the result depends on neither the input order nor the
//! thread count (step 4 adds angle thresholds in rounded arithmetic, tolerances of its rule
//! argued in `super::spikes`). When every point is on a curve (a clean sample) nothing runs.

use std::cmp::Reverse;
use std::collections::{BTreeMap, BTreeSet, BinaryHeap, HashMap};

use super::shared::{EditedCurves, Repair, Swap};
use super::spikes::drop_woven_spikes;
use crate::ids::{ids, LocalPoint};
use crate::kernel::metric::{dot_sign, length_order};
use crate::kernel::Sign;
use crate::reconstruct::curves::Adjacency;
use crate::reconstruct::proximity::closer;
use crate::reconstruct::thresholds::detours::{
    MAX_ANCHORS, MAX_DETOUR_POINTS, MIN_UNASSIGNED_FOR_SPIKES, ROUNDS,
};
use crate::voronoi::Voronoi;

/// The repair (module docs) of `edges` (distinct, `[min, max]`, any order), as edges to add
/// and to remove.
pub(crate) fn repair_detours(vor: &Voronoi<'_>, edges: &[[LocalPoint; 2]]) -> Repair {
    let n = vor.triangulation().points.len();
    let mut on_curve = vec![false; n];
    for &[a, b] in edges {
        on_curve[a.index()] = true;
        on_curve[b.index()] = true;
    }
    if on_curve.iter().all(|&t| t) {
        return Repair::none();
    }
    let mut named = NeighbourNames::new(vor);
    // The curves as edited, built at the first edit (an adjacency of all the edges, 20
    // bytes a point: most inputs with a few points off the curves have nothing to swap).
    let mut edited: Option<EditedCurves> = None;
    let original = on_curve.clone();
    let mut median = None;
    let unassigned = on_curve.iter().filter(|&&t| !t).count();
    let look_for_spikes = unassigned as f64 >= MIN_UNASSIGNED_FOR_SPIKES * n as f64;
    for _ in 0..ROUNDS {
        if let Some(curves) = &edited {
            on_curve = curves.on_curve(&original);
        }
        let mut swapped = false;
        for group in &stretches(&mut named, &on_curve) {
            let curves = edited.get_or_insert_with(|| EditedCurves::new(n, edges));
            swapped |= swap_detours(&mut named, curves, &on_curve, group);
        }
        // Step 4: spikes, on the curves as the swaps left them. A dropped spike is
        // unassigned, and the next round may swap it back in as part of a stretch.
        if look_for_spikes {
            let curves = edited.get_or_insert_with(|| EditedCurves::new(n, edges));
            swapped |= drop_woven_spikes(vor, curves, &mut median) > 0;
        }
        if !swapped {
            break;
        }
    }
    edited.map_or_else(Repair::none, EditedCurves::into_repair)
}

/// A group of step 1 as its edges, sorted.
type Group = Vec<[LocalPoint; 2]>;

/// Step 1: the candidate edges, without loose ends, in groups ordered by their smallest
/// point; only the groups that touch between 2 and [`MAX_ANCHORS`] points on a curve.
fn stretches(named: &mut NeighbourNames<'_, '_>, on_curve: &[bool]) -> Vec<Group> {
    let candidates = candidate_edges(named, on_curve);
    // The structures below are over the candidates' points alone, renamed to their
    // positions among them (over all points, they were most of the repair's time on large,
    // nearly clean inputs). The renaming keeps the order, so edges stay `[min, max]`, sorted,
    // and a group's smallest point is still its root. Positions are `u32`, no local points.
    let mut members: Vec<LocalPoint> = candidates.iter().flatten().copied().collect();
    members.sort_unstable();
    members.dedup();
    let position = |p: LocalPoint| members.binary_search(&p).unwrap_or_default() as u32;
    let mut renamed: Vec<[u32; 2]> = candidates
        .iter()
        .map(|&[a, b]| [position(a), position(b)])
        .collect();
    let members_on_curve: Vec<bool> = members.iter().map(|&p| on_curve[p.index()]).collect();
    without_loose_ends(&mut renamed, &members_on_curve);
    if renamed.is_empty() {
        return Vec::new();
    }
    let mut groups = UnionFind::new(members.len());
    for &[a, b] in &renamed {
        groups.union(a, b);
    }
    // Sorted by root, the smallest point of the group: the groups in the order of it.
    let mut keyed: Vec<(u32, [u32; 2])> = renamed.iter().map(|&e| (groups.find(e[0]), e)).collect();
    keyed.sort_unstable();
    let named = |p: u32| members[p as usize];
    keyed
        .chunk_by(|x, y| x.0 == y.0)
        .map(|group| {
            group
                .iter()
                .map(|&(_, [a, b])| [named(a), named(b)])
                .collect::<Group>()
        })
        .filter(|group| (2..=MAX_ANCHORS).contains(&anchors(group, on_curve).len()))
        .collect()
}

/// The points of a group that are on a curve, sorted.
fn anchors(group: &[[LocalPoint; 2]], on_curve: &[bool]) -> Vec<LocalPoint> {
    let mut anchors: Vec<LocalPoint> = group
        .iter()
        .flatten()
        .copied()
        .filter(|&p| on_curve[p.index()])
        .collect();
    anchors.sort_unstable();
    anchors.dedup();
    anchors
}

/// Step 2 for one group: every pair of its points on a curve, in order, whose bottleneck
/// path through the group's unassigned points (not taken by an earlier swap of the group)
/// replaces a detour between them; each swap is made at once. Whether any was made.
fn swap_detours(
    named: &mut NeighbourNames<'_, '_>,
    curves: &mut EditedCurves,
    on_curve: &[bool],
    group: &Group,
) -> bool {
    let vor = named.vor;
    let mut around: BTreeMap<LocalPoint, Vec<LocalPoint>> = BTreeMap::new();
    for &[a, b] in group {
        around.entry(a).or_default().push(b);
        around.entry(b).or_default().push(a);
    }
    for neighbours in around.values_mut() {
        neighbours.sort_unstable();
    }
    let rank = length_ranks(vor, group);
    let passable =
        |p: LocalPoint, taken: &BTreeSet<LocalPoint>| !on_curve[p.index()] && !taken.contains(&p);
    let mut taken: BTreeSet<LocalPoint> = BTreeSet::new();
    let anchors = anchors(group, on_curve);
    for (i, &a) in anchors.iter().enumerate() {
        // Walked when a later anchor first asks (the last anchor of a group never does).
        let mut chains: Option<Vec<Vec<LocalPoint>>> = None;
        let mut tree: Option<BTreeMap<LocalPoint, LocalPoint>> = None;
        for &b in &anchors[i + 1..] {
            let walked = chains.get_or_insert_with(|| chains_from(curves, a));
            let Some(detour) = detour_to(walked, b) else {
                continue;
            };
            // One search from `a` serves all its pairs until a swap takes points.
            let tree = tree.get_or_insert_with(|| {
                bottleneck_tree(
                    &around,
                    &rank,
                    |p| passable(p, &taken),
                    a,
                    &anchors[i + 1..],
                )
            });
            let Some(stretch) = path_in(tree, a, b) else {
                continue;
            };
            if longest_edge_order(vor, &stretch, &detour) == std::cmp::Ordering::Less {
                taken.extend(stretch.iter().flatten().copied());
                curves.swap(&Swap { stretch, detour });
                chains = Some(chains_from(curves, a));
                *tree = bottleneck_tree(
                    &around,
                    &rank,
                    |p| passable(p, &taken),
                    a,
                    &anchors[i + 1..],
                );
            }
        }
    }
    !taken.is_empty()
}

/// The order of the longest edge of `first` and of `second` (non-empty), exact.
fn longest_edge_order(
    vor: &Voronoi<'_>,
    first: &[[LocalPoint; 2]],
    second: &[[LocalPoint; 2]],
) -> std::cmp::Ordering {
    let points = &vor.triangulation().points;
    let at = |i: LocalPoint| points[i.index()];
    let order = |e: &[LocalPoint; 2], f: &[LocalPoint; 2]| {
        length_order(at(e[0]), at(e[1]), at(f[0]), at(f[1]))
    };
    let longest = |edges: &[[LocalPoint; 2]]| {
        edges
            .iter()
            .copied()
            .max_by(|e, f| order(e, f))
            .unwrap_or([LocalPoint::new(0); 2])
    };
    order(&longest(first), &longest(second))
}

/// The rank of every edge of `group` by length, shortest first (exact; ties by the points).
fn length_ranks(vor: &Voronoi<'_>, group: &Group) -> BTreeMap<[LocalPoint; 2], u32> {
    let points = &vor.triangulation().points;
    let at = |i: LocalPoint| points[i.index()];
    let mut sorted = group.clone();
    sorted.sort_by(|&[a, b], &[c, d]| {
        length_order(at(a), at(b), at(c), at(d)).then_with(|| [a, b].cmp(&[c, d]))
    });
    sorted.into_iter().zip(0..).collect()
}

/// Bottleneck paths from `a` through `around` whose inner points are `passable`: the longest
/// edge shortest (by `rank`), then fewest edges (Dijkstra on these keys, ties by the points),
/// until every point of `targets` is reached. Each reached point's predecessor.
fn bottleneck_tree(
    around: &BTreeMap<LocalPoint, Vec<LocalPoint>>,
    rank: &BTreeMap<[LocalPoint; 2], u32>,
    passable: impl Fn(LocalPoint) -> bool,
    a: LocalPoint,
    targets: &[LocalPoint],
) -> BTreeMap<LocalPoint, LocalPoint> {
    // The best cost found so far to a point, (rank of the longest edge, edges), and from where.
    let mut best: BTreeMap<LocalPoint, ((u32, u32), LocalPoint)> =
        BTreeMap::from([(a, ((0, 0), a))]);
    let mut queue = BinaryHeap::from([Reverse(((0u32, 0u32), a))]);
    let mut settled: BTreeMap<LocalPoint, LocalPoint> = BTreeMap::new();
    let mut left = targets.len();
    while let Some(Reverse((cost, p))) = queue.pop() {
        if settled.contains_key(&p) {
            continue;
        }
        settled.insert(p, best[&p].1);
        if targets.contains(&p) {
            left -= 1;
            if left == 0 {
                break;
            }
            continue;
        }
        if p != a && !passable(p) {
            continue;
        }
        for &q in around.get(&p).into_iter().flatten() {
            let next = (cost.0.max(rank[&[p.min(q), p.max(q)]]), cost.1 + 1);
            if !settled.contains_key(&q) && best.get(&q).is_none_or(|&(c, _)| next < c) {
                best.insert(q, (next, p));
                queue.push(Reverse((next, q)));
            }
        }
    }
    settled
}

/// The path from `a` to `b` in a [`bottleneck_tree`] from `a`, as sorted edges.
fn path_in(
    tree: &BTreeMap<LocalPoint, LocalPoint>,
    a: LocalPoint,
    b: LocalPoint,
) -> Option<Vec<[LocalPoint; 2]>> {
    let mut path = Vec::new();
    let mut at = b;
    while at != a {
        let previous = *tree.get(&at)?;
        path.push([at.min(previous), at.max(previous)]);
        at = previous;
    }
    path.sort_unstable();
    Some(path)
}

/// The points along the curves from `a` in each direction of its two curve edges, `a`
/// first, up to [`MAX_DETOUR_POINTS`] inner points on, as far as every inner point has
/// degree 2 (empty when `a` does not have two curve edges).
fn chains_from(curves: &EditedCurves, a: LocalPoint) -> Vec<Vec<LocalPoint>> {
    let Some([x, y]) = curves.two_neighbours(a) else {
        return Vec::new();
    };
    [x, y]
        .into_iter()
        .map(|first| {
            let mut chain = vec![a, first];
            // The last point may be a detour's far end, inner points need degree 2.
            while chain.len() <= MAX_DETOUR_POINTS + 1 {
                let (previous, at) = (chain[chain.len() - 2], chain[chain.len() - 1]);
                let Some([x, y]) = curves.two_neighbours(at) else {
                    break;
                };
                let next = if x == previous { y } else { x };
                if next == a {
                    break;
                }
                chain.push(next);
            }
            chain
        })
        .collect()
}

/// The detour a swap between `a` and `b` replaces, given `a`'s [`chains_from`]: the chain
/// that reaches `b`, when exactly one does, as edges.
fn detour_to(chains: &[Vec<LocalPoint>], b: LocalPoint) -> Option<Vec<[LocalPoint; 2]>> {
    let mut reaching = chains
        .iter()
        .filter_map(|chain| chain.iter().position(|&p| p == b).map(|end| &chain[..=end]));
    let chain = reaching.next()?;
    if reaching.next().is_some() {
        return None;
    }
    Some(
        chain
            .windows(2)
            .map(|w| [w[0].min(w[1]), w[0].max(w[1])])
            .collect(),
    )
}

/// Candidate edges of step 1 (module docs), sorted.
fn candidate_edges(named: &mut NeighbourNames<'_, '_>, on_curve: &[bool]) -> Vec<[LocalPoint; 2]> {
    let mut candidates = Vec::new();
    for p in ids::<LocalPoint>(on_curve.len()) {
        if on_curve[p.index()] {
            continue;
        }
        let names = named.of(p);
        for q in named.around(p) {
            // The names of a curve point are never asked (their computation is the cost).
            let named_by_unassigned = names.contains(&Some(q))
                || (!on_curve[q.index()] && named.of(q).contains(&Some(p)));
            if named_by_unassigned {
                candidates.push([p.min(q), p.max(q)]);
            }
        }
    }
    candidates.sort_unstable();
    candidates.dedup();
    candidates
}

/// Removes, repeatedly, the edges with an unassigned end that no other edge touches: what is
/// left of a group joins points on curves through unassigned points. On the group's
/// positions among its members (`u32`), as `stretches` renames them.
fn without_loose_ends(edges: &mut Vec<[u32; 2]>, on_curve: &[bool]) {
    if edges.is_empty() {
        return;
    }
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
/// the unassigned points and those they name are ever asked, so they are kept in a map (an
/// array over all points was 16 bytes a point at the memory peak of this phase).
struct NeighbourNames<'v, 't> {
    vor: &'v Voronoi<'t>,
    cache: HashMap<LocalPoint, [Option<LocalPoint>; 2]>,
}

impl<'v, 't> NeighbourNames<'v, 't> {
    fn new(vor: &'v Voronoi<'t>) -> Self {
        NeighbourNames {
            vor,
            cache: HashMap::new(),
        }
    }

    /// The Delaunay neighbours of `p` along edges with a dual Voronoi edge.
    fn around(&self, p: LocalPoint) -> impl Iterator<Item = LocalPoint> + Clone + 'v {
        self.vor.dual_neighbours(p)
    }

    /// `[nearest, half]` neighbour of `p` among its Delaunay neighbours along edges with a
    /// dual Voronoi edge (the NN-crust's candidates, so cocircular diagonals never count).
    fn of(&mut self, p: LocalPoint) -> [Option<LocalPoint>; 2] {
        if let Some(&names) = self.cache.get(&p) {
            return names;
        }
        let points = &self.vor.triangulation().points;
        let at = |i: LocalPoint| points[i.index()];
        let around = self.around(p);
        let nearest = |candidates: &mut dyn Iterator<Item = LocalPoint>| {
            candidates.min_by(|&a, &b| closer(at(p), at(a), at(b)))
        };
        let q = nearest(&mut around.clone());
        let half = q.and_then(|q| {
            nearest(&mut around.filter(|&s| dot_sign(at(p), at(s), at(q)) == Sign::Negative))
        });
        self.cache.insert(p, [q, half]);
        [q, half]
    }
}

/// Union–find over positions (those of `stretches`); the root of a group is its smallest member, so it does
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
pub(crate) mod tests {
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
    /// The whole repair on `edges` (caller indices of `points`), sorted.
    pub(in crate::reconstruct) fn repaired(
        points: &[[f64; 2]],
        edges: &[[u32; 2]],
    ) -> Vec<[u32; 2]> {
        let tri = triangulate(points).unwrap();
        let vor = tri.voronoi();
        let mut local: Vec<[LocalPoint; 2]> = edges
            .iter()
            .map(|&[a, b]| {
                let (a, b) = (tri.local_index(a), tri.local_index(b));
                [a.min(b), a.max(b)]
            })
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
    fn a_detour_through_six_outliers_is_swapped_for_the_skipped_stretch() {
        // Six outliers outside the arc 3 … 7; the curve runs 3 → 24 → … → 29 → 7. (The
        // earlier rule took detours of at most 4 outliers.)
        let out = |t: f64, r: f64| [r * (t * TAU / 24.0).cos(), r * (t * TAU / 24.0).sin()];
        let extra: Vec<[f64; 2]> = (0..6).map(|k| out(3.3 + k as f64 * 0.7, 1.8)).collect();
        let points = circle_with(&extra);
        let edges = polygon_with_detour(3, 7, &[24, 25, 26, 27, 28, 29]);
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
        assert_repaired_alike_in_any_order(&points, &edges, &expected, 5);
    }

    /// [`repaired`] on ten shuffles of `points` (edges renamed along) gives `expected`.
    pub(in crate::reconstruct) fn assert_repaired_alike_in_any_order(
        points: &[[f64; 2]],
        edges: &[[u32; 2]],
        expected: &[[u32; 2]],
        seed: u64,
    ) {
        let mut rng = wdm_crust_testkit::Rng::new(seed);
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
