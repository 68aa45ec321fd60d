//! What an inverse kinematics call returns: every branch's joint values with what is known of
//! them, in a fixed-capacity list (no heap), and the error for a target that is no pose.
//!
//! `IkSolutions` has a fixed capacity: `measure` with the robot's forward kinematics, `from_lanes`
//! from a compiled body's branches and their poses in lanes, `nearest`, `within_limits`;
//! `check_target` and `IkError` for the target.

use core::fmt;

use super::bounded::{BoundedList, Full};
use super::real::IkReal;
use super::vector::dot;
use crate::kinematics::JointLimits;
use crate::lanes::Lanes;
use crate::pose::Pose;

/// How far a target's rotation may be from orthonormal (the largest entry of `R R^T - I`)
/// before the solvers refuse it: loose enough for rotations rounded to a few more digits than
/// `f32` carries, tight enough that a matrix that is no rotation is never answered.
pub const ROTATION_TOLERANCE: f64 = 1e-6;

/// A target the solvers refuse: it is no pose.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum IkError {
    /// An entry of the rotation or the translation is NaN or infinite.
    NonFinite,
    /// A seed (`tip_ik_nearest`, `tip_ik_numeric`) has an entry that is NaN or infinite.
    NonFiniteSeed,
    /// The free joint's value (`tip_ik` of a seven-joint arm) is NaN or infinite.
    NonFiniteFree,
    /// The rotation is not orthonormal with determinant 1 (within [`ROTATION_TOLERANCE`]).
    NotARotation {
        /// The largest entry of `R R^T - I`, or how far the determinant is from 1 if larger.
        deviation: f64,
    },
}

impl fmt::Display for IkError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            IkError::NonFinite => f.write_str("the target pose has an entry that is not a finite number"),
            IkError::NonFiniteFree => f.write_str("the free joint's value is not a finite number"),
            IkError::NonFiniteSeed => f.write_str("the seed configuration has an entry that is not a finite number"),
            IkError::NotARotation { deviation } => write!(
                f,
                "the target's rotation is not a rotation: it is {deviation:e} from orthonormal with determinant 1 \
                 (tolerance {ROTATION_TOLERANCE:e})"
            ),
        }
    }
}

impl core::error::Error for IkError {}

/// The target as the solvers take it, or why not: every entry finite, the rotation orthonormal
/// with determinant 1 within [`ROTATION_TOLERANCE`].
pub fn check_target(target: &Pose<f64>) -> Result<(), IkError> {
    let r = &target.rotation;
    if !r.iter().flatten().chain(&target.translation).all(|x| x.is_finite()) {
        return Err(IkError::NonFinite);
    }
    // Finite entries can still overflow in a product (1e200 * 1e200 - 1e200 * 1e200 is NaN):
    // every comparison here counts NaN as the largest deviation, never as none.
    let mut deviation: f64 = 0.0;
    let mut worse = |d: f64| {
        if d.is_nan() {
            deviation = f64::INFINITY;
        } else if d > deviation {
            deviation = d;
        }
    };
    for i in 0..3 {
        for j in 0..3 {
            let expected = if i == j { 1.0 } else { 0.0 };
            worse((dot(r[i], r[j]) - expected).abs());
        }
    }
    worse((dot(r[0], super::vector::cross(r[1], r[2])) - 1.0).abs());
    if deviation > ROTATION_TOLERANCE {
        return Err(IkError::NotARotation { deviation });
    }
    Ok(())
}

/// The seed as the solvers take it (every entry finite), or the error.
pub fn check_seed(seed: &[f64]) -> Result<(), IkError> {
    if seed.iter().all(|x| x.is_finite()) { Ok(()) } else { Err(IkError::NonFiniteSeed) }
}

/// One solution: joint values in degree-of-freedom order and what is known of them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkSolution<const N: usize> {
    /// Joint values; revolute angles in `(-pi, pi]` unless moved into limits
    /// ([`IkSolutions::within_limits`]).
    pub q: [f64; N],
    /// Every equation of this branch had a real solution: the pose is reached (see the errors).
    /// `false`: the target is out of this branch's reach and `q` is the least-squares best.
    pub exact: bool,
    /// Some joint was free (a singularity, such as a wrist with its fifth joint at zero): `q` is
    /// one representative of a continuum of solutions.
    pub singular: bool,
    /// Distance from the target's translation to the pose `q` reaches (metres), measured with
    /// the robot's generated forward kinematics.
    pub position_error: f64,
    /// Angle between the target's rotation and the one `q` reaches (radians), measured the same
    /// way.
    pub rotation_error: f64,
}

impl<const N: usize> IkSolution<N> {
    /// A solution with its flags, errors not yet measured (infinite).
    pub fn unmeasured(q: [f64; N], exact: bool, singular: bool) -> Self {
        IkSolution { q, exact, singular, position_error: f64::INFINITY, rotation_error: f64::INFINITY }
    }
}

/// Every solution of an inverse kinematics call, up to `M` (the family's maximum), without heap.
///
/// Closed-form solvers return every branch, in a fixed order, exact or not; [`Self::exact`]
/// iterates the exact ones, [`Self::nearest`] picks the one closest to a configuration and
/// [`Self::within_limits`] keeps those inside joint limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkSolutions<const N: usize, const M: usize> {
    solutions: BoundedList<IkSolution<N>, M>,
}

impl<const N: usize, const M: usize> Default for IkSolutions<N, M> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize, const M: usize> IkSolutions<N, M> {
    /// No solutions.
    pub fn new() -> Self {
        IkSolutions { solutions: BoundedList::new(IkSolution::unmeasured([0.0; N], false, false)) }
    }

    /// Adds a solution, or returns [`Full`] (and adds nothing) when there are `M` already (the
    /// solvers never produce more than their family's maximum, which is the capacity they
    /// declare).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn push(&mut self, solution: IkSolution<N>) -> Result<(), Full> {
        self.solutions.push(solution)
    }

    /// The solutions, in the solver's branch order.
    pub fn as_slice(&self) -> &[IkSolution<N>] {
        self.solutions.as_slice()
    }

    /// The solutions, in branch order, to change in place (the refinement's).
    pub(super) fn solutions_mut(&mut self) -> &mut [IkSolution<N>] {
        self.solutions.as_mut_slice()
    }

    /// How many there are.
    pub fn len(&self) -> usize {
        self.solutions.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.solutions.is_empty()
    }

    /// The solutions in branch order.
    pub fn iter(&self) -> core::slice::Iter<'_, IkSolution<N>> {
        self.as_slice().iter()
    }

    /// The exact solutions (every equation solvable), in branch order.
    pub fn exact(&self) -> impl Iterator<Item = &IkSolution<N>> {
        self.iter().filter(|s| s.exact)
    }

    /// Measures every solution's pose errors against `target` with `forward` (the robot's
    /// generated forward kinematics). A pose with a non-finite entry counts as infinitely far.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn measure(&mut self, target: &Pose<f64>, forward: impl Fn(&[f64; N]) -> Pose<f64>) {
        for solution in self.solutions.as_mut_slice() {
            let reached = forward(&solution.q);
            let (position, rotation) = pose_errors(&reached, target);
            solution.position_error = position;
            solution.rotation_error = rotation;
        }
    }

    /// All `M` solutions, in order.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub(crate) fn from_array(solutions: [IkSolution<N>; M]) -> Self {
        IkSolutions { solutions: BoundedList::from_first(solutions, M) }
    }

    /// The branches a compiled closed form computed side by side, one per lane: lane `i`'s joint
    /// values and flags, and the pose `reached` there (the robot's forward kinematics of them, in
    /// the same lanes), its errors measured against `target`. The first `M` lanes are taken, in
    /// lane order.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn from_lanes<L: Lanes<Scalar = f64> + IkReal>(
        branches: &super::real::IkBranch<L, N>,
        reached: &Pose<L>,
        target: &Pose<f64>,
    ) -> Self {
        let count = M.min(L::LANES);
        let mut solutions = [IkSolution::unmeasured([0.0; N], false, false); M];
        // Column by column: each lane type's value is read once.
        for (j, column) in branches.q.iter().enumerate() {
            for (lane, solution) in solutions[..count].iter_mut().enumerate() {
                solution.q[j] = column.lane(lane);
            }
        }
        let errors = LaneErrors::of(reached, target);
        for (lane, solution) in solutions[..count].iter_mut().enumerate() {
            let (position_error, rotation_error) = errors.lane(lane);
            solution.exact = branches.exact.lane(lane) == 1.0;
            solution.singular = branches.singular.lane(lane) == 1.0;
            solution.position_error = position_error;
            solution.rotation_error = rotation_error;
        }
        IkSolutions { solutions: BoundedList::from_first(solutions, count) }
    }

    /// The solution nearest `seed` (Euclidean distance in joint space, each angle of a joint
    /// marked in `revolute` first moved by a multiple of 2 pi to the seed's side), preferring
    /// exact solutions to least-squares ones. `None` only when there are no solutions.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn nearest(&self, seed: &[f64; N], revolute: &[bool; N]) -> Option<IkSolution<N>> {
        // The distances first, without a branch on the angles (their turns are selects), then the
        // choice: a branch per solution, not per joint.
        let mut best: Option<(bool, f64, usize)> = None;
        for (k, solution) in self.iter().enumerate() {
            let mut distance = 0.0;
            for i in 0..N {
                let d = solution.q[i] - seed[i];
                let d = if revolute[i] { super::vector::nearest_turn(d) } else { d };
                distance += d * d;
            }
            let better = match best {
                None => true,
                Some((exact, d, _)) => (solution.exact && !exact) || (solution.exact == exact && distance < d),
            };
            if better {
                best = Some((solution.exact, distance, k));
            }
        }
        // Not `Option::map`: its closure was left a call from the dispatched `tip_ik_nearest`.
        let (_, _, k) = best?;
        let mut moved = self.as_slice()[k];
        for i in 0..N {
            if revolute[i] {
                moved.q[i] = seed[i] + super::vector::nearest_turn(moved.q[i] - seed[i]);
            }
        }
        Some(moved)
    }

    /// The solutions inside `limits` (closed intervals), each angle of a joint marked in
    /// `revolute` moved by a multiple of 2 pi into its interval where one fits; a solution with
    /// any joint that fits no way is left out.
    pub fn within_limits(&self, limits: &[JointLimits; N], revolute: &[bool; N]) -> Self {
        let mut kept = Self::new();
        'solutions: for solution in self.iter() {
            let mut moved = *solution;
            for i in 0..N {
                let JointLimits { lower, upper } = limits[i];
                let mut value = moved.q[i];
                if revolute[i] && lower.is_finite() && !(lower <= value && value <= upper) {
                    // The smallest value at or above `lower` that is `value` plus whole turns.
                    let tau = core::f64::consts::TAU;
                    value = lower + (value - lower).rem_euclid_tau(tau);
                }
                if !(lower <= value && value <= upper) {
                    continue 'solutions;
                }
                moved.q[i] = value;
            }
            // At most as many as there are, which fit.
            #[allow(clippy::expect_used, reason = "invariant: a subset of a list of capacity M fits in one")]
            kept.push(moved).expect("invariant: the solutions kept are at most the solutions, at most M");
        }
        kept
    }
}

/// The pose errors of every lane of a pose against one target, computed in lanes: the distance,
/// and the angle's sine and small-angle series, each lane past the series taking the scalar path
/// of [`errors_of_squares`] (which gives the same value for the others).
pub(super) struct LaneErrors<L> {
    position: L,
    frobenius2: L,
    sine: L,
    series: L,
}

impl<L: Lanes<Scalar = f64> + IkReal> LaneErrors<L> {
    /// The errors of `reached`'s lanes against `target`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub(super) fn of(reached: &Pose<L>, target: &Pose<f64>) -> Self {
        let (distance2, frobenius2) = squared_differences(reached, &super::real::splat_pose(target));
        let (position, sine) = (distance2.sqrt(), (frobenius2 * L::from_f64(0.125)).sqrt());
        let series = L::from_f64(2.0) * sine * (L::from_f64(1.0) + sine * sine / L::from_f64(6.0));
        LaneErrors { position, frobenius2, sine, series }
    }

    /// Lane `lane`'s position and rotation errors, as [`pose_errors`] gives them.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub(super) fn lane(&self, lane: usize) -> (f64, f64) {
        let (position, frobenius2, sine) = (self.position.lane(lane), self.frobenius2.lane(lane), self.sine.lane(lane));
        if sine < SERIES_BOUND && position.is_finite() && frobenius2.is_finite() {
            (position, self.series.lane(lane))
        } else {
            errors_of_squares(position, frobenius2, sine)
        }
    }
}

/// `rem_euclid` by 2 pi without `std` (libm's `fmod`, made non-negative).
trait RemEuclidTau {
    fn rem_euclid_tau(self, tau: f64) -> f64;
}

impl RemEuclidTau for f64 {
    fn rem_euclid_tau(self, tau: f64) -> f64 {
        let r = libm::fmod(self, tau);
        if r < 0.0 { r + tau } else { r }
    }
}

/// The distance between two poses' translations, and the angle between their rotations
/// (`2 asin(|Ra - Rb|_F / sqrt 8)`, accurate for small angles, where the trace formula loses half
/// the digits). Non-finite entries give infinity.
pub fn pose_errors(a: &Pose<f64>, b: &Pose<f64>) -> (f64, f64) {
    pose_errors_inline(a, b)
}

/// [`pose_errors`], always inlined (into the numeric solver's dispatched body).
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn pose_errors_inline(a: &Pose<f64>, b: &Pose<f64>) -> (f64, f64) {
    let (distance2, frobenius2) = squared_differences(a, b);
    errors_of_squares(IkReal::sqrt(distance2), frobenius2, IkReal::sqrt(frobenius2 / 8.0))
}

/// The squared distance between two poses' translations and the squared Frobenius norm of the
/// difference of their rotations, for any scalar (lanes: every lane's at once).
#[cfg_attr(not(debug_assertions), inline(always))]
fn squared_differences<T: IkReal>(a: &Pose<T>, b: &Pose<T>) -> (T, T) {
    let square = |x: T| x * x;
    let [ax, ay, az] = a.translation;
    let [bx, by, bz] = b.translation;
    let distance2 = square(ax - bx) + square(ay - by) + square(az - bz);
    let mut frobenius2 = square(a.rotation[0][0] - b.rotation[0][0]);
    for (i, j) in [(0, 1), (0, 2), (1, 0), (1, 1), (1, 2), (2, 0), (2, 1), (2, 2)] {
        frobenius2 = frobenius2 + square(a.rotation[i][j] - b.rotation[i][j]);
    }
    (distance2, frobenius2)
}

/// Below this sine of half the rotation error, its angle comes from the series (see
/// [`errors_of_squares`]).
const SERIES_BOUND: f64 = 1e-4;

/// [`pose_errors`] from the distance, the squared Frobenius norm and its sine `sqrt(f^2 / 8)`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn errors_of_squares(position: f64, frobenius2: f64, sine: f64) -> (f64, f64) {
    // For the small angles exact solutions have, the series 2 asin(s) = 2 s (1 + s^2 / 6 + ...)
    // is exact to rounding below s = 1e-4 (the next term is 3 s^4 / 40 < 1e-17 of it) and
    // costs no call.
    let rotation = if sine < SERIES_BOUND {
        2.0 * sine * (1.0 + sine * sine / 6.0)
    } else {
        2.0 * libm::asin(if sine < 1.0 { sine } else { 1.0 })
    };
    let finite = |x: f64| if x.is_finite() { x } else { f64::INFINITY };
    if !frobenius2.is_finite() {
        return (finite(position), f64::INFINITY);
    }
    (finite(position), rotation)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn identity_at(t: [f64; 3]) -> Pose<f64> {
        Pose { rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], translation: t }
    }

    #[test]
    fn targets_that_are_no_pose_are_refused() {
        assert_eq!(check_target(&identity_at([0.0, 1.0, 2.0])), Ok(()));
        assert_eq!(check_target(&identity_at([f64::NAN, 0.0, 0.0])), Err(IkError::NonFinite));
        assert_eq!(check_target(&identity_at([f64::INFINITY, 0.0, 0.0])), Err(IkError::NonFinite));
        let mut scaled = identity_at([0.0; 3]);
        scaled.rotation[0][0] = 1.1;
        assert!(matches!(check_target(&scaled), Err(IkError::NotARotation { .. })));
        // Rows whose products overflow (to infinity, and NaN where inf - inf) are no rotation: the
        // deviation is infinite, never a NaN a comparison would pass over.
        let mut huge = identity_at([0.0; 3]);
        huge.rotation = [[1e200, 1e200, 0.0], [1e200, -1e200, 0.0], [0.0, 0.0, 1.0]];
        assert!(matches!(check_target(&huge), Err(IkError::NotARotation { deviation }) if deviation == f64::INFINITY));
        let mut mirrored = identity_at([0.0; 3]);
        mirrored.rotation[2][2] = -1.0;
        assert!(matches!(check_target(&mirrored), Err(IkError::NotARotation { deviation }) if deviation == 2.0));
    }

    #[test]
    fn nearest_moves_angles_by_whole_turns_and_prefers_exact() {
        let mut all = IkSolutions::<2, 4>::new();
        assert_eq!(all.push(IkSolution::unmeasured([3.0, 0.5], true, false)), Ok(()));
        assert_eq!(all.push(IkSolution::unmeasured([0.1, 0.1], false, false)), Ok(()));
        assert_eq!(all.push(IkSolution::unmeasured([-3.0, 0.4], true, false)), Ok(()));
        let nearest = all.nearest(&[3.2, 0.4], &[true, false]).map(|s| s.q);
        // -3.0 is 3.2832 after a whole turn: 0.0832 from the seed, nearer than 3.0.
        assert!(matches!(nearest, Some([a, b]) if (a - (-3.0 + core::f64::consts::TAU)).abs() < 1e-15 && b == 0.4));
    }

    #[test]
    fn limits_move_angles_by_whole_turns_or_drop_the_solution() {
        let mut all = IkSolutions::<2, 4>::new();
        assert_eq!(all.push(IkSolution::unmeasured([-3.0, 0.1], true, false)), Ok(()));
        assert_eq!(all.push(IkSolution::unmeasured([1.0, 0.9], true, false)), Ok(()));
        let limits = [JointLimits { lower: 0.0, upper: 6.0 }, JointLimits { lower: 0.0, upper: 0.5 }];
        let kept = all.within_limits(&limits, &[true, false]);
        assert_eq!(kept.len(), 1);
        assert!((kept.as_slice()[0].q[0] - (-3.0 + core::f64::consts::TAU)).abs() < 1e-15);
    }

    #[test]
    fn pose_errors_of_a_small_rotation_are_its_angle() {
        let a = identity_at([0.0; 3]);
        let (s, c) = libm::sincos(1e-9);
        let b = Pose { rotation: [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]], translation: [3.0, 4.0, 0.0] };
        let (position, rotation) = pose_errors(&a, &b);
        assert_eq!(position, 5.0);
        assert!((rotation - 1e-9).abs() < 1e-22, "{rotation}");
        let nan = identity_at([f64::NAN; 3]);
        assert_eq!(pose_errors(&nan, &a).0, f64::INFINITY);
    }
}
