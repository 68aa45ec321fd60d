//! The emitted Rust of the fixed-seed random robots (`build/random_robots.rs`, compiled by the
//! build script through `emit_robot`, the derive's own path) against the runtime reference built
//! from the same text with the same exactness policy: every generated function (link poses and
//! positions, tip poses and positions, their `_f32` twins, the `Kinematics` trait's methods through
//! slices, both `reference()`s) and every constant, on many configurations, held to
//! `kinematics::AGREEMENT_TOLERANCE` (f64) and `AGREEMENT_TOLERANCE_F32` (f32) by `Pose::deviation`;
//! and the tips' velocities (Jacobians in both frames, pose and Jacobian, twists) against the
//! runtime reference, the generated pose on dual numbers and extrapolated differences.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

#[allow(dead_code)] // the build script uses all of it; the tests the set and its options
#[path = "../build/random_robots.rs"]
mod random_robots;

use kinematics::model::{ExactAngles, KinematicTree, SourceFormat, parse_source_with};
use kinematics::{AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, Configurations, JointLimits, Pose, ReferenceFk};
use kinematics_checks::random::RANDOM;
use kinematics_checks::{PosesFn, RandomRobot, Typed, on_every_core};
use nalgebra::Isometry3;

/// Configurations per robot (the first five put every joint at a special angle).
const CASES: usize = 2000;

fn policy(exact_angles: bool) -> ExactAngles {
    ExactAngles::on(exact_angles)
}

/// The generated robot's options, by name.
fn options(name: &str) -> random_robots::RandomRobot {
    random_robots::generate().into_iter().find(|r| r.name == name).expect("every compiled robot is in the set")
}

/// The tree the test builds itself, from the compiled text, under the robot's policy.
fn tree(robot: &RandomRobot, exact_angles: bool) -> KinematicTree {
    parse_source_with(robot.file, robot.text, policy(exact_angles)).unwrap()
}

fn pose_of(iso: &Isometry3<f64>) -> Pose<f64> {
    let r = iso.rotation.to_rotation_matrix();
    let t = iso.translation.vector;
    Pose {
        rotation: [
            [r[(0, 0)], r[(0, 1)], r[(0, 2)]],
            [r[(1, 0)], r[(1, 1)], r[(1, 2)]],
            [r[(2, 0)], r[(2, 1)], r[(2, 2)]],
        ],
        translation: [t[0], t[1], t[2]],
    }
}

fn widen(p: &Pose<f32>) -> Pose<f64> {
    Pose { rotation: p.rotation.map(|row| row.map(f64::from)), translation: p.translation.map(f64::from) }
}

/// A position as a pose with the reference's rotation, so the deviation measures the position alone.
fn at(position: [f64; 3], reference: &Isometry3<f64>) -> Pose<f64> {
    Pose { translation: position, ..pose_of(reference) }
}

/// Every link's pose in `base`, by the reference (`ReferenceFk::relative_pose`'s own composition,
/// computed once per configuration).
fn expected(fk: &ReferenceFk, q: &[f64], base: &str, links: &[&str]) -> Vec<Isometry3<f64>> {
    let poses = fk.link_poses(q).unwrap();
    let from = poses[fk.link_id(base).unwrap().0].inverse();
    links.iter().map(|l| from * poses[fk.link_id(l).unwrap().0]).collect()
}

/// Collects the failures of one robot (all of them, up to a limit), so one run shows every fault.
struct Faults {
    robot: &'static str,
    list: Vec<String>,
    worst: f64,
    worst_f32: f64,
    /// Scalar types whose batches and lane functions were compared with the typed functions.
    lanes_checked: usize,
}

impl Faults {
    fn check(&mut self, what: &str, link: &str, d: f64, tolerance: f64, q: &[f64]) {
        // A NaN deviation is a failure too.
        if d.is_nan() || d > tolerance {
            if self.list.len() < 12 {
                self.list.push(format!(
                    "{} {what} `{link}`: off by {d:e} (tolerance {tolerance:e}) at q = {q:?}",
                    self.robot
                ));
            }
        } else if tolerance == AGREEMENT_TOLERANCE {
            self.worst = self.worst.max(d);
        } else {
            self.worst_f32 = self.worst_f32.max(d);
        }
    }

    fn fail(&mut self, message: String) {
        self.list.push(format!("{}: {message}", self.robot));
    }
}

fn limits_of(tree: &KinematicTree) -> Vec<JointLimits> {
    tree.dof_limits()
        .iter()
        .map(|l| match l {
            Some(l) => JointLimits { lower: l.lower, upper: l.upper },
            None => JointLimits { lower: f64::NEG_INFINITY, upper: f64::INFINITY },
        })
        .collect()
}

/// The constants, inherent and through the trait, against the tree and the options compiled.
fn check_constants(robot: &RandomRobot, tree: &KinematicTree, faults: &mut Faults) {
    let o = options(robot.name);
    let base = o.base.clone().unwrap_or_else(|| tree.link(tree.root()).name.clone());
    let links: Vec<&str> = tree.links().iter().map(|l| l.name.as_str()).filter(|l| *l != base).collect();
    let tips: Vec<&str> = o.tips.iter().map(String::as_str).collect();
    let checks = [
        ("ROBOT", robot.consts.robot == tree.name()),
        ("BASE", robot.consts.base == base),
        ("DOF", robot.consts.dof == tree.dof()),
        ("JOINT_NAMES", robot.consts.joint_names == tree.dof_names()),
        ("JOINT_LIMITS", robot.consts.joint_limits == limits_of(tree)),
        ("LINK_NAMES", robot.consts.links == links),
        ("TIPS", robot.consts.tips == tips),
        ("the trait's constants", (robot.trait_consts)() == robot.consts),
    ];
    for (name, ok) in checks {
        if !ok {
            faults.fail(format!("{name} differs from the description"));
        }
    }
}

/// Every generated function of one robot, and both `reference()`s, on `CASES` configurations.
fn check_robot(robot: &RandomRobot) -> Faults {
    let exact_angles = options(robot.name).exact_angles;
    let tree = tree(robot, exact_angles);
    let fk = ReferenceFk::new(tree.clone());
    let reach = tree.reach();
    let mut faults = Faults { robot: robot.name, list: Vec::new(), worst: 0.0, worst_f32: 0.0, lanes_checked: 0 };
    check_constants(robot, &tree, &mut faults);
    // Both `reference()`s must be the same robot as the test's own.
    let references: Vec<(&str, ReferenceFk)> =
        [("reference()", robot.reference), ("Kinematics::reference()", robot.trait_reference)]
            .into_iter()
            .filter_map(|(name, f)| match f() {
                Ok(r) => Some((name, r)),
                Err(e) => {
                    faults.fail(format!("{name} fails: {e}"));
                    None
                }
            })
            .collect();
    let zero = Pose { rotation: [[0.0; 3]; 3], translation: [0.0; 3] };
    let (tol, tol32) = (AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32);
    for q in Configurations::new(&tree).take(CASES) {
        let links = expected(&fk, &q, robot.consts.base, robot.consts.links);
        let tips = expected(&fk, &q, robot.consts.base, robot.consts.tips);
        if let Some(f) = &robot.f64 {
            for ((p, e), l) in (f.link_poses)(&q).iter().zip(&links).zip(robot.consts.links) {
                faults.check("link_poses", l, p.deviation(e, reach), tol, &q);
            }
            if let Some(positions) = f.link_positions {
                for ((p, e), l) in positions(&q).iter().zip(&links).zip(robot.consts.links) {
                    faults.check("link_positions", l, at(*p, e).deviation(e, reach), tol, &q);
                }
            }
            if let Some(poses) = f.tip_poses {
                for ((p, e), l) in poses(&q).iter().zip(&tips).zip(robot.consts.tips) {
                    faults.check("tip_pose(s)", l, p.deviation(e, reach), tol, &q);
                }
            }
            if let Some(positions) = f.tip_positions {
                for ((p, e), l) in positions(&q).iter().zip(&tips).zip(robot.consts.tips) {
                    faults.check("tip_position(s)", l, at(*p, e).deviation(e, reach), tol, &q);
                }
            }
        }
        if let Some(f) = &robot.f32 {
            // The f32 code is held to its tolerance at the configuration it was given.
            let q32: Vec<f32> = q.iter().map(|&x| x as f32).collect();
            let q64: Vec<f64> = q32.iter().map(|&x| f64::from(x)).collect();
            let links = expected(&fk, &q64, robot.consts.base, robot.consts.links);
            let tips = expected(&fk, &q64, robot.consts.base, robot.consts.tips);
            for ((p, e), l) in (f.link_poses)(&q32).iter().zip(&links).zip(robot.consts.links) {
                faults.check("link_poses_f32", l, widen(p).deviation(e, reach), tol32, &q64);
            }
            if let Some(positions) = f.link_positions {
                for ((p, e), l) in positions(&q32).iter().zip(&links).zip(robot.consts.links) {
                    faults.check("link_positions_f32", l, at(p.map(f64::from), e).deviation(e, reach), tol32, &q64);
                }
            }
            if let Some(poses) = f.tip_poses {
                for ((p, e), l) in poses(&q32).iter().zip(&tips).zip(robot.consts.tips) {
                    faults.check("tip_pose(s)_f32", l, widen(p).deviation(e, reach), tol32, &q64);
                }
            }
            if let Some(positions) = f.tip_positions {
                for ((p, e), l) in positions(&q32).iter().zip(&tips).zip(robot.consts.tips) {
                    faults.check("tip_position(s)_f32", l, at(p.map(f64::from), e).deviation(e, reach), tol32, &q64);
                }
            }
        }
        // The trait's methods, through slices.
        let mut out = vec![zero; robot.consts.tips.len()];
        match (robot.tip_poses_into)(&q, &mut out) {
            Ok(()) => {
                for ((p, e), l) in out.iter().zip(&tips).zip(robot.consts.tips) {
                    faults.check("Kinematics::tip_poses_into", l, p.deviation(e, reach), tol, &q);
                }
            }
            Err(e) => faults.fail(format!("tip_poses_into fails: {e}")),
        }
        let mut out = vec![zero; robot.consts.links.len()];
        match (robot.link_poses_into)(&q, &mut out) {
            Ok(()) => {
                for ((p, e), l) in out.iter().zip(&links).zip(robot.consts.links) {
                    faults.check("Kinematics::link_poses_into", l, p.deviation(e, reach), tol, &q);
                }
            }
            Err(e) => faults.fail(format!("link_poses_into fails: {e}")),
        }
        for (name, reference) in &references {
            for ((p, e), l) in expected(reference, &q, robot.consts.base, robot.consts.links)
                .iter()
                .zip(&links)
                .zip(robot.consts.links)
            {
                faults.check(name, l, pose_of(p).deviation(e, reach), tol, &q);
            }
        }
        if faults.list.len() >= 12 {
            break;
        }
    }
    faults.lanes_checked = check_batches_and_lanes(robot, &tree, &mut faults);
    if let Some(velocities) = &robot.velocities {
        check_velocities(robot, velocities, &fk, &mut faults);
    }
    // Slices of the wrong length are errors, not panics.
    let q = vec![0.0; robot.consts.dof + 1];
    let mut out = vec![zero; robot.consts.links.len()];
    if (robot.link_poses_into)(&q, &mut out).is_ok() {
        faults.fail("link_poses_into accepts a q one too long".to_owned());
    }
    let mut out = vec![zero; robot.consts.links.len() + 1];
    if (robot.link_poses_into)(&q[..robot.consts.dof], &mut out).is_ok() {
        faults.fail("link_poses_into accepts an output one too long".to_owned());
    }
    let mut out = vec![zero; robot.consts.tips.len() + 1];
    if (robot.tip_poses_into)(&q[..robot.consts.dof], &mut out).is_ok() {
        faults.fail("tip_poses_into accepts an output one too long".to_owned());
    }
    faults
}

/// Configurations the velocities are checked on (the first few also against differences).
const VELOCITY_CASES: usize = 300;

/// A runtime Jacobian as columns.
fn columns(j: &nalgebra::Matrix6xX<f64>) -> Vec<[f64; 6]> {
    (0..j.ncols()).map(|c| std::array::from_fn(|r| j[(r, c)])).collect()
}

/// The largest difference of two Jacobians (columns of `[linear; angular]`), linear rows divided
/// by `reach`; infinite for a value that is not finite or a different number of columns.
fn jacobian_deviation(a: &[[f64; 6]], b: &[[f64; 6]], reach: f64) -> f64 {
    if a.len() != b.len() {
        return f64::INFINITY;
    }
    let mut worst = 0.0f64;
    for (x, y) in a.iter().zip(b) {
        for r in 0..6 {
            if !(x[r].is_finite() && y[r].is_finite()) {
                return f64::INFINITY;
            }
            worst = worst.max((x[r] - y[r]).abs() / if r < 3 { reach } else { 1.0 });
        }
    }
    worst
}

/// The tips' generated velocities against the runtime reference (relative to the robot's own
/// base, wherever it is), the generated pose on dual numbers, extrapolated differences of the
/// generated pose (a few configurations), and each other: the pose-and-Jacobian pair against the
/// pose and the Jacobian, the twists against the Jacobians times the rates.
fn check_velocities(robot: &RandomRobot, v: &kinematics_checks::Velocities, fk: &ReferenceFk, faults: &mut Faults) {
    use kinematics::model::JacobianFrame;
    let tree = fk.tree();
    let reach = tree.reach();
    let tol = AGREEMENT_TOLERANCE;
    let base = robot.consts.base;
    let tip_poses = robot.f64.as_ref().and_then(|f| f.tip_poses);
    for (case, q) in Configurations::new(tree).take(VELOCITY_CASES).enumerate() {
        let jacobians = (v.jacobians)(&q);
        let locals = (v.jacobians_local)(&q);
        let duals = (v.by_duals)(&q, &kinematics_checks::dual::directions(tree, &q));
        let pairs = (v.poses_and_jacobians)(&q);
        let qd: Vec<f64> = (0..tree.velocity_dof()).map(|i| ((i * 7 + case) % 11) as f64 / 5.0 - 1.0).collect();
        let (twists, twists_local) = ((v.twists)(&q, &qd), (v.twists_local)(&q, &qd));
        let poses = tip_poses.map(|f| f(&q));
        for (k, tip) in robot.consts.tips.iter().enumerate() {
            let runtime = columns(&fk.jacobian(&q, base, tip).unwrap());
            faults.check("tip Jacobian vs runtime", tip, jacobian_deviation(&jacobians[k], &runtime, reach), tol, &q);
            let local = columns(&fk.jacobian_in(&q, base, tip, JacobianFrame::Local).unwrap());
            faults.check("LOCAL Jacobian vs runtime", tip, jacobian_deviation(&locals[k], &local, reach), tol, &q);
            faults.check(
                "tip Jacobian vs dual numbers",
                tip,
                jacobian_deviation(&jacobians[k], &duals[k], reach),
                tol,
                &q,
            );
            faults.check(
                "pose-and-Jacobian's Jacobian",
                tip,
                jacobian_deviation(&pairs[k].1, &jacobians[k], reach),
                tol,
                &q,
            );
            if let Some(poses) = &poses {
                let pose = poses[k].to_isometry();
                faults.check("pose-and-Jacobian's pose", tip, pairs[k].0.deviation(&pose, reach), tol, &q);
            }
            for (twist, jacobian, what) in
                [(&twists[k], &jacobians[k], "twist"), (&twists_local[k], &locals[k], "LOCAL twist")]
            {
                let product: [f64; 6] = std::array::from_fn(|r| jacobian.iter().zip(&qd).map(|(c, x)| c[r] * x).sum());
                // The products of a Jacobian of `n` columns by rates up to 1 add `n` roundings.
                let scale = (tree.velocity_dof().max(1)) as f64;
                faults.check(what, tip, jacobian_deviation(&[*twist], &[product], reach) / scale, tol, &q);
            }
            if case < 3
                && let Some(f) = tip_poses
            {
                let differences = kinematics_checks::differences::jacobian(tree, |x| f(x)[k], &q);
                let d = jacobian_deviation(&jacobians[k], &differences, reach);
                faults.check("tip Jacobian vs extrapolated differences", tip, d, tol, &q);
            }
        }
        if faults.list.len() >= 12 {
            break;
        }
    }
}

/// How many configurations the batches are given: not a multiple of 4 or 8, so the last pack of
/// lanes is partly filled.
const BATCH: usize = 19;

/// The batch functions and the generic functions on lane types compute, lane by lane, exactly what
/// the typed functions compute (the same operations in the same order, and sines and cosines that
/// are the same in every lane), so they are held to equality; the typed functions are held to the
/// reference above.
fn check_batches_and_lanes(robot: &RandomRobot, tree: &KinematicTree, faults: &mut Faults) -> usize {
    fn compare<T: Copy + PartialEq + std::fmt::Debug>(
        name: &str,
        typed: PosesFn<T>,
        qs: &[Vec<T>],
        got: &[Vec<Pose<T>>],
        faults: &mut Faults,
    ) {
        if got.len() != qs.len() {
            return faults.fail(format!("{name}: {} results for {} configurations", got.len(), qs.len()));
        }
        for (q, poses) in qs.iter().zip(got) {
            if typed(q) != *poses {
                faults.fail(format!("{name} differs from the typed function at q = {q:?}"));
            }
        }
    }
    fn one<T: Copy + PartialEq + std::fmt::Debug>(
        suffix: &str,
        lanes: usize,
        f: &Typed<T>,
        qs: &[Vec<T>],
        faults: &mut Faults,
    ) {
        match (f.link_poses_batch)(qs) {
            Ok(got) => compare(&format!("link_poses_batch{suffix}"), f.link_poses, qs, &got, faults),
            Err(e) => faults.fail(format!("link_poses_batch{suffix} fails: {e}")),
        }
        for chunk in qs.chunks_exact(lanes) {
            let got = (f.link_poses_lanes)(chunk);
            compare(&format!("link_poses_generic ({lanes} lanes)"), f.link_poses, chunk, &got, faults);
        }
        if let (Some(batch), Some(lanes_fn), Some(typed)) = (f.tip_poses_batch, f.tip_poses_lanes, f.tip_poses) {
            match batch(qs) {
                Ok(got) => compare(&format!("tip_pose(s)_batch{suffix}"), typed, qs, &got, faults),
                Err(e) => faults.fail(format!("tip_pose(s)_batch{suffix} fails: {e}")),
            }
            for chunk in qs.chunks_exact(lanes) {
                compare(&format!("tip_pose(s)_generic ({lanes} lanes)"), typed, chunk, &lanes_fn(chunk), faults);
            }
        }
    }
    let qs: Vec<Vec<f64>> = Configurations::new(tree).take(BATCH).collect();
    let mut checked = 0;
    if let Some(f) = &robot.f64 {
        one("", 4, f, &qs, faults);
        checked += 1;
    }
    if let Some(f) = &robot.f32 {
        let q32: Vec<Vec<f32>> = qs.iter().map(|q| q.iter().map(|&x| x as f32).collect()).collect();
        one("_f32", 8, f, &q32, faults);
        checked += 1;
    }
    checked
}

#[test]
fn every_function_of_every_random_robot_agrees_with_the_runtime_reference() {
    let mut all = Vec::new();
    let (mut lanes_checked, mut std_trig) = (0, 0);
    for (robot, faults) in RANDOM.iter().zip(on_every_core(RANDOM, check_robot)) {
        lanes_checked += faults.lanes_checked;
        std_trig += usize::from(robot.trig == "Std");
        println!(
            "{:<36} {:<4} trig, {CASES} configurations: largest error {:.2e} (f64), {:.2e} (f32)",
            robot.file, robot.trig, faults.worst, faults.worst_f32
        );
        all.extend(faults.list);
    }
    assert!(all.is_empty(), "{} disagreements:\n{}", all.len(), all.join("\n"));
    // The set covers both sines and cosines, and batches and lanes in both scalar types.
    assert!(std_trig >= 10 && lanes_checked >= 10, "{std_trig} robots on std trig, {lanes_checked} lane checks");
}

/// The set compiled is the set the generator makes, byte for byte, run after run, every robot of it.
#[test]
fn the_random_set_is_deterministic_and_compiled_whole() {
    let set = random_robots::generate();
    assert_eq!(set, random_robots::generate());
    assert!(set.len() >= 60, "{} random robots", set.len());
    let mut compiled = RANDOM.iter();
    for robot in &set {
        let r = compiled.next().unwrap_or_else(|| panic!("{} is not compiled", robot.name));
        assert_eq!((r.name, r.file, r.text), (robot.name.as_str(), robot.file.as_str(), robot.text.as_str()));
    }
    assert!(compiled.next().is_none());
}

/// The generated set hits every shape the emitter must get right (among the robots compiled and
/// checked).
#[test]
fn the_random_set_covers_every_shape() {
    let set = random_robots::generate();
    let checked: Vec<(&random_robots::RandomRobot, KinematicTree)> =
        set.iter().map(|r| (r, parse_source_with(&r.file, &r.text, policy(r.exact_angles)).unwrap())).collect();
    let any = |what: &str, f: &dyn Fn(&random_robots::RandomRobot, &KinematicTree) -> bool| {
        assert!(checked.iter().any(|(r, t)| f(r, t)), "no checked random robot has {what}");
    };
    use kinematics::model::JointKind;
    let kinds = |t: &KinematicTree, k: JointKind| t.joints().iter().filter(|j| j.kind == k).count();
    any("a single link", &|_, t| t.links().len() == 1);
    any("zero degrees of freedom and fixed joints", &|_, t| t.dof() == 0 && t.joints().len() >= 2);
    any("three prismatic joints", &|_, t| kinds(t, JointKind::Prismatic) >= 3);
    any("continuous joints", &|_, t| kinds(t, JointKind::Continuous) >= 2);
    // Depth of a link: joints from the root.
    let depth = |t: &KinematicTree| {
        let mut d = vec![0usize; t.links().len()];
        for j in t.joints() {
            d[j.child.0] = d[j.parent.0] + 1;
        }
        d.into_iter().max().unwrap_or(0)
    };
    any("a chain 40 joints deep", &|_, t| depth(t) >= 40);
    any("a DH chain 24 rows deep", &|r, t| r.file.ends_with(".toml") && depth(t) >= 24);
    any("a root with 8 children", &|_, t| t.link(t.root()).child_joints.len() >= 8);
    // Three fixed joints in a row along a path.
    any("a run of three fixed joints", &|_, t| {
        t.joints().iter().any(|j| {
            let mut run = 0;
            let mut at = Some(j);
            while let Some(joint) = at.filter(|j| j.kind == JointKind::Fixed) {
                run += 1;
                at = t.link(joint.parent).parent_joint.map(|p| &t.joints()[p.0]);
            }
            run >= 3
        })
    });
    // Mimic joints as written: a mimic of a mimic, negative and fractional multipliers, offsets.
    let mimics = |r: &random_robots::RandomRobot| {
        let d = SourceFormat::from_file_name(&r.file).unwrap().parse(&r.text).unwrap();
        let mimics: Vec<_> = d.joints.iter().filter_map(|j| j.mimic.clone()).collect();
        let of_mimic = d.joints.iter().filter(|j| {
            j.mimic.as_ref().is_some_and(|m| d.joints.iter().any(|s| s.name == m.joint && s.mimic.is_some()))
        });
        (mimics.clone(), of_mimic.count())
    };
    any("a mimic of a mimic of a mimic", &|r, _| r.file.ends_with(".urdf") && mimics(r).1 >= 2);
    any("a negative mimic multiplier", &|r, _| {
        r.file.ends_with(".urdf") && mimics(r).0.iter().any(|m| m.multiplier < 0.0)
    });
    any("a fractional mimic multiplier", &|r, _| {
        r.file.ends_with(".urdf") && mimics(r).0.iter().any(|m| m.multiplier.fract() != 0.0)
    });
    any("a mimic offset", &|r, _| r.file.ends_with(".urdf") && mimics(r).0.iter().any(|m| m.offset != 0.0));
    any("a skewed axis", &|_, t| {
        t.joints().iter().any(|j| j.kind != JointKind::Fixed && j.axis.iter().filter(|a| **a != 0.0).count() >= 2)
    });
    any("a ROS decimal quarter turn recognised", &|r, t| {
        r.exact_angles && r.text.contains("3.14159265359") && !t.recognised_angles().is_empty()
    });
    any("a ROS decimal quarter turn kept as written", &|r, t| {
        !r.exact_angles && r.text.contains("1.57079632679") && t.recognised_angles().is_empty()
    });
    any("a near miss kept as a number", &|r, _| r.text.contains("1.5708\""));
    any("a standard DH table in TOML", &|r, _| r.file.ends_with(".toml") && r.text.contains("\"standard\""));
    any("a modified DH table in TOML", &|r, _| r.file.ends_with(".toml") && r.text.contains("\"modified\""));
    any("a standard DH table in JSON", &|r, _| r.file.ends_with(".json") && r.text.contains("\"standard\""));
    any("a modified DH table in JSON", &|r, _| r.file.ends_with(".json") && r.text.contains("\"modified\""));
    any("a DH table in degrees", &|r, _| r.text.contains("\"degrees\""));
    any("a prismatic DH row", &|r, _| !r.file.ends_with(".urdf") && r.text.contains("\"prismatic\""));
    any("a base that is not the root", &|r, t| r.base.as_ref().is_some_and(|b| *b != t.link(t.root()).name));
    any("a base on a leaf", &|r, t| {
        r.base.as_ref().is_some_and(|b| t.links()[t.link_id(b).unwrap().0].child_joints.is_empty())
    });
    any("several tips", &|r, _| r.tips.len() >= 3);
    any("one tip", &|r, _| r.tips.len() == 1);
    any("no tips", &|r, t| r.tips.is_empty() && t.links().len() > 2);
    any("f32 functions only", &|r, _| r.f32 && !r.f64);
    any("f64 functions only", &|r, _| r.f64 && !r.f32);
    any("position functions", &|r, t| r.positions && t.dof() > 0);
    any("a floating root with tips", &|r, t| {
        t.joints().first().is_some_and(|j| j.kind == JointKind::Floating) && !r.tips.is_empty() && r.f64
    });
    any("a floating joint mid-chain", &|_, t| t.joints().iter().skip(1).any(|j| j.kind == JointKind::Floating));
    any("a planar joint with a skewed normal", &|_, t| {
        t.joints().iter().any(|j| j.kind == JointKind::Planar && j.axis.iter().filter(|a| **a != 0.0).count() >= 2)
    });
    any("velocities relative to a base that is not the root", &|r, t| {
        r.f64 && !r.tips.is_empty() && r.base.as_ref().is_some_and(|b| *b != t.link(t.root()).name)
    });
    // The shape the emitter does not compile yet stays in the set.
    assert!(
        set.iter().any(|r| parse_source_with(&r.file, &r.text, policy(r.exact_angles)).unwrap().links().len() == 2),
        "no random robot with exactly one link below the root"
    );
}
