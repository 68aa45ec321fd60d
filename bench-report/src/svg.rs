//! The chart: `benches/ratios.svg`, the main speed-ups of one build as horizontal bars, a group of
//! bars per robot (paired ratios where the benchmark timed them, else ratios of the medians), with
//! a scale in whole multiples and a legend. Written by hand, as plain SVG text, so the output is
//! the same bytes for the same figures and needs no plotting crate.

use std::fmt::Write as _;

use crate::read::{Run, ratio};

/// The chart of `run`.
pub fn svg(run: &Run) -> String {
    let rows = &run.rows;
    let series: [(&str, &str, &str, &str); 6] = [
        ("std-trig pose / generated pose", "std_pose_f64", "generated_pose_f64", "#e15759"),
        ("runtime all / generated all", "runtime_all_f64", "generated_all_f64", "#4e79a7"),
        ("runtime all / trig floor of all (bound)", "runtime_all_f64", "floor_all_f64", "#a0cbe8"),
        ("k all / generated all", "k_all_f64", "generated_all_f64", "#f28e2b"),
        ("galaw all / generated all", "galaw_all_f64", "generated_all_f64", "#b07aa1"),
        ("pose / trig floor", "generated_pose_f64", "floor_f64", "#59a14f"),
    ];
    let values: Vec<Vec<Option<f64>>> = rows
        .iter()
        .map(|r| {
            series
                .iter()
                .map(|(_, a, b, _)| {
                    // The paired ratio where the benchmark timed one, else the ratio of the medians.
                    r.paired
                        .get(&format!("{a}/{b}"))
                        .copied()
                        .or_else(|| ratio(r.ns.get(a).copied(), r.ns.get(b).copied()))
                })
                .collect()
        })
        .collect();
    let max = values.iter().flatten().flatten().fold(1.0f64, |m, &v| m.max(v)).ceil();
    let (width, bar, gap, left, top, height) =
        (900.0, 14.0, 14.0, 130.0, 40.0, rows.len() as f64 * (series.len() as f64 * 14.0 + 14.0));
    let scale = (width - left - 40.0) / max;
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{}\" font-family=\"sans-serif\" font-size=\"12\">\n\
         <rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"{left}\" y=\"20\" font-size=\"14\">Forward kinematics, f64, {} build: ratios (x) per robot, from benches/SUMMARY.md (paired where timed so)</text>\n",
        top + height + 70.0,
        run.name
    );
    for (i, (r, vals)) in rows.iter().zip(&values).enumerate() {
        let y0 = top + i as f64 * (series.len() as f64 * bar + gap);
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
            left - 8.0,
            y0 + series.len() as f64 * bar / 2.0 + 4.0,
            r.group
        );
        for (j, v) in vals.iter().enumerate() {
            if let Some(v) = v {
                let y = y0 + j as f64 * bar;
                let _ = writeln!(
                    s,
                    "<rect x=\"{left}\" y=\"{y}\" width=\"{:.1}\" height=\"{}\" fill=\"{}\"/><text x=\"{:.1}\" y=\"{:.1}\" font-size=\"10\">{v:.1}</text>",
                    v * scale,
                    bar - 2.0,
                    series[j].3,
                    left + v * scale + 4.0,
                    y + bar - 4.0
                );
            }
        }
    }
    let axis_y = top + height + 5.0;
    for t in 0..=(max as usize) {
        let x = left + t as f64 * scale;
        let _ = writeln!(
            s,
            "<line x1=\"{x}\" y1=\"{top}\" x2=\"{x}\" y2=\"{axis_y}\" stroke=\"#ddd\"/><text x=\"{x}\" y=\"{}\" text-anchor=\"middle\" font-size=\"10\">{t}</text>",
            axis_y + 12.0
        );
    }
    for (j, (label, _, _, color)) in series.iter().enumerate() {
        // Three legend entries a row.
        let x = left + (j % 3) as f64 * 250.0;
        let y = axis_y + 28.0 + (j / 3) as f64 * 18.0;
        let _ = writeln!(
            s,
            "<rect x=\"{x}\" y=\"{}\" width=\"12\" height=\"12\" fill=\"{color}\"/><text x=\"{}\" y=\"{}\">{label}</text>",
            y - 10.0,
            x + 16.0,
            y
        );
    }
    s + "</svg>\n"
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;
    use crate::read::test_row;

    #[test]
    fn a_bar_per_figure_and_an_axis_to_the_largest_rounded_up() {
        // Paired where timed (7.5), else the ratio of the medians (3.0); no bar without a figure.
        let row = test_row(
            "ur5",
            &[("std_pose_f64", 30.0), ("generated_pose_f64", 10.0)],
            &[("k_all_f64/generated_all_f64", 7.5)],
        );
        let run = Run { name: "plain", build: String::new(), dir: PathBuf::new(), rows: vec![row] };
        let s = svg(&run);
        assert!(s.starts_with("<svg ") && s.ends_with("</svg>\n"));
        assert!(s.contains(">3.0</text>") && s.contains(">7.5</text>"), "{s}");
        // One background, two bars, six legend swatches.
        assert_eq!(s.matches("<rect ").count(), 1 + 2 + 6);
        // Ticks 0 to 8.
        assert!(s.contains("font-size=\"10\">8</text>") && !s.contains("font-size=\"10\">9</text>"), "{s}");
        assert!(s.contains("plain build"));
    }
}
