//! The reader held to MuJoCo itself: each fixture of `tests/fixtures/mujoco/` against the body and
//! site poses MuJoCo's compiler gives it (MuJoCo 4's Python bindings, written beside the fixture
//! by `scripts/mujoco_poses.py`), at MuJoCo's reference configuration and at random ones, to
//! 1e-12. `cargo test` reads the JSON; it needs no Python.

use std::collections::BTreeMap;

use kinematics::ReferenceFk;

/// A frame as MuJoCo gives it: the world position and the rotation by rows.
#[derive(Debug)]
struct Frame {
    pos: [f64; 3],
    rows: [[f64; 3]; 3],
}

/// One configuration: each joint's `qpos` entries (MuJoCo's order: a free joint's position and
/// then `w x y z`, a ball joint's `w x y z`), and the bodies' and sites' frames there.
#[derive(Debug)]
struct Configuration {
    qpos: BTreeMap<String, Vec<f64>>,
    frames: BTreeMap<String, Frame>,
}

fn numbers(value: &serde_json::Value) -> Vec<f64> {
    value.as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect()
}

fn configurations(fixture: &str) -> Vec<Configuration> {
    let path = format!("{}/tests/fixtures/mujoco/{fixture}.poses.json", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let json: serde_json::Value = serde_json::from_str(&text).unwrap();
    let frame = |v: &serde_json::Value| {
        let pos = numbers(&v["pos"]).try_into().unwrap();
        let rows: Vec<[f64; 3]> =
            v["rows"].as_array().unwrap().iter().map(|r| numbers(r).try_into().unwrap()).collect();
        Frame { pos, rows: rows.try_into().unwrap() }
    };
    json["configurations"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let qpos = c["qpos"].as_object().unwrap().iter().map(|(k, v)| (k.clone(), numbers(v))).collect();
            let mut frames = BTreeMap::new();
            for kind in ["bodies", "sites"] {
                for (name, v) in c[kind].as_object().unwrap() {
                    assert!(frames.insert(name.clone(), frame(v)).is_none(), "{fixture}: `{name}` twice");
                }
            }
            Configuration { qpos, frames }
        })
        .collect()
}

/// `q` in the tree's order from MuJoCo's `qpos`, entry by entry through the names the tree gives
/// them (`joint`, or `joint.qx` ... for a ball or free joint's quaternion, which MuJoCo writes
/// `w` first).
fn q_of(tree: &kinematics::model::KinematicTree, qpos: &BTreeMap<String, Vec<f64>>) -> Vec<f64> {
    tree.dof_names()
        .iter()
        .map(|entry| {
            let (joint, suffix) = entry.split_once('.').unwrap_or((entry, ""));
            let values = qpos.get(joint).unwrap_or_else(|| panic!("MuJoCo has no joint `{joint}`"));
            let quaternion = values.len().saturating_sub(4);
            match suffix {
                "" | "x" => values[0],
                "y" => values[1],
                "z" => values[2],
                "qw" => values[quaternion],
                "qx" => values[quaternion + 1],
                "qy" => values[quaternion + 2],
                "qz" => values[quaternion + 3],
                other => panic!("entry `{entry}`: suffix `{other}`"),
            }
        })
        .collect()
}

/// The fixture read as a user reads a file (the files it names read beside it).
fn fixture_tree(fixture: &str) -> kinematics::model::KinematicTree {
    let path = format!("{}/tests/fixtures/mujoco/{fixture}.xml", env!("CARGO_MANIFEST_DIR"));
    kinematics::load(&path).unwrap_or_else(|e| panic!("{fixture}: {e}"))
}

/// Every body and site MuJoCo places, placed by the reader's tree within 1e-12 at each of the
/// fixture's configurations.
fn agrees_with_mujoco(fixture: &str) {
    let tree = fixture_tree(fixture);
    let reference = ReferenceFk::new(tree.clone());
    let configurations = configurations(fixture);
    assert!(configurations.len() >= 2, "{fixture}: the reference configuration and a random one at least");
    for (k, c) in configurations.iter().enumerate() {
        let q = q_of(&tree, &c.qpos);
        for (name, expected) in &c.frames {
            let iso = reference.link_pose(&q, name).unwrap_or_else(|e| panic!("{fixture}: `{name}`: {e}"));
            let (m, t) = (iso.rotation.to_rotation_matrix(), iso.translation.vector);
            for i in 0..3 {
                assert!(
                    (t[i] - expected.pos[i]).abs() < 1e-12,
                    "{fixture}, configuration {k}: `{name}` at {t:?}, MuJoCo {:?}",
                    expected.pos
                );
                for j in 0..3 {
                    assert!(
                        (m[(i, j)] - expected.rows[i][j]).abs() < 1e-12,
                        "{fixture}, configuration {k}: `{name}` turned {m}, MuJoCo {:?}",
                        expected.rows
                    );
                }
            }
        }
    }
}

#[test]
fn fromto_sites_point_their_z_axis_from_to_towards_from_as_mujoco_does() {
    agrees_with_mujoco("fromto_sites");
}

#[test]
fn every_orientation_form_classes_and_frames_agree_with_mujoco() {
    agrees_with_mujoco("orientations");
}

#[test]
fn unnamed_bodies_and_joints_load_under_mujocos_ids_and_agree_with_mujoco() {
    agrees_with_mujoco("unnamed");
    let tree = fixture_tree("unnamed");
    // Two unnamed free joints are two joints, each under its id; no name is given twice.
    let joints: Vec<&str> = tree.joints().iter().map(|j| j.name.as_str()).collect();
    for name in ["joint0", "joint1", "joint2", "named_hinge", "joint4", "joint5", "joint6"] {
        assert_eq!(joints.iter().filter(|j| **j == name).count(), 1, "{name} in {joints:?}");
    }
    assert!(!joints.contains(&"root_joint"), "{joints:?}");
    // A body of several joints: its intermediate link named after the body and the joint.
    assert!(tree.links().iter().any(|l| l.name == "body2.joint1"), "{:?}", tree.links());
}

#[test]
fn the_one_unnamed_free_joint_is_root_joint() {
    agrees_with_mujoco("one_free_body");
    let text =
        std::fs::read_to_string(format!("{}/tests/fixtures/mujoco/one_free_body.xml", env!("CARGO_MANIFEST_DIR")));
    let tree = super::load(&text.unwrap()).unwrap();
    assert_eq!(&tree.dof_names()[..2], ["root_joint.x", "root_joint.y"]);
}

#[test]
fn attach_with_a_body_without_one_and_with_a_frame_agrees_with_mujoco() {
    agrees_with_mujoco("attach_arm");
    agrees_with_mujoco("attach");
    let tree = fixture_tree("attach");
    // The attached model's equality, kept with its prefix wherever both joints are attached: the
    // whole model's and the body's; the tip's attachment leaves `j1` out.
    let mimics: Vec<(&str, &str)> = tree
        .joints()
        .iter()
        .filter_map(|j| match j.motion {
            kinematics::model::JointMotion::Mimic { source, .. } => {
                Some((j.name.as_str(), tree.joint(source).name.as_str()))
            }
            _ => None,
        })
        .collect();
    assert_eq!(mimics, [("whole_j2", "whole_j1"), ("body_j2", "body_j1")]);
    assert!(
        tree.ignored().iter().any(|i| i.contains("`tip_j1`, which the attachment leaves out")),
        "{:?}",
        tree.ignored()
    );
    // The whole world body brings its sites and frames, prefixed.
    for link in ["whole_world_site", "whole_side", "whole_side_site", "frame_side", "frame_side_site"] {
        assert!(tree.links().iter().any(|l| l.name == link), "{link}");
    }
}

#[test]
fn a_body_a_joint_and_a_site_of_one_name_load_and_agree_with_mujoco() {
    agrees_with_mujoco("names_per_kind");
    let tree = fixture_tree("names_per_kind");
    assert_eq!(tree.dof_names(), ["x", "elbow"]);
}
