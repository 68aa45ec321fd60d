//! What a compiled robot's checked entry points return when the caller's slices do not fit.
//!
//! `KinematicsError` is all `'static`: nothing allocates.

use core::fmt;

/// A call whose slices do not fit the robot. Every field is `'static` or a number: building one
/// allocates nothing.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum KinematicsError {
    /// `q` does not have one entry per degree of freedom.
    WrongDof {
        /// Robot name.
        robot: &'static str,
        /// Degrees of freedom.
        expected: usize,
        /// Length of `q`.
        got: usize,
        /// The joint names in degree-of-freedom order, for the message.
        joints: &'static [&'static str],
    },
    /// An output slice of the wrong length.
    WrongOutputLength {
        /// Robot name.
        robot: &'static str,
        /// Values computed.
        expected: usize,
        /// Length of the output slice.
        got: usize,
    },
    /// A column of a column-wise batch (`*_batch_columns`) of another length than the output.
    WrongColumnLength {
        /// Robot name.
        robot: &'static str,
        /// The joint whose column it is.
        joint: &'static str,
        /// Length of the output slice.
        expected: usize,
        /// Length of the column.
        got: usize,
    },
    /// An input of a batch of several (`qds`, `qdds` or `taus` beside `qs`, as
    /// `inverse_dynamics_batch` takes them) of another length than the output.
    WrongInputLength {
        /// Robot name.
        robot: &'static str,
        /// The input (`"qs"`, `"qds"`, `"qdds"`, `"taus"`, `"forces"`).
        input: &'static str,
        /// Length of the output slice.
        expected: usize,
        /// Length of the input.
        got: usize,
    },
    /// A motion's resolution (`motion_collides`) that is not positive and finite.
    BadResolution {
        /// Robot name.
        robot: &'static str,
        /// The resolution given.
        resolution: f64,
    },
    /// A proximity cost's margin (`proximity_cost`) that is negative or not finite.
    BadMargin {
        /// Robot name.
        robot: &'static str,
        /// The margin given.
        margin: f64,
    },
    /// Forward dynamics through a mass matrix that cannot be inverted: the velocity named moves
    /// no mass of its own (a joint that carries no mass, or carries only what other joints move
    /// the same way), so no torque determines its acceleration.
    SingularMassMatrix {
        /// Robot name.
        robot: &'static str,
        /// The velocity whose pivot vanished (one of `VELOCITY_NAMES`).
        velocity: &'static str,
    },
    /// Forward dynamics whose accelerations overflowed (finite inputs too large for them).
    NotFinite {
        /// Robot name.
        robot: &'static str,
        /// What overflowed.
        quantity: &'static str,
    },
    /// [`KinematicsError::SingularMassMatrix`] at a configuration of a batch
    /// (`forward_dynamics_batch`): the first configuration refused.
    SingularMassMatrixInBatch {
        /// Robot name.
        robot: &'static str,
        /// The configuration's index in the batch.
        configuration: usize,
        /// The velocity whose pivot vanished (one of `VELOCITY_NAMES`).
        velocity: &'static str,
    },
    /// [`KinematicsError::NotFinite`] at a configuration of a batch (`forward_dynamics_batch`):
    /// the first configuration refused.
    NotFiniteInBatch {
        /// Robot name.
        robot: &'static str,
        /// The configuration's index in the batch.
        configuration: usize,
        /// What overflowed.
        quantity: &'static str,
    },
}

impl KinematicsError {
    /// The error as configuration `configuration` of a batch gives it: a refusal of forward
    /// dynamics (a singular mass matrix, an overflow) with the configuration's index; any other
    /// error as it is.
    pub(crate) fn in_batch(self, configuration: usize) -> Self {
        match self {
            KinematicsError::SingularMassMatrix { robot, velocity } => {
                KinematicsError::SingularMassMatrixInBatch { robot, configuration, velocity }
            }
            KinematicsError::NotFinite { robot, quantity } => {
                KinematicsError::NotFiniteInBatch { robot, configuration, quantity }
            }
            other => other,
        }
    }
}

/// What a singular mass matrix means, after the robot's name.
fn singular(f: &mut fmt::Formatter<'_>, velocity: &str) -> fmt::Result {
    write!(
        f,
        "the mass matrix is singular: forward dynamics cannot determine the acceleration of `{velocity}`, which moves \
         no mass of its own"
    )
}

impl fmt::Display for KinematicsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            KinematicsError::WrongDof { robot, expected, got, joints } => {
                write!(f, "robot `{robot}` has {expected} degrees of freedom (")?;
                for (i, joint) in joints.iter().enumerate() {
                    if i > 0 {
                        f.write_str(", ")?;
                    }
                    f.write_str(joint)?;
                }
                write!(f, "), but q has {got} values")
            }
            KinematicsError::WrongOutputLength { robot, expected, got } => {
                write!(f, "robot `{robot}`: the output holds {got} values, but {expected} are computed")
            }
            KinematicsError::WrongColumnLength { robot, joint, expected, got } => write!(
                f,
                "robot `{robot}`: the column of joint `{joint}` holds {got} values, but the output holds {expected}"
            ),
            KinematicsError::WrongInputLength { robot, input, expected, got } => {
                write!(f, "robot `{robot}`: `{input}` holds {got} values, but the output holds {expected}")
            }
            KinematicsError::BadResolution { robot, resolution } => write!(
                f,
                "robot `{robot}`: a motion's resolution (a joint step, or states per unit of joint-space \
                 distance) must be positive and finite, not {resolution}"
            ),
            KinematicsError::BadMargin { robot, margin } => write!(
                f,
                "robot `{robot}`: a proximity cost's margin must be finite and not negative (the distance \
                 within which pairs cost), not {margin}"
            ),
            KinematicsError::SingularMassMatrix { robot, velocity } => {
                write!(f, "robot `{robot}`: ")?;
                singular(f, velocity)
            }
            KinematicsError::NotFinite { robot, quantity } => {
                write!(f, "robot `{robot}`: the {quantity} overflowed to values that are not finite")
            }
            KinematicsError::SingularMassMatrixInBatch { robot, configuration, velocity } => {
                write!(f, "robot `{robot}`, configuration {configuration} of the batch: ")?;
                singular(f, velocity)
            }
            KinematicsError::NotFiniteInBatch { robot, configuration, quantity } => write!(
                f,
                "robot `{robot}`, configuration {configuration} of the batch: the {quantity} overflowed to values that \
                 are not finite"
            ),
        }
    }
}

impl core::error::Error for KinematicsError {}
