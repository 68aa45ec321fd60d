//! The derive's own expansion time (attribute parsing, reading the file, compiling, emitting
//! tokens): a 7-joint arm's tip pose and a 40-joint tree with every frame.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use quote::quote;

/// A 40-joint tree as URDF: a torso and four 10-joint limbs, axes cycling y, x, z, and a fixed tool
/// frame on each limb (the shape of `kinematics_model::synthetic::tree(4, 10)`).
fn tree40_urdf() -> String {
    let mut text = String::from("<robot name=\"tree40\"><link name=\"torso\"/>");
    let axes = ["0 1 0", "1 0 0", "0 0 1"];
    for limb in 0..4 {
        let mut parent = "torso".to_owned();
        for k in 0..10 {
            let child = format!("limb{limb}_link{k}");
            let origin = if k == 0 {
                format!("xyz=\"{} 0.2 0.3\" rpy=\"0 0 {}\"", 0.1 * limb as f64, 0.3 * limb as f64)
            } else {
                "xyz=\"0 0.05 0.25\" rpy=\"0 0 0\"".to_owned()
            };
            text += &format!(
                "<link name=\"{child}\"/><joint name=\"limb{limb}_joint{k}\" type=\"revolute\"><parent link=\"{parent}\"/>\
                 <child link=\"{child}\"/><origin {origin}/><axis xyz=\"{}\"/>\
                 <limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint>",
                axes[k % 3]
            );
            parent = child;
        }
        text += &format!(
            "<link name=\"limb{limb}_tool\"/><joint name=\"limb{limb}_tool_joint\" type=\"fixed\"><parent link=\"{parent}\"/>\
             <child link=\"limb{limb}_tool\"/><origin xyz=\"0 0 0.1\"/></joint>"
        );
    }
    text + "</robot>"
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("derive_expansion");
    let arm = quote! {
        #[kinematics(dh = "../robots/panda.toml", tip = "flange")]
        struct Panda;
    };
    let fallback = quote! {
        #[kinematics(dh(convention = "modified",
            joint(name = "j1", d = 0.333), joint(name = "j2", alpha = "-pi/2"), joint(name = "j3", alpha = "pi/2", d = 0.316),
            joint(name = "j4", alpha = "pi/2", a = 0.0825), joint(name = "j5", alpha = "-pi/2", a = -0.0825, d = 0.384),
            joint(name = "j6", alpha = "pi/2"), joint(name = "j7", alpha = "pi/2", a = 0.088)), tip = "link7")]
        struct Arm7;
    };
    // The Panda's table when robots/ has it, otherwise the same kinematics written inline.
    let arm = if std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../robots/panda.toml")).exists() {
        arm
    } else {
        fallback
    };
    group.bench_function("arm7_tip", |b| b.iter(|| kinematics_derive_core::expand(black_box(arm.clone()))));
    let path = std::env::temp_dir().join("kinematics_bench_tree40.urdf");
    if std::fs::write(&path, tree40_urdf()).is_ok() {
        let path = path.to_string_lossy().into_owned();
        let tree = quote! {
            #[kinematics(urdf = #path, positions)]
            struct Tree40;
        };
        group.bench_function("tree40_all_frames", |b| {
            b.iter(|| kinematics_derive_core::expand(black_box(tree.clone())))
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
