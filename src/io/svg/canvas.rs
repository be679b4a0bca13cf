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
        let unit = if extent.is_finite() && extent > 0.0 {
            extent / DATA_PX
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
        if self.holds_px(pa) && self.holds_px(pb) {
            return Some([pa, pb]);
        }
        let origin = self.exact_px(&exact_point(a)?);
        let end = self.exact_px(&exact_point(b)?);
        let dir = [&end[0] - &origin[0], &end[1] - &origin[1]];
        let one = BigRational::from_integer(BigInt::from(1));
        self.clip_exact(&origin, &dir, Some(BigRational::zero()), Some(one))
    }

    /// The part of the ray from `origin` along the data direction `d` inside the drawing area.
    pub(super) fn ray(&self, origin: [f64; 2], d: [f64; 2]) -> Option<[[f64; 2]; 2]> {
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
