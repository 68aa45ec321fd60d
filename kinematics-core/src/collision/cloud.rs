//! Point clouds as obstacles (with the `point-cloud` feature, which `std` of the facade turns on):
//! points with one radius, in kiddo's k-d tree, built once per scene and asked by every check.

use kiddo::{ImmutableKdTree, SquaredEuclidean};

use super::obstacles::{ObstacleError, SphereQuery, Vec3};

/// Points, each a ball of `radius` (the sensor's resolution, or zero), as obstacles: built once
/// (a k-d tree, kiddo's `ImmutableKdTree`), then given to an environment with
/// [`Environment::with_query`](super::Environment::with_query). A sphere touches the cloud when
/// its nearest point is within the two radii.
///
/// ```
/// use kinematics_core::collision::{Environment, PointCloud};
/// let points = [[1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.3, 0.3, 3.0]];
/// let cloud = PointCloud::new(&points, 0.01)?;
/// let env = Environment::empty().with_query(&cloud);
/// assert!(env.hits([0.9, 0.0, 0.0], 0.09) && !env.hits([0.9, 0.0, 0.0], 0.08));
/// assert_eq!(env.len(), 3);
/// # Ok::<(), kinematics_core::collision::ObstacleError>(())
/// ```
pub struct PointCloud {
    tree: Option<ImmutableKdTree<f64, 3>>,
    radius: f64,
    len: usize,
}

impl core::fmt::Debug for PointCloud {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PointCloud").field("points", &self.len).field("radius", &self.radius).finish()
    }
}

impl PointCloud {
    /// The cloud of `points`, each of `radius` (zero or more). A point or a radius with a NaN or
    /// an infinity, and a negative radius, are errors (such a point would never collide); so is a
    /// cloud of more points than the index can number (2^32).
    pub fn new(points: &[Vec3], radius: f64) -> Result<Self, ObstacleError> {
        if !radius.is_finite() {
            return Err(ObstacleError::NonFinite { kind: "point cloud radius", index: 0 });
        }
        if radius < 0.0 {
            return Err(ObstacleError::BadSize { kind: "point cloud radius", index: 0 });
        }
        if let Some(index) = points.iter().position(|p| !p.iter().all(|x| x.is_finite())) {
            return Err(ObstacleError::NonFinite { kind: "point", index });
        }
        let tree = if points.is_empty() {
            None
        } else {
            let tree = ImmutableKdTree::new_from_slice(points)
                .map_err(|_| ObstacleError::TooMany { kind: "point", count: points.len() })?;
            Some(tree)
        };
        Ok(PointCloud { tree, radius, len: points.len() })
    }

    /// Each point's radius.
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The squared distance from `center` to the nearest point (infinite for an empty cloud).
    pub fn nearest_squared(&self, center: Vec3) -> f64 {
        self.tree
            .as_ref()
            .map_or(f64::INFINITY, |tree| tree.query(&center).nearest_one::<SquaredEuclidean<f64>>().execute().distance)
    }
}

impl SphereQuery for PointCloud {
    fn touches(&self, center: Vec3, radius: f64) -> bool {
        let reach = radius + self.radius;
        // Not above: a NaN distance counts as touching.
        self.nearest_squared(center).partial_cmp(&(reach * reach)) != Some(core::cmp::Ordering::Greater)
    }

    fn len(&self) -> usize {
        self.len
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::vec::Vec;

    /// A deterministic stream in [-1, 1) (splitmix64).
    fn stream(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            #[allow(clippy::cast_precision_loss)]
            let unit = ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64;
            2.0 * unit - 1.0
        }
    }

    #[test]
    fn the_tree_answers_as_every_point_asked_in_turn() {
        for (count, seed) in [(1, 1), (7, 2), (100, 3), (5_000, 4)] {
            let mut next = stream(seed);
            let points: Vec<Vec3> = (0..count).map(|_| [next(), next(), next()]).collect();
            let cloud = PointCloud::new(&points, 0.02).unwrap();
            let (mut touching, mut apart) = (0, 0);
            for _ in 0..2_000 {
                let (center, radius) = ([next(), next(), next()], 0.01 + 0.2 * next().abs());
                let reach = radius + 0.02;
                let brute = points.iter().any(|p| {
                    let d: f64 = (0..3).map(|i| (p[i] - center[i]).powi(2)).sum();
                    d <= reach * reach
                });
                assert_eq!(cloud.touches(center, radius), brute, "{count} points, {center:?} {radius}");
                if brute { touching += 1 } else { apart += 1 }
            }
            assert!(count < 100 || (touching > 100 && apart > 100), "{touching} touching, {apart} apart");
        }
    }

    #[test]
    fn bad_clouds_are_refused() {
        assert_eq!(
            PointCloud::new(&[[0.0; 3], [f64::NAN, 0.0, 0.0]], 0.1).unwrap_err(),
            ObstacleError::NonFinite { kind: "point", index: 1 }
        );
        assert!(PointCloud::new(&[[0.0; 3]], -0.1).is_err());
        assert!(PointCloud::new(&[[0.0; 3]], f64::INFINITY).is_err());
        let empty = PointCloud::new(&[], 0.0).unwrap();
        assert!(!empty.touches([0.0; 3], 10.0) && empty.is_empty());
        // A point of radius zero still collides with a sphere around it.
        assert!(PointCloud::new(&[[0.0; 3]], 0.0).unwrap().touches([0.05, 0.0, 0.0], 0.05));
    }
}
