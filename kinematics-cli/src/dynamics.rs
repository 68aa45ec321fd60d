//! `--dynamics`: the compiled dynamics of `generate`, `check` and `expr` (and `demo`'s step 8).
//!
//! The flags (`--gravity X,Y,Z`, `--inertia-as-written`) become the compiler's `DynamicsRequest`,
//! checked by the compiler's own option rule (`Options::check`: a finite gravity, some mass, every
//! inertia a rigid body's), whose faults name the flag, the link and the line as `generate`'s do.
//! `check` evaluates every compiled function's graph (`CompiledDynamics::eval`) against the runtime
//! reference (`ReferenceDynamics`) over the configurations `check` draws and random rates and
//! accelerations; `expr` prints the gravity torques as text.
//!
//! **The measure.** Per state, the largest difference of a function's entries over the scale of
//! the reference's values there (their largest magnitude, at least 1, as the workspace's dynamics
//! tests measure); forward dynamics in torque units: the mass matrix times the difference of the
//! accelerations, over the scale of the torques and the nonlinear effects, because the
//! accelerations themselves carry the mass matrix's conditioning. A NaN or an infinity is an
//! infinite error. A state where the mass matrix is singular must be refused by both (the
//! reference's `SingularMassMatrix`, a pivot of the compiled factorisation at most
//! `SINGULAR_RATIO` of the largest, as generated code refuses it): such states are counted, and
//! a refusal by one alone is an error.

use kinematics::model::KinematicTree;
use kinematics::runtime::{DynamicsError, ReferenceDynamics};
use kinematics_compiler::dynamics::{
    CompiledDynamics, DynamicsFunction, DynamicsRequest, STANDARD_GRAVITY, compile_dynamics,
};
use kinematics_compiler::emit::{Names, text_listing};
use kinematics_compiler::options::Options;
use kinematics_compiler::symbolic::graph::{ExprGraph, ExprId, Node};

use crate::agreement::{Configurations, TOLERANCE, worst_of};
use crate::error::{CliError, FlagFault};
use crate::generate::flag;

/// `--gravity` and `--inertia-as-written`, which go with a subcommand's own `--dynamics`.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct DynamicsArgs {
    /// With `--dynamics`: gravity in the root link's frame, m/s^2, three comma-separated numbers
    /// (default `0,0,-9.81`: z up).
    #[arg(long, value_name = "X,Y,Z", value_parser = gravity, allow_hyphen_values = true, requires = "dynamics")]
    pub gravity: Option<[f64; 3]>,
    /// With `--dynamics`: take inertia tensors that break the triangle inequality as written (real
    /// descriptions have them); they must still be positive semi-definite.
    #[arg(long, requires = "dynamics")]
    pub inertia_as_written: bool,
    /// With `--dynamics`: links external forces act on, comma-separated; `generate` adds
    /// `inverse_dynamics_with_forces` and `forward_dynamics_with_forces`, `check` compares them
    /// too.
    #[arg(long, value_name = "LINK,LINK", value_delimiter = ',', requires = "dynamics")]
    pub forces: Vec<String>,
}

impl DynamicsArgs {
    /// The compiler's request for these flags.
    pub fn request(&self) -> DynamicsRequest {
        DynamicsRequest {
            gravity: self.gravity.unwrap_or(STANDARD_GRAVITY),
            inertia_as_written: self.inertia_as_written,
            forces: self.forces.clone(),
        }
    }
}

/// `--gravity`'s value: three numbers, comma-separated. Whether they are finite is the compiler's
/// rule (its fault names the flag), so `nan` and `inf` are read here.
fn gravity(text: &str) -> Result<[f64; 3], String> {
    let values: Vec<f64> = text
        .split(',')
        .map(|x| x.trim().parse::<f64>().map_err(|e| format!("`{}`: {e}", x.trim())))
        .collect::<Result<_, _>>()?;
    <[f64; 3]>::try_from(values.as_slice())
        .map_err(|_| format!("three numbers are needed (X,Y,Z in m/s^2), not {}", values.len()))
}

/// Checks `request` against `tree` by the compiler's rule for the option: a fault is
/// [`CliError::Options`] naming `--gravity` or `--dynamics` and, for an inertia, the link and the
/// line of its `<inertial>`.
pub fn check_request(tree: &KinematicTree, file: &str, request: &DynamicsRequest) -> Result<(), CliError> {
    let options = Options { dynamics: Some(request.clone()), ..Options::default() };
    match options.check(tree) {
        Ok(_) => Ok(()),
        Err(rejected) => Err(CliError::Options {
            file: file.to_owned(),
            faults: rejected.faults.into_iter().map(|fault| FlagFault { flag: flag(fault.key), fault }).collect(),
        }),
    }
}

/// Checks the request, then compiles `functions`.
pub fn compile(
    tree: &KinematicTree,
    file: &str,
    request: &DynamicsRequest,
    functions: &[DynamicsFunction],
) -> Result<Vec<CompiledDynamics>, CliError> {
    check_request(tree, file, request)?;
    let spinner = crate::progress::spinner("compiling the dynamics");
    let compiled = functions.iter().map(|&f| compile_dynamics(tree, request, f)).collect::<Result<Vec<_>, _>>();
    spinner.finish_and_clear();
    compiled.map_err(|source| CliError::compile(file, source))
}

/// `(x, y, z)` with short numbers.
pub fn vector_text(v: [f64; 3]) -> String {
    let short = crate::inspect::short;
    format!("({}, {}, {})", short(v[0]), short(v[1]), short(v[2]))
}

/// What a subject of the comparison gives for one function at one state.
pub enum Evaluated {
    /// The function's values (the mass matrix row by row; forward dynamics' accelerations).
    Values(Vec<f64>),
    /// Forward dynamics refused a singular mass matrix (naming these velocities, when known).
    Singular(Vec<String>),
}

/// Something that computes the dynamics: the compiled graphs, or generated code (`demo`).
pub trait Subject {
    /// `function` at `q`, rates `qd` and its inputs `input`: its third argument (`qdd`, `tau`, or
    /// unused), then for the functions with external forces six per link, as
    /// `CompiledDynamics::eval` takes them.
    fn eval(&self, function: DynamicsFunction, q: &[f64], qd: &[f64], input: &[f64]) -> Evaluated;
}

/// The compiled graphs, one per function compared.
pub struct Graphs<'a>(pub &'a [CompiledDynamics]);

impl Subject for Graphs<'_> {
    fn eval(&self, function: DynamicsFunction, q: &[f64], qd: &[f64], input: &[f64]) -> Evaluated {
        let Some(compiled) = self.0.iter().find(|c| c.function == function) else {
            return Evaluated::Values(Vec::new());
        };
        let values = compiled.eval(q, qd, input);
        if !function.is_forward() {
            return Evaluated::Values(values);
        }
        let (accelerations, pivots) = values.split_at(compiled.velocity_dof());
        match singular_pivot(pivots) {
            Some(k) => Evaluated::Singular(vec![compiled.velocity_names[k].clone()]),
            None => Evaluated::Values(accelerations.to_vec()),
        }
    }
}

/// The first pivot of the mass matrix's factorisation at most `SINGULAR_RATIO` of the largest (or
/// not a number): where generated code refuses the mass matrix as singular.
pub fn singular_pivot(pivots: &[f64]) -> Option<usize> {
    let largest = pivots.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    pivots.iter().position(|&p| !p.is_finite() || p <= ReferenceDynamics::SINGULAR_RATIO * largest)
}

/// The largest error of every function over the states, and the states at which the mass matrix
/// is singular.
#[derive(Debug, Clone)]
pub struct Report {
    /// Per function of [`DynamicsFunction::ALL`] (then, with forces, of
    /// [`DynamicsFunction::WITH_FORCES`]), the largest error (see the module's measure); none for
    /// forward dynamics when the mass matrix was singular at every state.
    pub errors: Vec<(DynamicsFunction, Option<f64>)>,
    /// The states compared.
    pub states: usize,
    /// The states at which both refused forward dynamics (a singular mass matrix).
    pub singular: usize,
    /// The gravity.
    pub gravity: [f64; 3],
}

/// The range the rates and accelerations are drawn from (rad/s, rad/s^2; m/s, m/s^2).
pub const RATES: f64 = 2.0;

/// A deterministic stream of numbers in `[-RATES, RATES]` (splitmix64, fixed seed).
struct Rates(u64);

impl Rates {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        RATES * (2.0 * (z >> 11) as f64 / (1u64 << 53) as f64 - 1.0)
    }

    fn vector(&mut self, n: usize) -> Vec<f64> {
        (0..n).map(|_| self.next()).collect()
    }
}

/// The reference for `tree` under `request`.
pub fn reference(tree: &KinematicTree, file: &str, request: &DynamicsRequest) -> Result<ReferenceDynamics, CliError> {
    ReferenceDynamics::new(tree.clone(), request.gravity, request.inertia_as_written)
        .map_err(|source| CliError::Dynamics { file: file.to_owned(), source: Box::new(source) })
}

/// Largest `|got - want|` over the scale of `want` (its largest magnitude, at least 1); a length
/// that differs, a NaN or an infinity is infinite.
fn relative(got: &[f64], want: &[f64], scale: f64) -> f64 {
    if got.len() != want.len() {
        return f64::INFINITY;
    }
    got.iter()
        .zip(want)
        .fold(0.0, |worst, (g, w)| worst_of(worst, if g.is_finite() { (g - w).abs() } else { f64::NAN }))
        / scale
}

/// The scale of values: their largest magnitude, at least 1.
fn scale<'a>(values: impl IntoIterator<Item = &'a f64>) -> f64 {
    values.into_iter().fold(1.0f64, |s, x| s.max(x.abs()))
}

/// Compares `subject` with the reference over `samples` states: `q` from `check`'s
/// configurations, rates and accelerations uniform in `[-RATES, RATES]`.
pub fn compare(
    tree: &KinematicTree,
    file: &str,
    reference: &ReferenceDynamics,
    subject: &dyn Subject,
    forces: &[String],
    samples: usize,
) -> Result<Report, CliError> {
    let nv = tree.velocity_dof();
    let error = |source| CliError::Dynamics { file: file.to_owned(), source: Box::new(source) };
    let mut worst = [0.0f64; 7];
    let mut singular = 0;
    let mut rates = Rates(0x6b69_6e65_6d61_7469);
    let bar = crate::progress::bar(samples as u64, "checking the dynamics");
    for q in Configurations::new(tree).take(samples) {
        let (qd, qdd) = (rates.vector(nv), rates.vector(nv));
        let tau = reference.inverse_dynamics(&q, &qd, &qdd).map_err(error)?;
        let h = reference.nonlinear_effects(&q, &qd).map_err(error)?;
        let m = reference.mass_matrix(&q).map_err(error)?;
        let m_rows: Vec<f64> = (0..nv).flat_map(|i| (0..nv).map(move |j| (i, j))).map(|(i, j)| m[(i, j)]).collect();
        let gravity = reference.gravity_torques(&q).map_err(error)?;
        let wanted: [(DynamicsFunction, &[f64], &[f64]); 4] = [
            (DynamicsFunction::Gravity, &[], &gravity),
            (DynamicsFunction::InverseDynamics, &qdd, &tau),
            (DynamicsFunction::NonlinearEffects, &[], &h),
            (DynamicsFunction::MassMatrix, &[], &m_rows),
        ];
        for (k, (function, input, want)) in wanted.into_iter().enumerate() {
            let got = match subject.eval(function, &q, &qd, input) {
                Evaluated::Values(values) => values,
                Evaluated::Singular(_) => vec![f64::NAN],
            };
            worst[k] = worst_of(worst[k], relative(&got, want, scale(want)));
        }
        let by_reference = match reference.forward_dynamics(&q, &qd, &tau) {
            Ok(a) => Ok(a),
            Err(DynamicsError::SingularMassMatrix { velocities, .. }) => Err(velocities),
            Err(e) => return Err(error(e)),
        };
        // M (a - a_ref): the torques the difference of accelerations stands for.
        let in_torques = |got: &[f64], want: &[f64], torque_scale: f64| {
            if got.len() == nv && got.iter().all(|a| a.is_finite()) {
                let difference: Vec<f64> = got.iter().zip(want).map(|(g, w)| g - w).collect();
                let torques: Vec<f64> = (0..nv).map(|i| (0..nv).map(|j| m[(i, j)] * difference[j]).sum()).collect();
                relative(&torques, &vec![0.0; nv], torque_scale)
            } else {
                f64::INFINITY
            }
        };
        if !forces.is_empty() {
            // Forces of a few newtons (and newton metres) on each link, the functions' inputs after
            // `qdd` or `tau`.
            let applied: Vec<[f64; 6]> =
                forces.iter().map(|_| std::array::from_fn(|_| 5.0 * rates.next() / RATES)).collect();
            let named: Vec<(&str, [f64; 6])> = forces.iter().map(String::as_str).zip(applied.iter().copied()).collect();
            let flat: Vec<f64> = applied.iter().flatten().copied().collect();
            let tau_f = reference.inverse_dynamics_with_forces(&q, &qd, &qdd, &named).map_err(error)?;
            let input: Vec<f64> = qdd.iter().chain(&flat).copied().collect();
            let got = match subject.eval(DynamicsFunction::InverseDynamicsWithForces, &q, &qd, &input) {
                Evaluated::Values(values) => values,
                Evaluated::Singular(_) => vec![f64::NAN],
            };
            worst[5] = worst_of(worst[5], relative(&got, &tau_f, scale(&tau_f)));
            // Forward dynamics with the forces of the torques `tau`: the accelerations `qdd`, where
            // the mass matrix is regular (a singular one is counted below, without forces).
            if let Ok(want) = reference.forward_dynamics_with_forces(&q, &qd, &tau_f, &named) {
                let input: Vec<f64> = tau_f.iter().chain(&flat).copied().collect();
                let e = match subject.eval(DynamicsFunction::ForwardDynamicsWithForces, &q, &qd, &input) {
                    Evaluated::Values(got) => in_torques(&got, &want, scale(tau_f.iter().chain(&h))),
                    Evaluated::Singular(_) => f64::INFINITY,
                };
                worst[6] = worst_of(worst[6], e);
            }
        }
        match (subject.eval(DynamicsFunction::ForwardDynamics, &q, &qd, &tau), by_reference) {
            (Evaluated::Singular(_), Err(_)) => singular += 1,
            (Evaluated::Values(got), Ok(want)) => {
                worst[4] = worst_of(worst[4], in_torques(&got, &want, scale(tau.iter().chain(&h))));
            }
            (Evaluated::Singular(by_subject), Ok(_)) => {
                bar.finish_and_clear();
                return Err(CliError::SingularDisagrees {
                    file: file.to_owned(),
                    q,
                    subject: by_subject,
                    reference: None,
                });
            }
            (Evaluated::Values(_), Err(velocities)) => {
                bar.finish_and_clear();
                return Err(CliError::SingularDisagrees {
                    file: file.to_owned(),
                    q,
                    subject: Vec::new(),
                    reference: Some(velocities),
                });
            }
        }
        bar.inc(1);
    }
    bar.finish_and_clear();
    let compared = |function: DynamicsFunction| !function.is_forward() || singular < samples;
    let functions = DynamicsFunction::ALL.into_iter().chain(DynamicsFunction::WITH_FORCES).take(if forces.is_empty() {
        DynamicsFunction::ALL.len()
    } else {
        worst.len()
    });
    Ok(Report {
        errors: functions.zip(worst).map(|(f, e)| (f, compared(f).then_some(e))).collect(),
        states: samples,
        singular,
        gravity: reference.gravity(),
    })
}

/// The report as `check` prints it: the states, a line per function, the singular states, the
/// largest error against the tolerance.
pub fn report_text(tree: &KinematicTree, report: &Report) -> String {
    let mut out = format!(
        "dynamics: the compiled functions against the runtime reference (ReferenceDynamics), gravity {} m/s^2 in \
         `{}`'s frame\n",
        vector_text(report.gravity),
        tree.link(tree.root()).name
    );
    out += &format!(
        "{} states: configurations drawn as above, rates and accelerations uniform in [-{RATES}, {RATES}]\n",
        report.states
    );
    let width = crate::inspect::column_width(report.errors.iter().map(|(f, _)| f.name())).max(8);
    out += &format!("{}  largest error (x the values' scale)\n", crate::inspect::pad("function", width));
    for (function, error) in &report.errors {
        let error = match error {
            None => "none compared: the mass matrix is singular at every state".to_owned(),
            Some(e) if function.is_forward() => {
                format!("{e:.2e}  (M (qdd - qdd_ref), x the torques' scale)")
            }
            Some(e) => format!("{e:.2e}"),
        };
        out += &format!("{}  {error}\n", crate::inspect::pad(function.name(), width));
    }
    out += &format!("singular mass matrix: {} of {} states, refused by both\n", report.singular, report.states);
    if let Some((function, error)) = worst(report) {
        let ok = if error <= TOLERANCE { "within" } else { "past" };
        out += &format!("largest: {error:.2e} (`{}`), {ok} the tolerance {TOLERANCE:e}\n", function.name());
    }
    out
}

/// The function with the largest error (the first of equals; an error is never NaN: NaN folds to
/// infinity).
pub fn worst(report: &Report) -> Option<(DynamicsFunction, f64)> {
    report.errors.iter().filter_map(|&(f, e)| Some((f, e?))).reduce(|a, b| if b.1 > a.1 { b } else { a })
}

/// The function with the largest error as the error `check` fails with, past the tolerance (or
/// not a number).
pub fn verdict(file: &str, report: &Report) -> Result<(), CliError> {
    match worst(report) {
        Some((function, error)) if error.is_nan() || error > TOLERANCE => Err(CliError::DynamicsDisagrees {
            file: file.to_owned(),
            function: function.name(),
            error,
            tolerance: TOLERANCE,
        }),
        _ => Ok(()),
    }
}

/// `c12/s12 = cos/sin(q1 + q2)` and the like, for the angles `outputs` use that are not a single
/// joint variable.
fn legend(g: &ExprGraph, names: &Names) -> Vec<String> {
    names
        .angles()
        .filter(|&angle| !matches!(g.node(angle), Node::Var(_)))
        .map(|angle| {
            let suffix = names.suffix(angle);
            format!("c{suffix}/s{suffix} = cos/sin({})", kinematics_compiler::emit::text(g, names, angle))
        })
        .collect()
}

/// The gravity torques as text: one line per velocity (`tau1 = ...`), or the named one's.
pub fn gravity_text(
    tree: &KinematicTree,
    file: &str,
    request: &DynamicsRequest,
    joint: Option<&str>,
) -> Result<String, CliError> {
    let compiled = compile(tree, file, request, &[DynamicsFunction::Gravity])?;
    let gravity = &compiled[0];
    let selected: Vec<usize> = match joint {
        None => (0..gravity.velocity_dof()).collect(),
        Some(name) => match gravity.velocity_names.iter().position(|v| v == name) {
            Some(k) => vec![k],
            None => {
                let suggestion = kinematics::model::closest(name, gravity.velocity_names.iter().map(String::as_str))
                    .map(str::to_owned);
                return Err(CliError::UnknownVelocity {
                    file: file.to_owned(),
                    name: name.to_owned(),
                    velocities: gravity.velocity_names.clone(),
                    suggestion,
                });
            }
        },
    };
    let outputs: Vec<ExprId> = selected.iter().map(|&k| gravity.outputs()[k]).collect();
    let g = gravity.graph();
    let names = Names::new(g, &outputs).with_sizes(gravity.dof(), gravity.velocity_dof());
    let mut out = format!(
        "robot `{}`: gravity torques (the generalized forces that hold it still), gravity {} m/s^2 in `{}`'s \
         frame\n",
        tree.name(),
        vector_text(request.gravity),
        tree.link(tree.root()).name
    );
    let joints: Vec<String> = gravity.dof_names.iter().enumerate().map(|(i, n)| format!("q{} = {n}", i + 1)).collect();
    if !joints.is_empty() {
        out += &format!("joints: {}\n", joints.join(", "));
    }
    if gravity.velocity_names != gravity.dof_names {
        let velocities: Vec<String> =
            gravity.velocity_names.iter().enumerate().map(|(i, n)| format!("tau{} = {n}", i + 1)).collect();
        out += &format!("velocities: {}\n", velocities.join(", "));
    }
    if !gravity.quaternions.is_empty() {
        let rotations: Vec<String> = gravity
            .quaternions
            .iter()
            .enumerate()
            .map(|(k, &start)| format!("rot{}_ij = `{}`'s", k + 1, tree.joint(tree.dof_joints()[start]).name))
            .collect();
        out += &format!("rotations: {} (row i, column j, from its quaternion)\n", rotations.join(", "));
    }
    let legend = legend(g, &names);
    if !legend.is_empty() {
        out += &format!("angles: {}\n", legend.join(", "));
    }
    out += "\n";
    let listing = text_listing(g, &names, &outputs);
    for (name, definition) in &listing.temporaries {
        out += &format!("{name} = {definition}\n");
    }
    if !listing.temporaries.is_empty() {
        out += "\n";
    }
    for (&k, entry) in selected.iter().zip(listing.entries) {
        out += &format!("tau{} = {entry}\n", k + 1);
    }
    Ok(out)
}

/// Operation counts of compiled functions as aligned `sin_cos / mul / add / div` lines.
pub fn op_table(compiled: &[CompiledDynamics]) -> String {
    let width = crate::inspect::column_width(compiled.iter().map(|c| c.function.name()));
    let mut out = format!("  {}  sin_cos / mul / add / div\n", crate::inspect::pad("", width));
    for c in compiled {
        let count = c.op_count();
        out += &format!(
            "  {}  {:>7} / {:>3} / {:>3} / {:>3}\n",
            crate::inspect::pad(c.function.name(), width),
            count.sin_cos,
            count.mul,
            count.add,
            count.div
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gravity_reads_three_numbers() {
        assert_eq!(gravity("0,0,-9.81"), Ok([0.0, 0.0, -9.81]));
        assert_eq!(gravity(" 1, -2 ,3"), Ok([1.0, -2.0, 3.0]));
        assert!(gravity("nan,0,0").is_ok_and(|g| g[0].is_nan()));
        assert!(gravity("0,-9.81").is_err_and(|e| e.contains("not 2")));
        assert!(gravity("0,0,down").is_err_and(|e| e.contains("`down`")));
    }

    #[test]
    fn a_pivot_at_most_the_ratio_of_the_largest_is_singular() {
        assert_eq!(singular_pivot(&[2.0, 1e-3]), None);
        assert_eq!(singular_pivot(&[2.0, 1e-13, 0.0]), Some(1));
        assert_eq!(singular_pivot(&[2.0, -1.0]), Some(1));
        assert_eq!(singular_pivot(&[f64::NAN, 1.0]), Some(0));
    }

    #[test]
    fn errors_are_relative_to_a_scale_of_at_least_one() {
        assert_eq!(relative(&[1.0, 2.5], &[1.0, 2.0], scale(&[1.0, 2.0])), 0.25);
        assert_eq!(relative(&[0.5], &[0.25], scale(&[0.25])), 0.25);
        assert_eq!(relative(&[f64::NAN], &[0.0], 1.0), f64::INFINITY);
        assert_eq!(relative(&[1.0], &[1.0, 2.0], 1.0), f64::INFINITY);
    }

    #[test]
    fn rates_stay_in_their_range() {
        let mut rates = Rates(1);
        assert!(rates.vector(1000).iter().all(|x| x.abs() <= RATES));
    }
}
