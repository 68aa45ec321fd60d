//! The dynamics' functions (with `dynamics`): what each compiles and what its documentation says.

use super::Context;
use crate::dynamics::{DynamicsFunction, compile_dynamics};
use crate::emit::emit_dynamics;
use crate::error::CompileError;

/// The generic body of `function` and the doc of its functions on the type.
pub(super) fn body(
    cx: &Context<'_>,
    function: DynamicsFunction,
    name: &str,
) -> Result<(proc_macro2::TokenStream, String), CompileError> {
    #[allow(clippy::expect_used, reason = "an invariant of the surface: dynamics outputs come from the option")]
    let request = cx.options().dynamics.as_ref().expect("dynamics outputs are emitted only with `dynamics`");
    let compiled = compile_dynamics(cx.tree(), request, function)?;
    let [gx, gy, gz] = request.gravity;
    let conventions = format!(
        "one entry per velocity (`VELOCITY_NAMES`; a mimic joint's torque folded into its source's), under \
         gravity ({gx}, {gy}, {gz}) m/s^2 in `{}`'s frame",
        cx.tree().link(cx.tree().root()).name
    );
    let forces = "The external forces `forces` act on the links of `FORCE_LINKS`, in that order, each \
                  `[fx, fy, fz, nx, ny, nz]`: the force and its moment about the link's origin, both in the link's \
                  own axes (N, N m), what the world does to the link";
    let doc = match function {
        DynamicsFunction::Gravity => {
            format!("The generalized forces that hold the robot still at `q` against gravity: {conventions}")
        }
        DynamicsFunction::InverseDynamics => format!(
            "Inverse dynamics (recursive Newton-Euler): the generalized forces that give accelerations `qdd` at `q` \
             and rates `qd`, {conventions}"
        ),
        DynamicsFunction::NonlinearEffects => format!(
            "The Coriolis, centrifugal and gravity forces at `q` and rates `qd` (inverse dynamics at zero \
             acceleration), {conventions}"
        ),
        DynamicsFunction::MassMatrix => {
            "The joint-space mass matrix at `q` (composite rigid bodies), symmetric, one row and column per velocity \
             (`VELOCITY_NAMES`)"
                .to_owned()
        }
        DynamicsFunction::ForwardDynamics => format!(
            "Forward dynamics: the accelerations the generalized forces `tau` give at `q` and rates `qd` (`M qdd = \
             tau - h` by the mass matrix's `L^T D L` factorisation), {conventions}; a singular mass matrix (a velocity \
             that moves no mass) is an error naming the velocity. The generic form returns the accelerations and the \
             factorisation's pivots, one per velocity, each positive where the mass matrix is regular: check them \
             before trusting the accelerations"
        ),
        DynamicsFunction::InverseDynamicsWithForces => format!(
            "Inverse dynamics (recursive Newton-Euler) with external forces on links: the generalized forces that \
             give accelerations `qdd` at `q` and rates `qd` while the world pushes on the links with `forces` \
             (`inverse_dynamics` less `J^T f` of each link's Jacobian in its own frame), {conventions}. {forces}"
        ),
        DynamicsFunction::ForwardDynamicsWithForces => format!(
            "Forward dynamics with external forces on links: the accelerations the generalized forces `tau` give at \
             `q` and rates `qd` while the world pushes on the links with `forces` (`M qdd = tau - h + J^T f`), \
             {conventions}; a singular mass matrix is an error naming the velocity, and the generic form returns the \
             pivots too, as `forward_dynamics`'s. {forces}"
        ),
    };
    let tokens = emit_dynamics(&compiled, &cx.body_options(name), &format!("{doc}."));
    Ok((tokens, doc))
}
