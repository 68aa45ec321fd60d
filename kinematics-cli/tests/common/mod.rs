//! What the command-line tests share: the binary run as a user runs it, from the workspace root,
//! and a scratch folder per test.
// Each test file uses some of these; the others would be dead code in its binary.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The workspace root: the binary runs there, so `robots/...` paths work as in the README.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// `kinematics ARGS` run from the workspace root.
pub fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_kinematics")).args(args).current_dir(root()).output().unwrap()
}

/// Standard output of a run that must succeed quietly.
pub fn ok(args: &[&str]) -> String {
    let output = run(args);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "kinematics {args:?} failed: {stderr}");
    assert!(stderr.is_empty(), "kinematics {args:?} wrote to stderr: {stderr}");
    String::from_utf8(output.stdout).unwrap()
}

/// The error message of a run that must fail: status 1, one `error: ...` message, nothing on
/// stdout.
pub fn fails(args: &[&str]) -> String {
    let output = run(args);
    assert_eq!(output.status.code(), Some(1), "kinematics {args:?} should fail with status 1");
    assert!(output.stdout.is_empty(), "kinematics {args:?} printed {}", String::from_utf8_lossy(&output.stdout));
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(stderr.starts_with("error: ") && stderr.ends_with('\n'), "{stderr}");
    stderr.trim_end().to_owned()
}

/// An empty folder of this test binary's and test's own.
pub fn scratch(test: &str) -> PathBuf {
    let binary = env!("CARGO_CRATE_NAME");
    let dir = std::env::temp_dir().join(format!("kinematics-{binary}-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
