//! `kinematics fk FILE --q ...`: link poses at a configuration, by the runtime reference.
//!
//! As a table or as JSON.

use std::io::Write;

use kinematics::ReferenceFk;
use kinematics::model::LinkId;
use serde_json::json;

use crate::error::CliError;

/// Arguments of `fk`.
#[derive(clap::Args)]
pub struct Args {
    /// A URDF file (.urdf, .xml), MJCF file (.xml, .mjcf) or DH table (.toml, .json).
    file: String,
    #[command(flatten)]
    configuration: crate::robot::ConfigurationArgs,
    /// Print only this link.
    #[arg(long)]
    link: Option<String>,
    /// Print JSON: the robot, `q` (radians) and, per link, its name, translation and rotation matrix
    /// (rows).
    #[arg(long)]
    json: bool,
}

/// Prints the poses.
pub fn run(args: &Args, out: &mut dyn Write) -> Result<(), CliError> {
    let file = &args.file;
    let fk = ReferenceFk::new(crate::robot::load(file)?);
    let tree = fk.tree();
    // Documented default: zeros when `--q` is omitted.
    let q = args.configuration.resolve(tree);
    let poses = fk.link_poses(&q).map_err(|source| CliError::Runtime { file: file.clone(), source })?;
    let selected: Vec<LinkId> = match &args.link {
        Some(name) => vec![crate::robot::link(tree, file, "requested", name)?],
        None => (0..poses.len()).map(LinkId).collect(),
    };
    if args.json {
        let links: Vec<_> = selected
            .iter()
            .map(|&id| {
                let pose = poses[id.0];
                let r = pose.rotation.to_rotation_matrix();
                json!({
                    "name": tree.link(id).name,
                    "translation": pose.translation.vector.as_slice(),
                    "rotation": (0..3).map(|i| [r[(i, 0)], r[(i, 1)], r[(i, 2)]]).collect::<Vec<_>>(),
                })
            })
            .collect();
        let document = json!({ "robot": tree.name(), "q": q, "links": links });
        writeln!(out, "{document:#}")?;
        return Ok(());
    }
    writeln!(out, "robot `{}` at q = {:?}", tree.name(), q)?;
    let width = crate::inspect::column_width(selected.iter().map(|&id| tree.link(id).name.as_str())).max(24);
    writeln!(out, "{} {:>34}   {:>30}", crate::inspect::pad("link", width), "position (m)", "roll, pitch, yaw (rad)")?;
    for id in selected {
        let pose = poses[id.0];
        let p = pose.translation.vector;
        let (roll, pitch, yaw) = pose.rotation.euler_angles();
        writeln!(
            out,
            "{} ({:>10.6}, {:>10.6}, {:>10.6})   ({:>8.5}, {:>8.5}, {:>8.5})",
            crate::inspect::pad(&tree.link(id).name, width),
            p.x,
            p.y,
            p.z,
            roll,
            pitch,
            yaw
        )?;
    }
    Ok(())
}
