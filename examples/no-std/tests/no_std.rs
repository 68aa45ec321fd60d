//! The crate built on its own, as a firmware user builds it: its dependencies are the no_std ones,
//! and the user binary holds no XML, TOML, JSON or nalgebra code.
//!
//! Inside the workspace, cargo unifies features across members, so `kinematics` gets `std` from
//! the other crates; these tests therefore run cargo on this package alone, in a target directory
//! of its own (the outer `cargo test` holds the workspace's).
//!
//! `cargo tree` must list only `kinematics`, `kinematics-core` and `libm`, with no `std` feature,
//! and the binary must hold no symbol of roxmltree, nalgebra, serde_json, toml, the model or the
//! runtime.

#![allow(clippy::expect_used)] // test helpers fail loudly

use std::path::PathBuf;
use std::process::Command;

fn manifest_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn cargo() -> Command {
    let mut command = Command::new(env!("CARGO"));
    command.current_dir(manifest_dir());
    command
}

/// `cargo tree` of this package's normal dependencies, one `name features` line each.
fn tree() -> String {
    let output = cargo()
        .args([
            "tree",
            "-p",
            "kinematics-no-std-example",
            "-e",
            "normal,no-proc-macro",
            "--prefix",
            "none",
            "--format",
            "{p} [{f}]",
        ])
        .output()
        .expect("cargo tree runs");
    assert!(output.status.success(), "cargo tree failed: {}", String::from_utf8_lossy(&output.stderr));
    String::from_utf8(output.stdout).expect("cargo tree prints UTF-8")
}

#[test]
fn the_run_time_dependencies_are_the_no_std_crates() {
    let tree = tree();
    let mut crates: Vec<&str> =
        tree.lines().filter_map(|line| line.split_whitespace().next()).filter(|name| !name.is_empty()).collect();
    crates.sort_unstable();
    crates.dedup();
    // The derive is a proc macro: it runs in the compiler and links nothing into the user's code
    // (`no-proc-macro` leaves it out). What the generated code calls is `kinematics` (the facade,
    // `no_std` without its `std` feature), `kinematics-core` and `libm` (both `no_std`).
    assert_eq!(crates, ["kinematics", "kinematics-core", "kinematics-no-std-example", "libm"], "{tree}");
    for line in tree.lines() {
        let features = line.rsplit_once('[').map_or("", |(_, f)| f);
        assert!(
            !features.contains("std") && !features.contains("nalgebra") && !features.contains("rayon"),
            "a feature that needs std is on: {line}\n{tree}"
        );
    }
}

#[test]
fn the_user_binary_holds_no_xml_toml_json_or_nalgebra_code() {
    let target = manifest_dir().join("../../target/no-std-check");
    let status = cargo()
        .args(["build", "-p", "kinematics-no-std-example", "--bin", "kinematics-no-std-example", "--target-dir"])
        .arg(&target)
        // The workspace optimises the compiler and the model for the tests that run them on
        // thousands of configurations; the derive here compiles one small robot, so in this
        // target directory of its own their optimisation would cost more than it saves.
        .args(["--config", "profile.dev.package.kinematics-compiler.opt-level=0"])
        .args(["--config", "profile.dev.package.kinematics-model.opt-level=0"])
        .status()
        .expect("cargo build runs");
    assert!(status.success(), "the no_std example does not build on its own");
    let binary = std::fs::read(target.join("debug/kinematics-no-std-example")).expect("the binary was built");
    let contains = |needle: &str| binary.windows(needle.len()).any(|w| w == needle.as_bytes());
    // Our own code is there (the sanity check that the search can find a crate's symbols)...
    assert!(contains("kinematics_no_std_example"));
    // ...and none of these crates' (mangled symbol names carry the crate name).
    for absent in ["roxmltree", "nalgebra", "serde_json", "toml", "kinematics_model", "kinematics_runtime", "urdf"] {
        assert!(!contains(absent), "the binary contains `{absent}`");
    }
}
