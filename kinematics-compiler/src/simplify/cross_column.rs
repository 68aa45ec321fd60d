//! Rule `cross-column`: a rotation column as the cross product of the other two.

use crate::stats::OpCount;
use crate::symbolic::graph::ExprGraph;
use crate::symbolic::transform::SymTransform;

use super::ExprPass;

/// Pass `cross-column` ([`cheapest_columns`], for a single pose whose rotation is an output).
pub const CROSS_COLUMN: ExprPass = ExprPass { name: "cross-column", run: cross_column };

fn cross_column(g: &mut ExprGraph, frames: &mut [SymTransform], position_only: bool) {
    // A single pose only: the cost below is measured on that pose alone.
    if let [t] = frames
        && !position_only
    {
        *t = cheapest_columns(g, *t);
    }
}

/// The rotation with whichever column is cheapest to derive from the other two replaced by their
/// cross product (the columns of a rotation are orthonormal and right-handed, so `c0 = c1 x c2`,
/// `c1 = c2 x c0`, `c2 = c0 x c1`), when that saves work.
fn cheapest_columns(g: &mut ExprGraph, t: SymTransform) -> SymTransform {
    let cost = |g: &ExprGraph, t: &SymTransform| OpCount::of(g, t.entries()).weighted();
    let mut best = (cost(g, &t), t);
    for replaced in 0..3 {
        let (a, b) = ((replaced + 1) % 3, (replaced + 2) % 3);
        let col = |j: usize| [t.r[0][j], t.r[1][j], t.r[2][j]];
        let (u, v) = (col(a), col(b));
        let mut candidate = t;
        for i in 0..3 {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let (x, y) = (g.mul(u[j], v[k]), g.mul(u[k], v[j]));
            candidate.r[i][replaced] = g.sub(x, y);
        }
        let c = cost(g, &candidate);
        if c < best.0 {
            best = (c, candidate);
        }
    }
    best.1
}
