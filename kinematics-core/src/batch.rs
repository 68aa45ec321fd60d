//! Batches: many configurations through a lane type, array-of-structs in and out.
//!
//! [`batch`] packs `L::LANES` configurations at a time into lanes (a structure of arrays), runs
//! the generated code once per pack, and unpacks each lane's result into the caller's output. The
//! last pack is filled up with copies of the batch's last configuration, whose results are thrown
//! away: every lane always computes a real configuration, and the tail costs one pack.

use crate::error::KinematicsError;
use crate::kinematics::check_output;
use crate::lanes::{LaneValue, Lanes};

/// Evaluates `f` on every configuration of `qs` into `out` (one output per configuration), `L::LANES`
/// configurations per call of `f`.
///
/// Generated `*_batch` functions are this with their generic body as `f`. An `out` of another
/// length than `qs` is an error naming `robot`; nothing is written then.
///
/// ```
/// use kinematics_core::{batch, F64x4, Real};
/// fn norm2<T: Real>(q: &[T; 2]) -> T { q[0] * q[0] + q[1] * q[1] }
/// let qs: Vec<[f64; 2]> = (0..7).map(|i| [i as f64, 1.0]).collect();
/// let mut out = vec![0.0; 7];
/// batch::<F64x4, 2, _>("demo", &qs, &mut out, norm2)?;
/// assert_eq!(out, qs.iter().map(norm2).collect::<Vec<f64>>());
/// assert!(batch::<F64x4, 2, _>("demo", &qs, &mut out[..6], norm2).is_err());
/// # Ok::<(), kinematics_core::KinematicsError>(())
/// ```
#[inline(always)]
pub fn batch<L: Lanes, const N: usize, O: LaneValue<L>>(
    robot: &'static str,
    qs: &[[L::Scalar; N]],
    out: &mut [O::Scalar],
    f: impl Fn(&[L; N]) -> O,
) -> Result<(), KinematicsError> {
    check_output(robot, qs.len(), out.len())?;
    // With `dispatch`, the whole loop (the generated body inlined into it) is compiled for each
    // instruction set pulp knows and the best the CPU has is chosen at run time.
    #[cfg(feature = "dispatch")]
    pulp::Arch::new().dispatch(Packs { qs, out, f: &f });
    #[cfg(not(feature = "dispatch"))]
    packs(qs, out, &f);
    Ok(())
}

/// The loop of [`batch`] as pulp's operation. A closure would not do: its `FnOnce` shim is not
/// inlined into pulp's `#[target_feature]` function (measured: no AVX instruction in the result),
/// while `with_simd` below and everything it calls are `#[inline(always)]`.
#[cfg(feature = "dispatch")]
struct Packs<'a, L: Lanes, const N: usize, O: LaneValue<L>, F> {
    qs: &'a [[L::Scalar; N]],
    out: &'a mut [O::Scalar],
    f: &'a F,
}

#[cfg(feature = "dispatch")]
impl<L: Lanes, const N: usize, O: LaneValue<L>, F: Fn(&[L; N]) -> O> pulp::WithSimd for Packs<'_, L, N, O, F> {
    type Output = ();
    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        packs(self.qs, self.out, self.f);
    }
}

/// The loop of [`batch`]: pack, evaluate, unpack.
#[inline(always)]
fn packs<L: Lanes, const N: usize, O: LaneValue<L>>(
    qs: &[[L::Scalar; N]],
    out: &mut [O::Scalar],
    f: &impl Fn(&[L; N]) -> O,
) {
    for (q, o) in qs.chunks(L::LANES).zip(out.chunks_mut(L::LANES)) {
        let last = q.len() - 1;
        let mut packed = [L::from_f64(0.0); N];
        for (j, lanes) in packed.iter_mut().enumerate() {
            *lanes = L::from_fn(|i| q[i.min(last)][j]);
        }
        let value = (*f)(&packed);
        for (i, slot) in o.iter_mut().enumerate() {
            *slot = value.lane(i);
        }
    }
}
