//! Operation counts of compiled expressions.

use std::collections::BTreeSet;
use std::fmt;

use crate::symbolic::graph::{ExprGraph, ExprId, Node};

/// What evaluating a set of expressions costs at run time.
///
/// Multiplications include those by constants; a negation is free (it folds into the sum that uses
/// it); additions include subtractions and the angle sums such as `q2 + q3`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct OpCount {
    /// Distinct angles whose sine or cosine is needed: one `sin_cos` call each.
    pub sin_cos: usize,
    /// Multiplications.
    pub mul: usize,
    /// Additions and subtractions.
    pub add: usize,
}

impl OpCount {
    /// Counts the nodes reachable from `outputs`.
    pub fn of(g: &ExprGraph, outputs: impl IntoIterator<Item = ExprId>) -> Self {
        let reachable = reachable(g, outputs);
        let mut count = OpCount::default();
        let mut angles = BTreeSet::new();
        for &id in &reachable {
            match g.node(id) {
                Node::Mul(..) => count.mul += 1,
                Node::Add(..) => count.add += 1,
                Node::Sin(a) | Node::Cos(a) => {
                    angles.insert(a);
                }
                _ => {}
            }
        }
        count.sin_cos = angles.len();
        count
    }
}

/// What each group of outputs adds to the groups before it: the nodes reachable from a group that
/// no earlier group reaches (a shared subexpression, or a `sin_cos` pair, counts for the first group
/// that needs it). The counts add up to [`OpCount::of`] all the groups together, so they say where
/// the cost of a set of poses goes (`kinematics expr --all` prints them per link).
pub fn marginal_counts<I>(g: &ExprGraph, groups: impl IntoIterator<Item = I>) -> Vec<OpCount>
where
    I: IntoIterator<Item = ExprId>,
{
    let mut seen = vec![false; g.len()];
    let mut angles = BTreeSet::new();
    let mut counts = Vec::new();
    for group in groups {
        let mut count = OpCount::default();
        let mut stack: Vec<ExprId> = group.into_iter().collect();
        while let Some(id) = stack.pop() {
            if std::mem::replace(&mut seen[id.index()], true) {
                continue;
            }
            match g.node(id) {
                Node::Mul(a, b) => {
                    count.mul += 1;
                    stack.extend([a, b]);
                }
                Node::Add(a, b) => {
                    count.add += 1;
                    stack.extend([a, b]);
                }
                Node::Sin(a) | Node::Cos(a) => {
                    if angles.insert(a) {
                        count.sin_cos += 1;
                    }
                    stack.push(a);
                }
                Node::Neg(a) => stack.push(a),
                Node::Const(_) | Node::Var(_) => {}
            }
        }
        counts.push(count);
    }
    counts
}

/// What one `sin_cos` costs in multiplications or additions, for choosing between forms: about
/// 20 ns against well under a nanosecond for a multiply-add on the machines we measured.
pub const SIN_COS_WEIGHT: usize = 40;

impl OpCount {
    /// One number to compare forms by: sines and cosines weighted by [`SIN_COS_WEIGHT`], plus every
    /// multiplication and addition.
    pub fn weighted(&self) -> usize {
        self.sin_cos * SIN_COS_WEIGHT + self.mul + self.add
    }
}

impl fmt::Display for OpCount {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} sin/cos pairs, {} multiplications, {} additions", self.sin_cos, self.mul, self.add)
    }
}

/// Every node reachable from `outputs`, in id order (children before parents).
pub fn reachable(g: &ExprGraph, outputs: impl IntoIterator<Item = ExprId>) -> Vec<ExprId> {
    let mut seen = vec![false; g.len()];
    let mut stack: Vec<ExprId> = outputs.into_iter().collect();
    while let Some(id) = stack.pop() {
        if std::mem::replace(&mut seen[id.index()], true) {
            continue;
        }
        match g.node(id) {
            Node::Sin(a) | Node::Cos(a) | Node::Neg(a) => stack.push(a),
            Node::Add(a, b) | Node::Mul(a, b) => {
                stack.push(a);
                stack.push(b);
            }
            Node::Const(_) | Node::Var(_) => {}
        }
    }
    seen.iter().enumerate().filter(|(_, s)| **s).map(|(i, _)| g.id(i)).collect()
}
