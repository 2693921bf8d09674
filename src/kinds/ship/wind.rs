//! The wind on a ship: the loads of the air on its hull and superstructure above water.
//!
//! Wind loads are given as ships' wind-tunnel data are published: coefficients over the
//! relative wind's angle, on the frontal and the lateral projected areas (Isherwood, *Trans.
//! RINA* 115, 1972; Fossen, *Handbook of Marine Craft Hydrodynamics and Motion Control*, 2011,
//! §8.1):
//!
//! ```text
//! X_w = ½ρ_a V_r² C_X(γ) A_F,   Y_w = ½ρ_a V_r² C_Y(γ) A_L,   N_w = ½ρ_a V_r² C_N(γ) A_L L_oa
//! ```
//!
//! with V_r the speed of the air relative to the ship and γ the angle off the bow it comes
//! from. The air's velocity relative to the ship is the wind's over ground less the ship's over
//! ground, which is the velocity through the water (the state's u, v) plus the current's; so
//! the loads depend on u, v and the heading ψ (the wind and the current are fixed in space),
//! and on the wind's speed, whose gusts ([`gust`]) are the model's third input. They enter the
//! proved program as applied loads (`eom_codegen::model::ship::ShipSpec::applied`), with
//! their derivatives in its Jacobians, computed here by hand from the formula above:
//! `V_r² dγ = u_r dv_r − v_r du_r` is written without dividing by V_r², so a ship at rest
//! in still air has loads and derivatives zero, not NaN.
//!
//! The table ([`WindCoefficients`]) is linear between its angles, as published tables are
//! read (and as MSS interpolates Isherwood's); its derivatives are the segment's slope, the
//! segment above at a tabulated angle itself. The moment is taken about midship, where the
//! model's equations are; a table's moment is about the middle of the length overall, which
//! for a merchant ship lies a few metres from midship of L_pp: not corrected, and said in the
//! docs.

mod check;
pub mod coefficients;
pub mod gust;

pub use check::{AIR_DENSITY, WIND_HEIGHT_M};
pub use coefficients::{Isherwood, WindCoefficients, WindTableError};
pub use gust::{Gust, GustError, Spectrum};

/// The ship's wind loads as a table gives them: its coefficients, its areas, the air.
#[derive(Debug, Clone, PartialEq)]
pub struct Windage {
    /// C_X, C_Y, C_N over the relative wind's angle.
    pub coefficients: WindCoefficients,
    /// A_F, the frontal projected area above water, m².
    pub frontal_area: f64,
    /// A_L, the lateral projected area above water, m².
    pub lateral_area: f64,
    /// L_oa, the length overall, m: the moment's length.
    pub length_overall: f64,
    /// ρ_a, kg/m³.
    pub air_density: f64,
    /// The geometry the coefficients are Isherwood's regression at; `None` for a table.
    pub isherwood: Option<Isherwood>,
}

/// A wind fixed in direction, its mean speed constant, gusting or not.
#[derive(Debug, Clone, PartialEq)]
pub struct Wind {
    /// Its mean speed, m/s.
    pub speed: f64,
    /// The direction it blows from, rad clockwise from north (X).
    pub from: f64,
    /// Its gusts: the speed's fluctuation over time, the model's third input.
    pub gust: Option<Gust>,
}

impl Wind {
    /// The unit vector the wind blows toward, north and east.
    fn toward(&self) -> [f64; 2] {
        let (sin, cos) = self.from.sin_cos();
        [-cos, -sin]
    }
}

/// The ship in a wind: what its model computes the wind's loads from.
#[derive(Debug, Clone, PartialEq)]
pub struct ShipWind {
    /// The ship's coefficients and areas.
    pub windage: Windage,
    /// The wind.
    pub wind: Wind,
    /// The current's north and east components, m/s (zero without one): the ship moves over
    /// ground at its velocity through the water plus the current's.
    pub current: [f64; 2],
}

/// The wind's loads at a state, with what they are of.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WindLoads {
    /// X_w, Y_w, N_w about midship, N, N, N m.
    pub loads: [f64; 3],
    /// The air's speed relative to the ship, V_r, m/s.
    pub relative_speed: f64,
    /// The angle off the bow the relative wind comes from, γ, rad, positive from starboard.
    pub relative_angle: f64,
    /// ∂(X_w, Y_w, N_w)/∂(u, v, ψ, g), g the gust (the wind's speed less its mean).
    pub by: [[f64; 4]; 3],
}

impl ShipWind {
    /// The wind's loads on the ship moving at (u, v) through the water on heading `psi`, the
    /// wind's speed its mean plus `gust`, with their derivatives.
    pub fn loads(&self, [u, v, psi]: [f64; 3], gust: f64) -> WindLoads {
        let (sin, cos) = psi.sin_cos();
        // A north-east vector's body components, and their derivative by ψ: d(u, v)/dψ = (v, −u).
        let body = |[north, east]: [f64; 2]| [north * cos + east * sin, east * cos - north * sin];
        let speed = self.wind.speed + gust;
        let toward = body(self.wind.toward());
        let current = body(self.current);
        // The ship relative to the air: its velocity over ground less the wind's.
        let relative = [
            u + current[0] - speed * toward[0],
            v + current[1] - speed * toward[1],
        ];
        let by_heading = [
            current[1] - speed * toward[1],
            -(current[0] - speed * toward[0]),
        ];
        let by_gust = [-toward[0], -toward[1]];
        let [ur, vr] = relative;
        let squared = ur * ur + vr * vr;
        // γ: the air comes at the ship from the direction the ship moves through it.
        let angle = vr.atan2(ur);
        let half = 0.5 * self.windage.air_density;
        let windage = &self.windage;
        let scales = [
            half * windage.frontal_area,
            half * windage.lateral_area,
            half * windage.lateral_area * windage.length_overall,
        ];
        let mut loads = [0.0; 3];
        let mut by = [[0.0; 4]; 3];
        let ship_axes = windage.coefficients.at(angle);
        for (k, ((coefficient, slope), scale)) in ship_axes.into_iter().zip(scales).enumerate() {
            loads[k] = scale * coefficient * squared;
            // ∂/∂u_r and ∂/∂v_r of scale · C(γ) · (u_r² + v_r²), with V_r² ∂γ/∂u_r = −v_r
            // and V_r² ∂γ/∂v_r = u_r.
            let by_relative = [
                scale * (2.0 * coefficient * ur - slope * vr),
                scale * (2.0 * coefficient * vr + slope * ur),
            ];
            let through = |d: [f64; 2]| by_relative[0] * d[0] + by_relative[1] * d[1];
            by[k] = [
                by_relative[0],
                by_relative[1],
                through(by_heading),
                through(by_gust),
            ];
        }
        WindLoads {
            loads,
            relative_speed: squared.sqrt(),
            relative_angle: angle,
            by,
        }
    }
}

#[cfg(test)]
mod tests;
