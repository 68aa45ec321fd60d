//! Subproblems 5 and 6: two angles tied by two scalar equations, each linear in the cosine and
//! sine of both. Both reduce to one problem ([`circle_pair`]): unit vectors `x` and `y` in the
//! plane with `A x + B y = d` (`A`, `B` 2 x 2). Solving the better-conditioned of `A`, `B` for its
//! vector leaves `|y|^2 = 1` (or `|x|^2 = 1`): a trigonometric polynomial of degree two in one
//! angle, whose roots are those of a quartic in the tangent of the half angle
//! ([`super::polynomial`]). At most four pairs; out of reach, the angles where the equation comes
//! closest, flagged.

use super::super::bounded::BoundedList;
use super::super::vector::{V3, add, cross, dot, norm_squared};
use super::polynomial::real_roots;
use super::{DEGENERATE, Quality, REACH_SLACK, Turn, rotation_onto};

/// Up to four solved angle pairs (subproblem 6), with the quality they share.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurnPairs {
    pairs: BoundedList<(Turn, Turn), 4>,
    /// Whether the pairs are exact (the equations met) and whether one was degenerate.
    pub quality: Quality,
}

impl TurnPairs {
    const NONE: TurnPairs = TurnPairs { pairs: BoundedList::new((Turn::ZERO, Turn::ZERO)), quality: Quality::EXACT };

    /// Adds a pair: one of at most four roots of a quartic, or the one a degenerate or continuous
    /// case gives.
    fn push(&mut self, pair: (Turn, Turn)) {
        #[allow(clippy::expect_used, reason = "invariant: a quartic's roots, at most four")]
        self.pairs.push(pair).expect("invariant: at most four roots of a degree-two trigonometric polynomial");
    }

    /// The pairs found.
    pub fn as_slice(&self) -> &[(Turn, Turn)] {
        self.pairs.as_slice()
    }
}

/// Up to four solved angle triples (subproblem 5), with the quality they share.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurnTriples {
    triples: BoundedList<[Turn; 3], 4>,
    /// Whether the triples are exact and whether any angle was degenerate.
    pub quality: Quality,
}

impl TurnTriples {
    /// The triples found.
    pub fn as_slice(&self) -> &[[Turn; 3]] {
        self.triples.as_slice()
    }
}

/// `f(t) = k[0] + k[1] cos t + k[2] sin t + k[3] cos 2t + k[4] sin 2t`.
type TrigQuadratic = [f64; 5];

/// At most four angles on the circle, as `(cos, sin)` pairs.
type Angles = BoundedList<(f64, f64), 4>;

/// Adds an angle to a list of at most four: the roots (or extrema) of a degree-two trigonometric
/// polynomial, or of its derivative, are at most four.
fn push_angle(angles: &mut Angles, cs: (f64, f64)) {
    #[allow(clippy::expect_used, reason = "invariant: a degree-two trigonometric polynomial has at most four roots")]
    angles.push(cs).expect("invariant: at most four roots of a degree-two trigonometric polynomial");
}

fn trig_value(k: &TrigQuadratic, (c, s): (f64, f64)) -> f64 {
    k[0] + k[1] * c + k[2] * s + k[3] * (c * c - s * s) + k[4] * (2.0 * s * c)
}

/// The eighth turns, whose cosines and sines are exact to rounding: the candidate shifts that keep
/// a root away from the half-angle substitution's point at infinity.
const EIGHTHS: [(f64, f64); 8] = {
    let h = core::f64::consts::FRAC_1_SQRT_2;
    [(1.0, 0.0), (h, h), (0.0, 1.0), (-h, h), (-1.0, 0.0), (-h, -h), (0.0, -1.0), (h, -h)]
};

/// `(cos, sin)` of the sum of two angles given by theirs.
fn compose((c1, s1): (f64, f64), (c2, s2): (f64, f64)) -> (f64, f64) {
    (c1 * c2 - s1 * s2, s1 * c2 + c1 * s2)
}

/// The roots of `f` on the circle, as `(cos, sin)` pairs (at most four), or an empty set when `f`
/// keeps one sign. `f` must not vanish identically.
///
/// With `t = phi + tau` and `u = tan(tau / 2)`, `(1 + u^2)^2 f` is a quartic in `u` whose leading
/// coefficient is `f(phi + pi)`. Taking `phi + pi` at the eighth turn where `|f|` is largest keeps
/// that coefficient as large as `f` allows (eight samples determine a degree-two trigonometric
/// polynomial), so no root sits near `u = infinity`.
fn trig_roots(k: &TrigQuadratic) -> Angles {
    let mut best = 0;
    for (i, &cs) in EIGHTHS.iter().enumerate() {
        if trig_value(k, cs).abs() > trig_value(k, EIGHTHS[best]).abs() {
            best = i;
        }
    }
    // phi = (the best eighth) + pi.
    let phi = EIGHTHS[(best + 4) % 8];
    let phi2 = compose(phi, phi);
    // g(tau) = f(phi + tau), in the same basis.
    let g0 = k[0];
    let g1c = k[1] * phi.0 + k[2] * phi.1;
    let g1s = -k[1] * phi.1 + k[2] * phi.0;
    let g2c = k[3] * phi2.0 + k[4] * phi2.1;
    let g2s = -k[3] * phi2.1 + k[4] * phi2.0;
    let quartic = [g0 + g1c + g2c, 2.0 * g1s + 4.0 * g2s, 2.0 * g0 - 6.0 * g2c, 2.0 * g1s - 4.0 * g2s, g0 - g1c + g2c];
    // What each coefficient is computed from: near a root at `tau = 0` the first two are small
    // differences of `f`'s terms and carry those terms' rounding, so a tangency there is judged
    // against these sizes.
    let (size0, size1, size2) = (k[0].abs(), k[1].abs() + k[2].abs(), k[3].abs() + k[4].abs());
    let sizes = [
        size0 + size1 + size2,
        2.0 * size1 + 4.0 * size2,
        2.0 * size0 + 6.0 * size2,
        2.0 * size1 + 4.0 * size2,
        size0 + size1 + size2,
    ];
    let roots = real_roots(&quartic, &sizes);
    let mut out = Angles::new((1.0, 0.0));
    for &u in roots.as_slice() {
        let w = 1.0 + u * u;
        push_angle(&mut out, compose(phi, ((1.0 - u * u) / w, 2.0 * u / w)));
    }
    out
}

/// The angles where `|f|` is smallest when `f` has no root: the minima of `f` if it is positive,
/// its maxima if negative (the roots of `f'` where `f f'' > 0`).
fn closest_approaches(k: &TrigQuadratic) -> Angles {
    let slope = [0.0, k[2], -k[1], 2.0 * k[4], -2.0 * k[3]];
    let curvature = |(c, s): (f64, f64)| -k[1] * c - k[2] * s - 4.0 * k[3] * (c * c - s * s) - 8.0 * k[4] * s * c;
    let critical = if slope.iter().any(|&x| x != 0.0) {
        trig_roots(&slope)
    } else {
        let mut constant = Angles::new((1.0, 0.0));
        push_angle(&mut constant, (1.0, 0.0));
        constant
    };
    let mut out = Angles::new((1.0, 0.0));
    for &cs in critical.as_slice() {
        if trig_value(k, cs) * curvature(cs) >= 0.0 {
            push_angle(&mut out, cs);
        }
    }
    if out.is_empty() {
        // Rounding can hide the sign of a flat extremum: keep the critical point of least |f|
        // (the first if there is none, as before: (1, 0)).
        let mut best = critical.as_slice().first().copied().unwrap_or((1.0, 0.0));
        for &cs in critical.as_slice() {
            if trig_value(k, cs).abs() < trig_value(k, best).abs() {
                best = cs;
            }
        }
        push_angle(&mut out, best);
    }
    out
}

type M2 = [[f64; 2]; 2];

fn det(m: &M2) -> f64 {
    m[0][0] * m[1][1] - m[0][1] * m[1][0]
}

/// Unit `x = (cos t1, sin t1)` and `y = (cos t2, sin t2)` with `A x + B y = d`: at most four
/// pairs. Out of reach, the angles `t1` where `|y|` comes closest to one, `y` then normalised,
/// flagged not exact. When neither `A` nor `B` can be solved (both of rank below two) the angles
/// are not determined: one pair of zeros, flagged singular and not exact.
pub(crate) fn circle_pair(a: M2, b: M2, d: [f64; 2]) -> TurnPairs {
    // Each equation scaled to its largest entry, so the two conditions compare.
    let (mut a, mut b, mut d) = (a, b, d);
    for i in 0..2 {
        let size = [a[i][0], a[i][1], b[i][0], b[i][1], d[i]].iter().fold(0.0_f64, |m, &x| m.max(x.abs()));
        if size > 0.0 {
            for j in 0..2 {
                a[i][j] /= size;
                b[i][j] /= size;
            }
            d[i] /= size;
        }
    }
    let (det_a, det_b) = (det(&a), det(&b));
    let mut out = TurnPairs::NONE;
    if det_a.abs().max(det_b.abs()) <= DEGENERATE {
        out.push((Turn::ZERO, Turn::ZERO));
        out.quality = Quality { exact: false, singular: true };
        return out;
    }
    // Solve the better-conditioned matrix for its vector: y = e - F x.
    let swapped = det_a.abs() > det_b.abs();
    let (a, b, det_b) = if swapped { (b, a, det_a) } else { (a, b, det_b) };
    let inverse = [[b[1][1] / det_b, -b[0][1] / det_b], [-b[1][0] / det_b, b[0][0] / det_b]];
    let apply = |m: &M2, v: [f64; 2]| [m[0][0] * v[0] + m[0][1] * v[1], m[1][0] * v[0] + m[1][1] * v[1]];
    let e = apply(&inverse, d);
    let f = [apply(&inverse, [a[0][0], a[1][0]]), apply(&inverse, [a[0][1], a[1][1]])]; // columns
    // |e - F x|^2 - 1 with x = (cos t, sin t), G = F^T F, g = F^T e.
    let g00 = f[0][0] * f[0][0] + f[0][1] * f[0][1];
    let g11 = f[1][0] * f[1][0] + f[1][1] * f[1][1];
    let g01 = f[0][0] * f[1][0] + f[0][1] * f[1][1];
    let (ge0, ge1) = (f[0][0] * e[0] + f[0][1] * e[1], f[1][0] * e[0] + f[1][1] * e[1]);
    let ee = e[0] * e[0] + e[1] * e[1];
    let k = [ee - 1.0 + 0.5 * (g00 + g11), -2.0 * ge0, -2.0 * ge1, 0.5 * (g00 - g11), g01];
    let scale = 1.0 + ee + g00 + g11;
    if k.iter().all(|x| x.abs() <= DEGENERATE * scale) {
        // Every t1 serves: a continuum.
        out.push(pair_at(&e, &f, (1.0, 0.0), swapped));
        out.quality = Quality { exact: true, singular: true };
        return out;
    }
    let roots = trig_roots(&k);
    let (angles, exact) = if !roots.is_empty() {
        (roots, true)
    } else {
        let closest = closest_approaches(&k);
        let exact = closest.as_slice().iter().all(|&cs| trig_value(&k, cs).abs() <= REACH_SLACK * scale);
        (closest, exact)
    };
    for &cs in angles.as_slice() {
        out.push(pair_at(&e, &f, cs, swapped));
    }
    out.quality = Quality { exact, singular: false };
    out
}

/// The pair at `x = cs`, `y = e - F x` normalised, in the caller's order.
fn pair_at(e: &[f64; 2], f: &[[f64; 2]; 2], (c, s): (f64, f64), swapped: bool) -> (Turn, Turn) {
    let y = [e[0] - f[0][0] * c - f[1][0] * s, e[1] - f[0][1] * c - f[1][1] * s];
    let solved = Turn::of(s, c);
    let other = Turn::of(y[1], y[0]);
    if swapped { (other, solved) } else { (solved, other) }
}

/// `rot(k, t) p` as `along + cos t * across + sin t * turned`: the three parts of Rodrigues'
/// formula, `(k . p) k`, `p - (k . p) k` and `k x p`, seen through `h`: `(h . along, h . across,
/// h . turned)`.
fn seen_through(h: V3, k: V3, p: V3) -> (f64, f64, f64) {
    let along = dot(k, p);
    (dot(h, k) * along, dot(h, p) - dot(h, k) * along, dot(h, cross(k, p)))
}

/// Subproblem 6: the angle pairs `(t1, t2)` with
/// `h1 . rot(k1, t1) p1 + h2 . rot(k2, t2) p2 = d1` and
/// `h3 . rot(k3, t1) p3 + h4 . rot(k4, t2) p4 = d2` (unit axes `k`), at most four.
pub fn two_heights(h: [V3; 4], k: [V3; 4], p: [V3; 4], d: [f64; 2]) -> TurnPairs {
    let parts = [0, 1, 2, 3].map(|i| seen_through(h[i], k[i], p[i]));
    let a = [[parts[0].1, parts[0].2], [parts[2].1, parts[2].2]];
    let b = [[parts[1].1, parts[1].2], [parts[3].1, parts[3].2]];
    let rhs = [d[0] - parts[0].0 - parts[1].0, d[1] - parts[2].0 - parts[3].0];
    circle_pair(a, b, rhs)
}

/// Subproblem 5: the angle triples `(t1, t2, t3)` with
/// `p0 + rot(k1, t1) p1 = rot(k2, t2) (p2 + rot(k3, t3) p3)` (unit axes `k`), at most four.
///
/// A rotation about `k2` keeps both a vector's component along `k2` and its length, so
/// `k2 . (p0 + rot(k1, t1) p1) = k2 . (p2 + rot(k3, t3) p3)` and
/// `|p0 + rot(k1, t1) p1|^2 = |p2 + rot(k3, t3) p3|^2` tie `t1` to `t3` alone (`circle_pair`);
/// then `t2` is subproblem 1.
pub fn three_rotations(p0: V3, k1: V3, p1: V3, k2: V3, p2: V3, k3: V3, p3: V3) -> TurnTriples {
    let (along1, across1, turned1) = seen_through(k2, k1, p1);
    let (along3, across3, turned3) = seen_through(k2, k3, p3);
    // |p0 + rot(k1, t1) p1|^2 = |p0|^2 + |p1|^2 + 2 p0 . rot(k1, t1) p1, and the same on the right.
    let (on1, cos1, sin1) = seen_through(p0, k1, p1);
    let (on3, cos3, sin3) = seen_through(p2, k3, p3);
    let a = [[across1, turned1], [2.0 * cos1, 2.0 * sin1]];
    let b = [[-across3, -turned3], [-2.0 * cos3, -2.0 * sin3]];
    let d = [
        dot(k2, p2) + along3 - dot(k2, p0) - along1,
        norm_squared(p2) + norm_squared(p3) + 2.0 * on3 - norm_squared(p0) - norm_squared(p1) - 2.0 * on1,
    ];
    let pairs = circle_pair(a, b, d);
    let mut out = TurnTriples { triples: BoundedList::new([Turn::ZERO; 3]), quality: pairs.quality };
    for &(t1, t3) in pairs.as_slice() {
        let left = add(p0, t1.rotate(k1, p1));
        let right = add(p2, t3.rotate(k3, p3));
        let (t2, second) = rotation_onto(k2, right, left);
        out.quality = out.quality.and(second);
        #[allow(clippy::expect_used, reason = "invariant: one triple per pair, both lists of four")]
        out.triples.push([t1, t2, t3]).expect("invariant: one triple per pair, and pairs are at most four");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::super::vector::{rotate, scale, sub};
    use super::*;

    fn unit(v: V3) -> V3 {
        scale(v, 1.0 / libm::sqrt(norm_squared(v)))
    }

    fn close(a: V3, b: V3) -> bool {
        norm_squared(sub(a, b)) <= 1e-24 * (1.0 + norm_squared(a))
    }

    #[test]
    fn trig_roots_are_roots_and_all_of_them() {
        let k = [0.1, -0.4, 0.7, 0.9, -0.2];
        let roots = trig_roots(&k);
        let n = roots.len();
        assert!(n >= 2, "a degree-two polynomial crossing zero has an even number of roots: {n}");
        for &(c, s) in roots.as_slice() {
            assert!((c * c + s * s - 1.0).abs() < 1e-15);
            assert!(trig_value(&k, (c, s)).abs() < 1e-14, "{}", trig_value(&k, (c, s)));
        }
        // And it finds them all: count the sign changes over a fine sweep.
        let mut changes = 0;
        let steps = 100_000;
        let mut previous = trig_value(&k, (1.0, 0.0));
        for i in 1..=steps {
            let t = core::f64::consts::TAU * i as f64 / steps as f64;
            let value = trig_value(&k, (libm::cos(t), libm::sin(t)));
            if (value < 0.0) != (previous < 0.0) {
                changes += 1;
            }
            previous = value;
        }
        assert_eq!(changes, n);
    }

    /// `f(t) = (1 - cos(t - t0)) (alpha + beta cos(t - t1))` touches zero at `t0` (a double root)
    /// and crosses it twice where `alpha + beta cos(t - t1) = 0`. With `t0` near an eighth turn the
    /// half-angle quartic puts the double root near `u = 0`, where its first coefficients are small
    /// differences of `f`'s terms: the tangency must still be found, on every such `f`.
    #[test]
    fn a_tangency_near_the_substitutions_origin_is_a_root() {
        let mut missed = 0;
        for i in 0..2000 {
            let x = |j: u32| libm::sin(f64::from(i * 7 + j) * 12.9898) * 0.5 + 0.5;
            let t0 = core::f64::consts::FRAC_PI_4 * f64::from(i % 8) + 0.02 * (x(0) - 0.5);
            let (alpha, t1) = (0.2 + 5.0 * x(1), 6.0 * x(2));
            // |beta| > alpha: the second factor crosses zero.
            let beta = (alpha + 0.1 + 5.0 * x(4)) * if x(3) < 0.5 { -1.0 } else { 1.0 };
            let k = [
                alpha - 0.5 * beta * libm::cos(t1 - t0),
                beta * libm::cos(t1) - alpha * libm::cos(t0),
                beta * libm::sin(t1) - alpha * libm::sin(t0),
                -0.5 * beta * libm::cos(t0 + t1),
                -0.5 * beta * libm::sin(t0 + t1),
            ];
            let roots = trig_roots(&k);
            let touching = roots.as_slice().iter().any(|&(c, s)| {
                let away = libm::atan2(s * libm::cos(t0) - c * libm::sin(t0), c * libm::cos(t0) + s * libm::sin(t0));
                away.abs() < 1e-6
            });
            missed += usize::from(!touching);
        }
        assert_eq!(missed, 0, "{missed} of 2,000 tangencies missed");
    }

    #[test]
    fn subproblem_6_recovers_both_angles() {
        let h = [unit([0.2, 0.1, 1.0]), unit([0.3, -1.0, 0.1]), unit([1.0, 0.4, -0.2]), unit([0.0, 0.6, 1.0])];
        let k = [unit([1.0, 1.0, 0.0]), unit([0.0, 0.3, 1.0]), unit([1.0, 1.0, 0.0]), unit([0.0, 0.3, 1.0])];
        let p = [[0.4, -0.2, 0.9], [1.1, 0.5, -0.3], [-0.6, 0.8, 0.2], [0.3, 0.3, 0.7]];
        let (t1, t2) = (0.9, -2.4);
        let d = [
            dot(h[0], rotate(k[0], t1, p[0])) + dot(h[1], rotate(k[1], t2, p[1])),
            dot(h[2], rotate(k[2], t1, p[2])) + dot(h[3], rotate(k[3], t2, p[3])),
        ];
        let pairs = two_heights(h, k, p, d);
        assert!(pairs.quality.exact && !pairs.quality.singular, "{pairs:?}");
        for (a, b) in pairs.as_slice() {
            let left = dot(h[0], a.rotate(k[0], p[0])) + dot(h[1], b.rotate(k[1], p[1]));
            let right = dot(h[2], a.rotate(k[2], p[2])) + dot(h[3], b.rotate(k[3], p[3]));
            assert!((left - d[0]).abs() < 1e-13 && (right - d[1]).abs() < 1e-13, "{a:?} {b:?}");
        }
        assert!(
            pairs.as_slice().iter().any(|(a, b)| (a.angle - t1).abs() < 1e-12 && (b.angle - t2).abs() < 1e-12),
            "{pairs:?}"
        );
    }

    #[test]
    fn subproblem_5_recovers_all_three_angles() {
        let (k1, k2, k3) = (unit([0.0, 0.1, 1.0]), unit([1.0, -0.2, 0.3]), unit([0.2, 1.0, 0.5]));
        let (p1, p2, p3) = ([0.5, 0.2, -0.1], [0.1, 0.7, 0.3], [0.6, -0.4, 0.2]);
        for (t1, t2, t3) in [(0.4, -1.3, 2.2), (-2.9, 0.2, -0.6), (1.7, 3.0, 0.05)] {
            let right = rotate(k2, t2, add(p2, rotate(k3, t3, p3)));
            let p0 = sub(right, rotate(k1, t1, p1));
            let triples = three_rotations(p0, k1, p1, k2, p2, k3, p3);
            assert!(triples.quality.exact, "{triples:?}");
            for [a, b, c] in triples.as_slice() {
                assert!(close(add(p0, a.rotate(k1, p1)), b.rotate(k2, add(p2, c.rotate(k3, p3)))), "{a:?} {b:?} {c:?}");
            }
            assert!(
                triples.as_slice().iter().any(|[a, b, c]| {
                    (a.angle - t1).abs() < 1e-11 && (b.angle - t2).abs() < 1e-11 && (c.angle - t3).abs() < 1e-11
                }),
                "{triples:?}"
            );
        }
    }

    #[test]
    fn subproblem_5_out_of_reach_is_flagged_and_finite() {
        let (k1, k2, k3) = ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        // The right side is at most 2 long, the left at least 100.
        let triples = three_rotations([100.0, 0.0, 0.0], k1, [1.0, 0.0, 0.0], k2, [1.0, 0.0, 0.0], k3, [0.0, 0.0, 1.0]);
        assert!(!triples.quality.exact);
        assert!(!triples.as_slice().is_empty());
        assert!(triples.as_slice().iter().flatten().all(|t| t.angle.is_finite() && t.cos.is_finite()));
    }

    #[test]
    fn degenerate_pairs_are_flagged_not_nan() {
        let pairs = circle_pair([[0.0; 2]; 2], [[0.0; 2]; 2], [1.0, 0.0]);
        assert_eq!(pairs.as_slice(), &[(Turn::ZERO, Turn::ZERO)]);
        assert_eq!(pairs.quality, Quality { exact: false, singular: true });
    }
}
