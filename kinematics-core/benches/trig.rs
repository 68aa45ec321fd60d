//! Speed of our sin/cos against std's and wide's: each benchmark computes the sine and cosine of
//! the same 1024 angles in [-pi, pi] and stores them, and criterion reports time per element, that
//! is per (sin, cos) pair. Run with and without `RUSTFLAGS="-C target-cpu=native"` (give the native
//! build its own `CARGO_TARGET_DIR`).

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use kinematics_core::trig::{sin_cos_f32, sin_cos_f32_lanes, sin_cos_f64, sin_cos_f64_lanes};
use std::hint::black_box;

const COUNT: usize = 1024;

fn angles() -> Vec<f64> {
    // A fixed, irregular spread over [-pi, pi] (golden-ratio steps), the same for every benchmark.
    (0..COUNT).map(|i| ((i as f64 * 0.618_033_988_749_895).fract() * 2.0 - 1.0) * core::f64::consts::PI).collect()
}

fn chunked_f64<const N: usize>(x: &[f64], s: &mut [f64], c: &mut [f64]) {
    for ((x, s), c) in x.chunks_exact(N).zip(s.chunks_exact_mut(N)).zip(c.chunks_exact_mut(N)) {
        let mut lanes = [0.0; N];
        lanes.copy_from_slice(x);
        let (ls, lc) = sin_cos_f64_lanes(lanes);
        s.copy_from_slice(&ls);
        c.copy_from_slice(&lc);
    }
}

fn chunked_f32<const N: usize>(x: &[f32], s: &mut [f32], c: &mut [f32]) {
    for ((x, s), c) in x.chunks_exact(N).zip(s.chunks_exact_mut(N)).zip(c.chunks_exact_mut(N)) {
        let mut lanes = [0.0; N];
        lanes.copy_from_slice(x);
        let (ls, lc) = sin_cos_f32_lanes(lanes);
        s.copy_from_slice(&ls);
        c.copy_from_slice(&lc);
    }
}

fn bench_f64(criterion: &mut Criterion) {
    let x = angles();
    let mut s = vec![0.0; COUNT];
    let mut c = vec![0.0; COUNT];
    let mut group = criterion.benchmark_group("sin_cos_f64");
    group.throughput(Throughput::Elements(COUNT as u64));
    group.bench_function("std", |b| {
        b.iter(|| {
            for i in 0..COUNT {
                (s[i], c[i]) = black_box(x[i]).sin_cos();
            }
            black_box((&s, &c));
        })
    });
    group.bench_function("ours_scalar", |b| {
        b.iter(|| {
            for i in 0..COUNT {
                (s[i], c[i]) = sin_cos_f64(black_box(x[i]));
            }
            black_box((&s, &c));
        })
    });
    group.bench_function("ours_lanes4", |b| {
        b.iter(|| {
            chunked_f64::<4>(black_box(&x), &mut s, &mut c);
            black_box((&s, &c));
        })
    });
    group.bench_function("ours_lanes8", |b| {
        b.iter(|| {
            chunked_f64::<8>(black_box(&x), &mut s, &mut c);
            black_box((&s, &c));
        })
    });
    group.bench_function("ours_lanes8_outlined", |b| {
        b.iter(|| {
            for ((x, s), c) in black_box(&x).chunks_exact(8).zip(s.chunks_exact_mut(8)).zip(c.chunks_exact_mut(8)) {
                let mut lanes = [0.0; 8];
                lanes.copy_from_slice(x);
                let (ls, lc) = asm_probe_f64_lanes8(lanes);
                s.copy_from_slice(&ls);
                c.copy_from_slice(&lc);
            }
            black_box((&s, &c));
        })
    });
    group.bench_function("wide_f64x4", |b| {
        b.iter(|| {
            for ((x, s), c) in black_box(&x).chunks_exact(4).zip(s.chunks_exact_mut(4)).zip(c.chunks_exact_mut(4)) {
                let (ws, wc) = wide::f64x4::from([x[0], x[1], x[2], x[3]]).sin_cos();
                s.copy_from_slice(&ws.to_array());
                c.copy_from_slice(&wc.to_array());
            }
            black_box((&s, &c));
        })
    });
    group.finish();
}

fn bench_f32(criterion: &mut Criterion) {
    let x: Vec<f32> = angles().iter().map(|&v| v as f32).collect();
    let mut s = vec![0.0f32; COUNT];
    let mut c = vec![0.0f32; COUNT];
    let mut group = criterion.benchmark_group("sin_cos_f32");
    group.throughput(Throughput::Elements(COUNT as u64));
    group.bench_function("std", |b| {
        b.iter(|| {
            for i in 0..COUNT {
                (s[i], c[i]) = black_box(x[i]).sin_cos();
            }
            black_box((&s, &c));
        })
    });
    group.bench_function("ours_scalar", |b| {
        b.iter(|| {
            for i in 0..COUNT {
                (s[i], c[i]) = sin_cos_f32(black_box(x[i]));
            }
            black_box((&s, &c));
        })
    });
    group.bench_function("ours_lanes8", |b| {
        b.iter(|| {
            chunked_f32::<8>(black_box(&x), &mut s, &mut c);
            black_box((&s, &c));
        })
    });
    group.bench_function("ours_lanes16", |b| {
        b.iter(|| {
            chunked_f32::<16>(black_box(&x), &mut s, &mut c);
            black_box((&s, &c));
        })
    });
    group.bench_function("ours_lanes8_outlined", |b| {
        b.iter(|| {
            for ((x, s), c) in black_box(&x).chunks_exact(8).zip(s.chunks_exact_mut(8)).zip(c.chunks_exact_mut(8)) {
                let mut lanes = [0.0f32; 8];
                lanes.copy_from_slice(x);
                let (ls, lc) = asm_probe_f32_lanes8(lanes);
                s.copy_from_slice(&ls);
                c.copy_from_slice(&lc);
            }
            black_box((&s, &c));
        })
    });
    group.bench_function("wide_f32x8", |b| {
        b.iter(|| {
            for ((x, s), c) in black_box(&x).chunks_exact(8).zip(s.chunks_exact_mut(8)).zip(c.chunks_exact_mut(8)) {
                let mut lanes = [0.0f32; 8];
                lanes.copy_from_slice(x);
                let (ws, wc) = wide::f32x8::from(lanes).sin_cos();
                s.copy_from_slice(&ws.to_array());
                c.copy_from_slice(&wc.to_array());
            }
            black_box((&s, &c));
        })
    });
    group.finish();
}

criterion_group! {
    name = benches;
    // Short runs: the machine is shared and the figures are compared as ratios.
    config = Criterion::default().warm_up_time(std::time::Duration::from_millis(500)).measurement_time(std::time::Duration::from_secs(2));
    targets = bench_f64, bench_f32
}
criterion_main!(benches);

/// Out of line so its assembly can be read on its own (`objdump -d` on the bench binary, symbol
/// `asm_probe_f64_lanes8`): packed multiplies and no branch but the slow-path test are the point.
#[inline(never)]
pub fn asm_probe_f64_lanes8(x: [f64; 8]) -> ([f64; 8], [f64; 8]) {
    sin_cos_f64_lanes(x)
}

/// The same for the f32 lanes, 8 wide.
#[inline(never)]
pub fn asm_probe_f32_lanes8(x: [f32; 8]) -> ([f32; 8], [f32; 8]) {
    sin_cos_f32_lanes(x)
}
