//! Angles as linear forms over the joint variables: `sum(k_i * q_i) + exact + numeric`.

use kinematics_model::PiRational;

use super::graph::{ExprGraph, ExprId, exact_sin_cos};

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

    /// The negated angle.
    pub fn negated(&self) -> LinearAngle {
        LinearAngle {
            terms: self.terms.iter().map(|&(d, k)| (d, -k)).collect(),
            exact: PiRational::new(-self.exact.num(), self.exact.den()).unwrap_or(self.exact),
            numeric: -self.numeric,
        }
    }

    /// The number of quarter turns in the constant part, when it is (within the exactness
    /// tolerance) a multiple of pi/2; the rest of the constant is then zero.
    fn quarter_turns(&self) -> Option<i64> {
        let c = self.constant_radians();
        exact_sin_cos(c)?;
        Some((c / std::f64::consts::FRAC_PI_2).round() as i64)
    }

    /// `(sin, cos)` of the angle as graph nodes.
    ///
    /// A constant part that is a whole number of quarter turns is taken out exactly
    /// (`sin(x + pi/2) = cos x`), so `q` and `q + pi/2` share one `sin_cos`.
    pub fn sin_cos(&self, g: &mut ExprGraph) -> (ExprId, ExprId) {
        let quarters = if self.is_constant() { None } else { self.quarter_turns() };
        let constant = if quarters.is_some() { 0.0 } else { self.constant_radians() };
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
