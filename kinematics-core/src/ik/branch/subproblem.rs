//! The Paden-Kahan subproblems 1 to 4 (IK-Geo's numbering, arXiv 2211.05737) for one branch, on
//! any [`Algebra`], with the tolerances of [`crate::ik::subproblem`]. Where that module returns
//! both roots of an equation, these take a branch sign (`+1` or `-1`) and return the root it
//! picks; where it branches on a degenerate case, these select.

use super::algebra::{Algebra, Flags, Turn, Vector};
use crate::ik::subproblem::{DEGENERATE, DOUBLE_ROOT, REACH_SLACK};

/// The subproblems, for every [`Algebra`].
pub trait Subproblems: Algebra {
    /// `atan2(y, x)` as a turn, its cosine and sine the vector normalised (one division, for the
    /// reciprocal of its length); no turn for the zero vector, nor where `none` is set.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn turn_of(&mut self, y: Self::Value, x: Self::Value, none: Self::Value) -> Turn<Self::Value> {
        let (xx, yy) = (self.mul(x, x), self.mul(y, y));
        let r2 = self.add(xx, yy);
        let r = self.sqrt(r2);
        let zero = self.constant(0.0);
        let vanishing = self.at_most(r, zero);
        let none = self.or(none, vanishing);
        let one = self.constant(1.0);
        let safe = self.select(none, one, r);
        let inverse = self.div(one, safe);
        let (cos, sin) = (self.mul(x, inverse), self.mul(y, inverse));
        let turn = self.turn(cos, sin);
        let zero_turn = self.zero_turn();
        self.select_turn(none, zero_turn, turn)
    }

    /// The part of `p` across the unit axis `k`: `p - (k . p) k`.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn across(&mut self, k: Vector<Self::Value>, p: Vector<Self::Value>) -> Vector<Self::Value> {
        let along = self.dot(k, p);
        let on_axis = self.scale(k, along);
        self.vsub(p, on_axis)
    }

    /// The flag `|k x p|^2 <= limit |p|^2`: `p` on the axis `k`, to `limit` (a squared sine).
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn on_axis(&mut self, k: Vector<Self::Value>, p: Vector<Self::Value>, limit: Self::Value) -> Self::Value {
        let kxp = self.cross(k, p);
        let across = self.norm_squared(kxp);
        let length = self.norm_squared(p);
        let bound = self.mul(limit, length);
        self.at_most(across, bound)
    }

    /// Subproblem 1: the angle `t` with `rot(k, t) p1 = p2` about the unit axis `k`, or the
    /// least-squares best; `0`, flagged singular, when either vector lies on the axis.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn rotation_onto(
        &mut self,
        k: Vector<Self::Value>,
        p1: Vector<Self::Value>,
        p2: Vector<Self::Value>,
    ) -> (Turn<Self::Value>, Flags<Self::Value>) {
        let u1 = self.across(k, p1);
        let u2 = self.across(k, p2);
        let x = self.dot(u1, u2);
        let u1xu2 = self.cross(u1, u2);
        let y = self.dot(k, u1xu2);
        let limit = self.constant(DEGENERATE * DEGENERATE);
        let first = self.on_axis(k, p1, limit);
        let second = self.on_axis(k, p2, limit);
        let singular = self.or(first, second);
        let turn = self.turn_of(y, x, singular);
        let one = self.constant(1.0);
        (turn, Flags { exact: one, singular })
    }

    /// The root `sign` picks of `a cos t + b sin t = c`: `atan2(b, a) + sign * acos(c / hypot(a, b))`,
    /// the least-squares best out of reach, `0` (singular) when `a = b = 0`.
    ///
    /// Written on squares: with `r^2 = a^2 + b^2` and `w = sqrt(r^2 - c^2)`, `cos t = (a c - sign b w) /
    /// r^2` and `sin t = (b c + sign a w) / r^2`, one square root and one division on the way
    /// (the looped `cos_sin_equation` takes `r`, then three quotients by it, then a second root: the
    /// same tests and the same values to rounding, on a path half as long). Near a double root
    /// (`|c| / r` within `DOUBLE_ROOT` of 1) and out of reach the root is snapped to `atan2(b, a)`
    /// or its opposite, as there.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn cos_sin_equation(
        &mut self,
        a: Self::Value,
        b: Self::Value,
        c: Self::Value,
        sign: Self::Value,
    ) -> (Turn<Self::Value>, Flags<Self::Value>) {
        let (aa, bb, cc) = (self.mul(a, a), self.mul(b, b), self.mul(c, c));
        let r2 = self.add(aa, bb);
        // r <= DEGENERATE max(r, |c|), and |c| <= DEGENERATE max(r, |c|) for the degenerate case's
        // exactness, on squares.
        let r2_over = self.sub(r2, cc);
        let scale2 = self.select(r2_over, r2, cc);
        let tiny = self.constant(DEGENERATE * DEGENERATE);
        let bound = self.mul(tiny, scale2);
        let degenerate = self.at_most(r2, bound);
        let exact_degenerate = self.at_most(cc, bound);
        let one = self.constant(1.0);
        let safe = self.select(degenerate, one, r2);
        let inverse2 = self.div(one, safe);
        // |c| / r <= 1 + REACH_SLACK, and |c| / r >= 1 - DOUBLE_ROOT, on squares.
        let reach = self.constant((1.0 + REACH_SLACK) * (1.0 + REACH_SLACK));
        let reach = self.mul(reach, r2);
        let exact = self.at_most(cc, reach);
        let double = self.constant((1.0 - DOUBLE_ROOT) * (1.0 - DOUBLE_ROOT));
        let double = self.mul(double, r2);
        let near = self.at_most(double, cc);
        // Away from a double root, r^2 - c^2 > 0.
        let w2 = self.sub(r2, cc);
        let w = self.sqrt(w2);
        let (ac, bc) = (self.mul(a, c), self.mul(b, c));
        let (bw, aw) = (self.mul(b, w), self.mul(a, w));
        let (signed_bw, signed_aw) = (self.mul(sign, bw), self.mul(sign, aw));
        let cos = self.sub(ac, signed_bw);
        let sin = self.add(bc, signed_aw);
        let (cos, sin) = (self.mul(cos, inverse2), self.mul(sin, inverse2));
        // At a double root or beyond: (a, b) / r, turned to the side of c.
        let minus_one = self.constant(-1.0);
        let side = self.select(c, one, minus_one);
        let inverse = self.sqrt(inverse2);
        let toward = self.mul(side, inverse);
        let (snapped_cos, snapped_sin) = (self.mul(a, toward), self.mul(b, toward));
        let cos = self.select(near, snapped_cos, cos);
        let sin = self.select(near, snapped_sin, sin);
        let turn = self.turn(cos, sin);
        let zero_turn = self.zero_turn();
        let turn = self.select_turn(degenerate, zero_turn, turn);
        let exact = self.select(degenerate, exact_degenerate, exact);
        (turn, Flags { exact, singular: degenerate })
    }

    /// Subproblem 3: the angle `t` with `|rot(k, t) p1 - p2| = d`, given `d^2`, the root `sign`
    /// picks.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn rotation_to_distance(
        &mut self,
        k: Vector<Self::Value>,
        p1: Vector<Self::Value>,
        p2: Vector<Self::Value>,
        d_squared: Self::Value,
        sign: Self::Value,
    ) -> (Turn<Self::Value>, Flags<Self::Value>) {
        let (kp1, kp2) = (self.dot(k, p1), self.dot(k, p2));
        let along = self.mul(kp1, kp2);
        let p1p2 = self.dot(p1, p2);
        let a = self.sub(p1p2, along);
        let p1xp2 = self.cross(p1, p2);
        let b = self.dot(k, p1xp2);
        let (n1, n2) = (self.norm_squared(p1), self.norm_squared(p2));
        let lengths = self.add(n1, n2);
        let difference = self.sub(lengths, d_squared);
        let half = self.constant(0.5);
        let halved = self.mul(half, difference);
        let c = self.sub(halved, along);
        self.cos_sin_equation(a, b, c, sign)
    }

    /// Subproblem 4: the angle `t` with `h . rot(k, t) p = d`, the root `sign` picks.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn rotation_to_height(
        &mut self,
        h: Vector<Self::Value>,
        k: Vector<Self::Value>,
        p: Vector<Self::Value>,
        d: Self::Value,
        sign: Self::Value,
    ) -> (Turn<Self::Value>, Flags<Self::Value>) {
        let (hk, kp) = (self.dot(h, k), self.dot(k, p));
        let hk_kp = self.mul(hk, kp);
        let hp = self.dot(h, p);
        let a = self.sub(hp, hk_kp);
        let kxp = self.cross(k, p);
        let b = self.dot(h, kxp);
        let c = self.sub(d, hk_kp);
        self.cos_sin_equation(a, b, c, sign)
    }

    /// Subproblem 4 for an orthogonal wrist (`h` and `p` square to `k`, all unit): the angle `t`
    /// with `h . rot(k, t) p = h . v`, the half-width's sine from `|h x v|` (its digits kept near
    /// the singularity). Always exact.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn rotation_to_height_on_great_circle(
        &mut self,
        h: Vector<Self::Value>,
        k: Vector<Self::Value>,
        p: Vector<Self::Value>,
        v: Vector<Self::Value>,
        sign: Self::Value,
    ) -> Turn<Self::Value> {
        let cos_phi = self.dot(h, p);
        let kxp = self.cross(k, p);
        let sin_phi = self.dot(h, kxp);
        let cos_delta = self.dot(h, v);
        let hxv = self.cross(h, v);
        let across = self.norm_squared(hxv);
        let sin_delta = self.sqrt(across);
        let (cc, ss) = (self.mul(cos_phi, cos_delta), self.mul(sin_phi, sin_delta));
        let signed_ss = self.mul(sign, ss);
        let cos = self.sub(cc, signed_ss);
        let (sc, cs) = (self.mul(sin_phi, cos_delta), self.mul(cos_phi, sin_delta));
        let signed_cs = self.mul(sign, cs);
        let sin = self.add(sc, signed_cs);
        self.turn(cos, sin)
    }

    /// Subproblem 2: the pair `(t1, t2)` with `rot(k1, t1) p1 = rot(k2, t2) p2` about axes that
    /// are not parallel, the crossing of the two cones `sign` picks; the least-squares best when
    /// they do not cross, and no turns (singular) when a vector is zero.
    #[cfg_attr(not(debug_assertions), inline(always))]
    #[allow(clippy::type_complexity, reason = "the two turns and their flags")]
    fn two_rotations(
        &mut self,
        k1: Vector<Self::Value>,
        p1: Vector<Self::Value>,
        k2: Vector<Self::Value>,
        p2: Vector<Self::Value>,
        sign: Self::Value,
    ) -> (Turn<Self::Value>, Turn<Self::Value>, Flags<Self::Value>) {
        let (n1, n2) = (self.norm_squared(p1), self.norm_squared(p2));
        let (n1, n2) = (self.sqrt(n1), self.sqrt(n2));
        let zero = self.constant(0.0);
        let one = self.constant(1.0);
        let (zero1, zero2) = (self.at_most(n1, zero), self.at_most(n2, zero));
        let degenerate = self.or(zero1, zero2);
        let gap = self.sub(n1, n2);
        let gap = self.abs(gap);
        let equal = self.at_most(gap, zero);
        let (safe1, safe2) = (self.select(n1, n1, one), self.select(n2, n2, one));
        let (inverse1, inverse2) = (self.div(one, safe1), self.div(one, safe2));
        let u1 = self.scale(p1, inverse1);
        let u2 = self.scale(p2, inverse2);
        let c = self.dot(k1, k2);
        let cc = self.mul(c, c);
        let s2 = self.sub(one, cc);
        let (a1, a2) = (self.dot(k1, u1), self.dot(k2, u2));
        // x = alpha k1 + beta k2 + gamma (k1 x k2), with k1 . x = a1, k2 . x = a2, |x| = 1.
        let c_a2 = self.mul(c, a2);
        let alpha = self.sub(a1, c_a2);
        let alpha = self.div(alpha, s2);
        let c_a1 = self.mul(c, a1);
        let beta = self.sub(a2, c_a1);
        let beta = self.div(beta, s2);
        let (alpha2, beta2) = (self.mul(alpha, alpha), self.mul(beta, beta));
        let two = self.constant(2.0);
        let twice_alpha = self.mul(two, alpha);
        let cross_term = self.mul(twice_alpha, beta);
        let cross_term = self.mul(cross_term, c);
        let rest = self.sub(one, alpha2);
        let rest = self.sub(rest, beta2);
        let rest = self.sub(rest, cross_term);
        let slack = self.constant(-REACH_SLACK);
        let exact = self.at_most(slack, rest);
        let clamped = self.select(rest, rest, zero);
        let over = self.div(clamped, s2);
        let gamma = self.sqrt(over);
        let (along1, along2) = (self.scale(k1, alpha), self.scale(k2, beta));
        let base = self.vadd(along1, along2);
        let normal = self.cross(k1, k2);
        let signed = self.mul(sign, gamma);
        let out = self.scale(normal, signed);
        let x = self.vadd(base, out);
        let (t1, first) = self.rotation_onto(k1, u1, x);
        let (t2, second) = self.rotation_onto(k2, u2, x);
        let quality = Flags { exact, singular: zero };
        let quality = self.both(quality, first);
        let quality = self.both(quality, second);
        let none = self.zero_turn();
        let t1 = self.select_turn(degenerate, none, t1);
        let t2 = self.select_turn(degenerate, none, t2);
        let exact = self.select(degenerate, equal, quality.exact);
        let singular = self.select(degenerate, one, quality.singular);
        (t1, t2, Flags { exact, singular })
    }
}

impl<A: Algebra> Subproblems for A {}
