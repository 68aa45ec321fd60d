//! The tips' velocities (there is at least one tip): geometric Jacobians in both frames, the pose
//! and Jacobian together, with `positions` the position Jacobian, and the twists `J * qd`: what
//! each compiles and what its documentation says.

use kinematics_model::JacobianFrame;

use super::Context;
use super::poses::Body;
use crate::error::CompileError;
use crate::request::compile;

/// What the axes of a velocity in `frame` are.
fn axes(frame: JacobianFrame, base: &str) -> String {
    match frame {
        JacobianFrame::Local => "in the tip's own axes".to_owned(),
        _ => format!("in `{base}`'s axes"),
    }
}

/// The tips, for docs: `` `tool0` ``, or `a, b`.
fn of(cx: &Context<'_>) -> String {
    if cx.one { format!("`{}`", cx.tips[0]) } else { cx.tips.join(", ") }
}

/// `tip_jacobian` (in `frame`).
pub(super) fn jacobian(cx: &Context<'_>, frame: JacobianFrame) -> Result<Body, CompileError> {
    let doc = format!(
        "Geometric Jacobian of {} relative to `{}` ({}: rows the linear velocity of the tip's origin, then the angular \
         velocity, {}; one column per entry of `q`)",
        of(cx),
        cx.base,
        frame.name(),
        axes(frame, &cx.base)
    );
    Ok((compile(cx.tree(), &cx.tip_request.clone().jacobian(frame))?, doc))
}

/// `tip_pose_and_jacobian`.
pub(super) fn pose_and_jacobian(cx: &Context<'_>) -> Result<Body, CompileError> {
    let doc = format!(
        "Pose and geometric Jacobian (`LOCAL_WORLD_ALIGNED`) of {} in `{}`, computed together",
        of(cx),
        cx.base
    );
    let request = cx.tip_request.clone().pose_and_jacobian(JacobianFrame::LocalWorldAligned);
    Ok((compile(cx.tree(), &request)?, doc))
}

/// `tip_position_jacobian`.
pub(super) fn position_jacobian(cx: &Context<'_>) -> Result<Body, CompileError> {
    let doc = format!(
        "The linear rows of the geometric Jacobian of {} in `{}` (the derivative of its position)",
        of(cx),
        cx.base
    );
    let request = cx.tip_request.clone().positions_only().jacobian(JacobianFrame::LocalWorldAligned);
    Ok((compile(cx.tree(), &request)?, doc))
}

/// `tip_twist` (in `frame`).
pub(super) fn twist(cx: &Context<'_>, frame: JacobianFrame) -> Result<Body, CompileError> {
    let doc = format!(
        "Twist of {} relative to `{}` at joint rates `qd` ({}: the linear velocity of the tip's origin, then the \
         angular velocity, {}): the Jacobian times `qd`, computed without forming the Jacobian",
        of(cx),
        cx.base,
        frame.name(),
        axes(frame, &cx.base)
    );
    Ok((compile(cx.tree(), &cx.tip_request.clone().twist(frame))?, doc))
}
