//! Ships as the MMG standard method models them: the forces of the hull, the propeller and the
//! rudder at a state, each quantity on the way kept.
//!
//! H. Yasukawa and Y. Yoshimura (2015), "Introduction of MMG standard method for ship
//! maneuvering predictions", *J. Mar. Sci. Technol.* 20:37–52, doi:10.1007/s00773-014-0293-y.
//!
//! **Why the forces are split.** A polynomial table (Abkowitz's, the Mariner's) fits the
//! whole ship's forces at once in captive tests, so a term cannot be traced to a part and a
//! change of propeller or rudder means new tests of everything. The MMG method ("modular")
//! writes each part's force from its own tests and physics: the hull's from oblique towing
//! and circular motion tests without rudder and propeller (H), the propeller's thrust from its
//! open-water curve at the advance ratio the hull's wake gives it (P), and the rudder's
//! normal force from its lift gradient at the inflow the propeller's race and the hull's
//! flow-straightening give it (R). What couples the parts is carried by a few interaction
//! coefficients (t_P, w_P, t_R, a_H, x_H, ε, κ, γ_R, l_R), measured in rudder-angle and
//! oblique tests with everything fitted. X = X_H + X_P + X_R, Y = Y_H + Y_R, N = N_H + N_R,
//! about midship.
//!
//! **What is implemented** (the paper's symbols; SI units):
//!
//! ```text
//! U = √(u² + v_m²),  β = atan2(−v_m, u),  v′ = v_m/U,  r′ = rL/U
//! hull:       X_H = ½ρLdU² (−R′₀ + X′_vv v′² + X′_vr v′r′ + X′_rr r′² + X′_vvvv v′⁴)
//!             Y_H = ½ρLdU² (Y′_v v′ + Y′_r r′ + Y′_vvv v′³ + Y′_vvr v′²r′ + Y′_vrr v′r′² + Y′_rrr r′³)
//!             N_H = ½ρL²dU² (N′_v v′ + N′_r r′ + N′_vvv v′³ + N′_vvr v′²r′ + N′_vrr v′r′² + N′_rrr r′³)
//! propeller:  β_P = β − x′_P r′
//!             1 − w_P = (1 − w_P0)(1 + (1 − exp(−C₁|β_P|))(C₂ − 1)),  C₂ = C₂⁺ (β_P ≥ 0), C₂⁻ (β_P < 0)
//!             J = u(1 − w_P)/(n_P D_P),  K_T = k₀ + k₁J + k₂J²,  T = ρn_P²D_P⁴K_T,  X_P = (1 − t_P)T
//! rudder:     u_R = εu(1 − w_P) √(η{1 + κ(√(1 + 8K_T/(πJ²)) − 1)}² + (1 − η)),  η = D_P/H_R
//!             β_R = β − l′_R r′,  γ_R = γ_R⁺ (β_R ≥ 0), γ_R⁻ (β_R < 0),  v_R = Uγ_Rβ_R
//!             U_R = √(u_R² + v_R²),  α_R = δ − atan2(v_R, u_R)
//!             F_N = ½ρA_R U_R² f_α sin α_R,  f_α = 6.13Λ/(Λ + 2.25), Λ = H_R²/A_R (Fujii) unless given
//!             X_R = −(1 − t_R)F_N sin δ,  Y_R = −(1 + a_H)F_N cos δ,  N_R = −(x_R + a_H x_H)F_N cos δ
//! ```
//!
//! with x_R = x′_R L, x_H = x′_H L. These are the paper's hull, propeller and rudder models as
//! the brief of this step and the paper's public transcriptions give them; the paper itself
//! was not read here (`data/README.md`), so this documentation names the equations by their
//! quantities and not by the paper's equation numbers. Where the public codes (shipmmg,
//! ShipMMG.jl, mmgdynamics) depart from the paper, the paper is followed: the wake law above
//! (not w_P0 exp(−4β_P²), nor mmgdynamics' misplaced parenthesis), β and v′ from the sway at
//! midship v_m (shipmmg takes v − x_G r for β and U but v for v′), Y′_v and N′_v on v′ (one
//! shipmmg version puts β there), x_R = x′_R L (not a fixed −0.5 m), and the race term at
//! J = 0 as its limit (below; the codes' k₀ n² D_P⁴ there is not a speed).
//!
//! **Signs.** x forward, y to starboard, z down, about midship; u, v_m, r of the midship
//! (r > 0 turns the bow to starboard). β > 0 when the midship moves to port of its heading
//! (v_m < 0). δ > 0 turns the ship to starboard: at β = r = 0 it gives F_N > 0, Y_R < 0 (the
//! stern pushed to port) and, with x_R + a_H x_H < 0, N_R > 0. This is the paper's sign, and
//! the opposite of eom's polynomial tables (the Mariner's puts positive δ to port,
//! [`super::side`]); an MMG scene writes δ in the paper's sign, and eom finds the side each
//! sign turns to from the linear model, as for any table.
//!
//! **The model's domain.** The paper's model is for a ship moving ahead (u ≥ 0) with its
//! propeller turning ahead (n_P > 0); [`MmgParameters::forces`] returns an [`MmgStateError`]
//! outside it rather than a number the paper does not give. Two limits are taken in it:
//! - *At rest* (U = 0, r = 0): β = v′ = r′ = 0, so the hull's forces are 0 (every term is U²
//!   times a bounded polynomial, the limit as u, v_m → 0). At U = 0 with r ≠ 0, r′ = rL/U is
//!   unbounded and the hull's r′³U² grows as 1/U: no limit exists, and that is an error.
//! - *J = 0* (u = 0 with the propeller turning): the race term √(1 + 8K_T/(πJ²)) is
//!   unbounded but u(1 − w_P) times it is not: u_R = εκ√η √(8K_T/π) n_P D_P, its limit as
//!   u → 0⁺.
//!
//! **How a ship runs it.** An MMG scene (`[hydrodynamics] model = "mmg"`, docs/mmg.md) is a
//! ship on 4.46 like any other: the symbolic engine derives the paper's equations of motion
//! at midship with the added masses m_x, m_y, J_z and the hull's polynomial, and proves them
//! with their Jacobians (`eom_codegen::model::ship`, the MMG form); the propeller's and the
//! rudder's loads, which are not polynomials, are computed beside the proved program and
//! read as its applied loads, their derivatives by dual numbers in its Jacobians
//! ([`MmgShip`]); the propeller is held at the rate that balances the approach
//! ([`balancing_rate`]). The run, the figures, the sides and the IMO criteria are the ship's.

mod applied;
mod check;
mod forces;
mod parameters;

pub use applied::{AppliedLoads, BY, MmgShip, balancing_rate};
pub use forces::{
    Controls, Edge, Kinematics, MidshipState, MmgForces, MmgStateError, PlanarLoads,
    PropellerAndRudder, PropellerForces, QUANTITIES, Real, RudderForces,
};
pub use parameters::{
    AddedMasses, HullDerivatives, MMG_COEFFICIENTS, MMG_PARTICULARS, MmgParameterError,
    MmgParameters, Particulars, PropellerCoefficients, RudderCoefficients, fujii_lift_gradient,
};
