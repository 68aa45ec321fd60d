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

use crate::emit::{EmitOptions, Trig, emit_function};
use crate::error::CompileError;
use crate::request::{Request, compile};
use kinematics_model::JacobianFrame;

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

/// Which inverse kinematics to emit (of the one tip).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum IkMode {
    /// None.
    #[default]
    Off,
    /// The closed form of the tip's family (`tip_ik`, `tip_ik_nearest`, `tip_ik_within_limits`,
    /// `IK_FAMILY`) and beside it the numeric solver (`tip_ik_numeric`); a chain no family covers
    /// is an error naming why.
    ClosedForm {
        /// For a seven-joint arm, the joint whose value `tip_ik` takes as an input.
        free: Option<String>,
    },
    /// The numeric solver only (`tip_ik_numeric`, `tip_ik_numeric_with`), for any chain.
    Numeric,
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
    /// Also emit the tips' velocities: geometric Jacobians in both frames, the pose with its
    /// Jacobian, the twist `J * qd` (and, with `positions`, the position Jacobian).
    pub jacobians: bool,
    /// Also emit inverse kinematics of the tip (needs exactly one tip).
    pub ik: IkMode,
    /// Scalar types.
    pub scalars: Scalars,
    /// Path to the `kinematics` crate in the user's crate (usually `::kinematics`); generated code
    /// reaches everything through its `__private` module.
    pub krate: TokenStream,
    /// Which sine and cosine the code calls.
    pub trig: Trig,
    /// The description's name in messages (the path as the user wrote it).
    pub source_label: String,
    /// An expression of type `&'static str` holding the description's text (e.g. `include_str!`).
    pub source_text: TokenStream,
    /// The root link [`kinematics_model::Description::with_floating_base`] added, when the tree was
    /// loaded with a free-flying root (`reference()` loads it the same way).
    pub floating_base: Option<String>,
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
///
/// Every computation (`tip_pose`, `link_poses`, ...) comes as one generic body (a free function
/// in the block) and, on the type: a typed function per scalar (`tip_pose`, `tip_pose_f32`), the
/// generic one for any `Real` type (`tip_pose_generic`: lanes,
/// dual numbers), and a batch per scalar over slices of configurations, four (`f64`) or eight
/// (`f32`) configurations per call in SIMD lanes (`tip_pose_batch`, `tip_pose_batch_f32`).
/// `reference()` and `impl ReferenceModel` are wrapped in the facade's `with_std!`, so they exist
/// only with its `std` feature.
pub fn emit_robot(self_ty: &TokenStream, spec: &RobotSpec<'_>) -> Result<TokenStream, CompileError> {
    let tree = spec.tree;
    let krate = &spec.krate;
    let p = quote!(#krate::__private);
    let base = spec.base.clone().unwrap_or_else(|| tree.link(tree.root()).name.clone());
    let all =
        compile(tree, &Request { base: Some(base.clone()), tips: Vec::new(), position_only: false, velocity: None })?;
    let n = tree.dof();
    let n_lit = Literal::usize_unsuffixed(n);
    let nv_lit = Literal::usize_unsuffixed(tree.velocity_dof());
    let velocity_names = tree.velocity_names();
    let link_names: Vec<String> = all.frames().iter().map(|f| f.link.clone()).collect();
    let m_lit = Literal::usize_unsuffixed(link_names.len());
    let joint_names: Vec<String> = tree.dof_names();
    let limits: Vec<TokenStream> = tree
        .dof_limits()
        .iter()
        .map(|l| {
            let (lo, hi) = match l {
                Some(l) => (number(l.lower), number(l.upper)),
                None => (quote!(-::core::primitive::f64::INFINITY), quote!(::core::primitive::f64::INFINITY)),
            };
            quote!(#p::JointLimits { lower: #lo, upper: #hi })
        })
        .collect();

    let trig = spec.trig;
    let scalar = scalar_parameter(&spec.impl_generics);
    let bound = trig.bound(&p);
    let private = |name: &str| EmitOptions { name: name.to_owned(), private: p.clone(), public: false, trig };
    let mut generic = vec![emit_function(&all, &private("generic_link_poses"))];
    let mut typed = Vec::new();
    // (suffix, scalar, lane type) per scalar asked for.
    let scalars: Vec<(&str, TokenStream, TokenStream)> = [
        (spec.scalars.f64, "", quote!(f64), quote!(#p::F64x4)),
        (spec.scalars.f32, "_f32", quote!(f32), quote!(#p::F32x8)),
    ]
    .into_iter()
    .filter(|(on, ..)| *on)
    .map(|(_, suffix, t, lanes)| (suffix, t, lanes))
    .collect();
    let pose_ty = |t: &TokenStream| quote!(#p::Pose<#t>);
    let mut add = |name: &str, generic_name: &str, ret: &dyn Fn(&TokenStream) -> TokenStream, doc: String| {
        let g = format_ident!("{generic_name}");
        for (suffix, t, lanes) in &scalars {
            let f = format_ident!("{name}{suffix}");
            let r = ret(t);
            let one = format!("{doc} (`{t}`).");
            typed.push(quote! {
                #[doc = #one]
                #[inline]
                pub fn #f(q: &[#t; #n_lit]) -> #r { #g(q) }
            });
            let batch = format_ident!("{name}_batch{suffix}");
            let many = format!(
                "[`Self::{f}`] for every configuration of `qs`, into `out` (one each), {} at a time in SIMD \
                 lanes (`{}`). An `out` of another length than `qs` is an error, and nothing is written.",
                if suffix.is_empty() { 4 } else { 8 },
                lanes.to_string().replace(' ', ""),
            );
            // A closure, `#[inline(always)]`, rather than the function itself: a function item
            // is called through a shim that is not inlined into the dispatched loop, which then
            // runs without the instruction set it was compiled for (measured).
            typed.push(quote! {
                #[doc = #many]
                #[inline]
                #[allow(clippy::redundant_closure)]
                pub fn #batch(qs: &[[#t; #n_lit]], out: &mut [#r]) -> ::core::result::Result<(), #p::KinematicsError> {
                    #p::batch::<#lanes, #n_lit, _>(Self::ROBOT, qs, out, #[inline(always)] |q| #g(q))
                }
            });
        }
        let f = format_ident!("{name}_generic");
        let r = ret(&scalar);
        let doc = format!(
            "{doc}, for any scalar type: the lane types `F64x4` and `F32x8` (four or eight configurations per \
             call), dual numbers, or a type of your own."
        );
        typed.push(quote! {
            #[doc = #doc]
            #[inline]
            pub fn #f<#scalar: #bound>(q: &[#scalar; #n_lit]) -> #r { #g(q) }
        });
    };
    add(
        "link_poses",
        "generic_link_poses",
        &|t| {
            let pose = pose_ty(t);
            quote!([#pose; #m_lit])
        },
        format!("Poses of every link but `{base}`, in `{base}` and in the order of `LINK_NAMES`"),
    );
    if spec.positions {
        let positions = compile(
            tree,
            &Request { base: Some(base.clone()), tips: Vec::new(), position_only: true, velocity: None },
        )?;
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
    let tip_request = Request { base: Some(base.clone()), tips: tips.clone(), position_only: false, velocity: None };
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
                    let pose = pose_ty(t);
                    quote!([#pose; #k_lit])
                }
            },
            what,
        );
        if spec.positions {
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
        if spec.jacobians {
            let (tips_word, of) = ("tip", if one { format!("`{}`", tips[0]) } else { tips.join(", ") });
            let j_ty = |t: &TokenStream, rows: usize| {
                let rows = Literal::usize_unsuffixed(rows);
                if one { quote!([[#t; #nv_lit]; #rows]) } else { quote!([[[#t; #nv_lit]; #rows]; #k_lit]) }
            };
            let frames = [
                (JacobianFrame::LocalWorldAligned, "", "in `{base}`'s axes"),
                (JacobianFrame::Local, "_local", "in the tip's own axes"),
            ];
            for (frame, suffix, axes) in frames {
                let axes = axes.replace("{base}", &base);
                let name = format!("{tips_word}_{}{suffix}", if one { "jacobian" } else { "jacobians" });
                let generic_name = format!("generic_{name}");
                let compiled = compile(tree, &Request { velocity: None, ..tip_request.clone() }.jacobian(frame))?;
                generic.push(emit_function(&compiled, &private(&generic_name)));
                add(
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
            let compiled = compile(tree, &tip_request.clone().pose_and_jacobian(JacobianFrame::LocalWorldAligned))?;
            generic.push(emit_function(&compiled, &private("generic_pose_and_jacobian")));
            add(
                name,
                "generic_pose_and_jacobian",
                &|t| {
                    let pair = quote!((#p::Pose<#t>, [[#t; #nv_lit]; 6]));
                    if one { pair } else { quote!([#pair; #k_lit]) }
                },
                format!("Pose and geometric Jacobian (`LOCAL_WORLD_ALIGNED`) of {of} in `{base}`, computed together"),
            );
            if spec.positions {
                let name = format!("{tips_word}_position_{}", if one { "jacobian" } else { "jacobians" });
                let compiled =
                    compile(tree, &tip_request.clone().positions_only().jacobian(JacobianFrame::LocalWorldAligned))?;
                generic.push(emit_function(&compiled, &private("generic_position_jacobian")));
                add(
                    &name,
                    "generic_position_jacobian",
                    &|t| j_ty(t, 3),
                    format!(
                        "The linear rows of the geometric Jacobian of {of} in `{base}` (the derivative of its position)"
                    ),
                );
            }
            for (frame, suffix, axes) in frames {
                let axes = axes.replace("{base}", &base);
                let name = format!("{tips_word}_{}{suffix}", if one { "twist" } else { "twists" });
                let generic_name = format!("generic_{name}");
                let compiled = compile(tree, &tip_request.clone().twist(frame))?;
                generic.push(emit_function(&compiled, &private(&generic_name)));
                let g = format_ident!("{generic_name}");
                let ret = |t: &TokenStream| if one { quote!([#t; 6]) } else { quote!([[#t; 6]; #k_lit]) };
                let doc = format!(
                    "Twist of {of} relative to `{base}` at joint rates `qd` ({}: the linear velocity of the tip's origin, then \
                     the angular velocity, {axes}): the Jacobian times `qd`, computed without forming the Jacobian",
                    frame.name()
                );
                for (suffix, t, _) in &scalars {
                    let f = format_ident!("{name}{suffix}");
                    let r = ret(t);
                    let one_doc = format!("{doc} (`{t}`).");
                    typed.push(quote! {
                        #[doc = #one_doc]
                        #[inline]
                        pub fn #f(q: &[#t; #n_lit], qd: &[#t; #nv_lit]) -> #r { #g(q, qd) }
                    });
                }
                let f = format_ident!("{name}_generic");
                let r = ret(&scalar);
                let doc = format!("{doc}, for any scalar type.");
                typed.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #f<#scalar: #bound>(q: &[#scalar; #n_lit], qd: &[#scalar; #nv_lit]) -> #r { #g(q, qd) }
                });
            }
        }
        if one { quote!(out[0] = generic_tip_poses(q);) } else { quote!(out.copy_from_slice(&generic_tip_poses(q));) }
    };
    if spec.ik != IkMode::Off {
        let [tip] = tips.as_slice() else {
            return Err(CompileError::IkNeedsOneTip { robot: tree.name().to_owned(), tips: tips.len() });
        };
        if let IkMode::ClosedForm { free } = &spec.ik {
            let plan = crate::ik::classify_with(tree, &base, tip, free.as_deref())?;
            let revolute: Vec<bool> = tree
                .dof_joints()
                .iter()
                .map(|&j| tree.joint(j).kind != kinematics_model::JointKind::Prismatic)
                .collect();
            typed.push(crate::ik::emit::emit_ik(&plan, &p, &quote!(generic_tip_poses), &revolute));
        }
        // The numeric solver steps on the pose and Jacobian together: the velocities' own
        // function when they are emitted, otherwise one for it.
        let pose_and_jacobian = if spec.jacobians {
            quote!(generic_pose_and_jacobian)
        } else {
            let compiled = compile(tree, &tip_request.clone().pose_and_jacobian(JacobianFrame::LocalWorldAligned))?;
            generic.push(emit_function(&compiled, &private("generic_ik_pose_and_jacobian")));
            quote!(generic_ik_pose_and_jacobian)
        };
        if tree.dof() != tree.velocity_dof() {
            return Err(CompileError::IkFloating { robot: tree.name().to_owned() });
        }
        typed.push(crate::ik::emit::emit_numeric(tip, &base, n, &p, &pose_and_jacobian));
    }
    let robot = tree.name();
    let label = &spec.source_label;
    let text = &spec.source_text;
    let (jn, ln, tn) = (strs(&joint_names), strs(&link_names), strs(&tips));
    let vn = strs(&velocity_names);
    // `reference()` loads the description with the tree's own exactness policy, so the reference
    // is the robot the code was compiled from.
    let policy = policy_tokens(&p, tree.exact_angles());
    let load = match &spec.floating_base {
        None => quote!(#p::parse_source_with(#label, #text, #policy)),
        Some(link) => quote!(#p::parse_source_floating(#label, #text, #policy, #link)),
    };
    let (impl_generics, where_clause) = (&spec.impl_generics, &spec.where_clause);
    Ok(quote! {
        const _: () = {
        #(#generic)*

        #[allow(clippy::approx_constant)] // limits and offsets are kept exactly as the description gives them
        #[allow(clippy::type_complexity)] // several tips' poses and Jacobians, as arrays of pairs
        impl #impl_generics #self_ty #where_clause {
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

            #(#typed)*

            #p::with_std! {
                /// The runtime reference model of this robot, built from the same description.
                pub fn reference() -> ::core::result::Result<#p::ReferenceFk, #p::LoadError> {
                    #load.map(#p::ReferenceFk::new)
                }
            }
        }

        #[allow(clippy::approx_constant)] // limits are kept exactly as the description gives them
        impl #impl_generics #p::Kinematics for #self_ty #where_clause {
            const ROBOT: &'static str = #robot;
            const BASE: &'static str = #base;
            const DOF: usize = #n_lit;
            const JOINT_NAMES: &'static [&'static str] = &#jn;
            const JOINT_LIMITS: &'static [#p::JointLimits] = &[#(#limits),*];
            const LINK_NAMES: &'static [&'static str] = &#ln;
            const TIPS: &'static [&'static str] = &#tn;

            fn tip_poses_into(q: &[f64], out: &mut [#p::Pose<f64>]) -> ::core::result::Result<(), #p::KinematicsError> {
                let q = #p::q_array::<#n_lit>(#robot, &#jn, q)?;
                #p::check_output(#robot, #k_lit, out.len())?;
                #tip_poses_body
                ::core::result::Result::Ok(())
            }

            fn link_poses_into(q: &[f64], out: &mut [#p::Pose<f64>]) -> ::core::result::Result<(), #p::KinematicsError> {
                let q = #p::q_array::<#n_lit>(#robot, &#jn, q)?;
                #p::check_output(#robot, #m_lit, out.len())?;
                out.copy_from_slice(&generic_link_poses(q));
                ::core::result::Result::Ok(())
            }
        }

        #p::with_std! {
            impl #impl_generics #p::ReferenceModel for #self_ty #where_clause {
                fn reference() -> ::core::result::Result<#p::ReferenceFk, #p::LoadError> {
                    Self::reference()
                }
            }
        }
        };
    })
}

/// The name of the `*_generic` functions' scalar parameter: `T`, unless the user's impl generics
/// use that name (then `S`, `R`, or a name nobody writes), since they are in scope there.
fn scalar_parameter(impl_generics: &TokenStream) -> TokenStream {
    fn idents(tokens: &TokenStream, out: &mut Vec<String>) {
        for token in tokens.clone() {
            match token {
                proc_macro2::TokenTree::Ident(i) => out.push(i.to_string()),
                proc_macro2::TokenTree::Group(g) => idents(&g.stream(), out),
                _ => {}
            }
        }
    }
    let mut taken = Vec::new();
    idents(impl_generics, &mut taken);
    let name = ["T", "S", "R"].into_iter().find(|n| !taken.iter().any(|t| t == n)).unwrap_or("__KinematicsScalar");
    let name = format_ident!("{name}");
    quote!(#name)
}

/// The policy as an expression of type `ExactAngles`.
fn policy_tokens(p: &TokenStream, policy: ExactAngles) -> TokenStream {
    match policy {
        ExactAngles::Off => quote!(#p::ExactAngles::Off),
        ExactAngles::Within(tolerance) => {
            let tolerance = number(tolerance);
            quote!(#p::ExactAngles::Within(#tolerance))
        }
    }
}

/// A number as an `f64` expression: a literal; values that are exactly a multiple of pi as an `f64`
/// get the constant's name; infinities and NaN their `f64` constants (never a panic, never another
/// number).
pub(crate) fn number(x: f64) -> TokenStream {
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
