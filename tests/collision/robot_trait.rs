//! The `Collision` trait: code written once for any robot with collision checking, run on two
//! robots of different degrees of freedom, each form's answers held to the others' through the
//! trait (the batch and the shared verdict to the configuration's own, the motions' yes/no to
//! their first collision, the centres to the inherent function's), and its slices checked.

use kinematics::collision::{Collision, Environment, Resolution};
use kinematics::{Configurations, KinematicsError};

use super::{PandaSrdf as Panda, Ur5Checked as Ur5};

/// The scene of `scenes/tabletop.toml`.
fn tabletop() -> kinematics::SceneObstacles {
    kinematics::load_scene(format!("{}/scenes/tabletop.toml", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// How many of `count` configurations drawn within the limits collide (obstacles, self), each
/// form through the trait agreeing with the configuration's own verdict.
fn survey<R: Collision<N>, const N: usize>(env: &Environment<'_>, count: usize) -> (usize, usize) {
    let qs: Vec<[f64; N]> =
        Configurations::within(R::JOINT_LIMITS).uniform().take(count).map(|q| q.try_into().unwrap()).collect();
    let (mut verdicts, mut self_verdicts) = (vec![false; qs.len()], vec![false; qs.len()]);
    R::collides_batch(&qs, env, &mut verdicts).unwrap();
    R::self_collides_batch(&qs, &mut self_verdicts).unwrap();
    for (k, q) in qs.iter().enumerate() {
        assert_eq!(verdicts[k], R::collides(q, env), "{}: configuration {k}", R::ROBOT);
        assert_eq!(self_verdicts[k], R::self_collides(q), "{}: configuration {k}", R::ROBOT);
        assert!(!self_verdicts[k] || verdicts[k], "{}: self-colliding is colliding", R::ROBOT);
    }
    for k in (0..qs.len()).step_by(5) {
        let end = qs.len().min(k + 11);
        assert_eq!(R::collides_any(&qs[k..end], env), verdicts[k..end].contains(&true));
        assert_eq!(R::self_collides_any(&qs[k..end]), self_verdicts[k..end].contains(&true));
    }
    let resolution = Resolution::StatesPerUnit(32.0);
    for m in qs.windows(2).take(40) {
        let first = R::motion_collides(&m[0], &m[1], env, resolution).unwrap();
        assert_eq!(R::motion_collides_any(&m[0], &m[1], env, resolution).unwrap(), first.is_some());
        // A motion's start is its first checked configuration.
        if R::collides(&m[0], env) {
            assert_eq!(first, Some(0.0));
        }
    }
    let hits = verdicts.iter().filter(|&&hit| hit).count();
    (hits, self_verdicts.iter().filter(|&&hit| hit).count())
}

#[test]
fn one_generic_survey_runs_on_robots_of_six_and_seven_joints() {
    let scene = tabletop();
    let env = scene.environment().unwrap();
    let (panda, panda_self) = survey::<Panda, 7>(&env, 300);
    let (ur5, ur5_self) = survey::<Ur5, 6>(&env, 300);
    // Both verdicts seen on both robots: the comparisons above test something.
    for (robot, hits, self_hits) in [("panda", panda, panda_self), ("ur5", ur5, ur5_self)] {
        assert!(hits > 0 && hits < 300, "{robot}: {hits} of 300 collide");
        assert!(self_hits > 0, "{robot}: no self-collision among 300");
    }
}

#[test]
fn the_trait_gives_the_inherent_centres_radii_and_links_and_checks_its_slices() {
    fn centres<R: Collision<N>, const N: usize>(q: &[f64; N]) -> Vec<[f64; 3]> {
        let mut out = vec![[0.0; 3]; R::SPHERE_RADII.len()];
        R::sphere_centers_into(q, &mut out).unwrap();
        assert_eq!(R::SPHERE_LINKS.len(), out.len());
        let mut short = vec![[0.0; 3]; out.len() - 1];
        let error = R::sphere_centers_into(q, &mut short).unwrap_err();
        assert!(matches!(error, KinematicsError::WrongOutputLength { .. }), "{error:?}");
        out
    }
    let q = [0.1, -0.4, 0.2, -2.0, 0.3, 1.6, 0.5];
    assert_eq!(centres::<Panda, 7>(&q), Panda::sphere_centers(&q).to_vec());
    assert_eq!(<Panda as Collision<7>>::SPHERE_RADII, &Panda::SPHERE_RADII[..]);
    assert_eq!(<Panda as Collision<7>>::SPHERE_LINKS, &Panda::SPHERE_LINKS[..]);
    let q = [0.3, -1.2, 1.0, -0.5, 0.4, 0.2];
    assert_eq!(centres::<Ur5, 6>(&q), Ur5::sphere_centers(&q).to_vec());
    let scene = tabletop();
    let env = scene.environment().unwrap();
    let (d, gradient) = <Ur5 as Collision<6>>::clearance_gradient(&q, &env);
    assert_eq!((d, gradient), Ur5::clearance_gradient(&q, &env));
    assert_eq!(<Ur5 as Collision<6>>::clearance(&q, &env), Ur5::clearance(&q, &env));
    let mut out = [false; 2];
    let error = <Ur5 as Collision<6>>::collides_batch(&[q; 3], &env, &mut out).unwrap_err();
    assert!(matches!(error, KinematicsError::WrongOutputLength { .. }), "{error:?}");
}
