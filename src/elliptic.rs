//! Complete elliptic integrals and Jacobi elliptic functions, by the arithmetic–geometric mean.
//!
//! The large-amplitude pendulum (4.24) and the torque-free asymmetric top both have closed-form
//! solutions in these functions. They are computed here from their mathematical definitions so
//! that the reference solutions used to judge the integrators owe nothing to an integrator.
//!
//! The parameter is `m = k²` throughout (Abramowitz & Stegun, ch. 16–17).

use thiserror::Error;

/// A parameter outside the domain where the functions are real and finite.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
pub enum EllipticError {
    /// `m` must satisfy `0 ≤ m < 1` (at `m = 1`, K is infinite).
    #[error("elliptic parameter m = {m} is outside [0, 1)")]
    ParameterOutOfRange {
        /// The offending parameter.
        m: f64,
    },
}

/// Iterations of the AGM: convergence is quadratic, so 1e-16 is reached in well under 10 steps
/// for any `m < 1 − 1e-300`; the cap only guards against a NaN slipping through.
const MAX_AGM_STEPS: usize = 64;

fn check_parameter(m: f64) -> Result<(), EllipticError> {
    if (0.0..1.0).contains(&m) {
        Ok(())
    } else {
        Err(EllipticError::ParameterOutOfRange { m })
    }
}

/// The complete elliptic integral of the first kind, K(m) = ∫₀^{π/2} dθ / √(1 − m sin²θ),
/// computed as π / (2 · AGM(1, √(1 − m))).
///
/// ```
/// let k = eom::elliptic::complete_k(0.0).unwrap();
/// assert!((k - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// ```
pub fn complete_k(m: f64) -> Result<f64, EllipticError> {
    check_parameter(m)?;
    let (mut a, mut b) = (1.0_f64, (1.0 - m).sqrt());
    for _ in 0..MAX_AGM_STEPS {
        if (a - b).abs() <= f64::EPSILON * a {
            break;
        }
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    Ok(std::f64::consts::FRAC_PI_2 / a)
}

/// Values of the Jacobi elliptic functions at one argument.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jacobi {
    /// sn(u | m)
    pub sn: f64,
    /// cn(u | m)
    pub cn: f64,
    /// dn(u | m)
    pub dn: f64,
    /// The amplitude am(u | m), with sn = sin(am) and cn = cos(am).
    pub am: f64,
}

/// sn, cn, dn and am of `u` for parameter `m`, by the descending AGM (A&S 16.4.3).
///
/// ```
/// let j = eom::elliptic::jacobi(0.3, 0.0).unwrap();
/// assert!((j.sn - 0.3_f64.sin()).abs() < 1e-15 && (j.dn - 1.0).abs() < 1e-15);
/// ```
pub fn jacobi(u: f64, m: f64) -> Result<Jacobi, EllipticError> {
    check_parameter(m)?;
    // The AGM sequences a_i, c_i, kept on the stack: a reference solution is evaluated at
    // every output time of a long run, so it should not allocate.
    let mut a = [0.0_f64; MAX_AGM_STEPS];
    let mut c = [0.0_f64; MAX_AGM_STEPS];
    (a[0], c[0]) = (1.0, m.sqrt());
    let mut b = (1.0 - m).sqrt();
    let mut n = 0;
    while n + 1 < MAX_AGM_STEPS && c[n].abs() > f64::EPSILON * a[n] {
        let (an, bn) = (a[n], b);
        n += 1;
        a[n] = 0.5 * (an + bn);
        c[n] = 0.5 * (an - bn);
        b = (an * bn).sqrt();
    }
    let mut phi = 2f64.powi(n as i32) * a[n] * u;
    for i in (1..=n).rev() {
        phi = 0.5 * (phi + (c[i] / a[i] * phi.sin()).asin());
    }
    let (sn, cn) = phi.sin_cos();
    let dn = (1.0 - m * sn * sn).sqrt();
    Ok(Jacobi {
        sn,
        cn,
        dn,
        am: phi,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    // Tolerances: both algorithms converge to round-off; 1e-14 absolute allows a few ulps of
    // accumulated error in values of order one.
    const TOL: f64 = 1e-14;

    #[test]
    fn complete_k_matches_tabulated_value_at_half() {
        // A&S table 17.1: K(0.5) = 1.854074677301372.
        assert!((complete_k(0.5).unwrap() - 1.854_074_677_301_372).abs() < TOL);
    }

    #[test]
    fn complete_k_rejects_parameter_one_and_nan() {
        assert!(complete_k(1.0).is_err());
        assert!(complete_k(f64::NAN).is_err());
        assert!(complete_k(-0.1).is_err());
    }

    #[test]
    fn jacobi_functions_satisfy_their_identities() {
        for &m in &[0.0, 0.1, 0.5, 0.9, 0.999] {
            for i in 0..20 {
                let u = -3.0 + 0.37 * i as f64;
                let j = jacobi(u, m).unwrap();
                assert!((j.sn * j.sn + j.cn * j.cn - 1.0).abs() < TOL);
                assert!((j.dn * j.dn + m * j.sn * j.sn - 1.0).abs() < TOL);
            }
        }
    }

    #[test]
    fn jacobi_sn_reaches_one_at_quarter_period() {
        for &m in &[0.2, 0.7, 0.95] {
            let j = jacobi(complete_k(m).unwrap(), m).unwrap();
            assert!((j.sn - 1.0).abs() < 1e-12 && j.cn.abs() < 1e-7);
        }
    }

    #[test]
    fn jacobi_derivative_matches_cn_dn() {
        // d sn / du = cn dn, checked by a central difference (step 1e-5, error O(h²) ≈ 1e-10).
        let (m, u, h) = (0.6, 0.8, 1e-5);
        let d = (jacobi(u + h, m).unwrap().sn - jacobi(u - h, m).unwrap().sn) / (2.0 * h);
        let j = jacobi(u, m).unwrap();
        assert!((d - j.cn * j.dn).abs() < 1e-9);
    }
}
