//! The Earth around a body that moves through space: its shape, its gravity, and where a body
//! is on it.
//!
//! Every scene today flies over the chapter's flat Earth under a constant g. A body that
//! flies far, fast or long feels the Earth's shape and its turning, and is compared with tools
//! (NASA's NESC check cases, JSBSim) that give its position as geodetic latitude, longitude and
//! altitude over an ellipsoid. This module holds what those need and what is not an equation of
//! motion: the Earth's constants ([`EarthConstants`], NESC's by default), the shapes
//! ([`Ellipsoid`]: WGS-84's or a sphere), the conversion between geodetic coordinates and the
//! Earth-centred Earth-fixed frame ([`geodesy`]), and the gravitation of a point mass, of an
//! oblate Earth to J2 ([`gravity`]). Each is checked against the six tools of the NESC check
//! cases (`data/nesc/`, `tests/earth_nesc.rs`): their printed positions and local gravity.
//!
//! The translational equations over a turning Earth (the Coriolis and centripetal terms) are
//! derived and proved as the chapter's are (`eom_codegen::model::earth`) and run as
//! [`point_mass::PointMass`] (feature `ship`, which brings the symbolic engine at run time);
//! the attitude over the Earth, the transport rate of local axes and the scenes are not here
//! yet.

pub mod geodesy;
pub mod gravity;
#[cfg(feature = "ship")]
pub mod point_mass;

pub use geodesy::{Ecef, Geodetic};
pub use gravity::Gravity;

/// The Earth's constants: the gravitational parameter, J2, the ellipsoid and the sphere, the
/// rotation rate; SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EarthConstants {
    /// GM, m³/s².
    pub gm: f64,
    /// J2, the oblateness term of the gravitational potential.
    pub j2: f64,
    /// The reference ellipsoid.
    pub ellipsoid: Ellipsoid,
    /// The radius of the sphere an Earth of that shape takes, m.
    pub sphere_radius: f64,
    /// Ω, the rotation rate about the polar axis, rad/s.
    pub rotation_rate: f64,
}

/// NASA's NESC check cases' constants (NASA/TM-2015-218675, as the check cases' data apply
/// them: their tools' local gravity at 30 000 ft over the equator is GM = 3.986004418e14 m³/s²
/// with J2 = 1.08262982e-3 on WGS-84 to 2e-12, `tests/earth_nesc.rs`): WGS-84's ellipsoid and
/// rotation rate, and the mean radius 6 371 007.1809 m for the spherical cases.
pub const NESC: EarthConstants = EarthConstants {
    gm: 3.986004418e14,
    j2: 1.08262982e-3,
    ellipsoid: Ellipsoid::WGS84,
    sphere_radius: 6_371_007.180_9,
    rotation_rate: 7.292115e-5,
};

/// An ellipsoid of revolution about the polar axis: its equatorial radius and flattening (a
/// sphere has f = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipsoid {
    /// a, m.
    pub equatorial_radius: f64,
    /// f = (a − b)/a.
    pub flattening: f64,
}

impl Ellipsoid {
    /// WGS-84's: a = 6 378 137 m, 1/f = 298.257223563.
    pub const WGS84: Ellipsoid = Ellipsoid {
        equatorial_radius: 6_378_137.0,
        flattening: 1.0 / 298.257_223_563,
    };

    /// A sphere of `radius`, m.
    pub const fn sphere(radius: f64) -> Ellipsoid {
        Ellipsoid {
            equatorial_radius: radius,
            flattening: 0.0,
        }
    }

    /// e² = f(2 − f), the first eccentricity squared.
    pub fn eccentricity_squared(&self) -> f64 {
        self.flattening * (2.0 - self.flattening)
    }

    /// b = a(1 − f), the polar radius, m.
    pub fn polar_radius(&self) -> f64 {
        self.equatorial_radius * (1.0 - self.flattening)
    }

    /// N(φ) = a/√(1 − e² sin²φ), the radius of curvature in the prime vertical, m.
    pub fn prime_vertical_radius(&self, latitude: f64) -> f64 {
        let sin = latitude.sin();
        self.equatorial_radius / (1.0 - self.eccentricity_squared() * sin * sin).sqrt()
    }
}
