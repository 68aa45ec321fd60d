//! Collision checking as a user derives it (issue 30): the sphere centres `collision` emits
//! against the runtime reference's own (its link poses, the elements' origins as nalgebra
//! isometries), on spherized robots and on an arm whose geometry is primitives, the radii and
//! links as the model covers them, and the batch and lane forms equal to the scalar one.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::model::collision::{Meshes, link_spheres};
use kinematics::{AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, Configurations, F64x4, Kinematics};

/// VAMP's spherized Panda (59 spheres).
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda_spherized.urdf", collision)]
pub struct Panda;

/// VAMP's spherized UR5 with its gripper (40 spheres), in `f64` and `f32`.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_spherized.urdf", collision, scalars(f64, f32))]
pub struct Ur5;

/// A UR5 whose geometry is cylinders, a capsule and a box, covered to 2 cm.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_primitives.urdf", base = "base", collision(sphere_cover = 0.02))]
pub struct Ur5Primitives;

/// The generated centres against the reference's on 2,000 configurations (the special angles,
/// beyond the limits, within them), to the agreement tolerance times the robot's reach, and the
/// radii and links against the model's cover.
fn agrees<const N: usize, const S: usize>(
    centers: impl Fn(&[f64; N]) -> [[f64; 3]; S],
    radii: &[f64; S],
    links: &[&str; S],
    reference: &kinematics::ReferenceFk,
    base: &str,
    cover: f64,
) {
    let tree = reference.tree();
    let spheres = link_spheres(tree, cover, Meshes::Refuse).unwrap();
    assert_eq!(spheres.len(), S);
    for (k, s) in spheres.iter().enumerate() {
        assert_eq!(radii[k], s.sphere.radius, "sphere {k}");
        assert_eq!(links[k], tree.link(s.link).name, "sphere {k}");
    }
    let tolerance = AGREEMENT_TOLERANCE * tree.reach();
    let mut worst = 0.0_f64;
    for q in Configurations::new(tree).take(2_000) {
        let q: [f64; N] = q.try_into().unwrap();
        let generated = centers(&q);
        let base_pose = reference.link_pose(&q, base).unwrap();
        for (k, expected) in reference.sphere_centers(&q, &spheres).unwrap().iter().enumerate() {
            let expected = base_pose.inverse() * expected;
            let error = (0..3).map(|i| (generated[k][i] - expected[i]).abs()).fold(0.0, f64::max);
            assert!(error.is_finite() && error <= tolerance, "sphere {k} at {q:?}: off by {error:e}");
            worst = worst.max(error);
        }
    }
    assert!(worst > 0.0, "the comparison compared nothing");
}

#[test]
fn sphere_centers_agree_with_the_reference() {
    agrees(
        Panda::sphere_centers,
        &Panda::SPHERE_RADII,
        &Panda::SPHERE_LINKS,
        &Panda::reference().unwrap(),
        Panda::BASE,
        0.01,
    );
    agrees(Ur5::sphere_centers, &Ur5::SPHERE_RADII, &Ur5::SPHERE_LINKS, &Ur5::reference().unwrap(), Ur5::BASE, 0.01);
    agrees(
        Ur5Primitives::sphere_centers,
        &Ur5Primitives::SPHERE_RADII,
        &Ur5Primitives::SPHERE_LINKS,
        &Ur5Primitives::reference().unwrap(),
        Ur5Primitives::BASE,
        0.02,
    );
    assert_eq!(Panda::SPHERE_RADII.len(), 59);
    assert_eq!(Ur5::SPHERE_RADII.len(), 40);
}

#[test]
fn batches_lanes_and_f32_equal_the_scalar_centres() {
    let reference = Ur5::reference().unwrap();
    let qs: Vec<[f64; 6]> = Configurations::new(reference.tree()).take(37).map(|q| q.try_into().unwrap()).collect();
    let mut out = vec![[[0.0; 3]; 40]; qs.len()];
    Ur5::sphere_centers_batch(&qs, &mut out).unwrap();
    for (q, batch) in qs.iter().zip(&out) {
        assert_eq!(*batch, Ur5::sphere_centers(q));
    }
    let lanes: [F64x4; 6] = std::array::from_fn(|j| F64x4::new(std::array::from_fn(|l| qs[l][j])));
    let centers = Ur5::sphere_centers_generic(&lanes);
    for (l, q) in qs.iter().take(4).enumerate() {
        let scalar = Ur5::sphere_centers(q);
        for k in 0..40 {
            for i in 0..3 {
                assert_eq!(centers[k][i].to_array()[l], scalar[k][i]);
            }
        }
    }
    for q in &qs {
        let single = Ur5::sphere_centers_f32(&q.map(|x| x as f32));
        let double = Ur5::sphere_centers(q);
        for k in 0..40 {
            for i in 0..3 {
                let error = (f64::from(single[k][i]) - double[k][i]).abs();
                assert!(error <= AGREEMENT_TOLERANCE_F32 * reference.tree().reach(), "sphere {k}: {error:e}");
            }
        }
    }
}
