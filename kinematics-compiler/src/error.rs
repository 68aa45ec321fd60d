//! Errors of the compiler: only requests can be wrong, never a (validated) tree.

/// A compile request that does not fit the robot.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CompileError {
    /// A base or tip link the robot does not have, or a tip not below the base.
    #[error("robot `{robot}`: {source}")]
    Model {
        /// Robot name.
        robot: String,
        /// What is wrong.
        #[source]
        source: kinematics_model::ModelError,
    },
    /// A pose whose constants are not all finite: numbers of the description that are each finite
    /// compose into an infinity or a NaN (two fixed offsets of 1e308 in a row, mimic multipliers of
    /// 1e200 along a chain). The code would compute infinities, so none is emitted.
    #[error(
        "robot `{robot}`: link `{link}`: the constants of its pose are not all finite numbers (one is {value}): \
         the description's numbers overflow when composed"
    )]
    NonFiniteConstant {
        /// Robot name.
        robot: String,
        /// The first link (in request order) whose pose holds the constant.
        link: String,
        /// The constant (infinite or NaN).
        value: f64,
    },
    /// A chain no closed-form inverse kinematics family covers (every family's reason given).
    #[error("{0}")]
    NoIkFamily(Box<NoIkFamily>),
    /// Numeric inverse kinematics of a robot with a floating or spherical joint (its quaternion's
    /// four entries of `q` against three velocities: the steps are not yet mapped back).
    #[error("robot `{robot}`: inverse kinematics of a robot with a floating or spherical joint is not supported yet")]
    IkFloating {
        /// Robot name.
        robot: String,
    },
    /// A link whose mass the dynamics cannot take (its inertia breaks a rigid body's rules, or
    /// its mass is left to its geometry), naming it and the line of its `<inertial>`.
    #[error("robot `{robot}`: {refusal}")]
    Inertia {
        /// Robot name.
        robot: String,
        /// Which link, and why (boxed: the error stays small).
        #[source]
        refusal: Box<kinematics_model::inertia::InertiaRefusal>,
    },
    /// A link named for external forces that cannot take one.
    #[error("robot `{robot}`: {fault}")]
    ForceLink {
        /// Robot name.
        robot: String,
        /// Which link, and why.
        #[source]
        fault: crate::dynamics::ForceLinkFault,
    },
    /// A gravity vector with a NaN or infinite component.
    #[error("robot `{robot}`: gravity {gravity:?} is not a finite vector")]
    NonFiniteGravity {
        /// Robot name.
        robot: String,
        /// The gravity given.
        gravity: [f64; 3],
    },
    /// Inverse kinematics asked of other than exactly one tip.
    #[error("robot `{robot}`: inverse kinematics needs exactly one tip (`tip = \"...\"`), not {tips}")]
    IkNeedsOneTip {
        /// Robot name.
        robot: String,
        /// How many tips were asked for.
        tips: usize,
    },
}

/// Why no closed-form inverse kinematics family covers a chain (boxed in [`CompileError`], which
/// stays small).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("robot `{robot}`: no closed-form inverse kinematics for `{base}` -> `{tip}`: {reason}")]
pub struct NoIkFamily {
    /// Robot name.
    pub robot: String,
    /// The base link.
    pub base: String,
    /// The tip link.
    pub tip: String,
    /// Why each family does not apply.
    pub reason: String,
}
