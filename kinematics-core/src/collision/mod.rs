//! Collision checking at run time, for generated code: obstacles (spheres, capsules, cylinders,
//! oriented boxes), an environment borrowing slices of them, and the checks a compiled robot's
//! `collides` and `self_collides` run on its sphere centres and the tables the compiler wrote,
//! on one configuration or on lanes of them, each with its own verdict.
//!
//! No heap: an [`Environment`] borrows the caller's slices. A NaN or infinite obstacle never makes
//! a configuration free: [`Environment::new`] refuses it (and a negative or zero size), so a
//! check never meets one; a configuration with a NaN or infinite entry is colliding. Touching
//! counts as colliding. The answer does not depend on the order of the obstacles: every obstacle
//! is tested until one is hit.

mod clearance;
#[cfg(feature = "point-cloud")]
mod cloud;
mod distance;
mod grid;
mod held;
mod motion;
mod obstacles;
mod robot;
mod tables;
mod verdicts;

#[cfg(feature = "point-cloud")]
#[cfg_attr(docsrs, doc(cfg(feature = "point-cloud")))]
pub use cloud::PointCloud;
pub use grid::{MAX_GRIDS, PairGrid};
pub use held::{Carried, Held, HeldError, HeldLink, HeldObject, HoldTables, Holding, World};
pub use motion::{
    Ends, Motion, Resolution, first_collisions, motion_any_wide, motion_wide, motions_any_wide, motions_wide,
};
pub use obstacles::{
    BoxObstacle, CapsuleObstacle, CylinderObstacle, Environment, ObstacleError, SphereObstacle, SphereQuery, Vec3,
};
pub use robot::Collision;
pub use tables::CollisionTables;
pub use verdicts::{CheckLanes, Flags, Flags32x8, Flags32x16, Flags64x4, Flags64x8, LaneMask, non_finite};
#[doc(hidden)]
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn box_hits<L: CheckLanes>(b: &BoxObstacle, c: &[L; 3], r: L) -> L::Flags {
    obstacles::Obstacle::hits(b, c, r)
}
