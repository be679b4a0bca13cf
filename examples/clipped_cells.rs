//! Cost of the clipped Voronoi cells, side by side in one run with the triangulation they
//! come from and with a peer: spade's bulk-loaded Delaunay triangulation and a walk over all
//! its Voronoi faces reading each vertex position (f64 circumcenters; spade does not clip
//! unbounded cells, so it does less work than `clipped_cells`).
//!
//! ```text
//! cargo run --release --example clipped_cells            # uniform points, 10^4 and 10^5
//! cargo run --release --example clipped_cells -- 1000000
//! ```
//!
//! Prints, per size, the minimum over 5 interleaved rounds of: `triangulate`,
//! `clipped_cells` (on a finished triangulation, default box), spade (bulk load + faces),
//! and the ratios.

use std::hint::black_box;
use std::time::{Duration, Instant};

use spade::{DelaunayTriangulation, Point2, Triangulation as _};
use wdm_crust::{triangulate, BoundingBox};

/// Deterministic uniform points in the unit square (xorshift64*).
fn uniform(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut state = seed;
    let mut next = || {
        state ^= state >> 12;
        state ^= state << 25;
        state ^= state >> 27;
        (state.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
    };
    (0..n).map(|_| [next(), next()]).collect()
}

fn time(f: impl FnOnce()) -> Duration {
    let start = Instant::now();
    f();
    start.elapsed()
}

fn main() {
    let sizes: Vec<usize> = match std::env::args().nth(1) {
        Some(n) => vec![n.parse().expect("a point count")],
        None => vec![10_000, 100_000],
    };
    println!("| n | triangulate | clipped_cells | spade bulk + Voronoi faces | cells / triangulate | cells / spade |");
    println!("|---:|---:|---:|---:|---:|---:|");
    for n in sizes {
        let points = uniform(n, 0x9e37_79b9_7f4a_7c15 ^ n as u64);
        let bbox = BoundingBox::around(&points).expect("points");
        let spade_points: Vec<Point2<f64>> =
            points.iter().map(|p| Point2::new(p[0], p[1])).collect();
        let (mut tri_t, mut cells_t, mut spade_t) = (Duration::MAX, Duration::MAX, Duration::MAX);
        for _ in 0..5 {
            tri_t = tri_t.min(time(|| {
                black_box(triangulate(&points).expect("valid"));
            }));
            let tri = triangulate(&points).expect("valid");
            cells_t = cells_t.min(time(|| {
                black_box(tri.voronoi().clipped_cells(&bbox));
            }));
            spade_t = spade_t.min(time(|| {
                let dt = DelaunayTriangulation::<Point2<f64>>::bulk_load(spade_points.clone())
                    .expect("valid");
                let mut sum = 0.0;
                for face in dt.voronoi_faces() {
                    for edge in face.adjacent_edges() {
                        if let Some(p) = edge.from().position() {
                            sum += p.x;
                        }
                    }
                }
                black_box(sum);
            }));
        }
        let ms = |d: Duration| d.as_secs_f64() * 1e3;
        println!(
            "| {n} | {:.1} ms | {:.1} ms | {:.1} ms | {:.2}× | {:.2}× |",
            ms(tri_t),
            ms(cells_t),
            ms(spade_t),
            cells_t.as_secs_f64() / tri_t.as_secs_f64(),
            cells_t.as_secs_f64() / spade_t.as_secs_f64()
        );
    }
}
