//! Compiles every robot in `robots/` into `OUT_DIR/robots.rs`: per robot, the pose and position of
//! each leaf link and the poses of all links, plus a registry the tests iterate over; and writes
//! `OUT_DIR/derived.rs`, where `#[derive(Kinematics)]` compiles every robot again from its file and,
//! for DH tables, from the same table written inline in the attribute. It also writes a fixed-seed
//! set of random robots (`build/random_robots.rs`) as description files into `OUT_DIR/random/`,
//! compiled through `kinematics_compiler::robot::emit_robot` (the derive's own path) into
//! `OUT_DIR/random_robots.rs`; and `OUT_DIR/stack.rs` (`build/stack_cases.rs`), every robot derived
//! with every option it takes and a case calling each function, for `tests/debug_stack.rs`.

#[path = "build/random_robots.rs"]
mod random_robots;
#[path = "build/stack_cases.rs"]
mod stack_cases;

use std::fmt::Write as _;
use std::path::Path;

use kinematics_compiler::emit::{EmitOptions, emit_function};
use kinematics_compiler::{Request, compile};
use kinematics_model::JacobianFrame;

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
    let (mut stack_structs, mut stack_cases) = (String::new(), String::new());
    for path in files {
        let file = path.file_name().and_then(|f| f.to_str()).unwrap_or_default().to_owned();
        if kinematics_model::SourceFormat::from_file_name(&file).is_none() {
            continue;
        }
        println!("cargo:rerun-if-changed={}", path.display());
        let tree = kinematics_model::parse_source(&file, &std::fs::read_to_string(&path)?)?;
        let module = ident(&file);
        let n = tree.dof();
        let leaves: Vec<String> = tree.leaves().map(|l| tree.link(l).name.clone()).collect();
        let mut functions = Vec::new();
        let mut tips = String::new();
        let nv = tree.velocity_dof();
        for leaf in &leaves {
            let pose = compile(&tree, &Request::tip(leaf))?;
            let position = compile(&tree, &Request::tip(leaf).positions_only())?;
            let (pose_fn, position_fn) = (format!("{}_pose", ident(leaf)), format!("{}_position", ident(leaf)));
            functions.push(emit_function(&pose, &EmitOptions::named(&pose_fn)));
            functions.push(emit_function(&position, &EmitOptions::named(&position_fn)));
            // The Jacobian in both frames, and the pose again on dual numbers: the generated
            // pose's own derivatives, a witness that shares no Jacobian code.
            let (jacobian_fn, local_fn) =
                (format!("{}_jacobian", ident(leaf)), format!("{}_jacobian_local", ident(leaf)));
            for (frame, name) in [(JacobianFrame::LocalWorldAligned, &jacobian_fn), (JacobianFrame::Local, &local_fn)] {
                let jacobian = compile(&tree, &Request::tip(leaf).jacobian(frame))?;
                functions.push(emit_function(&jacobian, &EmitOptions::named(name)));
            }
            writeln!(
                tips,
                "Tip {{ link: {leaf:?}, pose: |q| {module}::{pose_fn}::<f64>(arr(q)), pose_f32: |q| {module}::{pose_fn}::<f32>(arr(q)), position: |q| {module}::{position_fn}::<f64>(arr(q)), \
                 jacobian: |q| columns({module}::{jacobian_fn}::<f64>(arr(q))), jacobian_local: |q| columns({module}::{local_fn}::<f64>(arr(q))), \
                 jacobian_by_duals: |q, d| dual::jacobian::<{n}, {nv}>({module}::{pose_fn}::<dual::Dual<{nv}>>, q, d) }},"
            )?;
        }
        let text = std::fs::read_to_string(&path)?;
        let key = match kinematics_model::SourceFormat::detect(&file, kinematics_model::SourceKind::ByExtension, &text)
        {
            Some(kinematics_model::SourceFormat::Urdf) => "urdf",
            Some(kinematics_model::SourceFormat::Mjcf) => "mjcf",
            _ => "dh",
        };
        let leaf_list = leaves.iter().map(|l| format!("{l:?}")).collect::<Vec<_>>().join(", ");
        let mut sources = vec![(format!("{key} = \"../robots/{file}\""), "file")];
        if key == "dh" && file.ends_with(".toml") {
            let table = kinematics_model::dh::parse_dh_toml(&std::fs::read_to_string(&path)?)?;
            sources.push((inline_dh(&table), "inline"));
        }
        stack_cases::write(&file, &module, &sources[0].0, &tree, &mut stack_structs, &mut stack_cases)?;
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
                "DerivedRobot {{ file: {file:?}, how: {how:?}, tips: &{ty}::TIPS, links: &{ty}::LINK_NAMES, tip_poses_into: <{ty} as ::kinematics::Kinematics>::tip_poses_into, link_poses_into: <{ty} as ::kinematics::Kinematics>::link_poses_into, tip_poses_f32: {tips_f32}, reference: <{ty} as ::kinematics::ReferenceModel>::reference }},"
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
    std::fs::write(
        out.join("stack.rs"),
        format!(
            "{stack_structs}\n/// Every function of every robot in `robots/`, each its own case.\npub const STACK_CASES: &[StackCase] = &[{stack_cases}];\n"
        ),
    )?;
    write_random_robots(&out)?;
    Ok(())
}

/// `random_07_mimic_chain` as `Random07MimicChain`.
fn type_name(name: &str) -> String {
    name.split('_')
        .map(|part| {
            let mut chars = part.chars();
            chars.next().map(|c| c.to_ascii_uppercase().to_string() + chars.as_str()).unwrap_or_default()
        })
        .collect()
}

/// Writes every random robot's description into `OUT_DIR/random/` and its compiled struct and
/// registry entry into `OUT_DIR/random_robots.rs`.
fn write_random_robots(out: &Path) -> Result<(), Box<dyn std::error::Error>> {
    use kinematics_compiler::options::{Options, Scalars, Trig};
    use kinematics_compiler::robot::{RobotSpec, emit_robot};
    use kinematics_model::ExactAngles;
    let dir = out.join("random");
    // Start empty, so no file of an earlier set stays behind.
    if dir.exists() {
        std::fs::remove_dir_all(&dir)?;
    }
    std::fs::create_dir_all(&dir)?;
    let mut code = String::new();
    let mut registry = String::new();
    for (index, robot) in random_robots::generate().into_iter().enumerate() {
        // Every fourth robot calls std's sine and cosine (`trig = "std"`), the others ours.
        let trig = if index % 4 == 3 { "Std" } else { "Fast" };
        std::fs::write(dir.join(&robot.file), &robot.text)?;
        let tree = kinematics_model::parse_source_with(&robot.file, &robot.text, ExactAngles::on(robot.exact_angles))
            .map_err(|e| format!("random robot {}: {e}\n{}", robot.file, robot.text))?;
        let ty = type_name(&robot.name);
        let text_expr = format!("include_str!(concat!(env!(\"OUT_DIR\"), \"/random/{}\"))", robot.file);
        // Every robot with tips and `f64` functions gets its tips' velocities, checked against the
        // runtime reference and dual numbers through its generated pose.
        let velocities = robot.f64 && !robot.tips.is_empty();
        let options = Options {
            base: robot.base.clone(),
            tips: robot.tips.clone(),
            positions: robot.positions,
            jacobians: velocities,
            scalars: Scalars { f64: robot.f64, f32: robot.f32 },
            trig: if trig == "Std" { Trig::Std } else { Trig::Fast },
            exact_angles: ExactAngles::on(robot.exact_angles),
            ..Options::default()
        };
        let spec = RobotSpec {
            robot: options.check(&tree).map_err(|e| format!("random robot {}: {e}", robot.file))?,
            krate: "::kinematics".parse()?,
            source_label: robot.file.clone(),
            source_text: text_expr.parse()?,
            source_files: None,
            impl_generics: "".parse()?,
            where_clause: "".parse()?,
        };
        let tokens = emit_robot(&ty.parse()?, &spec).map_err(|e| format!("random robot {}: {e}", robot.file))?;
        let item =
            format!("/// `random/{}` ({}).\n#[derive(Debug)]\npub struct {ty};\n{tokens}\n", robot.file, robot.shape);
        code += &item;
        let tips = robot.tips.len();
        // Every robot's batch and lane-type functions are checked too: each is the whole robot
        // again, on a lane type and, dispatched, once per instruction set. Unoptimised (see the
        // workspace's profiles) that is about two minutes of compile time; optimised, checking
        // only every sixth robot's took most of CI's.
        let typed = |on: bool, suffix: &str, t: &str| {
            if !on {
                return "None".to_owned();
            }
            let lanes = if t == "f64" { "::kinematics::F64x4" } else { "::kinematics::F32x8" };
            let position = |what: &str| {
                if robot.positions {
                    format!("Some(|q| {ty}::{what}{suffix}(arr(q)).to_vec())")
                } else {
                    "None".to_owned()
                }
            };
            let (tip_poses, tip_positions) = match tips {
                0 => ("None".to_owned(), "None".to_owned()),
                1 => (
                    format!("Some(|q| vec![{ty}::tip_pose{suffix}(arr(q))])"),
                    if robot.positions {
                        format!("Some(|q| vec![{ty}::tip_position{suffix}(arr(q))])")
                    } else {
                        "None".to_owned()
                    },
                ),
                _ => (format!("Some(|q| {ty}::tip_poses{suffix}(arr(q)).to_vec())"), position("tip_positions")),
            };
            let tip_batch = match tips {
                0 => "None".to_owned(),
                1 => format!(
                    "Some(|qs| batch(qs, {ty}::tip_pose_batch{suffix}).map(|v| v.into_iter().map(|p| vec![p]).collect()))"
                ),
                _ => format!(
                    "Some(|qs| batch(qs, {ty}::tip_poses_batch{suffix}).map(|v| v.into_iter().map(|p| p.to_vec()).collect()))"
                ),
            };
            let tip_lanes = match tips {
                0 => "None".to_owned(),
                1 => format!("Some(|qs| lanes::<{lanes}, _, _>(qs, |q| [{ty}::tip_pose_generic(q)]))"),
                _ => format!("Some(|qs| lanes::<{lanes}, _, _>(qs, {ty}::tip_poses_generic))"),
            };
            let link_batch = format!(
                "|qs| batch(qs, {ty}::link_poses_batch{suffix}).map(|v| v.into_iter().map(|p| p.to_vec()).collect())"
            );
            let link_lanes = format!("|qs| lanes::<{lanes}, _, _>(qs, {ty}::link_poses_generic)");
            format!(
                "Some(Typed::<{t}> {{ link_poses: |q| {ty}::link_poses{suffix}(arr(q)).to_vec(), link_positions: {}, tip_poses: {tip_poses}, tip_positions: {tip_positions}, link_poses_batch: {link_batch}, tip_poses_batch: {tip_batch}, link_poses_lanes: {link_lanes}, tip_poses_lanes: {tip_lanes} }})",
                position("link_positions")
            )
        };
        writeln!(
            registry,
            "RandomRobot {{ name: {:?}, file: {:?}, trig: {trig:?}, text: {text_expr}, consts: TraitConsts {{ robot: {ty}::ROBOT, base: {ty}::BASE, dof: {ty}::DOF, joint_names: &{ty}::JOINT_NAMES, joint_limits: &{ty}::JOINT_LIMITS, links: &{ty}::LINK_NAMES, tips: &{ty}::TIPS }}, f64: {}, f32: {}, tip_poses_into: <{ty} as ::kinematics::Kinematics>::tip_poses_into, link_poses_into: <{ty} as ::kinematics::Kinematics>::link_poses_into, reference: {ty}::reference, trait_reference: <{ty} as ::kinematics::ReferenceModel>::reference, trait_consts: trait_consts::<{ty}>, velocities: {} }},",
            robot.name,
            robot.file,
            typed(robot.f64, "", "f64"),
            typed(robot.f32, "_f32", "f32"),
            if velocities {
                velocity_entry(&ty, robot.tips.len(), tree.dof(), tree.velocity_dof())
            } else {
                "None".to_owned()
            },
        )?;
    }
    writeln!(
        code,
        "/// The random robots, in the order of the generated set.\npub const RANDOM: &[RandomRobot] = &[{registry}];"
    )?;
    std::fs::write(out.join("random_robots.rs"), code)?;
    Ok(())
}

/// The registry entry of a random robot's velocity functions (`k` tips, `n` entries of `q`, `nv`
/// velocities).
fn velocity_entry(ty: &str, k: usize, n: usize, nv: usize) -> String {
    let d = format!("dual::Dual<{nv}>");
    if k == 1 {
        format!(
            "Some(Velocities {{ jacobians: |q| vec![columns({ty}::tip_jacobian(arr(q)))], jacobians_local: |q| vec![columns({ty}::tip_jacobian_local(arr(q)))], \
             poses_and_jacobians: |q| {{ let (p, j) = {ty}::tip_pose_and_jacobian(arr(q)); vec![(p, columns(j))] }}, \
             twists: |q, qd| vec![{ty}::tip_twist(arr(q), arr(qd))], twists_local: |q, qd| vec![{ty}::tip_twist_local(arr(q), arr(qd))], \
             by_duals: |q, d| vec![dual::jacobian::<{n}, {nv}>({ty}::tip_pose_generic::<{d}>, q, d)] }})"
        )
    } else {
        format!(
            "Some(Velocities {{ jacobians: |q| {ty}::tip_jacobians(arr(q)).into_iter().map(columns).collect(), jacobians_local: |q| {ty}::tip_jacobians_local(arr(q)).into_iter().map(columns).collect(), \
             poses_and_jacobians: |q| {ty}::tip_poses_and_jacobians(arr(q)).into_iter().map(|(p, j)| (p, columns(j))).collect(), \
             twists: |q, qd| {ty}::tip_twists(arr(q), arr(qd)).to_vec(), twists_local: |q, qd| {ty}::tip_twists_local(arr(q), arr(qd)).to_vec(), \
             by_duals: |q, d| dual::jacobians::<{n}, {nv}, {k}>({ty}::tip_poses_generic::<{d}>, q, d) }})"
        )
    }
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
