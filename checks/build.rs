//! Compiles every robot in `robots/` into `OUT_DIR/robots.rs`: per robot, the pose and position of
//! each leaf link and the poses of all links, plus a registry the tests iterate over.

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
    let out = Path::new(&std::env::var("OUT_DIR")?).join("robots.rs");
    std::fs::write(out, code)?;
    Ok(())
}
