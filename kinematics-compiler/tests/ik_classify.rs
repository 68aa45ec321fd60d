//! Which family each robot of `robots/` gets, or why none: the classification is part of the
//! compiler's output a user sees (`kinematics inspect`), so it is pinned here.
#![allow(clippy::expect_used, clippy::panic)] // test helpers fail loudly

use kinematics_compiler::ik::{IkFamily, SixFamily, classify};

fn load(file: &str) -> kinematics_model::KinematicTree {
    let path = format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("the robot file is readable");
    kinematics_model::parse_source(file, &text).expect("the robot file is valid")
}

fn deepest(tree: &kinematics_model::KinematicTree) -> String {
    let leaf = tree.leaves().max_by_key(|&l| tree.depth(l)).expect("a tree has a leaf");
    tree.link(leaf).name.clone()
}

/// Each robot of `robots/` with the tip classified, and the family or a piece of the reason.
const EXPECTED: &[(&str, Result<IkFamily, &str>)] = &[
    ("ball_tree.xml", Err("joint `right_wrist` is a spherical joint")),
    ("dual_arm_torso.urdf", Err("the chain has 8 moving joints")),
    ("gen3.urdf", Err("the chain has 7 moving joints")),
    ("humanoid.urdf", Err("joint `RFinger21` mimics `RHand`")),
    ("iiwa14.toml", Err("the chain has 7 moving joints")),
    ("iiwa14.urdf", Err("the chain has 7 moving joints")),
    ("irb120.urdf", Ok(IkFamily::Six(SixFamily::SphericalTwoParallel))),
    ("panda.toml", Err("the chain has 7 moving joints")),
    ("panda.urdf", Err("joint `panda_finger_joint2` mimics `panda_finger_joint1`")),
    ("panda_meshes.urdf", Err("joint `panda_finger_joint2` mimics `panda_finger_joint1`")),
    ("panda_primitives.urdf", Err("joint `panda_finger_joint2` mimics `panda_finger_joint1`")),
    ("panda_spherized.urdf", Err("the chain has 7 moving joints")),
    ("planar_2r.toml", Ok(IkFamily::Planar)),
    ("planar_3r.toml", Ok(IkFamily::Planar)),
    ("planar_3r.urdf", Ok(IkFamily::Planar)),
    ("planar_3r_modified.toml", Ok(IkFamily::Planar)),
    ("puma560.toml", Ok(IkFamily::Six(SixFamily::SphericalTwoParallel))),
    ("quadruped.urdf", Err("the robot has 12 degrees of freedom and the chain moves 3 of them")),
    ("scara.toml", Ok(IkFamily::Planar)),
    ("seed_tree.urdf", Err("the robot has 3 degrees of freedom and the chain moves 2 of them")),
    ("stanford_arm.toml", Ok(IkFamily::Six(SixFamily::SphericalPrismaticThird))),
    ("ur10e.toml", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("ur10e.urdf", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("ur5.toml", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("ur5.urdf", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("ur5_mjcf.xml", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("ur5_modified.toml", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("ur5_primitives.urdf", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("ur5_ros.urdf", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("ur5_spherized.urdf", Ok(IkFamily::Six(SixFamily::ThreeParallelTwoIntersecting))),
    ("walker.urdf", Err("the chain has 5 moving joints")),
    ("walker.xml", Err("joint `root_joint` is a floating joint")),
];

#[test]
fn every_robot_is_classified_or_told_why_not() {
    let dir = format!("{}/../robots", env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .expect("robots/ is readable")
        .map(|e| e.expect("an entry").file_name().to_string_lossy().into_owned())
        // Descriptions only (not the SRDFs and licence files beside them).
        .filter(|f| kinematics_model::SourceFormat::from_file_name(f).is_some())
        .collect();
    files.sort();
    let listed: Vec<&str> = EXPECTED.iter().map(|(f, _)| *f).collect();
    assert_eq!(files, listed, "a robot was added to robots/: say which family it gets");
    for (file, expected) in EXPECTED {
        let tree = load(file);
        let root = tree.link(tree.root()).name.clone();
        let tip = deepest(&tree);
        match (classify(&tree, &root, &tip), expected) {
            (Ok(plan), Ok(family)) => {
                assert_eq!(plan.family(), *family, "{file}");
                // Every arm of `robots/` is of its family as written (to rounding): nothing for
                // `tip_ik` to refine in every call.
                assert!(!plan.made_exact, "{file}: {:?}", plan.notes);
            }
            (Err(e), Err(piece)) => assert!(e.to_string().contains(piece), "{file}: {e}"),
            (got, _) => panic!("{file}: expected {expected:?}, got {got:?}"),
        }
    }
}

#[test]
fn a_chain_no_family_covers_is_told_why_for_each_family() {
    // The UR5's table with the elbow twisted a quarter turn: no three parallel axes, and a wrist
    // whose axes do not meet (d5 and d6 offsets).
    let dh = r#"
convention = "standard"
[[joints]]
name = "j1"
d = 0.089159
alpha = "pi/2"
[[joints]]
name = "j2"
a = -0.425
[[joints]]
name = "j3"
a = -0.39225
alpha = "pi/2"
[[joints]]
name = "j4"
d = 0.10915
alpha = "pi/2"
[[joints]]
name = "j5"
d = 0.09465
alpha = "-pi/2"
[[joints]]
name = "j6"
d = 0.0823
"#;
    let tree = kinematics_model::parse_source("twisted.toml", dh).expect("a valid table");
    let error = classify(&tree, "base", "link6").expect_err("no family covers it").to_string();
    assert_eq!(error.matches("spherical wrist").count(), 1, "{error}");
    for piece in [
        "no closed-form inverse kinematics for `base` -> `link6`",
        "axes 2, 3, 4 parallel, axes 5 and 6 meet: axes 2 and 4 are not parallel: 1.5708 rad apart",
        "spherical wrist: axes 4, 5, 6 do not meet: axis 6 passes 0.0946 m from where 4 and 5 meet",
    ] {
        assert!(error.contains(piece), "{error}\nlacks: {piece}");
    }
}

#[test]
fn a_seven_joint_arm_with_a_free_joint() {
    let iiwa = load("iiwa14.urdf");
    let plan = kinematics_compiler::ik::classify_with(&iiwa, "world", "iiwa_link_ee", Some("iiwa_joint_3"))
        .expect("the iiwa less its third joint is a spherical-wrist arm");
    assert_eq!(plan.family(), SixFamily::SphericalFirstTwoIntersecting.into());
    let free = plan.free().expect("a free joint");
    assert_eq!((free.name.as_str(), free.index), ("iiwa_joint_3", 2));
    assert_eq!(
        plan.joints,
        ["iiwa_joint_1", "iiwa_joint_2", "iiwa_joint_4", "iiwa_joint_5", "iiwa_joint_6", "iiwa_joint_7"]
    );

    // Without a free joint: the hint.
    let error = classify(&iiwa, "world", "iiwa_link_ee").expect_err("seven joints").to_string();
    assert!(
        error.contains("the chain has 7 moving joints; the closed forms solve six (name one joint free"),
        "{error}"
    );
    // A name that is no moving joint of the chain.
    let error = kinematics_compiler::ik::classify_with(&iiwa, "world", "iiwa_link_ee", Some("iiwa_joint_9"))
        .expect_err("no such joint")
        .to_string();
    assert!(error.contains("`iiwa_joint_9` is not a moving joint of the chain (those are `iiwa_joint_1`"), "{error}");
    // The elbow free: shoulder and wrist each a point, the distance between them fixed.
    let error = kinematics_compiler::ik::classify_with(&iiwa, "world", "iiwa_link_ee", Some("iiwa_joint_4"))
        .expect_err("a degenerate arm")
        .to_string();
    assert!(error.contains("axis 3 is in line with the offset beside it"), "{error}");
    // The second joint free: the family's pairs straddle it.
    let error = kinematics_compiler::ik::classify_with(&iiwa, "world", "iiwa_link_ee", Some("iiwa_joint_2"))
        .expect_err("no family")
        .to_string();
    assert!(error.contains("on either side of the free joint"), "{error}");
    // A free joint asked of a six-joint arm.
    let ur5 = load("ur5.urdf");
    let error = kinematics_compiler::ik::classify_with(&ur5, "base_link", "tool0", Some("elbow_joint"))
        .expect_err("six joints")
        .to_string();
    assert!(error.contains("the chain has 6 moving joints; the closed forms solve seven, one of them free"), "{error}");
}

/// An arm within tolerance of its family is solved with the family's relations made exact, and
/// says so (`tip_ik` then refines every solution in one pass): the IRB 120 with half turns written
/// 3.14159265359, read as written (2e-13 rad off); read with its angles made exact it is not
/// (and no arm of `robots/` is, above: the UR5's URDF writes its quarter turns as doubles, off by
/// rounding only).
#[test]
fn an_arm_made_exact_is_marked() {
    use kinematics_model::ExactAngles;
    let path = format!("{}/../tests/arms/irb120_half_turns.urdf", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("the arm is readable");
    for (angles, made_exact) in [(ExactAngles::Off, true), (ExactAngles::default(), false)] {
        let tree = kinematics_model::parse_source_with("irb120_half_turns.urdf", &text, angles).expect("valid");
        let plan = classify(&tree, "base_link", "tool0").expect("its family");
        assert_eq!(plan.made_exact, made_exact, "{angles:?}: {:?}", plan.notes);
    }
}
