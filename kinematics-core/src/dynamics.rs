//! What generated forward dynamics needs at run time: the refusal of a singular mass matrix.
//!
//! Generated `forward_dynamics` solves `M qdd = tau - h` by the `L^T D L` factorisation of the
//! mass matrix and returns its pivots `D` beside the accelerations; [`accelerations_checked`]
//! turns them into the accelerations or the error naming the velocity whose pivot vanished,
//! never the infinities or NaN a division by a zero pivot gives. [`accelerations_batch`] is the
//! batch of it (`forward_dynamics_batch`): the same refusal, lane by lane.

use crate::batch::{Fenced, Inputs, Unpack, run};
use crate::error::KinematicsError;
use crate::lanes::Lanes;
use crate::real::Real;

/// How small a pivot of the mass matrix's factorisation may be, relative to the largest, before
/// the matrix is taken as singular: the runtime reference's ratio for its eigenvalues
/// (`ReferenceDynamics::SINGULAR_RATIO`), far below any real robot's (a wrist's pivot is about a
/// thousandth of the shoulder's) and far above rounding's (about `n * f64::EPSILON`).
pub const SINGULAR_RATIO: f64 = 1e-12;

/// The accelerations; or [`KinematicsError::NotFinite`] when a pivot is not finite (the mass
/// matrix overflowed, or `q` held a NaN); or [`KinematicsError::SingularMassMatrix`] naming the
/// first velocity (in `names`' order) whose pivot is not above [`SINGULAR_RATIO`] of the largest;
/// or [`KinematicsError::NotFinite`] when an acceleration is not finite.
///
/// ```
/// use kinematics_core::{KinematicsError, dynamics::accelerations_checked};
/// const NAMES: [&str; 2] = ["shoulder", "wrist"];
/// let names = &NAMES;
/// assert_eq!(accelerations_checked("arm", names, [1.0, 2.0], [0.5, 0.01]), Ok([1.0, 2.0]));
/// assert_eq!(
///     accelerations_checked("arm", names, [1.0, f64::NAN], [0.5, 0.0]),
///     Err(KinematicsError::SingularMassMatrix { robot: "arm", velocity: "wrist" })
/// );
/// assert!(matches!(
///     accelerations_checked("arm", names, [1.0, 2.0], [f64::NAN, 1.0]),
///     Err(KinematicsError::NotFinite { .. })
/// ));
/// ```
pub fn accelerations_checked<T: Copy + Into<f64>, const N: usize>(
    robot: &'static str,
    names: &'static [&'static str; N],
    accelerations: [T; N],
    pivots: [T; N],
) -> Result<[T; N], KinematicsError> {
    let pivots: [f64; N] = pivots.map(Into::into);
    if pivots.iter().any(|p| !p.is_finite()) {
        return Err(KinematicsError::NotFinite { robot, quantity: "mass matrix" });
    }
    let largest = pivots.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    if let Some(k) = pivots.iter().position(|&p| p <= SINGULAR_RATIO * largest) {
        return Err(KinematicsError::SingularMassMatrix { robot, velocity: names[k] });
    }
    if accelerations.iter().any(|&a| !Into::<f64>::into(a).is_finite()) {
        return Err(KinematicsError::NotFinite { robot, quantity: "forward dynamics' accelerations" });
    }
    Ok(accelerations)
}

/// Forward dynamics over a batch: `narrow` and `wide` are the generic body (the accelerations and
/// the pivots) on a pack of `inputs` (`q`, `qd` and `tau`'s rows, see [`crate::batch_inputs`]) in
/// the lanes the CPU fills, and each configuration's accelerations are checked as
/// [`accelerations_checked`] checks one configuration's, into `out`.
///
/// An input of another length than `out` is an error naming it, and nothing is written then.
/// Otherwise every configuration is computed and written: a refused one (a singular mass matrix,
/// a value that is not finite) as NaN in every entry, never what dividing by its pivot gave, and
/// the error names the first refused ([`KinematicsError::SingularMassMatrixInBatch`] or
/// [`KinematicsError::NotFiniteInBatch`], with its index); the others hold their accelerations,
/// bit for bit what the body gives them one at a time.
///
/// ```
/// use kinematics_core::dynamics::accelerations_batch;
/// use kinematics_core::{F64x4, F64x8, Input, KinematicsError, Real};
/// // A "robot" of two velocities whose second moves no mass where `q[1]` is 0.
/// fn solve<T: Real>(q: &[T; 2], tau: &[T; 2]) -> ([T; 2], [T; 2]) {
///     let pivots = [T::from_f64(2.0), q[1] * q[1]];
///     ([tau[0] / pivots[0], tau[1] / pivots[1]], pivots)
/// }
/// let qs: Vec<[f64; 2]> = (0..9).map(|i| [0.0, if i == 6 { 0.0 } else { 1.0 }]).collect();
/// let taus = vec![[1.0, 3.0]; 9];
/// let mut out = vec![[0.0; 2]; 9];
/// let error = accelerations_batch::<F64x4, F64x8, _, 2>(
///     "demo",
///     &["shoulder", "wrist"],
///     (Input::new("qs", &qs), Input::new("taus", &taus)),
///     &mut out,
///     |(q, tau)| solve(q, tau),
///     |(q, tau)| solve(q, tau),
/// )
/// .unwrap_err();
/// assert_eq!(
///     error,
///     KinematicsError::SingularMassMatrixInBatch { robot: "demo", configuration: 6, velocity: "wrist" }
/// );
/// assert!(out[6].iter().all(|a| a.is_nan()));
/// assert_eq!(out[8], [0.5, 3.0]);
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn accelerations_batch<L, W, I, const V: usize>(
    robot: &'static str,
    names: &'static [&'static str; V],
    inputs: I,
    out: &mut [[L::Scalar; V]],
    narrow: impl Fn(&I::Packed<L>) -> ([L; V], [L; V]),
    wide: impl Fn(&I::Packed<W>) -> ([W; V], [W; V]),
) -> Result<(), KinematicsError>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    L::Scalar: Real + Into<f64>,
    I: Inputs<L::Scalar>,
{
    inputs.check(robot, out.len())?;
    run(inputs, out, &Fenced(Checked { robot, names }), &narrow, &wide)
}

/// A pack of forward dynamics' values (accelerations, pivots) into the batch's output, each lane
/// checked by [`accelerations_checked`].
struct Checked<const V: usize> {
    robot: &'static str,
    names: &'static [&'static str; V],
}

impl<L: Lanes, const V: usize> Unpack<L, ([L; V], [L; V]), [L::Scalar; V]> for Checked<V>
where
    L::Scalar: Real + Into<f64>,
{
    type Error = KinematicsError;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn unpack(
        &self,
        (accelerations, pivots): &([L; V], [L; V]),
        start: usize,
        out: &mut [[L::Scalar; V]],
    ) -> Result<(), KinematicsError> {
        let mut first = Ok(());
        for (i, slot) in out.iter_mut().enumerate() {
            let (mut lane, mut lane_pivots) = ([L::Scalar::from_f64(0.0); V], [L::Scalar::from_f64(0.0); V]);
            for k in 0..V {
                lane[k] = accelerations[k].lane(i);
                lane_pivots[k] = pivots[k].lane(i);
            }
            *slot = match accelerations_checked(self.robot, self.names, lane, lane_pivots) {
                Ok(accelerations) => accelerations,
                Err(error) => {
                    if first.is_ok() {
                        first = Err(error.in_batch(start + i));
                    }
                    [L::Scalar::from_f64(f64::NAN); V]
                }
            };
        }
        first
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::batch::Input;
    use crate::lanes::{F32x8, F64x4, F64x8};

    const NAMES: [&str; 2] = ["shoulder", "wrist"];

    /// A "robot" whose wrist moves no mass where `q[1]` is 0, and whose shoulder's pivot is `q[0]`.
    fn solve<T: Real>(q: &[T; 2], tau: &[T; 2]) -> ([T; 2], [T; 2]) {
        let pivots = [q[0], q[1] * q[1]];
        ([tau[0] / pivots[0], tau[1] / pivots[1]], pivots)
    }

    /// The batch's configurations are [`accelerations_checked`]'s one by one: each accepted one's
    /// accelerations bit for bit, each refused one NaN, and the error the first refused with its
    /// index, whichever lanes and wherever it falls in a pack (the padded tail's included).
    #[test]
    fn a_batch_refuses_what_one_configuration_refuses() {
        fn check<L: Lanes<Scalar = f64>, W: Lanes<Scalar = f64>>(qs: &[[f64; 2]]) {
            let taus: [[f64; 2]; 13] = core::array::from_fn(|i| [1.0 + i as f64, -0.5]);
            let taus = &taus[..qs.len()];
            let mut out = [[7.0; 2]; 13];
            let out = &mut out[..qs.len()];
            let result = accelerations_batch::<L, W, _, 2>(
                "demo",
                &NAMES,
                (Input::new("qs", qs), Input::new("taus", taus)),
                out,
                |(q, tau)| solve(q, tau),
                |(q, tau)| solve(q, tau),
            );
            let mut first = None;
            for (i, got) in out.iter().enumerate() {
                let (a, p) = solve(&qs[i], &taus[i]);
                match accelerations_checked("demo", &NAMES, a, p) {
                    Ok(want) => assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "configuration {i}"),
                    Err(error) => {
                        assert!(got.iter().all(|a| a.is_nan()), "refused configuration {i}: {got:?}");
                        first.get_or_insert(error.in_batch(i));
                    }
                }
            }
            assert_eq!(result, first.map_or(Ok(()), Err));
        }
        let regular = [[2.0, 1.0]; 13];
        let mut singular_late = regular;
        singular_late[12][1] = 0.0; // in the tail pack of four and of eight
        let mut two = regular;
        two[5][1] = 0.0;
        two[9][0] = f64::NAN;
        let mut overflow = regular;
        overflow[3][0] = 1e-300; // a pivot far below the other's: singular too
        for qs in [&regular[..], &singular_late[..], &two[..], &two[6..], &overflow[..], &regular[..0]] {
            check::<F64x4, F64x8>(qs);
            check::<F64x8, F64x4>(qs);
        }
        // The index and the velocity named, as read.
        let mut out = [[0.0; 2]; 13];
        let taus = [[1.0, 1.0]; 13];
        let error = accelerations_batch::<F64x4, F64x8, _, 2>(
            "demo",
            &NAMES,
            (Input::new("qs", &two), Input::new("taus", &taus)),
            &mut out,
            |(q, tau)| solve(q, tau),
            |(q, tau)| solve(q, tau),
        );
        assert_eq!(
            error,
            Err(KinematicsError::SingularMassMatrixInBatch { robot: "demo", configuration: 5, velocity: "wrist" })
        );
        // f32, whose pivots are checked in f64 as one configuration's are.
        let qs = [[2.0f32, 1.0], [2.0, 0.0], [f32::INFINITY, 1.0]];
        let mut out = [[0.0f32; 2]; 3];
        let result = accelerations_batch::<F32x8, F32x8, _, 2>(
            "demo",
            &NAMES,
            (Input::new("qs", &qs), Input::new("taus", &[[1.0f32, 1.0]; 3])),
            &mut out,
            |(q, tau)| solve(q, tau),
            |(q, tau)| solve(q, tau),
        );
        assert_eq!(
            result,
            Err(KinematicsError::SingularMassMatrixInBatch { robot: "demo", configuration: 1, velocity: "wrist" })
        );
        assert_eq!(out[0], [0.5, 1.0]);
        assert!(out[1].iter().chain(&out[2]).all(|a| a.is_nan()));
    }

    /// An input of another length than the output: its name, and nothing written.
    #[test]
    fn a_short_input_is_refused_before_anything_is_written() {
        let (qs, taus) = ([[2.0, 1.0]; 6], [[1.0, 1.0]; 5]);
        let mut out = [[7.0; 2]; 6];
        let error = accelerations_batch::<F64x4, F64x8, _, 2>(
            "demo",
            &NAMES,
            (Input::new("qs", &qs), Input::new("taus", &taus)),
            &mut out,
            |(q, tau)| solve(q, tau),
            |(q, tau)| solve(q, tau),
        );
        assert_eq!(error, Err(KinematicsError::WrongInputLength { robot: "demo", input: "taus", expected: 6, got: 5 }));
        assert_eq!(out, [[7.0; 2]; 6]);
    }
}
