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
//! family gives its branches. The five families whose every step has two roots at most are
//! written once, one branch at a time, in [`mod@super::branch`] (which the compiler also emits as
//! straight-line code); their functions here run the eight branches side by side in lanes. The
//! general spherical wrist and the three-parallel arm find their first joints by the quartic of
//! subproblem 5 or 6 here, then end in that module's wrist or planar elbow, once per root and
//! sign. At the wrist's singularity each branch gets a representative, which for the arms with
//! axes 2, 3, 4 parallel moves the sum of those joints where `q6 = 0` would leave the elbow out of
//! reach. `FreeArm6` is the six of a seven-joint arm with the part after the free joint turned at
//! run time; `PlanarArm` is two or three revolute joints about parallel axes and at most one
//! prismatic joint along them, solved for what such an arm can reach.

use super::branch::{self, Numbers};
use super::solutions::{IkSolution, IkSolutions};
use super::subproblem::{self, rotation_onto, rotation_to_distance, three_rotations, two_heights};
use super::vector::{M3, V3, add, cross, dot, mul, mul_transposed, norm_squared, scale, sub, wrap};
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

/// Below this (the cosine between two unit axes) a wrist's axes are square for subproblem 4 on
/// the great circle: the rounding of axes written as exact quarter turns.
pub const ORTHOGONAL: f64 = 1e-15;

/// Spherical wrist with axes 1 and 2 meeting (`p12 = 0`) and joint 3 prismatic along `h3` (the
/// Stanford arm): [`branch::spherical_prismatic_third`]'s eight branches (two slides, two
/// shoulders, two wrists), side by side in lanes. `q3` is a length, not wrapped. Needs `h1` not
/// parallel to `h2`.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::redundant_closure, reason = "a function passed by name is called through a shim LLVM leaves uninlined")]
pub fn spherical_prismatic_third(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    branch::solve_in_lanes(
        arm,
        target,
        #[cfg_attr(not(debug_assertions), inline(always))]
        |b, p| branch::spherical_prismatic_third(b, p),
    )
}

/// Spherical wrist (axes 4, 5, 6 meet, `p45 = p56 = 0`) with axes 2 and 3 parallel (PUMA 560,
/// IRB 120): [`branch::spherical_two_parallel`]'s eight branches (`q1` by subproblem 4, `q3` by
/// subproblem 3, `q2` by subproblem 1, then the wrist), side by side in lanes. Needs `h1` not
/// parallel to `h2`.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::redundant_closure, reason = "a function passed by name is called through a shim LLVM leaves uninlined")]
pub fn spherical_two_parallel(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    branch::solve_in_lanes(
        arm,
        target,
        #[cfg_attr(not(debug_assertions), inline(always))]
        |b, p| branch::spherical_two_parallel(b, p),
    )
}

/// Spherical wrist with axes 1 and 2 meeting (`p12 = 0`): [`branch::spherical_first_two_intersecting`]'s
/// eight branches (`q3` by subproblem 3, `q1`, `q2` by subproblem 2, then the wrist), side by side
/// in lanes. Needs `h1` not parallel to `h2`.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::redundant_closure, reason = "a function passed by name is called through a shim LLVM leaves uninlined")]
pub fn spherical_first_two_intersecting(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    branch::solve_in_lanes(
        arm,
        target,
        #[cfg_attr(not(debug_assertions), inline(always))]
        |b, p| branch::spherical_first_two_intersecting(b, p),
    )
}

/// Spherical wrist with axes 2 and 3 meeting (`p23 = 0`): [`branch::spherical_last_two_intersecting`]'s
/// eight branches (`q1` by subproblem 3, `q2`, `q3` by subproblem 2, then the wrist), side by side
/// in lanes. Needs `h2` not parallel to `h3`.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::redundant_closure, reason = "a function passed by name is called through a shim LLVM leaves uninlined")]
pub fn spherical_last_two_intersecting(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    branch::solve_in_lanes(
        arm,
        target,
        #[cfg_attr(not(debug_assertions), inline(always))]
        |b, p| branch::spherical_last_two_intersecting(b, p),
    )
}

/// Axes 2, 3, 4 parallel and axes 5, 6 meeting (`p56 = 0`), the UR family:
/// [`branch::three_parallel_two_intersecting`]'s eight branches (`q1` and `q5` by subproblem 4,
/// then the planar elbow), side by side in lanes, with the pass at the wrist's singularity. Needs
/// `h1` and `h5` not parallel to `h2`.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::redundant_closure, reason = "a function passed by name is called through a shim LLVM leaves uninlined")]
pub fn three_parallel_two_intersecting(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    // As the compiled `tip_ik`: without the pass at the wrist's singularity first (it costs
    // about a third of the branch), and again with it only where some lane is singular and missed.
    let mut singular_pass = false;
    loop {
        let branches = branch::branches_in_lanes(
            arm,
            target,
            singular_pass,
            #[cfg_attr(not(debug_assertions), inline(always))]
            |b, p| branch::three_parallel_two_intersecting(b, p),
        );
        if singular_pass || !branch::needs_singular_pass(&branches) {
            return branch::unmeasured(&branches);
        }
        singular_pass = true;
    }
}

/// The problem of a family whose first step is a quartic, on numbers: its branch signs are
/// given where each root's branches are taken.
#[cfg_attr(not(debug_assertions), inline(always))]
fn numbers_problem<'a>(arm: &'a Arm6, target: &Pose<f64>) -> branch::Problem<'a, f64> {
    branch::Problem {
        arm,
        rotation: target.rotation,
        translation: target.translation,
        signs: [1.0; 3],
        singular_pass: true,
    }
}

/// A branch computed on numbers as a solution.
#[cfg_attr(not(debug_assertions), inline(always))]
fn solution(branch: branch::Branch<f64>) -> IkSolution<6> {
    IkSolution::unmeasured(branch.q, branch.quality.exact == 1.0, branch.quality.singular == 1.0)
}

/// Axes 2, 3, 4 parallel (direction `h = h2`), no other two meeting: `q1` and `q5` together by
/// subproblem 6 (the tool flange's height along `h`, and the angle between `h` and `h6`, are
/// both fixed, and each depends on `q1` and `q5` alone; at most four pairs), then the planar
/// elbow of [`mod@branch`] for each pair, two branches each. Needs `h1` and `h5` not parallel
/// to `h`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn three_parallel(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h, _, _, h5, h6] = arm.axes;
    let [_, p12, p23, p34, p45, p56, _] = arm.offsets;
    let numbers = &mut Numbers::<f64>::new();
    let (values, r06, v0) = branch::wrist_target(numbers, &numbers_problem(arm, target));
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
        // The pass at the wrist's singularity (a third of the branch) only where it can apply:
        // axis 6 near the parallel axes, tested here with twice the branch's limits, so that a
        // branch the pass would change always takes it.
        let seen = q5.back().rotate(h5, h);
        let w = mul_transposed(&r06, t1.back().rotate(h1, h));
        let singular_pass =
            near_axis(h6, seen, 2.0 * NEAR_SINGULAR_SIXTH) || near_axis(h6, w, 2.0 * subproblem::DEGENERATE);
        for sign in [1.0, -1.0] {
            // Near the wrist singularity the quartic's two roots there (the wrist flips) are found
            // to about 1e-7 rad, or as one at their tangency: short of the sixth subproblem's own
            // test, so near it an elbow out of reach counts as singular.
            let elbow = branch::Elbow {
                t1: t1.into(),
                q5: q5.into(),
                quality: pairs.quality.into(),
                sign,
                singular_pass,
                near_singular: NEAR_SINGULAR_SIXTH,
            };
            #[allow(clippy::expect_used, reason = "invariant: two elbows per (q1, q5) pair, four pairs at most")]
            out.push(solution(branch::parallel_elbow(numbers, &values, &r06, v0, elbow)))
                .expect("invariant: two elbows for each of at most four (q1, q5) branches: at most 8 solutions");
        }
    }
    out
}

/// Whether `v` lies within the angle whose sine is `limit` of the unit axis `k` (either way).
#[cfg_attr(not(debug_assertions), inline(always))]
fn near_axis(k: V3, v: V3, limit: f64) -> bool {
    norm_squared(cross(k, v)) <= limit * limit * norm_squared(v)
}

/// How near the wrist's singularity (the sine of the angle between axis 6 and the parallel axes,
/// as joint 5 turns them) the three-parallel arm's branches count as at it when the sum that the
/// sixth joint's angle gives leaves the elbow out of reach: near it its quartic's two roots (the
/// wrist flips) are found to about 1e-7 rad, short of the subproblem's `DEGENERATE`, and the sixth
/// angle of such a root is noise. The branch is then flagged singular, and its errors (up to about
/// this times the sixth angle's move, in rad) are measured like any other's.
pub const NEAR_SINGULAR_SIXTH: f64 = 1e-6;

/// Spherical wrist (axes 4, 5, 6 meet, `p45 = p56 = 0`) with no two of axes 1, 2, 3 parallel or
/// meeting: `q1`, `q2`, `q3` by subproblem 5 (`R1^T W - p12 = R2 (p23 + R3 p34)` for the wrist
/// centre `W`; at most four triples), then the wrist of [`mod@branch`] for each, two branches each.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn spherical(arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let [h1, h2, h3, ..] = arm.axes;
    let [_, p12, p23, p34, ..] = arm.offsets;
    let numbers = &mut Numbers::<f64>::new();
    let (values, r06, v0) = branch::wrist_target(numbers, &numbers_problem(arm, target));
    let mut out = IkSolutions::new();
    let triples = three_rotations(scale(p12, -1.0), h1, v0, h2, p23, h3, p34);
    for &[t1, q2, q3] in triples.as_slice() {
        for sign in [1.0, -1.0] {
            let turns = [t1.back().into(), q2.into(), q3.into()];
            let branch = branch::spherical_branch(numbers, &values, &r06, turns, None, triples.quality.into(), sign);
            #[allow(
                clippy::expect_used,
                reason = "invariant: two wrist flips per arm branch, four arm branches at most"
            )]
            out.push(solution(branch))
                .expect("invariant: two wrist flips for each of at most four arm branches: at most 8 solutions");
        }
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
    #[cfg_attr(not(debug_assertions), inline(always))]
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
#[cfg_attr(not(debug_assertions), inline(always))]
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
    #[cfg_attr(not(debug_assertions), inline(always))]
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
            None => {
                exact &= rise.abs() <= PLANAR_SLACK * (1.0 + crate::real::square_root(norm_squared(target.translation)))
            }
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
