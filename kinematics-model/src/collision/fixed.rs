//! Sphere pairs held apart for good: two spheres of a checked pair of links whose distance no
//! joint can change, because each joint between their links turns about an axis one of the
//! centres lies on (or, a spherical joint, about a point it sits at). Such a pair never collides and
//! its distance is a constant, so it would cap the clearance at that constant with a zero
//! gradient: the distances (clearance, proximity cost) leave it out, while the checks keep it.
//! VAMP's spherized Panda has two (`panda_link5` against `panda_link7`, 1.5 and 2.5 cm apart:
//! `panda_link5`'s spheres on joint 6's axis, `panda_link7`'s on joint 7's), and the UR5 two
//! (`base_link` against `upper_arm_link`, 2.5 mm apart; `shoulder_link` against `forearm_link`,
//! 27 cm).
//!
//! The rule is a selection shared by the compiler and the runtime reference, as the pairs are; it
//! carries points through the fixed transforms of the tree in floating point, which is all the
//! transform math it needs. Its tests hold it to distances sampled through the reference's
//! forward kinematics.
//!
//! `fixed_apart_pairs` carries each centre towards the links' common ancestor through every joint
//! whose axis it lies on; where both meet, no joint changes their distance. The compiler and the
//! reference both leave these pairs out of the distances.

use crate::JointKind;
use crate::collision::LinkSphere;
use crate::tree::{JointId, KinematicTree, LinkId};

/// How far (m) a centre may lie from a joint's axis (or a spherical joint's centre) and count as on
/// it: far below any sphere's size, and above the rounding of axes written to 12 digits.
pub const ON_AXIS: f64 = 1e-9;

/// Two spheres (indices into the robot's spheres, `a < b`) whose signed distance is the same in
/// every configuration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FixedPair {
    /// The sphere on the pair's first link.
    pub a: usize,
    /// The sphere on the pair's second link.
    pub b: usize,
    /// Their signed distance (m): the distance between the centres less both radii.
    pub distance: f64,
}

/// The sphere pairs of the link pairs `pairs` (each `(a, b)` with `a` first in tree order) held
/// a positive distance apart in every configuration, in the order of `pairs` and then of the
/// spheres. A pair at a fixed distance of zero or less collides everywhere and is not listed:
/// the distances keep it, as the checks do.
pub fn fixed_apart_pairs(tree: &KinematicTree, spheres: &[LinkSphere], pairs: &[(LinkId, LinkId)]) -> Vec<FixedPair> {
    let center = |s: &LinkSphere| s.sphere.center;
    let mut out = Vec::new();
    for &(link_a, link_b) in pairs {
        for (a, sa) in spheres.iter().enumerate().filter(|(_, s)| s.link == link_a) {
            for (b, sb) in spheres.iter().enumerate().filter(|(_, s)| s.link == link_b) {
                let Some(gap) = fixed_gap(tree, (link_a, center(sa)), (link_b, center(sb))) else { continue };
                let distance = gap - sa.sphere.radius - sb.sphere.radius;
                if distance > 0.0 {
                    out.push(FixedPair { a: a.min(b), b: a.max(b), distance });
                }
            }
        }
    }
    out
}

/// The distance between the point `pa` of link `a` and `pb` of link `b` (each in its link's
/// frame) if no joint can change it: each point is carried towards the links' common ancestor
/// through every joint it lies on the axis of, and the one that gets there down the other's side
/// as far as that one got. `None` where a joint between them moves one of them.
fn fixed_gap(tree: &KinematicTree, (a, pa): (LinkId, [f64; 3]), (b, pb): (LinkId, [f64; 3])) -> Option<f64> {
    let (up_a, up_b) = paths(tree, a, b);
    let (xa, na) = carry_up(tree, &up_a, pa);
    let (xb, nb) = carry_up(tree, &up_b, pb);
    let (x, y) = match (na == up_a.len(), nb == up_b.len()) {
        (true, true) => (xa, xb),
        // A's point reached the common ancestor: down B's side to where B's point stopped.
        (true, false) => (carry_down(tree, &up_b[nb..], xa)?, xb),
        (false, true) => (xa, carry_down(tree, &up_a[na..], xb)?),
        (false, false) => return None,
    };
    Some(distance(x, y))
}

/// The joints from `a` and from `b` up to their nearest common ancestor, each list from its link
/// upwards.
pub(super) fn paths(tree: &KinematicTree, a: LinkId, b: LinkId) -> (Vec<JointId>, Vec<JointId>) {
    let ancestors = |mut link: LinkId| {
        let mut chain = vec![(link, None)];
        while let Some(j) = tree.link(link).parent_joint {
            link = tree.joint(j).parent;
            chain.push((link, Some(j)));
        }
        chain
    };
    let (from_a, from_b) = (ancestors(a), ancestors(b));
    // The nearest common ancestor: the first link of `a`'s line that `b`'s line holds.
    #[allow(clippy::expect_used, reason = "invariant: both lines end at the tree's one root")]
    let (ia, ib) = from_a
        .iter()
        .enumerate()
        .find_map(|(i, (link, _))| from_b.iter().position(|(l, _)| l == link).map(|k| (i, k)))
        .expect("two links of one tree share its root");
    let joints =
        |line: &[(LinkId, Option<JointId>)], end: usize| line[1..=end].iter().filter_map(|(_, j)| *j).collect();
    (joints(&from_a, ia), joints(&from_b, ib))
}

/// Whether `y`, in a joint's frame, stays where it is as the joint moves.
fn unmoved(tree: &KinematicTree, joint: JointId, y: [f64; 3]) -> bool {
    let joint = tree.joint(joint);
    match joint.kind {
        JointKind::Fixed => true,
        JointKind::Revolute | JointKind::Continuous => {
            let u = joint.axis;
            let along = y[0] * u[0] + y[1] * u[1] + y[2] * u[2];
            distance(y, [along * u[0], along * u[1], along * u[2]]) <= ON_AXIS
        }
        JointKind::Spherical => distance(y, [0.0; 3]) <= ON_AXIS,
        JointKind::Prismatic | JointKind::Floating | JointKind::Planar => false,
    }
}

/// `p` (in the frame of the first joint's child) carried up through the joints `up` while the
/// joints leave it where it is: the point in the last frame reached, and how many joints it
/// passed.
fn carry_up(tree: &KinematicTree, up: &[JointId], mut p: [f64; 3]) -> ([f64; 3], usize) {
    for (passed, &j) in up.iter().enumerate() {
        let joint = tree.joint(j);
        let y = joint.after_motion.apply(p);
        if !unmoved(tree, j, y) {
            return (p, passed);
        }
        p = joint.origin.apply(y);
    }
    (p, up.len())
}

/// `p` (in the frame of the last joint's parent) carried down through the joints `up` (listed
/// upwards) to the first one's child, if every one leaves it where it is.
fn carry_down(tree: &KinematicTree, up: &[JointId], mut p: [f64; 3]) -> Option<[f64; 3]> {
    for &j in up.iter().rev() {
        let joint = tree.joint(j);
        let y = joint.origin.apply_inverse(p);
        if !unmoved(tree, j, y) {
            return None;
        }
        p = joint.after_motion.apply_inverse(y);
    }
    Some(p)
}

/// The distance between two points.
pub(super) fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::angle::Angle;
    use crate::transform::{Axis, FixedTransform};

    #[test]
    fn a_transform_and_its_inverse_return_a_point() {
        let t = FixedTransform::from_xyz_rpy([0.1, -0.2, 0.3], [0.4, -0.5, 0.6].map(Angle::Radians))
            .rotate(Axis::Z, Angle::Radians(1.2));
        let p = [0.7, 0.8, -0.9];
        let back = t.apply_inverse(t.apply(p));
        assert!(distance(back, p) < 1e-15, "{back:?}");
        assert!(distance(t.apply(p), p) > 0.1, "the transform moves the point");
        // A quarter turn about z takes x to y.
        let quarter = FixedTransform::identity().rotate(Axis::Z, Angle::Radians(std::f64::consts::FRAC_PI_2));
        assert!(distance(quarter.apply([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]) < 1e-15);
    }
}
