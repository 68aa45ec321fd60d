//! MJCF (issue 33): the reader against hand-worked poses, the walker against its URDF twin, the
//! MJCF UR5 against the URDF one, includes and attachments, ball joints (hand-worked, and
//! `ball_tree.xml` generated against the runtime reference and against differences along the
//! quaternion's tangent), and errors naming element and line.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::f64::consts::FRAC_PI_2;

use kinematics::ReferenceFk;
use kinematics::model::{ExactAngles, JointKind, KinematicTree, Source, SourceFormat, SourceKind};
use kinematics_compiler::{Request, compile};

fn robot(file: &str) -> String {
    format!("{}/robots/{file}", env!("CARGO_MANIFEST_DIR"))
}

fn load(text: &str) -> Result<KinematicTree, String> {
    let source = Source::from_file_name("t.xml", SourceKind::ByExtension, text).map_err(|e| e.to_string())?;
    assert_eq!(source.format, SourceFormat::Mjcf);
    source.load(ExactAngles::default()).map_err(|e| e.to_string())
}

fn mjcf(text: &str) -> KinematicTree {
    load(text).unwrap_or_else(|e| panic!("{e}"))
}

/// A link's pose at `q`: rotation rows and translation.
fn pose(tree: &KinematicTree, q: &[f64], link: &str) -> ([[f64; 3]; 3], [f64; 3]) {
    let iso = ReferenceFk::new(tree.clone()).link_pose(q, link).unwrap();
    let m = iso.rotation.to_rotation_matrix();
    let r = std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)]));
    (r, iso.translation.vector.into())
}

fn assert_pose(tree: &KinematicTree, q: &[f64], link: &str, r: [[f64; 3]; 3], t: [f64; 3]) {
    let (got_r, got_t) = pose(tree, q, link);
    for i in 0..3 {
        assert!((got_t[i] - t[i]).abs() < 1e-15, "{link}: translation {got_t:?}, expected {t:?}");
        for j in 0..3 {
            assert!((got_r[i][j] - r[i][j]).abs() < 1e-15, "{link}: rotation {got_r:?}, expected {r:?}");
        }
    }
}

#[path = "mjcf/mujoco.rs"]
mod mujoco;

#[path = "mjcf/geometry.rs"]
mod geometry;

#[path = "mjcf/inertial.rs"]
mod inertial;

const I: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
const RZ90: [[f64; 3]; 3] = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];

#[test]
fn a_hinge_off_the_body_origin_rotates_about_its_own_point() {
    // Body b at (1, 0, 0); its hinge through (0, 0.5, 0) in b's frame, i.e. (1, 0.5, 0), about z.
    // At q = pi/2 b's origin, (0, -0.5, 0) from the pivot, turns to (0.5, 0, 0) from it:
    // (1.5, 0.5, 0), and b's axes are Rz(90).
    let tree = mjcf(
        r#"<mujoco><compiler angle="radian"/><worldbody>
             <body name="b" pos="1 0 0"><joint name="j" pos="0 0.5 0" axis="0 0 1"/></body>
           </worldbody></mujoco>"#,
    );
    assert_pose(&tree, &[0.0], "b", I, [1.0, 0.0, 0.0]);
    assert_pose(&tree, &[FRAC_PI_2], "b", RZ90, [1.5, 0.5, 0.0]);
    // Exactly: Trans(b) Trans(pos), the rotation, then Trans(-pos) after it.
    let j = tree.joint_by_name("j").unwrap();
    assert_eq!(j.kind, JointKind::Continuous);
    assert_eq!(j.after_motion, kinematics::model::FixedTransform::identity().translate([0.0, -0.5, 0.0]));
    // `ref`: the body is as written at q = ref (here 90 degrees): at q = 90 degrees it is at
    // (1, 0, 0) unturned; at q = 180 degrees it is where q = 90 degrees put it without a ref.
    let tree = mjcf(
        r#"<mujoco><worldbody>
             <body name="b" pos="1 0 0"><joint name="j" pos="0 0.5 0" axis="0 0 1" ref="90" range="0 180"/></body>
           </worldbody></mujoco>"#,
    );
    assert_pose(&tree, &[FRAC_PI_2], "b", I, [1.0, 0.0, 0.0]);
    assert_pose(&tree, &[2.0 * FRAC_PI_2], "b", RZ90, [1.5, 0.5, 0.0]);
    let limits = tree.joint_by_name("j").unwrap().limits.unwrap();
    assert_eq!((limits.lower, limits.upper), (0.0, std::f64::consts::PI));
}

#[test]
fn several_joints_in_one_body_compose_in_the_order_written() {
    // First a slide along x by q1, then a hinge about z by q2 (MuJoCo applies them in order):
    // at q = (0.5, pi/2) the body is at (0.5, 0, 0) turned by Rz(90). Written the other way
    // round, the slide runs along the turned x axis: (0, 0.5, 0).
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="b">
             <joint name="s" type="slide" axis="1 0 0"/><joint name="h" axis="0 0 1"/>
           </body></worldbody></mujoco>"#,
    );
    assert_pose(&tree, &[0.5, FRAC_PI_2], "b", RZ90, [0.5, 0.0, 0.0]);
    assert_eq!(tree.link_by_name("b.s").map(|l| l.name.as_str()), Some("b.s"));
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="b">
             <joint name="h" axis="0 0 1"/><joint name="s" type="slide" axis="1 0 0"/>
           </body></worldbody></mujoco>"#,
    );
    assert_pose(&tree, &[FRAC_PI_2, 0.5], "b", RZ90, [0.0, 0.5, 0.0]);
}

/// A body `b` oriented by `orientation`, with a site `s` at `site` in it: the site's position in
/// the world is `R site`.
fn oriented(compiler: &str, orientation: &str, site: &str) -> KinematicTree {
    mjcf(&format!(
        r#"<mujoco><compiler {compiler}/><worldbody>
             <body name="b" {orientation}><site name="s" pos="{site}"/></body>
           </worldbody></mujoco>"#
    ))
}

#[test]
fn every_orientation_form_by_hand() {
    let rx90 = [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];
    let rx180 = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]];
    // euler="90 0 0" in degrees (MuJoCo's default unit), sequence xyz: Rx(90) takes y to z.
    let tree = oriented("", r#"euler="90 0 0""#, "0 1 0");
    assert_pose(&tree, &[], "b", rx90, [0.0; 3]);
    assert_pose(&tree, &[], "s", rx90, [0.0, 0.0, 1.0]);
    // Whole degrees are exact: no decimal for the policy to judge.
    assert!(tree.recognised_angles().is_empty());
    // eulerseq="zyx" in radians: Rz(pi/2) then Ry(pi/2) about the turned y, which is the world's
    // -x: Rz(90) Ry(90) = [[0, -1, 0], [0, 0, 1], [-1, 0, 0]] (Rz(90) applied to Ry(90)'s
    // columns (0, 0, -1), (0, 1, 0), (1, 0, 0)); so x goes to (0, 0, -1).
    let tree =
        oriented(r#"angle="radian" eulerseq="zyx""#, r#"euler="1.5707963267948966 1.5707963267948966 0""#, "1 0 0");
    assert_pose(&tree, &[], "b", [[0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0]], [0.0; 3]);
    // The same with fixed axes (ZYX): Ry(90) Rz(90) = [[0, 0, 1], [1, 0, 0], [0, 1, 0]].
    let tree =
        oriented(r#"angle="radian" eulerseq="ZYX""#, r#"euler="1.5707963267948966 1.5707963267948966 0""#, "1 0 0");
    assert_pose(&tree, &[], "s", [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [0.0, 1.0, 0.0]);
    // quat="0 1 0 0": a half turn about x, y to -y.
    let tree = oriented("", r#"quat="0 1 0 0""#, "0 1 0");
    assert_pose(&tree, &[], "s", rx180, [0.0, -1.0, 0.0]);
    // quat="0.7071068 0.7071068 0 0": not unit (MuJoCo normalises), a quarter turn about x to
    // the last bit, which the exactness policy makes exact and lists.
    let tree = oriented("", r#"quat="0.7071068 0.7071068 0 0""#, "0 1 0");
    assert_pose(&tree, &[], "s", rx90, [0.0, 0.0, 1.0]);
    assert_eq!(tree.recognised_angles().len(), 1);
    assert_eq!(tree.recognised_angles()[0].exact.to_string(), "pi/2");
    // axisangle="1 1 1 120": the cyclic permutation x -> y -> z -> x.
    let tree = oriented("", r#"axisangle="1 1 1 120""#, "1 0 0");
    assert_pose(&tree, &[], "s", [[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [0.0, 1.0, 0.0]);
    // axisangle="0 0 -2 -90": a quarter turn about z, exact (one rotation by the angle written).
    let tree = oriented("", r#"axisangle="0 0 -2 -90""#, "1 0 0");
    assert_pose(&tree, &[], "s", RZ90, [0.0, 1.0, 0.0]);
    assert!(tree.recognised_angles().is_empty());
    // xyaxes: x' = (0, 1, 0), y' = (-1, 0, 0): Rz(90).
    let tree = oriented("", r#"xyaxes="0 1 0 -1 0 0""#, "1 0 0");
    assert_pose(&tree, &[], "s", RZ90, [0.0, 1.0, 0.0]);
    // zaxis="0 0 -1": a half turn about x (MuJoCo's choice for the opposite axis).
    let tree = oriented("", r#"zaxis="0 0 -1""#, "0 1 0");
    assert_pose(&tree, &[], "s", rx180, [0.0, -1.0, 0.0]);
    // zaxis="1 0 0": Ry(90) takes z to x: [[0, 0, 1], [0, 1, 0], [-1, 0, 0]], site z to x.
    let tree = oriented("", r#"zaxis="1 0 0""#, "0 0 2");
    assert_pose(&tree, &[], "s", [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]], [2.0, 0.0, 0.0]);
    // A site's fromto: the midpoint, z from `to` towards `from` as MuJoCo's compiler takes it:
    // (0.5, 0, 0) and Ry(-90), z = (-1, 0, 0).
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="b">
             <site name="s" type="capsule" size="0.1" fromto="0 0 0 1 0 0"/>
           </body></worldbody></mujoco>"#,
    );
    assert_pose(&tree, &[], "s", [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]], [0.5, 0.0, 0.0]);
}

#[test]
fn frames_place_their_children_and_named_ones_are_links() {
    // A frame at (0, 0, 1) turned Rz(90) holds body c at (1, 0, 0) in its frame: (0, 1, 1).
    let tree = mjcf(
        r#"<mujoco><worldbody>
             <frame name="f" pos="0 0 1" euler="0 0 90"><body name="c" pos="1 0 0"/></frame>
             <frame pos="0 0 2"><site name="top"/></frame>
           </worldbody></mujoco>"#,
    );
    assert_pose(&tree, &[], "f", RZ90, [0.0, 0.0, 1.0]);
    assert_pose(&tree, &[], "c", RZ90, [0.0, 1.0, 1.0]);
    assert_pose(&tree, &[], "top", I, [0.0, 0.0, 2.0]);
    assert_eq!(tree.links().len(), 4, "world, f, c, top: the unnamed frame is no link");
}

#[test]
fn limits_follow_limited_range_and_autolimits() {
    let joint = |compiler: &str, attributes: &str| {
        load(&format!(
            r#"<mujoco><compiler {compiler}/><worldbody><body name="b"><joint name="j" {attributes}/></body></worldbody></mujoco>"#
        ))
        .map(|t| {
            let j = t.joint_by_name("j").unwrap();
            (j.kind, j.limits.map(|l| (l.lower, l.upper)))
        })
    };
    let deg = |d: f64| d.to_radians();
    assert_eq!(joint("", r#"range="-90 45""#), Ok((JointKind::Revolute, Some((deg(-90.0), deg(45.0))))));
    assert_eq!(joint("", ""), Ok((JointKind::Continuous, None)));
    assert_eq!(joint("", r#"range="-90 45" limited="false""#), Ok((JointKind::Continuous, None)));
    assert_eq!(joint("", r#"type="slide" range="0 0.5""#), Ok((JointKind::Prismatic, Some((0.0, 0.5)))));
    assert_eq!(joint("", r#"type="slide""#), Ok((JointKind::Prismatic, None)));
    assert_eq!(joint(r#"angle="radian""#, r#"range="-1 1""#), Ok((JointKind::Revolute, Some((-1.0, 1.0)))));
    let off = r#"autolimits="false""#;
    assert_eq!(joint(off, r#"range="-1 1" limited="true""#), Ok((JointKind::Revolute, Some((deg(-1.0), deg(1.0))))));
    assert_eq!(joint(off, ""), Ok((JointKind::Continuous, None)));
    assert_eq!(
        joint(off, r#"range="-1 1""#),
        Err("t.xml: joint `j` (line 1): a `range` without `limited=\"true\"` under `<compiler autolimits=\"false\">`"
            .to_owned())
    );
}

#[test]
fn the_walker_is_its_urdf_twin_with_a_floating_base() {
    let from_mjcf = kinematics::load(robot("walker.xml")).unwrap();
    let text = std::fs::read_to_string(robot("walker.urdf")).unwrap();
    let from_urdf = Source::from_file_name("walker.urdf", SourceKind::ByExtension, text)
        .unwrap()
        .load_with_floating_base(ExactAngles::default(), Some("world"))
        .unwrap();
    assert_eq!(from_mjcf.name(), from_urdf.name());
    // The same links; the MJCF pelvis has a box geom (for the mass MuJoCo requires), which
    // the URDF leaves out.
    let bare = |tree: &KinematicTree| {
        tree.links().iter().map(|l| kinematics::model::Link { collisions: Vec::new(), ..l.clone() }).collect::<Vec<_>>()
    };
    assert_eq!(bare(&from_mjcf), bare(&from_urdf));
    let pelvis = from_mjcf.link(from_mjcf.link_id("pelvis").unwrap());
    assert_eq!(pelvis.collisions.len(), 1);
    assert_eq!(pelvis.collisions[0].shape, kinematics::model::collision::Shape::Box { size: [0.2, 0.3, 0.1] });
    assert_eq!(from_mjcf.dof_names(), from_urdf.dof_names());
    assert_eq!(from_mjcf.joints().len(), from_urdf.joints().len());
    for (m, u) in from_mjcf.joints().iter().zip(from_urdf.joints()) {
        // URDF requires effort and velocity limits; MJCF has none: the one difference.
        assert!(u.velocity_limit.is_some() || u.kind != JointKind::Revolute);
        let strip = |j: &kinematics::model::Joint| kinematics::model::Joint {
            velocity_limit: None,
            effort_limit: None,
            ..j.clone()
        };
        assert_eq!(strip(m), strip(u), "joint `{}`", m.name);
    }
    assert_eq!(from_mjcf.recognised_angles(), from_urdf.recognised_angles());
    assert!(from_mjcf.ignored().is_empty());
    // The generated poses of every link are equal, bit for bit.
    let (a, b) = (compile(&from_mjcf, &Request::default()).unwrap(), compile(&from_urdf, &Request::default()).unwrap());
    for k in 0..20 {
        let mut q: Vec<f64> = (0..from_mjcf.dof()).map(|i| ((i * 7 + k * 13) % 17) as f64 / 8.0 - 1.0).collect();
        q[3..7].copy_from_slice(&[0.1, -0.2, 0.3, 0.9]);
        assert_eq!(a.eval(&q), b.eval(&q));
    }
}

#[test]
fn the_mjcf_ur5_is_the_urdf_ur5_with_tool0_a_site() {
    let mjcf = kinematics::load(robot("ur5_mjcf.xml")).unwrap();
    let urdf = kinematics::load(robot("ur5.urdf")).unwrap();
    let (m, u) = (ReferenceFk::new(mjcf.clone()), ReferenceFk::new(urdf));
    for k in 0..50 {
        let q: Vec<f64> = (0..6).map(|i| (((i * 5 + k * 11) % 23) as f64 / 23.0 - 0.5) * 12.0).collect();
        for link in ["base", "shoulder_link", "upper_arm_link", "forearm_link", "wrist_3_link", "ee_link", "tool0"] {
            let (a, b) =
                (m.relative_pose(&q, "base_link", link).unwrap(), u.relative_pose(&q, "base_link", link).unwrap());
            assert!((a.to_homogeneous() - b.to_homogeneous()).iter().all(|e| e.abs() < 1e-14), "{link} at {q:?}");
        }
    }
    // Every fixed rotation is exact: whole degrees (euler, axisangle) as written; the zaxis,
    // xyaxes and quat forms give pi/2 as a number (to the last bit), which the policy recognised
    // and lists, as `inspect` shows.
    let recognised: Vec<&str> = mjcf.recognised_angles().iter().map(|r| r.joint.as_str()).collect();
    assert_eq!(recognised, ["shoulder_lift_joint", "ee_link", "tool0"]);
    assert!(mjcf.recognised_angles().iter().all(|r| r.change().abs() < 1e-15));
    let ik = kinematics_compiler::ik::classify(&mjcf, "base_link", "tool0").unwrap();
    let ik_urdf =
        kinematics_compiler::ik::classify(&kinematics::load(robot("ur5.urdf")).unwrap(), "base_link", "tool0");
    assert_eq!(ik.family(), ik_urdf.unwrap().family());
}

#[test]
fn equalities_other_than_linear_joint_couplings_are_listed_not_applied() {
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="a"><joint name="j1" ref="10"/>
             <body name="b"><joint name="j2" ref="20"/><body name="c"><joint name="j3"/></body></body></body>
           </worldbody>
           <equality>
             <joint joint1="j2" joint2="j1" polycoef="0.1 2 0 0 0"/>
             <joint joint1="j3" joint2="j1" polycoef="0 1 0.5 0 0"/>
             <connect name="loop" body1="a" body2="c" anchor="0 0 0"/>
             <joint joint1="j3" joint2="j1" active="false"/>
           </equality></mujoco>"#,
    );
    // y - y0 = a0 + a1 (x - x0): j2 = 2 j1 + 0.1 + 20 deg - 2 * 10 deg = 2 j1 + 0.1.
    let j2 = tree.joint_by_name("j2").unwrap();
    assert!(matches!(j2.motion, kinematics::model::JointMotion::Mimic { multiplier, offset, .. }
        if multiplier == 2.0 && (offset - 0.1).abs() < 1e-15));
    assert_eq!(tree.dof(), 2);
    assert_eq!(
        tree.ignored(),
        [
            "<equality><joint> (line 6): a polynomial of degree above 1, not applied",
            "<equality><connect name=\"loop\"> (line 7): not kinematics of a tree, not applied",
            "<equality><joint> (line 8): inactive, not applied",
        ]
    );
}

#[test]
fn defaults_classes_and_childclass() {
    let tree = mjcf(
        r#"<mujoco>
             <default><joint axis="1 0 0"/>
               <default class="arm"><joint range="-10 10"/>
                 <default class="wrist"><joint axis="0 1 0"/></default></default></default>
             <worldbody><body name="a" childclass="arm"><joint name="j1"/>
               <body name="b"><joint name="j2" class="wrist"/><joint name="j3" class="main"/></body></body>
             </worldbody></mujoco>"#,
    );
    let j = |n: &str| tree.joint_by_name(n).unwrap().clone();
    assert_eq!((j("j1").axis, j("j1").kind), ([1.0, 0.0, 0.0], JointKind::Revolute));
    assert_eq!((j("j2").axis, j("j2").kind), ([0.0, 1.0, 0.0], JointKind::Revolute));
    assert_eq!((j("j3").axis, j("j3").kind), ([1.0, 0.0, 0.0], JointKind::Continuous));
    // Two top-level <default>s both fill class `main`.
    let tree = mjcf(
        r#"<mujoco><default><joint axis="1 0 0"/></default><default><joint range="-1 1"/></default>
             <worldbody><body name="a"><joint name="j"/></body></worldbody></mujoco>"#,
    );
    let j = tree.joint_by_name("j").unwrap();
    assert_eq!((j.axis, j.kind), ([1.0, 0.0, 0.0], JointKind::Revolute));
}

/// A directory of its own under the system's temporary one, for files that include others.
fn scratch(name: &str, files: &[(&str, &str)]) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("kinematics-mjcf-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (file, text) in files {
        std::fs::write(dir.join(file), text).unwrap();
    }
    dir
}

#[test]
fn includes_and_attached_models_are_read_relative_to_the_main_file() {
    let dir = scratch(
        "include",
        &[
            (
                "main.xml",
                r#"<mujoco model="m"><include file="defaults.xml"/>
                   <asset><model name="gripper" file="gripper.xml"/></asset>
                   <worldbody><body name="arm"><joint name="j"/>
                     <include file="tool.xml"/>
                     <attach model="gripper" body="palm" prefix="g_"/>
                   </body></worldbody></mujoco>"#,
            ),
            ("defaults.xml", r#"<mujoco><default><joint axis="0 1 0" range="-1 1"/></default></mujoco>"#),
            ("tool.xml", r#"<mujoco><site name="tcp" pos="0 0 0.5"/></mujoco>"#),
            // The attached file keeps its own compiler settings (radians) and classes.
            (
                "gripper.xml",
                r#"<mujoco><compiler angle="radian"/><default><joint axis="1 0 0" range="-2 2"/></default>
                   <worldbody><body name="palm" pos="0 0 1"><joint name="roll"/></body></worldbody>
                   <equality><weld body1="palm"/></equality></mujoco>"#,
            ),
        ],
    );
    let tree = kinematics::load(dir.join("main.xml")).unwrap();
    let j = tree.joint_by_name("j").unwrap();
    assert_eq!(j.axis, [0.0, 1.0, 0.0]);
    assert_eq!(j.limits.map(|l| l.upper), Some(1f64.to_radians()));
    let roll = tree.joint_by_name("g_roll").unwrap();
    assert_eq!((roll.axis, roll.limits.map(|l| l.upper)), ([1.0, 0.0, 0.0], Some(2.0)));
    assert_pose(&tree, &[0.0, 0.0], "tcp", I, [0.0, 0.0, 0.5]);
    assert_pose(&tree, &[0.0, 0.0], "g_palm", I, [0.0, 0.0, 1.0]);
    assert_eq!(
        tree.ignored(),
        ["<equality><weld> (line 3 of `gripper.xml`, attached as `gripper`): not kinematics of a tree, not applied"]
    );
    // Without a file reader an include is refused, naming its line.
    let text = std::fs::read_to_string(dir.join("main.xml")).unwrap();
    let error = load(&text).unwrap_err();
    assert_eq!(
        error,
        "t.xml: line 1: cannot read `defaults.xml`: `defaults.xml` cannot be read here (no file reader was given)"
    );
    // A missing file, and an error inside an included file, each name the file and line.
    let dir = scratch(
        "missing",
        &[
            ("main.xml", "<mujoco>\n  <include file=\"nowhere.xml\"/>\n</mujoco>"),
            ("bad.xml", "<mujoco>\n  <include file=\"part.xml\"/>\n</mujoco>"),
            (
                "part.xml",
                "<mujoco>\n<worldbody>\n  <body name=\"b\"><joint name=\"j\" type=\"hinj\"/></body>\n</worldbody></mujoco>",
            ),
        ],
    );
    let error = kinematics::load(dir.join("main.xml")).unwrap_err().kind.to_string();
    assert!(error.starts_with("line 2: cannot read `nowhere.xml`: "), "{error}");
    let error = kinematics::load(dir.join("bad.xml")).unwrap_err().kind.to_string();
    assert_eq!(error, "in `part.xml`: joint `j` (line 3): `type=\"hinj\"` is not one of hinge, slide, ball, free");
}

#[test]
fn errors_name_the_element_and_the_line() {
    let check = |body: &str, expected: &str| {
        let text = format!("<mujoco>\n<worldbody>\n{body}\n</worldbody>\n</mujoco>");
        assert_eq!(load(&text).unwrap_err(), expected, "{body}");
    };
    check(
        r#"<body name="b"><joint name="j" type="screw"/></body>"#,
        "t.xml: joint `j` (line 3): `type=\"screw\"` is not one of hinge, slide, ball, free",
    );
    check(
        r#"<body name="b"><joint name="j" type="ball" axis="0 0 1"/></body>"#,
        "t.xml: joint `j` (line 3): a ball joint takes no `axis` (it turns about every axis through its `pos`)",
    );
    // An unnamed element is named by its MuJoCo id, and an error in it says so by that name.
    check(
        r#"<body><joint type="screw"/></body>"#,
        "t.xml: joint `joint0` (line 3): `type=\"screw\"` is not one of hinge, slide, ball, free",
    );
    check(
        r#"<body name="b" quat="0 0 0 0"/>"#,
        "t.xml: body `b` (line 3): `quat=\"0 0 0 0\"` is no rotation (a zero or parallel vector)",
    );
    check(r#"<body name="b" pos="1 2"/>"#, "t.xml: body `b` (line 3): `pos=\"1 2\"` needs 3 numbers, found 2");
    check(
        r#"<body name="b" euler="0 0 0" quat="1 0 0 0"/>"#,
        "t.xml: body `b` (line 3): more than one orientation (`quat` and `euler`): write one",
    );
    check(r#"<body name="b" colour="red"/>"#, "t.xml: body `b` (line 3): <body>: unknown attribute `colour`");
    check(r#"<body name="b"><jiont name="j"/></body>"#, "t.xml: line 3: unknown element <jiont> in <body>");
    assert_eq!(
        load("<mujoco>\n<worldbdy/>\n</mujoco>").unwrap_err(),
        "t.xml: line 2: unknown element <worldbdy> in <mujoco>"
    );
    check(
        r#"<body name="a"><body name="b"><freejoint/></body></body>"#,
        "t.xml: joint `joint0` (line 3): a free joint must be the only joint of a body whose parent is the world body",
    );
    check(
        r#"<body name="b"><joint name="j" class="arm"/></body>"#,
        "t.xml: joint `j` (line 3): default class `arm` does not exist",
    );
    assert_eq!(
        load("<mujoco/>\n<mujoco/>").unwrap_err(),
        "t.xml: line 2: a second root element: an MJCF file holds one <mujoco>"
    );
    let bad_sequence = "<mujoco>\n  <compiler eulerseq=\"xyw\"/>\n</mujoco>";
    assert_eq!(load(bad_sequence).unwrap_err(), "t.xml: line 2: `eulerseq=\"xyw\"`: only x, y, z, X, Y, Z name axes");
    // A model rule broken: the joint named as the model's rules name it.
    check(
        r#"<body name="b"><joint name="j" range="10 -10"/></body>"#,
        "t.xml: joint `j`: lower limit 0.17453292519943295 is greater than upper limit -0.17453292519943295",
    );
}

#[test]
fn xml_files_are_urdf_or_mjcf_by_their_root_element_and_explicit_kinds_are_obeyed() {
    let text = "<mujoco><worldbody><body name=\"b\"/></worldbody></mujoco>";
    let by = |name: &str, kind| SourceFormat::detect(name, kind, text);
    assert_eq!(by("r.xml", SourceKind::ByExtension), Some(SourceFormat::Mjcf));
    assert_eq!(by("r.XML", SourceKind::ByExtension), Some(SourceFormat::Mjcf));
    assert_eq!(by("r.mjcf", SourceKind::ByExtension), Some(SourceFormat::Mjcf));
    assert_eq!(by("r.txt", SourceKind::Mjcf), Some(SourceFormat::Mjcf));
    assert_eq!(by("r.urdf", SourceKind::ByExtension), Some(SourceFormat::Urdf));
    assert_eq!(SourceFormat::detect("r.xml", SourceKind::ByExtension, "<robot name=\"r\"/>"), Some(SourceFormat::Urdf));
    let as_urdf = Source::from_file_name("r.xml", SourceKind::Urdf, text).unwrap().load(ExactAngles::default());
    assert_eq!(as_urdf.unwrap_err().to_string(), "r.xml: line 1: the root element is <mujoco>, not <robot>");
    let source = Source::from_file_name("r.txt", SourceKind::Mjcf, text).unwrap();
    assert_eq!(source.file_name(), "r.txt.mjcf");
    assert_eq!(source.load(ExactAngles::default()).unwrap().links().len(), 2);
    let urdf_as_mjcf = Source::from_file_name("r.xml", SourceKind::Mjcf, "<robot name=\"r\"/>").unwrap();
    assert_eq!(
        urdf_as_mjcf.load(ExactAngles::Off).unwrap_err().to_string(),
        "r.xml: line 1: the root element is <robot>, not <mujoco>"
    );
}

/// The UR5 as MJCF derives like the URDF one, its site `tool0` the tip of every function, the
/// closed-form inverse kinematics included.
#[derive(kinematics::Kinematics)]
#[kinematics(mjcf = "robots/ur5_mjcf.xml", base = "base_link", tip = "tool0", jacobians, ik)]
struct Ur5Mjcf;

#[derive(kinematics::Kinematics)]
#[kinematics(urdf = "robots/ur5.urdf", base = "base_link", tip = "tool0", jacobians, ik)]
struct Ur5Urdf;

#[test]
fn a_site_is_the_tip_of_every_function_inverse_kinematics_included() {
    let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
    let (pose, urdf) = (Ur5Mjcf::tip_pose(&q), Ur5Urdf::tip_pose(&q));
    for i in 0..3 {
        assert!((pose.translation[i] - urdf.translation[i]).abs() < 1e-14);
        for j in 0..3 {
            assert!((pose.rotation[i][j] - urdf.rotation[i][j]).abs() < 1e-14);
        }
    }
    let reference = Ur5Mjcf::reference().unwrap().relative_pose(&q, "base_link", "tool0").unwrap();
    assert!((pose.to_isometry().to_homogeneous() - reference.to_homogeneous()).iter().all(|e| e.abs() < 1e-14));
    let jacobian = Ur5Mjcf::tip_jacobian(&q);
    assert!(
        jacobian.iter().flatten().zip(Ur5Urdf::tip_jacobian(&q).iter().flatten()).all(|(a, b)| (a - b).abs() < 1e-14)
    );
    let solutions = Ur5Mjcf::tip_ik(&pose).unwrap();
    assert_eq!(solutions.exact().count(), 8);
    assert!(solutions.exact().any(|s| s.q.iter().zip(&q).all(|(a, b)| (a - b).abs() < 1e-9)));
}

/// mjcf-rs (dimforge's MJCF reader, which folds frames and orientation forms into each body's
/// pose by code of its own) as a second witness: every body's and named site's frame in its
/// parent body's, at `q = 0` (every quaternion the identity), equal to ours by the runtime
/// reference.
#[test]
fn mjcf_rs_reads_the_same_body_and_site_frames() {
    use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion};
    let iso = |p: &mjcf_rs::Pose| {
        let (r, t) = (p.rotation, p.translation);
        let rotation = UnitQuaternion::from_quaternion(Quaternion::new(r.w, r.x, r.y, r.z));
        Isometry3::from_parts(Translation3::new(t.x, t.y, t.z), rotation)
    };
    for file in ["ur5_mjcf.xml", "walker.xml", "ball_tree.xml"] {
        let model = mjcf_rs::Model::from_file(robot(file)).unwrap();
        let tree = kinematics::load(robot(file)).unwrap();
        let fk = ReferenceFk::new(tree.clone());
        let mut q = vec![0.0; tree.dof()];
        for start in tree.quaternion_entries() {
            // The identity quaternion: a free body's pose is q's, not the file's, and a ball
            // joint's body is as written.
            q[start + 3] = 1.0;
        }
        let name = |i: usize| model.bodies[i].body.name.clone().unwrap_or_else(|| "world".to_owned());
        let mut compared = 0;
        for (i, entry) in model.bodies.iter().enumerate() {
            let body = name(i);
            let free = entry.body.joints.iter().any(|j| j.type_ == mjcf_rs::body::JointType::Free);
            if let Some(parent) = entry.parent
                && !free
            {
                let ours = fk.relative_pose(&q, &name(parent), &body).unwrap();
                let theirs = iso(&entry.body.pose);
                assert!(
                    (ours.to_homogeneous() - theirs.to_homogeneous()).iter().all(|e| e.abs() < 1e-12),
                    "{file}: body {body}"
                );
                compared += 1;
            }
            for site in &entry.body.sites {
                let Some(site_name) = &site.name else { continue };
                let ours = fk.relative_pose(&q, &body, site_name).unwrap();
                assert!(
                    (ours.to_homogeneous() - iso(&site.pose).to_homogeneous()).iter().all(|e| e.abs() < 1e-12),
                    "{file}: {site_name}"
                );
                compared += 1;
            }
        }
        assert!(compared >= 9, "{file}: {compared}");
    }
}

/// Ball joints (spherical joints): `q` holds the body's orientation as a quaternion
/// `qx, qy, qz, qw` (normalised), turning it about the joint's `pos`.
#[test]
fn a_ball_joint_turns_its_body_about_its_pos_by_the_quaternion() {
    // Body b at (1, 0, 0); its ball joint at (0, 0.5, 0) in b's frame, i.e. (1, 0.5, 0); a site
    // s at (1, 0, 0) in b. A quarter turn about z, (0, 0, 1, 1) normalised: b's origin,
    // (0, -0.5, 0) from the pivot, turns to (0.5, 0, 0) from it: (1.5, 0.5, 0), axes Rz(90); the
    // site, (1, -0.5, 0) from the pivot, to (0.5, 1, 0): (1.5, 1.5, 0).
    let tree = mjcf(
        r#"<mujoco><worldbody>
             <body name="b" pos="1 0 0"><joint name="ball" type="ball" pos="0 0.5 0"/><site name="s" pos="1 0 0"/></body>
           </worldbody></mujoco>"#,
    );
    let ball = tree.joint_by_name("ball").unwrap();
    assert_eq!((ball.kind, ball.limits), (JointKind::Spherical, None));
    assert_eq!(ball.after_motion, kinematics::model::FixedTransform::identity().translate([0.0, -0.5, 0.0]));
    assert_eq!(tree.dof_names(), ["ball.qx", "ball.qy", "ball.qz", "ball.qw"]);
    assert_eq!(tree.velocity_names(), ["ball.wx", "ball.wy", "ball.wz"]);
    // The identity: as written.
    assert_pose(&tree, &[0.0, 0.0, 0.0, 1.0], "b", I, [1.0, 0.0, 0.0]);
    assert_pose(&tree, &[0.0, 0.0, 0.0, 1.0], "s", I, [2.0, 0.0, 0.0]);
    let quarter = [0.0, 0.0, 1.0, 1.0];
    assert_pose(&tree, &quarter, "b", RZ90, [1.5, 0.5, 0.0]);
    assert_pose(&tree, &quarter, "s", RZ90, [1.5, 1.5, 0.0]);
    // A half turn about x, (1, 0, 0, 0): the site stays on the line through the pivot along x,
    // b's origin goes to (1, 1, 0), its y and z axes reversed.
    let rx180 = [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]];
    assert_pose(&tree, &[1.0, 0.0, 0.0, 0.0], "b", rx180, [1.0, 1.0, 0.0]);
    assert_pose(&tree, &[1.0, 0.0, 0.0, 0.0], "s", rx180, [2.0, 1.0, 0.0]);
    // The compiled poses are the same numbers.
    let compiled = compile(&tree, &Request::tip("s")).unwrap();
    let [pose] = compiled.eval(&quarter)[..] else { panic!("one frame") };
    let expected = [0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.5, 1.5, 0.0];
    assert!(pose.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-15), "{pose:?}");
    // `limited="false"` keeps a written range from limiting the joint; a default class's axis
    // and ref (meant for the class's hinges) are ignored, as MuJoCo ignores them.
    let tree = mjcf(
        r#"<mujoco><default><joint axis="1 0 0" ref="10" range="-1 1" limited="false"/></default>
             <worldbody><body name="b"><joint name="ball" type="ball"/></body></worldbody></mujoco>"#,
    );
    assert_eq!(tree.joint_by_name("ball").unwrap().kind, JointKind::Spherical);
    assert_pose(&tree, &[0.0, 0.0, 0.0, 2.0], "b", I, [0.0; 3]);
}

#[test]
fn ball_joints_refuse_what_they_cannot_mean() {
    let check = |text: &str, expected: &str| assert_eq!(load(text).unwrap_err(), expected, "{text}");
    let body = |joint: &str| format!("<mujoco>\n<worldbody>\n<body name=\"b\">{joint}</body>\n</worldbody>\n</mujoco>");
    check(
        &body(r#"<joint name="j" type="ball" ref="10"/>"#),
        "t.xml: joint `j` (line 3): a ball joint takes no `ref` (its `qpos0` is the body as written)",
    );
    check(
        &body(r#"<joint name="j" type="ball" range="0 45"/>"#),
        "t.xml: joint `j` (line 3): a ball joint's `range` is a cone limit (its largest angle from the body as \
         written), which is not modelled: remove it or write `limited=\"false\"`",
    );
    // From a default class too, naming the class's line.
    check(
        "<mujoco>\n<default><joint range=\"0 45\"/></default>\n<worldbody><body name=\"b\">\n<joint name=\"j\" \
         type=\"ball\"/>\n</body></worldbody></mujoco>",
        "t.xml: joint `j` (line 2): a ball joint's `range` is a cone limit (its largest angle from the body as \
         written), which is not modelled: remove it or write `limited=\"false\"`",
    );
    check(
        &body(r#"<joint name="j" type="ball" limited="true"/>"#),
        "t.xml: joint `j` (line 3): `limited=\"true\"` needs a `range`",
    );
    // An equality couples hinges and slides: a ball or free joint named by one is refused, at the
    // attribute's line, whichever side it is on and whether or not the coupling is active.
    let coupled = |free: &str, equality: &str| {
        format!(
            "<mujoco>\n<worldbody>\n<body name=\"a\">{free}<body name=\"b\"><joint name=\"ball\" type=\"ball\"/>\
             <body name=\"c\"><joint name=\"hinge\"/></body></body></body>\n</worldbody>\n<equality>\n{equality}\n\
             </equality>\n</mujoco>"
        )
    };
    let refused = |line: usize, joint: &str, kind: &str| {
        format!(
            "t.xml: line {line}: <equality><joint>: `{joint}` is a {kind} joint (a quaternion in `q`, not one \
             value): only hinges and slides are coupled"
        )
    };
    check(&coupled("", r#"<joint joint1="hinge" joint2="ball"/>"#), &refused(6, "ball", "ball"));
    check(&coupled("", r#"<joint joint1="ball" joint2="hinge" active="false"/>"#), &refused(6, "ball", "ball"));
    check(&coupled("", r#"<joint joint1="ball"/>"#), &refused(6, "ball", "ball"));
    check(
        &coupled("<freejoint name=\"free\"/>", r#"<joint joint1="hinge" joint2="free"/>"#),
        &refused(6, "free", "free"),
    );
    // A zero quaternion has no rotation: the reference refuses it, naming the joint.
    let tree = mjcf(&body(r#"<joint name="j" type="ball"/>"#));
    let error = ReferenceFk::new(tree).link_poses(&[0.0; 4]).unwrap_err();
    assert_eq!(
        error.to_string(),
        "robot `MuJoCo Model`: the quaternion of spherical joint `j` (q[0..4]) has no length to normalise"
    );
}

/// `robots/ball_tree.xml`: a free torso, a ball shoulder off its body's origin, three hinges in
/// one body, a ball wrist and a ball neck; every tip's pose, position, Jacobians and twists.
#[derive(kinematics::Kinematics)]
#[kinematics(mjcf = "robots/ball_tree.xml", tips("left_hand", "right_tool", "eye"), positions, jacobians)]
struct BallTree;

/// Deterministic values in [-1, 1).
fn values(count: usize, seed: u64) -> Vec<f64> {
    let mut state = seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1;
    (0..count)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 52) as f64 - 1.0
        })
        .collect()
}

/// A configuration of `tree` with every quaternion a random unit one (four values in [-1, 1)
/// drawn until their length is at least 0.25, then normalised), the other entries in [-2, 2).
fn unit_configuration(tree: &KinematicTree, seed: u64) -> Vec<f64> {
    let mut q: Vec<f64> = values(tree.dof(), seed).iter().map(|v| 2.0 * v).collect();
    for (k, start) in tree.quaternion_entries().into_iter().enumerate() {
        let mut draw = seed * 1000 + k as u64 * 10;
        let quaternion = loop {
            let v = values(4, draw);
            let norm = v.iter().map(|x| x * x).sum::<f64>().sqrt();
            if norm >= 0.25 {
                break v.iter().map(|x| x / norm).collect::<Vec<_>>();
            }
            draw += 1;
        };
        q[start..start + 4].copy_from_slice(&quaternion);
    }
    q
}

#[test]
fn the_ball_tree_agrees_with_the_reference_at_random_unit_quaternions() {
    assert_eq!((BallTree::DOF, BallTree::VELOCITY_DOF), (24, 20));
    assert_eq!(
        BallTree::JOINT_NAMES[7..11],
        ["left_shoulder.qx", "left_shoulder.qy", "left_shoulder.qz", "left_shoulder.qw"]
    );
    assert_eq!(BallTree::VELOCITY_NAMES[6..9], ["left_shoulder.wx", "left_shoulder.wy", "left_shoulder.wz"]);
    let reference = BallTree::reference().unwrap();
    let tree = reference.tree();
    assert_eq!(tree.quaternion_entries(), [3, 7, 16, 20]);
    let reach = tree.reach().max(1.0);
    let close = |what: &str, got: f64, expected: f64, tolerance: f64| {
        assert!(got.is_finite() && (got - expected).abs() <= tolerance, "{what}: {got} vs {expected}");
    };
    for seed in 1..=40 {
        let q: [f64; 24] = unit_configuration(tree, seed).try_into().unwrap();
        let qd: [f64; 20] = values(20, seed + 500).try_into().unwrap();
        let (poses, positions) = (BallTree::tip_poses(&q), BallTree::tip_positions(&q));
        let (lwa, local) = (BallTree::tip_jacobians(&q), BallTree::tip_jacobians_local(&q));
        let (twists, twists_local) = (BallTree::tip_twists(&q, &qd), BallTree::tip_twists_local(&q, &qd));
        for (k, tip) in BallTree::TIPS.iter().enumerate() {
            let expected = reference.relative_pose(&q, "world", tip).unwrap();
            let deviation = poses[k].deviation(&expected, reach);
            assert!(deviation <= 1e-12, "{tip} at seed {seed}: pose deviates by {deviation:e}");
            for (r, position) in positions[k].iter().enumerate() {
                close(&format!("{tip} position"), *position, expected.translation.vector[r], 1e-12 * reach);
            }
            for (frame, jacobian, twist) in [
                (kinematics::model::JacobianFrame::LocalWorldAligned, &lwa[k], &twists[k]),
                (kinematics::model::JacobianFrame::Local, &local[k], &twists_local[k]),
            ] {
                let j = reference.jacobian_in(&q, "world", tip, frame).unwrap();
                assert_eq!(j.ncols(), 20);
                for row in 0..6 {
                    let scale = if row < 3 { reach } else { 1.0 };
                    for col in 0..20 {
                        close(
                            &format!("{tip} J[{row}][{col}] ({frame:?})"),
                            jacobian[row][col],
                            j[(row, col)],
                            1e-12 * scale,
                        );
                    }
                    let jqd: f64 = (0..20).map(|c| j[(row, c)] * qd[c]).sum();
                    close(&format!("{tip} twist[{row}] ({frame:?})"), twist[row], jqd, 1e-11 * scale);
                }
            }
        }
        // Every link, and a quaternion of any length gives the same poses.
        let links = BallTree::link_poses(&q);
        let mut scaled = q;
        for start in tree.quaternion_entries() {
            for v in &mut scaled[start..start + 4] {
                *v *= 0.3 + seed as f64 / 10.0;
            }
        }
        let again = BallTree::link_poses(&scaled);
        for (i, link) in BallTree::LINK_NAMES.iter().enumerate() {
            let expected = reference.link_pose(&q, link).unwrap();
            assert!(links[i].deviation(&expected, reach) <= 1e-12, "{link}");
            assert!(again[i].deviation(&expected, reach) <= 1e-12, "{link}, scaled quaternions");
        }
    }
    // A zero quaternion has no rotation: NaN from the generated code.
    let mut zero = unit_configuration(tree, 1);
    zero[7..11].copy_from_slice(&[0.0; 4]);
    let zero: [f64; 24] = zero.try_into().unwrap();
    assert!(BallTree::tip_poses(&zero)[0].rotation[0][0].is_nan());
}

/// The generated Jacobian's columns of every ball joint are the derivatives of the generated pose
/// along the quaternion's tangent: `q` moved by `h` along angular velocity `e_k` is the
/// quaternion times `exp(h e_k / 2)` (turning the body about its own axis `k`), and the central
/// differences of the tip's position and orientation (`dR R^T`) match the columns (the linear rows
/// and the angular ones, in base axes).
#[test]
fn ball_joint_columns_are_the_pose_differentiated_along_the_quaternion() {
    use nalgebra::{Quaternion, UnitQuaternion, Vector3};
    let reference = BallTree::reference().unwrap();
    let tree = reference.tree();
    let balls: Vec<_> =
        tree.joints().iter().filter(|j| j.kind == JointKind::Spherical).map(|j| j.name.clone()).collect();
    assert_eq!(balls, ["left_shoulder", "right_wrist", "neck"]);
    let mut checked = 0;
    for seed in 1..=10 {
        let q: [f64; 24] = unit_configuration(tree, seed).try_into().unwrap();
        let jacobians = BallTree::tip_jacobians(&q);
        for name in &balls {
            let id = tree.joint_id(name).unwrap();
            let (kinematics::model::JointMotion::Dof(start), Some(column)) =
                (tree.joint(id).motion, tree.velocity_start(id))
            else {
                panic!("{name} is independent")
            };
            for k in 0..3 {
                let moved = |h: f64| {
                    let turned = UnitQuaternion::from_quaternion(Quaternion::new(
                        q[start + 3],
                        q[start],
                        q[start + 1],
                        q[start + 2],
                    )) * UnitQuaternion::from_scaled_axis(Vector3::ith(k, h));
                    let mut moved = q;
                    moved[start..start + 4].copy_from_slice(turned.coords.as_slice());
                    BallTree::tip_poses(&moved)
                };
                let h = 1e-6;
                let (plus, minus) = (moved(h), moved(-h));
                for (t, tip) in BallTree::TIPS.iter().enumerate() {
                    let (p, m) = (plus[t].to_isometry(), minus[t].to_isometry());
                    let linear = (p.translation.vector - m.translation.vector) / (2.0 * h);
                    let turn = (p.rotation * m.rotation.inverse()).scaled_axis() / (2.0 * h);
                    let j = &jacobians[t];
                    for r in 0..3 {
                        let what = format!("{tip}, {name} w{k}, row {r}, seed {seed}");
                        assert!(
                            (j[r][column + k] - linear[r]).abs() < 1e-7,
                            "{what}: {} vs {}",
                            j[r][column + k],
                            linear[r]
                        );
                        assert!(
                            (j[r + 3][column + k] - turn[r]).abs() < 1e-7,
                            "{what}: {} vs {}",
                            j[r + 3][column + k],
                            turn[r]
                        );
                    }
                    checked += 1;
                }
            }
        }
    }
    assert_eq!(checked, 10 * 3 * 3 * 3);
}

/// The hand-worked case on the robot: the neck a quarter turn about z, the torso at the origin
/// unturned. The neck turns about (0, 0, 0.25) in the torso (the head at (0, 0, 0.3), the joint
/// at -0.05 along its z); the eye, (0.1, 0, 0.08) from the head, is (0.1, 0, 0.13) from the pivot,
/// which the turn takes to (0, 0.1, 0.13): (0, 0.1, 0.38), its axes Rz(90).
#[test]
fn the_ball_trees_neck_turned_a_quarter_about_z() {
    let mut q = [0.0; 24];
    q[6] = 1.0; // the torso's quaternion: the identity
    for start in [7, 16] {
        q[start + 3] = 1.0;
    }
    q[20..24].copy_from_slice(&[0.0, 0.0, 0.5_f64.sqrt(), 0.5_f64.sqrt()]);
    let eye = BallTree::tip_poses(&q)[2];
    let expected = [0.0, 0.1, 0.38];
    assert!(eye.translation.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-15), "{:?}", eye.translation);
    let rotation = eye.rotation.iter().flatten().zip(RZ90.iter().flatten());
    assert!(rotation.into_iter().all(|(a, b)| (a - b).abs() < 1e-15), "{:?}", eye.rotation);
    // The neck's columns: the eye's origin turns about the head's axes through the pivot; about
    // the head's z (the world's z) it moves along -x at 0.1 m/rad.
    let j = BallTree::tip_jacobians(&q)[2];
    let column = BallTree::VELOCITY_NAMES.iter().position(|n| *n == "neck.wz").unwrap();
    let expected = [-0.1, 0.0, 0.0, 0.0, 0.0, 1.0];
    for (row, e) in expected.iter().enumerate() {
        assert!((j[row][column] - e).abs() < 1e-15, "row {row}: {}", j[row][column]);
    }
}

#[test]
fn a_name_given_twice_is_refused_naming_both_elements_their_kinds_and_lines() {
    let check = |body: &str, expected: &str| {
        let text = format!("<mujoco>\n<worldbody>\n{body}\n</worldbody>\n</mujoco>");
        assert_eq!(load(&text).unwrap_err(), expected, "{body}");
    };
    check(
        "<body name=\"b\"/>\n<body name=\"b\"/>",
        "t.xml: body `b` (line 4): this body makes a link named `b`, and so does the body at line 3: the model's \
         links need names of their own (rename one)",
    );
    // A written name equal to an unnamed body's: the unnamed body is body 1.
    check(
        "<body><joint name=\"j\"/></body>\n<body name=\"body1\"/>",
        "t.xml: body `body1` (line 4): this body makes a link named `body1`, and so does the body at line 3: the \
         model's links need names of their own (rename one)",
    );
    check(
        "<body name=\"world\"/>",
        "t.xml: body `world` (line 3): this body makes a link named `world`, and so does the world body at the \
         model's root: the model's links need names of their own (rename one)",
    );
    // Names per kind, as MuJoCo keeps them: a body and a joint named alike load as they are (the
    // model keeps links and joints apart); a site or frame named like a body or joint gives way,
    // as `name.site` or `name.frame`, whether it comes first in the file or after.
    let tree = mjcf(
        "<mujoco><worldbody>
           <site name=\"hand\" pos=\"0 0 2\"/>
           <body name=\"x\"><joint name=\"x\"/><site name=\"x\" pos=\"1 0 0\"/><frame name=\"x\"/>
             <body name=\"hand\"><joint name=\"wrist\"/><frame name=\"wrist\" pos=\"0 1 0\"/></body>
           </body>
         </worldbody></mujoco>",
    );
    assert_eq!(tree.dof_names(), ["x", "wrist"]);
    let links: Vec<&str> = tree.links().iter().map(|l| l.name.as_str()).collect();
    assert_eq!(links, ["world", "hand.site", "x", "x.site", "x.frame", "hand", "wrist.frame"]);
    assert_pose(&tree, &[0.0, 0.0], "hand.site", I, [0.0, 0.0, 2.0]);
    assert_pose(&tree, &[0.0, 0.0], "x.site", I, [1.0, 0.0, 0.0]);
    assert_pose(&tree, &[0.0, 0.0], "wrist.frame", I, [0.0, 1.0, 0.0]);
    // Two sites of one name: MuJoCo refuses them too.
    check(
        "<site name=\"s\"/>\n<site name=\"s\"/>",
        "t.xml: site `s` (line 4): this site makes a link named `s`, and so does the site at line 3: the model's \
         links need names of their own (rename one)",
    );
}

#[test]
fn an_attach_mujoco_refuses_is_refused_naming_its_line() {
    let refused = |attach: &str| {
        let main = format!(
            "<mujoco>\n<asset><model name=\"g\" file=\"g.xml\"/></asset>\n<worldbody>\n{attach}\n</worldbody></mujoco>"
        );
        let dir = scratch(
            "attach_refused",
            &[
                ("main.xml", main.as_str()),
                ("g.xml", r#"<mujoco><worldbody><body name="palm"><frame name="f"/></body></worldbody></mujoco>"#),
            ],
        );
        kinematics::load(dir.join("main.xml")).unwrap_err().kind.to_string()
    };
    assert_eq!(
        refused(r#"<attach model="g" body="palm"/>"#),
        "line 4: <attach> needs a `prefix` attribute (MuJoCo requires one)"
    );
    assert_eq!(
        refused(r#"<attach model="g" body="palm" frame="f" prefix="a_"/>"#),
        "line 4: <attach> takes a `body` or a `frame`, not both"
    );
    assert_eq!(
        refused(r#"<attach model="g" frame="nowhere" prefix="a_"/>"#),
        "line 4: the model `g` (`g.xml`) has no frame `nowhere` to attach"
    );
}
