//! The tips' velocities: geometric Jacobians in both frames, the pose and Jacobian together, with
//! `positions` the position Jacobian, and the twists `J * qd`.

use kinematics_model::JacobianFrame;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::Context;
use super::functions::Functions;
use crate::error::CompileError;
use crate::request::compile;

/// The two frames a velocity is written in: (frame, name suffix, what its axes are).
const FRAMES: [(JacobianFrame, &str, &str); 2] = [
    (JacobianFrame::LocalWorldAligned, "", "in `{base}`'s axes"),
    (JacobianFrame::Local, "_local", "in the tip's own axes"),
];

/// Every velocity function of the tips (there is at least one tip).
pub(super) fn velocities(cx: &Context<'_>, out: &mut Functions) -> Result<(), CompileError> {
    let (p, base, tips, one, nv_lit, k_lit) = (&cx.p, &cx.base, &cx.tips, cx.one, &cx.nv_lit, &cx.k_lit);
    let tree = cx.tree();
    let request = &cx.tip_request;
    let (tips_word, of) = ("tip", if one { format!("`{}`", tips[0]) } else { tips.join(", ") });
    let j_ty = |t: &TokenStream, rows: usize| {
        let rows = Literal::usize_unsuffixed(rows);
        if one { quote!([[#t; #nv_lit]; #rows]) } else { quote!([[[#t; #nv_lit]; #rows]; #k_lit]) }
    };
    for (frame, suffix, axes) in FRAMES {
        let axes = axes.replace("{base}", base);
        let name = format!("{tips_word}_{}{suffix}", if one { "jacobian" } else { "jacobians" });
        let generic_name = format!("generic_{name}");
        let compiled = compile(tree, &request.clone().jacobian(frame))?;
        out.body(cx, &compiled, &generic_name);
        out.on_type(
            cx,
            &name,
            &generic_name,
            &|t| j_ty(t, 6),
            format!(
                "Geometric Jacobian of {of} relative to `{base}` ({}: rows the linear velocity of the tip's origin, then \
                 the angular velocity, {axes}; one column per entry of `q`)",
                frame.name()
            ),
        );
    }
    let name = if one { "tip_pose_and_jacobian" } else { "tip_poses_and_jacobians" };
    let compiled = compile(tree, &request.clone().pose_and_jacobian(JacobianFrame::LocalWorldAligned))?;
    out.body(cx, &compiled, "generic_pose_and_jacobian");
    out.on_type(
        cx,
        name,
        "generic_pose_and_jacobian",
        &|t| {
            let pair = quote!((#p::Pose<#t>, [[#t; #nv_lit]; 6]));
            if one { pair } else { quote!([#pair; #k_lit]) }
        },
        format!("Pose and geometric Jacobian (`LOCAL_WORLD_ALIGNED`) of {of} in `{base}`, computed together"),
    );
    if cx.spec.positions {
        let name = format!("{tips_word}_position_{}", if one { "jacobian" } else { "jacobians" });
        let compiled = compile(tree, &request.clone().positions_only().jacobian(JacobianFrame::LocalWorldAligned))?;
        out.body(cx, &compiled, "generic_position_jacobian");
        out.on_type(
            cx,
            &name,
            "generic_position_jacobian",
            &|t| j_ty(t, 3),
            format!("The linear rows of the geometric Jacobian of {of} in `{base}` (the derivative of its position)"),
        );
    }
    for (frame, suffix, axes) in FRAMES {
        let axes = axes.replace("{base}", base);
        let name = format!("{tips_word}_{}{suffix}", if one { "twist" } else { "twists" });
        let generic_name = format!("generic_{name}");
        out.body(cx, &compile(tree, &request.clone().twist(frame))?, &generic_name);
        let doc = format!(
            "Twist of {of} relative to `{base}` at joint rates `qd` ({}: the linear velocity of the tip's origin, then \
             the angular velocity, {axes}): the Jacobian times `qd`, computed without forming the Jacobian",
            frame.name()
        );
        out.on_type_with_rates(
            cx,
            &name,
            &generic_name,
            &|t| if one { quote!([#t; 6]) } else { quote!([[#t; 6]; #k_lit]) },
            &doc,
        );
    }
    Ok(())
}
