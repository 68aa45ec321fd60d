//! The checks a compiled robot runs on its sphere centres: against an [`Environment`]'s obstacles
//! and against itself, on any [`CheckLanes`] type, each configuration (lane) with its own verdict.
//!
//! Against obstacles, each link's bounding sphere is tested first against the box holding every
//! obstacle (the environment's extent), then against each obstacle where that touches, and the
//! link's spheres only where the bound hits. Against the robot, each pair's bounding spheres come
//! first, then their groups' (a few neighbouring spheres each), and a group's spheres (placed by
//! the link's pose only when tested) only where that hits, then only on the lanes it hits. A lane
//! found colliding is not tested again, and a check ends as soon as every lane is colliding. Every obstacle is tested until one is hit, so the order of the
//! obstacles does not change an answer.
//!
//! `CollisionTables` holds what a compiled robot's `collides` and `self_collides` run on its links'
//! poses. The self pairs are tested group by group; each lane is decided once.

use super::grid::{GridVerdicts, PairGrid};
use super::held::HeldObject;
use super::obstacles::{Environment, Obstacle, Prepared, SphereQuery, Vec3, Visit, query_lanes};
use super::verdicts::{AnyLane, CheckLanes, EveryLane, Flags, LaneMask, Until, non_finite_entries};
use crate::pose::Pose;
use core::marker::PhantomData;

/// A compiled robot's collision tables, as its generated code holds them: each link with spheres
/// (its range of groups, its bounding sphere's centre in the link's frame and radius), each group
/// of a few neighbouring spheres (its range of spheres, its bounding sphere), each sphere's centre
/// in its link's frame and radius, and the link pairs its self-collision check tests.
///
/// A check finds the centres of the robot's spheres and bounding spheres in one of two ways.
/// [`CollisionTables::collides`] and [`CollisionTables::self_collides`] take the poses of the
/// links with spheres (in the order of `links`) and place a centre (`R p + t`) only when it is
/// tested: a link's spheres only where its bounding sphere hits. This is how a robot loaded at
/// run time is checked. [`CollisionTables::collides_points`] and
/// [`CollisionTables::self_collides_points`] take every centre computed ahead, as the generated
/// `generic_collision_points` returns them: the compiler derives each centre symbolically with
/// the link poses' simplifications, which costs less than placing the ones the tests reach,
/// since a pair's tests place the same group and sphere centres again and again.
///
/// ```
/// use kinematics_core::collision::{CollisionTables, Environment, SphereObstacle};
/// use kinematics_core::Pose;
/// // Two links of one sphere each at their origins, bounding spheres equal to their spheres.
/// let tables = CollisionTables {
///     links: &[(0, 1, [0.0; 3], 0.1), (1, 2, [0.0; 3], 0.1)],
///     groups: &[(0, 1, [0.0; 3], 0.1), (1, 2, [0.0; 3], 0.1)],
///     centers: &[[0.0; 3], [0.0; 3]],
///     radii: &[0.1, 0.1],
///     pairs: &[(0, 1)],
///     fixed: &[],
///     grids: &[],
/// };
/// let poses = [Pose::from_rpy([0.0; 3], [0.0; 3]), Pose::from_rpy([0.0; 3], [1.0, 0.0, 0.0])];
/// let ball = [SphereObstacle { center: [1.0, 0.3, 0.0], radius: 0.25 }];
/// let env = Environment::new(&ball, &[], &[], &[])?;
/// assert!(tables.collides(&[0.0_f64], &poses, &env, None).any());
/// assert!(!tables.self_collides(&[0.0_f64], &poses).any());
/// # Ok::<(), kinematics_core::collision::ObstacleError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct CollisionTables<'a> {
    /// Per link with spheres: its groups `start..end` in `groups`, and its bounding sphere's
    /// centre (in the link's frame) and radius.
    pub links: &'a [(usize, usize, Vec3, f64)],
    /// Per group: its spheres `start..end` in `centers` and `radii`, and its bounding sphere's
    /// centre (in its link's frame) and radius.
    pub groups: &'a [(usize, usize, Vec3, f64)],
    /// Each sphere's centre in its link's frame.
    pub centers: &'a [Vec3],
    /// Each sphere's radius.
    pub radii: &'a [f64],
    /// The pairs of links (indices into `links`) the self-collision check tests.
    pub pairs: &'a [(usize, usize)],
    /// The sphere pairs of `pairs` (indices into `centers`, the first first; sorted) that no
    /// joint brings nearer or farther: held a positive distance apart for good, they never
    /// collide, and the distances leave them out (their constant would cap the clearance, with a
    /// zero gradient). The checks test them with the rest.
    pub fixed: &'a [(usize, usize)],
    /// The grids deciding some of `pairs` by the values of the one or two joints that move
    /// them (at most [`super::MAX_GRIDS`]): the checks test a grid's pairs only on the
    /// configurations whose cells leave them to the tests. The distances do not read them.
    pub grids: &'a [PairGrid<'a>],
}

impl CollisionTables<'_> {
    /// The lanes where the robot at `q`, its links with spheres at `poses`, touches an obstacle
    /// of `env` or itself, or where the object it holds (`held`, if any) touches an obstacle or
    /// a link it is tested against: the robot's obstacles first, then the held object's, then
    /// the pairs, each only on the lanes still free. A lane whose `q` is not finite is colliding.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn collides<L: CheckLanes>(
        &self,
        q: &[L],
        poses: &[Pose<L>],
        env: &Environment<'_>,
        held: Option<HeldObject<'_>>,
    ) -> LaneMask {
        self.world::<L, EveryLane>(q, poses, env, held).bits()
    }

    /// Whether some lane of [`CollisionTables::collides`] collides: one verdict for the pack,
    /// the check ending at the first hit on any lane (the lanes then left undecided).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn collides_any<L: CheckLanes>(
        &self,
        q: &[L],
        poses: &[Pose<L>],
        env: &Environment<'_>,
        held: Option<HeldObject<'_>>,
    ) -> bool {
        self.world::<L, AnyLane>(q, poses, env, held).any()
    }

    /// [`CollisionTables::collides`] on the robot's points as the generated
    /// `generic_collision_points` returns them (every sphere's centre in the checks' order, then
    /// each group's bounding sphere's, then each link's), with the links' poses only for a held
    /// object, whose own centres are placed by them.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn collides_points<L: CheckLanes>(
        &self,
        q: &[L],
        points: &[[L; 3]],
        env: &Environment<'_>,
        held: Option<(HeldObject<'_>, &[Pose<L>])>,
    ) -> LaneMask {
        self.world_points::<L, EveryLane>(q, points, env, held).bits()
    }

    /// [`CollisionTables::collides_any`] on the robot's points (see
    /// [`CollisionTables::collides_points`]).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn collides_points_any<L: CheckLanes>(
        &self,
        q: &[L],
        points: &[[L; 3]],
        env: &Environment<'_>,
        held: Option<(HeldObject<'_>, &[Pose<L>])>,
    ) -> bool {
        self.world_points::<L, AnyLane>(q, points, env, held).any()
    }

    /// [`CollisionTables::self_collides`] on the robot's points (see
    /// [`CollisionTables::collides_points`]).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn self_collides_points<L: CheckLanes>(&self, q: &[L], points: &[[L; 3]]) -> LaneMask {
        let at = Placed::new(self, fence(points));
        self.itself::<L, _, EveryLane>(q, &at).bits()
    }

    /// [`CollisionTables::self_collides_any`] on the robot's points (see
    /// [`CollisionTables::collides_points`]).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn self_collides_points_any<L: CheckLanes>(&self, q: &[L], points: &[[L; 3]]) -> bool {
        let at = Placed::new(self, fence(points));
        self.itself::<L, _, AnyLane>(q, &at).any()
    }

    /// The lanes where two links of a checked pair of the robot at `q` touch. A lane whose `q` is
    /// not finite is colliding.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn self_collides<L: CheckLanes>(&self, q: &[L], poses: &[Pose<L>]) -> LaneMask {
        let at = Placing { tables: self, poses: fence(poses) };
        self.itself::<L, _, EveryLane>(q, &at).bits()
    }

    /// Whether some lane of [`CollisionTables::self_collides`] collides, the check ending at the
    /// first hit on any lane.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn self_collides_any<L: CheckLanes>(&self, q: &[L], poses: &[Pose<L>]) -> bool {
        let at = Placing { tables: self, poses: fence(poses) };
        self.itself::<L, _, AnyLane>(q, &at).any()
    }

    /// The check against obstacles and itself on centres placed from `poses`, until `G` says.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn world<L: CheckLanes, G: Until>(
        &self,
        q: &[L],
        poses: &[Pose<L>],
        env: &Environment<'_>,
        held: Option<HeldObject<'_>>,
    ) -> L::Flags {
        let poses = fence(poses);
        let at = Placing { tables: self, poses };
        // The grids first: a lookup per configuration, which may settle some before any test.
        let grids = GridVerdicts::of(self.grids, q);
        let mut hit =
            self.obstacle_hits::<L, _, G>(&at, env, non_finite_entries(q) | L::Flags::from_mask(grids.colliding));
        if let Some(held) = held {
            hit = held.hits::<L, G>(self, poses, env, hit);
        }
        if G::done(hit) {
            return hit;
        }
        self.self_hits::<L, _, G>(&at, hit, &grids)
    }

    /// The check against obstacles and itself on the points computed ahead, until `G` says.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn world_points<L: CheckLanes, G: Until>(
        &self,
        q: &[L],
        points: &[[L; 3]],
        env: &Environment<'_>,
        held: Option<(HeldObject<'_>, &[Pose<L>])>,
    ) -> L::Flags {
        let at = Placed::new(self, fence(points));
        let grids = GridVerdicts::of(self.grids, q);
        let mut hit =
            self.obstacle_hits::<L, _, G>(&at, env, non_finite_entries(q) | L::Flags::from_mask(grids.colliding));
        if let Some((held, poses)) = held {
            hit = held.hits::<L, G>(self, poses, env, hit);
        }
        if G::done(hit) {
            return hit;
        }
        self.self_hits::<L, _, G>(&at, hit, &grids)
    }

    /// The self check at `q` on centres from `at`, until `G` says.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn itself<L: CheckLanes, C: Centers<L>, G: Until>(&self, q: &[L], at: &C) -> L::Flags {
        let grids = GridVerdicts::of(self.grids, q);
        self.self_hits::<L, C, G>(at, non_finite_entries(q) | L::Flags::from_mask(grids.colliding), &grids)
    }

    /// `hit` and the lanes where a sphere touches an obstacle: a few links at a time (their
    /// bounding spheres placed once), each link's bounding sphere first tested against the box
    /// holding every obstacle (and the link left out where no lane still free touches it), then
    /// each obstacle prepared once in lanes and tested against each link's bounding sphere, then
    /// against its spheres only where that hits.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn obstacle_hits<L: CheckLanes, C: Centers<L>, G: Until>(
        &self,
        at: &C,
        env: &Environment<'_>,
        mut hit: L::Flags,
    ) -> L::Flags {
        if G::done(hit) || env.is_empty() {
            return hit;
        }
        let extent = env.extent.map(|extent| extent.prepare::<L>());
        let n = self.links.len();
        // The chunk's placed bounds; the links the obstacles are tested against are listed
        // below by their positions in it, as bytes. A second array of placed bounds, zeroed on
        // every check as this one is, was a tenth of the Panda's check in `F32x8` lanes (a
        // `memset` of kilobytes, by `perf`).
        let mut bounds = [([L::from_f64(0.0); 3], L::from_f64(0.0)); CHUNK];
        for first in (0..n).step_by(CHUNK) {
            let count = CHUNK.min(n - first);
            for (slot, k) in bounds.iter_mut().zip(first..first + count) {
                *slot = (at.link(k), L::from_f64(self.links[k].3));
            }
            if let Some(extent) = &extent {
                let mut near = [0u8; CHUNK];
                let mut listed = 0;
                for (i, (center, radius)) in bounds[..count].iter().enumerate() {
                    if extent.hits(center, *radius).and_not(hit).any() {
                        near[listed] = i as u8;
                        listed += 1;
                    }
                }
                let chunk =
                    Chunk { tables: self, at, first, bounds: &bounds, list: &near[..listed], until: PhantomData::<G> };
                hit = chunk.against(env.spheres, hit);
                hit = chunk.against(env.capsules, hit);
                hit = chunk.against(env.cylinders, hit);
                hit = chunk.against(env.boxes, hit);
            }
            if let Some(query) = env.query {
                let mut every = [0u8; CHUNK];
                for (i, slot) in (0..).zip(&mut every) {
                    *slot = i;
                }
                let chunk =
                    Chunk { tables: self, at, first, bounds: &bounds, list: &every[..count], until: PhantomData::<G> };
                hit = chunk.against_query(query, hit);
            }
            if G::done(hit) {
                return hit;
            }
        }
        hit
    }

    /// `hit` and the lanes where two links of a checked pair touch, on the lanes `grids` leave
    /// to the tests: their bounding spheres first, then each group of the first against the
    /// second's bounding sphere, then group against group, then the spheres of two touching
    /// groups: each of the first's against the second group's bounding sphere, and where that
    /// touches, against each of the second's.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn self_hits<L: CheckLanes, C: Centers<L>, G: Until>(
        &self,
        at: &C,
        mut hit: L::Flags,
        grids: &GridVerdicts,
    ) -> L::Flags {
        // Filled anew for each pair of groups; made once (zeroing it per pair was measured).
        let mut placed = [([L::from_f64(0.0); 3], L::from_f64(0.0)); PLACED];
        // The compiler's pairs come sorted by their first link: its bound is placed once for
        // its run of pairs (any order gives the same answers; measured: the Panda's self check
        // in `F32x8` lanes 1.08x faster). Placing every link's bound once up front, in an
        // array, was measured slower (1.6x in `F32x8` lanes, 1.05x in `F32x16`).
        let (mut last, mut bound_i) = (usize::MAX, [L::from_f64(0.0); 3]);
        for (pair, &(i, j)) in self.pairs.iter().enumerate() {
            if G::done(hit) {
                return hit;
            }
            let to_test = L::Flags::from_mask(grids.tested(self.grids, pair)).and_not(hit);
            if !to_test.any() {
                continue;
            }
            let ((ga, ea, ..), (gb, eb, ..)) = (self.links[i], self.links[j]);
            if i != last {
                (last, bound_i) = (i, at.link(i));
            }
            let bound_j = at.link(j);
            let (ra, rb) = (L::from_f64(self.links[i].3), L::from_f64(self.links[j].3));
            let near = touch(&bound_i, ra, &bound_j, rb) & to_test;
            if !near.any() {
                continue;
            }
            'pair: for a in ga..ea {
                let (a0, a1, _, ra) = self.groups[a];
                let (ca, ra) = (at.group(i, a), L::from_f64(ra));
                let close_a = touch(&ca, ra, &bound_j, rb) & near;
                if !close_a.any() {
                    continue;
                }
                for b in gb..eb {
                    let (b0, b1, _, rg) = self.groups[b];
                    let (cb, rg) = (at.group(j, b), L::from_f64(rg));
                    let close = touch(&ca, ra, &cb, rg) & close_a;
                    if !close.any() {
                        continue;
                    }
                    // The second group's spheres, a chunk at a time (a group holds a few),
                    // placed together when the first of the first group's spheres to touch the
                    // second group's bound does, and not at all when none does (measured: the
                    // Panda's check in `F32x8` lanes 1.04x faster than placing them up front).
                    // Testing each of them against the first group's bound was measured slower
                    // (a branch per sphere no predictor guesses).
                    for first in (b0..b1).step_by(PLACED) {
                        let mut count = 0;
                        for s in a0..a1 {
                            let (center, r) = (at.sphere(i, s), L::from_f64(self.radii[s]));
                            let close_s = touch(&center, r, &cb, rg) & close;
                            if !close_s.any() {
                                continue;
                            }
                            if count == 0 {
                                for t in first..b1.min(first + PLACED) {
                                    placed[count] = (at.sphere(j, t), L::from_f64(self.radii[t]));
                                    count += 1;
                                }
                            }
                            for (other, r_other) in &placed[..count] {
                                hit = hit | (touch(&center, r, other, *r_other) & close_s);
                                if G::settled(near, hit) {
                                    break 'pair;
                                }
                            }
                        }
                    }
                }
            }
        }
        hit
    }
}

/// How many links' bounding spheres the obstacle check places at a time (each listed by its
/// position, a byte).
const CHUNK: usize = 16;
const _: () = assert!(CHUNK <= 256, "a chunk's positions are bytes");

/// How many spheres of a group the self check places at a time: the compiler's groups hold at
/// most four (a larger group is taken four at a time).
const PLACED: usize = 4;

/// `poses`, after which the compiler computes nothing of them ahead (a `black_box`): inlined
/// together, the straight-line poses and the work on them made one block too large for LLVM's
/// vectorizer to schedule whole, and parts of it ran in 4-lane pieces (measured: the Panda's
/// `collides` in `F32x16` lanes 1.15x slower without it).
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn fence<T: ?Sized>(poses: &T) -> &T {
    core::hint::black_box(poses)
}

/// Consecutive links of a check from `first`, their bounding spheres placed, and which of them
/// (positions in `bounds`) the tests take.
#[derive(Clone, Copy)]
struct Chunk<'c, 't, L, C, G> {
    tables: &'c CollisionTables<'t>,
    at: &'c C,
    first: usize,
    bounds: &'c [([L; 3], L)],
    list: &'c [u8],
    until: PhantomData<G>,
}

impl<L: CheckLanes, C: Centers<L>, G: Until> Chunk<'_, '_, L, C, G> {
    /// `hit` and the lanes where one of the links' spheres touches one of `obstacles`: per
    /// obstacle (prepared once), each link's bounding sphere first, then its spheres (placed as
    /// they are tested) on the lanes it hits until each of them is decided.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn against<O: Obstacle>(&self, obstacles: &[O], hit: L::Flags) -> L::Flags {
        let mut visit = Against { chunk: self, hit };
        for obstacle in obstacles {
            obstacle.prepare(&mut visit);
            if G::done(visit.hit) {
                break;
            }
        }
        visit.hit
    }
}

impl<L: CheckLanes, C: Centers<L>, G: Until> Chunk<'_, '_, L, C, G> {
    /// `hit` and the lanes where one of the links' spheres touches an obstacle of `query`: each
    /// link's bounding sphere asked first, then its spheres on the lanes it touches, one lane at
    /// a time.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn against_query(&self, query: &dyn SphereQuery, mut hit: L::Flags) -> L::Flags {
        let Chunk { tables, at, first, bounds, list, .. } = *self;
        for &i in list {
            let (k, (bound, radius)) = (first + usize::from(i), bounds[usize::from(i)]);
            let near = query_lanes(query, &bound, radius, !hit.bits());
            if !near.any() {
                continue;
            }
            let (g0, g1, ..) = tables.links[k];
            let (start, end) = (tables.groups[g0].0, tables.groups[g1 - 1].1);
            for s in start..end {
                let center = at.sphere(k, s);
                let asked = near.and_not(hit).bits();
                hit = hit | query_lanes(query, &center, L::from_f64(tables.radii[s]), asked);
                if G::settled(near, hit) {
                    break;
                }
            }
            if G::done(hit) {
                break;
            }
        }
        hit
    }
}

/// A chunk of links tested against one prepared obstacle after another.
struct Against<'a, 'c, 't, L: CheckLanes, C, G> {
    chunk: &'a Chunk<'c, 't, L, C, G>,
    hit: L::Flags,
}

impl<L: CheckLanes, C: Centers<L>, G: Until> Visit<L> for Against<'_, '_, '_, L, C, G> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn visit<P: Prepared<L>>(&mut self, prepared: &P) {
        let Chunk { tables, at, first, bounds, list, .. } = *self.chunk;
        let mut hit = self.hit;
        for &i in list {
            let (k, (bound, radius)) = (first + usize::from(i), &bounds[usize::from(i)]);
            let near = prepared.hits(bound, *radius).and_not(hit);
            if !near.any() {
                continue;
            }
            // The link's spheres are its groups' in order: against an obstacle the groups'
            // bounds are not tested (measured slower: a link's few spheres cost about as much).
            let (g0, g1, ..) = tables.links[k];
            let (start, end) = (tables.groups[g0].0, tables.groups[g1 - 1].1);
            for s in start..end {
                let center = at.sphere(k, s);
                hit = hit | (prepared.hits(&center, L::from_f64(tables.radii[s])) & near);
                if G::settled(near, hit) {
                    break;
                }
            }
            if G::done(hit) {
                break;
            }
        }
        self.hit = hit;
    }
}

/// Where a check finds the centres in the base frame of link `k`'s bounding sphere, of its group
/// `g`'s and of its sphere `s` (`g` and `s` indices into the tables' `groups` and `centers`).
trait Centers<L> {
    fn link(&self, k: usize) -> [L; 3];
    fn group(&self, k: usize, g: usize) -> [L; 3];
    fn sphere(&self, k: usize, s: usize) -> [L; 3];
}

/// Centres placed by the links' poses (`R p + t`) when asked.
#[derive(Clone, Copy)]
struct Placing<'a, 't, L> {
    tables: &'a CollisionTables<'t>,
    poses: &'a [Pose<L>],
}

impl<L: CheckLanes> Centers<L> for Placing<'_, '_, L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn link(&self, k: usize) -> [L; 3] {
        self.poses[k].place(self.tables.links[k].2)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn group(&self, k: usize, g: usize) -> [L; 3] {
        self.poses[k].place(self.tables.groups[g].2)
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sphere(&self, k: usize, s: usize) -> [L; 3] {
        self.poses[k].place(self.tables.centers[s])
    }
}

/// Centres computed ahead, in the generated points' order: the spheres, the groups, the links.
#[derive(Clone, Copy)]
struct Placed<'a, L> {
    spheres: &'a [[L; 3]],
    groups: &'a [[L; 3]],
    links: &'a [[L; 3]],
}

impl<'a, L> Placed<'a, L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn new(tables: &CollisionTables<'_>, points: &'a [[L; 3]]) -> Self {
        let (spheres, rest) = points.split_at(tables.centers.len());
        let (groups, links) = rest.split_at(tables.groups.len());
        Placed { spheres, groups, links }
    }
}

impl<L: CheckLanes> Centers<L> for Placed<'_, L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn link(&self, k: usize) -> [L; 3] {
        self.links[k]
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn group(&self, _: usize, g: usize) -> [L; 3] {
        self.groups[g]
    }
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn sphere(&self, _: usize, s: usize) -> [L; 3] {
        self.spheres[s]
    }
}

/// The lanes where two spheres touch (or a distance is NaN).
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn touch<L: CheckLanes>(a: &[L; 3], ra: L, b: &[L; 3], rb: L) -> L::Flags {
    let d = [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let reach = ra + rb;
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).not_above(reach * reach)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::{PairGrid, SphereObstacle};
    use crate::{F64x4, Lanes, Real};

    /// Two links of one sphere each at their origins.
    const TABLES: CollisionTables<'static> = CollisionTables {
        links: &[(0, 1, [0.0; 3], 0.1), (1, 2, [0.0; 3], 0.1)],
        groups: &[(0, 1, [0.0; 3], 0.1), (1, 2, [0.0; 3], 0.1)],
        centers: &[[0.0; 3], [0.0; 3]],
        radii: &[0.1, 0.1],
        pairs: &[(0, 1)],
        fixed: &[],
        grids: &[],
    };

    /// The points `collides_points` reads, placed from `poses`: each sphere's centre, each
    /// group's bounding sphere's, each link's, as the generated `generic_collision_points` orders
    /// them.
    fn points_of<L: CheckLanes>(tables: &CollisionTables<'_>, poses: &[Pose<L>]) -> std::vec::Vec<[L; 3]> {
        let at = Placing { tables, poses };
        let link_of = |g: usize| tables.links.iter().position(|&(g0, g1, ..)| (g0..g1).contains(&g)).unwrap();
        let group_of = |s: usize| tables.groups.iter().position(|&(s0, s1, ..)| (s0..s1).contains(&s)).unwrap();
        let spheres = (0..tables.centers.len()).map(|s| at.sphere(link_of(group_of(s)), s));
        let groups = (0..tables.groups.len()).map(|g| at.group(link_of(g), g));
        spheres.chain(groups).chain((0..tables.links.len()).map(|k| at.link(k))).collect()
    }

    /// `tables.collides` on `poses`, asserted equal to `collides_points` on the points placed
    /// from them.
    fn collides<L: CheckLanes>(
        tables: &CollisionTables<'_>,
        q: &[L],
        poses: &[Pose<L>],
        env: &Environment<'_>,
    ) -> LaneMask {
        let by_poses = tables.collides(q, poses, env, None);
        let points = points_of(tables, poses);
        let by_points = tables.collides_points(q, &points, env, None);
        assert_eq!(by_points.bits(), by_poses.bits(), "collides_points against collides");
        // The shared verdicts: some lane colliding, whichever lane it is.
        assert_eq!(tables.collides_any(q, poses, env, None), by_poses.any(), "collides_any");
        assert_eq!(tables.collides_points_any(q, &points, env, None), by_poses.any(), "collides_points_any");
        by_poses
    }

    /// `tables.self_collides` on `poses`, asserted equal to `self_collides_points`.
    fn self_collides<L: CheckLanes>(tables: &CollisionTables<'_>, q: &[L], poses: &[Pose<L>]) -> LaneMask {
        let by_poses = tables.self_collides(q, poses);
        let points = points_of(tables, poses);
        let by_points = tables.self_collides_points(q, &points);
        assert_eq!(by_points.bits(), by_poses.bits(), "self_collides_points against self_collides");
        assert_eq!(tables.self_collides_any(q, poses), by_poses.any(), "self_collides_any");
        assert_eq!(tables.self_collides_points_any(q, &points), by_poses.any(), "self_collides_points_any");
        by_poses
    }

    fn at<T: Real>(x: T) -> Pose<T> {
        let (zero, one) = (T::from_f64(0.0), T::from_f64(1.0));
        Pose { rotation: [[one, zero, zero], [zero, one, zero], [zero, zero, one]], translation: [x, zero, zero] }
    }

    #[test]
    fn a_configuration_that_is_not_finite_is_never_free() {
        let far = [at(0.0), at(5.0)];
        assert!(!self_collides(&TABLES, &[0.0_f64], &far).any());
        assert!(self_collides(&TABLES, &[f64::NAN], &far).any());
        assert!(collides(&TABLES, &[f64::INFINITY], &far, &Environment::empty()).any());
        assert!(!collides(&TABLES, &[0.0], &far, &Environment::empty()).any());
    }

    /// A grid over `q[0]` from 0 to 4 in four cells (to test, free, colliding, to test) deciding
    /// the one pair: its verdict is taken where it gives one, even against the spheres (which
    /// the grid's own test in the model rules out), and the pair is tested elsewhere.
    #[test]
    fn a_grid_decides_its_pairs_where_its_cells_say() {
        let grid = PairGrid {
            dofs: [0, 0],
            lower: [0.0, 0.0],
            scale: [1.0, 0.0],
            cells: [4, 1],
            states: &[0b00_10_01_00],
            pairs: &[0],
        };
        let tables = CollisionTables { grids: &[grid], ..TABLES };
        let (touching, apart) = ([at(0.0), at(0.1)], [at(0.0), at(5.0)]);
        // Cell 0 and beyond the grid: tested.
        assert!(self_collides(&tables, &[0.5], &touching).any());
        assert!(!self_collides(&tables, &[0.5], &apart).any());
        assert!(self_collides(&tables, &[9.0], &touching).any());
        // Cell 1 free, cell 2 colliding, whatever the poses.
        assert!(!self_collides(&tables, &[1.5], &touching).any());
        assert!(self_collides(&tables, &[2.5], &apart).any());
        assert!(collides(&tables, &[2.5], &apart, &Environment::empty()).any());
        assert!(!collides(&tables, &[1.5], &touching, &Environment::empty()).any());
        // In lanes, each lane by its own cell.
        let q = [F64x4::new([0.5, 1.5, 2.5, 3.5])];
        let poses = [at(F64x4::from_f64(0.0)), at(F64x4::new([0.1, 0.1, 5.0, 5.0]))];
        assert_eq!(self_collides(&tables, &q, &poses).bits(), 0b0101);
    }

    /// Three links of a few spheres each, posed at random in eight lanes, in random environments
    /// of every kind of obstacle (turned boxes among them) near and far: each lane's verdict is
    /// each of its placed spheres asked of every obstacle in turn (no bounding sphere, no box
    /// holding the obstacles), on `f64` and `f32` lanes; both verdicts come up often.
    #[test]
    fn the_obstacle_check_in_lanes_equals_every_sphere_against_every_obstacle() {
        use crate::F32x8;
        use crate::collision::{BoxObstacle, CapsuleObstacle, CylinderObstacle};
        use crate::splitmix::SplitMix;
        let mut rng = SplitMix(0x7461_626c_6573);
        let mut uniform = |scale: f64| scale * (2.0 * rng.next() - 1.0);
        let mut counts = [0; 2];
        for round in 0..2000 {
            // Link k: three spheres within 0.15 of its origin, its bound the origin's sphere
            // reaching them all.
            let mut centers = [[0.0; 3]; 9];
            let mut radii = [0.0; 9];
            let mut links = [(0, 0, [0.0; 3], 0.0); 3];
            let mut groups = [(0, 0, [0.0; 3], 0.0); 3];
            for k in 0..3 {
                let mut reach: f64 = 0.0;
                for s in 3 * k..3 * k + 3 {
                    centers[s] = [uniform(0.1), uniform(0.1), uniform(0.1)];
                    radii[s] = 0.02 + 0.03 * uniform(1.0).abs();
                    let d = centers[s];
                    reach = reach.max(crate::real::square_root(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + radii[s]);
                }
                groups[k] = (3 * k, 3 * k + 3, [0.0; 3], reach);
                links[k] = (k, k + 1, [0.0; 3], reach);
            }
            let tables = CollisionTables {
                links: &links,
                groups: &groups,
                centers: &centers,
                radii: &radii,
                pairs: &[],
                fixed: &[],
                grids: &[],
            };
            let lane_poses: [[Pose<f64>; 3]; 8] = core::array::from_fn(|_| {
                core::array::from_fn(|_| {
                    Pose::from_rpy(
                        [uniform(3.0), uniform(3.0), uniform(3.0)],
                        [uniform(0.6), uniform(0.6), uniform(0.6)],
                    )
                })
            });
            let spheres = [SphereObstacle {
                center: [uniform(1.0), uniform(1.0), uniform(1.0)],
                radius: 0.02 + 0.4 * uniform(1.0).abs(),
            }];
            let capsules = [CapsuleObstacle {
                a: [uniform(1.0), uniform(1.0), uniform(1.0)],
                b: [uniform(1.0), uniform(1.0), uniform(1.0)],
                radius: 0.02 + 0.25 * uniform(1.0).abs(),
            }];
            let cylinders = [CylinderObstacle {
                a: [uniform(1.0), uniform(1.0), uniform(1.0)],
                b: [uniform(1.0), uniform(1.0), uniform(1.0)],
                radius: 0.02 + 0.25 * uniform(1.0).abs(),
            }];
            let turned =
                Pose::from_rpy([uniform(3.0), uniform(3.0), uniform(3.0)], [uniform(1.0), uniform(1.0), uniform(1.0)]);
            let size =
                [0.05 + 0.6 * uniform(1.0).abs(), 0.05 + 0.6 * uniform(1.0).abs(), 0.05 + 0.6 * uniform(1.0).abs()];
            let boxes = [
                BoxObstacle::from_pose(turned.rotation, turned.translation, size),
                BoxObstacle {
                    center: [uniform(1.5), uniform(1.5), uniform(1.5)],
                    rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
                    half_extents: size,
                },
            ];
            // Some rounds one kind alone, so the box holding the obstacles is that one's.
            let kind = round % 5;
            let env = Environment::new(
                if kind <= 1 { &spheres } else { &[] },
                if kind == 0 || kind == 2 { &capsules } else { &[] },
                if kind == 0 || kind == 3 { &cylinders } else { &[] },
                if kind == 0 || kind == 4 { &boxes } else { &[] },
            )
            .unwrap();
            // Every obstacle, one by one: not `Environment::hits`, which asks the extent first.
            let every = |c: Vec3, r: f64| {
                spheres.iter().any(|o| o.hits(&c, r)) && kind <= 1
                    || capsules.iter().any(|o| o.hits(&c, r)) && (kind == 0 || kind == 2)
                    || cylinders.iter().any(|o| o.hits(&c, r)) && (kind == 0 || kind == 3)
                    || boxes.iter().any(|o| o.hits(&c, r)) && (kind == 0 || kind == 4)
            };
            let expected: [bool; 8] =
                core::array::from_fn(|l| (0..9).any(|s| every(lane_poses[l][s / 3].place(centers[s]), radii[s])));
            let poses64: [Pose<F64x4>; 3] = core::array::from_fn(|k| lanes_of(|l| lane_poses[l][k], 0));
            let poses64_hi: [Pose<F64x4>; 3] = core::array::from_fn(|k| lanes_of(|l| lane_poses[l][k], 4));
            let poses32: [Pose<F32x8>; 3] = core::array::from_fn(|k| lanes_of(|l| lane_poses[l][k], 0));
            let q64 = [F64x4::from_f64(0.0)];
            let got64 =
                collides(&tables, &q64, &poses64, &env).bits() | collides(&tables, &q64, &poses64_hi, &env).bits() << 4;
            let got32 = collides(&tables, &[F32x8::from_f64(0.0)], &poses32, &env).bits();
            for l in 0..8 {
                assert_eq!(got64 >> l & 1 == 1, expected[l], "round {round}, lane {l} (f64)");
                counts[usize::from(expected[l])] += 1;
            }
            // In f32, a sphere this near contact may go either way: those lanes are left out.
            let near_contact = (0..8).filter(|&l| {
                (0..9).any(|s| {
                    let c = lane_poses[l][s / 3].place(centers[s]);
                    every(c, radii[s] + 1e-4) != every(c, (radii[s] - 1e-4).max(0.0))
                })
            });
            let mask = !near_contact.fold(0u32, |m, l| m | 1 << l);
            assert_eq!(got32 & mask, got64 & mask, "round {round} (f32)");
        }
        assert!(counts[0] > 2000 && counts[1] > 2000, "free and colliding lanes: {counts:?}");
    }

    /// Lanes `first..` of `F`-lane poses from one pose per lane.
    fn lanes_of<L: Lanes>(pose: impl Fn(usize) -> Pose<f64>, first: usize) -> Pose<L>
    where
        L::Scalar: Real,
    {
        let lane = |f: &dyn Fn(&Pose<f64>) -> f64| L::from_fn(|l| L::Scalar::from_f64(f(&pose(first + l))));
        Pose {
            rotation: core::array::from_fn(|i| core::array::from_fn(|j| lane(&|p| p.rotation[i][j]))),
            translation: core::array::from_fn(|i| lane(&|p| p.translation[i])),
        }
    }

    #[test]
    fn each_lane_has_its_own_verdict() {
        // Lane k puts link 1 at x = offset + 0.1 k: within 0.2 of link 0 (itself) in lanes 0 to 2
        // of the first offset, within 0.2 of the ball at x = 0.7 in lanes 1 to 3 of the second.
        let ball = [SphereObstacle { center: [0.7, 0.0, 0.0], radius: 0.1 }];
        let env = Environment::new(&ball, &[], &[], &[]).unwrap();
        for (offset, expected) in [(0.0, 0b0111), (0.4, 0b1110)] {
            let x = F64x4::from_fn(|k| offset + 0.1 * k as f64);
            let poses = [at(F64x4::from_f64(0.0)), at(x)];
            let q = [F64x4::from_f64(0.0)];
            let world = collides(&TABLES, &q, &poses, &env);
            let itself = self_collides(&TABLES, &q, &poses);
            for k in 0..4 {
                let scalar = [at(0.0), at(offset + 0.1 * k as f64)];
                assert_eq!(itself.lane(k), self_collides(&TABLES, &[0.0], &scalar).any(), "lane {k}");
                assert_eq!(world.lane(k), collides(&TABLES, &[0.0], &scalar, &env).any(), "lane {k}");
            }
            assert_eq!(world.bits(), expected, "offset {offset}");
        }
    }
}
