//! Straight motions in joint space, checked at a resolution: the configurations along the segment
//! from `q0` to `q1`, so close that no joint moves more than the resolution between two checked
//! ones, checked in lanes, several points of the segment at once, for the first that collides.
//!
//! The lanes take the segment in runs (lane `i` the `i`-th run of consecutive configurations, all
//! lanes one step along their run at a time), so a collision anywhere is met within a few
//! checks, VAMP's way; once one is met, only the configurations before it are still checked, and
//! the answer is the first colliding one, as checking them one by one in order would give.
//!
//! `Motion` is a straight motion's checked configurations at a resolution; `motion_wide` is the
//! search for its first colliding one in the lanes the CPU fills; `motions_wide` and
//! `first_collisions` check several motions, one per lane.

use crate::error::KinematicsError;
use crate::lanes::Lanes;
use crate::real::Real;
use core::marker::PhantomData;

use super::verdicts::LaneMask;
use crate::batch::{OnLanes, on_widest};

/// A straight motion from `q0` to `q1` checked at a resolution: configurations `k = 0..=steps`
/// at fractions `k / steps`, `steps` the fewest that keep every joint's move between two checked
/// configurations within the resolution (at least one: both ends are checked).
///
/// ```
/// use kinematics_core::collision::Motion;
/// let motion = Motion::new("demo", [0.0_f64, 1.0], [0.25, 0.0], 0.1)?;
/// assert_eq!(motion.steps(), 10); // the second joint moves 1.0
/// assert_eq!(motion.configuration(0), [0.0, 1.0]);
/// assert_eq!(motion.configuration(10), [0.25, 0.0]);
/// assert_eq!(motion.fraction(4), 0.4);
/// assert!(Motion::new("demo", [0.0_f64], [1.0], 0.0).is_err());
/// # Ok::<(), kinematics_core::KinematicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion<S, const N: usize> {
    q0: [S; N],
    q1: [S; N],
    steps: usize,
}

impl<S: Real + Into<f64>, const N: usize> Motion<S, N> {
    /// The motion from `q0` to `q1` at `resolution` (a [`Resolution`]; an `f64` is a
    /// [`Resolution::JointStep`]), its value positive and finite, else an error naming the robot.
    /// A NaN or infinite entry in `q0` or `q1` gives one step (both ends checked, and a
    /// configuration that is not finite is colliding).
    pub fn new(
        robot: &'static str,
        q0: [S; N],
        q1: [S; N],
        resolution: impl Into<Resolution>,
    ) -> Result<Self, KinematicsError> {
        let resolution = resolution.into();
        check_resolution(robot, resolution)?;
        Ok(Self::at(q0, q1, resolution))
    }

    /// [`Motion::new`] for a resolution already checked.
    fn at(q0: [S; N], q1: [S; N], resolution: Resolution) -> Self {
        let mut largest = 0.0_f64;
        let mut squares = 0.0_f64;
        for j in 0..N {
            let step = (q1[j].into() - q0[j].into()).abs();
            squares += step * step;
            // A NaN step makes `largest` NaN rather than being skipped (as `f64::max` would).
            if step.is_nan() || step > largest {
                largest = step;
            }
        }
        let steps = match resolution {
            Resolution::JointStep(step) => libm::ceil(largest / step),
            Resolution::StatesPerUnit(states) => libm::ceil(libm::sqrt(squares) * states),
        };
        // `as` saturates: a span beyond `usize::MAX` resolutions asks for what it asks for.
        let steps = if steps.is_finite() { (steps as usize).max(1) } else { 1 };
        Motion { q0, q1, steps }
    }

    /// How many steps the motion is checked in (`steps + 1` configurations).
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// The fraction of the motion configuration `k` sits at: `k / steps`.
    pub fn fraction(&self, k: usize) -> f64 {
        k as f64 / self.steps as f64
    }

    /// Configuration `k` (`0..=steps`): `(1 - t) q0 + t q1` at `t = k / steps`, exactly `q0` and
    /// `q1` at the ends.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn configuration(&self, k: usize) -> [S; N] {
        let mut q = self.q0;
        for (j, x) in q.iter_mut().enumerate() {
            *x = self.joint(k, j);
        }
        q
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn joint(&self, k: usize, j: usize) -> S {
        // The ends as given: `0 * q1` is NaN where `q1` is infinite.
        if k == 0 {
            return self.q0[j];
        }
        if k >= self.steps {
            return self.q1[j];
        }
        let t = S::from_f64(self.fraction(k));
        (S::from_f64(1.0) - t) * self.q0[j] + t * self.q1[j]
    }

    /// The first colliding configuration's index (`None`: every one is free), `check` answering
    /// for `L::LANES` configurations at a time.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn first_collision<L: Lanes<Scalar = S>>(&self, check: impl Fn(&[L; N]) -> LaneMask) -> Option<usize> {
        // Saturating: a motion of `usize::MAX` steps (a resolution far below its span) loses its
        // last configuration to the count rather than overflow.
        let count = self.steps.saturating_add(1);
        // Lane `i` takes configurations `i * run..(i + 1) * run`, one per round.
        let run = count.div_ceil(L::LANES);
        let mut first = count;
        for step in 0..run {
            let index = |i: usize| i * run + step;
            // Lanes past the end, or past a collision already found, are not asked.
            let mut asked = 0u32;
            for i in 0..L::LANES {
                if index(i) < first {
                    asked |= 1 << i;
                }
            }
            if asked == 0 {
                break;
            }
            let mut q = [L::from_fn(|_| self.q0[0]); N];
            for (j, lanes) in q.iter_mut().enumerate() {
                *lanes = L::from_fn(|i| self.joint(index(i).min(first - 1), j));
            }
            let hits = check(&q).bits() & asked;
            if hits != 0 {
                // Within a round the index grows with the lane: the lowest hit is the first.
                first = index(hits.trailing_zeros() as usize);
            }
        }
        (first < count).then_some(first)
    }
}

impl<S: Real + Into<f64>, const N: usize> Motion<S, N> {
    /// Whether some checked configuration collides, `check` answering whether any of
    /// `L::LANES` configurations does (ending at its first hit on any lane), and the first pack
    /// with a hit ending the search.
    ///
    /// The lanes are spread along the motion (lane `i` in the `i`-th stretch of consecutive
    /// configurations, `run` of them), and the rounds take the stretches' offsets coarse to fine
    /// (0, then `run / 2`, then `run / 4` and `3 run / 4`, ..., the bit-reversed order), so the
    /// first rounds sample the whole motion evenly and a colliding stretch of it is met early,
    /// wherever it lies. Every configuration is checked once when the motion is free.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn any_collision<L: Lanes<Scalar = S>>(&self, check: impl Fn(&[L; N]) -> bool) -> bool {
        let count = self.steps.saturating_add(1);
        let run = count.div_ceil(L::LANES);
        // The offsets: 0..2^bits in bit-reversed order, those at or past `run` skipped.
        let bits = usize::BITS - (run - 1).leading_zeros();
        for round in 0..(1usize << bits) {
            let offset = if bits == 0 { 0 } else { round.reverse_bits() >> (usize::BITS - bits) };
            if offset >= run {
                continue;
            }
            // A lane past the end repeats the last configuration (checked, and the same answer).
            let mut q = [L::from_fn(|_| self.q0[0]); N];
            for (j, lanes) in q.iter_mut().enumerate() {
                *lanes = L::from_fn(|i| self.joint((i * run + offset).min(count - 1), j));
            }
            if check(&q) {
                return true;
            }
        }
        false
    }
}

/// A resolution whose value is positive and finite, else an error naming the robot.
fn check_resolution(robot: &'static str, resolution: Resolution) -> Result<(), KinematicsError> {
    let value = resolution.value();
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(KinematicsError::BadResolution { robot, resolution: value })
    }
}

/// A batch of motions' `resolution`, checked (positive and finite), and its output's length,
/// `outputs`, checked against the `motions` (one each): else the error naming `robot`.
fn batch_checked(
    robot: &'static str,
    resolution: Resolution,
    motions: usize,
    outputs: usize,
) -> Result<Resolution, KinematicsError> {
    check_resolution(robot, resolution)?;
    if outputs != motions {
        return Err(KinematicsError::WrongOutputLength { robot, expected: motions, got: outputs });
    }
    Ok(resolution)
}

/// How finely a straight motion is checked: how many configurations along it, both ends
/// included, are checked (the motion's `steps + 1`).
///
/// ```
/// use kinematics_core::collision::{Motion, Resolution};
/// let (q0, q1) = ([0.0_f64, 0.0], [0.3, 0.4]); // 0.5 apart, 0.4 the largest joint move
/// assert_eq!(Motion::new("demo", q0, q1, Resolution::JointStep(0.1))?.steps(), 4);
/// assert_eq!(Motion::new("demo", q0, q1, 0.1)?.steps(), 4); // an f64 is a joint step
/// assert_eq!(Motion::new("demo", q0, q1, Resolution::StatesPerUnit(32.0))?.steps(), 16);
/// # Ok::<(), kinematics_core::KinematicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Resolution {
    /// The largest move of any one joint between two checked configurations (radians, or metres
    /// for a prismatic joint): `steps = ceil(max_j |q1_j - q0_j| / step)`. It bounds every
    /// joint's move, whatever the others do.
    JointStep(f64),
    /// Checked configurations per unit of joint-space distance, the unit VAMP's planners and
    /// OMPL's motion validators count in (VAMP's default is 32 per radian):
    /// `steps = ceil(|q1 - q0| * states)`, `|.|` the Euclidean norm over the joints. A motion
    /// of many joints moving together takes fewer checks than at the same joint step.
    StatesPerUnit(f64),
}

impl Resolution {
    /// The number given (a step or a count per unit).
    pub fn value(self) -> f64 {
        match self {
            Resolution::JointStep(x) | Resolution::StatesPerUnit(x) => x,
        }
    }
}

impl From<f64> for Resolution {
    /// A joint step.
    fn from(step: f64) -> Self {
        Resolution::JointStep(step)
    }
}

/// A motion's two ends, `(q0, q1)`.
pub type Ends<S, const N: usize> = ([S; N], [S; N]);

/// A lane's motion in a search of several: its index in the batch, the motion, the configuration
/// the lane is at.
type LaneMotion<S, const N: usize> = (usize, Motion<S, N>, usize);

/// The most lanes a search of several motions keeps: the widest lane type's.
const MOST_LANES: usize = 32;

/// Several straight motions searched together, one per lane: each lane checks its motion's
/// configurations in order and, when it meets a collision or the motion's end, takes the next
/// motion of the batch, so every lane stays busy until the batch runs out.
///
/// `out[m]` is motion `m`'s first colliding configuration's fraction, as
/// [`Motion::first_collision`] finds it (`None`: free); every entry is written, `out` being at
/// least as long as `motions`, and `resolution` positive and finite ([`motions_wide`] checks
/// both). (Each motion alone would
/// spread the lanes along itself; several at once, a lane per motion wastes no lane on the
/// configurations past a collision, and a free motion costs its configurations' checks alone.)
///
/// ```
/// use kinematics_core::collision::{first_collisions, LaneMask, Motion};
/// use kinematics_core::{F64x4, Lanes};
/// fn beyond<L: Lanes<Scalar = f64>>(q: &[L; 1]) -> LaneMask {
///     let mut bits = 0;
///     for i in 0..L::LANES {
///         bits |= u32::from(q[0].lane(i) > 0.62) << i;
///     }
///     LaneMask::from_bits(bits)
/// }
/// let motions = [([0.0], [1.0]), ([0.0], [0.5]), ([2.0], [0.0])];
/// let mut out = [None; 3];
/// first_collisions::<F64x4, 1>(&motions, 0.05, beyond, &mut out);
/// assert_eq!(out, [Some(0.65), None, Some(0.0)]);
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn first_collisions<L: Lanes, const N: usize>(
    motions: &[Ends<L::Scalar, N>],
    resolution: impl Into<Resolution>,
    check: impl Fn(&[L; N]) -> LaneMask,
    out: &mut [Option<f64>],
) where
    L::Scalar: Real + Into<f64>,
{
    let resolution = resolution.into();
    // Each lane's motion: its index in the batch, the motion, the configuration it is at.
    let mut lanes: [Option<LaneMotion<L::Scalar, N>>; MOST_LANES] = [None; MOST_LANES];
    let mut next = 0;
    let take = |slot: &mut Option<LaneMotion<L::Scalar, N>>, next: &mut usize| {
        *slot = motions.get(*next).map(|(q0, q1)| (*next, Motion::at(*q0, *q1, resolution), 0));
        *next += 1;
    };
    for slot in lanes.iter_mut().take(L::LANES) {
        take(slot, &mut next);
    }
    loop {
        let mut active = 0u32;
        for (i, slot) in lanes.iter().enumerate().take(L::LANES) {
            active |= u32::from(slot.is_some()) << i;
        }
        if active == 0 {
            break;
        }
        // An idle lane repeats the first busy one's configuration, its verdict unread.
        let busy = active.trailing_zeros() as usize;
        let mut q = [L::from_fn(|_| motions[0].0[0]); N];
        for (j, lane) in q.iter_mut().enumerate() {
            *lane = L::from_fn(|i| {
                #[allow(clippy::expect_used, reason = "invariant: lane `busy` holds a motion")]
                let (_, motion, k) = lanes[i].or(lanes[busy]).expect("lane `busy` holds a motion");
                motion.joint(k, j)
            });
        }
        let hits = check(&q).bits();
        for (i, slot) in lanes.iter_mut().enumerate().take(L::LANES) {
            let Some((m, motion, k)) = slot else { continue };
            if (hits >> i) & 1 == 1 {
                out[*m] = Some(motion.fraction(*k));
            } else if *k < motion.steps {
                *k += 1;
                continue;
            } else {
                out[*m] = None;
            }
            take(slot, &mut next);
        }
    }
}

/// [`Motion::first_collision`] in the lanes that fill the CPU's registers, as the batches choose
/// them ([`crate::batch_wide`]): `wide` (`W`) where the CPU has AVX-512, `narrow` (`L`)
/// elsewhere, each compiled for the instruction set it runs on. The first colliding
/// configuration's fraction of the motion, or `None` when every one is free.
///
/// ```
/// use kinematics_core::collision::{motion_wide, LaneMask, Motion};
/// use kinematics_core::{F64x4, F64x8, Lanes};
/// // A "robot" colliding wherever its one joint is beyond 0.62.
/// fn beyond<L: Lanes<Scalar = f64>>(q: &[L; 1]) -> LaneMask {
///     let mut bits = 0;
///     for i in 0..L::LANES {
///         bits |= u32::from(q[0].lane(i) > 0.62) << i;
///     }
///     LaneMask::from_bits(bits)
/// }
/// let motion = Motion::new("demo", [0.0], [1.0], 0.05)?;
/// assert_eq!(motion_wide::<F64x4, F64x8, 1>(&motion, beyond, beyond), Some(0.65));
/// # Ok::<(), kinematics_core::KinematicsError>(())
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn motion_wide<L, W, const N: usize>(
    motion: &Motion<L::Scalar, N>,
    narrow: impl Fn(&[L; N]) -> LaneMask,
    wide: impl Fn(&[W; N]) -> LaneMask,
) -> Option<f64>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    L::Scalar: Real + Into<f64>,
{
    let first = on_widest(Job { motion, narrow, wide, lanes: PhantomData::<fn(L, W)> });
    first.map(|k| motion.fraction(k))
}

/// Whether some checked configuration of the motion collides, in the lanes the CPU fills (as
/// [`motion_wide`] chooses them), `narrow` and `wide` answering whether any lane collides
/// (ending at the first hit on any). See [`Motion::any_collision`] for the order the
/// configurations are checked in.
///
/// ```
/// use kinematics_core::collision::{motion_any_wide, Motion};
/// use kinematics_core::{F64x4, F64x8, Lanes};
/// fn beyond<L: Lanes<Scalar = f64>>(q: &[L; 1]) -> bool {
///     (0..L::LANES).any(|i| q[0].lane(i) > 0.62)
/// }
/// assert!(motion_any_wide::<F64x4, F64x8, 1>(&Motion::new("demo", [0.0], [1.0], 0.05)?, beyond, beyond));
/// assert!(!motion_any_wide::<F64x4, F64x8, 1>(&Motion::new("demo", [0.0], [0.6], 0.05)?, beyond, beyond));
/// # Ok::<(), kinematics_core::KinematicsError>(())
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn motion_any_wide<L, W, const N: usize>(
    motion: &Motion<L::Scalar, N>,
    narrow: impl Fn(&[L; N]) -> bool,
    wide: impl Fn(&[W; N]) -> bool,
) -> bool
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    L::Scalar: Real + Into<f64>,
{
    on_widest(AnyJob { motion, narrow, wide, lanes: PhantomData::<fn(L, W)> })
}

/// [`motion_any_wide`] for every motion `(q0, q1)` of `motions` at `resolution`, into `out`
/// (whether it collides), one motion after another in one dispatched loop (each motion's lanes
/// spread along it, as [`Motion::any_collision`] takes them). A resolution that is not positive
/// and finite, or an `out` of another length than `motions`, is an error naming `robot`, and
/// nothing is written.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn motions_any_wide<L, W, const N: usize>(
    robot: &'static str,
    motions: &[Ends<L::Scalar, N>],
    resolution: impl Into<Resolution>,
    out: &mut [bool],
    narrow: impl Fn(&[L; N]) -> bool,
    wide: impl Fn(&[W; N]) -> bool,
) -> Result<(), KinematicsError>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    L::Scalar: Real + Into<f64>,
{
    let resolution = batch_checked(robot, resolution.into(), motions.len(), out.len())?;
    on_widest(AnyJobs { motions, resolution, out, narrow, wide, lanes: PhantomData::<fn(L, W)> });
    Ok(())
}

/// [`first_collisions`] in the lanes that fill the CPU's registers (as [`motion_wide`] chooses
/// them), after checking `resolution` (positive and finite) and that `out` has one entry per
/// motion (else an error naming `robot`, and nothing is written): each motion's first colliding
/// configuration's fraction, or `None` when every one is free.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn motions_wide<L, W, const N: usize>(
    robot: &'static str,
    motions: &[Ends<L::Scalar, N>],
    resolution: impl Into<Resolution>,
    out: &mut [Option<f64>],
    narrow: impl Fn(&[L; N]) -> LaneMask,
    wide: impl Fn(&[W; N]) -> LaneMask,
) -> Result<(), KinematicsError>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    L::Scalar: Real + Into<f64>,
{
    let resolution = batch_checked(robot, resolution.into(), motions.len(), out.len())?;
    on_widest(Jobs { motions, resolution, out, narrow, wide, lanes: PhantomData::<fn(L, W)> });
    Ok(())
}

/// [`motion_wide`]'s work. The checks are held by value: called through a reference they went
/// through `<&F as Fn>::call`, a shim LLVM did not inline into pulp's `#[target_feature]`
/// function, so the whole check ran compiled for the baseline (measured: the Panda's motions 2.7
/// times slower per configuration than its batch).
struct Job<'a, S, const N: usize, F, G, P> {
    motion: &'a Motion<S, N>,
    narrow: F,
    wide: G,
    lanes: PhantomData<P>,
}

impl<S, const N: usize, L, W, F, G> OnLanes for Job<'_, S, N, F, G, fn(L, W)>
where
    S: Real + Into<f64>,
    L: Lanes<Scalar = S>,
    W: Lanes<Scalar = S>,
    F: Fn(&[L; N]) -> LaneMask,
    G: Fn(&[W; N]) -> LaneMask,
{
    type Output = Option<usize>;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn narrow(self) -> Option<usize> {
        self.motion.first_collision(self.narrow)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn wide(self) -> Option<usize> {
        self.motion.first_collision(self.wide)
    }
}

/// [`motions_wide`]'s work.
struct Jobs<'a, S, const N: usize, F, G, P> {
    motions: &'a [Ends<S, N>],
    resolution: Resolution,
    out: &'a mut [Option<f64>],
    narrow: F,
    wide: G,
    lanes: PhantomData<P>,
}

impl<S, const N: usize, L, W, F, G> OnLanes for Jobs<'_, S, N, F, G, fn(L, W)>
where
    S: Real + Into<f64>,
    L: Lanes<Scalar = S>,
    W: Lanes<Scalar = S>,
    F: Fn(&[L; N]) -> LaneMask,
    G: Fn(&[W; N]) -> LaneMask,
{
    type Output = ();
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn narrow(self) {
        first_collisions(self.motions, self.resolution, self.narrow, self.out);
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn wide(self) {
        first_collisions(self.motions, self.resolution, self.wide, self.out);
    }
}

/// [`motion_any_wide`]'s work: one motion, already made.
struct AnyJob<'a, S, const N: usize, F, G, P> {
    motion: &'a Motion<S, N>,
    narrow: F,
    wide: G,
    lanes: PhantomData<P>,
}

impl<S, const N: usize, L, W, F, G> OnLanes for AnyJob<'_, S, N, F, G, fn(L, W)>
where
    S: Real + Into<f64>,
    L: Lanes<Scalar = S>,
    W: Lanes<Scalar = S>,
    F: Fn(&[L; N]) -> bool,
    G: Fn(&[W; N]) -> bool,
{
    type Output = bool;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn narrow(self) -> bool {
        self.motion.any_collision(self.narrow)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn wide(self) -> bool {
        self.motion.any_collision(self.wide)
    }
}

/// [`motions_any_wide`]'s work.
struct AnyJobs<'a, S, const N: usize, F, G, P> {
    motions: &'a [Ends<S, N>],
    resolution: Resolution,
    out: &'a mut [bool],
    narrow: F,
    wide: G,
    lanes: PhantomData<P>,
}

impl<S, const N: usize, L, W, F, G> OnLanes for AnyJobs<'_, S, N, F, G, fn(L, W)>
where
    S: Real + Into<f64>,
    L: Lanes<Scalar = S>,
    W: Lanes<Scalar = S>,
    F: Fn(&[L; N]) -> bool,
    G: Fn(&[W; N]) -> bool,
{
    type Output = ();
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn narrow(self) {
        for ((q0, q1), out) in self.motions.iter().zip(self.out) {
            *out = Motion::at(*q0, *q1, self.resolution).any_collision(&self.narrow);
        }
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn wide(self) {
        for ((q0, q1), out) in self.motions.iter().zip(self.out) {
            *out = Motion::at(*q0, *q1, self.resolution).any_collision(&self.wide);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{F32x8, F64x4, F64x8};

    #[test]
    fn steps_keep_every_joint_within_the_resolution() {
        let steps = |q0: [f64; 2], q1: [f64; 2], r: f64| Motion::new("t", q0, q1, r).map(|m| m.steps());
        assert_eq!(steps([0.0, 0.0], [0.0, 0.0], 0.1), Ok(1), "a motion that stays put checks its ends");
        assert_eq!(steps([0.0, 0.0], [1.0, -0.3], 0.1), Ok(10));
        assert_eq!(steps([0.0, 0.0], [1.0, -1.05], 0.1), Ok(11));
        assert_eq!(steps([f64::NAN, 0.0], [1.0, 0.0], 0.1), Ok(1));
        assert_eq!(steps([0.0, 0.0], [f64::INFINITY, 0.0], 0.1), Ok(1));
        assert_eq!(steps([0.0, 0.0], [1.0, 0.0], 1e-300), Ok(usize::MAX), "saturates");
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(matches!(
                Motion::new("t", [0.0], [1.0], bad),
                Err(KinematicsError::BadResolution { robot: "t", .. })
            ));
        }
    }

    /// The shared search against a scan: on motions of 1 to 70 steps and two lane widths, it
    /// answers whether some configuration of a drawn set collides; on a free motion it checks
    /// every configuration, each in exactly one round; and the first round samples the motion
    /// evenly (one configuration per lane's stretch).
    #[test]
    fn the_shared_search_answers_whether_any_configuration_collides() {
        use std::cell::RefCell;
        let mut rng = crate::splitmix::SplitMix(0x0061_6e79);
        let mut draw = || (rng.next() * 2f64.powi(53)) as u64;
        fn check<L: Lanes<Scalar = f64>>(set: u128, seen: &RefCell<std::vec::Vec<usize>>) -> impl Fn(&[L; 1]) -> bool {
            move |q: &[L; 1]| {
                let mut any = false;
                for i in 0..L::LANES {
                    let (x, k) = (q[0].lane(i), q[0].lane(i).round());
                    assert!(k >= 0.0 && (x - k).abs() < 1e-9, "{x}");
                    seen.borrow_mut().push(k as usize);
                    any |= set >> (k as u32) & 1 == 1;
                }
                any
            }
        }
        for steps in 1..=70_usize {
            let motion = Motion::new("t", [0.0_f64], [steps as f64], 1.0).unwrap();
            for round in 0..30 {
                let mask = (1u128 << (steps + 1)) - 1;
                let set = if round == 0 { 0 } else { (u128::from(draw()) << 64 | u128::from(draw())) & mask };
                let set = if round % 2 == 1 { set & (u128::from(draw()) << 64 | u128::from(draw())) } else { set };
                let seen = RefCell::new(std::vec::Vec::new());
                let four = motion.any_collision::<F64x4>(check(set, &seen));
                let first = seen.borrow().iter().take(4).copied().collect::<std::vec::Vec<_>>();
                let eight = motion.any_collision::<F64x8>(check(set, &RefCell::new(std::vec::Vec::new())));
                assert_eq!((four, eight), (set != 0, set != 0), "{steps} steps, set {set:b}");
                let run = (steps + 1).div_ceil(4);
                let spread: std::vec::Vec<usize> = (0..4).map(|i| (i * run).min(steps)).collect();
                assert_eq!(first, spread, "the first round, {steps} steps");
                if set == 0 {
                    let mut every = seen.into_inner();
                    every.sort_unstable();
                    every.dedup();
                    assert_eq!(every, (0..=steps).collect::<std::vec::Vec<_>>(), "{steps} steps");
                }
            }
        }
    }

    /// The lanes' search against a scan in order, for every set of colliding configurations a
    /// stream draws, on motions of 1 to 40 steps and two lane widths.
    #[test]
    fn the_search_finds_what_a_scan_in_order_finds() {
        let mut state = 0x5eed_u64;
        let mut next = || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        };
        for steps in 1..=40_usize {
            for _ in 0..20 {
                // Configuration k collides where bit k of `set` is (a sparse set, or none).
                let set = next() & next() & next() & ((1u64 << (steps + 1)) - 1);
                let motion = Motion::new("t", [0.0_f64], [steps as f64], 1.0).unwrap();
                assert_eq!(motion.steps(), steps);
                let expected = (0..=steps).find(|&k| set >> k & 1 == 1);
                // The check reads back each lane's configuration index (joint value = k).
                fn hits<L: Lanes<Scalar = f64>>(set: u64) -> impl Fn(&[L; 1]) -> LaneMask {
                    move |q: &[L; 1]| {
                        let mut bits = 0;
                        for i in 0..L::LANES {
                            // `(1 - t) 0 + t steps` is `k` to rounding.
                            let (x, k) = (q[0].lane(i), q[0].lane(i).round());
                            assert!(k >= 0.0 && (x - k).abs() < 1e-9, "{x}");
                            bits |= u32::from(set >> (k as u64) & 1 == 1) << i;
                        }
                        LaneMask::from_bits(bits)
                    }
                }
                assert_eq!(motion.first_collision::<F64x4>(hits(set)), expected, "{steps} steps, set {set:b}");
                assert_eq!(motion.first_collision::<F64x8>(hits(set)), expected, "{steps} steps, set {set:b}");
            }
        }
        // f32 lanes: the fraction rounded to f32, the ends exact.
        let motion = Motion::new("t", [0.5_f32], [2.5], 0.5).unwrap();
        let at_end = |q: &[F32x8; 1]| {
            let mut bits = 0;
            for i in 0..8 {
                bits |= u32::from(q[0].lane(i) == 2.5) << i;
            }
            LaneMask::from_bits(bits)
        };
        assert_eq!(motion.first_collision(at_end), Some(4));
    }

    /// Several motions one per lane against each searched alone, on batches of 1 to 40 motions of
    /// 1 to 40 steps (each configuration's second joint names its motion), two lane widths.
    #[test]
    fn a_batch_finds_what_each_motion_alone_finds() {
        let mut state = 0xba7c_u64;
        let mut next = || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        };
        fn hits<L: Lanes<Scalar = f64>>(sets: &[u64]) -> impl Fn(&[L; 2]) -> LaneMask + '_ {
            move |q: &[L; 2]| {
                let mut bits = 0;
                for i in 0..L::LANES {
                    let (k, m) = (q[0].lane(i).round() as u64, q[1].lane(i) as usize);
                    bits |= u32::from(sets[m] >> k & 1 == 1) << i;
                }
                LaneMask::from_bits(bits)
            }
        }
        for count in 1..=40_usize {
            let steps: std::vec::Vec<u64> = (0..count).map(|_| 1 + next() % 40).collect();
            let sets: std::vec::Vec<u64> =
                steps.iter().map(|&s| next() & next() & next() & ((1u64 << (s + 1)) - 1)).collect();
            let motions: std::vec::Vec<([f64; 2], [f64; 2])> =
                steps.iter().enumerate().map(|(m, &s)| ([0.0, m as f64], [s as f64, m as f64])).collect();
            let alone: std::vec::Vec<Option<f64>> = motions
                .iter()
                .map(|&(q0, q1)| {
                    let motion = Motion::new("t", q0, q1, 1.0).unwrap();
                    motion.first_collision::<F64x4>(hits(&sets)).map(|k| motion.fraction(k))
                })
                .collect();
            let mut four = std::vec![Some(-1.0); count];
            first_collisions::<F64x4, 2>(&motions, 1.0, hits(&sets), &mut four);
            assert_eq!(four, alone, "{count} motions of {steps:?} steps");
            let mut eight = std::vec![Some(-1.0); count];
            first_collisions::<F64x8, 2>(&motions, 1.0, hits(&sets), &mut eight);
            assert_eq!(eight, alone, "{count} motions of {steps:?} steps");
        }
    }
}
