//! Poses and positions: of every link (`link_poses`, `link_positions`) and of the tips
//! (`tip_pose` or `tip_poses`, `tip_position` or `tip_positions`): what each compiles and what its
//! documentation says.

use super::Context;
use crate::error::CompileError;
use crate::request::{Compiled, Request, compile};

/// A compiled body and its function's doc.
pub(super) type Body = (Compiled, String);

/// What `link_poses` returns, for its doc (the caller compiles it first: it needs its frames).
pub(super) fn link_poses_doc(cx: &Context<'_>) -> String {
    format!("Poses of {}, in `{}` and in the order of `LINK_NAMES`", cx.links_described(), cx.base)
}

/// `link_positions`.
pub(super) fn link_positions(cx: &Context<'_>) -> Result<Body, CompileError> {
    let compiled = compile(cx.tree(), &super::link_request(cx.spec, &cx.base, true))?.into_link_list();
    Ok((compiled, format!("Positions of {}, in `{}`", cx.links_described(), cx.base)))
}

/// `tip_pose` or `tip_poses`.
pub(super) fn tip_poses(cx: &Context<'_>) -> Result<Body, CompileError> {
    let (base, tips) = (&cx.base, &cx.tips);
    let doc = if cx.one {
        format!("Pose of `{}` in `{base}`", tips[0])
    } else {
        format!("Poses of {} in `{base}`", tips.join(", "))
    };
    Ok((compile(cx.tree(), &cx.tip_request)?, doc))
}

/// `tip_position` or `tip_positions`.
pub(super) fn tip_positions(cx: &Context<'_>) -> Result<Body, CompileError> {
    let compiled = compile(cx.tree(), &Request { position_only: true, ..cx.tip_request.clone() })?;
    Ok((compiled, format!("Positions of {}", cx.tips.join(", "))))
}
