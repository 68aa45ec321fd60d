//! The linear solve of the numeric solver's steps and of the closed forms' refinement: a small
//! symmetric positive definite system by its `L D L^T` factorisation, on the stack.

use super::real::IkReal;

/// Solves `a x = b` for a symmetric positive definite `a` by its `L D L^T` factorisation, in
/// place, for `f64` or lane by lane: returns `1` where every pivot was positive (`a` positive
/// definite to rounding), else `0` (a NaN pivot counts as not; that lane's `b` is then no
/// solution). `L D L^T` rather than Cholesky's `L L^T`: no square roots, whose latency chained
/// pivot to pivot was a third of the numeric solver's time. Each pivot's reciprocal is taken once
/// and multiplied by (a division takes several times a multiplication's latency). `L` (unit
/// diagonal) is left below the diagonal, `D` on it, and `L D` above it.
#[allow(clippy::needless_range_loop, reason = "a factorisation reads as the index arithmetic it is")]
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn ldl_solve<T: IkReal, const N: usize>(a: &mut [[T; N]; N], b: &mut [T; N]) -> T {
    let (one, zero) = (T::from_f64(1.0), T::from_f64(0.0));
    let mut positive = one;
    let mut inverse = [zero; N];
    for j in 0..N {
        let mut d = a[j][j];
        for k in 0..j {
            // L[j][k] D[k], kept above the diagonal for the rows below this one.
            let scaled = a[j][k] * a[k][k];
            a[k][j] = scaled;
            d = d - scaled * a[j][k];
        }
        // A pivot that is not positive flags its lane and is replaced by 1, so the other lanes
        // go on (no branch).
        positive = d.if_positive(positive, zero);
        let d = d.if_positive(d, one);
        a[j][j] = d;
        inverse[j] = one / d;
        for i in j + 1..N {
            let mut s = a[i][j];
            for k in 0..j {
                s = s - a[i][k] * a[k][j];
            }
            a[i][j] = s * inverse[j];
        }
    }
    // L z = b, then L^T x = D^-1 z.
    for i in 0..N {
        let mut s = b[i];
        for k in 0..i {
            s = s - a[i][k] * b[k];
        }
        b[i] = s;
    }
    for i in (0..N).rev() {
        let mut s = b[i] * inverse[i];
        for k in i + 1..N {
            s = s - a[k][i] * b[k];
        }
        b[i] = s;
    }
    positive
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::splitmix::SplitMix;

    #[test]
    fn ldl_solves_and_refuses() {
        let mut a = [[4.0, 2.0], [2.0, 3.0]];
        let mut b = [2.0, 1.0];
        assert_eq!(ldl_solve(&mut a, &mut b), 1.0);
        assert!((b[0] - 0.5).abs() < 1e-15 && b[1].abs() < 1e-15, "{b:?}");
        let mut singular = [[1.0, 1.0], [1.0, 1.0]];
        assert_eq!(ldl_solve(&mut singular, &mut [1.0, 1.0]), 0.0);
        let mut indefinite = [[1.0, 2.0], [2.0, 1.0]];
        assert_eq!(ldl_solve(&mut indefinite, &mut [1.0, 1.0]), 0.0);
    }

    /// Random symmetric positive definite systems of sizes 1 to 9 (`B^T B + I`): the solution
    /// reproduces the right-hand side.
    #[test]
    fn ldl_solves_random_systems() {
        let mut rng = SplitMix(7);
        fn check<const N: usize>(rng: &mut SplitMix) {
            for _ in 0..50 {
                let b: [[f64; N]; N] = core::array::from_fn(|_| core::array::from_fn(|_| 2.0 * rng.next() - 1.0));
                let a: [[f64; N]; N] = core::array::from_fn(|i| {
                    core::array::from_fn(|j| (0..N).map(|k| b[k][i] * b[k][j]).sum::<f64>() + f64::from(i == j))
                });
                let rhs: [f64; N] = core::array::from_fn(|_| 2.0 * rng.next() - 1.0);
                let mut x = rhs;
                assert_eq!(ldl_solve(&mut a.clone(), &mut x), 1.0, "{a:?}");
                for i in 0..N {
                    let back: f64 = (0..N).map(|j| a[i][j] * x[j]).sum();
                    assert!((back - rhs[i]).abs() < 1e-12, "size {N}: row {i}: {back} against {}", rhs[i]);
                }
            }
        }
        check::<1>(&mut rng);
        check::<2>(&mut rng);
        check::<3>(&mut rng);
        check::<6>(&mut rng);
        check::<7>(&mut rng);
        check::<9>(&mut rng);
    }
}
