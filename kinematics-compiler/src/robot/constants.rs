//! The type's constants: the robot's name, base, joints, limits, links and tips, on the type and
//! in `impl Kinematics`.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::surface::Constant;
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

/// The constants of the type's own `impl`: [`Constant::ALWAYS`], typed by the surface.
pub(super) fn inherent(cx: &Context<'_>) -> TokenStream {
    let items = super::surface::constants(cx.options()).into_iter().map(|constant| {
        let (name, ty) = (format_ident!("{}", constant.name()), cx.render.constant_type(constant));
        let docs = doc(constant).iter().map(|line| format!(" {line}"));
        let value = value(cx, constant);
        quote! {
            #(#[doc = #docs])*
            pub const #name: #ty = #value;
        }
    });
    quote!(#(#items)*)
}

/// A constant's doc, line by line.
fn doc(constant: Constant) -> &'static [&'static str] {
    match constant {
        Constant::Robot => &["Robot name."],
        Constant::Base => &["The link every pose is expressed in."],
        Constant::Dof => &["Degrees of freedom: the length of `q`."],
        Constant::JointNames => &[
            "Joint names, in the order of `q` (a planar joint's three entries, a spherical",
            "joint's four and a floating joint's seven are named after it: `.x`, `.y`, `.theta`;",
            "`.qx`, `.qy`, `.qz`, `.qw`; `.x`, `.y`, `.z`, `.qx`, `.qy`, `.qz`, `.qw`).",
        ],
        Constant::VelocityDof => &[
            "Velocities: a Jacobian's columns and the length of `qd` (`DOF` less one per",
            "floating or spherical joint, whose six or three velocities are its child's in its",
            "own axes).",
        ],
        Constant::VelocityNames => &["Velocity names, in the order of a Jacobian's columns."],
        Constant::JointLimits => &["Position limits, in the order of `q` (infinite for continuous joints)."],
        Constant::LinkNames => &["The links `link_poses` returns, in order."],
        Constant::Tips => &["The tip links."],
        Constant::SphereRadii => &["The collision spheres' radii (m), in the order of `sphere_centers`."],
        Constant::SphereLinks => &["The link each collision sphere moves with, in the order of `sphere_centers`."],
        Constant::ForceLinks => &[
            "The links the external forces of `inverse_dynamics_with_forces` and",
            "`forward_dynamics_with_forces` act on, in the order of their `forces` argument.",
        ],
    }
}

/// A constant's value.
fn value(cx: &Context<'_>, constant: Constant) -> TokenStream {
    let tree = cx.tree();
    match constant {
        Constant::Robot => {
            let robot = tree.name();
            quote!(#robot)
        }
        Constant::Base => {
            let base = &cx.base;
            quote!(#base)
        }
        Constant::Dof => cx.render.dof(),
        Constant::JointNames => strs(&tree.dof_names()),
        Constant::VelocityDof => cx.render.velocities(),
        Constant::VelocityNames => strs(&tree.velocity_names()),
        Constant::JointLimits => {
            let limits = limits(cx);
            quote!([#(#limits),*])
        }
        Constant::LinkNames => strs(&cx.link_names),
        Constant::Tips => strs(&cx.tips),
        Constant::SphereRadii => {
            let radii = cx.spheres().iter().map(|s| number(s.sphere.radius));
            quote!([#(#radii),*])
        }
        Constant::SphereLinks => {
            let names: Vec<String> = cx.spheres().iter().map(|s| tree.link(s.link).name.clone()).collect();
            strs(&names)
        }
        Constant::ForceLinks => strs(&cx.options().dynamics.as_ref().map(|d| d.forces.clone()).unwrap_or_default()),
    }
}

/// The constants of `impl Kinematics`.
pub(super) fn of_trait(cx: &Context<'_>) -> TokenStream {
    let tree = cx.tree();
    let (p, robot, base, n_lit) = (&cx.p, tree.name(), &cx.base, cx.render.dof());
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
