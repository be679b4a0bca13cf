use super::*;

fn svg_with(rec: &Reconstruction, options: &SvgOptions) -> String {
    let mut out = Vec::new();
    write_reconstruction_svg(rec, options, &mut out).unwrap();
    String::from_utf8(out).unwrap()
}

fn svg_of(points: &[[f64; 2]], options: &SvgOptions) -> String {
    svg_with(&crate::reconstruct(points).unwrap(), options)
}

fn all_layers() -> SvgOptions {
    SvgOptions {
        delaunay: true,
        voronoi: true,
        labels: true,
        ..SvgOptions::default()
    }
}

fn circle(n: usize, r: f64, centre: [f64; 2]) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = (k * 7 % n) as f64 * std::f64::consts::TAU / n as f64;
            [centre[0] + r * t.cos(), centre[1] + r * t.sin()]
        })
        .collect()
}

/// An ellipse (2 : 1) with a bump, its coordinates on the grid of 2⁻²⁰, so that scaling by a
/// power of two and adding a multiple of 2⁻²⁰ below 2³² are exact.
fn dyadic_shape() -> Vec<[f64; 2]> {
    let grid = (1u64 << 20) as f64;
    (0..40)
        .map(|k| {
            let t = (k * 13 % 40) as f64 * std::f64::consts::TAU / 40.0;
            let r = 1.0 + 0.2 * (3.0 * t).cos();
            [
                (2.0 * r * t.cos() * grid).round() / grid,
                (r * t.sin() * grid).round() / grid,
            ]
        })
        .collect()
}

/// Every `<name` has its `</name>` or ends in `/>`, properly nested.
fn assert_balanced(svg: &str) {
    let mut stack: Vec<&str> = Vec::new();
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        let close = rest[open..].find('>').expect("unterminated tag") + open;
        let tag = &rest[open + 1..close];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop(), Some(name), "mismatched </{name}>");
        } else if !tag.ends_with('/') {
            stack.push(tag.split_whitespace().next().unwrap());
        }
        rest = &rest[close + 1..];
    }
    assert!(stack.is_empty(), "unclosed {stack:?}");
}

/// The value of attribute `name` in every tag that has it.
fn attributes<'a>(svg: &'a str, name: &str) -> Vec<&'a str> {
    let key = format!(" {name}=\"");
    svg.match_indices(&key)
        .map(|(i, _)| {
            let start = i + key.len();
            &svg[start..start + svg[start..].find('"').unwrap()]
        })
        .collect()
}

/// The numbers of a path's `d` (`M x y L x y ... Z`; the legend's `h20` included).
fn path_numbers(d: &str) -> Vec<f64> {
    d.split(|c: char| c.is_ascii_alphabetic() || c == ' ')
        .filter(|t| !t.is_empty())
        .map(|t| t.parse().unwrap_or_else(|_| panic!("{t:?} in {d:?}")))
        .collect()
}

/// The picture's size from its viewBox, which must start at the origin and agree with the
/// width and height attributes.
fn canvas_size(svg: &str) -> [f64; 2] {
    let view: Vec<f64> = attributes(svg, "viewBox")[0]
        .split(' ')
        .map(|t| t.parse().unwrap())
        .collect();
    assert_eq!(view[..2], [0.0, 0.0]);
    let width: f64 = attributes(svg, "width")[0].parse().unwrap();
    let height: f64 = attributes(svg, "height")[0].parse().unwrap();
    assert_eq!([width, height], [view[2], view[3]]);
    [view[2], view[3]]
}

/// The centres of the circles in the group `id`.
fn circles(svg: &str, id: &str) -> Vec<[f64; 2]> {
    let Some(start) = svg.find(&format!("<g id=\"{id}\"")) else {
        return Vec::new();
    };
    let group = &svg[start..start + svg[start..].find("</g>").unwrap()];
    attributes(group, "cx")
        .iter()
        .zip(attributes(group, "cy"))
        .map(|(x, y)| [x.parse().unwrap(), y.parse().unwrap()])
        .collect()
}

/// What makes a picture render in any viewer: every coordinate finite and inside the canvas,
/// every stroke width and radius positive and of a sane size in pixels, a canvas of a sane
/// size, and the points' dots an undistorted image of the points (one scale on both axes:
/// the dots' bounding box has the data's aspect).
fn assert_renderable(svg: &str, points: &[[f64; 2]], y_down: bool) {
    assert_balanced(svg);
    assert!(!svg.contains("NaN") && !svg.contains("inf"));
    let [width, height] = canvas_size(svg);
    assert!((400.0..2000.0).contains(&width), "width {width}");
    assert!((60.0..2000.0).contains(&height), "height {height}");
    let inside = |x: f64, y: f64| (0.0..=width).contains(&x) && (0.0..=height).contains(&y);
    for d in attributes(svg, "d") {
        let numbers = path_numbers(d);
        if d.contains('h') {
            continue; // a legend swatch: "M x y h20"
        }
        assert!(numbers.len() % 2 == 0, "{d}");
        for xy in numbers.chunks(2) {
            assert!(inside(xy[0], xy[1]), "{xy:?} outside {width} x {height}");
        }
    }
    for (x, y) in attributes(svg, "cx").iter().zip(attributes(svg, "cy")) {
        let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
        assert!(inside(x, y), "circle at {x} {y} outside {width} x {height}");
    }
    for size in attributes(svg, "r")
        .into_iter()
        .chain(attributes(svg, "stroke-width"))
    {
        let size: f64 = size.parse().unwrap();
        assert!((0.2..=10.0).contains(&size), "size {size} px");
    }
    // The dots of the distinct points, unassigned or not, against the points themselves.
    let mut dots = circles(svg, "points");
    dots.extend(circles(svg, "unassigned-points"));
    let (min, max) = bounding_box(points);
    let (dmin, dmax) = bounding_box(&dots);
    let data = [max[0] - min[0], max[1] - min[1]];
    let drawn = [dmax[0] - dmin[0], dmax[1] - dmin[1]];
    let longer = data[0].max(data[1]);
    if longer > 0.0 && !points.is_empty() {
        assert!(
            (drawn[0].max(drawn[1]) - DATA_PX).abs() <= 0.02,
            "{drawn:?}"
        );
        for k in 0..2 {
            let expected = data[k] / longer * DATA_PX;
            assert!((drawn[k] - expected).abs() <= 0.02, "{drawn:?} vs {data:?}");
        }
        // Orientation: the point with the largest y is at the top unless y is down.
        let top = points.iter().max_by(|a, b| a[1].total_cmp(&b[1])).unwrap();
        let x_px = dmin[0] + (top[0] - min[0]) / longer * DATA_PX;
        let y_px = if y_down { dmax[1] } else { dmin[1] };
        assert!(
            dots.iter()
                .any(|d| (d[0] - x_px).abs() <= 0.02 && (d[1] - y_px).abs() <= 0.02),
            "no dot at the expected place of {top:?}"
        );
    }
}

/// The pictures of `points` with every layer, y up and y down, each checked by
/// [`assert_renderable`].
fn renderable_both_ways(points: &[[f64; 2]]) -> [String; 2] {
    [false, true].map(|y_down| {
        let options = SvgOptions {
            y_down,
            ..all_layers()
        };
        let svg = svg_of(points, &options);
        assert_renderable(&svg, points, y_down);
        svg
    })
}

/// The numbers of a line in order, and the line with every number replaced by `#`.
fn numbers_and_skeleton(line: &str) -> (Vec<f64>, String) {
    let mut numbers = Vec::new();
    let mut skeleton = String::with_capacity(line.len());
    let mut chars = line.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        let sign = c == '-' && chars.peek().is_some_and(|(_, d)| d.is_ascii_digit());
        if !(c.is_ascii_digit() || sign) {
            skeleton.push(c);
            continue;
        }
        let mut end = i + c.len_utf8();
        while let Some(&(j, d)) = chars.peek() {
            if d.is_ascii_digit() || d == '.' {
                end = j + 1;
                chars.next();
            } else {
                break;
            }
        }
        numbers.push(line[i..end].parse().unwrap());
        skeleton.push('#');
    }
    (numbers, skeleton)
}

/// The elements of a picture as (group, skeleton, numbers), in a canonical order: the order
/// in which edges are drawn, and which end a segment starts from, follow the triangulation's
/// internal order, which depends on where the data lies.
fn canonical_elements(svg: &str) -> Vec<(String, String, Vec<f64>)> {
    let mut group = String::new();
    let mut elements: Vec<(String, String, Vec<f64>)> = svg
        .lines()
        .map(|line| {
            if let Some(rest) = line.strip_prefix("<g id=\"") {
                group = rest[..rest.find('"').unwrap()].to_string();
            }
            let (mut numbers, skeleton) = numbers_and_skeleton(line);
            if skeleton.ends_with("Z\"/>") && numbers.len() >= 6 {
                // A loop, from its first point towards the lexicographically smaller
                // neighbour. (Its direction is the curve module's business: the orientation
                // test there sums the shoelace formula in floating point, which cancels for
                // data far from the origin, so the loop's direction can flip with an offset.)
                let mut ring: Vec<[f64; 2]> = numbers.chunks(2).map(|c| [c[0], c[1]]).collect();
                let n = ring.len();
                if ring[n - 1] < ring[1] {
                    ring[1..].reverse();
                }
                numbers = ring.concat();
            }
            if skeleton.contains("d=\"M# #L# #\"") {
                // A segment: from its lexicographically smaller end.
                let n = numbers.len();
                let ends = &mut numbers[n - 4..];
                if (ends[2], ends[3]) < (ends[0], ends[1]) {
                    ends.swap(0, 2);
                    ends.swap(1, 3);
                }
            }
            (group.clone(), skeleton, numbers)
        })
        .collect();
    // Sorted on numbers rounded to 0.1 px, so that sub-pixel noise cannot reorder them.
    let key = |(g, s, n): &(String, String, Vec<f64>)| {
        let rounded: Vec<i64> = n.iter().map(|v| (v * 10.0).round() as i64).collect();
        (g.clone(), s.clone(), rounded)
    };
    elements.sort_by_cached_key(key);
    elements
}

#[test]
fn every_layer_is_drawn_and_the_document_is_balanced() {
    let options = SvgOptions {
        title: Some("a <circle> & more".to_string()),
        ..all_layers()
    };
    let points = circle(24, 3.0, [10.0, -4.0]);
    let svg = svg_of(&points, &options);
    assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\" "));
    assert_renderable(&svg, &points, false);
    for id in [
        "delaunay",
        "voronoi",
        "outer-vertices",
        "inner-vertices",
        "medial-axis",
        "closed-curves",
        "points",
        "legend",
    ] {
        assert!(svg.contains(&format!("<g id=\"{id}\"")), "{id} missing");
    }
    assert!(svg.contains("<title>a &lt;circle&gt; &amp; more</title>"));
    assert!(svg.contains("1 closed curve"));
    assert!(!svg.contains("unassigned"));
}

#[test]
fn every_extent_and_offset_renders() {
    let cases: &[(&str, f64, [f64; 2])] = &[
        ("1e-6 wide", 1e-6, [0.0, 0.0]),
        ("1 wide", 1.0, [0.0, 0.0]),
        ("1e9 wide", 1e9, [0.0, 0.0]),
        ("1 wide at 1e9", 1.0, [1e9, -1e9]),
        ("1e-6 wide at 1e6", 1e-6, [1e6, 1e6]),
        ("1e-6 wide at 1e9 (8 f64 values per axis)", 1e-6, [1e9, 1e9]),
        ("1e-30 wide", 1e-30, [0.0, 0.0]),
        ("1e50 wide", 1e50, [-3e50, 0.0]),
    ];
    for &(name, extent, offset) in cases {
        let points: Vec<[f64; 2]> = dyadic_shape()
            .iter()
            .map(|p| [offset[0] + extent * p[0], offset[1] + extent * p[1]])
            .collect();
        for svg in renderable_both_ways(&points) {
            if !name.contains("f64 values") {
                assert!(svg.contains("<g id=\"closed-curves\""), "{name}");
            }
        }
    }
}

#[test]
fn the_picture_does_not_depend_on_scale_or_offset() {
    let shape = dyadic_shape();
    let reference = canonical_elements(&svg_of(&shape, &all_layers()));
    // Powers of two scale exactly, and the offsets keep every coordinate on its grid: the
    // same points up to an exact similarity, so the same picture.
    for (scale, offset) in [
        (2f64.powi(-20), [0.0, 0.0]),
        (2f64.powi(30), [0.0, 0.0]),
        (1.0, [2f64.powi(30), -(2f64.powi(31))]),
        (2f64.powi(-20), [1024.0, 4096.0]),
    ] {
        let points: Vec<[f64; 2]> = shape
            .iter()
            .map(|p| [offset[0] + scale * p[0], offset[1] + scale * p[1]])
            .collect();
        let elements = canonical_elements(&svg_of(&points, &all_layers()));
        assert_eq!(elements.len(), reference.len());
        for (a, b) in elements.iter().zip(&reference) {
            assert_eq!(
                (&a.0, &a.1),
                (&b.0, &b.1),
                "scale {scale}, offset {offset:?}"
            );
            for (x, y) in a.2.iter().zip(&b.2) {
                // Circumcenters are rounded to f64 in the data's units: far from the origin
                // that moves them by up to half a unit in the last place, far below a pixel.
                assert!(
                    (x - y).abs() <= 0.011,
                    "{a:?} vs {b:?} (scale {scale}, offset {offset:?})"
                );
            }
        }
    }
}

#[test]
fn y_down_draws_the_mirror_image() {
    let points = dyadic_shape();
    let mirrored: Vec<[f64; 2]> = points.iter().map(|p| [p[0], -p[1]]).collect();
    let down = svg_with(
        &crate::reconstruct(&points).unwrap(),
        &SvgOptions {
            y_down: true,
            ..SvgOptions::default()
        },
    );
    let up = svg_of(&mirrored, &SvgOptions::default());
    assert_eq!(circles(&down, "points"), circles(&up, "points"));
    assert_eq!(canvas_size(&down), canvas_size(&up));
    // And it is not the same picture as y up.
    let plain = svg_of(&points, &SvgOptions::default());
    assert_ne!(circles(&down, "points"), circles(&plain, "points"));
}

#[test]
fn unassigned_points_are_drawn_apart_with_a_legend_entry() {
    // A circle and a point at its centre, on no curve.
    let mut points = circle(24, 1.0, [0.0, 0.0]);
    points.push([0.0, 0.0]);
    let rec = crate::reconstruct(&points).unwrap();
    assert!(
        rec.unassigned().contains(&24),
        "the centre is on no curve: {:?}",
        rec.unassigned()
    );
    let svg = svg_with(&rec, &SvgOptions::default());
    assert_renderable(&svg, &points, false);
    let rings = circles(&svg, "unassigned-points");
    assert_eq!(rings.len(), rec.unassigned().len());
    assert_eq!(
        circles(&svg, "points").len() + rings.len(),
        points.len(),
        "every point is drawn once"
    );
    assert!(svg.contains(&format!(">{} unassigned</text>", rec.unassigned().len())));
}

#[test]
fn degenerate_inputs_draw_something_sane() {
    for points in [
        vec![],
        vec![[5.0, 5.0]],
        vec![[1.0, 1.0], [1.0, 1.0]],
        vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]],
        vec![[1e9, 0.0], [1e9, 1e-6], [1e9, 2e-6]],
    ] {
        renderable_both_ways(&points);
    }
}

/// The distance in pixels from `q` to the line through `a` and `b`.
fn distance_to_line(q: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    ((q[0] - a[0]) * d[1] - (q[1] - a[1]) * d[0]).abs() / d[0].hypot(d[1])
}

#[test]
fn clipping_is_exact_for_far_ends() {
    let canvas = Canvas::new(&[[0.0, 0.0], [1.0, 1.0]], false);
    let on_edge = |q: [f64; 2]| {
        let near = |v: f64, edge: f64| (v - edge).abs() < 1e-9;
        near(q[0], 0.0)
            || near(q[0], canvas.width_px)
            || near(q[1], 0.0)
            || near(q[1], canvas.data_height_px)
    };
    // The diagonal y = x between two points 2^600 away: in floating point the clipped ends
    // would be off by about 2^548 pixels.
    let far = 2f64.powi(600);
    let [p, q] = canvas.segment([-far, -far], [far, far]).unwrap();
    let (a, b) = (canvas.to_px([0.0, 0.0]), canvas.to_px([1.0, 1.0]));
    for end in [p, q] {
        assert!(distance_to_line(end, a, b) < 1e-9, "{end:?}");
        assert!(on_edge(end) && canvas.holds_px(end), "{end:?}");
    }
    // From a point inside to one 2^600 away on the diagonal (the floating-point path).
    let [p, q] = canvas.segment([0.25, 0.25], [far, far]).unwrap();
    assert_eq!(p, canvas.to_px([0.25, 0.25]));
    assert!(distance_to_line(q, a, b) < 1e-9 && on_edge(q), "{q:?}");
    let [p, q] = canvas.segment([far, far], [0.25, 0.25]).unwrap();
    assert_eq!(q, canvas.to_px([0.25, 0.25]));
    assert!(distance_to_line(p, a, b) < 1e-9 && on_edge(p), "{p:?}");
    // Far outside on one side, and crossing the drawing from outside to outside.
    assert!(canvas.segment([-far, -far], [-far, far]).is_none());
    assert!(canvas.segment([2.0, -1.0], [2.0, 3.0]).is_none());
    let [p, q] = canvas.segment([-1.0, 0.5], [2.0, 0.5]).unwrap();
    assert_eq!([p[0], q[0]], [0.0, canvas.width_px]);
    // A ray from far away towards the drawing, and one pointing away from it.
    let [p, q] = canvas.ray([-far, 0.5], [1.0, 0.0]).unwrap();
    assert_eq!([p[1], q[1]], [canvas.to_px([0.0, 0.5])[1]; 2]);
    assert_eq!([p[0], q[0]], [0.0, canvas.width_px]);
    assert!(canvas.ray([-far, 0.5], [-1.0, 0.0]).is_none());
    assert!(canvas.ray([0.5, 0.5], [0.0, 0.0]).is_none());
    // A segment inside is drawn as it is; one outside is not drawn.
    assert_eq!(
        canvas.segment([0.25, 0.25], [0.75, 0.5]),
        Some([canvas.to_px([0.25, 0.25]), canvas.to_px([0.75, 0.5])])
    );
    assert!(canvas.segment([2.0, 2.0], [3.0, 2.0]).is_none());
    assert!(canvas.segment([f64::INFINITY, 0.5], [0.5, 0.5]).is_none());
    // The bisector of two far-from-origin points that f64 cannot average exactly.
    let canvas = Canvas::new(&[[1e9, 0.0], [1e9 + 1.0, 1.0]], true);
    let (u, v) = ([1e9, 0.0], [1e9 + 2f64.powi(-23) * 3.0, 0.0]);
    let [p, q] = canvas.bisector(u, v).unwrap();
    let mid_px = canvas.to_px(u)[0] + 1.5 * 2f64.powi(-23) / (1.0 / DATA_PX);
    assert!((p[0] - mid_px).abs() < 1e-6 && (q[0] - mid_px).abs() < 1e-6);
}

#[test]
fn numbers_are_pixels_to_the_hundredth_without_negative_zero() {
    let mut out = Vec::new();
    let mut w = SvgWriter {
        out: &mut out,
        buf: String::new(),
    };
    w.nums(&[1.0, -0.001, 2.346, -3.5]);
    assert_eq!(w.buf, "1.00 0.00 2.35 -3.50");
}
