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
//! `cargo run -p bench-report -- --ik` rewrites only the inverse kinematics part, from the results of
//! `cargo bench --bench ik` and `benches/ik-geo/run.sh`'s record (`kinematics-ik-geo.tsv`), keeping the
//! forward kinematics sections.
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
    if std::env::args().nth(1).as_deref() == Some("--ik") {
        return ik_only(&root, &target);
    }
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
    summary += &ik_part(&root, &target);
    std::fs::write(root.join("benches/SUMMARY.md"), summary)?;
    // The bars show the plain build, the one every user gets, when it was run.
    std::fs::write(root.join("benches/ratios.svg"), svg::svg(&runs[0]))?;
    let names: Vec<&str> = runs.iter().map(|r| r.name).collect();
    println!("wrote benches/SUMMARY.md and benches/ratios.svg from the {} run(s)", names.join(" and "));
    Ok(())
}

/// The inverse kinematics part (plain build only): its tables, then its targets when it was run.
fn ik_part(root: &std::path::Path, target: &std::path::Path) -> String {
    let ik = read::read_ik(root, &target.join("criterion"));
    let mut part = tables::ik_section(ik.as_ref(), &read::machine());
    if let Some(ik) = &ik {
        part += &targets::ik_targets(ik);
    }
    part
}

/// `bench-report --ik`: the inverse kinematics part of `benches/SUMMARY.md` rewritten from the
/// IK results alone, the forward kinematics sections kept as they are (measured by their own
/// runs, on whichever machine those were: the IK part names its own).
fn ik_only(root: &std::path::Path, target: &std::path::Path) -> Result<()> {
    let path = root.join("benches/SUMMARY.md");
    let summary = std::fs::read_to_string(&path)?;
    let Some(start) = summary.find(tables::IK_HEADING) else {
        return Err(format!(
            "{} has no inverse kinematics part to replace: run `cargo run -p bench-report`",
            path.display()
        )
        .into());
    };
    std::fs::write(&path, format!("{}{}", &summary[..start], ik_part(root, target)))?;
    println!("rewrote the inverse kinematics part of benches/SUMMARY.md");
    Ok(())
}
