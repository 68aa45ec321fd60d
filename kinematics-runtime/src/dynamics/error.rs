//! Errors of the reference dynamics.

use kinematics_model::inertia::InertiaRefusal;

use crate::error::RuntimeError;

/// Why [`super::ReferenceDynamics`] refuses a robot or a query.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum DynamicsError {
    /// A link whose mass the dynamics cannot take (its `<inertial>` is no rigid body's, or its
    /// mass is left to its geometry: the reference does not infer inertias).
    #[error("robot `{robot}`: {refusal}")]
    Inertia {
        /// Robot name.
        robot: String,
        /// Which link, and why.
        #[source]
        refusal: InertiaRefusal,
    },
    /// A gravity vector with a NaN or infinite component.
    #[error("robot `{robot}`: gravity {gravity:?} is not a finite vector")]
    NonFiniteGravity {
        /// Robot name.
        robot: String,
        /// The gravity given.
        gravity: [f64; 3],
    },
    /// `q` of the wrong length, with a NaN or infinite entry, or with a quaternion that cannot be
    /// normalised (the forward kinematics' own check).
    #[error(transparent)]
    Configuration(#[from] RuntimeError),
    /// Velocities, accelerations or torques not of one entry per velocity.
    #[error("robot `{robot}` has {expected} velocities ({names}), but {argument} has {got} values")]
    WrongLength {
        /// Robot name.
        robot: String,
        /// Which argument (`v`, `a`, `tau`).
        argument: &'static str,
        /// The number of velocities.
        expected: usize,
        /// Its length.
        got: usize,
        /// The velocities' names, for the message.
        names: String,
    },
    /// A NaN or infinite velocity, acceleration or torque.
    #[error("robot `{robot}`: {argument}[{index}] (`{name}`) is {value}, not a finite number")]
    NonFiniteValue {
        /// Robot name.
        robot: String,
        /// Which argument (`v`, `a`, `tau`).
        argument: &'static str,
        /// Its index.
        index: usize,
        /// The name of the velocity it belongs to.
        name: String,
        /// The value.
        value: f64,
    },
    /// An external force on a link the robot does not have.
    #[error("robot `{robot}`: {source}")]
    UnknownLink {
        /// Robot name.
        robot: String,
        /// The link named, and the closest name the robot has.
        #[source]
        source: kinematics_model::UnknownLink,
    },
    /// A NaN or infinite entry of an external force.
    #[error("robot `{robot}`: the external force on link `{link}` has {value} at [{index}], not a finite number")]
    NonFiniteForce {
        /// Robot name.
        robot: String,
        /// The link it acts on.
        link: String,
        /// Its index in `[fx, fy, fz, nx, ny, nz]`.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A result that overflowed (finite inputs too large for it).
    #[error("robot `{robot}`: the {quantity} overflowed to values that are not finite")]
    NotFinite {
        /// Robot name.
        robot: String,
        /// What overflowed.
        quantity: &'static str,
    },
    /// A mass matrix that cannot be inverted: these velocities move no mass (or only mass that
    /// other velocities move the same way), so no torque determines their accelerations.
    #[error(
        "robot `{robot}`: the mass matrix is singular: forward dynamics cannot determine the accelerations of {}, which move no mass of their own",
        names(velocities)
    )]
    SingularMassMatrix {
        /// Robot name.
        robot: String,
        /// The velocities it cannot determine ([`kinematics_model::KinematicTree::velocity_names`]).
        velocities: Vec<String>,
    },
}

fn names(list: &[String]) -> String {
    list.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}
