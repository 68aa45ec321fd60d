//! What the compiler emits for small robots, pinned as snapshots so a reviewer sees every change.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use kinematics_compiler::emit::{EmitOptions, emit_module_source};
use kinematics_compiler::{Request, compile};

fn source(file: &str, request: &Request, name: &str) -> String {
    let compiled = compile(&common::robot(file), request).unwrap();
    emit_module_source(&compiled, &EmitOptions::named(name)).unwrap()
}

#[test]
fn planar_3r_tip() {
    insta::assert_snapshot!(source("planar_3r.toml", &Request::tip("link3"), "link3_pose"));
}

#[test]
fn planar_3r_tip_position() {
    insta::assert_snapshot!(source("planar_3r.toml", &Request::tip("link3").positions_only(), "link3_position"));
}

#[test]
fn ur5_dh_flange() {
    insta::assert_snapshot!(source("ur5.toml", &Request::tip("wrist_3_link"), "flange_pose"));
}

#[test]
fn ur5_urdf_tool0() {
    insta::assert_snapshot!(source("ur5.urdf", &Request::tip("tool0").with_base("base"), "tool0_pose"));
}

#[test]
fn seed_tree_all_links() {
    insta::assert_snapshot!(source("seed_tree.urdf", &Request::all_links(), "all_links"));
}

#[test]
fn output_is_byte_identical_across_runs() {
    for file in ["planar_3r.toml", "ur5.urdf", "seed_tree.urdf"] {
        let first = source(file, &Request::all_links(), "all_links");
        for _ in 0..3 {
            assert_eq!(source(file, &Request::all_links(), "all_links"), first, "{file}");
        }
    }
}
