//! One robot, several descriptions (standard DH, modified DH, URDF): the frames each one attaches
//! to a link must move together, i.e. differ by a fixed transform, at every configuration.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::pair::{Pair, related_at_zero};
use common::{AGREEMENT_TOLERANCE, assert_pose_eq, reference};
use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;
use std::f64::consts::PI;

fn tx(a: f64) -> Isometry3<f64> {
    Isometry3::translation(a, 0.0, 0.0)
}

fn planar_std_vs_urdf() -> Pair {
    // Standard DH frame i sits at the far end of link i: the URDF link frame moved by a_i along x.
    Pair {
        a: reference("planar_3r.toml"),
        a_base: "base",
        b: reference("planar_3r.urdf"),
        b_base: "base",
        links: vec![
            ("link1", "link1", tx(-1.0)),
            ("link2", "link2", tx(-1.0)),
            ("link3", "link3", tx(-0.5)),
            ("link3", "tool", Isometry3::identity()),
        ],
    }
}

fn planar_modified_vs_urdf() -> Pair {
    // Modified DH frame i sits at joint i, where the URDF puts link i.
    Pair {
        a: reference("planar_3r_modified.toml"),
        a_base: "base",
        b: reference("planar_3r.urdf"),
        b_base: "base",
        links: ["link1", "link2", "link3", "tool"].map(|l| (l, l, Isometry3::identity())).to_vec(),
    }
}

const UR5_LINKS: [&str; 6] =
    ["shoulder_link", "upper_arm_link", "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link"];

fn ur5_std_vs_modified() -> Pair {
    let mut links: Vec<(&str, &str)> = UR5_LINKS.iter().map(|&l| (l, l)).collect();
    links.push(("wrist_3_link", "tool0"));
    related_at_zero(reference("ur5.toml"), "base", reference("ur5_modified.toml"), "base", &links)
}

fn ur5_std_vs_urdf() -> Pair {
    // The URDF's `base` link is the frame of Universal Robots' DH table (frame 0).
    let mut links: Vec<(&str, &str)> = UR5_LINKS.iter().map(|&l| (l, l)).collect();
    links.push(("wrist_3_link", "tool0"));
    related_at_zero(reference("ur5.toml"), "base", reference("ur5.urdf"), "base", &links)
}

fn q(n: usize) -> impl Strategy<Value = Vec<f64>> {
    proptest::collection::vec(-2.0 * std::f64::consts::PI..2.0 * std::f64::consts::PI, n)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn planar_3r_standard_dh_matches_urdf(q in q(3)) {
        planar_std_vs_urdf().check(&q);
    }

    #[test]
    fn planar_3r_modified_dh_matches_urdf(q in q(3)) {
        planar_modified_vs_urdf().check(&q);
    }

    #[test]
    fn ur5_standard_dh_matches_modified_dh(q in q(6)) {
        ur5_std_vs_modified().check(&q);
    }

    #[test]
    fn ur5_standard_dh_matches_urdf(q in q(6)) {
        ur5_std_vs_urdf().check(&q);
    }
}

#[test]
fn ur5_frames_relate_as_published() {
    // Beyond "some fixed transform": ROS-Industrial's `tool0` is the DH flange frame 6 itself, and
    // its `base` is DH frame 0, a half turn about z from `base_link`.
    let pair = ur5_std_vs_urdf();
    let (_, _, tool) = pair.links.last().unwrap();
    assert_pose_eq(tool, &Isometry3::identity(), AGREEMENT_TOLERANCE, "DH frame 6 vs tool0");
    let base = pair.b.relative_pose(&[0.0; 6], "base_link", "base").unwrap();
    let half_turn =
        Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_axis_angle(&Vector3::z_axis(), PI));
    assert_pose_eq(&base, &half_turn, AGREEMENT_TOLERANCE, "base vs base_link");
}
