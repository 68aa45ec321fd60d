//! Central differences of a pose along each velocity, Richardson-extrapolated: a third witness of
//! Jacobians, sharing no code with the compiler's, the runtime's or the dual numbers'.
//!
//! A central difference `D(h) = (f(h) - f(-h)) / 2h` along a smooth path is the derivative plus
//! a series in `h^2`; [`LEVELS`] differences at `h, h/2, h/4, ...` combined by Richardson's
//! extrapolation cancel the first `LEVELS - 1` terms of that series. What is left is rounding:
//! about `eps * |f| / h_min` times the extrapolation's weights (a few), so about `1e-13` times the
//! size of the pose entries for the steps below (measured on every robot: see
//! `checks/tests/jacobians.rs`, whose tolerance for them is `1e-12` times the reach).

use kinematics::Pose;
use kinematics::model::{JointMotion, KinematicTree};

/// The largest step, in radians or metres (or, along a floating or spherical joint's angular
/// velocity, radians of turn).
pub const STEP: f64 = 0.1;

/// Differences taken, at `STEP`, `STEP / 2`, ... (each halving the last).
pub const LEVELS: usize = 5;

/// `q` moved by `t` along velocity `v` of `tree`: a joint's own entry for a velocity of one entry;
/// along a floating joint's child axis (its rotation's column) for a linear velocity of it, and
/// the quaternion times `exp(t e / 2)` on the right for a floating or spherical joint's angular
/// one (the path whose derivative is Pinocchio's free-flyer or spherical joint velocity).
///
/// # Panics
///
/// If `v` is not a velocity of `tree` (a test's bug).
pub fn moved(tree: &KinematicTree, q: &[f64], v: usize, t: f64) -> Vec<f64> {
    let mut q = q.to_vec();
    if let Some(entry) = tree.velocity_of_entry().iter().position(|&c| c == Some(v)) {
        q[entry] += t;
        return q;
    }
    for joint in tree.quaternion_joints() {
        let kind = tree.joint(joint).kind;
        let (JointMotion::Dof(s), Some(c), Some(offset)) =
            (tree.joint(joint).motion, tree.velocity_start(joint), kind.quaternion_offset())
        else {
            continue;
        };
        if !(c..c + kind.velocities()).contains(&v) {
            continue;
        }
        // The quaternion, after a floating joint's position; its linear velocities first.
        let (qs, k) = (s + offset, v - c);
        let [x, y, z, w] = [q[qs], q[qs + 1], q[qs + 2], q[qs + 3]];
        if k < offset {
            let rotation = kinematics::quaternion_matrix(x, y, z, w);
            for a in 0..3 {
                q[s + a] += t * rotation[a][k];
            }
        } else {
            let (sn, cs) = (t / 2.0).sin_cos();
            let mut e = [0.0; 3];
            e[k - offset] = sn;
            let [bx, by, bz] = e;
            q[qs] = w * bx + x * cs + y * bz - z * by;
            q[qs + 1] = w * by - x * bz + y * cs + z * bx;
            q[qs + 2] = w * bz + x * by - y * bx + z * cs;
            q[qs + 3] = w * cs - x * bx - y * by - z * bz;
        }
        return q;
    }
    #[allow(clippy::panic)]
    {
        panic!("velocity {v} belongs to no joint of `{}`", tree.name())
    }
}

/// The geometric Jacobian (`LOCAL_WORLD_ALIGNED`) of `pose` at `q`, one column per velocity of
/// `tree`: the derivatives of the pose's twelve entries along [`moved`], extrapolated, then the
/// translation's and `w` from the skew part of `dR R^T`.
pub fn jacobian(tree: &KinematicTree, pose: impl Fn(&[f64]) -> Pose<f64>, q: &[f64]) -> Vec<[f64; 6]> {
    let p = pose(q).entries();
    (0..tree.velocity_dof())
        .map(|v| {
            // A central difference at each step; `romberg` extrapolates them.
            let mut rows: Vec<[f64; 12]> = Vec::with_capacity(LEVELS);
            let mut h = STEP;
            for _ in 0..LEVELS {
                let (plus, minus) = (pose(&moved(tree, q, v, h)).entries(), pose(&moved(tree, q, v, -h)).entries());
                let row: [f64; 12] = std::array::from_fn(|k| (plus[k] - minus[k]) / (2.0 * h));
                rows.push(row);
                h /= 2.0;
            }
            let d = romberg(&rows);
            let r = |a: usize, b: usize| p[3 * a + b];
            let m = |a: usize, b: usize| (0..3).map(|k| d[3 * a + k] * r(b, k)).sum::<f64>();
            [d[9], d[10], d[11], (m(2, 1) - m(1, 2)) / 2.0, (m(0, 2) - m(2, 0)) / 2.0, (m(1, 0) - m(0, 1)) / 2.0]
        })
        .collect()
}

/// Richardson's extrapolation of central differences at halving steps (errors in `h^2`, `h^4`,
/// ...): the last entry of Romberg's table.
fn romberg(differences: &[[f64; 12]]) -> [f64; 12] {
    let mut table: Vec<[f64; 12]> = differences.to_vec();
    let mut factor = 4.0;
    for _ in 1..differences.len() {
        table = table
            .windows(2)
            .map(|pair| std::array::from_fn(|k| pair[1][k] + (pair[1][k] - pair[0][k]) / (factor - 1.0)))
            .collect();
        factor *= 4.0;
    }
    table[0]
}
