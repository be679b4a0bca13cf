//! Reading point files and writing results.
//!
//! * [`read_points`] / [`read_points_from_path`] read plain text, CSV and Triangle `.node` /
//!   Dey `.gtn` point files (see [`parse`] for the formats and the errors, each with its line).
//! * [`write_triangulation_json`] and [`write_triangulation_text`] write a
//!   [`Triangulation`](crate::Triangulation) (see [`output`] for the formats).

mod lines;
pub mod output;
pub mod parse;

pub use output::{write_triangulation_json, write_triangulation_text};
pub use parse::{
    detect_format, format_from_path, read_points, read_points_from_path, Axis, InputFormat,
    ParseError, ParseErrorKind,
};
