//! Operation counts of the generated code for every robot in `robots/`, against a plain sequential
//! product of the same transforms (zeros and ones folded, nothing else), and the targets we hold
//! the compiler to. `cargo test -p kinematics-compiler --test op_counts -- --nocapture` prints the
//! table the README carries.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use kinematics_compiler::{OpCount, Request, compile, plain_product_count};
use kinematics_model::KinematicTree;

/// The end effector: the deepest link (the last leaf of the longest path from the root).
fn end_effector(tree: &KinematicTree) -> String {
    let deepest = (0..tree.links().len()).max_by_key(|&l| (tree.path_from_root(kinematics_model::LinkId(l)).len(), l));
    tree.link(kinematics_model::LinkId(deepest.unwrap_or(0))).name.clone()
}

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

fn short(c: OpCount) -> String {
    format!("{}/{}/{}", c.sin_cos, c.mul, c.add)
}

#[test]
fn table_of_every_robot() {
    println!("sin_cos/mul/add per robot (tip pose: generated | plain product; position only; all links)");
    for file in robots() {
        let tree = common::robot(&file);
        let tip = end_effector(&tree);
        let pose = compile(&tree, &Request::tip(&tip)).unwrap().op_count();
        let position = compile(&tree, &Request::tip(&tip).positions_only()).unwrap().op_count();
        let all = compile(&tree, &Request::all_links()).unwrap().op_count();
        let plain = plain_product_count(&tree, tree.link(tree.root()).name.as_str(), &tip).unwrap();
        println!(
            "| {file:<24} | {:>2} | {tip:<20} | {:>12} | {:>12} | {:>12} | {:>13} |",
            tree.dof(),
            short(pose),
            short(plain),
            short(position),
            short(all)
        );
        assert!(pose.mul <= plain.mul && pose.add <= plain.add + tree.dof(), "{file}: {pose} vs plain {plain}");
        assert!(position.mul <= pose.mul, "{file}");
    }
}

fn pose_count(file: &str, tip: &str) -> OpCount {
    compile(&common::robot(file), &Request::tip(tip)).unwrap().op_count()
}

#[test]
fn ur5_end_effector() {
    let count = pose_count("ur5.toml", "wrist_3_link");
    assert_eq!(count.sin_cos, 6);
    assert!(count.add <= 22, "{count}");
    assert!(count.mul <= 37, "{count}");
}

#[test]
fn puma560_end_effector() {
    let count = pose_count("puma560.toml", "link6");
    assert_eq!(count.sin_cos, 6, "{count}");
    assert!(count.mul <= 46 && count.add <= 23, "{count}");
}

#[test]
fn panda_flange() {
    let count = pose_count("panda.toml", "flange");
    assert_eq!(count.sin_cos, 7, "{count}");
    assert!(count.mul <= 80 && count.add <= 43, "{count}");
}
