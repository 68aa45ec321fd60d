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

/// Every link of a chain past the bound on tips folded each from the base (256): each link built on
/// its parent's pose, one sin/cos pair per joint, about one joint's worth of operations per link
/// (the same per-link cost as a chain below the bound), and the poses those of the chain below the
/// bound to rounding. Compiling this chain took 36 s at 2,000 links when every link was folded
/// from the base as well (`kinematics check` on a 5,000-joint chain: over five minutes, 6 s now).
#[test]
fn a_long_chain_compiles_every_link_in_linear_work() {
    let (short, long) = (synthetic::dh_chain(200), synthetic::dh_chain(600));
    let (short, long) =
        (compile(&short, &Request::all_links()).unwrap(), compile(&long, &Request::all_links()).unwrap());
    let (a, b) = (short.op_count(), long.op_count());
    println!("all links, 200 joints: {a}; 600 joints: {b}");
    assert_eq!((a.sin_cos, b.sin_cos), (200, 600));
    let per_link = |c: kinematics_compiler::OpCount, n: f64| (c.mul + c.add) as f64 / n;
    assert!(per_link(b, 600.0) < 1.2 * per_link(a, 200.0), "{a} vs {b}");
    // The first 200 links of the long chain are the short chain's links.
    let q: Vec<f64> = (0..600).map(|i| 0.1 * f64::from(i % 13) - 0.6).collect();
    let (poses_short, poses_long) = (short.eval(&q[..200]), long.eval(&q));
    for (k, (s, l)) in poses_short.iter().zip(&poses_long).enumerate() {
        assert!(s.iter().zip(l.iter()).all(|(x, y)| (x - y).abs() < 1e-9), "link {k}: {s:?} vs {l:?}");
    }
}
