//! The Paden-Kahan subproblems the closed-form families are composed of, in the numbering of
//! IK-Geo (Elias and Wen, "IK-Geo: Unified robot inverse kinematics using subproblem
//! decomposition", arXiv 2211.05737): each finds the angles of one or two rotations about known
//! unit axes, and says whether they are exact or the least-squares best (the target out of reach)
//! and whether they are one representative of a continuum (a singularity).
//!
//! - subproblem 1, [`rotation_onto`]: `rot(k, t) p1 = p2`;
//! - subproblem 2, [`two_rotations`]: `rot(k1, t1) p1 = rot(k2, t2) p2`;
//! - subproblem 3, [`rotation_to_distance`]: `|rot(k, t) p1 - p2| = d`;
//! - subproblem 4, [`rotation_to_height`]: `h . rot(k, t) p = d` (and
//!   [`rotation_to_height_on_great_circle`], its well-conditioned form for orthogonal wrists);
//! - subproblem 5, [`three_rotations`]: `p0 + rot(k1, t1) p1 = rot(k2, t2) (p2 + rot(k3, t3) p3)`;
//! - subproblem 6, [`two_heights`]: two equations `h . rot(k, t1) p + h' . rot(k', t2) p' = d`.
//!
//! Subproblems 3 and 4 are both `a cos t + b sin t = c` ([`cos_sin_equation`]). No function here
//! returns NaN for finite input: a degenerate case gives a representative angle and a flag.
//! Subproblems 1 to 4 are written once, one root at a time, in [`super::branch::Subproblems`]
//! (what the closed-form families and the compiled bodies are made of); the functions here run it
//! on numbers, once per root.
//!
//! Each angle is a `Turn` carrying its cosine and sine from the same arithmetic, so rotating by a
//! solved angle costs no trigonometric call. Every result is flagged exact or least-squares,
//! singular or not. Subproblems 5 and 6 are in `circles` (reduced to a degree-two trigonometric
//! polynomial in one angle) and `polynomial` (the real roots of its quartic).

use super::branch::{self, Numbers, Subproblems};
use super::vector::{V3, cross, dot, norm_squared};

mod circles;
mod polynomial;

pub use circles::{TurnPairs, TurnTriples, three_rotations, two_heights};

/// Relative slack on a discriminant before an equation counts as out of reach: rounding alone
/// takes a target exactly on the boundary of the workspace a few ulp past it.
pub const REACH_SLACK: f64 = 1e-12;

/// Within this of `+-1`, the ratio of `a cos t + b sin t = c` is taken as exactly `+-1`: a double
/// root, the two solutions one. Targets built at a singularity (a UR's fifth joint at zero) land
/// there with a few ulp of rounding, which `acos` would turn into an angle error of the order of
/// the square root of it (1e-8 rad); the price is that targets within about `sqrt(2e-14)`,
/// 1.4e-7 rad, of a double root are solved as if on it.
pub const DOUBLE_ROOT: f64 = 1e-14;

/// Below this (relative to the vectors' lengths) a component is taken as zero: the angle it
/// would fix is free, a singularity.
pub const DEGENERATE: f64 = 1e-9;

/// What is known of a solved angle (or of a whole solution): whether every equation on its way had
/// a real solution, and whether any had a continuum of them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Quality {
    /// Every equation had a real solution: the angles reach the target (to rounding).
    pub exact: bool,
    /// Some angle was free (a singularity): the value given is one representative.
    pub singular: bool,
}

impl Quality {
    /// An exact, regular solution.
    pub const EXACT: Quality = Quality { exact: true, singular: false };

    /// Both qualities together: exact if both are, singular if either is.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[must_use]
    pub fn and(self, other: Quality) -> Quality {
        Quality { exact: self.exact && other.exact, singular: self.singular || other.singular }
    }
}

/// A solved angle with its cosine and sine, which the subproblems get from the same quantities
/// as the angle (the arguments of its `atan2`, or an angle sum's formula), so that rotating by it
/// costs no trigonometric call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Turn {
    /// The angle (radians, in `(-pi, pi]` unless made otherwise).
    pub angle: f64,
    /// Its cosine.
    pub cos: f64,
    /// Its sine.
    pub sin: f64,
}

impl Turn {
    /// No turn.
    pub const ZERO: Turn = Turn { angle: 0.0, cos: 1.0, sin: 0.0 };

    /// The angle of the vector `(x, y)`: `atan2(y, x)`, its cosine and sine the vector
    /// normalised (no turn for the zero vector).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn of(y: f64, x: f64) -> Turn {
        let r = crate::real::square_root(x * x + y * y);
        if r > 0.0 { Turn { angle: crate::trig::atan2(y, x), cos: x / r, sin: y / r } } else { Turn::ZERO }
    }

    /// The opposite turn.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[must_use]
    pub fn back(self) -> Turn {
        Turn { angle: -self.angle, cos: self.cos, sin: -self.sin }
    }

    /// `v` rotated by this turn about the unit axis `k`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn rotate(self, k: V3, v: V3) -> V3 {
        super::vector::rotate_cs(k, self.cos, self.sin, v)
    }
}

impl From<branch::Turn<f64>> for Turn {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn from(turn: branch::Turn<f64>) -> Turn {
        Turn { angle: turn.angle, cos: turn.cos, sin: turn.sin }
    }
}

impl From<Turn> for branch::Turn<f64> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn from(turn: Turn) -> branch::Turn<f64> {
        branch::Turn { angle: turn.angle, cos: turn.cos, sin: turn.sin }
    }
}

/// A branch's flags, `1` or `0` each, as a quality.
impl From<branch::Flags<f64>> for Quality {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn from(flags: branch::Flags<f64>) -> Quality {
        Quality { exact: flags.exact == 1.0, singular: flags.singular == 1.0 }
    }
}

impl From<Quality> for branch::Flags<f64> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn from(quality: Quality) -> branch::Flags<f64> {
        let flag = |x: bool| if x { 1.0 } else { 0.0 };
        branch::Flags { exact: flag(quality.exact), singular: flag(quality.singular) }
    }
}

/// Subproblem 1: the angle `t` with `rot(k, t) p1 = p2` about the unit axis `k`, or the
/// least-squares best when the two vectors differ in their component along `k` or in their
/// distance from it. When `p1` lies on the axis every angle serves: `0`, flagged singular.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn rotation_onto(k: V3, p1: V3, p2: V3) -> (Turn, Quality) {
    let (turn, flags) = Numbers::<f64>::new().rotation_onto(k, p1, p2);
    (turn.into(), flags.into())
}

/// The two solutions of `a cos t + b sin t = c`, `atan2(b, a) + acos(c / hypot(a, b))` first
/// and the one with the minus second, wrapped into `(-pi, pi]`. Out of reach
/// (`|c| > hypot(a, b)`), both are the least-squares best (`t` at or opposite `atan2(b, a)`);
/// when `a = b = 0`, both are `0`, exact (and singular) if `c = 0` too.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn cos_sin_equation(a: f64, b: f64, c: f64) -> ([Turn; 2], Quality) {
    let numbers = &mut Numbers::<f64>::new();
    let (plus, quality) = numbers.cos_sin_equation(a, b, c, 1.0);
    let (minus, _) = numbers.cos_sin_equation(a, b, c, -1.0);
    ([plus.into(), minus.into()], quality.into())
}

/// Subproblem 3: the angles `t` with `|rot(k, t) p1 - p2| = d`, given `d^2` (the callers know
/// the square, so no root is taken).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn rotation_to_distance(k: V3, p1: V3, p2: V3, d_squared: f64) -> ([Turn; 2], Quality) {
    let numbers = &mut Numbers::<f64>::new();
    let (plus, quality) = numbers.rotation_to_distance(k, p1, p2, d_squared, 1.0);
    let (minus, _) = numbers.rotation_to_distance(k, p1, p2, d_squared, -1.0);
    ([plus.into(), minus.into()], quality.into())
}

/// The squared distances subproblem 3 reaches exactly, `[lo, hi]`: `|rot(k, t) p1 - p2|^2` over
/// every `t` (the same equation [`rotation_to_distance`] solves: `d^2` within them is exact, to its
/// [`REACH_SLACK`]).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn distance_range(k: V3, p1: V3, p2: V3) -> (f64, f64) {
    let along = dot(k, p1) * dot(k, p2);
    let a = dot(p1, p2) - along;
    let b = dot(k, cross(p1, p2));
    // c = (|p1|^2 + |p2|^2 - d^2) / 2 - along, and |c| <= hypot(a, b).
    let middle = norm_squared(p1) + norm_squared(p2) - 2.0 * along;
    let swing = 2.0 * crate::real::square_root(a * a + b * b);
    (middle - swing, middle + swing)
}

/// Subproblem 4: the angles `t` with `h . rot(k, t) p = d`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn rotation_to_height(h: V3, k: V3, p: V3, d: f64) -> ([Turn; 2], Quality) {
    let numbers = &mut Numbers::<f64>::new();
    let (plus, quality) = numbers.rotation_to_height(h, k, p, d, 1.0);
    let (minus, _) = numbers.rotation_to_height(h, k, p, d, -1.0);
    ([plus.into(), minus.into()], quality.into())
}

/// Subproblem 4 for an orthogonal wrist: the angles `t` with `h . rot(k, t) p = h . v`, for unit
/// `h`, `k`, `p`, `v` with `h` and `p` both square to `k` (so `rot(k, t) p` sweeps the great circle
/// through `h`). Then `h . rot(k, t) p = cos(t - phi)` for the angle `phi` of `h` on that circle,
/// and the half-width `delta` of the solutions has `cos delta = h . v` and `sin delta = |h x v|`:
/// taking the sine from the cross product keeps its digits where the height is near `+-1` (near
/// the wrist's singularity), which `sqrt(1 - height^2)` would lose (half of them at a distance
/// of 1e-8 rad). Always exact: `v` is reached by construction.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn rotation_to_height_on_great_circle(h: V3, k: V3, p: V3, v: V3) -> [Turn; 2] {
    let numbers = &mut Numbers::<f64>::new();
    let plus = numbers.rotation_to_height_on_great_circle(h, k, p, v, 1.0);
    let minus = numbers.rotation_to_height_on_great_circle(h, k, p, v, -1.0);
    [plus.into(), minus.into()]
}

/// Subproblem 2: the angle pairs `(t1, t2)` with `rot(k1, t1) p1 = rot(k2, t2) p2` about unit
/// axes that are not parallel. The vectors are taken as directions (their lengths are equal
/// when the target is reachable). Two pairs: the rotated vector `x` is where the two cones about
/// `k1` and `k2` cross; when they do not, both pairs are the least-squares best.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn two_rotations(k1: V3, p1: V3, k2: V3, p2: V3) -> ([(Turn, Turn); 2], Quality) {
    let numbers = &mut Numbers::<f64>::new();
    let (t1, t2, first) = numbers.two_rotations(k1, p1, k2, p2, 1.0);
    let (u1, u2, second) = numbers.two_rotations(k1, p1, k2, p2, -1.0);
    let quality = Quality::from(first).and(second.into());
    ([(t1.into(), t2.into()), (u1.into(), u2.into())], quality)
}

#[cfg(test)]
mod tests {
    use super::super::vector::{norm_squared, rotate, scale, sub};
    use super::*;

    fn unit(v: V3) -> V3 {
        scale(v, 1.0 / libm::sqrt(norm_squared(v)))
    }

    fn close(a: V3, b: V3, tolerance: f64) -> bool {
        norm_squared(sub(a, b)) <= tolerance * tolerance
    }

    #[test]
    fn subproblem_1_recovers_the_angle() {
        let k = unit([0.3, -0.5, 0.8]);
        let p1 = [0.4, 1.2, -0.7];
        for angle in [-3.0, -1.0, 0.0, 0.5, 2.9] {
            let p2 = rotate(k, angle, p1);
            let (t, quality) = rotation_onto(k, p1, p2);
            assert!((t.angle - angle).abs() < 1e-14, "{t:?} vs {angle}");
            assert!((t.cos - angle.cos()).abs() < 1e-15 && (t.sin - angle.sin()).abs() < 1e-15, "{t:?}");
            assert_eq!(quality, Quality::EXACT);
        }
    }

    #[test]
    fn subproblem_1_on_the_axis_is_singular_not_nan() {
        let (t, quality) = rotation_onto([0.0, 0.0, 1.0], [0.0, 0.0, 2.0], [0.0, 0.0, 2.0]);
        assert_eq!(t, Turn::ZERO);
        assert!(quality.singular);
    }

    #[test]
    fn subproblem_2_both_pairs_map_p1_and_p2_together() {
        let k1 = unit([0.0, 0.2, 1.0]);
        let k2 = unit([1.0, 0.1, -0.3]);
        let p2 = [0.2, 0.9, 0.4];
        let p1 = rotate(k1, -0.7, rotate(k2, 1.3, p2));
        let (pairs, quality) = two_rotations(k1, p1, k2, p2);
        assert!(quality.exact && !quality.singular);
        let mut found = false;
        for (t1, t2) in pairs {
            assert!(close(rotate(k1, t1.angle, p1), rotate(k2, t2.angle, p2), 1e-14));
            assert!(close(t1.rotate(k1, p1), t2.rotate(k2, p2), 1e-14));
            found |= (t1.angle - 0.7).abs() < 1e-12 && (t2.angle - 1.3).abs() < 1e-12;
        }
        assert!(found, "{pairs:?}");
    }

    #[test]
    fn subproblem_2_out_of_reach_is_flagged() {
        // Cones of half-angle 10 degrees about perpendicular axes do not meet.
        let k1 = [0.0, 0.0, 1.0];
        let k2 = [1.0, 0.0, 0.0];
        let (pairs, quality) = two_rotations(k1, [0.1, 0.0, 1.0], k2, [1.0, 0.1, 0.0]);
        assert!(!quality.exact);
        assert!(pairs.iter().all(|(a, b)| a.angle.is_finite() && b.angle.is_finite()));
    }

    #[test]
    fn subproblem_3_both_angles_give_the_distance() {
        let k = unit([0.2, 1.0, 0.1]);
        let (p1, p2) = ([0.5, 0.1, 0.3], [-0.2, 0.4, 0.9]);
        let d2 = norm_squared(sub(rotate(k, 2.2, p1), p2));
        let (angles, quality) = rotation_to_distance(k, p1, p2, d2);
        assert_eq!(quality, Quality::EXACT);
        assert!(angles.iter().any(|t| (t.angle - 2.2).abs() < 1e-12), "{angles:?}");
        for t in angles {
            assert!((norm_squared(sub(rotate(k, t.angle, p1), p2)) - d2).abs() < 1e-14);
            assert!((t.cos - t.angle.cos()).abs() < 1e-15 && (t.sin - t.angle.sin()).abs() < 1e-15, "{t:?}");
        }
    }

    #[test]
    fn subproblem_3_out_of_reach_gives_the_closest_distance() {
        let k = [0.0, 0.0, 1.0];
        let (angles, quality) = rotation_to_distance(k, [1.0, 0.0, 0.0], [2.0, 0.0, 0.0], 100.0);
        assert!(!quality.exact);
        // The farthest the rotated point gets from p2 is 3 (at t = pi).
        for t in angles {
            assert!((norm_squared(sub(rotate(k, t.angle, [1.0, 0.0, 0.0]), [2.0, 0.0, 0.0])) - 9.0).abs() < 1e-12);
        }
    }

    #[test]
    fn subproblem_3_reaches_exactly_its_distance_range() {
        let k = unit([0.2, 1.0, 0.1]);
        let (p1, p2) = ([0.5, 0.1, 0.3], [-0.2, 0.4, 0.9]);
        let (lo, hi) = distance_range(k, p1, p2);
        // Sampled over a turn, the squared distance stays within the range and comes to its ends.
        let (mut least, mut most) = (f64::INFINITY, f64::NEG_INFINITY);
        for i in 0..10_000 {
            let d2 = norm_squared(sub(rotate(k, f64::from(i) * core::f64::consts::TAU / 10_000.0, p1), p2));
            assert!(d2.is_finite(), "{d2}");
            (least, most) = (least.min(d2), most.max(d2));
        }
        assert!(lo <= least + 1e-15 && most <= hi + 1e-15, "{lo} {least} {most} {hi}");
        assert!(least - lo < 1e-6 && hi - most < 1e-6, "{lo} {least} {most} {hi}");
        for (d2, exact) in [(lo, true), (hi, true), (0.5 * (lo + hi), true), (lo - 1e-6, false), (hi + 1e-6, false)] {
            assert_eq!(rotation_to_distance(k, p1, p2, d2).1.exact, exact, "{d2} in [{lo}, {hi}]");
        }
    }

    #[test]
    fn subproblem_4_both_angles_give_the_height() {
        let h = unit([0.1, -0.3, 1.0]);
        let k = unit([1.0, 0.5, 0.2]);
        let p = [0.3, 0.7, -0.4];
        let d = dot(h, rotate(k, -1.1, p));
        let (angles, quality) = rotation_to_height(h, k, p, d);
        assert_eq!(quality, Quality::EXACT);
        assert!(angles.iter().any(|t| (t.angle + 1.1).abs() < 1e-12), "{angles:?}");
        for t in angles {
            assert!((dot(h, rotate(k, t.angle, p)) - d).abs() < 1e-14);
            assert!((dot(h, t.rotate(k, p)) - d).abs() < 1e-14);
        }
    }

    #[test]
    fn degenerate_equations_are_flagged_not_nan() {
        let (angles, quality) = cos_sin_equation(0.0, 0.0, 0.0);
        assert_eq!((angles, quality), ([Turn::ZERO; 2], Quality { exact: true, singular: true }));
        let (angles, quality) = cos_sin_equation(0.0, 0.0, 1.0);
        assert_eq!((angles, quality), ([Turn::ZERO; 2], Quality { exact: false, singular: true }));
        let (angles, quality) = cos_sin_equation(1.0, 0.0, 2.0);
        assert_eq!(angles, [Turn::ZERO; 2]);
        assert!(!quality.exact);
    }
}
