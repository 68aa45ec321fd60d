//! The hand-worked test vectors of the reference notes, through every description of the robot.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::reference;
use nalgebra::{Isometry3, Matrix3, UnitQuaternion, Vector3};

const VECTOR_TOLERANCE: f64 = 1e-9;

/// Planar 3R, q = (30, -60, 20) degrees: joint positions (0,0), (0.866025, 0.5), (1.732051, 0),
/// (2.224455, -0.086824); the notes print them to 6 decimals.
const PLANAR_3R_POINTS: [[f64; 2]; 4] = [[0.0, 0.0], [0.866025, 0.5], [1.732051, 0.0], [2.224455, -0.086824]];

fn planar_q() -> [f64; 3] {
    [30f64.to_radians(), -60f64.to_radians(), 20f64.to_radians()]
}

fn assert_point(fk: &kinematics::ReferenceFk, link: &str, expected: [f64; 2], orientation: f64) {
    let pose = fk.link_pose(&planar_q(), link).unwrap();
    let p = pose.translation.vector;
    assert!((p - Vector3::new(expected[0], expected[1], 0.0)).norm() < 1e-6, "{link}: {p} != {expected:?}");
    let expected_rotation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), orientation.to_radians());
    assert!(pose.rotation.angle_to(&expected_rotation) < VECTOR_TOLERANCE, "{link} orientation");
}

#[test]
fn planar_3r_standard_dh() {
    let fk = reference("planar_3r.toml");
    assert_point(&fk, "base", PLANAR_3R_POINTS[0], 0.0);
    assert_point(&fk, "link1", PLANAR_3R_POINTS[1], 30.0);
    assert_point(&fk, "link2", PLANAR_3R_POINTS[2], -30.0);
    assert_point(&fk, "link3", PLANAR_3R_POINTS[3], -10.0);
}

#[test]
fn planar_3r_modified_dh() {
    // Modified DH frames sit at the joint axes: frame i at the start of link i.
    let fk = reference("planar_3r_modified.toml");
    assert_point(&fk, "link1", PLANAR_3R_POINTS[0], 30.0);
    assert_point(&fk, "link2", PLANAR_3R_POINTS[1], -30.0);
    assert_point(&fk, "link3", PLANAR_3R_POINTS[2], -10.0);
    assert_point(&fk, "tool", PLANAR_3R_POINTS[3], -10.0);
}

#[test]
fn planar_3r_urdf() {
    let fk = reference("planar_3r.urdf");
    assert_point(&fk, "link1", PLANAR_3R_POINTS[0], 30.0);
    assert_point(&fk, "link2", PLANAR_3R_POINTS[1], -30.0);
    assert_point(&fk, "link3", PLANAR_3R_POINTS[2], -10.0);
    assert_point(&fk, "tool", PLANAR_3R_POINTS[3], -10.0);
}

/// Every entry of position and rotation matrix within [`VECTOR_TOLERANCE`] (the notes give 9 decimals).
fn assert_entries(got: &Isometry3<f64>, p: [f64; 3], r: [[f64; 3]; 3], what: &str) {
    let dp = (got.translation.vector - Vector3::from(p)).amax();
    let dr = (got.rotation.to_rotation_matrix().matrix() - Matrix3::from_row_slice(&r.concat())).amax();
    assert!(dp.max(dr) < VECTOR_TOLERANCE, "{what}: differs by {dp:e} (position), {dr:e} (rotation)\n{got}");
}

const I3: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

#[test]
fn seed_tree_at_zero() {
    let fk = reference("seed_tree.urdf");
    let q = [0.0; 3];
    let (c, s) = (1.57f64.cos(), 1.57f64.sin());
    let rz157 = [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]];
    let check = |link: &str, p, r| assert_entries(&fk.link_pose(&q, link).unwrap(), p, r, link);
    check("link1", [0.0; 3], I3);
    check("link2", [5.0, 3.0, 0.0], I3);
    check("link3", [-2.0, 5.0, 0.0], rz157);
    check("link4", [-1.996018366, 9.999998415, 0.0], I3);
}

#[test]
fn seed_tree_at_a_general_configuration() {
    let fk = reference("seed_tree.urdf");
    let q = [0.5, -0.3, 1.2];
    assert_entries(
        &fk.link_pose(&q, "link4").unwrap(),
        [-1.884448542, 9.888250756, 1.044821711],
        [
            [0.796479837, -0.158892247, -0.583415052],
            [-0.434305864, 0.520995087, -0.734807823],
            [0.420711641, 0.838640193, 0.345954248],
        ],
        "link4",
    );
    // link3's origin does not move with joint 2 (it turns about an axis through that origin).
    assert_entries(
        &fk.link_pose(&q, "link3").unwrap(),
        [-2.0, 5.0, 0.0],
        [
            [0.023110292, -0.977685718, 0.208797872],
            [0.977650151, -0.021553205, -0.209130680],
            [0.208964342, 0.208964342, 0.955336489],
        ],
        "link3",
    );
}
