//! The crate's packaged copies of the workspace's files (compiled in by `build.rs` and
//! `src/panda.rs` so a published package builds on its own) are the workspace's, byte for byte:
//! the robots and the scene `kinematics demo` times are the ones every other test checks.
#![allow(clippy::panic)] // a missing file fails the test, naming the path

use std::path::Path;

/// The UR5 of the demo's forward kinematics, VAMP's Panda, its SRDF and the licence notice that
/// must travel with them, and the scene of the demo's collision step.
const PACKAGED: [&str; 5] =
    ["robots/ur5.urdf", "robots/panda_spherized.urdf", "robots/panda.srdf", "robots/NOTICE", "scenes/tabletop.toml"];

#[test]
fn packaged_files_are_the_workspace_files() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |path: &Path| std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    for file in PACKAGED {
        let packaged = read(&crate_dir.join(file));
        let workspace = read(&crate_dir.join("..").join(file));
        assert!(packaged == workspace, "kinematics-cli/{file} differs from {file}: copy the workspace's file over it");
    }
}

/// Every packaged copy is in the package: `Cargo.toml`'s `include` names each.
#[test]
fn packaged_files_are_included() {
    let manifest = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml"))
        .unwrap_or_else(|e| panic!("Cargo.toml: {e}"));
    for file in PACKAGED {
        assert!(manifest.contains(&format!("\"/{file}\"")), "Cargo.toml's `include` does not name /{file}");
    }
}
