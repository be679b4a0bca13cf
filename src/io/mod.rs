//! Reading point files and writing results.
//!
//! * [`read_points`] / [`read_points_from_path`] read plain text, CSV and Triangle `.node` /
//!   Dey `.gtn` point files (see [`parse`] for the formats and the errors, each with its line);
//!   [`read_points_with`] also takes the columns of x and y ([`ReadOptions`]).
//! * [`write_triangulation_json`] / [`write_triangulation_text`],
//!   [`write_voronoi_json`] / [`write_voronoi_text`] and
//!   [`write_reconstruction_json`] / [`write_reconstruction_text`] write a
//!   [`Triangulation`](crate::Triangulation), a [`Voronoi`](crate::Voronoi) diagram and a
//!   [`Reconstruction`](crate::Reconstruction) (see [`output`] for the formats).
//! * [`write_reconstruction_svg`] draws a reconstruction as an SVG picture (see [`svg`]).
//! * [`write_voronoi_geojson`] writes the Voronoi cells clipped to a box as GeoJSON polygons.
//! * [`write_reconstruction_geojson`] writes a reconstruction as GeoJSON: polygons with
//!   holes, open chains, the medial axis, the unassigned points (see [`geojson`]).

pub mod geojson;
mod lines;
pub mod output;
pub mod parse;
pub mod svg;
mod voronoi_geojson;

pub use geojson::write_reconstruction_geojson;
pub use output::{
    write_reconstruction_json, write_reconstruction_text, write_triangulation_json,
    write_triangulation_text, write_voronoi_json, write_voronoi_text,
};
pub use parse::{
    detect_format, format_from_path, read_points, read_points_from_path, read_points_with, Axis,
    Column, ColumnSelection, ColumnSelectionError, FileKind, InputFormat, ParseError,
    ParseErrorKind, ReadOptions,
};
pub use svg::{write_reconstruction_svg, SvgOptions};
pub use voronoi_geojson::write_voronoi_geojson;
