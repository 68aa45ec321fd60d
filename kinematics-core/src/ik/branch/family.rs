//! The six-joint families whose every step has two roots at most, one branch at a time: each a
//! fixed composition of subproblems 1 to 4 on an [`Algebra`]. Three binary choices pick the
//! branch (`signs[0]` outermost), so a family evaluated with every combination of signs gives its
//! eight solutions, in the order of [`crate::ik::branch_signs`]. The spherical wrist and the
//! planar elbow after axes 2, 3, 4 parallel are also the last steps of the two families whose
//! first step is a quartic (`crate::ik::spherical`, `crate::ik::three_parallel`), which call
//! them once per root and sign.
//!
//! The UR family has its pass at the wrist's singularity (where `q6 = 0` leaves the elbow out of
//! reach, the sum of the parallel joints moves: [`free_sixth`]), which [`Problem::singular_pass`]
//! can leave out.

use super::algebra::{Algebra, Flags, Matrix, Turn, Vector};
use super::subproblem::Subproblems;
use crate::ik::family::{Arm6, ORTHOGONAL};
use crate::ik::subproblem::distance_range;
use crate::ik::vector::dot;

/// What a branch computes: joint values (revolute angles in `(-pi, pi]`), each joint's cosine
/// and sine (of the angle `q` is the `atan2` of; `1` and `0` for a prismatic joint), and the
/// flags.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Branch<V> {
    /// The joint values.
    pub q: [V; 6],
    /// Their cosines.
    pub cos: [V; 6],
    /// Their sines.
    pub sin: [V; 6],
    /// Whether every equation had a real solution, and whether any was singular.
    pub quality: Flags<V>,
}

/// The arm (as numbers: what depends on them alone is decided as the branch is written), the
/// target (rotation rows, translation) and the branch signs.
#[derive(Debug, Clone, Copy)]
pub struct Problem<'a, V> {
    /// The arm.
    pub arm: &'a Arm6,
    /// The target's rotation, row-major.
    pub rotation: Matrix<V>,
    /// The target's translation.
    pub translation: Vector<V>,
    /// The branch signs, `+1` or `-1` each.
    pub signs: [V; 3],
    /// Whether the UR family moves the sum of the parallel joints where `q6 = 0` leaves the elbow
    /// out of reach at the wrist's singularity (the compiler emits a body without it, run first,
    /// the pass costing about a third of the body for targets a random pose almost never is).
    pub singular_pass: bool,
}

/// A family's branch, on the algebra `A`.
pub type Composer<A> = fn(&mut A, &Problem<'_, <A as Algebra>::Value>) -> Branch<<A as Algebra>::Value>;

/// The arm's constants as values, beside the numbers they came from.
pub(crate) struct Arm<'a, V> {
    pub h: [Vector<V>; 6],
    pub p: [Vector<V>; 7],
    pub numbers: &'a Arm6,
}

/// The arm's constants, then the wrist's rotation `R06 = R R6T^T` and the point
/// `p - R06 p6T - p01` the first joints must reach.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::type_complexity, reason = "the three things every family starts from")]
pub(crate) fn wrist_target<'a, A: Algebra>(
    b: &mut A,
    problem: &Problem<'a, A::Value>,
) -> (Arm<'a, A::Value>, Matrix<A::Value>, Vector<A::Value>) {
    let numbers = problem.arm;
    let [a0, a1, a2, a3, a4, a5] = numbers.axes;
    let h = [b.vector(a0), b.vector(a1), b.vector(a2), b.vector(a3), b.vector(a4), b.vector(a5)];
    let [o0, o1, o2, o3, o4, o5, o6] = numbers.offsets;
    let p = [b.vector(o0), b.vector(o1), b.vector(o2), b.vector(o3), b.vector(o4), b.vector(o5), b.vector(o6)];
    let arm = Arm { h, p, numbers };
    let [t0, t1, t2] = numbers.tool_rotation;
    let tool = [b.vector(t0), b.vector(t1), b.vector(t2)];
    let rows = problem.rotation;
    let mut r06 = rows;
    for i in 0..3 {
        for j in 0..3 {
            r06[i][j] = b.dot(rows[i], tool[j]);
        }
    }
    let tool_offset = b.mul_vector(&r06, arm.p[6]);
    let point = b.vsub(problem.translation, tool_offset);
    let point = b.vsub(point, arm.p[0]);
    b.step("the wrist's target: R06 = R R6T^T, the point p - R06 p6T - p01", point);
    (arm, r06, point)
}

/// The angle `x` moved by whole turns into `(-pi, pi]`, for a sum of at most three angles in
/// `[-pi, pi]` (two conditional turns each way).
#[cfg_attr(not(debug_assertions), inline(always))]
fn wrap_sum<A: Algebra>(b: &mut A, x: A::Value) -> A::Value {
    let once = wrap_both(b, x);
    wrap_both(b, once)
}

/// One conditional turn either way: `x - 2 pi` above `pi`, `x + 2 pi` at or below `-pi`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn wrap_both<A: Algebra>(b: &mut A, x: A::Value) -> A::Value {
    use core::f64::consts::{PI, TAU};
    let pi = b.constant(PI);
    let over = b.sub(x, pi);
    let tau = b.constant(TAU);
    let down = b.sub(x, tau);
    let within = wrap(b, x);
    b.select(over, down, within)
}

/// The angle `x`, in `[-pi, pi]` (an `atan2`'s, or its negation), moved into `(-pi, pi]`: `-pi`
/// becomes `pi`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn wrap<A: Algebra>(b: &mut A, x: A::Value) -> A::Value {
    use core::f64::consts::{PI, TAU};
    let (pi, tau) = (b.constant(PI), b.constant(TAU));
    let up = b.add(x, tau);
    let under = b.add(x, pi);
    b.select(under, x, up)
}

/// `v` turned back through the arm's first three joints: `R03^T v`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn back_through_arm<A: Algebra>(
    b: &mut A,
    h: &[Vector<A::Value>; 6],
    [q1, q2, q3]: [Turn<A::Value>; 3],
    v: Vector<A::Value>,
) -> Vector<A::Value> {
    let (t1, t2, t3) = (b.back(q1), b.back(q2), b.back(q3));
    let v = b.rotate(t1, h[0], v);
    let v = b.rotate(t2, h[1], v);
    b.rotate(t3, h[2], v)
}

/// A branch of these joint values and the turns' cosines and sines.
#[cfg_attr(not(debug_assertions), inline(always))]
fn branch<V: Copy>(q: [V; 6], turns: [Turn<V>; 6], quality: Flags<V>) -> Branch<V> {
    let mut cos = q;
    let mut sin = q;
    for (j, turn) in turns.iter().enumerate() {
        cos[j] = turn.cos;
        sin[j] = turn.sin;
    }
    Branch { q, cos, sin, quality }
}

/// The spherical wrist's `q4, q5, q6` for the arm's turns: `q5` by subproblem 4 (on the great
/// circle for an orthogonal wrist), `q4` and `q6` by subproblem 1. `sign` picks `q5`'s root.
/// (Subproblem 2 would give `q4` with `q5`, but from where two cones nearly touch, which near the
/// singularity loses half the digits of `q4` and `q6`; subproblem 1 loses only as many as the
/// distance to it.)
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::type_complexity, reason = "three turns and their flags")]
fn spherical_wrist<A: Algebra>(
    b: &mut A,
    arm: &Arm<'_, A::Value>,
    r06: &Matrix<A::Value>,
    [q1, q2, q3]: [Turn<A::Value>; 3],
    quality: Flags<A::Value>,
    sign: A::Value,
) -> ([Turn<A::Value>; 3], Flags<A::Value>) {
    let h = &arm.h;
    let seen6 = b.mul_vector(r06, h[5]);
    let r36_h6 = back_through_arm(b, h, [q1, q2, q3], seen6);
    let seen5 = b.mul_vector(r06, h[4]);
    let r36_h5 = back_through_arm(b, h, [q1, q2, q3], seen5);
    // An orthogonal wrist (the usual one: h4 and h6 both square to h5) takes the well-conditioned
    // form of subproblem 4; decided on the numbers, so a compiled body has one form.
    let axes = &arm.numbers.axes;
    let orthogonal = dot(axes[3], axes[4]).abs() <= ORTHOGONAL && dot(axes[5], axes[4]).abs() <= ORTHOGONAL;
    let (q5, fifth) = if orthogonal {
        let q5 = b.rotation_to_height_on_great_circle(h[3], h[4], h[5], r36_h6, sign);
        (q5, b.exact())
    } else {
        let height = b.dot(h[3], r36_h6);
        b.rotation_to_height(h[3], h[4], h[5], height, sign)
    };
    b.step("q5 by SP4", q5.nodes().into_iter().chain(fifth.nodes()));
    let turned = b.rotate(q5, h[4], h[5]);
    let (q4, fourth) = b.rotation_onto(h[3], turned, r36_h6);
    b.step("q4 by SP1", q4.nodes().into_iter().chain(fourth.nodes()));
    let (back4, back5) = (b.back(q4), b.back(q5));
    let v = b.rotate(back4, h[3], r36_h5);
    let v = b.rotate(back5, h[4], v);
    let (q6, sixth) = b.rotation_onto(h[5], h[4], v);
    b.step("q6 by SP1", q6.nodes().into_iter().chain(sixth.nodes()));
    let quality = b.both(quality, fifth);
    let quality = b.both(quality, fourth);
    let quality = b.both(quality, sixth);
    ([q4, q5, q6], quality)
}

/// The elbow of an arm whose third joint turns the forearm `p34` about `h3` at the end of the
/// upper arm `p23`: `q3` by subproblem 3 (the forearm's end at `distance` squared from the
/// elbow's base), recorded as a step, and the vector from the base of `p23` to the forearm's end.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::type_complexity, reason = "a turn, its flags and the forearm's end")]
fn elbow<A: Algebra>(
    b: &mut A,
    arm: &Arm<'_, A::Value>,
    distance: A::Value,
    sign: A::Value,
) -> (Turn<A::Value>, Flags<A::Value>, Vector<A::Value>) {
    let [_, _, h3, ..] = arm.h;
    let [_, _, p23, p34, ..] = arm.p;
    let minus_one = b.constant(-1.0);
    let back23 = b.scale(p23, minus_one);
    let (q3, third) = b.rotation_to_distance(h3, p34, back23, distance, sign);
    b.step("q3 by SP3", q3.nodes().into_iter().chain(third.nodes()));
    let turned = b.rotate(q3, h3, p34);
    let forearm = b.vadd(p23, turned);
    (q3, third, forearm)
}

/// A spherical-wrist branch as joint values: every angle wrapped, `slide` in place of `q3` for
/// a prismatic third joint.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn spherical_branch<A: Algebra>(
    b: &mut A,
    arm: &Arm<'_, A::Value>,
    r06: &Matrix<A::Value>,
    arm_turns: [Turn<A::Value>; 3],
    slide: Option<A::Value>,
    quality: Flags<A::Value>,
    sign: A::Value,
) -> Branch<A::Value> {
    let ([q4, q5, q6], quality) = spherical_wrist(b, arm, r06, arm_turns, quality, sign);
    let [q1, q2, q3] = arm_turns;
    let turns = [q1, q2, q3, q4, q5, q6];
    let mut q = [q1.angle; 6];
    for (angle, turn) in q.iter_mut().zip(turns) {
        *angle = wrap(b, turn.angle);
    }
    if let Some(slide) = slide {
        q[2] = slide;
    }
    branch(q, turns, quality)
}

/// Spherical wrist (axes 4, 5, 6 meet, `p45 = p56 = 0`) with axes 2 and 3 parallel (PUMA 560,
/// IRB 120): `q1` by subproblem 4 (the wrist centre's height along `h2` is fixed), `q3` by
/// subproblem 3 (its distance from axis 2), `q2` by subproblem 1, then the wrist. Needs `h1`
/// not parallel to `h2`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn spherical_two_parallel<A: Algebra>(b: &mut A, problem: &Problem<'_, A::Value>) -> Branch<A::Value> {
    let (arm, r06, v0) = wrist_target(b, problem);
    let [s1, s2, s3] = problem.signs;
    let [h1, h2, ..] = arm.h;
    let [_, p12, p23, p34, ..] = arm.p;
    let reach = b.vadd(p12, p23);
    let reach = b.vadd(reach, p34);
    let height = b.dot(h2, reach);
    let (t1, first) = b.rotation_to_height(h2, h1, v0, height, s1);
    b.step("q1 by SP4", t1.nodes().into_iter().chain(first.nodes()));
    let turned = b.rotate(t1, h1, v0);
    let v1 = b.vsub(turned, p12);
    let distance = b.norm_squared(v1);
    let (q3, third, forearm) = elbow(b, &arm, distance, s2);
    let (q2, second) = b.rotation_onto(h2, forearm, v1);
    b.step("q2 by SP1", q2.nodes().into_iter().chain(second.nodes()));
    let quality = b.both(first, third);
    let quality = b.both(quality, second);
    let q1 = b.back(t1);
    spherical_branch(b, &arm, &r06, [q1, q2, q3], None, quality, s3)
}

/// Spherical wrist with axes 1 and 2 meeting (`p12 = 0`): `q3` by subproblem 3 (the wrist
/// centre's distance from the shoulder), `q1`, `q2` by subproblem 2, then the wrist. Needs `h1`
/// not parallel to `h2`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn spherical_first_two_intersecting<A: Algebra>(b: &mut A, problem: &Problem<'_, A::Value>) -> Branch<A::Value> {
    let (arm, r06, v0) = wrist_target(b, problem);
    let [s1, s2, s3] = problem.signs;
    let [h1, h2, ..] = arm.h;
    let distance = b.norm_squared(v0);
    let (q3, third, u) = elbow(b, &arm, distance, s1);
    let (t1, q2, shoulder) = b.two_rotations(h1, v0, h2, u, s2);
    b.step("q1, q2 by SP2", t1.nodes().into_iter().chain(q2.nodes()).chain(shoulder.nodes()));
    let quality = b.both(third, shoulder);
    let q1 = b.back(t1);
    spherical_branch(b, &arm, &r06, [q1, q2, q3], None, quality, s3)
}

/// Spherical wrist with axes 2 and 3 meeting (`p23 = 0`): `q1` by subproblem 3 (the wrist
/// centre seen from axis 1 lies at `|p34|` from the elbow), `q2`, `q3` by subproblem 2, then the
/// wrist. Needs `h2` not parallel to `h3`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn spherical_last_two_intersecting<A: Algebra>(b: &mut A, problem: &Problem<'_, A::Value>) -> Branch<A::Value> {
    let (arm, r06, v0) = wrist_target(b, problem);
    let [s1, s2, s3] = problem.signs;
    let [h1, h2, h3, ..] = arm.h;
    let [_, p12, _, p34, ..] = arm.p;
    let distance = b.norm_squared(p34);
    let (t1, first) = b.rotation_to_distance(h1, v0, p12, distance, s1);
    b.step("q1 by SP3", t1.nodes().into_iter().chain(first.nodes()));
    let turned = b.rotate(t1, h1, v0);
    let v1 = b.vsub(turned, p12);
    let (t2, q3, elbow) = b.two_rotations(h2, v1, h3, p34, s2);
    b.step("q2, q3 by SP2", t2.nodes().into_iter().chain(q3.nodes()).chain(elbow.nodes()));
    let quality = b.both(first, elbow);
    let (q1, q2) = (b.back(t1), b.back(t2));
    spherical_branch(b, &arm, &r06, [q1, q2, q3], None, quality, s3)
}

/// Spherical wrist with axes 1 and 2 meeting (`p12 = 0`) and joint 3 prismatic along `h3` (the
/// Stanford arm): the slide from the wrist centre's distance from the shoulder (a quadratic:
/// `|p23 + p34 + q3 h3| = |W - S|`), `q1`, `q2` by subproblem 2, then the wrist. `q3` is a
/// length, not wrapped. Needs `h1` not parallel to `h2`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn spherical_prismatic_third<A: Algebra>(b: &mut A, problem: &Problem<'_, A::Value>) -> Branch<A::Value> {
    let (arm, r06, v0) = wrist_target(b, problem);
    let [s1, s2, s3] = problem.signs;
    let [h1, h2, h3, ..] = arm.h;
    let [_, _, p23, p34, ..] = arm.p;
    // |u + q3 h3|^2 = |v0|^2 with u = p23 + p34: q3^2 + 2 (u . h3) q3 + |u|^2 - |v0|^2 = 0.
    let u = b.vadd(p23, p34);
    let half_b = b.dot(u, h3);
    let (uu, vv) = (b.norm_squared(u), b.norm_squared(v0));
    let bb = b.mul(half_b, half_b);
    let discriminant = b.sub(bb, uu);
    let discriminant = b.add(discriminant, vv);
    let size = b.add(uu, vv);
    let slack = b.constant(-1e-12);
    let bound = b.mul(slack, size);
    let exact = b.at_most(bound, discriminant);
    let zero = b.constant(0.0);
    let clamped = b.select(discriminant, discriminant, zero);
    let root = b.sqrt(clamped);
    let signed = b.mul(s1, root);
    let minus_b = b.neg(half_b);
    let slide = b.add(minus_b, signed);
    let reach = Flags { exact, singular: zero };
    b.step("q3 from the wrist centre's distance (a quadratic)", [slide, exact]);
    let along = b.scale(h3, slide);
    let u = b.vadd(u, along);
    let (t1, q2, shoulder) = b.two_rotations(h1, v0, h2, u, s2);
    b.step("q1, q2 by SP2", t1.nodes().into_iter().chain(q2.nodes()).chain(shoulder.nodes()));
    let quality = b.both(reach, shoulder);
    let (q1, none) = (b.back(t1), b.zero_turn());
    spherical_branch(b, &arm, &r06, [q1, q2, none], Some(slide), quality, s3)
}

/// Axes 2, 3, 4 parallel (direction `h = h2`) and axes 5, 6 meeting (`p56 = 0`): the UR family.
/// `q1` by subproblem 4 (the tool flange's height along `h` is fixed), `q5` by subproblem 4 (so
/// is the angle between `h` and `h6`), then the planar elbow. Needs `h1` and `h5` not parallel
/// to `h`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn three_parallel_two_intersecting<A: Algebra>(b: &mut A, problem: &Problem<'_, A::Value>) -> Branch<A::Value> {
    let (arm, r06, v0) = wrist_target(b, problem);
    let [s1, s2, s3] = problem.signs;
    let [h1, h, _, _, h5, h6] = arm.h;
    let [_, p12, p23, p34, p45, ..] = arm.p;
    let first_two = b.vadd(p12, p23);
    let last_two = b.vadd(p34, p45);
    let reach = b.vadd(first_two, last_two);
    let height = b.dot(h, reach);
    let (t1, first) = b.rotation_to_height(h, h1, v0, height, s1);
    b.step("q1 by SP4", t1.nodes().into_iter().chain(first.nodes()));
    // `h` seen from the tool flange: R16^T h.
    let q1 = b.back(t1);
    let turned = b.rotate(q1, h1, h);
    let w = b.mul_transposed(&r06, turned);
    // An orthogonal wrist (`h` and `h6` both square to `h5`: every UR) on the great circle
    // (`h6 . rot(h5, -q5) h = h6 . w`), whose half-width's sine comes from `|h6 x w|`: near the
    // wrist's singularity (`w` near `+-h6`) that keeps the digits of `q5` which the general form,
    // through `sqrt(1 - height^2)`, loses. Decided on the numbers.
    let axes = &arm.numbers.axes;
    let orthogonal = dot(axes[1], axes[4]).abs() <= ORTHOGONAL && dot(axes[5], axes[4]).abs() <= ORTHOGONAL;
    let (q5, fifth) = if orthogonal {
        let minus_q5 = b.rotation_to_height_on_great_circle(h6, h5, h, w, s2);
        (b.back(minus_q5), b.exact())
    } else {
        let height = b.dot(w, h6);
        b.rotation_to_height(h, h5, h6, height, s2)
    };
    b.step("q5 by SP4", q5.nodes().into_iter().chain(fifth.nodes()));
    let quality = b.both(first, fifth);
    let elbow = Elbow { t1, q5, quality, sign: s3, singular_pass: problem.singular_pass, near_singular: 0.0 };
    parallel_elbow(b, &arm, &r06, v0, elbow)
}

/// What [`parallel_elbow`] starts from: `q1` (as `t1 = -q1`) and `q5`, their flags, the branch
/// sign of the elbow, and how the wrist's singularity is met.
pub(crate) struct Elbow<V> {
    pub t1: Turn<V>,
    pub q5: Turn<V>,
    pub quality: Flags<V>,
    pub sign: V,
    /// Whether the sum of the parallel joints moves where `q6 = 0` leaves the elbow out of reach.
    pub singular_pass: bool,
    /// Above zero, how near the singularity (the sine between axis 6 and the parallel axes) a
    /// branch counts as at it even where subproblem 1 finds it regular ([`crate::ik::NEAR_SINGULAR_SIXTH`],
    /// for a `q5` found by a quartic to about 1e-7 rad there); zero, subproblem 1's own test.
    pub near_singular: f64,
}

/// The rest of an arm with axes 2, 3, 4 parallel, once `q1` and `q5` are known: `q6` and the sum
/// `q2 + q3 + q4` (with the axes' signs) by subproblem 1, `q3` by subproblem 3, `q2` by
/// subproblem 1, `q4` by difference.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn parallel_elbow<A: Algebra>(
    b: &mut A,
    arm: &Arm<'_, A::Value>,
    r06: &Matrix<A::Value>,
    v0: Vector<A::Value>,
    Elbow { t1, q5, quality, sign, singular_pass, near_singular }: Elbow<A::Value>,
) -> Branch<A::Value> {
    let [h1, h, h3, h4, h5, h6] = arm.h;
    let [_, p12, _, _, p45, p56, _] = arm.p;
    let (sign3, sign4) = (b.dot(h, h3), b.dot(h, h4));
    // A direction across `h`, rotated by the sum of the parallel joints' angles.
    let across = b.cross(h, h5);
    let q1 = b.back(t1);
    let turned = b.rotate(q1, h1, h);
    let w = b.mul_transposed(r06, turned);
    let turned = b.rotate(t1, h1, v0);
    let v1 = b.vsub(turned, p12);
    let back5 = b.back(q5);
    let seen = b.rotate(back5, h5, h);
    let (t6, sixth) = b.rotation_onto(h6, seen, w);
    b.step("q6 by SP1", t6.nodes().into_iter().chain(sixth.nodes()));
    let across5 = b.rotate(back5, h5, across);
    let across6 = b.rotate(t6, h6, across5);
    let in_base = b.mul_vector(r06, across6);
    let turned = b.rotate(t1, h1, in_base);
    let (sum, summed) = b.rotation_onto(h, across, turned);
    b.step("q2 + q3 + q4 by SP1", sum.nodes().into_iter().chain(summed.nodes()));
    // The wrist's offset from the end of the forearm, turned with the sum.
    let u = b.rotate(q5, h5, p56);
    let u = b.vadd(p45, u);
    let t6 = b.back(t6);
    let sixth_angle = wrap(b, t6.angle);
    let (sum, t6, sixth_angle, sixth) = if singular_pass {
        let seen_along = b.dot(h6, seen);
        let free = free_sixth(b, arm, v1, u, sum, seen_along);
        let (moved, sixth) = if near_singular > 0.0 {
            // Near the singularity, by the sine between axis 6 and the parallel axes.
            let axis_across = b.cross(h6, seen);
            let across_squared = b.norm_squared(axis_across);
            let seen_squared = b.norm_squared(seen);
            let limit = b.constant(near_singular * near_singular);
            let bound = b.mul(limit, seen_squared);
            let close = b.at_most(across_squared, bound);
            let near = b.or(sixth.singular, close);
            let moved = b.and(near, free.moves);
            let singular = b.or(sixth.singular, moved);
            (moved, Flags { exact: sixth.exact, singular })
        } else {
            (b.and(sixth.singular, free.moves), sixth)
        };
        let sum = b.select_turn(moved, free.sum, sum);
        let t6 = b.select_turn(moved, free.sixth, t6);
        let sixth_angle = b.select(moved, free.sixth.angle, sixth_angle);
        b.step(
            "at the wrist's singularity, the sum and q6 moved where q6 = 0 leaves the elbow out of reach",
            sum.nodes().into_iter().chain(t6.nodes()).chain([sixth_angle]),
        );
        (sum, t6, sixth_angle, sixth)
    } else {
        (sum, t6, sixth_angle, sixth)
    };
    let wrist = b.rotate(sum, h, u);
    let v = b.vsub(v1, wrist);
    let distance = b.norm_squared(v);
    let (q3, third, forearm) = elbow(b, arm, distance, sign);
    let (q2, second) = b.rotation_onto(h, forearm, v);
    b.step("q2 by SP1", q2.nodes().into_iter().chain(second.nodes()));
    // q4 = sign4 (sum - q2 - sign3 q3), its cosine and sine by the angle-sum formulas (the signs
    // are +-1: the axes are parallel, exactly or as the plan wrote them).
    let rest = b.sub(sum.angle, q2.angle);
    let third_part = b.mul(sign3, q3.angle);
    let rest = b.sub(rest, third_part);
    let q4 = b.mul(sign4, rest);
    let axes = &arm.numbers.axes;
    let (sign3_exact, sign4_exact) = (dot(axes[1], axes[2]).signum(), dot(axes[1], axes[3]).signum());
    let t4 = b.difference(sum, q2);
    let t4 = if sign3_exact > 0.0 { b.difference(t4, q3) } else { b.angle_sum(t4, q3) };
    let t4 = if sign4_exact > 0.0 { t4 } else { b.back(t4) };
    b.step("q4 by difference", [q4, t4.cos, t4.sin]);
    let quality = b.both(quality, sixth);
    let quality = b.both(quality, summed);
    let quality = b.both(quality, third);
    let quality = b.both(quality, second);
    let turns = [q1, q2, q3, t4, q5, t6];
    let (w1, w2, w3) = (wrap(b, q1.angle), wrap(b, q2.angle), wrap(b, q3.angle));
    let w4 = wrap_sum(b, q4);
    let w5 = wrap(b, q5.angle);
    branch([w1, w2, w3, w4, w5, sixth_angle], turns, quality)
}

/// The sum `q2 + q3 + q4` and `q6` at the wrist's singularity, where axis 6 is in line with the
/// parallel axes (`seen_along` the cosine between them, `e` its sign): the rotation then fixes
/// only `sum + e q6`, and the sum found (with `q6 = 0` at the singularity itself) is one
/// representative. The wrist's offset `u` turns with the sum, and the elbow must reach what it
/// leaves (`v1 - rot(h, sum) u`), so where the sum found leaves the elbow out of reach the sum
/// moves: to where the elbow's squared distance is the middle of what both the elbow and the
/// turning offset can reach (so neither is at its limit), the root of that subproblem 4 nearest
/// the sum found, and `q6` takes up the difference.
struct FreeSixth<V> {
    /// `1` where the sum moves (the elbow misses with the sum found, and the distance turns with
    /// the sum: the offset has a part across the axes), else `0`; the caller ands it with the
    /// singularity.
    moves: V,
    /// The sum moved.
    sum: Turn<V>,
    /// `q6` for it, its angle in `(-pi, pi]`.
    sixth: Turn<V>,
}

#[cfg_attr(not(debug_assertions), inline(always))]
fn free_sixth<A: Algebra>(
    b: &mut A,
    arm: &Arm<'_, A::Value>,
    v1: Vector<A::Value>,
    u: Vector<A::Value>,
    sum: Turn<A::Value>,
    seen_along: A::Value,
) -> FreeSixth<A::Value> {
    let [_, h, h3, ..] = arm.h;
    let [_, _, p23, p34, ..] = arm.p;
    let minus_one = b.constant(-1.0);
    let one = b.constant(1.0);
    let back23 = b.scale(p23, minus_one);
    let turned = b.rotate(sum, h, u);
    let v = b.vsub(v1, turned);
    let distance = b.norm_squared(v);
    // Whether the elbow reaches does not depend on which of its roots: either sign serves.
    let (_, reached) = b.rotation_to_distance(h3, p34, back23, distance, one);
    // The elbow's squared distances (numbers: the arm's alone), and those of
    // `v1 - rot(h, t) u` over every `t`.
    let numbers = arm.numbers;
    let [x, y, z] = numbers.offsets[2];
    let (elbow_lo, elbow_hi) = distance_range(numbers.axes[2], numbers.offsets[3], [-x, -y, -z]);
    let (elbow_lo, elbow_hi) = (b.constant(elbow_lo), b.constant(elbow_hi));
    let (vv, uu) = (b.norm_squared(v1), b.norm_squared(u));
    // Written as subproblem 4 below writes them (`v1 . h`, `h . u`, `h x u`), so a graph shares them.
    let (hv, hu) = (b.dot(v1, h), b.dot(h, u));
    let lengths = b.add(vv, uu);
    let two = b.constant(2.0);
    let twice = b.mul(two, hv);
    let twice = b.mul(twice, hu);
    let middle = b.sub(lengths, twice);
    let (hxv, hxu) = (b.cross(h, v1), b.cross(h, u));
    let (across_v, across_u) = (b.norm_squared(hxv), b.norm_squared(hxu));
    let across = b.mul(across_v, across_u);
    let root = b.sqrt(across);
    let swing = b.mul(two, root);
    let (least, most) = (b.sub(middle, swing), b.add(middle, swing));
    let over = b.sub(elbow_lo, least);
    let lo = b.select(over, elbow_lo, least);
    let under = b.sub(most, elbow_hi);
    let hi = b.select(under, elbow_hi, most);
    let half = b.constant(0.5);
    let goal = b.add(lo, hi);
    let goal = b.mul(half, goal);
    // |v1 - rot(h, t) u|^2 = goal: v1 . rot(h, t) u = (|v1|^2 + |u|^2 - goal) / 2.
    let height = b.sub(lengths, goal);
    let height = b.mul(half, height);
    // The root nearest the sum found. The equation is `a cos t + b sin t = c` (subproblem 4's `a`
    // and `b`, the same values), whose roots `t` have `cos(t - sum) = (c (a cos sum + b sin sum)
    // +- w (a sin sum - b cos sum)) / (a^2 + b^2)` with `w >= 0`: the sign of `a sin sum - b cos
    // sum` picks the nearer.
    let hu_along = b.mul(hv, hu);
    let vu = b.dot(v1, u);
    let a = b.sub(vu, hu_along);
    let hxu_dot = b.dot(v1, hxu);
    let (a_sin, b_cos) = (b.mul(a, sum.sin), b.mul(hxu_dot, sum.cos));
    let nearer = b.sub(a_sin, b_cos);
    let zero = b.constant(0.0);
    let plus_nearer = b.at_most(zero, nearer);
    let sign = b.select(plus_nearer, one, minus_one);
    let (new_sum, moved) = b.rotation_to_height(v1, h, u, height, sign);
    // q6 moves by e (sum - new sum), its cosine and sine by the angle-difference formulas.
    let e = b.select(seen_along, one, minus_one);
    let change = b.sub(sum.angle, new_sum.angle);
    let change = b.mul(e, change);
    let angle = wrap_sum(b, change);
    let difference = b.difference(sum, new_sum);
    let sin = b.mul(e, difference.sin);
    let sixth = Turn { angle, cos: difference.cos, sin };
    let missed = b.sub(one, reached.exact);
    let regular = b.sub(one, moved.singular);
    let moves = b.and(missed, regular);
    FreeSixth { moves, sum: new_sum, sixth }
}
