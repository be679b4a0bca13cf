//! Open curves beside closed ones: the loops the water flow is sure of are kept, and every
//! other point is joined into chains by proximity.
//!
//! The water flow separates inner from outer Voronoi vertices, so every boundary it draws
//! is closed: on an open curve it closes a loop through a chord, wraps a thin loop around
//! both sides of the samples, leaves the points untouched, or meets itself at junctions.
//! This stage reads the result of the passes before it and settles it into curves that are
//! 1-manifold (no point on more than two edges):
//!
//! 1. **Sure loops.** A loop of the flow is kept when it is a simple cycle and none of its
//!    edges is a *chord*: longer than [`CHORD_DOUBLINGS`] doublings of each of the two loop
//!    edges on one side of it and [`CHORD_SIDE_DOUBLINGS`] doublings of the two on the other
//!    (a chord from a dense curve to a sparse one), and than [`CHORD_OUTLIER_DOUBLINGS`] doublings of
//!    the loop's longest ordinary edge (a closed curve sampled at random positions has gaps
//!    8× their neighbours by chance, among ordinary gaps nearly as long); or, whatever its
//!    neighbours, longer than [`LONE_CHORD_DOUBLINGS`] doublings of every other edge of the
//!    loop (noise makes the steps beside a gap uneven). A loop the flow closes around an open curve
//!    crosses from one end to the other, many sample spacings long beside steps of one
//!    spacing; a closed curve's loop has no such edge, whatever its corners, its sampling
//!    density (the ε = 1.2 samples of the quality benchmark) or its noise (two edges on each
//!    side, because noise puts samples next to each other). Every point of a loop that is
//!    not sure goes on to the next rule.
//! 2. **Chains.** Every point on no sure loop proposes its nearest neighbour and its half
//!    neighbour among such points ([`DelaunayGraph::proposal`]). A proposed edge longer than
//!    [`GAP_DOUBLINGS`] doublings of the nearest-neighbour distance at both ends is a gap
//!    between two curves, not a step along one, and is dropped. The rest are taken greedily,
//!    edges proposed by both ends first, shorter before longer, each only while both its
//!    points have fewer than two edges: so no point gets a third. An edge between the two
//!    ends of one chain closes it into a loop only when the chain has at least
//!    [`MIN_CLOSED_POINTS`] points. Then the ends left (noise turns a step away from both
//!    its ends' proposals now and then) join the Delaunay neighbours that are ends too or on
//!    no chain and choose each other as nearest, under the same rules, when the join is at
//!    most [`JOIN_DOUBLINGS`] doublings of the chain's step at each end it joins, or at most
//!    [`GAP_JOIN_DOUBLINGS`] doublings of the longest step of either chain it joins (samples
//!    at random positions leave gaps far longer than the steps beside them); in rounds while
//!    any pair joins. A loop so closed loses its chords (rule 1's test): an end's half
//!    neighbour can be the other end across an open curve's gap. Where noise interleaves the
//!    samples of a sharp corner's two sides, an end and the sample before it swap places to
//!    join the other side's end ([`swap_interleaved_ends`]).
//! 3. **Junk.** A piece is a curve when it has at least [`MIN_CHAIN_POINTS`] points and at
//!    least three quarters of them are *isolated*: every Delaunay neighbour off the piece is
//!    farther than [`ISOLATION_DOUBLINGS`] doublings of the point's longer step along it. A
//!    sampled curve is nearer to itself than to anything else; a chain drawn through a
//!    scatter of outliers or through the leftovers of a noise band beside a loop is not.
//!    The points of other pieces stay unassigned.
//! 4. **Loops beside chains.** A sure loop that a chain runs beside (more than a quarter of
//!    its points have a chain point within [`ISOLATION_DOUBLINGS`] doublings of their longer
//!    loop step) is a thin loop the flow wrapped around part of an open curve's samples,
//!    among noise: it is dissolved, and the chains are drawn again with its points. So is a
//!    loop that a chain ends beside, nearer to one of its points than that point's longer
//!    loop step: the chain goes on along the loop, which the flow closed around the end of
//!    the same open curve. A dissolved loop whose points proximity then leaves in more than
//!    [`MAX_DISSOLVED_PIECES`] pieces (or a quarter of them on none) is put back for good:
//!    the chain was noise left beside a closed curve, and a chain of fewer than twice
//!    [`MIN_CHAIN_POINTS`] points ending beside such a loop is dropped as a stub of it.
//! 5. **The flow's paths.** Where a loop with chords lies on points that proximity joined
//!    into no curve (a noisy scan of an open curve, whose chains are no isolated curves),
//!    the loop's paths between its chords are kept, each run of at least
//!    [`MIN_CHAIN_POINTS`] such points an open chain.
//!
//! Every decision is exact: distances are compared by the kernel, the length ratios are
//! powers of two, ties fall to the local indices, which follow the coordinates (the Z
//! order), never the input order.

use std::cmp::Ordering;

use super::curves::lone_longest_edge;
use super::proximity::{closer, DelaunayGraph, Proposal};
use super::thresholds::open_curves::{
    CHORD_DOUBLINGS, CHORD_OUTLIER_DOUBLINGS, CHORD_SIDE_DOUBLINGS, GAP_DOUBLINGS,
    GAP_JOIN_DOUBLINGS, ISOLATION_DOUBLINGS, JOIN_DOUBLINGS, LONE_CHORD_DOUBLINGS,
    MAX_DISSOLVED_PIECES, MIN_CHAIN_POINTS, MIN_CLOSED_POINTS,
};
use crate::delaunay::Triangulation;
use crate::ids::{ids, LocalPoint};
use crate::kernel::metric::{length_order, scaled_length_order};
use crate::voronoi::Voronoi;

/// At most this many rounds of joins of chain ends: each round joins the mutual nearest
/// ends; a curve broken at several random gaps needs a round for each gap that only a grown
/// chain's longest step admits.
const MAX_JOIN_ROUNDS: usize = 8;

/// No loop, no position on one.
const NONE: u32 = u32::MAX;

/// No point (no neighbour along a chain or loop, no piece, no choice).
const NO_POINT: LocalPoint = LocalPoint::new(u32::MAX);

/// The edges of `edges` (local, distinct, `[a, b]` with `a < b`) settled into sure loops
/// and proximity chains, every point on at most two edges; in no particular order (the
/// curves are assembled from them).
pub(super) fn settle(
    tri: &Triangulation,
    vor: &Voronoi<'_>,
    edges: &[[LocalPoint; 2]],
) -> Vec<[LocalPoint; 2]> {
    let points = &tri.points;
    let n = points.len();
    let mut loops = sure_loops(points, edges);
    if loops.of.iter().filter(|&&l| l == NONE).count() < MIN_CHAIN_POINTS {
        // (Nearly) every point on a sure loop, the samples of closed curves: too few points
        // left for any chain or any path of the flow's.
        return loops.edges_of(edges);
    }
    // Each round joins the free points into chains; a loop that a chain runs beside is
    // dissolved and its points join the next round (rule 4). At most one round a loop.
    let (chain_edges, graph) = loop {
        let free = |p: LocalPoint| loops.of[p.index()] == NONE;
        // The Delaunay neighbours of the free points only: few on closed curves.
        let listed: Vec<LocalPoint> = ids::<LocalPoint>(n).filter(|&p| free(p)).collect();
        let graph = DelaunayGraph::of_points(vor, &listed);
        let chain_edges = chains(&graph, points, &free);
        // A loop dissolved in the round before whose points proximity cannot draw as a few
        // curves is restored, for good: the flow's loop was the better reading.
        let failed = loops.failed_dissolutions(n, &chain_edges);
        if !failed.is_empty() {
            for l in failed {
                loops.restore(l);
            }
            continue;
        }
        let beside = loops_beside_chains(&graph, points, &chain_edges, &loops);
        if beside.is_empty() {
            break (chain_edges, graph);
        }
        for l in beside {
            loops.dissolve(l);
        }
    };
    let chain_edges = without_stubs_of_restored_loops(&graph, points, chain_edges, &loops);
    let mut kept: Vec<[LocalPoint; 2]> = edges
        .iter()
        .copied()
        .filter(|e| {
            loops.of[e[0].index()] != NONE && loops.of[e[0].index()] == loops.of[e[1].index()]
        })
        .collect();
    // Rule 5: the flow's paths between chords where proximity drew no curve.
    let mut on_chain = vec![false; n];
    for &p in chain_edges.iter().flatten() {
        on_chain[p.index()] = true;
    }
    kept.extend(chain_edges);
    for path in &loops.fallbacks {
        for run in path.split(|&p| on_chain[p.index()] || loops.of[p.index()] != NONE) {
            if run.len() >= MIN_CHAIN_POINTS {
                kept.extend(run.windows(2).map(|w| [w[0].min(w[1]), w[0].max(w[1])]));
            }
        }
    }
    debug_assert!({
        let mut degree = vec![0u8; n];
        kept.iter().flatten().all(|&p| {
            degree[p.index()] += 1;
            degree[p.index()] <= 2
        })
    });
    kept
}

/// The edges of `edges` on those sure loops of `edges` (rule 1 of the module docs) that
/// `keep` accepts (given their points in order): what a scatter keeps (`scatter`), whose
/// leftovers hold no curves for proximity to draw.
pub(super) fn sure_loop_edges(
    points: &[[f64; 2]],
    edges: &[[LocalPoint; 2]],
    keep: impl Fn(&[LocalPoint]) -> bool,
) -> Vec<[LocalPoint; 2]> {
    let loops = sure_loops(points, edges);
    let kept: Vec<bool> = loops.cycles.iter().map(|c| keep(c)).collect();
    edges
        .iter()
        .copied()
        .filter(|e| {
            let l = loops.of[e[0].index()];
            l != NONE && kept[l as usize]
        })
        .collect()
}

/// The sure loops (rule 1 of the module docs): each loop's points in order, and the loop of
/// every point (`NONE` when free).
struct SureLoops {
    cycles: Vec<Vec<LocalPoint>>,
    of: Vec<u32>,
    /// The paths that the loops with chords leave without them (rule 5).
    fallbacks: Vec<Vec<LocalPoint>>,
    /// The loops dissolved since their dissolutions were last checked.
    dissolved: Vec<u32>,
    /// Whether a loop was restored after a dissolution that failed (never dissolved again).
    restored: Vec<bool>,
}

impl SureLoops {
    /// Each point's position on its loop (`NONE` when on none), for `longer_step`.
    fn positions(&self, n: usize) -> Vec<u32> {
        let mut position = vec![NONE; n];
        for cycle in &self.cycles {
            for (i, &p) in cycle.iter().enumerate() {
                position[p.index()] = i as u32;
            }
        }
        position
    }

    /// The edges of `edges` on a sure loop.
    fn edges_of(&self, edges: &[[LocalPoint; 2]]) -> Vec<[LocalPoint; 2]> {
        edges
            .iter()
            .copied()
            .filter(|e| self.of[e[0].index()] != NONE)
            .collect()
    }

    fn dissolve(&mut self, l: u32) {
        for &p in &self.cycles[l as usize] {
            self.of[p.index()] = NONE;
        }
        self.dissolved.push(l);
    }

    /// Puts loop `l` back; it is never dissolved again.
    fn restore(&mut self, l: u32) {
        for &p in &self.cycles[l as usize] {
            self.of[p.index()] = l;
        }
        self.restored[l as usize] = true;
    }

    /// The loops dissolved since the last call whose points the chains `chain_edges` leave
    /// in more than [`MAX_DISSOLVED_PIECES`] pieces, or more than a quarter of them on no
    /// chain: a loop dissolved for a chain beside it is expected to become that chain's curve
    /// (or two curves), and a clean loop among noise leftovers falls apart instead.
    fn failed_dissolutions(&mut self, n: usize, chain_edges: &[[LocalPoint; 2]]) -> Vec<u32> {
        let dissolved = std::mem::take(&mut self.dissolved);
        if dissolved.is_empty() {
            return dissolved;
        }
        let mut pieces = Pieces::of(n, chain_edges);
        let mut on_chain = vec![false; n];
        for &p in chain_edges.iter().flatten() {
            on_chain[p.index()] = true;
        }
        dissolved
            .into_iter()
            .filter(|&l| {
                let cycle = &self.cycles[l as usize];
                let mut roots: Vec<LocalPoint> = cycle
                    .iter()
                    .filter(|&&p| on_chain[p.index()])
                    .map(|&p| pieces.root(p))
                    .collect();
                let placed = roots.len();
                roots.sort_unstable();
                roots.dedup();
                roots.len() > MAX_DISSOLVED_PIECES || 4 * (cycle.len() - placed) > cycle.len()
            })
            .collect()
    }

    /// The longer of the two loop edges at `p`, as its far end.
    fn longer_step(&self, points: &[[f64; 2]], p: LocalPoint, position: &[u32]) -> LocalPoint {
        let cycle = &self.cycles[self.of[p.index()] as usize];
        let (k, i) = (cycle.len(), position[p.index()] as usize);
        let (a, b) = (cycle[(i + 1) % k], cycle[(i + k - 1) % k]);
        let at = |i: LocalPoint| points[i.index()];
        if length_order(at(p), at(a), at(p), at(b)) == Ordering::Less {
            b
        } else {
            a
        }
    }
}

/// Which points lie on a sure loop of `edges` (rule 1 of the module docs).
fn sure_loops(points: &[[f64; 2]], edges: &[[LocalPoint; 2]]) -> SureLoops {
    let n = points.len();
    let mut loops = SureLoops {
        cycles: Vec::new(),
        of: vec![NONE; n],
        fallbacks: Vec::new(),
        dissolved: Vec::new(),
        restored: Vec::new(),
    };
    for cycle in simple_cycles(n, edges) {
        let chords = chords(points, &cycle);
        if chords.is_empty() {
            let l = loops.cycles.len() as u32;
            for &p in &cycle {
                loops.of[p.index()] = l;
            }
            loops.cycles.push(cycle);
            loops.restored.push(false);
        } else {
            // The loop between its chords, from the end of one to the start of the next.
            for (c, &i) in chords.iter().enumerate() {
                let j = chords[(c + 1) % chords.len()];
                let length = (j + cycle.len() - i - 1) % cycle.len() + 1;
                let path = (1..=length).map(|d| cycle[(i + d) % cycle.len()]).collect();
                loops.fallbacks.push(path);
            }
        }
    }
    loops
}

/// The simple cycles of `edges` among `n` points (components whose points all have two
/// edges), each as its points in order.
fn simple_cycles(n: usize, edges: &[[LocalPoint; 2]]) -> Vec<Vec<LocalPoint>> {
    // The two neighbours of every point of degree at most 2; degree above 2 marked.
    let mut next = vec![[NO_POINT; 2]; n];
    let mut degree = vec![0u32; n];
    for &[a, b] in edges {
        for (p, q) in [(a, b), (b, a)] {
            let d = degree[p.index()];
            if d < 2 {
                next[p.index()][d as usize] = q;
            }
            degree[p.index()] = d + 1;
        }
    }
    let mut cycles = Vec::new();
    let mut seen = vec![false; n];
    for start in ids::<LocalPoint>(n) {
        if seen[start.index()] || degree[start.index()] != 2 {
            continue;
        }
        // Walk from `start`; a simple cycle returns to it through degree-2 points only.
        let mut cycle = vec![start];
        let (mut prev, mut at) = (start, next[start.index()][0]);
        seen[start.index()] = true;
        let mut simple = true;
        while at != start {
            if degree[at.index()] != 2 || seen[at.index()] {
                simple = false;
                break;
            }
            seen[at.index()] = true;
            cycle.push(at);
            let [x, y] = next[at.index()];
            (prev, at) = (at, if x == prev { y } else { x });
        }
        if simple {
            cycles.push(cycle);
        }
    }
    cycles
}

/// `edges` (each point on at most two) without the chords of their loops (rule 1's test on
/// the loops that proximity closed): the half neighbour of a chain's end can be its other
/// end across the gap of an open curve, shorter than a gap between curves.
fn without_chords(points: &[[f64; 2]], mut edges: Vec<[LocalPoint; 2]>) -> Vec<[LocalPoint; 2]> {
    let mut chords_of_loops: Vec<[LocalPoint; 2]> = simple_cycles(points.len(), &edges)
        .into_iter()
        .flat_map(|cycle| {
            let k = cycle.len();
            chords(points, &cycle)
                .into_iter()
                .map(move |i| {
                    let (a, b) = (cycle[i], cycle[(i + 1) % k]);
                    [a.min(b), a.max(b)]
                })
                .collect::<Vec<_>>()
        })
        .collect();
    if !chords_of_loops.is_empty() {
        chords_of_loops.sort_unstable();
        edges.retain(|e| chords_of_loops.binary_search(e).is_err());
    }
    edges
}

/// `chain_edges` without the short chains that end beside a loop put back (rule 4 of the
/// module docs): fewer than twice [`MIN_CHAIN_POINTS`] points, an end nearer to a point of
/// such a loop than that point's longer loop step. The loop was dissolved for them and could
/// not be drawn again without it: they are a stub of its noise, not the rest of its curve.
fn without_stubs_of_restored_loops(
    graph: &DelaunayGraph,
    points: &[[f64; 2]],
    chain_edges: Vec<[LocalPoint; 2]>,
    loops: &SureLoops,
) -> Vec<[LocalPoint; 2]> {
    if chain_edges.is_empty() || !loops.restored.iter().any(|&r| r) {
        return chain_edges;
    }
    let n = points.len();
    let at = |i: LocalPoint| points[i.index()];
    let position = loops.positions(n);
    let mut pieces = Pieces::of(n, &chain_edges);
    let mut degree = vec![0u8; n];
    for &p in chain_edges.iter().flatten() {
        degree[p.index()] += 1;
    }
    let mut stub = vec![false; n];
    for &c in chain_edges.iter().flatten() {
        if degree[c.index()] != 1 {
            continue;
        }
        let beside = graph.neighbours(c).iter().any(|&p| {
            let l = loops.of[p.index()];
            l != NONE && loops.restored[l as usize] && {
                let step = loops.longer_step(points, p, &position);
                length_order(at(p), at(c), at(p), at(step)) == Ordering::Less
            }
        });
        if beside {
            let root = pieces.root(c);
            stub[root.index()] = true;
        }
    }
    chain_edges
        .into_iter()
        .filter(|&[a, _]| {
            let root = pieces.root(a);
            !(stub[root.index()] && (pieces.size[root.index()] as usize) < 2 * MIN_CHAIN_POINTS)
        })
        .collect()
}

/// The loops still sure that a chain runs beside (rule 4 of the module docs): more than a
/// quarter of their points have a chain point as Delaunay neighbour within
/// `2^ISOLATION_DOUBLINGS` times their longer loop step.
fn loops_beside_chains(
    graph: &DelaunayGraph,
    points: &[[f64; 2]],
    chain_edges: &[[LocalPoint; 2]],
    loops: &SureLoops,
) -> Vec<u32> {
    if chain_edges.is_empty() {
        return Vec::new();
    }
    let n = points.len();
    let position = loops.positions(n);
    let at = |i: LocalPoint| points[i.index()];
    let mut crowded = vec![false; n];
    let mut count = vec![0usize; loops.cycles.len()];
    let mut on_chain = vec![false; n];
    let mut chain_degree = vec![0u8; n];
    for &c in chain_edges.iter().flatten() {
        chain_degree[c.index()] += 1;
    }
    let mut continued = vec![false; loops.cycles.len()];
    for &c in chain_edges.iter().flatten() {
        if std::mem::replace(&mut on_chain[c.index()], true) {
            continue;
        }
        // A chain that ends nearer to a loop point than that point's longer loop step
        // goes on along the loop: one curve, which the flow closed around its end.
        if chain_degree[c.index()] == 1 {
            for &p in graph.neighbours(c) {
                let l = loops.of[p.index()];
                if l != NONE {
                    let step = loops.longer_step(points, p, &position);
                    if length_order(at(p), at(c), at(p), at(step)) == Ordering::Less {
                        continued[l as usize] = true;
                    }
                }
            }
        }
        for &p in graph.neighbours(c) {
            let l = loops.of[p.index()];
            if l == NONE || crowded[p.index()] {
                continue;
            }
            let step = loops.longer_step(points, p, &position);
            if scaled_length_order(at(p), at(c), at(p), at(step), ISOLATION_DOUBLINGS)
                != Ordering::Greater
            {
                crowded[p.index()] = true;
                count[l as usize] += 1;
            }
        }
    }
    (0..loops.cycles.len() as u32)
        .filter(|&l| {
            let cycle = &loops.cycles[l as usize];
            loops.of[cycle[0].index()] == l
                && !loops.restored[l as usize]
                && (continued[l as usize] || 4 * count[l as usize] > cycle.len())
        })
        .collect()
}

/// The chords of the simple cycle `cycle` (its points in order), by position (edge `i`
/// joins positions `i` and `i + 1`): edges longer than `2^CHORD_DOUBLINGS` times each of the
/// two loop edges before them and the two after them (rule 1). (Two edges on each side, not
/// one nor the nearest-neighbour distance: noise puts samples next to each other, and one
/// short step beside an ordinary one is no chord. A median over a wider window or the whole
/// loop was measured and broke the loops of real noisy scans, whose spacing varies.)
pub(crate) fn chords(points: &[[f64; 2]], cycle: &[LocalPoint]) -> Vec<usize> {
    let k = cycle.len();
    let at = |i: usize| points[cycle[i % k].index()];
    // Each edge's squared length in rounded arithmetic decides where it is far from the
    // bound (every edge of a closed curve against its first neighbour); the kernel decides
    // the rest exactly.
    let squared: Vec<f64> = (0..k)
        .map(|i| {
            let (p, q) = (at(i), at(i + 1));
            let (dx, dy) = (p[0] - q[0], p[1] - q[1]);
            dx * dx + dy * dy
        })
        .collect();
    let longer_by = |i: usize, j: usize, doublings: u32| {
        let (a, b) = (squared[i], f64::from(4u32.pow(doublings)) * squared[j % k]);
        // Each rounded square is within 4 units of the exact one while nothing overflows or
        // nears the subnormal range; 16 units of margin cover both and the product.
        let normal = |d: f64| d.is_finite() && d > 1e-280;
        if normal(a) && normal(b) {
            const MARGIN: f64 = 16.0 * f64::EPSILON;
            if a > b * (1.0 + MARGIN) {
                return true;
            }
            if a < b * (1.0 - MARGIN) {
                return false;
            }
        }
        let j = j % k;
        scaled_length_order(at(i), at(i + 1), at(j), at(j + 1), doublings) == Ordering::Greater
    };
    let longer = |i: usize, j: usize| longer_by(i, j, CHORD_DOUBLINGS);
    // Long against the two edges on one side and, by a smaller factor, the two on the other:
    // a chord from a densely sampled curve to a sparser one is many of the dense curve's
    // steps but fewer of the sparse one's.
    let before = |i: usize, d: u32| longer_by(i, i + k - 1, d) && longer_by(i, i + k - 2, d);
    let after = |i: usize, d: u32| longer_by(i, i + 1, d) && longer_by(i, i + 2, d);
    let locally_long: Vec<usize> = (0..k)
        .filter(|&i| {
            (before(i, CHORD_DOUBLINGS) && after(i, CHORD_SIDE_DOUBLINGS))
                || (before(i, CHORD_SIDE_DOUBLINGS) && after(i, CHORD_DOUBLINGS))
        })
        .collect();
    if locally_long.is_empty() {
        // Whatever its neighbours, an edge alone in its length: noise makes the steps beside
        // an open curve's gap uneven.
        return lone_longest_edge(points, cycle, LONE_CHORD_DOUBLINGS)
            .map(|(longest, _)| longest)
            .into_iter()
            .collect();
    }
    // A candidate is a chord only when it also stands out of the whole loop: longer than
    // `2^CHORD_OUTLIER_DOUBLINGS` times the loop's longest *ordinary* edge, one no longer
    // than `2^CHORD_DOUBLINGS` times any of its four neighbours (an edge beside a chord is
    // long without being a candidate). Picked exactly; none when no edge is ordinary.
    let ordinary = |i: usize| (1..=2).all(|d| !longer(i, i + k - d) && !longer(i, i + d));
    let longest_ordinary = (0..k).filter(|&i| ordinary(i)).reduce(|a, b| {
        match length_order(at(a), at(a + 1), at(b), at(b + 1)) {
            Ordering::Less => b,
            _ => a,
        }
    });
    let Some(ordinary) = longest_ordinary else {
        return locally_long;
    };
    locally_long
        .into_iter()
        .filter(|&i| {
            scaled_length_order(
                at(i),
                at(i + 1),
                at(ordinary),
                at(ordinary + 1),
                CHORD_OUTLIER_DOUBLINGS,
            ) == Ordering::Greater
        })
        .collect()
}

/// Whether `pq` is longer than `2^doublings` times the nearest-neighbour distance at both
/// `p` and `q` (their proposals `at_p`, `at_q`).
fn is_long(
    points: &[[f64; 2]],
    p: LocalPoint,
    q: LocalPoint,
    at_p: Proposal,
    at_q: Proposal,
    doublings: u32,
) -> bool {
    let at = |i: LocalPoint| points[i.index()];
    let longer_than = |from: LocalPoint, nearest: Option<LocalPoint>| {
        nearest.is_some_and(|m| {
            scaled_length_order(at(p), at(q), at(from), at(m), doublings) == Ordering::Greater
        })
    };
    longer_than(p, at_p.nearest) && longer_than(q, at_q.nearest)
}

/// The chain edges among the points on no sure loop (rules 2 and 3 of the module docs).
fn chains(
    graph: &DelaunayGraph,
    points: &[[f64; 2]],
    free: &dyn Fn(LocalPoint) -> bool,
) -> Vec<[LocalPoint; 2]> {
    let n = points.len();
    let proposals: Vec<Proposal> = ids::<LocalPoint>(n)
        .map(|p| {
            if free(p) {
                graph.proposal(points, p, free)
            } else {
                Proposal::default()
            }
        })
        .collect();
    // Each proposed edge once, with whether both ends propose it.
    let mut candidates: Vec<([LocalPoint; 2], bool)> = Vec::new();
    for p in ids::<LocalPoint>(n) {
        for q in proposals[p.index()].iter() {
            let mutual = proposals[q.index()].contains(p);
            if mutual && q < p {
                continue;
            }
            if is_long(
                points,
                p,
                q,
                proposals[p.index()],
                proposals[q.index()],
                GAP_DOUBLINGS,
            ) {
                continue;
            }
            candidates.push(([p.min(q), p.max(q)], mutual));
        }
    }
    let at = |i: LocalPoint| points[i.index()];
    candidates.sort_unstable_by(|&(e, me), &(f, mf)| {
        mf.cmp(&me)
            .then_with(|| length_order(at(e[0]), at(e[1]), at(f[0]), at(f[1])))
            .then_with(|| e.cmp(&f))
    });
    candidates.dedup_by_key(|c| c.0);
    let mut greedy = Greedy::new(n);
    for (edge, _) in candidates {
        greedy.take(edge);
    }
    // Noise turns a step of the curve away from both its ends' proposals now and then (the
    // next sample falls less than 90° from the previous one), and samples at random positions
    // leave gaps far longer than the steps beside them: the chain ends there. Ends that are
    // Delaunay neighbours join, shortest first, under the same rules, in rounds while any
    // join (chains that grew may reach across a gap they could not before).
    for _ in 0..MAX_JOIN_ROUNDS {
        if join_ends(graph, points, free, &mut greedy) == 0 {
            break;
        }
    }
    swap_interleaved_ends(graph, points, free, &mut greedy);
    keep_curve_like_pieces(graph, points, without_chords(points, greedy.taken))
}

/// The chain's step at its end `end`, as a pair: the longer of its last two edges (noise
/// makes single steps short); `None` for a point on no chain. `along` is each point's
/// neighbours along the chains.
fn end_step(
    points: &[[f64; 2]],
    along: &[[LocalPoint; 2]],
    end: LocalPoint,
) -> Option<[LocalPoint; 2]> {
    let at = |i: LocalPoint| points[i.index()];
    let first = along[end.index()][0];
    if first == NO_POINT {
        return None;
    }
    let [x, y] = along[first.index()];
    let second = if x == end { y } else { x };
    Some(
        if second != NO_POINT
            && length_order(at(first), at(second), at(end), at(first)) == Ordering::Greater
        {
            [first, second]
        } else {
            [end, first]
        },
    )
}

/// One round of joins of chain ends (rule 2 of the module docs): each end's nearest admissible
/// end or lone point among its Delaunay neighbours; pairs that choose each other join. The
/// number of joins taken.
fn join_ends(
    graph: &DelaunayGraph,
    points: &[[f64; 2]],
    free: &dyn Fn(LocalPoint) -> bool,
    greedy: &mut Greedy,
) -> usize {
    let n = points.len();
    let at = |i: LocalPoint| points[i.index()];
    let along = greedy.along(n);
    let end_step = |end: LocalPoint| end_step(points, &along, end);
    // Each chain's longest step, by the chain's root.
    let root: Vec<LocalPoint> = ids::<LocalPoint>(n)
        .map(|p| greedy.pieces.root(p))
        .collect();
    let mut longest = vec![[NO_POINT; 2]; n];
    for &[a, b] in &greedy.taken {
        let slot = &mut longest[root[a.index()].index()];
        if slot[0] == NO_POINT
            || length_order(at(a), at(b), at(slot[0]), at(slot[1])) == Ordering::Greater
        {
            *slot = [a, b];
        }
    }
    // A join is no longer than `2^JOIN_DOUBLINGS` times the step at each chain end it
    // joins, or than `2^GAP_JOIN_DOUBLINGS` times the longest step of either chain it joins:
    // a break of one curve, not the gap between two. (Samples at random positions leave
    // gaps many times the steps beside them, each no longer than the longest gaps elsewhere
    // along the same curve.)
    // A piece too small to be a curve ([`MIN_CHAIN_POINTS`]) sets no bound of its own: a
    // close pair of random samples in a gap would otherwise bar both its sides.
    let sizes: Vec<u32> = root.iter().map(|r| greedy.pieces.size[r.index()]).collect();
    let short = |p: LocalPoint, q: LocalPoint| {
        [(p, q), (q, p)].iter().all(|&(end, other)| {
            (sizes[end.index()] as usize) < MIN_CHAIN_POINTS
                || end_step(end).is_none_or(|[a, b]| {
                    scaled_length_order(at(end), at(other), at(a), at(b), JOIN_DOUBLINGS)
                        != Ordering::Greater
                        || [end, other].iter().any(|&x| {
                            let [c, d] = longest[root[x.index()].index()];
                            c != NO_POINT
                                && scaled_length_order(
                                    at(end),
                                    at(other),
                                    at(c),
                                    at(d),
                                    GAP_JOIN_DOUBLINGS,
                                ) != Ordering::Greater
                        })
                })
        })
    };
    let step: Vec<LocalPoint> = along.iter().map(|a| a[0]).collect();
    // Each end's nearest admissible end (or point on no chain); pairs that choose each
    // other join.
    let degree = &greedy.degree;
    let open = |p: LocalPoint| free(p) && degree[p.index()] < 2;
    let best: Vec<LocalPoint> = ids::<LocalPoint>(n)
        .map(|p| {
            if !open(p) {
                return NO_POINT;
            }
            graph
                .neighbours(p)
                .iter()
                .copied()
                .filter(|&q| {
                    open(q)
                        && step[p.index()] != q
                        && degree[p.index()] + degree[q.index()] >= 1
                        // The other end of a chain too short to close: a join `take`
                        // refuses, which would bar both ends from any other.
                        && !(root[p.index()] == root[q.index()]
                            && (sizes[p.index()] as usize) < MIN_CLOSED_POINTS)
                        && short(p, q)
                })
                .min_by(|&a, &b| closer(at(p), at(a), at(b)))
                .unwrap_or(NO_POINT)
        })
        .collect();
    let mut joins: Vec<[LocalPoint; 2]> = ids::<LocalPoint>(n)
        .filter_map(|p| {
            let q = best[p.index()];
            (q != NO_POINT && q > p && best[q.index()] == p).then_some([p, q])
        })
        .collect();
    joins.sort_unstable_by(|e, f| {
        length_order(at(e[0]), at(e[1]), at(f[0]), at(f[1])).then_with(|| e.cmp(f))
    });
    let taken = joins.len();
    for edge in joins {
        greedy.take(edge);
    }
    taken
}

/// Where the samples of a curve's two sides interleave (noise at a sharp corner), one chain
/// ends at the tip `p` with the sample `x` before it lying between the tip and the other
/// chain's end `q`, so that `p` and `q` are no Delaunay neighbours and never join: the chain
/// runs `… y, x, p` where the curve runs `… y, p, x, q …`. Swaps `x` and `p` and joins `x` to
/// `q` when `y p` and `x q` are Delaunay edges no longer than `2^JOIN_DOUBLINGS` times the
/// chain's steps `y x` and `x p` (the longer of them) and than the step at `q`.
fn swap_interleaved_ends(
    graph: &DelaunayGraph,
    points: &[[f64; 2]],
    free: &dyn Fn(LocalPoint) -> bool,
    greedy: &mut Greedy,
) {
    let n = points.len();
    let at = |i: LocalPoint| points[i.index()];
    let along = greedy.along(n);
    let other = |p: LocalPoint, not: LocalPoint| {
        let [u, v] = along[p.index()];
        if u == not {
            v
        } else {
            u
        }
    };
    let is_end = |p: LocalPoint| free(p) && greedy.degree[p.index()] == 1;
    // `pq` no longer than `2^JOIN_DOUBLINGS` times `ab`.
    let within = |p: LocalPoint, q: LocalPoint, [a, b]: [LocalPoint; 2]| {
        scaled_length_order(at(p), at(q), at(a), at(b), JOIN_DOUBLINGS) != Ordering::Greater
    };
    let longer_of = |e: [LocalPoint; 2], f: [LocalPoint; 2]| {
        if length_order(at(e[0]), at(e[1]), at(f[0]), at(f[1])) == Ordering::Less {
            f
        } else {
            e
        }
    };
    let mut touched = vec![false; n];
    let mut removed: Vec<[LocalPoint; 2]> = Vec::new();
    let mut added: Vec<[LocalPoint; 2]> = Vec::new();
    let mut joined: Vec<LocalPoint> = Vec::new();
    for p in ids::<LocalPoint>(n) {
        if !is_end(p) || touched[p.index()] {
            continue;
        }
        let x = along[p.index()][0];
        if greedy.degree[x.index()] != 2 || touched[x.index()] {
            continue;
        }
        let y = other(x, p);
        if touched[y.index()] || !graph.neighbours(p).contains(&y) {
            continue;
        }
        let step = longer_of([y, x], [x, p]);
        let chain = greedy.pieces.root(p);
        let partner = graph
            .neighbours(x)
            .iter()
            .copied()
            .filter(|&q| {
                q != p
                    && is_end(q)
                    && !touched[q.index()]
                    && greedy.pieces.root(q) != chain
                    && !graph.neighbours(p).contains(&q)
                    && within(x, q, step)
                    && within(y, p, step)
                    && end_step(points, &along, q).is_some_and(|step| within(x, q, step))
            })
            .min_by(|&a, &b| closer(at(x), at(a), at(b)));
        let Some(q) = partner else {
            continue;
        };
        for z in [p, x, y, q] {
            touched[z.index()] = true;
        }
        removed.extend([[y.min(x), y.max(x)], [x.min(p), x.max(p)]]);
        added.extend([[y, p], [p, x], [x, q]]);
        let (a, b) = (greedy.pieces.root(p), greedy.pieces.root(q));
        greedy.pieces.join(a, b);
        joined.push(q);
    }
    if added.is_empty() {
        return;
    }
    for q in joined {
        greedy.degree[q.index()] += 1;
    }
    removed.sort_unstable();
    greedy
        .taken
        .retain(|&[a, b]| removed.binary_search(&[a.min(b), a.max(b)]).is_err());
    greedy.taken.extend(added);
}

/// The chains drawn so far: each point's degree, the pieces, the edges taken.
struct Greedy {
    degree: Vec<u8>,
    pieces: Pieces,
    taken: Vec<[LocalPoint; 2]>,
}

impl Greedy {
    fn new(n: usize) -> Greedy {
        Greedy {
            degree: vec![0; n],
            pieces: Pieces::new(n),
            taken: Vec::new(),
        }
    }

    /// Each point's neighbours along the chains among `n` points (`NO_POINT` where it has
    /// fewer than two).
    fn along(&self, n: usize) -> Vec<[LocalPoint; 2]> {
        let mut along = vec![[NO_POINT; 2]; n];
        for &[a, b] in &self.taken {
            for (p, q) in [(a, b), (b, a)] {
                let slot = usize::from(along[p.index()][0] != NO_POINT);
                along[p.index()][slot] = q;
            }
        }
        along
    }

    /// Takes `[a, b]` if both have fewer than two edges and, when they are the ends of one
    /// chain, the chain has at least [`MIN_CLOSED_POINTS`] points (three close samples of a
    /// noisy curve propose each other all round).
    fn take(&mut self, [a, b]: [LocalPoint; 2]) {
        if self.degree[a.index()] >= 2 || self.degree[b.index()] >= 2 {
            return;
        }
        let (ra, rb) = (self.pieces.root(a), self.pieces.root(b));
        if ra == rb && (self.pieces.size[ra.index()] as usize) < MIN_CLOSED_POINTS {
            return;
        }
        self.pieces.join(ra, rb);
        self.degree[a.index()] += 1;
        self.degree[b.index()] += 1;
        self.taken.push([a, b]);
    }
}

/// Union–find over the points: the chains drawn so far.
struct Pieces {
    parent: Vec<LocalPoint>,
    size: Vec<u32>,
}

impl Pieces {
    fn new(n: usize) -> Pieces {
        Pieces {
            parent: ids(n).collect(),
            size: vec![1; n],
        }
    }

    /// The pieces of `edges` among `n` points.
    fn of(n: usize, edges: &[[LocalPoint; 2]]) -> Pieces {
        let mut pieces = Pieces::new(n);
        for &[a, b] in edges {
            let (ra, rb) = (pieces.root(a), pieces.root(b));
            pieces.join(ra, rb);
        }
        pieces
    }

    fn root(&mut self, mut p: LocalPoint) -> LocalPoint {
        while self.parent[p.index()] != p {
            let up = self.parent[self.parent[p.index()].index()];
            self.parent[p.index()] = up;
            p = up;
        }
        p
    }

    /// Joins the pieces of the roots `a` and `b` (the smaller root stays).
    fn join(&mut self, a: LocalPoint, b: LocalPoint) {
        if a != b {
            let (keep, gone) = (a.min(b), a.max(b));
            self.parent[gone.index()] = keep;
            self.size[keep.index()] += self.size[gone.index()];
        }
    }
}

/// The pieces of `edges` (each point on at most two) that are curves (rule 3 of the module
/// docs): at least [`MIN_CHAIN_POINTS`] points, at least three quarters of them isolated.
fn keep_curve_like_pieces(
    graph: &DelaunayGraph,
    points: &[[f64; 2]],
    edges: Vec<[LocalPoint; 2]>,
) -> Vec<[LocalPoint; 2]> {
    let n = points.len();
    let mut next = vec![[NO_POINT; 2]; n];
    for &[a, b] in &edges {
        for (p, q) in [(a, b), (b, a)] {
            let slot = usize::from(next[p.index()][0] != NO_POINT);
            next[p.index()][slot] = q;
        }
    }
    // Each piece's points, found by a walk from each point not yet labelled; labelled by
    // their first point.
    let mut piece = vec![NO_POINT; n];
    let mut pieces: Vec<Vec<LocalPoint>> = Vec::new();
    for start in ids::<LocalPoint>(n) {
        if piece[start.index()] != NO_POINT || next[start.index()][0] == NO_POINT {
            continue;
        }
        let mut members = Vec::new();
        let mut stack = vec![start];
        piece[start.index()] = start;
        while let Some(p) = stack.pop() {
            members.push(p);
            for q in next[p.index()] {
                if q != NO_POINT && piece[q.index()] == NO_POINT {
                    piece[q.index()] = start;
                    stack.push(q);
                }
            }
        }
        if members.len() >= MIN_CHAIN_POINTS {
            pieces.push(members);
        }
    }
    let mut keep = vec![false; n];
    let isolated_enough = |members: &[LocalPoint]| {
        let isolated = members
            .iter()
            .filter(|&&p| is_isolated(graph, points, p, next[p.index()], &piece))
            .count();
        4 * isolated >= 3 * members.len()
    };
    for members in pieces {
        if isolated_enough(&members) {
            for &p in &members {
                keep[p.index()] = true;
            }
        }
    }
    edges
        .into_iter()
        .filter(|&[a, _]| keep[a.index()])
        .collect()
}

/// Whether every Delaunay neighbour of `p` off its piece is farther than
/// `2^ISOLATION_DOUBLINGS` times `p`'s longer edge along the piece (`along`): a point of a
/// sampled curve is nearer its neighbours along the curve than anything else, a point of a
/// scatter (outliers, the leftovers of a noise band) is not.
fn is_isolated(
    graph: &DelaunayGraph,
    points: &[[f64; 2]],
    p: LocalPoint,
    along: [LocalPoint; 2],
    piece: &[LocalPoint],
) -> bool {
    let at = |i: LocalPoint| points[i.index()];
    let step = match along {
        [a, NO_POINT] => a,
        [a, b] => {
            if length_order(at(p), at(a), at(p), at(b)) == Ordering::Less {
                b
            } else {
                a
            }
        }
    };
    let own = piece[p.index()];
    graph
        .neighbours(p)
        .iter()
        .filter(|&&o| piece[o.index()] != own)
        .all(|&o| {
            scaled_length_order(at(p), at(o), at(p), at(step), ISOLATION_DOUBLINGS)
                == Ordering::Greater
        })
}
