//! URDF `<inertial>` (issue 61): a link's mass, centre-of-mass frame and tensor read as written,
//! with its line; a missing or malformed part refused naming the link and the line; a second
//! `<inertial>` refused; and every robot of `robots/` that carries inertials loading each link's
//! as its file writes it (read here a second way, straight from the XML).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::path::Path;

use kinematics_model::inertia::Inertial;
use kinematics_model::{Angle, FixedTransform, KinematicTree, parse_source};

/// A robot whose link `a` holds `inertial` on line 3 (a joint to `b` after it).
fn robot(inertial: &str) -> String {
    format!(
        "<robot name=\"r\">\n  <link name=\"a\">\n    {inertial}\n  </link>\n  <link name=\"b\"/>\n  \
         <joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>\n</robot>\n"
    )
}

fn load(text: &str) -> KinematicTree {
    parse_source("arm.urdf", text).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

/// `text` fails to load as `arm.urdf` with exactly `expected`.
#[track_caller]
fn check(text: &str, expected: &str) {
    match parse_source("arm.urdf", text) {
        Ok(_) => panic!("loaded, expected `{expected}`:\n{text}"),
        Err(e) => assert_eq!(e.to_string(), expected, "\n{text}"),
    }
}

const INERTIA: &str = r#"<inertia ixx="0.3" ixy="-0.01" ixz="0.02" iyy="0.4" iyz="-0.03" izz="0.5"/>"#;

#[test]
fn a_links_inertial_is_read_with_its_origin_and_line() {
    let tree = load(&robot(&format!(
        r#"<inertial><origin xyz="0.1 -0.2 0.3" rpy="0.5 -0.25 1.5"/><mass value=" 2.5 "/>{INERTIA}</inertial>"#
    )));
    let a = tree.link_by_name("a").unwrap();
    let expected = Inertial {
        mass: 2.5,
        origin: FixedTransform::from_xyz_rpy([0.1, -0.2, 0.3], [0.5, -0.25, 1.5].map(Angle::Radians)),
        inertia: [0.3, -0.01, 0.02, 0.4, -0.03, 0.5],
    };
    assert_eq!(a.inertial, Some(expected));
    assert_eq!(tree.inertial_line("a"), Some(3));
    // No <inertial>: no inertial, no line (a massless link).
    assert_eq!(tree.link_by_name("b").unwrap().inertial, None);
    assert_eq!(tree.inertial_line("b"), None);
    // URDF has no inertia from geometry.
    assert!(tree.inertia_from_geometry().is_empty());
}

#[test]
fn the_origin_defaults_to_the_links_frame() {
    for origin in ["", "<origin/>", r#"<origin xyz="0 0 0" rpy="0 0 0"/>"#] {
        let tree = load(&robot(&format!(r#"<inertial>{origin}<mass value="1"/>{INERTIA}</inertial>"#)));
        let inertial = tree.link_by_name("a").unwrap().inertial.clone().unwrap();
        assert!(inertial.origin.steps().is_empty(), "{origin}: {:?}", inertial.origin);
        assert_eq!(inertial.mass, 1.0);
    }
}

#[test]
fn values_are_taken_as_written_not_checked() {
    // A negative mass and a NaN load: the rigid-body rules are checked where dynamics are asked for.
    let tree = load(&robot(&format!(r#"<inertial><mass value="-1"/>{INERTIA}</inertial>"#)));
    let inertial = tree.link_by_name("a").unwrap().inertial.clone().unwrap();
    assert_eq!(inertial.mass, -1.0);
    assert!(inertial.fault(false).is_some());
    let tree = load(&robot(
        r#"<inertial><mass value="NaN"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="nan"/></inertial>"#,
    ));
    let inertial = tree.link_by_name("a").unwrap().inertial.clone().unwrap();
    assert!(inertial.mass.is_nan() && inertial.inertia[5].is_nan());
}

#[test]
fn a_missing_or_malformed_part_is_refused_naming_the_link_and_the_line() {
    let at = "arm.urdf: link `a` (line 3): ";
    check(
        &robot(&format!("<inertial>{INERTIA}</inertial>")),
        &format!("{at}<inertial> needs a <mass value=\"...\"> element"),
    );
    check(&robot(&format!("<inertial><mass/>{INERTIA}</inertial>")), &format!("{at}<mass> needs a `value` attribute"));
    check(
        &robot(&format!(r#"<inertial><mass value="heavy"/>{INERTIA}</inertial>"#)),
        &format!("{at}<mass value=\"heavy\"> is not a number"),
    );
    check(
        &robot(r#"<inertial><mass value="1"/></inertial>"#),
        &format!("{at}<inertial> needs an <inertia ixx ixy ixz iyy iyz izz> element"),
    );
    // urdfdom requires all six entries.
    check(
        &robot(r#"<inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0"/></inertial>"#),
        &format!("{at}<inertia> needs a `izz` attribute"),
    );
    check(
        &robot(r#"<inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1 2"/></inertial>"#),
        &format!("{at}<inertia izz=\"1 2\"> is not a number"),
    );
    check(
        &robot(&format!(r#"<inertial><origin xyz="0 0"/><mass value="1"/>{INERTIA}</inertial>"#)),
        &format!("{at}<origin xyz=\"0 0\"> needs 3 numbers, found 2"),
    );
    // URDF 1.1's quaternion, refused as a collision's or a joint's is.
    check(
        &robot(&format!(r#"<inertial><origin quat_xyzw="0 0 0 1"/><mass value="1"/>{INERTIA}</inertial>"#)),
        &format!("{at}<origin quat_xyzw> (URDF 1.1) is not read: write the rotation as `rpy`"),
    );
    // One of each part.
    check(
        &robot(&format!(r#"<inertial><mass value="1"/><mass value="2"/>{INERTIA}</inertial>"#)),
        &format!("{at}more than one <mass>"),
    );
}

#[test]
fn a_second_inertial_is_refused_at_its_line() {
    let one = format!(r#"<inertial><mass value="1"/>{INERTIA}</inertial>"#);
    check(&robot(&format!("{one}\n    {one}")), "arm.urdf: link `a` (line 4): more than one <inertial>");
}

/// Every robot of `robots/` with `<inertial>` elements, and how many.
const WITH_INERTIALS: [(&str, usize); 7] = [
    ("humanoid.urdf", 51),
    ("panda.urdf", 11),
    ("panda_spherized.urdf", 13),
    ("ur5.urdf", 7),
    ("ur5_primitives.urdf", 7),
    ("ur5_ros.urdf", 7),
    ("ur5_spherized.urdf", 17),
];

/// The robots of `robots/` whose text holds `<inertial`.
fn robots_with_inertials() -> Vec<String> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots");
    let mut found: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "urdf" || e == "xml"))
        .filter(|p| std::fs::read_to_string(p).unwrap().contains("<inertial"))
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    found.sort();
    found
}

/// The first child element `<tag>` of `node`.
fn child<'a, 'i>(node: roxmltree::Node<'a, 'i>, tag: &str) -> Option<roxmltree::Node<'a, 'i>> {
    node.children().find(|c| c.has_tag_name(tag))
}

/// The numbers of attribute `name`, zeros when it is not written.
fn numbers(node: roxmltree::Node<'_, '_>, name: &str) -> Vec<f64> {
    node.attribute(name).map_or(vec![0.0; 3], |v| v.split_whitespace().map(|w| w.parse().unwrap()).collect())
}

/// Each link's `<inertial>` read straight from the XML, by another way than the reader's.
fn written_inertials(text: &str) -> Vec<(String, usize, Inertial)> {
    let doc = roxmltree::Document::parse(text).unwrap();
    let mut out = Vec::new();
    for link in doc.root_element().children().filter(|c| c.has_tag_name("link")) {
        let Some(inertial) = child(link, "inertial") else { continue };
        let (xyz, rpy) = match child(inertial, "origin") {
            Some(origin) => (numbers(origin, "xyz"), numbers(origin, "rpy")),
            None => (vec![0.0; 3], vec![0.0; 3]),
        };
        let mass = child(inertial, "mass").unwrap().attribute("value").unwrap().trim().parse().unwrap();
        let tensor = child(inertial, "inertia").unwrap();
        let inertia = ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"].map(|a| tensor.attribute(a).unwrap().parse().unwrap());
        let origin =
            FixedTransform::from_xyz_rpy([xyz[0], xyz[1], xyz[2]], [rpy[0], rpy[1], rpy[2]].map(Angle::Radians));
        let line = doc.text_pos_at(inertial.range().start).row as usize;
        out.push((link.attribute("name").unwrap().to_owned(), line, Inertial { mass, origin, inertia }));
    }
    out
}

#[test]
fn every_robot_with_inertials_loads_each_as_written() {
    let listed: Vec<&str> = WITH_INERTIALS.iter().map(|(file, _)| *file).collect();
    assert_eq!(robots_with_inertials(), listed, "the robots carrying <inertial> changed: update the list");
    for (file, count) in WITH_INERTIALS {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots").join(file);
        let text = std::fs::read_to_string(&path).unwrap();
        let tree = parse_source(file, &text).unwrap_or_else(|e| panic!("{e}"));
        let written = written_inertials(&text);
        assert_eq!(written.len(), count, "{file}");
        for (link, line, inertial) in &written {
            let got = tree.link_by_name(link).unwrap_or_else(|| panic!("{file}: no link `{link}`"));
            assert_eq!(got.inertial.as_ref(), Some(inertial), "{file}: `{link}`");
            assert_eq!(tree.inertial_line(link), Some(*line), "{file}: `{link}`");
        }
        // The other links have none.
        let with: usize = tree.links().iter().filter(|l| l.inertial.is_some()).count();
        assert_eq!(with, count, "{file}");
    }
}

#[test]
fn spot_checks_against_the_files() {
    let load_robot = |file: &str| {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots").join(file);
        parse_source(file, &std::fs::read_to_string(path).unwrap()).unwrap()
    };
    // ur5.urdf, lines 118-122: upper_arm_link's mass 8.393 at z 0.28, ixx = iyy = 0.22689067591, izz 0.0151074.
    let ur5 = load_robot("ur5.urdf");
    let upper = ur5.link_by_name("upper_arm_link").unwrap().inertial.clone().unwrap();
    assert_eq!(upper.mass, 8.393);
    assert_eq!(upper.origin, FixedTransform::identity().translate([0.0, 0.0, 0.28]));
    assert_eq!(upper.inertia, [0.22689067591, 0.0, 0.0, 0.22689067591, 0.0, 0.0151074]);
    assert_eq!(ur5.inertial_line("upper_arm_link"), Some(118));
    assert_eq!(ur5.link_by_name("tool0").unwrap().inertial, None);
    // ur5_spherized.urdf, lines 257-261: the gripper base's products of inertia, written in E notation.
    let spherized = load_robot("ur5_spherized.urdf");
    let base = spherized.link_by_name("robotiq_85_base_link").unwrap().inertial.clone().unwrap();
    assert_eq!(base.mass, 0.30915);
    assert_eq!(base.inertia, [0.00028972, -5.7879E-10, -1.8543E-06, 0.00030737, 1.682E-12, 0.00019914]);
    assert_eq!(base.origin, FixedTransform::identity().translate([0.00021987, -2.3546E-10, 0.030163]));
    // panda_spherized.urdf, lines 4-8: the base's 2.9 kg at z 0.05.
    let panda = load_robot("panda_spherized.urdf");
    let root = panda.link(panda.root());
    assert_eq!(panda.inertial_line(&root.name), Some(4));
    let inertial = root.inertial.clone().unwrap();
    assert_eq!((inertial.mass, inertial.inertia), (2.9, [0.1, 0.0, 0.0, 0.1, 0.0, 0.1]));
    // humanoid.urdf, lines 52-56: the NAO's torso; lines 258-261: a placeholder with no <origin>.
    let humanoid = load_robot("humanoid.urdf");
    let torso = humanoid.link_by_name("torso").unwrap().inertial.clone().unwrap();
    assert_eq!(torso.mass, 1.04956);
    assert_eq!(torso.origin, FixedTransform::identity().translate([-0.00413, 0.0, 0.04342]));
    assert_eq!(torso.inertia, [0.00308361, 1.43116e-05, -3.30211e-05, 0.0028835, -2.70793e-05, 0.0015924]);
    assert_eq!(humanoid.inertial_line("torso"), Some(52));
    let gripper = humanoid.link_by_name("l_gripper").unwrap().inertial.clone().unwrap();
    assert_eq!((gripper.mass, gripper.inertia), (2e-06, [1.1e-09, 0.0, 0.0, 1.1e-09, 0.0, 1.1e-09]));
    assert_eq!(gripper.origin, FixedTransform::identity());
    assert_eq!(humanoid.link_by_name("l_sole").unwrap().inertial, None);
    // Every published tensor keeps a rigid body's rules, the triangle inequality included.
    assert_eq!(humanoid.inertia_refusals(false), vec![]);
}
