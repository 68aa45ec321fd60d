//! The reference dynamics (`ReferenceDynamics`) against hand-worked closed forms, against
//! identities that need no second implementation (on random robots with fixed, mimic, planar,
//! spherical and floating joints, checked through the forward kinematics and its Jacobians), and
//! on bad input.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::f64::consts::PI;

use kinematics_model::inertia::{InertiaFault, Inertial};
use kinematics_model::{
    Angle, Description, Element, FixedTransform, InertialDescription, JointDescription, JointKind, JointMotion,
    JointTypeDescription, KinematicTree, LimitsDescription, MimicDescription,
};
use kinematics_runtime::{DynamicsError, ReferenceDynamics, RuntimeError, fixed_isometry};
use nalgebra::{DMatrix, DVector, Matrix3, Matrix3xX, Quaternion, UnitQuaternion, Vector3};

const G: f64 = 9.81;

// ---------------------------------------------------------------------------------------------
// Building robots in code.

fn radians(rpy: [f64; 3]) -> [Angle; 3] {
    rpy.map(Angle::Radians)
}

fn joint(name: &str, kind: JointTypeDescription, parent: &str, child: &str) -> JointDescription {
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

fn inertial(link: &str, mass: f64, xyz: [f64; 3], rpy: [f64; 3], inertia: [f64; 6]) -> InertialDescription {
    InertialDescription {
        link: link.to_owned(),
        line: None,
        inertial: Inertial { mass, origin: FixedTransform::from_xyz_rpy(xyz, radians(rpy)), inertia },
    }
}

fn robot(
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

fn dynamics(description: &Description, gravity: [f64; 3]) -> ReferenceDynamics {
    ReferenceDynamics::new(KinematicTree::from_description(description).unwrap(), gravity, false).unwrap()
}

/// `got` within `rel` of `want`, relative to `want`'s largest entry (the torques' scale).
fn assert_close(got: &[f64], want: &[f64], rel: f64, what: &str) {
    assert_close_at(got, want, rel, 0.0, what);
}

/// [`assert_close`] relative to `scale` where `want` is smaller (accelerations that are zero
/// come out of a solve as rounding: relative to `tau / M`).
fn assert_close_at(got: &[f64], want: &[f64], rel: f64, scale: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}");
    let scale = want.iter().fold(scale.max(1e-300), |s, w| if w.abs() > s { w.abs() } else { s });
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        let error = (g - w).abs() / scale;
        assert!(error <= rel, "{what}[{k}]: {g} against {w} (relative {error:.2e})\n got {got:?}\nwant {want:?}");
    }
}

fn matrix_entries(m: &DMatrix<f64>) -> Vec<f64> {
    m.iter().copied().collect()
}

// ---------------------------------------------------------------------------------------------
// Hand-worked cases.

/// The URDF rotation `Rz(yaw) Ry(pitch) Rx(roll)` written out (reference notes, URDF), rows first.
fn rpy_matrix([r, p, y]: [f64; 3]) -> [[f64; 3]; 3] {
    let (cr, sr, cp, sp, cy, sy) = (r.cos(), r.sin(), p.cos(), p.sin(), y.cos(), y.sin());
    [
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ]
}

/// A pendulum: a bob of mass m whose centre of mass is l below a hinge about y, gravity g along
/// -z. Turned by q about y, the centre of mass is at `Ry(q) (0, 0, -l) = (-l sin q, 0, -l cos q)`,
/// so the potential is `V = -m g l cos q` and the torque that holds it is `dV/dq = m g l sin q`
/// (positive: gravity turns a bob at q > 0 back, about -y). Its inertia about the hinge is
/// `m l^2 + I_yy`, `I_yy` the bob's own moment about y through its centre of mass: with the tensor
/// `diag(d)` written in a frame turned by `R = rpy(0.3, 0.5, 0.7)` from the link's,
/// `I_yy = (R diag(d) R^T)_yy = sum_k R_yk^2 d_k`. One joint: no Coriolis or centrifugal term, so
/// `tau = (m l^2 + I_yy) a + m g l sin q`.
#[test]
fn pendulum_by_hand() {
    let (m, l, d, rpy) = (1.7, 0.8, [0.02, 0.03, 0.04], [0.3, 0.5, 0.7]);
    let mut hinge = joint("hinge", JointTypeDescription::Continuous, "base", "bob");
    hinge.axis = [0.0, 1.0, 0.0];
    let description = robot(
        "pendulum",
        &["base", "bob"],
        vec![hinge],
        vec![inertial("bob", m, [0.0, 0.0, -l], rpy, [d[0], 0.0, 0.0, d[1], 0.0, d[2]])],
    );
    let dynamics = dynamics(&description, [0.0, 0.0, -G]);
    let r = rpy_matrix(rpy);
    let i_yy: f64 = (0..3).map(|k| r[1][k] * r[1][k] * d[k]).sum();
    let inertia = m * l * l + i_yy;
    for (q, v, a) in [(0.0, 0.0, 0.0), (0.3, -1.2, 0.7), (2.0, 0.5, -3.0), (-2.9, 4.0, 1.5), (PI / 2.0, 0.0, 0.0)] {
        let hold = m * G * l * q.sin();
        assert_close(&dynamics.gravity_torques(&[q]).unwrap(), &[hold], 1e-12, "gravity");
        assert_close(&dynamics.nonlinear_effects(&[q], &[v]).unwrap(), &[hold], 1e-12, "h");
        assert_close(&matrix_entries(&dynamics.mass_matrix(&[q]).unwrap()), &[inertia], 1e-12, "M");
        let tau = inertia * a + hold;
        assert_close(&dynamics.inverse_dynamics(&[q], &[v], &[a]).unwrap(), &[tau], 1e-12, "tau");
        let a_scale = tau.abs() / inertia;
        assert_close_at(&dynamics.forward_dynamics(&[q], &[v], &[tau]).unwrap(), &[a], 1e-12, a_scale, "a");
    }
}

/// The two-link planar arm ("planar elbow manipulator") of Spong, Hutchinson and Vidyasagar,
/// *Robot Modeling and Control* (Wiley, 2006), ch. 7: links of length l1, l2 turning about z,
/// centres of mass at lc1, lc2 along them, masses m1, m2, moments I1, I2 about z through the centres
/// of mass, gravity g along -y, q1 from the x axis, q2 relative to link 1:
///
/// ```text
/// M11 = m1 lc1^2 + m2 (l1^2 + lc2^2 + 2 l1 lc2 cos q2) + I1 + I2
/// M12 = M21 = m2 (lc2^2 + l1 lc2 cos q2) + I2
/// M22 = m2 lc2^2 + I2
/// h = -m2 l1 lc2 sin q2 (Christoffel symbols c121 = c211 = c221 = h, c112 = -h, others zero)
/// phi1 = (m1 lc1 + m2 l1) g cos q1 + m2 lc2 g cos(q1 + q2),  phi2 = m2 lc2 g cos(q1 + q2)
/// tau1 = M11 a1 + M12 a2 + 2 h v1 v2 + h v2^2 + phi1
/// tau2 = M21 a1 + M22 a2 - h v1^2 + phi2
/// ```
///
/// The links' tensors have z principal (an `ixy` product, a frame flipped about x and turned
/// about z), so only I1 and I2 act in the plane.
struct PlanarArm {
    m1: f64,
    m2: f64,
    l1: f64,
    lc1: f64,
    lc2: f64,
    i1: f64,
    i2: f64,
}

impl PlanarArm {
    const ARM: PlanarArm = PlanarArm { m1: 2.3, m2: 1.4, l1: 0.9, lc1: 0.42, lc2: 0.35, i1: 0.11, i2: 0.06 };

    fn description(&self, mimic: Option<(f64, f64)>) -> Description {
        let j1 = joint("shoulder", JointTypeDescription::Revolute, "base", "upper");
        let mut j2 = joint("elbow", JointTypeDescription::Revolute, "upper", "fore");
        j2.origin = FixedTransform::identity().translate([self.l1, 0.0, 0.0]);
        j2.mimic = mimic.map(|(multiplier, offset)| MimicDescription { joint: "shoulder".into(), multiplier, offset });
        let tensor = |i: f64| [0.6 * i, 0.05 * i, 0.0, 0.7 * i, 0.0, i];
        robot(
            "planar_arm",
            &["base", "upper", "fore"],
            vec![j1, j2],
            vec![
                inertial("upper", self.m1, [self.lc1, 0.0, 0.0], [0.0, 0.0, 0.4], tensor(self.i1)),
                inertial("fore", self.m2, [self.lc2, 0.0, 0.0], [PI, 0.0, -1.1], tensor(self.i2)),
            ],
        )
    }

    fn mass_matrix(&self, q2: f64) -> [[f64; 2]; 2] {
        let PlanarArm { m1, m2, l1, lc1, lc2, i1, i2 } = *self;
        let m11 = m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2.0 * l1 * lc2 * q2.cos()) + i1 + i2;
        let m12 = m2 * (lc2 * lc2 + l1 * lc2 * q2.cos()) + i2;
        [[m11, m12], [m12, m2 * lc2 * lc2 + i2]]
    }

    fn gravity(&self, [q1, q2]: [f64; 2]) -> [f64; 2] {
        let PlanarArm { m1, m2, l1, lc1, lc2, .. } = *self;
        let phi2 = m2 * lc2 * G * (q1 + q2).cos();
        [(m1 * lc1 + m2 * l1) * G * q1.cos() + phi2, phi2]
    }

    fn inverse_dynamics(&self, q: [f64; 2], v: [f64; 2], a: [f64; 2]) -> [f64; 2] {
        let m = self.mass_matrix(q[1]);
        let h = -self.m2 * self.l1 * self.lc2 * q[1].sin();
        let phi = self.gravity(q);
        [
            m[0][0] * a[0] + m[0][1] * a[1] + 2.0 * h * v[0] * v[1] + h * v[1] * v[1] + phi[0],
            m[1][0] * a[0] + m[1][1] * a[1] - h * v[0] * v[0] + phi[1],
        ]
    }
}

const ARM_STATES: [([f64; 2], [f64; 2], [f64; 2]); 5] = [
    ([0.0, 0.0], [0.0, 0.0], [0.0, 0.0]),
    ([0.3, -0.7], [1.2, -0.4], [0.5, 2.0]),
    ([1.1, 0.4], [-2.0, 3.0], [-1.0, 0.3]),
    ([-2.5, 2.9], [0.7, 0.7], [0.0, -4.0]),
    ([PI / 2.0, -PI / 2.0], [-1.5, 0.2], [2.5, 1.0]),
];

#[test]
fn two_link_planar_arm_closed_forms() {
    let arm = PlanarArm::ARM;
    let dynamics = dynamics(&arm.description(None), [0.0, -G, 0.0]);
    for (q, v, a) in ARM_STATES {
        let m = arm.mass_matrix(q[1]);
        let got = dynamics.mass_matrix(&q).unwrap();
        assert_close(&matrix_entries(&got), &[m[0][0], m[1][0], m[0][1], m[1][1]], 1e-12, "M");
        assert_close(&dynamics.gravity_torques(&q).unwrap(), &arm.gravity(q), 1e-12, "gravity");
        let h = arm.inverse_dynamics(q, v, [0.0; 2]);
        assert_close(&dynamics.nonlinear_effects(&q, &v).unwrap(), &h, 1e-12, "h");
        let tau = arm.inverse_dynamics(q, v, a);
        assert_close(&dynamics.inverse_dynamics(&q, &v, &a).unwrap(), &tau, 1e-12, "tau");
        let a_scale = tau[0].abs().max(tau[1].abs()) / m[1][1];
        assert_close_at(&dynamics.forward_dynamics(&q, &v, &tau).unwrap(), &a, 1e-12, a_scale, "a");
    }
}

/// The same arm with the elbow mimicking the shoulder, `q2 = k q1 + o`: one velocity, whose
/// generalized force is the shoulder's torque plus k times the elbow's (virtual work: the elbow
/// moves k times as far), and whose inertia is `[1 k] M [1 k]^T`.
#[test]
fn a_mimic_joint_folds_its_torque_into_its_source() {
    let arm = PlanarArm::ARM;
    let (k, o) = (-0.6, 0.25);
    let dynamics = dynamics(&arm.description(Some((k, o))), [0.0, -G, 0.0]);
    assert_eq!(dynamics.tree().velocity_dof(), 1);
    for (q, v, a) in ARM_STATES {
        let (q, v, a) = (q[0], v[0], a[0]);
        let joint_q = [q, k * q + o];
        let m = arm.mass_matrix(joint_q[1]);
        let inertia = m[0][0] + 2.0 * k * m[0][1] + k * k * m[1][1];
        assert_close(&matrix_entries(&dynamics.mass_matrix(&[q]).unwrap()), &[inertia], 1e-12, "M");
        let tau = arm.inverse_dynamics(joint_q, [v, k * v], [a, k * a]);
        let folded = tau[0] + k * tau[1];
        assert_close(&dynamics.inverse_dynamics(&[q], &[v], &[a]).unwrap(), &[folded], 1e-12, "tau");
        let a_scale = folded.abs() / inertia;
        assert_close_at(&dynamics.forward_dynamics(&[q], &[v], &[folded]).unwrap(), &[a], 1e-12, a_scale, "a");
    }
}

/// A free-flying body (Pinocchio's free-flyer: velocities in the body's own axes), let go at
/// rest: it falls with g and does not turn, so its accelerations are `R^T g` (gravity in its axes)
/// and zero, wherever its centre of mass sits; held, it needs the force `-m R^T g` at its centre
/// of mass, whose moment about its origin is `c x (-m R^T g)`.
#[test]
fn a_free_body_falls_in_its_own_axes() {
    let (m, c) = (3.2, [0.2, -0.4, 0.1]);
    let description = robot(
        "body",
        &["body"],
        Vec::new(),
        vec![inertial("body", m, c, [0.4, 0.2, -0.9], [0.3, 0.01, -0.02, 0.25, 0.03, 0.2])],
    )
    .with_floating_base("world");
    let gravity = Vector3::new(0.5, -1.0, -G);
    let dynamics = dynamics(&description, gravity.into());
    let turn = UnitQuaternion::from_euler_angles(0.7, -0.3, 1.9);
    let qc = turn.into_inner();
    let q = [1.0, -2.0, 0.5, qc.i, qc.j, qc.k, qc.w];
    let g_body = turn.inverse() * gravity;
    let a = dynamics.forward_dynamics(&q, &[0.0; 6], &[0.0; 6]).unwrap();
    assert_close(&a, &[g_body.x, g_body.y, g_body.z, 0.0, 0.0, 0.0], 1e-12, "a");
    let force = -m * g_body;
    let moment = Vector3::from(c).cross(&force);
    let hold = dynamics.gravity_torques(&q).unwrap();
    assert_close(&hold, &[force.x, force.y, force.z, moment.x, moment.y, moment.z], 1e-12, "hold");
}

// ---------------------------------------------------------------------------------------------
// Random robots.

/// SplitMix64: a deterministic stream of numbers, the same on every machine.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }

    fn vector(&mut self, r: f64) -> [f64; 3] {
        [self.range(-r, r), self.range(-r, r), self.range(-r, r)]
    }

    fn rotation(&mut self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_euler_angles(self.range(-PI, PI), self.range(-PI, PI), self.range(-PI, PI))
    }

    /// A solid box's tensor about its centre (so positive definite, with the triangle
    /// inequality), turned by a random rotation: products of inertia in every entry.
    fn tensor(&mut self, mass: f64) -> [f64; 6] {
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
enum Variant {
    Fixed,
    FloatingBase,
    PlanarAndSpherical,
}

/// A random tree of 3 to 7 moving or fixed joints with random origins, transforms after the
/// motion, axes and inertias (every leaf a solid; inner links solid, point masses or massless),
/// one joint a mimic of another.
fn random_robot(seed: u64, variant: Variant) -> Description {
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
fn random_q(tree: &KinematicTree, rng: &mut Rng) -> Vec<f64> {
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

fn random_vector(n: usize, rng: &mut Rng) -> Vec<f64> {
    (0..n).map(|_| rng.range(-1.5, 1.5)).collect()
}

/// The configuration reached from `q` in time `t` moving at `v + a t / 2` (right to first order in
/// `t`, which central differences need): `q + v t` for entries whose rate is their velocity; for
/// a quaternion joint, its rotation times `exp((w + alpha t / 2) t)` (angular velocity in its own
/// axes) and a floating joint's position moved by its rotation times its linear velocity.
fn advance(tree: &KinematicTree, q: &[f64], v: &[f64], a: &[f64], t: f64) -> Vec<f64> {
    let mut out = q.to_vec();
    let rate = |k: usize| v[k] + 0.5 * a[k] * t;
    for (index, joint) in tree.joints().iter().enumerate() {
        let JointMotion::Dof(start) = joint.motion else { continue };
        let Some(k) = tree.velocity_start(kinematics_model::JointId(index)) else { continue };
        let quaternion =
            |at: usize| UnitQuaternion::from_quaternion(Quaternion::new(q[at + 3], q[at], q[at + 1], q[at + 2]));
        let turned = |turn: UnitQuaternion<f64>, w: usize| {
            let c = (turn * UnitQuaternion::from_scaled_axis(Vector3::new(rate(w), rate(w + 1), rate(w + 2)) * t))
                .into_inner();
            [c.i, c.j, c.k, c.w]
        };
        match joint.kind {
            JointKind::Floating => {
                let turn = quaternion(start + 3);
                let moved = turn * Vector3::new(rate(k), rate(k + 1), rate(k + 2)) * t;
                for i in 0..3 {
                    out[start + i] += moved[i];
                }
                out[start + 3..start + 7].copy_from_slice(&turned(turn, k + 3));
            }
            JointKind::Spherical => out[start..start + 4].copy_from_slice(&turned(quaternion(start), k)),
            kind => {
                for i in 0..kind.positions() {
                    out[start + i] += rate(k + i) * t;
                }
            }
        }
    }
    out
}

/// One massive link at `(q, v)`, from the forward kinematics alone: its mass, centre of mass and
/// tensor in the root's frame, and the Jacobian of its centre of mass's velocity and of its angular
/// velocity (3 x velocities each).
struct LinkMotion {
    mass: f64,
    com: Vector3<f64>,
    tensor: Matrix3<f64>,
    linear: Matrix3xX<f64>,
    angular: Matrix3xX<f64>,
}

fn link_motions(dynamics: &ReferenceDynamics, q: &[f64]) -> Vec<LinkMotion> {
    let (tree, fk) = (dynamics.tree(), dynamics.fk());
    let poses = fk.link_poses(q).unwrap();
    let root = &tree.link(tree.root()).name;
    let mut out = Vec::new();
    for (i, link) in tree.links().iter().enumerate() {
        let Some(inertial) = &link.inertial else { continue };
        let frame = poses[i] * fixed_isometry(&inertial.origin);
        let turn = frame.rotation.to_rotation_matrix().into_inner();
        let [xx, xy, xz, yy, yz, zz] = inertial.inertia;
        let tensor = turn * Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz) * turn.transpose();
        let jacobian = fk.jacobian(q, root, &link.name).unwrap();
        let angular: Matrix3xX<f64> = jacobian.fixed_rows::<3>(3).into_owned();
        // The centre of mass moves with the origin plus w x r.
        let r = frame.translation.vector - poses[i].translation.vector;
        let linear = jacobian.fixed_rows::<3>(0) - r.cross_matrix() * &angular;
        out.push(LinkMotion { mass: inertial.mass, com: frame.translation.vector, tensor, linear, angular });
    }
    out
}

fn potential(dynamics: &ReferenceDynamics, q: &[f64]) -> f64 {
    let g = Vector3::from(dynamics.gravity());
    link_motions(dynamics, q).iter().map(|l| -l.mass * g.dot(&l.com)).sum()
}

fn kinetic_energy(dynamics: &ReferenceDynamics, q: &[f64], v: &[f64]) -> f64 {
    let v = DVector::from_column_slice(v);
    link_motions(dynamics, q)
        .iter()
        .map(|l| {
            let (vc, w) = (&l.linear * &v, &l.angular * &v);
            0.5 * l.mass * vc.norm_squared() + 0.5 * w.dot(&(l.tensor * w))
        })
        .sum()
}

/// The generalized forces by d'Alembert's principle: each link's Newton-Euler wrench about its
/// centre of mass (`d/dt(m v_c) - m g`, `d/dt(I w)`), the derivatives by central differences along
/// the motion, mapped through the transposed Jacobians.
fn dalembert(dynamics: &ReferenceDynamics, q: &[f64], v: &[f64], a: &[f64], dt: f64) -> Vec<f64> {
    let tree = dynamics.tree();
    let g = Vector3::from(dynamics.gravity());
    let momenta = |t: f64| {
        let (qt, vt) =
            (advance(tree, q, v, a, t), DVector::from_iterator(v.len(), v.iter().zip(a).map(|(v, a)| v + a * t)));
        link_motions(dynamics, &qt)
            .iter()
            .map(|l| (l.mass * (&l.linear * &vt), l.tensor * (&l.angular * &vt)))
            .collect::<Vec<_>>()
    };
    let (after, before) = (momenta(dt), momenta(-dt));
    let mut tau = DVector::zeros(v.len());
    for (l, ((p1, h1), (p0, h0))) in link_motions(dynamics, q).iter().zip(after.iter().zip(&before)) {
        let force = (p1 - p0) / (2.0 * dt) - l.mass * g;
        let moment = (h1 - h0) / (2.0 * dt);
        tau += l.linear.transpose() * force + l.angular.transpose() * moment;
    }
    tau.iter().copied().collect()
}

fn random_cases() -> impl Iterator<Item = (u64, Variant)> {
    (0..60u64)
        .map(|seed| (seed, [Variant::Fixed, Variant::FloatingBase, Variant::PlanarAndSpherical][seed as usize % 3]))
}

#[test]
fn random_robots_cover_every_joint_kind_and_body() {
    let (mut kinds, mut mimics, mut afters, mut bodies) = (std::collections::BTreeSet::new(), 0, 0, [0; 3]);
    for (seed, variant) in random_cases() {
        let tree = KinematicTree::from_description(&random_robot(seed, variant)).unwrap();
        for joint in tree.joints() {
            kinds.insert(joint.kind.name());
            mimics += usize::from(matches!(joint.motion, JointMotion::Mimic { .. }));
            afters += usize::from(!joint.after_motion.is_identity());
        }
        for link in tree.links() {
            bodies[match &link.inertial {
                None => 0,
                Some(i) if i.inertia == [0.0; 6] => 1,
                Some(_) => 2,
            }] += 1;
        }
    }
    let every = ["revolute", "prismatic", "fixed", "floating", "planar", "spherical"];
    assert!(every.iter().all(|k| kinds.contains(k)), "{kinds:?}");
    assert!(mimics >= 50 && afters >= 50, "{mimics} mimics, {afters} transforms after the motion");
    assert!(bodies.iter().all(|&b| b >= 20), "massless, point masses, solids: {bodies:?}");
}

#[test]
fn random_robots_keep_the_identities() {
    for (seed, variant) in random_cases() {
        let description = random_robot(seed, variant);
        let dynamics = dynamics(&description, [0.3, -0.2, -G]);
        let tree = dynamics.tree();
        let n = tree.velocity_dof();
        let mut rng = Rng(1000 + seed);
        for _ in 0..3 {
            let q = random_q(tree, &mut rng);
            let (v, a, tau) = (random_vector(n, &mut rng), random_vector(n, &mut rng), random_vector(n, &mut rng));
            let context = format!("seed {seed} ({variant:?}), q {q:?}");
            let m = dynamics.mass_matrix(&q).unwrap();
            assert_eq!(m, m.transpose(), "{context}: M symmetric");
            if n > 0 {
                let eigen = m.clone().symmetric_eigen().eigenvalues;
                assert!(eigen.iter().all(|&e| e > 1e-9 * eigen.amax()), "{context}: M positive definite, {eigen}");
            }
            // M a + h = inverse dynamics.
            let h = dynamics.nonlinear_effects(&q, &v).unwrap();
            let id = dynamics.inverse_dynamics(&q, &v, &a).unwrap();
            let ma_h: Vec<f64> = (&m * DVector::from_column_slice(&a)).iter().zip(&h).map(|(x, y)| x + y).collect();
            assert_close(&ma_h, &id, 1e-12, &format!("{context}: M a + h"));
            // Forward dynamics inverts inverse dynamics (to rounding of `tau - h`).
            let acceleration = dynamics.forward_dynamics(&q, &v, &tau).unwrap();
            let back = dynamics.inverse_dynamics(&q, &v, &acceleration).unwrap();
            let h_scale = h.iter().fold(0.0_f64, |s, x| s.max(x.abs()));
            assert_close_at(&back, &tau, 1e-12, h_scale, &format!("{context}: ID(FD(tau))"));
            // The kinetic energy of the mass matrix is the links' energies.
            let energy = 0.5 * DVector::from_column_slice(&v).dot(&(&m * DVector::from_column_slice(&v)));
            assert_close(&[energy], &[kinetic_energy(&dynamics, &q, &v)], 1e-12, &format!("{context}: energy"));
            // The gravity torques are the potential's gradient along each velocity.
            let eps = 1e-4;
            let gradient: Vec<f64> = (0..n)
                .map(|k| {
                    let unit: Vec<f64> = (0..n).map(|i| if i == k { 1.0 } else { 0.0 }).collect();
                    let zero = vec![0.0; n];
                    let up = potential(&dynamics, &advance(tree, &q, &unit, &zero, eps));
                    let down = potential(&dynamics, &advance(tree, &q, &unit, &zero, -eps));
                    (up - down) / (2.0 * eps)
                })
                .collect();
            // Differences err by about eps^2 of the third derivative: relative to the robot's
            // weight on a lever of 1 m where the torques are smaller.
            let weight = G * link_motions(&dynamics, &q).iter().map(|l| l.mass).sum::<f64>();
            let gravity = dynamics.gravity_torques(&q).unwrap();
            assert_close_at(&gravity, &gradient, 1e-7, weight, &format!("{context}: gravity"));
            // Inverse dynamics is d'Alembert's principle on the links' momenta.
            let dalembert = dalembert(&dynamics, &q, &v, &a, 1e-4);
            assert_close_at(&id, &dalembert, 1e-7, weight, &format!("{context}: d'Alembert"));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Bad input.

fn one_link(inertia: Inertial, line: Option<usize>) -> KinematicTree {
    let mut j = joint("hinge", JointTypeDescription::Continuous, "base", "arm");
    j.axis = [0.0, 1.0, 0.0];
    let mut description = robot("r", &["base", "arm"], vec![j], Vec::new());
    description.inertials.push(InertialDescription { link: "arm".into(), line, inertial: inertia });
    KinematicTree::from_description(&description).unwrap()
}

#[test]
fn bad_inertias_are_refused_naming_the_link_and_line() {
    let at = FixedTransform::identity().translate([0.0, 0.0, -1.0]);
    let negative = Inertial { mass: -1.0, origin: at.clone(), inertia: [0.1, 0.0, 0.0, 0.1, 0.0, 0.1] };
    let err = ReferenceDynamics::new(one_link(negative, Some(12)), [0.0, 0.0, -G], true).unwrap_err();
    assert_eq!(
        err,
        DynamicsError::Inertial {
            robot: "r".into(),
            link: "arm".into(),
            line: Some(12),
            fault: InertiaFault::NegativeMass(-1.0)
        }
    );
    assert_eq!(
        err.to_string(),
        "robot `r`: the <inertial> of link `arm` (line 12): its mass is -1 kg (must be zero or more)"
    );

    // Principal moments (1, 1, 3): no rigid body's, but taken as written when asked.
    let triangle = Inertial { mass: 1.0, origin: at.clone(), inertia: [1.0, 0.0, 0.0, 1.0, 0.0, 3.0] };
    let err = ReferenceDynamics::new(one_link(triangle.clone(), None), [0.0, 0.0, -G], false).unwrap_err();
    assert!(
        matches!(&err, DynamicsError::Inertial { link, line: None, fault: InertiaFault::Triangle(_), .. } if link == "arm"),
        "{err}"
    );
    assert!(
        err.to_string().starts_with("robot `r`: the <inertial> of link `arm`: its inertia's principal moments"),
        "{err}"
    );
    let taken = ReferenceDynamics::new(one_link(triangle, None), [0.0, 0.0, -G], true).unwrap();
    // About the hinge (y): 1 + 1 * 1^2.
    assert_close(&matrix_entries(&taken.mass_matrix(&[0.2]).unwrap()), &[2.0], 1e-12, "M");

    let nan = Inertial { mass: f64::NAN, origin: at.clone(), inertia: [0.1, 0.0, 0.0, 0.1, 0.0, 0.1] };
    let err = ReferenceDynamics::new(one_link(nan, Some(3)), [0.0, 0.0, -G], true).unwrap_err();
    assert!(matches!(err, DynamicsError::Inertial { fault: InertiaFault::NotFinite(_), .. }), "{err}");

    let fine = Inertial { mass: 1.0, origin: at, inertia: [0.1, 0.0, 0.0, 0.1, 0.0, 0.1] };
    let err = ReferenceDynamics::new(one_link(fine.clone(), None), [0.0, f64::NAN, -G], false).unwrap_err();
    assert!(matches!(err, DynamicsError::NonFiniteGravity { .. }), "{err}");

    // A link whose mass is left to its geometry (an MJCF body with geoms and no <inertial>).
    let mut description = random_robot(7, Variant::Fixed);
    description.inertia_from_geometry.push("l2".into());
    let tree = KinematicTree::from_description(&description).unwrap();
    let err = ReferenceDynamics::new(tree, [0.0, 0.0, -G], false).unwrap_err();
    assert_eq!(err, DynamicsError::MassFromGeometry { robot: "random7".into(), link: "l2".into() });
}

#[test]
fn non_finite_and_ill_sized_inputs_are_errors() {
    let dynamics = dynamics(&PlanarArm::ARM.description(None), [0.0, -G, 0.0]);
    let err = dynamics.inverse_dynamics(&[0.1, f64::NAN], &[0.0; 2], &[0.0; 2]).unwrap_err();
    assert!(
        matches!(&err, DynamicsError::Configuration(RuntimeError::NonFiniteValue { joint, index: 1, .. }) if joint == "elbow"),
        "{err}"
    );
    assert_eq!(err.to_string(), "robot `planar_arm`: the value of joint `elbow` (q[1]) is NaN, not a finite number");
    let err = dynamics.nonlinear_effects(&[0.1, 0.2], &[f64::INFINITY, 0.0]).unwrap_err();
    assert_eq!(err.to_string(), "robot `planar_arm`: v[0] (`shoulder`) is inf, not a finite number");
    let err = dynamics.forward_dynamics(&[0.1, 0.2], &[0.0; 2], &[0.0, f64::NEG_INFINITY]).unwrap_err();
    assert!(matches!(&err, DynamicsError::NonFiniteValue { argument: "tau", index: 1, .. }), "{err}");
    let err = dynamics.inverse_dynamics(&[0.1, 0.2], &[0.0; 2], &[0.0; 3]).unwrap_err();
    assert_eq!(err.to_string(), "robot `planar_arm` has 2 velocities (shoulder, elbow), but a has 3 values");
    assert!(matches!(dynamics.mass_matrix(&[0.1]), Err(DynamicsError::Configuration(RuntimeError::WrongDof { .. }))));
    assert!(matches!(dynamics.gravity_torques(&[f64::NAN, 0.0]), Err(DynamicsError::Configuration(_))));
    // Finite, but too large for the torques.
    let err = dynamics.inverse_dynamics(&[0.1, 0.2], &[1e300, 1e300], &[0.0; 2]).unwrap_err();
    assert!(matches!(err, DynamicsError::NotFinite { .. }), "{err}");
}

/// A robot with no velocities has empty answers, not a panic.
#[test]
fn a_robot_that_cannot_move() {
    let weld = joint("weld", JointTypeDescription::Fixed, "base", "arm");
    let dynamics = dynamics(
        &robot("statue", &["base", "arm"], vec![weld], vec![inertial("arm", 1.0, [0.1; 3], [0.0; 3], [0.0; 6])]),
        [0.0, 0.0, -G],
    );
    assert_eq!(dynamics.forward_dynamics(&[], &[], &[]).unwrap(), Vec::<f64>::new());
    assert_eq!(dynamics.gravity_torques(&[]).unwrap(), Vec::<f64>::new());
    assert_eq!(dynamics.mass_matrix(&[]).unwrap().shape(), (0, 0));
}

/// A chain whose last two links carry no mass, and a hinge whose axis runs through a point mass:
/// the mass matrix is singular, and forward dynamics names the joints it cannot determine rather
/// than return NaN.
#[test]
fn forward_dynamics_names_the_joints_that_move_no_mass() {
    let mut joints = Vec::new();
    let links = ["base", "l1", "l2", "l3"];
    for i in 1..4 {
        let mut j = joint(&format!("j{i}"), JointTypeDescription::Revolute, links[i - 1], links[i]);
        j.origin = FixedTransform::identity().translate([0.5, 0.0, 0.0]);
        j.axis = [0.0, 1.0, 0.0];
        joints.push(j);
    }
    let massive = inertial("l1", 2.0, [0.25, 0.0, 0.0], [0.0; 3], [0.01, 0.0, 0.0, 0.02, 0.0, 0.02]);
    let chain = dynamics(&robot("chain", &links, joints.clone(), vec![massive.clone()]), [0.0, 0.0, -G]);
    let m = chain.mass_matrix(&[0.1, 0.2, 0.3]).unwrap();
    assert!(m[(0, 0)] > 0.0 && m.column(1).iter().chain(m.column(2).iter()).all(|&x| x == 0.0), "{m}");
    let err = chain.forward_dynamics(&[0.1, 0.2, 0.3], &[0.5, -0.5, 1.0], &[1.0, 0.0, 0.0]).unwrap_err();
    assert_eq!(
        err,
        DynamicsError::SingularMassMatrix { robot: "chain".into(), velocities: vec!["j2".into(), "j3".into()] }
    );
    assert_eq!(
        err.to_string(),
        "robot `chain`: the mass matrix is singular: forward dynamics cannot determine the accelerations of `j2`, `j3`, which move no mass of their own"
    );
    // Inverse dynamics still answers: the massless joints need no torque.
    let tau = chain.inverse_dynamics(&[0.1, 0.2, 0.3], &[0.5, -0.5, 1.0], &[0.3, 2.0, -1.0]).unwrap();
    assert_eq!(tau[1..], [0.0, 0.0]);

    // A point mass on the last hinge's axis: that hinge turns it without moving it.
    let mut on_axis = vec![massive.clone(), inertial("l3", 1.0, [0.0, 0.0, 0.0], [0.0; 3], [0.0; 6])];
    let point = dynamics(&robot("point", &links, joints.clone(), on_axis.clone()), [0.0, 0.0, -G]);
    let err = point.forward_dynamics(&[0.1, 0.2, 0.3], &[0.0; 3], &[0.0; 3]).unwrap_err();
    assert_eq!(err, DynamicsError::SingularMassMatrix { robot: "point".into(), velocities: vec!["j3".into()] });
    // Given a tensor, it turns: every acceleration is determined.
    on_axis[1] = inertial("l3", 1.0, [0.0, 0.0, 0.0], [0.0; 3], [0.01, 0.0, 0.0, 0.01, 0.0, 0.01]);
    let solid = dynamics(&robot("solid", &links, joints, on_axis), [0.0, 0.0, -G]);
    let a = solid.forward_dynamics(&[0.1, 0.2, 0.3], &[0.0; 3], &[0.0; 3]).unwrap();
    assert!(a.iter().all(|x| x.is_finite()), "{a:?}");
}
