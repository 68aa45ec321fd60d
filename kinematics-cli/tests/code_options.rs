//! Options that change what is loaded or emitted: the global `--exact-angles <on|off>` (every
//! subcommand loads with it) and `generate --trig <fast|std>`.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::path::PathBuf;
use std::process::{Command, Output};

/// A chain whose fixed joint is turned by pi as ROS spells it (2e-13 rad off).
const ROS_PI: &str = r#"<robot name="r"><link name="a"/><link name="b"/><link name="c"/>
  <joint name="flip" type="fixed"><parent link="a"/><child link="b"/><origin rpy="3.14159265359 0 0"/></joint>
  <joint name="turn" type="continuous"><parent link="b"/><child link="c"/><origin xyz="0 1 0"/><axis xyz="0 0 1"/></joint>
</robot>"#;

/// A scratch directory holding `ros_pi.urdf`.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kinematics-cli-exact-{test}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("ros_pi.urdf"), ROS_PI).unwrap();
    dir
}

fn run(dir: &PathBuf, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_kinematics")).args(args).current_dir(dir).output().unwrap()
}

fn stdout(dir: &PathBuf, args: &[&str]) -> String {
    let output = run(dir, args);
    assert!(output.status.success(), "{args:?}: {}", String::from_utf8_lossy(&output.stderr));
    String::from_utf8(output.stdout).unwrap()
}

#[test]
fn the_option_reaches_loading_before_or_after_the_subcommand() {
    let dir = scratch("fk");
    let fk = ["fk", "ros_pi.urdf", "--json", "--q", "0.3"];
    let default = stdout(&dir, &fk);
    let on = stdout(&dir, &[&["--exact-angles", "on"], &fk[..]].concat());
    let off = stdout(&dir, &[&fk[..], &["--exact-angles", "off"]].concat());
    assert_eq!(default, on);
    // Read as written, the turn leaves its 2e-13 rad in the reference poses.
    assert_ne!(on, off);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn generate_honours_the_option() {
    // A quarter turn written 2e-10 rad off: exact when on, a number when off.
    let dir = scratch("generate");
    std::fs::write(dir.join("quarter.urdf"), ROS_PI.replace("3.14159265359", "1.570796327")).unwrap();
    let on = stdout(&dir, &["generate", "quarter.urdf"]);
    let off = stdout(&dir, &["--exact-angles", "off", "generate", "quarter.urdf"]);
    assert!(on.contains("pub struct R;") && off.contains("pub struct R;"));
    assert_ne!(on, off);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn generate_takes_the_trig_option() {
    let dir = scratch("trig");
    let fast = stdout(&dir, &["generate", "ros_pi.urdf"]);
    let std = stdout(&dir, &["generate", "ros_pi.urdf", "--trig", "std"]);
    assert_eq!(fast, stdout(&dir, &["generate", "ros_pi.urdf", "--trig", "fast"]));
    assert!(fast.contains("sin_cos") && !fast.contains("StdTrig"), "{fast}");
    assert!(std.contains("StdTrig::sin_cos_std("), "{std}");
    let output = run(&dir, &["generate", "ros_pi.urdf", "--trig", "libm"]);
    assert_eq!(output.status.code(), Some(2));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_bad_value_is_refused() {
    let dir = scratch("bad");
    let output = run(&dir, &["--exact-angles", "maybe", "inspect", "ros_pi.urdf"]);
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(stderr.contains("invalid value 'maybe' for '--exact-angles <on|off>'"), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}
