//! What a run checks after every accepted step, and why each bound is where it is.
//!
//! # Gimbal lock
//!
//! With Euler angles the attitude rates are 4.60's
//! φ̇ = p + (q sin φ + r cos φ) tan θ and ψ̇ = (q sin φ + r cos φ) sec θ. The state holds the
//! pitch θ rounded to f64, an error δθ of up to about ε|θ| (ε = 2.2·10⁻¹⁶, one rounding, with a
//! factor 2 to spare). Since cos(θ + δθ) = cos θ − sin θ·δθ, sec θ and tan θ then carry a
//! relative error of |tan θ|·δθ ≈ ε|θ|/|cos θ| near ±90°, however exactly the cosine is
//! evaluated: every evaluation of the rates has it, and no step size removes it. The run stops
//! before it exceeds a bound η:
//!
//! ```text
//! |cos θ| < ε|θ| / η,   η = min(rtol, 1e-8) for dop853 and dopri5, 1e-8 for a fixed step
//! ```
//!
//! so the rates are never less accurate than an adaptive run's steps are asked to be, nor than
//! 10⁻⁸ (where a fixed-step run has no tolerance to go by). At θ = 90° and η = 10⁻⁸ the bound
//! is |cos θ| < 3.5·10⁻⁸: within 3.5·10⁻⁸ rad (2·10⁻⁶ degrees) of the pole; at rtol = 10⁻¹⁰,
//! 3.5·10⁻⁶. The band is narrow, and a step can jump it (a fixed step always may; so may an
//! adaptive step on a pure pitch, whose rates stay finite): the run also stops when the pitch
//! has crossed ±90° (mod 180°) since the last check, i.e. when θ/π + ½ has changed its integer
//! part. Both take a multiplication, a floor and a comparison per step, no cosine.
//!
//! # A fixed step against the rate of turn
//!
//! A body turning at |ω| turns its body-axis velocity and its attitude: the linearised motion
//! has eigenvalues ±i|ω| (for a free body, the nutation's frequency is at most |ω| too, by the
//! triangle inequality of the moments). A fixed-step method multiplies such a mode by R(iy)
//! per step, y = h|ω|, where the exact motion turns it by e^{iy}; it is stable while
//! |R(iy)| ≤ 1, its stability interval on the imaginary axis:
//!
//! - **rk4**: |1 + z + z²/2 + z³/6 + z⁴/24| ≤ 1 at z = iy for |y| ≤ 2√2 ≈ 2.83
//!   ([`RK4_LIMIT`]); beyond it the run stops ([`RunError::StepTooLarge`]);
//! - **symplectic-euler** on the pendulum, a separable oscillator θ̈ = −ω₀² sin θ: the step's
//!   matrix has trace 2 − y², stable while y < 2 ([`SYMPLECTIC_EULER_LIMIT`]); beyond it the
//!   run stops;
//! - **euler**: |1 + iy| = √(1 + y²) > 1 for every y ≠ 0: explicit Euler grows every rotation,
//!   whatever the step, so there is no limit to stop at and the run is not stopped (a step
//!   far too long overflows the state, and the run stops there, naming the component);
//! - **symplectic-euler** on any other family kicks the body-axis velocities and rates
//!   together from the state at the start of the step, so it turns them exactly as explicit
//!   Euler does, unstable for every step: it is treated as explicit Euler;
//! - **lie-midpoint** (implicit midpoint) is stable for every step on the imaginary axis; its
//!   fixed-point iteration reports a step too long itself (`NotConverged`).
//!
//! Stable is not accurate: rk4 at h|ω| = 2.5 damps a rotation to nothing within a few turns.
//! So every fixed-step method also has an accuracy bound, the y at which one turn of the mode
//! (2π/y steps) accumulates an error of 10 % ([`TURN_ERROR`]), (2π/y)·|R(iy) − e^{iy}| = 0.1:
//! y ≈ 0.0318 for explicit Euler, 1.18 for rk4, 0.605 for symplectic Euler on the oscillator
//! (its phase; it keeps the amplitude) ([`Scheme::accuracy_bound`]). Beyond it the run goes on,
//! and its summary warns ([`Report::warnings`](super::Report::warnings)) with the largest y
//! reached, its time, the error per turn there and the step that would meet the bound.
//!
//! The rate is |ω| = |(p, q, r)| for a spatial body; for a top the larger of |ω| and its
//! swing's frequency √(Mg|h|/I), I the smaller transverse moment about the pivot; |r| for a
//! planar body in body axes; and a pendulum's small-swing frequency ω₀ = √(Mgh/I₀), the largest
//! of its linearisation (ω₀√|cos θ|). A planar body in space axes has no rotation among its
//! state's rates (its body-axis loads turn with ψ, a forcing, not an eigenvalue), and is not
//! checked. Damping is not checked either: a step too long for it blows the state up, and the
//! run stops there naming the state component or the load input that stopped being finite.
//! The check compares squares, so it costs a few multiplications per step.

use super::{Body, BodyScene, RunError};
use crate::models::{Family, Kinematics};
use crate::scene::Method;
use std::f64::consts::PI;
use std::ops::Range;

/// The relative error the Euler-angle rates may carry from the rounding of θ, at most: the
/// bound η of the gimbal-lock check for a fixed step, and its ceiling for an adaptive one.
pub const RATE_ERROR: f64 = 1e-8;

/// RK4's stability interval on the imaginary axis: h·|ω| ≤ 2√2.
pub const RK4_LIMIT: f64 = 2.0 * std::f64::consts::SQRT_2;

/// Symplectic Euler's stability limit for the harmonic oscillator: h·ω < 2.
pub const SYMPLECTIC_EULER_LIMIT: f64 = 2.0;

/// The error one turn of a rotation may accumulate before the summary warns: 10 %.
pub const TURN_ERROR: f64 = 0.1;

/// How a fixed-step method acts on a rotation ż = iωz, one step being z ↦ R(ih|ω|) z.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    /// R(iy) = 1 + iy: explicit Euler, and symplectic Euler on rates it kicks together.
    Euler,
    /// R(iy) = 1 + iy − y²/2 − iy³/6 + y⁴/24.
    Rk4,
    /// Symplectic Euler on the separable oscillator: a rotation by φ, cos φ = 1 − y²/2.
    SymplecticOscillator,
}

impl Scheme {
    /// The largest y = h|ω| at which the scheme is stable on the imaginary axis; `None` where it
    /// is unstable for every step (explicit Euler).
    pub fn stability_limit(self) -> Option<f64> {
        match self {
            Scheme::Euler => None,
            Scheme::Rk4 => Some(RK4_LIMIT),
            Scheme::SymplecticOscillator => Some(SYMPLECTIC_EULER_LIMIT),
        }
    }

    /// The error one turn accumulates at y = h|ω|: (2π/y)·|R(iy) − e^{iy}|, the steps of a
    /// turn times how far one step leaves a unit rotation from where it should be.
    ///
    /// ```
    /// use eom::kinds::body::guard::Scheme;
    /// // Explicit Euler's one-step error is about y²/2, so a turn's is about πy.
    /// assert!((Scheme::Euler.turn_error(1e-3) - std::f64::consts::PI * 1e-3).abs() < 1e-8);
    /// ```
    pub fn turn_error(self, y: f64) -> f64 {
        let (re, im) = match self {
            Scheme::Euler => (1.0, y),
            Scheme::Rk4 => {
                let y2 = y * y;
                (1.0 - y2 / 2.0 + y2 * y2 / 24.0, y - y * y2 / 6.0)
            }
            Scheme::SymplecticOscillator => {
                let phi = (1.0 - y * y / 2.0).clamp(-1.0, 1.0).acos();
                (phi.cos(), phi.sin())
            }
        };
        let step = (re - y.cos()).hypot(im - y.sin());
        2.0 * PI / y * step
    }

    /// The y = h|ω| at which one turn accumulates [`TURN_ERROR`] (found by bisection; the
    /// turn's error grows with y up to the stability limit): 0.0318 for explicit Euler, 1.18
    /// for rk4, 0.605 for symplectic Euler on the oscillator.
    pub fn accuracy_bound(self) -> f64 {
        let (mut low, mut high) = (1e-9, self.stability_limit().unwrap_or(2.0));
        for _ in 0..100 {
            let middle = 0.5 * (low + high);
            if self.turn_error(middle) < TURN_ERROR {
                low = middle;
            } else {
                high = middle;
            }
        }
        low
    }
}

/// The least |cos θ| a run with Euler angles goes on at, for a pitch θ and the run's relative
/// tolerance (`None` for a fixed step): ε|θ|/η, η = min(rtol, [`RATE_ERROR`]).
///
/// ```
/// let bound = eom::kinds::body::guard::gimbal_bound(std::f64::consts::FRAC_PI_2, None);
/// assert!((bound - 3.49e-8).abs() < 1e-10);
/// ```
pub fn gimbal_bound(theta: f64, rtol: Option<f64>) -> f64 {
    let eta = rtol.map_or(RATE_ERROR, |r| r.min(RATE_ERROR));
    f64::EPSILON * theta.abs() / eta
}

/// The checks of one run, and what they found.
pub(crate) struct Guard {
    pitch: Option<Pitch>,
    rate: Option<Rate>,
    stop: Option<RunError>,
}

/// The gimbal-lock check of an Euler-angle attitude.
struct Pitch {
    /// θ's index in the state.
    index: usize,
    /// The run's rtol, `None` for a fixed step.
    rtol: Option<f64>,
    /// The integer part of θ/π + ½ at the last check, and its time: it changes where θ
    /// crosses ±90°.
    band: Option<(f64, f64)>,
}

/// The step-against-rate check of a fixed-step run.
struct Rate {
    /// The rates whose norm is the rate of turn (empty: only `floor`).
    entries: Range<usize>,
    /// A rate the state turns at whatever its rates (a swing's frequency), rad/s.
    floor: f64,
    /// The step taken, s: each interval between rows in equal steps of at most `written`.
    step: f64,
    /// `integrator.step` as written, s.
    written: f64,
    /// The method's name in scene files.
    method: &'static str,
    scheme: Scheme,
    /// [`Scheme::accuracy_bound`], squared, over h².
    warn_squared: f64,
    /// [`Scheme::stability_limit`], squared, over h².
    stop_squared: f64,
    /// The largest rate beyond the accuracy bound so far, and its time.
    worst: Option<(f64, f64)>,
}

impl Guard {
    /// The checks `scene` needs: gimbal lock for Euler-angle kinematics, the rate of turn for
    /// a fixed-step method.
    pub(crate) fn new(scene: &BodyScene) -> Self {
        let info = scene.selection.info;
        let spec = &scene.integrator;
        // The pitch θ of an Euler-angle attitude, where the catalog's layout has one.
        let pitch = (info.kinematics == Some(Kinematics::Euler))
            .then(|| info.state.iter().position(|name| *name == "theta"))
            .flatten()
            .map(|index| Pitch {
                index,
                rtol: spec.adaptive.map(|options| options.rtol),
                band: None,
            });
        // Symplectic Euler is symplectic for the pendulum only: the other families' rotation
        // lives among the rates it kicks together, which it turns as explicit Euler does.
        let scheme = match (spec.method, info.family) {
            (Method::Rk4, _) => Some(Scheme::Rk4),
            (Method::SymplecticEuler, Family::Pendulum) => Some(Scheme::SymplecticOscillator),
            (Method::Euler | Method::SymplecticEuler, _) => Some(Scheme::Euler),
            (Method::Dop853 | Method::Dopri5 | Method::LieMidpoint, _) => None,
        };
        let turning = match (&scene.body, info.family) {
            (Body::Pendulum(p), _) => Some((0..0, p.natural_frequency().unwrap_or(0.0))),
            (Body::Spatial { .. }, _) => Some((3..6, 0.0)),
            (Body::Planar { .. }, Family::PlanarAtG | Family::PlanarMidship) => Some((2..3, 0.0)),
            (Body::Planar { .. }, _) => None,
            (
                Body::Top {
                    mass,
                    inertia,
                    h,
                    g,
                },
                _,
            ) => {
                let transverse = inertia.ixx().min(inertia.iyy()) + mass * h * h;
                Some((0..3, (mass * g * h.abs() / transverse).sqrt()))
            }
        };
        let written = spec.step.unwrap_or(0.0);
        let step = match written > 0.0 {
            true => crate::integrate::segment::step_taken(written, scene.every),
            false => written,
        };
        let rate = scheme.zip(turning).map(|(scheme, (entries, floor))| {
            let per_step = |y: f64| (y / step).powi(2);
            Rate {
                entries,
                floor,
                step,
                written,
                method: spec.method.name(),
                scheme,
                warn_squared: per_step(scheme.accuracy_bound()),
                stop_squared: scheme.stability_limit().map_or(f64::INFINITY, per_step),
                worst: None,
            }
        });
        Guard {
            pitch,
            rate,
            stop: None,
        }
    }

    /// Checks the state `y` at `t`; `false` once the run must stop (the first reason is kept,
    /// for [`Guard::stop`]).
    pub(crate) fn check(&mut self, t: f64, y: &[f64]) -> bool {
        if self.stop.is_some() {
            return false;
        }
        if let Some(pitch) = self.pitch.as_mut() {
            self.stop = pitch.check(t, y[pitch.index]);
        }
        if self.stop.is_none()
            && let Some(rate) = self.rate.as_mut()
        {
            self.stop = rate.check(t, y);
        }
        self.stop.is_none()
    }

    /// Why a check stopped the run, if one did.
    pub(crate) fn stop(&mut self) -> Option<RunError> {
        self.stop.take()
    }

    /// What the run should say without stopping: the largest h·|ω| beyond the method's
    /// accuracy bound.
    pub(crate) fn warnings(&self) -> Vec<String> {
        self.rate
            .as_ref()
            .and_then(Rate::warning)
            .into_iter()
            .collect()
    }
}

impl Pitch {
    fn check(&mut self, t: f64, theta: f64) -> Option<RunError> {
        if !theta.is_finite() {
            return None;
        }
        // The poles θ = (n − ½)π are where s = θ/π + ½ is an integer; the distance to the
        // nearest is π·min(frac s, 1 − frac s), which is |cos θ| to a relative 10⁻¹⁵ inside
        // the bound.
        let s = theta / PI + 0.5;
        let band = s.floor();
        let fraction = s - band;
        let distance = PI * fraction.min(1.0 - fraction);
        let bound = gimbal_bound(theta, self.rtol);
        let crossed_since = self
            .band
            .and_then(|(before, since)| (before != band).then_some(since));
        self.band = Some((band, t));
        (crossed_since.is_some() || distance < bound).then(|| RunError::GimbalLock {
            t,
            pitch_deg: theta.to_degrees(),
            cos_pitch: theta.cos(),
            bound,
            crossed_since,
        })
    }
}

impl Rate {
    /// The rate's name in messages: the floor's when it is the larger.
    fn name(&self, turn: f64) -> &'static str {
        match (self.entries.len(), turn <= self.floor) {
            (0, _) | (_, true) => "ω₀",
            (1, false) => "|r|",
            _ => "|ω|",
        }
    }

    fn check(&mut self, t: f64, y: &[f64]) -> Option<RunError> {
        let squared = y[self.entries.clone()]
            .iter()
            .map(|w| w * w)
            .sum::<f64>()
            .max(self.floor * self.floor);
        if squared > self.stop_squared {
            let turn = squared.sqrt();
            return Some(RunError::StepTooLarge {
                t,
                method: self.method,
                rate: turn,
                rate_name: self.name(turn),
                step: self.step,
                limit: self.scheme.stability_limit().unwrap_or(f64::INFINITY),
                accurate_step: self.scheme.accuracy_bound() / turn,
            });
        }
        if squared > self.warn_squared && self.worst.is_none_or(|(_, w)| squared > w * w) {
            self.worst = Some((t, squared.sqrt()));
        }
        None
    }

    fn warning(&self) -> Option<String> {
        let (t, turn) = self.worst?;
        let y = self.step * turn;
        let name = self.name(turn);
        let why = match (self.scheme, self.method) {
            (Scheme::Euler, "euler") => {
                " (explicit Euler grows every rotation, by √(1 + (h·ω)²) a step, whatever the \
                 step)"
            }
            (Scheme::Euler, _) => {
                " (symplectic-euler kicks the body's velocities and rates together, so it turns \
                 them as explicit Euler does, growing them whatever the step)"
            }
            _ => "",
        };
        let taken = match self.step == self.written {
            true => String::new(),
            false => format!(
                ", the step taken: `integrator.step` = {} s written, each row's interval run in \
                 equal steps no longer",
                crate::Short(self.written)
            ),
        };
        Some(format!(
            "{}: h·{name} reached {y:.4} at t = {} s (h = {} s{taken}, {name} = {turn:.3} \
             rad/s), where a rotation at {name} is off by {:.0} % per turn{why}; a step ≤ \
             {:.3e} s keeps it within {:.0} % (h·{name} ≤ {:.4})",
            self.method,
            super::solve::seconds(t),
            crate::Short(self.step),
            100.0 * self.scheme.turn_error(y),
            self.scheme.accuracy_bound() / turn,
            100.0 * TURN_ERROR,
            self.scheme.accuracy_bound(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bounds_are_where_the_docs_put_them() {
        let rk4 = |y: f64| 1.0 - y * y / 2.0 + y.powi(4) / 24.0;
        let rk4_im = |y: f64| y - y.powi(3) / 6.0;
        // |R(iy)| = 1 at the limit, below it inside, above it beyond.
        let modulus = |y: f64| rk4(y).hypot(rk4_im(y));
        assert!((modulus(RK4_LIMIT) - 1.0).abs() < 1e-12);
        assert!(modulus(0.99 * RK4_LIMIT) < 1.0 && modulus(1.01 * RK4_LIMIT) > 1.0);
        for (scheme, bound) in [
            (Scheme::Euler, 0.0318),
            (Scheme::Rk4, 1.18),
            (Scheme::SymplecticOscillator, 0.605),
        ] {
            let found = scheme.accuracy_bound();
            assert!(
                (found - bound).abs() < 1e-3 * bound.max(1.0),
                "{scheme:?}: {found}"
            );
            assert!((scheme.turn_error(found) - TURN_ERROR).abs() < 1e-9);
        }
        // A turn's error grows with y up to the stability limit (the bisection relies on it).
        for scheme in [Scheme::Euler, Scheme::Rk4, Scheme::SymplecticOscillator] {
            let limit = scheme.stability_limit().unwrap_or(2.0);
            let errors: Vec<f64> = (1..200)
                .map(|k| scheme.turn_error(limit * k as f64 / 200.0))
                .collect();
            assert!(errors.windows(2).all(|w| w[0] < w[1]), "{scheme:?}");
        }
    }

    #[test]
    fn the_gimbal_bound_is_the_rounding_of_the_pitch_over_the_rate_error() {
        let quarter = std::f64::consts::FRAC_PI_2;
        assert!((gimbal_bound(quarter, None) - 3.4879e-8).abs() < 1e-12);
        assert_eq!(
            gimbal_bound(quarter, Some(1e-6)),
            gimbal_bound(quarter, None)
        );
        assert!((gimbal_bound(quarter, Some(1e-10)) - 3.4879e-6).abs() < 1e-10);
        // The distance the check measures is |cos θ| to far better than the bound.
        let mut pitch = Pitch {
            index: 0,
            rtol: None,
            band: None,
        };
        for offset in [1e-6, 3.6e-8] {
            assert!(pitch.check(0.0, quarter - offset).is_none(), "{offset}");
        }
        let near = pitch.check(0.0, quarter - 3.4e-8);
        assert!(matches!(
            near,
            Some(RunError::GimbalLock {
                crossed_since: None,
                ..
            })
        ));
        // Past the pole within one step, from a safe distance on either side.
        let mut pitch = Pitch {
            index: 0,
            rtol: None,
            band: None,
        };
        assert!(pitch.check(1.0, quarter - 0.01).is_none());
        let crossed = pitch.check(2.0, quarter + 0.01);
        assert!(matches!(
            crossed,
            Some(RunError::GimbalLock {
                crossed_since: Some(1.0),
                ..
            })
        ));
    }
}
