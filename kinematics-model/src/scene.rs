//! Scene files: the obstacles a robot is checked against, kept beside the robot as TOML or JSON.
//!
//! Each obstacle is one entry of an `obstacle` array with one shape, in URDF's terms (a `sphere`,
//! a `box`, a `cylinder` or a `capsule`, each centred on its frame, cylinders and capsules along
//! its z axis), placed by `xyz` and `rpy` (metres and radians, in the robot's base frame, both
//! optional) and named by `name` (optional):
//!
//! ```toml
//! [[obstacle]]
//! name = "table"
//! xyz = [0.6, 0.0, -0.05]
//! box = { size = [0.8, 1.4, 0.1] }
//!
//! [[obstacle]]
//! name = "bottle"
//! xyz = [0.5, 0.2, 0.1]
//! rpy = [0.0, 0.0, 0.0]
//! cylinder = { radius = 0.04, length = 0.2 }
//! ```
//!
//! The sizes follow the rules of URDF's `<collision>` geometry ([`Shape::fault`]); a NaN or an
//! infinity anywhere, an entry with no shape or with two, and an unknown key are errors naming
//! the obstacle (and, in TOML, its line).

use std::path::Path;

use serde::Deserialize;

use crate::angle::Angle;
use crate::collision::Shape;
use crate::error::{Element, LoadErrorKind};
use crate::transform::FixedTransform;

/// The obstacles of a scene file, in file order.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The obstacles.
    pub obstacles: Vec<SceneObstacle>,
}

/// One obstacle: a shape placed in the robot's base frame.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneObstacle {
    /// Its name (`obstacle N`, 1-based, when the file gives none).
    pub name: String,
    /// Its position (m).
    pub xyz: [f64; 3],
    /// Its roll, pitch and yaw (rad; URDF's fixed-axis order).
    pub rpy: [f64; 3],
    /// Its shape, centred on its frame.
    pub shape: Shape,
}

impl SceneObstacle {
    /// The obstacle's frame in the base frame.
    pub fn origin(&self) -> FixedTransform {
        FixedTransform::from_xyz_rpy(self.xyz, self.rpy.map(Angle::Radians))
    }
}

/// How a scene file is written.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SceneFormat {
    /// TOML.
    Toml,
    /// JSON.
    Json,
}

impl SceneFormat {
    /// The format of a file by its extension (`.toml`, `.json`), or `None`.
    pub fn from_file_name(name: &str) -> Option<Self> {
        match Path::new(name).extension().and_then(|e| e.to_str()) {
            Some("toml") => Some(SceneFormat::Toml),
            Some("json") => Some(SceneFormat::Json),
            _ => None,
        }
    }
}

/// The file's shape, as serde reads it.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    #[serde(default)]
    obstacle: Vec<Entry>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    name: Option<String>,
    xyz: Option<[f64; 3]>,
    rpy: Option<[f64; 3]>,
    sphere: Option<SphereSize>,
    #[serde(rename = "box")]
    cuboid: Option<BoxSize>,
    cylinder: Option<RoundSize>,
    capsule: Option<RoundSize>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SphereSize {
    radius: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BoxSize {
    size: [f64; 3],
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RoundSize {
    radius: f64,
    length: f64,
}

/// Parses a scene's text.
///
/// ```
/// use kinematics_model::scene::{parse_scene, SceneFormat};
/// use kinematics_model::collision::Shape;
/// let scene = parse_scene("[[obstacle]]\nname = \"ball\"\nxyz = [0.5, 0.0, 0.3]\nsphere = { radius = 0.1 }\n", SceneFormat::Toml)?;
/// assert_eq!(scene.obstacles[0].shape, Shape::Sphere { radius: 0.1 });
/// let bad = parse_scene("[[obstacle]]\nsphere = { radius = -0.1 }\n", SceneFormat::Toml).unwrap_err();
/// assert_eq!(bad.to_string(), "obstacle 1 (line 1): <sphere radius> is -0.1 (must be a finite positive length)");
/// # Ok::<(), kinematics_model::LoadErrorKind>(())
/// ```
pub fn parse_scene(text: &str, format: SceneFormat) -> Result<Scene, LoadErrorKind> {
    let (file, lines): (SceneFile, Vec<Option<usize>>) = match format {
        SceneFormat::Toml => {
            let file: SceneFile = toml::from_str(text).map_err(|e| LoadErrorKind::Syntax {
                line: e.span().map(|s| line_of(text, s.start)),
                message: e.message().to_owned(),
            })?;
            // The line of each `[[obstacle]]` header, in order (TOML has no other way to write
            // an array of tables that holds keys of its own).
            let headers: Vec<Option<usize>> = text
                .lines()
                .enumerate()
                .filter(|(_, l)| l.trim_start().starts_with("[[obstacle]]"))
                .map(|(i, _)| Some(i + 1))
                .collect();
            let lines = if headers.len() == file.obstacle.len() { headers } else { vec![None; file.obstacle.len()] };
            (file, lines)
        }
        SceneFormat::Json => {
            let file: SceneFile = serde_json::from_str(text)
                .map_err(|e| LoadErrorKind::Syntax { line: Some(e.line()), message: e.to_string() })?;
            let lines = vec![None; file.obstacle.len()];
            (file, lines)
        }
    };
    let obstacles = file
        .obstacle
        .into_iter()
        .zip(lines)
        .enumerate()
        .map(|(index, (entry, line))| obstacle(index, entry, line))
        .collect::<Result<_, _>>()?;
    Ok(Scene { obstacles })
}

fn line_of(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())].matches('\n').count() + 1
}

fn obstacle(index: usize, entry: Entry, line: Option<usize>) -> Result<SceneObstacle, LoadErrorKind> {
    let element = Element::Obstacle(match &entry.name {
        Some(name) => format!("{} (`{name}`)", index + 1),
        None => (index + 1).to_string(),
    });
    let fault = |message: String| match line {
        Some(line) => LoadErrorKind::Located { element: Some(element.clone()), line, message },
        None => LoadErrorKind::Value { element: element.clone(), message },
    };
    let name = entry.name.clone().unwrap_or_else(|| format!("obstacle {}", index + 1));
    let shapes: Vec<Shape> = [
        entry.sphere.map(|s| Shape::Sphere { radius: s.radius }),
        entry.cuboid.map(|b| Shape::Box { size: b.size }),
        entry.cylinder.map(|c| Shape::Cylinder { radius: c.radius, length: c.length }),
        entry.capsule.map(|c| Shape::Capsule { radius: c.radius, length: c.length }),
    ]
    .into_iter()
    .flatten()
    .collect();
    let shape = match <[Shape; 1]>::try_from(shapes) {
        Ok([shape]) => shape,
        Err(shapes) => {
            return Err(fault(format!(
                "an obstacle has one shape (`sphere`, `box`, `cylinder` or `capsule`), this one has {}",
                shapes.len()
            )));
        }
    };
    if let Some(message) = shape.fault() {
        return Err(fault(message));
    }
    let (xyz, rpy) = (entry.xyz.unwrap_or_default(), entry.rpy.unwrap_or_default());
    for (key, values) in [("xyz", xyz), ("rpy", rpy)] {
        if let Some(bad) = values.iter().find(|v| !v.is_finite()) {
            return Err(fault(format!("`{key}` holds {bad}, not a finite number")));
        }
    }
    Ok(SceneObstacle { name, xyz, rpy, shape })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shape_reads_in_toml_and_json() {
        let toml = r#"
[[obstacle]]
name = "table"
xyz = [0.6, 0.0, -0.05]
box = { size = [0.8, 1.4, 0.1] }

[[obstacle]]
rpy = [0.0, 1.5707963267948966, 0.0]
cylinder = { radius = 0.04, length = 0.2 }

[[obstacle]]
capsule = { radius = 0.02, length = 0.3 }

[[obstacle]]
sphere = { radius = 0.1 }
"#;
        let scene = parse_scene(toml, SceneFormat::Toml).unwrap();
        assert_eq!(scene.obstacles.len(), 4);
        assert_eq!(scene.obstacles[0].name, "table");
        assert_eq!(scene.obstacles[1].name, "obstacle 2");
        assert_eq!(scene.obstacles[1].shape, Shape::Cylinder { radius: 0.04, length: 0.2 });
        let json = r#"{"obstacle": [
            {"name": "table", "xyz": [0.6, 0.0, -0.05], "box": {"size": [0.8, 1.4, 0.1]}},
            {"rpy": [0.0, 1.5707963267948966, 0.0], "cylinder": {"radius": 0.04, "length": 0.2}},
            {"capsule": {"radius": 0.02, "length": 0.3}},
            {"sphere": {"radius": 0.1}}
        ]}"#;
        assert_eq!(parse_scene(json, SceneFormat::Json).unwrap(), scene);
    }

    #[test]
    fn bad_obstacles_are_refused_naming_them() {
        let cases = [
            ("[[obstacle]]\nname = \"shelf\"\nbox = { size = [0.1, 0.0, 0.1] }\n", "obstacle 1 (`shelf`) (line 1)"),
            ("[[obstacle]]\nxyz = [0.0, 0.0, 0.0]\n", "has 0"),
            ("[[obstacle]]\nsphere = { radius = 0.1 }\nbox = { size = [1.0, 1.0, 1.0] }\n", "has 2"),
            ("[[obstacle]]\nsphere = { radius = 0.1 }\nxyz = [0.0, nan, 0.0]\n", "`xyz` holds NaN"),
            ("[[obstacle]]\nsphere = { radius = 0.1 }\ncolour = \"red\"\n", "line 3: unknown field `colour`"),
            ("[[obstacle]]\ncylinder = { radius = 0.1 }\n", "missing field `length`"),
        ];
        for (text, expected) in cases {
            let message = parse_scene(text, SceneFormat::Toml).unwrap_err().to_string();
            assert!(message.contains(expected), "{text}: {message}");
        }
        let json = parse_scene(r#"{"obstacle": [{"sphere": {"radius": 0}}]}"#, SceneFormat::Json).unwrap_err();
        assert_eq!(json.to_string(), "obstacle 1: <sphere radius> is 0 (must be a finite positive length)");
    }
}
