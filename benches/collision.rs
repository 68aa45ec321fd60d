//! Collision checking (issue 30): per configuration, the generated `sphere_centers` against the
//! runtime reference's, and `collides` in a tabletop scene of 12 boxes (mixed free and colliding
//! configurations, the fraction free printed) and on all-free configurations (no early exit),
//! and `self_collides`, on VAMP's spherized Panda and UR5. `cargo bench --bench collision`
//! measures; under `cargo test` every body runs once and its answers are checked.
#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[allow(dead_code)] // the helpers the fk and ik benchmarks use and this one does not
mod common;

use std::hint::black_box;
use std::time::Duration;

use kinematics::collision::{BoxObstacle, Environment};
use kinematics::model::collision::{Meshes, link_spheres};
use kinematics::{Configurations, Kinematics};

#[derive(Kinematics)]
#[kinematics(urdf = "robots/panda_spherized.urdf", collision(srdf = "robots/panda.srdf"), scalars(f64, f32))]
struct Panda;

#[derive(Kinematics)]
#[kinematics(urdf = "robots/ur5_spherized.urdf", collision, scalars(f64, f32))]
struct Ur5;

const IDENTITY: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

/// A table under the arm and eleven boxes on and around it (a tabletop scene of 12 boxes).
fn tabletop() -> Vec<BoxObstacle> {
    let mut boxes = vec![BoxObstacle::from_pose(IDENTITY, [0.6, 0.0, -0.05], [0.8, 1.4, 0.1])];
    for k in 0..11 {
        let (x, y) = (0.35 + 0.05 * f64::from(k % 4) * 2.0, -0.6 + 0.12 * f64::from(k));
        boxes.push(BoxObstacle::from_pose(IDENTITY, [x, y, 0.08], [0.06, 0.06, 0.16]));
    }
    boxes
}

/// 1,024 configurations of `N` joints within the limits.
fn inputs<const N: usize>(limits: &[kinematics::JointLimits]) -> Vec<[f64; N]> {
    Configurations::within(limits).skip(5).take(1024).map(|q| q.try_into().unwrap()).collect()
}

macro_rules! robot {
    ($c:expr, $name:literal, $robot:ty, $n:literal) => {{
        let qs: Vec<[f64; $n]> = inputs(&<$robot>::JOINT_LIMITS);
        let boxes = tabletop();
        let scene = Environment::new(&[], &[], &[], &boxes).unwrap();
        let free: Vec<[f64; $n]> = qs.iter().copied().filter(|q| !<$robot>::collides(q, &scene)).collect();
        let reference = <$robot>::reference().unwrap();
        let spheres = link_spheres(reference.tree(), 0.01, Meshes::Refuse).unwrap();
        let Some(c) = $c else {
            // Check mode: the centres against the reference's, the verdicts against a plain loop.
            let q = qs[0];
            let generated = <$robot>::sphere_centers(&q);
            for (g, r) in generated.iter().zip(reference.sphere_centers(&q, &spheres).unwrap()) {
                assert!((0..3).all(|i| (g[i] - r[i]).abs() < 1e-12), "{}", $name);
            }
            for q in &qs {
                let plain =
                    <$robot>::sphere_centers(q).iter().zip(<$robot>::SPHERE_RADII).any(|(c, r)| scene.hits(*c, r));
                assert_eq!(<$robot>::collides(q, &scene), plain, "{}", $name);
            }
            assert!(!free.is_empty() && free.len() < qs.len(), "{}: {} free of {}", $name, free.len(), qs.len());
            return;
        };
        println!("{}: {} of {} configurations free in the tabletop scene", $name, free.len(), qs.len());
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
        group.bench_function("collides_tabletop", |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                black_box(<$robot>::collides(black_box(&qs[k]), &scene))
            })
        });
        group.bench_function("collides_tabletop_all_free", |b| {
            b.iter(|| {
                k = (k + 1) % free.len();
                black_box(<$robot>::collides(black_box(&free[k]), &scene))
            })
        });
        group.bench_function("self_collides", |b| {
            b.iter(|| {
                k = (k + 1) % qs.len();
                black_box(<$robot>::self_collides(black_box(&qs[k])))
            })
        });
        // Batches: per configuration, each with its own verdict (criterion's throughput).
        let qs32: Vec<[f32; $n]> = qs.iter().map(|q| q.map(|x| x as f32)).collect();
        let free32: Vec<[f32; $n]> = free.iter().map(|q| q.map(|x| x as f32)).collect();
        let mut centers64 = vec![[[0.0; 3]; <$robot>::SPHERE_RADII.len()]; qs.len()];
        let mut centers32 = vec![[[0.0f32; 3]; <$robot>::SPHERE_RADII.len()]; qs.len()];
        let mut verdicts = vec![false; qs.len()];
        group.throughput(criterion::Throughput::Elements(qs.len() as u64));
        group.bench_function("sphere_centers_batch", |b| {
            b.iter(|| <$robot>::sphere_centers_batch(black_box(&qs), &mut centers64).unwrap())
        });
        group.bench_function("sphere_centers_batch_f32", |b| {
            b.iter(|| <$robot>::sphere_centers_batch_f32(black_box(&qs32), &mut centers32).unwrap())
        });
        group.bench_function("collides_tabletop_batch", |b| {
            b.iter(|| <$robot>::collides_batch(black_box(&qs), &scene, &mut verdicts).unwrap())
        });
        group.bench_function("collides_tabletop_batch_f32", |b| {
            b.iter(|| <$robot>::collides_batch_f32(black_box(&qs32), &scene, &mut verdicts).unwrap())
        });
        group.bench_function("self_collides_batch_f32", |b| {
            b.iter(|| <$robot>::self_collides_batch_f32(black_box(&qs32), &mut verdicts).unwrap())
        });
        group.throughput(criterion::Throughput::Elements(free.len() as u64));
        let mut free_verdicts = vec![false; free.len()];
        group.bench_function("collides_tabletop_all_free_batch", |b| {
            b.iter(|| <$robot>::collides_batch(black_box(&free), &scene, &mut free_verdicts).unwrap())
        });
        group.bench_function("collides_tabletop_all_free_batch_f32", |b| {
            b.iter(|| <$robot>::collides_batch_f32(black_box(&free32), &scene, &mut free_verdicts).unwrap())
        });
        group.finish();
    }};
}

fn panda(c: Option<&mut criterion::Criterion>) {
    robot!(c, "panda", Panda, 7)
}

fn ur5(c: Option<&mut criterion::Criterion>) {
    robot!(c, "ur5", Ur5, 6)
}

fn main() {
    if common::measuring() {
        let mut c = common::criterion(Duration::from_millis(500), Duration::from_secs(2));
        panda(Some(&mut c));
        ur5(Some(&mut c));
        c.final_summary();
    } else {
        panda(None);
        ur5(None);
        println!("collision benchmarks: every body ran once and its answers were checked");
    }
}
