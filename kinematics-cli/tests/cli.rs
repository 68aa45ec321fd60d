//! The `kinematics` binary run as a user runs it, on every robot in `robots/` and on bad input:
//! what each subcommand prints, that `fk --json` agrees with the runtime library, that `generate`
//! prints byte for byte what the build API writes, and that every error names the file, the
//! element and the fault, exits non-zero and leaves no output file behind.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use kinematics::ReferenceFk;

/// The workspace root: the binary runs there, so `robots/...` paths work as in the README.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_kinematics")).args(args).current_dir(root()).output().unwrap()
}

/// Standard output of a run that must succeed quietly.
fn ok(args: &[&str]) -> String {
    let output = run(args);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "kinematics {args:?} failed: {stderr}");
    assert!(stderr.is_empty(), "kinematics {args:?} wrote to stderr: {stderr}");
    String::from_utf8(output.stdout).unwrap()
}

/// The error message of a run that must fail: one `error: ...` line on stderr, nothing on stdout.
fn fails(args: &[&str]) -> String {
    let output = run(args);
    assert!(!output.status.success(), "kinematics {args:?} should fail");
    assert_eq!(output.status.code(), Some(1), "kinematics {args:?}");
    assert!(output.stdout.is_empty(), "kinematics {args:?} printed {}", String::from_utf8_lossy(&output.stdout));
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(stderr.starts_with("error: ") && stderr.ends_with('\n'), "{stderr}");
    stderr.trim_end().to_owned()
}

/// Every description in `robots/`, as `robots/<file>`.
fn robots() -> Vec<String> {
    let mut files: Vec<String> = std::fs::read_dir(root().join("robots"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|f| kinematics::model::SourceFormat::from_file_name(f).is_some())
        .map(|f| format!("robots/{f}"))
        .collect();
    files.sort();
    assert!(files.len() >= 10, "robots/ should hold the robot library: {files:?}");
    files
}

fn load(file: &str) -> kinematics::KinematicTree {
    kinematics::load(root().join(file)).unwrap()
}

/// A fresh scratch directory for one test.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("kinematics-cli-{test}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
}

fn leaves(tree: &kinematics::KinematicTree) -> Vec<&str> {
    tree.links()
        .iter()
        .filter(|l| l.child_joints.is_empty() && l.parent_joint.is_some())
        .map(|l| l.name.as_str())
        .collect()
}

#[test]
fn inspect_prints_the_tree_of_every_robot() {
    for file in robots() {
        let tree = load(&file);
        let out = ok(&["inspect", &file]);
        assert!(out.starts_with(&format!("robot `{}`: {} links", tree.name(), tree.links().len())), "{file}:\n{out}");
        assert!(out.contains(&format!("{} degrees of freedom", tree.dof())), "{file}");
        assert!(out.contains(&format!("root link: {}\n", tree.link(tree.root()).name)), "{file}");
        for joint in tree.joints() {
            let line = out.lines().find(|l| l.trim_start().starts_with(&format!("{} ", joint.name)));
            let line = line.unwrap_or_else(|| panic!("{file}: no line for joint {}", joint.name));
            assert!(line.contains(joint.kind.name()), "{file}: {line}");
            assert!(line.contains(&format!("{} -> {}", tree.link(joint.parent).name, tree.link(joint.child).name)));
        }
        let dofs: Vec<String> = tree.dof_names().iter().enumerate().map(|(i, n)| format!("q[{i}] {n}")).collect();
        assert!(out.contains(&format!("DoF order: {}\n", dofs.join(", "))), "{file}");
        let chains = out.split("chains from the root to each leaf:\n").nth(1).unwrap();
        for leaf in leaves(&tree) {
            assert!(
                chains.lines().any(|l| l.starts_with(&format!("  {leaf}: ")) && l.ends_with(leaf)),
                "{file}: {leaf}"
            );
        }
    }
    // Mimic joints say whom they follow.
    let humanoid = ok(&["inspect", "robots/humanoid.urdf"]);
    assert!(humanoid.lines().any(|l| l.contains(" mimics ") && l.contains("* q[")), "{humanoid}");
}

/// A configuration with distinct values, some negative.
fn configuration(dof: usize) -> Vec<f64> {
    (0..dof).map(|i| 0.37 * (i as f64 + 1.0) - 1.1).collect()
}

fn joined(q: &[f64]) -> String {
    q.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(",")
}

#[test]
fn fk_json_agrees_with_the_runtime_library() {
    for file in robots() {
        let fk = ReferenceFk::new(load(&file));
        let q = configuration(fk.tree().dof());
        let out = ok(&["fk", &file, "--q", &joined(&q), "--json"]);
        let json: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{file}: {e}\n{out}"));
        assert_eq!(json["robot"], fk.tree().name());
        let links = json["links"].as_array().unwrap();
        assert_eq!(links.len(), fk.tree().links().len(), "{file}");
        let poses = fk.link_poses(&q).unwrap();
        for (link, (pose, expected)) in links.iter().zip(poses.iter().zip(fk.tree().links())) {
            assert_eq!(link["name"], expected.name.as_str(), "{file}");
            let t: Vec<f64> = serde_json::from_value(link["translation"].clone()).unwrap();
            let r: Vec<Vec<f64>> = serde_json::from_value(link["rotation"].clone()).unwrap();
            let m = pose.rotation.to_rotation_matrix();
            for i in 0..3 {
                assert!((t[i] - pose.translation.vector[i]).abs() < 1e-14, "{file} {}: {t:?}", expected.name);
                for j in 0..3 {
                    assert!((r[i][j] - m[(i, j)]).abs() < 1e-14, "{file} {}: {r:?}", expected.name);
                }
            }
        }
    }
}

#[test]
fn fk_reads_degrees_and_prints_one_link() {
    let radians = ok(&["fk", "robots/ur5.urdf", "--q", "0,-1.5707963267948966,1.5707963267948966,0,0,0", "--json"]);
    let degrees = ok(&["fk", "robots/ur5.urdf", "--q", "0,-90,90,0,0,0", "--degrees", "--json"]);
    let (radians, degrees): (serde_json::Value, serde_json::Value) =
        (serde_json::from_str(&radians).unwrap(), serde_json::from_str(&degrees).unwrap());
    assert_eq!(radians["links"], degrees["links"]);
    let one = ok(&["fk", "robots/ur5.urdf", "--link", "tool0", "--json"]);
    let one: serde_json::Value = serde_json::from_str(&one).unwrap();
    assert_eq!(one["links"].as_array().map(Vec::len), Some(1));
    assert_eq!(one["links"][0]["name"], "tool0");
    let table = ok(&["fk", "robots/planar_3r.toml", "--q", "0.5,-0.25,0.1"]);
    assert!(table.starts_with("robot `planar_3r` at q = [0.5, -0.25, 0.1]\nlink "), "{table}");
    assert_eq!(table.lines().count(), 2 + load("robots/planar_3r.toml").links().len(), "{table}");
}

#[test]
fn expr_prints_the_pose_and_its_cost_for_every_robot() {
    for file in robots() {
        let out = ok(&["expr", &file]);
        assert!(out.starts_with(&format!("robot `{}`: pose of `", load(&file).name())), "{file}");
        for entry in ["r11 = ", "r33 = ", "  x = ", "  z = "] {
            assert!(out.contains(entry), "{file}: no `{entry}`");
        }
        for row in ["generated", "plain product", "position of"] {
            assert!(out.lines().any(|l| l.contains(row) && l.contains(" / ")), "{file}: no `{row}` row in\n{out}");
        }
    }
    // The counts the command prints are the library's.
    let ur5 = ok(&["expr", "robots/ur5.urdf", "--tip", "tool0"]);
    let tree = load("robots/ur5.urdf");
    let generated =
        kinematics_compiler::compile(&tree, &kinematics_compiler::Request::tip("tool0")).unwrap().op_count();
    let plain = kinematics_compiler::plain_product_count(&tree, "base_link", "tool0").unwrap();
    let counts = |c: kinematics_compiler::OpCount| [c.sin_cos.to_string(), c.mul.to_string(), c.add.to_string()];
    let numbers = |row: Vec<&str>| row.into_iter().filter(|w| *w != "/").map(str::to_owned).collect::<Vec<_>>();
    assert!(ur5.contains("angles: c23/s23 = cos/sin(q2 + q3), c234/s234 = cos/sin(q2 + q3 + q4)"), "{ur5}");
    let row = |what: &str| ur5.lines().find(|l| l.contains(what)).unwrap().split_whitespace().collect::<Vec<_>>();
    assert_eq!(numbers(row("pose of tool0, generated")[4..].to_vec()), counts(generated));
    assert_eq!(numbers(row("pose of tool0, plain product")[5..].to_vec()), counts(plain));
    let planar = ok(&["expr", "robots/planar_3r.toml", "--tip", "link3", "--latex"]);
    assert!(
        planar.contains("\\begin{aligned}\n") && planar.contains("  x &= c_{1} + c_{12} + 0.5 \\, c_{123} \\\\\n"),
        "{planar}"
    );
    assert!(planar.contains("  z &= 0\n\\end{aligned}\n"), "{planar}");
    let relative = ok(&["expr", "robots/ur5.urdf", "--base", "base", "--tip", "tool0"]);
    assert!(relative.starts_with("robot `ur5`: pose of `tool0` in `base`\n"), "{relative}");
}

#[test]
fn generate_prints_what_the_build_api_writes() {
    for file in robots() {
        let out = ok(&["generate", &file]);
        let expected = kinematics_build::Robot::file(&file).manifest_dir(root()).generate().unwrap();
        assert!(out == expected, "{file}: `kinematics generate` differs from the build API");
        assert!(out.contains("pub struct "), "{file}");
    }
    let args =
        ["generate", "robots/ur5.urdf", "--base", "base", "--tip", "tool0", "--name", "Flange", "--positions", "--f32"];
    let out = ok(&args);
    let expected = kinematics_build::Robot::file("robots/ur5.urdf")
        .manifest_dir(root())
        .base("base")
        .tip("tool0")
        .struct_name("Flange")
        .positions()
        .f32()
        .generate()
        .unwrap();
    assert_eq!(out, expected);
    assert!(out.contains("pub struct Flange;") && out.contains("pub fn tip_position_f32(q: &[f32; 6]) -> [f32; 3]"));
    let tips = ok(&["generate", "robots/panda.urdf", "--tip", "panda_leftfinger", "--tip", "panda_rightfinger"]);
    assert!(tips.contains("pub fn tip_poses(q: &[f64; 8]) -> [::kinematics::Pose<f64>; 2]"), "{tips}");
}

#[test]
fn generate_writes_a_file_atomically() {
    let dir = scratch("generate");
    let path = dir.join("fk.rs");
    let target = path.to_str().unwrap();
    assert_eq!(ok(&["generate", "robots/ur5.urdf", "--tip", "tool0", "-o", target]), "");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), ok(&["generate", "robots/ur5.urdf", "--tip", "tool0"]));
    assert_eq!(entries(&dir), ["fk.rs"]);
    // A failing run leaves the old file as it was and nothing beside it.
    std::fs::write(&path, "old").unwrap();
    let message = fails(&["generate", "robots/ur5.urdf", "--tip", "tool9", "-o", target]);
    assert_eq!(message, "error: robots/ur5.urdf: tip link `tool9` does not exist; did you mean `tool0`?");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
    assert_eq!(entries(&dir), ["fk.rs"]);
    // And creates none when there was none.
    std::fs::remove_file(&path).unwrap();
    fails(&["generate", "robots/none.urdf", "-o", target]);
    fails(&["generate", "robots/ur5.urdf", "--name", "not a name", "-o", target]);
    assert!(entries(&dir).is_empty());
    let message = fails(&["generate", "robots/ur5.urdf", "-o", dir.join("missing/fk.rs").to_str().unwrap()]);
    assert!(message.starts_with("error: robots/ur5.urdf: cannot write `"), "{message}");
    assert!(entries(&dir).is_empty());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn check_passes_on_every_robot() {
    for file in robots() {
        let out = ok(&["check", &file, "--samples", "200"]);
        let tree = load(&file);
        assert!(out.contains("200 configurations"), "{file}");
        let table: Vec<&str> = out
            .lines()
            .skip_while(|l| !l.starts_with("link "))
            .skip(1)
            .take_while(|l| !l.starts_with("largest: "))
            .collect();
        assert_eq!(table.len(), tree.links().len() - 1, "{file}:\n{out}");
        for line in table {
            let error: f64 = line.split_whitespace().last().unwrap().parse().unwrap();
            assert!(error <= 1e-12, "{file}: {line}");
        }
        let last = out.lines().last().unwrap();
        assert!(last.starts_with("largest: ") && last.ends_with("within the tolerance 1e-12"), "{file}: {last}");
    }
}

#[test]
fn graph_draws_every_link_and_joint() {
    for file in robots() {
        let tree = load(&file);
        let out = ok(&["graph", &file]);
        assert!(out.starts_with(&format!("digraph \"{}\" {{\n", tree.name())) && out.ends_with("}\n"), "{file}");
        for link in tree.links() {
            assert!(out.contains(&format!("  \"{}\";\n", link.name)), "{file}: {}", link.name);
        }
        for joint in tree.joints() {
            let edge = format!(
                "  \"{}\" -> \"{}\" [label=\"{}\\n{}",
                tree.link(joint.parent).name,
                tree.link(joint.child).name,
                joint.name,
                joint.kind.name()
            );
            assert!(out.contains(&edge), "{file}: no `{edge}`");
        }
        assert_eq!(out.matches(" -> ").count(), tree.joints().len(), "{file}");
    }
}

#[test]
fn demo_walks_through_the_pipeline() {
    let out = ok(&["demo", "--samples", "300", "--evaluations", "300"]);
    assert!(out.starts_with("kinematics demo: robots/ur5.urdf, the pose of `tool0` (the deepest link) in `base_link`"));
    for section in ["\n1. ", "\n2. ", "\n3. ", "\n4. ", "\n5. "] {
        assert!(out.contains(section), "no section `{section}` in\n{out}");
    }
    assert!(out.contains("pose of tool0, plain product"), "{out}");
    assert!(out.contains("generated Rust in this binary (Ur5):     largest error"), "{out}");
    assert!(out.contains("generated code, Ur5::tip_pose:") && out.contains("x faster"), "{out}");
    let other = ok(&["demo", "robots/planar_3r.toml", "--samples", "100", "--evaluations", "100"]);
    assert!(other.contains("runtime reference, ReferenceFk::link_pose:"), "{other}");
    assert!(other.contains("generated code: not timed."), "{other}");
    assert!(!other.contains("generated Rust in this binary"), "{other}");
}

#[test]
fn a_missing_file_is_named_by_every_subcommand() {
    for command in ["inspect", "fk", "expr", "generate", "check", "graph", "demo"] {
        let message = fails(&[command, "robots/none.urdf"]);
        assert!(message.starts_with("error: robots/none.urdf: cannot read the file: "), "{command}: {message}");
    }
    let dir = scratch("extension");
    let xacro = dir.join("ur5.xacro");
    std::fs::copy(root().join("robots/ur5.urdf"), &xacro).unwrap();
    let xacro = xacro.to_str().unwrap();
    for command in ["inspect", "generate"] {
        assert_eq!(
            fails(&[command, xacro]),
            format!("error: {xacro}: unknown description format (expected .urdf, .xml, .toml or .json)")
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn malformed_descriptions_are_named_with_the_fault() {
    let dir = scratch("malformed");
    let write = |name: &str, text: &str| {
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path.to_str().unwrap().to_owned()
    };
    let xml = write("broken.urdf", "<robot name=\"broken\">\n  <link name=\"a\">\n</robot>\n");
    let cycle = write(
        "cycle.urdf",
        r#"<robot name="loop"><link name="root"/><link name="a"/><link name="b"/>
          <joint name="j0" type="fixed"><parent link="root"/><child link="a"/></joint>
          <joint name="j1" type="fixed"><parent link="a"/><child link="b"/></joint>
          <joint name="j2" type="fixed"><parent link="b"/><child link="a"/></joint></robot>"#,
    );
    let dh = write("bad.toml", "convention = \"standard\"\n[[joints]]\nname = \"j1\"\na = \"x\"\n");
    for command in ["inspect", "fk", "expr", "generate", "check", "graph"] {
        let message = fails(&[command, &xml]);
        assert!(message.starts_with(&format!("error: {xml}: ")), "{command}: {message}");
        let message = fails(&[command, &cycle]);
        assert!(message.starts_with(&format!("error: {cycle}: ")), "{command}: {message}");
        assert!(message.contains("link `a` has more than one parent joint: `j0`, `j2`"), "{command}: {message}");
        let message = fails(&[command, &dh]);
        assert!(message.starts_with(&format!("error: {dh}: line ")), "{command}: {message}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn unknown_links_are_named_with_a_suggestion() {
    let hint = "error: robots/ur5.urdf: tip link `tool9` does not exist; did you mean `tool0`?";
    assert_eq!(fails(&["expr", "robots/ur5.urdf", "--tip", "tool9"]), hint);
    assert_eq!(fails(&["generate", "robots/ur5.urdf", "--tip", "tool9"]), hint);
    assert_eq!(
        fails(&["expr", "robots/ur5.urdf", "--base", "bse"]),
        "error: robots/ur5.urdf: base link `bse` does not exist; did you mean `base`?"
    );
    assert_eq!(
        fails(&["fk", "robots/ur5.urdf", "--link", "gripper"]),
        "error: robots/ur5.urdf: requested link `gripper` does not exist"
    );
}

#[test]
fn a_wrong_number_of_joint_values_is_refused() {
    assert_eq!(
        fails(&["fk", "robots/ur5.urdf", "--q", "1,2,3"]),
        "error: robots/ur5.urdf: robot `ur5` has 6 degrees of freedom (shoulder_pan_joint, shoulder_lift_joint, \
         elbow_joint, wrist_1_joint, wrist_2_joint, wrist_3_joint), but q has 3 values"
    );
    // Not a number: clap's usage error (status 2).
    let output = run(&["fk", "robots/ur5.urdf", "--q", "1,x"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&output.stderr).contains("invalid value 'x'"));
}
