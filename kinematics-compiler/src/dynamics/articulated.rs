//! Forward dynamics by the articulated-body algorithm (Featherstone, *Rigid Body Dynamics
//! Algorithms*, 2008, Table 7.1), written over the bodies symbolically: the other way to forward
//! dynamics beside the mass matrix's factorisation (`solve`), the cheaper of the two kept.
//!
//! It applies where every body moves along one direction with a velocity of its own (revolute,
//! prismatic and planar joints, no mimic joint: a mimic's body shares its source's velocity, which
//! the recursion cannot split, and a floating or spherical joint's several directions would need a
//! small matrix inverted per body). Each body's articulated inertia is a symmetric 6 x 6 matrix of
//! nodes, angular rows first; zeros fold as the nodes are built, so a massless body or an axis along
//! `z` costs what it must. The pivots `D_i = S_i^T I^A_i S_i` are outputs, as the factorisation's
//! are: a vanished one is a velocity that moves no mass.

use super::algebra;
use super::bodies::{Body, Inertia};
use super::recursive::{
    External, Spatial, cross_force, cross_motion, direction, force_out_of, force_up, inertia_times, joint_motion,
    motion_down,
};
use crate::symbolic::graph::{ExprGraph, ExprId};

/// A spatial vector as six nodes, angular part first.
type Vec6 = [ExprId; 6];

/// A symmetric 6 x 6 matrix, every entry held (`m[i][j]` and `m[j][i]` the same node).
type Sym6 = [[ExprId; 6]; 6];

fn flat(s: Spatial) -> Vec6 {
    [s.angular[0], s.angular[1], s.angular[2], s.linear[0], s.linear[1], s.linear[2]]
}

fn spatial(v: Vec6) -> Spatial {
    Spatial { angular: [v[0], v[1], v[2]], linear: [v[3], v[4], v[5]] }
}

fn dot6(g: &mut ExprGraph, a: &Vec6, b: &Vec6) -> ExprId {
    let mut sum = g.constant(0.0);
    for (&x, &y) in a.iter().zip(b) {
        let t = g.mul(x, y);
        sum = g.add(sum, t);
    }
    sum
}

fn times(g: &mut ExprGraph, m: &Sym6, v: &Vec6) -> Vec6 {
    std::array::from_fn(|i| dot6(g, &m[i], v))
}

/// A rigid body's spatial inertia about the body's origin: `[[I, h x], [(h x)^T, m 1]]`.
fn rigid(g: &mut ExprGraph, inertia: Option<&Inertia>) -> Sym6 {
    let zero = g.constant(0.0);
    let mut m = [[zero; 6]; 6];
    let Some(inertia) = inertia else { return m };
    for (i, row) in m.iter_mut().enumerate().take(3) {
        for (j, entry) in row.iter_mut().enumerate().take(3) {
            *entry = inertia.rotational[algebra::sym_index(i, j)];
        }
    }
    for (i, row) in m.iter_mut().enumerate().skip(3) {
        row[i] = inertia.mass;
    }
    let h = inertia.first_moment;
    // (h x) a = h x a: rows of the skew matrix of h.
    let skew: [[Option<(usize, bool)>; 3]; 3] = [
        [None, Some((2, false)), Some((1, true))],
        [Some((2, true)), None, Some((0, false))],
        [Some((1, false)), Some((0, true)), None],
    ];
    for i in 0..3 {
        for j in 0..3 {
            if let Some((k, positive)) = skew[i][j] {
                let entry = if positive { h[k] } else { g.neg(h[k]) };
                m[i][3 + j] = entry;
                m[3 + j][i] = entry;
            }
        }
    }
    m
}

/// `X^T m X` for the motion transform `X` from `body`'s parent to `body`: an articulated inertia
/// in the body's frame carried to its parent's (the upper triangle computed, mirrored).
fn carried_up(g: &mut ExprGraph, body: &Body, m: &Sym6) -> Sym6 {
    let zero = g.constant(0.0);
    // X = [[R^T, 0], [-R^T [p]x, R^T]]: the columns of X are what a unit motion of the parent
    // is in the body's frame.
    let mut x = [[zero; 6]; 6];
    for c in 0..6 {
        let mut unit = [zero; 6];
        unit[c] = g.constant(1.0);
        let column = flat(motion_down(g, body, spatial(unit)));
        for r in 0..6 {
            x[r][c] = column[r];
        }
    }
    // m X, then X^T (m X) on and above the diagonal.
    let mx: [[ExprId; 6]; 6] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let column: Vec6 = std::array::from_fn(|k| x[k][j]);
            dot6(g, &m[i], &column)
        })
    });
    let mut out = [[zero; 6]; 6];
    for i in 0..6 {
        for j in i..6 {
            let xi: Vec6 = std::array::from_fn(|k| x[k][i]);
            let mj: Vec6 = std::array::from_fn(|k| mx[k][j]);
            let entry = dot6(g, &xi, &mj);
            out[i][j] = entry;
            out[j][i] = entry;
        }
    }
    out
}

/// The accelerations and the pivots (one per velocity) of forward dynamics by the articulated-body
/// algorithm, or `None` where it does not apply (see the module's doc): `rates` are `qd`, `tau`
/// the generalized forces, `external` the forces on links.
pub(super) fn forward_dynamics(
    g: &mut ExprGraph,
    bodies: &[Body],
    velocities: usize,
    gravity: [f64; 3],
    rates: &dyn Fn(&mut ExprGraph, usize) -> Option<ExprId>,
    tau: &dyn Fn(&mut ExprGraph, usize) -> ExprId,
    external: &[External],
) -> Option<(Vec<ExprId>, Vec<ExprId>)> {
    let mut owner = vec![None; velocities];
    for (i, body) in bodies.iter().enumerate() {
        let [motion] = body.motions.as_slice() else { return None };
        if motion.rate != 1.0 || owner[motion.column].replace(i).is_some() {
            return None;
        }
    }
    if owner.iter().any(Option::is_none) {
        return None;
    }
    let one = g.constant(1.0);
    // Out: velocities, velocity-product accelerations `c` and bias forces `p` (less the external
    // forces), each body's own inertia.
    let mut velocity: Vec<Spatial> = Vec::with_capacity(bodies.len());
    let mut bias: Vec<Spatial> = Vec::with_capacity(bodies.len());
    let mut force: Vec<Spatial> = Vec::with_capacity(bodies.len());
    let mut articulated: Vec<Sym6> = Vec::with_capacity(bodies.len());
    for body in bodies {
        let v_parent = match body.parent {
            None => Spatial::zero(g),
            Some(p) => velocity[p],
        };
        let v_joint = joint_motion(g, body, rates);
        let v_down = motion_down(g, body, v_parent);
        let v = v_down.add(g, v_joint);
        bias.push(cross_motion(g, v, v_joint));
        force.push(match &body.inertia {
            None => Spatial::zero(g),
            Some(inertia) => {
                let iv = inertia_times(g, inertia, v);
                cross_force(g, v, iv)
            }
        });
        articulated.push(rigid(g, body.inertia.as_ref()));
        velocity.push(v);
    }
    for e in external {
        let applied = Spatial { angular: e.moment, linear: e.force };
        let on_body = force_out_of(g, &e.frame, applied);
        force[e.body] = force[e.body].sub(g, on_body);
    }
    // In: each body's `U = I^A S`, pivot `D = S^T U` and `u = tau - S^T p^A`; what the joint
    // passes on to its parent.
    let n = bodies.len();
    let (mut u_vectors, mut reciprocal, mut u_forces) = (Vec::with_capacity(n), vec![one; n], vec![one; n]);
    let mut pivots = vec![one; velocities];
    for i in (0..n).rev() {
        let motion = bodies[i].motions[0];
        let s = flat(direction(g, &motion, one));
        let u_vector = times(g, &articulated[i], &s);
        let d = dot6(g, &s, &u_vector);
        pivots[motion.column] = d;
        reciprocal[i] = g.div(one, d);
        let sp = dot6(g, &s, &flat(force[i]));
        let t = tau(g, motion.column);
        u_forces[i] = g.sub(t, sp);
        if let Some(p) = bodies[i].parent {
            let w: Vec6 = u_vector.map(|x| g.mul(x, reciprocal[i]));
            let mut passed = articulated[i];
            for r in 0..6 {
                for c in r..6 {
                    let t = g.mul(w[r], u_vector[c]);
                    let entry = g.sub(passed[r][c], t);
                    passed[r][c] = entry;
                    passed[c][r] = entry;
                }
            }
            let ic = times(g, &passed, &flat(bias[i]));
            let wu = w.map(|x| g.mul(x, u_forces[i]));
            let pa: Vec6 = std::array::from_fn(|k| {
                let sum = g.add(flat(force[i])[k], ic[k]);
                g.add(sum, wu[k])
            });
            let up = carried_up(g, &bodies[i], &passed);
            for r in 0..6 {
                for c in r..6 {
                    let entry = g.add(articulated[p][r][c], up[r][c]);
                    articulated[p][r][c] = entry;
                    articulated[p][c][r] = entry;
                }
            }
            let pa_up = force_up(g, &bodies[i], spatial(pa));
            force[p] = force[p].add(g, pa_up);
        }
        u_vectors.push((i, u_vector));
    }
    u_vectors.reverse();
    // Out again: accelerations, gravity as the root's `-g`.
    let root = Spatial { angular: algebra::zero(g), linear: algebra::constant(g, gravity.map(|x| -x)) };
    let zero = g.constant(0.0);
    let mut qdd = vec![zero; velocities];
    let mut acceleration: Vec<Spatial> = Vec::with_capacity(n);
    for (i, body) in bodies.iter().enumerate() {
        let a_parent = body.parent.map_or(root, |p| acceleration[p]);
        let down = motion_down(g, body, a_parent);
        let a_prime = down.add(g, bias[i]);
        let (_, u_vector) = &u_vectors[i];
        let ua = dot6(g, u_vector, &flat(a_prime));
        let numerator = g.sub(u_forces[i], ua);
        let motion = body.motions[0];
        let value = g.mul(numerator, reciprocal[i]);
        qdd[motion.column] = value;
        let along = direction(g, &motion, value);
        acceleration.push(a_prime.add(g, along));
    }
    Some((qdd, pivots))
}
