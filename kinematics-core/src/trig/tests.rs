//! Unit tests of the trig entry points: special values, symmetry, quadrant boundaries, lanes
//! against scalar bit for bit, fast bound and slow path. Accuracy over many points is the
//! `trig-accuracy` crate's job.

use super::*;
use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// Distance in ulps of `got` from `want`, in units of `want`'s ulp; infinity if either is NaN or
/// infinite, so a NaN can never pass a bound.
fn ulps_f64(got: f64, want: f64) -> f64 {
    if !got.is_finite() || !want.is_finite() {
        return f64::INFINITY;
    }
    let exponent = ((want.to_bits() >> 52) & 0x7ff) as i32;
    let ulp = f64::from_bits(((exponent.max(1) - 1) as u64) << 52) * f64::EPSILON * 2.0;
    let ulp = if exponent <= 52 { f64::from_bits(1).max(ulp) } else { ulp };
    (got - want).abs() / ulp
}

fn ulps_f32(got: f32, want: f64) -> f64 {
    if !got.is_finite() || !want.is_finite() {
        return f64::INFINITY;
    }
    let w = want as f32;
    let exponent = ((w.to_bits() >> 23) & 0xff) as i32;
    let ulp = if exponent <= 1 {
        f64::from(f32::from_bits(1))
    } else {
        f64::from(f32::from_bits(((exponent - 1) as u32) << 23)) * f64::from(f32::EPSILON) * 2.0
    };
    (f64::from(got) - want).abs() / ulp
}

/// libm's f64 sin/cos is within 1 ulp of the truth (its kernels' documented bound); ours within
/// 2: the two may be 3 apart. Points here are few and chosen, the contract is measured elsewhere.
fn check_f64(x: f64) {
    let (s, c) = sin_cos_f64(x);
    let (ls, lc) = libm::sincos(x);
    assert!(ulps_f64(s, ls) <= 3.0, "sin({x:e}) = {s:e}, libm {ls:e}");
    assert!(ulps_f64(c, lc) <= 3.0, "cos({x:e}) = {c:e}, libm {lc:e}");
}

/// Ours in f32 within 0.8 ulp of the truth (its measured bound, every f32 of the fast range
/// checked by `trig-accuracy --exhaustive`); libm's f64 values are far closer than an f32 ulp, so
/// 1 ulp from them holds.
fn check_f32(x: f32) {
    let (s, c) = sin_cos_f32(x);
    let (ls, lc) = libm::sincos(f64::from(x));
    assert!(ulps_f32(s, ls) <= 1.0, "sin({x:e}) = {s:e}, libm {ls:e}");
    assert!(ulps_f32(c, lc) <= 1.0, "cos({x:e}) = {c:e}, libm {lc:e}");
}

#[test]
fn zeros_keep_their_sign() {
    assert_eq!(sin_cos_f64(0.0).0.to_bits(), 0.0f64.to_bits());
    assert_eq!(sin_cos_f64(-0.0).0.to_bits(), (-0.0f64).to_bits());
    assert_eq!(sin_cos_f64(0.0).1, 1.0);
    assert_eq!(sin_cos_f64(-0.0).1, 1.0);
    assert_eq!(sin_cos_f32(0.0).0.to_bits(), 0.0f32.to_bits());
    assert_eq!(sin_cos_f32(-0.0).0.to_bits(), (-0.0f32).to_bits());
    assert_eq!(sin_cos_f32(-0.0).1, 1.0);
}

#[test]
fn tiny_and_subnormal_inputs_give_sin_x_cos_one() {
    for x in [f64::from_bits(1), f64::MIN_POSITIVE, 1e-300, 1e-20, 1e-9] {
        assert_eq!(sin_cos_f64(x), (x, 1.0), "x = {x:e}");
        assert_eq!(sin_cos_f64(-x), (-x, 1.0), "x = {x:e}");
    }
    for x in [f32::from_bits(1), f32::MIN_POSITIVE, 1e-30, 1e-5] {
        assert_eq!(sin_cos_f32(x), (x, 1.0), "x = {x:e}");
        assert_eq!(sin_cos_f32(-x), (-x, 1.0), "x = {x:e}");
    }
}

#[test]
fn nan_and_infinities_give_nan() {
    for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let (s, c) = sin_cos_f64(x);
        assert!(s.is_nan() && c.is_nan(), "x = {x}");
    }
    for x in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let (s, c) = sin_cos_f32(x);
        assert!(s.is_nan() && c.is_nan(), "x = {x}");
    }
}

#[test]
fn sin_is_odd_and_cos_even_bit_for_bit() {
    let mut x = 1e-3;
    while x < 2.0 * FAST_BOUND {
        let (s, c) = sin_cos_f64(x);
        let (ns, nc) = sin_cos_f64(-x);
        assert_eq!((-s).to_bits(), ns.to_bits(), "x = {x:e}");
        assert_eq!(c.to_bits(), nc.to_bits(), "x = {x:e}");
        let (s, c) = sin_cos_f32(x as f32);
        let (ns, nc) = sin_cos_f32(-x as f32);
        assert_eq!((-s).to_bits(), ns.to_bits(), "x = {x:e}");
        assert_eq!(c.to_bits(), nc.to_bits(), "x = {x:e}");
        x *= 1.37;
    }
}

#[test]
fn multiples_of_pi_over_4_and_their_neighbours() {
    for k in -64..=64 {
        let x = f64::from(k) * FRAC_PI_4;
        for y in [x, x.next_up(), x.next_down()] {
            check_f64(y);
            check_f32(y as f32);
        }
    }
    for x in [PI, FRAC_PI_2, 1e4 * PI, 1e5 * FRAC_PI_2] {
        check_f64(x);
    }
    // f32 up to beyond its fast bound (k pi/4 = 314 at k = 400), where the reduction cancels most.
    for k in -400..=400 {
        let x = (f64::from(k) * FRAC_PI_4) as f32;
        for y in [x, x.next_up(), x.next_down()] {
            check_f32(y);
        }
    }
}

#[test]
fn exact_values_at_quadrant_boundaries() {
    // sin(pi) for the f64 pi is pi's error, 1.2246467991473532e-16 (sin(pi - e) = sin(e) ~ e).
    let (s, c) = sin_cos_f64(PI);
    assert!(ulps_f64(s, 1.2246467991473532e-16) <= 1.0, "sin(pi) = {s:e}");
    assert_eq!(c, -1.0);
    let (s, c) = sin_cos_f64(FRAC_PI_2);
    assert_eq!(s, 1.0);
    assert!(ulps_f64(c, 6.123233995736766e-17) <= 1.0, "cos(pi/2) = {c:e}");
}

#[test]
fn fast_bound_and_its_neighbours_agree_with_libm() {
    for x in [FAST_BOUND, FAST_BOUND.next_up(), FAST_BOUND.next_down(), 1e7, 1e22, f64::MAX] {
        check_f64(x);
        check_f64(-x);
    }
    // Beyond the bound the slow path is libm itself.
    assert_eq!(sin_cos_f64(1e22), libm::sincos(1e22));
    let bound = FAST_BOUND_F32;
    for x in [bound, bound.next_up(), bound.next_down(), 1e4, FAST_BOUND as f32, 1e30, f32::MAX] {
        check_f32(x);
        check_f32(-x);
    }
    // Beyond the f32 bound the slow path is libm's f64 values, rounded once.
    let (s, c) = libm::sincos(f64::from(bound.next_up()));
    assert_eq!(sin_cos_f32(bound.next_up()), (s as f32, c as f32));
}

/// Values of every path mixed: zeros, both fast paths, 256 and 300 (the f32 bound and a value
/// beyond it, on the f64 fast path), values beyond the f64 bound, NaN, infinity, a subnormal.
const MIXED: [f64; 15] =
    [0.0, -0.0, 0.3, -2.5, PI, 100.0, 256.0, -1e4, FAST_BOUND, 300.0, 2e6, f64::NAN, f64::INFINITY, 1e-310, f64::MAX];

#[test]
fn lanes_equal_scalar_bit_for_bit() {
    let values = MIXED;
    fn check<const N: usize>(x: [f64; N]) {
        let (s, c) = sin_cos_f64_lanes(x);
        for i in 0..N {
            let (ss, sc) = sin_cos_f64(x[i]);
            assert_eq!((s[i].to_bits(), c[i].to_bits()), (ss.to_bits(), sc.to_bits()), "x = {:e}", x[i]);
        }
        let x32 = x.map(|v| v as f32);
        let (s, c) = sin_cos_f32_lanes(x32);
        for i in 0..N {
            let (ss, sc) = sin_cos_f32(x32[i]);
            assert_eq!((s[i].to_bits(), c[i].to_bits()), (ss.to_bits(), sc.to_bits()), "x = {:e}", x32[i]);
        }
    }
    for start in 0..values.len() {
        let mut four = [0.0; 4];
        let mut eight = [0.0; 8];
        for i in 0..8 {
            let v = values[(start + i) % values.len()];
            eight[i] = v;
            if i < 4 {
                four[i] = v;
            }
        }
        check(four);
        check(eight);
        check([values[start]]);
    }
    check(values);
}

/// The packed routines decide the slow path by the largest magnitude key (`widest.max(key)`, an
/// integer maximum): that is right only if a key is at most the bound's key exactly where the
/// fast path is right. Held at the bound and its neighbours, zeros, subnormals, infinities and
/// NaNs of both signs and both types, so a NaN can never slip under the bound.
#[test]
fn the_magnitude_key_orders_as_the_fast_range() {
    let f64s = [0.0, 1e-310, 1.0, FAST_BOUND.next_down(), FAST_BOUND, FAST_BOUND.next_up(), 1e22, f64::MAX];
    for x in f64s.into_iter().chain([f64::INFINITY, f64::NAN, -f64::NAN]) {
        for x in [x, -x] {
            assert_eq!(x.magnitude_key() <= f64::BOUND_KEY, x.in_fast_range(), "x = {x:e}");
        }
    }
    let bound = FAST_BOUND_F32;
    let f32s = [0.0, 1e-40, 1.0, bound.next_down(), bound, bound.next_up(), 1e30, f32::MAX];
    for x in f32s.into_iter().chain([f32::INFINITY, f32::NAN, -f32::NAN]) {
        for x in [x, -x] {
            assert_eq!(x.magnitude_key() <= f32::BOUND_KEY, Kernel::in_fast_range(x), "x = {x:e}");
        }
    }
}

/// The packed routines (one loop over every lane of several values, one test of the fast range
/// for all of them) give each lane what the scalar routine gives its value, bit for bit, with the
/// slow path's values (beyond the bound, NaN, infinities) anywhere among them.
#[test]
fn packed_lanes_equal_scalar_bit_for_bit() {
    let values = MIXED;
    let at = |k: usize| values[k % values.len()];
    for start in 0..values.len() {
        // Three values of eight lanes; the slow ones fall in every value and lane in turn.
        let x: [[f64; 8]; 3] = core::array::from_fn(|m| core::array::from_fn(|i| at(start + 8 * m + i)));
        let (s, c) = sin_cos_packed_many(x);
        let x32 = x.map(|v| v.map(|v| v as f32));
        let (s32, c32) = sin_cos_packed_many(x32);
        for m in 0..3 {
            for i in 0..8 {
                let (ss, sc) = sin_cos_f64(x[m][i]);
                assert_eq!((s[m][i].to_bits(), c[m][i].to_bits()), (ss.to_bits(), sc.to_bits()), "x = {:e}", x[m][i]);
                let (ss, sc) = sin_cos_f32(x32[m][i]);
                assert_eq!(
                    (s32[m][i].to_bits(), c32[m][i].to_bits()),
                    (ss.to_bits(), sc.to_bits()),
                    "x = {:e}",
                    x32[m][i]
                );
            }
        }
        let (one_s, one_c) = sin_cos_packed(x[0]);
        assert_eq!(
            (one_s.map(f64::to_bits), one_c.map(f64::to_bits)),
            (s[0].map(f64::to_bits), c[0].map(f64::to_bits))
        );
    }
    // Every value fast: the slow path's branch not taken.
    let fast: [[f64; 8]; 2] = core::array::from_fn(|m| core::array::from_fn(|i| (m * 8 + i) as f64 - 7.5));
    let (s, c) = sin_cos_packed_many(fast);
    for m in 0..2 {
        for i in 0..8 {
            assert_eq!((s[m][i], c[m][i]), sin_cos_f64(fast[m][i]));
        }
    }
}

#[test]
fn the_quadrant_factor_is_2_over_pi_as_the_script_computed_it() {
    assert_eq!(super::coefficients::FRAC_2_PI.to_bits(), super::coefficients::FRAC_2_PI_BITS);
    assert_eq!(super::coefficients::FRAC_2_PI_F32.to_bits(), super::coefficients::FRAC_2_PI_F32_BITS);
}
