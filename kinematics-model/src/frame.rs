//! The reference frames a Jacobian or a velocity is expressed in, named as Pinocchio names them.
//!
//! The runtime reference and the compiler both take this vocabulary from the model, so a request
//! means the same in both (they share the model and nothing else).
//!
//! `JacobianFrame` names them (`LOCAL_WORLD_ALIGNED`, `LOCAL`): the vocabulary of velocities the
//! runtime and the compiler share.

/// Which axes and which point a Jacobian's rows (and a twist) refer to.
///
/// Both give the linear velocity of the frame's origin (rows 0..3) and the angular velocity
/// (rows 3..6), relative to the base link; they differ in the axes they are written in.
///
/// ```
/// use kinematics_model::JacobianFrame;
/// assert_eq!(JacobianFrame::default(), JacobianFrame::LocalWorldAligned);
/// assert_eq!(JacobianFrame::Local.name(), "LOCAL");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum JacobianFrame {
    /// Pinocchio's `LOCAL_WORLD_ALIGNED`: the velocity of the frame's origin and the angular
    /// velocity, in the base link's axes. The rows are the time derivative of the translation of
    /// the pose in the base and the angular velocity `w` with `dR/dt = [w]x R`.
    #[default]
    LocalWorldAligned,
    /// Pinocchio's `LOCAL`: the same two vectors in the frame's own axes (`R^T` times each).
    Local,
}

impl JacobianFrame {
    /// Both frames.
    pub const ALL: [JacobianFrame; 2] = [JacobianFrame::LocalWorldAligned, JacobianFrame::Local];

    /// Pinocchio's name of the frame (`LOCAL_WORLD_ALIGNED`, `LOCAL`).
    pub fn name(self) -> &'static str {
        match self {
            JacobianFrame::LocalWorldAligned => "LOCAL_WORLD_ALIGNED",
            JacobianFrame::Local => "LOCAL",
        }
    }
}
