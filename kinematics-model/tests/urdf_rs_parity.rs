//! Every URDF file in the repository, read by the built-in reader and by urdf-rs then
//! [`KinematicTree::from_urdf_rs`], gives the same tree (links, joints, parents, types, axes,
//! origins with their exact angles, limits, mimics, the recognised angles, the inertials), with
//! the exactness policy on and off (urdf-rs gives a massless inertial where the file has none,
//! which the model reads as none, and keeps no lines, which trees do not compare); a file one way
//! refuses, the other refuses too. The reader moved from urdf-rs to roxmltree with such a test;
//! it comes back for the `urdf-rs` feature.
#![cfg(feature = "urdf-rs")]
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::path::{Path, PathBuf};

use kinematics_model::{ExactAngles, KinematicTree, LoadErrorKind, ModelErrors, parse_source_with, urdf_rs};

/// The workspace root (this crate's parent directory).
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("the model crate sits in the workspace").to_owned()
}

/// Every `.urdf` and `.xml` file under `dir`, skipping build output and hidden directories.
fn urdf_files(dir: &Path, found: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for path in entries {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            if !(name.starts_with('.') || name == "target") {
                urdf_files(&path, found);
            }
        } else if name.ends_with(".urdf") || name.ends_with(".xml") {
            found.push(path);
        }
    }
}

/// The files under test, named relative to the root: MJCF files (`.xml` files whose root is
/// `<mujoco>`) are not URDF and are left out.
fn all_files() -> Vec<(String, String)> {
    let root = root();
    let mut found = Vec::new();
    urdf_files(&root, &mut found);
    found
        .into_iter()
        .map(|p| {
            let name = p.strip_prefix(&root).unwrap().display().to_string();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .filter(|(name, text)| {
            kinematics_model::SourceFormat::detect(name, kinematics_model::SourceKind::ByExtension, text)
                != Some(kinematics_model::SourceFormat::Mjcf)
        })
        .collect()
}

const POLICIES: [ExactAngles; 2] =
    [ExactAngles::Within(kinematics_model::exactness::DEFAULT_TOLERANCE), ExactAngles::Off];

/// How urdf-rs's side ended for a file.
#[derive(Debug)]
enum UrdfRs {
    /// urdf-rs read it and the model built this tree.
    Tree(Box<KinematicTree>),
    /// urdf-rs refused the text.
    ReadRefused(String),
    /// urdf-rs read it and the conversion or the model refused it.
    Refused(LoadErrorKind),
}

fn via_urdf_rs(text: &str, policy: ExactAngles) -> UrdfRs {
    match urdf_rs::read_from_string(text) {
        Err(e) => UrdfRs::ReadRefused(e.to_string()),
        Ok(robot) => match KinematicTree::from_urdf_rs(&robot, policy) {
            Ok(tree) => UrdfRs::Tree(Box::new(tree)),
            Err(e) => UrdfRs::Refused(e),
        },
    }
}

#[test]
fn every_urdf_in_the_repository_derives_the_same_robot_both_ways() {
    let files = all_files();
    let mut accepted = Vec::new();
    let mut refused = Vec::new();
    for (name, text) in &files {
        for policy in POLICIES {
            let built_in = parse_source_with(name, text, policy);
            match (built_in, via_urdf_rs(text, policy)) {
                (Ok(ours), UrdfRs::Tree(theirs)) => {
                    assert!(same_tree(&ours, &theirs), "{name} ({policy:?}):\n{ours:?}\n{theirs:?}");
                    same_inertials(&ours, &theirs, name);
                    // Spelled out, what the equality covers for exactness.
                    assert_eq!(ours.recognised_angles(), theirs.recognised_angles(), "{name}");
                    accepted.push(name.clone());
                }
                (Ok(_), other) => panic!("{name} ({policy:?}): the built-in reader accepts it, urdf-rs: {other:?}"),
                (Err(ours), theirs) => {
                    match (&ours.kind, &theirs) {
                        // A model fault: urdf-rs reads the file and the same rules refuse it alike.
                        (LoadErrorKind::Model(ours), UrdfRs::Refused(LoadErrorKind::Model(theirs))) => {
                            // urdf-rs keeps no lines: a geometry fault's line is the built-in's own.
                            assert_eq!(without_lines(ours), without_lines(theirs), "{name}");
                        }
                        (LoadErrorKind::Model(_), _) => panic!("{name}: {ours}; urdf-rs: {theirs:?}"),
                        // A fault of the text: urdf-rs must not make a robot of it.
                        (_, UrdfRs::Tree(_)) => panic!("{name}: {ours}; urdf-rs accepts it"),
                        (_, UrdfRs::ReadRefused(why)) => eprintln!("{name}: urdf-rs refuses it: {why}"),
                        (_, UrdfRs::Refused(why)) => eprintln!("{name}: refused after urdf-rs: {why}"),
                    }
                    refused.push(name.clone());
                }
            }
        }
    }
    // The robots all load (they are the library), and the walk found them all.
    let robots: Vec<String> = std::fs::read_dir(root().join("robots"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "urdf"))
        .map(|p| p.strip_prefix(root()).unwrap().display().to_string())
        .collect();
    assert!(!robots.is_empty());
    for robot in &robots {
        assert!(accepted.contains(robot), "{robot} was not compared");
    }
    assert_eq!(accepted.len() + refused.len(), files.len() * POLICIES.len());
    eprintln!(
        "{} files: {} accepted both ways, {} refused both ways",
        files.len(),
        accepted.len() / 2,
        refused.len() / 2
    );
}

/// Spelled out, what the comparison of trees covers for inertials: each link's as written (none
/// where the file has none); lines from the built-in reader only.
/// The trees are equal, a NaN written in the same place of both counting as equal: the model keeps
/// an `<inertial>`'s numbers as written, a NaN too (the dynamics refuse it, naming the link; the
/// kinematics never read it), and `NaN != NaN`. Their debug text, which writes NaN as `NaN`, is
/// compared instead, less the lines of the `<inertial>`s, which urdf-rs does not keep (and which
/// the trees' equality ignores).
fn same_tree(ours: &KinematicTree, theirs: &KinematicTree) -> bool {
    fn without_lines(tree: &KinematicTree) -> String {
        let text = format!("{tree:?}");
        let start = text.find("inertial_lines: Lines(").expect("the tree's debug text lists its inertial lines");
        let end = start + text[start..].find(")").expect("the lines' list closes");
        format!("{}{}", &text[..start], &text[end..])
    }
    ours == theirs || without_lines(ours) == without_lines(theirs)
}

fn same_inertials(ours: &KinematicTree, theirs: &KinematicTree, file: &str) {
    assert_eq!(ours.links().len(), theirs.links().len(), "{file}");
    for (our, their) in ours.links().iter().zip(theirs.links()) {
        assert_eq!(our.name, their.name, "{file}");
        assert_eq!(format!("{:?}", their.inertial), format!("{:?}", our.inertial), "{file}: `{}`", our.name);
        assert_eq!(ours.inertial_line(&our.name).is_some(), our.inertial.is_some(), "{file}: `{}`", our.name);
        assert_eq!(theirs.inertial_line(&our.name), None, "{file}");
    }
}

/// The refused fixtures, each refused where it should be: a model fault by the same rules after
/// urdf-rs read the file, malformed XML by urdf-rs itself.
#[test]
fn refused_fixtures_are_refused_by_the_same_rule() {
    let model = |file: &str| -> ModelErrors {
        let text = std::fs::read_to_string(root().join(file)).unwrap();
        let UrdfRs::Refused(LoadErrorKind::Model(theirs)) = via_urdf_rs(&text, ExactAngles::default()) else {
            panic!("{file}: urdf-rs then the model should refuse it")
        };
        let ours = parse_source_with(file, &text, ExactAngles::default()).unwrap_err();
        assert_eq!(ours.model_errors(), Some(&theirs), "{file}");
        theirs
    };
    let cycle = model("ui-tests/tests/ui/fixtures/cycle.urdf");
    assert!(cycle.to_string().contains("form a cycle"), "{cycle}");
    let far = model("kinematics-derive-core/tests/fixtures/far.urdf");
    assert!(far.to_string().contains("reach"), "{far}");
    let text = std::fs::read_to_string(root().join("ui-tests/tests/ui/fixtures/malformed.urdf")).unwrap();
    assert!(matches!(via_urdf_rs(&text, ExactAngles::default()), UrdfRs::ReadRefused(_)));
}

/// Where the two readers part, the conversion never makes a robot the built-in reader would
/// not, except where urdf-rs drops what would tell (the module notes of the conversion list it).
#[test]
fn what_urdf_rs_cannot_tell() {
    let arm = |joint: &str| {
        format!(
            r#"<robot name="arm"><link name="base"/><link name="upper"/>
            <joint name="elbow" {joint}<parent link="base"/><child link="upper"/></joint></robot>"#
        )
    };
    let both = |text: &str| {
        (parse_source_with("arm.urdf", text, ExactAngles::default()), via_urdf_rs(text, ExactAngles::default()))
    };

    // No <limit>: the built-in reader names the line; after urdf-rs the joint is still named.
    let (ours, theirs) = both(&arm(r#"type="revolute">"#));
    assert!(
        ours.unwrap_err().to_string().starts_with("arm.urdf: joint `elbow` (line 2): a revolute joint needs a <limit>")
    );
    let UrdfRs::Refused(theirs) = theirs else { panic!("{theirs:?}") };
    assert!(theirs.to_string().starts_with("joint `elbow`: a revolute joint needs a <limit> element"), "{theirs}");

    // No `effort`: urdf-rs reads 0, which cannot be told from a written 0.
    let (ours, theirs) = both(&arm(r#"type="revolute"><limit lower="-1" upper="1" velocity="2"/>"#));
    assert!(ours.unwrap_err().to_string().contains("<limit> needs a `effort` attribute"));
    let UrdfRs::Tree(tree) = theirs else { panic!("{theirs:?}") };
    assert_eq!(tree.joint_by_name("elbow").unwrap().effort_limit, Some(0.0));

    // A word in a vector: urdf-rs skips it.
    let (ours, theirs) = both(&arm(r#"type="continuous"><axis xyz="0 x 0 1"/>"#));
    assert!(ours.unwrap_err().to_string().contains("needs 3 numbers, found 4"));
    let UrdfRs::Tree(tree) = theirs else { panic!("{theirs:?}") };
    assert_eq!(tree.joint_by_name("elbow").unwrap().axis, [0.0, 0.0, 1.0]);

    // No <inertial>: urdf-rs gives its default, a massless one, which the model reads as none.
    let (ours, theirs) = both(&arm(r#"type="continuous">"#));
    assert_eq!(ours.unwrap().link_by_name("upper").unwrap().inertial, None);
    let UrdfRs::Tree(tree) = theirs else { panic!("{theirs:?}") };
    assert_eq!(tree.link_by_name("upper").unwrap().inertial, None);

    // An <inertial> without <mass> or with five entries of <inertia>: refused both ways.
    let inertia = r#"<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>"#;
    let link =
        |inertial: &str| format!(r#"<robot name="r"><link name="a"><inertial>{inertial}</inertial></link></robot>"#);
    for inertial in
        [inertia.to_owned(), r#"<mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0"/>"#.to_owned()]
    {
        let (ours, theirs) = both(&link(&inertial));
        assert!(ours.is_err(), "{inertial}");
        assert!(matches!(theirs, UrdfRs::ReadRefused(_)), "{inertial}: {theirs:?}");
    }

    // Two <inertial>s: refused both ways (urdf-rs: "duplicate field `inertial`").
    let one = format!(r#"<mass value="1"/>{inertia}"#);
    let text = format!(
        r#"<robot name="r"><link name="a"><inertial>{one}</inertial><inertial>{one}</inertial></link></robot>"#
    );
    let (ours, theirs) = both(&text);
    assert!(ours.unwrap_err().to_string().ends_with("more than one <inertial>"));
    assert!(matches!(theirs, UrdfRs::ReadRefused(_)), "{theirs:?}");
}

/// A quaternion origin (URDF 1.1): the built-in reader refuses it, naming joint and line;
/// urdf-rs turns it into roll, pitch and yaw, which the policy then judges like written ones.
#[test]
fn a_quaternion_origin() {
    let text = |version: &str| {
        format!(
            r#"<robot name="r"{version}><link name="a"/><link name="b"/>
            <joint name="j" type="fixed"><parent link="a"/><child link="b"/>
            <origin quat_xyzw="0 0 0.7071067811865476 0.7071067811865476"/></joint></robot>"#
        )
    };
    let ours = parse_source_with("r.urdf", &text(r#" version="1.1""#), ExactAngles::default()).unwrap_err();
    assert_eq!(
        ours.to_string(),
        "r.urdf: joint `j` (line 3): <origin quat_xyzw> (URDF 1.1) is not read: write the rotation as `rpy`"
    );
    let UrdfRs::Tree(tree) = via_urdf_rs(&text(r#" version="1.1""#), ExactAngles::default()) else { panic!() };
    let quarter = kinematics_model::PiRational::new(1, 2).unwrap();
    assert_eq!(
        tree.joint_by_name("j").unwrap().origin.steps(),
        [kinematics_model::Elementary::Rotation(kinematics_model::Axis::Z, kinematics_model::Angle::Exact(quarter))]
    );
    // In a URDF 1.0 file urdf-rs, like urdfdom, ignores it: after reading nothing shows it was there.
    let UrdfRs::Tree(tree) = via_urdf_rs(&text(""), ExactAngles::default()) else { panic!() };
    assert!(tree.joint_by_name("j").unwrap().origin.steps().is_empty());
}

/// The exactness policy gives the same verdict on the same decimals either way: a full-precision
/// quarter turn, xacro's pi, a truncated pi, and decimals meant as numbers.
#[test]
fn the_exactness_policy_judges_the_same_numbers() {
    let cases = [
        ("0 0 1.5707963267948966", 1),
        ("3.14159265359 0 0", 1),
        ("0 3.14159265 0", 1),
        ("1.5708 0 0", 0),
        ("0 0 1.570796", 0),
    ];
    for (rpy, recognised) in cases {
        let text = format!(
            r#"<robot name="r"><link name="a"/><link name="b"/>
            <joint name="j" type="fixed"><parent link="a"/><child link="b"/><origin rpy="{rpy}"/></joint></robot>"#
        );
        for policy in POLICIES {
            let ours = parse_source_with("r.urdf", &text, policy).unwrap();
            let UrdfRs::Tree(theirs) = via_urdf_rs(&text, policy) else { panic!("{rpy}") };
            assert_eq!(ours, *theirs, "{rpy} ({policy:?})");
            let expected = if policy == ExactAngles::Off { 0 } else { recognised };
            assert_eq!(theirs.recognised_angles().len(), expected, "{rpy} ({policy:?})");
        }
    }
}

/// The model errors with the lines of geometry and inertial faults left out (urdf-rs keeps none).
fn without_lines(errors: &kinematics_model::ModelErrors) -> Vec<kinematics_model::ModelError> {
    errors
        .errors()
        .iter()
        .map(|e| match e {
            kinematics_model::ModelError::Geometry { link, fault, .. } => {
                kinematics_model::ModelError::Geometry { link: link.clone(), line: None, fault: fault.clone() }
            }
            kinematics_model::ModelError::Inertial { link, fault, .. } => {
                kinematics_model::ModelError::Inertial { link: link.clone(), line: None, fault: fault.clone() }
            }
            other => other.clone(),
        })
        .collect()
}
