//! Point clouds (issue 31, point 3): obstacles given as points with a radius, in a k-d tree,
//! checked by `collides` (every form) against a brute-force reference over every point on the
//! reference's own sphere centres, on random clouds, with and without a held object. A module of
//! the collision tests, on their robots.

use kinematics::collision::{Environment, PointCloud, SphereObstacle};
use kinematics::model::collision::{Cover, Meshes, link_spheres, sphere_pairs};
use kinematics::runtime::ReferenceObstacles;
use kinematics::{Configurations, F64x4, F64x8, Lanes};

use super::{PandaSrdf as Panda, Stream};

/// `count` points in clusters (a sensor sees surfaces, not a uniform haze) within the arm's
/// reach: each cluster a patch of a plane through a random centre.
fn cloud(stream: &mut Stream, count: usize) -> Vec<[f64; 3]> {
    let mut points = Vec::with_capacity(count);
    while points.len() < count {
        let center = [stream.within(0.8), stream.within(0.8), stream.next() * 0.9];
        let (u, v) = ([stream.within(1.0), stream.within(1.0), stream.within(1.0)], [stream.within(1.0); 3]);
        for _ in 0..200.min(count - points.len()) {
            let (a, b) = (stream.within(0.15), stream.within(0.15));
            points.push(std::array::from_fn(|i| center[i] + a * u[i] + b * v[i]));
        }
    }
    points
}

/// The smallest gap between the robot's spheres (the reference's centres) and the cloud's points,
/// by every pair: negative where a sphere reaches past a point's radius.
fn brute_gap(centers: &[nalgebra::Point3<f64>], radii: &[f64], points: &[[f64; 3]], point_radius: f64) -> f64 {
    let mut least = f64::INFINITY;
    for (c, r) in centers.iter().zip(radii) {
        for p in points {
            let d = ((c.x - p[0]).powi(2) + (c.y - p[1]).powi(2) + (c.z - p[2]).powi(2)).sqrt();
            least = least.min(d - r - point_radius);
        }
    }
    least
}

#[test]
fn point_clouds_are_checked_as_every_point_asked_in_turn() {
    let reference = Panda::reference().unwrap();
    let tree = reference.tree();
    let spheres = link_spheres(tree, &Cover::default(), Meshes::Read).unwrap();
    let radii: Vec<f64> = spheres.iter().map(|s| s.sphere.radius).collect();
    let text = std::fs::read_to_string(format!("{}/robots/panda.srdf", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let disabled = kinematics::model::srdf::parse_srdf(&text).unwrap().disabled_pairs(tree).unwrap();
    let pairs = sphere_pairs(tree, &spheres, Some(&disabled)).pairs;
    let mut stream = Stream(33);
    let (mut judged, mut colliding, mut by_the_cloud) = (0, 0, 0);
    for (round, count) in [400, 2_000, 6_000].into_iter().enumerate() {
        let points = cloud(&mut stream, count);
        let point_radius = 0.005 * round as f64;
        let cloud = PointCloud::new(&points, point_radius).unwrap();
        let env = Environment::empty().with_query(&cloud);
        let qs: Vec<[f64; 7]> =
            Configurations::new(tree).skip(300 * round).take(150).map(|q| q.try_into().unwrap()).collect();
        let mut batch = vec![false; qs.len()];
        Panda::collides_batch(&qs, &env, &mut batch).unwrap();
        let packs = |width: usize, check: &dyn Fn(&[[f64; 7]]) -> Vec<bool>| {
            qs.chunks(width).flat_map(check).collect::<Vec<bool>>()
        };
        let four = packs(4, &|pack| {
            let lanes: [F64x4; 7] = std::array::from_fn(|j| F64x4::from_fn(|i| pack[i.min(pack.len() - 1)][j]));
            let mask = Panda::collides_generic(&lanes, &env);
            (0..pack.len()).map(|i| mask.lane(i)).collect()
        });
        let eight = packs(8, &|pack| {
            let lanes: [F64x8; 7] = std::array::from_fn(|j| F64x8::from_fn(|i| pack[i.min(pack.len() - 1)][j]));
            let mask = Panda::collides_generic(&lanes, &env);
            (0..pack.len()).map(|i| mask.lane(i)).collect()
        });
        assert_eq!((&four, &eight), (&batch, &batch), "lanes");
        for (k, q) in qs.iter().enumerate() {
            let verdict = Panda::collides(q, &env);
            assert_eq!(batch[k], verdict, "batch at {q:?}");
            let centers = reference.sphere_centers(q, &spheres).unwrap();
            let gap = brute_gap(&centers, &radii, &points, point_radius);
            let itself = reference.self_distance(q, &spheres, &pairs).unwrap();
            let nearest = gap.min(itself);
            assert!(!nearest.is_nan(), "nothing measured at {q:?}");
            if gap < -1e-9 || itself < -1e-9 || nearest > 1e-9 {
                assert_eq!(verdict, nearest < 0.0, "at {q:?}: cloud gap {gap:e}, self {itself:e}");
                judged += 1;
                colliding += usize::from(verdict);
                by_the_cloud += usize::from(verdict && itself > 1e-9);
            }
        }
    }
    eprintln!("point clouds: {judged} judged, {colliding} colliding, {by_the_cloud} by the cloud alone");
    assert!(judged > 400 && by_the_cloud > 50 && judged - colliding > 50, "{judged} {colliding} {by_the_cloud}");
}

#[test]
fn a_held_object_meets_the_cloud_too() {
    let reference = Panda::reference().unwrap();
    let tree = reference.tree();
    let spheres = link_spheres(tree, &Cover::default(), Meshes::Read).unwrap();
    let text = std::fs::read_to_string(format!("{}/robots/panda.srdf", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let disabled = kinematics::model::srdf::parse_srdf(&text).unwrap().disabled_pairs(tree).unwrap();
    let pairs = sphere_pairs(tree, &spheres, Some(&disabled)).pairs;
    // A shell of points of radius 3 cm (overlapping: a solid wall) around the arm, 0.6 m from its axis (the reference takes
    // each as a ball), and a long object in the hand that reaches it where the arm does not.
    let wall: Vec<[f64; 3]> = (0..64)
        .flat_map(|i| {
            let angle = std::f64::consts::TAU * f64::from(i) / 64.0;
            (0..25).map(move |j| [0.6 * angle.cos(), 0.6 * angle.sin(), 0.05 * f64::from(j)])
        })
        .collect();
    let cloud = PointCloud::new(&wall, 0.03).unwrap();
    let env = Environment::empty().with_query(&cloud);
    let balls: Vec<SphereObstacle> = wall.iter().map(|&center| SphereObstacle { center, radius: 0.03 }).collect();
    let reference_wall = ReferenceObstacles::new(&balls, &[], &[], &[]);
    let rod = [0.0, 0.1, 0.2, 0.3, 0.4].map(|z| SphereObstacle { center: [0.0, 0.0, z], radius: 0.02 });
    let held = Panda::hold("panda_grasptarget", &rod, &[]).unwrap();
    let world = env.holding(&held);
    let holder = kinematics::model::LinkId(tree.links().iter().position(|l| l.name == "panda_grasptarget").unwrap());
    let body = kinematics::model::collision::rigid_bodies(tree);
    let skip: Vec<_> = (0..body.len()).filter(|&l| body[l] == body[holder.0]).map(kinematics::model::LinkId).collect();
    let (mut judged, mut by_the_rod) = (0, 0);
    for q in Configurations::new(tree).skip(1000).take(200) {
        let q: [f64; 7] = q.try_into().unwrap();
        let verdict = Panda::collides(&q, &world);
        let d = reference.obstacle_distance(&q, &spheres, &reference_wall).unwrap();
        let s = reference.self_distance(&q, &spheres, &pairs).unwrap();
        let (ho, hr) = reference.held_distances(&q, holder, &rod, &spheres, &reference_wall, &skip).unwrap();
        let robot = d.min(s);
        let nearest = robot.min(ho).min(hr);
        if [d, s, ho, hr].iter().any(|&x| x < -1e-9) || nearest > 1e-9 {
            assert_eq!(verdict, nearest < 0.0, "at {q:?}: robot {d:e} self {s:e} rod {ho:e} / {hr:e}");
            judged += 1;
            // The rod through the wall where the arm is clear of it.
            by_the_rod += usize::from(ho < -1e-9 && d > 1e-9);
        }
    }
    assert!(judged > 150 && by_the_rod > 10, "{judged} judged, {by_the_rod} with the rod alone through the wall");
}
