//! Ground-truth curves from the `<path d="...">` elements of simple (Inkscape) SVG files.
//!
//! Supported: path commands `M m L l H h V v C c Z z` with implicit repeats, numbers separated
//! by spaces and/or commas (exponents included), and `transform` attributes (`matrix`,
//! `translate`, `scale`, `rotate`) on the path and its ancestors. Paths inside `<defs>`,
//! `<clipPath>`, `<mask>`, `<marker>`, `<pattern>` and `<symbol>` are skipped. Coordinates
//! are kept as in the file (SVG's y axis points down).

use super::curve::DenseCurve;
use super::vec2::{angle_between, dist, sub, P2};
use std::fmt;

/// Joins where the tangent turns by more than this (radians) are corners. Inkscape writes
/// smooth nodes collinear up to print precision, far below this.
const CORNER_ANGLE: f64 = 2.0 * std::f64::consts::PI / 180.0;

/// Elements whose content is not drawn.
const HIDDEN: [&str; 6] = ["defs", "clipPath", "mask", "marker", "pattern", "symbol"];

/// An SVG that could not be read.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SvgError(pub String);

impl fmt::Display for SvgError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "SVG: {}", self.0)
    }
}

impl std::error::Error for SvgError {}

fn err<T>(msg: impl Into<String>) -> Result<T, SvgError> {
    Err(SvgError(msg.into()))
}

/// One piece of a path, in absolute (transformed) coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Segment {
    /// Straight segment from the first point to the second.
    Line([f64; 2], [f64; 2]),
    /// Cubic Bézier: start, two control points, end.
    Cubic([[f64; 2]; 4]),
}

impl Segment {
    /// The point at parameter `t ∈ [0, 1]`.
    pub fn point(&self, t: f64) -> [f64; 2] {
        match *self {
            Segment::Line(a, b) => [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])],
            Segment::Cubic(p) => {
                let s = 1.0 - t;
                let w = [s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t];
                let x = (0..4).map(|i| w[i] * p[i][0]).sum();
                let y = (0..4).map(|i| w[i] * p[i][1]).sum();
                [x, y]
            }
        }
    }

    /// Approximate length (exact for lines; 32 chords for cubics).
    pub fn length(&self) -> f64 {
        match *self {
            Segment::Line(a, b) => dist(a, b),
            Segment::Cubic(_) => (0..32)
                .map(|i| {
                    dist(
                        self.point(i as f64 / 32.0),
                        self.point((i + 1) as f64 / 32.0),
                    )
                })
                .sum(),
        }
    }

    /// Direction of travel at the start (first non-degenerate control leg).
    fn start_tangent(&self) -> P2 {
        match *self {
            Segment::Line(a, b) => sub(b, a),
            Segment::Cubic(p) => first_nonzero([sub(p[1], p[0]), sub(p[2], p[0]), sub(p[3], p[0])]),
        }
    }

    /// Direction of travel at the end.
    fn end_tangent(&self) -> P2 {
        match *self {
            Segment::Line(a, b) => sub(b, a),
            Segment::Cubic(p) => first_nonzero([sub(p[3], p[2]), sub(p[3], p[1]), sub(p[3], p[0])]),
        }
    }
}

fn first_nonzero(vs: [P2; 3]) -> P2 {
    vs.into_iter()
        .find(|v| v[0] != 0.0 || v[1] != 0.0)
        .unwrap_or([0.0, 0.0])
}

/// A connected run of segments from one moveto; closed when it ended with `z`.
#[derive(Debug, Clone, PartialEq)]
pub struct SvgSubpath {
    /// The segments in order (a closing `z` adds the line back to the start if needed).
    pub segments: Vec<Segment>,
    /// Whether the subpath ended with `z`.
    pub closed: bool,
}

impl SvgSubpath {
    /// Approximate length.
    pub fn length(&self) -> f64 {
        self.segments.iter().map(Segment::length).sum()
    }

    /// A dense polyline with points about `spacing` apart (uniform in each segment's
    /// parameter), corners at joins where the tangent turns by more than 2°.
    pub fn dense(&self, spacing: f64) -> DenseCurve {
        let mut points = Vec::new();
        let mut corners = Vec::new();
        let count = self.segments.len();
        for (s, seg) in self.segments.iter().enumerate() {
            let prev = if s > 0 {
                Some(&self.segments[s - 1])
            } else if self.closed {
                self.segments.last()
            } else {
                None
            };
            if let Some(prev) = prev {
                if angle_between(prev.end_tangent(), seg.start_tangent()) > CORNER_ANGLE {
                    corners.push(points.len());
                }
            }
            let pieces = (seg.length() / spacing).ceil().max(1.0) as usize;
            let last = !self.closed && s + 1 == count;
            let end = if last { pieces + 1 } else { pieces };
            points.extend((0..end).map(|k| seg.point(k as f64 / pieces as f64)));
        }
        DenseCurve::from_points(&points, self.closed, &corners)
    }
}

/// All subpaths of all drawn `<path>` elements of an SVG document, transforms applied.
pub fn parse_svg(svg: &str) -> Result<Vec<SvgSubpath>, SvgError> {
    let mut out = Vec::new();
    // One entry per open element: its accumulated transform and whether it is hidden.
    let mut stack: Vec<(Affine, bool)> = vec![(IDENTITY, false)];
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        rest = &rest[open..];
        if let Some(skip) = skip_special(rest)? {
            rest = &rest[skip..];
            continue;
        }
        if let Some(body) = rest.strip_prefix("</") {
            stack.pop();
            if stack.is_empty() {
                return err("unbalanced closing tag");
            }
            let close = body
                .find('>')
                .ok_or_else(|| SvgError("unterminated tag".into()))?;
            rest = &body[close + 1..];
            continue;
        }
        let tag = parse_tag(&rest[1..])?;
        rest = &rest[1 + tag.consumed..];
        let (parent, parent_hidden) = *stack.last().unwrap_or(&(IDENTITY, false));
        let own = match tag.attr("transform") {
            Some(t) => parse_transform(t)?,
            None => IDENTITY,
        };
        let transform = compose(&parent, &own);
        let hidden = parent_hidden || HIDDEN.contains(&local_name(tag.name));
        if local_name(tag.name) == "path" && !hidden {
            if let Some(d) = tag.attr("d") {
                out.extend(parse_path_data(d, &transform)?);
            }
        }
        if !tag.self_closing {
            stack.push((transform, hidden));
        }
    }
    Ok(out)
}

/// Dense curves for every subpath of an SVG, with about `points` dense points in total,
/// shared in proportion to length.
pub fn svg_dense_curves(svg: &str, points: usize) -> Result<Vec<DenseCurve>, SvgError> {
    let subpaths = parse_svg(svg)?;
    let total: f64 = subpaths.iter().map(SvgSubpath::length).sum();
    if total <= 0.0 {
        return Ok(Vec::new());
    }
    let spacing = total / points.max(1) as f64;
    Ok(subpaths
        .iter()
        .map(|s| s.dense(spacing))
        .filter(|c| c.len() >= 2)
        .collect())
}

/// The name without a namespace prefix (`svg:path` → `path`).
fn local_name(name: &str) -> &str {
    name.rsplit(':').next().unwrap_or(name)
}

/// Length of a comment, processing instruction, declaration or CDATA at the start of `s`.
fn skip_special(s: &str) -> Result<Option<usize>, SvgError> {
    for (open, close) in [
        ("<!--", "-->"),
        ("<![CDATA[", "]]>"),
        ("<?", "?>"),
        ("<!", ">"),
    ] {
        if let Some(body) = s.strip_prefix(open) {
            let end = body
                .find(close)
                .ok_or_else(|| SvgError(format!("unterminated {open}")))?;
            return Ok(Some(open.len() + end + close.len()));
        }
    }
    Ok(None)
}

/// A start tag: name, attributes, whether it ends with `/>`, and its length after `<`.
struct Tag<'a> {
    name: &'a str,
    attrs: Vec<(&'a str, &'a str)>,
    self_closing: bool,
    consumed: usize,
}

impl<'a> Tag<'a> {
    fn attr(&self, name: &str) -> Option<&'a str> {
        self.attrs.iter().find(|(n, _)| *n == name).map(|&(_, v)| v)
    }
}

/// Parses a start tag from just after its `<`.
fn parse_tag(s: &str) -> Result<Tag<'_>, SvgError> {
    let bytes = s.as_bytes();
    let is_space = |b: u8| b.is_ascii_whitespace();
    let mut i = 0;
    while i < bytes.len() && !is_space(bytes[i]) && bytes[i] != b'>' && bytes[i] != b'/' {
        i += 1;
    }
    let name = &s[..i];
    let mut attrs = Vec::new();
    loop {
        while i < bytes.len() && is_space(bytes[i]) {
            i += 1;
        }
        match bytes.get(i) {
            None => return err(format!("unterminated <{name}")),
            Some(b'>') => {
                return Ok(Tag {
                    name,
                    attrs,
                    self_closing: false,
                    consumed: i + 1,
                });
            }
            Some(b'/') if bytes.get(i + 1) == Some(&b'>') => {
                return Ok(Tag {
                    name,
                    attrs,
                    self_closing: true,
                    consumed: i + 2,
                });
            }
            _ => {}
        }
        let start = i;
        while i < bytes.len() && bytes[i] != b'=' && !is_space(bytes[i]) && bytes[i] != b'>' {
            i += 1;
        }
        let attr = &s[start..i];
        while i < bytes.len() && is_space(bytes[i]) {
            i += 1;
        }
        if bytes.get(i) != Some(&b'=') {
            return err(format!("attribute {attr} of <{name}> has no value"));
        }
        i += 1;
        while i < bytes.len() && is_space(bytes[i]) {
            i += 1;
        }
        let quote = match bytes.get(i) {
            Some(&q) if q == b'"' || q == b'\'' => q,
            _ => return err(format!("attribute {attr} of <{name}> is not quoted")),
        };
        let value_start = i + 1;
        let len = bytes[value_start..]
            .iter()
            .position(|&b| b == quote)
            .ok_or_else(|| SvgError(format!("unterminated attribute {attr}")))?;
        attrs.push((attr, &s[value_start..value_start + len]));
        i = value_start + len + 1;
    }
}

/// An affine map `[a, b, c, d, e, f]` in SVG's order: `x' = a x + c y + e`, `y' = b x + d y + f`.
type Affine = [f64; 6];

const IDENTITY: Affine = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];

/// `outer ∘ inner`: apply `inner` first.
fn compose(outer: &Affine, inner: &Affine) -> Affine {
    let [a, b, c, d, e, f] = *outer;
    let [a2, b2, c2, d2, e2, f2] = *inner;
    [
        a * a2 + c * b2,
        b * a2 + d * b2,
        a * c2 + c * d2,
        b * c2 + d * d2,
        a * e2 + c * f2 + e,
        b * e2 + d * f2 + f,
    ]
}

fn apply(m: &Affine, p: P2) -> P2 {
    [
        m[0] * p[0] + m[2] * p[1] + m[4],
        m[1] * p[0] + m[3] * p[1] + m[5],
    ]
}

/// Parses a transform list such as `translate(1,2) scale(3)`; the rightmost applies first.
fn parse_transform(s: &str) -> Result<Affine, SvgError> {
    let mut m = IDENTITY;
    let mut rest = s.trim();
    while !rest.is_empty() {
        let open = rest
            .find('(')
            .ok_or_else(|| SvgError(format!("bad transform {s:?}")))?;
        let close = rest
            .find(')')
            .ok_or_else(|| SvgError(format!("bad transform {s:?}")))?;
        let name = rest[..open].trim().trim_start_matches(',').trim();
        let args = numbers(&rest[open + 1..close])?;
        let t = match (name, args.as_slice()) {
            ("matrix", &[a, b, c, d, e, f]) => [a, b, c, d, e, f],
            ("translate", &[x]) => [1.0, 0.0, 0.0, 1.0, x, 0.0],
            ("translate", &[x, y]) => [1.0, 0.0, 0.0, 1.0, x, y],
            ("scale", &[k]) => [k, 0.0, 0.0, k, 0.0, 0.0],
            ("scale", &[x, y]) => [x, 0.0, 0.0, y, 0.0, 0.0],
            ("rotate", &[deg]) => rotation(deg),
            ("rotate", &[deg, cx, cy]) => {
                let to = [1.0, 0.0, 0.0, 1.0, cx, cy];
                let back = [1.0, 0.0, 0.0, 1.0, -cx, -cy];
                compose(&compose(&to, &rotation(deg)), &back)
            }
            _ => return err(format!("unsupported transform {name}({:?})", args)),
        };
        m = compose(&m, &t);
        rest = rest[close + 1..].trim();
    }
    Ok(m)
}

fn rotation(deg: f64) -> Affine {
    let (s, c) = deg.to_radians().sin_cos();
    [c, s, -s, c, 0.0, 0.0]
}

/// All numbers in a separator-delimited list.
fn numbers(s: &str) -> Result<Vec<f64>, SvgError> {
    let mut lex = Lexer {
        s: s.as_bytes(),
        pos: 0,
    };
    let mut out = Vec::new();
    while lex.at_number() {
        out.push(lex.number()?);
    }
    if lex.pos < lex.s.len() {
        return err(format!("unexpected text in number list {s:?}"));
    }
    Ok(out)
}

/// Tokenizer for path data: numbers and single-letter commands.
struct Lexer<'a> {
    s: &'a [u8],
    pos: usize,
}

impl Lexer<'_> {
    fn skip_separators(&mut self) {
        while self.pos < self.s.len()
            && (self.s[self.pos].is_ascii_whitespace() || self.s[self.pos] == b',')
        {
            self.pos += 1;
        }
    }

    /// Whether a number starts here (after separators).
    fn at_number(&mut self) -> bool {
        self.skip_separators();
        matches!(self.s.get(self.pos), Some(b'0'..=b'9' | b'+' | b'-' | b'.'))
    }

    /// The command letter here, if any (after separators), consumed.
    fn command(&mut self) -> Option<u8> {
        self.skip_separators();
        let c = *self.s.get(self.pos)?;
        c.is_ascii_alphabetic().then(|| {
            self.pos += 1;
            c
        })
    }

    /// A number: sign, digits with at most one point, optional exponent. A second point
    /// starts the next number (`0.5.5` is two numbers), as SVG allows.
    fn number(&mut self) -> Result<f64, SvgError> {
        self.skip_separators();
        let start = self.pos;
        let s = self.s;
        let mut i = self.pos;
        if matches!(s.get(i), Some(b'+' | b'-')) {
            i += 1;
        }
        let mut digits = 0;
        while s.get(i).is_some_and(u8::is_ascii_digit) {
            i += 1;
            digits += 1;
        }
        if s.get(i) == Some(&b'.') {
            i += 1;
            while s.get(i).is_some_and(u8::is_ascii_digit) {
                i += 1;
                digits += 1;
            }
        }
        if digits == 0 {
            return err(format!("expected a number at byte {start}"));
        }
        if matches!(s.get(i), Some(b'e' | b'E')) {
            let mut j = i + 1;
            if matches!(s.get(j), Some(b'+' | b'-')) {
                j += 1;
            }
            if s.get(j).is_some_and(u8::is_ascii_digit) {
                while s.get(j).is_some_and(u8::is_ascii_digit) {
                    j += 1;
                }
                i = j;
            }
        }
        self.pos = i;
        let text = std::str::from_utf8(&s[start..i]).map_err(|_| SvgError("bad number".into()))?;
        text.parse()
            .map_err(|_| SvgError(format!("bad number {text:?}")))
    }

    fn pair(&mut self) -> Result<P2, SvgError> {
        Ok([self.number()?, self.number()?])
    }
}

/// Subpath under construction, in local coordinates.
struct Builder {
    done: Vec<SvgSubpath>,
    segments: Vec<Segment>,
    current: P2,
    start: P2,
}

impl Builder {
    /// Ends the current subpath (dropped if it has no segments).
    fn finish(&mut self, closed: bool) {
        if !self.segments.is_empty() {
            let segments = std::mem::take(&mut self.segments);
            self.done.push(SvgSubpath { segments, closed });
        }
    }

    fn line_to(&mut self, p: P2) {
        self.segments.push(Segment::Line(self.current, p));
        self.current = p;
    }
}

/// Parses the `d` attribute of a path into subpaths, mapping every point through the affine
/// map `m = [a, b, c, d, e, f]` in SVG's order (`x' = a x + c y + e`, `y' = b x + d y + f`;
/// `[1, 0, 0, 1, 0, 0]` is the identity).
pub fn parse_path_data(d: &str, m: &[f64; 6]) -> Result<Vec<SvgSubpath>, SvgError> {
    let mut lex = Lexer {
        s: d.as_bytes(),
        pos: 0,
    };
    let mut b = Builder {
        done: Vec::new(),
        segments: Vec::new(),
        current: [0.0; 2],
        start: [0.0; 2],
    };
    let mut cmd: Option<u8> = None;
    loop {
        let explicit = lex.command();
        let c = match (explicit, cmd) {
            (Some(c), _) => c,
            (None, Some(c)) if lex.at_number() => c,
            (None, _) if lex.pos >= lex.s.len() => break,
            (None, _) => return err(format!("unexpected path data at byte {}", lex.pos)),
        };
        let rel = c.is_ascii_lowercase();
        let base = if rel { b.current } else { [0.0, 0.0] };
        let offset = |p: P2| [p[0] + base[0], p[1] + base[1]];
        match c.to_ascii_uppercase() {
            b'M' => {
                b.finish(false);
                let p = offset(lex.pair()?);
                b.current = p;
                b.start = p;
                // Further coordinate pairs after a moveto are implicit linetos.
                cmd = Some(if rel { b'l' } else { b'L' });
                continue;
            }
            b'L' => {
                let p = offset(lex.pair()?);
                b.line_to(p);
            }
            b'H' => {
                let x = lex.number()? + base[0];
                b.line_to([x, b.current[1]]);
            }
            b'V' => {
                let y = lex.number()? + base[1];
                b.line_to([b.current[0], y]);
            }
            b'C' => {
                let (p1, p2, p3) = (
                    offset(lex.pair()?),
                    offset(lex.pair()?),
                    offset(lex.pair()?),
                );
                b.segments.push(Segment::Cubic([b.current, p1, p2, p3]));
                b.current = p3;
            }
            b'Z' => {
                if b.current != b.start {
                    b.line_to(b.start);
                }
                b.finish(true);
                b.current = b.start;
                cmd = None;
                continue;
            }
            _ => return err(format!("unsupported path command {:?}", c as char)),
        }
        cmd = Some(c);
    }
    b.finish(false);
    Ok(b.done
        .into_iter()
        .map(|s| transform_subpath(s, m))
        .collect())
}

fn transform_subpath(s: SvgSubpath, m: &Affine) -> SvgSubpath {
    let segments = s
        .segments
        .into_iter()
        .map(|seg| match seg {
            Segment::Line(a, b) => Segment::Line(apply(m, a), apply(m, b)),
            Segment::Cubic(p) => Segment::Cubic(p.map(|q| apply(m, q))),
        })
        .collect();
    SvgSubpath {
        segments,
        closed: s.closed,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transforms_compose_right_to_left() {
        let m = parse_transform("translate(10, 0) scale(2)").unwrap();
        assert_eq!(apply(&m, [1.0, 1.0]), [12.0, 2.0]);
        let r = parse_transform("rotate(90 1 1)").unwrap();
        let p = apply(&r, [2.0, 1.0]);
        assert!((p[0] - 1.0).abs() < 1e-12 && (p[1] - 2.0).abs() < 1e-12);
        let mat = parse_transform("matrix(1,2,3,4,5,6)").unwrap();
        assert_eq!(apply(&mat, [1.0, 1.0]), [9.0, 12.0]);
        assert!(parse_transform("skewX(3)").is_err());
    }

    #[test]
    fn number_lexing() {
        assert_eq!(
            numbers("1,-2.5e1 .5.5-1").unwrap(),
            vec![1.0, -25.0, 0.5, 0.5, -1.0]
        );
        // A dangling exponent marker is not part of the number, and not a number either.
        assert!(numbers(" 3e ").is_err());
        assert!(numbers("1 x").is_err());
    }

    #[test]
    fn corners_at_cusps_only() {
        // A smooth join (collinear handles) and a cusp.
        let id = IDENTITY;
        let subs = parse_path_data("M 0 0 C 1 0 2 0 3 0 C 4 0 5 1 5 2 L 8 2", &id).unwrap();
        let dense = subs[0].dense(0.1);
        assert_eq!(dense.corners.len(), 1);
        assert_eq!(dense.points[dense.corners[0]], [5.0, 2.0]);
        assert!(!dense.closed);
        assert_eq!(*dense.points.last().unwrap(), [8.0, 2.0]);
    }
}
