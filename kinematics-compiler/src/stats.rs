//! Operation counts of compiled expressions.
//!
//! Divisions, square roots, `atan2` and selects are counted beside the forward kinematics'
//! operations. `marginal_counts` is what each pose adds to the poses before it
//! (`Compiled::marginal_op_counts`, printed per link by `kinematics expr --all`).

use std::collections::BTreeSet;
use std::fmt;

use crate::symbolic::graph::{ExprGraph, ExprId, Node};

/// What evaluating a set of expressions costs at run time.
///
/// Multiplications include those by constants; a negation is free (it folds into the sum that uses
/// it); additions include subtractions and the angle sums such as `q2 + q3`. Divisions, square
/// roots, `atan2` calls and selects appear only in inverse kinematics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct OpCount {
    /// Distinct angles whose sine or cosine is needed: one `sin_cos` call each.
    pub sin_cos: usize,
    /// Multiplications.
    pub mul: usize,
    /// Additions and subtractions.
    pub add: usize,
    /// Divisions.
    pub div: usize,
    /// Square roots.
    pub sqrt: usize,
    /// `atan2` calls.
    pub atan2: usize,
    /// Selects (`if_positive`).
    pub select: usize,
}

impl OpCount {
    /// Counts one arithmetic node (sines and cosines count per angle, by the caller).
    fn count(&mut self, node: Node) {
        match node {
            Node::Mul(..) => self.mul += 1,
            Node::Add(..) => self.add += 1,
            Node::Div(..) => self.div += 1,
            Node::Sqrt(_) => self.sqrt += 1,
            Node::Atan2(..) => self.atan2 += 1,
            Node::IfPositive(..) => self.select += 1,
            Node::Const(_) | Node::Var(_) | Node::Input(_) | Node::Neg(_) | Node::Sin(_) | Node::Cos(_) => {}
        }
    }

    /// Counts the nodes reachable from `outputs`.
    pub fn of(g: &ExprGraph, outputs: impl IntoIterator<Item = ExprId>) -> Self {
        let reachable = reachable(g, outputs);
        let mut count = OpCount::default();
        let mut angles = BTreeSet::new();
        for &id in &reachable {
            match g.node(id) {
                Node::Sin(a) | Node::Cos(a) => {
                    angles.insert(a);
                }
                node => count.count(node),
            }
        }
        count.sin_cos = angles.len();
        count
    }
}

/// The nodes and `sin_cos` angles a set of outputs already computes, and what more outputs would
/// add to them: the cost of one more pose given the poses before it.
#[derive(Debug, Clone, Default)]
pub struct Reached {
    seen: Vec<bool>,
    angles: BTreeSet<ExprId>,
}

impl Reached {
    /// Nothing reached yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// What `outputs` cost beyond the nodes already reached, and the angles they need that were
    /// not reached (nothing is recorded).
    pub fn cost_of(&self, g: &ExprGraph, outputs: impl IntoIterator<Item = ExprId>) -> (OpCount, BTreeSet<ExprId>) {
        let mut visited = rustc_hash::FxHashSet::default();
        let mut angles = BTreeSet::new();
        let count = self.walk(g, outputs, |id| visited.insert(id), |a| angles.insert(a));
        (count, angles)
    }

    /// Records `outputs` as reached and returns what they added.
    pub fn add(&mut self, g: &ExprGraph, outputs: impl IntoIterator<Item = ExprId>) -> OpCount {
        self.add_angles(g, outputs).0
    }

    /// [`Reached::add`], with the angles the outputs added (in the order first met).
    pub fn add_angles(&mut self, g: &ExprGraph, outputs: impl IntoIterator<Item = ExprId>) -> (OpCount, Vec<ExprId>) {
        let mut seen = std::mem::take(&mut self.seen);
        let mut angles = std::mem::take(&mut self.angles);
        let mut added = Vec::new();
        seen.resize(g.len(), false);
        let count = self.walk(
            g,
            outputs,
            |id| !std::mem::replace(&mut seen[id.index()], true),
            |a| {
                angles.insert(a) && {
                    added.push(a);
                    true
                }
            },
        );
        (self.seen, self.angles) = (seen, angles);
        (count, added)
    }

    /// Counts the nodes reachable from `outputs` through nodes not reached before, visiting each
    /// once (`first_visit` says whether a node is new to this walk); an angle counts when neither
    /// this set nor the walk (`new_angle`) had it.
    fn walk(
        &self,
        g: &ExprGraph,
        outputs: impl IntoIterator<Item = ExprId>,
        mut first_visit: impl FnMut(ExprId) -> bool,
        mut new_angle: impl FnMut(ExprId) -> bool,
    ) -> OpCount {
        let mut count = OpCount::default();
        let mut stack: Vec<ExprId> = outputs.into_iter().collect();
        while let Some(id) = stack.pop() {
            if self.seen.get(id.index()).copied().unwrap_or(false) || !first_visit(id) {
                continue;
            }
            match g.node(id) {
                Node::Sin(a) | Node::Cos(a) => {
                    if !self.angles.contains(&a) && new_angle(a) {
                        count.sin_cos += 1;
                    }
                    stack.push(a);
                }
                node => {
                    count.count(node);
                    stack.extend(node.operands());
                }
            }
        }
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
    let mut reached = Reached::new();
    groups.into_iter().map(|group| reached.add(g, group)).collect()
}

/// What one `sin_cos` costs in multiplications or additions, for choosing between forms: about
/// 20 ns against well under a nanosecond for a multiply-add on the machines we measured.
pub const SIN_COS_WEIGHT: usize = 40;

/// What a division or a square root costs against a multiply-add (their latency, about four
/// times a multiplication's on the machines we measured).
pub const ROOT_WEIGHT: usize = 4;

/// What one `atan2` costs against a multiply-add (ours: one division and a polynomial of 11
/// terms).
pub const ATAN2_WEIGHT: usize = 20;

impl OpCount {
    /// One number to compare forms by: sines and cosines weighted by `SIN_COS_WEIGHT`, plus every
    /// multiplication and addition.
    pub fn weighted(&self) -> usize {
        self.sin_cos * SIN_COS_WEIGHT
            + self.mul
            + self.add
            + ROOT_WEIGHT * (self.div + self.sqrt)
            + self.select
            + ATAN2_WEIGHT * self.atan2
    }
}

/// Counts added field by field (the cost of two computations that share nothing).
impl std::ops::Add for OpCount {
    type Output = OpCount;
    fn add(self, other: OpCount) -> OpCount {
        OpCount {
            sin_cos: self.sin_cos + other.sin_cos,
            mul: self.mul + other.mul,
            add: self.add + other.add,
            div: self.div + other.div,
            sqrt: self.sqrt + other.sqrt,
            atan2: self.atan2 + other.atan2,
            select: self.select + other.select,
        }
    }
}

impl fmt::Display for OpCount {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} sin/cos pairs, {} multiplications, {} additions", self.sin_cos, self.mul, self.add)?;
        for (count, what) in
            [(self.div, "divisions"), (self.sqrt, "square roots"), (self.atan2, "atan2"), (self.select, "selects")]
        {
            if count > 0 {
                write!(f, ", {count} {what}")?;
            }
        }
        Ok(())
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
        stack.extend(g.node(id).operands());
    }
    seen.iter().enumerate().filter(|(_, s)| **s).map(|(i, _)| g.id(i)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `a*b` for the first group, `a*b + c` and `sin(q1)` for the second: the shared product
    /// counts once, for the first group; an angle counts once, for the first group needing it.
    #[test]
    fn marginal_counts_charge_shared_work_to_the_first_user() {
        let mut g = ExprGraph::new();
        let (a, b, c) = (g.var(0), g.var(1), g.var(2));
        let ab = g.mul(a, b);
        let sum = g.add(ab, c);
        let (s, co) = (g.sin(a), g.cos(a));
        let counts = marginal_counts(&g, [vec![ab, s], vec![sum, co], vec![ab]]);
        let count = |sin_cos, mul, add| OpCount { sin_cos, mul, add, ..OpCount::default() };
        assert_eq!(counts, vec![count(1, 1, 0), count(0, 0, 1), count(0, 0, 0)]);
        assert_eq!(OpCount::of(&g, [ab, s, sum, co]), count(1, 1, 1));
        // What a group would add is not recorded until it is added.
        let mut reached = Reached::new();
        reached.add(&g, [ab]);
        let (would, angles) = reached.cost_of(&g, [sum, s]);
        assert_eq!((would, angles.len()), (count(1, 0, 1), 1));
        assert_eq!(reached.add(&g, [sum, s]), count(1, 0, 1));
        assert_eq!(reached.add(&g, [sum, co]), count(0, 0, 0));
    }
}
