//! Structured fuzz input: point sets built from the configurations that break geometry code.
//!
//! A [`Scene`] is a list of [`Part`]s, each placed by a [`Placement`]: small integer lattices
//! and full grids (cocircular everywhere), collinear lattice points, lattice points of circles
//! `x² + y² = r²` (many cocircular points), sampled curves (realistic input for the
//! reconstruction), exact duplicates and ulp-nudged copies of earlier points, and raw `f64`
//! bit patterns (NaN, infinities, subnormals, the ends of the `f64` range, and the bounds
//! `2^-142`, `2^201` of the adaptive predicates' range, where the kernel changes path).
//! Placements rotate exactly (quarter turns, Pythagorean rotations) or inexactly (an `f64`
//! angle), scale by a power of two anywhere from the subnormals to `2^1023`, biased towards
//! the ends of the range and the kernel's path boundaries, stretch one axis by another power
//! of two and translate (exactly or with rounding, which leaves nearly degenerate
//! configurations). No input is filtered: every finite coordinate must be handled exactly.
//! The fuzzer mutates the structure, not the noise.

use arbitrary::Arbitrary;

/// `2^k` for `k` in the normal range `-1022..=1023` (clamped).
pub fn pow2(k: i32) -> f64 {
    f64::from_bits(((k.clamp(-1022, 1023) + 1023) as u64) << 52)
}

/// `x · 2^k` for any `k` (in normal-range steps; rounds only where the result is subnormal,
/// overflows only where it is beyond the `f64` range).
pub fn ldexp(mut x: f64, mut k: i32) -> f64 {
    while k != 0 && x != 0.0 && x.is_finite() {
        let step = k.clamp(-1000, 1000);
        x *= pow2(step);
        k -= step;
    }
    x
}

/// `x` moved by `steps` units in the last place (towards +∞ for positive steps).
pub fn nudge(x: f64, steps: i8) -> f64 {
    let mut x = x;
    for _ in 0..steps.unsigned_abs() {
        if !x.is_finite() {
            break;
        }
        let up = steps > 0;
        x = if x == 0.0 {
            if up {
                f64::from_bits(1)
            } else {
                -f64::from_bits(1)
            }
        } else if (x > 0.0) == up {
            f64::from_bits(x.to_bits() + 1)
        } else {
            f64::from_bits(x.to_bits() - 1)
        };
    }
    x
}

/// A point set to fuzz with.
#[derive(Debug, Clone, Arbitrary)]
pub struct Scene {
    /// The parts, generated in order (copies refer to earlier points).
    pub parts: Vec<Part>,
    /// Seed of the permutation used by order-independence checks.
    pub order: u64,
}

/// One ingredient of a [`Scene`].
#[derive(Debug, Clone, Arbitrary)]
pub enum Part {
    /// Arbitrary points of a small integer lattice.
    Lattice {
        /// Placement.
        place: Placement,
        /// Lattice coordinates.
        points: Vec<[i8; 2]>,
    },
    /// A full `nx × ny` grid with spacing `step` (every unit square is cocircular).
    Grid {
        /// Placement.
        place: Placement,
        /// Columns (at most 40).
        nx: u8,
        /// Rows (at most 40).
        ny: u8,
        /// Spacing (at least 1).
        step: u8,
    },
    /// Collinear lattice points `t · dir`.
    Line {
        /// Placement.
        place: Placement,
        /// Direction.
        dir: [i8; 2],
        /// Parameters along the line.
        ts: Vec<i16>,
    },
    /// Lattice points of the circle `x² + y² = r²` for an `r` with many of them.
    Circle {
        /// Placement.
        place: Placement,
        /// Index into [`CIRCLE_RADII`].
        radius: u8,
        /// All lattice points of the circle, or only the picked ones.
        all: bool,
        /// Indices of the lattice points to take.
        picks: Vec<u8>,
    },
    /// `n` samples of a closed curve (ellipse, star, or an ellipse rounded to the lattice).
    Curve {
        /// Placement.
        place: Placement,
        /// 0: ellipse, 1: star, 2: ellipse rounded to integers, 3: regular polygon corners.
        shape: u8,
        /// Number of samples (at least 3).
        n: u8,
        /// Size parameters.
        a: u8,
        /// Size parameters.
        b: u8,
        /// Start angle in 1/65536 turns.
        phase: u16,
        /// Irregular spacing: 0 uniform, else the amount of angular jitter.
        jitter: u8,
    },
    /// Exact copies of earlier points (indices modulo the count so far).
    Copies {
        /// Which points to copy.
        picks: Vec<u16>,
    },
    /// Earlier points moved by a few ulps per coordinate.
    Nudged {
        /// `(point, x steps, y steps)`; steps are reduced to `-4..=4`.
        picks: Vec<(u16, i8, i8)>,
    },
    /// Raw coordinates, mostly special values.
    Raw {
        /// The coordinates.
        coords: Vec<[RawCoord; 2]>,
    },
}

/// A raw coordinate.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum RawCoord {
    /// Any bit pattern.
    Bits(u64),
    /// A value from [`SPECIAL_VALUES`].
    Special(u8),
    /// A finite value: `±(1 + m/2^52) · 2^e`, rounded where that is subnormal.
    Finite {
        /// Mantissa bits (low 52 used).
        mantissa: u64,
        /// Exponent, reduced to `-1080..=1023`.
        exponent: i16,
        /// Sign.
        negative: bool,
    },
}

/// Coordinates at and around the ends of `f64` and of the adaptive predicates' range.
pub const SPECIAL_VALUES: [f64; 16] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    f64::from_bits(0x3710_0000_0000_0000),  // 2^-142
    -f64::from_bits(0x3710_0000_0000_0000), // -2^-142
    f64::from_bits(0x4c80_0000_0000_0000),  // 2^201
    -f64::from_bits(0x4c80_0000_0000_0000), // -2^201
    f64::from_bits(0x370f_ffff_ffff_ffff),  // 2^-142 minus one ulp (outside)
    f64::from_bits(0x4c80_0000_0000_0001),  // 2^201 plus one ulp (outside)
    f64::MIN_POSITIVE,
    5e-324,
    f64::MAX,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
];

/// Radii whose circles `x² + y² = r²` have many lattice points.
pub const CIRCLE_RADII: [i64; 8] = [5, 25, 65, 85, 125, 325, 425, 1105];

/// Where a part goes: `shift + scale · rotate(offset + p)`, applied to each point `p`.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub struct Placement {
    /// Lattice offset added first.
    pub offset: [i8; 2],
    /// Rotation.
    pub rotation: Rotation,
    /// Power-of-two scale.
    pub scale: Exponent,
    /// Extra power of two for y only (anisotropic), `-8..=8`, if any.
    pub stretch: Option<i8>,
    /// Translation after scaling.
    pub shift: Option<Shift>,
}

/// A rotation.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Rotation {
    /// None.
    Identity,
    /// `k` quarter turns (exact).
    Quarter(u8),
    /// By a Pythagorean triple `(a, b, c)`: `(a x − b y, b x + a y)`, an exact rotation
    /// scaled by `c` on integers.
    Pythagorean(u8),
    /// By `k / 65536` turns in `f64` (rounds: near-degenerate configurations).
    Float(u16),
}

/// A power of two, biased towards the ends of the `f64` range and the bounds of the
/// adaptive predicates' range.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Exponent {
    /// `2^0`.
    Unit,
    /// `2^(k mod 17 − 8)`.
    Small(i8),
    /// Around the small bound of the adaptive range: `2^(−144 + k mod 24)`.
    Tiny(u8),
    /// Around the large bound of the adaptive range: `2^(170 + k mod 36)`.
    Huge(u8),
    /// Into the subnormals: `2^(−1090 + k mod 80)`.
    Subnormal(u8),
    /// Near the top of the `f64` range: `2^(960 + k mod 64)`; large points may overflow.
    Top(u8),
    /// Anywhere in `2^(−1090..=1023)`.
    Any(i16),
}

impl Exponent {
    /// The exponent.
    pub fn value(self) -> i32 {
        match self {
            Exponent::Unit => 0,
            Exponent::Small(k) => i32::from(k).rem_euclid(17) - 8,
            Exponent::Tiny(k) => -144 + i32::from(k % 24),
            Exponent::Huge(k) => 170 + i32::from(k % 36),
            Exponent::Subnormal(k) => -1090 + i32::from(k % 80),
            Exponent::Top(k) => 960 + i32::from(k % 64),
            Exponent::Any(k) => i32::from(k).rem_euclid(2114) - 1090,
        }
    }
}

/// A translation `m · 2^(scale + j)` per coordinate.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub struct Shift {
    /// Integer multipliers.
    pub m: [i16; 2],
    /// Exponent relative to the part's scale, reduced to `-60..=60`.
    pub j: i8,
}

const TRIPLES: [(i64, i64); 5] = [(3, 4), (5, 12), (8, 15), (7, 24), (20, 21)];

impl Placement {
    /// Rotation of an integer point, exact.
    fn rotate_int(&self, p: [i64; 2]) -> [i64; 2] {
        let [x, y] = [
            p[0] + i64::from(self.offset[0]),
            p[1] + i64::from(self.offset[1]),
        ];
        match self.rotation {
            Rotation::Identity | Rotation::Float(_) => [x, y],
            Rotation::Quarter(k) => match k % 4 {
                0 => [x, y],
                1 => [-y, x],
                2 => [-x, -y],
                _ => [y, -x],
            },
            Rotation::Pythagorean(k) => {
                let (a, b) = TRIPLES[k as usize % TRIPLES.len()];
                [a * x - b * y, b * x + a * y]
            }
        }
    }

    /// Places an integer point: exact except for [`Rotation::Float`] and rounding shifts.
    pub fn place_int(&self, p: [i64; 2]) -> [f64; 2] {
        let q = self.rotate_int(p);
        self.finish([q[0] as f64, q[1] as f64])
    }

    /// Places a real point (rotations in `f64`).
    pub fn place_real(&self, p: [f64; 2]) -> [f64; 2] {
        let [x, y] = [
            p[0] + f64::from(self.offset[0]),
            p[1] + f64::from(self.offset[1]),
        ];
        let q = match self.rotation {
            Rotation::Identity | Rotation::Float(_) => [x, y],
            Rotation::Quarter(k) => match k % 4 {
                0 => [x, y],
                1 => [-y, x],
                2 => [-x, -y],
                _ => [y, -x],
            },
            Rotation::Pythagorean(k) => {
                let (a, b) = TRIPLES[k as usize % TRIPLES.len()];
                let (a, b) = (a as f64, b as f64);
                [a * x - b * y, b * x + a * y]
            }
        };
        self.finish(q)
    }

    fn finish(&self, q: [f64; 2]) -> [f64; 2] {
        let [mut x, mut y] = q;
        if let Rotation::Float(k) = self.rotation {
            let t = f64::from(k) * std::f64::consts::TAU / 65536.0;
            let (s, c) = t.sin_cos();
            [x, y] = [c * x - s * y, s * x + c * y];
        }
        let k = self.scale.value();
        let ky = k + self.stretch.map_or(0, |s| i32::from(s).clamp(-8, 8));
        x = ldexp(x, k);
        y = ldexp(y, ky);
        if let Some(shift) = self.shift {
            let j = i32::from(shift.j).clamp(-60, 60);
            x += ldexp(f64::from(shift.m[0]), k + j);
            y += ldexp(f64::from(shift.m[1]), ky + j);
        }
        [x, y]
    }
}

/// All lattice points of `x² + y² = r²`, counterclockwise from `(r, 0)`.
pub fn circle_lattice_points(r: i64) -> Vec<[i64; 2]> {
    let mut pts = Vec::new();
    for x in -r..=r {
        let y2 = r * r - x * x;
        let y = (y2 as f64).sqrt().round() as i64;
        if y * y == y2 {
            pts.push([x, y]);
            if y != 0 {
                pts.push([x, -y]);
            }
        }
    }
    pts.sort_by(|p, q| {
        let (a, b) = (
            (p[1] as f64).atan2(p[0] as f64),
            (q[1] as f64).atan2(q[0] as f64),
        );
        a.total_cmp(&b)
    });
    pts
}

impl RawCoord {
    /// The coordinate.
    pub fn value(self) -> f64 {
        match self {
            RawCoord::Bits(b) => f64::from_bits(b),
            RawCoord::Special(k) => SPECIAL_VALUES[k as usize % SPECIAL_VALUES.len()],
            RawCoord::Finite {
                mantissa,
                exponent,
                negative,
            } => {
                let e = i32::from(exponent).rem_euclid(2104) - 1080;
                let m = 1.0 + (mantissa & ((1 << 52) - 1)) as f64 / pow2(52);
                let v = ldexp(m, e);
                if negative {
                    -v
                } else {
                    v
                }
            }
        }
    }
}

impl Scene {
    /// The points, at most `max` of them (parts are cut when the budget is spent).
    pub fn points(&self, max: usize) -> Vec<[f64; 2]> {
        let mut out: Vec<[f64; 2]> = Vec::new();
        for part in &self.parts {
            if out.len() >= max {
                break;
            }
            let room = max - out.len();
            match part {
                Part::Lattice { place, points } => {
                    out.extend(
                        points
                            .iter()
                            .take(room)
                            .map(|p| place.place_int([i64::from(p[0]), i64::from(p[1])])),
                    );
                }
                Part::Grid {
                    place,
                    nx,
                    ny,
                    step,
                } => {
                    let (nx, ny) = (i64::from(*nx % 41), i64::from(*ny % 41));
                    let step = i64::from((*step).max(1));
                    let grid = (0..nx).flat_map(|i| (0..ny).map(move |j| [i * step, j * step]));
                    out.extend(grid.take(room).map(|p| place.place_int(p)));
                }
                Part::Line { place, dir, ts } => {
                    let d = [i64::from(dir[0]), i64::from(dir[1])];
                    out.extend(
                        ts.iter()
                            .take(room)
                            .map(|&t| place.place_int([i64::from(t) * d[0], i64::from(t) * d[1]])),
                    );
                }
                Part::Circle {
                    place,
                    radius,
                    all,
                    picks,
                } => {
                    let r = CIRCLE_RADII[*radius as usize % CIRCLE_RADII.len()];
                    let lattice = circle_lattice_points(r);
                    if *all {
                        out.extend(lattice.iter().take(room).map(|&p| place.place_int(p)));
                    } else {
                        out.extend(
                            picks
                                .iter()
                                .take(room)
                                .map(|&k| place.place_int(lattice[k as usize % lattice.len()])),
                        );
                    }
                }
                Part::Curve {
                    place,
                    shape,
                    n,
                    a,
                    b,
                    phase,
                    jitter,
                } => {
                    let n = usize::from((*n).max(3)).min(room);
                    let lobes = f64::from(3 + *b % 5);
                    let (a, b) = (f64::from((*a).max(1)), f64::from((*b).max(1)));
                    let phase = f64::from(*phase) / 65536.0 * std::f64::consts::TAU;
                    let step = std::f64::consts::TAU / n as f64;
                    for i in 0..n {
                        // Deterministic jitter: a fraction of the step, varying with i.
                        let wobble =
                            f64::from(*jitter) / 600.0 * ((i * 7919 % 13) as f64 - 6.0) / 6.0;
                        let t = phase + step * (i as f64 + wobble);
                        let (s, c) = t.sin_cos();
                        let p = match shape % 4 {
                            0 => [a * c, b * s],
                            1 => {
                                let r = a * (1.0 + 0.25 * (lobes * t).cos());
                                [r * c, r * s]
                            }
                            2 => [(a * c).round(), (b * s).round()],
                            _ => [a * c, a * s],
                        };
                        out.push(place.place_real(p));
                    }
                }
                Part::Copies { picks } => {
                    for &k in picks.iter().take(room) {
                        if out.is_empty() {
                            break;
                        }
                        let p = out[k as usize % out.len()];
                        out.push(p);
                    }
                }
                Part::Nudged { picks } => {
                    for &(k, dx, dy) in picks.iter().take(room) {
                        if out.is_empty() {
                            break;
                        }
                        let p = out[k as usize % out.len()];
                        out.push([nudge(p[0], dx % 5), nudge(p[1], dy % 5)]);
                    }
                }
                Part::Raw { coords } => {
                    out.extend(
                        coords
                            .iter()
                            .take(room)
                            .map(|c| [c[0].value(), c[1].value()]),
                    );
                }
            }
        }
        out.truncate(max);
        out
    }
}

/// A permutation of `0..n` from a seed (Fisher–Yates on splitmix64).
pub fn permutation(n: usize, seed: u64) -> Vec<usize> {
    let mut state = seed;
    let mut next = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    };
    let mut perm: Vec<usize> = (0..n).collect();
    for i in (1..n).rev() {
        let j = (next() % (i as u64 + 1)) as usize;
        perm.swap(i, j);
    }
    perm
}
