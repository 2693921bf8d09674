//! The swing test: a model's radius of gyration from the period of its swing as a compound
//! pendulum (4.24–4.29).
//!
//! A body swinging about a horizontal pivot O, with G at distance h below it, obeys
//! `I₀ θ̈ = −M g h sin θ` (4.24). For small swings its period is `T₀ = 2π √(I₀ / (M g h))`
//! (4.27), so timing the swing gives `κ = (T₀ / 2π) √(g h)` about the pivot (4.28) and, by
//! Steiner's theorem, `κ_G = √(κ² − h²)` about G (4.29).
//!
//! The chapter stops at small swings. A real swing has a finite amplitude θ₀, and its period is
//! longer: exactly `T = 4 K(m) / ω₀` with `m = sin²(θ₀/2)` and `ω₀ = √(M g h / I₀)`, that is
//! `T = T₀ · (2/π) K(m)`. [`SwingTest::solve`] removes that factor before applying 4.28, and
//! [`SwungBody`] gives the period and the exact large-amplitude motion
//! ([`crate::reference::LargeSwing`]) of a body of known parameters, to check it.

use crate::elliptic::complete_k;
use crate::reference::LargeSwing;
use crate::validate::positive;
use crate::{ParameterError, PendulumParameters};
use std::f64::consts::{FRAC_2_PI, PI};
use thiserror::Error;

/// Standard gravity, 9.80665 m/s².
pub const STANDARD_GRAVITY: f64 = 9.806_65;

/// Why a swing test or a swung body cannot be evaluated.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SwingError {
    /// A measured quantity (the period, the mass, `pivot_to_cg`, gravity) is not positive and
    /// finite, or a swung body has no period (`g` or `h` not positive); the error names it.
    #[error(transparent)]
    Parameter(#[from] ParameterError),
    /// The amplitude is negative, NaN, or so large that the body would go over the top.
    #[error("amplitude θ₀ = {degrees}° must be at least 0° and below 180°")]
    AmplitudeOutOfRange {
        /// The amplitude, in degrees.
        degrees: f64,
    },
    /// `κ ≤ h`: the period is too short for the pivot-to-G distance, and κ_G would be imaginary.
    #[error(
        "κ = {kappa} about the pivot is not larger than h = {pivot_to_cg}, so κ_G = √(κ² − h²) \
         would be imaginary (4.29): the period is too short for this h, or h is too long"
    )]
    ImaginaryGyradius {
        /// The radius of gyration about the pivot, from 4.28.
        kappa: f64,
        /// The pivot-to-G distance.
        pivot_to_cg: f64,
    },
    /// `times` and `angles` have different lengths.
    #[error("{times} times but {angles} angles")]
    LengthMismatch {
        /// Length of `times`.
        times: usize,
        /// Length of `angles`.
        angles: usize,
    },
    /// A sample is NaN or infinite.
    #[error("{field}[{index}] is not finite")]
    NotFiniteSample {
        /// `"times"` or `"angles"`.
        field: &'static str,
        /// The sample's index.
        index: usize,
    },
    /// The times do not increase strictly.
    #[error("times must increase strictly, but times[{index}] does not exceed times[{}]", index - 1)]
    TimesNotIncreasing {
        /// The first index where they do not.
        index: usize,
    },
    /// Fewer than two upward zero crossings: not even one full period was recorded.
    #[error("found {found} upward zero crossing(s); a period needs at least 2")]
    TooFewCrossings {
        /// How many were found.
        found: usize,
    },
}

/// The ratio `T / T₀ = (2/π) K(sin²(θ₀/2))` of the period at amplitude θ₀ (radians) to the
/// small-amplitude period of 4.27.
///
/// ```
/// // At 90° a pendulum is 18.034 % slower than the small-amplitude formula says.
/// let factor = eom::swing::period_factor(std::f64::consts::FRAC_PI_2).unwrap();
/// assert!((factor - 1.180_340_599).abs() < 1e-9);
/// ```
pub fn period_factor(amplitude: f64) -> Result<f64, SwingError> {
    if !(0.0..PI).contains(&amplitude) {
        return Err(SwingError::AmplitudeOutOfRange {
            degrees: amplitude.to_degrees(),
        });
    }
    let m = (0.5 * amplitude).sin().powi(2);
    let k = complete_k(m).map_err(|_| SwingError::AmplitudeOutOfRange {
        degrees: amplitude.to_degrees(),
    })?;
    Ok(FRAC_2_PI * k)
}

/// A body hung on the swing-test rig: the motion and the period that a swing test would time
/// on a pendulum of known parameters — the forward model that [`SwingTest::solve`] inverts.
///
/// ```
/// use eom::PendulumParameters;
/// use eom::swing::{STANDARD_GRAVITY, SwungBody};
/// // κ_G = 0.25 m, hung 0.12 m from G, 20 kg.
/// let parameters = PendulumParameters::from_gyradius(0.25, 20.0, STANDARD_GRAVITY, 0.12).unwrap();
/// let body = SwungBody::new(&parameters).unwrap();
/// // A perfect measurement at 15° gives κ_G back through 4.28 and 4.29.
/// let result = body.measurement(15f64.to_radians()).unwrap().solve().unwrap();
/// assert!((result.kappa_g - 0.25).abs() < 1e-14);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwungBody {
    parameters: PendulumParameters,
    omega0: f64,
}

impl SwungBody {
    /// The body of `parameters` on the rig. It must swing: `g > 0` and `h > 0`, or the error
    /// names whichever is not (see [`PendulumParameters::natural_frequency`]).
    pub fn new(parameters: &PendulumParameters) -> Result<Self, SwingError> {
        Ok(Self {
            parameters: *parameters,
            omega0: parameters.natural_frequency()?,
        })
    }

    /// The parameters of the body on the rig.
    pub fn parameters(&self) -> &PendulumParameters {
        &self.parameters
    }

    /// `ω₀ = √(M g h / I₀)`, the small-amplitude angular frequency (4.27).
    pub fn natural_frequency(&self) -> f64 {
        self.omega0
    }

    /// The small-amplitude period `T₀ = 2π √(I₀ / (M g h))` (4.27).
    pub fn small_amplitude_period(&self) -> f64 {
        2.0 * PI / self.omega0
    }

    /// The exact period at amplitude θ₀ (radians): `T = T₀ (2/π) K(sin²(θ₀/2))`.
    pub fn period(&self, amplitude: f64) -> Result<f64, SwingError> {
        Ok(self.small_amplitude_period() * period_factor(amplitude)?)
    }

    /// The exact motion after release from rest at θ = θ₀ (radians) at t = 0.
    pub fn released_from(&self, amplitude: f64) -> Result<LargeSwing, SwingError> {
        period_factor(amplitude)?;
        Ok(LargeSwing::new(&self.parameters, amplitude)?)
    }

    /// What a perfect swing test at amplitude θ₀ (radians) records: the exact period, with the
    /// body's `h`, `M` and `g`.
    pub fn measurement(&self, amplitude: f64) -> Result<SwingTest, SwingError> {
        Ok(SwingTest {
            period: self.period(amplitude)?,
            pivot_to_cg: self.parameters.h(),
            mass: self.parameters.mass(),
            gravity: self.parameters.g(),
            amplitude,
        })
    }
}

/// What a swing test measures: the period, the pivot-to-G distance, the mass, gravity and
/// (optionally) the amplitude of the swing in radians (0 for the chapter's small-swing formula).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwingTest {
    /// The measured period T.
    pub period: f64,
    /// The distance h from the pivot O to G.
    pub pivot_to_cg: f64,
    /// The mass M.
    pub mass: f64,
    /// Gravity g (use [`STANDARD_GRAVITY`] unless it was measured).
    pub gravity: f64,
    /// The amplitude θ₀ of the swing in radians; 0 means small swings.
    pub amplitude: f64,
}

/// The results of a swing test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SwingResult {
    /// `T / T₀ = (2/π) K(sin²(θ₀/2))`, the lengthening of the period by the amplitude (1 when
    /// the amplitude is 0).
    pub period_factor: f64,
    /// `T₀`, the small-amplitude period that the measured one corresponds to.
    pub small_amplitude_period: f64,
    /// `κ = (T₀ / 2π) √(g h)`, the radius of gyration about the pivot (4.28).
    pub kappa_pivot: f64,
    /// `I₀ = M κ²`, the moment of inertia about the pivot.
    pub inertia_pivot: f64,
    /// `ℓ = κ² / h`, the length of the equivalent simple pendulum (4.26).
    pub equivalent_length: f64,
    /// `κ_G = √(κ² − h²)`, the radius of gyration about G (4.29).
    pub kappa_g: f64,
    /// `I_G = I₀ − M h² = M κ_G²` (4.29).
    pub inertia_g: f64,
}

impl SwingTest {
    /// Applies 4.28 and 4.29 to the small-amplitude period `T₀ = T / ((2/π) K(sin²(θ₀/2)))`.
    ///
    /// ```
    /// use eom::swing::{SwingTest, STANDARD_GRAVITY};
    /// let test = SwingTest { period: 2.0, pivot_to_cg: 0.5, mass: 10.0,
    ///                        gravity: STANDARD_GRAVITY, amplitude: 0.0 };
    /// let result = test.solve().unwrap();
    /// let kappa = 2.0 / (2.0 * std::f64::consts::PI) * (STANDARD_GRAVITY * 0.5_f64).sqrt();
    /// assert!((result.kappa_pivot - kappa).abs() < 1e-15);
    /// assert!((result.kappa_g - (kappa * kappa - 0.25).sqrt()).abs() < 1e-15);
    /// ```
    pub fn solve(&self) -> Result<SwingResult, SwingError> {
        let period = positive("period", self.period)?;
        let h = positive("pivot_to_cg", self.pivot_to_cg)?;
        let mass = positive("mass", self.mass)?;
        let gravity = positive("gravity", self.gravity)?;
        let factor = period_factor(self.amplitude)?;
        let small = period / factor;
        let kappa = small / (2.0 * PI) * (gravity * h).sqrt();
        let kappa_g_squared = (kappa - h) * (kappa + h);
        if kappa_g_squared <= 0.0 {
            return Err(SwingError::ImaginaryGyradius {
                kappa,
                pivot_to_cg: h,
            });
        }
        Ok(SwingResult {
            period_factor: factor,
            small_amplitude_period: small,
            kappa_pivot: kappa,
            inertia_pivot: mass * kappa * kappa,
            equivalent_length: kappa * kappa / h,
            kappa_g: kappa_g_squared.sqrt(),
            inertia_g: mass * kappa_g_squared,
        })
    }
}

/// The period of an oscillation sampled at `times`, from its upward zero crossings.
///
/// Each crossing time is found by cubic inverse interpolation: t as a cubic in θ through the
/// four samples around the crossing, evaluated at θ = 0 (linear interpolation where the four
/// samples are not strictly increasing, or at the ends of the record). The period is the
/// least-squares slope of crossing time against crossing number, which uses every crossing and
/// averages out timing noise.
///
/// ```
/// let times: Vec<f64> = (0..400).map(|i| i as f64 * 0.05).collect();
/// let angles: Vec<f64> = times.iter().map(|t| (2.0 * std::f64::consts::PI * t / 3.0).sin()).collect();
/// let period = eom::swing::measure_period(&times, &angles).unwrap();
/// assert!((period - 3.0).abs() < 1e-9);
/// ```
pub fn measure_period(times: &[f64], angles: &[f64]) -> Result<f64, SwingError> {
    check_samples(times, angles)?;
    let crossings: Vec<f64> = (0..times.len().saturating_sub(1))
        .filter(|&i| angles[i] < 0.0 && angles[i + 1] >= 0.0)
        .map(|i| crossing_time(times, angles, i))
        .collect();
    if crossings.len() < 2 {
        return Err(SwingError::TooFewCrossings {
            found: crossings.len(),
        });
    }
    Ok(least_squares_slope(&crossings))
}

fn check_samples(times: &[f64], angles: &[f64]) -> Result<(), SwingError> {
    if times.len() != angles.len() {
        return Err(SwingError::LengthMismatch {
            times: times.len(),
            angles: angles.len(),
        });
    }
    for (field, samples) in [("times", times), ("angles", angles)] {
        if let Some(index) = samples.iter().position(|x| !x.is_finite()) {
            return Err(SwingError::NotFiniteSample { field, index });
        }
    }
    match times.windows(2).position(|w| w[1] <= w[0]) {
        Some(i) => Err(SwingError::TimesNotIncreasing { index: i + 1 }),
        None => Ok(()),
    }
}

/// The time at which θ crosses zero upwards between samples `i` and `i + 1`.
fn crossing_time(times: &[f64], angles: &[f64], i: usize) -> f64 {
    if i >= 1 && i + 2 < times.len() {
        let nodes = i - 1..i + 3;
        if angles[nodes.clone()].windows(2).all(|w| w[1] > w[0]) {
            return lagrange_at_zero(&angles[nodes.clone()], &times[nodes]);
        }
    }
    let (a, b) = (angles[i], angles[i + 1]);
    times[i] + (times[i + 1] - times[i]) * (-a) / (b - a)
}

/// The Lagrange polynomial through `(x_j, y_j)` evaluated at x = 0.
fn lagrange_at_zero(x: &[f64], y: &[f64]) -> f64 {
    (0..x.len())
        .map(|j| {
            let weight: f64 = (0..x.len())
                .filter(|&k| k != j)
                .map(|k| -x[k] / (x[j] - x[k]))
                .product();
            y[j] * weight
        })
        .sum()
}

/// The slope of the least-squares line through `(n, values[n])`.
fn least_squares_slope(values: &[f64]) -> f64 {
    let n = values.len() as f64;
    let mean_index = 0.5 * (n - 1.0);
    let mean_value = values.iter().sum::<f64>() / n;
    let (covariance, variance) = values
        .iter()
        .enumerate()
        .fold((0.0, 0.0), |(c, v), (i, y)| {
            let di = i as f64 - mean_index;
            (c + di * (y - mean_value), v + di * di)
        });
    covariance / variance
}
