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
}
