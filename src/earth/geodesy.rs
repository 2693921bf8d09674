//! Geodetic coordinates and the Earth-centred Earth-fixed frame.
//!
//! ECEF: the origin at the Earth's centre, X through the equator at the prime meridian, Z
//! through the north pole, Y completing the right hand (90° E). A point's geodetic latitude φ is
//! the angle of the ellipsoid's normal through it to the equator, its altitude h the distance
//! along that normal, so that (N the prime-vertical radius, e² the eccentricity squared)
//!
//! ```text
//! X = (N + h) cos φ cos λ,   Y = (N + h) cos φ sin λ,   Z = (N(1 − e²) + h) sin φ.
//! ```
//!
//! The inverse has no closed form as simple: [`Ecef::geodetic`] starts from Bowring's latitude
//! (1976; good to a millimetre on Earth) and takes Newton's steps on the latitude's equation
//! until it moves by less than 1e-15 rad, two or three of them (on a sphere, one). Near the
//! poles the altitude is read from Z rather than from the distance to the axis, where the
//! first divides by cos φ.

use super::Ellipsoid;

/// A position in geodetic coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Geodetic {
    /// φ, rad, north positive.
    pub latitude: f64,
    /// λ, rad, east positive.
    pub longitude: f64,
    /// h over the ellipsoid, m.
    pub altitude: f64,
}

/// A position in the Earth-centred Earth-fixed frame, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ecef(pub [f64; 3]);

impl Geodetic {
    /// The position in ECEF over `ellipsoid`.
    pub fn ecef(&self, ellipsoid: &Ellipsoid) -> Ecef {
        let n = ellipsoid.prime_vertical_radius(self.latitude);
        let (sin_lat, cos_lat) = self.latitude.sin_cos();
        let (sin_lon, cos_lon) = self.longitude.sin_cos();
        let across = (n + self.altitude) * cos_lat;
        Ecef([
            across * cos_lon,
            across * sin_lon,
            (n * (1.0 - ellipsoid.eccentricity_squared()) + self.altitude) * sin_lat,
        ])
    }
}

impl Ecef {
    /// The geodetic coordinates over `ellipsoid` (module docs); at the centre itself, where no
    /// normal passes, the latitude is 0 and the altitude −a.
    pub fn geodetic(&self, ellipsoid: &Ellipsoid) -> Geodetic {
        let [x, y, z] = self.0;
        let e2 = ellipsoid.eccentricity_squared();
        let (a, b) = (ellipsoid.equatorial_radius, ellipsoid.polar_radius());
        let p = x.hypot(y);
        let longitude = y.atan2(x);
        // Bowring's start: the parametric latitude of the point's projection.
        let second = e2 / (1.0 - e2);
        let parametric = (z * a).atan2(p * b);
        let (sin, cos) = parametric.sin_cos();
        let mut latitude = (z + second * b * sin.powi(3)).atan2(p - e2 * a * cos.powi(3));
        for _ in 0..8 {
            let n = ellipsoid.prime_vertical_radius(latitude);
            // tan φ = Z / (p (1 − e² N/(N + h))), with N + h = p / cos φ.
            let next = (z + e2 * n * latitude.sin()).atan2(p);
            let moved = (next - latitude).abs();
            latitude = next;
            if moved < 1e-15 {
                break;
            }
        }
        let n = ellipsoid.prime_vertical_radius(latitude);
        let (sin, cos) = latitude.sin_cos();
        let altitude = if cos.abs() > sin.abs() {
            p / cos - n
        } else {
            z / sin - n * (1.0 - e2)
        };
        Geodetic {
            latitude,
            longitude,
            altitude,
        }
    }

    /// The distance from the Earth's centre, m.
    pub fn radius(&self) -> f64 {
        let [x, y, z] = self.0;
        (x * x + y * y + z * z).sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    const NESC_SPHERE: f64 = crate::earth::NESC.sphere_radius;

    /// Geodetic → ECEF → geodetic returns each coordinate to rounding, from the equator to
    /// the poles, from the sea floor to orbit, on WGS-84 and on a sphere.
    #[test]
    fn the_conversions_are_each_others_inverse() {
        for ellipsoid in [Ellipsoid::WGS84, Ellipsoid::sphere(NESC_SPHERE)] {
            for latitude_deg in [-90.0, -89.9999, -60.0, -1e-9, 0.0, 36.019, 45.0, 89.0, 90.0] {
                for altitude in [-11_000.0, 0.0, 3052.0, 400_000.0, 3.6e7] {
                    let given = Geodetic {
                        latitude: f64::to_radians(latitude_deg),
                        longitude: f64::to_radians(-122.4),
                        altitude,
                    };
                    let back = given.ecef(&ellipsoid).geodetic(&ellipsoid);
                    assert!(
                        (back.latitude - given.latitude).abs() < 1e-14,
                        "{latitude_deg}° at {altitude} m: {}",
                        back.latitude.to_degrees()
                    );
                    assert!(
                        (back.altitude - altitude).abs() < 1e-8 * (1.0 + altitude.abs() / 1e6),
                        "{latitude_deg}° at {altitude} m: {} m",
                        back.altitude
                    );
                    if latitude_deg.abs() < 90.0 {
                        assert!((back.longitude - given.longitude).abs() < 1e-14);
                    }
                }
            }
        }
    }

    /// On the equator at the prime meridian, X is a + h; at the pole, Z is b + h.
    #[test]
    fn the_axes_are_where_the_frame_says() {
        let wgs84 = Ellipsoid::WGS84;
        let equator = Geodetic {
            latitude: 0.0,
            longitude: 0.0,
            altitude: 9144.0,
        };
        assert_eq!(equator.ecef(&wgs84).0, [6_378_137.0 + 9144.0, 0.0, 0.0]);
        let pole = Geodetic {
            latitude: std::f64::consts::FRAC_PI_2,
            longitude: 0.0,
            altitude: 0.0,
        };
        let z = pole.ecef(&wgs84).0[2];
        assert!((z - wgs84.polar_radius()).abs() < 1e-8, "{z}");
        assert!((wgs84.polar_radius() - 6_356_752.314_245).abs() < 1e-6);
    }
}
