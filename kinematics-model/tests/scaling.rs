//! Loading scales (issue 13: loading was roughly cubic, 30 s for a 5,000-joint chain): validating
//! a 5,000-joint chain, a 5,000-joint mimic chain, a 5,000-link cycle and a 1,000-joint tree, and
//! looking every link and joint up by name, each take well under two seconds.
//!
//! Wall-clock bounds, deliberately generous so that a busy machine does not make them flaky: the
//! fixed code validates the chain in tens of milliseconds. The descriptions are built here rather
//! than parsed, so the bound measures the model (parsing is urdf-rs's, linear, and about 1.5 s for
//! this chain's text in a debug build). Names share a long prefix, so that a lookup that scans
//! every link compares long strings and shows.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::time::{Duration, Instant};

use kinematics_model::{
    Description, Element, FixedTransform, JointDescription, JointTypeDescription, KinematicTree, LimitsDescription,
    LinkId, MimicDescription,
};

const BOUND: Duration = Duration::from_secs(2);

/// A long common prefix for every name.
fn name(kind: &str, i: usize) -> String {
    format!("{}_{kind}{i}", "robot_part".repeat(20))
}

fn joint(i: usize, parent: usize, mimic: Option<usize>) -> JointDescription {
    let name = name("joint", i);
    JointDescription {
        element: Element::Joint(name.clone()),
        name,
        kind: JointTypeDescription::Revolute,
        parent: self::name("link", parent),
        child: self::name("link", i),
        origin: FixedTransform::identity().translate([0.0, 0.0, 0.1]),
        after_motion: FixedTransform::identity(),
        axis: [0.0, 1.0, 0.0],
        limits: Some(LimitsDescription { lower: -1.0, upper: 1.0, velocity: None, effort: None }),
        mimic: mimic.map(|m| MimicDescription { joint: self::name("joint", m), multiplier: 1.0, offset: 0.0 }),
    }
}

/// Links `0..=n`; joint `i` (1..=n) hangs link `i` below link `parent(i)`, mimicking `mimic(i)`.
/// Joints are listed leaves first, so that no order of the description helps.
fn description(n: usize, parent: impl Fn(usize) -> usize, mimic: impl Fn(usize) -> Option<usize>) -> Description {
    Description {
        name: "big".to_owned(),
        links: (0..=n).rev().map(|i| name("link", i)).collect(),
        joints: (1..=n).rev().map(|i| joint(i, parent(i), mimic(i))).collect(),
        collisions: Vec::new(),
        ignored: Vec::new(),
        excluded_pairs: Vec::new(),
        inertials: Vec::new(),
        inertia_from_geometry: Vec::new(),
    }
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, Duration) {
    let start = Instant::now();
    let value = f();
    (value, start.elapsed())
}

/// Every per-link query a front end makes, for every link: lookups by name and depth; then the
/// chain to the deepest link.
fn query_every_link(tree: &KinematicTree) {
    for (i, link) in tree.links().iter().enumerate() {
        assert_eq!(tree.link_id(&link.name), Some(LinkId(i)));
        assert!(tree.link_by_name(&link.name).is_some());
        if let Some(j) = link.parent_joint {
            assert_eq!(tree.joint_id(&tree.joint(j).name), Some(j));
            assert_eq!(tree.depth(LinkId(i)), tree.depth(tree.joint(j).parent) + 1);
        }
    }
    let deepest = (0..tree.links().len()).map(LinkId).max_by_key(|&l| tree.depth(l)).unwrap();
    let chain = tree.chain(&tree.link(tree.root()).name, &tree.link(deepest).name).unwrap();
    assert_eq!(chain.joints.len(), tree.depth(deepest));
    assert_eq!(tree.path_from_root(deepest), chain.joints);
}

fn load_and_query(d: &Description) -> KinematicTree {
    let (tree, took) = timed(|| KinematicTree::from_description(d).unwrap());
    assert!(took < BOUND, "validation took {took:?}");
    let ((), took) = timed(|| query_every_link(&tree));
    assert!(took < BOUND, "the queries took {took:?}");
    tree
}

#[test]
fn a_5000_joint_chain_loads_in_under_two_seconds() {
    let tree = load_and_query(&description(5000, |i| i - 1, |_| None));
    assert_eq!((tree.links().len(), tree.dof()), (5001, 5000));
    assert_eq!(tree.depth(LinkId(5000)), 5000);
}

#[test]
fn a_5000_joint_chain_of_mimics_loads_in_under_two_seconds() {
    // Every joint but the first mimics the one before it: one mimic chain 4,999 long.
    let tree = load_and_query(&description(5000, |i| i - 1, |i| (i > 1).then(|| i - 1)));
    assert_eq!(tree.dof(), 1);
    let last = tree.joint_by_name(&name("joint", 5000)).unwrap();
    assert_eq!(last.motion.value(&[0.5]), Some(0.5));
}

#[test]
fn a_1000_joint_tree_loads_in_under_two_seconds() {
    // A binary tree: link `i` hangs below link `(i - 1) / 2`.
    let tree = load_and_query(&description(1000, |i| (i - 1) / 2, |_| None));
    assert_eq!((tree.links().len(), tree.dof()), (1001, 1000));
    assert_eq!(tree.link(tree.root()).name, name("link", 0));
    // Depth-first pre-order: children in description order (listed leaves first here), each subtree after its link.
    assert_eq!(tree.link(LinkId(1)).name, name("link", 2));
    assert_eq!(tree.link(LinkId(2)).name, name("link", 6));
}

#[test]
fn a_5000_link_cycle_is_found_in_under_two_seconds() {
    // Link i hangs below link i + 1 (mod n), and a separate root: one cycle through every link
    // but the root. The cycle walk used to start from every link and search its path linearly.
    let n = 5000;
    let mut d = description(n - 1, |i| (i + 1) % n, |_| None);
    d.joints.push(joint(0, 1, None));
    d.links.push(name("link", n));
    let (result, took) = timed(|| KinematicTree::from_description(&d));
    let errors = result.unwrap_err();
    assert_eq!(errors.errors().len(), 1, "{errors}");
    assert!(matches!(&errors.errors()[0], kinematics_model::ModelError::Cycle { links } if links.len() == n));
    assert!(took < BOUND, "took {took:?}");
}

#[test]
fn a_5000_joint_mimic_loop_is_found_in_under_two_seconds() {
    let n = 5000;
    let d = description(n, |i| i - 1, |i| Some(if i == 1 { n } else { i - 1 }));
    let (result, took) = timed(|| KinematicTree::from_description(&d));
    let errors = result.unwrap_err();
    assert_eq!(errors.errors().len(), 1, "{errors}");
    assert!(matches!(&errors.errors()[0], kinematics_model::ModelError::MimicLoop { joints } if joints.len() == n));
    assert!(took < BOUND, "took {took:?}");
}
