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
//!   on no curve, as hollow grey rings), unless [`SvgOptions::points`] leaves them out or
//!   they are too dense for dots (below);
//! * a legend below the drawing: a title line, then one entry per layer with its count.
//!
//! The picture is drawn on a canvas in pixels, not in the data's units: the data's bounding
//! box is scaled (the same on both axes) so that its longer side is 720 px, with a 30 px
//! margin and the legend strip below; the `viewBox` is `0 0 width height` in those pixels.
//! Every coordinate written is a number of pixels with two decimals, so data 10⁻⁶ units wide
//! and data 10⁹ units wide (or 10⁹ units from the origin) render alike in every viewer. The y
//! axis points up, as in the input, unless [`SvgOptions::y_down`] says that the data is in
//! image coordinates. The document starts with `<svg` (no XML declaration) and is UTF-8.
//!
//! Sizes follow the samples' spacing `s`: the median length of the reconstructed edges in
//! pixels (with no edges, the spacing of as many points spread evenly over the drawing).
//! Curves are `0.16 s` wide (0.8 to 2.2 px), the medial axis 0.6 times that (at least 0.7
//! px). Dots have the radius `0.2 s`, at most 3.5 px and at least 0.9 times the curves'
//! width, so that a dot stands out from the curve it is on. Where that radius is more than
//! `0.3 s` (samples less than 2.4 px apart), dots would cover the curve between them: the
//! dots are left out and the legend says so, and the unassigned points are drawn as unfilled
//! rings of the smallest size, through which the curves show.
//!
//! Large inputs give files that viewers open: a vertex of a curve whose written coordinates
//! are those of the vertex written before it is left out (never a curve's first or last
//! vertex), and a dot at the written position of a dot already drawn in its layer is not
//! drawn again; neither changes a pixel. A path's `d` attribute holds at most 64 KiB: a
//! longer curve goes on in further `<path>` elements, each from the last vertex of the one
//! before, so that its stroke is unbroken. Every element ends its line, so no line but a
//! long title's is longer than that.

mod canvas;
mod legend;

use std::collections::HashSet;
use std::fmt::Write as _;
use std::io::{self, BufWriter, Write};

use self::canvas::{bounding_box, Canvas, DATA_PX};
use self::legend::{legend_items, write_legend};
use crate::delaunay::NO_TWIN;
use crate::reconstruct::Label;
use crate::Reconstruction;

/// What to draw besides the curves and the medial axis, and which way is up.
#[derive(Debug, Clone, PartialEq, Eq)]
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
    /// Draw the input points (the default): dots on the curves' points, rings on the
    /// unassigned ones. `false` leaves out both, dots and rings, so that the curves and the
    /// axis are seen alone; the legend still counts the points. Points too dense for dots
    /// are left out whatever this says (see the [module docs](self)).
    pub points: bool,
}

impl Default for SvgOptions {
    fn default() -> Self {
        SvgOptions {
            delaunay: false,
            voronoi: false,
            labels: false,
            title: None,
            y_down: false,
            points: true,
        }
    }
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
    let style = Style::new(rec, points, options.points);
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
            for (a, b) in tri.hull().zip(tri.hull().skip(1)) {
                w.segment(canvas.segment(points[a as usize], points[b as usize]))?;
            }
        } else {
            for (e, &twin) in tri.halfedge_ids().zip(tri.halfedges()) {
                if twin == NO_TWIN || e < twin {
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
            w.segment(canvas.segment(positions[a.index()], positions[b.index()]))?;
        }
        for (_, v, d) in vor.rays() {
            w.segment(canvas.ray(positions[v.index()], d))?;
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
            let positions = rec
                .labels()
                .iter()
                .zip(vor.vertex_positions())
                .filter(|&(&l, _)| l == label)
                .map(|(_, &p)| canvas.to_px(p))
                .filter(|&q| canvas.holds_px(q));
            w.dots(positions, style.label_radius)?;
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

    if style.dots == Dots::Drawn {
        let mut skip = vec![false; points.len()];
        for &[duplicate, _] in tri.duplicates() {
            skip[duplicate as usize] = true;
        }
        for &p in rec.unassigned() {
            skip[p as usize] = true;
        }
        w.open_fill_group("points", POINT)?;
        let positions = points
            .iter()
            .zip(skip)
            .filter(|&(_, skip)| !skip)
            .map(|(&p, _)| canvas.to_px(p));
        w.dots(positions, style.point_radius)?;
        w.close_group()?;
    }
    if style.dots != Dots::Off && !rec.unassigned().is_empty() {
        // Over dense curves the rings are hollow: the curve shows through them.
        let fill = if style.dots == Dots::Drawn {
            "#ffffff"
        } else {
            "none"
        };
        let _ = write!(
            w.buf,
            "<g id=\"unassigned-points\" fill=\"{fill}\" stroke=\"{UNASSIGNED}\" stroke-width=\""
        );
        w.num(0.35 * style.point_radius);
        w.buf.push_str("\">\n");
        let positions = rec
            .unassigned()
            .iter()
            .map(|&p| canvas.to_px(points[p as usize]));
        w.dots(positions, 1.3 * style.point_radius)?;
        w.close_group()?;
    }
    w.flush()?;

    write_legend(&mut w, canvas.data_height_px, canvas.width_px, &legend)?;
    w.buf.push_str("</svg>\n");
    w.flush()?;
    out.flush()
}

/// How the input points are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Dots {
    /// Dots on the curves' points, white-filled rings on the unassigned ones.
    Drawn,
    /// No dots: the samples are too close for dots that stand out from the curve and leave
    /// it visible. Unassigned points are unfilled rings.
    TooDense,
    /// Neither dots nor rings ([`SvgOptions::points`] is `false`).
    Off,
}

/// Sizes in pixels that depend on the data: the denser the points, the finer the lines.
pub(super) struct Style {
    pub(super) dots: Dots,
    /// The radius of a point's dot (that of the rings follows it), also when no dots are
    /// drawn.
    pub(super) point_radius: f64,
    curve_width: f64,
    axis_width: f64,
    label_radius: f64,
}

impl Style {
    fn new(rec: &Reconstruction, points: &[[f64; 2]], draw_points: bool) -> Self {
        let spacing_px = spacing_px(rec, points);
        let curve_width = (0.16 * spacing_px).clamp(0.8, 2.2);
        // At least 0.9 times the curve's width: a dot is wider than the stroke it is on.
        let point_radius = (0.2 * spacing_px).max(0.9 * curve_width).min(3.5);
        // Dots wider than 0.6 of the spacing leave less than 0.4 of the curve between them
        // in sight; at the smallest radius (0.72 px) that is a spacing under 2.4 px.
        let dots = if !draw_points {
            Dots::Off
        } else if point_radius > 0.3 * spacing_px {
            Dots::TooDense
        } else {
            Dots::Drawn
        };
        Style {
            dots,
            point_radius,
            curve_width,
            axis_width: (0.6 * curve_width).max(0.7),
            label_radius: (0.8 * point_radius).max(0.9),
        }
    }
}

/// The typical spacing of the samples in pixels: the median length of the reconstructed
/// edges (the median, not the mean, so that a few long edges across a gap do not make dense
/// samples look sparse); without edges, the spacing of the points spread evenly over the
/// drawing; 20 px for a single point.
fn spacing_px(rec: &Reconstruction, points: &[[f64; 2]]) -> f64 {
    let (min, max) = bounding_box(points);
    let extent = (max[0] - min[0]).max(max[1] - min[1]);
    let spacing = if extent > 0.0 && !rec.edges().is_empty() {
        let mut lengths: Vec<f64> = rec
            .edges()
            .iter()
            .map(|&[a, b]| {
                let (p, q) = (points[a as usize], points[b as usize]);
                (q[0] - p[0]).hypot(q[1] - p[1])
            })
            .collect();
        let middle = lengths.len() / 2;
        let (_, &mut median, _) = lengths.select_nth_unstable_by(middle, f64::total_cmp);
        median / extent * DATA_PX
    } else if extent > 0.0 && points.len() > 1 {
        DATA_PX / (points.len() as f64).sqrt()
    } else {
        20.0
    };
    // Extents beyond f64's range (an infinite width) have no sensible spacing.
    if spacing.is_finite() && spacing > 0.0 {
        spacing
    } else {
        20.0
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

/// The longest `d` attribute written, in bytes; a longer curve is split into several paths.
/// libxml2, which parses SVG for rsvg-convert and many other viewers, refuses an attribute
/// value of 10⁷ bytes or more (unless told to read "huge" documents), and text tools slow to
/// a crawl on lines of megabytes. 64 KiB (some 4,500 vertices) is far below both, and costs
/// one `"/>` and `<path d="M x y` (under 30 bytes) per piece: less than 0.05 % of the file.
pub(super) const MAX_PATH_DATA: usize = 1 << 16;

/// The buffer is written out when it reaches this size.
const FLUSH_BYTES: usize = 1 << 15;

/// Appends one number of pixels, to 1/100 px (never `-0.00`).
fn push_px(buf: &mut String, x: f64) {
    let start = buf.len();
    let _ = write!(buf, "{x:.2}");
    let written = &buf[start..];
    if written.starts_with('-') && written[1..].bytes().all(|b| b == b'0' || b == b'.') {
        buf.remove(start);
    }
}

/// Appends a position in pixels, `x y`.
fn push_position(buf: &mut String, p: [f64; 2]) {
    push_px(buf, p[0]);
    buf.push(' ');
    push_px(buf, p[1]);
}

/// A number as written by [`push_px`], in hundredths of a pixel (`None` beyond `i64`).
fn hundredths(written: &str) -> Option<i64> {
    let mut value: i64 = 0;
    for b in written.bytes() {
        match b {
            b'0'..=b'9' => value = value.checked_mul(10)?.checked_add(i64::from(b - b'0'))?,
            b'.' | b'-' => {}
            _ => return None,
        }
    }
    Some(if written.starts_with('-') {
        -value
    } else {
        value
    })
}

/// Writes SVG elements through a reusable text buffer, numbers in pixels with two decimals.
pub(super) struct SvgWriter<'w, W: Write> {
    out: &'w mut W,
    pub(super) buf: String,
}

impl<W: Write> SvgWriter<'_, W> {
    /// Appends one number of pixels, to 1/100 px (never `-0.00`).
    fn num(&mut self, x: f64) {
        push_px(&mut self.buf, x);
    }

    /// Appends numbers separated by spaces.
    #[cfg(test)]
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
        if self.buf.len() >= FLUSH_BYTES {
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

    /// A polyline in pixels (closed if `closed`) as a path, or as several paths of at most
    /// [`MAX_PATH_DATA`] bytes of data each, every one from the last vertex of the one before
    /// (a split loop is closed by a line back to its first vertex rather than `Z`: with round
    /// caps and joins the two draw the same pixels). A vertex written at the position of the
    /// vertex written before it is left out, but for the last.
    fn polyline(&mut self, points: impl Iterator<Item = [f64; 2]>, closed: bool) -> io::Result<()> {
        let mut points = points.peekable();
        let Some(first) = points.next() else {
            return Ok(());
        };
        let mut start = String::new();
        push_position(&mut start, first);
        let mut last = start.clone();
        let mut vertex = String::new();
        self.buf.push_str("<path d=\"M");
        self.buf.push_str(&start);
        let mut data = 1 + start.len();
        let mut split = false;
        while let Some(p) = points.next() {
            vertex.clear();
            push_position(&mut vertex, p);
            if vertex == last && points.peek().is_some() {
                continue;
            }
            self.line_to(&vertex, &last, &mut data, &mut split);
            std::mem::swap(&mut last, &mut vertex);
            self.maybe_flush()?;
        }
        if closed {
            if split {
                self.line_to(&start, &last, &mut data, &mut split);
            } else {
                self.buf.push('Z');
            }
        }
        self.buf.push_str("\"/>\n");
        self.maybe_flush()
    }

    /// Appends `L vertex` to the path whose data is `data` bytes long and ends at `last`,
    /// first starting a new path from `last` if the data would grow beyond
    /// [`MAX_PATH_DATA`] (with a byte to spare for a closing `Z`).
    fn line_to(&mut self, vertex: &str, last: &str, data: &mut usize, split: &mut bool) {
        if *data + 1 + vertex.len() + 1 > MAX_PATH_DATA {
            self.buf.push_str("\"/>\n<path d=\"M");
            self.buf.push_str(last);
            *data = 1 + last.len();
            *split = true;
        }
        self.buf.push('L');
        self.buf.push_str(vertex);
        *data += 1 + vertex.len();
    }

    /// Circles of radius `r` at positions in pixels, one per written position: a dot at the
    /// position of one already drawn would only draw it again.
    fn dots(&mut self, positions: impl Iterator<Item = [f64; 2]>, r: f64) -> io::Result<()> {
        let mut radius = String::new();
        push_px(&mut radius, r);
        let (mut x, mut y) = (String::new(), String::new());
        let mut drawn = HashSet::new();
        for p in positions {
            x.clear();
            y.clear();
            push_px(&mut x, p[0]);
            push_px(&mut y, p[1]);
            if let (Some(hx), Some(hy)) = (hundredths(&x), hundredths(&y)) {
                if !drawn.insert([hx, hy]) {
                    continue;
                }
            }
            let _ = writeln!(self.buf, "<circle cx=\"{x}\" cy=\"{y}\" r=\"{radius}\"/>");
            self.maybe_flush()?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests;
