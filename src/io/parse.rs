//! Reading point files: plain text, CSV and Triangle `.node` / Dey `.gtn`.
//!
//! # Formats
//!
//! * **Plain text** ([`InputFormat::Text`]): one point per line, `x` and `y` separated by white
//!   space and/or one comma; further columns are ignored (`x y z`, `x<TAB>y<TAB>1`).
//! * **CSV** ([`InputFormat::Csv`]): the same lines, after an optional header line such as
//!   `x,y` (any first line whose fields are all words rather than numbers). Fields may be
//!   quoted (`"1.5","2"`).
//! * **Triangle `.node` / Dey `.gtn`** ([`InputFormat::Node`]): a header line `N 2 A B`
//!   (point count, dimension 2, attribute count, boundary-marker flag 0 or 1), then `N` lines
//!   `index x y [attributes] [marker]`. The indices must run consecutively from 0 or from 1, and
//!   the number of point lines must be `N`.
//!
//! In every format blank lines are skipped, `#` starts a comment that runs to the end of the
//! line, and `\n`, `\r\n` and lone `\r` all end a line. A point's index is its position among
//! the points read, counting from 0, whatever the format.
//!
//! # Detection
//!
//! [`format_from_path`] maps the extensions `.node` and `.gtn` to [`InputFormat::Node`] and
//! `.csv` to [`InputFormat::Csv`]; everything else is detected from the content by
//! [`detect_format`] (which [`read_points`] does on the fly when given no format): a first line
//! of four integers `N 2 A B` followed by a matching `index x y ...` line is a `.node` header; a
//! first line of words is a CSV header; anything else is plain text.
//!
//! # Errors
//!
//! Every problem is a [`ParseError`] carrying the 1-based number of the offending line: a
//! token that is not a number, a line with only one number, NaN or infinity, a decimal that
//! rounds to zero or overflows as an `f64` (every finite `f64` itself is accepted, see
//! [`crate::error::check_coordinate`]), binary data, a `.node`
//! header that does not match its points, or an I/O error.

use std::fmt;
use std::fs::File;
use std::io::{self, BufRead, BufReader};
use std::path::Path;

use super::lines::LineReader;
use crate::error::check_coordinate;

/// The point-file formats understood by [`read_points`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum InputFormat {
    /// One point per line: two numbers separated by white space and/or one comma, further
    /// columns ignored. No header line.
    Text,
    /// Like [`InputFormat::Text`], after an optional header line of column names (`x,y`).
    Csv,
    /// Triangle `.node` or Dey `.gtn`: a header `N 2 A B`, then `index x y [attributes] [marker]`.
    Node,
}

impl fmt::Display for InputFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            InputFormat::Text => "text",
            InputFormat::Csv => "csv",
            InputFormat::Node => "node",
        })
    }
}

/// Which coordinate of a point a problem is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum Axis {
    /// The first coordinate.
    X,
    /// The second coordinate.
    Y,
}

impl fmt::Display for Axis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Axis::X => "x",
            Axis::Y => "y",
        })
    }
}

/// What is wrong with the input; see [`ParseError`] for where.
#[derive(Debug)]
#[non_exhaustive]
pub enum ParseErrorKind {
    /// Reading failed.
    Io(io::Error),
    /// The input contains a NUL byte: binary data or UTF-16 text.
    NulByte,
    /// The input is not valid UTF-8: binary data.
    InvalidUtf8,
    /// A line is longer than `limit` bytes: binary data without line breaks.
    LineTooLong {
        /// The limit in bytes.
        limit: usize,
    },
    /// A coordinate token is not a number.
    NotANumber {
        /// The coordinate.
        axis: Axis,
        /// The token as found (shortened if long).
        token: String,
    },
    /// A coordinate field is empty, as in `1,,2` or `,2`.
    EmptyField {
        /// The coordinate.
        axis: Axis,
    },
    /// The line holds only one number.
    MissingY,
    /// A coordinate is NaN or infinite.
    NotFinite {
        /// The coordinate.
        axis: Axis,
        /// The token as found.
        token: String,
    },
    /// A non-zero decimal so small that it rounds to zero as an `f64` (the point would move).
    TooSmall {
        /// The coordinate.
        axis: Axis,
        /// The token as found.
        token: String,
    },
    /// A decimal so large that it overflows an `f64`.
    TooLarge {
        /// The coordinate.
        axis: Axis,
        /// The token as found.
        token: String,
    },
    /// The first line of a `.node` file is not `N 2 A B`.
    NodeHeader {
        /// What does not match.
        reason: String,
    },
    /// A `.node` point line has fewer than the three fields `index x y`.
    NodeFields {
        /// Number of fields found.
        found: usize,
    },
    /// A `.node` point index is not the expected one.
    NodeIndex {
        /// The index token as found.
        token: String,
        /// The index expected; `None` for the first point, whose index must be 0 or 1.
        expected: Option<u64>,
    },
    /// A `.node` file has fewer point lines than its header declares (reported on the header line).
    NodeTooFewPoints {
        /// Points declared by the header.
        declared: u64,
        /// Points found.
        found: usize,
    },
    /// A `.node` file has more point lines than its header declares (reported on the first extra line).
    NodeTooManyPoints {
        /// Points declared by the header.
        declared: u64,
    },
}

impl fmt::Display for ParseErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParseErrorKind::Io(e) => write!(f, "read error: {e}"),
            ParseErrorKind::NulByte => f.write_str(
                "NUL byte: this looks like a binary (or UTF-16) file, not a text file of point coordinates",
            ),
            ParseErrorKind::InvalidUtf8 => f.write_str(
                "invalid UTF-8: this looks like a binary file, not a text file of point coordinates",
            ),
            ParseErrorKind::LineTooLong { limit } => write!(
                f,
                "line longer than {limit} bytes: this looks like a binary file, not a text file of point coordinates"
            ),
            ParseErrorKind::NotANumber { axis, token } => write!(
                f,
                "{axis} coordinate {token:?} is not a number (expected `x y`, `x,y` or `x y z...`)"
            ),
            ParseErrorKind::EmptyField { axis } => {
                write!(f, "empty field where the {axis} coordinate should be")
            }
            ParseErrorKind::MissingY => {
                f.write_str("only one number on the line; a point needs two coordinates `x y`")
            }
            ParseErrorKind::NotFinite { axis, token } => {
                write!(f, "{axis} coordinate {token:?} is not a finite number")
            }
            ParseErrorKind::TooSmall { axis, token } => write!(
                f,
                "{axis} coordinate {token:?} is non-zero but rounds to zero as a 64-bit float \
                 (its magnitude is below about 2.5e-324)"
            ),
            ParseErrorKind::TooLarge { axis, token } => write!(
                f,
                "{axis} coordinate {token:?} overflows a 64-bit float (its magnitude is above \
                 about 1.8e308)"
            ),
            ParseErrorKind::NodeHeader { reason } => write!(
                f,
                "bad .node header: {reason}; expected `N 2 A B` (point count, dimension 2, \
                 attribute count, boundary-marker flag 0 or 1)"
            ),
            ParseErrorKind::NodeFields { found } => write!(
                f,
                "a .node point line needs `index x y`, found {found} field{}",
                if *found == 1 { "" } else { "s" }
            ),
            ParseErrorKind::NodeIndex {
                token,
                expected: None,
            } => write!(
                f,
                "the first point index must be 0 or 1, found {token:?}"
            ),
            ParseErrorKind::NodeIndex {
                token,
                expected: Some(expected),
            } => write!(
                f,
                "point index {token:?} is out of sequence, expected {expected}"
            ),
            ParseErrorKind::NodeTooFewPoints { declared, found } => write!(
                f,
                "the .node header declares {declared} points but the file has {found}"
            ),
            ParseErrorKind::NodeTooManyPoints { declared } => write!(
                f,
                "more points than the {declared} declared by the .node header"
            ),
        }
    }
}

/// A point file that could not be read: where (1-based line number) and what.
#[derive(Debug)]
#[non_exhaustive]
pub struct ParseError {
    /// The 1-based line number of the problem, if it has one (opening a file has none).
    pub line: Option<usize>,
    /// What is wrong.
    pub kind: ParseErrorKind,
}

impl ParseError {
    fn at(line: usize, kind: ParseErrorKind) -> Self {
        ParseError {
            line: Some(line),
            kind,
        }
    }
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "line {line}: {}", self.kind),
            None => write!(f, "{}", self.kind),
        }
    }
}

impl std::error::Error for ParseError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            ParseErrorKind::Io(e) => Some(e),
            _ => None,
        }
    }
}

impl From<io::Error> for ParseError {
    fn from(e: io::Error) -> Self {
        ParseError {
            line: None,
            kind: ParseErrorKind::Io(e),
        }
    }
}

/// The format implied by a file name's extension (case-insensitive): `.node` and `.gtn` are
/// [`InputFormat::Node`], `.csv` is [`InputFormat::Csv`]; anything else is `None`, to be
/// detected from the content.
pub fn format_from_path(path: &Path) -> Option<InputFormat> {
    let ext = path.extension()?.to_str()?.to_ascii_lowercase();
    match ext.as_str() {
        "node" | "gtn" => Some(InputFormat::Node),
        "csv" => Some(InputFormat::Csv),
        _ => None,
    }
}

/// Detects the format from the start of a file's content (a few lines are enough).
///
/// A first line of four integers `N 2 A B` followed by a line `index x y ...` with the
/// matching number of fields and index 0 or 1 is [`InputFormat::Node`] (so is `0 2 A B`
/// alone); a first line made only of words (`x,y`, `"x","y"`, `X Y`) or with a comma is
/// [`InputFormat::Csv`]; anything else is [`InputFormat::Text`]. Blank lines and `#` comments
/// are skipped, and the content need not be valid UTF-8 (only the lines looked at are decoded).
///
/// ```
/// use wdm_crust::io::{detect_format, InputFormat};
/// assert_eq!(detect_format(b"3 2 0 0\n0 1.5 2\n1 3 4\n2 5 6\n"), InputFormat::Node);
/// assert_eq!(detect_format(b"x,y\r\n1,2\r\n"), InputFormat::Csv);
/// assert_eq!(detect_format(b"# points\n1.5 2\n"), InputFormat::Text);
/// ```
pub fn detect_format(head: &[u8]) -> InputFormat {
    // The reader skips a UTF-8 byte-order mark; detection must see the same first line.
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    let mut significant = head
        .split(|&b| b == b'\n' || b == b'\r')
        .filter_map(|line| std::str::from_utf8(line).ok())
        .map(strip_comment)
        .filter(|line| !line.is_empty());
    let Some(first) = significant.next() else {
        return InputFormat::Text;
    };
    if let Some(header) = node_header_candidate(first) {
        match significant.next() {
            Some(second) if header.confirmed_by(second) => return InputFormat::Node,
            None if header.count == 0 => return InputFormat::Node,
            _ => {}
        }
    }
    if looks_like_header(first) || first.contains(',') {
        InputFormat::Csv
    } else {
        InputFormat::Text
    }
}

/// Reads the points of a file, with the format implied by its extension
/// ([`format_from_path`]) or else detected from the content.
///
/// # Errors
/// An error opening the file has no line number; every other error is as for [`read_points`].
pub fn read_points_from_path(path: &Path) -> Result<Vec<[f64; 2]>, ParseError> {
    let file = File::open(path)?;
    read_points(
        BufReader::with_capacity(1 << 16, file),
        format_from_path(path),
    )
}

/// Reads points from `reader`, in `format` or, if `None`, in the format detected from the
/// content (see [`detect_format`]). The reader is consumed line by line, never held whole.
///
/// # Errors
/// The first problem found, with its 1-based line number (see the [module docs](self)).
///
/// ```
/// let text = "# x y\n1.5 2\r\n-3,4e2\r5\t6\t0.8\n";
/// let points = wdm_crust::io::read_points(text.as_bytes(), None)?;
/// assert_eq!(points, vec![[1.5, 2.0], [-3.0, 400.0], [5.0, 6.0]]);
///
/// let err = wdm_crust::io::read_points("1 2\n3 four\n".as_bytes(), None).unwrap_err();
/// assert_eq!(err.line, Some(2));
/// # Ok::<(), wdm_crust::io::ParseError>(())
/// ```
pub fn read_points<R: BufRead>(
    reader: R,
    format: Option<InputFormat>,
) -> Result<Vec<[f64; 2]>, ParseError> {
    let mut lines = LineReader::new(reader);
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut state = State::Start;
    while let Some((line_number, raw)) = lines.next_line()? {
        let line = strip_comment(raw);
        if line.is_empty() {
            continue;
        }
        let at = |kind| ParseError::at(line_number, kind);
        state = match state {
            State::Start => match format {
                Some(InputFormat::Node) => {
                    let header = parse_node_header(line).map_err(at)?;
                    points.reserve(header.count.min(1 << 20) as usize);
                    State::Node(NodeState::new(header, line_number))
                }
                Some(InputFormat::Csv) if looks_like_header(line) => State::Delimited,
                Some(_) => {
                    points.push(parse_delimited(line).map_err(at)?);
                    State::Delimited
                }
                None => {
                    if let Some(header) = node_header_candidate(line) {
                        State::PendingNode(header, line_number)
                    } else {
                        if !looks_like_header(line) {
                            points.push(parse_delimited(line).map_err(at)?);
                        }
                        State::Delimited
                    }
                }
            },
            State::PendingNode(header, header_line) => {
                if header.confirmed_by(line) {
                    points.reserve(header.count.min(1 << 20) as usize);
                    let mut node = NodeState::new(header, header_line);
                    points.push(node.parse_point(line).map_err(at)?);
                    State::Node(node)
                } else {
                    // Not a .node file after all: the first line was a point with extra columns.
                    points.push(header.as_point());
                    points.push(parse_delimited(line).map_err(at)?);
                    State::Delimited
                }
            }
            State::Delimited => {
                points.push(parse_delimited(line).map_err(at)?);
                State::Delimited
            }
            State::Node(mut node) => {
                points.push(node.parse_point(line).map_err(at)?);
                State::Node(node)
            }
        };
    }
    match state {
        State::PendingNode(header, _) if header.count > 0 => points.push(header.as_point()),
        State::Node(node) if node.seen < node.header.count => {
            return Err(ParseError::at(
                node.header_line,
                ParseErrorKind::NodeTooFewPoints {
                    declared: node.header.count,
                    found: points.len(),
                },
            ))
        }
        _ => {}
    }
    Ok(points)
}

/// Where the reader is in the file.
enum State {
    /// No significant line yet.
    Start,
    /// The first line could be a `.node` header (on the given line); the next line decides.
    PendingNode(NodeHeader, usize),
    /// Text or CSV point lines.
    Delimited,
    /// `.node` point lines.
    Node(NodeState),
}

/// A `.node` header `N 2 A B`.
#[derive(Debug, Clone, Copy)]
struct NodeHeader {
    count: u64,
    attributes: u64,
    markers: u64,
}

impl NodeHeader {
    /// Whether `line` is the first point line of a file with this header: exactly
    /// `3 + A + B` fields, an index of 0 or 1, and numeric coordinates.
    fn confirmed_by(&self, line: &str) -> bool {
        let mut fields = Fields::new(line);
        let (Some(Ok(index)), Some(Ok(x)), Some(Ok(y))) =
            (fields.next(), fields.next(), fields.next())
        else {
            return false;
        };
        let rest = fields.count() as u64;
        (index == "0" || index == "1")
            && x.parse::<f64>().is_ok()
            && y.parse::<f64>().is_ok()
            && Some(rest) == self.attributes.checked_add(self.markers)
    }

    /// The header line read as a point of plain text: `(N, 2)`.
    fn as_point(&self) -> [f64; 2] {
        [self.count as f64, 2.0]
    }
}

/// Progress through the point lines of a `.node` file.
struct NodeState {
    header: NodeHeader,
    header_line: usize,
    /// Point lines read so far.
    seen: u64,
    /// Index of the first point (0 or 1), once read.
    base: Option<u64>,
}

impl NodeState {
    fn new(header: NodeHeader, header_line: usize) -> Self {
        NodeState {
            header,
            header_line,
            seen: 0,
            base: None,
        }
    }

    /// Parses `index x y [attributes] [marker]`, checking the index and the count.
    fn parse_point(&mut self, line: &str) -> Result<[f64; 2], ParseErrorKind> {
        if self.seen == self.header.count {
            return Err(ParseErrorKind::NodeTooManyPoints {
                declared: self.header.count,
            });
        }
        let mut fields = Fields::new(line);
        let mut tokens = [""; 3];
        for (found, slot) in tokens.iter_mut().enumerate() {
            match fields.next() {
                Some(Ok(token)) => *slot = token,
                Some(Err(())) if found > 0 && fields.pos < line.len() => {
                    let axis = if found == 1 { Axis::X } else { Axis::Y };
                    return Err(ParseErrorKind::EmptyField { axis });
                }
                _ => return Err(ParseErrorKind::NodeFields { found }),
            }
        }
        let [index_token, x_token, y_token] = tokens;
        let index = index_token.parse::<u64>().ok();
        match (self.base, index) {
            (None, Some(base @ (0 | 1))) => self.base = Some(base),
            (None, _) => {
                return Err(ParseErrorKind::NodeIndex {
                    token: shorten(index_token),
                    expected: None,
                })
            }
            (Some(base), index) => {
                let expected = base + self.seen;
                if index != Some(expected) {
                    return Err(ParseErrorKind::NodeIndex {
                        token: shorten(index_token),
                        expected: Some(expected),
                    });
                }
            }
        }
        let point = [
            parse_coordinate(x_token, Axis::X)?,
            parse_coordinate(y_token, Axis::Y)?,
        ];
        self.seen += 1;
        Ok(point)
    }
}

/// The line before any `#` comment, without surrounding white space.
fn strip_comment(line: &str) -> &str {
    let line = match line.find('#') {
        Some(i) => &line[..i],
        None => line,
    };
    line.trim_matches(is_blank_char)
}

/// White space between fields (line ends never reach the tokenizer).
#[inline]
fn is_blank_char(c: char) -> bool {
    matches!(c, ' ' | '\t' | '\x0b' | '\x0c')
}

#[inline]
fn is_blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\x0b' | b'\x0c')
}

/// The fields of a trimmed line: separated by white space and/or one comma, optionally
/// quoted with `"`. An empty field (`1,,2`, `,1`, `1,`) is `Err(())`.
struct Fields<'a> {
    line: &'a str,
    pos: usize,
    first: bool,
}

impl<'a> Fields<'a> {
    fn new(line: &'a str) -> Self {
        Fields {
            line,
            pos: 0,
            first: true,
        }
    }
}

impl<'a> Iterator for Fields<'a> {
    type Item = Result<&'a str, ()>;

    fn next(&mut self) -> Option<Self::Item> {
        let bytes = self.line.as_bytes();
        let n = bytes.len();
        let mut p = self.pos;
        while p < n && is_blank(bytes[p]) {
            p += 1;
        }
        let mut comma = false;
        if !self.first && p < n && bytes[p] == b',' {
            comma = true;
            p += 1;
            while p < n && is_blank(bytes[p]) {
                p += 1;
            }
        }
        self.first = false;
        if p == n {
            self.pos = n;
            return if comma { Some(Err(())) } else { None };
        }
        if bytes[p] == b',' {
            self.pos = p;
            return Some(Err(()));
        }
        if bytes[p] == b'"' {
            if let Some(len) = self.line[p + 1..].find('"') {
                let end = p + 1 + len;
                let after = end + 1;
                if after == n || is_blank(bytes[after]) || bytes[after] == b',' {
                    self.pos = after;
                    return Some(Ok(&self.line[p + 1..end]));
                }
            }
        }
        let start = p;
        while p < n && !is_blank(bytes[p]) && bytes[p] != b',' {
            p += 1;
        }
        self.pos = p;
        Some(Ok(&self.line[start..p]))
    }
}

/// Whether a line is a header of column names: every field a word that starts with a letter
/// or `_` and is not a number (`nan`, `inf` and `infinity` are numbers).
fn looks_like_header(line: &str) -> bool {
    Fields::new(line).all(|field| match field {
        Ok(word) => {
            word.starts_with(|c: char| c.is_alphabetic() || c == '_')
                && word.parse::<f64>().is_err()
        }
        Err(()) => false,
    })
}

/// A line of exactly four unsigned integers `N 2 A B` with `B` 0 or 1: possibly a `.node` header.
fn node_header_candidate(line: &str) -> Option<NodeHeader> {
    let mut fields = line.split(is_blank_char).filter(|f| !f.is_empty());
    let mut number = || fields.next()?.parse::<u64>().ok();
    let (count, dimension, attributes, markers) = (number()?, number()?, number()?, number()?);
    if fields.next().is_some() || dimension != 2 || markers > 1 {
        return None;
    }
    Some(NodeHeader {
        count,
        attributes,
        markers,
    })
}

/// Parses a `.node` header strictly, saying what is wrong.
fn parse_node_header(line: &str) -> Result<NodeHeader, ParseErrorKind> {
    let fields: Vec<&str> = line
        .split(is_blank_char)
        .filter(|f| !f.is_empty())
        .collect();
    let bad = |reason: String| ParseErrorKind::NodeHeader { reason };
    if fields.len() != 4 {
        return Err(bad(format!(
            "found {} field{} instead of 4",
            fields.len(),
            if fields.len() == 1 { "" } else { "s" }
        )));
    }
    let names = [
        "point count",
        "dimension",
        "attribute count",
        "boundary-marker flag",
    ];
    let mut values = [0u64; 4];
    for ((value, field), name) in values.iter_mut().zip(&fields).zip(names) {
        *value = field.parse::<u64>().map_err(|_| {
            bad(format!(
                "the {name} {:?} is not a non-negative integer",
                shorten(field)
            ))
        })?;
    }
    let [count, dimension, attributes, markers] = values;
    if dimension != 2 {
        return Err(bad(format!(
            "the dimension is {dimension}, only 2 is supported"
        )));
    }
    if markers > 1 {
        return Err(bad(format!(
            "the boundary-marker flag is {markers}, it must be 0 or 1"
        )));
    }
    Ok(NodeHeader {
        count,
        attributes,
        markers,
    })
}

/// Parses the first two fields of a text or CSV line as a point.
#[inline]
fn parse_delimited(line: &str) -> Result<[f64; 2], ParseErrorKind> {
    let mut fields = Fields::new(line);
    let x = match fields.next() {
        Some(Ok(token)) => parse_coordinate(token, Axis::X)?,
        Some(Err(())) | None => return Err(ParseErrorKind::EmptyField { axis: Axis::X }),
    };
    let y = match fields.next() {
        Some(Ok(token)) => parse_coordinate(token, Axis::Y)?,
        Some(Err(())) if fields.pos < line.len() => {
            return Err(ParseErrorKind::EmptyField { axis: Axis::Y })
        }
        Some(Err(())) | None => return Err(ParseErrorKind::MissingY),
    };
    Ok([x, y])
}

/// Parses one coordinate: any decimal that is a finite `f64` without rounding to zero.
#[inline]
fn parse_coordinate(token: &str, axis: Axis) -> Result<f64, ParseErrorKind> {
    let value = token
        .parse::<f64>()
        .map_err(|_| ParseErrorKind::NotANumber {
            axis,
            token: shorten(token),
        })?;
    if value == 0.0 && has_nonzero_digit(token) {
        // A decimal like 1e-400 that rounds to zero: refuse it rather than move the point.
        return Err(ParseErrorKind::TooSmall {
            axis,
            token: shorten(token),
        });
    }
    if value.is_infinite() && token.bytes().all(|b| !matches!(b, b'i' | b'I')) {
        // A decimal like 1e400 that overflows: too large rather than "infinite".
        return Err(ParseErrorKind::TooLarge {
            axis,
            token: shorten(token),
        });
    }
    match check_coordinate(0, value) {
        Ok(()) => Ok(value),
        Err(_) => Err(ParseErrorKind::NotFinite {
            axis,
            token: shorten(token),
        }),
    }
}

/// Whether the significand of a decimal token has a non-zero digit.
fn has_nonzero_digit(token: &str) -> bool {
    token
        .bytes()
        .take_while(|&b| b != b'e' && b != b'E')
        .any(|b| (b'1'..=b'9').contains(&b))
}

/// A token for an error message, cut to a readable length.
fn shorten(token: &str) -> String {
    const MAX_CHARS: usize = 40;
    match token.char_indices().nth(MAX_CHARS) {
        Some((i, _)) => format!("{}...", &token[..i]),
        None => token.to_string(),
    }
}

#[cfg(test)]
mod tests;
