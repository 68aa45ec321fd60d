//! The emit stage: naming and scheduling graph nodes, and rendering them as text, LaTeX and Rust.
//!
//! Names follow the textbook: `c1`, `s1` for the cosine and sine of `q1`, `c23` for `cos(q2 + q3)`;
//! shared intermediate values are `t0, t1, ...` in schedule order, so a small change to a robot
//! makes a small diff in its code.

mod chunks;
mod names;
mod rust;
mod schedule;
mod text;

pub use names::Names;
pub use rust::{
    EmitOptions, StraightLine, Trig, emit_dynamics, emit_function, emit_module_source, emit_points, straight_line,
};
pub use schedule::{INLINE_DEPTH_LIMIT, MAX_EXPRESSION_DEPTH, Schedule};
pub use text::{INLINE_BUDGET, Listing, latex, latex_listing, text, text_listing};
