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
/// it is used. Sines and cosines come in `sin_cos` pairs, at the point the first of them is needed.
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
        let mut items = Vec::new();
        let mut bound = BTreeMap::new();
        let mut used_vars = BTreeSet::new();
        let mut emitted_angles = BTreeSet::new();
        for &id in &nodes {
            match g.node(id) {
                Node::Var(i) => {
                    used_vars.insert(i as usize);
                }
                Node::Sin(a) | Node::Cos(a) if emitted_angles.insert(a) => {
                    items.push(Item::SinCos(a));
                }
                Node::Add(..) | Node::Mul(..) if uses[id.index()] >= 2 => {
                    let name = format!("t{}", bound.len());
                    bound.insert(id, name.clone());
                    items.push(Item::Let(id, name));
                }
                _ => {}
            }
        }
        Schedule { items, bound, names, used_vars }
    }
}
