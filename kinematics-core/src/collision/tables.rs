//! The checks a compiled robot runs on its sphere centres: against an [`Environment`]'s obstacles
//! and against itself, on any [`CheckLanes`] type, each configuration (lane) with its own verdict.
//!
//! Each link's bounding sphere is tested first and its spheres only where that hits, then only
//! on the lanes it hits; a lane found colliding is not tested again, and a check ends as soon as
//! every lane is colliding. Every obstacle is tested until one is hit, so the order of the
//! obstacles does not change an answer.

use super::obstacles::{Environment, Obstacle};
use super::verdicts::{CheckLanes, Flags, LaneMask, non_finite};

/// A compiled robot's collision tables, as its generated code holds them: each link with spheres
/// (its range of spheres and its bounding sphere's radius), the spheres' radii, and the link pairs
/// its self-collision check tests.
///
/// The centres a check takes are the spheres' (in the order of `radii`) followed by the links'
/// bounding spheres' (in the order of `links`), as the generated `generic_collision_centers`
/// returns them.
///
/// ```
/// use kinematics_core::collision::{CollisionTables, Environment, SphereObstacle};
/// // Two links of one sphere each, 1 m apart, bounding spheres equal to their spheres.
/// let tables = CollisionTables { links: &[(0, 1, 0.1), (1, 2, 0.1)], radii: &[0.1, 0.1], pairs: &[(0, 1)] };
/// let centers = [[0.0; 3], [1.0, 0.0, 0.0], [0.0; 3], [1.0, 0.0, 0.0]];
/// let ball = [SphereObstacle { center: [1.0, 0.3, 0.0], radius: 0.25 }];
/// let env = Environment::new(&ball, &[], &[], &[])?;
/// assert!(tables.collides(&[0.0_f64], &centers, &env).any());
/// assert!(!tables.self_collides(&[0.0_f64], &centers).any());
/// # Ok::<(), kinematics_core::collision::ObstacleError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct CollisionTables<'a> {
    /// Per link with spheres: its spheres `start..end` in the sphere order, and its bounding
    /// sphere's radius (its centre follows the spheres' in the centres array, in link order).
    pub links: &'a [(usize, usize, f64)],
    /// Each sphere's radius.
    pub radii: &'a [f64],
    /// The pairs of links (indices into `links`) the self-collision check tests.
    pub pairs: &'a [(usize, usize)],
}

impl CollisionTables<'_> {
    /// The lanes where the robot at `q`, with these centres, touches an obstacle of `env` or
    /// itself: the obstacles first, then the pairs, each only on the lanes still free. A lane
    /// whose `q` is not finite is colliding.
    #[inline(always)]
    pub fn collides<L: CheckLanes, const N: usize>(
        &self,
        q: &[L; N],
        centers: &[[L; 3]],
        env: &Environment<'_>,
    ) -> LaneMask {
        let hit = self.obstacle_hits(centers, env, non_finite(q));
        if hit.all() {
            return hit.bits();
        }
        self.self_hits(centers, hit).bits()
    }

    /// The lanes where two links of a checked pair of the robot at `q` touch. A lane whose `q` is
    /// not finite is colliding.
    #[inline(always)]
    pub fn self_collides<L: CheckLanes, const N: usize>(&self, q: &[L; N], centers: &[[L; 3]]) -> LaneMask {
        self.self_hits(centers, non_finite(q)).bits()
    }

    /// `hit` and the lanes where a sphere touches an obstacle.
    #[inline(always)]
    fn obstacle_hits<L: CheckLanes>(&self, centers: &[[L; 3]], env: &Environment<'_>, mut hit: L::Flags) -> L::Flags {
        if hit.all() || env.is_empty() {
            return hit;
        }
        let bounds = &centers[self.radii.len()..];
        for (&(start, end, radius), bound) in self.links.iter().zip(bounds) {
            let link = Link {
                bound,
                radius: L::from_f64(radius),
                centers: &centers[start..end],
                radii: &self.radii[start..end],
            };
            hit = link.against(env.spheres, hit);
            hit = link.against(env.capsules, hit);
            hit = link.against(env.cylinders, hit);
            hit = link.against(env.boxes, hit);
            if hit.all() {
                return hit;
            }
        }
        hit
    }

    /// `hit` and the lanes where two links of a checked pair touch: their bounding spheres first,
    /// then each sphere of the first against the second's bounding sphere, then sphere against
    /// sphere.
    #[inline(always)]
    fn self_hits<L: CheckLanes>(&self, centers: &[[L; 3]], mut hit: L::Flags) -> L::Flags {
        let bounds = &centers[self.radii.len()..];
        for &(i, j) in self.pairs {
            if hit.all() {
                return hit;
            }
            let ((sa, ea, ra), (sb, eb, rb)) = (self.links[i], self.links[j]);
            let (ra, rb) = (L::from_f64(ra), L::from_f64(rb));
            let near = touch(&bounds[i], ra, &bounds[j], rb).and_not(hit);
            if !near.any() {
                continue;
            }
            'spheres: for a in sa..ea {
                let r = L::from_f64(self.radii[a]);
                let close = touch(&centers[a], r, &bounds[j], rb) & near;
                if !close.any() {
                    continue;
                }
                for b in sb..eb {
                    hit = hit | (touch(&centers[a], r, &centers[b], L::from_f64(self.radii[b])) & close);
                    if !near.and_not(hit).any() {
                        break 'spheres;
                    }
                }
            }
        }
        hit
    }
}

/// One link's part of a check: its bounding sphere and its spheres.
struct Link<'c, L> {
    bound: &'c [L; 3],
    radius: L,
    centers: &'c [[L; 3]],
    radii: &'c [f64],
}

impl<L: CheckLanes> Link<'_, L> {
    /// `hit` and the lanes where one of the link's spheres touches one of `obstacles`: per
    /// obstacle, the bounding sphere first, then the spheres on the lanes it hits until each of
    /// them is decided.
    #[inline(always)]
    fn against<O: Obstacle>(&self, obstacles: &[O], mut hit: L::Flags) -> L::Flags {
        for obstacle in obstacles {
            let near = obstacle.hits(self.bound, self.radius).and_not(hit);
            if !near.any() {
                continue;
            }
            for (center, &radius) in self.centers.iter().zip(self.radii) {
                hit = hit | (obstacle.hits(center, L::from_f64(radius)) & near);
                if !near.and_not(hit).any() {
                    break;
                }
            }
        }
        hit
    }
}

/// The lanes where two spheres touch (or a distance is NaN).
#[inline(always)]
fn touch<L: CheckLanes>(a: &[L; 3], ra: L, b: &[L; 3], rb: L) -> L::Flags {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let reach = ra + rb;
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).not_above(reach * reach)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::SphereObstacle;
    use crate::{F64x4, Lanes, Real};

    const TABLES: CollisionTables<'static> =
        CollisionTables { links: &[(0, 1, 0.1), (1, 2, 0.1)], radii: &[0.1, 0.1], pairs: &[(0, 1)] };

    #[test]
    fn a_configuration_that_is_not_finite_is_never_free() {
        let far = [[0.0; 3], [5.0, 0.0, 0.0], [0.0; 3], [5.0, 0.0, 0.0]];
        assert!(!TABLES.self_collides(&[0.0_f64], &far).any());
        assert!(TABLES.self_collides(&[f64::NAN], &far).any());
        assert!(TABLES.collides(&[f64::INFINITY], &far, &Environment::empty()).any());
        assert!(!TABLES.collides(&[0.0], &far, &Environment::empty()).any());
    }

    #[test]
    fn each_lane_has_its_own_verdict() {
        // Lane k puts link 1 at x = offset + 0.1 k: within 0.2 of link 0 (itself) in lanes 0 to 2
        // of the first offset, within 0.2 of the ball at x = 0.7 in lanes 1 to 3 of the second.
        let ball = [SphereObstacle { center: [0.7, 0.0, 0.0], radius: 0.1 }];
        let env = Environment::new(&ball, &[], &[], &[]).unwrap();
        for (offset, expected) in [(0.0, 0b0111), (0.4, 0b1110)] {
            let x = F64x4::from_fn(|k| offset + 0.1 * k as f64);
            let zero = F64x4::from_f64(0.0);
            let link1 = [x, zero, zero];
            let centers = [[zero; 3], link1, [zero; 3], link1];
            let q = [zero];
            let collides = TABLES.collides(&q, &centers, &env);
            let itself = TABLES.self_collides(&q, &centers);
            for k in 0..4 {
                let at = [offset + 0.1 * k as f64, 0.0, 0.0];
                let scalar = [[0.0; 3], at, [0.0; 3], at];
                assert_eq!(itself.lane(k), TABLES.self_collides(&[0.0], &scalar).any(), "lane {k}");
                assert_eq!(collides.lane(k), TABLES.collides(&[0.0], &scalar, &env).any(), "lane {k}");
            }
            assert_eq!(collides.bits(), expected, "offset {offset}");
        }
    }
}
