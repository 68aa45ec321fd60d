//! `draw --path FILE`: a path as the planner example writes it (`--path-out`), one configuration a
//! line, its values comma-separated in radians and metres (as `--q` takes them); blank lines and
//! lines starting with `#` are skipped.

use kinematics::model::KinematicTree;

use crate::error::CliError;

/// The configurations of the path file `path`, each checked against the robot: as many values as it
/// has degrees of freedom, each a finite number. Every fault names the line.
pub fn read(path: &str, tree: &KinematicTree) -> Result<Vec<Vec<f64>>, CliError> {
    let fault = |line: Option<usize>, fault: String| CliError::BadPath { path: path.to_owned(), line, fault };
    let text = std::fs::read_to_string(path).map_err(|e| fault(None, format!("cannot read: {e}")))?;
    let names: Vec<&str> = tree.dof_joints().iter().map(|&j| tree.joint(j).name.as_str()).collect();
    parse(&text, &names).map_err(|(line, message)| fault(line, message))
}

/// The configurations of a path's text, for a robot whose entries are named `names`; a fault is
/// its line (from 1) and what is wrong there.
fn parse(text: &str, names: &[&str]) -> Result<Vec<Vec<f64>>, (Option<usize>, String)> {
    let mut path = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let number = Some(index + 1);
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let q = line
            .split(',')
            .map(|value| {
                value.trim().parse::<f64>().map_err(|_| (number, format!("`{}` is not a number", value.trim())))
            })
            .collect::<Result<Vec<f64>, _>>()?;
        if q.len() != names.len() {
            return Err((
                number,
                format!(
                    "{} values, but the robot has {} degrees of freedom ({})",
                    q.len(),
                    names.len(),
                    names.join(", ")
                ),
            ));
        }
        if let Some((j, value)) = q.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err((number, format!("the value of `{}` (q[{j}]) is {value}, not a finite number", names[j])));
        }
        path.push(q);
    }
    if path.is_empty() {
        return Err((None, "no configuration (one a line, values comma-separated)".to_owned()));
    }
    Ok(path)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(text: &str, expected: Result<Vec<Vec<f64>>, (Option<usize>, &str)>) {
        let got = parse(text, &["a", "b"]);
        assert_eq!(got, expected.map_err(|(line, m)| (line, m.to_owned())), "{text:?}");
    }

    #[test]
    fn paths_are_read_line_by_line_and_faults_name_their_line() {
        check("# a path\n0,1\n\n 2 , -3e-1 \n", Ok(vec![vec![0.0, 1.0], vec![2.0, -0.3]]));
        check("0,1\n0,x\n", Err((Some(2), "`x` is not a number")));
        check("0,1\n0,1\n\n1,2,3\n", Err((Some(4), "3 values, but the robot has 2 degrees of freedom (a, b)")));
        check("0,1\nNaN,1\n", Err((Some(2), "the value of `a` (q[0]) is NaN, not a finite number")));
        check("0,inf\n", Err((Some(1), "the value of `b` (q[1]) is inf, not a finite number")));
        check("0,\n", Err((Some(1), "`` is not a number")));
        check("# nothing\n\n", Err((None, "no configuration (one a line, values comma-separated)")));
    }
}
