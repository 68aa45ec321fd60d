//! The one front end: the format chosen in one place, the one loader, the exactness policy
//! threaded through it, and link lookup with "did you mean" (issue 13, "one front end").
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_model::{ExactAngles, LoadErrorKind, Source, SourceFormat, SourceKind, parse_source_with};

/// A fixed joint turned by pi as ROS spells it (2e-13 rad off), then a revolute joint.
const ROS_PI: &str = r#"<robot name="r"><link name="a"/><link name="b"/><link name="c"/>
  <joint name="flip" type="fixed"><parent link="a"/><child link="b"/><origin rpy="3.14159265359 0 0"/></joint>
  <joint name="turn" type="continuous"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/></joint></robot>"#;

#[test]
fn the_format_is_chosen_from_the_name_and_the_kind() {
    use SourceFormat::{DhJson, DhToml, Urdf};
    let cases = [
        ("arm.urdf", SourceKind::ByExtension, Some(Urdf)),
        ("arm.URDF", SourceKind::ByExtension, Some(Urdf)),
        ("arm.xml", SourceKind::ByExtension, Some(Urdf)),
        ("arm.toml", SourceKind::ByExtension, Some(DhToml)),
        ("arm.json", SourceKind::ByExtension, Some(DhJson)),
        ("arm.xacro", SourceKind::ByExtension, None),
        ("arm", SourceKind::ByExtension, None),
        ("arm.xacro", SourceKind::Urdf, Some(Urdf)),
        ("arm.toml", SourceKind::Urdf, Some(Urdf)),
        ("arm.json", SourceKind::Dh, Some(DhJson)),
        ("arm.toml", SourceKind::Dh, Some(DhToml)),
        ("arm.table", SourceKind::Dh, Some(DhToml)),
        ("arm.urdf", SourceKind::Dh, Some(DhToml)),
    ];
    for (name, kind, expected) in cases {
        assert_eq!(SourceFormat::choose(name, kind), expected, "{name} as {kind:?}");
    }
}

#[test]
fn an_unknown_extension_names_the_file() {
    let error = Source::from_bytes("robots/arm.xacro", SourceKind::ByExtension, ROS_PI.into()).unwrap_err();
    assert!(matches!(error.kind, LoadErrorKind::UnknownFormat), "{error:?}");
    assert_eq!(
        error.to_string(),
        "robots/arm.xacro: unknown description format (expected .urdf, .xml, .mjcf, .toml or .json)"
    );
}

#[test]
fn bytes_must_be_utf8_and_the_line_is_given() {
    let mut bytes = b"<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"".to_vec();
    bytes.extend([0xff, 0xfe]);
    bytes.extend(b"\"/></robot>");
    let error = Source::from_bytes("arm.urdf", SourceKind::ByExtension, bytes).unwrap_err();
    assert_eq!(error.to_string(), "arm.urdf: line 3: the text is not UTF-8");
}

#[test]
fn the_file_name_names_the_format() {
    let name = |label: &str, format| Source::new(format, label, "").file_name();
    assert_eq!(name("robots/arm.urdf", SourceFormat::Urdf), "robots/arm.urdf");
    assert_eq!(name("robots/arm.xacro", SourceFormat::Urdf), "robots/arm.xacro.urdf");
    assert_eq!(name("arm.table", SourceFormat::DhToml), "arm.table.toml");
    assert_eq!(name("arm.json", SourceFormat::DhJson), "arm.json");
    assert_eq!(name("arm.json", SourceFormat::DhToml), "arm.json.toml");
    // What `parse_source` reads under that name is what the source holds.
    let source = Source::new(SourceFormat::Urdf, "arm.xacro", ROS_PI);
    let tree = parse_source_with(&source.file_name(), &source.text, ExactAngles::Off).unwrap();
    assert_eq!(tree, source.load(ExactAngles::Off).unwrap());
}

#[test]
fn the_loader_applies_the_exactness_policy() {
    let source = Source::from_bytes("arm.urdf", SourceKind::ByExtension, ROS_PI.into()).unwrap();
    let on = source.load(ExactAngles::default()).unwrap();
    let off = source.load(ExactAngles::Off).unwrap();
    assert_eq!(on.recognised_angles().len(), 1, "{:?}", on.recognised_angles());
    assert!(off.recognised_angles().is_empty(), "{:?}", off.recognised_angles());
    assert_eq!((on.exact_angles(), off.exact_angles()), (ExactAngles::default(), ExactAngles::Off));
    assert_ne!(on, off);
}

#[test]
fn errors_name_the_label() {
    let source = Source::new(
        SourceFormat::DhToml,
        "inline DH table",
        "convention = \"standard\"\n[[joints]]\nname = \"j\"\nalpha = \"pie\"\n",
    );
    let error = source.load(ExactAngles::default()).unwrap_err();
    assert_eq!(
        error.to_string(),
        "inline DH table: DH row 1 (joint `j`): `alpha` = \"pie\" is neither a number nor an exact angle like \"pi/2\""
    );
}

#[test]
fn links_are_found_or_a_near_name_is_suggested() {
    let tree = Source::new(SourceFormat::Urdf, "arm.urdf", ROS_PI).load(ExactAngles::default()).unwrap();
    assert_eq!(tree.find_link("tip", "c").map(|l| tree.link(l).name.clone()), Ok("c".to_owned()));
    let cases = [
        ("base", "d", "base link `d` does not exist; did you mean `a`?"),
        ("tip", "gripper", "tip link `gripper` does not exist"),
        ("requested", "", "requested link `` does not exist; did you mean `a`?"),
    ];
    for (role, name, expected) in cases {
        let error = tree.find_link(role, name).unwrap_err();
        assert_eq!((error.role, error.link.as_str()), (role, name));
        assert_eq!(error.to_string(), expected);
    }
}
