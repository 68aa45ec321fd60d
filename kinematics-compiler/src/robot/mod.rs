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
//!
//! One module per kind of output: `poses`, `velocities`, `ik`, `constants`, `collision`, `dynamics`, `impls`
//! (the block, the trait impls and `reference()`), `functions` (a generic body into its typed,
//! batch and `_generic` functions), and `surface`, the API surface as data; `emit_robot` walks the
//! surface's outputs and compiles each.

mod collision;
mod constants;
mod dynamics;
mod functions;
mod ik;
mod impls;
mod poses;
pub mod surface;
mod velocities;

use kinematics_model::KinematicTree;
use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use crate::emit::EmitOptions;
use crate::error::CompileError;
use crate::options::{Checked, Options};
use crate::request::{Compiled, Request, compile};
use functions::Functions;
use surface::{Dims, Output, Render};

/// Everything [`emit_robot`] needs: the checked robot and how the output reaches the user's crate.
#[derive(Debug, Clone)]
pub struct RobotSpec<'a> {
    /// The robot and its options, checked ([`Options::check`]).
    pub robot: Checked<'a>,
    /// Path to the `kinematics` crate in the user's crate (usually `::kinematics`); generated code
    /// reaches everything through its `__private` module.
    pub krate: TokenStream,
    /// The description's name in messages (the path as the user wrote it).
    pub source_label: String,
    /// An expression of type `&'static str` holding the description's text (e.g. `include_str!`).
    pub source_text: TokenStream,
    /// For a description that names other files (an MJCF `<include>` or `<model file>`), an
    /// expression of type `&'static [(&'static str, &'static str)]` holding each (path as
    /// written, text), which `reference()` reads them from; `None` for one that names none.
    pub source_files: Option<TokenStream>,
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
/// What is emitted, and every signature, is [`surface`]'s: the [`Output`]s the options ask for,
/// each compiled by its module (`poses`: link and tip poses and positions; `velocities`:
/// Jacobians, pose and Jacobian, twists), then `ik` (inverse kinematics); `constants` (the type's
/// constants) and `impls` (the block, the trait impls and `reference()`) around them; `functions`
/// turns one generic body into the typed, batch and lane functions. Adding a kind of output is
/// adding it to [`surface`] and a module that compiles it.
pub fn emit_robot(self_ty: &TokenStream, spec: &RobotSpec<'_>) -> Result<TokenStream, CompileError> {
    let (tree, options) = (spec.robot.tree(), spec.robot.options());
    let base = spec.robot.base().to_owned();
    let links = compile(tree, &link_request(spec, &base, false))?.into_link_list();
    let cx = Context::new(spec, base, &links);
    let mut out = Functions::default();
    for output in surface::outputs(options) {
        let body = match output {
            Output::SphereCenters => {
                let (bodies, doc) = collision::bodies(&cx, &output.body(cx.one))?;
                out.generic.extend(bodies);
                out.on_type(&cx, output, &doc);
                continue;
            }
            Output::Dynamics(function) => {
                let (body, doc) = dynamics::body(&cx, function, &output.body(cx.one))?;
                out.generic.push(body);
                out.on_type(&cx, output, &doc);
                continue;
            }
            Output::LinkPoses => None,
            Output::LinkPositions => Some(poses::link_positions(&cx)?),
            Output::TipPoses => Some(poses::tip_poses(&cx)?),
            Output::TipPositions => Some(poses::tip_positions(&cx)?),
            Output::Jacobian(frame) => Some(velocities::jacobian(&cx, frame)?),
            Output::PoseAndJacobian => Some(velocities::pose_and_jacobian(&cx)?),
            Output::PositionJacobian => Some(velocities::position_jacobian(&cx)?),
            Output::Twist(frame) => Some(velocities::twist(&cx, frame)?),
        };
        let (compiled, doc) = match &body {
            Some((compiled, doc)) => (compiled, doc.clone()),
            None => (&links, poses::link_poses_doc(&cx)),
        };
        out.body(&cx, compiled, &output.body(cx.one));
        out.on_type(&cx, output, &doc);
    }
    ik::ik(&cx, &mut out)?;
    collision::checks(&cx, &mut out);
    Ok(impls::robot_block(self_ty, &cx, &out))
}

/// The poses (or positions) `link_poses` (`link_positions`) returns: every link but the base, or
/// the options' list of links, in its order.
fn link_request(spec: &RobotSpec<'_>, base: &str, position_only: bool) -> Request {
    Request { base: Some(base.to_owned()), tips: spec.robot.listed_links().to_vec(), position_only, velocity: None }
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
    /// The signatures, with every length known.
    render: Render,
    /// The tips' poses, in `base`: the request every tip function starts from.
    tip_request: Request,
}

impl<'a> Context<'a> {
    fn new(spec: &'a RobotSpec<'a>, base: String, links: &Compiled) -> Self {
        let (tree, options) = (spec.robot.tree(), spec.robot.options());
        let krate = &spec.krate;
        let p = quote!(#krate::__private);
        let link_names: Vec<String> = links.frames().iter().map(|f| f.link.clone()).collect();
        let tips = options.tips.clone();
        let tip_request =
            Request { base: Some(base.clone()), tips: tips.clone(), position_only: false, velocity: None };
        let render = Render {
            p: p.clone(),
            scalars: options.scalars,
            scalar: scalar_parameter(&spec.impl_generics),
            trig: options.trig,
            dims: Dims {
                dof: Some(tree.dof()),
                velocities: Some(tree.velocity_dof()),
                links: Some(link_names.len()),
                tips: Some(tips.len()),
                spheres: spec.robot.collision().map(|c| c.spheres.len()),
                held_words: spec.robot.collision().map(|c| crate::collision_layout::held_words(&c.spheres)),
                forces: options.dynamics.as_ref().map_or(0, |d| d.forces.len()),
            },
        };
        Context { spec, p, base, one: tips.len() == 1, link_names, tips, render, tip_request }
    }

    /// The tree.
    fn tree(&self) -> &'a KinematicTree {
        self.spec.robot.tree()
    }

    /// The options.
    fn options(&self) -> &'a Options {
        self.spec.robot.options()
    }

    /// The collision spheres (none without `collision`).
    fn spheres(&self) -> &'a [kinematics_model::collision::LinkSphere] {
        self.spec.robot.collision().map_or(&[], |c| c.spheres.as_slice())
    }

    /// The links `link_poses` returns, for its doc: "every link but `base`", or the list's names.
    fn links_described(&self) -> String {
        let listed = self.spec.robot.listed_links();
        if listed.is_empty() {
            format!("every link but `{}`", self.base)
        } else {
            listed.iter().map(|l| format!("`{l}`")).collect::<Vec<_>>().join(", ")
        }
    }

    /// How the generic body `name` is emitted: public in the block's private module `bodies`
    /// (so the block can call it), with the options' trig.
    fn body_options(&self, name: &str) -> EmitOptions {
        EmitOptions { name: name.to_owned(), private: self.p.clone(), public: true, trig: self.options().trig }
    }
}

/// The name of the `*_generic` functions' scalar parameter: `T`, unless the user's impl generics
/// use that name (then `S`, `R`, or a name nobody writes), since they are in scope there.
pub fn scalar_parameter(impl_generics: &TokenStream) -> TokenStream {
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
