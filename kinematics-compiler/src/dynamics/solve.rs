//! Forward dynamics' linear solve: `M a = b` by the `L^T D L` factorisation of the mass matrix
//! (Featherstone §6.5, Table 6.3), eliminating from the last velocity up.
//!
//! With velocities in tree order (a parent's before its children's), `M[i][j]` is zero unless one
//! of the two joints is above the other, and eliminating from the last velocity up fills in none
//! of those zeros: the factor keeps the tree's sparsity, which the graph sees as constant zeros
//! and skips. Each pivot `D[k]` is divided by once (its reciprocal multiplies), and the pivots are
//! outputs too: the generated function refuses a mass matrix whose pivot is not positive (a
//! velocity that moves no mass) rather than return what division by zero gives.

use crate::symbolic::graph::{ExprGraph, ExprId};

/// The solution of `M a = rhs` and the pivots of `M = L^T D L`, from `M`'s upper triangle
/// (`upper[i][j]` for `i <= j`; the entries below are not read).
pub(super) fn solve(g: &mut ExprGraph, upper: Vec<Vec<ExprId>>, rhs: Vec<ExprId>) -> (Vec<ExprId>, Vec<ExprId>) {
    let n = rhs.len();
    let one = g.constant(1.0);
    // h[k][i] for i <= k: the lower triangle, from the upper one.
    let mut h: Vec<Vec<ExprId>> = (0..n).map(|k| (0..=k).map(|i| upper[i][k]).collect()).collect();
    let mut reciprocal = vec![one; n];
    for k in (0..n).rev() {
        reciprocal[k] = g.div(one, h[k][k]);
        for i in (0..k).rev() {
            if g.is_const(h[k][i], 0.0) {
                continue;
            }
            let a = g.mul(h[k][i], reciprocal[k]);
            // Row i (below k) less a times row k, over the columns up to i.
            let (above, from_k) = h.split_at_mut(k);
            for (entry, &by) in above[i].iter_mut().zip(&from_k[0][..=i]) {
                if !g.is_const(by, 0.0) {
                    let t = g.mul(a, by);
                    *entry = g.sub(*entry, t);
                }
            }
            h[k][i] = a;
        }
    }
    // L^T y = rhs (from the last up), D z = y, L a = z (from the first down).
    let mut x = rhs;
    for k in (0..n).rev() {
        for i in 0..k {
            if !g.is_const(h[k][i], 0.0) {
                let t = g.mul(h[k][i], x[k]);
                x[i] = g.sub(x[i], t);
            }
        }
    }
    for k in 0..n {
        x[k] = g.mul(x[k], reciprocal[k]);
    }
    for k in 0..n {
        for i in 0..k {
            if !g.is_const(h[k][i], 0.0) {
                let t = g.mul(h[k][i], x[i]);
                x[k] = g.sub(x[k], t);
            }
        }
    }
    let pivots = (0..n).map(|k| h[k][k]).collect();
    (x, pivots)
}
