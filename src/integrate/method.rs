//! The integration methods by name, as a scene and a run choose them.

/// The integration methods a scene can name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Explicit Euler, fixed step.
    Euler,
    /// Semi-implicit Euler, fixed step, velocities kicked first.
    SymplecticEuler,
    /// Classical Runge–Kutta, fixed step.
    Rk4,
    /// Dormand–Prince 5(4), adaptive.
    Dopri5,
    /// Dormand–Prince 8(5,3), adaptive.
    Dop853,
    /// The geometric rotation integrator, fixed step (free spatial bodies with a quaternion).
    LieMidpoint,
}

impl Method {
    /// Every method, by its name in scene files.
    pub const ALL: [(Method, &'static str); 6] = [
        (Method::Euler, "euler"),
        (Method::SymplecticEuler, "symplectic-euler"),
        (Method::Rk4, "rk4"),
        (Method::Dopri5, "dopri5"),
        (Method::Dop853, "dop853"),
        (Method::LieMidpoint, "lie-midpoint"),
    ];

    /// The name in scene files.
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(m, _)| *m == self)
            .map(|(_, n)| *n)
            .expect("every method is listed")
    }

    /// Whether the step is chosen by a tolerance.
    pub fn is_adaptive(self) -> bool {
        matches!(self, Method::Dopri5 | Method::Dop853)
    }

    /// How a run of it is refined to check its figures' convergence, as a summary and a
    /// report say it: `"half the step"` or `"tolerances / 100"`
    /// ([`super::Stepper::refined`], [`super::AdaptiveOptions::tightened`]).
    pub fn refinement(self) -> &'static str {
        match self.is_adaptive() {
            true => "tolerances / 100",
            false => "half the step",
        }
    }
}
