//! Every validation rule, fed a bad description: the error must name the offending element.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_model::{LoadError, LoadErrorKind, ModelError, parse_source};

/// A URDF document with the given links and joint elements.
fn urdf(links: &[&str], joints: &str) -> String {
    let links: String = links.iter().map(|l| format!("<link name=\"{l}\"/>")).collect();
    format!("<robot name=\"r\">{links}{joints}</robot>")
}

fn joint(name: &str, kind: &str, parent: &str, child: &str, extra: &str) -> String {
    format!(
        "<joint name=\"{name}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"{child}\"/>\
         <axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>{extra}</joint>"
    )
}

fn load_err(file: &str, text: &str) -> LoadError {
    match parse_source(file, text) {
        Ok(tree) => panic!("{file} was accepted: {tree:?}"),
        Err(e) => e,
    }
}

/// Checks that loading fails with model errors, each message containing the given fragments.
fn check(text: &str, expected: &[&[&str]]) -> Vec<ModelError> {
    let err = load_err("bad.urdf", text);
    let message = err.to_string();
    assert!(message.starts_with("bad.urdf: "), "{message}");
    let errors = err.model_errors().unwrap_or_else(|| panic!("not a model error: {message}")).errors().to_vec();
    assert_eq!(errors.len(), expected.len(), "{errors:#?}");
    for (e, fragments) in errors.iter().zip(expected) {
        for f in *fragments {
            assert!(e.to_string().contains(f), "`{e}` lacks `{f}`");
        }
    }
    errors
}

#[test]
fn cycle_names_its_links() {
    let text = urdf(
        &["root", "a", "b"],
        &[
            joint("j1", "revolute", "root", "a", ""),
            joint("j2", "revolute", "a", "b", ""),
            joint("j3", "revolute", "b", "a", ""),
        ]
        .concat(),
    );
    // `a` has two parents (j1, j3) and {a, b} form a cycle: the parent rule reports it.
    check(&text, &[&["link `a`", "`j1`", "`j3`"]]);
    let text = urdf(
        &["root", "a", "b"],
        &[joint("j2", "revolute", "a", "b", ""), joint("j3", "revolute", "b", "a", "")].concat(),
    );
    let errors = check(&text, &[&["cycle", "`a`", "`b`"]]);
    assert!(matches!(&errors[0], ModelError::Cycle { links } if links.len() == 2));
}

#[test]
fn self_loop_is_a_cycle() {
    let text = urdf(
        &["root", "a"],
        &[joint("j1", "revolute", "root", "a", ""), joint("j2", "fixed", "root", "root", "")].concat(),
    );
    check(&text, &[&["cycle", "`root`"]]);
}

#[test]
fn more_than_one_root() {
    let text = urdf(&["a", "b", "c"], &joint("j", "revolute", "a", "b", ""));
    check(&text, &[&["more than one root", "`a`", "`c`"]]);
}

#[test]
fn unknown_parent_and_child() {
    let text = urdf(
        &["a"],
        &[joint("j1", "revolute", "nowhere", "a", ""), joint("j2", "revolute", "a", "ghost", "")].concat(),
    );
    check(&text, &[&["joint `j1`", "parent link `nowhere`"], &["joint `j2`", "child link `ghost`"]]);
}

#[test]
fn duplicate_names() {
    let text =
        urdf(&["a", "b", "b"], &[joint("j", "revolute", "a", "b", ""), joint("j", "revolute", "a", "b", "")].concat());
    check(&text, &[&["link `b`", "more than once"], &["joint `j`", "more than once"]]);
}

#[test]
fn zero_axis() {
    let text = urdf(&["a", "b"], &joint("spin", "continuous", "a", "b", "").replace("0 0 1", "0 0 0"));
    check(&text, &[&["joint `spin`", "axis is zero"]]);
}

#[test]
fn non_finite_numbers() {
    let text = urdf(&["a", "b"], &joint("j", "revolute", "a", "b", "<origin xyz=\"NaN 0 0\"/>"));
    check(&text, &[&["joint `j`", "origin", "not a finite number"]]);
    let text = urdf(&["a", "b"], &joint("j", "revolute", "a", "b", "").replace("0 0 1", "0 inf 1"));
    check(&text, &[&["joint `j`", "axis", "not a finite number"]]);
    let text = urdf(&["a", "b"], &joint("j", "revolute", "a", "b", "").replace("lower=\"-1\"", "lower=\"nan\""));
    check(&text, &[&["joint `j`", "lower limit", "not a finite number"]]);
}

#[test]
fn lower_limit_above_upper() {
    let text = urdf(&["a", "b"], &joint("elbow", "revolute", "a", "b", "").replace("lower=\"-1\"", "lower=\"2\""));
    check(&text, &[&["joint `elbow`", "lower limit 2 is greater than upper limit 1"]]);
}

#[test]
fn mimic_of_unknown_joint() {
    let text = urdf(&["a", "b"], &joint("finger", "revolute", "a", "b", "<mimic joint=\"thumb\"/>"));
    check(&text, &[&["joint `finger`", "mimics joint `thumb`", "does not exist"]]);
}

#[test]
fn mimic_of_fixed_joint() {
    let text = urdf(
        &["a", "b", "c"],
        &[joint("mount", "fixed", "a", "b", ""), joint("finger", "revolute", "b", "c", "<mimic joint=\"mount\"/>")]
            .concat(),
    );
    check(&text, &[&["joint `finger`", "mimics joint `mount`", "fixed"]]);
}

#[test]
fn mimic_loop() {
    let text = urdf(
        &["a", "b", "c", "d"],
        &[
            joint("j1", "revolute", "a", "b", ""),
            joint("j2", "revolute", "b", "c", "<mimic joint=\"j3\"/>"),
            joint("j3", "revolute", "c", "d", "<mimic joint=\"j2\"/>"),
        ]
        .concat(),
    );
    check(&text, &[&["mimic joints form a loop", "`j2`", "`j3`"]]);
}

#[test]
fn floating_and_planar_joints_are_refused_by_name() {
    let text = urdf(
        &["a", "b", "c"],
        &[joint("free", "floating", "a", "b", ""), joint("slide", "planar", "a", "c", "")].concat(),
    );
    check(&text, &[&["joint `free`", "`floating` is not supported"], &["joint `slide`", "`planar` is not supported"]]);
}

#[test]
fn every_fault_is_reported_at_once() {
    let text = urdf(
        &["a", "b", "c"],
        &[
            joint("j1", "revolute", "a", "b", "").replace("0 0 1", "0 0 0"),
            joint("j2", "revolute", "b", "c", "").replace("lower=\"-1\"", "lower=\"5\""),
        ]
        .concat(),
    );
    check(&text, &[&["joint `j1`", "axis is zero"], &["joint `j2`", "lower limit"]]);
}

#[test]
fn mimic_chains_resolve_to_their_source() {
    let text = urdf(
        &["a", "b", "c", "d"],
        &[
            joint("j1", "revolute", "a", "b", ""),
            joint("j2", "revolute", "b", "c", "<mimic joint=\"j1\" multiplier=\"2\" offset=\"0.5\"/>"),
            joint("j3", "revolute", "c", "d", "<mimic joint=\"j2\" multiplier=\"-1\" offset=\"0.25\"/>"),
        ]
        .concat(),
    );
    let tree = parse_source("ok.urdf", &text).unwrap();
    assert_eq!(tree.dof(), 1);
    // j3 = -1 * (2 q + 0.5) + 0.25 = -2 q - 0.25
    let j3 = tree.joint_by_name("j3").unwrap();
    assert_eq!(j3.motion.value(&[1.0]), Some(-2.25));
    assert!(matches!(j3.motion, kinematics_model::JointMotion::Mimic { dof: 0, .. }));
}

#[test]
fn urdf_syntax_error_names_the_file() {
    let err = load_err("broken.urdf", "<robot name=\"r\"><link name=\"a\"></robot>");
    assert!(matches!(err.kind, LoadErrorKind::Syntax { .. }), "{err}");
    assert!(err.to_string().starts_with("broken.urdf: "), "{err}");
}

#[test]
fn unknown_extension() {
    let err = load_err("robot.yaml", "");
    assert!(matches!(err.kind, LoadErrorKind::UnknownFormat), "{err}");
}

const GOOD_ROW: &str = "[[joints]]\nname = \"j1\"\na = 1.0\n";

#[test]
fn dh_syntax_error_gives_the_line() {
    let text = format!("convention = \"standard\"\n{GOOD_ROW}alpha = [1\n");
    let err = load_err("arm.toml", &text);
    match &err.kind {
        LoadErrorKind::Syntax { line, .. } => assert_eq!(*line, Some(5), "{err}"),
        other => panic!("{other:?}"),
    }
    let err = load_err("arm.json", "{\"convention\": \"standard\",\n \"joints\": [}");
    match &err.kind {
        LoadErrorKind::Syntax { line, .. } => assert_eq!(*line, Some(2), "{err}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn dh_bad_values_name_the_row() {
    let text = format!("convention = \"standard\"\n{GOOD_ROW}[[joints]]\nname = \"elbow\"\nalpha = \"pie/2\"\n");
    let err = load_err("arm.toml", &text);
    assert!(err.to_string().contains("DH row 2 (joint `elbow`)"), "{err}");
    assert!(err.to_string().contains("alpha"), "{err}");
    let text = format!("convention = \"standard\"\n{GOOD_ROW}lower = -1.0\n");
    let err = load_err("arm.toml", &text);
    assert!(err.to_string().contains("DH row 1 (joint `j1`): give both"), "{err}");
    let text = format!("convention = \"modified\"\n{GOOD_ROW}upper = -1.0\nlower = 1.0\n");
    let err = load_err("arm.toml", &text);
    assert!(err.to_string().contains("DH row 1 (joint `j1`): lower limit 1 is greater"), "{err}");
}

#[test]
fn dh_unknown_keys_and_conventions_are_refused() {
    let err = load_err("arm.toml", &format!("convention = \"standard\"\n{GOOD_ROW}alfa = 0.0\n"));
    assert!(err.to_string().contains("alfa"), "{err}");
    let err = load_err("arm.toml", &format!("convention = \"sideways\"\n{GOOD_ROW}"));
    assert!(err.to_string().contains("sideways"), "{err}");
}

#[test]
fn dh_exact_twists_stay_exact() {
    let text = "convention = \"standard\"\n[[joints]]\nname = \"j1\"\nalpha = \"-pi/2\"\n[[joints]]\nname = \"j2\"\nalpha = 1.5708\n";
    let tree = parse_source("arm.toml", text).unwrap();
    let twist = |name: &str| match tree.joint_by_name(name).unwrap().after_motion.steps().last() {
        Some(kinematics_model::Elementary::Rotation(_, angle)) => *angle,
        other => panic!("{other:?}"),
    };
    assert_eq!(twist("j1").exact(), kinematics_model::PiRational::new(-1, 2));
    assert_eq!(twist("j2").exact(), None);
}

#[test]
fn dof_order_is_depth_first_in_description_order() {
    // Joints listed out of tree order: the DoF order is still depth-first from the root, and the
    // children of one link keep the order the file gives them.
    let text = urdf(
        &["torso", "l1", "l2", "r1", "r2"],
        &[
            joint("left_2", "revolute", "l1", "l2", ""),
            joint("right_1", "revolute", "torso", "r1", ""),
            joint("left_1", "revolute", "torso", "l1", ""),
            joint("right_2", "revolute", "r1", "r2", ""),
        ]
        .concat(),
    );
    let tree = parse_source("tree.urdf", &text).unwrap();
    assert_eq!(tree.dof_names(), ["right_1", "right_2", "left_1", "left_2"]);
    assert_eq!(tree.link(tree.root()).name, "torso");
    let chain = tree.chain("r1", "r2").unwrap();
    assert_eq!(chain.joints.len(), 1);
    assert!(matches!(tree.chain("l1", "r2"), Err(ModelError::NotAChain { .. })));
    assert!(matches!(tree.chain("torso", "hand"), Err(ModelError::NoSuchLink(_))));
}

#[test]
fn dh_json_reads_like_toml() {
    let toml = "name = \"arm\"\nconvention = \"modified\"\nangle_unit = \"degrees\"\n[[joints]]\nname = \"j1\"\nd = 0.3\n[[joints]]\nname = \"j2\"\nalpha = -90\na = 0.1\nlower = -45\nupper = 45\n";
    let json = r#"{"name": "arm", "convention": "modified", "angle_unit": "degrees",
        "joints": [{"name": "j1", "d": 0.3}, {"name": "j2", "alpha": -90, "a": 0.1, "lower": -45, "upper": 45}]}"#;
    let from_toml = parse_source("arm.toml", toml).unwrap();
    let from_json = parse_source("arm.json", json).unwrap();
    assert_eq!(from_toml, from_json);
    // -90 degrees is exactly -pi/2; the limits are in radians in the model.
    let j2 = from_json.joint_by_name("j2").unwrap();
    assert!(
        matches!(j2.origin.steps()[0], kinematics_model::Elementary::Rotation(_, a) if a.exact() == kinematics_model::PiRational::new(-1, 2))
    );
    assert!((j2.limits.unwrap().upper - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
}
