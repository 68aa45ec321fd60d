//! The exactness policy: which constant angles written as decimals are read as exact quarter turns.
//!
//! Real descriptions spell pi as `3.14159265359` (2e-13 rad off) and pi/2 as `1.57079632679`
//! (5e-12 rad off). Read literally, such an angle leaves constants like `4.9e-12` in the generated
//! code and costs multiplications an exact quarter turn (a signed permutation) does not. This step
//! of the model decides once, before the tree is built, which angles are exact, so the runtime
//! reference and the compiler always compute the same robot: the compiler itself never rounds.
//!
//! **Policy** ([`ExactAngles::default`]): a constant rotation angle of a fixed transform (a URDF
//! `<origin rpy>`, a DH `alpha`, `theta` or revolute `offset`) written as a number is read as the
//! multiple of pi/2 nearest to it when it lies within [`DEFAULT_TOLERANCE`] (1e-8 rad) of it and
//! within [`RANGE`] (64 pi) of zero. So `3.14159265359` (xacro's output, 2e-13 off), `1.57079632679`
//! (5e-12 off) and the truncated `3.14159265` of some expanded ROS files (4e-9 off) become exact;
//! `1.5708` (7e-6 off), `1.570796` (3e-7 off) and `1.5707963` (3e-8 off) stay as written. At a
//! metre from the axis, 1e-8 rad is 10 nm: below any calibration, far above rounding. Angles
//! written exactly (`"pi/2"`, whole degrees) are exact under any policy. Mimic offsets, joint
//! values and every length are used as written. [`ExactAngles::Off`] reads every angle as written.
//! The tree keeps the list of angles it changed ([`crate::KinematicTree::recognised_angles`]).

use crate::angle::{Angle, PiRational};
use crate::description::Description;

/// Angles within this many radians of a multiple of pi/2 are that multiple (the default policy).
pub const DEFAULT_TOLERANCE: f64 = 1e-8;

/// Angles farther than this from zero are never recognised: past a few turns nobody means a
/// quarter turn, and for huge values the nearest multiple of pi/2 is no longer computed exactly.
pub const RANGE: f64 = 64.0 * std::f64::consts::PI;

/// Which decimal angles the model reads as exact multiples of pi/2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ExactAngles {
    /// Every angle is used as written; only angles written exactly (`"pi/2"`) are exact.
    Off,
    /// An angle within `tolerance` radians of a multiple of pi/2 (and within [`RANGE`]) is that
    /// multiple. The tolerance must be finite and at most 1e-6.
    Within(f64),
}

impl Default for ExactAngles {
    fn default() -> Self {
        ExactAngles::Within(DEFAULT_TOLERANCE)
    }
}

impl ExactAngles {
    /// The largest tolerance [`ExactAngles::Within`] accepts: beyond it, decimals like `1.5708`
    /// that their authors meant as numbers would be rounded.
    pub const MAX_TOLERANCE: f64 = 1e-6;

    /// On (the default tolerance) or off.
    pub fn on(on: bool) -> Self {
        if on { Self::default() } else { Self::Off }
    }

    /// The exact multiple of pi/2 this policy reads `radians` as, if any.
    pub fn recognise(self, radians: f64) -> Option<PiRational> {
        let ExactAngles::Within(tolerance) = self else { return None };
        if !(radians.abs() <= RANGE && tolerance.is_finite()) {
            return None;
        }
        let tolerance = tolerance.clamp(0.0, Self::MAX_TOLERANCE);
        let quarters = (radians / std::f64::consts::FRAC_PI_2).round();
        // |quarters| <= 128 by RANGE, so the cast is exact.
        let exact = PiRational::new(quarters as i64, 2)?;
        ((radians - exact.radians()).abs() <= tolerance).then_some(exact)
    }
}

/// One angle the policy changed: where it was, what was written and the exact value used.
#[derive(Debug, Clone, PartialEq)]
pub struct RecognisedAngle {
    /// The joint (URDF joint or DH row's joint) whose fixed transform holds the angle.
    pub joint: String,
    /// The angle as written, in radians.
    pub written: f64,
    /// The exact multiple of pi used instead.
    pub exact: PiRational,
}

impl RecognisedAngle {
    /// How far the exact value is from the written one, in radians (`exact - written`).
    pub fn change(&self) -> f64 {
        self.exact.radians() - self.written
    }
}

/// Applies `policy` to every constant rotation angle of `description`; returns what it changed.
pub(crate) fn recognise(description: &mut Description, policy: ExactAngles) -> Vec<RecognisedAngle> {
    let mut changed = Vec::new();
    for joint in &mut description.joints {
        for transform in [&mut joint.origin, &mut joint.after_motion] {
            transform.map_angles(|angle| match angle {
                Angle::Radians(x) => match policy.recognise(x) {
                    Some(exact) => {
                        changed.push(RecognisedAngle { joint: joint.name.clone(), written: x, exact });
                        Angle::Exact(exact)
                    }
                    None => angle,
                },
                Angle::Exact(_) => angle,
            });
        }
    }
    changed
}

#[cfg(test)]
#[allow(clippy::approx_constant)] // the cases are decimals that merely resemble pi, on purpose
mod tests {
    use super::*;

    fn quarters(policy: ExactAngles, x: f64) -> Option<i64> {
        policy.recognise(x).map(|r| r.num() * 2 / r.den())
    }

    #[test]
    fn ros_spellings_of_pi_are_recognised() {
        let on = ExactAngles::default();
        assert_eq!(quarters(on, 3.14159265359), Some(2));
        assert_eq!(quarters(on, -3.14159265359), Some(-2));
        assert_eq!(quarters(on, 1.57079632679), Some(1));
        assert_eq!(quarters(on, 1.570796327), Some(1));
        assert_eq!(quarters(on, 3.14159265), Some(2));
        assert_eq!(quarters(on, 1.570796325), Some(1));
        assert_eq!(quarters(on, -1.5707963267948966), Some(-1));
        assert_eq!(quarters(on, 4.71238898038), Some(3));
        assert_eq!(quarters(on, 6.28318530718), Some(4));
        assert_eq!(quarters(on, 0.0), Some(0));
        assert_eq!(quarters(on, 1e-12), Some(0));
    }

    #[test]
    fn decimals_meant_as_numbers_stay() {
        let on = ExactAngles::default();
        for x in [1.5708, 3.1416, 1.570796, 1.5707963, 3.1415927, 3.14159, 0.5, 1e-6, 2e-8, -2.0, 0.785398163397] {
            assert_eq!(on.recognise(x), None, "{x}");
        }
    }

    #[test]
    fn huge_and_non_finite_angles_are_never_recognised() {
        let on = ExactAngles::default();
        for x in [1e16, -1e17, 1e300, f64::INFINITY, f64::NAN, 64.0 * std::f64::consts::PI + 0.1] {
            assert_eq!(on.recognise(x), None, "{x}");
        }
        // Just inside the range, an exact multiple still counts.
        assert_eq!(quarters(on, 40.0 * std::f64::consts::PI), Some(80));
    }

    #[test]
    fn off_recognises_nothing_and_the_tolerance_is_capped() {
        assert_eq!(ExactAngles::Off.recognise(std::f64::consts::FRAC_PI_2), None);
        assert_eq!(quarters(ExactAngles::Within(1e-3), 1.5708), None);
        assert_eq!(quarters(ExactAngles::Within(0.0), std::f64::consts::PI), Some(2));
        assert_eq!(ExactAngles::Within(f64::NAN).recognise(std::f64::consts::PI), None);
    }
}
