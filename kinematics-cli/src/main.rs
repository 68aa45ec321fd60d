//! The `kinematics` command-line tool: a thin clap front end over the library calls.
//!
//! `kinematics inspect FILE` prints the kinematic tree; `kinematics fk FILE --q ...` prints the
//! runtime reference pose of every link (or one). Errors go to stderr, naming the file and the
//! element, with a non-zero exit status.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use kinematics::ReferenceFk;
use kinematics::model::{JointMotion, KinematicTree};

/// Forward kinematics of robots described by URDF files or DH tables.
#[derive(Parser)]
#[command(name = "kinematics", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Print the kinematic tree: links, joints, types, axes, limits, mimic relations, DoF order.
    Inspect {
        /// A URDF file (.urdf, .xml) or DH table (.toml, .json).
        file: String,
    },
    /// Print the world pose of every link (or one) at a configuration, by the runtime reference.
    Fk {
        /// A URDF file (.urdf, .xml) or DH table (.toml, .json).
        file: String,
        /// Joint values in DoF order, comma-separated (radians, metres); zeros if omitted.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        q: Option<Vec<f64>>,
        /// Read `--q` in degrees (prismatic values stay in metres).
        #[arg(long)]
        degrees: bool,
        /// Print only this link.
        #[arg(long)]
        link: Option<String>,
    },
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Inspect { file } => {
            kinematics::load(&file).map_err(|e| e.to_string()).map(|t| print!("{}", inspect(&t)))
        }
        Command::Fk { file, q, degrees, link } => fk(&file, q, degrees, link.as_deref()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn inspect(tree: &KinematicTree) -> String {
    let mut out = format!(
        "robot `{}`: {} links, {} joints, {} degrees of freedom\n",
        tree.name(),
        tree.links().len(),
        tree.joints().len(),
        tree.dof()
    );
    out += &format!("root link: {}\n", tree.link(tree.root()).name);
    out += "joints (depth-first from the root):\n";
    for joint in tree.joints() {
        let motion = match joint.motion {
            JointMotion::Fixed => String::new(),
            JointMotion::Dof(i) => format!("  q[{i}]"),
            JointMotion::Mimic { source, multiplier, offset, .. } => {
                format!("  = {multiplier} * {} + {offset}", tree.joint(source).name)
            }
        };
        let axis = if joint.kind.name() == "fixed" {
            String::new()
        } else {
            format!("  axis ({:.6}, {:.6}, {:.6})", joint.axis[0], joint.axis[1], joint.axis[2])
        };
        let limits = joint.limits.map(|l| format!("  limits [{}, {}]", l.lower, l.upper)).unwrap_or_default();
        out += &format!(
            "  {:<24} {:<10} {} -> {}{axis}{limits}{motion}\n",
            joint.name,
            joint.kind.name(),
            tree.link(joint.parent).name,
            tree.link(joint.child).name
        );
    }
    out += &format!("DoF order: {}\n", tree.dof_names().join(", "));
    out
}

fn fk(file: &str, q: Option<Vec<f64>>, degrees: bool, link: Option<&str>) -> Result<(), String> {
    let fk = ReferenceFk::new(kinematics::load(file).map_err(|e| e.to_string())?);
    let tree = fk.tree();
    let mut q = q.unwrap_or_else(|| vec![0.0; tree.dof()]);
    if degrees {
        for (value, &joint) in q.iter_mut().zip(tree.dof_joints()) {
            if tree.joint(joint).kind.is_rotational() {
                *value = value.to_radians();
            }
        }
    }
    let poses = fk.link_poses(&q).map_err(|e| format!("{file}: {e}"))?;
    let selected: Vec<usize> = match link {
        Some(name) => vec![fk.link_id(name).map_err(|e| format!("{file}: {e}"))?.0],
        None => (0..poses.len()).collect(),
    };
    println!("robot `{}` at q = {:?}", tree.name(), q);
    println!("{:<24} {:>34}   {:>30}", "link", "position (m)", "roll, pitch, yaw (rad)");
    for i in selected {
        let pose = poses[i];
        let p = pose.translation.vector;
        let (r, pch, y) = pose.rotation.euler_angles();
        println!(
            "{:<24} ({:>10.6}, {:>10.6}, {:>10.6})   ({:>8.5}, {:>8.5}, {:>8.5})",
            tree.link(kinematics::model::LinkId(i)).name,
            p.x,
            p.y,
            p.z,
            r,
            pch,
            y
        );
    }
    Ok(())
}
