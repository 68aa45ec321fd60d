//! The expression graph: a hash-consed arena of scalar expressions over the joint variables.
//!
//! Nodes are canonical when built: constants fold, `0` and `+-1` vanish from sums and products,
//! negations are pulled out of products (so `a*b` and `-a*b` share `a*b`, and a negation costs
//! nothing), operands of `+` and `*` are ordered by id, and `sin^2 x + cos^2 x` is `1`. Equal
//! nodes get equal ids (the `memo` map), so common subexpressions are shared as they are built.
//! Children are always older than their parents: ids are a topological order.
//!
//! The graph is an arena of `Node`s indexed by `ExprId`, with the memo map; canonicalisation
//! happens at construction, not in passes. The forward kinematics' nodes are constants, joint
//! variables, sines, cosines, sums, products and negations; the inverse kinematics adds inputs,
//! quotients, square roots, `atan2` and selects, folded the same way (a constant `atan2` by the
//! core's own).

use rustc_hash::FxHashMap;

/// Index of a node in an [`ExprGraph`]. Smaller ids are older; children precede parents.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ExprId(u32);

impl ExprId {
    /// The index into the arena.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A finite `f64` as a hashable key; `-0.0` is stored as `0.0`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Const(u64);

impl Const {
    fn new(value: f64) -> Self {
        Const(if value == 0.0 { 0.0f64.to_bits() } else { value.to_bits() })
    }

    /// The value.
    pub fn value(self) -> f64 {
        f64::from_bits(self.0)
    }
}

/// One node of the graph.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Node {
    /// A constant.
    Const(Const),
    /// The joint variable `q[i]`.
    Var(u32),
    /// `sin` of a node.
    Sin(ExprId),
    /// `cos` of a node.
    Cos(ExprId),
    /// Sum (operands ordered by id).
    Add(ExprId, ExprId),
    /// Product (operands ordered by id).
    Mul(ExprId, ExprId),
    /// Negation (free at run time: it folds into the surrounding sum).
    Neg(ExprId),
    /// A run-time input that is no joint variable: an inverse kinematics body's target entries
    /// and branch signs, named by whoever emits the graph. (The nodes from here on appear only in
    /// inverse kinematics.)
    Input(u32),
    /// Quotient.
    Div(ExprId, ExprId),
    /// Square root.
    Sqrt(ExprId),
    /// `atan2(y, x)`, the angle of `(x, y)`.
    Atan2(ExprId, ExprId),
    /// `then` where `condition > 0`, else `otherwise` (a select: both are computed).
    IfPositive(ExprId, ExprId, ExprId),
}

impl Node {
    /// The node's operands, in order.
    pub fn operands(self) -> impl Iterator<Item = ExprId> {
        let none = ExprId(0);
        let (list, len) = match self {
            Node::Const(_) | Node::Var(_) | Node::Input(_) => ([none; 3], 0),
            Node::Sin(a) | Node::Cos(a) | Node::Neg(a) | Node::Sqrt(a) => ([a, none, none], 1),
            Node::Add(a, b) | Node::Mul(a, b) | Node::Div(a, b) | Node::Atan2(a, b) => ([a, b, none], 2),
            Node::IfPositive(c, a, b) => ([c, a, b], 3),
        };
        list.into_iter().take(len)
    }
}

/// A hash-consed arena of expressions.
#[derive(Debug, Clone, Default)]
pub struct ExprGraph {
    nodes: Vec<Node>,
    memo: FxHashMap<Node, ExprId>,
}

impl ExprGraph {
    /// An empty graph.
    pub fn new() -> Self {
        Self::default()
    }

    /// The id of the node at arena index `index`.
    ///
    /// # Panics
    ///
    /// If `index` is not below [`ExprGraph::len`] (a caller's bug: ids come from this graph).
    #[allow(clippy::panic, reason = "an id outside the arena is a bug of the caller, named in the message")]
    pub fn id(&self, index: usize) -> ExprId {
        if index >= self.nodes.len() {
            panic!("node index {index} is outside the graph ({} nodes)", self.nodes.len());
        }
        ExprId(Self::index_u32(index))
    }

    /// An arena index as the `u32` an id holds.
    #[allow(clippy::expect_used, reason = "an invariant of the arena, named in the message")]
    fn index_u32(index: usize) -> u32 {
        // A node takes 16 bytes and its memo entry more: 2^32 of them would need over 100 GB, so
        // no graph that fits in memory reaches this.
        u32::try_from(index).expect("the expression graph holds fewer than 2^32 nodes")
    }

    /// The node with this id.
    pub fn node(&self, id: ExprId) -> Node {
        self.nodes[id.index()]
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether the graph has no nodes.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    fn intern(&mut self, node: Node) -> ExprId {
        if let Some(&id) = self.memo.get(&node) {
            return id;
        }
        let id = ExprId(Self::index_u32(self.nodes.len()));
        self.nodes.push(node);
        self.memo.insert(node, id);
        id
    }

    /// A constant (must be finite; the model guarantees it).
    pub fn constant(&mut self, value: f64) -> ExprId {
        self.intern(Node::Const(Const::new(value)))
    }

    /// The value of a constant node.
    pub fn as_const(&self, id: ExprId) -> Option<f64> {
        match self.node(id) {
            Node::Const(c) => Some(c.value()),
            _ => None,
        }
    }

    /// Whether `id` is the constant `value`.
    pub fn is_const(&self, id: ExprId, value: f64) -> bool {
        self.as_const(id) == Some(value)
    }

    /// The joint variable `q[index]`.
    pub fn var(&mut self, index: usize) -> ExprId {
        // A degree of freedom is a joint of the model: fewer than 2^32 of them fit in memory.
        self.intern(Node::Var(Self::index_u32(index)))
    }

    /// `-a` (rule `neg-neg`, `neg-const`).
    pub fn neg(&mut self, a: ExprId) -> ExprId {
        match self.node(a) {
            Node::Const(c) => self.constant(-c.value()),
            Node::Neg(inner) => inner,
            _ => self.intern(Node::Neg(a)),
        }
    }

    /// Splits off a negation: `(true, x)` for `-x`, `(false, a)` otherwise.
    pub fn unneg(&self, a: ExprId) -> (bool, ExprId) {
        match self.node(a) {
            Node::Neg(inner) => (true, inner),
            _ => (false, a),
        }
    }

    /// `a + b` (rules `add-const`, `add-zero`, `neg-sum`, `pythagoras`).
    pub fn add(&mut self, a: ExprId, b: ExprId) -> ExprId {
        match (self.as_const(a), self.as_const(b)) {
            (Some(x), Some(y)) => return self.constant(x + y),
            (Some(0.0), None) => return b,
            (None, Some(0.0)) => return a,
            _ => {}
        }
        let (na, ia) = self.unneg(a);
        let (nb, ib) = self.unneg(b);
        if na && nb {
            let sum = self.add(ia, ib);
            return self.neg(sum);
        }
        if ia == ib && na != nb {
            return self.constant(0.0);
        }
        if !na && !nb && self.is_pythagorean(a, b) {
            return self.constant(1.0);
        }
        let (x, y) = if a <= b { (a, b) } else { (b, a) };
        self.intern(Node::Add(x, y))
    }

    /// `a - b`.
    pub fn sub(&mut self, a: ExprId, b: ExprId) -> ExprId {
        let nb = self.neg(b);
        self.add(a, nb)
    }

    /// `sin(x)^2 + cos(x)^2` in either order.
    fn is_pythagorean(&self, a: ExprId, b: ExprId) -> bool {
        let square_of = |id: ExprId| match self.node(id) {
            Node::Mul(x, y) if x == y => Some(self.node(x)),
            _ => None,
        };
        match (square_of(a), square_of(b)) {
            (Some(Node::Sin(x)), Some(Node::Cos(y))) | (Some(Node::Cos(x)), Some(Node::Sin(y))) => x == y,
            _ => false,
        }
    }

    /// `a * b` (rules `mul-const`, `mul-zero`, `mul-one`, `neg-product`, `const-assoc`).
    pub fn mul(&mut self, a: ExprId, b: ExprId) -> ExprId {
        match (self.as_const(a), self.as_const(b)) {
            (Some(x), Some(y)) => return self.constant(x * y),
            (Some(x), _) | (_, Some(x)) if x == 0.0 => return self.constant(0.0),
            (Some(1.0), None) => return b,
            (None, Some(1.0)) => return a,
            (Some(-1.0), None) => return self.neg(b),
            (None, Some(-1.0)) => return self.neg(a),
            _ => {}
        }
        let (na, ia) = self.unneg(a);
        let (nb, ib) = self.unneg(b);
        if na || nb {
            let product = self.mul(ia, ib);
            return if na != nb { self.neg(product) } else { product };
        }
        // A negative constant factor becomes a negation, so `k*x` and `-k*x` share `k*x`.
        for (c, other) in [(a, b), (b, a)] {
            if let Some(k) = self.as_const(c) {
                if k < 0.0 {
                    let positive = self.constant(-k);
                    let product = self.mul(positive, other);
                    return self.neg(product);
                }
                // k1 * (k2 * x) = (k1 k2) * x
                if let Node::Mul(x, y) = self.node(other)
                    && let Some(k2) = self.as_const(x)
                {
                    let folded = self.constant(k * k2);
                    return self.mul(folded, y);
                }
            }
        }
        let (x, y) = if a <= b { (a, b) } else { (b, a) };
        self.intern(Node::Mul(x, y))
    }

    /// `sin(a)` (rules `sin-const`, `sin-neg`). A constant folds to its sine as `f64` computes
    /// it, never rounded to a quarter turn's: exact angles are exact before they reach the graph
    /// ([`crate::symbolic::angle::LinearAngle::sin_cos`]).
    pub fn sin(&mut self, a: ExprId) -> ExprId {
        if let Some(x) = self.as_const(a) {
            return self.constant(x.sin());
        }
        let (negated, inner) = self.unneg(a);
        if negated {
            let s = self.sin(inner);
            return self.neg(s);
        }
        self.intern(Node::Sin(a))
    }

    /// `cos(a)` (rules `cos-const`, `cos-neg`), constants folded as [`ExprGraph::sin`] does.
    pub fn cos(&mut self, a: ExprId) -> ExprId {
        if let Some(x) = self.as_const(a) {
            return self.constant(x.cos());
        }
        let (_, inner) = self.unneg(a);
        self.intern(Node::Cos(inner))
    }

    /// Evaluates `id` at `q`, memoising every node below it in `values` (one slot per node).
    ///
    /// # Panics
    ///
    /// If `q` is shorter than a variable of the expression needs (a caller's bug: the caller
    /// checks `q` against the robot's degrees of freedom), or the expression has an input.
    pub fn eval(&self, id: ExprId, q: &[f64], values: &mut Vec<Option<f64>>) -> f64 {
        self.eval_with_inputs(id, q, &[], values)
    }

    /// [`ExprGraph::eval`] with the values of the inputs ([`Node::Input`]) too. Square roots,
    /// `atan2` and selects evaluate as the generated code's `f64` does (`kinematics_core`'s
    /// `atan2`), so values agree with it bit for bit where the operations are the same.
    ///
    /// # Panics
    ///
    /// If `q` or `inputs` is shorter than a variable or an input of the expression needs (a
    /// caller's bug).
    pub fn eval_with_inputs(&self, id: ExprId, q: &[f64], inputs: &[f64], values: &mut Vec<Option<f64>>) -> f64 {
        values.resize(self.nodes.len(), None);
        if let Some(v) = values[id.index()] {
            return v;
        }
        let v = Self::value(self.node(id), q, inputs, |a| self.eval_with_inputs(a, q, inputs, values));
        values[id.index()] = Some(v);
        v
    }

    /// Evaluates every node of `order` (ids with each node's operands before it, as
    /// the compiler's `stats::reachable` lists them) at `q` and `inputs`, into `values` (one slot per
    /// node of the graph): the values [`ExprGraph::eval_with_inputs`] gives, bit for bit, without
    /// its recursion or its memo's checks, for callers that evaluate the same nodes at many
    /// configurations.
    ///
    /// # Panics
    ///
    /// If `values` is shorter than the graph, or `q` or `inputs` shorter than a variable or an
    /// input needs (callers' bugs).
    pub fn eval_in_order(&self, order: &[ExprId], q: &[f64], inputs: &[f64], values: &mut [f64]) {
        for &id in order {
            let v = Self::value(self.node(id), q, inputs, |a| values[a.index()]);
            values[id.index()] = v;
        }
    }

    /// The value of `node` at `q` and `inputs`, its operands' values given by `at` (each asked once,
    /// in order): the one place the evaluators say what a node computes.
    fn value(node: Node, q: &[f64], inputs: &[f64], mut at: impl FnMut(ExprId) -> f64) -> f64 {
        match node {
            Node::Const(c) => c.value(),
            Node::Var(i) => q[i as usize],
            Node::Input(i) => inputs[i as usize],
            Node::Sin(a) => at(a).sin(),
            Node::Cos(a) => at(a).cos(),
            Node::Add(a, b) => at(a) + at(b),
            Node::Mul(a, b) => at(a) * at(b),
            Node::Div(a, b) => at(a) / at(b),
            Node::Neg(a) => -at(a),
            Node::Sqrt(a) => at(a).sqrt(),
            Node::Atan2(y, x) => kinematics_core::trig::atan2(at(y), at(x)),
            Node::IfPositive(c, a, b) => {
                let (c, a, b) = (at(c), at(a), at(b));
                if c > 0.0 { a } else { b }
            }
        }
    }

    /// `node` with each operand replaced by `map` of it, built through the smart constructors (so
    /// it folds and shares as any new node does). A leaf is itself.
    pub fn rebuild(&mut self, node: Node, map: impl Fn(ExprId) -> ExprId) -> ExprId {
        match node {
            Node::Const(c) => self.constant(c.value()),
            Node::Var(i) => self.var(i as usize),
            Node::Input(i) => self.input(i as usize),
            Node::Sin(a) => self.sin(map(a)),
            Node::Cos(a) => self.cos(map(a)),
            Node::Neg(a) => self.neg(map(a)),
            Node::Sqrt(a) => self.sqrt(map(a)),
            Node::Add(a, b) => self.add(map(a), map(b)),
            Node::Mul(a, b) => self.mul(map(a), map(b)),
            Node::Div(a, b) => self.div(map(a), map(b)),
            Node::Atan2(y, x) => self.atan2(map(y), map(x)),
            Node::IfPositive(c, a, b) => self.if_positive(map(c), map(a), map(b)),
        }
    }

    /// A run-time input ([`Node::Input`]).
    pub fn input(&mut self, index: usize) -> ExprId {
        self.intern(Node::Input(Self::index_u32(index)))
    }

    /// `a / b` (rules `div-const`, `div-one`, `div-zero`, `neg-quotient`). A quotient of constants
    /// folds only when it is finite: a zero divisor stays for the run time to show.
    pub fn div(&mut self, a: ExprId, b: ExprId) -> ExprId {
        match (self.as_const(a), self.as_const(b)) {
            (_, Some(0.0)) => return self.intern(Node::Div(a, b)),
            (Some(x), Some(y)) if (x / y).is_finite() => return self.constant(x / y),
            (_, Some(1.0)) => return a,
            (_, Some(-1.0)) => return self.neg(a),
            (Some(0.0), _) => return a,
            _ => {}
        }
        let (na, ia) = self.unneg(a);
        let (nb, ib) = self.unneg(b);
        if na || nb {
            let quotient = self.div(ia, ib);
            return if na != nb { self.neg(quotient) } else { quotient };
        }
        self.intern(Node::Div(a, b))
    }

    /// `sqrt(a)` (rule `sqrt-const`, for a constant at or above zero).
    pub fn sqrt(&mut self, a: ExprId) -> ExprId {
        match self.as_const(a) {
            Some(x) if x >= 0.0 => self.constant(x.sqrt()),
            _ => self.intern(Node::Sqrt(a)),
        }
    }

    /// `atan2(y, x)` (rule `atan2-const`, folded by the run time's own `atan2`).
    pub fn atan2(&mut self, y: ExprId, x: ExprId) -> ExprId {
        match (self.as_const(y), self.as_const(x)) {
            (Some(y), Some(x)) => self.constant(kinematics_core::trig::atan2(y, x)),
            _ => self.intern(Node::Atan2(y, x)),
        }
    }

    /// `then` where `condition > 0`, else `otherwise` (rules `select-const`, `select-same`).
    pub fn if_positive(&mut self, condition: ExprId, then: ExprId, otherwise: ExprId) -> ExprId {
        if then == otherwise {
            return then;
        }
        match self.as_const(condition) {
            Some(c) if c > 0.0 => then,
            Some(_) => otherwise,
            None => self.intern(Node::IfPositive(condition, then, otherwise)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folds_zero_one_and_constants() {
        let mut g = ExprGraph::new();
        let x = g.var(0);
        let zero = g.constant(0.0);
        let one = g.constant(1.0);
        let minus_one = g.constant(-1.0);
        assert_eq!(g.add(x, zero), x);
        assert_eq!(g.mul(x, one), x);
        assert_eq!(g.mul(x, zero), zero);
        let nx = g.neg(x);
        assert_eq!(g.mul(minus_one, x), nx);
        assert_eq!(g.neg(nx), x);
        let two = g.constant(2.0);
        let three = g.constant(3.0);
        let five = g.add(two, three);
        assert!(g.is_const(five, 5.0));
        assert_eq!(g.sub(x, x), zero);
    }

    #[test]
    fn shares_and_orders_operands() {
        let mut g = ExprGraph::new();
        let (x, y) = (g.var(0), g.var(1));
        assert_eq!(g.mul(x, y), g.mul(y, x));
        assert_eq!(g.add(x, y), g.add(y, x));
        // -k*x shares k*x
        let k = g.constant(0.5);
        let mk = g.constant(-0.5);
        let kx = g.mul(k, x);
        let mkx = g.mul(mk, x);
        assert_eq!(g.node(mkx), Node::Neg(kx));
        let nx = g.neg(x);
        let p = g.mul(nx, y);
        let xy = g.mul(x, y);
        assert_eq!(g.node(p), Node::Neg(xy));
    }

    #[test]
    #[allow(clippy::approx_constant)] // the point: near-pi/2 decimals as URDF files write them
    fn constant_trig_folds_as_f64_computes_it() {
        let mut g = ExprGraph::new();
        for angle in [0.0, std::f64::consts::FRAC_PI_2, -std::f64::consts::PI, 1.57079632679, 1.5708] {
            let a = g.constant(angle);
            let (sa, ca) = (g.sin(a), g.cos(a));
            assert!(g.is_const(sa, angle.sin()) && g.is_const(ca, angle.cos()), "{angle}");
        }
        let zero = g.constant(0.0);
        let (s0, c0) = (g.sin(zero), g.cos(zero));
        assert!(g.is_const(s0, 0.0) && g.is_const(c0, 1.0));
    }

    #[test]
    fn pythagoras() {
        let mut g = ExprGraph::new();
        let x = g.var(3);
        let (s, c) = (g.sin(x), g.cos(x));
        let (ss, cc) = (g.mul(s, s), g.mul(c, c));
        let sum = g.add(ss, cc);
        assert!(g.is_const(sum, 1.0));
        let nx = g.neg(x);
        assert_eq!(g.cos(nx), c);
        let sn = g.sin(nx);
        assert_eq!(g.node(sn), Node::Neg(s));
    }
}
