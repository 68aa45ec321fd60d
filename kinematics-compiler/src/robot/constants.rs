//! The type's constants: the robot's name, base, joints, limits, links and tips, on the type and
//! in `impl Kinematics`.

use proc_macro2::TokenStream;
use quote::quote;

use super::{Context, number};

/// `["a", "b"]`.
fn strs(names: &[String]) -> TokenStream {
    quote!([#(#names),*])
}

/// The joint limits, in the order of `q`, as `JointLimits` expressions (infinite for continuous
/// joints).
fn limits(cx: &Context<'_>) -> Vec<TokenStream> {
    let p = &cx.p;
    cx.tree()
        .dof_limits()
        .iter()
        .map(|l| {
            let (lo, hi) = match l {
                Some(l) => (number(l.lower), number(l.upper)),
                None => (quote!(-::core::primitive::f64::INFINITY), quote!(::core::primitive::f64::INFINITY)),
            };
            quote!(#p::JointLimits { lower: #lo, upper: #hi })
        })
        .collect()
}

/// The constants of the type's own `impl`.
pub(super) fn inherent(cx: &Context<'_>) -> TokenStream {
    let tree = cx.tree();
    let (p, robot, base, n_lit, nv_lit, m_lit, k_lit) =
        (&cx.p, tree.name(), &cx.base, &cx.n_lit, &cx.nv_lit, &cx.m_lit, &cx.k_lit);
    let (jn, vn, ln, tn) =
        (strs(&tree.dof_names()), strs(&tree.velocity_names()), strs(&cx.link_names), strs(&cx.tips));
    let limits = limits(cx);
    quote! {
            /// Robot name.
            pub const ROBOT: &'static str = #robot;
            /// The link every pose is expressed in.
            pub const BASE: &'static str = #base;
            /// Degrees of freedom: the length of `q`.
            pub const DOF: usize = #n_lit;
            /// Joint names, in the order of `q` (a planar joint's three entries and a floating
            /// joint's seven are named after it: `.x`, `.y`, `.theta`; `.x`, `.y`, `.z`, `.qx`,
            /// `.qy`, `.qz`, `.qw`).
            pub const JOINT_NAMES: [&'static str; #n_lit] = #jn;
            /// Velocities: a Jacobian's columns and the length of `qd` (`DOF` less one per
            /// floating joint, whose six velocities are its child's in its own axes).
            pub const VELOCITY_DOF: usize = #nv_lit;
            /// Velocity names, in the order of a Jacobian's columns.
            pub const VELOCITY_NAMES: [&'static str; #nv_lit] = #vn;
            /// Position limits, in the order of `q` (infinite for continuous joints).
            pub const JOINT_LIMITS: [#p::JointLimits; #n_lit] = [#(#limits),*];
            /// The links `link_poses` returns, in order.
            pub const LINK_NAMES: [&'static str; #m_lit] = #ln;
            /// The tip links.
            pub const TIPS: [&'static str; #k_lit] = #tn;
    }
}

/// The constants of `impl Kinematics`.
pub(super) fn of_trait(cx: &Context<'_>) -> TokenStream {
    let tree = cx.tree();
    let (p, robot, base, n_lit) = (&cx.p, tree.name(), &cx.base, &cx.n_lit);
    let (jn, ln, tn) = (joint_names(cx), strs(&cx.link_names), strs(&cx.tips));
    let limits = limits(cx);
    quote! {
            const ROBOT: &'static str = #robot;
            const BASE: &'static str = #base;
            const DOF: usize = #n_lit;
            const JOINT_NAMES: &'static [&'static str] = &#jn;
            const JOINT_LIMITS: &'static [#p::JointLimits] = &[#(#limits),*];
            const LINK_NAMES: &'static [&'static str] = &#ln;
            const TIPS: &'static [&'static str] = &#tn;
    }
}

/// `JOINT_NAMES`' value, `["j1", "j2"]`.
pub(super) fn joint_names(cx: &Context<'_>) -> TokenStream {
    strs(&cx.tree().dof_names())
}
