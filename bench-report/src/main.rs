//! `cargo run -p bench-report`: reads criterion's results of `cargo bench --bench fk` for the plain
//! build (`target/criterion`) and for the native build (`target/native/criterion`, from the same
//! command with `RUSTFLAGS="-C target-cpu=native" CARGO_TARGET_DIR=target/native`), whichever exist:
//! the medians in `<robot>/<variant>/new/estimates.json`, the robot list (`kinematics-robots.tsv`),
//! the build record (`kinematics-build.tsv`) and the paired ratios (`kinematics-paired.tsv`) the
//! benchmark writes. It writes `benches/SUMMARY.md` (per build and robot: median ns per call or per
//! configuration, the ratios, the operation counts, the machine and the commands; the plain build
//! against the native one; then the issues' targets, each with its measured figure and whether it
//! is met) and `benches/ratios.svg` (the
//! ratios as bars). Nothing here is typed in by hand.
//!
//! One module per output: `read` (every input, as data), `tables` (the Markdown), `svg` (the
//! chart) and `targets` (the targets, met or not). This file only puts them in order.

mod read;
mod svg;
mod tables;
mod targets;

use std::path::PathBuf;

use read::Result;

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e}");
        std::process::exit(1);
    }
}

fn run() -> Result<()> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let target = root.join("target");
    let mut runs = Vec::new();
    for (name, dir) in [("plain", target.join("criterion")), ("native", target.join("native/criterion"))] {
        runs.extend(read::read_run(&root, name, dir)?);
    }
    if runs.is_empty() {
        return Err(format!(
            "no benchmark results in {} or {}: run `cargo bench --bench fk` first (see benches/SUMMARY.md)",
            target.join("criterion").display(),
            target.join("native/criterion").display()
        )
        .into());
    }
    // Forward kinematics: each build's tables, the two builds side by side, the targets over all
    // builds, the notes.
    let mut summary = tables::header(&read::machine());
    for run in &runs {
        tables::run_sections(&mut summary, run);
    }
    tables::plain_against_native(&mut summary, &runs);
    targets::targets(&mut summary, &runs);
    summary += &tables::notes();
    // Inverse kinematics (plain build only): its tables, then its targets when it was run.
    let ik = read::read_ik(&root, &target.join("criterion"));
    summary += &tables::ik_section(ik.as_ref());
    if let Some(ik) = &ik {
        summary += &targets::ik_targets(ik);
    }
    std::fs::write(root.join("benches/SUMMARY.md"), summary)?;
    // The bars show the plain build, the one every user gets, when it was run.
    std::fs::write(root.join("benches/ratios.svg"), svg::svg(&runs[0]))?;
    let names: Vec<&str> = runs.iter().map(|r| r.name).collect();
    println!("wrote benches/SUMMARY.md and benches/ratios.svg from the {} run(s)", names.join(" and "));
    Ok(())
}
