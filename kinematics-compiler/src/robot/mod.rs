//! A whole compiled robot: constants, typed functions and the `Kinematics` trait impl for a type.
//!
//! The derive macro and the build API both emit through [`emit_robot`], so their output is the same.
//!
//! The output is one anonymous block, `const _: () = { ... };`, holding the generic functions (in
//! a module `bodies` private to the block) and the impls that call them. Nothing in it can collide
//! with the user's names: the generic functions' own scalar parameter `T` is declared where no
//! other generics are in scope, the user's generics appear only on the impls (as given in
//! [`RobotSpec::impl_generics`]), and everything else is reached by absolute paths (`::core`, the
//! crate path).
//!
//! The generic functions' locals (`q1`, `s1`, `c23`, `t0`, ...) are in a module of their own
//! because a `let` whose name is a constant or unit struct in scope is a pattern, not a binding:
//! beside a user's `const q1: f64` in the same module, `let [q1, q2] = *q;` would not compile.
//! A module sees none of its parent's items, so its bodies see none of the user's. Hygiene
//! (`Span::mixed_site()`) would not do: it hides locals from each other, not items from
//! patterns (tried: a `const q1` beside a mixed-site `let q1` still makes it a pattern), and
//! the build API's output is text, which has no hygiene at all. The impls' own parameters and
//! locals (`q`, `qd`, `qs`, `out`, `target`, `seed`, `free`, `options`, `solutions`) are in the
//! user's scope, as a hand-written function's would be. The module reaches the crate by
//! [`RobotSpec::krate`], so that path must name it from any module (an absolute path, a
//! `crate::` path or a dependency's name), as the `crate` option's renamed dependency does.

mod constants;
mod functions;
mod ik;
mod impls;
mod poses;
mod velocities;

use kinematics_model::KinematicTree;
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use crate::emit::{EmitOptions, Trig};
use crate::error::CompileError;
use crate::request::{Compiled, Request, compile};
use functions::Functions;

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
    /// The links `link_poses` (and `link_positions`, `LINK_NAMES`) return, in this order; empty
    /// means every link but the base. The caller has checked the names (unknown ones are a
    /// [`CompileError`]) and that none repeats.
    pub links: Vec<String>,
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
///
/// Each kind of output has its own module: `poses` (link and tip poses and positions),
/// `velocities` (Jacobians, pose and Jacobian, twists), `ik` (inverse kinematics),
/// `constants` (the type's constants), `impls` (the block, the trait impls and `reference()`);
/// `functions` turns one generic body into the typed, batch and lane functions. Adding a kind of
/// output is adding a module and one call here.
pub fn emit_robot(self_ty: &TokenStream, spec: &RobotSpec<'_>) -> Result<TokenStream, CompileError> {
    let tree = spec.tree;
    let base = spec.base.clone().unwrap_or_else(|| tree.link(tree.root()).name.clone());
    let links = compile(tree, &link_request(spec, &base, false))?.into_link_list();
    let cx = Context::new(spec, base, &links);
    let mut out = Functions::default();
    poses::link_poses(&cx, &links, &mut out)?;
    if !cx.tips.is_empty() {
        poses::tip_poses(&cx, &mut out)?;
        if spec.jacobians {
            velocities::velocities(&cx, &mut out)?;
        }
    }
    ik::ik(&cx, &mut out)?;
    Ok(impls::robot_block(self_ty, &cx, &out))
}

/// The poses (or positions) `link_poses` (`link_positions`) returns: every link but the base, or
/// the spec's list of links, in its order.
fn link_request(spec: &RobotSpec<'_>, base: &str, position_only: bool) -> Request {
    Request { base: Some(base.to_owned()), tips: spec.links.clone(), position_only, velocity: None }
}

/// What every kind of output needs: the spec, the paths and lengths as tokens, and the scalars.
struct Context<'a> {
    /// The spec.
    spec: &'a RobotSpec<'a>,
    /// `krate::__private`, the one path generated code reaches the facade by.
    p: TokenStream,
    /// The base link (given, or the root).
    base: String,
    /// The tip links.
    tips: Vec<String>,
    /// Whether there is one tip (`tip_pose`) rather than several (`tip_poses`).
    one: bool,
    /// The links `link_poses` returns, in order.
    link_names: Vec<String>,
    /// `DOF`, `VELOCITY_DOF`, the number of links and of tips, as literals.
    n_lit: Literal,
    nv_lit: Literal,
    m_lit: Literal,
    k_lit: Literal,
    /// (suffix, scalar, lane type, wide lane type) per scalar asked for: the batches run the
    /// wide lanes where the CPU has AVX-512, the others elsewhere.
    scalars: Vec<(&'static str, TokenStream, TokenStream, TokenStream)>,
    /// The `*_generic` functions' scalar parameter and its bound.
    scalar: TokenStream,
    bound: TokenStream,
    /// The tips' poses, in `base`: the request every tip function starts from.
    tip_request: Request,
}

impl<'a> Context<'a> {
    fn new(spec: &'a RobotSpec<'a>, base: String, links: &Compiled) -> Self {
        let tree = spec.tree;
        let krate = &spec.krate;
        let p = quote!(#krate::__private);
        let link_names: Vec<String> = links.frames().iter().map(|f| f.link.clone()).collect();
        let scalars = [
            (spec.scalars.f64, "", quote!(f64), quote!(#p::F64x4), quote!(#p::F64x8)),
            (spec.scalars.f32, "_f32", quote!(f32), quote!(#p::F32x8), quote!(#p::F32x16)),
        ]
        .into_iter()
        .filter(|(on, ..)| *on)
        .map(|(_, suffix, t, lanes, wide)| (suffix, t, lanes, wide))
        .collect();
        let tips = spec.tips.clone();
        let tip_request =
            Request { base: Some(base.clone()), tips: tips.clone(), position_only: false, velocity: None };
        Context {
            spec,
            scalar: scalar_parameter(&spec.impl_generics),
            bound: spec.trig.bound(&p),
            p,
            base,
            one: tips.len() == 1,
            n_lit: Literal::usize_unsuffixed(tree.dof()),
            nv_lit: Literal::usize_unsuffixed(tree.velocity_dof()),
            m_lit: Literal::usize_unsuffixed(link_names.len()),
            k_lit: Literal::usize_unsuffixed(tips.len()),
            link_names,
            tips,
            scalars,
            tip_request,
        }
    }

    /// The tree.
    fn tree(&self) -> &'a KinematicTree {
        self.spec.tree
    }

    /// The links `link_poses` returns, for its doc: "every link but `base`", or the list's names.
    fn links_described(&self) -> String {
        if self.spec.links.is_empty() {
            format!("every link but `{}`", self.base)
        } else {
            self.spec.links.iter().map(|l| format!("`{l}`")).collect::<Vec<_>>().join(", ")
        }
    }

    /// How the generic body `name` is emitted: public in the block's private module `bodies`
    /// (so the block can call it), with the spec's trig.
    fn body_options(&self, name: &str) -> EmitOptions {
        EmitOptions { name: name.to_owned(), private: self.p.clone(), public: true, trig: self.spec.trig }
    }

    /// `Pose<t>`.
    fn pose_ty(&self, t: &TokenStream) -> TokenStream {
        let p = &self.p;
        quote!(#p::Pose<#t>)
    }
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
