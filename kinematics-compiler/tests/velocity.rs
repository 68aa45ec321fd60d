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

use kinematics_compiler::{Compiled, Request, compile};
use kinematics_model::{JacobianFrame, KinematicTree, LinkId};

fn robots() -> Vec<String> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots");
    let mut files: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|f| kinematics_model::SourceFormat::from_file_name(f).is_some())
        .collect();
    files.sort();
    files
}

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

#[test]
#[ignore]
fn print_counts() {
    for (file, tip) in [("ur5.urdf", "tool0"), ("panda.urdf", "panda_hand"), ("iiwa14.urdf", "tool0")] {
        let Ok(text) = std::fs::read_to_string(format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"))) else {
            continue;
        };
        let tree = kinematics_model::parse_source(file, &text).unwrap();
        let f = JacobianFrame::LocalWorldAligned;
        let c = |r: Request| compile(&tree, &r).unwrap().op_count();
        println!(
            "{file}: pose {} | J {} | J local {} | pose+J {} | twist {} | posJ {}",
            c(Request::tip(tip)),
            c(Request::tip(tip).jacobian(f)),
            c(Request::tip(tip).jacobian(JacobianFrame::Local)),
            c(Request::tip(tip).pose_and_jacobian(f)),
            c(Request::tip(tip).twist(f)),
            c(Request::tip(tip).positions_only().jacobian(f))
        );
    }
}
