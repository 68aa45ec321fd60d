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
//! [`batch_inputs`] is [`batch_wide`] for functions of several per-configuration inputs (the
//! twists' `q` and `qd`, inverse dynamics' `q`, `qd` and `qdd`): its [`Inputs`] are a tuple of
//! named row slices ([`Input`]), each row a [`Packable`] value (a vector `[T; N]`, or an array of
//! them such as `[[T; 6]; K]`), packing into the tuple of their lanes, which the body takes. Every
//! input must be as long as the output, and nothing is written otherwise. Generated `*_batch`
//! functions of rate-taking functions are this one (forward dynamics, whose configurations may be
//! refused one by one, is `dynamics::accelerations_batch`, the same loop).
//!
//! They run on the wide lanes under AVX-512 and the narrow ones otherwise; rows or columns are an
//! [`Inputs`] source, and what a pack's value becomes in the output is an `Unpack` (written lane
//! by lane, or checked lane by lane). The generated body reaches every dispatched function
//! through an `#[inline(always)]` closure (see `dispatch`).

use core::convert::Infallible;

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
    let Ok(()) = pulp::Arch::new().dispatch(Packs::new(rows(qs), out, &f, &Write));
    #[cfg(not(feature = "dispatch"))]
    let Ok(()) = packs_from(rows(qs), out, &f, &Write);
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
    let Ok(()) = run(rows(qs), out, &Write, &narrow, &wide);
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
    let columns = Columns { joints, columns };
    columns.check(robot, out.len())?;
    let Ok(()) = run(columns, out, &Write, &narrow, &wide);
    Ok(())
}

/// [`batch_wide`] for a function of several per-configuration inputs: `inputs` is a tuple of
/// [`Input`]s (`q`'s rows, then the rates' and so on, up to four), packed together, lane `i` of
/// each input configuration `i`, so the bodies take the tuple of their packs. Every input must
/// hold one row per output: one of another length is an error naming `robot` and the input
/// ([`KinematicsError::WrongInputLength`]), checked before anything is computed, and nothing is
/// written then.
///
/// ```
/// use kinematics_core::{batch_inputs, F64x4, F64x8, Input, KinematicsError, Real};
/// // A "twist" of two joints: the rates times the cosines.
/// fn twist<T: Real>(q: &[T; 2], qd: &[T; 2]) -> T {
///     let (_, c) = T::sin_cos_many(*q);
///     c[0] * qd[0] + c[1] * qd[1]
/// }
/// let qs: Vec<[f64; 2]> = (0..11).map(|i| [0.1 * i as f64, 1.0]).collect();
/// let qds: Vec<[f64; 2]> = (0..11).map(|i| [1.0, -0.5 * i as f64]).collect();
/// let mut out = vec![0.0; 11];
/// batch_inputs::<F64x4, F64x8, _, _, _>(
///     "demo",
///     (Input::new("qs", &qs), Input::new("qds", &qds)),
///     &mut out,
///     |(q, qd)| twist(q, qd),
///     |(q, qd)| twist(q, qd),
/// )?;
/// for i in 0..11 {
///     assert_eq!(out[i], twist(&qs[i], &qds[i])); // bit for bit, the last pack padded
/// }
/// // A short input is refused by name, and nothing is written.
/// let mut untouched = vec![7.0; 11];
/// let error = batch_inputs::<F64x4, F64x8, _, _, _>(
///     "demo",
///     (Input::new("qs", &qs), Input::new("qds", &qds[1..])),
///     &mut untouched,
///     |(q, qd)| twist(q, qd),
///     |(q, qd)| twist(q, qd),
/// )
/// .unwrap_err();
/// assert_eq!(error, KinematicsError::WrongInputLength { robot: "demo", input: "qds", expected: 11, got: 10 });
/// assert!(untouched.iter().all(|&x| x == 7.0));
/// # Ok::<(), KinematicsError>(())
/// ```
///
/// A further input is one more [`Input`] in the tuple, of any [`Packable`] shape: here an
/// external spatial force on each of two links, `[[T; 6]; 2]` per configuration, packed to
/// `[[L; 6]; 2]`:
///
/// ```
/// use kinematics_core::{batch_inputs, F64x4, F64x8, Input, Real};
/// fn load<T: Real>(q: &[T; 2], qd: &[T; 2], qdd: &[T; 2], forces: &[[T; 6]; 2]) -> [T; 2] {
///     [q[0] * qdd[0] + forces[0][5], qd[1] * qdd[1] + forces[1][2]]
/// }
/// let (qs, qds, qdds) = (vec![[0.5, 1.0]; 9], vec![[2.0, 3.0]; 9], vec![[4.0, 5.0]; 9]);
/// let forces: Vec<[[f64; 6]; 2]> = (0..9).map(|i| [[i as f64; 6], [-(i as f64); 6]]).collect();
/// let mut out = vec![[0.0; 2]; 9];
/// batch_inputs::<F64x4, F64x8, _, _, _>(
///     "demo",
///     (Input::new("qs", &qs), Input::new("qds", &qds), Input::new("qdds", &qdds), Input::new("forces", &forces)),
///     &mut out,
///     |(q, qd, qdd, f)| load(q, qd, qdd, f),
///     |(q, qd, qdd, f)| load(q, qd, qdd, f),
/// )?;
/// assert_eq!(out[8], load(&qs[8], &qds[8], &qdds[8], &forces[8]));
/// # Ok::<(), kinematics_core::KinematicsError>(())
/// ```
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn batch_inputs<L, W, I, O, P>(
    robot: &'static str,
    inputs: I,
    out: &mut [O::Scalar],
    narrow: impl Fn(&I::Packed<L>) -> O,
    wide: impl Fn(&I::Packed<W>) -> P,
) -> Result<(), KinematicsError>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    I: Inputs<L::Scalar>,
    O: LaneValue<L>,
    P: LaneValue<W, Scalar = O::Scalar>,
{
    inputs.check(robot, out.len())?;
    let Ok(()) = run(inputs, out, &Fenced(Write), &narrow, &wide);
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
        if (*f)(&rows(qs).pack::<L>(start, last)) {
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

/// One configuration's value of a batch input, which packs into lanes entry by entry: a vector
/// `[T; N]` (a configuration, its rates) packs to `[L; N]`, an array of vectors `[[T; M]; K]` (a
/// spatial force on each of `K` links, `M = 6`) to `[[L; M]; K]`, lane `i` of every entry being
/// row `i`'s. `S` is the scalar (`L::Scalar`); another shape is one more impl here.
pub trait Packable<S: Copy>: Copy {
    /// The same shape in lanes of `S`.
    type Packed<L: Lanes<Scalar = S>>: Copy;
    /// The lanes whose lane `i` is `row(i)`'s value, entry by entry.
    fn pack<'a, L: Lanes<Scalar = S>>(row: impl Fn(usize) -> &'a Self) -> Self::Packed<L>
    where
        Self: 'a;
}

// Filled from zeros and then each entry, as before the shapes were generic: no `array::from_fn`
// on the batch path (see `lanes`).
impl<S: Copy, const N: usize> Packable<S> for [S; N] {
    type Packed<L: Lanes<Scalar = S>> = [L; N];
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn pack<'a, L: Lanes<Scalar = S>>(row: impl Fn(usize) -> &'a Self) -> [L; N]
    where
        Self: 'a,
    {
        let mut packed = [L::from_f64(0.0); N];
        for (j, lanes) in packed.iter_mut().enumerate() {
            *lanes = L::from_fn(|i| row(i)[j]);
        }
        packed
    }
}

impl<S: Copy, const M: usize, const K: usize> Packable<S> for [[S; M]; K] {
    type Packed<L: Lanes<Scalar = S>> = [[L; M]; K];
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn pack<'a, L: Lanes<Scalar = S>>(row: impl Fn(usize) -> &'a Self) -> [[L; M]; K]
    where
        Self: 'a,
    {
        let mut packed = [[L::from_f64(0.0); M]; K];
        for (k, vector) in packed.iter_mut().enumerate() {
            *vector = <[S; M]>::pack(|i| &row(i)[k]);
        }
        packed
    }
}

/// Where a batch's configurations come from, packed `L::LANES` at a time: one slice of rows
/// ([`Input`]), the columns of `*_batch_columns`, or a tuple of up to four inputs (packing to the
/// tuple of their packs, which the batch's bodies take).
pub trait Inputs<S: Copy>: Copy {
    /// A pack of configurations in lanes of `S`.
    type Packed<L: Lanes<Scalar = S>>;
    /// That every input holds `len` configurations (the output's length): else the error naming
    /// `robot` and the first input that does not.
    fn check(self, robot: &'static str, len: usize) -> Result<(), KinematicsError>;
    /// Configurations `start..start + L::LANES` as lanes, those past `last` replaced by `last`
    /// (`start <= last`, `last` below the batch's length, checked by [`Inputs::check`]).
    fn pack<L: Lanes<Scalar = S>>(self, start: usize, last: usize) -> Self::Packed<L>;
}

/// One input of a batch, array of structures: a row (a [`Packable`] value) per configuration,
/// and the name its length is reported under (`"qds"`).
#[derive(Debug, Clone, Copy)]
pub struct Input<'a, E> {
    name: &'static str,
    rows: &'a [E],
}

impl<'a, E> Input<'a, E> {
    /// The input `name`, one row per configuration.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub const fn new(name: &'static str, rows: &'a [E]) -> Self {
        Input { name, rows }
    }
}

/// The configurations of a batch of `q` alone (their length checked against the output's by
/// `check_output`, as it always was).
#[cfg_attr(not(debug_assertions), inline(always))]
fn rows<S, const N: usize>(qs: &[[S; N]]) -> Input<'_, [S; N]> {
    Input::new("qs", qs)
}

impl<S: Copy, E: Packable<S>> Inputs<S> for Input<'_, E> {
    type Packed<L: Lanes<Scalar = S>> = E::Packed<L>;
    fn check(self, robot: &'static str, len: usize) -> Result<(), KinematicsError> {
        match self.rows.len() {
            got if got == len => Ok(()),
            got => Err(KinematicsError::WrongInputLength { robot, input: self.name, expected: len, got }),
        }
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn pack<L: Lanes<Scalar = S>>(self, start: usize, last: usize) -> E::Packed<L> {
        E::pack(|i| &self.rows[(start + i).min(last)])
    }
}

/// Tuples of inputs: each checked in order, packed side by side.
macro_rules! inputs_tuple {
    ($($input:ident $index:tt),+) => {
        impl<S: Copy, $($input: Inputs<S>),+> Inputs<S> for ($($input,)+) {
            type Packed<L: Lanes<Scalar = S>> = ($($input::Packed<L>,)+);
            fn check(self, robot: &'static str, len: usize) -> Result<(), KinematicsError> {
                $(self.$index.check(robot, len)?;)+
                Ok(())
            }
            #[cfg_attr(not(debug_assertions), inline(always))]
            fn pack<L: Lanes<Scalar = S>>(self, start: usize, last: usize) -> Self::Packed<L> {
                ($(self.$index.pack(start, last),)+)
            }
        }
    };
}

inputs_tuple!(A 0, B 1);
inputs_tuple!(A 0, B 1, C 2);
inputs_tuple!(A 0, B 1, C 2, D 3);

/// Structure of arrays: one slice per joint, each as long as the batch (checked by
/// [`Inputs::check`], naming the joint).
#[derive(Clone, Copy)]
struct Columns<'a, S, const N: usize> {
    joints: &'static [&'static str; N],
    columns: [&'a [S]; N],
}

impl<S: Copy, const N: usize> Inputs<S> for Columns<'_, S, N> {
    type Packed<L: Lanes<Scalar = S>> = [L; N];
    fn check(self, robot: &'static str, len: usize) -> Result<(), KinematicsError> {
        for (column, &joint) in self.columns.iter().zip(self.joints) {
            if column.len() != len {
                return Err(KinematicsError::WrongColumnLength { robot, joint, expected: len, got: column.len() });
            }
        }
        Ok(())
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn pack<L: Lanes<Scalar = S>>(self, start: usize, last: usize) -> [L; N] {
        let mut packed = [L::from_f64(0.0); N];
        for (lanes, column) in packed.iter_mut().zip(self.columns) {
            // A whole pack is one slice of known length: a contiguous load, no per-lane check.
            *lanes = match column.get(start..start + L::LANES) {
                Some(values) => L::from_fn(|i| values[i]),
                None => L::from_fn(|i| column[(start + i).min(last)]),
            };
        }
        packed
    }
}

/// What a batch makes of each pack's value `O` (lanes `L`) in its output of `T`s.
pub(crate) trait Unpack<L: Lanes, O, T> {
    /// Why a configuration's output is refused (`Infallible` for none).
    type Error;
    /// Lanes `0..out.len()` of `value` into `out`, the pack's first configuration being `start`
    /// of the batch; every lane is written, and the first refused is the error.
    fn unpack(&self, value: &O, start: usize, out: &mut [T]) -> Result<(), Self::Error>;
}

/// Every lane's value written as it is, entry by entry ([`LaneValue::write_lanes`]).
pub(crate) struct Write;

impl<L: Lanes, O: LaneValue<L>> Unpack<L, O, O::Scalar> for Write {
    type Error = Infallible;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn unpack(&self, value: &O, _: usize, out: &mut [O::Scalar]) -> Result<(), Infallible> {
        value.write_lanes(out);
        Ok(())
    }
}

/// Another unpacking behind a fence: the pack's value is in memory (a `black_box` of it, as the
/// collision tables' `fence`) before its lanes are taken, so the compiler interleaves nothing of
/// the body with the lane-by-lane writes. Without it LLVM left inverse dynamics' body in scalar
/// pieces, and the Panda's `inverse_dynamics_batch` took longer per configuration than calling
/// `inverse_dynamics` in a loop (seen in the disassembly and a harness outside the tree; no
/// committed benchmark times the unfenced form). The batches of `q` alone keep their unfenced
/// [`Write`].
pub(crate) struct Fenced<U>(pub(crate) U);

impl<L: Lanes, O, T, U: Unpack<L, O, T>> Unpack<L, O, T> for Fenced<U> {
    type Error = U::Error;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn unpack(&self, value: &O, start: usize, out: &mut [T]) -> Result<(), U::Error> {
        self.0.unpack(core::hint::black_box(value), start, out)
    }
}

/// The loop on the lanes that fill the CPU's registers (see [`batch_wide`]), each pack's value put
/// into `out` by `unpack`; the first refusal, if any. The inputs hold `out.len()` configurations
/// (checked by the callers).
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn run<L, W, I, O, P, T, U>(
    inputs: I,
    out: &mut [T],
    unpack: &U,
    narrow: &impl Fn(&I::Packed<L>) -> O,
    wide: &impl Fn(&I::Packed<W>) -> P,
) -> Result<(), <U as Unpack<L, O, T>>::Error>
where
    L: Lanes,
    W: Lanes<Scalar = L::Scalar>,
    I: Inputs<L::Scalar>,
    U: Unpack<L, O, T> + Unpack<W, P, T, Error = <U as Unpack<L, O, T>>::Error>,
{
    #[cfg(all(feature = "dispatch", target_arch = "x86_64", not(target_feature = "avx512f")))]
    {
        use pulp::Simd;
        match pulp::Arch::new() {
            pulp::Arch::V4(simd) => Simd::vectorize(simd, Packs::new(inputs, out, wide, unpack)),
            pulp::Arch::V3(simd) => Simd::vectorize(simd, Packs::new(inputs, out, narrow, unpack)),
            _ => packs_from(inputs, out, narrow, unpack),
        }
    }
    #[cfg(all(feature = "dispatch", not(target_arch = "x86_64"), not(target_feature = "avx512f")))]
    {
        let _ = wide;
        pulp::Arch::new().dispatch(Packs::new(inputs, out, narrow, unpack))
    }
    // Without dispatch, or with a target that already has AVX-512 (nothing wider to choose), the
    // lanes the build's own target fills.
    #[cfg(any(not(feature = "dispatch"), target_feature = "avx512f"))]
    {
        if cfg!(target_feature = "avx512f") {
            packs_from(inputs, out, wide, unpack)
        } else {
            packs_from(inputs, out, narrow, unpack)
        }
    }
}

/// The loop of [`batch`] and [`run`] as pulp's operation. A closure would not do: its `FnOnce`
/// shim is not inlined into pulp's `#[target_feature]` function (measured: no AVX instruction in
/// the result), while `with_simd` below and everything it calls are `#[inline(always)]`.
#[cfg(feature = "dispatch")]
struct Packs<'a, L, I, O, T, F, U> {
    inputs: I,
    out: &'a mut [T],
    f: &'a F,
    unpack: &'a U,
    lanes: core::marker::PhantomData<fn(L) -> O>,
}

#[cfg(feature = "dispatch")]
impl<'a, L, I, O, T, F, U> Packs<'a, L, I, O, T, F, U> {
    /// The loop over `inputs` into `out`, evaluating `f`, its values put by `unpack`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn new(inputs: I, out: &'a mut [T], f: &'a F, unpack: &'a U) -> Self {
        Packs { inputs, out, f, unpack, lanes: core::marker::PhantomData }
    }
}

#[cfg(feature = "dispatch")]
impl<L, I, O, T, F, U> pulp::WithSimd for Packs<'_, L, I, O, T, F, U>
where
    L: Lanes,
    I: Inputs<L::Scalar>,
    F: Fn(&I::Packed<L>) -> O,
    U: Unpack<L, O, T>,
{
    type Output = Result<(), U::Error>;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn with_simd<S: pulp::Simd>(self, _: S) -> Self::Output {
        packs_from(self.inputs, self.out, self.f, self.unpack)
    }
}

/// Pack, evaluate, unpack, `L::LANES` configurations at a time; the last pack padded with the
/// last configuration. The inputs hold `out.len()` configurations (checked by the callers). Every
/// pack is unpacked; the first refusal (in configuration order) is the answer.
#[cfg_attr(not(debug_assertions), inline(always))]
fn packs_from<L: Lanes, I: Inputs<L::Scalar>, O, T, U: Unpack<L, O, T>>(
    inputs: I,
    out: &mut [T],
    f: &impl Fn(&I::Packed<L>) -> O,
    unpack: &U,
) -> Result<(), U::Error> {
    let len = out.len();
    let mut first = Ok(());
    for (pack, o) in out.chunks_mut(L::LANES).enumerate() {
        let start = pack * L::LANES;
        let packed: I::Packed<L> = inputs.pack(start, len - 1);
        let unpacked = unpack.unpack(&(*f)(&packed), start, o);
        if first.is_ok() {
            first = unpacked;
        }
    }
    first
}

#[cfg(test)]
mod tests {
    use core::cell::Cell;

    use super::*;
    use crate::lanes::{F32x8, F64x4, F64x8};
    use crate::real::Real;

    /// A function of three inputs of three shapes: a configuration, rates, and a force on each of
    /// two links (the shape a fourth input of external forces would have).
    fn body<T: Real>(q: &[T; 3], qd: &[T; 2], forces: &[[T; 6]; 2]) -> [T; 2] {
        let (s, c) = T::sin_cos_many(*q);
        [s[0] * qd[0] + c[2] * forces[1][5], c[1] * qd[1] - s[2] * forces[0][3] + forces[1][0]]
    }

    /// Nineteen rows of each input of [`body`].
    type Samples = ([[f64; 3]; 19], [[f64; 2]; 19], [[[f64; 6]; 2]; 19]);

    /// Nineteen rows of each input: every value distinct, so a lane taken from the wrong row shows.
    fn samples() -> Samples {
        let value = |i: usize, k: usize| 0.01 * (100 * i + k) as f64 - 3.0;
        (
            core::array::from_fn(|i| core::array::from_fn(|k| value(i, k))),
            core::array::from_fn(|i| core::array::from_fn(|k| value(i, 10 + k))),
            core::array::from_fn(|i| core::array::from_fn(|l| core::array::from_fn(|k| value(i, 20 + 6 * l + k)))),
        )
    }

    /// A pack's lane `i` is row `start + i` of every input, entry by entry, and lanes past the
    /// last row repeat it; a tuple packs side by side.
    #[test]
    fn a_pack_takes_lane_i_from_row_i_and_pads_with_the_last() {
        let (qs, qds, forces) = samples();
        let inputs = (Input::new("qs", &qs[..10]), Input::new("qds", &qds[..10]), Input::new("forces", &forces[..10]));
        for start in [0, 4, 8] {
            let (q, qd, f): ([F64x4; 3], [F64x4; 2], [[F64x4; 6]; 2]) = inputs.pack(start, 9);
            for i in 0..4 {
                let row = (start + i).min(9);
                assert_eq!(q.map(|l| l.lane(i)), qs[row], "q, lane {i} of the pack at {start}");
                assert_eq!(qd.map(|l| l.lane(i)), qds[row], "qd, lane {i} of the pack at {start}");
                assert_eq!(f.map(|v| v.map(|l| l.lane(i))), forces[row], "forces, lane {i} of the pack at {start}");
            }
        }
    }

    /// Every length from 0 to 19, in four, eight (`f64`) and eight (`f32`) lanes: each output is the
    /// function on its own configuration, bit for bit; the body runs once per pack (the tail pack
    /// too, padded with the last configuration) and nothing past the output is touched.
    #[test]
    fn batches_of_inputs_are_the_function_per_configuration() {
        fn check<L: Lanes<Scalar = f64> + LaneValue<L, Scalar = f64>>(len: usize) {
            let (qs, qds, forces) = samples();
            let calls = Cell::new(0);
            let f = |(q, qd, forces): &([L; 3], [L; 2], [[L; 6]; 2])| {
                calls.set(calls.get() + 1);
                body(q, qd, forces)
            };
            let mut out = [[7.0; 2]; 20];
            let inputs =
                (Input::new("qs", &qs[..len]), Input::new("qds", &qds[..len]), Input::new("f", &forces[..len]));
            batch_inputs::<L, L, _, _, _>("demo", inputs, &mut out[..len], f, f).unwrap();
            assert_eq!(calls.get(), len.div_ceil(L::LANES), "one call per pack, {len} configurations");
            for i in 0..len {
                let want = body(&qs[i], &qds[i], &forces[i]);
                assert_eq!(out[i].map(f64::to_bits), want.map(f64::to_bits), "configuration {i} of {len}");
            }
            assert!(out[len..].iter().all(|o| *o == [7.0; 2]), "past the output");
        }
        for len in 0..=19 {
            check::<F64x4>(len);
            check::<F64x8>(len);
        }
        // f32 in eight lanes, the wide lanes the same type.
        let qs: [[f32; 3]; 11] = core::array::from_fn(|i| [0.1 * i as f32, -0.5, 1.0 + i as f32]);
        let qds: [[f32; 2]; 11] = core::array::from_fn(|i| [1.0, -0.25 * i as f32]);
        let forces: [[[f32; 6]; 2]; 11] = core::array::from_fn(|i| [[i as f32; 6], [0.5 - i as f32; 6]]);
        let mut out = [[0.0f32; 2]; 11];
        let inputs = (Input::new("qs", &qs), Input::new("qds", &qds), Input::new("forces", &forces));
        let f = |(q, qd, forces): &([F32x8; 3], [F32x8; 2], [[F32x8; 6]; 2])| body(q, qd, forces);
        batch_inputs::<F32x8, F32x8, _, _, _>("demo", inputs, &mut out, f, f).unwrap();
        for i in 0..11 {
            assert_eq!(out[i].map(f32::to_bits), body(&qs[i], &qds[i], &forces[i]).map(f32::to_bits), "f32 {i}");
        }
    }

    /// An input of another length than the output is refused by name (the first in order), before
    /// the body runs: nothing is written.
    #[test]
    fn inputs_of_another_length_are_refused_by_name_and_nothing_is_written() {
        let (qs, qds, forces) = samples();
        let calls = Cell::new(0);
        let f = |(q, qd, forces): &([F64x4; 3], [F64x4; 2], [[F64x4; 6]; 2])| {
            calls.set(calls.get() + 1);
            body(q, qd, forces)
        };
        let g = |(q, qd, forces): &([F64x8; 3], [F64x8; 2], [[F64x8; 6]; 2])| body(q, qd, forces);
        let mut out = [[7.0; 2]; 12];
        let cases = [(12, 11, 12, "qds", 11), (12, 12, 13, "forces", 13), (3, 12, 0, "qs", 3), (12, 0, 0, "qds", 0)];
        for (a, b, c, input, got) in cases {
            let inputs = (Input::new("qs", &qs[..a]), Input::new("qds", &qds[..b]), Input::new("forces", &forces[..c]));
            let error = batch_inputs::<F64x4, F64x8, _, _, _>("demo", inputs, &mut out, f, g).unwrap_err();
            assert_eq!(error, KinematicsError::WrongInputLength { robot: "demo", input, expected: 12, got });
        }
        assert_eq!(calls.get(), 0, "the body never ran");
        assert!(out.iter().all(|o| *o == [7.0; 2]), "nothing is written");
    }
}
