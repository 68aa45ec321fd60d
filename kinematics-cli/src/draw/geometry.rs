//! The collision geometry drawn under the spheres: every link's `<collision>` elements placed at
//! the configuration drawn (the link's pose by the runtime reference composed with the element's
//! origin, by the runtime's `fixed_isometry`), and the points that trace each one in a view.
//!
//! A primitive (sphere, ellipsoid, box, cylinder, capsule) is convex, so its projection is the
//! convex hull of the projections of a few points of its surface: a box's eight corners, and for
//! a round shape its support points (the point farthest along a direction) for a ring of
//! directions in the view's plane, as many as keep the hull within a quarter pixel of the curve.
//! Every such point lies on the shape's surface, so the hull lies inside the true projection.
//!
//! A mesh keeps its triangles (scaled and placed in the root frame): `silhouette.rs` turns their
//! projections into the region they cover.

use std::f64::consts::PI;

use kinematics::model::KinematicTree;
use kinematics::model::collision::Shape;
use nalgebra::{Isometry3, Point3, Vector3};

/// A `<collision>` element of a link, placed at the configuration drawn.
pub struct Solid {
    /// Its link's name.
    pub link: String,
    /// Its place among the link's `<collision>` elements (from 0).
    pub element: usize,
    /// Its shape's name as URDF writes it (`box`, `mesh`, ...).
    pub shape: &'static str,
    /// Its geometry in the root frame.
    pub form: Form,
}

/// A placed element's geometry.
pub enum Form {
    /// A primitive: its frame in the root frame and its shape there.
    Convex {
        /// The element's frame (link pose, then origin).
        pose: Isometry3<f64>,
        /// The shape in that frame.
        shape: Convex,
    },
    /// A mesh: its vertices scaled and placed in the root frame, and its triangles (indices).
    Mesh {
        /// Vertices (metres, root frame).
        vertices: Vec<[f64; 3]>,
        /// Triangles, as indices into `vertices`.
        triangles: Vec<[u32; 3]>,
    },
}

/// A convex primitive, centred in its own frame (round shapes' axes along z).
#[derive(Clone, Copy, Debug)]
pub enum Convex {
    /// A ball.
    Sphere {
        /// Radius.
        radius: f64,
    },
    /// An ellipsoid of semi-axes along x, y, z.
    Ellipsoid {
        /// Semi-axes.
        radii: [f64; 3],
    },
    /// A box.
    Box {
        /// Half its edge lengths along x, y, z.
        half: [f64; 3],
    },
    /// A cylinder.
    Cylinder {
        /// Radius.
        radius: f64,
        /// Half its length.
        half_length: f64,
    },
    /// A capsule: the points within `radius` of the segment of `2 * half_length` along z.
    Capsule {
        /// Radius.
        radius: f64,
        /// Half the segment's length.
        half_length: f64,
    },
}

impl Convex {
    /// The primitive of a model shape; `None` for a mesh.
    fn of(shape: &Shape) -> Option<Self> {
        Some(match *shape {
            Shape::Sphere { radius } => Convex::Sphere { radius },
            Shape::Ellipsoid { radii } => Convex::Ellipsoid { radii },
            Shape::Box { size } => Convex::Box { half: size.map(|s| s / 2.0) },
            Shape::Cylinder { radius, length } => Convex::Cylinder { radius, half_length: length / 2.0 },
            Shape::Capsule { radius, length } => Convex::Capsule { radius, half_length: length / 2.0 },
            Shape::Mesh { .. } => return None,
        })
    }

    /// A point of the surface farthest along the unit direction `e` (its own frame). Where several
    /// are (a face or an edge turned to `e`), one of them, always the same.
    fn support(self, e: Vector3<f64>) -> Vector3<f64> {
        let sign = |x: f64| if x < 0.0 { -1.0 } else { 1.0 };
        match self {
            Convex::Sphere { radius } => e * radius,
            Convex::Ellipsoid { radii } => {
                // The ellipsoid is A times the unit ball (A = diag(radii)): the point is A² e / |A e|.
                let a = Vector3::from(radii);
                let ae = a.component_mul(&e);
                a.component_mul(&ae) / ae.norm()
            }
            Convex::Box { half } => Vector3::new(sign(e.x) * half[0], sign(e.y) * half[1], sign(e.z) * half[2]),
            Convex::Cylinder { radius, half_length } => {
                let radial = Vector3::new(e.x, e.y, 0.0);
                let norm = radial.norm();
                let rim = if norm > 0.0 { radial * (radius / norm) } else { Vector3::zeros() };
                rim + Vector3::z() * (sign(e.z) * half_length)
            }
            Convex::Capsule { radius, half_length } => e * radius + Vector3::z() * (sign(e.z) * half_length),
        }
    }

    /// The radius of its curved outline that sets how many directions trace it.
    fn roundness(self) -> f64 {
        match self {
            Convex::Sphere { radius } | Convex::Cylinder { radius, .. } | Convex::Capsule { radius, .. } => radius,
            Convex::Ellipsoid { radii } => radii.into_iter().fold(0.0, f64::max),
            Convex::Box { .. } => 0.0,
        }
    }
}

/// Directions that trace a round outline of `radius` pixels within a quarter pixel: `n` such that
/// a chord between neighbouring support points, `2π / n` apart, sags at most 0.25 px; a multiple
/// of four (the view's axes among them), from 8 to 96.
fn directions(radius: f64) -> usize {
    let cos = (1.0 - 0.25 / radius).max(-1.0);
    let n = (PI / cos.acos()).ceil();
    let n = if n.is_finite() { n.clamp(8.0, 96.0) as usize } else { 96 };
    n.div_ceil(4) * 4
}

fn array(v: &Vector3<f64>) -> [f64; 3] {
    [v.x, v.y, v.z]
}

impl Solid {
    /// The solid's point farthest along the unit direction `e` of the root frame (a primitive's).
    fn support(pose: &Isometry3<f64>, shape: Convex, e: Vector3<f64>) -> [f64; 3] {
        array(&(pose * Point3::from(shape.support(pose.rotation.inverse() * e))).coords)
    }

    /// Its smallest and largest coordinates in the root frame.
    pub fn bounds(&self) -> [[f64; 3]; 2] {
        match &self.form {
            Form::Convex { pose, shape } => {
                let unit = |k: usize, s: f64| Vector3::from_fn(|i, _| if i == k { s } else { 0.0 });
                let lo = std::array::from_fn(|k| Self::support(pose, *shape, unit(k, -1.0))[k]);
                let hi = std::array::from_fn(|k| Self::support(pose, *shape, unit(k, 1.0))[k]);
                [lo, hi]
            }
            Form::Mesh { vertices, triangles } => {
                let mut bounds = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
                for &i in triangles.iter().flatten() {
                    for (k, x) in vertices[i as usize].into_iter().enumerate() {
                        bounds[0][k] = bounds[0][k].min(x);
                        bounds[1][k] = bounds[1][k].max(x);
                    }
                }
                bounds
            }
        }
    }

    /// A primitive placed at `pose`: points of its surface whose projections' convex hull is its
    /// outline in the view whose screen axes are the root frame's coordinates `u` and `v`, drawn
    /// at `scale` pixels a metre.
    pub fn outline_points(pose: &Isometry3<f64>, shape: Convex, u: usize, v: usize, scale: f64) -> Vec<[f64; 3]> {
        if let Convex::Box { half } = shape {
            return (0..8)
                .map(|k| {
                    let corner = Vector3::from_fn(|i, _| if k >> i & 1 == 1 { half[i] } else { -half[i] });
                    array(&(pose * Point3::from(corner)).coords)
                })
                .collect();
        }
        let n = directions(shape.roundness() * scale);
        (0..n)
            .map(|k| {
                let angle = 2.0 * PI * k as f64 / n as f64;
                let mut e = Vector3::zeros();
                e[u] = angle.cos();
                e[v] = angle.sin();
                Self::support(pose, shape, e)
            })
            .collect()
    }
}

/// Every `<collision>` element of `tree` placed at the link poses `poses` (the tree's link order),
/// links in tree order, each link's elements in description order; meshes only where `meshes`
/// and their triangles were read (the others are counted in the second value).
pub fn solids(tree: &KinematicTree, poses: &[Isometry3<f64>], meshes: bool) -> (Vec<Solid>, usize) {
    let mut out = Vec::new();
    let mut left_out = 0;
    for (link, pose) in tree.links().iter().zip(poses) {
        for (element, collision) in link.collisions.iter().enumerate() {
            let placed = pose * kinematics::runtime::fixed_isometry(&collision.origin);
            let form = match (&collision.shape, Convex::of(&collision.shape)) {
                (_, Some(shape)) => Form::Convex { pose: placed, shape },
                (Shape::Mesh { loaded: Some(mesh), scale: s, .. }, None) if meshes => Form::Mesh {
                    vertices: mesh
                        .vertices()
                        .iter()
                        .map(|v| array(&(placed * Point3::new(v[0] * s[0], v[1] * s[1], v[2] * s[2])).coords))
                        .collect(),
                    triangles: mesh.triangles().to_vec(),
                },
                _ => {
                    left_out += 1;
                    continue;
                }
            };
            out.push(Solid { link: link.name.clone(), element, shape: collision.shape.name(), form });
        }
    }
    (out, left_out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn support_points_lie_on_the_surface_farthest_along_the_direction() {
        let e = Vector3::new(0.3, -0.5, 0.8).normalize();
        let p = Convex::Ellipsoid { radii: [0.1, 0.2, 0.3] }.support(e);
        let on = (p.x / 0.1).powi(2) + (p.y / 0.2).powi(2) + (p.z / 0.3).powi(2);
        assert!((on - 1.0).abs() < 1e-12, "{on}");
        // The normal there, (x/a², y/b², z/c²), is parallel to e.
        let normal = Vector3::new(p.x / 0.01, p.y / 0.04, p.z / 0.09).normalize();
        assert!((normal - e).norm() < 1e-12);
        let p = Convex::Cylinder { radius: 0.1, half_length: 0.2 }.support(e);
        assert!(((p.x * p.x + p.y * p.y).sqrt() - 0.1).abs() < 1e-15 && p.z == 0.2);
        let p = Convex::Capsule { radius: 0.1, half_length: 0.2 }.support(-e);
        assert!(((p - Vector3::new(0.0, 0.0, -0.2)).norm() - 0.1).abs() < 1e-15);
        assert_eq!(Convex::Box { half: [1.0, 2.0, 3.0] }.support(e), Vector3::new(1.0, -2.0, 3.0));
    }

    #[test]
    fn round_outlines_get_more_directions_the_larger_they_are() {
        assert_eq!(directions(0.0), 8);
        assert_eq!(directions(1.0), 8);
        let n = directions(100.0);
        assert!(n.is_multiple_of(4) && 100.0 * (1.0 - (PI / n as f64).cos()) <= 0.25, "{n}");
        assert_eq!(directions(1e9), 96);
    }
}
