//! A whole compiled robot: constants, typed functions and the `Kinematics` trait impl for a type.
//!
//! The derive macro and the build API both emit through [`emit_robot`], so their output is the same.
//!
//! The output is one anonymous block, `const _: () = { ... };`, holding the generic functions (free
//! functions, private to the block) and the impls that call them. Nothing in it can collide with
//! the user's names: the generic functions' own scalar parameter `T` is declared where no other
//! generics are in scope, the user's generics appear only on the impls (as given in
//! [`RobotSpec::impl_generics`]), and everything else is reached by absolute paths (`::core`, the
//! crate path).

use kinematics_model::{ExactAngles, KinematicTree};
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use crate::emit::{EmitOptions, emit_function};
use crate::error::CompileError;
use crate::request::{Request, compile};

/// Which scalar types get typed functions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Scalars {
    /// `f64` functions (`tip_pose`).
    pub f64: bool,
    /// `f32` functions (`tip_pose_f32`).
    pub f32: bool,
}

impl Default for Scalars {
    fn default() -> Self {
        Scalars { f64: true, f32: false }
    }
}

/// Everything [`emit_robot`] needs.
#[derive(Debug, Clone)]
pub struct RobotSpec<'a> {
    /// The validated robot.
    pub tree: &'a KinematicTree,
    /// The frame poses are expressed in (default: the root link).
    pub base: Option<String>,
    /// Tip links (may be empty).
    pub tips: Vec<String>,
    /// Also emit position-only functions.
    pub positions: bool,
    /// Scalar types.
    pub scalars: Scalars,
    /// Path to the `kinematics` crate in the user's crate (usually `::kinematics`).
    pub krate: TokenStream,
    /// The description's name in messages (the path as the user wrote it).
    pub source_label: String,
    /// An expression of type `&'static str` holding the description's text (e.g. `include_str!`).
    pub source_text: TokenStream,
    /// The generic parameters of the impls, with their bounds (`<'a, T: Clone, const N: usize>`,
    /// syn's `impl_generics`); empty for a type without generics. `self_ty` carries the arguments.
    pub impl_generics: TokenStream,
    /// The where clause of the impls (`where T: Default`), or nothing.
    pub where_clause: TokenStream,
}

fn strs(names: &[String]) -> TokenStream {
    quote!([#(#names),*])
}

/// The robot's constants and functions on `self_ty` (the type with its generic arguments, such as
/// `Arm<'a, T, N>`) and `impl Kinematics` for it, in an anonymous `const _: () = { ... };` block.
pub fn emit_robot(self_ty: &TokenStream, spec: &RobotSpec<'_>) -> Result<TokenStream, CompileError> {
    let tree = spec.tree;
    let krate = &spec.krate;
    let base = spec.base.clone().unwrap_or_else(|| tree.link(tree.root()).name.clone());
    let all = compile(tree, &Request { base: Some(base.clone()), tips: Vec::new(), position_only: false })?;
    let n = tree.dof();
    let n_lit = Literal::usize_unsuffixed(n);
    let link_names: Vec<String> = all.frames().iter().map(|f| f.link.clone()).collect();
    let m_lit = Literal::usize_unsuffixed(link_names.len());
    let joint_names: Vec<String> = tree.dof_names().into_iter().map(str::to_owned).collect();
    let limits: Vec<TokenStream> = tree
        .dof_limits()
        .iter()
        .map(|l| {
            let (lo, hi) = match l {
                Some(l) => (number(l.lower), number(l.upper)),
                None => (quote!(-::core::primitive::f64::INFINITY), quote!(::core::primitive::f64::INFINITY)),
            };
            quote!(#krate::JointLimits { lower: #lo, upper: #hi })
        })
        .collect();

    let private = |name: &str| EmitOptions { name: name.to_owned(), krate: krate.clone(), public: false };
    let mut generic = vec![emit_function(&all, &private("generic_link_poses"))];
    let mut typed = Vec::new();
    let scalars: Vec<(&str, TokenStream)> = [(spec.scalars.f64, ""), (spec.scalars.f32, "_f32")]
        .into_iter()
        .filter(|(on, _)| *on)
        .map(|(_, suffix)| (suffix, if suffix.is_empty() { quote!(f64) } else { quote!(f32) }))
        .collect();
    let pose_ty = |t: &TokenStream| quote!(#krate::Pose<#t>);
    let mut add = |name: &str, generic_name: &str, ret: &dyn Fn(&TokenStream) -> TokenStream, doc: String| {
        for (suffix, t) in &scalars {
            let f = format_ident!("{name}{suffix}");
            let g = format_ident!("{generic_name}");
            let r = ret(t);
            let doc = format!("{doc} (`{t}`)");
            typed.push(quote! {
                #[doc = #doc]
                #[inline]
                pub fn #f(q: &[#t; #n_lit]) -> #r { #g(q) }
            });
        }
    };
    add(
        "link_poses",
        "generic_link_poses",
        &|t| {
            let p = pose_ty(t);
            quote!([#p; #m_lit])
        },
        format!("Poses of every link but `{base}`, in `{base}` and in the order of `LINK_NAMES`"),
    );
    if spec.positions && !scalars.is_empty() {
        let positions = compile(tree, &Request { base: Some(base.clone()), tips: Vec::new(), position_only: true })?;
        generic.push(emit_function(&positions, &private("generic_link_positions")));
        add(
            "link_positions",
            "generic_link_positions",
            &|t| quote!([[#t; 3]; #m_lit]),
            format!("Positions of every link but `{base}`, in `{base}`"),
        );
    }
    let tips = spec.tips.clone();
    let k_lit = Literal::usize_unsuffixed(tips.len());
    let tip_request = Request { base: Some(base.clone()), tips: tips.clone(), position_only: false };
    let tip_poses_body = if tips.is_empty() {
        quote!(let _ = (q, out);)
    } else {
        let compiled = compile(tree, &tip_request)?;
        generic.push(emit_function(&compiled, &private("generic_tip_poses")));
        let one = tips.len() == 1;
        let (name, what) = if one {
            ("tip_pose", format!("Pose of `{}` in `{base}`", tips[0]))
        } else {
            ("tip_poses", format!("Poses of {} in `{base}`", tips.join(", ")))
        };
        add(
            name,
            "generic_tip_poses",
            &|t| {
                if one {
                    pose_ty(t)
                } else {
                    let p = pose_ty(t);
                    quote!([#p; #k_lit])
                }
            },
            what,
        );
        if spec.positions && !scalars.is_empty() {
            let compiled = compile(tree, &Request { position_only: true, ..tip_request.clone() })?;
            generic.push(emit_function(&compiled, &private("generic_tip_positions")));
            let name = if one { "tip_position" } else { "tip_positions" };
            add(
                name,
                "generic_tip_positions",
                &|t| if one { quote!([#t; 3]) } else { quote!([[#t; 3]; #k_lit]) },
                format!("Positions of {}", tips.join(", ")),
            );
        }
        if one { quote!(out[0] = generic_tip_poses(q);) } else { quote!(out.copy_from_slice(&generic_tip_poses(q));) }
    };
    let robot = tree.name();
    let label = &spec.source_label;
    let text = &spec.source_text;
    let (jn, ln, tn) = (strs(&joint_names), strs(&link_names), strs(&tips));
    // `reference()` loads the description with the tree's own exactness policy, so the reference
    // is the robot the code was compiled from.
    let policy = policy_tokens(krate, tree.exact_angles());
    let (impl_generics, where_clause) = (&spec.impl_generics, &spec.where_clause);
    Ok(quote! {
        const _: () = {
        #(#generic)*

        #[allow(clippy::approx_constant)] // limits and offsets are kept exactly as the description gives them
        impl #impl_generics #self_ty #where_clause {
            /// Robot name.
            pub const ROBOT: &'static str = #robot;
            /// The link every pose is expressed in.
            pub const BASE: &'static str = #base;
            /// Degrees of freedom: the length of `q`.
            pub const DOF: usize = #n_lit;
            /// Joint names, in the order of `q`.
            pub const JOINT_NAMES: [&'static str; #n_lit] = #jn;
            /// Position limits, in the order of `q` (infinite for continuous joints).
            pub const JOINT_LIMITS: [#krate::JointLimits; #n_lit] = [#(#limits),*];
            /// The links `link_poses` returns, in order.
            pub const LINK_NAMES: [&'static str; #m_lit] = #ln;
            /// The tip links.
            pub const TIPS: [&'static str; #k_lit] = #tn;

            #(#typed)*

            /// The runtime reference model of this robot, built from the same description.
            pub fn reference() -> ::core::result::Result<#krate::ReferenceFk, #krate::LoadError> {
                #krate::model::parse_source_with(#label, #text, #policy).map(#krate::ReferenceFk::new)
            }
        }

        #[allow(clippy::approx_constant)] // limits are kept exactly as the description gives them
        impl #impl_generics #krate::Kinematics for #self_ty #where_clause {
            const ROBOT: &'static str = #robot;
            const BASE: &'static str = #base;
            const DOF: usize = #n_lit;
            const JOINT_NAMES: &'static [&'static str] = &#jn;
            const JOINT_LIMITS: &'static [#krate::JointLimits] = &[#(#limits),*];
            const LINK_NAMES: &'static [&'static str] = &#ln;
            const TIPS: &'static [&'static str] = &#tn;

            fn tip_poses_into(q: &[f64], out: &mut [#krate::Pose<f64>]) -> ::core::result::Result<(), #krate::RuntimeError> {
                let q = #krate::runtime::q_array::<#n_lit>(#robot, &#jn, q)?;
                #krate::runtime::check_output(#robot, #k_lit, out.len())?;
                #tip_poses_body
                ::core::result::Result::Ok(())
            }

            fn link_poses_into(q: &[f64], out: &mut [#krate::Pose<f64>]) -> ::core::result::Result<(), #krate::RuntimeError> {
                let q = #krate::runtime::q_array::<#n_lit>(#robot, &#jn, q)?;
                #krate::runtime::check_output(#robot, #m_lit, out.len())?;
                out.copy_from_slice(&generic_link_poses(q));
                ::core::result::Result::Ok(())
            }

            fn reference() -> ::core::result::Result<#krate::ReferenceFk, #krate::LoadError> {
                Self::reference()
            }
        }
        };
    })
}

/// Whether two policies are the same (a NaN tolerance equals itself: both read nothing as exact).
/// The policy as an expression of type `ExactAngles`.
fn policy_tokens(krate: &TokenStream, policy: ExactAngles) -> TokenStream {
    match policy {
        ExactAngles::Off => quote!(#krate::model::ExactAngles::Off),
        ExactAngles::Within(tolerance) => {
            let tolerance = number(tolerance);
            quote!(#krate::model::ExactAngles::Within(#tolerance))
        }
    }
}

/// A number as an `f64` expression: a literal; values that are exactly a multiple of pi as an `f64`
/// get the constant's name; infinities and NaN their `f64` constants (never a panic, never another
/// number).
fn number(x: f64) -> TokenStream {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};
    let named = [(PI, quote!(PI)), (TAU, quote!(TAU)), (FRAC_PI_2, quote!(FRAC_PI_2)), (FRAC_PI_4, quote!(FRAC_PI_4))]
        .into_iter()
        .find(|(v, _)| *v == x.abs())
        .map(|(_, name)| quote!(::core::f64::consts::#name));
    if x.is_nan() {
        quote!(::core::primitive::f64::NAN)
    } else if x.is_finite() {
        let magnitude = named.unwrap_or_else(|| {
            let lit = Literal::f64_suffixed(x.abs());
            quote!(#lit)
        });
        if x < 0.0 { quote!(-#magnitude) } else { magnitude }
    } else if x > 0.0 {
        quote!(::core::primitive::f64::INFINITY)
    } else {
        quote!(-::core::primitive::f64::INFINITY)
    }
}
