//! MJCF mass and inertia (issue 61): a body's `<inertial>` (`diaginertia` in its orientation's
//! axes, `fullinertia` in MuJoCo's order turned into URDF's, placed by the body's frames), which
//! bodies `<compiler inertiafromgeom>` leaves to MuJoCo's geoms, the world body's refused, and
//! errors naming the body and the line. The expected values are MuJoCo 4.0.1's where it gives
//! them (its `body_inertia`, `body_ipos`). A module of the MJCF tests.

use std::path::Path;

use kinematics::model::KinematicTree;
use kinematics::model::inertia::Inertial;
use kinematics::runtime::fixed_isometry;
use nalgebra::Matrix3;

use super::{load, mjcf};

/// Link `link`'s inertial, which it must have.
fn inertial(tree: &KinematicTree, link: &str) -> Inertial {
    let found = tree.link_by_name(link).unwrap_or_else(|| panic!("no link `{link}`"));
    found.inertial.clone().unwrap_or_else(|| panic!("link `{link}` has no inertial"))
}

/// The tensor in the link's axes, `R I R^T` with `R` the centre-of-mass frame's rotation.
fn in_link_axes(i: &Inertial) -> Matrix3<f64> {
    let r = fixed_isometry(&i.origin).rotation.to_rotation_matrix().into_inner();
    let m = i.matrix();
    r * Matrix3::from_fn(|row, col| m[row][col]) * r.transpose()
}

/// The centre of mass in the link's frame.
fn centre(i: &Inertial) -> [f64; 3] {
    fixed_isometry(&i.origin).translation.vector.into()
}

#[track_caller]
fn near(a: Matrix3<f64>, b: Matrix3<f64>) {
    assert!((a - b).abs().max() < 1e-15, "{a} is not {b}");
}

#[track_caller]
fn near3(a: [f64; 3], b: [f64; 3]) {
    assert!((0..3).all(|i| (a[i] - b[i]).abs() < 1e-15), "{a:?} is not {b:?}");
}

#[test]
fn diaginertia_gives_the_principal_moments_in_the_orientations_axes() {
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="b" pos="1 0 0"><joint name="j"/>
             <inertial pos="0.1 0.2 0.3" euler="0 0 90" mass="2" diaginertia="1 2 3"/>
           </body>
           <body name="q"><inertial pos="0 0 0" quat="0.7071067811865476 0 0 0.7071067811865476" mass="2" diaginertia="1 2 3"/></body>
           </worldbody></mujoco>"#,
    );
    let b = inertial(&tree, "b");
    assert_eq!((b.mass, b.inertia), (2.0, [1.0, 0.0, 0.0, 2.0, 0.0, 3.0]));
    assert_eq!(tree.inertial_line("b"), Some(2));
    near3(centre(&b), [0.1, 0.2, 0.3]);
    // MuJoCo: iquat (0.7071, 0, 0, 0.7071), body_inertia (1, 2, 3): about the body's axes the
    // moments about x and y trade places.
    let turned = Matrix3::from_diagonal(&[2.0, 1.0, 3.0].into());
    near(in_link_axes(&b), turned);
    // A quaternion says the same.
    assert!((in_link_axes(&inertial(&tree, "q")) - turned).abs().max() < 1e-15);
    // None of them is left to the geoms.
    assert!(tree.inertia_from_geometry().is_empty());
}

#[test]
fn fullinertia_is_read_in_mujocos_order() {
    let tree = mjcf(
        r#"<mujoco><worldbody>
             <body name="full"><joint/><inertial pos="0 0 0" mass="1" fullinertia="3 4 5 0.1 0.2 0.3"/></body>
             <body name="by_hand"><joint/><inertial pos="0 0 0" mass="1" fullinertia="1.5 1.5 3 -0.5 0 0"/></body>
             <body name="turned"><joint/><inertial pos="0 0 0" mass="1" euler="0 0 45" diaginertia="1 2 3"/></body>
           </worldbody></mujoco>"#,
    );
    // M(1,1) M(2,2) M(3,3) M(1,2) M(1,3) M(2,3) into ixx ixy ixz iyy iyz izz.
    let full = inertial(&tree, "full");
    assert_eq!(full.inertia, [3.0, 0.1, 0.2, 4.0, 0.3, 5.0]);
    assert!(full.origin.steps().is_empty(), "the tensor is in the body's axes");
    // MuJoCo's principal moments of it (body_inertia 5.10597667 3.91882911 2.97519422).
    let moments = full.principal_moments();
    for (got, mujoco) in moments.iter().zip([2.97519422, 3.91882911, 5.10597667]) {
        assert!((got - mujoco).abs() < 1e-8, "{moments:?}");
    }
    // A tensor made by hand: diag(1, 2, 3) turned 45 degrees about z is
    // [[1.5, -0.5, 0], [-0.5, 1.5, 0], [0, 0, 3]]; the same body as diaginertia and euler.
    let by_hand = inertial(&tree, "by_hand");
    assert_eq!(by_hand.inertia, [1.5, -0.5, 0.0, 1.5, 0.0, 3.0]);
    let expected = Matrix3::new(1.5, -0.5, 0.0, -0.5, 1.5, 0.0, 0.0, 0.0, 3.0);
    assert!((in_link_axes(&inertial(&tree, "turned")) - expected).abs().max() < 1e-15);
    near(in_link_axes(&by_hand), expected);
}

#[test]
fn a_frame_places_the_inertial_of_its_body() {
    // MuJoCo 4.0.1: body_ipos (0, 1, 0), body_inertia (3, 2, 1) on turned axes.
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="b"><joint/>
             <frame euler="0 0 90"><inertial pos="1 0 0" mass="1" fullinertia="1 2 3 0 0 0"/></frame>
           </body></worldbody></mujoco>"#,
    );
    let b = inertial(&tree, "b");
    near3(centre(&b), [0.0, 1.0, 0.0]);
    near(in_link_axes(&b), Matrix3::from_diagonal(&[2.0, 1.0, 3.0].into()));
}

#[test]
fn the_inertial_of_a_body_with_several_joints_is_its_last_links() {
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="b"><joint name="j1"/><joint name="j2" axis="1 0 0"/>
             <inertial pos="0 0 0.5" mass="4" diaginertia="1 1 1"/>
           </body></worldbody></mujoco>"#,
    );
    assert_eq!(inertial(&tree, "b").mass, 4.0);
    assert_eq!(tree.link_by_name("b.j1").unwrap().inertial, None);
    assert_eq!(tree.link_by_name("world").unwrap().inertial, None);
}

/// Bodies of every kind for `inertiafromgeom`: geoms only, both, an inertial only, neither, a
/// visual geom only, a geom in a frame; the world body's geom is the scene.
fn bodies(compiler: &str) -> KinematicTree {
    mjcf(&format!(
        r#"<mujoco>{compiler}<worldbody>
             <geom name="floor" type="plane" size="1 1 1"/>
             <body name="geom_only"><joint/><geom size="0.1"/>
               <body name="both"><joint/><geom size="0.1"/><inertial pos="0 0 0" mass="2" diaginertia="1 1 1"/>
                 <body name="inertial_only"><joint/><inertial pos="0 0 0" mass="3" diaginertia="1 1 1"/>
                   <body name="neither"><joint/><site name="s"/>
                     <body name="visual"><joint/><geom size="0.1" contype="0" conaffinity="0"/>
                       <body name="in_frame"><joint/><frame pos="1 0 0"><geom size="0.1"/></frame></body>
                     </body>
                   </body>
                 </body>
               </body>
             </body>
           </worldbody></mujoco>"#
    ))
}

/// The links left to their geoms, sorted, and each link's mass where it has an inertial.
fn inertias(tree: &KinematicTree) -> (Vec<String>, Vec<(String, f64)>) {
    let mut listed = tree.inertia_from_geometry().to_vec();
    listed.sort();
    let masses = tree.links().iter().filter_map(|l| Some((l.name.clone(), l.inertial.as_ref()?.mass))).collect();
    (listed, masses)
}

fn names(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| (*s).to_owned()).collect()
}

#[test]
fn inertiafromgeom_auto_lists_bodies_with_geoms_and_no_inertial() {
    // MuJoCo 4.0.1: a body with a geom and an <inertial> keeps the inertial's mass; a visual geom
    // and a geom in a frame give mass.
    for compiler in ["", r#"<compiler inertiafromgeom="auto"/>"#] {
        let (listed, masses) = inertias(&bodies(compiler));
        assert_eq!(listed, names(&["geom_only", "in_frame", "visual"]), "{compiler}");
        assert_eq!(masses, [("both".to_owned(), 2.0), ("inertial_only".to_owned(), 3.0)], "{compiler}");
    }
}

#[test]
fn inertiafromgeom_true_lists_every_body_with_geoms_dropping_its_inertial() {
    // MuJoCo 4.0.1: the geom's mass replaces the <inertial>'s; a body without geoms keeps its own.
    let (listed, masses) = inertias(&bodies(r#"<compiler inertiafromgeom="true"/>"#));
    assert_eq!(listed, names(&["both", "geom_only", "in_frame", "visual"]));
    assert_eq!(masses, [("inertial_only".to_owned(), 3.0)]);
}

#[test]
fn inertiafromgeom_false_takes_only_the_inertials() {
    let (listed, masses) = inertias(&bodies(r#"<compiler inertiafromgeom="false"/>"#));
    assert!(listed.is_empty(), "{listed:?}");
    assert_eq!(masses, [("both".to_owned(), 2.0), ("inertial_only".to_owned(), 3.0)]);
}

#[test]
fn an_attached_model_keeps_its_own_inertiafromgeom() {
    let arm = r#"<mujoco><compiler inertiafromgeom="false"/><worldbody>
                   <body name="arm"><joint/><geom size="0.1"/></body></worldbody></mujoco>"#;
    let main = r#"<mujoco><asset><model name="arm" file="arm.xml"/></asset><worldbody>
                    <body name="mount"><geom size="0.1"/><attach model="arm" body="arm" prefix="a_"/></body>
                  </worldbody></mujoco>"#;
    let source =
        kinematics::model::Source::from_file_name("t.xml", kinematics::model::SourceKind::ByExtension, main).unwrap();
    let read = |path: &str| if path == "arm.xml" { Ok(arm.to_owned()) } else { Err(format!("no {path}")) };
    let tree = source.load_reading(kinematics::ExactAngles::default(), None, &read).unwrap();
    assert_eq!(tree.inertia_from_geometry(), ["mount"]);
}

#[test]
fn the_world_body_takes_no_inertial() {
    let why = "the world body has no mass (MuJoCo: \"World body cannot have inertia\")";
    let inertial = r#"<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>"#;
    assert_eq!(
        load(&format!("<mujoco>\n<worldbody>\n{inertial}\n</worldbody></mujoco>")).unwrap_err(),
        format!("t.xml: line 3: an <inertial> belongs in a <body>, not in <worldbody>: {why}")
    );
    assert_eq!(
        load(&format!("<mujoco>\n<worldbody><frame>\n{inertial}\n</frame></worldbody></mujoco>")).unwrap_err(),
        format!("t.xml: line 3: an <inertial> belongs in a <body>, not in <frame>: {why}")
    );
}

#[test]
fn inertial_errors_name_the_body_and_the_line() {
    let error = |body: &str| {
        load(&format!("<mujoco>\n<worldbody>\n{body}\n</worldbody>\n</mujoco>")).expect_err(body).to_string()
    };
    let inertial = |attributes: &str| error(&format!(r#"<body name="b"><inertial {attributes}/></body>"#));
    let at = "t.xml: body `b` (line 3): <inertial>: ";
    let cases = [
        (r#"pos="0 0 0" mass="x" diaginertia="1 1 1""#, "`mass=\"x\"`: `x` is not a number"),
        (r#"pos="0 0 0" mass="1 2" diaginertia="1 1 1""#, "`mass=\"1 2\"` needs 1 numbers, found 2"),
        (r#"pos="0 0" mass="1" diaginertia="1 1 1""#, "`pos=\"0 0\"` needs 3 numbers, found 2"),
        (r#"pos="0 0 0" mass="1" diaginertia="1 2""#, "`diaginertia=\"1 2\"` needs 3 numbers, found 2"),
        (r#"pos="0 0 0" mass="1" fullinertia="1 2 3""#, "`fullinertia=\"1 2 3\"` needs 6 numbers, found 3"),
        (r#"pos="0 0 0" mass="1" euler="0 0" diaginertia="1 1 1""#, "`euler=\"0 0\"` needs 3 numbers, found 2"),
        (r#"mass="1" diaginertia="1 1 1""#, "needs a `pos` (MuJoCo requires one)"),
        (r#"pos="0 0 0" diaginertia="1 1 1""#, "needs a `mass` (MuJoCo requires one)"),
        (r#"pos="0 0 0" mass="1""#, "needs `diaginertia` or `fullinertia` (MuJoCo's XML reference requires one)"),
        (
            r#"pos="0 0 0" mass="1" diaginertia="1 1 1" fullinertia="1 1 1 0 0 0""#,
            "`diaginertia` and `fullinertia` cannot both be written",
        ),
        (
            r#"pos="0 0 0" mass="1" quat="1 0 0 0" fullinertia="1 1 1 0 0 0""#,
            "`fullinertia` and `quat` cannot both be written: the tensor is in the body's axes (MuJoCo refuses both)",
        ),
        (
            r#"pos="0 0 0" mass="1" quat="1 0 0 0" euler="0 0 0" diaginertia="1 1 1""#,
            "more than one orientation (`quat` and `euler`): write one",
        ),
        (r#"pos="0 0 0" mass="1" diaginertia="1 1 1" inertia="1""#, "unknown attribute `inertia`"),
    ];
    for (attributes, expected) in cases {
        assert_eq!(inertial(attributes), format!("{at}{expected}"), "{attributes}");
    }
    // The second <inertial> of a body, at its own line.
    let one = r#"<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>"#;
    assert_eq!(
        error(&format!("<body name=\"b\">{one}\n<frame>{one}</frame></body>")),
        "t.xml: body `b` (line 4): <inertial>: a second one in this body (MuJoCo's schema allows one)"
    );
    // An unnamed body is named by MuJoCo's id.
    assert_eq!(
        error(r#"<body><inertial pos="0 0 0" mass="heavy" diaginertia="1 1 1"/></body>"#),
        "t.xml: body `body1` (line 3): <inertial>: `mass=\"heavy\"`: `heavy` is not a number"
    );
    assert_eq!(
        load("<mujoco>\n<compiler inertiafromgeom=\"maybe\"/><worldbody/></mujoco>").unwrap_err(),
        "t.xml: line 2: `inertiafromgeom=\"maybe\"` is not one of false, true, auto"
    );
}

#[test]
fn values_are_taken_as_written() {
    // A negative mass and a NaN load (MuJoCo's compiler refuses a moving body of either):
    // dynamics check the rules of a rigid body, loading does not.
    let tree = mjcf(
        r#"<mujoco><worldbody>
             <body name="negative"><joint/><inertial pos="0 0 0" mass="-1" diaginertia="1 1 1"/></body>
             <body name="nan"><joint/><inertial pos="0 0 0" mass="nan" diaginertia="1 1 1"/></body>
           </worldbody></mujoco>"#,
    );
    assert_eq!(inertial(&tree, "negative").mass, -1.0);
    assert!(inertial(&tree, "nan").mass.is_nan());
    assert!(inertial(&tree, "negative").fault(false).is_some());
}

/// Every MJCF file of `robots/` and `tests/fixtures/mujoco/` loads: none writes an <inertial>, so
/// with `inertiafromgeom` at its default the bodies with geoms are listed, and no link has mass.
#[test]
fn the_robots_and_fixtures_load_with_their_geoms_listed() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["robots", "tests/fixtures/mujoco"] {
        for entry in std::fs::read_dir(root.join(dir)).unwrap() {
            let path = entry.unwrap().path();
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            if path.extension().is_some_and(|e| e == "xml") && text.contains("<mujoco") {
                files.push(path);
            }
        }
    }
    files.sort();
    assert!(files.len() >= 11, "{files:?}");
    for path in files {
        let tree = kinematics::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(tree.links().iter().all(|l| l.inertial.is_none()), "{}", path.display());
        let listed = tree.inertia_from_geometry();
        assert!(!listed.is_empty(), "{}: its bodies have geoms", path.display());
        for link in listed {
            assert!(tree.link_by_name(link).is_some(), "{}: `{link}`", path.display());
        }
    }
    // The walker: its one geom is the torso's.
    let walker = kinematics::load(root.join("robots/walker.xml")).unwrap();
    assert_eq!(walker.inertia_from_geometry().len(), 1);
}
