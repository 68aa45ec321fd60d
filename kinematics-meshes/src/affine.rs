//! The affine maps a Collada scene places its geometry by (`<matrix>`, `<translate>`, `<rotate>`,
//! `<scale>`, `<lookat>`, the unit), in `f64`.

use std::ops::Mul;

/// An affine map of points: the top three rows of a 4x4 matrix acting on column vectors (the
/// bottom row is `0 0 0 1`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Affine([[f64; 4]; 3]);

impl Affine {
    pub(crate) const IDENTITY: Affine = Affine([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]);

    /// Collada's `<matrix>`: 16 numbers, row by row. The bottom row is dropped: a projective node
    /// transform has no meaning for a mesh.
    pub(crate) fn from_rows(m: &[f64; 16]) -> Affine {
        Affine([[m[0], m[1], m[2], m[3]], [m[4], m[5], m[6], m[7]], [m[8], m[9], m[10], m[11]]])
    }

    pub(crate) fn translation(t: [f64; 3]) -> Affine {
        let mut a = Affine::IDENTITY;
        (0..3).for_each(|i| a.0[i][3] = t[i]);
        a
    }

    pub(crate) fn scale(s: [f64; 3]) -> Affine {
        let mut a = Affine::IDENTITY;
        (0..3).for_each(|i| a.0[i][i] = s[i]);
        a
    }

    /// Rotation by `degrees` about `axis` (right-handed; the axis need not be of unit length);
    /// `None` for a zero axis.
    pub(crate) fn rotation(axis: [f64; 3], degrees: f64) -> Option<Affine> {
        let [x, y, z] = unit(axis)?;
        let (s, c) = degrees.to_radians().sin_cos();
        let t = 1.0 - c;
        Some(Affine([
            [t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0.0],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0.0],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0.0],
        ]))
    }

    /// Collada's `<lookat>`: the node at `eye`, its -z towards `interest`, its y as near `up` as
    /// is square to that; `None` when the direction is zero or along `up`.
    pub(crate) fn look_at(eye: [f64; 3], interest: [f64; 3], up: [f64; 3]) -> Option<Affine> {
        let dir = unit(sub(interest, eye))?;
        let right = unit(cross(dir, up))?;
        // Square to both, unlike the `up` as written.
        let up = cross(right, dir);
        let back = dir.map(|c| -c);
        Some(Affine([
            [right[0], up[0], back[0], eye[0]],
            [right[1], up[1], back[1], eye[1]],
            [right[2], up[2], back[2], eye[2]],
        ]))
    }

    pub(crate) fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        self.0.map(|r| r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3])
    }

    /// The determinant of the linear part: negative for a mirroring map, which turns a triangle's
    /// winding (and so which side is inside) over.
    pub(crate) fn determinant(&self) -> f64 {
        let [a, b, c] = self.0.map(|r| [r[0], r[1], r[2]]);
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    }
}

impl Mul for Affine {
    type Output = Affine;

    /// `self` after `rhs`: `(a * b).apply(p) == a.apply(b.apply(p))`.
    fn mul(self, rhs: Affine) -> Affine {
        let (a, b) = (self.0, rhs.0);
        Affine(std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let translation = if j == 3 { a[i][3] } else { 0.0 };
                a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + translation
            })
        }))
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn norm(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

fn unit(a: [f64; 3]) -> Option<[f64; 3]> {
    let n = norm(a);
    (n > 0.0 && n.is_finite()).then(|| a.map(|c| c / n))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: [f64; 3], b: [f64; 3]) -> bool {
        (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
    }

    #[test]
    fn composition_applies_the_right_factor_first() {
        let t = Affine::translation([1.0, 0.0, 0.0]);
        let s = Affine::scale([2.0, 2.0, 2.0]);
        // Scale after translate: the translation is scaled too.
        assert!(close((s * t).apply([0.0, 0.0, 0.0]), [2.0, 0.0, 0.0]));
        assert!(close((t * s).apply([1.0, 0.0, 0.0]), [3.0, 0.0, 0.0]));
    }

    #[test]
    fn rotation_is_right_handed_in_degrees() {
        let r = Affine::rotation([0.0, 0.0, 2.0], 90.0).unwrap();
        assert!(close(r.apply([1.0, 0.0, 0.0]), [0.0, 1.0, 0.0]));
        assert!((r.determinant() - 1.0).abs() < 1e-12);
        assert!(Affine::rotation([0.0; 3], 90.0).is_none());
    }

    #[test]
    fn look_at_points_minus_z_at_the_interest() {
        let m = Affine::look_at([1.0, 2.0, 3.0], [1.0, 2.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
        assert!(close(m.apply([0.0, 0.0, -3.0]), [1.0, 2.0, 0.0]));
        assert!((m.determinant() - 1.0).abs() < 1e-12);
        assert!(Affine::look_at([0.0; 3], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0]).is_none());
    }

    #[test]
    fn a_mirror_has_a_negative_determinant() {
        assert!(Affine::scale([-1.0, 1.0, 1.0]).determinant() < 0.0);
        assert_eq!(
            Affine::from_rows(&[1., 0., 0., 5., 0., 1., 0., 6., 0., 0., 1., 7., 0., 0., 0., 1.]).apply([0.0; 3]),
            [5.0, 6.0, 7.0]
        );
    }
}
