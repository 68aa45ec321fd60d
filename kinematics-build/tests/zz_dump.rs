//! Temporary: dump generated code for every robot and option set (byte-identity check).
use kinematics_build::{Robot, Trig};
use kinematics_model::{ExactAngles, Source, SourceKind};

#[test]
fn dump() {
    let out = std::env::var("DUMP_DIR").unwrap();
    std::fs::create_dir_all(&out).unwrap();
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files: Vec<_> = std::fs::read_dir(root.join("robots")).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    for path in files {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let bytes = std::fs::read(&path).unwrap();
        let Ok(source) = Source::from_bytes(name.clone(), SourceKind::ByExtension, bytes) else { continue };
        let Ok(tree) = source.load(ExactAngles::default()) else { continue };
        let links: Vec<String> = tree.links().iter().map(|l| l.name.clone()).collect();
        let leaves: Vec<String> = tree.links().iter().enumerate()
            .filter(|(_, l)| l.child_joints.is_empty())
            .map(|(_, l)| l.name.clone()).collect();
        let tip = leaves.last().unwrap().clone();
        let base = || Robot::file(path.clone());
        let mut sets: Vec<(&str, Robot)> = vec![
            ("plain", base()),
            ("tip_all", base().tip(&tip).positions().jacobians().f32()),
            ("tips_all", base().tips(&leaves).positions().jacobians()),
            ("ik", base().tip(&tip).ik()),
            ("ik_jac", base().tip(&tip).ik().jacobians().f32()),
            ("ik_numeric", base().tip(&tip).ik_numeric()),
            ("links", base().links([links[links.len() - 1].clone(), links[1].clone()]).positions()),
            ("std_inexact", base().tip(&tip).trig(Trig::Std).exact_angles(false)),
            ("free", base().tip(&tip).ik_free("iiwa_joint_3")),
            ("named", base().struct_name("Named").crate_path("kin")),
        ];
        if name.ends_with(".urdf") {
            sets.push(("floating", base().floating_base("world_fb").tip(&tip).jacobians()));
        }
        for (set, robot) in sets {
            let text = match robot.generate() {
                Ok(code) => code,
                Err(e) => format!("ERROR\n{e}\n"),
            };
            std::fs::write(format!("{out}/{name}.{set}.rs"), text).unwrap();
        }
    }
}
