//! An MMG ship as its model runs it: the propeller's and the rudder's loads, which the proved
//! program of 4.46 reads as applied loads (`eom_codegen::model::ship`, the MMG form), with
//! their exact derivatives for its Jacobians, and the propeller rate that balances the
//! approach.
//!
//! The hull's forces are in the proved program (a polynomial in v′ and r′ on U²); what is
//! not a polynomial — the wake law's exp(−C₁|β_P|), the open-water curve at J, the race's
//! square roots, the rudder's angle of attack through atan2 — is [`MmgParameters::forces_of`],
//! evaluated here in f64 for the loads and in dual numbers (`num_dual`, five derivatives:
//! u, v, r, δ, n) for their derivatives, one definition for both.
//!
//! **Where the model is not smooth.** C₂ and γ_R change with the sign of β_P and β_R; at
//! β_P = 0 the wake law has a kink (|β_P|) and at β_R = 0 the rudder's inflow across changes
//! its slope (γ_R⁺ against γ_R⁻). The derivatives given at a branch's edge are those of the
//! branch the paper assigns the edge to (β ≥ 0: C₂⁺, γ_R⁺, the derivative of |β_P| taken as
//! +1), the one-sided derivatives toward β > 0, i.e. toward v < 0 (the midship moving to
//! port). On the straight course v = r = 0 both edges are met at once;
//! [`MmgShip::loads_with_derivatives_toward`] with [`Edge::TowardNegative`] gives the other
//! one-sided derivatives there, a small turn to port's (the ship's two linear models,
//! [`crate::kinds::ship::linear::LinearModel::mmg`]).

use num_dual::DualSVec64;

use super::forces::{Controls, Edge, MidshipState, MmgStateError, Real, check_domain};
use super::parameters::MmgParameters;
use crate::kinds::ship::ShipError;

/// The variables the applied loads are differentiated by, in order: u, v (m/s), r (rad/s),
/// δ (rad, positive to starboard), n (rev/s).
pub const BY: [&str; 5] = ["u", "v", "r", "delta", "n"];

/// An MMG ship: its parameters, the rate that balances the approach and the rate its
/// propeller is held at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MmgShip {
    /// The hull's, the propeller's and the rudder's parameters.
    pub parameters: MmgParameters,
    /// U₀, m/s: the approach speed.
    pub approach_speed: f64,
    /// n₀, rev/s: the propeller rate at which X = 0 on the straight course at U₀ with the
    /// rudder amidships ([`balancing_rate`]).
    pub balancing_rate: f64,
    /// The rate the propeller is held at from the approach on, rev/s: n₀ unless the scene
    /// gives another (a model test's measured rate, a public code's), at which the approach
    /// is not steady ([`MmgShip::approach_surge`] says how far).
    pub approach_rate: f64,
}

/// The propeller's and the rudder's X, Y, N about midship and their derivatives by
/// [`BY`]: `by[load][variable]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AppliedLoads {
    /// X_P + X_R, Y_R, N_R: N, N, N m.
    pub loads: [f64; 3],
    /// ∂(X_P + X_R, Y_R, N_R)/∂(u, v, r, δ, n).
    pub by: [[f64; 5]; 3],
}

impl MmgShip {
    /// The ship with the rate that balances the approach at `approach_speed` solved, its
    /// propeller held at `held` or, by default, at that rate.
    pub fn new(
        parameters: MmgParameters,
        approach_speed: f64,
        held: Option<f64>,
    ) -> Result<Self, ShipError> {
        let balancing = balancing_rate(&parameters, approach_speed)?;
        Ok(MmgShip {
            parameters,
            approach_speed,
            balancing_rate: balancing,
            approach_rate: held.unwrap_or(balancing),
        })
    }

    /// X on the straight course at U₀, the rudder amidships, the propeller at the held rate,
    /// N: zero to rounding at the balancing rate, else what accelerates (X > 0) or slows the
    /// ship from its approach.
    pub fn approach_surge(&self) -> f64 {
        let state = MidshipState {
            u: self.approach_speed,
            v_m: 0.0,
            r: 0.0,
        };
        let controls = Controls {
            rudder_angle: 0.0,
            propeller_rate: self.approach_rate,
        };
        let forces = self.parameters.forces(state, controls);
        forces.map_or(f64::NAN, |forces| forces.total.x)
    }

    /// X_P + X_R, Y_R, N_R at (u, v, r, δ, n), or why the paper's model has none there.
    pub fn loads(&self, at: [f64; 5]) -> Result<[f64; 3], MmgStateError> {
        let [u, v_m, r, rudder_angle, propeller_rate] = at;
        let controls = Controls {
            rudder_angle,
            propeller_rate,
        };
        check_domain(MidshipState { u, v_m, r }, controls)?;
        self.applied(at, Edge::TowardPositive)
    }

    /// X_P + X_R, Y_R, N_R in any [`Real`], the domain checked by the caller: the propeller
    /// and the rudder alone, the hull's forces being the proved program's own.
    fn applied<D: Real>(&self, at: [D; 5], edge: Edge) -> Result<[D; 3], MmgStateError> {
        let (_, p, r) = self.parameters.propeller_and_rudder_of(at, edge)?;
        Ok([p.surge + r.loads.x, r.loads.y, r.loads.n])
    }

    /// [`MmgShip::loads`] and their derivatives (module docs for the branches' edges).
    pub fn loads_with_derivatives(&self, at: [f64; 5]) -> Result<AppliedLoads, MmgStateError> {
        self.loads_with_derivatives_toward(at, Edge::TowardPositive)
    }

    /// [`MmgShip::loads_with_derivatives`], an inflow angle of exactly zero taken on the side
    /// `edge` says: [`Edge::TowardNegative`] gives the other one-sided derivatives there.
    pub fn loads_with_derivatives_toward(
        &self,
        at: [f64; 5],
        edge: Edge,
    ) -> Result<AppliedLoads, MmgStateError> {
        let loads = self.loads(at)?;
        let seeded: [DualSVec64<5>; 5] =
            std::array::from_fn(|i| DualSVec64::from_re(at[i]).derivative(i));
        let by = self.applied(seeded, edge)?.map(|load| {
            let gradient = load.eps.unwrap_generic(nalgebra::Const::<5>, nalgebra::U1);
            std::array::from_fn(|i| gradient[i])
        });
        Ok(AppliedLoads { loads, by })
    }
}

/// n₀ > 0 at which the propeller's X_P balances the hull's resistance on the straight course
/// at U₀, rudder amidships (X_R = 0 there: α_R = 0): with a = U₀(1 − w_P0)/D_P, J = a/n and
/// n²K_T(J) = k₀n² + k₁an + k₂a², so that
///
/// ```text
/// (1 − t_P)ρD_P⁴(k₀n² + k₁an + k₂a²) = ½ρLdU₀²R′₀,
/// ```
///
/// a quadratic in n whose positive root is taken (k₀ > 0 for a propeller that pushes at
/// J = 0). The SIMMAN setup asks for exactly this: the rate that holds the approach speed.
pub fn balancing_rate(parameters: &MmgParameters, speed: f64) -> Result<f64, ShipError> {
    let (ship, p) = (&parameters.particulars, &parameters.propeller);
    let invalid = |reason: String| ShipError::invalid("hydrodynamics.design_speed", reason);
    let ahead = speed > 0.0 && speed.is_finite();
    if !ahead {
        return Err(invalid(format!(
            "the approach speed {speed} m/s must be positive: the MMG model is for a ship moving ahead"
        )));
    }
    let diameter = ship.propeller_diameter;
    let advance = speed * (1.0 - p.straight_wake) / diameter;
    let [k0, k1, k2] = p.thrust_curve;
    let thrust = (1.0 - p.thrust_deduction) * ship.density * diameter.powi(4);
    let resistance = 0.5 * ship.density * ship.length * ship.draft * speed * speed;
    // thrust (k₀ n² + k₁ a n + k₂ a²) − resistance R′₀ = 0.
    let (a, b, c) = (
        thrust * k0,
        thrust * k1 * advance,
        thrust * k2 * advance * advance - resistance * parameters.hull.resistance,
    );
    let discriminant = b * b - 4.0 * a * c;
    // Written so that a NaN (a coefficient that is not a number) is refused too.
    let solvable = a > 0.0 && discriminant >= 0.0;
    if !solvable {
        return Err(invalid(format!(
            "no propeller rate balances the resistance at {speed} m/s: (1 − t_P)ρD_P⁴ k₀ = {a:e} \
             must be positive and the balance's discriminant {discriminant:e} non-negative"
        )));
    }
    // The larger root, without cancellation: q = −(b + sign(b)√Δ)/2, n = q/a or c/q.
    let q = -0.5 * (b + b.signum() * discriminant.sqrt());
    let rate = if b <= 0.0 { q / a } else { c / q };
    let turning_ahead = rate > 0.0 && rate.is_finite();
    if !turning_ahead {
        return Err(invalid(format!(
            "the propeller rate that balances the resistance at {speed} m/s is {rate} rev/s, \
             not ahead"
        )));
    }
    Ok(rate)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kvlcc2(scale: &str) -> MmgParameters {
        let text = include_str!("../../../../data/kvlcc2_mmg.json");
        let document: serde_json::Value = serde_json::from_str(text).unwrap();
        MmgParameters::from_json(&document, scale, 1025.0).unwrap()
    }

    /// At the balancing rate the whole ship's X on the straight course is zero, to the
    /// rounding of the forces it sums (1e-12 of the thrust).
    #[test]
    fn the_balancing_rate_holds_the_approach_speed() {
        for (scale, speed) in [("L7", 1.179), ("full", 7.97)] {
            let parameters = kvlcc2(scale);
            let ship = MmgShip::new(parameters, speed, None).unwrap();
            let forces = parameters
                .forces(
                    MidshipState {
                        u: speed,
                        v_m: 0.0,
                        r: 0.0,
                    },
                    Controls {
                        rudder_angle: 0.0,
                        propeller_rate: ship.approach_rate,
                    },
                )
                .unwrap();
            let thrust = forces.propeller.thrust;
            assert_eq!(ship.approach_surge(), forces.total.x);
            assert!(
                forces.total.x.abs() <= 1e-12 * thrust,
                "{scale}: X = {} at n₀ = {}",
                forces.total.x,
                ship.approach_rate
            );
        }
    }

    /// The dual numbers' derivatives against central differences, away from the branches'
    /// edges (β_P, β_R ≠ 0), at relative 1e-6 (the differences' own truncation at h = 1e-6
    /// of each variable's scale).
    #[test]
    fn the_derivatives_are_those_of_the_loads() {
        let ship = MmgShip::new(kvlcc2("L7"), 1.179, None).unwrap();
        for at in [
            [1.0, -0.1, 0.02, 0.3, 10.0],
            [0.9, 0.2, -0.05, -0.5, 9.0],
            [1.1, 0.15, 0.02, 0.17, 10.0],
        ] {
            let exact = ship.loads_with_derivatives(at).unwrap();
            assert_eq!(exact.loads, ship.loads(at).unwrap());
            for variable in 0..5 {
                let h = 1e-6 * at[variable].abs().max(1e-2);
                let shifted = |sign: f64| {
                    let mut x = at;
                    x[variable] += sign * h;
                    ship.loads(x).unwrap()
                };
                let (up, down) = (shifted(1.0), shifted(-1.0));
                for load in 0..3 {
                    let central = (up[load] - down[load]) / (2.0 * h);
                    let scale = exact.by[load].iter().map(|d| d.abs()).fold(1e-9, f64::max);
                    let error = (exact.by[load][variable] - central).abs();
                    assert!(
                        error <= 1e-6 * scale,
                        "∂load{load}/∂{}: {} against {central}",
                        BY[variable],
                        exact.by[load][variable]
                    );
                }
            }
        }
    }

    #[test]
    fn an_approach_the_propeller_cannot_hold_is_refused() {
        let mut parameters = kvlcc2("L7");
        parameters.propeller.thrust_curve = [-0.1, 0.0, 0.0];
        let error = MmgShip::new(parameters, 1.179, None)
            .unwrap_err()
            .to_string();
        assert!(error.contains("no propeller rate balances"), "{error}");
        let error = MmgShip::new(kvlcc2("L7"), 0.0, None)
            .unwrap_err()
            .to_string();
        assert!(error.contains("must be positive"), "{error}");
    }
}
