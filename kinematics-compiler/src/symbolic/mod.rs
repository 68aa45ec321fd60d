//! The symbolic stage: the expression graph, angles as linear forms, the chain IR of steps,
//! symbolic rigid transforms, and lowering from the model.

pub mod angle;
pub mod differential;
pub mod graph;
pub mod lower;
pub mod step;
pub mod transform;
