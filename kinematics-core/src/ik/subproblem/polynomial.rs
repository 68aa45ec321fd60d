//! Real roots of a polynomial of degree at most four, for the subproblems whose two angles meet in
//! a quartic (5 and 6). Each root is isolated between consecutive roots of the derivative (found
//! the same way, down to a linear one) and then polished by Newton's method kept inside its bracket
//! by bisection: no closed-form radicals, whose cancellation near double roots costs half the
//! digits, and no heap.

use super::super::bounded::BoundedList;

/// At most four real roots, in increasing order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Roots {
    values: BoundedList<f64, 4>,
}

impl Roots {
    const NONE: Roots = Roots { values: BoundedList::new(0.0) };

    /// Adds a root: at most one per interval between critical points (a quartic has at most
    /// three, so four intervals), a root where the curve touches zero taking the place of the next
    /// interval's (which then starts at zero and brackets none).
    fn push(&mut self, x: f64) {
        // A double root found from both sides of its critical point (or the critical point itself
        // and a bracket beside it) is one root.
        if let Some(&last) = self.values.last()
            && (x - last).abs() <= 1e-12 * (1.0 + x.abs())
        {
            return;
        }
        #[allow(clippy::expect_used, reason = "invariant: at most one root per interval, four intervals at most")]
        self.values.push(x).expect("invariant: a polynomial of degree at most four has at most four roots here");
    }

    /// The roots found.
    pub(crate) fn as_slice(&self) -> &[f64] {
        self.values.as_slice()
    }
}

/// `c[0] + c[1] x + ... + c[n] x^n` by Horner's rule, with its derivative.
fn evaluate(c: &[f64], x: f64) -> (f64, f64) {
    let mut value = 0.0;
    let mut slope = 0.0;
    for &coefficient in c.iter().rev() {
        slope = slope * x + value;
        value = value * x + coefficient;
    }
    (value, slope)
}

/// The size of the terms of `c[0] + ... + c[n] x^n` at `x`, each coefficient counted as
/// `sizes[i]`: a bound on the value's rounding error, in units of the coefficients' own.
fn size_at(sizes: &[f64], x: f64) -> f64 {
    let mut size = 0.0;
    for &coefficient in sizes.iter().rev() {
        size = size * x.abs() + coefficient;
    }
    size
}

/// Below this times the terms' size, a polynomial's value at a critical point counts as zero:
/// the critical point is a double root (a tangency), which rounding may lift a little off zero.
const TOUCH: f64 = 1e-13;

/// The root in `[lo, hi]`, where the values at the ends have opposite signs (or one is zero).
fn bracketed(c: &[f64], mut lo: f64, mut hi: f64) -> f64 {
    let (f_lo, _) = evaluate(c, lo);
    if f_lo == 0.0 {
        return lo;
    }
    let rising = f_lo < 0.0;
    let mut x = 0.5 * (lo + hi);
    // Bisection alone halves the bracket each step and needs about 64 steps from any finite
    // bracket; Newton's steps, taken when they stay inside, usually finish in a handful.
    for _ in 0..128 {
        let (f, slope) = evaluate(c, x);
        if f == 0.0 {
            return x;
        }
        if (f < 0.0) == rising {
            lo = x;
        } else {
            hi = x;
        }
        let newton = x - f / slope;
        let next = if newton > lo && newton < hi && slope != 0.0 { newton } else { 0.5 * (lo + hi) };
        if next == x || hi - lo <= 2.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE) {
            return next;
        }
        x = next;
    }
    x
}

/// The real roots of `c[0] + c[1] x + ... + c[n] x^n` (`n = c.len() - 1`, at most 4, with
/// `c[n] != 0`), each once, in increasing order. A critical point where the value is zero to
/// rounding is a (double) root.
///
/// `sizes[i]` is the size of what `c[i]` was computed from (at least `|c[i]|`): a coefficient that
/// is the small difference of large terms carries their rounding, and the value at a critical
/// point counts as zero within [`TOUCH`] of those sizes, not of the difference's. (A half-angle
/// quartic's constant term near `u = 0` is such a difference: measured against its own size, the
/// tangency of a wrist singularity was missed.)
pub(crate) fn real_roots(c: &[f64], sizes: &[f64]) -> Roots {
    debug_assert_eq!(c.len(), sizes.len(), "one size per coefficient");
    let n = c.len() - 1;
    let mut roots = Roots::NONE;
    if n == 0 {
        return roots;
    }
    if n == 1 {
        roots.push(-c[0] / c[1]);
        return roots;
    }
    // Every root lies within Cauchy's bound.
    let lead = c[n];
    let bound = 1.0 + c[..n].iter().fold(0.0_f64, |m, &x| m.max((x / lead).abs()));
    let mut derivative = [0.0; 4];
    let mut derivative_sizes = [0.0; 4];
    for i in 0..n {
        derivative[i] = c[i + 1] * (i + 1) as f64;
        derivative_sizes[i] = sizes[i + 1] * (i + 1) as f64;
    }
    let critical = real_roots(&derivative[..n], &derivative_sizes[..n]);
    let mut edges = [0.0; 5];
    let mut count = 0;
    edges[count] = -bound;
    count += 1;
    for &x in critical.as_slice() {
        if x > -bound && x < bound {
            edges[count] = x;
            count += 1;
        }
    }
    // A critical point whose value is zero to rounding is a root, and its value counts as zero:
    // the sign change rounding may leave beside it is the same (double) root.
    edges[count] = bound;
    let mut lo = edges[0];
    let (mut f_lo, _) = evaluate(c, lo);
    for (i, &hi) in edges[1..=count].iter().enumerate() {
        let (mut f_hi, _) = evaluate(c, hi);
        // Every edge but the last (the bound) is a critical point.
        let touches = i + 1 < count && f_hi.abs() <= TOUCH * size_at(sizes, hi);
        if touches {
            f_hi = 0.0;
        }
        if f_lo != 0.0 && f_hi != 0.0 && (f_lo < 0.0) != (f_hi < 0.0) {
            roots.push(bracketed(c, lo, hi));
        }
        if touches {
            roots.push(hi);
        }
        lo = hi;
        f_lo = f_hi;
    }
    roots
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Coefficients computed exactly: each is its own size.
    fn own_sizes(c: &[f64; 5]) -> [f64; 5] {
        c.map(f64::abs)
    }

    /// The coefficients of `lead * (x - r1) ... (x - rk)`, lowest first.
    fn from_roots(lead: f64, roots: &[f64]) -> [f64; 5] {
        let mut c = [0.0; 5];
        c[0] = lead;
        for (k, &r) in roots.iter().enumerate() {
            // Multiply by (x - r).
            for i in (0..=k + 1).rev() {
                let shifted = if i > 0 { c[i - 1] } else { 0.0 };
                c[i] = shifted - r * c[i];
            }
        }
        c
    }

    #[test]
    fn four_distinct_roots_are_found_in_order() {
        let c = from_roots(2.5, &[-3.0, -0.25, 0.5, 7.0]);
        let roots = real_roots(&c, &own_sizes(&c));
        assert_eq!(roots.as_slice().len(), 4);
        for (found, expected) in roots.as_slice().iter().zip([-3.0, -0.25, 0.5, 7.0]) {
            assert!((found - expected).abs() < 1e-13, "{roots:?}");
        }
    }

    #[test]
    fn no_real_roots_gives_none() {
        // (x^2 + 1)(x^2 + 2x + 5)
        let c = [5.0, 2.0, 6.0, 2.0, 1.0];
        assert!(real_roots(&c, &own_sizes(&c)).as_slice().is_empty());
    }

    #[test]
    fn a_double_root_is_found_once() {
        let c = from_roots(1.0, &[1.5, 1.5, -2.0, 4.0]);
        let roots = real_roots(&c, &own_sizes(&c));
        assert_eq!(roots.as_slice().len(), 3, "{roots:?}");
        assert!(roots.as_slice().iter().any(|r| (r - 1.5).abs() < 1e-7));
    }

    /// A double root at `x = 0.004` (a local maximum touching zero) that rounding pushes 1e-15
    /// below zero, as it does to coefficients computed from terms of size 10 (a half-angle
    /// quartic's): measured against the coefficients' own sizes (near `x = 0` mostly the constant
    /// term's 1e-4) that value is 1e-11 off zero and the root is lost; against the sizes they came
    /// from, it is a root.
    #[test]
    fn a_double_root_is_found_within_the_size_its_coefficients_came_from() {
        let mut c = from_roots(10.0, &[0.004, 0.004, -0.7, 0.9]);
        c[0] -= 1e-15;
        let own = real_roots(&c, &own_sizes(&c));
        assert_eq!(own.as_slice().len(), 2, "measured against its own size the touch is lost: {own:?}");
        let roots = real_roots(&c, &[10.0; 5]);
        assert_eq!(roots.as_slice().len(), 3, "{roots:?}");
        assert!(roots.as_slice().iter().any(|r| (r - 0.004).abs() < 1e-6), "{roots:?}");
    }

    #[test]
    fn lower_degrees_work() {
        assert_eq!(real_roots(&[-6.0, 2.0], &[6.0, 2.0]).as_slice(), &[3.0]);
        let quadratic = real_roots(&[-2.0, 1.0, 1.0], &[2.0, 1.0, 1.0]);
        assert_eq!(quadratic.as_slice().len(), 2);
        assert!((quadratic.as_slice()[0] + 2.0).abs() < 1e-15 && (quadratic.as_slice()[1] - 1.0).abs() < 1e-15);
        let cubic = from_roots(-1.0, &[0.1, 0.2, 30.0]);
        let cubic = real_roots(&cubic[..4], &own_sizes(&cubic)[..4]);
        assert_eq!(cubic.as_slice().len(), 3, "{cubic:?}");
    }
}
