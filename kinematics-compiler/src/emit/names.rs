//! Textbook names for sines, cosines and angles.

use std::collections::{BTreeMap, BTreeSet};

use crate::stats::reachable;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};

/// The name suffix of every angle whose sine or cosine is used: `1` for `q1`, `23` for `q2 + q3`
/// (`10_11` once an index has two digits), `a0, a1, ...` for any other angle.
#[derive(Debug, Clone, Default)]
pub struct Names {
    angle_suffix: BTreeMap<ExprId, String>,
    /// The lengths of `q` and `qd`, when known: variables past `q` are rates and rotations.
    sizes: Option<(usize, usize)>,
}

impl Names {
    /// With the lengths of `q` and `qd`, so variables past `q` get their names (`qd1`, `rot1_12`:
    /// row 1, column 2 of the first floating or spherical joint's rotation) rather than `q`'s.
    pub fn with_sizes(mut self, dof: usize, velocities: usize) -> Self {
        self.sizes = Some((dof, velocities));
        self
    }

    /// The name of variable `i`: `q1`, or with [`Names::with_sizes`] `qd1` or `rot1_12` past `q`.
    /// The parts after the letters are returned apart, for LaTeX subscripts.
    pub fn var(&self, i: usize) -> (&'static str, String) {
        match self.sizes {
            Some((n, nv)) if i >= n + nv => {
                let k = i - n - nv;
                ("rot", format!("{}_{}{}", k / 9 + 1, k % 9 / 3 + 1, k % 3 + 1))
            }
            Some((n, _)) if i >= n => ("qd", (i - n + 1).to_string()),
            _ => ("q", (i + 1).to_string()),
        }
    }

    /// Names the angles reachable from `outputs`.
    pub fn new(g: &ExprGraph, outputs: &[ExprId]) -> Self {
        let mut angle_suffix = BTreeMap::new();
        let mut taken = BTreeSet::new();
        let mut generic = 0;
        for id in reachable(g, outputs.iter().copied()) {
            let (Node::Sin(angle) | Node::Cos(angle)) = g.node(id) else { continue };
            if angle_suffix.contains_key(&angle) {
                continue;
            }
            let suffix = match unit_sum(g, angle) {
                Some(vars) => {
                    let separator = if vars.iter().any(|&v| v >= 9) { "_" } else { "" };
                    vars.iter().map(|v| (v + 1).to_string()).collect::<Vec<_>>().join(separator)
                }
                None => String::new(),
            };
            let suffix = if suffix.is_empty() || taken.contains(&suffix) {
                generic += 1;
                format!("a{}", generic - 1)
            } else {
                suffix
            };
            taken.insert(suffix.clone());
            angle_suffix.insert(angle, suffix);
        }
        Names { angle_suffix, sizes: None }
    }

    /// `s23` for the sine of angle `q2 + q3`.
    pub fn sin(&self, angle: ExprId) -> String {
        format!("s{}", self.suffix(angle))
    }

    /// `c23` for the cosine of angle `q2 + q3`.
    pub fn cos(&self, angle: ExprId) -> String {
        format!("c{}", self.suffix(angle))
    }

    /// The suffix of an angle.
    pub fn suffix(&self, angle: ExprId) -> String {
        self.angle_suffix.get(&angle).cloned().unwrap_or_else(|| format!("x{}", angle.index()))
    }

    /// The named angles, in id order.
    pub fn angles(&self) -> impl Iterator<Item = ExprId> + '_ {
        self.angle_suffix.keys().copied()
    }
}

/// The variable indices of `q_i + q_j + ...` (each with coefficient 1), in order of appearance.
fn unit_sum(g: &ExprGraph, id: ExprId) -> Option<Vec<usize>> {
    match g.node(id) {
        Node::Var(i) => Some(vec![i as usize]),
        Node::Add(a, b) => {
            let mut vars = unit_sum(g, a)?;
            vars.extend(unit_sum(g, b)?);
            vars.sort_unstable();
            Some(vars)
        }
        _ => None,
    }
}
