//! Angles that remember whether they are exact multiples of pi.

use std::fmt;

/// An exact rational multiple of pi, `num / den * pi`, always in lowest terms with `den > 0`.
///
/// A DH twist written `"pi/2"` becomes `PiRational { num: 1, den: 2 }`; the compiler uses this to give
/// such angles exact sines and cosines.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct PiRational {
    num: i64,
    den: i64,
}

impl PiRational {
    /// Zero.
    pub const ZERO: PiRational = PiRational { num: 0, den: 1 };

    /// `num / den * pi`, reduced; `None` when `den` is zero or the value would overflow.
    pub fn new(num: i64, den: i64) -> Option<Self> {
        if den == 0 {
            return None;
        }
        let g = gcd(num.unsigned_abs(), den.unsigned_abs()).max(1);
        let g = i64::try_from(g).ok()?;
        let sign = if den < 0 { -1 } else { 1 };
        Some(Self { num: num.checked_div(g)?.checked_mul(sign)?, den: den.checked_div(g)?.checked_mul(sign)? })
    }

    /// `num / den * pi` for use in constants: `None` unless `den > 0` and the fraction is in lowest terms.
    pub const fn new_const(num: i64, den: i64) -> Option<Self> {
        let (mut a, mut b) = (num.unsigned_abs(), den.unsigned_abs());
        while b != 0 {
            let t = a % b;
            a = b;
            b = t;
        }
        if den > 0 && a == 1 { Some(Self { num, den }) } else { None }
    }

    /// Numerator (carries the sign).
    pub fn num(self) -> i64 {
        self.num
    }

    /// Denominator (positive).
    pub fn den(self) -> i64 {
        self.den
    }

    /// The angle in radians.
    pub fn radians(self) -> f64 {
        self.num as f64 * std::f64::consts::PI / self.den as f64
    }

    /// Exact negation, `None` on overflow.
    pub fn checked_neg(self) -> Option<Self> {
        Some(Self { num: self.num.checked_neg()?, den: self.den })
    }

    /// Exact sum, `None` on overflow.
    pub fn checked_add(self, other: Self) -> Option<Self> {
        let num = self.num.checked_mul(other.den)?.checked_add(other.num.checked_mul(self.den)?)?;
        Self::new(num, self.den.checked_mul(other.den)?)
    }
}

fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

impl fmt::Display for PiRational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.num, self.den) {
            (0, _) => write!(f, "0"),
            (1, 1) => write!(f, "pi"),
            (-1, 1) => write!(f, "-pi"),
            (n, 1) => write!(f, "{n}*pi"),
            (1, d) => write!(f, "pi/{d}"),
            (-1, d) => write!(f, "-pi/{d}"),
            (n, d) => write!(f, "{n}*pi/{d}"),
        }
    }
}

/// An angle as the description gave it: an exact multiple of pi, or a number of radians.
///
/// Exactness is never guessed: `1.5708` stays `Radians(1.5708)`; only angles written exactly
/// (`"pi/2"` in a DH table, or whole degrees in a table whose unit is degrees) are `Exact`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Angle {
    /// An exact rational multiple of pi.
    Exact(PiRational),
    /// A plain number of radians.
    Radians(f64),
}

impl Angle {
    /// The zero angle (exact).
    pub const ZERO: Angle = Angle::Exact(PiRational::ZERO);

    /// The angle in radians.
    pub fn radians(self) -> f64 {
        match self {
            Angle::Exact(r) => r.radians(),
            Angle::Radians(x) => x,
        }
    }

    /// The exact multiple of pi, if the angle was given exactly.
    pub fn exact(self) -> Option<PiRational> {
        match self {
            Angle::Exact(r) => Some(r),
            Angle::Radians(_) => None,
        }
    }

    /// Whether the angle is exactly zero.
    pub fn is_zero(self) -> bool {
        match self {
            Angle::Exact(r) => r.num == 0,
            Angle::Radians(x) => x == 0.0,
        }
    }

    /// Sum of two angles; exact when both are exact (also available as `+`).
    pub fn sum(self, other: Angle) -> Angle {
        match (self, other) {
            (Angle::Exact(a), Angle::Exact(b)) => match a.checked_add(b) {
                Some(sum) => Angle::Exact(sum),
                None => Angle::Radians(a.radians() + b.radians()),
            },
            (a, b) if b.is_zero() => a,
            (a, b) if a.is_zero() => b,
            (a, b) => Angle::Radians(a.radians() + b.radians()),
        }
    }

    /// An angle in degrees: whole degrees are exact (`90` is exactly pi/2), others become radians.
    pub fn from_degrees(degrees: f64) -> Angle {
        if degrees.is_finite()
            && degrees.fract() == 0.0
            && degrees.abs() < 1e15
            && let Some(r) = PiRational::new(degrees as i64, 180)
        {
            return Angle::Exact(r);
        }
        Angle::Radians(degrees.to_radians())
    }

    /// Parses an exact angle written as text: `pi`, `-pi/2`, `2*pi/3`, `3pi/4`, `0`.
    ///
    /// Returns `None` for anything else; a plain decimal is not accepted here, so that a
    /// number is never mistaken for an exact angle.
    pub fn parse_exact(text: &str) -> Option<Angle> {
        let s: String = text.chars().filter(|c| !c.is_whitespace()).collect();
        if s == "0" {
            return Some(Angle::ZERO);
        }
        let (sign, s) = match s.strip_prefix('-') {
            Some(rest) => (-1, rest),
            None => (1, s.strip_prefix('+').unwrap_or(&s)),
        };
        let pi_at = s.find("pi")?;
        let (head, tail) = (&s[..pi_at], &s[pi_at + 2..]);
        let num: i64 = match head.strip_suffix('*').unwrap_or(head) {
            "" => 1,
            n => n.parse().ok()?,
        };
        let den: i64 = match tail {
            "" => 1,
            t => t.strip_prefix('/')?.parse().ok()?,
        };
        PiRational::new(sign * num, den).map(Angle::Exact)
    }
}

impl std::ops::Add for Angle {
    type Output = Angle;

    fn add(self, other: Angle) -> Angle {
        self.sum(other)
    }
}

impl fmt::Display for Angle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Angle::Exact(r) => r.fmt(f),
            Angle::Radians(x) => write!(f, "{x}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(text: &str, expected: Option<(i64, i64)>) {
        let got = Angle::parse_exact(text).and_then(Angle::exact).map(|r| (r.num(), r.den()));
        assert_eq!(got, expected, "parsing {text:?}");
    }

    #[test]
    fn parses_exact_angles() {
        check("pi", Some((1, 1)));
        check("-pi", Some((-1, 1)));
        check("pi/2", Some((1, 2)));
        check("-pi/2", Some((-1, 2)));
        check(" 2*pi / 4 ", Some((1, 2)));
        check("3pi/4", Some((3, 4)));
        check("0", Some((0, 1)));
        check("-2*pi", Some((-2, 1)));
        check("1.5708", None);
        check("pi/0", None);
        check("pie", None);
        check("tau", None);
        check("pi/2/2", None);
    }

    #[test]
    fn whole_degrees_are_exact() {
        assert_eq!(Angle::from_degrees(90.0).exact(), PiRational::new(1, 2));
        assert_eq!(Angle::from_degrees(-180.0).exact(), PiRational::new(-1, 1));
        assert_eq!(Angle::from_degrees(12.5).exact(), None);
        assert!((Angle::from_degrees(12.5).radians() - 12.5f64.to_radians()).abs() < 1e-15);
    }

    #[test]
    fn exact_sums_stay_exact() {
        let half = Angle::parse_exact("pi/2").unwrap();
        let third = Angle::parse_exact("pi/3").unwrap();
        assert_eq!((half + third).exact(), PiRational::new(5, 6));
        assert_eq!((half + Angle::Radians(0.1)).exact(), None);
        assert_eq!(half + Angle::Radians(0.0), half);
    }
}
