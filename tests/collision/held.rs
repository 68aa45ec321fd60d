//! Held objects (issue 31, point 2): spheres attached to a link at run time, checked by
//! `collides` (every form) and `motion_collides` against the runtime reference, which places the
//! object by its own link poses and measures it with parry3d-f64 against the obstacles and the
//! robot's spheres on the links it is tested against, worked out here from the model's rigid
//! bodies and the touching links. A module of the collision tests, on their robots.

use kinematics::collision::{Environment, HeldError, HeldLink, SphereObstacle};
use kinematics::model::LinkId;
use kinematics::model::collision::{Cover, Meshes, link_spheres, rigid_bodies, sphere_pairs};
use kinematics::runtime::ReferenceObstacles;
use kinematics::{Configurations, F64x4, F64x8, Lanes};

use super::{PandaSrdf as Panda, Stream, Ur5Checked as Ur5, obstacles};

/// The links the object held by `link` is not tested against, by the rule read here: the links
/// of `link`'s rigid body (fixed joints between) and the touching ones.
fn skipped(tree: &kinematics::model::KinematicTree, link: &str, touching: &[&str]) -> (LinkId, Vec<LinkId>) {
    let body = rigid_bodies(tree);
    let id = |name: &str| LinkId(tree.links().iter().position(|l| l.name == name).unwrap());
    let holder = id(link);
    let mut skip: Vec<LinkId> = (0..body.len()).filter(|&l| body[l] == body[holder.0]).map(LinkId).collect();
    skip.extend(touching.iter().map(|name| id(name)));
    (holder, skip)
}

/// A few spheres (4 to 10 cm) within 20 cm of the holding link's origin, ahead along its z axis.
fn object(stream: &mut Stream, count: usize) -> Vec<SphereObstacle> {
    (0..count)
        .map(|_| SphereObstacle {
            center: [stream.within(0.08), stream.within(0.08), 0.04 + 0.16 * stream.next()],
            radius: 0.04 + 0.06 * stream.next(),
        })
        .collect()
}

/// How many configurations the reference decided, and how many of them the object alone made
/// colliding (free without it).
#[derive(Debug, Default)]
struct Seen {
    judged: usize,
    banded: usize,
    colliding: usize,
    by_the_object: usize,
}

/// `collides` holding an object, against the reference, on one configuration and in the batch and
/// lane forms, for the Panda holding by `link` with `touching` left out.
fn held_checks(link: &str, touching: &[&str], seed: u64) -> Seen {
    let reference = Panda::reference().unwrap();
    let tree = reference.tree();
    let spheres = link_spheres(tree, &Cover::default(), Meshes::Read).unwrap();
    let text = std::fs::read_to_string(format!("{}/robots/panda.srdf", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let disabled = kinematics::model::srdf::parse_srdf(&text).unwrap().disabled_pairs(tree).unwrap();
    let pairs = sphere_pairs(tree, &spheres, Some(&disabled)).pairs;
    let (holder, skip) = skipped(tree, link, touching);
    let mut stream = Stream(seed);
    let mut seen = Seen::default();
    for round in 0..3 {
        let o = obstacles(&mut stream, 0.8, 1);
        let env = Environment::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes).unwrap();
        let reference_obstacles = ReferenceObstacles::new(&o.spheres, &o.capsules, &o.cylinders, &o.boxes);
        let balls = object(&mut stream, 1 + round);
        let held = Panda::hold(link, &balls, touching).unwrap();
        let world = env.holding(&held);
        let qs: Vec<[f64; 7]> =
            Configurations::new(tree).skip(50 + 200 * round).take(200).map(|q| q.try_into().unwrap()).collect();
        let mut batch = vec![false; qs.len()];
        Panda::collides_batch(&qs, &world, &mut batch).unwrap();
        let columns: Vec<Vec<f64>> = (0..7).map(|j| qs.iter().map(|q| q[j]).collect()).collect();
        let columns: [&[f64]; 7] = std::array::from_fn(|j| columns[j].as_slice());
        let mut by_columns = vec![false; qs.len()];
        Panda::collides_batch_columns(columns, &world, &mut by_columns).unwrap();
        assert_eq!(by_columns, batch, "column batch");
        assert_eq!(lanes::<F64x4>(&qs, &world), batch, "four lanes");
        assert_eq!(lanes::<F64x8>(&qs, &world), batch, "eight lanes");
        for (k, q) in qs.iter().enumerate() {
            let verdict = Panda::collides(q, &world);
            assert_eq!(batch[k], verdict, "batch at {q:?}");
            let d = reference.obstacle_distance(q, &spheres, &reference_obstacles).unwrap();
            let s = reference.self_distance(q, &spheres, &pairs).unwrap();
            let (ho, hr) = reference.held_distances(q, holder, &balls, &spheres, &reference_obstacles, &skip).unwrap();
            assert!(![d, s, ho, hr].iter().any(|x| x.is_nan()), "the reference measured nothing at {q:?}");
            let robot = d.min(s);
            let nearest = robot.min(ho).min(hr);
            if [d, s, ho, hr].iter().any(|&x| x < -1e-9) || nearest > 1e-9 {
                assert_eq!(verdict, nearest < 0.0, "at {q:?}: robot {d:e} self {s:e} object {ho:e} / {hr:e}");
                seen.judged += 1;
                seen.colliding += usize::from(verdict);
                seen.by_the_object += usize::from(verdict && robot > 1e-9);
            } else {
                seen.banded += 1;
            }
            // The object only adds: what collides without it collides with it.
            if Panda::collides(q, &env) {
                assert!(verdict, "holding made {q:?} free");
            }
            let f32_q = q.map(|x| x as f32);
            if nearest.abs() > 1e-4 {
                assert_eq!(Panda::collides_f32(&f32_q, &world), nearest < 0.0, "f32 at {q:?}");
            }
        }
    }
    eprintln!("held by {link}: {seen:?}");
    seen
}

/// The generic form a pack at a time (the tail repeats the last configuration).
fn lanes<L: Lanes<Scalar = f64> + kinematics::collision::CheckLanes>(
    qs: &[[f64; 7]],
    world: &impl kinematics::collision::World<Panda>,
) -> Vec<bool> {
    let mut out = Vec::new();
    for start in (0..qs.len()).step_by(L::LANES) {
        let lanes: [L; 7] = std::array::from_fn(|j| L::from_fn(|i| qs[(start + i).min(qs.len() - 1)][j]));
        let mask = Panda::collides_generic(&lanes, world);
        out.extend((0..L::LANES).map(|i| mask.lane(i)).take(qs.len() - start));
    }
    out
}

#[test]
fn a_held_object_is_checked_as_the_reference_measures_it() {
    // A frame without spheres on the hand's body (the object hangs on the body's first link with
    // spheres, through a fixed pose), and a link in the middle of the arm leaving out a neighbour.
    for (link, touching, seed) in
        [("panda_grasptarget", &[][..], 31), ("panda_link5", &["panda_link4", "panda_link6"][..], 32)]
    {
        let seen = held_checks(link, touching, seed);
        assert!(seen.judged > 400, "too few configurations judged: {seen:?}");
        assert!(seen.by_the_object > 10, "the object decided too few verdicts: {seen:?}");
        assert!(seen.judged - seen.colliding > 50, "too few free configurations: {seen:?}");
    }
}

#[test]
fn the_holding_body_and_the_touching_links_are_left_out() {
    let reference = Panda::reference().unwrap();
    let tree = reference.tree();
    let spheres = link_spheres(tree, &Cover::default(), Meshes::Read).unwrap();
    let none = ReferenceObstacles::new(&[], &[], &[], &[]);
    let empty = Environment::empty();
    let qs: Vec<[f64; 7]> = Configurations::new(tree).take(400).map(|q| q.try_into().unwrap()).collect();
    let free: Vec<&[f64; 7]> = qs.iter().filter(|q| !Panda::collides(q, &empty)).collect();
    assert!(free.len() > 100);
    // A ball across the fingers (on the holding body): it collides only where the reference,
    // leaving that body out, finds it touching another link.
    let ball = [SphereObstacle { center: [0.0, 0.0, 0.0], radius: 0.05 }];
    let held = Panda::hold("panda_grasptarget", &ball, &[]).unwrap();
    let (holder, skip) = skipped(tree, "panda_grasptarget", &[]);
    assert!(skip.len() > 3, "the hand's body: {skip:?}");
    let mut untouched = 0;
    for q in &free {
        let (_, to_robot) = reference.held_distances(*q, holder, &ball, &spheres, &none, &skip).unwrap();
        if to_robot.abs() > 1e-9 {
            assert_eq!(Panda::collides(q, &empty.holding(&held)), to_robot < 0.0, "{q:?}: {to_robot:e}");
            untouched += usize::from(to_robot > 0.0);
        }
    }
    assert!(untouched > 100, "the fingers' own ball was free in {untouched} configurations");
    // A ball held by link 5 at its elbow end, where it overlaps link 4 in every configuration,
    // with and without link 4 left out: each verdict the reference's with its own links left
    // out, and leaving link 4 out frees most configurations.
    let ball = [SphereObstacle { center: [0.0, 0.0, -0.25], radius: 0.05 }];
    let mut freed = 0;
    for q in &free {
        let mut verdicts = [false; 2];
        for (verdict, touching) in verdicts.iter_mut().zip([&[][..], &["panda_link4"][..]]) {
            let held = Panda::hold("panda_link5", &ball, touching).unwrap();
            let (holder, skip) = skipped(tree, "panda_link5", touching);
            let (_, to_robot) = reference.held_distances(*q, holder, &ball, &spheres, &none, &skip).unwrap();
            *verdict = Panda::collides(q, &empty.holding(&held));
            if to_robot.abs() > 1e-9 {
                assert_eq!(*verdict, to_robot < 0.0, "{q:?}, {touching:?} left out: {to_robot:e}");
            }
        }
        assert!(verdicts[0], "link 4 untouched at {q:?}");
        freed += usize::from(!verdicts[1]);
    }
    assert!(freed > free.len() / 2, "leaving link 4 out freed {freed} of {} configurations", free.len());
}

#[test]
fn motions_holding_an_object_end_where_the_held_check_does() {
    let scene = kinematics::load_scene(format!("{}/scenes/tabletop.toml", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let env = scene.environment().unwrap();
    let box_in_hand = [
        SphereObstacle { center: [0.0, 0.0, 0.05], radius: 0.04 },
        SphereObstacle { center: [0.0, 0.0, 0.12], radius: 0.04 },
    ];
    let held = Panda::hold("panda_grasptarget", &box_in_hand, &[]).unwrap();
    let world = env.holding(&held);
    let qs: Vec<[f64; 7]> = Configurations::new(Panda::reference().unwrap().tree())
        .skip(7)
        .take(120)
        .map(|q| q.try_into().unwrap())
        .collect();
    let (mut colliding, mut differs) = (0, 0);
    for pair in qs.chunks_exact(2) {
        let (q0, q1) = (&pair[0], &pair[1]);
        let resolution = 0.1;
        let steps = q0.iter().zip(q1).map(|(a, b)| (b - a).abs()).fold(0.0, f64::max) / resolution;
        let steps = (steps.ceil() as usize).max(1);
        let first = (0..=steps).find(|&k| {
            let t = k as f64 / steps as f64;
            Panda::collides(&std::array::from_fn(|j| (1.0 - t) * q0[j] + t * q1[j]), &world)
        });
        let expected = first.map(|k| k as f64 / steps as f64);
        assert_eq!(Panda::motion_collides(q0, q1, &world, resolution).unwrap(), expected, "{q0:?} -> {q1:?}");
        colliding += usize::from(first.is_some());
        differs += usize::from(Panda::motion_collides(q0, q1, &env, resolution).unwrap() != expected);
    }
    assert!(colliding > 5 && differs > 0, "{colliding} colliding motions, {differs} changed by the object");
}

#[test]
fn bad_held_objects_are_refused_naming_what_is_wrong() {
    let ball = [SphereObstacle { center: [0.0; 3], radius: 0.05 }];
    let robot = Panda::ROBOT;
    let err = |r: Result<_, HeldError>| r.map(|_: kinematics::collision::Held<'_, Panda>| ()).unwrap_err();
    assert_eq!(err(Panda::hold("panda_palm", &ball, &[])), HeldError::UnknownLink { robot, which: HeldLink::Holding });
    assert_eq!(
        err(Panda::hold("panda_hand", &ball, &["panda_link6", "panda_link9"])),
        HeldError::UnknownLink { robot, which: HeldLink::Touching(1) }
    );
    assert_eq!(
        err(Panda::hold("panda_hand", &ball, &["panda_grasptarget"])),
        HeldError::NotChecked { robot, link: "panda_grasptarget" }
    );
    let nan = [ball[0], SphereObstacle { center: [f64::NAN, 0.0, 0.0], radius: 0.05 }];
    assert_eq!(err(Panda::hold("panda_hand", &nan, &[])), HeldError::BadSphere { robot, index: 1, not_finite: true });
    let flat = [SphereObstacle { center: [0.0; 3], radius: 0.0 }];
    assert_eq!(err(Panda::hold("panda_hand", &flat, &[])), HeldError::BadSphere { robot, index: 0, not_finite: false });
    let message = err(Panda::hold("panda_hand", &ball, &["panda_grasptarget"])).to_string();
    assert!(message.contains("`panda_grasptarget` has no collision spheres"), "{message}");
    // Another arm's object cannot be handed to this one: `Held<'_, Ur5>` is not a `World<Panda>`
    // (a compile error; here, the UR5's own check takes it).
    let ur5_held = Ur5::hold("tool0", &ball, &[]).unwrap();
    let _ = Ur5::collides(&[0.0; 6], &Environment::empty().holding(&ur5_held));
}
