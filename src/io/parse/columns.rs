//! Text and CSV rows: which columns hold x and y (by name from a header, or the first two),
//! and the rule that every row has as many columns as the header or the first row.

use super::fields::Fields;
use super::{parse_coordinate, shorten, Axis, ParseErrorKind};

/// Column names listed in an error message, at most.
const NAMES_SHOWN: usize = 12;

/// Where the coordinates are in a row, and how many columns a row has.
#[derive(Debug, Clone, Copy)]
pub(super) struct Columns {
    x: usize,
    y: usize,
    count: usize,
    /// The line that set `count`: the header, or the first row.
    line: usize,
    from_header: bool,
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

impl Columns {
    /// The columns of a file without a header whose first row, on `line`, has `count` fields.
    pub(super) fn first_row(count: usize, line: usize) -> Self {
        Columns {
            x: 0,
            y: 1,
            count,
            line,
            from_header: false,
        }
    }

    /// The columns named by a header line (see [`looks_like_header`]): `x` and `y`, compared
    /// without regard to case.
    pub(super) fn from_header(line: &str, line_number: usize) -> Result<Self, ParseErrorKind> {
        let names: Vec<&str> = Fields::new(line).collect();
        let find = |wanted: &str| -> Result<Option<usize>, ParseErrorKind> {
            let mut found = (0..names.len()).filter(|&i| names[i].eq_ignore_ascii_case(wanted));
            let first = found.next();
            if found.next().is_some() {
                return Err(ParseErrorKind::DuplicateColumn {
                    name: wanted.to_string(),
                });
            }
            Ok(first)
        };
        match (find("x")?, find("y")?) {
            (Some(x), Some(y)) => Ok(Columns {
                x,
                y,
                count: names.len(),
                line: line_number,
                from_header: true,
            }),
            _ => Err(ParseErrorKind::HeaderWithoutXY {
                columns: names.iter().take(NAMES_SHOWN).map(|n| shorten(n)).collect(),
                more: names.len().saturating_sub(NAMES_SHOWN),
            }),
        }
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
        if !layout.from_header && (count < 2 || y == Some("") && count == 2) {
            // `3`, `3,`: one number where a point needs two (or one token that is no number).
            if let Some(token) = x.filter(|t| !t.is_empty()) {
                parse_coordinate(token, Axis::X)?;
            }
            return Err(ParseErrorKind::MissingY);
        }
        if layout.count == 0 {
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
}
