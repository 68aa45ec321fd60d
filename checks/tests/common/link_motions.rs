//! The links' motions computed from the runtime reference's forward kinematics alone (poses and
//! Jacobians, no dynamics): centres of mass, tensors in the root's frame, the Jacobians of their
//! velocities, and from them the potential and kinetic energies; and moving a configuration along a
//! velocity (quaternion joints by the exponential map), for central differences.

use kinematics::model::{JointId, JointKind, JointMotion, KinematicTree};
use kinematics::runtime::{ReferenceDynamics, fixed_isometry};
use nalgebra::{DVector, Matrix3, Matrix3xX, Quaternion, UnitQuaternion, Vector3};

/// The configuration reached from `q` in time `t` moving at `v + a t / 2` (right to first order in
/// `t`, which central differences need): `q + v t` for entries whose rate is their velocity; for
/// a quaternion joint, its rotation times `exp((w + alpha t / 2) t)` (angular velocity in its own
/// axes) and a floating joint's position moved by its rotation times its linear velocity.
pub fn advance(tree: &KinematicTree, q: &[f64], v: &[f64], a: &[f64], t: f64) -> Vec<f64> {
    let mut out = q.to_vec();
    let rate = |k: usize| v[k] + 0.5 * a[k] * t;
    for (index, joint) in tree.joints().iter().enumerate() {
        let JointMotion::Dof(start) = joint.motion else { continue };
        let Some(k) = tree.velocity_start(JointId(index)) else { continue };
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
pub struct LinkMotion {
    pub mass: f64,
    pub com: Vector3<f64>,
    pub tensor: Matrix3<f64>,
    pub linear: Matrix3xX<f64>,
    pub angular: Matrix3xX<f64>,
}

pub fn link_motions(dynamics: &ReferenceDynamics, q: &[f64]) -> Vec<LinkMotion> {
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

pub fn potential(dynamics: &ReferenceDynamics, q: &[f64]) -> f64 {
    let g = Vector3::from(dynamics.gravity());
    link_motions(dynamics, q).iter().map(|l| -l.mass * g.dot(&l.com)).sum()
}

pub fn kinetic_energy(dynamics: &ReferenceDynamics, q: &[f64], v: &[f64]) -> f64 {
    let v = DVector::from_column_slice(v);
    link_motions(dynamics, q)
        .iter()
        .map(|l| {
            let (vc, w) = (&l.linear * &v, &l.angular * &v);
            0.5 * l.mass * vc.norm_squared() + 0.5 * w.dot(&(l.tensor * w))
        })
        .sum()
}
