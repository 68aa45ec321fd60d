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
fn a_fixed_joint_mimicking_a_fixed_one_is_listed_and_one_mimicking_a_moving_one_refused() {
    // VAMP's Panda: both fingers fixed, the second with a <mimic> of the first.
    let text = urdf(
        &["a", "b", "c"],
        &[joint("finger1", "fixed", "a", "b", ""), joint("finger2", "fixed", "a", "c", "<mimic joint=\"finger1\"/>")]
            .concat(),
    );
    let tree = parse_source("ok.urdf", &text).unwrap();
    assert_eq!(tree.vacuous_mimics(), ["finger2"]);
    assert_eq!(tree.dof(), 0);
    let text = urdf(
        &["a", "b", "c"],
        &[
            joint("finger1", "revolute", "a", "b", ""),
            joint("finger2", "fixed", "a", "c", "<mimic joint=\"finger1\"/>"),
        ]
        .concat(),
    );
    check(&text, &[&["joint `finger2`", "a fixed joint cannot mimic"]]);
}

#[test]
fn bad_collision_geometry_names_the_link_and_the_line() {
    let geometry = |shape: &str| {
        format!(
            "<robot name=\"r\">\n<link name=\"a\">\n<collision><geometry>{shape}</geometry></collision>\n</link>\n</robot>"
        )
    };
    for (shape, fault) in [
        ("<sphere radius=\"-0.1\"/>", "<sphere radius> is -0.1"),
        ("<sphere radius=\"nan\"/>", "<sphere radius> is NaN"),
        ("<box size=\"0.1 0 0.1\"/>", "<box size y> is 0"),
        ("<cylinder radius=\"0.1\" length=\"inf\"/>", "<cylinder length> is inf"),
        ("<capsule radius=\"0\" length=\"0.1\"/>", "<capsule radius> is 0"),
    ] {
        check(&geometry(shape), &[&["link `a` (line 3): <collision>: ", fault]]);
    }
    // Malformed elements are syntax errors with their line.
    for (shape, fault) in [
        ("", "<geometry> needs exactly one of"),
        ("<sphere/>", "<sphere> needs a `radius` attribute"),
        ("<cone radius=\"1\"/>", "unknown geometry <cone>"),
    ] {
        let message = load_err("bad.urdf", &geometry(shape)).to_string();
        assert!(message.starts_with("bad.urdf: link `a` (line 3): ") && message.contains(fault), "{message}");
    }
    // Good geometry is kept, in order, on its link.
    let text = geometry("<mesh filename=\"a.stl\"/>").replace(
        "</collision>",
        "</collision><collision><origin xyz=\"0 0 1\"/><geometry><capsule radius=\"0.1\" length=\"0\"/></geometry></collision>",
    );
    let tree = parse_source("ok.urdf", &text).unwrap();
    let shapes: Vec<&str> = tree.link(tree.root()).collisions.iter().map(|c| c.shape.name()).collect();
    assert_eq!(shapes, ["mesh", "capsule"]);
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
fn floating_and_planar_joints_take_their_entries_of_q() {
    let text = urdf(
        &["a", "b", "c", "d"],
        &[
            joint("slide", "planar", "a", "b", ""),
            joint("free", "floating", "b", "c", ""),
            joint("turn", "revolute", "c", "d", ""),
        ]
        .concat(),
    );
    let tree = parse_source("ok.urdf", &text).unwrap();
    assert_eq!((tree.dof(), tree.velocity_dof()), (11, 10));
    assert_eq!(
        tree.dof_names(),
        [
            "slide.x",
            "slide.y",
            "slide.theta",
            "free.x",
            "free.y",
            "free.z",
            "free.qx",
            "free.qy",
            "free.qz",
            "free.qw",
            "turn"
        ]
    );
    assert_eq!(
        tree.velocity_names(),
        ["slide.x", "slide.y", "slide.theta", "free.vx", "free.vy", "free.vz", "free.wx", "free.wy", "free.wz", "turn"]
    );
    let columns: Vec<Option<usize>> = tree.velocity_of_entry();
    assert_eq!(columns[..3], [Some(0), Some(1), Some(2)]);
    assert!(columns[3..10].iter().all(Option::is_none));
    assert_eq!(columns[10], Some(9));
    let id = |name: &str| tree.joint_id(name).unwrap();
    assert_eq!(
        [tree.velocity_start(id("slide")), tree.velocity_start(id("free")), tree.velocity_start(id("turn"))],
        [Some(0), Some(3), Some(9)]
    );
    // URDF gives limits to revolute and prismatic joints only: the written ones are not used.
    assert!(tree.dof_limits()[..10].iter().all(Option::is_none));
    assert!(tree.dof_limits()[10].is_some());
    assert_eq!(tree.chain_dofs(&tree.chain("a", "d").unwrap()), (0..11).collect::<Vec<_>>());
}

#[test]
fn a_mimic_of_a_planar_or_floating_joint_is_refused_by_name() {
    let text = urdf(
        &["a", "b", "c", "d"],
        &[
            joint("slide", "planar", "a", "b", ""),
            joint("follow", "revolute", "b", "c", "<mimic joint=\"slide\"/>"),
            joint("free", "floating", "c", "d", "<mimic joint=\"follow\"/>"),
        ]
        .concat(),
    );
    check(
        &text,
        &[
            &["joint `follow`", "mimics joint `slide`, but a planar joint takes several values"],
            &["joint `free`", "mimics joint `follow`, but a floating joint takes several values"],
        ],
    );
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

/// A URDF joint with the given type, origin, axis, limits and extra elements.
#[allow(clippy::too_many_arguments, reason = "one argument per URDF attribute the cases vary")]
fn joint_with(
    name: &str,
    kind: &str,
    parent: &str,
    child: &str,
    xyz: &str,
    axis: &str,
    limits: &str,
    extra: &str,
) -> String {
    format!(
        "<joint name=\"{name}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"{child}\"/>\
         <origin xyz=\"{xyz}\"/><axis xyz=\"{axis}\"/><limit lower=\"{limits}\" effort=\"1\" velocity=\"1\"/>{extra}</joint>"
    )
    .replace("lower=\"\"", "")
}

#[test]
fn huge_and_tiny_axes_are_normalised_without_overflow() {
    // issue 13: the norm of `0 0 1e200` overflowed to infinity and the normalised axis was NaN;
    // `1e-300 0 0` squared to zero and was refused as a zero axis.
    for (axis, expected) in [
        ("0 0 1e200", [0.0, 0.0, 1.0]),
        ("0 -1e308 0", [0.0, -1.0, 0.0]),
        ("1e-300 0 0", [1.0, 0.0, 0.0]),
        ("0 0 -4.9e-324", [0.0, 0.0, -1.0]),
        ("1e-200 1e-200 0", [std::f64::consts::FRAC_1_SQRT_2, std::f64::consts::FRAC_1_SQRT_2, 0.0]),
        ("1e308 1e308 0", [std::f64::consts::FRAC_1_SQRT_2, std::f64::consts::FRAC_1_SQRT_2, 0.0]),
    ] {
        let text = urdf(&["a", "b"], &joint("spin", "continuous", "a", "b", "").replace("0 0 1", axis));
        let tree = parse_source("ok.urdf", &text).unwrap_or_else(|e| panic!("{axis}: {e}"));
        let got = tree.joint_by_name("spin").unwrap().axis;
        for i in 0..3 {
            assert!((got[i] - expected[i]).abs() <= 2e-16, "{axis}: {got:?}");
        }
        assert!((got.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-15, "{axis}: {got:?}");
    }
    // Zero stays zero, for each kind of moving joint.
    for kind in ["revolute", "continuous", "prismatic"] {
        let text = urdf(&["a", "b"], &joint("spin", kind, "a", "b", "").replace("0 0 1", "0 -0 0"));
        check(&text, &[&["joint `spin`", "axis is zero"]]);
    }
}

/// A chain of `multipliers.len() + 1` revolute joints, each after the first mimicking the one
/// before it with the given multiplier and offset.
fn mimic_chain(kind: &str, limits: &str, mimics: &[(&str, &str)]) -> String {
    let links: Vec<String> = (0..=mimics.len() + 1).map(|i| format!("l{i}")).collect();
    let links: Vec<&str> = links.iter().map(String::as_str).collect();
    let mut joints = joint_with("j0", kind, "l0", "l1", "0 0 0", "0 0 1", limits, "");
    for (i, (multiplier, offset)) in mimics.iter().enumerate() {
        joints += &joint_with(
            &format!("j{}", i + 1),
            kind,
            &format!("l{}", i + 1),
            &format!("l{}", i + 2),
            "0 0 0",
            "0 0 1",
            limits,
            &format!("<mimic joint=\"j{i}\" multiplier=\"{multiplier}\" offset=\"{offset}\"/>"),
        );
    }
    urdf(&links, &joints)
}

#[test]
fn composed_mimic_multipliers_and_offsets_stay_finite() {
    // issue 13: multipliers of 1e200 along a chain composed to 1e400.
    let text = mimic_chain("revolute", "-1\" upper=\"1", &[("1e200", "0"), ("1e200", "0"), ("1e200", "0")]);
    let errors = check(&text, &[&["joint `j2`", "joint `j0`", "mimic multiplier", "not a finite number"]]);
    assert!(matches!(&errors[0], ModelError::MimicOverflow { offset: false, .. }));
    // Offsets compose too: o2 + m2 * o1 = 1e308 + 10 * 1e308.
    let text = mimic_chain("continuous", "", &[("1", "1e308"), ("10", "1e308")]);
    check(&text, &[&["joint `j2`", "mimic offset", "not a finite number"]]);
    // Large but finite compositions are fine: (-1e150)^2 = 1e300.
    let text = mimic_chain("revolute", "-1\" upper=\"1", &[("-1e150", "0.5"), ("-1e150", "0")]);
    let tree = parse_source("ok.urdf", &text).unwrap();
    let j2 = tree.joint_by_name("j2").unwrap();
    assert!(matches!(j2.motion, kinematics_model::JointMotion::Mimic { multiplier, offset, .. }
        if (multiplier / 1e300 - 1.0).abs() < 1e-15 && offset == -0.5e150));
    // Two chains overflowing from one source: each reported once, where it overflows.
    let text = urdf(
        &["a", "b", "c", "d", "e", "f"],
        &[
            joint_with("src", "continuous", "a", "b", "0 0 0", "0 0 1", "", ""),
            joint_with(
                "m1",
                "continuous",
                "b",
                "c",
                "0 0 0",
                "0 0 1",
                "",
                "<mimic joint=\"src\" multiplier=\"1e300\"/>",
            ),
            joint_with(
                "m2",
                "continuous",
                "c",
                "d",
                "0 0 0",
                "0 0 1",
                "",
                "<mimic joint=\"m1\" multiplier=\"-1e300\"/>",
            ),
            joint_with("m3", "continuous", "d", "e", "0 0 0", "0 0 1", "", "<mimic joint=\"m2\" multiplier=\"1\"/>"),
            joint_with("n1", "continuous", "b", "f", "0 0 0", "0 0 1", "", "<mimic joint=\"m1\" multiplier=\"1e10\"/>"),
        ]
        .concat(),
    );
    check(&text, &[&["joint `m2`", "`src`", "multiplier"], &["joint `n1`", "`src`", "multiplier"]]);
}

#[test]
fn the_reach_stays_finite() {
    // issue 13: two fixed joints at x = 1e308 put a link at 2e308.
    let fixed = |name: &str, parent: &str, child: &str, xyz: &str| {
        joint_with(name, "fixed", parent, child, xyz, "0 0 1", "", "")
    };
    let text =
        urdf(&["a", "b", "c"], &[fixed("f1", "a", "b", "1e308 0 0"), fixed("f2", "b", "c", "1e308 0 0")].concat());
    let errors = check(&text, &[&["joint `f2`", "reach", "not a finite number"]]);
    assert!(matches!(&errors[0], ModelError::ReachOverflow { .. }));
    // One offset whose length overflows although each coordinate is finite.
    let text = urdf(&["a", "b"], &fixed("f", "a", "b", "1.5e308 -1.5e308 0"));
    check(&text, &[&["joint `f`", "reach"]]);
    // A prismatic stroke after a long offset.
    let text = urdf(
        &["a", "b", "c"],
        &[
            fixed("f", "a", "b", "0 0 1e308"),
            joint_with("slide", "prismatic", "b", "c", "0 0 0", "1 0 0", "0\" upper=\"1e308", ""),
        ]
        .concat(),
    );
    check(&text, &[&["joint `slide`", "reach"]]);
    // A prismatic mimic slides its multiplier times its source's stroke: 1e300 * (1e10 + 1).
    let text = urdf(
        &["a", "b", "c"],
        &[
            joint_with("slide", "prismatic", "a", "b", "0 0 0", "1 0 0", "0\" upper=\"1e10", ""),
            joint_with(
                "follow",
                "prismatic",
                "b",
                "c",
                "0 0 0",
                "1 0 0",
                "0\" upper=\"1",
                "<mimic joint=\"slide\" multiplier=\"1e300\"/>",
            ),
        ]
        .concat(),
    );
    check(&text, &[&["joint `follow`", "reach"]]);
    // Large offsets that add up to a finite reach are fine (the lengths scale before squaring).
    let text =
        urdf(&["a", "b", "c"], &[fixed("f1", "a", "b", "1e200 1e200 0"), fixed("f2", "b", "c", "-1e307 0 0")].concat());
    let tree = parse_source("ok.urdf", &text).unwrap();
    assert!(tree.reach().is_finite() && tree.reach() >= 1e307);
}

#[test]
fn a_prismatic_joint_with_an_unlimited_side_has_the_reach_of_an_unlimited_one() {
    // The reach counts each prismatic joint's stroke as far as agreement checks slide it: up to
    // 1 beyond finite limits, up to pi + 1 either way when a side is unlimited (it used to be
    // infinite for a half-unlimited joint, and 1 for an unlimited one).
    let slide = |limits: &str| {
        let text = urdf(&["a", "b"], &joint_with("slide", "prismatic", "a", "b", "0 0 0", "1 0 0", limits, ""));
        parse_source("ok.urdf", &text).unwrap().reach()
    };
    let unlimited = std::f64::consts::PI + 1.0;
    assert_eq!(slide("-inf\" upper=\"0.5"), unlimited);
    assert_eq!(slide("0\" upper=\"inf"), unlimited);
    assert_eq!(slide("-inf\" upper=\"inf"), unlimited);
    assert_eq!(slide("-0.5\" upper=\"2"), 3.0);
}

#[test]
fn ball_joints_take_a_quaternion_and_three_velocities() {
    // A hinge, a ball, a free joint mid-tree and a ball below it: the velocities skip one entry
    // per quaternion.
    let mjcf = r#"<mujoco><worldbody>
      <body name="a"><joint name="turn"/>
        <body name="b"><joint name="ball" type="ball"/>
          <body name="c"><joint name="slide" type="slide"/><joint name="wrist" type="ball" pos="0 0 0.5"/></body>
        </body>
      </body></worldbody></mujoco>"#;
    let tree = parse_source("ok.xml", mjcf).unwrap();
    assert_eq!((tree.dof(), tree.velocity_dof()), (10, 8));
    assert_eq!(
        tree.dof_names(),
        ["turn", "ball.qx", "ball.qy", "ball.qz", "ball.qw", "slide", "wrist.qx", "wrist.qy", "wrist.qz", "wrist.qw"]
    );
    assert_eq!(
        tree.velocity_names(),
        ["turn", "ball.wx", "ball.wy", "ball.wz", "slide", "wrist.wx", "wrist.wy", "wrist.wz"]
    );
    let columns = tree.velocity_of_entry();
    assert_eq!(columns, [Some(0), None, None, None, None, Some(4), None, None, None, None]);
    let id = |name: &str| tree.joint_id(name).unwrap();
    assert_eq!(
        ["turn", "ball", "slide", "wrist"].map(|j| tree.velocity_start(id(j))),
        [Some(0), Some(1), Some(4), Some(5)]
    );
    assert_eq!(tree.quaternion_entries(), [1, 6]);
    let kinds: Vec<_> = tree.quaternion_joints().map(|j| tree.joint(j).name.as_str()).collect();
    assert_eq!(kinds, ["ball", "wrist"]);
    assert!(tree.dof_limits().iter().all(Option::is_none));
    let wrist = tree.joint_by_name("wrist").unwrap();
    assert_eq!(wrist.kind, kinematics_model::JointKind::Spherical);
    assert_eq!(wrist.limits, None);
    assert_eq!(tree.chain_dofs(&tree.chain("b", "c").unwrap()), [5, 6, 7, 8, 9]);
}

#[test]
fn a_mimic_of_a_ball_joint_is_refused_by_name() {
    // MJCF cannot write one (its equality refuses a ball joint); the model's rule holds for any
    // description.
    let mjcf = r#"<mujoco><worldbody><body name="a"><joint name="ball" type="ball"/>
      <body name="b"><joint name="follow"/></body></body></worldbody></mujoco>"#;
    let mut description = kinematics_model::mjcf::parse_mjcf(mjcf).unwrap();
    description.joints[1].mimic =
        Some(kinematics_model::MimicDescription { joint: "ball".to_owned(), multiplier: 1.0, offset: 0.0 });
    let errors = kinematics_model::KinematicTree::from_description(&description).unwrap_err();
    let message = errors.to_string();
    assert!(
        message.contains("joint `follow`") && message.contains("a spherical joint takes several values"),
        "{message}"
    );
}

#[test]
fn urdf_spherical_joints_are_refused() {
    // URDF does not define them (MJCF's ball joints are the model's spherical joints).
    let text = urdf(&["a", "b"], &joint("ball", "spherical", "a", "b", ""));
    check(&text, &[&["joint `ball`", "joint type `spherical` is not supported"]]);
}
