//! Loading robots from `robots/` for the compiler's tests.
#![allow(dead_code)]

use kinematics_model::KinematicTree;

pub mod arms;

/// A robot from the workspace's `robots/` directory.
pub fn robot(file: &str) -> KinematicTree {
    let path = format!("{}/../robots/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    kinematics_model::parse_source(file, &text).unwrap_or_else(|e| panic!("{e}"))
}

/// Every description file in `robots/`, sorted.
pub fn robots() -> Vec<String> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots");
    let mut files: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{dir}: {e}"))
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|f| kinematics_model::SourceFormat::from_file_name(f).is_some())
        .collect();
    files.sort();
    files
}
