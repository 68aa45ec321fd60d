//! `kinematics draw` run as a user runs it (issue 21): the SVG of every robot in `robots/` read
//! back, its link origins and joint axes held against the runtime reference at the same
//! configuration, every view's screen coordinates against the 3D data and the one scale, and bad
//! input refused with nothing written.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::collections::BTreeMap;
use std::path::Path;

use kinematics::ReferenceFk;
use kinematics::model::JointKind;

mod common;
use common::{fails, ok, root, run, scratch};

/// Every description in `robots/`, as `robots/<file>`.
fn robots() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(root().join("robots"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| kinematics::model::SourceFormat::from_file_name(f).is_some())
        .map(|f| format!("robots/{f}"))
        .collect();
    files.sort();
    assert!(files.len() >= 10, "robots/ should hold the robot library: {files:?}");
    files
}

fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
}

/// A configuration with distinct values, some negative, none special.
fn configuration(dof: usize) -> Vec<f64> {
    (0..dof).map(|i| 0.61 * ((i * 7 % 11) as f64) - 2.3 + 0.013 * i as f64).collect()
}

fn joined(q: &[f64]) -> String {
    q.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(",")
}

/// One start tag of the SVG: its name and attributes (values unescaped), in document order,
/// with the index of the `view` group it sits in, if any.
#[derive(Debug)]
struct Element {
    name: String,
    attributes: BTreeMap<String, String>,
    view: Option<usize>,
}

impl Element {
    fn get(&self, key: &str) -> &str {
        self.attributes.get(key).unwrap_or_else(|| panic!("<{}> has no `{key}`: {:?}", self.name, self.attributes))
    }

    fn number(&self, key: &str) -> f64 {
        self.get(key).parse().unwrap_or_else(|e| panic!("`{key}` = `{}`: {e}", self.get(key)))
    }

    fn class(&self) -> &str {
        self.attributes.get("class").map_or("", String::as_str)
    }
}

fn unescape(text: &str) -> String {
    text.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&apos;", "'").replace("&amp;", "&")
}

/// The start tags of an SVG written as `draw` writes it (attribute values in double quotes,
/// `<` escaped inside them and in text).
fn elements(svg: &str) -> Vec<Element> {
    let mut out = Vec::new();
    let mut views = 0;
    let mut in_view = None;
    for chunk in svg.split('<').skip(1) {
        let tag = &chunk[..chunk.find('>').unwrap()];
        if tag.starts_with('/') {
            if tag == "/g" {
                in_view = None;
            }
            continue;
        }
        let name_end = tag.find([' ', '/']).unwrap_or(tag.len());
        let name = tag[..name_end].to_owned();
        let mut attributes = BTreeMap::new();
        let mut rest = &tag[name_end..];
        while let Some(eq) = rest.find("=\"") {
            let key = rest[..eq].trim().to_owned();
            let value_end = rest[eq + 2..].find('"').unwrap();
            attributes.insert(key, unescape(&rest[eq + 2..eq + 2 + value_end]));
            rest = &rest[eq + 2 + value_end + 1..];
        }
        let element = Element { name, attributes, view: in_view };
        if element.name == "g" && element.class() == "view" {
            in_view = Some(views);
            views += 1;
        }
        out.push(element);
    }
    out
}

fn point(e: &Element) -> [f64; 3] {
    [e.number("data-x"), e.number("data-y"), e.number("data-z")]
}

fn close(a: [f64; 3], b: [f64; 3], tolerance: f64) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() <= tolerance)
}

/// A screen coordinate printed with three decimals.
fn on_screen(printed: f64, exact: f64) -> bool {
    (printed - exact).abs() <= 5e-4 + 1e-9 * exact.abs()
}

#[test]
fn draw_puts_every_origin_and_axis_where_the_runtime_reference_does() {
    for file in robots() {
        let fk = ReferenceFk::new(kinematics::load(root().join(&file)).unwrap());
        let tree = fk.tree();
        let q = configuration(tree.dof());
        let svg = ok(&["draw", &file, "--skip-meshes", "--q", &joined(&q)]);
        assert!(svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\"") && svg.ends_with("</svg>\n"), "{file}");
        let poses = fk.link_poses(&q).unwrap();
        let reach = tree.reach().max(f64::MIN_POSITIVE);
        let tolerance = 1e-9 * reach;
        let elements = elements(&svg);
        let root = &elements[0];
        assert_eq!(root.get("data-robot"), tree.name());
        assert_eq!(root.get("data-q"), joined(&q), "{file}");
        let scale = root.number("data-scale");
        assert!(scale > 0.0 && scale.is_finite(), "{file}: {scale}");
        let views: Vec<&Element> = elements.iter().filter(|e| e.name == "g" && e.class() == "view").collect();
        let names: Vec<&str> = views.iter().map(|v| v.get("data-view")).collect();
        assert_eq!(names, ["front", "side", "top"], "{file}");
        let coordinate = |name: &str| ["x", "y", "z"].iter().position(|c| *c == name).unwrap();
        let uv: Vec<(usize, usize)> =
            views.iter().map(|v| (coordinate(v.get("data-u")), coordinate(v.get("data-v")))).collect();
        assert_eq!(uv, [(0, 2), (1, 2), (0, 1)], "{file}");
        // Where a view must put a root-frame point.
        let project = |view: usize, p: [f64; 3]| {
            let (u, v) = uv[view];
            (views[view].number("data-ox") + scale * p[u], views[view].number("data-oy") - scale * p[v])
        };
        let panels: Vec<&Element> = elements.iter().filter(|e| e.class() == "panel").collect();
        let inside = |view: usize, x: f64, y: f64| {
            let panel = panels[view];
            let (left, top) = (panel.number("x"), panel.number("y"));
            (left..=left + panel.number("width")).contains(&x) && (top..=top + panel.number("height")).contains(&y)
        };

        // Every link's origin, once per view, at the runtime's position and projected by the scale.
        let dots: Vec<&Element> = elements.iter().filter(|e| e.class() == "origin").collect();
        assert_eq!(dots.len(), 3 * tree.links().len(), "{file}");
        for dot in &dots {
            let id = tree.link_id(dot.get("data-link")).unwrap();
            let expected = poses[id.0].translation.vector;
            let drawn = point(dot);
            assert!(close(drawn, [expected.x, expected.y, expected.z], tolerance), "{file}: {drawn:?} {expected:?}");
            let view = dot.view.unwrap();
            let (x, y) = project(view, drawn);
            assert!(on_screen(dot.number("cx"), x) && on_screen(dot.number("cy"), y), "{file}: {dot:?}");
            assert!(inside(view, x, y), "{file}: {} outside its panel", dot.get("data-link"));
        }

        // Every joint's segment, from the parent's origin to the child's, once per view.
        let segments: Vec<&Element> = elements.iter().filter(|e| e.name == "polyline").collect();
        assert_eq!(segments.len(), 3 * tree.joints().len(), "{file}");
        for segment in &segments {
            let joint = tree.joint_by_name(segment.get("data-joint")).unwrap();
            let points: Vec<[f64; 3]> = segment
                .get("data-points")
                .split(' ')
                .map(|p| {
                    let c: Vec<f64> = p.split(',').map(|x| x.parse().unwrap()).collect();
                    [c[0], c[1], c[2]]
                })
                .collect();
            let origin = |id: kinematics::model::LinkId| {
                let t = poses[id.0].translation.vector;
                [t.x, t.y, t.z]
            };
            assert!(close(points[0], origin(joint.parent), tolerance), "{file}: {}", joint.name);
            assert!(close(*points.last().unwrap(), origin(joint.child), tolerance), "{file}: {}", joint.name);
            let screen: Vec<f64> =
                segment.get("points").split([' ', ',']).map(|x| x.parse().unwrap()).collect::<Vec<_>>();
            assert_eq!(screen.len(), 2 * points.len(), "{file}");
            for (p, xy) in points.iter().zip(screen.chunks(2)) {
                let (x, y) = project(segment.view.unwrap(), *p);
                assert!(on_screen(xy[0], x) && on_screen(xy[1], y), "{file}: {segment:?}");
            }
        }

        // Every moving joint's axis (fixed, floating and spherical joints have none), at the joint
        // frame after its motion, along the axis in the root frame, styled by its kind.
        let axes: Vec<&Element> =
            elements.iter().filter(|e| e.name == "line" && e.attributes.contains_key("data-joint")).collect();
        let drawn_kinds = tree
            .joints()
            .iter()
            .filter(|j| !matches!(j.kind, JointKind::Fixed | JointKind::Floating | JointKind::Spherical));
        assert_eq!(axes.len(), 3 * drawn_kinds.count(), "{file}");
        for axis in &axes {
            let joint = tree.joint_by_name(axis.get("data-joint")).unwrap();
            let style = match joint.kind {
                JointKind::Revolute | JointKind::Continuous => "axis revolute",
                JointKind::Prismatic => "axis prismatic",
                JointKind::Planar => "axis planar",
                other => panic!("{file}: a {other:?} joint has an axis"),
            };
            assert_eq!(axis.class(), style, "{file}: {}", joint.name);
            let moved = poses[joint.child.0] * kinematics::runtime::fixed_isometry(&joint.after_motion).inverse();
            let at = moved.translation.vector;
            assert!(close(point(axis), [at.x, at.y, at.z], tolerance), "{file}: {}", joint.name);
            let d = moved.rotation * nalgebra::Vector3::from(joint.axis);
            let drawn = [axis.number("data-dx"), axis.number("data-dy"), axis.number("data-dz")];
            assert!(close(drawn, [d.x, d.y, d.z], 1e-12), "{file}: {}: {drawn:?} {d:?}", joint.name);
            let view = axis.view.unwrap();
            let (x, y) = project(view, point(axis));
            assert!(on_screen(axis.number("x1"), x) && on_screen(axis.number("y1"), y), "{file}: {axis:?}");
            // The drawn arrow points along the axis's projection: parallel, same sense.
            let (u, v) = uv[view];
            let (ex, ey) = (axis.number("x2") - axis.number("x1"), -(axis.number("y2") - axis.number("y1")));
            let cross = ex * drawn[v] - ey * drawn[u];
            let dot = ex * drawn[u] + ey * drawn[v];
            assert!(cross.abs() < 2e-3 && dot >= -2e-3, "{file}: {}: {ex} {ey} against {drawn:?}", joint.name);
        }

        // The collision geometry (its primitives: meshes are left out here), one path per element
        // and view, inside its panel.
        let primitives = tree.links().iter().flat_map(|l| &l.collisions).filter(|c| c.shape.name() != "mesh").count();
        let drawn = geometry(&elements);
        assert_eq!(drawn.len(), 3 * primitives, "{file}");
        for Drawn { path, loops, .. } in &drawn {
            for &(x, y) in loops.iter().flatten() {
                assert!(inside(path.view.unwrap(), x, y), "{file}: {path:?} outside its panel");
            }
        }

        // The scale bar is as long as it says, on the common scale.
        let bar = elements.iter().find(|e| e.class() == "scale").unwrap();
        let line = elements.iter().find(|e| e.class() == "scale-bar").unwrap();
        let length = line.number("x2") - line.number("x1");
        assert!(on_screen(length, bar.number("data-metres") * scale), "{file}: {length} px for {bar:?}");
        assert!(svg.contains(" m</text></g>"), "{file}");
    }
}

#[test]
fn draw_writes_the_file_it_prints_and_reads_degrees_and_zeros_as_fk_does() {
    let printed = ok(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "0.3,-1.2,1.0,0.4,-0.7,2.0"]);
    // Deterministic: the same run prints the same bytes.
    assert_eq!(printed, ok(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "0.3,-1.2,1.0,0.4,-0.7,2.0"]));
    let dir = scratch("output");
    let path = dir.join("ur5.svg");
    assert_eq!(
        ok(&[
            "draw",
            "robots/ur5.urdf",
            "--skip-meshes",
            "--q",
            "0.3,-1.2,1.0,0.4,-0.7,2.0",
            "-o",
            path.to_str().unwrap()
        ]),
        ""
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), printed);
    assert_eq!(entries(&dir), ["ur5.svg"]);
    std::fs::remove_dir_all(&dir).unwrap();
    let radians =
        ok(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "0,-1.5707963267948966,1.5707963267948966,0,0,0"]);
    let degrees = ok(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "0,-90,90,0,0,0", "--degrees"]);
    assert_eq!(radians, degrees);
    // Omitted, `--q` is the zero configuration, as for `fk`.
    assert_eq!(
        ok(&["draw", "robots/ur5.urdf", "--skip-meshes"]),
        ok(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "0,0,0,0,0,0"])
    );
}

#[test]
fn draw_refuses_bad_configurations_and_leaves_no_file_behind() {
    let dir = scratch("errors");
    let path = dir.join("robot.svg");
    let target = path.to_str().unwrap();
    assert_eq!(
        fails(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "1,2,3", "-o", target]),
        "error: robots/ur5.urdf: robot `ur5` has 6 degrees of freedom (shoulder_pan_joint, shoulder_lift_joint, \
         elbow_joint, wrist_1_joint, wrist_2_joint, wrist_3_joint), but q has 3 values"
    );
    assert_eq!(
        fails(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "0,NaN,0,0,0,0", "-o", target]),
        "error: robots/ur5.urdf: robot `ur5`: the value of joint `shoulder_lift_joint` (q[1]) is NaN, not a finite number"
    );
    assert_eq!(
        fails(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "0,0,inf,0,0,0", "-o", target]),
        "error: robots/ur5.urdf: robot `ur5`: the value of joint `elbow_joint` (q[2]) is inf, not a finite number"
    );
    assert_eq!(
        fails(&["draw", "robots/none.urdf", "-o", target]).split(": cannot read").next(),
        Some("error: robots/none.urdf")
    );
    assert!(entries(&dir).is_empty(), "{:?}", entries(&dir));
    // A path that cannot be written: a missing directory, and a directory in the file's place.
    let missing = dir.join("missing").join("robot.svg");
    let message = fails(&["draw", "robots/ur5.urdf", "--skip-meshes", "-o", missing.to_str().unwrap()]);
    assert!(
        message.starts_with(&format!("error: robots/ur5.urdf: cannot write `{}`: ", missing.display())),
        "{message}"
    );
    std::fs::create_dir(&path).unwrap();
    let message = fails(&["draw", "robots/ur5.urdf", "--skip-meshes", "-o", target]);
    assert!(message.starts_with(&format!("error: robots/ur5.urdf: cannot write `{target}`: ")), "{message}");
    assert_eq!(entries(&dir), ["robot.svg"]);
    assert!(entries(&path).is_empty());
    std::fs::remove_dir_all(&dir).unwrap();
    // Not a number: clap's usage error (status 2), as for `fk`.
    let output = run(&["draw", "robots/ur5.urdf", "--skip-meshes", "--q", "1,x"]);
    assert_eq!(output.status.code(), Some(2));
}

#[test]
fn names_are_escaped_and_read_back() {
    let dir = scratch("names");
    let urdf = r#"<robot name="r&amp;d"><link name="base &lt;0&gt;"/><link name="tip &quot;1&quot; &amp; 'x'"/>
      <joint name="j&lt;1&gt;" type="prismatic"><parent link="base &lt;0&gt;"/><child link="tip &quot;1&quot; &amp; 'x'"/>
      <origin xyz="0.1 0 0.2"/><axis xyz="0 0 1"/><limit lower="0" upper="1" effort="1" velocity="1"/></joint></robot>"#;
    let file = dir.join("names.urdf");
    std::fs::write(&file, urdf).unwrap();
    let svg = ok(&["draw", file.to_str().unwrap(), "--q", "0.25"]);
    let elements = elements(&svg);
    assert_eq!(elements[0].get("data-robot"), "r&d");
    let links: Vec<&str> =
        elements.iter().filter(|e| e.class() == "origin" && e.view == Some(0)).map(|e| e.get("data-link")).collect();
    assert_eq!(links, ["base <0>", "tip \"1\" & 'x'"]);
    let axis = elements.iter().find(|e| e.class() == "axis prismatic" && e.view == Some(0)).unwrap();
    assert_eq!(axis.get("data-joint"), "j<1>");
    // Text content is escaped too: no raw `<` or `&` outside markup.
    assert!(svg.contains(">base &lt;0&gt;</text>") && svg.contains("<title>robot r&amp;d drawn"), "{svg}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn draw_shows_the_collision_spheres_and_a_scenes_obstacles() {
    let file = "robots/panda_spherized.urdf";
    let fk = ReferenceFk::new(kinematics::load(root().join(file)).unwrap());
    let q = configuration(7);
    let svg = ok(&["draw", file, "--q", &joined(&q), "--scene", "scenes/shelf.toml"]);
    let elements = elements(&svg);
    let scale = elements[0].number("data-scale");
    let spheres = kinematics::model::collision::link_spheres(
        fk.tree(),
        &kinematics::model::collision::Cover::default(),
        kinematics::model::collision::Meshes::Read,
    )
    .unwrap();
    let centers = fk.sphere_centers(&q, &spheres).unwrap();
    // Every sphere once per view, where the reference puts it, as wide as it is on the scale.
    let drawn: Vec<&Element> = elements.iter().filter(|e| e.class() == "sphere").collect();
    assert_eq!(drawn.len(), 3 * spheres.len());
    for (k, circle) in drawn.iter().enumerate() {
        let (center, sphere) = (centers[k % spheres.len()], &spheres[k % spheres.len()]);
        assert!(close(point(circle), [center.x, center.y, center.z], 1e-12), "{circle:?}");
        assert_eq!(circle.number("data-r"), sphere.sphere.radius);
        assert!(on_screen(circle.number("r"), sphere.sphere.radius * scale), "{circle:?}");
    }
    // Every obstacle of the scene once per view, each kind its outline.
    let scene = kinematics::load_scene(root().join("scenes/shelf.toml")).unwrap();
    let outlines: Vec<&Element> = elements.iter().filter(|e| e.attributes.contains_key("data-obstacle")).collect();
    assert_eq!(outlines.len(), 3 * scene.len());
    for name in &scene.names {
        assert_eq!(outlines.iter().filter(|e| e.get("data-obstacle") == name).count(), 3, "{name}");
    }
    let boxes = outlines.iter().filter(|e| e.name == "path").count();
    assert_eq!(boxes, 3 * scene.boxes.len());
    // A bad scene is refused naming its obstacle, and nothing is written.
    let dir = scratch("scene");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "[[obstacle]]\nname = \"post\"\ncylinder = { radius = 0.1, length = -1.0 }\n").unwrap();
    let message = fails(&["draw", file, "--scene", bad.to_str().unwrap(), "-o", dir.join("out.svg").to_str().unwrap()]);
    assert!(message.contains("obstacle 1 (`post`) (line 1): <cylinder length> is -1"), "{message}");
    assert_eq!(entries(&dir), ["bad.toml"]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn draw_shows_a_path_and_refuses_bad_path_files_naming_the_line() {
    let file = "robots/panda_spherized.urdf";
    let fk = ReferenceFk::new(kinematics::load(root().join(file)).unwrap());
    let tree = fk.tree();
    let path = [configuration(7), vec![0.0, 0.3, 0.0, -1.2, 0.0, 1.5, 0.8], vec![1.2, 0.3, 0.0, -1.2, 0.0, 1.5, 0.8]];
    let dir = scratch("path");
    let written = dir.join("plan.txt");
    let text = format!("# a plan\n{}\n\n{}\n  {}  \n", joined(&path[0]), joined(&path[1]), joined(&path[2]));
    std::fs::write(&written, text).unwrap();
    let plan = written.to_str().unwrap();
    let svg = ok(&["draw", file, "--path", plan, "--scene", "scenes/table_shelves.toml"]);
    let elements = elements(&svg);
    // The robot in full at the last configuration, as `--q` draws it.
    assert_eq!((elements[0].get("data-q"), elements[0].get("data-path")), (joined(&path[2]).as_str(), "3"));
    let poses: Vec<Vec<nalgebra::Isometry3<f64>>> = path.iter().map(|q| fk.link_poses(q).unwrap()).collect();
    let origin = |k: usize, link: kinematics::model::LinkId| {
        let t = poses[k][link.0].translation.vector;
        [t.x, t.y, t.z]
    };
    for dot in elements.iter().filter(|e| e.class() == "origin") {
        assert!(close(point(dot), origin(2, tree.link_id(dot.get("data-link")).unwrap()), 1e-12), "{dot:?}");
    }
    // The earlier configurations faded: every joint's segment from its parent's origin to its child's.
    let ghosts: Vec<&Element> = elements.iter().filter(|e| e.class() == "ghost").collect();
    assert_eq!(ghosts.len(), 3 * 2 * tree.joints().len());
    for ghost in &ghosts {
        let k: usize = ghost.get("data-waypoint").parse().unwrap();
        let joint = tree.joint_by_name(ghost.get("data-joint")).unwrap();
        let points: Vec<[f64; 3]> = ghost
            .get("data-points")
            .split(' ')
            .map(|p| {
                let c: Vec<f64> = p.split(',').map(|x| x.parse().unwrap()).collect();
                [c[0], c[1], c[2]]
            })
            .collect();
        assert!(k < 2, "{ghost:?}");
        assert!(close(points[0], origin(k, joint.parent), 1e-12), "{ghost:?}");
        assert!(close(*points.last().unwrap(), origin(k, joint.child), 1e-12), "{ghost:?}");
    }
    // The deepest link's trace along the straight motions, through each configuration's origin.
    let tip = tree.link_id("panda_grasptarget").unwrap();
    let traces: Vec<&Element> = elements.iter().filter(|e| e.class() == "trace").collect();
    assert_eq!(traces.len(), 3);
    let points: Vec<[f64; 3]> = traces[0]
        .get("data-points")
        .split(' ')
        .map(|p| {
            let c: Vec<f64> = p.split(',').map(|x| x.parse().unwrap()).collect();
            [c[0], c[1], c[2]]
        })
        .collect();
    assert_eq!((traces[0].get("data-link"), points.len()), ("panda_grasptarget", 2 * 16 + 1));
    for k in 0..3 {
        assert!(close(points[16 * k], origin(k, tip), 1e-12), "configuration {k}");
    }
    let halfway: Vec<f64> = path[1].iter().zip(&path[2]).map(|(a, b)| 0.5 * a + 0.5 * b).collect();
    let t = fk.link_poses(&halfway).unwrap()[tip.0].translation.vector;
    assert!(close(points[16 + 8], [t.x, t.y, t.z], 1e-12));
    let dots: Vec<&Element> = elements.iter().filter(|e| e.class() == "waypoint").collect();
    assert_eq!(dots.len(), 3 * 3);
    assert!(dots.iter().all(|d| close(point(d), origin(d.get("data-waypoint").parse().unwrap(), tip), 1e-12)));
    // Bad files: refused naming the file and the line, nothing written.
    let out = dir.join("out.svg");
    let target = out.to_str().unwrap();
    let good = joined(&path[0]);
    for (text, fault) in [
        (
            format!("{good}\n\n0,0,0,0,0,0\n"),
            "line 3: 6 values, but the robot has 7 degrees of freedom (panda_joint1, ",
        ),
        (
            format!("# x\n{good}\n0,0,0,NaN,0,0,0\n"),
            "line 3: the value of `panda_joint4` (q[3]) is NaN, not a finite number",
        ),
        (format!("{good}\n0,0,zero,0,0,0,0\n"), "line 2: `zero` is not a number"),
        ("# nothing\n".to_owned(), "no configuration (one a line, values comma-separated)"),
    ] {
        let bad = dir.join("bad.txt");
        std::fs::write(&bad, text).unwrap();
        let message = fails(&["draw", file, "--path", bad.to_str().unwrap(), "-o", target]);
        assert!(message.starts_with(&format!("error: {}: {fault}", bad.display())), "{message}");
    }
    let missing = dir.join("missing.txt");
    let message = fails(&["draw", file, "--path", missing.to_str().unwrap(), "-o", target]);
    assert!(message.starts_with(&format!("error: {}: cannot read: ", missing.display())), "{message}");
    assert_eq!(entries(&dir), ["bad.txt", "plan.txt"]);
    // A path is drawn instead of `--q`, not with it (clap's usage error, status 2).
    assert_eq!(run(&["draw", file, "--path", plan, "--q", "0,0,0,0,0,0,0"]).status.code(), Some(2));
    assert_eq!(run(&["draw", file, "--path", plan, "--degrees"]).status.code(), Some(2));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn links_whose_origins_coincide_share_one_label() {
    // The UR5's `ee_link` and `tool0` sit at one point, as do `base_link` and `base`: each pair
    // shares one label in every view, and neither has a label of its own. (In the view from
    // above, `shoulder_link` falls on the base's point too and joins its label.)
    let file = root().join("robots/ur5.urdf");
    let svg = ok(&["draw", file.to_str().unwrap(), "--skip-meshes", "--q", "0.3,-1.2,1.0,0.4,-0.7,2.0"]);
    let views = svg.matches("class=\"view-label\"").count();
    assert_eq!(views, 3);
    assert_eq!(svg.matches(">ee_link, tool0</text>").count(), views, "{svg}");
    assert_eq!(svg.matches(">base_link, base</text>").count(), 2, "{svg}");
    assert_eq!(svg.matches(">base_link, shoulder_link, base</text>").count(), 1, "{svg}");
    for alone in ["tool0", "ee_link", "base", "base_link"] {
        assert!(!svg.contains(&format!(">{alone}</text>")), "{alone} labelled alone");
    }
    // A link elsewhere keeps its own label.
    assert_eq!(svg.matches(">wrist_1_link</text>").count(), views);
}

/// The loops of a path's `d` as `draw` writes the collision geometry: `M x,y`, then `L x,y`,
/// `H x` or `V y` (absolute), each loop closed by `Z`.
fn loops(d: &str) -> Vec<Vec<(f64, f64)>> {
    let mut tokens: Vec<String> = Vec::new();
    for c in d.chars() {
        match c {
            'M' | 'L' | 'H' | 'V' | 'Z' => tokens.push(c.to_string()),
            ' ' | ',' => tokens.push(String::new()),
            _ => match tokens.last_mut() {
                Some(t) if !matches!(t.as_str(), "M" | "L" | "H" | "V" | "Z") => t.push(c),
                _ => tokens.push(c.to_string()),
            },
        }
    }
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let (mut command, mut numbers, mut at) = ("", Vec::new(), (0.0, 0.0));
    for token in tokens.iter().filter(|t| !t.is_empty()) {
        if let Ok(x) = token.parse::<f64>() {
            numbers.push(x);
        } else {
            command = token.as_str();
            numbers.clear();
            if command == "M" {
                out.push(Vec::new());
            }
            continue;
        }
        let point = match (command, numbers.as_slice()) {
            ("M" | "L", [x, y]) => Some((*x, *y)),
            ("H", [x]) => Some((*x, at.1)),
            ("V", [y]) => Some((at.0, *y)),
            ("M" | "L", [_]) => None,
            other => panic!("{other:?} in `{d}`"),
        };
        if let Some(p) = point {
            at = p;
            out.last_mut().unwrap().push(p);
            numbers.clear();
        }
    }
    out
}

/// Whether the region the loops fill (nonzero rule) holds the point `p`, or its edge passes
/// within `tolerance` of it.
fn holds(loops: &[Vec<(f64, f64)>], p: (f64, f64), tolerance: f64) -> bool {
    let mut winding = 0;
    for l in loops {
        for (k, &a) in l.iter().enumerate() {
            let b = l[(k + 1) % l.len()];
            // Near the edge from a to b.
            let (ab, ap) = ((b.0 - a.0, b.1 - a.1), (p.0 - a.0, p.1 - a.1));
            let t = ((ap.0 * ab.0 + ap.1 * ab.1) / (ab.0 * ab.0 + ab.1 * ab.1).max(f64::MIN_POSITIVE)).clamp(0.0, 1.0);
            if (ap.0 - t * ab.0).hypot(ap.1 - t * ab.1) <= tolerance {
                return true;
            }
            if (a.1 <= p.1) != (b.1 <= p.1) {
                let x = a.0 + (p.1 - a.1) / (b.1 - a.1) * (b.0 - a.0);
                if x > p.0 {
                    winding += if b.1 > a.1 { 1 } else { -1 };
                }
            }
        }
    }
    winding != 0
}

/// A collision element as a view draws it (`class="geometry"`).
struct Drawn<'a> {
    path: &'a Element,
    /// Its path's loops.
    loops: Vec<Vec<(f64, f64)>>,
    /// How far its points may lie outside the true projection: a mesh's grid cell's diagonal, and
    /// the printing's rounding.
    slack: f64,
}

fn geometry(elements: &[Element]) -> Vec<Drawn<'_>> {
    elements
        .iter()
        .filter(|e| e.class() == "geometry")
        .map(|path| {
            let cell = path.attributes.get("data-cell").map_or(0.0, |c| c.parse::<f64>().unwrap() * 2f64.sqrt());
            Drawn { path, loops: loops(path.get("d")), slack: cell + 1e-3 }
        })
        .collect()
}

/// Checks that every point of every geometry path lies within a sphere of its link as the view
/// draws it (the cover holds the geometry, so its projection is within the spheres' discs), that
/// every path comes before the first sphere of its view (drawn under them), and that each view
/// has one path per element. Returns the geometry's paths.
fn geometry_within_spheres<'a>(file: &str, elements: &'a [Element], elements_per_view: usize) -> Vec<Drawn<'a>> {
    let scale = elements[0].number("data-scale");
    let views: Vec<&Element> = elements.iter().filter(|e| e.name == "g" && e.class() == "view").collect();
    let drawn = geometry(elements);
    assert_eq!(drawn.len(), 3 * elements_per_view, "{file}");
    let spheres: Vec<&Element> = elements.iter().filter(|e| e.class() == "sphere").collect();
    assert!(!spheres.is_empty(), "{file}");
    for (view, v) in views.iter().enumerate() {
        let first_sphere = elements.iter().position(|e| e.class() == "sphere" && e.view == Some(view)).unwrap();
        let last_geometry = elements.iter().rposition(|e| e.class() == "geometry" && e.view == Some(view)).unwrap();
        assert!(last_geometry < first_sphere, "{file}: view {view}: geometry over the spheres");
        let coordinate = |name: &str| ["x", "y", "z"].iter().position(|c| *c == name).unwrap();
        let (u, w) = (coordinate(v.get("data-u")), coordinate(v.get("data-v")));
        let (ox, oy) = (v.number("data-ox"), v.number("data-oy"));
        let discs: Vec<(&str, (f64, f64), f64)> = spheres
            .iter()
            .filter(|s| s.view == Some(view))
            .map(|s| {
                let c = point(s);
                (s.get("data-link"), (ox + scale * c[u], oy - scale * c[w]), scale * s.number("data-r"))
            })
            .collect();
        for Drawn { path, loops, slack } in drawn.iter().filter(|d| d.path.view == Some(view)) {
            let link = path.get("data-link");
            assert!(!loops.is_empty() && loops.iter().all(|l| l.len() >= 3), "{file}: {path:?}");
            for &(x, y) in loops.iter().flatten() {
                let inside = discs.iter().any(|&(l, (cx, cy), r)| l == link && (x - cx).hypot(y - cy) <= r + slack);
                assert!(
                    inside,
                    "{file}: view {view}: ({x}, {y}) of {link}'s {} outside its spheres",
                    path.get("data-shape")
                );
            }
        }
    }
    drawn
}

#[test]
fn draw_shows_the_collision_meshes_under_the_spheres_that_cover_them() {
    let file = "robots/panda_meshes.urdf";
    let q = configuration(8);
    let svg = ok(&["draw", file, "--q", &joined(&q)]);
    // The Panda's eleven meshes (38 000 triangles) in three views keep the file small.
    assert!(svg.len() < 1_000_000, "{file}: {} bytes", svg.len());
    assert_eq!(svg, ok(&["draw", file, "--q", &joined(&q)]), "{file}: not deterministic");
    let elements = elements(&svg);
    let drawn = geometry_within_spheres(file, &elements, 11);
    assert!(drawn.iter().all(|d| d.path.get("data-shape") == "mesh" && d.path.attributes.contains_key("data-cell")));

    // Every vertex of every mesh, placed by the reference, falls in the region drawn for it: the
    // geometry is where the robot is, not merely inside some sphere.
    let mut tree = kinematics::load(root().join(file)).unwrap();
    let resolver = kinematics_meshes::Resolver::new(&root().join(file), &kinematics_meshes::Packages::new());
    kinematics_meshes::load_tree_meshes(&mut tree, &resolver).unwrap();
    let fk = ReferenceFk::new(tree);
    let poses = fk.link_poses(&q).unwrap();
    let scale = elements[0].number("data-scale");
    let views: Vec<&Element> = elements.iter().filter(|e| e.name == "g" && e.class() == "view").collect();
    let mut checked = 0;
    for Drawn { path, loops, slack } in &drawn {
        let view = path.view.unwrap();
        let (u, v) = [(0, 2), (1, 2), (0, 1)][view];
        let (ox, oy) = (views[view].number("data-ox"), views[view].number("data-oy"));
        let link = fk.tree().link_id(path.get("data-link")).unwrap();
        let element: usize = path.get("data-element").parse().unwrap();
        let collision = &fk.tree().link(link).collisions[element];
        let kinematics::model::collision::Shape::Mesh { loaded: Some(mesh), scale: s, .. } = &collision.shape else {
            panic!("{path:?} is not a mesh");
        };
        let placed = poses[link.0] * kinematics::runtime::fixed_isometry(&collision.origin);
        for &i in mesh.triangles().iter().flatten() {
            let m = mesh.vertices()[i as usize];
            let p = placed * nalgebra::Point3::new(m[0] * s[0], m[1] * s[1], m[2] * s[2]);
            let screen = (ox + scale * p[u], oy - scale * p[v]);
            assert!(holds(loops, screen, 1e-9), "{file}: {path:?} misses {screen:?}");
            checked += 1;
        }
        assert!(*slack > 0.7 && *slack < 0.72, "{slack}");
    }
    assert!(checked > 3 * 3 * 38_000, "{checked}");

    // Left out with `--skip-meshes`: no geometry, and the legend says so.
    let skipped = ok(&["draw", file, "--skip-meshes", "--q", &joined(&q)]);
    assert!(!skipped.contains("class=\"geometry\""));
    assert!(skipped.contains("11 collision meshes not drawn"), "{skipped}");
}

/// Draws the robot of `file` (primitives only) at a configuration, checks its geometry as
/// [`geometry_within_spheres`] does and each outline holds its element's origin placed by the
/// reference, and returns how many outlines each shape has.
fn primitives_where_the_reference_puts_them(file: &str) -> BTreeMap<String, usize> {
    let fk = ReferenceFk::new(kinematics::load(root().join(file)).unwrap());
    let q = configuration(fk.tree().dof());
    let svg = ok(&["draw", file, "--q", &joined(&q)]);
    let elements = elements(&svg);
    let count: usize = fk.tree().links().iter().map(|l| l.collisions.len()).sum();
    let drawn = geometry_within_spheres(file, &elements, count);
    let poses = fk.link_poses(&q).unwrap();
    let scale = elements[0].number("data-scale");
    let views: Vec<&Element> = elements.iter().filter(|e| e.name == "g" && e.class() == "view").collect();
    let mut shapes = BTreeMap::new();
    for Drawn { path, loops, .. } in &drawn {
        // One convex loop, around the element's origin.
        assert_eq!(loops.len(), 1, "{file}: {path:?}");
        assert!(!path.attributes.contains_key("data-cell"), "{file}: {path:?}");
        let view = path.view.unwrap();
        let (u, v) = [(0, 2), (1, 2), (0, 1)][view];
        let link = fk.tree().link_id(path.get("data-link")).unwrap();
        let collision = &fk.tree().link(link).collisions[path.get("data-element").parse::<usize>().unwrap()];
        assert_eq!(path.get("data-shape"), collision.shape.name(), "{file}");
        let centre = (poses[link.0] * kinematics::runtime::fixed_isometry(&collision.origin)).translation.vector;
        let screen =
            (views[view].number("data-ox") + scale * centre[u], views[view].number("data-oy") - scale * centre[v]);
        assert!(holds(loops, screen, 0.0), "{file}: {path:?} does not hold {screen:?}");
        *shapes.entry(collision.shape.name().to_owned()).or_default() += 1;
    }
    // Primitives are no meshes: `--skip-meshes` draws the same picture.
    assert_eq!(ok(&["draw", file, "--skip-meshes", "--q", &joined(&q)]), svg, "{file}");
    shapes
}

#[test]
fn draw_shows_primitive_collision_geometry_as_outlines_where_the_reference_puts_it() {
    let shapes = primitives_where_the_reference_puts_them("robots/ur5_primitives.urdf");
    let count = |name: &str| shapes.get(name).copied().unwrap_or(0);
    assert_eq!((count("box"), count("capsule"), count("cylinder")), (3, 3, 3 * 8), "{shapes:?}");
    // Every primitive, MJCF's ellipsoid too, placed by `pos`, `euler` and `fromto`.
    let dir = scratch("primitives");
    let file = dir.join("shapes.xml");
    std::fs::write(
        &file,
        r#"<mujoco model="shapes"><worldbody><body name="base">
          <geom type="box" size="0.1 0.05 0.03" pos="0 0 0.03"/>
          <body name="arm" pos="0 0 0.06"><joint name="j1" type="hinge" axis="0 0 1"/>
            <geom type="cylinder" size="0.03" fromto="0 0 0 0.3 0 0.1"/>
            <geom type="ellipsoid" size="0.05 0.08 0.03" pos="0.3 0 0.1" euler="0.3 0.4 0.5"/>
            <body name="tip" pos="0.3 0 0.1"><joint name="j2" type="hinge" axis="0 1 0"/>
              <geom type="capsule" size="0.02 0.1" pos="0.1 0 0" euler="0 1.2 0"/>
              <geom type="sphere" size="0.04" pos="0.25 0 0"/>
            </body></body></body></worldbody></mujoco>"#,
    )
    .unwrap();
    let shapes = primitives_where_the_reference_puts_them(file.to_str().unwrap());
    assert_eq!(shapes.values().collect::<Vec<_>>(), [&3; 5], "{shapes:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}
