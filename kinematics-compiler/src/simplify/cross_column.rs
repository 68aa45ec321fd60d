//! Rule `cross-column`: a rotation column as the cross product of the other two.

use crate::stats::OpCount;
use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::transform::SymTransform;

use super::ExprPass;

/// Pass `cross-column`: for a single pose whose rotation is an output, the column cheapest to
/// derive from the other two becomes their cross product, when that saves work.
pub const CROSS_COLUMN: ExprPass = ExprPass { name: "cross-column", run: cross_column };

fn cross_column(g: &mut ExprGraph, frames: &mut [SymTransform], extra: &mut [ExprId], position_only: bool) {
    // A single pose with no further outputs only: the cost below is measured on that pose alone.
    if let [t] = frames
        && extra.is_empty()
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

#[cfg(test)]
mod tests {
    use super::super::testing::check_frames;
    use super::*;

    /// Columns `(0, 0, sin(q3))`, `(q1, q4, 0)`, `(q2, q5, 0)`: the first costs a `sin_cos`, the
    /// cross product of the other two `q1*q5 - q2*q4`.
    const COSTLY_FIRST_COLUMN: &str = "[0, q1, q2, 0, q4, q5, sin(q3), 0, 0; q6, 0, 0]";

    #[test]
    fn cross_column() {
        let check = |input: &[&str], expected: &[&str]| check_frames(&CROSS_COLUMN, false, input, expected);
        check(&[COSTLY_FIRST_COLUMN], &["[0, q1, q2, 0, q4, q5, q1*q5 - q2*q4, 0, 0; q6, 0, 0]"]);
        // c1 = c2 x c0 and c2 = c0 x c1: the same columns in other places.
        check(
            &["[q2, sin(q3), q1, q5, 0, q4, 0, 0, 0; 0, 0, 0]"],
            &["[q2, 0, q1, q5, 0, q4, 0, q1*q5 - q2*q4, 0; 0, 0, 0]"],
        );
        check(
            &["[q1, q2, sin(q3), q4, q5, 0, 0, 0, 0; 0, 0, 0]"],
            &["[q1, q2, 0, q4, q5, 0, 0, 0, q1*q5 - q2*q4; 0, 0, 0]"],
        );
        // Cheaper as it is: stays.
        let rz = "[cos(q1), -sin(q1), 0, sin(q1), cos(q1), 0, 0, 0, 1; q2, 0, 0]";
        check(&[rz], &[rz]);
        let rz_rx = "[cos(q1), -sin(q1)*cos(q2), sin(q1)*sin(q2), sin(q1), cos(q1)*cos(q2), -cos(q1)*sin(q2), 0, sin(q2), cos(q2); 0, 0, 0]";
        check(&[rz_rx], &[rz_rx]);
        // Only for one pose whose rotation is wanted.
        check(&[COSTLY_FIRST_COLUMN, COSTLY_FIRST_COLUMN], &[COSTLY_FIRST_COLUMN, COSTLY_FIRST_COLUMN]);
        check_frames(&CROSS_COLUMN, true, &[COSTLY_FIRST_COLUMN], &[COSTLY_FIRST_COLUMN]);
    }
}
