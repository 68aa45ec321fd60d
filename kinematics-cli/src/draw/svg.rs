//! Three orthographic views of a [`Scene`] as SVG, written by hand.
//!
//! Every view shares one scale (pixels per metre). A view maps the root-frame point `p` to the
//! screen point `(ox + scale * p[u], oy - scale * p[v])` (SVG's y grows downwards), and its group
//! carries `data-u`, `data-v`, `data-ox`, `data-oy`; the root element carries `data-scale`. Every
//! link origin, segment and axis carries its 3D data (`data-x`, `data-y`, `data-z`, and an axis's
//! unit direction `data-dx`, `data-dy`, `data-dz`) in Rust's shortest round-trip form, so a reader
//! gets the runtime's numbers back exactly; screen coordinates have three decimals. The collision
//! geometry (class `geometry`, with `data-link`, `data-element`, `data-shape`) carries screen
//! coordinates only: a primitive's outline as a polygon (three decimals), a mesh's region as the
//! outline of whole grid cells (corners at multiples of `data-cell` pixels, written exactly, edges
//! as `H` and `V`). The output depends on the scene alone (no hash map, no clock).
//!
//! The tests read the picture back through these attributes.

use std::fmt::Write as _;

use super::geometry::{Form, Solid};
use super::silhouette::{self, CELL};
use super::{AxisStyle, ObstacleShape, Scene};

/// Side of a view's square panel, in pixels.
const PANEL: f64 = 360.0;
/// Space between the robot's bounding box and the panel's edge, in pixels.
const MARGIN: f64 = 28.0;
/// Height of the band at the top of a panel that holds the view's name (nothing is drawn there).
const LABEL_BAND: f64 = 24.0;
/// Space between panels and around them.
const GAP: f64 = 16.0;
/// Height of the title band above the panels.
const HEADER: f64 = 40.0;
/// Height of the band below the panels (scale bar, legend).
const FOOTER: f64 = 44.0;
/// Length of a joint axis drawn in full (seen side-on), in pixels.
const AXIS_PX: f64 = 26.0;
/// Above this many links, names are left to the tooltips: labels would cover the drawing.
const LABEL_LIMIT: usize = 40;
/// Labels longer than this many characters are shortened (the tooltip keeps the whole name).
const LABEL_CHARS: usize = 32;
/// Characters in a line of the legend's text (the rest of the footer's width at 11 px).
const LEGEND_CHARS: usize = 96;
/// Space between the legend's lines, in pixels.
const LEGEND_LEADING: f64 = 12.0;
/// Joint values shown in the title (all of them are in the root's `data-q`).
const TITLE_VALUES: usize = 12;

/// One orthographic view: which root-frame coordinates become the screen's right and up.
struct View {
    name: &'static str,
    u: usize,
    v: usize,
}

/// Front (looking along +y: x right, z up), side (looking along -x: y right, z up), top (looking
/// down -z: x right, y up).
const VIEWS: [View; 3] =
    [View { name: "front", u: 0, v: 2 }, View { name: "side", u: 1, v: 2 }, View { name: "top", u: 0, v: 1 }];

const AXIS_NAMES: [&str; 3] = ["x", "y", "z"];

/// Text for XML content and attribute values: `&`, `<`, `>`, `"`, `'` escaped.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            // Control characters other than tab and newline are not allowed in XML 1.0 at all.
            c if c.is_control() && c != '\t' && c != '\n' => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
    out
}

/// A label: the name, shortened to [`LABEL_CHARS`] characters with an ellipsis.
fn label(name: &str) -> String {
    if name.chars().count() <= LABEL_CHARS {
        escape(name)
    } else {
        escape(&format!("{}…", name.chars().take(LABEL_CHARS - 1).collect::<String>()))
    }
}

/// A screen coordinate: fixed three decimals, `-0.000` written `0.000`.
fn px(x: f64) -> String {
    let s = format!("{x:.3}");
    if s == "-0.000" { "0.000".to_owned() } else { s }
}

/// The 3D data attributes of a point.
fn point_data(p: [f64; 3]) -> String {
    format!("data-x=\"{}\" data-y=\"{}\" data-z=\"{}\"", p[0], p[1], p[2])
}

/// Where a view puts root-frame points on the screen.
struct Placed<'a> {
    view: &'a View,
    scale: f64,
    ox: f64,
    oy: f64,
}

impl Placed<'_> {
    fn screen(&self, p: [f64; 3]) -> (f64, f64) {
        (self.ox + self.scale * p[self.view.u], self.oy - self.scale * p[self.view.v])
    }
}

/// The bounding box of everything drawn: per coordinate, smallest and largest.
fn bounds(scene: &Scene) -> [(f64, f64); 3] {
    let mut bounds = [(f64::INFINITY, f64::NEG_INFINITY); 3];
    for (p, r) in scene.extent() {
        for (b, x) in bounds.iter_mut().zip(p) {
            *b = (b.0.min(x - r), b.1.max(x + r));
        }
    }
    bounds
}

/// The scale bar's length: the largest 1, 2 or 5 times a power of ten within a quarter of
/// `extent`, and the decimals that print it exactly.
fn bar_length(extent: f64) -> (f64, usize) {
    let quarter = extent / 4.0;
    let exponent = quarter.log10().floor() as i32;
    let power = 10f64.powi(exponent);
    let mantissa = [5.0, 2.0, 1.0].into_iter().find(|m| m * power <= quarter).unwrap_or(1.0);
    (mantissa * power, usize::try_from(-exponent).unwrap_or(0))
}

/// The SVG document.
pub fn render(scene: &Scene) -> String {
    let bounds = bounds(scene);
    // The extent is the largest side of the box; a robot whose every origin coincides (a lone
    // link, or links stacked at one point) is drawn at one metre per panel.
    let largest = bounds.iter().map(|(lo, hi)| hi - lo).fold(0.0, f64::max);
    let extent = if largest > 0.0 { largest } else { 1.0 };
    let scale = (PANEL - LABEL_BAND - 2.0 * MARGIN) / extent;
    let width = 3.0 * PANEL + 4.0 * GAP;
    let height = HEADER + PANEL + FOOTER;
    let q: Vec<String> = scene.q.iter().map(f64::to_string).collect();
    let mut out = String::new();
    // `write!` into a String cannot fail.
    let mut w = |text: String| out.push_str(&text);
    w(format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" \
         data-robot=\"{}\" data-scale=\"{scale}\" data-q=\"{}\"{}>\n",
        px(width),
        px(height),
        px(width),
        px(height),
        escape(&scene.robot),
        q.join(","),
        if scene.trace.is_some() { format!(" data-path=\"{}\"", scene.ghosts.len() + 1) } else { String::new() }
    ));
    w(format!("<title>robot {} drawn by kinematics draw</title>\n", escape(&scene.robot)));
    w("<defs>\n".to_owned());
    for (style, colour) in [("revolute", "#1f5fbf"), ("prismatic", "#d2691e"), ("planar", "#2e8b57")] {
        w(format!(
            "<marker id=\"head-{style}\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"4\" \
             markerHeight=\"4\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"{colour}\"/></marker>\n"
        ));
    }
    w("</defs>\n".to_owned());
    w(concat!(
        "<style>\n",
        "text { font-family: Helvetica, Arial, sans-serif; fill: #222; }\n",
        ".panel { fill: #fafafa; stroke: #bbb; }\n",
        ".view-label { font-size: 13px; font-weight: bold; }\n",
        ".link { fill: none; stroke: #555; stroke-width: 2.5; stroke-linecap: round; stroke-linejoin: round; }\n",
        ".origin { fill: #222; }\n",
        ".axis { stroke-width: 2; }\n",
        ".revolute { stroke: #1f5fbf; }\n",
        ".prismatic { stroke: #d2691e; stroke-dasharray: 4 2; }\n",
        ".planar { stroke: #2e8b57; stroke-dasharray: 1 2; }\n",
        ".label { font-size: 9px; fill: #444; }\n",
        ".scale-bar { stroke: #222; stroke-width: 1.5; }\n",
        ".geometry { fill: #6b7280; fill-opacity: 0.35; stroke: #374151; stroke-width: 0.5; stroke-opacity: 0.6; stroke-linejoin: round; }\n",
        ".sphere { fill: #e8a33d; fill-opacity: 0.25; stroke: #c07a12; stroke-width: 0.6; }\n",
        ".obstacle { fill: #8a8fa3; fill-opacity: 0.3; stroke: #4d5266; stroke-width: 1; }\n",
        ".obstacle-edge { stroke: #4d5266; stroke-width: 1; }\n",
        ".ghost { fill: none; stroke: #555; stroke-width: 1.5; stroke-linecap: round; stroke-linejoin: round; }\n",
        ".trace { fill: none; stroke: #c0392b; stroke-width: 1.5; }\n",
        ".waypoint { fill: #c0392b; }\n",
        "</style>\n"
    )
    .to_owned());
    let shown: Vec<String> = scene.q.iter().take(TITLE_VALUES).map(|v| format!("{v:.4}")).collect();
    let more = if scene.q.len() > TITLE_VALUES { format!(", … ({} values)", scene.q.len()) } else { String::new() };
    let along = match &scene.trace {
        Some(_) => format!(" along a path of {} configurations, the last", scene.ghosts.len() + 1),
        None => String::new(),
    };
    w(format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"15\">robot {}{along} at q = ({}{more})</text>\n",
        px(GAP),
        px(HEADER - 14.0),
        label(&scene.robot),
        shown.join(", ")
    ));
    for (i, view) in VIEWS.iter().enumerate() {
        let left = GAP + i as f64 * (PANEL + GAP);
        let (u_lo, u_hi) = bounds[view.u];
        let (v_lo, v_hi) = bounds[view.v];
        // Centre the box's projection in the panel (an empty scene has an infinite box: centre 0).
        let centre = |lo: f64, hi: f64| if lo <= hi { (lo + hi) / 2.0 } else { 0.0 };
        let placed = Placed {
            view,
            scale,
            ox: left + PANEL / 2.0 - scale * centre(u_lo, u_hi),
            oy: HEADER + LABEL_BAND + (PANEL - LABEL_BAND) / 2.0 + scale * centre(v_lo, v_hi),
        };
        w(view_group(scene, &placed, left));
    }
    let (metres, decimals) = bar_length(extent);
    let (x0, y) = (GAP, HEADER + PANEL + 22.0);
    let x1 = x0 + metres * scale;
    w(format!(
        "<g class=\"scale\" data-metres=\"{metres}\"><line class=\"scale-bar\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>\
         <line class=\"scale-bar\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/><line class=\"scale-bar\" x1=\"{}\" y1=\"{}\" \
         x2=\"{}\" y2=\"{}\"/><text x=\"{}\" y=\"{}\" font-size=\"11\">{metres:.decimals$} m</text></g>\n",
        px(x0),
        px(y),
        px(x1),
        px(y),
        px(x0),
        px(y - 4.0),
        px(x0),
        px(y + 4.0),
        px(x1),
        px(y - 4.0),
        px(x1),
        px(y + 4.0),
        px(x1 + 6.0),
        px(y + 4.0)
    ));
    w(legend(scene, x1 + 90.0, y));
    out.push_str("</svg>\n");
    out
}

/// The legend from `x` along the line at `y`: each axis style, then what else is drawn, on lines
/// centred on it (two or three for most drawings).
fn legend(scene: &Scene, mut x: f64, y: f64) -> String {
    let mut out = String::new();
    for style in [AxisStyle::Revolute, AxisStyle::Prismatic, AxisStyle::Planar] {
        let class = style.class();
        let text = match style {
            AxisStyle::Revolute => "revolute axis",
            AxisStyle::Prismatic => "prismatic axis",
            AxisStyle::Planar => "planar normal",
        };
        let _ = writeln!(
            out,
            "<g class=\"legend\"><line class=\"axis {class}\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" \
             marker-end=\"url(#head-{class})\"/><text x=\"{}\" y=\"{}\" font-size=\"11\">{text}</text></g>",
            px(x),
            px(y),
            px(x + AXIS_PX),
            px(y),
            px(x + AXIS_PX + 6.0),
            px(y + 4.0)
        );
        x += 130.0;
    }
    let mut parts = vec!["links grey, origins as dots".to_owned(), "fixed and floating joints have no axis".to_owned()];
    if !scene.spheres.is_empty() {
        parts.push(format!("{} collision spheres orange", scene.spheres.len()));
    }
    match (scene.solids.len(), scene.meshes_left_out) {
        (0, 0) => {}
        (0, m) => parts.push(format!("{m} collision meshes not drawn")),
        (_, m) => {
            let under = if scene.spheres.is_empty() { "" } else { " under them" };
            let left_out = if m == 0 { String::new() } else { format!(" ({m} meshes not drawn)") };
            parts.push(format!("the collision geometry{under} shaded{left_out}"));
        }
    }
    if !scene.obstacles.is_empty() {
        parts.push(format!("{} obstacles blue-grey", scene.obstacles.len()));
    }
    if let Some(trace) = &scene.trace {
        parts.push(format!(
            "a path of {} configurations, the earlier faded, the trace of {} red",
            scene.ghosts.len() + 1,
            label(&trace.link)
        ));
    }
    // As many lines of at most LEGEND_CHARS characters as it takes, centred on the line at `y`.
    let mut lines: Vec<String> = Vec::new();
    for part in parts {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 2 + part.chars().count() <= LEGEND_CHARS => {
                line.push_str("; ");
                line.push_str(&part);
            }
            _ => lines.push(part),
        }
    }
    for (k, line) in lines.iter().enumerate() {
        let baseline = y + 4.0 + LEGEND_LEADING * (k as f64 - (lines.len() - 1) as f64 / 2.0);
        let _ = writeln!(out, "<text x=\"{}\" y=\"{}\" font-size=\"11\">{line}</text>", px(x), px(baseline));
    }
    out
}

/// One view's group: panel, label, segments, axes, origins and (for small robots) names.
fn view_group(scene: &Scene, placed: &Placed, left: f64) -> String {
    let view = placed.view;
    let (u, v) = (AXIS_NAMES[view.u], AXIS_NAMES[view.v]);
    let mut out = format!(
        "<g class=\"view\" data-view=\"{}\" data-u=\"{u}\" data-v=\"{v}\" data-ox=\"{}\" data-oy=\"{}\">\n\
         <rect class=\"panel\" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/>\n\
         <text class=\"view-label\" x=\"{}\" y=\"{}\">{} ({u}-{v}: {u} right, {v} up)</text>\n",
        view.name,
        placed.ox,
        placed.oy,
        px(left),
        px(HEADER),
        px(PANEL),
        px(PANEL),
        px(left + 8.0),
        px(HEADER + 18.0),
        view.name
    );
    out.push_str(&obstacles(scene, placed));
    out.push_str(&path(scene, placed));
    out.push_str(&geometry(scene, placed));
    for ball in &scene.spheres {
        let (x, y) = placed.screen(ball.center);
        let _ = writeln!(
            out,
            "<circle class=\"sphere\" data-link=\"{}\" {} data-r=\"{}\" cx=\"{}\" cy=\"{}\" r=\"{}\"/>",
            escape(&ball.link),
            point_data(ball.center),
            ball.radius,
            px(x),
            px(y),
            px(ball.radius * placed.scale)
        );
    }
    for joint in &scene.joints {
        let points: Vec<String> = joint
            .points
            .iter()
            .map(|&p| {
                let (x, y) = placed.screen(p);
                format!("{},{}", px(x), px(y))
            })
            .collect();
        let data: Vec<String> = joint.points.iter().map(|p| format!("{},{},{}", p[0], p[1], p[2])).collect::<Vec<_>>();
        let _ = writeln!(
            out,
            "<polyline class=\"link\" data-joint=\"{}\" data-points=\"{}\" points=\"{}\"><title>link {} (joint {}, {})</title></polyline>",
            escape(&joint.name),
            data.join(" "),
            points.join(" "),
            escape(&joint.child),
            escape(&joint.name),
            joint.kind
        );
    }
    for joint in &scene.joints {
        let Some((at, direction, style)) = joint.axis else { continue };
        let (x1, y1) = placed.screen(at);
        let (x2, y2) = (x1 + AXIS_PX * direction[view.u], y1 - AXIS_PX * direction[view.v]);
        let class = style.class();
        let _ = writeln!(
            out,
            "<line class=\"axis {class}\" data-joint=\"{}\" {} data-dx=\"{}\" data-dy=\"{}\" data-dz=\"{}\" x1=\"{}\" \
             y1=\"{}\" x2=\"{}\" y2=\"{}\" marker-end=\"url(#head-{class})\"><title>joint {} ({}) axis</title></line>",
            escape(&joint.name),
            point_data(at),
            direction[0],
            direction[1],
            direction[2],
            px(x1),
            px(y1),
            px(x2),
            px(y2),
            escape(&joint.name),
            joint.kind
        );
    }
    for link in &scene.links {
        let (x, y) = placed.screen(link.origin);
        let _ = writeln!(
            out,
            "<circle class=\"origin\" data-link=\"{}\" {} cx=\"{}\" cy=\"{}\" r=\"3\"><title>link {}</title></circle>",
            escape(&link.name),
            point_data(link.origin),
            px(x),
            px(y),
            escape(&link.name)
        );
    }
    if scene.links.len() <= LABEL_LIMIT {
        // Links whose origins fall on one point of this view share one label ("ee_link, tool0",
        // in the order they come), rather than labels drawn over each other.
        let mut spots: Vec<((String, String), Vec<&str>)> = Vec::new();
        for link in &scene.links {
            let (x, y) = placed.screen(link.origin);
            let at = (px(x + 5.0), px(y - 5.0));
            match spots.iter_mut().find(|(spot, _)| *spot == at) {
                Some((_, names)) => names.push(&link.name),
                None => spots.push((at, vec![&link.name])),
            }
        }
        for ((x, y), names) in spots {
            let _ = writeln!(out, "<text class=\"label\" x=\"{x}\" y=\"{y}\">{}</text>", label(&names.join(", ")));
        }
    }
    out.push_str("</g>\n");
    out
}

/// A path in one view: each earlier configuration's links, fainter the earlier it comes, then the
/// trace, with a dot where each configuration puts the traced link.
fn path(scene: &Scene, placed: &Placed) -> String {
    let mut out = String::new();
    let Some(trace) = &scene.trace else { return out };
    let screen = |points: &[[f64; 3]]| -> (String, String) {
        let data: Vec<String> = points.iter().map(|p| format!("{},{},{}", p[0], p[1], p[2])).collect();
        let xy: Vec<String> = points
            .iter()
            .map(|&p| {
                let (x, y) = placed.screen(p);
                format!("{},{}", px(x), px(y))
            })
            .collect();
        (data.join(" "), xy.join(" "))
    };
    let count = scene.ghosts.len() + 1;
    for ghost in &scene.ghosts {
        let opacity = 0.15 + 0.45 * ghost.index as f64 / count as f64;
        for (joint, points) in &ghost.segments {
            let (data, xy) = screen(points);
            let _ = writeln!(
                out,
                "<polyline class=\"ghost\" data-waypoint=\"{}\" data-joint=\"{}\" data-points=\"{data}\" \
                 points=\"{xy}\" stroke-opacity=\"{opacity:.3}\"/>",
                ghost.index,
                escape(joint)
            );
        }
    }
    let (data, xy) = screen(&trace.points);
    let _ = writeln!(
        out,
        "<polyline class=\"trace\" data-link=\"{}\" data-points=\"{data}\" points=\"{xy}\"><title>path of {}</title></polyline>",
        escape(&trace.link),
        escape(&trace.link)
    );
    for (index, &p) in trace.points.iter().step_by(super::TRACE_STEPS).enumerate() {
        let (x, y) = placed.screen(p);
        let _ = writeln!(
            out,
            "<circle class=\"waypoint\" data-waypoint=\"{index}\" {} cx=\"{}\" cy=\"{}\" r=\"2.5\"><title>configuration {index}</title></circle>",
            point_data(p),
            px(x),
            px(y)
        );
    }
    out
}

/// The collision geometry in one view, each element one path: a primitive's outline, a mesh's
/// region on the grid of cells (its loops' corners, edges written `H` and `V`).
fn geometry(scene: &Scene, placed: &Placed) -> String {
    let mut out = String::new();
    let (u, v) = (placed.view.u, placed.view.v);
    for solid in &scene.solids {
        let link = escape(&solid.link);
        let _ = write!(
            out,
            "<path class=\"geometry\" data-link=\"{link}\" data-element=\"{}\" data-shape=\"{}\"",
            solid.element, solid.shape
        );
        let mut d = String::new();
        match &solid.form {
            Form::Convex { pose, shape } => {
                let points = Solid::outline_points(pose, *shape, u, v, placed.scale);
                let outline = silhouette::hull(points.into_iter().map(|p| placed.screen(p)).collect());
                for (k, (x, y)) in outline.into_iter().enumerate() {
                    let _ = write!(d, "{}{},{}", if k == 0 { "M" } else { " L" }, px(x), px(y));
                }
                d.push('Z');
            }
            Form::Mesh { vertices, triangles } => {
                let points: Vec<(f64, f64)> = vertices.iter().map(|&p| placed.screen(p)).collect();
                let at = |i: i64| i as f64 * CELL;
                for corners in silhouette::outline(&points, triangles) {
                    for (k, &(i, j)) in corners.iter().enumerate() {
                        // Edges are horizontal or vertical: each corner differs from the last in one.
                        let _ = match k {
                            0 => write!(d, "M{},{}", at(i), at(j)),
                            _ if j == corners[k - 1].1 => write!(d, "H{}", at(i)),
                            _ => write!(d, "V{}", at(j)),
                        };
                    }
                    d.push('Z');
                }
                let _ = write!(out, " data-cell=\"{CELL}\"");
            }
        }
        let _ = writeln!(out, " d=\"{d}\"><title>collision {} {} of {link}</title></path>", solid.shape, solid.element);
    }
    out
}

/// The obstacles' outlines in one view: spheres as circles, cylinders and capsules as their axis
/// drawn as wide as they are (round ends for capsules), boxes as their twelve edges.
fn obstacles(scene: &Scene, placed: &Placed) -> String {
    let mut out = String::new();
    for obstacle in &scene.obstacles {
        let name = escape(&obstacle.name);
        match &obstacle.shape {
            ObstacleShape::Sphere { center, radius } => {
                let (x, y) = placed.screen(*center);
                let _ = writeln!(
                    out,
                    "<circle class=\"obstacle\" data-obstacle=\"{name}\" cx=\"{}\" cy=\"{}\" r=\"{}\"><title>{name}</title></circle>",
                    px(x),
                    px(y),
                    px(radius * placed.scale)
                );
            }
            ObstacleShape::Round { a, b, radius, capsule } => {
                let ((x1, y1), (x2, y2)) = (placed.screen(*a), placed.screen(*b));
                let cap = if *capsule { "round" } else { "butt" };
                let _ = writeln!(
                    out,
                    "<line class=\"obstacle-edge\" data-obstacle=\"{name}\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" \
                     stroke-opacity=\"0.3\" stroke-linecap=\"{cap}\" stroke-width=\"{}\"><title>{name}</title></line>",
                    px(x1),
                    px(y1),
                    px(x2),
                    px(y2),
                    px(2.0 * radius * placed.scale)
                );
            }
            ObstacleShape::Box { corners } => {
                let mut path = String::new();
                // The edges join corners that differ in one bit.
                for (i, &c) in corners.iter().enumerate() {
                    for bit in 0..3 {
                        let j = i | 1 << bit;
                        if j != i {
                            let ((x1, y1), (x2, y2)) = (placed.screen(c), placed.screen(corners[j]));
                            let _ = write!(path, "M{},{} L{},{} ", px(x1), px(y1), px(x2), px(y2));
                        }
                    }
                }
                let _ = writeln!(
                    out,
                    "<path class=\"obstacle-edge\" data-obstacle=\"{name}\" d=\"{}\"><title>{name}</title></path>",
                    path.trim_end()
                );
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_escaped_for_xml() {
        assert_eq!(escape("a<b>&\"c\"'d'"), "a&lt;b&gt;&amp;&quot;c&quot;&apos;d&apos;");
        assert_eq!(escape("bell\u{7}"), "bell\u{FFFD}");
        assert_eq!(label(&"x".repeat(40)), format!("{}…", "x".repeat(31)));
    }

    #[test]
    fn scale_bars_are_round_lengths_within_a_quarter_of_the_extent() {
        for (extent, metres, decimals) in
            [(1.0, 0.2, 1), (0.85, 0.2, 1), (4.0, 1.0, 0), (10.0, 2.0, 0), (0.021, 0.005, 3), (30.0, 5.0, 0)]
        {
            let (got, d) = bar_length(extent);
            assert!((got - metres).abs() < 1e-15 && d == decimals, "{extent}: {got} {d}");
        }
    }

    #[test]
    fn negative_zero_prints_as_zero() {
        assert_eq!(px(-0.0), "0.000");
        assert_eq!(px(-0.0001), "0.000");
        assert_eq!(px(1.23456), "1.235");
    }
}
