//! Compile cost: model to Rust tokens (compile, then emit), for a 7-joint arm, a 40-joint tree with
//! all frames, and synthetic chains of 6, 12, 24 and 48 joints (growth should be about linear).

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use kinematics_compiler::emit::{EmitOptions, emit_function};
use kinematics_compiler::{Request, compile};
use kinematics_model::{KinematicTree, synthetic};

fn to_tokens(tree: &KinematicTree, request: &Request) -> usize {
    let compiled = compile(tree, request).map(|c| emit_function(&c, &EmitOptions::named("fk")));
    compiled.map(|t| t.into_iter().count()).unwrap_or_default()
}

fn panda() -> Option<KinematicTree> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/panda.toml");
    kinematics_model::parse_source("panda.toml", &std::fs::read_to_string(path).ok()?).ok()
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("compile");
    let arm = panda().unwrap_or_else(|| synthetic::dh_chain(7));
    let tip = arm.links().last().map(|l| l.name.clone()).unwrap_or_default();
    group.bench_function("arm7_tip_pose", |b| b.iter(|| to_tokens(black_box(&arm), &Request::tip(&tip))));
    let tree = synthetic::tree(4, 10);
    group.bench_function("tree40_all_frames", |b| b.iter(|| to_tokens(black_box(&tree), &Request::all_links())));
    for n in [6, 12, 24, 48] {
        let chain = synthetic::dh_chain(n);
        let tip = format!("link{n}");
        group.bench_with_input(BenchmarkId::new("chain_tip_pose", n), &chain, |b, chain| {
            b.iter(|| to_tokens(black_box(chain), &Request::tip(&tip)))
        });
    }
    group.finish();
}

// Short runs keep the whole `cargo bench` under ten minutes on 2 cores; these take milliseconds each.
criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(std::time::Duration::from_secs(1))
        .measurement_time(std::time::Duration::from_secs(2));
    targets = bench
}
criterion_main!(benches);
