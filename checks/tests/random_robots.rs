//! Property tests: random DH chains and random URDF trees, compiled and evaluated symbolically
//! (the simplified graph the emitter prints), against the runtime reference.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::model::dh::{AngleUnit, DhConvention, DhJointType, DhRow, DhTable, Value};
use kinematics::model::{KinematicTree, parse_source};
use kinematics::{AGREEMENT_TOLERANCE, Pose, ReferenceFk};
use kinematics_compiler::{Request, compile};
use proptest::prelude::*;

fn exact_or_numeric_angle() -> impl Strategy<Value = Value> {
    prop_oneof![
        3 => prop::sample::select(vec!["0", "pi/2", "-pi/2", "pi", "-pi", "pi/4"]).prop_map(|s| Value::Text(s.to_owned())),
        1 => (-3.2..3.2f64).prop_map(Value::Number),
    ]
}

fn length() -> impl Strategy<Value = f64> {
    prop_oneof![1 => Just(0.0), 2 => -1.0..1.0f64]
}

fn dh_row(i: usize) -> impl Strategy<Value = DhRow> {
    (
        prop_oneof![4 => Just(DhJointType::Revolute), 1 => Just(DhJointType::Prismatic)],
        length(),
        length(),
        // Twists of 0 and pi make runs of parallel axes.
        prop_oneof![2 => Just(Value::Text("0".to_owned())), 1 => Just(Value::Text("pi".to_owned())), 3 => exact_or_numeric_angle()],
        exact_or_numeric_angle(),
        exact_or_numeric_angle(),
    )
        .prop_map(move |(kind, a, d, alpha, theta, offset)| DhRow {
            name: format!("j{i}"),
            link: None,
            kind,
            a,
            alpha,
            d,
            theta,
            offset: if kind == DhJointType::Prismatic { Value::Number(0.1) } else { offset },
            lower: None,
            upper: None,
            velocity: None,
            effort: None,
        })
}

fn dh_chain() -> impl Strategy<Value = KinematicTree> {
    (1..=12usize, prop_oneof![Just(DhConvention::Standard), Just(DhConvention::Modified)])
        .prop_flat_map(|(n, convention)| {
            (0..n).map(dh_row).collect::<Vec<_>>().prop_map(move |joints| DhTable {
                name: "random".to_owned(),
                convention,
                angle_unit: AngleUnit::Radians,
                base_link: "base".to_owned(),
                base: None,
                tool: None,
                joints,
            })
        })
        .prop_map(|table| KinematicTree::from_description(&table.to_description().unwrap()).unwrap())
}

/// One joint of a random tree: (parent index, type, xyz, rpy, axis, mimic).
type JointSpec = (usize, usize, [f64; 3], [f64; 3], [f64; 3], Option<(f64, f64)>);

fn rpy_angle() -> impl Strategy<Value = f64> {
    use std::f64::consts::{FRAC_PI_2, PI};
    prop_oneof![2 => Just(0.0), 1 => prop::sample::select(vec![FRAC_PI_2, -FRAC_PI_2, PI]), 2 => -3.2..3.2f64]
}

fn axis() -> impl Strategy<Value = [f64; 3]> {
    prop_oneof![
        2 => prop::sample::select(vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, -1.0], [-1.0, 0.0, 0.0]]),
        // General axes that recur, also reversed, so parallel general axes occur.
        1 => prop::sample::select(vec![[0.6, 0.8, 0.0], [-0.6, -0.8, 0.0], [0.0, 0.6, 0.8]]),
        1 => [-1.0..1.0f64, -1.0..1.0f64, 0.1..1.0f64],
    ]
}

fn joint_spec(i: usize) -> impl Strategy<Value = JointSpec> {
    (
        0..=i,
        0..4usize,
        [length(), length(), length()],
        [rpy_angle(), rpy_angle(), rpy_angle()],
        axis(),
        prop::option::weighted(0.25, (-2.0..2.0f64, -1.0..1.0f64)),
    )
}

/// A random tree as URDF text: link `l{k+1}` hangs from a random earlier link; joints are
/// revolute, continuous, prismatic or fixed, and some mimic the first joint when it moves.
fn urdf_tree() -> impl Strategy<Value = String> {
    (1..=10usize).prop_flat_map(|n| (0..n).map(joint_spec).collect::<Vec<_>>()).prop_map(|specs| {
        let mut text = String::from("<robot name=\"random\"><link name=\"l0\"/>");
        let first_moves = specs.first().is_some_and(|s| s.1 != 3);
        for (k, (parent, kind, xyz, rpy, axis, mimic)) in specs.iter().enumerate() {
            let kind_name = ["revolute", "continuous", "prismatic", "fixed"][*kind];
            let mimic = match mimic {
                Some((m, o)) if k > 0 && first_moves && *kind != 3 => {
                    format!("<mimic joint=\"j0\" multiplier=\"{m}\" offset=\"{o}\"/>")
                }
                _ => String::new(),
            };
            text += &format!(
                "<link name=\"l{}\"/><joint name=\"j{k}\" type=\"{kind_name}\"><parent link=\"l{parent}\"/>\
                 <child link=\"l{}\"/><origin xyz=\"{} {} {}\" rpy=\"{} {} {}\"/><axis xyz=\"{} {} {}\"/>\
                 <limit lower=\"-2\" upper=\"2\" effort=\"1\" velocity=\"1\"/>{mimic}</joint>",
                k + 1,
                k + 1,
                xyz[0],
                xyz[1],
                xyz[2],
                rpy[0],
                rpy[1],
                rpy[2],
                axis[0],
                axis[1],
                axis[2]
            );
        }
        text + "</robot>"
    })
}

/// Every link's pose, and every leaf's pose compiled alone, against the runtime.
fn check(tree: &KinematicTree, q: &[f64]) -> Result<(), TestCaseError> {
    let fk = ReferenceFk::new(tree.clone());
    let reference = fk.link_poses(q).unwrap();
    let reach = tree.reach();
    let mut requests = vec![Request::all_links()];
    let last = tree.links().last().map(|l| l.name.clone()).unwrap_or_default();
    for link in tree.leaves().map(|l| tree.link(l)) {
        requests.push(Request::tip(&link.name));
        // Relative to another link, usually on another branch: up to the common ancestor and down.
        requests.push(Request::tip(&link.name).with_base(&last));
    }
    for request in requests {
        let compiled = compile(tree, &request).unwrap();
        for (frame, values) in compiled.frames().iter().zip(compiled.eval(q)) {
            let expected = match &request.base {
                Some(base) => fk.relative_pose(q, base, &frame.link).unwrap(),
                None => reference[fk.link_id(&frame.link).unwrap().0],
            };
            // The project's one measure and tolerance: translation over the reach, rotation
            // entries absolute, NaN infinitely far.
            let d = Pose::from_entries(&values).deviation(&expected, reach);
            prop_assert!(d <= AGREEMENT_TOLERANCE, "{}: off by {d:e} x reach at q = {q:?}", frame.link);
        }
    }
    Ok(())
}

fn with_q(tree: KinematicTree) -> impl Strategy<Value = (KinematicTree, Vec<f64>)> {
    let n = tree.dof();
    (Just(tree), proptest::collection::vec(-4.0..4.0f64, n))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn random_dh_chains((tree, q) in dh_chain().prop_flat_map(with_q)) {
        check(&tree, &q)?;
    }

    #[test]
    fn random_urdf_trees((tree, q) in urdf_tree().prop_map(|t| parse_source("random.urdf", &t).unwrap()).prop_flat_map(with_q)) {
        check(&tree, &q)?;
    }
}

/// Parallel general axes pointing opposite ways, separated by an offset: the angle-sum rule must
/// subtract the second angle (random trees rarely draw this case).
#[test]
fn antiparallel_general_axes() {
    let urdf = r#"<robot name="antiparallel"><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
      <joint name="j1" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0.6 0.8 0"/></joint>
      <joint name="j2" type="continuous"><parent link="b"/><child link="c"/><origin xyz="0.3 -0.2 0.5"/><axis xyz="-0.6 -0.8 0"/></joint>
      <joint name="j3" type="revolute"><parent link="c"/><child link="d"/><origin xyz="0.1 0.4 -0.3"/><axis xyz="0 0 -1"/>
        <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
    </robot>"#;
    let tree = parse_source("antiparallel.urdf", urdf).unwrap();
    for q in [[0.3, -1.1, 0.7], [2.0, 0.5, -0.4], [-1.5, -2.5, 0.9]] {
        check(&tree, &q).unwrap();
    }
}
