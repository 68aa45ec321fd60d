//! Operation counts of the generated code for every robot in `robots/`, against a plain sequential
//! product of the same transforms (zeros and ones folded, nothing else), and the targets we hold
//! the compiler to. `cargo test -p kinematics-compiler --test op_counts -- --nocapture` prints the
//! table the guide carries (`src/guide/emitted.md`).
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

mod common;

use common::robots;

use kinematics_compiler::{OpCount, Request, compile, plain_product_count};
use kinematics_model::{JacobianFrame, KinematicTree};

/// The end effector: the deepest link (the last leaf of the longest path from the root).
fn end_effector(tree: &KinematicTree) -> String {
    let deepest = (0..tree.links().len()).max_by_key(|&l| (tree.path_from_root(kinematics_model::LinkId(l)).len(), l));
    tree.link(kinematics_model::LinkId(deepest.unwrap_or(0))).name.clone()
}

fn short(c: OpCount) -> String {
    format!("{}/{}/{}", c.sin_cos, c.mul, c.add)
}

/// The table the guide prints (`src/guide/emitted.md`): one markdown row per robot in `robots/`.
fn table() -> String {
    let mut rows = String::from(
        "| robot | DoF | tip | generated | plain product | position only | all links |\n|---|---|---|---|---|---|---|\n",
    );
    for file in robots() {
        let tree = common::robot(&file);
        let tip = end_effector(&tree);
        let pose = compile(&tree, &Request::tip(&tip)).unwrap().op_count();
        let position = compile(&tree, &Request::tip(&tip).positions_only()).unwrap().op_count();
        let all = compile(&tree, &Request::all_links()).unwrap().op_count();
        let plain = plain_product_count(&tree, tree.link(tree.root()).name.as_str(), &tip).unwrap();
        rows.push_str(&format!(
            "| {file} | {} | {tip} | {} | {} | {} | {} |\n",
            tree.dof(),
            short(pose),
            short(plain),
            short(position),
            short(all)
        ));
        assert!(pose.mul <= plain.mul && pose.add <= plain.add + tree.dof(), "{file}: {pose} vs plain {plain}");
        assert!(position.mul <= pose.mul, "{file}");
    }
    rows
}

/// The op counts of every robot are pinned: a compiler change that moves any of them shows in
/// the snapshot's diff (review with `cargo insta review`, or `INSTA_UPDATE=always` and `git diff`).
#[test]
fn table_of_every_robot() {
    let table = table();
    println!("sin_cos/mul/add per robot (tip pose: generated | plain product; position only; all links)\n{table}");
    insta::assert_snapshot!("op_counts", table);
}

/// Every row of the guide's op-count table (`src/guide/emitted.md`) is a row of the pinned table,
/// so the guide cannot quote counts the compiler no longer produces.
#[test]
fn the_guide_quotes_the_pinned_table() {
    let rows = guide_quotes(&table(), "emitted.md", "| robot | DoF | tip | generated |");
    assert!(rows >= 10, "{rows} rows");
}

/// Every row of the table under `header` on the guide's page `page` is a row of `table`, so the
/// guide cannot quote counts the compiler no longer produces; the number of rows quoted.
fn guide_quotes(table: &str, page: &str, header: &str) -> usize {
    let path = format!("{}/../src/guide/{page}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap();
    let section = text.split(header).nth(1).unwrap_or_else(|| panic!("{page} has the table `{header}`"));
    let rows: Vec<&str> = section.lines().skip(2).take_while(|l| l.starts_with('|')).collect();
    for row in &rows {
        assert!(table.lines().any(|l| l == *row), "{page}: row `{row}` is not what the compiler produces:\n{table}");
    }
    rows.len()
}

/// The velocity functions of every robot's end effector: the Jacobian (`LOCAL_WORLD_ALIGNED` and
/// `LOCAL`), the pose with the Jacobian, the twist, and the twist as `J * qd` with `J` formed.
fn velocity_table() -> String {
    let mut rows = String::from(
        "| robot | DoF | tip | pose | Jacobian | LOCAL Jacobian | pose + Jacobian | twist | J formed, times qd |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for file in robots() {
        let tree = common::robot(&file);
        let tip = end_effector(&tree);
        let n = tree.dof();
        let count = |r: Request| compile(&tree, &r).unwrap().op_count();
        let pose = count(Request::tip(&tip));
        let jacobian = count(Request::tip(&tip).jacobian(JacobianFrame::LocalWorldAligned));
        let local = count(Request::tip(&tip).jacobian(JacobianFrame::Local));
        let both = count(Request::tip(&tip).pose_and_jacobian(JacobianFrame::LocalWorldAligned));
        let twist = count(Request::tip(&tip).twist(JacobianFrame::LocalWorldAligned));
        let formed = OpCount { mul: jacobian.mul + 6 * n, add: jacobian.add + 6 * n.saturating_sub(1), ..jacobian };
        rows.push_str(&format!(
            "| {file} | {n} | {tip} | {} | {} | {} | {} | {} | {} |\n",
            short(pose),
            short(jacobian),
            short(local),
            short(both),
            short(twist),
            short(formed)
        ));
        // The pair never calls sin_cos more than the pose, and costs less than the two apart.
        assert!(both.sin_cos <= pose.sin_cos.max(jacobian.sin_cos) + 1, "{file}: {both} vs {pose}, {jacobian}");
        assert!(both.mul <= pose.mul + jacobian.mul, "{file}: {both} vs {pose} + {jacobian}");
        // The twist is cheaper than forming J and multiplying.
        assert!(twist.mul + twist.add < formed.mul + formed.add, "{file}: twist {twist} vs formed {formed}");
    }
    rows
}

/// The velocity op counts are pinned as the pose counts are, and the guide quotes them
/// (`src/guide/velocities.md`).
#[test]
fn velocity_table_of_every_robot() {
    let table = velocity_table();
    println!("sin_cos/mul/add of the end effector's velocity functions\n{table}");
    insta::assert_snapshot!("velocity_op_counts", table);
    guide_quotes(&table, "velocities.md", "| robot | DoF | tip | pose | Jacobian |");
}

fn pose_count(file: &str, tip: &str) -> OpCount {
    compile(&common::robot(file), &Request::tip(tip)).unwrap().op_count()
}

#[test]
fn ur5_end_effector() {
    let count = pose_count("ur5.toml", "wrist_3_link");
    assert_eq!(count.sin_cos, 6);
    assert!(count.add <= 22, "{count}");
    assert!(count.mul <= 37, "{count}");
}

#[test]
fn puma560_end_effector() {
    let count = pose_count("puma560.toml", "link6");
    assert_eq!(count.sin_cos, 6, "{count}");
    assert!(count.mul <= 46 && count.add <= 23, "{count}");
}

#[test]
fn panda_flange() {
    let count = pose_count("panda.toml", "flange");
    assert_eq!(count.sin_cos, 7, "{count}");
    assert!(count.mul <= 80 && count.add <= 43, "{count}");
}

/// The dynamics of every robot in `robots/` whose inertias the rules take: each function's
/// operations (`sin_cos/mul/add`; forward dynamics' divisions after it), then in parentheses the
/// plain recursive algorithm's (`plain_op_count`: the same recursion with the robot's numbers
/// unknown until run time).
fn dynamics_table() -> String {
    use kinematics_compiler::dynamics::{DynamicsFunction, DynamicsRequest, compile_dynamics, plain_op_count};
    let mut rows = String::from(
        "| robot | velocities | gravity | inverse dynamics | nonlinear effects | mass matrix | forward dynamics |\n|---|---|---|---|---|---|---|\n",
    );
    for file in robots() {
        let tree = common::robot(&file);
        let request = DynamicsRequest::default();
        let massless = tree.links().iter().all(|l| l.inertial.is_none());
        if massless || compile_dynamics(&tree, &request, DynamicsFunction::Gravity).is_err() {
            continue;
        }
        let mut cells = Vec::new();
        let mut totals = Vec::new();
        for function in DynamicsFunction::ALL {
            let generated = compile_dynamics(&tree, &request, function).unwrap().op_count();
            let plain = plain_op_count(&tree, &request, function).unwrap();
            let div = |c: OpCount| if c.div > 0 { format!(" + {} div", c.div) } else { String::new() };
            cells.push(format!("{}{} ({}{})", short(generated), div(generated), short(plain), div(plain)));
            // The robot's numbers never cost operations.
            assert!(
                generated.mul <= plain.mul && generated.add <= plain.add && generated.div <= plain.div,
                "{file} {function:?}: {generated} against plain {plain}"
            );
            assert!(generated.div <= tree.velocity_dof(), "{file}: at most one division per pivot, {generated}");
            totals.push(generated.mul + generated.add);
        }
        // Gravity alone is the cheapest; inverse dynamics holds the nonlinear effects' work.
        assert!(totals[0] < totals[2] && totals[2] <= totals[1], "{file}: {totals:?}");
        rows.push_str(&format!("| {file} | {} | {} |\n", tree.velocity_dof(), cells.join(" | ")));
    }
    rows
}

/// The dynamics' op counts are pinned as the poses' are, and the guide quotes them
/// (`src/guide/dynamics.md`).
#[test]
fn dynamics_table_of_every_robot_with_inertias() {
    let table = dynamics_table();
    println!("sin_cos/mul/add of the dynamics\n{table}");
    insta::assert_snapshot!("dynamics_op_counts", table);
    assert!(guide_quotes(&table, "dynamics.md", "| robot | velocities | gravity |") >= 2);
}
