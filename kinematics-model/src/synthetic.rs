//! Synthetic robots of any size, for benchmarks and scaling tests.
//!
//! They are built through the same description path as files, so they are ordinary validated trees.

use crate::angle::{Angle, PiRational};
use crate::description::{Description, JointDescription, JointTypeDescription, LimitsDescription};
use crate::error::Element;
use crate::transform::{Axis, FixedTransform};
use crate::tree::KinematicTree;

const QUARTER: Angle = Angle::Exact(match PiRational::new_const(1, 2) {
    Some(r) => r,
    None => PiRational::ZERO,
});

/// A serial arm of `n` revolute joints in standard DH form, repeating an industrial pattern:
/// twists `pi/2, 0, 0, pi/2, -pi/2, 0` (shoulder, two parallel elbow joints, a spherical wrist),
/// with link lengths and offsets that differ from joint to joint.
pub fn dh_chain(n: usize) -> KinematicTree {
    let twists = [1, 0, 0, 1, -1, 0];
    let mut description =
        Description { name: format!("chain{n}"), links: vec!["base".to_owned()], ..Description::default() };
    for i in 0..n {
        let twist = match twists[i % 6] {
            0 => Angle::ZERO,
            1 => QUARTER,
            _ => Angle::Exact(PiRational::new(-1, 2).unwrap_or(PiRational::ZERO)),
        };
        let a = if twists[i % 6] == 0 { 0.3 + 0.01 * i as f64 } else { 0.0 };
        let d = if twists[i % 6] != 0 { 0.1 + 0.005 * i as f64 } else { 0.0 };
        let after = FixedTransform::identity().translate([0.0, 0.0, d]).translate([a, 0.0, 0.0]).rotate(Axis::X, twist);
        description.joints.push(revolute(
            &format!("j{}", i + 1),
            &description.links[i],
            &format!("link{}", i + 1),
            FixedTransform::identity(),
            after,
            [0.0, 0.0, 1.0],
        ));
        description.links.push(format!("link{}", i + 1));
    }
    build(&description)
}

/// A branching tree: a torso with `limbs` serial limbs of `joints_per_limb` joints each, URDF style
/// (origins with offsets and rotations, axes cycling through y, x, z), plus a fixed tool frame at
/// the end of every limb.
pub fn tree(limbs: usize, joints_per_limb: usize) -> KinematicTree {
    let mut description = Description {
        name: format!("tree{limbs}x{joints_per_limb}"),
        links: vec!["torso".to_owned()],
        ..Description::default()
    };
    let axes = [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
    for limb in 0..limbs {
        let mut parent = "torso".to_owned();
        for k in 0..joints_per_limb {
            let child = format!("limb{limb}_link{k}");
            let yaw = Angle::Radians(0.3 * limb as f64);
            let origin = if k == 0 {
                FixedTransform::from_xyz_rpy([0.1 * limb as f64, 0.2, 0.3], [Angle::ZERO, Angle::ZERO, yaw])
            } else {
                FixedTransform::from_xyz_rpy([0.0, 0.05, 0.25], [Angle::ZERO, Angle::ZERO, Angle::ZERO])
            };
            let joint = revolute(
                &format!("limb{limb}_joint{k}"),
                &parent,
                &child,
                origin,
                FixedTransform::identity(),
                axes[k % 3],
            );
            description.joints.push(joint);
            description.links.push(child.clone());
            parent = child;
        }
        let tool = format!("limb{limb}_tool");
        let mut fixed = revolute(
            &format!("{tool}_joint"),
            &parent,
            &tool,
            FixedTransform::identity().translate([0.0, 0.0, 0.1]),
            FixedTransform::identity(),
            [0.0, 0.0, 1.0],
        );
        fixed.kind = JointTypeDescription::Fixed;
        fixed.limits = None;
        description.joints.push(fixed);
        description.links.push(tool);
    }
    build(&description)
}

fn revolute(
    name: &str,
    parent: &str,
    child: &str,
    origin: FixedTransform,
    after_motion: FixedTransform,
    axis: [f64; 3],
) -> JointDescription {
    JointDescription {
        name: name.to_owned(),
        element: Element::Joint(name.to_owned()),
        kind: JointTypeDescription::Revolute,
        parent: parent.to_owned(),
        child: child.to_owned(),
        origin,
        after_motion,
        axis,
        limits: Some(LimitsDescription { lower: -3.0, upper: 3.0, velocity: None, effort: None }),
        mimic: None,
    }
}

/// Synthetic descriptions are valid by construction (unique names, one root, finite numbers,
/// unit axes), which the unit tests below check for every generator.
#[allow(clippy::expect_used, reason = "an invariant of this module, named in the message")]
fn build(description: &Description) -> KinematicTree {
    KinematicTree::from_description(description).expect("synthetic descriptions are valid by construction")
}

#[cfg(test)]
mod tests {
    #[test]
    fn sizes() {
        let chain = super::dh_chain(48);
        assert_eq!((chain.dof(), chain.links().len()), (48, 49));
        let tree = super::tree(4, 10);
        assert_eq!((tree.dof(), tree.links().len()), (40, 45));
    }
}
