//! Angles as linear forms over the joint variables: `sum(k_i * q_i) + exact + numeric`.

use std::fmt;

use kinematics_model::PiRational;

use super::graph::{ExprGraph, ExprId};

/// An angle `sum(coefficient * q[dof]) + exact * pi + numeric`.
///
/// Rotations about one axis compose by adding their angles, so merging joints with parallel axes
/// is adding linear forms; the constant part stays exact as long as every summand was exact.
#[derive(Debug, Clone, PartialEq)]
pub struct LinearAngle {
    /// `(dof, coefficient)`, sorted by dof, no zero coefficients.
    terms: Vec<(usize, f64)>,
    /// Exact multiple of pi.
    exact: PiRational,
    /// Numeric radians.
    numeric: f64,
}

impl LinearAngle {
    /// A constant angle, exact or numeric.
    pub fn constant(angle: kinematics_model::Angle) -> Self {
        match angle {
            kinematics_model::Angle::Exact(r) => Self { terms: Vec::new(), exact: r, numeric: 0.0 },
            kinematics_model::Angle::Radians(x) => Self { terms: Vec::new(), exact: PiRational::ZERO, numeric: x },
        }
    }

    /// `multiplier * q[dof] + offset`.
    pub fn joint(dof: usize, multiplier: f64, offset: f64) -> Self {
        let mut angle = Self::constant(kinematics_model::Angle::Radians(offset));
        if multiplier != 0.0 {
            angle.terms.push((dof, multiplier));
        }
        angle
    }

    /// Whether no joint variable appears.
    pub fn is_constant(&self) -> bool {
        self.terms.is_empty()
    }

    /// The variable part.
    pub fn terms(&self) -> &[(usize, f64)] {
        &self.terms
    }

    /// The constant part in radians.
    pub fn constant_radians(&self) -> f64 {
        self.exact.radians() + self.numeric
    }

    /// The sum of two angles.
    pub fn plus(&self, other: &LinearAngle) -> LinearAngle {
        let mut terms = self.terms.clone();
        for &(dof, k) in &other.terms {
            match terms.iter_mut().find(|(d, _)| *d == dof) {
                Some((_, existing)) => *existing += k,
                None => terms.push((dof, k)),
            }
        }
        terms.retain(|&(_, k)| k != 0.0);
        terms.sort_by_key(|&(d, _)| d);
        let (exact, numeric) = match self.exact.checked_add(other.exact) {
            Some(e) => (e, self.numeric + other.numeric),
            None => (self.exact, self.numeric + other.numeric + other.exact.radians()),
        };
        LinearAngle { terms, exact, numeric }
    }

    /// The negated angle (exactly: a constant part whose negation would overflow moves to the
    /// numeric part, which only happens past any angle a description can write).
    pub fn negated(&self) -> LinearAngle {
        let terms = self.terms.iter().map(|&(d, k)| (d, -k)).collect();
        match self.exact.checked_neg() {
            Some(exact) => LinearAngle { terms, exact, numeric: -self.numeric },
            None => LinearAngle { terms, exact: PiRational::ZERO, numeric: -(self.numeric + self.exact.radians()) },
        }
    }

    /// The number of quarter turns in the exact part, when it is a whole number of them.
    ///
    /// Only an exact part counts: the model's exactness policy decided which written angles are
    /// exact, so the compiler never rounds a number (the runtime reference computes with the same
    /// angles, and the two always describe the same robot).
    fn quarter_turns(&self) -> Option<i64> {
        match self.exact.den() {
            1 => self.exact.num().checked_mul(2),
            2 => Some(self.exact.num()),
            _ => None,
        }
    }

    /// Whether the angle is a constant whole number of quarter turns (its rotation is a signed
    /// permutation).
    pub fn is_quarter_turns(&self) -> bool {
        self.is_constant() && self.numeric == 0.0 && self.quarter_turns().is_some()
    }

    /// `(sin, cos)` of a constant angle: exact for whole quarter turns, and a quarter-turn
    /// exact part is taken out exactly otherwise (`sin(pi/2 + x) = cos x`).
    pub fn constant_sin_cos(&self) -> (f64, f64) {
        match self.quarter_turns() {
            Some(k) => rotate_quarters(k, self.numeric.sin(), self.numeric.cos()),
            None => {
                let x = self.constant_radians();
                (x.sin(), x.cos())
            }
        }
    }

    /// `(sin, cos)` of the angle as graph nodes.
    ///
    /// An exact part that is a whole number of quarter turns is taken out exactly
    /// (`sin(x + pi/2) = cos x`), so `q` and `q + pi/2` share one `sin_cos`.
    pub fn sin_cos(&self, g: &mut ExprGraph) -> (ExprId, ExprId) {
        let quarters = self.quarter_turns();
        let constant = if quarters.is_some() { self.numeric } else { self.constant_radians() };
        let mut sum: Option<ExprId> = None;
        for &(dof, k) in &self.terms {
            let q = g.var(dof);
            let kq = {
                let k = g.constant(k);
                g.mul(k, q)
            };
            sum = Some(match sum {
                Some(s) => g.add(s, kq),
                None => kq,
            });
        }
        let c = g.constant(constant);
        let angle = match sum {
            Some(s) => g.add(s, c),
            None => c,
        };
        let (s, c) = (g.sin(angle), g.cos(angle));
        match quarters.map(|k| k.rem_euclid(4)) {
            Some(1) => (c, g.neg(s)),
            Some(2) => (g.neg(s), g.neg(c)),
            Some(3) => (g.neg(c), s),
            _ => (s, c),
        }
    }
}

/// A number as text that reads back to the same `f64`: plain decimals (`0.5`, `1.5707963267948966`),
/// with an exponent for very small or very large magnitudes (`6.123233995736766e-17`).
pub(crate) fn number_text(x: f64) -> String {
    if x != 0.0 && x.is_finite() && (x.abs() < 1e-4 || x.abs() >= 1e16) { format!("{x:e}") } else { format!("{x}") }
}

/// `q1 + 2*q3 - pi/2 + 0.3`: the joint terms in dof order (`q1` is dof 0), then the exact part,
/// then the numeric part; `0` for the zero angle.
impl fmt::Display for LinearAngle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // (negative, magnitude as text)
        let mut parts: Vec<(bool, String)> = Vec::new();
        for &(dof, k) in &self.terms {
            let var = format!("q{}", dof + 1);
            let magnitude = if k.abs() == 1.0 { var } else { format!("{}*{var}", number_text(k.abs())) };
            parts.push((k < 0.0, magnitude));
        }
        if self.exact != PiRational::ZERO {
            parts.push(match self.exact.checked_neg() {
                Some(positive) if self.exact.num() < 0 => (true, positive.to_string()),
                _ => (false, self.exact.to_string()),
            });
        }
        if self.numeric != 0.0 {
            parts.push((self.numeric < 0.0, number_text(self.numeric.abs())));
        }
        if parts.is_empty() {
            return f.write_str("0");
        }
        for (i, (negative, magnitude)) in parts.iter().enumerate() {
            let sign = match (i, negative) {
                (0, false) => "",
                (0, true) => "-",
                (_, false) => " + ",
                (_, true) => " - ",
            };
            write!(f, "{sign}{magnitude}")?;
        }
        Ok(())
    }
}

/// `(sin, cos)` of `k` quarter turns plus an angle whose sine and cosine are `s` and `c`.
fn rotate_quarters(k: i64, s: f64, c: f64) -> (f64, f64) {
    match k.rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kinematics_model::Angle;
    use std::f64::consts::{FRAC_PI_2, PI};

    fn exact(num: i64, den: i64) -> LinearAngle {
        LinearAngle::constant(Angle::Exact(PiRational::new(num, den).unwrap()))
    }

    #[test]
    fn exact_quarter_turns_have_exact_sines() {
        for (k, s, c) in [(0, 0.0, 1.0), (1, 1.0, 0.0), (2, 0.0, -1.0), (3, -1.0, 0.0), (-1, -1.0, 0.0), (5, 1.0, 0.0)]
        {
            let angle = exact(k, 2);
            assert!(angle.is_quarter_turns());
            assert_eq!(angle.constant_sin_cos(), (s, c), "{k} quarter turns");
        }
    }

    #[test]
    #[allow(clippy::approx_constant, reason = "the point: near-pi decimals as URDF files write them")]
    fn numbers_are_never_rounded() {
        // The compiler takes numbers as written: the nearest f64 to pi/2 is not the quarter turn
        // (the model's exactness policy is where a written angle becomes exact).
        for x in [FRAC_PI_2, PI, 1.57079632679, 3.14159265359, 1.5708] {
            let angle = LinearAngle::constant(Angle::Radians(x));
            assert!(!angle.is_quarter_turns(), "{x}");
            assert_eq!(angle.constant_sin_cos(), (x.sin(), x.cos()), "{x}");
        }
    }

    #[test]
    fn a_quarter_turn_part_is_taken_out_exactly() {
        let angle = exact(1, 2).plus(&LinearAngle::constant(Angle::Radians(0.25)));
        assert!(!angle.is_quarter_turns());
        assert_eq!(angle.constant_sin_cos(), (0.25f64.cos(), -0.25f64.sin()));
        let third = exact(1, 3);
        assert_eq!(third.constant_sin_cos(), ((PI / 3.0).sin(), (PI / 3.0).cos()));
    }

    #[test]
    fn negation_is_exact() {
        let angle = exact(3, 2).plus(&LinearAngle::joint(0, 2.0, 0.5));
        let negated = angle.negated();
        assert_eq!(negated.terms(), &[(0, -2.0)]);
        assert_eq!(negated.constant_radians(), -angle.constant_radians());
        assert_eq!(negated.negated(), angle);
    }

    #[test]
    fn display_reads_like_the_formula() {
        let radians = |x: f64| LinearAngle::constant(Angle::Radians(x));
        let mimic = LinearAngle::joint(2, 2.0, 0.0);
        let cases = [
            (LinearAngle::joint(0, 1.0, 0.0), "q1"),
            (
                LinearAngle::joint(0, 1.0, 0.0).plus(&mimic).plus(&exact(1, 2)).plus(&radians(0.3)),
                "q1 + 2*q3 + pi/2 + 0.3",
            ),
            (LinearAngle::joint(1, -1.0, 0.0).plus(&exact(-3, 2)).plus(&radians(-0.3)), "-q2 - 3*pi/2 - 0.3"),
            (LinearAngle::joint(0, -0.5, 0.0).plus(&LinearAngle::joint(1, 1.0, 0.0)), "-0.5*q1 + q2"),
            (exact(-1, 2), "-pi/2"),
            (exact(1, 1), "pi"),
            (exact(0, 1), "0"),
            (LinearAngle::joint(0, 1.0, 0.0).plus(&LinearAngle::joint(0, -1.0, 0.0)), "0"),
            (radians(-FRAC_PI_2), "-1.5707963267948966"),
            (radians(1e-20), "1e-20"),
            (LinearAngle::joint(9, 1e20, 0.0), "1e20*q10"),
        ];
        for (angle, text) in cases {
            assert_eq!(angle.to_string(), text, "{angle:?}");
        }
    }

    #[test]
    fn numbers_read_back_exactly() {
        for x in [0.5, FRAC_PI_2, 6.123233995736766e-17, 1e-4, 9.99e-5, 1e16, 1e300, -2.5e-300, 0.0, -0.0] {
            let text = number_text(x);
            assert_eq!(text.parse::<f64>().map(f64::to_bits), Ok(x.to_bits()), "{text}");
        }
        assert_eq!(number_text(1.0), "1");
        assert_eq!(number_text(6.123233995736766e-17), "6.123233995736766e-17");
    }

    #[test]
    #[allow(clippy::approx_constant, reason = "the point: near-pi decimals as URDF files write them")]
    fn joint_sin_cos_shares_the_joint_angle() {
        let mut g = ExprGraph::new();
        let plain = LinearAngle::joint(0, 1.0, 0.0).sin_cos(&mut g);
        let shifted = LinearAngle::joint(0, 1.0, 0.0).plus(&exact(1, 2)).sin_cos(&mut g);
        // sin(q + pi/2) = cos q, cos(q + pi/2) = -sin q
        assert_eq!(shifted.0, plain.1);
        assert_eq!(shifted.1, g.neg(plain.0));
        // A decimal near pi/2 is a different angle.
        let decimal = LinearAngle::joint(0, 1.0, 1.57079632679).sin_cos(&mut g);
        assert_ne!(decimal.0, plain.1);
    }
}
