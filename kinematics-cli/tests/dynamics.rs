//! `--dynamics` (issue 61) on the command line: `generate` prints what the build API writes with
//! `.dynamics()`, `check` compares every compiled function with the runtime reference and counts
//! the states where the mass matrix is singular, `expr` prints the gravity torques as a textbook
//! writes them; every refusal (no mass, an inertia no rigid body has, a gravity that is not
//! finite, a joint the robot does not have) names the flag, and the link and line where there are
//! ones.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::path::Path;

mod common;
use common::{fails, ok, root, run, scratch};

/// The two-link arm in the vertical plane, point masses at the link ends (see the file).
const ARM: &str = "kinematics-cli/tests/fixtures/two_link_arm.urdf";

/// A link whose principal moments (1, 1, 3) break the triangle inequality, its `<inertial>` on
/// line 3.
const BAD_INERTIA: &str = r#"<robot name="bad">
  <link name="a"/>
  <link name="b"><inertial><mass value="1"/>
    <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="3"/></inertial></link>
  <joint name="j" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 1 0"/></joint>
</robot>"#;

/// A two-joint arm whose hand carries no mass: its wrist's acceleration no torque determines.
const MASSLESS_HAND: &str = r#"<robot name="massless_hand">
  <link name="base"/>
  <link name="upper"><inertial><origin xyz="0.5 0 0"/><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial></link>
  <link name="hand"/>
  <joint name="shoulder" type="continuous"><parent link="base"/><child link="upper"/><axis xyz="0 1 0"/></joint>
  <joint name="wrist" type="continuous"><parent link="upper"/><child link="hand"/>
    <origin xyz="1 0 0"/><axis xyz="0 1 0"/></joint>
</robot>"#;

/// Writes `text` as `name` in `dir` and returns the path as a string.
fn write_file(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_owned()
}

/// A usage error of clap's: status 2, the message naming `fragment`.
fn usage_error(args: &[&str], fragment: &str) {
    let output = run(args);
    assert_eq!(output.status.code(), Some(2), "kinematics {args:?}");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains(fragment), "kinematics {args:?}: {stderr}");
}

#[test]
fn generate_emits_the_dynamics_as_the_build_api_does() {
    let out = ok(&["generate", "robots/ur5.urdf", "--dynamics"]);
    let expected = kinematics_build::Robot::file("robots/ur5.urdf").manifest_dir(root()).dynamics().generate().unwrap();
    assert!(out == expected, "`kinematics generate --dynamics` differs from the build API");
    for signature in [
        "pub fn gravity_torques(q: &[f64; 6]) -> [f64; 6]",
        "pub fn nonlinear_effects(q: &[f64; 6], qd: &[f64; 6]) -> [f64; 6]",
        "pub fn mass_matrix(q: &[f64; 6]) -> [[f64; 6]; 6]",
        "pub fn inverse_dynamics(",
        "pub fn forward_dynamics(",
    ] {
        assert!(out.contains(signature), "no `{signature}`");
    }
    assert!(out.contains("under gravity (0, 0, -9.81) m/s^2 in `base_link`'s frame"));
    // Another gravity, and tensors taken as written.
    let dir = scratch("generate");
    let bad = write_file(&dir, "bad.urdf", BAD_INERTIA);
    let out = ok(&["generate", &bad, "--dynamics", "--gravity", "0.5,0,-9.81", "--inertia-as-written"]);
    let expected =
        kinematics_build::Robot::file(&bad).gravity([0.5, 0.0, -9.81]).inertia_as_written().generate().unwrap();
    assert!(out == expected, "`--gravity` and `--inertia-as-written` differ from the build API's");
    assert!(out.contains("under gravity (0.5, 0, -9.81) m/s^2 in `a`'s frame"), "{out}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn generate_refusals_name_the_flag_the_link_and_the_line() {
    let dir = scratch("generate-refusals");
    let bad = write_file(&dir, "bad.urdf", BAD_INERTIA);
    assert_eq!(
        fails(&["generate", &bad, "--dynamics"]),
        format!(
            "error: {bad}: `--dynamics`: robot `bad`: the <inertial> of link `b` (line 3): its inertia's principal \
             moments [1.0, 1.0, 3.0] kg m^2 break the triangle inequality (each must be at most the sum of the other \
             two), as no rigid body's do"
        )
    );
    assert_eq!(
        fails(&["generate", "robots/planar_3r.urdf", "--dynamics"]),
        "error: robots/planar_3r.urdf: `--dynamics`: `dynamics` of a robot with no mass: no link has an <inertial> \
         (a link without one is massless)"
    );
    assert_eq!(
        fails(&["generate", "robots/ur5.urdf", "--dynamics", "--gravity", "inf,0,-9.81"]),
        "error: robots/ur5.urdf: `--gravity`: `gravity` is [inf, 0.0, -9.81] (must be three finite numbers, m/s^2 in \
         the root link's frame)"
    );
    // Not three numbers, or without `--dynamics`: clap's usage errors.
    usage_error(&["generate", "robots/ur5.urdf", "--dynamics", "--gravity", "0,-9.81"], "three numbers are needed");
    usage_error(&["generate", "robots/ur5.urdf", "--gravity", "0,0,-9.81"], "--dynamics");
    usage_error(&["generate", "robots/ur5.urdf", "--inertia-as-written"], "--dynamics");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The `function  error` rows of `check --dynamics`' table.
fn dynamics_rows(out: &str) -> Vec<(String, String)> {
    out.lines()
        .skip_while(|l| !l.starts_with("function "))
        .skip(1)
        .take_while(|l| !l.starts_with("singular mass matrix: "))
        .map(|l| {
            let (name, rest) = l.split_once(' ').unwrap();
            (name.to_owned(), rest.trim().to_owned())
        })
        .collect()
}

#[test]
fn check_compares_every_dynamics_function_with_the_reference() {
    for file in ["robots/ur5.urdf", "robots/panda.urdf"] {
        let out = ok(&["check", file, "--samples", "20", "--dynamics", "--dynamics-samples", "200"]);
        assert!(out.contains("\ndynamics: the compiled functions against the runtime reference (ReferenceDynamics)"));
        assert!(
            out.contains("\n200 states: configurations drawn as above, rates and accelerations uniform in [-2, 2]\n")
        );
        let rows = dynamics_rows(&out);
        let names: Vec<&str> = rows.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(
            names,
            ["gravity_torques", "inverse_dynamics", "nonlinear_effects", "mass_matrix", "forward_dynamics"],
            "{out}"
        );
        for (name, error) in &rows {
            let error: f64 = error.split_whitespace().next().unwrap().parse().unwrap();
            assert!(error <= 1e-12, "{file}: {name}: {error}");
        }
        assert!(out.contains("\nsingular mass matrix: 0 of 200 states, refused by both\n"), "{out}");
        assert!(out.ends_with("within the tolerance 1e-12\n"), "{out}");
    }
    // Another gravity is the reference's too.
    let tilted = ok(&[
        "check",
        "robots/ur5.urdf",
        "--samples",
        "5",
        "--dynamics",
        "--gravity",
        "1,-2,-9",
        "--dynamics-samples",
        "20",
    ]);
    assert!(tilted.contains("gravity (1, -2, -9) m/s^2 in `base_link`'s frame"), "{tilted}");
    assert!(tilted.ends_with("within the tolerance 1e-12\n"), "{tilted}");
    // A hand that carries no mass: both refuse forward dynamics at every state, and that is no error.
    let dir = scratch("check-singular");
    let hand = write_file(&dir, "hand.urdf", MASSLESS_HAND);
    let out = ok(&["check", &hand, "--samples", "5", "--dynamics", "--dynamics-samples", "50"]);
    assert!(out.contains("\nsingular mass matrix: 50 of 50 states, refused by both\n"), "{out}");
    let rows = dynamics_rows(&out);
    assert_eq!(rows[4].1, "none compared: the mass matrix is singular at every state", "{out}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn check_dynamics_refusals_name_the_flag_before_anything_is_printed() {
    assert_eq!(
        fails(&["check", "robots/ur5.urdf", "--dynamics", "--gravity", "nan,0,-9.81"]),
        "error: robots/ur5.urdf: `--gravity`: `gravity` is [NaN, 0.0, -9.81] (must be three finite numbers, m/s^2 in \
         the root link's frame)"
    );
    let message = fails(&["check", "robots/planar_3r.toml", "--dynamics"]);
    assert!(message.ends_with("`--dynamics`: `dynamics` of a robot with no mass: no link has an <inertial> (a link without one is massless)"), "{message}");
    let dir = scratch("check-refusals");
    let bad = write_file(&dir, "bad.urdf", BAD_INERTIA);
    let message = fails(&["check", &bad, "--dynamics"]);
    assert!(
        message.starts_with(&format!("error: {bad}: `--dynamics`: robot `bad`: the <inertial> of link `b` (line 3)")),
        "{message}"
    );
    // As written, the same tensor is checked.
    let out = ok(&["check", &bad, "--dynamics", "--inertia-as-written", "--dynamics-samples", "20"]);
    assert!(out.ends_with("within the tolerance 1e-12\n"), "{out}");
    usage_error(&["check", "robots/ur5.urdf", "--dynamics", "--dynamics-samples", "0"], "checks nothing");
    usage_error(&["check", "robots/ur5.urdf", "--dynamics-samples", "10"], "--dynamics");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The arm of `tests/fixtures/two_link_arm.urdf`: m1 = 3 kg at l1 = 1 m, m2 = 1.5 kg at
/// l2 = 0.5 m, both joints about -y (a positive angle raises the arm), gravity 9.81 m/s^2 down.
///
/// The textbook's torques that hold it still are `tau1 = g (m1 + m2) l1 c1 + g m2 l2 c12` and
/// `tau2 = g m2 l2 c12`, with `(m1 + m2) l1 = 4.5` and `m2 l2 = 0.75`. The compiler prints
/// exactly those: `tau1 = 9.81*(0.75*c12 + 4.5*c1)` and `tau2 = 7.3575*c12` (`9.81 * 0.75`).
#[test]
fn expr_prints_the_gravity_torques_of_a_two_link_arm() {
    let out = ok(&["expr", ARM, "--dynamics"]);
    assert_eq!(
        out,
        "robot `two_link_arm`: gravity torques (the generalized forces that hold it still), gravity (0, 0, -9.81) \
         m/s^2 in `base`'s frame\n\
         joints: q1 = shoulder, q2 = elbow\n\
         angles: c12/s12 = cos/sin(q1 + q2)\n\
         \n\
         tau1 = 9.81*(0.75*c12 + 4.5*c1)\n\
         tau2 = 7.3575*c12\n\
         \n\
         operations:\n\
         \x20                    sin_cos / mul / add / div\n\
         \x20 gravity_torques          2 /   4 /   2 /   0\n\
         \x20 inverse_dynamics         2 /  25 /  17 /   0\n\
         \x20 nonlinear_effects        2 /  23 /  13 /   0\n\
         \x20 mass_matrix              1 /   2 /   2 /   0\n\
         \x20 forward_dynamics         2 /  29 /  19 /   1\n"
    );
    // The text is the reference's numbers: the formula above at a configuration.
    let (q1, q2) = (0.3f64, -1.1f64);
    let tau2 = 0.75 * 9.81 * (q1 + q2).cos();
    let tau1 = 9.81 * 4.5 * q1.cos() + tau2;
    let tree = kinematics::load(root().join(ARM)).unwrap();
    let reference = kinematics::runtime::ReferenceDynamics::new(tree, [0.0, 0.0, -9.81], false).unwrap();
    let held = reference.gravity_torques(&[q1, q2]).unwrap();
    assert!((held[0] - tau1).abs() < 1e-12 && (held[1] - tau2).abs() < 1e-12, "{held:?}");
    // One joint, and another gravity.
    let elbow = ok(&["expr", ARM, "--dynamics", "--joint", "elbow"]);
    assert!(elbow.contains("\n\ntau2 = 7.3575*c12\n\noperations:\n"), "{elbow}");
    assert!(!elbow.contains("tau1"), "{elbow}");
    let moon = ok(&["expr", ARM, "--dynamics", "--gravity", "0,0,-1.62", "--joint", "elbow"]);
    assert!(moon.contains("gravity (0, 0, -1.62) m/s^2") && moon.contains("tau2 = 1.215*c12\n"), "{moon}");
}

#[test]
fn expr_dynamics_refuses_an_unknown_joint_and_a_robot_without_mass() {
    assert_eq!(
        fails(&["expr", ARM, "--dynamics", "--joint", "elbw"]),
        format!(
            "error: {ARM}: `--joint`: `elbw` is none of the velocities (`shoulder`, `elbow`); did you mean `elbow`?"
        )
    );
    assert_eq!(
        fails(&["expr", "robots/planar_3r.urdf", "--dynamics"]),
        "error: robots/planar_3r.urdf: `--dynamics`: `dynamics` of a robot with no mass: no link has an <inertial> \
         (a link without one is massless)"
    );
    let dir = scratch("expr-refusals");
    let bad = write_file(&dir, "bad.urdf", BAD_INERTIA);
    assert!(
        fails(&["expr", &bad, "--dynamics"]).contains("`--dynamics`: robot `bad`: the <inertial> of link `b` (line 3)")
    );
    assert!(ok(&["expr", &bad, "--dynamics", "--inertia-as-written"]).contains("\ntau1 = "));
    std::fs::remove_dir_all(&dir).unwrap();
    // `--joint` belongs to `--dynamics`, which prints no pose.
    usage_error(&["expr", ARM, "--joint", "elbow"], "--dynamics");
    usage_error(&["expr", ARM, "--dynamics", "--jacobian"], "cannot be used with");
}

/// A free-flying body with a hinged arm: its torques are in its own axes, through the rotation's
/// entries.
const FLYER: &str = r#"<robot name="flyer"><link name="world"/>
  <link name="body"><inertial><origin xyz="0.1 0 0"/><mass value="2"/>
    <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.25"/></inertial></link>
  <link name="arm"><inertial><origin xyz="0.3 0 0"/><mass value="1"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.02"/></inertial></link>
  <joint name="free" type="floating"><parent link="world"/><child link="body"/></joint>
  <joint name="elbow" type="continuous"><parent link="body"/><child link="arm"/><origin xyz="0.2 0 0"/>
    <axis xyz="0 0 1"/></joint>
</robot>"#;

#[test]
fn expr_and_check_take_a_floating_base() {
    let dir = scratch("flyer");
    let flyer = write_file(&dir, "flyer.urdf", FLYER);
    let out = ok(&["expr", &flyer, "--dynamics"]);
    assert!(
        out.contains(
            "\nvelocities: tau1 = free.vx, tau2 = free.vy, tau3 = free.vz, tau4 = free.wx, tau5 = free.wy, tau6 = \
             free.wz, tau7 = elbow\nrotations: rot1_ij = `free`'s (row i, column j, from its quaternion)\n"
        ),
        "{out}"
    );
    assert_eq!(out.lines().filter(|l| l.starts_with("tau")).count(), 7, "{out}");
    assert!(out.contains("rot1_3"), "{out}");
    let checked = ok(&["check", &flyer, "--samples", "5", "--dynamics", "--dynamics-samples", "100"]);
    assert!(checked.ends_with("within the tolerance 1e-12\n"), "{checked}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--forces`: `check` compares the two functions with external forces too, `generate` writes
/// them, and a link they cannot take is refused naming the flag.
#[test]
fn forces_on_links_are_checked_generated_and_refused() {
    let out = ok(&[
        "check",
        "robots/panda.urdf",
        "--samples",
        "5",
        "--dynamics",
        "--forces",
        "panda_hand,panda_link3",
        "--dynamics-samples",
        "100",
    ]);
    let rows = dynamics_rows(&out);
    let names: Vec<&str> = rows.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names[5..], ["inverse_dynamics_with_forces", "forward_dynamics_with_forces"], "{out}");
    for (name, error) in &rows {
        let error: f64 = error.split_whitespace().next().unwrap().parse().unwrap();
        assert!(error <= 1e-12, "{name}: {error}");
    }
    assert!(out.ends_with("within the tolerance 1e-12\n"), "{out}");
    let source = ok(&["generate", "robots/ur5.urdf", "--dynamics", "--forces", "tool0"]);
    assert!(source.contains("pub const FORCE_LINKS: [&'static str; 1] = [\"tool0\"];"));
    assert!(source.contains("pub fn forward_dynamics_with_forces("));
    assert_eq!(
        fails(&["generate", "robots/ur5.urdf", "--dynamics", "--forces", "tool0,base_link"]),
        "error: robots/ur5.urdf: `--forces`: link `base_link` is the root: a force on it moves nothing"
    );
    usage_error(&["generate", "robots/ur5.urdf", "--forces", "tool0"], "--dynamics");
}
