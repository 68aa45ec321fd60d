//! MJCF (issue 33): the reader against hand-worked poses, the walker against its URDF twin, the
//! MJCF UR5 against the URDF one, includes and attachments, and errors naming element and line.
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
    // A site's fromto: the midpoint, z along the segment: (0.5, 0, 0) and Ry(90).
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="b">
             <site name="s" type="capsule" size="0.1" fromto="0 0 0 1 0 0"/>
           </body></worldbody></mujoco>"#,
    );
    assert_pose(&tree, &[], "s", [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]], [0.5, 0.0, 0.0]);
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
    assert_eq!(from_mjcf.links(), from_urdf.links());
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
    assert_eq!(ik.family, ik_urdf.unwrap().family);
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
        ["<equality> (line 3 of `gripper.xml`, attached as `gripper`): an attached model's constraints are not read"]
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
        r#"<body name="b"><joint name="j" type="ball"/></body>"#,
        "t.xml: joint `j` (line 3): ball joints are not supported yet (the model has no spherical joint): write three hinges",
    );
    check(r#"<body><joint name="j"/></body>"#, "t.xml: line 3: a <body> needs a `name` (it is a link of the robot)");
    check(
        r#"<body name="b"><joint/></body>"#,
        "t.xml: joint `root_joint` (line 3): a <joint> needs a `name` (it names a degree of freedom)",
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
        "t.xml: joint `root_joint` (line 3): a free joint must be the only joint of a body whose parent is the world body",
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
/// parent body's, at `q = 0`, equal to ours by the runtime reference.
#[test]
fn mjcf_rs_reads_the_same_body_and_site_frames() {
    use nalgebra::{Isometry3, Quaternion, Translation3, UnitQuaternion};
    let iso = |p: &mjcf_rs::Pose| {
        let (r, t) = (p.rotation, p.translation);
        let rotation = UnitQuaternion::from_quaternion(Quaternion::new(r.w, r.x, r.y, r.z));
        Isometry3::from_parts(Translation3::new(t.x, t.y, t.z), rotation)
    };
    for file in ["ur5_mjcf.xml", "walker.xml"] {
        let model = mjcf_rs::Model::from_file(robot(file)).unwrap();
        let tree = kinematics::load(robot(file)).unwrap();
        let fk = ReferenceFk::new(tree.clone());
        let mut q = vec![0.0; tree.dof()];
        for j in tree.floating_joints() {
            if let kinematics::model::JointMotion::Dof(start) = tree.joint(j).motion {
                q[start + 6] = 1.0; // the identity quaternion: a free body's pose is q's, not the file's
            }
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
        assert!(compared >= 10, "{file}: {compared}");
    }
}
