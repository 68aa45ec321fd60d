//! Signed distances from a point to each kind of prepared obstacle, with their gradients, on any
//! [`CheckLanes`] type: what `clearance` and `proximity_cost` measure.
//!
//! A distance is the point's signed distance to the obstacle's surface: positive outside, minus
//! the depth inside (the distance to the nearest point of the surface). Its gradient with respect
//! to the point is the unit vector away from that nearest point (for a point inside, away from the
//! nearest face); where it is not defined (a point at a sphere's centre, on a capsule's axis, on a
//! cylinder's axis when the curved side is nearest) it is zero, a subgradient a descent treats as
//! flat. A sphere of radius `r` at the point is then `distance - r` from the obstacle: signed
//! distances are 1-Lipschitz, so a sphere's distance is never below its bounding sphere's, which
//! is what lets a check skip a link whose bound is farther than the nearest pair found.

use super::obstacles::{AlignedBox, PreparedCapsule, PreparedCylinder, PreparedSphere, TurnedBox, lane_dot, lane_sub};
use super::verdicts::{CheckLanes, Flags, LaneMask};

/// A prepared obstacle's signed distance and its gradient.
pub(crate) trait Measure<L: CheckLanes> {
    /// The signed distance from `p` to the obstacle's surface and its gradient with respect to
    /// `p` (a unit vector, or zero where it is not defined).
    fn distance(&self, p: &[L; 3]) -> (L, [L; 3]);
}

/// `[f(0), f(1), f(2)]`, written out. An array's `map` goes through iterator adapters whose
/// closures LLVM left as calls, compiled for the baseline instruction set, inside a dispatched
/// lane body (measured: the clearance in `F64x4` lanes spent a third of its time in them, in
/// SSE2); direct calls of a small closure are inlined.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn each3<T>(mut f: impl FnMut(usize) -> T) -> [T; 3] {
    [f(0), f(1), f(2)]
}

/// `v / length`, or zero in the lanes where `length` is zero (`v` is then zero too).
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn unit<L: CheckLanes>(v: &[L; 3], length: L) -> [L; 3] {
    let zero = L::from_f64(0.0);
    let at_zero = length.not_above(zero);
    each3(|i| L::select(at_zero, zero, v[i] / length))
}

/// The length of `v`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn length<L: CheckLanes>(v: &[L; 3]) -> L {
    lane_dot(v, v).sqrt()
}

/// Every lane's flag set.
#[cfg_attr(not(debug_assertions), inline(always))]
fn every<L: CheckLanes>() -> L::Flags {
    L::Flags::from_mask(LaneMask::full(L::WIDTH))
}

impl<L: CheckLanes> Measure<L> for PreparedSphere<L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn distance(&self, p: &[L; 3]) -> (L, [L; 3]) {
        let d = lane_sub(p, &self.center);
        let l = length(&d);
        (l - self.radius, unit(&d, l))
    }
}

impl<L: CheckLanes> Measure<L> for PreparedCapsule<L> {
    /// From the nearest point of the axis segment.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn distance(&self, p: &[L; 3]) -> (L, [L; 3]) {
        let ab = &self.axis;
        let ap = lane_sub(p, &self.a);
        let (zero, one) = (L::from_f64(0.0), L::from_f64(1.0));
        let t = (lane_dot(&ap, ab) * self.inverse).max(zero).min(one);
        let d = [ap[0] - ab[0] * t, ap[1] - ab[1] * t, ap[2] - ab[2] * t];
        let l = length(&d);
        (l - self.radius, unit(&d, l))
    }
}

impl<L: CheckLanes> Measure<L> for PreparedCylinder<L> {
    /// With `dr` the point's distance from the axis less the radius and `over` its distance
    /// beyond the nearer cap's plane (negative between the caps): outside, the length of
    /// `(max(dr, 0), max(over, 0))` along the radial direction and the axis; inside (both
    /// negative), the larger of the two, from the curved side or the nearer cap.
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn distance(&self, p: &[L; 3]) -> (L, [L; 3]) {
        let zero = L::from_f64(0.0);
        let u = &self.unit;
        let ap = lane_sub(p, &self.a);
        let along = lane_dot(&ap, u);
        let radial = [ap[0] - u[0] * along, ap[1] - u[1] * along, ap[2] - u[2] * along];
        let rho = length(&radial);
        let outward = unit(&radial, rho);
        let dr = rho - self.radius;
        let (below, above) = (-along, along - self.length);
        let over = below.max(above);
        // Along the axis, away from the nearer cap.
        let beyond_b = below.not_above(above);
        let axial = each3(|i| L::select(beyond_b, u[i], -u[i]));
        let inside = dr.not_above(zero) & over.not_above(zero);
        let (er, ea) = (dr.max(zero), over.max(zero));
        let outside_length = (er * er + ea * ea).sqrt();
        let outside = each3(|i| (er * outward[i] + ea * axial[i]) / outside_length);
        let side_nearer = over.not_above(dr);
        let within = each3(|i| L::select(side_nearer, outward[i], axial[i]));
        let gradient = each3(|i| L::select(inside, within[i], outside[i]));
        (L::select(inside, dr.max(over), outside_length), gradient)
    }
}

/// The signed distance from a point at `local` in a box's frame to the box of half extents `half`
/// and its gradient in the box's frame: outside, the length of the coordinates beyond the half
/// extents; inside, the largest (nearest face) of those differences, all negative.
#[cfg_attr(not(debug_assertions), inline(always))]
fn box_distance<L: CheckLanes>(local: &[L; 3], half: &[L; 3]) -> (L, [L; 3]) {
    let (zero, one) = (L::from_f64(0.0), L::from_f64(1.0));
    let sign = each3(|i| L::select(local[i].not_above(zero), -one, one));
    let q = each3(|i| local[i].abs() - half[i]);
    let e = each3(|i| q[i].max(zero));
    let outside_length = length(&e);
    let outside = each3(|i| sign[i] * e[i] / outside_length);
    // The nearest face from inside: the axis of the largest difference.
    let past_x = q[0].not_above(q[1]);
    let largest_xy = L::select(past_x, q[1], q[0]);
    let take_z = largest_xy.not_above(q[2]);
    let take_y = past_x.and_not(take_z);
    let take_x = every::<L>().and_not(take_y | take_z);
    let largest = L::select(take_z, q[2], largest_xy);
    let faces = [take_x, take_y, take_z];
    let within = each3(|i| L::select(faces[i], sign[i], zero));
    let inside = largest.not_above(zero);
    let gradient = each3(|i| L::select(inside, within[i], outside[i]));
    (L::select(inside, largest, outside_length), gradient)
}

impl<L: CheckLanes> Measure<L> for AlignedBox<L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn distance(&self, p: &[L; 3]) -> (L, [L; 3]) {
        box_distance(&lane_sub(p, &self.center), &self.half)
    }
}

impl<L: CheckLanes> Measure<L> for TurnedBox<L> {
    #[cfg_attr(not(debug_assertions), inline(always))]
    fn distance(&self, p: &[L; 3]) -> (L, [L; 3]) {
        let d = lane_sub(p, &self.center);
        let rows = &self.rows;
        let local = [lane_dot(&rows[0], &d), lane_dot(&rows[1], &d), lane_dot(&rows[2], &d)];
        let (distance, g) = box_distance(&local, &self.half);
        // Back to the world: the rows are the box's axes.
        let world = each3(|i| g[0] * rows[0][i] + g[1] * rows[1][i] + g[2] * rows[2][i]);
        (distance, world)
    }
}

/// `a x b`.
#[cfg_attr(not(debug_assertions), inline(always))]
pub(super) fn cross<L: CheckLanes>(a: &[L; 3], b: &[L; 3]) -> [L; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collision::obstacles::{Obstacle, Prepared, Visit};
    use crate::collision::{BoxObstacle, CapsuleObstacle, CylinderObstacle, SphereObstacle};
    use crate::{F64x4, Lanes};

    /// The distance and gradient of one obstacle at one point, through the visitor a check uses.
    struct At<'a, L: CheckLanes> {
        p: &'a [L; 3],
        out: (L, [L; 3]),
    }

    impl<L: CheckLanes> Visit<L> for At<'_, L> {
        fn visit<P: Prepared<L>>(&mut self, obstacle: &P) {
            self.out = obstacle.distance(self.p);
        }
    }

    fn measure<L: CheckLanes>(o: &impl Obstacle, p: [L; 3]) -> (L, [L; 3]) {
        let mut at = At { p: &p, out: (L::from_f64(0.0), [L::from_f64(0.0); 3]) };
        o.prepare(&mut at);
        at.out
    }

    /// `o`'s distance at `p` is `d` with gradient `g`; in `f64`, and in each lane of `F64x4`
    /// beside three other points that are not `p`.
    fn expect(o: &impl Obstacle, p: [f64; 3], d: f64, g: [f64; 3]) {
        let (distance, gradient) = measure(o, p);
        assert!((distance - d).abs() < 1e-14, "{p:?}: distance {distance}, expected {d}");
        for i in 0..3 {
            assert!((gradient[i] - g[i]).abs() < 1e-14, "{p:?}: gradient {gradient:?}, expected {g:?}");
        }
        for lane in 0..4 {
            let lanes = [0, 1, 2].map(|i| F64x4::from_fn(|k| if k == lane { p[i] } else { p[i] + 7.0 }));
            let (distance, gradient) = measure(o, lanes);
            assert_eq!(distance.lane(lane).to_bits(), measure(o, p).0.to_bits(), "{p:?} in lane {lane}");
            for (g, one) in gradient.iter().zip(measure(o, p).1) {
                assert_eq!(g.lane(lane).to_bits(), one.to_bits(), "{p:?} in lane {lane}");
            }
        }
    }

    #[test]
    fn each_shape_measures_by_hand() {
        let s = SphereObstacle { center: [1.0, 0.0, 0.0], radius: 0.5 };
        expect(&s, [3.0, 0.0, 0.0], 1.5, [1.0, 0.0, 0.0]);
        expect(&s, [1.0, 0.3, 0.0], -0.2, [0.0, 1.0, 0.0]);
        expect(&s, [1.0, 0.0, 0.0], -0.5, [0.0; 3]);
        let c = CapsuleObstacle { a: [0.0; 3], b: [0.0, 0.0, 2.0], radius: 0.5 };
        expect(&c, [0.0, 2.0, 1.0], 1.5, [0.0, 1.0, 0.0]);
        expect(&c, [0.0, 0.0, 4.0], 1.5, [0.0, 0.0, 1.0]);
        expect(&c, [0.0, -3.0, -4.0], 4.5, [0.0, -0.6, -0.8]);
        let y = CylinderObstacle { a: [0.0; 3], b: [0.0, 0.0, 2.0], radius: 0.5 };
        // Beside the curved side, beyond a cap, beyond the rim (3-4-5), and inside: nearer the
        // side, nearer the top cap, nearer the bottom cap.
        expect(&y, [2.0, 0.0, 1.0], 1.5, [1.0, 0.0, 0.0]);
        expect(&y, [0.3, 0.0, 3.0], 1.0, [0.0, 0.0, 1.0]);
        expect(&y, [0.0, 3.5, 6.0], 5.0, [0.0, 0.6, 0.8]);
        expect(&y, [0.0, 0.4, 1.0], -0.1, [0.0, 1.0, 0.0]);
        expect(&y, [0.1, 0.0, 1.9], -0.1, [0.0, 0.0, 1.0]);
        expect(&y, [0.1, 0.0, 0.05], -0.05, [0.0, 0.0, -1.0]);
        let b = BoxObstacle {
            center: [0.0; 3],
            rotation: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            half_extents: [1.0, 2.0, 3.0],
        };
        expect(&b, [4.0, 0.0, 0.0], 3.0, [1.0, 0.0, 0.0]);
        expect(&b, [-4.0, 6.0, 0.0], 5.0, [-0.6, 0.8, 0.0]);
        expect(&b, [0.5, -1.8, 0.5], -0.2, [0.0, -1.0, 0.0]);
        expect(&b, [0.5, 0.5, -2.9], -0.1, [0.0, 0.0, -1.0]);
        expect(&b, [-0.7, 0.5, 0.5], -0.3, [-1.0, 0.0, 0.0]);
        // Turned a quarter about z: its 4 m edge lies along x.
        let turned =
            BoxObstacle::from_pose([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], [1.0; 3], [2.0, 4.0, 6.0]);
        expect(&turned, [4.0, 1.0, 1.0], 1.0, [1.0, 0.0, 0.0]);
        expect(&turned, [1.0, 3.0, 1.0], 1.0, [0.0, 1.0, 0.0]);
        expect(&turned, [1.0, 1.5, 1.0], -0.5, [0.0, 1.0, 0.0]);
    }
}
