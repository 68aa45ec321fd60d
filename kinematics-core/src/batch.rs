//! Batches: many configurations through a lane type, one output per configuration.
//!
//! [`batch`] packs `L::LANES` configurations at a time into lanes (a structure of arrays), runs
//! the generated code once per pack, and unpacks each lane's result into the caller's output, entry
//! by entry (`LaneValue::write_lanes`: each entry of every lane written in place). The
//! last pack is filled up with copies of the batch's last configuration, whose results are thrown
//! away: every lane always computes a real configuration, and the tail costs one pack.
//!
//! [`batch_wide`] is the same with two lane types, a narrow one for AVX2 and the baseline and a
//! wide one for AVX-512, the body chosen at run time with the lanes that fill the CPU's registers;
//! [`batch_columns`] takes the configurations column-wise (one slice per joint, as planners keep
//! them), so packing a lane is a contiguous load rather than a transpose. Generated `*_batch` and
//! `*_batch_columns` functions are these two.
//!
//! They run on the wide lanes under AVX-512 and the narrow ones otherwise; rows or columns are a
//! `Configurations` source. The generated body reaches every dispatched function through an
//! `#[inline(always)]` closure (see `dispatch`).

use crate::error::KinematicsError;
use crate::kinematics::check_output;
use crate::lanes::{LaneValue, Lanes};

/// Evaluates `f` on every configuration of `qs` into `out` (one output per configuration), `L::LANES`
/// configurations per call of `f`.
///
/// An `out` of another length than `qs` is an error naming `robot`; nothing is written then.
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
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn batch<L: Lanes, const N: usize, O: LaneValue<L>>(
    robot: &'static str,
    qs: &[[L::Scalar; N]],
    out: &mut [O::Scalar],
    f: impl Fn(&[L; N]) -> O,
) -> Result<(), KinematicsError> {
    check_output(robot, qs.len(), out.len())?;
    // With `dispatch`, the whole loop (the body inlined into it) is compiled for each instruction
    // set pulp knows and the best the CPU has is chosen at run time.
    #[cfg(feature = "dispatch")]
    pulp::Arch::new().dispatch(Packs::new(Rows(qs), out, &f));
    #[cfg(not(feature = "dispatch"))]
    packs_from(Rows(qs), out, &f);
    Ok(())
}

/// [`batch`] with the lanes chosen for the CPU: `wide` (`W`, e.g. `F64x8`) where it has AVX-512,
/// `narrow` (`L`, e.g. `F64x4`) elsewhere. Both are the same body on different lane types, so
/// the results are the same whichever runs (see [`crate::dispatch`]).
///
/// ```
/// use kinematics_core::{batch_wide, F64x4, F64x8, Real};
/// fn norm2<T: Real>(q: &[T; 2]) -> T { q[0] * q[0] + q[1] * q[1] }
/// let qs: Vec<[f64; 2]> = (0..11).map(|i| [i as f64, 1.0]).collect();
/// let mut out = vec![0.0; 11];
/// batch_wide::<F64x4, F64x8, 2, _, _>("demo", &qs, &mut out, norm2, norm2)?;
/// assert_eq!(out, qs.iter().map(norm2).collect::<Vec<f64>>());
/// # Ok::<(), kinematics_core::KinematicsError>(())
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn batch_wide<L, W, const N: usize, O, P>(
    robot: &'static str,
    qs: &[[L::Scalar; N]],
    out: &mut [O::Scalar],
    narrow: impl Fn(&[L; N]) -> O,
    wide: impl Fn(&[W; N]) -> P,
) -> Result<(), KinematicsError>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    O: LaneValue<L>,
    P: LaneValue<W, Scalar = O::Scalar>,
{
    check_output(robot, qs.len(), out.len())?;
    run(Rows(qs), out, &narrow, &wide);
    Ok(())
}

/// [`batch_wide`] on configurations given column-wise: `columns[j][i]` is joint `j`'s value in
/// configuration `i`. Every column must hold one value per output; a column of another length is
/// an error naming its joint (`joints[j]`, the robot's `JOINT_NAMES`), and nothing is written then.
///
/// ```
/// use kinematics_core::{batch_columns, F64x4, F64x8, Real};
/// fn norm2<T: Real>(q: &[T; 2]) -> T { q[0] * q[0] + q[1] * q[1] }
/// let x: Vec<f64> = (0..11).map(f64::from).collect();
/// let y = vec![1.0; 11];
/// let mut out = vec![0.0; 11];
/// batch_columns::<F64x4, F64x8, 2, _, _>("demo", &["x", "y"], [&x, &y], &mut out, norm2, norm2)?;
/// assert_eq!(out, x.iter().map(|&x| norm2(&[x, 1.0])).collect::<Vec<f64>>());
/// assert!(batch_columns::<F64x4, F64x8, 2, _, _>("demo", &["x", "y"], [&x, &y[1..]], &mut out, norm2, norm2).is_err());
/// # Ok::<(), kinematics_core::KinematicsError>(())
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn batch_columns<L, W, const N: usize, O, P>(
    robot: &'static str,
    joints: &'static [&'static str; N],
    columns: [&[L::Scalar]; N],
    out: &mut [O::Scalar],
    narrow: impl Fn(&[L; N]) -> O,
    wide: impl Fn(&[W; N]) -> P,
) -> Result<(), KinematicsError>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    O: LaneValue<L>,
    P: LaneValue<W, Scalar = O::Scalar>,
{
    for (column, &joint) in columns.iter().zip(joints) {
        if column.len() != out.len() {
            return Err(KinematicsError::WrongColumnLength { robot, joint, expected: out.len(), got: column.len() });
        }
    }
    run(Columns(columns), out, &narrow, &wide);
    Ok(())
}

/// Whether `f` holds for some configuration of `qs` (`false` for none), `L::LANES`
/// configurations per call of `f` (`W::LANES` where the CPU has AVX-512, as [`batch_wide`]
/// chooses), the packs taken in order and the first that answers `true` ending the work: one
/// verdict shared by every configuration, as a planner validating a path or a batch of samples
/// wants it. The last pack is filled up with the last configuration.
///
/// ```
/// use kinematics_core::{any_wide, F64x4, F64x8, Lanes};
/// // Some configuration's first joint beyond 2.5.
/// fn beyond<L: Lanes<Scalar = f64>>(q: &[L; 2]) -> bool {
///     (0..L::LANES).any(|i| q[0].lane(i) > 2.5)
/// }
/// let qs: Vec<[f64; 2]> = (0..12).map(|i| [0.25 * i as f64, 1.0]).collect(); // to 2.75
/// assert!(any_wide::<F64x4, F64x8, 2>(&qs, beyond, beyond));
/// assert!(!any_wide::<F64x4, F64x8, 2>(&qs[..11], beyond, beyond));
/// assert!(!any_wide::<F64x4, F64x8, 2>(&[], beyond, beyond));
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn any_wide<L, W, const N: usize>(
    qs: &[[L::Scalar; N]],
    narrow: impl Fn(&[L; N]) -> bool,
    wide: impl Fn(&[W; N]) -> bool,
) -> bool
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
{
    on_widest(AnyPack { qs, narrow, wide, lanes: core::marker::PhantomData })
}

/// [`any_wide`]'s work: its configurations and its two bodies.
struct AnyPack<'a, L: Lanes, W, const N: usize, F, G> {
    qs: &'a [[L::Scalar; N]],
    narrow: F,
    wide: G,
    lanes: core::marker::PhantomData<fn(L, W)>,
}

impl<L, W, const N: usize, F, G> OnLanes for AnyPack<'_, L, W, N, F, G>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    F: Fn(&[L; N]) -> bool,
    G: Fn(&[W; N]) -> bool,
{
    type Output = bool;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn narrow(self) -> bool {
        any_pack(self.qs, &self.narrow)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn wide(self) -> bool {
        any_pack(self.qs, &self.wide)
    }
}

/// Pack and evaluate `L::LANES` configurations at a time until `f` answers `true`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn any_pack<L: Lanes, const N: usize>(qs: &[[L::Scalar; N]], f: &impl Fn(&[L; N]) -> bool) -> bool {
    let Some(last) = qs.len().checked_sub(1) else { return false };
    // A loop, not `Iterator::any`: its closure stayed a function of its own, compiled for the
    // baseline rather than inside pulp's `#[target_feature]` body (measured by `perf`: the
    // Panda's whole check ran there, 1.2 times the per-configuration batch's time).
    for start in (0..qs.len()).step_by(L::LANES) {
        if (*f)(&Rows(qs).pack(start, last)) {
            return true;
        }
    }
    false
}

/// Work with two bodies, one on narrow lanes (AVX2 and the baseline) and one on wide lanes
/// (AVX-512), for [`on_widest`] to run the one that fills the CPU's registers.
pub(crate) trait OnLanes {
    /// What the work answers.
    type Output;
    /// The work on the narrow lanes.
    fn narrow(self) -> Self::Output;
    /// The work on the wide lanes.
    fn wide(self) -> Self::Output;
}

/// `job` on the lanes that fill the CPU's registers, chosen as the batches choose them: with the
/// `dispatch` feature, compiled for each instruction set and chosen at run time (the wide body
/// under AVX-512, the narrow one under AVX2 and the baseline); without it, or for a target that
/// has AVX-512 already, the lanes the build's target fills.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn on_widest<J: OnLanes>(job: J) -> J::Output {
    #[cfg(all(feature = "dispatch", target_arch = "x86_64", not(target_feature = "avx512f")))]
    {
        use pulp::Simd;
        match pulp::Arch::new() {
            pulp::Arch::V4(simd) => Simd::vectorize(simd, Wide(job)),
            pulp::Arch::V3(simd) => Simd::vectorize(simd, Narrow(job)),
            _ => job.narrow(),
        }
    }
    #[cfg(all(feature = "dispatch", not(target_arch = "x86_64"), not(target_feature = "avx512f")))]
    {
        pulp::Arch::new().dispatch(Narrow(job))
    }
    #[cfg(any(not(feature = "dispatch"), target_feature = "avx512f"))]
    {
        if cfg!(target_feature = "avx512f") { job.wide() } else { job.narrow() }
    }
}

/// A job's narrow body as pulp's operation (a closure would not be inlined into pulp's
/// `#[target_feature]` function; see [`Packs`]).
#[cfg(feature = "dispatch")]
struct Narrow<J>(J);

#[cfg(feature = "dispatch")]
impl<J: OnLanes> pulp::WithSimd for Narrow<J> {
    type Output = J::Output;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn with_simd<S: pulp::Simd>(self, _: S) -> J::Output {
        self.0.narrow()
    }
}

/// A job's wide body as pulp's operation.
#[cfg(all(feature = "dispatch", target_arch = "x86_64", not(target_feature = "avx512f")))]
struct Wide<J>(J);

#[cfg(all(feature = "dispatch", target_arch = "x86_64", not(target_feature = "avx512f")))]
impl<J: OnLanes> pulp::WithSimd for Wide<J> {
    type Output = J::Output;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn with_simd<S: pulp::Simd>(self, _: S) -> J::Output {
        self.0.wide()
    }
}

/// Where a batch's configurations come from: packs of `L::LANES` of them as lanes.
trait Configurations<S: Copy, const N: usize>: Copy {
    /// Configurations `start..start + L::LANES` as lanes, those past `last` replaced by `last`
    /// (`start <= last`, `last` below the batch's length).
    fn pack<L: Lanes<Scalar = S>>(self, start: usize, last: usize) -> [L; N];
}

/// Array of structures: one array per configuration.
#[derive(Clone, Copy)]
struct Rows<'a, S, const N: usize>(&'a [[S; N]]);

impl<S: Copy, const N: usize> Configurations<S, N> for Rows<'_, S, N> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn pack<L: Lanes<Scalar = S>>(self, start: usize, last: usize) -> [L; N] {
        let mut packed = [L::from_f64(0.0); N];
        for (j, lanes) in packed.iter_mut().enumerate() {
            *lanes = L::from_fn(|i| self.0[(start + i).min(last)][j]);
        }
        packed
    }
}

/// Structure of arrays: one slice per joint, each as long as the batch (checked by the caller).
#[derive(Clone, Copy)]
struct Columns<'a, S, const N: usize>([&'a [S]; N]);

impl<S: Copy, const N: usize> Configurations<S, N> for Columns<'_, S, N> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn pack<L: Lanes<Scalar = S>>(self, start: usize, last: usize) -> [L; N] {
        let mut packed = [L::from_f64(0.0); N];
        for (lanes, column) in packed.iter_mut().zip(self.0) {
            // A whole pack is one slice of known length: a contiguous load, no per-lane check.
            *lanes = match column.get(start..start + L::LANES) {
                Some(values) => L::from_fn(|i| values[i]),
                None => L::from_fn(|i| column[(start + i).min(last)]),
            };
        }
        packed
    }
}

/// The loop on the lanes that fill the CPU's registers (see [`batch_wide`]).
#[cfg_attr(not(debug_assertions), inline(always))]
fn run<L, W, const N: usize, O, P, C>(
    source: C,
    out: &mut [O::Scalar],
    narrow: &impl Fn(&[L; N]) -> O,
    wide: &impl Fn(&[W; N]) -> P,
) where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    O: LaneValue<L>,
    P: LaneValue<W, Scalar = O::Scalar>,
    C: Configurations<L::Scalar, N>,
{
    #[cfg(all(feature = "dispatch", target_arch = "x86_64", not(target_feature = "avx512f")))]
    {
        use pulp::Simd;
        match pulp::Arch::new() {
            pulp::Arch::V4(simd) => Simd::vectorize(simd, Packs::new(source, out, wide)),
            pulp::Arch::V3(simd) => Simd::vectorize(simd, Packs::new(source, out, narrow)),
            _ => packs_from(source, out, narrow),
        }
    }
    #[cfg(all(feature = "dispatch", not(target_arch = "x86_64"), not(target_feature = "avx512f")))]
    {
        let _ = wide;
        pulp::Arch::new().dispatch(Packs::new(source, out, narrow));
    }
    // Without dispatch, or with a target that already has AVX-512 (nothing wider to choose), the
    // lanes the build's own target fills.
    #[cfg(any(not(feature = "dispatch"), target_feature = "avx512f"))]
    {
        if cfg!(target_feature = "avx512f") {
            packs_from(source, out, wide);
        } else {
            packs_from(source, out, narrow);
        }
    }
}

/// The loop of [`batch`] and [`run`] as pulp's operation. A closure would not do: its `FnOnce`
/// shim is not inlined into pulp's `#[target_feature]` function (measured: no AVX instruction in
/// the result), while `with_simd` below and everything it calls are `#[inline(always)]`.
#[cfg(feature = "dispatch")]
struct Packs<'a, L: Lanes, const N: usize, O: LaneValue<L>, C, F> {
    source: C,
    out: &'a mut [O::Scalar],
    f: &'a F,
    lanes: core::marker::PhantomData<fn(&[L; N]) -> O>,
}

#[cfg(feature = "dispatch")]
impl<'a, L: Lanes, const N: usize, O: LaneValue<L>, C, F> Packs<'a, L, N, O, C, F> {
    /// The loop over `source` into `out`, evaluating `f`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn new(source: C, out: &'a mut [O::Scalar], f: &'a F) -> Self {
        Packs { source, out, f, lanes: core::marker::PhantomData }
    }
}

#[cfg(feature = "dispatch")]
impl<L: Lanes, const N: usize, O: LaneValue<L>, C: Configurations<L::Scalar, N>, F: Fn(&[L; N]) -> O> pulp::WithSimd
    for Packs<'_, L, N, O, C, F>
{
    type Output = ();
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        packs_from(self.source, self.out, self.f);
    }
}

/// Pack, evaluate, unpack, `L::LANES` configurations at a time; the last pack padded with the
/// last configuration. The source holds `out.len()` configurations (checked by the callers).
#[cfg_attr(not(debug_assertions), inline(always))]
fn packs_from<L: Lanes, const N: usize, O: LaneValue<L>>(
    source: impl Configurations<L::Scalar, N>,
    out: &mut [O::Scalar],
    f: &impl Fn(&[L; N]) -> O,
) {
    let len = out.len();
    for (pack, o) in out.chunks_mut(L::LANES).enumerate() {
        let packed: [L; N] = source.pack(pack * L::LANES, len - 1);
        (*f)(&packed).write_lanes(o);
    }
}
