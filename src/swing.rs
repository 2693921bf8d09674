//! The compound pendulum (4.24–4.29) and the swing test that uses it to measure a model's
//! radius of gyration.
//!
//! A body swinging about a horizontal pivot O, with G at distance h below it, obeys
//! `I₀ θ̈ = −M g h sin θ` (4.24). For small swings its period is `T₀ = 2π √(I₀ / (M g h))`
//! (4.27), so timing the swing gives `κ = (T₀ / 2π) √(g h)` about the pivot (4.28) and, by
//! Steiner's theorem, `κ_G = √(κ² − h²)` about G (4.29).
//!
//! The chapter stops at small swings. A real swing has a finite amplitude θ₀, and its period is
//! longer: exactly `T = 4 K(m) / ω₀` with `m = sin²(θ₀/2)` and `ω₀ = √(M g h / I₀)`, that is
//! `T = T₀ · (2/π) K(m)`. [`SwingTest::solve`] removes that factor before applying 4.28, and
//! [`CompoundPendulum::released_from`] gives the exact large-amplitude motion used to check it.

use crate::ParameterError;
use crate::elliptic::{complete_k, jacobi};
use crate::validate::positive;
use std::f64::consts::{FRAC_2_PI, PI};
use thiserror::Error;

/// Standard gravity, 9.80665 m/s².
pub const STANDARD_GRAVITY: f64 = 9.806_65;

/// Why a swing test or a pendulum cannot be evaluated.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SwingError {
    /// A quantity that must be positive (the period, the mass, `pivot_to_cg`, gravity) is zero,
    /// negative, NaN or infinite; the error names it.
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

/// A compound pendulum: moment of inertia `I₀` about the pivot, mass `M`, pivot-to-G distance
/// `h` and gravity `g` (4.24).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompoundPendulum {
    inertia_pivot: f64,
    mass: f64,
    pivot_to_cg: f64,
    gravity: f64,
}

impl CompoundPendulum {
    /// Builds the pendulum; every argument must be positive and finite, and `I₀ ≥ M h²`
    /// (the moment about G, 4.29, cannot be negative).
    pub fn new(
        inertia_pivot: f64,
        mass: f64,
        pivot_to_cg: f64,
        gravity: f64,
    ) -> Result<Self, SwingError> {
        let pendulum = Self {
            inertia_pivot: positive("inertia_pivot", inertia_pivot)?,
            mass: positive("mass", mass)?,
            pivot_to_cg: positive("pivot_to_cg", pivot_to_cg)?,
            gravity: positive("gravity", gravity)?,
        };
        if inertia_pivot <= mass * pivot_to_cg * pivot_to_cg {
            return Err(SwingError::ImaginaryGyradius {
                kappa: (inertia_pivot / mass).sqrt(),
                pivot_to_cg,
            });
        }
        Ok(pendulum)
    }

    /// The pendulum of a body with radius of gyration `κ_G` about G, swung at distance `h`
    /// from G: `I₀ = M (κ_G² + h²)` (4.29).
    pub fn from_gyradius(
        kappa_g: f64,
        mass: f64,
        pivot_to_cg: f64,
        gravity: f64,
    ) -> Result<Self, SwingError> {
        let kappa_g = positive("kappa_g", kappa_g)?;
        let h = positive("pivot_to_cg", pivot_to_cg)?;
        Self::new(mass * (kappa_g * kappa_g + h * h), mass, h, gravity)
    }

    /// `I₀`, the moment of inertia about the pivot.
    pub fn inertia_pivot(&self) -> f64 {
        self.inertia_pivot
    }

    /// `M g h`, the restoring moment per unit of sin θ (4.24).
    pub fn restoring_moment(&self) -> f64 {
        self.mass * self.gravity * self.pivot_to_cg
    }

    /// `ω₀ = √(M g h / I₀)`, the small-amplitude angular frequency (4.27).
    pub fn natural_frequency(&self) -> f64 {
        (self.restoring_moment() / self.inertia_pivot).sqrt()
    }

    /// The small-amplitude period `T₀ = 2π √(I₀ / (M g h))` (4.27).
    pub fn small_amplitude_period(&self) -> f64 {
        2.0 * PI / self.natural_frequency()
    }

    /// The exact period at amplitude θ₀ (radians): `T = T₀ (2/π) K(sin²(θ₀/2))`.
    pub fn period(&self, amplitude: f64) -> Result<f64, SwingError> {
        Ok(self.small_amplitude_period() * period_factor(amplitude)?)
    }

    /// The exact motion after release from rest at θ = θ₀ (radians) at t = 0.
    pub fn released_from(&self, amplitude: f64) -> Result<ExactSwing, SwingError> {
        period_factor(amplitude)?;
        let k = (0.5 * amplitude).sin();
        let m = k * k;
        let quarter = complete_k(m).map_err(|_| SwingError::AmplitudeOutOfRange {
            degrees: amplitude.to_degrees(),
        })?;
        Ok(ExactSwing {
            omega0: self.natural_frequency(),
            k,
            m,
            quarter,
        })
    }
}

/// The exact large-amplitude motion of a compound pendulum released from rest at θ₀.
///
/// With `k = sin(θ₀/2)`, `m = k²` and `u = ω₀ t + K(m)`:
/// `sin(θ/2) = k sn(u | m)` and `θ̇ = 2 k ω₀ cn(u | m)`.
/// At t = 0, sn(K) = 1 gives θ = θ₀ and cn(K) = 0 gives θ̇ = 0. Differentiating,
/// `½ cos(θ/2) θ̇ = k ω₀ cn dn` and `cos(θ/2) = √(1 − k² sn²) = dn`, which gives θ̇; then
/// `½ I₀ θ̇² + M g h (1 − cos θ) = 2 M g h k² (cn² + sn²) = M g h (1 − cos θ₀)`, the energy
/// integral 4.35 with `I₀ ω₀² = M g h`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExactSwing {
    omega0: f64,
    k: f64,
    m: f64,
    quarter: f64,
}

impl ExactSwing {
    /// θ(t), in radians.
    pub fn angle(&self, t: f64) -> f64 {
        2.0 * (self.k * self.jacobi(t).sn).asin()
    }

    /// θ̇(t), in radians per unit time.
    pub fn rate(&self, t: f64) -> f64 {
        2.0 * self.k * self.omega0 * self.jacobi(t).cn
    }

    /// The exact period `4 K(m) / ω₀`.
    pub fn period(&self) -> f64 {
        4.0 * self.quarter / self.omega0
    }

    fn jacobi(&self, t: f64) -> crate::elliptic::Jacobi {
        // m = sin²(θ₀/2) with θ₀ checked to lie in [0, π), so 0 ≤ m < 1 and jacobi cannot fail.
        jacobi(self.omega0 * t + self.quarter, self.m).expect("m checked in released_from")
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
