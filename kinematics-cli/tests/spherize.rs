//! `kinematics spherize` run as a user runs it: the URDF it writes reads back as the same robot
//! with spheres for collision geometry (the compiler's cover, to the bit), everything but the
//! collision elements and the header comment is the input byte for byte, and bad input (MJCF, a
//! missing mesh, `--spheres 0`) is refused with the file, the element and the fault named.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::path::Path;

use kinematics::KinematicTree;
use kinematics::model::collision::{Cover, LinkSphere, Meshes, Shape, link_spheres};
use kinematics::model::parse_source;

mod common;
use common::{fails, ok, root, scratch};

/// `text` written to `name` in the test's scratch directory; the path, as an argument.
fn write(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_owned()
}

/// `spherize` of `text` (written to a scratch file) with `args`.
fn spherize_text(test: &str, text: &str, args: &[&str]) -> String {
    let dir = scratch(test);
    let file = write(&dir, "robot.urdf", text);
    let mut all = vec!["spherize", file.as_str()];
    all.extend_from_slice(args);
    ok(&all)
}

/// The text without its `<collision>` elements, each with the spaces before it on its line and,
/// when it began its line, that line break (the part `spherize` replaces).
fn without_collisions(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(start) = rest.find("<collision") {
        let end = start + rest[start..].find("</collision>").unwrap() + "</collision>".len();
        let before = rest[..start].trim_end_matches([' ', '\t']);
        let before = before.strip_suffix('\n').map_or(before, |b| b.strip_suffix('\r').unwrap_or(b));
        out += before;
        rest = &rest[end..];
    }
    out + rest
}

/// The text without the header comment `spherize` writes, and the line break it added: after the
/// XML declaration, or at the top when there is none.
fn without_header(text: &str) -> String {
    let start = text.find("<!-- Written by `kinematics spherize`").expect("a header comment");
    let end = start + text[start..].find("-->").unwrap() + "-->".len();
    let newline = if text.contains("\r\n") { "\r\n" } else { "\n" };
    if start == 0 {
        return text[end..].strip_prefix(newline).unwrap().to_owned();
    }
    let before = text[..start].strip_suffix(newline).unwrap();
    assert!(before.ends_with("?>"), "the header follows the declaration: {text}");
    format!("{before}{}", &text[end..])
}

/// Each link's spheres as the tree reads them from its `<collision>` elements (all spheres).
fn written_spheres(tree: &KinematicTree) -> Vec<LinkSphere> {
    let mut out = Vec::new();
    for (i, link) in tree.links().iter().enumerate() {
        for c in &link.collisions {
            let Shape::Sphere { radius } = c.shape else { panic!("link `{}`: a {}", link.name, c.shape.name()) };
            let center = c.origin.apply([0.0; 3]);
            out.push(LinkSphere {
                link: kinematics::model::LinkId(i),
                sphere: kinematics::model::collision::Sphere { center, radius },
            });
        }
    }
    out
}

/// The most spheres any one link has.
fn most_per_link(spheres: &[LinkSphere]) -> usize {
    let mut counts = std::collections::BTreeMap::new();
    for s in spheres {
        *counts.entry(s.link).or_insert(0) += 1;
    }
    counts.into_values().max().unwrap_or(0)
}

fn link_names(tree: &KinematicTree) -> Vec<&str> {
    tree.links().iter().map(|l| l.name.as_str()).collect()
}

/// The robot the spherized text describes has the original's links and joints (names, kinds,
/// origins, axes, limits, mimics: the whole `Joint`).
fn same_kinematics(original: &KinematicTree, spherized: &KinematicTree) {
    assert_eq!(link_names(original), link_names(spherized));
    assert_eq!(original.joints(), spherized.joints());
    assert_eq!(original.name(), spherized.name());
}

#[test]
fn ur5_primitives_becomes_the_compilers_four_spheres_per_link() {
    let file = "robots/ur5_primitives.urdf";
    let input = std::fs::read_to_string(root().join(file)).unwrap();
    let original = parse_source(file, &input).unwrap();
    let text = ok(&["spherize", file, "--spheres", "4"]);
    let spherized = parse_source("out.urdf", &text).unwrap();
    same_kinematics(&original, &spherized);

    let written = written_spheres(&spherized);
    let cover = link_spheres(&original, &Cover::spheres(4), Meshes::Read).unwrap();
    assert_eq!(written.len(), cover.len());
    assert!(most_per_link(&written) <= 4, "{}", most_per_link(&written));
    for (w, c) in written.iter().zip(&cover) {
        assert_eq!(w.link, c.link);
        let off = (0..3).map(|i| (w.sphere.center[i] - c.sphere.center[i]).abs()).fold(0.0, f64::max);
        assert!(off <= 1e-12 && (w.sphere.radius - c.sphere.radius).abs() <= 1e-12, "{w:?} against {c:?}");
    }
    // A link of spheres alone keeps them as written: the default cover of the spherized file is
    // its spheres, to the bit.
    assert_eq!(link_spheres(&spherized, &Cover::default(), Meshes::Read).unwrap(), written);
    assert!(text.contains(&format!("{} spheres on 8 links (4 spheres per link)", written.len())), "{text}");
    assert_eq!(without_collisions(&without_header(&text)), without_collisions(&input));
}

#[test]
fn panda_meshes_by_default_with_an_output_file() {
    let file = "robots/panda_meshes.urdf";
    let input = std::fs::read_to_string(root().join(file)).unwrap();
    let dir = scratch("panda");
    let out = dir.join("panda_spherized.urdf");
    let stdout = ok(&["spherize", file, "-o", out.to_str().unwrap()]);
    assert!(stdout.is_empty(), "{stdout}");
    let text = std::fs::read_to_string(&out).unwrap();
    let spherized = parse_source("out.urdf", &text).unwrap();
    same_kinematics(&parse_source(file, &input).unwrap(), &spherized);
    let written = written_spheres(&spherized);
    assert!(!written.is_empty() && most_per_link(&written) <= 10, "{}", most_per_link(&written));
    assert!(!text.contains("<mesh"), "every mesh replaced");
    assert!(text.contains("mesh triangles lies inside the link's spheres"), "{text}");
    // The joints as written, and everything else but the collision elements.
    let joints = |t: &str| {
        t.match_indices("<joint").map(|(i, _)| t[i..].split_once("</joint>").unwrap().0.to_owned()).collect::<Vec<_>>()
    };
    assert_eq!(joints(&text), joints(&input));
    assert_eq!(without_collisions(&without_header(&text)), without_collisions(&input));
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1, "only the output file is left");
}

#[test]
fn mjcf_is_refused_naming_spherize_and_urdf() {
    let message = fails(&["spherize", "robots/walker.xml"]);
    assert!(message.contains("robots/walker.xml") && message.contains("`spherize`"), "{message}");
    assert!(message.contains("URDF") && message.contains("MJCF"), "{message}");
    let message = fails(&["spherize", "robots/ur5.toml"]);
    assert!(message.contains("URDF") && message.contains("DH table"), "{message}");
}

#[test]
fn a_missing_mesh_is_refused_naming_the_link_and_the_uri() {
    let dir = scratch("missing-mesh");
    let urdf = r#"<robot name="r">
  <link name="base"/>
  <link name="arm">
    <collision>
      <geometry><mesh filename="package://nowhere/x.stl"/></geometry>
    </collision>
  </link>
  <joint name="j" type="continuous"><parent link="base"/><child link="arm"/></joint>
</robot>
"#;
    let file = write(&dir, "robot.urdf", urdf);
    let out = dir.join("out.urdf");
    let message = fails(&["spherize", &file, "-o", out.to_str().unwrap()]);
    assert!(message.contains("`arm`") && message.contains("package://nowhere/x.stl"), "{message}");
    assert!(!out.exists(), "no output is left behind");
    // Left out, the mesh is kept as written: nothing else to cover.
    let text = ok(&["spherize", &file, "--skip-meshes"]);
    assert_eq!(without_header(&text), urdf);
    assert!(text.contains("0 spheres on 0 links") && text.contains("1 mesh <collision> element kept"), "{text}");
}

#[test]
fn zero_spheres_is_refused() {
    let message = fails(&["spherize", "robots/ur5_primitives.urdf", "--spheres", "0"]);
    assert!(message.contains("`--spheres`"), "{message}");
}

/// A link with comments, a visual, an inertial between two collision elements, a self-closing
/// link, a material and a joint.
const SMALL: &str = r#"<?xml version="1.0"?>
<!-- A small robot. -->
<robot name="small">
  <material name="grey"><color rgba="0.5 0.5 0.5 1"/></material>
  <link name="base"/>
  <link name="arm">
    <!-- The arm's visual. -->
    <visual>
      <origin xyz="0 0 0.1" rpy="0 0 0"/>
      <geometry><box size="0.1 0.1 0.2"/></geometry>
      <material name="grey"/>
    </visual>
    <collision>
      <origin xyz="0 0 0.1" rpy="0 0 0"/>
      <geometry>
        <box size="0.1 0.1 0.2"/>
      </geometry>
    </collision>
    <inertial>
      <mass value="1.5"/>
      <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.001"/>
    </inertial>
    <collision>
      <!-- The tool. -->
      <origin xyz="0 0 0.25" rpy="1.5707963267948966 0 0"/>
      <geometry>
        <cylinder radius="0.03" length="0.1"/>
      </geometry>
    </collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/>
    <child link="arm"/>
    <origin xyz="0 0 0.3" rpy="0 0 0"/>
    <axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="1"/>
  </joint>
</robot>
"#;

#[test]
fn everything_but_the_collisions_is_kept_byte_for_byte() {
    let text = spherize_text("small", SMALL, &["--spheres", "3"]);
    assert_eq!(without_collisions(&without_header(&text)), without_collisions(SMALL));
    assert!(text.starts_with("<?xml version=\"1.0\"?>\n<!-- Written by `kinematics spherize` from "), "{text}");
    // Three spheres where the first collision element was, indented like it, before the inertial.
    let first = text.find("    <collision name=\"sphere_0\">\n      <origin xyz=\"").unwrap();
    assert!(text.find("<visual>").unwrap() < first && first < text.find("<inertial>").unwrap(), "{text}");
    assert!(text.contains("      <geometry>\n        <sphere radius=\""), "{text}");
    assert_eq!(text.matches("<collision").count(), 3, "{text}");
    assert!(!text.contains("The tool."), "a comment inside a collision element goes with it");
    let tree = parse_source("out.urdf", &text).unwrap();
    same_kinematics(&parse_source("in.urdf", SMALL).unwrap(), &tree);
    let cover = link_spheres(&parse_source("in.urdf", SMALL).unwrap(), &Cover::spheres(3), Meshes::Read).unwrap();
    assert_eq!(written_spheres(&tree), cover, "the spheres round-trip to the bit");
}

#[test]
fn line_breaks_tabs_and_one_line_elements_are_followed() {
    // Windows line breaks: every line break written is one too.
    let crlf = SMALL.replace('\n', "\r\n");
    let text = spherize_text("crlf", &crlf, &[]);
    assert_eq!(without_collisions(&without_header(&text)), without_collisions(&crlf));
    assert_eq!(text.matches('\n').count(), text.matches("\r\n").count(), "{text:?}");
    // Tabs: the spheres indented by tabs.
    let tabs = SMALL.replace("  ", "\t");
    let text = spherize_text("tabs", &tabs, &["--spheres", "2"]);
    assert_eq!(without_collisions(&without_header(&text)), without_collisions(&tabs));
    assert!(text.contains("\t\t<collision name=\"sphere_1\">\n\t\t\t<origin"), "{text}");
    // A link on one line, no declaration: spheres on its line, the header on top.
    let one_line = concat!(
        "<robot name=\"r\"><link name=\"a\">",
        "<collision><geometry><box size=\"1 1 1\"/></geometry></collision>",
        "</link></robot>\n"
    );
    let text = spherize_text("one-line", one_line, &["--spheres", "2"]);
    assert!(text.starts_with("<!-- Written by"), "{text}");
    assert_eq!(without_collisions(&without_header(&text)), without_collisions(one_line));
    assert!(text.contains("<robot name=\"r\"><link name=\"a\"><collision name=\"sphere_0\"><origin xyz=\""), "{text}");
    assert!(text.contains("\"/></geometry></collision><collision name=\"sphere_1\"><origin xyz=\""), "{text}");
    assert!(text.ends_with("\"/></geometry></collision></link></robot>\n"), "{text}");
    assert_eq!(parse_source("out.urdf", &text).unwrap().link(kinematics::model::LinkId(0)).collisions.len(), 2);
}

#[test]
fn skip_meshes_keeps_mesh_elements_and_replaces_the_rest() {
    let urdf = r#"<robot name="r">
  <link name="a">
    <collision>
      <geometry><mesh filename="package://nowhere/x.stl"/></geometry>
    </collision>
    <collision>
      <origin xyz="0 0 0.5"/>
      <geometry><sphere radius="0.2"/></geometry>
    </collision>
  </link>
</robot>
"#;
    let text = spherize_text("skip", urdf, &["--skip-meshes"]);
    assert_eq!(without_collisions(&without_header(&text)), without_collisions(urdf));
    // The mesh as written, then its neighbour's sphere (kept as the cover keeps a lone sphere).
    let kept = concat!(
        "      <geometry><mesh filename=\"package://nowhere/x.stl\"/></geometry>\n",
        "    </collision>\n",
        "    <collision name=\"sphere_0\">\n",
        "      <origin xyz=\"0 0 0.5\" rpy=\"0 0 0\"/>\n",
        "      <geometry>\n",
        "        <sphere radius=\"0.2\"/>\n",
        "      </geometry>\n",
        "    </collision>\n",
        "  </link>\n",
    );
    assert!(text.contains(kept), "{text}");
    assert!(
        text.contains("1 sphere on 1 link")
            && text.contains("1 mesh <collision> element kept as written")
            && text.contains(
                "Links whose geometry was spheres alone keep them as written, however many (the cover's rule): 1."
            ),
        "{text}"
    );
}
