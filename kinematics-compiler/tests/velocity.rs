//! The compiler's velocities against its own evaluator: every robot in `robots/`, every leaf, and
//! bases at the root, mid-chain, below the tip and on another branch.
//!
//! This is the compiler's own consistency check, evaluated with [`Compiled::eval_outputs`] (no
//! Rust compiled): the Jacobian against central differences of the compiled pose (a loose bound,
//! `1e-6` times the reach: differences of step `1e-5` are good to about that), and the forms
//! against each other exactly up to rounding: `LOCAL` is `R^T` times `LOCAL_WORLD_ALIGNED`, the
//! twist is `J * qd`, the pose-and-Jacobian pair is the pose and the Jacobian, the position
//! Jacobian is the linear rows. The independent checks (the runtime reference, dual numbers
//! through the generated pose, extrapolated differences) are in the `checks` crate.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::robots;

use kinematics_compiler::{Compiled, Request, compile};
use kinematics_model::{JacobianFrame, KinematicTree, LinkId};

/// Deterministic configurations in [-3, 3].
fn configurations(dof: usize, count: usize) -> Vec<Vec<f64>> {
    let mut state = 0x9e37_79b9_7f4a_7c15_u64;
    (0..count)
        .map(|_| {
            (0..dof)
                .map(|_| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    (state >> 11) as f64 / (1u64 << 53) as f64 * 6.0 - 3.0
                })
                .collect()
        })
        .collect()
}

/// Bases to try for `tip`: the root, the tip's grandparent, a leaf of another branch, a link
/// below the tip (if any), and the tip itself.
fn bases(tree: &KinematicTree, tip: LinkId) -> Vec<String> {
    let mut bases = vec![tree.link(tree.root()).name.clone(), tree.link(tip).name.clone()];
    let path = tree.path_from_root(tip);
    if path.len() >= 2 {
        bases.push(tree.link(tree.joint(path[path.len() - 2]).parent).name.clone());
    }
    if let Some(other) = tree.leaves().find(|&l| l != tip && !tree.path_from_root(l).starts_with(&path)) {
        bases.push(tree.link(other).name.clone());
    }
    if let Some(&child) = tree.link(tip).child_joints.first() {
        bases.push(tree.link(tree.joint(child).child).name.clone());
    }
    bases.sort();
    bases.dedup();
    bases
}

fn outputs(c: &Compiled, q: &[f64]) -> Vec<f64> {
    let out = c.eval_outputs(q);
    assert_eq!(out.len(), 1);
    assert!(out[0].iter().all(|v| v.is_finite()), "non-finite output");
    out[0].clone()
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
}

#[test]
fn velocities_agree_with_the_pose_and_with_each_other() {
    let mut checked = 0;
    for file in robots() {
        let tree = common::robot(&file);
        // A floating joint's seven entries of `q` give six columns (a spherical joint's four,
        // three), which differences of `q`'s entries cannot show: the test below, `tests/mjcf.rs`,
        // `tests/floating_base.rs` and the checks crate's Jacobians (every robot, `walker.xml`'s
        // free joint and `ball_tree.xml`'s ball joints included) hold those against the runtime
        // reference.
        if tree.quaternion_joints().next().is_some() {
            continue;
        }
        let n = tree.dof();
        let reach = tree.reach().max(1.0);
        let qs = configurations(n, 4);
        let leaves: Vec<LinkId> = tree.leaves().collect();
        for &tip in &leaves {
            let tip_name = tree.link(tip).name.clone();
            for base in bases(&tree, tip) {
                let request = |r: Request| r.with_base(&base);
                let pose = compile(&tree, &request(Request::tip(&tip_name))).unwrap();
                let lwa = compile(&tree, &request(Request::tip(&tip_name).jacobian(JacobianFrame::LocalWorldAligned)))
                    .unwrap();
                let local = compile(&tree, &request(Request::tip(&tip_name).jacobian(JacobianFrame::Local))).unwrap();
                let both = compile(
                    &tree,
                    &request(Request::tip(&tip_name).pose_and_jacobian(JacobianFrame::LocalWorldAligned)),
                )
                .unwrap();
                let linear = compile(
                    &tree,
                    &request(Request::tip(&tip_name).positions_only().jacobian(JacobianFrame::LocalWorldAligned)),
                )
                .unwrap();
                let twist =
                    compile(&tree, &request(Request::tip(&tip_name).twist(JacobianFrame::LocalWorldAligned))).unwrap();
                let what = format!("{file}: `{tip_name}` in `{base}`");
                for q in &qs {
                    let p = outputs(&pose, q);
                    let j = outputs(&lwa, q);
                    assert_eq!(j.len(), 6 * n, "{what}");
                    // Central differences of the pose, column by column.
                    let h = 1e-5;
                    for i in 0..n {
                        let (mut qp, mut qm) = (q.clone(), q.clone());
                        qp[i] += h;
                        qm[i] -= h;
                        let (pp, pm) = (outputs(&pose, &qp), outputs(&pose, &qm));
                        let d: Vec<f64> = (0..12).map(|k| (pp[k] - pm[k]) / (2.0 * h)).collect();
                        // Angular velocity: vee(dR R^T).
                        let r = |a: usize, b: usize| p[3 * a + b];
                        let dr = |a: usize, b: usize| d[3 * a + b];
                        let m = |a: usize, b: usize| (0..3).map(|k| dr(a, k) * r(b, k)).sum::<f64>();
                        let w = [(m(2, 1) - m(1, 2)) / 2.0, (m(0, 2) - m(2, 0)) / 2.0, (m(1, 0) - m(0, 1)) / 2.0];
                        for row in 0..3 {
                            let lin = j[row * n + i];
                            let ang = j[(row + 3) * n + i];
                            assert!(
                                (lin - d[9 + row]).abs() < 1e-6 * reach,
                                "{what}: J[{row}][{i}] {lin} vs {}",
                                d[9 + row]
                            );
                            assert!((ang - w[row]).abs() < 1e-6, "{what}: J[{}][{i}] {ang} vs {}", row + 3, w[row]);
                        }
                    }
                    // LOCAL = R^T LOCAL_WORLD_ALIGNED, row blocks of three.
                    let l = outputs(&local, q);
                    for i in 0..n {
                        for block in [0, 3] {
                            for a in 0..3 {
                                let expected: f64 = (0..3).map(|k| p[3 * k + a] * j[(block + k) * n + i]).sum();
                                let got = l[(block + a) * n + i];
                                assert!((got - expected).abs() < 1e-12 * reach, "{what}: LOCAL");
                            }
                        }
                    }
                    let b = outputs(&both, q);
                    assert!(max_diff(&b[..12], &p) < 1e-12 * reach, "{what}: pose of the pair");
                    assert!(max_diff(&b[12..], &j) < 1e-12 * reach, "{what}: Jacobian of the pair");
                    assert!(max_diff(&outputs(&linear, q), &j[..3 * n]) < 1e-12 * reach, "{what}: linear rows");
                    let qd = configurations(n, 5).pop().unwrap();
                    let with_rates: Vec<f64> = q.iter().chain(&qd).copied().collect();
                    let t = outputs(&twist, &with_rates);
                    let jqd: Vec<f64> = (0..6).map(|row| (0..n).map(|i| j[row * n + i] * qd[i]).sum()).collect();
                    assert!(max_diff(&t, &jqd) < 1e-11 * reach, "{what}: twist {t:?} vs J qd {jqd:?}");
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 100, "{checked}");
}

/// The UR5's tip: the twist costs fewer multiplications than the Jacobian times the rates, and
/// the pose and Jacobian together cost less than apart.
#[test]
fn twist_is_cheaper_than_forming_the_jacobian() {
    let tree = common::robot("ur5.urdf");
    let frame = JacobianFrame::LocalWorldAligned;
    let n = tree.dof();
    let j = compile(&tree, &Request::tip("tool0").jacobian(frame)).unwrap().op_count();
    let t = compile(&tree, &Request::tip("tool0").twist(frame)).unwrap().op_count();
    // J * qd: 6n products and 6(n - 1) sums on top of J.
    assert!(t.mul < j.mul + 6 * n, "twist {t} vs J {j}");
    let pose = compile(&tree, &Request::tip("tool0")).unwrap().op_count();
    let both = compile(&tree, &Request::tip("tool0").pose_and_jacobian(frame)).unwrap().op_count();
    assert!(both.mul < pose.mul + j.mul, "pose {pose} + J {j} vs both {both}");
    assert_eq!(both.sin_cos, pose.sin_cos, "the pair calls sin_cos no more than the pose");
}

/// A tree with a floating root (the quadruped's trunk made free-flying), a planar joint, and
/// `ball_tree.xml` (a free root and three ball joints), the Jacobian's columns checked by central
/// differences along each velocity: a floating joint's linear velocities move its child along the
/// child's own axes, a floating or spherical joint's angular ones turn the child about them (the
/// quaternion times `exp(h e_k / 2)` on the right); the others as before.
#[test]
fn floating_spherical_and_planar_joints_against_differences() {
    let planar = r#"<robot name="planar_base">
      <link name="ground"/><link name="cart"/><link name="arm"/><link name="hand"/>
      <joint name="slide" type="planar"><parent link="ground"/><child link="cart"/>
        <origin xyz="0.1 0.2 0.3" rpy="0.3 -0.2 0.1"/><axis xyz="0.2 0.3 0.9"/></joint>
      <joint name="shoulder" type="revolute"><parent link="cart"/><child link="arm"/>
        <origin xyz="0 0 0.5"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
      <joint name="elbow" type="revolute"><parent link="arm"/><child link="hand"/>
        <origin xyz="0.4 0 0"/><axis xyz="0 0 1"/><limit lower="-2" upper="2" effort="1" velocity="1"/><mimic joint="shoulder" multiplier="-1.5"/></joint>
    </robot>"#;
    let quadruped = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/quadruped.urdf")).unwrap();
    let floating = kinematics_model::urdf::parse_urdf(&quadruped).unwrap().with_floating_base("world");
    let trees = [
        kinematics_model::parse_source("planar_base.urdf", planar).unwrap(),
        KinematicTree::from_description(&floating).unwrap(),
        common::robot("ball_tree.xml"),
    ];
    assert_eq!((trees[0].dof(), trees[0].velocity_dof()), (4, 4));
    assert_eq!((trees[1].dof(), trees[1].velocity_dof()), (19, 18));
    assert_eq!((trees[2].dof(), trees[2].velocity_dof()), (24, 20));
    let mut checked = 0;
    for tree in &trees {
        let (n, nv) = (tree.dof(), tree.velocity_dof());
        let reach = tree.reach().max(1.0);
        let leaves: Vec<LinkId> = tree.leaves().collect();
        for &tip in &leaves {
            let tip_name = tree.link(tip).name.clone();
            for base in bases(tree, tip) {
                for frame in JacobianFrame::ALL {
                    let what = format!("{}: `{tip_name}` in `{base}` ({})", tree.name(), frame.name());
                    let pose = compile(tree, &Request::tip(&tip_name).with_base(&base)).unwrap();
                    let jacobian = compile(tree, &Request::tip(&tip_name).with_base(&base).jacobian(frame)).unwrap();
                    let twist = compile(tree, &Request::tip(&tip_name).with_base(&base).twist(frame)).unwrap();
                    for mut q in configurations(n, 3) {
                        // A quaternion of any length: the rotation is its normalisation's.
                        for start in tree.quaternion_entries() {
                            q[start + 3] += 2.5;
                        }
                        let p = outputs(&pose, &q);
                        let j = outputs(&jacobian, &q);
                        assert_eq!(j.len(), 6 * nv, "{what}");
                        let h = 1e-5;
                        for v in 0..nv {
                            let (pp, pm) =
                                (outputs(&pose, &retract(tree, &q, v, h)), outputs(&pose, &retract(tree, &q, v, -h)));
                            let d: Vec<f64> = (0..12).map(|k| (pp[k] - pm[k]) / (2.0 * h)).collect();
                            let r = |a: usize, b: usize| p[3 * a + b];
                            let m = |a: usize, b: usize| (0..3).map(|k| d[3 * a + k] * r(b, k)).sum::<f64>();
                            let w = [(m(2, 1) - m(1, 2)) / 2.0, (m(0, 2) - m(2, 0)) / 2.0, (m(1, 0) - m(0, 1)) / 2.0];
                            let mut expected = [d[9], d[10], d[11], w[0], w[1], w[2]];
                            if frame == JacobianFrame::Local {
                                // Both 3-vectors in the tip's axes.
                                for block in [0, 3] {
                                    let u = [expected[block], expected[block + 1], expected[block + 2]];
                                    for a in 0..3 {
                                        expected[block + a] = (0..3).map(|k| r(k, a) * u[k]).sum();
                                    }
                                }
                            }
                            for row in 0..6 {
                                let got = j[row * nv + v];
                                let scale = if row < 3 { reach * 10.0 } else { 1.0 };
                                assert!(
                                    (got - expected[row]).abs() < 1e-6 * scale,
                                    "{what}: J[{row}][{v}] {got} vs {}",
                                    expected[row]
                                );
                            }
                        }
                        let qd = configurations(nv, 7).pop().unwrap();
                        let with_rates: Vec<f64> = q.iter().chain(&qd).copied().collect();
                        let t = outputs(&twist, &with_rates);
                        let jqd: Vec<f64> = (0..6).map(|row| (0..nv).map(|i| j[row * nv + i] * qd[i]).sum()).collect();
                        assert!(max_diff(&t, &jqd) < 1e-10 * reach, "{what}: twist");
                        checked += 1;
                    }
                }
            }
        }
    }
    assert!(checked > 100, "{checked}");
}

/// `q` moved by `h` along velocity `v`: a floating joint's linear velocities along its child's
/// axes, a floating or spherical joint's angular ones about them (right multiplication of the
/// quaternion); any other velocity is its entry of `q`.
fn retract(tree: &KinematicTree, q: &[f64], v: usize, h: f64) -> Vec<f64> {
    let mut q = q.to_vec();
    let of_entry = tree.velocity_of_entry();
    if let Some(entry) = of_entry.iter().position(|&c| c == Some(v)) {
        q[entry] += h;
        return q;
    }
    for joint in tree.quaternion_joints() {
        let kind = tree.joint(joint).kind;
        let (Some(start), kinematics_model::JointMotion::Dof(s), Some(offset)) =
            (tree.velocity_start(joint), tree.joint(joint).motion, kind.quaternion_offset())
        else {
            continue;
        };
        if !(start..start + kind.velocities()).contains(&v) {
            continue;
        }
        // The quaternion follows a floating joint's position, its angular velocities the linear.
        let qs = s + offset;
        let [x, y, z, w] = [q[qs], q[qs + 1], q[qs + 2], q[qs + 3]];
        let norm = (x * x + y * y + z * z + w * w).sqrt();
        let (x, y, z, w) = (x / norm, y / norm, z / norm, w / norm);
        let k = v - start;
        if k < offset {
            // The child's axis k in the parent frame: column k of the rotation.
            let r = [
                [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - z * w), 2.0 * (x * z + y * w)],
                [2.0 * (x * y + z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - x * w)],
                [2.0 * (x * z - y * w), 2.0 * (y * z + x * w), 1.0 - 2.0 * (x * x + y * y)],
            ];
            for a in 0..3 {
                q[s + a] += h * r[a][k];
            }
        } else {
            // quaternion * (cos(h/2), sin(h/2) e_k), Hamilton product, (x, y, z, w) order.
            let (c, sn) = ((h / 2.0).cos(), (h / 2.0).sin());
            let mut e = [0.0; 3];
            e[k - offset] = sn;
            let (bx, by, bz, bw) = (e[0], e[1], e[2], c);
            q[qs] = w * bx + x * bw + y * bz - z * by;
            q[qs + 1] = w * by - x * bz + y * bw + z * bx;
            q[qs + 2] = w * bz + x * by - y * bx + z * bw;
            q[qs + 3] = w * bw - x * bx - y * by - z * bz;
        }
        return q;
    }
    unreachable!("velocity {v} belongs to no joint")
}
