//! The accuracy contract of kinematics-core's sin/cos on a fixed-seed sample (10^6 points per
//! range) and on special values. The full 10^8-point sweep is `cargo run --release -p
//! trig-accuracy -- --points 100000000`.

#![allow(clippy::unwrap_used)]

use kinematics_core::trig::{FAST_BOUND, FAST_BOUND_F32, sin_cos_f32, sin_cos_f64};
use trig_accuracy::{
    Errors, RANGES_F32, RANGES_F64, Subject, errors_f32, errors_f64, exhaustive_f32, special_values_f64, sweep_f32,
    sweep_f64, ulp_f64,
};

const POINTS: u64 = 1_000_000;

/// glibc's documented largest known error for sin and cos (double, x86_64), in ulps.
const REFERENCE_ULPS: f64 = 1.0;

fn f64_range(name: &str) -> Errors {
    let (i, range) = RANGES_F64.iter().enumerate().find(|(_, r)| r.name == name).unwrap();
    sweep_f64(Subject::Ours, *range, POINTS, 0x7e57_0000 + i as u64)
}

#[test]
fn f64_within_2_ulp_on_minus_pi_to_pi() {
    let e = f64_range("[-pi, pi]");
    assert_eq!(e.points, POINTS);
    assert!(e.max_ulp() + REFERENCE_ULPS <= 2.0, "{e:?}");
}

#[test]
fn f64_within_1e_15_absolute_up_to_1e4() {
    for name in ["[-pi, pi]", "[-100, 100]", "[-1e4, 1e4]"] {
        let e = f64_range(name);
        // The reference may be 1 ulp off: at most 2^-53 for results of magnitude below 1.
        assert!(e.max_abs() + REFERENCE_ULPS * ulp_f64(0.9) <= 1e-15, "{name}: {e:?}");
    }
}

#[test]
fn f64_within_1_ulp_of_glibc_everywhere() {
    for (i, range) in RANGES_F64.iter().enumerate() {
        let e = sweep_f64(Subject::Ours, *range, POINTS, 0x7e57_0000 + i as u64);
        assert!(e.max_ulp() <= 1.0, "{}: {e:?}", range.name);
    }
}

/// The f32 contract: within 0.8 ulp of the truth (the fast path's largest error over every f32
/// of its range, 0.79994, by `trig-accuracy --exhaustive`; the slow path is libm's f64 values
/// rounded once). The reference's own error is 2^-29 f32 ulp.
const F32_ULPS: f64 = 0.8;

#[test]
fn f32_within_its_bound_everywhere() {
    for (i, range) in RANGES_F32.iter().enumerate() {
        let e = sweep_f32(Subject::Ours, *range, POINTS, 0x7e32_0000 + i as u64);
        assert_eq!(e.points, POINTS);
        assert!(e.max_ulp() <= F32_ULPS, "{}: {e:?}", range.name);
    }
}

/// Every f32 from 2^-4 to the fast bound, both signs (2e8 values: every quadrant count the
/// reduction meets; below 2^-4 the count is zero and the sample's binades cover it).
#[test]
fn f32_within_its_bound_on_every_value_of_the_reduction() {
    let e = exhaustive_f32(Subject::Ours, 0.0625, FAST_BOUND_F32);
    assert_eq!(e.points, 2 * (12 << 23) + 2);
    assert!(e.max_ulp() <= F32_ULPS, "{e:?}");
}

#[test]
fn special_values() {
    let values = special_values_f64();
    let e = errors_f64(Subject::Ours, &values);
    assert!(e.max_ulp() <= 1.0, "{e:?}");
    let values32: Vec<f32> = values.iter().map(|&x| x as f32).filter(|x| x.is_finite()).collect();
    let e = errors_f32(Subject::Ours, &values32);
    assert!(e.max_ulp() <= F32_ULPS, "{e:?}");
    for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let (s, c) = sin_cos_f64(x);
        assert!(s.is_nan() && c.is_nan());
        let (s, c) = sin_cos_f32(x as f32);
        assert!(s.is_nan() && c.is_nan());
    }
    assert!(values.contains(&FAST_BOUND) && values.contains(&FAST_BOUND.next_up()));
}

#[test]
fn lanes_match_scalar_on_the_sample() {
    let values = special_values_f64();
    for chunk in values.chunks_exact(8) {
        let x: [f64; 8] = chunk.try_into().unwrap();
        let (s, c) = kinematics_core::trig::sin_cos_f64_lanes(x);
        for i in 0..8 {
            let (ss, sc) = sin_cos_f64(x[i]);
            assert_eq!((s[i].to_bits(), c[i].to_bits()), (ss.to_bits(), sc.to_bits()));
        }
    }
}

#[test]
fn a_wrong_result_is_caught() {
    // The measure must see errors and NaN: feed it a deliberately perturbed comparison.
    let mut e = Errors::default();
    e = e.merge(errors_f64(Subject::Ours, &[1.0]));
    assert!(e.max_ulp() <= 1.0);
    let nan_errors = trig_accuracy::errors_f64(Subject::Wide, &[f64::NAN]);
    // NaN in, NaN reference out: the error is NaN, counted as infinite.
    assert!(nan_errors.max_ulp().is_infinite());
}
