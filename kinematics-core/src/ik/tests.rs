//! Round trips of every family on random arms built to it: random axes (with the family's
//! parallel and intersecting pairs), random offsets and tool rotations, random configurations.

use super::vector::{V3, add, cross, norm_squared, scale, wrap};
use super::*;
use crate::lanes::{F64x8, Lanes};

/// A small deterministic generator (xorshift64*), so the core needs no dev-dependency for this.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
        bits as f64 / (1u64 << 53) as f64
    }

    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    fn vector(&mut self, size: f64) -> V3 {
        [0, 1, 2].map(|_| self.uniform(-size, size))
    }

    fn unit(&mut self) -> V3 {
        loop {
            let v = self.vector(1.0);
            let n = norm_squared(v);
            if n > 0.01 && n <= 1.0 {
                return scale(v, 1.0 / libm::sqrt(n));
            }
        }
    }

    fn sign(&mut self) -> f64 {
        if self.next() < 0.5 { -1.0 } else { 1.0 }
    }

    fn rotation(&mut self) -> [[f64; 3]; 3] {
        let x = self.unit();
        let y = loop {
            let v = self.unit();
            let across = cross(x, v);
            if norm_squared(across) > 0.1 {
                break scale(across, 1.0 / libm::sqrt(norm_squared(across)));
            }
        };
        let z = cross(x, y);
        // Columns x, y, z.
        [[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]
    }
}

#[derive(Debug, Clone, Copy)]
enum Family {
    SphericalTwoParallel,
    SphericalFirstTwoIntersecting,
    SphericalLastTwoIntersecting,
    ThreeParallelTwoIntersecting,
    Spherical,
    ThreeParallel,
}

impl Family {
    const ALL: [Family; 6] = [
        Family::SphericalTwoParallel,
        Family::SphericalFirstTwoIntersecting,
        Family::SphericalLastTwoIntersecting,
        Family::ThreeParallelTwoIntersecting,
        Family::Spherical,
        Family::ThreeParallel,
    ];

    /// Whether the family's first step is a quartic (subproblem 5 or 6), whose number of real
    /// roots depends on the target: two, four, six or eight solutions, not always eight.
    fn quartic(self) -> bool {
        matches!(self, Family::Spherical | Family::ThreeParallel)
    }
}

fn random_arm(rng: &mut Rng, family: Family) -> Arm6 {
    let mut axes = [0; 6].map(|_| rng.unit());
    let mut offsets = [0; 7].map(|_| rng.vector(0.5));
    match family {
        Family::SphericalTwoParallel => axes[2] = scale(axes[1], rng.sign()),
        Family::SphericalFirstTwoIntersecting => offsets[1] = [0.0; 3],
        Family::SphericalLastTwoIntersecting => offsets[2] = [0.0; 3],
        Family::ThreeParallelTwoIntersecting => {
            axes[2] = scale(axes[1], rng.sign());
            axes[3] = scale(axes[1], rng.sign());
            offsets[5] = [0.0; 3];
        }
        Family::ThreeParallel => {
            axes[2] = scale(axes[1], rng.sign());
            axes[3] = scale(axes[1], rng.sign());
        }
        Family::Spherical => {}
    }
    if !matches!(family, Family::ThreeParallelTwoIntersecting | Family::ThreeParallel) {
        offsets[4] = [0.0; 3];
        offsets[5] = [0.0; 3];
    }
    Arm6 { axes, offsets, tool_rotation: rng.rotation() }
}

fn solve(family: Family, arm: &Arm6, target: &Pose<f64>) -> IkSolutions<6, 8> {
    match family {
        Family::SphericalTwoParallel => spherical_two_parallel(arm, target),
        Family::SphericalFirstTwoIntersecting => spherical_first_two_intersecting(arm, target),
        Family::SphericalLastTwoIntersecting => spherical_last_two_intersecting(arm, target),
        Family::ThreeParallelTwoIntersecting => three_parallel_two_intersecting(arm, target),
        Family::Spherical => spherical(arm, target),
        Family::ThreeParallel => three_parallel(arm, target),
    }
}

/// A solution's larger error, NaN counted as infinitely far (`f64::max` would drop it).
fn error_of(s: &IkSolution<6>) -> f64 {
    if s.position_error.is_nan() || s.rotation_error.is_nan() {
        return f64::INFINITY;
    }
    s.position_error.max(s.rotation_error)
}

/// The largest difference of two configurations' angles, modulo 2 pi; a NaN angle counts as
/// infinitely far.
fn angle_distance(a: &[f64; 6], b: &[f64; 6]) -> f64 {
    let mut largest = 0.0;
    for (x, y) in a.iter().zip(b) {
        let d = wrap(x - y).abs();
        if d.is_nan() {
            return f64::INFINITY;
        }
        if d > largest {
            largest = d;
        }
    }
    largest
}

#[test]
fn every_family_round_trips_on_random_arms() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for family in Family::ALL {
        let mut worst_error: f64 = 0.0;
        let mut worst_match: f64 = 0.0;
        for _ in 0..40 {
            let arm = random_arm(&mut rng, family);
            for _ in 0..50 {
                let q = [0; 6].map(|_| rng.uniform(-3.1, 3.1));
                let target = arm.pose(&q);
                let mut solutions = solve(family, &arm, &target);
                solutions.measure(&target, |q| arm.pose(q));
                if family.quartic() {
                    assert!(solutions.len() >= 2 && solutions.len().is_multiple_of(2), "{family:?}: {solutions:?}");
                } else {
                    assert_eq!(solutions.len(), 8);
                }
                let nearest = solutions.iter().map(|s| angle_distance(&s.q, &q)).fold(f64::INFINITY, f64::min);
                let solution = solutions.iter().find(|s| angle_distance(&s.q, &q) == nearest);
                assert!(solution.is_some_and(|s| s.exact), "{family:?}: q {q:?} not among {solutions:?}");
                worst_match = worst_match.max(nearest);
                for s in solutions.exact() {
                    let error = error_of(s);
                    assert!(error.is_finite(), "{family:?}: {s:?}");
                    worst_error = worst_error.max(error);
                }
            }
        }
        assert!(worst_error < 1e-11, "{family:?}: worst pose error {worst_error:e}");
        assert!(worst_match < 1e-6, "{family:?}: worst distance to q {worst_match:e}");
    }
}

/// Every solver fits a small thread's stack in an unoptimised build too: inlined whole on `F64x8`
/// lanes, a family took about 3 MB there (the branch module forces inlining only in an optimised
/// build); now each takes under 128 KB. 256 KB is an eighth of a test thread's stack. (An overflow
/// aborts the test run.)
#[test]
fn every_solver_fits_a_small_stack() {
    let solved = std::thread::Builder::new()
        .stack_size(256 * 1024)
        .spawn(|| {
            let mut rng = Rng(5);
            let mut count = 0;
            for family in Family::ALL {
                let arm = random_arm(&mut rng, family);
                let target = arm.pose(&[0.3, -0.4, 0.9, 0.2, 0.5, -0.1]);
                count += solve(family, &arm, &target).exact().count();
            }
            count
        })
        .expect("a thread")
        .join()
        .expect("the solvers return");
    assert!(solved >= Family::ALL.len(), "{solved} exact solutions");
}

#[test]
fn unreachable_targets_come_back_flagged_and_finite() {
    let mut rng = Rng(7);
    for family in Family::ALL {
        let arm = random_arm(&mut rng, family);
        let mut target = arm.pose(&[0.1; 6]);
        target.translation = [100.0, -50.0, 20.0];
        let solutions = solve(family, &arm, &target);
        assert!(!solutions.is_empty(), "{family:?}");
        if !family.quartic() {
            assert_eq!(solutions.len(), 8);
        }
        assert!(solutions.iter().all(|s| !s.exact && s.q.iter().all(|x| x.is_finite())), "{family:?}: {solutions:?}");
    }
}

/// A random arm of the family with an orthogonal wrist (h5 square to h4) whose
/// `h6 = rot(h5, theta) h4`, and the angle of joint 5 at its wrist singularity: at `q5 = -theta`,
/// `R5 h6 = h4`. (Oblique wrists solve q5 by a general subproblem 4, whose double root at the
/// singularity costs up to `DOUBLE_ROOT`'s 1e-7 rad, as documented there.)
fn with_singular_wrist(rng: &mut Rng, family: Family) -> (Arm6, f64) {
    let mut arm = random_arm(rng, family);
    let theta = rng.uniform(-3.1, 3.1);
    let h4 = arm.axes[3];
    let across = cross(h4, rng.unit());
    arm.axes[4] = scale(across, 1.0 / libm::sqrt(norm_squared(across)));
    arm.axes[5] = super::vector::rotate(arm.axes[4], theta, h4);
    (arm, -theta)
}

/// At a wrist singularity (axis 6 turned in line with axis 4, so joints 4 and 6 turn about the
/// same axis and only a sum is fixed) every family returns branches flagged singular, and a pose
/// the arm reaches is reached: some exact branch has it to rounding. For the families with axes
/// 2, 3, 4 parallel the choice of representative decides that (the sum of the parallel joints
/// moves the wrist's offset, and `q6 = 0` can leave the elbow out of reach), so every family is
/// tried on random arms, each at its own singular angle of joint 5, from many configurations.
#[test]
fn a_wrist_singularity_gives_representatives_that_reach_the_pose() {
    let mut rng = Rng(11);
    for family in Family::ALL {
        let mut singular = 0;
        for _ in 0..40 {
            let (arm, singular_q5) = with_singular_wrist(&mut rng, family);
            for _ in 0..25 {
                let mut q = [0; 6].map(|_| rng.uniform(-3.1, 3.1));
                q[4] = singular_q5;
                let target = arm.pose(&q);
                let mut solutions = solve(family, &arm, &target);
                solutions.measure(&target, |q| arm.pose(q));
                singular += solutions.iter().filter(|s| s.singular).count();
                let best = solutions.exact().map(error_of).fold(f64::INFINITY, f64::min);
                // The three-parallel arm's quartic has a double root here: a tangency, which its
                // roots count (within the rounding of the terms its coefficients came from).
                for s in solutions.exact().filter(|s| s.singular) {
                    assert!(error_of(s) < 1e-10, "{family:?}: q {q:?}: {s:?}");
                }
                assert!(best < 1e-10, "{family:?}: q {q:?}: no exact solution reaches the pose: {solutions:#?}");
            }
        }
        assert!(singular > 0, "{family:?}: no branch flagged singular");
    }
}

/// Near the wrist singularity (joint 5 within 1e-4 to 1e-8 rad of it) an orthogonal wrist keeps its
/// digits: the UR family's `q5` on the great circle, as the spherical wrists', so every exact
/// solution reaches the pose within 1e-12 (the general form of subproblem 4 lost them: errors grew
/// as 1e-16 over the distance, 4e-10 rad at 1e-6 on the UR5) and the configuration is among them;
/// within `DEGENERATE` (1e-10, 1e-12) the branch is the singular representative, off by about the
/// distance. (`q4` and `q6` apart are found as well as the distance lets them be.)
#[test]
fn near_a_wrist_singularity_orthogonal_wrists_keep_their_digits() {
    let mut rng = Rng(13);
    for family in [Family::ThreeParallelTwoIntersecting, Family::SphericalTwoParallel] {
        let mut worst: f64 = 0.0;
        for _ in 0..40 {
            let (arm, singular_q5) = with_singular_wrist(&mut rng, family);
            for distance in [1e-4, 1e-6, 1e-8, 1e-10, 1e-12] {
                let mut q = [0; 6].map(|_| rng.uniform(-3.1, 3.1));
                q[4] = singular_q5 + rng.sign() * distance;
                let target = arm.pose(&q);
                let mut solutions = solve(family, &arm, &target);
                solutions.measure(&target, |q| arm.pose(q));
                // Within `DEGENERATE` of the singularity the branch is its representative, whose
                // pose is off by about the distance (`q5` taken as at the singularity).
                let bound = if distance > 1e-9 { 1e-12 } else { 4.0 * distance };
                for s in solutions.exact() {
                    let error = error_of(s) / bound;
                    assert!(error <= 1.0, "{family:?}: q {q:?}: {s:?} (bound {bound:e})");
                    worst = worst.max(error);
                }
                if distance > 1e-8 {
                    // At `distance` from the singularity the pose fixes `q4` and `q6` apart only to
                    // the arm's own error over the distance: the arm's angles are known to about
                    // 1e-11 where its elbow is near its double root (one of these arms, its two
                    // elbows 0.0017 rad apart, misses by 4.3e-6 at 1e-6 rad), the others to 1e-6.
                    let wrist = 1e-6 + 1e-10 / distance;
                    let found = solutions.exact().any(|s| {
                        (0..6).all(|j| {
                            let bound = if j == 3 || j == 5 { wrist } else { 1e-6 };
                            wrap(s.q[j] - q[j]).abs() < bound
                        })
                    });
                    assert!(found, "{family:?}: {q:?} not among {solutions:?}");
                }
            }
        }
        assert!(worst <= 1.0, "{family:?}: worst pose error near the singularity {worst:e} of its bound");
    }
}

/// The three-parallel arm whose wrist axes do not meet finds `q1` and `q5` together from a quartic,
/// whose two roots near the wrist's singularity (the two wrist flips) are about the distance apart:
/// their digits, and `q6`'s (fixed by a cross product of about that size), go as the distance
/// shrinks. Stated in the guide: from 1e-3 rad of the singularity every target has an exact
/// solution within 1e-10 of it and the configuration among them; nearer, some do not (at 1e-5 rad,
/// 47 of 400 in a run of this test's arms at that distance).
#[test]
fn the_three_parallel_quartic_keeps_its_digits_from_a_thousandth_of_a_radian() {
    let mut rng = Rng(17);
    for _ in 0..100 {
        let (arm, singular_q5) = with_singular_wrist(&mut rng, Family::ThreeParallel);
        for distance in [1e-1, 1e-2, 1e-3] {
            let mut q = [0; 6].map(|_| rng.uniform(-3.1, 3.1));
            q[4] = singular_q5 + rng.sign() * distance;
            let target = arm.pose(&q);
            let mut solutions = solve(Family::ThreeParallel, &arm, &target);
            solutions.measure(&target, |q| arm.pose(q));
            let best = solutions.exact().map(error_of).fold(f64::INFINITY, f64::min);
            assert!(best < 1e-10, "{distance:e} from the singularity: q {q:?}: {solutions:#?}");
            let found = solutions.exact().any(|s| error_of(s) < 1e-10 && angle_distance(&s.q, &q) < 1e-6);
            assert!(found, "{distance:e} from the singularity: {q:?} not among {solutions:#?}");
        }
    }
}

/// A random planar arm: revolute joints about +-h through random points, a prismatic joint along
/// h where `slide` says.
fn random_planar<const N: usize>(rng: &mut Rng, slide: Option<usize>) -> PlanarArm<N> {
    let h = rng.unit();
    let joints = core::array::from_fn(|i| {
        if Some(i) == slide {
            PlanarJoint::Prismatic { sign: rng.sign() }
        } else {
            PlanarJoint::Revolute { sign: rng.sign(), point: rng.vector(0.6) }
        }
    });
    PlanarArm { axis: h, joints, tip_point: rng.vector(0.6), tool_rotation: rng.rotation() }
}

fn planar_round_trip<const N: usize>(rng: &mut Rng, slide: Option<usize>) {
    for _ in 0..40 {
        let arm: PlanarArm<N> = random_planar(rng, slide);
        for _ in 0..50 {
            let q: [f64; N] =
                core::array::from_fn(
                    |i| if Some(i) == slide { rng.uniform(-0.3, 0.3) } else { rng.uniform(-3.1, 3.1) },
                );
            let target = arm.pose(&q);
            let mut solutions = arm.solve(&target);
            solutions.measure(&target, |q| arm.pose(q));
            assert_eq!(solutions.len(), 2);
            let matched = solutions.exact().any(|s| s.q.iter().zip(&q).all(|(a, b)| wrap(a - b).abs() < 1e-7));
            assert!(matched, "{q:?} not among {solutions:?}");
            // Two joints place the point: the rotation about h follows, not asked.
            for s in solutions.exact() {
                assert!(s.position_error < 1e-12, "{s:?}");
                if N > 2 {
                    assert!(s.rotation_error < 1e-12, "{s:?}");
                }
            }
        }
    }
}

#[test]
fn planar_arms_and_the_scara_round_trip() {
    let mut rng = Rng(31);
    planar_round_trip::<2>(&mut rng, None);
    planar_round_trip::<3>(&mut rng, None);
    planar_round_trip::<4>(&mut rng, Some(2));
}

#[test]
fn planar_targets_off_the_plane_are_least_squares() {
    let mut rng = Rng(41);
    let arm: PlanarArm<3> = random_planar(&mut rng, None);
    let mut target = arm.pose(&[0.3, -0.5, 1.0]);
    // Raised along the axis: an arm without a prismatic joint cannot follow.
    target.translation = add(target.translation, scale(arm.axis, 0.1));
    assert!(arm.solve(&target).iter().all(|s| !s.exact));
    // Tilted off the axis: no turn about it gives that rotation.
    let mut tilted = arm.pose(&[0.3, -0.5, 1.0]);
    let across = cross(arm.axis, [1.0, 0.0, 0.0]);
    let k = scale(across, 1.0 / libm::sqrt(norm_squared(across)));
    let columns = [0, 1, 2]
        .map(|j| super::vector::rotate(k, 0.2, [tilted.rotation[0][j], tilted.rotation[1][j], tilted.rotation[2][j]]));
    tilted.rotation = [0, 1, 2].map(|r| [columns[0][r], columns[1][r], columns[2][r]]);
    assert!(arm.solve(&tilted).iter().all(|s| !s.exact && s.q.iter().all(|x| x.is_finite())));
}

/// The pose of an arm whose third joint slides along `h3` (the Stanford arm's form).
fn stanford_pose(arm: &Arm6, q: &[f64; 6]) -> Pose<f64> {
    let mut rotation = arm.tool_rotation;
    let mut point = arm.offsets[6];
    for i in (0..6).rev() {
        if i == 2 {
            point = add(arm.offsets[2], add(scale(arm.axes[2], q[2]), point));
            continue;
        }
        let columns = [0, 1, 2]
            .map(|j| super::vector::rotate(arm.axes[i], q[i], [rotation[0][j], rotation[1][j], rotation[2][j]]));
        rotation = [0, 1, 2].map(|r| [columns[0][r], columns[1][r], columns[2][r]]);
        point = add(arm.offsets[i], super::vector::rotate(arm.axes[i], q[i], point));
    }
    Pose { rotation, translation: point }
}

#[test]
fn stanford_arms_round_trip() {
    let mut rng = Rng(53);
    let mut worst: f64 = 0.0;
    for _ in 0..40 {
        let mut arm = random_arm(&mut rng, Family::SphericalFirstTwoIntersecting);
        arm.offsets[3] = rng.vector(0.3);
        for _ in 0..50 {
            let mut q = [0; 6].map(|_| rng.uniform(-3.1, 3.1));
            q[2] = rng.uniform(0.2, 1.0);
            let target = stanford_pose(&arm, &q);
            let mut solutions = spherical_prismatic_third(&arm, &target);
            solutions.measure(&target, |q| stanford_pose(&arm, q));
            assert_eq!(solutions.len(), 8);
            let found = solutions.exact().any(|s| {
                (s.q[2] - q[2]).abs() < 1e-7
                    && s.q.iter().zip(&q).enumerate().all(|(i, (a, b))| i == 2 || wrap(a - b).abs() < 1e-7)
            });
            assert!(found, "{q:?} not among {solutions:?}");
            for s in solutions.exact() {
                worst = worst.max(s.position_error).max(s.rotation_error);
            }
        }
    }
    assert!(worst < 1e-11, "worst pose error {worst:e}");
}

/// The central difference of `arm`'s pose in joint `j` (step `h`): the tip's linear velocity and
/// the angular velocity (the vee of `dR R^T`).
fn differentiated(arm: &Arm6, q: &[f64; 6], j: usize, h: f64) -> [f64; 6] {
    let (mut plus, mut minus) = (*q, *q);
    plus[j] += h;
    minus[j] -= h;
    let (a, b, at) = (arm.pose(&plus), arm.pose(&minus), arm.pose(q));
    let d = |r: usize, c: usize| (a.rotation[r][c] - b.rotation[r][c]) / (2.0 * h);
    let w = |r: usize, c: usize| (0..3).map(|k| d(r, k) * at.rotation[c][k]).sum::<f64>();
    let v = |k: usize| (a.translation[k] - b.translation[k]) / (2.0 * h);
    [v(0), v(1), v(2), w(2, 1), w(0, 2), w(1, 0)]
}

/// `Arm6::pose_and_jacobian` is `Arm6::pose` (to rounding: the two fold in opposite orders) and
/// its derivative (central differences, to 1e-7).
#[test]
#[allow(clippy::needless_range_loop, reason = "a matrix's rows and columns, by index")]
fn the_arm_jacobian_is_the_derivative_of_its_pose() {
    let mut rng = Rng(29);
    for family in [Family::SphericalTwoParallel, Family::ThreeParallelTwoIntersecting, Family::ThreeParallel] {
        for _ in 0..20 {
            let (arm, _) = with_singular_wrist(&mut rng, family);
            let q = [0; 6].map(|_| rng.uniform(-3.1, 3.1));
            let (pose, jacobian) = arm.pose_and_jacobian(&q);
            let expected = arm.pose(&q);
            let (position, rotation) = pose_errors(&pose, &expected);
            assert!(position < 1e-13 && rotation < 1e-13, "{family:?}: {position:e} {rotation:e}");
            for j in 0..6 {
                let column = differentiated(&arm, &q, j, 1e-6);
                for k in 0..6 {
                    assert!(
                        (jacobian[k][j] - column[k]).abs() < 1e-7,
                        "{family:?} ({k}, {j}): {} against {}",
                        jacobian[k][j],
                        column[k]
                    );
                }
            }
        }
    }
}

/// Refined on the arm's pose and Jacobian (`IkSolutions::refined`), the three-parallel quartic's
/// solutions near the singularity get their digits back: at 1e-2 and 1e-3 rad every target has an
/// exact solution within 1e-13 (before: 351 and 232 of 400 in this run), and the configuration is
/// among those within 1e-13 for all at 1e-2 and 399 of 400 at 1e-3 (before: 283 and 49); at 1e-4
/// rad 398 and 394 (before: 206 and 2). Stated in the guide.
#[test]
fn the_three_parallel_quartic_refined_keeps_its_digits() {
    let arm_of = RefineArm { reach: 1.0, moving: [true; 6], revolute: [true; 6] };
    for (distance, least_found) in [(1e-2, 400), (1e-3, 399), (1e-4, 394)] {
        let mut rng = Rng(17);
        let (mut reached, mut found) = (0, 0);
        for _ in 0..400 {
            let (arm, singular_q5) = with_singular_wrist(&mut rng, Family::ThreeParallel);
            let mut q = [0; 6].map(|_| rng.uniform(-3.1, 3.1));
            q[4] = singular_q5 + rng.sign() * distance;
            let target = arm.pose(&q);
            let mut solutions = solve(Family::ThreeParallel, &arm, &target);
            solutions.measure(&target, |q| arm.pose(q));
            let solutions = solutions.refined(&target, &arm_of, arm_in_lanes(&arm));
            reached += usize::from(solutions.exact().any(|s| error_of(s) < 1e-13));
            found += usize::from(solutions.exact().any(|s| error_of(s) < 1e-13 && angle_distance(&s.q, &q) < 1e-6));
        }
        let least_reached = if distance > 1e-4 { 400 } else { 398 };
        assert!(reached >= least_reached, "{distance:e} rad from the singularity: {reached} of 400 reached to 1e-13");
        assert!(
            found >= least_found,
            "{distance:e} rad from the singularity: the configuration found for {found} of 400"
        );
    }
}

/// `arm`'s pose and Jacobian on eight lanes of configurations (each lane by
/// `Arm6::pose_and_jacobian`), as the refinement takes a generated one.
pub(super) fn arm_in_lanes(arm: &Arm6) -> impl Fn(&[F64x8; 6]) -> (Pose<F64x8>, [[F64x8; 6]; 6]) + '_ {
    move |q| {
        let each: [(Pose<f64>, [[f64; 6]; 6]); 8] =
            core::array::from_fn(|k| arm.pose_and_jacobian(&q.map(|x| x.lane(k))));
        let lanes = |f: &dyn Fn(usize) -> f64| F64x8::from_fn(f);
        let rotation = core::array::from_fn(|r| core::array::from_fn(|c| lanes(&|k| each[k].0.rotation[r][c])));
        let translation = core::array::from_fn(|r| lanes(&|k| each[k].0.translation[r]));
        let jacobian = core::array::from_fn(|r| core::array::from_fn(|c| lanes(&|k| each[k].1[r][c])));
        (Pose { rotation, translation }, jacobian)
    }
}
