//! `clearance` and `proximity_cost` against the reference's signed distances (parry3d-f64 on the
//! reference's own sphere centres), every obstacle kind and the self pairs; their gradients
//! against central differences of the functions themselves; the lanes against one configuration
//! at a time; a point cloud against every point asked in turn.

use kinematics::collision::{Environment, PointCloud};
use kinematics::runtime::ReferenceObstacles;
use kinematics::runtime::kinematics_model::collision::fixed_apart_pairs;
use kinematics::{Configurations, F64x4, F64x8, Lanes, ReferenceFk};

use super::{Obstacles, Panda, PandaSrdf, Stream, Ur5Checked, Ur5PrimitivesChecked, obstacles, spheres_and_pairs};

/// A derived robot's distances, every form.
trait Distances<const N: usize> {
    fn reference() -> ReferenceFk;
    fn clearance(q: &[f64; N], env: &Environment<'_>) -> f64;
    fn clearance_gradient(q: &[f64; N], env: &Environment<'_>) -> (f64, [f64; N]);
    fn cost(q: &[f64; N], env: &Environment<'_>, margin: f64) -> f64;
    fn cost_gradient(q: &[f64; N], env: &Environment<'_>, margin: f64) -> (f64, [f64; N]);
    /// Every lane form (4 and 8 lanes) of the four on `qs` (a pack each), as values per
    /// configuration: clearance, its gradient, cost, its gradient.
    fn lanes(qs: &[[f64; N]], env: &Environment<'_>, margin: f64) -> Vec<(f64, [f64; N], f64, [f64; N])>;
}

macro_rules! distances {
    ($robot:ty, $n:literal) => {
        impl Distances<$n> for $robot {
            fn reference() -> ReferenceFk {
                <$robot>::reference().unwrap()
            }
            fn clearance(q: &[f64; $n], env: &Environment<'_>) -> f64 {
                <$robot>::clearance(q, env)
            }
            fn clearance_gradient(q: &[f64; $n], env: &Environment<'_>) -> (f64, [f64; $n]) {
                <$robot>::clearance_gradient(q, env)
            }
            fn cost(q: &[f64; $n], env: &Environment<'_>, margin: f64) -> f64 {
                <$robot>::proximity_cost(q, env, margin).unwrap()
            }
            fn cost_gradient(q: &[f64; $n], env: &Environment<'_>, margin: f64) -> (f64, [f64; $n]) {
                <$robot>::proximity_cost_gradient(q, env, margin).unwrap()
            }
            fn lanes(qs: &[[f64; $n]], env: &Environment<'_>, margin: f64) -> Vec<(f64, [f64; $n], f64, [f64; $n])> {
                fn packs<L: Lanes<Scalar = f64> + kinematics::collision::CheckLanes + kinematics::Real>(
                    qs: &[[f64; $n]],
                    env: &Environment<'_>,
                    margin: f64,
                ) -> Vec<(f64, [f64; $n], f64, [f64; $n])> {
                    let mut out = Vec::new();
                    for start in (0..qs.len()).step_by(L::LANES) {
                        let q: [L; $n] = std::array::from_fn(|j| L::from_fn(|i| qs[(start + i).min(qs.len() - 1)][j]));
                        let c = <$robot>::clearance_generic(&q, env);
                        let (c2, g) = <$robot>::clearance_gradient_generic(&q, env);
                        let cost = <$robot>::proximity_cost_generic(&q, env, margin).unwrap();
                        let (cost2, h) = <$robot>::proximity_cost_gradient_generic(&q, env, margin).unwrap();
                        for i in 0..L::LANES.min(qs.len() - start) {
                            // With a gradient the poses come from the Jacobians' body: the
                            // same values to the last bits.
                            assert!((c.lane(i) - c2.lane(i)).abs() <= 1e-14, "clearance with its gradient");
                            assert!((cost.lane(i) - cost2.lane(i)).abs() <= 1e-14, "cost with its gradient");
                            out.push((c.lane(i), g.map(|x| x.lane(i)), cost.lane(i), h.map(|x| x.lane(i))));
                        }
                    }
                    out
                }
                let four = packs::<F64x4>(qs, env, margin);
                let eight = packs::<F64x8>(qs, env, margin);
                assert_eq!(bits(&four), bits(&eight), "four and eight lanes");
                four
            }
        }
    };
}

distances!(Panda, 7);
distances!(PandaSrdf, 7);
distances!(Ur5Checked, 6);
distances!(Ur5PrimitivesChecked, 6);

/// The bits of every number, to compare lanes exactly.
fn bits<const N: usize>(values: &[(f64, [f64; N], f64, [f64; N])]) -> Vec<u64> {
    values
        .iter()
        .flat_map(|(c, g, cost, h)| {
            std::iter::once(*c).chain(g.iter().copied()).chain([*cost]).chain(h.iter().copied()).map(f64::to_bits)
        })
        .collect()
}

/// The reference's proximity cost: every sphere-obstacle pair and every sphere pair of the
/// checked link pairs within `margin`.
fn reference_cost(distances: &[f64], margin: f64) -> f64 {
    distances.iter().map(|d| (margin - d).max(0.0).powi(2)).sum()
}

const MARGIN: f64 = 0.05;

/// The clearance and the cost against the reference's distances on random configurations among
/// obstacles of every kind, within 1e-12 m (and 1e-12 of the cost per pair within the margin);
/// the gradients' values equal the functions' to 1e-14 (their poses come from the Jacobians'
/// body); every lane equal to the function on its
/// configuration, bit for bit.
fn agrees<R: Distances<N>, const N: usize>(cover: Option<f64>, seed: u64, srdf: Option<&str>) -> (usize, usize) {
    let reference = R::reference();
    let tree = reference.tree();
    let (spheres, pairs) = spheres_and_pairs(tree, cover, srdf);
    let fixed = fixed_apart_pairs(tree, &spheres, &pairs);
    let mut stream = Stream(seed);
    let (mut overlapping, mut apart) = (0, 0);
    for round in 0..3 {
        let Obstacles { spheres: balls, capsules, cylinders, boxes } = obstacles(&mut stream, 0.8, 2 + round);
        let env = Environment::new(&balls, &capsules, &cylinders, &boxes).unwrap();
        let shapes = ReferenceObstacles::new(&balls, &capsules, &cylinders, &boxes);
        let qs: Vec<[f64; N]> =
            Configurations::new(tree).skip(60 * round).take(61).map(|q| q.try_into().unwrap()).collect();
        let lanes = R::lanes(&qs, &env, MARGIN);
        for (q, lane) in qs.iter().zip(&lanes) {
            let mut distances = reference.obstacle_distances(q, &spheres, &shapes).unwrap();
            distances.extend(reference.measured_self_distances(q, &spheres, &pairs, &fixed).unwrap());
            assert!(distances.iter().all(|d| !d.is_nan()), "the reference measured nothing at {q:?}");
            let expected = distances.iter().copied().fold(f64::INFINITY, f64::min);
            let clearance = R::clearance(q, &env);
            assert!((clearance - expected).abs() <= 1e-12, "clearance {clearance} at {q:?}: reference {expected}");
            let within = distances.iter().filter(|&&d| d < MARGIN).count();
            let cost = R::cost(q, &env, MARGIN);
            let expected_cost = reference_cost(&distances, MARGIN);
            assert!(
                (cost - expected_cost).abs() <= 1e-12 * (within.max(1) as f64),
                "cost {cost} at {q:?}: reference {expected_cost} ({within} pairs within the margin)"
            );
            let (c, g) = R::clearance_gradient(q, &env);
            let (h_cost, h) = R::cost_gradient(q, &env, MARGIN);
            assert!((c - clearance).abs() <= 1e-14 && (h_cost - cost).abs() <= 1e-14, "{q:?}");
            assert_eq!(bits(&[*lane]), bits(&[(clearance, g, cost, h)]), "lanes at {q:?}");
            if clearance < 0.0 { overlapping += 1 } else { apart += 1 }
        }
    }
    eprintln!("{}: {overlapping} overlapping, {apart} apart", tree.name());
    (overlapping, apart)
}

// One test per robot, so that the harness runs them side by side.

/// The scenes test both signs of the clearance.
fn both_signs((overlapping, apart): (usize, usize)) {
    assert!(overlapping > 0 && apart > 0, "the scenes test one sign only: {overlapping}, {apart}");
}

#[test]
fn clearance_and_cost_agree_with_the_reference_panda() {
    both_signs(agrees::<Panda, 7>(None, 21, None));
}

#[test]
fn clearance_and_cost_agree_with_the_reference_panda_srdf() {
    both_signs(agrees::<PandaSrdf, 7>(None, 22, Some("robots/panda.srdf")));
}

#[test]
fn clearance_and_cost_agree_with_the_reference_ur5() {
    both_signs(agrees::<Ur5Checked, 6>(None, 23, None));
}

/// The primitives arm's wrist links touch everywhere (see the verdicts' test): both signs are not
/// expected.
#[test]
fn clearance_and_cost_agree_with_the_reference_primitives() {
    agrees::<Ur5PrimitivesChecked, 6>(Some(0.02), 24, None);
}

/// The sphere pairs the model says are held apart for good are those, and only those, of the
/// checked pairs whose distance the reference measures the same (within 1e-9 m) and positive on
/// 100 random configurations; and without them the clearance moves: its gradient with no
/// obstacle is not zero on any of them (the Panda's and the UR5's clearance was otherwise a
/// constant pair's on most configurations, with a zero gradient).
fn fixed_pairs<R: Distances<N>, const N: usize>(cover: Option<f64>, srdf: Option<&str>) -> usize {
    let reference = R::reference();
    let tree = reference.tree();
    let (spheres, pairs) = spheres_and_pairs(tree, cover, srdf);
    let fixed = fixed_apart_pairs(tree, &spheres, &pairs);
    let qs: Vec<[f64; N]> = Configurations::new(tree).take(100).map(|q| q.try_into().unwrap()).collect();
    let centers: Vec<_> = qs.iter().map(|q| reference.sphere_centers(q, &spheres).unwrap()).collect();
    for &(a, b) in &pairs {
        for i in (0..spheres.len()).filter(|&i| spheres[i].link == a) {
            for j in (0..spheres.len()).filter(|&j| spheres[j].link == b) {
                let radii = spheres[i].sphere.radius + spheres[j].sphere.radius;
                let d: Vec<f64> = centers.iter().map(|c| (c[i] - c[j]).norm() - radii).collect();
                // `min` and `max` would pass over a NaN: none may be there.
                assert!(d.iter().all(|x| x.is_finite()), "{}: spheres {i} and {j}: {d:?}", tree.name());
                let (least, most) =
                    d.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, m), &x| (l.min(x), m.max(x)));
                let sampled = most - least <= 1e-9 && least > 0.0;
                let listed = fixed.iter().find(|f| (f.a, f.b) == (i.min(j), i.max(j)));
                assert_eq!(listed.is_some(), sampled, "{}: spheres {i} and {j}, {least} to {most} m", tree.name());
                if let Some(f) = listed {
                    assert!((f.distance - least).abs() <= 1e-12, "{}: {f:?} measured {least}", tree.name());
                }
            }
        }
    }
    let empty = Environment::empty();
    for q in &qs {
        let (clearance, gradient) = R::clearance_gradient(q, &empty);
        assert!(
            clearance.is_finite() && gradient.iter().any(|g| *g != 0.0),
            "{}: {clearance} {gradient:?}",
            tree.name()
        );
    }
    fixed.len()
}

#[test]
fn fixed_pairs_are_those_no_joint_moves_and_the_clearance_leaves_them_out() {
    assert_eq!(fixed_pairs::<PandaSrdf, 7>(None, Some("robots/panda.srdf")), 2, "link5 against link7");
    assert_eq!(fixed_pairs::<Panda, 7>(None, None), 16, "without the SRDF, more pairs are checked");
    assert_eq!(fixed_pairs::<Ur5Checked, 6>(None, None), 2, "base against upper arm, shoulder against forearm");
    fixed_pairs::<Ur5PrimitivesChecked, 6>(Some(0.02), None);
}

/// Central differences of `f` along each joint at `q`, step `h`.
fn central<const N: usize>(f: impl Fn(&[f64; N]) -> f64, q: &[f64; N], h: f64) -> [f64; N] {
    std::array::from_fn(|j| {
        let (mut plus, mut minus) = (*q, *q);
        plus[j] += h;
        minus[j] -= h;
        (f(&plus) - f(&minus)) / (2.0 * h)
    })
}

/// The gradients against central differences: the clearance's where the nearest pair is the
/// same a step either way (its gradient there unchanged to 1e-5), the cost's everywhere.
fn gradients<R: Distances<N>, const N: usize>(seed: u64) -> usize {
    let reference = R::reference();
    let mut stream = Stream(seed);
    let Obstacles { spheres: balls, capsules, cylinders, boxes } = obstacles(&mut stream, 0.8, 4);
    let env = Environment::new(&balls, &capsules, &cylinders, &boxes).unwrap();
    let h = 1e-6;
    let mut compared = 0;
    let qs: Vec<[f64; N]> = Configurations::new(reference.tree()).take(120).map(|q| q.try_into().unwrap()).collect();
    for q in &qs {
        let (_, g) = R::clearance_gradient(q, &env);
        let steady = (0..N).all(|j| {
            [h, -h].iter().all(|step| {
                let mut moved = *q;
                moved[j] += step;
                let (_, there) = R::clearance_gradient(&moved, &env);
                there.iter().zip(&g).all(|(a, b)| (a - b).abs() < 1e-5)
            })
        });
        if steady {
            let numeric = central(|q| R::clearance(q, &env), q, h);
            for j in 0..N {
                assert!(
                    (numeric[j] - g[j]).abs() < 1e-7,
                    "clearance gradient {j} at {q:?}: {} vs {}",
                    g[j],
                    numeric[j]
                );
            }
            compared += 1;
        }
        let (cost, g) = R::cost_gradient(q, &env, MARGIN);
        let numeric = central(|q| R::cost(q, &env, MARGIN), q, h);
        for j in 0..N {
            let scale = 1.0 + g[j].abs();
            assert!(
                (numeric[j] - g[j]).abs() < 1e-6 * scale,
                "cost gradient {j} at {q:?} (cost {cost}): {} vs {}",
                g[j],
                numeric[j]
            );
        }
    }
    assert!(compared >= qs.len() / 2, "only {compared} of {} configurations had a steady nearest pair", qs.len());
    compared
}

#[test]
fn gradients_agree_with_central_differences() {
    gradients::<PandaSrdf, 7>(31);
    gradients::<Ur5Checked, 6>(32);
}

#[test]
fn nothing_that_is_not_finite_passes() {
    let q = [0.0, f64::NAN, 0.0, -1.5, 0.0, 1.5, 0.0];
    let env = Environment::empty();
    assert!(Panda::clearance(&q, &env).is_nan());
    let (c, g) = Panda::clearance_gradient(&q, &env);
    assert!(c.is_nan() && g.iter().all(|x| x.is_nan()));
    assert!(Panda::proximity_cost(&q, &env, 0.1).unwrap().is_nan());
    let good = [0.0, 0.0, 0.0, -1.5, 0.0, 1.5, 0.0];
    for margin in [-0.1, f64::NAN, f64::INFINITY] {
        assert!(Panda::proximity_cost(&good, &env, margin).is_err(), "margin {margin}");
        assert!(Panda::proximity_cost_gradient(&good, &env, margin).is_err(), "margin {margin}");
    }
    // One lane not finite: that lane NaN, the others their own.
    let lanes: [F64x4; 7] = std::array::from_fn(|j| F64x4::from_fn(|i| if i == 2 { q[j] } else { good[j] }));
    let c = Panda::clearance_generic(&lanes, &env);
    assert!(c.lane(2).is_nan());
    assert_eq!(c.lane(0).to_bits(), Panda::clearance(&good, &env).to_bits());
}

/// With a point cloud: the clearance against every point asked in turn (and the self pairs).
#[test]
fn clearance_to_a_point_cloud_is_the_nearest_point() {
    let reference = PandaSrdf::reference().unwrap();
    let tree = reference.tree();
    let (spheres, pairs) = spheres_and_pairs(tree, None, Some("robots/panda.srdf"));
    let fixed = fixed_apart_pairs(tree, &spheres, &pairs);
    let mut stream = Stream(41);
    for (count, point_radius) in [(300, 0.0), (3000, 0.01)] {
        let points: Vec<[f64; 3]> = (0..count).map(|_| stream.point(0.8)).collect();
        let cloud = PointCloud::new(&points, point_radius).unwrap();
        let env = Environment::empty().with_query(&cloud);
        for q in Configurations::new(tree).take(40) {
            let q: [f64; 7] = q.try_into().unwrap();
            let centers = reference.sphere_centers(&q, &spheres).unwrap();
            let measured = reference.measured_self_distances(&q, &spheres, &pairs, &fixed).unwrap();
            let mut expected = measured.into_iter().fold(f64::INFINITY, f64::min);
            for (s, c) in spheres.iter().zip(&centers) {
                for p in &points {
                    let d = ((c.x - p[0]).powi(2) + (c.y - p[1]).powi(2) + (c.z - p[2]).powi(2)).sqrt();
                    expected = expected.min(d - s.sphere.radius - point_radius);
                }
            }
            let clearance = PandaSrdf::clearance(&q, &env);
            assert!((clearance - expected).abs() <= 1e-12, "{clearance} vs {expected} at {q:?}");
            let lanes: [F64x4; 7] = std::array::from_fn(|j| F64x4::splat(q[j]));
            assert_eq!(PandaSrdf::clearance_generic(&lanes, &env).lane(3).to_bits(), clearance.to_bits());
        }
    }
}
