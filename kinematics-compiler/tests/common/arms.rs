//! Random arms built to each closed-form family (random lengths, offsets and axis signs, written
//! as DH tables), and the run time's family functions that solve them.

use kinematics_compiler::ik::{IkGeometry, IkPlan, SixFamily};
use kinematics_core::Pose;
use kinematics_core::ik::IkSolutions;

/// splitmix64, uniform in [0, 1).
pub struct Uniform(pub u64);

impl Uniform {
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) as f64 / 2f64.powi(64)
    }

    fn length(&mut self) -> f64 {
        let magnitude = 0.05 + 0.5 * self.next();
        if self.next() < 0.5 { -magnitude } else { magnitude }
    }

    fn twist(&mut self) -> &'static str {
        if self.next() < 0.5 { "\"pi/2\"" } else { "\"-pi/2\"" }
    }
}

/// A standard DH table of six revolute rows `(a, d, alpha)`, `theta` offsets random.
fn table(rng: &mut Uniform, rows: [(f64, f64, &str); 6]) -> String {
    let mut text = "convention = \"standard\"\n".to_owned();
    for (i, (a, d, alpha)) in rows.iter().enumerate() {
        let theta = 2.0 * rng.next() - 1.0;
        text += &format!("[[joints]]\nname = \"j{}\"\na = {a}\nd = {d}\nalpha = {alpha}\ntheta = {theta}\n", i + 1);
    }
    text
}

pub fn random_arm(rng: &mut Uniform, family: SixFamily) -> String {
    let l: [f64; 12] = [0; 12].map(|_| rng.length());
    let t: [&str; 5] = [0; 5].map(|_| rng.twist());
    let rows = match family {
        // UR-like: axes 2, 3, 4 parallel, 5 and 6 meeting.
        SixFamily::ThreeParallelTwoIntersecting => [
            (0.0, l[0], t[0]),
            (l[1], 0.0, "0"),
            (l[2], 0.0, "0"),
            (0.0, l[3], t[3]),
            (0.0, l[4], t[4]),
            (0.0, l[5], "0"),
        ],
        // PUMA-like: an offset first axis, 2 and 3 parallel, a spherical wrist.
        SixFamily::SphericalTwoParallel => [
            (l[0], l[1], t[0]),
            (l[2], l[3], "0"),
            (l[4], l[5], t[2]),
            (0.0, l[6], t[3]),
            (0.0, 0.0, t[4]),
            (0.0, l[7], "0"),
        ],
        // Axes 1 and 2 meeting, 2 and 3 square, a spherical wrist.
        SixFamily::SphericalFirstTwoIntersecting => [
            (0.0, l[0], t[0]),
            (l[1], l[2], t[1]),
            (l[3], l[4], t[2]),
            (0.0, l[5], t[3]),
            (0.0, 0.0, t[4]),
            (0.0, l[6], "0"),
        ],
        // An offset first axis, 2 and 3 meeting, a spherical wrist.
        SixFamily::SphericalLastTwoIntersecting => [
            (l[0], l[1], t[0]),
            (0.0, l[2], t[1]),
            (l[3], l[4], t[2]),
            (0.0, l[5], t[3]),
            (0.0, 0.0, t[4]),
            (0.0, l[6], "0"),
        ],
        // Axes 1, 2, 3 skew (offsets along both common normals, one twist not square), a
        // spherical wrist.
        SixFamily::Spherical => [
            (l[0], l[1], t[0]),
            (l[2], l[3], "1.1"),
            (l[4], l[5], t[2]),
            (0.0, l[6], t[3]),
            (0.0, 0.0, t[4]),
            (0.0, l[7], "0"),
        ],
        // UR-like, but axes 5 and 6 apart (a common normal of length l[8]).
        SixFamily::ThreeParallel => [
            (0.0, l[0], t[0]),
            (l[1], 0.0, "0"),
            (l[2], 0.0, "0"),
            (0.0, l[3], t[3]),
            (l[8], l[4], t[4]),
            (0.0, l[5], "0"),
        ],
        SixFamily::SphericalPrismaticThird => panic!("a prismatic arm: tested in the core and on the Stanford arm"),
    };
    table(rng, rows)
}

pub fn solve(plan: &IkPlan, target: &Pose<f64>) -> IkSolutions<6, 8> {
    let IkGeometry::Six { family, arm: six, .. } = &plan.geometry else { panic!("not a six-joint family") };
    let arm = six.arm();
    (family.facts().solver.function)(&arm, target)
}

pub fn wrapped(x: f64) -> f64 {
    let tau = std::f64::consts::TAU;
    x - tau * (x / tau).round()
}
