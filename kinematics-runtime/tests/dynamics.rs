//! The reference dynamics (`ReferenceDynamics`) against hand-worked closed forms and on bad input.
//! Its identities on random robots (with fixed, mimic, planar, spherical and floating joints,
//! checked through the forward kinematics and its Jacobians) are in the checks crate
//! (`checks/tests/reference_dynamics.rs`), beside the compiled dynamics' tests on the same robots.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

/// The robot builders and random robots the checks' dynamics tests use too.
#[path = "../../checks/tests/common/dynamics_robots.rs"]
mod dynamics_robots;

use std::f64::consts::PI;

use dynamics_robots::{G, Variant, assert_close, assert_close_at, inertial, joint, random_robot, robot};
use kinematics_model::inertia::{InertiaFault, InertiaRefusal, Inertial};
use kinematics_model::{
    Description, FixedTransform, InertialDescription, JointTypeDescription, KinematicTree, MimicDescription,
};
use kinematics_runtime::{DynamicsError, ReferenceDynamics, RuntimeError};
use nalgebra::{DMatrix, UnitQuaternion, Vector3};

fn dynamics(description: &Description, gravity: [f64; 3]) -> ReferenceDynamics {
    ReferenceDynamics::new(KinematicTree::from_description(description).unwrap(), gravity, false).unwrap()
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
        DynamicsError::Inertia {
            robot: "r".into(),
            refusal: InertiaRefusal::Fault {
                link: "arm".into(),
                line: Some(12),
                fault: InertiaFault::NegativeMass(-1.0)
            }
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
        matches!(&err, DynamicsError::Inertia { refusal: InertiaRefusal::Fault { link, line: None, fault: InertiaFault::Triangle(_) }, .. } if link == "arm"),
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
    assert!(
        matches!(
            err,
            DynamicsError::Inertia { refusal: InertiaRefusal::Fault { fault: InertiaFault::NotFinite(_), .. }, .. }
        ),
        "{err}"
    );

    let fine = Inertial { mass: 1.0, origin: at, inertia: [0.1, 0.0, 0.0, 0.1, 0.0, 0.1] };
    let err = ReferenceDynamics::new(one_link(fine.clone(), None), [0.0, f64::NAN, -G], false).unwrap_err();
    assert!(matches!(err, DynamicsError::NonFiniteGravity { .. }), "{err}");

    // A link whose mass is left to its geometry (an MJCF body with geoms and no <inertial>).
    let mut description = random_robot(7, Variant::Fixed);
    description.inertia_from_geometry.push("l2".into());
    let tree = KinematicTree::from_description(&description).unwrap();
    let err = ReferenceDynamics::new(tree, [0.0, 0.0, -G], false).unwrap_err();
    assert_eq!(
        err,
        DynamicsError::Inertia { robot: "random7".into(), refusal: InertiaRefusal::FromGeometry { link: "l2".into() } }
    );
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
