//! Concrete smooth closed curves for ground-truth inputs.

use super::curve::ClosedCurve;
use std::f64::consts::TAU;

/// Point and `d/dt` of a polar curve `r(θ)` with `θ = 2πt`, given `r` and `dr/dθ`.
fn polar(theta: f64, r: f64, dr: f64) -> ([f64; 2], [f64; 2]) {
    let (s, c) = theta.sin_cos();
    let point = [r * c, r * s];
    let derivative = [TAU * (dr * c - r * s), TAU * (dr * s + r * c)];
    (point, derivative)
}

/// The axis-aligned ellipse `(x/a)² + (y/b)² = 1`, counter-clockwise from `(a, 0)`.
///
/// For `a > b` its medial axis is the segment between `(±(a²−b²)/a, 0)`, so its local
/// feature size is known exactly (see [`Ellipse::exact_lfs`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    /// Semi-axis along x (positive).
    pub a: f64,
    /// Semi-axis along y (positive).
    pub b: f64,
}

impl Ellipse {
    /// The circle of radius `r` centred at the origin.
    pub fn circle(r: f64) -> Self {
        Ellipse { a: r, b: r }
    }

    /// The exact local feature size at a point `p` of the ellipse: its distance to the medial
    /// axis, the segment between the centres of curvature of the two ends of the major axis.
    pub fn exact_lfs(&self, p: [f64; 2]) -> f64 {
        let (major, minor, along, across) = if self.a >= self.b {
            (self.a, self.b, p[0], p[1])
        } else {
            (self.b, self.a, p[1], p[0])
        };
        let half = (major * major - minor * minor) / major;
        let nearest = along.clamp(-half, half);
        (along - nearest).hypot(across)
    }
}

impl ClosedCurve for Ellipse {
    fn point(&self, t: f64) -> [f64; 2] {
        let (s, c) = (TAU * t).sin_cos();
        [self.a * c, self.b * s]
    }

    fn derivative(&self, t: f64) -> [f64; 2] {
        let (s, c) = (TAU * t).sin_cos();
        [-TAU * self.a * s, TAU * self.b * c]
    }
}

/// The smooth star `r(θ) = 1 + a·cos(kθ)`.
///
/// Simple for `|a| < 1`; keep `|a|` moderate (about `≤ 0.3` for `k = 5`) so the dents stay
/// gentle and the curve well sampled by moderate ε.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Star {
    /// Amplitude of the radial wave, `|a| < 1`.
    pub a: f64,
    /// Number of arms.
    pub k: u32,
}

impl Star {
    fn eval(&self, t: f64) -> ([f64; 2], [f64; 2]) {
        let theta = TAU * t;
        let k = f64::from(self.k);
        let (s, c) = (k * theta).sin_cos();
        polar(theta, 1.0 + self.a * c, -self.a * k * s)
    }
}

impl ClosedCurve for Star {
    fn point(&self, t: f64) -> [f64; 2] {
        self.eval(t).0
    }

    fn derivative(&self, t: f64) -> [f64; 2] {
        self.eval(t).1
    }
}

/// A non-convex "peanut"/bean `r(θ) = 1 + a·cos(2θ) + b·cos(3θ)`.
///
/// Simple for `|a| + |b| < 1`; `a = 0.3, b = 0.15` gives a bean with one clear waist.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peanut {
    /// Amplitude of the `cos 2θ` term.
    pub a: f64,
    /// Amplitude of the `cos 3θ` term.
    pub b: f64,
}

impl Peanut {
    fn eval(&self, t: f64) -> ([f64; 2], [f64; 2]) {
        let theta = TAU * t;
        let (s2, c2) = (2.0 * theta).sin_cos();
        let (s3, c3) = (3.0 * theta).sin_cos();
        let r = 1.0 + self.a * c2 + self.b * c3;
        let dr = -2.0 * self.a * s2 - 3.0 * self.b * s3;
        polar(theta, r, dr)
    }
}

impl ClosedCurve for Peanut {
    fn point(&self, t: f64) -> [f64; 2] {
        self.eval(t).0
    }

    fn derivative(&self, t: f64) -> [f64; 2] {
        self.eval(t).1
    }
}

/// The superellipse `|x/a|^p + |y/b|^p = 1` in polar form, `r(θ) = (|cos θ/a|^p + |sin θ/b|^p)^(-1/p)`.
///
/// Convex and at least twice differentiable for `p ≥ 2` (a rounded rectangle for large `p`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Superellipse {
    /// Semi-axis along x.
    pub a: f64,
    /// Semi-axis along y.
    pub b: f64,
    /// Exponent, `p ≥ 2`.
    pub p: f64,
}

impl Superellipse {
    fn eval(&self, t: f64) -> ([f64; 2], [f64; 2]) {
        let theta = TAU * t;
        let (s, c) = theta.sin_cos();
        let p = self.p;
        let (u, v) = (c / self.a, s / self.b);
        // f = |u|^p + |v|^p, r = f^(-1/p); df/dθ uses d|u|^p/du = p |u|^(p-1) sgn u.
        let f = u.abs().powf(p) + v.abs().powf(p);
        let df = p * u.abs().powf(p - 1.0) * u.signum() * (-s / self.a)
            + p * v.abs().powf(p - 1.0) * v.signum() * (c / self.b);
        let r = f.powf(-1.0 / p);
        let dr = -r / (p * f) * df;
        polar(theta, r, dr)
    }
}

impl ClosedCurve for Superellipse {
    fn point(&self, t: f64) -> [f64; 2] {
        self.eval(t).0
    }

    fn derivative(&self, t: f64) -> [f64; 2] {
        self.eval(t).1
    }
}

/// A random-looking smooth blob `r(θ) = 1 + Σ_k a_k cos(kθ + φ_k)`, `k = 2, 3, …`: broad lobes
/// whose medial branches have a small object angle all along.
///
/// Simple (star-shaped) while `Σ |a_k| < 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct FourierBlob {
    /// `(a_k, φ_k)` for `k = 2, 3, …` in order.
    pub terms: Vec<(f64, f64)>,
}

impl FourierBlob {
    /// Terms for `k = 2..=5` with `a_k` uniform in `[0, 0.3 / k)` and a uniform phase.
    pub fn random(rng: &mut crate::Rng) -> Self {
        let terms = (2..=5)
            .map(|k| (rng.range(0.0, 0.3 / f64::from(k)), rng.range(0.0, TAU)))
            .collect();
        FourierBlob { terms }
    }

    fn eval(&self, t: f64) -> ([f64; 2], [f64; 2]) {
        let theta = TAU * t;
        let (mut r, mut dr) = (1.0, 0.0);
        for (i, &(a, phase)) in self.terms.iter().enumerate() {
            let k = (i + 2) as f64;
            let (s, c) = (k * theta + phase).sin_cos();
            r += a * c;
            dr -= a * k * s;
        }
        polar(theta, r, dr)
    }
}

impl ClosedCurve for FourierBlob {
    fn point(&self, t: f64) -> [f64; 2] {
        self.eval(t).0
    }

    fn derivative(&self, t: f64) -> [f64; 2] {
        self.eval(t).1
    }
}
