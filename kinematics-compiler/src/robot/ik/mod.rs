//! Inverse kinematics of the one tip: the closed form of its family ([`items::emit_ik`]) and the
//! numeric solver beside it, or the numeric solver alone, each item where and as
//! [`super::surface`] lists it.

mod items;

use kinematics_model::{JacobianFrame, JointKind};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::Context;
use super::functions::Functions;
use super::surface::{IkFunction, IkItem, IkShape, Signature};
use crate::error::CompileError;
use crate::options::CheckedIk;
use crate::request::compile;
use items::{IkItems, Measures, Part, emit_ik, emit_numeric};

/// The functions the checked options ask for (none when `ik` is off).
#[allow(clippy::expect_used)] // internal invariants, named
pub(super) fn ik(cx: &Context<'_>, out: &mut Functions) -> Result<(), CompileError> {
    let spec = cx.spec;
    let (tree, p, base) = (cx.tree(), &cx.p, &cx.base);
    if matches!(spec.robot.ik(), CheckedIk::Off) {
        return Ok(());
    }
    // The numeric solver steps on the pose and Jacobian together, and the closed form's
    // refinement too: the velocities' own function when they are emitted, otherwise one for it
    // (emitted after the closed form's bodies).
    let pose_and_jacobian =
        if cx.options().jacobians { quote!(generic_pose_and_jacobian) } else { quote!(generic_ik_pose_and_jacobian) };
    let closed = match spec.robot.ik() {
        CheckedIk::Off | CheckedIk::Numeric => None,
        CheckedIk::ClosedForm(plan) => {
            let revolute: Vec<bool> =
                tree.dof_joints().iter().map(|&j| tree.joint(j).kind != JointKind::Prismatic).collect();
            let tip_pose = compile(tree, &cx.tip_request)?;
            // An arm the family solves with its relations made exact is refined in one pass,
            // from its pose and Jacobian at the solver's cosines and sines.
            let pose_and_jacobian_measure = if plan.made_exact {
                let with_jacobian =
                    compile(tree, &cx.tip_request.clone().pose_and_jacobian(JacobianFrame::LocalWorldAligned))?;
                crate::ik::Measure::of(&with_jacobian)
            } else {
                None
            };
            let measures =
                Measures { pose: crate::ik::Measure::of(&tip_pose), pose_and_jacobian: pose_and_jacobian_measure };
            Some(emit_ik(plan, p, &quote!(generic_tip_poses), &pose_and_jacobian, &measures, &revolute))
        }
    };
    let shape = IkShape::of(spec.robot.ik(), closed.as_ref().is_some_and(|c| c.branch))
        .expect("invariant: `ik` is on here, so the checked robot has an inverse kinematics shape");
    if let Some(closed) = &closed {
        out.generic.extend(closed.bodies.iter().cloned());
    }
    if !cx.options().jacobians {
        let compiled = compile(tree, &cx.tip_request.clone().pose_and_jacobian(JacobianFrame::LocalWorldAligned))?;
        out.body(cx, &compiled, "generic_ik_pose_and_jacobian");
    }
    let numeric = emit_numeric(&cx.tips[0], base, p, &pose_and_jacobian);
    for item in cx.render.ik_items(&shape) {
        out.typed.push(match item {
            IkItem::Family => constant("IK_FAMILY", &quote!(&'static str), &closed_part(&closed).family),
            IkItem::Arm(ty) => constant("IK_ARM", &ty, &closed_part(&closed).arm),
            IkItem::Function(function, signature) => {
                let part = match function {
                    IkFunction::All => &closed_part(&closed).all,
                    IkFunction::Branch => closed_part(&closed)
                        .branch_fn
                        .as_ref()
                        .expect("invariant: the surface lists `tip_ik_branch_generic` only for a compiled family"),
                    IkFunction::WithinLimits => &closed_part(&closed).within_limits,
                    IkFunction::Nearest => &closed_part(&closed).nearest,
                    IkFunction::Numeric => &numeric.numeric,
                    IkFunction::NumericWith => &numeric.with,
                };
                function_item(&signature, part)
            }
        });
    }
    Ok(())
}

/// The closed form's parts, which the surface asks for only when there is one.
#[allow(clippy::expect_used)] // an internal invariant, named
fn closed_part(closed: &Option<IkItems>) -> &IkItems {
    closed.as_ref().expect("invariant: the surface lists closed-form items only for a closed-form plan")
}

/// `attrs pub const NAME: ty = value;`.
fn constant(name: &str, ty: &TokenStream, part: &Part) -> TokenStream {
    let (name, attrs, value) = (format_ident!("{name}"), &part.attrs, &part.body);
    quote! {
        #attrs
        pub const #name: #ty = #value;
    }
}

/// `attrs pub fn name(..) -> .. { body }`.
fn function_item(signature: &Signature, part: &Part) -> TokenStream {
    let (attrs, sig, body) = (&part.attrs, signature.tokens(), &part.body);
    quote! {
        #attrs
        #sig { #body }
    }
}
