//! `motion_collides`: a straight motion in joint space checked at a resolution, in lanes, against
//! the runtime reference checking the same configurations one by one, worked out here on their
//! own (the number of steps, `(1 - t) q0 + t q1`). A module of the collision tests, on their
//! robots (one test binary: each derive and link costs CI time).

use kinematics::collision::{Environment, Resolution, SphereObstacle};
use kinematics::runtime::ReferenceObstacles;
use kinematics::{Configurations, KinematicsError};

use super::{PandaSrdf as Panda, Ur5Checked as Ur5};

/// The steps a motion is checked in: the fewest keeping every joint's move within `resolution`.
fn steps<const N: usize>(q0: &[f64; N], q1: &[f64; N], resolution: f64) -> usize {
    let largest = q0.iter().zip(q1).map(|(a, b)| (b - a).abs()).fold(0.0, f64::max);
    ((largest / resolution).ceil() as usize).max(1)
}

fn at<const N: usize>(q0: &[f64; N], q1: &[f64; N], t: f64) -> [f64; N] {
    std::array::from_fn(|j| (1.0 - t) * q0[j] + t * q1[j])
}

/// The scene of `scenes/tabletop.toml`.
fn tabletop() -> kinematics::SceneObstacles {
    kinematics::load_scene(format!("{}/scenes/tabletop.toml", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// What the reference says of motion `q0 -> q1`: the index of its first colliding configuration
/// (`Some`) or none, or `Err` when a configuration before the answer lies within 1e-9 m of contact
/// (the reference and the compiled check may then differ by rounding).
fn reference_first<const N: usize>(
    reference: &kinematics::ReferenceFk,
    srdf: Option<&str>,
    obstacles: &ReferenceObstacles,
    q0: &[f64; N],
    q1: &[f64; N],
    resolution: f64,
) -> Result<Option<usize>, ()> {
    let tree = reference.tree();
    let (spheres, pairs) = super::spheres_and_pairs(tree, None, srdf);
    let n = steps(q0, q1, resolution);
    for k in 0..=n {
        let q = at(q0, q1, k as f64 / n as f64);
        let d = reference.obstacle_distance(&q, &spheres, obstacles).unwrap();
        let s = reference.self_distance(&q, &spheres, &pairs).unwrap();
        assert!(!d.is_nan() && !s.is_nan(), "the reference measured nothing at {q:?}");
        let nearest = d.min(s);
        if nearest.abs() <= 1e-9 {
            return Err(());
        }
        if nearest < 0.0 {
            return Ok(Some(k));
        }
    }
    Ok(None)
}

#[test]
fn motions_agree_with_the_reference_one_configuration_at_a_time() {
    let scene = tabletop();
    let env = scene.environment().unwrap();
    let obstacles = scene.reference();
    for (resolution, pairs) in [(0.05, 40), (0.2, 60)] {
        let (mut colliding, mut free, mut banded) = (0, 0, 0);
        let qs: Vec<[f64; 7]> =
            Configurations::within(&Panda::JOINT_LIMITS).take(2 * pairs).map(|q| q.try_into().unwrap()).collect();
        let panda = Panda::reference().unwrap();
        for pair in qs.chunks(2) {
            let (q0, q1) = (&pair[0], &pair[1]);
            let found = Panda::motion_collides(q0, q1, &env, resolution).unwrap();
            assert_eq!(Panda::motion_collides_any(q0, q1, &env, resolution).unwrap(), found.is_some(), "yes/no");
            let n = steps(q0, q1, resolution);
            // The same configurations through the compiled one-configuration check, in order.
            let one_by_one = (0..=n).find(|&k| Panda::collides(&at(q0, q1, k as f64 / n as f64), &env));
            assert_eq!(found, one_by_one.map(|k| k as f64 / n as f64), "{q0:?} -> {q1:?} at {resolution}");
            match reference_first(&panda, Some("robots/panda.srdf"), &obstacles, q0, q1, resolution) {
                Ok(first) => {
                    assert_eq!(found, first.map(|k| k as f64 / n as f64), "{q0:?} -> {q1:?}: the reference");
                    if first.is_some() { colliding += 1 } else { free += 1 }
                }
                Err(()) => banded += 1,
            }
        }
        eprintln!("Panda at {resolution}: {colliding} colliding, {free} free, {banded} within 1e-9 m of contact");
        assert!(colliding > 5 && free > 5, "both answers occur: {colliding} colliding, {free} free");
    }
    // The UR5 (no SRDF) on one width of motion, and motions short enough for one pack.
    let ur5 = Ur5::reference().unwrap();
    let qs: Vec<[f64; 6]> = Configurations::new(ur5.tree()).take(60).map(|q| q.try_into().unwrap()).collect();
    for pair in qs.chunks(2) {
        for resolution in [0.1, 1.5] {
            let (q0, q1) = (&pair[0], &pair[1]);
            let n = steps(q0, q1, resolution);
            let one_by_one = (0..=n).find(|&k| Ur5::collides(&at(q0, q1, k as f64 / n as f64), &env));
            let found = Ur5::motion_collides(q0, q1, &env, resolution).unwrap();
            assert_eq!(found, one_by_one.map(|k| k as f64 / n as f64), "UR5 {q0:?} -> {q1:?} at {resolution}");
            assert_eq!(Ur5::motion_collides_any(q0, q1, &env, resolution).unwrap(), found.is_some(), "UR5 yes/no");
        }
    }
}

#[test]
fn f32_motions_equal_their_configurations_checked_one_by_one() {
    let scene = tabletop();
    let env = scene.environment().unwrap();
    let qs: Vec<[f32; 7]> = Configurations::within(&Panda::JOINT_LIMITS)
        .skip(7)
        .take(60)
        .map(|q| std::array::from_fn(|j| q[j] as f32))
        .collect();
    let mut colliding = 0;
    for pair in qs.chunks(2) {
        let (q0, q1) = (&pair[0], &pair[1]);
        let wide = (q0.map(f64::from), q1.map(f64::from));
        let n = steps(&wide.0, &wide.1, 0.1);
        // The motion's configurations as `f32` computes them: the fraction rounded to `f32` first.
        let q = |k: usize| -> [f32; 7] {
            let t = (k as f64 / n as f64) as f32;
            std::array::from_fn(|j| (1.0 - t) * q0[j] + t * q1[j])
        };
        let one_by_one = (0..=n).find(|&k| Panda::collides_f32(&q(k), &env));
        let found = Panda::motion_collides_f32(q0, q1, &env, 0.1).unwrap();
        assert_eq!(found, one_by_one.map(|k| k as f64 / n as f64), "{q0:?} -> {q1:?}");
        assert_eq!(Panda::motion_collides_any_f32(q0, q1, &env, 0.1).unwrap(), found.is_some(), "f32 yes/no");
        colliding += usize::from(found.is_some());
    }
    assert!(colliding > 3 && colliding < 27, "{colliding} of 30 motions collide");
}

/// An obstacle met only between two checked configurations: the motion turns the outstretched
/// Panda about its first joint (1 rad), and a 1 mm ball sits at the centre of its sphere farthest
/// from that axis a quarter of the way along. At a resolution of 0.6 rad the motion is checked at
/// its ends and middle only, 0.25 rad of turn (over 10 cm there) from the ball: it is reported
/// free, as that resolution implies; at 0.05 rad the quarter is a checked configuration and the
/// motion collides there or before.
#[test]
fn a_collision_between_checked_configurations_is_found_as_the_resolution_implies() {
    let q0 = [0.0, 0.3, 0.0, -1.2, 0.0, 1.5, 0.8];
    let mut q1 = q0;
    q1[0] = 1.0;
    let quarter = at(&q0, &q1, 0.25);
    // The sphere farthest from the turning axis, which moves most.
    let centers = Panda::sphere_centers(&quarter);
    let far = (0..centers.len()).max_by(|&a, &b| radial(centers[a]).total_cmp(&radial(centers[b]))).unwrap();
    let ball = [SphereObstacle { center: centers[far], radius: 0.001 }];
    let env = Environment::new(&ball, &[], &[], &[]).unwrap();
    // The premises: the checked configurations of the coarse motion are free, the quarter is not.
    for t in [0.0, 0.5, 1.0] {
        assert!(!Panda::collides(&at(&q0, &q1, t), &env), "at {t}");
    }
    assert!(Panda::collides(&quarter, &env));
    assert_eq!(Panda::motion_collides(&q0, &q1, &env, 0.6).unwrap(), None);
    let fine = Panda::motion_collides(&q0, &q1, &env, 0.05).unwrap().expect("the quarter is checked at 0.05");
    assert!(fine <= 0.25 && fine > 0.0, "{fine}");
}

fn radial(p: [f64; 3]) -> f64 {
    p[0].hypot(p[1])
}

#[test]
fn a_resolution_that_is_not_positive_and_finite_is_refused() {
    let env = Environment::empty();
    let q = [0.0, -0.5, 0.0, -2.0, 0.0, 1.5, 0.8];
    for resolution in [0.0, -0.1, f64::NAN, f64::INFINITY] {
        let error = Panda::motion_collides(&q, &q, &env, resolution).unwrap_err();
        assert!(matches!(error, KinematicsError::BadResolution { robot: "panda", .. }), "{error:?}");
        assert!(error.to_string().contains("must be positive and finite"), "{error}");
        for error in [
            Panda::motion_collides_any(&q, &q, &env, resolution).unwrap_err(),
            Panda::motion_collides(&q, &q, &env, Resolution::StatesPerUnit(resolution)).unwrap_err(),
            Panda::motion_collides_any_batch(&[(q, q)], &env, resolution, &mut [false]).unwrap_err(),
        ] {
            assert!(matches!(error, KinematicsError::BadResolution { robot: "panda", .. }), "{error:?}");
        }
    }
}

#[test]
fn a_motion_through_a_configuration_that_is_not_finite_is_never_free() {
    let env = Environment::empty();
    let q = [0.0, -0.5, 0.0, -2.0, 0.0, 1.5, 0.8];
    let mut bad = q;
    bad[3] = f64::NAN;
    assert_eq!(Panda::motion_collides(&q, &q, &env, 0.1).unwrap(), None, "a motion that stays put, free");
    assert_eq!(Panda::motion_collides(&bad, &q, &env, 0.1).unwrap(), Some(0.0));
    assert_eq!(Panda::motion_collides(&q, &bad, &env, 0.1).unwrap(), Some(1.0));
    assert!(!Panda::motion_collides_any(&q, &q, &env, 0.1).unwrap());
    assert!(Panda::motion_collides_any(&bad, &q, &env, 0.1).unwrap());
    assert!(Panda::motion_collides_any(&q, &bad, &env, 0.1).unwrap());
    bad[3] = f64::INFINITY;
    assert_eq!(Panda::motion_collides(&q, &bad, &env, 0.1).unwrap(), Some(1.0));
    assert!(Panda::motion_collides_any(&q, &bad, &env, 0.1).unwrap());
}

/// The batch of several motions equals `motion_collides` on each, for motions of very different
/// lengths (so lanes take new motions at different times), colliding and free, `f64` and `f32`,
/// with a motion through a configuration that is not finite among them; its errors write nothing.
#[test]
fn a_batch_of_motions_equals_each_motion_alone() {
    let scene = tabletop();
    let env = scene.environment().unwrap();
    let qs: Vec<[f64; 7]> =
        Configurations::within(&Panda::JOINT_LIMITS).skip(3).take(90).map(|q| q.try_into().unwrap()).collect();
    // Full motions, and motions a tenth or a hundredth as long (a planner's short extensions).
    let mut motions: Vec<([f64; 7], [f64; 7])> = Vec::new();
    for (k, pair) in qs.chunks(2).enumerate() {
        let scale = [1.0, 0.1, 0.01][k % 3];
        let q1 = std::array::from_fn(|j| pair[0][j] + scale * (pair[1][j] - pair[0][j]));
        motions.push((pair[0], q1));
    }
    let mut bad = motions[4].0;
    bad[2] = f64::NAN;
    motions.insert(5, (motions[5].0, bad));
    for resolution in [0.05, 0.3] {
        let mut out = vec![Some(-1.0); motions.len()];
        Panda::motion_collides_batch(&motions, &env, resolution, &mut out).unwrap();
        let alone: Vec<Option<f64>> =
            motions.iter().map(|(q0, q1)| Panda::motion_collides(q0, q1, &env, resolution).unwrap()).collect();
        assert_eq!(out, alone, "at {resolution}");
        let colliding = out.iter().filter(|t| t.is_some()).count();
        assert!(colliding > 3 && colliding + 3 < out.len(), "{colliding} of {} collide", out.len());
        assert_eq!(out[5], Some(1.0), "the motion to a configuration that is not finite");
        // f32: the same against the f32 motion one at a time.
        let motions32: Vec<([f32; 7], [f32; 7])> =
            motions.iter().map(|(a, b)| (a.map(|x| x as f32), b.map(|x| x as f32))).collect();
        let mut out32 = vec![None; motions32.len()];
        Panda::motion_collides_batch_f32(&motions32, &env, resolution, &mut out32).unwrap();
        let alone32: Vec<Option<f64>> =
            motions32.iter().map(|(q0, q1)| Panda::motion_collides_f32(q0, q1, &env, resolution).unwrap()).collect();
        assert_eq!(out32, alone32, "f32 at {resolution}");
    }
    // An empty batch, a batch of one.
    Panda::motion_collides_batch(&[], &env, 0.1, &mut []).unwrap();
    let mut one = [None];
    Panda::motion_collides_batch(&motions[..1], &env, 0.1, &mut one).unwrap();
    assert_eq!(one[0], Panda::motion_collides(&motions[0].0, &motions[0].1, &env, 0.1).unwrap());
    // Errors, nothing written.
    let mut out = vec![Some(-1.0); 2];
    let error = Panda::motion_collides_batch(&motions[..2], &env, 0.0, &mut out).unwrap_err();
    assert!(matches!(error, KinematicsError::BadResolution { robot: "panda", .. }), "{error:?}");
    let error = Panda::motion_collides_batch(&motions[..3], &env, 0.1, &mut out).unwrap_err();
    assert!(matches!(error, KinematicsError::WrongOutputLength { expected: 3, got: 2, .. }), "{error:?}");
    assert_eq!(out, vec![Some(-1.0); 2]);
}

/// States per unit of joint-space distance, as VAMP and OMPL count them: the configurations
/// checked are `ceil(|q1 - q0| * states)` steps apart (worked out here), the first collision
/// found where checking them one by one finds it, and the yes/no form and its batch agree, in
/// the tabletop scene and in the shelf scene, `f64` and `f32`.
#[test]
fn states_per_unit_distance_check_the_configurations_they_count() {
    for name in ["tabletop", "shelf"] {
        let scene = kinematics::load_scene(format!("{}/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"))).unwrap();
        let env = scene.environment().unwrap();
        let qs: Vec<[f64; 7]> =
            Configurations::within(&Panda::JOINT_LIMITS).skip(11).take(80).map(|q| q.try_into().unwrap()).collect();
        let motions: Vec<([f64; 7], [f64; 7])> = qs.chunks(2).map(|p| (p[0], p[1])).collect();
        let mut colliding = 0;
        for states in [32.0, 4.0] {
            let mut any = vec![false; motions.len()];
            Panda::motion_collides_any_batch(&motions, &env, Resolution::StatesPerUnit(states), &mut any).unwrap();
            let q32 = |q: &[f64; 7]| q.map(|x| x as f32);
            let mut any32 = vec![false; motions.len()];
            let motions32: Vec<_> = motions.iter().map(|(a, b)| (q32(a), q32(b))).collect();
            Panda::motion_collides_any_batch_f32(&motions32, &env, Resolution::StatesPerUnit(states), &mut any32)
                .unwrap();
            for (m, (q0, q1)) in motions.iter().enumerate() {
                let distance = q0.iter().zip(q1).map(|(a, b)| (b - a) * (b - a)).sum::<f64>().sqrt();
                let n = ((distance * states).ceil() as usize).max(1);
                let one_by_one = (0..=n).find(|&k| Panda::collides(&at(q0, q1, k as f64 / n as f64), &env));
                let found = Panda::motion_collides(q0, q1, &env, Resolution::StatesPerUnit(states)).unwrap();
                assert_eq!(found, one_by_one.map(|k| k as f64 / n as f64), "{name}: {q0:?} -> {q1:?} at {states}");
                let yes = Panda::motion_collides_any(q0, q1, &env, Resolution::StatesPerUnit(states)).unwrap();
                assert_eq!((yes, any[m]), (found.is_some(), found.is_some()), "{name}: motion {m}");
                let yes32 = Panda::motion_collides_any_f32(&q32(q0), &q32(q1), &env, Resolution::StatesPerUnit(states));
                assert_eq!(yes32.unwrap(), any32[m], "{name}: motion {m}, f32 batch");
                colliding += usize::from(yes);
            }
        }
        assert!(colliding > 5 && colliding < 75, "{name}: {colliding} of 80 motions collide");
    }
}
