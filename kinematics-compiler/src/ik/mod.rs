//! Inverse kinematics, compiled: the families as data ([`families`]: each one's relations of
//! axes, solver, capacity and subproblems), the chain's geometry at its zero configuration
//! ([`geometry`]), the closed-form family that solves it, decided at compile time
//! ([`mod@classify`]: which family's relations hold, and where to place the points on the axes;
//! the plan is a six-joint family with six-joint geometry or a planar arm), the families composed as
//! straight-line code over the expression graph ([`closed_form`]: each family's branch, written
//! once in `kinematics_core::ik::branch` over an algebra, built with the graph as that algebra,
//! the geometry folded in; the eight branches side by side in lanes), the forward kinematics each solution is
//! measured with ([`measure`]: the compiled pose, on the solver's own sines and cosines), and the
//! body's emission ([`emit`]: one branch as straight-line Rust). The robot's functions built on it
//! (or on the family's solver in `kinematics-core`, called with the geometry as constants) are
//! written with the other output kinds, in `robot::ik`.

pub mod classify;
pub mod closed_form;
pub mod emit;
pub mod families;
pub mod geometry;
pub mod measure;

pub use classify::{
    FreeJoint, IkGeometry, IkPlan, MEET_TOLERANCE, PARALLEL_TOLERANCE, PlanarGeometry, SixGeometry, classify,
    classify_with,
};
pub use closed_form::{BranchValue, IkBody};
pub use families::{IkFamily, Relation, SixFacts, SixFamily, Solver};
pub use measure::Measure;
