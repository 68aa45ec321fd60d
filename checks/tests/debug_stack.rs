//! Every generated function of every robot in `robots/` (lanes, batches, inverse kinematics and
//! collision included) runs on a thread of 512 KB, in this crate's unoptimised build: what a
//! user's `cargo test` compiles the derive's code as. A test thread has 2 MB, and an unoptimised
//! body keeps a stack slot for each of its values, so a large robot's body once took megabytes;
//! the generated bodies now run each stretch between two block marks as a call of its own in a
//! debug build (`kinematics_core::chunk`).
//!
//! The one thing a function cannot shrink is the value it computes: a batch holds one pack of its
//! outputs in lanes (eight configurations' worth in `F64x8`), a generic function its value, and
//! unoptimised code holds it up to four times (its entries as they are computed, the value
//! assembled from them, the value returned, a batch's pack). So a case whose value is more than
//! a quarter of [`STACK`] runs on four times its value and half of `STACK`: the primitives UR5's
//! 2,464 sphere centres are 473 KB in `F64x8` lanes (2.1 MB); every value up to 128 KB (the
//! humanoid's 156 link poses are 117 KB in `F64x8` lanes) runs on `STACK`.
//!
//! A case that overflows aborts the test process, naming the case's thread
//! (`humanoid.urdf: crate::Derived_humanoid_urdf_file::link_poses_batch`).
//! `KINEMATICS_STACK_KB=N cargo test -p kinematics-checks --test debug_stack` tries another
//! `STACK`; `KINEMATICS_STACK_CASE=text` runs only the cases whose robot or function holds it.

use kinematics_checks::stack::STACK_CASES;

/// The stack each case runs on: a quarter of a test thread's.
const STACK: usize = 512 * 1024;

#[test]
fn every_function_runs_on_a_small_stack() {
    // A value given is used or refused, never replaced by the default.
    let given = |name: &str| match std::env::var(name) {
        Ok(value) => Some(value),
        Err(std::env::VarError::NotPresent) => None,
        Err(e) => panic!("{name}: {e}"),
    };
    let stack = given("KINEMATICS_STACK_KB").map_or(STACK, |kb| {
        1024 * kb.parse::<usize>().unwrap_or_else(|e| panic!("KINEMATICS_STACK_KB={kb}: not a number of KB: {e}"))
    });
    let mut robots = std::collections::BTreeSet::new();
    let mut larger = Vec::new();
    // `KINEMATICS_STACK_CASE=text`: only the cases whose name holds it.
    let only = given("KINEMATICS_STACK_CASE").unwrap_or_default();
    let mut ran = 0;
    for case in STACK_CASES.iter().filter(|c| c.function.contains(&only) || c.robot.contains(&only)) {
        let name = format!("{}: {}", case.robot, case.function);
        let run = case.run;
        let size = if case.value > stack / 4 { 4 * case.value + stack / 2 } else { stack };
        if size > stack {
            larger.push(format!("{name}: {} KB ({} KB of value)", size / 1024, case.value / 1024));
        }
        std::thread::Builder::new()
            .name(name.clone())
            .stack_size(size)
            .spawn(run)
            .unwrap_or_else(|e| panic!("{name}: cannot start a thread: {e}"))
            .join()
            .unwrap_or_else(|_| panic!("{name} panicked"));
        robots.insert(case.robot);
        ran += 1;
    }
    assert!(ran > 0, "KINEMATICS_STACK_CASE={only}: no case's robot or function holds it");
    // Every robot file the crate compiles has cases (tips, and so poses, at least).
    let files = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../robots"))
        .expect("the robots folder")
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|f| kinematics::model::SourceFormat::from_file_name(f).is_some())
        .count();
    if only.is_empty() {
        assert_eq!(robots.len(), files, "every robot in robots/ has cases");
    }
    println!(
        "{ran} functions of {} robots, each on a stack of {} KB but {} whose value is larger:\n  {}",
        robots.len(),
        stack / 1024,
        larger.len(),
        larger.join("\n  ")
    );
}
