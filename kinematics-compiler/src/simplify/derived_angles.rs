//! Rule `derived-angles`: the sine and cosine of an angle that is another computed angle plus a
//! constant, or the sum of two computed angles (plus a constant), come from theirs by the sum
//! formulas instead of a `sin_cos` call.
//!
//! An angle whose joint terms are the negation of a computed angle's (`k - q` beside `q`: a mimic
//! joint with multiplier -1 and an offset) comes from it the same way, `sin(k - a) = sin k cos a -
//! cos k sin a`, for the same four multiplications; with a zero offset the graph already shares the
//! call (`sin(-q) = -sin q`).
//!
//! Mimic joints make such angles: a finger joint that follows its hand joint with a multiplier
//! `m` and sits behind a fixed `Rz(-m)` turns by `m*q - m` while its base link turns by `m*q`, and
//! merging parallel finger joints gives `2*m*q - m`. Each would be its own `sin_cos` (about forty
//! multiplications' worth of time), where `sin(a + k) = sin a cos k + cos a sin k` and
//! `cos(a + k) = cos a cos k - sin a sin k` cost four multiplications and two additions.
//!
//! Angles are read as linear forms over the joint variables (coefficients compared exactly, as the
//! chain passes added them). The simplest angles (fewest joint variables, then smallest
//! coefficients, then oldest) keep their `sin_cos`; each other angle is derived from angles
//! already available when it can be, at most [`MAX_DERIVATION_DEPTH`] formulas deep, so rounding
//! cannot pile up. The sum of two angles is searched only among [`MAX_PAIR_SEARCH`] angles, which
//! keeps the pass linear on long chains (whose angle sums `q1 + ... + qk` derive from nothing).

use std::collections::BTreeMap;

use crate::stats::reachable;
use crate::symbolic::graph::{ExprGraph, ExprId, Node};
use crate::symbolic::transform::SymTransform;

use super::ExprPass;

/// Pass `derived-angles`: `sin`/`cos` of `a + k` or `a + b + k` from those of `a` and `b`.
pub const DERIVED_ANGLES: ExprPass = ExprPass { name: "derived-angles", run: derive_frames };

/// How many sum formulas may stand between a derived angle and the `sin_cos` calls it comes from.
const MAX_DERIVATION_DEPTH: usize = 3;

/// Above this many distinct angles, only `a + k` is looked for (one map lookup per angle), not
/// `a + b + k` (a search over pairs).
const MAX_PAIR_SEARCH: usize = 64;

/// The variable part of an angle: `(dof, coefficient bits)`, sorted by dof, no zero coefficients.
type Terms = Vec<(u32, u64)>;

/// An angle as `terms + constant`.
#[derive(Debug, Clone)]
struct Linear {
    terms: Terms,
    constant: f64,
}

/// The angle `id` as a linear form, or `None` if it is not one (only sums, negations, constants,
/// variables and constant multiples of variables are).
fn linear(g: &ExprGraph, id: ExprId) -> Option<Linear> {
    let mut coefficients: BTreeMap<u32, f64> = BTreeMap::new();
    let mut constant = 0.0;
    let mut stack = vec![(id, 1.0)];
    while let Some((id, sign)) = stack.pop() {
        match g.node(id) {
            Node::Const(c) => constant += sign * c.value(),
            Node::Var(i) => *coefficients.entry(i).or_insert(0.0) += sign,
            Node::Neg(a) => stack.push((a, -sign)),
            Node::Add(a, b) => stack.extend([(a, sign), (b, sign)]),
            Node::Mul(a, b) => match (g.node(a), g.node(b)) {
                (Node::Const(k), Node::Var(i)) | (Node::Var(i), Node::Const(k)) => {
                    *coefficients.entry(i).or_insert(0.0) += sign * k.value();
                }
                _ => return None,
            },
            _ => return None,
        }
    }
    let terms = coefficients.into_iter().filter(|&(_, k)| k != 0.0).map(|(i, k)| (i, k.to_bits())).collect();
    Some(Linear { terms, constant })
}

/// The variable part of the angle `id` (its joint terms without the constant), if it is a linear
/// form, with the sign that makes its first coefficient positive: angles with equal parts, or
/// parts equal but for the sign, derive from one another by [`DERIVED_ANGLES`] for four
/// multiplications, which is what the search over fold orders charges for them.
pub(crate) fn angle_terms(g: &ExprGraph, id: ExprId) -> Option<Vec<(u32, u64)>> {
    linear(g, id).map(|l| match l.terms.first() {
        Some(&(_, k)) if f64::from_bits(k) < 0.0 => negated(&l.terms),
        _ => l.terms,
    })
}

/// The angle `id` as `sum of k_i q_i + constant`: the variables (by index, ascending) with their
/// coefficients, and the constant; `None` if it is not a linear form.
pub(crate) fn linear_form(g: &ExprGraph, id: ExprId) -> Option<(Vec<(usize, f64)>, f64)> {
    linear(g, id).map(|l| (l.terms.iter().map(|&(i, k)| (i as usize, f64::from_bits(k))).collect(), l.constant))
}

/// `-terms` (exact: negation only flips the sign bit).
fn negated(terms: &Terms) -> Terms {
    terms.iter().map(|&(i, k)| (i, (-f64::from_bits(k)).to_bits())).collect()
}

/// What deriving an angle's sine and cosine from another's costs, in multiplications plus additions.
pub(crate) const DERIVATION_COST: usize = 6;

/// `a - b` of two variable parts, exactly (`None` when a coefficient difference is inexact).
fn difference(a: &Terms, b: &Terms) -> Option<Terms> {
    let mut out: BTreeMap<u32, f64> = a.iter().map(|&(i, k)| (i, f64::from_bits(k))).collect();
    for &(i, k) in b {
        let k = f64::from_bits(k);
        let entry = out.entry(i).or_insert(0.0);
        let d = *entry - k;
        // Exactly representable: adding `k` back gives the coefficient again.
        if d + k != *entry {
            return None;
        }
        *entry = d;
    }
    Some(out.into_iter().filter(|&(_, k)| k != 0.0).map(|(i, k)| (i, k.to_bits())).collect())
}

/// `(sin, cos)` of `x + y` from those of `x` and `y`.
pub(crate) fn sum_formula(
    g: &mut ExprGraph,
    (sx, cx): (ExprId, ExprId),
    (sy, cy): (ExprId, ExprId),
) -> (ExprId, ExprId) {
    let (a, b) = (g.mul(sx, cy), g.mul(cx, sy));
    let sin = g.add(a, b);
    let (c, d) = (g.mul(cx, cy), g.mul(sx, sy));
    let cos = g.sub(c, d);
    (sin, cos)
}

/// `(sin, cos)` of `x + k` for a constant `k` (nothing to do for `k = 0`).
fn offset(g: &mut ExprGraph, x: (ExprId, ExprId), k: f64) -> (ExprId, ExprId) {
    if k == 0.0 {
        return x;
    }
    let (sk, ck) = (g.constant(k.sin()), g.constant(k.cos()));
    sum_formula(g, x, (sk, ck))
}

fn derive_frames(g: &mut ExprGraph, frames: &mut [SymTransform], extra: &mut [ExprId], position_only: bool) {
    let outputs: Vec<ExprId> = frames
        .iter()
        .flat_map(|t| if position_only { t.p.to_vec() } else { t.entries().to_vec() })
        .chain(extra.iter().copied())
        .collect();
    let nodes = reachable(g, outputs.iter().copied());
    // Every angle with its sine and cosine nodes (either may be absent: then it is made).
    let mut angles: BTreeMap<ExprId, Linear> = BTreeMap::new();
    for &id in &nodes {
        if let Node::Sin(a) | Node::Cos(a) = g.node(id)
            && !angles.contains_key(&a)
            && let Some(form) = linear(g, a)
        {
            angles.insert(a, form);
        }
    }
    if angles.len() < 2 {
        return;
    }
    let magnitude = |l: &Linear| l.terms.iter().map(|&(_, k)| f64::from_bits(k).abs()).sum::<f64>();
    let mut order: Vec<ExprId> = angles.keys().copied().collect();
    order.sort_by(|a, b| {
        let (la, lb) = (&angles[a], &angles[b]);
        la.terms.len().cmp(&lb.terms.len()).then(magnitude(la).total_cmp(&magnitude(lb))).then(a.cmp(b))
    });
    // The angles available so far: their (sin, cos) nodes and how many formulas deep they are.
    let mut available: Vec<(ExprId, (ExprId, ExprId), usize)> = Vec::new();
    let mut by_terms: BTreeMap<Terms, Vec<usize>> = BTreeMap::new();
    let mut derived: BTreeMap<ExprId, (ExprId, ExprId)> = BTreeMap::new();
    for angle in order {
        let form = angles[&angle].clone();
        // The shallowest available angle with a given variable part.
        let shallowest = |terms: &Terms, available: &[(ExprId, (ExprId, ExprId), usize)]| {
            by_terms.get(terms).and_then(|list| {
                list.iter().copied().filter(|&i| available[i].2 < MAX_DERIVATION_DEPTH).min_by_key(|&i| available[i].2)
            })
        };
        let mut found: Option<((ExprId, ExprId), usize)> = None;
        if let Some(i) = shallowest(&form.terms, &available) {
            let (a, sc, depth) = available[i];
            let k = form.constant - angles[&a].constant;
            found = Some((offset(g, sc, k), depth + 1));
        } else if let Some(i) = shallowest(&negated(&form.terms), &available) {
            // form = -a + k: the sine and cosine of -a are -sin a and cos a.
            let (a, (sa, ca), depth) = available[i];
            let k = form.constant + angles[&a].constant;
            let minus_a = (g.neg(sa), ca);
            found = Some((offset(g, minus_a, k), depth + 1));
        } else if angles.len() <= MAX_PAIR_SEARCH {
            for i in 0..available.len() {
                let (a, sc_a, depth_a) = available[i];
                if depth_a >= MAX_DERIVATION_DEPTH {
                    continue;
                }
                let Some(rest) = difference(&form.terms, &angles[&a].terms) else { continue };
                if rest.is_empty() {
                    continue;
                }
                if let Some(j) = shallowest(&rest, &available) {
                    let (b, sc_b, depth_b) = available[j];
                    let k = form.constant - angles[&a].constant - angles[&b].constant;
                    let sum = sum_formula(g, sc_a, sc_b);
                    found = Some((offset(g, sum, k), depth_a.max(depth_b) + 1));
                    break;
                }
            }
        }
        let (sc, depth) = match found {
            Some((sc, depth)) => {
                derived.insert(angle, sc);
                (sc, depth)
            }
            None => ((g.sin(angle), g.cos(angle)), 0),
        };
        by_terms.entry(form.terms).or_default().push(available.len());
        available.push((angle, sc, depth));
    }
    if derived.is_empty() {
        return;
    }
    // Rebuild the outputs with the derived sines and cosines in place of the calls.
    let mut new: BTreeMap<ExprId, ExprId> = BTreeMap::new();
    for &id in &nodes {
        let rewritten = match g.node(id) {
            Node::Sin(a) => derived.get(&a).map_or(id, |&(s, _)| s),
            Node::Cos(a) => derived.get(&a).map_or(id, |&(_, c)| c),
            node => g.rebuild(node, |a| new[&a]),
        };
        new.insert(id, rewritten);
    }
    for t in frames.iter_mut() {
        if !position_only {
            t.r = t.r.map(|row| row.map(|x| new[&x]));
        }
        t.p = t.p.map(|x| new[&x]);
    }
    for x in extra.iter_mut() {
        *x = new[x];
    }
}

#[cfg(test)]
mod tests {
    use super::super::testing::check_frames;
    use super::*;

    fn check(input: &[&str], expected: &[&str]) {
        check_frames(&DERIVED_ANGLES, true, input, expected);
    }

    #[test]
    fn an_angle_plus_a_constant() {
        // cos(q1 + 0.5) = cos(0.5) cos q1 - sin(0.5) sin q1, from the sin_cos of q1 the first
        // entry needs anyway.
        check(
            &["[sin(q1), cos(q1 + 0.5), 0]"],
            &["[sin(q1), 0.8775825618903728*cos(q1) - 0.479425538604203*sin(q1), 0]"],
        );
        // The simplest angle keeps its call whichever entry asks first.
        check(
            &["[sin(0.999899*q8 - 0.999899), sin(0.999899*q8), 0]"],
            &["[0.5403872916816489*sin(0.999899*q8) - 0.8414164099831738*cos(0.999899*q8), sin(0.999899*q8), 0]"],
        );
    }

    #[test]
    fn a_negated_angle_plus_a_constant() {
        // A constant less an angle: a mimic joint with multiplier -1 and an offset.
        check(
            &["[sin(q1), sin(0.5 - q1), cos(0.5 - q1)]"],
            &["[sin(q1), 0.479425538604203*cos(q1) - 0.8775825618903728*sin(q1), 0.8775825618903728*cos(q1) + \
               0.479425538604203*sin(q1)]"],
        );
    }

    #[test]
    fn a_sum_of_two_angles() {
        check(&["[sin(q1), sin(q2), cos(q1 + q2)]"], &["[sin(q1), sin(q2), cos(q1)*cos(q2) - sin(q1)*sin(q2)]"]);
        // Twice an angle, less a constant: a finger's second joint behind its first.
        check(
            &["[sin(q1), sin(2*q1 - 1), 0]"],
            &[
                "[sin(q1), 0.5403023058681398*(sin(q1)*cos(q1) + sin(q1)*cos(q1)) - 0.8414709848078965*(cos(q1)*cos(q1) - \
               sin(q1)*sin(q1)), 0]",
            ],
        );
    }

    #[test]
    fn angles_that_derive_from_nothing_keep_their_calls() {
        // A planar chain's angle sums: q1 + q2 needs q2, which nothing computes.
        check(&["[sin(q1), sin(q1 + q2), sin(q1 + q2 + q3)]"], &["[sin(q1), sin(q1 + q2), sin(q1 + q2 + q3)]"]);
        // A multiple other than a sum of available angles.
        check(&["[sin(q1), sin(0.3*q1), 0]"], &["[sin(q1), sin(0.3*q1), 0]"]);
        // Twice an angle is a sum of two: the smaller keeps its call.
        check(&["[sin(q1), sin(0.5*q1), 0]"], &["[sin(0.5*q1)*cos(0.5*q1) + sin(0.5*q1)*cos(0.5*q1), sin(0.5*q1), 0]"]);
        // One angle: nothing to derive from.
        check(&["[sin(q1), cos(q1), 0]"], &["[sin(q1), cos(q1), 0]"]);
    }
}
