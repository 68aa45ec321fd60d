//! Random robots for the dynamics tests, and the means of building robots in code: a fixed-seed
//! generator of trees with revolute, prismatic, fixed and mimic joints, a floating base or planar
//! and spherical joints, and solids, point masses and massless links.
//!
//! The checks' tests reach it as `common::dynamics_robots`; `kinematics-runtime/tests/dynamics.rs`
//! includes this file by path for its hand-worked robots, so it names only `kinematics_model` and
//! nalgebra, which both crates have.
#![allow(dead_code)] // each test uses some of the helpers

use std::f64::consts::PI;

use kinematics_model::inertia::Inertial;
use kinematics_model::{
    Angle, Description, Element, FixedTransform, InertialDescription, JointDescription, JointKind, JointMotion,
    JointTypeDescription, KinematicTree, LimitsDescription, MimicDescription,
};
use nalgebra::{Matrix3, UnitQuaternion, Vector3};

/// Standard gravity (m/s^2).
pub const G: f64 = 9.81;

// ---------------------------------------------------------------------------------------------
// Building robots in code.

pub fn radians(rpy: [f64; 3]) -> [Angle; 3] {
    rpy.map(Angle::Radians)
}

pub fn joint(name: &str, kind: JointTypeDescription, parent: &str, child: &str) -> JointDescription {
    let limits = matches!(kind, JointTypeDescription::Revolute | JointTypeDescription::Prismatic)
        .then_some(LimitsDescription { lower: -3.0, upper: 3.0, velocity: None, effort: None });
    JointDescription {
        name: name.to_owned(),
        element: Element::Joint(name.to_owned()),
        kind,
        parent: parent.to_owned(),
        child: child.to_owned(),
        origin: FixedTransform::identity(),
        after_motion: FixedTransform::identity(),
        axis: [0.0, 0.0, 1.0],
        limits,
        mimic: None,
    }
}

pub fn inertial(link: &str, mass: f64, xyz: [f64; 3], rpy: [f64; 3], inertia: [f64; 6]) -> InertialDescription {
    InertialDescription {
        link: link.to_owned(),
        line: None,
        inertial: Inertial { mass, origin: FixedTransform::from_xyz_rpy(xyz, radians(rpy)), inertia },
    }
}

pub fn robot(
    name: &str,
    links: &[&str],
    joints: Vec<JointDescription>,
    inertials: Vec<InertialDescription>,
) -> Description {
    Description {
        name: name.to_owned(),
        links: links.iter().map(|l| (*l).to_owned()).collect(),
        joints,
        inertials,
        ..Description::default()
    }
}

// ---------------------------------------------------------------------------------------------
// Comparisons (NaN and infinities fail: their error is never `<= rel`).

/// `got` within `rel` of `want`, relative to `want`'s largest entry (the torques' scale).
#[track_caller]
pub fn assert_close(got: &[f64], want: &[f64], rel: f64, what: &str) {
    assert_close_at(got, want, rel, 0.0, what);
}

/// [`assert_close`] relative to `scale` where `want` is smaller (accelerations that are zero
/// come out of a solve as rounding: relative to `tau / M`).
#[track_caller]
pub fn assert_close_at(got: &[f64], want: &[f64], rel: f64, scale: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}");
    let scale = want.iter().fold(scale.max(1e-300), |s, w| if w.abs() > s { w.abs() } else { s });
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        let error = (g - w).abs() / scale;
        assert!(error <= rel, "{what}[{k}]: {g} against {w} (relative {error:.2e})\n got {got:?}\nwant {want:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Random robots.

/// SplitMix64: a deterministic stream of numbers, the same on every machine.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    pub fn vector(&mut self, r: f64) -> [f64; 3] {
        [self.range(-r, r), self.range(-r, r), self.range(-r, r)]
    }

    pub fn rotation(&mut self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_euler_angles(self.range(-PI, PI), self.range(-PI, PI), self.range(-PI, PI))
    }

    /// A solid box's tensor about its centre (so positive definite, with the triangle
    /// inequality), turned by a random rotation: products of inertia in every entry.
    pub fn tensor(&mut self, mass: f64) -> [f64; 6] {
        let [a, b, c] = [self.range(0.05, 0.5), self.range(0.05, 0.5), self.range(0.05, 0.5)];
        let principal =
            Matrix3::from_diagonal(&Vector3::new(b * b + c * c, a * a + c * c, a * a + b * b)) * (mass / 12.0);
        let turn = self.rotation().to_rotation_matrix().into_inner();
        let t = turn * principal * turn.transpose();
        [t[(0, 0)], t[(0, 1)], t[(0, 2)], t[(1, 1)], t[(1, 2)], t[(2, 2)]]
    }
}

/// What a random robot may hold beyond revolute, prismatic, fixed and mimic joints.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Variant {
    Fixed,
    FloatingBase,
    PlanarAndSpherical,
}

/// A random tree of 3 to 7 moving or fixed joints with random origins, transforms after the
/// motion, axes and inertias (every leaf a solid; inner links solid, point masses or massless),
/// one joint a mimic of another.
pub fn random_robot(seed: u64, variant: Variant) -> Description {
    let mut rng = Rng(seed);
    let n = 3 + rng.below(5);
    let links: Vec<String> = std::iter::once("base".to_owned()).chain((1..=n).map(|i| format!("l{i}"))).collect();
    let mut joints = Vec::new();
    let special = [rng.below(n), rng.below(n)];
    for i in 1..=n {
        let parent = if rng.range(0.0, 1.0) < 0.6 { i - 1 } else { rng.below(i) };
        let roll = rng.range(0.0, 1.0);
        let mut kind = match roll {
            r if r < 0.55 => JointTypeDescription::Revolute,
            r if r < 0.8 => JointTypeDescription::Prismatic,
            _ => JointTypeDescription::Fixed,
        };
        if variant == Variant::PlanarAndSpherical && i - 1 == special[0] {
            kind = JointTypeDescription::Planar;
        } else if variant == Variant::PlanarAndSpherical && i - 1 == special[1] {
            kind = JointTypeDescription::Ball;
        }
        let mut j = joint(&format!("j{i}"), kind, &links[parent], &links[i]);
        j.origin = FixedTransform::from_xyz_rpy(rng.vector(0.6), radians(rng.vector(PI)));
        // Half the joints with a transform after the motion (standard DH's constants, an MJCF
        // joint off its body's origin).
        if rng.range(0.0, 1.0) < 0.5 {
            j.after_motion = FixedTransform::from_xyz_rpy(rng.vector(0.4), radians(rng.vector(PI)));
        }
        j.axis = loop {
            let axis = rng.vector(1.0);
            if axis.iter().map(|x| x * x).sum::<f64>() > 0.1 {
                break axis;
            }
        };
        joints.push(j);
    }
    // One mimic: a revolute or prismatic joint following another.
    let single: Vec<usize> = (0..n)
        .filter(|&i| matches!(joints[i].kind, JointTypeDescription::Revolute | JointTypeDescription::Prismatic))
        .collect();
    if single.len() >= 2 {
        let follower = single[1 + rng.below(single.len() - 1)];
        let source = single[rng.below(single.iter().position(|&i| i == follower).unwrap_or(1))];
        let multiplier = if rng.range(0.0, 1.0) < 0.5 { rng.range(-1.5, -0.3) } else { rng.range(0.3, 1.5) };
        joints[follower].mimic =
            Some(MimicDescription { joint: joints[source].name.clone(), multiplier, offset: rng.range(-0.3, 0.3) });
    }
    // Leaves are solids, and so are the base (a floating base's trunk) and a planar or ball
    // joint's child: massless, they would leave a body more velocities than it has independent
    // motions (a massless trunk's six and the next joint's; a ball's three and a planar joint's
    // three, its turn a ball turn plus a slide), a singular mass matrix.
    let parents: std::collections::BTreeSet<&str> = joints.iter().map(|j| j.parent.as_str()).collect();
    let several: std::collections::BTreeSet<&str> = joints
        .iter()
        .filter(|j| matches!(j.kind, JointTypeDescription::Planar | JointTypeDescription::Ball))
        .map(|j| j.child.as_str())
        .collect();
    let mut inertials = Vec::new();
    for link in &links {
        let roll = rng.range(0.0, 1.0);
        let mass = rng.range(0.3, 4.0);
        let (xyz, rpy) = (rng.vector(0.3), rng.vector(PI));
        let solid = !parents.contains(link.as_str()) || several.contains(link.as_str()) || link == "base";
        if solid || roll < 0.6 {
            let tensor = rng.tensor(mass);
            inertials.push(inertial(link, mass, xyz, rpy, tensor));
        } else if roll < 0.8 {
            inertials.push(inertial(link, mass, xyz, rpy, [0.0; 6]));
        }
    }
    let names: Vec<&str> = links.iter().map(String::as_str).collect();
    let description = robot(&format!("random{seed}"), &names, joints, inertials);
    if variant == Variant::FloatingBase { description.with_floating_base("world") } else { description }
}

/// A random configuration: each independent joint's entries of `q` (unit quaternions for
/// floating and spherical joints).
pub fn random_q(tree: &KinematicTree, rng: &mut Rng) -> Vec<f64> {
    let mut q = vec![0.0; tree.dof()];
    for joint in tree.joints() {
        let JointMotion::Dof(start) = joint.motion else { continue };
        let entries = &mut q[start..start + joint.kind.positions()];
        match joint.kind {
            JointKind::Floating | JointKind::Spherical => {
                let turn = rng.rotation().into_inner();
                let n = entries.len();
                entries[..n - 4].copy_from_slice(&rng.vector(1.0)[..n - 4]);
                entries[n - 4..].copy_from_slice(&[turn.i, turn.j, turn.k, turn.w]);
            }
            JointKind::Prismatic => entries[0] = rng.range(-0.5, 0.5),
            JointKind::Planar => {
                entries.copy_from_slice(&[rng.range(-0.5, 0.5), rng.range(-0.5, 0.5), rng.range(-PI, PI)])
            }
            _ => entries[0] = rng.range(-2.5, 2.5),
        }
    }
    q
}

pub fn random_vector(n: usize, rng: &mut Rng) -> Vec<f64> {
    (0..n).map(|_| rng.range(-1.5, 1.5)).collect()
}

/// The random robots the dynamics tests run on: 60 seeds, the variants in turn (every one with a
/// mimic joint where it has two single-axis joints).
pub fn random_cases() -> impl Iterator<Item = (u64, Variant)> {
    (0..60u64)
        .map(|seed| (seed, [Variant::Fixed, Variant::FloatingBase, Variant::PlanarAndSpherical][seed as usize % 3]))
}
