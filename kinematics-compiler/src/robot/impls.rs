//! The block around everything: the generic bodies, the type's `impl` (constants, functions,
//! `reference()`), `impl Kinematics`, `impl Collision<DOF, VELOCITIES>` (with collision checking and `f64`)
//! and `impl ReferenceModel`.
//!
//! `reference()` and `impl ReferenceModel` sit inside the facade's `with_std!`, parsing with the
//! tree's exactness policy.

use kinematics_model::ExactAngles;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::functions::Functions;
use super::{Context, constants, number};

/// The whole output, `const _: () = { ... };`, for `self_ty` with the functions of `out`.
pub(super) fn robot_block(self_ty: &TokenStream, cx: &Context<'_>, out: &Functions) -> TokenStream {
    let p = &cx.p;
    let (generic, typed) = (&out.generic, &out.typed);
    let (impl_generics, where_clause) = (&cx.spec.impl_generics, &cx.spec.where_clause);
    let inherent = constants::inherent(cx);
    let of_trait = constants::of_trait(cx);
    let reference = reference(cx);
    let into = trait_functions(cx);
    let collision = collision_impl(self_ty, cx);
    quote! {
        const _: () = {
        mod bodies {
            #(#generic)*
        }
        use bodies::*;

        #[allow(clippy::approx_constant)] // limits and offsets are kept exactly as the description gives them
        #[allow(clippy::type_complexity)] // several tips' poses and Jacobians, as arrays of pairs
        impl #impl_generics #self_ty #where_clause {
            #inherent

            #(#typed)*

            #p::with_std! {
                /// The runtime reference model of this robot, built from the same description.
                pub fn reference() -> ::core::result::Result<#p::ReferenceFk, #p::LoadError> {
                    #reference.map(#p::ReferenceFk::new)
                }
            }
        }

        #[allow(clippy::approx_constant)] // limits are kept exactly as the description gives them
        impl #impl_generics #p::Kinematics for #self_ty #where_clause {
            #of_trait

            #into
        }

        #collision

        #p::with_std! {
            impl #impl_generics #p::ReferenceModel for #self_ty #where_clause {
                fn reference() -> ::core::result::Result<#p::ReferenceFk, #p::LoadError> {
                    Self::reference()
                }
            }
        }
        };
    }
}

/// `impl Collision<DOF, VELOCITIES>` for a robot with collision checking and `f64` functions: each method
/// the inherent function of its name (inherent items come first in `Self::` paths), the centres
/// copied into a checked slice. Nothing without collision checking or without `f64`.
fn collision_impl(self_ty: &TokenStream, cx: &Context<'_>) -> TokenStream {
    if cx.spec.robot.collision().is_none() || !cx.render.scalars.f64 {
        return quote!();
    }
    let (p, robot, n, v) = (&cx.p, cx.tree().name(), cx.render.dof(), cx.render.velocities());
    let (impl_generics, where_clause) = (&cx.spec.impl_generics, &cx.spec.where_clause);
    let spheres = Literal::usize_unsuffixed(cx.spheres().len());
    quote! {
        impl #impl_generics #p::collision::Collision<#n, #v> for #self_ty #where_clause {
            const SPHERE_RADII: &'static [f64] = &Self::SPHERE_RADII;
            const SPHERE_LINKS: &'static [&'static str] = &Self::SPHERE_LINKS;
            fn sphere_centers_into(q: &[f64; #n], out: &mut [[f64; 3]]) -> ::core::result::Result<(), #p::KinematicsError> {
                #p::check_output(#robot, #spheres, out.len())?;
                out.copy_from_slice(&Self::sphere_centers(q));
                ::core::result::Result::Ok(())
            }
            fn collides(q: &[f64; #n], environment: &impl #p::collision::World<Self>) -> bool {
                Self::collides(q, environment)
            }
            fn self_collides(q: &[f64; #n]) -> bool {
                Self::self_collides(q)
            }
            fn collides_batch(
                qs: &[[f64; #n]],
                environment: &impl #p::collision::World<Self>,
                out: &mut [bool],
            ) -> ::core::result::Result<(), #p::KinematicsError> {
                Self::collides_batch(qs, environment, out)
            }
            fn self_collides_batch(qs: &[[f64; #n]], out: &mut [bool]) -> ::core::result::Result<(), #p::KinematicsError> {
                Self::self_collides_batch(qs, out)
            }
            fn collides_any(qs: &[[f64; #n]], environment: &impl #p::collision::World<Self>) -> bool {
                Self::collides_any(qs, environment)
            }
            fn self_collides_any(qs: &[[f64; #n]]) -> bool {
                Self::self_collides_any(qs)
            }
            fn motion_collides(
                q0: &[f64; #n],
                q1: &[f64; #n],
                environment: &impl #p::collision::World<Self>,
                resolution: impl ::core::convert::Into<#p::collision::Resolution>,
            ) -> ::core::result::Result<::core::option::Option<f64>, #p::KinematicsError> {
                Self::motion_collides(q0, q1, environment, resolution)
            }
            fn motion_collides_any(
                q0: &[f64; #n],
                q1: &[f64; #n],
                environment: &impl #p::collision::World<Self>,
                resolution: impl ::core::convert::Into<#p::collision::Resolution>,
            ) -> ::core::result::Result<bool, #p::KinematicsError> {
                Self::motion_collides_any(q0, q1, environment, resolution)
            }
            fn clearance(q: &[f64; #n], environment: &#p::collision::Environment<'_>) -> f64 {
                Self::clearance(q, environment)
            }
            fn clearance_gradient(q: &[f64; #n], environment: &#p::collision::Environment<'_>) -> (f64, [f64; #v]) {
                Self::clearance_gradient(q, environment)
            }
        }
    }
}

/// `tip_poses_into` and `link_poses_into` of `impl Kinematics`: the slice checked against the
/// robot's lengths, then the generic bodies' values copied in.
fn trait_functions(cx: &Context<'_>) -> TokenStream {
    let (p, robot, n_lit) = (&cx.p, cx.tree().name(), cx.render.dof());
    let (m_lit, k_lit) = (Literal::usize_unsuffixed(cx.link_names.len()), Literal::usize_unsuffixed(cx.tips.len()));
    let jn = constants::joint_names(cx);
    let tip_poses_body = if cx.tips.is_empty() {
        quote!(let _ = (q, out);)
    } else if cx.one {
        quote!(out[0] = generic_tip_poses(q);)
    } else {
        quote!(out.copy_from_slice(&generic_tip_poses(q));)
    };
    quote! {
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
}

/// The expression loading the reference model's tree: the description's text parsed with the
/// tree's own exactness policy (and free-flying root), so the reference is the robot the code
/// was compiled from.
fn reference(cx: &Context<'_>) -> TokenStream {
    let p = &cx.p;
    let (label, text) = (&cx.spec.source_label, &cx.spec.source_text);
    let policy = policy_tokens(p, cx.tree().exact_angles());
    if let Some(files) = &cx.spec.source_files {
        let floating = match &cx.options().floating_base {
            None => quote!(::core::option::Option::None),
            Some(link) => quote!(::core::option::Option::Some(#link)),
        };
        return quote!(#p::parse_source_files(#label, #text, #files, #policy, #floating));
    }
    match &cx.options().floating_base {
        None => quote!(#p::parse_source_with(#label, #text, #policy)),
        Some(link) => quote!(#p::parse_source_floating(#label, #text, #policy, #link)),
    }
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
