//! Text and CSV rows: which columns hold x and y (chosen with a [`ColumnSelection`], by name
//! from a header, or the first two), and the rule that every row has as many columns as the
//! header or the first row.

use std::fmt;
use std::str::FromStr;

use super::fields::Fields;
use super::{parse_coordinate, shorten, Axis, ParseErrorKind};

/// Column names listed in an error message, at most.
const NAMES_SHOWN: usize = 12;

/// The header names recognised without a [`ColumnSelection`], one family per row: the names
/// of its x column, the names of its y column. Compared without regard to ASCII case.
const COORDINATE_NAMES: [(&[&str], &[&str]); 3] = [
    (&["x"], &["y"]),
    (&["lon", "lng", "long", "longitude"], &["lat", "latitude"]),
    (&["easting"], &["northing"]),
];

/// One coordinate column of a [`ColumnSelection`].
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Column {
    /// The header column of this name, compared without regard to ASCII case (quotes and
    /// white space around a header name are not part of it).
    Name(String),
    /// The column at this position, counting from 1: of the header, or of the rows of a file
    /// without one.
    Position(usize),
}

impl fmt::Display for Column {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Column::Name(name) => f.write_str(name),
            Column::Position(position) => write!(f, "{position}"),
        }
    }
}

/// Which columns of a text or CSV file hold x and y, instead of the header's names: the
/// command line's `--columns X,Y`.
///
/// Each column is a header name (any case) or a 1-based position; a position also reads a
/// file without a header. The two must be different columns.
///
/// ```
/// use wdm_crust::io::{read_points_with, Column, ColumnSelection, ReadOptions};
/// let columns: ColumnSelection = "Lat_deg,LON_DEG".parse()?;
/// assert_eq!(columns.x(), &Column::Name("Lat_deg".into()));
/// // y first in the file: the names decide, not the order.
/// let csv = "station,lon_deg,lat_deg\nA,7.5,46.25\nB,8,47\n";
/// let options = ReadOptions::new().with_columns("lon_deg,lat_deg".parse()?);
/// assert_eq!(read_points_with(csv.as_bytes(), &options)?, vec![[7.5, 46.25], [8.0, 47.0]]);
/// // By position, in a file without a header.
/// let options = ReadOptions::new().with_columns("3,2".parse()?);
/// assert_eq!(read_points_with("7 1 2\n8 3 4\n".as_bytes(), &options)?, vec![[2.0, 1.0], [4.0, 3.0]]);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct ColumnSelection {
    x: Column,
    y: Column,
}

impl ColumnSelection {
    /// The columns `x` and `y`; an error when they are the same name (any case) or the same
    /// position, or a position is 0.
    pub fn new(x: Column, y: Column) -> Result<Self, ColumnSelectionError> {
        for column in [&x, &y] {
            match column {
                Column::Position(0) => {
                    return Err(ColumnSelectionError(
                        "column positions count from 1".to_string(),
                    ))
                }
                Column::Name(name) if name.is_empty() => {
                    return Err(ColumnSelectionError("a column name is empty".to_string()))
                }
                _ => {}
            }
        }
        let same = match (&x, &y) {
            (Column::Name(a), Column::Name(b)) => a.eq_ignore_ascii_case(b),
            (a, b) => a == b,
        };
        if same {
            let (a, b) = (x.to_string(), y.to_string());
            return Err(ColumnSelectionError(if a == b {
                format!("x and y must be two different columns, got {a} twice")
            } else {
                format!(
                    "x and y must be two different columns, got {a} and {b} (names are \
                     compared in any case)"
                )
            }));
        }
        Ok(ColumnSelection { x, y })
    }

    /// The column of x.
    pub fn x(&self) -> &Column {
        &self.x
    }

    /// The column of y.
    pub fn y(&self) -> &Column {
        &self.y
    }

    /// Whether a column is chosen by name (which needs a header).
    fn names_a_column(&self) -> Option<&str> {
        [&self.x, &self.y].into_iter().find_map(|c| match c {
            Column::Name(name) => Some(name.as_str()),
            Column::Position(_) => None,
        })
    }
}

impl fmt::Display for ColumnSelection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{},{}", self.x, self.y)
    }
}

/// `X,Y`: two names or 1-based positions separated by one comma, white space around each
/// ignored. A field of decimal digits only is a position.
impl FromStr for ColumnSelection {
    type Err = ColumnSelectionError;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let fields: Vec<&str> = text.split(',').map(str::trim).collect();
        let [x, y] = fields[..] else {
            return Err(ColumnSelectionError(format!(
                "expected two columns X,Y (names or 1-based positions) separated by a comma, got {}",
                if fields.len() == 1 {
                    "one".to_string()
                } else {
                    fields.len().to_string()
                }
            )));
        };
        let column = |field: &str| -> Result<Column, ColumnSelectionError> {
            if !field.is_empty() && field.bytes().all(|b| b.is_ascii_digit()) {
                let position = field.parse::<usize>().map_err(|_| {
                    ColumnSelectionError(format!("column position {field} is too large"))
                })?;
                Ok(Column::Position(position))
            } else {
                Ok(Column::Name(field.to_string()))
            }
        };
        ColumnSelection::new(column(x)?, column(y)?)
    }
}

/// A [`ColumnSelection`] that cannot be made: what is wrong with it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ColumnSelectionError(String);

impl fmt::Display for ColumnSelectionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ColumnSelectionError {}

/// Where the coordinates are in a row, and how many columns a row has.
#[derive(Debug, Clone, Copy)]
pub(super) struct Columns {
    x: usize,
    y: usize,
    count: usize,
    /// The line that set `count`: the header, or the first row.
    line: usize,
    from_header: bool,
    /// Chosen by position in a file without a header (not the first two columns).
    by_position: bool,
}

/// Whether a line is a header of column names: no field is a number, and at least one is a
/// word (starts with a letter or `_`; `nan`, `inf` and `infinity` are numbers). Empty fields
/// are allowed (`,x,y`, the header of an unnamed index column).
pub(super) fn looks_like_header(line: &str) -> bool {
    let mut words = 0;
    for field in Fields::new(line) {
        if field.is_empty() {
            continue;
        }
        let word = field.starts_with(|c: char| c.is_alphabetic() || c == '_')
            && field.parse::<f64>().is_err();
        if !word {
            return false;
        }
        words += 1;
    }
    words > 0
}

/// The names of a header for an error message: the first few, shortened, and how many more.
fn shown(names: &[&str]) -> (Vec<String>, usize) {
    (
        names.iter().take(NAMES_SHOWN).map(|n| shorten(n)).collect(),
        names.len().saturating_sub(NAMES_SHOWN),
    )
}

impl Columns {
    /// The columns of a file without a header whose first row, on `line`, has `count` fields.
    pub(super) fn first_row(count: usize, line: usize) -> Self {
        Columns {
            x: 0,
            y: 1,
            count,
            line,
            from_header: false,
            by_position: false,
        }
    }

    /// The columns of a file without a header whose first row is on `line`: the first two,
    /// or the positions of `selection`; a selection by name is an error (there is no header
    /// to find the name in).
    pub(super) fn without_header(
        selection: Option<&ColumnSelection>,
        line: usize,
    ) -> Result<Self, ParseErrorKind> {
        let Some(selection) = selection else {
            return Ok(Columns::first_row(0, line));
        };
        let (&Column::Position(x), &Column::Position(y)) = (selection.x(), selection.y()) else {
            return Err(ParseErrorKind::ColumnsWithoutHeader {
                name: shorten(selection.names_a_column().unwrap_or_default()),
            });
        };
        Ok(Columns {
            // Positions count from 1 (`ColumnSelection::new` refuses 0).
            x: x.saturating_sub(1),
            y: y.saturating_sub(1),
            count: 0,
            line,
            from_header: false,
            by_position: true,
        })
    }

    /// The columns named by a header line (see [`looks_like_header`]): those of `selection`,
    /// or else the one pair of recognised coordinate names (see [`COORDINATE_NAMES`]).
    pub(super) fn from_header(
        line: &str,
        line_number: usize,
        selection: Option<&ColumnSelection>,
    ) -> Result<Self, ParseErrorKind> {
        let names: Vec<&str> = Fields::new(line).collect();
        let (x, y) = match selection {
            Some(selection) => (
                find_selected(&names, selection.x())?,
                find_selected(&names, selection.y())?,
            ),
            None => find_coordinate_names(&names)?,
        };
        if x == y {
            // A name and the position of the same column.
            return Err(ParseErrorKind::SameColumn {
                name: shorten(names[x]),
            });
        }
        Ok(Columns {
            x,
            y,
            count: names.len(),
            line: line_number,
            from_header: true,
            by_position: false,
        })
    }

    /// Parses a row, against these columns or, for the first row of a file without a header
    /// (`columns` is `None`), taking x and y from its first two columns and setting the
    /// column count for the rows after it.
    #[inline]
    pub(super) fn parse_row(
        columns: &mut Option<Columns>,
        line: &str,
        line_number: usize,
    ) -> Result<[f64; 2], ParseErrorKind> {
        let layout = *columns.get_or_insert(Columns::first_row(0, line_number));
        let (mut x, mut y, mut count) = (None, None, 0);
        for (i, field) in Fields::new(line).enumerate() {
            if i == layout.x {
                x = Some(field);
            } else if i == layout.y {
                y = Some(field);
            }
            count = i + 1;
        }
        if !layout.from_header && !layout.by_position && (count < 2 || y == Some("") && count == 2)
        {
            // `3`, `3,`: one number where a point needs two (or one token that is no number).
            if let Some(token) = x.filter(|t| !t.is_empty()) {
                parse_coordinate(token, Axis::X)?;
            }
            return Err(ParseErrorKind::MissingY);
        }
        if layout.count == 0 {
            let needed = layout.x.max(layout.y) + 1;
            if count < needed {
                return Err(ParseErrorKind::NoSuchColumn {
                    position: needed,
                    count,
                    header: false,
                });
            }
            if let Some(c) = columns.as_mut() {
                c.count = count;
            }
        } else if count != layout.count {
            return Err(ParseErrorKind::ColumnCount {
                found: count,
                expected: layout.count,
                line: layout.line,
                header: layout.from_header,
            });
        }
        let coordinate = |field: Option<&str>, axis| match field {
            Some("") | None => Err(ParseErrorKind::EmptyField { axis }),
            Some(token) => parse_coordinate(token, axis),
        };
        Ok([coordinate(x, Axis::X)?, coordinate(y, Axis::Y)?])
    }

    /// Sets the column count of a file without a header from its first row.
    pub(super) fn set_count(&mut self, count: usize) {
        self.count = count;
    }

    /// The point of the first line of a file without a header, already split into the
    /// numbers `fields` (the four integers of a line that looked like a `.node` header).
    pub(super) fn point_of(&self, fields: &[f64]) -> Result<[f64; 2], ParseErrorKind> {
        let needed = self.x.max(self.y) + 1;
        if fields.len() < needed {
            return Err(ParseErrorKind::NoSuchColumn {
                position: needed,
                count: fields.len(),
                header: false,
            });
        }
        Ok([fields[self.x], fields[self.y]])
    }
}

/// The header column chosen by `column`.
fn find_selected(names: &[&str], column: &Column) -> Result<usize, ParseErrorKind> {
    match column {
        Column::Position(position) => {
            if *position <= names.len() {
                Ok(position.saturating_sub(1))
            } else {
                Err(ParseErrorKind::NoSuchColumn {
                    position: *position,
                    count: names.len(),
                    header: true,
                })
            }
        }
        Column::Name(wanted) => {
            let mut found = (0..names.len()).filter(|&i| names[i].eq_ignore_ascii_case(wanted));
            match (found.next(), found.next()) {
                (Some(i), None) => Ok(i),
                (Some(_), Some(_)) => Err(ParseErrorKind::DuplicateColumn {
                    name: shorten(wanted),
                }),
                (None, _) => {
                    let (columns, more) = shown(names);
                    Err(ParseErrorKind::ColumnNotFound {
                        name: shorten(wanted),
                        columns,
                        more,
                    })
                }
            }
        }
    }
}

/// The one pair of recognised coordinate names in a header: x and y, or a pair of another
/// family of [`COORDINATE_NAMES`]. Refused when it could be misread: no pair, a name twice,
/// or more than one pair (`x,y` beside `lon,lat`, or `lon` beside `longitude`).
fn find_coordinate_names(names: &[&str]) -> Result<(usize, usize), ParseErrorKind> {
    let is_one_of =
        |list: &[&str], i: usize| list.iter().any(|name| names[i].eq_ignore_ascii_case(name));
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    for (x_names, y_names) in COORDINATE_NAMES {
        let xs: Vec<usize> = (0..names.len())
            .filter(|&i| is_one_of(x_names, i))
            .collect();
        let ys: Vec<usize> = (0..names.len())
            .filter(|&i| is_one_of(y_names, i))
            .collect();
        for found in [&xs, &ys] {
            if let [a, b, ..] = found[..] {
                if names[a].eq_ignore_ascii_case(names[b]) {
                    return Err(ParseErrorKind::DuplicateColumn {
                        name: shorten(&names[a].to_ascii_lowercase()),
                    });
                }
            }
        }
        for &x in &xs {
            for &y in &ys {
                pairs.push((x, y));
            }
        }
    }
    match pairs[..] {
        [pair] => Ok(pair),
        [] => {
            let (columns, more) = shown(names);
            Err(ParseErrorKind::HeaderWithoutXY { columns, more })
        }
        _ => Err(ParseErrorKind::AmbiguousColumns {
            pairs: pairs
                .iter()
                .map(|&(x, y)| [shorten(names[x]), shorten(names[y])])
                .collect(),
        }),
    }
}
