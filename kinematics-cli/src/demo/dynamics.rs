//! Step 8 of `kinematics demo`: the dynamics from the links' inertias. What each compiled function
//! costs; the compiled expressions against the runtime reference (`ReferenceDynamics`) as `check
//! --dynamics` measures them; and for the built-in UR5 (whose generated dynamics `build.rs`
//! compiled into this binary) the generated code's agreement and a timing of each function
//! against the reference.

use std::hint::black_box;
use std::io::Write;

use kinematics::model::KinematicTree;
use kinematics::runtime::ReferenceDynamics;
use kinematics_compiler::dynamics::{DynamicsFunction, DynamicsRequest};

use super::{Args, per_call, thousands};
use crate::agreement::{Configurations, TOLERANCE};
use crate::dynamics::{Evaluated, Graphs, Report, Subject};
use crate::error::CliError;
use crate::ur5::Ur5;

/// The most states compared with the reference.
const SAMPLES: usize = 1_000;

/// Runs the step on `tree` (`built_in`: the UR5 whose generated code this binary holds).
pub(super) fn run(
    args: &Args,
    out: &mut dyn Write,
    tree: &KinematicTree,
    file: &str,
    built_in: bool,
) -> Result<(), CliError> {
    writeln!(
        out,
        "\n8. Dynamics from the links' inertias (`kinematics expr --dynamics`, `kinematics check --dynamics`)\n"
    )?;
    let request = DynamicsRequest::default();
    let compiled = match crate::dynamics::compile(tree, file, &request, &DynamicsFunction::ALL) {
        Ok(compiled) => compiled,
        // A robot without masses (or with an inertia no rigid body has) has no dynamics to show.
        Err(CliError::Options { faults, .. }) => {
            for fault in faults {
                writeln!(out, "  not compiled: {fault}")?;
            }
            return Ok(());
        }
        Err(e) => return Err(e),
    };
    writeln!(
        out,
        "  gravity {} m/s^2 in `{}`'s frame; what each generated function computes:\n",
        crate::dynamics::vector_text(request.gravity),
        tree.link(tree.root()).name
    )?;
    write!(out, "{}", crate::dynamics::op_table(&compiled))?;
    out.flush()?;

    let reference = crate::dynamics::reference(tree, file, &request)?;
    let samples = args.samples.min(SAMPLES);
    writeln!(
        out,
        "\n  against the runtime reference (ReferenceDynamics: Featherstone's algorithms on nalgebra), {} states:",
        thousands(samples)
    )?;
    let graphs = crate::dynamics::compare(tree, file, &reference, &Graphs(&compiled), &[], samples)?;
    writeln!(out, "  compiled expressions:                 {}", largest(&graphs))?;
    if built_in {
        let generated = crate::dynamics::compare(tree, file, &reference, &Generated, &[], samples)?;
        writeln!(out, "  generated Rust in this binary (Ur5):  {}", largest(&generated))?;
    }
    writeln!(
        out,
        "  (each function's values x their scale, forward dynamics as M (qdd - qdd_ref) x the torques'; tolerance \
         {TOLERANCE:e})"
    )?;
    if !built_in {
        writeln!(
            out,
            "\n  generated code: not timed. This binary holds generated dynamics for the UR5 only; for this robot,\n  \
             `kinematics generate {file} --dynamics` or the derive's `dynamics` key in your crate."
        )?;
        return Ok(());
    }
    timing(args, out, tree, &reference)
}

/// `largest error 2.30e-14 (`inverse_dynamics`)`.
fn largest(report: &Report) -> String {
    match crate::dynamics::worst(report) {
        Some((function, error)) => format!("largest error {error:.2e} (`{}`)", function.name()),
        None => "nothing compared".to_owned(),
    }
}

/// Each function of the built-in UR5, the reference's and the generated code's.
fn timing(
    args: &Args,
    out: &mut dyn Write,
    tree: &KinematicTree,
    reference: &ReferenceDynamics,
) -> Result<(), CliError> {
    // The reference allocates and walks the tree per call: a tenth of the evaluations is plenty.
    let (slow, fast) = ((args.evaluations / 10).max(1), (args.evaluations / 2).max(1));
    writeln!(
        out,
        "\n  Timing: {} evaluations of the reference, {} of the generated code, per function; inputs precomputed,\n  \
         results through black_box\n",
        thousands(slow),
        thousands(fast)
    )?;
    out.flush()?;
    let states: Vec<([f64; Ur5::DOF], [f64; Ur5::DOF], [f64; Ur5::DOF])> = Configurations::new(tree)
        .take(1024)
        .enumerate()
        .filter_map(|(i, q)| {
            let q: [f64; Ur5::DOF] = q.as_slice().try_into().ok()?;
            // Rates and accelerations of a few rad/s, different per state.
            let v = std::array::from_fn(|j| ((i * 7 + j * 3) % 11) as f64 * 0.4 - 2.0);
            let a = std::array::from_fn(|j| ((i * 5 + j * 7) % 13) as f64 * 0.3 - 1.8);
            Some((q, v, a))
        })
        .collect();
    let n = states.len().max(1);
    let torques: Vec<[f64; Ur5::DOF]> = states.iter().map(|(q, v, a)| Ur5::inverse_dynamics(q, v, a)).collect();
    for function in DynamicsFunction::ALL {
        let reference_ns = per_call(slow, |i| {
            let (q, v, a) = &states[i % n];
            let _ = black_box(match function {
                DynamicsFunction::Gravity => reference.gravity_torques(black_box(q)),
                DynamicsFunction::InverseDynamics => reference.inverse_dynamics(black_box(q), v, a),
                DynamicsFunction::NonlinearEffects => reference.nonlinear_effects(black_box(q), v),
                DynamicsFunction::MassMatrix => reference.mass_matrix(black_box(q)).map(|m| vec![m[(0, 0)]]),
                DynamicsFunction::ForwardDynamics => reference.forward_dynamics(black_box(q), v, &torques[i % n]),
                // Not in `ALL`: the built-in UR5 takes no external forces.
                DynamicsFunction::InverseDynamicsWithForces | DynamicsFunction::ForwardDynamicsWithForces => {
                    Ok(Vec::new())
                }
            });
        });
        let generated_ns = per_call(fast, |i| {
            let (q, v, a) = &states[i % n];
            match function {
                DynamicsFunction::Gravity => {
                    black_box(Ur5::gravity_torques(black_box(q)));
                }
                DynamicsFunction::InverseDynamics => {
                    black_box(Ur5::inverse_dynamics(black_box(q), v, a));
                }
                DynamicsFunction::NonlinearEffects => {
                    black_box(Ur5::nonlinear_effects(black_box(q), v));
                }
                DynamicsFunction::MassMatrix => {
                    black_box(Ur5::mass_matrix(black_box(q)));
                }
                DynamicsFunction::ForwardDynamics => {
                    let _ = black_box(Ur5::forward_dynamics(black_box(q), v, &torques[i % n]));
                }
                DynamicsFunction::InverseDynamicsWithForces | DynamicsFunction::ForwardDynamicsWithForces => {}
            }
        });
        let name = function.name();
        writeln!(
            out,
            "  {:<57}{reference_ns:>9.1} ns per call",
            format!("runtime reference, ReferenceDynamics::{name}:")
        )?;
        writeln!(
            out,
            "  {:<57}{generated_ns:>9.1} ns per call ({:.0}x faster)",
            format!("generated code, Ur5::{name}:"),
            reference_ns / generated_ns.max(1e-3)
        )?;
    }
    if cfg!(debug_assertions) {
        writeln!(out, "  (a debug build: run with `cargo run --release` for representative numbers)")?;
    }
    Ok(())
}

/// The generated dynamics of the built-in UR5, as the comparison takes them.
struct Generated;

impl Subject for Generated {
    fn eval(&self, function: DynamicsFunction, q: &[f64], qd: &[f64], input: &[f64]) -> Evaluated {
        let array = |x: &[f64]| -> [f64; Ur5::DOF] { std::array::from_fn(|i| x.get(i).copied().unwrap_or(f64::NAN)) };
        let (q, qd, input) = (array(q), array(qd), array(input));
        let values = match function {
            DynamicsFunction::Gravity => Ur5::gravity_torques(&q).to_vec(),
            DynamicsFunction::InverseDynamics => Ur5::inverse_dynamics(&q, &qd, &input).to_vec(),
            DynamicsFunction::NonlinearEffects => Ur5::nonlinear_effects(&q, &qd).to_vec(),
            DynamicsFunction::MassMatrix => Ur5::mass_matrix(&q).concat(),
            DynamicsFunction::ForwardDynamics => match Ur5::forward_dynamics(&q, &qd, &input) {
                Ok(a) => a.to_vec(),
                Err(kinematics::KinematicsError::SingularMassMatrix { velocity, .. }) => {
                    return Evaluated::Singular(vec![velocity.to_owned()]);
                }
                // Not finite: the comparison counts it as an infinite error.
                Err(_) => vec![f64::NAN; Ur5::DOF],
            },
            // The built-in UR5 takes no external forces, and is compared without them.
            DynamicsFunction::InverseDynamicsWithForces | DynamicsFunction::ForwardDynamicsWithForces => Vec::new(),
        };
        Evaluated::Values(values)
    }
}
