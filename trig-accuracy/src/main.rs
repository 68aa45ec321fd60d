//! The full accuracy sweep: `cargo run --release -p trig-accuracy -- --points 100000000` measures
//! that many fixed-seed points per range, for f64 and f32, ours and (with `--wide`) wide's, and
//! prints one markdown table per precision.
//!
//! Its table is in `SWEEP.md` (run with `--points 100000000 --wide`). `--exhaustive` measures
//! instead every f32 in the f32 fast path's range (|x| <= 256, about 2.2e9 values), ours only.

use std::time::Instant;
use trig_accuracy::{Errors, RANGES_F32, RANGES_F64, Subject, exhaustive_f32, sweep_f32, sweep_f64};

fn row(subject: Subject, range: &str, e: &Errors) {
    println!(
        "| {subject:?} | {range} | {} | {:.3} | {:.3} | {:.3e} | {:.3e} | {:e} |",
        e.points, e.ulp_sin, e.ulp_cos, e.abs_sin, e.abs_cos, e.worst_x
    );
}

fn header(what: &str) {
    println!("\n{what}\n");
    println!("| impl | range | points | max ulp sin | max ulp cos | max abs sin | max abs cos | worst x |");
    println!("|---|---|---|---|---|---|---|---|");
}

fn main() {
    let mut points: u64 = 10_000_000;
    let mut subjects = vec![Subject::Ours];
    let mut exhaustive = false;
    let mut args = std::env::args().skip(1);
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--points" => match args.next().and_then(|p| p.parse().ok()) {
                Some(p) => points = p,
                None => {
                    eprintln!("--points needs a number");
                    std::process::exit(2);
                }
            },
            "--wide" => subjects.push(Subject::Wide),
            "--exhaustive" => exhaustive = true,
            _ => {
                eprintln!("usage: trig-accuracy [--points N] [--wide] [--exhaustive]");
                std::process::exit(2);
            }
        }
    }
    let start = Instant::now();
    if exhaustive {
        let bound = kinematics_core::trig::FAST_BOUND_F32;
        header("f32, every value of the fast path's range (reference: glibc f64 sin/cos, unrounded; ulps of f32)");
        let e = exhaustive_f32(Subject::Ours, 0.0, bound);
        row(Subject::Ours, &format!("every f32 with |x| <= {bound}"), &e);
        println!("\nlargest errors, unrounded: sin {} ulp, cos {} ulp", e.ulp_sin, e.ulp_cos);
        println!("\nwall time: {:.1} s on {} threads", start.elapsed().as_secs_f64(), rayon::current_num_threads());
        return;
    }
    header("f64 (reference: glibc sin/cos; ulps are distances to it, add its 1 ulp for the truth)");
    for &subject in &subjects {
        for (i, range) in RANGES_F64.iter().enumerate() {
            let e = sweep_f64(subject, *range, points, 0x5eed_0000 + i as u64);
            row(subject, range.name, &e);
        }
    }
    header("f32 (reference: glibc f64 sin/cos, unrounded; ulps of f32)");
    for &subject in &subjects {
        for (i, range) in RANGES_F32.iter().enumerate() {
            let e = sweep_f32(subject, *range, points, 0xf32_0000 + i as u64);
            row(subject, range.name, &e);
        }
    }
    println!("\nwall time: {:.1} s on {} threads", start.elapsed().as_secs_f64(), rayon::current_num_threads());
}
