//! Legged robots with a free-flying trunk: the quadruped and the humanoid of `robots/`, their trunk's
//! pose an input (`floating_base`), feet and wrists computed with their Jacobians.
//!
//! `cargo run --example floating_base`
#![allow(clippy::print_stdout)] // an example prints what it computes

use kinematics::Kinematics;

#[derive(Kinematics)]
#[kinematics(
    urdf = "robots/quadruped.urdf",
    floating_base,
    tips("FR_foot", "FL_foot", "RR_foot", "RL_foot"),
    jacobians
)]
/// The quadruped, its trunk free-flying in `world`.
pub struct Quadruped;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/humanoid.urdf", floating_base, tips("l_sole", "r_sole", "l_wrist", "r_wrist"), jacobians)]
/// The humanoid, its torso free-flying in `world`.
pub struct Humanoid;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    // The trunk 0.3 m up and yawed 30 degrees: the quaternion (0, 0, sin 15deg, cos 15deg), here
    // scaled by 2 (the rotation is the normalised quaternion's); the legs bent.
    let (s, c) = 15f64.to_radians().sin_cos();
    let mut q = [0.0; Quadruped::DOF];
    q[..7].copy_from_slice(&[0.0, 0.0, 0.3, 0.0, 0.0, 2.0 * s, 2.0 * c]);
    for leg in 0..4 {
        q[7 + 3 * leg + 1] = 0.8; // thigh
        q[7 + 3 * leg + 2] = -1.6; // calf
    }
    let feet = Quadruped::tip_poses(&q);
    let jacobians = Quadruped::tip_jacobians(&q);
    let reference = Quadruped::reference()?;
    println!(
        "quadruped: {} entries of q, {} velocities ({})",
        Quadruped::DOF,
        Quadruped::VELOCITY_DOF,
        Quadruped::VELOCITY_NAMES[..6].join(", ")
    );
    for (k, foot) in Quadruped::TIPS.iter().enumerate() {
        let [x, y, z] = feet[k].translation;
        let check = reference.relative_pose(&q, Quadruped::BASE, foot)?;
        let deviation = feet[k].deviation(&check, reference.tree().reach());
        // The trunk's yaw rate (its angular velocity about its own z) moves the foot sideways.
        let yaw = [jacobians[k][0][5], jacobians[k][1][5], jacobians[k][2][5]];
        println!(
            "  {foot:8} at ({x:+.4}, {y:+.4}, {z:+.4}) m; per rad/s of trunk yaw ({:+.4}, {:+.4}, {:+.4}) m/s; deviation from the reference {deviation:.1e}",
            yaw[0], yaw[1], yaw[2]
        );
    }

    let mut q = [0.0; Humanoid::DOF];
    q[..7].copy_from_slice(&[0.5, -0.2, 0.33, 0.0, 0.0, 0.0, 1.0]);
    let poses = Humanoid::tip_poses(&q);
    let reference = Humanoid::reference()?;
    println!("humanoid: {} entries of q, {} velocities", Humanoid::DOF, Humanoid::VELOCITY_DOF);
    for (k, link) in Humanoid::TIPS.iter().enumerate() {
        let [x, y, z] = poses[k].translation;
        let deviation =
            poses[k].deviation(&reference.relative_pose(&q, Humanoid::BASE, link)?, reference.tree().reach());
        println!("  {link:8} at ({x:+.4}, {y:+.4}, {z:+.4}) m; deviation from the reference {deviation:.1e}");
    }
    Ok(())
}
