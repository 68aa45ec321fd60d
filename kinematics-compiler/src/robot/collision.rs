//! Collision: every sphere's centre in the base frame (`sphere_centers`), from the poses of the
//! links that carry spheres, each centre `R p + t` of its link's pose with `p` its place in the
//! link's frame (the `<collision>` element's origin applied to the cover's centre): only what the
//! centres need of the poses is computed. For the checks (`collides`, `self_collides`), a second
//! body from the same compile returns the poses of the links with spheres, and the block holds
//! the tables the core's checks read (each sphere in its link's frame, each link's bounding
//! sphere: [`crate::collision_layout`]).
//!
//! The centres are built in the graph (`Compiled::points`) and emitted by `emit::emit_points`. The
//! checks come in every form (`collides` and `self_collides` typed, in batches, in column batches,
//! generic on lanes), `motion_collides` per scalar, and `hold` with its `HOLD_TABLES` (each link's
//! carrier and fixed pose).

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::Context;
use super::functions::Functions;
use super::surface::{CollisionFunction, Form, ScalarType};
use crate::collision_layout::CollisionLayout;
use crate::emit::{emit_function, emit_points};
use crate::error::CompileError;
use crate::request::{Compiled, Request, compile};

/// The name of the body computing the poses of the links with spheres, which the checks take.
const CHECK_BODY: &str = "generic_collision_poses";

/// The name of the body computing the points the checks read: every sphere's centre in the
/// checks' order, then each group's bounding sphere's, then each link's.
const POINTS_BODY: &str = "generic_collision_points";

/// The name of the body computing the poses and geometric Jacobians (`LOCAL_WORLD_ALIGNED`) of
/// the links with spheres, which the distances' gradients take.
const JACOBIAN_BODY: &str = "generic_collision_jacobians";

fn link_frame(cx: &Context<'_>) -> CollisionLayout {
    CollisionLayout::new(cx.spheres())
}

/// The most points a check computes ahead (every sphere's centre, each group's bounding sphere's
/// and each link's) rather than placing those its tests reach from the links' poses. Computing
/// them ahead shares the poses' simplifications and places no centre twice, but computes every
/// point before the first test: measured in a scratch harness (`F32x8`, AVX2, 1,024
/// configurations within the limits, tabletop scene), VAMP's Panda (90 points) checks in 0.73 to
/// 0.84 of the time placing takes, while the primitives UR5 at a 2 cm cover (745 points), where
/// every configuration collides and a placing check ends at its first hit, took 24 times as
/// long, and its release build more than 8 times as long.
const MAX_POINTS_AHEAD: usize = 128;

/// The points the checks read computed ahead, in the order `CollisionTables::collides_points`
/// takes them (every sphere's centre in the checks' order, each group's bounding sphere's, each
/// link's), each with its link; `None` where they are more than [`MAX_POINTS_AHEAD`], and the
/// checks place centres from the links' poses.
fn check_points(frame: &CollisionLayout) -> Option<Vec<(usize, [f64; 3])>> {
    let count = frame.order.len() + frame.groups.len() + frame.bounds.len();
    if count > MAX_POINTS_AHEAD {
        return None;
    }
    let mut points: Vec<(usize, [f64; 3])> = frame.order.iter().map(|&k| frame.points[k]).collect();
    for (link, &(first, end)) in frame.link_groups.iter().enumerate() {
        points.extend(frame.groups[first..end].iter().map(|&(_, _, center, _)| (link, center)));
    }
    points.extend(frame.bounds.iter().enumerate().map(|(link, &(center, _))| (link, center)));
    debug_assert_eq!(points.len(), count, "invariant: the groups are the links' groups");
    Some(points)
}

/// The links' poses, compiled once: the sphere centres and the bounding spheres' centres are both
/// built on them.
fn compiled_links(cx: &Context<'_>, frame: &CollisionLayout) -> Result<Compiled, CompileError> {
    let tree = cx.tree();
    let request = Request {
        base: Some(cx.base.clone()),
        tips: frame.links.iter().map(|&l| tree.link(l).name.clone()).collect(),
        position_only: false,
        velocity: None,
    };
    compile(tree, &request)
}

/// Every generic item collision needs, from one compile of the links' poses: the body of
/// `sphere_centers` (named `name`), the checks' bodies (the points they read, and the poses of
/// the links with spheres, which place a held object), and the tables
/// the core's checks read; and `sphere_centers`' doc.
pub(super) fn bodies(cx: &Context<'_>, name: &str) -> Result<(Vec<TokenStream>, String), CompileError> {
    let frame = link_frame(cx);
    let mut compiled = compiled_links(cx, &frame)?;
    let centers = compiled.points(&frame.points);
    let doc = format!(
        "The centres of the robot's {} collision spheres in `{}` (radii in `SPHERE_RADII`, links in `SPHERE_LINKS`)",
        frame.points.len(),
        cx.base
    );
    let body_doc = format!(" {doc}.");
    let mut items = vec![
        emit_points(&compiled, &centers, &cx.body_options(name), &body_doc),
        emit_function(&compiled, &cx.body_options(CHECK_BODY)),
    ];
    if let Some(points) = check_points(&frame) {
        let points = compiled.points(&points);
        items.push(emit_points(
            &compiled,
            &points,
            &cx.body_options(POINTS_BODY),
            " The checks' points: every sphere's centre in the checks' order, then each group's bounding sphere's, then each link's.",
        ));
    }
    items.extend(tables(cx, &frame));
    items.push(hold_tables(cx, &frame)?);
    items.push(jacobians_body(cx, &frame)?);
    Ok((items, doc))
}

/// The body the distances' gradients take: the links with spheres, each its pose and geometric
/// Jacobian (`LOCAL_WORLD_ALIGNED`, at its origin), computed together.
fn jacobians_body(cx: &Context<'_>, frame: &CollisionLayout) -> Result<TokenStream, CompileError> {
    let tree = cx.tree();
    let request = Request {
        base: Some(cx.base.clone()),
        tips: frame.links.iter().map(|&l| tree.link(l).name.clone()).collect(),
        ..Request::default()
    }
    .pose_and_jacobian(kinematics_model::JacobianFrame::LocalWorldAligned);
    Ok(emit_function(&compile(tree, &request)?, &cx.body_options(JACOBIAN_BODY)))
}

/// The tables a held object is made from (`collision::HoldTables`): every link of the tree with,
/// if its rigid body carries spheres, the first link there with spheres (its index among the
/// checks' links) and the link's pose in that link's frame (folded at compile time: the joints
/// between are fixed), and each link with spheres with its rigid body.
fn hold_tables(cx: &Context<'_>, frame: &CollisionLayout) -> Result<TokenStream, CompileError> {
    let p = &cx.p;
    let tree = cx.tree();
    let body = kinematics_model::collision::rigid_bodies(tree);
    let mut places: Vec<Option<(usize, [f64; 12])>> = vec![None; tree.links().len()];
    for (carrier, &link) in frame.links.iter().enumerate() {
        let members: Vec<usize> = (0..body.len()).filter(|&l| body[l] == body[link.0]).collect();
        if members.iter().any(|&l| places[l].is_some()) {
            continue; // An earlier link with spheres carries this body.
        }
        let request = Request {
            base: Some(tree.link(link).name.clone()),
            tips: members.iter().map(|&l| tree.links()[l].name.clone()).collect(),
            position_only: false,
            velocity: None,
        };
        let poses = compile(tree, &request)?.eval(&vec![0.0; tree.dof()]);
        for (&l, pose) in members.iter().zip(poses) {
            places[l] = Some((carrier, pose));
        }
    }
    let frames = tree.links().iter().zip(&places).map(|(link, place)| {
        let name = &link.name;
        match place {
            None => quote!((#name, ::core::option::Option::None)),
            Some((carrier, e)) => {
                let carrier = Literal::usize_unsuffixed(*carrier);
                let e = e.map(super::number);
                let [a, b, c, d, f, g, h, i, j, x, y, z] = e;
                quote!((#name, ::core::option::Option::Some((#carrier, #p::Pose {
                    rotation: [[#a, #b, #c], [#d, #f, #g], [#h, #i, #j]], translation: [#x, #y, #z],
                }))))
            }
        }
    });
    let links = frame.links.iter().map(|&l| {
        let (name, b) = (&tree.link(l).name, Literal::usize_unsuffixed(body[l.0]));
        quote!((#name, #b))
    });
    let robot = tree.name();
    Ok(quote! {
        /// Where a held object can hang: every link (with, if its rigid body has spheres, the first
        /// link there with spheres and the link's pose in its frame), and each link with spheres
        /// with its rigid body.
        #[allow(clippy::approx_constant, clippy::unreadable_literal)]
        pub const HOLD_TABLES: #p::collision::HoldTables = #p::collision::HoldTables {
            robot: #robot,
            frames: &[#(#frames),*],
            links: &[#(#links),*],
        };
    })
}

/// The collision tables (each link's groups and bounding sphere, each group's spheres and
/// bounding sphere, each sphere's centre in its link's frame and radius in the checks' order, the
/// link pairs the self-collision check tests), as constants of the block's `bodies` module.
fn tables(cx: &Context<'_>, frame: &CollisionLayout) -> Vec<TokenStream> {
    let p = &cx.p;
    let plan = cx.spec.robot.collision();
    let pairs = plan.map_or(&[][..], |plan| plan.pairs.pairs.as_slice());
    let fixed = frame.fixed_in_order(plan.map_or(&[][..], |plan| plan.fixed.as_slice())).into_iter().map(|(a, b)| {
        let (a, b) = (Literal::usize_unsuffixed(a), Literal::usize_unsuffixed(b));
        quote!((#a, #b))
    });
    let point = |v: &[f64; 3]| {
        let [x, y, z] = v.map(super::number);
        quote!([#x, #y, #z])
    };
    let entry = |(start, end): (usize, usize), center: &[f64; 3], radius: f64| {
        let (s, e) = (Literal::usize_unsuffixed(start), Literal::usize_unsuffixed(end));
        let (center, radius) = (point(center), super::number(radius));
        quote!((#s, #e, #center, #radius))
    };
    let links = frame.link_groups.iter().zip(&frame.bounds).map(|(&range, (c, r))| entry(range, c, *r));
    let groups = frame.groups.iter().map(|&(s, e, c, r)| entry((s, e), &c, r));
    let index = |l: kinematics_model::LinkId| {
        #[allow(clippy::expect_used, reason = "invariant: pairs are of links with spheres")]
        let i = frame.links.binary_search(&l).expect("a paired link has spheres");
        Literal::usize_unsuffixed(i)
    };
    let pairs = pairs.iter().map(|&(a, b)| {
        let (a, b) = (index(a), index(b));
        quote!((#a, #b))
    });
    let checked = plan.map_or(&[][..], |plan| plan.pairs.pairs.as_slice());
    let grids = plan.map_or(&[][..], |plan| plan.grids.as_slice()).iter().map(|grid| {
        let [d0, d1] = grid.dofs.map(Literal::usize_unsuffixed);
        let [n0, n1] = grid.cells.map(Literal::usize_unsuffixed);
        let [l0, l1] = grid.lower.map(super::number);
        let [s0, s1] = grid.scale().map(super::number);
        let states = Literal::byte_string(&grid.packed());
        let covered = grid.pairs.iter().map(|pair| {
            #[allow(clippy::expect_used, reason = "invariant: a grid's pairs are checked pairs")]
            let k = checked.iter().position(|p| p == pair).expect("a grid decides checked pairs");
            Literal::usize_unsuffixed(k)
        });
        quote!(#p::collision::PairGrid {
            dofs: [#d0, #d1],
            lower: [#l0, #l1],
            scale: [#s0, #s1],
            cells: [#n0, #n1],
            states: #states,
            pairs: &[#(#covered),*],
        })
    });
    let centers = frame.order.iter().map(|&k| point(&frame.points[k].1));
    let radii = frame.order.iter().map(|&k| super::number(cx.spheres()[k].sphere.radius));
    let count = Literal::usize_unsuffixed(cx.spheres().len());
    vec![
        quote! {
            /// The collision tables: each link with spheres (its groups, its bounding sphere's
            /// centre in its frame and radius), each group (its spheres, its bounding sphere),
            /// each sphere's centre in its link's frame and radius, the link pairs the
            /// self-collision check tests, the sphere pairs among them held apart for good, and
            /// the grids deciding the pairs one or two joints move.
            #[allow(clippy::approx_constant, clippy::unreadable_literal)] // radii are kept as given
            pub const COLLISION_TABLES: #p::collision::CollisionTables<'static> = #p::collision::CollisionTables {
                links: &[#(#links),*],
                groups: &[#(#groups),*],
                centers: &CENTERS,
                radii: &RADII,
                pairs: &[#(#pairs),*],
                fixed: &[#(#fixed),*],
                grids: &[#(#grids),*],
            };
        },
        quote! {
            #[allow(clippy::approx_constant, clippy::unreadable_literal)] // radii are kept as given
            const RADII: [f64; #count] = [#(#radii),*];
        },
        quote! {
            #[allow(clippy::approx_constant, clippy::unreadable_literal)]
            const CENTERS: [[f64; 3]; #count] = [#(#centers),*];
        },
    ]
}

/// How `self_collides`' doc states the pairs were chosen: the SRDF's or the adjacency rule, less
/// the pairs the description rules out.
fn pairs_rule(cx: &Context<'_>, rule: kinematics_model::collision::PairRule) -> String {
    let mut out = match rule {
        kinematics_model::collision::PairRule::Srdf => "less the SRDF's disabled pairs".to_owned(),
        kinematics_model::collision::PairRule::Adjacent => {
            "less the links of bodies joined by one joint (no SRDF given)".to_owned()
        }
    };
    let excluded = cx.tree().excluded_pairs().len();
    if excluded > 0 {
        out += &format!(", less the {excluded} link pairs the description rules out (MJCF `<contact>`)");
    }
    out
}

/// `collides` and `self_collides` on the type, as the surface lists them, on the checks' body and
/// tables ([`bodies`]): per scalar on one configuration (dispatched) and in batches (lanes of the
/// width the CPU fills), and on any lane type.
pub(super) fn checks(cx: &Context<'_>, out: &mut Functions) {
    let Some(plan) = cx.spec.robot.collision() else { return };
    let p = &cx.p;
    let n = cx.render.dof();
    let g = proc_macro2::Ident::new(CHECK_BODY, proc_macro2::Span::call_site());
    let frame = link_frame(cx);
    // One link with spheres: the body returns its pose alone.
    let pose_values = if frame.links.len() == 1 { quote!([#g(q)]) } else { quote!(#g(q)) };
    let poses = quote!(&#pose_values);
    let ahead = check_points(&frame).is_some();
    let pairs_rule = pairs_rule(cx, plan.pairs.rule);
    for (function, form, signature) in cx.render.collision_items() {
        let sig = signature.tokens();
        let (what, check) = match function {
            CollisionFunction::Hold => {
                out.typed.push(hold(&sig));
                continue;
            }
            CollisionFunction::Collides => (
                format!(
                    "Whether the robot at `q` touches an obstacle of `environment` or itself (its {} spheres; \
                     each link's bounding sphere tested first, the first hit ending the check; any order of \
                     obstacles; the pairs as in `self_collides`)",
                    cx.spheres().len()
                ),
                world_check(p, &pose_values, ahead, false),
            ),
            CollisionFunction::SelfCollides => (
                format!(
                    "Whether two links of the robot at `q` touch ({} pairs: links with spheres on different rigid \
                     bodies, {pairs_rule})",
                    plan.pairs.pairs.len()
                ),
                self_check(&poses, ahead, false),
            ),
            CollisionFunction::CollidesAny | CollisionFunction::SelfCollidesAny => {
                let check = if function == CollisionFunction::CollidesAny {
                    world_check(p, &pose_values, ahead, true)
                } else {
                    self_check(&poses, ahead, true)
                };
                out.typed.push(shared(cx, function, form, &sig, &check));
                continue;
            }
            CollisionFunction::MotionCollides => {
                out.typed.push(motion(cx, form, &sig, &pose_values, ahead));
                continue;
            }
            CollisionFunction::MotionCollidesAny => {
                out.typed.push(motion_any(cx, form, &sig, &pose_values, ahead));
                continue;
            }
            CollisionFunction::Clearance
            | CollisionFunction::ClearanceGradient
            | CollisionFunction::ProximityCost
            | CollisionFunction::ProximityCostGradient => {
                out.typed.push(distance(cx, function, form, &sig, &poses));
                continue;
            }
        };
        let never_free = "A configuration with a NaN or infinite entry is colliding.";
        let item = match form {
            Form::Typed(ScalarType { t, .. }) => {
                let doc = format!("{what} (`{t}`). {never_free}");
                quote! {
                    #[doc = #doc]
                    #[inline]
                    #[allow(clippy::redundant_closure)]
                    #sig { #p::dispatch(#[inline(always)] || #check).any() }
                }
            }
            Form::Batch(scalar) => {
                let ScalarType { suffix, lanes, check_wide: wide, .. } = &scalar;
                let doc = format!(
                    "[`Self::{}{suffix}`] for every configuration of `qs`, into `out` (one verdict each), in SIMD \
                     lanes ({}), each lane with its own verdict and a pack ending when all of its lanes collide. \
                     An `out` of another length than `qs` is an error, and nothing is written.",
                    function.name(),
                    scalar.check_lanes_doc(),
                );
                quote! {
                    #[doc = #doc]
                    #[inline]
                    #[allow(clippy::redundant_closure)]
                    #sig {
                        #p::batch_wide::<#lanes, #wide, #n, _, _>(
                            Self::ROBOT, qs, out, #[inline(always)] |q| #check, #[inline(always)] |q| #check,
                        )
                    }
                }
            }
            Form::Columns(ScalarType { suffix, lanes, check_wide: wide, .. }) => {
                let doc = format!(
                    "[`Self::{}_batch{suffix}`] on configurations given column-wise: `columns[j][i]` is joint \
                     `j`'s value (in the order of `JOINT_NAMES`) in configuration `i`. A column of another \
                     length than `out` is an error naming its joint, and nothing is written.",
                    function.name()
                );
                quote! {
                    #[doc = #doc]
                    #[inline]
                    #[allow(clippy::redundant_closure)]
                    #sig {
                        #p::batch_columns::<#lanes, #wide, #n, _, _>(
                            Self::ROBOT, &Self::JOINT_NAMES, columns, out,
                            #[inline(always)] |q| #check, #[inline(always)] |q| #check,
                        )
                    }
                }
            }
            Form::Generic => {
                let doc = format!(
                    "{what}, on any lane type (`F64x4`, `F64x8`, `F32x8`, `F32x16`; `f64` and `f32` are one \
                     lane): bit `i` of the mask is configuration `i`'s verdict, each lane's check ending when \
                     every lane collides. {never_free} Not dispatched: wrap a loop of calls in \
                     `kinematics::dispatch(#[inline(always)] || ...)` to run it with the widest instruction set the \
                     CPU has (the closure marked so, to be compiled inside the dispatched body)."
                );
                generic_item(&doc, &sig, &check)
            }
        };
        out.typed.push(item);
    }
}

/// A check's or a distance's generic form: `sig` with `body`, always inlined in an optimised
/// build, where it must compile inside the caller's `dispatch` closure to run with the CPU's
/// widest instructions (as `#[inline]` alone, LLVM left `clearance_gradient_generic` a call, run
/// in SSE2, measured at half the speed); only hinted in a debug build, where an always-inlined
/// body keeps its own stack slots in the caller's frame (a test calling eight of them in one
/// function overflowed its thread's stack).
fn generic_item(doc: &str, sig: &TokenStream, body: &TokenStream) -> TokenStream {
    quote! {
        #[doc = #doc]
        #[cfg_attr(debug_assertions, inline)]
        #[cfg_attr(not(debug_assertions), inline(always))]
        #sig { #body }
    }
}

/// `self_collides`: on the points computed ahead if `ahead`, else on the links' `poses`; the
/// lanes' verdicts, or (`any`) whether some lane collides.
fn self_check(poses: &TokenStream, ahead: bool, any: bool) -> TokenStream {
    match (ahead, any) {
        (true, false) => {
            let points = proc_macro2::Ident::new(POINTS_BODY, proc_macro2::Span::call_site());
            quote!(COLLISION_TABLES.self_collides_points(q, &#points(q)))
        }
        (true, true) => {
            let points = proc_macro2::Ident::new(POINTS_BODY, proc_macro2::Span::call_site());
            quote!(COLLISION_TABLES.self_collides_points_any(q, &#points(q)))
        }
        (false, false) => quote!(COLLISION_TABLES.self_collides(q, #poses)),
        (false, true) => quote!(COLLISION_TABLES.self_collides_any(q, #poses)),
    }
}

/// `collides` against `environment`, a `collision::World` of the robot: its obstacles, and the
/// object it holds if any; on the points computed ahead if `ahead` (the poses then computed only
/// for a held object), else on the links' poses; the lanes' verdicts, or (`any`) whether some
/// lane collides.
fn world_check(p: &TokenStream, poses: &TokenStream, ahead: bool, any: bool) -> TokenStream {
    let (by_poses, by_points) = if any {
        (quote!(collides_any), quote!(collides_points_any))
    } else {
        (quote!(collides), quote!(collides_points))
    };
    if !ahead {
        return quote!(COLLISION_TABLES.#by_poses(
            q,
            &#poses,
            #p::collision::World::<Self>::environment(environment),
            #p::collision::World::<Self>::held(environment),
        ));
    }
    let points = proc_macro2::Ident::new(POINTS_BODY, proc_macro2::Span::call_site());
    quote!({
        let held = #p::collision::World::<Self>::held(environment);
        let poses;
        let held = match held {
            ::core::option::Option::Some(held) => {
                poses = #poses;
                ::core::option::Option::Some((held, &poses[..]))
            }
            ::core::option::Option::None => ::core::option::Option::None,
        };
        COLLISION_TABLES.#by_points(
            q,
            &#points(q),
            #p::collision::World::<Self>::environment(environment),
            held,
        )
    })
}

/// `hold`: a held object, from the hold tables.
fn hold(sig: &TokenStream) -> TokenStream {
    let doc = "An object held by `link`: `spheres` (centres in `link`'s frame) moving with it, for \
               `collides` and `motion_collides` to check against the obstacles and the robot's links \
               (`environment.holding(&held)`), except the links of `link`'s rigid body (joined to it by \
               fixed joints) and `touching` (the links it touches by design, such as the fingers around \
               it). An unknown link, a holding link on a body with no collision spheres, a touching link \
               with none, or a sphere with a number that is not finite or a radius that is not positive is \
               an error. Nothing is allocated: the object borrows `spheres`.";
    quote! {
        #[doc = #doc]
        #sig { HOLD_TABLES.hold(link, spheres, touching) }
    }
}

/// `motion_collides` (per scalar): the motion's configurations checked by `collides` in the
/// lanes the CPU fills (`collision::motion_wide`); and its batch, several motions one per lane
/// (`collision::motions_wide`).
fn motion(cx: &Context<'_>, form: Form, sig: &TokenStream, poses: &TokenStream, ahead: bool) -> TokenStream {
    let p = &cx.p;
    let n = cx.render.dof();
    let check = world_check(p, poses, ahead, false);
    let (t, lanes, wide, batch) = match form {
        Form::Typed(ScalarType { t, lanes, check_wide: wide, .. }) => (t, lanes, wide, false),
        Form::Batch(ScalarType { t, lanes, check_wide: wide, .. }) => (t, lanes, wide, true),
        _ => unreachable!("invariant: the surface gives motion_collides a typed and a batch form per scalar"),
    };
    if batch {
        let doc = format!(
            "`motion_collides` for every motion `(q0, q1)` of `motions`, into `out` (one answer each, as \
             `motion_collides` gives it) (`{t}`): the motions one per SIMD lane, each lane checking its motion's \
             configurations in order and taking the next motion when it meets a collision or the end, so every \
             lane stays busy until the batch runs out. A resolution that is not positive and finite, or an `out` \
             of another length than `motions`, is an error, and nothing is written."
        );
        return quote! {
            #[doc = #doc]
            #[inline]
            #[allow(clippy::redundant_closure)]
            #sig {
                #p::collision::motions_wide::<#lanes, #wide, #n>(
                    Self::ROBOT, motions, resolution, out, #[inline(always)] |q| #check, #[inline(always)] |q| #check,
                )
            }
        };
    }
    let doc = format!(
        "Where the straight motion from `q0` to `q1` first collides (as `collides`: obstacles and self), \
         checked at `resolution`: the configurations `(1 - t) q0 + t q1` at `t = k / steps`, `k = 0..=steps`, \
         `steps` as `resolution` asks (an `f64` is the largest move of any joint between two checked \
         configurations, radians or metres; `collision::Resolution::StatesPerUnit` counts configurations per \
         unit of joint-space distance, as VAMP and OMPL do), both ends included (`{t}`). `Ok(Some(t))`: the first colliding configuration's \
         fraction `t`, as checking them one by one in order would find; `Ok(None)`: every one is free. \
         Several points of the motion are checked at once in SIMD lanes, spread along it, so a collision \
         anywhere ends the search early. A resolution that is not positive and finite is an error; a \
         configuration with a NaN or infinite entry is colliding. What lies between two checked \
         configurations is not checked: the guide's collision page says what a resolution guarantees."
    );
    quote! {
        #[doc = #doc]
        #[inline]
        #[allow(clippy::redundant_closure)]
        #sig {
            let motion = #p::collision::Motion::new(Self::ROBOT, *q0, *q1, resolution)?;
            ::core::result::Result::Ok(#p::collision::motion_wide::<#lanes, #wide, #n>(
                &motion, #[inline(always)] |q| #check, #[inline(always)] |q| #check,
            ))
        }
    }
}

/// `collides_any` and `self_collides_any`: per scalar on a slice (`any_wide`: packs in the lanes
/// the CPU fills, the first pack with a hit ending the work), and on any lane type (`check`, the
/// shared verdict of the lanes).
fn shared(
    cx: &Context<'_>,
    function: CollisionFunction,
    form: Form,
    sig: &TokenStream,
    check: &TokenStream,
) -> TokenStream {
    let p = &cx.p;
    let n = cx.render.dof();
    let (what, single) = match function {
        CollisionFunction::CollidesAny => ("touches an obstacle of `environment` or itself", "collides"),
        _ => ("has two links of a checked pair touching", "self_collides"),
    };
    let never_free = "A configuration with a NaN or infinite entry is colliding.";
    match form {
        Form::Typed(ScalarType { t, lanes, wide, .. }) => {
            let doc = format!(
                "Whether the robot at some configuration of `qs` {what} (`{t}`; `false` for none): one verdict \
                 shared by them all, as `qs.iter().any(|q| Self::{single}(q, ..))` gives it, found in SIMD lanes \
                 (packs of the configurations in order, the check of a pack ending at its first hit on any lane, \
                 and the first pack with a hit ending the work). For a planner validating a path's states or a \
                 batch of samples it needs no more than this; `{single}_batch` gives each configuration its own \
                 verdict. {never_free}"
            );
            quote! {
                #[doc = #doc]
                #[inline]
                #[allow(clippy::redundant_closure)]
                #sig {
                    #p::any_wide::<#lanes, #wide, #n>(qs, #[inline(always)] |q| #check, #[inline(always)] |q| #check)
                }
            }
        }
        Form::Generic => {
            let doc = format!(
                "Whether the robot at some lane's configuration of `q` {what}, on any lane type (`F64x4`, `F64x8`, \
                 `F32x8`, `F32x16`; `f64` and `f32` are one lane): one verdict for the lanes, the check ending at \
                 the first hit on any of them (`{single}_generic(q, ..).any()`, sooner). {never_free} Not \
                 dispatched: wrap a loop of calls in `kinematics::dispatch(#[inline(always)] || ...)`."
            );
            generic_item(&doc, sig, check)
        }
        _ => unreachable!("invariant: the surface gives the shared verdicts typed and generic forms only"),
    }
}

/// `motion_collides_any` (per scalar): whether the motion collides, its configurations checked by
/// the shared verdict in the lanes the CPU fills (`collision::motion_any_wide`); and its batch,
/// the motions one after another (`collision::motions_any_wide`).
fn motion_any(cx: &Context<'_>, form: Form, sig: &TokenStream, poses: &TokenStream, ahead: bool) -> TokenStream {
    let p = &cx.p;
    let n = cx.render.dof();
    let check = world_check(p, poses, ahead, true);
    match form {
        Form::Typed(ScalarType { t, lanes, check_wide: wide, .. }) => {
            let doc = format!(
                "Whether the straight motion from `q0` to `q1` collides (as `collides`: obstacles and self), \
                 checked at `resolution` as `motion_collides` checks it, the same configurations, both ends \
                 included (`{t}`): `Ok(true)` exactly when `motion_collides` finds a first collision, sooner. \
                 The SIMD lanes are spread along the motion and their offsets taken coarse to fine, so the first \
                 packs sample the whole motion, and the first pack with a hit on any lane ends the search (a \
                 planner's edge check). A resolution that is not positive and finite is an error; a \
                 configuration with a NaN or infinite entry is colliding."
            );
            quote! {
                #[doc = #doc]
                #[inline]
                #[allow(clippy::redundant_closure)]
                #sig {
                    let motion = #p::collision::Motion::new(Self::ROBOT, *q0, *q1, resolution)?;
                    ::core::result::Result::Ok(#p::collision::motion_any_wide::<#lanes, #wide, #n>(
                        &motion, #[inline(always)] |q| #check, #[inline(always)] |q| #check,
                    ))
                }
            }
        }
        Form::Batch(ScalarType { t, lanes, check_wide: wide, .. }) => {
            let doc = format!(
                "`motion_collides_any` for every motion `(q0, q1)` of `motions`, into `out` (`{t}`), one motion \
                 after another in one dispatched loop. A resolution that is not positive and finite, or an `out` \
                 of another length than `motions`, is an error, and nothing is written."
            );
            quote! {
                #[doc = #doc]
                #[inline]
                #[allow(clippy::redundant_closure)]
                #sig {
                    #p::collision::motions_any_wide::<#lanes, #wide, #n>(
                        Self::ROBOT, motions, resolution, out, #[inline(always)] |q| #check, #[inline(always)] |q| #check,
                    )
                }
            }
        }
        _ => unreachable!("invariant: the surface gives motion_collides_any a typed and a batch form per scalar"),
    }
}

/// `clearance`, `clearance_gradient`, `proximity_cost` and `proximity_cost_gradient`: the core's
/// scans on the checks' poses, or (for a gradient) on the poses and Jacobians of the links with
/// spheres; per scalar dispatched, or on any lane type.
fn distance(
    cx: &Context<'_>,
    function: CollisionFunction,
    form: Form,
    sig: &TokenStream,
    poses: &TokenStream,
) -> TokenStream {
    let p = &cx.p;
    let j = proc_macro2::Ident::new(JACOBIAN_BODY, proc_macro2::Span::call_site());
    let split = if link_frame(cx).links.len() == 1 {
        quote!(let (pose, jacobian) = #j(q); let (poses, jacobians) = ([pose], [jacobian]);)
    } else {
        // Read out of `both` in place: `both.map(..)` takes the array by value, and an unoptimised
        // build copies it for each call (with lanes, hundreds of KB of a debug build's stack).
        let m = proc_macro2::Literal::usize_unsuffixed(link_frame(cx).links.len());
        quote!(
            let both = #j(q);
            let poses: [_; #m] = ::core::array::from_fn(|k| both[k].0);
            let jacobians: [_; #m] = ::core::array::from_fn(|k| both[k].1);
        )
    };
    let (value, what, margin) = match function {
        CollisionFunction::Clearance => (
            quote!(COLLISION_TABLES.clearance(q, #poses, environment)),
            "The clearance of the robot at `q`: the smallest signed distance (m) between one of its spheres and an \
             obstacle of `environment` (a point cloud's too), or between two spheres of a pair `self_collides` \
             checks; negative, the depth of the deepest overlap; infinite with neither",
            false,
        ),
        CollisionFunction::ClearanceGradient => (
            quote!({ #split COLLISION_TABLES.clearance_gradient(q, &poses, &jacobians, environment) }),
            "The clearance (as `clearance`) and its gradient with respect to the velocities (one entry per column \
             of a Jacobian: per joint, or the floating base's six first): the nearest pair's ends carried through \
             their links' Jacobians. Where two pairs are equally near the clearance has a kink and the gradient is \
             the first found's; where the nearest spheres' centres coincide its direction is taken as zero",
            false,
        ),
        CollisionFunction::ProximityCost => (
            quote!(COLLISION_TABLES.proximity_cost(q, #poses, environment, margin)),
            "The proximity cost of the robot at `q`: over every pair `clearance` measures whose signed distance `d` \
             is below `margin` (m), the sum of `(margin - d)^2`; zero when all are at least `margin` apart, and \
             smooth but where a pair is exactly at the margin. A margin that is negative or not finite is an error",
            true,
        ),
        CollisionFunction::ProximityCostGradient => (
            quote!({ #split COLLISION_TABLES.proximity_cost_gradient(q, &poses, &jacobians, environment, margin) }),
            "The proximity cost (as `proximity_cost`) and its gradient with respect to the velocities (as \
             `clearance_gradient`'s): each pair within the margin contributes `-2 (margin - d)` times its \
             distance's gradient. A margin that is negative or not finite is an error",
            true,
        ),
        _ => unreachable!("invariant: distance() is called for the four distance functions only"),
    };
    let never_free = "A configuration with a NaN or infinite entry gives NaN.";
    let checked = |value: TokenStream| {
        if margin {
            quote! {
                if !(margin.is_finite() && margin >= 0.0) {
                    return ::core::result::Result::Err(#p::KinematicsError::BadMargin { robot: Self::ROBOT, margin });
                }
                ::core::result::Result::Ok(#value)
            }
        } else {
            value
        }
    };
    match form {
        Form::Typed(ScalarType { t, .. }) => {
            let doc = format!("{what} (`{t}`). {never_free}");
            let body = checked(quote!(#p::dispatch(#[inline(always)] || #value)));
            quote! {
                #[doc = #doc]
                #[inline]
                #[allow(clippy::redundant_closure)]
                #sig { #body }
            }
        }
        Form::Generic => {
            let doc = format!(
                "{what}, on any lane type (`F64x4`, `F64x8`, `F32x8`, `F32x16`; `f64` and `f32` are one lane), each \
                 lane its own configuration's. {never_free} Not dispatched: wrap a loop of calls in \
                 `kinematics::dispatch(#[inline(always)] || ...)` to run it with the widest instruction set the CPU \
                 has (the closure marked so, to be compiled inside the dispatched body)."
            );
            generic_item(&doc, sig, &checked(value))
        }
        _ => unreachable!("invariant: the surface gives the distances typed and generic forms only"),
    }
}
