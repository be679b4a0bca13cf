//! The wdm-crust engine in the browser: the WebAssembly face of the static page in `web/`.
//!
//! The page's Web Worker calls [`parse_points`] on a file's bytes, [`reconstruct`] on the
//! points with the choices of the page's controls, and reads the drawing, the summary, the
//! warnings and the downloads off the [`Outcome`]. Everything is the engine's own: the
//! parser and its messages, the exact kernel, the command line's JSON, SVG and GeoJSON
//! writers; the logic is in [`engine`], which runs natively too, and this layer converts.
#![deny(unsafe_code)]

pub mod engine;

use wasm_bindgen::prelude::*;

use engine::{Choices, Drawing, SvgLayers};

/// The points of the file `name`, from its bytes, as `x, y` pairs.
///
/// # Errors
/// The parser's message, after the file name: `bad.txt: line 2: ...`.
#[wasm_bindgen(js_name = parsePoints)]
pub fn parse_points(name: &str, bytes: &[u8]) -> Result<Vec<f64>, String> {
    let points = engine::read_points(name, bytes)?;
    Ok(points.into_iter().flatten().collect())
}

/// Reconstructs the points `coords` (`x, y` pairs) with the page's choices, calling
/// `on_phase(name)` as each phase of the pipeline ends; the Voronoi diagram and its labels
/// are drawn only `with_voronoi`.
///
/// # Errors
/// An unknown choice, or the engine's error about the points.
#[wasm_bindgen]
#[allow(clippy::too_many_arguments)] // the page's controls, one argument each
pub fn reconstruct(
    coords: &[f64],
    algorithm: &str,
    peeling: bool,
    medial_axis: &str,
    smoothing: bool,
    thinning: bool,
    with_voronoi: bool,
    on_phase: &js_sys::Function,
) -> Result<Outcome, String> {
    let choices = Choices {
        algorithm: algorithm.to_string(),
        peeling,
        medial_axis: medial_axis.to_string(),
        smoothing,
        thinning,
    };
    let options = engine::options(&choices)?;
    let points: Vec<[f64; 2]> = coords.chunks_exact(2).map(|p| [p[0], p[1]]).collect();
    let rec = engine::reconstruct(&points, &options, &mut |phase| {
        // A progress report: a failing callback must not fail the reconstruction.
        let _ = on_phase.call1(&JsValue::NULL, &JsValue::from_str(phase));
    })?;
    let drawing = engine::drawing(&rec, with_voronoi);
    Ok(Outcome { rec, drawing })
}

/// A reconstruction and what the page draws of it.
#[wasm_bindgen]
pub struct Outcome {
    rec: wdm_crust::Reconstruction,
    drawing: Drawing,
}

#[wasm_bindgen]
impl Outcome {
    /// `1 closed curve, 0 open chains, 0 points on no curve, 0 duplicates. ...`.
    pub fn summary(&self) -> String {
        engine::summary(&self.rec)
    }

    /// The warnings, one line each: the message and its code in brackets.
    pub fn warnings(&self) -> Vec<String> {
        engine::warnings(&self.rec)
    }

    /// The command line's JSON (`--format json`).
    pub fn json(&self) -> String {
        engine::json(&self.rec)
    }

    /// The command line's GeoJSON (`--format geojson`).
    pub fn geojson(&self) -> String {
        engine::geojson(&self.rec)
    }

    /// The command line's SVG picture with these layers (`--show`, `--y-down`).
    pub fn svg(&self, delaunay: bool, voronoi: bool, labels: bool, y_down: bool) -> String {
        let layers = SvgLayers {
            delaunay,
            voronoi,
            labels,
            y_down,
        };
        engine::svg(&self.rec, layers)
    }

    /// See [`Drawing::curve_closed`].
    #[wasm_bindgen(js_name = curveClosed)]
    pub fn curve_closed(&self) -> Vec<u8> {
        self.drawing.curve_closed.clone()
    }

    /// See [`Drawing::curve_offsets`].
    #[wasm_bindgen(js_name = curveOffsets)]
    pub fn curve_offsets(&self) -> Vec<u32> {
        self.drawing.curve_offsets.clone()
    }

    /// See [`Drawing::curve_points`].
    #[wasm_bindgen(js_name = curvePoints)]
    pub fn curve_points(&self) -> Vec<u32> {
        self.drawing.curve_points.clone()
    }

    /// See [`Drawing::curve_coords`].
    #[wasm_bindgen(js_name = curveCoords)]
    pub fn curve_coords(&self) -> Vec<f64> {
        self.drawing.curve_coords.clone()
    }

    /// See [`Drawing::unassigned`].
    pub fn unassigned(&self) -> Vec<u32> {
        self.drawing.unassigned.clone()
    }

    /// See [`Drawing::axis_vertices`].
    #[wasm_bindgen(js_name = axisVertices)]
    pub fn axis_vertices(&self) -> Vec<f64> {
        self.drawing.axis_vertices.clone()
    }

    /// See [`Drawing::axis_edges`].
    #[wasm_bindgen(js_name = axisEdges)]
    pub fn axis_edges(&self) -> Vec<u32> {
        self.drawing.axis_edges.clone()
    }

    /// See [`Drawing::delaunay_edges`].
    #[wasm_bindgen(js_name = delaunayEdges)]
    pub fn delaunay_edges(&self) -> Vec<u32> {
        self.drawing.delaunay_edges.clone()
    }

    /// See [`Drawing::voronoi_vertices`].
    #[wasm_bindgen(js_name = voronoiVertices)]
    pub fn voronoi_vertices(&self) -> Vec<f64> {
        self.drawing.voronoi_vertices.clone()
    }

    /// See [`Drawing::voronoi_edges`].
    #[wasm_bindgen(js_name = voronoiEdges)]
    pub fn voronoi_edges(&self) -> Vec<u32> {
        self.drawing.voronoi_edges.clone()
    }

    /// See [`Drawing::voronoi_rays`].
    #[wasm_bindgen(js_name = voronoiRays)]
    pub fn voronoi_rays(&self) -> Vec<f64> {
        self.drawing.voronoi_rays.clone()
    }

    /// See [`Drawing::voronoi_bisectors`].
    #[wasm_bindgen(js_name = voronoiBisectors)]
    pub fn voronoi_bisectors(&self) -> Vec<u32> {
        self.drawing.voronoi_bisectors.clone()
    }

    /// See [`Drawing::labels`].
    pub fn labels(&self) -> Vec<u8> {
        self.drawing.labels.clone()
    }

    /// See [`Drawing::warning_points`].
    #[wasm_bindgen(js_name = warningPoints)]
    pub fn warning_points(&self) -> Vec<u32> {
        self.drawing.warning_points.clone()
    }
}
