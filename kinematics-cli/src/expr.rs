//! `kinematics expr FILE`: the simplified symbolic pose of one link and what it costs, with
//! `--jacobian` its geometric Jacobian and what the velocity functions cost, with `--all` what
//! every link's pose adds to the all-links code (where the cost of a tree goes), or with
//! `--dynamics` the gravity torques and what the dynamics functions cost (`dynamics`).
//!
//! The listings are `emit::text_listing` and `latex_listing`; the cost is `op_count` against
//! `plain_product_count`.

use std::io::Write;

use kinematics::model::JacobianFrame;
use kinematics::model::KinematicTree;
use kinematics_compiler::dynamics::DynamicsFunction;
use kinematics_compiler::{Compiled, OpCount, Request, compile, plain_product_count};

use crate::error::CliError;

/// Arguments of `expr`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml), MJCF file (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
    /// The frame the pose is expressed in (default: the root link).
    #[arg(long)]
    base: Option<String>,
    /// The link whose pose is printed (default: the deepest link).
    #[arg(long, conflicts_with = "all")]
    tip: Option<String>,
    /// Print LaTeX instead of text.
    #[arg(long, conflicts_with = "all")]
    latex: bool,
    /// Compile the poses of every link (as the all-links function does) and print, per link, the
    /// operations its pose adds to those of the links listed before it.
    #[arg(long)]
    all: bool,
    /// Print the geometric Jacobian of the link instead of its pose, and the operation counts of
    /// every velocity function (Jacobian, pose and Jacobian, position Jacobian, twist).
    #[arg(long, conflicts_with = "all")]
    jacobian: bool,
    /// The axes of the Jacobian: the base's (`local-world-aligned`, Pinocchio's
    /// LOCAL_WORLD_ALIGNED) or the link's own (`local`).
    #[arg(long, value_enum, default_value = "local-world-aligned", requires = "jacobian")]
    frame: Frame,
    /// Print the link's closed-form inverse kinematics instead: its family, the subproblems it is
    /// composed of, and the geometry the compiler folds into it (or why no family applies).
    #[arg(long, conflicts_with_all = ["all", "jacobian", "latex"])]
    ik: bool,
    /// With `--ik`, the joint of a seven-joint arm whose value is given.
    #[arg(long, requires = "ik")]
    free: Option<String>,
    /// Print the gravity torques instead (the generalized forces that hold the robot still, from
    /// the links' inertias), one line per velocity, and the operation counts of every dynamics
    /// function (gravity torques, inverse dynamics, nonlinear effects, mass matrix, forward
    /// dynamics).
    #[arg(long, conflicts_with_all = ["all", "jacobian", "latex", "ik", "base", "tip"])]
    dynamics: bool,
    /// With `--dynamics`, only the torque of this velocity (a joint's name).
    #[arg(long, requires = "dynamics")]
    joint: Option<String>,
    /// With `--dynamics`: the gravity and how inertias are read.
    #[command(flatten)]
    dynamics_options: crate::dynamics::DynamicsArgs,
}

/// `--frame`.
#[derive(Clone, Copy, clap::ValueEnum)]
enum Frame {
    LocalWorldAligned,
    Local,
}

impl Frame {
    fn model(self) -> JacobianFrame {
        match self {
            Frame::LocalWorldAligned => JacobianFrame::LocalWorldAligned,
            Frame::Local => JacobianFrame::Local,
        }
    }
}

/// Prints the pose and its operation counts.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let tree = crate::robot::load(&args.file)?;
    if args.dynamics {
        let request = args.dynamics_options.request();
        write!(out, "{}", crate::dynamics::gravity_text(&tree, &args.file, &request, args.joint.as_deref())?)?;
        let compiled = crate::dynamics::compile(&tree, &args.file, &request, &DynamicsFunction::ALL)?;
        writeln!(out, "\noperations:")?;
        write!(out, "{}", crate::dynamics::op_table(&compiled))?;
        return Ok(());
    }
    if args.all {
        let (base, _) = crate::robot::base_and_tip(&tree, &args.file, args.base.as_deref(), None)?;
        // Every link's pose is compiled: minutes on a chain of thousands of joints.
        let spinner = crate::progress::spinner("compiling every link's pose");
        let table = all_links_table(&tree, &args.file, &base);
        spinner.finish_and_clear();
        write!(out, "{}", table?)?;
        return Ok(());
    }
    let (base, tip) = crate::robot::base_and_tip(&tree, &args.file, args.base.as_deref(), args.tip.as_deref())?;
    if args.ik {
        let plan = kinematics_compiler::ik::classify_with(&tree, &base, &tip, args.free.as_deref())
            .map_err(|source| CliError::compile(&args.file, source))?;
        let text = ik_text(&tree, &plan).map_err(|source| CliError::compile(&args.file, source))?;
        write!(out, "{text}")?;
        return Ok(());
    }
    if args.jacobian {
        let frame = args.frame.model();
        write!(out, "{}", jacobian_text(&tree, &args.file, &base, &tip, frame, args.latex)?)?;
        writeln!(out, "\noperations:")?;
        write!(out, "{}", op_table(&velocity_op_counts(&tree, &args.file, &base, &tip, frame)?))?;
        return Ok(());
    }
    write!(out, "{}", pose_text(&tree, &args.file, &base, &tip, args.latex)?)?;
    writeln!(out, "\noperations:")?;
    write!(out, "{}", op_table(&op_counts(&tree, &args.file, &base, &tip)?))?;
    Ok(())
}

/// A closed-form plan as text: family, subproblems, and per joint its axis and the offset to it
/// from the previous point.
fn ik_text(
    tree: &KinematicTree,
    plan: &kinematics_compiler::ik::IkPlan,
) -> Result<String, kinematics_compiler::CompileError> {
    let short = crate::inspect::short;
    let v = |v: &[f64; 3]| format!("({}, {}, {})", short(v[0]), short(v[1]), short(v[2]));
    let mut out = format!(
        "robot `{}`: inverse kinematics of `{}` in `{}`\nfamily: {}\nsubproblems (IK-Geo's numbering): {}\n",
        tree.name(),
        plan.tip,
        plan.base,
        plan.family().name(),
        plan.family().subproblems()
    );
    if let Some(free) = plan.free() {
        out += &format!(
            "free joint: `{}` (q[{}]), axis {} through {}\n",
            free.name,
            free.index,
            v(&free.axis),
            v(&free.point)
        );
    }
    match &plan.geometry {
        kinematics_compiler::ik::IkGeometry::Six { arm: six, .. } => {
            out += "geometry at q = 0 (base frame): joint, axis h, offset p from the previous point\n";
            let width = crate::inspect::column_width(plan.joints.iter().map(String::as_str));
            for (i, joint) in plan.joints.iter().enumerate() {
                out += &format!(
                    "  {}  h{} = {}  p{}{} = {}\n",
                    crate::inspect::pad(joint, width),
                    i + 1,
                    v(&six.axes[i]),
                    i,
                    i + 1,
                    v(&six.offsets[i])
                );
            }
            out += &format!(
                "  tool: p6T = {}, R6T rows {}\n",
                v(&six.offsets[6]),
                six.tool_rotation.iter().map(v).collect::<Vec<_>>().join(" ")
            );
        }
        kinematics_compiler::ik::IkGeometry::Planar(planar) => {
            out += &format!("geometry at q = 0 (base frame): every axis along {}\n", v(&planar.axis));
            let width = crate::inspect::column_width(plan.joints.iter().map(String::as_str));
            for (joint, (sign, point)) in plan.joints.iter().zip(&planar.joints) {
                let what = match point {
                    Some(point) => format!("revolute about {} h through {}", short(*sign), v(point)),
                    None => format!("prismatic along {} h", short(*sign)),
                };
                out += &format!("  {}  {what}\n", crate::inspect::pad(joint, width));
            }
            out += &format!("  tool: at {}\n", v(&planar.tip_point));
        }
    }
    for note in &plan.notes {
        out += &format!("note: {note}\n");
    }
    if plan.made_exact {
        out += "note: solved with these relations made exact; `tip_ik` refines its solutions on the arm as written\n";
    }
    out += &format!(
        "solutions: up to {} (every branch, exact or least-squares, flagged)\n",
        plan.family().max_solutions()
    );
    out += &emitted_ik_text(tree, plan)?;
    Ok(out)
}

/// An operation count without the kinds it has none of (`3 multiplications, 1 atan2`).
fn ik_count_text(count: &kinematics_compiler::OpCount) -> String {
    let parts: Vec<String> = [
        (count.sin_cos, "sin/cos pairs"),
        (count.mul, "multiplications"),
        (count.add, "additions"),
        (count.div, "divisions"),
        (count.sqrt, "square roots"),
        (count.atan2, "atan2"),
        (count.select, "selects"),
    ]
    .into_iter()
    .filter(|(n, _)| *n > 0)
    .map(|(n, what)| format!("{n} {what}"))
    .collect();
    if parts.is_empty() { "nothing".to_owned() } else { parts.join(", ") }
}

/// What the compiler emits for a plan: the straight-line body's subproblems with what each adds
/// to the operations before it, and the measure's cost; or the run time's function it calls.
fn emitted_ik_text(
    tree: &KinematicTree,
    plan: &kinematics_compiler::ik::IkPlan,
) -> Result<String, kinematics_compiler::CompileError> {
    let Some(body) = kinematics_compiler::ik::IkBody::of(plan) else {
        let why = if plan.free().is_some() {
            "its geometry is turned by the free joint at run time"
        } else if matches!(plan.geometry, kinematics_compiler::ik::IkGeometry::Planar(_)) {
            "a planar arm"
        } else {
            "its first step is a quartic, whose real roots an iteration finds"
        };
        return Ok(format!(
            "emitted: a call of the run time's `kinematics::ik::{}` with the geometry above as constants ({why}), \
             every solution measured by the generated pose\n",
            plan.family().solver()
        ));
    };
    let mut out = String::from(
        "emitted: one straight-line body computing one branch, run on F64x8 with the eight branches side by side \
         (one per lane), the geometry folded in as constants\noperations per branch, each step's beyond the steps \
         before it:\n",
    );
    let steps = body.step_counts();
    let width = steps.iter().map(|(label, _)| label.len()).max().unwrap_or(0);
    for (label, count) in &steps {
        out += &format!("  {label:<width$}  {}\n", ik_count_text(count));
    }
    out += &format!("  {:<width$}  {}\n", "total", ik_count_text(&body.op_count()));
    if let Some(regular) = kinematics_compiler::ik::IkBody::regular(plan) {
        out += &format!(
            "tip_ik runs the body without its pass at the wrist's singularity first ({}), and the whole body only \
             when a lane comes back singular and not exact\n",
            ik_count_text(&regular.op_count())
        );
    }
    let pose = kinematics_compiler::compile(tree, &kinematics_compiler::Request::tip(&plan.tip).with_base(&plan.base))?;
    out += &match kinematics_compiler::ik::Measure::of(&pose) {
        Some(measure) => format!(
            "measure: the generated pose at each joint's cosine and sine from the solver, per branch: {}\n",
            ik_count_text(&measure.op_count())
        ),
        None => "measure: the generated pose at q (an angle of the chain is no sum of joint values)\n".to_owned(),
    };
    Ok(out)
}

/// The 12 entries' names: the rotation row-major, then the translation.
const ENTRIES: [(&str, &str); 12] = [
    ("r11", "r_{11}"),
    ("r12", "r_{12}"),
    ("r13", "r_{13}"),
    ("r21", "r_{21}"),
    ("r22", "r_{22}"),
    ("r23", "r_{23}"),
    ("r31", "r_{31}"),
    ("r32", "r_{32}"),
    ("r33", "r_{33}"),
    ("x", "x"),
    ("y", "y"),
    ("z", "z"),
];

/// Compiles the pose of `tip` in `base` and the position alone.
pub fn compile_pose(tree: &KinematicTree, file: &str, base: &str, tip: &str) -> Result<(Compiled, Compiled), CliError> {
    let request = Request::tip(tip).with_base(base);
    let error = |source| CliError::compile(file, source);
    let pose = compile(tree, &request).map_err(error)?;
    let position = compile(tree, &request.positions_only()).map_err(error)?;
    Ok((pose, position))
}

/// The pose as text (or LaTeX) and the names it uses.
pub fn pose_text(tree: &KinematicTree, file: &str, base: &str, tip: &str, latex: bool) -> Result<String, CliError> {
    let (pose, _) = compile_pose(tree, file, base, tip)?;
    let mut out = format!("robot `{}`: pose of `{tip}` in `{base}`\n", tree.name());
    let joints: Vec<String> = pose.dof_names.iter().enumerate().map(|(i, n)| format!("q{} = {n}", i + 1)).collect();
    if !joints.is_empty() {
        out += &format!("joints: {}\n", joints.join(", "));
    }
    let legend = legend(&pose);
    if !legend.is_empty() {
        out += &format!("angles: {}\n", legend.join(", "));
    }
    out += "\n";
    // Shared subexpressions too long to repeat are printed once, as temporaries `t1, t2, ...`, so
    // the text stays linear in the size of the expression graph.
    let g = pose.graph();
    let names = kinematics_compiler::emit::Names::new(g, &pose.outputs()).with_sizes(pose.dof(), pose.velocity_dof());
    let outputs = pose.frame_outputs(0);
    if latex {
        let listing = kinematics_compiler::emit::latex_listing(g, &names, &outputs);
        out += "\\begin{aligned}\n";
        let rows: Vec<String> = listing
            .temporaries
            .iter()
            .map(|(name, definition)| format!("  {name} &= {definition}"))
            .chain(ENTRIES.iter().zip(listing.entries).map(|((_, name), entry)| format!("  {name} &= {entry}")))
            .collect();
        out += &rows.join(" \\\\\n");
        out += "\n\\end{aligned}\n";
    } else {
        let listing = kinematics_compiler::emit::text_listing(g, &names, &outputs);
        for (name, definition) in &listing.temporaries {
            out += &format!("{name:>3} = {definition}\n");
        }
        if !listing.temporaries.is_empty() {
            out += "\n";
        }
        for ((name, _), entry) in ENTRIES.iter().zip(listing.entries) {
            out += &format!("{name:>3} = {entry}\n");
        }
    }
    Ok(out)
}

/// The Jacobian of `tip` in `base` as text (or LaTeX): entries `J[row][column]`, rows `vx vy vz`
/// (the linear velocity of the tip's origin) then `wx wy wz` (the angular velocity), columns the
/// entries of `q`.
pub fn jacobian_text(
    tree: &KinematicTree,
    file: &str,
    base: &str,
    tip: &str,
    frame: JacobianFrame,
    latex: bool,
) -> Result<String, CliError> {
    let jacobian = compile(tree, &Request::tip(tip).with_base(base).jacobian(frame))
        .map_err(|source| CliError::compile(file, source))?;
    let mut out = format!("robot `{}`: geometric Jacobian of `{tip}` in `{base}` ({})\n", tree.name(), frame.name());
    let axes = match frame {
        JacobianFrame::LocalWorldAligned => format!("`{base}`'s axes"),
        JacobianFrame::Local => format!("`{tip}`'s own axes"),
    };
    out += &format!("rows: vx vy vz (velocity of the origin of `{tip}`), wx wy wz (angular velocity), in {axes}\n");
    let joints: Vec<String> = jacobian.dof_names.iter().enumerate().map(|(i, n)| format!("q{} = {n}", i + 1)).collect();
    if !joints.is_empty() {
        out += &format!("columns: {}\n", joints.join(", "));
    }
    let legend = legend(&jacobian);
    if !legend.is_empty() {
        out += &format!("angles: {}\n", legend.join(", "));
    }
    out += "\n";
    let g = jacobian.graph();
    let names = kinematics_compiler::emit::Names::new(g, &jacobian.outputs())
        .with_sizes(jacobian.dof(), jacobian.velocity_dof());
    let outputs = jacobian.frame_outputs(0);
    let n = jacobian.dof();
    let rows = ["vx", "vy", "vz", "wx", "wy", "wz"];
    let entry_names: Vec<String> =
        (0..outputs.len()).map(|k| format!("J[{}][q{}]", rows[k / n.max(1)], k % n.max(1) + 1)).collect();
    if latex {
        let listing = kinematics_compiler::emit::latex_listing(g, &names, &outputs);
        out += "\\begin{aligned}\n";
        let lines: Vec<String> = listing
            .temporaries
            .iter()
            .map(|(name, definition)| format!("  {name} &= {definition}"))
            .chain(entry_names.iter().zip(listing.entries).map(|(name, entry)| {
                format!("  J_{{{}}} &= {entry}", name.trim_start_matches("J[").replace("][", ",").trim_end_matches(']'))
            }))
            .collect();
        out += &lines.join(" \\\\\n");
        out += "\n\\end{aligned}\n";
    } else {
        let listing = kinematics_compiler::emit::text_listing(g, &names, &outputs);
        for (name, definition) in &listing.temporaries {
            out += &format!("{name:>3} = {definition}\n");
        }
        if !listing.temporaries.is_empty() {
            out += "\n";
        }
        for (name, entry) in entry_names.iter().zip(listing.entries) {
            out += &format!("{name} = {entry}\n");
        }
    }
    Ok(out)
}

/// The operation counts of the velocity functions of `tip` in `base`: the pose, the Jacobian in
/// `frame`, both together, the position Jacobian, the twist, and the twist had it been computed
/// as the Jacobian times the rates (`6n` multiplications and `6(n - 1)` additions more).
pub fn velocity_op_counts(
    tree: &KinematicTree,
    file: &str,
    base: &str,
    tip: &str,
    frame: JacobianFrame,
) -> Result<Vec<(String, OpCount)>, CliError> {
    let count = |request: Request| {
        compile(tree, &request.with_base(base)).map(|c| c.op_count()).map_err(|source| CliError::compile(file, source))
    };
    let n = tree.dof();
    let jacobian = count(Request::tip(tip).jacobian(frame))?;
    let formed = OpCount { mul: jacobian.mul + 6 * n, add: jacobian.add + 6 * n.saturating_sub(1), ..jacobian };
    let name = frame.name();
    Ok(vec![
        (format!("pose of {tip}"), count(Request::tip(tip))?),
        (format!("Jacobian of {tip} ({name})"), jacobian),
        (format!("pose and Jacobian of {tip}"), count(Request::tip(tip).pose_and_jacobian(frame))?),
        (format!("position Jacobian of {tip}"), count(Request::tip(tip).positions_only().jacobian(frame))?),
        (format!("twist of {tip} (J * qd, J not formed)"), count(Request::tip(tip).twist(frame))?),
        ("J * qd with J formed".to_owned(), formed),
    ])
}

/// The operation counts of the generated pose and position of `tip` and of the plain product of
/// the chain's transforms (zeros and ones folded, nothing else).
pub fn op_counts(tree: &KinematicTree, file: &str, base: &str, tip: &str) -> Result<Vec<(String, OpCount)>, CliError> {
    let (pose, position) = compile_pose(tree, file, base, tip)?;
    let plain = plain_product_count(tree, base, tip).map_err(|source| CliError::compile(file, source))?;
    Ok(vec![
        (format!("pose of {tip}, generated"), pose.op_count()),
        (format!("pose of {tip}, plain product"), plain),
        (format!("position of {tip}, generated"), position.op_count()),
    ])
}

/// The poses of every link but `base` compiled together (the all-links function's code), one row
/// per link: the joint it hangs from and the operations its pose adds to the rows above it
/// (a subexpression or `sin_cos` pair shared with an earlier link is counted there), then the
/// total, which the rows add up to.
pub fn all_links_table(tree: &KinematicTree, file: &str, base: &str) -> Result<String, CliError> {
    let compiled =
        compile(tree, &Request::all_links().with_base(base)).map_err(|source| CliError::compile(file, source))?;
    let counts = compiled.marginal_op_counts();
    let joint_of = |link: &str| {
        let joint = tree.link_by_name(link).and_then(|l| l.parent_joint).map(|j| tree.joint(j));
        joint.map_or_else(String::new, |j| {
            let how = match j.motion {
                kinematics::model::JointMotion::Fixed => "fixed",
                kinematics::model::JointMotion::Dof(_) => "moving",
                kinematics::model::JointMotion::Mimic { .. } => "mimic",
            };
            format!("{} ({how})", j.name)
        })
    };
    let rows: Vec<(String, String, OpCount)> = compiled
        .frames()
        .iter()
        .zip(counts)
        .map(|(frame, count)| (frame.link.clone(), joint_of(&frame.link), count))
        .collect();
    let mut out = format!(
        "robot `{}`: poses of all {} links in `{base}`; what each adds to the links above it\n\n",
        tree.name(),
        rows.len()
    );
    let link_width = crate::inspect::column_width(rows.iter().map(|(l, _, _)| l.as_str()).chain(["link", "total"]));
    let joint_width = crate::inspect::column_width(rows.iter().map(|(_, j, _)| j.as_str()).chain(["joint"]));
    let line = |link: &str, joint: &str, count: &OpCount| {
        let (link, joint) = (crate::inspect::pad(link, link_width), crate::inspect::pad(joint, joint_width));
        format!("  {link}  {joint}  {:>7} / {:>3} / {:>3}\n", count.sin_cos, count.mul, count.add)
    };
    out += &format!(
        "  {}  {}  sin_cos / mul / add\n",
        crate::inspect::pad("link", link_width),
        crate::inspect::pad("joint", joint_width)
    );
    for (link, joint, count) in &rows {
        out += &line(link, joint, count);
    }
    out += &line("total", "", &compiled.op_count());
    Ok(out)
}

/// Operation counts as aligned `sin_cos / mul / add` lines.
pub fn op_table(rows: &[(String, OpCount)]) -> String {
    let width = crate::inspect::column_width(rows.iter().map(|(what, _)| what.as_str()));
    let mut out = format!("  {}  sin_cos / mul / add\n", crate::inspect::pad("", width));
    for (what, count) in rows {
        let what = crate::inspect::pad(what, width);
        out += &format!("  {what}  {:>7} / {:>3} / {:>3}\n", count.sin_cos, count.mul, count.add);
    }
    out
}

/// `c23 = cos(q2 + q3)` and the like: the names of angles other than a single joint variable.
fn legend(compiled: &Compiled) -> Vec<String> {
    let g = compiled.graph();
    let names = kinematics_compiler::emit::Names::new(g, &compiled.outputs());
    names
        .angles()
        .filter(|&angle| !matches!(g.node(angle), kinematics_compiler::symbolic::graph::Node::Var(_)))
        .map(|angle| {
            let suffix = names.suffix(angle);
            format!("c{suffix}/s{suffix} = cos/sin({})", kinematics_compiler::emit::text(g, &names, angle))
        })
        .collect()
}
