//! The simplified pose as text and LaTeX, and the numeric evaluator, on hand-checkable robots.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use kinematics_compiler::{Request, compile};

#[test]
fn planar_3r_reads_like_the_textbook() {
    // x = l1 c1 + l2 c12 + l3 c123 with l = (1, 1, 0.5); the joints' angles add up.
    let compiled = compile(&common::robot("planar_3r.toml"), &Request::tip("link3")).unwrap();
    let text = compiled.frame_text(0);
    assert_eq!(text[9], "c1 + c12 + 0.5*c123");
    assert_eq!(text[10], "s1 + s12 + 0.5*s123");
    assert_eq!(text[11], "0");
    assert_eq!(&text[0..2], ["c123", "-s123"]);
    let latex = compiled.frame_latex(0);
    assert_eq!(latex[9], "c_{1} + c_{12} + 0.5 \\, c_{123}");
    assert_eq!(compiled.op_count().sin_cos, 3);
}

#[test]
fn evaluator_matches_the_test_vector() {
    let compiled = compile(&common::robot("planar_3r.toml"), &Request::tip("link3")).unwrap();
    let q = [30f64.to_radians(), -60f64.to_radians(), 20f64.to_radians()];
    let pose = &compiled.eval(&q)[0];
    assert!((pose[9] - 2.224455).abs() < 1e-6 && (pose[10] + 0.086824).abs() < 1e-6, "{pose:?}");
}

#[test]
fn exact_twists_cost_nothing_and_1_5708_is_not_pi_over_2() {
    let exact = "convention = \"standard\"\n[[joints]]\nname = \"a\"\nalpha = \"pi/2\"\n[[joints]]\nname = \"b\"\n";
    let approx = exact.replace("\"pi/2\"", "1.5708");
    let cost = |text: &str| {
        let tree = kinematics_model::parse_source("arm.toml", text).unwrap();
        compile(&tree, &Request::tip("link2")).unwrap().op_count()
    };
    let (exact, approx) = (cost(exact), cost(&approx));
    // Rz(q1) Rx(pi/2) Rz(q2): the quarter turn is a permutation, the product is 4 multiplications.
    assert_eq!((exact.sin_cos, exact.mul, exact.add), (2, 4, 0));
    assert!(approx.mul > exact.mul, "{approx} vs {exact}");
}

#[test]
fn position_only_and_one_branch_cost_less() {
    let tree = common::robot("ur5.toml");
    let pose = compile(&tree, &Request::tip("wrist_3_link")).unwrap().op_count();
    let position = compile(&tree, &Request::tip("wrist_3_link").positions_only()).unwrap().op_count();
    assert!(position.mul < pose.mul && position.add < pose.add, "{position} vs {pose}");
    let tree = common::robot("seed_tree.urdf");
    let branch = compile(&tree, &Request::tip("link2")).unwrap().op_count();
    assert_eq!(branch.sin_cos, 1, "only joint1 moves link2");
}

#[test]
fn unknown_links_are_errors() {
    let tree = common::robot("ur5.toml");
    let err = compile(&tree, &Request::tip("flange")).unwrap_err();
    assert_eq!(err.to_string(), "robot `ur5`: link `flange` does not exist");
    let err = compile(&tree, &Request::tip("link1").with_base("nowhere")).unwrap_err();
    assert_eq!(err.to_string(), "robot `ur5`: link `nowhere` does not exist");
}

/// A ball joint (a spherical joint, MJCF) lowers to its quaternion's rotation between the
/// translations to and back from its `pos`: `T(pos) F(R) T(-pos)`, `R`'s nine entries variables
/// after `q` (four entries) and `qd` (three velocities), which the generated code computes from
/// the quaternion first.
#[test]
fn a_ball_joint_is_its_quaternions_rotation_about_its_pos() {
    use kinematics_compiler::symbolic::{graph::ExprGraph, lower::lower_path, step::steps_text};
    let tree = kinematics_model::parse_source(
        "ball.xml",
        r#"<mujoco><worldbody><body name="b" pos="1 0 0"><joint name="ball" type="ball" pos="0 0.5 0"/>
             <site name="s" pos="1 0 0"/></body></worldbody></mujoco>"#,
    )
    .unwrap();
    let mut g = ExprGraph::new();
    let path = tree.path_from_root(tree.link_id("s").unwrap());
    let steps = lower_path(&mut g, &tree, &path);
    assert_eq!(
        steps_text(&g, &steps),
        "T(1, 0, 0) T(0, 0.5, 0) F(q8, q9, q10; q11, q12, q13; q14, q15, q16) T(0, -0.5, 0) T(1, 0, 0)"
    );
    let compiled = compile(&tree, &Request::tip("s")).unwrap();
    let text = compiled.frame_text(0);
    // The site turns with the body; its origin, (1, -0.5, 0) from the pivot at (1, 0.5, 0), turns
    // by R.
    assert_eq!(text[..3], ["rot1_11", "rot1_12", "rot1_13"]);
    assert_eq!(text[9..], ["1 + rot1_11 - 0.5*rot1_12", "0.5 + rot1_21 - 0.5*rot1_22", "rot1_31 - 0.5*rot1_32"]);
    assert_eq!(compiled.op_count().sin_cos, 0, "no angle: the rotation is the quaternion's");
}
