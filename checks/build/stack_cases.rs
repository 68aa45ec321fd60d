//! `OUT_DIR/stack.rs`: every robot in `robots/` derived with every option it takes, and a case
//! calling each function the derive wrote, for `tests/debug_stack.rs` to run on a small stack.
//!
//! Per robot: the derive of `derived.rs` (every leaf a tip, with positions) for the links' and the
//! tips' functions, and up to four structs more, each with cases for the functions it adds: the
//! deepest link's velocities (Jacobians and twists), its inverse kinematics (the closed form where
//! a family takes the chain, for seven joints with the third joint given, else the numeric
//! solver), the collision checks (where the `<collision>` geometry can be covered), and the
//! dynamics (where the inertias keep a rigid body's rules). Which options a robot takes is what
//! the compiler's own rules say (`Options::check`), so a robot added to `robots/` is covered as it
//! is.
//!
//! The functions are the API surface the emitter writes (`kinematics_compiler::robot::surface`),
//! listed by the same code the emitter and the derive's stub use; the arguments of each are
//! made here, by an exhaustive match on what the function is, so a function added to the surface
//! does not compile here until it has a case. Each case is its own closure (one stack frame), and
//! the test runs each on a thread of its own.

use std::fmt::Write as _;

use kinematics_compiler::dynamics::{DynamicsFunction, DynamicsRequest};
use kinematics_compiler::options::{CheckedIk, CollisionOptions, IkMode, Options, Scalars};
use kinematics_compiler::robot::surface::{
    CollisionFunction, Dims, Form, IkFunction, IkItem, IkShape, Output, Render, outputs,
};
use kinematics_model::{JointMotion, KinematicTree, LinkId};

/// What the cases of one derived struct are built from.
struct Derived<'a> {
    /// The struct's name.
    ty: String,
    /// `robots/` file, for the case's name.
    file: &'a str,
    /// Joints (entries of `q`) and velocities (of `qd`).
    dof: usize,
    velocities: usize,
}

/// Appends the structs and the cases of the robot `file` (its attribute's source key `source`)
/// to `structs` and `cases`.
pub fn write(
    file: &str,
    module: &str,
    source: &str,
    tree: &KinematicTree,
    structs: &mut String,
    cases: &mut String,
) -> Result<(), Box<dyn std::error::Error>> {
    let both = Scalars { f64: true, f32: true };
    let sets = option_sets(module, tree, both);
    for (ty, options, keys, cased) in sets {
        let checked = options.check(tree).map_err(|e| format!("{file}: {e}"))?;
        if let Some(keys) = keys {
            writeln!(
                structs,
                "/// `robots/{file}`: {keys}.\n#[derive(::kinematics::Kinematics)]\n#[kinematics({source}, {keys}, \
                 scalars(f64, f32))]\n#[allow(non_camel_case_types)]\npub struct {ty};"
            )?;
        }
        let derived = Derived { ty, file, dof: tree.dof(), velocities: tree.velocity_dof() };
        // The value a function holds in its widest lanes (one pack of a batch's outputs, a
        // generic function's `F64x8` value): the generic signature on those lanes, with the
        // robot's lengths.
        let dims = Dims {
            dof: Some(tree.dof()),
            velocities: Some(tree.velocity_dof()),
            links: Some(tree.links().len() - 1),
            tips: Some(options.tips.len()),
            spheres: checked.collision().map(|c| c.spheres.len()),
            held_words: None,
            forces: 0,
        };
        let render = Render {
            p: "::kinematics::__private".parse()?,
            scalars: both,
            scalar: "T".parse()?,
            trig: options.trig,
            dims,
        };
        let one_tip = options.tips.len() == 1;
        let on = |lanes: &str| -> Result<Render, Box<dyn std::error::Error>> {
            Ok(Render { scalar: lanes.parse()?, dims, ..render.clone() })
        };
        let (wide, wide32) = (on("::kinematics::F64x8")?, on("::kinematics::F32x8")?);
        for output in cased {
            let value = |render: &Render| {
                let generic = render.functions(output, one_tip).pop().map(|(_, s)| s.output);
                generic.map_or_else(|| "()".to_owned(), |ty| ty.to_string())
            };
            for (form, signature) in render.functions(output, one_tip) {
                let name = signature.name.to_string();
                let value = match &form {
                    Form::Typed(_) => signature.output.to_string(),
                    Form::Batch(s) | Form::Columns(s) if s.suffix == "_f32" => value(&wide32),
                    Form::Batch(_) | Form::Columns(_) | Form::Generic => value(&wide),
                };
                let call = output_call(&derived, output, one_tip, &form, &name);
                derived.case((structs, cases), &name, &value, &call)?;
            }
        }
        let plan = match checked.ik() {
            CheckedIk::ClosedForm(plan) => Some(plan.as_ref()),
            _ => None,
        };
        if let Some(shape) = IkShape::implied(&options, plan) {
            for item in render.ik_items(&shape) {
                if let IkItem::Function(function, signature) = item {
                    let name = signature.name.to_string();
                    let free = shape.closed_form.is_some_and(|c| c.free);
                    derived.case((structs, cases), &name, "()", &ik_call(&derived, function, &name, free))?;
                }
            }
        }
        if options.collision.is_some() {
            for (function, form, signature) in render.collision_items() {
                let name = signature.name.to_string();
                derived.case((structs, cases), &name, "()", &collision_call(&derived, function, &form, &name))?;
            }
        }
    }
    Ok(())
}

/// One struct's derive and cases: its name, options, attribute keys (`None`: the derive of
/// `derived.rs`, not derived again) and the outputs whose functions get cases.
type OptionSet = (String, Options, Option<String>, Vec<Output>);

/// The structs of the robot `tree` (`module`: its name in identifiers): the derive of
/// `derived.rs` for the links and tips, then one struct per option that adds functions, each with
/// cases for what it adds, where the compiler's rules take the option.
fn option_sets(module: &str, tree: &KinematicTree, both: Scalars) -> Vec<OptionSet> {
    let leaves: Vec<String> = tree.leaves().map(|l| tree.link(l).name.clone()).collect();
    let deepest = (0..tree.links().len()).map(LinkId).max_by_key(|&l| (tree.depth(l), l)).unwrap_or(tree.root());
    let deepest = tree.link(deepest).name.clone();
    // (struct, options, its attribute's keys, the outputs whose functions get cases): the
    // derive of `derived.rs` for the links and tips (not derived again here), then one struct per
    // option that adds functions, each with cases for what it adds.
    let mut sets: Vec<OptionSet> = Vec::new();
    let fk = Options { tips: leaves.clone(), positions: true, scalars: both, ..Options::default() };
    let fk_outputs = outputs(&fk);
    sets.push((format!("crate::Derived_{module}_file"), fk, None, fk_outputs));
    // The velocities of the deepest link (one tip: a Jacobian of every leaf of a humanoid is
    // minutes of compile time, and the same code per tip).
    let tip = vec![deepest.clone()];
    let velocities =
        Options { tips: tip.clone(), positions: true, jacobians: true, scalars: both, ..Options::default() };
    let added = outputs(&velocities)
        .into_iter()
        .filter(|o| {
            matches!(o, Output::Jacobian(_) | Output::PoseAndJacobian | Output::PositionJacobian | Output::Twist(_))
        })
        .collect();
    sets.push((
        format!("StackVelocities_{module}"),
        velocities,
        Some(format!("tip = {deepest:?}, positions, jacobians")),
        added,
    ));
    // The inverse: the closed form, with the third joint given for seven joints, else numeric.
    let third = tree.joints().iter().filter(|j| j.kind.positions() > 0).nth(2).map(|j| j.name.clone());
    let mut tries = vec![(IkMode::ClosedForm { free: None }, "ik".to_owned())];
    if let Some(third) = third {
        let key = format!("ik(free = {third:?})");
        tries.push((IkMode::ClosedForm { free: Some(third) }, key));
    }
    tries.push((IkMode::Numeric, "ik = \"numeric\"".to_owned()));
    for (ik, key) in tries {
        let options = Options { tips: tip.clone(), ik, scalars: both, ..Options::default() };
        if options.check(tree).is_ok() {
            sets.push((format!("StackIk_{module}"), options, Some(format!("tip = {deepest:?}, {key}")), Vec::new()));
            break;
        }
    }
    let collision = Options { collision: Some(CollisionOptions::default()), scalars: both, ..Options::default() };
    if collision.check(tree).is_ok() {
        sets.push((
            format!("StackCollision_{module}"),
            collision,
            Some("collision".to_owned()),
            vec![Output::SphereCenters],
        ));
    }
    // The dynamics with an external force on the deepest link a joint moves.
    let moved = tree.links().iter().enumerate().rev().find(|(i, _)| {
        tree.path_from_root(LinkId(*i)).iter().any(|&j| !matches!(tree.joint(j).motion, JointMotion::Fixed))
    });
    if let Some((_, link)) = moved {
        let request = DynamicsRequest { forces: vec![link.name.clone()], ..DynamicsRequest::default() };
        let dynamics = Options { dynamics: Some(request), scalars: both, ..Options::default() };
        if dynamics.check(tree).is_ok() {
            let functions =
                DynamicsFunction::ALL.into_iter().chain(DynamicsFunction::WITH_FORCES).map(Output::Dynamics).collect();
            let keys = format!("dynamics(forces({:?}))", link.name);
            sets.push((format!("StackDynamics_{module}"), dynamics, Some(keys), functions));
        }
    }
    sets
}

impl Derived<'_> {
    /// One case: `body` (statements ending in a value) run by a closure of its own.
    fn case(
        &self,
        (items, cases): (&mut String, &mut String),
        name: &str,
        value: &str,
        body: &str,
    ) -> std::fmt::Result {
        let (file, ty) = (self.file, &self.ty);
        // A function item each, not a closure in the list: closures are type-checked with the item
        // holding them, and one list of two thousand took minutes.
        let index = cases.lines().count();
        writeln!(items, "fn case_{index}() {{ {} {body} }}", self.inputs())?;
        writeln!(
            cases,
            "StackCase {{ robot: {file:?}, function: \"{ty}::{name}\", value: ::core::mem::size_of::<{value}>(), run: \
             case_{index} }},"
        )
    }

    /// The inputs every case may use: `q` and `qd` in each scalar type, a batch of 17 (two
    /// packs of eight and one more) of each, the configurations' columns, and lanes (`F64x8`: the
    /// widest lanes, 64 bytes a value like `F32x16`'s, so the most stack a body can take).
    fn inputs(&self) -> String {
        let (n, nv) = (self.dof, self.velocities);
        format!(
            "let q: [f64; {n}] = ::core::array::from_fn(|j| 0.1 + 0.2 * j as f64); \
             let q32: [f32; {n}] = q.map(|x| x as f32); \
             let qd: [f64; {nv}] = [0.3; {nv}]; let qd32: [f32; {nv}] = [0.3; {nv}]; \
             let qs = vec![q; 17]; let qs32 = vec![q32; 17]; let qds = vec![qd; 17]; let qds32 = vec![qd32; 17]; \
             let cols: Vec<Vec<f64>> = (0..{n}).map(|j| vec![q[j]; 17]).collect(); \
             let cols32: Vec<Vec<f32>> = (0..{n}).map(|j| vec![q32[j]; 17]).collect(); \
             let columns: [&[f64]; {n}] = ::core::array::from_fn(|j| cols[j].as_slice()); \
             let columns32: [&[f32]; {n}] = ::core::array::from_fn(|j| cols32[j].as_slice()); \
             let lanes: [::kinematics::F64x8; {n}] = q.map(::kinematics::F64x8::splat); \
             let qd_lanes: [::kinematics::F64x8; {nv}] = qd.map(::kinematics::F64x8::splat); \
             let forces = [[0.5f64; 6]; 1]; let forces32 = [[0.5f32; 6]; 1]; \
             let forcess = vec![forces; 17]; let forcess32 = vec![forces32; 17]; \
             let forces_lanes = [[::kinematics::F64x8::splat(0.5); 6]; 1]; \
             let _ = (&q, &q32, &qd, &qd32, &qs, &qs32, &qds, &qds32, &columns, &columns32, &lanes, &qd_lanes); \
             let _ = (&forces, &forces32, &forcess, &forcess32, &forces_lanes);"
        )
    }
}

/// The arguments a function of `form` takes in its scalar type: `(q, qs, columns, qd, qds)`.
fn scalar_inputs(form: &Form) -> (&'static str, &'static str, &'static str, &'static str, &'static str) {
    match form {
        Form::Typed(s) | Form::Batch(s) | Form::Columns(s) if s.suffix == "_f32" => {
            ("q32", "qs32", "columns32", "qd32", "qds32")
        }
        _ => ("q", "qs", "columns", "qd", "qds"),
    }
}

/// A call of an output's function `name` of `form` (the rates `qd` its third argument too, `qdd`
/// or `tau`, where it takes one).
fn output_call(d: &Derived<'_>, output: Output, one_tip: bool, form: &Form, name: &str) -> String {
    let ty = &d.ty;
    let (q, qs, columns, qd, qds) = scalar_inputs(form);
    let rates = output.takes_rates();
    // The third argument (the rates again, as `qdd` or `tau`) and, with forces, the one link's.
    let forces = |name: &str| if output.takes_forces() { format!(", &{name}") } else { String::new() };
    let f32_form = matches!(form, Form::Typed(s) | Form::Batch(s) if s.suffix == "_f32");
    let (force, force_rows) = if f32_form { ("forces32", "forcess32") } else { ("forces", "forcess") };
    let third_only =
        |rates: &str| if output.third_argument().is_some() { format!(", &{rates}") } else { String::new() };
    // Given a batch's rows of rates (`qds`, `qds32`), a batch's rows of forces.
    let third = |rates: &str| {
        let rows = rates.starts_with("qds");
        format!("{}{}", third_only(rates), forces(if rows { force_rows } else { force }))
    };
    match form {
        Form::Typed(_) if rates => {
            let third = third(qd);
            format!("let value = {ty}::{name}(&{q}, &{qd}{third}); ::std::hint::black_box(&value);")
        }
        // A batch of rows of `q`, `qd` (and the rates again as `qdd` or `tau`). Forward dynamics
        // may refuse a robot's configuration (a joint moving no mass): its answer is kept, not
        // expected to be `Ok`.
        Form::Batch(s) if rates => {
            let typed = format!("{}{}", output.name(one_tip), s.suffix);
            let one = format!("{ty}::{typed}(&{q}, &{qd}{})", third(qd));
            let call = format!("{ty}::{name}(&{qs}, &{qds}{}, &mut out)", third(qds));
            if output.is_forward() {
                let nv = d.velocities;
                format!(
                    "let mut out = vec![{one}.unwrap_or([0.0; {nv}]); 17]; let result = {call}; \
                     ::std::hint::black_box((&out, &result));"
                )
            } else {
                format!("let mut out = vec![{one}; 17]; {call}.expect(\"17 outputs\"); ::std::hint::black_box(&out);")
            }
        }
        Form::Typed(_) => format!("let value = {ty}::{name}(&{q}); ::std::hint::black_box(&value);"),
        Form::Batch(s) | Form::Columns(s) => {
            let typed = format!("{}{}", output.name(one_tip), s.suffix);
            let input = if matches!(form, Form::Batch(_)) { format!("&{qs}") } else { columns.to_owned() };
            format!(
                "let mut out = vec![{ty}::{typed}(&{q}); 17]; {ty}::{name}({input}, &mut out).expect(\"17 outputs\"); \
                 ::std::hint::black_box(&out);"
            )
        }
        Form::Generic if rates => {
            let third = format!("{}{}", third_only("qd_lanes"), forces("forces_lanes"));
            format!("let value = {ty}::{name}(&lanes, &qd_lanes{third}); ::std::hint::black_box(&value);")
        }
        Form::Generic => format!("let value = {ty}::{name}(&lanes); ::std::hint::black_box(&value);"),
    }
}

/// A call of the inverse kinematics' function `name`, on the pose of `q`.
fn ik_call(d: &Derived<'_>, function: IkFunction, name: &str, free: bool) -> String {
    let ty = &d.ty;
    let pose = format!("let target = {ty}::tip_pose(&q);");
    let free = if free { ", 0.3" } else { "" };
    let call = match function {
        IkFunction::All | IkFunction::WithinLimits => format!("{ty}::{name}(&target{free})"),
        IkFunction::Branch => format!(
            "{ty}::{name}(&::kinematics::ik::splat_pose::<::kinematics::F64x8>(&target), &::kinematics::ik::BRANCH_SIGNS_8)"
        ),
        IkFunction::Nearest | IkFunction::Numeric => format!("{ty}::{name}(&target, &q)"),
        IkFunction::NumericWith => {
            format!("{ty}::{name}(&target, &q, &::kinematics::ik::NumericOptions::default())")
        }
    };
    format!("{pose} let value = {call}; ::std::hint::black_box(&value);")
}

/// A call of the collision check `name` of `form`, in a scene of a ball and a box near the robot
/// (every test a check can reach: bounds, groups, spheres, obstacles of two kinds).
fn collision_call(d: &Derived<'_>, function: CollisionFunction, form: &Form, name: &str) -> String {
    let ty = &d.ty;
    let (q, qs, columns, _, _) = scalar_inputs(form);
    let scene = "let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]; \
         let balls = [::kinematics::collision::SphereObstacle { center: [0.3, 0.1, 0.4], radius: 0.1 }]; \
         let boxes = [::kinematics::collision::BoxObstacle::from_pose(identity, [0.5, 0.0, 0.2], [0.2, 0.3, 0.4])]; \
         let env = ::kinematics::collision::Environment::new(&balls, &[], &[], &boxes).expect(\"a valid scene\"); \
         let _ = &env;";
    let world = if matches!(function, CollisionFunction::SelfCollides | CollisionFunction::SelfCollidesAny) {
        ""
    } else {
        ", &env"
    };
    let call = match (function, form) {
        (CollisionFunction::Collides | CollisionFunction::SelfCollides, Form::Typed(_)) => {
            format!("let value = {ty}::{name}(&{q}{world}); ::std::hint::black_box(&value);")
        }
        (CollisionFunction::Collides | CollisionFunction::SelfCollides, Form::Batch(_) | Form::Columns(_)) => {
            let input = if matches!(form, Form::Batch(_)) { format!("&{qs}") } else { columns.to_owned() };
            format!(
                "let mut out = vec![false; 17]; {ty}::{name}({input}{world}, &mut out).expect(\"17 verdicts\"); \
                 ::std::hint::black_box(&out);"
            )
        }
        (CollisionFunction::Collides | CollisionFunction::SelfCollides, Form::Generic) => {
            format!("let value = {ty}::{name}(&lanes{world}); ::std::hint::black_box(&value);")
        }
        (CollisionFunction::CollidesAny | CollisionFunction::SelfCollidesAny, Form::Generic) => {
            format!("let value = {ty}::{name}(&lanes{world}); ::std::hint::black_box(&value);")
        }
        (CollisionFunction::CollidesAny | CollisionFunction::SelfCollidesAny, _) => {
            format!("let value = {ty}::{name}(&{qs}{world}); ::std::hint::black_box(&value);")
        }
        (CollisionFunction::MotionCollides | CollisionFunction::MotionCollidesAny, Form::Batch(_)) => {
            let zero = if q == "q32" { "0.0f32" } else { "0.0f64" };
            let none = if function == CollisionFunction::MotionCollides { "None" } else { "false" };
            format!(
                "let motions = vec![({q}, {q}.map(|x| -x + {zero})); 9]; let mut out = vec![{none}; 9]; \
                 {ty}::{name}(&motions, &env, 0.05, &mut out).expect(\"9 motions\"); ::std::hint::black_box(&out);"
            )
        }
        (CollisionFunction::MotionCollides | CollisionFunction::MotionCollidesAny, _) => {
            format!(
                "let value = {ty}::{name}(&{q}, &{q}.map(|x| -x), &env, 0.05).expect(\"a resolution\"); ::std::hint::black_box(&value);"
            )
        }
        (CollisionFunction::Hold, _) => format!(
            "let held = {ty}::{name}({ty}::SPHERE_LINKS[{ty}::SPHERE_LINKS.len() - 1], &balls, &[]).expect(\"a link \
             with spheres\"); let value = {ty}::collides(&q, &env.holding(&held)); ::std::hint::black_box(&value);"
        ),
        (
            CollisionFunction::Clearance
            | CollisionFunction::ClearanceGradient
            | CollisionFunction::ProximityCost
            | CollisionFunction::ProximityCostGradient,
            _,
        ) => {
            let margin =
                if matches!(function, CollisionFunction::ProximityCost | CollisionFunction::ProximityCostGradient) {
                    ", 0.05"
                } else {
                    ""
                };
            let input = if matches!(form, Form::Generic) { "lanes" } else { q };
            format!("let value = {ty}::{name}(&{input}, &env{margin}); ::std::hint::black_box(&value);")
        }
    };
    format!("{scene} {call}")
}
