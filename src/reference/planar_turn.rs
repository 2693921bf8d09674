//! Planar motion at G (4.43–4.44) at a constant yaw rate r under a constant body-fixed force:
//! M(u̇ − vr) = F_x, M(v̇ + ur) = F_y, ψ̇ = r, Ẋ = u cos ψ − v sin ψ, Ẏ = u sin ψ + v cos ψ.
//!
//! In complex form w = u + iv, f = (F_x + iF_y)/M, Z = X + iY: ẇ = −irw + f, Ż = e^{iψ}w. The
//! solution is w(t) = w_p + (w₀ − w_p)e^{−irt} with the steady turn w_p = f/(ir), and, with
//! ψ = ψ₀ + rt, Z(t) = Z₀ + e^{iψ₀}[w_p (e^{irt} − 1)/(ir) + (w₀ − w_p) t]. The speed relative to
//! the steady turn, |w − w_p|, is conserved. (e^{irt} − 1)/(ir) is evaluated as
//! e^{irt/2} · 2 sin(rt/2)/r, which does not cancel.

use nalgebra::{Complex, RealField, SVector};

use super::ReferenceProblem;
use crate::ParameterError;
use crate::integrate::OdeSystem;
use crate::validate::{non_zero, positive};

/// A body turning at constant yaw rate under a constant body-fixed force; state
/// `[u, v, ψ, X, Y]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanarTurn {
    r: f64,
    f: Complex<f64>,
    w0: Complex<f64>,
    psi0: f64,
    z0: Complex<f64>,
}

impl PlanarTurn {
    /// A body of mass `mass` at yaw rate `r` (non-zero) under the body-fixed force
    /// `(fx, fy)`, starting with body velocity `(u0, v0)` at heading 0 from the origin.
    /// `r = 0` is refused: it is uniform acceleration, not a turn.
    pub fn new(
        mass: f64,
        r: f64,
        (fx, fy): (f64, f64),
        (u0, v0): (f64, f64),
    ) -> Result<Self, ParameterError> {
        let mass = positive("mass", mass)?;
        let r = non_zero("r", r)?;
        let f = Complex::new(fx, fy) / mass;
        Ok(Self {
            r,
            f,
            w0: Complex::new(u0, v0),
            psi0: 0.0,
            z0: Complex::new(0.0, 0.0),
        })
    }

    /// The steady-turn body velocity w_p = f/(ir).
    fn steady(&self) -> Complex<f64> {
        self.f / Complex::new(0.0, self.r)
    }

    /// The exact state `[u, v, ψ, X, Y]` at `t`.
    pub fn exact(&self, t: f64) -> SVector<f64, 5> {
        let wp = self.steady();
        let turn = Complex::from_polar(1.0, -self.r * t);
        let w = wp + (self.w0 - wp) * turn;
        let half = 0.5 * self.r * t;
        let chord = Complex::from_polar(2.0 * half.sin() / self.r, half);
        let z = self.z0 + Complex::from_polar(1.0, self.psi0) * (wp * chord + (self.w0 - wp) * t);
        SVector::<f64, 5>::from([w.re, w.im, self.psi0 + self.r * t, z.re, z.im])
    }
}

impl<T: RealField + Copy> OdeSystem<T, 5> for PlanarTurn {
    fn rhs(&self, _t: T, y: &SVector<T, 5>, dy: &mut SVector<T, 5>) {
        let r: T = nalgebra::convert(self.r);
        let (fx, fy): (T, T) = (nalgebra::convert(self.f.re), nalgebra::convert(self.f.im));
        let (sin_psi, cos_psi) = y[2].sin_cos();
        *dy = SVector::<T, 5>::from([
            y[1] * r + fx,
            -y[0] * r + fy,
            r,
            y[0] * cos_psi - y[1] * sin_psi,
            y[0] * sin_psi + y[1] * cos_psi,
        ]);
    }
}

impl ReferenceProblem<5> for PlanarTurn {
    fn name(&self) -> &'static str {
        "planar turn"
    }

    fn initial_state(&self) -> SVector<f64, 5> {
        self.exact(0.0)
    }

    /// Two full turns, 2 · 2π/|r|.
    fn t_end(&self) -> f64 {
        2.0 * std::f64::consts::TAU / self.r.abs()
    }

    /// The largest error in velocity, relative to the steady-turn speed scale |w₀| + |w_p|, or
    /// in position, relative to the distance that speed covers in one radian of turn.
    fn error(&self, t: f64, y: &SVector<f64, 5>) -> f64 {
        let e = self.exact(t);
        let speed = self.w0.norm() + self.steady().norm();
        let length = speed / self.r.abs();
        let velocity = (y[0] - e[0]).abs().max((y[1] - e[1]).abs()) / speed;
        let position = (y[3] - e[3]).abs().max((y[4] - e[4]).abs()) / length;
        velocity.max(position).max((y[2] - e[2]).abs())
    }

    /// The speed relative to the steady turn, |w − w_p|.
    fn invariants(&self, y: &SVector<f64, 5>) -> Vec<f64> {
        vec![(Complex::new(y[0], y[1]) - self.steady()).norm()]
    }
}
