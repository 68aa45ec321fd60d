//! What a measured run leaves for `bench-report` beside criterion's results in
//! `target/criterion/`: the robot list (`kinematics-robots.tsv`: group, file, tip), the build
//! record (`kinematics-build.tsv`: label, vector features and the level dispatch runs) and the paired ratios
//! (`kinematics-paired.tsv`: group, pair, ratio). The report finds criterion's medians by the
//! group and benchmark names, so those names are the interface and never change.

use crate::common::FILTER;
use crate::common::criterion_dir;
use crate::mode::PAIRED;

/// How this benchmark was compiled, for `bench-report`: a label (`KINEMATICS_BENCH_BUILD` when the
/// command sets it, `native` or `baseline`; else `native` when the code may use AVX2, which a plain
/// x86-64 build may not) and the vector features the compiler was allowed to use.
fn build_record() -> String {
    let features = [
        ("avx", cfg!(target_feature = "avx")),
        ("avx2", cfg!(target_feature = "avx2")),
        ("fma", cfg!(target_feature = "fma")),
        ("avx512f", cfg!(target_feature = "avx512f")),
    ];
    let on: Vec<&str> = features.iter().filter(|(_, on)| *on).map(|(name, _)| *name).collect();
    let inferred = if cfg!(target_feature = "avx2") { "native" } else { "baseline" };
    let label = std::env::var("KINEMATICS_BENCH_BUILD").unwrap_or_else(|_| inferred.to_owned());
    let on = if on.is_empty() { "sse2 only".to_owned() } else { on.join(",") };
    // What `kinematics::dispatch` runs on this CPU: the generated functions' instruction set, and
    // which lanes the batches (and their floors) take.
    let dispatch = kinematics::dispatched_level();
    format!("build\t{label}\nfeatures\t{on}\ndispatch\t{dispatch}\n")
}

/// The robot list (`manifest`, one `group, file, tip` line each) and the build record, for
/// `bench-report` to find the results by.
pub fn write_robots(manifest: &str) {
    let dir = criterion_dir();
    let written = std::fs::create_dir_all(&dir)
        .and_then(|()| std::fs::write(dir.join("kinematics-robots.tsv"), manifest))
        .and_then(|()| std::fs::write(dir.join("kinematics-build.tsv"), build_record()));
    if let Err(e) = written {
        eprintln!("cannot write the robot list for bench-report: {e}");
    }
}

/// The paired ratios of this run. A filtered run replaces the pairs it timed and keeps the last
/// run's others.
pub fn write_paired() {
    let paired = PAIRED.lock().unwrap_or_else(std::sync::PoisonError::into_inner).concat();
    let path = criterion_dir().join("kinematics-paired.tsv");
    let id = |line: &str| line.rsplit_once('\t').map(|(id, _)| id.to_owned());
    let timed: std::collections::BTreeSet<String> = paired.lines().filter_map(id).collect();
    let kept: String = match FILTER.as_deref() {
        Some(_) => std::fs::read_to_string(&path)
            .unwrap_or_default()
            .lines()
            .filter(|l| id(l).is_none_or(|id| !timed.contains(&id)))
            .map(|l| format!("{l}\n"))
            .collect(),
        None => String::new(),
    };
    if let Err(e) = std::fs::write(&path, kept + &paired) {
        eprintln!("cannot write the paired ratios for bench-report: {e}");
    }
}
