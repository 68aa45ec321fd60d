//! Errors of the runtime reference.

use kinematics_model::ModelError;

/// A runtime query that cannot be answered.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RuntimeError {
    /// `q` does not have one entry per degree of freedom.
    #[error("robot `{robot}` has {expected} degrees of freedom ({joints}), but q has {got} values")]
    WrongDof {
        /// Robot name.
        robot: String,
        /// Degrees of freedom.
        expected: usize,
        /// Length of `q`.
        got: usize,
        /// The joint names in DoF order, for the message.
        joints: String,
    },
    /// A joint value in `q` that is NaN or infinite.
    #[error("robot `{robot}`: the value of joint `{joint}` (q[{index}]) is {value}, not a finite number")]
    NonFiniteValue {
        /// Robot name.
        robot: String,
        /// The joint the value drives.
        joint: String,
        /// Its index in `q`.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A floating or spherical joint's quaternion whose squared length is zero, subnormal or
    /// overflows: it cannot be normalised into a rotation.
    #[error("robot `{robot}`: the quaternion of {kind} joint `{joint}` (q[{index}..{}]) has no length to normalise", .index + 4)]
    DegenerateQuaternion {
        /// Robot name.
        robot: String,
        /// The joint.
        joint: String,
        /// Its kind (`floating` or `spherical`).
        kind: &'static str,
        /// Where its quaternion starts in `q`.
        index: usize,
    },
    /// A link or chain that the tree does not have.
    #[error("robot `{robot}`: {source}")]
    Model {
        /// Robot name.
        robot: String,
        /// What is missing.
        #[source]
        source: ModelError,
    },
}
