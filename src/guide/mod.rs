//! The guide: everything the README leaves out, one page per topic.
//!
//! These modules hold documentation and nothing else. Each page is a Markdown file beside this one
//! (`src/guide/*.md`, readable on its own), pulled in with `include_str!`, so docs.rs renders it
//! and `cargo test --doc -p kinematics` runs every Rust example on it as a doctest. Every figure
//! comes with the command that measured it.
//!
//! Start with the [`tutorial`]: from `cargo add` to a pose, its Jacobian, its inverse and a
//! collision check, in small steps. Then [`derive`](mod@derive): what `#[derive(Kinematics)]`
//! takes and what a struct gets. Then, by topic:
//!
//! | page | what it covers |
//! |---|---|
//! | [`tutorial`] | a first read: a pose, its check, the Jacobian, the inverse, batches and lanes, collision |
//! | [`derive`](mod@derive) | the derive's keys, the functions a struct gets, inline DH tables, compile errors |
//! | [`velocities`] | Jacobians (`LOCAL_WORLD_ALIGNED`, `LOCAL`), pose with Jacobian, twists; how they are checked |
//! | [`inverse_kinematics`] | closed-form families, what comes back, seven joints, the numeric solver, speed |
//! | [`dynamics`] | gravity torques, inverse dynamics, the mass matrix, forward dynamics from the links' inertias |
//! | [`collision`] | collision geometry from URDF and SRDF, its sphere cover, the pairs, `sphere_centers`, `collides`, `self_collides`, obstacles |
//! | [`floating_bases`] | free-flying roots, URDF `floating` and `planar` joints, MJCF ball joints, quaternions in `q` |
//! | [`orientation`] | a [`Pose`](crate::Pose)'s rotation as quaternions, roll-pitch-yaw, ZYZ, axis-angle |
//! | [`exactness`] | decimal angles that mean a quarter turn, and the policy that reads them so |
//! | [`trig`] | our sine and cosine, its accuracy contract, our `atan2` |
//! | [`lanes`] | `F64x4`, `F32x8`, batches, `parallel::batch` |
//! | [`no_std`] | firmware: the crate without `std` |
//! | [`errors`] | what can go wrong, and what you get |
//! | [`command_line`] | the `kinematics` command: `demo`, `inspect`, `fk`, `ik`, `expr`, `generate`, `check`, `draw`, `graph` |
//! | [`build_scripts`] | `kinematics-build`: the same code from `build.rs`, as a file |
//! | [`emitted`] | what the compiler emits, its operation counts, compile cost |
//! | [`checks`] | how the generated code is checked, and how closely it agrees |
//! | [`speed`] | every timing, with the command that took it |
//! | [`runtime`] | the runtime reference ([`ReferenceFk`](crate::ReferenceFk)) |
//! | [`descriptions`] | URDF, MJCF and DH tables: what is read, what is ignored, and the robots in `robots/` |
//! | [`layout`] | the crates and where the design is written down |
//!
//! The examples load robots from `robots/` in the repository (paths in `urdf = "..."` are relative
//! to the crate's `Cargo.toml`), so they run from a checkout: `cargo test --doc -p kinematics`.
//! Read the pages locally with `cargo doc -p kinematics --open` (then `kinematics::guide`).

pub mod tutorial {
    #![doc = include_str!("tutorial.md")]
}

pub mod derive {
    #![doc = include_str!("derive.md")]
}

pub mod velocities {
    #![doc = include_str!("velocities.md")]
}

pub mod inverse_kinematics {
    #![doc = include_str!("inverse_kinematics.md")]
}

pub mod collision {
    #![doc = include_str!("collision.md")]
}

pub mod dynamics {
    #![doc = include_str!("dynamics.md")]
}

pub mod floating_bases {
    #![doc = include_str!("floating_bases.md")]
}

pub mod orientation {
    #![doc = include_str!("orientation.md")]
}

pub mod exactness {
    #![doc = include_str!("exactness.md")]
}

pub mod trig {
    #![doc = include_str!("trig.md")]
}

pub mod lanes {
    #![doc = include_str!("lanes.md")]
}

pub mod no_std {
    #![doc = include_str!("no_std.md")]
}

pub mod errors {
    #![doc = include_str!("errors.md")]
}

pub mod command_line {
    #![doc = include_str!("command_line.md")]
}

pub mod build_scripts {
    #![doc = include_str!("build_scripts.md")]
}

pub mod emitted {
    #![doc = include_str!("emitted.md")]
}

pub mod checks {
    #![doc = include_str!("checks.md")]
}

pub mod speed {
    #![doc = include_str!("speed.md")]
}

pub mod runtime {
    #![doc = include_str!("runtime.md")]
}

pub mod descriptions {
    #![doc = include_str!("descriptions.md")]
}

pub mod layout {
    #![doc = include_str!("layout.md")]
}
