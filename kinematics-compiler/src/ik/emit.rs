//! The inverse kinematics functions of a robot with a closed-form plan: the family's solver
//! called with the plan's geometry as a constant (so the optimiser folds it into the body), every
//! solution measured with the robot's generated forward kinematics, and the nearest and
//! within-limits forms.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use super::classify::{FreeJoint, IkPlan};
use crate::robot::number;

fn vector(v: &[f64; 3]) -> TokenStream {
    let [x, y, z] = v.map(number);
    quote!([#x, #y, #z])
}

/// The associated constant and functions (inside the robot's `impl`) for `plan`. `forward` names
/// the generic function computing the tip's pose.
pub fn emit_ik(plan: &IkPlan, private: &TokenStream, forward: &TokenStream) -> TokenStream {
    match &plan.free {
        None => emit_six(plan, private, forward),
        Some(free) => emit_free(plan, free, private, forward),
    }
}

fn emit_six(plan: &IkPlan, private: &TokenStream, forward: &TokenStream) -> TokenStream {
    let p = private;
    let family = plan.family.name();
    let solver = format_ident!("{}", plan.family.solver());
    let capacity = Literal::usize_unsuffixed(plan.family.max_solutions());
    let axes = plan.axes.iter().map(vector);
    let offsets = plan.offsets.iter().map(vector);
    let rows = plan.tool_rotation.iter().map(vector);
    let (base, tip) = (&plan.base, &plan.tip);
    let solutions = quote!(#p::ik::IkSolutions<6, #capacity>);
    let result = |t: TokenStream| quote!(::core::result::Result<#t, #p::ik::IkError>);
    let all = result(solutions.clone());
    let one = result(quote!(::core::option::Option<#p::ik::IkSolution<6>>));
    let doc_family = format!("The closed-form inverse kinematics family of `{tip}` in `{base}`: {family}.");
    let doc_all = format!(
        "Every closed-form inverse kinematics solution for a pose of `{tip}` in `{base}` ({family}): all \
         {capacity} branches, each exact or the least-squares best where the target is out of its reach, flagged \
         when singular, with its pose errors measured by this robot's forward kinematics. Angles are in \
         `(-pi, pi]`. A target with a non-finite entry or a rotation that is not orthonormal is an error."
    );
    quote! {
        #[doc = #doc_family]
        pub const IK_FAMILY: &'static str = #family;

        /// The geometry the closed form solves: the chain at `q = 0` as a product of exponentials,
        /// points on meeting axes placed where they meet.
        pub const IK_ARM: #p::ik::Arm6 = #p::ik::Arm6 {
            axes: [#(#axes),*],
            offsets: [#(#offsets),*],
            tool_rotation: [#(#rows),*],
        };

        #[doc = #doc_all]
        #[inline]
        pub fn tip_ik(target: &#p::Pose<f64>) -> #all {
            #p::ik::check_target(target)?;
            let mut solutions = #p::ik::#solver(&Self::IK_ARM, target);
            solutions.measure(target, #[inline(always)] |q| #forward(q));
            ::core::result::Result::Ok(solutions)
        }

        /// The solutions of [`Self::tip_ik`] inside `JOINT_LIMITS`, each angle moved by a whole
        /// turn into its limits where that fits.
        #[inline]
        pub fn tip_ik_within_limits(target: &#p::Pose<f64>) -> #all {
            ::core::result::Result::Ok(Self::tip_ik(target)?.within_limits(&Self::JOINT_LIMITS, &[true; 6]))
        }

        /// The solution of [`Self::tip_ik`] nearest `seed` (each angle moved by whole turns to the
        /// seed's side), exact ones preferred to least-squares ones. A seed with a non-finite entry is
        /// an error.
        #[inline]
        pub fn tip_ik_nearest(target: &#p::Pose<f64>, seed: &[f64; 6]) -> #one {
            #p::ik::check_seed(seed)?;
            ::core::result::Result::Ok(Self::tip_ik(target)?.nearest(seed, &[true; 6]))
        }
    }
}

/// A seven-joint arm's functions: the free joint's value an input (`tip_ik`,
/// `tip_ik_within_limits`) or taken from the seed (`tip_ik_nearest`).
fn emit_free(plan: &IkPlan, free: &FreeJoint, private: &TokenStream, forward: &TokenStream) -> TokenStream {
    let p = private;
    let family = plan.family.name();
    let solver = format_ident!("{}", plan.family.solver());
    let capacity = Literal::usize_unsuffixed(plan.family.max_solutions());
    let axes = plan.axes.iter().map(vector);
    let points = plan.points.iter().map(vector);
    let rows = plan.tool_rotation.iter().map(vector);
    let (tip_point, free_axis, free_point) = (vector(&plan.tip_point), vector(&free.axis), vector(&free.point));
    let index = Literal::usize_unsuffixed(free.index);
    let (base, tip, name) = (&plan.base, &plan.tip, &free.name);
    let result = |t: TokenStream| quote!(::core::result::Result<#t, #p::ik::IkError>);
    let all = result(quote!(#p::ik::IkSolutions<7, #capacity>));
    let one = result(quote!(::core::option::Option<#p::ik::IkSolution<7>>));
    let doc_family = format!(
        "The closed-form inverse kinematics family of `{tip}` in `{base}` with joint `{name}` given: {family}."
    );
    let doc_all = format!(
        "Every closed-form inverse kinematics solution for a pose of `{tip}` in `{base}` with joint `{name}` at \
         `free` ({family} for the other six): all {capacity} branches, each exact or the least-squares best \
         where the target is out of its reach, flagged when singular, with its pose errors measured by this \
         robot's forward kinematics. `q` holds `free` as given and the other angles in `(-pi, pi]`. A target \
         that is no pose, or a `free` that is not a finite number, is an error."
    );
    let doc_nearest = format!(
        "The solution of [`Self::tip_ik`] with joint `{name}` at the seed's value nearest `seed` (each angle \
         moved by whole turns to the seed's side), exact ones preferred to least-squares ones."
    );
    quote! {
        #[doc = #doc_family]
        pub const IK_FAMILY: &'static str = #family;

        /// The geometry the closed form solves, at the free joint's zero (turned to its value at
        /// run time).
        pub const IK_ARM: #p::ik::FreeArm6 = #p::ik::FreeArm6 {
                axes: [#(#axes),*],
                points: [#(#points),*],
                tip_point: #tip_point,
                tool_rotation: [#(#rows),*],
                free_axis: #free_axis,
                free_point: #free_point,
                free_index: #index,
        };

        #[doc = #doc_all]
        #[inline]
        pub fn tip_ik(target: &#p::Pose<f64>, free: f64) -> #all {
            #p::ik::check_target(target)?;
            if !free.is_finite() {
                return ::core::result::Result::Err(#p::ik::IkError::NonFiniteFree);
            }
            let six = #p::ik::#solver(&Self::IK_ARM.at(free), target);
            let mut solutions = #p::ik::insert_free(&six, #index, free);
            solutions.measure(target, #[inline(always)] |q| #forward(q));
            ::core::result::Result::Ok(solutions)
        }

        /// The solutions of [`Self::tip_ik`] inside `JOINT_LIMITS`, each angle moved by a whole
        /// turn into its limits where that fits.
        #[inline]
        pub fn tip_ik_within_limits(target: &#p::Pose<f64>, free: f64) -> #all {
            ::core::result::Result::Ok(Self::tip_ik(target, free)?.within_limits(&Self::JOINT_LIMITS, &[true; 7]))
        }

        #[doc = #doc_nearest]
        #[inline]
        pub fn tip_ik_nearest(target: &#p::Pose<f64>, seed: &[f64; 7]) -> #one {
            #p::ik::check_seed(seed)?;
            ::core::result::Result::Ok(Self::tip_ik(target, seed[#index])?.nearest(seed, &[true; 7]))
        }
    }
}

/// The numeric solver's functions (inside the robot's `impl`): Levenberg-Marquardt on
/// `pose_and_jacobian` (the generic function computing the tip's pose and `LOCAL_WORLD_ALIGNED`
/// Jacobian), within `JOINT_LIMITS`.
pub fn emit_numeric(
    tip: &str,
    base: &str,
    dof: usize,
    private: &TokenStream,
    pose_and_jacobian: &TokenStream,
) -> TokenStream {
    let p = private;
    let n = Literal::usize_unsuffixed(dof);
    let result = quote!(::core::result::Result<#p::ik::NumericSolution<#n>, #p::ik::IkError>);
    let doc = format!(
        "Numeric inverse kinematics of `{tip}` in `{base}`: Levenberg-Marquardt from `seed` on this robot's \
         generated pose and Jacobian, within `JOINT_LIMITS`, restarting from deterministic configurations \
         when a start does not converge (`NumericOptions::default()`: 1e-10 m and rad, 100 steps, 20 restarts). \
         Returns the best configuration found and whether it converged. A target that is no pose, or a seed \
         with a non-finite entry, is an error."
    );
    quote! {
        #[doc = #doc]
        #[inline]
        pub fn tip_ik_numeric(target: &#p::Pose<f64>, seed: &[f64; #n]) -> #result {
            Self::tip_ik_numeric_with(target, seed, &#p::ik::NumericOptions::default())
        }

        /// [`Self::tip_ik_numeric`] with the tolerance, steps and restarts given.
        #[inline]
        pub fn tip_ik_numeric_with(target: &#p::Pose<f64>, seed: &[f64; #n], options: &#p::ik::NumericOptions) -> #result {
            #p::ik::check_target(target)?;
            #p::ik::check_seed(seed)?;
            ::core::result::Result::Ok(#p::ik::levenberg_marquardt(
                target,
                seed,
                &Self::JOINT_LIMITS,
                options,
                #[inline(always)] |q| #pose_and_jacobian(q),
            ))
        }
    }
}
