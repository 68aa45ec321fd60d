//! The recursive algorithms, written symbolically over the bodies: Newton-Euler (inverse
//! dynamics, nonlinear effects), composite first moments (gravity), composite rigid bodies (the
//! mass matrix).
//!
//! Each body's velocity, acceleration and force are spatial vectors at its origin in its own axes
//! (angular part, then linear), as in Featherstone's *Rigid Body Dynamics Algorithms* (2008), ch.
//! 2 and 5; gravity enters as the root's acceleration `-g` (§5.3). With a body's frame `(R, p)` in
//! its parent's, motion vectors go down as `w' = R^T w`, `v' = R^T (v + w x p)`, and forces come up
//! as `f = R f'`, `n = R n' + p x f`. A rigid body of mass `m`, first moment `h = m c` and inertia
//! `I` about its origin turns an acceleration `(a_w, a_v)` into the force `(I a_w + h x a_v,
//! m a_v + a_w x h)`.

use super::algebra::{self, Sym3, Vec3, add, cross, dot, mat_t_vec, mat_vec, rotate_sym, scale, sym_index, sym_vec};
use super::bodies::{Body, Inertia, Motion};
use crate::symbolic::graph::{ExprGraph, ExprId};
use crate::symbolic::transform::SymTransform;

/// A spatial vector: angular part, then linear.
#[derive(Debug, Clone, Copy)]
pub(super) struct Spatial {
    pub(super) angular: Vec3,
    pub(super) linear: Vec3,
}

impl Spatial {
    pub(super) fn zero(g: &mut ExprGraph) -> Self {
        Spatial { angular: algebra::zero(g), linear: algebra::zero(g) }
    }

    pub(super) fn add(self, g: &mut ExprGraph, other: Spatial) -> Self {
        Spatial { angular: add(g, self.angular, other.angular), linear: add(g, self.linear, other.linear) }
    }

    pub(super) fn sub(self, g: &mut ExprGraph, other: Spatial) -> Self {
        let angular = std::array::from_fn(|i| g.sub(self.angular[i], other.angular[i]));
        let linear = std::array::from_fn(|i| g.sub(self.linear[i], other.linear[i]));
        Spatial { angular, linear }
    }
}

/// A motion vector of the parent's frame in `body`'s frame.
pub(super) fn motion_down(g: &mut ExprGraph, body: &Body, m: Spatial) -> Spatial {
    let t = &body.transform;
    let angular = mat_t_vec(g, &t.r, m.angular);
    let arm = cross(g, m.angular, t.p);
    let at = add(g, m.linear, arm);
    Spatial { angular, linear: mat_t_vec(g, &t.r, at) }
}

/// A force in `body`'s frame in its parent's frame.
pub(super) fn force_up(g: &mut ExprGraph, body: &Body, f: Spatial) -> Spatial {
    force_out_of(g, &body.transform, f)
}

/// A force in the frame `t` (a frame placed in another by `t`) in that other frame.
pub(super) fn force_out_of(g: &mut ExprGraph, t: &SymTransform, f: Spatial) -> Spatial {
    let linear = mat_vec(g, &t.r, f.linear);
    let turned = mat_vec(g, &t.r, f.angular);
    let moment = cross(g, t.p, linear);
    Spatial { angular: add(g, turned, moment), linear }
}

/// A motion's direction as a spatial vector of constants, times `k`.
pub(super) fn direction(g: &mut ExprGraph, motion: &Motion, k: ExprId) -> Spatial {
    let angular = motion.angular.map(|x| {
        let x = g.constant(x);
        g.mul(x, k)
    });
    let linear = motion.linear.map(|x| {
        let x = g.constant(x);
        g.mul(x, k)
    });
    Spatial { angular, linear }
}

/// The generalized force of a spatial force along `motion` (per unit of its velocity).
fn project(g: &mut ExprGraph, motion: &Motion, f: Spatial) -> ExprId {
    let angular = algebra::constant(g, motion.angular.map(|x| x * motion.rate));
    let linear = algebra::constant(g, motion.linear.map(|x| x * motion.rate));
    let a = dot(g, angular, f.angular);
    let b = dot(g, linear, f.linear);
    g.add(a, b)
}

/// The joint's own velocity (or acceleration) from per-velocity values `x` (`None`: zero).
pub(super) fn joint_motion(
    g: &mut ExprGraph,
    body: &Body,
    x: &dyn Fn(&mut ExprGraph, usize) -> Option<ExprId>,
) -> Spatial {
    let mut sum = Spatial::zero(g);
    for motion in &body.motions {
        if let Some(value) = x(g, motion.column) {
            let rate = g.constant(motion.rate);
            let k = g.mul(rate, value);
            let d = direction(g, motion, k);
            sum = sum.add(g, d);
        }
    }
    sum
}

/// A rigid body's force for acceleration `a` (the inertia times `a`).
pub(super) fn inertia_times(g: &mut ExprGraph, inertia: &Inertia, a: Spatial) -> Spatial {
    let (h, m) = (inertia.first_moment, inertia.mass);
    let i_a = sym_vec(g, &inertia.rotational, a.angular);
    let h_a = cross(g, h, a.linear);
    let m_a = scale(g, m, a.linear);
    let a_h = cross(g, a.angular, h);
    Spatial { angular: add(g, i_a, h_a), linear: add(g, m_a, a_h) }
}

/// `v x* f`, the spatial force cross product.
pub(super) fn cross_force(g: &mut ExprGraph, v: Spatial, f: Spatial) -> Spatial {
    let wn = cross(g, v.angular, f.angular);
    let vf = cross(g, v.linear, f.linear);
    Spatial { angular: add(g, wn, vf), linear: cross(g, v.angular, f.linear) }
}

/// `v x m`, the spatial motion cross product.
pub(super) fn cross_motion(g: &mut ExprGraph, v: Spatial, m: Spatial) -> Spatial {
    let wv = cross(g, v.angular, m.linear);
    let vw = cross(g, v.linear, m.angular);
    Spatial { angular: cross(g, v.angular, m.angular), linear: add(g, wv, vw) }
}

/// An external force on a link: the body the link rides on, the link's frame in the body's, and
/// the force and its moment about the link's origin in the link's axes.
#[derive(Debug, Clone)]
pub(super) struct External {
    /// The body (its index).
    pub(super) body: usize,
    /// The link's frame in the body's (constants).
    pub(super) frame: SymTransform,
    /// The force.
    pub(super) force: Vec3,
    /// Its moment about the link's origin.
    pub(super) moment: Vec3,
}

/// What the Newton-Euler algorithm takes besides `q`: each velocity's rate and acceleration as
/// nodes (`None`: zero), the gravity vector and the external forces.
pub(super) struct NewtonEuler<'a> {
    /// The rates `qd`.
    pub(super) rates: &'a dyn Fn(&mut ExprGraph, usize) -> Option<ExprId>,
    /// The accelerations.
    pub(super) accelerations: &'a dyn Fn(&mut ExprGraph, usize) -> Option<ExprId>,
    /// Gravity in the root's frame.
    pub(super) gravity: [f64; 3],
    /// External forces on links (none for plain inverse dynamics).
    pub(super) external: &'a [External],
}

/// The generalized forces (one per velocity, `velocities` of them) that give the accelerations
/// at the rates: the recursive Newton-Euler algorithm (Featherstone Table 5.1).
pub(super) fn newton_euler(
    g: &mut ExprGraph,
    bodies: &[Body],
    velocities: usize,
    input: &NewtonEuler<'_>,
) -> Vec<ExprId> {
    let root_acceleration =
        Spatial { angular: algebra::zero(g), linear: algebra::constant(g, input.gravity.map(|x| -x)) };
    let mut velocity: Vec<Spatial> = Vec::with_capacity(bodies.len());
    let mut acceleration: Vec<Spatial> = Vec::with_capacity(bodies.len());
    let mut force: Vec<Spatial> = Vec::with_capacity(bodies.len());
    for body in bodies {
        let (v_parent, a_parent) = match body.parent {
            None => (Spatial::zero(g), root_acceleration),
            Some(p) => (velocity[p], acceleration[p]),
        };
        let v_joint = joint_motion(g, body, input.rates);
        let v_down = motion_down(g, body, v_parent);
        let v = v_down.add(g, v_joint);
        let a_joint = joint_motion(g, body, input.accelerations);
        let a_down = motion_down(g, body, a_parent);
        let bias = cross_motion(g, v, v_joint);
        let a = a_down.add(g, a_joint).add(g, bias);
        let f = match &body.inertia {
            None => Spatial::zero(g),
            Some(inertia) => {
                let ia = inertia_times(g, inertia, a);
                let iv = inertia_times(g, inertia, v);
                let gyro = cross_force(g, v, iv);
                ia.add(g, gyro)
            }
        };
        velocity.push(v);
        acceleration.push(a);
        force.push(f);
    }
    // What the world does to a link the joints need not do (Featherstone's `f_i - f_i^x`, Table
    // 5.1): each external force in its body's frame, taken from the body's.
    for external in input.external {
        let applied = Spatial { angular: external.moment, linear: external.force };
        let on_body = force_out_of(g, &external.frame, applied);
        force[external.body] = force[external.body].sub(g, on_body);
    }
    let zero = g.constant(0.0);
    let mut tau = vec![zero; velocities];
    for (i, body) in bodies.iter().enumerate().rev() {
        let f = force[i];
        for motion in &body.motions {
            let t = project(g, motion, f);
            tau[motion.column] = g.add(tau[motion.column], t);
        }
        if let Some(p) = body.parent {
            let up = force_up(g, body, f);
            force[p] = force[p].add(g, up);
        }
    }
    tau
}

/// The generalized forces that hold the robot still against `gravity`: per body, its subtree's
/// mass `M` and first moment `H` about its origin, so that its subtree's weight is the force
/// `(H x a, M a)` with `a = -g` in its axes (Newton-Euler with no velocity, folded by hand: no
/// force is carried up, only first moments).
pub(super) fn gravity(g: &mut ExprGraph, bodies: &[Body], velocities: usize, gravity: [f64; 3]) -> Vec<ExprId> {
    let root = algebra::constant(g, gravity.map(|x| -x));
    let mut down: Vec<Vec3> = Vec::with_capacity(bodies.len());
    for body in bodies {
        let above = body.parent.map_or(root, |p| down[p]);
        down.push(mat_t_vec(g, &body.transform.r, above));
    }
    let zero = g.constant(0.0);
    let mut mass: Vec<ExprId> = bodies.iter().map(|b| b.inertia.map_or(zero, |i| i.mass)).collect();
    let mut moment: Vec<Vec3> = bodies.iter().map(|b| b.inertia.map_or([zero; 3], |i| i.first_moment)).collect();
    let mut tau = vec![zero; velocities];
    for (i, body) in bodies.iter().enumerate().rev() {
        let a = down[i];
        let f = Spatial { angular: cross(g, moment[i], a), linear: scale(g, mass[i], a) };
        for motion in &body.motions {
            let t = project(g, motion, f);
            tau[motion.column] = g.add(tau[motion.column], t);
        }
        if let Some(p) = body.parent {
            let t = &body.transform;
            let turned = mat_vec(g, &t.r, moment[i]);
            let carried = scale(g, mass[i], t.p);
            let up = add(g, turned, carried);
            moment[p] = add(g, moment[p], up);
            mass[p] = g.add(mass[p], mass[i]);
        }
    }
    tau
}

/// The joint-space mass matrix's upper triangle, row-major pairs `(i, j)` with `i <= j`, by
/// composite rigid bodies (Featherstone Table 6.2): each body's subtree as one rigid body, its
/// force along each of the body's motions carried up to every body above.
pub(super) fn mass_matrix(g: &mut ExprGraph, bodies: &[Body], velocities: usize) -> Vec<Vec<ExprId>> {
    let zero = g.constant(0.0);
    let empty = Inertia { mass: zero, first_moment: [zero; 3], rotational: [zero; 6] };
    let mut composite: Vec<Inertia> = bodies.iter().map(|b| b.inertia.unwrap_or(empty)).collect();
    let mut m = vec![vec![zero; velocities]; velocities];
    let mut accumulate = |g: &mut ExprGraph, a: usize, b: usize, value: ExprId| {
        let (i, j) = (a.min(b), a.max(b));
        m[i][j] = g.add(m[i][j], value);
    };
    for (i, body) in bodies.iter().enumerate().rev() {
        if let Some(p) = body.parent {
            let up = composite_up(g, body, &composite[i]);
            let parent = &composite[p];
            composite[p] = Inertia {
                mass: g.add(parent.mass, up.mass),
                first_moment: add(g, parent.first_moment, up.first_moment),
                rotational: std::array::from_fn(|k| g.add(parent.rotational[k], up.rotational[k])),
            };
        }
        let one = g.constant(1.0);
        for (u, motion) in body.motions.iter().enumerate() {
            let s = direction(g, motion, one);
            let rate = g.constant(motion.rate);
            let mut f = inertia_times(g, &composite[i], s);
            // The body's own motions: each ordered pair once (the triangle's diagonal twice over
            // for two motions of one velocity).
            for other in &body.motions[u..] {
                let value = project(g, other, f);
                let value = g.mul(rate, value);
                accumulate(g, motion.column, other.column, value);
                if !std::ptr::eq(other, motion) && motion.column == other.column {
                    accumulate(g, motion.column, other.column, value);
                }
            }
            let mut at = i;
            while let Some(p) = bodies[at].parent {
                f = force_up(g, &bodies[at], f);
                at = p;
                for other in &bodies[at].motions {
                    let value = project(g, other, f);
                    let value = g.mul(rate, value);
                    accumulate(g, motion.column, other.column, value);
                    if motion.column == other.column {
                        accumulate(g, motion.column, other.column, value);
                    }
                }
            }
        }
    }
    m
}

/// A body's composite inertia in its parent's frame (Featherstone §2.13, the parallel axes for
/// the first moment and the rotational inertia).
fn composite_up(g: &mut ExprGraph, body: &Body, inertia: &Inertia) -> Inertia {
    let t = &body.transform;
    let (m, p) = (inertia.mass, t.p);
    let h = mat_vec(g, &t.r, inertia.first_moment);
    let mp = scale(g, m, p);
    let first_moment = add(g, h, mp);
    let turned: Sym3 = rotate_sym(g, &t.r, &inertia.rotational);
    // I' = R I R^T + m (|p|^2 1 - p p^T) + 2 (p . h) 1 - (p h^T + h p^T), h = R h_body.
    let p2 = dot(g, p, p);
    let ph = dot(g, p, h);
    let two = g.constant(2.0);
    let two_ph = g.mul(two, ph);
    let mut rotational = turned;
    for i in 0..3 {
        for j in i..3 {
            let k = sym_index(i, j);
            let pp = g.mul(p[i], p[j]);
            let mut entry = if i == j { g.sub(p2, pp) } else { g.neg(pp) };
            entry = g.mul(m, entry);
            if i == j {
                entry = g.add(entry, two_ph);
            }
            let (a, b) = (g.mul(p[i], h[j]), g.mul(h[i], p[j]));
            let cross_terms = g.add(a, b);
            entry = g.sub(entry, cross_terms);
            rotational[k] = g.add(rotational[k], entry);
        }
    }
    Inertia { mass: m, first_moment, rotational }
}

/// The gravity torques with every body's first moment in the root's axes: a joint moving its
/// subtree about the axis `z` through its origin (or along `w`) holds it against `z . (D x a)` (or
/// `w . (M a)`), the derivative of the potential energy, where `M` is the subtree's mass, `D` its
/// first moment about the joint's origin in the root's axes and `a = -g`. With `R` the body's
/// orientation in the root's frame, `D = R (h + sum_c M_c p_c) + sum_c D_c` over its children
/// `c` (at `p_c` in its frame). Each `R` comes from the body's whole path through the chain
/// passes, so parallel axes give angle sums (`m2 g l2 cos(q1 + q2)`, as a textbook writes a planar
/// arm), which the recursion in each body's own axes ([`gravity`]) writes as products of the
/// joints' sines and cosines.
pub(super) fn gravity_from_root(
    g: &mut ExprGraph,
    bodies: &[Body],
    velocities: usize,
    gravity: [f64; 3],
) -> Vec<ExprId> {
    let a = algebra::constant(g, gravity.map(|x| -x));
    let zero = g.constant(0.0);
    let turns: Vec<_> = (0..bodies.len()).map(|i| super::bodies::pose_in_root(g, bodies, i).r).collect();
    let mut mass: Vec<ExprId> = bodies.iter().map(|b| b.inertia.map_or(zero, |i| i.mass)).collect();
    // Per body: its own first moment plus its children's masses at their origins, in its axes
    // (then turned into the root's), and its children's moments already in the root's axes.
    let mut own: Vec<Vec3> = bodies.iter().map(|b| b.inertia.map_or([zero; 3], |i| i.first_moment)).collect();
    let mut below: Vec<Vec3> = vec![[zero; 3]; bodies.len()];
    let mut tau = vec![zero; velocities];
    for (i, body) in bodies.iter().enumerate().rev() {
        let turned = mat_vec(g, &turns[i], own[i]);
        let moment = add(g, turned, below[i]);
        let torque = cross(g, moment, a);
        let weight = scale(g, mass[i], a);
        for motion in &body.motions {
            let z = algebra::constant(g, motion.angular.map(|x| x * motion.rate));
            let w = algebra::constant(g, motion.linear.map(|x| x * motion.rate));
            let (z, w) = (mat_vec(g, &turns[i], z), mat_vec(g, &turns[i], w));
            let (turning, sliding) = (dot(g, z, torque), dot(g, w, weight));
            let t = g.add(turning, sliding);
            tau[motion.column] = g.add(tau[motion.column], t);
        }
        if let Some(p) = body.parent {
            let carried = scale(g, mass[i], body.transform.p);
            own[p] = add(g, own[p], carried);
            below[p] = add(g, below[p], moment);
            mass[p] = g.add(mass[p], mass[i]);
        }
    }
    tau
}
