//! Reading point files: plain text, CSV and Triangle `.node` / Dey `.gtn`.
//!
//! # Formats
//!
//! * **Plain text** ([`InputFormat::Text`]): one point per line, `x` and `y` in the first two
//!   columns; further columns are ignored (`x y z`, `x<TAB>y<TAB>1`, `x,y,label`). A line with
//!   a comma is split at its commas (white space around a field is trimmed); a line without one
//!   at runs of white space. Plain text has no header: a first line of column names makes
//!   detected content CSV, and is an error ([`ParseErrorKind::HeaderInText`]) when plain text
//!   is asked for explicitly.
//! * **CSV** ([`InputFormat::Csv`]): the same rows, after an optional header line of column
//!   names on the first line that is not a comment or blank (a line with no number and at
//!   least one word, such as `x,y`, `id,x,y`, `",x,y"` or `X Y`). A header selects the
//!   coordinates by name, compared without regard to case, quotes and white space around
//!   them: the columns `x` and `y`, `lon` and `lat` (`lng`, `long` or `longitude` with `lat`
//!   or `latitude`), or `easting` and `northing`, wherever they are (`lat,lon` reads the
//!   second column as x). Fields may be quoted (`"1.5","2"`, `"a, b",1,2`).
//!
//! # Choosing the columns
//!
//! A [`ColumnSelection`] ([`ReadOptions::with_columns`], the command line's `--columns X,Y`)
//! names the columns of x and y instead: header names (any case), or 1-based positions,
//! which also read a file without a header (`--columns 2,3` for `id x y` rows). A header is
//! read only when it is unambiguous, and otherwise refused with a message that says to
//! choose the columns:
//!
//! * no pair of the names above (`x (m),y (m)`, `lat` alone): [`ParseErrorKind::HeaderWithoutXY`];
//! * a name twice (`x,y,X`): [`ParseErrorKind::DuplicateColumn`];
//! * more than one pair (`x,y` beside `lon,lat`; `lon` and `longitude` beside `lat`):
//!   [`ParseErrorKind::AmbiguousColumns`].
//!
//! A chosen name that the header lacks is an error listing the header's columns; a name in
//! a file without a header, a position beyond the header or first row, and any selection
//! for a `.node` file are errors too.
//! * **Triangle `.node` / Dey `.gtn`** ([`InputFormat::Node`]): a header line `N 2 A B`
//!   (point count, dimension 2, attribute count, boundary-marker flag 0 or 1), then `N` lines
//!   `index x y [attributes] [marker]` of exactly `3 + A + B` fields. The indices must run
//!   consecutively from 0 or from 1.
//!
//! In every format blank lines are skipped, `#` starts a comment that runs to the end of the
//! line, and `\n`, `\r\n` and lone `\r` all end a line. A point's index is its position among
//! the points read, counting from 0, whatever the format.
//!
//! # Read right or refused
//!
//! Text and CSV rows must all have as many columns as the header (or, without one, as the
//! first row): a decimal comma, a thousands separator or a missing value shifts the columns of
//! its row, and is refused instead of read as a different point. A decimal comma inside a
//! line, `0,5 1,5`, makes a field with white space inside (`5 1`), which is not a number;
//! `0,5;1,5` makes a field with a semicolon. What no rule can catch is a file whose every
//! value has a decimal comma and no white space (`0,5,1,5` on every line reads as four
//! columns); such files must be converted first.
//!
//! # Detection
//!
//! [`format_from_path`] maps the extensions `.node` and `.gtn` to [`InputFormat::Node`] and
//! `.csv` to [`InputFormat::Csv`]; everything else is detected from the content by
//! [`detect_format`] (which [`read_points`] does on the fly when given no format): a first line
//! of four integers `N 2 A B` followed by a matching `index x y ...` line is a `.node` header; a
//! first line of column names is a CSV header; anything else is plain text.
//!
//! # Errors
//!
//! Every problem is a [`ParseError`] carrying the 1-based number of the offending line: a
//! token that is not a number, a line with only one number, a row with the wrong number of
//! columns, a header without a pair of coordinate names or with more than one, NaN or
//! infinity, a decimal that rounds to zero or overflows as an `f64` (every finite `f64`
//! itself is accepted, see [`crate::error::check_coordinate`]), binary data, a `.node` header
//! that does not match its points, or an I/O error.
//!
//! A file that is no point list at all is refused before its first line, with what it looks
//! like and what to do ([`ParseErrorKind::NotAPointFile`], [`FileKind`]): an SVG, HTML or
//! other XML document, JSON or GeoJSON, gzip/xz/bzip2/zstd data, a ZIP archive (spreadsheets
//! are ones), a PDF, a PNG/JPEG/GIF image, UTF-16 text. Each of them would be refused anyway;
//! the test only chooses the message.

use std::fmt;
use std::fs::File;
use std::io::{self, BufRead, BufReader, Read};
use std::path::Path;

mod columns;
mod fields;
mod node;
mod sniff;

pub use self::columns::{Column, ColumnSelection, ColumnSelectionError};
pub use self::sniff::FileKind;

use self::columns::{looks_like_header, Columns};
use self::fields::is_blank_char;
use self::node::{node_header_candidate, parse_node_header, NodeHeader, NodeState};
use super::lines::LineReader;
use crate::error::check_coordinate;

/// The point-file formats understood by [`read_points`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum InputFormat {
    /// One point per line: x and y in the first two columns, separated by commas or white
    /// space, further columns ignored. No header line.
    Text,
    /// Like [`InputFormat::Text`], after an optional header line of column names that selects
    /// the coordinate columns by name (`x,y`, `id,x,y`, `lon,lat`; see the
    /// [module docs](self)).
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
    /// A `.node` point line has three or more fields, but not the `3 + A + B` its header asks for.
    NodeFieldCount {
        /// Number of fields found.
        found: u64,
        /// Attributes per point, from the header.
        attributes: u64,
        /// Boundary markers per point (0 or 1), from the header.
        markers: u64,
    },
    /// A text or CSV row has a different number of columns than the header or the first row.
    ColumnCount {
        /// Columns in this row.
        found: usize,
        /// Columns in the header or the first row.
        expected: usize,
        /// The line of the header or the first row.
        line: usize,
        /// Whether `line` is a header (column names) rather than the first row.
        header: bool,
    },
    /// A CSV header (a first line of column names) without a pair of coordinate names:
    /// `x` and `y`, `lon` and `lat` (or their longer spellings), `easting` and `northing`.
    HeaderWithoutXY {
        /// The column names found (the first few, shortened).
        columns: Vec<String>,
        /// How many more names the header has.
        more: usize,
    },
    /// A CSV header names two columns `x` (or two `y`, two `lat`, ...), or a column chosen
    /// by a [`ColumnSelection`] by name is there twice.
    DuplicateColumn {
        /// The name repeated.
        name: String,
    },
    /// A CSV header names more than one pair of coordinate columns (`x,y` beside `lon,lat`,
    /// or `lon` and `longitude` beside `lat`): which one is meant is not guessed.
    AmbiguousColumns {
        /// The pairs found, `[x, y]` as the header spells them.
        pairs: Vec<[String; 2]>,
    },
    /// A column chosen by name ([`ColumnSelection`]) is not in the header.
    ColumnNotFound {
        /// The name asked for.
        name: String,
        /// The column names the header has (the first few, shortened).
        columns: Vec<String>,
        /// How many more names the header has.
        more: usize,
    },
    /// A column chosen by position ([`ColumnSelection`]) is beyond the header or the first
    /// row.
    NoSuchColumn {
        /// The 1-based position asked for.
        position: usize,
        /// Columns in the header or the first row.
        count: usize,
        /// Whether `count` is the header's rather than the first row's.
        header: bool,
    },
    /// A [`ColumnSelection`] chooses one column for both x and y (a name and the position
    /// of the same column).
    SameColumn {
        /// The column's name in the header.
        name: String,
    },
    /// A [`ColumnSelection`] chooses a column by name, but the file has no header line.
    ColumnsWithoutHeader {
        /// The name asked for.
        name: String,
    },
    /// A [`ColumnSelection`] was given for a `.node` file, whose columns are fixed.
    ColumnsInNode,
    /// The content is not a point list at all but another kind of file (an SVG drawing,
    /// JSON, a compressed file, an image, UTF-16 text...); reported without a line.
    NotAPointFile {
        /// What it looks like.
        looks_like: FileKind,
    },
    /// The first line is a header of column names, but the format is plain text, which has
    /// none (read it as [`InputFormat::Csv`], or let the format be detected).
    HeaderInText,
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
                "{axis} coordinate {token:?} is not a number ({})",
                not_a_number_hint(token)
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
            ParseErrorKind::NodeFieldCount {
                found,
                attributes,
                markers,
            } => write!(
                f,
                "{found} fields, but the .node header asks for 3 + {attributes} + {markers} \
                 (index, x, y, {attributes} attribute{}, {markers} boundary marker{})",
                if *attributes == 1 { "" } else { "s" },
                if *markers == 1 { "" } else { "s" }
            ),
            ParseErrorKind::ColumnCount {
                found,
                expected,
                line,
                header,
            } => write!(
                f,
                "{found} column{}, but {} on line {line} has {expected}; every row must have \
                 the same number of columns (a decimal comma, a thousands separator or a \
                 missing value would shift them)",
                if *found == 1 { "" } else { "s" },
                if *header { "the header" } else { "the first row" }
            ),
            ParseErrorKind::HeaderWithoutXY { columns, more } => {
                f.write_str("the header line names the columns ")?;
                write_names(f, columns, *more)?;
                f.write_str(
                    " but no pair of coordinate names it knows (x,y; lon, lng, long or \
                     longitude with lat or latitude; easting,northing; any case): choose the \
                     columns with --columns X,Y, or remove the header line",
                )?;
                if columns.iter().any(|name| name.contains(';')) {
                    f.write_str(" (semicolons do not separate columns here: use commas)")?;
                }
                Ok(())
            }
            ParseErrorKind::DuplicateColumn { name } => write!(
                f,
                "the header line names two columns {name:?}; the coordinates must be \
                 unambiguous: choose them by position with --columns X,Y (e.g. --columns 2,3)"
            ),
            ParseErrorKind::AmbiguousColumns { pairs } => {
                f.write_str("the header line names more than one pair of coordinate columns (")?;
                for (i, [x, y]) in pairs.iter().enumerate() {
                    let separator = match i {
                        0 => "",
                        _ if i + 1 == pairs.len() => " and ",
                        _ => ", ",
                    };
                    write!(f, "{separator}`{x},{y}`")?;
                }
                write!(
                    f,
                    "): choose one with --columns X,Y (e.g. --columns {},{})",
                    pairs[0][0], pairs[0][1]
                )
            }
            ParseErrorKind::ColumnNotFound {
                name,
                columns,
                more,
            } => {
                write!(
                    f,
                    "--columns asks for a column {name:?}, but the header line has none \
                     (names are compared in any case); its columns are "
                )?;
                write_names(f, columns, *more)
            }
            ParseErrorKind::NoSuchColumn {
                position,
                count,
                header,
            } => write!(
                f,
                "--columns asks for column {position}, but {} has {count} column{}",
                if *header {
                    "the header line"
                } else {
                    "the first row"
                },
                if *count == 1 { "" } else { "s" }
            ),
            ParseErrorKind::SameColumn { name } => write!(
                f,
                "--columns chooses the column {name:?} for both x and y"
            ),
            ParseErrorKind::ColumnsWithoutHeader { name } => write!(
                f,
                "--columns asks for a column {name:?} by name, but the file has no header line \
                 (this first line is a row, not column names): choose the columns by their \
                 1-based position (e.g. --columns 2,3), or add a header line"
            ),
            ParseErrorKind::ColumnsInNode => f.write_str(
                "--columns chooses the columns of text and CSV files, but this is a .node file \
                 (`index x y ...` after a header `N 2 A B`): leave --columns out",
            ),
            ParseErrorKind::NotAPointFile { looks_like } => write!(
                f,
                "this looks like {looks_like}, not a list of points; {}",
                looks_like.advice()
            ),
            ParseErrorKind::HeaderInText => f.write_str(
                "a header line of column names, but plain text has none; read the file as CSV",
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

/// `"a", "b", "c" and 4 more`.
fn write_names(f: &mut fmt::Formatter<'_>, names: &[String], more: usize) -> fmt::Result {
    for (i, name) in names.iter().enumerate() {
        write!(f, "{}{name:?}", if i == 0 { "" } else { ", " })?;
    }
    if more > 0 {
        write!(f, " and {more} more")?;
    }
    Ok(())
}

/// A point file that could not be read: where (1-based line number) and what.
#[derive(Debug)]
#[non_exhaustive]
pub struct ParseError {
    /// The 1-based line number of the problem, if it has one (opening a file, and a file
    /// that is no point list at all, [`ParseErrorKind::NotAPointFile`], have none).
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
/// alone); a first line of column names (`x,y`, `"x","y"`, `id x y`) or with a comma is
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
/// let text = "# x y\n1.5 2 0.1\r\n-3,4e2,0.2\r5\t6\t0.8\n";
/// let points = wdm_crust::io::read_points(text.as_bytes(), None)?;
/// assert_eq!(points, vec![[1.5, 2.0], [-3.0, 400.0], [5.0, 6.0]]);
///
/// // A header selects the columns by name.
/// let csv = "id,X,Y\n7,1.5,2\n8,-3,400\n";
/// let points = wdm_crust::io::read_points(csv.as_bytes(), None)?;
/// assert_eq!(points, vec![[1.5, 2.0], [-3.0, 400.0]]);
///
/// let err = wdm_crust::io::read_points("1 2\n3 four\n".as_bytes(), None).unwrap_err();
/// assert_eq!(err.line, Some(2));
/// // Decimal commas are refused, not read as other points.
/// let err = wdm_crust::io::read_points("0,5 1,5\n".as_bytes(), None).unwrap_err();
/// assert!(err.to_string().contains("decimal comma"));
/// # Ok::<(), wdm_crust::io::ParseError>(())
/// ```
pub fn read_points<R: BufRead>(
    reader: R,
    format: Option<InputFormat>,
) -> Result<Vec<[f64; 2]>, ParseError> {
    let options = ReadOptions {
        format,
        columns: None,
    };
    read_points_with(reader, &options)
}

/// How [`read_points_with`] reads a file: in which format, and which columns hold x and y.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct ReadOptions {
    format: Option<InputFormat>,
    columns: Option<ColumnSelection>,
}

impl ReadOptions {
    /// The format detected from the content, the coordinate columns found by the header's
    /// names (or the first two).
    pub fn new() -> Self {
        Self::default()
    }

    /// Reads the file in `format` instead of detecting it.
    pub fn with_format(mut self, format: InputFormat) -> Self {
        self.format = Some(format);
        self
    }

    /// Reads x and y from these columns of a text or CSV file (by header name, or by
    /// position) instead of the header's coordinate names or the first two columns.
    pub fn with_columns(mut self, columns: ColumnSelection) -> Self {
        self.columns = Some(columns);
        self
    }

    /// See [`with_format`](Self::with_format); `None`: detected.
    pub fn format(&self) -> Option<InputFormat> {
        self.format
    }

    /// See [`with_columns`](Self::with_columns).
    pub fn columns(&self) -> Option<&ColumnSelection> {
        self.columns.as_ref()
    }
}

/// Reads points from `reader` as [`read_points`] does, with the format and the coordinate
/// columns of `options`.
///
/// # Errors
/// As for [`read_points`]; besides, a column of the [`ColumnSelection`] that the file does
/// not have, a selection by name in a file without a header, or any selection in a `.node`
/// file.
pub fn read_points_with<R: BufRead>(
    mut reader: R,
    options: &ReadOptions,
) -> Result<Vec<[f64; 2]>, ParseError> {
    // The kind of file is told from a head of fixed length, read here whatever the
    // reader's buffer holds (a small buffer must not change the verdict), then read again
    // by the line reader in front of the rest.
    let mut head = Vec::with_capacity(sniff::HEAD_BYTES);
    if let Err(e) = (&mut reader)
        .take(sniff::HEAD_BYTES as u64)
        .read_to_end(&mut head)
    {
        // On the line being read, as the line reader would say.
        let ends = head
            .iter()
            .enumerate()
            .filter(|&(i, &b)| b == b'\n' || (b == b'\r' && head.get(i + 1) != Some(&b'\n')))
            .count();
        let line = 1 + ends;
        return Err(ParseError::at(line, ParseErrorKind::Io(e)));
    }
    if let Some(kind) = sniff::sniff(&head) {
        return Err(ParseError {
            line: None,
            kind: ParseErrorKind::NotAPointFile { looks_like: kind },
        });
    }
    let (format, selection) = (options.format, options.columns.as_ref());
    let mut lines = LineReader::new(io::Cursor::new(head).chain(reader));
    let mut points: Vec<[f64; 2]> = Vec::new();
    let mut state = State::Start;
    while let Some((line_number, raw)) = lines.next_line()? {
        let line = strip_comment(raw);
        if line.is_empty() {
            continue;
        }
        let at = |kind| ParseError::at(line_number, kind);
        state = match state {
            State::Start => {
                let node_header = match format {
                    Some(InputFormat::Node) => Some(parse_node_header(line).map_err(at)?),
                    None => node_header_candidate(line),
                    Some(_) => None,
                };
                match (node_header, format) {
                    (Some(_), Some(_)) if selection.is_some() => {
                        return Err(at(ParseErrorKind::ColumnsInNode));
                    }
                    (Some(header), Some(_)) => {
                        points.reserve(header.count.min(1 << 20) as usize);
                        State::Node(NodeState::new(header, line_number))
                    }
                    (Some(header), None) => State::PendingNode(header, line_number),
                    (None, Some(InputFormat::Text)) if looks_like_header(line) => {
                        return Err(at(ParseErrorKind::HeaderInText));
                    }
                    (None, _) if looks_like_header(line) => State::Rows(Some(
                        Columns::from_header(line, line_number, selection).map_err(at)?,
                    )),
                    (None, _) => {
                        let mut columns =
                            Some(Columns::without_header(selection, line_number).map_err(at)?);
                        points
                            .push(Columns::parse_row(&mut columns, line, line_number).map_err(at)?);
                        State::Rows(columns)
                    }
                }
            }
            State::PendingNode(header, header_line) => {
                if header.confirmed_by(line) {
                    if selection.is_some() {
                        return Err(ParseError::at(header_line, ParseErrorKind::ColumnsInNode));
                    }
                    points.reserve(header.count.min(1 << 20) as usize);
                    let mut node = NodeState::new(header, header_line);
                    points.push(node.parse_point(line).map_err(at)?);
                    State::Node(node)
                } else {
                    // Not a .node file after all: the first line was a row of four numbers.
                    let columns = first_row_of_four(header, header_line, selection)?;
                    points.push(
                        columns
                            .point_of(&header.as_row())
                            .map_err(|kind| ParseError::at(header_line, kind))?,
                    );
                    let mut columns = Some(columns);
                    points.push(Columns::parse_row(&mut columns, line, line_number).map_err(at)?);
                    State::Rows(columns)
                }
            }
            State::Rows(mut columns) => {
                points.push(Columns::parse_row(&mut columns, line, line_number).map_err(at)?);
                State::Rows(columns)
            }
            State::Node(mut node) => {
                points.push(node.parse_point(line).map_err(at)?);
                State::Node(node)
            }
        };
    }
    match state {
        State::PendingNode(header, header_line) if header.count > 0 => {
            let columns = first_row_of_four(header, header_line, selection)?;
            let point = columns
                .point_of(&header.as_row())
                .map_err(|kind| ParseError::at(header_line, kind))?;
            points.push(point);
        }
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

/// The columns of a file whose first line, `header_line`, looked like a `.node` header
/// `N 2 A B` but was a row of four numbers.
fn first_row_of_four(
    header: NodeHeader,
    header_line: usize,
    selection: Option<&ColumnSelection>,
) -> Result<Columns, ParseError> {
    let mut columns = Columns::without_header(selection, header_line)
        .map_err(|kind| ParseError::at(header_line, kind))?;
    columns.set_count(header.as_row().len());
    Ok(columns)
}

/// Where the reader is in the file.
enum State {
    /// No significant line yet.
    Start,
    /// The first line could be a `.node` header (on the given line); the next line decides.
    PendingNode(NodeHeader, usize),
    /// Text or CSV rows; `None` until the first row (or the header) fixes the columns.
    Rows(Option<Columns>),
    /// `.node` point lines.
    Node(NodeState),
}

/// The line before any `#` comment, without surrounding white space.
fn strip_comment(line: &str) -> &str {
    let line = match line.find('#') {
        Some(i) => &line[..i],
        None => line,
    };
    line.trim_matches(is_blank_char)
}

/// Parses one coordinate: any decimal that is a finite `f64` without rounding to zero.
#[inline]
pub(super) fn parse_coordinate(token: &str, axis: Axis) -> Result<f64, ParseErrorKind> {
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

/// What a token that is not a number probably is, for the error message.
fn not_a_number_hint(token: &str) -> &'static str {
    let digit = |c: Option<char>| c.is_some_and(|c| c.is_ascii_digit());
    let between_digits = |separator: char| {
        token.match_indices(separator).any(|(i, _)| {
            digit(token[..i].chars().next_back()) && digit(token[i + 1..].chars().next())
        })
    };
    if token.contains(';') {
        "semicolons do not separate fields here, and decimal commas are not supported: \
         write `0.5 1.5` or `0.5,1.5`"
    } else if between_digits(',') || token.contains(|c: char| is_blank_char(c)) {
        "decimal commas are not supported: write `0.5 1.5` or `0.5,1.5`, not `0,5 1,5`"
    } else {
        "expected `x y`, `x,y` or `x y z...`"
    }
}

/// A token for an error message, cut to a readable length.
pub(super) fn shorten(token: &str) -> String {
    const MAX_CHARS: usize = 40;
    match token.char_indices().nth(MAX_CHARS) {
        Some((i, _)) => format!("{}...", &token[..i]),
        None => token.to_string(),
    }
}

#[cfg(test)]
mod tests;
