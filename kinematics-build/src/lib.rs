//! Compiled forward kinematics from a build script: the build-time twin of `#[derive(Kinematics)]`.
//!
//! This crate owns generating a robot's Rust as a *file*: reading the description relative to the
//! crate's `Cargo.toml` ([`Robot`]), checking the options against it (the compiler's rules),
//! emitting `pub struct Name;` with its impls through `kinematics_compiler::robot::emit_robot` (the
//! very function the derive calls, so both give the same constants, functions and
//! `kinematics::Kinematics` impl), formatting with prettyplease, and writing atomically
//! ([`write_atomic`]). The `kinematics generate` command prints the same text.
//!
//! In `build.rs` (with `kinematics-build` under `[build-dependencies]` and `kinematics` under
//! `[dependencies]`):
//!
//! ```no_run
//! fn main() -> Result<(), kinematics_build::BuildError> {
//!     kinematics_build::Robot::urdf("robots/ur5.urdf")
//!         .base("base")
//!         .tip("tool0")
//!         .positions()
//!         .struct_name("Ur5")
//!         .write_to_out_dir("ur5.rs")?;
//!     Ok(())
//! }
//! ```
//!
//! and in the crate, `include!(concat!(env!("OUT_DIR"), "/ur5.rs"));` defines `Ur5` with
//! `Ur5::tip_pose(&q)`, `Ur5::link_poses(&q)`, `Ur5::reference()` and the rest, exactly as the
//! derive would. A build script's `main` may return [`BuildError`]: its `Debug` is its message, so
//! cargo shows ``robots/ur5.urdf: `.tip(..)`: tip link `tool9` does not exist; did you mean `tool0`?``.
//!
//! [`Robot::generate`] returns the formatted source instead of writing it:
//!
//! ```
//! let dir = std::env::temp_dir().join(format!("kinematics-build-doc-{}", std::process::id()));
//! std::fs::create_dir_all(&dir)?;
//! let table = "convention = \"standard\"\nname = \"pendulum\"\n[[joints]]\nname = \"swing\"\na = 1.0\n";
//! std::fs::write(dir.join("pendulum.toml"), table)?;
//! let source = kinematics_build::Robot::dh("pendulum.toml").manifest_dir(&dir).tip("link1").generate()?;
//! assert!(source.contains("pub struct Pendulum;"));
//! assert!(source.contains("pub fn tip_pose(q: &[f64; 1]) -> ::kinematics::__private::Pose<f64>"));
//! # std::fs::remove_dir_all(&dir)?;
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod emit;
mod error;
mod robot;
mod source;
mod write;

pub use emit::default_struct_name;
pub use error::{BuildError, CallFault};
pub use kinematics_compiler::emit::Trig;
pub use robot::Robot;
pub use write::write_atomic;
