//! Collision checking (issue 30), per configuration, on VAMP's spherized Panda and UR5:
//!
//! - `sphere_centers` (one configuration, and batches of 1,024 in lanes, f64 and f32) against the
//!   runtime reference's, and the generic form on 16 `f32` configurations at a time, the centres
//!   kept in lanes;
//! - `collides` in the tabletop (12 boxes) and shelf (18 boxes, capsules and cylinders) scenes of
//!   `scenes/`, each configuration with its own verdict (the fraction free printed), and on
//!   all-free configurations (no early exit), one at a time and in batches (lanes);
//! - `self_collides`, one at a time and in batches, and with the link poses in the wide lanes
//!   (`F64x8`, `F32x16`; the generic forms in a dispatched loop);
//! - `motion_collides` (`f64` and `f32`) on motions between consecutive free configurations at
//!   0.05 rad, per motion (the fraction colliding and the configurations a motion printed), and
//!   per checked configuration on the free motions beside `collides_batch` on the same
//!   configurations;
//! - `clearance`, `clearance_gradient` (one configuration, and in `F64x4` lanes) and
//!   `proximity_cost_gradient` (a 5 cm margin) on the all-free configurations, beside the
//!   reference's parry distances;
//! - point clouds (the Panda): a cloud of 10^3 to 10^6 points sampled on the tabletop scene's
//!   surfaces, its k-d tree's build time and `collides` per configuration against it;
//! - holding an object (the Panda, a two-sphere bottle in the grasp frame) in the tabletop scene;
//! - the baselines a user has without `collision`: our generated link poses plus a hand loop over
//!   the spheres, and the same centres with parry3d-f64's intersection tests (the reference's
//!   shapes);
//! - the Panda from franka_description's collision meshes (issue 59): the time to cover every link
//!   with spheres (`link_spheres`, the default cover), the meshes read beforehand, and reading and
//!   covering together; and its `collides` against the spherized Panda's (VAMP's 59 spheres) in
//!   the same scenes on the same configurations.
//!
//! Batches report their throughput (configurations per second): the time per configuration is its
//! inverse. `cargo bench --bench collision` measures; under `cargo test` every body runs once and
//! its answers are checked.
#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[allow(dead_code)] // the helpers the fk and ik benchmarks use and this one does not
mod common;

use std::hint::black_box;
use std::path::Path;
use std::time::Duration;

use criterion::{BatchSize, Throughput};
use kinematics::collision::{BoxObstacle, Environment, PointCloud, SphereObstacle};
use kinematics::model::collision::{Cover, Meshes, fixed_apart_pairs, link_spheres, sphere_pairs};
use kinematics::{Configurations, F32x16, F64x4, F64x8, Kinematics, Lanes, SceneObstacles};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda_spherized.urdf", collision(srdf = "robots/panda.srdf"), scalars(f64, f32))]
struct Panda;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_spherized.urdf", collision(srdf = "robots/ur5_spherized.srdf"), scalars(f64, f32))]
struct Ur5;

/// The Panda with franka_description's collision meshes, covered by the derive's default (at most
/// 10 spheres per link, stopping at 1 cm), with the spherized Panda's SRDF.
#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda_meshes.urdf", collision(srdf = "robots/panda.srdf"), scalars(f64, f32))]
struct PandaMeshes;

/// 1,024 configurations of `N` joints drawn uniformly within the limits, as a planner samples
/// them (the agreement stream's special angles and values beyond the limits are for tests).
fn inputs<const N: usize>(limits: &[kinematics::JointLimits]) -> Vec<[f64; N]> {
    Configurations::within(limits).uniform().take(1024).map(|q| q.try_into().unwrap()).collect()
}

/// The resolution motions are checked at (radians): the largest joint step between checked
/// configurations.
const RESOLUTION: f64 = 0.05;

/// The proximity cost's margin (m): pairs nearer than this cost.
const MARGIN: f64 = 0.05;

/// Every configuration the motions check at [`RESOLUTION`], motion after motion.
fn along<S: kinematics::Real + Into<f64>, const N: usize>(motions: &[([S; N], [S; N])]) -> Vec<[S; N]> {
    motions
        .iter()
        .flat_map(|m| {
            let motion = kinematics::collision::Motion::new("bench", m.0, m.1, RESOLUTION).unwrap();
            (0..=motion.steps()).map(move |k| motion.configuration(k))
        })
        .collect()
}

fn scene(name: &str) -> SceneObstacles {
    kinematics::load_scene(format!("{}/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

macro_rules! robot {
    ($c:expr, $name:literal, $robot:ty, $n:literal, $srdf:expr) => {{
        let mut criterion: Option<&mut criterion::Criterion> = $c;
        const S: usize = <$robot>::SPHERE_RADII.len();
        let qs: Vec<[f64; $n]> = inputs(&<$robot>::JOINT_LIMITS);
        let qs32: Vec<[f32; $n]> = qs.iter().map(|q| q.map(|x| x as f32)).collect();
        let reference = <$robot>::reference().unwrap();
        let spheres = link_spheres(reference.tree(), &Cover::default(), Meshes::Read).unwrap();
        let srdf: Option<&str> = $srdf;
        let disabled = srdf.map(|file| {
            let text = std::fs::read_to_string(format!("{}/{file}", env!("CARGO_MANIFEST_DIR"))).unwrap();
            kinematics::model::srdf::parse_srdf(&text).unwrap().disabled_pairs(reference.tree()).unwrap()
        });
        let reference_pairs = sphere_pairs(reference.tree(), &spheres, disabled.as_ref()).pairs;
        let fixed = fixed_apart_pairs(reference.tree(), &spheres, &reference_pairs);
        // Each sphere's link's index in `link_poses` (none for the base, which it leaves out) and
        // its centre in that link's frame.
        let local: Vec<(Option<usize>, [f64; 3])> = spheres
            .iter()
            .map(|s| {
                let link = reference.tree().link(s.link);
                let index = <$robot>::LINK_NAMES.iter().position(|n| *n == link.name);
                (index, s.sphere.center)
            })
            .collect();
        let hand_centers = |q: &[f64; $n]| -> [[f64; 3]; S] {
            let poses = <$robot>::link_poses(q);
            let mut out = [[0.0; 3]; S];
            for (c, (link, p)) in out.iter_mut().zip(&local) {
                *c = match link {
                    Some(link) => {
                        let (r, t) = (&poses[*link].rotation, &poses[*link].translation);
                        [0, 1, 2].map(|i| r[i][0] * p[0] + r[i][1] * p[1] + r[i][2] * p[2] + t[i])
                    }
                    None => *p,
                };
            }
            out
        };
        for scene_name in ["tabletop", "shelf"] {
            let obstacles = scene(scene_name);
            let env: Environment<'_> = obstacles.environment().unwrap();
            let shapes = obstacles.reference();
            let free: Vec<[f64; $n]> = qs.iter().copied().filter(|q| !<$robot>::collides(q, &env)).collect();
            let free32: Vec<[f32; $n]> = free.iter().map(|q| q.map(|x| x as f32)).collect();
            // Motions between free configurations, as a planner's edges: consecutive pairs.
            let motions: Vec<([f64; $n], [f64; $n])> = free.chunks_exact(2).map(|m| (m[0], m[1])).collect();
            let motions32: Vec<([f32; $n], [f32; $n])> = free32.chunks_exact(2).map(|m| (m[0], m[1])).collect();
            // The baselines: generated link poses, then the spheres by hand against the same
            // environment (`Environment::hits`) or against parry's shapes; self-collision
            // through `self_collides`, as a user without a check of their own would.
            let hand = |q: &[f64; $n]| {
                hand_centers(q).iter().zip(<$robot>::SPHERE_RADII).any(|(c, r)| env.hits(*c, r))
                    || <$robot>::self_collides(q)
            };
            let parry = |q: &[f64; $n]| {
                hand_centers(q).iter().zip(<$robot>::SPHERE_RADII).any(|(c, r)| shapes.intersects(*c, r))
                    || <$robot>::self_collides(q)
            };
            // The free motions and every configuration they check: a motion per checked
            // configuration beside `collides_batch` on the same configurations (the lanes spent
            // on points of the segment against the lanes spent on a batch).
            let free_motions: Vec<([f64; $n], [f64; $n])> = motions
                .iter()
                .copied()
                .filter(|m| <$robot>::motion_collides(&m.0, &m.1, &env, RESOLUTION).unwrap().is_none())
                .collect();
            let free_motions32: Vec<([f32; $n], [f32; $n])> =
                free_motions.iter().map(|m| (m.0.map(|x| x as f32), m.1.map(|x| x as f32))).collect();
            let (along, along32) = (along(&free_motions), along(&free_motions32));
            let Some(c) = criterion.as_deref_mut() else {
                // Check mode: the centres against the reference's, every form's verdicts against
                // the one-configuration function, the baselines against it (they agree but at
                // touching contact, which these configurations do not meet).
                for q in qs.iter().take(8) {
                    let generated = <$robot>::sphere_centers(q);
                    for (g, r) in generated.iter().zip(reference.sphere_centers(q, &spheres).unwrap()) {
                        assert!((0..3).all(|i| (g[i] - r[i]).abs() < 1e-12), "{}", $name);
                    }
                    for (g, h) in generated.iter().zip(hand_centers(q)) {
                        assert!((0..3).all(|i| (g[i] - h[i]).abs() < 1e-12), "{}", $name);
                    }
                }
                let mut verdicts = vec![false; qs.len()];
                <$robot>::collides_batch(&qs, &env, &mut verdicts).unwrap();
                for (q, v) in qs.iter().zip(&verdicts) {
                    let one = <$robot>::collides(q, &env);
                    assert_eq!((*v, hand(q), parry(q)), (one, one, one), "{} in the {scene_name} scene", $name);
                }
                assert!(!free.is_empty() && free.len() < qs.len(), "{}: {} free of {}", $name, free.len(), qs.len());
                // The clearance is positive exactly where `collides` finds nothing (touching
                // counts as colliding), and the reference's distances agree.
                for (q, v) in qs.iter().zip(&verdicts) {
                    let clearance = <$robot>::clearance(q, &env);
                    assert_eq!(clearance <= 0.0, *v, "{} clearance {clearance} in the {scene_name} scene", $name);
                }
                // Every configuration of a free motion is free.
                let mut along_verdicts = vec![true; along.len()];
                <$robot>::collides_batch(&along, &env, &mut along_verdicts).unwrap();
                assert!(
                    !along.is_empty() && along_verdicts.iter().all(|v| !v),
                    "{}: a free motion's configurations",
                    $name
                );
                // A motion's answer is a configuration that collides, or its ends are free.
                for m in motions.iter().take(8) {
                    match <$robot>::motion_collides(&m.0, &m.1, &env, RESOLUTION).unwrap() {
                        Some(t) => {
                            assert!(<$robot>::collides(&std::array::from_fn(|j| (1.0 - t) * m.0[j] + t * m.1[j]), &env))
                        }
                        None => assert!(!<$robot>::collides(&m.0, &env) && !<$robot>::collides(&m.1, &env)),
                    }
                }
                continue;
            };
            println!("{}: {} of {} configurations free in the {scene_name} scene", $name, free.len(), qs.len());
            let mut group = c.benchmark_group(format!("{}/{scene_name}", $name));
            let mut k = 0;
            group.bench_function("collides", |b| {
                b.iter(|| {
                    k = (k + 1) % qs.len();
                    black_box(<$robot>::collides(black_box(&qs[k]), &env))
                })
            });
            group.bench_function("collides_all_free", |b| {
                b.iter(|| {
                    k = (k + 1) % free.len();
                    black_box(<$robot>::collides(black_box(&free[k]), &env))
                })
            });
            group.bench_function("link_poses_and_hand_loop", |b| {
                b.iter(|| {
                    k = (k + 1) % qs.len();
                    black_box(hand(black_box(&qs[k])))
                })
            });
            group.bench_function("link_poses_and_parry", |b| {
                b.iter(|| {
                    k = (k + 1) % qs.len();
                    black_box(parry(black_box(&qs[k])))
                })
            });
            let mut verdicts = vec![false; qs.len()];
            group.throughput(Throughput::Elements(qs.len() as u64));
            group.bench_function("collides_batch", |b| {
                b.iter(|| <$robot>::collides_batch(black_box(&qs), &env, &mut verdicts).unwrap())
            });
            group.bench_function("collides_batch_f32", |b| {
                b.iter(|| <$robot>::collides_batch_f32(black_box(&qs32), &env, &mut verdicts).unwrap())
            });
            let mut free_verdicts = vec![false; free.len()];
            group.throughput(Throughput::Elements(free.len() as u64));
            group.bench_function("collides_all_free_batch", |b| {
                b.iter(|| <$robot>::collides_batch(black_box(&free), &env, &mut free_verdicts).unwrap())
            });
            group.bench_function("collides_all_free_batch_f32", |b| {
                b.iter(|| <$robot>::collides_batch_f32(black_box(&free32), &env, &mut free_verdicts).unwrap())
            });
            let colliding = motions
                .iter()
                .filter(|m| <$robot>::motion_collides(&m.0, &m.1, &env, RESOLUTION).unwrap().is_some())
                .count();
            let checked: usize = motions
                .iter()
                .map(|m| kinematics::collision::Motion::new("bench", m.0, m.1, RESOLUTION).unwrap().steps() + 1)
                .sum();
            println!(
                "{}: {colliding} of {} motions between free configurations collide in the {scene_name} scene \
                 ({:.0} configurations a motion at {RESOLUTION} rad)",
                $name,
                motions.len(),
                checked as f64 / motions.len() as f64
            );
            group.throughput(Throughput::Elements(1));
            group.bench_function("motion_collides", |b| {
                b.iter(|| {
                    k = (k + 1) % motions.len();
                    black_box(<$robot>::motion_collides(&motions[k].0, &motions[k].1, &env, RESOLUTION))
                })
            });
            group.bench_function("motion_collides_f32", |b| {
                b.iter(|| {
                    k = (k + 1) % motions32.len();
                    black_box(<$robot>::motion_collides_f32(&motions32[k].0, &motions32[k].1, &env, RESOLUTION))
                })
            });
            // Per checked configuration: every configuration of the free motions, by
            // `motion_collides` and by `collides_batch`.
            group.throughput(Throughput::Elements(along.len() as u64));
            group.bench_function("motion_collides_free_motions", |b| {
                b.iter(|| {
                    for m in &free_motions {
                        black_box(<$robot>::motion_collides(black_box(&m.0), &m.1, &env, RESOLUTION).unwrap());
                    }
                })
            });
            group.bench_function("motion_collides_f32_free_motions", |b| {
                b.iter(|| {
                    for m in &free_motions32 {
                        black_box(<$robot>::motion_collides_f32(black_box(&m.0), &m.1, &env, RESOLUTION).unwrap());
                    }
                })
            });
            let mut along_verdicts = vec![false; along.len()];
            group.bench_function("collides_batch_free_motions", |b| {
                b.iter(|| <$robot>::collides_batch(black_box(&along), &env, &mut along_verdicts).unwrap())
            });
            group.bench_function("collides_batch_f32_free_motions", |b| {
                b.iter(|| <$robot>::collides_batch_f32(black_box(&along32), &env, &mut along_verdicts).unwrap())
            });
            group.throughput(Throughput::Elements(1));
            // Distances on the free configurations (where no check ends early), beside
            // `collides_all_free`: the clearance alone, with its gradient, in lanes, the
            // proximity cost with its gradient, and the reference's parry distances.
            group.bench_function("clearance_all_free", |b| {
                b.iter(|| {
                    k = (k + 1) % free.len();
                    black_box(<$robot>::clearance(black_box(&free[k]), &env))
                })
            });
            group.bench_function("clearance_gradient_all_free", |b| {
                b.iter(|| {
                    k = (k + 1) % free.len();
                    black_box(<$robot>::clearance_gradient(black_box(&free[k]), &env))
                })
            });
            group.bench_function("proximity_cost_gradient_all_free", |b| {
                b.iter(|| {
                    k = (k + 1) % free.len();
                    black_box(<$robot>::proximity_cost_gradient(black_box(&free[k]), &env, MARGIN))
                })
            });
            let lanes: Vec<[F64x4; $n]> =
                free.chunks_exact(4).map(|pack| std::array::from_fn(|j| F64x4::from_fn(|i| pack[i][j]))).collect();
            group.throughput(Throughput::Elements(4 * lanes.len() as u64));
            group.bench_function("clearance_all_free_f64x4", |b| {
                b.iter(|| {
                    kinematics::dispatch(
                        #[inline(always)]
                        || {
                            for q in &lanes {
                                black_box(<$robot>::clearance_generic(black_box(q), &env));
                            }
                        },
                    )
                })
            });
            group.bench_function("clearance_gradient_all_free_f64x4", |b| {
                b.iter(|| {
                    kinematics::dispatch(
                        #[inline(always)]
                        || {
                            for q in &lanes {
                                black_box(<$robot>::clearance_gradient_generic(black_box(q), &env));
                            }
                        },
                    )
                })
            });
            group.throughput(Throughput::Elements(1));
            group.bench_function("reference_clearance", |b| {
                b.iter(|| {
                    k = (k + 1) % free.len();
                    let q = black_box(&free[k]);
                    let d = reference.obstacle_distance(q, &spheres, &shapes).unwrap();
                    let measured = reference.measured_self_distances(q, &spheres, &reference_pairs, &fixed).unwrap();
                    black_box(measured.into_iter().fold(d, f64::min))
                })
            });
            group.finish();
        }
        let Some(c) = criterion else { return };
        let mut group = c.benchmark_group($name);
        let mut k = 0;
        group.bench_function("sphere_centers", |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                black_box(<$robot>::sphere_centers(black_box(&qs[k])))
            })
        });
        group.bench_function("reference_sphere_centers", |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                black_box(reference.sphere_centers(black_box(&qs[k]), &spheres).unwrap())
            })
        });
        group.bench_function("link_poses_and_hand_centers", |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                black_box(hand_centers(black_box(&qs[k])))
            })
        });
        group.bench_function("self_collides", |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                black_box(<$robot>::self_collides(black_box(&qs[k])))
            })
        });
        let mut centers64 = vec![[[0.0; 3]; S]; qs.len()];
        let mut centers32 = vec![[[0.0f32; 3]; S]; qs.len()];
        let mut verdicts = vec![false; qs.len()];
        group.throughput(Throughput::Elements(qs.len() as u64));
        group.bench_function("sphere_centers_batch", |b| {
            b.iter(|| <$robot>::sphere_centers_batch(black_box(&qs), &mut centers64).unwrap())
        });
        group.bench_function("sphere_centers_batch_f32", |b| {
            b.iter(|| <$robot>::sphere_centers_batch_f32(black_box(&qs32), &mut centers32).unwrap())
        });
        // The centres kept in lanes (what a check in lanes reads, and what VAMP's figure
        // measures): the generic form on sixteen `f32` configurations at a time, the loop
        // dispatched once.
        let packs: Vec<[F32x16; $n]> =
            qs32.chunks_exact(16).map(|pack| std::array::from_fn(|j| F32x16::from_fn(|i| pack[i][j]))).collect();
        group.throughput(Throughput::Elements(16 * packs.len() as u64));
        group.bench_function("sphere_centers_lanes_f32x16", |b| {
            b.iter(|| {
                kinematics::dispatch(
                    #[inline(always)]
                    || {
                        for q in &packs {
                            black_box(&<$robot>::sphere_centers_generic(black_box(q)));
                        }
                    },
                )
            })
        });
        // The link poses and the self check on the wide lanes (`F64x8` and `F32x16`, which
        // a user's own loop may take; their bodies are the ones most prone to run in scalar
        // pieces without block marks), the loop dispatched once.
        let packs64: Vec<[F64x8; $n]> =
            qs.chunks_exact(8).map(|pack| std::array::from_fn(|j| F64x8::from_fn(|i| pack[i][j]))).collect();
        macro_rules! wide {
            ($id:literal, $packs:expr, $lanes:literal, $f:ident) => {
                group.throughput(Throughput::Elements($lanes * $packs.len() as u64));
                group.bench_function($id, |b| {
                    b.iter(|| {
                        kinematics::dispatch(
                            #[inline(always)]
                            || {
                                for q in &$packs {
                                    black_box(&<$robot>::$f(black_box(q)));
                                }
                            },
                        )
                    })
                });
            };
        }
        wide!("link_poses_lanes_f64x8", packs64, 8, link_poses_generic);
        wide!("link_poses_lanes_f32x16", packs, 16, link_poses_generic);
        wide!("self_collides_lanes_f64x8", packs64, 8, self_collides_generic);
        wide!("self_collides_lanes_f32x16", packs, 16, self_collides_generic);
        group.throughput(Throughput::Elements(qs.len() as u64));
        group.bench_function("self_collides_batch", |b| {
            b.iter(|| <$robot>::self_collides_batch(black_box(&qs), &mut verdicts).unwrap())
        });
        group.bench_function("self_collides_batch_f32", |b| {
            b.iter(|| <$robot>::self_collides_batch_f32(black_box(&qs32), &mut verdicts).unwrap())
        });
        // The self check where no early exit helps: configurations free of self-collision.
        let self_free32: Vec<[f32; $n]> = qs32.iter().copied().filter(|q| !<$robot>::self_collides_f32(q)).collect();
        println!("{}: {} of {} configurations free of self-collision", $name, self_free32.len(), qs32.len());
        let mut self_free_verdicts = vec![false; self_free32.len()];
        group.throughput(Throughput::Elements(self_free32.len() as u64));
        group.bench_function("self_collides_batch_f32_self_free", |b| {
            b.iter(|| <$robot>::self_collides_batch_f32(black_box(&self_free32), &mut self_free_verdicts).unwrap())
        });
        group.finish();
    }};
}

/// The MotionBenchMaker-like scenes of `scenes/` (`mbm_*.toml`: a table to pick from and the
/// same from under, a box, bookshelves of three sizes, a cage), cluttered around the arm.
const CLUTTERED: [&str; 7] = [
    "mbm_table_pick",
    "mbm_table_under_pick",
    "mbm_box",
    "mbm_bookshelf_small",
    "mbm_bookshelf_tall",
    "mbm_bookshelf_thin",
    "mbm_cage",
];

/// The states per radian of joint-space distance motions are checked at: VAMP's planners' default.
const STATES_PER_RADIAN: f64 = 32.0;

/// Per cluttered scene, the three forms of the check in `f32` on 1,024 configurations drawn
/// within the limits, each figure per configuration: `shared_f32` (`collides_any_f32` on packs
/// of sixteen, one verdict per pack, the first hit on any lane ending it: what a planner's
/// validation of several states needs), `collides_batch_f32` (a verdict per configuration) and
/// `free_f32` (the batch on the configurations that are free, where nothing ends early), with
/// `free_self_f32` (their self check alone); and per
/// motion between consecutive free configurations at 32 states per radian, the yes/no check
/// (`motion_any_f32`) and the first collision (`motion_first_f32`).
macro_rules! cluttered {
    ($c:expr, $name:literal, $robot:ty, $n:literal) => {{
        let mut criterion: Option<&mut criterion::Criterion> = $c;
        let qs: Vec<[f64; $n]> = inputs(&<$robot>::JOINT_LIMITS);
        let qs32: Vec<[f32; $n]> = qs.iter().map(|q| q.map(|x| x as f32)).collect();
        let resolution = kinematics::collision::Resolution::StatesPerUnit(STATES_PER_RADIAN);
        for scene_name in CLUTTERED {
            let obstacles = scene(scene_name);
            let env: Environment<'_> = obstacles.environment().unwrap();
            let free32: Vec<[f32; $n]> = qs32.iter().copied().filter(|q| !<$robot>::collides_f32(q, &env)).collect();
            let motions32: Vec<([f32; $n], [f32; $n])> = free32.windows(2).take(256).map(|m| (m[0], m[1])).collect();
            let Some(c) = criterion.as_deref_mut() else {
                // Check mode: the shared verdict is the `any` of the configurations' own, and a
                // motion's yes/no is whether it has a first collision.
                let mut verdicts = vec![false; qs32.len()];
                <$robot>::collides_batch_f32(&qs32, &env, &mut verdicts).unwrap();
                for (chunk, own) in qs32.chunks(16).zip(verdicts.chunks(16)).take(8) {
                    assert_eq!(<$robot>::collides_any_f32(chunk, &env), own.iter().any(|&v| v), "{scene_name}");
                }
                for m in motions32.iter().take(4) {
                    let first = <$robot>::motion_collides_f32(&m.0, &m.1, &env, resolution).unwrap();
                    let any = <$robot>::motion_collides_any_f32(&m.0, &m.1, &env, resolution).unwrap();
                    assert_eq!(any, first.is_some(), "{scene_name}");
                }
                continue;
            };
            let colliding = motions32
                .iter()
                .filter(|m| <$robot>::motion_collides_any_f32(&m.0, &m.1, &env, resolution).unwrap())
                .count();
            println!(
                "{}: {} of {} configurations free in the {scene_name} scene; {colliding} of {} motions between \
                 free configurations collide",
                $name,
                free32.len(),
                qs32.len(),
                motions32.len()
            );
            let mut group = c.benchmark_group(format!("{}/{scene_name}", $name));
            group.throughput(Throughput::Elements(qs32.len() as u64));
            group.bench_function("shared_f32", |b| {
                b.iter(|| {
                    for pack in black_box(&qs32).chunks(16) {
                        black_box(<$robot>::collides_any_f32(pack, &env));
                    }
                })
            });
            let mut verdicts = vec![false; qs32.len()];
            group.bench_function("collides_batch_f32", |b| {
                b.iter(|| <$robot>::collides_batch_f32(black_box(&qs32), &env, &mut verdicts).unwrap())
            });
            let mut free_verdicts = vec![false; free32.len()];
            group.throughput(Throughput::Elements(free32.len() as u64));
            group.bench_function("free_f32", |b| {
                b.iter(|| <$robot>::collides_batch_f32(black_box(&free32), &env, &mut free_verdicts).unwrap())
            });
            // The same configurations' self check alone: what of `free_f32` the robot's own
            // pairs take (the rest is the obstacles' tests).
            group.bench_function("free_self_f32", |b| {
                b.iter(|| <$robot>::self_collides_batch_f32(black_box(&free32), &mut free_verdicts).unwrap())
            });
            group.throughput(Throughput::Elements(1));
            let mut k = 0;
            group.bench_function("motion_any_f32", |b| {
                b.iter(|| {
                    k = (k + 1) % motions32.len();
                    let m = black_box(&motions32[k]);
                    black_box(<$robot>::motion_collides_any_f32(&m.0, &m.1, &env, resolution).unwrap())
                })
            });
            group.bench_function("motion_first_f32", |b| {
                b.iter(|| {
                    k = (k + 1) % motions32.len();
                    let m = black_box(&motions32[k]);
                    black_box(<$robot>::motion_collides_f32(&m.0, &m.1, &env, resolution).unwrap())
                })
            });
            group.finish();
        }
    }};
}

fn cluttered(mut c: Option<&mut criterion::Criterion>) {
    cluttered!(c.as_deref_mut(), "panda", Panda, 7);
    cluttered!(c, "ur5", Ur5, 6);
}

fn panda(c: Option<&mut criterion::Criterion>) {
    robot!(c, "panda", Panda, 7, Some("robots/panda.srdf"))
}

fn ur5(c: Option<&mut criterion::Criterion>) {
    robot!(c, "ur5", Ur5, 6, Some("robots/ur5_spherized.srdf"))
}

/// `count` points on the surfaces of `boxes`, each face drawn by its area, from a seeded stream.
fn surface_points(boxes: &[BoxObstacle], count: usize) -> Vec<[f64; 3]> {
    // splitmix64, seeded: the same points on every run.
    let mut state = 7u64;
    let mut next = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    // Each face: its box, the axis it faces along and the side.
    let faces: Vec<(usize, usize, f64, f64)> = (0..boxes.len())
        .flat_map(|b| {
            let h = boxes[b].half_extents;
            (0..3).flat_map(move |axis| {
                let area = 4.0 * h[(axis + 1) % 3] * h[(axis + 2) % 3];
                [(b, axis, 1.0, area), (b, axis, -1.0, area)]
            })
        })
        .collect();
    let total: f64 = faces.iter().map(|f| f.3).sum();
    (0..count)
        .map(|_| {
            let mut pick = next() * total;
            let &(b, axis, side, _) = faces
                .iter()
                .find(|f| {
                    pick -= f.3;
                    pick <= 0.0
                })
                .unwrap_or(&faces[faces.len() - 1]);
            let o = &boxes[b];
            let local: [f64; 3] = std::array::from_fn(|i| {
                if i == axis { side * o.half_extents[i] } else { (2.0 * next() - 1.0) * o.half_extents[i] }
            });
            std::array::from_fn(|k| o.center[k] + (0..3).map(|i| local[i] * o.rotation[i][k]).sum::<f64>())
        })
        .collect()
}

/// The Panda against point clouds sampled on the tabletop scene's surfaces (10^3 to 10^6 points,
/// 5 mm each): the k-d tree's build and `collides` per configuration; and holding a bottle in the
/// tabletop scene.
fn clouds(mut criterion: Option<&mut criterion::Criterion>) {
    let qs: Vec<[f64; 7]> = inputs(&Panda::JOINT_LIMITS);
    let qs32: Vec<[f32; 7]> = qs.iter().map(|q| q.map(|x| x as f32)).collect();
    let tabletop = scene("tabletop");
    let bottle = [
        SphereObstacle { center: [0.0, 0.0, 0.02], radius: 0.04 },
        SphereObstacle { center: [0.0, 0.0, 0.1], radius: 0.04 },
    ];
    let held = Panda::hold("panda_grasptarget", &bottle, &[]).unwrap();
    let env = tabletop.environment().unwrap();
    let holding = env.holding(&held);
    for count in [1_000, 10_000, 100_000, 1_000_000] {
        let points = surface_points(&tabletop.boxes, count);
        let cloud = PointCloud::new(&points, 0.005).unwrap();
        let env = Environment::empty().with_query(&cloud);
        let Some(c) = criterion.as_deref_mut() else {
            // Check mode: the batch's verdicts are the one-configuration function's, and the
            // cloud's answers those of every point asked in turn.
            let mut verdicts = vec![false; 64];
            Panda::collides_batch(&qs[..64], &env, &mut verdicts).unwrap();
            for (q, v) in qs.iter().zip(&verdicts) {
                assert_eq!(*v, Panda::collides(q, &env));
            }
            for c in Panda::sphere_centers(&qs[0]).iter().take(8) {
                let brute =
                    points.iter().any(|p| (0..3).map(|i| (p[i] - c[i]).powi(2)).sum::<f64>() <= 0.105f64.powi(2));
                assert_eq!(brute, kinematics::collision::SphereQuery::touches(&cloud, *c, 0.1));
            }
            if count >= 100_000 {
                break; // the larger clouds' building is what the measurement is for
            }
            continue;
        };
        let free = qs.iter().filter(|q| !Panda::collides(q, &env)).count();
        println!("panda: {free} of {} configurations free against a cloud of {count} points", qs.len());
        let mut group = c.benchmark_group(format!("panda/cloud/{count}"));
        if count >= 100_000 {
            group.sample_size(10);
        }
        group.bench_function("build", |b| b.iter(|| PointCloud::new(black_box(&points), 0.005).unwrap()));
        let mut verdicts = vec![false; qs.len()];
        group.throughput(Throughput::Elements(qs.len() as u64));
        group.bench_function("collides_batch", |b| {
            b.iter(|| Panda::collides_batch(black_box(&qs), &env, &mut verdicts).unwrap())
        });
        group.bench_function("collides_batch_f32", |b| {
            b.iter(|| Panda::collides_batch_f32(black_box(&qs32), &env, &mut verdicts).unwrap())
        });
        group.finish();
    }
    let Some(c) = criterion else {
        let mut verdicts = vec![false; qs.len()];
        Panda::collides_batch(&qs, &holding, &mut verdicts).unwrap();
        for (q, v) in qs.iter().zip(&verdicts).take(64) {
            assert_eq!(*v, Panda::collides(q, &holding));
            assert!(*v || !Panda::collides(q, &env), "holding freed a configuration");
        }
        return;
    };
    let free = qs.iter().filter(|q| !Panda::collides(q, &holding)).count();
    println!("panda: {free} of {} configurations free holding a bottle in the tabletop scene", qs.len());
    let mut group = c.benchmark_group("panda/tabletop_holding");
    let mut verdicts = vec![false; qs.len()];
    group.throughput(Throughput::Elements(qs.len() as u64));
    group.bench_function("collides_batch", |b| {
        b.iter(|| Panda::collides_batch(black_box(&qs), &holding, &mut verdicts).unwrap())
    });
    group.bench_function("collides_batch_f32", |b| {
        b.iter(|| Panda::collides_batch_f32(black_box(&qs32), &holding, &mut verdicts).unwrap())
    });
    group.finish();
}

/// The Panda's tree with franka_description's collision meshes read, as the derive reads them
/// (from beside `robots/panda_meshes.urdf`).
fn read_meshes(mut tree: kinematics::model::KinematicTree) -> kinematics::model::KinematicTree {
    let urdf = Path::new(env!("CARGO_MANIFEST_DIR")).join("robots/panda_meshes.urdf");
    let packages = kinematics_meshes::Packages::default();
    kinematics_meshes::load_tree_meshes(&mut tree, &kinematics_meshes::Resolver::new(&urdf, &packages)).unwrap();
    tree
}

/// Spheres and self-check pairs of a cover: the spheres, the pairs of links checked against each
/// other (the SRDF's disabled pairs left out) and the pairs of spheres those hold.
fn self_pairs(tree: &kinematics::model::KinematicTree, spheres: &[kinematics::model::collision::LinkSphere]) -> String {
    let text = std::fs::read_to_string(format!("{}/robots/panda.srdf", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let disabled = kinematics::model::srdf::parse_srdf(&text).unwrap().disabled_pairs(tree).unwrap();
    let pairs = sphere_pairs(tree, spheres, Some(&disabled)).pairs;
    let on = |link| spheres.iter().filter(|s| s.link == link).count();
    let sphere_pairs: usize = pairs.iter().map(|&(a, b)| on(a) * on(b)).sum();
    let mut links: Vec<_> = spheres.iter().map(|s| s.link).collect();
    links.dedup();
    let per_link: Vec<String> = links.iter().map(|&l| format!("{} {}", tree.link(l).name, on(l))).collect();
    format!(
        "{} spheres ({}), {} pairs of links, {sphere_pairs} pairs of spheres",
        spheres.len(),
        per_link.join(", "),
        pairs.len()
    )
}

/// Issue 59's cover time: every link of the Panda from its meshes covered by the default cover
/// (`link_spheres`), the meshes read beforehand; and reading the meshes and covering together.
fn cover(criterion: Option<&mut criterion::Criterion>) {
    let unread = PandaMeshes::reference().unwrap().tree().clone();
    let tree = read_meshes(unread.clone());
    let Some(c) = criterion else {
        // Check mode: spheres, each finite, and the derive's own (the same links and radii).
        let spheres = link_spheres(&tree, &Cover::default(), Meshes::Read).unwrap();
        assert!(!spheres.is_empty());
        assert_eq!(spheres.len(), PandaMeshes::SPHERE_RADII.len());
        for (s, (radius, link)) in spheres.iter().zip(PandaMeshes::SPHERE_RADII.iter().zip(PandaMeshes::SPHERE_LINKS)) {
            assert!(
                s.sphere.center.iter().all(|x| x.is_finite()) && s.sphere.radius.is_finite() && s.sphere.radius > 0.0
            );
            assert_eq!((tree.link(s.link).name.as_str(), s.sphere.radius), (link, *radius));
        }
        return;
    };
    let mut group = c.benchmark_group("cover/panda_meshes");
    group.sample_size(10);
    group.bench_function("link_spheres", |b| {
        b.iter(|| link_spheres(black_box(&tree), &Cover::default(), Meshes::Read).unwrap())
    });
    group.bench_function("read_meshes_and_link_spheres", |b| {
        b.iter_batched(
            || unread.clone(),
            |unread| link_spheres(&read_meshes(unread), &Cover::default(), Meshes::Read).unwrap(),
            BatchSize::LargeInput,
        )
    });
    group.finish();
}

/// Issue 59's comparison: `collides` on the Panda from its meshes (the default cover) against the
/// spherized Panda's (VAMP's 59 spheres), in the tabletop and shelf scenes, on the same 1,024 arm
/// configurations (drawn within franka_description's limits, which lie within VAMP's), the
/// meshes Panda's fingers open (0.04 m): one configuration at a time on all of them, and on those
/// both robots find free (no early exit), one at a time and in an `f32` batch (and the batch's
/// self check alone); with the paired ratio (meshes / spherized) of each check, printed.
fn meshes_against_spheres(mut criterion: Option<&mut criterion::Criterion>) {
    assert_eq!(PandaMeshes::JOINT_NAMES[7], "panda_finger_joint1");
    let arm: Vec<[f64; 7]> = inputs(&PandaMeshes::JOINT_LIMITS[..7]);
    let open = PandaMeshes::JOINT_LIMITS[7].upper;
    let with_fingers = |q: &[f64; 7]| -> [f64; 8] { std::array::from_fn(|j| if j < 7 { q[j] } else { open }) };
    let meshes: Vec<[f64; 8]> = arm.iter().map(with_fingers).collect();
    if criterion.is_some() && common::selected("panda_meshes_vs_spherized") {
        let tree = read_meshes(PandaMeshes::reference().unwrap().tree().clone());
        let spheres = link_spheres(&tree, &Cover::default(), Meshes::Read).unwrap();
        println!("panda_meshes: {}", self_pairs(&tree, &spheres));
        let reference = Panda::reference().unwrap();
        let spheres = link_spheres(reference.tree(), &Cover::default(), Meshes::Read).unwrap();
        println!("panda (spherized): {}", self_pairs(reference.tree(), &spheres));
    }
    for scene_name in ["tabletop", "shelf"] {
        let obstacles = scene(scene_name);
        let env: Environment<'_> = obstacles.environment().unwrap();
        let hit_spheres: Vec<bool> = arm.iter().map(|q| Panda::collides(q, &env)).collect();
        let hit_meshes: Vec<bool> = meshes.iter().map(|q| PandaMeshes::collides(q, &env)).collect();
        let both_free: Vec<usize> = (0..arm.len()).filter(|&i| !hit_spheres[i] && !hit_meshes[i]).collect();
        let (arm_free, meshes_free): (Vec<[f64; 7]>, Vec<[f64; 8]>) =
            both_free.iter().map(|&i| (arm[i], meshes[i])).unzip();
        let arm_free32: Vec<[f32; 7]> = arm_free.iter().map(|q| q.map(|x| x as f32)).collect();
        let meshes_free32: Vec<[f32; 8]> = meshes_free.iter().map(|q| q.map(|x| x as f32)).collect();
        let Some(c) = criterion.as_deref_mut() else {
            // Check mode: the meshes Panda's batch agrees with its one-configuration check, each
            // robot finds some configurations free and some not, and both find some free.
            let mut verdicts = vec![false; meshes.len()];
            PandaMeshes::collides_batch(&meshes, &env, &mut verdicts).unwrap();
            assert_eq!(verdicts, hit_meshes, "panda_meshes in the {scene_name} scene");
            for hits in [&hit_spheres, &hit_meshes] {
                assert!(hits.iter().any(|&h| h) && hits.iter().any(|&h| !h), "{scene_name}");
            }
            assert!(!both_free.is_empty(), "{scene_name}");
            continue;
        };
        let count = |hits: &[bool]| hits.iter().filter(|&&h| !h).count();
        println!(
            "panda_meshes_vs_spherized/{scene_name}: free of {}: spherized {}, meshes {}, both {}",
            arm.len(),
            count(&hit_spheres),
            count(&hit_meshes),
            both_free.len()
        );
        let id = format!("panda_meshes_vs_spherized/{scene_name}");
        if common::selected(&id) {
            for (pair, inputs) in [("collides", arm.len()), ("collides_all_free", both_free.len())] {
                let pick = |i: usize| if pair == "collides" { i } else { both_free[i] };
                let ratio = common::paired_ratio(
                    201,
                    2000,
                    inputs,
                    |i| PandaMeshes::collides(&meshes[pick(i)], &env),
                    |i| Panda::collides(&arm[pick(i)], &env),
                );
                println!("{id}/{pair}: paired ratio meshes / spherized {ratio:.3} (median of 201 alternating rounds)");
            }
            let (mut ours, mut theirs) = (vec![false; both_free.len()], vec![false; both_free.len()]);
            let ratio = common::paired_ratio(
                201,
                2,
                1,
                |_| PandaMeshes::collides_batch_f32(&meshes_free32, &env, &mut ours).unwrap(),
                |_| Panda::collides_batch_f32(&arm_free32, &env, &mut theirs).unwrap(),
            );
            println!(
                "{id}/collides_all_free_batch_f32: paired ratio meshes / spherized {ratio:.3} (median of 201 alternating rounds)"
            );
        }
        let mut group = c.benchmark_group(id);
        let mut k = 0;
        group.bench_function("collides_spherized", |b| {
            b.iter(|| {
                k = (k + 1) % arm.len();
                black_box(Panda::collides(black_box(&arm[k]), &env))
            })
        });
        group.bench_function("collides_meshes", |b| {
            b.iter(|| {
                k = (k + 1) % meshes.len();
                black_box(PandaMeshes::collides(black_box(&meshes[k]), &env))
            })
        });
        group.bench_function("collides_all_free_spherized", |b| {
            b.iter(|| {
                k = (k + 1) % arm_free.len();
                black_box(Panda::collides(black_box(&arm_free[k]), &env))
            })
        });
        group.bench_function("collides_all_free_meshes", |b| {
            b.iter(|| {
                k = (k + 1) % meshes_free.len();
                black_box(PandaMeshes::collides(black_box(&meshes_free[k]), &env))
            })
        });
        let mut verdicts = vec![false; both_free.len()];
        group.throughput(Throughput::Elements(both_free.len() as u64));
        group.bench_function("collides_all_free_batch_f32_spherized", |b| {
            b.iter(|| Panda::collides_batch_f32(black_box(&arm_free32), &env, &mut verdicts).unwrap())
        });
        group.bench_function("collides_all_free_batch_f32_meshes", |b| {
            b.iter(|| PandaMeshes::collides_batch_f32(black_box(&meshes_free32), &env, &mut verdicts).unwrap())
        });
        // Their self checks alone: what of the batches the robots' own pairs take (the rest is
        // the obstacles' tests).
        group.bench_function("self_collides_all_free_batch_f32_spherized", |b| {
            b.iter(|| Panda::self_collides_batch_f32(black_box(&arm_free32), &mut verdicts).unwrap())
        });
        group.bench_function("self_collides_all_free_batch_f32_meshes", |b| {
            b.iter(|| PandaMeshes::self_collides_batch_f32(black_box(&meshes_free32), &mut verdicts).unwrap())
        });
        group.finish();
    }
}

fn main() {
    if common::measuring() {
        let mut c = common::criterion(Duration::from_millis(500), Duration::from_secs(2));
        panda(Some(&mut c));
        ur5(Some(&mut c));
        cluttered(Some(&mut c));
        clouds(Some(&mut c));
        cover(Some(&mut c));
        meshes_against_spheres(Some(&mut c));
        c.final_summary();
    } else {
        panda(None);
        ur5(None);
        cluttered(None);
        clouds(None);
        cover(None);
        meshes_against_spheres(None);
        println!("collision benchmarks: every body ran once and its answers were checked");
    }
}
