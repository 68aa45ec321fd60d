//! How far a compiled robot is from colliding, and which way to move it: the clearance (the
//! smallest signed distance between its spheres and the obstacles, and between the spheres of
//! its checked self pairs) and a smooth proximity cost (the sum of squared depths within a
//! margin), each with its gradient with respect to the joints, on any [`CheckLanes`] type.
//!
//! Both scan the same pairs as `collides`: each link's bounding sphere against each obstacle (a
//! sphere's signed distance is never below its bound's, distances being 1-Lipschitz), then its
//! groups and spheres only where the bound is nearer than the scan's limit (the nearest pair
//! found so far, or the margin); each checked pair of links by their bounds, then their groups',
//! then their spheres. A bound's or a group's distance is taken only where an overlap test on
//! squared lengths (no root) says it may pass the limit, and a bound's distance `d` lowers the
//! limit to `d + R`.
//! A gradient is the pair's ends' directions carried through the links' geometric Jacobians
//! (`LOCAL_WORLD_ALIGNED`, at each link's origin): a sphere at `c` on a link at `t` moves by
//! `v + w x (c - t)`, so its distance along the unit direction `n` changes by `n . v + (c - t) x n
//! . w`; each link's six coefficients are summed first and its Jacobian taken once.
//!
//! `clearance` and `proximity_cost` scan the self pairs first, then the obstacles, pruned by
//! bounding spheres against the nearest pair or the margin; the sphere pairs held apart for good
//! are left out.

use super::distance::{cross, each3, length, unit};
use super::obstacles::{Environment, Obstacle, Prepared, SphereQuery, Visit, lane_dot, lane_sub};
use super::tables::{CollisionTables, fence};
use super::verdicts::{CheckLanes, Flags, non_finite};
use crate::pose::Pose;

/// One end of a measured pair: a sphere of link `link` (its index among the checks' links)
/// centred at `center`, and the direction moving it increases the distance.
#[derive(Clone, Copy)]
struct End<L> {
    link: usize,
    center: [L; 3],
    normal: [L; 3],
}

/// What a scan does with each pair it measures.
trait Sink<L: CheckLanes> {
    /// Whether the sink's limit falls with upper bounds on the nearest pair ([`Sink::upper`]).
    const WANTS_UPPER: bool;
    /// An upper bound on the nearest pair's distance.
    fn upper(&mut self, bound: L);
    /// Pairs that are not nearer than this in any lane need not be measured.
    fn limit(&self) -> L;
    /// A pair at signed distance `d`: a sphere (`a`) and an obstacle, or two of the robot's
    /// spheres (`a` and `b`).
    fn take(&mut self, d: L, a: &End<L>, b: Option<&End<L>>);
}

/// Every primitive obstacle of `env`, prepared and visited in turn.
#[cfg_attr(not(debug_assertions), inline(always))]
fn each_obstacle<L: CheckLanes, V: Visit<L>>(env: &Environment<'_>, visit: &mut V) {
    for o in env.spheres {
        o.prepare(visit);
    }
    for o in env.capsules {
        o.prepare(visit);
    }
    for o in env.cylinders {
        o.prepare(visit);
    }
    for o in env.boxes {
        o.prepare(visit);
    }
}

/// How many links' bounding spheres a scan places at a time.
const CHUNK: usize = 16;

impl CollisionTables<'_> {
    /// The clearance of the robot at `q`, its links with spheres at `poses`: the smallest signed
    /// distance (m; negative, the depth of the deepest overlap) between one of its spheres and
    /// an obstacle of `env`, or between two spheres of a checked self pair; infinite with neither.
    /// NaN in a lane whose `q` is not finite.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn clearance<L: CheckLanes, const N: usize, const K: usize>(
        &self,
        q: &[L; N],
        poses: &[Pose<L>; K],
        env: &Environment<'_>,
    ) -> L {
        let mut least = Least::<L, false>::new();
        self.scan(poses, env, &mut least);
        nan_where(non_finite(q), least.best)
    }

    /// The clearance ([`CollisionTables::clearance`]) and its gradient with respect to the
    /// velocities (the columns of `jacobians`, each link's geometric Jacobian at its origin in
    /// the base's axes, `LOCAL_WORLD_ALIGNED`): the nearest pair's ends moved by their links.
    /// Where the nearest pair changes, the clearance has a kink and the gradient is the nearest
    /// pair's found first; a zero gradient where there is no pair.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn clearance_gradient<L: CheckLanes, const N: usize, const K: usize, const V: usize>(
        &self,
        q: &[L; N],
        poses: &[Pose<L>; K],
        jacobians: &[[[L; V]; 6]; K],
        env: &Environment<'_>,
    ) -> (L, [L; V]) {
        let mut least = Least::<L, true>::new();
        self.scan(poses, env, &mut least);
        let jacobians = fence(jacobians);
        let zero = L::from_f64(0.0);
        let mut gradient = [zero; V];
        for (k, (pose, jacobian)) in poses.iter().zip(jacobians).enumerate() {
            let index = L::from_f64(index_f64(k));
            let on_a = same(least.a_link, index);
            let on_b = same(least.b_link, index);
            if !(on_a | on_b).any() {
                continue;
            }
            let a = moment(&least.a_center, &least.a_normal, pose);
            let b = moment(&least.b_center, &least.b_normal, pose);
            let pick = |r: usize| L::select(on_a, a[r], zero) + L::select(on_b, b[r], zero);
            let coefficients = [pick(0), pick(1), pick(2), pick(3), pick(4), pick(5)];
            contract(&coefficients, jacobian, &mut gradient);
        }
        let bad = non_finite(q);
        nan_each(bad, &mut gradient);
        (nan_where(bad, least.best), gradient)
    }

    /// The proximity cost of the robot at `q`: over every pair the clearance measures whose
    /// signed distance `d` is below `margin` (m), the sum of `(margin - d)^2`; zero when every
    /// pair is at least `margin` apart. Smooth where no pair is exactly at the margin or has a
    /// zero distance between centres. NaN in a lane whose `q` is not finite, and everywhere for
    /// a margin that is negative or not finite (the generated functions refuse those first).
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn proximity_cost<L: CheckLanes, const N: usize, const K: usize>(
        &self,
        q: &[L; N],
        poses: &[Pose<L>; K],
        env: &Environment<'_>,
        margin: f64,
    ) -> L {
        let mut cost = Cost::<L, K, false>::new(margin, poses);
        self.scan(poses, env, &mut cost);
        nan_where(non_finite(q) | bad_margin::<L>(margin), cost.sum)
    }

    /// The proximity cost ([`CollisionTables::proximity_cost`]) and its gradient with respect
    /// to the velocities (`jacobians` as for [`CollisionTables::clearance_gradient`]): each pair
    /// within the margin contributes `-2 (margin - d)` times its distance's gradient.
    #[cfg_attr(not(debug_assertions), inline(always))]
    pub fn proximity_cost_gradient<L: CheckLanes, const N: usize, const K: usize, const V: usize>(
        &self,
        q: &[L; N],
        poses: &[Pose<L>; K],
        jacobians: &[[[L; V]; 6]; K],
        env: &Environment<'_>,
        margin: f64,
    ) -> (L, [L; V]) {
        let mut cost = Cost::<L, K, true>::new(margin, poses);
        self.scan(poses, env, &mut cost);
        let mut gradient = [L::from_f64(0.0); V];
        let jacobians = fence(jacobians);
        for ((coefficients, jacobian), touched) in cost.coefficients.iter().zip(jacobians).zip(cost.touched) {
            if touched {
                contract(coefficients, jacobian, &mut gradient);
            }
        }
        let bad = non_finite(q) | bad_margin::<L>(margin);
        nan_each(bad, &mut gradient);
        (nan_where(bad, cost.sum), gradient)
    }

    /// Every pair `sink` asks for: the self pairs, then each link's spheres against each
    /// obstacle, each pruned by bounding spheres against the sink's limit. The self pairs come
    /// first: a few sphere pairs of links near one another (no obstacle's distance, which costs
    /// more) often give the nearest pair, or a limit that prunes most of the obstacles' work.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn scan<L: CheckLanes, S: Sink<L>>(&self, poses: &[Pose<L>], env: &Environment<'_>, sink: &mut S) {
        let poses = fence(poses);
        self.scan_pairs(poses, sink);
        for first in (0..self.links.len()).step_by(CHUNK) {
            let (bounds, count) = self.bounds(poses, first);
            let mut visit = Measuring { tables: self, poses, first, bounds: &bounds[..count], sink: &mut *sink };
            each_obstacle(env, &mut visit);
            if let Some(query) = env.query {
                visit.query(query);
            }
        }
    }

    /// The bounding spheres of up to [`CHUNK`] links from `first`, placed, and how many.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn bounds<L: CheckLanes>(&self, poses: &[Pose<L>], first: usize) -> ([([L; 3], L); CHUNK], usize) {
        let mut bounds = [([L::from_f64(0.0); 3], L::from_f64(0.0)); CHUNK];
        let links = first..self.links.len().min(first + CHUNK);
        for (slot, k) in bounds.iter_mut().zip(links.clone()) {
            *slot = (poses[k].place(self.links[k].2), L::from_f64(self.links[k].3));
        }
        (bounds, links.len())
    }

    /// The spheres of link `k`, `start..end` in the tables.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn spheres_of(&self, k: usize) -> core::ops::Range<usize> {
        let (g0, g1, ..) = self.links[k];
        self.groups[g0].0..self.groups[g1 - 1].1
    }

    /// The self pairs: each pair of links by their bounds, their groups' bounds, their spheres,
    /// less the sphere pairs held apart for good (`fixed`).
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn scan_pairs<L: CheckLanes, S: Sink<L>>(&self, poses: &[Pose<L>], sink: &mut S) {
        for &(i, j) in self.pairs {
            let ((ga, ea, ba, ra), (gb, eb, bb, rb)) = (self.links[i], self.links[j]);
            let (bound_i, bound_j) = (poses[i].place(ba), poses[j].place(bb));
            if !may_reach(&bound_i, &bound_j, ra + rb, sink.limit()).any() {
                continue;
            }
            for a in ga..ea {
                let (a0, a1, ca, rga) = self.groups[a];
                let ca = poses[i].place(ca);
                if !may_reach(&ca, &bound_j, rga + rb, sink.limit()).any() {
                    continue;
                }
                for b in gb..eb {
                    let (b0, b1, cb, rgb) = self.groups[b];
                    let cb = poses[j].place(cb);
                    if !may_reach(&ca, &cb, rga + rgb, sink.limit()).any() {
                        continue;
                    }
                    for s in a0..a1 {
                        let cs = poses[i].place(self.centers[s]);
                        for t in b0..b1 {
                            let ct = poses[j].place(self.centers[t]);
                            let radii = self.radii[s] + self.radii[t];
                            if !may_reach(&cs, &ct, radii, sink.limit()).any() || self.fixed.contains(&(s, t)) {
                                continue;
                            }
                            let d = lane_sub(&cs, &ct);
                            let l = length(&d);
                            let n = unit(&d, l);
                            let distance = l - L::from_f64(radii);
                            let a = End { link: i, center: cs, normal: n };
                            let b = End { link: j, center: ct, normal: each3(|i| -n[i]) };
                            sink.take(distance, &a, Some(&b));
                        }
                    }
                }
            }
        }
    }
}

/// How far a sphere may be from something and still count against `limit` (m): `limit + radius`,
/// or zero where that is negative (a signed distance below a negative reach needs the centre
/// inside, which a reach of zero still lets through). A NaN limit (only in a lane whose `q` is not
/// finite, whose answer is made NaN at the end) gives zero too.
#[cfg_attr(not(debug_assertions), inline(always))]
fn reach<L: CheckLanes>(limit: L, radius: L) -> L {
    (limit + radius).max(L::from_f64(0.0))
}

/// The lanes where spheres at `a` and `b` with radii summing to `radii` may be nearer than
/// `limit`: `|a - b| - radii <= limit`, tested on squares (no root; the exact distance follows
/// where it passes). NaN lanes pass.
#[cfg_attr(not(debug_assertions), inline(always))]
fn may_reach<L: CheckLanes>(a: &[L; 3], b: &[L; 3], radii: f64, limit: L) -> L::Flags {
    let reach = reach(limit, L::from_f64(radii));
    let d = lane_sub(a, b);
    lane_dot(&d, &d).not_above(reach * reach)
}

/// A few consecutive links (from `first`), their bounding spheres placed, measured against one
/// prepared obstacle after another.
struct Measuring<'a, 'c, 't, L: CheckLanes, S> {
    tables: &'c CollisionTables<'t>,
    poses: &'c [Pose<L>],
    first: usize,
    bounds: &'c [([L; 3], L)],
    sink: &'a mut S,
}

impl<L: CheckLanes, S: Sink<L>> Visit<L> for Measuring<'_, '_, '_, L, S> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn visit<P: Prepared<L>>(&mut self, prepared: &P) {
        // The bounds first: each near enough to pass the limit gives an upper bound on the
        // nearest pair (a link whose bound is at `d` has every sphere within `d + R`), which
        // lowers the limit before any sphere of this obstacle is measured (else the first
        // obstacles, perhaps far, prune nothing). Each distance is asked only where the
        // obstacle's overlap test (no root) says it may pass; a far bound stays at infinity.
        let mut gaps = [L::from_f64(f64::INFINITY); CHUNK];
        for (gap, (bound, radius)) in gaps.iter_mut().zip(self.bounds) {
            if !prepared.hits(bound, reach(self.sink.limit(), *radius)).any() {
                continue;
            }
            let d = prepared.distance(bound).0;
            *gap = d - *radius;
            if S::WANTS_UPPER {
                self.sink.upper(d + *radius);
            }
        }
        for (k, gap) in gaps.iter().enumerate().take(self.bounds.len()) {
            let link = self.first + k;
            if !gap.not_above(self.sink.limit()).any() {
                continue;
            }
            // Then the link's groups (where it has more than one) by the overlap test, and the
            // spheres of a group that passes by their distances (an overlap test before each
            // was measured no faster: most spheres of a near group are near too).
            let (g0, g1, ..) = self.tables.links[link];
            for g in g0..g1 {
                let (s0, s1, c, r) = self.tables.groups[g];
                if g1 - g0 > 1
                    && !prepared.hits(&self.poses[link].place(c), reach(self.sink.limit(), L::from_f64(r))).any()
                {
                    continue;
                }
                for s in s0..s1 {
                    let center = self.poses[link].place(self.tables.centers[s]);
                    let r = L::from_f64(self.tables.radii[s]);
                    let (d, normal) = prepared.distance(&center);
                    self.sink.take(d - r, &End { link, center, normal }, None);
                }
            }
        }
    }
}

impl<L: CheckLanes, S: Sink<L>> Measuring<'_, '_, '_, L, S> {
    /// The links against `query`'s obstacles, asked one lane at a time: each link's bound,
    /// then its spheres in the lanes where the bound is nearer than the limit.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn query(&mut self, query: &dyn SphereQuery) {
        for (k, (bound, radius)) in self.bounds.iter().enumerate() {
            let link = self.first + k;
            let limit = self.sink.limit();
            let mut near = 0u32;
            for i in 0..L::WIDTH {
                let c = bound.map(|x| x.lane_f64(i));
                if c.iter().all(|x| x.is_finite()) {
                    let reach = limit.lane_f64(i) + radius.lane_f64(i);
                    near |= u32::from(query.nearest(c, reach).is_some()) << i;
                }
            }
            if near == 0 {
                continue;
            }
            for s in self.tables.spheres_of(link) {
                let center = self.poses[link].place(self.tables.centers[s]);
                let r = self.tables.radii[s];
                let limit = self.sink.limit();
                let mut found = [None; 32];
                for (i, slot) in found.iter_mut().enumerate().take(L::WIDTH) {
                    let c = center.map(|x| x.lane_f64(i));
                    if (near >> i) & 1 == 1 && c.iter().all(|x| x.is_finite()) {
                        *slot = query.nearest(c, limit.lane_f64(i) + r);
                    }
                }
                let d = L::from_lanes(|i| found[i].map_or(f64::INFINITY, |(d, _)| d - r));
                let normal = each3(|a| L::from_lanes(|i| found[i].map_or(0.0, |(_, n)| n[a])));
                self.sink.take(d, &End { link, center, normal }, None);
            }
        }
    }
}

/// The nearest pair so far, lane by lane, and (with `WITNESS`) its ends: each end's link as a
/// number (`-1`: an obstacle), centre and direction.
struct Least<L, const WITNESS: bool> {
    best: L,
    /// The least upper bound on the nearest pair (with a little slack for rounding).
    upper: L,
    a_link: L,
    a_center: [L; 3],
    a_normal: [L; 3],
    b_link: L,
    b_center: [L; 3],
    b_normal: [L; 3],
}

impl<L: CheckLanes, const WITNESS: bool> Least<L, WITNESS> {
    fn new() -> Self {
        let zero = [L::from_f64(0.0); 3];
        let none = L::from_f64(-1.0);
        Least {
            best: L::from_f64(f64::INFINITY),
            upper: L::from_f64(f64::INFINITY),
            a_link: none,
            a_center: zero,
            a_normal: zero,
            b_link: none,
            b_center: zero,
            b_normal: zero,
        }
    }
}

impl<L: CheckLanes, const WITNESS: bool> Sink<L> for Least<L, WITNESS> {
    const WANTS_UPPER: bool = true;

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn upper(&mut self, bound: L) {
        // A nanometre over: the bound and the distances are rounded apart.
        self.upper = self.upper.min(bound + L::from_f64(1e-9));
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn limit(&self) -> L {
        self.best.min(self.upper)
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn take(&mut self, d: L, a: &End<L>, b: Option<&End<L>>) {
        // Strictly nearer: the first pair found keeps a tie (and a lane whose distance is NaN,
        // from a configuration that is not finite, is made NaN at the end).
        let nearer = L::Flags::from_mask(!self.best.not_above(d).bits());
        if !nearer.any() {
            return;
        }
        self.best = L::select(nearer, d, self.best);
        if WITNESS {
            let pick = |new: &[L; 3], old: &[L; 3]| each3(|i| L::select(nearer, new[i], old[i]));
            self.a_link = L::select(nearer, L::from_f64(index_f64(a.link)), self.a_link);
            self.a_center = pick(&a.center, &self.a_center);
            self.a_normal = pick(&a.normal, &self.a_normal);
            let (b_link, b_center, b_normal) = match b {
                Some(b) => (L::from_f64(index_f64(b.link)), b.center, b.normal),
                None => (L::from_f64(-1.0), [L::from_f64(0.0); 3], [L::from_f64(0.0); 3]),
            };
            self.b_link = L::select(nearer, b_link, self.b_link);
            self.b_center = pick(&b_center, &self.b_center);
            self.b_normal = pick(&b_normal, &self.b_normal);
        }
    }
}

/// The proximity cost so far and (with `GRADIENT`) each link's six coefficients (what its
/// Jacobian's rows are multiplied by) and whether any pair touched it.
struct Cost<'p, L, const K: usize, const GRADIENT: bool> {
    margin: L,
    sum: L,
    poses: &'p [Pose<L>; K],
    coefficients: [[L; 6]; K],
    touched: [bool; K],
}

impl<'p, L: CheckLanes, const K: usize, const GRADIENT: bool> Cost<'p, L, K, GRADIENT> {
    fn new(margin: f64, poses: &'p [Pose<L>; K]) -> Self {
        let zero = L::from_f64(0.0);
        Cost { margin: L::from_f64(margin), sum: zero, poses, coefficients: [[zero; 6]; K], touched: [false; K] }
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn add(&mut self, weight: L, end: &End<L>) {
        let m = moment(&end.center, &end.normal, &self.poses[end.link]);
        let c = &mut self.coefficients[end.link];
        for r in 0..6 {
            c[r] = c[r] + weight * m[r];
        }
        self.touched[end.link] = true;
    }
}

impl<L: CheckLanes, const K: usize, const GRADIENT: bool> Sink<L> for Cost<'_, L, K, GRADIENT> {
    const WANTS_UPPER: bool = false;

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn upper(&mut self, _: L) {}

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn limit(&self) -> L {
        self.margin
    }

    #[cfg_attr(not(debug_assertions), inline(always))]
    fn take(&mut self, d: L, a: &End<L>, b: Option<&End<L>>) {
        let zero = L::from_f64(0.0);
        // Lanes beyond the margin (an infinite distance from a query's lane not asked too)
        // contribute nothing.
        let within = L::Flags::from_mask(!self.margin.not_above(d).bits());
        if !within.any() {
            return;
        }
        let depth = L::select(within, self.margin - d, zero);
        self.sum = self.sum + depth * depth;
        if GRADIENT {
            let weight = L::from_f64(-2.0) * depth;
            self.add(weight, a);
            if let Some(b) = b {
                self.add(weight, b);
            }
        }
    }
}

/// A sphere end's six coefficients on its link's Jacobian rows: the direction `n` (linear rows)
/// and `(c - t) x n` (angular rows), `t` the link's origin.
#[cfg_attr(not(debug_assertions), inline(always))]
fn moment<L: CheckLanes>(center: &[L; 3], normal: &[L; 3], pose: &Pose<L>) -> [L; 6] {
    let arm = cross(&lane_sub(center, &pose.translation), normal);
    [normal[0], normal[1], normal[2], arm[0], arm[1], arm[2]]
}

/// `gradient += coefficients^T jacobian`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn contract<L: CheckLanes, const V: usize>(coefficients: &[L; 6], jacobian: &[[L; V]; 6], gradient: &mut [L; V]) {
    for (c, row) in coefficients.iter().zip(jacobian) {
        for (g, x) in gradient.iter_mut().zip(row) {
            *g = *g + *c * *x;
        }
    }
}

/// Whether `a` and `b` are the same link number (both whole numbers).
#[cfg_attr(not(debug_assertions), inline(always))]
fn same<L: CheckLanes>(a: L, b: L) -> L::Flags {
    (a - b).abs().not_above(L::from_f64(0.25))
}

/// `k` as a number (links number far below 2^24: exact in `f32` too).
#[cfg_attr(not(debug_assertions), inline(always))]
fn index_f64(k: usize) -> f64 {
    #[allow(clippy::cast_precision_loss, reason = "a link index is far below 2^52")]
    let k = k as f64;
    k
}

/// `x`, NaN in the lanes of `bad`.
#[cfg_attr(not(debug_assertions), inline(always))]
fn nan_where<L: CheckLanes>(bad: L::Flags, x: L) -> L {
    L::select(bad, L::from_f64(f64::NAN), x)
}

/// Every entry of `values` NaN in the lanes of `bad` (a loop, not an array's `map`: see
/// [`each3`]).
#[cfg_attr(not(debug_assertions), inline(always))]
fn nan_each<L: CheckLanes, const V: usize>(bad: L::Flags, values: &mut [L; V]) {
    for x in values.iter_mut() {
        *x = nan_where(bad, *x);
    }
}

/// Every lane when `margin` is negative or not finite.
#[cfg_attr(not(debug_assertions), inline(always))]
fn bad_margin<L: CheckLanes>(margin: f64) -> L::Flags {
    let bad = !(margin.is_finite() && margin >= 0.0);
    L::Flags::from_mask(if bad { super::LaneMask::full(L::WIDTH) } else { super::LaneMask::NONE })
}
