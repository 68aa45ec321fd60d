//! The closed-form families of six-joint revolute arms, each a fixed composition of the
//! subproblems (IK-Geo's decompositions, arXiv 2211.05737, section V), for the geometry the
//! compiler classified and wrote as constants. Every function returns its branches in a fixed order
//! (first joint's branch outermost), exact or least-squares, flagged: all eight where the family's
//! first step is a subproblem of two solutions, and as many as the quartic of subproblem 5 or 6
//! has (up to four, each with two more branches) where it is one of those.
//!
//! The arm is written as IK-Geo writes it, a product of exponentials at the zero configuration:
//! `R = rot(h1, q1) ... rot(h6, q6) R6T` and
//! `p = p01 + R01 p12 + R02 p23 + R03 p34 + R04 p45 + R05 p56 + R06 p6T`, every vector in the base
//! frame. Offsets along an axis can be moved freely, and the compiler moves them so that the
//! axes a family needs to meet have a zero offset between them (`p45 = p56 = 0` for a spherical
//! wrist).
//!
//! `Arm6` is a six-joint arm at `q = 0` as a product of exponentials; one function per closed-form
//! family composes the subproblems into its branches (all eight, or two per real root of a quartic
//! for the general spherical wrist and the three-parallel arm), the Stanford arm's slide by a
//! quadratic. At the wrist's singularity each branch gets a representative, which for the arms with
//! axes 2, 3, 4 parallel moves the sum of those joints where `q6 = 0` would leave the elbow out of
//! reach (`free_sixth`). `FreeArm6` is the six of a seven-joint arm with the part after the free
//! joint turned at run time; `PlanarArm` is two or three revolute joints about parallel axes and at
//! most one prismatic joint along them, solved for what such an arm can reach.

use super::solutions::{IkSolution, IkSolutions};
use super::subproblem::{
    Quality, Turn, distance_range, rotation_onto, rotation_to_distance, rotation_to_height,
    rotation_to_height_on_great_circle, three_rotations, two_heights, two_rotations,
};
use super::vector::{M3, V3, add, cross, dot, mul, mul_by_transpose, norm_squared, scale, sub, wrap};
use crate::pose::Pose;

/// A six-joint revolute arm at its zero configuration (IK-Geo's form): unit axes `h1..h6`, the
/// offsets `p01, p12, ..., p56, p6T` between points on consecutive axes, and the tool's rotation
/// `R6T`, all in the base frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Arm6 {
    /// `h1 .. h6`: unit joint axes.
    pub axes: [V3; 6],
    /// `p01, p12, p23, p34, p45, p56, p6T`.
    pub offsets: [V3; 7],
    /// `R6T`: the tool's rotation at the zero configuration.
    pub tool_rotation: M3,
}

/// The wrist's position and rotation the first joints must reach: `R06 = R R6T^T` and the point
/// `p - R06 p6T` less `p01`.
#[inline(always)]
fn wrist_target(arm: &Arm6, target: &Pose<f64>) -> (M3, V3) {
    let r06 = mul_by_transpose(&target.rotation, &arm.tool_rotation);
    let point = sub(sub(target.translation, mul(&r06, arm.offsets[6])), arm.offsets[0]);
    (r06, point)
}

/// Below this (the cosine between two unit axes) a wrist's axes are square for
/// [`rotation_to_height_on_great_circle`]: the rounding of axes written as exact quarter turns.
pub const ORTHOGONAL: f64 = 1e-15;

/// The spherical wrist's joints 4, 5, 6 for arm angles `q1, q2, q3`: `rot(h4, q4) rot(h5, q5)
/// rot(h6, q6) = R03^T R06`, `q5` by subproblem 4 (turning about `h4` keeps the height of `R36 h6`
/// along it), then `q4` and `q6` each by subproblem 1. Two branches. (Subproblem 2 would give `q4`
/// with `q5`, but from where two cones nearly touch, which near the singularity loses half the
/// digits of `q4` and `q6`; subproblem 1 loses only as many as the distance to it.)
#[inline(always)]
fn spherical_wrist(arm: &Arm6, r06: &M3, [q1, q2, q3]: [Turn; 3], quality: Quality, out: &mut IkSolutions<6, 8>) {
    spherical_wrist_after(arm, r06, [q1, q2, q3], None, quality, out);
}

/// [`spherical_wrist`], with joint 3 a slide by `slide` (its turn then `Turn::ZERO`) when given.
#[inline(always)]
fn spherical_wrist_after(
    arm: &Arm6,
    r06: &M3,
    [q1, q2, q3]: [Turn; 3],
    slide: Option<f64>,
    quality: Quality,
    out: &mut IkSolutions<6, 8>,
) {
    let h = &arm.axes;
    let back = |v: V3| q3.back().rotate(h[2], q2.back().rotate(h[1], q1.back().rotate(h[0], v)));
    let r36_h6 = back(mul(r06, h[5]));
    let r36_h5 = back(mul(r06, h[4]));
    // An orthogonal wrist (the usual one: h4 and h6 both square to h5, known at compile time, so
    // the test folds away) takes the well-conditioned form of subproblem 4.
    let orthogonal = dot(h[3], h[4]).abs() <= ORTHOGONAL && dot(h[5], h[4]).abs() <= ORTHOGONAL;
    let (q5s, fifth) = if orthogonal {
        (rotation_to_height_on_great_circle(h[3], h[4], h[5], r36_h6), Quality::EXACT)
    } else {
        rotation_to_height(h[3], h[4], h[5], dot(h[3], r36_h6))
    };
    for q5 in q5s {
        let (q4, fourth) = rotation_onto(h[3], q5.rotate(h[4], h[5]), r36_h6);
        let (q6, sixth) = rotation_onto(h[5], h[4], q5.back().rotate(h[4], q4.back().rotate(h[3], r36_h5)));
        let all = quality.and(fifth).and(fourth).and(sixth);
        let mut q = [q1.angle, q2.angle, q3.angle, q4.angle, q5.angle, q6.angle].map(wrap);
        if let Some(slide) = slide {
            q[2] = slide;
        }
        #[allow(clippy::expect_used, reason = "invariant: two wrist flips per arm branch, four arm branches at most")]
        out.push(IkSolution::unmeasured(q, all.exact, all.singular))
            .expect("invariant: two wrist flips for each of at most four arm branches: at most 8 solutions");
    }
}

/// Spherical wrist with axes 1 and 2 meeting (`p12 = 0`) and joint 3 prismatic along `h3` (the
/// Stanford arm): the slide from the wrist centre's distance from the shoulder (a quadratic:
/// `|p23 + p34 + q3 h3| = |W - S|`, two roots), `q1`, `q2` by subproblem 2, then the wrist. `q3`
/// is a length, not wrapped. Needs `h1` not parallel to `h2`.
#[inline(always)]
pub fn spherical_prismatic_third(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h2, h3, ..] = arm.axes;
    let [_, _, p23, p34, ..] = arm.offsets;
    let (r06, v0) = wrist_target(arm, target);
    let mut out = IkSolutions::new();
    // |u + q3 h3|^2 = |v0|^2 with u = p23 + p34: q3^2 + 2 (u . h3) q3 + |u|^2 - |v0|^2 = 0.
    let u = add(p23, p34);
    let b = dot(u, h3);
    let discriminant = b * b - norm_squared(u) + norm_squared(v0);
    let size = norm_squared(u) + norm_squared(v0);
    let exact = discriminant >= -1e-12 * size;
    let root = if discriminant > 0.0 { libm::sqrt(discriminant) } else { 0.0 };
    let reach = Quality { exact, singular: false };
    for q3 in [-b + root, -b - root] {
        let (pairs, shoulder) = two_rotations(h1, v0, h2, add(u, scale(h3, q3)));
        for (t1, q2) in pairs {
            spherical_wrist_after(arm, &r06, [t1.back(), q2, Turn::ZERO], Some(q3), reach.and(shoulder), &mut out);
        }
    }
    out
}

/// Spherical wrist (axes 4, 5, 6 meet, `p45 = p56 = 0`) with axes 2 and 3 parallel (PUMA 560,
/// IRB 120): `q1` by subproblem 4 (the wrist centre's height along `h2` is fixed), `q3` by
/// subproblem 3 (its distance from axis 2), `q2` by subproblem 1, then the wrist. Needs `h1`
/// not parallel to `h2`.
#[inline(always)]
pub fn spherical_two_parallel(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h2, h3, ..] = arm.axes;
    let [_, p12, p23, p34, ..] = arm.offsets;
    let (r06, v0) = wrist_target(arm, target);
    let mut out = IkSolutions::new();
    let (t1s, first) = rotation_to_height(h2, h1, v0, dot(h2, add(add(p12, p23), p34)));
    for t1 in t1s {
        let v1 = sub(t1.rotate(h1, v0), p12);
        let (q3s, third) = rotation_to_distance(h3, p34, scale(p23, -1.0), norm_squared(v1));
        for q3 in q3s {
            let (q2, second) = rotation_onto(h2, add(p23, q3.rotate(h3, p34)), v1);
            let quality = first.and(third).and(second);
            spherical_wrist(arm, &r06, [t1.back(), q2, q3], quality, &mut out);
        }
    }
    out
}

/// Spherical wrist with axes 1 and 2 meeting (`p12 = 0`): `q3` by subproblem 3 (the wrist
/// centre's distance from the shoulder), `q1`, `q2` by subproblem 2, then the wrist. Needs `h1`
/// not parallel to `h2`.
#[inline(always)]
pub fn spherical_first_two_intersecting(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h2, h3, ..] = arm.axes;
    let [_, _, p23, p34, ..] = arm.offsets;
    let (r06, v0) = wrist_target(arm, target);
    let mut out = IkSolutions::new();
    let (q3s, third) = rotation_to_distance(h3, p34, scale(p23, -1.0), norm_squared(v0));
    for q3 in q3s {
        let u = add(p23, q3.rotate(h3, p34));
        let (pairs, shoulder) = two_rotations(h1, v0, h2, u);
        for (t1, q2) in pairs {
            spherical_wrist(arm, &r06, [t1.back(), q2, q3], third.and(shoulder), &mut out);
        }
    }
    out
}

/// Spherical wrist with axes 2 and 3 meeting (`p23 = 0`): `q1` by subproblem 3 (the wrist
/// centre seen from axis 1 lies at `|p34|` from the elbow), `q2`, `q3` by subproblem 2, then the
/// wrist. Needs `h2` not parallel to `h3`.
#[inline(always)]
pub fn spherical_last_two_intersecting(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h2, h3, ..] = arm.axes;
    let [_, p12, _, p34, ..] = arm.offsets;
    let (r06, v0) = wrist_target(arm, target);
    let mut out = IkSolutions::new();
    let (t1s, first) = rotation_to_distance(h1, v0, p12, norm_squared(p34));
    for t1 in t1s {
        let v1 = sub(t1.rotate(h1, v0), p12);
        let (pairs, elbow) = two_rotations(h2, v1, h3, p34);
        for (t2, q3) in pairs {
            spherical_wrist(arm, &r06, [t1.back(), t2.back(), q3], first.and(elbow), &mut out);
        }
    }
    out
}

/// Axes 2, 3, 4 parallel (direction `h = h2`) and axes 5, 6 meeting (`p56 = 0`): the UR family.
/// `q1` by subproblem 4 (the tool flange's height along `h` is fixed), `q5` by subproblem 4 (so
/// is the angle between `h` and `h6`), then `parallel_elbow`. Needs `h1` and `h5` not parallel
/// to `h`.
#[inline(always)]
pub fn three_parallel_two_intersecting(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h, _, _, h5, h6] = arm.axes;
    let [_, p12, p23, p34, p45, ..] = arm.offsets;
    let (r06, v0) = wrist_target(arm, target);
    let mut out = IkSolutions::new();
    let (t1s, first) = rotation_to_height(h, h1, v0, dot(h, add(add(p12, p23), add(p34, p45))));
    for t1 in t1s {
        // `h` seen from the tool flange: R16^T h.
        let w = super::vector::mul_transposed(&r06, t1.back().rotate(h1, h));
        let (q5s, fifth) = fifth_angle(h, h5, h6, w);
        for q5 in q5s {
            parallel_elbow(arm, &r06, v0, t1, q5, first.and(fifth), 0.0, &mut out);
        }
    }
    out
}

/// `q5` of an arm with axes 2, 3, 4 parallel (direction `h`): `h . rot(h5, q5) h6 = h6 . w` for
/// `w = R16^T h` (subproblem 4). An orthogonal wrist (`h` and `h6` both square to `h5`: every UR;
/// known at compile time, so the test folds away) takes it as `h6 . rot(h5, -q5) h = h6 . w` on the
/// great circle, whose half-width's sine comes from `|h6 x w|`: near the wrist's singularity
/// (`w` near `+-h6`) that keeps the digits of `q5` which the general form, through `sqrt(1 -
/// height^2)`, loses (its error grows as 1e-16 over the distance to the singularity, and the
/// pose's with it).
#[inline(always)]
fn fifth_angle(h: V3, h5: V3, h6: V3, w: V3) -> ([Turn; 2], Quality) {
    let orthogonal = dot(h, h5).abs() <= ORTHOGONAL && dot(h6, h5).abs() <= ORTHOGONAL;
    if orthogonal {
        let [plus, minus] = rotation_to_height_on_great_circle(h6, h5, h, w);
        ([plus.back(), minus.back()], Quality::EXACT)
    } else {
        rotation_to_height(h, h5, h6, dot(w, h6))
    }
}

/// Axes 2, 3, 4 parallel (direction `h = h2`), no other two meeting: `q1` and `q5` together by
/// subproblem 6 (the tool flange's height along `h`, and the angle between `h` and `h6`, are
/// both fixed, and each depends on `q1` and `q5` alone; at most four pairs), then
/// `parallel_elbow`. Needs `h1` and `h5` not parallel to `h`.
#[inline(always)]
pub fn three_parallel(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h, _, _, h5, h6] = arm.axes;
    let [_, p12, p23, p34, p45, p56, _] = arm.offsets;
    let (r06, v0) = wrist_target(arm, target);
    let mut out = IkSolutions::new();
    // h . R1^T v0 - h . R5 p56 = h . (p12 + p23 + p34 + p45) and h . R1^T R06 h6 - h . R5 h6 = 0,
    // with t1 = -q1.
    let pairs = two_heights(
        [h; 4],
        [h1, h5, h1, h5],
        [v0, scale(p56, -1.0), mul(&r06, h6), scale(h6, -1.0)],
        [dot(h, add(add(p12, p23), add(p34, p45))), 0.0],
    );
    for &(t1, q5) in pairs.as_slice() {
        // Near the wrist singularity the quartic's two roots there (the wrist flips) are found to
        // about 1e-7 rad, or as one at their tangency: short of the sixth subproblem's own test,
        // so near it an elbow out of reach counts as singular.
        parallel_elbow(arm, &r06, v0, t1, q5, pairs.quality, NEAR_SINGULAR_SIXTH, &mut out);
    }
    out
}

/// The rest of an arm with axes 2, 3, 4 parallel, once `q1` (as `t1 = -q1`) and `q5` are known:
/// `q6` by subproblem 1, the sum `q2 + q3 + q4` (with the axes' signs) by subproblem 1, then the
/// planar elbow: `q3` by subproblem 3, `q2` by subproblem 1, `q4` from the sum. Two branches.
#[inline(always)]
#[allow(clippy::too_many_arguments, reason = "the steps before it, and how near the singularity counts")]
fn parallel_elbow(
    arm: &Arm6,
    r06: &M3,
    v0: V3,
    t1: Turn,
    q5: Turn,
    quality: Quality,
    near_singular: f64,
    out: &mut IkSolutions<6, 8>,
) {
    let [h1, h, h3, h4, h5, h6] = arm.axes;
    let [_, p12, p23, p34, p45, p56, _] = arm.offsets;
    let (sign3, sign4) = (dot(h, h3), dot(h, h4));
    // A direction across `h`, rotated by the sum of the parallel joints' angles.
    let across = cross(h, h5);
    let q1 = t1.back();
    // `h` seen from the tool flange: R16^T h.
    let w = super::vector::mul_transposed(r06, q1.rotate(h1, h));
    let v1 = sub(t1.rotate(h1, v0), p12);
    let seen = q5.back().rotate(h5, h);
    let (t6, sixth) = rotation_onto(h6, seen, w);
    let turned = t1.rotate(h1, mul(r06, t6.rotate(h6, q5.back().rotate(h5, across))));
    let (sum, summed) = rotation_onto(h, across, turned);
    // The wrist's offset from the end of the forearm, turned with the sum.
    let u = add(p45, q5.rotate(h5, p56));
    let near = sixth.singular || norm_squared(cross(h6, seen)) <= near_singular * near_singular * norm_squared(seen);
    let free = if near { free_sixth(arm, v1, u, sum, dot(h6, seen)) } else { None };
    let (sum, q6, sixth) = match free {
        Some((sum, moved)) => (sum, -t6.angle + moved.angle, Quality { exact: sixth.exact, singular: true }),
        None => (sum, -t6.angle, sixth),
    };
    let v = sub(v1, sum.rotate(h, u));
    let (q3s, third) = rotation_to_distance(h3, p34, scale(p23, -1.0), norm_squared(v));
    for q3 in q3s {
        let (q2, second) = rotation_onto(h, add(p23, q3.rotate(h3, p34)), v);
        let q4 = sign4 * (sum.angle - q2.angle - sign3 * q3.angle);
        let all = quality.and(sixth).and(summed).and(third).and(second);
        let q = [q1.angle, q2.angle, q3.angle, q4, q5.angle, q6];
        #[allow(clippy::expect_used, reason = "invariant: two elbows per q1 and q5 branch, four of those at most")]
        out.push(IkSolution::unmeasured(q.map(wrap), all.exact, all.singular))
            .expect("invariant: two elbows for each of at most four (q1, q5) branches: at most 8 solutions");
    }
}

/// How near the wrist's singularity (the sine of the angle between axis 6 and the parallel axes,
/// as joint 5 turns them) the three-parallel arm's branches count as at it when the sum that the
/// sixth joint's angle gives leaves the elbow out of reach: near it its quartic's two roots (the
/// wrist flips) are found to about 1e-7 rad, short of the subproblem's `DEGENERATE`, and the sixth
/// angle of such a root is noise. The branch is then flagged singular, and its errors (up to about this times
/// the sixth angle's move, in rad) are measured like any other's.
pub const NEAR_SINGULAR_SIXTH: f64 = 1e-6;

/// The sum `q2 + q3 + q4` and `q6` at the wrist's singularity, where axis 6 is in line with the
/// parallel axes (`R5^T h = e h6`, `e = +-1`: `seen_along`, the cosine between them): the rotation
/// then fixes only `sum + e q6`, and the sum found (with `q6 = 0` at the singularity itself) is
/// one representative. The
/// wrist's offset `u` turns with the sum, and the elbow must reach what it leaves (`v1 - rot(h,
/// sum) u`), so where `q6 = 0` leaves the elbow out of reach the sum moves: to where the elbow's
/// squared distance is the middle of what both the elbow and the turning offset can reach (so
/// neither is at its limit), the root of that equation (subproblem 4) nearest the sum found, and
/// `q6` takes up the difference: the new sum, and the turn to add to `q6`. `None` where the sum
/// found serves, or where the offset has no part across the axes (the distance does not change
/// with the sum).
#[inline(always)]
fn free_sixth(arm: &Arm6, v1: V3, u: V3, sum: Turn, seen_along: f64) -> Option<(Turn, Turn)> {
    let [_, h, h3, ..] = arm.axes;
    let [_, _, p23, p34, ..] = arm.offsets;
    let back23 = scale(p23, -1.0);
    let (_, reached) = rotation_to_distance(h3, p34, back23, norm_squared(sub(v1, sum.rotate(h, u))));
    if reached.exact {
        return None;
    }
    // The elbow's squared distances, and those of `v1 - rot(h, t) u` over every `t`.
    let (elbow_lo, elbow_hi) = distance_range(h3, p34, back23);
    let middle = norm_squared(v1) + norm_squared(u) - 2.0 * dot(h, v1) * dot(h, u);
    let swing = 2.0 * libm::sqrt(norm_squared(cross(h, v1)) * norm_squared(cross(h, u)));
    let lo = if elbow_lo > middle - swing { elbow_lo } else { middle - swing };
    let hi = if elbow_hi < middle + swing { elbow_hi } else { middle + swing };
    let goal = 0.5 * (lo + hi);
    // |v1 - rot(h, t) u|^2 = goal: v1 . rot(h, t) u = (|v1|^2 + |u|^2 - goal) / 2.
    let height = 0.5 * (norm_squared(v1) + norm_squared(u) - goal);
    let ([plus, minus], moved) = rotation_to_height(v1, h, u, height);
    if moved.singular {
        return None;
    }
    let closeness = |t: Turn| t.cos * sum.cos + t.sin * sum.sin;
    let new_sum = if closeness(plus) >= closeness(minus) { plus } else { minus };
    // q6 moves by e (sum - new_sum), its cosine and sine by the angle-difference formulas.
    let e = if seen_along > 0.0 { 1.0 } else { -1.0 };
    let q6 = Turn {
        angle: wrap(e * (sum.angle - new_sum.angle)),
        cos: sum.cos * new_sum.cos + sum.sin * new_sum.sin,
        sin: e * (sum.sin * new_sum.cos - sum.cos * new_sum.sin),
    };
    Some((new_sum, q6))
}

/// Spherical wrist (axes 4, 5, 6 meet, `p45 = p56 = 0`) with no two of axes 1, 2, 3 parallel or
/// meeting: `q1`, `q2`, `q3` by subproblem 5 (`R1^T W - p12 = R2 (p23 + R3 p34)` for the wrist
/// centre `W`; at most four triples), then the wrist.
#[inline(always)]
pub fn spherical(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h2, h3, ..] = arm.axes;
    let [_, p12, p23, p34, ..] = arm.offsets;
    let (r06, v0) = wrist_target(arm, target);
    let mut out = IkSolutions::new();
    let triples = three_rotations(scale(p12, -1.0), h1, v0, h2, p23, h3, p34);
    for &[t1, q2, q3] in triples.as_slice() {
        spherical_wrist(arm, &r06, [t1.back(), q2, q3], triples.quality, &mut out);
    }
    out
}

/// A seven-joint arm whose joint `free` (its value an input) is fixed before solving the other
/// six in closed form: the six's geometry at the free joint's zero (points on their axes rather
/// than offsets, so that the part after the free joint can be turned rigidly), and the free
/// joint's axis and a point on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeArm6 {
    /// The six solved joints' unit axes, at the free joint's zero.
    pub axes: [V3; 6],
    /// A point on each of their axes (meeting axes share theirs).
    pub points: [V3; 6],
    /// The tip's origin at the free joint's zero.
    pub tip_point: V3,
    /// The tip's rotation at zero.
    pub tool_rotation: M3,
    /// The free joint's unit axis.
    pub free_axis: V3,
    /// A point on it.
    pub free_point: V3,
    /// The first of the six after the free joint (the free joint's index in `q`).
    pub free_index: usize,
}

impl FreeArm6 {
    /// The six-joint arm with the free joint at `angle`: everything after it turned about its
    /// axis.
    #[inline(always)]
    pub fn at(&self, angle: f64) -> Arm6 {
        let (s, c) = libm::sincos(angle);
        let k = self.free_axis;
        let turn_point = |p: V3| add(self.free_point, super::vector::rotate_cs(k, c, s, sub(p, self.free_point)));
        let mut axes = self.axes;
        let mut points = self.points;
        for i in self.free_index..6 {
            axes[i] = super::vector::rotate_cs(k, c, s, axes[i]);
            points[i] = turn_point(points[i]);
        }
        let tip = turn_point(self.tip_point);
        let r = &self.tool_rotation;
        let columns = [0, 1, 2].map(|j| super::vector::rotate_cs(k, c, s, [r[0][j], r[1][j], r[2][j]]));
        let tool_rotation = [0, 1, 2].map(|i| [columns[0][i], columns[1][i], columns[2][i]]);
        Arm6::from_points(axes, &points, tip, tool_rotation)
    }
}

impl Arm6 {
    /// The arm whose axes pass through `points` (one on each, in the base frame at `q = 0`) with
    /// its tip at `tip_point`: the offsets are the points' differences, from the base's origin
    /// to the first and from the last to the tip (points placed at one meeting point subtract to
    /// exact zeros).
    pub fn from_points(axes: [V3; 6], points: &[V3; 6], tip_point: V3, tool_rotation: M3) -> Arm6 {
        let mut offsets = [[0.0; 3]; 7];
        offsets[0] = points[0];
        for i in 1..6 {
            offsets[i] = sub(points[i], points[i - 1]);
        }
        offsets[6] = sub(tip_point, points[5]);
        Arm6 { axes, offsets, tool_rotation }
    }
}

/// Six-joint solutions as seven-joint ones: `value` (the free joint's) inserted at `index`.
#[inline(always)]
pub fn insert_free<const M: usize>(six: &IkSolutions<6, M>, index: usize, value: f64) -> IkSolutions<7, M> {
    let mut out = IkSolutions::new();
    for s in six.iter() {
        let mut q = [value; 7];
        let mut from = 0;
        for (i, entry) in q.iter_mut().enumerate() {
            if i != index {
                *entry = s.q[from];
                from += 1;
            }
        }
        let seven = IkSolution {
            q,
            exact: s.exact,
            singular: s.singular,
            position_error: s.position_error,
            rotation_error: s.rotation_error,
        };
        #[allow(clippy::expect_used, reason = "invariant: one seven-joint solution per six-joint one, same capacity")]
        out.push(seven).expect("invariant: one seven-joint solution per six-joint one, both lists of capacity M");
    }
    out
}

/// One joint of a [`PlanarArm`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlanarJoint {
    /// A revolute joint about `sign * h` through `point`.
    Revolute {
        /// `+1` or `-1`: its axis is `sign * h`.
        sign: f64,
        /// A point on its axis at `q = 0`.
        point: V3,
    },
    /// A prismatic joint sliding along `sign * h`.
    Prismatic {
        /// `+1` or `-1`.
        sign: f64,
    },
}

/// An arm whose revolute joints (two or three) all turn about axes parallel to `h`, with at most
/// one prismatic joint sliding along `h`: planar 2R and 3R arms, the SCARA. It reaches what it
/// can of a pose: the position (2R), the position and the rotation about `h` (3R), and with the
/// prismatic joint the height along `h` too (SCARA); an arm without one keeps its height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarArm<const N: usize> {
    /// The common direction of the axes (unit).
    pub axis: V3,
    /// The joints, in the order of `q`.
    pub joints: [PlanarJoint; N],
    /// The tip's origin at `q = 0`.
    pub tip_point: V3,
    /// The tip's rotation at `q = 0`.
    pub tool_rotation: M3,
}

/// Below this (relative to the lengths involved) a height counts as reached.
const PLANAR_SLACK: f64 = 1e-12;

/// Below this a target's rotation counts as a turn about the arm's axis (the distance by which it
/// moves the axis's image, in radians).
const TILT_SLACK: f64 = 1e-9;

impl<const N: usize> PlanarArm<N> {
    /// The pose the arm reaches at `q` (a product of exponentials; for tests and tools).
    pub fn pose(&self, q: &[f64; N]) -> Pose<f64> {
        let mut rotation = self.tool_rotation;
        let mut point = self.tip_point;
        for i in (0..N).rev() {
            match self.joints[i] {
                PlanarJoint::Revolute { sign, point: o } => {
                    let k = scale(self.axis, sign);
                    let columns = [0, 1, 2]
                        .map(|j| super::vector::rotate(k, q[i], [rotation[0][j], rotation[1][j], rotation[2][j]]));
                    rotation = [0, 1, 2].map(|r| [columns[0][r], columns[1][r], columns[2][r]]);
                    point = add(o, super::vector::rotate(k, q[i], sub(point, o)));
                }
                PlanarJoint::Prismatic { sign } => point = add(point, scale(self.axis, sign * q[i])),
            }
        }
        Pose { rotation, translation: point }
    }

    /// Both solutions (elbow one way and the other) for `target`.
    #[inline(always)]
    pub fn solve(&self, target: &Pose<f64>) -> IkSolutions<N, 2> {
        let h = self.axis;
        let mut revolute = [0usize; 3];
        let mut count = 0;
        let mut prismatic = None;
        for (i, joint) in self.joints.iter().enumerate() {
            match joint {
                PlanarJoint::Revolute { .. } if count < 3 => {
                    revolute[count] = i;
                    count += 1;
                }
                PlanarJoint::Prismatic { sign } => prismatic = Some((i, *sign)),
                PlanarJoint::Revolute { .. } => {}
            }
        }
        let point = |i: usize| match self.joints[i] {
            PlanarJoint::Revolute { point, .. } => point,
            PlanarJoint::Prismatic { .. } => [0.0; 3],
        };
        let sign = |i: usize| match self.joints[i] {
            PlanarJoint::Revolute { sign, .. } | PlanarJoint::Prismatic { sign } => sign,
        };
        // A slide along h commutes with every turn about an axis parallel to it: take it out
        // first. Without one, the target's height must be the arm's.
        let rise = dot(h, sub(target.translation, self.tip_point));
        let mut exact = true;
        let mut slide = 0.0;
        match prismatic {
            Some((_, s)) => slide = s * rise,
            None => exact &= rise.abs() <= PLANAR_SLACK * (1.0 + libm::sqrt(norm_squared(target.translation))),
        }
        let p_target = sub(target.translation, scale(h, rise * f64::from(u8::from(prismatic.is_some()))));
        let (o1, o2) = (point(revolute[0]), point(revolute[1]));
        // With a third revolute joint, the turn about h is fixed by the rotation, and the point
        // on its axis is what the first two place.
        let (carried, goal, total) = if count == 3 {
            let r0 = &self.tool_rotation;
            // The column of R0 farthest from h turns by the total angle about h.
            let columns = [0, 1, 2].map(|j| [r0[0][j], r0[1][j], r0[2][j]]);
            let mut best = 0;
            for j in 1..3 {
                if norm_squared(cross(h, columns[j])) > norm_squared(cross(h, columns[best])) {
                    best = j;
                }
            }
            let reached = [0, 1, 2].map(|r| target.rotation[r][best]);
            let (total, _) = rotation_onto(h, columns[best], reached);
            // The target's rotation must be a turn about h of R0: it keeps R0^T h on h.
            let r0h = super::vector::mul_transposed(r0, h);
            let tilt = norm_squared(sub(mul(&target.rotation, r0h), h));
            exact &= tilt <= TILT_SLACK * TILT_SLACK;
            let o3 = point(revolute[2]);
            let goal = sub(p_target, total.rotate(h, sub(self.tip_point, o3)));
            (o3, goal, Some(total))
        } else {
            (self.tip_point, p_target, None)
        };
        // The two-link problem: rot(h1, q1) (o2 - o1 + rot(h2, q2) (c - o2)) = goal - o1.
        let (h1, h2) = (scale(h, sign(revolute[0])), scale(h, sign(revolute[1])));
        let arm = sub(o2, o1);
        let forearm = sub(carried, o2);
        let reach = sub(goal, o1);
        let (elbows, elbow) = rotation_to_distance(h2, forearm, scale(arm, -1.0), norm_squared(reach));
        let mut out = IkSolutions::new();
        for q2 in elbows {
            let (q1, shoulder) = rotation_onto(h1, add(arm, q2.rotate(h2, forearm)), reach);
            let quality = elbow.and(shoulder);
            let mut q = [0.0; N];
            q[revolute[0]] = q1.angle;
            q[revolute[1]] = q2.angle;
            if let Some(total) = total {
                // sign1 q1 + sign2 q2 + sign3 q3 = total.
                let third = revolute[2];
                q[third] =
                    wrap(sign(third) * (total.angle - sign(revolute[0]) * q1.angle - sign(revolute[1]) * q2.angle));
            }
            if let Some((i, _)) = prismatic {
                q[i] = slide;
            }
            #[allow(clippy::expect_used, reason = "invariant: a planar arm has two elbows")]
            out.push(IkSolution::unmeasured(q, quality.exact && exact, quality.singular))
                .expect("invariant: a planar arm's two elbows: two solutions, its list's capacity");
        }
        out
    }
}
