//! The trait every robot compiled with collision checking implements, so that code covering
//! several robots (a planner, a benchmark, a test harness) names the checks once.

use super::held::World;
use super::motion::Resolution;
use super::obstacles::Environment;
use crate::error::KinematicsError;
use crate::kinematics::Kinematics;

/// A robot compiled with collision checking (`collision` in the derive, `.collision()` in the
/// build API) and `f64` functions, its `N` degrees of freedom: the `f64` checks of its inherent
/// functions, under the same names, for code generic over robots.
///
/// Each method is the inherent function of the same name, called through the trait: the same
/// body, the same dispatch, the same answers (the inherent one is what the trait's calls
/// reach). The `f32` forms, the `_generic` lane forms, the columns batches and `hold` stay
/// inherent: they differ by robot in ways a trait would hide (the lane types, the held object's
/// link).
///
/// ```
/// use kinematics_core::collision::{Collision, Environment, Resolution};
/// /// How many of the sampled configurations are free, and whether a path through them is.
/// fn survey<R: Collision<N>, const N: usize>(qs: &[[f64; N]], env: &Environment<'_>) -> (usize, bool) {
///     let mut verdicts = vec![false; qs.len()];
///     R::collides_batch(qs, env, &mut verdicts).expect("one verdict per configuration");
///     let free = verdicts.iter().filter(|&&hit| !hit).count();
///     let path_free = qs.windows(2).all(|m| {
///         !R::motion_collides_any(&m[0], &m[1], env, Resolution::StatesPerUnit(32.0)).expect("a valid resolution")
///     });
///     (free, path_free)
/// }
/// ```
///
/// `N` is the length of `q`; `V`, the number of velocities, the length of a gradient: as `N`
/// unless the robot has a ball or free joint (a quaternion's four entries of `q`, three
/// velocities), so `Collision<N>` names every robot without one.
pub trait Collision<const N: usize, const V: usize = N>: Kinematics + Sized {
    /// Each collision sphere's radius (m), in the order of
    /// [`Collision::sphere_centers_into`].
    const SPHERE_RADII: &'static [f64];
    /// Each collision sphere's link, in the same order.
    const SPHERE_LINKS: &'static [&'static str];

    /// Every sphere's centre in `BASE` at `q`, into `out` (one per sphere: an `out` of another
    /// length is an error, and nothing is written).
    fn sphere_centers_into(q: &[f64; N], out: &mut [[f64; 3]]) -> Result<(), KinematicsError>;

    /// Whether the robot at `q` (or an object it holds) touches an obstacle of `environment` or
    /// itself. A configuration with a NaN or infinite entry is colliding.
    fn collides(q: &[f64; N], environment: &impl World<Self>) -> bool;

    /// Whether two links of a checked pair touch at `q`.
    fn self_collides(q: &[f64; N]) -> bool;

    /// [`Collision::collides`] for every configuration of `qs`, into `out` (one verdict each;
    /// an `out` of another length is an error, and nothing is written).
    fn collides_batch(qs: &[[f64; N]], environment: &impl World<Self>, out: &mut [bool])
    -> Result<(), KinematicsError>;

    /// [`Collision::self_collides`] for every configuration of `qs`, into `out`.
    fn self_collides_batch(qs: &[[f64; N]], out: &mut [bool]) -> Result<(), KinematicsError>;

    /// Whether some configuration of `qs` collides: one verdict shared by them all, the first
    /// pack with a hit ending the work.
    fn collides_any(qs: &[[f64; N]], environment: &impl World<Self>) -> bool;

    /// Whether some configuration of `qs` self-collides, found the same way.
    fn self_collides_any(qs: &[[f64; N]]) -> bool;

    /// Where the straight motion from `q0` to `q1`, checked at `resolution`, first collides: the
    /// fraction of the motion, or `None`. A resolution that is not positive and finite is an
    /// error.
    fn motion_collides(
        q0: &[f64; N],
        q1: &[f64; N],
        environment: &impl World<Self>,
        resolution: impl Into<Resolution>,
    ) -> Result<Option<f64>, KinematicsError>;

    /// Whether the straight motion from `q0` to `q1` collides: `motion_collides(..).is_some()`,
    /// sooner (a planner's edge check).
    fn motion_collides_any(
        q0: &[f64; N],
        q1: &[f64; N],
        environment: &impl World<Self>,
        resolution: impl Into<Resolution>,
    ) -> Result<bool, KinematicsError>;

    /// The clearance at `q`: the smallest signed distance (m) between one of the robot's spheres
    /// and an obstacle of `environment`, or between two spheres of a pair `self_collides` checks;
    /// negative, the depth of the deepest overlap; infinite with neither. A configuration with a
    /// NaN or infinite entry gives NaN.
    fn clearance(q: &[f64; N], environment: &Environment<'_>) -> f64;

    /// [`Collision::clearance`] and its gradient in the joints' velocities (one entry per
    /// velocity, as the Jacobians' columns).
    fn clearance_gradient(q: &[f64; N], environment: &Environment<'_>) -> (f64, [f64; V]);
}
