//! The `kinematics` binary run as a user runs it, on every robot in `robots/` and on bad input:
//! what each subcommand prints, that `fk --json` agrees with the runtime library, that `generate`
//! prints byte for byte what the build API writes, and that every error names the file, the
//! element and the fault, exits non-zero and leaves no output file behind.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::path::Path;

use kinematics::ReferenceFk;

mod common;
use common::{fails, ok, root, run, scratch};

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

fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    names.sort();
    names
}

fn leaves(tree: &kinematics::KinematicTree) -> Vec<&str> {
    tree.leaves().map(|l| tree.link(l).name.as_str()).collect()
}

#[test]
fn inspect_prints_the_tree_of_every_robot() {
    for file in robots() {
        let tree = load(&file);
        let out = ok(&["inspect", &file]);
        assert!(out.starts_with(&format!("robot `{}`: {} links", tree.name(), tree.links().len())), "{file}:\n{out}");
        // A floating base's seven entries of `q` are six degrees of freedom.
        assert!(out.contains(&format!("{} degrees of freedom", tree.velocity_dof())), "{file}");
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

/// `expr --all`: one row per link with the operations it adds to the links above it; the rows add
/// up to the total, which is the all-links code's count.
#[test]
fn expr_all_prints_what_each_link_adds() {
    for file in ["robots/humanoid.urdf", "robots/dual_arm_torso.urdf", "robots/ur5.urdf", "robots/planar_3r.toml"] {
        let out = ok(&["expr", file, "--all"]);
        let tree = load(file);
        let all = kinematics_compiler::compile(&tree, &kinematics_compiler::Request::all_links()).unwrap();
        let numbers = |line: &str| -> [usize; 3] {
            let fields: Vec<usize> = line.split_whitespace().filter_map(|w| w.parse().ok()).collect();
            let n = fields.len();
            assert!(n >= 3, "{file}: `{line}`");
            [fields[n - 3], fields[n - 2], fields[n - 1]]
        };
        let rows: Vec<&str> = out.lines().filter(|l| l.contains(" / ") && !l.contains("sin_cos")).collect();
        let (total, links) = rows.split_last().unwrap();
        assert!(total.trim_start().starts_with("total"), "{file}: {total}");
        assert_eq!(links.len(), tree.links().len() - 1, "{file}: one row per link but the root\n{out}");
        let whole = all.op_count();
        assert_eq!(numbers(total), [whole.sin_cos, whole.mul, whole.add], "{file}");
        let sum = links.iter().map(|l| numbers(l)).fold([0; 3], |acc, n| [acc[0] + n[0], acc[1] + n[1], acc[2] + n[2]]);
        assert_eq!(sum, numbers(total), "{file}: the rows do not add up to the total\n{out}");
        // Each row names its link and the joint it hangs from.
        for (row, frame) in links.iter().zip(all.frames()) {
            assert!(row.trim_start().starts_with(&format!("{} ", frame.link)), "{file}: `{row}`");
        }
    }
    let humanoid = ok(&["expr", "robots/humanoid.urdf", "--all"]);
    assert!(humanoid.lines().any(|l| l.contains("LFinger12_link") && l.contains("LFinger12 (mimic)")), "{humanoid}");
    assert!(humanoid.lines().any(|l| l.contains("l_sole") && l.contains("(fixed)")), "{humanoid}");
    // One link's pose and all links are different questions.
    assert!(!run(&["expr", "robots/ur5.urdf", "--all", "--tip", "tool0"]).status.success());
}

/// `expr --jacobian`: the 6 x DoF entries, the rows and columns named, and the velocity
/// functions' op counts, for every robot and both frames.
#[test]
fn expr_jacobian_prints_every_entry_and_the_velocity_costs() {
    for file in robots() {
        let tree = load(&file);
        for frame in ["local-world-aligned", "local"] {
            let out = ok(&["expr", &file, "--jacobian", "--frame", frame]);
            let entries = out.lines().filter(|l| l.starts_with("J[")).count();
            assert_eq!(entries, 6 * tree.velocity_dof(), "{file} {frame}:\n{out}");
            for what in
                ["Jacobian of", "pose and Jacobian of", "position Jacobian of", "twist of", "J * qd with J formed"]
            {
                assert!(out.contains(what), "{file}: no `{what}` row\n{out}");
            }
        }
    }
    let ur5 = ok(&["expr", "robots/ur5.urdf", "--tip", "tool0", "--jacobian"]);
    assert!(ur5.contains("(LOCAL_WORLD_ALIGNED)") && ur5.contains("J[wz][q1] = 1"), "{ur5}");
    // The last wrist joint turns the tool about its own origin's axis: no linear velocity.
    assert!(ur5.contains("J[vx][q6] = 0"), "{ur5}");
    let local = ok(&["expr", "robots/ur5.urdf", "--tip", "tool0", "--jacobian", "--frame", "local", "--latex"]);
    assert!(local.contains("(LOCAL)") && local.contains("\\begin{aligned}"), "{local}");
    // `--frame` belongs to `--jacobian`, and a Jacobian is one link's.
    assert!(!run(&["expr", "robots/ur5.urdf", "--frame", "local"]).status.success());
    assert!(!run(&["expr", "robots/ur5.urdf", "--all", "--jacobian"]).status.success());
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
    let velocities = ok(&["generate", "robots/ur5.urdf", "--tip", "tool0", "--jacobians"]);
    let expected = kinematics_build::Robot::file("robots/ur5.urdf")
        .manifest_dir(root())
        .tip("tool0")
        .jacobians()
        .generate()
        .unwrap();
    assert_eq!(velocities, expected);
    assert!(velocities.contains("pub fn tip_jacobian(q: &[f64; 6]) -> [[f64; 6]; 6]"), "{velocities}");
    assert!(velocities.contains("pub fn tip_twist(q: &[f64; 6], qd: &[f64; 6]) -> [f64; 6]"), "{velocities}");
    let no_tip = fails(&["generate", "robots/ur5.urdf", "--jacobians"]);
    assert!(no_tip.contains("`jacobians` needs a tip"), "{no_tip}");
    // Inverse kinematics: the build API's `.ik()`, `.ik_free(..)`, `.ik_numeric()`, byte for byte.
    let build = |robot: kinematics_build::Robot| robot.manifest_dir(root()).generate().unwrap();
    let ik = ok(&["generate", "robots/ur5.urdf", "--tip", "tool0", "--ik"]);
    assert_eq!(ik, build(kinematics_build::Robot::file("robots/ur5.urdf").tip("tool0").ik()));
    assert!(ik.contains("pub fn tip_ik(") && ik.contains("pub fn tip_ik_numeric("), "{ik}");
    let free = ok(&["generate", "robots/iiwa14.urdf", "--tip", "iiwa_link_ee", "--ik", "--free", "iiwa_joint_3"]);
    assert_eq!(
        free,
        build(kinematics_build::Robot::file("robots/iiwa14.urdf").tip("iiwa_link_ee").ik_free("iiwa_joint_3"))
    );
    let numeric = ok(&["generate", "robots/panda.toml", "--tip", "flange", "--ik", "numeric"]);
    assert_eq!(numeric, build(kinematics_build::Robot::file("robots/panda.toml").tip("flange").ik_numeric()));
    assert!(!numeric.contains("pub fn tip_ik(") && numeric.contains("pub fn tip_ik_numeric("), "{numeric}");
    let no_family = fails(&["generate", "robots/panda.toml", "--tip", "flange", "--ik"]);
    assert!(no_family.contains("no closed-form inverse kinematics"), "{no_family}");
    let tips = ok(&["generate", "robots/panda.urdf", "--tip", "panda_leftfinger", "--tip", "panda_rightfinger"]);
    assert!(tips.contains("pub fn tip_poses(q: &[f64; 8]) -> [::kinematics::__private::Pose<f64>; 2]"), "{tips}");
}

#[test]
fn generate_emits_collision_checking_as_the_build_api_does() {
    let out = ok(&["generate", "robots/panda_spherized.urdf", "--collision", "--srdf", "robots/panda.srdf"]);
    let expected = kinematics_build::Robot::file("robots/panda_spherized.urdf")
        .manifest_dir(root())
        .srdf("robots/panda.srdf")
        .generate()
        .unwrap();
    assert_eq!(out, expected);
    assert!(out.contains("pub fn self_collides(q: &[f64; 7]) -> bool"), "{out}");
    let covered = ok(&["generate", "robots/ur5_primitives.urdf", "--collision", "--sphere-cover", "0.05"]);
    assert!(covered.contains("pub const SPHERE_RADII"), "{covered}");
    // ur5.urdf names its meshes by `package://ur_description`, which is not shipped: an error
    // naming the link, the URI and every place looked.
    let message = fails(&["generate", "robots/ur5.urdf", "--collision"]);
    assert!(
        message.starts_with(
            "error: robots/ur5.urdf: link `base_link`: mesh `package://ur_description/meshes/ur5/collision/base.stl`: \
             cannot find"
        ) && message.contains("looked, in order, at:")
            && message.contains("--package ur_description=PATH"),
        "{message}"
    );
    // Left out, the meshes are not looked for; the file's other geometry is covered.
    let skipped = ok(&["generate", "robots/ur5.urdf", "--collision", "--skip-meshes"]);
    assert!(skipped.contains("pub const SPHERE_RADII"), "{skipped}");
    // Each fault names the flag that caused it.
    let message = fails(&["generate", "robots/ur5_spherized.urdf", "--collision", "--sphere-cover", "0"]);
    assert_eq!(
        message,
        "error: robots/ur5_spherized.urdf: `--cover`: `sphere_cover` is 0 (must be a finite positive length in \
         metres)"
    );
    let message = fails(&["generate", "robots/ur5_spherized.urdf", "--collision", "--srdf", "robots/panda.srdf"]);
    assert!(
        message.starts_with("error: robots/ur5_spherized.urdf: `--srdf`: robots/panda.srdf: line 51:"),
        "{message}"
    );
    // Meshes left out, the UR5 keeps the small box on its `ee_link`: one sphere.
    let skipped = ok(&["generate", "robots/ur5.urdf", "--collision", "--skip-meshes"]);
    assert!(skipped.contains(r#"pub const SPHERE_LINKS: [&'static str; 1] = ["ee_link"];"#), "{skipped}");
}

#[test]
fn generate_lists_the_links_asked_for() {
    let out = ok(&["generate", "robots/humanoid.urdf", "--links", "r_sole,l_sole", "--positions"]);
    let expected = kinematics_build::Robot::file("robots/humanoid.urdf")
        .manifest_dir(root())
        .links(["r_sole", "l_sole"])
        .positions()
        .generate()
        .unwrap();
    assert_eq!(out, expected);
    assert!(out.contains(r#"pub const LINK_NAMES: [&'static str; 2] = ["r_sole", "l_sole"];"#));
    let message = fails(&["generate", "robots/humanoid.urdf", "--links", "r_sole,l_sol"]);
    assert_eq!(
        message,
        "error: robots/humanoid.urdf: `--links`: listed link `l_sol` does not exist; did you mean `l_sole`?"
    );
    let message = fails(&["generate", "robots/humanoid.urdf", "--links", "r_sole,r_sole"]);
    assert_eq!(message, "error: robots/humanoid.urdf: `--links`: link `r_sole` is listed twice in `links`");
    // Every fault at once, each naming its flag.
    let message =
        fails(&["generate", "robots/humanoid.urdf", "--links", "r_sole,r_sole", "--tip", "l_sol", "--jacobians"]);
    assert_eq!(
        message,
        "error: robots/humanoid.urdf: `--tip`: tip link `l_sol` does not exist; did you mean `l_sole`?; `--links`: link \
         `r_sole` is listed twice in `links`"
    );
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
    assert_eq!(message, "error: robots/ur5.urdf: `--tip`: tip link `tool9` does not exist; did you mean `tool0`?");
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
    for section in ["\n1. ", "\n2. ", "\n3. ", "\n4. ", "\n5. ", "\n6. ", "\n7. ", "\n8. ", "\n9. "] {
        assert!(out.contains(section), "no section `{section}` in\n{out}");
    }
    // Inverse kinematics: the pose's eight solutions, each reproducing it by the generated pose and
    // by the runtime reference's, then the closed form timed against the numeric solver.
    assert!(out.contains(": 8 solutions, 8 exact (axes 2, 3, 4 parallel, axes 5 and 6 meet)"), "{out}");
    let rows: Vec<&str> = out.lines().filter(|l| l.starts_with("  [") && l.contains(" m  ")).collect();
    assert_eq!(rows.len(), 8, "{out}");
    for row in rows {
        let errors: Vec<f64> = row
            .split(']')
            .nth(1)
            .unwrap()
            .split_whitespace()
            .filter(|w| *w != "m")
            .map(|w| w.parse().unwrap())
            .collect();
        assert!(errors.len() == 3 && errors.iter().all(|e| *e <= 1e-12), "{row}");
    }
    assert!(out.contains("closed form, Ur5::tip_ik (every solution):"), "{out}");
    assert!(
        out.contains("numeric, Ur5::tip_ik_numeric (one solution):") && out.contains("converged; the closed form"),
        "{out}"
    );
    // The generated Jacobian's agreement is measured, and within the agreement tolerance.
    let jacobian = out.lines().find(|l| l.contains("Ur5::tip_jacobian against ReferenceFk::jacobian")).unwrap();
    let error: f64 = jacobian.rsplit(' ').next().unwrap().parse().unwrap();
    assert!(error <= 1e-12, "{jacobian}");
    assert!(out.contains("generated code, Ur5::tip_jacobian:") && out.contains("J * qd with J formed"), "{out}");
    assert!(out.contains("pose of tool0, plain product"), "{out}");
    assert!(out.contains("generated Rust in this binary (Ur5):     largest error"), "{out}");
    assert!(out.contains("generated code, Ur5::tip_pose:") && out.contains("x faster"), "{out}");
    // Dynamics (issue 61): what each function costs, the compiled expressions and the generated
    // code against the reference, and each function timed against the reference's.
    let dynamics = &out[out.find("\n8. ").unwrap()..out.find("\n9. ").unwrap()];
    assert!(dynamics.starts_with("\n8. Dynamics from the links' inertias"), "{dynamics}");
    for agreement in ["  compiled expressions:  ", "  generated Rust in this binary (Ur5):  "] {
        let line = dynamics.lines().find(|l| l.starts_with(agreement)).unwrap_or_else(|| panic!("no `{agreement}`"));
        let error: f64 = line.split("largest error ").nth(1).unwrap().split(' ').next().unwrap().parse().unwrap();
        assert!(error <= 1e-12, "{line}");
    }
    for function in ["gravity_torques", "inverse_dynamics", "nonlinear_effects", "mass_matrix", "forward_dynamics"] {
        let cost = dynamics.lines().find(|l| l.starts_with(&format!("  {function} "))).unwrap();
        assert_eq!(cost.split('/').count(), 4, "{cost}");
        for timing in
            [format!("runtime reference, ReferenceDynamics::{function}:"), format!("generated code, Ur5::{function}:")]
        {
            let line = dynamics
                .lines()
                .find(|l| l.trim_start().starts_with(&timing))
                .unwrap_or_else(|| panic!("no `{timing}`"));
            let ns: f64 = line.trim_start()[timing.len()..].split_whitespace().next().unwrap().parse().unwrap();
            assert!(ns > 0.0 && line.contains(" ns per call"), "{line}");
        }
    }
    // Collision (issue 57): the built-in spherized Panda whatever the robot, its generated
    // `collides` judged by the reference on every sample, the hand loop giving its verdicts, and
    // the four timings.
    let collision = &out[out.find("\n9. ").unwrap()..];
    assert!(
        collision.starts_with(
            "\n9. Collision, on the spherized Panda (robots/panda_spherized.urdf, robots/panda.srdf) in \
             scenes/tabletop.toml\n\n  59 spheres on 11 links (at most 10 spheres per link, stopping at an overshoot \
             of 0.01 m), 21 self-collision pairs (less \
             the pairs robots/panda.srdf disables); scene scenes/tabletop.toml (12 obstacles)\n"
        ),
        "{collision}"
    );
    let judged = collision.lines().find(|l| l.contains(" as the reference says, ")).unwrap();
    let words: Vec<&str> = judged.split_whitespace().collect();
    let count = |word: &str| -> usize {
        let before = words.windows(2).find(|w| w[1] == word).unwrap_or_else(|| panic!("no `{word}` in {judged}"));
        before[0].replace(',', "").parse().unwrap()
    };
    let (colliding, free, banded, disagreeing) =
        (count("colliding"), count("free"), count("within"), count("disagreeing"));
    assert!(colliding > 0 && free > 0 && colliding + free + banded == 300 && disagreeing == 0, "{judged}");
    assert!(judged.ends_with(", 0 disagreeing"), "{judged}");
    assert!(collision.contains("generated Panda::collides against the runtime reference (parry3d-f64 distances), 300"));
    assert!(
        collision.contains("the hand loop below against Panda::collides on 1,024 configurations: 0 differing\n"),
        "{collision}"
    );
    for timing in [
        "  runtime reference, every distance (parry3d-f64):  ",
        "  the naive way: Panda::link_poses and a hand loop:  ",
        "  generated code, Panda::collides:  ",
        "  generated code, Panda::collides_batch, 1,024 a call:  ",
        "  generated code, Panda::collides_batch_f32, 1,024 a call:  ",
    ] {
        let line = collision.lines().find(|l| l.starts_with(timing)).unwrap_or_else(|| panic!("no `{timing}`"));
        let ns: f64 = line[timing.len()..].split_whitespace().next().unwrap().parse().unwrap();
        assert!(ns > 0.0 && line.contains(" ns"), "{line}");
        if timing.contains("generated") {
            assert!(
                line.contains("x faster than the reference, ") && line.ends_with("x than the hand loop)"),
                "{line}"
            );
        }
    }
    let other = ok(&["demo", "robots/planar_3r.toml", "--samples", "100", "--evaluations", "100"]);
    // A robot given on the command line: the Panda's section, then its own geometry (none here).
    assert!(other.contains("\n9. Collision, on the spherized Panda"), "{other}");
    // Its dynamics: no mass to compile.
    assert!(
        other.contains(
            "\n8. Dynamics from the links' inertias (`kinematics expr --dynamics`, `kinematics check --dynamics`)\n\n  \
             not compiled: `--dynamics`: `dynamics` of a robot with no mass"
        ),
        "{other}"
    );
    assert!(
        other.ends_with(
            "robots/planar_3r.toml, its own <collision> geometry against the reference in scenes/tabletop.toml \
             (not timed):\n  no <collision> geometry the cover reads (meshes are not read)\n"
        ),
        "{other}"
    );
    assert!(other.contains("runtime reference, ReferenceFk::link_pose:"), "{other}");
    assert!(other.contains("generated code: not timed."), "{other}");
    assert!(!other.contains("generated Rust in this binary"), "{other}");
    assert!(other.contains("\n6. ") && !other.contains("Ur5::tip_jacobian"), "{other}");
    assert!(other.contains("\n7. Inverse kinematics") && !other.contains("Ur5::tip_ik"), "{other}");
}

#[test]
fn a_missing_file_is_named_by_every_subcommand() {
    for command in ["inspect", "fk", "expr", "generate", "check", "graph", "draw", "demo"] {
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
            format!("error: {xacro}: unknown description format (expected .urdf, .xml, .mjcf, .toml or .json)")
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
    // `generate` checks its options by the compiler's rules, each fault naming its flag.
    assert_eq!(
        fails(&["generate", "robots/ur5.urdf", "--tip", "tool9"]),
        "error: robots/ur5.urdf: `--tip`: tip link `tool9` does not exist; did you mean `tool0`?"
    );
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

/// Writes `text` as `name` in `dir` and returns the path as a string.
fn write_file(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_owned()
}

/// A run that must fail with exit status 1 and an error on stderr containing every fragment;
/// stdout may hold what was printed before the fault (`check`'s table).
fn fails_with(args: &[&str], fragments: &[&str]) -> String {
    let output = run(args);
    assert_eq!(output.status.code(), Some(1), "kinematics {args:?}: {}", String::from_utf8_lossy(&output.stderr));
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(stderr.starts_with("error: "), "{stderr}");
    for f in fragments {
        assert!(stderr.contains(f), "kinematics {args:?}: `{stderr}` lacks `{f}`");
    }
    stderr
}

#[test]
fn check_refuses_sample_counts_that_check_nothing() {
    // issue 13: `check --samples 0` passed.
    for command in ["check", "demo"] {
        let output = run(&[command, "robots/planar_3r.toml", "--samples", "0"]);
        assert_eq!(output.status.code(), Some(2), "{command}");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains("0 checks nothing"), "{command}: {stderr}");
        assert!(output.stdout.is_empty());
    }
    let one = ok(&["check", "robots/planar_3r.toml", "--samples", "1"]);
    assert!(one.contains("1 configurations"), "{one}");
    // A robot with no link besides its root: nothing to compare, so no pass.
    let dir = scratch("nothing");
    let lone = write_file(&dir, "lone.urdf", "<robot name=\"lone\"><link name=\"base\"/></robot>");
    fails_with(&["check", &lone], &[&format!("{lone}: nothing to check")]);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn descriptions_whose_poses_would_not_be_numbers_fail_check_naming_the_joint() {
    // issue 13: an axis `0 0 1e200` gave NaN poses and `check` reported 0.00 and passed; constants
    // that compose past f64::MAX did the same. The model now normalises that axis exactly and
    // refuses the overflows, and `check` shows the model's error.
    let dir = scratch("nan");
    let joint = |name: &str, kind: &str, parent: &str, child: &str, xyz: &str, extra: &str| {
        format!(
            "<joint name=\"{name}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"{child}\"/>\
             <origin xyz=\"{xyz}\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>{extra}</joint>"
        )
    };
    let links = "<link name=\"a\"/><link name=\"b\"/><link name=\"c\"/><link name=\"d\"/>";
    let far = write_file(
        &dir,
        "far.urdf",
        &format!(
            "<robot name=\"far\">{links}{}{}{}</robot>",
            joint("f1", "fixed", "a", "b", "1e308 0 0", ""),
            joint("f2", "fixed", "b", "c", "1e308 0 0", ""),
            joint("j", "revolute", "c", "d", "0 0 0", "")
        ),
    );
    let mimic = write_file(
        &dir,
        "mimic.urdf",
        &format!(
            "<robot name=\"mimic\">{links}{}{}{}</robot>",
            joint("j1", "revolute", "a", "b", "0 0 1", ""),
            joint("j2", "revolute", "b", "c", "0 0 1", "<mimic joint=\"j1\" multiplier=\"1e200\"/>"),
            joint("j3", "revolute", "c", "d", "0 0 1", "<mimic joint=\"j2\" multiplier=\"1e200\"/>")
        ),
    );
    for command in ["check", "fk", "expr", "generate", "inspect"] {
        fails_with(&[command, &far], &[&format!("{far}: joint `f2`: the robot's reach"), "not a finite number"]);
        fails_with(&[command, &mimic], &[&format!("{mimic}: joint `j3`: "), "mimic multiplier is not a finite number"]);
    }
    // The axis that used to overflow is a valid axis now, and the check passes.
    let huge_axis =
        std::fs::read_to_string(root().join("robots/ur5.urdf")).unwrap().replace("xyz=\"0 0 1\"", "xyz=\"0 0 1e200\"");
    assert!(huge_axis.contains("1e200"));
    let huge_axis = write_file(&dir, "huge_axis.urdf", &huge_axis);
    let out = ok(&["check", &huge_axis, "--samples", "200"]);
    assert!(out.contains("within the tolerance"), "{out}");
    // A joint value that is not a number: the runtime reference refuses it, naming the joint.
    for q in ["nan,0,0,0,0,0", "0,inf,0,0,0,0"] {
        let joint = if q.starts_with("nan") { "shoulder_pan_joint" } else { "shoulder_lift_joint" };
        fails_with(&["fk", "robots/ur5.urdf", "--q", q], &[&format!("joint `{joint}`"), "not a finite number"]);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn names_of_70000_bytes_pass_through_every_subcommand() {
    // issue 13: names of 65,536 bytes or more panicked `inspect`, `fk`, `expr` and `check` (a
    // `format!` width argument).
    let dir = scratch("long-names");
    let link = format!("link_{}", "l".repeat(70_000));
    let joint = format!("joint_{}", "j".repeat(70_000));
    let file = write_file(
        &dir,
        "long.urdf",
        &format!(
            "<robot name=\"long\"><link name=\"base\"/><link name=\"{link}\"/><link name=\"tip\"/>\
             <joint name=\"{joint}\" type=\"revolute\"><parent link=\"base\"/><child link=\"{link}\"/>\
             <origin xyz=\"0 0 0.5\"/><axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\
             <joint name=\"wrist\" type=\"continuous\"><parent link=\"{link}\"/><child link=\"tip\"/>\
             <origin xyz=\"0.3 0 0\"/><axis xyz=\"0 0 1\"/></joint></robot>"
        ),
    );
    let runs: [&[&str]; 9] = [
        &["inspect", &file],
        &["fk", &file],
        &["fk", &file, "--json"],
        &["fk", &file, "--link", &link],
        &["expr", &file],
        &["expr", &file, "--tip", &link, "--latex"],
        &["check", &file, "--samples", "50"],
        &["graph", &file],
        &["demo", &file, "--samples", "50", "--evaluations", "10"],
    ];
    for args in runs {
        let out = ok(args);
        let has_link = out.contains(&link);
        let has_joint = out.contains(&joint);
        match args[0] {
            "inspect" | "graph" => assert!(has_link && has_joint, "{}", args[0]),
            "fk" | "check" => assert!(has_link, "{:?}", &args[..1]),
            _ => assert!(has_link || has_joint || out.contains("q1"), "{}", args[0]),
        }
        // Padding stops at a cap: a line without the long names is not padded out to their width.
        let longest = out.lines().filter(|l| !l.contains("lllll") && !l.contains("jjjjj")).map(str::len).max().unwrap();
        assert!(longest < 1000, "{}: a line of {longest} bytes", args[0]);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn inspect_lists_the_sphere_pairs_held_apart_for_good() {
    let out = ok(&["inspect", "robots/panda_spherized.urdf", "--srdf", "robots/panda.srdf"]);
    // panda_link5's first two spheres lie on joint 6's axis, panda_link7's first on joint 7's.
    assert!(
        out.contains(
            "sphere pairs held apart for good (no joint moves them; the distances leave them out): 2: \
             panda_link5 #0-panda_link7 #0 (0.015176 m), panda_link5 #1-panda_link7 #0 (0.025163 m)\n"
        ),
        "{out}"
    );
    // A planar arm (two joints 0.3 m apart along x, about z) with spheres of 5 cm at `xa` on `a`
    // and at `xc` on `c` (each along its link's x): `a` and `c` are the one pair checked.
    let dir = scratch("held-apart");
    let planar = |xa: f64, xc: f64| {
        let link = |name: &str, x: f64| {
            format!(
                "<link name=\"{name}\"><collision><origin xyz=\"{x} 0 0\"/>\
                 <geometry><sphere radius=\"0.05\"/></geometry></collision></link>"
            )
        };
        let joint = |name: &str, parent: &str, child: &str| {
            format!(
                "<joint name=\"{name}\" type=\"revolute\"><parent link=\"{parent}\"/><child link=\"{child}\"/>\
                 <origin xyz=\"0.3 0 0\"/><axis xyz=\"0 0 1\"/>\
                 <limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>"
            )
        };
        let (a, b, c) = (link("a", xa), link("b", 0.1), link("c", xc));
        let (j1, j2) = (joint("j1", "a", "b"), joint("j2", "b", "c"));
        write_file(
            &dir,
            &format!("planar_{xa}_{xc}.urdf"),
            &format!("<robot name=\"planar\">{a}{b}{c}{j1}{j2}</robot>"),
        )
    };
    let held = "sphere pairs held apart for good (no joint moves them; the distances leave them out): ";
    // Off the axes, both joints move the pair.
    let out = ok(&["inspect", &planar(0.1, 0.1)]);
    assert!(out.contains("self-collision pairs: 1 (") && out.contains(&format!("{held}0\n")), "{out}");
    // `a`'s sphere on j1's axis, `c`'s on j2's: 0.3 m apart for good, less both radii.
    let out = ok(&["inspect", &planar(0.3, 0.0)]);
    assert!(out.contains(&format!("{held}1: a #0-c #0 (0.2 m)\n")), "{out}");
    // One of the two on its axis: the other joint moves them.
    let out = ok(&["inspect", &planar(0.3, 0.1)]);
    assert!(out.contains(&format!("{held}0\n")), "{out}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn inspect_lists_the_angles_the_exactness_policy_changed() {
    let dir = scratch("exact-angles");
    let urdf = write_file(
        &dir,
        "flip.urdf",
        "<robot name=\"flip\"><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>\
         <joint name=\"shoulder\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>\
         <origin xyz=\"0 0 0.1\" rpy=\"3.14159265359 0 0\"/><axis xyz=\"0 0 1\"/>\
         <limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>\
         <joint name=\"elbow\" type=\"revolute\"><parent link=\"b\"/><child link=\"c\"/>\
         <origin xyz=\"0 0 0.1\" rpy=\"0 -1.57079632679 1.5708\"/><axis xyz=\"0 0 1\"/>\
         <limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint></robot>",
    );
    let out = ok(&["inspect", &urdf]);
    assert!(out.contains("exact angles: 2 changed"), "{out}");
    // pi - 3.14159265359 = -2.07e-13: the change from the written value to the exact one.
    assert!(out.contains("  joint `shoulder`: 3.14159265359 -> pi (-2.07e-13 rad)\n"), "{out}");
    assert!(out.contains("  joint `elbow`: -1.57079632679 -> -pi/2 ("), "{out}");
    // 1.5708 is a number, not a quarter turn.
    assert!(!out.contains("1.5708 ->"), "{out}");
    let exact = ok(&["inspect", "robots/planar_3r.toml"]);
    assert!(exact.contains("exact angles: none changed\n"), "{exact}");
    // The shortest decimal of the f64 nearest to pi/2 changes by less than an f64 can show.
    let ur5 = ok(&["inspect", "robots/ur5.urdf"]);
    assert!(
        ur5.contains("  joint `shoulder_lift_joint`: 1.5707963267948966 -> pi/2 (the nearest f64 to it)\n"),
        "{ur5}"
    );
    let off = ok(&["--exact-angles", "off", "inspect", "robots/ur5.urdf"]);
    assert!(off.contains("exact angles: off (every angle as written)\n"), "{off}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn expr_of_a_1000_joint_chain_is_linear_in_size() {
    // issue 13: `expr` printed each entry as a tree (30 joints: 8 s and 241 MB; 35: out of
    // memory). Shared subexpressions are now temporaries, printed once.
    let dir = scratch("long-chain");
    let twists = ["\"pi/2\"", "0", "0", "\"pi/2\"", "\"-pi/2\"", "0"];
    let mut toml = String::from("convention = \"standard\"\n");
    for i in 0..1000 {
        toml += &format!(
            "[[joints]]\nname = \"j{}\"\na = {}\nd = 0.1\nalpha = {}\n",
            i + 1,
            0.3 + 0.001 * i as f64,
            twists[i % 6]
        );
    }
    let file = write_file(&dir, "chain.toml", &toml);
    for latex in [false, true] {
        let args: Vec<&str> = if latex { vec!["expr", &file, "--latex"] } else { vec!["expr", &file] };
        let out = ok(&args);
        assert!(out.len() < 4_000_000, "{} bytes", out.len());
        assert!(out.contains(if latex { "t_{1} &= " } else { " t1 = " }), "{}", &out[..2000.min(out.len())]);
        assert!(out.contains("  pose of link1000, generated"), "{}", &out[out.len().saturating_sub(2000)..]);
    }
    // The same chain of 30 joints: a few kilobytes, not hundreds of megabytes.
    let short: String = toml.split("[[joints]]").take(31).collect::<Vec<_>>().join("[[joints]]");
    let file = write_file(&dir, "chain30.toml", &short);
    let out = ok(&["expr", &file]);
    assert!(out.len() < 100_000, "{} bytes", out.len());
    std::fs::remove_dir_all(&dir).unwrap();
    // Small robots print without temporaries: the UR5 as the README quotes it.
    let out = ok(&["expr", "robots/ur5.urdf"]);
    assert!(!out.contains(" t1 = "), "{out}");
    assert!(out.contains("r13 = s5*c234*c1 - c5*s1\n"), "{out}");
    assert!(
        out.contains("  x = (0.425*c2 + 0.39225*c23 - 0.09465*s234)*c1 - 0.10915*s1 + 0.0823*(s5*c234*c1 - c5*s1)\n"),
        "{out}"
    );
}

/// `ik --from-q` round-trips on every robot a closed-form family covers: eight exact solutions,
/// the given configuration among them, every error tiny (by the runtime reference).
#[test]
fn ik_round_trips_on_every_covered_robot() {
    let q = "0.3,-1.2,1.0,0.4,-0.7,2.0";
    // The limits word the given configuration's row must carry: the PUMA's second joint turns from
    // -45 degrees, and -1.2 rad is -69.
    for (file, tip, family, limits) in [
        ("robots/ur5.urdf", "tool0", "axes 2, 3, 4 parallel, axes 5 and 6 meet", "within"),
        ("robots/ur10e.toml", "wrist_3_link", "axes 2, 3, 4 parallel, axes 5 and 6 meet", "within"),
        ("robots/irb120.urdf", "tool0", "spherical wrist, axes 2 and 3 parallel", "within"),
        ("robots/puma560.toml", "link6", "spherical wrist, axes 2 and 3 parallel", "beyond"),
    ] {
        let out = ok(&["ik", file, "--tip", tip, "--from-q", q]);
        assert!(out.contains(&format!("closed form: {family}")), "{out}");
        assert!(out.contains("8 solutions, 8 exact"), "{out}");
        let line = out.lines().find(|l| l.starts_with("round trip: --from-q is solution")).expect("a round-trip line");
        let difference: f64 = line.rsplit(": ").next().unwrap().trim_end_matches(" rad)").parse().unwrap();
        assert!(difference < 1e-9, "{file}: {line}");
        let number = line.split_whitespace().nth(5).unwrap();
        let row = out.lines().find(|l| l.trim_start().starts_with(&format!("{number}  ("))).expect("its row");
        assert!(row.contains(&format!("  {limits}  ")), "{file}: {row}");
        for row in out.lines().filter(|l| l.contains("  exact")) {
            let errors: Vec<f64> = row.split_whitespace().rev().take(2).map(|e| e.parse().unwrap()).collect();
            assert!(errors.iter().all(|e| *e < 1e-12), "{file}: {row}");
        }
    }
    // Solutions the joints cannot take, even moved by whole turns, say so: the IRB 120's first
    // joint turns within 165 degrees either way (solutions 1 to 4 have -168.5), its third from -110
    // to 70 (solutions 5 and 6 have -131).
    let out = ok(&["ik", "robots/irb120.urdf", "--from-q", "0.2,0.3,-0.4,0.5,0.6,0.7"]);
    let words: Vec<&str> = out
        .lines()
        .filter(|l| l.contains("  exact  "))
        .map(|l| if l.contains("  beyond  ") { "beyond" } else { "within" })
        .collect();
    assert_eq!(words, ["beyond", "beyond", "beyond", "beyond", "beyond", "beyond", "within", "within"], "{out}");
    // Degrees in, degrees out.
    let out = ok(&["ik", "robots/ur5.urdf", "--degrees", "--from-q", "10,-60,45,20,-30,90"]);
    assert!(out.contains("angles in degrees") && out.contains(" 90.00000)"), "{out}");
}

/// `ik --from-q` at the UR5's wrist singularity (`q5 = 0`), for a configuration whose pose the
/// representative with `q6 = 0` cannot reach (the elbow would be out of reach; found by a new
/// user's trial): exact singular solutions reach the pose, and the round trip says the solutions
/// are representatives rather than claiming a solution 2 rad away is the configuration given.
#[test]
fn ik_round_trips_at_a_wrist_singularity() {
    let q = "-5.018908040145822,-6.2591372179042715,-0.6672045709120269,-1.9140345437751227,0.0,4.4077715493666085";
    let out = ok(&["ik", "robots/ur5.urdf", "--tip", "tool0", "--from-q", q]);
    let singular: Vec<&str> = out.lines().filter(|l| l.contains("  exact, singular")).collect();
    assert!(!singular.is_empty(), "{out}");
    for row in singular {
        let errors: Vec<f64> = row.split_whitespace().rev().take(2).map(|e| e.parse().unwrap()).collect();
        assert!(errors.iter().all(|e| *e < 1e-12), "{row}");
    }
    assert!(out.contains("round trip: --from-q is at a singularity, where the solutions are representatives"), "{out}");
}

#[test]
fn ik_takes_a_pose_and_refuses_what_is_no_pose() {
    let out = ok(&["ik", "robots/ur5.urdf", "--pose", "0.4 0.1 0.5 0 1 0 0"]);
    assert!(out.contains("target: position (0.4, 0.1, 0.5), rotation rows (1, 0, 0; 0, -1, 0; 0, 0, -1)"), "{out}");
    let far = ok(&["ik", "robots/ur5.urdf", "--pose", "5 0 0 1 0 0 0"]);
    assert!(far.contains("8 solutions, 0 exact") && far.contains("least squares"), "{far}");
    for (pose, fault) in [
        ("0.4 0.1 0.5 0 0 0 0", "the quaternion has length zero: it is no rotation"),
        ("0.4 0.1 0.5 1 0 0", "6 values given; it takes seven: x y z qw qx qy qz"),
        ("0.4 x 0.5 1 0 0 0", "`x` is not a number"),
        ("0.4 NaN 0.5 1 0 0 0", "every value must be a finite number"),
    ] {
        let error = fails(&["ik", "robots/ur5.urdf", "--pose", pose]);
        assert_eq!(error, format!("error: robots/ur5.urdf: --pose \"{pose}\": {fault}"));
    }
}

#[test]
fn ik_on_a_chain_no_family_covers_says_why() {
    let error = fails(&["ik", "robots/iiwa14.urdf", "--pose", "0.4 0.1 0.5 0 1 0 0"]);
    assert!(
        error.starts_with("error: robots/iiwa14.urdf: robot `iiwa14`: no closed-form inverse kinematics"),
        "{error}"
    );
    assert!(error.contains("the chain has 7 moving joints; the closed forms solve six"), "{error}");
    let error = fails(&["ik", "robots/humanoid.urdf", "--tip", "RFinger23_link", "--pose", "0 0 0 1 0 0 0"]);
    assert!(error.contains("mimics `RHand`"), "{error}");
    // The Stanford arm: its slide from the wrist centre's distance.
    let stanford = ok(&["ik", "robots/stanford_arm.toml", "--from-q", "0.2,-0.4,0.5,0.3,0.6,-0.2"]);
    assert!(stanford.contains("joint 3 prismatic") && stanford.contains("8 solutions"), "{stanford}");
    // The SCARA is planar: two elbows, the stroke from the height.
    let scara = ok(&["ik", "robots/scara.toml", "--from-q", "0.3,-0.8,0.1,0.5"]);
    assert!(scara.contains("closed form: planar") && scara.contains("2 solutions, 2 exact"), "{scara}");
}

#[test]
fn inspect_names_each_leaf_s_ik_family() {
    let ur5 = ok(&["inspect", "robots/ur5.urdf"]);
    assert!(ur5.contains("inverse kinematics in closed form, from the root to each leaf:\n"), "{ur5}");
    assert!(ur5.contains("\n  tool0: axes 2, 3, 4 parallel, axes 5 and 6 meet (point of axis 5"), "{ur5}");
    assert!(ur5.contains("\n  base: none: the chain has 0 moving joints; the closed forms solve six\n"), "{ur5}");
    let panda = ok(&["inspect", "robots/panda.toml"]);
    assert!(panda.contains("  flange: none: the chain has 7 moving joints"), "{panda}");
}

#[test]
fn expr_ik_prints_the_family_its_subproblems_and_its_geometry() {
    let out = ok(&["expr", "robots/ur5.urdf", "--ik"]);
    for line in [
        "family: axes 2, 3, 4 parallel, axes 5 and 6 meet",
        "subproblems (IK-Geo's numbering): q1 by SP4, q5 by SP4, q6 by SP1",
        "  wrist_3_joint        h6 = (0, 1, 0)  p56 = (0, 0, 0)",
        "note: point of axis 5 (joint `wrist_2_joint`) moved +0.094650 m along it",
    ] {
        assert!(out.contains(line), "{out}\nlacks: {line}");
    }
    let free = ok(&["expr", "robots/iiwa14.urdf", "--ik", "--free", "iiwa_joint_3"]);
    assert!(free.contains("free joint: `iiwa_joint_3` (q[2]), axis (0, 0, 1) through (0, 0, 0.5645)"), "{free}");
    let error = fails(&["expr", "robots/panda.toml", "--ik"]);
    assert!(error.contains("the chain has 7 moving joints"), "{error}");
}

#[test]
fn check_runs_the_collision_checks_against_the_reference() {
    let out = ok(&[
        "check",
        "robots/panda_spherized.urdf",
        "--samples",
        "20",
        "--collision-samples",
        "200",
        "--srdf",
        "robots/panda.srdf",
        "--scene",
        "scenes/shelf.toml",
    ]);
    assert!(
        out.contains(
            "collision: 59 spheres on 11 links (at most 10 spheres per link, stopping at an overshoot of 0.01 m), 21 \
             self-collision pairs (less the pairs \
             robots/panda.srdf disables); scene scenes/shelf.toml (18 obstacles)"
        ),
        "{out}"
    );
    // Both verdicts occur, and every one outside the band is the reference's (or the run fails).
    for check in ["self_collides", "collides (obstacles and self)"] {
        let line = out.lines().find(|l| l.trim_start().starts_with(&format!("{check}:"))).unwrap();
        let numbers: Vec<usize> = line
            .split(|c: char| !c.is_ascii_digit())
            .filter(|w| !w.is_empty())
            .filter_map(|w| w.parse().ok())
            .collect();
        let (colliding, free) = (numbers[1], numbers[2]);
        assert!(colliding > 0 && free > 0 && colliding + free <= 200, "{line}");
    }
    let none = ok(&["check", "robots/planar_3r.urdf", "--samples", "5", "--collision"]);
    assert!(none.ends_with("collision: no <collision> geometry the cover reads\n"), "{none}");
    let message = fails(&["check", "robots/ur5_spherized.urdf", "--samples", "5", "--srdf", "robots/panda.srdf"]);
    assert!(message.contains("robots/panda.srdf: line 51:"), "{message}");
}

/// Issue 33: `inspect` of an MJCF file shows MJCF's names; `--format` overrides the extension.
#[test]
fn mjcf_files_are_read_by_their_root_element_or_as_format_says() {
    let text = ok(&["inspect", "robots/ur5_mjcf.xml"]);
    assert!(text.starts_with("robot `ur5`: 11 links, 10 joints, 6 degrees of freedom\nroot link: world\n"), "{text}");
    assert!(text.contains("  joint `tool0`: -1.5707963267948966 -> -pi/2 (the nearest f64 to it)"), "{text}");
    assert_eq!(ok(&["--format", "mjcf", "inspect", "robots/ur5_mjcf.xml"]), text);
    assert_eq!(
        fails(&["--format", "urdf", "inspect", "robots/ur5_mjcf.xml"]),
        "error: robots/ur5_mjcf.xml: line 11: the root element is <mujoco>, not <robot>"
    );
    let dir = scratch("mjcf-format");
    let renamed = dir.join("arm.model");
    std::fs::copy(root().join("robots/ur5_mjcf.xml"), &renamed).unwrap();
    let renamed = renamed.to_string_lossy().into_owned();
    assert!(fails(&["inspect", &renamed]).contains("unknown description format"));
    assert!(ok(&["--format", "mjcf", "fk", &renamed]).contains("tool0"));
    // What MJCF says and is not applied is listed.
    let coupled = dir.join("coupled.xml");
    std::fs::write(
        &coupled,
        "<mujoco><worldbody><body name=\"a\"><joint name=\"j\"/><body name=\"b\"><joint name=\"k\"/></body></body>\
         </worldbody><equality><weld body1=\"a\" body2=\"b\"/></equality></mujoco>",
    )
    .unwrap();
    let text = ok(&["inspect", &coupled.to_string_lossy()]);
    assert!(
        text.contains("not applied (1):\n  <equality><weld> (line 1): not kinematics of a tree, not applied\n"),
        "{text}"
    );
}

/// Issue 33: `convert` writes the URDF of an MJCF file's kinematics, which reads back as the
/// same robot (every link's pose at many configurations), a hinge off its body's origin
/// included.
#[test]
fn convert_writes_urdf_that_reads_back_as_the_same_robot() {
    let dir = scratch("convert");
    let off = dir.join("off.xml");
    std::fs::write(
        &off,
        "<mujoco><worldbody><body name=\"b\" pos=\"1 0 0\" quat=\"0.9 0.1 0.3 0.2\">\
         <joint name=\"h\" pos=\"0 0.5 0\" axis=\"1 1 0\" range=\"-90 90\"/>\
         <body name=\"c\" pos=\"0 0 1\"><joint name=\"s\" type=\"slide\" ref=\"0.2\"/></body></body></worldbody></mujoco>",
    )
    .unwrap();
    for file in ["robots/walker.xml".to_owned(), "robots/ur5_mjcf.xml".to_owned(), off.to_string_lossy().into_owned()] {
        let out = dir.join("robot.urdf");
        assert_eq!(ok(&["convert", &file, "-o", &out.to_string_lossy()]), "");
        let urdf = std::fs::read_to_string(&out).unwrap();
        assert!(urdf.contains("Geometry, inertia, actuators and everything else the source says\n     are left out"));
        let (a, b) = (ReferenceFk::new(load(&file)), ReferenceFk::new(kinematics::load(&out).unwrap()));
        assert_eq!(a.tree().dof(), b.tree().dof(), "{file}");
        for k in 0..20 {
            let q: Vec<f64> = (0..a.tree().dof()).map(|i| ((i * 7 + k * 3) % 11) as f64 / 11.0 - 0.4).collect();
            for link in a.tree().links() {
                let (p, r) = (a.link_pose(&q, &link.name).unwrap(), b.link_pose(&q, &link.name).unwrap());
                assert!(
                    (p.to_homogeneous() - r.to_homogeneous()).iter().all(|e| e.abs() < 1e-12),
                    "{file}: {}",
                    link.name
                );
            }
        }
    }
    assert!(ok(&["convert", &off.to_string_lossy()]).contains("<link name=\"h.frame\"/>"));
}

/// Issue 33: URDF has no spherical joint, so `convert` refuses a robot with an MJCF ball joint,
/// naming the joint, and writes nothing; `inspect` shows the joint's kind and its four entries of
/// `q`, and no axis.
#[test]
fn convert_refuses_a_spherical_joint_and_inspect_shows_one() {
    let dir = scratch("convert-ball");
    let out = dir.join("robot.urdf");
    let message = fails(&["convert", "robots/ball_tree.xml", "-o", &out.to_string_lossy()]);
    assert_eq!(
        message,
        "error: robots/ball_tree.xml: joint `left_shoulder`: a spherical joint cannot be written as URDF (URDF has \
         no joint whose position is a quaternion; its `spherical` type is not in the specification), so nothing is \
         written"
    );
    assert!(!out.exists(), "nothing written");
    fails(&["convert", "robots/ball_tree.xml"]);
    let text = ok(&["inspect", "robots/ball_tree.xml"]);
    assert!(
        text.starts_with("robot `ball_tree`: 13 links, 12 joints, 20 degrees of freedom (24 entries of q)\n"),
        "{text}"
    );
    let line = text.lines().find(|l| l.trim_start().starts_with("left_shoulder ")).unwrap();
    assert!(line.contains("spherical") && line.ends_with("q[7..11]") && !line.contains("axis"), "{line}");
    assert!(
        text.contains("q[7] left_shoulder.qx, q[8] left_shoulder.qy, q[9] left_shoulder.qz, q[10] left_shoulder.qw")
    );
    // Without `--q`, every quaternion is the identity: the robot as written, its torso at the origin.
    let fk = ok(&["fk", "robots/ball_tree.xml", "--link", "eye", "--json"]);
    assert!(fk.contains("0.38"), "{fk}");
    // A floating joint shows no axis either (it has none).
    let line = text.lines().find(|l| l.trim_start().starts_with("root_joint ")).unwrap();
    assert!(line.contains("floating") && !line.contains("axis"), "{line}");
}

/// Issue 31: `collision-pairs` writes an SRDF the derive's reader takes, the same for the same
/// seed; its adjacent pairs are the model's, its `Never` pairs touch in none of the samples
/// (checked here on the reference's sphere centres of the same stream), and bad arguments are
/// refused, nothing written.
#[test]
fn collision_pairs_writes_an_srdf_the_derive_reads() {
    use kinematics::model::collision::{Cover, Meshes, link_spheres, sphere_pairs};
    let dir = scratch("collision-pairs");
    let out = dir.join("panda.srdf");
    let file = "robots/panda_spherized.urdf";
    assert_eq!(ok(&["collision-pairs", file, "--samples", "300", "-o", &out.to_string_lossy()]), "");
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(text, ok(&["collision-pairs", file, "--samples", "300"]), "the same seed, the same file");
    assert_ne!(text, ok(&["collision-pairs", file, "--samples", "300", "--seed", "1"]), "another seed");
    // What the derive reads: the model's SRDF reader, every pair's links in the tree.
    let tree = load(file);
    let srdf = kinematics::model::srdf::parse_srdf(&text).unwrap();
    let disabled = srdf.disabled_pairs(&tree).unwrap();
    let spheres = link_spheres(&tree, &Cover::default(), Meshes::Skip).unwrap();
    let checked = sphere_pairs(&tree, &spheres, Some(&disabled)).pairs;
    let without_srdf = sphere_pairs(&tree, &spheres, None).pairs;
    let id = |name: &str| tree.links().iter().position(|l| l.name == name).map(kinematics::model::LinkId).unwrap();
    let reasons: Vec<(kinematics::model::LinkId, kinematics::model::LinkId, String)> = text
        .lines()
        .filter(|l| l.contains("<disable_collisions"))
        .map(|l| {
            let attribute =
                |key: &str| l.split(&format!("{key}=\"")).nth(1).unwrap().split('"').next().unwrap().to_owned();
            let (a, b) = (id(&attribute("link1")), id(&attribute("link2")));
            (a.min(b), a.max(b), attribute("reason"))
        })
        .collect();
    assert_eq!(reasons.len(), disabled.len());
    for (a, b, reason) in &reasons {
        assert!(!checked.contains(&(*a, *b)), "a disabled pair is not checked");
        assert_eq!(reason == "Adjacent", !without_srdf.contains(&(*a, *b)), "{a:?} {b:?}: {reason}");
    }
    // The `Never` pairs touch in none of the same samples.
    let fk = ReferenceFk::new(tree.clone());
    let never: Vec<_> = reasons.iter().filter(|r| r.2 == "Never").map(|r| (r.0, r.1)).collect();
    assert!(!never.is_empty());
    for q in kinematics::Configurations::new(&tree).seeded(0).uniform().take(300) {
        let centers = fk.sphere_centers(&q, &spheres).unwrap();
        for (s, a) in spheres.iter().enumerate() {
            for (t, b) in spheres.iter().enumerate() {
                let reach = a.sphere.radius + b.sphere.radius;
                if never.contains(&(a.link, b.link)) && (centers[s] - centers[t]).norm() <= reach {
                    panic!("{:?} and {:?} touch at {q:?}", a.link, b.link);
                }
            }
        }
    }
    for (args, fault) in [
        (vec!["--samples", "0"], "`--samples`"),
        (vec!["--always", "1.5"], "`--always`"),
        (vec!["--sphere-cover=-1"], "`--cover`"),
        (vec!["--spheres=0"], "`--spheres`"),
    ] {
        let bad = dir.join("bad.srdf");
        let mut all = vec!["collision-pairs", file, "-o", bad.to_str().unwrap()];
        all.extend(args);
        assert!(fails(&all).contains(fault), "{fault}");
        assert!(!bad.exists(), "nothing written");
    }
    assert!(fails(&["collision-pairs", "robots/planar_2r.toml"]).contains("no collision geometry"));
}

#[test]
fn inspect_lists_the_links_masses_and_the_inertias_dynamics_refuse() {
    // The total is the sum of the file's masses, each link with one listed, the others massless.
    let tree = load("robots/ur5.urdf");
    let masses: Vec<(&str, f64)> =
        tree.links().iter().filter_map(|l| l.inertial.as_ref().map(|i| (l.name.as_str(), i.mass))).collect();
    let total: f64 = masses.iter().map(|(_, m)| m).sum();
    let printed = ok(&["inspect", "robots/ur5.urdf", "--skip-meshes"]);
    let header =
        format!("mass: {} kg on {} of {} links\n", (total * 1e6).round() / 1e6, masses.len(), tree.links().len());
    assert!(printed.contains(&header), "{header}{printed}");
    for (link, mass) in &masses {
        assert!(printed.contains(&format!(" {link} ")) && printed.contains(&format!(" {mass} kg at ")), "{link}");
    }
    assert!(printed.contains("  massless: ee_link, tool0, base\n"), "{printed}");
    // A negative mass and a tensor breaking the triangle inequality are named with their lines.
    let dir = scratch("inspect_masses");
    let file = dir.join("bad.urdf");
    std::fs::write(
        &file,
        "<robot name=\"r\">\n<link name=\"a\">\n<inertial><mass value=\"-1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" \
         iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial>\n</link>\n<link name=\"b\">\n<inertial><mass value=\"1\"/><inertia \
         ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"3\"/></inertial>\n</link>\n<joint name=\"j\" \
         type=\"continuous\"><parent link=\"a\"/><child link=\"b\"/></joint>\n</robot>\n",
    )
    .unwrap();
    let printed = ok(&["inspect", file.to_str().unwrap()]);
    assert!(printed.contains("  link `a` (line 3): its mass is -1 kg (must be zero or more)\n"), "{printed}");
    assert!(printed.contains("  link `b` (line 6): its inertia's principal moments [1.0, 1.0, 3.0]"), "{printed}");
    std::fs::remove_dir_all(&dir).unwrap();
    // An MJCF body left to MuJoCo's inference is named.
    let printed = ok(&["inspect", "robots/walker.xml"]);
    assert!(
        printed
            .contains("left to MuJoCo to infer from their geoms (dynamics refuse them; write an <inertial>): pelvis\n")
    );
}
