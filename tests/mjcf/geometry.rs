//! MJCF geometry (issue 59): a body's `<geom>`s as its link's collision geometry, sized and placed
//! as MuJoCo reads them (types, `fromto`, classes, mesh assets under `meshdir`), visual and world
//! geoms left out, `<contact>` and the contact bits ruling pairs out; the MJCF twin of
//! `panda_meshes.urdf` giving the same link poses and the same spheres; errors naming the body
//! and the line. A module of the MJCF tests.

use std::path::Path;

use kinematics::ReferenceFk;
use kinematics::model::collision::{Cover, Meshes, Shape, collision_pairs, link_spheres};
use kinematics::model::{KinematicTree, LinkId};
use kinematics::runtime::fixed_isometry;
use nalgebra::Point3;

use super::{load, mjcf};

/// The shapes of link `link`, in the order written.
fn shapes(tree: &KinematicTree, link: &str) -> Vec<Shape> {
    tree.link(tree.link_id(link).unwrap()).collisions.iter().map(|c| c.shape.clone()).collect()
}

/// Where point `p` of the `k`-th element of `link` lies in the link's frame.
fn placed(tree: &KinematicTree, link: &str, k: usize, p: [f64; 3]) -> [f64; 3] {
    let element = &tree.link(tree.link_id(link).unwrap()).collisions[k];
    fixed_isometry(&element.origin).transform_point(&Point3::from(p)).coords.into()
}

fn near(a: [f64; 3], b: [f64; 3]) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
}

#[test]
fn each_type_is_sized_as_mujoco_reads_size() {
    let tree = mjcf(
        r#"<mujoco><worldbody>
             <geom name="floor" type="plane" size="1 1 0.1"/>
             <geom name="table" type="box" size="0.5 0.5 0.02" pos="0 0 -0.1"/>
             <body name="b">
               <joint name="j"/>
               <geom size="0.1"/>
               <geom type="capsule" size="0.05 0.2" pos="0 0 0.3"/>
               <geom type="cylinder" size="0.04 0.1"/>
               <geom type="box" size="0.1 0.2 0.3"/>
               <geom type="ellipsoid" size="0.1 0.2 0.3"/>
               <geom type="sphere" size="0.5" contype="0" conaffinity="0"/>
               <geom type="box" size="0.1 0.1 0.1" contype="0" conaffinity="2"/>
             </body>
           </worldbody></mujoco>"#,
    );
    assert_eq!(
        shapes(&tree, "b"),
        [
            Shape::Sphere { radius: 0.1 },
            Shape::Capsule { radius: 0.05, length: 0.4 },
            Shape::Cylinder { radius: 0.04, length: 0.2 },
            Shape::Box { size: [0.2, 0.4, 0.6] },
            Shape::Ellipsoid { radii: [0.1, 0.2, 0.3] },
            // contype 0 and conaffinity 0 touches nothing: left out; conaffinity alone is enough.
            Shape::Box { size: [0.2, 0.2, 0.2] },
        ]
    );
    assert!(near(placed(&tree, "b", 1, [0.0, 0.0, 0.2]), [0.0, 0.0, 0.5]));
    // The world body's geoms are the scene, not the robot.
    assert!(shapes(&tree, "world").is_empty());
}

#[test]
fn fromto_runs_the_shape_between_its_points() {
    let tree = mjcf(
        r#"<mujoco><worldbody><body name="b" pos="5 5 5">
             <geom type="capsule" size="0.05" fromto="0 0 0 0 0 0.4"/>
             <geom type="cylinder" size="0.03 9" fromto="0.1 0.2 0.3 0.1 0.5 0.7"/>
             <geom type="box" size="0.1 7 7" fromto="0 0 0 0.3 0 0"/>
             <geom type="ellipsoid" size="0.02 7 7" fromto="-0.1 -0.1 0 0.1 0.1 0"/>
           </body></worldbody></mujoco>"#,
    );
    let length = |a: [f64; 3], b: [f64; 3]| ((0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>()).sqrt();
    let half = length([-0.1, -0.1, 0.0], [0.1, 0.1, 0.0]) / 2.0;
    assert_eq!(
        shapes(&tree, "b"),
        [
            Shape::Capsule { radius: 0.05, length: 0.4 },
            Shape::Cylinder { radius: 0.03, length: length([0.1, 0.2, 0.3], [0.1, 0.5, 0.7]) },
            Shape::Box { size: [0.2, 0.2, 0.3] },
            Shape::Ellipsoid { radii: [0.02, 0.02, half] },
        ]
    );
    // Each shape's ends along its z axis are the two points, in either order (the shapes are
    // symmetric about their xy plane).
    let ends = [
        (0, 0.2, [0.0, 0.0, 0.0], [0.0, 0.0, 0.4]),
        (1, 0.25, [0.1, 0.2, 0.3], [0.1, 0.5, 0.7]),
        (2, 0.15, [0.0, 0.0, 0.0], [0.3, 0.0, 0.0]),
        (3, half, [-0.1, -0.1, 0.0], [0.1, 0.1, 0.0]),
    ];
    for (k, h, from, to) in ends {
        let (a, b) = (placed(&tree, "b", k, [0.0, 0.0, -h]), placed(&tree, "b", k, [0.0, 0.0, h]));
        assert!((near(a, from) && near(b, to)) || (near(a, to) && near(b, from)), "geom {k}: {a:?} {b:?}");
    }
}

#[test]
fn classes_give_geoms_their_attributes_and_a_frame_places_them() {
    let tree = mjcf(
        r#"<mujoco><default>
             <geom type="capsule" size="0.02 0.1"/>
             <default class="big"><geom size="0.05 0.3"/></default>
             <default class="visual"><geom contype="0" conaffinity="0"/></default>
           </default>
           <worldbody><body name="b" childclass="big"><joint name="j"/>
             <geom/>
             <geom class="main"/>
             <geom class="visual"/>
             <frame pos="0 0 1"><geom class="main" type="sphere"/></frame>
           </body></worldbody></mujoco>"#,
    );
    assert_eq!(
        shapes(&tree, "b"),
        [
            Shape::Capsule { radius: 0.05, length: 0.6 },
            Shape::Capsule { radius: 0.02, length: 0.2 },
            Shape::Sphere { radius: 0.02 },
        ]
    );
    assert!(near(placed(&tree, "b", 2, [0.0; 3]), [0.0, 0.0, 1.0]));
}

#[test]
fn mesh_geoms_name_their_asset_file_under_meshdir_with_its_scale() {
    let mesh = |compiler: &str| {
        let tree = mjcf(&format!(
            r#"<mujoco>{compiler}
                 <default><mesh scale="0.001 0.001 0.001"/></default>
                 <asset>
                   <mesh file="parts/link.stl" scale="2 2 2"/>
                   <mesh name="hand" file="hand.obj"/>
                 </asset>
                 <worldbody><body name="b">
                   <geom type="mesh" mesh="link"/>
                   <geom type="mesh" mesh="hand"/>
                 </body></worldbody></mujoco>"#
        ));
        shapes(&tree, "b")
            .into_iter()
            .map(|s| match s {
                Shape::Mesh { filename, scale, loaded: None } => (filename, scale),
                other => panic!("{other:?}"),
            })
            .collect::<Vec<_>>()
    };
    let milli = [0.001; 3];
    assert_eq!(mesh(""), [("parts/link.stl".to_owned(), [2.0; 3]), ("hand.obj".to_owned(), milli)]);
    assert_eq!(
        mesh(r#"<compiler meshdir="assets"/>"#),
        [("assets/parts/link.stl".to_owned(), [2.0; 3]), ("assets/hand.obj".to_owned(), milli)]
    );
    // `assetdir` serves when no `meshdir` is written; `strippath` drops the file's folders.
    assert_eq!(mesh(r#"<compiler assetdir="a" strippath="true"/>"#)[0].0, "a/link.stl");
    assert_eq!(mesh(r#"<compiler meshdir="/abs/m" assetdir="a"/>"#)[0].0, "/abs/m/parts/link.stl");
}

#[test]
fn contact_exclusions_and_bits_rule_pairs_out_and_an_explicit_pair_brings_one_back() {
    let text = |pair: &str| {
        format!(
            r#"<mujoco><worldbody>
                 <body name="a"><joint name="ja"/><geom name="ga" size="0.1"/>
                   <body name="b" pos="1 0 0"><joint name="jb"/><geom size="0.1"/>
                     <body name="c" pos="1 0 0"><joint name="jc"/><geom size="0.1"/></body>
                   </body>
                 </body>
                 <body name="d" pos="0 3 0"><joint name="jd"/><geom name="gd" size="0.1" contype="2" conaffinity="2"/></body>
               </worldbody>
               <contact><exclude body1="c" body2="a"/>{pair}</contact></mujoco>"#
        )
    };
    let tree = mjcf(&text(""));
    let excluded: Vec<(&str, &str)> =
        tree.excluded_pairs().iter().map(|p| (p.link1.as_str(), p.link2.as_str())).collect();
    assert_eq!(excluded, [("a", "c"), ("a", "d"), ("b", "d"), ("c", "d")]);
    assert_eq!(tree.excluded_pairs()[0].why, "<contact><exclude> (line 9)");
    assert_eq!(tree.excluded_pairs()[1].why, "their geoms' contype and conaffinity never meet");
    let pairs = |tree: &KinematicTree| {
        let named = |l: LinkId| tree.link(l).name.clone();
        collision_pairs(tree, &|l| !tree.link(l).collisions.is_empty(), None)
            .pairs
            .into_iter()
            .map(|(a, b)| (named(a), named(b)))
            .collect::<Vec<_>>()
    };
    // a-b and b-c are adjacent, a-c excluded, d meets none of them.
    assert!(pairs(&tree).is_empty());
    let tree = mjcf(&text(r#"<pair geom1="gd" geom2="ga"/>"#));
    assert_eq!(pairs(&tree), [("a".to_owned(), "d".to_owned())]);
}

#[test]
fn geometry_errors_name_the_body_and_the_line() {
    let check = |body: &str, expected: &str| {
        let text = format!(
            "<mujoco>\n<asset><mesh name=\"inline\" vertex=\"0 0 0 1 0 0 0 1 0\"/></asset>\n<worldbody>\n{body}\n</worldbody>\n</mujoco>"
        );
        assert_eq!(load(&text).unwrap_err(), expected, "{body}");
    };
    check(
        r#"<body name="b"><geom type="capsule" size="0.1"/></body>"#,
        "t.xml: body `b` (line 4): <geom>: a capsule needs 2 sizes (radius, half-length), `size` gives `0.1`",
    );
    check(
        r#"<body name="b"><geom/></body>"#,
        "t.xml: body `b` (line 4): <geom>: a sphere needs 1 sizes (radius), `size` gives none",
    );
    check(
        r#"<body name="b"><geom type="mesh" mesh="arm"/></body>"#,
        "t.xml: body `b` (line 4): <geom>: no <asset><mesh> named `arm`",
    );
    check(
        r#"<body name="b"><geom type="box" mesh="inline"/></body>"#,
        "t.xml: body `b` (line 4): <geom>: a box fitted to mesh `inline` is not read: write `type=\"mesh\"`",
    );
    check(
        r#"<body name="b"><geom type="mesh" mesh="inline"/></body>"#,
        "t.xml: body `b` (line 2): <mesh name=\"inline\">: `vertex` is not read (give the mesh as a file, placed by the geom)",
    );
    check(
        r#"<body name="b"><geom type="sdf" size="1"/></body>"#,
        "t.xml: body `b` (line 4): `type=\"sdf\"` is not one of plane, hfield, sphere, capsule, ellipsoid, cylinder, box, mesh",
    );
    check(
        r#"<body name="b"><geom size="0.1" contype="1.5"/></body>"#,
        "t.xml: body `b` (line 4): <geom>: `contype=\"1.5\"` is not a bit mask (0 to 2^31 - 1)",
    );
    check(
        r#"<body name="b"><geom type="capsule" size="0.1" fromto="0 0 0 0 0 1" pos="1 0 0"/></body>"#,
        "t.xml: body `b` (line 4): <geom>: `pos` and `fromto` cannot both place it",
    );
    check(
        r#"<body name="b"><geom size="-0.1"/></body>"#,
        "t.xml: body `b` (line 4): <geom>: `size=\"-0.1\"`: <sphere radius> is -0.1 (must be a finite positive length)",
    );
    check(
        r#"<body name="b"><geom size="0.1" colour="red"/></body>"#,
        "t.xml: body `b` (line 4): <geom>: unknown attribute `colour`",
    );
    let contact = |inner: &str| {
        let text = format!(
            "<mujoco><worldbody><body name=\"b\"><geom name=\"g\" size=\"1\"/></body></worldbody>\n<contact>{inner}</contact></mujoco>"
        );
        load(&text).unwrap_err()
    };
    assert_eq!(contact(r#"<exclude body1="b" body2="x"/>"#), "t.xml: line 2: <contact><exclude>: no body `x`");
    assert_eq!(contact(r#"<pair geom1="g" geom2="h"/>"#), "t.xml: line 2: <contact><pair>: no geom `h`");
    assert_eq!(contact(r#"<exclude body1="b"/>"#), "t.xml: line 2: <contact><exclude> needs `body2`");
}

/// The MJCF twin of `panda_meshes.urdf` (`tests/fixtures/mujoco/panda_meshes.xml`), its meshes
/// read as the derive reads them.
fn with_meshes(path: &Path) -> KinematicTree {
    let mut tree = kinematics::load(path).unwrap();
    let resolver = kinematics_meshes::Resolver::new(path, &kinematics_meshes::Packages::new());
    kinematics_meshes::load_tree_meshes(&mut tree, &resolver).unwrap();
    tree
}

#[test]
fn the_mjcf_panda_is_its_urdf_twin_link_for_link_and_sphere_for_sphere() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let from_mjcf = with_meshes(&root.join("tests/fixtures/mujoco/panda_meshes.xml"));
    let from_urdf = with_meshes(&root.join("robots/panda_meshes.urdf"));
    // The visual geoms (whose files are not shipped) were not read, the floor neither.
    assert!(from_mjcf.ignored().is_empty(), "{:?}", from_mjcf.ignored());
    assert_eq!(from_mjcf.dof_names(), from_urdf.dof_names());
    let (m, u) = (ReferenceFk::new(from_mjcf.clone()), ReferenceFk::new(from_urdf.clone()));
    for k in 0..20 {
        let q: Vec<f64> = (0..from_urdf.dof()).map(|i| (((i * 7 + k * 13) % 17) as f64 / 17.0 - 0.5) * 2.0).collect();
        for link in from_urdf.links().iter().map(|l| l.name.as_str()).filter(|l| from_mjcf.link_id(l).is_some()) {
            let (a, b) = (m.link_pose(&q, link).unwrap(), u.link_pose(&q, link).unwrap());
            assert!((a.to_homogeneous() - b.to_homogeneous()).amax() < 1e-12, "{link} at {q:?}");
        }
    }
    let spheres = |tree: &KinematicTree| {
        let mut out: Vec<(String, [f64; 3], f64)> = link_spheres(tree, &Cover::default(), Meshes::Read)
            .unwrap()
            .into_iter()
            .map(|s| (tree.link(s.link).name.clone(), s.sphere.center, s.sphere.radius))
            .collect();
        out.sort_by(|a, b| a.0.cmp(&b.0));
        out
    };
    let (a, b) = (spheres(&from_mjcf), spheres(&from_urdf));
    assert_eq!(a.len(), b.len());
    assert!(a.len() > 50, "{}", a.len());
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.0, y.0);
        assert!(near(x.1, y.1) && (x.2 - y.2).abs() < 1e-12, "{x:?} against {y:?}");
    }
}
