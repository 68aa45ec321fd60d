//! The expression graph as the algebra a branch is written in (`kinematics_core::ik::branch`):
//! every operation goes through the graph's smart constructors, so the chain's constants (axes,
//! offsets, their dot and cross products) fold as the expressions are built, and an expression
//! built twice is one node; the steps are recorded for `kinematics expr --ik`.

use kinematics_core::ik::branch::Algebra;

use crate::symbolic::graph::{ExprGraph, ExprId};

/// The graph being built, with the steps recorded for `kinematics expr --ik`.
#[derive(Debug, Default)]
pub(crate) struct Builder {
    pub g: ExprGraph,
    /// Each subproblem solved, in order: its label and the nodes it produced.
    pub steps: Vec<(String, Vec<ExprId>)>,
}

impl Algebra for Builder {
    type Value = ExprId;

    fn constant(&mut self, x: f64) -> ExprId {
        self.g.constant(x)
    }

    fn add(&mut self, a: ExprId, b: ExprId) -> ExprId {
        self.g.add(a, b)
    }

    fn sub(&mut self, a: ExprId, b: ExprId) -> ExprId {
        self.g.sub(a, b)
    }

    fn mul(&mut self, a: ExprId, b: ExprId) -> ExprId {
        self.g.mul(a, b)
    }

    fn neg(&mut self, a: ExprId) -> ExprId {
        self.g.neg(a)
    }

    /// `a / b`; by a constant, a product with its reciprocal (a multiplication, where a division
    /// takes several times as long).
    fn div(&mut self, a: ExprId, b: ExprId) -> ExprId {
        match self.g.as_const(b) {
            Some(k) if k != 0.0 => {
                let reciprocal = self.g.constant(1.0 / k);
                self.g.mul(a, reciprocal)
            }
            _ => self.g.div(a, b),
        }
    }

    fn sqrt(&mut self, a: ExprId) -> ExprId {
        self.g.sqrt(a)
    }

    fn atan2(&mut self, y: ExprId, x: ExprId) -> ExprId {
        self.g.atan2(y, x)
    }

    fn if_positive(&mut self, condition: ExprId, then: ExprId, otherwise: ExprId) -> ExprId {
        self.g.if_positive(condition, then, otherwise)
    }

    fn step(&mut self, label: &'static str, nodes: impl IntoIterator<Item = ExprId>) {
        self.steps.push((label.to_string(), nodes.into_iter().collect()));
    }
}
