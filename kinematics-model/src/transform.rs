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
