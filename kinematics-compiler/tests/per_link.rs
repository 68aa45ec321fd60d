//! Per-link operation counts of all-links code ([`Compiled::marginal_op_counts`]) and what they
//! pin about trees: each link extends what the links before it computed, so a finger link costs a
//! joint's rotation and offset, not its whole path from the torso again.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use kinematics_compiler::{Compiled, OpCount, Request, compile};

fn all_links(file: &str) -> (kinematics_model::KinematicTree, Compiled) {
    let tree = common::robot(file);
    let compiled = compile(&tree, &Request::all_links()).unwrap();
    (tree, compiled)
}

fn sum(counts: &[OpCount]) -> OpCount {
    counts.iter().fold(OpCount::default(), |a, c| a + *c)
}

#[test]
fn per_link_counts_add_up_to_the_whole() {
    for file in ["humanoid.urdf", "dual_arm_torso.urdf", "quadruped.urdf", "ur5.urdf", "seed_tree.urdf", "panda.toml"] {
        let (_, compiled) = all_links(file);
        let counts = compiled.marginal_op_counts();
        assert_eq!(counts.len(), compiled.frames().len(), "{file}");
        assert_eq!(sum(&counts), compiled.op_count(), "{file}");
        // A frame alone costs at least what it adds after the frames before it.
        for (i, c) in counts.iter().enumerate() {
            let alone = compiled.frame_op_count(i);
            assert!(c.mul <= alone.mul && c.add <= alone.add && c.sin_cos <= alone.sin_cos, "{file} frame {i}");
        }
    }
}

/// The humanoid's fingers (mimic joints of the hand, `Rz(-0.999899)` fixed before each
/// `Rz(0.999899*q)`): every finger link after the first of its finger adds one rotation about its
/// axis and one offset along x (12 + 3 multiplications) and no `sin_cos` of its own (its angle
/// `0.999899*q - 0.999899` comes from `0.999899*q` by the sum formulas, four multiplications), so
/// the whole robot needs one `sin_cos` per degree of freedom and one per hand for the finger angle.
#[test]
fn humanoid_finger_links_extend_their_parents() {
    let (tree, compiled) = all_links("humanoid.urdf");
    let counts = compiled.marginal_op_counts();
    let mut checked = 0;
    for (frame, count) in compiled.frames().iter().zip(&counts) {
        let link = &frame.link;
        let follower = ["Finger12", "Finger13", "Finger22", "Finger23", "Thumb2"].iter().any(|f| link.contains(f));
        if follower {
            assert_eq!(count.sin_cos, 0, "{link}: {count}");
            assert!(count.mul <= 12 + 3 + 4, "{link}: {count}");
            checked += 1;
        }
    }
    assert_eq!(checked, 10);
    assert_eq!(compiled.op_count().sin_cos, tree.dof() + 2, "{}", compiled.op_count());
}

/// A fixed joint with the identity origin adds nothing: its link's pose is its parent's.
#[test]
fn a_frame_equal_to_its_parent_costs_nothing() {
    let (_, compiled) = all_links("humanoid.urdf");
    let counts = compiled.marginal_op_counts();
    let torso = compiled.frames().iter().position(|f| f.link == "torso").unwrap();
    assert_eq!(counts[torso], OpCount::default());
}

/// The evaluator `kinematics check` runs (each node the poses need, once, in order) gives every
/// frame's entries bit for bit as the graph's recursive evaluation, at configurations across the
/// joints' ranges, on trees and mimic joints.
#[test]
fn the_evaluator_agrees_with_the_recursive_evaluation_bit_for_bit() {
    for file in ["humanoid.urdf", "quadruped.urdf", "ur5.urdf", "panda.toml", "seed_tree.urdf"] {
        let (tree, compiled) = all_links(file);
        let mut evaluator = compiled.evaluator();
        for k in 0..20 {
            let q: Vec<f64> = (0..tree.dof()).map(|i| (0.37 * (k * 7 + i) as f64).sin() * 3.0).collect();
            let vars = compiled.variables(&q);
            let mut memo = Vec::new();
            let recursive: Vec<[f64; 12]> = compiled
                .frames()
                .iter()
                .map(|f| f.transform.entries().map(|id| compiled.graph().eval(id, &vars, &mut memo)))
                .collect();
            let bits = |poses: &[[f64; 12]]| poses.iter().flatten().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&evaluator.eval(&q)), bits(&recursive), "{file} at {q:?}");
            assert!(recursive.iter().flatten().all(|x| x.is_finite()), "{file}");
        }
    }
}
