//! Point sets and adapters shared by the `compare` bench and the `peak_rss` binary.
//!
//! Every store is called through [`Store::run`], which returns the flat result's triangle
//! count, so the timed work is exactly the library call (validation where the library does
//! it, ordering, construction, conversion to flat arrays, the copy of the input points into
//! the result) plus freeing the result.

use std::f64::consts::TAU;

/// SplitMix64: small, deterministic, no dependency.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Rng(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Standard normal (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let u = 1.0 - self.uniform(); // (0, 1]
        (-2.0 * u.ln()).sqrt() * (TAU * self.uniform()).cos()
    }

    pub fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            let j = (self.next_u64() % (i as u64 + 1)) as usize;
            v.swap(i, j);
        }
    }
}

/// `n` points uniform in the unit square.
pub fn uniform(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut rng = Rng::new(seed);
    (0..n).map(|_| [rng.uniform(), rng.uniform()]).collect()
}

/// `n` points along the ellipse with semi-axes 1 and 0.6, at stratified random parameters
/// `t = 2π (i + u) / n`, moved off the curve radially by a normal offset with standard
/// deviation a quarter of the mean parameter spacing (`0.25 · 2π / n`), then shuffled.
pub fn noisy_ellipse(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut rng = Rng::new(seed);
    let sigma = 0.25 * TAU / n as f64;
    let mut pts: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = TAU * (i as f64 + rng.uniform()) / n as f64;
            let r = 1.0 + sigma * rng.normal();
            [r * t.cos(), 0.6 * r * t.sin()]
        })
        .collect();
    rng.shuffle(&mut pts);
    pts
}

/// The three triangulators compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Store {
    /// wdm-crust at 79d15e6: quad-edge store, lexicographic order, vertical cuts,
    /// robust-crate predicates, conversion of the quad-edges into flat arrays at the end.
    QuadEdge,
    /// The current triangle store (`mesh.rs`) driven by 79d15e6's pipeline.
    TriangleLex,
    /// The current crate: triangle store, Z order, Dwyer cuts, static filters.
    Current,
}

impl Store {
    pub const ALL: [Store; 3] = [Store::QuadEdge, Store::TriangleLex, Store::Current];

    pub fn name(self) -> &'static str {
        match self {
            Store::QuadEdge => "quadedge_79d15e6",
            Store::TriangleLex => "triangle_oldpipeline",
            Store::Current => "triangle_current",
        }
    }

    pub fn from_name(name: &str) -> Option<Store> {
        Store::ALL.into_iter().find(|s| s.name() == name)
    }

    /// Triangulates and returns the number of triangles (the result is freed on return).
    pub fn run(self, pts: &[[f64; 2]]) -> usize {
        match self {
            Store::QuadEdge => wdm_crust_quadedge::triangulate(pts)
                .expect("valid points")
                .triangles()
                .len(),
            Store::TriangleLex => triangle_lex::triangulate(pts).triangles.len(),
            Store::Current => wdm_crust::triangulate(pts)
                .expect("valid points")
                .triangles()
                .len(),
        }
    }

    /// The triangles as coordinate triples, each rotated to start at its smallest corner,
    /// sorted: equal for two stores exactly when they give the same triangulation.
    pub fn canonical(self, pts: &[[f64; 2]]) -> Vec<[[u64; 2]; 3]> {
        let triangles: Vec<[u32; 3]> = match self {
            Store::QuadEdge => wdm_crust_quadedge::triangulate(pts)
                .expect("valid points")
                .triangles()
                .to_vec(),
            Store::TriangleLex => triangle_lex::triangulate(pts).triangles,
            Store::Current => wdm_crust::triangulate(pts)
                .expect("valid points")
                .triangles()
                .to_vec(),
        };
        let key = |v: u32| pts[v as usize].map(f64::to_bits);
        let mut all: Vec<[[u64; 2]; 3]> = triangles
            .iter()
            .map(|t| {
                let k = t.map(key);
                let m = (0..3).min_by_key(|&i| k[i]).unwrap_or(0);
                [k[m], k[(m + 1) % 3], k[(m + 2) % 3]]
            })
            .collect();
        all.sort_unstable();
        all
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The three stores agree, and 79d15e6's own invariant checker accepts its result.
    #[test]
    fn stores_agree() {
        for n in [3, 4, 5, 17, 1000, 20_000] {
            for pts in [uniform(n, n as u64), noisy_ellipse(n, n as u64)] {
                wdm_crust_quadedge::triangulate(&pts)
                    .unwrap()
                    .validate()
                    .unwrap();
                wdm_crust::triangulate(&pts).unwrap().validate().unwrap();
                let reference = Store::QuadEdge.canonical(&pts);
                assert!(!reference.is_empty());
                for store in [Store::TriangleLex, Store::Current] {
                    assert!(store.canonical(&pts) == reference, "{store:?} at n = {n}");
                }
            }
        }
        // Collinear input and duplicates.
        let line: Vec<[f64; 2]> = (0..50).map(|i| [i as f64, 2.0 * i as f64]).collect();
        assert_eq!(Store::TriangleLex.run(&line), 0);
        let mut dup = uniform(500, 9);
        dup.extend_from_within(0..100);
        for store in Store::ALL {
            assert_eq!(store.run(&dup), Store::QuadEdge.run(&dup));
        }
    }
}
