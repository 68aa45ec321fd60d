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

use kinematics::collision::{BoxObstacle, CapsuleObstacle, CylinderObstacle, Environment, SphereObstacle};
use kinematics::runtime::ReferenceObstacles;
use kinematics::runtime::kinematics_model::collision::sphere_pairs;

/// A deterministic stream of numbers in [0, 1) (splitmix64).
struct Stream(u64);

impl Stream {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn within(&mut self, half: f64) -> f64 {
        (2.0 * self.next() - 1.0) * half
    }

    fn point(&mut self, half: f64) -> [f64; 3] {
        [self.within(half), self.within(half), self.within(half).abs()]
    }

    /// A rotation's rows: a random unit quaternion's matrix.
    fn rotation(&mut self) -> [[f64; 3]; 3] {
        let q = [self.within(1.0), self.within(1.0), self.within(1.0), self.within(1.0)];
        let n = q.iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-3);
        let [x, y, z, w] = q.map(|v| v / n);
        [
            [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - z * w), 2.0 * (x * z + y * w)],
            [2.0 * (x * y + z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - x * w)],
            [2.0 * (x * z - y * w), 2.0 * (y * z + x * w), 1.0 - 2.0 * (x * x + y * y)],
        ]
    }
}

/// Obstacles of every kind within `reach` of the base, sizes 2 to 20 cm, in a shuffled order.
struct Obstacles {
    spheres: Vec<SphereObstacle>,
    capsules: Vec<CapsuleObstacle>,
    cylinders: Vec<CylinderObstacle>,
    boxes: Vec<BoxObstacle>,
}

fn obstacles(stream: &mut Stream, reach: f64, each: usize) -> Obstacles {
    let mut o = Obstacles { spheres: Vec::new(), capsules: Vec::new(), cylinders: Vec::new(), boxes: Vec::new() };
    for _ in 0..each {
        let size = |s: &mut Stream| 0.02 + 0.18 * s.next();
        o.spheres.push(SphereObstacle { center: stream.point(reach), radius: size(stream) });
        let a = stream.point(reach);
        let b = [a[0] + stream.within(0.3), a[1] + stream.within(0.3), a[2] + stream.within(0.3)];
        o.capsules.push(CapsuleObstacle { a, b, radius: size(stream) });
        let a = stream.point(reach);
        let b = [a[0] + stream.within(0.3), a[1] + stream.within(0.3), a[2] + 0.05 + stream.next() * 0.3];
        o.cylinders.push(CylinderObstacle { a, b, radius: size(stream) });
        let (rotation, center) = (stream.rotation(), stream.point(reach));
        o.boxes.push(BoxObstacle::from_pose(rotation, center, [size(stream), size(stream), size(stream)]));
    }
    // Shuffled: the answer must not depend on the order.
    o.spheres.reverse();
    o.boxes.rotate_left(each / 2);
    o
}

/// `collides` and `self_collides` against the reference's signed distances (parry3d-f64 on the
/// reference's own sphere centres) on every configuration whose distance is farther than 1e-9 m
/// from zero; those within are counted, not judged. Both verdicts must occur.
fn checks<const N: usize>(
    collides: impl Fn(&[f64; N], &Environment<'_>) -> bool,
    self_collides: impl Fn(&[f64; N]) -> bool,
    reference: &kinematics::ReferenceFk,
    cover: f64,
    seed: u64,
    srdf: Option<&str>,
) -> (usize, usize) {
    let tree = reference.tree();
    let spheres = link_spheres(tree, cover, Meshes::Refuse).unwrap();
    let disabled = srdf.map(|file| {
        let text = std::fs::read_to_string(format!("{}/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
        kinematics::model::srdf::parse_srdf(&text).unwrap().disabled_pairs(tree).unwrap()
    });
    let pairs = sphere_pairs(tree, &spheres, disabled.as_ref()).pairs;
    let mut stream = Stream(seed);
    let (mut hits, mut free, mut banded, mut self_hits, mut self_free) = (0, 0, 0, 0, 0);
    for round in 0..4 {
        let o = obstacles(&mut stream, 0.8, 2 + round);
        let env = Environment::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes).unwrap();
        let reference_obstacles = ReferenceObstacles::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes);
        for q in Configurations::new(tree).skip(100 * round).take(300) {
            let q: [f64; N] = q.try_into().unwrap();
            let d = reference.obstacle_distance(&q, &spheres, &reference_obstacles).unwrap();
            assert!(!d.is_nan(), "the reference measured nothing at {q:?}");
            if d.abs() <= 1e-9 {
                banded += 1;
            } else {
                assert_eq!(collides(&q, &env), d < 0.0, "collides at {q:?}: reference distance {d:e}");
                if d < 0.0 { hits += 1 } else { free += 1 }
            }
            if round == 0 {
                let s = reference.self_distance(&q, &spheres, &pairs).unwrap();
                if s.abs() > 1e-9 {
                    assert_eq!(self_collides(&q), s < 0.0, "self_collides at {q:?}: reference distance {s:e}");
                    if s < 0.0 { self_hits += 1 } else { self_free += 1 }
                }
            }
        }
        // With no obstacle, only the robot itself can collide.
        let empty = Environment::empty();
        assert!(Configurations::new(tree).take(50).all(|q| !collides(&q.try_into().unwrap(), &empty)));
    }
    eprintln!(
        "{}: {hits} colliding, {free} free, {banded} within 1e-9 m of contact; self: {self_hits} colliding, {self_free} free",
        tree.name()
    );
    assert!(hits > 0 && free > 0, "{hits} colliding, {free} free: the environments test one verdict only");
    (self_hits, self_free)
}

/// The arms without an SRDF: pairs less adjacent bodies. Obstacles are in `BASE`'s frame, the
/// root here, as the reference's distances are.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_spherized.urdf", collision)]
pub struct Ur5Checked;

/// The spherized robots with their SRDFs: `self_collides` leaves their disabled pairs out.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda_spherized.urdf", collision(srdf = "robots/panda.srdf"))]
pub struct PandaSrdf;

/// The spherized UR5 with its SRDF.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_spherized.urdf", collision(srdf = "robots/ur5.srdf"))]
pub struct Ur5Srdf;

/// The primitives arm from its root, covered to 2 cm.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_primitives.urdf", collision(sphere_cover = 0.02))]
pub struct Ur5PrimitivesChecked;

#[test]
fn collides_and_self_collides_agree_with_the_reference() {
    let ur5 = checks(Ur5Checked::collides, Ur5Checked::self_collides, &Ur5Checked::reference().unwrap(), 0.01, 1, None);
    let panda = checks(Panda::collides, Panda::self_collides, &Panda::reference().unwrap(), 0.01, 2, None);
    // With the SRDFs' disabled pairs.
    let panda_srdf = checks(
        PandaSrdf::collides,
        PandaSrdf::self_collides,
        &PandaSrdf::reference().unwrap(),
        0.01,
        4,
        Some("robots/panda.srdf"),
    );
    let ur5_srdf = checks(
        Ur5Srdf::collides,
        Ur5Srdf::self_collides,
        &Ur5Srdf::reference().unwrap(),
        0.01,
        5,
        Some("robots/ur5.srdf"),
    );
    // Without an SRDF the primitives arm's wrist links (two joints apart, covered to 2 cm) touch
    // at every configuration: its self check is compared, but only the others show both verdicts.
    checks(
        Ur5PrimitivesChecked::collides,
        Ur5PrimitivesChecked::self_collides,
        &Ur5PrimitivesChecked::reference().unwrap(),
        0.02,
        3,
        None,
    );
    for (self_hits, self_free) in [ur5, panda, panda_srdf] {
        assert!(self_hits > 0 && self_free > 0, "{self_hits} self-colliding, {self_free} free");
    }
    // VAMP's UR5 SRDF disables wrist_2_link against wrist_3_link but not against fts_robotside,
    // which is bolted to wrist_3_link, and their spheres overlap by 1.25 cm at every
    // configuration: with that SRDF the arm always self-collides (the reference agrees).
    assert_eq!(ur5_srdf.1, 0, "{ur5_srdf:?}");
}

#[test]
fn a_configuration_that_is_not_finite_is_never_free() {
    let table =
        [BoxObstacle::from_pose([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [5.0, 5.0, 5.0], [0.1, 0.1, 0.1])];
    let ball = [SphereObstacle { center: [5.0, -5.0, 5.0], radius: 0.1 }];
    let env = Environment::new(&ball, &[], &[], &table).unwrap();
    let only_ball = Environment::new(&ball, &[], &[], &[]).unwrap();
    let q = [0.0, -1.57, 0.0, -1.57, 0.0, 0.0];
    // Free, and free of itself, as written: the faults below are the NaN's.
    assert!(!Ur5Checked::collides(&q, &env) && !Ur5Checked::self_collides(&q));
    for bad in [f64::NAN, f64::INFINITY] {
        let mut q = q;
        q[2] = bad;
        assert!(Ur5Checked::collides(&q, &env), "{q:?}");
        assert!(Ur5Checked::collides(&q, &only_ball), "{q:?}");
        assert!(Ur5Checked::self_collides(&q), "{q:?}");
    }
}

#[test]
fn a_nan_obstacle_is_refused_where_the_environment_is_built() {
    let nan = [SphereObstacle { center: [0.0, f64::NAN, 0.0], radius: 0.1 }];
    let error = Environment::new(&nan, &[], &[], &[]).unwrap_err();
    assert_eq!(error.to_string(), "sphere obstacle 0 has a number that is not finite (it would never collide)");
}
