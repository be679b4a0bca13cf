//! Where the data goes in the picture: a canvas in pixel units, whatever the data's units.
//!
//! The data's bounding box is mapped onto a fixed-size drawing area (its longer side
//! [`DATA_PX`] pixels) by a translation and one scale, the same on both axes, so the shape keeps
//! its aspect; y is flipped for data with y up (the default) and kept for image coordinates.
//! Everything written to the SVG is then a number between 0 and about 1000 with two decimals, so
//! viewers draw a 10⁻⁶ wide part and a 10⁹ wide map alike: no viewer sees the data's units, tiny
//! stroke widths or coordinates with fifteen significant digits.
//!
//! Precision: `(x − min) / unit` loses nothing that matters. `x − min` is exact when `x` and
//! `min` are within a factor of two of each other (Sterbenz), which is the case for data far
//! from the origin (`1e9 + 1e-6 k`), and otherwise has a relative error of 2⁻⁵³ of a length of
//! the drawing. Segments that leave the drawing (Voronoi rays, far circumcenters) are clipped
//! in exact rational arithmetic and rounded once, because clipping a line between two far
//! points in floating point cancels catastrophically near the drawing.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{ToPrimitive, Zero};

/// The longest side of the data's bounding box, in pixels.
pub(super) const DATA_PX: f64 = 720.0;
/// Space around the data, in pixels.
pub(super) const MARGIN_PX: f64 = 30.0;
/// The picture is at least this wide, so that the legend fits next to a thin shape.
pub(super) const MIN_WIDTH_PX: f64 = 420.0;

/// The mapping from data coordinates to the picture's pixels, and the picture's size.
#[derive(Debug, Clone)]
pub(super) struct Canvas {
    /// The data's bounding box.
    min: [f64; 2],
    max: [f64; 2],
    /// Data units per pixel.
    unit: f64,
    /// The pixel position of the bounding box's left edge.
    left_px: f64,
    /// Image coordinates: y grows downwards in the data as in the picture.
    y_down: bool,
    /// Width of the picture in pixels.
    pub(super) width_px: f64,
    /// Height of the drawing area (data and margins), where the legend strip starts.
    pub(super) data_height_px: f64,
}

impl Canvas {
    /// The canvas for `points` (their bounding box; a unit box when there are none).
    pub(super) fn new(points: &[[f64; 2]], y_down: bool) -> Self {
        let (min, max) = bounding_box(points);
        let size = [max[0] - min[0], max[1] - min[1]];
        let extent = size[0].max(size[1]);
        // One distinct point (or none): any scale draws it in the middle.
        // A subnormal extent divided by the picture's size may round to zero: the smallest
        // positive double is then the unit (the points lie on its grid, fewer than
        // `DATA_PX` steps apart).
        let unit = if extent.is_finite() && extent > 0.0 {
            (extent / DATA_PX).max(f64::from_bits(1))
        } else {
            1.0
        };
        let data_px = [size[0] / unit, size[1] / unit];
        let width_px = (data_px[0] + 2.0 * MARGIN_PX).max(MIN_WIDTH_PX);
        Canvas {
            min,
            max,
            unit,
            left_px: 0.5 * (width_px - data_px[0]),
            y_down,
            width_px,
            data_height_px: data_px[1] + 2.0 * MARGIN_PX,
        }
    }

    /// The pixel position of a data point (not clipped; far points may map far away).
    pub(super) fn to_px(&self, p: [f64; 2]) -> [f64; 2] {
        let x = self.left_px + (p[0] - self.min[0]) / self.unit;
        let y = if self.y_down {
            MARGIN_PX + (p[1] - self.min[1]) / self.unit
        } else {
            MARGIN_PX + (self.max[1] - p[1]) / self.unit
        };
        [x, y]
    }

    /// Whether a pixel position lies in the drawing area (margins included).
    pub(super) fn holds_px(&self, q: [f64; 2]) -> bool {
        (0.0..=self.width_px).contains(&q[0]) && (0.0..=self.data_height_px).contains(&q[1])
    }

    /// The part of the segment `a b` inside the drawing area, in pixels.
    pub(super) fn segment(&self, a: [f64; 2], b: [f64; 2]) -> Option<[[f64; 2]; 2]> {
        let (pa, pb) = (self.to_px(a), self.to_px(b));
        match (self.holds_px(pa), self.holds_px(pb)) {
            (true, true) => return Some([pa, pb]),
            // From an end inside, floating point loses nothing that shows: the error is a
            // few units in the last place of the distance to the border.
            (true, false) if pb.iter().all(|v| v.is_finite()) => {
                return Some([
                    pa,
                    self.exit_from_inside(pa, [pb[0] - pa[0], pb[1] - pa[1]], 1.0),
                ])
            }
            (false, true) if pa.iter().all(|v| v.is_finite()) => {
                return Some([
                    self.exit_from_inside(pb, [pa[0] - pb[0], pa[1] - pb[1]], 1.0),
                    pb,
                ])
            }
            (false, false) => {
                let d = [pb[0] - pa[0], pb[1] - pa[1]];
                if self.surely_misses_line(pa, d, 0.0, 1.0) {
                    return None;
                }
            }
            _ => {}
        }
        let origin = self.exact_px(&exact_point(a)?);
        let end = self.exact_px(&exact_point(b)?);
        let dir = [&end[0] - &origin[0], &end[1] - &origin[1]];
        let one = BigRational::from_integer(BigInt::from(1));
        self.clip_exact(&origin, &dir, Some(BigRational::zero()), Some(one))
    }

    /// The part of the ray from `origin` along the data direction `d` inside the drawing area.
    pub(super) fn ray(&self, origin: [f64; 2], d: [f64; 2]) -> Option<[[f64; 2]; 2]> {
        let o = self.to_px(origin);
        let dir = [d[0], if self.y_down { d[1] } else { -d[1] }];
        if dir.iter().all(|v| v.is_finite()) && dir != [0.0, 0.0] {
            if self.holds_px(o) {
                return Some([o, self.exit_from_inside(o, dir, f64::INFINITY)]);
            }
            if self.surely_misses_line(o, dir, 0.0, f64::INFINITY) {
                return None;
            }
        }
        let origin = self.exact_px(&exact_point(origin)?);
        let dir = self.exact_direction(d)?;
        self.clip_exact(&origin, &dir, Some(BigRational::zero()), None)
    }

    /// The part of the perpendicular bisector of `a` and `b` inside the drawing area.
    pub(super) fn bisector(&self, a: [f64; 2], b: [f64; 2]) -> Option<[[f64; 2]; 2]> {
        let (ea, eb) = (exact_point(a)?, exact_point(b)?);
        let half = BigRational::new(BigInt::from(1), BigInt::from(2));
        let mid = [(&ea[0] + &eb[0]) * &half, (&ea[1] + &eb[1]) * &half];
        let origin = self.exact_px(&mid);
        let dir = self.exact_direction([b[1] - a[1], a[0] - b[0]])?;
        self.clip_exact(&origin, &dir, None, None)
    }

    /// Where `inside + t d`, `0 ≤ t ≤ t_max`, from a point in the drawing area, leaves it (or
    /// its end, if that comes first). `d` is finite and not zero.
    fn exit_from_inside(&self, inside: [f64; 2], d: [f64; 2], t_max: f64) -> [f64; 2] {
        let bounds = [self.width_px, self.data_height_px];
        let mut t = t_max;
        for k in 0..2 {
            if d[k] > 0.0 {
                t = t.min((bounds[k] - inside[k]) / d[k]);
            } else if d[k] < 0.0 {
                t = t.min(-inside[k] / d[k]);
            }
        }
        // `t d` may overflow for a tiny `d`: the border is then where the line goes.
        [0, 1].map(|k| {
            let v = inside[k] + t * d[k];
            if v.is_nan() {
                inside[k]
            } else {
                v.clamp(0.0, bounds[k])
            }
        })
    }

    /// Whether `o + t d`, `lo ≤ t ≤ hi`, in pixels, certainly misses the drawing area: it
    /// misses the area grown by more than floating point can err here (Liang–Barsky). `false`
    /// when unsure, or when a value is not finite.
    fn surely_misses_line(&self, o: [f64; 2], d: [f64; 2], lo: f64, hi: f64) -> bool {
        if !o.iter().chain(&d).all(|v| v.is_finite()) {
            return false;
        }
        let bounds = [self.width_px, self.data_height_px];
        let (mut lo, mut hi) = (lo, hi);
        for k in 0..2 {
            let slack = 1.0 + 1e-9 * o[k].abs();
            let (low, high) = (-slack, bounds[k] + slack);
            if d[k] == 0.0 {
                if o[k] < low || o[k] > high {
                    return true;
                }
                continue;
            }
            let (a, b) = ((low - o[k]) / d[k], (high - o[k]) / d[k]);
            lo = lo.max(a.min(b));
            hi = hi.min(a.max(b));
        }
        // Only a clear gap counts: t values carry rounding too.
        lo.is_finite() && hi.is_finite() && lo > hi + 1e-9 * (lo.abs() + hi.abs())
    }

    /// The pixel position of an exact data point.
    fn exact_px(&self, p: &[BigRational; 2]) -> [BigRational; 2] {
        // Every f64 here is finite (checked by `new` and `exact_point`): the conversions hold.
        let r = |v: f64| BigRational::from_float(v).unwrap_or_else(BigRational::zero);
        let unit = r(self.unit);
        let x = r(self.left_px) + (&p[0] - r(self.min[0])) / &unit;
        let dy = if self.y_down {
            &p[1] - r(self.min[1])
        } else {
            r(self.max[1]) - &p[1]
        };
        [x, r(MARGIN_PX) + dy / unit]
    }

    /// A data direction as a pixel direction (the scale does not matter for rays and lines).
    fn exact_direction(&self, d: [f64; 2]) -> Option<[BigRational; 2]> {
        let [dx, dy] = exact_point(d)?;
        if dx.is_zero() && dy.is_zero() {
            return None;
        }
        Some([dx, if self.y_down { dy } else { -dy }])
    }

    /// Clips `origin + t dir` for `lo ≤ t ≤ hi` (`None`: unbounded) to the drawing area
    /// (Liang–Barsky, exactly), and rounds the ends to pixels.
    fn clip_exact(
        &self,
        origin: &[BigRational; 2],
        dir: &[BigRational; 2],
        mut lo: Option<BigRational>,
        mut hi: Option<BigRational>,
    ) -> Option<[[f64; 2]; 2]> {
        let bounds = [self.width_px, self.data_height_px];
        for k in 0..2 {
            let low = BigRational::zero();
            let high = BigRational::from_float(bounds[k])?;
            if dir[k].is_zero() {
                if origin[k] < low || origin[k] > high {
                    return None;
                }
                continue;
            }
            let a = (&low - &origin[k]) / &dir[k];
            let b = (&high - &origin[k]) / &dir[k];
            let (enter, leave) = if a <= b { (a, b) } else { (b, a) };
            lo = Some(match lo {
                Some(t) if t >= enter => t,
                _ => enter,
            });
            hi = Some(match hi {
                Some(t) if t <= leave => t,
                _ => leave,
            });
        }
        let (lo, hi) = (lo?, hi?);
        if lo > hi {
            return None;
        }
        let at = |t: &BigRational| -> Option<[f64; 2]> {
            Some([
                (&origin[0] + t * &dir[0]).to_f64()?,
                (&origin[1] + t * &dir[1]).to_f64()?,
            ])
        };
        Some([at(&lo)?, at(&hi)?])
    }
}

/// A finite data point as exact rationals.
fn exact_point(p: [f64; 2]) -> Option<[BigRational; 2]> {
    Some([
        BigRational::from_float(p[0])?,
        BigRational::from_float(p[1])?,
    ])
}

/// The bounding box of `points`, or the unit square when there are none.
pub(super) fn bounding_box(points: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
    let mut min = [f64::INFINITY; 2];
    let mut max = [f64::NEG_INFINITY; 2];
    for p in points {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    if points.is_empty() {
        ([0.0; 2], [1.0; 2])
    } else {
        (min, max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (xorshift64) of values in [-1, 1).
    fn pseudo_random(state: &mut u64) -> f64 {
        *state ^= *state << 13;
        *state ^= *state >> 7;
        *state ^= *state << 17;
        (*state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    #[test]
    fn the_floating_point_shortcuts_agree_with_exact_clipping() {
        let mut state = 0x9e37_79b9_7f4a_7c15;
        for y_down in [false, true] {
            let canvas = Canvas::new(&[[0.0, 0.0], [1.0, 0.5]], y_down);
            let exact_segment = |a: [f64; 2], b: [f64; 2]| {
                let (ea, eb) = (exact_point(a).unwrap(), exact_point(b).unwrap());
                let (pa, pb) = (canvas.exact_px(&ea), canvas.exact_px(&eb));
                let dir = [&pb[0] - &pa[0], &pb[1] - &pa[1]];
                let one = BigRational::from_integer(BigInt::from(1));
                canvas.clip_exact(&pa, &dir, Some(BigRational::zero()), Some(one))
            };
            let exact_ray = |o: [f64; 2], d: [f64; 2]| {
                let origin = canvas.exact_px(&exact_point(o).unwrap());
                let dir = canvas.exact_direction(d).unwrap();
                canvas.clip_exact(&origin, &dir, Some(BigRational::zero()), None)
            };
            let close = |a: Option<[[f64; 2]; 2]>, b: Option<[[f64; 2]; 2]>| match (a, b) {
                (Some(a), Some(b)) => {
                    (0..2).all(|i| (0..2).all(|k| (a[i][k] - b[i][k]).abs() < 1e-6))
                }
                (a, b) => a.is_none() && b.is_none(),
            };
            for _ in 0..2000 {
                let mut r = || pseudo_random(&mut state);
                let inside = [0.5 + 0.5 * r(), 0.25 + 0.25 * r()];
                let scale = 10f64.powi((6.0 * r()).round() as i32);
                let far = [inside[0] + scale * r(), inside[1] + scale * r()];
                let d = [r(), r()];
                let outside = [3.0 + 2.0 * r(), 3.0 * r()];
                for (a, b) in [(inside, far), (far, inside), (outside, far)] {
                    let (fast, exact) = (canvas.segment(a, b), exact_segment(a, b));
                    assert!(close(fast, exact), "{a:?} {b:?}: {fast:?} vs {exact:?}");
                }
                for o in [inside, far, outside] {
                    let (fast, exact) = (canvas.ray(o, d), exact_ray(o, d));
                    assert!(close(fast, exact), "{o:?} {d:?}: {fast:?} vs {exact:?}");
                }
            }
        }
    }
}
