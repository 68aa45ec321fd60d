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

include!(concat!(env!("OUT_DIR"), "/robots.rs"));
