//! The inverse kinematics functions of a robot with a closed-form plan: the family's solver
//! called with the plan's geometry as a constant (so the optimiser folds it into the body), every
//! solution measured with the robot's generated forward kinematics, and the nearest and
//! within-limits forms.

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use super::classify::{IkGeometry, IkPlan};
use crate::robot::number;

fn vector(v: &[f64; 3]) -> TokenStream {
    let [x, y, z] = v.map(number);
    quote!([#x, #y, #z])
}

/// The associated constants and functions (inside the robot's `impl`) for `plan`. `forward`
/// names the generic function computing the tip's pose, `dof` is the length of `q` and
/// `revolute` says which of its entries are angles (moved by whole turns into limits or toward a
/// seed).
pub fn emit_ik(plan: &IkPlan, private: &TokenStream, forward: &TokenStream, revolute: &[bool]) -> TokenStream {
    let p = private;
    let family = plan.family.name();
    let capacity = Literal::usize_unsuffixed(plan.family.max_solutions());
    let (base, tip) = (&plan.base, &plan.tip);
    let n = Literal::usize_unsuffixed(revolute.len());
    // The six-joint families' core functions (a planar arm solves by its method).
    let solver = || format_ident!("{}", plan.family.solver());
    let mask = quote!([#(#revolute),*]);
    let (arm_ty, arm, solve, free_param, free_doc, free_value) = match (&plan.geometry, &plan.free) {
        (IkGeometry::Six(six), None) => {
            let (axes, offsets, rows) =
                (six.axes.iter().map(vector), six.offsets.iter().map(vector), six.tool_rotation.iter().map(vector));
            (
                quote!(#p::ik::Arm6),
                quote!(#p::ik::Arm6 { axes: [#(#axes),*], offsets: [#(#offsets),*], tool_rotation: [#(#rows),*] }),
                {
                    let solver = solver();
                    quote!(#p::ik::#solver(&Self::IK_ARM, target))
                },
                quote!(),
                String::new(),
                None,
            )
        }
        (IkGeometry::Six(six), Some(free)) => {
            let (axes, points, rows) =
                (six.axes.iter().map(vector), six.points.iter().map(vector), six.tool_rotation.iter().map(vector));
            let (tip_point, free_axis, free_point) = (vector(&six.tip_point), vector(&free.axis), vector(&free.point));
            let index = Literal::usize_unsuffixed(free.index);
            (
                quote!(#p::ik::FreeArm6),
                quote!(#p::ik::FreeArm6 {
                    axes: [#(#axes),*],
                    points: [#(#points),*],
                    tip_point: #tip_point,
                    tool_rotation: [#(#rows),*],
                    free_axis: #free_axis,
                    free_point: #free_point,
                    free_index: #index,
                }),
                {
                    let solver = solver();
                    quote!(#p::ik::insert_free(&#p::ik::#solver(&Self::IK_ARM.at(free), target), #index, free))
                },
                quote!(, free: f64),
                format!(" with joint `{}` at `free` (`q` holds `free` as given)", free.name),
                Some(index),
            )
        }
        (IkGeometry::Planar(planar), _) => {
            let joints = planar.joints.iter().map(|(sign, point)| {
                let sign = number(*sign);
                match point {
                    Some(point) => {
                        let point = vector(point);
                        quote!(#p::ik::PlanarJoint::Revolute { sign: #sign, point: #point })
                    }
                    None => quote!(#p::ik::PlanarJoint::Prismatic { sign: #sign }),
                }
            });
            let (axis, tip_point) = (vector(&planar.axis), vector(&planar.tip_point));
            let rows = planar.tool_rotation.iter().map(vector);
            (
                quote!(#p::ik::PlanarArm<#n>),
                quote!(#p::ik::PlanarArm { axis: #axis, joints: [#(#joints),*], tip_point: #tip_point, tool_rotation: [#(#rows),*] }),
                quote!(Self::IK_ARM.solve(target)),
                quote!(),
                String::from(
                    ", reaching what the arm can: the position (two revolute joints), the rotation about the axes \
                     (three), the height (a prismatic joint)",
                ),
                None,
            )
        }
    };
    let result = |t: TokenStream| quote!(::core::result::Result<#t, #p::ik::IkError>);
    let all = result(quote!(#p::ik::IkSolutions<#n, #capacity>));
    let one = result(quote!(::core::option::Option<#p::ik::IkSolution<#n>>));
    let doc_family = format!("The closed-form inverse kinematics family of `{tip}` in `{base}`: {family}.");
    let doc_all = format!(
        "Every closed-form inverse kinematics solution for a pose of `{tip}` in `{base}` ({family}){free_doc}: all \
         {capacity} branches, each exact or the least-squares best where the target is out of its reach, flagged \
         when singular, with its pose errors measured by this robot's forward kinematics. Angles are in \
         `(-pi, pi]`. A target with a non-finite entry or a rotation that is not orthonormal is an error."
    );
    let (free_arg, free_check, nearest_free) = match &free_value {
        Some(index) => (
            quote!(, free),
            quote! {
                if !free.is_finite() {
                    return ::core::result::Result::Err(#p::ik::IkError::NonFiniteFree);
                }
            },
            quote!(, seed[#index]),
        ),
        None => (quote!(), quote!(), quote!()),
    };
    let doc_nearest = match &plan.free {
        Some(free) => format!(
            "The solution of [`Self::tip_ik`] with joint `{}` at the seed's value nearest `seed` (each angle moved by \
             whole turns to the seed's side), exact ones preferred to least-squares ones. A seed with a non-finite \
             entry is an error.",
            free.name
        ),
        None => {
            "The solution of [`Self::tip_ik`] nearest `seed` (each angle moved by whole turns to the seed's side), \
                 exact ones preferred to least-squares ones. A seed with a non-finite entry is an error."
                .to_owned()
        }
    };
    quote! {
        #[doc = #doc_family]
        pub const IK_FAMILY: &'static str = #family;

        /// The geometry the closed form solves (at the free joint's zero, for a seven-joint arm,
        /// turned to its value at run time): the chain at `q = 0`, points on meeting axes placed
        /// where they meet.
        pub const IK_ARM: #arm_ty = #arm;

        #[doc = #doc_all]
        #[inline]
        pub fn tip_ik(target: &#p::Pose<f64> #free_param) -> #all {
            #p::ik::check_target(target)?;
            #free_check
            // Dispatched (`__private::dispatch`): the measure's forward kinematics runs with the
            // widest instruction set the CPU has.
            ::core::result::Result::Ok(#p::dispatch(#[inline(always)] || {
                let mut solutions = #solve;
                solutions.measure(target, #[inline(always)] |q| #forward(q));
                solutions
            }))
        }

        /// The solutions of [`Self::tip_ik`] inside `JOINT_LIMITS`, each angle moved by a whole
        /// turn into its limits where that fits.
        #[inline]
        pub fn tip_ik_within_limits(target: &#p::Pose<f64> #free_param) -> #all {
            ::core::result::Result::Ok(Self::tip_ik(target #free_arg)?.within_limits(&Self::JOINT_LIMITS, &#mask))
        }

        #[doc = #doc_nearest]
        #[inline]
        pub fn tip_ik_nearest(target: &#p::Pose<f64>, seed: &[f64; #n]) -> #one {
            #p::ik::check_seed(seed)?;
            ::core::result::Result::Ok(Self::tip_ik(target #nearest_free)?.nearest(seed, &#mask))
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
            // Dispatched: the iteration's pose and Jacobian run with the widest instruction set
            // the CPU has.
            ::core::result::Result::Ok(#p::dispatch(#[inline(always)] || #p::ik::levenberg_marquardt(
                target,
                seed,
                &Self::JOINT_LIMITS,
                options,
                #[inline(always)] |q| #pose_and_jacobian(q),
            )))
        }
    }
}
