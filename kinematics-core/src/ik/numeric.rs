//! The numeric inverse kinematics every chain gets: Levenberg-Marquardt on the robot's generated
//! pose and Jacobian, joint limits respected (joints at a limit that would step past it held
//! still, steps clamped into them), restarts from deterministic seeds when a start does not
//! converge or stalls (has not halved its error in three steps), and no heap in the iteration.
//! Joints that do not move the tip (a tree's other branches) keep the seed's values throughout.
//!
//! The error is the twist that takes the reached pose to the target: the position difference and
//! the rotation vector of `R_target R^T`, both in the base frame, which is what the geometric
//! Jacobian in `LOCAL_WORLD_ALIGNED` maps joint rates to. Each step solves
//! `(J^T J + lambda (diag(J^T J) + mu I)) dq = J^T e` (Marquardt's scaling, with `mu` keeping
//! joints that do not move the tip still), scaled down so that no joint moves more than
//! [`MAX_JOINT_STEP`], taken only when it lowers the error; `lambda` falls after a good step and
//! rises after a rejected one.
//!
//! The constants were chosen on the Panda, the iiwa 14 and the UR5 (random reachable targets,
//! random seeds within the limits, the IK benchmark's protocol) by the pose and Jacobian
//! evaluations a solve takes, which is what its time follows: about 70 to 28 on the Panda, 36 to
//! 18 on the iiwa 14, 52 to 22 on the UR5, against the ten-step stall, a damping of `1e-3` rising
//! fourfold over ten tries, and unlimited steps. Most of the saving is in the starts that fail:
//! on the Panda about two in three starts from a random seed stall short of the target (in the
//! traces we read, against joint limits), and the sooner one is given up the cheaper; a step of at
//! most a radian keeps a start from crossing the workspace into a limit on its first, linearised,
//! step.

use super::ldl::ldl_solve;
use super::solutions::pose_errors_inline as pose_errors;
use super::vector::{V3, dot, sub};
use crate::kinematics::JointLimits;
use crate::pose::Pose;
use crate::real::{Real, square_root};
use crate::splitmix::SplitMix;

/// How hard the numeric solver tries, and when it is done.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NumericOptions {
    /// Converged when the position error is at most this (metres) and the rotation error at most
    /// this (radians).
    pub tolerance: f64,
    /// Steps (each one pose-and-Jacobian evaluation) per start.
    pub max_iterations: usize,
    /// Starts after the first (from deterministic pseudo-random configurations within the limits)
    /// when a start does not converge.
    pub restarts: usize,
}

impl Default for NumericOptions {
    /// `1e-10`, 100 steps per start, 20 restarts.
    fn default() -> Self {
        NumericOptions { tolerance: 1e-10, max_iterations: 100, restarts: 20 }
    }
}

/// What the numeric solver found: the best configuration of all starts and how it got there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NumericSolution<const N: usize> {
    /// The configuration (within the limits given).
    pub q: [f64; N],
    /// Both errors within [`NumericOptions::tolerance`].
    pub converged: bool,
    /// Distance to the target's translation (metres).
    pub position_error: f64,
    /// Angle to the target's rotation (radians).
    pub rotation_error: f64,
    /// Steps taken, over all starts.
    pub iterations: usize,
    /// Starts made, over all (1 when the seed converged).
    pub starts: usize,
}

/// The rotation vector (axis times angle) of the rotation `r`, accurate near 0 and near pi.
#[cfg_attr(not(debug_assertions), inline(always))]
fn rotation_vector(r: &[[f64; 3]; 3]) -> V3 {
    let vee = [r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1]];
    let sine2 = square_root(dot(vee, vee)); // 2 sin(angle)
    let cosine2 = r[0][0] + r[1][1] + r[2][2] - 1.0; // 2 cos(angle)
    let angle = crate::trig::atan2(sine2, cosine2);
    if cosine2 > -1.0 {
        // Away from a half turn: the skew part gives the axis.
        let scale = if sine2 > 1e-300 { angle / sine2 } else { 0.5 };
        return [vee[0] * scale, vee[1] * scale, vee[2] * scale];
    }
    // Near a half turn the skew part vanishes: the axis is the column of R + I of largest norm
    // (R + I = 2 u u^T at pi), its sign from the skew part.
    let mut best = 0;
    let mut best_norm = -1.0;
    for j in 0..3 {
        let column = [r[0][j], r[1][j], r[2][j]];
        let mut c = column;
        c[j] += 1.0;
        let n = dot(c, c);
        if n > best_norm {
            best = j;
            best_norm = n;
        }
    }
    let mut axis = [r[0][best], r[1][best], r[2][best]];
    axis[best] += 1.0;
    let n = square_root(best_norm);
    let mut axis = [axis[0] / n, axis[1] / n, axis[2] / n];
    if dot(axis, vee) < 0.0 {
        axis = [-axis[0], -axis[1], -axis[2]];
    }
    [axis[0] * angle, axis[1] * angle, axis[2] * angle]
}

/// The error twist from `reached` to `target`: position difference, then rotation vector of
/// `R_target R_reached^T`, both in the base frame.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn error_twist(reached: &Pose<f64>, target: &Pose<f64>) -> [f64; 6] {
    let p = sub(target.translation, reached.translation);
    let t = &target.rotation;
    let r = &reached.rotation;
    // R_target R_reached^T: rows of target against rows of reached.
    // Written out: `array::map` here was left a call (`try_map`), 6% of a solve.
    let row = |i: usize| [dot(t[i], r[0]), dot(t[i], r[1]), dot(t[i], r[2])];
    let m = [row(0), row(1), row(2)];
    let w = rotation_vector(&m);
    [p[0], p[1], p[2], w[0], w[1], w[2]]
}

/// Steps after which a start must have halved its cost to go on.
const STALL_STEPS: usize = 3;

/// The damping a start begins with.
const INITIAL_DAMPING: f64 = 1e-2;

/// Rejected tries (each raising the damping tenfold) after which a start has no step left.
const DAMPING_TRIES: usize = 4;

/// The largest change of one joint in one step (radians, or metres for a prismatic joint): a
/// longer step is scaled down whole, keeping its direction.
pub const MAX_JOINT_STEP: f64 = 1.0;

#[cfg_attr(not(debug_assertions), inline(always))]
fn clamp<const N: usize>(q: &mut [f64; N], limits: &[JointLimits; N]) {
    for (value, l) in q.iter_mut().zip(limits) {
        // Infinite limits clamp nothing; the model keeps lower <= upper.
        if *value < l.lower {
            *value = l.lower;
        }
        if *value > l.upper {
            *value = l.upper;
        }
    }
}

/// The damped step `(A + lambda (diag A + mu)) dq = g` with the joints that sit on a limit and
/// would step past it held still (their rows and columns dropped), so the others still take the
/// step the error asks of them rather than a clamped remnant; `None` if the system is singular.
#[allow(clippy::needless_range_loop, reason = "rows and columns of one matrix, by index")]
#[cfg_attr(not(debug_assertions), inline(always))]
fn bounded_step<const N: usize>(
    a: &[[f64; N]; N],
    g: &[f64; N],
    lambda: f64,
    q: &[f64; N],
    limits: &[JointLimits; N],
) -> Option<[f64; N]> {
    // A joint that does not move the tip at all (a finger beside the chain) stays still.
    let mut held: [bool; N] = core::array::from_fn(|i| a[i][i] == 0.0);
    // Each pass holds at least one more joint or ends: at most N + 1 passes.
    for _ in 0..=N {
        let mut m = *a;
        let mut dq = *g;
        for i in 0..N {
            m[i][i] += lambda * (a[i][i] + 1e-9);
            if held[i] {
                for j in 0..N {
                    m[i][j] = 0.0;
                    m[j][i] = 0.0;
                }
                m[i][i] = 1.0;
                dq[i] = 0.0;
            }
        }
        if ldl_solve(&mut m, &mut dq) != 1.0 {
            return None;
        }
        let mut more = false;
        for i in 0..N {
            let at_lower = q[i] <= limits[i].lower && dq[i] < 0.0;
            let at_upper = q[i] >= limits[i].upper && dq[i] > 0.0;
            if !held[i] && (at_lower || at_upper) {
                held[i] = true;
                more = true;
            }
        }
        if !more {
            return Some(dq);
        }
    }
    None
}

/// The deterministic generator of restart seeds.
struct Seeds(SplitMix);

impl Seeds {
    /// `seed` with the joints marked in `moving` drawn anew within the limits (within one turn
    /// either side of zero where a joint has none); the others keep the seed's values.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn within<const N: usize>(&mut self, limits: &[JointLimits; N], seed: &[f64; N], moving: &[bool; N]) -> [f64; N] {
        let mut q = *seed;
        for ((value, l), &moves) in q.iter_mut().zip(limits).zip(moving) {
            let (lo, hi) = if l.lower.is_finite() && l.upper.is_finite() {
                (l.lower, l.upper)
            } else {
                (-core::f64::consts::PI, core::f64::consts::PI)
            };
            let drawn = lo + (hi - lo) * self.0.next();
            if moves {
                *value = drawn;
            }
        }
        q
    }
}

/// Levenberg-Marquardt from `seed` toward `target`, with `pose_and_jacobian` the robot's
/// generated tip pose and geometric Jacobian (`LOCAL_WORLD_ALIGNED`, one column per entry of
/// `q`), the configuration kept within `limits`; restarts from deterministic seeds within the
/// limits when a start does not converge. Returns the best configuration found.
// Always inlined: the generated `tip_ik_numeric_with` calls it inside `dispatch`, and only code
// inlined there is compiled for the CPU's widest instruction set (called, it ran the baseline's:
// the pose and Jacobian's `sin_cos` two lanes wide instead of four or eight).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn levenberg_marquardt<const N: usize>(
    target: &Pose<f64>,
    seed: &[f64; N],
    limits: &[JointLimits; N],
    options: &NumericOptions,
    pose_and_jacobian: impl Fn(&[f64; N]) -> (Pose<f64>, [[f64; N]; 6]),
) -> NumericSolution<N> {
    let mut seeds = Seeds(SplitMix(0x6b69_6e65_6d61_7469));
    let mut iterations = 0;
    let mut starts = 0;
    // The joints that move the tip: a column of the Jacobian that is not zero (a revolute joint's
    // holds its axis, a prismatic one's its direction, wherever the arm is). The others (a tree's
    // other branches) never step, and restarts keep them at the seed's values too.
    let mut moving = [false; N];
    let first = {
        let mut q = *seed;
        clamp(&mut q, limits);
        q
    };
    let at_seed = pose_and_jacobian(&first);
    for (i, moves) in moving.iter_mut().enumerate() {
        *moves = at_seed.1.iter().any(|row| row[i] != 0.0);
    }
    // One start: steps from the seed (start 0) or from a configuration drawn within the limits.
    // Inlined like everything here: a closure is a function of its own, and one left a call is
    // compiled for the build's baseline (SSE2), not the dispatched instruction set. It was: the
    // whole iteration, the pose and Jacobian with it, ran as SSE2 code called from the AVX-512
    // or AVX2 body (on an Intel Xeon, SSE code after AVX-512 code pays for the upper halves of
    // the registers the latter left dirty).
    let mut attempt = inlined(
        #[cfg_attr(not(debug_assertions), inline(always))]
        |start: usize| {
            starts += 1;
            let mut q = if start == 0 { first } else { seeds.within(limits, &first, &moving) };
            clamp(&mut q, limits);
            let (mut pose, mut jacobian) = if start == 0 { at_seed } else { pose_and_jacobian(&q) };
            let mut error = error_twist(&pose, target);
            let mut cost = dot6(&error);
            let mut lambda = INITIAL_DAMPING;
            let mut steps = 0;
            // The cost three steps ago: a start that has not halved it since is stuck (a local minimum
            // or a limit), and a fresh start is cheaper than more steps (converging starts shrink the
            // cost quadratically).
            let mut checkpoint = cost;
            while steps < options.max_iterations {
                if steps > 0 && steps % STALL_STEPS == 0 {
                    if cost > 0.5 * checkpoint {
                        break;
                    }
                    checkpoint = cost;
                }
                // Converged needs both errors within the tolerance, so a cost (their squares' sum, the
                // same distance and angle to rounding) above twice its square cannot be; the margin
                // of 4 absorbs the rounding, and the errors (an arcsine) are computed only near the end.
                if cost <= 4.0 * options.tolerance * options.tolerance {
                    let (position, rotation) = pose_errors(&pose, target);
                    if position <= options.tolerance && rotation <= options.tolerance {
                        break;
                    }
                }
                steps += 1;
                let (a, g) = normal_equations(&jacobian, &error);
                let Some(next) = damped_step(&a, &g, &mut lambda, &q, cost, limits, target, &pose_and_jacobian) else {
                    break;
                };
                Step { q, pose, jacobian, error, cost } = next;
            }
            iterations += steps;
            let (position_error, rotation_error) = pose_errors(&pose, target);
            let converged = position_error <= options.tolerance && rotation_error <= options.tolerance;
            NumericSolution { q, converged, position_error, rotation_error, iterations, starts: start + 1 }
        },
    );
    // The first start always runs, so there is a best from the start (no placeholder for none);
    // a start that converges ends the search and is kept, whatever the sum of its errors.
    let mut best = attempt(0);
    for start in 1..=options.restarts {
        if best.converged {
            break;
        }
        let found = attempt(start);
        if found.converged || found.position_error + found.rotation_error < best.position_error + best.rotation_error {
            best = found;
        }
    }
    best.iterations = iterations;
    best.starts = starts;
    best
}

/// `closure` as it is: where a closure is an argument, it can be marked `#[inline(always)]`
/// (an attribute on a closure bound by `let` is not stable Rust).
#[cfg_attr(not(debug_assertions), inline(always))]
fn inlined<F: FnMut(usize) -> R, R>(closure: F) -> F {
    closure
}

/// An accepted step: the configuration, its pose and Jacobian, its error twist and cost.
struct Step<const N: usize> {
    q: [f64; N],
    pose: Pose<f64>,
    jacobian: [[f64; N]; 6],
    error: [f64; 6],
    cost: f64,
}

/// The normal equations of the least-squares step: `J^T J` and `J^T e`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn normal_equations<T: Real, const N: usize>(
    jacobian: &[[T; N]; 6],
    error: &[T; 6],
) -> ([[T; N]; N], [T; N]) {
    let zero = T::from_f64(0.0);
    let mut a = [[zero; N]; N];
    let mut g = [zero; N];
    for i in 0..N {
        for j in 0..=i {
            let mut s = zero;
            for row in jacobian {
                s = s + row[i] * row[j];
            }
            a[i][j] = s;
            a[j][i] = s;
        }
        for (row, &e) in jacobian.iter().zip(error) {
            g[i] = g[i] + row[i] * e;
        }
    }
    (a, g)
}

/// The damped step from `q` (at `cost`) that lowers the cost, with `lambda` lowered after it; a
/// rejected step raises `lambda` and tries again, and after [`DAMPING_TRIES`] there is none (`None`: the
/// start is done). `#[inline(always)]`, like the rest of the iteration, so that it runs inside the
/// caller's dispatched body.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::too_many_arguments)] // the iteration's state, passed as it is
fn damped_step<const N: usize>(
    a: &[[f64; N]; N],
    g: &[f64; N],
    lambda: &mut f64,
    q: &[f64; N],
    cost: f64,
    limits: &[JointLimits; N],
    target: &Pose<f64>,
    pose_and_jacobian: &impl Fn(&[f64; N]) -> (Pose<f64>, [[f64; N]; 6]),
) -> Option<Step<N>> {
    for _ in 0..DAMPING_TRIES {
        let Some(dq) = bounded_step(a, g, *lambda, q, limits) else {
            *lambda *= 10.0;
            continue;
        };
        // A NaN step (none comes from a solve that succeeded) would make a NaN cost below, which
        // is never lower: the try is rejected either way.
        let longest = dq.iter().fold(0.0, |m: f64, step| m.max(step.abs()));
        let scale = if longest > MAX_JOINT_STEP { MAX_JOINT_STEP / longest } else { 1.0 };
        let mut candidate = *q;
        for (value, step) in candidate.iter_mut().zip(&dq) {
            *value += step * scale;
        }
        clamp(&mut candidate, limits);
        let (new_pose, new_jacobian) = pose_and_jacobian(&candidate);
        let new_error = error_twist(&new_pose, target);
        let new_cost = dot6(&new_error);
        if new_cost < cost {
            *lambda = if *lambda > 1e-12 { *lambda / 3.0 } else { 1e-12 };
            return Some(Step {
                q: candidate,
                pose: new_pose,
                jacobian: new_jacobian,
                error: new_error,
                cost: new_cost,
            });
        }
        *lambda *= 10.0;
    }
    None
}

#[cfg_attr(not(debug_assertions), inline(always))]
fn dot6(e: &[f64; 6]) -> f64 {
    e.iter().map(|x| x * x).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rz(t: f64) -> [[f64; 3]; 3] {
        let (s, c) = libm::sincos(t);
        [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]
    }

    #[test]
    fn rotation_vectors_of_small_and_half_turns() {
        for angle in [0.0, 1e-12, 0.3, 3.0, core::f64::consts::PI - 1e-9, core::f64::consts::PI] {
            let w = rotation_vector(&rz(angle));
            assert!((w[2] - angle).abs() < 1e-9 && w[0].abs() < 1e-12 && w[1].abs() < 1e-12, "{angle}: {w:?}");
        }
        // A half turn about x: either sign of the axis is the same rotation.
        let w = rotation_vector(&[[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]);
        assert!((w[0].abs() - core::f64::consts::PI).abs() < 1e-15 && w[1] == 0.0 && w[2] == 0.0, "{w:?}");
    }

    /// A planar 2R arm with unit links, its pose and Jacobian by hand.
    fn planar(q: &[f64; 2]) -> (Pose<f64>, [[f64; 2]; 6]) {
        let (s1, c1) = libm::sincos(q[0]);
        let (s12, c12) = libm::sincos(q[0] + q[1]);
        let pose = Pose { rotation: rz(q[0] + q[1]), translation: [c1 + c12, s1 + s12, 0.0] };
        let j = [[-s1 - s12, -s12], [c1 + c12, c12], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [1.0, 1.0]];
        (pose, j)
    }

    #[test]
    fn a_planar_arm_converges_and_respects_limits() {
        let unlimited = [JointLimits { lower: f64::NEG_INFINITY, upper: f64::INFINITY }; 2];
        let target = planar(&[0.7, -1.1]).0;
        let found = levenberg_marquardt(&target, &[0.0, 0.5], &unlimited, &NumericOptions::default(), planar);
        assert!(found.converged, "{found:?}");
        assert!((found.q[0] - 0.7).abs() < 1e-9 && (found.q[1] + 1.1).abs() < 1e-9, "{found:?}");
        // With the elbow limited to positive angles the only exact answer is out of reach: the
        // best stays within the limits and says it did not converge.
        let limited = [unlimited[0], JointLimits { lower: 0.0, upper: 3.0 }];
        let found = levenberg_marquardt(&target, &[0.0, 0.5], &limited, &NumericOptions::default(), planar);
        assert!(!found.converged && found.q[1] >= 0.0 && found.q[1] <= 3.0, "{found:?}");
        assert!(found.position_error.is_finite() && found.starts == 21, "{found:?}");
    }
}
