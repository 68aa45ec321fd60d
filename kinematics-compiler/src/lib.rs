//! The kinematics compiler: from a validated [`kinematics_model::KinematicTree`] to straight-line Rust.
//!
//! The stages after the model live here, one module each:
//! [`symbolic`] (a hash-consed expression graph, angles as linear forms, the chain IR of steps and
//! its lowering from the model), [`simplify`] (directed, named rewrites of the chain: exact quarter
//! turns, merged parallel axes, angle sums), and [`emit`] (scheduling and naming of the graph's
//! nodes, and Rust tokens through `quote`). [`compile`] runs them; [`Compiled`] holds the result,
//! its operation counts ([`OpCount`]), a numeric evaluator, text and LaTeX renderings, and the Rust
//! code. The compiler never depends on the runtime reference, which is what checks it.
//!
//! ```
//! use kinematics_compiler::{compile, Request};
//! let dh = "convention = \"standard\"\n[[joints]]\nname = \"j1\"\na = 1.0\n[[joints]]\nname = \"j2\"\na = 1.0\n";
//! let tree = kinematics_model::parse_source("planar_2r.toml", dh)?;
//! let compiled = compile(&tree, &Request::tip("link2"))?;
//! assert_eq!(compiled.frame_text(0)[9], "c1 + c12");
//! assert_eq!(compiled.op_count().sin_cos, 2);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod collision_layout;
pub mod dynamics;
pub mod emit;
mod error;
pub mod ik;
pub mod options;
mod request;
pub mod robot;
pub mod simplify;
mod stats;
pub mod symbolic;

pub use error::{CompileError, NoIkFamily};
pub use request::{
    Compiled, Frame, FrameEvaluator, FrameVelocity, Request, Velocity, VelocityForm, compile, plain_product_count,
};
pub use stats::{OpCount, marginal_counts};
