//! Poses and positions: of every link (`link_poses`, `link_positions`) and of the tips
//! (`tip_pose` or `tip_poses`, `tip_position` or `tip_positions`).

use quote::quote;

use super::Context;
use super::functions::Functions;
use crate::error::CompileError;
use crate::request::{Compiled, Request, compile};

/// Every link's pose (`links`, compiled by the caller, who needs its frames' names), and with
/// `positions` their positions.
pub(super) fn link_poses(cx: &Context<'_>, links: &Compiled, out: &mut Functions) -> Result<(), CompileError> {
    let (base, m_lit) = (&cx.base, &cx.m_lit);
    out.body(cx, links, "generic_link_poses");
    out.on_type(
        cx,
        "link_poses",
        "generic_link_poses",
        &|t| {
            let pose = cx.pose_ty(t);
            quote!([#pose; #m_lit])
        },
        format!("Poses of {}, in `{base}` and in the order of `LINK_NAMES`", cx.links_described()),
    );
    if cx.spec.positions {
        let positions = compile(cx.tree(), &super::link_request(cx.spec, base, true))?.into_link_list();
        out.body(cx, &positions, "generic_link_positions");
        out.on_type(
            cx,
            "link_positions",
            "generic_link_positions",
            &|t| quote!([[#t; 3]; #m_lit]),
            format!("Positions of {}, in `{base}`", cx.links_described()),
        );
    }
    Ok(())
}

/// The tips' poses (there is at least one tip), and with `positions` their positions.
pub(super) fn tip_poses(cx: &Context<'_>, out: &mut Functions) -> Result<(), CompileError> {
    let (base, tips, one, k_lit) = (&cx.base, &cx.tips, cx.one, &cx.k_lit);
    out.body(cx, &compile(cx.tree(), &cx.tip_request)?, "generic_tip_poses");
    let (name, what) = if one {
        ("tip_pose", format!("Pose of `{}` in `{base}`", tips[0]))
    } else {
        ("tip_poses", format!("Poses of {} in `{base}`", tips.join(", ")))
    };
    out.on_type(
        cx,
        name,
        "generic_tip_poses",
        &|t| {
            let pose = cx.pose_ty(t);
            if one { pose } else { quote!([#pose; #k_lit]) }
        },
        what,
    );
    if cx.spec.positions {
        let compiled = compile(cx.tree(), &Request { position_only: true, ..cx.tip_request.clone() })?;
        out.body(cx, &compiled, "generic_tip_positions");
        let name = if one { "tip_position" } else { "tip_positions" };
        out.on_type(
            cx,
            name,
            "generic_tip_positions",
            &|t| if one { quote!([#t; 3]) } else { quote!([[#t; 3]; #k_lit]) },
            format!("Positions of {}", tips.join(", ")),
        );
    }
    Ok(())
}
