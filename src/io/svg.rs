//! Drawing a reconstruction as an SVG picture that a person can read at a glance.
//!
//! [`write_reconstruction_svg`] draws, from back to front:
//!
//! * optional underlays chosen with [`SvgOptions`]: the Delaunay edges (faint grey), the
//!   Voronoi diagram (finite edges and rays, faint blue, clipped to the picture) and the
//!   water-flow labels of the Voronoi vertices (inner orange, outer blue dots);
//! * the medial axis (thin, green);
//! * the reconstructed curves (strong: closed loops red, open chains purple);
//! * the points (small black dots; the [unassigned](crate::Reconstruction::unassigned) points,
//!   on no curve, as hollow grey rings);
//! * a legend below the drawing: a title line, then one entry per layer with its count.
//!
//! The picture is drawn on a canvas in pixels, not in the data's units: the data's bounding
//! box is scaled (the same on both axes) so that its longer side is 720 px, with a 30 px
//! margin and the legend strip below; the `viewBox` is `0 0 width height` in those pixels.
//! Every coordinate written is a number of pixels with two decimals, so data 10⁻⁶ units wide
//! and data 10⁹ units wide (or 10⁹ units from the origin) render alike in every viewer. The y
//! axis points up, as in the input, unless [`SvgOptions::y_down`] says that the data is in
//! image coordinates. Stroke widths and dot sizes follow the mean length of the reconstructed
//! edges, so dense and sparse samples both stay readable. The document starts with `<svg` (no
//! XML declaration) and is UTF-8.

mod canvas;
mod legend;

use std::fmt::Write as _;
use std::io::{self, BufWriter, Write};

use self::canvas::{bounding_box, Canvas, DATA_PX};
use self::legend::{legend_items, write_legend};
use crate::delaunay::NO_TWIN;
use crate::reconstruct::Label;
use crate::Reconstruction;

/// What to draw besides the points, the curves and the medial axis, and which way is up.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct SvgOptions {
    /// Draw the Delaunay edges under everything (faint grey).
    pub delaunay: bool,
    /// Draw the Voronoi diagram (finite edges and rays clipped to the picture, faint blue);
    /// for collinear input, the bisectors of consecutive points.
    pub voronoi: bool,
    /// Draw the Voronoi vertices as dots coloured by their water-flow label (inner orange,
    /// outer blue). Only WDM labels its vertices: for the baseline algorithms there is nothing
    /// to draw and the legend says so.
    pub labels: bool,
    /// The first line of the legend and the document's `<title>`; by default the algorithm
    /// and the number of points.
    pub title: Option<String>,
    /// The data is in image coordinates (y grows downwards, as in pixel positions of a
    /// scanned picture): draw it with y down so that it is the right way up. By default y
    /// grows upwards, as in a plot. Only the picture changes; the data is not touched.
    pub y_down: bool,
}

// Colours.
const POINT: &str = "#111111";
const UNASSIGNED: &str = "#8c8c8c";
const CLOSED: &str = "#d62728";
const OPEN: &str = "#7b3fb5";
const MEDIAL: &str = "#2ca02c";
const DELAUNAY: &str = "#bdbdbd";
const VORONOI: &str = "#8fb9dc";
const INNER: &str = "#ff7f0e";
const OUTER: &str = "#1f77b4";

/// Writes `rec` as an SVG document (see the [module docs](self)).
///
/// # Errors
/// Any error of `out`.
///
/// ```
/// let octagon: Vec<[f64; 2]> = (0..8)
///     .map(|k| [(k as f64 * 0.785).cos(), (k as f64 * 0.785).sin()])
///     .collect();
/// let rec = wdm_crust::reconstruct(&octagon)?;
/// let mut options = wdm_crust::io::SvgOptions::default();
/// options.delaunay = true;
/// options.y_down = true;
/// let mut out = Vec::new();
/// wdm_crust::io::write_reconstruction_svg(&rec, &options, &mut out)?;
/// let svg = String::from_utf8(out)?;
/// assert!(svg.starts_with("<svg "));
/// assert!(svg.contains(" viewBox=\"0 0 "));
/// assert!(svg.trim_end().ends_with("</svg>"));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn write_reconstruction_svg<W: Write>(
    rec: &Reconstruction,
    options: &SvgOptions,
    out: W,
) -> io::Result<()> {
    let mut out = BufWriter::with_capacity(1 << 16, out);
    let tri = rec.triangulation();
    // The caller's points, duplicates included: everything drawn is in caller indices.
    let points: Vec<[f64; 2]> = (0..tri.point_count() as u32)
        .map(|i| tri.point(i))
        .collect();
    let points = &points[..];
    let style = Style::new(rec, points);
    let legend = legend_items(rec, options, &style);
    let canvas = Canvas::new(points, options.y_down);
    let height_px = canvas.data_height_px + legend.height_px(canvas.width_px);
    let mut w = SvgWriter {
        out: &mut out,
        buf: String::new(),
    };

    let (width, height) = (canvas.width_px, height_px);
    let _ = write!(
        w.buf,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width:.2}\" height=\"{height:.2}\" \
         viewBox=\"0 0 {width:.2} {height:.2}\" font-family=\"sans-serif\">\n<title>"
    );
    escape_into(&mut w.buf, &legend.title);
    let _ = write!(
        w.buf,
        "</title>\n<rect fill=\"#ffffff\" x=\"0\" y=\"0\" width=\"{width:.2}\" height=\"{height:.2}\"/>\n"
    );
    w.flush()?;

    if options.delaunay {
        w.open_stroke_group("delaunay", DELAUNAY, 0.7)?;
        if tri.is_degenerate() {
            for pair in tri.hull().windows(2) {
                w.segment(canvas.segment(points[pair[0] as usize], points[pair[1] as usize]))?;
            }
        } else {
            for (e, &twin) in tri.halfedges().iter().enumerate() {
                if twin == NO_TWIN || (e as u32) < twin {
                    let a = points[tri.halfedge_origin(e) as usize];
                    let b = points[tri.halfedge_destination(e) as usize];
                    w.segment(canvas.segment(a, b))?;
                }
            }
        }
        w.close_group()?;
    }

    let needs_voronoi = options.voronoi || (options.labels && !rec.labels().is_empty());
    let vor = needs_voronoi.then(|| tri.voronoi());
    if let (true, Some(vor)) = (options.voronoi, &vor) {
        w.open_stroke_group("voronoi", VORONOI, 0.8)?;
        let positions = vor.vertex_positions();
        for (_, a, b) in vor.finite_edges() {
            w.segment(canvas.segment(positions[a as usize], positions[b as usize]))?;
        }
        for (_, v, d) in vor.rays() {
            w.segment(canvas.ray(positions[v as usize], d))?;
        }
        for [a, b] in vor.collinear_bisectors() {
            w.segment(canvas.bisector(points[a as usize], points[b as usize]))?;
        }
        w.close_group()?;
    }
    if let (true, Some(vor)) = (options.labels, &vor) {
        for (label, colour, id) in [
            (Label::Outer, OUTER, "outer-vertices"),
            (Label::Inner, INNER, "inner-vertices"),
        ] {
            w.open_fill_group(id, colour)?;
            for (&l, &p) in rec.labels().iter().zip(vor.vertex_positions()) {
                let q = canvas.to_px(p);
                if l == label && canvas.holds_px(q) {
                    w.dot(q, style.label_radius)?;
                }
            }
            w.close_group()?;
        }
    }

    let axis = rec.medial_axis();
    if !axis.edges.is_empty() {
        w.open_stroke_group("medial-axis", MEDIAL, style.axis_width)?;
        for &[a, b] in &axis.edges {
            let (pa, pb) = (axis.vertices[a as usize], axis.vertices[b as usize]);
            w.segment(canvas.segment(pa, pb))?;
        }
        w.close_group()?;
    }

    for (closed, colour, id) in [
        (true, CLOSED, "closed-curves"),
        (false, OPEN, "open-chains"),
    ] {
        if !rec.curves().iter().any(|c| c.closed == closed) {
            continue;
        }
        w.open_stroke_group(id, colour, style.curve_width)?;
        for curve in rec.curves().iter().filter(|c| c.closed == closed) {
            // Through the fitted positions with smoothing.
            let path = curve
                .points
                .iter()
                .map(|&i| canvas.to_px(rec.curve_vertex(i).unwrap_or(points[i as usize])));
            w.polyline(path, closed)?;
        }
        w.close_group()?;
    }

    let mut skip = vec![false; points.len()];
    for &[duplicate, _] in tri.duplicates() {
        skip[duplicate as usize] = true;
    }
    for &p in rec.unassigned() {
        skip[p as usize] = true;
    }
    w.open_fill_group("points", POINT)?;
    for (p, &point) in points.iter().enumerate() {
        if !skip[p] {
            w.dot(canvas.to_px(point), style.point_radius)?;
        }
    }
    w.close_group()?;
    if !rec.unassigned().is_empty() {
        let _ = write!(
            w.buf,
            "<g id=\"unassigned-points\" fill=\"#ffffff\" stroke=\"{UNASSIGNED}\" stroke-width=\""
        );
        w.num(0.35 * style.point_radius);
        w.buf.push_str("\">\n");
        for &p in rec.unassigned() {
            w.dot(canvas.to_px(points[p as usize]), 1.3 * style.point_radius)?;
        }
        w.close_group()?;
    }
    w.flush()?;

    write_legend(&mut w, canvas.data_height_px, canvas.width_px, &legend)?;
    w.buf.push_str("</svg>\n");
    w.flush()?;
    out.flush()
}

/// Sizes in pixels that depend on the data: the denser the points, the finer the lines.
pub(super) struct Style {
    pub(super) point_radius: f64,
    curve_width: f64,
    axis_width: f64,
    label_radius: f64,
}

impl Style {
    fn new(rec: &Reconstruction, points: &[[f64; 2]]) -> Self {
        let (min, max) = bounding_box(points);
        let extent = (max[0] - min[0]).max(max[1] - min[1]);
        let length = |&[a, b]: &[u32; 2]| {
            let (p, q) = (points[a as usize], points[b as usize]);
            (q[0] - p[0]).hypot(q[1] - p[1])
        };
        // The typical spacing of the samples, in pixels.
        let spacing_px = if extent > 0.0 && !rec.edges().is_empty() {
            let mean = rec.edges().iter().map(length).sum::<f64>() / rec.edges().len() as f64;
            mean / extent * DATA_PX
        } else if extent > 0.0 && points.len() > 1 {
            DATA_PX / (points.len() as f64).sqrt()
        } else {
            20.0
        };
        let curve_width = (0.16 * spacing_px).clamp(0.8, 2.2);
        let point_radius = (0.2 * spacing_px).clamp(0.9, 3.5).max(0.9 * curve_width);
        Style {
            point_radius,
            curve_width,
            axis_width: (0.6 * curve_width).max(0.7),
            label_radius: (0.8 * point_radius).max(0.9),
        }
    }
}

/// Appends `text` with the XML special characters escaped.
pub(super) fn escape_into(buf: &mut String, text: &str) {
    for c in text.chars() {
        match c {
            '&' => buf.push_str("&amp;"),
            '<' => buf.push_str("&lt;"),
            '>' => buf.push_str("&gt;"),
            '"' => buf.push_str("&quot;"),
            c if c.is_control() => buf.push(' '),
            c => buf.push(c),
        }
    }
}

/// Writes SVG elements through a reusable text buffer, numbers in pixels with two decimals.
pub(super) struct SvgWriter<'w, W: Write> {
    out: &'w mut W,
    pub(super) buf: String,
}

impl<W: Write> SvgWriter<'_, W> {
    /// Appends one number of pixels, to 1/100 px (never `-0.00`).
    fn num(&mut self, x: f64) {
        let start = self.buf.len();
        let _ = write!(self.buf, "{x:.2}");
        let written = &self.buf[start..];
        if written.starts_with('-') && written[1..].bytes().all(|b| b == b'0' || b == b'.') {
            self.buf.remove(start);
        }
    }

    /// Appends numbers separated by spaces.
    fn nums(&mut self, xs: &[f64]) {
        for (i, &x) in xs.iter().enumerate() {
            if i > 0 {
                self.buf.push(' ');
            }
            self.num(x);
        }
    }

    /// Writes out the buffer when it is large (or always, from `flush`).
    pub(super) fn maybe_flush(&mut self) -> io::Result<()> {
        if self.buf.len() >= 1 << 15 {
            self.flush()?;
        }
        Ok(())
    }

    pub(super) fn flush(&mut self) -> io::Result<()> {
        self.out.write_all(self.buf.as_bytes())?;
        self.buf.clear();
        Ok(())
    }

    /// `<g id=.. fill="none" stroke=..>` for lines.
    fn open_stroke_group(&mut self, id: &str, colour: &str, width: f64) -> io::Result<()> {
        let _ = write!(
            self.buf,
            "<g id=\"{id}\" fill=\"none\" stroke=\"{colour}\" stroke-linecap=\"round\" stroke-linejoin=\"round\" stroke-width=\""
        );
        self.num(width);
        self.buf.push_str("\">\n");
        self.maybe_flush()
    }

    /// `<g id=.. fill=..>` for dots.
    fn open_fill_group(&mut self, id: &str, colour: &str) -> io::Result<()> {
        let _ = writeln!(self.buf, "<g id=\"{id}\" fill=\"{colour}\">");
        self.maybe_flush()
    }

    fn close_group(&mut self) -> io::Result<()> {
        self.buf.push_str("</g>\n");
        self.maybe_flush()
    }

    /// One straight segment (in pixels, already clipped) as a path.
    fn segment(&mut self, ends: Option<[[f64; 2]; 2]>) -> io::Result<()> {
        match ends {
            Some(ends) => self.polyline(ends.into_iter(), false),
            None => Ok(()),
        }
    }

    /// A polyline in pixels (closed with `Z` if `closed`) as a path.
    fn polyline(&mut self, points: impl Iterator<Item = [f64; 2]>, closed: bool) -> io::Result<()> {
        self.buf.push_str("<path d=\"");
        for (i, p) in points.enumerate() {
            self.buf.push(if i == 0 { 'M' } else { 'L' });
            self.nums(&p);
            if self.buf.len() >= 1 << 15 {
                self.flush()?;
            }
        }
        if closed {
            self.buf.push('Z');
        }
        self.buf.push_str("\"/>\n");
        self.maybe_flush()
    }

    /// A circle at a position in pixels.
    fn dot(&mut self, p: [f64; 2], r: f64) -> io::Result<()> {
        self.buf.push_str("<circle cx=\"");
        self.num(p[0]);
        self.buf.push_str("\" cy=\"");
        self.num(p[1]);
        self.buf.push_str("\" r=\"");
        self.num(r);
        self.buf.push_str("\"/>\n");
        self.maybe_flush()
    }
}

#[cfg(test)]
mod tests;
