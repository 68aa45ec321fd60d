//! Vectors, turns and flags over the expression graph: what the subproblems are written with.
//! Every operation goes through the graph's smart constructors, so the chain's constants (axes,
//! offsets, their dot and cross products) fold as the expressions are built, and an expression
//! built twice is one node.
//!
//! Flags are numbers, `1` for true and `0` for false: `and` is a product, `or` and the choice
//! between two values a select ([`Builder::select`]), so one body evaluates every branch in the
//! lanes of a SIMD type without a branch in the code.

use crate::ik::geometry::V3;
use crate::symbolic::graph::{ExprGraph, ExprId};

/// A 3-vector of expressions.
pub(super) type Vector = [ExprId; 3];

/// A 3x3 matrix of expressions, row-major.
pub(super) type Matrix = [[ExprId; 3]; 3];

/// A solved angle with its cosine and sine (the arguments of its `atan2`, normalised, or an
/// angle sum's formula), so rotating by it costs no trigonometric call: the run time's `Turn`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Turn {
    pub angle: ExprId,
    pub cos: ExprId,
    pub sin: ExprId,
}

/// Whether every equation on a branch's way had a real solution, and whether any had a
/// continuum of them: the run time's `Quality`, as flags.
#[derive(Debug, Clone, Copy)]
pub(super) struct Quality {
    pub exact: ExprId,
    pub singular: ExprId,
}

/// The graph being built, with the steps recorded for `kinematics expr --ik`.
#[derive(Debug, Default)]
pub(super) struct Builder {
    pub g: ExprGraph,
    /// Each subproblem solved, in order: its label and the nodes it produced.
    pub steps: Vec<(String, Vec<ExprId>)>,
}

impl Builder {
    pub fn constant(&mut self, x: f64) -> ExprId {
        self.g.constant(x)
    }

    pub fn vector(&mut self, v: V3) -> Vector {
        v.map(|x| self.g.constant(x))
    }

    pub fn add(&mut self, a: ExprId, b: ExprId) -> ExprId {
        self.g.add(a, b)
    }

    pub fn sub(&mut self, a: ExprId, b: ExprId) -> ExprId {
        self.g.sub(a, b)
    }

    pub fn mul(&mut self, a: ExprId, b: ExprId) -> ExprId {
        self.g.mul(a, b)
    }

    pub fn neg(&mut self, a: ExprId) -> ExprId {
        self.g.neg(a)
    }

    /// `a / b`; by a constant, a product with its reciprocal (a multiplication, where a division
    /// takes several times as long).
    pub fn div(&mut self, a: ExprId, b: ExprId) -> ExprId {
        match self.g.as_const(b) {
            Some(k) if k != 0.0 => {
                let reciprocal = self.g.constant(1.0 / k);
                self.g.mul(a, reciprocal)
            }
            _ => self.g.div(a, b),
        }
    }

    pub fn sqrt(&mut self, a: ExprId) -> ExprId {
        self.g.sqrt(a)
    }

    /// `then` where `condition > 0`, else `otherwise`.
    pub fn select(&mut self, condition: ExprId, then: ExprId, otherwise: ExprId) -> ExprId {
        self.g.if_positive(condition, then, otherwise)
    }

    /// `|a|`.
    pub fn abs(&mut self, a: ExprId) -> ExprId {
        let minus = self.g.neg(a);
        self.g.if_positive(a, a, minus)
    }

    /// The flag `a <= b`.
    pub fn at_most(&mut self, a: ExprId, b: ExprId) -> ExprId {
        let over = self.g.sub(a, b);
        let (zero, one) = (self.g.constant(0.0), self.g.constant(1.0));
        self.g.if_positive(over, zero, one)
    }

    /// The flag `x` and `y`.
    pub fn and(&mut self, x: ExprId, y: ExprId) -> ExprId {
        self.g.mul(x, y)
    }

    /// The flag `x` or `y`.
    pub fn or(&mut self, x: ExprId, y: ExprId) -> ExprId {
        let one = self.g.constant(1.0);
        self.g.if_positive(x, one, y)
    }

    /// `a + b + c`, summed left to right as the run time's vector code sums.
    fn sum3(&mut self, [a, b, c]: [ExprId; 3]) -> ExprId {
        let ab = self.g.add(a, b);
        self.g.add(ab, c)
    }

    pub fn dot(&mut self, a: Vector, b: Vector) -> ExprId {
        let products = [0, 1, 2].map(|i| self.g.mul(a[i], b[i]));
        self.sum3(products)
    }

    pub fn cross(&mut self, a: Vector, b: Vector) -> Vector {
        [0, 1, 2].map(|i| {
            let (j, k) = ((i + 1) % 3, (i + 2) % 3);
            let x = self.g.mul(a[j], b[k]);
            let y = self.g.mul(a[k], b[j]);
            self.g.sub(x, y)
        })
    }

    pub fn vadd(&mut self, a: Vector, b: Vector) -> Vector {
        [0, 1, 2].map(|i| self.g.add(a[i], b[i]))
    }

    pub fn vsub(&mut self, a: Vector, b: Vector) -> Vector {
        [0, 1, 2].map(|i| self.g.sub(a[i], b[i]))
    }

    pub fn scale(&mut self, a: Vector, s: ExprId) -> Vector {
        a.map(|x| self.g.mul(x, s))
    }

    pub fn norm_squared(&mut self, a: Vector) -> ExprId {
        self.dot(a, a)
    }

    /// `m v`.
    pub fn mul_vector(&mut self, m: &Matrix, v: Vector) -> Vector {
        [0, 1, 2].map(|i| self.dot(m[i], v))
    }

    /// `m^T v`.
    pub fn mul_transposed(&mut self, m: &Matrix, v: Vector) -> Vector {
        [0, 1, 2].map(|j| {
            let products = [0, 1, 2].map(|i| self.g.mul(m[i][j], v[i]));
            self.sum3(products)
        })
    }

    /// `v` rotated by `turn` about the unit axis `k`: its part along the axis kept, the part across
    /// it turned, `(k . v) k + c (v - (k . v) k) + s (k x v)`. For an axis along a coordinate axis
    /// (the usual case) the kept part is one entry, untouched, and the turned part four products:
    /// Rodrigues' `c v + s (k x v) + (1 - c)(k . v) k` would compute the kept entry as
    /// `c x + (1 - c) x`.
    pub fn rotate(&mut self, turn: Turn, k: Vector, v: Vector) -> Vector {
        let kv = self.dot(k, v);
        let along = self.scale(k, kv);
        let across = self.vsub(v, along);
        let kxv = self.cross(k, v);
        [0, 1, 2].map(|i| {
            let a = self.g.mul(turn.cos, across[i]);
            let b = self.g.mul(turn.sin, kxv[i]);
            self.sum3([along[i], a, b])
        })
    }

    /// No turn.
    pub fn zero_turn(&mut self) -> Turn {
        let (zero, one) = (self.g.constant(0.0), self.g.constant(1.0));
        Turn { angle: zero, cos: one, sin: zero }
    }

    /// The opposite turn.
    pub fn back(&mut self, turn: Turn) -> Turn {
        Turn { angle: self.g.neg(turn.angle), cos: turn.cos, sin: self.g.neg(turn.sin) }
    }

    /// `if_true` where the flag is set, else `if_false`, angle, cosine and sine alike.
    pub fn select_turn(&mut self, flag: ExprId, if_true: Turn, if_false: Turn) -> Turn {
        Turn {
            angle: self.g.if_positive(flag, if_true.angle, if_false.angle),
            cos: self.g.if_positive(flag, if_true.cos, if_false.cos),
            sin: self.g.if_positive(flag, if_true.sin, if_false.sin),
        }
    }

    /// The turn by `a + b`, its cosine and sine by the angle-sum formulas.
    pub fn angle_sum(&mut self, a: Turn, b: Turn) -> Turn {
        let (cc, ss) = (self.g.mul(a.cos, b.cos), self.g.mul(a.sin, b.sin));
        let (sc, cs) = (self.g.mul(a.sin, b.cos), self.g.mul(a.cos, b.sin));
        Turn { angle: self.g.add(a.angle, b.angle), cos: self.g.sub(cc, ss), sin: self.g.add(sc, cs) }
    }

    /// The turn by `a - b`, its cosine and sine by the angle-difference formulas.
    pub fn difference(&mut self, a: Turn, b: Turn) -> Turn {
        let minus_b = self.back(b);
        self.angle_sum(a, minus_b)
    }

    /// The turn whose cosine and sine are given (already normalised): its angle by `atan2`.
    pub fn turn(&mut self, cos: ExprId, sin: ExprId) -> Turn {
        Turn { angle: self.g.atan2(sin, cos), cos, sin }
    }

    /// An exact, regular result.
    pub fn exact(&mut self) -> Quality {
        let (zero, one) = (self.g.constant(0.0), self.g.constant(1.0));
        Quality { exact: one, singular: zero }
    }

    /// Both qualities together: exact if both are, singular if either is.
    pub fn both(&mut self, a: Quality, b: Quality) -> Quality {
        Quality { exact: self.and(a.exact, b.exact), singular: self.or(a.singular, b.singular) }
    }

    /// Records a step for `expr --ik`.
    pub fn step(&mut self, label: impl Into<String>, nodes: impl IntoIterator<Item = ExprId>) {
        self.steps.push((label.into(), nodes.into_iter().collect()));
    }
}

impl Turn {
    /// The nodes a step records of it.
    pub fn nodes(self) -> [ExprId; 3] {
        [self.angle, self.cos, self.sin]
    }
}

impl Quality {
    /// The nodes a step records of it.
    pub fn nodes(self) -> [ExprId; 2] {
        [self.exact, self.singular]
    }
}
