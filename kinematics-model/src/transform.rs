//! Fixed transforms as products of elementary steps, kept symbolic so exactness survives.

use crate::angle::Angle;

/// A coordinate axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The x axis.
    X,
    /// The y axis.
    Y,
    /// The z axis.
    Z,
}

/// One elementary rigid motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Elementary {
    /// Translation by a vector.
    Translation([f64; 3]),
    /// Rotation by an angle about a coordinate axis.
    Rotation(Axis, Angle),
}

impl Elementary {
    /// `p` moved by the step, its rotation's angle times `sign` (`-1`: the rotation undone).
    fn apply(self, p: [f64; 3], sign: f64) -> [f64; 3] {
        match self {
            Elementary::Translation(v) => [p[0] + v[0], p[1] + v[1], p[2] + v[2]],
            Elementary::Rotation(axis, angle) => {
                let (s, c) = (sign * angle.radians()).sin_cos();
                let turn = |a: f64, b: f64| (c * a - s * b, s * a + c * b);
                match axis {
                    Axis::X => {
                        let (y, z) = turn(p[1], p[2]);
                        [p[0], y, z]
                    }
                    Axis::Y => {
                        let (z, x) = turn(p[2], p[0]);
                        [x, p[1], z]
                    }
                    Axis::Z => {
                        let (x, y) = turn(p[0], p[1]);
                        [x, y, p[2]]
                    }
                }
            }
        }
    }
}

/// A fixed rigid transform written as the product `steps[0] * steps[1] * ...` (each step applied in
/// the frame left by the previous ones).
///
/// A URDF `<origin xyz rpy>` is `[Translation(xyz), Rotation(Z, yaw), Rotation(Y, pitch),
/// Rotation(X, roll)]`; a DH row is the product its convention prescribes. Steps that are exactly
/// the identity are left out, so the identity is the empty product.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FixedTransform {
    steps: Vec<Elementary>,
}

impl FixedTransform {
    /// The identity.
    pub fn identity() -> Self {
        Self::default()
    }

    /// The URDF origin `Trans(xyz) * Rz(yaw) * Ry(pitch) * Rx(roll)`, angles in radians.
    pub fn from_xyz_rpy(xyz: [f64; 3], rpy: [Angle; 3]) -> Self {
        Self::identity().translate(xyz).rotate(Axis::Z, rpy[2]).rotate(Axis::Y, rpy[1]).rotate(Axis::X, rpy[0])
    }

    /// `self * Trans(v)`; a zero vector adds nothing.
    pub fn translate(mut self, v: [f64; 3]) -> Self {
        if v != [0.0; 3] {
            self.steps.push(Elementary::Translation(v));
        }
        self
    }

    /// `self * R_axis(angle)`; a zero angle adds nothing.
    pub fn rotate(mut self, axis: Axis, angle: Angle) -> Self {
        if !angle.is_zero() {
            self.steps.push(Elementary::Rotation(axis, angle));
        }
        self
    }

    /// `self * other`.
    pub fn then(mut self, other: &FixedTransform) -> Self {
        self.steps.extend_from_slice(&other.steps);
        self
    }

    /// The steps, leftmost first.
    pub fn steps(&self) -> &[Elementary] {
        &self.steps
    }

    /// Whether this is the identity (no steps).
    pub fn is_identity(&self) -> bool {
        self.steps.is_empty()
    }

    /// The point `p` carried by the transform (in floating point): `self * p`.
    pub fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        self.steps.iter().rev().fold(p, |p, step| step.apply(p, 1.0))
    }

    /// The point `p` carried by the inverse transform: `self^-1 * p`.
    pub fn apply_inverse(&self, p: [f64; 3]) -> [f64; 3] {
        self.steps.iter().fold(p, |p, step| match *step {
            Elementary::Translation(v) => [p[0] - v[0], p[1] - v[1], p[2] - v[2]],
            rotation => rotation.apply(p, -1.0),
        })
    }

    /// Replaces every rotation angle by `f(angle)`, dropping rotations that become exactly zero.
    pub(crate) fn map_angles(&mut self, mut f: impl FnMut(Angle) -> Angle) {
        for step in &mut self.steps {
            if let Elementary::Rotation(_, angle) = step {
                *angle = f(*angle);
            }
        }
        self.steps.retain(|step| !matches!(step, Elementary::Rotation(_, angle) if angle.is_zero()));
    }

    /// Every number in the transform, for finiteness checks.
    pub(crate) fn numbers(&self) -> impl Iterator<Item = f64> + '_ {
        self.steps.iter().flat_map(|step| match *step {
            Elementary::Translation(v) => v.to_vec(),
            Elementary::Rotation(_, angle) => vec![angle.radians()],
        })
    }
}
