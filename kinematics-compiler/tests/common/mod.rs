//! Loading robots from `robots/` for the compiler's tests.
#![allow(dead_code)]

use kinematics_model::KinematicTree;

/// A robot from the workspace's `robots/` directory.
pub fn robot(file: &str) -> KinematicTree {
    let path = format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    kinematics_model::parse_source(file, &text).unwrap_or_else(|e| panic!("{e}"))
}
