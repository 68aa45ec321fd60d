//! Inverse kinematics at run time, for code the compiler generates: the Paden-Kahan subproblems
//! ([`subproblem`]), the closed-form families they compose into (six-joint arms: [`Arm6`] and the
//! family functions, [`FreeArm6`] for the six of a seven-joint arm; planar arms and the SCARA:
//! [`PlanarArm`]), the families' branches and subproblems 1 to 4 written once over an algebra
//! ([`branch`]: the solvers here run them on numbers, the compiler builds them as expressions), the numeric solver every chain gets ([`levenberg_marquardt`]), what a call
//! returns ([`IkSolutions`], [`NumericSolution`], [`IkError`]) and the refinement of a closed
//! form's solutions on the arm as written ([`IkSolutions::refined`]). The solver's steps and the
//! refinement share one linear solve (`ldl`: `L D L^T`, on the stack, lane by lane). No heap, no
//! `std`: `libm` does the square roots and inverse trigonometry.
//!
//! The compiler classifies a robot's chain at compile time and emits a call of one family
//! function with the chain's geometry as constants, so the optimiser folds them into the body;
//! the generated `tip_ik` then measures every solution's pose errors with the robot's own
//! generated forward kinematics ([`IkSolutions::measure`]) and, for a six-joint arm, refines the
//! exact solutions that miss their target by more than rounding ([`IkSolutions::refined`], or in
//! one pass of the lanes where the compiler made the arm's relations exact:
//! [`IkSolutions::from_lanes_refined`]).
//!
//! ```
//! use kinematics_core::ik::{Arm6, three_parallel_two_intersecting};
//! // The UR5 (Universal Robots' DH table) at its zero configuration, in IK-Geo's form.
//! let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
//! let arm = Arm6 {
//!     axes: [z, [0.0, -1.0, 0.0], [0.0, -1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0], [0.0, -1.0, 0.0]],
//!     offsets: [
//!         [0.0, 0.0, 0.089159], [0.0; 3], [-0.425, 0.0, 0.0], [-0.39225, 0.0, 0.0],
//!         [0.0, -0.10915, -0.09465], [0.0; 3], [0.0, -0.0823, 0.0],
//!     ],
//!     tool_rotation: [x, [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
//! };
//! let q = [0.3, -1.2, 1.0, 0.4, -0.7, 2.0];
//! let target = arm.pose(&q);
//! let mut solutions = three_parallel_two_intersecting(&arm, &target);
//! solutions.measure(&target, |q| arm.pose(q));
//! assert_eq!(solutions.exact().count(), 8);
//! assert!(solutions.iter().all(|s| s.position_error < 1e-14 && s.rotation_error < 1e-14));
//! assert!(solutions.iter().any(|s| s.q.iter().zip(&q).all(|(a, b)| (a - b).abs() < 1e-12)));
//! ```

mod bounded;
pub mod branch;
mod family;
mod ldl;
mod numeric;
mod real;
mod refine;
mod solutions;
pub mod subproblem;
mod target;
pub mod vector;

pub use bounded::{BoundedList, Full};
pub use family::{
    Arm6, FreeArm6, NEAR_SINGULAR_SIXTH, ORTHOGONAL, PlanarArm, PlanarJoint, insert_free, spherical,
    spherical_first_two_intersecting, spherical_last_two_intersecting, spherical_prismatic_third,
    spherical_two_parallel, three_parallel, three_parallel_two_intersecting,
};
pub use numeric::{NumericOptions, NumericSolution, levenberg_marquardt};
pub use real::{BRANCH_SIGNS_8, IkBranch, IkReal, branch_signs, branch_signs_4, splat_pose};
pub use refine::{LONGEST_CORRECTION, REFINE_ABOVE, RefineArm};
pub use solutions::{IkError, IkSolution, IkSolutions, ROTATION_TOLERANCE, check_seed, check_target, pose_errors};
pub use target::IkTarget;

use crate::pose::Pose;
use vector::{add, rotate};

impl Arm6 {
    /// The pose the arm reaches at `q`: the product of exponentials the family functions invert,
    /// `rot(h1, q1) ... rot(h6, q6) R6T` and `p01 + R01 p12 + ... + R06 p6T` (for tests and
    /// tools; generated code measures with the robot's generated forward kinematics).
    pub fn pose(&self, q: &[f64; 6]) -> Pose<f64> {
        // Fold from the tool back: each joint rotates everything after it.
        let mut rotation = self.tool_rotation;
        let mut point = self.offsets[6];
        for i in (0..6).rev() {
            let columns =
                [0, 1, 2].map(|j| rotate(self.axes[i], q[i], [rotation[0][j], rotation[1][j], rotation[2][j]]));
            rotation = [0, 1, 2].map(|r| [columns[0][r], columns[1][r], columns[2][r]]);
            point = add(self.offsets[i], rotate(self.axes[i], q[i], point));
        }
        Pose { rotation, translation: point }
    }

    /// [`Self::pose`] and the geometric Jacobian at `q` in `LOCAL_WORLD_ALIGNED` (column `i`:
    /// the linear velocity of the tip's origin and the angular velocity, in the base frame, per
    /// unit rate of joint `i`), as the generated `tip_pose_and_jacobian` gives them (for tests
    /// and tools, such as refining solutions with [`IkSolutions::refined`]).
    pub fn pose_and_jacobian(&self, q: &[f64; 6]) -> (Pose<f64>, [[f64; 6]; 6]) {
        // From the base out: joint i turns about R_0(i-1) h_i through the point reached so far.
        let mut rotation = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let mut point = self.offsets[0];
        let mut axes = [[0.0; 3]; 6];
        let mut points = [[0.0; 3]; 6];
        for i in 0..6 {
            axes[i] = vector::mul(&rotation, self.axes[i]);
            points[i] = point;
            // R_0i = R_0(i-1) rot(h_i, q_i): each column of R_0(i-1) turned about the joint's axis.
            let columns = [0, 1, 2].map(|j| rotate(axes[i], q[i], [rotation[0][j], rotation[1][j], rotation[2][j]]));
            rotation = [0, 1, 2].map(|r| [columns[0][r], columns[1][r], columns[2][r]]);
            point = add(point, vector::mul(&rotation, self.offsets[i + 1]));
        }
        let tool =
            [0, 1, 2].map(|r| [0, 1, 2].map(|c| (0..3).map(|k| rotation[r][k] * self.tool_rotation[k][c]).sum()));
        let mut jacobian = [[0.0; 6]; 6];
        for i in 0..6 {
            let linear = vector::cross(axes[i], vector::sub(point, points[i]));
            for k in 0..3 {
                jacobian[k][i] = linear[k];
                jacobian[3 + k][i] = axes[i][k];
            }
        }
        (Pose { rotation: tool, translation: point }, jacobian)
    }
}

#[cfg(test)]
mod tests;
