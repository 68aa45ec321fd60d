//! MJCF's orientation forms as products of elementary rotations, so that exactness survives.
//!
//! MuJoCo's XML reference (body, "orientation" attributes) and the Modeling chapter ("Frame
//! orientations") define five ways to write a frame's orientation: `quat` (w x y z, normalised by
//! the compiler), `axisangle` (axis, normalised, then an angle in the compiler's unit), `euler`
//! (three angles about the axes of `<compiler eulerseq>`, lower case rotating with the frame,
//! upper case fixed), `xyaxes` (the frame's x axis, then its y axis made orthogonal to x, z their
//! cross product) and `zaxis` (the smallest rotation taking (0, 0, 1) to the axis).
//!
//! The model keeps fixed rotations as products of rotations about coordinate axes
//! ([`crate::FixedTransform`]). So:
//!
//! - `euler` becomes its three rotations as written (whole degrees stay exact multiples of pi);
//! - an `axisangle` about a coordinate axis becomes one rotation by the angle as written;
//! - a quaternion whose vector part lies on a coordinate axis (`0.7071068 0 0 0.7071068`) becomes
//!   one rotation by `2 atan2(|v|, w)`, a number the exactness policy then judges like a URDF
//!   angle (here pi/2 to the last bit, so it becomes exact);
//! - every other rotation (and `xyaxes`, `zaxis`) becomes yaw, pitch and roll,
//!   `Rz(yaw) Ry(pitch) Rx(roll)` as URDF writes it, read off the rotation matrix; a signed
//!   permutation matrix gives multiples of pi/2 to the last bit.
//!
//! Degenerate input (a zero quaternion, axis or `xyaxes` pair) is `None`, for the reader to refuse
//! naming the element and the line; MuJoCo's compiler refuses it too.
//!
//! This is the one place the model computes with a rotation, because its fixed transforms hold only
//! elementary steps.

use crate::angle::Angle;
use crate::transform::Axis;

/// A rotation as elementary steps, leftmost first (`steps[0] * steps[1] * ...`).
pub(crate) type Steps = Vec<(Axis, Angle)>;

/// The angle's negation, exact when the angle is.
pub(crate) fn negate(angle: Angle) -> Angle {
    match angle {
        Angle::Exact(r) => r.checked_neg().map_or(Angle::Radians(-r.radians()), Angle::Exact),
        Angle::Radians(x) => Angle::Radians(-x),
    }
}

/// `euler` with the sequence `seq` (three of `xyzXYZ`, checked by the caller): a lower-case axis
/// rotates with the frame (post-multiplied), an upper-case one is fixed (pre-multiplied).
pub(crate) fn euler(angles: [Angle; 3], seq: [u8; 3]) -> Steps {
    let mut steps = std::collections::VecDeque::new();
    for (letter, angle) in seq.into_iter().zip(angles) {
        let axis = match letter.to_ascii_lowercase() {
            b'x' => Axis::X,
            b'y' => Axis::Y,
            _ => Axis::Z,
        };
        if letter.is_ascii_lowercase() {
            steps.push_back((axis, angle));
        } else {
            steps.push_front((axis, angle));
        }
    }
    steps.into_iter().collect()
}

/// The coordinate axis `v` lies on and its sign, if two of its components are zero and the third
/// is not.
fn coordinate_axis(v: [f64; 3]) -> Option<(Axis, bool)> {
    match v.map(|c| c != 0.0) {
        [true, false, false] => Some((Axis::X, v[0] > 0.0)),
        [false, true, false] => Some((Axis::Y, v[1] > 0.0)),
        [false, false, true] => Some((Axis::Z, v[2] > 0.0)),
        _ => None,
    }
}

/// `axisangle`: one rotation when the axis is a coordinate axis (the angle as written, exact if
/// it was), else through the quaternion. `None` for a zero or non-finite axis.
pub(crate) fn axis_angle(axis: [f64; 3], angle: Angle) -> Option<Steps> {
    if let Some((along, positive)) = coordinate_axis(axis) {
        return Some(vec![(along, if positive { angle } else { negate(angle) })]);
    }
    let n = norm(axis)?;
    let (s, c) = (angle.radians() / 2.0).sin_cos();
    quaternion([c, s * axis[0] / n, s * axis[1] / n, s * axis[2] / n])
}

/// `quat` (w, x, y, z), normalised first. `None` for a zero or non-finite quaternion.
pub(crate) fn quaternion(q: [f64; 4]) -> Option<Steps> {
    // Finite first: `f64::max` below would pass over a NaN component.
    if !q.iter().all(|c| c.is_finite()) {
        return None;
    }
    let scale = q.iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    if scale == 0.0 || !scale.is_finite() {
        return None;
    }
    let scaled = q.map(|c| c / scale);
    let n = scaled.iter().map(|c| c * c).sum::<f64>().sqrt();
    let [w, x, y, z] = scaled.map(|c| c / n);
    if let Some((along, positive)) = coordinate_axis([x, y, z]) {
        let s = x.abs() + y.abs() + z.abs();
        let angle = 2.0 * s.atan2(w);
        return Some(vec![(along, Angle::Radians(if positive { angle } else { -angle }))]);
    }
    if [x, y, z] == [0.0; 3] {
        return Some(Vec::new());
    }
    // The rotation matrix of a unit quaternion (REFERENCE.md, "Quaternion to rotation matrix").
    let m = [
        [1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y)],
        [2.0 * (x * y + w * z), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - w * x)],
        [2.0 * (x * z - w * y), 2.0 * (y * z + w * x), 1.0 - 2.0 * (x * x + y * y)],
    ];
    Some(matrix(m))
}

/// `xyaxes`: x normalised, y made orthogonal to x and normalised, z = x cross y (MuJoCo's
/// compiler does the same). `None` when x is zero or y is parallel to it.
pub(crate) fn xy_axes(x: [f64; 3], y: [f64; 3]) -> Option<Steps> {
    let nx = norm(x)?;
    let x = x.map(|c| c / nx);
    let along = dot(x, y);
    let y = [y[0] - along * x[0], y[1] - along * x[1], y[2] - along * x[2]];
    let ny = norm(y)?;
    let y = y.map(|c| c / ny);
    let z = cross(x, y);
    Some(matrix([[x[0], y[0], z[0]], [x[1], y[1], z[1]], [x[2], y[2], z[2]]]))
}

/// `zaxis`: the smallest rotation taking (0, 0, 1) to `z` (about `(0, 0, 1) x z`, by the angle
/// between them); to `-z` it is a half turn about x, as MuJoCo's compiler takes it. `None` for a
/// zero axis.
pub(crate) fn z_axis(z: [f64; 3]) -> Option<Steps> {
    norm(z)?;
    let about = [-z[1], z[0], 0.0];
    if about == [0.0; 3] {
        return Some(if z[2] > 0.0 {
            Vec::new()
        } else {
            vec![(Axis::X, Angle::Exact(crate::PiRational::new(1, 1)?))]
        });
    }
    let angle = norm(about)?.atan2(z[2]);
    axis_angle(about, Angle::Radians(angle))
}

/// A rotation matrix (rows) as `Rz(yaw) Ry(pitch) Rx(roll)`: yaw from the first column, then
/// pitch and roll from `Rz(-yaw) R`, which is `Ry(pitch) Rx(roll)` to rounding even where pitch
/// is a quarter turn and yaw is not determined (there yaw is 0 and roll takes the rest).
pub(crate) fn matrix(m: [[f64; 3]; 3]) -> Steps {
    let yaw = m[1][0].atan2(m[0][0]);
    let (sy, cy) = yaw.sin_cos();
    // Rows 0 and 1 of Rz(-yaw) m; row 2 is m's.
    let r0 = [cy * m[0][0] + sy * m[1][0], cy * m[0][1] + sy * m[1][1], cy * m[0][2] + sy * m[1][2]];
    let r1 = [-sy * m[0][0] + cy * m[1][0], -sy * m[0][1] + cy * m[1][1], -sy * m[0][2] + cy * m[1][2]];
    let pitch = (-m[2][0]).atan2(r0[0]);
    let roll = (-r1[2]).atan2(r1[1]);
    [(Axis::Z, yaw), (Axis::Y, pitch), (Axis::X, roll)]
        .into_iter()
        .filter(|(_, a)| *a != 0.0)
        .map(|(axis, a)| (axis, Angle::Radians(a)))
        .collect()
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// The length of `v`, when it is finite and not zero.
fn norm(v: [f64; 3]) -> Option<f64> {
    let n = dot(v, v).sqrt();
    (n > 0.0 && n.is_finite()).then_some(n)
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, PI};

    use super::*;

    fn exact(num: i64, den: i64) -> Angle {
        Angle::Exact(crate::PiRational::new(num, den).unwrap())
    }

    /// The steps as radians, for comparison with hand-worked angles.
    fn radians(steps: &Steps) -> Vec<(Axis, f64)> {
        steps.iter().map(|(axis, a)| (*axis, a.radians())).collect()
    }

    fn close(steps: &Steps, expected: &[(Axis, f64)]) {
        let got = radians(steps);
        assert_eq!(got.len(), expected.len(), "{got:?} vs {expected:?}");
        for ((a, x), (b, y)) in got.iter().zip(expected) {
            assert!(a == b && (x - y).abs() < 1e-15, "{got:?} vs {expected:?}");
        }
    }

    #[test]
    fn euler_sequences_rotate_with_the_frame_or_stay_fixed() {
        let (a, b, c) = (exact(1, 2), exact(1, 3), exact(1, 6));
        // xyz (MuJoCo's default): R = Rx(a) Ry(b) Rz(c), each about the rotated axes.
        assert_eq!(euler([a, b, c], *b"xyz"), vec![(Axis::X, a), (Axis::Y, b), (Axis::Z, c)]);
        // XYZ: fixed axes, R = Rz(c) Ry(b) Rx(a) (URDF's rpy is this one).
        assert_eq!(euler([a, b, c], *b"XYZ"), vec![(Axis::Z, c), (Axis::Y, b), (Axis::X, a)]);
        // Mixed zYx: Rz(a) first, then Y fixed (pre-multiplied), then x rotating: Ry(b) Rz(a) Rx(c).
        assert_eq!(euler([a, b, c], *b"zYx"), vec![(Axis::Y, b), (Axis::Z, a), (Axis::X, c)]);
    }

    #[test]
    fn axis_angle_about_a_coordinate_axis_keeps_the_angle_as_written() {
        assert_eq!(axis_angle([0.0, 2.0, 0.0], exact(-1, 2)), Some(vec![(Axis::Y, exact(-1, 2))]));
        assert_eq!(axis_angle([0.0, 0.0, -1.0], exact(1, 3)), Some(vec![(Axis::Z, exact(-1, 3))]));
        assert_eq!(axis_angle([0.0; 3], exact(1, 3)), None);
        // 120 degrees about (1, 1, 1) is the cyclic permutation x -> y -> z -> x:
        // R = [[0, 0, 1], [1, 0, 0], [0, 1, 0]] = Rz(90) Rx(90) (worked in the quaternion test).
        // Through cos(60) and sin(60) the pitch comes out 1e-16, not 0: rounding, which the
        // exactness policy turns into exactly 0 (and drops).
        let mut steps = axis_angle([1.0, 1.0, 1.0], exact(2, 3)).unwrap();
        steps.retain(|(_, a)| a.radians().abs() > 1e-15);
        close(&steps, &[(Axis::Z, FRAC_PI_2), (Axis::X, FRAC_PI_2)]);
    }

    #[test]
    #[allow(clippy::approx_constant)] // 0.7071068 is what MJCF files write for cos 45, on purpose
    fn quaternions_are_normalised_and_single_axis_ones_give_one_rotation() {
        // (cos 45, 0, 0, sin 45) to 7 digits: 2 atan2(s, c) with s = c is pi/2 to the last bit.
        assert_eq!(quaternion([0.7071068, 0.0, 0.0, 0.7071068]), Some(vec![(Axis::Z, Angle::Radians(FRAC_PI_2))]));
        // Unnormalised (MuJoCo normalises): (1, 1, 0, 0) is also a quarter turn, about x.
        assert_eq!(quaternion([1.0, 1.0, 0.0, 0.0]), Some(vec![(Axis::X, Angle::Radians(FRAC_PI_2))]));
        // (0, 0, -1, 0): a half turn about -y, i.e. -pi about y.
        assert_eq!(quaternion([0.0, 0.0, -1.0, 0.0]), Some(vec![(Axis::Y, Angle::Radians(-PI))]));
        assert_eq!(quaternion([2.0, 0.0, 0.0, 0.0]), Some(vec![]));
        assert_eq!(quaternion([0.0; 4]), None);
        // (0.5, 0.5, 0.5, 0.5): by the REFERENCE formula R = [[0, 0, 1], [1, 0, 0], [0, 1, 0]].
        // yaw = atan2(r21, r11) = atan2(1, 0) = pi/2; Rz(-pi/2) R = [[1, 0, 0], [0, 0, -1], [0, 1, 0]]
        // = Rx(pi/2), so pitch = atan2(-r31, 1) = 0 and roll = atan2(1, 0) = pi/2:
        // R = Rz(pi/2) Rx(pi/2) (check: Rz(90) maps Rx(90)'s columns (1,0,0), (0,0,1), (0,-1,0)
        // to (0,1,0), (0,0,1), (1,0,0), R's columns).
        close(&quaternion([0.5, 0.5, 0.5, 0.5]).unwrap(), &[(Axis::Z, FRAC_PI_2), (Axis::X, FRAC_PI_2)]);
    }

    #[test]
    fn xyaxes_and_zaxis_by_hand() {
        // x' = (0, 1, 0), y' = (-1, 0, 0): a quarter turn about z.
        close(&xy_axes([0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]).unwrap(), &[(Axis::Z, FRAC_PI_2)]);
        // y is made orthogonal to x first: (-1, 5, 0) against x = (0, 1, 0) leaves (-1, 0, 0).
        close(&xy_axes([0.0, 2.0, 0.0], [-1.0, 5.0, 0.0]).unwrap(), &[(Axis::Z, FRAC_PI_2)]);
        assert_eq!(xy_axes([1.0, 0.0, 0.0], [2.0, 0.0, 0.0]), None);
        // z' = (1, 0, 0): Ry(theta) takes (0, 0, 1) to (sin theta, 0, cos theta), so theta = pi/2.
        close(&z_axis([1.0, 0.0, 0.0]).unwrap(), &[(Axis::Y, FRAC_PI_2)]);
        // z' = (0, 1, 0): Rx(theta) takes (0, 0, 1) to (0, -sin theta, cos theta): theta = -pi/2.
        close(&z_axis([0.0, 3.0, 0.0]).unwrap(), &[(Axis::X, -FRAC_PI_2)]);
        assert_eq!(z_axis([0.0, 0.0, 2.0]), Some(vec![]));
        assert_eq!(z_axis([0.0, 0.0, -1.0]), Some(vec![(Axis::X, exact(1, 1))]));
        assert_eq!(z_axis([0.0; 3]), None);
    }

    #[test]
    fn a_gimbal_locked_matrix_is_reproduced() {
        // Ry(pi/2) Rx(0.3) = [[0, s, c], [0, c, -s], [-1, 0, 0]] with c, s of 0.3: yaw = atan2(0, 0) = 0.
        let (s, c) = 0.3_f64.sin_cos();
        close(&matrix([[0.0, s, c], [0.0, c, -s], [-1.0, 0.0, 0.0]]), &[(Axis::Y, FRAC_PI_2), (Axis::X, 0.3)]);
    }
}
