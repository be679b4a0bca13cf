//! Drawing a reconstruction as an SVG picture that a person can read at a glance.
//!
//! [`write_reconstruction_svg`] draws, from back to front:
//!
//! * optional underlays chosen with [`SvgOptions`]: the Delaunay edges (faint grey), the
//!   Voronoi diagram (finite edges and rays, faint blue, clipped to the picture) and the
//!   water-flow labels of the Voronoi vertices (inner orange, outer blue dots);
//! * the medial axis (thin, green);
//! * the reconstructed curves (strong: closed loops red, open chains purple);
//! * the points (small black dots; points on no reconstructed edge as hollow grey rings);
//! * a legend below the drawing: a title line, then one entry per layer with its count.
//!
//! The drawing is in the data's own coordinates: the `viewBox` is the bounding box of the
//! points plus a margin (and the legend strip below it), and the data layers sit in one group
//! with `transform="scale(1,-1)"` so that the y axis points up, as in the input. Stroke widths
//! and dot sizes are computed from the size of the data (the longest side of the bounding box
//! is drawn 720 px wide) and from the mean length of the reconstructed edges, so a picture of
//! a 1 mm part and one of a 10 km coastline look alike. Coordinates are written with enough
//! decimals for 1/20 px. The document starts with `<svg` (no XML declaration) and is UTF-8.

use std::fmt::Write as _;
use std::io::{self, BufWriter, Write};

use crate::delaunay::NO_TWIN;
use crate::reconstruct::{Algorithm, Label};
use crate::Reconstruction;

/// What to draw besides the points, the curves and the medial axis.
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
}

/// The longest side of the data's bounding box, in pixels of the picture.
const DATA_PX: f64 = 720.0;
/// Space around the data, in pixels.
const MARGIN_PX: f64 = 30.0;
/// The picture is at least this wide, so that the legend fits next to a thin shape.
const MIN_WIDTH_PX: f64 = 420.0;
/// Legend text size and row height, in pixels.
const FONT_PX: f64 = 13.0;
const ROW_PX: f64 = 20.0;

// Colours.
const POINT: &str = "#111111";
const UNTOUCHED: &str = "#8c8c8c";
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
/// let mut out = Vec::new();
/// wdm_crust::io::write_reconstruction_svg(&rec, &options, &mut out)?;
/// let svg = String::from_utf8(out)?;
/// assert!(svg.starts_with("<svg "));
/// assert!(svg.contains(" viewBox=\""));
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
    let untouched = rec.untouched_points();
    let style = Style::new(rec, points);
    let legend = legend_items(rec, options, &untouched, points);
    let frame = Frame::new(points, &legend);
    let mut w = SvgWriter {
        out: &mut out,
        decimals: frame.decimals,
        buf: String::new(),
    };

    w.buf.clear();
    let _ = write!(w.buf, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"");
    w.px(frame.width_px);
    w.buf.push_str("\" height=\"");
    w.px(frame.height_px);
    w.buf.push_str("\" viewBox=\"");
    w.nums(&[frame.view[0], frame.view[1], frame.view[2], frame.view[3]]);
    w.buf.push_str("\" font-family=\"sans-serif\">\n<title>");
    escape_into(&mut w.buf, &legend.title);
    w.buf.push_str("</title>\n<rect fill=\"#ffffff\" x=\"");
    w.num(frame.view[0]);
    w.buf.push_str("\" y=\"");
    w.num(frame.view[1]);
    w.buf.push_str("\" width=\"");
    w.num(frame.view[2]);
    w.buf.push_str("\" height=\"");
    w.num(frame.view[3]);
    w.buf.push_str("\"/>\n<g transform=\"scale(1,-1)\">\n");
    w.flush()?;

    let unit = frame.unit;
    if options.delaunay {
        w.open_stroke_group("delaunay", DELAUNAY, 0.7 * unit)?;
        if tri.is_degenerate() {
            for pair in tri.hull().windows(2) {
                w.segment(points[pair[0] as usize], points[pair[1] as usize])?;
            }
        } else {
            for (e, &twin) in tri.halfedges().iter().enumerate() {
                if twin == NO_TWIN || (e as u32) < twin {
                    let a = points[tri.halfedge_origin(e) as usize];
                    let b = points[tri.halfedge_destination(e) as usize];
                    w.segment(a, b)?;
                }
            }
        }
        w.close_group()?;
    }

    let needs_voronoi = options.voronoi || (options.labels && !rec.labels().is_empty());
    let vor = needs_voronoi.then(|| tri.voronoi());
    if let (true, Some(vor)) = (options.voronoi, &vor) {
        w.open_stroke_group("voronoi", VORONOI, 0.8 * unit)?;
        let rect = frame.clip;
        let positions = vor.vertex_positions();
        for (_, a, b) in vor.finite_edges() {
            let (pa, pb) = (positions[a as usize], positions[b as usize]);
            let d = [pb[0] - pa[0], pb[1] - pa[1]];
            if let Some((p, q)) = clip(pa, d, 0.0, 1.0, &rect) {
                w.segment(p, q)?;
            }
        }
        for (_, v, d) in vor.rays() {
            if let Some((p, q)) = clip(positions[v as usize], d, 0.0, f64::INFINITY, &rect) {
                w.segment(p, q)?;
            }
        }
        for [a, b] in vor.collinear_bisectors() {
            let (pa, pb) = (points[a as usize], points[b as usize]);
            let mid = [0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])];
            let d = [pb[1] - pa[1], pa[0] - pb[0]];
            if let Some((p, q)) = clip(mid, d, f64::NEG_INFINITY, f64::INFINITY, &rect) {
                w.segment(p, q)?;
            }
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
                if l == label && frame.clip.contains(p) {
                    w.dot(p, style.label_radius * unit)?;
                }
            }
            w.close_group()?;
        }
    }

    let axis = rec.medial_axis();
    if !axis.edges.is_empty() {
        w.open_stroke_group("medial-axis", MEDIAL, style.axis_width * unit)?;
        for &[a, b] in &axis.edges {
            let (pa, pb) = (axis.vertices[a as usize], axis.vertices[b as usize]);
            let d = [pb[0] - pa[0], pb[1] - pa[1]];
            if let Some((p, q)) = clip(pa, d, 0.0, 1.0, &frame.clip) {
                w.segment(p, q)?;
            }
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
        w.open_stroke_group(id, colour, style.curve_width * unit)?;
        for curve in rec.curves().iter().filter(|c| c.closed == closed) {
            w.polyline(curve.points.iter().map(|&i| points[i as usize]), closed)?;
        }
        w.close_group()?;
    }

    let mut skip = vec![false; points.len()];
    for &[duplicate, _] in tri.duplicates() {
        skip[duplicate as usize] = true;
    }
    for &p in &untouched {
        skip[p as usize] = true;
    }
    w.open_fill_group("points", POINT)?;
    for (p, &point) in points.iter().enumerate() {
        if !skip[p] {
            w.dot(point, style.point_radius * unit)?;
        }
    }
    w.close_group()?;
    if !untouched.is_empty() {
        let _ = write!(
            w.buf,
            "<g id=\"untouched-points\" fill=\"#ffffff\" stroke=\"{UNTOUCHED}\" stroke-width=\""
        );
        w.num(0.35 * style.point_radius * unit);
        w.buf.push_str("\">\n");
        for &p in &untouched {
            w.dot(points[p as usize], 1.3 * style.point_radius * unit)?;
        }
        w.close_group()?;
    }
    w.buf.push_str("</g>\n");
    w.flush()?;

    write_legend(&mut w, &frame, &legend)?;
    w.buf.push_str("</svg>\n");
    w.flush()?;
    out.flush()
}

/// Sizes in pixels that depend on the data: the denser the points, the finer the lines.
struct Style {
    point_radius: f64,
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

/// The bounding box of `points`, or the unit square when there are none.
fn bounding_box(points: &[[f64; 2]]) -> ([f64; 2], [f64; 2]) {
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

/// An axis-aligned rectangle in data coordinates.
#[derive(Debug, Clone, Copy)]
struct Rect {
    min: [f64; 2],
    max: [f64; 2],
}

impl Rect {
    fn contains(&self, p: [f64; 2]) -> bool {
        (0..2).all(|k| self.min[k] <= p[k] && p[k] <= self.max[k])
    }
}

/// Where everything goes: the data's bounding box, the scale, the viewBox.
struct Frame {
    /// Data units per pixel.
    unit: f64,
    /// The viewBox `[x, y, width, height]` (y flipped: the data's top is `-max_y`).
    view: [f64; 4],
    width_px: f64,
    height_px: f64,
    /// The visible data area (without the legend strip), in data coordinates.
    clip: Rect,
    /// The top of the legend strip, in viewBox coordinates.
    legend_top: f64,
    /// Decimals written for a coordinate.
    decimals: usize,
}

impl Frame {
    fn new(points: &[[f64; 2]], legend: &Legend) -> Self {
        let (min, max) = bounding_box(points);
        let size = [max[0] - min[0], max[1] - min[1]];
        let mut extent = size[0].max(size[1]);
        if !extent.is_finite() || extent <= 0.0 {
            // One distinct point: a frame proportionate to its coordinates.
            extent = min[0].abs().max(min[1].abs());
            if extent == 0.0 {
                extent = 1.0;
            }
        }
        let unit = extent / DATA_PX;
        let data_px = [size[0] / unit, size[1] / unit];
        let width_px = (data_px[0] + 2.0 * MARGIN_PX).max(MIN_WIDTH_PX);
        let left_px = 0.5 * (width_px - data_px[0]);
        let legend_px = legend.height_px(width_px);
        let height_px = data_px[1] + 2.0 * MARGIN_PX + legend_px;
        let view = [
            min[0] - left_px * unit,
            -max[1] - MARGIN_PX * unit,
            width_px * unit,
            height_px * unit,
        ];
        let clip = Rect {
            min: [view[0], min[1] - MARGIN_PX * unit],
            max: [view[0] + view[2], max[1] + MARGIN_PX * unit],
        };
        // 1/20 px resolution.
        let decimals = (-(unit / 20.0).log10()).ceil().clamp(0.0, 60.0) as usize;
        Frame {
            unit,
            view,
            width_px,
            height_px,
            clip,
            legend_top: -min[1] + MARGIN_PX * unit,
            decimals,
        }
    }
}

/// Clips the part `t0 ≤ t ≤ t1` of the line `p + t d` to `rect` (Liang–Barsky); `t0` and
/// `t1` may be infinite. `None` when nothing is left or the input is not finite.
fn clip(p: [f64; 2], d: [f64; 2], t0: f64, t1: f64, rect: &Rect) -> Option<([f64; 2], [f64; 2])> {
    if !p.iter().chain(&d).all(|v| v.is_finite()) {
        return None;
    }
    let (mut lo, mut hi) = (t0, t1);
    for k in 0..2 {
        if d[k] == 0.0 {
            if p[k] < rect.min[k] || p[k] > rect.max[k] {
                return None;
            }
            continue;
        }
        let a = (rect.min[k] - p[k]) / d[k];
        let b = (rect.max[k] - p[k]) / d[k];
        lo = lo.max(a.min(b));
        hi = hi.min(a.max(b));
    }
    if !(lo.is_finite() && hi.is_finite()) || lo > hi {
        return None;
    }
    let at = |t: f64| [p[0] + t * d[0], p[1] + t * d[1]];
    Some((at(lo), at(hi)))
}

/// Appends `text` with the XML special characters escaped.
fn escape_into(buf: &mut String, text: &str) {
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

/// Writes SVG elements through a reusable text buffer, numbers with a fixed precision.
struct SvgWriter<'w, W: Write> {
    out: &'w mut W,
    decimals: usize,
    buf: String,
}

impl<W: Write> SvgWriter<'_, W> {
    /// Appends one coordinate (never `-0.00`).
    fn num(&mut self, x: f64) {
        let start = self.buf.len();
        let _ = write!(self.buf, "{x:.*}", self.decimals);
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

    /// Appends a size in pixels.
    fn px(&mut self, x: f64) {
        let _ = write!(self.buf, "{x:.1}");
    }

    /// Writes out the buffer when it is large (or always, from `flush`).
    fn maybe_flush(&mut self) -> io::Result<()> {
        if self.buf.len() >= 1 << 15 {
            self.flush()?;
        }
        Ok(())
    }

    fn flush(&mut self) -> io::Result<()> {
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

    /// One straight segment as a path.
    fn segment(&mut self, a: [f64; 2], b: [f64; 2]) -> io::Result<()> {
        self.polyline([a, b].into_iter(), false)
    }

    /// A polyline (closed with `Z` if `closed`) as a path.
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

    /// A filled circle.
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

/// How one legend entry is drawn.
#[derive(Debug, Clone, Copy)]
enum Swatch {
    /// A short line of this colour and width (in px).
    Line(&'static str, f64),
    /// A dot of this colour and radius (in px).
    Dot(&'static str, f64),
    /// A hollow ring.
    Ring(&'static str),
    /// No swatch: a note.
    Note,
}

/// The legend: a title line and entries laid out in rows.
struct Legend {
    title: String,
    items: Vec<(Swatch, String)>,
}

/// Width of a swatch plus the gap before its text, and the gap after an entry, in px.
const SWATCH_PX: f64 = 28.0;
const GAP_PX: f64 = 18.0;

impl Legend {
    /// Estimated width of `text` at the legend's font size.
    fn text_px(text: &str) -> f64 {
        0.56 * FONT_PX * text.chars().count() as f64
    }

    fn item_px((swatch, text): &(Swatch, String)) -> f64 {
        let swatch = if matches!(swatch, Swatch::Note) {
            0.0
        } else {
            SWATCH_PX
        };
        swatch + Self::text_px(text) + GAP_PX
    }

    /// The entries' positions (x in px from the left edge, row from 0) for this width.
    fn layout(&self, width_px: f64) -> Vec<(f64, usize)> {
        let mut x = MARGIN_PX;
        let mut row = 0;
        let mut positions = Vec::with_capacity(self.items.len());
        for item in &self.items {
            let w = Self::item_px(item);
            if x > MARGIN_PX && x + w > width_px - MARGIN_PX + GAP_PX {
                x = MARGIN_PX;
                row += 1;
            }
            positions.push((x, row));
            x += w;
        }
        positions
    }

    /// Height of the legend strip under the data, in px.
    fn height_px(&self, width_px: f64) -> f64 {
        let rows = self.layout(width_px).last().map_or(0, |&(_, row)| row + 1);
        ROW_PX * (1 + rows) as f64 + 0.5 * MARGIN_PX
    }
}

/// The legend entries for what is drawn, with counts.
fn legend_items(
    rec: &Reconstruction,
    options: &SvgOptions,
    untouched: &[u32],
    points: &[[f64; 2]],
) -> Legend {
    let tri = rec.triangulation();
    let n = tri.point_count();
    let style = Style::new(rec, points);
    let name = match rec.algorithm() {
        Algorithm::Wdm => "WDM_CRUST",
        Algorithm::Crust => "Crust",
        Algorithm::NnCrust => "NN-Crust",
    };
    let title = options
        .title
        .clone()
        .unwrap_or_else(|| format!("{name} reconstruction of {n} points"));
    let closed = rec.curves().iter().filter(|c| c.closed).count();
    let open = rec.curves().len() - closed;
    let plural =
        |k: usize, one: &str, many: &str| format!("{k} {}", if k == 1 { one } else { many });
    let mut items = vec![(
        Swatch::Dot(POINT, style.point_radius.max(2.0)),
        plural(n, "point", "points"),
    )];
    if !untouched.is_empty() {
        items.push((
            Swatch::Ring(UNTOUCHED),
            format!("{} on no curve", untouched.len()),
        ));
    }
    if closed > 0 || open == 0 {
        items.push((
            Swatch::Line(CLOSED, 2.5),
            plural(closed, "closed curve", "closed curves"),
        ));
    }
    if open > 0 {
        items.push((
            Swatch::Line(OPEN, 2.5),
            plural(open, "open chain", "open chains"),
        ));
    }
    if rec.algorithm() == Algorithm::Wdm {
        let m = rec.medial_axis().edges.len();
        items.push((
            Swatch::Line(MEDIAL, 1.5),
            format!("medial axis ({})", plural(m, "segment", "segments")),
        ));
    }
    if options.delaunay {
        items.push((Swatch::Line(DELAUNAY, 1.0), "Delaunay edges".to_string()));
    }
    if options.voronoi {
        items.push((Swatch::Line(VORONOI, 1.0), "Voronoi edges".to_string()));
    }
    if options.labels {
        if rec.labels().is_empty() {
            items.push((Swatch::Note, format!("(no labels: {name} does not label)")));
        } else {
            let inner = rec.labels().iter().filter(|&&l| l == Label::Inner).count();
            let outer = rec.labels().len() - inner;
            items.push((
                Swatch::Dot(INNER, 2.5),
                format!("{inner} inner Voronoi vertices"),
            ));
            items.push((Swatch::Dot(OUTER, 2.5), format!("{outer} outer")));
        }
    }
    Legend { title, items }
}

/// Draws the legend strip: a group translated to the strip's top-left corner and scaled so
/// that its own units are pixels (text sized in tiny data units renders badly).
fn write_legend<W: Write>(
    w: &mut SvgWriter<'_, W>,
    frame: &Frame,
    legend: &Legend,
) -> io::Result<()> {
    w.buf
        .push_str("<g id=\"legend\" fill=\"#222222\" transform=\"translate(");
    w.nums(&[frame.view[0], frame.legend_top]);
    let _ = write!(
        w.buf,
        ") scale({:?})\" font-size=\"{FONT_PX}\">\n<text font-weight=\"bold\" x=\"{MARGIN_PX}\" y=\"{}\">",
        frame.unit,
        0.75 * ROW_PX
    );
    escape_into(&mut w.buf, &legend.title);
    w.buf.push_str("</text>\n");
    for ((swatch, text), (x, row)) in legend.items.iter().zip(legend.layout(frame.width_px)) {
        let baseline = (row as f64 + 1.75) * ROW_PX;
        let middle = baseline - 0.35 * FONT_PX;
        let text_x = match *swatch {
            Swatch::Line(colour, width) => {
                let _ = writeln!(
                    w.buf,
                    "<path fill=\"none\" stroke=\"{colour}\" stroke-linecap=\"round\" stroke-width=\"{width}\" d=\"M{x:.1} {middle:.1}h20\"/>"
                );
                x + SWATCH_PX
            }
            Swatch::Dot(colour, r) => {
                let _ = writeln!(
                    w.buf,
                    "<circle fill=\"{colour}\" cx=\"{:.1}\" cy=\"{middle:.1}\" r=\"{r:.1}\"/>",
                    x + 10.0
                );
                x + SWATCH_PX
            }
            Swatch::Ring(colour) => {
                let _ = writeln!(
                    w.buf,
                    "<circle fill=\"#ffffff\" stroke=\"{colour}\" cx=\"{:.1}\" cy=\"{middle:.1}\" r=\"3\"/>",
                    x + 10.0
                );
                x + SWATCH_PX
            }
            Swatch::Note => x,
        };
        let _ = write!(w.buf, "<text x=\"{text_x:.1}\" y=\"{baseline:.1}\">");
        escape_into(&mut w.buf, text);
        w.buf.push_str("</text>\n");
        w.maybe_flush()?;
    }
    w.buf.push_str("</g>\n");
    w.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn svg_of(points: &[[f64; 2]], options: &SvgOptions) -> String {
        let rec = crate::reconstruct(points).unwrap();
        let mut out = Vec::new();
        write_reconstruction_svg(&rec, options, &mut out).unwrap();
        String::from_utf8(out).unwrap()
    }

    fn circle(n: usize, r: f64, centre: [f64; 2]) -> Vec<[f64; 2]> {
        (0..n)
            .map(|k| {
                let t = (k * 7 % n) as f64 * std::f64::consts::TAU / n as f64;
                [centre[0] + r * t.cos(), centre[1] + r * t.sin()]
            })
            .collect()
    }

    /// Every `<name` has its `</name>` or ends in `/>`, properly nested.
    fn assert_balanced(svg: &str) {
        let mut stack: Vec<&str> = Vec::new();
        let mut rest = svg;
        while let Some(open) = rest.find('<') {
            let close = rest[open..].find('>').expect("unterminated tag") + open;
            let tag = &rest[open + 1..close];
            if let Some(name) = tag.strip_prefix('/') {
                assert_eq!(stack.pop(), Some(name), "mismatched </{name}>");
            } else if !tag.ends_with('/') {
                stack.push(tag.split_whitespace().next().unwrap());
            }
            rest = &rest[close + 1..];
        }
        assert!(stack.is_empty(), "unclosed {stack:?}");
    }

    #[test]
    fn every_layer_is_drawn_and_the_document_is_balanced() {
        let options = SvgOptions {
            delaunay: true,
            voronoi: true,
            labels: true,
            title: Some("a <circle> & more".to_string()),
        };
        let svg = svg_of(&circle(24, 3.0, [10.0, -4.0]), &options);
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\" "));
        assert_balanced(&svg);
        for id in [
            "delaunay",
            "voronoi",
            "outer-vertices",
            "inner-vertices",
            "medial-axis",
            "closed-curves",
            "points",
            "legend",
        ] {
            assert!(svg.contains(&format!("<g id=\"{id}\"")), "{id} missing");
        }
        assert!(svg.contains("<title>a &lt;circle&gt; &amp; more</title>"));
        assert!(svg.contains("1 closed curve"));
    }

    #[test]
    fn the_view_box_holds_the_data_with_y_up() {
        let svg = svg_of(&circle(16, 1.0, [100.0, 50.0]), &SvgOptions::default());
        let start = svg.find("viewBox=\"").unwrap() + 9;
        let end = start + svg[start..].find('"').unwrap();
        let v: Vec<f64> = svg[start..end]
            .split(' ')
            .map(|t| t.parse().unwrap())
            .collect();
        // x: 99..101 inside; y flipped: -51..-49 inside.
        assert!(v[0] < 99.0 && v[0] + v[2] > 101.0, "{v:?}");
        assert!(v[1] < -51.0 && v[1] + v[3] > -49.0, "{v:?}");
        assert!(v[2] < 4.0, "margin too wide: {v:?}");
        assert!(svg.contains("transform=\"scale(1,-1)\""));
    }

    #[test]
    fn degenerate_inputs_draw_something_sane() {
        for points in [
            vec![],
            vec![[5.0, 5.0]],
            vec![[1.0, 1.0], [1.0, 1.0]],
            vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]],
        ] {
            let options = SvgOptions {
                delaunay: true,
                voronoi: true,
                labels: true,
                title: None,
            };
            let svg = svg_of(&points, &options);
            assert_balanced(&svg);
            assert!(!svg.contains("NaN") && !svg.contains("inf"), "{svg}");
        }
    }

    #[test]
    fn clipping() {
        let rect = Rect {
            min: [0.0, 0.0],
            max: [1.0, 1.0],
        };
        let (a, b) = clip([0.5, 0.5], [1.0, 0.0], 0.0, f64::INFINITY, &rect).unwrap();
        assert_eq!((a, b), ([0.5, 0.5], [1.0, 0.5]));
        let (a, b) = clip(
            [0.5, -1.0],
            [0.0, 1.0],
            f64::NEG_INFINITY,
            f64::INFINITY,
            &rect,
        )
        .unwrap();
        assert_eq!((a, b), ([0.5, 0.0], [0.5, 1.0]));
        assert!(clip([2.0, 2.0], [1.0, 1.0], 0.0, 1.0, &rect).is_none());
        assert!(clip([0.5, 0.5], [0.0, 0.0], 0.0, f64::INFINITY, &rect).is_none());
        assert!(clip([f64::INFINITY, 0.5], [1.0, 0.0], 0.0, 1.0, &rect).is_none());
    }

    #[test]
    fn numbers_have_fixed_precision_and_no_negative_zero() {
        let mut out = Vec::new();
        let mut w = SvgWriter {
            out: &mut out,
            decimals: 2,
            buf: String::new(),
        };
        w.nums(&[1.0, -0.001, 2.346, -3.5]);
        assert_eq!(w.buf, "1.00 0.00 2.35 -3.50");
    }
}
