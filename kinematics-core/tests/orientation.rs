//! The orientation forms of a `Pose`: round trips on many rotations, hand-worked cases, the
//! singular cases (gimbal lock exactly and within 1e-9 of it, ZYZ at 0 and pi, half turns, tiny
//! angles), `f32`, refused inputs, and agreement with nalgebra's own conversions.
#![allow(clippy::panic, clippy::unwrap_used, clippy::expect_used)] // test helpers fail loudly

use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI};

use kinematics_core::{OrientationError, Pose};

/// Deterministic values in [-1, 1).
struct Values(u64);

impl Values {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// Rotations from random quaternions, plus every quarter and half turn about the axes.
fn rotations() -> Vec<Pose<f64>> {
    let mut values = Values(0x0123_4567_89ab_cdef);
    let mut out: Vec<Pose<f64>> = (0..5000)
        .map(|_| {
            let q = [values.next(), values.next(), values.next(), values.next()];
            Pose::from_quaternion_wxyz(q, [0.0; 3]).unwrap()
        })
        .collect();
    for angle in [FRAC_PI_2, PI, -FRAC_PI_2] {
        for axis in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 0.0], [1.0, -2.0, 3.0]] {
            out.push(Pose::from_axis_angle(axis, angle, [0.0; 3]).unwrap());
        }
    }
    out
}

/// The largest entrywise difference of two rotations; infinite if either has a value that is not
/// finite.
fn difference(a: &Pose<f64>, b: &Pose<f64>) -> f64 {
    let mut worst = 0.0f64;
    for (x, y) in a.rotation.iter().flatten().zip(b.rotation.iter().flatten()) {
        if !(x.is_finite() && y.is_finite()) {
            return f64::INFINITY;
        }
        worst = worst.max((x - y).abs());
    }
    worst
}

const TOLERANCE: f64 = 1e-14;

#[test]
fn every_form_gives_back_its_rotation() {
    for pose in rotations() {
        let [w, x, y, z] = pose.quaternion_wxyz();
        assert!(w >= 0.0 && ((w * w + x * x + y * y + z * z) - 1.0).abs() < 1e-15, "{:?}", [w, x, y, z]);
        let back = Pose::from_quaternion_wxyz([w, x, y, z], [0.0; 3]).unwrap();
        assert!(difference(&back, &pose) < TOLERANCE, "quaternion {pose:?}");
        let xyzw = Pose::from_quaternion_xyzw(pose.quaternion_xyzw(), [0.0; 3]).unwrap();
        assert!(difference(&xyzw, &pose) < TOLERANCE, "xyzw {pose:?}");
        let rpy = pose.rpy();
        assert!(rpy[1].abs() <= FRAC_PI_2 && rpy[0].abs() <= PI && rpy[2].abs() <= PI, "{rpy:?}");
        assert!(difference(&Pose::from_rpy(rpy, [0.0; 3]), &pose) < TOLERANCE, "rpy {rpy:?} of {pose:?}");
        let zyz = pose.euler_zyz();
        assert!((0.0..=PI).contains(&zyz[1]), "{zyz:?}");
        assert!(difference(&Pose::from_euler_zyz(zyz, [0.0; 3]), &pose) < TOLERANCE, "zyz {zyz:?} of {pose:?}");
        let (axis, angle) = pose.axis_angle();
        assert!((0.0..=PI).contains(&angle) && (axis.iter().map(|a| a * a).sum::<f64>() - 1.0).abs() < 1e-15);
        let from_axis = Pose::from_axis_angle(axis, angle, [0.0; 3]).unwrap();
        assert!(difference(&from_axis, &pose) < TOLERANCE, "axis-angle {axis:?} {angle} of {pose:?}");
        let from_vector = Pose::from_rotation_vector(pose.rotation_vector(), [0.0; 3]).unwrap();
        assert!(difference(&from_vector, &pose) < TOLERANCE, "rotation vector of {pose:?}");
    }
}

#[test]
fn angles_give_back_themselves_away_from_the_singular_cases() {
    let mut values = Values(42);
    for _ in 0..2000 {
        let rpy = [PI * values.next(), 1.5 * values.next(), PI * values.next()];
        let got = Pose::from_rpy(rpy, [0.0; 3]).rpy();
        assert!(rpy.iter().zip(got).all(|(a, b)| (a - b).abs() < 1e-13), "{rpy:?} -> {got:?}");
        let zyz = [PI * values.next(), 0.05 + 3.0 * (values.next() + 1.0) / 2.0, PI * values.next()];
        let got = Pose::from_euler_zyz(zyz, [0.0; 3]).euler_zyz();
        assert!(zyz.iter().zip(got).all(|(a, b)| (a - b).abs() < 1e-13), "{zyz:?} -> {got:?}");
    }
}

#[test]
fn hand_worked_cases() {
    let h = FRAC_1_SQRT_2;
    let identity = Pose { rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], translation: [0.0; 3] };
    assert_eq!(identity.quaternion_wxyz(), [1.0, 0.0, 0.0, 0.0]);
    assert_eq!(identity.rpy(), [0.0, 0.0, 0.0]);
    assert_eq!(identity.axis_angle(), ([1.0, 0.0, 0.0], 0.0));
    assert_eq!(identity.rotation_vector(), [0.0, 0.0, 0.0]);
    // A quarter turn about z: x to y.
    let z90 = Pose { rotation: [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], translation: [0.0; 3] };
    let q = z90.quaternion_wxyz();
    assert!((q[0] - h).abs() < 1e-15 && q[1] == 0.0 && q[2] == 0.0 && (q[3] - h).abs() < 1e-15, "{q:?}");
    assert!((z90.rpy()[2] - FRAC_PI_2).abs() < 1e-16);
    let (axis, angle) = z90.axis_angle();
    assert!(axis == [0.0, 0.0, 1.0] && (angle - FRAC_PI_2).abs() < 1e-15);
    // Quarter turns about x and y.
    let x90 = Pose { rotation: [[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]], translation: [0.0; 3] };
    assert!((x90.rpy()[0] - FRAC_PI_2).abs() < 1e-16 && x90.axis_angle().0 == [1.0, 0.0, 0.0]);
    let y90 = Pose { rotation: [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]], translation: [0.0; 3] };
    assert_eq!(y90.axis_angle().0, [0.0, 1.0, 0.0]);
    // Half turns about x, y, z and about (1, 1, 0)/sqrt 2: w = 0, the axis exact, its first
    // non-zero component positive.
    for (axis, matrix) in [
        ([1.0, 0.0, 0.0], [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]]),
        ([0.0, 1.0, 0.0], [[-1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]),
        ([0.0, 0.0, 1.0], [[-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]]),
        ([h, h, 0.0], [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]]),
    ] {
        let pose = Pose { rotation: matrix, translation: [0.0; 3] };
        let (got, angle) = pose.axis_angle();
        assert!((angle - PI).abs() < 1e-15, "{angle}");
        assert!(got.iter().zip(axis).all(|(a, b)| (a - b).abs() < 1e-15), "{got:?} vs {axis:?}");
        assert_eq!(pose.quaternion_wxyz()[0], 0.0);
    }
}

#[test]
fn gimbal_lock_and_its_neighbourhood() {
    for pitch in [FRAC_PI_2, -FRAC_PI_2] {
        for (roll, yaw) in [(0.3, 0.2), (-1.0, 2.5), (0.0, 0.0), (3.0, -3.0)] {
            let pose = Pose::from_rpy([roll, pitch, yaw], [0.0; 3]);
            let got = pose.rpy();
            // Exactly at the lock: roll is 0, pitch the lock, and the rotation is the same.
            assert_eq!(got[0], 0.0, "{got:?}");
            assert!((got[1] - pitch).abs() < 1e-15, "{got:?}");
            assert!(difference(&Pose::from_rpy(got, [0.0; 3]), &pose) < TOLERANCE, "{got:?}");
            // Within 1e-9 of it, the angles are ill-conditioned but the rotation they give is not.
            for near in [pitch - pitch.signum() * 1e-9, pitch - pitch.signum() * 1e-12] {
                let pose = Pose::from_rpy([roll, near, yaw], [0.0; 3]);
                let got = pose.rpy();
                assert!(difference(&Pose::from_rpy(got, [0.0; 3]), &pose) < 1e-12, "{near}: {got:?}");
            }
        }
    }
}

#[test]
fn zyz_at_zero_and_pi() {
    for b in [0.0, PI] {
        for (a, c) in [(0.3, 0.2), (-2.0, 1.0)] {
            let pose = Pose::from_euler_zyz([a, b, c], [0.0; 3]);
            let got = pose.euler_zyz();
            assert_eq!(got[2], 0.0, "{got:?}");
            assert!((got[1] - b).abs() < 1e-15, "{got:?}");
            assert!(difference(&Pose::from_euler_zyz(got, [0.0; 3]), &pose) < TOLERANCE, "{got:?}");
        }
    }
}

#[test]
fn tiny_angles() {
    for angle in [1e-12f64, 1e-300, 3e-8] {
        let pose = Pose::from_axis_angle([0.0, 0.6, 0.8], angle, [0.0; 3]).unwrap();
        let (axis, got) = pose.axis_angle();
        // The matrix holds the angle to about 1e-16 absolute (its off-diagonal entries).
        assert!((got - angle).abs() < 1e-16, "{angle}: {got}");
        if angle > 1e-15 {
            assert!((axis[1] - 0.6).abs() < 1e-3 && (axis[2] - 0.8).abs() < 1e-3, "{axis:?}");
        }
    }
}

#[test]
fn what_is_no_rotation_is_refused() {
    assert_eq!(Pose::from_quaternion_wxyz([0.0; 4], [0.0; 3]), Err(OrientationError::ZeroLength));
    assert_eq!(Pose::from_quaternion_wxyz([1e-200, 0.0, 0.0, 0.0], [0.0; 3]), Err(OrientationError::ZeroLength));
    assert_eq!(Pose::from_quaternion_xyzw([f64::NAN, 0.0, 0.0, 1.0], [0.0; 3]), Err(OrientationError::NotFinite));
    assert_eq!(Pose::from_axis_angle([0.0; 3], 1.0, [0.0; 3]), Err(OrientationError::ZeroLength));
    assert_eq!(Pose::from_axis_angle([1.0, 0.0, 0.0], f64::INFINITY, [0.0; 3]), Err(OrientationError::NotFinite));
    assert_eq!(Pose::from_rotation_vector([f64::NAN, 0.0, 0.0], [0.0; 3]), Err(OrientationError::NotFinite));
    assert_eq!(OrientationError::ZeroLength.to_string(), "the quaternion or axis has zero length: it is no rotation");
    // A quaternion of any other length is normalised.
    let a = Pose::from_quaternion_wxyz([3.0, 0.0, 0.0, 4.0], [0.0; 3]).unwrap();
    let b = Pose::from_quaternion_wxyz([0.6, 0.0, 0.0, 0.8], [0.0; 3]).unwrap();
    assert!(difference(&a, &b) < 1e-15);
}

#[test]
fn single_precision() {
    let pose = Pose::<f32>::from_rpy([0.1, -0.4, 2.0], [0.0; 3]);
    let [r, p, y] = pose.rpy();
    assert!((r - 0.1).abs() < 1e-6 && (p + 0.4).abs() < 1e-6 && (y - 2.0).abs() < 1e-6);
    let q = pose.quaternion_wxyz();
    let back = Pose::<f32>::from_quaternion_wxyz(q, [0.0; 3]).unwrap();
    for (a, b) in back.rotation.iter().flatten().zip(pose.rotation.iter().flatten()) {
        assert!((a - b).abs() < 1e-6);
    }
    let lock = Pose::<f32>::from_rpy([0.3, std::f32::consts::FRAC_PI_2, 0.2], [0.0; 3]).rpy();
    assert_eq!(lock[0], 0.0);
    let (axis, angle) = Pose::<f32>::from_axis_angle([0.0, 0.0, 2.0], 3.0, [0.0; 3]).unwrap().axis_angle();
    assert!((angle - 3.0).abs() < 1e-6 && (axis[2] - 1.0).abs() < 1e-6, "{axis:?} {angle}");
    // `f32::consts::PI` is a little more than pi: the same turn, read the short way, about -z.
    let (axis, angle) =
        Pose::<f32>::from_axis_angle([0.0, 0.0, 2.0], std::f32::consts::PI, [0.0; 3]).unwrap().axis_angle();
    assert!((angle - std::f32::consts::PI).abs() < 1e-6 && (axis[2] + 1.0).abs() < 1e-6, "{axis:?} {angle}");
}

/// nalgebra's conversions agree where the conventions are the same (its Euler angles are the same
/// roll-pitch-yaw; its quaternion's sign may differ).
#[cfg(feature = "nalgebra")]
#[test]
fn agrees_with_nalgebra() {
    for pose in rotations() {
        let q = pose.unit_quaternion();
        let [w, x, y, z] = pose.quaternion_wxyz();
        let sign = if q.w < 0.0 || (q.w == 0.0 && q.i < 0.0) { -1.0 } else { 1.0 };
        let theirs = [q.w, q.i, q.j, q.k].map(|v| v * sign);
        assert!(
            [w, x, y, z].iter().zip(theirs).all(|(a, b)| (a - b).abs() < 1e-14),
            "{theirs:?} vs {:?}",
            [w, x, y, z]
        );
        let (roll, pitch, yaw) = pose.rotation3().euler_angles();
        let rpy = pose.rpy();
        if pitch.abs() < 1.5 {
            assert!((rpy[0] - roll).abs() < 1e-12 && (rpy[1] - pitch).abs() < 1e-12 && (rpy[2] - yaw).abs() < 1e-12);
        }
        if let Some((axis, angle)) = q.axis_angle() {
            let (mine, my_angle) = pose.axis_angle();
            if angle < 3.0 {
                assert!(
                    (my_angle - angle).abs() < 1e-12 && mine.iter().zip(axis.iter()).all(|(a, b)| (a - b).abs() < 1e-9)
                );
            }
        }
    }
}
