//! Fixtures the tests write: meshes in each format, a cube or a tetrahedron, and the checks on
//! what is read back.

#![allow(dead_code)] // Each test file uses its own share.

use std::path::Path;

use kinematics_model::collision::TriangleMesh;

pub type Triangle = [[f32; 3]; 3];

/// Writes `bytes` to `path`, making its folders.
pub fn write(path: &Path, bytes: impl AsRef<[u8]>) {
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(path, bytes).unwrap();
}

/// The cube `[0, side]^3`, its triangles wound outwards.
pub fn cube(side: f32) -> Vec<Triangle> {
    let mut triangles = Vec::new();
    for axis in 0..3 {
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        for high in [false, true] {
            let corner = |a: f32, b: f32| {
                let mut p = [0.0; 3];
                p[axis] = if high { side } else { 0.0 };
                p[u] = a;
                p[v] = b;
                p
            };
            let (p00, p10, p11, p01) = (corner(0.0, 0.0), corner(side, 0.0), corner(side, side), corner(0.0, side));
            // (u, v, axis) is right-handed: u then v turns about +axis, the high face's outside.
            if high {
                triangles.extend([[p00, p10, p11], [p00, p11, p01]]);
            } else {
                triangles.extend([[p00, p11, p10], [p00, p01, p11]]);
            }
        }
    }
    triangles
}

/// The tetrahedron of the origin and the three unit points, wound outwards (volume 1/6).
pub fn tetrahedron() -> Vec<Triangle> {
    let (o, x, y, z) = ([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    vec![[o, y, x], [o, x, z], [o, z, y], [x, y, z]]
}

pub fn binary_stl(triangles: &[Triangle]) -> Vec<u8> {
    let mut out = vec![0u8; 80];
    out[..11].copy_from_slice(b"binary mesh");
    out.extend((triangles.len() as u32).to_le_bytes());
    for t in triangles {
        out.extend([0f32; 3].iter().flat_map(|x| x.to_le_bytes()));
        out.extend(t.iter().flatten().flat_map(|x| x.to_le_bytes()));
        out.extend([0u8; 2]);
    }
    out
}

pub fn ascii_stl(triangles: &[Triangle]) -> String {
    let mut out = String::from("solid test\n");
    for t in triangles {
        out.push_str("  facet normal 0 0 0\n    outer loop\n");
        for p in t {
            out.push_str(&format!("      vertex {} {} {}\n", p[0], p[1], p[2]));
        }
        out.push_str("    endloop\n  endfacet\n");
    }
    out.push_str("endsolid test\n");
    out
}

/// The unit cube as OBJ: 8 vertices and 6 quads, wound outwards.
pub fn cube_obj() -> &'static str {
    "# unit cube\nmtllib missing.mtl\no cube\n\
     v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
     f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n"
}

/// A Collada document whose one geometry, `cube`, is the cube `[0, side]^3` as triangles; `asset`
/// goes in `<asset>`, `scene` after the libraries (`<library_visual_scenes>`, `<scene>`, ...).
pub fn collada(side: f32, asset: &str, scene: &str) -> String {
    let positions: Vec<String> = cube(side).iter().flatten().map(|p| format!("{} {} {}", p[0], p[1], p[2])).collect();
    let indices: Vec<String> = (0..36).map(|i| i.to_string()).collect();
    format!(
        r##"<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset>{asset}</asset>
  <library_geometries>
    <geometry id="cube" name="cube">
      <mesh>
        <source id="cube-positions">
          <float_array id="cube-positions-array" count="108">{}</float_array>
          <technique_common>
            <accessor source="#cube-positions-array" count="36" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="cube-vertices"><input semantic="POSITION" source="#cube-positions"/></vertices>
        <triangles count="12"><input semantic="VERTEX" source="#cube-vertices" offset="0"/><p>{}</p></triangles>
      </mesh>
    </geometry>
  </library_geometries>
  {scene}
</COLLADA>
"##,
        positions.join(" "),
        indices.join(" ")
    )
}

/// A visual scene `scene` holding `nodes`, instantiated.
pub fn visual_scene(nodes: &str) -> String {
    format!(
        r##"<library_visual_scenes><visual_scene id="scene">{nodes}</visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>"##
    )
}

/// The volume the mesh encloses (positive when wound outwards): the divergence theorem's sum of
/// the tetrahedra the origin makes with each triangle.
pub fn volume(mesh: &TriangleMesh) -> f64 {
    mesh.corners()
        .map(|[a, b, c]| {
            a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
        })
        .sum::<f64>()
        / 6.0
}

/// The smallest and largest coordinates along each axis.
pub fn bounds(mesh: &TriangleMesh) -> ([f64; 3], [f64; 3]) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for v in mesh.vertices() {
        for i in 0..3 {
            lo[i] = lo[i].min(v[i]);
            hi[i] = hi[i].max(v[i]);
        }
    }
    (lo, hi)
}

pub fn assert_close(a: [f64; 3], b: [f64; 3]) {
    assert!((0..3).all(|i| (a[i] - b[i]).abs() < 1e-6), "{a:?} != {b:?}");
}
