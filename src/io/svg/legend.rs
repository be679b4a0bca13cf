//! The legend under the drawing: a title line, then one entry per layer with its count,
//! laid out in rows that fit the picture's width. Everything here is in pixels.

use std::fmt::Write as _;
use std::io::{self, Write};

use super::canvas::MARGIN_PX;
use super::{
    escape_into, Dots, Style, SvgOptions, SvgWriter, CLOSED, DELAUNAY, INNER, MEDIAL, OPEN, OUTER,
    POINT, UNASSIGNED, VORONOI,
};
use crate::reconstruct::{Algorithm, Label, MedialAxisMode};
use crate::Reconstruction;

/// Legend text size and row height, in pixels.
const FONT_PX: f64 = 13.0;
const ROW_PX: f64 = 20.0;

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
pub(super) struct Legend {
    pub(super) title: String,
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
    pub(super) fn height_px(&self, width_px: f64) -> f64 {
        let rows = self.layout(width_px).last().map_or(0, |&(_, row)| row + 1);
        ROW_PX * (1 + rows) as f64 + 0.5 * MARGIN_PX
    }
}

/// The legend entries for what is drawn, with counts.
pub(super) fn legend_items(rec: &Reconstruction, options: &SvgOptions, style: &Style) -> Legend {
    let n = rec.triangulation().point_count();
    let unassigned = rec.unassigned().len();
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
    let points = plural(n, "point", "points");
    let mut items = vec![match style.dots {
        Dots::Drawn => (Swatch::Dot(POINT, style.point_radius.max(2.0)), points),
        Dots::TooDense => (Swatch::Note, format!("{points} (too dense for dots)")),
        Dots::Off => (Swatch::Note, format!("{points} (not drawn)")),
    }];
    if unassigned > 0 {
        items.push(match style.dots {
            Dots::Drawn | Dots::TooDense => {
                (Swatch::Ring(UNASSIGNED), format!("{unassigned} unassigned"))
            }
            Dots::Off => (Swatch::Note, format!("{unassigned} unassigned (not drawn)")),
        });
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
    // Only an axis that was computed has an entry (none for the baselines, none when it was
    // omitted): "0 segments" would say that the curves enclose nothing.
    if matches!(
        rec.medial_axis_mode(),
        Some(MedialAxisMode::Pruned | MedialAxisMode::Raw)
    ) {
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

/// Draws the legend strip: a group translated to the strip's top-left corner, `top_px`
/// pixels from the top of the picture.
pub(super) fn write_legend<W: Write>(
    w: &mut SvgWriter<'_, W>,
    top_px: f64,
    width_px: f64,
    legend: &Legend,
) -> io::Result<()> {
    let _ = write!(
        w.buf,
        "<g id=\"legend\" fill=\"#222222\" transform=\"translate(0 {top_px:.2})\" font-size=\"{FONT_PX}\">\n<text font-weight=\"bold\" x=\"{MARGIN_PX}\" y=\"{}\">",
        0.75 * ROW_PX
    );
    escape_into(&mut w.buf, &legend.title);
    w.buf.push_str("</text>\n");
    for ((swatch, text), (x, row)) in legend.items.iter().zip(legend.layout(width_px)) {
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
