//! Triangle `.node` / Dey `.gtn`: a header `N 2 A B`, then `N` lines
//! `index x y [A attributes] [marker]`, with consecutive indices from 0 or 1.

use super::fields::{is_blank_char, Fields};
use super::{parse_coordinate, shorten, Axis, ParseErrorKind};

/// A `.node` header `N 2 A B`.
#[derive(Debug, Clone, Copy)]
pub(super) struct NodeHeader {
    pub(super) count: u64,
    attributes: u64,
    markers: u64,
}

impl NodeHeader {
    /// Fields of a point line: index, x, y, the attributes and the marker.
    fn fields(&self) -> Option<u64> {
        self.attributes.checked_add(self.markers)?.checked_add(3)
    }

    /// Whether `line` is the first point line of a file with this header: exactly
    /// `3 + A + B` fields, an index of 0 or 1, and numeric coordinates.
    pub(super) fn confirmed_by(&self, line: &str) -> bool {
        let mut fields = Fields::new(line);
        let (Some(index), Some(x), Some(y)) = (fields.next(), fields.next(), fields.next()) else {
            return false;
        };
        let count = 3 + fields.count() as u64;
        (index == "0" || index == "1")
            && x.parse::<f64>().is_ok()
            && y.parse::<f64>().is_ok()
            && Some(count) == self.fields()
    }

    /// The header line read as a row of plain text: the four numbers `N 2 A B`.
    pub(super) fn as_row(&self) -> [f64; 4] {
        [
            self.count as f64,
            2.0,
            self.attributes as f64,
            self.markers as f64,
        ]
    }
}

/// A line of exactly four unsigned integers `N 2 A B` with `B` 0 or 1: possibly a `.node` header.
pub(super) fn node_header_candidate(line: &str) -> Option<NodeHeader> {
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
pub(super) fn parse_node_header(line: &str) -> Result<NodeHeader, ParseErrorKind> {
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

/// Progress through the point lines of a `.node` file.
pub(super) struct NodeState {
    pub(super) header: NodeHeader,
    pub(super) header_line: usize,
    /// Point lines read so far.
    pub(super) seen: u64,
    /// Index of the first point (0 or 1), once read.
    base: Option<u64>,
}

impl NodeState {
    pub(super) fn new(header: NodeHeader, header_line: usize) -> Self {
        NodeState {
            header,
            header_line,
            seen: 0,
            base: None,
        }
    }

    /// Parses `index x y [attributes] [marker]`, checking the index, the number of fields
    /// and the number of points.
    pub(super) fn parse_point(&mut self, line: &str) -> Result<[f64; 2], ParseErrorKind> {
        if self.seen == self.header.count {
            return Err(ParseErrorKind::NodeTooManyPoints {
                declared: self.header.count,
            });
        }
        let mut fields = Fields::new(line);
        let mut tokens = [""; 3];
        for (found, slot) in tokens.iter_mut().enumerate() {
            *slot = fields.next().ok_or(ParseErrorKind::NodeFields { found })?;
        }
        let found = 3 + fields.count() as u64;
        if Some(found) != self.header.fields() {
            return Err(ParseErrorKind::NodeFieldCount {
                found,
                attributes: self.header.attributes,
                markers: self.header.markers,
            });
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
        let coordinate = |token: &str, axis| match token {
            "" => Err(ParseErrorKind::EmptyField { axis }),
            token => parse_coordinate(token, axis),
        };
        let point = [coordinate(x_token, Axis::X)?, coordinate(y_token, Axis::Y)?];
        self.seen += 1;
        Ok(point)
    }
}
