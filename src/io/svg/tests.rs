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

/// What `f` writes through an [`SvgWriter`].
fn written(f: impl FnOnce(&mut SvgWriter<'_, Vec<u8>>) -> io::Result<()>) -> String {
    let mut out = Vec::new();
    let mut w = SvgWriter {
        out: &mut out,
        buf: String::new(),
    };
    f(&mut w).unwrap();
    w.flush().unwrap();
    String::from_utf8(out).unwrap()
}

/// Well-formed XML as this writer makes it: one root element; every tag a name and
/// `name="value"` attributes, closed by `/>` or by its end tag, properly nested; no `<` in a
/// value, no `&` but the four entities it writes, nothing but white space outside the root.
fn assert_well_formed(svg: &str) {
    let entities_ok = |text: &str| {
        text.match_indices('&').all(|(i, _)| {
            ["&amp;", "&lt;", "&gt;", "&quot;"]
                .iter()
                .any(|e| text[i..].starts_with(e))
        })
    };
    let name_ok = |name: &str| {
        !name.is_empty()
            && name
                .bytes()
                .all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b':')
    };
    let mut stack: Vec<&str> = Vec::new();
    let mut roots = 0;
    let mut rest = svg;
    while let Some(open) = rest.find('<') {
        let text = &rest[..open];
        assert!(entities_ok(text) && !text.contains('>'), "text {text:?}");
        assert!(
            !stack.is_empty() || text.trim().is_empty(),
            "text outside the root"
        );
        let close = rest[open..].find('>').expect("unterminated tag") + open;
        let tag = &rest[open + 1..close];
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop(), Some(name), "mismatched </{name}>");
        } else {
            let empty = tag.ends_with('/');
            let body = tag.trim_end_matches('/');
            let name_end = body.find(' ').unwrap_or(body.len());
            let name = &body[..name_end];
            assert!(name_ok(name), "tag name {name:?}");
            let mut attributes = &body[name_end..];
            while !attributes.is_empty() {
                let a = attributes
                    .strip_prefix(' ')
                    .expect("a space before an attribute");
                let eq = a.find("=\"").expect("name=\"value\"");
                assert!(name_ok(&a[..eq]), "attribute name {:?}", &a[..eq]);
                let value_end = a[eq + 2..].find('"').expect("an unterminated value") + eq + 2;
                let value = &a[eq + 2..value_end];
                assert!(
                    !value.contains('<') && entities_ok(value),
                    "value {value:?}"
                );
                attributes = &a[value_end + 1..];
            }
            if stack.is_empty() {
                roots += 1;
            }
            if !empty {
                stack.push(name);
            }
        }
        rest = &rest[close + 1..];
    }
    assert!(stack.is_empty(), "unclosed {stack:?}");
    assert!(rest.trim().is_empty(), "text after the root");
    assert_eq!(roots, 1, "one root element");
}

/// The `d` attributes of the paths in the group `id`.
fn group_paths<'a>(svg: &'a str, id: &str) -> Vec<&'a str> {
    let Some(start) = svg.find(&format!("<g id=\"{id}\"")) else {
        return Vec::new();
    };
    attributes(&svg[start..start + svg[start..].find("</g>").unwrap()], "d")
}

/// The vertices of a path's data `M x y L x y ... [Z]`, as written, and whether it ends in `Z`.
fn path_vertices(d: &str) -> (Vec<&str>, bool) {
    let closed = d.ends_with('Z');
    let d = d.strip_prefix('M').unwrap().trim_end_matches('Z');
    (d.split('L').collect(), closed)
}

/// `n` samples of a star-shaped closed curve in scrambled order, jittered along it by half
/// their spacing and across it by a tenth.
fn noisy_star(n: usize) -> Vec<[f64; 2]> {
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut uniform = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let spacing = std::f64::consts::TAU / n as f64;
    let mut points: Vec<[f64; 2]> = (0..n)
        .map(|i| {
            let t = (i as f64 + 0.5 * uniform()) * spacing;
            let r = 1.0 + 0.3 * (5.0 * t).cos() + 0.1 * spacing * (uniform() - 0.5);
            [r * t.cos(), 0.7 * r * t.sin()]
        })
        .collect();
    for i in (1..n).rev() {
        points.swap(i, (uniform() * (i + 1) as f64) as usize);
    }
    points
}

/// `n` points of the star `r = 1 + 0.2 cos 3t`, in the order `k · 11 mod n` (`n` not a
/// multiple of 11).
fn star(n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = (k * 11 % n) as f64 * std::f64::consts::TAU / n as f64;
            let r = 1.0 + 0.2 * (3.0 * t).cos();
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

#[test]
fn a_vertex_on_the_pixel_of_the_one_before_is_left_out_but_the_ends_stay() {
    // Positions written as 0.00 0.00 (twice more, -0.00 included), 5.00 5.00 (three times).
    let run = [
        [0.0, 0.0],
        [0.001, -0.004],
        [-0.004, 0.002],
        [5.0, 5.0],
        [5.001, 4.996],
        [5.002, 5.004],
    ];
    let open = written(|w| w.polyline(run.into_iter(), false));
    assert_eq!(open, "<path d=\"M0.00 0.00L5.00 5.00L5.00 5.00\"/>\n");
    let closed = written(|w| w.polyline(run.into_iter(), true));
    assert_eq!(closed, "<path d=\"M0.00 0.00L5.00 5.00L5.00 5.00Z\"/>\n");
    // A curve on one pixel keeps its two ends (a dot of the stroke's width), closed or not.
    let one_pixel = [[1.0, 1.0], [1.004, 1.0], [0.996, 1.002], [1.0, 0.999]];
    let dot = written(|w| w.polyline(one_pixel.into_iter(), true));
    assert_eq!(dot, "<path d=\"M1.00 1.00L1.00 1.00Z\"/>\n");
    // Only a repeat of the vertex just before is dropped: going back to a pixel is a line.
    let back = written(|w| w.polyline([[0.0, 0.0], [1.0, 0.0], [0.0, 0.0]].into_iter(), false));
    assert_eq!(back, "<path d=\"M0.00 0.00L1.00 0.00L0.00 0.00\"/>\n");
    assert_eq!(written(|w| w.polyline([].into_iter(), true)), "");
}

#[test]
fn a_long_curve_is_split_into_paths_that_continue_one_another() {
    // 20,000 distinct vertices, about 14 bytes each: some five pieces.
    let vertices: Vec<[f64; 2]> = (0..20_000)
        .map(|i| [0.01 * i as f64, 100.0 + (i % 7) as f64])
        .collect();
    for closed in [false, true] {
        let text = written(|w| w.polyline(vertices.iter().copied(), closed));
        let d = attributes(&text, "d");
        assert!(d.len() >= 4, "{} pieces", d.len());
        assert_eq!(text.lines().count(), d.len(), "one path per line");
        let mut all: Vec<&str> = Vec::new();
        for (k, piece) in d.iter().enumerate() {
            assert!(piece.len() <= MAX_PATH_DATA, "{} bytes", piece.len());
            let (v, z) = path_vertices(piece);
            assert!(!z, "a split curve closes with a line to its start");
            if k > 0 {
                assert_eq!(v[0], *all.last().unwrap(), "piece {k} starts elsewhere");
                all.extend(&v[1..]);
            } else {
                all.extend(&v);
            }
        }
        let mut expected: Vec<String> = vertices
            .iter()
            .map(|&p| {
                let mut s = String::new();
                push_position(&mut s, p);
                s
            })
            .collect();
        if closed {
            expected.push(expected[0].clone());
        }
        assert_eq!(all, expected);
    }
    // A curve that fits is one path, closed by `Z`.
    let short = written(|w| w.polyline(vertices[..100].iter().copied(), true));
    assert_eq!(attributes(&short, "d").len(), 1);
    assert!(short.ends_with("Z\"/>\n"));
}

#[test]
fn a_dot_on_a_dot_already_drawn_is_left_out() {
    let positions = [
        [1.0, 1.0],
        [1.006, 1.0],
        [1.004, 0.999],
        [-0.001, 2.0],
        [1.01, 1.0],
        [0.0, 2.0],
    ];
    let text = written(|w| w.dots(positions.into_iter(), 2.0));
    assert_eq!(
        text,
        "<circle cx=\"1.00\" cy=\"1.00\" r=\"2.00\"/>\n\
         <circle cx=\"1.01\" cy=\"1.00\" r=\"2.00\"/>\n\
         <circle cx=\"0.00\" cy=\"2.00\" r=\"2.00\"/>\n"
    );
    assert_eq!(hundredths("-12.34"), Some(-1234));
    assert_eq!(hundredths("0.05"), Some(5));
    assert_eq!(hundredths(&format!("{:.2}", 1e300)), None);
}

#[test]
fn a_large_picture_is_split_deduplicated_and_well_formed() {
    let points = noisy_star(200_000);
    let rec = crate::reconstruct(&points).unwrap();
    assert_eq!(rec.curves().len(), 1, "one curve");
    assert!(rec.curves()[0].closed);
    let svg = svg_with(&rec, &SvgOptions::default());
    assert_well_formed(&svg);
    // No data longer than the bound, no line longer than a path element around it.
    for d in attributes(&svg, "d") {
        assert!(d.len() <= MAX_PATH_DATA, "a d of {} bytes", d.len());
    }
    let longest = svg.lines().map(str::len).max().unwrap();
    assert!(longest <= MAX_PATH_DATA + 12, "a line of {longest} bytes");
    // The curve's pieces, joined, are its points' written positions with every repeat of
    // the position before left out, and a line back to the start.
    let pieces = group_paths(&svg, "closed-curves");
    assert!(pieces.len() > 10, "{} pieces", pieces.len());
    let mut drawn: Vec<&str> = Vec::new();
    for piece in &pieces {
        let (v, z) = path_vertices(piece);
        assert!(!z);
        if let Some(&last) = drawn.last() {
            assert_eq!(v[0], last, "a piece starts where the one before ends");
            drawn.extend(&v[1..]);
        } else {
            drawn.extend(&v);
        }
    }
    let canvas = Canvas::new(&points, false);
    let curve = &rec.curves()[0].points;
    let mut expected: Vec<String> = Vec::new();
    for (k, &i) in curve.iter().enumerate() {
        let mut s = String::new();
        push_position(&mut s, canvas.to_px(points[i as usize]));
        if k + 1 == curve.len() || expected.last() != Some(&s) {
            expected.push(s);
        }
    }
    expected.push(expected[0].clone());
    assert_eq!(drawn, expected);
    assert!(
        drawn.len() < curve.len(),
        "{} vertices of {} points: none on a pixel already drawn",
        drawn.len(),
        curve.len()
    );
    // Far too dense for dots: the legend says so, and the file is small.
    assert!(!svg.contains("<g id=\"points\""));
    assert!(svg.contains(">200000 points (too dense for dots)</text>"));
    assert!(svg.len() < 4 << 20, "{} bytes", svg.len());
}

#[test]
fn no_points_leaves_out_the_dots_and_the_rings() {
    let mut points = circle(24, 1.0, [0.0, 0.0]);
    points.push([0.0, 0.0]);
    let rec = crate::reconstruct(&points).unwrap();
    assert_eq!(rec.unassigned(), [24]);
    let options = SvgOptions {
        points: false,
        ..SvgOptions::default()
    };
    let svg = svg_with(&rec, &options);
    assert_well_formed(&svg);
    assert!(!svg.contains("<circle"), "a dot or a ring drawn");
    assert!(!svg.contains("<g id=\"points\"") && !svg.contains("<g id=\"unassigned-points\""));
    assert!(svg.contains("<g id=\"closed-curves\""));
    assert!(svg.contains(">25 points (not drawn)</text>"));
    assert!(svg.contains(">1 unassigned (not drawn)</text>"));
    // The same picture but for the points.
    let with_points = svg_with(&rec, &SvgOptions::default());
    assert_eq!(
        group_paths(&svg, "closed-curves"),
        group_paths(&with_points, "closed-curves")
    );
    assert_eq!(circles(&with_points, "unassigned-points").len(), 1);
}

#[test]
fn dots_shrink_with_density_and_give_way_to_dense_curves() {
    let mut previous = f64::INFINITY;
    // Samples some 190, 23, 5.7 and 3.2 px apart.
    for n in [12, 100, 400, 701] {
        let points = star(n);
        let svg = svg_of(&points, &SvgOptions::default());
        assert_renderable(&svg, &points, false);
        let start = svg.find("<g id=\"points\"").expect("dots");
        let group = &svg[start..start + svg[start..].find("</g>").unwrap()];
        let radii: Vec<f64> = attributes(group, "r")
            .iter()
            .map(|r| r.parse().unwrap())
            .collect();
        assert_eq!(radii.len(), n);
        let r = radii[0];
        assert!(radii.iter().all(|&q| q == r));
        assert!(r <= previous, "{n} points: radius {r} after {previous}");
        previous = r;
        // The dots leave most of the curve between them in sight.
        let (ring, _) = path_vertices(group_paths(&svg, "closed-curves")[0]);
        let ring: Vec<[f64; 2]> = ring
            .iter()
            .map(|v| {
                let (x, y) = v.split_once(' ').unwrap();
                [x.parse().unwrap(), y.parse().unwrap()]
            })
            .collect();
        let mut gaps: Vec<f64> = ring
            .windows(2)
            .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
            .collect();
        gaps.sort_by(f64::total_cmp);
        let spacing = gaps[gaps.len() / 2];
        assert!(
            2.0 * r <= 0.6 * spacing + 0.02,
            "{n}: radius {r}, spacing {spacing}"
        );
    }
    assert!(previous < 0.9, "the densest dots are {previous} px");
    // Samples 0.75 px apart: no dots, a note, and the unassigned centre as a hollow ring.
    let mut points = star(3001);
    points.push([0.0, 0.0]);
    let rec = crate::reconstruct(&points).unwrap();
    assert!(rec.unassigned().contains(&3001), "{:?}", rec.unassigned());
    let svg = svg_with(&rec, &SvgOptions::default());
    assert_balanced(&svg);
    assert!(!svg.contains("<g id=\"points\""));
    assert!(svg.contains(">3002 points (too dense for dots)</text>"));
    assert!(svg.contains("<g id=\"closed-curves\""));
    assert!(svg.contains("<g id=\"unassigned-points\" fill=\"none\""));
    assert_eq!(
        circles(&svg, "unassigned-points").len(),
        rec.unassigned().len()
    );
}

/// Points a few ulps of the smallest subnormal apart: the extent over the picture's size
/// rounds to zero, and the smallest positive double is the unit instead (the exact clipping
/// divided by a zero unit).
#[test]
fn a_subnormal_extent_renders() {
    let tiny = f64::from_bits(1);
    let mut points = Vec::new();
    for i in -22i32..=22 {
        for j in -22i32..=22 {
            if (i, j) != (0, 0) && (i % 22 == 0 || j % 22 == 0) {
                points.push([f64::from(i) * tiny, f64::from(j) * tiny]);
            }
        }
    }
    let svg = svg_of(&points, &all_layers());
    assert!(svg.starts_with("<svg ") && svg.trim_end().ends_with("</svg>"));
    // One pixel per smallest double: the 44-ulp square is drawn 44 pixels wide.
    let dots = circles(&svg, "points");
    let (lo, hi) = bounding_box(&dots);
    assert_eq!([hi[0] - lo[0], hi[1] - lo[1]], [44.0, 44.0]);
}
