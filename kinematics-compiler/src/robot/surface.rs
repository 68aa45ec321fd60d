//! The API surface of a compiled robot as data: every constant and function its options imply,
//! in the order they are emitted, with their signatures. [`super::emit_robot`] gives each item a
//! body; the derive's error stub gives each `unreachable!()` (where a fault stops the build, it
//! stands in so one fault does not cascade into "no function `tip_pose`" wherever the type is
//! used). Both render signatures here, so the stub cannot drift from what the emitter writes; a
//! test holds the two equal for every option set.
//!
//! Lengths the stub cannot know (the description did not load, a list could not be read) are
//! [`None`] in [`Dims`]: every one is written as [`UNKNOWN_LENGTH`], a constant the stub defines
//! whose value is the derive's first `compile_error!`. Its type is then an error to rustc, which
//! reports nothing more of any type it is part of: a call's `q`, a seed built by
//! `std::array::from_fn`, the links `link_poses` returns, destructured or not, all check without a
//! second error.

use kinematics_model::JacobianFrame;
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

use crate::dynamics::DynamicsFunction;
use crate::ik::{IkGeometry, IkPlan};
use crate::options::{CheckedIk, IkMode, Options, Scalars, Trig};

/// The lengths in the signatures: `None` where the stub cannot know them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Dims {
    /// Entries of `q`.
    pub dof: Option<usize>,
    /// Velocities (a Jacobian's columns, the entries of `qd`).
    pub velocities: Option<usize>,
    /// Links `link_poses` returns.
    pub links: Option<usize>,
    /// Tips.
    pub tips: Option<usize>,
    /// Collision spheres.
    pub spheres: Option<usize>,
    /// The 64-bit words of a held object's set of links (one bit per link with spheres).
    pub held_words: Option<usize>,
    /// The links external forces act on (`dynamics(forces(..))`; known from the options alone).
    pub forces: usize,
}

/// One computation on the type: a value of `q` (and for twists and some of the dynamics `qd`, and
/// `qdd` or `tau`), as a function per scalar, a batch per scalar, a column batch per scalar (only
/// of functions of `q` alone), and a generic one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    /// `link_poses`.
    LinkPoses,
    /// `link_positions`.
    LinkPositions,
    /// `tip_pose` or `tip_poses`.
    TipPoses,
    /// `tip_position` or `tip_positions`.
    TipPositions,
    /// `tip_jacobian` (`LOCAL_WORLD_ALIGNED`) or `tip_jacobian_local`, or `tip_jacobians*`.
    Jacobian(JacobianFrame),
    /// `tip_pose_and_jacobian` or `tip_poses_and_jacobians`.
    PoseAndJacobian,
    /// `tip_position_jacobian` or `tip_position_jacobians`.
    PositionJacobian,
    /// `tip_twist` or `tip_twist_local`, or `tip_twists*`.
    Twist(JacobianFrame),
    /// `sphere_centers`: every collision sphere's centre.
    SphereCenters,
    /// A function of the dynamics: `gravity_torques`, `inverse_dynamics`, `nonlinear_effects`,
    /// `mass_matrix`, `forward_dynamics`.
    Dynamics(DynamicsFunction),
}

/// The two frames velocities come in, in the order emitted, with their names' suffixes.
pub const VELOCITY_FRAMES: [(JacobianFrame, &str); 2] =
    [(JacobianFrame::LocalWorldAligned, ""), (JacobianFrame::Local, "_local")];

/// What [`Output`]s `options` ask for, in the order emitted: the links', then (with tips) the
/// tips' poses, positions and velocities, then (with `collision`) the sphere centres.
pub fn outputs(options: &Options) -> Vec<Output> {
    collision_outputs(options, tip_outputs(options))
}

/// The links' and the tips' outputs.
fn tip_outputs(options: &Options) -> Vec<Output> {
    let mut out = vec![Output::LinkPoses];
    if options.positions {
        out.push(Output::LinkPositions);
    }
    if options.tips.is_empty() {
        return out;
    }
    out.push(Output::TipPoses);
    if options.positions {
        out.push(Output::TipPositions);
    }
    if options.jacobians {
        out.extend(VELOCITY_FRAMES.map(|(frame, _)| Output::Jacobian(frame)));
        out.push(Output::PoseAndJacobian);
        if options.positions {
            out.push(Output::PositionJacobian);
        }
        out.extend(VELOCITY_FRAMES.map(|(frame, _)| Output::Twist(frame)));
    }
    out
}

/// [`tip_outputs`]'s outputs then, with `collision`, the sphere centres, and with `dynamics` its
/// functions.
fn collision_outputs(options: &Options, mut out: Vec<Output>) -> Vec<Output> {
    if options.collision.is_some() {
        out.push(Output::SphereCenters);
    }
    if let Some(dynamics) = &options.dynamics {
        out.extend(DynamicsFunction::ALL.map(Output::Dynamics));
        if !dynamics.forces.is_empty() {
            out.extend(DynamicsFunction::WITH_FORCES.map(Output::Dynamics));
        }
    }
    out
}

/// The suffix of a velocity in `frame`.
fn frame_suffix(frame: JacobianFrame) -> &'static str {
    VELOCITY_FRAMES.iter().find(|(f, _)| *f == frame).map_or("", |(_, suffix)| suffix)
}

impl Output {
    /// The function's name on the type (for one tip, or several).
    pub fn name(self, one_tip: bool) -> String {
        let (one, several) = match self {
            Output::LinkPoses => ("link_poses", "link_poses"),
            Output::LinkPositions => ("link_positions", "link_positions"),
            Output::TipPoses => ("tip_pose", "tip_poses"),
            Output::TipPositions => ("tip_position", "tip_positions"),
            Output::Jacobian(frame) => return format!("tip_{}{}", plural(one_tip, "jacobian"), frame_suffix(frame)),
            Output::PoseAndJacobian => ("tip_pose_and_jacobian", "tip_poses_and_jacobians"),
            Output::PositionJacobian => ("tip_position_jacobian", "tip_position_jacobians"),
            Output::Twist(frame) => return format!("tip_{}{}", plural(one_tip, "twist"), frame_suffix(frame)),
            Output::SphereCenters => ("sphere_centers", "sphere_centers"),
            Output::Dynamics(function) => return function.name().to_owned(),
        };
        (if one_tip { one } else { several }).to_owned()
    }

    /// The name of the generic body (a free function in the block's module) the functions call.
    pub fn body(self, one_tip: bool) -> String {
        match self {
            Output::LinkPoses => "generic_link_poses".to_owned(),
            Output::LinkPositions => "generic_link_positions".to_owned(),
            Output::TipPoses => "generic_tip_poses".to_owned(),
            Output::TipPositions => "generic_tip_positions".to_owned(),
            Output::PoseAndJacobian => "generic_pose_and_jacobian".to_owned(),
            Output::PositionJacobian => "generic_position_jacobian".to_owned(),
            Output::SphereCenters => "generic_sphere_centers".to_owned(),
            Output::Jacobian(_) | Output::Twist(_) | Output::Dynamics(_) => format!("generic_{}", self.name(one_tip)),
        }
    }

    /// Whether the functions take the joint rates `qd` too (and have no column batches).
    pub fn takes_rates(self) -> bool {
        match self {
            Output::Twist(_) => true,
            Output::Dynamics(function) => function.takes_rates(),
            _ => false,
        }
    }

    /// The third argument, one value per velocity (`qdd` of inverse dynamics, `tau` of forward
    /// dynamics), if any.
    pub fn third_argument(self) -> Option<&'static str> {
        match self {
            Output::Dynamics(function) => function.input(),
            _ => None,
        }
    }

    /// Whether the functions take external forces on links (a fourth argument `forces`).
    pub fn takes_forces(self) -> bool {
        matches!(self, Output::Dynamics(function) if function.takes_forces())
    }

    /// Whether it is forward dynamics, whose typed functions refuse a singular mass matrix.
    pub fn is_forward(self) -> bool {
        matches!(self, Output::Dynamics(function) if function.is_forward())
    }

    /// The names of the per-configuration arguments in order: `q`, then `qd`, the third argument
    /// and `forces` where it takes them. A batch takes a slice of each ([`Output::batch_name`]).
    pub fn inputs(self) -> Vec<&'static str> {
        let mut out = vec!["q"];
        if self.takes_rates() {
            out.push("qd");
        }
        out.extend(self.third_argument());
        if self.takes_forces() {
            out.push("forces");
        }
        out
    }

    /// The slice a batch takes of per-configuration argument `name`: `qs`, `qds`, `qdds`, `taus`,
    /// and `forces` (already plural).
    pub fn batch_name(name: &str) -> String {
        if name == "forces" { name.to_owned() } else { format!("{name}s") }
    }

    /// The arguments the functions pass to the generic body: `q`, `q, qd`, `q, qd, tau` or
    /// `q, qd, tau, forces`.
    pub fn arguments(self) -> TokenStream {
        let names = self.inputs().into_iter().map(|name| format_ident!("{name}"));
        quote!(#(#names),*)
    }

    /// How many values it returns: one per link, per tip or per sphere.
    fn count(self, dims: &Dims) -> (Option<usize>, bool) {
        match self {
            Output::LinkPoses | Output::LinkPositions => (dims.links, true),
            Output::SphereCenters => (dims.spheres, true),
            _ => (dims.tips, false),
        }
    }

    /// The type of one value for scalar `t`.
    fn element(self, t: &TokenStream, p: &TokenStream, nv: &TokenStream) -> TokenStream {
        match self {
            Output::LinkPoses | Output::TipPoses => quote!(#p::Pose<#t>),
            Output::LinkPositions | Output::TipPositions | Output::SphereCenters => quote!([#t; 3]),
            Output::Jacobian(_) => quote!([[#t; #nv]; 6]),
            Output::PoseAndJacobian => quote!((#p::Pose<#t>, [[#t; #nv]; 6])),
            Output::PositionJacobian => quote!([[#t; #nv]; 3]),
            Output::Twist(_) => quote!([#t; 6]),
            Output::Dynamics(DynamicsFunction::MassMatrix) => quote!([[#t; #nv]; #nv]),
            Output::Dynamics(_) => quote!([#t; #nv]),
        }
    }
}

/// `word`, or `word` + `s` for several tips.
fn plural(one_tip: bool, word: &str) -> String {
    if one_tip { word.to_owned() } else { format!("{word}s") }
}

/// One scalar type's functions: the name suffix, the type, and the lane types its batches run on
/// (narrow, and wide where the CPU has AVX-512).
///
/// `f32` runs in eight lanes (`F32x8`) on every CPU, AVX-512 ones included (the body compiled
/// with AVX-512's instructions there): sixteen lanes were measured slower. Over 77 generated
/// bodies of 13 robots (poses, Jacobians, in a dispatched loop on this project's AMD EPYC
/// machine, whose AVX-512 runs each 512-bit operation as two 256-bit halves), sixteen lanes took
/// 1.19 times as long as eight (geometric mean), 0.75 to 5.0 times, because LLVM's SLP
/// vectorizer, which turns the lanes' loops into vector instructions, runs out of its scheduling
/// budget on sixteen lanes of many bodies (not only large ones) and leaves them in scalar pieces;
/// no count of operations told which. The collision checks, measured the same way in two
/// scenes: the UR5's 1.08 to 1.21 times faster in eight lanes, the Panda's 1.02 to 1.07 times
/// slower. `f64` keeps eight lanes under AVX-512: over the same bodies eight took 0.80 times as
/// long as four (0.51 to 1.40; `F64x8` takes the core's packed sine and cosine), and the checks
/// 0.74 to 0.82 times.
///
/// The collision checks' batches (`collides_batch*`, `self_collides_batch*`, their columns forms
/// and the motions) take `f32` in sixteen lanes (`F32x16`) where the CPU has AVX-512
/// (`check_wide`). Measured on the MotionBenchMaker scenes of `benches/collision.rs` (three
/// scenes, this machine, 2026-12-06), sixteen lanes against eight: the UR5's verdict per
/// configuration 0.75 to 0.78 times the time, its free configurations 0.75 to 0.77, its motions
/// 0.77 to 0.85, its self check on self-free configurations 0.78; the Panda's motions 0.86 to
/// 0.91, its self check 0.95, its verdicts per configuration 0.94 to 1.04 and its free
/// configurations 0.97 to 1.06. The shared verdict over a slice (`collides_any*`,
/// `self_collides_any*`) stays in eight: its first pack with a hit ends the work, and a pack of
/// sixteen took 1.3 to 1.7 times as long on those scenes, where most packs of eight hold a hit.
#[derive(Debug, Clone)]
pub struct ScalarType {
    /// `""` or `"_f32"`.
    pub suffix: &'static str,
    /// `f64` or `f32`.
    pub t: TokenStream,
    /// `F64x4` or `F32x8`.
    pub lanes: TokenStream,
    /// `F64x8` or `F32x8` (the same as `lanes`).
    pub wide: TokenStream,
    /// The collision checks' lanes where the CPU has AVX-512: `F64x8` or `F32x16`.
    pub check_wide: TokenStream,
}

impl ScalarType {
    /// The names of the lane types its batches run on (narrow, wide) and how many lanes each has.
    pub fn lane_names(&self) -> ((&'static str, usize), (&'static str, usize)) {
        if self.suffix.is_empty() { (("F64x4", 4), ("F64x8", 8)) } else { (("F32x8", 8), ("F32x8", 8)) }
    }

    /// The names of the lane types the collision checks' batches run on (narrow, wide) and how
    /// many lanes each has.
    pub fn check_lane_names(&self) -> ((&'static str, usize), (&'static str, usize)) {
        if self.suffix.is_empty() { (("F64x4", 4), ("F64x8", 8)) } else { (("F32x8", 8), ("F32x16", 16)) }
    }

    /// The lanes a collision check's batch runs on, for its doc.
    pub fn check_lanes_doc(&self) -> String {
        Self::doc_of(self.check_lane_names())
    }

    /// The lanes a batch runs on, for its doc: "`F64x4`, or `F64x8` where the CPU has AVX-512".
    pub fn lanes_doc(&self) -> String {
        Self::doc_of(self.lane_names())
    }

    fn doc_of(names: ((&'static str, usize), (&'static str, usize))) -> String {
        match names {
            ((narrow, _), (wide, _)) if narrow == wide => format!("`{narrow}`, on every CPU"),
            ((narrow, _), (wide, _)) => format!("`{narrow}`, or `{wide}` where the CPU has AVX-512"),
        }
    }
}

/// The form of one function of an [`Output`].
#[derive(Debug, Clone)]
pub enum Form {
    /// `name` / `name_f32`: one configuration, dispatched.
    Typed(ScalarType),
    /// `name_batch`: slices of configurations in lanes.
    Batch(ScalarType),
    /// `name_batch_columns`: configurations given column-wise.
    Columns(ScalarType),
    /// `name_generic`: any scalar.
    Generic,
}

/// One function's signature: `pub fn name<generics>(inputs) -> output`.
#[derive(Debug, Clone)]
pub struct Signature {
    /// The function's name.
    pub name: Ident,
    /// Its generic parameters (none: no angle brackets).
    pub generics: Vec<TokenStream>,
    /// Its parameters.
    pub inputs: TokenStream,
    /// Its value's type.
    pub output: TokenStream,
}

impl Signature {
    /// `pub fn name<generics>(inputs) -> output`, the body to follow.
    pub fn tokens(&self) -> TokenStream {
        let Signature { name, generics, inputs, output } = self;
        let generics = if generics.is_empty() { quote!() } else { quote!(<#(#generics),*>) };
        quote!(pub fn #name #generics(#inputs) -> #output)
    }
}

/// Renders signatures: the facade's private path, the scalars, the generic scalar parameter and
/// its bound, and the lengths.
#[derive(Debug, Clone)]
pub struct Render {
    /// `krate::__private`.
    pub p: TokenStream,
    /// The scalar types asked for.
    pub scalars: Scalars,
    /// The `_generic` functions' scalar parameter (`T` unless the user's generics take it).
    pub scalar: TokenStream,
    /// The sine and cosine the code calls (the generic scalar's bound).
    pub trig: Trig,
    /// The lengths.
    pub dims: Dims,
}

/// The constant the stub defines for every length it cannot know (its value is the derive's first
/// `compile_error!`, so it stands for an error, never a number).
pub const UNKNOWN_LENGTH: &str = "__KINEMATICS_UNKNOWN_LENGTH";

impl Render {
    /// Each scalar asked for, `f64` first.
    pub fn scalar_types(&self) -> Vec<ScalarType> {
        let p = &self.p;
        [
            (self.scalars.f64, "", quote!(f64), quote!(#p::F64x4), quote!(#p::F64x8), quote!(#p::F64x8)),
            (self.scalars.f32, "_f32", quote!(f32), quote!(#p::F32x8), quote!(#p::F32x8), quote!(#p::F32x16)),
        ]
        .into_iter()
        .filter(|(on, ..)| *on)
        .map(|(_, suffix, t, lanes, wide, check_wide)| ScalarType { suffix, t, lanes, wide, check_wide })
        .collect()
    }

    /// The number of joints: a literal, or the unknown length.
    pub fn dof(&self) -> TokenStream {
        length(self.dims.dof)
    }

    /// The number of velocities: a literal, or (unknown) as many as the joints.
    pub fn velocities(&self) -> TokenStream {
        match self.dims.velocities {
            Some(n) => literal(n),
            None => self.dof(),
        }
    }

    /// The generic scalar parameter with its bound.
    fn generic_scalar(&self) -> TokenStream {
        let (scalar, bound) = (&self.scalar, self.trig.bound(&self.p));
        quote!(#scalar: #bound)
    }

    /// `output`'s value for scalar `t`.
    fn value(&self, output: Output, one_tip: bool, t: &TokenStream) -> TokenStream {
        let element = output.element(t, &self.p, &self.velocities());
        let (count, always_array) = output.count(&self.dims);
        if !always_array && one_tip || matches!(output, Output::Dynamics(_)) {
            return element;
        }
        let n = length(count);
        quote!([#element; #n])
    }

    /// Every function of `output`, in the order emitted: per scalar the typed function and its two
    /// batches (or, taking rates, the typed function and its batch of rows), then the generic one.
    /// A batch takes a slice per argument (`qs`, then `qds`, `qdds`, `taus`: `[[T; DOF]]`, then
    /// `[[T; VELOCITY_DOF]]` each, and `forces`: `[[[T; 6]; K]]`) and fills `out` with the typed function's values (forward
    /// dynamics' accelerations, its refusals the batch's error).
    pub fn functions(&self, output: Output, one_tip: bool) -> Vec<(Form, Signature)> {
        let (p, n, nv) = (&self.p, self.dof(), self.velocities());
        let name = output.name(one_tip);
        let rates = output.takes_rates();
        let error = quote!(::core::result::Result<(), #p::KinematicsError>);
        let mut out = Vec::new();
        let forward = output.is_forward();
        let k = literal(self.dims.forces);
        let extra = |t: &TokenStream| {
            let qd = if rates { quote!(, qd: &[#t; #nv]) } else { quote!() };
            let third = output.third_argument().map(|name| {
                let name = format_ident!("{name}");
                quote!(, #name: &[#t; #nv])
            });
            let forces = output.takes_forces().then(|| quote!(, forces: &[[#t; 6]; #k]));
            quote!(#qd #third #forces)
        };
        for scalar in self.scalar_types() {
            let (suffix, t) = (scalar.suffix, &scalar.t);
            let qd = extra(t);
            let value = self.value(output, one_tip, t);
            let typed = Signature {
                name: format_ident!("{name}{suffix}"),
                generics: Vec::new(),
                inputs: quote!(q: &[#t; #n] #qd),
                output: if forward {
                    quote!(::core::result::Result<#value, #p::KinematicsError>)
                } else {
                    value.clone()
                },
            };
            let rows = output.inputs().into_iter().map(|name| {
                let slice = format_ident!("{}", Output::batch_name(name));
                let row = match name {
                    "q" => quote!([#t; #n]),
                    "forces" => quote!([[#t; 6]; #k]),
                    _ => quote!([#t; #nv]),
                };
                quote!(#slice: &[#row])
            });
            let batches = [
                (format_ident!("{name}_batch{suffix}"), quote!(#(#rows),*)),
                (format_ident!("{name}_batch_columns{suffix}"), quote!(columns: [&[#t]; #n])),
            ]
            .map(|(batch, input)| Signature {
                name: batch,
                generics: Vec::new(),
                inputs: quote!(#input, out: &mut [#value]),
                output: error.clone(),
            });
            out.push((Form::Typed(scalar.clone()), typed));
            let [batch, columns] = batches;
            out.push((Form::Batch(scalar.clone()), batch));
            if !rates {
                out.push((Form::Columns(scalar), columns));
            }
        }
        let scalar = &self.scalar;
        let qd = extra(scalar);
        let mut value = self.value(output, one_tip, scalar);
        if forward {
            // The accelerations and the pivots of the mass matrix's factorisation.
            value = quote!((#value, #value));
        }
        out.push((
            Form::Generic,
            Signature {
                name: format_ident!("{name}_generic"),
                generics: vec![self.generic_scalar()],
                inputs: quote!(q: &[#scalar; #n] #qd),
                output: value,
            },
        ));
        out
    }

    /// The type of a constant: an array of the length when it is known, a slice otherwise.
    pub fn constant_type(&self, constant: Constant) -> TokenStream {
        let p = &self.p;
        let (element, length) = match constant {
            Constant::Robot | Constant::Base => return quote!(&'static str),
            Constant::Dof | Constant::VelocityDof => return quote!(usize),
            Constant::JointNames => (quote!(&'static str), self.dims.dof),
            Constant::VelocityNames => (quote!(&'static str), self.dims.velocities.or(self.dims.dof)),
            Constant::JointLimits => (quote!(#p::JointLimits), self.dims.dof),
            Constant::LinkNames => (quote!(&'static str), self.dims.links),
            Constant::Tips => (quote!(&'static str), self.dims.tips),
            Constant::SphereRadii => (quote!(f64), self.dims.spheres),
            Constant::SphereLinks => (quote!(&'static str), self.dims.spheres),
            Constant::ForceLinks => (quote!(&'static str), Some(self.dims.forces)),
        };
        let n = self::length(length);
        quote!([#element; #n])
    }

    /// The inverse kinematics' items, in the order emitted.
    pub fn ik_items(&self, ik: &IkShape) -> Vec<IkItem> {
        let p = &self.p;
        let n = self.dof();
        let target = quote!(target: &impl #p::ik::IkTarget);
        let seed = quote!(seed: &[f64; #n]);
        let result = |t: TokenStream| quote!(::core::result::Result<#t, #p::ik::IkError>);
        let signature = |name: &str, generics: Vec<TokenStream>, inputs, output| Signature {
            name: Ident::new(name, Span::call_site()),
            generics,
            inputs,
            output,
        };
        let mut items = Vec::new();
        if let Some(closed) = &ik.closed_form {
            items.push(IkItem::Family);
            if let Some(arm) = closed.arm {
                let ty = match arm {
                    ArmKind::Six => quote!(#p::ik::Arm6),
                    ArmKind::FreeSix => quote!(#p::ik::FreeArm6),
                    ArmKind::Planar => quote!(#p::ik::PlanarArm<#n>),
                };
                items.push(IkItem::Arm(ty));
            }
            let capacity = literal(closed.capacity);
            let all = result(quote!(#p::ik::IkSolutions<#n, #capacity>));
            let free = if closed.free { quote!(, free: f64) } else { quote!() };
            items.push(IkItem::Function(
                IkFunction::All,
                signature("tip_ik", Vec::new(), quote!(#target #free), all.clone()),
            ));
            if closed.branch {
                items.push(IkItem::Function(
                    IkFunction::Branch,
                    signature(
                        "tip_ik_branch_generic",
                        vec![quote!(S: #p::ik::IkReal)],
                        quote!(target: &#p::Pose<S>, signs: &[S; 3]),
                        quote!(#p::ik::IkBranch<S, #n>),
                    ),
                ));
            }
            items.push(IkItem::Function(
                IkFunction::WithinLimits,
                signature("tip_ik_within_limits", Vec::new(), quote!(#target #free), all),
            ));
            items.push(IkItem::Function(
                IkFunction::Nearest,
                signature(
                    "tip_ik_nearest",
                    Vec::new(),
                    quote!(#target, #seed),
                    result(quote!(::core::option::Option<#p::ik::IkSolution<#n>>)),
                ),
            ));
        }
        let numeric = result(quote!(#p::ik::NumericSolution<#n>));
        items.push(IkItem::Function(
            IkFunction::Numeric,
            signature("tip_ik_numeric", Vec::new(), quote!(#target, #seed), numeric.clone()),
        ));
        items.push(IkItem::Function(
            IkFunction::NumericWith,
            signature(
                "tip_ik_numeric_with",
                Vec::new(),
                quote!(#target, #seed, options: &#p::ik::NumericOptions),
                numeric,
            ),
        ));
        items
    }
}

/// A literal length, or the unknown length's constant.
fn length(n: Option<usize>) -> TokenStream {
    match n {
        Some(n) => literal(n),
        None => {
            let name = format_ident!("{UNKNOWN_LENGTH}");
            quote!(#name)
        }
    }
}

/// `n` as an unsuffixed literal.
fn literal(n: usize) -> TokenStream {
    let n = Literal::usize_unsuffixed(n);
    quote!(#n)
}

/// The type's own constants, in the order emitted (the inverse kinematics' are [`IkItem`]s).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Constant {
    /// `ROBOT`.
    Robot,
    /// `BASE`.
    Base,
    /// `DOF`.
    Dof,
    /// `JOINT_NAMES`.
    JointNames,
    /// `VELOCITY_DOF`.
    VelocityDof,
    /// `VELOCITY_NAMES`.
    VelocityNames,
    /// `JOINT_LIMITS`.
    JointLimits,
    /// `LINK_NAMES`.
    LinkNames,
    /// `TIPS`.
    Tips,
    /// `SPHERE_RADII` (with `collision`).
    SphereRadii,
    /// `SPHERE_LINKS` (with `collision`).
    SphereLinks,
    /// `FORCE_LINKS` (with `dynamics(forces(..))`).
    ForceLinks,
}

/// The type's own constants for `options`, in the order emitted: [`Constant::ALWAYS`], then with
/// `collision` the spheres' radii and links, and with `dynamics(forces(..))` the links the forces
/// act on.
pub fn constants(options: &Options) -> Vec<Constant> {
    let mut out = Constant::ALWAYS.to_vec();
    if options.collision.is_some() {
        out.extend([Constant::SphereRadii, Constant::SphereLinks]);
    }
    if options.dynamics.as_ref().is_some_and(|d| !d.forces.is_empty()) {
        out.push(Constant::ForceLinks);
    }
    out
}

impl Constant {
    /// Every constant every robot has, in the order emitted.
    pub const ALWAYS: [Constant; 9] = [
        Constant::Robot,
        Constant::Base,
        Constant::Dof,
        Constant::JointNames,
        Constant::VelocityDof,
        Constant::VelocityNames,
        Constant::JointLimits,
        Constant::LinkNames,
        Constant::Tips,
    ];

    /// Its name.
    pub fn name(self) -> &'static str {
        match self {
            Constant::Robot => "ROBOT",
            Constant::Base => "BASE",
            Constant::Dof => "DOF",
            Constant::JointNames => "JOINT_NAMES",
            Constant::VelocityDof => "VELOCITY_DOF",
            Constant::VelocityNames => "VELOCITY_NAMES",
            Constant::JointLimits => "JOINT_LIMITS",
            Constant::LinkNames => "LINK_NAMES",
            Constant::Tips => "TIPS",
            Constant::SphereRadii => "SPHERE_RADII",
            Constant::SphereLinks => "SPHERE_LINKS",
            Constant::ForceLinks => "FORCE_LINKS",
        }
    }
}

/// What the inverse kinematics' items look like.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IkShape {
    /// The closed form's items (none for the numeric solver alone).
    pub closed_form: Option<ClosedFormShape>,
}

/// What the closed form's items look like.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ClosedFormShape {
    /// The type of `IK_ARM` (unknown to a stub whose chain was not classified: no `IK_ARM`).
    pub arm: Option<ArmKind>,
    /// How many solutions `tip_ik` holds.
    pub capacity: usize,
    /// Whether `tip_ik` takes the free joint's value.
    pub free: bool,
    /// Whether the family is compiled to a branch body (`tip_ik_branch_generic`).
    pub branch: bool,
}

/// The geometry type `IK_ARM` has.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArmKind {
    /// `Arm6`.
    Six,
    /// `FreeArm6`.
    FreeSix,
    /// `PlanarArm<N>`.
    Planar,
}

/// The capacity a stub gives `tip_ik` when no plan says the family's: the six-joint families'.
pub const UNKNOWN_CAPACITY: usize = 8;

impl IkShape {
    /// The shape of a checked robot's inverse kinematics (`None` when it has none); `branch`
    /// says whether the closed form compiles to a branch body.
    pub fn of(ik: &CheckedIk, branch: bool) -> Option<IkShape> {
        match ik {
            CheckedIk::Off => None,
            CheckedIk::Numeric => Some(IkShape { closed_form: None }),
            CheckedIk::ClosedForm(plan) => Some(IkShape { closed_form: Some(ClosedFormShape::of(plan, branch)) }),
        }
    }

    /// The shape the options imply when the plan is known only if given: for a stub.
    pub fn implied(options: &Options, plan: Option<&IkPlan>) -> Option<IkShape> {
        match &options.ik {
            IkMode::Off => None,
            IkMode::Numeric => Some(IkShape { closed_form: None }),
            IkMode::ClosedForm { free } => Some(IkShape {
                closed_form: Some(match plan {
                    Some(plan) => ClosedFormShape::of(plan, crate::ik::IkBody::of(plan).is_some()),
                    None => {
                        ClosedFormShape { arm: None, capacity: UNKNOWN_CAPACITY, free: free.is_some(), branch: false }
                    }
                }),
            }),
        }
    }
}

impl ClosedFormShape {
    /// The shape of `plan`'s items.
    fn of(plan: &IkPlan, branch: bool) -> Self {
        let arm = match &plan.geometry {
            IkGeometry::Six { free: None, .. } => ArmKind::Six,
            IkGeometry::Six { free: Some(_), .. } => ArmKind::FreeSix,
            IkGeometry::Planar(_) => ArmKind::Planar,
        };
        ClosedFormShape { arm: Some(arm), capacity: plan.family().max_solutions(), free: plan.free().is_some(), branch }
    }
}

/// The collision checks' functions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CollisionFunction {
    /// `collides(&q, &environment)`.
    Collides,
    /// `self_collides(&q)`.
    SelfCollides,
    /// `motion_collides(&q0, &q1, &environment, resolution)`, and its batch of several motions,
    /// per scalar.
    MotionCollides,
    /// `collides_any(&qs, &environment)` per scalar (whether some configuration of a slice
    /// collides) and `collides_any_generic(&q, &environment)` (whether some lane does).
    CollidesAny,
    /// `self_collides_any(&qs)` and `self_collides_any_generic(&q)`.
    SelfCollidesAny,
    /// `motion_collides_any(&q0, &q1, &environment, resolution)` (whether the motion collides),
    /// and its batch of several motions, per scalar.
    MotionCollidesAny,
    /// `hold(link, spheres, touching)`: a held object.
    Hold,
    /// `clearance(&q, &environment)`: the smallest signed distance.
    Clearance,
    /// `clearance_gradient(&q, &environment)`: it and its gradient.
    ClearanceGradient,
    /// `proximity_cost(&q, &environment, margin)`: the sum of squared depths within a margin.
    ProximityCost,
    /// `proximity_cost_gradient(&q, &environment, margin)`: it and its gradient.
    ProximityCostGradient,
}

impl Render {
    /// The collision checks' functions (with `collision`), in the order emitted: for `collides`
    /// then `self_collides`, per scalar the function on one configuration and its two batches
    /// (verdicts into `out: &mut [bool]`), then the generic one on any lane type (a verdict mask);
    /// then the shared verdicts `collides_any` and `self_collides_any` (per scalar on a slice,
    /// then on any lane type: whether some configuration collides), then per scalar
    /// `motion_collides` (the first colliding fraction of a straight motion) and its batch
    /// (several motions, one per lane), and `motion_collides_any` (whether it collides) and its
    /// batch, then
    /// `hold`, then the distances (`clearance`, `proximity_cost` and their gradients). What `collides` and `motion_collides` are checked against is a `collision::World`
    /// of the robot: an `Environment`, or one with an object the robot holds.
    pub fn collision_items(&self) -> Vec<(CollisionFunction, Form, Signature)> {
        let mut out = self.check_items();
        out.extend(self.shared_items());
        out.extend(self.motion_items());
        out.push(self.hold_item());
        out.extend(self.distance_items());
        out
    }

    /// A `collision::World` of the robot, as the checks against obstacles take it.
    fn world(&self) -> TokenStream {
        let p = &self.p;
        quote!(environment: &impl #p::collision::World<Self>)
    }

    /// `collides` and `self_collides`: per scalar on one configuration, in batches and in column
    /// batches, then on any lane type.
    fn check_items(&self) -> Vec<(CollisionFunction, Form, Signature)> {
        let (p, n, world) = (&self.p, self.dof(), self.world());
        let error = quote!(::core::result::Result<(), #p::KinematicsError>);
        let mut out = Vec::new();
        for function in [CollisionFunction::Collides, CollisionFunction::SelfCollides] {
            let name = function.name();
            let environment = match function {
                CollisionFunction::SelfCollides => quote!(),
                _ => quote!(, #world),
            };
            for scalar in self.scalar_types() {
                let (suffix, t) = (scalar.suffix, &scalar.t);
                let signature = |name: String, inputs: TokenStream, output: TokenStream| Signature {
                    name: Ident::new(&name, Span::call_site()),
                    generics: Vec::new(),
                    inputs,
                    output,
                };
                out.push((
                    function,
                    Form::Typed(scalar.clone()),
                    signature(format!("{name}{suffix}"), quote!(q: &[#t; #n] #environment), quote!(bool)),
                ));
                out.push((
                    function,
                    Form::Batch(scalar.clone()),
                    signature(
                        format!("{name}_batch{suffix}"),
                        quote!(qs: &[[#t; #n]] #environment, out: &mut [bool]),
                        error.clone(),
                    ),
                ));
                out.push((
                    function,
                    Form::Columns(scalar.clone()),
                    signature(
                        format!("{name}_batch_columns{suffix}"),
                        quote!(columns: [&[#t]; #n] #environment, out: &mut [bool]),
                        error.clone(),
                    ),
                ));
            }
            let scalar = &self.scalar;
            let generics = vec![self.collision_scalar()];
            out.push((
                function,
                Form::Generic,
                Signature {
                    name: format_ident!("{name}_generic"),
                    generics,
                    inputs: quote!(q: &[#scalar; #n] #environment),
                    output: quote!(#p::collision::LaneMask),
                },
            ));
        }
        out
    }

    /// `collides_any` and `self_collides_any`: per scalar on a slice, then on any lane type.
    fn shared_items(&self) -> Vec<(CollisionFunction, Form, Signature)> {
        let (n, world) = (self.dof(), self.world());
        let mut out = Vec::new();
        for function in [CollisionFunction::CollidesAny, CollisionFunction::SelfCollidesAny] {
            let name = function.name();
            let environment = match function {
                CollisionFunction::SelfCollidesAny => quote!(),
                _ => quote!(, #world),
            };
            for scalar in self.scalar_types() {
                let (suffix, t) = (scalar.suffix, &scalar.t);
                out.push((
                    function,
                    Form::Typed(scalar.clone()),
                    Signature {
                        name: format_ident!("{name}{suffix}"),
                        generics: Vec::new(),
                        inputs: quote!(qs: &[[#t; #n]] #environment),
                        output: quote!(bool),
                    },
                ));
            }
            let scalar = &self.scalar;
            out.push((
                function,
                Form::Generic,
                Signature {
                    name: format_ident!("{name}_generic"),
                    generics: vec![self.collision_scalar()],
                    inputs: quote!(q: &[#scalar; #n] #environment),
                    output: quote!(bool),
                },
            ));
        }
        out
    }

    /// `motion_collides` (the first colliding fraction of a straight motion) and
    /// `motion_collides_any` (whether it collides), per scalar on one motion and on a batch.
    fn motion_items(&self) -> Vec<(CollisionFunction, Form, Signature)> {
        let (p, n, world) = (&self.p, self.dof(), self.world());
        let resolution = quote!(resolution: impl ::core::convert::Into<#p::collision::Resolution>);
        let error = quote!(::core::result::Result<(), #p::KinematicsError>);
        let mut out = Vec::new();
        for scalar in self.scalar_types() {
            let (suffix, t) = (scalar.suffix, &scalar.t);
            let one = quote!(q0: &[#t; #n], q1: &[#t; #n], #world, #resolution);
            let motions = quote!(motions: &[([#t; #n], [#t; #n])], #world, #resolution);
            let first = quote!(::core::option::Option<f64>);
            for (function, form, name, inputs, output) in [
                (
                    CollisionFunction::MotionCollides,
                    Form::Typed(scalar.clone()),
                    "motion_collides",
                    one.clone(),
                    quote!(::core::result::Result<#first, #p::KinematicsError>),
                ),
                (
                    CollisionFunction::MotionCollides,
                    Form::Batch(scalar.clone()),
                    "motion_collides_batch",
                    quote!(#motions, out: &mut [#first]),
                    error.clone(),
                ),
                (
                    CollisionFunction::MotionCollidesAny,
                    Form::Typed(scalar.clone()),
                    "motion_collides_any",
                    one.clone(),
                    quote!(::core::result::Result<bool, #p::KinematicsError>),
                ),
                (
                    CollisionFunction::MotionCollidesAny,
                    Form::Batch(scalar.clone()),
                    "motion_collides_any_batch",
                    quote!(#motions, out: &mut [bool]),
                    error.clone(),
                ),
            ] {
                let name = format_ident!("{name}{suffix}");
                out.push((function, form, Signature { name, generics: Vec::new(), inputs, output }));
            }
        }
        out
    }

    /// `hold`: a held object's check tables.
    fn hold_item(&self) -> (CollisionFunction, Form, Signature) {
        let p = &self.p;
        let words = length(self.dims.held_words);
        (
            CollisionFunction::Hold,
            Form::Generic,
            Signature {
                name: format_ident!("hold"),
                // A lifetime no user's struct names: the impl's own generics are in scope here, and a
                // `'a` of theirs would be shadowed (an error).
                generics: vec![quote!('kinematics_spheres)],
                inputs: quote!(
                    link: &str, spheres: &'kinematics_spheres [#p::collision::SphereObstacle], touching: &[&str]
                ),
                output: quote!(
                    ::core::result::Result<
                        #p::collision::Held<'kinematics_spheres, Self, #words>,
                        #p::collision::HeldError,
                    >
                ),
            },
        )
    }

    /// The distances' functions: `clearance`, `clearance_gradient`, `proximity_cost` and
    /// `proximity_cost_gradient`, each per scalar on one configuration (dispatched), then on any
    /// lane type. A gradient has one entry per velocity (the Jacobians' columns); a cost takes a
    /// margin and refuses one that is negative or not finite.
    fn distance_items(&self) -> Vec<(CollisionFunction, Form, Signature)> {
        let (p, n, nv) = (&self.p, self.dof(), self.velocities());
        let environment = quote!(environment: &#p::collision::Environment<'_>);
        let mut out = Vec::new();
        for function in [
            CollisionFunction::Clearance,
            CollisionFunction::ClearanceGradient,
            CollisionFunction::ProximityCost,
            CollisionFunction::ProximityCostGradient,
        ] {
            let name = function.name();
            let (gradient, margin) = match function {
                CollisionFunction::ClearanceGradient => (true, false),
                CollisionFunction::ProximityCost => (false, true),
                CollisionFunction::ProximityCostGradient => (true, true),
                _ => (false, false),
            };
            let output = |t: &TokenStream| {
                let value = if gradient { quote!((#t, [#t; #nv])) } else { quote!(#t) };
                if margin { quote!(::core::result::Result<#value, #p::KinematicsError>) } else { value }
            };
            let margin = if margin { quote!(, margin: f64) } else { quote!() };
            for scalar in self.scalar_types() {
                let (suffix, t) = (scalar.suffix, &scalar.t);
                out.push((
                    function,
                    Form::Typed(scalar.clone()),
                    Signature {
                        name: format_ident!("{name}{suffix}"),
                        generics: Vec::new(),
                        inputs: quote!(q: &[#t; #n], #environment #margin),
                        output: output(t),
                    },
                ));
            }
            let scalar = &self.scalar;
            let generics = vec![self.collision_scalar()];
            out.push((
                function,
                Form::Generic,
                Signature {
                    name: format_ident!("{name}_generic"),
                    generics,
                    inputs: quote!(q: &[#scalar; #n], #environment #margin),
                    output: output(scalar),
                },
            ));
        }
        out
    }

    /// The generic scalar parameter of the collision checks: the trig bound and the checks'.
    fn collision_scalar(&self) -> TokenStream {
        let (p, scalar, bound) = (&self.p, &self.scalar, self.trig.bound(&self.p));
        quote!(#scalar: #bound + #p::collision::CheckLanes)
    }
}

impl CollisionFunction {
    /// The function's name on the type (a batch's and the generic one's stem).
    pub fn name(self) -> &'static str {
        match self {
            CollisionFunction::Collides => "collides",
            CollisionFunction::SelfCollides => "self_collides",
            CollisionFunction::MotionCollides => "motion_collides",
            CollisionFunction::CollidesAny => "collides_any",
            CollisionFunction::SelfCollidesAny => "self_collides_any",
            CollisionFunction::MotionCollidesAny => "motion_collides_any",
            CollisionFunction::Hold => "hold",
            CollisionFunction::Clearance => "clearance",
            CollisionFunction::ClearanceGradient => "clearance_gradient",
            CollisionFunction::ProximityCost => "proximity_cost",
            CollisionFunction::ProximityCostGradient => "proximity_cost_gradient",
        }
    }
}

/// One of the inverse kinematics' items.
#[derive(Debug, Clone)]
pub enum IkItem {
    /// `IK_FAMILY`.
    Family,
    /// `IK_ARM`, of this type.
    Arm(TokenStream),
    /// A function.
    Function(IkFunction, Signature),
}

/// The inverse kinematics' functions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IkFunction {
    /// `tip_ik`.
    All,
    /// `tip_ik_branch_generic`.
    Branch,
    /// `tip_ik_within_limits`.
    WithinLimits,
    /// `tip_ik_nearest`.
    Nearest,
    /// `tip_ik_numeric`.
    Numeric,
    /// `tip_ik_numeric_with`.
    NumericWith,
}
