//! The inverse kinematics functions of a robot with a closed-form plan: for the families
//! composed over the expression graph ([`IkBody`]), its straight-line body
//! ([`crate::ik::emit`]) evaluated with the eight branches side by side in the lanes of `F64x8`;
//! for the others, the run time's family solver called with the plan's geometry as a constant
//! (so the optimiser folds it into the body). Either way every solution is measured with the
//! robot's generated forward kinematics, a six-joint arm's exact solutions that miss their target
//! by more than rounding are refined by Gauss-Newton steps on its generated pose and Jacobian, in
//! the lanes of `F64x8` (`IkSolutions::refined`: the family solved the arm with its relations made
//! exact), and the
//! nearest and within-limits forms follow. Also the numeric solver's two functions.
//!
//! The items: `tip_ik`, `tip_ik_nearest`, `tip_ik_within_limits`, `IK_FAMILY`, `IK_ARM`. For a
//! composed family the body and the measure are generic functions, `tip_ik` running the eight
//! branches in `F64x8` lanes and `tip_ik_branch_generic` exposing the body; where the family has a
//! singular pass, `generic_tip_ik_branch_regular` too, which `tip_ik` runs first, the whole body
//! only when a lane comes back singular and not exact. For the other families the plan's geometry
//! is a constant passed to the core's family function, the solutions measured by the generated
//! pose. `tip_ik_numeric` runs on the generated pose and Jacobian.

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::{format_ident, quote};

use crate::ik::emit::{BRANCH_BODY, REGULAR_BODY, emit_branch_body};
use crate::ik::measure::{MEASURE_BODY, MEASURE_JACOBIAN_BODY, Measure, emit_measure};
use crate::ik::{IkBody, IkGeometry, IkPlan};
use crate::robot::number;

/// What [`emit_ik`] adds: generic bodies (for a composed family: its branch and its measure) and,
/// for each item of the type's `impl` the API surface lists
/// ([`crate::robot::surface::Render::ik_items`], which gives the signatures), its attributes and
/// its value or body.
pub struct IkItems {
    /// The generic bodies.
    pub bodies: Vec<TokenStream>,
    /// Whether the family is compiled to a branch body (`tip_ik_branch_generic`).
    pub branch: bool,
    /// `IK_FAMILY`: its doc, and its value.
    pub family: Part,
    /// `IK_ARM`: its doc, and its value.
    pub arm: Part,
    /// `tip_ik`.
    pub all: Part,
    /// `tip_ik_branch_generic`, where the family is compiled.
    pub branch_fn: Option<Part>,
    /// `tip_ik_within_limits`.
    pub within_limits: Part,
    /// `tip_ik_nearest`.
    pub nearest: Part,
}

/// One item's attributes (its doc first) and its value or body.
pub struct Part {
    /// The attributes.
    pub attrs: TokenStream,
    /// A constant's value, or a function's body (without its braces).
    pub body: TokenStream,
}

/// The numeric solver's two functions.
pub struct NumericItems {
    /// `tip_ik_numeric`.
    pub numeric: Part,
    /// `tip_ik_numeric_with`.
    pub with: Part,
}

fn vector(v: &[f64; 3]) -> TokenStream {
    let [x, y, z] = v.map(number);
    quote!([#x, #y, #z])
}

/// The associated constants and functions (inside the robot's `impl`) for `plan`. `forward`
/// names the generic function computing the tip's pose, `measures` are the same pose (and its
/// Jacobian) from the joints' cosines and sines (when the chain has that form), `revolute` says
/// which entries of `q` are angles (moved by whole turns into limits or toward a seed).
pub fn emit_ik(
    plan: &IkPlan,
    private: &TokenStream,
    forward: &TokenStream,
    pose_and_jacobian: &TokenStream,
    measures: &Measures,
    revolute: &[bool],
) -> IkItems {
    let measure = measures.pose.as_ref();
    let p = private;
    let compiled = IkBody::of(plan);
    let refine_arm = refine_arm(plan, p, revolute);
    let refine = refine(refine_arm.as_ref(), p, pose_and_jacobian);
    let solutions_refined = refine.clone().unwrap_or_else(|| quote!(solutions));
    let family = plan.family().name();
    let capacity = Literal::usize_unsuffixed(plan.family().max_solutions());
    let n = Literal::usize_unsuffixed(revolute.len());
    let mask = quote!([#(#revolute),*]);
    let ArmAndSolver { arm, solve, doc: free_doc, free } = arm_and_solver(plan, p);
    let FreeArgument { arg: free_arg, check: free_check, from_seed: nearest_free } = free_argument(free.as_ref(), p);
    let doc_family =
        format!("The closed-form inverse kinematics family of `{}` in `{}`: {family}.", plan.tip, plan.base);
    let doc_all = doc_all(plan, compiled.is_some() && measure.is_some(), &free_doc);
    let doc_nearest = doc_nearest(plan);
    let Solving { bodies, solve_and_measure, branch_fn } = match &compiled {
        Some(body) => {
            let refinement = refine_arm.zip(refine.clone()).map(|(arm, steps)| Refinement {
                arm,
                pose_and_jacobian,
                steps,
                one_pass: measures.pose_and_jacobian.as_ref(),
            });
            solving_compiled(plan, body, measure, forward, refinement.as_ref(), p)
        }
        None => Solving {
            bodies: Vec::new(),
            solve_and_measure: quote! {
                let mut solutions = #solve;
                solutions.measure(target, #[inline(always)] |q| #forward(q));
                #solutions_refined
            },
            branch_fn: None,
        },
    };
    IkItems {
        bodies,
        branch: branch_fn.is_some(),
        family: Part { attrs: quote!(#[doc = #doc_family]), body: quote!(#family) },
        arm: Part {
            attrs: quote! {
                /// The geometry the closed form solves (at the free joint's zero, for a seven-joint arm,
                /// turned to its value at run time): the chain at `q = 0`, points on meeting axes placed
                /// where they meet.
            },
            body: arm,
        },
        all: Part {
            attrs: quote! {
                #[doc = #doc_all]
                #[inline]
                // The measure's pose is a closure marked `#[inline(always)]`, to be compiled inside
                // the dispatched body (a function's name alone would not be).
                #[allow(clippy::redundant_closure)]
            },
            body: quote! {
                let target = &#p::ik::IkTarget::target_pose(target);
                #p::ik::check_target(target)?;
                #free_check
                // Dispatched (`__private::dispatch`): the measure's forward kinematics runs with the
                // widest instruction set the CPU has.
                ::core::result::Result::Ok(#p::dispatch(#[inline(always)] || { #solve_and_measure }))
            },
        },
        branch_fn,
        within_limits: Part {
            attrs: quote! {
                /// The solutions of [`Self::tip_ik`] inside `JOINT_LIMITS`, each angle moved by a whole
                /// turn into its limits where that fits.
                #[inline]
            },
            body: quote! {
                ::core::result::Result::Ok(Self::tip_ik(target #free_arg)?.within_limits(&Self::JOINT_LIMITS, &#mask))
            },
        },
        nearest: Part {
            attrs: quote! {
                #[doc = #doc_nearest]
                #[inline]
                #[allow(clippy::redundant_closure)] // as `tip_ik`'s
            },
            body: quote! {
                let target = &#p::ik::IkTarget::target_pose(target);
                #p::ik::check_seed(seed)?;
                #p::ik::check_target(target)?;
                #nearest_free
                // Solved, measured and chosen in one dispatched body.
                ::core::result::Result::Ok(#p::dispatch(#[inline(always)] || {
                    let solutions: #p::ik::IkSolutions<#n, #capacity> = { #solve_and_measure };
                    solutions.nearest(seed, &#mask)
                }))
            },
        },
    }
}

/// The plan's geometry as the generated code holds it (`IK_ARM`), and the run time's family
/// solver called with it.
struct ArmAndSolver {
    /// `IK_ARM`'s value.
    arm: TokenStream,
    /// The call solving `target` with `Self::IK_ARM` (and `free`, for a seven-joint arm).
    solve: TokenStream,
    /// What `tip_ik`'s doc says of this geometry.
    doc: String,
    /// The free joint's index in `q`, for a seven-joint arm.
    free: Option<Literal>,
}

fn arm_and_solver(plan: &IkPlan, p: &TokenStream) -> ArmAndSolver {
    // The six-joint families' core functions (a planar arm solves by its method).
    let solver = || format_ident!("{}", plan.family().solver());
    match &plan.geometry {
        IkGeometry::Six { arm: six, free: None, .. } => {
            let (axes, offsets, rows) =
                (six.axes.iter().map(vector), six.offsets.iter().map(vector), six.tool_rotation.iter().map(vector));
            let solver = solver();
            ArmAndSolver {
                arm: quote!(#p::ik::Arm6 { axes: [#(#axes),*], offsets: [#(#offsets),*], tool_rotation: [#(#rows),*] }),
                solve: quote!(#p::ik::#solver(&Self::IK_ARM, target)),
                doc: String::new(),
                free: None,
            }
        }
        IkGeometry::Six { arm: six, free: Some(free), .. } => {
            let (axes, points, rows) =
                (six.axes.iter().map(vector), six.points.iter().map(vector), six.tool_rotation.iter().map(vector));
            let (tip_point, free_axis, free_point) = (vector(&six.tip_point), vector(&free.axis), vector(&free.point));
            let index = Literal::usize_unsuffixed(free.index);
            let solver = solver();
            ArmAndSolver {
                arm: quote!(#p::ik::FreeArm6 {
                    axes: [#(#axes),*],
                    points: [#(#points),*],
                    tip_point: #tip_point,
                    tool_rotation: [#(#rows),*],
                    free_axis: #free_axis,
                    free_point: #free_point,
                    free_index: #index,
                }),
                solve: quote!(#p::ik::insert_free(&#p::ik::#solver(&Self::IK_ARM.at(free), target), #index, free)),
                doc: format!(" with joint `{}` at `free` (`q` holds `free` as given)", free.name),
                free: Some(index),
            }
        }
        IkGeometry::Planar(planar) => {
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
            ArmAndSolver {
                arm: quote!(#p::ik::PlanarArm { axis: #axis, joints: [#(#joints),*], tip_point: #tip_point, tool_rotation: [#(#rows),*] }),
                solve: quote!(Self::IK_ARM.solve(target)),
                doc: String::from(
                    ", reaching what the arm can: the position (two revolute joints), the rotation about the axes \
                     (three), the height (a prismatic joint)",
                ),
                free: None,
            }
        }
    }
}

/// What the refinement takes of a six-joint arm (`kinematics::ik::RefineArm`), `None` for a
/// planar arm: its exact solutions reach what the arm can, not the whole pose, and a step on the
/// whole pose's error would trade the one for the other.
fn refine_arm(plan: &IkPlan, p: &TokenStream, revolute: &[bool]) -> Option<TokenStream> {
    plan.six()?;
    let reach = number(plan.reach);
    let free = plan.free().map(|f| f.index);
    let moving = (0..revolute.len()).map(|i| Some(i) != free);
    Some(quote!(#p::ik::RefineArm { reach: #reach, moving: [#(#moving),*], revolute: [#(#revolute),*] }))
}

/// `solutions` refined on the arm's generated pose and Jacobian (see [`refine_arm`]).
fn refine(arm: Option<&TokenStream>, p: &TokenStream, pose_and_jacobian: &TokenStream) -> Option<TokenStream> {
    let arm = arm?;
    Some(quote! {
        // Back to the arm as written where the family's exact relations missed it.
        solutions.refined::<#p::F64x8>(target, &#arm, #[inline(always)] |q| #pose_and_jacobian(q))
    })
}

/// What a free joint adds: `tip_ik`'s argument and its check, and `tip_ik_nearest`'s value of it
/// (the seed's). Empty without one.
struct FreeArgument {
    arg: TokenStream,
    check: TokenStream,
    from_seed: TokenStream,
}

fn free_argument(index: Option<&Literal>, p: &TokenStream) -> FreeArgument {
    match index {
        Some(index) => FreeArgument {
            arg: quote!(, free),
            check: quote! {
                if !free.is_finite() {
                    return ::core::result::Result::Err(#p::ik::IkError::NonFiniteFree);
                }
            },
            from_seed: quote!(let free = seed[#index];),
        },
        None => FreeArgument { arg: quote!(), check: quote!(), from_seed: quote!() },
    }
}

/// `tip_ik`'s doc; `measured_by_cosines` where the solutions' poses come from the solver's own
/// cosines and sines.
fn doc_all(plan: &IkPlan, measured_by_cosines: bool, free_doc: &str) -> String {
    let (tip, base, family) = (&plan.tip, &plan.base, plan.family().name());
    let capacity = plan.family().max_solutions();
    let measured = if measured_by_cosines {
        " (at the cosines and sines the solver computed for each angle, of which `q` is the `atan2`)"
    } else {
        ""
    };
    format!(
        "Every closed-form inverse kinematics solution for a pose of `{tip}` in `{base}` ({family}){free_doc}: all \
         {capacity} branches, each exact or the least-squares best where the target is out of its reach, flagged \
         when singular, with its pose errors measured by this robot's forward kinematics{measured}. Angles are in \
         `(-pi, pi]`. A target with a non-finite entry or a rotation that is not orthonormal is an error."
    )
}

/// `tip_ik_nearest`'s doc.
fn doc_nearest(plan: &IkPlan) -> String {
    match plan.free() {
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
    }
}

/// The measures of a chain whose angles are sums of joint values ([`Measure`]): the tip's pose,
/// and for an arm the family solved with its relations made exact, its pose and Jacobian (which
/// refine the solutions in one pass: `IkSolutions::from_lanes_refined`).
pub struct Measures {
    /// The tip's pose from the joints' cosines and sines.
    pub pose: Option<Measure>,
    /// Its pose and Jacobian from them.
    pub pose_and_jacobian: Option<Measure>,
}

/// How a compiled family's solutions are refined on the arm as written: what the refinement
/// takes of the arm, the generic pose and Jacobian at `q`, the steps on it refining `solutions`
/// ([`refine`]), and the pose and Jacobian at the solver's cosines and sines, for one pass in
/// lanes where the arm was made exact.
struct Refinement<'a> {
    arm: TokenStream,
    pose_and_jacobian: &'a TokenStream,
    steps: TokenStream,
    one_pass: Option<&'a Measure>,
}

/// How `tip_ik` solves and measures: the statements computing its `IkSolutions`, the generic
/// bodies they call, and `tip_ik_branch_generic` where the family is compiled.
struct Solving {
    bodies: Vec<TokenStream>,
    solve_and_measure: TokenStream,
    branch_fn: Option<Part>,
}

/// [`Solving`] for a compiled family: the body's eight branches side by side in lanes (with the
/// body without its singular pass first, where it has one), measured in the same lanes.
fn solving_compiled(
    plan: &IkPlan,
    body: &IkBody,
    measure: Option<&Measure>,
    forward: &TokenStream,
    refinement: Option<&Refinement<'_>>,
    p: &TokenStream,
) -> Solving {
    let (tip, base, family) = (&plan.tip, &plan.base, plan.family().name());
    let branch_doc = format!(
        "One branch of the closed-form inverse kinematics of `{tip}` in `{base}` ({family}), for any `IkReal` \
         scalar: the joint values with their cosines and sines, and `1` or `0` for whether every equation had a \
         real solution (else the values are the least-squares best) and whether some joint was free (a \
         singularity). `signs` picks the branch (`+1` or `-1` for each of the three choices, the first \
         outermost: `kinematics::ik::branch_signs`); with `F64x8` and `kinematics::ik::BRANCH_SIGNS_8` every \
         branch at once, one per lane, in the order of [`Self::tip_ik`]. The target must be a pose (see \
         [`Self::tip_ik`]); nothing is checked here."
    );
    let g = Ident::new(BRANCH_BODY, Span::call_site());
    let mut bodies = vec![emit_branch_body(body, p, BRANCH_BODY, &branch_doc)];
    // Where the body has a pass at the wrist's singularity, the body without it first,
    // and the whole body again only when some lane needed the pass.
    let solve = match &IkBody::regular(plan) {
        Some(regular) => {
            let r = Ident::new(REGULAR_BODY, Span::call_site());
            let doc = format!(
                "`{BRANCH_BODY}` without its pass at the wrist's singularity (where `q6 = 0` leaves the \
                 elbow out of reach, that pass moves the sum of the parallel joints): the same branches \
                 but those, which it returns singular and not exact."
            );
            bodies.push(emit_branch_body(regular, p, REGULAR_BODY, &doc));
            quote! {
                let regular = #r(&lanes, &#p::ik::BRANCH_SIGNS_8);
                let branches = if regular.misses_at_a_singularity() {
                    #g(&lanes, &#p::ik::BRANCH_SIGNS_8)
                } else {
                    regular
                };
            }
        }
        None => quote!(let branches = #g(&lanes, &#p::ik::BRANCH_SIGNS_8);),
    };
    // The solutions' poses, in the same lanes: from the cosines and sines the solver
    // computed where the chain allows, else at `q`.
    let reached = match measure {
        Some(measure) => {
            bodies.push(emit_measure(measure, p, tip, base));
            let m = Ident::new(MEASURE_BODY, Span::call_site());
            quote!(#m(&branches.q, &branches.cos, &branches.sin))
        }
        None => quote!(#forward(&branches.q)),
    };
    let from_lanes = match refinement {
        None => quote! {
            let reached = #reached;
            #p::ik::IkSolutions::from_lanes(&branches, &reached, target)
        },
        // An arm made exact: its pose and Jacobian at the solver's cosines and sines, one step
        // in every lane, measured by the pose at the cosines and sines turned by it.
        Some(Refinement { arm, pose_and_jacobian, one_pass: Some(with_jacobian), .. }) if measure.is_some() => {
            bodies.push(emit_measure(with_jacobian, p, tip, base));
            let (mj, m) =
                (Ident::new(MEASURE_JACOBIAN_BODY, Span::call_site()), Ident::new(MEASURE_BODY, Span::call_site()));
            quote! {
                let reached = #mj(&branches.q, &branches.cos, &branches.sin);
                // Back to the arm as written where the family's exact relations missed it.
                #p::ik::IkSolutions::from_lanes_refined(
                    &branches,
                    &reached,
                    target,
                    &#arm,
                    #[inline(always)] |q, cos, sin| #m(q, cos, sin),
                    #[inline(always)] |q| #pose_and_jacobian(q),
                )
            }
        }
        Some(Refinement { steps, .. }) => quote! {
            let reached = #reached;
            let solutions = #p::ik::IkSolutions::from_lanes(&branches, &reached, target);
            #steps
        },
    };
    Solving {
        bodies,
        solve_and_measure: quote! {
            // The eight branches side by side, one per lane.
            let lanes = #p::ik::splat_pose::<#p::F64x8>(target);
            #solve
            #from_lanes
        },
        branch_fn: Some(Part {
            attrs: quote! {
                #[doc = #branch_doc]
                #[inline]
            },
            body: quote!(#g(target, signs)),
        }),
    }
}

/// The numeric solver's functions (inside the robot's `impl`): Levenberg-Marquardt on
/// `pose_and_jacobian` (the generic function computing the tip's pose and `LOCAL_WORLD_ALIGNED`
/// Jacobian), within `JOINT_LIMITS`.
pub fn emit_numeric(tip: &str, base: &str, private: &TokenStream, pose_and_jacobian: &TokenStream) -> NumericItems {
    let p = private;
    let doc = format!(
        "Numeric inverse kinematics of `{tip}` in `{base}`: Levenberg-Marquardt from `seed` on this robot's \
         generated pose and Jacobian, within `JOINT_LIMITS`, restarting from deterministic configurations \
         when a start does not converge (`NumericOptions::default()`: 1e-10 m and rad, 100 steps, 20 restarts). \
         Returns the best configuration found and whether it converged. A target that is no pose, or a seed \
         with a non-finite entry, is an error."
    );
    NumericItems {
        numeric: Part {
            attrs: quote! {
                #[doc = #doc]
                #[inline]
            },
            body: quote!(Self::tip_ik_numeric_with(target, seed, &#p::ik::NumericOptions::default())),
        },
        with: Part {
            attrs: quote! {
                /// [`Self::tip_ik_numeric`] with the tolerance, steps and restarts given.
                #[inline]
                // The pose and Jacobian are a closure marked `#[inline(always)]`, to be compiled
                // inside the dispatched body (a function's name alone would not be).
                #[allow(clippy::redundant_closure)]
            },
            body: quote! {
                let target = &#p::ik::IkTarget::target_pose(target);
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
            },
        },
    }
}
