//! Newton refinement of closed-form solutions on the arm as written.
//!
//! A family's solver takes the arm's geometry with its relations made exact: axes within
//! `1e-12` of parallel written as parallel, points within `1e-12` x reach of a common point moved
//! onto it. A description whose angles are read as written (`exact_angles = false`: pi given to
//! 12 digits) is such an arm, and its solutions then miss their targets by about what was made
//! exact (a few `1e-13` x reach on an IRB 120 written with half turns of `3.14159265359`); a
//! family whose first step is a quartic loses digits near its singularity the same way. Each
//! exact solution measured farther than [`REFINE_ABOVE`] x reach from its target takes Gauss-Newton
//! steps on the robot's generated pose and Jacobian (the arm as written) until it is within that,
//! keeping each step only if it brings the solution closer; a solution already that close (every
//! solution of an arm whose relations hold exactly, to rounding) costs one comparison.
//!
//! The solutions are refined side by side, one per lane (`F64x8` in generated code: the eight
//! branches of a six-joint family at once), each step one pose and Jacobian of every lane, a
//! linear solve in lanes, and each lane's step kept or dropped on its own. A compiled family on an
//! arm the compiler made exact, whose every solution needs it, is refined in one pass
//! ([`IkSolutions::from_lanes_refined`]): the measure at the solver's cosines and sines carries the
//! Jacobian, and the pose after the step is measured at the cosines and sines turned by it, so no
//! step computes a sine; what is still far then takes the steps above.
//!
//! A correction longer than [`LONGEST_CORRECTION`] is not taken: that is no rounding to undo, and
//! a step that long could leave the branch the solver chose.

use super::ldl::ldl_solve;
use super::real::{IkBranch, IkReal, splat_pose};
use super::solutions::{IkSolution, IkSolutions, LaneErrors};
use crate::lanes::Lanes;
use crate::pose::Pose;

/// Solutions farther than this times the arm's reach from their target (by position, or by
/// rotation times the reach) are refined: ten times the rounding of a closed form on an arm whose
/// relations hold exactly (the UR5's and the IRB 120's solutions are within `2e-15` x reach).
pub const REFINE_ABOVE: f64 = 1e-14;

/// Steps at most per solution: each roughly squares the distance, and two take a few `1e-13`
/// to rounding.
const REFINE_STEPS: usize = 3;

/// The longest correction of one joint taken (radians, or metres for a prismatic joint).
pub const LONGEST_CORRECTION: f64 = 1e-4;

/// What the refinement needs of the arm beside its pose and Jacobian.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RefineArm<const N: usize> {
    /// The chain's reach (metres): the scale of the distances.
    pub reach: f64,
    /// The joints a step may move: the solved ones (not a seven-joint arm's free joint, whose
    /// value was given).
    pub moving: [bool; N],
    /// The revolute joints, whose angles are kept in `(-pi, pi]`.
    pub revolute: [bool; N],
}

impl<const N: usize, const M: usize> IkSolutions<N, M> {
    /// The solutions with every exact one farther than [`REFINE_ABOVE`] x reach from `target`
    /// refined by Gauss-Newton steps on `pose_and_jacobian` (the robot's generated tip pose and
    /// `LOCAL_WORLD_ALIGNED` Jacobian, evaluated on lanes of `L`: one solution per lane), each
    /// step kept only when it brings its solution closer; the errors are those of the pose at the
    /// refined `q`. Least-squares solutions (`exact` false) are left as solved, and so are all
    /// when none is that far (one comparison each).
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[must_use]
    pub fn refined<L: Lanes<Scalar = f64> + IkReal>(
        mut self,
        target: &Pose<f64>,
        arm: &RefineArm<N>,
        pose_and_jacobian: impl Fn(&[L; N]) -> (Pose<L>, [[L; N]; 6]),
    ) -> Self {
        let (mut pending, any) = self.pending(arm.reach);
        if !any {
            return self;
        }
        let mut start = 0;
        while start < self.len() {
            let end = (start + L::LANES).min(self.len());
            self.refine_lanes(start, end, &mut pending, target, arm, &pose_and_jacobian);
            start = end;
        }
        self
    }

    /// The branches a compiled closed form computed side by side, one per lane, as
    /// [`IkSolutions::from_lanes`] takes them, with every exact solution farther than
    /// [`REFINE_ABOVE`] x reach from `target` refined on the arm as written in one pass of the
    /// lanes: `reached` is the robot's generated pose and `LOCAL_WORLD_ALIGNED` Jacobian at the
    /// branches' own cosines and sines, one Gauss-Newton step is taken in every lane, its
    /// cosines and sines turned by the correction (no `sin_cos`: a correction is at most
    /// [`LONGEST_CORRECTION`]), and `pose_from_cos_sin` (the generated pose at them) measures it,
    /// each lane's step kept only if it brings its solution closer. A solution still farther (near
    /// a singularity) takes the steps of [`IkSolutions::refined`] on `pose_and_jacobian`.
    ///
    /// What a pass costs beside the measure: the Jacobian's entries, one linear solve in lanes,
    /// and the pose again; nothing when no solution is that far, but the Jacobian.
    #[allow(clippy::needless_range_loop, reason = "joints and lanes, by index")]
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[must_use]
    pub fn from_lanes_refined<L: Lanes<Scalar = f64> + IkReal>(
        branches: &IkBranch<L, N>,
        reached: &(Pose<L>, [[L; N]; 6]),
        target: &Pose<f64>,
        arm: &RefineArm<N>,
        pose_from_cos_sin: impl Fn(&[L; N], &[L; N], &[L; N]) -> Pose<L>,
        pose_and_jacobian: impl Fn(&[L; N]) -> (Pose<L>, [[L; N]; 6]),
    ) -> Self {
        let (pose, jacobian) = reached;
        let mut solutions = Self::from_lanes(branches, pose, target);
        let count = solutions.len();
        let (mut pending, any) = solutions.pending(arm.reach);
        if !any {
            return solutions;
        }
        let (dq, positive) = gauss_newton_step(pose, jacobian, &splat_pose::<L>(target), arm);
        let (mut q, mut cos, mut sin) = (branches.q, branches.cos, branches.sin);
        for i in 0..N {
            q[i] = q[i] + dq[i];
            if arm.revolute[i] {
                q[i] = within_half_turn(q[i]);
                (cos[i], sin[i]) = turned(cos[i], sin[i], dq[i]);
            }
        }
        let errors = LaneErrors::of(&pose_from_cos_sin(&q, &cos, &sin), target);
        let more = take_closer(
            &mut solutions.solutions_mut()[..count],
            &mut pending[..count],
            &q,
            &dq,
            positive,
            &errors,
            arm,
        );
        if more {
            solutions.refine_lanes(0, count, &mut pending, target, arm, &pose_and_jacobian);
        }
        solutions
    }

    /// Which solutions to refine (the exact ones farther than [`REFINE_ABOVE`] x `reach` from
    /// their targets by their errors), and whether any is.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn pending(&self, reach: f64) -> ([bool; M], bool) {
        let mut pending = [false; M];
        for (flag, solution) in pending.iter_mut().zip(self.as_slice()) {
            *flag = solution.exact && distance(reach, solution.position_error, solution.rotation_error) > REFINE_ABOVE;
        }
        (pending, pending.contains(&true))
    }

    /// Refines the pending solutions of `start..end` (at most `L::LANES`), lane `k` solution
    /// `start + k`.
    #[allow(clippy::needless_range_loop, reason = "joints and lanes, by index")]
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn refine_lanes<L: Lanes<Scalar = f64> + IkReal>(
        &mut self,
        start: usize,
        end: usize,
        pending: &mut [bool; M],
        target: &Pose<f64>,
        arm: &RefineArm<N>,
        pose_and_jacobian: &impl Fn(&[L; N]) -> (Pose<L>, [[L; N]; 6]),
    ) {
        if !pending[start..end].iter().any(|&p| p) {
            return;
        }
        let solutions = self.solutions_mut();
        // Lanes past the last solution repeat it (any finite configuration would do).
        let mut q = [L::from_f64(0.0); N];
        for j in 0..N {
            q[j] = L::from_fn(|k| solutions[(start + k).min(end - 1)].q[j]);
        }
        let target_lanes = splat_pose::<L>(target);
        let (mut pose, mut jacobian) = pose_and_jacobian(&q);
        for _ in 0..REFINE_STEPS {
            let (dq, positive) = gauss_newton_step(&pose, &jacobian, &target_lanes, arm);
            let mut next = q;
            for i in 0..N {
                next[i] = q[i] + dq[i];
                if arm.revolute[i] {
                    next[i] = within_half_turn(next[i]);
                }
            }
            let (next_pose, next_jacobian) = pose_and_jacobian(&next);
            let errors = LaneErrors::of(&next_pose, target);
            let more =
                take_closer(&mut solutions[start..end], &mut pending[start..end], &next, &dq, positive, &errors, arm);
            if !more {
                return;
            }
            (q, pose, jacobian) = (next, next_pose, next_jacobian);
        }
    }
}

/// Lane `k`'s step taken for solution `k` of `solutions` where it is pending, short (every
/// correction within [`LONGEST_CORRECTION`], from positive normal equations) and brings it
/// closer by its `errors`; each stays pending if taken and still farther than [`REFINE_ABOVE`].
/// Whether any does.
#[allow(clippy::needless_range_loop, reason = "joints and lanes, by index")]
#[cfg_attr(not(debug_assertions), inline(always))]
fn take_closer<L: Lanes<Scalar = f64> + IkReal, const N: usize>(
    solutions: &mut [IkSolution<N>],
    pending: &mut [bool],
    next: &[L; N],
    dq: &[L; N],
    positive: L,
    errors: &LaneErrors<L>,
    arm: &RefineArm<N>,
) -> bool {
    let mut more = false;
    for (k, (solution, pending)) in solutions.iter_mut().zip(pending.iter_mut()).enumerate() {
        if !*pending {
            continue;
        }
        let (position, rotation) = errors.lane(k);
        let closer = distance(arm.reach, position, rotation);
        let short = positive.lane(k) == 1.0 && (0..N).all(|i| dq[i].lane(k).abs() <= LONGEST_CORRECTION);
        // The current distance is a number (a NaN one is never pending); a NaN `closer` is no
        // closer.
        if short && closer < distance(arm.reach, solution.position_error, solution.rotation_error) {
            for i in 0..N {
                solution.q[i] = next[i].lane(k);
            }
            (solution.position_error, solution.rotation_error) = (position, rotation);
            *pending = closer > REFINE_ABOVE;
        } else {
            *pending = false;
        }
        more |= *pending;
    }
    more
}

/// One Gauss-Newton step of every lane from `pose` (with its `jacobian`) toward `target`: the
/// correction of each joint (zero for one that may not move), and `1` in the lanes whose normal
/// equations were positive definite (a step to take), else `0`.
#[allow(clippy::needless_range_loop, reason = "joints and lanes, by index")]
#[cfg_attr(not(debug_assertions), inline(always))]
fn gauss_newton_step<L: IkReal, const N: usize>(
    pose: &Pose<L>,
    jacobian: &[[L; N]; 6],
    target: &Pose<L>,
    arm: &RefineArm<N>,
) -> ([L; N], L) {
    let error = small_angle_twist(pose, target);
    // The normal equations `J^T J dq = J^T e`, built where they are solved (returned from a
    // function, the 36 entries in lanes were copied by `memcpy`); `ldl_solve` reads the lower
    // triangle only.
    let zero = L::from_f64(0.0);
    let (mut a, mut dq) = ([[zero; N]; N], [zero; N]);
    for i in 0..N {
        for j in 0..=i {
            let mut s = jacobian[0][i] * jacobian[0][j];
            for row in &jacobian[1..] {
                s = s + row[i] * row[j];
            }
            a[i][j] = s;
        }
        let mut s = jacobian[0][i] * error[0];
        for (row, &e) in jacobian[1..].iter().zip(&error[1..]) {
            s = s + row[i] * e;
        }
        dq[i] = s;
    }
    for i in 0..N {
        if arm.moving[i] {
            // A trace of damping, below the rounding of a well-conditioned system, so that a
            // Jacobian singular to rounding still has a solve (1e-12 held steps near a
            // singularity short of the target: of 400 quartic targets 1e-3 rad from the wrist's
            // singularity, 398 had a solution within 1e-13 and 397 their configuration so,
            // against 400 and 399 with this, 232 and 49 unrefined).
            a[i][i] = a[i][i] * L::from_f64(1.0 + 1e-15);
        } else {
            for j in 0..N {
                a[i][j] = zero;
                a[j][i] = zero;
            }
            a[i][i] = L::from_f64(1.0);
            dq[i] = zero;
        }
    }
    let positive = ldl_solve(&mut a, &mut dq);
    (dq, positive)
}

/// The larger of the position error and the rotation error times the reach, over the reach
/// (NaN if either is NaN, so that it never compares as far or as close).
#[cfg_attr(not(debug_assertions), inline(always))]
fn distance(reach: f64, position: f64, rotation: f64) -> f64 {
    let larger = if position > rotation * reach { position } else { rotation * reach };
    if position.is_nan() || rotation.is_nan() { f64::NAN } else { larger / reach }
}

/// The error twist from `reached` to `target` for a step: the position difference, and
/// `vee(R_target R_reached^T) / 2`, which is the rotation vector `angle axis` to within
/// `angle^2 / 6` of it (a refinement's angles are under `1e-4`; the numeric solver's exact
/// rotation vector needs an `atan2` and a branch at a half turn).
#[cfg_attr(not(debug_assertions), inline(always))]
fn small_angle_twist<L: IkReal>(reached: &Pose<L>, target: &Pose<L>) -> [L; 6] {
    let (t, r) = (&target.rotation, &reached.rotation);
    // Entry (i, j) of R_target R_reached^T: row i of the target against row j of the reached.
    let m = |i: usize, j: usize| t[i][0] * r[j][0] + t[i][1] * r[j][1] + t[i][2] * r[j][2];
    let half = L::from_f64(0.5);
    [
        target.translation[0] - reached.translation[0],
        target.translation[1] - reached.translation[1],
        target.translation[2] - reached.translation[2],
        (m(2, 1) - m(1, 2)) * half,
        (m(0, 2) - m(2, 0)) * half,
        (m(1, 0) - m(0, 1)) * half,
    ]
}

/// The cosine and sine of an angle whose cosine and sine are `(cos, sin)`, turned by `d`
/// radians, `|d|` at most [`LONGEST_CORRECTION`]: the angle-sum formulas with `cos d` and
/// `sin d` from their series to `d^2` and `d^3`, whose next terms (`d^4 / 24`, `d^5 / 120`) are
/// below the rounding of either at that length.
#[cfg_attr(not(debug_assertions), inline(always))]
fn turned<L: IkReal>(cos: L, sin: L, d: L) -> (L, L) {
    let d2 = d * d;
    let (cos_d, sin_d) = (L::from_f64(1.0) - d2 * L::from_f64(0.5), d - d * d2 * L::from_f64(1.0 / 6.0));
    (cos * cos_d - sin * sin_d, sin * cos_d + cos * sin_d)
}

/// `x` moved by a whole turn into `(-pi, pi]` if a correction took it just past either end,
/// lane by lane.
#[cfg_attr(not(debug_assertions), inline(always))]
fn within_half_turn<L: IkReal>(x: L) -> L {
    let (pi, tau) = (L::from_f64(core::f64::consts::PI), L::from_f64(core::f64::consts::TAU));
    let below = (x - pi).if_positive(x - tau, x);
    (below + pi).if_positive(below, below + tau)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ik::Arm6;
    use crate::ik::tests::arm_in_lanes;
    use crate::lanes::F64x8;

    /// An IRB 120-like spherical-wrist arm (axes 2 and 3 parallel), and the same arm with its
    /// axes tilted by `tilt` rad: the first is what the solver solves, the second the arm as
    /// written.
    fn arms(tilt: f64) -> (Arm6, Arm6) {
        let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
        let exact = Arm6 {
            axes: [z, y, y, x, y, x],
            offsets: [
                [0.0, 0.0, 0.29],
                [0.0; 3],
                [0.0, 0.0, 0.27],
                [0.302, 0.0, 0.07],
                [0.0; 3],
                [0.0; 3],
                [0.072, 0.0, 0.0],
            ],
            tool_rotation: [[0.0, 0.0, 1.0], y, [-1.0, 0.0, 0.0]],
        };
        let mut written = exact;
        let (c, s) = (libm::cos(tilt), libm::sin(tilt));
        written.axes[2] = [-s, c, 0.0];
        written.axes[4] = [0.0, c, s];
        written.axes[5] = [c, 0.0, -s];
        (exact, written)
    }

    /// Solutions of the exact arm, measured on the tilted one, miss by about the tilt; refined,
    /// every one is within `REFINE_ABOVE` x reach, each still its branch (within 1e-9 rad of where it
    /// was), and an arm with nothing to refine keeps its solutions bit for bit.
    #[test]
    fn refinement_brings_solutions_back_to_the_arm_as_written() {
        let (exact, written) = arms(1e-12);
        let refine = RefineArm { reach: 1.0, moving: [true; 6], revolute: [true; 6] };
        let mut refined = 0;
        for q in [[0.3, -0.4, 0.5, 0.6, -0.7, 0.8], [-1.2, 0.2, -0.3, 2.0, 1.1, -2.5], [2.5, 0.9, -1.0, -0.4, 0.5, 0.1]]
        {
            let target = written.pose(&q);
            let mut solutions = crate::ik::spherical_two_parallel(&exact, &target);
            solutions.measure(&target, |q| written.pose(q));
            let before = solutions;
            assert!(solutions.exact().any(|s| s.position_error > 1e-13 || s.rotation_error > 1e-13), "{solutions:?}");
            let solutions = solutions.refined::<F64x8>(&target, &refine, arm_in_lanes(&written));
            for (after, before) in solutions.iter().zip(before.iter()) {
                if !after.exact {
                    assert_eq!(after, before);
                    continue;
                }
                refined += 1;
                assert!(after.position_error <= REFINE_ABOVE && after.rotation_error <= REFINE_ABOVE, "{after:?}");
                assert!(after.q.iter().zip(&before.q).all(|(a, b)| (a - b).abs() < 1e-9), "{after:?} from {before:?}");
            }
            // The exact arm itself: nothing to refine, nothing changed.
            let target = exact.pose(&q);
            let mut solutions = crate::ik::spherical_two_parallel(&exact, &target);
            solutions.measure(&target, |q| exact.pose(q));
            let before = solutions;
            let solutions = solutions.refined::<F64x8>(&target, &refine, arm_in_lanes(&exact));
            assert_eq!(solutions, before);
        }
        assert!(refined >= 12, "{refined}");
    }

    /// A pose and Jacobian in lanes.
    type PoseAndJacobian = (Pose<F64x8>, [[F64x8; 6]; 6]);

    /// The solutions of `arm` for `target` as a compiled body returns them, one per lane, and
    /// `measured`'s pose and Jacobian there.
    fn in_lanes(arm: &Arm6, measured: &Arm6, target: &Pose<f64>) -> (IkBranch<F64x8, 6>, PoseAndJacobian) {
        let solutions = crate::ik::spherical_two_parallel(arm, target);
        assert_eq!(solutions.len(), 8);
        let s = solutions.as_slice();
        let q: [F64x8; 6] = core::array::from_fn(|j| F64x8::from_fn(|k| s[k].q[j]));
        let branches = IkBranch {
            q,
            cos: q.map(|x| F64x8::from_fn(|k| libm::cos(x.lane(k)))),
            sin: q.map(|x| F64x8::from_fn(|k| libm::sin(x.lane(k)))),
            exact: F64x8::from_fn(|k| if s[k].exact { 1.0 } else { 0.0 }),
            singular: F64x8::from_fn(|k| if s[k].singular { 1.0 } else { 0.0 }),
        };
        let reached = arm_in_lanes(measured)(&q);
        (branches, reached)
    }

    /// One pass in lanes does what the steps of `refined` do: on the tilted arm every exact
    /// solution ends within `REFINE_ABOVE` x reach (its errors those of the generated pose at
    /// its cosines and sines, here the arm's pose at `q`), within 1e-12 rad of the solution
    /// `refined` gives; the exact arm's solutions are those of `from_lanes`, bit for bit.
    #[test]
    fn one_pass_in_lanes_refines_as_the_steps_do() {
        let (exact, written) = arms(1e-12);
        let refine = RefineArm { reach: 1.0, moving: [true; 6], revolute: [true; 6] };
        let mut refined = 0;
        for q in [[0.3, -0.4, 0.5, 0.6, -0.7, 0.8], [-1.2, 0.2, -0.3, 2.0, 1.1, -2.5], [2.5, 0.9, -1.0, -0.4, 0.5, 0.1]]
        {
            for (arm, tilted) in [(&written, true), (&exact, false)] {
                let target = arm.pose(&q);
                let (branches, reached) = in_lanes(&exact, arm, &target);
                let pose_at = |q: &[F64x8; 6], _: &[F64x8; 6], _: &[F64x8; 6]| arm_in_lanes(arm)(q).0;
                let one_pass = IkSolutions::<6, 8>::from_lanes_refined(
                    &branches,
                    &reached,
                    &target,
                    &refine,
                    pose_at,
                    arm_in_lanes(arm),
                );
                let unrefined = IkSolutions::<6, 8>::from_lanes(&branches, &reached.0, &target);
                if !tilted {
                    assert_eq!(one_pass, unrefined);
                    continue;
                }
                let stepped = unrefined.refined::<F64x8>(&target, &refine, arm_in_lanes(arm));
                for ((pass, steps), before) in one_pass.iter().zip(stepped.iter()).zip(unrefined.iter()) {
                    if !before.exact {
                        assert_eq!(pass, before);
                        continue;
                    }
                    refined += 1;
                    assert!(before.position_error > REFINE_ABOVE || before.rotation_error > REFINE_ABOVE, "{before:?}");
                    assert!(pass.position_error <= REFINE_ABOVE && pass.rotation_error <= REFINE_ABOVE, "{pass:?}");
                    assert!(pass.q.iter().zip(&steps.q).all(|(a, b)| (a - b).abs() < 1e-12), "{pass:?} {steps:?}");
                }
            }
        }
        assert!(refined >= 12, "{refined}");
    }

    /// A joint that may not move (a seven-joint arm's free joint) keeps its value, and a
    /// correction longer than `LONGEST_CORRECTION` is refused.
    #[test]
    fn held_joints_and_long_corrections_stay() {
        let (exact, written) = arms(1e-12);
        let q = [0.3, -0.4, 0.5, 0.6, -0.7, 0.8];
        let target = written.pose(&q);
        let mut solutions = crate::ik::spherical_two_parallel(&exact, &target);
        solutions.measure(&target, |q| written.pose(q));
        let before = solutions;
        let held = RefineArm { reach: 1.0, moving: [true, true, false, true, true, true], revolute: [true; 6] };
        let solutions = solutions.refined::<F64x8>(&target, &held, arm_in_lanes(&written));
        assert!(solutions.iter().zip(before.iter()).all(|(a, b)| a.q[2] == b.q[2]));
        // Tilted by 1e-2 the solutions are no rounding away: left as solved.
        let (_, far) = arms(1e-2);
        let target = far.pose(&q);
        let mut solutions = crate::ik::spherical_two_parallel(&exact, &target);
        solutions.measure(&target, |q| far.pose(q));
        let before = solutions;
        let all = RefineArm { reach: 1.0, moving: [true; 6], revolute: [true; 6] };
        let solutions = solutions.refined::<F64x8>(&target, &all, arm_in_lanes(&far));
        assert_eq!(solutions, before);
    }

    #[test]
    fn angles_stay_within_a_half_turn() {
        let pi = core::f64::consts::PI;
        assert_eq!(within_half_turn(pi), pi);
        assert!((within_half_turn(pi + 1e-13) - (-pi + 1e-13)).abs() < 1e-15);
        assert!((within_half_turn(-pi) - pi).abs() < 1e-15);
        assert_eq!(within_half_turn(0.5), 0.5);
    }
}
