//! What the derive emits beside its errors: a stub with the names the attribute implies, so one
//! fault does not cascade into "no function `tip_pose`" and "trait `Kinematics` not implemented"
//! errors wherever the struct is used (as thiserror's `fallback.rs` and serde_derive do).
//!
//! The stub never runs: the `compile_error!`s beside it stop the build. Its functions take and
//! return arrays of the robot's lengths when the description loaded. Otherwise the number of
//! joints is a const parameter (`q: &[f64; N]`, under a name the user's generics cannot take),
//! which every call's `q` fixes, and an array of links or of tips no one could count is an
//! `UnknownLength` that indexes, iterates and compares as the array would, so
//! `let poses = Robot::link_poses(&q); poses[2]` adds no "type annotations needed" (a batch's
//! `out` gives its length, so batches keep a const parameter). The fallible ones return errors;
//! the infallible ones (`tip_pose`) have nothing to return and are `unreachable!`.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use syn::punctuated::Punctuated;

use crate::options::KinematicsInput;
use kinematics_compiler::robot::IkMode;

/// The inverse kinematics functions the attribute implies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum IkNames {
    /// None.
    Off,
    /// `tip_ik(&target)` and the numeric solver.
    ClosedForm,
    /// `tip_ik(&target, free)` and the numeric solver.
    Free,
    /// The numeric solver only.
    Numeric,
}

/// The function names the attribute implies.
#[derive(Debug, Clone, Copy)]
struct Names {
    /// `tip_pose` (one tip).
    one_tip: bool,
    /// `tip_poses` (several tips).
    several_tips: bool,
    /// The position functions.
    positions: bool,
    /// The velocity functions (`tip_jacobian`, ...).
    jacobians: bool,
    /// Which inverse kinematics functions.
    ik: IkNames,
    /// `f64` functions (no suffix).
    f64: bool,
    /// `_f32` functions.
    f32: bool,
    /// How many tips, if they could be counted.
    tips: Option<usize>,
    /// Which links `link_poses` returns.
    links: LinkCount,
}

/// How many links `link_poses` returns, as far as the attribute says.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum LinkCount {
    /// Every link but the base (no `links` key): the description's count, if it loaded.
    All,
    /// The entries of `links`.
    Listed(usize),
    /// A `links` key that could not be read.
    Unknown,
}

impl Names {
    /// Every name the derive can emit: for an attribute that cannot be read at all.
    const ALL: Names = Names {
        one_tip: true,
        several_tips: true,
        positions: true,
        jacobians: true,
        ik: IkNames::ClosedForm,
        f64: true,
        f32: true,
        tips: None,
        links: LinkCount::Unknown,
    };

    /// From options darling parsed (the scalar list may still be wrong: then both scalar types).
    fn from_options(options: &KinematicsInput) -> Self {
        let tips = options.tips().len();
        let (f64, f32) = match options.output().scalars() {
            Ok(s) => (s.f64, s.f32),
            Err(_) => (true, true),
        };
        Names {
            one_tip: tips == 1,
            several_tips: tips > 1,
            positions: options.output().positions,
            jacobians: options.output().jacobians.is_present(),
            ik: match options.output().ik_mode() {
                Ok(IkMode::Off) => IkNames::Off,
                Ok(IkMode::ClosedForm { free: Some(_) }) => IkNames::Free,
                Ok(IkMode::Numeric) => IkNames::Numeric,
                // An unknown kind: the closed form's names, the most a user would call.
                Ok(IkMode::ClosedForm { free: None }) | Err(_) => IkNames::ClosedForm,
            },
            f64,
            f32,
            tips: Some(tips),
            links: match &options.keys.links {
                Some(list) => LinkCount::Listed(list.as_ref().0.len()),
                None => LinkCount::All,
            },
        }
    }

    /// From the attribute's keys alone, when darling could not parse it: only which keys are
    /// there matters (`tip`, `tips(...)` and how many, `positions`, `scalars(...)`); whatever
    /// cannot be read counts as present.
    fn from_attributes(input: &syn::DeriveInput) -> Self {
        let mut names = Names {
            one_tip: false,
            several_tips: false,
            positions: false,
            jacobians: false,
            ik: IkNames::Off,
            f64: true,
            f32: false,
            tips: None,
            links: LinkCount::All,
        };
        let mut tips = 0usize;
        for attr in input.attrs.iter().filter(|a| a.path().is_ident("kinematics")) {
            let Ok(items) = attr.parse_args_with(Punctuated::<syn::Meta, syn::Token![,]>::parse_terminated) else {
                return Names::ALL;
            };
            for item in items {
                let path = item.path();
                if path.is_ident("tip") {
                    tips += 1;
                } else if path.is_ident("tips") {
                    match &item {
                        syn::Meta::List(list) => {
                            match list.parse_args_with(Punctuated::<syn::Expr, syn::Token![,]>::parse_terminated) {
                                Ok(list) => tips += list.len(),
                                Err(_) => (names.one_tip, names.several_tips) = (true, true),
                            }
                        }
                        _ => (names.one_tip, names.several_tips) = (true, true),
                    }
                } else if path.is_ident("links") {
                    names.links = match &item {
                        syn::Meta::NameValue(syn::MetaNameValue { value: syn::Expr::Array(list), .. }) => {
                            LinkCount::Listed(list.elems.len())
                        }
                        _ => LinkCount::Unknown,
                    };
                } else if path.is_ident("positions") {
                    names.positions = true;
                } else if path.is_ident("jacobians") {
                    names.jacobians = true;
                } else if path.is_ident("ik") {
                    names.ik = match &item {
                        syn::Meta::List(_) => IkNames::Free,
                        syn::Meta::NameValue(nv) if quote!(#nv).to_string().contains("\"numeric\"") => IkNames::Numeric,
                        _ => IkNames::ClosedForm,
                    };
                } else if path.is_ident("scalars") {
                    let text = match &item {
                        syn::Meta::List(list) => list.tokens.to_string(),
                        _ => String::new(),
                    };
                    let words: Vec<&str> = text.split(|c: char| !c.is_alphanumeric()).collect();
                    names.f32 = words.contains(&"f32") || !words.contains(&"f64");
                    names.f64 = words.contains(&"f64") || !words.contains(&"f32");
                }
            }
        }
        if !(names.one_tip || names.several_tips) {
            names.tips = Some(tips);
        }
        names.one_tip |= tips == 1;
        names.several_tips |= tips > 1;
        names
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

/// What is known of the robot when its description loaded (the fault was elsewhere): the stub's
/// functions then take and return arrays of the robot's own lengths.
#[derive(Debug, Clone, Copy)]
pub struct Known {
    /// Degrees of freedom.
    pub dof: usize,
    /// Velocities (a Jacobian's columns).
    pub velocities: usize,
    /// Links but the base (whatever the base: every link but one).
    pub links: usize,
}

/// How many values a stub function returns: one, or an array of them whose length is known or
/// not.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Frames {
    /// One value (`tip_pose`).
    One,
    /// An array (`link_poses`, `tip_poses`), of the length given if known.
    Many(Option<usize>),
}

/// The stub: `impl Type { ... }` with the constants, the functions the attribute implies and
/// `reference()`, and `impl Kinematics for Type`, in an anonymous block. Lengths not known (no
/// description, or tips that could not be counted) are const parameters of the functions, which
/// the call site infers.
pub fn stub(input: &syn::DeriveInput, options: Option<&KinematicsInput>, known: Option<Known>) -> TokenStream {
    let names = options.map_or_else(|| Names::from_attributes(input), Names::from_options);
    let krate = crate_path(input, options);
    let p = quote!(#krate::__private);
    let ident = &input.ident;
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let message = "the derive failed: its compile errors say why";
    let scalars: Vec<(&str, TokenStream)> = [(names.f64, "", quote!(f64)), (names.f32, "_f32", quote!(f32))]
        .into_iter()
        .filter(|(on, _, _)| *on)
        .map(|(_, suffix, t)| (suffix, t))
        .collect();
    let (dof, dof_param) = match known {
        Some(k) => {
            let n = proc_macro2::Literal::usize_unsuffixed(k.dof);
            (quote!(#n), None)
        }
        None => (quote!(__KINEMATICS_DOF), Some(quote!(const __KINEMATICS_DOF: usize))),
    };
    // Unknown, the velocities are taken to be as many as `q`'s entries (no floating joint), so a
    // call fixes both.
    let nv = match known {
        Some(k) => {
            let n = proc_macro2::Literal::usize_unsuffixed(k.velocities);
            quote!(#n)
        }
        None => dof.clone(),
    };
    let links = match names.links {
        LinkCount::All => known.map(|k| k.links),
        LinkCount::Listed(n) => Some(n),
        LinkCount::Unknown => None,
    };
    let tips = names.tips;
    let array = |elem: TokenStream, frames: Frames, batch: bool| match frames {
        Frames::One => elem,
        Frames::Many(Some(n)) => {
            let n = proc_macro2::Literal::usize_unsuffixed(n);
            quote!([#elem; #n])
        }
        // A batch's `out` gives the length; a value nothing gives it to is `UnknownLength`.
        Frames::Many(None) if batch => quote!([#elem; __KINEMATICS_FRAMES]),
        Frames::Many(None) => quote!(UnknownLength<#elem>),
    };
    let attrs = quote!(#[allow(missing_docs, unused_variables, clippy::missing_panics_doc)]);
    let mut functions = Vec::new();
    // `name` (and its batch per scalar, and `name_generic`), returning `frames` values of `elem`'s
    // type for the scalar; `rates`: the function takes the joint rates `qd` too (and has no batch).
    let mut function = |name: &str, frames: Frames, rates: bool, elem: &dyn Fn(&TokenStream) -> TokenStream| {
        let params: Vec<&TokenStream> = dof_param.iter().collect();
        let frames_param = (frames == Frames::Many(None)).then(|| quote!(const __KINEMATICS_FRAMES: usize));
        let batch_params: Vec<&TokenStream> = dof_param.iter().chain(&frames_param).collect();
        let qd = |t: &TokenStream| if rates { quote!(, qd: &[#t; #nv]) } else { quote!() };
        for (suffix, t) in &scalars {
            let f = format_ident!("{name}{suffix}");
            let (r, qd) = (array(elem(t), frames, false), qd(t));
            functions.push(quote! {
                #attrs
                pub fn #f<#(#params),*>(q: &[#t; #dof] #qd) -> #r {
                    ::core::unreachable!(#message)
                }
            });
            if !rates {
                let batch = format_ident!("{name}_batch{suffix}");
                let r = array(elem(t), frames, true);
                functions.push(quote! {
                    #attrs
                    pub fn #batch<#(#batch_params),*>(qs: &[[#t; #dof]], out: &mut [#r]) -> ::core::result::Result<(), #p::KinematicsError> {
                        ::core::unreachable!(#message)
                    }
                });
                let columns = format_ident!("{name}_batch_columns{suffix}");
                functions.push(quote! {
                    #attrs
                    pub fn #columns<#(#batch_params),*>(columns: [&[#t]; #dof], out: &mut [#r]) -> ::core::result::Result<(), #p::KinematicsError> {
                        ::core::unreachable!(#message)
                    }
                });
            }
        }
        let f = format_ident!("{name}_generic");
        let scalar = quote!(__KinematicsScalar);
        let (r, qd) = (array(elem(&scalar), frames, false), qd(&scalar));
        functions.push(quote! {
            #attrs
            pub fn #f<#scalar: #p::Real, #(#params),*>(q: &[#scalar; #dof] #qd) -> #r {
                ::core::unreachable!(#message)
            }
        });
    };
    let pose = |t: &TokenStream| quote!(#p::Pose<#t>);
    function("link_poses", Frames::Many(links), false, &pose);
    if names.one_tip {
        function("tip_pose", Frames::One, false, &pose);
    }
    if names.several_tips {
        function("tip_poses", Frames::Many(tips), false, &pose);
    }
    if names.positions {
        let position = |t: &TokenStream| quote!([#t; 3]);
        function("link_positions", Frames::Many(links), false, &position);
        if names.one_tip {
            function("tip_position", Frames::One, false, &position);
        }
        if names.several_tips {
            function("tip_positions", Frames::Many(tips), false, &position);
        }
    }
    if names.jacobians {
        // (one tip, several tips, rows)
        let mut velocity = vec![("tip_jacobian", "tip_jacobians", 6), ("tip_jacobian_local", "tip_jacobians_local", 6)];
        if names.positions {
            velocity.push(("tip_position_jacobian", "tip_position_jacobians", 3));
        }
        for (one, several, rows) in velocity {
            let rows = proc_macro2::Literal::usize_unsuffixed(rows);
            let jacobian = |t: &TokenStream| quote!([[#t; #nv]; #rows]);
            if names.one_tip {
                function(one, Frames::One, false, &jacobian);
            }
            if names.several_tips {
                function(several, Frames::Many(tips), false, &jacobian);
            }
        }
        let pair = |t: &TokenStream| quote!((#p::Pose<#t>, [[#t; #nv]; 6]));
        if names.one_tip {
            function("tip_pose_and_jacobian", Frames::One, false, &pair);
        }
        if names.several_tips {
            function("tip_poses_and_jacobians", Frames::Many(tips), false, &pair);
        }
        let twist = |t: &TokenStream| quote!([#t; 6]);
        for (name, frames) in [("tip_twist", Frames::One), ("tip_twists", Frames::Many(tips))] {
            if (frames == Frames::One && names.one_tip) || (frames != Frames::One && names.several_tips) {
                function(name, frames, true, &twist);
                function(&format!("{name}_local"), frames, true, &twist);
            }
        }
    }
    let dof_const = known.map_or(0, |k| k.dof);
    if names.ik != IkNames::Off {
        let attrs = quote!(#[allow(missing_docs, unused_variables, clippy::missing_panics_doc)]);
        let params: Vec<&TokenStream> = dof_param.iter().collect();
        let result = |t: TokenStream| quote!(::core::result::Result<#t, #p::ik::IkError>);
        let all = result(quote!(#p::ik::IkSolutions<#dof, 8>));
        let one = result(quote!(::core::option::Option<#p::ik::IkSolution<#dof>>));
        let numeric = result(quote!(#p::ik::NumericSolution<#dof>));
        let free = (names.ik == IkNames::Free).then(|| quote!(, free: f64));
        if names.ik != IkNames::Numeric {
            functions.push(quote! {
                pub const IK_FAMILY: &'static str = "";
                #attrs
                pub fn tip_ik<#(#params),*>(target: &impl #p::ik::IkTarget #free) -> #all { ::core::unreachable!(#message) }
                #attrs
                pub fn tip_ik_within_limits<#(#params),*>(target: &impl #p::ik::IkTarget #free) -> #all { ::core::unreachable!(#message) }
                #attrs
                pub fn tip_ik_nearest<#(#params),*>(target: &impl #p::ik::IkTarget, seed: &[f64; #dof]) -> #one { ::core::unreachable!(#message) }
            });
        }
        functions.push(quote! {
            #attrs
            pub fn tip_ik_numeric<#(#params),*>(target: &impl #p::ik::IkTarget, seed: &[f64; #dof]) -> #numeric { ::core::unreachable!(#message) }
            #attrs
            pub fn tip_ik_numeric_with<#(#params),*>(target: &impl #p::ik::IkTarget, seed: &[f64; #dof], options: &#p::ik::NumericOptions) -> #numeric {
                ::core::unreachable!(#message)
            }
        });
    }
    let velocity_const = known.map_or(0, |k| k.velocities);
    let unknown_length = unknown_length(message);
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
            #unknown_length

            #[allow(dead_code, missing_docs)]
            impl #impl_generics #ident #ty_generics #where_clause {
                pub const ROBOT: &'static str = "";
                pub const BASE: &'static str = "";
                pub const DOF: usize = #dof_const;
                pub const VELOCITY_DOF: usize = #velocity_const;
                pub const VELOCITY_NAMES: &'static [&'static str] = &[];
                pub const JOINT_NAMES: &'static [&'static str] = &[];
                pub const JOINT_LIMITS: &'static [#p::JointLimits] = &[];
                pub const LINK_NAMES: &'static [&'static str] = &[];
                pub const TIPS: &'static [&'static str] = &[];
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

/// The type a stub function returns for an array whose length no one knows (the links of a
/// description that could not be read, tips that could not be counted): an array type would need
/// that length, and a const parameter for it is "type annotations needed" wherever the call's
/// value is used without one (`let poses = Robot::link_poses(&q); poses[2]`). It acts as the array
/// would where no length is written: indexing, `len`, `iter`, `for` (through `Deref` to a slice
/// and `IntoIterator`), `==` with arrays. Code that writes the length down
/// (`let poses: [Pose<f64>; 9] = ...`, `let [a, b] = ...`) gets a second error naming
/// `UnknownLength`: no one type can be an array of every length. The batches take their
/// length from `out`, so they keep a const parameter.
fn unknown_length(message: &str) -> TokenStream {
    quote! {
        /// The value of a stub function whose length the derive could not know.
        #[allow(dead_code)]
        #[derive(Debug, Clone, Copy)]
        pub struct UnknownLength<T>(::core::marker::PhantomData<T>);

        impl<T> ::core::ops::Deref for UnknownLength<T> {
            type Target = [T];
            fn deref(&self) -> &[T] {
                ::core::unreachable!(#message)
            }
        }

        impl<T> ::core::ops::DerefMut for UnknownLength<T> {
            fn deref_mut(&mut self) -> &mut [T] {
                ::core::unreachable!(#message)
            }
        }

        impl<T> ::core::iter::IntoIterator for UnknownLength<T> {
            type Item = T;
            type IntoIter = ::core::iter::Empty<T>;
            fn into_iter(self) -> Self::IntoIter {
                ::core::unreachable!(#message)
            }
        }

        impl<'a, T> ::core::iter::IntoIterator for &'a UnknownLength<T> {
            type Item = &'a T;
            type IntoIter = ::core::slice::Iter<'a, T>;
            fn into_iter(self) -> Self::IntoIter {
                ::core::unreachable!(#message)
            }
        }

        impl<T> ::core::cmp::PartialEq for UnknownLength<T> {
            fn eq(&self, _: &Self) -> bool {
                ::core::unreachable!(#message)
            }
        }

        impl<T, const N: usize> ::core::cmp::PartialEq<[T; N]> for UnknownLength<T> {
            fn eq(&self, _: &[T; N]) -> bool {
                ::core::unreachable!(#message)
            }
        }

        impl<T, const N: usize> ::core::cmp::PartialEq<UnknownLength<T>> for [T; N] {
            fn eq(&self, _: &UnknownLength<T>) -> bool {
                ::core::unreachable!(#message)
            }
        }
    }
}
