//! What the derive emits beside its errors: a stub with the names the attribute implies, so one
//! fault does not cascade into "no function `tip_pose`" and "trait `Kinematics` not implemented"
//! errors wherever the struct is used (as thiserror's `fallback.rs` and serde_derive do).
//!
//! The stub is the API surface the emitter writes ([`kinematics_compiler::robot::surface`]: the
//! same list of items, the same signatures) with bodies that never run: the `compile_error!`s
//! stop the build. Its functions take and return arrays of the robot's lengths when the
//! description loaded. A length no one could know is the constant
//! [`UNKNOWN_LENGTH`](kinematics_compiler::robot::surface::UNKNOWN_LENGTH), whose value is the
//! derive's first `compile_error!` itself: to rustc its value is an error already reported, so
//! every type it is part of is an error type, and rustc reports nothing more about code that uses
//! one (a seed built by `std::array::from_fn`, links destructured into a pattern of any length).
//! One mistake, one error. A test holds the stub's items equal to the emitted ones for every
//! combination of options.

use std::collections::BTreeSet;

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::punctuated::Punctuated;

use crate::options::KinematicsInput;
use kinematics_compiler::collision_layout::held_words;
use kinematics_compiler::dynamics::DynamicsRequest;
use kinematics_compiler::ik::IkPlan;
use kinematics_compiler::options::{IkKind, IkMode, Options, Scalars, choose};
use kinematics_compiler::robot::scalar_parameter;
use kinematics_compiler::robot::surface::{
    Constant, Dims, IkItem, IkShape, Render, UNKNOWN_LENGTH, constants, outputs,
};
use kinematics_model::KinematicTree;
use kinematics_model::collision::link_spheres;

/// What the stub knows: the options (as read, or as far as a lenient reading of the attribute
/// goes), the lengths, and the inverse kinematics' plan if the chain was classified.
#[derive(Debug, Clone)]
pub struct Implied {
    /// The options.
    pub options: Options,
    /// Whether the tips could be counted (else the stub has both `tip_pose` and `tip_poses`).
    pub tips_counted: bool,
    /// Whether `links` could be read (else `link_poses` returns an array of unknown length).
    pub links_read: bool,
    /// The robot, when its description loaded.
    pub dims: Dims,
    /// The plan, when `ik` asked for a closed form and the chain has one.
    pub ik_plan: Option<Box<IkPlan>>,
}

impl Implied {
    /// From options darling read.
    pub fn from_options(options: Options) -> Self {
        Implied { options, tips_counted: true, links_read: true, dims: Dims::default(), ik_plan: None }
    }

    /// From the attribute's keys alone, when darling could not read it: only which keys are there
    /// matters (`tip`, `tips(...)` and how many, `links = [...]` and how many, `positions`,
    /// `jacobians`, `ik` and its kind, `dynamics`, `scalars(...)`); whatever cannot be read counts
    /// as present.
    pub fn from_attributes(input: &syn::DeriveInput) -> Self {
        let mut options = Options::default();
        let (mut tips, mut tips_counted, mut links_read) = (0usize, true, true);
        for attr in input.attrs.iter().filter(|a| a.path().is_ident("kinematics")) {
            let Ok(items) = attr.parse_args_with(Punctuated::<syn::Meta, syn::Token![,]>::parse_terminated) else {
                return Implied::everything();
            };
            for item in items {
                let path = item.path();
                if path.is_ident("tip") {
                    tips += 1;
                } else if path.is_ident("tips") {
                    let list = match &item {
                        syn::Meta::List(list) => {
                            list.parse_args_with(Punctuated::<syn::Expr, syn::Token![,]>::parse_terminated).ok()
                        }
                        _ => None,
                    };
                    match list {
                        Some(list) => tips += list.len(),
                        None => tips_counted = false,
                    }
                } else if path.is_ident("links") {
                    match &item {
                        syn::Meta::NameValue(syn::MetaNameValue { value: syn::Expr::Array(list), .. }) => {
                            options.links = Some(vec![String::new(); list.elems.len()]);
                        }
                        _ => links_read = false,
                    }
                } else if path.is_ident("positions") {
                    options.positions = true;
                } else if path.is_ident("jacobians") {
                    options.jacobians = true;
                } else if path.is_ident("ik") {
                    options.ik = match &item {
                        syn::Meta::List(_) => IkMode::ClosedForm { free: Some(String::new()) },
                        syn::Meta::NameValue(syn::MetaNameValue {
                            value: syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(kind), .. }),
                            ..
                        }) if choose::<IkKind>(&kind.value()) == Ok(IkKind::Numeric) => IkMode::Numeric,
                        // An unknown kind: the closed form's names, the most a user would call.
                        _ => IkMode::ClosedForm { free: None },
                    };
                } else if path.is_ident("dynamics") {
                    // Its functions' names and types do not depend on the gravity or the
                    // inertias, whatever of the key could not be read.
                    options.dynamics = Some(DynamicsRequest::default());
                } else if path.is_ident("scalars") {
                    let words = match &item {
                        syn::Meta::List(list) => list
                            .parse_args_with(Punctuated::<syn::Path, syn::Token![,]>::parse_terminated)
                            .map(|paths| paths.iter().filter_map(|p| p.get_ident().map(ToString::to_string)).collect())
                            .unwrap_or_default(),
                        _ => Vec::new(),
                    };
                    options.scalars =
                        Scalars { f64: words.iter().any(|w| w == "f64"), f32: words.iter().any(|w| w == "f32") };
                }
            }
        }
        // One tip for each counted, or both forms when they could not be counted.
        options.tips = vec![String::new(); if tips_counted { tips } else { 2 }];
        Implied { options, tips_counted, links_read, dims: Dims::default(), ik_plan: None }
    }

    /// Every name the derive can emit: for an attribute that cannot be read at all.
    fn everything() -> Self {
        let options = Options {
            tips: vec![String::new(); 2],
            positions: true,
            jacobians: true,
            ik: IkMode::ClosedForm { free: None },
            scalars: Scalars { f64: true, f32: true },
            dynamics: Some(DynamicsRequest::default()),
            ..Options::default()
        };
        Implied { options, tips_counted: false, links_read: false, dims: Dims::default(), ik_plan: None }
    }

    /// With the lengths of the robot that loaded (the fault was elsewhere): the stub's functions
    /// then take and return arrays of the robot's own lengths.
    pub fn with_robot(mut self, tree: &KinematicTree) -> Self {
        // The cover, when it can be made (a mesh refused leaves its counts unknown).
        let spheres = self
            .options
            .collision
            .as_ref()
            .and_then(|c| c.cover.fault().is_none().then(|| link_spheres(tree, &c.cover, c.meshes).ok()).flatten());
        let links = match &self.options.links {
            Some(listed) => listed.len(),
            // Every link but the base, whatever the base.
            None => tree.links().len().saturating_sub(1),
        };
        self.dims = Dims {
            dof: Some(tree.dof()),
            velocities: Some(tree.velocity_dof()),
            links: self.links_read.then_some(links),
            tips: self.tips_counted.then_some(self.options.tips.len()),
            // The cover's count, when it can be made (a mesh refused leaves it unknown).
            spheres: spheres.as_ref().map(Vec::len),
            held_words: spheres.as_deref().map(held_words),
            forces: self.dims.forces,
        };
        self
    }

    /// With the inverse kinematics' plan, when the chain was classified.
    pub fn with_plan(mut self, plan: Option<Box<IkPlan>>) -> Self {
        self.ik_plan = plan;
        self
    }

    /// The lengths as far as they are known without a robot.
    fn dims(&self) -> Dims {
        let listed = self.options.links.as_ref().map(Vec::len);
        Dims {
            links: self.dims.links.or(if self.links_read { listed } else { None }),
            tips: self.dims.tips.or(self.tips_counted.then_some(self.options.tips.len())),
            forces: self.options.dynamics.as_ref().map_or(0, |d| d.forces.len()),
            ..self.dims
        }
    }
}

/// The crate path from `crate = "..."`, read leniently, or `::kinematics`.
fn crate_path(input: &syn::DeriveInput, options: Option<&KinematicsInput>) -> TokenStream {
    if let Some(path) = options.and_then(|o| o.output().krate.as_ref()) {
        return quote!(#path);
    }
    for attr in input.attrs.iter().filter(|a| a.path().is_ident("kinematics")) {
        let Ok(items) = attr.parse_args_with(Punctuated::<syn::Meta, syn::Token![,]>::parse_terminated) else {
            continue;
        };
        for item in items {
            if let syn::Meta::NameValue(nv) = item
                && nv.path.is_ident("crate")
                && let syn::Expr::Lit(syn::ExprLit { lit: syn::Lit::Str(s), .. }) = &nv.value
                && let Ok(path) = s.parse::<syn::Path>()
            {
                return quote!(#path);
            }
        }
    }
    quote!(::kinematics)
}

/// The stub: `impl Type { ... }` with the constants and functions the surface lists for the
/// implied options and `reference()`, and `impl Kinematics for Type`, in an anonymous block
/// beside the unknown length's constant, whose value is `first_error` (a `compile_error!`
/// invocation: the derive's first error, which the stub thereby reports).
pub fn stub(
    input: &syn::DeriveInput,
    options: Option<&KinematicsInput>,
    implied: &Implied,
    first_error: TokenStream,
) -> TokenStream {
    let krate = crate_path(input, options);
    let p = quote!(#krate::__private);
    let unknown = format_ident!("{UNKNOWN_LENGTH}");
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let message = "the derive failed: its compile errors say why";
    let mut scalars = implied.options.scalars;
    if !scalars.f64 && !scalars.f32 {
        // A list that named none (or none readably): both.
        scalars = Scalars { f64: true, f32: true };
    }
    let render = Render {
        p: p.clone(),
        scalars,
        scalar: scalar_parameter(&quote!(#impl_generics)),
        trig: implied.options.trig,
        dims: implied.dims(),
    };
    let attrs = quote!(#[allow(missing_docs, unused_variables, clippy::missing_panics_doc)]);
    let constants = constants(&implied.options).into_iter().map(|constant| {
        let name = format_ident!("{}", constant.name());
        let ty = render.constant_type(constant);
        let value = constant_value(&render, constant, &p);
        quote!(pub const #name: #ty = #value;)
    });
    let mut functions = Vec::new();
    let mut seen = BTreeSet::new();
    // Tips that could not be counted: both the one tip's names and several tips'.
    let one_tip = implied.options.tips.len() == 1;
    let forms: &[bool] = if implied.tips_counted { &[one_tip][..] } else { &[true, false][..] };
    for &one in forms {
        for output in outputs(&implied.options) {
            for (_, signature) in render.functions(output, one) {
                if seen.insert(signature.name.to_string()) {
                    let sig = signature.tokens();
                    functions.push(quote!(#attrs #sig { ::core::unreachable!(#message) }));
                }
            }
        }
    }
    if let Some(shape) = IkShape::implied(&implied.options, implied.ik_plan.as_deref()) {
        functions.extend(ik_items(&render, &shape, &attrs, message));
    }
    if implied.options.collision.is_some() {
        for (_, _, signature) in render.collision_items() {
            let sig = signature.tokens();
            functions.push(quote!(#attrs #sig { ::core::unreachable!(#message) }));
        }
    }
    let load_error = quote! {
        ::core::result::Result::Err(#p::LoadError::new(
            "",
            #p::LoadErrorKind::Syntax { line: ::core::option::Option::None, message: ::std::string::String::from(#message) },
        ))
    };
    let kinematics_error = quote! {
        ::core::result::Result::Err(#p::KinematicsError::WrongOutputLength { robot: #message, expected: 0, got: out.len() })
    };
    quote! {
        const _: () = {
            #[allow(dead_code)]
            const #unknown: usize = #first_error;

            #[allow(dead_code, missing_docs)]
            impl #impl_generics #ident #ty_generics #where_clause {
                #(#constants)*
                #(#functions)*
                #p::with_std! {
                    pub fn reference() -> ::core::result::Result<#p::ReferenceFk, #p::LoadError> {
                        #load_error
                    }
                }
            }

            impl #impl_generics #p::Kinematics for #ident #ty_generics #where_clause {
                const ROBOT: &'static str = "";
                const BASE: &'static str = "";
                const DOF: usize = 0;
                const JOINT_NAMES: &'static [&'static str] = &[];
                const JOINT_LIMITS: &'static [#p::JointLimits] = &[];
                const LINK_NAMES: &'static [&'static str] = &[];
                const TIPS: &'static [&'static str] = &[];
                fn tip_poses_into(q: &[f64], out: &mut [#p::Pose<f64>]) -> ::core::result::Result<(), #p::KinematicsError> {
                    let _ = q;
                    #kinematics_error
                }
                fn link_poses_into(q: &[f64], out: &mut [#p::Pose<f64>]) -> ::core::result::Result<(), #p::KinematicsError> {
                    let _ = q;
                    #kinematics_error
                }
            }

            #p::with_std! {
                impl #impl_generics #p::ReferenceModel for #ident #ty_generics #where_clause {
                    fn reference() -> ::core::result::Result<#p::ReferenceFk, #p::LoadError> {
                        #load_error
                    }
                }
            }
        };
    }
}

/// The inverse kinematics' stub items of `shape`: constants whose values never run, functions
/// that are `unreachable!`. A family the derive could not tell gets an `IK_ARM` of a type that
/// is an error (see the module's doc), so code using it reports nothing more.
fn ik_items(render: &Render, shape: &IkShape, attrs: &TokenStream, message: &str) -> Vec<TokenStream> {
    let unknown = format_ident!("{UNKNOWN_LENGTH}");
    render
        .ik_items(shape)
        .into_iter()
        .map(|item| match item {
            IkItem::Family => {
                let arm = shape
                    .closed_form
                    .as_ref()
                    .is_some_and(|closed| closed.arm.is_none())
                    .then(|| quote!(pub const IK_ARM: [(); #unknown] = ::core::panic!(#message);));
                quote!(
                    pub const IK_FAMILY: &'static str = "";
                    #arm
                )
            }
            IkItem::Arm(ty) => quote!(pub const IK_ARM: #ty = ::core::panic!(#message);),
            IkItem::Function(_, signature) => {
                let sig = signature.tokens();
                quote!(#attrs #sig { ::core::unreachable!(#message) })
            }
        })
        .collect()
}

/// A stand-in value of a constant of the type the surface gives it: empty names, no limits, the
/// robot's lengths where known (zero otherwise).
fn constant_value(render: &Render, constant: Constant, p: &TokenStream) -> TokenStream {
    let count = |n: Option<usize>, element: TokenStream| match n {
        Some(n) => {
            let n = proc_macro2::Literal::usize_unsuffixed(n);
            quote!([#element; #n])
        }
        None => {
            let unknown = format_ident!("{UNKNOWN_LENGTH}");
            quote!([#element; #unknown])
        }
    };
    let dims = render.dims;
    let limits = quote!(#p::JointLimits {
        lower: ::core::primitive::f64::NEG_INFINITY,
        upper: ::core::primitive::f64::INFINITY,
    });
    match constant {
        Constant::Robot | Constant::Base => quote!(""),
        Constant::Dof => {
            let n = proc_macro2::Literal::usize_unsuffixed(dims.dof.unwrap_or(0));
            quote!(#n)
        }
        Constant::VelocityDof => {
            let n = proc_macro2::Literal::usize_unsuffixed(dims.velocities.or(dims.dof).unwrap_or(0));
            quote!(#n)
        }
        Constant::JointNames => count(dims.dof, quote!("")),
        Constant::VelocityNames => count(dims.velocities.or(dims.dof), quote!("")),
        Constant::JointLimits => count(dims.dof, limits),
        Constant::LinkNames => count(dims.links, quote!("")),
        Constant::Tips => count(dims.tips, quote!("")),
        Constant::SphereRadii => count(dims.spheres, quote!(0.0)),
        Constant::SphereLinks => count(dims.spheres, quote!("")),
        Constant::ForceLinks => count(Some(dims.forces), quote!("")),
    }
}

#[cfg(test)]
mod tests {
    //! The stub lists what the emitter writes, signature for signature, for every option set.

    use kinematics_compiler::dynamics::DynamicsRequest;
    use kinematics_compiler::options::{CheckedIk, CollisionOptions, Cover, IkMode, Options, Scalars, Trig};
    use kinematics_compiler::robot::{RobotSpec, emit_robot};
    use kinematics_model::{ExactAngles, KinematicTree, Source, SourceKind};
    use quote::quote;

    use super::{Implied, stub};

    /// The inherent impl's items (a constant's type, a function's signature) in order, without
    /// attributes, values or bodies; `with_std!` (the reference) left out.
    fn surface(tokens: proc_macro2::TokenStream) -> Vec<String> {
        let file: syn::File = syn::parse2(tokens).unwrap();
        let mut items = Vec::new();
        for item in file.items {
            let syn::Item::Const(block) = item else { continue };
            let syn::Expr::Block(block) = *block.expr else { continue };
            for statement in block.block.stmts {
                let syn::Stmt::Item(syn::Item::Impl(imp)) = statement else { continue };
                if imp.trait_.is_some() {
                    continue;
                }
                for item in imp.items {
                    match item {
                        syn::ImplItem::Const(c) => {
                            let (name, ty) = (&c.ident, &c.ty);
                            items.push(quote!(const #name: #ty).to_string());
                        }
                        syn::ImplItem::Fn(f) => {
                            let sig = &f.sig;
                            items.push(quote!(#sig).to_string());
                        }
                        _ => {}
                    }
                }
            }
        }
        items
    }

    fn robot(file: &str) -> KinematicTree {
        robot_with(file, None)
    }

    /// `robots/file`, with a free-flying root when `floating_base` names the new root link.
    fn robot_with(file: &str, floating_base: Option<&str>) -> KinematicTree {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../robots").join(file);
        let source = Source::from_bytes(file, SourceKind::ByExtension, std::fs::read(path).unwrap()).unwrap();
        source.load_with_floating_base(ExactAngles::default(), floating_base).unwrap()
    }

    /// Every combination of tips, positions, Jacobians, inverse kinematics and scalars on robots
    /// of each kind of plan (a compiled six-joint body, the run time's solver, a planar arm, a
    /// free joint, none), with the link list and trig alternating, and on the arms with inertias the
    /// dynamics every other `ik`: the stub given the robot's lengths (and the plan) lists exactly
    /// the emitted items.
    #[test]
    fn the_stub_lists_what_the_emitter_writes() {
        let robots = [
            ("ur5.urdf", ["tool0", "wrist_2_link"], None),
            ("puma560.toml", ["link6", "link3"], None),
            ("planar_3r.urdf", ["tool", "link2"], None),
            ("iiwa14.urdf", ["iiwa_link_ee", "iiwa_link_3"], Some("iiwa_joint_3")),
            ("humanoid.urdf", ["l_sole", "r_sole"], None),
            ("ur5_primitives.urdf", ["tool0", "wrist_2_link"], None),
        ];
        // One thread per robot: the longest unit test of a cold `cargo test` otherwise.
        let compared: usize = std::thread::scope(|scope| {
            let threads = robots.map(|(file, tips, free)| scope.spawn(move || stub_matches_emitted(file, tips, free)));
            threads.into_iter().map(|t| t.join().expect("a robot's comparison panicked")).sum()
        });
        // Per robot and scalar list, the four position and Jacobian choices: with one tip, `ik` off
        // and numeric, with two, `ik` off (the rules refuse `ik` of two tips); and with one tip
        // the closed form on the five robots that have one (the humanoid's leg has none).
        assert_eq!(compared, 3 * 4 * (6 * (2 + 1) + 5), "option sets compared");
    }

    /// The option sets of [`the_stub_lists_what_the_emitter_writes`] on one robot: how many were
    /// compared (the rules refuse some).
    fn stub_matches_emitted(file: &str, tips: [&str; 2], free: Option<&str>) -> usize {
        let mut compared = 0;
        let tree = robot(file);
        let dynamics =
            Options { dynamics: Some(DynamicsRequest::default()), ..Options::default() }.check(&tree).is_ok();
        // The robots with inertias: the two arms and the humanoid. The arms' dynamics are compared
        // here; the humanoid's would add 25 velocities' worth of compile time to the longest unit
        // test and no item the arms' do not list.
        let with_inertias = file.starts_with("ur5") || file == "humanoid.urdf";
        assert_eq!(dynamics, with_inertias, "{file}: the rules' verdict on `dynamics`");
        let dynamics = dynamics && file.starts_with("ur5");
        let links: Vec<String> = tree.links().iter().rev().take(2).map(|l| l.name.clone()).collect();
        let mut case = 0;
        for several in [false, true] {
            for (positions, jacobians) in [(false, false), (true, false), (false, true), (true, true)] {
                for ik in [IkMode::Off, IkMode::ClosedForm { free: free.map(str::to_owned) }, IkMode::Numeric] {
                    for scalars in [(true, false), (false, true), (true, true)] {
                        case += 1;
                        let options = Options {
                            tips: tips[..if several { 2 } else { 1 }].iter().map(|t| (*t).to_owned()).collect(),
                            positions,
                            jacobians,
                            ik: ik.clone(),
                            scalars: Scalars { f64: scalars.0, f32: scalars.1 },
                            links: (case % 3 == 0).then(|| links.clone()),
                            trig: if case % 2 == 0 { Trig::Std } else { Trig::Fast },
                            // The arm with primitive geometry gets its sphere centres.
                            collision: (file == "ur5_primitives.urdf").then(|| CollisionOptions {
                                cover: Cover::overshoot(0.03),
                                ..CollisionOptions::default()
                            }),
                            // The arms with inertias, every other `ik`, their dynamics.
                            dynamics: (dynamics && (case - 1) / 3 % 2 == 0).then(DynamicsRequest::default),
                            ..Options::default()
                        };
                        compared += usize::from(stub_matches(file, &tree, &options));
                    }
                }
            }
        }
        compared
    }

    /// Whether the rules take `options` on `tree`; if so, asserts that the stub given the robot's
    /// lengths (and the plan) lists exactly the emitted items.
    fn stub_matches(file: &str, tree: &KinematicTree, options: &Options) -> bool {
        let Ok(checked) = options.check(tree) else { return false };
        let plan = match checked.ik() {
            CheckedIk::ClosedForm(plan) => Some(plan.clone()),
            _ => None,
        };
        let spec = RobotSpec {
            robot: checked,
            krate: quote!(::kinematics),
            source_label: file.to_owned(),
            source_text: quote!(""),
            source_files: None,
            impl_generics: quote!(),
            where_clause: quote!(),
        };
        let emitted = emit_robot(&quote!(Robot), &spec).unwrap();
        let input: syn::DeriveInput = syn::parse2(quote!(
            struct Robot;
        ))
        .unwrap();
        let implied = Implied::from_options(options.clone()).with_robot(tree).with_plan(plan);
        let stubbed = stub(&input, None, &implied, quote!(::core::compile_error!("")));
        assert_eq!(surface(stubbed), surface(emitted), "{file}: {options:?}");
        true
    }

    /// The dynamics of a free-flying UR5 (a quaternion in `q`: thirteen entries, twelve
    /// velocities) and of the Panda, in each scalar list: the stub lists the emitted items.
    #[test]
    fn the_stub_lists_the_dynamics_the_emitter_writes() {
        let mut compared = 0;
        for (file, floating_base) in [("ur5.urdf", Some("world")), ("panda.urdf", None)] {
            let tree = robot_with(file, floating_base);
            assert!(tree.velocity_dof() == 12 || floating_base.is_none());
            for scalars in [(true, false), (false, true), (true, true)] {
                let options = Options {
                    floating_base: floating_base.map(str::to_owned),
                    scalars: Scalars { f64: scalars.0, f32: scalars.1 },
                    dynamics: Some(DynamicsRequest {
                        gravity: [0.0, 0.0, 0.0],
                        inertia_as_written: true,
                        // External forces on the last link and one moved by the first joint.
                        forces: if file == "panda.urdf" {
                            vec!["panda_hand".to_owned(), "panda_link1".to_owned()]
                        } else {
                            vec!["tool0".to_owned()]
                        },
                    }),
                    ..Options::default()
                };
                assert!(stub_matches(file, &tree, &options), "{file}: the rules refused {options:?}");
                compared += 1;
            }
        }
        assert_eq!(compared, 6);
    }

    /// A failing attribute darling cannot read keeps the dynamics' names in its stub: every one of
    /// the five functions, in the scalars listed.
    #[test]
    fn an_unreadable_dynamics_key_keeps_its_functions() {
        let input: syn::DeriveInput = syn::parse2(quote!(
            #[kinematics(urdf = "ur5.urdf", dynamics(gravity = "down"), scalars(f32))]
            struct Robot;
        ))
        .unwrap();
        let implied = Implied::from_attributes(&input);
        assert!(implied.options.dynamics.is_some());
        let stubbed = surface(stub(&input, None, &implied, quote!(::core::compile_error!(""))));
        for name in ["gravity_torques_f32", "inverse_dynamics_f32", "nonlinear_effects_f32", "mass_matrix_batch_f32"] {
            assert!(stubbed.iter().any(|s| s.starts_with(&format!("fn {name} ("))), "{name} in {stubbed:?}");
        }
        assert!(stubbed.iter().any(|s| s.starts_with("fn forward_dynamics_generic <")), "{stubbed:?}");
        assert!(!stubbed.iter().any(|s| s.starts_with("fn gravity_torques (")), "{stubbed:?}");
        // An attribute that cannot be read at all: every name, the dynamics' too.
        let everything = surface(stub(&input, None, &Implied::everything(), quote!(::core::compile_error!(""))));
        assert!(everything.iter().any(|s| s.starts_with("fn mass_matrix (")), "{everything:?}");
    }
}
