//! The `#[derive(Kinematics)]` macro (placeholder).
//!
//! This crate will read a robot description at compile time and emit closed-form forward
//! kinematics through the compiler crate. Until that lands it exports nothing, so that the
//! workspace layout and the root crate's re-exports are already in their final shape.
