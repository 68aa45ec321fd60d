//! Compiles every robot in `robots/` into `OUT_DIR/robots.rs`: per robot, the pose and position of
//! each leaf link and the poses of all links, plus a registry the tests iterate over; and writes
//! `OUT_DIR/derived.rs`, where `#[derive(Kinematics)]` compiles every robot again from its file and,
//! for DH tables, from the same table written inline in the attribute.

use std::fmt::Write as _;
use std::path::Path;

use kinematics_compiler::emit::{EmitOptions, emit_function};
use kinematics_compiler::{Request, compile};

fn ident(name: &str) -> String {
    let s: String =
        name.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' }).collect();
    if s.starts_with(|c: char| c.is_ascii_digit()) { format!("l_{s}") } else { s }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let robots = Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots");
    println!("cargo:rerun-if-changed={}", robots.display());
    let mut files: Vec<_> = std::fs::read_dir(&robots)?.filter_map(Result::ok).map(|e| e.path()).collect();
    files.sort();
    let mut code = String::new();
    let mut registry = String::new();
    let mut derived = String::new();
    let mut derived_registry = String::new();
    for path in files {
        let file = path.file_name().and_then(|f| f.to_str()).unwrap_or_default().to_owned();
        if kinematics_model::SourceFormat::from_file_name(&file).is_none() {
            continue;
        }
        println!("cargo:rerun-if-changed={}", path.display());
        let tree = kinematics_model::parse_source(&file, &std::fs::read_to_string(&path)?)?;
        let module = ident(&file);
        let n = tree.dof();
        let leaves: Vec<String> = tree
            .links()
            .iter()
            .filter(|l| l.child_joints.is_empty() && l.parent_joint.is_some())
            .map(|l| l.name.clone())
            .collect();
        let mut functions = Vec::new();
        let mut tips = String::new();
        for leaf in &leaves {
            let pose = compile(&tree, &Request::tip(leaf))?;
            let position = compile(&tree, &Request::tip(leaf).positions_only())?;
            let (pose_fn, position_fn) = (format!("{}_pose", ident(leaf)), format!("{}_position", ident(leaf)));
            functions.push(emit_function(&pose, &EmitOptions::named(&pose_fn)));
            functions.push(emit_function(&position, &EmitOptions::named(&position_fn)));
            writeln!(
                tips,
                "Tip {{ link: {leaf:?}, pose: |q| {module}::{pose_fn}::<f64>(arr(q)), pose_f32: |q| {module}::{pose_fn}::<f32>(arr(q)), position: |q| {module}::{position_fn}::<f64>(arr(q)) }},"
            )?;
        }
        let key = if file.ends_with(".urdf") { "urdf" } else { "dh" };
        let leaf_list = leaves.iter().map(|l| format!("{l:?}")).collect::<Vec<_>>().join(", ");
        let mut sources = vec![(format!("{key} = \"../robots/{file}\""), "file")];
        if key == "dh" && file.ends_with(".toml") {
            let table = kinematics_model::dh::parse_dh_toml(&std::fs::read_to_string(&path)?)?;
            sources.push((inline_dh(&table), "inline"));
        }
        for (source, how) in sources {
            let ty = format!("Derived_{module}_{how}");
            // Keyword rows repeat keys (`a = ..` in every `joint(..)`), which clippy's
            // `duplicated_attributes` mistakes for duplicates; the positional `row(..)` form avoids it.
            let allow = if how == "inline" { "#[allow(clippy::duplicated_attributes)]\n" } else { "" };
            writeln!(
                derived,
                "/// `robots/{file}` ({how}).\n{allow}#[derive(::kinematics::Kinematics)]\n#[kinematics({source}, tips({leaf_list}), positions, scalars(f64, f32))]\n#[allow(non_camel_case_types)]\npub struct {ty};"
            )?;
            let tips_f32 = if leaves.len() == 1 {
                format!("|q| vec![{ty}::tip_pose_f32(arr(q))]")
            } else {
                format!("|q| {ty}::tip_poses_f32(arr(q)).to_vec()")
            };
            writeln!(
                derived_registry,
                "DerivedRobot {{ file: {file:?}, how: {how:?}, tips: &{ty}::TIPS, links: &{ty}::LINK_NAMES, tip_poses_into: <{ty} as ::kinematics::Kinematics>::tip_poses_into, link_poses_into: <{ty} as ::kinematics::Kinematics>::link_poses_into, tip_poses_f32: {tips_f32}, reference: <{ty} as ::kinematics::Kinematics>::reference }},"
            )?;
        }
        let all = compile(&tree, &Request::all_links())?;
        functions.push(emit_function(&all, &EmitOptions::named("all_links")));
        let links: Vec<String> = all.frames().iter().map(|f| format!("{:?}", f.link)).collect();
        let functions: String = functions.iter().map(|f| f.to_string()).collect::<Vec<_>>().join("\n");
        writeln!(code, "/// Generated from `robots/{file}`.\npub mod {module} {{\n{functions}\n}}")?;
        writeln!(
            registry,
            "GeneratedRobot {{ file: {file:?}, dof: {n}, tips: &[{tips}], all_links: &[{}], all_poses: |q| {module}::all_links::<f64>(arr(q)).to_vec() }},",
            links.join(", ")
        )?;
    }
    writeln!(code, "/// Every robot in `robots/`, compiled.\npub const ROBOTS: &[GeneratedRobot] = &[{registry}];")?;
    writeln!(
        derived,
        "/// Every robot in `robots/`, derived.\npub const DERIVED: &[DerivedRobot] = &[{derived_registry}];"
    )?;
    let out = Path::new(&std::env::var("OUT_DIR")?).to_path_buf();
    std::fs::write(out.join("robots.rs"), code)?;
    std::fs::write(out.join("derived.rs"), derived)?;
    Ok(())
}

/// A DH table as the inline `dh(...)` attribute form.
fn inline_dh(table: &kinematics_model::dh::DhTable) -> String {
    use kinematics_model::dh::{AngleUnit, DhConvention, DhFixed, DhJointType, Value};
    let value = |v: &Value| match v {
        Value::Number(x) => format!("{x:?}"),
        Value::Text(t) => format!("{t:?}"),
    };
    let fixed = |key: &str, f: &DhFixed| {
        format!(
            "{key}(name = {:?}, xyz({}), rpy({}))",
            f.name,
            f.xyz.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>().join(", "),
            f.rpy.iter().map(value).collect::<Vec<_>>().join(", ")
        )
    };
    let mut parts = vec![
        format!("convention = {:?}", if table.convention == DhConvention::Standard { "standard" } else { "modified" }),
        format!("name = {:?}", table.name),
        format!("base_link = {:?}", table.base_link),
    ];
    if table.angle_unit == AngleUnit::Degrees {
        parts.push("angle_unit = \"degrees\"".to_owned());
    }
    if let Some(base) = &table.base {
        parts.push(fixed("base", base));
    }
    if let Some(tool) = &table.tool {
        parts.push(fixed("tool", tool));
    }
    for row in &table.joints {
        let mut cols = vec![format!("name = {:?}", row.name)];
        if let Some(link) = &row.link {
            cols.push(format!("link = {link:?}"));
        }
        if row.kind == DhJointType::Prismatic {
            cols.push("type = \"prismatic\"".to_owned());
        }
        cols.push(format!("a = {:?}", row.a));
        cols.push(format!("alpha = {}", value(&row.alpha)));
        cols.push(format!("d = {:?}", row.d));
        cols.push(format!("theta = {}", value(&row.theta)));
        cols.push(format!("offset = {}", value(&row.offset)));
        for (key, v) in [("lower", &row.lower), ("upper", &row.upper)] {
            if let Some(v) = v {
                cols.push(format!("{key} = {}", value(v)));
            }
        }
        parts.push(format!("joint({})", cols.join(", ")));
    }
    format!("dh({})", parts.join(", "))
}
