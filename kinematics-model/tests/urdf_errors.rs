//! Every fault class of the URDF reader gives one message naming the file, the element (joint or
//! link), the line and the fault (issue 13: urdf-rs said `custom: Wrong vector element count,
//! expected 3 found 0` with no joint and no line, "No elements found" for a truncated file, ignored
//! a second `<robot>` and gave a revolute joint without `<limit>` the limits [0, 0]).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_model::{Elementary, LoadErrorKind, parse_source};

/// A two-link robot whose one joint has `joint` as its body; the joint starts on line 3.
fn robot(joint: &str) -> String {
    format!(
        "<robot name=\"r\">\n  <link name=\"a\"/> <link name=\"b\"/>\n  <joint name=\"elbow\" type=\"revolute\">\n{joint}\n  </joint>\n</robot>\n"
    )
}

const LINKS: &str = "    <parent link=\"a\"/> <child link=\"b\"/>";
const LIMIT: &str = "    <limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>";

/// A joint body: the links, the limit, then `extra` on line 6.
fn joint_with(extra: &str) -> String {
    robot(&format!("{LINKS}\n{LIMIT}\n    {extra}"))
}

/// `text` fails to load as `arm.urdf` with exactly `expected`.
#[track_caller]
fn check(text: &str, expected: &str) {
    match parse_source("arm.urdf", text) {
        Ok(_) => panic!("loaded, expected `{expected}`:\n{text}"),
        Err(e) => assert_eq!(e.to_string(), expected, "\n{text}"),
    }
}

#[test]
fn the_template_loads() {
    let tree = parse_source("arm.urdf", &joint_with("<origin xyz=\"1 2 3\" rpy=\"0 0 0.5\"/>")).unwrap();
    assert_eq!(tree.dof(), 1);
}

#[test]
fn vectors_need_three_numbers() {
    check(
        &joint_with("<origin xyz=\"1 2\"/>"),
        "arm.urdf: joint `elbow` (line 6): <origin xyz=\"1 2\"> needs 3 numbers, found 2",
    );
    check(
        &joint_with("<origin xyz=\"\"/>"),
        "arm.urdf: joint `elbow` (line 6): <origin xyz=\"\"> needs 3 numbers, found 0",
    );
    check(
        &joint_with("<origin xyz=\"1 2 3 4\"/>"),
        "arm.urdf: joint `elbow` (line 6): <origin xyz=\"1 2 3 4\"> needs 3 numbers, found 4",
    );
    check(
        &joint_with("<origin rpy=\"0 0\"/>"),
        "arm.urdf: joint `elbow` (line 6): <origin rpy=\"0 0\"> needs 3 numbers, found 2",
    );
    check(
        &joint_with("<origin xyz=\"0 0 0\" rpy=\"0 0 0 0\"/>"),
        "arm.urdf: joint `elbow` (line 6): <origin rpy=\"0 0 0 0\"> needs 3 numbers, found 4",
    );
    check(
        &joint_with("<axis xyz=\"0 1\"/>"),
        "arm.urdf: joint `elbow` (line 6): <axis xyz=\"0 1\"> needs 3 numbers, found 2",
    );
}

#[test]
fn numbers_must_be_numbers() {
    check(
        &joint_with("<origin xyz=\"1 a 2\"/>"),
        "arm.urdf: joint `elbow` (line 6): <origin xyz=\"1 a 2\">: `a` is not a number",
    );
    check(
        &joint_with("<origin rpy=\"1.0.0 0 0\"/>"),
        "arm.urdf: joint `elbow` (line 6): <origin rpy=\"1.0.0 0 0\">: `1.0.0` is not a number",
    );
    check(
        &joint_with("<axis xyz=\"0 0 1,\"/>"),
        "arm.urdf: joint `elbow` (line 6): <axis xyz=\"0 0 1,\">: `1,` is not a number",
    );
    check(
        &robot(&format!("{LINKS}\n    <limit lower=\"-pi\" upper=\"1\" effort=\"1\" velocity=\"1\"/>")),
        "arm.urdf: joint `elbow` (line 5): <limit lower=\"-pi\"> is not a number",
    );
    check(
        &robot(&format!("{LINKS}\n    <limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"\"/>")),
        "arm.urdf: joint `elbow` (line 5): <limit velocity=\"\"> is not a number",
    );
    check(
        &joint_with("<mimic joint=\"x\" multiplier=\"two\"/>"),
        "arm.urdf: joint `elbow` (line 6): <mimic multiplier=\"two\"> is not a number",
    );
}

#[test]
fn numbers_are_trimmed_and_non_finite_ones_reach_validation() {
    let tree = parse_source("arm.urdf", &joint_with("<origin xyz=\" 1  2\t3 \" rpy=\"0 0 +.5\"/>")).unwrap();
    let steps = tree.joint_by_name("elbow").unwrap().origin.steps().to_vec();
    assert_eq!(steps[0], Elementary::Translation([1.0, 2.0, 3.0]), "{steps:?}");
    check(&joint_with("<origin xyz=\"inf 0 0\"/>"), "arm.urdf: joint `elbow`: origin is not a finite number");
    check(&joint_with("<axis xyz=\"0 0 NaN\"/>"), "arm.urdf: joint `elbow`: axis is not a finite number");
}

#[test]
fn moving_joints_need_limits() {
    check(
        &robot(LINKS),
        "arm.urdf: joint `elbow` (line 3): a revolute joint needs a <limit> element (with `effort` and `velocity`)",
    );
    check(
        &robot(LINKS).replace("revolute", "prismatic"),
        "arm.urdf: joint `elbow` (line 3): a prismatic joint needs a <limit> element (with `effort` and `velocity`)",
    );
    check(
        &robot(&format!("{LINKS}\n    <limit lower=\"-1\" upper=\"1\" velocity=\"1\"/>")),
        "arm.urdf: joint `elbow` (line 5): <limit> needs a `effort` attribute",
    );
    check(
        &robot(&format!("{LINKS}\n    <limit lower=\"-1\" upper=\"1\" effort=\"1\"/>")),
        "arm.urdf: joint `elbow` (line 5): <limit> needs a `velocity` attribute",
    );
    // A continuous joint's <limit> is optional, but when written it is read by the same rules.
    assert!(parse_source("arm.urdf", &robot(LINKS).replace("revolute", "continuous")).is_ok());
    check(
        &robot(&format!("{LINKS}\n    <limit effort=\"1\"/>")).replace("revolute", "continuous"),
        "arm.urdf: joint `elbow` (line 5): <limit> needs a `velocity` attribute",
    );
}

#[test]
fn omitted_lower_and_upper_are_zero() {
    let tree =
        parse_source("arm.urdf", &robot(&format!("{LINKS}\n    <limit upper=\"2\" effort=\"1\" velocity=\"1\"/>")))
            .unwrap();
    let limits = tree.joint_by_name("elbow").unwrap().limits.unwrap();
    assert_eq!((limits.lower, limits.upper), (0.0, 2.0));
}

#[test]
fn joints_need_name_type_parent_and_child() {
    check(
        &robot(&format!("{LINKS}\n{LIMIT}")).replace("name=\"elbow\" ", ""),
        "arm.urdf: line 3: <joint> needs a `name` attribute",
    );
    check(
        &robot(&format!("{LINKS}\n{LIMIT}")).replace(" type=\"revolute\"", ""),
        "arm.urdf: joint `elbow` (line 3): <joint> needs a `type` attribute",
    );
    check(
        &robot(&format!("    <child link=\"b\"/>\n{LIMIT}")),
        "arm.urdf: joint `elbow` (line 3): needs a <parent link=\"...\"> element",
    );
    check(
        &robot(&format!("    <parent link=\"a\"/>\n{LIMIT}")),
        "arm.urdf: joint `elbow` (line 3): needs a <child link=\"...\"> element",
    );
    check(
        &robot(&format!("    <parent name=\"a\"/> <child link=\"b\"/>\n{LIMIT}")),
        "arm.urdf: joint `elbow` (line 4): <parent> needs a `link` attribute",
    );
    check(
        &joint_with("<mimic multiplier=\"2\"/>"),
        "arm.urdf: joint `elbow` (line 6): <mimic> needs a `joint` attribute",
    );
}

#[test]
fn unknown_joint_types_are_refused() {
    for kind in ["hinge", "Revolute", "", "ball"] {
        check(
            &robot(&format!("{LINKS}\n{LIMIT}")).replace("\"revolute\"", &format!("\"{kind}\"")),
            &format!(
                "arm.urdf: joint `elbow` (line 3): unknown joint type `{kind}` (expected revolute, continuous, prismatic, fixed, floating or planar)"
            ),
        );
    }
}

#[test]
fn an_element_given_twice_is_refused() {
    check(
        &joint_with("<origin xyz=\"1 0 0\"/> <origin xyz=\"2 0 0\"/>"),
        "arm.urdf: joint `elbow` (line 6): more than one <origin>",
    );
    check(&joint_with("<parent link=\"b\"/>"), "arm.urdf: joint `elbow` (line 6): more than one <parent>");
    check(
        &joint_with("<limit effort=\"1\" velocity=\"1\"/>"),
        "arm.urdf: joint `elbow` (line 6): more than one <limit>",
    );
}

#[test]
fn links_and_the_robot_need_names() {
    check("<robot name=\"r\">\n<link/>\n</robot>", "arm.urdf: line 2: <link> needs a `name` attribute");
    check("<robot>\n<link name=\"a\"/>\n</robot>", "arm.urdf: line 1: <robot> needs a `name` attribute");
}

#[test]
fn the_root_must_be_robot() {
    check(
        "<?xml version=\"1.0\"?>\n<model name=\"r\"><link name=\"a\"/></model>",
        "arm.urdf: line 2: the root element is <model>, not <robot>",
    );
    check("<sdf/>", "arm.urdf: line 1: the root element is <sdf>, not <robot>");
    check("", "arm.urdf: the file is empty");
    check(" \n", "arm.urdf: the file is empty");
    check("<!-- nothing -->\n", "arm.urdf: line 1: no root element (truncated?)");
}

#[test]
fn malformed_xml_gives_the_line() {
    let good = joint_with("<origin xyz=\"1 2 3\"/>");
    // Truncated: the file ends inside the robot, inside a tag, inside an attribute.
    let cut = &good[..good.find("</joint>").unwrap()];
    check(cut, "arm.urdf: line 7: the file ends before the root element is closed (truncated?)");
    let cut = &good[..good.find("<origin").unwrap() + 4];
    check(cut, "arm.urdf: line 6: the file ends before the root element is closed (truncated?)");
    let cut = &good[..good.find("xyz=\"1").unwrap() + 6];
    check(cut, "arm.urdf: line 6: the file ends in the middle of a tag (truncated?)");
    check("<?xml version=\"1.0\"?>\n<robot name=\"r\"", "arm.urdf: line 2: no root element (truncated?)");
    // Two roots: a second <robot> is an error, not ignored.
    check(
        &format!("{good}<robot name=\"other\"/>\n"),
        "arm.urdf: line 9: a second root element: a URDF file holds one <robot>",
    );
    check(
        "<robot name=\"r\"><link name=\"a\"/></robot>\n<robot name=\"s\"><link name=\"b\"/></robot>",
        "arm.urdf: line 2: a second root element: a URDF file holds one <robot>",
    );
    check(
        "<robot name=\"r\"/>\n\n  <link name=\"b\"/>",
        "arm.urdf: line 3: a second root element: a URDF file holds one <robot>",
    );
    check("<robot name=\"r\"/>\ntext", "arm.urdf: line 2: unknown token");
    // A bad attribute, a mismatched close tag.
    check("<robot name=\"r\">\n<link name=a/>\n</robot>", "arm.urdf: line 2: expected a quote not 'a'");
    check(
        "<robot name=\"r\">\n<link name=\"a\">\n</robot>",
        "arm.urdf: line 3: </robot> where </link> should close <link>",
    );
    check("<robot name=\"r\" name=\"s\"/>", "arm.urdf: line 1: attribute 'name' is already defined");
}

#[test]
fn syntax_errors_carry_the_line_as_data() {
    let err = parse_source("arm.urdf", "<robot name=\"r\">\n\n<link name=a/>\n</robot>").unwrap_err();
    assert!(matches!(err.kind, LoadErrorKind::Syntax { line: Some(3), .. }), "{err:?}");
    let err = parse_source("arm.urdf", &joint_with("<axis xyz=\"1\"/>")).unwrap_err();
    assert!(matches!(err.kind, LoadErrorKind::Located { line: 6, .. }), "{err:?}");
}

#[test]
fn what_urdf_allows_to_leave_out_takes_its_default() {
    // No <origin>: identity; no <axis>: x; an <axis> or <origin> without attributes: the same.
    for body in [String::new(), "<origin/> <axis/>".to_owned()] {
        let text = robot(&format!("{LINKS}\n{LIMIT}\n{body}"));
        let tree = parse_source("arm.urdf", &text).unwrap();
        let joint = tree.joint_by_name("elbow").unwrap();
        assert_eq!(joint.axis, [1.0, 0.0, 0.0]);
        assert!(joint.origin.steps().is_empty(), "{:?}", joint.origin);
    }
    // Mimic defaults.
    let text = "<robot name=\"r\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>
      <joint name=\"j1\" type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/></joint>
      <joint name=\"j2\" type=\"continuous\"><parent link=\"b\"/><child link=\"c\"/><mimic joint=\"j1\"/></joint></robot>";
    let tree = parse_source("arm.urdf", text).unwrap();
    assert_eq!(tree.joint_by_name("j2").unwrap().motion.value(&[0.5]), Some(0.5));
    // Ignored: visual meshes, transmissions, gazebo, xacro leftovers, unknown elements.
    let text = "<robot name=\"r\" xmlns:xacro=\"http://www.ros.org/wiki/xacro\">
      <xacro:property name=\"l\" value=\"1\"/>
      <material name=\"blue\"><color rgba=\"0 0 1 1\"/></material>
      <link name=\"a\"><visual><geometry><mesh filename=\"a.dae\"/></geometry></visual><inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>
      <link name=\"b\"/>
      <joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/><dynamics damping=\"x\"/><calibration rising=\"0\"/></joint>
      <transmission name=\"t\"><type>SimpleTransmission</type></transmission>
      <gazebo reference=\"a\"><material>Gazebo/Blue</material></gazebo>
      <whatever/></robot>";
    assert_eq!(parse_source("arm.urdf", text).unwrap().links().len(), 2);
}

/// Cut anywhere, a real robot file loads or fails with a message whose line is inside the text
/// that is there; never a panic.
#[test]
fn every_truncation_is_an_error_at_a_line_of_the_text() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots/planar_3r.urdf");
    let text = std::fs::read_to_string(path).unwrap();
    let end = text.trim_end().len();
    for cut in (0..end).filter(|&i| text.is_char_boundary(i)) {
        let prefix = &text[..cut];
        let lines = prefix.split('\n').count();
        let Err(error) = parse_source("arm.urdf", prefix) else { panic!("a file cut at byte {cut} loaded") };
        match error.kind {
            LoadErrorKind::Syntax { line: Some(line), .. } | LoadErrorKind::Located { line, .. } => {
                assert!((1..=lines).contains(&line), "cut at {cut}: line {line} of {lines}: {error}");
            }
            LoadErrorKind::Syntax { line: None, .. } => assert!(prefix.trim().is_empty(), "cut at {cut}: {error}"),
            _ => panic!("cut at {cut}: {error}"),
        }
    }
}

proptest::proptest! {
    /// Arbitrary text, and arbitrary bytes spliced into a valid file, never panic the reader.
    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,200}", splice in "[<>/=\" a-z0-9.]{0,12}", at in 0usize..400) {
        let _ = parse_source("arm.urdf", &text);
        let good = joint_with("<origin xyz=\"1 2 3\" rpy=\"0 0 0.5\"/> <mimic joint=\"x\"/>");
        let at = (0..=at.min(good.len())).rev().find(|&i| good.is_char_boundary(i)).unwrap_or(0);
        let _ = parse_source("arm.urdf", &format!("{}{splice}{}", &good[..at], &good[at..]));
    }
}
