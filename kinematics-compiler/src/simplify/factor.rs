//! Rule `common-factor`: `k*a + k*b = k*(a + b)`, over the finished expressions.
//!
//! Sums are built two operands at a time as transforms multiply, so terms that share a factor
//! (often a link length: `0.0825*t4 - 0.0825*t10`) end up apart. This pass flattens each sum
//! through the sums and negations only it uses, groups the products that only it uses by a shared
//! factor (greedily, the most frequent factor first, ties to the oldest node), and rebuilds
//! `f * (sum of cofactors)`: one multiplication instead of one per term. Shared nodes are left
//! whole, so no work is duplicated.

use std::collections::BTreeMap;

use crate::stats::reachable;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};
use crate::symbolic::transform::SymTransform;

use super::ExprPass;

/// Pass `common-factor`: `k*a + k*b = k*(a + b)` over every output of the poses (the translations,
/// and the rotations unless only positions are wanted).
pub const COMMON_FACTOR: ExprPass = ExprPass { name: "common-factor", run: factor_frames };

fn factor_frames(g: &mut ExprGraph, frames: &mut [SymTransform], extra: &mut [ExprId], position_only: bool) {
    let per_frame = if position_only { 3 } else { 12 };
    let outputs: Vec<ExprId> = frames
        .iter()
        .flat_map(|t| if position_only { t.p.to_vec() } else { t.entries().to_vec() })
        .chain(extra.iter().copied())
        .collect();
    let factored = factor_common(g, &outputs);
    let (poses, rest) = factored.split_at(frames.len() * per_frame);
    extra.copy_from_slice(rest);
    for (t, new) in frames.iter_mut().zip(poses.chunks(per_frame)) {
        if position_only {
            t.p = [new[0], new[1], new[2]];
        } else {
            t.r = [[new[0], new[1], new[2]], [new[3], new[4], new[5]], [new[6], new[7], new[8]]];
            t.p = [new[9], new[10], new[11]];
        }
    }
}

/// Rewrites `outputs` (new ids in the same graph; the old nodes stay, unreachable).
fn factor_common(g: &mut ExprGraph, outputs: &[ExprId]) -> Vec<ExprId> {
    let nodes = reachable(g, outputs.iter().copied());
    let mut uses = vec![0usize; g.len()];
    // The user of each node (meaningful for nodes used once).
    let mut parent: Vec<Option<ExprId>> = vec![None; g.len()];
    for &id in &nodes {
        for a in g.node(id).operands() {
            uses[a.index()] += 1;
            parent[a.index()] = Some(id);
        }
    }
    // Whether a node is an output, by index: asking the list of outputs for each node made a long
    // chain's thousands of frames quadratic.
    let mut is_output = vec![false; g.len()];
    for &o in outputs {
        uses[o.index()] += 1;
        is_output[o.index()] = true;
    }
    // A sum or negation used once, inside a sum, is flattened into that sum and needs no rewriting
    // of its own (rewriting every level would make long sums quadratic).
    let is_add = |g: &ExprGraph, id: Option<ExprId>| id.is_some_and(|p| matches!(g.node(p), Node::Add(..)));
    let absorbed = |g: &ExprGraph, id: ExprId| -> bool {
        if uses[id.index()] != 1 || is_output[id.index()] {
            return false;
        }
        let p = parent[id.index()];
        match g.node(id) {
            Node::Add(..) => {
                is_add(g, p)
                    || p.is_some_and(|n| {
                        matches!(g.node(n), Node::Neg(_)) && uses[n.index()] == 1 && is_add(g, parent[n.index()])
                    })
            }
            Node::Neg(_) => is_add(g, p),
            _ => false,
        }
    };
    let mut new: BTreeMap<ExprId, ExprId> = BTreeMap::new();
    for &id in &nodes {
        if absorbed(g, id) {
            continue;
        }
        let rewritten = match g.node(id) {
            Node::Add(..) => {
                let mut terms = Vec::new();
                flatten(g, id, false, &uses, &new, &mut terms, true);
                rebuild(g, terms, &uses)
            }
            node => g.rebuild(node, |a| new[&a]),
        };
        new.insert(id, rewritten);
    }
    outputs.iter().map(|o| new[o]).collect()
}

/// The signed terms of the sum at `id`, descending through sums and negations used only here.
/// Terms are already-rewritten ids; a term is `(negated, id, original id)`.
fn flatten(
    g: &ExprGraph,
    id: ExprId,
    negated: bool,
    uses: &[usize],
    new: &BTreeMap<ExprId, ExprId>,
    terms: &mut Vec<(bool, ExprId, ExprId)>,
    top: bool,
) {
    let private = top || uses[id.index()] == 1;
    match g.node(id) {
        Node::Add(a, b) if private => {
            flatten(g, a, negated, uses, new, terms, false);
            flatten(g, b, negated, uses, new, terms, false);
        }
        Node::Neg(a) if private && matches!(g.node(a), Node::Add(..)) && uses[a.index()] == 1 => {
            flatten(g, a, !negated, uses, new, terms, false);
        }
        Node::Neg(a) if private => terms.push((!negated, new[&a], a)),
        _ => terms.push((negated, new[&id], id)),
    }
}

/// Sums the terms, factoring out shared factors of products used only in this sum.
fn rebuild(g: &mut ExprGraph, terms: Vec<(bool, ExprId, ExprId)>, uses: &[usize]) -> ExprId {
    // Products eligible for factoring: used only here (in the original graph).
    let factors = |g: &ExprGraph, (_, id, original): &(bool, ExprId, ExprId)| -> Option<(ExprId, ExprId)> {
        match (g.node(*id), uses[original.index()]) {
            (Node::Mul(a, b), 1) => Some((a, b)),
            _ => None,
        }
    };
    let mut remaining: Vec<Option<(bool, ExprId, ExprId)>> = terms.into_iter().map(Some).collect();
    // Placed results: (position of the first term of the group, negated, id).
    let mut placed: Vec<(usize, bool, ExprId)> = Vec::new();
    loop {
        let mut count: BTreeMap<ExprId, usize> = BTreeMap::new();
        for term in remaining.iter().flatten() {
            if let Some((a, b)) = factors(g, term) {
                *count.entry(a).or_default() += 1;
                if b != a {
                    *count.entry(b).or_default() += 1;
                }
            }
        }
        let Some((&factor, _)) =
            count.iter().filter(|(_, n)| **n >= 2).max_by_key(|&(id, n)| (*n, std::cmp::Reverse(*id)))
        else {
            break;
        };
        let mut first = None;
        let mut cofactors: Option<ExprId> = None;
        for (position, slot) in remaining.iter_mut().enumerate() {
            let Some(term) = *slot else { continue };
            let Some((a, b)) = factors(g, &term) else { continue };
            let other = if a == factor {
                b
            } else if b == factor {
                a
            } else {
                continue;
            };
            let signed = if term.0 { g.neg(other) } else { other };
            cofactors = Some(match cofactors {
                Some(sum) => g.add(sum, signed),
                None => signed,
            });
            first.get_or_insert(position);
            *slot = None;
        }
        if let (Some(position), Some(sum)) = (first, cofactors) {
            let product = g.mul(factor, sum);
            placed.push((position, false, product));
        }
    }
    for (position, slot) in remaining.into_iter().enumerate() {
        if let Some((negated, id, _)) = slot {
            placed.push((position, negated, id));
        }
    }
    placed.sort_by_key(|&(position, _, _)| position);
    let mut sum: Option<ExprId> = None;
    for (_, negated, id) in placed {
        let term = if negated { g.neg(id) } else { id };
        sum = Some(match sum {
            Some(s) => g.add(s, term),
            None => term,
        });
    }
    #[allow(clippy::expect_used, reason = "an invariant of flatten, named in the message")]
    let sum = sum.expect("invariant: a sum flattens into at least two terms, and every term is placed");
    sum
}

#[cfg(test)]
mod tests {
    use super::super::testing::check_frames;
    use super::*;

    /// `common-factor` on the translation of one pose (rotation the identity), positions only.
    #[track_caller]
    fn check(input: &str, expected: &str) {
        check_frames(&COMMON_FACTOR, true, &[&format!("[{input}, 0, 0]")], &[&format!("[{expected}, 0, 0]")]);
    }

    #[test]
    fn common_factor() {
        check("0.5*cos(q1) + 0.5*sin(q2)", "0.5*(cos(q1) + sin(q2))");
        check("q1*q2 - q1*q3", "q1*(q2 - q3)");
        check("-q1*q2 - q1*q3", "-q1*(q2 + q3)");
        check("q1*q2 + q2*q3", "q2*(q1 + q3)");
        check("q1*q1 + q1*q2", "q1*(q1 + q2)");
        // Nothing shared.
        check("cos(q1) + sin(q2)", "cos(q1) + sin(q2)");
        check("q1*q2 + q3*q4", "q1*q2 + q3*q4");
        check("q1*q2", "q1*q2");
        // The most frequent factor first, then the next.
        check("q1*q2 + q3*q4 + q3*q5 + q1*q6 + q3*q7", "q3*(q7 + (q4 + q5)) + q1*(q2 + q6)");
        // Ties to the oldest node (here the first variable read); both cofactor sums are `q3 + q1`,
        // one node.
        check("q2*q3 + q1*q2 + q1*q4 + q3*q4", "q2*(q3 + q1) + q4*(q3 + q1)");
        // Sums and negated sums used only here are flattened into the sum.
        check("q1*q2 + (q3 + q1*q4)", "q3 + q1*(q2 + q4)");
        check("q1*q2 - (q3 + q1*q4)", "q1*(q2 - q4) - q3");
    }

    #[test]
    fn shared_nodes_stay_whole() {
        // `q1*q2` is an output of its own: factoring it would compute it twice.
        check_frames(&COMMON_FACTOR, true, &["[q1*q2 + q1*q3, q1*q2, 0]"], &["[q1*q2 + q1*q3, q1*q2, 0]"]);
        // A sum two outputs share is rewritten once, for both.
        check_frames(
            &COMMON_FACTOR,
            true,
            &["[q1*q2 + q1*q3, q1*q2 + q1*q3, 0]"],
            &["[q1*(q2 + q3), q1*(q2 + q3), 0]"],
        );
    }

    #[test]
    fn rotations_only_when_they_are_outputs() {
        let pose = "[q1*q2 + q1*q3, 0, 0, 0, 1, 0, 0, 0, 1; q4*q5 + q4*q6, 0, 0]";
        check_frames(&COMMON_FACTOR, false, &[pose], &["[q1*(q2 + q3), 0, 0, 0, 1, 0, 0, 0, 1; q4*(q5 + q6), 0, 0]"]);
        check_frames(&COMMON_FACTOR, true, &[pose], &["[q1*q2 + q1*q3, 0, 0, 0, 1, 0, 0, 0, 1; q4*(q5 + q6), 0, 0]"]);
    }
}
