//! Inverse kinematics of the one tip: the closed form of its family (emitted by
//! [`crate::ik::emit::emit_ik`]) and the numeric solver beside it, or the numeric solver alone.

use kinematics_model::{JacobianFrame, JointKind};
use quote::quote;

use super::functions::Functions;
use super::{Context, IkMode};
use crate::error::CompileError;
use crate::request::compile;

/// The functions [`super::RobotSpec::ik`] asks for (none when it is off).
pub(super) fn ik(cx: &Context<'_>, out: &mut Functions) -> Result<(), CompileError> {
    let spec = cx.spec;
    if spec.ik == IkMode::Off {
        return Ok(());
    }
    let (tree, p, base) = (cx.tree(), &cx.p, &cx.base);
    let [tip] = cx.tips.as_slice() else {
        return Err(CompileError::IkNeedsOneTip { robot: tree.name().to_owned(), tips: cx.tips.len() });
    };
    if let IkMode::ClosedForm { free } = &spec.ik {
        let plan = crate::ik::classify_with(tree, base, tip, free.as_deref())?;
        let revolute: Vec<bool> =
            tree.dof_joints().iter().map(|&j| tree.joint(j).kind != JointKind::Prismatic).collect();
        let tip_pose = compile(tree, &cx.tip_request)?;
        let measure = crate::ik::Measure::of(&tip_pose);
        let items = crate::ik::emit::emit_ik(&plan, p, &quote!(generic_tip_poses), measure.as_ref(), &revolute);
        out.generic.extend(items.bodies);
        out.typed.push(items.typed);
    }
    // The numeric solver steps on the pose and Jacobian together: the velocities' own
    // function when they are emitted, otherwise one for it.
    let pose_and_jacobian = if spec.jacobians {
        quote!(generic_pose_and_jacobian)
    } else {
        let compiled = compile(tree, &cx.tip_request.clone().pose_and_jacobian(JacobianFrame::LocalWorldAligned))?;
        out.body(cx, &compiled, "generic_ik_pose_and_jacobian");
        quote!(generic_ik_pose_and_jacobian)
    };
    if tree.dof() != tree.velocity_dof() {
        return Err(CompileError::IkFloating { robot: tree.name().to_owned() });
    }
    out.typed.push(crate::ik::emit::emit_numeric(tip, base, tree.dof(), p, &pose_and_jacobian));
    Ok(())
}
