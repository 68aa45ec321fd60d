//! Scheduling: which nodes get a `let`, in what order, and under which name.

use std::collections::{BTreeMap, BTreeSet};

use super::names::Names;
use crate::stats::reachable;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};

/// One binding of the straight-line code.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Item {
    /// `let (s, c) = angle.sin_cos();`
    SinCos(ExprId),
    /// `let tN = expr;`
    Let(ExprId, String),
}

/// The bindings in evaluation order, and the name of every bound node.
///
/// A sum or product used more than once is bound to a `tN`; one used once is written inline where
/// it is used. Sines and cosines come in `sin_cos` pairs, all of them first (after the few bindings
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
                Node::Neg(a) => uses[a.index()] += 1,
                Node::Add(a, b) | Node::Mul(a, b) => {
                    uses[a.index()] += 1;
                    uses[b.index()] += 1;
                }
                Node::Const(_) | Node::Var(_) => {}
            }
        }
        for &o in outputs {
            uses[o.index()] += 1;
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
        let mut bound = BTreeMap::new();
        let mut used_vars = BTreeSet::new();
        let mut emitted_angles = BTreeSet::new();
        let (mut before_calls, mut calls, mut after_calls) = (Vec::new(), Vec::new(), Vec::new());
        for &id in &nodes {
            match g.node(id) {
                Node::Var(i) => {
                    used_vars.insert(i as usize);
                }
                Node::Sin(a) | Node::Cos(a) if emitted_angles.insert(a) => {
                    calls.push(Item::SinCos(a));
                }
                Node::Add(..) | Node::Mul(..) if uses[id.index()] >= 2 => {
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
        Schedule { items, bound, names, used_vars }
    }
}
