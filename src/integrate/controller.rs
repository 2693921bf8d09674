//! What the adaptive methods share besides their stepping loop (`adaptive.rs`): their
//! options, the weighted error norm, Hairer's initial step, and the PI step-size controller.
//!
//! The controller is Gustafsson's PI controller as Hairer's DOPRI5/DOP853 codes use it
//! (Hairer, Nørsett & Wanner, *Solving ODEs I*, §II.4): with the scaled error `err` of the
//! step, the new step is `h · clamp(err^(−α) · err_prev^β / safety⁻¹, fac_min, fac_max)`, where
//! α = 1/5 − 0.75β in DOPRI5 and α = 1/8 − 0.2β in DOP853, as in Hairer's codes. β = 0 is the
//! classical (integral-only) controller.

use nalgebra::{RealField, SVector};

use super::{IntegrateError, OdeSystem, lit};

/// Tolerances and limits of an adaptive method.
///
/// A step is accepted when the root mean square of `errᵢ / (atol + rtol · max(|yᵢ|, |ŷᵢ|))`
/// is at most one (Hairer's norm).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdaptiveOptions {
    /// Relative tolerance.
    pub rtol: f64,
    /// Absolute tolerance.
    pub atol: f64,
    /// The smallest step allowed; the run fails with [`IntegrateError::StepSizeTooSmall`]
    /// below it (and always when a step no longer changes `t`).
    pub h_min: f64,
    /// The largest step allowed (`f64::INFINITY` for the length of the interval).
    pub h_max: f64,
    /// The initial step; `None` for Hairer's heuristic.
    pub h0: Option<f64>,
    /// The most steps (accepted plus rejected) a run may take.
    pub max_steps: usize,
    /// The PI controller's β in [0, 0.2] (0.04 for DOPRI5 and 0 for DOP853 by default, as in
    /// Hairer's codes, which refuse β > 0.2).
    pub beta: f64,
    /// Safety factor on the predicted step, in (0, 1] (0.9).
    pub safety: f64,
    /// The smallest ratio of successive steps, in (0, 1] (0.2 for DOPRI5, 0.333 for DOP853).
    pub fac_min: f64,
    /// The largest ratio of successive steps, at least 1 (10 for DOPRI5, 6 for DOP853).
    pub fac_max: f64,
}

/// The smallest relative tolerance an adaptive method accepts in the scalar type `T`: ten
/// rounding units, 10·ε/2 (1.1e-15 in f64, 6.0e-7 in f32); 0, a purely absolute tolerance,
/// stays allowed. Below it the error estimate is rounding noise and the method buys steps, not
/// accuracy: before this limit, DOP853 in f32 at rtol = atol = 1e-9 took 25 times the steps of
/// 1e-8 for no gain, and returned without an error. Hairer's DOP853 refuses RTOL ≤ 10·UROUND
/// in the same way.
///
/// ```
/// assert_eq!(eom::integrate::min_rtol::<f64>(), 5.0 * f64::EPSILON);
/// assert_eq!(eom::integrate::min_rtol::<f32>(), 5.0 * f64::from(f32::EPSILON));
/// ```
pub fn min_rtol<T: RealField>() -> f64 {
    5.0 * T::default_epsilon().to_subset().unwrap_or(f64::EPSILON)
}

impl AdaptiveOptions {
    /// The same options with rtol and atol a hundred times tighter: a refined run, to check
    /// a figure's convergence.
    pub fn tightened(self) -> Self {
        Self {
            rtol: self.rtol / 100.0,
            atol: self.atol / 100.0,
            ..self
        }
    }

    /// Hairer's DOPRI5 defaults with the given tolerances.
    pub fn dopri5(rtol: f64, atol: f64) -> Self {
        Self {
            rtol,
            atol,
            h_min: 0.0,
            h_max: f64::INFINITY,
            h0: None,
            max_steps: 100_000,
            beta: 0.04,
            safety: 0.9,
            fac_min: 0.2,
            fac_max: 10.0,
        }
    }

    /// Hairer's DOP853 defaults with the given tolerances.
    pub fn dop853(rtol: f64, atol: f64) -> Self {
        Self {
            beta: 0.0,
            fac_min: 0.333,
            fac_max: 6.0,
            ..Self::dopri5(rtol, atol)
        }
    }

    /// Checks that `rtol` is 0 or at least [`min_rtol`] of the scalar type `T`.
    pub(crate) fn check_precision<T: RealField>(&self) -> Result<(), IntegrateError> {
        let min = min_rtol::<T>();
        if self.rtol > 0.0 && self.rtol < min {
            return Err(IntegrateError::ToleranceBelowPrecision {
                rtol: self.rtol,
                min,
                precision: std::any::type_name::<T>(),
            });
        }
        Ok(())
    }

    /// Checks every field, naming the first one that is out of range.
    pub(crate) fn validate(&self) -> Result<(), IntegrateError> {
        self.validate_tolerances()?;
        self.validate_steps()?;
        self.validate_controller()
    }

    /// Both tolerances finite and non-negative, not both zero.
    fn validate_tolerances(&self) -> Result<(), IntegrateError> {
        let tol_ok = |v: f64| v.is_finite() && v >= 0.0;
        for (name, value) in [("rtol", self.rtol), ("atol", self.atol)] {
            if !tol_ok(value) {
                return Err(IntegrateError::InvalidTolerance { name, value });
            }
        }
        if self.rtol == 0.0 && self.atol == 0.0 {
            return Err(IntegrateError::InvalidTolerance {
                name: "rtol",
                value: 0.0,
            });
        }
        Ok(())
    }

    /// `h_min` finite and non-negative, `h_max` positive, `h0` (if given) positive and finite.
    fn validate_steps(&self) -> Result<(), IntegrateError> {
        if !(self.h_min.is_finite() && self.h_min >= 0.0) {
            return Err(IntegrateError::InvalidStep {
                name: "h_min",
                value: self.h_min,
            });
        }
        if self.h_max.is_nan() || self.h_max <= 0.0 {
            return Err(IntegrateError::InvalidStep {
                name: "h_max",
                value: self.h_max,
            });
        }
        match self.h0 {
            Some(h0) if !(h0.is_finite() && h0 > 0.0) => Err(IntegrateError::InvalidStep {
                name: "h0",
                value: h0,
            }),
            _ => Ok(()),
        }
    }

    /// The controller's parameters in the ranges their documentation gives; outside them the
    /// controller still runs but steers badly (negative steps, steps that never grow), and
    /// the run would fail later under a name that hides the culprit.
    fn validate_controller(&self) -> Result<(), IntegrateError> {
        let in_unit = |v: f64| v > 0.0 && v <= 1.0;
        let beta_ok = (0.0..=0.2).contains(&self.beta);
        let checks = [
            ("beta", self.beta, beta_ok, "[0, 0.2]"),
            ("safety", self.safety, in_unit(self.safety), "(0, 1]"),
            ("fac_min", self.fac_min, in_unit(self.fac_min), "(0, 1]"),
            ("fac_max", self.fac_max, self.fac_max >= 1.0, "[1, ∞]"),
        ];
        match checks.into_iter().find(|&(_, _, ok, _)| !ok) {
            None => Ok(()),
            Some((name, value, _, range)) => {
                Err(IntegrateError::InvalidController { name, value, range })
            }
        }
    }
}

/// The weighted root-mean-square norm of `e` with weights `atol + rtol · max(|yᵢ|, |zᵢ|)`
/// (Hairer's norm).
pub(crate) fn scaled_rms<T: RealField + Copy, const N: usize>(
    e: &SVector<T, N>,
    y: &SVector<T, N>,
    z: &SVector<T, N>,
    tols: (T, T),
) -> T {
    let mut sum = T::zero();
    for i in 0..N {
        let r = in_units_of(e[i], weight(y[i], z[i], tols));
        sum += r * r;
    }
    (sum / lit::<T>(N as f64)).sqrt()
}

/// Hairer's weight `atol + rtol · max(|y|, |z|)` of a component whose values at both ends of
/// the step are `y` and `z`.
pub(crate) fn weight<T: RealField + Copy>(y: T, z: T, (rtol, atol): (T, T)) -> T {
    atol + rtol * y.abs().max(z.abs())
}

/// The error `e` of a component in units of its weight `w`.
pub(crate) fn in_units_of<T: RealField + Copy>(e: T, w: T) -> T {
    // An exact zero error counts as zero even where the weight is zero (atol = 0 and a
    // component that stays at zero), instead of 0/0.
    if e == T::zero() { T::zero() } else { e / w }
}

/// The weighted Euclidean norm of `e` with weights `atol + rtol · |yᵢ|` (Hairer's `hinit`
/// uses this norm, not the RMS one of the error test).
fn scaled_norm<T: RealField + Copy, const N: usize>(
    e: &SVector<T, N>,
    y: &SVector<T, N>,
    tols: (T, T),
) -> T {
    scaled_rms(e, y, y, tols) * lit::<T>(N as f64).sqrt()
}

/// Hairer's initial step (`hinit` of DOPRI5/DOP853): a step that makes an explicit Euler step
/// of the given order meet the tolerance, from ‖y₀‖, ‖f₀‖ and a difference estimate of ‖f′‖.
/// Costs one RHS evaluation; `f0` is the derivative at `(t0, y0)`.
pub(crate) fn initial_step<T, const N: usize, S>(
    system: &S,
    (t0, y0, f0): (T, &SVector<T, N>, &SVector<T, N>),
    order: i32,
    tols: (T, T),
    h_max: T,
) -> T
where
    T: RealField + Copy,
    S: OdeSystem<T, N> + ?Sized,
{
    let d0 = scaled_norm(y0, y0, tols);
    let d1 = scaled_norm(f0, y0, tols);
    // Hairer compares the squared norms with 1e-10.
    let tiny = lit::<T>(1e-5);
    let fallback = lit::<T>(1e-6).min(h_max);
    let mut h = if d0 <= tiny || d1 <= tiny {
        lit(1e-6)
    } else {
        lit::<T>(0.01) * d0 / d1
    };
    // With atol = 0, a component that starts at zero but moves has zero weight and infinite
    // scaled rate, so the estimate collapses to zero; take Hairer's fallback step instead.
    h = if h > T::zero() && h.is_finite() {
        h.min(h_max)
    } else {
        fallback
    };
    let y1 = y0 + f0 * h;
    let mut f1 = SVector::<T, N>::zeros();
    system.rhs(t0 + h, &y1, &mut f1);
    let d2 = scaled_norm(&(f1 - f0), y0, tols) / h;
    let d = d1.max(d2);
    let h1 = if d <= lit(1e-15) {
        (h * lit(1e-3)).max(lit(1e-6))
    } else {
        (lit::<T>(0.01) / d).powf(lit::<T>(1.0 / f64::from(order)))
    };
    let h = (h * lit(100.0)).min(h1).min(h_max);
    if h > T::zero() && h.is_finite() {
        h
    } else {
        fallback
    }
}

/// What the controller decided about a step.
pub(crate) enum Verdict<T> {
    /// Keep the step; try the next one with this size.
    Accept(T),
    /// Redo the step with this size.
    Reject(T),
}

/// The PI step-size controller, with the memory of the last accepted error.
pub(crate) struct PiController<T> {
    alpha: T,
    beta: T,
    safety: T,
    fac_min: T,
    fac_max: T,
    err_prev: T,
    rejected_last: bool,
}

impl<T: RealField + Copy> PiController<T> {
    /// A controller with exponent α = `alpha0` − `beta_weight` · β (Hairer's (0.2, 0.75) for
    /// DOPRI5, (0.125, 0.2) for DOP853).
    pub(crate) fn new(options: &AdaptiveOptions, (alpha0, beta_weight): (f64, f64)) -> Self {
        let alpha = alpha0 - beta_weight * options.beta;
        Self {
            alpha: lit(alpha),
            beta: lit(options.beta),
            safety: lit(options.safety),
            fac_min: lit(options.fac_min),
            fac_max: lit(options.fac_max),
            err_prev: lit(1e-4),
            rejected_last: false,
        }
    }

    /// Accepts a step of size `h` with scaled error `err ≤ 1` and proposes the next size, or
    /// rejects it and proposes a smaller one. After a rejection the step is not allowed to
    /// grow (Hairer's rule, which avoids repeated rejections).
    pub(crate) fn decide(&mut self, err: T, h: T) -> Verdict<T> {
        let err_alpha = err.powf(self.alpha);
        if err <= T::one() {
            let fac = err_alpha / self.err_prev.powf(self.beta) / self.safety;
            let mut h_new = h / fac
                .max(T::one() / self.fac_max)
                .min(T::one() / self.fac_min);
            if self.rejected_last {
                h_new = h_new.min(h);
            }
            self.err_prev = err.max(lit(1e-4));
            self.rejected_last = false;
            Verdict::Accept(h_new)
        } else {
            self.rejected_last = true;
            Verdict::Reject(h / (T::one() / self.fac_min).min(err_alpha / self.safety))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn controller_parameters_out_of_range_are_named() {
        type Set = fn(&mut AdaptiveOptions, f64);
        let cases: [(&str, Set, [f64; 3]); 4] = [
            ("beta", |o, v| o.beta = v, [-0.01, 0.3, f64::NAN]),
            ("safety", |o, v| o.safety = v, [0.0, 1.5, f64::NAN]),
            ("fac_min", |o, v| o.fac_min = v, [0.0, 2.0, f64::NAN]),
            ("fac_max", |o, v| o.fac_max = v, [0.5, -1.0, f64::NAN]),
        ];
        for (field, set, values) in cases {
            for value in values {
                let mut options = AdaptiveOptions::dop853(1e-6, 1e-6);
                set(&mut options, value);
                match options.validate() {
                    Err(IntegrateError::InvalidController { name, .. }) => assert_eq!(name, field),
                    other => panic!("{field} = {value}: {other:?}"),
                }
            }
        }
    }

    #[test]
    fn hairers_defaults_and_the_range_ends_are_valid() {
        for options in [
            AdaptiveOptions::dopri5(1e-6, 0.0),
            AdaptiveOptions::dop853(0.0, 1e-6),
        ] {
            assert_eq!(options.validate(), Ok(()));
        }
        let edges = AdaptiveOptions {
            beta: 0.2,
            safety: 1.0,
            fac_min: 1.0,
            fac_max: f64::INFINITY,
            ..AdaptiveOptions::dopri5(1e-6, 1e-6)
        };
        assert_eq!(edges.validate(), Ok(()));
    }
}
