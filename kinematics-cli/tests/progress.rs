//! Progress (issue 21): `check` draws a spinner while it compiles and a bar over the
//! configurations when stderr is a terminal, and writes nothing to stderr when it is not (every
//! test in `cli.rs` also requires an empty stderr of a successful run).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A standard-DH chain of `n` joints, written into a scratch directory.
fn chain(test: &str, n: usize) -> (PathBuf, String) {
    let dir = std::env::temp_dir().join(format!("kinematics-progress-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let twists = ["\"pi/2\"", "0", "0", "\"pi/2\"", "\"-pi/2\"", "0"];
    let mut toml = String::from("convention = \"standard\"\n");
    for i in 0..n {
        toml += &format!(
            "[[joints]]\nname = \"j{}\"\na = {}\nd = 0.1\nalpha = {}\n",
            i + 1,
            0.3 + 0.001 * i as f64,
            twists[i % 6]
        );
    }
    let file = dir.join("chain.toml");
    std::fs::write(&file, toml).unwrap();
    (dir, file.to_str().unwrap().to_owned())
}

#[test]
fn check_is_quiet_on_stderr_when_piped() {
    let (dir, file) = chain("piped", 60);
    let output = Command::new(env!("CARGO_BIN_EXE_kinematics"))
        .args(["check", &file, "--samples", "3000"])
        .current_dir(root())
        .output()
        .unwrap();
    assert!(output.status.success());
    assert!(output.stderr.is_empty(), "{}", String::from_utf8_lossy(&output.stderr));
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(stdout.starts_with("robot `robot`: the compiled pose of every link") && !stdout.contains('\r'), "{stdout}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// On a terminal (a pseudo-terminal made by util-linux `script`, so stdout and stderr both reach
/// it), the stages show, and the table still follows.
#[cfg(target_os = "linux")]
#[test]
fn check_shows_its_stages_on_a_terminal() {
    let (dir, file) = chain("terminal", 60);
    let command = format!("{} check {file} --samples 3000", env!("CARGO_BIN_EXE_kinematics"));
    let output = Command::new("script")
        .args(["--quiet", "--return", "--command", &command, "/dev/null"])
        .current_dir(root())
        .env("TERM", "xterm")
        .output()
        .expect("util-linux `script` runs the command on a pseudo-terminal");
    let screen = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{screen}");
    assert!(screen.contains("compiling every link's pose"), "{screen}");
    assert!(screen.contains("checking configurations"), "{screen}");
    assert!(screen.contains("within the tolerance 1e-12"), "{screen}");
    std::fs::remove_dir_all(&dir).unwrap();
}
