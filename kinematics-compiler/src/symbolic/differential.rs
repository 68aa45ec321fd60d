//! Differential kinematics over the chain IR: the geometric Jacobian of a chain of steps and its
//! twist `J * qdot`, as expressions in the same graph as the pose, so they share its work.
//!
//! The chain `T = S1 S2 ... Sn` is folded from the base out. Each step that depends on the joint
//! variables moves everything after it; by the product rule the Jacobian is the sum of what each
//! step contributes with the others held still. With `A` the product of the steps before it (its
//! rotation `R_A`, its origin `o = p_A`) and `p` the tip's origin, all in base axes:
//!
//! - a rotation by `a(q)` about the unit axis `u` turns everything after it about the axis
//!   `z = R_A u` through `o`: column `i` gains `da/dq_i * [z x (p - o); z]`;
//! - a translation by `v(q)` moves everything after it: column `i` gains `[R_A dv/dq_i; 0]`.
//!
//! Angles are linear forms in the joint variables, so `da/dq_i` is a constant (a mimic joint's
//! multiplier; `1` and `1` for an angle sum `q2 + q3`; `-1` on an inverted step, where the base's
//! side of the tree moves); translations are differentiated symbolically ([`derivative`]). The
//! twist is built the same way with `a' = sum_i da/dq_i * qdot_i` per step, so a step contributes
//! one cross product however many joints its angle sums (cheaper than forming `J` and
//! multiplying). The joint rates are the graph's variables after the joint positions
//! (`q[dof + i]` is `qdot[i]`).
//!
//! `Differential` records, folding from the base out, each moving step's axis and origin (or, for a
//! translation, its symbolic derivative); the geometric Jacobian or the twist is the sum of what
//! each contributes. For `LOCAL` the inverted chain is folded from the tip, so axes and origins
//! come out in the tip's axes. Lever arms have the terms the tip and joint origins share cancelled.

use rustc_hash::FxHashMap;

use super::graph::{ExprGraph, ExprId, Node};
use super::step::Step;
use super::transform::{SymTransform, apply_right, const_vec, mat_vec};

/// One column of a geometric Jacobian: the linear velocity of the tip's origin, then the angular
/// velocity, per unit rate of one degree of freedom.
pub type Column = [ExprId; 6];

/// What a joint-dependent step contributes, recorded while folding.
enum Contribution {
    /// A rotation: the rates of its angle per degree of freedom, its axis and origin in base axes.
    Rotation { rates: Vec<(usize, f64)>, axis: [ExprId; 3], origin: [ExprId; 3] },
    /// A translation: per degree of freedom, the velocity it gives the tip, in base axes.
    Translation { velocities: Vec<(usize, [ExprId; 3])> },
    /// A floating or spherical joint: the child's axes (the columns of its rotation) and origin
    /// in base axes, its first column, whether it translates (a floating joint: three linear
    /// columns before the angular ones), and `-1` on the base's side of the tree.
    Free { axes: [[ExprId; 3]; 3], origin: [ExprId; 3], column: usize, translates: bool, sign: f64 },
}

/// The chain's pose folded from the base out, and what each of its joint-dependent steps
/// contributes to the velocity of the tip.
pub struct Differential {
    /// The pose of the chain (`start` times the steps).
    pub pose: SymTransform,
    contributions: Vec<Contribution>,
}

impl Differential {
    /// Folds `steps` from `start` (the identity for a chain from the base), recording each
    /// joint-dependent step's axis and origin (rotations) or velocity (translations).
    ///
    /// `columns` maps each entry of `q` to its velocity (Jacobian column): the model's
    /// `velocity_of_entry`, `None` for a floating or spherical joint's entries, whose columns its
    /// [`Step::Free`] gives instead (derivatives by those entries, and by the rotation variables
    /// beyond `q`, are not velocities and are left out).
    pub fn fold(g: &mut ExprGraph, start: SymTransform, steps: &[Step], columns: &[Option<usize>]) -> Self {
        let column = |i: usize| columns.get(i).copied().flatten();
        let mut t = start;
        let mut contributions = Vec::new();
        for step in steps {
            match step {
                Step::Rotate { axis, angle } if !angle.is_constant() => {
                    let u = const_vec(g, *axis);
                    let z = mat_vec(g, &t.r, u);
                    let rates = angle.terms().iter().filter_map(|&(i, k)| Some((column(i)?, k))).collect();
                    contributions.push(Contribution::Rotation { rates, axis: z, origin: t.p });
                }
                Step::Translate(v) => {
                    let mut vars = Vec::new();
                    for &x in v {
                        collect_vars(g, x, &mut vars);
                    }
                    vars.sort_unstable();
                    vars.dedup();
                    let velocities = vars
                        .into_iter()
                        .filter_map(|i| {
                            let c = column(i)?;
                            let dv = v.map(|x| derivative(g, x, i));
                            Some((c, mat_vec(g, &t.r, dv)))
                        })
                        .collect::<Vec<_>>();
                    if !velocities.is_empty() {
                        contributions.push(Contribution::Translation { velocities });
                    }
                }
                // The child's frame: after the rotation, or, inverted, before it (where the
                // child's side of the tree is).
                Step::Free { column, translates, inverted: true, .. } => {
                    let axes = columns_of(&t.r);
                    let (column, translates) = (*column, *translates);
                    contributions.push(Contribution::Free { axes, origin: t.p, column, translates, sign: -1.0 });
                }
                Step::Free { column, translates, inverted: false, rotation } => {
                    let r = crate::symbolic::transform::mat_mul(g, &t.r, rotation);
                    let axes = columns_of(&r);
                    let (column, translates) = (*column, *translates);
                    contributions.push(Contribution::Free { axes, origin: t.p, column, translates, sign: 1.0 });
                }
                _ => {}
            }
            t = apply_right(g, &t, step);
        }
        Differential { pose: t, contributions }
    }

    /// Whether a floating or spherical joint is among the steps (the inverted chain's `LOCAL` formulas do
    /// not cover it).
    pub fn has_free(&self) -> bool {
        self.contributions.iter().any(|c| matches!(c, Contribution::Free { .. }))
    }

    /// The geometric Jacobian in base axes (Pinocchio's `LOCAL_WORLD_ALIGNED`): `velocities`
    /// columns, of the tip whose origin is `p` (the chain's own translation, or the same point as
    /// the simplified pose computes it).
    pub fn jacobian(&self, g: &mut ExprGraph, p: [ExprId; 3], velocities: usize) -> Vec<Column> {
        let zero = g.constant(0.0);
        let mut columns = vec![[zero; 6]; velocities];
        for contribution in &self.contributions {
            match contribution {
                Contribution::Rotation { rates, axis, origin } => {
                    let arm = sub3(g, p, *origin);
                    let linear = cross(g, *axis, arm);
                    for &(i, rate) in rates {
                        let k = g.constant(rate);
                        for r in 0..3 {
                            let l = g.mul(k, linear[r]);
                            columns[i][r] = g.add(columns[i][r], l);
                            let a = g.mul(k, axis[r]);
                            columns[i][r + 3] = g.add(columns[i][r + 3], a);
                        }
                    }
                }
                Contribution::Translation { velocities } => {
                    for (i, v) in velocities {
                        for r in 0..3 {
                            columns[*i][r] = g.add(columns[*i][r], v[r]);
                        }
                    }
                }
                Contribution::Free { axes, origin, column, translates, sign } => {
                    let arm = sub3(g, p, *origin);
                    let k = g.constant(*sign);
                    let angular = angular_column(*column, *translates);
                    for (a, axis) in axes.iter().enumerate() {
                        let linear = cross(g, *axis, arm);
                        for r in 0..3 {
                            let (v, l) = (g.mul(k, axis[r]), g.mul(k, linear[r]));
                            if *translates {
                                columns[column + a][r] = g.add(columns[column + a][r], v);
                            }
                            columns[angular + a][r] = g.add(columns[angular + a][r], l);
                            columns[angular + a][r + 3] = g.add(columns[angular + a][r + 3], v);
                        }
                    }
                }
            }
        }
        columns
    }

    /// The twist `J * qdot` in base axes (linear, then angular), with `qdot[i]` the graph's
    /// variable `dof + i` (`dof`: the length of `q`): per rotation step one cross product of its
    /// axis scaled by its angle's rate.
    pub fn twist(&self, g: &mut ExprGraph, p: [ExprId; 3], dof: usize) -> [ExprId; 6] {
        let zero = g.constant(0.0);
        let mut twist = [zero; 6];
        for contribution in &self.contributions {
            match contribution {
                Contribution::Rotation { rates, axis, origin } => {
                    let mut rate = zero;
                    for &(i, k) in rates {
                        let (k, qd) = (g.constant(k), g.var(dof + i));
                        let term = g.mul(k, qd);
                        rate = g.add(rate, term);
                    }
                    let w = axis.map(|z| g.mul(rate, z));
                    let arm = sub3(g, p, *origin);
                    let linear = cross(g, w, arm);
                    for r in 0..3 {
                        twist[r] = g.add(twist[r], linear[r]);
                        twist[r + 3] = g.add(twist[r + 3], w[r]);
                    }
                }
                Contribution::Translation { velocities } => {
                    for (i, v) in velocities {
                        let qd = g.var(dof + i);
                        for r in 0..3 {
                            let term = g.mul(qd, v[r]);
                            twist[r] = g.add(twist[r], term);
                        }
                    }
                }
                Contribution::Free { axes, origin, column, translates, sign } => {
                    // The child's velocity and angular velocity, from its own axes to base axes.
                    let k = g.constant(*sign);
                    let (v, w) = free_velocity(g, axes, dof + column, *translates, k);
                    let arm = sub3(g, p, *origin);
                    let turn = cross(g, w, arm);
                    for r in 0..3 {
                        let linear = g.add(v[r], turn[r]);
                        twist[r] = g.add(twist[r], linear);
                        twist[r + 3] = g.add(twist[r + 3], w[r]);
                    }
                }
            }
        }
        twist
    }
}

/// Where a floating or spherical joint's angular columns start: after a floating joint's three
/// linear ones.
fn angular_column(column: usize, translates: bool) -> usize {
    if translates { column + 3 } else { column }
}

/// A floating or spherical joint's child velocity and angular velocity from its rates (the
/// graph's variables from `first_rate` on, each times `k`), from the child's axes to the fold's:
/// `sum_a k qd_a axes[a]` for the three linear rates of a joint that translates (zero for one
/// that does not), then for the three angular ones.
fn free_velocity(
    g: &mut ExprGraph,
    axes: &[[ExprId; 3]; 3],
    first_rate: usize,
    translates: bool,
    k: ExprId,
) -> ([ExprId; 3], [ExprId; 3]) {
    let zero = g.constant(0.0);
    let mut part = |offset: usize| -> [ExprId; 3] {
        let rates: [ExprId; 3] = std::array::from_fn(|a| {
            let qd = g.var(first_rate + offset + a);
            g.mul(k, qd)
        });
        std::array::from_fn(|r| {
            let mut sum = g.constant(0.0);
            for a in 0..3 {
                let term = g.mul(rates[a], axes[a][r]);
                sum = g.add(sum, term);
            }
            sum
        })
    };
    let v = if translates { part(0) } else { [zero; 3] };
    let w = part(angular_column(0, translates));
    (v, w)
}

/// The columns of a rotation: the images of the three axes.
fn columns_of(r: &[[ExprId; 3]; 3]) -> [[ExprId; 3]; 3] {
    std::array::from_fn(|j| [r[0][j], r[1][j], r[2][j]])
}

/// The Jacobian and twist in the tip's own axes (Pinocchio's `LOCAL`), from a [`Differential`]
/// folded over the *inverted* chain (tip to base): there each joint's axis `z'` and origin `o'`
/// are already in the tip's axes, and a rotation whose (inverted) angle has rate `k'` gives the
/// tip's origin the velocity `k' z' x o'` and the angular velocity `-k' z'` (a translation, minus
/// its velocity; a floating or spherical joint's child axes `a` through `o'`, with sign `s` (`-1` where the
/// inverted chain meets the joint's own direction), give its linear columns `-s a` and its angular
/// ones `[s a x o'; -s a]`; a spherical joint's, the angular ones only). These are `LOCAL(T) = [-v + w x p'; -w]` of the inverted chain's own
/// columns `[v; w]` and translation `p'`. That is one cross product per step, where rotating a
/// base-axes column into the tip's axes takes two matrix products.
impl Differential {
    /// The geometric Jacobian in the tip's axes; `self` folded over the inverted chain.
    pub fn local_jacobian(&self, g: &mut ExprGraph, velocities: usize) -> Vec<Column> {
        let zero = g.constant(0.0);
        let mut columns = vec![[zero; 6]; velocities];
        for contribution in &self.contributions {
            match contribution {
                Contribution::Rotation { rates, axis, origin } => {
                    let linear = cross(g, *axis, *origin);
                    for &(i, rate) in rates {
                        let k = g.constant(rate);
                        let nk = g.constant(-rate);
                        for r in 0..3 {
                            let l = g.mul(k, linear[r]);
                            columns[i][r] = g.add(columns[i][r], l);
                            let a = g.mul(nk, axis[r]);
                            columns[i][r + 3] = g.add(columns[i][r + 3], a);
                        }
                    }
                }
                Contribution::Translation { velocities } => {
                    for (i, v) in velocities {
                        for r in 0..3 {
                            columns[*i][r] = g.sub(columns[*i][r], v[r]);
                        }
                    }
                }
                Contribution::Free { axes, origin, column, translates, sign } => {
                    let (k, nk) = (g.constant(*sign), g.constant(-sign));
                    let angular = angular_column(*column, *translates);
                    for (a, axis) in axes.iter().enumerate() {
                        let turn = cross(g, *axis, *origin);
                        for r in 0..3 {
                            let (v, l) = (g.mul(nk, axis[r]), g.mul(k, turn[r]));
                            if *translates {
                                columns[column + a][r] = g.add(columns[column + a][r], v);
                            }
                            columns[angular + a][r] = g.add(columns[angular + a][r], l);
                            columns[angular + a][r + 3] = g.add(columns[angular + a][r + 3], v);
                        }
                    }
                }
            }
        }
        columns
    }

    /// The twist `J * qdot` in the tip's axes; `self` folded over the inverted chain.
    pub fn local_twist(&self, g: &mut ExprGraph, dof: usize) -> [ExprId; 6] {
        let zero = g.constant(0.0);
        let mut twist = [zero; 6];
        for contribution in &self.contributions {
            match contribution {
                Contribution::Rotation { rates, axis, origin } => {
                    let mut rate = zero;
                    for &(i, k) in rates {
                        let (k, qd) = (g.constant(k), g.var(dof + i));
                        let term = g.mul(k, qd);
                        rate = g.add(rate, term);
                    }
                    let w = axis.map(|z| g.mul(rate, z));
                    let linear = cross(g, w, *origin);
                    for r in 0..3 {
                        twist[r] = g.add(twist[r], linear[r]);
                        twist[r + 3] = g.sub(twist[r + 3], w[r]);
                    }
                }
                Contribution::Translation { velocities } => {
                    for (i, v) in velocities {
                        let qd = g.var(dof + i);
                        for r in 0..3 {
                            let term = g.mul(qd, v[r]);
                            twist[r] = g.sub(twist[r], term);
                        }
                    }
                }
                Contribution::Free { axes, origin, column, translates, sign } => {
                    // Linear rates along -s a, angular rates about -s a through o'.
                    let nk = g.constant(-sign);
                    let (v, w) = free_velocity(g, axes, dof + column, *translates, nk);
                    // [s a x o'] rate = -(w x o') with w = -s a rate.
                    let turn = cross(g, *origin, w);
                    for r in 0..3 {
                        let linear = g.add(v[r], turn[r]);
                        twist[r] = g.add(twist[r], linear);
                        twist[r + 3] = g.add(twist[r + 3], w[r]);
                    }
                }
            }
        }
        twist
    }
}

/// `a - b` for each entry, as [`difference`] builds it.
fn sub3(g: &mut ExprGraph, a: [ExprId; 3], b: [ExprId; 3]) -> [ExprId; 3] {
    std::array::from_fn(|i| difference(g, a[i], b[i]))
}

/// The terms of a sum, with their signs: `a + b - (c + d)` is `+a, +b, -c, -d`.
fn sum_terms(g: &ExprGraph, id: ExprId, negated: bool, out: &mut Vec<(bool, ExprId)>) {
    match g.node(id) {
        Node::Add(a, b) => {
            sum_terms(g, a, negated, out);
            sum_terms(g, b, negated, out);
        }
        Node::Neg(a) => sum_terms(g, a, !negated, out),
        _ => out.push((negated, id)),
    }
}

/// `a - b` with the terms the two sums share cancelled. The lever arm `p - o` from a joint's
/// origin to the tip is the sum of the translations after the joint: `p` was accumulated from
/// `o` onwards, so `o`'s terms are among `p`'s, and subtracting node by node would compute them
/// twice and cancel them in floating point.
pub fn difference(g: &mut ExprGraph, a: ExprId, b: ExprId) -> ExprId {
    let (mut left, mut right) = (Vec::new(), Vec::new());
    sum_terms(g, a, false, &mut left);
    sum_terms(g, b, true, &mut right);
    for term in right {
        let opposite = (!term.0, term.1);
        match left.iter().position(|&t| t == opposite) {
            Some(k) => {
                left.remove(k);
            }
            None => left.push(term),
        }
    }
    let mut sum = g.constant(0.0);
    for (negated, term) in left {
        let term = if negated { g.neg(term) } else { term };
        sum = g.add(sum, term);
    }
    sum
}

/// `a x b`. An entry whose two products have the same factors is zero, whatever their grouping:
/// a lever arm along the joint's own axis (`z x k z`, a wrist's last joint with the tool on its
/// axis) gives zeros, not `x*k*y - y*k*x` computed and rounded.
fn cross(g: &mut ExprGraph, a: [ExprId; 3], b: [ExprId; 3]) -> [ExprId; 3] {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        if product_factors(g, &[a[j], b[k]]) == product_factors(g, &[a[k], b[j]]) {
            return g.constant(0.0);
        }
        let x = g.mul(a[j], b[k]);
        let y = g.mul(a[k], b[j]);
        g.sub(x, y)
    })
}

/// A product as its constant coefficient (sign included) and its other factors, sorted.
fn product_factors(g: &ExprGraph, ids: &[ExprId]) -> (u64, Vec<ExprId>) {
    fn walk(g: &ExprGraph, id: ExprId, coefficient: &mut f64, factors: &mut Vec<ExprId>) {
        match g.node(id) {
            Node::Mul(a, b) => {
                walk(g, a, coefficient, factors);
                walk(g, b, coefficient, factors);
            }
            Node::Neg(a) => {
                *coefficient = -*coefficient;
                walk(g, a, coefficient, factors);
            }
            Node::Const(c) => *coefficient *= c.value(),
            _ => factors.push(id),
        }
    }
    let (mut coefficient, mut factors) = (1.0, Vec::new());
    for &id in ids {
        walk(g, id, &mut coefficient, &mut factors);
    }
    factors.sort_unstable();
    (coefficient.to_bits(), factors)
}

/// The joint variables `id` depends on, pushed onto `out` (unsorted, possibly repeated).
fn collect_vars(g: &ExprGraph, id: ExprId, out: &mut Vec<usize>) {
    let mut stack = vec![id];
    let mut seen = rustc_hash::FxHashSet::default();
    while let Some(id) = stack.pop() {
        if !seen.insert(id) {
            continue;
        }
        match g.node(id) {
            Node::Var(i) => out.push(i as usize),
            node => stack.extend(node.operands()),
        }
    }
}

/// `d id / d q[var]`, built with the graph's smart constructors (so zeros vanish as they appear).
pub fn derivative(g: &mut ExprGraph, id: ExprId, var: usize) -> ExprId {
    let mut memo = FxHashMap::default();
    derivative_memo(g, id, var, &mut memo)
}

fn derivative_memo(g: &mut ExprGraph, id: ExprId, var: usize, memo: &mut FxHashMap<ExprId, ExprId>) -> ExprId {
    if let Some(&d) = memo.get(&id) {
        return d;
    }
    let d = match g.node(id) {
        Node::Const(_) => g.constant(0.0),
        Node::Var(i) => g.constant(if i as usize == var { 1.0 } else { 0.0 }),
        Node::Sin(a) => {
            let da = derivative_memo(g, a, var, memo);
            let c = g.cos(a);
            g.mul(c, da)
        }
        Node::Cos(a) => {
            let da = derivative_memo(g, a, var, memo);
            let s = g.sin(a);
            let ds = g.mul(s, da);
            g.neg(ds)
        }
        Node::Neg(a) => {
            let da = derivative_memo(g, a, var, memo);
            g.neg(da)
        }
        Node::Add(a, b) => {
            let (da, db) = (derivative_memo(g, a, var, memo), derivative_memo(g, b, var, memo));
            g.add(da, db)
        }
        Node::Mul(a, b) => {
            let (da, db) = (derivative_memo(g, a, var, memo), derivative_memo(g, b, var, memo));
            let (x, y) = (g.mul(da, b), g.mul(a, db));
            g.add(x, y)
        }
        // The inverse kinematics' operations (a body of it is never differentiated today; the
        // rules are the textbook's, so the graph stays one algebra).
        Node::Input(_) => g.constant(0.0),
        Node::Div(a, b) => {
            // (da b - a db) / b^2
            let (da, db) = (derivative_memo(g, a, var, memo), derivative_memo(g, b, var, memo));
            let (x, y, bb) = (g.mul(da, b), g.mul(a, db), g.mul(b, b));
            let numerator = g.sub(x, y);
            g.div(numerator, bb)
        }
        Node::Sqrt(a) => {
            // da / (2 sqrt a)
            let da = derivative_memo(g, a, var, memo);
            let two = g.constant(2.0);
            let twice = g.mul(two, id);
            g.div(da, twice)
        }
        Node::Atan2(y, x) => {
            // (x dy - y dx) / (x^2 + y^2)
            let (dy, dx) = (derivative_memo(g, y, var, memo), derivative_memo(g, x, var, memo));
            let (a, b) = (g.mul(x, dy), g.mul(y, dx));
            let numerator = g.sub(a, b);
            let (xx, yy) = (g.mul(x, x), g.mul(y, y));
            let r2 = g.add(xx, yy);
            g.div(numerator, r2)
        }
        Node::IfPositive(c, a, b) => {
            let (da, db) = (derivative_memo(g, a, var, memo), derivative_memo(g, b, var, memo));
            g.if_positive(c, da, db)
        }
    };
    memo.insert(id, d);
    d
}
