//! What the tests of the extremes and the examples that print their tables share: the bodies,
//! the runs through the generated quaternion models, and the measures of error.
//!
//! Every run goes through a generated spatial model with quaternion attitude, at rest in
//! translation (u = v = w = 0, x = y = z = 0, which no load changes): the rotation
//! `[p, q, r, q0, q1, q2, q3]` of a reference problem sits at entries 3–5 and 9–12 of the
//! model's 13-entry state.

use eom::InertiaTensor;
use eom::generic::{quaternion_state_of_rotation, rotation_of_quaternion_state};
use eom::integrate::{
    AdaptiveOptions, Dop853, Dopri5, IntegrateError, Integrator, OdeSystem, Statistics, Stats,
};
use eom::models::{Constant, Model, SpatialFullQuaternion, SpatialPrincipalQuaternion};
use eom::reference::{AxisymmetricTop, ReferenceProblem, TennisRacket};
use nalgebra::{Matrix3, Quaternion, Rotation3, SVector, SymmetricEigen, UnitQuaternion, Vector3};

use crate::double_double;

/// The spin rates measured, rad/s: the unit rate, against which the others are judged, and
/// the two extremes.
pub const RATES: [f64; 3] = [1.0, 1e3, 1e4];

/// The racket's principal moments (I₁ < I₂ < I₃), those of the work–precision harness.
pub const RACKET_MOMENTS: [f64; 3] = [1.0, 2.0, 3.0];

/// The axisymmetric top's transverse and axial moments.
pub const TOP_MOMENTS: (f64, f64) = (2.0, 3.5);

/// The tennis racket of the work–precision harness, spun `rate` times faster: ω₀ = (0, 1, 0.1)
/// · `rate`. Its period is 21.6 s / `rate`.
pub fn racket(rate: f64) -> TennisRacket {
    let attitude = UnitQuaternion::from_euler_angles(0.3, -0.2, 0.5);
    TennisRacket::new(Vector3::from(RACKET_MOMENTS), rate, 0.1 * rate, attitude)
        .expect("a racket near its middle axis")
}

/// The torque-free axisymmetric top of the integrator tests, spun `rate` times faster:
/// ω₀ = (0.6, −0.3, 1.2) · `rate`.
pub fn top(rate: f64) -> AxisymmetricTop {
    let attitude = UnitQuaternion::from_euler_angles(0.1, 0.4, -0.7);
    let (transverse, axial) = TOP_MOMENTS;
    AxisymmetricTop::new(
        transverse,
        axial,
        Vector3::new(0.6, -0.3, 1.2) * rate,
        attitude,
    )
    .expect("a physical top")
}

/// The top's principal moments (I₁ = I₂).
pub fn top_moments() -> Vector3<f64> {
    let (transverse, axial) = TOP_MOMENTS;
    Vector3::new(transverse, transverse, axial)
}

/// A principal tensor of `moments`.
pub fn principal_tensor(moments: &Vector3<f64>) -> InertiaTensor {
    InertiaTensor::new(moments.x, moments.y, moments.z, 0.0, 0.0, 0.0)
        .expect("physical principal moments")
}

/// The generated principal-axes quaternion model of a body of unit mass and `moments`.
pub fn principal_model<T: nalgebra::SimdRealField + Copy>(
    moments: &Vector3<f64>,
) -> SpatialPrincipalQuaternion<T> {
    SpatialPrincipalQuaternion::new(1.0, &principal_tensor(moments)).expect("a valid model")
}

/// The two embedded Runge–Kutta pairs, at rtol = atol.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Adaptive {
    /// Dormand–Prince 5(4).
    Dopri5,
    /// Dormand–Prince 8(5,3).
    Dop853,
}

impl Adaptive {
    /// Both, in the order of the tables.
    pub const ALL: [Adaptive; 2] = [Adaptive::Dopri5, Adaptive::Dop853];

    /// The name in the tables.
    pub fn name(self) -> &'static str {
        match self {
            Adaptive::Dopri5 => "DOPRI5",
            Adaptive::Dop853 => "DOP853",
        }
    }

    /// Runs `system` from `(0, y0)` to `t_end` at rtol = atol = `tol`, calling `observe` after
    /// every accepted step; returns the end state and the statistics.
    pub fn run<S: OdeSystem<f64, 13>>(
        self,
        system: &S,
        y0: SVector<f64, 13>,
        t_end: f64,
        tol: f64,
        observe: impl FnMut(f64, &SVector<f64, 13>),
    ) -> Result<(SVector<f64, 13>, Stats), IntegrateError> {
        match self {
            Adaptive::Dopri5 => {
                let mut method = Dopri5::new(AdaptiveOptions::dopri5(tol, tol));
                let end = method.integrate_with(system, 0.0, y0, t_end, observe)?;
                Ok((end, method.stats()))
            }
            Adaptive::Dop853 => {
                let mut method = Dop853::new(AdaptiveOptions::dop853(tol, tol));
                let end = method.integrate_with(system, 0.0, y0, t_end, observe)?;
                Ok((end, method.stats()))
            }
        }
    }
}

/// The largest relative drifts of the kinetic energy and of |H| over a run.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Drifts {
    /// max |T/T₀ − 1|.
    pub energy: f64,
    /// max ||H|/|H₀| − 1|.
    pub momentum: f64,
}

impl Drifts {
    /// Folds the state `y` of a body of tensor `inertia` into the maxima, against `y0`.
    pub fn observe(&mut self, inertia: &Matrix3<f64>, y0: &SVector<f64, 13>, y: &SVector<f64, 13>) {
        let rates = |s: &SVector<f64, 13>| Vector3::new(s[3], s[4], s[5]);
        let (w0, w) = (rates(y0), rates(y));
        let energy = |w: &Vector3<f64>| w.dot(&(inertia * w));
        let momentum = |w: &Vector3<f64>| (inertia * w).norm();
        self.energy = self.energy.max((energy(&w) / energy(&w0) - 1.0).abs());
        self.momentum = self
            .momentum
            .max((momentum(&w) / momentum(&w0) - 1.0).abs());
    }
}

/// What one run of a spinning body measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinRun {
    /// The problem's own error measure at the end (for the racket the larger of the rate
    /// error relative to |ω₀| and the angle of H off its fixed direction, for the top the
    /// larger of the rate error and the attitude angle to the exact attitude, radians).
    pub error: f64,
    /// The drifts of T and |H| over the accepted steps.
    pub drifts: Drifts,
    /// The statistics of the run.
    pub stats: Stats,
}

/// Runs `problem`, a torque-free body of principal `moments`, through the generated
/// `SpatialPrincipalQuaternion` with `method` at rtol = atol = `tol` from 0 to `t_end`.
pub fn spin_run<P: ReferenceProblem<7>>(
    problem: &P,
    moments: &Vector3<f64>,
    method: Adaptive,
    tol: f64,
    t_end: f64,
) -> SpinRun {
    let model = principal_model::<f64>(moments);
    let inertia = Matrix3::from_diagonal(moments);
    let y0 = quaternion_state_of_rotation(&problem.initial_state());
    let mut drifts = Drifts::default();
    let (end, stats) = method
        .run(
            &model.driven_by(Constant::zero()),
            y0,
            t_end,
            tol,
            |_, y| drifts.observe(&inertia, &y0, y),
        )
        .expect("the spinning body is integrated");
    SpinRun {
        error: problem.error(t_end, &rotation_of_quaternion_state(&end)),
        drifts,
        stats,
    }
}

/// The fixed rotation that turns the principal axes of the conditioning cases into general
/// body axes, where every product of inertia is non-zero.
pub fn turn() -> Rotation3<f64> {
    Rotation3::from_euler_angles(0.7, -0.4, 1.9)
}

/// The tensor of principal `moments` in principal axes, or turned by [`turn`] (R D Rᵀ,
/// computed in f64 and symmetrised; its f64 entries are then the body's data).
pub fn tensor_matrix(moments: &Vector3<f64>, turned: bool) -> Matrix3<f64> {
    let diagonal = Matrix3::from_diagonal(moments);
    if turned {
        let r = turn().into_inner();
        let m = r * diagonal * r.transpose();
        (m + m.transpose()) * 0.5
    } else {
        diagonal
    }
}

/// cond₂([I]) = λ_max / λ_min of a symmetric positive definite tensor.
pub fn condition(inertia: &Matrix3<f64>) -> f64 {
    let eigenvalues = SymmetricEigen::new(*inertia).eigenvalues;
    eigenvalues.max() / eigenvalues.min()
}

/// A small deterministic generator (xorshift64), so that the samples are the same each run.
pub struct Samples(u64);

impl Samples {
    /// A generator from a non-zero seed.
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// The next number, uniform in [−1, 1).
    // A stream that never ends, drawn from by hand: not an iterator.
    #[allow(clippy::should_implement_trait)]
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    /// Body rates in a random direction with a magnitude between 10⁻³ and 10³ rad/s.
    pub fn rates(&mut self) -> Vector3<f64> {
        let direction = Vector3::new(self.next(), self.next(), self.next());
        direction * 10f64.powf(3.0 * self.next())
    }
}

/// The error of one form of ω̇ at one ω, against the double-double solution of 4.51.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct RateError {
    /// ρ = |ω̇ − ω̇ₑₓ| / (ε |[I]⁻¹|₂ |ω| |[I]ω|): the error in units of ε times the size of
    /// what [I]⁻¹ multiplies. ρ of order one is as accurate as f64 data allow.
    pub rho: f64,
    /// |ω̇ − ω̇ₑₓ| / |ω̇ₑₓ| (zero where both vanish).
    pub relative: f64,
    /// max over components |ω̇ᵢ − ω̇ₑₓ,ᵢ| / |ω̇ₑₓ,ᵢ|.
    pub componentwise: f64,
    /// The relative error over the bound that conditioning puts on it,
    /// cond([I]) · ε / sin∠(ω, [I]ω); at most ρ.
    pub of_condition: f64,
}

impl RateError {
    /// The larger of each measure.
    pub fn max(self, other: RateError) -> RateError {
        RateError {
            rho: self.rho.max(other.rho),
            relative: self.relative.max(other.relative),
            componentwise: self.componentwise.max(other.componentwise),
            of_condition: self.of_condition.max(other.of_condition),
        }
    }
}

/// The worst errors of the three forms of ω̇ over the samples of one tensor.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Conditioning {
    /// cond₂([I]).
    pub condition: f64,
    /// The generated full-tensor model (`SpatialFullQuaternion`), adjugate over determinant.
    pub full: RateError,
    /// The generic nalgebra form (`generic::RigidBody`), nalgebra's inverse.
    pub generic: RateError,
    /// The generated principal-axes model, for a tensor in principal axes.
    pub principal: Option<RateError>,
}

/// The error of `rate` against `exact` at ω with tensor `inertia`, whose smallest and largest
/// eigenvalues are `extremes`.
fn rate_error(
    rate: &Vector3<f64>,
    exact: &Vector3<f64>,
    inertia: &Matrix3<f64>,
    (smallest, largest): (f64, f64),
    omega: &Vector3<f64>,
) -> RateError {
    let gap = rate - exact;
    let momentum = inertia * omega;
    let scale = f64::EPSILON * omega.norm() * momentum.norm() / smallest;
    let sine = omega.cross(&momentum).norm() / (omega.norm() * momentum.norm());
    let ratio = |gap: f64, of: f64| if gap == 0.0 { 0.0 } else { gap / of };
    let relative = ratio(gap.norm(), exact.norm());
    RateError {
        rho: ratio(gap.norm(), scale),
        relative,
        componentwise: (0..3)
            .map(|i| ratio(gap[i].abs(), exact[i].abs()))
            .fold(0.0, f64::max),
        of_condition: relative * sine / (largest / smallest * f64::EPSILON),
    }
}

/// ω̇ of a generated spatial model at rest in translation, attitude the identity, no load.
fn generated_rates<M: Model<f64, 13, 6>>(model: &M, omega: &Vector3<f64>) -> Vector3<f64> {
    let mut state = [0.0; 13];
    state[3..6].copy_from_slice(omega.as_slice());
    state[9] = 1.0;
    let rate = model.rhs(&state, &[0.0; 6]);
    Vector3::new(rate[3], rate[4], rate[5])
}

/// Evaluates ω̇ = [I]⁻¹(−ω × [I]ω) by every form at `samples` random ω and returns the worst
/// errors against the double-double solution from the same f64 data.
pub fn conditioning(inertia: &Matrix3<f64>, samples: usize, seed: u64) -> Conditioning {
    let tensor = InertiaTensor::from_matrix(*inertia).expect("a physical tensor");
    let full = SpatialFullQuaternion::<f64>::new(1.0, &tensor).expect("a valid model");
    let principal = SpatialPrincipalQuaternion::<f64>::new(1.0, &tensor).ok();
    let generic = eom::generic::RigidBody::<f64>::new(1.0, &tensor).expect("a valid body");
    let eigenvalues = SymmetricEigen::new(*inertia).eigenvalues;
    let extremes = (eigenvalues.min(), eigenvalues.max());
    let rows = [0, 1, 2].map(|r| [0, 1, 2].map(|c| inertia[(r, c)]));
    let mut worst = Conditioning {
        condition: eigenvalues.max() / eigenvalues.min(),
        principal: principal.map(|_| RateError::default()),
        ..Conditioning::default()
    };
    let mut draw = Samples::new(seed);
    for _ in 0..samples {
        let omega = draw.rates();
        let exact = Vector3::from(double_double::euler_rates(&rows, omega.into()));
        let judge = |rate: Vector3<f64>| rate_error(&rate, &exact, inertia, extremes, &omega);
        worst.full = worst.full.max(judge(generated_rates(&full, &omega)));
        worst.generic = worst.generic.max(judge(
            generic.angular_acceleration(&omega, &Vector3::zeros()),
        ));
        if let (Some(model), Some(error)) = (&principal, &mut worst.principal) {
            *error = error.max(judge(generated_rates(model, &omega)));
        }
    }
    worst
}

/// A thin rod, I = (10⁻⁶, 1, 1 + ½·10⁻⁶): a physical body (I_zz − I_yy ≤ I_xx) with a moment
/// ratio of 10⁶, tumbling end over end with a little spin about its axis.
pub const ROD_MOMENTS: [f64; 3] = [1e-6, 1.0, 1.0 + 0.5e-6];

/// The rod's body rates at t = 0 in its principal axes.
pub const ROD_RATES: [f64; 3] = [0.3, 1.0, 0.5];

/// What the thin rod's runs measured: the same motion in principal axes (generated
/// principal model) and in the turned axes (generated full model).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RodRuns {
    /// Drifts of the principal-axes run.
    pub principal: Drifts,
    /// Drifts of the turned run.
    pub turned: Drifts,
    /// Accepted steps of the principal-axes and the turned run.
    pub steps: (usize, usize),
    /// |ω_turned − ω_principal| / |ω₀| at the end, the turned run's rates turned back.
    pub difference: f64,
    /// |ω| t at the end: the angle turned, radians.
    pub turned_angle: f64,
}

/// The thin rod torque-free for `t_end` with DOP853 at rtol = atol = `tol`, in principal
/// axes and in the turned axes of [`turn`].
pub fn rod_runs(tol: f64, t_end: f64) -> RodRuns {
    let moments = Vector3::from(ROD_MOMENTS);
    let run = |turned: bool| {
        let inertia = tensor_matrix(&moments, turned);
        let rates = if turned {
            turn() * Vector3::from(ROD_RATES)
        } else {
            Vector3::from(ROD_RATES)
        };
        let mut y0 = SVector::<f64, 13>::zeros();
        y0.fixed_rows_mut::<3>(3).copy_from(&rates);
        y0[9] = 1.0;
        let tensor = InertiaTensor::from_matrix(inertia).expect("a physical rod");
        let mut drifts = Drifts::default();
        let observe = |y: &SVector<f64, 13>, drifts: &mut Drifts| drifts.observe(&inertia, &y0, y);
        let (end, stats) = if turned {
            let model = SpatialFullQuaternion::<f64>::new(1.0, &tensor).expect("a valid model");
            let system = model.driven_by(Constant::zero());
            Adaptive::Dop853.run(&system, y0, t_end, tol, |_, y| observe(y, &mut drifts))
        } else {
            let model =
                SpatialPrincipalQuaternion::<f64>::new(1.0, &tensor).expect("a valid model");
            let system = model.driven_by(Constant::zero());
            Adaptive::Dop853.run(&system, y0, t_end, tol, |_, y| observe(y, &mut drifts))
        }
        .expect("the rod is integrated");
        let rates = Vector3::new(end[3], end[4], end[5]);
        let rates = if turned {
            turn().inverse() * rates
        } else {
            rates
        };
        (drifts, stats.steps, rates)
    };
    let (principal, principal_steps, principal_rates) = run(false);
    let (turned, turned_steps, turned_rates) = run(true);
    let w0 = Vector3::from(ROD_RATES).norm();
    RodRuns {
        principal,
        turned,
        steps: (principal_steps, turned_steps),
        difference: (turned_rates - principal_rates).norm() / w0,
        turned_angle: w0 * t_end,
    }
}

/// The cyclic permutation that takes a near-symmetric body with I_yy ≈ I_zz (symmetry axis x)
/// to the axisymmetric top's axes (symmetry axis z): v′ = P v = (v_y, v_z, v_x). A proper
/// rotation, so the model's attitude is the top's times P: R = R′ P.
fn permutation() -> Matrix3<f64> {
    Matrix3::new(0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0)
}

/// What the near-symmetric body's run measured against the exact symmetric top.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NearSymmetricRun {
    /// The top's error measure at the end (rates and attitude against the exact solution of
    /// the exactly symmetric body).
    pub error: f64,
    /// Drifts of T and |H|.
    pub drifts: Drifts,
    /// Accepted steps.
    pub steps: usize,
}

/// A body with I = (I₃, I₁, I₁(1 + `asymmetry`)), I₁ and I₃ those of [`top_of_near_symmetric`],
/// run through the generated principal model with DOP853 at rtol = atol = `tol` for
/// `periods` of the top's horizon, against the exact solution of the exactly symmetric top.
pub fn near_symmetric_run(asymmetry: f64, tol: f64, periods: f64) -> NearSymmetricRun {
    let top = top_of_near_symmetric();
    let (i1, i3) = NEAR_SYMMETRIC_MOMENTS;
    let moments = Vector3::new(i3, i1, i1 * (1.0 + asymmetry));
    let inertia = Matrix3::from_diagonal(&moments);
    let p = permutation();
    let p_quaternion =
        UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(p)).into_inner();
    // The top's rotation state in the model's axes, and back.
    let to_model = |y: &SVector<f64, 7>| {
        let w = p.transpose() * Vector3::new(y[0], y[1], y[2]);
        let q = Quaternion::new(y[3], y[4], y[5], y[6]) * p_quaternion;
        SVector::<f64, 7>::from([w.x, w.y, w.z, q.w, q.i, q.j, q.k])
    };
    let to_top = |y: &SVector<f64, 7>| {
        let w = p * Vector3::new(y[0], y[1], y[2]);
        let q = Quaternion::new(y[3], y[4], y[5], y[6]) * p_quaternion.conjugate();
        SVector::<f64, 7>::from([w.x, w.y, w.z, q.w, q.i, q.j, q.k])
    };
    let model = principal_model::<f64>(&moments);
    let y0 = quaternion_state_of_rotation(&to_model(&top.initial_state()));
    let t_end = periods * top.t_end();
    let mut drifts = Drifts::default();
    let (end, stats) = Adaptive::Dop853
        .run(
            &model.driven_by(Constant::zero()),
            y0,
            t_end,
            tol,
            |_, y| drifts.observe(&inertia, &y0, y),
        )
        .expect("the near-symmetric body is integrated");
    NearSymmetricRun {
        error: top.error(t_end, &to_top(&rotation_of_quaternion_state(&end))),
        drifts,
        steps: stats.steps,
    }
}

/// The near-symmetric body's I₁ (= I_yy ≈ I_zz) and I₃ (= I_xx).
pub const NEAR_SYMMETRIC_MOMENTS: (f64, f64) = (2.0, 1.3);

/// The exactly symmetric top the near-symmetric body is judged against.
pub fn top_of_near_symmetric() -> AxisymmetricTop {
    let (i1, i3) = NEAR_SYMMETRIC_MOMENTS;
    let attitude = UnitQuaternion::from_euler_angles(0.1, 0.4, -0.7);
    AxisymmetricTop::new(i1, i3, Vector3::new(0.6, -0.3, 1.2), attitude).expect("a physical top")
}

/// How far apart two spatial states are in rotation: |ω_a − ω_b| / `rate_scale`, and the
/// angle between the attitudes (each normalised first), radians.
pub fn rotation_gap(a: &SVector<f64, 13>, b: &SVector<f64, 13>, rate_scale: f64) -> (f64, f64) {
    let rates = |s: &SVector<f64, 13>| Vector3::new(s[3], s[4], s[5]);
    let attitude = |s: &SVector<f64, 13>| {
        UnitQuaternion::from_quaternion(Quaternion::new(s[9], s[10], s[11], s[12]))
    };
    (
        (rates(a) - rates(b)).norm() / rate_scale,
        attitude(a).angle_to(&attitude(b)),
    )
}
