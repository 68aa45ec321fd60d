//! Operation counts of synthetic chains grow linearly with the number of joints.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics_compiler::{Request, compile};
use kinematics_model::synthetic;

#[test]
fn chain_op_counts_grow_linearly() {
    let mut counts = Vec::new();
    for n in [6, 12, 24, 48] {
        let count = compile(&synthetic::dh_chain(n), &Request::tip(&format!("link{n}"))).unwrap().op_count();
        println!("chain of {n:>2} joints: {count}");
        counts.push((n, count));
    }
    // The work each added joint costs stays the same from 6 to 48 joints (a quadratic blow-up would
    // double it at every step).
    let marginal: Vec<f64> = counts
        .windows(2)
        .map(|w| ((w[1].1.mul + w[1].1.add) - (w[0].1.mul + w[0].1.add)) as f64 / (w[1].0 - w[0].0) as f64)
        .collect();
    println!("operations per added joint: {marginal:?}");
    for m in &marginal {
        assert!((m / marginal[0] - 1.0).abs() < 0.2, "per-joint cost drifts: {marginal:?}");
    }
    for (n, count) in &counts {
        assert_eq!(count.sin_cos, *n, "one sin/cos pair per joint angle or angle sum");
    }
}

#[test]
fn tree_all_frames_shares_partial_products() {
    let tree = synthetic::tree(4, 10);
    let all = compile(&tree, &Request::all_links()).unwrap().op_count();
    let tips: usize =
        (0..4).map(|limb| compile(&tree, &Request::tip(&format!("limb{limb}_tool"))).unwrap().op_count().mul).sum();
    println!("40-joint tree, all 44 frames: {all}; four tool poses alone: {tips} multiplications");
    assert_eq!(all.sin_cos, 40);
    // Every frame costs about one joint's worth on top of its parent: far less than recomputing
    // each frame from the torso.
    assert!(all.mul < 3 * tips, "{all} vs {tips}");
}
