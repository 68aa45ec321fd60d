//! A URDF as robots ship them (meshes, materials, inertials, transmissions, gazebo plugins) loads,
//! and only its kinematics is taken from it.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use kinematics::model::JointKind;

#[test]
fn ur5_urdf_with_everything_a_real_file_has() {
    let text = std::fs::read_to_string(common::robot_path("ur5.urdf")).unwrap();
    // The file must really carry the non-kinematic parts, or this test proves nothing.
    for tag in ["<mesh ", "<material ", "<inertial>", "<transmission ", "<gazebo", "<dynamics ", "<collision>"] {
        assert!(text.contains(tag), "ur5.urdf has no {tag}");
    }
    let tree = common::load("ur5.urdf");
    assert_eq!(tree.name(), "ur5");
    assert_eq!(
        tree.dof_names(),
        ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"]
    );
    assert_eq!(tree.link(tree.root()).name, "base_link");
    for link in ["base", "tool0", "ee_link", "wrist_3_link"] {
        assert!(tree.link_by_name(link).is_some(), "{link}");
    }
    let elbow = tree.joint_by_name("elbow_joint").unwrap();
    assert_eq!(elbow.kind, JointKind::Revolute);
    assert_eq!(elbow.velocity_limit, Some(3.15));
    assert_eq!(elbow.effort_limit, Some(150.0));
    let limits = elbow.limits.unwrap();
    assert!((limits.upper - 2.0 * std::f64::consts::PI).abs() < 1e-6 && limits.lower == -limits.upper);
    assert_eq!(tree.joint_by_name("wrist_3_link-tool0_fixed_joint").unwrap().kind, JointKind::Fixed);
}
