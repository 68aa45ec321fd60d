//! The few operations on 3-vectors and 3x3 rotations the solvers need, on plain arrays; the
//! compiler's classification of a chain uses the same ones.

/// A 3-vector.
pub type V3 = [f64; 3];
/// A 3x3 matrix, row by row.
pub type M3 = [[f64; 3]; 3];

/// `a . b`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a x b`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// `a + b`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// `a - b`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `s a`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// `|a|^2`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn norm_squared(a: V3) -> f64 {
    dot(a, a)
}

/// `m * v`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn mul(m: &M3, v: V3) -> V3 {
    [dot(m[0], v), dot(m[1], v), dot(m[2], v)]
}

/// `m^T * v`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn mul_transposed(m: &M3, v: V3) -> V3 {
    [
        m[0][0] * v[0] + m[1][0] * v[1] + m[2][0] * v[2],
        m[0][1] * v[0] + m[1][1] * v[1] + m[2][1] * v[2],
        m[0][2] * v[0] + m[1][2] * v[1] + m[2][2] * v[2],
    ]
}

/// `a * b^T`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn mul_by_transpose(a: &M3, b: &M3) -> M3 {
    let row = |r: V3| [dot(r, b[0]), dot(r, b[1]), dot(r, b[2])];
    [row(a[0]), row(a[1]), row(a[2])]
}

/// `v` rotated by the angle whose cosine and sine are `c`, `s` about the unit axis `k`
/// (Rodrigues: `c v + s (k x v) + (1 - c)(k . v) k`).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn rotate_cs(k: V3, c: f64, s: f64, v: V3) -> V3 {
    let kv = dot(k, v) * (1.0 - c);
    let kxv = cross(k, v);
    [c * v[0] + s * kxv[0] + kv * k[0], c * v[1] + s * kxv[1] + kv * k[1], c * v[2] + s * kxv[2] + kv * k[2]]
}

/// `v` rotated by `angle` about the unit axis `k`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn rotate(k: V3, angle: f64, v: V3) -> V3 {
    let (s, c) = libm::sincos(angle);
    rotate_cs(k, c, s, v)
}

/// `angle` moved by a multiple of 2 pi into `(-pi, pi]`. The solvers' angles are sums of at
/// most a few angles in `[-pi, pi]`, which two conditional turns bring back; anything larger
/// takes the general path (`round` in software costs more than the rest: baseline x86-64 has no
/// rounding instruction).
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn wrap(angle: f64) -> f64 {
    use core::f64::consts::{PI, TAU};
    if angle.abs() <= 3.0 * PI {
        let once = if angle > PI {
            angle - TAU
        } else if angle <= -PI {
            angle + TAU
        } else {
            angle
        };
        return if once > PI {
            once - TAU
        } else if once <= -PI {
            once + TAU
        } else {
            once
        };
    }
    let wrapped = angle - TAU * libm::round(angle / TAU);
    if wrapped <= -PI { wrapped + TAU } else { wrapped }
}

/// `angle` less the whole turns nearest it: within half a turn of zero (`[-pi, pi]`, either end
/// where it falls on one), with no branch. The turns are rounded by adding and subtracting
/// `1.5 * 2^52`, exact for fewer than 2^51 turns; beyond that (angles past 1e16 rad) the
/// subtraction of a float's worth of turns is already all the precision the angle has.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(crate) fn nearest_turn(angle: f64) -> f64 {
    use core::f64::consts::TAU;
    const ROUND: f64 = 6_755_399_441_055_744.0; // 1.5 * 2^52
    let turns = (angle * (1.0 / TAU) + ROUND) - ROUND;
    angle - turns * TAU
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotation_about_z_by_a_quarter_turn() {
        let v = rotate([0.0, 0.0, 1.0], core::f64::consts::FRAC_PI_2, [1.0, 2.0, 3.0]);
        assert!((v[0] + 2.0).abs() < 1e-15 && (v[1] - 1.0).abs() < 1e-15 && (v[2] - 3.0).abs() < 1e-15);
    }

    #[test]
    fn nearest_turn_is_within_half_a_turn() {
        use core::f64::consts::{PI, TAU};
        for angle in [0.0, 1.0, -1.0, 3.0, -3.0, 3.2, -3.2, 7.0, -7.0, 100.0, -1e6, 12.0 * TAU + 0.1] {
            let near = nearest_turn(angle);
            assert!(near.abs() <= PI + 1e-12, "{angle} -> {near}");
            let turns = (angle - near) / TAU;
            assert!((turns - libm::round(turns)).abs() < 1e-9, "{angle} -> {near}: not whole turns");
        }
    }

    #[test]
    fn wrap_lands_in_the_half_open_interval() {
        use core::f64::consts::PI;
        for (angle, expected) in
            [(0.0, 0.0), (PI, PI), (-PI, PI), (3.0 * PI, PI), (7.0, 7.0 - 2.0 * PI), (-7.0, 2.0 * PI - 7.0)]
        {
            let w = wrap(angle);
            assert!((w - expected).abs() < 1e-12, "wrap({angle}) = {w}, expected {expected}");
            assert!(w > -PI && w <= PI);
        }
    }
}
