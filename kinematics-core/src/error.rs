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
            KinematicsError::SingularMassMatrix { robot, velocity } => write!(
                f,
                "robot `{robot}`: the mass matrix is singular: forward dynamics cannot determine the acceleration \
                 of `{velocity}`, which moves no mass of its own"
            ),
            KinematicsError::NotFinite { robot, quantity } => {
                write!(f, "robot `{robot}`: the {quantity} overflowed to values that are not finite")
            }
        }
    }
}

impl core::error::Error for KinematicsError {}
