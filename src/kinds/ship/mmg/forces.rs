//! The MMG forces at one state, hull, propeller and rudder in turn, every quantity on the way
//! kept (the module's documentation gives the formulas and the signs).

use num_dual::DualNum;
use std::f64::consts::PI;

use super::parameters::{HullDerivatives, MmgParameters, Particulars};
use crate::Short;

/// The motion of the midship: u, v_m (m/s) and r (rad/s), x forward, y to starboard.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MidshipState {
    /// u, the surge velocity, m/s.
    pub u: f64,
    /// v_m, the sway velocity at midship, m/s (to starboard).
    pub v_m: f64,
    /// r, the yaw rate, rad/s (to starboard).
    pub r: f64,
}

/// What the ship is steered and driven with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Controls {
    /// δ, the rudder angle, rad; positive turns the ship to starboard (the paper's sign).
    pub rudder_angle: f64,
    /// n_P, the propeller rate, rev/s.
    pub propeller_rate: f64,
}

/// A number the forces are computed in: f64 for their values, a dual number of
/// [`num_dual`] for their exact derivatives (the model's Jacobians), by one definition.
pub trait Real: DualNum<Primitive = f64> + Copy {}

impl<D: DualNum<Primitive = f64> + Copy> Real for D {}

/// Which branch an inflow angle of exactly zero takes, where the model changes with its sign
/// (C₂ and the wake law's |β_P|, γ_R): the paper's assigns β = 0 to β ≥ 0; taken toward
/// negative angles, the derivatives there are the other one-sided ones (a turn to port's).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Edge {
    /// β = 0 is on the side β > 0 (the paper's).
    TowardPositive,
    /// β = 0 is on the side β < 0.
    TowardNegative,
}

impl Edge {
    /// Whether `angle` is on the positive side.
    fn positive(self, angle: f64) -> bool {
        match self {
            Edge::TowardPositive => angle >= 0.0,
            Edge::TowardNegative => angle > 0.0,
        }
    }
}

/// A force pair and a moment about midship: X, Y in N, N in N m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarLoads<D = f64> {
    /// X, N.
    pub x: D,
    /// Y, N.
    pub y: D,
    /// N, N m.
    pub n: D,
}

/// The speed and drift of the midship, and the non-dimensional sway and yaw the hull's
/// derivatives are written in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kinematics<D = f64> {
    /// U = √(u² + v_m²), m/s.
    pub speed: D,
    /// β = atan2(−v_m, u), rad (0 at rest).
    pub drift: D,
    /// v′ = v_m/U (0 at rest).
    pub sway_prime: D,
    /// r′ = rL/U (0 at rest).
    pub yaw_rate_prime: D,
}

/// The propeller in the hull's wake.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PropellerForces<D = f64> {
    /// β_P = β − x′_P r′, the inflow angle at the propeller, rad.
    pub inflow_angle: D,
    /// w_P, the wake fraction in the manoeuvre.
    pub wake_fraction: D,
    /// J = u(1 − w_P)/(n_P D_P).
    pub advance_ratio: D,
    /// K_T(J).
    pub thrust_coefficient: D,
    /// T = ρn_P²D_P⁴K_T, N.
    pub thrust: D,
    /// X_P = (1 − t_P)T, N.
    pub surge: D,
}

/// The rudder in the propeller's race and the hull's straightened flow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RudderForces<D = f64> {
    /// β_R = β − l′_R r′, rad.
    pub inflow_angle: D,
    /// γ_R, γ_R⁺ or γ_R⁻ by the sign of β_R.
    pub flow_straightening: f64,
    /// u_R, the inflow ahead, m/s.
    pub inflow_ahead: D,
    /// v_R = Uγ_Rβ_R, the inflow across, m/s.
    pub inflow_across: D,
    /// α_R = δ − atan2(v_R, u_R), rad.
    pub angle_of_attack: D,
    /// U_R = √(u_R² + v_R²), m/s.
    pub inflow_speed: D,
    /// F_N = ½ρA_R U_R² f_α sin α_R, N.
    pub normal_force: D,
    /// X_R, Y_R, N_R about midship.
    pub loads: PlanarLoads<D>,
}

/// The kinematics, the propeller's forces and the rudder's at one state, without the hull's
/// ([`MmgParameters::propeller_and_rudder_of`]).
pub type PropellerAndRudder<D> = (Kinematics<D>, PropellerForces<D>, RudderForces<D>);

/// Every quantity of the MMG forces at one state, in SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MmgForces<D = f64> {
    /// U, β, v′, r′.
    pub kinematics: Kinematics<D>,
    /// X_H, Y_H, N_H.
    pub hull: PlanarLoads<D>,
    /// β_P, w_P, J, K_T, T, X_P.
    pub propeller: PropellerForces<D>,
    /// β_R, γ_R, u_R, v_R, α_R, U_R, F_N, X_R, Y_R, N_R.
    pub rudder: RudderForces<D>,
    /// X = X_H + X_P + X_R, Y = Y_H + Y_R, N = N_H + N_R, about midship.
    pub total: PlanarLoads<D>,
}

/// Why the forces cannot be given at a state: it is outside the paper's model.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum MmgStateError {
    /// A state or control value that is NaN or infinite.
    #[error("{name} = {} is not finite", Short(*value))]
    NotFinite {
        /// `u`, `v_m`, `r`, `rudder_angle` or `propeller_rate`.
        name: &'static str,
        /// The value.
        value: f64,
    },
    /// u < 0: the paper's propeller and rudder models are for a ship moving ahead.
    #[error("u = {} m/s is astern; the MMG standard method is for a ship moving ahead", Short(*u))]
    Astern {
        /// u, m/s.
        u: f64,
    },
    /// n_P ≤ 0: the open-water curve K_T(J) is for a propeller turning ahead.
    #[error(
        "n_P = {} rev/s: the MMG standard method's propeller turns ahead (n_P > 0)",
        Short(*rate)
    )]
    PropellerNotAhead {
        /// n_P, rev/s.
        rate: f64,
    },
    /// U = 0 with r ≠ 0: r′ = rL/U is unbounded and the hull's forces have no limit.
    #[error("r = {} rad/s at U = 0: the hull's forces on r′ = rL/U have no limit", Short(*r))]
    TurningAtRest {
        /// r, rad/s.
        r: f64,
    },
    /// A square root of the rudder's inflow that is negative: K_T too negative at J for
    /// the race term √(1 + 8K_T/(πJ²)), or for η{…}² + (1 − η).
    #[error(
        "the rudder's inflow u_R is undefined at J = {}, K_T = {}",
        Short(*advance_ratio),
        Short(*thrust_coefficient)
    )]
    RaceUndefined {
        /// J.
        advance_ratio: f64,
        /// K_T.
        thrust_coefficient: f64,
    },
}

/// The names of [`MmgForces::quantities`], in order (those of `peer/mmg/checkpoints.json`).
pub const QUANTITIES: [&str; 26] = [
    "U", "beta", "v_prime", "r_prime", "X_H", "Y_H", "N_H", "beta_P", "w_P", "J", "K_T", "T",
    "X_P", "beta_R", "gamma_R", "u_R", "v_R", "alpha_R", "U_R", "F_N", "X_R", "Y_R", "N_R", "X",
    "Y", "N",
];

impl MmgForces {
    /// Every quantity by its name in [`QUANTITIES`], in that order.
    pub fn quantities(&self) -> [(&'static str, f64); 26] {
        let (k, h, p, r, t) = (
            self.kinematics,
            self.hull,
            self.propeller,
            self.rudder,
            self.total,
        );
        let values = [
            k.speed,
            k.drift,
            k.sway_prime,
            k.yaw_rate_prime,
            h.x,
            h.y,
            h.n,
            p.inflow_angle,
            p.wake_fraction,
            p.advance_ratio,
            p.thrust_coefficient,
            p.thrust,
            p.surge,
            r.inflow_angle,
            r.flow_straightening,
            r.inflow_ahead,
            r.inflow_across,
            r.angle_of_attack,
            r.inflow_speed,
            r.normal_force,
            r.loads.x,
            r.loads.y,
            r.loads.n,
            t.x,
            t.y,
            t.n,
        ];
        std::array::from_fn(|i| (QUANTITIES[i], values[i]))
    }
}

impl MmgParameters {
    /// The hull's, the propeller's and the rudder's forces at `state` under `controls`, and
    /// their sums about midship, with every quantity on the way.
    pub fn forces(
        &self,
        state: MidshipState,
        controls: Controls,
    ) -> Result<MmgForces, MmgStateError> {
        check_domain(state, controls)?;
        let MidshipState { u, v_m, r } = state;
        let at = [u, v_m, r, controls.rudder_angle, controls.propeller_rate];
        self.forces_of(at, Edge::TowardPositive)
    }

    /// [`MmgParameters::forces`] in any [`Real`] at (u, v_m, r, δ, n_P), an inflow angle of
    /// zero on the side `edge` says, the domain checked by the caller: with dual numbers
    /// seeded on these five, their derivatives by each.
    pub fn forces_of<D: Real>(
        &self,
        [u, v_m, r, delta, rate]: [D; 5],
        edge: Edge,
    ) -> Result<MmgForces<D>, MmgStateError> {
        let (kinematics, propeller, rudder) =
            self.propeller_and_rudder_of([u, v_m, r, delta, rate], edge)?;
        let hull = hull_loads(&self.hull, &self.particulars, &kinematics);
        let total = PlanarLoads {
            x: hull.x + propeller.surge + rudder.loads.x,
            y: hull.y + rudder.loads.y,
            n: hull.n + rudder.loads.n,
        };
        Ok(MmgForces {
            kinematics,
            hull,
            propeller,
            rudder,
            total,
        })
    }

    /// The propeller's and the rudder's forces alone (not the hull's), with the kinematics
    /// they are of, as [`MmgParameters::forces_of`] takes them: what a proved program that
    /// has the hull's forces of its own reads beside it.
    pub fn propeller_and_rudder_of<D: Real>(
        &self,
        [u, v_m, r, delta, rate]: [D; 5],
        edge: Edge,
    ) -> Result<PropellerAndRudder<D>, MmgStateError> {
        let kinematics = kinematics([u, v_m, r], self.particulars.length)?;
        let propeller = self.propeller_forces(u, &kinematics, rate, edge);
        let rudder = self.rudder_forces(u, &kinematics, &propeller, (delta, rate), edge)?;
        Ok((kinematics, propeller, rudder))
    }

    /// β_P and β_R at `state`, rad: the inflow angles whose signs choose C₂ and γ_R (zero at
    /// rest), or why the paper's model has none there.
    pub fn inflow_angles(&self, state: MidshipState) -> Result<[f64; 2], MmgStateError> {
        let motion = kinematics([state.u, state.v_m, state.r], self.particulars.length)?;
        Ok([
            inflow_angle(&motion, self.propeller.position),
            inflow_angle(&motion, self.rudder.effective_position),
        ])
    }

    /// β_P, the wake in the manoeuvre, J, K_T, T and X_P.
    fn propeller_forces<D: Real>(
        &self,
        u: D,
        motion: &Kinematics<D>,
        rate: D,
        edge: Edge,
    ) -> PropellerForces<D> {
        let p = &self.propeller;
        let diameter = self.particulars.propeller_diameter;
        let inflow_angle = inflow_angle(motion, p.position);
        let (wake_gain, magnitude) = if edge.positive(inflow_angle.re()) {
            (p.wake_gain_positive, inflow_angle)
        } else {
            (p.wake_gain_negative, -inflow_angle)
        };
        let growth = -(magnitude * -p.wake_rate).exp() + 1.0;
        let wake_fraction = -((growth * (wake_gain - 1.0) + 1.0) * (1.0 - p.straight_wake)) + 1.0;
        let advance_ratio = u * (-wake_fraction + 1.0) / (rate * diameter);
        let [k0, k1, k2] = p.thrust_curve;
        let thrust_coefficient = advance_ratio * k1 + advance_ratio * advance_ratio * k2 + k0;
        let thrust =
            rate * rate * thrust_coefficient * (self.particulars.density * diameter.powi(4));
        PropellerForces {
            inflow_angle,
            wake_fraction,
            advance_ratio,
            thrust_coefficient,
            thrust,
            surge: thrust * (1.0 - p.thrust_deduction),
        }
    }

    /// The rudder's inflow, its normal force and what it gives about midship.
    fn rudder_forces<D: Real>(
        &self,
        u: D,
        motion: &Kinematics<D>,
        propeller: &PropellerForces<D>,
        (delta, rate): (D, D),
        edge: Edge,
    ) -> Result<RudderForces<D>, MmgStateError> {
        let c = &self.rudder;
        let ship = &self.particulars;
        let inflow_angle = inflow_angle(motion, c.effective_position);
        let flow_straightening = if edge.positive(inflow_angle.re()) {
            c.straightening_positive
        } else {
            c.straightening_negative
        };
        let inflow_ahead = self.rudder_inflow_ahead(u, propeller, rate)?;
        let inflow_across = motion.speed * inflow_angle * flow_straightening;
        let angle_of_attack = delta - inflow_across.atan2(inflow_ahead);
        let inflow_speed = (inflow_ahead * inflow_ahead + inflow_across * inflow_across).sqrt();
        let normal_force = inflow_speed
            * inflow_speed
            * angle_of_attack.sin()
            * (0.5 * ship.density * ship.rudder_area * c.lift_gradient);
        let (sin_delta, cos_delta) = delta.sin_cos();
        let lever = (c.position + c.hull_force_share * c.hull_force_position) * ship.length;
        Ok(RudderForces {
            inflow_angle,
            flow_straightening,
            inflow_ahead,
            inflow_across,
            angle_of_attack,
            inflow_speed,
            normal_force,
            loads: PlanarLoads {
                x: -(normal_force * sin_delta * (1.0 - c.drag_deduction)),
                y: -(normal_force * cos_delta * (1.0 + c.hull_force_share)),
                n: -(normal_force * cos_delta * lever),
            },
        })
    }

    /// u_R = εu(1 − w_P) √(η{1 + κ(√(1 + 8K_T/(πJ²)) − 1)}² + (1 − η)), or its limit
    /// εκ√η √(8K_T/π) n_P D_P at J = 0 (where u(1 − w_P) = 0 and the race term is unbounded;
    /// its derivatives there are the limit's, which holds n_P D_P and K_T's).
    fn rudder_inflow_ahead<D: Real>(
        &self,
        u: D,
        propeller: &PropellerForces<D>,
        rate: D,
    ) -> Result<D, MmgStateError> {
        let c = &self.rudder;
        let (j, k_t) = (propeller.advance_ratio, propeller.thrust_coefficient);
        let undefined = MmgStateError::RaceUndefined {
            advance_ratio: j.re(),
            thrust_coefficient: k_t.re(),
        };
        let race_radicand = k_t * 8.0 / (j * j * PI) + 1.0;
        if j.re() == 0.0 || race_radicand.re().is_infinite() {
            let thrust_radicand = k_t * (8.0 / PI);
            if thrust_radicand.re() < 0.0 {
                return Err(undefined);
            }
            let diameter = self.particulars.propeller_diameter;
            let race = c.wake_ratio * c.race_share * c.span_in_race.sqrt();
            return Ok(thrust_radicand.sqrt() * rate * (race * diameter));
        }
        if race_radicand.re() < 0.0 {
            return Err(undefined);
        }
        let race = (race_radicand.sqrt() - 1.0) * c.race_share + 1.0;
        let radicand = race * race * c.span_in_race + (1.0 - c.span_in_race);
        if radicand.re() < 0.0 {
            return Err(undefined);
        }
        Ok(u * (-propeller.wake_fraction + 1.0) * radicand.sqrt() * c.wake_ratio)
    }
}

/// The state and controls the paper's model is written for: finite, ahead, the propeller
/// turning ahead.
pub(crate) fn check_domain(state: MidshipState, controls: Controls) -> Result<(), MmgStateError> {
    for (name, value) in [
        ("u", state.u),
        ("v_m", state.v_m),
        ("r", state.r),
        ("rudder_angle", controls.rudder_angle),
        ("propeller_rate", controls.propeller_rate),
    ] {
        if !value.is_finite() {
            return Err(MmgStateError::NotFinite { name, value });
        }
    }
    if state.u < 0.0 {
        return Err(MmgStateError::Astern { u: state.u });
    }
    if controls.propeller_rate <= 0.0 {
        return Err(MmgStateError::PropellerNotAhead {
            rate: controls.propeller_rate,
        });
    }
    Ok(())
}

/// U, β, v′, r′ of the midship; at rest (U = 0) β, v′, r′ are 0, and a yaw rate there is an
/// error. U is √(u² + v_m²) as the proved program's U is computed, to the bit.
fn kinematics<D: Real>([u, v_m, r]: [D; 3], length: f64) -> Result<Kinematics<D>, MmgStateError> {
    let speed = (u * u + v_m * v_m).sqrt();
    if speed.re() == 0.0 {
        if r.re() != 0.0 {
            return Err(MmgStateError::TurningAtRest { r: r.re() });
        }
        let zero = D::from(0.0);
        return Ok(Kinematics {
            speed: zero,
            drift: zero,
            sway_prime: zero,
            yaw_rate_prime: zero,
        });
    }
    Ok(Kinematics {
        speed,
        drift: (-v_m).atan2(u),
        sway_prime: v_m / speed,
        yaw_rate_prime: r * length / speed,
    })
}

/// β − x′r′: the inflow angle at the propeller (x′ = x′_P) or the rudder (x′ = l′_R).
fn inflow_angle<D: Real>(motion: &Kinematics<D>, position: f64) -> D {
    motion.drift - motion.yaw_rate_prime * position
}

/// The hull's sway force or yaw moment, non-dimensional, from its terms in v′, r′, v′³, v′²r′,
/// v′r′² and r′³ (the paper writes Y′_H and N′_H alike).
fn lateral<D: Real>([v1, r1, vvv, vvr, vrr, rrr]: [f64; 6], (v, r): (D, D)) -> D {
    v * v1 + r * r1 + v.powi(3) * vvv + v * v * r * vvr + v * r * r * vrr + r.powi(3) * rrr
}

/// X_H, Y_H on ½ρLdU², N_H on ½ρL²dU², from the hull's polynomials in v′ and r′.
fn hull_loads<D: Real>(
    hull: &HullDerivatives,
    ship: &Particulars,
    motion: &Kinematics<D>,
) -> PlanarLoads<D> {
    let (v, r) = (motion.sway_prime, motion.yaw_rate_prime);
    let surge = v * v * hull.x_vv + v * r * hull.x_vr + r * r * hull.x_rr + v.powi(4) * hull.x_vvvv
        - hull.resistance;
    let sway = lateral(
        [
            hull.y_v, hull.y_r, hull.y_vvv, hull.y_vvr, hull.y_vrr, hull.y_rrr,
        ],
        (v, r),
    );
    let yaw = lateral(
        [
            hull.n_v, hull.n_r, hull.n_vvv, hull.n_vvr, hull.n_vrr, hull.n_rrr,
        ],
        (v, r),
    );
    let force_scale = motion.speed.powi(2) * (0.5 * ship.density * ship.length * ship.draft);
    PlanarLoads {
        x: force_scale * surge,
        y: force_scale * sway,
        n: force_scale * yaw * ship.length,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kvlcc2_model() -> MmgParameters {
        let text = include_str!("../../../../data/kvlcc2_mmg.json");
        let document: serde_json::Value = serde_json::from_str(text).unwrap();
        MmgParameters::from_json(&document, "L7", 1025.0).unwrap()
    }

    fn state(u: f64, v_m: f64, r: f64) -> MidshipState {
        MidshipState { u, v_m, r }
    }

    fn controls(rudder_angle: f64, propeller_rate: f64) -> Controls {
        Controls {
            rudder_angle,
            propeller_rate,
        }
    }

    /// The forces of a turn to starboard and of its mirror image to port.
    fn turning_both_ways(model: &MmgParameters) -> (MmgForces, MmgForces) {
        let starboard = model.forces(state(0.9, -0.2, 0.06), controls(0.6, 10.0));
        let port = model.forces(state(0.9, 0.2, -0.06), controls(-0.6, 10.0));
        (starboard.unwrap(), port.unwrap())
    }

    #[test]
    fn positive_rudder_turns_the_ship_to_starboard() {
        let forces = kvlcc2_model()
            .forces(state(1.179, 0.0, 0.0), controls(0.2, 10.0))
            .unwrap();
        assert!(forces.rudder.normal_force > 0.0);
        assert!(forces.rudder.loads.y < 0.0, "the stern is pushed to port");
        assert!(forces.rudder.loads.n > 0.0, "the bow turns to starboard");
        assert!(forces.rudder.loads.x < 0.0, "the rudder drags");
    }

    /// With the side-dependent coefficients made equal, the model is symmetric port to
    /// starboard: (u, −v_m, −r, −δ) gives (X, −Y, −N) at every step, the hull's odd terms
    /// and the rudder's signs included.
    #[test]
    fn with_equal_side_coefficients_the_mirrored_state_gives_the_mirrored_forces() {
        let mut model = kvlcc2_model();
        model.propeller.wake_gain_negative = model.propeller.wake_gain_positive;
        model.rudder.straightening_negative = model.rudder.straightening_positive;
        let (starboard, port) = turning_both_ways(&model);
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * a.abs().max(1.0);
        for (name, (a, b)) in [
            ("X", (starboard.total.x, port.total.x)),
            ("Y", (starboard.total.y, -port.total.y)),
            ("N", (starboard.total.n, -port.total.n)),
            ("T", (starboard.propeller.thrust, port.propeller.thrust)),
            (
                "F_N",
                (starboard.rudder.normal_force, -port.rudder.normal_force),
            ),
        ] {
            assert!(close(a, b), "{name}: {a} against {b}");
        }
    }

    #[test]
    fn the_sides_differ_where_the_paper_says_they_do() {
        let model = kvlcc2_model();
        let (starboard, port) = turning_both_ways(&model);
        assert_eq!(starboard.rudder.flow_straightening, 0.64);
        assert_eq!(port.rudder.flow_straightening, 0.395);
        // C₂⁺ = 1.6 thins the wake when the flow comes from starboard of the propeller.
        assert!(starboard.propeller.wake_fraction < port.propeller.wake_fraction);
    }

    #[test]
    fn at_rest_the_hull_gives_nothing_and_the_rudder_sees_the_race_alone() {
        let model = kvlcc2_model();
        let forces = model
            .forces(state(0.0, 0.0, 0.0), controls(0.3, 10.0))
            .unwrap();
        let k = forces.kinematics;
        assert_eq!(
            (k.speed, k.drift, k.sway_prime, k.yaw_rate_prime),
            (0.0, 0.0, 0.0, 0.0)
        );
        assert_eq!(
            (forces.hull.x, forces.hull.y, forces.hull.n),
            (0.0, 0.0, 0.0)
        );
        assert_eq!(forces.propeller.advance_ratio, 0.0);
        assert_eq!(forces.propeller.wake_fraction, 0.4);
        let r = model.rudder;
        let race = r.wake_ratio * r.race_share * r.span_in_race.sqrt();
        let expected = race * (8.0 * 0.2931 / PI).sqrt() * 10.0 * 0.216;
        assert!((forces.rudder.inflow_ahead - expected).abs() <= 1e-15 * expected);
        assert_eq!(forces.rudder.angle_of_attack, 0.3);
        assert!(
            forces
                .quantities()
                .iter()
                .all(|(_, value)| value.is_finite())
        );
    }

    #[test]
    fn the_race_at_rest_is_the_limit_of_moving_ahead_slowly() {
        let model = kvlcc2_model();
        let at = |u: f64| {
            model
                .forces(state(u, 0.0, 0.0), controls(0.0, 10.0))
                .unwrap()
                .rudder
                .inflow_ahead
        };
        let rest = at(0.0);
        for u in [1e-6, 1e-9, 1e-300] {
            let relative = (at(u) - rest).abs() / rest;
            assert!(relative < 1e-5, "u = {u}: {} against {rest}", at(u));
        }
    }

    #[test]
    fn turning_at_rest_is_an_error_and_so_is_a_state_outside_the_model() {
        let model = kvlcc2_model();
        let ahead = controls(0.0, 10.0);
        let error = |s, c| model.forces(s, c).unwrap_err();
        assert_eq!(
            error(state(0.0, 0.0, 0.01), ahead),
            MmgStateError::TurningAtRest { r: 0.01 }
        );
        assert_eq!(
            error(state(-0.5, 0.0, 0.0), ahead),
            MmgStateError::Astern { u: -0.5 }
        );
        assert_eq!(
            error(state(1.0, 0.0, 0.0), controls(0.0, 0.0)),
            MmgStateError::PropellerNotAhead { rate: 0.0 }
        );
        assert!(matches!(
            error(state(1.0, f64::NAN, 0.0), ahead),
            MmgStateError::NotFinite { name: "v_m", .. }
        ));
    }

    #[test]
    fn a_thrust_curve_that_reverses_the_race_is_an_error_not_a_nan() {
        let mut model = kvlcc2_model();
        model.propeller.thrust_curve = [-0.1, 0.0, 0.0];
        let error = model
            .forces(state(0.0, 0.0, 0.0), controls(0.0, 10.0))
            .unwrap_err();
        assert!(matches!(error, MmgStateError::RaceUndefined { .. }));
        let error = model
            .forces(state(0.05, 0.0, 0.0), controls(0.0, 10.0))
            .unwrap_err();
        assert!(matches!(error, MmgStateError::RaceUndefined { .. }));
    }

    #[test]
    fn the_quantities_are_named_in_order() {
        let forces = kvlcc2_model()
            .forces(state(1.0, -0.1, 0.02), controls(0.1, 10.0))
            .unwrap();
        let names: Vec<_> = forces.quantities().iter().map(|(name, _)| *name).collect();
        assert_eq!(names, QUANTITIES);
        assert_eq!(forces.quantities()[12], ("X_P", forces.propeller.surge));
        assert_eq!(forces.quantities()[25], ("N", forces.total.n));
    }
}
