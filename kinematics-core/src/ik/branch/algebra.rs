//! What a branch is written with: an [`Algebra`]'s few operations on its values, and, built on
//! them once for every algebra, vectors, turns and flags.
//!
//! No method takes a closure of the algebra (such as `array::map`'s): on numbers in lanes each
//! would be a function LLVM may leave uninlined, and run outside the caller's instruction set.
//!
//! Flags are values, `1` for true and `0` for false: `and` is a product, `or` and the choice
//! between two values a select ([`Algebra::if_positive`]), so one branch evaluates every other
//! branch in the lanes of a SIMD type without a branch in the code. The order of the operations
//! in each method is part of its meaning for the compiler's algebra, which emits them in that
//! order: a change here changes the generated code.

/// A 3-vector of values.
pub type Vector<V> = [V; 3];

/// A 3x3 matrix of values, row-major.
pub type Matrix<V> = [[V; 3]; 3];

/// A solved angle with its cosine and sine (the arguments of its `atan2`, normalised, or an angle
/// sum's formula), so rotating by it costs no trigonometric call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Turn<V> {
    /// The angle.
    pub angle: V,
    /// Its cosine.
    pub cos: V,
    /// Its sine.
    pub sin: V,
}

/// Whether every equation on a branch's way had a real solution, and whether any had a continuum
/// of them, as values (`1` true, `0` false).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Flags<V> {
    /// `1` where every equation had a real solution (else the least-squares best was taken).
    pub exact: V,
    /// `1` where some equation had a continuum of solutions (a singularity).
    pub singular: V,
}

impl<V: Copy> Turn<V> {
    /// The values a step records of it.
    pub fn nodes(self) -> [V; 3] {
        [self.angle, self.cos, self.sin]
    }
}

impl<V: Copy> Flags<V> {
    /// The values a step records of it.
    pub fn nodes(self) -> [V; 2] {
        [self.exact, self.singular]
    }
}

/// The arithmetic a branch is written in: numbers that compute ([`super::Numbers`]) or the
/// compiler's expression graph, whose values are nodes and whose constants fold as they are
/// built. The required methods are the primitive operations; the provided ones are written on
/// them here, once.
pub trait Algebra {
    /// A value: a number, a lane of numbers, or a node of a graph.
    type Value: Copy;

    /// A constant.
    fn constant(&mut self, x: f64) -> Self::Value;
    /// `a + b`.
    fn add(&mut self, a: Self::Value, b: Self::Value) -> Self::Value;
    /// `a - b`.
    fn sub(&mut self, a: Self::Value, b: Self::Value) -> Self::Value;
    /// `a b`.
    fn mul(&mut self, a: Self::Value, b: Self::Value) -> Self::Value;
    /// `-a`.
    fn neg(&mut self, a: Self::Value) -> Self::Value;
    /// `a / b`.
    fn div(&mut self, a: Self::Value, b: Self::Value) -> Self::Value;
    /// The square root (the callers clamp first: never of a negative value).
    fn sqrt(&mut self, a: Self::Value) -> Self::Value;
    /// `atan2(y, x)`, in `[-pi, pi]`.
    fn atan2(&mut self, y: Self::Value, x: Self::Value) -> Self::Value;
    /// `then` where `condition > 0`, else `otherwise` (a select, not a branch).
    fn if_positive(&mut self, condition: Self::Value, then: Self::Value, otherwise: Self::Value) -> Self::Value;

    /// Records a step (a subproblem solved, and the values it produced), for the compiler's
    /// per-subproblem operation counts; numbers ignore it.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn step(&mut self, label: &'static str, nodes: impl IntoIterator<Item = Self::Value>) {
        let _ = (label, nodes);
    }

    /// A vector of constants.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn vector(&mut self, v: [f64; 3]) -> Vector<Self::Value> {
        [self.constant(v[0]), self.constant(v[1]), self.constant(v[2])]
    }

    /// `then` where `condition > 0`, else `otherwise`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn select(&mut self, condition: Self::Value, then: Self::Value, otherwise: Self::Value) -> Self::Value {
        self.if_positive(condition, then, otherwise)
    }

    /// `|a|`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn abs(&mut self, a: Self::Value) -> Self::Value {
        let minus = self.neg(a);
        self.if_positive(a, a, minus)
    }

    /// The flag `a <= b`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn at_most(&mut self, a: Self::Value, b: Self::Value) -> Self::Value {
        let over = self.sub(a, b);
        let (zero, one) = (self.constant(0.0), self.constant(1.0));
        self.if_positive(over, zero, one)
    }

    /// The flag `x` and `y`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn and(&mut self, x: Self::Value, y: Self::Value) -> Self::Value {
        self.mul(x, y)
    }

    /// The flag `x` or `y`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn or(&mut self, x: Self::Value, y: Self::Value) -> Self::Value {
        let one = self.constant(1.0);
        self.if_positive(x, one, y)
    }

    /// `a + b + c`, summed left to right.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sum3(&mut self, [a, b, c]: [Self::Value; 3]) -> Self::Value {
        let ab = self.add(a, b);
        self.add(ab, c)
    }

    /// `a . b`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn dot(&mut self, a: Vector<Self::Value>, b: Vector<Self::Value>) -> Self::Value {
        let products = [self.mul(a[0], b[0]), self.mul(a[1], b[1]), self.mul(a[2], b[2])];
        self.sum3(products)
    }

    /// `a x b`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn cross(&mut self, a: Vector<Self::Value>, b: Vector<Self::Value>) -> Vector<Self::Value> {
        let (x, y) = (self.mul(a[1], b[2]), self.mul(a[2], b[1]));
        let first = self.sub(x, y);
        let (x, y) = (self.mul(a[2], b[0]), self.mul(a[0], b[2]));
        let second = self.sub(x, y);
        let (x, y) = (self.mul(a[0], b[1]), self.mul(a[1], b[0]));
        let third = self.sub(x, y);
        [first, second, third]
    }

    /// `a + b`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn vadd(&mut self, a: Vector<Self::Value>, b: Vector<Self::Value>) -> Vector<Self::Value> {
        [self.add(a[0], b[0]), self.add(a[1], b[1]), self.add(a[2], b[2])]
    }

    /// `a - b`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn vsub(&mut self, a: Vector<Self::Value>, b: Vector<Self::Value>) -> Vector<Self::Value> {
        [self.sub(a[0], b[0]), self.sub(a[1], b[1]), self.sub(a[2], b[2])]
    }

    /// `s a`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn scale(&mut self, a: Vector<Self::Value>, s: Self::Value) -> Vector<Self::Value> {
        [self.mul(a[0], s), self.mul(a[1], s), self.mul(a[2], s)]
    }

    /// `|a|^2`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn norm_squared(&mut self, a: Vector<Self::Value>) -> Self::Value {
        self.dot(a, a)
    }

    /// `m v`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn mul_vector(&mut self, m: &Matrix<Self::Value>, v: Vector<Self::Value>) -> Vector<Self::Value> {
        [self.dot(m[0], v), self.dot(m[1], v), self.dot(m[2], v)]
    }

    /// `m^T v`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn mul_transposed(&mut self, m: &Matrix<Self::Value>, v: Vector<Self::Value>) -> Vector<Self::Value> {
        let column = |j: usize| [m[0][j], m[1][j], m[2][j]];
        [self.dot(column(0), v), self.dot(column(1), v), self.dot(column(2), v)]
    }

    /// `v` rotated by `turn` about the unit axis `k`: its part along the axis kept, the part across
    /// it turned, `(k . v) k + c (v - (k . v) k) + s (k x v)`. For an axis along a coordinate axis
    /// (the usual case) the kept part is one entry, untouched, and the turned part four products:
    /// Rodrigues' `c v + s (k x v) + (1 - c)(k . v) k` would compute the kept entry as
    /// `c x + (1 - c) x`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn rotate(
        &mut self,
        turn: Turn<Self::Value>,
        k: Vector<Self::Value>,
        v: Vector<Self::Value>,
    ) -> Vector<Self::Value> {
        let kv = self.dot(k, v);
        let along = self.scale(k, kv);
        let across = self.vsub(v, along);
        let kxv = self.cross(k, v);
        let mut out = along;
        for i in 0..3 {
            let a = self.mul(turn.cos, across[i]);
            let b = self.mul(turn.sin, kxv[i]);
            out[i] = self.sum3([along[i], a, b]);
        }
        out
    }

    /// No turn.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn zero_turn(&mut self) -> Turn<Self::Value> {
        let (zero, one) = (self.constant(0.0), self.constant(1.0));
        Turn { angle: zero, cos: one, sin: zero }
    }

    /// The opposite turn.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn back(&mut self, turn: Turn<Self::Value>) -> Turn<Self::Value> {
        Turn { angle: self.neg(turn.angle), cos: turn.cos, sin: self.neg(turn.sin) }
    }

    /// `if_true` where the flag is set, else `if_false`, angle, cosine and sine alike.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn select_turn(
        &mut self,
        flag: Self::Value,
        if_true: Turn<Self::Value>,
        if_false: Turn<Self::Value>,
    ) -> Turn<Self::Value> {
        Turn {
            angle: self.if_positive(flag, if_true.angle, if_false.angle),
            cos: self.if_positive(flag, if_true.cos, if_false.cos),
            sin: self.if_positive(flag, if_true.sin, if_false.sin),
        }
    }

    /// The turn by `a + b`, its cosine and sine by the angle-sum formulas.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn angle_sum(&mut self, a: Turn<Self::Value>, b: Turn<Self::Value>) -> Turn<Self::Value> {
        let (cc, ss) = (self.mul(a.cos, b.cos), self.mul(a.sin, b.sin));
        let (sc, cs) = (self.mul(a.sin, b.cos), self.mul(a.cos, b.sin));
        Turn { angle: self.add(a.angle, b.angle), cos: self.sub(cc, ss), sin: self.add(sc, cs) }
    }

    /// The turn by `a - b`, its cosine and sine by the angle-difference formulas.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn difference(&mut self, a: Turn<Self::Value>, b: Turn<Self::Value>) -> Turn<Self::Value> {
        let minus_b = self.back(b);
        self.angle_sum(a, minus_b)
    }

    /// The turn whose cosine and sine are given (already normalised): its angle by `atan2`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn turn(&mut self, cos: Self::Value, sin: Self::Value) -> Turn<Self::Value> {
        Turn { angle: self.atan2(sin, cos), cos, sin }
    }

    /// An exact, regular result.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn exact(&mut self) -> Flags<Self::Value> {
        let (zero, one) = (self.constant(0.0), self.constant(1.0));
        Flags { exact: one, singular: zero }
    }

    /// Both results together: exact if both are, singular if either is.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn both(&mut self, a: Flags<Self::Value>, b: Flags<Self::Value>) -> Flags<Self::Value> {
        Flags { exact: self.and(a.exact, b.exact), singular: self.or(a.singular, b.singular) }
    }
}
