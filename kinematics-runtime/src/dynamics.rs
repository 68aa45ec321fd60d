//! Reference rigid-body dynamics: inverse dynamics, gravity, the mass matrix and forward dynamics
//! of a [`KinematicTree`] whose links carry inertias, written from Featherstone's *Rigid Body
//! Dynamics Algorithms* (Springer, 2008) on nalgebra, sharing nothing with generated code.
//!
//! What it owns: [`ReferenceDynamics`] (built from a tree, a gravity vector and whether inertia
//! tensors are taken as written), its typed errors ([`DynamicsError`]), and the spatial algebra it
//! needs, written here (`spatial.rs`: motion and force 6-vectors, Plücker transforms, rigid-body
//! spatial inertias; ch. 2, §2.8, §2.9, §2.13). `joint.rs` gives each joint's transform and motion
//! subspace at a configuration (ch. 4), `algorithms.rs` the recursive Newton-Euler algorithm
//! (§5.3, Table 5.1), the composite-rigid-body algorithm (§6.2, Table 6.2) and forward dynamics by
//! the mass matrix's Cholesky factorisation (ch. 6).
//!
//! **Bodies.** Every link is a body, its spatial inertia about its own origin in its own axes,
//! from its `<inertial>` (mass, the centre of mass's frame, the tensor about the centre of mass in
//! that frame's axes, turned into the link's); a link without one is massless. Every joint,
//! fixed ones included, is walked: a fixed joint's child rides on its parent with the composed
//! transform, so nothing is lumped.
//!
//! **Conventions.** `q` is [`ReferenceFk`]'s (one entry per independent position; a floating
//! joint's position then quaternion `(qx, qy, qz, qw)`). Velocities, accelerations and
//! generalized forces have [`KinematicTree::velocity_dof`] entries, in the order of
//! [`KinematicTree::velocity_names`] and the Jacobian's columns ([`ReferenceFk::jacobian_in`]):
//!
//! - a revolute, continuous or prismatic joint's rate; a planar joint's rates of its three
//!   entries of `q` (the slides along its in-plane axes, fixed in the parent, and the turn);
//! - a floating joint's six (Pinocchio's free-flyer): the child's linear velocity (of its origin)
//!   then its angular velocity, **both in the child's own axes** (the body frame, not the world);
//!   its accelerations are the time derivatives of those six components (the spatial
//!   acceleration in the body frame: the classical acceleration of the origin is `vdot + w x v`);
//! - a spherical joint's three: the child's angular velocity in its own axes;
//! - a mimic joint has none: it moves at its multiplier times its source's velocity, its motion
//!   subspace adds to its source's column scaled by the multiplier, so its torque is folded into
//!   the source's (the generalized forces are those of the independent velocities, the principle
//!   of virtual work: `tau_source += multiplier * tau_mimic`).
//!
//! Gravity is a vector in the root link's frame (`(0, 0, -9.81)` for z up), applied as the root's
//! acceleration `-g` (Featherstone §5.3); a floating base is the child of a fixed root, so its
//! velocities are absolute. `gravity_torques` are the torques that hold the robot still: the
//! gradient of the potential energy `V = -sum m g . c`, with the sign of `inverse_dynamics`.
//!
//! **Refused.** A link whose inertia breaks a rigid body's rules
//! ([`kinematics_model::inertia::Inertial::fault`]; the triangle inequality only unless taken as
//! written), a link whose mass is left to its geometry ([`KinematicTree::inertia_from_geometry`]),
//! a non-finite gravity, non-finite or ill-sized inputs, results that overflow, and forward
//! dynamics through a singular mass matrix (velocities that move no mass: each is named). Every
//! joint kind the forward kinematics has is supported.

mod algorithms;
mod error;
mod joint;
mod spatial;

use kinematics_model::{JointMotion, KinematicTree, LinkId};
use nalgebra::{DMatrix, Isometry3, Matrix3, Matrix6, Vector3};

pub use error::DynamicsError;

use crate::fk::{ReferenceFk, fixed_isometry};

/// The reference dynamics of one robot.
///
/// | query | algorithm |
/// |---|---|
/// | [`inverse_dynamics`](Self::inverse_dynamics)`(q, v, a)` | recursive Newton-Euler (RNEA) |
/// | [`gravity_torques`](Self::gravity_torques)`(q)` | RNEA with `v = a = 0` |
/// | [`nonlinear_effects`](Self::nonlinear_effects)`(q, v)` | RNEA with `a = 0`: Coriolis, centrifugal and gravity |
/// | [`mass_matrix`](Self::mass_matrix)`(q)` | composite rigid bodies (CRBA), symmetric |
/// | [`forward_dynamics`](Self::forward_dynamics)`(q, v, tau)` | `M a = tau - h` by Cholesky |
/// | [`inverse_dynamics_with_forces`](Self::inverse_dynamics_with_forces)`(q, v, a, forces)` | RNEA less the links' external forces |
/// | [`forward_dynamics_with_forces`](Self::forward_dynamics_with_forces)`(q, v, tau, forces)` | `M a = tau - h + J^T f` |
///
/// The module documentation gives the conventions (a floating base's velocities in its own
/// axes, a mimic joint's torque folded into its source's).
///
/// # Example
///
/// A pendulum: a point mass of 2 kg, 0.5 m below a horizontal hinge about y, under gravity along
/// -z. Turned by `q`, it holds against `m g l sin q`, and its inertia about the hinge is `m l^2`.
///
/// ```
/// use kinematics_model::{FixedTransform, InertialDescription, KinematicTree, inertia::Inertial, urdf::parse_urdf};
/// use kinematics_runtime::ReferenceDynamics;
///
/// let urdf = r#"<robot name="pendulum"><link name="base"/><link name="bob"/>
///   <joint name="hinge" type="continuous"><parent link="base"/><child link="bob"/><axis xyz="0 1 0"/></joint>
/// </robot>"#;
/// let mut description = parse_urdf(urdf)?;
/// description.inertials.push(InertialDescription {
///     link: "bob".into(),
///     line: None,
///     inertial: Inertial { mass: 2.0, origin: FixedTransform::identity().translate([0.0, 0.0, -0.5]), inertia: [0.0; 6] },
/// });
/// let tree = KinematicTree::from_description(&description)?;
/// let dynamics = ReferenceDynamics::new(tree, [0.0, 0.0, -9.81], false)?;
///
/// let q = [0.3];
/// let hold = dynamics.gravity_torques(&q)?;
/// approx::assert_relative_eq!(hold[0], 2.0 * 9.81 * 0.5 * 0.3_f64.sin(), max_relative = 1e-12);
/// approx::assert_relative_eq!(dynamics.mass_matrix(&q)?[(0, 0)], 2.0 * 0.5 * 0.5, max_relative = 1e-12);
/// // Let go, it swings back: a = -(g / l) sin q.
/// let a = dynamics.forward_dynamics(&q, &[0.0], &[0.0])?;
/// approx::assert_relative_eq!(a[0], -9.81 / 0.5 * 0.3_f64.sin(), max_relative = 1e-12);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct ReferenceDynamics {
    fk: ReferenceFk,
    gravity: Vector3<f64>,
    /// Each link's spatial inertia about its origin, in its axes (zero for a massless link).
    inertias: Vec<Matrix6<f64>>,
    origins: Vec<Isometry3<f64>>,
    afters: Vec<Isometry3<f64>>,
    /// Each joint's first velocity (its source's for a mimic joint; 0 for a fixed joint, which
    /// has none).
    velocity: Vec<usize>,
}

impl ReferenceDynamics {
    /// Prepares the dynamics of `tree` under `gravity` (in the root link's frame, m/s^2), taking
    /// inertia tensors that break the triangle inequality as written when `as_written`.
    ///
    /// Fails on a non-finite gravity, and on the first link, in tree order, whose inertia breaks
    /// a rigid body's rules or whose mass is left to its geometry ([`DynamicsError::Inertia`],
    /// from [`KinematicTree::inertia_refusals`], with the line of its `<inertial>`).
    ///
    /// ```
    /// use kinematics_model::{FixedTransform, InertialDescription, KinematicTree, inertia::Inertial, urdf::parse_urdf};
    /// use kinematics_model::inertia::InertiaRefusal;
    /// use kinematics_runtime::{DynamicsError, ReferenceDynamics};
    ///
    /// let mut description = parse_urdf(r#"<robot name="r"><link name="a"/></robot>"#)?;
    /// // Principal moments (1, 1, 3): no rigid body's (3 > 1 + 1), though real files have such.
    /// let inertial = Inertial { mass: 1.0, origin: FixedTransform::identity(), inertia: [1.0, 0.0, 0.0, 1.0, 0.0, 3.0] };
    /// description.inertials.push(InertialDescription { link: "a".into(), line: Some(7), inertial });
    /// let tree = KinematicTree::from_description(&description)?;
    /// let err = ReferenceDynamics::new(tree.clone(), [0.0, 0.0, -9.81], false).unwrap_err();
    /// assert!(matches!(&err, DynamicsError::Inertia { refusal: InertiaRefusal::Fault { link, line: Some(7), .. }, .. } if link == "a"), "{err}");
    /// assert!(ReferenceDynamics::new(tree, [0.0, 0.0, -9.81], true).is_ok());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn new(tree: KinematicTree, gravity: [f64; 3], as_written: bool) -> Result<Self, DynamicsError> {
        let robot = || tree.name().to_owned();
        if gravity.iter().any(|g| !g.is_finite()) {
            return Err(DynamicsError::NonFiniteGravity { robot: robot(), gravity });
        }
        if let Some(refusal) = tree.inertia_refusals(as_written).into_iter().next() {
            return Err(DynamicsError::Inertia { robot: robot(), refusal });
        }
        let mut inertias = Vec::with_capacity(tree.links().len());
        for link in tree.links() {
            let Some(inertial) = &link.inertial else {
                inertias.push(Matrix6::zeros());
                continue;
            };
            // The tensor about the centre of mass in its frame's axes, turned into the link's.
            let com = fixed_isometry(&inertial.origin);
            let turn = com.rotation.to_rotation_matrix().into_inner();
            let [xx, xy, xz, yy, yz, zz] = inertial.inertia;
            let tensor = turn * Matrix3::new(xx, xy, xz, xy, yy, yz, xz, yz, zz) * turn.transpose();
            inertias.push(spatial::rigid_body_inertia(inertial.mass, com.translation.vector, tensor));
        }
        let origins = tree.joints().iter().map(|j| fixed_isometry(&j.origin)).collect();
        let afters = tree.joints().iter().map(|j| fixed_isometry(&j.after_motion)).collect();
        let of_entry = tree.velocity_of_entry();
        let velocity = (0..tree.joints().len())
            .map(|i| {
                let id = kinematics_model::JointId(i);
                match tree.joint(id).motion {
                    JointMotion::Fixed => None,
                    JointMotion::Dof(_) => tree.velocity_start(id),
                    JointMotion::Mimic { dof, .. } => of_entry[dof],
                }
                .unwrap_or(0)
            })
            .collect();
        Ok(ReferenceDynamics {
            fk: ReferenceFk::new(tree),
            gravity: Vector3::from(gravity),
            inertias,
            origins,
            afters,
            velocity,
        })
    }

    /// The tree this evaluates.
    pub fn tree(&self) -> &KinematicTree {
        self.fk.tree()
    }

    /// The forward kinematics of the same tree (link poses, Jacobians).
    pub fn fk(&self) -> &ReferenceFk {
        &self.fk
    }

    /// Gravity, in the root link's frame.
    pub fn gravity(&self) -> [f64; 3] {
        self.gravity.into()
    }

    /// The spatial inertia of link `link` about its origin, in its axes, angular rows and
    /// columns first (Featherstone's order): `[I_c + m c^x c^xT, m c^x; m c^xT, m 1]` for mass
    /// `m`, centre of mass `c` and tensor `I_c` about it; zero for a massless link.
    ///
    /// ```
    /// # use kinematics_model::{FixedTransform, InertialDescription, KinematicTree, inertia::Inertial, urdf::parse_urdf};
    /// # let mut description = parse_urdf(r#"<robot name="r"><link name="a"/></robot>"#)?;
    /// # let inertial = Inertial { mass: 3.0, origin: FixedTransform::identity().translate([1.0, 0.0, 0.0]), inertia: [0.0; 6] };
    /// # description.inertials.push(InertialDescription { link: "a".into(), line: None, inertial });
    /// # let tree = KinematicTree::from_description(&description)?;
    /// let dynamics = kinematics_runtime::ReferenceDynamics::new(tree, [0.0; 3], false)?;
    /// // 3 kg at (1, 0, 0): 3 kg m^2 about y and z through the origin.
    /// let inertia = dynamics.link_inertia(dynamics.tree().root());
    /// assert_eq!((inertia[(1, 1)], inertia[(2, 2)], inertia[(5, 5)]), (3.0, 3.0, 3.0));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn link_inertia(&self, link: LinkId) -> Matrix6<f64> {
        self.inertias[link.0]
    }

    /// The generalized forces (joint torques and forces, one per velocity) that give the
    /// accelerations `a` at positions `q` and velocities `v`: `M(q) a + h(q, v)`, by the recursive
    /// Newton-Euler algorithm.
    pub fn inverse_dynamics(&self, q: &[f64], v: &[f64], a: &[f64]) -> Result<Vec<f64>, DynamicsError> {
        self.check(q, &[("v", v), ("a", a)])?;
        self.finite("inverse dynamics", self.rnea(q, v, a, &[]))
    }

    /// The generalized forces that hold the robot still against gravity at `q` (the gradient of
    /// its potential energy): inverse dynamics with zero velocities and accelerations.
    pub fn gravity_torques(&self, q: &[f64]) -> Result<Vec<f64>, DynamicsError> {
        self.check(q, &[])?;
        let zero = vec![0.0; self.tree().velocity_dof()];
        self.finite("gravity torques", self.rnea(q, &zero, &zero, &[]))
    }

    /// The Coriolis, centrifugal and gravity terms `h(q, v)`: inverse dynamics with zero
    /// accelerations.
    pub fn nonlinear_effects(&self, q: &[f64], v: &[f64]) -> Result<Vec<f64>, DynamicsError> {
        self.check(q, &[("v", v)])?;
        let zero = vec![0.0; self.tree().velocity_dof()];
        self.finite("nonlinear effects", self.rnea(q, v, &zero, &[]))
    }

    /// The joint-space mass matrix `M(q)` (`velocity_dof` square, symmetric, positive
    /// semi-definite; definite unless some velocity moves no mass), by the composite-rigid-body
    /// algorithm. The kinetic energy is `v^T M v / 2`.
    pub fn mass_matrix(&self, q: &[f64]) -> Result<DMatrix<f64>, DynamicsError> {
        self.check(q, &[])?;
        let m = self.crba(q);
        if m.iter().any(|x| !x.is_finite()) {
            return Err(DynamicsError::NotFinite { robot: self.tree().name().to_owned(), quantity: "mass matrix" });
        }
        Ok(m)
    }

    /// The accelerations that the generalized forces `tau` give at `(q, v)`: `M a = tau - h`,
    /// solved by the Cholesky factorisation of `M`.
    ///
    /// A mass matrix with a zero eigenvalue (at most [`SINGULAR_RATIO`](Self::SINGULAR_RATIO) of
    /// the largest) is [`DynamicsError::SingularMassMatrix`], naming the velocities along its
    /// eigenvectors: a joint that carries no mass (the last joint of a chain of massless links, a
    /// hinge whose axis runs through a point mass) has an acceleration no torque determines.
    ///
    /// ```
    /// use kinematics_model::{FixedTransform, InertialDescription, KinematicTree, inertia::Inertial, urdf::parse_urdf};
    /// use kinematics_runtime::{DynamicsError, ReferenceDynamics};
    ///
    /// let urdf = r#"<robot name="arm"><link name="base"/><link name="upper"/><link name="hand"/>
    ///   <joint name="shoulder" type="continuous"><parent link="base"/><child link="upper"/></joint>
    ///   <joint name="wrist" type="continuous"><parent link="upper"/><child link="hand"/>
    ///     <origin xyz="1 0 0"/></joint></robot>"#;
    /// let mut description = parse_urdf(urdf)?;
    /// // Mass on the upper arm only: the hand carries none.
    /// let inertial = Inertial { mass: 1.0, origin: FixedTransform::identity().translate([0.0, 0.5, 0.0]), inertia: [0.0; 6] };
    /// description.inertials.push(InertialDescription { link: "upper".into(), line: None, inertial });
    /// let dynamics = ReferenceDynamics::new(KinematicTree::from_description(&description)?, [0.0; 3], false)?;
    /// let err = dynamics.forward_dynamics(&[0.0, 0.0], &[0.0, 0.0], &[1.0, 0.0]).unwrap_err();
    /// assert_eq!(err, DynamicsError::SingularMassMatrix { robot: "arm".into(), velocities: vec!["wrist".into()] });
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn forward_dynamics(&self, q: &[f64], v: &[f64], tau: &[f64]) -> Result<Vec<f64>, DynamicsError> {
        self.forward_dynamics_with_forces(q, v, tau, &[])
    }

    /// [`inverse_dynamics`](Self::inverse_dynamics) while the world pushes on links: each of
    /// `forces` names a link and gives `[fx, fy, fz, nx, ny, nz]`, the force and its moment about
    /// the link's origin, both in the link's own axes, exerted on the link. The result is
    /// `M(q) a + h(q, v) - sum J^T f` over the links' Jacobians in their own frames.
    ///
    /// ```
    /// # use kinematics_model::{FixedTransform, InertialDescription, KinematicTree, inertia::Inertial, urdf::parse_urdf};
    /// use kinematics_runtime::ReferenceDynamics;
    /// // A massless hinge about z with a link 1 m along x: a push of 2 N along the link's y at
    /// // its origin needs -2 N m at the hinge to hold.
    /// let urdf = r#"<robot name="r"><link name="base"/><link name="arm"/><link name="tip"/>
    ///   <joint name="hinge" type="continuous"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/></joint>
    ///   <joint name="bolt" type="fixed"><parent link="arm"/><child link="tip"/><origin xyz="1 0 0"/></joint>
    /// </robot>"#;
    /// let mut description = parse_urdf(urdf)?;
    /// let inertial = Inertial { mass: 1.0, origin: FixedTransform::identity(), inertia: [1.0, 0.0, 0.0, 1.0, 0.0, 1.0] };
    /// description.inertials.push(InertialDescription { link: "arm".into(), line: None, inertial });
    /// let dynamics = ReferenceDynamics::new(KinematicTree::from_description(&description)?, [0.0; 3], false)?;
    /// let tau = dynamics.inverse_dynamics_with_forces(&[0.4], &[0.0], &[0.0], &[("tip", [0.0, 2.0, 0.0, 0.0, 0.0, 0.0])])?;
    /// approx::assert_relative_eq!(tau[0], -2.0, max_relative = 1e-12);
    /// assert!(dynamics.inverse_dynamics_with_forces(&[0.4], &[0.0], &[0.0], &[("tips", [0.0; 6])]).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn inverse_dynamics_with_forces(
        &self,
        q: &[f64],
        v: &[f64],
        a: &[f64],
        forces: &[(&str, [f64; 6])],
    ) -> Result<Vec<f64>, DynamicsError> {
        self.check(q, &[("v", v), ("a", a)])?;
        let external = self.external(forces)?;
        self.finite("inverse dynamics", self.rnea(q, v, a, &external))
    }

    /// [`forward_dynamics`](Self::forward_dynamics) while the world pushes on links (`forces` as
    /// [`inverse_dynamics_with_forces`](Self::inverse_dynamics_with_forces) takes them): `M a = tau
    /// - h + sum J^T f`.
    pub fn forward_dynamics_with_forces(
        &self,
        q: &[f64],
        v: &[f64],
        tau: &[f64],
        forces: &[(&str, [f64; 6])],
    ) -> Result<Vec<f64>, DynamicsError> {
        self.check(q, &[("v", v), ("tau", tau)])?;
        let external = self.external(forces)?;
        let h = self.rnea(q, v, &vec![0.0; v.len()], &external);
        let m = self.crba(q);
        let robot = || self.tree().name().to_owned();
        if m.iter().chain(&h).any(|x| !x.is_finite()) {
            return Err(DynamicsError::NotFinite { robot: robot(), quantity: "mass matrix or nonlinear effects" });
        }
        let rhs = tau.iter().zip(&h).map(|(t, h)| t - h).collect();
        match self.solve(m, rhs) {
            Ok(a) => self.finite("forward dynamics", a),
            Err(undetermined) => {
                let names = self.tree().velocity_names();
                let velocities = undetermined.into_iter().map(|k| names[k].clone()).collect();
                Err(DynamicsError::SingularMassMatrix { robot: robot(), velocities })
            }
        }
    }

    /// How small an eigenvalue of the mass matrix, relative to its largest, forward dynamics
    /// takes as zero.
    pub const SINGULAR_RATIO: f64 = algorithms::SINGULAR_RATIO;

    /// `q` as the forward kinematics checks it; each of `vectors` one finite entry per velocity.
    fn check(&self, q: &[f64], vectors: &[(&'static str, &[f64])]) -> Result<(), DynamicsError> {
        self.fk.check_q(q)?;
        let tree = self.tree();
        for &(argument, values) in vectors {
            if values.len() != tree.velocity_dof() {
                return Err(DynamicsError::WrongLength {
                    robot: tree.name().to_owned(),
                    argument,
                    expected: tree.velocity_dof(),
                    got: values.len(),
                    names: tree.velocity_names().join(", "),
                });
            }
            if let Some(index) = values.iter().position(|x| !x.is_finite()) {
                return Err(DynamicsError::NonFiniteValue {
                    robot: tree.name().to_owned(),
                    argument,
                    index,
                    name: tree.velocity_names()[index].clone(),
                    value: values[index],
                });
            }
        }
        Ok(())
    }

    /// Each external force as its link's index and a spatial force (moment first), checked: a link
    /// of the tree, finite entries.
    fn external(&self, forces: &[(&str, [f64; 6])]) -> Result<Vec<(usize, spatial::Spatial)>, DynamicsError> {
        let tree = self.tree();
        let robot = || tree.name().to_owned();
        forces
            .iter()
            .map(|(name, f)| {
                let link = tree
                    .find_link("force", name)
                    .map_err(|source| DynamicsError::UnknownLink { robot: robot(), source })?;
                if let Some(index) = f.iter().position(|x| !x.is_finite()) {
                    let link = (*name).to_owned();
                    return Err(DynamicsError::NonFiniteForce { robot: robot(), link, index, value: f[index] });
                }
                let [fx, fy, fz, nx, ny, nz] = *f;
                Ok((link.0, spatial::spatial(Vector3::new(nx, ny, nz), Vector3::new(fx, fy, fz))))
            })
            .collect()
    }

    /// `values`, unless one overflowed.
    fn finite(&self, quantity: &'static str, values: Vec<f64>) -> Result<Vec<f64>, DynamicsError> {
        if values.iter().all(|x| x.is_finite()) {
            Ok(values)
        } else {
            Err(DynamicsError::NotFinite { robot: self.tree().name().to_owned(), quantity })
        }
    }
}
