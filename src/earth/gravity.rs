//! The Earth's gravitation: constant (the chapter's g), a point mass (GM/r²), or an oblate
//! Earth to J2, in the Earth-centred Earth-fixed frame.
//!
//! The J2 field is the gradient of U = (GM/r)(1 − J2 (a/r)² (3 sin²ψ − 1)/2), ψ the geocentric
//! latitude (sin ψ = Z/r):
//!
//! ```text
//! g_X = −(GM/r³) X [1 + (3/2) J2 (a/r)² (1 − 5 Z²/r²)]
//! g_Y = −(GM/r³) Y [1 + (3/2) J2 (a/r)² (1 − 5 Z²/r²)]
//! g_Z = −(GM/r³) Z [1 + (3/2) J2 (a/r)² (3 − 5 Z²/r²)]
//! ```
//!
//! (the Z term's 3 is where some public codes write 1). The centripetal acceleration of the
//! turning Earth is not gravitation and is not in it. `tests` holds the field to the gradient of
//! U by differences; `tests/earth_nesc.rs` its magnitude to the NESC tools' local gravity.

use super::Ecef;

/// A gravitational field.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Gravity {
    /// g, m/s², along −Z of the frame it is given in (the chapter's flat Earth, Z down: +g).
    Constant(f64),
    /// A point mass of GM, m³/s².
    InverseSquare {
        /// GM, m³/s².
        gm: f64,
    },
    /// An oblate Earth to J2.
    J2 {
        /// GM, m³/s².
        gm: f64,
        /// J2.
        j2: f64,
        /// a, the equatorial radius J2 is referred to, m.
        equatorial_radius: f64,
    },
}

impl Gravity {
    /// The gravitational acceleration at `position`, m/s², in ECEF axes; a constant field's
    /// is (0, 0, −g) whatever the position.
    pub fn at(&self, position: &Ecef) -> [f64; 3] {
        let [x, y, z] = position.0;
        let r2 = x * x + y * y + z * z;
        let r = r2.sqrt();
        match *self {
            Gravity::Constant(g) => [0.0, 0.0, -g],
            Gravity::InverseSquare { gm } => {
                let k = -gm / (r2 * r);
                [k * x, k * y, k * z]
            }
            Gravity::J2 {
                gm,
                j2,
                equatorial_radius,
            } => {
                let k = -gm / (r2 * r);
                let oblate = 1.5 * j2 * equatorial_radius * equatorial_radius / r2;
                let polar = 5.0 * z * z / r2;
                let across = k * (1.0 + oblate * (1.0 - polar));
                [
                    across * x,
                    across * y,
                    k * z * (1.0 + oblate * (3.0 - polar)),
                ]
            }
        }
    }

    /// The magnitude of [`Gravity::at`], m/s².
    pub fn magnitude(&self, position: &Ecef) -> f64 {
        let [a, b, c] = self.at(position);
        (a * a + b * b + c * c).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::earth::NESC;

    /// The J2 field is the gradient of its potential by central differences at 30 m (their
    /// error: h² U‴/6 ≈ 2e-10 m/s² from the step, ε U/h ≈ 2e-10 from rounding U ≈ 6e7 m²/s²),
    /// to 1e-8 m/s²; writing 1 for the Z term's 3 moves g_Z by about 0.03 m/s².
    #[test]
    fn the_j2_field_is_the_gradient_of_its_potential() {
        let (gm, j2, a) = (NESC.gm, NESC.j2, NESC.ellipsoid.equatorial_radius);
        let potential = |p: [f64; 3]| {
            let r = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
            let sin2 = p[2] * p[2] / (r * r);
            gm / r * (1.0 - j2 * (a / r).powi(2) * (3.0 * sin2 - 1.0) / 2.0)
        };
        let field = Gravity::J2 {
            gm,
            j2,
            equatorial_radius: a,
        };
        for p in [
            [6.4e6, 0.0, 0.0],
            [3.0e6, -2.0e6, 5.1e6],
            [0.0, 0.0, 6.36e6],
            [-4.2e6, 4.2e6, -3.3e6],
        ] {
            let g = field.at(&Ecef(p));
            for k in 0..3 {
                let (mut up, mut down) = (p, p);
                up[k] += 30.0;
                down[k] -= 30.0;
                let gradient = (potential(up) - potential(down)) / 60.0;
                assert!(
                    (g[k] - gradient).abs() < 1e-8,
                    "{p:?} {k}: {} {gradient}",
                    g[k]
                );
            }
        }
    }

    /// Without J2 the field is the point mass's, and a constant field is one vector.
    #[test]
    fn the_simpler_fields_are_what_they_say() {
        let p = Ecef([3.0e6, -2.0e6, 5.1e6]);
        let point = Gravity::InverseSquare { gm: NESC.gm }.at(&p);
        let no_j2 = Gravity::J2 {
            gm: NESC.gm,
            j2: 0.0,
            equatorial_radius: 6.4e6,
        }
        .at(&p);
        assert_eq!(point, no_j2);
        let r = p.radius();
        let magnitude = Gravity::InverseSquare { gm: NESC.gm }.magnitude(&p);
        assert!((magnitude - NESC.gm / (r * r)).abs() < 1e-14 * magnitude);
        assert_eq!(Gravity::Constant(9.81).at(&p), [0.0, 0.0, -9.81]);
    }
}
