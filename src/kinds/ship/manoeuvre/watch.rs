//! What a manoeuvre's run watches for: the functions of the state whose zeros are its events
//! (the heading's changes, the yaw rate passing zero, the ship stopping) and the kinks of the
//! ship's right-hand side a stretch ends on (the steering gear's rate limit, an MMG ship's
//! change of branch).

use super::DriveState;

/// What a run watches for: a function of the state whose zero is an event.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Watch {
    /// |ψ − ψ₀| reaches `angle` (rad): g = (ψ − ψ₀)² − angle².
    HeadingChange(f64),
    /// ψ − ψ₀ reaches `side`·ψ_a: g = side·(ψ − ψ₀) − ψ_a.
    HeadingOnSide(f64),
    /// The yaw rate is zero: g = r.
    YawRateZero,
    /// The steering gear's lag rate reaches its limit, or leaves it: g = ((δ_c − δ)/T_δ)² −
    /// δ̇_max². Nothing changes there but the form of δ̇ (clamped or not), which has a kink: a
    /// step across it is only first-order accurate in where the kink falls, so every run ends
    /// a stretch on it, whatever its method.
    RateLimit,
    /// The ship stops: g = u.
    Stopped,
    /// An MMG ship's inflow angle at the propeller (0: β_P) or the rudder (1: β_R) changes
    /// sign: g = the angle. The model changes branch there (C₂, γ_R) and the wake law has a
    /// kink (|β_P|), so, as at [`Watch::RateLimit`], every run ends a stretch on it.
    InflowSide(usize),
}

impl Watch {
    pub(super) fn g(self, y: &DriveState, heading0: f64, heading_a: f64) -> f64 {
        let change = y[5] - heading0;
        match self {
            Watch::HeadingChange(angle) => change * change - angle * angle,
            Watch::HeadingOnSide(side) => side * change - heading_a,
            Watch::YawRateZero => y[2],
            Watch::Stopped => y[0],
            Watch::RateLimit | Watch::InflowSide(_) => {
                unreachable!("the model's kinks are evaluated by the driver")
            }
        }
    }

    /// Whether this is a kink of the ship's right-hand side, where only a stretch ends, not
    /// an event of the manoeuvre.
    pub(super) fn is_kink(self) -> bool {
        matches!(self, Watch::RateLimit | Watch::InflowSide(_))
    }
}
