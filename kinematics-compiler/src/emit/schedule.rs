//! Scheduling: which nodes get a `let`, in what order, and under which name.
//!
//! A node gets a `let` when it is used more than once (a negation's operand counting each use of
//! the negation), and when its expression would nest deeper than `INLINE_DEPTH_LIMIT`, so no
//! emitted expression is deeper than `MAX_EXPRESSION_DEPTH`. The sines and cosines come first,
//! after only what the angles are computed from: with our trig (`Trig::Fast`) one
//! `T::sin_cos_many([...])` call for every angle of the function, computed side by side in SIMD
//! lanes; with `Trig::Std` one `sin_cos_std` call each.

use std::collections::{BTreeMap, BTreeSet};

use super::names::Names;
use crate::stats::reachable;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};

/// One binding of the straight-line code.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Item {
    /// The sine and cosine of an angle. The calls come one after another in the schedule, and
    /// the emitter writes them as one call for all (`sin_cos_many`) or one each (std trig).
    SinCos(ExprId),
    /// `let tN = expr;`
    Let(ExprId, String),
}

/// How deeply an expression written out inline may nest (in the conservative measure of
/// [`Schedule::new`]): a sum or product that would nest deeper is bound to a `tN` instead. Writing
/// every single-use node inline makes expressions as deep as the chain is long, and rustc recurses
/// over expressions: a 500-joint chain overflowed its stack. With this bound every emitted
/// expression, including the pose and array literals around the outputs, nests at most
/// [`MAX_EXPRESSION_DEPTH`] levels, whatever the robot; binding changes no operation count.
pub const INLINE_DEPTH_LIMIT: usize = 24;

/// The deepest any emitted expression nests (syntax-tree levels, counting parentheses, unary minus,
/// calls and the literals holding the outputs): [`INLINE_DEPTH_LIMIT`] plus what surrounds it.
pub const MAX_EXPRESSION_DEPTH: usize = 32;

/// The bindings in evaluation order, and the name of every bound node.
///
/// A sum or product used more than once is bound to a `tN`; one used once is written inline where
/// it is used, unless that would nest deeper than [`INLINE_DEPTH_LIMIT`]. Sines and cosines come in `sin_cos` pairs, all of them first (after the few bindings
/// an angle itself needs), then the arithmetic. The order matters for speed, not for values: a
/// `sin_cos` is a call into libm, and every floating-point register is lost across a call, so an
/// intermediate computed before a later `sin_cos` has to be spilled to the stack and reloaded.
/// With the calls first, only their results are live across them (measured: all link poses of the
/// Kinova Gen3 and of the dual-arm torso about 10% faster, the benchmark's `*_all_f64/floor_all_f64`).
#[derive(Debug, Clone)]
pub struct Schedule {
    /// Bindings in order (children before parents: graph id order).
    pub items: Vec<Item>,
    /// Name of each bound node.
    pub bound: BTreeMap<ExprId, String>,
    /// Angle names.
    pub names: Names,
    /// Joint variables that are used.
    pub used_vars: BTreeSet<usize>,
    /// Inputs ([`Node::Input`]) that are used.
    pub used_inputs: BTreeSet<usize>,
    /// Angles whose sine is used.
    pub sines: BTreeSet<ExprId>,
    /// Angles whose cosine is used.
    pub cosines: BTreeSet<ExprId>,
}

impl Schedule {
    /// Schedules everything `outputs` needs.
    pub fn new(g: &ExprGraph, outputs: &[ExprId]) -> Self {
        let names = Names::new(g, outputs);
        let nodes = reachable(g, outputs.iter().copied());
        let mut uses = vec![0usize; g.len()];
        let mut angles_seen = BTreeSet::new();
        for &id in &nodes {
            match g.node(id) {
                Node::Sin(a) | Node::Cos(a) => {
                    if angles_seen.insert(a) {
                        uses[a.index()] += 1;
                    }
                }
                node => {
                    for a in node.operands() {
                        uses[a.index()] += 1;
                    }
                }
            }
        }
        for &o in outputs {
            uses[o.index()] += 1;
        }
        // A negation is never bound: written out wherever it is used, it writes its operand each
        // time. So an operand used once, by a negation used twice, is written twice unless bound.
        // (Negations never nest, and their users are counted above.)
        for &id in &nodes {
            if let Node::Neg(a) = g.node(id) {
                uses[a.index()] += uses[id.index()].saturating_sub(1);
            }
        }
        // Everything an angle is computed from: its bindings must precede the `sin_cos` calls.
        let angles: Vec<ExprId> = nodes
            .iter()
            .filter_map(|&id| match g.node(id) {
                Node::Sin(a) | Node::Cos(a) => Some(a),
                _ => None,
            })
            .collect();
        let mut feeds_angle = vec![false; g.len()];
        for id in reachable(g, angles) {
            feeds_angle[id.index()] = true;
        }
        let bind = bind_for_depth(g, &nodes, &uses);
        let mut bound = BTreeMap::new();
        let mut used_vars = BTreeSet::new();
        let mut used_inputs = BTreeSet::new();
        let mut emitted_angles = BTreeSet::new();
        let (mut sines, mut cosines) = (BTreeSet::new(), BTreeSet::new());
        let (mut before_calls, mut calls, mut after_calls) = (Vec::new(), Vec::new(), Vec::new());
        for &id in &nodes {
            match g.node(id) {
                Node::Var(i) => {
                    used_vars.insert(i as usize);
                }
                Node::Input(i) => {
                    used_inputs.insert(i as usize);
                }
                Node::Sin(a) | Node::Cos(a) => {
                    if matches!(g.node(id), Node::Sin(_)) { &mut sines } else { &mut cosines }.insert(a);
                    if emitted_angles.insert(a) {
                        calls.push(Item::SinCos(a));
                    }
                }
                _ if bind[id.index()] => {
                    if feeds_angle[id.index()] { &mut before_calls } else { &mut after_calls }.push(id);
                }
                _ => {}
            }
        }
        // Temporaries are numbered in the order they are written.
        let mut bind = |id: ExprId| {
            let name = format!("t{}", bound.len());
            bound.insert(id, name.clone());
            Item::Let(id, name)
        };
        let before_calls: Vec<Item> = before_calls.into_iter().map(&mut bind).collect();
        let after_calls: Vec<Item> = after_calls.into_iter().map(&mut bind).collect();
        let items = [before_calls, calls, after_calls].concat();
        Schedule { items, bound, names, used_vars, used_inputs, sines, cosines }
    }
}

/// Which sums and products get a `let`: those used more than once, and those that written out
/// inline would nest deeper than [`INLINE_DEPTH_LIMIT`].
///
/// The depth is measured conservatively in syntax-tree levels of the emitted Rust: a name is 1, a
/// constant (`T::from_f64(-0.5)`) 3, a negation 2 more than its operand (unary minus, maybe
/// parentheses), a sum or product 2 more than its deeper operand (the operator, maybe parentheses).
/// Nodes are visited children first (`nodes` is in id order), so a node is bound as soon as its
/// own depth passes the limit, and then counts as a name: every binding's right-hand side nests at
/// most `INLINE_DEPTH_LIMIT + 4` levels (a sum of a negated deepest operand), every inline operand
/// at most `INLINE_DEPTH_LIMIT + 2`.
fn bind_for_depth(g: &ExprGraph, nodes: &[ExprId], uses: &[usize]) -> Vec<bool> {
    let mut bind = vec![false; g.len()];
    let mut depth = vec![1usize; g.len()];
    for &id in nodes {
        let i = id.index();
        depth[i] = match g.node(id) {
            Node::Const(_) => 3,
            Node::Var(_) | Node::Input(_) | Node::Sin(_) | Node::Cos(_) => 1,
            Node::Neg(a) => 2 + depth[a.index()],
            // A sum, product or quotient (an operator, maybe parentheses), or a call (`T::sqrt(..)`:
            // the call and its argument list).
            node => {
                let inline = 2 + node.operands().map(|a| depth[a.index()]).max().unwrap_or(0);
                bind[i] = uses[i] >= 2 || inline > INLINE_DEPTH_LIMIT;
                if bind[i] { 1 } else { inline }
            }
        };
    }
    bind
}
