//! Gusts: the wind's speed fluctuating about its mean, drawn from a spectrum with a seed.
//!
//! The spectrum is NORSOK N-003's (also DNV-RP-C205's and ISO 19901-1's) for the wind over the
//! sea, the variance per hertz of the speed along the mean wind at height z,
//!
//! ```text
//! S(f) = 320 (U₀/10)² (z/10)^0.45 / (1 + f̃ⁿ)^(5/(3n)),   f̃ = 172 f (z/10)^(2/3) (U₀/10)^(−3/4),
//! ```
//!
//! n = 0.468, U₀ the one-hour mean speed at 10 m (m/s), f in Hz, S in m²/s² per Hz. A
//! realisation is a sum of harmonics,
//!
//! ```text
//! g(t) = Σₖ aₖ cos(2π fₖ t + φₖ),   aₖ = √(2 ∫ S df over bin k),
//! ```
//!
//! over [`BINS`] bins of equal width up to [`HIGHEST_FREQUENCY`], each frequency drawn within
//! its bin and each phase over [0, 2π) from ChaCha8 seeded by the scene's seed, so that a seed
//! gives one series on every machine and the series does not repeat. Each bin's variance is
//! the spectrum's over it (Simpson's rule on 16 intervals), so the series' variance is the
//! spectrum's below the highest frequency, which [`Gust::variance`] gives beside the whole
//! spectrum's ([`Spectrum::variance`]): NORSOK's at U₀ = 20 m/s puts 86 % of it below 0.5 Hz;
//! the rest, faster than any ship's response, is left out. Only the speed fluctuates; the
//! direction is the mean wind's.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;

/// How many harmonics a series sums.
pub const BINS: usize = 250;

/// The highest frequency a series holds, Hz.
pub const HIGHEST_FREQUENCY: f64 = 0.5;

/// NORSOK's exponent n.
const NORSOK_N: f64 = 0.468;

/// Why gusts cannot be drawn; each names the key at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GustError {
    /// A value that is not a finite number, or out of its range.
    #[error("`{key}`: {reason}")]
    Invalid {
        /// The key, as the scene writes it (`environment.wind_height_m`).
        key: &'static str,
        /// What is wrong.
        reason: String,
    },
}

/// A spectrum of the wind's speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spectrum {
    /// NORSOK N-003's (module docs).
    Norsok {
        /// U₀, the one-hour mean speed at 10 m, m/s.
        mean_speed: f64,
        /// z, the height the gusts are at, m.
        height: f64,
    },
}

impl Spectrum {
    /// The spectrum as a scene names it (`"norsok"`), at `mean_speed` and `height`.
    pub fn named(name: &str, mean_speed: f64, height: f64) -> Result<Self, GustError> {
        let invalid = |key, reason: String| GustError::Invalid { key, reason };
        if name != "norsok" {
            return Err(invalid(
                "environment.wind_spectrum",
                format!("`{name}`: the spectra known are \"norsok\" (NORSOK N-003's)"),
            ));
        }
        if !(mean_speed.is_finite() && mean_speed > 0.0) {
            return Err(invalid(
                "environment.wind_m_s",
                format!("{mean_speed}: a gusting wind has a positive mean speed"),
            ));
        }
        if !(height.is_finite() && height > 0.0) {
            return Err(invalid(
                "environment.wind_height_m",
                format!("{height}: a height above the sea, positive"),
            ));
        }
        Ok(Spectrum::Norsok { mean_speed, height })
    }

    /// S(0), m²/s² per Hz, and f̃/f, s.
    fn scales(&self) -> (f64, f64) {
        let Spectrum::Norsok { mean_speed, height } = *self;
        let (speed, level) = (mean_speed / 10.0, height / 10.0);
        (
            320.0 * speed * speed * level.powf(0.45),
            172.0 * level.powf(2.0 / 3.0) * speed.powf(-0.75),
        )
    }

    /// S(f), m²/s² per Hz.
    pub fn density(&self, frequency: f64) -> f64 {
        let (at_zero, per_reduced) = self.scales();
        at_zero / (1.0 + (per_reduced * frequency).powf(NORSOK_N)).powf(5.0 / (3.0 * NORSOK_N))
    }

    /// ∫ S df from `low` to `high`, Simpson's rule on `intervals`.
    fn integral(&self, low: f64, high: f64, intervals: usize) -> f64 {
        simpson(|f| self.density(f), low, high, intervals)
    }

    /// The variance of the whole spectrum, m²/s²: ∫₀^∞ S df. With x = f̃ it is
    /// (S(0)/(172 …)) ∫₀^∞ (1 + xⁿ)^(−5/(3n)) dx, and t = xⁿ/(1 + xⁿ) turns the integral into
    /// Euler's B(1/n, 2/(3n))/n, taken here by Simpson's rule on [0, 1] (20 000 intervals;
    /// its integrand's (1 − t)^0.42 at t = 1 leaves an error below 10⁻⁶ of it).
    pub fn variance(&self) -> f64 {
        const N: f64 = NORSOK_N;
        let (at_zero, per_reduced) = self.scales();
        let beta = |t: f64| t.powf(1.0 / N - 1.0) * (1.0 - t).powf(2.0 / (3.0 * N) - 1.0);
        let integral = simpson(beta, 0.0, 1.0, 20_000);
        at_zero / per_reduced * integral / N
    }
}

/// ∫ f from `low` to `high` by Simpson's rule on `intervals` (even).
fn simpson(f: impl Fn(f64) -> f64, low: f64, high: f64, intervals: usize) -> f64 {
    let h = (high - low) / intervals as f64;
    let weight = |i: usize| match i {
        0 => 1.0,
        i if i == intervals => 1.0,
        i if i % 2 == 1 => 4.0,
        _ => 2.0,
    };
    let sum: f64 = (0..=intervals)
        .map(|i| weight(i) * f(low + i as f64 * h))
        .sum();
    sum * h / 3.0
}

/// One realisation of a spectrum: the harmonics it sums.
#[derive(Debug, Clone, PartialEq)]
pub struct Gust {
    /// The spectrum drawn from.
    pub spectrum: Spectrum,
    /// The seed drawn with.
    pub seed: u64,
    /// (2π fₖ, aₖ, φₖ) of each harmonic.
    harmonics: Vec<[f64; 3]>,
}

impl Gust {
    /// The realisation of `spectrum` that `seed` draws (module docs).
    pub fn new(spectrum: Spectrum, seed: u64) -> Self {
        let mut stream = ChaCha8Rng::seed_from_u64(seed);
        let width = HIGHEST_FREQUENCY / BINS as f64;
        let harmonics = (0..BINS)
            .map(|k| {
                let low = k as f64 * width;
                let frequency = low + width * stream.random::<f64>();
                let phase = 2.0 * PI * stream.random::<f64>();
                let amplitude = (2.0 * spectrum.integral(low, low + width, 16)).sqrt();
                [2.0 * PI * frequency, amplitude, phase]
            })
            .collect();
        Gust {
            spectrum,
            seed,
            harmonics,
        }
    }

    /// g(t), m/s: the wind's speed less its mean at `t`.
    pub fn at(&self, t: f64) -> f64 {
        (self.harmonics.iter())
            .map(|[omega, amplitude, phase]| amplitude * (omega * t + phase).cos())
            .sum()
    }

    /// The series' variance, m²/s²: Σ aₖ²/2, the spectrum's below [`HIGHEST_FREQUENCY`].
    pub fn variance(&self) -> f64 {
        self.harmonics.iter().map(|[_, a, _]| 0.5 * a * a).sum()
    }
}
