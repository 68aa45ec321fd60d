//! The crate's packaged copy of the UR5 (`robots/ur5.urdf`, compiled in by `build.rs` so a
//! published package builds on its own) is the workspace's robot, byte for byte: the robot
//! `kinematics demo` times is the one every other test checks.
#![allow(clippy::panic)] // a missing file fails the test, naming the path

use std::path::Path;

#[test]
fn packaged_ur5_is_the_workspace_robot() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |path: &Path| std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let packaged = read(&crate_dir.join("robots/ur5.urdf"));
    let workspace = read(&crate_dir.join("../robots/ur5.urdf"));
    assert!(
        packaged == workspace,
        "kinematics-cli/robots/ur5.urdf differs from robots/ur5.urdf: copy the workspace's file over it"
    );
}
