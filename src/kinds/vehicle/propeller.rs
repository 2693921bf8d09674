//! A vehicle's propeller as a law in its rate: Healey & Lienard's (1993) NPS AUV II as
//! Fossen's MSS `npsauv.m` gives it, in the prime system (U = u, ½ρL²):
//!
//! ```text
//! prop = a n/u                                   (n the shaft speed, rad/s; a = 0.012 m/rad)
//! X    = ½ρL² u² C_d0 (prop|prop| − 1)           (thrust and resistance)
//! ε    = −1 + sign(n)/sign(u) · (√(C_t + 1) − 1)/(√(C_t1 + 1) − 1),
//!        C_t = c L² prop|prop|/2, C_t1 = c L²/2  (c = 0.008)
//! ```
//!
//! For u > 0 and n > 0, the law's X is the thrust ½ρL²C_d0(a n)², constant in u, less the
//! resistance ½ρL²C_d0u², which the table holds as its own term (X_uu = −C_d0): the model
//! takes the thrust as the constant `X_prop` it is, and the cruise is u = a n (prop = 1).
//! ε is not a polynomial in u: it is computed here, beside the proved program, which reads
//! it as its input `n` (the factor the source's names give it: `Zqn` is u·q·ε), so each of
//! the source's terms in ε (Xqdsn, Xwdsn, Xdsdsn, Zqn, Zwn, Zdsn, Kpn, Mqn, Mwn, Mdsn) stays a
//! proved polynomial term. The model's Jacobian adds the chain rule ∂f/∂ε · ∂ε/∂u to the
//! column of u, with ∂ε/∂u written by hand below:
//!
//! ```text
//! ε  = −1 + (√(1 + k (a n/u)²) − 1)/(√(1 + k) − 1),             k = c L²/2
//! ∂ε/∂u = −k (a n)² / (u³ √(1 + k (a n/u)²) (√(1 + k) − 1))
//! ```
//!
//! The law is the source's for u > 0, a propeller turning ahead: the source's sign(n)/sign(u)
//! and its guards against dividing by zero (1e-10 added to u and to the denominator) are not
//! carried; at u ≤ 0 ε is not finite, and the run stops there on its guard against
//! non-finite values rather than go on with a law that does not hold.

use simba::simd::SimdRealField;
use std::f64::consts::PI;

/// The law's numbers, as the scene gives them ([`super::scene`]), with the prime system's L.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PropellerLaw {
    /// The propeller's rate, rpm.
    pub rpm: f64,
    /// a in prop = a n/u, m/rad: the speed per shaft speed at which thrust meets resistance.
    pub advance: f64,
    /// C_d0: the thrust ½ρL²C_d0(a n)² (and the resistance the table holds, X_uu = −C_d0).
    pub drag_coefficient: f64,
    /// c in C_t = c L² prop|prop|/2.
    pub thrust_coefficient: f64,
    /// ρ, kg/m³ (the prime system's).
    pub density: f64,
    /// L, m (the prime system's).
    pub length: f64,
}

/// ε and ∂ε/∂u at a surge speed.
#[derive(Debug, Clone, Copy)]
pub struct Epsilon<T> {
    /// ε.
    pub value: T,
    /// ∂ε/∂u, s/m.
    pub by_u: T,
}

impl PropellerLaw {
    /// n, the shaft speed, rad/s.
    pub fn shaft_speed(&self) -> f64 {
        self.rpm / 60.0 * 2.0 * PI
    }

    /// The cruise the law is made about: u = a n, where prop = 1 and ε = 0, m/s.
    pub fn cruise_speed(&self) -> f64 {
        self.advance * self.shaft_speed()
    }

    /// The thrust for u > 0, ½ρL²C_d0(a n)², N.
    pub fn thrust(&self) -> f64 {
        0.5 * self.density
            * self.length.powi(2)
            * self.drag_coefficient
            * self.cruise_speed().powi(2)
    }

    /// k = c L²/2: C_t = k prop|prop|.
    fn k(&self) -> f64 {
        self.thrust_coefficient * self.length * self.length / 2.0
    }

    /// ε and ∂ε/∂u at the surge speed `u` (see the module docs); not finite for u ≤ 0.
    pub fn epsilon<T: SimdRealField + Copy>(&self, u: T) -> Epsilon<T> {
        let value = |x: f64| T::from_subset(&x);
        let k = self.k();
        let one = value(1.0);
        let denominator = value((1.0 + k).sqrt() - 1.0);
        let speed = value(self.cruise_speed());
        let prop = speed / u;
        let root = (one + value(k) * prop * prop).simd_sqrt();
        // A surge speed not ahead: NaN, which the run's guard stops on.
        let ahead = u.simd_gt(T::zero());
        let nan = value(f64::NAN);
        Epsilon {
            value: (-one + (root - one) / denominator).select(ahead, nan),
            by_u: (-value(k) * speed * speed / (u * u * u * root * denominator)).select(ahead, nan),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_dual::Dual64;

    /// npsauv.m's law at SIMnpsauv.m's 1300 rpm.
    fn nps() -> PropellerLaw {
        PropellerLaw {
            rpm: 1300.0,
            advance: 0.012,
            drag_coefficient: 0.00385,
            thrust_coefficient: 0.008,
            density: 1025.0,
            length: 5.3,
        }
    }

    /// The source's ε as it writes it, for u > 0 and n > 0 (without its 1e-10 guards).
    fn source_epsilon(law: &PropellerLaw, u: f64) -> f64 {
        let prop = law.advance * law.shaft_speed() / u;
        let ct = law.thrust_coefficient * law.length.powi(2) * prop.abs() * prop / 2.0;
        let ct1 = law.thrust_coefficient * law.length.powi(2) / 2.0;
        -1.0 + ((ct + 1.0).sqrt() - 1.0) / ((ct1 + 1.0).sqrt() - 1.0)
    }

    #[test]
    fn epsilon_is_zero_at_the_cruise_and_the_source_s_elsewhere() {
        let law = nps();
        assert_eq!(law.epsilon(law.cruise_speed()).value, 0.0);
        for u in [0.3, 1.0, 1.39, 1.6, 2.5, 4.0] {
            let (ours, source) = (law.epsilon(u).value, source_epsilon(&law, u));
            // The same operations in another order: rounding of values of order one.
            assert!(
                (ours - source).abs() < 1e-14,
                "u = {u}: {ours} against {source}"
            );
        }
        // Slower than the cruise the propeller is loaded more: ε > 0.
        assert!(law.epsilon(1.39).value > 0.3);
        assert!(law.epsilon(0.0_f64).value.is_nan() && law.epsilon(-1.0_f64).by_u.is_nan());
    }

    /// ∂ε/∂u by hand against the dual number's, to rounding (1e-14 relative).
    #[test]
    fn the_derivative_of_epsilon_is_that_of_its_value() {
        let law = nps();
        for u in [0.3, 1.0, 1.39, 1.6336, 2.5, 4.0] {
            let dual = law.epsilon(Dual64::new(u, 1.0));
            let by_hand = law.epsilon(u).by_u;
            let relative = (by_hand - dual.value.eps) / dual.value.eps;
            assert!(
                relative.abs() < 1e-14,
                "u = {u}: {by_hand} against {}",
                dual.value.eps
            );
            assert_eq!(dual.value.re, law.epsilon(u).value);
        }
    }

    #[test]
    fn the_thrust_meets_the_resistance_at_the_cruise() {
        let law = nps();
        let u = law.cruise_speed();
        let resistance = 0.5 * law.density * law.length.powi(2) * law.drag_coefficient * u * u;
        assert!((law.thrust() - resistance).abs() <= 1e-14 * resistance);
        assert!((u - 1.6336281798666925).abs() < 1e-15);
    }
}
