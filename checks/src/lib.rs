//! Every robot in `robots/`, compiled to Rust at build time by `kinematics-compiler`, and a registry
//! of the generated functions for the agreement tests (`tests/`) to iterate over.
//!
//! Being a workspace member, this crate also puts the generated code through the workspace's
//! `cargo clippy -D warnings`: the emitted code must be clippy-clean in a user's crate.

pub use kinematics::Pose;

/// One generated leaf-link function set.
pub struct Tip {
    /// The link.
    pub link: &'static str,
    /// Its pose, `f64`.
    pub pose: fn(&[f64]) -> Pose<f64>,
    /// Its pose, `f32`.
    pub pose_f32: fn(&[f32]) -> Pose<f32>,
    /// Its position, `f64`.
    pub position: fn(&[f64]) -> [f64; 3],
}

/// The generated functions of one robot file.
pub struct GeneratedRobot {
    /// File name in `robots/`.
    pub file: &'static str,
    /// Degrees of freedom.
    pub dof: usize,
    /// Leaf links.
    pub tips: &'static [Tip],
    /// Links in the order `all_poses` returns them.
    pub all_links: &'static [&'static str],
    /// Poses of every link below the root.
    pub all_poses: fn(&[f64]) -> Vec<Pose<f64>>,
}

/// A slice as a fixed-size array reference; the registry only passes slices of the right length.
fn arr<T, const N: usize>(q: &[T]) -> &[T; N] {
    match q.try_into() {
        Ok(a) => a,
        Err(_) => unreachable_len(q.len(), N),
    }
}

#[cold]
fn unreachable_len(got: usize, expected: usize) -> ! {
    // The tests build q from `dof`; a mismatch is a bug in the test itself.
    #[allow(clippy::panic)]
    {
        panic!("q has {got} values, the generated function takes {expected}")
    }
}

/// `Kinematics::tip_poses_into` and `link_poses_into`.
pub type PosesInto = fn(&[f64], &mut [Pose<f64>]) -> Result<(), kinematics::RuntimeError>;

/// One robot compiled by `#[derive(Kinematics)]`, reached through the `Kinematics` trait.
pub struct DerivedRobot {
    /// File name in `robots/`.
    pub file: &'static str,
    /// `file` (the attribute names the file) or `inline` (the table is written in the attribute).
    pub how: &'static str,
    /// The tips.
    pub tips: &'static [&'static str],
    /// The links `link_poses_into` computes.
    pub links: &'static [&'static str],
    /// `Kinematics::tip_poses_into`.
    pub tip_poses_into: PosesInto,
    /// `Kinematics::link_poses_into`.
    pub link_poses_into: PosesInto,
    /// The tips' poses through the `f32` functions.
    pub tip_poses_f32: fn(&[f32]) -> Vec<Pose<f32>>,
    /// `Kinematics::reference`.
    pub reference: fn() -> Result<kinematics::ReferenceFk, kinematics::LoadError>,
}

include!(concat!(env!("OUT_DIR"), "/robots.rs"));
include!(concat!(env!("OUT_DIR"), "/derived.rs"));
