//! The UR5's forward kinematics, Jacobians, inverse kinematics and dynamics (`robots/ur5.urdf`,
//! root `base_link` to `tool0`), generated at build time by `build.rs` with the build API: the
//! code `kinematics demo` times against the runtime reference and the numeric solver. The command
//! cannot compile Rust at run time, so this is the one robot whose generated code it holds.
#![allow(dead_code)] // the generated API is complete; the demo uses part of it

include!(concat!(env!("OUT_DIR"), "/ur5.rs"));
