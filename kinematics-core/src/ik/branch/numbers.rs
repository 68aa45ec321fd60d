//! The algebra that computes: [`Numbers`] over any [`IkReal`] (`f64`, or lanes of it), and the
//! run time's solver of a family, its eight branches side by side in `F64x8` lanes.

use core::marker::PhantomData;

use super::algebra::Algebra;
use super::family::{Branch, Problem};
use crate::ik::family::Arm6;
use crate::ik::real::{BRANCH_SIGNS_8, IkReal};
use crate::ik::solutions::{IkSolution, IkSolutions};
use crate::lanes::{F64x8, Lanes};
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
    #[inline(always)]
    fn constant(&mut self, x: f64) -> T {
        T::from_f64(x)
    }
    #[inline(always)]
    fn add(&mut self, a: T, b: T) -> T {
        a + b
    }
    #[inline(always)]
    fn sub(&mut self, a: T, b: T) -> T {
        a - b
    }
    #[inline(always)]
    fn mul(&mut self, a: T, b: T) -> T {
        a * b
    }
    #[inline(always)]
    fn neg(&mut self, a: T) -> T {
        -a
    }
    #[inline(always)]
    fn div(&mut self, a: T, b: T) -> T {
        a / b
    }
    #[inline(always)]
    fn sqrt(&mut self, a: T) -> T {
        a.sqrt()
    }
    #[inline(always)]
    fn atan2(&mut self, y: T, x: T) -> T {
        y.atan2(x)
    }
    #[inline(always)]
    fn if_positive(&mut self, condition: T, then: T, otherwise: T) -> T {
        condition.if_positive(then, otherwise)
    }
}

/// The eight branches of `family` for `target`, computed side by side in `F64x8` lanes (one
/// branch per lane, [`BRANCH_SIGNS_8`]), as unmeasured solutions in the order of the signs.
#[inline(always)]
pub fn solve_in_lanes(
    arm: &Arm6,
    target: &Pose<f64>,
    family: impl FnOnce(&mut Numbers<F64x8>, &Problem<'_, F64x8>) -> Branch<F64x8>,
) -> IkSolutions<6, 8> {
    let splat = |x: f64| F64x8::from_fn(|_| x);
    let problem = Problem {
        arm,
        rotation: target.rotation.map(|row| row.map(splat)),
        translation: target.translation.map(splat),
        signs: BRANCH_SIGNS_8,
        singular_pass: true,
    };
    let branch = family(&mut Numbers::new(), &problem);
    let solutions = core::array::from_fn(|lane| {
        let q = branch.q.map(|column| column.lane(lane));
        IkSolution::unmeasured(q, branch.quality.exact.lane(lane) == 1.0, branch.quality.singular.lane(lane) == 1.0)
    });
    IkSolutions::from_array(solutions)
}
