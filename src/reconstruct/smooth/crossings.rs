//! The smoothed curves kept simple, decided exactly: no two curve segments meet except
//! where they share an end, two segments that share an end do not fold over each other,
//! and a closed curve still runs counterclockwise. Where a test fails the moves of the
//! points involved are undone, until nothing fails.

use super::super::curves::ring_orientation_by;
use super::super::curves::LocalCurve;
use super::super::thresholds::smooth::{MAX_ROUNDS, SHORTENED, STAGES};
use crate::ids::LocalPoint;
use crate::kernel::{orient, Sign};

/// Shortens or undoes the moves of `moved` (fitted positions by local point, `None`: at
/// `points`) where the curves through them would cross, touch or turn clockwise; what
/// remains in `moved` is where the points go.
pub(super) fn undo_crossings(
    points: &[[f64; 2]],
    curves: &[LocalCurve],
    moved: &mut [Option<[f64; 2]>],
) {
    let mut segments: Vec<[LocalPoint; 2]> = Vec::new();
    for c in curves {
        let k = c.points.len();
        let count = if c.closed { k } else { k.saturating_sub(1) };
        segments.extend((0..count).map(|i| [c.points[i], c.points[(i + 1) % k]]));
    }
    let fitted: Vec<Option<[f64; 2]>> = moved.to_vec();
    let mut stage = vec![0u8; moved.len()];
    for _ in 0..MAX_ROUNDS {
        let at = |p: LocalPoint| moved[p.index()].unwrap_or(points[p.index()]);
        let mut undo: Vec<LocalPoint> = Vec::new();
        for [a, b] in meeting_pairs(&segments, &at) {
            undo.extend(a);
            undo.extend(b);
        }
        for c in curves.iter().filter(|c| c.closed) {
            let ring = &c.points;
            if ring.iter().any(|&p| moved[p.index()].is_some())
                && ring_orientation_by(ring.len(), |i| at(ring[i])) != Sign::Positive
            {
                undo.extend_from_slice(ring);
            }
        }
        undo.sort_unstable();
        undo.dedup();
        let mut changed = false;
        for p in undo {
            let p = p.index();
            let (Some(f), Some(_)) = (fitted[p], moved[p]) else {
                continue;
            };
            changed = true;
            stage[p] += 1;
            moved[p] = (stage[p] <= STAGES).then(|| {
                let share = SHORTENED.powi(i32::from(stage[p]));
                let o = points[p];
                [o[0] + (f[0] - o[0]) * share, o[1] + (f[1] - o[1]) * share]
            });
        }
        if !changed {
            return;
        }
    }
    moved.iter_mut().for_each(|m| *m = None);
}

/// Pairs of segments that meet other than at a shared end (a shared end counts when the two
/// fold over each other, and a segment of length zero meets everything), decided exactly;
/// candidates from a grid over the segments' boxes.
fn meeting_pairs(
    segments: &[[LocalPoint; 2]],
    at: &impl Fn(LocalPoint) -> [f64; 2],
) -> Vec<[[LocalPoint; 2]; 2]> {
    let mut found = Vec::new();
    if segments.is_empty() {
        return found;
    }
    let ends: Vec<[[f64; 2]; 2]> = segments.iter().map(|&[a, b]| [at(a), at(b)]).collect();
    for (s, e) in segments.iter().zip(&ends) {
        if e[0] == e[1] {
            found.push([*s, *s]);
        }
    }
    let grid = Grid::new(&ends);
    let mut cell_of = vec![Vec::new(); grid.cells()];
    for (i, e) in ends.iter().enumerate() {
        let ([x0, y0], [x1, y1]) = grid.range(e);
        for cx in x0..=x1 {
            for cy in y0..=y1 {
                cell_of[cy * grid.columns + cx].push(i as u32);
            }
        }
    }
    for cell in &cell_of {
        for (k, &i) in cell.iter().enumerate() {
            for &j in &cell[k + 1..] {
                let (i, j) = (i as usize, j as usize);
                // Tested once: in the first cell of the two ranges' overlap.
                let (ri, rj) = (grid.range(&ends[i]), grid.range(&ends[j]));
                let first = [ri.0[0].max(rj.0[0]), ri.0[1].max(rj.0[1])];
                if cell.as_ptr() != cell_of[first[1] * grid.columns + first[0]].as_ptr() {
                    continue;
                }
                if segments_meet(segments[i], segments[j], ends[i], ends[j]) {
                    found.push([segments[i], segments[j]]);
                }
            }
        }
    }
    found
}

/// A uniform grid over boxes, cells about the median segment long, at most a few cells a
/// segment on the whole. Cell indices are monotone functions of the coordinates (each
/// rounded step is), so two boxes that overlap get overlapping cell ranges.
struct Grid {
    origin: [f64; 2],
    cell: f64,
    columns: usize,
    rows: usize,
}

impl Grid {
    fn new(ends: &[[[f64; 2]; 2]]) -> Grid {
        // Halves throughout: differences of halves never overflow.
        let half = |x: f64| 0.5 * x;
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for e in ends {
            for p in e {
                for c in 0..2 {
                    lo[c] = lo[c].min(half(p[c]));
                    hi[c] = hi[c].max(half(p[c]));
                }
            }
        }
        let extent = [hi[0] - lo[0], hi[1] - lo[1]];
        let mut lengths: Vec<f64> = ends
            .iter()
            .map(|[p, q]| {
                (half(p[0]) - half(q[0]))
                    .abs()
                    .max((half(p[1]) - half(q[1])).abs())
            })
            .collect();
        let middle = lengths.len() / 2;
        let median = *lengths.select_nth_unstable_by(middle, f64::total_cmp).1;
        let budget = (4 * ends.len() + 16) as f64;
        let mut cell = median.max(extent[0].max(extent[1]) / budget);
        if !(cell > 0.0 && cell.is_finite()) {
            cell = f64::INFINITY;
        }
        let mut grid = Grid {
            origin: lo,
            cell,
            columns: 1,
            rows: 1,
        };
        loop {
            let count = |e: f64| {
                if grid.cell.is_finite() {
                    (e / grid.cell) as usize + 1
                } else {
                    1
                }
            };
            grid.columns = count(extent[0]);
            grid.rows = count(extent[1]);
            let filled: usize = ends
                .iter()
                .map(|e| {
                    let (a, b) = grid.range(e);
                    (b[0] - a[0] + 1) * (b[1] - a[1] + 1)
                })
                .sum();
            if grid.columns * grid.rows <= 2 * budget as usize && filled <= 16 * ends.len()
                || !grid.cell.is_finite()
            {
                return grid;
            }
            grid.cell *= 2.0;
        }
    }

    fn cells(&self) -> usize {
        self.columns * self.rows
    }

    /// The cell of a coordinate along axis `c`.
    fn index(&self, x: f64, c: usize) -> usize {
        let limit = if c == 0 { self.columns } else { self.rows };
        if !self.cell.is_finite() {
            return 0;
        }
        let k = (0.5 * x - self.origin[c]) / self.cell;
        (k.max(0.0) as usize).min(limit - 1)
    }

    /// The lowest and highest cells of a segment's box.
    fn range(&self, e: &[[f64; 2]; 2]) -> ([usize; 2], [usize; 2]) {
        let lo = [0, 1].map(|c| self.index(e[0][c].min(e[1][c]), c));
        let hi = [0, 1].map(|c| self.index(e[0][c].max(e[1][c]), c));
        (lo, hi)
    }
}

/// Whether segments `s` and `t` (point indices, ends at `ps` and `pt`) meet other than
/// at an end they share, exactly; two that share an end meet when they fold over each
/// other (collinear, overlapping past it).
fn segments_meet(
    s: [LocalPoint; 2],
    t: [LocalPoint; 2],
    ps: [[f64; 2]; 2],
    pt: [[f64; 2]; 2],
) -> bool {
    let shared = (0..2).find_map(|i| (0..2).find(|&j| s[i] == t[j]).map(|j| (i, j)));
    if let Some((i, j)) = shared {
        if s[1 - i] == t[1 - j] {
            // The same segment twice (not on curves of one triangulation's edges).
            return false;
        }
        // `c` the shared end, `a` and `b` the others.
        let (c, a, b) = (ps[i], ps[1 - i], pt[1 - j]);
        return orient(c, a, b) == Sign::Zero && (within(c, a, b) || within(c, b, a));
    }
    let [a, b] = ps;
    let [c, d] = pt;
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    let opposite = |x: Sign, y: Sign| {
        matches!(
            (x, y),
            (Sign::Positive, Sign::Negative) | (Sign::Negative, Sign::Positive)
        )
    };
    (opposite(o1, o2) && opposite(o3, o4))
        || (o1 == Sign::Zero && within(a, b, c))
        || (o2 == Sign::Zero && within(a, b, d))
        || (o3 == Sign::Zero && within(c, d, a))
        || (o4 == Sign::Zero && within(c, d, b))
}

/// Whether `q`, collinear with `a` and `b`, lies on the closed segment between them (a
/// comparison of coordinates, exact).
fn within(a: [f64; 2], b: [f64; 2], q: [f64; 2]) -> bool {
    (0..2).all(|c| a[c].min(b[c]) <= q[c] && q[c] <= a[c].max(b[c]))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The local points numbered `ends`.
    fn local(ends: [u32; 2]) -> [LocalPoint; 2] {
        ends.map(LocalPoint::new)
    }

    #[test]
    fn segments_meet_exactly() {
        let s = |a: [f64; 2], b: [f64; 2]| [a, b];
        // Crossing, touching at an inner point, apart, collinear overlapping, collinear apart.
        assert!(segments_meet(
            local([0, 1]),
            local([2, 3]),
            s([0.0, 0.0], [2.0, 2.0]),
            s([0.0, 2.0], [2.0, 0.0])
        ));
        assert!(segments_meet(
            local([0, 1]),
            local([2, 3]),
            s([0.0, 0.0], [2.0, 0.0]),
            s([1.0, 0.0], [1.0, 1.0])
        ));
        assert!(!segments_meet(
            local([0, 1]),
            local([2, 3]),
            s([0.0, 0.0], [1.0, 0.0]),
            s([2.0, 0.0], [3.0, 1.0])
        ));
        assert!(segments_meet(
            local([0, 1]),
            local([2, 3]),
            s([0.0, 0.0], [2.0, 0.0]),
            s([1.0, 0.0], [3.0, 0.0])
        ));
        assert!(!segments_meet(
            local([0, 1]),
            local([2, 3]),
            s([0.0, 0.0], [1.0, 0.0]),
            s([2.0, 0.0], [3.0, 0.0])
        ));
        // Sharing an end: a turn is fine, folding back is not.
        assert!(!segments_meet(
            local([0, 1]),
            local([1, 2]),
            s([0.0, 0.0], [1.0, 0.0]),
            s([1.0, 0.0], [1.0, 1.0])
        ));
        assert!(!segments_meet(
            local([0, 1]),
            local([1, 2]),
            s([0.0, 0.0], [1.0, 0.0]),
            s([1.0, 0.0], [2.0, 0.0])
        ));
        assert!(segments_meet(
            local([0, 1]),
            local([1, 2]),
            s([0.0, 0.0], [1.0, 0.0]),
            s([1.0, 0.0], [0.5, 0.0])
        ));
    }

    #[test]
    fn a_crossing_move_is_undone_and_only_there() {
        // A square ring of 8 points; point 2 moved across the far side, point 7 a little.
        let points = [
            [0.0, 0.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [2.0, 2.0],
            [1.0, 2.0],
            [0.0, 2.0],
            [0.0, 1.0],
        ];
        let curves = [LocalCurve {
            closed: true,
            points: crate::ids::ids(8).collect(),
        }];
        let mut moved = vec![None; 8];
        moved[2] = Some([1.0, 2.5]);
        moved[7] = Some([0.1, 1.0]);
        undo_crossings(&points, &curves, &mut moved);
        assert!(moved[2].is_none_or(|p| p[1] < 2.0), "{:?}", moved[2]);
        assert_eq!(moved[7], Some([0.1, 1.0]));
        // A ring mirrored as a whole would turn clockwise: the moves are shortened until it
        // runs counterclockwise again (a quarter of each keeps it a squashed square).
        let mirrored: Vec<Option<[f64; 2]>> = points.iter().map(|&[x, y]| Some([y, x])).collect();
        let mut moved = mirrored.clone();
        undo_crossings(&points, &curves, &mut moved);
        let at = |i: usize| moved[i].unwrap_or(points[i]);
        assert_eq!(ring_orientation_by(8, at), Sign::Positive);
        for i in 0..8 {
            let full = mirrored[i].unwrap();
            let d = |q: [f64; 2]| (q[0] - points[i][0]).hypot(q[1] - points[i][1]);
            assert!(d(at(i)) <= 0.25 * d(full), "{i}: {:?}", moved[i]);
        }
    }
}
