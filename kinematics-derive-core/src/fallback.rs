//! What the derive emits beside its errors: a stub with the names the attribute implies, so one
//! fault does not cascade into "no function `tip_pose`" and "trait `Kinematics` not implemented"
//! errors wherever the struct is used (as thiserror's `fallback.rs` and serde_derive do).
//!
//! The stub never runs: the `compile_error!`s beside it stop the build. Its functions take and
//! return arrays of the robot's lengths when the description loaded; otherwise they are generic
//! over them (`q: &[f64; N]`, `[Pose<f64>; M]`, under names the user's generics cannot take), so
//! calls that fix the lengths type check whatever the robot was meant to be. The fallible ones return errors; the infallible ones
//! (`tip_pose`) have nothing to return and are `unreachable!`.

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
    let length = |known: Option<usize>, param: &TokenStream| match known {
        Some(n) => {
            let n = proc_macro2::Literal::usize_unsuffixed(n);
            (quote!(#n), None)
        }
        None => (param.clone(), Some(quote!(const #param: usize))),
    };
    let (dof, dof_param) = length(known.map(|k| k.dof), &quote!(__KINEMATICS_DOF));
    // Unknown, the velocities are taken to be as many as `q`'s entries (no floating joint), so a
    // call fixes both.
    let (nv, _) = length(known.map(|k| k.velocities), &dof);
    let (links, links_param) = length(known.map(|k| k.links), &quote!(__KINEMATICS_FRAMES));
    let (tips, tips_param) = length(names.tips, &quote!(__KINEMATICS_FRAMES));
    let mut functions = Vec::new();
    let mut function = |name: &str, frames: Option<&Option<TokenStream>>, ret: &dyn Fn(&TokenStream) -> TokenStream| {
        let params: Vec<&TokenStream> = dof_param.iter().chain(frames.into_iter().flatten()).collect();
        let attrs = quote!(#[allow(missing_docs, unused_variables, clippy::missing_panics_doc)]);
        for (suffix, t) in &scalars {
            let f = format_ident!("{name}{suffix}");
            let batch = format_ident!("{name}_batch{suffix}");
            let r = ret(t);
            functions.push(quote! {
                #attrs
                pub fn #f<#(#params),*>(q: &[#t; #dof]) -> #r {
                    ::core::unreachable!(#message)
                }
                #attrs
                pub fn #batch<#(#params),*>(qs: &[[#t; #dof]], out: &mut [#r]) -> ::core::result::Result<(), #p::KinematicsError> {
                    ::core::unreachable!(#message)
                }
            });
        }
        let f = format_ident!("{name}_generic");
        let scalar = quote!(__KinematicsScalar);
        let r = ret(&scalar);
        functions.push(quote! {
            #attrs
            pub fn #f<#scalar: #p::Real, #(#params),*>(q: &[#scalar; #dof]) -> #r {
                ::core::unreachable!(#message)
            }
        });
    };
    let pose = |t: &TokenStream| quote!(#p::Pose<#t>);
    function("link_poses", Some(&links_param), &|t| {
        let p = pose(t);
        quote!([#p; #links])
    });
    if names.one_tip {
        function("tip_pose", None, &pose);
    }
    if names.several_tips {
        function("tip_poses", Some(&tips_param), &|t| {
            let p = pose(t);
            quote!([#p; #tips])
        });
    }
    if names.positions {
        function("link_positions", Some(&links_param), &|t| quote!([[#t; 3]; #links]));
        if names.one_tip {
            function("tip_position", None, &|t| quote!([#t; 3]));
        }
        if names.several_tips {
            function("tip_positions", Some(&tips_param), &|t| quote!([[#t; 3]; #tips]));
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
            if names.one_tip {
                function(one, None, &|t| quote!([[#t; #nv]; #rows]));
            }
            if names.several_tips {
                function(several, Some(&tips_param), &|t| quote!([[[#t; #nv]; #rows]; #tips]));
            }
        }
        let pair = |t: &TokenStream| quote!((#p::Pose<#t>, [[#t; #nv]; 6]));
        if names.one_tip {
            function("tip_pose_and_jacobian", None, &pair);
        }
        if names.several_tips {
            function("tip_poses_and_jacobians", Some(&tips_param), &|t| {
                let pair = pair(t);
                quote!([#pair; #tips])
            });
        }
    }
    if names.jacobians {
        let attrs = quote!(#[allow(missing_docs, unused_variables, clippy::missing_panics_doc)]);
        let mut twists = Vec::new();
        if names.one_tip {
            twists.extend([("tip_twist", None), ("tip_twist_local", None)]);
        }
        if names.several_tips {
            twists.extend([("tip_twists", Some(&tips_param)), ("tip_twists_local", Some(&tips_param))]);
        }
        for (name, frames) in twists {
            let params: Vec<&TokenStream> = dof_param.iter().chain(frames.into_iter().flatten()).collect();
            let ret = |t: &TokenStream| if frames.is_some() { quote!([[#t; 6]; #tips]) } else { quote!([#t; 6]) };
            for (suffix, t) in &scalars {
                let f = format_ident!("{name}{suffix}");
                let r = ret(t);
                functions.push(quote! {
                    #attrs
                    pub fn #f<#(#params),*>(q: &[#t; #dof], qd: &[#t; #nv]) -> #r {
                        ::core::unreachable!(#message)
                    }
                });
            }
            let f = format_ident!("{name}_generic");
            let scalar = quote!(__KinematicsScalar);
            let r = ret(&scalar);
            functions.push(quote! {
                #attrs
                pub fn #f<#scalar: #p::Real, #(#params),*>(q: &[#scalar; #dof], qd: &[#scalar; #nv]) -> #r {
                    ::core::unreachable!(#message)
                }
            });
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
                pub fn tip_ik<#(#params),*>(target: &#p::Pose<f64> #free) -> #all { ::core::unreachable!(#message) }
                #attrs
                pub fn tip_ik_within_limits<#(#params),*>(target: &#p::Pose<f64> #free) -> #all { ::core::unreachable!(#message) }
                #attrs
                pub fn tip_ik_nearest<#(#params),*>(target: &#p::Pose<f64>, seed: &[f64; #dof]) -> #one { ::core::unreachable!(#message) }
            });
        }
        functions.push(quote! {
            #attrs
            pub fn tip_ik_numeric<#(#params),*>(target: &#p::Pose<f64>, seed: &[f64; #dof]) -> #numeric { ::core::unreachable!(#message) }
            #attrs
            pub fn tip_ik_numeric_with<#(#params),*>(target: &#p::Pose<f64>, seed: &[f64; #dof], options: &#p::ik::NumericOptions) -> #numeric {
                ::core::unreachable!(#message)
            }
        });
    }
    let velocity_const = known.map_or(0, |k| k.velocities);
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
