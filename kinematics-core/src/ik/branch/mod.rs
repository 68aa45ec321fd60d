//! One branch of a closed form, written once for every kind of arithmetic: the six-joint
//! families whose every step has at most two roots, composed of subproblems 1 to 4, generic over
//! an [`Algebra`] that either computes ([`Numbers`], on `f64` or on lanes of it) or builds the
//! compiler's expression graph, which emits the branch as straight-line code (where the arm's
//! numbers fold as the expressions are built). The run time's solver of such a family
//! ([`crate::ik::spherical_two_parallel`] and the others) runs its eight branches side by side in
//! `F64x8` lanes ([`solve_in_lanes`]); the compiler's `tip_ik` is the same branch emitted; the
//! families whose first step is a quartic end in this module's wrist and elbow, once per root.
//!
//! ```
//! use kinematics_core::ik::branch::{self, Numbers, Problem};
//! use kinematics_core::ik::{Arm6, branch_signs};
//! // A PUMA-like arm: axes 2, 3 parallel, a spherical wrist.
//! let (x, y, z) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
//! let arm = Arm6 {
//!     axes: [z, y, y, x, y, x],
//!     offsets: [[0.0; 3], [0.0; 3], [0.4, 0.0, 0.0], [0.4, 0.0, 0.0], [0.0; 3], [0.0; 3], [0.1, 0.0, 0.0]],
//!     tool_rotation: [x, y, z],
//! };
//! let target = arm.pose(&[0.3, -0.4, 0.9, 0.2, 0.5, -0.1]);
//! // Branch 0 on numbers, then all eight in lanes: branch 0 is lane 0, bit for bit.
//! let problem = Problem {
//!     arm: &arm,
//!     rotation: target.rotation,
//!     translation: target.translation,
//!     signs: branch_signs(0),
//!     singular_pass: true,
//! };
//! let one = branch::spherical_two_parallel(&mut Numbers::<f64>::new(), &problem);
//! let all = kinematics_core::ik::spherical_two_parallel(&arm, &target);
//! assert_eq!(one.q, all.as_slice()[0].q);
//! assert!(all.iter().any(|s| s.q.iter().zip([0.3, -0.4, 0.9, 0.2, 0.5, -0.1]).all(|(a, b)| (a - b).abs() < 1e-12)));
//! ```

//! **Inlining.** In an optimised build every function here is `#[inline(always)]`, so that in a
//! dispatched body (a generated `tip_ik` calling a family's solver) the whole branch runs in the
//! caller's instruction set; in a debug build none is forced inline, so that a frame holds one
//! function's temporaries rather than a whole family's (a family inlined whole on `F64x8` lanes
//! takes about 3 MB of stack unoptimised, more than a test thread has).

mod algebra;
mod family;
mod numbers;
mod subproblem;

pub use algebra::{Algebra, Flags, Matrix, Turn, Vector};
pub use family::{
    Branch, Composer, Problem, spherical_first_two_intersecting, spherical_last_two_intersecting,
    spherical_prismatic_third, spherical_two_parallel, three_parallel_two_intersecting,
};
pub(crate) use family::{Elbow, parallel_elbow, spherical_branch, wrist_target};
pub use numbers::{Numbers, branches_in_lanes, needs_singular_pass, solve_in_lanes, unmeasured};
pub use subproblem::Subproblems;
