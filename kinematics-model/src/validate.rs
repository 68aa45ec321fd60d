//! Validation: one function per rule, all of them run, every fault collected; then the tree is built.
//!
//! Rules that need a sound structure (the cycle and mimic checks) run only when the name checks
//! passed, so one mistake is not reported three times.

use std::collections::{BTreeMap, BTreeSet};

use crate::description::{Description, JointDescription, JointTypeDescription};
use crate::error::{ModelError, ModelErrors};
use crate::joint::{Joint, JointKind, JointMotion, Limits, Link};
use crate::tree::{JointId, KinematicTree, LinkId};

/// Checks `d` and builds the tree.
pub(crate) fn build(d: &Description) -> Result<KinematicTree, ModelErrors> {
    let mut errors = Vec::new();
    check_not_empty(d, &mut errors);
    check_unique_names(d, &mut errors);
    for joint in &d.joints {
        check_joint_type(joint, &mut errors);
        check_finite(joint, &mut errors);
        check_axis(joint, &mut errors);
        check_limits(joint, &mut errors);
    }
    let names_ok = errors.is_empty();
    check_links_exist(d, &mut errors);
    if names_ok && errors.is_empty() {
        check_structure(d, &mut errors);
        check_mimics(d, &mut errors);
    }
    if let Some(errors) = ModelErrors::from_vec(errors) {
        return Err(errors);
    }
    Ok(assemble(d))
}

/// Rule: a robot has at least one link.
fn check_not_empty(d: &Description, errors: &mut Vec<ModelError>) {
    if d.links.is_empty() {
        errors.push(ModelError::NoLinks);
    }
}

/// Rule: link names are unique, and so are joint names.
fn check_unique_names(d: &Description, errors: &mut Vec<ModelError>) {
    for name in duplicates(d.links.iter()) {
        errors.push(ModelError::DuplicateLink(name));
    }
    for name in duplicates(d.joints.iter().map(|j| &j.name)) {
        errors.push(ModelError::DuplicateJoint(name));
    }
}

fn duplicates<'a>(names: impl Iterator<Item = &'a String>) -> Vec<String> {
    let mut seen = BTreeSet::new();
    let mut reported = BTreeSet::new();
    let mut out = Vec::new();
    for name in names {
        if !seen.insert(name) && reported.insert(name) {
            out.push(name.clone());
        }
    }
    out
}

/// Rule: only revolute, continuous, prismatic and fixed joints are supported (for now).
fn check_joint_type(j: &JointDescription, errors: &mut Vec<ModelError>) {
    if matches!(j.kind, JointTypeDescription::Floating | JointTypeDescription::Planar | JointTypeDescription::Spherical)
    {
        errors.push(ModelError::UnsupportedJoint { element: j.element.clone(), kind: j.kind.name() });
    }
}

/// Rule: every number is finite (infinite position limits mean "no limit" and are allowed).
fn check_finite(j: &JointDescription, errors: &mut Vec<ModelError>) {
    let mut fault = |field| errors.push(ModelError::NonFinite { element: j.element.clone(), field });
    if !j.origin.numbers().chain(j.after_motion.numbers()).all(f64::is_finite) {
        fault("origin");
    }
    if !j.axis.iter().all(|v| v.is_finite()) {
        fault("axis");
    }
    if let Some(l) = &j.limits {
        if l.lower.is_nan() {
            fault("lower limit");
        }
        if l.upper.is_nan() {
            fault("upper limit");
        }
        if l.velocity.is_some_and(|v| !v.is_finite()) {
            fault("velocity limit");
        }
        if l.effort.is_some_and(|v| !v.is_finite()) {
            fault("effort limit");
        }
    }
    if let Some(m) = &j.mimic {
        if !m.multiplier.is_finite() {
            fault("mimic multiplier");
        }
        if !m.offset.is_finite() {
            fault("mimic offset");
        }
    }
}

/// Rule: a moving joint's axis is not zero (it is normalised when the tree is built).
fn check_axis(j: &JointDescription, errors: &mut Vec<ModelError>) {
    let moving = !matches!(j.kind, JointTypeDescription::Fixed);
    if moving && j.axis.iter().all(|v| v.is_finite()) && norm(j.axis) == 0.0 {
        errors.push(ModelError::ZeroAxis { element: j.element.clone() });
    }
}

/// Rule: a lower limit is not above the upper one; a fixed joint does not mimic.
fn check_limits(j: &JointDescription, errors: &mut Vec<ModelError>) {
    if let Some(l) = &j.limits
        && l.lower > l.upper
    {
        errors.push(ModelError::LimitOrder { element: j.element.clone(), lower: l.lower, upper: l.upper });
    }
    if j.kind == JointTypeDescription::Fixed && j.mimic.is_some() {
        errors.push(ModelError::FixedMimic { element: j.element.clone() });
    }
}

/// Rule: every joint's parent and child links exist.
fn check_links_exist(d: &Description, errors: &mut Vec<ModelError>) {
    let links: BTreeSet<&str> = d.links.iter().map(String::as_str).collect();
    for j in &d.joints {
        for (role, link) in [("parent", &j.parent), ("child", &j.child)] {
            if !links.contains(link.as_str()) {
                errors.push(ModelError::UnknownLink { element: j.element.clone(), role, link: link.clone() });
            }
        }
    }
}

/// Rules: each link has at most one parent joint, exactly one link has none (the root), and every
/// link is reached from the root (otherwise the joints form a cycle).
fn check_structure(d: &Description, errors: &mut Vec<ModelError>) {
    let mut parents: BTreeMap<&str, Vec<&JointDescription>> = BTreeMap::new();
    for j in &d.joints {
        parents.entry(j.child.as_str()).or_default().push(j);
    }
    let mut multiple = false;
    for link in &d.links {
        if let Some(js) = parents.get(link.as_str()).filter(|js| js.len() > 1) {
            multiple = true;
            errors.push(ModelError::MultipleParents {
                link: link.clone(),
                joints: js.iter().map(|j| j.name.clone()).collect(),
            });
        }
    }
    let roots: Vec<&String> = d.links.iter().filter(|l| !parents.contains_key(l.as_str())).collect();
    if roots.len() > 1 {
        errors.push(ModelError::MultipleRoots { links: roots.into_iter().cloned().collect() });
        return;
    }
    if multiple {
        return;
    }
    // One parent per link: follow parent pointers from each link; a walk that revisits a link
    // without reaching a root has found a cycle.
    let parent_of = |link: &str| parents.get(link).map(|js| js[0].parent.as_str());
    let mut reported: BTreeSet<&str> = BTreeSet::new();
    for start in &d.links {
        let mut seen: Vec<&str> = Vec::new();
        let mut at = start.as_str();
        while let Some(p) = parent_of(at) {
            if let Some(pos) = seen.iter().position(|&s| s == at) {
                let cycle = &seen[pos..];
                if cycle.iter().all(|l| reported.insert(l)) {
                    let mut links: Vec<String> = cycle.iter().map(|s| s.to_string()).collect();
                    links.reverse();
                    errors.push(ModelError::Cycle { links });
                }
                break;
            }
            seen.push(at);
            at = p;
        }
    }
}

/// Rules: a mimic joint follows a joint that exists and moves, and mimic relations do not loop.
fn check_mimics(d: &Description, errors: &mut Vec<ModelError>) {
    let by_name: BTreeMap<&str, &JointDescription> = d.joints.iter().map(|j| (j.name.as_str(), j)).collect();
    let mut in_loop: BTreeSet<&str> = BTreeSet::new();
    for j in &d.joints {
        let Some(m) = &j.mimic else { continue };
        match by_name.get(m.joint.as_str()) {
            None => errors.push(ModelError::MimicUnknown { element: j.element.clone(), source_joint: m.joint.clone() }),
            Some(source) if source.kind == JointTypeDescription::Fixed => {
                errors.push(ModelError::MimicOfFixed { element: j.element.clone(), source_joint: m.joint.clone() })
            }
            Some(_) => {
                let mut walk = vec![j.name.as_str()];
                let mut at: &JointDescription = j;
                while let Some(next) = at.mimic.as_ref().and_then(|m| by_name.get(m.joint.as_str())) {
                    if let Some(pos) = walk.iter().position(|&n| n == next.name) {
                        let joints = &walk[pos..];
                        if pos == 0 && joints.iter().all(|n| in_loop.insert(n)) {
                            errors
                                .push(ModelError::MimicLoop { joints: joints.iter().map(|s| s.to_string()).collect() });
                        }
                        break;
                    }
                    walk.push(next.name.as_str());
                    at = next;
                }
            }
        }
    }
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// Builds the tree from a description that passed every rule.
fn assemble(d: &Description) -> KinematicTree {
    let root =
        d.links.iter().find(|l| !d.joints.iter().any(|j| &j.child == *l)).map(String::as_str).unwrap_or_default();
    // Depth-first pre-order from the root, children in description order; a joint takes its place
    // when its child link is visited, so joints follow the same pre-order as links.
    let mut links: Vec<Link> = Vec::new();
    let mut order: Vec<&JointDescription> = Vec::new();
    let mut stack: Vec<(&str, Option<&JointDescription>)> = vec![(root, None)];
    while let Some((name, via)) = stack.pop() {
        links.push(Link { name: name.to_owned(), parent_joint: None, child_joints: Vec::new() });
        order.extend(via);
        for j in d.joints.iter().filter(|j| j.parent == name).rev() {
            stack.push((j.child.as_str(), Some(j)));
        }
    }
    let link_index: BTreeMap<String, usize> = links.iter().enumerate().map(|(i, l)| (l.name.clone(), i)).collect();
    let joint_index: BTreeMap<&str, usize> = order.iter().enumerate().map(|(i, j)| (j.name.as_str(), i)).collect();
    for (i, j) in order.iter().enumerate() {
        links[link_index[&j.child]].parent_joint = Some(JointId(i));
        links[link_index[&j.parent]].child_joints.push(JointId(i));
    }
    let mut dof_joints = Vec::new();
    let mut dof_of: BTreeMap<&str, usize> = BTreeMap::new();
    for (i, j) in order.iter().enumerate() {
        if j.kind != JointTypeDescription::Fixed && j.mimic.is_none() {
            dof_of.insert(j.name.as_str(), dof_joints.len());
            dof_joints.push(JointId(i));
        }
    }
    let by_name: BTreeMap<&str, &JointDescription> = d.joints.iter().map(|j| (j.name.as_str(), j)).collect();
    let joints = order
        .iter()
        .map(|j| {
            let kind = match j.kind {
                JointTypeDescription::Revolute => JointKind::Revolute,
                JointTypeDescription::Continuous => JointKind::Continuous,
                JointTypeDescription::Prismatic => JointKind::Prismatic,
                _ => JointKind::Fixed,
            };
            let motion = if kind == JointKind::Fixed {
                JointMotion::Fixed
            } else if j.mimic.is_none() {
                JointMotion::Dof(dof_of[j.name.as_str()])
            } else {
                resolve_mimic(j, &by_name, &dof_of, &joint_index)
            };
            let n = norm(j.axis);
            let axis = if kind == JointKind::Fixed || n == 0.0 {
                j.axis
            } else {
                [j.axis[0] / n, j.axis[1] / n, j.axis[2] / n]
            };
            let limits = match (kind, j.limits) {
                (JointKind::Continuous | JointKind::Fixed, _) | (_, None) => None,
                (_, Some(l)) => {
                    let lower = l.lower;
                    let upper = l.upper;
                    (lower.is_finite() || upper.is_finite()).then_some(Limits { lower, upper })
                }
            };
            Joint {
                name: j.name.clone(),
                kind,
                parent: LinkId(link_index[&j.parent]),
                child: LinkId(link_index[&j.child]),
                origin: j.origin.clone(),
                after_motion: j.after_motion.clone(),
                axis,
                limits,
                velocity_limit: j.limits.and_then(|l| l.velocity),
                effort_limit: j.limits.and_then(|l| l.effort),
                motion,
            }
        })
        .collect();
    KinematicTree {
        name: d.name.clone(),
        links,
        joints,
        dof_joints,
        exact_angles: crate::exactness::ExactAngles::Off,
        recognised: Vec::new(),
    }
}

/// Follows a mimic chain to its independent source, composing `m * q + o` along the way.
fn resolve_mimic(
    j: &JointDescription,
    by_name: &BTreeMap<&str, &JointDescription>,
    dof_of: &BTreeMap<&str, usize>,
    joint_index: &BTreeMap<&str, usize>,
) -> JointMotion {
    let (mut multiplier, mut offset) = (1.0, 0.0);
    let mut at = j;
    // Validation ruled out loops and unknown or fixed sources, so this ends at an independent joint.
    while let Some(m) = &at.mimic {
        // value(at) = m.multiplier * value(next) + m.offset, substituted into the running form.
        offset += multiplier * m.offset;
        multiplier *= m.multiplier;
        match by_name.get(m.joint.as_str()) {
            Some(next) => at = next,
            None => break,
        }
    }
    JointMotion::Mimic {
        source: JointId(joint_index.get(at.name.as_str()).copied().unwrap_or_default()),
        dof: dof_of.get(at.name.as_str()).copied().unwrap_or_default(),
        multiplier,
        offset,
    }
}
