//! A chain's geometry at its zero configuration, in numbers: each moving joint's axis and a point
//! on it, and the tip's pose, all in the base frame. Quarter turns the model holds exactly give
//! exact zeros and ones here (no `cos(pi/2) = 6e-17`), so axes written parallel or meeting are
//! found so exactly.

use kinematics_model::{Angle, Axis, Elementary, FixedTransform, JointKind, JointMotion, KinematicTree};

/// A 3-vector.
pub type V3 = [f64; 3];
/// A rotation, row-major.
pub type M3 = [[f64; 3]; 3];

/// A moving joint at the zero configuration.
#[derive(Debug, Clone, PartialEq)]
pub struct ZeroJoint {
    /// Joint name.
    pub name: String,
    /// How it moves.
    pub kind: JointKind,
    /// Its unit axis in the base frame.
    pub axis: V3,
    /// Its frame's origin in the base frame: a point on the axis.
    pub point: V3,
}

/// The chain from a base to a tip at `q = 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct ZeroConfiguration {
    /// The moving joints, base first.
    pub joints: Vec<ZeroJoint>,
    /// The tip's rotation in the base frame.
    pub tip_rotation: M3,
    /// The tip's origin in the base frame.
    pub tip_point: V3,
    /// The length of the path base -> joint points -> tip: the scale of the chain's distances.
    pub reach: f64,
}

/// A joint of the chain no closed form takes, with why.
#[derive(Debug, Clone, PartialEq)]
pub struct UnsupportedJoint {
    /// Joint name.
    pub joint: String,
    /// What it is.
    pub why: String,
}

/// A rigid transform in numbers.
#[derive(Debug, Clone, Copy)]
struct Rigid {
    r: M3,
    t: V3,
}

const IDENTITY: Rigid = Rigid { r: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], t: [0.0; 3] };

/// `(sin, cos)` of an angle, exact for exact multiples of a quarter turn.
fn sin_cos(angle: Angle) -> (f64, f64) {
    if let Some(exact) = angle.exact() {
        let (num, den) = (exact.num(), exact.den());
        if let Some(twice) = num.checked_mul(2)
            && twice % den == 0
        {
            return match (twice / den).rem_euclid(4) {
                0 => (0.0, 1.0),
                1 => (1.0, 0.0),
                2 => (0.0, -1.0),
                _ => (-1.0, 0.0),
            };
        }
    }
    angle.radians().sin_cos()
}

pub(crate) fn mul_v(r: &M3, v: V3) -> V3 {
    [0, 1, 2].map(|i| r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2])
}

fn then(a: Rigid, step: &Elementary) -> Rigid {
    match *step {
        Elementary::Translation(v) => {
            let d = mul_v(&a.r, v);
            Rigid { r: a.r, t: [a.t[0] + d[0], a.t[1] + d[1], a.t[2] + d[2]] }
        }
        Elementary::Rotation(axis, angle) => {
            let (s, c) = sin_cos(angle);
            let e: M3 = match axis {
                Axis::X => [[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]],
                Axis::Y => [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]],
                Axis::Z => [[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]],
            };
            let r = [0, 1, 2].map(|i| [0, 1, 2].map(|j| (0..3).map(|k| a.r[i][k] * e[k][j]).sum()));
            Rigid { r, t: a.t }
        }
    }
}

fn apply(a: Rigid, transform: &FixedTransform) -> Rigid {
    transform.steps().iter().fold(a, then)
}

fn distance(a: V3, b: V3) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// The chain's joints (`chain` from [`KinematicTree::chain`]) folded at `q = 0`; every joint
/// that is not revolute, continuous or prismatic, and every mimic joint, is listed instead.
pub fn zero_configuration(
    tree: &KinematicTree,
    chain: &kinematics_model::Chain,
) -> Result<ZeroConfiguration, Vec<UnsupportedJoint>> {
    let mut frame = IDENTITY;
    let mut joints = Vec::new();
    let mut unsupported = Vec::new();
    for &id in &chain.joints {
        let joint = tree.joint(id);
        frame = apply(frame, &joint.origin);
        match (joint.kind, joint.motion) {
            (JointKind::Fixed, _) => {}
            (_, JointMotion::Mimic { source, .. }) => unsupported.push(UnsupportedJoint {
                joint: joint.name.clone(),
                why: format!("mimics `{}`", tree.joint(source).name),
            }),
            (JointKind::Revolute | JointKind::Continuous | JointKind::Prismatic, _) => joints.push(ZeroJoint {
                name: joint.name.clone(),
                kind: joint.kind,
                axis: mul_v(&frame.r, joint.axis),
                point: frame.t,
            }),
            (kind, _) => unsupported
                .push(UnsupportedJoint { joint: joint.name.clone(), why: format!("is a {} joint", kind.name()) }),
        }
        frame = apply(frame, &joint.after_motion);
    }
    if !unsupported.is_empty() {
        return Err(unsupported);
    }
    let mut reach = 0.0;
    let mut at = [0.0; 3];
    for point in joints.iter().map(|j| j.point).chain([frame.t]) {
        reach += distance(at, point);
        at = point;
    }
    Ok(ZeroConfiguration { joints, tip_rotation: frame.r, tip_point: frame.t, reach })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quarter_turns_are_exact() {
        for (num, expected) in [(0, (0.0, 1.0)), (1, (1.0, 0.0)), (2, (0.0, -1.0)), (3, (-1.0, 0.0)), (-1, (-1.0, 0.0))]
        {
            let angle = Angle::Exact(kinematics_model::PiRational::new(num, 2).expect("a valid fraction"));
            assert_eq!(sin_cos(angle), expected, "{num} pi/2");
        }
    }

    #[test]
    fn a_dh_arm_at_zero() {
        let dh = "convention = \"standard\"\n[[joints]]\nname = \"j1\"\nd = 0.5\nalpha = \"pi/2\"\n[[joints]]\nname = \"j2\"\na = 1.0\n";
        let tree = kinematics_model::parse_source("arm.toml", dh).expect("a valid table");
        let chain = tree.chain("base", "link2").expect("a chain");
        let zero = zero_configuration(&tree, &chain).expect("revolute joints");
        assert_eq!(zero.joints.len(), 2);
        assert_eq!(zero.joints[0].axis, [0.0, 0.0, 1.0]);
        // After Rx(pi/2), the second axis is -y exactly.
        assert_eq!(zero.joints[1].axis, [0.0, -1.0, 0.0]);
        assert_eq!(zero.joints[1].point, [0.0, 0.0, 0.5]);
        assert_eq!(zero.tip_point, [1.0, 0.0, 0.5]);
    }
}
