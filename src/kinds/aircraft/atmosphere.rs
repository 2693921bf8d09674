//! The air the aircraft flies in: its density, and the speed of sound for the Mach number,
//! with their derivatives in the altitude (the model's Jacobians read them).
//!
//! Two atmospheres, named in the scene: the one a source defines with its model (Stevens &
//! Lewis's `adc`, a linear-lapse fit in feet that the F-16's tables were published with),
//! and the 1976 U.S. Standard Atmosphere's troposphere and lower stratosphere (to 20 km), in
//! the scene's units.

use thiserror::Error;

/// The air at an altitude, with the derivatives the Jacobians need.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Air {
    /// Density (slug/ft³ or kg/m³, as the atmosphere's units).
    pub density: f64,
    /// d(density)/d(altitude).
    pub density_by_altitude: f64,
    /// The speed of sound (ft/s or m/s).
    pub speed_of_sound: f64,
    /// d(speed of sound)/d(altitude).
    pub sound_by_altitude: f64,
}

/// Which atmosphere, in which units.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Atmosphere {
    /// Stevens & Lewis's air-data function `adc` (feet, slug, °R): T = 519(1 − 0.703e-5 h) °R
    /// below 35 000 ft and 390 °R above, ρ = 2.377e-3 (1 − 0.703e-5 h)^4.14 slug/ft³ at every
    /// altitude, a = √(1.4 · 1716.3 · T).
    StevensLewis,
    /// The 1976 U.S. Standard Atmosphere to 20 km (troposphere with −6.5 K/km from 288.15 K
    /// and 101 325 Pa, then the isothermal layer at 216.65 K), in SI (m, kg/m³, m/s).
    Standard1976Si,
    /// The same, with the altitude in feet and the results in slug/ft³ and ft/s.
    Standard1976Us,
}

/// An altitude where the atmosphere is not defined.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("the {atmosphere} atmosphere is defined from {low} to {high} {unit}, not at {altitude}")]
pub struct OutsideAtmosphere {
    /// The atmosphere's name.
    pub atmosphere: &'static str,
    /// The altitude asked.
    pub altitude: f64,
    /// The lowest altitude.
    pub low: f64,
    /// The highest.
    pub high: f64,
    /// The altitude's unit.
    pub unit: &'static str,
}

const FOOT: f64 = 0.3048;
const SLUG_PER_FT3: f64 = 515.378_818_393_195_8; // kg/m³ per slug/ft³: 14.593 902 94 kg / 0.3048³ m³

impl Atmosphere {
    /// The name a scene gives it.
    pub fn name(self) -> &'static str {
        match self {
            Atmosphere::StevensLewis => "stevens-lewis",
            Atmosphere::Standard1976Si => "standard-1976",
            Atmosphere::Standard1976Us => "standard-1976-us",
        }
    }

    /// The air at `altitude` (the atmosphere's length unit).
    pub fn at(self, altitude: f64) -> Result<Air, OutsideAtmosphere> {
        match self {
            Atmosphere::StevensLewis => stevens_lewis(altitude),
            Atmosphere::Standard1976Si => standard_1976(altitude),
            Atmosphere::Standard1976Us => {
                let si = standard_1976(altitude * FOOT).map_err(|e| OutsideAtmosphere {
                    altitude,
                    low: e.low / FOOT,
                    high: e.high / FOOT,
                    unit: "ft",
                    ..e
                })?;
                Ok(Air {
                    density: si.density / SLUG_PER_FT3,
                    density_by_altitude: si.density_by_altitude * FOOT / SLUG_PER_FT3,
                    speed_of_sound: si.speed_of_sound / FOOT,
                    sound_by_altitude: si.sound_by_altitude,
                })
            }
        }
    }
}

/// `adc`: the fit is defined while 1 − 0.703e-5 h > 0 (below about 142 000 ft); the code
/// gives it no other bound, and neither does this, but the ground (h < 0 by more than a
/// deep valley) is refused.
fn stevens_lewis(altitude: f64) -> Result<Air, OutsideAtmosphere> {
    const LAPSE: f64 = 0.703e-5;
    let (low, high) = (-5_000.0, 1.0 / LAPSE);
    if !(altitude >= low && altitude < high) {
        return Err(OutsideAtmosphere {
            atmosphere: "stevens-lewis",
            altitude,
            low,
            high,
            unit: "ft",
        });
    }
    let tfac = 1.0 - LAPSE * altitude;
    let (temperature, temperature_by_altitude) = if altitude >= 35_000.0 {
        (390.0, 0.0)
    } else {
        (519.0 * tfac, -519.0 * LAPSE)
    };
    // ρ ∝ tfac^4.14, so dρ/dh = 4.14 ρ/tfac · dtfac/dh.
    let density = 2.377e-3 * tfac.powf(4.14);
    let speed_of_sound = (1.4 * 1716.3 * temperature).sqrt();
    Ok(Air {
        density,
        density_by_altitude: 4.14 * density / tfac * -LAPSE,
        speed_of_sound,
        sound_by_altitude: speed_of_sound / (2.0 * temperature) * temperature_by_altitude,
    })
}

/// The 1976 standard atmosphere in SI at the geometric `altitude`, to 20 km: the standard's
/// layers are in geopotential altitude H = r₀z/(r₀ + z), r₀ = 6 356 766 m, and its
/// derivatives carry dH/dz = (r₀/(r₀ + z))².
fn standard_1976(altitude: f64) -> Result<Air, OutsideAtmosphere> {
    const EARTH_RADIUS: f64 = 6_356_766.0;
    const T0: f64 = 288.15;
    const P0: f64 = 101_325.0;
    const LAPSE: f64 = -0.0065;
    const R: f64 = 287.052_87; // J/(kg K): R*/M₀ = 8.314 32 / 0.028 964 4
    const G0: f64 = 9.806_65;
    const GAMMA: f64 = 1.4;
    const TROPOPAUSE: f64 = 11_000.0;
    let (low, high) = (-610.0, 20_000.0);
    if !(altitude >= low && altitude <= high) {
        return Err(OutsideAtmosphere {
            atmosphere: "standard-1976",
            altitude,
            low,
            high,
            unit: "m",
        });
    }
    let geopotential = EARTH_RADIUS * altitude / (EARTH_RADIUS + altitude);
    let by_geometric = (EARTH_RADIUS / (EARTH_RADIUS + altitude)).powi(2);
    let exponent = -G0 / (LAPSE * R);
    let (temperature, pressure, temperature_by_altitude, pressure_by_altitude) =
        if geopotential <= TROPOPAUSE {
            let t = T0 + LAPSE * geopotential;
            let p = P0 * (t / T0).powf(exponent);
            (t, p, LAPSE, p * exponent * LAPSE / t)
        } else {
            let t11 = T0 + LAPSE * TROPOPAUSE;
            let p11 = P0 * (t11 / T0).powf(exponent);
            let p = p11 * (-G0 * (geopotential - TROPOPAUSE) / (R * t11)).exp();
            (t11, p, 0.0, -p * G0 / (R * t11))
        };
    let density = pressure / (R * temperature);
    let speed_of_sound = (GAMMA * R * temperature).sqrt();
    Ok(Air {
        density,
        density_by_altitude: (pressure_by_altitude - density * R * temperature_by_altitude)
            / (R * temperature)
            * by_geometric,
        speed_of_sound,
        sound_by_altitude: speed_of_sound / (2.0 * temperature)
            * temperature_by_altitude
            * by_geometric,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 1976 standard's own tabulated values at geometric altitudes (U.S. Standard
    /// Atmosphere, 1976, NOAA/NASA/USAF, Table I): ρ at 0, 5, 11 and 20 km and the speed of
    /// sound at 0 and 12 km, to the digits printed (1e-4 relative).
    #[test]
    fn the_standard_atmosphere_gives_its_tabulated_values() {
        for (h, rho) in [
            (0.0, 1.2250),
            (5_000.0, 0.73643),
            (11_000.0, 0.36480),
            (20_000.0, 0.088910),
        ] {
            let air = Atmosphere::Standard1976Si.at(h).unwrap();
            assert!(
                (air.density / rho - 1.0).abs() < 1e-4,
                "{h}: {}",
                air.density
            );
        }
        let sea = Atmosphere::Standard1976Si.at(0.0).unwrap();
        assert!((sea.speed_of_sound - 340.29).abs() < 0.01);
        let stratosphere = Atmosphere::Standard1976Si.at(12_000.0).unwrap();
        assert!((stratosphere.speed_of_sound - 295.07).abs() < 0.01);
        assert!((stratosphere.density / 0.31194 - 1.0).abs() < 1e-4);
        let us = Atmosphere::Standard1976Us.at(0.0).unwrap();
        assert!((us.density - 0.0023769).abs() < 1e-7);
    }

    /// Each atmosphere's derivatives against central differences (h = 1, relative 1e-6:
    /// the second derivative of ρ over a metre or a foot is below that).
    #[test]
    fn the_derivatives_in_altitude_are_the_functions_slopes() {
        for (atmosphere, altitudes) in [
            (Atmosphere::StevensLewis, [0.0, 10_000.0, 40_000.0]),
            (Atmosphere::Standard1976Si, [0.0, 5_000.0, 15_000.0]),
            (Atmosphere::Standard1976Us, [0.0, 20_000.0, 50_000.0]),
        ] {
            for h in altitudes {
                let at = |h: f64| atmosphere.at(h).unwrap();
                let air = at(h);
                let density = (at(h + 1.0).density - at(h - 1.0).density) / 2.0;
                let sound = (at(h + 1.0).speed_of_sound - at(h - 1.0).speed_of_sound) / 2.0;
                assert!(
                    (air.density_by_altitude / density - 1.0).abs() < 1e-6,
                    "{h}"
                );
                assert!((air.sound_by_altitude - sound).abs() < 1e-6 * air.speed_of_sound);
            }
        }
    }

    #[test]
    fn an_altitude_outside_the_atmosphere_is_refused() {
        let refused = Atmosphere::Standard1976Si.at(30_000.0).unwrap_err();
        assert_eq!(
            refused.to_string(),
            "the standard-1976 atmosphere is defined from -610 to 20000 m, not at 30000"
        );
        assert!(Atmosphere::StevensLewis.at(f64::NAN).is_err());
    }
}
