//! The algebra that computes: [`Numbers`] over any [`IkReal`] (`f64`, or lanes of it), and the
//! run time's solver of a family, its eight branches side by side in `F64x8` lanes.

use core::marker::PhantomData;

use super::algebra::Algebra;
use super::family::{Branch, Problem};
use crate::ik::family::Arm6;
use crate::ik::real::{BRANCH_SIGNS_8, IkReal};
use crate::ik::solutions::{IkSolution, IkSolutions};
use crate::lanes::F64x8;
use crate::pose::Pose;

/// Arithmetic on numbers of type `T`: every operation computes at once.
#[derive(Debug, Clone, Copy, Default)]
pub struct Numbers<T>(PhantomData<T>);

impl<T> Numbers<T> {
    /// The algebra.
    pub const fn new() -> Self {
        Numbers(PhantomData)
    }
}

impl<T: IkReal> Algebra for Numbers<T> {
    type Value = T;
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn constant(&mut self, x: f64) -> T {
        T::from_f64(x)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn add(&mut self, a: T, b: T) -> T {
        a + b
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sub(&mut self, a: T, b: T) -> T {
        a - b
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn mul(&mut self, a: T, b: T) -> T {
        a * b
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn neg(&mut self, a: T) -> T {
        -a
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn div(&mut self, a: T, b: T) -> T {
        a / b
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sqrt(&mut self, a: T) -> T {
        a.sqrt()
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn atan2(&mut self, y: T, x: T) -> T {
        y.atan2(x)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn if_positive(&mut self, condition: T, then: T, otherwise: T) -> T {
        condition.if_positive(then, otherwise)
    }
}

/// The eight branches of `family` for `target`, computed side by side in `F64x8` lanes (one
/// branch per lane, [`BRANCH_SIGNS_8`]), as unmeasured solutions in the order of the signs.
///
/// Pass the family in an `#[inline(always)]` closure: a function item passed by name is called
/// through a shim LLVM does not inline, and would run outside the caller's instruction set (see
/// [`crate::dispatch`]).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn solve_in_lanes(
    arm: &Arm6,
    target: &Pose<f64>,
    family: impl FnOnce(&mut Numbers<F64x8>, &Problem<'_, F64x8>) -> Branch<F64x8>,
) -> IkSolutions<6, 8> {
    unmeasured(&branches_in_lanes(arm, target, true, family))
}

/// The eight branches of `family` for `target` in `F64x8` lanes, with or without the UR family's
/// pass at the wrist's singularity ([`Problem::singular_pass`]).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn branches_in_lanes(
    arm: &Arm6,
    target: &Pose<f64>,
    singular_pass: bool,
    family: impl FnOnce(&mut Numbers<F64x8>, &Problem<'_, F64x8>) -> Branch<F64x8>,
) -> Branch<F64x8> {
    let mut rotation = [[F64x8::splat(0.0); 3]; 3];
    let mut translation = [F64x8::splat(0.0); 3];
    for (i, row) in rotation.iter_mut().enumerate() {
        for (j, entry) in row.iter_mut().enumerate() {
            *entry = F64x8::splat(target.rotation[i][j]);
        }
        translation[i] = F64x8::splat(target.translation[i]);
    }
    let problem = Problem { arm, rotation, translation, signs: BRANCH_SIGNS_8, singular_pass };
    family(&mut Numbers::new(), &problem)
}

/// Whether some lane of `branch` is singular and not exact: where the UR family's pass at the
/// wrist's singularity can change the answer (elsewhere the branch is the same with or without it).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn needs_singular_pass(branch: &Branch<F64x8>) -> bool {
    let mut needs = false;
    for lane in 0..8 {
        needs |= branch.quality.singular.lane(lane) == 1.0 && branch.quality.exact.lane(lane) != 1.0;
    }
    needs
}

/// The branches in lanes as unmeasured solutions, lane `i` the `i`-th.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn unmeasured(branch: &Branch<F64x8>) -> IkSolutions<6, 8> {
    let mut solutions = [IkSolution::unmeasured([0.0; 6], false, false); 8];
    for (lane, solution) in solutions.iter_mut().enumerate() {
        for j in 0..6 {
            solution.q[j] = branch.q[j].lane(lane);
        }
        solution.exact = branch.quality.exact.lane(lane) == 1.0;
        solution.singular = branch.quality.singular.lane(lane) == 1.0;
    }
    IkSolutions::from_array(solutions)
}
