//! Validation: one function per rule, all of them run, every fault collected; then the tree is built.
//!
//! Rules that need a sound structure (the cycle and mimic checks) run only when the name checks
//! passed, so one mistake is not reported three times; the rules on composed numbers (mimic
//! chains, the robot's reach) run on the assembled tree, once every other rule passed.
//!
//! **Cost.** Loading is O(n log n) in the number of links and joints: names are looked up in
//! ordered maps built once, every walk (parent pointers, mimic chains) visits each element once,
//! and nothing scans all joints per link.
//!
//! Every fault is collected into `ModelErrors`; the `KinematicTree` (`tree.rs`, `joint.rs`) is then
//! assembled.

use std::collections::{BTreeMap, BTreeSet};

use crate::description::{CollisionDescription, Description, ExcludedPair, JointDescription, JointTypeDescription};
use crate::error::{ModelError, ModelErrors, SeveralValues};
use crate::joint::{Joint, JointKind, JointMotion, Limits, Link, unit_axis};
use crate::transform::Elementary;
use crate::tree::{JointId, KinematicTree, LinkId};

/// Checks `d` and builds the tree.
pub(crate) fn build(d: &Description) -> Result<KinematicTree, ModelErrors> {
    let (owned, vacuous) = without_vacuous_mimics(d);
    let d = owned.as_ref().unwrap_or(d);
    let mut tree = build_checked(d)?;
    tree.vacuous_mimics = vacuous;
    tree.ignored = d.ignored.clone();
    tree.excluded_pairs = d.excluded_pairs.clone();
    tree.inertial_lines =
        crate::tree::Lines(d.inertials.iter().filter_map(|i| Some((i.link.clone(), i.line?))).collect());
    tree.inertia_from_geometry = d.inertia_from_geometry.clone();
    Ok(tree)
}

/// The description without the `<mimic>` of each fixed joint whose source is a fixed joint too
/// (both say it does not move), and those joints' names; `None` when there is none.
fn without_vacuous_mimics(d: &Description) -> (Option<Description>, Vec<String>) {
    let fixed: BTreeSet<&str> =
        d.joints.iter().filter(|j| j.kind == JointTypeDescription::Fixed).map(|j| j.name.as_str()).collect();
    let vacuous = |j: &JointDescription| {
        j.kind == JointTypeDescription::Fixed && j.mimic.as_ref().is_some_and(|m| fixed.contains(m.joint.as_str()))
    };
    let names: Vec<String> = d.joints.iter().filter(|j| vacuous(j)).map(|j| j.name.clone()).collect();
    if names.is_empty() {
        return (None, names);
    }
    let mut owned = d.clone();
    for j in &mut owned.joints {
        if vacuous(j) {
            j.mimic = None;
        }
    }
    (Some(owned), names)
}

/// [`build`] once vacuous mimics are set aside: every rule, then the tree.
fn build_checked(d: &Description) -> Result<KinematicTree, ModelErrors> {
    let mut errors = Vec::new();
    check_not_empty(d, &mut errors);
    check_unique_names(d, &mut errors);
    for joint in &d.joints {
        check_joint_type(joint, &mut errors);
        check_finite(joint, &mut errors);
        check_axis(joint, &mut errors);
        check_limits(joint, &mut errors);
    }
    let links: BTreeSet<&str> = d.links.iter().map(String::as_str).collect();
    for collision in &d.collisions {
        check_geometry(collision, &links, &mut errors);
    }
    for pair in &d.excluded_pairs {
        check_excluded_pair(pair, &links, &mut errors);
    }
    check_inertials(d, &links, &mut errors);
    let names_ok = errors.is_empty();
    check_links_exist(d, &mut errors);
    let mut root = None;
    if names_ok && errors.is_empty() {
        root = check_structure(d, &mut errors);
        check_mimics(d, &mut errors);
    }
    if let Some(errors) = ModelErrors::from_vec(errors) {
        return Err(errors);
    }
    #[allow(clippy::expect_used, reason = "invariant: a description that passed every structural rule has one root")]
    let root = root.expect("a description that passed the structural rules has exactly one root");
    let tree = assemble(d, root);
    let mut errors = Vec::new();
    check_mimic_composition(d, &tree, &mut errors);
    if errors.is_empty() {
        // The reach sums every mimic stroke: only meaningful once the compositions are finite.
        check_reach(d, &tree, &mut errors);
    }
    match ModelErrors::from_vec(errors) {
        Some(errors) => Err(errors),
        None => Ok(tree),
    }
}

/// Rule: collision geometry has finite, positive sizes (a capsule's length may be zero) and a
/// finite origin.
fn check_geometry(c: &CollisionDescription, links: &BTreeSet<&str>, errors: &mut Vec<ModelError>) {
    if !links.contains(c.link.as_str()) {
        errors.push(ModelError::Geometry { link: c.link.clone(), line: c.line, fault: "no such link".to_owned() });
        return;
    }
    let origin_finite = c.collision.origin.steps().iter().all(|step| match step {
        Elementary::Translation(v) => v.iter().all(|x| x.is_finite()),
        Elementary::Rotation(_, angle) => angle.radians().is_finite(),
    });
    let fault = c.collision.shape.fault().or_else(|| (!origin_finite).then(|| "<origin> is not finite".to_owned()));
    if let Some(fault) = fault {
        errors.push(ModelError::Geometry { link: c.link.clone(), line: c.line, fault });
    }
}

/// Rule: an excluded collision pair names two links of the robot.
fn check_excluded_pair(pair: &ExcludedPair, links: &BTreeSet<&str>, errors: &mut Vec<ModelError>) {
    for link in [&pair.link1, &pair.link2] {
        if !links.contains(link.as_str()) {
            let fault = format!("{} names no such link", pair.why);
            errors.push(ModelError::Geometry { link: link.clone(), line: None, fault });
        }
    }
}

/// Rule: an `<inertial>` belongs to a link of the robot, at most one to each. (Its values keep
/// the rules of [`crate::inertia::Inertial::fault`] only where dynamics are asked for.)
fn check_inertials(d: &Description, links: &BTreeSet<&str>, errors: &mut Vec<ModelError>) {
    let mut seen = BTreeSet::new();
    for i in &d.inertials {
        let fault = if !links.contains(i.link.as_str()) {
            "no such link"
        } else if !seen.insert(i.link.as_str()) {
            "more than one <inertial>"
        } else {
            continue;
        };
        errors.push(ModelError::Inertial { link: i.link.clone(), line: i.line, fault: fault.to_owned() });
    }
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

/// Rule: the joint types of URDF are supported (revolute, continuous, prismatic, fixed, floating,
/// planar), and MJCF's ball joint; URDF `spherical`, which the URDF specification does not
/// define, is not.
fn check_joint_type(j: &JointDescription, errors: &mut Vec<ModelError>) {
    if matches!(j.kind, JointTypeDescription::Spherical) {
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

/// Rule: a moving joint's axis is not zero. It is normalised when the tree is built, scaled by
/// its largest component first, so any finite non-zero axis (`0 0 1e200`, `1e-300 0 0`) has a
/// unit direction.
fn check_axis(j: &JointDescription, errors: &mut Vec<ModelError>) {
    // A floating or ball joint has no axis (URDF ignores a floating joint's); a planar joint's is
    // the plane's normal.
    let moving =
        !matches!(j.kind, JointTypeDescription::Fixed | JointTypeDescription::Floating | JointTypeDescription::Ball);
    if moving && j.axis.iter().all(|v| v.is_finite()) && unit_axis(j.axis).is_none() {
        errors.push(ModelError::ZeroAxis { element: j.element.clone() });
    }
}

/// Rule: a lower limit is not above the upper one; a fixed joint does not mimic (a moving joint:
/// the mimic of a fixed one was set aside before the rules).
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

/// Where a walk over parent (or mimic-source) pointers has been.
#[derive(Clone, Copy, PartialEq)]
enum Visit {
    /// Not reached yet.
    New,
    /// On the current walk, at this position.
    OnWalk(usize),
    /// Reached by an earlier walk (which ended at a root or at a cycle already reported).
    Done,
}

/// The cycles of a graph in which every node has at most one successor (`next`), each once,
/// in the order a walk from each node in turn (in index order) first closes it: the nodes of a
/// cycle in walk order, starting from the node at which the walk re-entered it. Every node is
/// visited once, so this is linear.
fn cycles(next: &[Option<usize>]) -> Vec<Vec<usize>> {
    let mut state = vec![Visit::New; next.len()];
    let mut found = Vec::new();
    let mut walk: Vec<usize> = Vec::new();
    for start in 0..next.len() {
        walk.clear();
        let mut at = start;
        loop {
            match state[at] {
                Visit::Done => break,
                Visit::OnWalk(pos) => {
                    found.push(walk[pos..].to_vec());
                    break;
                }
                Visit::New => {
                    state[at] = Visit::OnWalk(walk.len());
                    walk.push(at);
                    match next[at] {
                        Some(n) => at = n,
                        None => break,
                    }
                }
            }
        }
        for &n in &walk {
            state[n] = Visit::Done;
        }
    }
    found
}

/// Rules: each link has at most one parent joint, exactly one link has none (the root), and every
/// link is reached from the root (otherwise the joints form a cycle). Returns the root's index
/// when every rule holds.
fn check_structure(d: &Description, errors: &mut Vec<ModelError>) -> Option<usize> {
    let mut parents: BTreeMap<&str, Vec<&JointDescription>> = BTreeMap::new();
    for j in &d.joints {
        parents.entry(j.child.as_str()).or_default().push(j);
    }
    let before = errors.len();
    for link in &d.links {
        if let Some(js) = parents.get(link.as_str()).filter(|js| js.len() > 1) {
            errors.push(ModelError::MultipleParents {
                link: link.clone(),
                joints: js.iter().map(|j| j.name.clone()).collect(),
            });
        }
    }
    let multiple = errors.len() > before;
    let roots: Vec<usize> = (0..d.links.len()).filter(|&i| !parents.contains_key(d.links[i].as_str())).collect();
    if roots.len() > 1 {
        errors.push(ModelError::MultipleRoots { links: roots.iter().map(|&i| d.links[i].clone()).collect() });
        return None;
    }
    if multiple {
        return None;
    }
    // One parent per link: follow parent pointers from each link; a walk that comes back to a
    // link of its own has found a cycle (reported parent first).
    let index: BTreeMap<&str, usize> = d.links.iter().enumerate().map(|(i, l)| (l.as_str(), i)).collect();
    let parent_of: Vec<Option<usize>> = d
        .links
        .iter()
        .map(|l| parents.get(l.as_str()).and_then(|js| index.get(js[0].parent.as_str()).copied()))
        .collect();
    let found = cycles(&parent_of);
    for cycle in &found {
        errors.push(ModelError::Cycle { links: cycle.iter().rev().map(|&i| d.links[i].clone()).collect() });
    }
    if found.is_empty() { roots.first().copied() } else { None }
}

/// Rules: a mimic joint follows a joint that exists and moves, and mimic relations do not loop.
fn check_mimics(d: &Description, errors: &mut Vec<ModelError>) {
    let index: BTreeMap<&str, usize> = d.joints.iter().enumerate().map(|(i, j)| (j.name.as_str(), i)).collect();
    let source: Vec<Option<usize>> =
        d.joints.iter().map(|j| j.mimic.as_ref().and_then(|m| index.get(m.joint.as_str()).copied())).collect();
    // Each loop is reported once, starting from its first joint in description order, at that
    // joint's place among the other mimic faults.
    let mut loop_at: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for mut cycle in cycles(&source) {
        if let Some(first) = (0..cycle.len()).min_by_key(|&pos| cycle[pos]) {
            cycle.rotate_left(first);
        }
        if let Some(&first) = cycle.first() {
            loop_at.insert(first, cycle);
        }
    }
    for (i, j) in d.joints.iter().enumerate() {
        let Some(m) = &j.mimic else { continue };
        match source[i].map(|s| &d.joints[s]) {
            None => errors.push(ModelError::MimicUnknown { element: j.element.clone(), source_joint: m.joint.clone() }),
            Some(source) if source.kind == JointTypeDescription::Fixed => {
                errors.push(ModelError::MimicOfFixed { element: j.element.clone(), source_joint: m.joint.clone() })
            }
            // A mimic follows one value with one value: not a planar, floating or ball joint's
            // several.
            Some(source) if several_values(source.kind) || several_values(j.kind) => {
                let kind = if several_values(j.kind) { j.kind } else { source.kind };
                let kind = match kind {
                    JointTypeDescription::Planar => SeveralValues::Planar,
                    JointTypeDescription::Ball => SeveralValues::Spherical,
                    _ => SeveralValues::Floating,
                };
                errors.push(ModelError::MimicOfSeveral {
                    element: j.element.clone(),
                    source_joint: m.joint.clone(),
                    kind,
                })
            }
            Some(_) => {
                if let Some(cycle) = loop_at.get(&i) {
                    errors.push(ModelError::MimicLoop {
                        joints: cycle.iter().map(|&k| d.joints[k].name.clone()).collect(),
                    });
                }
            }
        }
    }
}

/// Whether a joint of this type takes several values (planar, floating, ball).
fn several_values(kind: JointTypeDescription) -> bool {
    matches!(kind, JointTypeDescription::Planar | JointTypeDescription::Floating | JointTypeDescription::Ball)
}

/// Rule: the composed multiplier and offset of every mimic joint (`m * q + o` after following
/// the chain of mimics to its independent source) are finite numbers. The fault is reported at
/// the joint where the composition first overflows, not again at the joints that follow it.
fn check_mimic_composition(d: &Description, tree: &KinematicTree, errors: &mut Vec<ModelError>) {
    let element = description_elements(d);
    for joint in tree.joints() {
        let JointMotion::Mimic { source, multiplier, offset, .. } = joint.motion else { continue };
        if multiplier.is_finite() && offset.is_finite() {
            continue;
        }
        // Reported once per chain: at the first joint whose own mimic source still composed to
        // finite numbers (or is the independent source itself).
        let written = d.joints[element[joint.name.as_str()]].mimic.as_ref();
        let parent_finite = written.and_then(|m| tree.joint_by_name(&m.joint)).is_none_or(|p| match p.motion {
            JointMotion::Mimic { multiplier, offset, .. } => multiplier.is_finite() && offset.is_finite(),
            _ => true,
        });
        if parent_finite {
            errors.push(ModelError::MimicOverflow {
                element: d.joints[element[joint.name.as_str()]].element.clone(),
                source_joint: tree.joint(source).name.clone(),
                offset: multiplier.is_finite(),
            });
        }
    }
}

/// Rule: the robot's reach ([`KinematicTree::reach`]: every fixed offset and every prismatic
/// stroke laid end to end, the scale agreement is measured against) is a finite number. The
/// fault names the joint (in the tree's order, the order the reach is summed in) at which the
/// running sum overflows.
fn check_reach(d: &Description, tree: &KinematicTree, errors: &mut Vec<ModelError>) {
    let element = description_elements(d);
    let mut sum = 0.0;
    for (i, joint) in tree.joints().iter().enumerate() {
        sum += tree.joint_reach(JointId(i));
        if !sum.is_finite() {
            errors.push(ModelError::ReachOverflow { element: d.joints[element[joint.name.as_str()]].element.clone() });
            return;
        }
    }
}

/// The index in the description of every joint, by name.
fn description_elements(d: &Description) -> BTreeMap<&str, usize> {
    d.joints.iter().enumerate().map(|(i, j)| (j.name.as_str(), i)).collect()
}

/// Builds the tree from a description that passed every rule, `root` being the root link's index.
fn assemble(d: &Description, root: usize) -> KinematicTree {
    // The joints below each link, in description order: one pass over the joints.
    let mut below: BTreeMap<&str, Vec<&JointDescription>> = BTreeMap::new();
    for j in &d.joints {
        below.entry(j.parent.as_str()).or_default().push(j);
    }
    // Each link's inertial (at most one: a rule), one pass.
    let mut inertials: BTreeMap<&str, crate::inertia::Inertial> =
        d.inertials.iter().map(|i| (i.link.as_str(), i.inertial.clone())).collect();
    // Each link's collision geometry, in description order: one pass.
    let mut geometry: BTreeMap<&str, Vec<crate::collision::Collision>> = BTreeMap::new();
    for c in &d.collisions {
        geometry.entry(c.link.as_str()).or_default().push(c.collision.clone());
    }
    // Depth-first pre-order from the root, children in description order; a joint takes its place
    // when its child link is visited, so joints follow the same pre-order as links.
    let mut links: Vec<Link> = Vec::new();
    let mut order: Vec<&JointDescription> = Vec::new();
    let mut stack: Vec<(&str, Option<&JointDescription>)> = vec![(d.links[root].as_str(), None)];
    while let Some((name, via)) = stack.pop() {
        let collisions = geometry.remove(name).unwrap_or_default();
        // A zero mass with a zero tensor is a massless link wherever its frame is: no inertial.
        let inertial = inertials.remove(name).filter(|i| !(i.mass == 0.0 && i.inertia == [0.0; 6]));
        links.push(Link { name: name.to_owned(), parent_joint: None, child_joints: Vec::new(), collisions, inertial });
        order.extend(via);
        for j in below.get(name).into_iter().flatten().rev() {
            stack.push((j.child.as_str(), Some(j)));
        }
    }
    let link_index: BTreeMap<&str, usize> =
        order.iter().enumerate().map(|(i, j)| (j.child.as_str(), i + 1)).chain([(d.links[root].as_str(), 0)]).collect();
    for (i, j) in order.iter().enumerate() {
        links[link_index[j.child.as_str()]].parent_joint = Some(JointId(i));
        links[link_index[j.parent.as_str()]].child_joints.push(JointId(i));
    }
    let joint_index: BTreeMap<&str, usize> = order.iter().enumerate().map(|(i, j)| (j.name.as_str(), i)).collect();
    // Every independent joint takes its entries of `q` in tree order: one, or a planar joint's
    // three, a spherical joint's four or a floating joint's seven.
    let mut dof_joints = Vec::new();
    let mut dof_of: Vec<Option<usize>> = vec![None; order.len()];
    for (i, j) in order.iter().enumerate() {
        if j.kind != JointTypeDescription::Fixed && j.mimic.is_none() {
            dof_of[i] = Some(dof_joints.len());
            let entries = joint_kind(j.kind).map_or(1, JointKind::positions);
            dof_joints.extend(std::iter::repeat_n(JointId(i), entries));
        }
    }
    let mimics = resolve_mimics(&order, &joint_index, &dof_of);
    let joints = order
        .iter()
        .zip(mimics)
        .enumerate()
        .map(|(i, (j, mimic))| {
            #[allow(clippy::expect_used, reason = "invariant: `check_joint_type` refused every other kind")]
            let kind = joint_kind(j.kind).expect("only supported joint kinds are assembled");
            let motion = match (kind, dof_of[i]) {
                (JointKind::Fixed, _) => JointMotion::Fixed,
                (_, Some(dof)) => JointMotion::Dof(dof),
                #[allow(clippy::expect_used, reason = "invariant: a moving joint is a degree of freedom or a mimic")]
                (_, None) => mimic.expect("a moving joint that is no degree of freedom is a resolved mimic"),
            };
            // A fixed joint keeps its axis as written (it is never used); a moving one passed
            // `check_axis`, so its unit axis exists.
            let axis = if matches!(kind, JointKind::Fixed | JointKind::Floating | JointKind::Spherical) {
                j.axis
            } else {
                #[allow(clippy::expect_used, reason = "invariant: `check_axis` refused zero axes of moving joints")]
                unit_axis(j.axis).expect("a moving joint's axis is finite and not zero")
            };
            // URDF gives limits to revolute and prismatic joints only.
            let limits = match (kind, j.limits) {
                (
                    JointKind::Continuous
                    | JointKind::Fixed
                    | JointKind::Floating
                    | JointKind::Planar
                    | JointKind::Spherical,
                    _,
                )
                | (_, None) => None,
                (_, Some(l)) => {
                    let lower = l.lower;
                    let upper = l.upper;
                    (lower.is_finite() || upper.is_finite()).then_some(Limits { lower, upper })
                }
            };
            Joint {
                name: j.name.clone(),
                kind,
                parent: LinkId(link_index[j.parent.as_str()]),
                child: LinkId(link_index[j.child.as_str()]),
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
    KinematicTree::new(d.name.clone(), links, joints, dof_joints)
}

/// The model's kind of a supported joint type (`None` for the types validation refuses).
fn joint_kind(kind: JointTypeDescription) -> Option<JointKind> {
    match kind {
        JointTypeDescription::Revolute => Some(JointKind::Revolute),
        JointTypeDescription::Continuous => Some(JointKind::Continuous),
        JointTypeDescription::Prismatic => Some(JointKind::Prismatic),
        JointTypeDescription::Fixed => Some(JointKind::Fixed),
        JointTypeDescription::Floating => Some(JointKind::Floating),
        JointTypeDescription::Planar => Some(JointKind::Planar),
        JointTypeDescription::Ball => Some(JointKind::Spherical),
        JointTypeDescription::Spherical => None,
    }
}

/// Resolves every mimic joint (`order` in tree order) to its independent source, composing
/// `m * q + o` along the chain: each joint's composition is computed once, from its source's.
fn resolve_mimics(
    order: &[&JointDescription],
    joint_index: &BTreeMap<&str, usize>,
    dof_of: &[Option<usize>],
) -> Vec<Option<JointMotion>> {
    let mut resolved: Vec<Option<JointMotion>> = vec![None; order.len()];
    let mut pending: Vec<usize> = Vec::new();
    for start in 0..order.len() {
        // Walk towards the source until a joint already resolved (or independent), then resolve
        // the walk backwards. Validation ruled out loops and unknown or fixed sources.
        let mut at = start;
        while resolved[at].is_none()
            && let Some(m) = &order[at].mimic
        {
            pending.push(at);
            #[allow(clippy::expect_used, reason = "invariant: `check_mimics` ruled out unknown sources")]
            let next = *joint_index.get(m.joint.as_str()).expect("a mimic's source joint exists");
            at = next;
        }
        while let Some(joint) = pending.pop() {
            #[allow(clippy::expect_used, reason = "invariant: only mimic joints are pending")]
            let m = order[joint].mimic.as_ref().expect("a pending joint mimics another");
            let source = joint_index[m.joint.as_str()];
            // value(joint) = m * value(source) + o, with value(source) = ms * q[dof] + os.
            let motion = match (resolved[source], dof_of[source]) {
                (Some(JointMotion::Mimic { source, dof, multiplier, offset }), _) => JointMotion::Mimic {
                    source,
                    dof,
                    multiplier: m.multiplier * multiplier,
                    offset: m.multiplier * offset + m.offset,
                },
                (_, Some(dof)) => {
                    JointMotion::Mimic { source: JointId(source), dof, multiplier: m.multiplier, offset: m.offset }
                }
                // Unreachable: `check_mimics` ruled out fixed sources and loops, and the walk
                // above resolves a source before the joints that follow it.
                _ => continue,
            };
            resolved[joint] = Some(motion);
        }
    }
    resolved
}
