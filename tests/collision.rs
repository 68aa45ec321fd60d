//! Collision checking as a user derives it (issue 30): the sphere centres `collision` emits
//! against the runtime reference's own (its link poses, the elements' origins as nalgebra
//! isometries), on spherized robots and on an arm whose geometry is primitives, the radii and
//! links as the model covers them, and the batch and lane forms equal to the scalar one.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use kinematics::model::collision::{Cover, Meshes, link_spheres};
use kinematics::{
    AGREEMENT_TOLERANCE, AGREEMENT_TOLERANCE_F32, Configurations, F32x8, F32x16, F64x4, F64x8, Kinematics, Lanes,
};

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
    cover: Option<f64>,
) {
    let tree = reference.tree();
    let spheres = link_spheres(tree, &cover_of(cover), Meshes::Read).unwrap();
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
        None,
    );
    agrees(Ur5::sphere_centers, &Ur5::SPHERE_RADII, &Ur5::SPHERE_LINKS, &Ur5::reference().unwrap(), Ur5::BASE, None);
    agrees(
        Ur5Primitives::sphere_centers,
        &Ur5Primitives::SPHERE_RADII,
        &Ur5Primitives::SPHERE_LINKS,
        &Ur5Primitives::reference().unwrap(),
        Ur5Primitives::BASE,
        Some(0.02),
    );
    assert_eq!(Panda::SPHERE_RADII.len(), 59);
    assert_eq!(Ur5::SPHERE_RADII.len(), 40);
}

/// Every form of `sphere_centers` runs one straight-line body: the batches, the column batches and
/// the generic form on each lane type give every configuration the centres of the function on one
/// configuration (`f64`, or the `f32` one for `f32` lanes), bit for bit, whichever lanes the CPU
/// takes. Then the `f32` centres against the `f64` ones.
#[test]
fn every_form_of_the_centres_is_the_one_configuration_function_bit_for_bit() {
    /// Each lane of `centers` (the generic form on a pack of `L::LANES` configurations from
    /// `first`) against `one` on that configuration, bit for bit.
    fn lanes_equal<L: Lanes, const S: usize>(
        centers: &[[L; 3]; S],
        one: impl Fn(usize) -> [[L::Scalar; 3]; S],
        first: usize,
        what: &str,
    ) where
        L::Scalar: Into<f64>,
    {
        for l in 0..L::LANES {
            let expected = one(first + l);
            for (k, (center, expected)) in centers.iter().zip(&expected).enumerate() {
                for i in 0..3 {
                    let (got, want): (f64, f64) = (center[i].lane(l).into(), expected[i].into());
                    assert_eq!(got.to_bits(), want.to_bits(), "{what}: sphere {k}, lane {l}");
                }
            }
        }
    }
    fn pack<L: Lanes, const N: usize>(qs: &[[L::Scalar; N]], first: usize) -> [L; N]
    where
        L::Scalar: Copy,
    {
        std::array::from_fn(|j| L::from_fn(|l| qs[first + l][j]))
    }

    let reference = Ur5::reference().unwrap();
    let qs: Vec<[f64; 6]> = Configurations::new(reference.tree()).take(37).map(|q| q.try_into().unwrap()).collect();
    let qs32: Vec<[f32; 6]> = qs.iter().map(|q| q.map(|x| x as f32)).collect();
    let (mut out, mut out32) = (vec![[[0.0; 3]; 40]; qs.len()], vec![[[0.0_f32; 3]; 40]; qs.len()]);
    Ur5::sphere_centers_batch(&qs, &mut out).unwrap();
    Ur5::sphere_centers_batch_f32(&qs32, &mut out32).unwrap();
    let (mut columns, mut columns32) = (vec![[[0.0; 3]; 40]; qs.len()], vec![[[0.0_f32; 3]; 40]; qs.len()]);
    let joint = |j: usize| qs.iter().map(|q| q[j]).collect::<Vec<f64>>();
    let joint32 = |j: usize| qs32.iter().map(|q| q[j]).collect::<Vec<f32>>();
    let c: [Vec<f64>; 6] = std::array::from_fn(joint);
    let c32: [Vec<f32>; 6] = std::array::from_fn(joint32);
    Ur5::sphere_centers_batch_columns([&c[0], &c[1], &c[2], &c[3], &c[4], &c[5]], &mut columns).unwrap();
    Ur5::sphere_centers_batch_columns_f32([&c32[0], &c32[1], &c32[2], &c32[3], &c32[4], &c32[5]], &mut columns32)
        .unwrap();
    for (i, (q, q32)) in qs.iter().zip(&qs32).enumerate() {
        let (one, one32) = (Ur5::sphere_centers(q), Ur5::sphere_centers_f32(q32));
        let bits = |c: &[[f64; 3]; 40]| c.map(|p| p.map(f64::to_bits));
        let bits32 = |c: &[[f32; 3]; 40]| c.map(|p| p.map(f32::to_bits));
        assert_eq!(bits(&out[i]), bits(&one), "batch, configuration {i}");
        assert_eq!(bits(&columns[i]), bits(&one), "column batch, configuration {i}");
        assert_eq!(bits32(&out32[i]), bits32(&one32), "f32 batch, configuration {i}");
        assert_eq!(bits32(&columns32[i]), bits32(&one32), "f32 column batch, configuration {i}");
        assert_eq!(bits(&Ur5::sphere_centers_generic(q)), bits(&one), "generic f64, configuration {i}");
    }
    let ur5 = |i: usize| Ur5::sphere_centers(&qs[i]);
    let ur5_32 = |i: usize| Ur5::sphere_centers_f32(&qs32[i]);
    for first in [0, 16] {
        lanes_equal(&Ur5::sphere_centers_generic(&pack::<F64x4, 6>(&qs, first)), ur5, first, "UR5, F64x4");
        lanes_equal(&Ur5::sphere_centers_generic(&pack::<F64x8, 6>(&qs, first)), ur5, first, "UR5, F64x8");
        lanes_equal(&Ur5::sphere_centers_generic(&pack::<F32x8, 6>(&qs32, first)), ur5_32, first, "UR5, F32x8");
        lanes_equal(&Ur5::sphere_centers_generic(&pack::<F32x16, 6>(&qs32, first)), ur5_32, first, "UR5, F32x16");
    }
    // The Panda (59 spheres on 11 links, the body long enough for several block marks) too.
    let panda: Vec<[f64; 7]> =
        Configurations::within(&Panda::JOINT_LIMITS).take(19).map(|q| q.try_into().unwrap()).collect();
    let panda32: Vec<[f32; 7]> = panda.iter().map(|q| q.map(|x| x as f32)).collect();
    let mut centers = vec![[[0.0; 3]; 59]; panda.len()];
    Panda::sphere_centers_batch(&panda, &mut centers).unwrap();
    for (q, batch) in panda.iter().zip(&centers) {
        assert_eq!(batch.map(|p| p.map(f64::to_bits)), Panda::sphere_centers(q).map(|p| p.map(f64::to_bits)));
    }
    let one = |i: usize| Panda::sphere_centers(&panda[i]);
    let one32 = |i: usize| Panda::sphere_centers_generic(&panda32[i]);
    lanes_equal(&Panda::sphere_centers_generic(&pack::<F64x4, 7>(&panda, 2)), one, 2, "Panda, F64x4");
    lanes_equal(&Panda::sphere_centers_generic(&pack::<F64x8, 7>(&panda, 2)), one, 2, "Panda, F64x8");
    lanes_equal(&Panda::sphere_centers_generic(&pack::<F32x8, 7>(&panda32, 2)), one32, 2, "Panda, F32x8");
    lanes_equal(&Panda::sphere_centers_generic(&pack::<F32x16, 7>(&panda32, 2)), one32, 2, "Panda, F32x16");
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

#[path = "collision/clearance.rs"]
mod clearance;
#[path = "collision/cloud.rs"]
mod cloud;
#[path = "collision/grid.rs"]
mod grid;
#[path = "collision/held.rs"]
mod held;
#[path = "collision/meshes.rs"]
mod meshes;
#[path = "collision/motion.rs"]
mod motion;
#[path = "collision/robot_trait.rs"]
mod robot_trait;

use kinematics::collision::{BoxObstacle, CapsuleObstacle, CylinderObstacle, Environment, SphereObstacle};
use kinematics::runtime::ReferenceObstacles;
use kinematics::runtime::kinematics_model::collision::sphere_pairs;

/// The derive's cover for `sphere_cover = d` (`Some(d)`), or its default (`None`).
fn cover_of(overshoot: Option<f64>) -> Cover {
    overshoot.map_or_else(Cover::default, Cover::overshoot)
}

/// The robot's spheres at a cover of `cover` (m), and the link pairs its self-collision check
/// tests: less the disabled pairs of `srdf` (a path from the repository's root), or without it,
/// less the adjacent bodies.
fn spheres_and_pairs(
    tree: &kinematics::model::KinematicTree,
    cover: Option<f64>,
    srdf: Option<&str>,
) -> (Vec<kinematics::model::collision::LinkSphere>, Vec<(kinematics::model::LinkId, kinematics::model::LinkId)>) {
    let spheres = link_spheres(tree, &cover_of(cover), Meshes::Read).unwrap();
    let disabled = srdf.map(|file| {
        let text = std::fs::read_to_string(format!("{}/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
        kinematics::model::srdf::parse_srdf(&text).unwrap().disabled_pairs(tree).unwrap()
    });
    let pairs = sphere_pairs(tree, &spheres, disabled.as_ref()).pairs;
    (spheres, pairs)
}

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

/// A derived robot's checks, every form, on one configuration or a batch of them.
trait Checks<const N: usize> {
    fn reference() -> kinematics::ReferenceFk;
    fn collides(q: &[f64; N], env: &Environment<'_>) -> bool;
    fn self_collides(q: &[f64; N]) -> bool;
    /// `collides` and `self_collides` by their batches, column batches and generic forms on
    /// `F64x4` and `F64x8`, each form's verdicts checked equal to the others'.
    fn batches(qs: &[[f64; N]], env: &Environment<'_>) -> (Vec<bool>, Vec<bool>);
}

/// The verdicts of every batch form, held equal to each other.
macro_rules! checks {
    ($robot:ty, $n:literal) => {
        impl Checks<$n> for $robot {
            fn reference() -> kinematics::ReferenceFk {
                <$robot>::reference().unwrap()
            }
            fn collides(q: &[f64; $n], env: &Environment<'_>) -> bool {
                <$robot>::collides(q, env)
            }
            fn self_collides(q: &[f64; $n]) -> bool {
                <$robot>::self_collides(q)
            }
            fn batches(qs: &[[f64; $n]], env: &Environment<'_>) -> (Vec<bool>, Vec<bool>) {
                let mut verdicts = [vec![false; qs.len()], vec![false; qs.len()]];
                <$robot>::collides_batch(qs, env, &mut verdicts[0]).unwrap();
                <$robot>::self_collides_batch(qs, &mut verdicts[1]).unwrap();
                let columns: Vec<Vec<f64>> = (0..$n).map(|j| qs.iter().map(|q| q[j]).collect()).collect();
                let columns: [&[f64]; $n] = std::array::from_fn(|j| columns[j].as_slice());
                let mut by_columns = [vec![false; qs.len()], vec![false; qs.len()]];
                <$robot>::collides_batch_columns(columns, env, &mut by_columns[0]).unwrap();
                <$robot>::self_collides_batch_columns(columns, &mut by_columns[1]).unwrap();
                assert_eq!(by_columns, verdicts, "column batches");
                // The generic form on both lane widths, a pack at a time (the tail repeats the last).
                fn packs<L: kinematics::Lanes<Scalar = f64> + kinematics::collision::CheckLanes, const N: usize>(
                    qs: &[[f64; N]],
                    check: impl Fn(&[L; N]) -> kinematics::collision::LaneMask,
                ) -> Vec<bool> {
                    let mut out = Vec::new();
                    for start in (0..qs.len()).step_by(L::LANES) {
                        let lanes: [L; N] =
                            std::array::from_fn(|j| L::from_fn(|i| qs[(start + i).min(qs.len() - 1)][j]));
                        let mask = check(&lanes);
                        out.extend((0..L::LANES).map(|i| mask.lane(i)).take(qs.len() - start));
                    }
                    out
                }
                let four = [
                    packs::<F64x4, $n>(qs, |q| <$robot>::collides_generic(q, env)),
                    packs::<F64x4, $n>(qs, |q| <$robot>::self_collides_generic(q)),
                ];
                let eight = [
                    packs::<kinematics::F64x8, $n>(qs, |q| <$robot>::collides_generic(q, env)),
                    packs::<kinematics::F64x8, $n>(qs, |q| <$robot>::self_collides_generic(q)),
                ];
                assert_eq!(four, verdicts, "four lanes");
                assert_eq!(eight, verdicts, "eight lanes");
                // The shared verdicts: on windows of every length up to 40 (so packs end at
                // every lane and hits sit anywhere in a pack), each the `any` of the window's own.
                for start in (0..qs.len()).step_by(13) {
                    for end in start..=qs.len().min(start + 40) {
                        let window = &qs[start..end];
                        let any = |v: &[bool]| v[start..end].iter().any(|&x| x);
                        assert_eq!(
                            <$robot>::collides_any(window, env),
                            any(&verdicts[0]),
                            "collides_any {start}..{end}"
                        );
                        assert_eq!(<$robot>::self_collides_any(window), any(&verdicts[1]), "self_collides_any");
                    }
                }
                fn any_packs<L: kinematics::Lanes<Scalar = f64>, const N: usize>(
                    qs: &[[f64; N]],
                    check: impl Fn(&[L; N]) -> bool,
                ) -> Vec<bool> {
                    (0..qs.len())
                        .step_by(L::LANES)
                        .map(|start| {
                            check(&std::array::from_fn(|j| L::from_fn(|i| qs[(start + i).min(qs.len() - 1)][j])))
                        })
                        .collect()
                }
                let packed =
                    |v: &[bool], width: usize| v.chunks(width).map(|c| c.iter().any(|&x| x)).collect::<Vec<_>>();
                assert_eq!(
                    any_packs::<F64x4, $n>(qs, |q| <$robot>::collides_any_generic(q, env)),
                    packed(&verdicts[0], 4)
                );
                assert_eq!(
                    any_packs::<F64x4, $n>(qs, |q| <$robot>::self_collides_any_generic(q)),
                    packed(&verdicts[1], 4)
                );
                assert_eq!(
                    any_packs::<kinematics::F64x8, $n>(qs, |q| <$robot>::collides_any_generic(q, env)),
                    packed(&verdicts[0], 8)
                );
                let [collides, itself] = verdicts;
                (collides, itself)
            }
        }
    };
}

/// What `checks` saw: configurations judged colliding and free, and within 1e-9 m of contact,
/// for `collides` and for `self_collides`.
#[derive(Debug, Default)]
struct Seen {
    hits: usize,
    free: usize,
    banded: usize,
    self_hits: usize,
    self_free: usize,
}

/// `collides` (obstacles and self) and `self_collides` against the reference's signed distances
/// (parry3d-f64 on the reference's own sphere centres) on every configuration whose verdict the
/// distances decide by more than 1e-9 m; those within are counted, not judged. The batches and
/// the lanes equal the functions on one configuration.
fn checks<R: Checks<N>, const N: usize>(cover: Option<f64>, seed: u64, srdf: Option<&str>) -> Seen {
    let reference = R::reference();
    let tree = reference.tree();
    let (spheres, pairs) = spheres_and_pairs(tree, cover, srdf);
    let mut stream = Stream(seed);
    let mut seen = Seen::default();
    for round in 0..4 {
        let o = obstacles(&mut stream, 0.8, 2 + round);
        let env = Environment::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes).unwrap();
        let reference_obstacles = ReferenceObstacles::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes);
        let qs: Vec<[f64; N]> =
            Configurations::new(tree).skip(100 * round).take(301).map(|q| q.try_into().unwrap()).collect();
        let (collides, itself) = R::batches(&qs, &env);
        // The obstacles in the opposite order, every list reversed: the same verdicts.
        let (s, c, y, b) = (&o.spheres, &o.capsules, &o.cylinders, &o.boxes);
        let (s, c, y, b): (Vec<_>, Vec<_>, Vec<_>, Vec<_>) = (
            s.iter().rev().copied().collect(),
            c.iter().rev().copied().collect(),
            y.iter().rev().copied().collect(),
            b.iter().rev().copied().collect(),
        );
        let reversed = Environment::new(&s, &c, &y, &b).unwrap();
        assert_eq!(R::batches(&qs, &reversed).0, collides, "the obstacles in the opposite order");
        for (k, q) in qs.iter().enumerate() {
            assert_eq!((collides[k], itself[k]), (R::collides(q, &env), R::self_collides(q)), "batch at {q:?}");
            let d = reference.obstacle_distance(q, &spheres, &reference_obstacles).unwrap();
            let s = reference.self_distance(q, &spheres, &pairs).unwrap();
            assert!(!d.is_nan() && !s.is_nan(), "the reference measured nothing at {q:?}");
            if s.abs() > 1e-9 {
                assert_eq!(itself[k], s < 0.0, "self_collides at {q:?}: reference distance {s:e}");
                if s < 0.0 { seen.self_hits += 1 } else { seen.self_free += 1 }
            }
            let nearest = d.min(s);
            if d < -1e-9 || s < -1e-9 || nearest > 1e-9 {
                assert_eq!(collides[k], nearest < 0.0, "collides at {q:?}: distances {d:e}, self {s:e}");
                if nearest < 0.0 { seen.hits += 1 } else { seen.free += 1 }
            } else {
                seen.banded += 1;
            }
        }
        // With no obstacle, only the robot itself can collide.
        let empty = Environment::empty();
        for q in qs.iter().take(50) {
            assert_eq!(R::collides(q, &empty), R::self_collides(q), "{q:?}");
        }
    }
    eprintln!("{}: {seen:?}", tree.name());
    seen
}

checks!(Ur5Checked, 6);
checks!(Panda, 7);
checks!(PandaSrdf, 7);
checks!(Ur5Srdf, 6);
checks!(Ur5PrimitivesChecked, 6);

/// The arms without an SRDF: pairs less adjacent bodies. Obstacles are in `BASE`'s frame, the
/// root here, as the reference's distances are.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_spherized.urdf", collision)]
pub struct Ur5Checked;

/// The spherized robots with their SRDFs: `self_collides` leaves their disabled pairs out.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda_spherized.urdf", collision(srdf = "robots/panda.srdf"), scalars(f64, f32))]
pub struct PandaSrdf;

/// The spherized UR5 with its SRDF.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_spherized.urdf", collision(srdf = "robots/ur5.srdf"))]
pub struct Ur5Srdf;

/// The primitives arm from its root, covered to 2 cm.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_primitives.urdf", collision(sphere_cover = 0.02))]
pub struct Ur5PrimitivesChecked;

// One test per robot, so that the harness runs them side by side.

/// Both verdicts of both checks are seen, obstacles and the robot itself.
fn both_verdicts(seen: &Seen) {
    assert!(seen.hits > 0 && seen.free > 0, "{seen:?}: the environments test one verdict only");
    assert!(seen.self_hits > 0 && seen.self_free > 0, "{seen:?}: the configurations test one verdict only");
}

#[test]
fn collides_and_self_collides_agree_with_the_reference_ur5() {
    both_verdicts(&checks::<Ur5Checked, 6>(None, 1, None));
}

#[test]
fn collides_and_self_collides_agree_with_the_reference_panda() {
    both_verdicts(&checks::<Panda, 7>(None, 2, None));
}

/// With the SRDF's disabled pairs.
#[test]
fn collides_and_self_collides_agree_with_the_reference_panda_srdf() {
    both_verdicts(&checks::<PandaSrdf, 7>(None, 4, Some("robots/panda.srdf")));
}

/// VAMP's UR5 SRDF disables wrist_2_link against wrist_3_link but not against fts_robotside,
/// which is bolted to wrist_3_link, and their spheres overlap by 1.25 cm at every configuration:
/// with that SRDF the arm always self-collides (the reference agrees).
#[test]
fn collides_and_self_collides_agree_with_the_reference_ur5_srdf() {
    let seen = checks::<Ur5Srdf, 6>(None, 5, Some("robots/ur5.srdf"));
    assert!(seen.self_free == 0 && seen.free == 0 && seen.hits > 0, "{seen:?}");
}

/// Without an SRDF the primitives arm's wrist links (two joints apart, covered to 2 cm) touch at
/// every configuration: its checks are compared, but only the others show both verdicts.
#[test]
fn collides_and_self_collides_agree_with_the_reference_primitives() {
    let seen = checks::<Ur5PrimitivesChecked, 6>(Some(0.02), 3, None);
    assert!(seen.self_free == 0 && seen.free == 0 && seen.hits > 0, "{seen:?}");
}

/// `f32` checks against the reference with a band of 1e-4 m, and their batches and lanes equal
/// to the `f32` function on one configuration.
#[test]
fn f32_checks_agree_with_the_reference() {
    let reference = Ur5::reference().unwrap();
    let tree = reference.tree();
    let spheres = link_spheres(tree, &Cover::default(), Meshes::Read).unwrap();
    let pairs = sphere_pairs(tree, &spheres, None).pairs;
    let mut stream = Stream(11);
    let (mut judged, mut banded) = (0, 0);
    for round in 0..3 {
        let o = obstacles(&mut stream, 0.8, 2 + round);
        let env = Environment::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes).unwrap();
        let reference_obstacles = ReferenceObstacles::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes);
        let qs: Vec<[f32; 6]> = Configurations::new(tree)
            .skip(50 * round)
            .take(203)
            .map(|q| std::array::from_fn(|j| q[j] as f32))
            .collect();
        let mut verdicts = [vec![false; qs.len()], vec![false; qs.len()]];
        Ur5::collides_batch_f32(&qs, &env, &mut verdicts[0]).unwrap();
        Ur5::self_collides_batch_f32(&qs, &mut verdicts[1]).unwrap();
        for (k, q) in qs.iter().enumerate() {
            assert_eq!(verdicts[0][k], Ur5::collides_f32(q, &env), "batch at {q:?}");
            assert_eq!(verdicts[1][k], Ur5::self_collides_f32(q), "batch at {q:?}");
            let lanes: [kinematics::F32x16; 6] = std::array::from_fn(|j| kinematics::F32x16::splat(q[j]));
            assert_eq!(Ur5::collides_generic(&lanes, &env).bits(), if verdicts[0][k] { 0xffff } else { 0 });
            let q64 = q.map(f64::from);
            let d = reference.obstacle_distance(&q64, &spheres, &reference_obstacles).unwrap();
            let s = reference.self_distance(&q64, &spheres, &pairs).unwrap();
            if s.abs() > 1e-4 {
                assert_eq!(verdicts[1][k], s < 0.0, "self_collides_f32 at {q:?}: reference distance {s:e}");
            }
            let nearest = d.min(s);
            if d < -1e-4 || s < -1e-4 || nearest > 1e-4 {
                assert_eq!(verdicts[0][k], nearest < 0.0, "collides_f32 at {q:?}: distances {d:e}, self {s:e}");
                judged += 1;
            } else {
                banded += 1;
            }
        }
    }
    eprintln!("f32: {judged} judged, {banded} within 1e-4 m of contact");
    assert!(judged > 500, "{judged} judged");
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
        assert!(Ur5::collides_f32(&q.map(|x| x as f32), &env) && Ur5::self_collides_f32(&q.map(|x| x as f32)));
        // In a batch, only its own lane: the others are free.
        let mut qs = vec![[0.0, -1.57, 0.0, -1.57, 0.0, 0.0]; 11];
        qs[6] = q;
        let mut out = vec![false; 11];
        Ur5Checked::collides_batch(&qs, &env, &mut out).unwrap();
        assert_eq!(out.iter().positions(), vec![6]);
        Ur5Checked::self_collides_batch(&qs, &mut out).unwrap();
        assert_eq!(out.iter().positions(), vec![6]);
    }
}

/// The indices of the `true` entries.
trait Positions {
    fn positions(self) -> Vec<usize>;
}

impl<'a, I: Iterator<Item = &'a bool>> Positions for I {
    fn positions(self) -> Vec<usize> {
        self.enumerate().filter(|(_, b)| **b).map(|(i, _)| i).collect()
    }
}

#[test]
fn a_nan_obstacle_is_refused_where_the_environment_is_built() {
    let nan = [SphereObstacle { center: [0.0, f64::NAN, 0.0], radius: 0.1 }];
    let error = Environment::new(&nan, &[], &[], &[]).unwrap_err();
    assert_eq!(error.to_string(), "sphere obstacle 0 has a number that is not finite (it would never collide)");
}
